"""What building a bearing costs before its first step (issue 52, item 3): the builder's
quasi-static load distribution (every call of it) and its steady or quasi-dynamic start, on the
cases the README quotes, warm (kernels cached, a first build done), median of ``--repeat``
builds. Also the quasi-static distribution alone (``solve_load_distribution``) with its
iterations, the figures its bars print (``loads``) to compare trees with.

    python benchmarks/start_cost.py [--repeat 3] [--cases ref-axial,ref-400-100,...]
"""
import argparse
import statistics

import exudyn as exu
import numpy as np

import exudyn_bearing.model.builder as builder
from exudyn_bearing import Bearing, races
from exudyn_bearing.presets import (CWRU_6205_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, REFERENCE_BEARING,
                                    SPINDLE_40MM_BEARING)
from exudyn_bearing.setup import BearingSetup
from exudyn_bearing.simulation.profile import Clock
from exudyn_bearing.solvers.quasistatic import solve_load_distribution

from call_profile import start_timed  # (run from benchmarks/: the script's folder is on the path)

#: a user's 7205-type bearing (tests/helpers.py BEARING_7205)
BEARING_7205 = Bearing(balls=13, ball_diameter=0.007938, pitch_diameter=0.0385, inner_conformity=0.52,
                       outer_conformity=0.53, contact_angle=np.radians(25.0))
#: the deep-groove example of docs/REFERENCE.md (6205-size balls, 10 um diametral play)
DEEP_GROOVE = Bearing.from_clearance(diametral_clearance=10e-6, balls=6, ball_diameter=11.1e-3,
                                     pitch_diameter=43.5e-3, inner_conformity=5.772 / 11.1,
                                     outer_conformity=5.883 / 11.1)


def _setup(name):
    if name == "reference":
        return BearingSetup(REFERENCE_BEARING)
    if name == "6205":
        return BearingSetup(CWRU_6205_BEARING)
    if name == "deep-groove":
        return BearingSetup(DEEP_GROOVE)
    if name == "spindle":
        return BearingSetup(SPINDLE_40MM_BEARING, lubricant=ESTER_TURBINE_OIL, drag=HIGH_SPEED_DRAG)
    if name == "7205":
        return BearingSetup(BEARING_7205)
    raise KeyError(name)


#: name: (bearing, axial N, radial N, inner rpm)
CASES = {"ref-axial": ("reference", 1300.0, 0.0, 1800.0),
         "ref-400-100": ("reference", 400.0, 100.0, 1800.0),
         "ref-800-500": ("reference", 800.0, 500.0, 1800.0),
         "ref-2800-850": ("reference", 2800.0, 850.0, 1800.0),
         "ref-2200-2000": ("reference", 2200.0, 2000.0, 1800.0),
         "7205-300-100": ("7205", 300.0, 100.0, 12000.0),
         "spindle-50-20": ("spindle", 50.0, 20.0, 40000.0),
         "6205-radial": ("6205", 0.0, 1000.0, 1797.0),
         "deep-groove-radial": ("deep-groove", 0.0, 1000.0, 1800.0)}


def one_build(case, clock):
    bearing, axial, radial, rpm = CASES[case]
    setup = _setup(bearing)
    with start_timed(clock, quasi_static="quasi-static", start="start"), clock.phase("build"):
        mbs = exu.SystemContainer().AddSystem()
        builder.CreateAngularContactBearing(mbs, setup, innerRace=races.Driven(rpm), axialForce=axial,
                                            radialForce=radial, show=False)


def bars(case):
    """The builder's first quasi-static distribution (nominal cage speed) and its iterations."""
    bearing, axial, radial, rpm = CASES[case]
    setup = _setup(bearing)
    return solve_load_distribution(setup.bearing, axial_force=axial, radial_force=radial, rpm=rpm,
                                   hertz_method=setup.contact_law.hertz_method)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="builds per case; the median is reported")
    parser.add_argument("--cases", default=",".join(CASES), help="cases, comma-separated")
    args = parser.parse_args()
    names = [c.strip() for c in args.cases.split(",") if c.strip()]
    one_build(names[0], Clock())  # warm-up: kernels loaded, first dispatches
    print("| case | build (s) | quasi-static (s, calls) | start (s) | distribution: iterations, "
          "max load (N), displacement (um) |")
    print("|---|---:|---:|---:|---|")
    for name in names:
        runs = []
        for _ in range(args.repeat):
            clock = Clock()
            one_build(name, clock)
            runs.append(clock)
        med = lambda key: statistics.median(c.seconds.get(key, 0.0) for c in runs)  # noqa: E731
        loads = bars(name)
        disp = ", ".join(f"{round(1e6 * v, 6) + 0.0:.6f}" for v in loads.displacement)
        print(f"| {name} | {med('build'):.3f} | {med('quasi-static'):.3f} ({runs[0].calls.get('quasi-static', 0)}) | "
              f"{med('start'):.3f} | {loads.iterations}, {loads.max_load:.6f}, ({disp}) |")


if __name__ == "__main__":
    main()
