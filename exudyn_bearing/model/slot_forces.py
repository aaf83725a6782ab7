"""The connector's generalized forces per node slot from its ball–race contacts, compiled:
each ball's contact forces and moments, cage and drag forces and pocket friction on the ball
and, as reactions, on the races and cage (:func:`assemble`), the guiding land (:func:`land`),
the applied force, held components and driven races (:func:`applied_held_driven`), and all of
it for the block Jacobian's states in one call (:func:`batch_tail`). Shared by the one-state
residual and the batch of :mod:`exudyn_bearing.model.compiled`; same equations and conventions
as :meth:`BearingConnector._batch_forces` (the numpy path): a global force F enters as F, a
global torque tau of a ``NodeRigidBodyRotVecLG`` as A^T tau.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from contact import kernels
from contact.kernel_cache import drop_stale

# these kernels call the contact/ kernels: recompile them when those changed
drop_stale(__file__, [__file__, *kernels.SOURCES])

__all__ = ["HELD_NONE", "HELD_ROTATION", "HELD_ALL", "Mount", "Guide", "add_reaction", "assemble", "land",
           "applied_held_driven", "batch_tail"]

HELD_NONE, HELD_ROTATION, HELD_ALL = 0, 1, 2


class Mount(NamedTuple):
    """Where a connector's bodies sit among its nodes (per-slot arrays: slot = node index)."""

    balls: np.ndarray  #: (Z,) slot of each ball, int64
    slots: np.ndarray  #: (2,) slot of the inner and outer race, -1: kinematic race
    cage_slot: int  #: slot of the rigid cage, -1: none
    local_pos: np.ndarray  #: (2, 3) race frame origin in its node's frame, m
    local_rot: np.ndarray  #: (2, 3, 3) race frame rotation in its node's frame
    fixed_origin: np.ndarray  #: (3,) origin of the kinematic races' frame, m
    fixed_rot: np.ndarray  #: (3, 3) its rotation
    held: np.ndarray  #: (n,) per slot HELD_NONE, HELD_ROTATION or HELD_ALL


class Guide(NamedTuple):
    """The guiding land of a race-guided cage (MODEL.md §1, §11d)."""

    race: int  #: 0 inner, 1 outer, -1 none
    play: float  #: radial play, m
    stiffness: float  #: N/m
    damping: float  #: N s/m
    friction: float  #: friction torque per unit slip speed of the land, N m s
    film: float  #: K = η0 R L³ / c² of the film's short-bearing force, N s; 0: none (eq. 11d.1)
    max_ratio: float  #: the largest ε the friction torque takes


@njit(cache=True, error_model="numpy")
def add_reaction(react, ib, j, s, rot, lever, f, m, sign):
    """react[ib, j, s] += sign (f, A^T (lever x f + m)): a force f at the ball centre plus a
    moment m, carried to node s."""
    tx = lever[1] * f[2] - lever[2] * f[1] + m[0]
    ty = lever[2] * f[0] - lever[0] * f[2] + m[1]
    tz = lever[0] * f[1] - lever[1] * f[0] + m[2]
    A = rot[ib, s]
    for i in range(3):
        react[ib, j, s, i] += sign * f[i]
        react[ib, j, s, 3 + i] += sign * (A[0, i] * tx + A[1, i] * ty + A[2, i] * tz)


@njit(cache=True, error_model="numpy")
def assemble(mount, c, pos, rot, force, moment, ball_loads, out, react):
    """Per-slot forces without the ball-caused race/cage parts (out, B x n x 6) and each
    ball's contributions to the race and cage slots (react, B x Z x n x 6) from the ball–race
    contacts (``force``, ``moment``) and ``ball_loads`` = (cage force, drag force, pocket
    friction on the balls, its point, whether there is pocket friction; MODEL.md §11d)."""
    balls, slots, cage_slot = mount.balls, mount.slots, mount.cage_slot
    cage_force, drag_force, friction, point, has_friction = ball_loads
    out[:] = 0.0
    react[:] = 0.0
    no_moment = np.zeros(3)
    lever = np.empty(3)
    for ib in range(pos.shape[0]):
        for j in range(balls.shape[0]):
            sb = balls[j]
            A = rot[ib, sb]
            m0 = moment[ib, 0, j, 0] + moment[ib, 1, j, 0]
            m1 = moment[ib, 0, j, 1] + moment[ib, 1, j, 1]
            m2 = moment[ib, 0, j, 2] + moment[ib, 1, j, 2]
            if has_friction:  # (p - c) x F_f about the ball centre
                a0, a1, a2 = point[ib, j, 0] - c[ib, j, 0], point[ib, j, 1] - c[ib, j, 1], point[ib, j, 2] - c[ib, j, 2]
                ff = friction[ib, j]
                m0 += a1 * ff[2] - a2 * ff[1]
                m1 += a2 * ff[0] - a0 * ff[2]
                m2 += a0 * ff[1] - a1 * ff[0]
            for i in range(3):
                out[ib, sb, i] = force[ib, 0, j, i] + force[ib, 1, j, i] + cage_force[ib, j, i] + drag_force[ib, j, i]
                if has_friction:
                    out[ib, sb, i] += friction[ib, j, i]
                out[ib, sb, 3 + i] = A[0, i] * m0 + A[1, i] * m1 + A[2, i] * m2
            for k in range(2):
                s = slots[k]
                if s >= 0:  # the race gets -F at p and -M_z n: about its node -(lever x F + M)
                    for i in range(3):
                        lever[i] = c[ib, j, i] - pos[ib, s, i]
                    add_reaction(react, ib, j, s, rot, lever, force[ib, k, j], moment[ib, k, j], -1.0)
            if cage_slot >= 0:
                for i in range(3):
                    lever[i] = c[ib, j, i] - pos[ib, cage_slot, i]
                add_reaction(react, ib, j, cage_slot, rot, lever, cage_force[ib, j], no_moment, -1.0)
                if has_friction:  # the cage takes -F_f at the contact point
                    for i in range(3):
                        lever[i] = point[ib, j, i] - pos[ib, cage_slot, i]
                    add_reaction(react, ib, j, cage_slot, rot, lever, friction[ib, j], no_moment, -1.0)


@njit(cache=True, error_model="numpy")
def land(nodes, frames, slots, cage_slot, guide, out):
    """Adds the guiding land's force and friction torque on the cage (slot ``cage_slot``) and
    their reaction at the cage centre on the guiding race's slot (if it has one) to ``out``
    (B, n, 6), for B node states ``nodes`` (position, rotation, velocity, GLOBAL angular velocity)
    with race ``frames`` (origin, rotation, velocity, angular velocity; B, 2, ...) and the
    :class:`Guide` as a plain tuple (MODEL.md §1, §11d)."""
    pos, rot, vel, omega = nodes
    race, play, stiffness, damping, friction, film, max_ratio = guide
    ro, rr, rv, rw = frames
    bsz, n = pos.shape[0], pos.shape[1]
    force, ecc, spin = np.empty((bsz, 3)), np.empty(bsz), np.zeros(bsz)
    for ib in range(bsz):
        for i in range(3):  # the film's surfaces' speeds about the race axis
            spin[ib] += (omega[ib, cage_slot, i] + rw[ib, race, i]) * rr[ib, race, i, 2]
    kernels.land_forces(pos[:, cage_slot].copy(), vel[:, cage_slot].copy(), ro[:, race].copy(), rv[:, race].copy(),
                        rr[:, race, :, 2].copy(), play, stiffness, damping, film, spin, force, ecc)
    s = slots[race]
    torque = np.empty(3)
    per_state = out.reshape(bsz, 1, n, 6)  # add_reaction's (B, 1 ball, n, 6) view of out
    for ib in range(bsz):
        for i in range(3):
            out[ib, cage_slot, i] += force[ib, i]
        torque[:] = 0.0
        if friction > 0.0:  # the land's friction torque about the race axis (MODEL.md §11d)
            ax = rr[ib, race, :, 2]
            slip = 0.0
            for i in range(3):
                slip += (rw[ib, race, i] - omega[ib, cage_slot, i]) * ax[i]
            eps = min(ecc[ib] / play, max_ratio)
            t_land = friction * slip / math.sqrt(1.0 - eps * eps)
            for i in range(3):
                torque[i] = t_land * ax[i]
            A = rot[ib, cage_slot]
            for i in range(3):
                out[ib, cage_slot, 3 + i] += A[0, i] * torque[0] + A[1, i] * torque[1] + A[2, i] * torque[2]
        if s >= 0:  # the race takes the reaction at the cage centre
            add_reaction(per_state, ib, 0, s, rot, pos[ib, cage_slot] - pos[ib, s], force[ib], torque, -1.0)


@njit(cache=True, error_model="numpy")
def applied_held_driven(rot, omega, slots, held, loads, out):
    """Into ``out`` (B, n, 6) of B node states (omega GLOBAL): ``loads`` = (the applied force
    (3,) N on the inner race's slot, the driven rows), the ``held`` components (per slot,
    :data:`HELD_NONE` ...) dropped, and per driven row (slot, I_axial kg m², dw_ref/dt rad/s²,
    w_ref rad/s, 1/tau 1/s) the driven race's axial torque I (dw_ref/dt + (w_ref - w)/tau)."""
    applied, driven = loads
    for ib in range(out.shape[0]):
        if slots[0] >= 0:
            for i in range(3):
                out[ib, slots[0], i] += applied[i]
        for s in range(out.shape[1]):
            if held[s] != HELD_NONE:
                for i in range(3 if held[s] == HELD_ROTATION else 0, 6):
                    out[ib, s, i] = 0.0
        for r in range(driven.shape[0]):
            s = int(driven[r, 0])
            w_axial = (rot[ib, s, 0, 2] * omega[ib, s, 0] + rot[ib, s, 1, 2] * omega[ib, s, 1]
                       + rot[ib, s, 2, 2] * omega[ib, s, 2])
            out[ib, s, 5] = driven[r, 1] * (driven[r, 2] + (driven[r, 3] - w_axial) * driven[r, 4])


@njit(cache=True, error_model="numpy")
def batch_tail(nodes, frames, balls_now, contacts, connector, loads, work, raw, out, react):
    """The generalized forces of B node states ``nodes`` (position, rotation, velocity, GLOBAL angular
    velocity) whose ball–race ``contacts`` (force, moment; B, 2, Z, 3) are known, as the
    one-state residual (:mod:`exudyn_bearing.model.compiled`) after its contacts but with the
    balls' parts on the races and cage kept apart: ``out`` (B, n, 6) and ``react`` (B, Z, n, 6)
    as :func:`assemble`'s, with the cage, drag, pocket friction, guiding land, applied force,
    held components and driven races.

    ``frames``: the race frames (origin, rotation, velocity, angular velocity);
    ``balls_now``: the balls' :class:`~contact.kernels.records.BallStates` as a plain tuple;
    ``connector``: (:class:`Mount`, (cage, pocket, guide, ball radius m)) as plain tuples;
    ``loads``: (applied force, driven rows) as :func:`applied_held_driven` takes them;
    ``work``: (cage force, drag force, pocket friction, its point), each (B, Z, 3);
    ``raw``: (slots, (B, Z, len(slots), 6)), the second receiving ``react`` of those slots
    before the held components are dropped."""
    pos, rot, vel, omega = nodes
    mount, (cage, pocket, guide, ball_radius) = connector
    mount, balls_now, cage = Mount(*mount), kernels.BallStates(*balls_now), kernels.CageRecord(*cage)
    mu, slip_scale = pocket
    cage_force, drag_force, friction, point = work
    force, moment = contacts
    raw_slots, raw_react = raw
    c, v = balls_now.position, balls_now.velocity
    cs = mount.cage_slot if mount.cage_slot >= 0 else 0  # (any slot when there is no cage body)
    cage_now = kernels.BodyStates(pos[:, cs].copy(), rot[:, cs].copy(), vel[:, cs].copy(), omega[:, cs].copy())
    kernels.cage_and_drag(c, v, cage, cage_now, cage_force, drag_force)
    if mu > 0.0:
        kernels.pocket_friction(cage_force, balls_now, cage_now, ball_radius, mu, slip_scale, friction, point)
    assemble(mount, c, pos, rot, force, moment, (cage_force, drag_force, friction, point, mu > 0.0), out, react)
    if guide[0] >= 0:
        land(nodes, frames, mount.slots, mount.cage_slot, guide, out)
    for ib in range(react.shape[0]):
        for j in range(react.shape[1]):
            for k in range(raw_slots.shape[0]):
                for i in range(6):
                    raw_react[ib, j, k, i] = react[ib, j, raw_slots[k], i]
    held = mount.held
    applied_held_driven(rot, omega, mount.slots, held, loads, out)
    for s in range(held.shape[0]):
        if held[s] != HELD_NONE:
            for ib in range(react.shape[0]):
                for j in range(react.shape[1]):
                    for i in range(3 if held[s] == HELD_ROTATION else 0, 6):
                        react[ib, j, s, i] = 0.0
