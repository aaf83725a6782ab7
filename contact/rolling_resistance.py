"""Hydrodynamic (EHL) rolling resistance of a ball–race contact (MODEL.md §11b; beyond the paper).

A per-contact term (:mod:`contact.terms`), written once as scalar numba functions that the
compiled kernels call per contact and the array functions below apply element by element
(:mod:`contact.elementwise`); switched on by :class:`contact.ballrace.ContactLaw` (``rolling_resistance``).
"""
from __future__ import annotations

import math

from numba import njit

from .elementwise import apply, at
from .hertz import fit_second_integral

__all__ = ["hydrodynamic_rolling_force", "rolling_resistance_force", "rolling_resistance_moment",
           "rolling_loads", "hydrodynamic_force"]

#: slip speed u_reg (m/s) that smooths the sign of the rolling resistance through zero rolling
ROLLING_REGULARIZATION = 1e-3


@njit(cache=True, error_model="numpy")
def hydrodynamic_force(load, entrainment, r_x, r_y, a, b, e_prime, viscosity, width, film_factor):
    """f of :func:`hydrodynamic_rolling_force` for one contact, N, times ``film_factor`` (the
    thermal φ_T of MODEL.md §11e, 1: none); ``width`` <= 0: no truncation; 0 for an unloaded
    contact or zero entrainment."""
    u = abs(entrainment)
    if not (load > 0.0 and u > 0.0 and a > 0.0):
        return 0.0
    kap = min(b / a, 1.0)
    beta = (4.0 / math.pi) * fit_second_integral(max(r_y / r_x, 1.0)) / (1.0 + r_x / r_y)
    big_u = 2.0 * viscosity * u / (e_prime * r_x)
    moes = beta ** 0.25 * kap * (load / (e_prime * r_x * r_x)) / big_u ** 0.75
    ehl = 1.8 * beta ** -0.25
    ivr = 0.77 * beta ** (-1.0 / 3.0) * kap ** 0.12 * big_u ** (-1.0 / 12.0)
    f_r = e_prime * r_x * (2.0 * a) * ((ivr - ehl) / (1.0 + moes / 6.6) + ehl) * big_u ** 0.75
    if width <= 0.0:
        return film_factor * f_r
    c_t = 0.85 / (1.0 + 4.72 * moes ** -0.39 * kap ** (0.484 * moes ** 0.165))
    span = min(2.0 * a / width, 1.0)
    return film_factor * f_r / (1.0 + (1.0 / c_t - 1.0) * span ** ((2.0 - kap) * (0.0018 * moes + 1.33)))


@njit(cache=True, error_model="numpy")
def rolling_loads(force, r_x, ball_radius, rolling_rate):
    """(couple about t2, N m; force along t1 at the contact point, N) of the rolling resistance
    on the ball (MODEL.md §11b): -2 f R_x s and f (2 R_x / r_b - 1) s with the sense
    s = tanh(R_x w_r / u_reg); the race takes the opposite of both.

    ``rolling_rate`` w_r = (w_ball - w_race) . t2 (rad/s) is the relative rolling rotation, so
    the couple dissipates 2 f R_x |w_r| = 2 f u_m in pure rolling (R_x |w_r| = u_m): Biboulet &
    Houpert's power loss. The couple is the moment of the film's forces about the contact
    point. The film shears each surface by f against its motion relative to the contact, and
    its pressure, whose resultant lies 2 f R_x / Q upstream of the contact centre (Biboulet &
    Houpert 2010, part 1, eqs. 32-37), pushes each body by 2 f R_x / R_body along it through
    that body's centre (Balan, Houpert et al. 2015, Lubricants 3, 222: the pressure force
    2 F_R through the ball centre); with the couple, the moment about the ball centre is
    -f r_b."""
    sense = math.tanh(r_x * rolling_rate / ROLLING_REGULARIZATION)
    return -2.0 * force * r_x * sense, force * (2.0 * r_x / ball_radius - 1.0) * sense


@njit(cache=True, error_model="numpy")
def _hydrodynamic_forces(out, load, entrainment, r_x, r_y, a, b, e_prime, viscosity, width, film_factor):
    for i in range(out.size):
        out[i] = hydrodynamic_force(at(load, i), at(entrainment, i), at(r_x, i), at(r_y, i), at(a, i), at(b, i),
                                    at(e_prime, i), at(viscosity, i), at(width, i), at(film_factor, i))


@njit(cache=True, error_model="numpy")
def _couples(out, force, r_x, rolling_rate):
    for i in range(out.size):
        out[i] = rolling_loads(at(force, i), at(r_x, i), 1.0, at(rolling_rate, i))[0]


@njit(cache=True, error_model="numpy")
def _pushes(out, force, r_x, ball_radius, rolling_rate):
    for i in range(out.size):
        out[i] = rolling_loads(at(force, i), at(r_x, i), at(ball_radius, i), at(rolling_rate, i))[1]


def hydrodynamic_rolling_force(load, entrainment, r_x, r_y, a, b, e_prime, viscosity, width=None):
    """Fully flooded hydrodynamic rolling force f of an elliptical EHL contact, N (MODEL.md §11b).

    Biboulet & Houpert (2010), "Hydrodynamic force and moment in pure rolling lubricated
    contacts. Part 2: point contacts", Proc. IMechE J 224, 777–787, eq. (32), one fit over the
    isoviscous-rigid and elastohydrodynamic regimes:

        T* = (2a/R_x) [(0.77 β^(-1/3) κ^0.12 U^(-1/12) - 1.8 β^(-1/4)) / (1 + M/6.6) + 1.8 β^(-1/4)] U^(3/4),
        f = E' R_x² T*,

    U = 2 η0 u_m / (E' R_x), W = Q / (E' R_x²), κ = b/a, β = (4/π) 𝓔 / (1 + R_x/R_y) (𝓔 the
    complete elliptic integral of the second kind, Brewe–Hamrock's fit 1.0003 + 0.5968 R_x/R_y),
    M = β^(1/4) κ W / U^(3/4); times the truncation factor of their eqs. (35)–(36) for a
    contact of width 2a on a race or ball of ``width`` 𝓛 (2a/𝓛 capped at 1).

    f is the Poiseuille shear force the film puts on each surface against the rolling; the
    moment about each body is f R_x (their T ≈ F) and the power lost in pure rolling
    2 f u_m (part 1, DOI 10.1243/13506501JET790).

    Parameters
    ----------
    load : array
        Q, N (0 where unloaded).
    entrainment : array
        u_m, mean surface speed relative to the contact, m/s (its magnitude is used).
    r_x, r_y : array
        Reduced radii along and across the rolling direction, m.
    a, b : array
        Hertz semi-axes across and along the rolling direction, m.
    e_prime : float
        E', 2/E' = (1 - ν1²)/E1 + (1 - ν2²)/E2, Pa (Hamrock–Dowson's convention).
    viscosity : float or array
        η0 at the inlet, Pa s.
    width : float, optional
        𝓛 of the truncation factor, m (the ball diameter); None: no truncation.
    """
    return apply(_hydrodynamic_forces, load, entrainment, r_x, r_y, a, b, float(e_prime), viscosity,
                 0.0 if width is None else float(width), 1.0)


def rolling_resistance_moment(force, r_x, rolling_rate):
    """Couple of the rolling resistance on the ball about the transverse axis t2, N m
    (:func:`rolling_loads`, MODEL.md §11b), on arrays; equal and opposite on the race."""
    return apply(_couples, force, r_x, rolling_rate)


def rolling_resistance_force(force, r_x, ball_radius, rolling_rate):
    """Net tangential force of the rolling resistance on the ball at the contact point along
    the rolling direction t1, N (:func:`rolling_loads`, MODEL.md §11b), on arrays; the race
    takes the opposite force there."""
    return apply(_pushes, force, r_x, float(ball_radius), rolling_rate)
