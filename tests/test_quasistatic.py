"""Quasi-static load distribution (MODEL.md §4) against independent numbers."""
import json
import math
import subprocess
import sys

import numpy as np
import pytest
from scipy import integrate, optimize

from contact import geometry, hertz
from exudyn_bearing import REFERENCE_BEARING as B, QuasiStaticError, solve_load_distribution
from tests.helpers import E_Z, JH_A0, JH_D, JH_DM, JH_E, JH_F, JH_MASS, JH_RP, JH_TUBE, JH_Z, _jh_ball, _jh_contacts, _jh_grooves, _newton, jh_hertz_k, jones_harris  # noqa: E402,F401

E_PRIME = float(hertz.effective_modulus(210e9, 0.3))


def k_eff_at(alpha):
    """Series Hertz stiffness of one ball at contact angle alpha, built from contact/ only."""
    ks = [hertz.hertz_contact(*geometry.curvature_radii(25e-3, 155e-3, alpha, 0.52, race), E_PRIME).stiffness
          for race in ("inner", "outer")]
    return float(hertz.effective_ball_stiffness(*ks))


def assert_matches_jones_harris(res, jh):
    """Loads to 1e-7 of the largest, contact angles of loaded contacts to 1e-8 rad."""
    q_i, q_o, a_i, a_o, _shift = jh
    scale = max(q_i.max(), q_o.max())
    np.testing.assert_allclose(res.inner_load, q_i, rtol=0, atol=1e-7 * scale)
    np.testing.assert_allclose(res.outer_load, q_o, rtol=0, atol=1e-7 * scale)
    np.testing.assert_allclose(res.inner_contact_angle[q_i > 0], a_i[q_i > 0], rtol=0, atol=1e-8)
    np.testing.assert_allclose(res.outer_contact_angle[q_o > 0], a_o[q_o > 0], rtol=0, atol=1e-8)


def printed(value, figure, decimals=0):
    """A figure printed in the docs with ``decimals`` decimals is ``value`` rounded."""
    return abs(value - figure) <= 0.5 * 10.0 ** -decimals + 1e-12


def test_pure_axial_rpm0_matches_jones_harris_thrust_equation():
    """Harris (Rolling Bearing Analysis, pure thrust): F_a = Z K (A (cos a0/cos a - 1))^1.5 sin a."""
    fa, a_dist, a0 = 1300.0, 1e-3, math.radians(40)
    alpha = optimize.brentq(lambda a: 16 * k_eff_at(a) * (a_dist * (math.cos(a0) / math.cos(a) - 1)) ** 1.5
                            * math.sin(a) - fa, a0 + 1e-9, a0 + 0.3)
    q_ref = fa / (16 * math.sin(alpha))
    res = solve_load_distribution(B, axial_force=fa, rpm=0)
    np.testing.assert_allclose(res.inner_load, q_ref, rtol=2e-3)  # K differs slightly inner vs outer angle
    np.testing.assert_allclose(res.inner_contact_angle, alpha, atol=2e-4)
    assert_matches_jones_harris(res, jones_harris(fa))
    # MODEL.md §4: "≈126 N at ≈40.3°"
    assert printed(q_ref, 126) and printed(math.degrees(alpha), 40.3, 1)


def test_combined_rpm0_max_load_and_unloaded_zone():
    res = solve_load_distribution(B, axial_force=2200, radial_force=2000, rpm=0)
    assert res.max_load == pytest.approx(650, rel=0.05)  # paper: 650 N
    jh = jones_harris(2200.0, 2000.0)
    assert_matches_jones_harris(res, jh)
    assert (jh[0] > 0).sum() == 9  # MODEL.md §9: 9 balls loaded
    assert (res.inner_load > 0).sum() == 9
    assert np.all(res.inner_load[np.abs(np.cos(res.azimuth)) > 0.99][1:] == 0) or res.inner_load[8] == 0
    _check_race_balance(res, 2200, 2000)


def _check_race_balance(res, fa, fr):
    """Inner-race balance from the returned loads, angles and circumferential (cage) forces."""
    qi, ai, psi = res.inner_load, res.inner_contact_angle, res.azimuth
    assert np.sum(qi * np.sin(ai)) == pytest.approx(fa, rel=1e-6)
    in_plane = np.sqrt(np.maximum(qi ** 2 - res.cage_force ** 2, 0.0))  # |Q n| minus its circumferential part
    radial_x = np.sum(in_plane * np.cos(ai) * np.cos(psi) + res.cage_force * np.sin(psi))
    assert radial_x == pytest.approx(fr, rel=1e-6, abs=1e-6 * fa)


@pytest.mark.parametrize("fa,inner,outer", [(1300, (115, 44.9), (141, 35.1)), (200, (None, 55), (None, 16))])
def test_centrifugal_force_splits_contact_angles_at_1800rpm(fa, inner, outer):
    """Against the Jones–Harris equilibrium solved here; ``inner``/``outer``: the (load N,
    angle deg) printed in MODEL.md §4 and the README, which must be its rounded values."""
    res = solve_load_distribution(B, axial_force=fa, rpm=1800)
    fc = 0.064 * 0.0775 * (1800 * math.pi / 30 / 2 * (1 - 25 * math.cos(math.radians(40)) / 155)) ** 2
    assert res.centrifugal_force == pytest.approx(fc, rel=1e-12) and fc == pytest.approx(34, abs=0.5)
    jh = jones_harris(float(fa), rpm=1800.0)
    assert_matches_jones_harris(res, jh)
    q_i, q_o, a_i, a_o, _ = jh
    for (q_doc, a_doc), q, a in ((inner, q_i, a_i), (outer, q_o, a_o)):
        assert np.ptp(q) < 1e-6 * q.max() and np.ptp(a) < 1e-9  # pure axial load: all balls alike
        if q_doc is not None:
            assert printed(q[0], q_doc), (q[0], q_doc)
        decimals = 1 if a_doc != round(a_doc) else 0
        assert printed(math.degrees(a[0]), a_doc, decimals), (math.degrees(a[0]), a_doc)
    assert a_i[0] > math.radians(40) > a_o[0]  # the split
    # each ball's own balance: contact forces + centrifugal at its orbit radius, closes to
    # 1e-6 of its load
    radial = (res.outer_load * np.cos(res.outer_contact_angle) - res.inner_load * np.cos(res.inner_contact_angle)
              - fc * (1 + res.ball_radius_offset / B.pitch_radius))
    axial = res.outer_load * np.sin(res.outer_contact_angle) - res.inner_load * np.sin(res.inner_contact_angle)
    assert np.max(np.hypot(radial, axial) / res.outer_load) < 1e-6
    _check_race_balance(res, fa, 0.0)


def test_combined_1800rpm_every_ball_loaded():
    res = solve_load_distribution(B, axial_force=2200, radial_force=2000, rpm=1800)
    jh = jones_harris(2200.0, 2000.0, 1800.0)
    assert_matches_jones_harris(res, jh)
    # MODEL.md §9: "≈26 N minimum, ≈890 N maximum"
    assert printed(jh[0].min(), 26) and printed(jh[0].max(), 890)
    _check_race_balance(res, 2200, 2000)


def _sjovall(eps):
    """Sjövall integrals J_r, J_a (Harris): loaded zone |psi| < psi_l, cos psi_l = 1 - 2 eps."""
    psi_l = math.acos(max(-1.0, 1 - 2 * eps))
    shape = lambda p: (1 - (1 - math.cos(p)) / (2 * eps)) ** 1.5
    j_r = integrate.quad(lambda p: shape(p) * math.cos(p), -psi_l, psi_l)[0] / (2 * math.pi)
    j_a = integrate.quad(shape, -psi_l, psi_l)[0] / (2 * math.pi)
    return j_r, j_a


def test_sjovall_reference_values():
    j_r, _ = _sjovall(0.5)
    assert j_r == pytest.approx(0.2288, abs=1e-4) and 1 / j_r == pytest.approx(4.37, abs=0.01)


def test_fixed_angle_combined_load_matches_sjovall():
    fa, fr, alpha = 2200.0, 2000.0, math.radians(40)
    target = fr * math.tan(alpha) / fa
    eps = optimize.brentq(lambda e: (lambda j: j[0] / j[1] - target)(_sjovall(e)), 0.01, 50)
    q_max = fa / (16 * _sjovall(eps)[1] * math.sin(alpha))
    res = solve_load_distribution(B, axial_force=fa, radial_force=fr, rpm=0, mode="fixed-angle")
    assert res.max_load == pytest.approx(q_max, rel=0.02)  # 16 discrete balls vs the integral
    assert res.max_load == pytest.approx(650, rel=0.05)


def test_fixed_angle_pure_radial_is_stribeck():
    fr, alpha = 2000.0, math.radians(40)
    res = solve_load_distribution(B, radial_force=fr, rpm=0, mode="fixed-angle", hold_axial=True)
    q_ref = fr / (16 * 0.2288 * math.cos(alpha))  # Q_max = 4.37 F_r / (Z cos a)
    assert res.max_load == pytest.approx(q_ref, rel=0.02)
    assert res.displacement[2] == 0.0


def test_fixed_angle_axial_is_paper_p4_p5():
    res = solve_load_distribution(B, axial_force=1300, rpm=0, mode="fixed-angle")
    np.testing.assert_allclose(res.inner_load, 1300 / (16 * math.sin(math.radians(40))), rtol=1e-9)
    delta = res.displacement[2] * math.sin(math.radians(40))
    np.testing.assert_allclose(res.inner_load, k_eff_at(math.radians(40)) * delta ** 1.5, rtol=1e-9)


def test_tilting_moment_balanced():
    m_y = 10.0
    res = solve_load_distribution(B, axial_force=2200, rpm=0, moment=(0.0, m_y))
    assert abs(res.tilt[1]) > 0 and np.all(res.reaction_moment == 0)
    # moment of the ball forces on the inner race about the centre (contact points at the
    # ball centre minus r n_i, normals in the meridional plane; tilts are ~1e-4 rad)
    r_c = B.pitch_radius + res.ball_radius_offset
    n_r, n_z = -np.cos(res.inner_contact_angle), -np.sin(res.inner_contact_angle)
    x = (r_c + B.ball_radius * n_r) * np.cos(res.azimuth)
    f_x, f_z = res.inner_load * n_r * np.cos(res.azimuth), res.inner_load * n_z
    z = res.ball_axial_offset + B.ball_radius * n_z
    my_balls = np.sum(z * f_x - x * f_z)
    assert my_balls + m_y == pytest.approx(0.0, abs=0.01 * m_y)


def test_bad_input_and_no_equilibrium():
    with pytest.raises(ValueError, match="axial"):
        solve_load_distribution(B, axial_force=-5.0)
    with pytest.raises(ValueError, match="radial"):
        solve_load_distribution(B, axial_force=100, radial_force=float("nan"))
    with pytest.raises(ValueError, match="axial"):
        solve_load_distribution(B, radial_force=1000, mode="fixed-angle")
    with pytest.raises(QuasiStaticError, match="did not converge"):
        solve_load_distribution(B, axial_force=1000, max_iter=1)
    with pytest.raises(ValueError, match="cage_speed"):
        solve_load_distribution(B, axial_force=1000, rpm=1800, cage_speed=float("inf"))


@pytest.mark.parametrize("mode", ["geometric", "fixed-angle"])
def test_race_force_balances_the_applied_load(mode):
    """The balls' force on the inner race is minus the applied load (equilibrium); in the
    geometric mode their moment is minus the reaction moment the shaft supplies; a given
    cage speed of 0 is the no-centrifugal (0 rpm) solution."""
    res = solve_load_distribution(B, axial_force=2200, radial_force=2000, rpm=1800, mode=mode)
    np.testing.assert_allclose(res.race_force, [-2000.0, 0.0, -2200.0], atol=1e-6 * 2200)
    if mode == "geometric":
        np.testing.assert_allclose(res.race_moment[:2], -res.reaction_moment, atol=1e-9)
    still = solve_load_distribution(B, axial_force=2200, radial_force=2000, rpm=1800, mode=mode, cage_speed=0.0)
    rest = solve_load_distribution(B, axial_force=2200, radial_force=2000, rpm=0, mode=mode)
    np.testing.assert_allclose(still.inner_load, rest.inner_load, rtol=1e-9, atol=1e-9)


def test_cli_json():
    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "loads", "--axial", "1300", "--radial", "0",
                          "--rpm", "0", "--json"], capture_output=True, text=True, check=True).stdout
    data = json.loads(out)
    assert len(data["inner_load"]) == 16 and len(data["outer_contact_angle"]) == 16
    q_i = jones_harris(1300.0)[0]
    np.testing.assert_allclose(data["inner_load"], q_i, rtol=1e-7)
    assert data["axial_displacement"] > 0 and data["radial_displacement"] == pytest.approx(0, abs=1e-9)
    # issue 16 item 7: the Python names, degrees beside radians, a unit for every key
    res = solve_load_distribution(B, axial_force=1300.0, rpm=0.0)
    assert set(vars(res)) <= set(data) and set(data["units"]) == set(data) - {"units", "inputs"}
    assert "balls=16" in data["inputs"]["bearing"]  # what produced it
    np.testing.assert_allclose(data["inner_contact_angle_deg"], np.degrees(data["inner_contact_angle"]), rtol=1e-12)
    assert data["units"]["inner_load"] == "N" and data["units"]["azimuth_deg"] == "deg"
    table = subprocess.run([sys.executable, "-m", "exudyn_bearing", "loads", "--axial", "1300", "--rpm", "1800",
                            "--fixed-angle"], capture_output=True, text=True, check=True).stdout
    assert "fixed-angle" in table
    bad = subprocess.run([sys.executable, "-m", "exudyn_bearing", "loads", "--axial", "-3"], capture_output=True, text=True)
    assert bad.returncode == 2 and "axial" in bad.stderr


def _deep_groove(clearance=10e-6):
    from exudyn_bearing import Bearing

    return Bearing.from_clearance(diametral_clearance=clearance, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                  inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)


@pytest.mark.parametrize("pd", [10e-6, 0.0])
def test_deep_groove_radial_load_alone_is_stribeck_with_clearance(pd):
    """A deep-groove bearing carries a radial load with its grooves centred: the loads
    follow the discrete Stribeck sum with diametral clearance P_d (Harris, Rolling Bearing
    Analysis, ch. 7): Q_j = K (delta_r cos psi_j - P_d/2)^1.5, sum Q_j cos psi_j = F_r,
    K the series stiffness of both contacts at zero contact angle (P_d = 0: free angle 0)."""
    brg, fr = _deep_groove(pd), 2500.0
    res = solve_load_distribution(brg, radial_force=fr, rpm=0)
    k_i, k_o = (brg.hertz(0.0, race).stiffness for race in ("inner", "outer"))
    k = (k_i ** (-2 / 3) + k_o ** (-2 / 3)) ** -1.5
    psi = 2 * np.pi * np.arange(brg.balls) / brg.balls

    def loads(dr):
        return k * np.maximum(dr * np.cos(psi) - pd / 2, 0.0) ** 1.5

    dr = optimize.brentq(lambda d: loads(d) @ np.cos(psi) - fr, pd / 2 + 1e-12, 1e-3)
    np.testing.assert_allclose(res.inner_load, loads(dr), rtol=5e-3, atol=1e-6 * fr)
    assert abs(res.race_force[2]) < 1e-6 * fr  # no axial force left on the race
    assert np.degrees(np.abs(res.inner_contact_angle)).max() < 0.5


def test_deep_groove_small_axial_with_large_radial():
    """Fixed angles cannot carry 2.5 kN radial with 200 N axial (1.25 F_r tan a0 = 422 N);
    full grooves can: the solve falls back to the centred start and balances both loads."""
    brg = _deep_groove()
    res = solve_load_distribution(brg, axial_force=200.0, radial_force=2500.0, rpm=3000)
    np.testing.assert_allclose(-res.race_force, [2500.0, 0.0, 200.0], atol=1e-6 * 2500)
    assert res.inner_contact_angle.max() > 0


def test_zero_clearance_deep_groove_under_axial_load():
    """No radial play (free contact angle 0): an axial load alone turns the contacts to the
    angle a with Z K (A (1/cos a - 1))^1.5 sin a = F_a (A = (f_i + f_o - 1) D, K the series
    stiffness at that angle), solved here by bisection; it used to divide by sin 0."""
    from exudyn_bearing import Bearing

    brg = Bearing.from_clearance(diametral_clearance=0.0, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                 inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)
    fa = 200.0
    a_len = (brg.inner_conformity + brg.outer_conformity - 1.0) * brg.ball_diameter

    def k_series(alpha):
        k_i, k_o = (brg.hertz(alpha, race).stiffness for race in ("inner", "outer"))
        return (k_i ** (-2 / 3) + k_o ** (-2 / 3)) ** -1.5

    def excess(alpha):
        return brg.balls * k_series(alpha) * (a_len * (1 / math.cos(alpha) - 1)) ** 1.5 * math.sin(alpha) - fa

    alpha = optimize.brentq(excess, 1e-3, 0.6)
    res = solve_load_distribution(brg, axial_force=fa, rpm=0)
    np.testing.assert_allclose(res.inner_contact_angle, alpha, atol=2e-3)  # inner/outer Hertz differ slightly
    np.testing.assert_allclose(res.inner_load, fa / (brg.balls * math.sin(alpha)), rtol=5e-3)


# ---------------------------------------------------------------------------------------
# The race's Newton: its Jacobian with the balls condensed out, a warm start (issue 52 item 3)
# ---------------------------------------------------------------------------------------
def _resolved_race_jacobian(model, x, steps, length):
    """d(race force, moment / length)/d(pose) by central differences of balances re-solved at
    each perturbed pose: the independent (and ~5x dearer) way."""
    def race(xx):
        offsets, con, _ = model.solve_balls(xx)
        f, m = model.race_forces(con, model.centres(offsets))
        return np.concatenate([f, m[:2] / length])
    return np.stack([(race(x + h * e) - race(x - h * e)) / (2 * h) for h, e in zip(steps, np.eye(5))], axis=1)


@pytest.mark.parametrize("bearing, pose, rpm", [
    (B, (25e-6, 3e-6, -40e-6, 1e-5, -2e-5), 1800.0),  # reference, tilted, centrifugal force on
    (B, (5e-6, 0.0, 8e-6, 0.0, 0.0), 0.0),
    ("deep-groove", (20e-6, 0.0, -60e-6, 0.0, 0.0), 1800.0)])
def test_condensed_race_jacobian_matches_re_solved_balances(bearing, pose, rpm):
    from exudyn_bearing import Bearing
    from exudyn_bearing.solvers.geometric import Geometric
    if bearing == "deep-groove":
        bearing = Bearing.from_clearance(diametral_clearance=10e-6, balls=6, ball_diameter=11.1e-3,
                                         pitch_diameter=43.5e-3, inner_conformity=5.772 / 11.1,
                                         outer_conformity=5.883 / 11.1)
    w_c = bearing.cage_speed(rpm * math.pi / 30)
    model = Geometric(bearing, bearing.ball_mass * bearing.pitch_radius * w_c ** 2, "fit")
    x = np.asarray(pose, dtype=float)
    offsets, _, _ = model.solve_balls(x)
    length = bearing.pitch_radius
    steps = np.array([1e-8, 1e-8, 1e-8, 1e-8 / length, 1e-8 / length])
    condensed = model.race_jacobian(x, offsets, steps, length)
    resolved = _resolved_race_jacobian(model, x, steps, length)
    scale = np.abs(resolved).max()
    assert scale > 1e6  # N/m: some ball carries load
    np.testing.assert_allclose(condensed, resolved, atol=1e-5 * scale)


def test_a_warm_start_pose_gives_the_same_distribution():
    cold = solve_load_distribution(B, axial_force=400.0, radial_force=100.0, rpm=1800.0)
    near = np.concatenate([cold.displacement * 1.02, cold.tilt])
    warm = solve_load_distribution(B, axial_force=400.0, radial_force=100.0, rpm=1800.0, start_pose=near)
    np.testing.assert_allclose(warm.inner_load, cold.inner_load, rtol=0, atol=1e-8 * cold.max_load)
    np.testing.assert_allclose(warm.displacement, cold.displacement, rtol=0, atol=1e-12)
    assert warm.iterations < cold.iterations
    held = solve_load_distribution(B, axial_force=400.0, radial_force=100.0, rpm=1800.0,
                                   start_pose=(*cold.displacement, 1e-3, -1e-3))  # no moment: the tilt stays 0
    np.testing.assert_allclose(held.inner_load, cold.inner_load, rtol=0, atol=1e-8 * cold.max_load)
    assert np.all(held.tilt == 0.0)
    for bad in (dict(start_pose=(0.0, np.nan, 0.0)), dict(start_pose=(0.0, 0.0, 0.0), mode="fixed-angle"),
                dict(start_pose=(0.0, 0.0, 0.0), displacement=(0.0, 0.0, 1e-6))):
        with pytest.raises(ValueError, match="start_pose"):
            solve_load_distribution(B, axial_force=400.0, **bad)
