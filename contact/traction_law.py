"""The local shear law of the traction rules and what they share (MODEL.md §5, §6, §6a).

:mod:`contact.traction` integrates this law over the Hertz ellipse, by the accurate rule
(:mod:`contact.traction_accurate`) or the fast rule (:mod:`contact.traction_fast`); this
module holds the result type, Crook's thermal factor, the smooth limiting shear, the input
checks and the Gauss rule they all use.  Pure numpy.

Physics (MODEL.md §5–§6)
------------------------
At a point (x, y) of the ellipse x²/b² + y²/a² ≤ 1 (x rolling direction t1, y transverse
t2; ``a`` is the TRANSVERSE semi-axis, ``b`` the rolling one) the Hertz pressure is
p = p_max √(1 − x²/b² − y²/a²), the Barus viscosity η = η0 exp(c_ηP p − c_ηT (T − T_R))
(P11) and the local slip, race surface minus ball surface, u(x, y) = (u_x − ω_s y,
u_y + ω_s x) (P14).  Crook's thermal Couette solution (P12, P13) gives the shear stress

    τ = (η/h) G(s) u,   s = c1 |u|,   c1 = √(η c_ηT / (8 K_c)),
    G(s) = asinh(s) / (s √(1 + s²))        (η_m = η G, ψ = s²),

whose magnitude peaks at s ≈ 1.51 and then falls (thermal softening).  The traction on the
BALL is f = ∬ τ dA, its spin moment M_z = ∬ (x τ_y − y τ_x) dA (P15, P16) and the heat
∬ τ·u dA ≥ 0.

Limiting shear (MODEL.md §6a)
-----------------------------
No oil transmits more than a limiting shear stress τ_L = Λ p (pressure-limited shear, Bair
& Winer 1979).  :func:`limit_shear` blends it in smoothly,

    |τ| = τ_L tanh(|τ_C| / τ_L),   direction along the local slip unchanged,

so the law stays monotone in slip (Crook's falling branch goes) and equals Crook's where
|τ_C| ≪ τ_L; at the ellipse edge p → 0 and τ → 0.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Optional

import numpy as np

__all__ = ["Traction", "thermal_factor", "limit_shear"]


@dataclass(frozen=True)
class Traction:
    """Result of :func:`contact.traction.crook_traction`; arrays have the broadcast input shape.

    Attributes
    ----------
    fx, fy : ndarray
        Traction force on the BALL along t1 (rolling) and t2 (transverse), N.  It points
        along the race-minus-ball slip.
    mz : ndarray
        Spin moment on the ball about the contact normal n, N m (MODEL.md §6, P16).
    heat : ndarray
        Heat generated in the film, ∬ τ·u dA, W (≥ 0).
    jacobian : ndarray or None
        With ``derivatives=True``: shape (..., 3, 3), ∂(fx, fy, mz)/∂(u_x, u_y, ω_s): N s/m
        (force/slip), N s (force/spin and moment/slip), N m s (moment/spin).  It is
        symmetric (τ is the gradient of a dissipation potential in u).  ``None`` otherwise.
    """

    fx: np.ndarray
    fy: np.ndarray
    mz: np.ndarray
    heat: np.ndarray
    jacobian: Optional[np.ndarray] = None


# ---------------------------------------------------------------------------------------
# Crook's thermal factor
# ---------------------------------------------------------------------------------------
_SERIES_PSI = 1.0e-3
_N_SERIES = 8
# G = Σ (-1)^n c_n ψ^n, c_n = 4^n (n!)² / (2n+1)!  (converges for ψ < 1)
_C = [1.0]
for _n in range(_N_SERIES):
    _C.append(_C[-1] * 2.0 * (_n + 1) / (2.0 * _n + 3.0))
_H_COEF = np.array([2.0 * (-1.0) ** n * n * _C[n] for n in range(1, _N_SERIES + 1)])  # 2 dG/dψ


def thermal_factor(psi, derivative=False):
    """Crook's thermal factor G = η_m/η as a function of ψ = s² (MODEL.md §6, P13).

    G(ψ) = asinh(√ψ) / √(ψ (1 + ψ)), G(0) = 1 exactly: asinh is written with log1p, accurate
    down to s → 0 (no cancellation), and ψ is clamped at 1e-300 (no 0/0).  H, which cancels
    for small ψ, uses the power series 2 Σ (−1)^n n c_n ψ^(n−1), c_n = 4^n (n!)²/(2n+1)!,
    for ψ < 1e-3.

    Parameters
    ----------
    psi : array_like
        ψ = η c_ηT |u|² / (8 K_c) ≥ 0, dimensionless.
    derivative : bool
        Also return H = G'(s)/s = 2 dG/dψ (H(0) = −4/3).

    Returns
    -------
    G, or (G, H) : ndarray
    """
    psi = np.asarray(psi, dtype=float)
    shape = psi.shape
    psi = psi.reshape(-1)
    pl = np.maximum(psi, 1e-300)
    s = np.sqrt(pl)
    r = np.sqrt(1.0 + pl)
    sr = s * r
    # asinh(s) = log1p(s + s²/(1 + √(1 + s²))): accurate for every s ≥ 0, and G → 1 exactly
    g = np.log1p(s + pl / (1.0 + r))
    g /= sr
    if not derivative:
        return g.reshape(shape)
    h = (1.0 - g * (1.0 + 2.0 * pl)) / (sr * sr)
    small = psi < _SERIES_PSI  # cancellation in h: power series
    if np.any(small):
        h[small] = np.polynomial.polynomial.polyval(psi[small], _H_COEF)
    g, h = g.reshape(shape), h.reshape(shape)
    return (g, h) if derivative else g


# ---------------------------------------------------------------------------------------
# Smooth limiting shear (MODEL.md §6a)
# ---------------------------------------------------------------------------------------
_CAP_SERIES_X = 0.25  # below: (sech²x − tanh(x)/x)/x² from its series (the difference cancels)
# (sech²x − tanh(x)/x)/x² = Σ d_n x^(2n), |error| < 1e-13 relative for x < 0.25
_CAP_D = (-2.0 / 3.0, 8.0 / 15.0, -34.0 / 105.0, 496.0 / 2835.0, -2764.0 / 31185.0,
          87376.0 / 2027025.0, -1859138.0 / 91216125.0, 102473312.0 / 10854718875.0)


def limit_shear(g, v, tau_l, k=None):
    """Smooth limiting shear applied to a local law τ = g u (MODEL.md §6a).

    With the slip speed v = |u| and T_C = g v the unlimited stress magnitude, the limited
    law is T = τ_L tanh(T_C/τ_L) along u, i.e. τ = g' u with g' = g tanh(x)/x, x = T_C/τ_L.
    Its derivative, in the form ∂τ/∂u = g I + k u uᵀ (k = g'(v)/v), follows from
    T' = sech²x (g + v² k):

        k' = (T' v − T)/v³ = k sech²x + g (sech²x − tanh(x)/x)/v²,

    the last term written (sech²x − tanh(x)/x)/x² · g (g/τ_L)² for x < 0.25 (its series;
    v → 0 is finite).  τ_L = 0 (p = 0 at the ellipse edge) gives τ = 0 and k' = 0.  The
    formulas are homogeneous, so any consistent scaling of τ, u and τ_L may be used.  Works
    in the dtype of ``g`` (float64 or float32).

    Parameters
    ----------
    g : ndarray
        Unlimited coefficient, τ = g u (> 0).
    v : ndarray
        |u| (≥ 0).
    tau_l : ndarray
        τ_L = Λ p (≥ 0), in the units of g v.
    k : ndarray, optional
        Unlimited k of ∂τ/∂u = g I + k u uᵀ.

    Returns
    -------
    (g', k') : ndarrays (k' is None without ``k``)
    """
    live = tau_l > 0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        x = np.where(live, g * v / np.where(live, tau_l, 1), np.inf)  # T_C/τ_L
        phi = np.tanh(x)
        phi /= x
        phi = np.where(x > 0, phi, 1)  # tanh(x)/x; 0 at x = inf
        g_lim = g * phi
        if k is None:
            return g_lim, None
        c = np.cosh(x)
        sech2 = 1 / (c * c)  # 0 where cosh overflows
        y = x * x
        series = _CAP_D[-1] + 0 * y
        for d in _CAP_D[-2::-1]:
            series *= y
            series += d
        r = g / np.where(live, tau_l, 1)
        small = g * series * r * r
        big = g * (sech2 - phi) / (v * v)
        k_lim = np.where(live, k * sech2 + np.where(x < _CAP_SERIES_X, small, big), 0)
    return g_lim, k_lim


@lru_cache(maxsize=None)
def _gauss01(n: int):
    """Gauss–Legendre nodes and weights on [0, 1] (cached, read-only)."""
    x, w = np.polynomial.legendre.leggauss(n)
    x = 0.5 * (x + 1.0)
    w = 0.5 * w
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


# ---------------------------------------------------------------------------------------
# Input handling
# ---------------------------------------------------------------------------------------
def _as_array(name, value, nonneg=False, positive=False):
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be numeric, got {value!r}") from exc
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (got NaN or inf)")
    if positive and np.any(arr <= 0):
        raise ValueError(f"{name} must be positive")
    if nonneg and np.any(arr < 0):
        raise ValueError(f"{name} must be non-negative")
    return arr


def _lubricant_params(lubricant):
    try:
        return (float(lubricant.viscosity), float(lubricant.reference_temperature),
                float(lubricant.pressure_viscosity), float(lubricant.temperature_viscosity),
                float(lubricant.thermal_conductivity))
    except AttributeError as exc:
        raise ValueError("lubricant must provide viscosity, reference_temperature, "
                         "pressure_viscosity, temperature_viscosity and "
                         "thermal_conductivity (see contact.lubricant.Lubricant)") from exc
