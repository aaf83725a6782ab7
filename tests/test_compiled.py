"""The compiled contact kernels (contact/kernels/, exudyn_bearing/model/compiled.py) against
the numpy functions of contact/ on the same states.

The numpy path is the reference: the traction is checked against the ACCURATE quadrature
(an independent rule with its own convergence tests), the whole connector against the
numpy path of the same connector, which tests/test_connector.py checks against physics
assembled by hand.
"""
from __future__ import annotations

import threading

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
pytest.importorskip("numba")

from contact import kernels as compiled  # noqa: E402
from contact.kernels import float32  # noqa: E402
from contact.ballrace import ContactLaw  # noqa: E402
from contact.traction import crook_traction  # noqa: E402
from exudyn_bearing import REFERENCE_LUBRICANT as LUB  # noqa: E402
from exudyn_bearing import races  # noqa: E402
from exudyn_bearing.cage import CageModel  # noqa: E402
from exudyn_bearing.jacobian import block_jacobian, jacobian_columns  # noqa: E402
from tests.helpers import SCENES, _assert_jacobian_matches_numpy, _both_paths, _contacts, _scale, _scene  # noqa: E402,F401


def test_crook_kernel_matches_the_accurate_rule():
    ux, uy, om, a, b, pm, h = _contacts(300)
    got = compiled.crook_fast(ux, uy, om, a, b, pm, h, LUB)
    ref = crook_traction(ux, uy, om, a, b, pm, h, LUB, fast=False, order=24)
    scale = _scale(ref.fx, ref.fy, ref.mz, np.maximum(a, b))
    for name, g, r, s in (("fx", got[0], ref.fx, scale), ("fy", got[1], ref.fy, scale),
                          ("mz", got[2] / np.maximum(a, b), ref.mz / np.maximum(a, b), scale),
                          ("heat", got[3], ref.heat, np.abs(ref.heat))):
        err = np.abs(g - r) / s
        # the fast rule's documented worst error on reference states is 4.6e-4
        assert np.max(err) < 2e-3, (name, np.max(err), int(np.argmax(err)))
    assert np.median(np.abs(got[0] - ref.fx) / scale) < 2e-4


def test_crook_kernel_is_the_numpy_fast_rule():
    """Same nodes and weights as the numpy fast rule (float32 there, float32 rays with
    float64 sums here): agreement far below the rule's own error."""
    ux, uy, om, a, b, pm, h = _contacts(200, seed=1)
    got = compiled.crook_fast(ux, uy, om, a, b, pm, h, LUB)
    ref = crook_traction(ux, uy, om, a, b, pm, h, LUB, fast=True)
    scale = _scale(ref.fx, ref.fy, ref.mz, np.maximum(a, b))
    assert np.max(np.abs(got[0] - ref.fx) / scale) < 3e-4
    assert np.max(np.abs(got[2] - ref.mz) / (scale * np.maximum(a, b))) < 3e-4


def test_float32_exp_and_log_are_float32_accurate():
    """The quadrature's vectorizable exp and log against numpy in float64: within two
    float32 ulps over the ranges they serve (e^x for 0 <= x <= 88, inf beyond; ln x for
    x >= 1 up to float32's largest numbers)."""
    x = np.concatenate([np.linspace(0.0, 88.0, 4001), [1e-7, 0.5 * np.log(2.0)]]).astype(np.float32)
    got = np.array([float32.exp32(v) for v in x], dtype=np.float64)
    ref = np.exp(x.astype(np.float64))
    assert np.max(np.abs(got - ref) / ref) < 2 * 2.0 ** -23
    assert float32.exp32(np.float32(89.0)) == np.inf
    y = np.concatenate([1.0 + np.logspace(-7, 0, 2000), np.logspace(0, 38, 2000), [1.0, np.sqrt(2.0)]])
    y = y.astype(np.float32)
    got = np.array([float32.log32(v) for v in y], dtype=np.float64)
    ref = np.log(y.astype(np.float64))
    assert np.max(np.abs(got - ref) / np.maximum(ref, 2.0 ** -23)) < 2 * 2.0 ** -23


def test_crook_kernel_redoes_float32_overflow_in_float64():
    """c_etaP p_max = 90: e^(lambda sigma) overflows float32 near the peak; those rays are
    redone in float64 and the result still matches the accurate rule."""
    ux, uy, om, a, b, _, h = _contacts(40, seed=2)
    pm = np.full(40, 90.0 / LUB.pressure_viscosity)
    got = compiled.crook_fast(ux, uy, om, a, b, pm, h, LUB)
    assert np.all(np.isfinite(got))
    ref = crook_traction(ux, uy, om, a, b, pm, h, LUB, fast=False)
    scale = _scale(ref.fx, ref.fy, ref.mz, np.maximum(a, b))
    assert np.max(np.abs(got[0] - ref.fx) / scale) < 5e-3


def test_unloaded_contact_has_no_traction():
    got = compiled.crook_fast([0.5], [0.1], [30.0], [0.0], [0.0], [0.0], [1e-7], LUB)
    assert np.all(got == 0.0)


@pytest.mark.parametrize("name", SCENES)
def test_connector_compiled_paths_match_numpy_path(name):
    kw = dict(SCENES[name])
    _sc, con, q, qt = _scene(**kw)
    assert con._compiled is not None
    single, fast, ref = _both_paths(con, q, qt)
    assert np.max(np.abs(ref[:, :3])) > 10.0  # loaded contacts
    for got in (single, fast):
        for part in (slice(0, 3), slice(3, 6)):  # forces (N) and torques (N m) on their own scales
            err = np.max(np.abs(got[:, part] - ref[:, part]))
            assert err < 1e-6 * np.max(np.abs(ref[:, part])), (part, err)


def test_compiled_paths_match_numpy_path_with_the_cage_on_its_land():
    """The cage 0.3 mm off-centre (beyond the 0.2 mm play) and 1 mm axially: the land
    force and its reaction on a free guiding race, whose torque about the race node needs
    the lever between the two centres."""
    _sc, con, q, qt = _scene(axialForce=600.0, outerRace=races.Free())
    s = con.layout["cage"]
    q = q.copy()
    q[6 * s:6 * s + 3] += [0.3e-3, 0.0, 1e-3]
    single, fast, ref = _both_paths(con, q, qt)
    outer = con.layout["outer"]
    assert np.max(np.abs(ref[outer, 3:])) > 0.1  # the land's moment on the free race
    for got in (single, fast):
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-6 * np.max(np.abs(ref)))


def test_single_state_path_hands_bad_states_to_the_checked_path():
    """A non-finite state and a ball pushed out of its groove: NaN forces and the reason
    recorded, as from the numpy path."""
    _sc, con, q, qt = _scene(axialForce=1300.0)
    bad = q - con.reference
    bad[7] = np.nan
    assert np.all(np.isnan(con.residual_forces(0.0, bad, qt)))
    assert "non-finite position of ball 1" in con.first_non_finite
    con.first_non_finite = None
    deep = q - con.reference
    deep[:2] += 0.05 * con.bearing.ball_diameter * q[:2] / np.hypot(*q[:2])  # ball 0 radially out by 5 % of D
    assert np.all(np.isnan(con.residual_forces(0.0, deep, qt)))
    assert "pushed ball 0 out of its groove at the outer race" in con.first_non_finite


def test_spin_moment_term_matches_numpy_path():
    """The spin moment M_z n alone (forces with it minus forces without it) is ~1e-4 of the
    ball torques: compared on its own scale. Both scenes start from the same (pure-rolling)
    state; a steady start would differ with the law."""
    parts = []
    for spin in (True, False):
        _sc, con, q, qt = _scene(law=ContactLaw(spin_moment=spin), axialForce=1300.0, initialState="rolling")
        parts.append(_both_paths(con, q, qt)[1:])
    d_fast, d_ref = parts[0][0] - parts[1][0], parts[0][1] - parts[1][1]
    assert np.max(np.abs(d_ref[:, 3:])) > 1e-6
    assert np.max(np.abs(d_fast - d_ref)) < 1e-4 * np.max(np.abs(d_ref[:, 3:]))


@pytest.mark.parametrize("name", ["axial, rigid cage, drag", "spring chain, no drag", "pocket play, free outer race",
                                  "speed ramp, inner-guided cage, turning outer race", "pocket friction",
                                  "race surfaces, combined load", "ball defects, combined load"])
def test_connector_jacobian_compiled_matches_numpy(name):
    """The compiled Jacobian (compiled states, kernels and assembly) equals the numpy one up
    to finite-difference noise of the float32 rays: ball blocks, coupled balls (spring
    chain: one column group per ball), a free outer race (all its columns) and a driven
    race (its rotation columns too). The races' translation columns, which the compiled path
    takes from the balls' (moving the balls by +eps where the numpy path moves the race by
    +eps, i.e. the balls by -eps), differ by twice the forward difference's truncation,
    eps/(2 delta) of the contact stiffness (2.2e-4 at 1 nm on the reference bearing's light
    contacts, ~1e-5 at 0.1 nm): 1e-3 for those columns (their own test holds them closer)."""
    _sc, con, q, qt = _scene(**SCENES[name])
    fast = con.jacobian(0.01, q, qt, 1.0, 1e-4)
    kernel, con._compiled = con._compiled, None
    try:
        ref = con.jacobian(0.01, q, qt, 1.0, 1e-4)
    finally:
        con._compiled = kernel
    _assert_jacobian_matches_numpy(fast, ref, con)


@pytest.mark.parametrize("name", ["axial, rigid cage, drag", "combined load", "spring chain, no drag",
                                  "pocket friction"])
def test_ball_rotation_columns_by_the_chain_rule_match_perturbed_orientations(name):
    """The compiled Jacobian takes the balls' rotation columns from their angular velocity
    columns (dF/d theta_k = sum_j (e_k x w_l)_j dF/dw_l,j, and -(e_k x A^T M) on the ball's
    own moment rows); the numpy path perturbs each ball's orientation. Compared with f_qt = 0
    (rotation columns alone) at steps above the float32 rays' noise (1e-5 rad, 1e-3 rad/s),
    the balls' force rows and moment rows each on their own scale: within 2 % (measured
    ≤ 0.6 %; a flipped moment term misses the moment rows by 18 % on the axial scene and 93 %
    with pocket friction)."""
    _sc, con, q, qt = _scene(**SCENES[name])
    steps = dict(eps_rotation=1e-5, eps_velocity=1e-3, eps_angular=1e-3)
    fast = block_jacobian(con, 0.01, q, qt, 1.0, 0.0, **steps)
    kernel, con._compiled = con._compiled, None
    try:
        ref = block_jacobian(con, 0.01, q, qt, 1.0, 0.0, **steps)
    finally:
        con._compiled = kernel
    balls = np.asarray(con.layout["balls"])
    cols = (6 * balls[:, None] + np.arange(3, 6)).ravel()
    assert np.max(np.abs(ref[:, cols])) > 1.0
    assert np.max(np.abs(fast[:, cols] - ref[:, cols])) < 2e-2 * np.max(np.abs(ref[:, cols]))
    for rows in (cols - 3, cols):  # the balls' force rows, then their moment rows
        scale = np.max(np.abs(ref[np.ix_(rows, cols)]))
        assert scale > 0.1
        assert np.max(np.abs(fast[np.ix_(rows, cols)] - ref[np.ix_(rows, cols)])) < 2e-2 * scale


SCENES_RACES = SCENES | {
    # the inner race (a node) guides the cage and keeps its perturbed columns, the free outer race's are chained
    "inner-guided cage, free outer race": dict(axialForce=600.0, radialForce=200.0, cage=CageModel(guidance="inner"),
                                               outerRace=races.Free()),
}


@pytest.mark.parametrize("name", ["combined load", "pocket play, free outer race",
                                  "land friction, outer-guided cage", "inner-guided cage, free outer race"])
@pytest.mark.parametrize("which", ["q", "v"])
def test_race_translation_columns_from_the_balls_match_perturbed_races(name, which):
    """The compiled Jacobian takes a race's translation columns from the balls' (a contact
    depends on ball and race positions and velocities through their differences only); the
    numpy path moves the race. Compared per kind (f_q = 1, f_qt = 0 or the reverse) at steps
    where the two forward differences' truncation (they move the contact in opposite
    directions) and the float32 rays' noise are both small (0.1 nm, 1e-5 m/s: 2e-5 and 2e-4
    of the columns' largest entry; 1e-3 m/s gives 2 %): within 2e-3, for a driven inner race
    (moment rows held), a free outer race, and with the cage guided by the other race or by
    this one (then perturbed as before)."""
    _sc, con, q, qt = _scene(**SCENES_RACES[name])
    assert jacobian_columns(con)["chain"].size
    steps = dict(eps_position=1e-10, eps_rotation=1e-7, eps_velocity=1e-5, eps_angular=1e-5)
    f_q, f_qt = (1.0, 0.0) if which == "q" else (0.0, 1.0)
    fast = block_jacobian(con, 0.01, q, qt, f_q, f_qt, **steps)
    kernel, con._compiled = con._compiled, None
    try:
        ref = block_jacobian(con, 0.01, q, qt, f_q, f_qt, **steps)
    finally:
        con._compiled = kernel
    races = [con.layout[k] for k in ("inner", "outer") if con.layout[k] is not None]
    cols = np.concatenate([6 * s + np.arange(3) for s in races])
    balls = np.asarray(con.layout["balls"])
    # each kind of row on its own scale (the balls' moment rows are ~1e-4 of the force rows,
    # and their differences carry the rays' float32 noise: 3 %; the next test holds their
    # exact part)
    for rows, tol in ((6 * balls[:, None] + np.arange(3), 2e-3), (6 * balls[:, None] + np.arange(3, 6), 3e-2),
                      (np.concatenate([6 * s + np.arange(6) for s in races]), 2e-3)):
        rows = rows.ravel()
        scale = np.max(np.abs(ref[np.ix_(rows, cols)]))
        assert scale > 1e-6
        assert np.max(np.abs(fast[np.ix_(rows, cols)] - ref[np.ix_(rows, cols)])) < tol * scale


@pytest.mark.parametrize("gamma, combined", [(1.875e4, True), (150.0, False)], ids=["1e-4 s", "1e-2 s"])
@pytest.mark.parametrize("name", ["axial, rigid cage, drag", "combined load", "pocket play, free outer race",
                                  "land friction, outer-guided cage", "ball defects, combined load"])
def test_combined_columns_match_the_separate_differences(name, gamma, combined):
    """At a step's ratio f_qt/f_q = γ' (1.875e4 1/s: generalized-alpha at 1e-4 s, ρ∞ = 0.5) the
    compiled Jacobian takes a coordinate whose position and velocity columns both remain as
    one column whose states move the coordinate by c f_q and its velocity by c f_qt (MODEL.md
    §10); the numpy path differences them apart, the race translations by moving the races.
    Equal to the finite-difference noise of :func:`_assert_jacobian_matches_numpy` (the
    position step is ~half the numpy path's there); with the balls' pits the ball rotations
    are combined too. A columns' weight or a combined column's position step taken twice or
    left out misses by the whole position part (the contact stiffness, ~1e8 N/m against ~1e6
    N s/m × γ'). At γ' = 150 1/s (a 1e-2 s step) the position would move 67 nm, more than ten
    of its own steps: the columns stay apart, and the velocity keeps its step."""
    from exudyn_bearing.jacobian.kernels import COMBINED

    _sc, con, q, qt = _scene(**SCENES_RACES[name])
    f_q, f_qt = 2.0, 2.0 * gamma  # f_q other than 1: a weight taken as f_q would show
    con._jac_spec = None
    fast = con.jacobian(0.01, q, qt, f_q, f_qt)
    assert list(con._jac_spec) == [combined]
    kinds = jacobian_columns(con, combined=True)["arrays"][2]
    assert np.count_nonzero(kinds == COMBINED) >= 3
    kernel, con._compiled = con._compiled, None
    try:
        ref = con.jacobian(0.01, q, qt, f_q, f_qt)
    finally:
        con._compiled = kernel
    _assert_jacobian_matches_numpy(fast, ref, con)


@pytest.mark.parametrize("f_qt", [0.0, 1.875e4])
def test_race_translation_columns_leave_frictionless_balls_without_moment(f_qt):
    """Without traction the contact forces pass through the ball centres: moving a race
    turns no ball. The compiled race columns recover each contact's moment from the race's
    reaction -A^T (l x F + M) with l = c - x_race, whose change holds e_k x F as well; left
    out, the balls' moment rows would carry |F| (~1e2 N) where they must vanish. From the
    position columns (f_qt = 0) and from the combined ones (f_qt = γ' at 1e-4 s), whose
    position part moves by c f_q."""
    _sc, con, q, qt = _scene(**SCENES["no traction"])
    jac = con.jacobian(0.01, q, qt, 1.0, f_qt)
    s = con.layout["inner"]
    assert s in jacobian_columns(con)["chain"]
    balls = np.asarray(con.layout["balls"])
    cols = 6 * s + np.arange(3)
    force_rows = (6 * balls[:, None] + np.arange(3)).ravel()
    moment_rows = force_rows + 3
    stiff = np.max(np.abs(jac[np.ix_(force_rows, cols)]))
    assert stiff > 1e6
    assert np.max(np.abs(jac[np.ix_(moment_rows, cols)])) < 1e-9 * stiff


def test_serial_kernel_from_a_thread_equals_parallel():
    """A batch (the Jacobian's states) runs on numba's threads from the main thread and
    serially from another thread: the same numbers."""
    _sc, con, q, qt = _scene(axialForce=1300.0)
    main = con.jacobian(0.01, q, qt, 1.0, 1e-4)
    box = {}
    worker = threading.Thread(target=lambda: box.setdefault("f", con.jacobian(0.01, q, qt, 1.0, 1e-4)))
    worker.start()
    worker.join()
    np.testing.assert_allclose(box["f"], main, rtol=0, atol=1e-9 * np.max(np.abs(main)))


def test_many_contacts_on_threads_are_the_serial_kernel(monkeypatch):
    """A recorded run's outputs (>= PARALLEL_CONTACTS contacts) spread the traction over
    numba's threads from the main thread and run serially from another thread: bit for bit
    the serial loop's numbers, with the limiting shear and the film's elasticity on."""
    from contact.kernels import crook

    ux, uy, om, a, b, pm, h = _contacts(2 * crook.PARALLEL_CONTACTS, seed=3)
    ent = np.linspace(-8.0, 8.0, ux.size)
    args = (ux, uy, om, a, b, pm, h, LUB)
    kw = dict(limiting_shear=0.047, film_modulus=0.2953, entrainment=ent)
    threaded = compiled.crook_fast(*args, **kw)
    assert crook._crook_many_prange.signatures  # the threaded loop ran
    box = {}
    worker = threading.Thread(target=lambda: box.setdefault("f", compiled.crook_fast(*args, **kw)))
    worker.start()
    worker.join()
    monkeypatch.setattr(crook, "PARALLEL_CONTACTS", 10 ** 9)
    serial = compiled.crook_fast(*args, **kw)
    assert np.array_equal(threaded, serial) and np.array_equal(box["f"], serial)
    assert np.all(np.isfinite(serial)) and np.count_nonzero(serial[0]) > ux.size // 2


@pytest.mark.parametrize("law", [ContactLaw(traction="coulomb"), ContactLaw(fast_quadrature=False),
                                 ContactLaw(compiled=False)])
def test_laws_the_kernel_does_not_cover_use_numpy(law):
    _sc, con, _q, _qt = _scene(law=law, axialForce=1300.0)
    assert con._compiled is None


def test_land_kernel_is_the_numpy_land_force():
    """The guiding-land kernel against contact.cage.land_forces (and, with a film constant,
    plus contact.land_film.land_film_forces) on random states around the play (inside,
    engaged, separating fast enough to clip), race arrays per state and shared (1, 3)."""
    from contact.cage import land_forces
    from contact.land_film import land_film_forces

    rng = np.random.default_rng(5)
    n = 400
    axis = rng.standard_normal((n, 3))
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    race_o = rng.normal(0.0, 1e-3, (n, 3))
    race_v = rng.normal(0.0, 0.01, (n, 3))
    direction = rng.standard_normal((n, 3))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    offset = rng.uniform(0.0, 0.35e-3, (n, 1)) * direction
    cage_v = rng.normal(0.0, 0.2, (n, 3))
    spin = rng.normal(0.0, 2000.0, n)
    play, k, c = 0.2e-3, 1e7, 400.0
    for shared in (False, True):
        for film in (0.0, 3e-4):
            ro, rv, ax = (race_o[:1], race_v[:1], axis[:1]) if shared else (race_o, race_v, axis)
            cage_o = ro + offset
            force, e = np.empty((n, 3)), np.empty(n)
            compiled.land_forces(cage_o, cage_v, ro, rv, ax, play, k, c, film, spin, force, e)
            expected = land_forces(cage_o, cage_v, ro, rv, ax, play, k, c)
            engaged = np.linalg.norm(expected, axis=1) > 0
            assert 50 < engaged.sum() < n - 50  # both regimes present
            if film > 0:
                axes = np.broadcast_to(ax, (n, 3))
                d = cage_o - ro
                radial = d - np.sum(d * axes, axis=1, keepdims=True) * axes
                rate = cage_v - rv
                rate = rate - np.sum(rate * axes, axis=1, keepdims=True) * axes
                film_force = land_film_forces(radial, rate, axes, spin, film, play)
                assert np.abs(film_force).max() > 0.1 * np.abs(expected).max()  # the film counts
                expected = expected + film_force
            np.testing.assert_allclose(force, expected, rtol=1e-10, atol=1e-10 * np.abs(expected).max())
            d = cage_o - ro
            np.testing.assert_allclose(e, np.linalg.norm(d - np.sum(d * ax, axis=1, keepdims=True) * ax, axis=1),
                                       rtol=1e-12)


def test_compilation_is_announced_once_when_no_cache_exists(monkeypatch, tmp_path, capsys):
    """A fresh install (no numba cache next to the glue module) says what the first, slow
    model build is doing; a second build does not repeat it."""
    from exudyn_bearing.model import compiled as glue

    monkeypatch.setattr(glue, "__file__", str(tmp_path / "compiled.py"))
    monkeypatch.setattr(glue, "_ANNOUNCED", [])
    glue._announce_compilation()
    glue._announce_compilation()
    err = capsys.readouterr().err
    assert err.count("compiling the contact kernels") == 1


@pytest.mark.parametrize("name", ["axial, rigid cage, drag", "combined load",
                                  "rolling resistance, thermal film, combined load", "race surfaces, combined load"])
def test_outputs_recomputed_by_the_compiled_rule_match_the_numpy_rule(name):
    """A run on the compiled path has its outputs' traction recomputed by the compiled rule
    (:meth:`BearingConnector.states`): the same rule's float32 nodes, within 1e-5 of each
    field's largest value of the numpy rule on the same states (as the run's forces,
    test_connector_compiled_paths_match_numpy_path); loads, films and pressures the same numbers."""
    kw = dict(SCENES[name])
    _sc, con, q, qt = _scene(kw.pop("law", ContactLaw()), **kw)
    t = np.full(3, 0.01)
    qs, qts = q + np.outer([0.0, 1e-7, -1e-7], np.ones_like(q)), np.repeat(qt[None], 3, axis=0)
    got = con.states(t, qs, qts)
    kernel, con._compiled = con._compiled, None
    try:
        ref = con.states(t, qs, qts)
    finally:
        con._compiled = kernel
    for race in ("inner_forces", "outer_forces"):
        g, r = getattr(got, race), getattr(ref, race)
        assert np.count_nonzero(r.normal_load) > 3
        for field in ("normal_load", "film_thickness", "max_pressure"):
            np.testing.assert_array_equal(getattr(g, field), getattr(r, field))
        for field in ("traction_rolling", "traction_transverse", "spin_moment", "heat"):
            err = np.max(np.abs(getattr(g, field) - getattr(r, field)))
            assert err < 1e-5 * np.max(np.abs(getattr(r, field))), (race, field, err)
        assert not np.array_equal(g.traction_rolling, r.traction_rolling)  # two rules ran, not one twice
