"""The lighter traction models a scene can choose instead of Crook's (issue 5):
isothermal Newtonian and regularized Coulomb, against closed forms and quadrature."""
import dataclasses
import math

import numpy as np
import pytest
from scipy import integrate

from contact.friction import coulomb_traction
from contact.lubricant import REFERENCE_LUBRICANT
from contact.traction import _spin_integral, crook_traction, newtonian_traction

A, B, H = 4e-4, 1.5e-4, 2e-7


@pytest.mark.parametrize("lam", [0.0, 0.3, 1.9, 2.1, 10.0, 35.0])
def test_spin_integral_matches_quadrature(lam):
    expected = integrate.quad(lambda r: r ** 3 * math.exp(lam * math.sqrt(1 - r * r)), 0, 1, epsabs=0,
                              epsrel=1e-12)[0]
    assert _spin_integral(lam) == pytest.approx(expected, rel=1e-9)


def test_newtonian_constant_viscosity_closed_form():
    lub = dataclasses.replace(REFERENCE_LUBRICANT, pressure_viscosity=0.0)
    eta = lub.viscosity
    tr = newtonian_traction(0.01, -0.02, 3.0, A, B, 1e9, H, lub)
    s0 = math.pi * A * B * eta / H
    assert tr.fx == pytest.approx(s0 * 0.01, rel=1e-12) and tr.fy == pytest.approx(-s0 * 0.02, rel=1e-12)
    assert tr.mz == pytest.approx(math.pi * A * B * (A * A + B * B) / 4 * eta / H * 3.0, rel=1e-12)
    assert tr.heat == pytest.approx(tr.fx * 0.01 + tr.fy * -0.02 + tr.mz * 3.0, rel=1e-12)


def test_newtonian_is_crooks_small_slip_limit():
    """Pure slip and pure spin, tiny: Crook's thermal factor -> 1."""
    p = 0.8e9
    slip = crook_traction(1e-9, 0.0, 0.0, A, B, p, H, REFERENCE_LUBRICANT, fast=False).fx
    assert newtonian_traction(1e-9, 0.0, 0.0, A, B, p, H, REFERENCE_LUBRICANT).fx == pytest.approx(slip, rel=1e-4)
    spin = crook_traction(0.0, 0.0, 1e-6, A, B, p, H, REFERENCE_LUBRICANT, fast=False).mz
    assert newtonian_traction(0.0, 0.0, 1e-6, A, B, p, H, REFERENCE_LUBRICANT).mz == pytest.approx(spin, rel=1e-4)


def test_coulomb_limits_and_pivoting_moment():
    q, mu = 200.0, 0.06
    big = coulomb_traction(3.0, 4.0, 0.0, A, B, q, mu)
    assert math.hypot(big.fx, big.fy) == pytest.approx(mu * q, rel=1e-6)
    assert big.fx / big.fy == pytest.approx(0.75)  # along the slip
    assert coulomb_traction(0.0, 0.0, 0.0, A, B, q, mu).fx == 0.0
    # fully pivoting circle of radius c: M = ∬ mu p r dA with Hertz p, Q = 2/3 pi c² p0
    c = math.sqrt(A * B)
    p0 = 1.5 * q / (math.pi * c * c)
    m_exact = integrate.quad(lambda r: mu * p0 * math.sqrt(1 - (r / c) ** 2) * r * 2 * math.pi * r, 0, c)[0]
    spin = coulomb_traction(0.0, 0.0, 1e6, A, B, q, mu)
    assert spin.mz == pytest.approx(m_exact, rel=1e-6)
    assert coulomb_traction(0.0, 0.0, -1e6, A, B, q, mu).mz == pytest.approx(-m_exact, rel=1e-6)
    with pytest.raises(ValueError, match="friction_coefficient"):
        coulomb_traction(0.0, 0.0, 0.0, A, B, q, -1.0)
