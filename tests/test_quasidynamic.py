"""The quasi-dynamic start under combined load (MODEL.md §12a, exudyn_bearing/solvers/quasidynamic.py)
against the axial steady state (a separate solver) and against the dynamic model."""
import numpy as np
import pytest

pytest.importorskip("exudyn")

from exudyn_bearing import REFERENCE_BEARING as B, REFERENCE_DRAG, REFERENCE_LUBRICANT, simulate, steady_state  # noqa: E402
from exudyn_bearing.solvers.quasidynamic import combined_load_state  # noqa: E402
from exudyn_bearing.simulation.runner import SolverSettings  # noqa: E402


def test_vanishing_radial_load_is_the_axial_steady_state():
    """400 N axial (the balls skid: ~71 % kinematic slip) with 1 N radial: every ball's balance
    at its azimuth, the cage and the inner race as one system gives the cage speed, ball spin
    and race shift of the one-ball steady-state solver (MODEL.md §12) to 0.1 %."""
    steady = steady_state(axial_force=400.0, rpm=1800.0)
    state = combined_load_state(B, REFERENCE_LUBRICANT, axial_force=400.0, radial_force=1.0, rpm=1800.0,
                                ball_drag=REFERENCE_DRAG,
                                steady=steady)
    assert state.converged, state.message
    assert state.cage_speed == pytest.approx(steady.cage_speed, rel=1e-3)
    np.testing.assert_allclose(state.omega, np.tile(steady.ball_omega, (B.balls, 1)), rtol=0,
                               atol=2e-3 * np.linalg.norm(steady.ball_omega))
    assert state.displacement[2] == pytest.approx(steady.inner_race_shift, rel=0.05)
    # the radial load pushes the inner race along +x; the pockets' forces balance the cage
    assert state.displacement[0] > 0
    assert abs(np.sum(state.pocket_force * state.orbit_radius)) < 1e-6 * np.max(np.abs(state.pocket_force)) + 1e-9


@pytest.mark.slow
def test_dynamic_run_from_the_combined_start_holds_its_cage_speed():
    """400 N + 100 N radial at 1800 rpm: from initialState='steady' (the quasi-dynamic start)
    the cage speed stays within 0.2 % of the start over 30 ms, where the pure-rolling start
    drifts by more than 5 % (it needs seconds to settle)."""
    settings = SolverSettings(progress=False)
    run = simulate(axial_force=400.0, radial_force=100.0, rpm=1800.0, time=0.03, initial_state="steady",
                   settings=settings)
    res = run.results
    assert run.initial_steady_state is None  # the combined start is no axial steady state
    start = res.cage_speed[0]
    assert np.max(np.abs(res.cage_speed - start)) < 2e-3 * start
    rolling = simulate(axial_force=400.0, radial_force=100.0, rpm=1800.0, time=0.03, initial_state="rolling",
                       settings=settings).results
    assert abs(rolling.cage_speed[-1] - rolling.cage_speed[0]) > 0.05 * rolling.cage_speed[0]


def _pocket_forces_at_start(mbs, handle):
    """The cage's force on each ball (Z, 3) in the assembled start state, from the connector."""
    import exudyn as exu

    mbs.Assemble()
    q = np.asarray(mbs.systemData.GetODE2Coordinates(configuration=exu.ConfigurationType.Initial))
    q_t = np.asarray(mbs.systemData.GetODE2Coordinates_t(configuration=exu.ConfigurationType.Initial))
    idx = np.concatenate([np.arange(mbs.GetNodeODE2Index(n), mbs.GetNodeODE2Index(n) + 6) for n in handle.nodeNumbers])
    return handle.connector.evaluate(0.0, q[idx] + handle.connector.reference, q_t[idx], details=True).cage_force


@pytest.mark.slow
def test_auto_takes_the_combined_start_and_loads_the_pockets(monkeypatch):
    """'auto' starts combined loads from the quasi-dynamic state, whether the axial load alone
    skids (400 N + 100 N: ~71 % slip) or not (2.2 kN + 2 kN); a continuation given too few
    steps says so. Each ball starts where its pocket pushes it with the balance's
    circumferential force P_j (to 0.1 %), not at the pocket centre (where it would push
    nothing and the balls would start ringing in their pockets). A budget too small for the
    path stops before its first solve."""
    import exudyn as exu

    from exudyn_bearing import CreateAngularContactBearing

    for axial, radial in ((400.0, 100.0), (2200.0, 2000.0)):
        mbs = exu.SystemContainer().AddSystem()
        handle = CreateAngularContactBearing(mbs, axialForce=axial, radialForce=radial, show=False)
        state = handle.initialQuasiDynamicState
        assert state is not None and state.converged and handle.initialSteadyState is None
        cage = _pocket_forces_at_start(mbs, handle)
        psi = state.azimuth
        circumferential = -cage[:, 0] * np.sin(psi) + cage[:, 1] * np.cos(psi)
        assert np.max(np.abs(state.pocket_force)) > 0.5
        np.testing.assert_allclose(circumferential, state.pocket_force, rtol=0,
                                   atol=1e-3 * np.max(np.abs(state.pocket_force)))
    # 300 N radial in steps of at most 40 N (a tenth of the axial load) takes at least 8: a
    # budget of 2 stops before the first solve; pure radial load adds 4 steps back to no axial load
    from exudyn_bearing.solvers import quasidynamic

    solves = []
    newton = quasidynamic.damped_newton
    monkeypatch.setattr(quasidynamic, "damped_newton", lambda *a, **k: solves.append(1) or newton(*a, **k))
    short = combined_load_state(B, REFERENCE_LUBRICANT, axial_force=400.0, radial_force=300.0, rpm=1800.0,
                                ball_drag=REFERENCE_DRAG, max_steps=2)
    assert not short.converged and "steps ran out" in short.message and "needs at least 8," in short.message
    radial = combined_load_state(B, REFERENCE_LUBRICANT, axial_force=0.0, radial_force=300.0, rpm=1800.0,
                                 ball_drag=REFERENCE_DRAG, max_steps=10, max_step=30.0)
    assert not radial.converged and "needs at least 14," in radial.message
    assert not solves


@pytest.mark.slow
def test_pure_radial_start_balances_every_ball():
    """Pure radial load (the README's deep-groove bearing, 10 um clearance, 2.5 kN, 3000 rpm)
    starts from the quasi-dynamic state continued from a seed axial load and taken back to
    zero: the inner race moves along the load, the cage's pocket forces are in torque balance
    (a free cage) and the cage turns at the kinematic speed of a rolling bearing. The 'auto'
    start (its step budget and stall check, steps of an eighth of the load) reaches the same
    balance."""
    from contact.ballrace import ContactLaw
    from exudyn_bearing import Bearing, races
    from exudyn_bearing.solvers.start import steady_start

    deep = Bearing.from_clearance(diametral_clearance=10e-6, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                  inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)
    state = combined_load_state(deep, REFERENCE_LUBRICANT, axial_force=0.0, radial_force=2500.0, rpm=3000.0,
                                ball_drag=REFERENCE_DRAG)
    auto = steady_start(deep, REFERENCE_LUBRICANT, "auto", axial_force=0.0, radial_force=2500.0, rpm_i=3000.0,
                        rpm_o=0.0, sense=1, inner=races.Driven(3000.0), displaced=False, contact_law=ContactLaw(),
                        ball_drag=REFERENCE_DRAG)
    assert auto is not None and auto.converged, getattr(auto, "message", None)
    assert auto.cage_speed == pytest.approx(state.cage_speed, rel=1e-6)
    assert state.converged, state.message
    # along the load, with a small sideways shift from the contacts' traction
    assert state.displacement[0] > 0 and abs(state.displacement[1]) < 0.02 * state.displacement[0]
    assert abs(np.sum(state.pocket_force * state.orbit_radius)) < 1e-6 * max(np.max(np.abs(state.pocket_force)), 1e-3)
    # the kinematic orbital speed of a rolling deep-groove bearing: w_i (1 - D/d_m) / 2 within 1 %
    w_i = 3000.0 * np.pi / 30.0
    assert state.cage_speed == pytest.approx(0.5 * w_i * (1 - deep.ball_diameter / deep.pitch_diameter), rel=0.01)


def _counted_states(monkeypatch, **kw):
    """combined_load_state of the CWRU 6205 (the package's defaults) at 1797 rpm, and the
    number of balances it built."""
    from exudyn_bearing import CWRU_6205_BEARING, BearingSetup
    from exudyn_bearing.solvers import quasidynamic

    s = BearingSetup(CWRU_6205_BEARING)
    balances = []
    make = quasidynamic._Balance.__init__

    def counting(self, *a, **k):
        balances.append(1)
        make(self, *a, **k)

    monkeypatch.setattr(quasidynamic._Balance, "__init__", counting)
    state = combined_load_state(s.bearing, s.lubricant, rpm=1797.0, ball_drag=s.drag, contact_law=s.contact_law,
                                cage=s.cage, **kw)
    return state, len(balances), s.bearing


def test_the_continuation_passes_where_newton_stalls_short_of_its_tolerance(monkeypatch):
    """The CWRU 6205 under 300 N radial from its 30-N seed, 75-N steps, the 'auto' budget:
    with 30 N axial, Newton cannot solve the balance to 1e-8 between ~131 and ~200 N radial
    (it stalls at 1e-7-1e-6: near-singular), which earlier sessions read as a fold. Solving
    the path's points to PATH_TOLERANCE and only the end to 1e-8 passes it (MODEL.md §12a):
    the end is a balance to 1e-8 and its cage turns at the kinematic speed of a rolling
    deep-groove bearing, w_i (1 - D/d_m) / 2, within 0.2 %. With every point solved to 1e-8
    the same continuation stops."""
    from exudyn_bearing.solvers import continuation

    kw = dict(axial_force=0.0, radial_force=300.0, max_steps=40, max_step=75.0)
    state, balances, bearing = _counted_states(monkeypatch, **kw)
    assert state.converged, state.message
    assert state.residual <= 1e-8
    w_i = 1797.0 * np.pi / 30.0
    assert state.cage_speed == pytest.approx(0.5 * w_i * (1 - bearing.ball_diameter / bearing.pitch_diameter),
                                             rel=2e-3)
    assert balances <= 25
    monkeypatch.setattr(continuation, "PATH_TOLERANCE", 0.0)
    strict, _, _ = _counted_states(monkeypatch, **kw)
    assert not strict.converged and "30 N axial" in strict.message, strict.message


def test_a_budgeted_continuation_stops_where_its_end_stalls(monkeypatch):
    """Ending inside that near-singular stretch (30 N axial + 131.25 N radial, 7.5-N steps),
    the end stalls within 1e3 of the tolerance: the 'auto' budget stops at its second stall
    in a row with the reason, within one step of the end, instead of halving on. (Whether
    an end there stalls depends on Newton's start: the same end converges from some paths.)"""
    state, balances, _ = _counted_states(monkeypatch, axial_force=30.0, radial_force=131.25, max_steps=40,
                                         max_step=7.5)
    assert not state.converged and state.message.endswith("a near-singular balance"), state.message
    assert "Newton stalls at 30 N axial + 131.25 N radial" in state.message
    beyond = float(state.message.split("beyond 30 N axial + ")[1].split(" N radial")[0])
    assert 131.25 - 7.5 <= beyond < 131.25
    assert balances <= 30


class _Fold:
    """r(x) = x^2 - (1 - t): the branches x = +-sqrt(1 - t) meet at the fold t = 1."""

    scale = np.ones(1)

    def __init__(self, t):
        self.t = float(np.atleast_1d(t)[0])

    def residual(self, x):
        return np.array([x[0] ** 2 - (1.0 - self.t)])

    def jacobian(self, x):
        return np.array([[2.0 * x[0]]])

    def bounds(self):
        return np.array([-np.inf]), np.array([np.inf])


def test_the_continuation_stops_at_a_true_fold():
    """The loose tolerance of the path's points does not carry the continuation across a
    fold: x^2 = 1 - t from t = 0 to 2 stops within 1e-3 of t = 1 on its branch, with or
    without a budget, and a path that ends before the fold ends on the closed-form root
    sqrt(1 - t) to the end's tolerance."""
    from exudyn_bearing.solvers.continuation import continue_path as _continue

    text = lambda p: f"t = {p[0]:.6g}"  # noqa: E731
    for budget in (None, 400):
        y, worst, message, _, _ = _continue(_Fold, np.array([1.0]), [0.0], [2.0], 0.25, 1e-12, budget, text)
        assert message is not None and message.startswith("no quasi-dynamic balance found beyond t = ")
        stop = float(message.split("beyond t = ")[1].split(" ")[0])
        assert abs(stop - 1.0) < 1e-3 and 0.0 < y[0] < 0.05
    y, worst, message, _, _ = _continue(_Fold, np.array([1.0]), [0.0], [0.9], 0.25, 1e-12, None, text)
    assert message is None and worst <= 1e-12
    assert y[0] == pytest.approx(np.sqrt(0.1), rel=1e-10)

def test_cli_start_flag_takes_the_combined_start(tmp_path):
    """`simulate --start steady` under combined load starts from the quasi-dynamic state (the
    cage speed of the Python API's start) and records it in the result's inputs."""
    import json
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--axial", "400", "--radial", "100",
                          "--time", "0.002", "--start", "steady", "--json"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]
    data = json.loads(out.stdout)
    assert data["inputs"]["initial_state"] == "'steady'"
    state = combined_load_state(B, REFERENCE_LUBRICANT, axial_force=400.0, radial_force=100.0, rpm=1800.0,
                                ball_drag=REFERENCE_DRAG)
    assert data["cage_speed"] == pytest.approx(state.cage_speed, rel=2e-3)


def test_the_start_holds_the_kinematic_slip_with_the_cage_on_its_land():
    """2.8 kN + 0.85 kN at 1800 rpm (demos/hss_shaft.py's first bearing): the dynamic model
    keeps the start's cage where the start seated it on its land (within 2 um of its 0.2 mm)
    and its kinematic cage slip within 0.03 pp over 20 ms. Each of the start's two terms
    matters here: without the spin's orbital transport the slip fell 0.86 -> 0.21 % in 40 ms;
    with the cage centred, the cage travelled to its land in 7 ms and the slip swung by 0.4 pp
    (MODEL.md §12a)."""
    run = simulate(axial_force=2798.0, radial_force=853.0, rpm=1800.0, time=0.02,
                   settings=SolverSettings(output_step=5e-4, progress=False))
    res = run.results
    play = 0.2e-3
    assert play < res.cage_eccentricity[0] < play + 5e-6
    assert np.max(np.abs(res.cage_eccentricity - res.cage_eccentricity[0])) < 2e-6
    slip = res.kinematic_cage_slip_percent
    assert np.max(np.abs(slip - slip[0])) < 0.03, slip


def test_a_batch_of_balances_is_each_balance_alone():
    """The Jacobian evaluates its perturbed states in one batch of contacts (issue 52 item 3):
    each state's parts equal those of the state alone, bit for bit (drag, a seated cage's
    offset, a tilted pose)."""
    from contact.ballrace import ContactLaw
    from exudyn_bearing.solvers import quasidynamic
    steady = steady_state(B, REFERENCE_LUBRICANT, axial_force=800.0, rpm=1800.0, ball_drag=REFERENCE_DRAG)
    law, w_i, w_o, land = quasidynamic._balance_inputs(B, REFERENCE_LUBRICANT, ContactLaw(), None, 1800.0, 0.0)
    y = quasidynamic._steady_unknowns(B, steady)
    rng = np.random.default_rng(3)
    for kw in (dict(cage_offset=(20e-6, -5e-6, 0.0)), dict(pose=(2e-6, 1e-6, steady.inner_race_shift, 2e-5, 0.0))):
        balance = quasidynamic._Balance(B, REFERENCE_LUBRICANT, w_i, w_o, REFERENCE_DRAG, law, land, 800.0, 300.0, **kw)
        xs = (y / balance.scale)[None, :] * (1.0 + 1e-3 * rng.standard_normal((5, len(y))))
        for x, batched in zip(xs, balance.parts_of_many(xs)):
            for one, many in zip(balance.parts(x), batched):
                assert np.array_equal(one, many)
