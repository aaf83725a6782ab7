"""The film's elastic shear compliance (MODEL.md §6b) against closed forms."""
import numpy as np
import pytest

from contact.film_elasticity import elastic_stress, series_factor


def ellipse_nodes(a, b, n=200):
    """Gauss nodes and weights over x²/b² + y²/a² ≤ 1 (x = b r cos t, y = a r sin t)."""
    r, wr = np.polynomial.legendre.leggauss(n)
    r, wr = 0.5 * (r + 1), 0.5 * wr
    t = 2 * np.pi * (np.arange(4 * n) + 0.5) / (4 * n)
    R, T = np.meshgrid(r, t, indexing="ij")
    W = np.outer(wr * r, np.full(t.size, 2 * np.pi / t.size)) * a * b
    return b * R * np.cos(T), a * R * np.sin(T), W


@pytest.mark.parametrize("entrainment", [3.0, -2.0])
def test_elastic_traction_of_a_non_spinning_contact(entrainment):
    """No spin: τ_e = G ξ u/(|ū| h), ∬ ξ dA = (8/3) a b² (ξ from the inlet edge), so
    |f| = (8/3) G a b² |u| / (|ū| h) — STIFFNESS.md's elastic initial slope."""
    a, b, h, G = 1.4e-3, 0.2e-3, 0.3e-6, 1e9
    u = np.array([1e-3, -4e-4])
    x, y, W = ellipse_nodes(a, b)
    tau = elastic_stress(x, y, a, b, u[0], u[1], 0.0, entrainment, h, G)
    force = np.sum(W * tau)
    assert force == pytest.approx(8 / 3 * G * a * b ** 2 * np.hypot(*u) / (abs(entrainment) * h), rel=1e-6)


def test_stress_grows_from_the_inlet_edge():
    a, b = 1e-3, 0.5e-3
    x = np.linspace(-b, b, 5)
    tau = elastic_stress(x, 0.0, a, b, 1.0, 0.0, 0.0, 1.0, 1e-6, 1e9)  # inlet at x = -b for u > 0
    assert tau[0] == 0 and np.all(np.diff(tau) > 0)
    tau_rev = elastic_stress(x, 0.0, a, b, 1.0, 0.0, 0.0, -1.0, 1e-6, 1e9)  # inlet at +b
    assert tau_rev[-1] == 0 and np.allclose(tau_rev, tau[::-1])


def test_spin_term_is_the_integral_of_the_slip_field():
    """With spin, ∫ u dx' from the inlet at a point equals the closed form's vector."""
    a, b, om, ux, uy = 1e-3, 0.4e-3, 30.0, 2e-3, -1e-3
    x, y = 0.1e-3, 0.3e-3
    x_in = -b * np.sqrt(1 - (y / a) ** 2)
    s = np.linspace(x_in, x, 20001)
    def trapezoid(f):
        return float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(s)))

    vx = trapezoid(ux - om * y + 0 * s)
    vy = trapezoid(uy + om * s)
    expect = 1e9 * np.hypot(vx, vy) / (2.0 * 1e-6)
    got = elastic_stress(x, y, a, b, ux - om * y, uy + om * x, om, 2.0, 1e-6, 1e9)
    assert got == pytest.approx(expect, rel=1e-8)


def test_series_limits():
    g = np.array([1e12, 1e12, 1e12, 5.0])
    slip = np.array([1e-9, 1.0, 0.0, 1.0])
    elastic = np.array([1e9, 1e3, 0.0, np.inf])
    f = series_factor(g, slip, elastic)
    # small viscous stress: Crook; huge viscous stress: the elastic stress (|τ| = |τ_e|)
    assert f[0] == pytest.approx(1 / (1 + 1e12 * 1e-9 / 1e9))
    assert g[1] * slip[1] * f[1] == pytest.approx(1e3, rel=1e-6)
    assert f[2] == 1.0 and f[3] == 1.0
    assert np.all((f >= 0) & (f <= 1))
