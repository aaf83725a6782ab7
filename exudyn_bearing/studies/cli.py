"""Command line: ``python -m exudyn_bearing COMMAND ...`` (see ``--help``)."""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys
import warnings

import numpy as np

from ..bearingfile import as_setup
from ..errors import SurfaceStartWarning
from ..presets import REFERENCE_BEARING
from ..setup import FROM_SETUP, BearingSetup
from ..results.records import assumptions_line, assumptions_record
from .options import COMMANDS, DefaultsFormatter, join_negative_values
from .run_report import plot_temperatures_beside, print_simulation, print_thermal
from .steady_report import print_combined, print_steady


def _setup(args, **changes) -> BearingSetup:
    """The setup of ``--bearing`` (the reference bearing without one), the command's contact-law
    options applied, and ``changes``; the one place a command reads its bearing."""
    if not args.bearing:
        setup = BearingSetup(REFERENCE_BEARING)
    else:
        try:
            setup = as_setup(args.bearing)
        except ValueError as err:
            raise ValueError(f"--bearing: {err}") from None
    if getattr(args, "no_drag", False):
        changes["drag"] = None
    return setup.replace(contact_law=_law(args, setup), **changes)


def _loads(args) -> int:
    from ..solvers.quasistatic import solve_load_distribution

    setup = _setup(args)
    result = solve_load_distribution(
        setup, axial_force=args.axial, radial_force=args.radial, rpm=args.rpm,
        moment=tuple(args.moment) if args.moment else None,
        mode="fixed-angle" if args.fixed_angle else "geometric", hold_axial=args.hold_axial,
        hertz_method="exact" if args.exact_hertz else FROM_SETUP)
    if args.json:
        from ..results.records import inputs_record

        data = result.to_dict() | {"inputs": inputs_record(
            setup.bearing, mode=result.mode, hold_axial=args.hold_axial, exact_hertz=args.exact_hertz)}
        json.dump(data, sys.stdout, indent=1)
        print()
        return 0
    b = setup.bearing
    print(f"Quasi-static load distribution ({result.mode} contact angles, MODEL.md §4)")
    print(f"bearing: Z={b.balls}, D={b.ball_diameter * 1e3:g} mm, d_m={b.pitch_diameter * 1e3:g} mm, "
          f"free angle {math.degrees(b.contact_angle):.2f} deg, f_i={b.inner_conformity:g}, f_o={b.outer_conformity:g}")
    print(f"loads: axial {args.axial:g} N, radial {args.radial:g} N, inner race {args.rpm:g} rpm; "
          f"centrifugal force {result.centrifugal_force:.2f} N per ball (cage {result.cage_speed:.2f} rad/s)")
    print(f"{'ball':>4} {'psi deg':>8} {'Q_i N':>9} {'a_i deg':>8} {'Q_o N':>9} {'a_o deg':>8} {'d_i um':>8} {'d_o um':>8}")
    for j in range(b.balls):
        print(f"{j:4d} {math.degrees(result.azimuth[j]):8.1f} {result.inner_load[j]:9.2f} "
              f"{math.degrees(result.inner_contact_angle[j]):8.2f} {result.outer_load[j]:9.2f} "
              f"{math.degrees(result.outer_contact_angle[j]):8.2f} {result.inner_deflection[j] * 1e6:8.3f} "
              f"{result.outer_deflection[j] * 1e6:8.3f}")
    # + 0.0: a component that rounds to zero prints as 0, whatever side of zero it lay
    dx, dy, dz = (result.displacement * 1e6).round(3) + 0.0
    print(f"inner-race displacement: x {dx:.3f} um, y {dy:.3f} um, axial {dz:.3f} um; "
          f"tilt {(np.degrees(result.tilt).round(6) + 0.0).tolist()} deg; max contact load {result.max_load:.1f} N")
    if np.any(result.reaction_moment != 0):
        print(f"reaction moment on the shaft (tilt held): {(result.reaction_moment.round(4) + 0.0).tolist()} N m")
    return 0


def _simulate(args) -> int:
    from ..simulation.runner import SolverSettings, simulate

    if args.axial == 0 and args.radial == 0:
        raise ValueError("no load: give --axial and/or --radial, N (both default to 0)")
    setup = _thermal(args, _setup(args))
    if args.order is not None:
        setup = setup.replace(contact_law=_law(args, setup, quadrature_order=args.order))
    if args.plot:
        from pathlib import Path

        folder = Path(args.plot).resolve().parent
        if not folder.is_dir():
            raise ValueError(f"--plot: the folder of {args.plot} does not exist ({folder})")
    settings = SolverSettings(solver=args.solver, step=args.step,
                              output_step=args.output_step if args.step is None else max(args.step, args.output_step))
    summary = simulate(setup, axial_force=args.axial, radial_force=args.radial, rpm=args.rpm, time=args.time,
                       settings=settings, error_estimate=args.error_estimate, initial_state=args.start,
                       profile=args.profile, initial_temperatures=args.initial_temperatures)
    data = summary.to_dict()
    if args.plot:
        from ..results.plots import plot_run

        title = f"F_a {args.axial:g} N, F_r {args.radial:g} N, {args.rpm:g} rpm"
        plot_run(summary.results, args.plot, title=title)
        data["plot"] = str(args.plot)
        plot_temperatures_beside(data, summary.thermal, args.plot, title)
    if args.json:
        json.dump(data, sys.stdout, indent=1)
        print()
        return 0
    print_simulation(data, args)
    return 0


def _defect_lines(setup, reaches) -> list:
    """Per defect: its place, outline and depth, and how deep a ball reaches into it, in um and
    as a share of the race's largest Hertz approach (``reaches``: the run's ``defect_reach_m``)."""
    out = []
    for d, (reach, delta) in zip(setup.surface.defects, reaches):
        if d.race == "ball":
            where, outline = f"ball {d.ball} at {d.angle_deg:g} deg", f"a round pit {d.length * 1e3:g} mm across"
        else:
            where = f"{d.race} race at {d.angle_deg:g} deg"
            if d.shape == "ellipse":
                outline = (f"a round pit {d.length * 1e3:g} mm across" if d.width is None else
                           f"an elliptical pit {d.length * 1e3:g} mm long, {d.width * 1e3:g} mm wide")
            else:
                outline = f"{d.length * 1e3:g} mm long, " + (f"{d.width * 1e3:g} mm wide" if d.width is not None
                                                            else "across the whole track (no width given)")
        share = f", {reach / delta:.2g} x the race's largest approach ({delta * 1e6:.3g} um)" if delta > 0 else ""
        out.append(f"{where}, {outline}, {d.depth * 1e6:g} um deep; a ball reaches {reach * 1e6:.3g} um of it{share}")
    return out


def _vibration(args) -> int:
    from pathlib import Path

    from .vibration import vibration, write_signal
    from .vibration_plot import plot_vibration

    if args.axial == 0 and args.radial == 0:
        raise ValueError("no load: give --axial and/or --radial, N (both default to 0)")
    setup = _thermal(args, _housed_setup(args))
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with warnings.catch_warnings():  # the surface start's outcome is a line of this command's report
        warnings.simplefilter("ignore", SurfaceStartWarning)
        result = vibration(setup, rpm=args.rpm, axial_force=args.axial, radial_force=args.radial, time=args.time,
                           sample_rate=args.sample_rate, settle=args.settle,
                           band=_band(args.band), error_estimate=args.error_estimate, masking=_masking(args),
                           fluctuation=_fluctuation(args), initial_temperatures=args.initial_temperatures)
    signal = out / "signal.csv"
    write_signal(result, signal)
    data = result.to_dict() | {"signal": str(signal)}
    if args.plot:
        title = f"F_a {args.axial:g} N, F_r {args.radial:g} N, {args.rpm:g} rpm"
        plot_vibration(result, args.plot, title=title, envelope_max_hz=args.plot_max)
        data["plot"] = str(args.plot)
        plot_temperatures_beside(data, result.thermal, args.plot, title)
    (out / "vibration.json").write_text(json.dumps(data, indent=1), encoding="utf-8")
    if args.json:
        json.dump(data, sys.stdout, indent=1)
        print()
        return 0
    b = setup.bearing
    surf = setup.surface
    print(f"Vibration run (MODEL.md §13): Z={b.balls}, D={b.ball_diameter * 1e3:g} mm, d_m={b.pitch_diameter * 1e3:g} mm; "
          f"axial {args.axial:g} N, radial {args.radial:g} N, inner race {args.rpm:g} rpm, {args.time:g} s at "
          f"{args.sample_rate:g} Hz (the first {args.settle:g} s left out)")
    for i, line in enumerate(_defect_lines(setup, result.solver["defect_reach_m"])):
        print(f"  defect {i}: {line}")
    if surf.waviness.active:
        print(f"  waviness: inner {list(surf.waviness.inner)}, outer {list(surf.waviness.outer)}, "
              f"ball {list(surf.waviness.ball)}")
    if result.solver.get("surface_start"):
        print(f"  {result.solver['surface_start']} (MODEL.md §13d)")
    print(f"  kinematic cage slip {result.kinematic_cage_slip_percent:.3f} %")
    print("  fault frequencies: nominal (catalogue formula, nominal contact angle), kinematic (pure rolling at the "
          "run's contact geometry), actual (the run's cage and ball speeds)")
    print(f"  {'':6} {'nominal Hz':>11} {'kinematic Hz':>13} {'actual Hz':>11} {'actual x shaft':>15}")
    faults = result.fault_frequencies
    for name in faults["kinematic"]:
        print(f"  {name:6} {faults['nominal'][name]:11.3f} {faults['kinematic'][name]:13.3f} "
              f"{faults['actual'][name]:11.3f} {faults['actual'][name] / (args.rpm / 60):15.4f}")
    peaks = ", ".join(f"{f:.2f} Hz ({a:.3g})" for f, a in result.envelope_peaks[:5])
    how = {"kurtogram": f"the kurtogram's, spectral kurtosis {result.band_kurtosis:.3g}" if result.band_kurtosis
           is not None else "", "housing": "about the housing resonance", "given": "given"}[result.band_from]
    print(f"  envelope peaks (band {result.band[0]:.0f}-{result.band[1]:.0f} Hz, {how}; m/s^2, uncalibrated: the "
          f"contact damping is assumed, MODEL.md §13c): {peaks}")
    sv = result.solver
    print(f"  defect passages: {len(result.defect_events)}; signal {signal}; wall time {result.wall_time_s:.1f} s "
          f"(step {_steps_said(sv)}, strike number {sv['strike_number']:.2g}, defect reach "
          f"{sv['reach_share']:.2g} of the approach, {sv['steps']} steps, "
          f"{sv['extra_steps']} more than planned; {sv['step_cuts']} step cuts, after {sv['passages_cut']} of the "
          f"{sv['passages']} passages)")
    imp = result.impacts
    if imp.get("entry_to_impact_s") is not None:
        said = imp["entry_to_impact_estimate_s"]
        print(f"  impacts ({imp['passages_read']} passages read from the contact load): entry to impact "
              f"{1e3 * imp['entry_to_impact_s']:.3f} ms (median; the geometry, MODEL.md eq. 13.8: "
              f"{'-' if said is None else f'{1e3 * said:.3f} ms'}), peak contact load {imp['peak_N']:.4g} N "
              f"(largest {imp['largest_peak_N']:.4g} N), read at the {1e6 * sv['step_s']:.3g}-us step")
    _print_spall_size(result.spall_size)
    est = result.error_estimate
    if est:
        print(f"  error estimate ({est['method']}, {est['reference_wall_time_s']:.1f} s more wall time): strongest "
              f"envelope line {est['envelope_line_Hz']:.3g} Hz, its amplitude {est['envelope_amplitude_percent']:.2g} % "
              f"(error bound {est['envelope_amplitude_bound_percent']:.2g} %), "
              f"kinematic cage slip {est['kinematic_cage_slip_pp']:.2g} pp")
    if result.thermal is not None:
        print_thermal(result.thermal)
    if args.plot:
        print(f"  plot written to {args.plot}")
    return 0


def _print_spall_size(size) -> None:
    """The outer-race spall's length read from the signal (``VibrationResult.spall_size``)."""
    if size is None:
        return
    if size["length_m"] is None:
        print(f"  spall size from the signal: not read ({size['message']})")
        return
    print(f"  spall size from the signal alone (its double impulse, MODEL.md eq. 13.10): "
          f"{1e3 * size['length_m']:.3f} mm against the true {1e3 * size['true_length_m']:.3f} mm "
          f"({size['error_percent']:+.1f} %); entry to strike {1e3 * size['spacing_s']:.3f} ms over "
          f"{size['passages']} passages at {size['speed_m_s']:.3f} m/s over the race")


def _housed_setup(args) -> BearingSetup:
    """:func:`_setup` on the file's [housing] (else ``HousingModel()``) with what --housing-* change."""
    from dataclasses import replace

    from ..races import HousingModel

    setup = _setup(args)
    changes = {k: v for k, v in (("frequency", args.housing_frequency), ("mass", args.housing_mass),
                                 ("damping_ratio", args.housing_damping)) if v is not None}
    return setup.replace(housing=replace(setup.housing or HousingModel(), **changes))


def _client(scheduler):
    """The Dask client of ``--scheduler`` (None without one)."""
    if not scheduler:
        return None
    try:
        from dask.distributed import Client
    except ImportError:
        raise ValueError("--scheduler needs dask[distributed]: pip install -e .[dask]") from None
    try:
        return Client(scheduler, timeout="10s")
    except (OSError, TimeoutError) as err:
        raise ValueError(f"--scheduler: cannot reach {scheduler} ({str(err).splitlines()[0][:120]})") from None


def _dataset(args) -> int:
    from . import dataset, skidmap

    settings = dataset.CaseSettings(time=args.time, sample_rate=args.sample_rate, settle=args.settle,
                                    band=_band(args.band), depth=args.depth, masking=_masking(args),
                                    fluctuation=_fluctuation(args))
    faults = [f.strip() for f in args.faults.split(",") if f.strip()]
    print(f"vibration data set of {'the reference bearing' if not args.bearing else args.bearing}: faults "
          f"{','.join(faults)}, sizes {args.sizes} m, axial {args.axial}, radial {args.radial}, rpm {args.rpm}, "
          f"{args.time:g} s per case -> {args.out}", flush=True)
    with warnings.catch_warnings():  # a surface start's outcome is in each case's inputs
        warnings.simplefilter("ignore", SurfaceStartWarning)
        result = dataset.dataset(_housed_setup(args), out=args.out, faults=faults,
                                 sizes=skidmap.parse_range(args.sizes), axial_force=skidmap.parse_range(args.axial),
                                 radial_force=skidmap.parse_range(args.radial), rpm=skidmap.parse_range(args.rpm),
                                 settings=settings, workers=args.workers, client=_client(args.scheduler),
                                 progress=lambda line: print(line, flush=True))
    print(f"wrote {len(result.cases)} cases to {args.out}/ (index.csv, inputs.json, one NPZ per case; "
          "pandas.read_csv(index.csv), numpy.load(<case>.npz))")
    failed = [c for c in result.cases if c.error]
    if failed:
        raise RuntimeError(f"{len(failed)} of {len(result.cases)} cases failed (first: {failed[0].name}: "
                           f"{failed[0].error}); a second run retries them")
    return 0


def _masking(args):
    """The :class:`Masking` of ``--snr``, ``--unbalance``, ``--mesh``, ``--housing-mode`` and ``--seed``, or None."""
    from .masking import Masking

    mesh = args.mesh or []
    if mesh and not 2 <= len(mesh) <= 3:
        raise ValueError(f"--mesh: TEETH AMPLITUDE [MODULATION], got {len(mesh)} values")
    if mesh and mesh[0] != int(mesh[0]):
        raise ValueError(f"--mesh: TEETH must be a whole number, got {mesh[0]:g}")
    masking = Masking(snr_db=args.snr, unbalance=args.unbalance, mesh_teeth=int(mesh[0]) if mesh else 0,
                      mesh_amplitude=mesh[1] if mesh else 0.0, mesh_modulation=mesh[2] if len(mesh) > 2 else 0.0,
                      seed=args.seed, modes=tuple(args.housing_mode or ()))
    return masking if masking.active else None


def _fluctuation(args):
    """The :class:`Fluctuation` of ``--speed-fluctuation``, ``--load-fluctuation``,
    ``--fluctuation-bandwidth`` and ``--seed``, or None (steady)."""
    from .masking import Fluctuation

    if not (args.speed_fluctuation or args.load_fluctuation):
        return None
    return Fluctuation(speed_percent=args.speed_fluctuation, load_percent=args.load_fluctuation,
                       bandwidth_hz=args.fluctuation_bandwidth, seed=args.seed)


def _band(words) -> tuple | str | None:
    """``--band``: auto, housing, LOW:HIGH or LOW HIGH (Hz) as :func:`vibration` takes it."""
    text = " ".join(words).strip()
    if text in ("auto", "housing"):
        return None if text == "housing" else text
    parts = text.replace(":", " ").split()
    try:
        low, high = (float(v) for v in parts)
    except ValueError:
        raise ValueError(f"--band: auto, housing, LOW:HIGH or LOW HIGH in Hz, got {text!r}") from None
    if low >= high:
        raise ValueError(f"--band: the low edge {low:g} Hz is not below the high edge {high:g} Hz (reversed?); "
                         "give LOW then HIGH")
    return low, high


def _steps_said(solver: dict) -> str:
    """The run's step(s) in words: one step, or the passage step near passages and the coarse one elsewhere."""
    fine, coarse = solver["step_s"], solver.get("coarse_step_s", solver["step_s"])
    if coarse <= fine:
        return f"{fine:g} s"
    return (f"{fine:g} s near defect passages ({100 * solver['passage_time_share']:.0f} % of the time), "
            f"{coarse:g} s elsewhere")


def _thermal(args, setup):
    """``setup`` with the thermal network's defaults where ``--thermal`` asks for one and the
    bearing file has no ``[thermal]`` (MODEL.md §14); its oil flow the jet's where
    ``[drag] oil_flow`` gives one (one oil, §11c)."""
    if args.thermal and setup.thermal is None:
        from contact.bearing_thermal import ThermalModel

        flow = 0.0 if setup.drag is None else setup.drag.oil_flow
        return setup.replace(thermal=ThermalModel(oil_flow=flow) if flow > 0 else ThermalModel())
    return setup


def _steady(args) -> int:
    from ..results.records import units_of
    from ..criteria import gyroscopic_minimum_axial, hirano_minimum_axial
    from ..solvers.steady import steady_state

    if args.radial != 0:
        return _combined(args)
    if not args.axial > 0:
        raise ValueError(f"--axial must be positive for the steady state (got {args.axial:g} N): give the axial "
                         "load, N")
    setup = _setup(args)
    setup = _thermal(args, setup)
    state = steady_state(setup, axial_force=args.axial, rpm=args.rpm)
    data = state.to_dict()
    data["assumptions"] = assumptions_record(setup.drag, setup.contact_law, setup.lubricant)
    data["units"].update(units_of({"assumptions": data["assumptions"]}))
    criteria = {"hirano_minimum_axial": hirano_minimum_axial(setup.bearing, args.rpm),
                "gyroscopic_minimum_axial": gyroscopic_minimum_axial(
                    setup.bearing, args.rpm, traction_coefficient=setup.lubricant.limiting_shear_coefficient or 0.047)}
    data.update(criteria)
    data["units"].update(units_of(criteria))
    if args.json:
        json.dump(data, sys.stdout, indent=1)
        print()
        return 0 if state.converged else 1
    print_steady(state, data, args)
    return 0 if state.converged else 1


def _combined(args) -> int:
    """``steady --radial R``: the quasi-dynamic state under the combined load (MODEL.md §12a)."""
    from ..results.records import setup_inputs, units_of
    from ..solvers.quasidynamic import combined_load_state

    if args.axial < 0:
        raise ValueError(f"--axial must be >= 0 under radial load (got {args.axial:g} N): give the axial load, N")
    setup = _thermal(args, _setup(args))
    state = combined_load_state(setup, axial_force=args.axial, radial_force=args.radial, rpm=args.rpm)
    data = state.to_dict()
    data["assumptions"] = assumptions_record(setup.drag, setup.contact_law, setup.lubricant)
    data["units"].update(units_of({"assumptions": data["assumptions"]}))
    data["inputs"] = setup_inputs(setup)
    if args.json:
        json.dump(data, sys.stdout, indent=1)
        print()
    else:
        print_combined(state, data, args)
    return 0 if state.converged else 1


def _skid_map(args) -> int:
    from . import skidmap

    setup = _setup(args)
    client = _client(args.scheduler)
    print(f"skid-risk map of {'the reference bearing' if not args.bearing else args.bearing}: "
          f"axial {args.axial}, radial {args.radial}, rpm {args.rpm}, "
          f"{'until settled' if args.time is None else f'{args.time:g} s'} per point -> {args.out}", flush=True)

    result = skidmap.skid_map(setup, axial_force=skidmap.parse_range(args.axial),
                              radial_force=skidmap.parse_range(args.radial), rpm=skidmap.parse_range(args.rpm),
                              time=args.time, out=args.out, workers=args.workers, client=client,
                              progress=lambda line: print(line, flush=True), refine=not args.no_refine)
    print(result.markdown())
    print(f"wrote {args.out}/" + ", ".join(result.files))
    if "skid_map.png" not in result.files:
        print("skid_map.png not written: matplotlib is missing (pip install -e '.[plot]')")
    failed = [p for p in result.points if p.error]
    if failed:
        raise RuntimeError(f"{len(failed)} of {len(result.points)} points failed (first: F_a {failed[0].axial:g} N, "
                           f"F_r {failed[0].radial:g} N, {failed[0].rpm:g} rpm: {failed[0].error}); see "
                           f"{args.out}/skid_map.md; a second run retries them")
    return 0


def _render(args) -> int:
    from .render import render_run

    if not (math.isfinite(args.time) and args.time > 0):
        raise ValueError(f"--time must be a positive number of seconds, got {args.time!r}")
    setup = _setup(args)
    if args.gif:
        from pathlib import Path

        if not Path(args.gif).resolve().parent.is_dir():
            raise ValueError(f"--gif: the folder of {args.gif} does not exist")
    files = render_run(args.out, axial_force=args.axial, radial_force=args.radial, rpm=args.rpm, time=args.time,
                       frames=args.frames, backend=args.backend, bearing=setup, animation=args.gif)
    print(f"wrote {len(files)} frame(s): {', '.join(str(f) for f in files)}")
    return 0


def _law(args, setup, **kw):
    """The bearing file's ContactLaw (``setup``; ContactLaw() without a file) with what a
    command's --traction and switches (--rolling-resistance, --thermal-film: any option named
    after a true-or-false field of the law) and ``kw`` (not None) change."""
    from dataclasses import fields, replace

    changes = {k: v for k, v in kw.items() if v is not None}
    if getattr(args, "traction", None) is not None:
        changes["traction"] = args.traction
    for f in fields(setup.contact_law):
        if f.type == "bool" and getattr(args, f.name, False) is True:
            changes[f.name] = True
    return replace(setup.contact_law, **changes)


def build_parser() -> argparse.ArgumentParser:
    from importlib.metadata import PackageNotFoundError, version

    # the installed command names itself; ``python -m exudyn_bearing`` runs __main__.py
    invoked = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else ""
    parser = argparse.ArgumentParser(prog="exudyn-bearing" if invoked.startswith("exudyn-bearing")
                                     else "python -m exudyn_bearing",
                                     description="Skidding analysis of angular-contact ball bearings with Exudyn.")
    try:
        versions = f"exudyn-bearing {version('exudyn-bearing')} (exudyn {version('exudyn')})"
    except PackageNotFoundError:
        versions = "exudyn-bearing (not installed)"
    parser.add_argument("--version", action="version", version=versions)
    sub = parser.add_subparsers(dest="command", required=True)
    run = {"loads": _loads, "simulate": _simulate, "steady": _steady, "render": _render, "vibration": _vibration,
           "skid-map": _skid_map, "dataset": _dataset}
    for name, (text, add_options) in COMMANDS.items():
        # every command's --help shows the defaults
        p = sub.add_parser(name, help=text, formatter_class=DefaultsFormatter)
        add_options(p)
        p.set_defaults(func=run[name])
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(join_negative_values(sys.argv[1:] if argv is None else list(argv)))
    try:
        code = args.func(args)
        sys.stdout.flush()  # a closed pipe shows here, not as an error at interpreter exit
        return code
    except BrokenPipeError:  # e.g. `loads ... | head`: the reader went away, nothing to report
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except ValueError as err:  # the functions' input names as the options that set them
        message = re.sub(r"\b(axial|radial)_force\b", r"--\1", str(err))
        parser.exit(2, f"error: {message}\n")
    except RuntimeError as err:  # solver failures carry their own explanation
        parser.exit(1, f"error: {err}\n")


def run() -> int:
    """The command line's entry point (the ``exudyn-bearing`` script and ``python -m
    exudyn_bearing``): :func:`main`, then an exit without the interpreter's last garbage
    collection (:func:`~exudyn_bearing.studies.grid.skip_final_collection`)."""
    from .grid import skip_final_collection

    code = main()
    skip_final_collection()
    return code
