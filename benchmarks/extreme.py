"""The stiff and extreme cases of issue 4 at full length (``tests/test_extreme.py`` runs
each for 1-4 ms). Every case must end with a finite, physically bounded state (the bounds of
``tests/test_extreme.assert_bounded``: applied load and centrifugal force, cage between the
races, ball kinetic energy below rolling at the inner-race speed) or stop with a
``BearingSimulationError`` that names what failed. Prints a markdown table with the outcome
and the wall time of each case (default settings: generalized-alpha, 1e-4 s).

    python benchmarks/extreme.py [--cases ramp,10000rpm,...] [--scale 1.0]

Run from the repository root (it reuses the test module's helpers).
"""
import argparse
import dataclasses
import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from exudyn_bearing import REFERENCE_LUBRICANT  # noqa: E402
from exudyn_bearing.cage import CageModel  # noqa: E402
from exudyn_bearing.errors import BearingSimulationError  # noqa: E402
from exudyn_bearing.races import Driven  # noqa: E402
from tests.test_extreme import RPM, W, assert_bounded, run  # noqa: E402

RAMP = 0.05  # s, 0 -> 1800 rpm
STEP = 0.005  # s, time of the load steps


def _ramp(t):
    return RPM * min(max(t, 0.0) / RAMP, 1.0)


# name: (simulated time s, run() keyword arguments, axial load and inner speed for the bounds)
CASES = {
    "c_etaP 2e-8 (very stiff traction), 1.3 kN": (
        0.05, dict(lubricant=dataclasses.replace(REFERENCE_LUBRICANT, pressure_viscosity=2e-8), axialForce=1300.0),
        1300.0, W),
    "near-zero load, F_a 20 N": (0.05, dict(axialForce=20.0), 20.0, W),
    "unloaded zone: 100 rpm, F_a 2.2 kN + F_r 2 kN": (
        0.05, dict(rpm=100.0, axialForce=2200.0, radialForce=2000.0), 2200.0 + 2000.0, 100 * math.pi / 30),
    "10 000 rpm, 1.3 kN": (0.02, dict(rpm=10000.0, axialForce=1300.0), 1300.0, 10000 * math.pi / 30),
    "run-up 0 -> 1800 rpm in 50 ms, 1.3 kN": (0.06, dict(innerRace=Driven(_ramp), axialForce=1300.0), 1300.0, W),
    "axial load step 0.2 -> 3 kN": (0.03, dict(axialForce=lambda t: 200.0 if t < STEP else 3000.0), 3000.0, W),
    "cage stiffness 1e9 N/m, 1.3 kN": (0.03, dict(cage=CageModel(stiffness=1e9), axialForce=1300.0), 1300.0, W),
    "very heavy axial load 100 kN": (0.01, dict(axialForce=1e5), 1e5, W),
    "impossible load (1e8 N step)": (0.01, dict(axialForce=lambda t: 1300.0 if t < STEP else 1e8), 1e8, W),
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scale", type=float, default=1.0, help="factor on every case's simulated time")
    args = parser.parse_args()
    print("| case | simulated (s) | outcome | wall (s) | wall per 0.1 s (s) |")
    print("|---|---:|---|---:|---:|")
    for name, (sim_time, kwargs, axial, w_max) in CASES.items():
        sim_time *= args.scale
        start = time.perf_counter()
        try:
            res = run(sim_time, **kwargs)
            try:
                assert_bounded(res, axial, w_max)
                outcome = (f"bounded; max inner load {res.inner['load'].max():.4g} N, final kinematic cage slip "
                           f"{res.kinematic_cage_slip_percent[-1]:.3g} %")
            except AssertionError as err:
                outcome = f"**NOT BOUNDED** ({err})"
        except BearingSimulationError as err:
            outcome = "stopped: " + str(err).split(": SolveDynamic")[0][:230]
        wall = time.perf_counter() - start
        print(f"| {name} | {sim_time:g} | {outcome} | {wall:.1f} | {wall / sim_time * 0.1:.1f} |", flush=True)


if __name__ == "__main__":
    main()
