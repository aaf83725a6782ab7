"""Exudyn runs of the reference bearing: momentum conservation, traction sign, kinematic
cage slip without drag (MODEL.md §6, §7; acceptance items).

Each run is a few ms of simulated time (wall times measured on a 2-core machine are given
per test).
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

exu = pytest.importorskip("exudyn")

from contact.ballrace import ContactLaw  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING, REFERENCE_LUBRICANT, races, solve_load_distribution  # noqa: E402
from exudyn_bearing.model.builder import CreateAngularContactBearing  # noqa: E402
from exudyn_bearing.simulation.runner import SolverSettings, run_solver  # noqa: E402
from tests.helpers import jones_harris  # noqa: E402

BRG = REFERENCE_BEARING


def _new_system():
    sc = exu.SystemContainer()
    return sc, sc.AddSystem()


def _inertias(mbs, handle):
    """Mass and body-frame inertia tensor of every body of the bearing, in node-slot order."""
    by_node = {}
    for body in [*handle.ballBodies, handle.cageBody, handle.innerRaceBody, handle.outerRaceBody]:
        if body is None:
            continue
        obj = mbs.GetObject(body)
        assert np.allclose(obj["centerOfMass"], 0.0)  # node = centre of mass
        j = obj["inertia"]  # [Jxx, Jyy, Jzz, Jyz, Jxz, Jxy]
        by_node[int(obj["nodeNumber"])] = (obj["mass"], np.array([[j[0], j[5], j[4]], [j[5], j[1], j[3]],
                                                             [j[4], j[3], j[2]]]))
    return [by_node[int(n)] for n in handle.nodeNumbers]


def _momenta(q, q_t, inertias, point):
    """Total linear momentum, angular momentum about ``point`` (incl. the spin parts
    A I A^T omega = A I omega_local) and the sum of |m v| (scale), from absolute node
    coordinates (RotVecLG: velocity coordinates are global v and LOCAL omega)."""
    q, q_t = q.reshape(-1, 6), q_t.reshape(-1, 6)
    p = np.zeros(3)
    l = np.zeros(3)
    scale = 0.0
    for k, (m, j) in enumerate(inertias):
        a = Rotation.from_rotvec(q[k, 3:]).as_matrix()
        p += m * q_t[k, :3]
        scale += m * np.linalg.norm(q_t[k, :3])
        l += np.cross(q[k, :3] - point, m * q_t[k, :3]) + a @ j @ q_t[k, 3:]
    return p, l, scale


def _conservation_run(race_mass=None, race_inertia=(None, None), end=5e-3):
    """Free inner race at 1800 rpm, free outer race at rest, rigid cage, no drag, no applied
    force, inner race displaced 10 µm axially (balls in quasi-static balance), every ball's
    angular velocity perturbed by ~50 rad/s per component (rolling slip ~0.7 m/s mean,
    up to 1.5 m/s: the Crook traction is in its thermal range)."""
    _, mbs = _new_system()
    law = ContactLaw(quadrature_order=8)
    handle = CreateAngularContactBearing(
        mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Free(1800.0, mass=race_mass, inertia=race_inertia[0]),
        outerRace=races.Free(0.0, mass=race_mass, inertia=race_inertia[1]), ballDrag=None,
        innerRaceDisplacement=(0.0, 0.0, 10e-6), contactLaw=law, show=False)
    rng = np.random.default_rng(0)
    for node in handle.ballNodes:
        v = np.asarray(mbs.GetNodeParameter(node, "initialVelocities"), dtype=float)
        v[3:] += 50.0 * rng.standard_normal(3)  # local = global omega: balls start unrotated
        mbs.SetNodeParameter(node, "initialVelocities", v.tolist())
    mbs.Assemble()
    run_solver(mbs, [handle], end, SolverSettings(solver="rk44", step=1e-5, output_step=2.5e-4))
    return mbs, handle


def _check_conservation(mbs, handle):
    t, q, q_t = handle.States(mbs)
    inertias = _inertias(mbs, handle)
    point = np.array([0.05, -0.03, 0.02])  # any fixed point
    p, l, scale = zip(*(_momenta(q[k], q_t[k], inertias, point) for k in range(len(t))))
    p0, l0, scale_p = p[0], l[0], max(scale)
    err_p = max(np.linalg.norm(pk - p0) for pk in p)
    err_l = max(np.linalg.norm(lk - l0) for lk in l)
    assert t[-1] == pytest.approx(5e-3)
    assert err_p <= 1e-9 * scale_p, (err_p, scale_p)
    assert err_l <= 1e-6 * np.linalg.norm(l0), (err_l, np.linalg.norm(l0))
    return t, q, q_t, inertias, point, err_p / scale_p, err_l / np.linalg.norm(l0)


def test_momentum_conserved_with_sliding_contacts():
    """Acceptance item: drag off, no applied force, races free -> total linear momentum
    (balls, cage, races) constant to 1e-9 of sum |m v| and total angular momentum about a
    fixed point constant to 1e-6 relative over 5 ms.

    Solver: explicit Lie-group RK44 at a fixed step of 1e-5 s (500 steps), traction
    quadrature order 8. The races carry a translational mass of 1e6 kg (rotational inertia
    of the default rings): a 10 µm displacement preload is not in balance for free races
    (the inner contacts push the races apart with ~3 kN), and with the default 1.7/2.6 kg
    rings the races separate within 0.1 ms and the bearing rattles (see the next test).
    Observed: linear 8e-16, angular 7e-12 relative; mean slip 0.68 -> 0.009 m/s. Wall ≈ 12–16 s.
    """
    mbs, handle = _conservation_run(race_mass=1e6, race_inertia=((0.00364, 0.00687), (0.01135, 0.02210)))
    t, q, q_t, inertias, point, rel_p, rel_l = _check_conservation(mbs, handle)
    res = handle.Results(mbs)
    # traction was active: large initial sliding at every contact that decays (MODEL.md §6)
    for race in (res.inner, res.outer):
        assert np.all(race["load"] > 200.0)  # stayed loaded throughout
        assert np.mean(race["slip"][0]) > 0.5 and np.max(race["slip"][0]) > 1.0
        assert np.mean(race["slip"][-1]) < 0.1 * np.mean(race["slip"][0])
        assert np.max(np.abs(race["traction_rolling"][0])) > 5.0
    # momentum really was exchanged between the bodies (the check has power): the inner
    # race's angular momentum and the races' linear momenta changed by far more than the
    # tolerances
    inner = handle.connector.layout["inner"]
    m_in, j_in = inertias[inner]
    qq0, qq1 = q[0].reshape(-1, 6), q[-1].reshape(-1, 6)
    vv0, vv1 = q_t[0].reshape(-1, 6), q_t[-1].reshape(-1, 6)
    l_in = [Rotation.from_rotvec(qq[inner, 3:]).as_matrix() @ j_in @ vv[inner, 3:] for qq, vv in ((qq0, vv0), (qq1, vv1))]
    l0 = _momenta(q[0], q_t[0], inertias, point)[1]
    assert np.linalg.norm(l_in[1] - l_in[0]) > 1e2 * 1e-6 * np.linalg.norm(l0)
    assert np.linalg.norm(m_in * (vv1[inner, :3] - vv0[inner, :3])) > 1.0  # N s, ~3 kN for 5 ms


def test_momentum_conserved_free_default_races():
    """The same with the default (light, 1.7/2.6 kg) free races, as the acceptance item
    states it: the preloaded races fly apart within ~0.1 ms and the bearing rattles, with
    contacts opening and closing (at commit 2f38baf this could raise in the force user
    function once some contacts of a race were loaded and others not). RK44, step 1e-5 s,
    5 ms. Observed: linear 3e-16, angular 8e-11 relative. Wall ≈ 6–11 s."""
    mbs, handle = _conservation_run()
    _check_conservation(mbs, handle)
    res = handle.Results(mbs)
    assert np.any(res.inner["load"] == 0.0)  # contacts did open


def test_combined_load_at_rest_keeps_quasi_static_loads():
    """Partly unloaded bearing in a run: the paper's combined load (F_a 2.2 kN, F_r 2 kN) at
    rest, Driven(0 rpm), drag off; the builder starts from the quasi-static solution with
    9 balls loaded (max ≈ 658 N, MODEL.md §9) and 7 free. The dynamic model must hold that
    state (at commit 2f38baf the first force evaluation raised). Generalized-alpha, step
    1e-4 s, 2 ms. Wall < 2 s."""
    _, mbs = _new_system()
    handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(0.0),
                                         axialForce=2200.0, radialForce=2000.0, ballDrag=None,
                                         contactLaw=ContactLaw(quadrature_order=8), show=False)
    mbs.Assemble()
    qs = handle.initialLoads
    # the start is the Jones–Harris equilibrium (solved independently in test_quasistatic)
    jh_inner, jh_outer = jones_harris(2200.0, 2000.0)[:2]
    assert np.count_nonzero(jh_inner > 0) == 9 and np.count_nonzero(qs.inner_load > 0) == 9
    np.testing.assert_allclose(qs.inner_load, jh_inner, rtol=0, atol=1e-7 * jh_inner.max())
    np.testing.assert_allclose(qs.outer_load, jh_outer, rtol=0, atol=1e-7 * jh_inner.max())
    assert abs(jh_inner.max() - 658.0) < 1.0  # MODEL.md §9: "≈658 N" (658.6 N)
    run_solver(mbs, [handle], 2e-3, SolverSettings(solver="generalized-alpha", step=1e-4, output_step=5e-4))
    t, q, q_t = handle.States(mbs)
    state = handle.connector.evaluate(t[-1], q[-1], q_t[-1], details=True)
    for forces, expected in ((state.inner_forces, qs.inner_load), (state.outer_forces, qs.outer_load)):
        np.testing.assert_array_equal(forces.normal_load > 0, expected > 0)
        np.testing.assert_allclose(forces.normal_load, expected, rtol=1e-2, atol=1.0)


def test_combined_load_at_speed_matches_quasi_static_peak_without_traction():
    """Combined load at 1800 rpm (F_a 2.2 kN, F_r 2 kN) with normal forces only (no
    traction, no drag, no cage): each ball keeps the orbital speed it starts with (its own
    pure-rolling speed, 82–96 rad/s around the bearing), so the balls drift apart and the
    load zone is crossed by ever other balls. Over the first 2 ms, before they have drifted,
    the inner-contact loads must match an independent quasi-static solve with each ball's
    own orbital speed as read from the run (centrifugal force m r_c w², MODEL.md §4) within
    3 % at the peak and the unloaded side must stay lightly loaded. (Against one mean cage
    speed the peak would differ: the fast balls start outside the load zone.) No cage:
    without traction only the pockets would tie the balls' different rolling speeds
    together, and their unbalanced resultant throws the cage about (unguided 6.7 mm off
    centre after 20 ms, land-guided hammering its land with up to 725 N), which is not
    what this test is about. Generalized-alpha 1e-4 s, 4 ms, wall ~1 s."""
    from exudyn_bearing import CageModel

    _, mbs = _new_system()
    handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(1800.0),
                                         axialForce=2200.0, radialForce=2000.0, ballDrag=None,
                                         contactLaw=ContactLaw(traction="none"), cage=CageModel("none"), show=False)
    mbs.Assemble()
    run_solver(mbs, [handle], 0.004, SolverSettings(output_step=2.5e-4))
    res = handle.Results(mbs)
    early = res.time <= 0.002
    speeds = res.ball_orbital_speed[0]
    qs = solve_load_distribution(BRG, axial_force=2200.0, radial_force=2000.0, rpm=1800.0, cage_speed=speeds)
    peak = float(res.inner["load"][early].max())
    assert np.ptp(speeds) > 0.1 * speeds.mean()  # the balls do orbit at different speeds
    assert peak == pytest.approx(qs.inner_load.max(), rel=0.03), (peak, qs.inner_load.max())
    # the unloaded side stays lightly loaded, as in the quasi-static solution
    assert res.inner["load"][early].min() == pytest.approx(qs.inner_load.min(), abs=0.3 * qs.inner_load.min() + 5.0)


def test_traction_pulls_sliding_balls_towards_rolling():
    """MODEL.md §6 sign convention, dynamically: drag off, Driven(1800 rpm) inner race with
    1.3 kN axial load, ball 0 started spinning 8 % too fast and ball 8 8 % too slow
    (rolling slip ~0.5 m/s at both contacts). The traction pulls both towards rolling:
    their rolling slip relative to an unperturbed ball decays (never grows) and their
    spin speed approaches the unperturbed one. Generalized-alpha, step 5e-5 s, 3 ms.
    Observed: slip 0.51 m/s -> <0.015 m/s. Wall ≈ 3–6 s."""
    _, mbs = _new_system()
    # the paper's law: the sign convention is what is tested, and its unbounded traction
    # brings the balls back within the 3 ms (the capped default needs longer)
    handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(1800.0),
                                         axialForce=1300.0, ballDrag=None, contactLaw=ContactLaw(traction="crook"),
                                         initialState="rolling", show=False)
    perturbed = {0: 1.08, 8: 0.92}
    reference = [4, 12]  # unperturbed balls (pure axial load: all balls are equivalent)
    for ball, factor in perturbed.items():
        node = handle.ballNodes[ball]
        v = np.asarray(mbs.GetNodeParameter(node, "initialVelocities"), dtype=float)
        v[3:] *= factor
        mbs.SetNodeParameter(node, "initialVelocities", v.tolist())
    mbs.Assemble()
    run_solver(mbs, [handle], 3e-3, SolverSettings(solver="generalized-alpha", step=5e-5, output_step=1e-4))
    res = handle.Results(mbs)
    spin = np.linalg.norm(res.ball_omega_orbiting, axis=2)
    for ball, factor in perturbed.items():
        for name, race in (("inner", res.inner), ("outer", res.outer)):
            u = race["slip_rolling"][:, ball] - np.mean(race["slip_rolling"][:, reference], axis=1)
            # clearly sliding at the start, and the traction on the ball points along the
            # race-minus-ball slip (pulls the ball towards the race's surface velocity)
            assert abs(u[0]) > 0.4, (ball, name, u[0])
            assert race["traction_rolling"][0, ball] * race["slip_rolling"][0, ball] > 0, (ball, name)
            # pulled towards rolling: the slip decays and never grows beyond its start
            assert np.all(np.abs(u) <= abs(u[0]) * (1 + 1e-3)), (ball, name, u)
            early = np.abs(u[:11])  # first 1 ms: monotone decay
            assert np.all(np.diff(early) < 0), (ball, name, early)
            assert abs(u[-1]) < 0.1 * abs(u[0]), (ball, name, u[-1], u[0])
        d_spin = spin[:, ball] - np.mean(spin[:, reference], axis=1)
        assert np.sign(d_spin[0]) == np.sign(factor - 1)
        assert abs(d_spin[-1]) < 0.2 * abs(d_spin[0]), (ball, d_spin[0], d_spin[-1])
        assert np.all(np.abs(d_spin) <= abs(d_spin[0]) * (1 + 1e-3))


@pytest.mark.parametrize("axial", [1300.0, 3000.0])
def test_kinematic_cage_slip_zero_without_drag(axial):
    """MODEL.md §7: without ball drag the kinematic cage slip stays within 0.05 % of zero
    (mean over the last third of a 12 ms run from the builder's quasi-static start).
    Generalized-alpha, step 1e-4 s, block Jacobian, traction quadrature order 8.
    Observed: 1300 N ≈ +0.028 %, 3000 N ≈ -0.0016 %. Wall ≈ 6–11 s / 15–22 s.

    The balls start at outer-race control (``initialControl='outer'``): without drag the
    axes drift towards it (from inner-race control at 1300 N: 52 deg -> 41 deg in 60 ms
    while the slip decays 0.12 % -> 0.055 %), so this start is near the steady state a
    short run can represent.

    The paper's law (pure Crook): with the default limiting shear (Lambda = 0.047 < the
    criterion's 0.06) 1300 N no longer satisfies Jones' criterion and settles at ~0.2 %;
    tests/test_results_guard.py checks the default law without drag at 3 kN.

    Not included: light loads. The balls' axes pivot towards the bearing axis in the first
    tens of ms and the kinematic slip grows (200 N: ≈ 10 % after 20 ms; 400 N: ≈ 6 %;
    700 N: ≈ 2.6 %; 1000 N: ≈ 0.5 %, all without drag, same with RK44 at 1e-5 s) and
    takes far longer than a test run to decay.
    """
    _, mbs = _new_system()
    handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(1800.0),
                                         axialForce=axial, ballDrag=None, initialControl="outer", initialState="rolling",
                                         contactLaw=ContactLaw(traction="crook", quadrature_order=8), show=False)
    mbs.Assemble()
    run_solver(mbs, [handle], 0.012, SolverSettings(solver="generalized-alpha", step=1e-4, output_step=5e-4))
    res = handle.Results(mbs)
    last = res.last(1 / 3)
    assert last.sum() >= 8
    slip = float(np.mean(res.kinematic_cage_slip_percent[last]))
    assert abs(slip) < 0.05, slip
    # the traction can hold the ball axes against the gyroscopic moment here (Jones)
    assert _gyroscopic_demand(res, BRG) < 1.0
    # the paper's P19 slip with the nominal angle is NOT zero here (angles differ from 40°):
    # the kinematic measure is what removes that
    assert abs(float(np.mean(res.cage_slip_percent[last]))) > 0.3


def _gyroscopic_demand(res, bearing, k=0, friction=0.06):
    """Jones' criterion for gyroscopic pivoting (Harris & Kotzalas, ch. 'ball spin'): the
    moment J w_c |w_b| sin(beta) that keeps a ball's spin axis fixed in the orbiting frame
    must come from traction at its two contacts, at most mu Q D. Returns the ratio
    (> 1: the axis cannot be held; mu = 0.06, a typical EHD traction coefficient), at
    recorded step k, worst ball."""
    inertia = 0.4 * bearing.ball_mass * bearing.ball_radius ** 2
    w_b = np.linalg.norm(res.ball_omega_orbiting[k], axis=1)
    demand = inertia * np.abs(res.cage_speed[k]) * w_b * np.sin(res.attitude_xz[k])
    load = np.minimum(res.inner["load"][k], res.outer["load"][k])
    return float(np.max(demand / (friction * load * bearing.ball_diameter)))


def test_light_load_without_drag_pivots_gyroscopically():
    """Why the no-drag kinematic slip is near zero only at heavier loads: at F_a = 200 N the
    traction cannot supply the gyroscopic moment (Jones' criterion, ratio > 1), so the
    ball axes pivot towards the bearing axis (beta_XZ falls) and the spin this causes at
    both contacts must be paid for by rolling slip, even without drag. At 3 kN the ratio is
    below 1 and the axes stay (see test_kinematic_cage_slip_zero_without_drag).
    Generalized-alpha 1e-4 s, 20 ms; observed: ratio 2.5, beta_XZ 14.1 -> 1.4 deg, kinematic
    slip 10.4 % (3 kN: ratio 0.23, slip -0.002 %)."""
    _, mbs = _new_system()
    handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(1800.0),
                                         axialForce=200.0, ballDrag=None, initialState="rolling", show=False)
    mbs.Assemble()
    run_solver(mbs, [handle], 0.02, SolverSettings(output_step=5e-4))
    res = handle.Results(mbs)
    assert _gyroscopic_demand(res, BRG) > 1.0
    beta = np.degrees(res.attitude_xz.mean(axis=1))
    assert beta[-1] < beta[0] - 5.0, (beta[0], beta[-1])
    assert float(np.mean(res.kinematic_cage_slip_percent[res.last(1 / 3)])) > 1.0


def test_diverging_run_stops_with_a_message():
    """RK44 far above its stability limit (EXUDYN_NOTES: NaN at 5e-5 s) must stop with a
    BearingSimulationError that says what diverged and what to change, never return NaN."""
    from exudyn_bearing.errors import BearingSimulationError

    _, mbs = _new_system()
    handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(1800.0),
                                         axialForce=1300.0, show=False)
    mbs.Assemble()
    with pytest.raises(BearingSimulationError, match="generalized-alpha|smaller step"):
        run_solver(mbs, [handle], 0.02, SolverSettings(solver="rk44", step=4e-4))


def test_guided_cage_stays_within_its_land_play():
    """The cage kicked radially at v = 0.05 m/s (F_a 700 N, 1800 rpm, 20 ms, generalized-alpha
    1e-4 s). Land-guided (default, outer land, radial play g = 0.2 mm, k = 1e7 N/m): its
    eccentricity never exceeds g + v sqrt(m/k) (all the kick's kinetic energy stored in the
    land spring: ~9.9 µm) and the land carries it. Unguided (guidance='balls'): the pockets
    alone let it drift past the play (observed 0.32 mm) — the free radial cage mode that
    grows into a runaway whirl in medium-load runs beyond 0.5 s (README)."""
    from exudyn_bearing import CageModel

    v = 0.05
    e_max = {}
    for guidance in ("outer", "balls"):
        _, mbs = _new_system()
        cage = CageModel(guidance=guidance)
        handle = CreateAngularContactBearing(mbs, BRG, REFERENCE_LUBRICANT, innerRace=races.Driven(1800.0),
                                             axialForce=700.0, cage=cage, show=False)
        w0 = list(mbs.GetNodeParameter(handle.cageNode, "initialVelocities"))[3:]
        mbs.SetNodeParameter(handle.cageNode, "initialVelocities", [v, 0.0, 0.0] + w0)
        mbs.Assemble()
        run_solver(mbs, [handle], 0.02, SolverSettings(output_step=2e-4))
        res = handle.Results(mbs)
        e_max[guidance] = float(res.cage_eccentricity.max())
        if guidance == "outer":
            mass = cage.mass_for(BRG)
            bound = 0.5 * cage.guide_clearance + v * np.sqrt(mass / cage.guide_stiffness)
            assert 0.5 * cage.guide_clearance < e_max[guidance] <= bound, (e_max, bound)
            assert res.cage_land_force.max() > 10.0
        else:
            assert np.all(res.cage_land_force == 0.0)
    assert e_max["balls"] > 0.5 * CageModel().guide_clearance + 50e-6, e_max
