"""Isothermal Newtonian traction over the Hertz ellipse: the zero-slip slope of Crook's law
and the Newtonian law in closed form (MODEL.md §6, §10).  Pure numpy, vectorised over
contacts."""
from __future__ import annotations

import numpy as np

from .traction_law import Traction, _as_array, _gauss01, _lubricant_params

__all__ = ["newtonian_slope", "newtonian_traction"]


def newtonian_slope(a, b, p_max, h, lubricant, *, temperature=None):
    """Zero-slip traction slope ∬ η/h dA over the Hertz ellipse, N s/m (MODEL.md §6, §10).

    Closed form ∬ η dA = 2π a b η_T [(λ − 1) e^λ + 1]/λ², λ = c_ηP p_max,
    η_T = η0 exp(−c_ηT (T − T_R)) (η0 at T_R by default); a power series is used for
    λ < 0.5, so the limit π a b η_T at λ → 0 is exact.  Without spin and for |u| → 0,
    f = newtonian_slope · u.

    Parameters
    ----------
    a, b : array_like
        Semi-axes (transverse, rolling), m.
    p_max : array_like
        Peak Hertz pressure, Pa.
    h : array_like
        Film thickness, m (> 0).
    lubricant : contact.lubricant.Lubricant
    temperature : array_like, optional
        °C; T_R if omitted.

    Returns
    -------
    ndarray
        N s/m.
    """
    a = _as_array("a", a, nonneg=True)
    b = _as_array("b", b, nonneg=True)
    pm = _as_array("p_max", p_max, nonneg=True)
    hh = _as_array("h", h, positive=True)
    eta0, t_ref, c_p, c_t, _ = _lubricant_params(lubricant)
    eta_t = eta0
    if temperature is not None:
        eta_t = eta0 * np.exp(-c_t * (_as_array("temperature", temperature) - t_ref))
    lam = c_p * pm
    small = lam < 0.5
    ls = np.where(small, lam, 0.0)
    # [(λ−1)e^λ + 1]/λ² = Σ_{j≥0} λ^j (j+1)/(j+2)!
    series = np.zeros_like(ls)
    term = np.ones_like(ls)
    fact = 2.0
    for j in range(20):
        series = series + term * ((j + 1) / fact)
        term = term * ls
        fact *= j + 3
    ll = np.where(small, 1.0, lam)
    closed = ((ll - 1.0) * np.exp(ll) + 1.0) / (ll * ll)
    return 2.0 * np.pi * a * b * eta_t * np.where(small, series, closed) / hh


def _spin_integral(lam):
    """∫_0^1 ρ³ exp(λ √(1 − ρ²)) dρ = ∫_0^1 (s − s³) e^{λ s} ds (closed form; Gauss–Legendre
    below λ = 2 where the closed form cancels)."""
    lam = np.asarray(lam, dtype=float)
    small = lam < 2.0
    s, w = _gauss01(24)
    ls = np.where(small, lam, 0.0)
    quad = np.einsum("k,...k->...", w * (s - s ** 3), np.exp(ls[..., None] * s))
    ll = np.where(small, 2.0, lam)
    e = np.exp(ll)
    first = (e * (ll - 1.0) + 1.0) / ll ** 2
    third = e * (1.0 / ll - 3.0 / ll ** 2 + 6.0 / ll ** 3 - 6.0 / ll ** 4) + 6.0 / ll ** 4
    return np.where(small, quad, first - third)


def newtonian_traction(u_x, u_y, omega_s, a, b, p_max, h, lubricant, *, temperature=None):
    """Isothermal Newtonian traction (Crook's law without the thermal factor, MODEL.md §6):
    τ = η(p) u / h with the Barus viscosity; exact over the Hertz ellipse.

    By symmetry the slip and spin parts decouple: F = S0 u with S0 = ∬ η/h dA
    (:func:`newtonian_slope`), M_z = S2 ω_s with S2 = ∬ η/h (x² + y²) dA
    = π a b (a² + b²) η_T/h ∫_0^1 ρ³ e^{λ√(1−ρ²)} dρ, heat = S0 |u|² + S2 ω_s².  Valid only
    for small slip (it grows without bound); the scene option ``ContactLaw(traction=
    'newtonian')``.

    Returns
    -------
    Traction
        With the (diagonal) Jacobian diag(S0, S0, S2).
    """
    s0 = newtonian_slope(a, b, p_max, h, lubricant, temperature=temperature)
    eta0, t_ref, c_p, c_t, _ = _lubricant_params(lubricant)
    a = _as_array("a", a, nonneg=True)
    b = _as_array("b", b, nonneg=True)
    eta_t = eta0 if temperature is None else eta0 * np.exp(-c_t * (_as_array("temperature", temperature) - t_ref))
    s2 = np.pi * a * b * (a * a + b * b) * eta_t * _spin_integral(c_p * _as_array("p_max", p_max, nonneg=True)) \
        / _as_array("h", h, positive=True)
    ux, uy, om = (np.asarray(v, dtype=float) for v in (u_x, u_y, omega_s))
    fx, fy, mz = s0 * ux, s0 * uy, s2 * om
    jac = np.zeros(np.shape(fx) + (3, 3))
    jac[..., 0, 0] = jac[..., 1, 1] = s0
    jac[..., 2, 2] = s2
    return Traction(fx, fy, mz, s0 * (ux * ux + uy * uy) + s2 * om * om, jac)
