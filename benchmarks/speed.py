"""Wall time per 0.1 s simulated: the reference bearing with full EHD contacts (16 balls,
1800 rpm, F_a 1.3 kN, recommended settings) with the compiled contact kernels (default) and
with the numpy functions (``ContactLaw(compiled=False)``), against Exudyn's own
``exudyn.machines.CreateBallBearing`` scene of the same ball count, speed and simulated
time (penalty contact with Coulomb friction in C++), measured in one run. Building the
model includes loading (or, the very first time, compiling) the numba kernels; that cost
is printed on its own. The default is one whole 0.1 s per scene, once (Exudyn's scene
alone takes ~2.5 min); ``--time 0.02 --repeat 3`` gives a quicker, interleaved median.

    python benchmarks/speed.py [--time 0.1] [--repeat 1]
"""
import argparse
import time

import numpy as np
import exudyn as exu
from exudyn.utilities import *  # noqa: F401,F403  (Exudyn scene style)
import exudyn.machines as machines

from contact.ballrace import ContactLaw
from exudyn_bearing import REFERENCE_BEARING as B, CreateAngularContactBearing, SolverSettings, races, run_solver


def ours(sim_time, law=ContactLaw()):
    """(solver wall time, RunInfo, model build time) of the reference scene."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    start = time.perf_counter()
    brg = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300, contactLaw=law, show=False)
    build = time.perf_counter() - start
    mbs.Assemble()
    info = run_solver(mbs, [brg], sim_time, SolverSettings())
    return info.wall_time_s, info, build


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
    mbs.CreateForce(itemNumber=inner, loadVector=[0, 0, 1300.0])  # pushes the inner ring axially
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
    parser.add_argument("--time", type=float, default=0.1, help="simulated time per scene, s")
    parser.add_argument("--repeat", type=int, default=1, help="runs per scene; the median wall time is reported")
    args = parser.parse_args()
    # interleaved repeats: a burst of load on the shared machine hits all scenes alike
    walls = {"ours": [], "numpy": [], "exudyn": []}
    build = None
    for _ in range(max(1, args.repeat)):
        wall, info, b = ours(args.time)
        build = b if build is None else build
        walls["ours"].append(wall)
        wall, info_numpy, _ = ours(args.time, ContactLaw(compiled=False))
        walls["numpy"].append(wall)
        walls["exudyn"].append(exudyn_ball_bearing(args.time))
    med = {k: float(np.median(v)) for k, v in walls.items()}
    per = lambda w: w / args.time * 0.1  # noqa: E731
    print(f"| scene | settings | wall per 0.1 s simulated (median of {args.repeat}) |")
    print("|---|---|---:|")
    print(f"| exudyn-bearing, reference bearing, full EHD | generalized-alpha, step {info.solver['step']:g} s, "
          f"{info.newton_iterations} Newton its / {info.steps} steps | {per(med['ours']):.2f} s |")
    print(f"| exudyn-bearing, numpy contacts | same, {info_numpy.newton_iterations} Newton its | {per(med['numpy']):.2f} s |")
    print(f"| Exudyn machines.CreateBallBearing (penalty + Coulomb) | generalized-alpha (defaults), step 1e-5 s | "
          f"{per(med['exudyn']):.2f} s |")
    print(f"ratio ours / Exudyn's = {med['ours'] / med['exudyn']:.3f}, numpy contacts / compiled = "
          f"{med['numpy'] / med['ours']:.2f} (same run, {args.time:g} s simulated each); building the first model "
          f"(kernels loaded or compiled): {build:.2f} s")


if __name__ == "__main__":
    main()
