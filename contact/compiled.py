"""Compiled (numba) evaluation of a whole bearing's contact forces in one pass.

The numpy functions of this package are the reference; this module computes the same
equations, contact by contact, without per-call array overhead (a 16-ball bearing's
right-hand side spends ~1 ms of its ~1.7 ms in numpy bookkeeping on arrays of 32 rows):

* :func:`race_contacts` — kinematics (MODEL.md §2, §6; :mod:`contact.kinematics`), Hertz
  fits (§3, :func:`contact.hertz.hertz_contact` with ``method='fit'``), damped normal load,
  Hamrock–Dowson film (§5, P17) and the Crook traction by the fast rule (§6, P12–P16,
  optionally with the smooth limiting shear of §6a;
  :func:`contact.traction.crook_traction` with ``fast=True``: the same node tables, float32
  along each ray as there, float64 for the rare ray that overflows float32), force and
  moment on the ball as :func:`contact.ballrace.ball_race_forces`;
* :func:`cage_and_drag` — rigid-cage pocket forces, the paper's spring chain (P9, P10) and
  ball drag (§8) as :mod:`contact.cage`;
* :func:`race_contacts_parallel` — the same with the contacts spread over numba's threads;
* :func:`land_forces` — the guiding land of a race-guided cage as :mod:`contact.cage`;
* :func:`crook_fast` — the traction rule alone, vectorized (for tests and benchmarks).

Everything is in one global frame and SI units. ``tests/test_compiled.py`` checks every
output against the numpy functions on the same states.
"""
from __future__ import annotations

import math
import os

import numpy as np

# GNU OpenMP threads (numba's parallel layer) spin ~300 000 times while they wait for work;
# when other processes share the cores (a skid map, a second run) the spinning threads take
# their CPU. Two runs side by side on 2 cores, 0.02 s simulated each: 10.5-11.7 s with that
# default, 1.9-2.0 s with a spin count of 3000 (alone: 1.30 vs 1.2 s). Must be set before the
# OpenMP runtime loads; a user's own OMP_WAIT_POLICY or GOMP_SPINCOUNT wins.
if "OMP_WAIT_POLICY" not in os.environ:
    os.environ.setdefault("GOMP_SPINCOUNT", "3000")

from pathlib import Path  # noqa: E402

from .kernel_cache import drop_stale  # noqa: E402

# the kernels inline functions of traction_fast.py: recompile when any contact/ source changed
drop_stale(__file__, Path(__file__).parent.glob("*.py"))

from llvmlite import ir  # noqa: E402
from numba import njit, prange, types  # noqa: E402
from numba.extending import intrinsic  # noqa: E402

from . import traction_fast as _tr
from .cage import LAND_DAMPING_DEPTH

__all__ = ["crook_fast", "crook_tables", "race_contacts", "race_contacts_parallel", "cage_and_drag",
           "land_forces", "rotation_matrices"]

_EPS_CAP = float(_tr._FAST_EPS_CAP)
_LOG2_EPS_CAP = math.log2(_EPS_CAP)
_EPS_STEPS = float(_tr._FAST_EPS_STEPS)
_N_EPS = int(_tr._FAST_N_EPS)
_N_BETA = int(_tr._FAST_N_BETA)
_FC = float(_tr._FAST_FC)
_BFAC = float(_tr._FAST_BFAC)
_BETA_MIN = float(_tr._FAST_BETA_MIN)
_BETA_STEP = float(_tr._FAST_BETA_STEP)
_PSI_MIN = 1e-12  # the fast rule's ψ floor (keeps G(ψ) finite at the pole)


def crook_tables(order: int = 16):
    """The fast rule's node tables (:func:`contact.traction_fast._fast_tables`): cosine and sine
    of the ray angles and their weights (float64), radial nodes and weights in float32 and
    float64 (same values): (cos_psi, sin_psi, wpsi, rho32, w32, rho64, w64)."""
    tab = _tr._fast_tables(int(order))
    psi, wpsi, rho, w = (np.ascontiguousarray(tab[k], dtype=np.float64) for k in ("psi", "wpsi", "rho", "w"))
    return np.cos(psi), np.sin(psi), wpsi, rho.astype(np.float32), w.astype(np.float32), rho, w


# fast-math flags without 'reassoc' (the (1 + z) - 1 correction below must survive) and
# without 'nnan'/'ninf' (NaN and inf are tested for)
_FLAGS = {"nsz", "arcp", "contract", "afn"}


# Vectorizable float32 exp and log. The PyPI llvmlite has no SVML, so math.exp/math.log
# stay scalar library calls and keep LLVM from vectorizing the quadrature; these Cephes
# polynomials (expf, logf; error ~1 ulp) with bit-level scaling vectorize. crook_fast on
# 32 contacts of the reference bearing's range at order 16: 550 -> 160 us per call.
@intrinsic
def _f32_bits(typingctx, x):
    if x != types.float32:
        return None
    return types.int32(types.float32), lambda context, builder, sig, args: builder.bitcast(args[0], ir.IntType(32))


@intrinsic
def _bits_f32(typingctx, i):
    if i != types.int32:
        return None
    return types.float32(types.int32), lambda context, builder, sig, args: builder.bitcast(args[0], ir.FloatType())


_F = np.float32
_I = np.int32
_F1, _FH = _F(1.0), _F(0.5)
_ROUND = _F(1.5 * 2.0 ** 23)  # x + _ROUND - _ROUND rounds x to an integer (|x| < 2^22)
_ROUND_BITS = _I(0x4B400000)  # bit pattern of _ROUND: bits(x + _ROUND) - _ROUND_BITS = round(x)
_LOG2E = _F(1.4426950408889634)
_LN2_HI, _LN2_LO = _F(0.693359375), _F(-2.12194440e-4)  # Cody–Waite split of ln 2
_EXP_MAX = _F(88.0)
_INF32 = _F(np.inf)
_SQRT2_32 = _F(math.sqrt(2.0))
_EXP_P = tuple(_F(c) for c in (1.9875691500e-4, 1.3981999507e-3, 8.3334519073e-3, 4.1665795894e-2,
                                1.6666665459e-1, 5.0000001201e-1))
_LOG_P = tuple(_F(c) for c in (7.0376836292e-2, -1.1514610310e-1, 1.1676998740e-1, -1.2420140846e-1,
                                1.4249322787e-1, -1.6668057665e-1, 2.0000714765e-1, -2.4999993993e-1,
                                3.3333331174e-1))


@njit(cache=True, error_model="numpy", fastmath=_FLAGS, inline="always")
def _exp32(x):
    """e^x in float32 for 0 <= x (inf above 88; Cephes expf)."""
    p0, p1, p2, p3, p4, p5 = _EXP_P
    v = x * _LOG2E + _ROUND
    n = v - _ROUND
    r = (x - n * _LN2_HI) - n * _LN2_LO
    y = (((((p0 * r + p1) * r + p2) * r + p3) * r + p4) * r + p5) * (r * r) + r + _F1
    scale = _bits_f32(_I((_f32_bits(v) - _ROUND_BITS + _I(127)) << _I(23)))  # 2^n
    return _INF32 if x > _EXP_MAX else y * scale


@njit(cache=True, error_model="numpy", fastmath=_FLAGS, inline="always")
def _log32(x):
    """ln x in float32 for finite x >= 1 (Cephes logf)."""
    l0, l1, l2, l3, l4, l5, l6, l7, l8 = _LOG_P
    i = _f32_bits(x)
    m = _bits_f32(_I((i & _I(0x007FFFFF)) | _I(0x3F800000)))  # mantissa in [1, 2)
    big = m > _SQRT2_32
    e = _F(_I((i >> _I(23)) - _I(127)) + _I(1) if big else _I((i >> _I(23)) - _I(127)))
    t = (m * _FH if big else m) - _F1
    z = t * t
    y = ((((((((l0 * t + l1) * t + l2) * t + l3) * t + l4) * t + l5) * t + l6) * t + l7) * t + l8) * t * z
    return t + ((y + _LN2_LO * e) - _FH * z) + _LN2_HI * e


@njit(cache=True, error_model="numpy", fastmath=_FLAGS)
def _rays32(ir, lam, a0, rho_tab, w_tab, ray, k):
    """k[j, d] = sum along ray d of g W ρ^j, j = 0, 1, 2 (MODEL.md §6: g = η_m/η_T, the
    Crook factor times the Barus viscosity), float32, for all rays at once (the inner loop
    runs over the rays and vectorizes). ``ray`` rows: ρ_max, ρ_2, C, B of each ray
    (ψ = c1²|u|² = (A + ρ (B + C ρ)) e^{λσ}); padding rays have ρ_max = 0."""
    rm, r2, cq, br = ray[0], ray[1], ray[2], ray[3]
    k0, k1, k2 = k[0], k[1], k[2]
    lam32, a032 = _F(lam), _F(a0)
    k[:] = 0.0
    for r in range(rho_tab.shape[0]):
        pr = rho_tab[r, ir]
        wr = w_tab[r, ir]
        for d in range(rm.shape[0]):
            rho = rm[d] * pr
            e = _exp32(lam32 * math.sqrt((rm[d] - rho) * (rho + r2[d])))  # η/η_T, σ = p/p_max
            psi = ((rho * cq[d] + br[d]) * rho + a032) * e
            # G = asinh(s)/(s r), s = √ψ, r = √(1 + ψ); asinh(s) = log1p(z), z = s + ψ/(1 + r),
            # log1p(z) = log(1 + z) z/((1 + z) − 1)
            sq = math.sqrt(psi)
            rt = math.sqrt(_F1 + psi)
            z = sq + psi / (_F1 + rt)
            u1 = _F1 + z
            wg = wr * (_log32(u1) * z * e / ((u1 - _F1) * (sq * rt)))
            k0[d] += wg
            wg *= pr
            k1[d] += wg
            k2[d] += wg * pr


# Smooth limiting shear (MODEL.md §6a): τ = τ_L tanh(x) along u, x = |τ_C|/τ_L. tanh(x) for
# x <= _CAP_X as x P(x²)/Q(x²), a minimax-weighted least-squares rational fit of tanh(x)/x
# of degree 3/3 in x² (P(0) = Q(0) = 1, so the law is Crook's as x -> 0), x P/Q at _CAP_X
# (= tanh to 2.3e-6) beyond: relative error below 3e-6 everywhere (tests/test_limiting_shear.py),
# far below the rule's own error. No exp and one division, so the ray loop still vectorizes.
_CAP_X = 6.5
_CAP_P = (1.0, 0.1244151739162312, 0.0024030125261559894, 4.54511452920797e-06)
_CAP_Q = (1.0, 0.45774726077250827, 0.021654500612336477, 0.00015623762350085177)
_CP32 = tuple(_F(c) for c in _CAP_P)
_CQ32 = tuple(_F(c) for c in _CAP_Q)
_CAP_X32 = _F(_CAP_X)


@njit(cache=True, error_model="numpy", fastmath=_FLAGS, inline="always")
def _tanh32(x):
    """tanh(x) for x >= 0 by the rational fit above (float32)."""
    p0, p1, p2, p3 = _CP32
    q0, q1, q2, q3 = _CQ32
    xc = min(x, _CAP_X32)
    y = xc * xc
    num = ((p3 * y + p2) * y + p1) * y + p0
    den = ((q3 * y + q2) * y + q1) * y + q0
    return xc * num / den


@njit(cache=True, error_model="numpy", fastmath=_FLAGS, inline="always")
def _capped_node(rm, r2, cq, br, pr, lamh32, a032, itlc32, tlc32):
    """g of one node with the smooth limiting shear (float32; see :func:`_rays32_capped`)."""
    rho = rm * pr
    sg = math.sqrt((rm - rho) * (rho + r2))  # σ = p/p_max
    eh = _exp32(lamh32 * sg)  # √(η/η_T)
    psi = ((rho * cq + br) * rho + a032) * (eh * eh)
    sq = math.sqrt(psi)
    rt = math.sqrt(_F1 + psi)
    z = sq + psi / (_F1 + rt)
    u1 = _F1 + z
    lz = _log32(u1) * z  # asinh(s) (u1 − 1), see _rays32
    # x = τ_C'/τ_L' = asinh(s) e^{λσ/2}/(√(1 + ψ) tlc σ); g = τ_L' tanh(x)/|u'| with
    # |u'| = s e^{−λσ/2}: one division each
    x = lz * eh * itlc32 / ((u1 - _F1) * rt * sg)
    return (tlc32 * sg * eh) * _tanh32(x) / sq


@njit(cache=True, error_model="numpy", fastmath=_FLAGS)
def _rays32_capped(ir, lam, a0, tlc, rho_tab, w_tab, ray, k):
    """:func:`_rays32` with the smooth limiting shear (MODEL.md §6a): g tanh(x)/x with
    x = τ_C'/τ_L', τ_C' = g √(A + ρ (B + C ρ)) = asinh(s) e^{λσ/2}/√(1 + ψ) and τ_L' = tlc σ
    (the rule's units: τ h c1(η_T)/η_T; ``tlc`` = Λ p_max h c1(η_T)/η_T). Two radial nodes
    per pass over the rays: the cap lengthens each node's dependency chain, and with ~5
    vectors of rays per pass the second node's independent work hides it."""
    rm, r2, cq, br = ray[0], ray[1], ray[2], ray[3]
    k0, k1, k2 = k[0], k[1], k[2]
    lamh32, a032, itlc32, tlc32 = _F(0.5 * lam), _F(a0), _F(1.0 / tlc), _F(tlc)
    k[:] = 0.0
    n_rad = rho_tab.shape[0]
    for r in range(0, n_rad - 1, 2):
        pa, wa = rho_tab[r, ir], w_tab[r, ir]
        pb, wb = rho_tab[r + 1, ir], w_tab[r + 1, ir]
        for d in range(rm.shape[0]):
            ga = wa * _capped_node(rm[d], r2[d], cq[d], br[d], pa, lamh32, a032, itlc32, tlc32)
            gb = wb * _capped_node(rm[d], r2[d], cq[d], br[d], pb, lamh32, a032, itlc32, tlc32)
            k0[d] += ga + gb
            ga *= pa
            gb *= pb
            k1[d] += ga + gb
            k2[d] += ga * pa + gb * pb
    if n_rad % 2:
        pa, wa = rho_tab[n_rad - 1, ir], w_tab[n_rad - 1, ir]
        for d in range(rm.shape[0]):
            ga = wa * _capped_node(rm[d], r2[d], cq[d], br[d], pa, lamh32, a032, itlc32, tlc32)
            k0[d] += ga
            ga *= pa
            k1[d] += ga
            k2[d] += ga * pa


@njit(cache=True, error_model="numpy", fastmath=_FLAGS, inline="always")
def _elastic_node(rm, r2, cq, br, cd, sd, pr, lamh32, a032, itlc32, tlc32, el):
    """g of one node with the film's elastic compliance in series (MODEL.md §6b) and, for
    ``tlc32`` > 0, the smooth limiting shear (float32; see :func:`_rays32_elastic`)."""
    xo, yo, sgn, omb, uoy, er0, icth = el[0], el[1], el[2], el[3], el[4], el[5], el[6]
    rho = rm * pr
    sg = math.sqrt((rm - rho) * (rho + r2))  # σ = p/p_max
    eh = _exp32(lamh32 * sg)  # √(η/η_T)
    av = (rho * cq + br) * rho + a032  # c_th |v|²
    psi = av * (eh * eh)
    sq = math.sqrt(psi)
    rt = math.sqrt(_F1 + psi)
    z = sq + psi / (_F1 + rt)
    u1 = _F1 + z
    tc = _log32(u1) * z * eh / ((u1 - _F1) * rt)  # τ_C' = asinh(s) e^{λσ/2}/√(1 + ψ)
    # strain since the inlet: Ξ = ξ/b, w = v − (0, ω ξ/2) (contact.film_elasticity)
    yy = yo + rho * sd
    xi = xo + rho * cd + sgn * math.sqrt(max(_F1 - yy * yy, _F(0.0)))
    oxi = omb * xi
    w2 = av * icth + oxi * (_F(0.25) * oxi - uoy - omb * cd * rho)
    d = sg * abs(xi) * math.sqrt(max(w2, _F(0.0))) + _F(1e-30)  # R = τ_C' er0/d (no 0/0 at ū → 0)
    f = d / (d + tc * er0)  # 1/(1 + R), R = τ_v/|τ_e|
    if tlc32 > _F(0.0):
        return (tlc32 * sg * eh) * _tanh32(tc * f * itlc32 / sg) / sq
    return tc * f * eh / sq


@njit(cache=True, error_model="numpy", fastmath=_FLAGS)
def _rays32_elastic(ir, lam, a0, tlc, rho_tab, w_tab, ray, el64, k):
    """:func:`_rays32` with the film's elastic compliance in series (MODEL.md §6b): g/(1 + R),
    R = τ_v/|τ_e| = τ_C' er0/(σ |Ξ| |w|), Ξ = ξ/b the distance from the inlet edge and w the
    strain rate averaged since the inlet; then the smooth limiting shear for ``tlc`` > 0.
    ``ray`` rows 4, 5: the ray's direction (c, s) in normalized coordinates; ``el64``: Xo,
    Yo (ray origin, normalized), sign ū, ω b, v_y at the origin, er0 = η_T |ū|/(√c_th κ p_max b)
    and 1/c_th."""
    rm, r2, cq, br, cd, sd = ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]
    k0, k1, k2 = k[0], k[1], k[2]
    lamh32, a032 = _F(0.5 * lam), _F(a0)
    tlc32 = _F(tlc)
    itlc32 = _F(1.0 / tlc) if tlc > 0.0 else _F(0.0)
    el = np.empty(7, np.float32)
    for i in range(7):
        el[i] = el64[i]
    k[:] = 0.0
    for r in range(rho_tab.shape[0]):
        pr = rho_tab[r, ir]
        wr = w_tab[r, ir]
        for d in range(rm.shape[0]):
            g = wr * _elastic_node(rm[d], r2[d], cq[d], br[d], cd[d], sd[d], pr, lamh32, a032, itlc32, tlc32, el)
            k0[d] += g
            g *= pr
            k1[d] += g
            k2[d] += g * pr


@njit(cache=True, error_model="numpy", fastmath=_FLAGS, inline="always")
def _ray_sums(rmax, r2, cq, br, a0, lam, tlc, ir, rho_tab, w_tab, scratch, cd, sd, el):
    """Sums along one ray of g W ρ^j, j = 0, 1, 2, as :func:`_rays32` (``tlc`` > 0: with
    the limiting shear of :func:`_rays32_capped`; ``el[5]`` > 0: with the film's elastic
    compliance of :func:`_rays32_elastic`, ray direction (``cd``, ``sd``)) for one ray in the
    tables' precision: float64 for the rare ray whose ψ overflows float32. ``scratch`` (dtype
    of the tables) casts the ray constants."""
    scratch[0] = rmax
    scratch[1] = r2
    scratch[2] = cq
    scratch[3] = br
    scratch[4] = a0
    scratch[5] = lam
    scratch[6] = 1.0
    rm, rr2, cq_, br_, a0_, lam_, one = (scratch[0], scratch[1], scratch[2], scratch[3], scratch[4], scratch[5],
                                         scratch[6])
    scratch[7] = 0.0
    k0 = k1 = k2 = scratch[7]
    for r in range(rho_tab.shape[0]):
        pr = rho_tab[r, ir]
        rho = rm * pr
        sg = math.sqrt((rm - rho) * (rho + rr2))  # p/p_max
        e = math.exp(lam_ * sg)  # η/η_T
        psi = ((rho * cq_ + br_) * rho + a0_) * e  # ψ = c1² |u|²
        # G = asinh(s)/(s r), s = √ψ, r = √(1 + ψ); asinh(s) = log1p(z), z = s + ψ/(1 + r),
        # log1p(z) = log(1 + z) z/((1 + z) − 1)
        sq = math.sqrt(psi)
        rt = math.sqrt(one + psi)
        z = sq + psi / (one + rt)
        u1 = one + z
        g = math.log(u1) * (z / (u1 - one)) / (sq * rt) * e
        if el[5] > 0.0:  # elastic film in series (MODEL.md §6b)
            tc = g * math.sqrt(psi / e)  # τ_C'
            yy = el[1] + rho * sd
            xi = el[0] + rho * cd + el[2] * math.sqrt(max(1.0 - yy * yy, 0.0))
            oxi = el[3] * xi
            w2 = (psi / e) * el[6] + oxi * (0.25 * oxi - el[4] - el[3] * cd * rho)
            dd = sg * abs(xi) * math.sqrt(max(w2, 0.0)) + 1e-30
            g *= dd / (dd + tc * el[5])
        if tlc > 0.0:  # smooth limiting shear (MODEL.md §6a)
            x = g * math.sqrt(psi / e) / (tlc * sg)
            if x > 0.0:
                g *= math.tanh(x) / x
        wg = w_tab[r, ir] * g
        k0 += wg
        wg *= pr
        k1 += wg
        k2 += wg * pr
    return float(k0), float(k1), float(k2)


@njit(cache=True, error_model="numpy")
def _crook_one(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, lam_s, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64,
               w64, kap_e=0.0, ent=0.0):
    """(f_x, f_y, M_z, heat) of one contact by the fast rule (MODEL.md §6; see
    :func:`contact.traction_fast._fast_crook`, whose steps this follows one contact at a time),
    with the smooth limiting shear Λ = ``lam_s`` (MODEL.md §6a; 0: none) and the film's
    elastic compliance G = ``kap_e`` p at the signed entrainment speed ``ent`` (m/s;
    MODEL.md §6b; ``kap_e`` 0 or ``ent`` 0: none)."""
    lo = min(a, b)
    if not lo > 0.0:
        return 0.0, 0.0, 0.0, 0.0
    hi = max(a, b)
    a_long = a >= b
    ab = a * b
    lam = c_p * pm
    cth = c1_coef * eta_t
    # spin pole, normalised (X = x/b, Y = y/a)
    Xp = uy / om / (-b)
    Yp = ux / om / a
    rp2 = Xp * Xp + Yp * Yp
    spin = rp2 < 1e12
    if not spin:
        Xp = 0.0
        Yp = 0.0
        rp2 = 0.0
    ridge = Yp if a_long else Xp
    r2r = ridge * ridge
    inv_c1w = 1.0 / math.sqrt(cth * (om * om))
    rho_pole = math.exp(-0.5 * lam * math.sqrt(max(1.0 - rp2, 0.0))) * inv_c1w
    rho_ridge = math.exp(-0.5 * lam * math.sqrt(max(1.0 - r2r, 0.0))) * inv_c1w
    rho_peak = math.exp(-0.5 * lam) * inv_c1w
    inside = rp2 < 1.0 - 1e-12
    lo2 = lo * lo
    hi2 = hi * hi
    rr2 = rho_ridge * rho_ridge
    mode_p = inside and ((rho_pole < hi) or ((r2r < 1.0) and ((rp2 - r2r) * lo2 + rr2 < hi2)))
    if mode_p:
        eps = math.asinh(math.sqrt((lo2 + 0.25 * rr2) / (hi2 - lo2)))
        th0 = 0.0 if a_long else 0.5 * math.pi
    else:
        if spin:
            rp = math.sqrt(rp2)
            q = rp / math.sqrt((b * Yp) ** 2 + (a * Xp) ** 2)
            d_out = rp - 1.0
            d_out = d_out * ab * q if d_out > 0.0 else 0.0  # fmax: NaN -> 0
            far = rho_pole / rp if inside else rho_peak
            eps = math.sqrt(d_out * d_out + far * far) * q
        else:
            eps = _EPS_CAP
        th0 = math.atan2(Yp, Xp)
    # table columns: angular grading rounded to (π/2) 2^(−k/8), radial grading to 0.3 + 0.1 k
    lev = -_EPS_STEPS * math.log2(eps) + _EPS_STEPS * _LOG2_EPS_CAP
    lev = min(max(np.rint(lev), 0.0), _N_EPS - 1.0) if lev == lev else 0.0
    lr_f = math.asinh(_FC * math.sqrt(ab) / rho_peak) * (_BFAC / _BETA_STEP) - _BETA_MIN / _BETA_STEP
    lr_f = min(max(np.rint(lr_f), 0.0), _N_BETA - 1.0) if lr_f == lr_f else 0.0
    ie = int(lev)
    if mode_p:
        ir = int(lr_f)
        Xo, Yo, rO = Xp, Yp, 1.0 - rp2
        uOx, uOy = 0.0, 0.0
    else:
        ir = _N_BETA  # rays from the centre
        Xo, Yo, rO = 0.0, 0.0, 1.0
        uOx, uOy = ux, uy
    wc = 2.0 * om * cth
    a0 = (uOx * uOx + uOy * uOy) * cth + _PSI_MIN
    w2c = om * om * cth
    # rays: float64 geometry, float32 constants padded to a multiple of 8 lanes (AVX2)
    n_rays = cos_tab.shape[0]
    c0, s0 = math.cos(th0), math.sin(th0)
    elastic = kap_e > 0.0 and ent != 0.0
    geo = np.empty((8, n_rays))
    ray = np.zeros((6 if elastic else 4, (n_rays + 7) // 8 * 8), np.float32)
    for d in range(n_rays):
        c = cos_tab[d, ie] * c0 - sin_tab[d, ie] * s0  # direction th0 + psi
        s = sin_tab[d, ie] * c0 + cos_tab[d, ie] * s0
        oe = c * Xo + s * Yo
        hc = math.sqrt(oe * oe + rO)
        bc = c * b  # ray direction, metres per unit ρ
        as_ = s * a
        q2 = bc * bc + as_ * as_
        geo[0, d] = ray[0, d] = hc - oe  # ρ_max
        geo[1, d] = ray[1, d] = hc + oe  # ρ_2
        geo[2, d] = ray[2, d] = q2 * w2c
        geo[3, d] = ray[3, d] = bc * (wc * uOy) - as_ * (wc * uOx)
        geo[4, d] = bc
        geo[5, d] = as_
        geo[6, d] = c
        geo[7, d] = s
        if elastic:
            ray[4, d] = c
            ray[5, d] = s
    k = np.empty((3, ray.shape[1]), np.float32)
    tlc = lam_s * pm * hh * math.sqrt(cth) / eta_t  # τ_L' = tlc σ in the rule's units
    el = np.zeros(7)
    if elastic:
        el[0], el[1] = Xo, Yo
        el[2] = 1.0 if ent > 0.0 else -1.0
        el[3], el[4] = om * b, uOy
        el[5] = eta_t * abs(ent) / (math.sqrt(cth) * kap_e * pm * b)
        el[6] = 1.0 / cth
        _rays32_elastic(ir, lam, a0, tlc, rho32, w32, ray, el, k)
    elif tlc > 0.0:
        _rays32_capped(ir, lam, a0, tlc, rho32, w32, ray, k)
    else:
        _rays32(ir, lam, a0, rho32, w32, ray, k)
    s64 = np.empty(8)
    S0 = 0.0
    Sx = 0.0
    Sy = 0.0
    Sr = 0.0
    scale = ab * eta_t / hh
    for d in range(n_rays):
        rmax, bc, as_ = geo[0, d], geo[4, d], geo[5, d]
        k0, k1, k2 = float(k[0, d]), float(k[1, d]), float(k[2, d])
        if not (abs(k0) < np.inf and abs(k1) < np.inf and abs(k2) < np.inf):
            k0, k1, k2 = _ray_sums(rmax, geo[1, d], geo[2, d], geo[3, d], a0, lam, tlc, ir, rho64, w64, s64,
                                   geo[6, d], geo[7, d], el)
        w0 = wpsi_tab[d, ie] * rmax * rmax * scale
        S0 += k0 * w0
        w0 *= rmax
        Sx += k1 * w0 * bc
        Sy += k1 * w0 * as_
        Sr += k2 * w0 * rmax * (bc * bc + as_ * as_)
    xo = Xo * b
    yo = Yo * a
    fx = -om * Sy + uOx * S0
    fy = om * Sx + uOy * S0
    cr = uOy * Sx - uOx * Sy
    mz = om * Sr + cr + xo * fy - yo * fx
    heat = om * om * Sr + (uOx * uOx + uOy * uOy) * S0 + 2.0 * om * cr
    return fx, fy, mz, heat


@njit(cache=True, error_model="numpy")
def _crook_many(ux, uy, om, a, b, pm, hh, eta_t, c_p, c1_coef, lam_s, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64,
                w64, out, kap_e, ent):
    for i in range(ux.shape[0]):
        out[0, i], out[1, i], out[2, i], out[3, i] = _crook_one(
            ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i], eta_t, c_p, c1_coef, lam_s, cos_tab, sin_tab, wpsi_tab,
            rho32, w32, rho64, w64, kap_e, ent[i])


def crook_fast(u_x, u_y, omega_s, a, b, p_max, h, lubricant, order=16, limiting_shear=None, film_modulus=None,
               entrainment=0.0):
    """Crook traction (f_x, f_y, M_z, heat) of n contacts by the compiled fast rule, each
    an array (n,) (MODEL.md §6, with ``limiting_shear`` = Λ the smooth cap of §6a; None or
    0: pure Crook; ``film_modulus`` = κ and the signed ``entrainment`` speed (m/s) the film's
    elastic compliance of §6b). Arguments as :func:`contact.traction.crook_traction` (flat
    arrays, reference temperature); no input checks."""
    args = [np.ascontiguousarray(v, dtype=np.float64).ravel() for v in (u_x, u_y, omega_s, a, b, p_max, h)]
    n = args[0].shape[0]
    out = np.empty((4, n))
    ent = np.ascontiguousarray(np.broadcast_to(np.asarray(entrainment, dtype=np.float64), (n,)))
    c1_coef = lubricant.temperature_viscosity / (8.0 * lubricant.thermal_conductivity)
    _crook_many(*args, float(lubricant.viscosity), float(lubricant.pressure_viscosity), c1_coef,
                float(limiting_shear or 0.0), *crook_tables(order), out, float(film_modulus or 0.0), ent)
    return out


@njit(cache=True, error_model="numpy")
def rotation_matrices(nu):
    """Rodrigues rotation matrices of rotation vectors (n, 3) -> (n, 3, 3), as
    :func:`contact.kinematics.rotation_matrices`."""
    n = nu.shape[0]
    out = np.empty((n, 3, 3))
    for i in range(n):
        x, y, z = nu[i, 0], nu[i, 1], nu[i, 2]
        angle2 = x * x + y * y + z * z
        if angle2 < 1e-12:
            c1 = 1.0 - angle2 / 6.0
            c2 = 0.5 - angle2 / 24.0
        else:
            angle = math.sqrt(angle2)
            c1 = math.sin(angle) / angle
            c2 = (1.0 - math.cos(angle)) / angle2
        # I + c1 S + c2 S², S the skew matrix of nu; S² = nu nuᵀ - |nu|² I
        out[i, 0, 0] = 1.0 + c2 * (x * x - angle2)
        out[i, 1, 1] = 1.0 + c2 * (y * y - angle2)
        out[i, 2, 2] = 1.0 + c2 * (z * z - angle2)
        out[i, 0, 1] = -c1 * z + c2 * x * y
        out[i, 1, 0] = c1 * z + c2 * x * y
        out[i, 0, 2] = c1 * y + c2 * x * z
        out[i, 2, 0] = -c1 * y + c2 * x * z
        out[i, 1, 2] = -c1 * x + c2 * y * z
        out[i, 2, 1] = c1 * x + c2 * y * z
    return out


@njit(cache=True, error_model="numpy")
def _race_contact(idx, c, v, w, ro, rr, rv, rw, groove, conformity, sign, ball_radius, pitch_diameter,
                  e_prime, ball_mass, damping_ratio, traction, spin_moment, min_film, eta0, c_p, max_barus,
                  c1_coef, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64, force, moment, penetration, load,
                  lam_s, kap_e, rr_width, th_k):
    """Contact ``idx`` (state idx // 2Z, race idx // Z % 2, ball idx % Z) of :func:`race_contacts`."""
    z = c.shape[1]
    diam = 2.0 * ball_radius
    p_cap = max_barus / c_p if c_p > 0.0 else np.inf
    ib = idx // (2 * z)
    k = (idx // z) % 2
    j = idx % z
    o = ro[ib, k]
    R = rr[ib, k]
    vo = rv[ib, k]
    wr = rw[ib, k]
    ri, zi, tube = groove[k, 0], groove[k, 1], groove[k, 2]
    sgn = sign[k]
    f_conf = conformity[k]
    cx, cy, cz = c[ib, j, 0], c[ib, j, 1], c[ib, j, 2]
    rx_, ry_, rz_ = cx - o[0], cy - o[1], cz - o[2]
    # race-frame position (Rᵀ rel) and the groove torus (MODEL.md §2)
    lx = R[0, 0] * rx_ + R[1, 0] * ry_ + R[2, 0] * rz_
    ly = R[0, 1] * rx_ + R[1, 1] * ry_ + R[2, 1] * rz_
    lz = R[0, 2] * rx_ + R[1, 2] * ry_ + R[2, 2] * rz_
    rho_c = math.hypot(lx, ly)
    ex, ey = lx / rho_c, ly / rho_c
    gx, gy, gz = ri * ex, ri * ey, zi
    dx, dy, dz = lx - gx, ly - gy, lz - gz
    dist = math.sqrt(dx * dx + dy * dy + dz * dz)
    nlx, nly, nlz = dx / dist, dy / dist, dz / dist
    angle = math.atan2(sgn * nlz, sgn * (nlx * ex + nly * ey))
    pen = dist - tube
    penetration[ib, k, j] = pen
    nx = R[0, 0] * nlx + R[0, 1] * nly + R[0, 2] * nlz
    ny = R[1, 0] * nlx + R[1, 1] * nly + R[1, 2] * nlz
    nz = R[2, 0] * nlx + R[2, 1] * nly + R[2, 2] * nlz
    t1x = -R[0, 0] * ey + R[0, 1] * ex  # R (e_z x radial)
    t1y = -R[1, 0] * ey + R[1, 1] * ex
    t1z = -R[2, 0] * ey + R[2, 1] * ex
    t2x = ny * t1z - nz * t1y
    t2y = nz * t1x - nx * t1z
    t2z = nx * t1y - ny * t1x
    # velocities at the contact centre p = c + r n (MODEL.md §6)
    wbx, wby, wbz = w[ib, j, 0], w[ib, j, 1], w[ib, j, 2]
    px, py, pz = ball_radius * nx, ball_radius * ny, ball_radius * nz  # p - c
    qx, qy, qz = rx_ + px, ry_ + py, rz_ + pz  # p - o
    sx = vo[0] + wr[1] * qz - wr[2] * qy - (v[ib, j, 0] + wby * pz - wbz * py)
    sy = vo[1] + wr[2] * qx - wr[0] * qz - (v[ib, j, 1] + wbz * px - wbx * pz)
    sz = vo[2] + wr[0] * qy - wr[1] * qx - (v[ib, j, 2] + wbx * py - wby * px)
    u_x = sx * t1x + sy * t1y + sz * t1z
    u_y = sx * t2x + sy * t2y + sz * t2z
    spin = (wr[0] - wbx) * nx + (wr[1] - wby) * ny + (wr[2] - wbz) * nz
    # groove-centre velocity -> approach rate
    ggx = R[0, 0] * gx + R[0, 1] * gy + R[0, 2] * gz
    ggy = R[1, 0] * gx + R[1, 1] * gy + R[1, 2] * gz
    ggz = R[2, 0] * gx + R[2, 1] * gy + R[2, 2] * gz
    vgx = vo[0] + wr[1] * ggz - wr[2] * ggy
    vgy = vo[1] + wr[2] * ggx - wr[0] * ggz
    vgz = vo[2] + wr[0] * ggy - wr[1] * ggx
    rate = (v[ib, j, 0] - vgx) * nx + (v[ib, j, 1] - vgy) * ny + (v[ib, j, 2] - vgz) * nz
    # the contact moves with the ball's orbit relative to the race
    orx = v[ib, j, 0] - (vo[0] + wr[1] * rz_ - wr[2] * ry_)
    ory = v[ib, j, 1] - (vo[1] + wr[2] * rx_ - wr[0] * rz_)
    orz = v[ib, j, 2] - (vo[2] + wr[0] * ry_ - wr[1] * rx_)
    orbit_rel = (orx * t1x + ory * t1y + orz * t1z) / rho_c
    rho_p = math.hypot(lx + ball_radius * nlx, ly + ball_radius * nly)
    entrainment = -0.5 * u_x - orbit_rel * rho_p
    # Hertz (Brewe–Hamrock fits, MODEL.md §3) and the damped normal load
    r_x = diam * (pitch_diameter + sgn * diam * math.cos(angle)) / (2.0 * pitch_diameter)
    r_y = f_conf * diam / (2.0 * f_conf - 1.0)
    ratio = max(r_y / r_x, 1.0)
    ell = 1.0339 * ratio ** 0.6360
    first = 1.5277 + 0.6023 * math.log(ratio)
    second = 1.0003 + 0.5968 / ratio
    radius = 1.0 / (1.0 / r_x + 1.0 / r_y)
    stiff = math.pi * ell * e_prime * math.sqrt(second * radius / (4.5 * first ** 3))
    q = 0.0
    if pen > 0.0:
        q = stiff * pen ** 1.5
        if damping_ratio > 0.0:
            q += 2.0 * damping_ratio * math.sqrt(1.5 * stiff * math.sqrt(pen) * ball_mass) * rate
        q = max(q, 0.0)
    load[ib, k, j] = q
    fx = 0.0
    fy = 0.0
    mz = 0.0
    m_r = 0.0  # rolling-resistance couple about t2, on the ball
    f_b = 0.0  # and its net force on the ball along t1 at the contact point
    if traction == 1 and q > 0.0:
        base = 6.0 * second * q * radius / (math.pi * e_prime)
        sa = np.cbrt(ell * ell * base)
        sb = np.cbrt(base / ell)
        p_max = 1.5 * q / (math.pi * sa * sb)
        # Hamrock–Dowson central film (P17), floored
        u_d = eta0 * abs(entrainment) / (e_prime * r_x)
        w_d = q / (e_prime * r_x * r_x)
        h = r_x * 2.69 * u_d ** 0.67 * (c_p * e_prime) ** 0.53 * w_d ** -0.067 * (
            1.0 - 0.61 * math.exp(-0.73 * ell))
        phi_t = 1.0
        if th_k > 0.0 and entrainment != 0.0:  # inlet shear heating (MODEL.md §11e)
            u_r = abs(entrainment)
            l_t = eta0 * th_k * u_r * u_r
            s_r = abs(u_x) / u_r
            phi_t = ((1.0 - 13.2 * (p_max / e_prime) * l_t ** 0.42)
                     / (1.0 + 0.213 * (1.0 + 2.23 * s_r ** 0.83) * l_t ** 0.64))
            phi_t = min(max(phi_t, 0.05), 1.0)
        h = max(phi_t * h, min_film)
        fx, fy, mz, _ = _crook_one(u_x, u_y, spin, sa, sb, min(p_max, p_cap), h, eta0, c_p, c1_coef, lam_s,
                                   cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64, kap_e, entrainment)
        if not spin_moment:
            mz = 0.0
        if rr_width > 0.0 and entrainment != 0.0:  # hydrodynamic rolling resistance (MODEL.md §11b)
            kap = min(sb / sa, 1.0)
            rxy = min(r_x / r_y, 1.0)
            beta = (4.0 / math.pi) * (1.0003 + 0.5968 * rxy) / (1.0 + r_x / r_y)
            big_u = 2.0 * eta0 * abs(entrainment) / (e_prime * r_x)
            moes = beta ** 0.25 * kap * (q / (e_prime * r_x * r_x)) / big_u ** 0.75
            ehl = 1.8 * beta ** -0.25
            ivr = 0.77 * beta ** (-1.0 / 3.0) * kap ** 0.12 * big_u ** (-1.0 / 12.0)
            f_r = e_prime * r_x * (2.0 * sa) * ((ivr - ehl) / (1.0 + moes / 6.6) + ehl) * big_u ** 0.75
            c_t = 0.85 / (1.0 + 4.72 * moes ** -0.39 * kap ** (0.484 * moes ** 0.165))
            span = min(2.0 * sa / rr_width, 1.0)
            f_r = phi_t * f_r / (1.0 + (1.0 / c_t - 1.0) * span ** ((2.0 - kap) * (0.0018 * moes + 1.33)))
            w_rel = ((wbx - wr[0]) * t2x + (wby - wr[1]) * t2y + (wbz - wr[2]) * t2z)
            sense = math.tanh(r_x * w_rel / 1e-3)
            m_r = -2.0 * f_r * r_x * sense
            f_b = f_r * (2.0 * r_x / ball_radius - 1.0) * sense
    Fx = -q * nx + fx * t1x + fy * t2x
    Fy = -q * ny + fx * t1y + fy * t2y
    Fz = -q * nz + fx * t1z + fy * t2z
    if f_b != 0.0:  # (a separate sum: the contact without rolling resistance stays bit for bit)
        Fx += f_b * t1x
        Fy += f_b * t1y
        Fz += f_b * t1z
    force[ib, k, j, 0] = Fx
    force[ib, k, j, 1] = Fy
    force[ib, k, j, 2] = Fz
    # lever arm r n: the normal part has no moment about the ball centre
    moment[ib, k, j, 0] = ball_radius * (ny * Fz - nz * Fy) + mz * nx + m_r * t2x
    moment[ib, k, j, 1] = ball_radius * (nz * Fx - nx * Fz) + mz * ny + m_r * t2y
    moment[ib, k, j, 2] = ball_radius * (nx * Fy - ny * Fx) + mz * nz + m_r * t2z


@njit(cache=True, error_model="numpy")
def race_contacts(c, v, w, ro, rr, rv, rw, groove, conformity, sign, ball_radius, pitch_diameter,
                  e_prime, ball_mass, damping_ratio, traction, spin_moment, min_film, eta0, c_p, max_barus,
                  c1_coef, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64, force, moment, penetration, load,
                  lam_s=0.0, kap_e=0.0, rr_width=0.0, th_k=0.0):
    """Forces of the Z balls of B states against both races (MODEL.md §2–§6).

    Parameters
    ----------
    c, v, w : ndarray (B, Z, 3)
        Ball centres (m), velocities (m/s), GLOBAL angular velocities (rad/s).
    ro, rr, rv, rw : ndarray (B, 2, 3), (B, 2, 3, 3), (B, 2, 3), (B, 2, 3)
        Origin, rotation (third column: axis), origin velocity and angular velocity of the
        inner (index 0) and outer (1) race frames.
    groove : ndarray (2, 3)
        Per race: groove-centre radius, axial position (race frame) and (f - 1/2) D, m.
    conformity, sign : ndarray (2,)
        f and the race sign (-1 inner, +1 outer) of :func:`contact.geometry.curvature_radii`.
    cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64 : ndarray
        :func:`crook_tables`.
    traction : int
        0: normal forces only; 1: Crook (fast rule).
    spin_moment : bool
    eta0, c_p, c1_coef, max_barus : float
        η0 (Pa s), c_ηP (1/Pa), c_ηT/(8 K_c), and the bound on c_ηP p_max of the traction.
    lam_s : float, optional
        Limiting-shear coefficient Λ of the smooth cap (MODEL.md §6a); 0 (default): pure
        Crook. Last, so that calls written before it existed keep working.
    kap_e : float, optional
        κ = G/p of the film's elastic compliance (MODEL.md §6b); 0 (default): none.
    rr_width : float, optional
        Hydrodynamic rolling resistance (MODEL.md §11b) with the truncation width 𝓛 (the
        ball diameter), m; 0 (default): none.
    th_k : float, optional
        c_ηT / K_c of the thermal film factor (MODEL.md §11e), m K/W / K; 0 (default): none.
    force, moment : ndarray (B, 2, Z, 3), out
        On each ball at its contact with race k, N; about the ball centre, N m.
    penetration, load : ndarray (B, 2, Z), out
        Elastic approach δ (m) and normal load Q (N).
    """
    for idx in range(c.shape[0] * 2 * c.shape[1]):
        _race_contact(idx, c, v, w, ro, rr, rv, rw, groove, conformity, sign, ball_radius, pitch_diameter,
                      e_prime, ball_mass, damping_ratio, traction, spin_moment, min_film, eta0, c_p, max_barus,
                      c1_coef, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64, force, moment, penetration, load,
                      lam_s, kap_e, rr_width, th_k)


@njit(cache=True, error_model="numpy", parallel=True)
def race_contacts_parallel(c, v, w, ro, rr, rv, rw, groove, conformity, sign, ball_radius, pitch_diameter,
                           e_prime, ball_mass, damping_ratio, traction, spin_moment, min_film, eta0, c_p, max_barus,
                           c1_coef, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64, force, moment, penetration,
                           load, lam_s, kap_e, rr_width, th_k, todo):
    """:func:`race_contacts` with the contacts spread over numba's threads, for the flat
    contact indices ``todo`` only (state idx // 2Z, race idx // Z % 2, ball idx % Z; int64):
    the rest of the outputs is left as it is (a Jacobian's race columns change one race's
    contacts only)."""
    for n in prange(todo.shape[0]):
        idx = todo[n]
        _race_contact(idx, c, v, w, ro, rr, rv, rw, groove, conformity, sign, ball_radius, pitch_diameter,
                      e_prime, ball_mass, damping_ratio, traction, spin_moment, min_film, eta0, c_p, max_barus,
                      c1_coef, cos_tab, sin_tab, wpsi_tab, rho32, w32, rho64, w64, force, moment, penetration, load,
                      lam_s, kap_e, rr_width, th_k)


@njit(cache=True, error_model="numpy")
def land_forces(cage_o, cage_v, race_o, race_v, axis, play, stiffness, damping, force, eccentricity):
    """Guiding-land force on a race-guided cage for B states (cage arrays (B, 3); race
    arrays (B, 3) or (1, 3) for all states) into ``force`` (B, 3), N, and the cage
    eccentricity into ``eccentricity`` (B,), m; as :func:`contact.cage.land_forces`
    (MODEL.md §1)."""
    for b in range(cage_o.shape[0]):
        r = b if race_o.shape[0] > 1 else 0
        d0, d1, d2 = cage_o[b, 0] - race_o[r, 0], cage_o[b, 1] - race_o[r, 1], cage_o[b, 2] - race_o[r, 2]
        da = d0 * axis[r, 0] + d1 * axis[r, 1] + d2 * axis[r, 2]
        e0, e1, e2 = d0 - da * axis[r, 0], d1 - da * axis[r, 1], d2 - da * axis[r, 2]
        e = math.sqrt(e0 * e0 + e1 * e1 + e2 * e2)
        eccentricity[b] = e
        force[b, 0] = force[b, 1] = force[b, 2] = 0.0
        if e > play:
            n0, n1, n2 = e0 / e, e1 / e, e2 / e
            e_dot = ((cage_v[b, 0] - race_v[r, 0]) * n0 + (cage_v[b, 1] - race_v[r, 1]) * n1
                     + (cage_v[b, 2] - race_v[r, 2]) * n2)
            u = min((e - play) / LAND_DAMPING_DEPTH, 1.0)  # contact.cage.contact_ramp
            magnitude = max(stiffness * (e - play) + damping * u * u * (3.0 - 2.0 * u) * e_dot, 0.0)
            force[b, 0], force[b, 1], force[b, 2] = -magnitude * n0, -magnitude * n1, -magnitude * n2


@njit(cache=True, error_model="numpy")
def pocket_friction(cage_force, c, v, wb, cage_o, cage_v, cage_w, ball_radius, mu, slip_scale, friction, point):
    """Ball–pocket friction of B states (MODEL.md §11d), as :func:`contact.cage.pocket_friction`:
    the force on each ball into ``friction`` (B, Z, 3), N, and its contact point into ``point``
    (B, Z, 3), m, from the pocket forces ``cage_force`` (B, Z, 3), N."""
    nb, z = c.shape[0], c.shape[1]
    for ib in range(nb):
        cw0, cw1, cw2 = cage_w[ib, 0], cage_w[ib, 1], cage_w[ib, 2]
        for j in range(z):
            f0, f1, f2 = cage_force[ib, j, 0], cage_force[ib, j, 1], cage_force[ib, j, 2]
            load = math.sqrt(f0 * f0 + f1 * f1 + f2 * f2)
            inv = 1.0 / max(load, 1e-300)
            a0, a1, a2 = -ball_radius * f0 * inv, -ball_radius * f1 * inv, -ball_radius * f2 * inv  # p - c
            p0, p1, p2 = c[ib, j, 0] + a0, c[ib, j, 1] + a1, c[ib, j, 2] + a2
            w0, w1, w2 = wb[ib, j, 0], wb[ib, j, 1], wb[ib, j, 2]
            r0, r1, r2 = p0 - cage_o[ib, 0], p1 - cage_o[ib, 1], p2 - cage_o[ib, 2]
            u0 = v[ib, j, 0] + w1 * a2 - w2 * a1 - (cage_v[ib, 0] + cw1 * r2 - cw2 * r1)
            u1 = v[ib, j, 1] + w2 * a0 - w0 * a2 - (cage_v[ib, 1] + cw2 * r0 - cw0 * r2)
            u2 = v[ib, j, 2] + w0 * a1 - w1 * a0 - (cage_v[ib, 2] + cw0 * r1 - cw1 * r0)
            un = (u0 * f0 + u1 * f1 + u2 * f2) * inv
            t0, t1, t2 = u0 - un * f0 * inv, u1 - un * f1 * inv, u2 - un * f2 * inv
            scale = mu * load / math.sqrt(t0 * t0 + t1 * t1 + t2 * t2 + slip_scale * slip_scale)
            friction[ib, j, 0], friction[ib, j, 1], friction[ib, j, 2] = -scale * t0, -scale * t1, -scale * t2
            point[ib, j, 0], point[ib, j, 1], point[ib, j, 2] = p0, p1, p2


@njit(cache=True, error_model="numpy")
def cage_and_drag(c, v, kind, cage_o, cage_r, cage_v, cage_w, pocket_angles, pitch_radius, clearance,
                  stiffness, damping, axis, origin, drag_factor, cage_force, drag_force):
    """Cage forces (``kind`` 1: rigid cage pockets, MODEL.md §1; 2: spring chain P9/P10;
    0: none) and drag forces (MODEL.md §8, ``drag_factor`` = 1/2 C_D rho pi r², 0: none) on
    the balls of B states, as :mod:`contact.cage`; written into ``cage_force``,
    ``drag_force`` (B, Z, 3)."""
    nb, z = c.shape[0], c.shape[1]
    gap = 0.5 * clearance
    for ib in range(nb):
        for j in range(z):
            for i in range(3):
                cage_force[ib, j, i] = 0.0
                drag_force[ib, j, i] = 0.0
        if kind == 1:
            R = cage_r[ib]
            arm = np.empty(3)  # pocket centre relative to the cage origin
            e = np.empty(3)  # pocket's circumferential direction
            for j in range(z):
                cs, sn = math.cos(pocket_angles[j]), math.sin(pocket_angles[j])
                for i in range(3):
                    arm[i] = pitch_radius * (R[i, 0] * cs + R[i, 1] * sn)
                    e[i] = -R[i, 0] * sn + R[i, 1] * cs
                s = 0.0
                for i in range(3):
                    s += (c[ib, j, i] - cage_o[ib, i] - arm[i]) * e[i]
                wxa0 = cage_w[ib, 1] * arm[2] - cage_w[ib, 2] * arm[1]
                wxa1 = cage_w[ib, 2] * arm[0] - cage_w[ib, 0] * arm[2]
                wxa2 = cage_w[ib, 0] * arm[1] - cage_w[ib, 1] * arm[0]
                s_dot = ((v[ib, j, 0] - cage_v[ib, 0] - wxa0) * e[0] + (v[ib, j, 1] - cage_v[ib, 1] - wxa1) * e[1]
                         + (v[ib, j, 2] - cage_v[ib, 2] - wxa2) * e[2])
                # e turns with the cage (contact.cage.pocket_forces): + (c - centre) . (w x e)
                d0 = c[ib, j, 0] - cage_o[ib, 0] - arm[0]
                d1 = c[ib, j, 1] - cage_o[ib, 1] - arm[1]
                d2 = c[ib, j, 2] - cage_o[ib, 2] - arm[2]
                s_dot += (d0 * (cage_w[ib, 1] * e[2] - cage_w[ib, 2] * e[1])
                          + d1 * (cage_w[ib, 2] * e[0] - cage_w[ib, 0] * e[2])
                          + d2 * (cage_w[ib, 0] * e[1] - cage_w[ib, 1] * e[0]))
                if gap == 0.0:
                    mag = -stiffness * s - damping * s_dot
                else:
                    sgn = 1.0 if s > 0.0 else (-1.0 if s < 0.0 else 0.0)
                    pen = abs(s) - gap
                    mag = -sgn * max(stiffness * pen + damping * s_dot * sgn, 0.0) if pen > 0.0 else 0.0
                for i in range(3):
                    cage_force[ib, j, i] = mag * e[i]
        elif kind == 2:  # torsional springs on the azimuth differences (contact.cage.spring_chain_forces)
            planar = np.empty((z, 3))
            radius = np.empty(z)
            for j in range(z):
                d0, d1, d2 = c[ib, j, 0] - origin[0], c[ib, j, 1] - origin[1], c[ib, j, 2] - origin[2]
                ca = d0 * axis[0] + d1 * axis[1] + d2 * axis[2]
                planar[j, 0], planar[j, 1], planar[j, 2] = d0 - ca * axis[0], d1 - ca * axis[1], d2 - ca * axis[2]
                radius[j] = math.sqrt(planar[j, 0] ** 2 + planar[j, 1] ** 2 + planar[j, 2] ** 2)
            for j in range(z):
                nxt = (j + 1) % z
                a, b = planar[j], planar[nxt]
                crs = ((a[1] * b[2] - a[2] * b[1]) * axis[0] + (a[2] * b[0] - a[0] * b[2]) * axis[1]
                       + (a[0] * b[1] - a[1] * b[0]) * axis[2])
                turn = math.atan2(crs, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])
                torque = stiffness * pitch_radius * pitch_radius * (turn - 2.0 * math.pi / z)
                for k, sgn in ((j, 1.0), (nxt, -1.0)):
                    p = planar[k]
                    e0 = (axis[1] * p[2] - axis[2] * p[1]) / radius[k]
                    e1 = (axis[2] * p[0] - axis[0] * p[2]) / radius[k]
                    e2 = (axis[0] * p[1] - axis[1] * p[0]) / radius[k]
                    mag = sgn * torque / radius[k]
                    cage_force[ib, k, 0] += mag * e0
                    cage_force[ib, k, 1] += mag * e1
                    cage_force[ib, k, 2] += mag * e2
        if drag_factor > 0.0:
            for j in range(z):
                r0, r1, r2 = c[ib, j, 0] - origin[0], c[ib, j, 1] - origin[1], c[ib, j, 2] - origin[2]
                e0 = axis[1] * r2 - axis[2] * r1
                e1 = axis[2] * r0 - axis[0] * r2
                e2 = axis[0] * r1 - axis[1] * r0
                norm = math.sqrt(e0 * e0 + e1 * e1 + e2 * e2)
                e0, e1, e2 = e0 / norm, e1 / norm, e2 / norm
                speed = v[ib, j, 0] * e0 + v[ib, j, 1] * e1 + v[ib, j, 2] * e2
                mag = -drag_factor * abs(speed) * speed
                drag_force[ib, j, 0] = mag * e0
                drag_force[ib, j, 1] = mag * e1
                drag_force[ib, j, 2] = mag * e2

