"""Wall time per 0.1 s simulated: the reference bearing with full EHD contacts (16 balls,
1800 rpm, F_a 1.3 kN, recommended settings) with the compiled contact kernels (default) and
with the numpy functions (``ContactLaw(compiled=False)``), against Exudyn's own
``exudyn.machines.CreateBallBearing`` scene of the same ball count, speed and simulated
time (penalty contact with Coulomb friction in C++), measured in one run. Building the
model includes loading (or, the very first time, compiling) the numba kernels; that cost
is printed on its own. The default is one whole 0.1 s per scene, once (Exudyn's scene
alone takes ~2.5 min); ``--time 0.02 --repeat 3`` gives a quicker, interleaved median.

    python benchmarks/speed.py [--time 0.1] [--repeat 1]

``--matrix`` instead runs the heavily-loaded and high-speed case matrix (issue 14: cases (a)-(f);
issue 19: (g28/g48/g72) the 35-mm bearing at 28 000-72 000 rpm, (h1/h2) the 40-mm spindle at 55 000 rpm;
issue 52: (g72L) the 35-mm bearing at 72 000 rpm with every loss of the TP-2275 heat comparison; each at the defaults from the package's start state, with the half-step error estimate) and
prints wall time, steps against the nominal count (more steps = step cuts), Newton
iterations, Jacobians, the estimate of the kinematic cage slip and the cost relative to
case (a) in the same run ((f) also per cage revolution):

    python benchmarks/speed.py --matrix [--time 0.1] [--cases a,b,e1]
"""
import argparse
import time

import numpy as np
import exudyn as exu
from exudyn.utilities import *  # noqa: F401,F403  (Exudyn scene style)
import exudyn.machines as machines

from contact.ballrace import ContactLaw
from exudyn_bearing.results.outputs import settled_label
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


def _deep_groove():
    """The deep-groove example bearing of docs/REFERENCE.md (6205-size balls, 10 um diametral clearance)."""
    from exudyn_bearing import Bearing

    return Bearing.from_clearance(diametral_clearance=10e-6, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                  inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)


def _spindle():
    """A spindle-type bearing: Z 18, D 7.144 mm, d_m 54 mm, conformity 0.52/0.52, 15 deg."""
    from exudyn_bearing import Bearing

    return Bearing(balls=18, ball_diameter=7.144e-3, pitch_diameter=54e-3, inner_conformity=0.52,
                   outer_conformity=0.52, contact_angle=np.radians(15.0))


def _high_speed():
    """The 35-mm high-speed bearing with its ester oil and 0.5 % oil-air drag (issue 19, MODEL.md §11)."""
    from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG

    return dict(bearing=HIGH_SPEED_35MM_BEARING, lubricant=ESTER_TURBINE_OIL, ball_drag=HIGH_SPEED_DRAG)


def _high_speed_every_loss():
    """The 35-mm bearing with every loss of NASA TP-2275's heat comparison (benchmarks/thermal_tp2275.py):
    rolling resistance, the thermal film, an outer-land-guided cage (4-mm land), 0.5 % oil-air drag."""
    from exudyn_bearing import CageModel, ContactLaw

    return dict(_high_speed(), cage=CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3),
                contact_law=ContactLaw(rolling_resistance=True, thermal_film=True))


def _spindle_40mm():
    """The 40-mm spindle bearing with the same oil and drag (issue 19)."""
    from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, SPINDLE_40MM_BEARING

    return dict(bearing=SPINDLE_40MM_BEARING, lubricant=ESTER_TURBINE_OIL, ball_drag=HIGH_SPEED_DRAG)


#: name: (description, factory of simulate() keywords — or of a Bearing — or None for the
#: reference, axial N, radial N, rpm)
MATRIX = {
    "a": ("reference, 1.3 kN axial, 1800 rpm", None, 1300.0, 0.0, 1800.0),
    "b": ("reference, 2.2 kN + 2 kN radial, 1800 rpm", None, 2200.0, 2000.0, 1800.0),
    "c": ("reference, 3 kN + 6 kN radial, 1800 rpm", None, 3000.0, 6000.0, 1800.0),
    "d": ("reference, 10 kN axial, 1800 rpm", None, 10000.0, 0.0, 1800.0),
    "e1": ("deep groove, 1 kN radial + 200 N axial, 3000 rpm", _deep_groove, 200.0, 1000.0, 3000.0),
    "e2": ("deep groove, 2.5 kN radial, 3000 rpm", _deep_groove, 0.0, 2500.0, 3000.0),
    "e3": ("deep groove, 1 kN axial, 3000 rpm", _deep_groove, 1000.0, 0.0, 3000.0),
    "f1": ("spindle, 300 N axial, 12 000 rpm", _spindle, 300.0, 0.0, 12000.0),
    "f2": ("spindle, 300 N + 600 N radial, 12 000 rpm", _spindle, 300.0, 600.0, 12000.0),
    "g28": ("35-mm high-speed, 667 N, 28 000 rpm", _high_speed, 667.0, 0.0, 28000.0),
    "g48": ("35-mm high-speed, 667 N, 48 000 rpm", _high_speed, 667.0, 0.0, 48000.0),
    "g72": ("35-mm high-speed, 667 N, 72 000 rpm", _high_speed, 667.0, 0.0, 72000.0),
    "g72L": ("35-mm high-speed, 667 N, 72 000 rpm, every loss", _high_speed_every_loss, 667.0, 0.0, 72000.0),
    "h1": ("40-mm spindle, 1 kN, 55 000 rpm", _spindle_40mm, 1000.0, 0.0, 55000.0),
    "h2": ("40-mm spindle, 1 kN + 500 N radial, 55 000 rpm", _spindle_40mm, 1000.0, 500.0, 55000.0),
    "h3": ("40-mm spindle, 1 kN, 4 000 rpm (thin film)", _spindle_40mm, 1000.0, 0.0, 4000.0),
}


def matrix(sim_time, names, law=None, settings=None):
    from exudyn_bearing import simulate
    from exudyn_bearing.errors import BearingSimulationError

    # a process's first run pays one-time costs (numba's thread pool, first dispatches):
    # 0.3-0.4 s on case (a), which would flatter every ratio to it
    simulate(axial_force=1300.0, rpm=1800.0, time=0.002, settings=SolverSettings(progress=False))
    rows, wall_a, cpu_a = [], None, None
    for name in names:
        text, factory, axial, radial, rpm = MATRIX[name]
        made = None if factory is None else factory()
        kw = {} if made is None else (made if isinstance(made, dict) else {"bearing": made})
        if law is not None:
            kw["contact_law"] = law
        if settings is not None:
            kw["settings"] = settings
        start = time.perf_counter()
        try:
            run = simulate(axial_force=axial, radial_force=radial, rpm=rpm, time=sim_time, error_estimate=True, **kw)
        except Exception as err:  # noqa: BLE001 - a failing case is a row of the table
            rows.append(f"| {name} | {text} | fails after {time.perf_counter() - start:.1f} s: "
                        f"{str(err)[:160]} | | | | | | | | |")
            continue
        wall = run.wall_time_s
        nominal = int(round(sim_time / run.solver["step"]))
        wall_a = wall if name == "a" else wall_a
        est = run.error_estimate["kinematic_cage_slip_percent"]
        revs = run.cage_speed * sim_time / (2 * np.pi)
        ratio = f"{wall / wall_a:.2f}" if wall_a else "-"
        cpu = run.cpu_time_s
        cpu_a = cpu if name == "a" else cpu_a
        cpu_ratio = f"{cpu / cpu_a:.2f}" if cpu_a else "-"
        rows.append(f"| {name} | {text} | {wall / sim_time * 0.1:.2f} s ({wall / max(revs, 1e-12):.2f} s per cage rev) "
                    f"| {cpu / sim_time * 0.1:.2f} s "
                    f"| {run.steps} / {nominal} ({run.solver['step']:.3g} s) | {run.newton_iterations} | {run.jacobian_updates} | "
                    f"{run.kinematic_cage_slip_percent:.3f} % ± {est:.2g} pp | {settled_label(run.settled)} | {ratio} "
                    f"| {cpu_ratio} |")
    print(f"| case | scene | wall per 0.1 s | CPU per 0.1 s | steps / nominal | Newton its | Jacobians | kinematic cage "
          f"slip ± half-step estimate | settled | wall / (a) | CPU / (a) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---|---:|---:|")
    print("\n".join(rows))
    print(f"({sim_time:g} s simulated per case, default settings, each from the package's start state; the "
          f"estimate's own run is not in the wall time)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.1, help="simulated time per scene, s")
    parser.add_argument("--repeat", type=int, default=1, help="runs per scene; the median wall time is reported")
    parser.add_argument("--matrix", action="store_true", help="the heavily-loaded/high-speed case matrix")
    parser.add_argument("--cases", default=",".join(MATRIX), help="matrix cases, comma-separated")
    parser.add_argument("--traction", default=None, help="matrix: ContactLaw(traction=...) for every case")
    parser.add_argument("--recovery-iterations", type=int, default=None,
                        help="matrix: SolverSettings(step_recovery_iterations=...) for every case")
    parser.add_argument("--no-predictor", action="store_true",
                        help="matrix: SolverSettings(predictor=False), Exudyn's zero-acceleration Newton start")
    args = parser.parse_args()
    if args.matrix:
        law = ContactLaw(traction=args.traction) if args.traction else None
        settings = None
        if args.recovery_iterations is not None or args.no_predictor:
            from exudyn_bearing import SolverSettings

            options = {"predictor": False} if args.no_predictor else {}
            if args.recovery_iterations is not None:
                options["step_recovery_iterations"] = args.recovery_iterations
            settings = SolverSettings(progress=False, **options)
        matrix(args.time, [c.strip() for c in args.cases.split(",") if c.strip()], law, settings)
        return
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
