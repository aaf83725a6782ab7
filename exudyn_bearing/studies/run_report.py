"""What the CLI's ``simulate`` prints for a run: its summary's JSON dictionary as text."""
from __future__ import annotations

from ..results.records import assumptions_line

__all__ = ["print_simulation", "print_thermal", "plot_temperatures_beside"]


def print_simulation(data: dict, args) -> None:
    """The text report of ``simulate``'s summary ``data`` (``SimulationSummary.to_dict()``)
    for the command line ``args``: the skid measures, loads, losses and energy balance, the
    solver's work and where the call's time went, the temperatures where the run had them,
    the error estimate where asked."""
    print(f"Dynamic run: axial {args.axial:g} N, radial {args.radial:g} N, inner race {args.rpm:g} rpm, "
          f"{args.time:g} s simulated (means over the last third)")
    print(f"  kinematic cage slip (MODEL.md §7)   {data['kinematic_cage_slip_percent']:8.3f} %   (the skid measure)")
    print(f"  paper's P19 cage slip (nominal)     {data['cage_slip_percent']:8.3f} %")
    print(f"  assumptions                         {assumptions_line(data['assumptions'])}")
    print(f"  cage speed                          {data['cage_speed']:8.3f} rad/s "
          f"(nominal {data['cage_speed_nominal']:.3f})")
    verdict = {True: "yes", False: "NO (still drifting: run longer)",
               None: "too short to judge (runs under 0.05 s)"}[data["settled"]]
    print(f"  settled                             {verdict}")
    d = data["details"]
    print(f"  max inner/outer load                {d['max_inner_load']:.1f} / {d['max_outer_load']:.1f} N")
    loss = data["power_loss_W"]
    parts = ", ".join(f"{k.replace('_', ' ')} {v:.1f}" for k, v in loss.items() if k != "total" and abs(v) >= 0.05)
    print(f"  power loss (MODEL.md §11)           {loss['total']:8.1f} W ({parts or 'none'}); "
          f"drive {data['drive_power_W']:.1f} W")
    remainder = {True: "settled: the integrator's damping only",
                 False: "not settled: it includes kinetic energy still changing",
                 None: "too short to judge: it includes kinetic energy still changing"}[data["settled"]]
    print(f"  energy balance (drive - loss)       {d['energy_balance_percent']:8.2f} % of the drive ({remainder})")
    print(f"  solver {data['solver']['solver']}, step {data['solver']['step']:g} s, {data['steps']} steps, "
          f"{data['newton_iterations']} Newton iterations, {data['jacobian_updates']} Jacobian updates, "
          f"wall time {data['wall_time_s']:.1f} s")
    call = data["call_time_s"]
    print(f"  whole call {call['whole']:.2f} s: build {call['build']:.2f} (model, start), assembly "
          f"{call['assembly']:.2f}, integration {call['integration']:.2f}, outputs {call['outputs']:.2f} s")
    prof = data["integration_profile"]
    if prof:
        print(f"    integration: {prof['force_evaluations']} force evaluations ({prof['force_evaluations_per_step']:.1f} "
              f"a step, {prof['force_evaluation_us']:.0f} us each) {prof['force_evaluations_s']:.2f} s, "
              f"{prof['jacobians']} Jacobians ({prof['jacobian_ms']:.2f} ms each) {prof['jacobians_s']:.2f} s, "
              f"Exudyn's own work and glue {prof['exudyn_and_glue_s']:.2f} s")
    if data.get("thermal"):
        print_thermal(data["thermal"])
    est = data.get("error_estimate")
    if est:
        print(f"  error estimate ({est['method']}, {est['reference_wall_time_s']:.1f} s more wall time):")
        print(f"    cage slip {est['cage_slip_percent']:.3g} pp, kinematic cage slip "
              f"{est['kinematic_cage_slip_percent']:.3g} pp, cage speed {est['cage_speed']:.3g} rad/s, "
              f"max inner load {est['max_inner_load']:.3g} N")
    if args.plot:
        print(f"  plots written to {args.plot}")


def print_thermal(th: dict) -> None:
    """Two lines of a run's temperatures (:func:`exudyn_bearing.results.temperatures.thermal_summary`)."""
    nodes = ", ".join(f"{k.replace('_', ' ')} {v:.2f} ({th['temperature_rise_K'][k]:+.3g})"
                      for k, v in th["temperatures_K"].items())
    start = "thermal steady state" if th["start"] == "steady" else "oil inlet temperature"
    oil, removed = th["contact_oil_temperature_K"], th["removed_W"]
    print(f"  temperatures (MODEL.md §14g), K     {nodes}; from the {start}")
    print(f"  heat {sum(th['heat_W'].values()):.1f} W: carried off by the oil {removed['oil_inlet']:.1f} W, "
          f"to ambient {removed['ambient']:.1f} W, stored {th['stored_W']:.1f} W "
          f"(balance {th['heat_balance_percent']:.2g} %); contact oil inner {oil['inner']:.2f} K, "
          f"outer {oil['outer']:.2f} K")


def plot_temperatures_beside(data: dict, thermal: dict | None, plot: str, title: str) -> None:
    """With temperatures, their plot beside the run's ``plot`` (its name + '_temperatures.png'),
    named in ``data``."""
    if thermal is None:
        return
    from pathlib import Path

    from ..results.temperatures import plot_temperatures

    path = Path(plot)
    data["temperature_plot"] = str(path.with_name(path.stem + "_temperatures.png"))
    plot_temperatures(thermal, data["temperature_plot"], title=title)
