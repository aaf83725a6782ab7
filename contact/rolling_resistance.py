"""Hydrodynamic (EHL) rolling resistance of a ball–race contact and the thermal reduction of
its film at speed (MODEL.md §11b, §11e; beyond the paper).

Both act per contact on arrays of contacts (SI units) and are switched on by
:class:`contact.ballrace.ContactLaw` (``rolling_resistance``, ``thermal_film``).
"""
from __future__ import annotations

import numpy as np

__all__ = ["hydrodynamic_rolling_force", "rolling_resistance_force", "rolling_resistance_moment", "thermal_film_factor"]


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
    q = np.asarray(load, dtype=float)
    u = np.abs(np.asarray(entrainment, dtype=float))
    r_x, r_y = np.asarray(r_x, dtype=float), np.asarray(r_y, dtype=float)
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    on = (q > 0) & (u > 0) & (a > 0)
    qs, us = np.where(on, q, 1.0), np.where(on, u, 1.0)
    a_s, b_s = np.where(on, a, 1.0), np.where(on, b, 1.0)
    kappa = np.minimum(b_s / a_s, 1.0)
    ratio = r_x / r_y
    beta = (4.0 / np.pi) * (1.0003 + 0.5968 * np.minimum(ratio, 1.0)) / (1.0 + ratio)
    big_u = 2.0 * viscosity * us / (e_prime * r_x)
    big_w = qs / (e_prime * r_x ** 2)
    moes = beta ** 0.25 * kappa * big_w / big_u ** 0.75
    ehl = 1.8 * beta ** -0.25
    ivr = 0.77 * beta ** (-1.0 / 3.0) * kappa ** 0.12 * big_u ** (-1.0 / 12.0)
    t_star = (2.0 * a_s / r_x) * ((ivr - ehl) / (1.0 + moes / 6.6) + ehl) * big_u ** 0.75
    force = e_prime * r_x ** 2 * t_star
    if width is not None:
        c = 0.85 / (1.0 + 4.72 * moes ** -0.39 * kappa ** (0.484 * moes ** 0.165))
        span = np.minimum(2.0 * a_s / width, 1.0)
        force = force / (1.0 + (1.0 / c - 1.0) * span ** ((2.0 - kappa) * (0.0018 * moes + 1.33)))
    return np.where(on, force, 0.0)


def rolling_resistance_moment(force, r_x, rolling_rate, regularization=1e-3):
    """Couple of the rolling resistance on the ball about the transverse axis t2, N m (MODEL.md
    §11b): -2 f R_x tanh(R_x w_r / u_reg), equal and opposite on the race.

    ``rolling_rate`` w_r = (w_ball - w_race) . t2 (rad/s) is the relative rolling rotation, so
    the couple dissipates 2 f R_x |w_r| = 2 f u_m in pure rolling (R_x |w_r| = u_m): Biboulet &
    Houpert's power loss. It is the moment of the film's forces about the contact point; with
    :func:`rolling_resistance_force` at that point the ball feels f r_b about its centre.
    ``regularization`` u_reg (m/s) smooths the sign through zero rolling."""
    r_x = np.asarray(r_x, dtype=float)
    return -2.0 * np.asarray(force, dtype=float) * r_x * np.tanh(r_x * np.asarray(rolling_rate, dtype=float)
                                                                   / regularization)


def rolling_resistance_force(force, r_x, ball_radius, rolling_rate, regularization=1e-3):
    """Net tangential force of the rolling resistance on the ball at the contact point along
    the rolling direction t1, N (MODEL.md §11b); the race takes the opposite force there.

    The film shears each surface by f against its motion relative to the contact, and its
    pressure, whose resultant lies 2 f R_x / Q upstream of the contact centre (Biboulet &
    Houpert 2010, part 1, eqs. 32-37), pushes each body by 2 f R_x / R_body along it through
    that body's centre (Balan, Houpert et al. 2015, Lubricants 3, 222: the pressure force
    2 F_R through the ball centre). On the ball (R_body = r_b) the sum is
    f (2 R_x / r_b - 1) along its surface's motion tanh(R_x w_r / u_reg) t1; with the couple of
    :func:`rolling_resistance_moment` the moment about the ball centre is -f r_b."""
    r_x = np.asarray(r_x, dtype=float)
    return (np.asarray(force, dtype=float) * (2.0 * r_x / ball_radius - 1.0)
            * np.tanh(r_x * np.asarray(rolling_rate, dtype=float) / regularization))


def thermal_film_factor(entrainment, slip, max_pressure, e_prime, viscosity, temperature_viscosity,
                        thermal_conductivity, floor=0.05):
    """Inlet-shear-heating reduction of the isothermal film thickness, φ_T in (0, 1] (MODEL.md §11e).

    Zhu & Cheng's fit as given by Zhou & Hoeprich (1991, ASME J. Tribol. 113, 590, eq. 21)
    and Gupta et al. (1992, ASME J. Tribol. 114, 707):

        φ_T = (1 - 13.2 (p_H/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64),
        L = (-dη/dT) u_r² / K = η0 c_ηT u_r² / K,   S = |u_s| / u_r,

    u_r the rolling (entrainment) speed, u_s the sliding speed along it. Clipped to
    [``floor``, 1] (the fit's numerator turns negative far outside its data).
    """
    u_r = np.abs(np.asarray(entrainment, dtype=float))
    loading = viscosity * temperature_viscosity * u_r ** 2 / thermal_conductivity
    s = np.abs(np.asarray(slip, dtype=float)) / np.where(u_r > 0, u_r, 1.0)
    phi = ((1.0 - 13.2 * (np.asarray(max_pressure, dtype=float) / e_prime) * loading ** 0.42)
           / (1.0 + 0.213 * (1.0 + 2.23 * s ** 0.83) * loading ** 0.64))
    return np.clip(np.where(u_r > 0, phi, 1.0), floor, 1.0)
