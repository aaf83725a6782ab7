"""Skid and power loss of a high-speed bearing against speed (issue 19, MODEL.md §11).

The 35-mm-bore bearing of MODEL.md §11 (16 balls of 7.144 mm, d_m 46.5 mm, 24 deg, M-50) with
the ester turbine oil at 121 degC and 0.5 % oil in the oil–air mixture, 667 N thrust, inner
race from 10 000 to 72 000 rpm (DN 0.35–2.5 million), every loss switched on (rolling
resistance §11b, drag §11c, outer-land cage friction §11d with an assumed 4-mm land and
0.25-mm diametral play, thermal film §11e). Each speed starts from its steady state
(MODEL.md §12) and runs until settled. Writes a table (markdown, CSV with units, JSON with
what produced it) and, with matplotlib, the kinematic cage slip and the power loss by
source (stacked) against speed to ``docs/high_speed`` (or ``--out``).

    python demos/high_speed.py                  # ~2 min on 2 cores
    python demos/high_speed.py --rpm 28000 72000 --time 0.02
    python demos/high_speed.py --no-land-film --out /tmp/old   # the land without its film's force
"""
import argparse
import csv
import json
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from exudyn_bearing import (settled_label, ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG, __version__, CageModel,
                            ContactLaw, simulate)

AXIAL = 667.0
SPEEDS = (10000.0, 20000.0, 28000.0, 40000.0, 48000.0, 60000.0, 72000.0)
LAW = ContactLaw(rolling_resistance=True, thermal_film=True)
#: outer-land-guided cage; land width and play are assumptions (no drawing of this cage)
CAGE = CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3)
SOURCES = ("traction", "rolling_resistance", "ball_drag", "cage", "contact_damping")


def run(rpm, sim_time, cage=CAGE):
    """One speed: a row of the table."""
    start = time.perf_counter()
    r = simulate(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, axial_force=AXIAL, rpm=rpm, time=sim_time,
                 ball_drag=HIGH_SPEED_DRAG,
                 contact_law=LAW, cage=cage)
    steady = r.initial_steady_state
    row = {"rpm": rpm, "dn_million": 35.0 * rpm / 1e6, "kinematic_cage_slip_percent": r.kinematic_cage_slip_percent,
           "steady_kinematic_cage_slip_percent": steady.kinematic_cage_slip_percent if steady else float("nan"),
           "cage_slip_percent": r.cage_slip_percent, "settled": r.settled, "drive_power_W": r.drive_power_W,
           "step_s": r.solver["step"], "steps": r.steps, "time_s": sim_time, "wall_s": time.perf_counter() - start}
    # the cage centre's offset from its land's axis over the last third, in radial plays
    window = r.results.last(1 / 3)
    ratio = r.results.cage_eccentricity[window] / (0.5 * cage.guide_clearance)
    row.update(cage_eccentricity_ratio=float(np.mean(ratio)), cage_eccentricity_ratio_min=float(np.min(ratio)),
               cage_eccentricity_ratio_max=float(np.max(ratio)))
    row.update({f"{k}_W": r.power_loss_W[k] for k in SOURCES + ("total",)})
    return row


def table(rows):
    lines = ["| rpm | DN (1e6) | kinematic cage slip (%) | steady (%) | cage slip P19 (%) | traction (W) | "
             "rolling resistance (W) | ball drag (W) | cage (W) | cage ε = e/c (min–max) | total loss (W) | drive (W) | "
             "settled | step (s) | wall (s) |", "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['rpm']:.0f} | {r['dn_million']:.2f} | {r['kinematic_cage_slip_percent']:.3f} | "
                     f"{r['steady_kinematic_cage_slip_percent']:.3f} | {r['cage_slip_percent']:.2f} | "
                     f"{r['traction_W']:.1f} | {r['rolling_resistance_W']:.1f} | {r['ball_drag_W']:.1f} | "
                     f"{r['cage_W']:.2f} | {r['cage_eccentricity_ratio']:.3f} ({r['cage_eccentricity_ratio_min']:.2f}–"
                     f"{r['cage_eccentricity_ratio_max']:.2f}) | {r['total_W']:.1f} | {r['drive_power_W']:.1f} | "
                     f"{settled_label(r['settled'])} | {r['step_s']:.3g} | {r['wall_s']:.1f} |")
    return "\n".join(lines)


def plot(rows, path):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no figure (pip install matplotlib)")
        return None
    rpm = [r["rpm"] / 1000 for r in rows]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    ax1.plot(rpm, [r["kinematic_cage_slip_percent"] for r in rows], "o-", label="dynamic (settled)")
    ax1.plot(rpm, [r["steady_kinematic_cage_slip_percent"] for r in rows], "x--", label="steady state, cage centred (MODEL.md §12)")
    ax1.set_ylabel("kinematic cage slip (%)")
    ax1.legend()
    ax1.grid(alpha=0.3)
    bottom = [0.0] * len(rows)
    for source in SOURCES[:4]:
        values = [r[f"{source}_W"] for r in rows]
        ax2.bar(rpm, values, width=3.5, bottom=bottom, label=source.replace("_", " "))
        bottom = [b + v for b, v in zip(bottom, values)]
    ax2.plot(rpm, [r["drive_power_W"] for r in rows], "k.--", label="drive power (energy check)")
    ax2.set_xlabel("inner-race speed (1000 rpm)")
    ax2.set_ylabel("power loss (W)")
    ax2.legend()
    ax2.grid(alpha=0.3)
    fig.suptitle(f"35-mm bearing (16 x 7.144 mm, 24 deg), {AXIAL:g} N, ester oil 3.2 mPa s at 121 degC, "
                 f"0.5 % oil-air;\nrolling resistance, land friction and thermal film on (exudyn-bearing {__version__})", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rpm", type=float, nargs="+", default=list(SPEEDS), help="inner-race speeds, rev/min")
    parser.add_argument("--time", type=float, default=0.1, help="simulated time per speed, s")
    parser.add_argument("--out", default="docs/high_speed", help="output folder")
    parser.add_argument("--no-land-film", action="store_true",
                        help="the land's film without its radial force (CageModel(land_film=False), MODEL.md §11d)")
    args = parser.parse_args()
    cage = replace(CAGE, land_film=not args.no_land_film)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    rows = []
    for rpm in args.rpm:
        rows.append(run(rpm, args.time, cage))
        print(f"{rpm:8.0f} rpm: kinematic cage slip {rows[-1]['kinematic_cage_slip_percent']:.3f} %, "
              f"loss {rows[-1]['total_W']:.1f} W, drive {rows[-1]['drive_power_W']:.1f} W, "
              f"{rows[-1]['wall_s']:.1f} s", flush=True)
    text = table(rows)
    meta = {"produced_by": f"demos/high_speed.py, exudyn-bearing {__version__}",
            "bearing": "HIGH_SPEED_35MM_BEARING", "lubricant": "ESTER_TURBINE_OIL", "drag": "HIGH_SPEED_DRAG",
            "axial_N": AXIAL, "contact_law": repr(LAW), "cage": repr(cage), "time_per_speed_s": args.time,
            "wall_total_s": time.perf_counter() - start}
    (out / "high_speed.md").write_text(text + "\n")
    (out / "high_speed.json").write_text(json.dumps({"meta": meta, "rows": rows}, indent=1) + "\n")
    with open(out / "high_speed.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    figure = plot(rows, out / "high_speed.png")
    print(text)
    print(f"total wall time {meta['wall_total_s']:.0f} s; wrote {out}/high_speed.md, .csv, .json"
          + (f", {figure}" if figure else ""))


if __name__ == "__main__":
    main()
