"""Crook thermal EHD traction integrated over the Hertz contact ellipse.

Implements MODEL.md §6 (paper P12–P16) with the quadrature asked for in MODEL.md §8
("Traction quadrature with spin").  Pure numpy; every function is vectorised over
contacts (arrays of shape ``(n,)`` or scalars, broadcast together).

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

Quadrature (MODEL.md §8)
------------------------
With spin the slip vanishes at the pole (x_p, y_p) = (−u_y/ω_s, u_x/ω_s).  Where the film
is thermally saturated (s ≫ 1) |τ| ∝ ln(ρ/ρ*)/ρ around it (ρ* = 1/(c1 |ω_s|), tens of µm at
1 GPa) and τ turns around it.  In the normalised coordinates X = x/b, Y = y/a (the ellipse
becomes the unit disc) this field is also very thin across the line through the pole
parallel to the long axis (width ≈ |x − x_p| b/a, the "ridge").  Tensor Gauss rules do
not resolve either.  The rule used here integrates along straight rays:

* origin at the pole if it lies inside the ellipse (mode P); chords of the cone of rays
  from the pole if it lies outside and the ridge crosses the ellipse (mode O); at the
  centre when there is no spin or neither the pole nor the ridge is sharp (mode C, also the
  best rule without spin).  "Sharp": width (thermal length, distance) < the long semi-axis;
* ray directions: a composite Gauss rule on panels whose ends are the directions where the
  integrand has near-singularities in the complex angle plane (P: the two tangent rays,
  the two ridge directions, the pressure peak; O: the ridge, the peak; C: the pole
  direction), each half-panel sinh-graded towards its end by the estimated distance of the
  singularity (sinh transform of Johnston & Elliott).  In mode O ψ = ψ_c + δ sin θ removes
  the √ behaviour at the tangent rays of the cone;
* along a ray two Gauss panels: [0, ρ_c] (sinh-graded towards the pole by ρ* in mode P)
  and [ρ_c, ρ_max] mapped by ρ = ρ_max − (ρ_max − ρ_c)(1 − t)², which makes the √ edge
  behaviour of p analytic (mode O: quadratic clustering at both chord ends).

The sharpness of the integrand also grows with λ = c_ηP p_max (viscosity peak, thermal
front where c1 |u| ≈ 1), so lightly loaded or nearly isothermal contacts use ½ or ¾ of the
requested order.  Contacts are grouped by (mode, order) and evaluated in numpy blocks of
≤ 8192 nodes; a contact's result does not depend on the other contacts of the call.
Measured against adaptive scipy integration the default order 16 gives relative errors
≤ 3e-4 (spin pole in or near 0.4–1.2 GPa contacts, 220 cases), order 24 ≤ 3e-5.

Fast rule (``fast=True``, for the dynamic model's right-hand side)
------------------------------------------------------------------
The accurate rule spends most of a 32-contact call in Python/numpy overhead (grouping,
chunking, per-group node construction).  The fast rule evaluates every contact of a call in
ONE fixed-size block, laid out (radial, direction, contact), in float32 (SIMD exp/log, half
the memory traffic; per-ray and per-contact sums in float64):

* origin of the rays: the spin pole when it is inside and sharp (mode P above), otherwise the
  centre (modes C and O; for the dynamic states rays from the centre beat the chords of O);
* 4·(n_main + n_other) directions: quarter panels between two "main" breakpoints θ0, θ0 + π
  (P: the ridge directions; C: towards and away from the pole) and two plain ones
  θ0 ± π/2, each half panel sinh-graded towards its breakpoint.  The gradings are taken
  from precomputed tables (the main breakpoints' ε rounded down to a factor 2^(1/8));
* 2·n_rad nodes per ray.  P: [0, 0.6 ρ_max] sinh-graded towards the pole by
  β = 0.85 asinh(0.6 √(ab)/ρ*(p_max)) (tabulated in steps of 0.1), [0.6 ρ_max, ρ_max] with
  ρ = ρ_max − 0.4 ρ_max (1 − t)².  C: Gauss in σ = p/p_max over [0, 1] (ρ dρ = σ dσ; the
  directions come in opposite pairs, so the integrand is smooth in σ);
* G(ψ) in float32 as log1p(z)/(s r), z = s + ψ/(1 + r), log1p(z) = log(1 + z) z/((1 + z) − 1);
  H = G'(s)/s from its power series below ψ = 1e-2;
* along a ray the slip is u = u_O + ω ρ (−a sin ψ, b cos ψ) (u_O the slip at the origin), so
  the forces, moment and heat need only ∑ g W ρ^j, j ≤ 2, per ray, and the Jacobian
  ∑ k W ρ^j, j ≤ 4.

:func:`fast_rule_size` gives the size per order (504 nodes per contact at the default 16).
Against the accurate rule at order 24–32, on the reference bearing's dynamic states (inner and
outer contacts 15–920 N, spin pole at the centre, inside, near the edge and outside, no
spin), the worst error relative to |f| + |M_z|/√(ab) is ≈ 6e-4 at order 16, 2e-4 at 20 and
1e-4 at 24; its Jacobian is within ≈ 2e-3 of the largest entry (≈ 1e-2 with the pole just
outside a heavily loaded contact).  Contacts with c_ηP p_max > 80 (40 with derivatives) are
beyond float32's range and use the accurate rule.  ``benchmarks/traction_speed.py`` tables
error against cost.
"""
from __future__ import annotations

import threading
from dataclasses import dataclass
from functools import lru_cache
from typing import Optional

import numpy as np

__all__ = ["Traction", "crook_traction", "newtonian_slope", "thermal_factor", "rule_size",
           "fast_rule_size"]

_TWO_PI = 2.0 * np.pi
_EPS_BIG = 1.0e3  # "no near-singularity" distance for the angular grading
_EPS_MIN = 1.0e-12
_FC = 0.6  # split of a ray from an interior origin (fraction of its length)
_KAPPA = 1.0  # pole/ridge "sharp" when its width < _KAPPA * long semi-axis
_CHUNK = 8192



@dataclass(frozen=True)
class Traction:
    """Result of :func:`crook_traction`; arrays have the broadcast input shape.

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
# Reference rules and 1-D building blocks
# ---------------------------------------------------------------------------------------
@lru_cache(maxsize=None)
def _gauss01(n: int):
    """Gauss–Legendre nodes and weights on [0, 1] (cached, read-only)."""
    x, w = np.polynomial.legendre.leggauss(n)
    x = 0.5 * (x + 1.0)
    w = 0.5 * w
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


@lru_cache(maxsize=None)
def _sizes(order: int):
    """(nodes per angular half-panel, nodes per radial panel)."""
    return max(2, (order + 1) // 2), max(3, (3 * order + 3) // 4)


def rule_size(order=16):
    """Largest number of quadrature nodes per contact used by :func:`crook_traction` at this
    order (rays from a pole: 10·⌈order/2⌉ directions × 2·⌈3·order/4⌉ radial nodes)."""
    n_ang, n_rad = _sizes(int(order))
    return 10 * n_ang * 2 * n_rad


def _graded(t, length, beta):
    """sinh map of t ∈ [0, 1] onto [0, length] graded towards 0 (β → 0: linear).

    Returns (offset, d offset / dt)."""
    beta = np.maximum(beta, 1e-8)  # sinh(βt)/sinh(β) = t (1 + O(β²)): linear to rounding
    inv_sb = length / np.sinh(beta)
    em1 = np.expm1(beta * t)  # sinh, cosh from one expm1, without cancellation
    inv_e = 1.0 / (em1 + 1.0)
    return (0.5 * inv_sb) * em1 * (1.0 + inv_e), (0.5 * beta * inv_sb) * (em1 + 1.0 + inv_e)


def _half_panels(start, end, e_start, e_end, n_ang):
    """Composite Gauss rule on panels [start, end] (arrays (n, K)); each panel is split in
    two halves sinh-graded towards their outer end, where a near-singularity sits at the
    imaginary distance e_start / e_end.  Returns nodes, weights of shape (n, 2 K n_ang)."""
    t, w = _gauss01(n_ang)
    half = 0.5 * (end - start)
    off_l, dl = _graded(t, half[..., None], np.arcsinh(half / e_start)[..., None])
    off_r, dr = _graded(t, half[..., None], np.arcsinh(half / e_end)[..., None])
    nodes = np.concatenate([start[..., None] + off_l, end[..., None] - off_r], -1)
    wt = np.concatenate([dl * w, dr * w], -1)
    n = start.shape[0]
    return nodes.reshape(n, -1), wt.reshape(n, -1)


def _effective_eps(bp, eps, period=None):
    """Distance from each break point to the nearest near-singularity of all the breaks."""
    d = np.abs(bp[..., :, None] - bp[..., None, :])
    if period is not None:
        d = np.minimum(d, period - d)
    return np.maximum(np.sqrt(eps[..., None, :] ** 2 + d ** 2).min(-1), _EPS_MIN)


def _periodic_nodes(bp, eps, n_ang):
    """Graded composite rule on the circle with breaks bp (n, K) of near-singularity
    distance eps (n, K).  Returns angles, weights of shape (n, 2 K n_ang)."""
    bp = np.mod(bp, _TWO_PI)
    order = np.argsort(bp, axis=-1)
    bp = np.take_along_axis(bp, order, -1)
    eps = np.take_along_axis(eps, order, -1)
    e_eff = _effective_eps(bp, eps, _TWO_PI)
    end = np.concatenate([bp[..., 1:], bp[..., :1] + _TWO_PI], -1)
    e_end = np.concatenate([e_eff[..., 1:], e_eff[..., :1]], -1)
    return _half_panels(bp, end, e_eff, e_end, n_ang)


def _interval_nodes(lo, hi, bp, eps, n_ang):
    """Graded composite rule on [lo, hi] with interior breaks bp (n, K)."""
    bp = np.clip(bp, lo[:, None], hi[:, None])
    order = np.argsort(bp, axis=-1)
    bp = np.take_along_axis(bp, order, -1)
    eps = np.take_along_axis(eps, order, -1)
    e_eff = _effective_eps(bp, eps)
    big = np.full_like(lo, _EPS_BIG)[:, None]
    start = np.concatenate([lo[:, None], bp], -1)
    end = np.concatenate([bp, hi[:, None]], -1)
    return _half_panels(start, end, np.concatenate([big, e_eff], -1),
                        np.concatenate([e_eff, big], -1), n_ang)


def _capped(e):
    return np.minimum(np.nan_to_num(e, nan=_EPS_BIG, posinf=_EPS_BIG), _EPS_BIG)


# ---------------------------------------------------------------------------------------
# Rays
# ---------------------------------------------------------------------------------------
@lru_cache(maxsize=None)
def _radial_patterns(n_rad):
    """Reference radial rule as column vectors (n_rad, 1) (cached, read-only): Gauss nodes t
    and weights w on [0, 1], and for the edge panels (1 − t)² and its weight 2 (1 − t) w."""
    t, w = _gauss01(n_rad)
    cols = (t[:, None], w[:, None], ((1.0 - t) ** 2)[:, None], (2.0 * (1.0 - t) * w)[:, None])
    for c in cols:
        c.setflags(write=False)
    return cols



def _ray_nodes_to_ellipse(a, b, xo, yo, rho, c, s, jac, wpsi, p, k):
    """Map ray nodes (distance rho along directions (c, s) from the normalized origin
    (xo, yo)) to ellipse coordinates x = b X, y = a Y and area weights a b rho |dJ| w."""
    x = (b * xo)[:, None, None] + rho * (b[:, None] * c)[:, None, :]
    y = (a * yo)[:, None, None] + rho * (a[:, None] * s)[:, None, :]
    rho *= jac
    rho *= ((a * b)[:, None] * wpsi)[:, None, :]
    return x.reshape(k, -1), y.reshape(k, -1), rho.reshape(k, -1), p.reshape(k, -1)


def _rays_inside(xo, yo, psi, wpsi, a, b, pm, rho_pole, n_rad, graded):
    """Rays from an origin (xo, yo) inside the unit disc: ρ ∈ [0, ρ_max(ψ)].

    Node arrays are laid out (k, 2 n_rad, Nt) (ray index innermost).  Returns x, y (m), W
    (area weights, m²) and p (Pa), each reshaped to (k, M)."""
    k, nt = psi.shape
    t, w, om, wb = _radial_patterns(n_rad)
    c, s = np.cos(psi), np.sin(psi)
    xo_ = xo[:, None]
    yo_ = yo[:, None]
    oe = xo_ * c + yo_ * s
    ox = xo_ * s - yo_ * c
    rho_2 = oe + np.sqrt(np.maximum(1.0 - ox * ox, 0.0))  # 1 − |O+ρe|² = (ρ_max − ρ)(ρ + ρ_2)
    rho_max = (1.0 - (xo * xo + yo * yo))[:, None] / rho_2
    rho_c = _FC * rho_max
    span = rho_max - rho_c
    shape = (k, 2 * n_rad, nt)
    rho = np.empty(shape)
    jac = np.empty(shape)
    gap = np.empty(shape)
    rc = rho_c[:, None, :]
    if graded:
        # sinh grading towards the pole by the thermal length (normalised units)
        q = np.sqrt((b[:, None] * c) ** 2 + (a[:, None] * s) ** 2)
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
            beta = np.arcsinh(rho_c * q / rho_pole[:, None])
        beta = np.nan_to_num(beta, nan=0.0, posinf=0.0)
        ra, da = _graded(t, rc, beta[:, None, :])
        rho[:, :n_rad] = ra
        jac[:, :n_rad] = da * w
    else:
        rho[:, :n_rad] = rc * t
        jac[:, :n_rad] = rc * w
    gap[:, :n_rad] = rho_max[:, None, :] - rho[:, :n_rad]
    gap[:, n_rad:] = span[:, None, :] * om
    rho[:, n_rad:] = rho_max[:, None, :] - gap[:, n_rad:]
    jac[:, n_rad:] = span[:, None, :] * wb
    gap *= rho + rho_2[:, None, :]  # 1 − X² − Y²
    p = np.sqrt(gap, out=gap)
    p *= pm[:, None, None]
    return _ray_nodes_to_ellipse(a, b, xo, yo, rho, c, s, jac, wpsi, p, k)


def _rays_outside(xo, yo, rp, psi_c, delta, theta, wth, a, b, pm, n_rad):
    """Chords of the rays from a pole outside the unit disc, ψ = ψ_c + δ sin θ
    (layout as :func:`_rays_inside`)."""
    k, nt = theta.shape
    sth = np.sin(theta)
    psi = psi_c[:, None] + delta[:, None] * sth
    wpsi = wth * delta[:, None] * np.cos(theta)
    c, s = np.cos(psi), np.sin(psi)
    mid = -(xo[:, None] * c + yo[:, None] * s)
    # half chord √(1 − r_p² sin²(δ sin θ)) written without cancellation at θ = ±π/2
    d = delta[:, None]
    one_m = 2.0 * np.sin(0.25 * np.pi - 0.5 * theta) ** 2  # 1 − sin θ
    one_p = 2.0 * np.sin(0.25 * np.pi + 0.5 * theta) ** 2  # 1 + sin θ
    hc2 = (rp * rp)[:, None] * 4.0 * (np.cos(0.5 * d * (1.0 + sth)) * np.sin(0.5 * d * one_m)
                                      * np.cos(0.5 * d * (1.0 - sth)) * np.sin(0.5 * d * one_p))
    hc = np.sqrt(np.maximum(hc2, 0.0))[:, None, :]
    # each half chord (edge → closest approach to the centre, where p peaks) like a ray of
    # mode C: a plain panel of 0.6 of its length at the middle, a panel with quadratic
    # clustering at the edge
    t, w, om, wb = _radial_patterns(n_rad)
    shape = (k, 4 * n_rad, nt)
    gap = np.empty(shape)  # distance to the nearer chord end
    sgn = np.empty(shape)
    jac = np.empty(shape)
    le = (1.0 - _FC) * hc  # edge panels
    li = _FC * hc  # inner panels
    n = n_rad
    gap[:, :n] = le * om[::-1]  # entry edge panel, ρ − ρ_1 = le t²  (t → 1 − t reversed)
    jac[:, :n] = le * wb[::-1]
    gap[:, n:2 * n] = le + li * t
    jac[:, n:2 * n] = li * w
    gap[:, 2 * n:3 * n] = le + li * t
    jac[:, 2 * n:3 * n] = li * w
    gap[:, 3 * n:] = le * om
    jac[:, 3 * n:] = le * wb
    sgn[:, :2 * n] = -1.0
    sgn[:, 2 * n:] = 1.0
    m = mid[:, None, :]
    rho = (m + sgn * hc) - sgn * gap
    p = np.sqrt(gap * (2.0 * hc - gap))  # √(1 − X² − Y²)
    p *= pm[:, None, None]
    return _ray_nodes_to_ellipse(a, b, xo, yo, rho, c, s, jac, wpsi, p, k)


# ---------------------------------------------------------------------------------------
# Quadrature rule for all contacts
# ---------------------------------------------------------------------------------------
def _analyse(ux, uy, om, a, b, pm, eta_t, c_p, c1_coef, force=None):
    """Per-contact choice of rule and its parameters (arrays of shape (n,)).

    Mode 0 (C): rays from the centre; 1 (P): rays from a pole inside; 2 (O): chords of the
    rays from a pole outside (see the module docstring)."""
    lo = np.minimum(a, b)
    hi = np.maximum(a, b)
    a_long = a >= b
    spin = om != 0.0
    om_s = np.where(spin, np.abs(om), 1.0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        Xp = -uy / np.where(spin, om, 1.0) / b
        Yp = ux / np.where(spin, om, 1.0) / a
    spin = spin & np.isfinite(Xp) & np.isfinite(Yp) & (np.abs(Xp) < 1e6) & (np.abs(Yp) < 1e6)
    Xp = np.where(spin, Xp, 0.0)
    Yp = np.where(spin, Yp, 0.0)
    rp2 = Xp * Xp + Yp * Yp
    rp = np.sqrt(rp2)
    inside = spin & (rp2 < 1.0 - 1e-12)
    outside = spin & ~inside

    def rstar(p):
        """Thermal length 1/(c1(p) |ω_s|), m (inf without spin)."""
        with np.errstate(over="ignore", divide="ignore"):
            r = 1.0 / (np.sqrt(eta_t * np.exp(c_p * p) * c1_coef) * om_s)
        return np.where(spin, np.minimum(r, 1e100), np.inf)

    rho_pole = rstar(pm * np.sqrt(np.maximum(1.0 - rp2, 0.0)))
    rho_peak = rstar(pm)
    # the "ridge": in normalised coordinates the saturated field |τ| ~ 1/|x − x_p| is thin
    # across the line through the pole parallel to the long axis
    ridge_c = np.where(a_long, Yp, Xp)
    cross_c = np.where(a_long, Xp, Yp)
    rho_ridge = rstar(pm * np.sqrt(np.maximum(1.0 - ridge_c ** 2, 0.0)))
    ridge_width = np.sqrt((lo * cross_c) ** 2 + rho_ridge ** 2)
    ridge_sharp = spin & (np.abs(ridge_c) < 1.0) & (ridge_width < _KAPPA * hi)
    mode_p = inside & ((rho_pole < _KAPPA * hi) | ridge_sharp)
    mode_o = outside & ridge_sharp
    if force == "centre":
        mode_p = mode_p & False
        mode_o = mode_o & False
    elif force == "pole":
        mode_p = inside
        mode_o = outside & (np.abs(ridge_c) < 1.0)

    psi_p = np.arctan2(Yp, Xp)
    sig_core = 1.0 / np.sqrt(np.maximum(c_p * pm, 1e-300))  # width of the viscosity peak
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # tangent rays from a pole near the edge
        eps_g = _capped(np.arcsinh(np.sqrt(np.maximum(1.0 - rp2, 0.0)) / rp))
        # ridge: seen from the pole |u|² has complex zeros near the short-axis directions
        reach = np.where(mode_o, rp + 1.0, 2.0)
        eps_t = _capped(np.arcsinh(np.sqrt((lo * lo + (rho_ridge / reach) ** 2)
                                           / np.maximum(hi * hi - lo * lo, 1e-300))))
        # pressure peak seen from the pole
        eps_k = _capped(sig_core / rp)
        # rays from the centre: towards the pole direction
        tan_stretch = np.sqrt((b * np.sin(psi_p)) ** 2 + (a * np.cos(psi_p)) ** 2)
        d_out = np.maximum(rp - 1.0, 0.0) * a * b / tan_stretch
        eps_c = _capped(np.where(inside, rho_pole / (rp * tan_stretch),
                                 np.sqrt(d_out ** 2 + rho_peak ** 2) / tan_stretch))
    with np.errstate(divide="ignore"):
        delta = np.arcsin(np.minimum(1.0 / np.where(outside, rp, 2.0), 1.0))  # cone half-angle
    return dict(mode=np.where(mode_p, 1, np.where(mode_o, 2, 0)), Xp=Xp, Yp=Yp, rp=rp,
                delta=delta, psi_p=psi_p, short_dir=np.where(a_long, 0.0, 0.5 * np.pi),
                rho_pole=rho_pole,
                eps_g=eps_g, eps_t=eps_t, eps_k=eps_k, eps_c=np.where(spin, eps_c, _EPS_BIG))


def _directions(mode, A, idx, n_ang):
    """Ray directions and their weights for the contacts idx, all of the given mode
    (angles ψ for modes C and P, θ of ψ = ψ_c + δ sin θ for mode O), (k, 10 n_ang)."""
    k = idx.size
    big = np.full(k, _EPS_BIG)
    pp = A["psi_p"][idx]
    if mode == 1:
        sd = A["short_dir"][idx]
        eg, et = A["eps_g"][idx], A["eps_t"][idx]
        bp = np.stack([pp + 0.5 * np.pi, pp - 0.5 * np.pi, sd, sd + np.pi, pp + np.pi], -1)
        ep = np.stack([eg, eg, et, et, A["eps_k"][idx]], -1)
        return _periodic_nodes(bp, ep, n_ang)
    if mode == 0:
        # four quarter panels starting at the pole direction (mirror-symmetric without spin)
        bp = pp[:, None] + 0.5 * np.pi * np.arange(4)[None, :]
        ep = np.stack([A["eps_c"][idx]] + [big] * 3, -1)
        return _periodic_nodes(bp, ep, n_ang)
    delta = A["delta"][idx]
    psi_c = pp + np.pi
    eps_t = A["eps_t"][idx]
    th_b = [np.zeros(k)]
    th_e = [_capped(A["eps_k"][idx] / delta)]
    for j, r_dir in enumerate((A["short_dir"][idx], A["short_dir"][idx] + np.pi)):
        dlt = np.mod(r_dir - psi_c + np.pi, _TWO_PI) - np.pi
        ok = np.abs(dlt) < delta
        th = np.arcsin(np.clip(dlt / delta, -1.0, 1.0))
        th_b.append(np.where(ok, th, (j - 0.5) * 0.5 * np.pi))
        with np.errstate(divide="ignore"):
            th_e.append(np.where(ok, _capped(eps_t / (delta * np.cos(th))), _EPS_BIG))
    th_b.append(np.full(k, 0.3 * np.pi))
    th_e.append(big)
    half_pi = np.full(k, 0.5 * np.pi)
    return _interval_nodes(-half_pi, half_pi, np.stack(th_b, -1), np.stack(th_e, -1), n_ang)


def _nodes(mode, A, idx, dirs, wdirs, a, b, pm, n_rad):
    """x, y (m), W (m²), p (Pa) at the nodes of the contacts idx (all of the given mode)."""
    if mode == 1:
        return _rays_inside(A["Xp"][idx], A["Yp"][idx], dirs, wdirs, a, b, pm,
                            A["rho_pole"][idx], n_rad, True)
    if mode == 0:
        zero = np.zeros(idx.size)
        return _rays_inside(zero, zero, dirs, wdirs, a, b, pm, None, n_rad, False)
    return _rays_outside(A["Xp"][idx], A["Yp"][idx], A["rp"][idx], A["psi_p"][idx] + np.pi,
                         A["delta"][idx], dirs, wdirs, a, b, pm, n_rad)


def _integrate(x, y, W, p, ux, uy, om, eta_t, inv_h, c_p, c1_coef, derivatives, lam_s):
    """Moments of the Crook stress over the nodes (node arrays (k, M), contact arrays (k,)).

    Returns (k, 4) [fx, fy, mz, heat] or, with derivatives, (k, 13) with the row-major
    3×3 Jacobian appended.  With τ = g u and u = (u_x − ω y, u_y + ω x):
    f = (u_x S0 − ω Sy, u_y S0 + ω Sx), M_z = u_y Sx − u_x Sy + ω Sr, S• = ∬ g (1, x, y, r²)."""
    eta = np.exp(c_p * p)
    eta *= eta_t[:, None]
    vx = ux[:, None] - om[:, None] * y
    vy = uy[:, None] + om[:, None] * x
    v2 = vx * vx
    v2 += vy * vy
    c12 = eta * c1_coef
    if derivatives:
        G, H = thermal_factor(c12 * v2, derivative=True)
    else:
        G = thermal_factor(c12 * v2)
    eta *= inv_h[:, None]  # η/h
    wg = eta * G  # g = η_m/h
    if derivatives:
        wk = eta * H
        wk *= c12  # ∂τ/∂u = g I + k u uᵀ
    if lam_s is not None:
        tau_l = lam_s * p
        vmag = np.sqrt(v2)
        cap = wg * vmag > tau_l
        if np.any(cap):
            vs = np.where(cap, vmag, 1.0)
            wg = np.where(cap, tau_l / vs, wg)
            if derivatives:
                wk = np.where(cap, -tau_l / (vs * vs * vs), wk)
    wg *= W
    s0 = wg.sum(-1)
    sx = _wsum(wg, x)
    sy = _wsum(wg, y)
    sr = _wsum(wg, x * x + y * y)
    out = np.empty((x.shape[0], 13 if derivatives else 4))
    out[:, 0] = ux * s0 - om * sy
    out[:, 1] = uy * s0 + om * sx
    out[:, 2] = uy * sx - ux * sy + om * sr
    out[:, 3] = _wsum(wg, v2)
    if derivatives:
        wk *= W
        d = x * vy - y * vx  # u · ∂u/∂ω_s
        wkx = wk * vx
        wky = wk * vy
        kxx = _wsum(wkx, vx)
        kxy = _wsum(wkx, vy)
        kyy = _wsum(wky, vy)
        kxd = _wsum(wkx, d)
        kyd = _wsum(wky, d)
        kdd = _wsum(wk * d, d)
        out[:, 4] = s0 + kxx
        out[:, 5] = kxy
        out[:, 6] = kxd - sy
        out[:, 7] = kxy
        out[:, 8] = s0 + kyy
        out[:, 9] = kyd + sx
        out[:, 10] = kxd - sy
        out[:, 11] = kyd + sx
        out[:, 12] = sr + kdd
    return out


# ---------------------------------------------------------------------------------------
# Fast rule (``crook_traction(..., fast=True)``): one fixed-size float32 block per call
# ---------------------------------------------------------------------------------------
_F32 = np.float32
_ONE = _F32(1.0)
_FAST_HP = 0.25 * np.pi  # half-panel length of the angular rule
_FAST_FC = 0.6  # split of a pole ray (fraction of its length)
_FAST_BFAC = 0.85  # radial grading β = 0.85 asinh(0.6 √(ab) / ρ*(p_max))
_FAST_EPS_CAP = 0.5 * np.pi  # angular near-singularity distance treated as "far"
_FAST_B0 = float(np.arcsinh(_FAST_HP / _FAST_EPS_CAP))
_FAST_EPS_STEPS = 8  # tabulated angular gradings ε = (π/2) 2^(−k/8), k < _FAST_N_EPS
_FAST_N_EPS = int(np.ceil(_FAST_EPS_STEPS * np.log2(_FAST_EPS_CAP / 1e-7))) + 1
_FAST_BETA_MIN = 0.3  # tabulated radial gradings: β = 0.3 + 0.1 k, k = 0 … _FAST_N_BETA − 1
_FAST_BETA_STEP = 0.1
_FAST_N_BETA = 120
_FAST_LEV_MAX = np.array([[_FAST_N_EPS - 1.0], [_FAST_N_BETA - 1.0]])
_FAST_PSI_MIN = _F32(1e-12)  # ψ floor: keeps (1 + z) − 1 > 0 in float32; G(ψ) unchanged
_FAST_H_PSI = _F32(1e-2)  # H from its series −4/3 + 32ψ/15 − 96ψ²/35 below this ψ
# float32 range: e^{λσ}, ψ and H stay normal numbers up to λ = c_ηP p_max ≈ 80 (forces) and
# 40 (Jacobian); beyond, the accurate rule is used (2.3 GPa for the reference oil)
_FAST_LAMBDA_MAX = (80.0, 40.0)


def fast_rule_size(order=16):
    """Size of the fast rule (``crook_traction(..., fast=True)``) at this order:
    (n_rad, n_main, n_other).  Every contact gets 4·(n_main + n_other) ray directions with
    2·n_rad radial nodes each (504 nodes at order 16)."""
    order = int(order)
    n_main = max(2, (order + 1) // 3)
    return max(3, (2 * order + 4) // 5), n_main, max(2, n_main - 1)


def _graded_half(t, w, beta):
    """Nodes and weights of a half panel [0, π/4] sinh-graded towards 0 (broadcasting)."""
    sb = np.sinh(beta)
    return _FAST_HP * np.sinh(beta * t) / sb, _FAST_HP * beta * np.cosh(beta * t) / sb * w


@lru_cache(maxsize=None)
def _fast_tables(order: int):
    """Reference tables of the fast rule (cached, read-only).

    psi, wpsi : (D, _FAST_N_EPS)  ray angles relative to θ0 and their weights, one column per
        tabulated grading of the two main breakpoints θ0, θ0 + π (the breakpoints θ0 ± π/2
        are graded with ε = π/2);
    rho, w : (R, _FAST_N_BETA + 1) ρ/ρ_max and ρ (dρ/dt) w/ρ_max² along a ray, one column per
        tabulated pole grading β (rays from a pole), the last column for rays from the centre
        (Gauss in σ = √(1 − ρ²): ρ dρ = σ dσ)."""
    nr, nm, no = fast_rule_size(order)
    R = 2 * nr
    D = 4 * (nm + no)
    eps = _FAST_EPS_CAP * 2.0 ** (-np.arange(_FAST_N_EPS) / _FAST_EPS_STEPS)
    t, w = _gauss01(nm)
    off, dof = _graded_half(t[:, None], w[:, None], np.arcsinh(_FAST_HP / eps)[None, :])
    t, w = _gauss01(no)
    off0, dof0 = _graded_half(t, w, _FAST_B0)
    other = np.concatenate([0.5 * np.pi + off0, 0.5 * np.pi - off0, 1.5 * np.pi + off0,
                            1.5 * np.pi - off0])
    psi = np.concatenate([off, -off, np.pi + off, np.pi - off,
                          np.repeat(other[:, None], _FAST_N_EPS, 1)])
    wpsi = np.concatenate([dof] * 4 + [np.repeat(np.tile(dof0, 4)[:, None], _FAST_N_EPS, 1)])
    # rays from a pole: [0, 0.6] sinh-graded (β), [0.6, 1] with ρ = 1 − 0.4 (1 − t)²
    t, w = _gauss01(nr)
    beta = _FAST_BETA_MIN + _FAST_BETA_STEP * np.arange(_FAST_N_BETA)
    sb = np.sinh(beta)
    fc, sp = _FAST_FC, 1.0 - _FAST_FC
    rho_in = fc * np.sinh(beta * t[:, None]) / sb
    w_in = rho_in * fc * beta * np.cosh(beta * t[:, None]) / sb * w[:, None]
    rho_out = np.repeat((1.0 - sp * (1.0 - t) ** 2)[:, None], _FAST_N_BETA, 1)
    w_out = rho_out * (sp * 2.0 * (1.0 - t) * w)[:, None]
    # rays from the centre: Gauss in σ on [0, 1] with R nodes
    ts, ws = _gauss01(R)
    rho = np.concatenate([np.vstack([rho_in, rho_out]), np.sqrt(1.0 - ts * ts)[:, None]], 1)
    wr = np.concatenate([np.vstack([w_in, w_out]), (ts * ws)[:, None]], 1)
    tab = dict(R=R, D=D, psi=psi, wpsi=wpsi, rho=rho.astype(_F32), w=wr.astype(_F32))
    for v in tab.values():
        if isinstance(v, np.ndarray):
            v.setflags(write=False)
    return tab


_FAST_WORK = threading.local()


def _fast_work(R, D, n):
    """Seven float32 work arrays (R, D, n), kept per thread and reused while the shape stays
    the same (fresh ~0.5 MB per call would cost page faults)."""
    key = (R, D, n)
    work = getattr(_FAST_WORK, "arrays", None)
    if work is None or work[0] != key:
        work = (key, tuple(np.empty(key, _F32) for _ in range(7)))
        _FAST_WORK.arrays = work
    return work[1]


def _fast_crook(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, order, derivatives, lam_s):
    """The fast rule for validated flat float64 arrays (n,).  Returns (4, n) [fx, fy, mz,
    heat] or, with derivatives, (13, n) with the row-major Jacobian appended.

    Nodes are laid out (R radial, D directions, n contacts), contacts innermost, so that
    per-ray arrays (D, n) broadcast over whole contiguous blocks."""
    n = ux.shape[0]
    lo = np.minimum(a, b)
    if lo.min() <= 0.0:  # unloaded contacts: zero
        res = np.zeros((13 if derivatives else 4, n))
        i = np.flatnonzero(lo > 0.0)
        if i.size:
            res[:, i] = _fast_crook(ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i], eta_t[i],
                                    c_p, c1_coef, order, derivatives, lam_s)
        return res
    if c_p * pm.max() > _FAST_LAMBDA_MAX[bool(derivatives)]:
        return _accurate_crook(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, order,
                               derivatives, lam_s).T.copy()
    tab = _fast_tables(order)
    R, D = tab["R"], tab["D"]

    # ---- per contact: pole, rule (as _analyse), gradings
    hi = np.maximum(a, b)
    a_long = a >= b
    ab = a * b
    lam = c_p * pm
    cth = c1_coef * eta_t  # c1² = cth e^{λσ}
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv_w = 1.0 / om
        Xp = uy * inv_w
        Xp /= -b  # pole, normalised (X = x/b, Y = y/a)
        Yp = ux * inv_w
        Yp /= a
        rp2 = Xp * Xp
        rp2 += Yp * Yp
        spin = rp2 < 1e12  # False without spin (NaN or inf)
        if not spin.all():
            Xp = np.where(spin, Xp, 0.0)
            Yp = np.where(spin, Yp, 0.0)
            rp2 = np.where(spin, rp2, 0.0)
        ridge = np.where(a_long, Yp, Xp)
        r2r = ridge * ridge
        # thermal lengths 1/(c1 |ω|) at the pole, the ridge line's middle and the peak
        tl3 = np.empty((3, n))
        np.subtract(1.0, rp2, out=tl3[0])
        np.subtract(1.0, r2r, out=tl3[1])
        tl3[2] = 1.0
        np.fmax(tl3, 0.0, out=tl3)
        np.sqrt(tl3, out=tl3)
        tl3 *= -0.5 * lam
        np.exp(tl3, out=tl3)
        tl3 *= 1.0 / np.sqrt(cth * (om * om))
        rho_pole, rho_ridge, rho_peak = tl3
        inside = rp2 < 1.0 - 1e-12
        lo2 = lo * lo
        hi2 = hi * hi
        rr2 = rho_ridge * rho_ridge
        mode_p = inside & ((rho_pole < hi)
                           | ((r2r < 1.0) & ((rp2 - r2r) * lo2 + rr2 < hi2)))
        allp = mode_p.all()
        # main breakpoints: P the ridge directions, C towards/away from the pole
        eps = np.arcsinh(np.sqrt((lo2 + 0.25 * rr2) / (hi2 - lo2)))
        th0 = 0.5 * np.pi * ~a_long
        if not allp:
            rp = np.sqrt(rp2)
            q = rp / np.sqrt((b * Yp) ** 2 + (a * Xp) ** 2)  # 1/(stretch of the pole direction)
            d_out = np.fmax(rp - 1.0, 0.0) * ab * q
            eps_c = np.sqrt(d_out * d_out + np.where(inside, rho_pole / rp, rho_peak) ** 2) * q
            eps = np.where(mode_p, eps, np.where(spin, eps_c, _FAST_EPS_CAP))
            th0 = np.where(mode_p, th0, np.arctan2(Yp, Xp))
        # table rows: angular grading ε rounded to (π/2) 2^(−k/8); radial grading towards the
        # pole by the thermal length at the peak pressure, β rounded to 0.3 + 0.1 k
        lev = np.empty((2, n))
        np.log2(eps, out=lev[0])
        lev[0] *= -_FAST_EPS_STEPS
        lev[0] += _FAST_EPS_STEPS * np.log2(_FAST_EPS_CAP)
        np.arcsinh(_FAST_FC * np.sqrt(ab) / rho_peak, out=lev[1])
        lev[1] *= _FAST_BFAC / _FAST_BETA_STEP
        lev[1] -= _FAST_BETA_MIN / _FAST_BETA_STEP
        np.rint(lev, out=lev)
        np.fmin(np.fmax(lev, 0.0, out=lev), _FAST_LEV_MAX, out=lev)  # NaN → 0
        lev, lr = lev.astype(np.intp)
    if allp:
        Xo, Yo, rO = Xp, Yp, 1.0 - rp2  # ray origin, 1 − |O|²
        uOx = uOy = np.zeros(n)  # slip at the origin
    else:
        lr[~mode_p] = _FAST_N_BETA  # rays from the centre
        Xo = Xp * mode_p
        Yo = Yp * mode_p
        rO = 1.0 - (Xo * Xo + Yo * Yo)
        not_p = ~mode_p
        uOx = ux * not_p
        uOy = uy * not_p

    # ---- rays (D, n): directions, then ρ_max forwards and ρ_2 backwards to the ellipse
    psi = np.take(tab["psi"], lev, axis=1)  # np.take: C-ordered result
    psi += th0
    psi = psi.astype(_F32)
    c = np.cos(psi)
    s = np.sin(psi)
    oe = c * Xo
    oe += s * Yo
    hc = oe * oe
    hc += rO
    np.sqrt(hc, out=hc)  # half chord
    rmax = hc - oe
    hc += oe
    r2 = hc.astype(_F32)
    rm = rmax.astype(_F32)
    bc = c * b.astype(_F32)  # ray direction, metres per unit ρ
    as_ = s * a.astype(_F32)
    q2 = bc * bc
    q2 += as_ * as_

    # ---- nodes (R, D, n): ρ, σ = p/p_max (work arrays reused between calls)
    rho, t, sg, sq, rt, z, d = _fast_work(R, D, n)
    pr = np.take(tab["rho"], lr, axis=1)  # (R, n)
    np.multiply(rm, pr[:, None, :], out=rho)
    np.subtract(rm, rho, out=t)
    np.add(rho, r2, out=sg)
    sg *= t  # 1 − X² − Y² = (ρ_max − ρ)(ρ + ρ_2)
    np.sqrt(sg, out=sg)
    lsig = None
    if c_p > 0.0:
        lrow = np.empty((D, n), _F32)
        lrow[...] = lam
        sg *= lrow  # λσ = c_ηP p
        if lam_s is not None:
            lsig = sg.copy()
        E = np.exp(sg, out=sg)  # η/η_T
    else:
        if lam_s is not None:
            lsig = sg.copy()
        sg[...] = _ONE
        E = sg
    # u2 = c1(η_T)² |u|² = A + ρ (B + C ρ) per ray
    np.multiply(rho, q2 * (om * om * cth).astype(_F32), out=t)
    if allp:
        t *= rho
        t += _FAST_PSI_MIN
    else:
        wc = 2.0 * om * cth
        Br = bc * (wc * uOy).astype(_F32)
        Br -= as_ * (wc * uOx).astype(_F32)
        t += Br
        t *= rho
        Ar = np.empty((D, n), _F32)
        Ar[...] = (uOx * uOx + uOy * uOy) * cth + 1e-12
        t += Ar
    u2 = t.copy() if lam_s is not None else None
    psi = t
    psi *= E  # ψ = c1² |u|²
    # G(ψ) = asinh(s)/(s r), s = √ψ, r = √(1 + ψ); asinh(s) = log1p(z), z = s + ψ/(1 + r),
    # log1p(z) = log(1 + z) z/((1 + z) − 1)
    np.sqrt(psi, out=sq)
    np.add(psi, _ONE, out=rt)
    np.sqrt(rt, out=rt)
    np.add(rt, _ONE, out=z)
    np.divide(psi, z, out=z)
    z += sq
    sq *= rt
    u1 = np.add(z, _ONE, out=rt)
    np.subtract(u1, _ONE, out=d)
    G = np.log(u1, out=u1)
    z /= d
    G *= z
    G /= sq
    if derivatives:
        # H = G'(s)/s = (1 − G (1 + 2ψ))/(ψ (1 + ψ)), its series −4/3 + 32ψ/15 − 96ψ²/35
        # for small ψ
        Hk = np.add(psi, psi, out=d)
        Hk += _ONE
        Hk *= G
        np.subtract(_ONE, Hk, out=Hk)
        Hk /= sq
        Hk /= sq  # (not sq²: no overflow)
        ser = z
        with np.errstate(over="ignore"):  # the series is used only where ψ < 1e-2
            np.multiply(psi, _F32(-96.0 / 35.0), out=ser)
            ser += _F32(32.0 / 15.0)
            ser *= psi
        ser -= _F32(4.0 / 3.0)
        Hk = np.where(psi < _FAST_H_PSI, ser, Hk)
        Hk *= E
        Hk *= E  # k h/(c1c η_T²), ∂τ/∂u = g I + k u uᵀ
    G *= E  # g h/η_T
    if lam_s is not None:
        # |τ| = g |u| ≤ Λ p;  here g h/η_T · c1(η_T)|u| ≤ Λ p h c1(η_T)/η_T, p = (λσ)/c_ηP
        vmag = np.sqrt(u2)
        scale = (1.0 / c_p) if c_p > 0.0 else pm
        tl = lsig * (lam_s * scale * hh * np.sqrt(cth) / eta_t).astype(_F32)
        cap = G * vmag > tl
        if cap.any():
            vs = np.where(cap, vmag, _ONE)
            G = np.where(cap, tl / vs, G)
            if derivatives:
                Hk = np.where(cap, -tl / (vs * vs * vs), Hk)

    # ---- sums: along each ray ∑ g W ρ^j (W = ρ_max² wψ × table), then over the rays
    npow = 5 if derivatives else 3
    pat = np.empty((npow, R, n), _F32)
    pat[0] = np.take(tab["w"], lr, axis=1)
    for j in range(1, npow):
        np.multiply(pat[j - 1], pr, out=pat[j])
    K = np.einsum("jrn,rdn->jdn", pat[:3], G)
    w0 = np.take(tab["wpsi"], lev, axis=1)
    w0 *= rmax
    w0 *= rmax * (ab * eta_t / hh)
    S0 = np.einsum("dn,dn->n", K[0], w0)  # ∬ g dA and ∬ g (x', y', x'² + y'²) dA
    w0 *= rmax
    K1 = K[1]
    K1 *= w0
    Sx = np.einsum("dn,dn->n", K1, bc)
    Sy = np.einsum("dn,dn->n", K1, as_)
    w0 *= rmax
    w0 *= q2
    Sr = np.einsum("dn,dn->n", K[2], w0)
    xo = Xo * b
    yo = Yo * a
    # τ = g u, u = u_O + ω (−y', x'):  f = u_O S0 + ω (−S'y, S'x)
    res = np.empty((13 if derivatives else 4, n))
    fx, fy, mz, heat = res[:4]
    np.multiply(om, Sy, out=fx)
    np.negative(fx, out=fx)
    np.multiply(om, Sx, out=fy)
    np.multiply(om, Sr, out=mz)
    np.multiply(om, mz, out=heat)
    if not allp:
        fx += uOx * S0
        fy += uOy * S0
        cross = uOy * Sx - uOx * Sy
        mz += cross
        heat += (uOx * uOx + uOy * uOy) * S0 + 2.0 * om * cross
    mz += xo * fy - yo * fx
    if derivatives:
        # ∂(f, M_z)/∂(u_x, u_y, ω_s) = ∬ g EᵀE + k v vᵀ dA, v = (u_x, u_y, x u_y − y u_x);
        # along a ray v = (uOx + dx ρ, uOy + dy ρ, p1 ρ + p2 ρ²) (x u_y − y u_x = 0 at the
        # origin: the pole, or the centre), so ∑ k v vᵀ needs V_j = ∑ k W ρ^j, j ≤ 4
        V = np.einsum("jrn,rdn->jdn", pat, Hk)
        wrow = np.take(tab["wpsi"], lev, axis=1)
        wrow *= rmax
        wrow *= rmax
        for j in range(5):
            V[j] *= wrow
            if j < 4:
                wrow *= rmax
        dx = as_ * -om
        dy = bc * om
        p1 = xo * dy - yo * dx + bc * uOy - as_ * uOx
        p2 = q2 * om
        V0, V1, V2, V3, V4 = V
        dx1 = dx * V1
        dy1 = dy * V1
        dx2 = dx * V2
        dy2 = dy * V2
        Q = p1 * V2 + p2 * V3
        A0 = V0.sum(0)
        A1x = dx1.sum(0)
        A1y = dy1.sum(0)
        Axx = np.einsum("dn,dn->n", dx, dx2)
        Axy = np.einsum("dn,dn->n", dx, dy2)
        Ayy = np.einsum("dn,dn->n", dy, dy2)
        B = np.einsum("dn,dn->n", p1, V1) + np.einsum("dn,dn->n", p2, V2)
        Cx = np.einsum("dn,dn->n", dx, Q)
        Cy = np.einsum("dn,dn->n", dy, Q)
        Czz = np.einsum("dn,dn->n", p1, Q) + np.einsum("dn,dn->n", p2, p1 * V3 + p2 * V4)
        kf = ab * eta_t / hh * c1_coef * eta_t
        J = res[4:].reshape(3, 3, n)
        J[0, 0] = (uOx * uOx * A0 + 2.0 * uOx * A1x + Axx) * kf + S0
        J[1, 1] = (uOy * uOy * A0 + 2.0 * uOy * A1y + Ayy) * kf + S0
        J[0, 1] = (uOx * uOy * A0 + uOx * A1y + uOy * A1x + Axy) * kf
        J[0, 2] = (uOx * B + Cx) * kf - (yo * S0 + Sy)
        J[1, 2] = (uOy * B + Cy) * kf + (xo * S0 + Sx)
        J[2, 2] = Czz * kf + (xo * xo + yo * yo) * S0 + 2.0 * (xo * Sx + yo * Sy) + Sr
        J[1, 0] = J[0, 1]
        J[2, 0] = J[0, 2]
        J[2, 1] = J[1, 2]
    return res


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


def _wsum(w, f):
    return np.einsum("ij,ij->i", w, f)


# ---------------------------------------------------------------------------------------
# Public API
# ---------------------------------------------------------------------------------------
def crook_traction(u_x, u_y, omega_s, a, b, p_max, h, lubricant, *, temperature=None,
                   order=16, derivatives=False, limiting_shear=None, fast=False) -> Traction:
    """Crook thermal EHD traction force and spin moment on the ball (MODEL.md §6, P12–P16).

    Integrates τ = η_m u / h over the Hertz ellipse x²/b² + y²/a² ≤ 1 with pressure
    p = p_max √(1 − x²/b² − y²/a²), viscosity η = η0 exp(c_ηP p − c_ηT (T − T_R)) (P11) and
    local slip u(x, y) = (u_x − ω_s y, u_y + ω_s x) (P14); η_m = η asinh(√ψ)/√(ψ(1+ψ)),
    ψ = η c_ηT |u|²/(8 K_c) (P12, P13).  The quadrature follows the spin pole (MODEL.md §8,
    "Traction quadrature with spin"); see the module docstring.

    Parameters
    ----------
    u_x, u_y : array_like
        Slip velocity at the contact centre, race surface minus ball surface, along t1
        (rolling) and t2 (transverse), m/s.
    omega_s : array_like
        Spin (ω_race − ω_ball)·n, rad/s.
    a, b : array_like
        Hertz semi-axes, m: ``a`` TRANSVERSE (y, across the groove), ``b`` rolling (x).
        A zero semi-axis (unloaded contact) gives zero traction.
    p_max : array_like
        Peak Hertz pressure, Pa (≥ 0).
    h : array_like
        Film thickness, m (> 0), constant over the ellipse (MODEL.md §5).
    lubricant : contact.lubricant.Lubricant
        η0 (Pa s), T_R (°C), c_ηP (1/Pa), c_ηT (1/K), K_c (W/(m K)).
    temperature : array_like, optional
        Film (wall) temperature, °C; T_R if omitted.
    order : int
        Quadrature order (≥ 4).  At most 10·⌈order/2⌉ ray directions with 2·⌈3·order/4⌉
        Gauss nodes each (:func:`rule_size`; 1920 nodes per contact for the default 16);
        contacts with c_ηP p_max ≲ 14 or negligible thermal softening use ¾ or ½ of the
        order.  The default gives relative errors ≤ 3e-4 in the hard cases (spin pole in or
        near a 1–1.2 GPa contact); errors fall roughly tenfold per +4 in order.
    derivatives : bool
        Also return ``jacobian`` = ∂(fx, fy, mz)/∂(u_x, u_y, ω_s), differentiated under the
        integral: ∂τ/∂u = (η/h)[G I + (G'(s)/s) c1² u uᵀ], ∂u/∂ω_s = (−y, x).
    limiting_shear : float, optional
        Λ (dimensionless, e.g. 0.08): caps |τ| at Λ p locally (MODEL.md §8 caveat);
        ``None`` (default) = off, as in the paper.
    fast : bool
        Use the fast rule meant for the dynamic model's right-hand side (module docstring,
        "Fast rule"): all contacts in one fixed-size float32 block, 4–5× cheaper per call
        for 32 contacts.  Same arguments and outputs; ``order`` sets its size
        (:func:`fast_rule_size`).  Worst error relative to |f| + |M_z|/√(ab) on the
        reference bearing's dynamic states ≈ 6e-4 at order 16 (the recommended order),
        2e-4 at 20, 1e-4 at 24; Jacobian within ≈ 1e-2 of its largest entry.

    Returns
    -------
    Traction
        ``fx``, ``fy`` (N), ``mz`` (N m), ``heat`` (W) of the broadcast input shape and, if
        requested, ``jacobian`` of that shape + (3, 3).

    Raises
    ------
    ValueError
        Non-finite input, negative a, b or p_max, non-positive h, bad order or Λ.
    """
    vals = (u_x, u_y, omega_s, a, b, p_max, h)
    flat = _quick_inputs(vals) if temperature is None else None
    if flat is None:
        ux = _as_array("u_x", u_x)
        uy = _as_array("u_y", u_y)
        om = _as_array("omega_s", omega_s)
        a = _as_array("a", a, nonneg=True)
        b = _as_array("b", b, nonneg=True)
        pm = _as_array("p_max", p_max, nonneg=True)
        hh = _as_array("h", h, positive=True)
    eta0, t_ref, c_p, c_t, k_c = _lubricant_params(lubricant)
    if flat is None:
        temp = (np.asarray(t_ref, dtype=float) if temperature is None
                else _as_array("temperature", temperature))
    if isinstance(order, (bool, np.bool_)) or not isinstance(order, (int, np.integer)) or order < 4:
        raise ValueError(f"order must be an integer >= 4, got {order!r}")
    order = int(order)
    lam_s = None
    if limiting_shear is not None:
        try:
            lam_s = float(limiting_shear)
        except (TypeError, ValueError):
            lam_s = float("nan")
        if not np.isfinite(lam_s) or lam_s <= 0:
            raise ValueError(f"limiting_shear must be a positive number, got {limiting_shear!r}")
    c1_coef = c_t / (8.0 * k_c)  # c1² = η c1_coef

    if flat is None:
        shape = np.broadcast_shapes(ux.shape, uy.shape, om.shape, a.shape, b.shape, pm.shape,
                                    hh.shape, temp.shape)
        ux, uy, om, a, b, pm, hh, temp = (np.broadcast_to(v, shape).reshape(-1)
                                          for v in (ux, uy, om, a, b, pm, hh, temp))
        eta_t = eta0 * np.exp(-c_t * (temp - t_ref))  # viscosity at ambient pressure, Pa s
    else:
        shape, (ux, uy, om, a, b, pm, hh) = flat
        eta_t = np.full(ux.shape[0], eta0)
    if fast:
        with np.errstate(over="ignore", invalid="ignore"):
            res = _fast_crook(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, order, derivatives,
                              lam_s)  # (4 or 13, n), rows contiguous
        bad = ~np.all(np.isfinite(res), axis=0)
        if bad.any():  # float32 overflow (extreme slip at high pressure): redo in float64
            i = np.flatnonzero(bad)
            res[:, i] = _accurate_crook(ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i], eta_t[i], c_p, c1_coef,
                                        order, derivatives, lam_s).T
    else:
        res = _accurate_crook(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, order,
                              derivatives, lam_s).T.copy()
    jac = res[4:].T.reshape(shape + (3, 3)) if derivatives else None
    return Traction(res[0].reshape(shape), res[1].reshape(shape), res[2].reshape(shape),
                    res[3].reshape(shape), jac)


def _quick_inputs(vals):
    """Validated flat float64 copies of (u_x, u_y, ω_s, a, b, p_max, h) and their shape when
    they all have one shape and pass every check, else None (the caller then checks them one
    by one, raising the documented errors).  A few numpy calls: this runs on every
    right-hand side of the dynamic model."""
    try:
        st = np.array(vals, dtype=float)
    except (TypeError, ValueError):  # ragged shapes or non-numeric
        return None
    shape = st.shape[1:]
    st = st.reshape(7, -1)
    if st.shape[1] == 0:
        return None
    total = float(st.sum())  # NaN or ±inf if any entry is
    lows = st[3:].min(axis=1)
    if not (total - total == 0.0 and lows[0] >= 0.0 and lows[1] >= 0.0 and lows[2] >= 0.0
            and lows[3] > 0.0):
        return None
    return shape, st


def _accurate_crook(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, order, derivatives, lam_s):
    """The accurate rule (module docstring) for validated flat arrays (n,)."""
    n = ux.shape[0]
    live = (a > 0) & (b > 0)
    a_s = np.where(live, a, 1.0)
    b_s = np.where(live, b, 1.0)

    A = _analyse(ux, uy, om, a_s, b_s, pm, eta_t, c_p, c1_coef)
    mode = A["mode"]
    # per-contact order: the integrand's features sharpen with λ = c_ηP p_max (the viscosity
    # peak and the thermal front where c1 |u| ≈ 1); lightly loaded or nearly isothermal
    # contacts need fewer nodes (three levels, so few evaluation groups)
    lam = c_p * pm
    with np.errstate(over="ignore"):
        s_max = (np.sqrt(eta_t * np.exp(lam) * c1_coef)
                 * (np.hypot(ux, uy) + np.abs(om) * np.maximum(a_s, b_s)))
    need = np.clip((lam + 6.0) / 24.0, 0.5, 1.0)
    need = np.where(s_max < 1e-2, 0.5, need)
    level = np.where(need <= 0.5, 0, np.where(need <= 0.75, 1, 2))
    orders = [max(4, -(-order * f // 4)) for f in (2, 3, 4)]  # ⌈order·(1/2, 3/4, 1)⌉
    inv_h = 1.0 / hh
    res = np.zeros((n, 13 if derivatives else 4))
    key = (mode * 3 + level) * live - (~live)
    for grp in np.unique(key):
        if grp < 0:
            continue
        m, lev = divmod(int(grp), 3)
        n_ang, n_rad = _sizes(orders[lev])
        # per half-panel direction counts: C has 8 half-panels, P and O 10; O has 4 radial
        # panels per ray (a chord crosses the pressure peak), C and P 2
        n_dir = (n_ang + 1, n_ang, n_ang)[m]
        nodes_per = (8 if m == 0 else 10) * n_dir * (4 if m == 2 else 2) * n_rad
        chunk = max(1, _CHUNK // nodes_per)
        idx_g = np.nonzero(key == grp)[0]
        dirs, wdirs = _directions(m, A, idx_g, n_dir)
        for i0 in range(0, idx_g.size, chunk):
            sl = slice(i0, i0 + chunk)
            idx = idx_g[sl]
            x, y, W, p = _nodes(m, A, idx, dirs[sl], wdirs[sl], a_s[idx], b_s[idx], pm[idx],
                                n_rad)
            res[idx] = _integrate(x, y, W, p, ux[idx], uy[idx], om[idx], eta_t[idx], inv_h[idx],
                                  c_p, c1_coef, derivatives, lam_s)
    return res


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
