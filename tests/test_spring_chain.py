"""The paper's spring-chain cage (P9, P10; contact.cage.spring_chain_forces and its compiled
twin): it holds the balls' angular spacing only."""
import math

import numpy as np
import pytest

from contact import kernels
from contact.cage import spring_chain_forces

Z, R_P, K = 16, 0.0775, 1e8
AXIS = np.array([0.0, 0.0, 1.0])
ORIGIN = np.array([0.01, -0.02, 0.3])  # a bearing away from the global origin


def _balls(psi, radius, z):
    return ORIGIN + np.stack([radius * np.cos(psi), radius * np.sin(psi), z], axis=1)


def _compiled(c):
    force, drag = np.empty((1, Z, 3)), np.empty((1, Z, 3))
    zeros = np.zeros((1, 3))
    params = kernels.CageRecord(2, 2 * np.pi * np.arange(Z) / Z, R_P, 0.0, K, 0.0, AXIS, ORIGIN, 0.0)
    cage = kernels.BodyStates(zeros, np.eye(3)[None], zeros, zeros)
    kernels.cage_and_drag(c[None], np.zeros((1, Z, 3)), params, cage, force, drag)
    return force[0]


def test_no_force_at_even_spacing_whatever_the_orbit_radius():
    """Balls 27-98 um outside r_p (as under centrifugal load) and axially offset: a chord
    spring would pull each inward by hundreds of newtons; the chain must not."""
    rng = np.random.default_rng(1)
    c = _balls(2 * np.pi * np.arange(Z) / Z + 0.3, R_P + rng.uniform(27e-6, 98e-6, Z), rng.normal(0, 1e-4, Z))
    for force in (spring_chain_forces(c, AXIS, R_P, K, ORIGIN), _compiled(c)):
        assert np.abs(force).max() < 1e-6


def test_forces_are_circumferential_with_no_net_moment():
    rng = np.random.default_rng(2)
    psi = 2 * np.pi * np.arange(Z) / Z + rng.normal(0, 1e-4, Z)
    radius = R_P + rng.uniform(0, 1e-4, Z)
    c = _balls(psi, radius, rng.normal(0, 1e-4, Z))
    force = spring_chain_forces(c, AXIS, R_P, K, ORIGIN)
    np.testing.assert_allclose(_compiled(c), force, rtol=0, atol=1e-9 * np.abs(force).max())
    e_r = np.stack([np.cos(psi), np.sin(psi), np.zeros(Z)], axis=1)
    assert np.abs(np.einsum("ij,ij->i", force, e_r)).max() < 1e-9 * np.abs(force).max()
    assert np.abs(force[:, 2]).max() == 0.0
    moment = np.cross(c - ORIGIN, force)[:, 2].sum()
    assert abs(moment) < 1e-12 * np.abs(force).max() * R_P


def test_one_ball_displaced_is_pulled_back_by_both_springs():
    """Ball 0 advanced by d psi: both neighbouring springs act on it, F = -2 k r_p² d psi / r
    along its circumferential direction; its neighbours get k r_p² d psi / r each."""
    dpsi = 1e-5
    psi = 2 * np.pi * np.arange(Z) / Z
    psi[0] += dpsi
    radius = np.full(Z, R_P + 5e-5)
    force = spring_chain_forces(_balls(psi, radius, np.zeros(Z)), AXIS, R_P, K, ORIGIN)
    e_psi = np.stack([-np.sin(psi), np.cos(psi), np.zeros(Z)], axis=1)
    tangential = np.einsum("ij,ij->i", force, e_psi)
    expected = K * R_P ** 2 * dpsi / radius[0]
    assert tangential[0] == pytest.approx(-2 * expected, rel=1e-6)
    assert tangential[1] == pytest.approx(expected, rel=1e-6) and tangential[-1] == pytest.approx(expected, rel=1e-6)
    assert np.abs(tangential[2:-1]).max() < 1e-9 * expected
    assert math.isclose(K * R_P * dpsi * R_P / radius[0], expected)
