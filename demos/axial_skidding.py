"""Cage slip and ball attitude versus axial load at 1800 rpm (paper figure 5).

An ordinary Exudyn scene per load: the reference bearing (Z = 16, 40 deg, MODEL.md §8) with
its inner race driven at 1800 rpm and pushed by the axial force, outer race fixed, rigid
cage, Crook EHD traction and ball drag. Writes a table (markdown + JSON) and, with
matplotlib, a PNG to ``out/axial_skidding``.

    python demos/axial_skidding.py            # full sweep (long: light loads settle slowly)
    python demos/axial_skidding.py --quick    # short runs, transients flagged as unsettled
"""
import argparse
import json
import time
from pathlib import Path

import exudyn as exu

from exudyn_bearing import (BearingSimulationError, CreateAngularContactBearing, races, run_solver, settled_label,
                            SolverSettings)


def run(axial, sim_time, drag=True, step=None):
    """One scene: returns the summary over the last third of the run, the run info and the
    scene's inputs (what produced the result)."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    kwargs = {} if drag else {"ballDrag": None}
    bearing = CreateAngularContactBearing(mbs, innerRace=races.Driven(rpm=1800), outerRace=races.Fixed(),
                                          axialForce=axial, show=False, **kwargs)
    mbs.Assemble()
    info = run_solver(mbs, [bearing], sim_time, SolverSettings(step=step, output_step=1e-3))
    return bearing.Results(mbs).summary(), info, bearing.Inputs(step=step)


def crossing(loads, slips, level=1.0):
    """Load where the (falling) slip curve first drops below ``level`` %, interpolated."""
    for (f0, s0), (f1, s1) in zip(zip(loads, slips), zip(loads[1:], slips[1:])):
        if s0 >= level > s1:
            return f0 + (s0 - level) * (f1 - f0) / (s0 - s1)
    return None


def report(rows, failed=()):
    """The markdown table and the 1 % crossings of the points that ran through."""
    loads = [r["axial_N"] for r in rows]
    kin = [r["kinematic_cage_slip_percent"] for r in rows]
    p19 = [r["cage_slip_percent"] for r in rows]
    f_kin, f_p19 = crossing(loads, kin), crossing(loads, p19)
    lines = ["| F_a (N) | kinematic cage slip (%) | cage slip P19 (%) | beta_XZ (deg) | beta_YZ (deg) | settled | "
             "simulated (s) | wall (s) |", "|---:|---:|---:|---:|---:|:---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['axial_N']:.0f} | {r['kinematic_cage_slip_percent']:.3f} | {r['cage_slip_percent']:.3f} | "
                     f"{r['attitude_xz_deg']:.2f} | {r['attitude_yz_deg']:.2f} | {settled_label(r['settled'])} | "
                     f"{r['time_s']:g} | {r['wall_s']:.0f} |")
    for fa, err in failed:
        lines.append(f"| {fa:.0f} | failed: {err} | | | | | | |")
    if len(rows) < 2:
        return "\n".join(lines)
    lines.append("")
    lines.append(f"Kinematic cage slip crosses 1 % at F_a = {f_kin:.0f} N" if f_kin
                 else "Kinematic cage slip does not cross 1 % in this range")
    lines.append("(paper, fixed 40 deg angles and P19 cage slip: about 1.3 kN).")
    monotonic = all(a > b for a, b in zip(p19, p19[1:]))
    if f_p19 and monotonic:
        lines.append(f"P19 cage slip crosses 1 % at {f_p19:.0f} N.")
    else:
        lines.append((f"P19 cage slip first drops below 1 % at {f_p19:.0f} N but " if f_p19 else "P19 cage slip ")
                     + "is not monotonic in load: its reference speed uses the nominal 40 deg, which mixes the "
                     "kinematic change of the cage speed (inner and outer angles differ under centrifugal force and "
                     "the ball axes turn with load) into it (MODEL.md §7); judge skidding by the kinematic slip.")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="short runs (0.05 s each)")
    parser.add_argument("--loads", default="200,400,700,1000,1300,1700,2200,3000", help="axial loads, N")
    parser.add_argument("--time", default=None,
                        help="simulated time per load, s: one value for all loads or one per load "
                             "(default: 5 s below 300 N, 2 s below 1.5 kN, where the cage and the ball axes "
                             "settle slowly; 0.3 s above)")
    parser.add_argument("--step", type=float, default=None,
                        help="time step, s (default: the bearing's recommended step, MODEL.md §10a)")
    parser.add_argument("--no-drag", action="store_true",
                        help="without ball drag (MODEL.md §7: the kinematic slip should then stay near zero)")
    parser.add_argument("--out", default="out/axial_skidding")
    parser.add_argument("--compare", default=None,
                        help="axial_skidding.json of another run whose kinematic slip the figure shows too")
    parser.add_argument("--compare-label", default="other run", help="its label in the figure")
    parser.add_argument("--replot", action="store_true", help="redraw the figure from --out's JSON, no runs")
    args = parser.parse_args()
    loads = [float(v) for v in args.loads.split(",")]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.replot:
        saved = json.loads((out / "axial_skidding.json").read_text())
        rows = [r for r in (saved["rows"] if isinstance(saved, dict) else saved) if "failed" not in r]
        plot(rows, out, args.compare, args.compare_label)
        return
    rows, failed, inputs = [], [], None
    times = [float(v) for v in args.time.split(",")] if args.time else None
    if times is not None and len(times) not in (1, len(loads)):
        parser.error("--time takes one value or one per load")
    for i, fa in enumerate(loads):
        if times is not None:
            sim_time = times[0] if len(times) == 1 else times[i]
        else:
            sim_time = 0.05 if args.quick else (5.0 if fa < 300 else 2.0 if fa < 1500 else 0.3)
        start = time.perf_counter()
        try:
            summary, info, inputs = run(fa, sim_time, drag=not args.no_drag, step=args.step)
        except BearingSimulationError as err:  # report the failed point, go on with the others
            print(f"F_a {fa:6.0f} N: FAILED after {time.perf_counter() - start:.0f} s: {err}", flush=True)
            failed.append((fa, str(err)))
            continue
        rows.append(dict(axial_N=fa, time_s=sim_time, wall_s=time.perf_counter() - start, steps=info.steps, **summary))
        r = rows[-1]
        print(f"F_a {fa:6.0f} N: kinematic slip {r['kinematic_cage_slip_percent']:7.3f} %, "
              f"P19 {r['cage_slip_percent']:7.3f} %, "
              f"beta_XZ {r['attitude_xz_deg']:5.1f} deg, beta_YZ {r['attitude_yz_deg']:5.2f} deg, "
              f"settled {r['settled']}, {sim_time} s simulated in {r['wall_s']:.0f} s", flush=True)
    text = report(rows, failed)
    print(text)
    (out / "axial_skidding.md").write_text(text + "\n")
    failures = [dict(axial_N=fa, failed=err) for fa, err in failed]
    (out / "axial_skidding.json").write_text(json.dumps({"inputs": inputs, "rows": rows + failures}, indent=1))
    plot(rows, out, args.compare, args.compare_label)


def plot(rows, out, compare=None, compare_label="other run"):
    """The figure of ``rows``, with the kinematic slip of the ``compare`` JSON if given."""
    try:
        from exudyn_bearing.results.plots import plot_skid_curve
    except ImportError as err:
        print(f"{err}: no plot")
        return
    reference = None
    if compare:
        other = [r for r in json.loads(Path(compare).read_text()) if "failed" not in r]
        reference = (compare_label, [r["axial_N"] for r in other], [r["kinematic_cage_slip_percent"] for r in other])
    plot_skid_curve(*([r[k] for r in rows] for k in ("axial_N", "kinematic_cage_slip_percent", "cage_slip_percent",
                                                     "attitude_xz_deg", "attitude_yz_deg", "settled")),
                    path=out / "axial_skidding.png", title="Reference bearing, 1800 rpm", reference=reference)
    print(f"wrote {out}/axial_skidding.png")


if __name__ == "__main__":
    main()
