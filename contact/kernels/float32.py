"""Vectorizable float32 exp, log and tanh for the traction kernels' ray loops.

The PyPI llvmlite has no SVML, so ``math.exp``/``math.log`` stay scalar library calls and
keep LLVM from vectorizing the quadrature; these Cephes polynomials (expf, logf; error
~1 ulp) with bit-level scaling vectorize. ``crook_fast`` on 32 contacts of the reference
bearing's range at order 16: 550 -> 160 us per call.
"""
from __future__ import annotations

import math

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.extending import intrinsic

__all__ = ["FLAGS", "exp32", "log32", "tanh32", "one_minus_exp_neg32", "CAP_X", "CAP_P", "CAP_Q"]

# fast-math flags without 'reassoc' (the (1 + z) - 1 correction of the ray loops must
# survive) and without 'nnan'/'ninf' (NaN and inf are tested for)
FLAGS = {"nsz", "arcp", "contract", "afn"}


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


@njit(cache=True, error_model="numpy", fastmath=FLAGS, inline="always")
def exp32(x):
    """e^x in float32 for 0 <= x (inf above 88; Cephes expf)."""
    p0, p1, p2, p3, p4, p5 = _EXP_P
    v = x * _LOG2E + _ROUND
    n = v - _ROUND
    r = (x - n * _LN2_HI) - n * _LN2_LO
    y = (((((p0 * r + p1) * r + p2) * r + p3) * r + p4) * r + p5) * (r * r) + r + _F1
    scale = _bits_f32(_I((_f32_bits(v) - _ROUND_BITS + _I(127)) << _I(23)))  # 2^n
    return _INF32 if x > _EXP_MAX else y * scale


@njit(cache=True, error_model="numpy", fastmath=FLAGS, inline="always")
def log32(x):
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


# Smooth limiting shear (MODEL.md §6a): τ = τ_L tanh(x) along u, x = |τ_C|/τ_L. tanh(x) for
# x <= CAP_X as x P(x²)/Q(x²), a minimax-weighted least-squares rational fit of tanh(x)/x
# of degree 3/3 in x² (P(0) = Q(0) = 1, so the law is Crook's as x -> 0), x P/Q at CAP_X
# (= tanh to 2.3e-6) beyond: relative error below 3e-6 everywhere (tests/test_limiting_shear.py),
# far below the rule's own error. No exp and one division, so the ray loop still vectorizes.
CAP_X = 6.5
CAP_P = (1.0, 0.1244151739162312, 0.0024030125261559894, 4.54511452920797e-06)
CAP_Q = (1.0, 0.45774726077250827, 0.021654500612336477, 0.00015623762350085177)
_CP32 = tuple(_F(c) for c in CAP_P)
_CQ32 = tuple(_F(c) for c in CAP_Q)
_CAP_X32 = _F(CAP_X)


@njit(cache=True, error_model="numpy", fastmath=FLAGS, inline="always")
def tanh32(x):
    """tanh(x) for x >= 0 by the rational fit above (float32)."""
    p0, p1, p2, p3 = _CP32
    q0, q1, q2, q3 = _CQ32
    xc = min(x, _CAP_X32)
    y = xc * xc
    num = ((p3 * y + p2) * y + p1) * y + p0
    den = ((q3 * y + q2) * y + q1) * y + q0
    return xc * num / den


@njit(cache=True, error_model="numpy", fastmath=FLAGS, inline="always")
def one_minus_exp_neg32(x):
    """1 − e^(−x) for x >= 0 (inf included) in float32, as 2t/(1 + t), t = tanh(x/2) by the
    rational fit of :func:`tanh32` (one division; no cancellation at small x, where
    1 − e^(−x) loses 1e-7/x)."""
    p0, p1, p2, p3 = _CP32
    q0, q1, q2, q3 = _CQ32
    xc = min(_F(0.5) * x, _CAP_X32)
    y = xc * xc
    num = xc * (((p3 * y + p2) * y + p1) * y + p0)
    den = ((q3 * y + q2) * y + q1) * y + q0
    return (num + num) / (den + num)

