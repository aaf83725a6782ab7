"""The envelope amplitude's sensitivity to the contact damping (MODEL.md §13c, issue 49 item 4).

    python benchmarks/contact_damping.py [--time 0.3]

The Case Western 6205 at 1797 rpm, 300 N radial, 20 kHz, housing 3 kHz / 2 kg / 5 %, with its
three 0.18-mm, 0.28-mm-deep EDM faults as round pits (outer race, inner race, a ball): the
line at the fault's frequency (BPFO, BPFI, 2 BSF) and the strongest envelope line at the
contact damping ratio ζ = 0.025, 0.05 (the default, assumed) and 0.1 (x0.5, x2), and at 0.3,
the lower end of what Kraemer's bearing damping range gives per contact; and, for a strike, the
12-ball bearing's deep notch (the 6205's balls on a 54-mm pitch, 0.8 mm x 0.3 mm outer notch,
600 rpm, 500 N radial; --strike-time, default 0.1 s). Prints one line per run and the ratios
to the default.
"""
from __future__ import annotations

import argparse
from dataclasses import replace

from contact.ballrace import ContactLaw
from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING
from exudyn_bearing.studies.vibration import vibration

FAULTS = {"outer": (SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3, shape="ellipse"),)), "BPFO", 1),
          "inner": (SurfaceModel((Defect("inner", 0.0, 0.18e-3, 0.28e-3, shape="ellipse"),)), "BPFI", 1),
          "ball": (SurfaceModel((Defect("ball", 0.0, 0.18e-3, 0.28e-3, ball=0),)), "BSF", 2)}
RATIOS = (0.05, 0.025, 0.1, 0.3)  # the default first: the others are read against it


def line_at(result, hz, tolerance=1.0):
    """The envelope peak within ``tolerance`` Hz of ``hz``: (Hz, m/s²), or (hz, 0) if none."""
    near = [p for p in result.envelope_peaks if abs(p[0] - hz) < tolerance]
    return max(near, key=lambda p: p[1]) if near else (hz, 0.0)


#: the strike case: (bearing, rpm, radial force N, surface, line, factor)
STRIKE = (replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3), 600.0, 500.0,
          SurfaceModel((Defect("outer", 0.0, 0.8e-3, 0.3e-3),)), "BPFO", 1)


def main(run_time: float, strike_time: float) -> None:
    cases = {name: (CWRU_6205_BEARING, 1797.0, 300.0, surface, key, factor, run_time)
             for name, (surface, key, factor) in FAULTS.items()}
    cases["12-ball deep notch (strike)"] = (*STRIKE, strike_time)
    for name, (bearing, rpm, radial, surface, key, factor, length) in cases.items():
        base = None
        for zeta in RATIOS:
            r = vibration(bearing, rpm=rpm, radial_force=radial, time=length, surface=surface,
                          contact_law=ContactLaw(damping_ratio=zeta))
            f = factor * r.fault_frequencies["actual"][key]
            hz, amp = line_at(r, f)
            strongest = r.envelope_peaks[0]
            if zeta == 0.05:
                base = (amp, strongest[1])
            print(f"{name}: zeta {zeta:g}: {factor if factor > 1 else ''}{key} line {hz:.2f} Hz {amp:.4g} m/s^2, "
                  f"strongest {strongest[0]:.2f} Hz {strongest[1]:.4g} m/s^2; run {r.wall_time_s:.1f} s", flush=True)
            if base is not None and zeta != 0.05:
                print(f"{name}: zeta {zeta:g} / 0.05: fault line x{amp / base[0]:.3f}, strongest x{strongest[1] / base[1]:.3f}",
                      flush=True)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.3)
    parser.add_argument("--strike-time", type=float, default=0.1)
    args = parser.parse_args()
    main(args.time, args.strike_time)
