"""The guiding land's oil film as a short journal bearing (MODEL.md §11d, eq. 11d.1).

A race-guided cage ring (radius R, width L) runs in its land with radial play c. With
eccentricity ratio ε = e/c, its rate ε̇ (1/s), the whirl φ̇ of the line of centres and the
surfaces' speeds ω_cage + ω_land about the axis, Ocvirk's short-bearing solution of
Reynolds' equation with the π (half-Sommerfeld) film gives, on the cage,

    F_r = K [ε² |ω_e| / (1 − ε²)² + π (1 + 2ε²) ε̇ / (2 (1 − ε²)^(5/2))]      back towards the centre
    F_t = K s [π ε |ω_e| / (4 (1 − ε²)^(3/2)) + 2 ε ε̇ / (1 − ε²)²]           along axis × n

K = η R L³ / c², ω_e = ω_cage + ω_land − 2 φ̇, s = sign(ω_e) (the film's pressure half
follows the wedge). Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication*
(2004), ch. 10 (short-width journal bearing); Childs, *Turbomachinery Rotordynamics* (1993),
§3 (the π-film forces with whirl and squeeze). Steady (φ̇ = ε̇ = 0) it is Ocvirk's load
W = K ω ε √(16 ε² + π² (1 − ε²)) / (4 (1 − ε²)²) at attitude tan ψ = π √(1 − ε²) / (4 ε).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["LAND_FILM_MAX_RATIO", "film_constant", "short_bearing_force", "film_force_vector", "land_film_forces",
           "steady_eccentricity"]

#: ε beyond which the film's force stays at its value there (a numerical guard: the film
#: force diverges as ε -> 1; past the play the land's contact spring takes over)
LAND_FILM_MAX_RATIO = 0.995


def film_constant(viscosity, radius, width, radial_clearance):
    """K = η R L³ / c² of :func:`short_bearing_force`, N s (SI inputs)."""
    return viscosity * radius * width ** 3 / radial_clearance ** 2


@njit(cache=True, error_model="numpy")
def short_bearing_force(eps, radial_rate, whirl_rate, spin_sum, constant, max_ratio):
    """(F_r, F_t) of the short-bearing π film on the journal, N (module docstring):
    F = −F_r n + F_t (axis × n), n the unit eccentricity. ``eps`` ε, ``radial_rate`` ε̇ 1/s,
    ``whirl_rate`` ε φ̇ 1/s (finite at ε = 0), ``spin_sum`` ω_cage + ω_land rad/s,
    ``constant`` K N s; ε taken at most ``max_ratio``."""
    e = min(eps, max_ratio)
    s = 1.0 - e * e
    wedge = e * spin_sum - 2.0 * whirl_rate  # ε ω_e
    sign = 1.0 if wedge >= 0.0 else -1.0
    f_r = constant * (e * abs(wedge) / (s * s) + math.pi * (1.0 + 2.0 * e * e) * radial_rate / (2.0 * s * s * math.sqrt(s)))
    f_t = constant * (math.pi * wedge / (4.0 * s * math.sqrt(s)) + sign * 2.0 * e * radial_rate / (s * s))
    return f_r, f_t


@njit(cache=True, error_model="numpy")
def film_force_vector(offset, rate, axis, spin_sum, constant, radial_clearance, max_ratio):
    """The film's force (3-tuple, N) on the cage of one state: :func:`short_bearing_force` turned
    to the unit offset n (tuples of 3: ``offset`` e m, its ``rate`` m/s, the unit ``axis``); the
    rate's axial part dropped. At e = 0, n is the rate's direction (the film then damps:
    −K π ė / (2c))."""
    a0, a1, a2 = axis
    v0, v1, v2 = rate
    va = v0 * a0 + v1 * a1 + v2 * a2  # the rate in the bearing plane
    v0, v1, v2 = v0 - va * a0, v1 - va * a1, v2 - va * a2
    e = math.sqrt(offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2])
    if e > 1e-12 * radial_clearance:
        n0, n1, n2 = offset[0] / e, offset[1] / e, offset[2] / e
    else:  # centred: the film damps along the motion
        size = max(math.sqrt(v0 * v0 + v1 * v1 + v2 * v2), 1e-300)
        n0, n1, n2 = v0 / size, v1 / size, v2 / size
    t0, t1, t2 = a1 * n2 - a2 * n1, a2 * n0 - a0 * n2, a0 * n1 - a1 * n0
    f_r, f_t = short_bearing_force(e / radial_clearance, (v0 * n0 + v1 * n1 + v2 * n2) / radial_clearance,
                                   (v0 * t0 + v1 * t1 + v2 * t2) / radial_clearance, spin_sum, constant, max_ratio)
    return -f_r * n0 + f_t * t0, -f_r * n1 + f_t * t1, -f_r * n2 + f_t * t2


def land_film_forces(offset, offset_rate, axis, spin_sum, constant, radial_clearance, max_ratio=LAND_FILM_MAX_RATIO):
    """The film's force on the cage, (B, 3) N, from its radial ``offset`` e (B, 3) m and its
    rate (B, 3) m/s, the unit ``axis`` (B, 3), ``spin_sum`` ω_cage + ω_land (B,) rad/s, K (N s)
    and c (m): :func:`film_force_vector` per state."""
    offset, offset_rate, axis = (np.atleast_2d(np.asarray(x, dtype=float)) for x in (offset, offset_rate, axis))
    spin_sum = np.broadcast_to(np.asarray(spin_sum, dtype=float), offset.shape[:1])
    force = np.zeros_like(offset)
    for b in range(offset.shape[0]):
        force[b] = film_force_vector(tuple(offset[b]), tuple(offset_rate[b]), tuple(axis[b]), float(spin_sum[b]),
                                     constant, radial_clearance, max_ratio)
    return force


def steady_eccentricity(load, constant, spin_sum, max_ratio=LAND_FILM_MAX_RATIO):
    """ε at which the steady film (no whirl, no squeeze) carries ``load`` N: Ocvirk's
    W(ε) = K |ω| ε √(16 ε² + π² (1 − ε²)) / (4 (1 − ε²)²) = load, by bisection (W rises
    with ε); None where even ``max_ratio`` cannot carry it."""
    def carried(eps):
        return math.hypot(*short_bearing_force(eps, 0.0, 0.0, spin_sum, constant, max_ratio))

    if load <= 0:
        return 0.0
    if carried(max_ratio) < load:
        return None
    low, high = 0.0, max_ratio
    for _ in range(60):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if carried(mid) < load else (low, mid)
    return 0.5 * (low + high)
