"""Newton in the implicit runs (MODEL.md §10b): the constant-acceleration start
(exudyn_bearing/model/predictor.py) may change how Newton gets to a step's solution, never the
solution; the absolute tolerance follows the force law's resolution."""
import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
from scipy.spatial.transform import Rotation  # noqa: E402

from exudyn_bearing import CreateAngularContactBearing, SolverSettings, races, run_solver  # noqa: E402
from exudyn_bearing.model.predictor import (VARIABLE, NewtonPredictor, compose_rotation_vectors,  # noqa: E402
                                                 install_predictor)


def test_composition_is_the_rotation_product():
    """R(compose(θ, ω)) = R(θ) exp(ω̃), against SciPy's rotations, near zero and near π."""
    rng = np.random.default_rng(3)
    theta = np.vstack([rng.normal(size=(20, 3)) * 1.5, [[0.0, 0.0, 0.0], [np.pi - 1e-3, 0.0, 0.0],
                                                        [0.0, 1e-9, 0.0]]])
    omega = np.vstack([rng.normal(size=(20, 3)) * 1e-3, [[1e-3, 2e-3, 0.0], [0.0, 0.0, 1e-2], [0.0, 0.0, 0.0]]])
    got = Rotation.from_rotvec(compose_rotation_vectors(theta, omega)).as_matrix()
    want = (Rotation.from_rotvec(theta) * Rotation.from_rotvec(omega)).as_matrix()
    assert np.abs(got - want).max() < 1e-12


def _spinning_body(predict):
    """A free asymmetric rigid body under gravity, spinning about all three axes."""
    from exudyn.utilities import RigidBodyInertia

    mbs = exu.SystemContainer().AddSystem()
    body = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=1.0, inertiaTensor=np.diag([1.0, 2.0, 2.5])),
                               referencePosition=[0, 0, 0], initialVelocity=[1, 0, 0],
                               initialAngularVelocity=[3.0, 1.0, 20.0], gravity=[0, -9.81, 0],
                               nodeType=exu.NodeType.RotationRotationVector, returnDict=True)
    predictor = install_predictor(mbs, [body["nodeNumber"]]) if predict else None
    mbs.Assemble()
    s = exu.SimulationSettings()
    s.timeIntegration.numberOfSteps, s.timeIntegration.endTime = 400, 0.4
    s.timeIntegration.newton.relativeTolerance = 1e-12
    s.timeIntegration.newton.absoluteTolerance = 1e-12
    s.timeIntegration.generalizedAlpha.spectralRadius = 0.5
    s.timeIntegration.verboseMode = 0
    s.solution.file.write = False
    assert exu.SolveDynamic(mbs, s)
    data = mbs.systemData
    return (np.asarray(data.GetODE2Coordinates()), np.asarray(data.GetODE2Coordinates_t()),
            mbs.sys["dynamicSolver"].it.newtonStepsCount, predictor)


def test_predictor_leaves_the_solution_of_a_spinning_body():
    """With Newton converged tightly, the predicted start gives the same motion to 1e-8
    (measured 4e-10; Exudyn's Lie-group Newton composes its increments one after another,
    so paths from different starts differ at second order). A start whose velocity misses
    its shift, or whose rotation is updated to first order only, would not: Newton's
    increments keep a start's inconsistency (checked: 0.43 and 3e-3 after 0.4 s)."""
    q0, v0, _, _ = _spinning_body(False)
    q1, v1, _, predictor = _spinning_body(True)
    assert predictor.shifts == 399  # every step but the first (module docstring)
    assert np.abs(q1 - q0).max() < 1e-8 and np.abs(v1 - v0).max() < 1e-9


def _reference_scene():
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    return mbs, handle


def test_bearing_solution_does_not_depend_on_the_predictor():
    """The reference bearing, Newton converged to 1e-8: cage slip and all node states with
    and without the predicted start agree to Newton's tolerance (at the default 1e-4 the
    two differ by ~1e-2 pp, each within its own convergence error)."""
    results = {}
    for predict in (True, False):
        mbs, handle = _reference_scene()
        info = run_solver(mbs, [handle], 0.004, SolverSettings(progress=False, predictor=predict,
                                                               relative_tolerance=1e-8, absolute_tolerance=1e-9))
        t, q, q_t = handle.States(mbs)
        results[predict] = (handle.Results(mbs).kinematic_cage_slip_percent[-1], q[-1], q_t[-1], info)
    (s1, q1, v1, i1), (s0, q0, v0, i0) = results[True], results[False]
    assert abs(s1 - s0) < 1e-5  # measured 1.4e-7 pp
    assert np.abs(q1 - q0).max() < 1e-7 and np.abs(v1 - v0).max() < 1e-7 * np.abs(v0).max()  # 6e-9, 3e-9
    assert i1.newton_iterations <= i0.newton_iterations


def test_plain_solve_dynamic_gets_the_predictor_and_settings_can_turn_it_off():
    mbs, handle = _reference_scene()
    predictor = mbs.variables[VARIABLE]
    assert isinstance(predictor, NewtonPredictor) and len(predictor.nodes) == len(handle.nodeNumbers)
    s = exu.SimulationSettings()
    s.timeIntegration.endTime, s.timeIntegration.numberOfSteps = 2e-3, 20
    s.timeIntegration.newton.relativeTolerance, s.timeIntegration.newton.absoluteTolerance = 1e-4, 1e-6
    s.timeIntegration.verboseMode = 0
    s.solution.file.write = False
    assert exu.SolveDynamic(mbs, s)
    assert predictor.shifts == 20  # every step: the reference bearing starts from its steady state
    run_solver(mbs, [handle], 1e-3, SolverSettings(progress=False, predictor=False))
    assert predictor.shifts == 20 and predictor.enabled  # off for that run only


def test_explicit_solver_is_left_alone():
    mbs, handle = _reference_scene()
    run_solver(mbs, [handle], 2e-5, SolverSettings(progress=False, solver="rk44", step=1e-6))
    assert mbs.variables[VARIABLE].shifts == 0


def test_a_users_own_pre_newton_function_is_still_called():
    calls = []
    mbs = exu.SystemContainer().AddSystem()
    mbs.SetPreNewtonResidualUserFunction(lambda mbs_, t, it, disc: calls.append(it))
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    run_solver(mbs, [handle], 5e-4, SolverSettings(progress=False))
    assert mbs.variables[VARIABLE].shifts == 5 and calls.count(0) == 5


def test_a_grown_step_gets_a_fresh_jacobian():
    """The 40-mm spindle bearing at 4 000 rpm (thin ester film) from Exudyn's own first step
    (its first step not predicted, as for a start that is not a steady state) cuts that step
    down to 2e-6 s and grows it back to 3.33e-5 s. Exudyn keeps the Jacobian of the smaller
    step, whose mass part is 4x too large after a doubling; from the predicted iterate that
    matrix diverged and each regrown step failed again (248 steps for these 2 ms, 60
    nominal); with a fresh Jacobian at a new step size: 93 (the first cascade's 33
    included). Predicted, the same first step is not cut at all (61 steps)."""
    from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, SPINDLE_40MM_BEARING

    steps = {}
    for steady in (False, True):
        mbs = exu.SystemContainer().AddSystem()
        handle = CreateAngularContactBearing(mbs, SPINDLE_40MM_BEARING, ESTER_TURBINE_OIL, innerRace=races.Driven(4000),
                                             axialForce=1000.0, ballDrag=HIGH_SPEED_DRAG, show=False)
        mbs.Assemble()
        mbs.variables[VARIABLE].steady_start = steady
        info = run_solver(mbs, [handle], 0.002, SolverSettings(progress=False))
        assert info.solver["step"] == pytest.approx(1e-4 / 3)
        steps[steady] = info.steps
    assert steps[True] <= 62 and 62 < steps[False] < 120


def test_newton_absolute_tolerance_follows_the_largest_contact_load():
    """run_solver's default absolute tolerance is 3e-5 of the largest contact load (MODEL.md
    §10b): on the reference bearing at 1.3 kN between F_a/Z and 1.5 F_a/(Z sin a0) (the inner
    load; the outer one adds the ~34 N centrifugal force), 1e-6 for DOPRI5."""
    import math

    from exudyn_bearing import REFERENCE_BEARING

    mbs, handle = _reference_scene()
    info = run_solver(mbs, [handle], 2e-4, SolverSettings(progress=False))
    share = 1300.0 / REFERENCE_BEARING.balls
    tol = info.solver["absolute_tolerance"]
    assert tol == handle.RecommendedAbsoluteTolerance()
    assert 3e-5 * share < tol < 3e-5 * 1.5 * share / math.sin(REFERENCE_BEARING.contact_angle)
    assert SolverSettings(solver="dopri5").resolved([handle]).absolute_tolerance == 1e-6
    assert SolverSettings(absolute_tolerance=1e-3).resolved([handle]).absolute_tolerance == 1e-3


@pytest.mark.slow
def test_first_step_is_predicted_only_from_a_steady_start():
    """The deep-groove bearing under 2.5 kN radial load starts from the quasi-dynamic balance,
    whose initial accelerations carry transients (the cage at ~1600 m/s²): its first step is
    left to Exudyn (5 steps, 4 predicted, no cut). Predicted from those accelerations, the
    first step failed and was cut (11 steps for 5)."""
    from exudyn_bearing import Bearing

    groove = Bearing.from_clearance(diametral_clearance=10e-6, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                    inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)
    steps = {}
    for force_steady in (False, True):
        mbs = exu.SystemContainer().AddSystem()
        handle = CreateAngularContactBearing(mbs, groove, innerRace=races.Driven(3000), radialForce=2500.0, show=False)
        mbs.Assemble()
        predictor = mbs.variables[VARIABLE]
        assert handle.initialSteadyState is None and not predictor.steady_start
        predictor.steady_start = force_steady
        info = run_solver(mbs, [handle], 1.25e-4, SolverSettings(progress=False))
        assert info.solver["step"] == pytest.approx(2.5e-5)
        steps[force_steady] = (info.steps, predictor.shifts)
    assert steps[False] == (6, 4)  # Exudyn counts the start as a step
    assert steps[True][0] > 6


@pytest.mark.parametrize("predict", [True, False])
def test_step_cuts_are_counted_as_exudyn_logs_them(tmp_path, predict):
    """The cut counter (RunInfo.cut_times) against Exudyn's own solver log: the CWRU 6205 from
    pure rolling under 300 N radial fails its first steps (the rolling start's transients),
    and every 'convergence failed' line of the log is one cut, at the failed attempt's end
    time; counted whether or not the predictor shifts Newton's start."""
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import CWRU_6205_BEARING

    mbs = exu.SystemContainer().AddSystem()
    CreateAngularContactBearing(mbs, CWRU_6205_BEARING, innerRace=races.Driven(1797.0), outerRace=races.Housing(),
                                radialForce=300.0, initialState="rolling", show=False,
                                surface=SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),)))
    mbs.Assemble()
    mbs.variables[VARIABLE].enabled = predict
    s = exu.SimulationSettings()
    s.timeIntegration.numberOfSteps, s.timeIntegration.endTime = 40, 1e-3
    s.timeIntegration.newton.relativeTolerance = 1e-4
    s.timeIntegration.verboseModeFile = 2
    s.solution.solverInformationFileName = str(tmp_path / "solver.txt")
    s.solution.file.write = False
    info = run_solver(mbs, [], 1e-3, s)
    logged = [float(line.rsplit("time =", 1)[1]) for line in (tmp_path / "solver.txt").read_text().splitlines()
              if "convergence failed" in line]
    assert len(logged) >= 2
    np.testing.assert_allclose(info.cut_times, logged, rtol=1e-5)


def _turn(k, angle):
    return Rotation.from_rotvec(np.asarray(k) * angle).as_matrix()


def test_orbit_carry_is_exact_on_a_precessing_orbit():
    """A ball on a uniform orbit about an axis k through o (any direction, any origin), its body
    A(t) = R_k(Ωt) A0 exp(t ω̃_s) spinning about a body axis that turns with the orbit: its
    acceleration is −Ω² r and its angular acceleration Ω k × A ω_s, both turning with the orbit.
    The accelerations carried from t to t + h equal the motion's own at t + h (translation as a
    global vector, rotation as Exudyn's local one, A(t + h)ᵀ α_g), to rounding; a constant
    acceleration (the predictor before) misses them by ~Ω h of their size."""
    from exudyn_bearing.model.predictor import _carry_orbits

    rng = np.random.default_rng(7)
    k = rng.normal(size=3)
    k /= np.linalg.norm(k)
    o = rng.normal(size=3) * 0.01
    r0 = np.cross(k, rng.normal(size=3))
    r0 *= 0.03 / np.linalg.norm(r0)
    big_omega, h, w_s = 3300.0, 1.25e-5, np.array([100.0, -2.3e4, 900.0])
    a0 = Rotation.from_rotvec(rng.normal(size=3)).as_matrix()
    ref = rng.normal(size=6) * 1e-3

    def state(t):
        turn = _turn(k, big_omega * t)
        r = turn @ r0
        body = turn @ a0 @ Rotation.from_rotvec(w_s * t).as_matrix()
        p = o + 0.004 * k + r
        v = big_omega * np.cross(k, r)
        acc = -big_omega ** 2 * r
        alpha_local = body.T @ (big_omega * np.cross(k, body @ w_s))
        q = np.concatenate([p, Rotation.from_matrix(body).as_rotvec()]) - ref
        return q, np.concatenate([v, np.zeros(3)]), np.concatenate([acc, alpha_local])

    t = 0.0123
    q0, v0, a_n = state(t)
    q1, _, a_exact = state(t + h)
    carried = a_n.copy()
    _carry_orbits(q0, v0, q1, ref, a_n, np.array([0]), o[None], k[None], h, carried)
    scale_t, scale_r = np.linalg.norm(a_exact[:3]), np.linalg.norm(a_exact[3:])
    assert np.linalg.norm(carried[:3] - a_exact[:3]) < 1e-12 * scale_t
    assert np.linalg.norm(carried[3:] - a_exact[3:]) < 1e-9 * scale_r
    # the constant acceleration misses by the step's turn: Ω h of the orbit, ~|ω_s| h in the body
    assert np.linalg.norm(a_n[:3] - a_exact[:3]) > 0.5 * big_omega * h * scale_t
    assert np.linalg.norm(a_n[3:] - a_exact[3:]) > 0.1 * scale_r


def _high_speed_scene(orbits=True):
    from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG

    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, innerRace=races.Driven(72000),
                                         axialForce=667.0, ballDrag=HIGH_SPEED_DRAG, show=False)
    mbs.Assemble()
    if not orbits:
        mbs.variables[VARIABLE].orbits.clear()
    return mbs, handle


def test_carried_orbits_take_fewer_newton_iterations_at_speed():
    """The 35-mm bearing at 72 000 rpm: its balls turn 0.04 rad about the axis a step, their
    bodies 0.3 rad, so the previous step's accelerations put the predicted iterate ~400 N from
    the solution (the balls' ~3e5 m/s² orbit acceleration) and Newton needs ~5.5 iterations a
    step; carried along the orbits, ~12 N and ~3 (measured over 0.01 s: 4386 against 2374
    iterations, 699 against 301 Jacobians). Over 1 ms here: at most 3/4 of the iterations, the
    same solution to the convergence test's own spread (0.01 pp of the cage slip)."""
    runs = {}
    for orbits in (True, False):
        mbs, handle = _high_speed_scene(orbits)
        info = run_solver(mbs, [handle], 0.001, SolverSettings(progress=False))
        runs[orbits] = (info, handle.Results(mbs).kinematic_cage_slip_percent[-1])
    (carried, slip1), (constant, slip0) = runs[True], runs[False]
    assert carried.steps == constant.steps
    assert carried.newton_iterations <= 0.75 * constant.newton_iterations
    assert abs(slip1 - slip0) < 0.01


def test_a_restarted_newton_starts_again_from_the_predicted_iterate():
    """Exudyn restarts a step's Newton from its zero-acceleration start when an iteration
    more than doubles the residual (CSolverBase::Newton). A scene function that throws the balls
    1 µm off at the third iteration of one step forces that: the predictor puts the restarted
    Newton back on its predicted iterate (once), the run ends where an undisturbed one does
    (Newton converged to 1e-8), and that step takes fewer iterations than when the restart is
    left at Exudyn's start (the predictor's re-application made a no-op)."""
    settings = SolverSettings(progress=False, relative_tolerance=1e-8, absolute_tolerance=1e-9)
    ends = {}
    for disturb in (True, "left at Exudyn's start", False):
        mbs = exu.SystemContainer().AddSystem()
        done = []

        def kick(mbs_, t, it, disc):
            if disturb and not done and it == 3 and t > 2.5e-4:
                done.append(t)
                data = mbs_.systemData
                q = np.array(data.GetODE2Coordinates(configuration=exu.ConfigurationType.Current))
                q[0:6 * 16:6] += 1e-6
                data.SetODE2Coordinates(q, configuration=exu.ConfigurationType.Current)

        mbs.SetPreNewtonResidualUserFunction(kick)
        handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
        mbs.Assemble()
        predictor = mbs.variables[VARIABLE]
        if disturb == "left at Exudyn's start":
            first = predictor._apply
            applied = []

            def first_only(mbs_, prediction):  # the restart's second application does nothing
                if not any(p is prediction for p in applied):
                    applied.append(prediction)
                    first(mbs_, prediction)

            predictor._apply = first_only
        info = run_solver(mbs, [handle], 5e-4, settings)
        ends[disturb] = (np.asarray(mbs.systemData.GetODE2Coordinates()), predictor, info, done)
    (q1, pred1, info1, done1), (q0, pred0, info0, _) = ends[True], ends[False]
    _, _, left, done_left = ends["left at Exudyn's start"]
    assert done1 and done_left and pred1.restarts == 1 and pred0.restarts == 0
    assert info1.steps == info0.steps and not pred1.cut_times
    assert np.abs(q1 - q0).max() < 1e-7
    assert info1.newton_iterations < left.newton_iterations
