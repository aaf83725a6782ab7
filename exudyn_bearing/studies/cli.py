"""Command line: ``python -m exudyn_bearing COMMAND ...`` (see ``--help``)."""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys

import numpy as np

from contact.traction_laws import TRACTION_LAWS
from contact.ballrace import ContactLaw as ContactLawDefaults
from ..bearingfile import as_setup
from ..presets import REFERENCE_BEARING
from ..setup import FROM_SETUP, BearingSetup
from ..results.records import assumptions_line, assumptions_record


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
    dx, dy, dz = result.displacement * 1e6
    print(f"inner-race displacement: x {dx:.3f} um, y {dy:.3f} um, axial {dz:.3f} um; "
          f"tilt {np.degrees(result.tilt).round(6).tolist()} deg; max contact load {result.max_load:.1f} N")
    if np.any(result.reaction_moment != 0):
        print(f"reaction moment on the shaft (tilt held): {result.reaction_moment.round(4).tolist()} N m")
    return 0


def _simulate(args) -> int:
    from ..simulation.runner import SolverSettings, simulate

    if args.axial == 0 and args.radial == 0:
        raise ValueError("no load: give --axial and/or --radial, N (both default to 0)")
    setup = _setup(args)
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
                       settings=settings, error_estimate=args.error_estimate, initial_state=args.start)
    data = summary.to_dict()
    if args.plot:
        from ..results.plots import plot_run

        plot_run(summary.results, args.plot, title=f"F_a {args.axial:g} N, F_r {args.radial:g} N, {args.rpm:g} rpm")
        data["plot"] = str(args.plot)
    if args.json:
        json.dump(data, sys.stdout, indent=1)
        print()
        return 0
    print(f"Dynamic run: axial {args.axial:g} N, radial {args.radial:g} N, inner race {args.rpm:g} rpm, "
          f"{args.time:g} s simulated (means over the last third)")
    print(f"  kinematic cage slip (MODEL.md §7)   {data['kinematic_cage_slip_percent']:8.3f} %   (the skid measure)")
    print(f"  paper's P19 cage slip (nominal)     {data['cage_slip_percent']:8.3f} %")
    print(f"  assumptions                         {assumptions_line(data['assumptions'])}")
    print(f"  cage speed                          {data['cage_speed']:8.3f} rad/s "
          f"(nominal {data['cage_speed_nominal']:.3f})")
    verdict = {True: "yes", False: "NO (still drifting: run longer)",
               None: "too short to judge (runs under 0.05 s)"}[data["settled"]]
    print(f"  settled                             {verdict}")
    d = data["details"]
    print(f"  max inner/outer load                {d['max_inner_load']:.1f} / {d['max_outer_load']:.1f} N")
    loss = data["power_loss_W"]
    parts = ", ".join(f"{k.replace('_', ' ')} {v:.1f}" for k, v in loss.items() if k != "total" and abs(v) >= 0.05)
    print(f"  power loss (MODEL.md §11)           {loss['total']:8.1f} W ({parts or 'none'}); "
          f"drive {data['drive_power_W']:.1f} W")
    remainder = {True: "settled: the integrator's damping only",
                 False: "not settled: it includes kinetic energy still changing",
                 None: "too short to judge: it includes kinetic energy still changing"}[data["settled"]]
    print(f"  energy balance (drive - loss)       {d['energy_balance_percent']:8.2f} % of the drive ({remainder})")
    print(f"  solver {data['solver']['solver']}, step {data['solver']['step']:g} s, {data['steps']} steps, "
          f"{data['newton_iterations']} Newton iterations, {data['jacobian_updates']} Jacobian updates, "
          f"wall time {data['wall_time_s']:.1f} s")
    est = data.get("error_estimate")
    if est:
        print(f"  error estimate ({est['method']}, {est['reference_wall_time_s']:.1f} s more wall time):")
        print(f"    cage slip {est['cage_slip_percent']:.3g} pp, kinematic cage slip "
              f"{est['kinematic_cage_slip_percent']:.3g} pp, cage speed {est['cage_speed']:.3g} rad/s, "
              f"max inner load {est['max_inner_load']:.3g} N")
    if args.plot:
        print(f"  plots written to {args.plot}")
    return 0


def _vibration(args) -> int:
    from pathlib import Path

    from dataclasses import replace

    from ..races import HousingModel
    from .vibration import plot_vibration, vibration, write_signal

    if args.axial == 0 and args.radial == 0:
        raise ValueError("no load: give --axial and/or --radial, N (both default to 0)")
    setup = _setup(args)
    # the file's [housing] (else HousingModel()), with what the options change
    housing = setup.housing or HousingModel()
    changes = {k: v for k, v in (("frequency", args.housing_frequency), ("mass", args.housing_mass),
                                 ("damping_ratio", args.housing_damping)) if v is not None}
    setup = setup.replace(housing=replace(housing, **changes))
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    result = vibration(setup, rpm=args.rpm, axial_force=args.axial, radial_force=args.radial, time=args.time,
                       sample_rate=args.sample_rate, settle=args.settle, band=tuple(args.band) if args.band else None,
                       error_estimate=args.error_estimate)
    signal = out / "signal.csv"
    write_signal(result, signal)
    data = result.to_dict() | {"signal": str(signal)}
    if args.plot:
        plot_vibration(result, args.plot, title=f"F_a {args.axial:g} N, F_r {args.radial:g} N, {args.rpm:g} rpm")
        data["plot"] = str(args.plot)
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
    for i, d in enumerate(surf.defects):
        # R_x at the nominal angle (a ball's pit meets the outer race first)
        reach = d.reach(b.curvature_radii(b.contact_angle, "outer" if d.race == "ball" else d.race)[0])
        note = "" if reach >= d.depth else f"; a ball reaches {reach * 1e6:.2f} um of its {d.depth * 1e6:g} um depth"
        where = f"ball {d.ball} at {d.angle_deg:g} deg" if d.race == "ball" else f"{d.race} race at {d.angle_deg:g} deg"
        print(f"  defect {i}: {where}, {d.length * 1e3:g} mm long{note}")
    if surf.waviness.active:
        print(f"  waviness: inner {list(surf.waviness.inner)}, outer {list(surf.waviness.outer)}, "
              f"ball {list(surf.waviness.ball)}")
    if result.solver.get("surface_start"):
        print(f"  {result.solver['surface_start']} (MODEL.md §13d)")
    print(f"  kinematic cage slip {result.kinematic_cage_slip_percent:.3f} %")
    print(f"  fault frequencies: nominal (catalogue formula, nominal contact angle), kinematic (pure rolling at the "
          f"run's contact geometry), actual (the run's cage and ball speeds)")
    print(f"  {'':6} {'nominal Hz':>11} {'kinematic Hz':>13} {'actual Hz':>11} {'actual x shaft':>15}")
    faults = result.fault_frequencies
    for name in faults["kinematic"]:
        print(f"  {name:6} {faults['nominal'][name]:11.3f} {faults['kinematic'][name]:13.3f} "
              f"{faults['actual'][name]:11.3f} {faults['actual'][name] / (args.rpm / 60):15.4f}")
    peaks = ", ".join(f"{f:.2f} Hz ({a:.3g})" for f, a in result.envelope_peaks[:5])
    print(f"  envelope peaks (band {result.band[0]:.0f}-{result.band[1]:.0f} Hz, m/s^2): {peaks}")
    sv = result.solver
    print(f"  defect passages: {len(result.defect_events)}; signal {signal}; wall time {result.wall_time_s:.1f} s "
          f"(step {sv['step_s']:g} s, strike number {sv['strike_number']:.2g}, defect reach "
          f"{sv['reach_share']:.2g} of the approach, {sv['steps']} steps, "
          f"{sv['extra_steps']} more than planned; {sv['step_cuts']} step cuts, after {sv['passages_cut']} of the "
          f"{sv['passages']} passages)")
    est = result.error_estimate
    if est:
        print(f"  error estimate ({est['method']}, {est['reference_wall_time_s']:.1f} s more wall time): strongest "
              f"envelope line {est['envelope_line_Hz']:.3g} Hz, its amplitude {est['envelope_amplitude_percent']:.2g} % "
              f"(error bound {est['envelope_amplitude_bound_percent']:.2g} %), "
              f"kinematic cage slip {est['kinematic_cage_slip_pp']:.2g} pp")
    if args.plot:
        print(f"  plot written to {args.plot}")
    return 0


def _steady(args) -> int:
    from ..results.records import units_of
    from ..criteria import gyroscopic_minimum_axial, hirano_minimum_axial
    from ..solvers.steady import steady_state

    if args.radial != 0:
        raise ValueError(f"--radial {args.radial:g}: steady solves the pure axial load (MODEL.md §12); for a combined "
                         f"load run 'simulate --axial A --radial {args.radial:g} --start steady', which starts from "
                         "every ball's own balance (MODEL.md §12a)")
    if not args.axial > 0:
        raise ValueError(f"--axial must be positive for the steady state (got {args.axial:g} N): give the axial "
                         "load, N")
    setup = _setup(args)
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
    print(f"Steady rolling state (MODEL.md §12): axial {args.axial:g} N, inner race {args.rpm:g} rpm"
          f"{', no drag' if args.no_drag else ''}")
    if not state.converged:
        print(f"  NOT CONVERGED: {state.message}")
    print(f"  kinematic cage slip (MODEL.md §7)   {state.kinematic_cage_slip_percent:8.3f} %   (the skid measure)")
    print(f"  paper's P19 cage slip (nominal)     {state.cage_slip_percent:8.3f} %")
    print(f"  assumptions                         {assumptions_line(data['assumptions'])}")
    print(f"  cage speed                          {state.cage_speed:8.3f} rad/s (nominal {state.nominal_cage_speed:.3f})")
    print(f"  ball attitude xz / yz               {state.attitude_xz_deg:8.3f} / {state.attitude_yz_deg:.3f} deg")
    print(f"  inner / outer load                  {state.inner_load:8.2f} / {state.outer_load:.2f} N")
    print(f"  inner / outer contact angle         {state.inner_contact_angle_deg:8.2f} / "
          f"{state.outer_contact_angle_deg:.2f} deg")
    print(f"  minimum axial load: Hirano {data['hirano_minimum_axial']:.0f} N, Jones' gyroscopic criterion "
          f"{data['gyroscopic_minimum_axial']:.0f} N")
    print(f"  wall time {state.wall_time_s:.2f} s")
    return 0 if state.converged else 1


def _skid_map(args) -> int:
    from . import skidmap

    setup = _setup(args)
    client = None
    if args.scheduler:
        try:
            from dask.distributed import Client
        except ImportError:
            raise ValueError("--scheduler needs dask[distributed]: pip install -e .[dask]") from None
        try:
            client = Client(args.scheduler, timeout="10s")
        except (OSError, TimeoutError) as err:
            raise ValueError(f"--scheduler: cannot reach {args.scheduler} ({str(err).splitlines()[0][:120]})") from None
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
    command's --traction, --rolling-resistance, --thermal-film (and ``kw`` not None) change."""
    from dataclasses import replace

    changes = {k: v for k, v in kw.items() if v is not None}
    if getattr(args, "traction", None) is not None:
        changes["traction"] = args.traction
    for flag in ("rolling_resistance", "thermal_film"):
        if getattr(args, flag, False):
            changes[flag] = True
    return replace(setup.contact_law, **changes)


#: the loads' help: units and sign conventions, the same in every command
AXIAL_HELP = ("axial force on the inner race, N, along the bearing axis (+z of the bearing frame): it presses the "
              "inner race against the balls' contact side; >= 0 (a load the other way: mount the bearing the other "
              "way round)")
RADIAL_HELP = "radial force on the inner race, N, along the bearing frame's x axis"
#: single-value options whose value may start with a minus sign ("-300,300", "-300:300:5")
_LIST_OPTIONS = ("--axial", "--radial", "--rpm")
_NUMBER_LIST = re.compile(r"^-[0-9.][0-9.eE+\-]*([,:][-+]?[0-9.][0-9.eE+\-]*)*$")


def _join_negative_values(argv):
    """``--axial -300,300`` → ``--axial=-300,300``: argparse reads a value starting with "-"
    that is not a plain number as an option."""
    out = []
    for token in argv:
        if out and out[-1] in _LIST_OPTIONS and _NUMBER_LIST.match(token):
            out[-1] = f"{out[-1]}={token}"
        else:
            out.append(token)
    return out


def _traction_option(p) -> None:
    p.add_argument("--traction", choices=tuple(TRACTION_LAWS), default=None,
                   help="ball-race traction law: " + "; ".join(f"{m.name} = {m.summary}" for m in TRACTION_LAWS.values())
                        + " (default: the bearing file's [contact_law], else crook-limited)")
    # the losses beyond the paper (MODEL.md §11), off by default
    p.add_argument("--rolling-resistance", action="store_true",
                   help="hydrodynamic rolling resistance at each contact (MODEL.md §11b; or the bearing file's "
                        "[contact_law])")
    p.add_argument("--thermal-film", action="store_true",
                   help="inlet-shear-heating reduction of the film thickness (MODEL.md §11e; or the bearing file's "
                        "[contact_law])")


class _DefaultsFormatter(argparse.HelpFormatter):
    """Appends "(default: X)" where an option has a default and its help does not name one."""

    def _get_help_string(self, action):
        text = action.help or ""
        if (action.default not in (None, False, argparse.SUPPRESS) and "default" not in text
                and action.option_strings):
            text += " (default: %(default)s)"
        return text


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
    _add_parser = sub.add_parser

    def add_parser(*args, **kw):  # every command's --help shows the defaults
        return _add_parser(*args, formatter_class=_DefaultsFormatter, **kw)

    sub.add_parser = add_parser
    p = sub.add_parser("loads", help="quasi-static load distribution (MODEL.md §4)")
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--rpm", type=float, default=0.0, help="inner-race speed, rev/min (0: no centrifugal force)")
    p.add_argument("--moment", type=float, nargs=2, metavar=("MX", "MY"), help="tilting moment, N m (frees the tilt)")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    p.add_argument("--fixed-angle", action="store_true", help="the paper's fixed contact angle (P4–P6)")
    p.add_argument("--hold-axial", action="store_true", help="hold the axial displacement at zero")
    p.add_argument("--exact-hertz", action="store_true", help="exact elliptic integrals instead of Brewe–Hamrock")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.set_defaults(func=_loads)

    from ..simulation.runner import SOLVERS

    p = sub.add_parser("simulate", help="dynamic Exudyn run of one bearing (MODEL.md §1–§7)")
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--rpm", type=float, default=1800.0, help="inner-race speed, rev/min (outer race fixed)")
    p.add_argument("--time", type=float, default=0.05, help="simulated time, s")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    p.add_argument("--solver", choices=SOLVERS, default="generalized-alpha", help="time integrator")
    p.add_argument("--step", type=float, default=None,
                   help="time step, s (default: 1e-4, less for small, stiff balls; docs/MODEL.md §10a)")
    p.add_argument("--output-step", type=float, default=5e-4, help="output period, s")
    p.add_argument("--order", type=int, default=None,
                   help="traction quadrature order (default: the bearing file's [contact_law], else "
                        f"{ContactLawDefaults.quadrature_order})")
    _traction_option(p)
    p.add_argument("--no-drag", action="store_true", help="switch the ball drag off")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--error-estimate", action="store_true",
                   help="repeat at half the step and report the differences as an error estimate")
    p.add_argument("--start", choices=("auto", "steady", "rolling"), default="auto",
                   help="start state: steady (axial: the steady state; combined load: every ball's own balance, "
                        "MODEL.md §12a), rolling (pure rolling), auto (steady where it applies, else rolling)")
    p.add_argument("--plot", metavar="PNG", help="save the paper-style plots of the run (needs the plot extra)")
    p.set_defaults(func=_simulate)
    p = sub.add_parser("steady", help="steady rolling state under pure axial load, no time integration (MODEL.md §12)")
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP + "; > 0 here")
    p.add_argument("--radial", type=float, default=0.0,
                   help="must be 0: steady solves pure axial load; for a combined load use "
                        "'simulate --radial R --start steady' (every ball's own balance, MODEL.md §12a)")
    p.add_argument("--rpm", type=float, default=1800.0, help="inner-race speed, rev/min (outer race fixed)")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    _traction_option(p)
    p.add_argument("--no-drag", action="store_true", help="switch the ball drag off")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(func=_steady)
    p = sub.add_parser("render", help="render a run to PNG frames (headless: Xvfb/OpenGL or the raytracer)")
    p.add_argument("--axial", type=float, default=1300.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--rpm", type=float, default=1800.0, help="inner-race speed, rev/min")
    p.add_argument("--time", type=float, default=0.002, help="simulated time, s")
    p.add_argument("--frames", type=int, default=4, help="number of frames spread over the run")
    p.add_argument("--backend", choices=("auto", "opengl", "raytracer"), default="auto",
                   help="auto: OpenGL with an X display (e.g. xvfb-run), else the raytracer")
    p.add_argument("--out", required=True, help="output directory")
    p.add_argument("--gif", help="also write the frames as an animated GIF to this file")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    _traction_option(p)
    p.set_defaults(func=_render)

    p = sub.add_parser("vibration", help="housing vibration with race defects and waviness (MODEL.md §13)")
    p.add_argument("--bearing", help="bearing TOML file with [[defect]] / [waviness] (default: the reference bearing)")
    p.add_argument("--rpm", type=float, required=True, help="inner-race speed, rev/min (outer race on the housing)")
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--time", type=float, default=0.5, help="simulated time, s")
    p.add_argument("--settle", type=float, default=0.02, help="start left out of the spectra, s")
    p.add_argument("--sample-rate", type=float, default=20000.0, help="output sample rate, Hz (the step is at most "
                                                                        "its period; the housing is recorded through an "
                                                                        "anti-aliasing filter at 0.4 x this rate)")
    p.add_argument("--band", type=float, nargs=2, metavar=("LOW", "HIGH"),
                   help="envelope band, Hz (default: 0.6-1.4 x the housing resonance)")
    p.add_argument("--housing-frequency", type=float, help="housing resonance, Hz (default: the bearing file's "
                                                           "[housing], else 3000)")
    p.add_argument("--housing-mass", type=float, help="housing mass (ring included), kg (default: the file's, else 2)")
    p.add_argument("--housing-damping", type=float, help="housing damping ratio (default: the file's, else 0.05)")
    p.add_argument("--out", default="out/vibration", help="output directory (signal.csv, vibration.json)")
    p.add_argument("--error-estimate", action="store_true",
                   help="repeat at half the step and report the changes of the strongest envelope line "
                        "(twice the amplitude's change bounds its error, MODEL.md §13c)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--plot", metavar="PNG", help="signal, spectrum and envelope spectrum with the fault frequencies")
    p.set_defaults(func=_vibration)

    from . import skidmap

    p = sub.add_parser("skid-map", help="skid-risk map over load and speed (the main job)")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    p.add_argument("--axial", default=",".join(f"{v:g}" for v in skidmap.DEFAULT_AXIAL),
                   help="axial loads, N: start:stop:count or a,b,c (" + AXIAL_HELP.split(", N, ", 1)[1] + ")")
    p.add_argument("--radial", default="0", help="radial loads, N: start:stop:count or a,b,c (along the bearing "
                                                 "frame's x axis)")
    p.add_argument("--rpm", default=",".join(f"{v:g}" for v in skidmap.DEFAULT_RPM), help="inner-race speeds, rpm")
    p.add_argument("--time", type=float, default=skidmap.DEFAULT_TIME,
                   help="fixed simulated time per point, s (default: until settled, 0.1 s doubling up to "
                        f"{skidmap.MAX_TIME:g} s)")
    p.add_argument("--out", default="out/skid_map", help="output directory (resumes what it finds there)")
    p.add_argument("--workers", type=int, default=None, help="local worker processes (default: CPU count)")
    p.add_argument("--scheduler", help="Dask scheduler address (runs the grid on that cluster)")
    p.add_argument("--no-refine", action="store_true",
                   help="skip the thresholds' steady-state refinement and its dynamic confirmation")
    _traction_option(p)
    p.set_defaults(func=_skid_map)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(_join_negative_values(sys.argv[1:] if argv is None else list(argv)))
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
