"""Wall time per 0.1 s simulated: the reference bearing with full EHD contacts (16 balls,
1800 rpm, F_a 1.3 kN, recommended settings) against Exudyn's own
``exudyn.machines.CreateBallBearing`` scene of the same ball count, speed and simulated
time (penalty contact with Coulomb friction in C++), measured in one run.

    python benchmarks/speed.py [--time 0.02]
"""
import argparse
import time

import numpy as np
import exudyn as exu
from exudyn.utilities import *  # noqa: F401,F403  (Exudyn scene style)
import exudyn.machines as machines

from exudyn_bearing import REFERENCE_BEARING as B, CreateAngularContactBearing, SolverSettings, races, run_solver


def ours(sim_time):
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    brg = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300, show=False)
    mbs.Assemble()
    info = run_solver(mbs, [brg], sim_time, SolverSettings())
    return info.wall_time_s, info


def exudyn_ball_bearing(sim_time, step=1e-5):
    """Exudyn's CreateBallBearing with the reference bearing's ball count and size."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    data = machines.GetBallBearingData(axis=[0, 0, 1], outsideDiameter=0.205, boreDiameter=0.105, width=0.04,
                                       nBalls=B.balls, radiusBalls=B.ball_radius, radiusCage=B.pitch_radius,
                                       innerGrooveRadius=0.52 * B.ball_diameter, outerGrooveRadius=0.52 * B.ball_diameter)
    ground = mbs.CreateGround()
    m_outer = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground))
    inner = mbs.CreateRigidBody(inertia=InertiaCylinder(7850, 0.04, outerRadius=0.06, axis=2, innerRadius=0.05),
                                initialAngularVelocity=[0, 0, 1800 * np.pi / 30],
                                nodeType=exu.NodeType.RotationRotationVector)
    m_inner = mbs.AddMarker(MarkerBodyRigid(bodyNumber=inner))
    mbs.CreateForce(bodyNumber=inner, loadVector=[0, 0, 1300.0])  # pushes the inner ring axially
    machines.CreateBallBearing(mbs, data, m_inner, m_outer, densityBalls=7850, densityCage=8500,
                               cageInitialAngularVelocity=[0, 0, B.cage_speed(1800 * np.pi / 30)])
    mbs.Assemble()
    s = exu.SimulationSettings()
    s.timeIntegration.endTime = sim_time
    s.timeIntegration.numberOfSteps = int(round(sim_time / step))
    s.timeIntegration.verboseMode = 0
    s.solution.file.write = False
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    exu.config.printToConsole = False
    exu.config.suppressWarnings = True
    start = time.perf_counter()
    # implicit: CreateBallBearing's balls carry Euler-parameter nodes, which Exudyn's
    # explicit solvers refuse (algebraic constraint)
    exu.SolveDynamic(mbs, s, showHints=False)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.02, help="simulated time per scene, s")
    args = parser.parse_args()
    wall_ours, info = ours(args.time)
    wall_exu = exudyn_ball_bearing(args.time)
    per = lambda w: w / args.time * 0.1  # noqa: E731
    print(f"| scene | settings | wall per 0.1 s simulated |")
    print(f"|---|---|---:|")
    print(f"| exudyn-bearing, reference bearing, full EHD | generalized-alpha, step {info.solver['step']:g} s, "
          f"{info.newton_iterations} Newton its / {info.steps} steps | {per(wall_ours):.2f} s |")
    print(f"| Exudyn machines.CreateBallBearing (penalty + Coulomb) | generalized-alpha (defaults), step 1e-5 s | {per(wall_exu):.2f} s |")
    print(f"ratio ours / Exudyn's = {wall_ours / wall_exu:.2f} (same run, {args.time:g} s simulated each)")


if __name__ == "__main__":
    main()
