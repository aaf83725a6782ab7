"""The thermal preload rise of a preloaded spindle pair (MODEL.md §14f): the 40-mm spindle
bearings back to back, each pressed 5 um past touching by its spacers, with the inner rings
warming above the outer rings (a motor spindle's shaft runs hotter than its housing; the
balls taken halfway), solved as a shaft on two bearings (MODEL.md §4) at each rise.

    python benchmarks/thermal_preload.py [--out docs]
"""
import argparse

import numpy as np

from exudyn_bearing.presets import SPINDLE_40MM_BEARING
from exudyn_bearing.solvers.shaft import ShaftBearing, solve_shaft

PRELOAD = 5e-6  #: m past touching, each bearing
HALF_SPAN = 0.05  #: m
RISES = (0.0, 5.0, 10.0, 20.0, 30.0, 40.0)  #: inner ring above the outer ring, K


def pair():
    back = np.diag([1.0, -1.0, -1.0])
    return [ShaftBearing(SPINDLE_40MM_BEARING, (0.0, 0.0, -HALF_SPAN), np.eye(3), (0.0, 0.0, -HALF_SPAN + PRELOAD)),
            ShaftBearing(SPINDLE_40MM_BEARING, (0.0, 0.0, HALF_SPAN), back, (0.0, 0.0, HALF_SPAN - PRELOAD))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    lines = ["# The thermal preload rise of a spindle pair (MODEL.md §14f)", "",
             "Made by `python benchmarks/thermal_preload.py --out docs`: the 40-mm spindle bearings back to back, "
             f"{PRELOAD * 1e6:g} um of preload interference each, inner rings ΔT above the outer rings (balls ΔT/2), "
             "AISI 52100 (11.9e-6 1/K), races held at their axial places.", "",
             "| inner ring ΔT K | diametral clearance um | free contact angle deg | interference um | preload N |",
             "|---:|---:|---:|---:|---:|"]
    for rise in RISES:
        hot = [sb.expanded(rise, 0.0, 0.5 * rise) for sb in pair()]
        load = abs(solve_shaft(hot).reaction_force[0, 2])
        b = hot[0].bearing
        lines.append(f"| {rise:g} | {b.diametral_clearance * 1e6:.2f} | {np.degrees(b.contact_angle):.2f} | "
                     f"{(hot[0].inner_position[2] + HALF_SPAN) * 1e6:.2f} | {load:.0f} |")
    print("\n".join(lines))
    if args.out:
        with open(f"{args.out}/thermal_preload.md", "w") as fh:
            fh.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
