"""Where a whole ``simulate`` call's time goes (issue 52, item 1): the build (the model, of it the
quasi-static load distribution and the steady or quasi-dynamic start), Exudyn's assembly, the
integration — split into the force evaluations (the connector's residual, every Newton
iteration), the Jacobians, and the rest (Exudyn's own work and the glue around the user
functions) — and the outputs (the results recomputed from the recorded states, the summary).
Each as a share of the whole call, for the first call of a process (what a CLI command pays)
and warm (a script's later calls), with the evaluations per step and their cost.

    python benchmarks/call_profile.py [--time 0.1] [--cases a,b]

Cases: (a) the reference bearing, 1.3 kN axial, 1800 rpm; (b) 2.2 kN axial + 2 kN radial.
The phases are timed by wrapping the package's own functions in this process (no profiler: its
overhead would bend the shares); what is not wrapped is in "rest".
"""
import argparse
from contextlib import contextmanager

import exudyn as exu

import exudyn_bearing.model.builder as builder
import exudyn_bearing.model.start_state as start_module
from exudyn_bearing import SolverSettings, races
from exudyn_bearing.simulation.profile import Clock
from exudyn_bearing.simulation.runner import run_solver, with_surface_step
from exudyn_bearing.setup import BearingSetup
from exudyn_bearing.presets import REFERENCE_BEARING

CASES = {"a": ("reference, 1.3 kN axial, 1800 rpm", 1300.0, 0.0, 1800.0),
         "b": ("reference, 2.2 kN + 2 kN radial, 1800 rpm", 2200.0, 2000.0, 1800.0)}


def one_call(axial, radial, rpm, sim_time, clock):
    """A ``simulate`` call's steps (exudyn_bearing.simulation.runner.simulate) with the clock on
    them; returns the integration's step count."""
    with start_timed(clock), clock.phase("whole call"):
        with clock.phase("build"):
            mbs = exu.SystemContainer().AddSystem()
            handle = builder.CreateAngularContactBearing(mbs, BearingSetup(REFERENCE_BEARING),
                                                         innerRace=races.Driven(rpm), axialForce=axial,
                                                         radialForce=radial, show=False)
        con = handle.connector
        con.residual_forces = clock.wrap("force evaluations", con.residual_forces)
        con.jacobian = clock.wrap("Jacobians", con.jacobian)
        with clock.phase("assembly"):
            mbs.Assemble()
        with clock.phase("integration"):
            info = run_solver(mbs, [handle], sim_time,
                              with_surface_step(SolverSettings(progress=False), handle, rpm))
        with clock.phase("outputs"):
            handle.Results(mbs).summary()
    return info.steps


@contextmanager
def start_timed(clock, quasi_static="quasi-static load distribution", start="steady / quasi-dynamic start"):
    """Within it, the builder's quasi-static load distribution and its steady or quasi-dynamic
    start (every call) timed on ``clock`` under these names."""
    patched = {(start_module, "solve_load_distribution"): quasi_static, (start_module, "steady_start"): start}
    saved = {key: getattr(*key) for key in patched}
    for (module, attr), name in patched.items():
        setattr(module, attr, clock.wrap(name, getattr(module, attr)))
    try:
        yield clock
    finally:
        for key, function in saved.items():
            setattr(*key, function)


def report(name, text, clock, steps):
    s, n = clock.seconds, clock.calls
    whole = s["whole call"]
    share = lambda x: f"{100 * x / whole:5.1f} %"  # noqa: E731
    integ = s["integration"]
    forces, jacs = s.get("force evaluations", 0.0), s.get("Jacobians", 0.0)
    rows = [("build", s["build"]),
            ("  of it quasi-static load distribution", s.get("quasi-static load distribution", 0.0)),
            ("  of it steady / quasi-dynamic start", s.get("steady / quasi-dynamic start", 0.0)),
            ("assembly", s["assembly"]), ("integration", integ),
            (f"  of it force evaluations ({n.get('force evaluations', 0)}, "
             f"{n.get('force evaluations', 0) / max(steps, 1):.1f} a step, "
             f"{1e6 * forces / max(n.get('force evaluations', 1), 1):.0f} us each)", forces),
            (f"  of it Jacobians ({n.get('Jacobians', 0)}, "
             f"{1e3 * jacs / max(n.get('Jacobians', 1), 1):.2f} ms each)", jacs),
            ("  of it the rest: Exudyn's own work and glue", integ - forces - jacs),
            ("outputs", s["outputs"]),
            ("not in a phase", whole - s["build"] - s["assembly"] - integ - s["outputs"])]
    print(f"\n({name}) {text}: whole call {whole:.2f} s, {steps} steps")
    print("| phase | s | share of the whole call |\n|---|---:|---:|")
    for label, value in rows:
        print(f"| {label} | {value:.3f} | {share(value)} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.1, help="simulated time per call, s")
    parser.add_argument("--cases", default="a,b", help="cases, comma-separated")
    args = parser.parse_args()
    names = [c.strip() for c in args.cases.split(",") if c.strip()]
    # the first call of a process (what every CLI command pays): kernels loaded from numba's
    # cache, first dispatches, the work arrays of the outputs' fast traction rule allocated
    text, axial, radial, rpm = CASES[names[0]]
    clock = Clock()
    steps = one_call(axial, radial, rpm, args.time, clock)
    report(names[0], text + ", the process's first call", clock, steps)
    for name in names:  # warm: a script's later calls
        text, axial, radial, rpm = CASES[name]
        clock = Clock()
        steps = one_call(axial, radial, rpm, args.time, clock)
        report(name, text + ", warm", clock, steps)


if __name__ == "__main__":
    main()
