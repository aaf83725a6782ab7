"""The Crook traction by the fast rule, compiled: one contact at a time (MODEL.md §6, P12–P16;
the smooth limiting shear of §6a and the film's elastic compliance of §6b).

:func:`crook_one` follows :func:`contact.traction_fast._fast_crook` (the numpy version, the
reference) one contact at a time: the same node tables, float32 along each ray, float64 for
the rare ray whose ψ overflows float32. :func:`crook_fast` evaluates n contacts (a recorded run's outputs, tests and
benchmarks; from :data:`PARALLEL_CONTACTS` on numba's threads).
"""
from __future__ import annotations

import math
import threading

import numba
import numpy as np
from numba import njit, prange

from .. import traction_fast as _tr
from .float32 import FLAGS as _FLAGS
from .float32 import exp32 as _exp32
from .float32 import log32 as _log32
from .float32 import one_minus_exp_neg32 as _one_minus_exp_neg32
from .float32 import tanh32 as _tanh32
from .records import CrookScratch, CrookTables, LawRecord, traction_record

_F = np.float32
_F1 = _F(1.0)

__all__ = ["crook_fast", "crook_law", "crook_one", "crook_scratch", "crook_tables"]

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


def _vector_lanes() -> int:
    """float32 lanes of the vectors numba compiles the ray loops for on this host: 16 where
    that was measured (AMD Zen 5, ``znver5``: LLVM vectorizes them with AVX-512), else 8, the
    AVX2 width (other processors are not measured, and a target other than the host,
    ``NUMBA_CPU_NAME``, may have other vectors)."""
    try:
        from llvmlite import binding

        wide = binding.get_host_cpu_name().startswith("znver5") and binding.get_host_cpu_features().get("avx512f")
    except Exception:  # noqa: BLE001 - a host llvmlite cannot describe gets the AVX2 width
        wide = False
    return 16 if wide and not numba.config.CPU_NAME else 8


#: the rays are padded to a multiple of this (padding rays have ρ_max = 0): a loop over rays
#: that is not a whole number of vectors ends in scalar code, which on a 16-lane host took
#: the 36 rays of order 16 (40 padded to 8 lanes: two vectors and 8 scalar rays) from 81 to
#: 96 µs for 32 contacts. Results differ between hosts of other widths by float32 rounding
#: (2e-8 N on those contacts)
LANES = _vector_lanes()


def crook_tables(order: int = 16) -> CrookTables:
    """The fast rule's node tables (:func:`contact.traction_fast._fast_tables`) as a
    :class:`~contact.kernels.records.CrookTables` record."""
    tab = _tr._fast_tables(int(order))
    psi, wpsi, rho, w = (np.ascontiguousarray(tab[k], dtype=np.float64) for k in ("psi", "wpsi", "rho", "w"))
    return CrookTables(np.cos(psi), np.sin(psi), wpsi, rho.astype(np.float32), w.astype(np.float32), rho, w)



@njit(cache=True, error_model="numpy")
def crook_scratch(tables):
    """The work arrays of :func:`crook_one` for ``tables`` (:class:`CrookScratch`), for one
    thread's loop over contacts; the rays padded to :data:`LANES`."""
    n_rays = tables.cos_psi.shape[0]
    padded = (n_rays + LANES - 1) // LANES * LANES
    return CrookScratch(np.empty((8, n_rays)), np.zeros((4, padded), np.float32), np.zeros((6, padded), np.float32),
                        np.empty((3, padded), np.float32), np.zeros(7), np.empty(7, np.float32), np.empty(8))


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
    """g of one node with the film's elastic compliance (MODEL.md §6b) and, for
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
    f = _one_minus_exp_neg32(d / (tc * er0))  # 1 − e^(−1/R), R = τ_v/|τ_e| (inf where τ_v = 0: 1)
    if tlc32 > _F(0.0):
        return (tlc32 * sg * eh) * _tanh32(tc * f * itlc32 / sg) / sq
    return tc * f * eh / sq


@njit(cache=True, error_model="numpy", fastmath=_FLAGS)
def _rays32_elastic(ir, lam, a0, tlc, rho_tab, w_tab, ray, el64, k, el):
    """:func:`_rays32` with the film's elastic compliance (MODEL.md §6b): g (1 − e^(−1/R)),
    R = τ_v/|τ_e| = τ_C' er0/(σ |Ξ| |w|), Ξ = ξ/b the distance from the inlet edge and w the
    strain rate averaged since the inlet; then the smooth limiting shear for ``tlc`` > 0.
    ``ray`` rows 4, 5: the ray's direction (c, s) in normalized coordinates; ``el64``: Xo,
    Yo (ray origin, normalized), sign ū, ω b, v_y at the origin, er0 = η_T |ū|/(√c_th κ p_max b)
    and 1/c_th; ``el`` (7,) float32 receives them."""
    rm, r2, cq, br, cd, sd = ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]
    k0, k1, k2 = k[0], k[1], k[2]
    lamh32, a032 = _F(0.5 * lam), _F(a0)
    tlc32 = _F(tlc)
    itlc32 = _F(1.0 / tlc) if tlc > 0.0 else _F(0.0)
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
def _ray_sums(geo, d, a0, lam, tlc, ir, rho_tab, w_tab, scratch, el):
    """Sums along ray ``d`` of g W ρ^j, j = 0, 1, 2, as :func:`_rays32` (``tlc`` > 0: with
    the limiting shear of :func:`_rays32_capped`; ``el[5]`` > 0: with the film's elastic
    compliance of :func:`_rays32_elastic`) in the tables' precision: float64 for the rare ray
    whose ψ overflows float32. ``geo`` rows: ρ_max, ρ_2, C, B, -, -, and the ray's direction
    (c, s); ``scratch`` (dtype of the tables) casts the ray constants."""
    rmax, r2, cq, br, cd, sd = geo[0, d], geo[1, d], geo[2, d], geo[3, d], geo[6, d], geo[7, d]
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
        if el[5] > 0.0:  # the film's elastic compliance (MODEL.md §6b)
            tc = g * math.sqrt(psi / e)  # τ_C'
            yy = el[1] + rho * sd
            xi = el[0] + rho * cd + el[2] * math.sqrt(max(1.0 - yy * yy, 0.0))
            oxi = el[3] * xi
            w2 = (psi / e) * el[6] + oxi * (0.25 * oxi - el[4] - el[3] * cd * rho)
            dd = sg * abs(xi) * math.sqrt(max(w2, 0.0)) + 1e-30
            den = tc * el[5]
            g *= -math.expm1(-dd / den) if den > 0.0 else 1.0
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
def _pole_rule(ux, uy, om, a, b, lo, lam, cth):
    """The spin pole and the rule of one contact (as :func:`contact.traction_fast._fast_pole`):
    (angular table column, radial table column, first main breakpoint θ0, ray origin X, Y
    and 1 − |O|², slip at the origin u_Ox, u_Oy)."""
    hi = max(a, b)
    a_long = a >= b
    ab = a * b
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
    return ie, ir, th0, Xo, Yo, rO, uOx, uOy


# no reference counting, as contact.kernels.race._race_contact, its caller in a run (it allocates
# nothing; set here so the flag does not depend on which caller compiles it first)
@njit(cache=True, error_model="numpy", _nrt=False)
def crook_one(ux, uy, om, a, b, pm, hh, ent, law, tables, scratch):
    """(f_x, f_y, M_z, heat) of one contact by the fast rule (MODEL.md §6; see
    :func:`contact.traction_fast._fast_crook`, whose steps this follows one contact at a time).

    Parameters
    ----------
    ux, uy, om : float
        Slip (race − ball) along and across the rolling direction, m/s, and spin, rad/s.
    a, b, pm, hh : float
        Hertz semi-axes across and along the rolling direction (m), p_max (Pa), film h (m).
    ent : float
        Signed entrainment speed, m/s (the film's elastic compliance, §6b).
    law : LawRecord
        η0, c_ηP, c_ηT/(8 K_c), the limiting shear Λ (§6a; 0: none) and κ = G/p (§6b; 0: none).
    tables : CrookTables
    scratch : CrookScratch
        :func:`crook_scratch` of ``tables`` (overwritten).
    """
    eta_t, c_p, c1_coef, lam_s, kap_e = law.eta0, law.c_p, law.c1_coef, law.limiting_shear, law.film_modulus
    cos_tab, sin_tab, wpsi_tab = tables.cos_psi, tables.sin_psi, tables.wpsi
    rho32, w32, rho64, w64 = tables.rho32, tables.w32, tables.rho64, tables.w64
    lo = min(a, b)
    if not lo > 0.0:
        return 0.0, 0.0, 0.0, 0.0
    ab = a * b
    lam = c_p * pm
    cth = c1_coef * eta_t
    ie, ir, th0, Xo, Yo, rO, uOx, uOy = _pole_rule(ux, uy, om, a, b, lo, lam, cth)
    wc = 2.0 * om * cth
    a0 = (uOx * uOx + uOy * uOy) * cth + _PSI_MIN
    w2c = om * om * cth
    # rays: float64 geometry, float32 constants padded to a multiple of LANES
    n_rays = cos_tab.shape[0]
    c0, s0 = math.cos(th0), math.sin(th0)
    elastic = kap_e > 0.0 and ent != 0.0
    geo = scratch.geo
    ray = scratch.ray6 if elastic else scratch.ray4
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
    # the padding rays repeat ray 0 (their sums are never read): with zeros (ρ_max = 0, σ = 0)
    # their lanes divided by zero and made subnormal numbers, slow on Intel processors (32
    # contacts of the elastic, limited law: 205 -> 132 us on a 2-core Xeon)
    for d in range(n_rays, ray.shape[1]):
        for i in range(ray.shape[0]):
            ray[i, d] = ray[i, 0]
    k = scratch.sums
    tlc = lam_s * pm * hh * math.sqrt(cth) / eta_t  # τ_L' = tlc σ in the rule's units
    el = scratch.elastic
    el[:] = 0.0
    if elastic:
        el[0], el[1] = Xo, Yo
        el[2] = 1.0 if ent > 0.0 else -1.0
        el[3], el[4] = om * b, uOy
        el[5] = eta_t * abs(ent) / (math.sqrt(cth) * kap_e * pm * b)
        el[6] = 1.0 / cth
        _rays32_elastic(ir, lam, a0, tlc, rho32, w32, ray, el, k, scratch.elastic32)
    elif tlc > 0.0:
        _rays32_capped(ir, lam, a0, tlc, rho32, w32, ray, k)
    else:
        _rays32(ir, lam, a0, rho32, w32, ray, k)
    s64 = scratch.wide
    S0 = 0.0
    Sx = 0.0
    Sy = 0.0
    Sr = 0.0
    scale = ab * eta_t / hh
    for d in range(n_rays):
        rmax, bc, as_ = geo[0, d], geo[4, d], geo[5, d]
        k0, k1, k2 = float(k[0, d]), float(k[1, d]), float(k[2, d])
        if not (abs(k0) < np.inf and abs(k1) < np.inf and abs(k2) < np.inf):
            k0, k1, k2 = _ray_sums(geo, d, a0, lam, tlc, ir, rho64, w64, s64, el)
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
def _crook_many(ux, uy, om, a, b, pm, hh, ent, law, tables, out):
    scratch = crook_scratch(tables)
    for i in range(ux.shape[0]):
        out[0, i], out[1, i], out[2, i], out[3, i] = crook_one(ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i], ent[i],
                                                               law, tables, scratch)


@njit(cache=True, error_model="numpy", parallel=True)
def _crook_many_prange(ux, uy, om, a, b, pm, hh, ent, flat_law, tables, out, chunks):
    """:func:`_crook_many` on numba's threads in ``chunks`` pieces, each with its own work arrays
    (the law crosses the parallel loop as a flat tuple, rebuilt per chunk)."""
    n = ux.shape[0]
    for c in prange(chunks):
        law = LawRecord(*flat_law)
        scratch = crook_scratch(tables)
        for i in range(c * n // chunks, (c + 1) * n // chunks):
            out[0, i], out[1, i], out[2, i], out[3, i] = crook_one(ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i],
                                                                   ent[i], law, tables, scratch)


#: chunks of contacts per thread in the threaded loops (:func:`crook_fast`,
#: :func:`contact.kernels.race.race_contacts_parallel`): each chunk makes its work arrays once,
#: and several per thread even out loaded and unloaded contacts
CHUNKS_PER_THREAD = 4


def thread_chunks(n: int) -> int:
    """Chunks for a threaded loop over ``n`` contacts: :data:`CHUNKS_PER_THREAD` per numba
    thread, at most ``n`` (counted here, in Python: ``numba.get_num_threads()`` inside a kernel
    makes it uncachable)."""
    return min(n, CHUNKS_PER_THREAD * numba.get_num_threads())

#: contacts from which :func:`crook_fast` spreads its loop over numba's threads (a recorded
#: run's outputs: the reference bearing's 0.1 s, 32 000 contacts, 0.151 -> 0.10 s on 2 cores;
#: one state's 32 contacts stay on one thread)
PARALLEL_CONTACTS = 512


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
    law = traction_record(lubricant, limiting_shear, film_modulus)
    # from the main thread only: a threaded caller (a Dask worker thread) runs serially, as
    # the race kernels do (exudyn_bearing.model.compiled: numba's workqueue layer serves one
    # caller at a time)
    if n >= PARALLEL_CONTACTS and threading.current_thread() is threading.main_thread():
        _crook_many_prange(*args, ent, tuple(law), crook_tables(order), out, thread_chunks(n))
    else:
        _crook_many(*args, ent, law, crook_tables(order), out)
    return out


def crook_law(slip, a, b, p_max, load, h, entrainment, lubricant, law):
    """The Crook laws' ``evaluate`` (:class:`contact.traction_laws.TractionModel`) by this
    compiled fast rule, for the n loaded contacts: :func:`crook_fast` with the law's order,
    limiting shear (§6a) and film elasticity (§6b); the kernel the dynamic model's forces run
    on, within 3e-4 of the numpy fast rule (tests/test_compiled.py)."""
    from ..traction_law import Traction

    fx, fy, mz, heat = crook_fast(*slip, a, b, p_max, h, lubricant, order=law.quadrature_order,
                                  limiting_shear=law.limiting_shear_for(lubricant),
                                  film_modulus=law.film_modulus_for(lubricant), entrainment=entrainment)
    return Traction(fx, fy, mz, heat)
