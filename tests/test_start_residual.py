"""The start residual of a predicted step from the predicted iterate (MODEL.md §10b,
exudyn_bearing/model/start_residual.py): a first-order Taylor expansion of the forces, the
predicted iterate's forces served exactly once, one force evaluation per Newton iteration."""
import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from exudyn_bearing import CreateAngularContactBearing, SolverSettings, races, run_solver  # noqa: E402
from exudyn_bearing.model.predictor import VARIABLE, compose_rotation_vectors  # noqa: E402
from exudyn_bearing.model.start_residual import StartResidual  # noqa: E402
from exudyn_bearing.races import node_rows  # noqa: E402


def _running_reference():
    """The reference bearing 2 ms into a run: (mbs, handle, t, q without reference, q̇, q̈)
    of the connector's nodes, and Exudyn's β' and γ' of its step."""
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    run_solver(mbs, [handle], 0.002, SolverSettings(progress=False))
    rows = node_rows(mbs, handle.nodeNumbers)
    data = mbs.systemData
    q, v, a = (np.asarray(f(), dtype=float)[rows] for f in (data.GetODE2Coordinates, data.GetODE2Coordinates_t,
                                                              data.GetODE2Coordinates_tt))
    solver = mbs.sys["dynamicSolver"]
    h, beta, gamma = solver.it.currentStepSize, solver.newmarkBeta, solver.newmarkGamma
    beta_prime = (1.0 - solver.alphaM) / (h * h * beta * (1.0 - solver.alphaF))
    return mbs, handle, float(data.GetTime()), q, v, a, beta_prime, gamma / (h * beta)


def _shifted(connector, q, v, delta, gamma_prime):
    """The state one Exudyn increment ``delta`` from (q, v): q + δ, rotations composed
    (R exp(δ̃)), v + γ'δ (MODEL.md §10b)."""
    q_p, ref = q.reshape(-1, 6).copy(), connector.reference.reshape(-1, 6)
    d = delta.reshape(-1, 6)
    q_p[:, :3] += d[:, :3]
    q_p[:, 3:] = compose_rotation_vectors(ref[:, 3:] + q_p[:, 3:], d[:, 3:]) - ref[:, 3:]
    return q_p.ravel(), v + gamma_prime * delta


def test_the_start_is_the_predicted_forces_expanded_to_first_order():
    """A step's start, one increment δ = s a/β' before the predicted iterate: the linearized
    forces' error against the exact ones falls as s² (halving s quarters it: first order
    exact, the remainder the contacts' curvature). Measured ratios 3.3–4.1; 15 % of the
    increment's force change at s = 1, a run's real increment."""
    _, handle, t, q, v, a, beta_prime, gamma_prime = _running_reference()
    con = handle.connector
    start = StartResidual(con)
    start.jacobian(t, q, v, 1.0, gamma_prime)
    errors, changes = [], []
    for s in (1.0, 0.5, 0.25, 0.125):
        delta = s * a / beta_prime
        q_p, v_p = _shifted(con, q, v, delta, gamma_prime)
        start.expect(t, q_p, v_p, delta, gamma_prime)
        linearized = start.forces(t, q, v)
        exact = np.asarray(con.residual_forces(t, q, v))
        errors.append(np.linalg.norm(linearized - exact))
        changes.append(np.linalg.norm(np.asarray(con.residual_forces(t, q_p, v_p)) - exact))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 3.0) & (ratios < 5.0)), ratios
    assert errors[0] < 0.3 * changes[0]
    assert start.linearized == 4 and start.exact == 0


def test_the_predicted_forces_are_served_once_and_exactly():
    """The forces served at the predicted iterate are the connector's own there, bit for bit,
    without evaluating again; a second call is evaluated, and a start without a Jacobian (none
    yet, another step size's, or the last solve's) is Exudyn's own."""
    _, handle, t, q, v, a, beta_prime, gamma_prime = _running_reference()
    con = handle.connector
    calls = []
    evaluate = con.residual_forces
    con.residual_forces = lambda *args: calls.append(args[0]) or evaluate(*args)
    start = StartResidual(con)
    assert np.array_equal(start.forces(t, q, v), evaluate(t, q, v)) and len(calls) == 1
    start.expect(t, q, v, np.zeros_like(q), gamma_prime)  # no Jacobian yet: Exudyn's start exactly
    start.forces(t, q, v)
    assert (start.linearized, start.exact, len(calls)) == (0, 1, 2)
    start.jacobian(t, q, v, 1.0, gamma_prime)
    delta = a / beta_prime
    q_p, v_p = _shifted(con, q, v, delta, gamma_prime)
    start.expect(t, q_p, v_p, delta, gamma_prime * (1 + 1e-9))  # a Jacobian of another step size
    start.forces(t, q, v)
    assert (start.linearized, start.exact, len(calls)) == (0, 2, 3)
    start.expect(t, q_p, v_p, delta, gamma_prime)
    start.forces(t, q, v)
    assert (start.linearized, len(calls)) == (1, 4)
    served = start.forces(t, q_p, v_p)
    assert len(calls) == 4 and np.array_equal(served, evaluate(t, q_p, v_p))
    start.forces(t, q_p, v_p)
    assert len(calls) == 5  # served once only
    start.reset()  # a new solve: no Jacobian of the last one
    start.expect(t, q_p, v_p, delta, gamma_prime)
    start.forces(t, q, v)
    assert (start.linearized, start.exact) == (1, 3)


def test_a_predicted_step_evaluates_the_forces_once_per_newton_iteration():
    """The reference run, 5 ms, from its steady state: every step is predicted, and every
    start but the first (no Jacobian yet) linearized, so the connector evaluates its forces
    once per Newton iteration, plus the first step's start and Exudyn's initial
    accelerations (without the linearized start: one evaluation more per step)."""
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    con = handle.connector
    calls = []
    evaluate = con.residual_forces
    con.residual_forces = lambda *args: calls.append(args[0]) or evaluate(*args)
    (start, _), = mbs.variables[VARIABLE].start_residuals
    info = run_solver(mbs, [handle], 0.005, SolverSettings(progress=False))
    steps = info.steps - 1  # Exudyn counts the start as a step
    assert info.cut_times == () and start.exact == 1 and start.linearized == steps - 1
    assert calls.count(0.0) == 1  # Exudyn's initial accelerations
    assert len(calls) == info.newton_iterations + 2


def test_a_step_slow_on_an_old_jacobian_gets_a_fresh_one_next():
    """Exudyn's modified Newton keeps a Jacobian while each iteration at least halves the
    residual; the reference bearing's drifts slowly (the balls orbit), so its steps creep to
    4–5 iterations. After a step that took 4 or more on a Jacobian that had served 10 steps
    or more, the next step takes a fresh one at its predicted iterate (MODEL.md §10b): seen
    here through a scene's own pre-Newton function, which the predictor chains. With the
    balls' accelerations carried along their orbits the reference bearing's steps rarely
    reach 4 iterations, so its predictor keeps them constant here, as before."""
    log = []
    mbs = exu.SystemContainer().AddSystem()
    mbs.SetPreNewtonResidualUserFunction(
        lambda mbs_, t, it, disc: log.append((it, mbs_.sys["dynamicSolver"].it.newtonJacobiCount)))
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    mbs.variables[VARIABLE].orbits.clear()
    run_solver(mbs, [handle], 0.01, SolverSettings(progress=False))
    starts = [i for i, (it, _) in enumerate(log) if it == 0]
    steps = [(max(it for it, _ in log[a:b]), log[a][1]) for a, b in zip(starts, starts[1:])]  # (iterations, Jacobians)
    age, slow = 0, []  # age: steps the Jacobian has served
    for k in range(len(steps) - 2):
        age = age + 1 if steps[k + 1][1] == steps[k][1] else 0
        if steps[k][0] >= 4 and age >= 10:
            slow.append(k)
    assert len(slow) >= 3
    assert all(steps[k + 2][1] > steps[k + 1][1] for k in slow)
