"""A ball's own surface (MODEL.md §13; beyond the paper): pits and waviness fixed in the ball's
material, which its two contacts meet as the ball turns. The records are
:class:`contact.surface.Defect` (``race = 'ball'``) and :class:`contact.surface.Waviness`
(``ball``); :func:`contact.surface.surface_record` puts them in the kernels' arrays.

* **Ball waviness**: h = Σ A_k cos(k φ + φ_k), φ the contact's longitude on the ball about its
  start spin axis (eq. 13.6): an even order changes the ball's diameter between its two
  (opposite) contacts, an odd one only shifts it.
* **Ball defect**: a round pit of diameter L on a ball, fixed in the ball's material. At each
  of its two contacts the pit's centre sits at (along, across) = r (atan2(d·t1, d·n),
  atan2(d·t2, d·n)) from the contact, d its direction from the ball centre; the contact path
  crosses it on a chord ℓ = 2 √((L/2)² − across²), over which eq. 13.2 holds with ℓ for L
  (eq. 13.3, :func:`ball_height`). The pit meets a race once per turn of the ball relative to
  the contact: where both contacts trace its circle (0° contact angle), the two races
  together at twice the ball-spin frequency.

The height enters the contact as a race surface's does (stage 0 of :mod:`contact.terms`,
:func:`contact.terms.ball_surface_height`), read with the ball's rotation matrix.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .surface import SurfaceRecord, path_drop, rim_drop

__all__ = ["ball_height", "ball_heights", "pit_path", "pit_paths"]


@njit(cache=True, error_model="numpy", inline="always")
def pit_path(pit, rotation, normal, rolling, transverse, ball_radius):
    """Where a pit (a row of ``SurfaceRecord.ball_defects``) lies on the path of one contact
    (eq. 13.3): its direction d from the ball centre (global, (3,)), c = d·n, a = d·t1, the
    distance of its centre from the contact along t1, r atan2(a, c) (m), and the chord ℓ (m)
    the contact's path crosses it on; ℓ = 0 where the path misses it (its centre on the
    ball's other half, or |across| ≥ L/2)."""
    d = np.empty(3)
    for r in range(3):
        d[r] = rotation[r, 0] * pit[1] + rotation[r, 1] * pit[2] + rotation[r, 2] * pit[3]
    c = d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]
    a = d[0] * rolling[0] + d[1] * rolling[1] + d[2] * rolling[2]
    if c <= 0.0:  # on the ball's other half
        return d, c, a, 0.0, 0.0
    e = d[0] * transverse[0] + d[1] * transverse[1] + d[2] * transverse[2]
    half = 0.5 * pit[4]
    across = ball_radius * math.atan2(e, c)
    if abs(across) >= half:
        return d, c, a, 0.0, 0.0
    return d, c, a, ball_radius * math.atan2(a, c), 2.0 * math.sqrt(half * half - across * across)


@njit(cache=True, error_model="numpy")
def _pit_paths(pits, rotation, normal, rolling, transverse, ball_radius, out):
    for i in range(pits.shape[0]):
        for k in range(normal.shape[0]):
            _, _, _, out[0, i, k], out[1, i, k] = pit_path(pits[i], rotation[k], normal[k], rolling[k], transverse[k],
                                                           ball_radius)


def pit_paths(surface: SurfaceRecord, rotation, normal, rolling, transverse, ball_radius) -> np.ndarray:
    """:func:`pit_path` of every pit of ``surface`` at n contacts of its ball (each pit at the
    contacts given: select them by ``ball_defects[:, 0]``): ``rotation`` (n, 3, 3), the
    contact vectors (n, 3). Returns (2, pits, n): the distance of the pit's centre from the
    contact along t1, m, and the chord, m (0: the path misses it)."""
    def arr(x):
        return np.ascontiguousarray(x, dtype=float)

    out = np.empty((2, surface.ball_defects.shape[0], len(normal)))
    _pit_paths(arr(surface.ball_defects), arr(rotation), arr(normal), arr(rolling), arr(transverse),
               float(ball_radius), out)
    return out


@njit(cache=True, error_model="numpy")
def ball_height(surface, ball, race, rotation, normal, rolling, transverse, relative_omega, ball_radius,
                rolling_radius):
    """(h m, dh/dt m/s, G (3,) m/rad) of the pits (eq. 13.3) and the waviness (eq. 13.6) of
    ``ball`` at its contact with ``race`` (0 inner, 1 outer): G = ∂h/∂φ, the height's change per radian the ball turns
    relative to the contact frame (about each global axis), so dh/dt = G·ω_rel and the contact's
    generalized forces are −Q G on the ball's rotation and, as the frame turns with the ball
    centre's azimuth, −Q (e·G)/ρ_c along t1 (eq. 13.7b).
    ``rotation`` the ball's body-to-global rotation (3, 3); the contact's ``normal`` n,
    ``rolling`` t1 and ``transverse`` t2 (global unit vectors, (3,)); ``relative_omega`` ω_rel the
    ball's angular velocity relative to the contact frame, which turns with the ball's orbit
    (ω_ball − Ω_orbit e_axis, rad/s, (3,)); ``ball_radius`` r and R_x in m."""
    h = 0.0
    g = np.zeros(3)
    pits = surface.ball_defects
    for i in range(pits.shape[0]):
        if int(pits[i, 0]) != ball:
            continue
        d, c, a, along, chord = pit_path(pits[i], rotation, normal, rolling, transverse, ball_radius)
        if chord <= 0.0:
            continue
        half = 0.5 * pits[i, 4]
        e = d[0] * transverse[0] + d[1] * transverse[1] + d[2] * transverse[2]
        across = ball_radius * math.atan2(e, c)
        if pits[i, 6] > 0.0:  # edge ramps: along the chord the path crosses (eq. 13.3)
            x = along + 0.5 * chord
            if x <= 0.0 or x >= chord:
                continue
            drop, slope = path_drop(x, chord, pits[i, 5], min(pits[i, 6], 0.5 * chord), rolling_radius)
            s_x, s_y = -slope, 0.0  # (the contact sits at −along from the pit's centre)
        else:  # a sharp round pit: the ball rests on its rim in both directions (eq. 13.3b)
            if along * along + across * across >= half * half:
                continue
            drop, s_x, s_y = rim_drop(-along, -across, half, half, pits[i, 5], rolling_radius, pits[i, 7 + race])
        h -= drop
        # d turns by dφ x d: d(along) = dφ · r d x (c t1 − a n)/(a² + c²), d(across) likewise with
        # t2 and e; the contact sits at (−along, −across) from the pit: dh = s_x d(along) + s_y d(across)
        f = s_x * ball_radius / (a * a + c * c)
        vx, vy, vz = c * rolling[0] - a * normal[0], c * rolling[1] - a * normal[1], c * rolling[2] - a * normal[2]
        g[0] += f * (d[1] * vz - d[2] * vy)
        g[1] += f * (d[2] * vx - d[0] * vz)
        g[2] += f * (d[0] * vy - d[1] * vx)
        if s_y != 0.0:
            f = s_y * ball_radius / (e * e + c * c)
            vx, vy, vz = (c * transverse[0] - e * normal[0], c * transverse[1] - e * normal[1],
                          c * transverse[2] - e * normal[2])
            g[0] += f * (d[1] * vz - d[2] * vy)
            g[1] += f * (d[2] * vx - d[0] * vz)
            g[2] += f * (d[0] * vy - d[1] * vx)
    waves = surface.ball_waviness
    if waves.shape[0] > 0:
        # the contact direction in the ball's body frame n_b = Aᵀ n: turning the ball by dφ moves
        # it by −Aᵀ (dφ x n), so d(n_b·z) = −dφ · (n x A z)
        nb = np.empty(3)
        for r in range(3):
            nb[r] = rotation[0, r] * normal[0] + rotation[1, r] * normal[1] + rotation[2, r] * normal[2]
        for i in range(waves.shape[0]):
            if int(waves[i, 0]) != ball:
                continue
            z = np.array([waves[i, 4], waves[i, 5], waves[i, 6]])
            ax = np.array([waves[i, 7], waves[i, 8], waves[i, 9]])
            y = np.array([ax[1] * z[2] - ax[2] * z[1], ax[2] * z[0] - ax[0] * z[2], ax[0] * z[1] - ax[1] * z[0]])
            x_b, y_b = nb[0] * z[0] + nb[1] * z[1] + nb[2] * z[2], nb[0] * y[0] + nb[1] * y[1] + nb[2] * y[2]
            zg, yg = rotation @ z, rotation @ y  # the longitude's zero and its quarter, global
            arg = waves[i, 1] * math.atan2(y_b, x_b) + waves[i, 3]
            h += waves[i, 2] * math.cos(arg)
            # dh = −A k sin(arg) (x dy − y dx)/(x² + y²), dx = −dφ·(n x zg), dy = −dφ·(n x yg)
            f = waves[i, 2] * waves[i, 1] * math.sin(arg) / (x_b * x_b + y_b * y_b)
            g[0] += f * (x_b * (normal[1] * yg[2] - normal[2] * yg[1]) - y_b * (normal[1] * zg[2] - normal[2] * zg[1]))
            g[1] += f * (x_b * (normal[2] * yg[0] - normal[0] * yg[2]) - y_b * (normal[2] * zg[0] - normal[0] * zg[2]))
            g[2] += f * (x_b * (normal[0] * yg[1] - normal[1] * yg[0]) - y_b * (normal[0] * zg[1] - normal[1] * zg[0]))
    rate = g[0] * relative_omega[0] + g[1] * relative_omega[1] + g[2] * relative_omega[2]
    return h, rate, g


@njit(cache=True, error_model="numpy")
def _ball_heights(surface, ball, race, rotation, normal, rolling, transverse, relative_omega, ball_radius,
                  rolling_radius, out):
    for i in range(ball.shape[0]):
        out[0, i], out[1, i], g = ball_height(surface, ball[i], race[i], rotation[i], normal[i], rolling[i],
                                              transverse[i], relative_omega[i], ball_radius, rolling_radius[i])
        out[2:, i] = g


def ball_heights(surface: SurfaceRecord, ball, race, rotation, normal, rolling, transverse, relative_omega, ball_radius,
                 rolling_radius) -> np.ndarray:
    """:func:`ball_height` for n contacts (the numpy path): ``ball`` and ``race`` (n,), ``rotation``
    (n, 3, 3), the vectors (n, 3), ``rolling_radius`` (n,). Rows (h m, dh/dt m/s, G_x, G_y, G_z
    m/rad), (5, n)."""
    def arr(x):
        return np.ascontiguousarray(x, dtype=float)

    ball = np.ascontiguousarray(ball, dtype=np.int64)
    race = np.ascontiguousarray(np.broadcast_to(race, ball.shape), dtype=np.int64)
    out = np.empty((5, ball.shape[0]))
    _ball_heights(surface, ball, race, arr(rotation), arr(normal), arr(rolling), arr(transverse), arr(relative_omega),
                  float(ball_radius), arr(np.broadcast_to(rolling_radius, ball.shape)), out)
    return out
