"""Elastic shear compliance of the EHD film (MODEL.md §6b), pure numpy.

In the high-pressure zone an EHD film behaves as a Maxwell fluid (Johnson & Tevaarwerk 1977):
(1/G) dτ/dt + τ/η_eff = γ̇, with d/dt = ū ∂/∂x for the oil carried through the contact at the
entrainment speed ū. Its elastic limit — the stress the film builds up by shearing
elastically from the inlet, where it enters unstressed — is, at a point (x, y),

    τ_e = G/(ū h) ∫_{x_in}^{x} u(x', y) dx' = G ξ/(ū h) (v_x, v_y − ω_s ξ/2),

with u(x, y) = (u_x − ω_s y, u_y + ω_s x) the local slip (P14), v = u(x, y), ξ = x − x_in and
x_in = −sign(ū) b √(1 − y²/a²) the inlet edge of the ellipse. Over a non-spinning contact it
integrates to f = (8/3) G a b² u/(ū h): a finite initial slope of the traction, where the
Newtonian film alone has ∬ η/h dA (near-infinite at 1–2 GPa: ../shared/STIFFNESS.md).

The elastic and viscous (Crook) responses act in series: the local stress magnitude is
|τ| = |τ_e| |τ_v| / (|τ_e| + |τ_v|), along the local slip as Crook's (so the heat τ·u stays
≥ 0 and the rules keep their τ = g u structure): g_eff = g / (1 + g |v| / |τ_e|). Where
|τ_e| ≫ |τ_v| (large slip, or slow entrainment) the law is Crook's; at small slip it is the
elastic film's. The limiting shear (§6a) caps the result.

This pointwise law approximates Johnson & Tevaarwerk's equation, which
:func:`maxwell_streamline` solves along the streamlines. Against that solution, with the
model's viscous law in it, the law is within −5.5 % to +2.4 % of the traction over
z = G L/(η ū) from 0.01 to 100 (two contacts, 1.0 and 1.7 GPa; ``benchmarks/film_maxwell.py``,
MODEL.md §6b). It is not the solution for a Newtonian film of constant properties, where the
equation gives τ_v (1 − e^(−r)), r = |τ_e|/τ_v, and the series form r/(1 + r) is up to 21 %
low in the transition; that exponential form, applied point by point to a real contact (the
viscosity rises e^(c_ηP p)-fold towards the centre, the thermal and limited law is nearly
plastic), was measured 25 % low there and is not used.

The modulus follows the pressure, G = κ p; κ is a lubricant input (MODEL.md §6b for its
provenance: τ_L/G → 1/(2π) with pressure, Proc. R. Soc. Lond. A 372 (1980) 155, gives the
default κ = 0.047 · 2π = 0.2953; Johnson & Roberts 1974 measured G = 0.1–1 GPa over 1–2 GPa
for a mineral oil).
"""
from __future__ import annotations

import numpy as np

__all__ = ["elastic_stress", "maxwell_streamline", "series_factor"]


def elastic_stress(x, y, a, b, v_x, v_y, omega_s, entrainment, h, modulus):
    """Magnitude of the film's elastic stress |τ_e| at the points (x, y), Pa (MODEL.md §6b).

    Parameters
    ----------
    x, y : array_like
        Points of the ellipse x²/b² + y²/a² ≤ 1, m (x rolling, y transverse).
    a, b : array_like
        Transverse and rolling semi-axes, m.
    v_x, v_y : array_like
        Local slip u(x, y) at the points, race minus ball, m/s.
    omega_s : array_like
        Spin, rad/s.
    entrainment : array_like
        Signed entrainment speed ū along +x, m/s; 0 gives an infinite elastic stress (the
        oil never leaves the contact: no elastic limit, the law is Crook's).
    h : array_like
        Film thickness, m.
    modulus : array_like
        Film shear modulus G at the points, Pa.
    """
    x, y, a, b = (np.asarray(v, dtype=float) for v in (x, y, a, b))
    u = np.asarray(entrainment, dtype=float)
    side = np.where(u < 0, -1.0, 1.0)
    x_in = -side * b * np.sqrt(np.maximum(1.0 - np.square(y / a), 0.0))
    xi = x - x_in
    ix = v_x
    iy = v_y - 0.5 * np.asarray(omega_s, dtype=float) * xi
    speed = np.abs(u)
    with np.errstate(divide="ignore", invalid="ignore"):
        stress = np.asarray(modulus, dtype=float) * np.abs(xi) * np.hypot(ix, iy) / (speed * h)
    return np.where(speed > 0, stress, np.inf)


def series_factor(g, slip, elastic):
    """g_eff / g for the series elastic–viscous film, 1 / (1 + g |v| / |τ_e|) (MODEL.md §6b).

    ``g`` is the viscous stress per unit slip (τ_v = g v), ``slip`` |v| (m/s), ``elastic``
    |τ_e| (Pa, may be inf). 0 where |τ_e| = 0 (the inlet edge) and the slip is not.
    """
    g = np.asarray(g, dtype=float)
    viscous = g * np.asarray(slip, dtype=float)
    elastic = np.asarray(elastic, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = elastic / (elastic + viscous)
    # 0/0 (no slip at the inlet edge): the stress is 0 either way; inf/inf: Crook's law
    return np.where(np.isfinite(elastic), np.where(elastic + viscous > 0, factor, 1.0), 1.0)


def maxwell_streamline(viscous, path, pressure, slip, entrainment, h, kappa, iterations=100):
    """Johnson & Tevaarwerk's Maxwell film solved along streamlines, the reference of MODEL.md
    §6b: (1/G) dτ/dt + s(τ)/h = v/h with d/dt = |ū| d/dx, i.e. (|ū| h/G) dτ/dx = v − s, where
    s is the viscous element's slip, τ = τ_v(s, p); G = κ p; τ = 0 at the inlet edge; no spin
    (the slip v is constant along a streamline).

    Backward Euler in the viscous slip s (monotone, solved by geometric bisection), first
    order in the step: use two step sizes and Richardson's extrapolation for a reference.

    Parameters
    ----------
    viscous : callable
        τ_v(s, p) ≥ 0, the viscous stress (Pa) at slip s (m/s) and pressure p (Pa),
        increasing in s where used; arrays of the streamlines' shape.
    path : array (K + 1, n)
        Distance along the flow from the inlet edge, m, from 0.
    pressure : array (K + 1, n)
        p at those points, Pa.
    slip, entrainment, h, kappa
        v (m/s), ū (m/s), film thickness (m), κ = G/p.

    Returns
    -------
    array (K + 1, n)
        τ along the streamlines, Pa.
    """
    path = np.asarray(path, dtype=float)
    pressure = np.asarray(pressure, dtype=float)
    tau = np.zeros_like(path)
    for k in range(1, path.shape[0]):
        kk = kappa * pressure[k] * (path[k] - path[k - 1]) / (abs(entrainment) * h)  # G Δx/(|ū| h)
        rhs = tau[k - 1] + kk * slip
        # s ≤ v + τ/kk (τ_v ≥ 0), unbounded at the outlet edge (kk → 0): bisect geometrically
        lo = np.full(path.shape[1:], 1e-30 * slip)
        hi = slip + tau[k - 1] / np.maximum(kk, 1e-300)
        for _ in range(iterations):
            mid = np.sqrt(lo * hi)
            below = viscous(mid, pressure[k]) + kk * mid < rhs
            lo = np.where(below, mid, lo)
            hi = np.where(below, hi, mid)
        tau[k] = viscous(0.5 * (lo + hi), pressure[k])
    return tau
