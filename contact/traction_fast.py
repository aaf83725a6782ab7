"""The fast float32 rule of :func:`contact.traction.crook_traction` (``fast=True``).

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

With the smooth limiting shear (MODEL.md §6a, Λ = 0.047) the same nodes are used and the
worst error on those states is 6.8e-3 at order 16 (99 %: 5.0e-3), 1.9e-3 at 24, Jacobian
within ≈ 2e-2 of its largest entry: the tanh transition where |τ_C| ≈ Λ p is about twice as
sharp in p as Crook's thermal one (``benchmarks/limiting_shear.py``).
"""
from __future__ import annotations

import threading
from functools import lru_cache
from types import SimpleNamespace

import numpy as np

from .traction_accurate import _accurate_crook
from .traction_law import _gauss01, limit_shear

__all__ = ["fast_rule_size"]

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


def _fast_crook(ux, uy, om, a, b, pm, hh, eta_t, rule):
    """The fast rule for validated flat float64 arrays (n,) with the
    :class:`~contact.traction_accurate.RuleParams` ``rule``.  Returns (4, n) [fx, fy, mz,
    heat] or, with derivatives, (13, n) with the row-major Jacobian appended; ``elastic`` =
    (κ, ū (n,)) adds the film's elastic compliance (MODEL.md §6b, no derivatives).

    Nodes are laid out (R radial, D directions, n contacts), contacts innermost, so that
    per-ray arrays (D, n) broadcast over whole contiguous blocks. The stages below share one
    namespace of arrays: per contact (n,), per ray (D, n) and per node (R, D, n)."""
    c_p, c1_coef, order, derivatives, lam_s, elastic = rule
    n = ux.shape[0]
    lo = np.minimum(a, b)
    if lo.min() <= 0.0:  # unloaded contacts: zero
        res = np.zeros((13 if derivatives else 4, n))
        i = np.flatnonzero(lo > 0.0)
        if i.size:
            el = None if elastic is None else (elastic[0], elastic[1][i])
            res[:, i] = _fast_crook(ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i], eta_t[i],
                                    rule._replace(elastic=el))
        return res
    if c_p * pm.max() > _FAST_LAMBDA_MAX[bool(derivatives)]:
        return _accurate_crook(ux, uy, om, a, b, pm, hh, eta_t, rule).T.copy()
    tab = _fast_tables(order)
    k = SimpleNamespace(ux=ux, uy=uy, om=om, a=a, b=b, pm=pm, hh=hh, eta_t=eta_t, c_p=c_p, c1_coef=c1_coef,
                        derivatives=derivatives, lam_s=lam_s, elastic=elastic, n=n, lo=lo, tab=tab, R=tab["R"],
                        D=tab["D"], Hk=None)
    _fast_pole(k)
    _fast_rays(k)
    _fast_nodes(k)
    _fast_slip(k)
    _fast_law(k)
    if elastic is not None:
        _fast_elastic(k)
    if lam_s is not None:
        # |τ| = Λp tanh(|τ_C|/(Λp)) (MODEL.md §6a) in this rule's units: g h/η_T, u' = c1(η_T) u
        # (|u'| = √u2), so τ_L' = Λ p h c1(η_T)/η_T with p = (λσ)/c_ηP (σ p_max without c_ηP)
        scale = (1.0 / c_p) if c_p > 0.0 else pm
        tl = k.lsig * (lam_s * scale * hh * np.sqrt(k.cth) / eta_t).astype(_F32)
        k.G, k.Hk = limit_shear(k.G, np.sqrt(k.u2), tl, k.Hk if derivatives else None)
    res = _fast_sums(k)
    if derivatives:
        _fast_jacobian(k, res)
    return res


def _fast_pole(k):
    """Per contact: the spin pole, the rule (mode P rays from the pole or rays from the
    centre, as _analyse) and the tabulated gradings (``lev``, ``lr``); the ray origin and the
    slip there."""
    ux, uy, om, a, b, lo, n = k.ux, k.uy, k.om, k.a, k.b, k.lo, k.n
    hi = np.maximum(a, b)
    a_long = a >= b
    k.ab = ab = a * b
    k.lam = lam = k.c_p * k.pm
    k.cth = cth = k.c1_coef * k.eta_t  # c1² = cth e^{λσ}
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
        k.allp = allp = mode_p.all()
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
    k.th0 = th0
    if allp:
        k.Xo, k.Yo, k.rO = Xp, Yp, 1.0 - rp2  # ray origin, 1 − |O|²
        k.uOx = k.uOy = np.zeros(n)  # slip at the origin
    else:
        lr[~mode_p] = _FAST_N_BETA  # rays from the centre
        k.Xo = Xp * mode_p
        k.Yo = Yp * mode_p
        k.rO = 1.0 - (k.Xo * k.Xo + k.Yo * k.Yo)
        not_p = ~mode_p
        k.uOx = ux * not_p
        k.uOy = uy * not_p
    k.lev, k.lr = lev, lr


def _fast_rays(k):
    """Per ray (D, n): directions, then ρ_max forwards and ρ_2 backwards to the ellipse."""
    psi = np.take(k.tab["psi"], k.lev, axis=1)  # np.take: C-ordered result
    psi += k.th0
    psi = psi.astype(_F32)
    k.c = c = np.cos(psi)
    k.s = s = np.sin(psi)
    oe = c * k.Xo
    oe += s * k.Yo
    hc = oe * oe
    hc += k.rO
    np.sqrt(hc, out=hc)  # half chord
    k.rmax = rmax = hc - oe
    hc += oe
    k.r2 = hc.astype(_F32)
    k.rm = rmax.astype(_F32)
    k.bc = bc = c * k.b.astype(_F32)  # ray direction, metres per unit ρ
    k.as_ = as_ = s * k.a.astype(_F32)
    k.q2 = q2 = bc * bc
    q2 += as_ * as_


def _fast_nodes(k):
    """Per node (R, D, n): ρ and σ = p/p_max, and e^{λσ} (work arrays reused between calls)."""
    k.work = rho, t, sg, sq, rt, z, d = _fast_work(k.R, k.D, k.n)
    k.rho = rho
    k.pr = pr = np.take(k.tab["rho"], k.lr, axis=1)  # (R, n)
    np.multiply(k.rm, pr[:, None, :], out=rho)
    np.subtract(k.rm, rho, out=t)
    np.add(rho, k.r2, out=sg)
    sg *= t  # 1 − X² − Y² = (ρ_max − ρ)(ρ + ρ_2)
    np.sqrt(sg, out=sg)
    k.sigma = sg.copy() if k.elastic is not None else None
    k.lsig = None
    if k.c_p > 0.0:
        lrow = np.empty((k.D, k.n), _F32)
        lrow[...] = k.lam
        sg *= lrow  # λσ = c_ηP p
        if k.lam_s is not None:
            k.lsig = sg.copy()
        k.E = np.exp(sg, out=sg)  # η/η_T
    else:
        if k.lam_s is not None:
            k.lsig = sg.copy()
        sg[...] = _ONE
        k.E = sg


def _fast_slip(k):
    """u2 = c1(η_T)² |u|² = A + ρ (B + C ρ) per ray, into the work array ``t``."""
    rho, t = k.rho, k.work[1]
    om, cth = k.om, k.cth
    np.multiply(rho, k.q2 * (om * om * cth).astype(_F32), out=t)
    if k.allp:
        t *= rho
        t += _FAST_PSI_MIN
    else:
        wc = 2.0 * om * cth
        Br = k.bc * (wc * k.uOy).astype(_F32)
        Br -= k.as_ * (wc * k.uOx).astype(_F32)
        t += Br
        t *= rho
        Ar = np.empty((k.D, k.n), _F32)
        Ar[...] = (k.uOx * k.uOx + k.uOy * k.uOy) * cth + 1e-12
        t += Ar
    k.u2 = t.copy() if k.lam_s is not None or k.elastic is not None else None


def _fast_law(k):
    """The Crook law's g h/η_T = G(ψ) e^{λσ} at the nodes (and k h/(c1c η_T²) with
    derivatives): G(ψ) = asinh(s)/(s r), s = √ψ, r = √(1 + ψ); asinh(s) = log1p(z),
    z = s + ψ/(1 + r), log1p(z) = log(1 + z) z/((1 + z) − 1)."""
    _rho, psi, _sg, sq, rt, z, d = k.work
    E = k.E
    psi *= E  # ψ = c1² |u|²
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
    if k.derivatives:
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
        k.Hk = Hk
    G *= E  # g h/η_T
    k.G = G


def _fast_elastic(k):
    """The Maxwell film's elastic compliance (MODEL.md §6b): g (1 − e^(−1/R)),
    R = τ_v/|τ_e| = τ_C' er0/(σ |Ξ| |w|) with τ_C' = g √u2, Ξ = ξ/b, w the slip averaged since
    the inlet (contact.kernels.crook)."""
    kap, ent = k.elastic
    om, b, rho, c = k.om, k.b, k.rho, k.c
    sgn = np.where(ent < 0, -1.0, 1.0)
    live = (ent != 0.0)
    er0 = np.where(live, k.eta_t * np.abs(ent) / (np.sqrt(k.cth) * kap * k.pm * b), 0.0).astype(_F32)
    yy = k.Yo.astype(_F32) + rho * k.s
    xi = k.Xo.astype(_F32) + rho * c + sgn.astype(_F32) * np.sqrt(np.maximum(_ONE - yy * yy, _F32(0.0)))
    omb = (om * b).astype(_F32)
    oxi = omb * xi
    w2 = k.u2 * (1.0 / k.cth).astype(_F32) + oxi * (_F32(0.25) * oxi - k.uOy.astype(_F32) - omb * c * rho)
    dd = k.sigma * np.abs(xi) * np.sqrt(np.maximum(w2, _F32(0.0))) + _F32(1e-30)  # no 0/0 at ū → 0
    with np.errstate(divide="ignore", invalid="ignore"):
        inv_r = dd / (k.G * np.sqrt(k.u2) * er0)  # 1/R; inf without stress or elastic limit
    k.G = k.G * -np.expm1(-np.nan_to_num(inv_r, nan=np.inf))


def _fast_sums(k):
    """Along each ray ∑ g W ρ^j (W = ρ_max² wψ × table), then over the rays: the forces, the
    moment and the heat, (13 or 4, n) with the Jacobian's rows left to :func:`_fast_jacobian`."""
    tab, lr, lev, pr, n = k.tab, k.lr, k.lev, k.pr, k.n
    om, rmax, uOx, uOy = k.om, k.rmax, k.uOx, k.uOy
    npow = 5 if k.derivatives else 3
    k.pat = pat = np.empty((npow, k.R, n), _F32)
    pat[0] = np.take(tab["w"], lr, axis=1)
    for j in range(1, npow):
        np.multiply(pat[j - 1], pr, out=pat[j])
    K = np.einsum("jrn,rdn->jdn", pat[:3], k.G)
    w0 = np.take(tab["wpsi"], lev, axis=1)
    w0 *= rmax
    w0 *= rmax * (k.ab * k.eta_t / k.hh)
    k.S0 = S0 = np.einsum("dn,dn->n", K[0], w0)  # ∬ g dA and ∬ g (x', y', x'² + y'²) dA
    w0 *= rmax
    K1 = K[1]
    K1 *= w0
    k.Sx = Sx = np.einsum("dn,dn->n", K1, k.bc)
    k.Sy = Sy = np.einsum("dn,dn->n", K1, k.as_)
    w0 *= rmax
    w0 *= k.q2
    k.Sr = Sr = np.einsum("dn,dn->n", K[2], w0)
    k.xo = xo = k.Xo * k.b
    k.yo = yo = k.Yo * k.a
    # τ = g u, u = u_O + ω (−y', x'):  f = u_O S0 + ω (−S'y, S'x)
    res = np.empty((13 if k.derivatives else 4, n))
    fx, fy, mz, heat = res[:4]
    np.multiply(om, Sy, out=fx)
    np.negative(fx, out=fx)
    np.multiply(om, Sx, out=fy)
    np.multiply(om, Sr, out=mz)
    np.multiply(om, mz, out=heat)
    if not k.allp:
        fx += uOx * S0
        fy += uOy * S0
        cross = uOy * Sx - uOx * Sy
        mz += cross
        heat += (uOx * uOx + uOy * uOy) * S0 + 2.0 * om * cross
    mz += xo * fy - yo * fx
    return res


def _fast_jacobian(k, res):
    """∂(f, M_z)/∂(u_x, u_y, ω_s) = ∬ g EᵀE + k v vᵀ dA, v = (u_x, u_y, x u_y − y u_x), into
    rows 4… of ``res``: along a ray v = (uOx + dx ρ, uOy + dy ρ, p1 ρ + p2 ρ²) (x u_y − y u_x = 0
    at the origin: the pole, or the centre), so ∑ k v vᵀ needs V_j = ∑ k W ρ^j, j ≤ 4."""
    om, rmax, bc, as_, uOx, uOy = k.om, k.rmax, k.bc, k.as_, k.uOx, k.uOy
    xo, yo, S0, Sx, Sy, Sr = k.xo, k.yo, k.S0, k.Sx, k.Sy, k.Sr
    V = np.einsum("jrn,rdn->jdn", k.pat, k.Hk)
    wrow = np.take(k.tab["wpsi"], k.lev, axis=1)
    wrow *= rmax
    wrow *= rmax
    for j in range(5):
        V[j] *= wrow
        if j < 4:
            wrow *= rmax
    dx = as_ * -om
    dy = bc * om
    p1 = xo * dy - yo * dx + bc * uOy - as_ * uOx
    p2 = k.q2 * om
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
    kf = k.ab * k.eta_t / k.hh * k.c1_coef * k.eta_t
    J = res[4:].reshape(3, 3, k.n)
    J[0, 0] = (uOx * uOx * A0 + 2.0 * uOx * A1x + Axx) * kf + S0
    J[1, 1] = (uOy * uOy * A0 + 2.0 * uOy * A1y + Ayy) * kf + S0
    J[0, 1] = (uOx * uOy * A0 + uOx * A1y + uOy * A1x + Axy) * kf
    J[0, 2] = (uOx * B + Cx) * kf - (yo * S0 + Sy)
    J[1, 2] = (uOy * B + Cy) * kf + (xo * S0 + Sx)
    J[2, 2] = Czz * kf + (xo * xo + yo * yo) * S0 + 2.0 * (xo * Sx + yo * Sy) + Sr
    J[1, 0] = J[0, 1]
    J[2, 0] = J[0, 2]
    J[2, 1] = J[1, 2]
