"""The pure-rolling start state ('rolling'): raceway control and radial balance, checked with
the connector's own contact kinematics (contact.kinematics), not with the builder's algebra."""
import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from contact.ballrace import ContactLaw  # noqa: E402
from exudyn_bearing import CreateAngularContactBearing  # noqa: E402
from exudyn_bearing.races import Driven  # noqa: E402


def _start_state(**kw):
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=Driven(1800.0), initialState="rolling", show=False, **kw)
    mbs.Assemble()
    q = np.asarray(mbs.systemData.GetODE2Coordinates())
    q_t = np.asarray(mbs.systemData.GetODE2Coordinates_t())
    idx = np.concatenate([np.arange(mbs.GetNodeODE2Index(n), mbs.GetNodeODE2Index(n) + 6) for n in handle.nodeNumbers])
    con = handle.connector
    return handle, con.evaluate(0.0, q[idx] + con.reference, q_t[idx], details=True)


@pytest.mark.parametrize("control, zero", [("outer", "outer"), ("inner", "inner")])
@pytest.mark.parametrize("axial", [200.0, 1300.0])
def test_raceway_control_has_no_spin_at_the_controlling_contact(control, zero, axial):
    """Jones' raceway control: the controlling contact rolls without spin, both contacts
    without rolling slip (pure axial load: every ball's pure-rolling orbit is the common
    cage speed); the other contact spins (1.3 kN: ~220 rad/s)."""
    _, state = _start_state(axialForce=axial, initialControl=control)
    other = "inner" if zero == "outer" else "outer"
    scale = np.abs(getattr(state, other).spin).max()
    assert scale > 50.0
    assert np.abs(getattr(state, zero).spin).max() < 1e-9 * scale
    for race in (state.inner, state.outer):
        assert np.abs(race.slip_rolling).max() < 1e-9 * scale * 0.0125  # m/s against r * spin


# no contact damping in the check: with the inner race displaced radially the balls orbit
# eccentrically to its groove, so their normal approach has a rate and damping adds ~0.4 N
@pytest.mark.parametrize("kw", [dict(axialForce=200.0), dict(axialForce=2200.0, radialForce=2000.0,
                                                              contactLaw=ContactLaw(damping_ratio=0.0),
                                                              initialControl="outer")])
def test_rolling_start_is_in_radial_balance(kw):
    """Each ball's normal contact forces balance the centrifugal force of its initial orbit,
    m v²/r_c (the quasi-static solve iterated to each ball's pure-rolling orbital speed):
    radial residual below 1e-4 of the outer load. With radial load the balls orbit at
    different speeds and the controlling contact still rolls without spin."""
    handle, state = _start_state(**kw)
    mass = handle.bearing.ball_mass
    c = state.ball_position - handle.connector.origin
    r_c = np.hypot(c[:, 0], c[:, 1])
    e_r = np.stack([c[:, 0] / r_c, c[:, 1] / r_c, np.zeros(len(c))], axis=1)
    v = np.linalg.norm(state.ball_velocity, axis=1)
    normal = sum(-f.normal_load[:, None] * k.normal for f, k in ((state.inner_forces, state.inner),
                                                               (state.outer_forces, state.outer)))
    residual = np.einsum("ij,ij->i", normal, e_r) + mass * v ** 2 / r_c
    assert np.abs(residual).max() < 1e-4 * state.outer_forces.normal_load.max()
    if "radialForce" in kw:
        speed = np.linalg.norm(state.ball_velocity, axis=1) / r_c
        assert np.ptp(speed) > 1e-3 * speed.mean()  # each ball its own pure-rolling orbit
        # (to 1e-6: the displaced inner race gives its normals a small circumferential part)
        controlled = np.minimum(np.abs(state.inner.spin), np.abs(state.outer.spin))
        assert controlled.max() < 1e-6 * np.abs(state.inner.spin).max()


def test_rolling_cage_speed_about_a_displaced_inner_race():
    """contact.kinematics.rolling_cage_speed with ``inner_origin``: the inner race surface
    speed is w_i (e_z x (p - o)) . t1 about the race's own centre o (a radially loaded race
    sits ~20 um off the axis: 6 mm/s at 3000 rpm), checked against the hand formula given as
    surface speeds."""
    from contact.kinematics import rolling_cage_speed

    c = np.array([[0.02, 0.003, 0.0005], [-0.01, 0.018, 0.0]])
    axis = np.array([[0.3, -0.2, 1.0], [0.1, 0.4, 0.9]])
    p_in = c - 0.005 * np.array([[1.0, 0.1, 0.2], [-0.5, 0.9, 0.1]])
    p_out = c + 0.005 * np.array([[1.0, 0.1, -0.2], [-0.5, 0.9, -0.1]])
    o, w_i = np.array([2e-5, -1e-5, 3e-6]), 314.0
    t1 = np.stack([-c[:, 1], c[:, 0], np.zeros(2)], axis=1) / np.hypot(c[:, 0], c[:, 1])[:, None]
    inner = np.einsum("ij,ij->i", np.cross([0.0, 0.0, w_i], p_in - o), t1)
    got = rolling_cage_speed(c, axis, p_in, p_out, w_i, 0.0, return_spin=True, inner_origin=o)
    want = rolling_cage_speed(c, axis, p_in, p_out, w_i, 0.0, return_spin=True, surface_speeds=(inner, np.zeros(2)))
    np.testing.assert_allclose(got, want, rtol=1e-12)
    centred = rolling_cage_speed(c, axis, p_in, p_out, w_i, 0.0)
    assert np.max(np.abs(got[0] - centred)) > 1e-3  # the displacement matters
