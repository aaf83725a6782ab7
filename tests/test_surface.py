"""Race surfaces (MODEL.md §13): input checks, the bearing file's [[defect]] and [waviness],
the height law against closed forms, and both force paths with surfaces."""
from __future__ import annotations

import math

import numpy as np
import pytest

from contact.kinematics import rotation_matrices
from contact.ball_surface import ball_heights
from contact.surface import Defect, SurfaceModel, Waviness, race_heights, surface_record
from exudyn_bearing import REFERENCE_BEARING
from exudyn_bearing.bearingfile import BearingFile, dumps_bearing, loads_bearing

B = REFERENCE_BEARING
R = B.ball_radius


@pytest.mark.parametrize("make, key", [
    (lambda: Defect("outer", 0.0, -1e-3, 1e-5), "defect.length"),
    (lambda: Defect("outer", 0.0, 1e-3, 0.0), "defect.depth"),
    (lambda: Defect("outer", 0.0, 1e-3, 1e-5, width=-1e-3), "defect.width"),
    (lambda: Defect("outer", math.nan, 1e-3, 1e-5), "defect.angle_deg"),
    (lambda: Defect("cage", 0.0, 1e-3, 1e-5), "defect.race"),
    (lambda: Defect("ball", 0.0, 1e-3, 1e-5), "defect.ball"),
    (lambda: Defect("ball", 0.0, 1e-3, 1e-5, ball=-1), "defect.ball"),
    (lambda: Defect("ball", 0.0, 1e-3, 1e-5, ball=2, width=1e-3), "defect.width"),
    (lambda: Defect("outer", 0.0, 1e-3, 1e-5, ball=2), "defect.ball"),
    (lambda: Defect("outer", 0.0, 1e-3, 1e-5, edge=0.6e-3), "defect.edge"),
    (lambda: Waviness(outer=((1, 1e-6, 0.0),)), "waviness.outer"),
    (lambda: Waviness(inner=((5, 0.0, 0.0),)), "waviness.inner: amplitude"),
    (lambda: Waviness(inner=((5, -1e-6, 0.0),)), "waviness.inner: amplitude"),
    (lambda: Waviness(outer=((5.5, 1e-6, 0.0),)), "waviness.outer"),
    (lambda: Waviness(outer=((5, 1e-6),)), "waviness.outer"),
    (lambda: Waviness(ball=((5, 1e-6, 0.0),)), "waviness.ball"),
    (lambda: Waviness(ball=((-1, 6, 1e-6, 0.0),)), "waviness.ball"),
    (lambda: Waviness(ball=((0, 1, 1e-6, 0.0),)), "waviness.ball"),
])
def test_bad_surfaces_name_their_key(make, key):
    with pytest.raises(ValueError, match=key.replace(".", r"\.")):
        make()


def test_surfaces_are_checked_against_the_bearing():
    outer_circumference = math.pi * (B.pitch_diameter + B.ball_diameter * math.cos(B.contact_angle))
    with pytest.raises(ValueError, match="defect.length.*circumference"):
        surface_record(SurfaceModel((Defect("outer", 0.0, 1.01 * outer_circumference, 1e-5),)), B)
    with pytest.raises(ValueError, match="defect.width.*wider than the inner groove"):
        surface_record(SurfaceModel((Defect("inner", 0.0, 1e-3, 1e-5, width=4 * B.ball_diameter),)), B)
    with pytest.raises(ValueError, match="ball_diameter_variation: one value per ball"):
        surface_record(SurfaceModel(waviness=Waviness(ball_diameter_variation=(1e-6, 0.0))), B)
    with pytest.raises(ValueError, match=r"defect\.ball: 16 is not a ball"):
        surface_record(SurfaceModel((Defect("ball", 0.0, 1e-3, 1e-5, ball=B.balls),)), B)
    with pytest.raises(ValueError, match=r"defect\.length: .* half the ball's circumference"):
        surface_record(SurfaceModel((Defect("ball", 0.0, 0.04, 1e-5, ball=0),)), B)


def test_the_builder_refuses_a_surface_that_does_not_fit_before_touching_mbs():
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing.model.builder import CreateAngularContactBearing

    mbs = exu.SystemContainer().AddSystem()
    with pytest.raises(ValueError, match="defect.length"):
        CreateAngularContactBearing(mbs, surface=SurfaceModel((Defect("inner", 0.0, 1.0, 1e-5),)), show=False)
    assert mbs.systemData.NumberOfNodes() == 0


SURFACE = SurfaceModel((Defect("outer", 10.0, 0.5e-3, 0.28e-3, width=2e-3, offset=1e-4),
                        Defect("inner", -45.0, 2e-3, 20e-6, edge=0.3e-3),
                        Defect("ball", 30.0, 0.5e-3, 10e-6, ball=3)),
                       Waviness(inner=((5, 0.5e-6, 30.0),), outer=((17, 0.3e-6, 0.0), (15, 0.2e-6, 45.0)),
                                ball_diameter_variation=(2e-6,) + (0.0,) * (B.balls - 1),
                                ball=((0, 6, 0.1e-6, 0.0), (5, 7, 0.2e-6, 90.0))))


def test_bearing_file_round_trips_its_surfaces():
    text = dumps_bearing(BearingFile(B, surface=SURFACE))
    assert "[[defect]]" in text and "[waviness]" in text
    assert loads_bearing(text).surface == SURFACE
    assert loads_bearing(dumps_bearing(BearingFile(B))).surface == SurfaceModel()


@pytest.mark.parametrize("text, message", [
    ('[[defect]]\nrace = "outer"\nlength = 1e-3\ndepth = 1e-5\n', r"\[\[defect\]\] number 1 needs angle_deg"),
    ('[[defect]]\nrace = "outer"\nangle_deg = 0\nlength = 1e-3\ndepth = 1e-5\nsize = 3\n', "unknown key.*size"),
    ('[[defect]]\nrace = "outer"\nangle_deg = 0\nlength = 1e-3\ndepth = -1e-5\n', "defect.depth"),
    ("[waviness]\nouter = [[1, 1e-6, 0.0]]\n", "waviness.outer.*order must be an integer >= 2"),
    ("[waviness]\nouter = [17, 1e-6, 0.0]\n", "waviness.outer"),
    ("[waviness]\nroundness = []\n", "unknown key.*roundness"),
])
def test_bearing_file_surface_errors_name_the_key(text, message):
    base = dumps_bearing(B)
    with pytest.raises(ValueError, match=message):
        loads_bearing(base + "\n" + text)


def _heights(surface, race, theta, angle=None, radius=None, ball=0):
    record = surface_record(surface, B)
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    angle = B.contact_angle if angle is None else angle
    radius = 0.5 * B.pitch_diameter if radius is None else radius
    return race_heights(record, race, theta, angle, radius, ball, R)


def test_waviness_height_is_the_fourier_sum():
    theta = np.linspace(-math.pi, math.pi, 41)
    h, slope = _heights(SurfaceModel(waviness=Waviness(outer=((17, 0.3e-6, 20.0), (4, 1e-6, -60.0)))), 1, theta)
    want = 0.3e-6 * np.cos(17 * theta + math.radians(20.0)) + 1e-6 * np.cos(4 * theta - math.radians(60.0))
    np.testing.assert_allclose(h, want, rtol=0, atol=1e-18)
    want_slope = -(17 * 0.3e-6 * np.sin(17 * theta + math.radians(20.0)) + 4e-6 * np.sin(4 * theta - math.radians(60.0)))
    np.testing.assert_allclose(slope, want_slope, rtol=0, atol=1e-17)
    inner, _ = _heights(SurfaceModel(waviness=Waviness(outer=((17, 0.3e-6, 20.0),))), 0, theta)
    assert np.all(inner == 0.0)  # another race's waviness


def test_short_notch_the_ball_cannot_reach_the_bottom_follows_the_circle_over_its_edges():
    """A 0.18-mm notch, 0.28 mm deep (the CWRU outer-race fault): the ball centre drops at most
    r - sqrt(r² - (L/2)²) in the middle (eq. 13.2), never the depth; its path is the circle
    over the nearer edge; nothing outside the notch."""
    length, rho = 0.18e-3, 0.5 * B.pitch_diameter
    notch = SurfaceModel((Defect("outer", 0.0, length, 0.28e-3),))
    x = np.linspace(-0.2e-3, 0.2e-3, 801)  # arc position from the notch centre
    h, slope = _heights(notch, 1, x / rho, radius=rho)
    u = np.clip(0.5 * length - np.abs(x), 0.0, None)  # distance to the nearer edge
    want = np.where(np.abs(x) < 0.5 * length, -(R - np.sqrt(R * R - u * u)), 0.0)
    np.testing.assert_allclose(h, want, rtol=0, atol=1e-15)
    assert -h.min() == pytest.approx(R - math.sqrt(R * R - (0.5 * length) ** 2), rel=1e-9)
    assert Defect("outer", 0.0, length, 0.28e-3).reach(R) == pytest.approx(-h.min(), rel=1e-9)
    smooth = (np.abs(x) < 0.5 * length - 2e-6) & (np.abs(x) > 2e-6)  # off the edges and the kink at the centre
    numeric = np.gradient(h, x / rho)
    np.testing.assert_allclose(slope[smooth], numeric[smooth], rtol=2e-2, atol=0)


def test_long_spall_reaches_its_depth_and_its_edge_ramps():
    length, depth, edge, rho = 4e-3, 10e-6, 0.5e-3, 0.5 * B.pitch_diameter
    x = np.linspace(-2.5e-3, 2.5e-3, 1001)
    h, _ = _heights(SurfaceModel((Defect("inner", 30.0, length, depth, edge=edge),)), 0,
                    math.radians(30.0) + x / rho, radius=rho)
    u = np.clip(0.5 * length - np.abs(x), 0.0, None)
    circle = R - np.sqrt(R * R - np.minimum(u, R) ** 2)
    want = np.where(np.abs(x) < 0.5 * length, -np.minimum.reduce([np.full_like(x, depth), depth * u / edge, circle]), 0)
    np.testing.assert_allclose(h, want, rtol=0, atol=1e-15)
    assert h.min() == -depth


def _pit_heights(pit, angle, spin, across=0.0, r_x=R):
    """(h, dh/dt, G) of ``pit`` (a Defect, or a SurfaceModel) on ball 0 (its start circle: zero
    e_x, spin axis e_z, the default) at a contact with n = e_x, t1 = e_y, t2 = e_z, the ball
    turned by ``angle`` (rad, (n,)) about e_z and then by ``across`` about -e_y, spinning at
    ``spin`` rad/s about e_z."""
    record = surface_record(pit if isinstance(pit, SurfaceModel) else SurfaceModel((pit,)), B)
    n = np.size(angle)
    rot = rotation_matrices(np.stack([np.zeros(n), np.zeros(n), np.asarray(angle)], axis=1))
    rot = rotation_matrices(np.array([[0.0, -across, 0.0]])) @ rot
    e = np.broadcast_to(np.eye(3)[:, None, :], (3, n, 3))
    out = ball_heights(record, np.zeros(n, dtype=int), 1, rot, e[0], e[1], e[2],
                       np.broadcast_to([0.0, 0.0, spin], (n, 3)), R, np.full(n, r_x))
    return out[0], out[1], out[2:].T  # h, dh/dt, G = dh/dphi (n, 3)


def test_ball_pit_follows_the_circle_over_its_edges_on_the_chord_the_contact_crosses():
    """A round pit of 1 mm on a ball with edge ramps (1 nm: sharp in effect; eq. 13.3): on its
    diameter the contact's drop is eq. 13.2 with L = 1 mm and R_x; 0.3 mm off it, the chord
    2 sqrt(0.5² - 0.3²) mm = 0.8 mm takes L's place; nothing on the ball's far side; dh/dt is
    the height's time derivative at the spin."""
    diameter, r_x, spin = 1e-3, 0.9 * R, 300.0
    pit = Defect("ball", 0.0, diameter, 0.28e-3, ball=0, edge=1e-9)
    x = np.linspace(-0.6e-3, 0.6e-3, 601)  # arc position of the pit's centre from the contact
    for across, chord in ((0.0, diameter), (0.3e-3, 0.8e-3)):
        h, rate, grad = _pit_heights(pit, x / R, spin, across / R, r_x)
        along = R * np.arctan2(np.sin(x / R), math.cos(across / R) * np.cos(x / R))  # the arc seen from the contact
        u = np.clip(0.5 * chord - np.abs(along), 0.0, None)
        want = np.where(np.abs(along) < 0.5 * chord, -(r_x - np.sqrt(r_x * r_x - u * u)), 0.0)
        np.testing.assert_allclose(h, want, rtol=0, atol=1e-14)
        smooth = (np.abs(x) < 0.5 * chord - 4e-6) & (np.abs(x) > 4e-6)
        numeric = np.gradient(h, x / R / spin)  # the ball turns by spin dt
        np.testing.assert_allclose(rate[smooth], numeric[smooth], rtol=2e-2, atol=0)
        # eq. 13.7b: G the height's change per radian the ball turns; about the turning axis
        # (e_z, then tipped by 'across' about -e_y) it is dh/d(angle)
        axis = rotation_matrices(np.array([[0.0, -across / R, 0.0]]))[0] @ np.array([0.0, 0.0, 1.0])
        np.testing.assert_allclose((grad @ axis)[smooth], np.gradient(h, x / R)[smooth], rtol=2e-2, atol=0)
    far, _, _ = _pit_heights(pit, np.array([math.pi]), spin)
    assert far[0] == 0.0
    # angle_deg turns the pit about the start spin axis: 90 deg ahead, met after the ball turns back by 90 deg
    turned, _, _ = _pit_heights(Defect("ball", 90.0, diameter, 5e-6, ball=0, edge=1e-9), np.array([-math.pi / 2, 0.0]),
                                spin)
    assert turned[0] == pytest.approx(-min(5e-6, r_x - math.sqrt(r_x ** 2 - (0.5 * diameter) ** 2)), rel=1e-6)
    assert turned[1] == 0.0


def _rim_drop_brute(along, across, radius, depth, r_x, r_y, samples=200001):
    """The drop of a contact at (−along, −across) from a round pit's centre: the least sag
    (x'²/(2 R_x) + y'²/(2 R_y)) over its rim, at most the depth; 0 outside the pit."""
    t = np.linspace(0.0, 2 * np.pi, samples)
    out = np.zeros(np.shape(along))
    for i, (a, c) in enumerate(zip(np.atleast_1d(along), np.atleast_1d(across))):
        if a * a + c * c < radius * radius:
            f = (radius * np.cos(t) + a) ** 2 / (2 * r_x) + (radius * np.sin(t) + c) ** 2 / (2 * r_y)
            out[i] = min(depth, f.min())
    return out


def test_sharp_ball_pit_rests_on_its_rim_in_both_directions():
    """A sharp round pit on a ball (eq. 13.3b): the contact's sag surface (R_x along, R_y =
    f D/(2f − 1) across) rests on the pit's rim. On its diameter, at x from the centre, the
    rim point (ρ u, ρ √(1 − u²)) sags ρ² u² (1/R_x − 1/R_y)/2 − ρ x u / R_x + x²/(2 R_x) + ρ²/(2 R_y),
    least at u = (x/ρ) R_y / (R_y − R_x) inside [−1, 1]; off it, a brute-force rim minimum; dh/dt
    and G = dh/dφ about both axes that move the pit, numerically; the Case Western 0.18-mm pit,
    narrower than the contact, is bridged: the ball sinks ~ρ²/(2 R_y), not s(L/2) = ρ²/(2 R_x)."""
    diameter, r_x, spin, depth = 1e-3, 0.9 * R, 300.0, 0.28e-3
    rho = 0.5 * diameter
    f_o = B.outer_conformity
    r_y = f_o * B.ball_diameter / (2 * f_o - 1)
    pit = Defect("ball", 0.0, diameter, depth, ball=0)
    x = np.linspace(-0.6e-3, 0.6e-3, 601)  # arc position of the pit's centre from the contact
    h, rate, grad = _pit_heights(pit, x / R, spin, 0.0, r_x)
    along = x  # on the diameter
    u = np.clip(along / rho * r_y / (r_y - r_x), -1.0, 1.0)
    sag = rho ** 2 * u ** 2 * (1 / r_x - 1 / r_y) / 2 - rho * along * u / r_x + along ** 2 / (2 * r_x) + rho ** 2 / (2 * r_y)
    want = np.where(np.abs(along) < rho, -np.minimum(depth, sag), 0.0)
    np.testing.assert_allclose(h, want, rtol=0, atol=1e-13)
    smooth = (np.abs(x) < rho - 4e-6) & (np.abs(x) > 4e-6)
    np.testing.assert_allclose(rate[smooth], np.gradient(h, x / R / spin)[smooth], rtol=2e-2, atol=1e-12)
    np.testing.assert_allclose(grad[smooth, 2], np.gradient(h, x / R)[smooth], rtol=2e-2, atol=1e-12)
    # 0.3 mm off the diameter, against the rim's brute-force minimum; G across: tipping the ball
    for across in (0.3e-3,):
        h, _, grad = _pit_heights(pit, x / R, spin, across / R, r_x)
        d = np.stack([np.cos(across / R) * np.cos(x / R), np.sin(x / R), np.sin(across / R) * np.cos(x / R)], axis=1)
        a_arc, c_arc = R * np.arctan2(d[:, 1], d[:, 0]), R * np.arctan2(d[:, 2], d[:, 0])
        np.testing.assert_allclose(h, -_rim_drop_brute(a_arc, c_arc, rho, depth, r_x, r_y), rtol=0, atol=1e-13)
    eps = 1e-7  # about e_y the pit moves across the contact (t2 = e_z)
    xs = np.array([-0.2e-3, 0.1e-3])
    lo, _, _ = _pit_heights(pit, xs / R, spin, (0.2e-3 - eps * R) / R, r_x)
    hi, _, g_mid = _pit_heights(pit, xs / R, spin, (0.2e-3 + eps * R) / R, r_x)
    # the tip is −across/R about e_y applied last: dh/d(tip about +e_y) = −(hi − lo)/(2 eps)
    np.testing.assert_allclose(g_mid[:, 1], -(hi - lo) / (2 * eps), rtol=2e-2)
    # the Case Western pit: bridged
    small, _, _ = _pit_heights(Defect("ball", 0.0, 0.18e-3, depth, ball=0), np.array([0.0]), spin, 0.0, r_x)
    assert -small[0] == pytest.approx(0.09e-3 ** 2 / (2 * r_y), rel=1e-6)
    assert -small[0] < 0.05 * (0.09e-3 ** 2 / (2 * r_x))  # R_x / R_y = 3.5 %


def test_ball_waviness_is_the_fourier_sum_over_the_contacts_longitude_on_the_ball():
    """Waviness of ball 0 (eq. 13.6): with the ball turned by -phi about its spin axis, the
    contact sits at longitude phi on it: h = sum A cos(k phi + phase); dh/dt is h's time
    derivative at the spin; ball 1's waviness is not ball 0's."""
    rows = ((0, 6, 0.3e-6, 20.0), (0, 3, 1e-6, -60.0), (1, 5, 2e-6, 0.0))
    phi = np.linspace(-math.pi, math.pi, 721)
    spin = 200.0
    h, rate, grad = _pit_heights(SurfaceModel(waviness=Waviness(ball=rows)), -phi, spin)
    want = 0.3e-6 * np.cos(6 * phi + math.radians(20.0)) + 1e-6 * np.cos(3 * phi - math.radians(60.0))
    np.testing.assert_allclose(h, want, rtol=0, atol=1e-15)
    numeric = np.gradient(h, -phi / spin)  # the ball turns by spin dt: phi falls
    np.testing.assert_allclose(rate[1:-1], numeric[1:-1], rtol=0, atol=2e-3 * np.max(np.abs(rate)))
    # the ball turned by d(-phi) about e_z: G_z = dh/d(-phi)
    np.testing.assert_allclose(grad[1:-1, 2], -np.gradient(h, phi)[1:-1], rtol=0,
                               atol=2e-3 * np.max(np.abs(grad[:, 2])))


def test_defect_across_the_raceway_and_turning_with_its_race():
    """A defect 2 mm wide whose centre line is 1.5 mm off the contact path: a contact at the
    nominal angle misses it, one moved by 1.5 mm of groove arc meets it."""
    notch = SurfaceModel((Defect("outer", 0.0, 1e-3, 5e-6, width=2e-3, offset=1.5e-3),))
    arc = B.outer_conformity * B.ball_diameter
    assert _heights(notch, 1, 0.0)[0][0] == 0.0
    assert _heights(notch, 1, 0.0, angle=B.contact_angle + 1.5e-3 / arc)[0][0] < 0.0
    assert _heights(notch, 0, 0.0)[0][0] == 0.0  # the inner race has no defect


def test_oversize_ball_adds_its_radius_excess_to_both_its_contacts():
    surf = SurfaceModel(waviness=Waviness(ball_diameter_variation=(0.0, 3e-6) + (0.0,) * (B.balls - 2)))
    for race in (0, 1):
        h, slope = _heights(surf, race, np.zeros(3), ball=np.array([0, 1, 2]))
        np.testing.assert_array_equal(h, [0.0, 1.5e-6, 0.0])
        assert np.all(slope == 0.0)


exu = pytest.importorskip("exudyn")


def _state(**kw):
    from tests.helpers import _scene

    return _scene(axialForce=2200.0, radialForce=2000.0, **kw)


@pytest.mark.slow
def test_oversize_ball_carries_more_in_both_force_paths():
    """Ball 3 made 2 um larger: its inner and outer approach grow by exactly 1 um (compiled
    kernel outputs), nothing else moves; the numpy path's loads agree."""
    from tests.helpers import _both_paths

    extra = np.zeros(B.balls)
    extra[3] = 2e-6
    pens = []
    state = None
    for surface in (SurfaceModel(), SurfaceModel(waviness=Waviness(ball_diameter_variation=tuple(extra)))):
        _sc, con, q, qt = _state(surface=surface)
        q, qt = state = state or (q, qt)  # the same state (the surface start moves ball 3 in its scene)
        con.residual_forces(0.01, q - con.reference, qt)
        pens.append(con._compiled.penetration.reshape(2, -1).copy())
        single, fast, ref = _both_paths(con, q, qt)
        np.testing.assert_allclose(single, ref, rtol=0, atol=1e-6 * np.max(np.abs(ref)))
    diff = pens[1] - pens[0]
    np.testing.assert_allclose(diff[:, 3], 1e-6, rtol=1e-6)
    assert np.all(diff[:, np.arange(B.balls) != 3] == 0.0)


@pytest.mark.slow
def test_a_defect_no_ball_touches_leaves_every_force_bit_for_bit():
    """The surface term is a separate branch: where it gives h = 0 the contact is computed
    exactly as for a perfect bearing (the feature costs nothing when off)."""
    _sc, con0, q, qt = _state()
    psi = np.degrees(np.arctan2(q[1], q[0]))  # ball 0's azimuth; the next ball is 22.5 degrees on
    far = SurfaceModel((Defect("outer", psi + 11.25, 0.1e-3, 5e-6),))
    _sc1, con1, q1, qt1 = _state(surface=far)
    np.testing.assert_array_equal(q, q1)
    for path in range(3):
        from tests.helpers import _both_paths

        np.testing.assert_array_equal(_both_paths(con0, q, qt)[path], _both_paths(con1, q, qt)[path])


def test_surface_start_an_oversize_ball_carries_the_rigid_ring_load_distribution():
    """A ball 2 um oversize among 16 under 1300 N axial at 10 rpm (no centrifugal force): the
    builder's surface start (MODEL.md §13d) moves the balls and the free inner race so that at
    t = 0 each ball carries what the rigid-ring load distribution gives (Harris): approach
    along the contact line z sin a + (x cos psi + y sin psi) cos a + dD_j, Q = K delta^1.5 with
    the series stiffness K of the two contacts, in axial and radial balance (within 0.1 %)."""
    exu = pytest.importorskip("exudyn")
    from scipy.optimize import fsolve

    from exudyn_bearing import CreateAngularContactBearing, races

    z, force, excess = B.balls, 1300.0, np.zeros(B.balls)
    excess[3] = 2e-6
    mbs = exu.SystemContainer().AddSystem()
    h = CreateAngularContactBearing(mbs, B, innerRace=races.Driven(10), axialForce=force, show=False,
                                    surface=SurfaceModel(waviness=Waviness(ball_diameter_variation=tuple(excess))))
    assert h.connector.surface_start["converged"]
    q = np.concatenate([mbs.GetNodeParameter(n, "initialCoordinates") for n in h.nodeNumbers])
    qt = np.concatenate([mbs.GetNodeParameter(n, "initialVelocities") for n in h.nodeNumbers])
    st = h.connector.evaluate(0.0, h.connector.reference + q, qt, details=True)
    a = float(np.mean(st.inner.contact_angle))
    k = (B.hertz(a, "inner").stiffness ** (-2 / 3) + B.hertz(a, "outer").stiffness ** (-2 / 3)) ** -1.5
    psi = 2 * np.pi * np.arange(z) / z

    def loads(u):
        approach = u[2] * math.sin(a) + (u[0] * np.cos(psi) + u[1] * np.sin(psi)) * math.cos(a) + excess
        return k * np.maximum(approach, 0.0) ** 1.5

    def balance(u):
        q_ = loads(1e-6 * u)
        return [np.sum(q_ * np.cos(psi)), np.sum(q_ * np.sin(psi)), np.sum(q_) * math.sin(a) - force]

    want = loads(1e-6 * fsolve(balance, [0.0, 0.0, 10.0]))
    assert want[3] > 1.8 * want[0]
    np.testing.assert_allclose(st.inner_forces.normal_load, want, rtol=1e-3)
    np.testing.assert_allclose(st.outer_forces.normal_load, want, rtol=1e-3)


def test_surface_start_is_settled_from_the_first_step():
    """The same oversize ball at 1800 rpm: over the first 2 ms its load stays within 2 % of
    what the oversize adds to it (the start carries the surface; without the surface start
    the ball would start with 2 um more approach on both contacts and ring)."""
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import CreateAngularContactBearing, races
    from exudyn_bearing.simulation.runner import SolverSettings, run_solver

    excess = np.zeros(B.balls)
    excess[3] = 2e-6
    mbs = exu.SystemContainer().AddSystem()
    h = CreateAngularContactBearing(mbs, B, innerRace=races.Driven(1800), axialForce=1300.0, show=False,
                                    surface=SurfaceModel(waviness=Waviness(ball_diameter_variation=tuple(excess))))
    mbs.Assemble()
    run_solver(mbs, [h], 0.002, SolverSettings(output_step=1e-5, progress=False))
    load = h.Results(mbs).outer["load"]
    added = load[0, 3] - load[0, 0]
    assert added > 15.0
    assert np.max(np.abs(load[:, 3] - load[0, 3])) < 0.02 * added


def test_over_a_notch_edge_the_load_tilts_with_the_ball_centres_path():
    """Ball 0's outer contact 0.2 mm inside the exit edge of a 1-mm, 50-um notch (traction
    off, 1300 N axial): the ball rests on the edge, and the load acts along the line from
    the edge to the ball centre, tilted against the rolling direction t1 by the centre's path
    (eq. 13.2, 13.7): its drop s(ρ_p θ) over the centre's own arc ρ_c θ, F.t1 / Q =
    -(ρ_p/ρ_c) u / sqrt(R_x² - u²), R_x = r (d_m + D cos a)/d_m at the contact's angle — at a
    0° contact u/r to first order, the edge-to-centre line (the numpy path); the compiled
    paths' forces equal it."""
    from contact.ballrace import ContactLaw
    from tests.helpers import _both_paths, _scene

    _sc, con0, q, _ = _scene(axialForce=1300.0, law=ContactLaw(traction="none"))
    length, u = 1e-3, 0.2e-3
    psi = math.atan2(q[1], q[0])  # ball 0's azimuth
    rho = math.hypot(q[0], q[1]) + R * math.cos(B.contact_angle)  # about the outer contact's radius
    notch = SurfaceModel((Defect("outer", math.degrees(psi - (0.5 * length - u) / rho), length, 50e-6),))
    _sc, con, q, qt = _scene(axialForce=1300.0, law=ContactLaw(traction="none"), surface=notch)
    state = con.evaluate(0.0, q, qt, details=True)
    kin, forces = state.outer, state.outer_forces
    assert forces.normal_load[0] > 10.0
    alpha = kin.contact_angle[0]
    r_x = R * (B.pitch_diameter + B.ball_diameter * math.cos(alpha)) / B.pitch_diameter
    edge = (kin.azimuth[0] - (psi - (0.5 * length - u) / rho) + 0.5 * length / kin.point_radius[0]) * kin.point_radius[0]
    u_here = length - edge  # the contact's distance from the exit edge
    assert u_here == pytest.approx(u, rel=0.05)
    want = -(kin.point_radius[0] / kin.orbit_radius[0]) * u_here / math.sqrt(r_x ** 2 - u_here ** 2)
    got = (forces.force[0] @ kin.rolling[0]) / forces.normal_load[0]
    assert got == pytest.approx(want, rel=1e-3)
    single, fast, ref = _both_paths(con, q, qt)
    np.testing.assert_allclose(single, ref, rtol=0, atol=1e-9 * np.max(np.abs(ref)))
    np.testing.assert_allclose(fast, ref, rtol=0, atol=1e-9 * np.max(np.abs(ref)))
