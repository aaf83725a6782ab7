"""What the CLI's ``steady`` prints: the steady rolling state under axial load (MODEL.md §12)
and the quasi-dynamic state under combined load (§12a), with their temperatures where the
bearing has a thermal network (§14d)."""
from __future__ import annotations

import math

import numpy as np

from ..results.records import assumptions_line

__all__ = ["print_steady", "print_combined"]


def print_steady(state, data: dict, args) -> None:
    """The text report of a :class:`~exudyn_bearing.solvers.steady.SteadyState` ``state``, its
    JSON dictionary ``data`` (with the assumptions and the minimum-load criteria) and the
    command line ``args``."""
    print(f"Steady rolling state (MODEL.md §12): axial {args.axial:g} N, inner race {args.rpm:g} rpm"
          f"{', no drag' if args.no_drag else ''}")
    if not state.converged:
        print(f"  NOT CONVERGED: {state.message}")
    print(f"  kinematic cage slip (MODEL.md §7)   {state.kinematic_cage_slip_percent:8.3f} %   (the skid measure)")
    print(f"  paper's P19 cage slip (nominal)     {state.cage_slip_percent:8.3f} %")
    print(f"  assumptions                         {assumptions_line(data['assumptions'])}")
    print(f"  cage speed                          {state.cage_speed:8.3f} rad/s "
          f"(nominal {state.nominal_cage_speed:.3f})")
    print(f"  ball attitude xz / yz               {state.attitude_xz_deg:8.3f} / {state.attitude_yz_deg:.3f} deg")
    print(f"  inner / outer load                  {state.inner_load:8.2f} / {state.outer_load:.2f} N")
    print(f"  inner / outer contact angle         {state.inner_contact_angle_deg:8.2f} / "
          f"{state.outer_contact_angle_deg:.2f} deg")
    print(f"  minimum axial load: Hirano {data['hirano_minimum_axial']:.0f} N, Jones' gyroscopic criterion "
          f"{data['gyroscopic_minimum_axial']:.0f} N")
    _print_heat(state)


def print_combined(state, data: dict, args) -> None:
    """The text report of a :class:`~exudyn_bearing.solvers.quasidynamic.AzimuthStates`
    ``state`` (every ball in its own balance at its azimuth, MODEL.md §12a), its JSON
    dictionary ``data`` and the command line ``args``."""
    print(f"Quasi-dynamic state under combined load (MODEL.md §12a): axial {args.axial:g} N, radial "
          f"{args.radial:g} N, inner race {args.rpm:g} rpm{', no drag' if args.no_drag else ''}")
    if not state.converged:
        print(f"  NOT CONVERGED: {state.message}")
        print(f"  (no balance to report; the dynamic model settles wherever it can: simulate --axial {args.axial:g} "
              f"--radial {args.radial:g})")
        return
    print(f"  kinematic cage slip (MODEL.md §7)   {state.kinematic_cage_slip_percent:8.3f} %   (the skid measure, "
          "mean over the balls)")
    print(f"  paper's P19 cage slip (nominal)     {state.cage_slip_percent:8.3f} %")
    print(f"  assumptions                         {assumptions_line(data['assumptions'])}")
    print(f"  cage speed                          {state.cage_speed:8.3f} rad/s "
          f"(nominal {state.nominal_cage_speed:.3f})")
    d = 1e6 * np.asarray(state.displacement)
    print(f"  inner race displacement             ({d[0]:.2f}, {d[1]:.2f}, {d[2]:.2f}) um")
    for race in ("inner", "outer"):
        load = getattr(state, f"{race}_load")
        angle = np.degrees(getattr(state, f"{race}_contact_angle"))
        k = int(np.argmax(load))
        print(f"  {race} load                          {load[k]:8.1f} N at {math.degrees(state.azimuth[k]):.0f} deg "
              f"(least {np.min(load):.1f} N); contact angle {np.min(angle):.2f}-{np.max(angle):.2f} deg")
    _print_heat(state)


def _print_heat(state) -> None:
    """The losses and drive power of a steady or quasi-dynamic ``state``, its temperatures
    where it has them, and its wall time."""
    loss = state.power_loss_W
    print(f"  power loss                          {loss['total']:8.1f} W (traction {loss['traction']:.1f}, rolling "
          f"resistance {loss['rolling_resistance']:.1f}, drag {loss['ball_drag']:.1f}"
          + (f", jet {loss['jet_momentum']:.1f}" if loss.get("jet_momentum") else "") + f", cage {loss['cage']:.1f}); "
          f"drive {state.drive_power_W:.1f} W"
          + (f" (the losses less the contacts' normal work {state.normal_work_W:.3g} W of the balance's kinematics)"
             if getattr(state, "normal_work_W", None) else ""))
    if state.thermal is not None and "heat_W" in state.thermal:
        _print_temperatures(state.thermal)
    print(f"  wall time {state.wall_time_s:.2f} s")


def _print_temperatures(th: dict) -> None:
    """The node and contact-oil temperatures of a steady state's ``thermal`` record (§14d)."""
    print("  temperatures (MODEL.md §14), K      " + ", ".join(f"{k.replace('_', ' ')} {v:.1f}"
                                                           for k, v in th["temperatures_K"].items()))
    print(f"  contact oil, K                      inner {th['contact_oil_temperature_K']['inner']:.1f}, outer "
          f"{th['contact_oil_temperature_K']['outer']:.1f} (inlet {th['oil_inlet_K']:.1f}); heat carried off "
          f"by the oil {th['removed_W']['oil_inlet']:.1f} W, to ambient {th['removed_W']['ambient']:.1f} W")
