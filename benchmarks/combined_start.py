"""Time to settle under combined load from the quasi-dynamic start ('auto', MODEL.md §12a)
and from pure rolling ('rolling'): the kinematic cage slip, mean over the 50 ms before each
time, reference bearing at 1800 rpm; and the cost of the quasi-dynamic solve on other bearings.

    python benchmarks/combined_start.py [--axial 300,800] [--radial 200] [--time 2.0]

docs/DEVELOPMENT.md, 'Start states', gives the figures of a run of it.
"""
import argparse
import time

import numpy as np

from exudyn_bearing import REFERENCE_BEARING, REFERENCE_DRAG, REFERENCE_LUBRICANT, SolverSettings, simulate, steady_state
from exudyn_bearing.presets import (ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG,
                                    SPINDLE_40MM_BEARING)
from exudyn_bearing.solvers.quasidynamic import combined_load_state

MARKS = (0.05, 0.1, 0.2, 0.4, 0.8, 1.2, 1.6, 2.0)
SOLVES = (("reference", REFERENCE_BEARING, REFERENCE_LUBRICANT, REFERENCE_DRAG, 400.0, 100.0, 1800.0),
          ("reference", REFERENCE_BEARING, REFERENCE_LUBRICANT, REFERENCE_DRAG, 400.0, 300.0, 1800.0),
          ("reference", REFERENCE_BEARING, REFERENCE_LUBRICANT, REFERENCE_DRAG, 800.0, 500.0, 1800.0),
          ("40-mm spindle", SPINDLE_40MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, 50.0, 20.0, 40000.0),
          ("40-mm spindle", SPINDLE_40MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, 1000.0, 500.0, 55000.0),
          ("35-mm high-speed", HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, 200.0, 100.0, 48000.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--axial", default="300,800", help="axial loads, N, comma-separated")
    parser.add_argument("--radial", type=float, default=200.0, help="radial load, N")
    parser.add_argument("--time", type=float, default=2.0, help="simulated time per run, s")
    args = parser.parse_args()
    print("| bearing | F_a (N) | F_r (N) | rpm | axial-only kinematic slip (%) | quasi-dynamic solve (s) | cage speed (rad/s) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, b, lub, drag, axial, radial, rpm in SOLVES:
        st = steady_state(b, lub, axial_force=axial, rpm=rpm, ball_drag=drag)
        state = combined_load_state(b, lub, axial_force=axial, radial_force=radial, rpm=rpm, ball_drag=drag, steady=st)
        print(f"| {name} | {axial:g} | {radial:g} | {rpm:g} | {st.kinematic_cage_slip_percent:.2f} | "
              f"{state.wall_time_s:.2f} | {state.cage_speed:.3f}{'' if state.converged else ' (' + state.message + ')'} |")
    marks = [m for m in MARKS if m <= args.time + 1e-9]
    print(f"\n| F_a (N) | start | wall (s) | at 0 | " + " | ".join(f"{m:g} s" for m in marks) + " |")
    print("|---:|---|---:|---:|" + "---:|" * len(marks))
    for axial in (float(a) for a in args.axial.split(",")):
        for start in ("auto", "rolling"):
            t0 = time.perf_counter()
            run = simulate(axial_force=axial, radial_force=args.radial, rpm=1800.0, time=args.time, initial_state=start,
                           settings=SolverSettings(progress=False))
            wall = time.perf_counter() - t0
            t, k = run.results.time, run.results.kinematic_cage_slip_percent
            means = [float(np.mean(k[(t > m - 0.05) & (t <= m + 1e-9)])) for m in marks]
            print(f"| {axial:g} | {start} | {wall:.1f} | {k[0]:.2f} | " + " | ".join(f"{v:.2f}" for v in means) + " |",
                  flush=True)


if __name__ == "__main__":
    main()
