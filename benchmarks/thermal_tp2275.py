"""The 35-mm jet-lubricated bearing of NASA TP-2275 with its thermal network (issue 51,
MODEL.md §14e): heat against the measured heat at 28 000–72 000 rpm, and its growth with speed.

667 N thrust, oil jet 760 cm^3/min at 394 K, every loss on (rolling resistance, 0.5 % oil
drag and the jet oil's momentum (MODEL.md §11c, eq. 11c.2), outer-land cage with a 4-mm land,
pocket friction off, thermal film), the steady state with the network; for comparison without
the jet's momentum (the model before session 42) and without the network. The jet's momentum
is printed also as it would be with the oil leaving at the pitch radius instead of the outer
raceway (no feedback), its one declared choice. Measured heat: Parker, NASA TP-2275 (1984),
0.35 / 0.70 / 1.10 / 1.40 kW, as digitized in YUXinluhk/BallBearing-Dynamics
(paper/manuscript_applsci.tex, ±3 %). Ring temperatures from an earlier manuscript of the
same repository are withdrawn there and printed only as unverified.

    python benchmarks/thermal_tp2275.py              # ~30 s on 2 cores
    python benchmarks/thermal_tp2275.py --out docs   # writes docs/thermal_tp2275.md and .json
"""
import argparse
import json
import math
import time
from pathlib import Path

from contact.bearing_thermal import ThermalModel
import dataclasses

from exudyn_bearing import (ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG, BearingSetup, CageModel,
                            ContactLaw, __version__, steady_state)

SPEEDS = (28000.0, 48000.0, 64000.0, 72000.0)
MEASURED_W = (350.0, 700.0, 1100.0, 1400.0)
#: "extracted from Figs. 3, 6, and 13" (paper/manuscript.tex), withdrawn in manuscript_applsci.tex
UNVERIFIED_RING_K = ((422.0, 413.0), (443.0, 425.0), (458.0, 435.0), (468.0, 443.0))
THERMAL = ThermalModel(oil_flow=760e-6 / 60, oil_inlet_temperature=394.0, bore=35e-3)
#: without the jet's momentum: the model before session 42
NO_JET = BearingSetup(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG,
                      CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3),
                      ContactLaw(rolling_resistance=True, thermal_film=True))
SETUP = NO_JET.replace(drag=dataclasses.replace(HIGH_SPEED_DRAG, oil_flow=THERMAL.oil_flow))


def growth(rows, key):
    """Exponent of n between the first and last speed."""
    return math.log(rows[-1][key] / rows[0][key]) / math.log(rows[-1]["rpm"] / rows[0]["rpm"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="directory for thermal_tp2275.md and .json")
    args = parser.parse_args()
    rows = []
    for rpm, measured, rings in zip(SPEEDS, MEASURED_W, UNVERIFIED_RING_K):
        start = time.perf_counter()
        cold = steady_state(SETUP, axial_force=667.0, rpm=rpm)
        hot = steady_state(SETUP.replace(thermal=THERMAL), axial_force=667.0, rpm=rpm)
        no_jet = steady_state(NO_JET.replace(thermal=THERMAL), axial_force=667.0, rpm=rpm)
        th = hot.thermal
        b, jet = SETUP.bearing, hot.power_loss_W["jet_momentum"]  # eq. 11c.2
        # were the oil to leave at r_p: (r_p / r_o)^2 of the jet's loss (no feedback)
        at_pitch = hot.power_loss_W["total"] - jet * (1.0 - (b.pitch_radius / (b.pitch_radius + b.ball_radius)) ** 2)
        rows.append({"rpm": rpm, "measured_W": measured, "isothermal_W": cold.power_loss_W["total"],
                     "thermal_W": hot.power_loss_W["total"], "by_source_W": hot.power_loss_W,
                     "jet_momentum_W": jet, "no_jet_W": no_jet.power_loss_W["total"],
                     "no_jet_error_percent": 100.0 * (no_jet.power_loss_W["total"] / measured - 1.0),
                     "exit_at_pitch_error_percent": 100.0 * (at_pitch / measured - 1.0),
                     "error_percent": 100.0 * (hot.power_loss_W["total"] / measured - 1.0),
                     "isothermal_error_percent": 100.0 * (cold.power_loss_W["total"] / measured - 1.0),
                     "temperatures_K": th["temperatures_K"], "contact_oil_K": th["contact_oil_temperature_K"],
                     "removed_W": th["removed_W"], "iterations": th["iterations"],
                     "converged": bool(hot.converged and th["converged"]),
                     "kinematic_cage_slip_percent": hot.kinematic_cage_slip_percent,
                     "isothermal_kinematic_cage_slip_percent": cold.kinematic_cage_slip_percent,
                     "unverified_ring_K": rings, "wall_s": time.perf_counter() - start})
        r = rows[-1]
        print(f"{rpm:7.0f} rpm: {r['thermal_W']:7.1f} W ({r['error_percent']:+.1f} %; jet momentum "
              f"{jet:5.1f} W, leaving at the pitch radius {r['exit_at_pitch_error_percent']:+.1f} %), without the "
              f"jet {r['no_jet_W']:7.1f} W ({r['no_jet_error_percent']:+.0f} %), isothermal "
              f"{r['isothermal_W']:7.1f} W ({r['isothermal_error_percent']:+.0f} %), measured {measured:.0f} W; "
              f"rings {r['temperatures_K']['inner_ring']:.0f}/{r['temperatures_K']['outer_ring']:.0f} K, oil out "
              f"{r['temperatures_K']['oil']:.0f} K, {r['iterations']} iterations, {r['wall_s']:.1f} s", flush=True)
    summary = {"growth_thermal": growth(rows, "thermal_W"), "growth_isothermal": growth(rows, "isothermal_W"),
               "growth_no_jet": growth(rows, "no_jet_W"),
               "growth_measured": growth(rows, "measured_W")}
    print(f"growth with speed (28 000 -> 72 000 rpm): thermal n^{summary['growth_thermal']:.2f} (without the jet's "
          f"momentum n^{summary['growth_no_jet']:.2f}), isothermal "
          f"n^{summary['growth_isothermal']:.2f}, measured n^{summary['growth_measured']:.2f}")
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "thermal_tp2275.json").write_text(json.dumps(
            {"rows": rows, "summary": summary, "inputs": {"setup": repr(SETUP), "thermal": repr(THERMAL),
                                                          "axial_N": 667.0, "version": __version__}}, indent=1))
        (out / "thermal_tp2275.md").write_text(markdown(rows, summary))
        print(f"wrote {out / 'thermal_tp2275.md'}")


def markdown(rows, summary):
    lines = ["# NASA TP-2275's 35-mm bearing with the thermal network (MODEL.md §14e)", "",
             "Written by `python benchmarks/thermal_tp2275.py --out docs`. 667 N thrust, oil jet 760 cm³/min at "
             "394 K, every loss on (the jet oil's momentum, §11c eq. 11c.2, included), steady state (§12) with "
             "and without the network (§14); 'no jet' is the thermal steady state without the jet's momentum "
             "(the model before session 42), 'at r_p' the error were the jet's oil to leave at the pitch radius "
             "instead of the outer raceway (no feedback). Measured heat: Parker, "
             "NASA TP-2275 (1984), as digitized in YUXinluhk/BallBearing-Dynamics (±3 %). The ring temperatures "
             "in the last column were withdrawn by that repository's later manuscript: unverified.", "",
             "| rpm | measured (W) | thermal (W) | error | jet momentum (W) | at r_p | no jet (W) | error | "
             "isothermal (W) | error | traction | rolling res. | drag | "
             "cage | inner ring (K) | balls (K) | outer ring (K) | oil out (K) | contact oil in/out (K) | "
             "kin. cage slip (%) | iterations | unverified rings in/out (K) |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
             "---:|---:|---:|"]
    for r in rows:
        t, s = r["temperatures_K"], r["by_source_W"]
        lines.append(
            f"| {r['rpm']:.0f} | {r['measured_W']:.0f} | {r['thermal_W']:.0f} | {r['error_percent']:+.1f} % | "
            f"{r['jet_momentum_W']:.1f} | {r['exit_at_pitch_error_percent']:+.1f} % | {r['no_jet_W']:.0f} | "
            f"{r['no_jet_error_percent']:+.0f} % | "
            f"{r['isothermal_W']:.0f} | {r['isothermal_error_percent']:+.0f} % | {s['traction']:.0f} | "
            f"{s['rolling_resistance']:.0f} | {s['ball_drag']:.0f} | {s['cage']:.0f} | {t['inner_ring']:.0f} | "
            f"{t['balls']:.0f} | {t['outer_ring']:.0f} | {t['oil']:.0f} | {r['contact_oil_K']['inner']:.0f} / "
            f"{r['contact_oil_K']['outer']:.0f} | {r['kinematic_cage_slip_percent']:.3f} | {r['iterations']} | "
            f"{r['unverified_ring_K'][0]:.0f} / {r['unverified_ring_K'][1]:.0f} |")
    lines += ["", f"Growth from 28 000 to 72 000 rpm: thermal n^{summary['growth_thermal']:.2f} (no jet "
              f"n^{summary['growth_no_jet']:.2f}), isothermal "
              f"n^{summary['growth_isothermal']:.2f}, measured n^{summary['growth_measured']:.2f}.", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()
