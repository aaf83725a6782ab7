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

The elastic and viscous (Crook) responses are combined as the Maxwell equation combines them
for constant properties: |τ| = τ_v (1 − e^(−|τ_e|/τ_v)), along the local slip as Crook's (so
the heat τ·u stays ≥ 0 and the rules keep their τ = g u structure): g_eff = g (1 − e^(−1/R)),
R = g |v| / |τ_e| (:func:`compliance_factor`). Where |τ_e| ≫ |τ_v| (large slip, or slow
entrainment) the law is Crook's; at small slip it is the elastic film's. The limiting shear
(§6a) caps the result.

This pointwise law approximates Johnson & Tevaarwerk's equation, which
:func:`maxwell_streamline` solves along the streamlines and :func:`maxwell_traction` over
whole contacts with spin. Against them, with the model's viscous law in it: −3.0 % in the
transition, +8.7 % at the worst small z (the initial slope, 1.0-GPa contact), over
z = G L/(η ū) from 0.01 to 100 (``benchmarks/film_maxwell.py``); 0.15–1 % of the force at the
reference bearing's own contacts near its skid threshold, where the series form
|τ_e||τ_v|/(|τ_e| + |τ_v|) used before was 1.6–4 % off (``benchmarks/film_maxwell_contacts.py``,
MODEL.md §6b).

The modulus follows the pressure, G = κ p; κ is a lubricant input (MODEL.md §6b for its
provenance: τ_L/G → 1/(2π) with pressure, Proc. R. Soc. Lond. A 372 (1980) 155, gives the
default κ = 0.047 · 2π = 0.2953; Johnson & Roberts 1974 measured G = 0.1–1 GPa over 1–2 GPa
for a mineral oil).
"""
from __future__ import annotations

import numpy as np

from .traction_law import Traction, limit_shear, thermal_factor

__all__ = ["compliance_factor", "crook_viscous", "elastic_stress", "maxwell_streamline", "maxwell_traction"]


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


def compliance_factor(g, slip, elastic):
    """g_eff / g of the Maxwell film, 1 − e^(−|τ_e|/τ_v), τ_v = g |v| (MODEL.md §6b).

    ``g`` is the viscous stress per unit slip (τ_v = g v), ``slip`` |v| (m/s), ``elastic``
    |τ_e| (Pa, may be inf). 1 where |τ_e| is infinite (no elastic limit) or the slip is 0 (no
    stress either way); 0 where |τ_e| = 0 (the inlet edge) and the slip is not.
    """
    viscous = np.asarray(g, dtype=float) * np.asarray(slip, dtype=float)
    elastic = np.asarray(elastic, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = elastic / viscous
    return np.where(np.isnan(ratio), 1.0, -np.expm1(-ratio))


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


def crook_viscous(lubricant, h, limiting_shear=None):
    """The viscous element of the Maxwell film: the (limited) Crook stress τ_v(s, p) and its
    slope dτ_v/ds at slip s (m/s) and pressure p (Pa), arrays of shape (n, m) for n contacts of
    film ``h`` (n,) m (MODEL.md §6, §6a; :func:`contact.traction_law.thermal_factor` and
    :func:`~contact.traction_law.limit_shear`, the law of the traction rules)."""
    eta0, c_p = float(lubricant.viscosity), float(lubricant.pressure_viscosity)
    c1_coef = float(lubricant.temperature_viscosity) / (8.0 * float(lubricant.thermal_conductivity))
    inv_h = 1.0 / np.asarray(h, dtype=float)[:, None]

    def viscous(s, p):
        eta = eta0 * np.exp(c_p * p)
        c12 = eta * c1_coef
        g, k = thermal_factor(c12 * s * s, derivative=True)
        g = g * eta * inv_h
        k = k * eta * inv_h * c12  # dτ/ds = g + k s²
        if limiting_shear is not None:
            g, k = limit_shear(g, s, limiting_shear * p, k)
        return g * s, g + k * s * s

    return viscous


def maxwell_traction(u_x, u_y, omega_s, a, b, p_max, h, entrainment, viscous, kappa, lines=48, steps=400):
    """Johnson & Tevaarwerk's Maxwell film solved over whole contacts, with spin: the reference
    of MODEL.md §6b for the pointwise laws at a bearing's own contacts.

    Along each streamline (|ū| h/G) dτ/dx = v(x) − s, τ = τ_v(|s|, p) s/|s|, G = κ p, τ = 0 at
    the inlet edge, where v = (u_x − ω_s y, u_y + ω_s x) is the local slip (P14), which spin
    turns along the streamline. Backward Euler: τ_k + k_k s_k = τ_(k−1) + k_k v_k with
    k_k = G Δx/(|ū| h), so s_k is parallel to the right side and its magnitude solves the
    scalar τ_v(s) + k_k s = |τ_(k−1) + k_k v_k| (safeguarded Newton, bracketed). Streamlines at
    the Gauss–Legendre points of y ∈ (−a, a); along each x = ±c sin θ, θ uniform (steps
    cluster at both edges); ``steps`` and ``steps``/2 combined by Richardson's extrapolation
    (first order in the step).

    Parameters
    ----------
    u_x, u_y, omega_s, a, b, p_max, h, entrainment : array_like (n,)
        Slip at the centre (m/s), spin (rad/s), transverse and rolling semi-axes (m), peak
        pressure (Pa), film (m) and signed entrainment speed along x (m/s, ≠ 0), as
        :func:`contact.traction.crook_traction`.
    viscous : callable
        ``viscous(s, p)`` → (τ_v, dτ_v/ds) for arrays (n, lines), e.g. :func:`crook_viscous`.
    kappa : float
        κ = G/p.
    lines, steps : int
        Streamlines and θ steps per streamline.

    Returns
    -------
    Traction
        fx, fy (N), mz (N m) on the ball and the heat ∬ τ·v dA (W), (n,).
    """
    u_x, u_y, om, a, b, pm, h, ent = (np.atleast_1d(np.asarray(v, dtype=float))
                                       for v in (u_x, u_y, omega_s, a, b, p_max, h, entrainment))
    yg, wy = np.polynomial.legendre.leggauss(lines)
    y = a[:, None] * yg[None, :]
    half = b[:, None] * np.sqrt(1.0 - yg ** 2)[None, :]  # half-length of each streamline, m
    side = np.where(ent < 0, -1.0, 1.0)[:, None]
    scale = (kappa / (np.abs(ent) * h))[:, None]  # G Δx/(|ū| h) = scale p Δx
    sums = []
    for n in (steps // 2, steps):
        theta = np.linspace(-0.5 * np.pi, 0.5 * np.pi, n + 1)
        dth = theta[1] - theta[0]
        total = np.zeros((4, u_x.size))
        tau = np.zeros((2,) + y.shape)
        s = np.zeros(y.shape)
        x_prev = -side * half
        for th in theta[1:]:
            x = side * half * np.sin(th)
            p = pm[:, None] * np.sqrt(1.0 - yg ** 2)[None, :] * np.cos(th)
            v = np.stack([u_x[:, None] - om[:, None] * y, u_y[:, None] + om[:, None] * x])
            kk = scale * p * np.abs(x - x_prev)
            rhs = tau + kk * v
            r = np.hypot(rhs[0], rhs[1])
            s = _viscous_slip(viscous, p, kk, r, s)
            t_mag, _ = viscous(s, p)
            with np.errstate(invalid="ignore", divide="ignore"):
                tau = np.where((r > 0) & (p > 0), t_mag / np.where(r > 0, r, 1.0), 0.0) * rhs
            w = half * np.cos(th) * dth * (a[:, None] * wy[None, :])  # dx dy
            total += np.stack([(w * tau[0]).sum(1), (w * tau[1]).sum(1),
                               (w * (x * tau[1] - y * tau[0])).sum(1), (w * (tau * v).sum(0)).sum(1)])
            x_prev = x
        sums.append(total)
    fx, fy, mz, heat = 2.0 * sums[1] - sums[0]
    return Traction(fx, fy, mz, heat)


def _viscous_slip(viscous, p, kk, r, start, iterations=60, rtol=1e-12):
    """The viscous slip s ≥ 0 with τ_v(s, p) + kk s = r (τ_v increasing): Newton from
    ``start`` kept inside the bracket [0, r/kk] that each residual narrows, bisecting where a
    step leaves it. 0 where r = 0 or p = 0 (no stress)."""
    live = (r > 0) & (p > 0) & (kk > 0)
    lo = np.zeros_like(r)
    with np.errstate(divide="ignore", invalid="ignore"):
        hi = np.where(live, r / np.where(live, kk, 1.0), 0.0)
    s = np.clip(start, lo, hi)
    for _ in range(iterations):
        tau, slope = viscous(s, p)
        f = tau + kk * s - r
        lo = np.where(f < 0, s, lo)
        hi = np.where(f > 0, s, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = s - f / (slope + kk)
        inside = (step > lo) & (step < hi)
        s_new = np.where(inside, step, 0.5 * (lo + hi))
        done = ~live | (np.abs(f) <= rtol * r) | (hi - lo <= rtol * hi)
        s = np.where(done, s, s_new)
        if np.all(done):
            break
    return np.where(live, s, 0.0)
