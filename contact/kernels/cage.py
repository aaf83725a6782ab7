"""Cage and ball drag of a whole bearing, compiled, for B states at once (MODEL.md §1, §8,
§11d; P9, P10): the rigid cage's pockets or the paper's spring chain, the ball drag, the
ball–pocket friction and the guiding land, as the numpy functions of :mod:`contact.cage`.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..cage import LAND_DAMPING_DEPTH
from ..land_film import LAND_FILM_MAX_RATIO, film_force_vector

__all__ = ["cage_and_drag", "land_forces", "pocket_friction"]


@njit(cache=True, error_model="numpy")
def land_forces(cage_o, cage_v, race_o, race_v, axis, play, stiffness, damping, film, spin_sum, force, eccentricity):
    """Guiding-land force on a race-guided cage for B states (cage arrays (B, 3); race
    arrays (B, 3) or (1, 3) for all states) into ``force`` (B, 3), N, and the cage
    eccentricity into ``eccentricity`` (B,), m: the contact beyond the play as
    :func:`contact.cage.land_forces` and, with ``film`` K > 0 (N s), the oil film's
    short-bearing force at the surfaces' speeds ``spin_sum`` (B,) rad/s as
    :func:`contact.land_film.land_film_forces` (MODEL.md §1, §11d)."""
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
        if film > 0.0:
            f0, f1, f2 = film_force_vector((e0, e1, e2), (cage_v[b, 0] - race_v[r, 0], cage_v[b, 1] - race_v[r, 1],
                                                          cage_v[b, 2] - race_v[r, 2]),
                                           (axis[r, 0], axis[r, 1], axis[r, 2]), spin_sum[b], film, play,
                                           LAND_FILM_MAX_RATIO)
            force[b, 0] += f0
            force[b, 1] += f1
            force[b, 2] += f2


@njit(cache=True, error_model="numpy")
def pocket_friction(cage_force, balls, cage, ball_radius, mu, slip_scale, friction, point):
    """Ball–pocket friction of B states (MODEL.md §11d), as :func:`contact.cage.pocket_friction`:
    the force on each ball (:class:`~contact.kernels.records.BallStates`) into ``friction``
    (B, Z, 3), N, and its contact point into ``point`` (B, Z, 3), m, from the pocket forces
    ``cage_force`` (B, Z, 3), N, the cage's :class:`~contact.kernels.records.BodyStates`, the
    friction coefficient ``mu`` and the ``slip_scale`` (m/s) that smooths it."""
    c, v, wb = balls.position, balls.velocity, balls.omega
    cage_o, cage_v, cage_w = cage.position, cage.velocity, cage.omega
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
def cage_and_drag(c, v, params, cage, cage_force, drag_force):
    """Cage forces (``params.kind`` 1: rigid cage pockets, MODEL.md §1; 2: spring chain
    P9/P10; 0: none) and drag forces (MODEL.md §8, §11c: ``params.drag_factor`` = 1/2 C_D rho pi
    r² and the jet momentum's ``params.drag_linear`` k, 0: none) on the balls of B states
    (centres ``c`` m, velocities ``v`` m/s, (B, Z, 3)), as
    :mod:`contact.cage`; ``params`` a :class:`~contact.kernels.records.CageRecord`, ``cage``
    the cage body's :class:`~contact.kernels.records.BodyStates`; written into
    ``cage_force``, ``drag_force`` (B, Z, 3)."""
    kind, pocket_angles = params.kind, params.pocket_angles
    pitch_radius, clearance = params.pitch_radius, params.clearance
    stiffness, damping, axis, origin = params.stiffness, params.damping, params.axis, params.origin
    drag_factor, drag_linear = params.drag_factor, params.drag_linear
    cage_o, cage_r, cage_v, cage_w = cage.position, cage.rotation, cage.velocity, cage.omega
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
        if drag_factor > 0.0 or drag_linear > 0.0:
            for j in range(z):
                r0, r1, r2 = c[ib, j, 0] - origin[0], c[ib, j, 1] - origin[1], c[ib, j, 2] - origin[2]
                e0 = axis[1] * r2 - axis[2] * r1
                e1 = axis[2] * r0 - axis[0] * r2
                e2 = axis[0] * r1 - axis[1] * r0
                norm = math.sqrt(e0 * e0 + e1 * e1 + e2 * e2)
                e0, e1, e2 = e0 / norm, e1 / norm, e2 / norm
                speed = v[ib, j, 0] * e0 + v[ib, j, 1] * e1 + v[ib, j, 2] * e2
                mag = -(drag_factor * abs(speed) + drag_linear) * speed
                drag_force[ib, j, 0] = mag * e0
                drag_force[ib, j, 1] = mag * e1
                drag_force[ib, j, 2] = mag * e2


