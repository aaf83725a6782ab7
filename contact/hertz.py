"""Hertz elliptical point contact (MODEL.md §3, paper P1–P3).

Conventions: x is the rolling direction, y the transverse one (across the groove).
``a`` is the transverse semi-axis, ``b`` the rolling one; for a ball in a groove
R_y > R_x, so a > b and the ellipticity k = a/b >= 1.

The contact is described by its curvature sum 1/R = 1/R_x + 1/R_y, the radius ratio
alpha_r = R_y / R_x and the effective modulus E' = 2 / ((1-nu1²)/E1 + (1-nu2²)/E2).
Everything is vectorized: pass arrays of contacts. The laws the compiled kernels share
(:mod:`contact.kernels.race`) are written once, as scalar numba functions (``fit_*``,
:func:`stiffness_of`, :func:`semi_axis_of`, :func:`max_pressure_of`) that the kernels call
and the array functions here apply element by element (:mod:`contact.elementwise`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy import optimize, special

from .elementwise import apply, at

__all__ = [
    "effective_modulus", "brewe_hamrock", "exact_ellipticity", "HertzContact",
    "hertz_contact", "effective_ball_stiffness", "fit_ellipticity", "fit_first_integral", "fit_second_integral",
    "stiffness_of", "semi_axis_of", "max_pressure_of",
]


def effective_modulus(youngs_1, poisson_1, youngs_2=None, poisson_2=None):
    """E' = 2 / ((1-nu1²)/E1 + (1-nu2²)/E2), Pa (MODEL.md §3).

    With only the first body given, both bodies are of the same material.
    """
    if youngs_2 is None:
        youngs_2, poisson_2 = youngs_1, poisson_1
    for name, value in (("youngs_modulus", youngs_1), ("youngs_modulus", youngs_2)):
        if not np.all(np.asarray(value) > 0):
            raise ValueError(f"{name} (youngs_1, youngs_2) must be positive, got {value!r}")
    for value in (poisson_1, poisson_2):
        if not np.all((np.asarray(value) > -1) & (np.asarray(value) < 0.5)):
            raise ValueError(f"poisson_ratio (poisson_1, poisson_2) must lie in (-1, 0.5), got {value!r}")
    return 2.0 / ((1 - np.square(poisson_1)) / youngs_1 + (1 - np.square(poisson_2)) / youngs_2)


@njit(cache=True, error_model="numpy")
def fit_ellipticity(ratio):
    """k = a/b of radius ratio alpha_r = R_y/R_x >= 1 by the Brewe–Hamrock fit (MODEL.md §3)."""
    return 1.0339 * ratio ** 0.6360


@njit(cache=True, error_model="numpy")
def fit_first_integral(ratio):
    """Elliptic integral of the first kind F by the Brewe–Hamrock fit (MODEL.md §3)."""
    return 1.5277 + 0.6023 * math.log(ratio)


@njit(cache=True, error_model="numpy")
def fit_second_integral(ratio):
    """Elliptic integral of the second kind E by the Brewe–Hamrock fit (MODEL.md §3)."""
    return 1.0003 + 0.5968 / ratio


@njit(cache=True, error_model="numpy")
def stiffness_of(ellipticity, first, second, radius, e_prime):
    """Hertz constant K of Q = K delta^(3/2), N/m^1.5 (P2), from k, F, E, the curvature
    radius R (1/R = 1/R_x + 1/R_y, m) and E' (Pa)."""
    return math.pi * ellipticity * e_prime * math.sqrt(second * radius / (4.5 * first ** 3))


@njit(cache=True, error_model="numpy")
def semi_axis_of(load, ellipticity, second, radius, e_prime, transverse):
    """Hertz semi-axis under load Q (N, >= 0), m (MODEL.md §3): ``transverse`` a, else the
    rolling b; a = (k² 6 E Q R / (pi E'))^(1/3), b = (6 E Q R / (pi E' k))^(1/3)."""
    base = 6.0 * second * load * radius / (math.pi * e_prime)
    if transverse:
        return np.cbrt(ellipticity * ellipticity * base)
    return np.cbrt(base / ellipticity)


@njit(cache=True, error_model="numpy")
def max_pressure_of(load, a, b):
    """Peak pressure p_max = 3Q / (2 pi a b), Pa; 0 for an unloaded contact."""
    if load > 0.0:
        return 1.5 * load / (math.pi * a * b)
    return 0.0


@njit(cache=True, error_model="numpy")
def _fits(out_k, out_first, out_second, ratio):
    for i in range(ratio.size):
        out_k[i] = fit_ellipticity(ratio[i])
        out_first[i] = fit_first_integral(ratio[i])
        out_second[i] = fit_second_integral(ratio[i])


@njit(cache=True, error_model="numpy")
def _stiffness(out, ellipticity, first, second, radius, e_prime):
    for i in range(out.size):
        out[i] = stiffness_of(at(ellipticity, i), at(first, i), at(second, i), at(radius, i), at(e_prime, i))


@njit(cache=True, error_model="numpy")
def _semi_axes(out_a, out_b, load, ellipticity, second, radius, e_prime):
    for i in range(out_a.size):
        q, k, e, r, ep = at(load, i), at(ellipticity, i), at(second, i), at(radius, i), at(e_prime, i)
        out_a[i] = semi_axis_of(q, k, e, r, ep, True)
        out_b[i] = semi_axis_of(q, k, e, r, ep, False)


@njit(cache=True, error_model="numpy")
def _max_pressure(out, load, a, b):
    for i in range(out.size):
        out[i] = max_pressure_of(at(load, i), at(a, i), at(b, i))


def brewe_hamrock(radius_ratio):
    """Ellipticity k and elliptic integrals F (first kind), E (second kind) by the
    Brewe–Hamrock (1977) fits (MODEL.md §3).

    Parameters
    ----------
    radius_ratio : array_like
        alpha_r = R_y / R_x >= 1.

    Returns
    -------
    k, first, second : ndarray
    """
    alpha_r = np.asarray(radius_ratio, dtype=float)
    flat = np.ascontiguousarray(alpha_r).reshape(-1)
    k, first, second = np.empty(flat.size), np.empty(flat.size), np.empty(flat.size)
    _fits(k, first, second, flat)
    if not alpha_r.shape:  # numpy floats for a scalar ratio, as before
        return k[0], first[0], second[0]
    return k.reshape(alpha_r.shape), first.reshape(alpha_r.shape), second.reshape(alpha_r.shape)


def _complete_integrals(k):
    """Complete elliptic integrals K(e), E(e) for eccentricity e² = 1 - 1/k²."""
    p = 1.0 / np.square(k)  # complementary parameter 1 - m, kept accurate for large k
    return special.ellipkm1(p), special.ellipe(1.0 - p)


def _radius_ratio_of(k):
    """alpha_r = (k² E - F) / (F - E): exact Hertz relation between ellipticity and
    the ratio of principal relative curvatures (Johnson, Contact Mechanics §4.2)."""
    first, second = _complete_integrals(k)
    return (np.square(k) * second - first) / (first - second)


def exact_ellipticity(radius_ratio):
    """Exact ellipticity k and elliptic integrals F, E for alpha_r = R_y / R_x.

    Root-finds k in alpha_r = (k² E(e) - F(e)) / (F(e) - E(e)), e² = 1 - 1/k², with
    ``scipy.special.ellipkm1/ellipe``. This is the oracle the Brewe–Hamrock fits
    approximate; alpha_r = 1 returns the circular contact k = 1, F = E = pi/2.
    """
    alpha_r = np.atleast_1d(np.asarray(radius_ratio, dtype=float))
    if np.any(~np.isfinite(alpha_r)) or np.any(alpha_r < 1.0):
        raise ValueError(f"radius_ratio must be finite and >= 1, got {radius_ratio!r}")
    k = np.ones_like(alpha_r)
    for i, target in enumerate(alpha_r.flat):
        if target > 1.0 + 1e-12:
            # alpha_r grows like k^(1/0.636) roughly; bracket generously
            k.flat[i] = optimize.brentq(lambda kk: _radius_ratio_of(kk) - target,
                                        1.0 + 1e-9, 2.0 * target + 2.0, xtol=1e-14, rtol=1e-14)
    first, second = _complete_integrals(k)
    first = np.where(k == 1.0, np.pi / 2, first)
    second = np.where(k == 1.0, np.pi / 2, second)
    shape = np.shape(radius_ratio)
    return k.reshape(shape), first.reshape(shape), second.reshape(shape)


@dataclass(frozen=True)
class HertzContact:
    """Load-independent description of a set of elliptical contacts (MODEL.md §3).

    Attributes
    ----------
    stiffness : ndarray
        K in Q = K delta^(3/2), N/m^1.5 (P2).
    ellipticity, first_integral, second_integral : ndarray
        k = a/b, F, E.
    curvature_radius : ndarray
        R with 1/R = 1/R_x + 1/R_y, m.
    effective_modulus : float or ndarray
        E', Pa.
    """

    stiffness: np.ndarray
    ellipticity: np.ndarray
    first_integral: np.ndarray
    second_integral: np.ndarray
    curvature_radius: np.ndarray
    effective_modulus: np.ndarray

    def load(self, deflection):
        """Normal load Q = K max(delta, 0)^(3/2), N (P1)."""
        return self.stiffness * np.maximum(np.asarray(deflection, dtype=float), 0.0) ** 1.5

    def deflection(self, load):
        """Deflection delta = (Q/K)^(2/3), m (P1)."""
        load = np.asarray(load, dtype=float)
        if np.any(~np.isfinite(load)) or np.any(load < 0):
            raise ValueError(f"load must be finite and non-negative, got {load!r}")
        return (load / self.stiffness) ** (2.0 / 3.0)

    def semi_axes(self, load):
        """Semi-axes (a transverse, b rolling), m, for load Q (MODEL.md §3)."""
        load = np.maximum(np.asarray(load, dtype=float), 0.0)
        parts = (load, self.ellipticity, self.second_integral, self.curvature_radius, self.effective_modulus)
        return apply(_semi_axes, *parts, outputs=2)

    def max_pressure(self, load):
        """Peak pressure p_max = 3Q / (2 pi a b), Pa; 0 for an unloaded contact."""
        load = np.maximum(np.asarray(load, dtype=float), 0.0)
        return apply(_max_pressure, load, *self.semi_axes(load))


def hertz_contact(r_x, r_y, e_prime, method="fit"):
    """Hertz contact constants for curvature radii R_x (rolling) and R_y (transverse).

    Parameters
    ----------
    r_x, r_y : array_like
        Principal relative radii of curvature, m, with R_y >= R_x.
    e_prime : float or array_like
        Effective modulus E', Pa (:func:`effective_modulus`).
    method : {'fit', 'exact'}
        Brewe–Hamrock fits (the paper's choice, fast) or the exact elliptic solution.
    """
    r_x = np.asarray(r_x, dtype=float)
    r_y = np.asarray(r_y, dtype=float)
    if np.any(~np.isfinite(r_x)) or np.any(r_x <= 0):
        raise ValueError(f"r_x must be positive, got {r_x!r}")
    if np.any(~np.isfinite(r_y)) or np.any(r_y < r_x * (1 - 1e-12)):
        raise ValueError(f"r_y must be finite and >= r_x (transverse radius is the larger), got {r_y!r}")
    ratio = np.maximum(r_y / r_x, 1.0)
    if method == "fit":
        k, first, second = brewe_hamrock(ratio)
    elif method == "exact":
        k, first, second = exact_ellipticity(ratio)
    else:
        raise ValueError(f"method must be 'fit' or 'exact', got {method!r}")
    radius = 1.0 / (1.0 / r_x + 1.0 / r_y)
    stiffness = apply(_stiffness, k, first, second, radius, e_prime)
    return HertzContact(stiffness, k, first, second, radius, np.asarray(e_prime, dtype=float))


def effective_ball_stiffness(k_inner, k_outer):
    """Series stiffness of a ball between two races, K_eff = [K_i^(-2/3) + K_o^(-2/3)]^(-3/2),
    N/m^1.5 (P3)."""
    return (np.asarray(k_inner, dtype=float) ** (-2.0 / 3.0) + np.asarray(k_outer, dtype=float) ** (-2.0 / 3.0)) ** -1.5
