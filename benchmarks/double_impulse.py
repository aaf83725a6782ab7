"""A spall's length from the vibration signal alone (issue 50 item 2; MODEL.md eq. 13.10,
``exudyn_bearing.studies.spall_size``) on three bearings, three speeds and three lengths, each
read from five analysis windows (starting one passage apart): the length's error against the
true one, and the run's own contact-load spacing beside the signal's.

    python benchmarks/double_impulse.py [--cases twelve,cwru,spindle]   (about 10 min)

Cases: the 12-ball bearing (the 6205's balls on a 54-mm pitch) at 300, 600 and 1200 rpm under
500 N radial; the Case Western 6205 at 1797 rpm under 500 N radial; the 40-mm spindle bearing
at 3000 rpm under 500 N axial + 500 N radial. Outer-race spalls 1, 2, 3 mm long, 0.5 mm deep,
recorded at 50 kHz.
"""
from __future__ import annotations

import argparse
from dataclasses import replace

import numpy as np

from contact.defect_passage import length_from_spacing
from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING, SPINDLE_40MM_BEARING
from exudyn_bearing.studies.spall_size import double_impulse
from exudyn_bearing.studies.vibration import vibration

TWELVE = replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3)
#: name: (bearing, [(rpm, simulated time s)], axial N, radial N)
CASES = {"twelve": (TWELVE, [(300.0, 0.6), (600.0, 0.3), (1200.0, 0.15)], 0.0, 500.0),
         "cwru": (CWRU_6205_BEARING, [(1797.0, 0.15)], 0.0, 500.0),
         "spindle": (SPINDLE_40MM_BEARING, [(3000.0, 0.1)], 500.0, 500.0)}


def windows(result, r_x, axial, radial, count=5, settle=0.02):
    """The length read from ``count`` analysis windows, the first from ``settle`` s (the run's
    default), each next one passage later, m."""
    bpfo = result.fault_frequencies["actual"]["BPFO"]
    load = np.array([radial, 0.0, axial], dtype=float)
    x = result.acceleration @ (load / np.linalg.norm(load))
    size = result.spall_size
    out = []
    for k in range(count):
        keep = result.time >= settle + k / bpfo
        spacing = double_impulse(x[keep], result.sample_rate, bpfo).spacing_s
        out.append(None if spacing is None else length_from_spacing(spacing, size["speed_m_s"], r_x,
                                                                     size["approach_m"]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", default=",".join(CASES))
    args = ap.parse_args()
    print("bearing | rpm | L mm | read mm (error %) | five windows, error % | entry to strike: signal / "
          "contact load ms | passages | wall s")
    for name in args.cases.split(","):
        bearing, speeds, axial, radial = CASES[name]
        r_x = float(bearing.curvature_radii(bearing.contact_angle, "outer")[0])
        for rpm, end in speeds:
            for length in (1e-3, 2e-3, 3e-3):
                r = vibration(bearing, rpm=rpm, axial_force=axial, radial_force=radial, time=end,
                              sample_rate=50000.0, surface=SurfaceModel((Defect("outer", 0.0, length, 0.5e-3),)))
                s = r.spall_size
                errs = ["-" if v is None else f"{100 * (v - length) / length:+.0f}" for v in windows(r, r_x, axial, radial)]
                read = "not read" if s["length_m"] is None else f"{1e3 * s['length_m']:.3f} ({s['error_percent']:+.1f})"
                spacing = "-" if s["spacing_s"] is None else f"{1e3 * s['spacing_s']:.3f}"
                print(f"{name} | {rpm:g} | {1e3 * length:g} | {read} | {' '.join(errs)} | {spacing} / "
                      f"{1e3 * r.impacts['entry_to_impact_s']:.3f} | {s['passages']} | {r.wall_time_s:.0f}",
                      flush=True)


if __name__ == "__main__":
    main()
