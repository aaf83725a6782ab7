"""Issue 51 item 5's lead, measured offline: the jet oil's momentum (Euler) loss beside the
TP-2275 thermal steady states (MODEL.md §14e; docs/DEVELOPMENT.md, session 41).

The oil jet (``THERMAL.oil_flow``, m³/s) enters without swirl and leaves the bearing at the
cage's orbital speed at the outer raceway's radius r_o = (d_m + D)/2; by Euler's equation the
cage (driven through the balls) puts in P = ρ Q (ω_c r_o)², W. The model does not have this
loss: here it is only added to each steady state's total, without its feedback on the
temperatures, to size it against the measured heat.

    python benchmarks/tp2275_oil_momentum.py      # ~20 s
"""
import math

from exudyn_bearing import steady_state

from thermal_tp2275 import MEASURED_W, SETUP, SPEEDS, THERMAL  # (run from benchmarks/)


def main():
    b = SETUP.bearing
    r_o = 0.5 * (b.pitch_diameter + b.ball_diameter)
    print(f"r_o {r_o * 1e3:.2f} mm, oil flow {THERMAL.oil_flow * 6e7:.0f} cm3/min")
    rows = []
    for rpm, measured in zip(SPEEDS, MEASURED_W):
        hot = steady_state(SETUP.replace(thermal=THERMAL), axial_force=667.0, rpm=rpm)
        rho = SETUP.lubricant.at_temperature(hot.thermal["temperatures_K"]["oil"] - 273.15).density
        euler = rho * THERMAL.oil_flow * (hot.cage_speed * r_o) ** 2
        total = hot.power_loss_W["total"]
        rows.append((rpm, total + euler))
        print(f"{rpm:6.0f} rpm: model {total:7.1f} W ({100 * (total / measured - 1):+.0f} %), oil momentum "
              f"{euler:6.1f} W (cage {hot.cage_speed:.0f} rad/s) -> {total + euler:7.1f} W "
              f"({100 * ((total + euler) / measured - 1):+.0f} % of the measured {measured:.0f} W)")
    growth = math.log(rows[-1][1] / rows[0][1]) / math.log(rows[-1][0] / rows[0][0])
    print(f"growth with the oil momentum loss: n^{growth:.2f} (measured n^1.47, target n^1.1-1.8)")


if __name__ == "__main__":
    main()
