"""What the reference bearing's skid threshold rests on: the 1 % kinematic-cage-slip
threshold at 900 and 1800 rpm and the slip at 1.3 kN, 1800 rpm, for the limiting shear
coefficient Λ × {0.7, 1, 1.3} and the film's shear modulus coefficient κ × {0.5, 1, 2}
(MODEL.md §6a, §6b; κ is not rescaled with Λ), and the paper's pure Crook law.

Steady-state solver (MODEL.md §12; within ~0.03 pp of settled dynamic runs), the threshold
by Brent's method on the slip between grid loads to ±2 N.

    python benchmarks/lubricant_sensitivity.py [--out docs/lubricant_sensitivity.md]
"""
import argparse
import dataclasses
import json
import time

from scipy import optimize

import exudyn_bearing
from contact.ballrace import ContactLaw
from contact.lubricant import REFERENCE_LUBRICANT as OIL
from exudyn_bearing import steady_state

GRID = (400.0, 700.0, 1000.0, 1400.0, 2000.0, 2800.0, 4000.0, 5600.0)


def slip(oil, law, axial, rpm):
    s = steady_state(lubricant=oil, axial_force=axial, rpm=rpm, contact_law=law)
    if not s.converged:
        raise RuntimeError(f"no steady state at {axial} N, {rpm} rpm: {s.message}")
    return s.kinematic_cage_slip_percent


def threshold(oil, law, rpm, level=1.0):
    """Axial load N where the steady kinematic cage slip crosses ``level`` %."""
    prev = None
    for load in GRID:
        s = slip(oil, law, load, rpm)
        if prev is not None and prev[1] >= level > s:
            return optimize.brentq(lambda f: slip(oil, law, f, rpm) - level, prev[0], load, xtol=2.0)
        prev = (load, s)
    return float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default="docs/lubricant_sensitivity.md")
    args = parser.parse_args()
    lam0, kap0 = OIL.limiting_shear_coefficient, OIL.film_shear_modulus_coefficient
    variants = [("paper's Crook law (no limit, no film elasticity)", OIL, ContactLaw(traction="crook"))]
    for f in (0.7, 1.0, 1.3):
        variants.append((f"Λ × {f:g} = {lam0 * f:.4g}, κ = {kap0:.4g}",
                         dataclasses.replace(OIL, limiting_shear_coefficient=lam0 * f), ContactLaw()))
    for f in (0.5, 2.0):
        variants.append((f"Λ = {lam0:.4g}, κ × {f:g} = {kap0 * f:.4g}",
                         dataclasses.replace(OIL, film_shear_modulus_coefficient=kap0 * f), ContactLaw()))
    variants.append(("Λ = 0.047, no film elasticity", OIL, ContactLaw(film_elasticity=False)))
    rows = []
    start = time.perf_counter()
    for name, oil, law in variants:
        row = dict(variant=name, threshold_900rpm_N=threshold(oil, law, 900.0),
                   threshold_1800rpm_N=threshold(oil, law, 1800.0), slip_1300N_1800rpm_percent=slip(oil, law, 1300.0, 1800.0))
        rows.append(row)
        print(row, flush=True)
    lines = ["# What the skid threshold rests on: Λ and κ", "",
             "Reference bearing and oil, drag of MODEL.md §8, steady-state solver (MODEL.md §12), "
             "kinematic cage slip. Made by `python benchmarks/lubricant_sensitivity.py` "
             f"(exudyn_bearing {exudyn_bearing.__version__}, {time.perf_counter() - start:.0f} s).", "",
             "| law | 1 % threshold at 900 rpm, N | at 1800 rpm, N | slip at 1.3 kN, 1800 rpm, % |",
             "|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['variant']} | {r['threshold_900rpm_N']:.0f} | {r['threshold_1800rpm_N']:.0f} | "
                     f"{r['slip_1300N_1800rpm_percent']:.3f} |")
    with open(args.out, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    with open(args.out.replace(".md", ".json"), "w") as fh:
        json.dump(rows, fh, indent=1)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
