"""Hamrock–Dowson EHD film thickness for elliptical contacts (MODEL.md §5, paper P17).

The central film is written once, :func:`central_film` (a scalar numba function the compiled
kernels call), and applied to arrays by :func:`central_film_thickness`.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .elementwise import apply, at

__all__ = ["central_film", "central_film_thickness", "minimum_film_thickness"]


@njit(cache=True, error_model="numpy")
def central_film(speed, load, r_x, ellipticity, e_prime, viscosity, pressure_viscosity):
    """Central film thickness h_c of one contact, m (P17): entrainment ``speed`` u (m/s, its
    magnitude is used), load Q > 0 (N), R_x (m), k, E' (Pa), eta_0 (Pa s), c_etaP (1/Pa);
    h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k))."""
    u_d = viscosity * abs(speed) / (e_prime * r_x)
    w_d = max(load, 2.2250738585072014e-308) / (e_prime * r_x * r_x)
    return r_x * 2.69 * u_d ** 0.67 * (pressure_viscosity * e_prime) ** 0.53 * w_d ** -0.067 * (
        1.0 - 0.61 * math.exp(-0.73 * ellipticity))


@njit(cache=True, error_model="numpy")
def _central_film(out, speed, load, r_x, ellipticity, e_prime, viscosity, pressure_viscosity):
    for i in range(out.size):
        out[i] = central_film(at(speed, i), at(load, i), at(r_x, i), at(ellipticity, i), at(e_prime, i),
                              at(viscosity, i), at(pressure_viscosity, i))


def _dimensionless(entrainment_speed, load, r_x, e_prime, lubricant):
    speed = np.abs(np.asarray(entrainment_speed, dtype=float))
    load = np.asarray(load, dtype=float)
    if np.any(load < 0) or np.any(~np.isfinite(load)):
        raise ValueError(f"load must be finite and non-negative, got {load!r}")
    u = lubricant.viscosity * speed / (e_prime * r_x)
    g = lubricant.pressure_viscosity * e_prime
    w = np.maximum(load, np.finfo(float).tiny) / (e_prime * np.square(r_x))
    return u, g, w


def central_film_thickness(entrainment_speed, load, r_x, ellipticity, e_prime, lubricant):
    """Central film thickness h_c, m (P17):
    h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)).

    Parameters
    ----------
    entrainment_speed : array_like
        Mean rolling speed u = (u_1 + u_2)/2 of the two surfaces relative to the
        contact, m/s (its magnitude is used).
    load : array_like
        Normal load Q, N.
    r_x : array_like
        Rolling-direction curvature radius R_x, m.
    ellipticity : array_like
        k = a/b.
    e_prime : float
        Effective modulus E', Pa.
    lubricant : contact.lubricant.Lubricant
        eta_0 and c_etaP are used (isothermal inlet at T_R).
    """
    _dimensionless(entrainment_speed, load, r_x, e_prime, lubricant)  # the inputs' checks
    return apply(_central_film, entrainment_speed, load, r_x, ellipticity, float(e_prime), float(lubricant.viscosity),
                 float(lubricant.pressure_viscosity))


def minimum_film_thickness(entrainment_speed, load, r_x, ellipticity, e_prime, lubricant):
    """Minimum film thickness h_min, m (Hamrock & Dowson 1977):
    h_min / R_x = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)). Arguments as
    :func:`central_film_thickness`."""
    u, g, w = _dimensionless(entrainment_speed, load, r_x, e_prime, lubricant)
    return r_x * 3.63 * u ** 0.68 * g ** 0.49 * w ** -0.073 * (1.0 - np.exp(-0.68 * np.asarray(ellipticity)))
