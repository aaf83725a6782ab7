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

from .surface import SurfaceRecord, path_drop

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
def ball_height(surface, ball, rotation, normal, rolling, transverse, relative_omega, ball_radius, rolling_radius):
    """(h m, dh/dt m/s, dh/ds) of the pits (eq. 13.3) and the waviness (eq. 13.6) of ``ball`` at
    one of its contacts, s the contact's position along t1 (the slope that tilts the contact
    force, eq. 13.7):
    ``rotation`` the ball's body-to-global rotation (3, 3); the contact's ``normal`` n,
    ``rolling`` t1 and ``transverse`` t2 (global unit vectors, (3,)); ``relative_omega`` the
    ball's angular velocity relative to the contact frame, which turns with the ball's orbit
    (ω_ball − Ω_orbit e_axis, rad/s, (3,)); ``ball_radius`` r and R_x in m."""
    h = 0.0
    rate = 0.0
    tilt = 0.0  # dh/ds, s the contact's position along t1 on the ball (eq. 13.7)
    pits = surface.ball_defects
    for i in range(pits.shape[0]):
        if int(pits[i, 0]) != ball:
            continue
        d, c, a, along, chord = pit_path(pits[i], rotation, normal, rolling, transverse, ball_radius)
        if chord <= 0.0:
            continue
        x = along + 0.5 * chord
        if x <= 0.0 or x >= chord:
            continue
        drop, slope = path_drop(x, chord, pits[i, 5], min(pits[i, 6], 0.5 * chord), rolling_radius)
        # d(along)/dt: d turns with the ball's spin relative to the contact frame
        wx, wy, wz = relative_omega[0], relative_omega[1], relative_omega[2]
        ddx, ddy, ddz = wy * d[2] - wz * d[1], wz * d[0] - wx * d[2], wx * d[1] - wy * d[0]
        a_t = ddx * rolling[0] + ddy * rolling[1] + ddz * rolling[2]
        c_t = ddx * normal[0] + ddy * normal[1] + ddz * normal[2]
        h -= drop
        rate -= slope * ball_radius * (a_t * c - a * c_t) / (a * a + c * c)
        tilt += slope  # the pit's centre is at 'along' from the contact: d(along)/ds = -1
    waves = surface.ball_waviness
    if waves.shape[0] == 0:
        return h, rate, tilt
    # the contact direction in the ball's body frame, n_b = Aᵀ n, and its rate -Aᵀ (w_rel x n)
    wx, wy, wz = relative_omega[0], relative_omega[1], relative_omega[2]
    mx = wy * normal[2] - wz * normal[1]
    my = wz * normal[0] - wx * normal[2]
    mz = wx * normal[1] - wy * normal[0]
    nb = np.empty(3)
    nd = np.empty(3)
    ns = np.empty(3)  # d n_b / ds: the contact moved by ds along t1 over the ball
    for r in range(3):
        nb[r] = rotation[0, r] * normal[0] + rotation[1, r] * normal[1] + rotation[2, r] * normal[2]
        nd[r] = -(rotation[0, r] * mx + rotation[1, r] * my + rotation[2, r] * mz)
        ns[r] = (rotation[0, r] * rolling[0] + rotation[1, r] * rolling[1] + rotation[2, r] * rolling[2]) / ball_radius
    for i in range(waves.shape[0]):
        if int(waves[i, 0]) != ball:
            continue
        z0, z1, z2 = waves[i, 4], waves[i, 5], waves[i, 6]
        a0, a1, a2 = waves[i, 7], waves[i, 8], waves[i, 9]
        y0, y1, y2 = a1 * z2 - a2 * z1, a2 * z0 - a0 * z2, a0 * z1 - a1 * z0  # axis x zero
        x = nb[0] * z0 + nb[1] * z1 + nb[2] * z2
        y = nb[0] * y0 + nb[1] * y1 + nb[2] * y2
        x_t = nd[0] * z0 + nd[1] * z1 + nd[2] * z2
        y_t = nd[0] * y0 + nd[1] * y1 + nd[2] * y2
        x_s = ns[0] * z0 + ns[1] * z1 + ns[2] * z2
        y_s = ns[0] * y0 + ns[1] * y1 + ns[2] * y2
        arg = waves[i, 1] * math.atan2(y, x) + waves[i, 3]
        h += waves[i, 2] * math.cos(arg)
        rate -= waves[i, 2] * waves[i, 1] * math.sin(arg) * (x * y_t - y * x_t) / (x * x + y * y)
        tilt -= waves[i, 2] * waves[i, 1] * math.sin(arg) * (x * y_s - y * x_s) / (x * x + y * y)
    return h, rate, tilt


@njit(cache=True, error_model="numpy")
def _ball_heights(surface, ball, rotation, normal, rolling, transverse, relative_omega, ball_radius, rolling_radius,
                  out):
    for i in range(ball.shape[0]):
        out[0, i], out[1, i], out[2, i] = ball_height(surface, ball[i], rotation[i], normal[i], rolling[i],
                                                      transverse[i], relative_omega[i], ball_radius,
                                                      rolling_radius[i])


def ball_heights(surface: SurfaceRecord, ball, rotation, normal, rolling, transverse, relative_omega, ball_radius,
                 rolling_radius) -> np.ndarray:
    """:func:`ball_height` for n contacts (the numpy path): ``ball`` (n,), ``rotation``
    (n, 3, 3), the vectors (n, 3), ``rolling_radius`` (n,). Rows (h m, dh/dt m/s, dh/ds), (3, n)."""
    def arr(x):
        return np.ascontiguousarray(x, dtype=float)

    ball = np.ascontiguousarray(ball, dtype=np.int64)
    out = np.empty((3, ball.shape[0]))
    _ball_heights(surface, ball, arr(rotation), arr(normal), arr(rolling), arr(transverse), arr(relative_omega),
                  float(ball_radius), arr(np.broadcast_to(rolling_radius, ball.shape)), out)
    return out
