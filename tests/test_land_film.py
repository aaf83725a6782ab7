"""The guiding land's short-bearing film (contact/land_film.py, MODEL.md §11d, eq. 11d.1)
against Reynolds' equation solved numerically over the whole land (finite differences in
both directions), and the land's refusal of bad input."""
import math

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import spsolve

from contact.land_film import film_constant, land_film_forces, short_bearing_force

MU, R, C = 0.01, 0.025, 100e-6  # Pa s, m, m


def reynolds_force(width, eps, eps_rate, whirl, w_journal, w_bearing, *, n_theta=360, n_z=21, region="clip"):
    """Force (x, y) on a journal displaced by e = ε c along +x, moving radially at ε̇ c and
    whirling at φ̇ (1/s), its surface and the bearing's turning at w_journal, w_bearing
    (rad/s, about +z): Reynolds' equation (h³ p_x)_x + (h³ p_z)_z = 6 μ (U1 + U2) h_x + 12 μ h_t
    by central differences, p = 0 at the land's edges, periodic around it. ``region``
    'clip': the half-Sommerfeld film (negative pressures dropped); 'pi': the pressure taken
    over the half from the thickest film onwards in the turning direction."""
    theta = np.arange(n_theta) * 2 * math.pi / n_theta
    z = np.linspace(-width / 2, width / 2, n_z)[1:-1]
    dx, dz = R * 2 * math.pi / n_theta, z[1] - z[0]
    e, e_dot, e_perp = eps * C, eps_rate * C, whirl * eps * C
    h = C - e * np.cos(theta)
    h_x = e * np.sin(theta) / R
    h_t = -e_dot * np.cos(theta) - e_perp * np.sin(theta)
    h_half = (C - e * np.cos(theta + math.pi / n_theta)) ** 3  # h³ at i + 1/2
    rows, cols, vals = [], [], []
    nz = len(z)

    def at(i, k):
        return (i % n_theta) * nz + k

    rhs = np.empty(n_theta * nz)
    for i in range(n_theta):
        hp, hm = h_half[i], h_half[i - 1]
        for k in range(nz):
            row = at(i, k)
            rows += [row, row, row]
            cols += [at(i + 1, k), at(i - 1, k), row]
            vals += [hp / dx ** 2, hm / dx ** 2, -(hp + hm) / dx ** 2 - 2 * h[i] ** 3 / dz ** 2]
            for kk in (k - 1, k + 1):
                if 0 <= kk < nz:
                    rows.append(row)
                    cols.append(at(i, kk))
                    vals.append(h[i] ** 3 / dz ** 2)
            rhs[row] = 6 * MU * R * (w_journal + w_bearing) * h_x[i] + 12 * MU * h_t[i]
    a = coo_matrix((vals, (rows, cols)), shape=(n_theta * nz, n_theta * nz)).tocsr()
    p = spsolve(a, rhs).reshape(n_theta, nz)
    if region == "clip":
        p = np.maximum(p, 0.0)
    else:  # θ from the thickest film (Θ = π here) in the turning direction
        sign = 1.0 if eps * (w_journal + w_bearing) - 2 * whirl * eps >= 0 else -1.0
        side = -np.sin(theta) * sign
        keep = np.where(np.abs(side) < 1e-12, 0.5, side > 0)  # trapezoid weights at the cut
        p = keep[:, None] * p
    line = p.sum(axis=1) * dz  # trapezoid: p = 0 at the edges
    return -np.array([np.sum(line * np.cos(theta)), np.sum(line * np.sin(theta))]) * R * 2 * math.pi / n_theta


def formula(width, eps, eps_rate, whirl, w_journal, w_bearing):
    k = film_constant(MU, R, width, C)
    f_r, f_t = short_bearing_force(eps, eps_rate, whirl * eps, w_journal + w_bearing, k, 0.999)
    return np.array([-f_r, f_t])


@pytest.mark.parametrize("eps", [0.3, 0.6, 0.85])
def test_steady_film_is_the_half_sommerfeld_solution_of_a_short_land(eps):
    """A short land (L/D = 0.05): Ocvirk's force against the numerical half-Sommerfeld
    solution within 2 % of its size, journal or bearing turning, and the classic attitude
    tan ψ = π √(1 − ε²) / (4 ε)."""
    width = 0.05 * 2 * R
    for w_j, w_b in ((1000.0, 0.0), (0.0, 1000.0), (600.0, -1400.0)):
        numeric = reynolds_force(width, eps, 0.0, 0.0, w_j, w_b)
        closed = formula(width, eps, 0.0, 0.0, w_j, w_b)
        assert np.linalg.norm(closed - numeric) < 0.02 * np.linalg.norm(numeric)
    f_r, f_t = -closed[0], closed[1]
    assert f_r > 0  # back towards the centre
    assert abs(f_t) / f_r == pytest.approx(math.pi * math.sqrt(1 - eps ** 2) / (4 * eps), rel=1e-12)


def test_whirl_and_squeeze_against_the_numerical_pi_film():
    """With whirl (ω_e = ω_j + ω_b − 2 φ̇, also past the sign change) and squeeze (ε̇ of either
    sign): the closed form against the numerical solution over the same π film, 2 %."""
    width = 0.05 * 2 * R
    for eps, rate, whirl, w_j in ((0.5, 0.0, 300.0, 1000.0), (0.5, 0.0, 800.0, 1000.0), (0.4, 200.0, 0.0, 1000.0),
                                  (0.7, -150.0, 100.0, 1000.0), (0.6, 300.0, 0.0, -500.0)):
        numeric = reynolds_force(width, eps, rate, whirl, w_j, 0.0, region="pi")
        closed = formula(width, eps, rate, whirl, w_j, 0.0)
        assert np.linalg.norm(closed - numeric) < 0.02 * np.linalg.norm(numeric), (eps, rate, whirl, closed, numeric)


def test_centred_film_damps_and_vector_form_turns_with_the_offset():
    """At e = 0 the film is a damper −K π ė / (2c); off centre the vector form is the scalar
    law turned to the offset's direction (any axis)."""
    k = 2e-4
    rate = np.array([[0.03, -0.01, 0.0]])
    f = land_film_forces(np.zeros((1, 3)), rate, np.array([[0.0, 0.0, 1.0]]), 1500.0, k, C)
    np.testing.assert_allclose(f, -k * math.pi / (2 * C) * rate, rtol=1e-12)
    rng = np.random.default_rng(3)
    axis = np.linalg.qr(rng.standard_normal((3, 3)))[0]
    n, t, a = axis[:, 0], axis[:, 1], np.cross(axis[:, 0], axis[:, 1])
    f = land_film_forces(0.4 * C * n[None], (0.01 * n + 0.02 * t)[None], a[None], 900.0, k, C)
    f_r, f_t = short_bearing_force(0.4, 0.01 / C, 0.02 / C, 900.0, k, 0.995)
    np.testing.assert_allclose(f[0], -f_r * n + f_t * t, rtol=1e-12, atol=1e-15)


def test_the_film_is_refused_a_wrong_switch():
    from exudyn_bearing import CageModel

    with pytest.raises(ValueError, match="land_film"):
        CageModel(land_width=5e-3, land_film="yes")


def test_the_seat_is_where_the_film_carries_the_pockets_force():
    """CageModel.land_seat with the film: the film's force there (no whirl, no squeeze) is
    minus the pockets' force (1e-9); a force beyond the film's reach seats the cage on its
    land; without the film, on its land as before."""
    from exudyn_bearing import CageModel, REFERENCE_BEARING, REFERENCE_LUBRICANT

    cage = CageModel(land_width=0.01)
    k = cage.land_film_constant(REFERENCE_BEARING, REFERENCE_LUBRICANT)
    play = 0.5 * cage.guide_clearance
    assert k == pytest.approx(REFERENCE_LUBRICANT.viscosity * cage.land_radius_for(REFERENCE_BEARING) * 0.01 ** 3
                              / play ** 2, rel=1e-12)
    spin = 80.0
    for force in (np.array([3.0, -4.0, 0.0]), np.array([0.0, 40.0, 0.0]), np.array([-0.2, 0.1, 0.0])):
        seat = cage.land_seat(force, k, spin)
        assert np.linalg.norm(seat) < play
        film = land_film_forces(seat[None], np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]), spin, k, play)[0]
        np.testing.assert_allclose(film, -force, rtol=0, atol=1e-9 * np.linalg.norm(force))
    huge = np.array([1e7, 0.0, 0.0])
    np.testing.assert_allclose(cage.land_seat(huge, k, spin), [play + 1e7 / cage.guide_stiffness, 0, 0], rtol=1e-12)
    np.testing.assert_allclose(cage.land_seat(np.array([3.0, -4.0, 0.0])),
                               np.array([0.6, -0.8, 0.0]) * (play + 5.0 / cage.guide_stiffness), rtol=1e-12)


def test_at_speed_the_film_holds_the_cage_inside_its_play():
    """35-mm bearing at 48 000 rpm, outer-guided cage on a 4-mm land (docs/high_speed): with
    the film's force its centre settles inside the play (ε 0.85 in docs/high_speed's 0.1-s
    run) and the energy balances; without it the cage rides its land past the play."""
    from exudyn_bearing import CageModel, ContactLaw, simulate
    from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG

    ratios = {}
    for film in (True, False):
        cage = CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3, land_film=film)
        run = simulate(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, axial_force=667.0, rpm=48000.0, time=0.06,
                       ball_drag=HIGH_SPEED_DRAG, contact_law=ContactLaw(rolling_resistance=True), cage=cage)
        res = run.results
        window = res.last(1 / 3)
        eps = res.cage_eccentricity[window] / 0.125e-3
        ratios[film] = eps
        if film:
            assert run.power_loss_W["total"] == pytest.approx(run.drive_power_W, rel=0.02)
    assert 0.5 < ratios[True].min() and ratios[True].max() < 0.95
    assert ratios[False].min() > 1.0
