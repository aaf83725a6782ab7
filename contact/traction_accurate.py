"""The accurate adaptive ray rule of :func:`contact.traction.crook_traction` (``fast=False``).

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
"""
from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple

import numpy as np

from .film_elasticity import compliance_factor, elastic_stress
from .traction_law import _gauss01, limit_shear, thermal_factor

__all__ = ["RuleParams", "rule_size"]


class RuleParams(NamedTuple):
    """What a traction rule needs besides the contacts' states (MODEL.md §6, §6a, §6b)."""

    c_p: float  #: c_ηP, 1/Pa
    c1_coef: float  #: c_ηT / (8 K_c), m/W: c1² = η c1_coef
    order: int  #: quadrature order
    derivatives: bool  #: also the Jacobian of (f_x, f_y, M_z) by (u_x, u_y, ω_s)
    lam_s: float | None  #: Λ of the smooth limiting shear; None: none
    elastic: tuple | None = None  #: (κ, ū (n,)) of the film's elastic compliance; None: none

_TWO_PI = 2.0 * np.pi
_EPS_BIG = 1.0e3  # "no near-singularity" distance for the angular grading
_EPS_MIN = 1.0e-12
_FC = 0.6  # split of a ray from an interior origin (fraction of its length)
_KAPPA = 1.0  # pole/ridge "sharp" when its width < _KAPPA * long semi-axis
_CHUNK = 8192


# ---------------------------------------------------------------------------------------
# 1-D building blocks
# ---------------------------------------------------------------------------------------
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


def _integrate(x, y, W, p, ux, uy, om, eta_t, inv_h, rule):
    """Moments of the Crook stress, smoothly limited to Λ p with ``lam_s`` = Λ (MODEL.md §6a),
    over the nodes (node arrays (k, M), contact arrays (k,)); ``elastic`` = (κ, a, b, ū) puts
    the film's elastic compliance G = κ p (MODEL.md §6b; no derivatives).

    Returns (k, 4) [fx, fy, mz, heat] or, with derivatives, (k, 13) with the row-major
    3×3 Jacobian appended.  With τ = g u and u = (u_x − ω y, u_y + ω x):
    f = (u_x S0 − ω Sy, u_y S0 + ω Sx), M_z = u_y Sx − u_x Sy + ω Sr, S• = ∬ g (1, x, y, r²)."""
    c_p, c1_coef, _, derivatives, lam_s, elastic = rule
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
    if elastic is not None:  # the Maxwell film's elastic compliance (MODEL.md §6b)
        kap, a, b, ent = elastic
        tau_e = elastic_stress(x, y, a[:, None], b[:, None], vx, vy, om[:, None], ent[:, None],
                               1.0 / inv_h[:, None], kap * p)
        wg = wg * compliance_factor(wg, np.sqrt(v2), tau_e)
    if lam_s is not None:  # |τ| = Λp tanh(|τ_C|/(Λp)) (MODEL.md §6a)
        wg, wk = limit_shear(wg, np.sqrt(v2), lam_s * p, wk if derivatives else None)
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


def _wsum(w, f):
    return np.einsum("ij,ij->i", w, f)


# ---------------------------------------------------------------------------------------
# All contacts of a call
# ---------------------------------------------------------------------------------------
def _accurate_crook(ux, uy, om, a, b, pm, hh, eta_t, rule):
    """The accurate rule (module docstring) for validated flat arrays (n,) with the
    :class:`RuleParams` ``rule``; its ``elastic`` = (κ, ū (n,)) adds the film's elastic
    compliance (MODEL.md §6b)."""
    c_p, c1_coef, order, derivatives, lam_s, elastic = rule
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
            el = None if elastic is None else (elastic[0], a_s[idx], b_s[idx], elastic[1][idx])
            res[idx] = _integrate(x, y, W, p, ux[idx], uy[idx], om[idx], eta_t[idx], inv_h[idx],
                                  rule._replace(elastic=el))
    return res
