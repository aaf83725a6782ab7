"""Time-varying operation: a run-up 0 -> 1800 rpm in 50 ms under 1.3 kN, then a gust-like
axial load drop to 300 N at t = 0.1 s: cage slip and ball slip rise and fall.

Uses ``Driven(rpm=function of t)`` (the race follows the prescribed speed) and
``axialForce=function of t``. Writes PNG + JSON to ``out/transient_skidding``.

    python demos/transient_skidding.py [--time 0.15]
"""
import argparse
import json
from pathlib import Path

import numpy as np
import exudyn as exu

from exudyn_bearing import CreateAngularContactBearing, races, run_solver, SolverSettings

RUN_UP, DROP_TIME = 0.05, 0.1  # s


def speed_rpm(t):
    return 1800.0 * min(max(t, 0.0) / RUN_UP, 1.0)


def axial_force(t):
    return 1300.0 if t < DROP_TIME else 300.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.15, help="simulated time, s")
    parser.add_argument("--out", default="out/transient_skidding")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    bearing = CreateAngularContactBearing(mbs, innerRace=races.Driven(rpm=speed_rpm), outerRace=races.Fixed(),
                                          axialForce=axial_force, show=False)
    mbs.Assemble()
    info = run_solver(mbs, [bearing], args.time, SolverSettings(output_step=5e-4))
    res = bearing.Results(mbs)
    slip = 0.5 * (res.inner["slip"].mean(axis=1) + res.outer["slip"].mean(axis=1))
    print(f"run: {info.steps} steps, wall {info.wall_time_s:.0f} s")
    for t_show in (0.02, 0.05, 0.09, 0.12, args.time):
        k = min(np.searchsorted(res.time, t_show), len(res.time) - 1)
        print(f"t = {res.time[k]:.3f} s: inner {res.inner_speed[k] * 30 / np.pi:7.1f} rpm, axial "
              f"{axial_force(res.time[k]):6.0f} N, kinematic cage slip {res.kinematic_cage_slip_percent[k]:7.3f} %, "
              f"mean ball slip {slip[k]:.4f} m/s")
    (out / "transient_skidding.json").write_text(json.dumps(dict(
        time=res.time.tolist(), inner_rpm=(res.inner_speed * 30 / np.pi).tolist(),
        kinematic_cage_slip_percent=res.kinematic_cage_slip_percent.tolist(), mean_ball_slip=slip.tolist(),
        inputs=bearing.Inputs(time=args.time))))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed (pip install -e .[plot]): no plot")
        return
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    axes[0].plot(res.time, res.inner_speed * 30 / np.pi, label="inner race")
    axes[0].plot(res.time, res.cage_speed * 30 / np.pi, label="cage")
    axes[0].set(ylabel="speed (rpm)")
    axes[0].legend()
    axes[1].plot(res.time, res.kinematic_cage_slip_percent, label="kinematic cage slip")
    axes[1].plot(res.time, res.cage_slip_percent, "--", label="cage slip (P19)")
    axes[1].set(ylabel="cage slip (%)")
    axes[1].legend()
    axes[2].plot(res.time, slip)
    axes[2].set(xlabel="time (s)", ylabel="mean ball-race slip (m/s)")
    for ax in axes:
        ax.axvline(RUN_UP, color="grey", ls=":")
        ax.axvline(DROP_TIME, color="red", ls=":")
    fig.suptitle("run-up to 1800 rpm in 50 ms at 1.3 kN, axial load drop to 300 N at 0.1 s")
    fig.tight_layout()
    fig.savefig(out / "transient_skidding.png", dpi=120)
    print(f"wrote {out}/transient_skidding.png, .json")


if __name__ == "__main__":
    main()
