"""A user's own Exudyn scene solved by ``exu.SolveDynamic`` with ``exu.SimulationSettings``
against the package's ``run_solver`` on the same scene, wall time measured in one run
(issue 16: within 1.3x). The builder installs the block Jacobian on the contact object, so
the plain solve gets it too, and the Newton start of MODEL.md §10b; Exudyn's default Newton
tolerances are set as the README says (relative 1e-4, absolute
``brg.RecommendedAbsoluteTolerance()``: its 1e-8 sits below the traction rule's resolution).

    python benchmarks/plain_solve.py [--time 0.05] [--case reference|deep-groove]
"""
import argparse
import sys
import time
from pathlib import Path

import exudyn as exu

from exudyn_bearing import CreateAngularContactBearing, SolverSettings, races, run_solver

sys.path.insert(0, str(Path(__file__).parent))
from speed import _deep_groove  # noqa: E402


def scene(case):
    mbs = exu.SystemContainer().AddSystem()
    if case == "reference":
        h = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    else:
        h = CreateAngularContactBearing(mbs, _deep_groove(), innerRace=races.Driven(3000), axialForce=200.0,
                                        radialForce=1000.0, show=False)
    mbs.Assemble()
    return mbs, h


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.05)
    parser.add_argument("--case", choices=("reference", "deep-groove"), default="reference")
    args = parser.parse_args()
    mbs, h = scene(args.case)
    info = run_solver(mbs, [h], args.time, SolverSettings())
    ours = h.Results(mbs).summary()["kinematic_cage_slip_percent"]

    mbs, h = scene(args.case)
    step = h.RecommendedStep()
    ss = exu.SimulationSettings()
    ss.timeIntegration.endTime = args.time
    ss.timeIntegration.numberOfSteps = int(round(args.time / step))
    ss.timeIntegration.newton.relativeTolerance = 1e-4
    ss.timeIntegration.newton.absoluteTolerance = h.RecommendedAbsoluteTolerance()
    ss.timeIntegration.adaptiveStepRecoveryIterations = 5
    ss.timeIntegration.verboseMode = 0
    ss.solution.sensors.writePeriod = 1e-4  # run_solver's output period: the state sensor records at it
    start = time.perf_counter()
    exu.SolveDynamic(mbs, ss)
    plain_wall = time.perf_counter() - start
    plain = h.Results(mbs).summary()["kinematic_cage_slip_percent"]
    print(f"{args.case}, {args.time:g} s: run_solver {info.wall_time_s:.2f} s ({ours:.4f} %), "
          f"exu.SolveDynamic {plain_wall:.2f} s ({plain:.4f} %), ratio {plain_wall / info.wall_time_s:.2f}")


if __name__ == "__main__":
    main()
