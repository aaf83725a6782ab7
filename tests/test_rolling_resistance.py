"""Hydrodynamic rolling resistance and the thermal film factor (contact/rolling_resistance.py,
MODEL.md §11b, §11e) against the asymptotes and numbers their sources print."""
import math

import numpy as np
import pytest

from contact.rolling_resistance import hydrodynamic_rolling_force, rolling_resistance_moment
from contact.thermal_film import thermal_film_factor

E_PRIME = 2.26e11  # steel on steel, Pa
R_X, R_Y = 5.0e-3, 0.2  # a wide ellipse (R_y/R_x = 40)
ETA = 0.04


def _semi_axes(load):
    """Hertz semi-axes (a across, b along rolling) with Brewe–Hamrock's fits, m."""
    ratio = R_Y / R_X
    k = 1.0339 * ratio ** 0.6360
    first, second = 1.5277 + 0.6023 * math.log(ratio), 1.0003 + 0.5968 / ratio
    radius = 1 / (1 / R_X + 1 / R_Y)
    base = 6.0 * second * load * radius / (math.pi * E_PRIME)
    return np.cbrt(k * k * base), np.cbrt(base / k)


def _parameters(load, speed):
    a, b = _semi_axes(load)
    beta = 4 / math.pi * (1.0003 + 0.5968 * R_X / R_Y) / (1 + R_X / R_Y)
    u = 2 * ETA * speed / (E_PRIME * R_X)
    w = load / (E_PRIME * R_X ** 2)
    kappa = b / a
    return a, b, beta, u, w, kappa, beta ** 0.25 * kappa * w / u ** 0.75


@pytest.mark.parametrize("load, speed, regime", [(5e4, 0.05, "ehl"), (1e-2, 50.0, "ivr")])
def test_fit_approaches_its_asymptotes(load, speed, regime):
    """Biboulet & Houpert (2010) eq. 32 tends to their eq. 31: the EHL asymptote
    1.8 β^-1/4 (2a/R_x) U^3/4 at large Moes M and the IVR one 0.77 β^-1/3 κ^0.12 (2a/R_x) U^2/3
    at small M (times E' R_x²)."""
    a, b, beta, u, w, kappa, moes = _parameters(load, speed)
    got = hydrodynamic_rolling_force(load, speed, R_X, R_Y, a, b, E_PRIME, ETA)
    if regime == "ehl":
        assert moes > 1e3
        ref = E_PRIME * R_X ** 2 * 1.8 * beta ** -0.25 * (2 * a / R_X) * u ** 0.75
    else:
        assert moes < 1e-3
        ref = E_PRIME * R_X ** 2 * 0.77 * beta ** (-1 / 3) * kappa ** 0.12 * (2 * a / R_X) * u ** (2 / 3)
    assert float(got) == pytest.approx(ref, rel=0.02)


def test_against_houperts_earlier_ehl_fit():
    """In the EHL regime Houpert's earlier fit F = 1.544 β^1/3 κ^-0.577 U^0.656 W^0.466
    G^0.022 E' R_x² (Biboulet & Houpert's eq. 29) relates to theirs as their §3.4 prints:
    0.734 (κ/0.01)^0.09 (U/1e-11)^-0.094 (W/1e-5)^0.133 (G/4000)^0.022."""
    load, speed, g = 1000.0, 5.0, 4000.0
    a, b, beta, u, w, kappa, moes = _parameters(load, speed)
    assert moes > 100  # EHL
    houpert = E_PRIME * R_X ** 2 * 1.544 * beta ** (1 / 3) * kappa ** -0.577 * u ** 0.656 * w ** 0.466 * g ** 0.022
    got = float(hydrodynamic_rolling_force(load, speed, R_X, R_Y, a, b, E_PRIME, ETA))
    printed = 0.734 * (kappa / 0.01) ** 0.09 * (u / 1e-11) ** -0.094 * (w / 1e-5) ** 0.133 * (g / 4000) ** 0.022
    assert houpert / got == pytest.approx(printed, rel=0.05)


def test_no_force_without_load_or_rolling_and_truncation_only_lowers_it():
    a, b = _semi_axes(1000.0)
    f = hydrodynamic_rolling_force(np.array([0.0, 1000.0, 1000.0]), np.array([5.0, 0.0, 5.0]), R_X, R_Y,
                                   np.array([a, a, a]), np.array([b, b, b]), E_PRIME, ETA)
    assert f[0] == 0.0 and f[1] == 0.0 and f[2] > 0.0
    truncated = hydrodynamic_rolling_force(1000.0, 5.0, R_X, R_Y, a, b, E_PRIME, ETA, width=2.2 * a)
    assert 0.0 < truncated < f[2]
    far = hydrodynamic_rolling_force(1000.0, 5.0, R_X, R_Y, a, b, E_PRIME, ETA, width=1e3 * a)
    assert float(far) == pytest.approx(f[2], rel=1e-3)


def test_couple_dissipates_twice_force_times_rolling_speed():
    """In pure rolling R_x |w_rel| = u_m, and the couple's power M w_rel = -2 f u_m
    (Biboulet & Houpert part 1: the power lost is twice the rolling force times the speed)."""
    f, u_m = 3.0, 7.0
    w_rel = np.array([u_m / R_X, -u_m / R_X])
    moment = rolling_resistance_moment(f, R_X, w_rel)
    assert np.allclose(moment * w_rel, -2 * f * u_m, rtol=1e-9)


def test_thermal_factor():
    """Zhu & Cheng's φ_T: 1 at rest, falling with speed and with sliding, and by hand at
    L = 0.546, S = 0.01, p_H/E' = 0.0059 (a point of the fit's range in the 35-mm bearing's oil;
    its outer contact at 72 000 rpm has L 3.21, p_H/E' 0.0093, MODEL.md §11e)."""
    eta, c_t, k = 3.2e-3, 0.016, 0.15
    speed = math.sqrt(0.546 * k / (eta * c_t))
    p_h = 0.0059 * E_PRIME
    phi = thermal_film_factor(np.array([0.0, 0.5 * speed, speed, speed]), np.array([0.0, 0.0, 0.01 * speed, speed]),
                              p_h, E_PRIME, eta, c_t, k)
    by_hand = (1 - 13.2 * 0.0059 * 0.546 ** 0.42) / (1 + 0.213 * (1 + 2.23 * 0.01 ** 0.83) * 0.546 ** 0.64)
    assert phi[0] == 1.0
    assert phi[2] == pytest.approx(by_hand, rel=1e-9)
    assert 1.0 > phi[1] > phi[2] > phi[3] > 0.05


def test_rolling_force_rises_with_film_thickness():
    """A thicker film (higher viscosity or speed: h ~ (η u)^0.67) carries a larger rolling
    force at the same load, in both regimes."""
    a, b = _semi_axes(1000.0)
    speeds = np.array([0.1, 1.0, 10.0, 100.0])
    by_speed = hydrodynamic_rolling_force(np.full(4, 1000.0), speeds, R_X, R_Y, np.full(4, a), np.full(4, b),
                                          E_PRIME, ETA)
    by_viscosity = [float(hydrodynamic_rolling_force(1000.0, 1.0, R_X, R_Y, a, b, E_PRIME, eta))
                    for eta in (0.004, 0.04, 0.4)]
    assert np.all(np.diff(by_speed) > 0) and np.all(np.diff(by_viscosity) > 0)


def test_force_and_moment_on_the_ball_by_hand():
    """One inner contact of the reference bearing in near-pure rolling (2 mm/s of slip): the
    rolling resistance adds, against the same contact without it, a force f (2 R_x/r_b − 1)
    along the ball surface's motion t1 at the contact point and a moment −f r_b about the
    ball centre (−2 f R_x about the contact point); the film's shear f against each surface
    and its pressure 2 f R_x/r_b through the ball centre (Biboulet & Houpert 2010 part 1,
    eqs. 32–37; Bălan, Houpert et al. 2015). By hand: R_x from the ball and race radii in
    the rolling direction, f from the fit (tested above against its asymptotes)."""
    from contact.ballrace import ContactLaw, ball_race_forces
    from contact.kinematics import ball_race_kinematics
    from exudyn_bearing import REFERENCE_BEARING as B, REFERENCE_LUBRICANT as LUB
    from tests.helpers import INNER, R_I, TUBE_I, W_RACE, Z_I, _inner_contacts

    c, v, w = _inner_contacts((30e-6,), u_x=2e-3, u_y=0.0, spin=0.0)
    kin = ball_race_kinematics(c, v, w, np.zeros(3), np.eye(3), np.zeros(3), W_RACE, (R_I, Z_I, TUBE_I),
                               B.ball_radius, "inner")
    with_rr = ball_race_forces(kin, INNER, LUB, ContactLaw(rolling_resistance=True))
    without = ball_race_forces(kin, INNER, LUB, ContactLaw())
    r_b = B.ball_radius
    alpha = kin.contact_angle[0]
    race_radius = (B.pitch_diameter - B.ball_diameter * math.cos(alpha)) / (2 * math.cos(alpha))
    r_x = 1 / (1 / r_b + 1 / race_radius)
    a, b = INNER.hertz(alpha, ContactLaw().hertz_method)[1].semi_axes(with_rr.normal_load)
    r_y = 1 / (1 / r_b - 1 / (B.inner_conformity * B.ball_diameter))
    f = float(hydrodynamic_rolling_force(with_rr.normal_load, kin.entrainment, r_x, r_y, a, b, B.effective_modulus,
                                         LUB.viscosity, width=B.ball_diameter)[0])
    assert f > 0.05  # a force worth testing (N)
    sense = math.copysign(1.0, float(kin.rolling_rate[0]))
    d_force = with_rr.force[0] - without.force[0]
    d_moment = with_rr.moment[0] - without.moment[0]
    t1, t2, n = kin.rolling[0], kin.transverse[0], kin.normal[0]
    assert d_force @ t1 == pytest.approx(sense * f * (2 * r_x / r_b - 1), rel=1e-6)
    assert abs(d_force @ t2) < 1e-9 * f and abs(d_force @ n) < 1e-9 * f
    assert d_moment @ t2 == pytest.approx(-sense * f * r_b, rel=1e-6)
    # about the contact point p = c + r_b n: the couple −2 f R_x alone
    assert (d_moment - np.cross(r_b * n, d_force)) @ t2 == pytest.approx(-2 * sense * f * r_x, rel=1e-6)
    # along the entrainment: the surfaces' mean motion relative to the contact
    assert sense * kin.entrainment[0] > 0
