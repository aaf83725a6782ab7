"""The connector's compiled path: node states -> race frames -> :mod:`contact.compiled` ->
generalized forces per node slot, for a batch of B states, without numpy call overhead.

Same equations and conventions as :meth:`BearingConnector._batch_forces` (the numpy
path, the reference): a global force F enters as F, a global torque tau of a
``NodeRigidBodyRotVecLG`` as A^T tau (velocity coordinates: local omega).
"""
from __future__ import annotations

import threading

import numpy as np
from numba import njit

from contact import compiled as kernels

__all__ = ["CompiledForces", "supports"]


def supports(law) -> bool:
    """Whether the compiled path computes this :class:`contact.ballrace.ContactLaw`:
    Crook traction by the fast rule (or no traction), Brewe–Hamrock Hertz fits, no limiting
    shear; other laws use the numpy path."""
    return (law.traction == "none" or (law.traction == "crook" and law.fast_quadrature)) \
        and law.hertz_method == "fit" and law.limiting_shear is None


@njit(cache=True, error_model="numpy")
def _race_frames(pos, rot, vel, omega, slots, local_pos, local_rot, fixed_origin, fixed_rot, fixed_omega,
                 ro, rr, rv, rw):
    """Origin, rotation, origin velocity and angular velocity of the inner and outer race
    frames (B, 2, ...): on their node (slot >= 0) or kinematic (fixed frame, given omega)."""
    for ib in range(pos.shape[0]):
        for k in range(2):
            s = slots[k]
            if s < 0:
                for i in range(3):
                    ro[ib, k, i] = fixed_origin[i]
                    rv[ib, k, i] = 0.0
                    rw[ib, k, i] = fixed_omega[k, i]
                    for m in range(3):
                        rr[ib, k, i, m] = fixed_rot[i, m]
                continue
            A = rot[ib, s]
            arm = A @ local_pos[k]
            rr[ib, k] = A @ local_rot[k]
            w = omega[ib, s]
            for i in range(3):
                ro[ib, k, i] = pos[ib, s, i] + arm[i]
                rw[ib, k, i] = w[i]
            rv[ib, k, 0] = vel[ib, s, 0] + w[1] * arm[2] - w[2] * arm[1]
            rv[ib, k, 1] = vel[ib, s, 1] + w[2] * arm[0] - w[0] * arm[2]
            rv[ib, k, 2] = vel[ib, s, 2] + w[0] * arm[1] - w[1] * arm[0]


@njit(cache=True, error_model="numpy")
def _add_reaction(react, ib, j, s, rot, lever, f, m, sign):
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
def _assemble(balls, slots, cage_slot, c, pos, rot, force, moment, cage_force, drag_force, out, react):
    """Per-slot forces without the ball-caused race/cage parts (out, B x n x 6) and each
    ball's contributions to the race and cage slots (react, B x Z x n x 6)."""
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
            for i in range(3):
                out[ib, sb, i] = force[ib, 0, j, i] + force[ib, 1, j, i] + cage_force[ib, j, i] + drag_force[ib, j, i]
                out[ib, sb, 3 + i] = A[0, i] * m0 + A[1, i] * m1 + A[2, i] * m2
            for k in range(2):
                s = slots[k]
                if s >= 0:  # the race gets -F at p and -M_z n: about its node -(lever x F + M)
                    for i in range(3):
                        lever[i] = c[ib, j, i] - pos[ib, s, i]
                    _add_reaction(react, ib, j, s, rot, lever, force[ib, k, j], moment[ib, k, j], -1.0)
            if cage_slot >= 0:
                for i in range(3):
                    lever[i] = c[ib, j, i] - pos[ib, cage_slot, i]
                _add_reaction(react, ib, j, cage_slot, rot, lever, cage_force[ib, j], no_moment, -1.0)


class CompiledForces:
    """The compiled counterpart of :meth:`BearingConnector._batch_forces` for one connector
    (constant arrays prepared once)."""

    def __init__(self, connector):
        con = connector
        b, law, lub = con.bearing, con.law, con.lubricant
        self.con = con
        self.balls = np.asarray(con.layout["balls"], dtype=np.int64)
        self.slots = np.array([-1 if con.layout[k] is None else con.layout[k] for k in ("inner", "outer")],
                              dtype=np.int64)
        self.local_pos = np.zeros((2, 3))
        self.local_rot = np.repeat(np.eye(3)[None], 2, axis=0)
        for k, name in enumerate(("inner", "outer")):
            if name in con.race_frames:
                self.local_pos[k], self.local_rot[k] = con.race_frames[name]
        self.groove = np.array([con.grooves["inner"], con.grooves["outer"]], dtype=float)
        self.conformity = np.array([b.inner_conformity, b.outer_conformity])
        self.sign = np.array([-1.0, 1.0])
        self.tables = kernels.crook_tables(law.quadrature_order)
        self.physics = (b.ball_radius, b.pitch_diameter, b.effective_modulus, b.ball_mass, law.damping_ratio,
                        1 if law.traction == "crook" else 0, law.spin_moment, law.min_film_thickness,
                        lub.viscosity, lub.pressure_viscosity, law.max_barus_exponent,
                        lub.temperature_viscosity / (8.0 * lub.thermal_conductivity))
        self.cage_kind = {"none": 0, "rigid": 1, "spring-chain": 2}[con.cage.kind]
        self.cage_slot = con.layout["cage"] if self.cage_kind == 1 else -1
        drag = con.drag
        self.drag_factor = 0.0
        if drag is not None and drag.drag_coefficient * drag.oil_volume_fraction > 0:
            self.drag_factor = (0.5 * drag.drag_coefficient * drag.oil_volume_fraction * lub.density * np.pi
                                * b.ball_radius ** 2)
        self._work = {}
        # compile (first use) or load the cached machine code now, not inside the solver's
        # first step (~0.3 s cached, ~20 s the very first time)
        n = con.n_nodes
        rot = np.repeat(np.eye(3)[None, None], n, axis=1)
        pos = np.zeros((1, n, 3))
        pos[0, self.balls, 0] = b.pitch_radius
        self(0.0, pos, rot, np.zeros((1, n, 3)), np.zeros((1, n, 3)))
        kernels.rotation_matrices(np.zeros((1, 3)))

    def _arrays(self, bsz):
        if bsz not in self._work:
            z = self.balls.shape[0]
            self._work[bsz] = dict(
                ro=np.empty((bsz, 2, 3)), rr=np.empty((bsz, 2, 3, 3)), rv=np.empty((bsz, 2, 3)),
                rw=np.empty((bsz, 2, 3)), force=np.empty((bsz, 2, z, 3)), moment=np.empty((bsz, 2, z, 3)),
                penetration=np.empty((bsz, 2, z)), load=np.empty((bsz, 2, z)), cage=np.empty((bsz, z, 3)),
                drag=np.empty((bsz, z, 3)))
        return self._work[bsz]

    def __call__(self, t, pos, rot, vel, omega, same_contacts=None):
        """(out (B, n, 6), react (B, Z, n, 6), penetration (B, 2, Z) m, load (B, 2, Z) N) for
        B node states (omega GLOBAL); the race/cage parts caused by ball j are react[:, j].
        ``same_contacts`` (bool, (B,)) marks states whose balls and races equal those of
        state 0 (e.g. only the cage perturbed): their ball–race contacts are copied from
        state 0 instead of recomputed."""
        bsz = pos.shape[0]
        if same_contacts is not None and np.any(same_contacts[1:]):
            # the ball–race contacts of the distinct states only (state 0 first), then spread
            sub = np.concatenate([[0], np.flatnonzero(~same_contacts[1:]) + 1])
            ws = self._contacts(t, *(np.take(x, sub, axis=0) for x in (pos, rot, vel, omega)))
            w = self._arrays(bsz)
            same = np.flatnonzero(same_contacts)
            for key in ("force", "moment", "penetration", "load"):
                w[key][sub] = ws[key]
                w[key][same] = ws[key][0]
        else:
            w = self._contacts(t, pos, rot, vel, omega)
        return self._finish(np.ascontiguousarray(pos), np.ascontiguousarray(rot), np.ascontiguousarray(vel),
                            np.ascontiguousarray(omega), w)

    def _contacts(self, t, pos, rot, vel, omega):
        """Ball–race contacts of B states into (and returns) the work arrays of size B."""
        con = self.con
        bsz = pos.shape[0]
        w = self._arrays(bsz)
        fixed_omega = np.array([con.races[k].speed(t) * con.axis if self.slots[i] < 0 else np.zeros(3)
                                for i, k in enumerate(("inner", "outer"))])
        pos, rot = np.ascontiguousarray(pos), np.ascontiguousarray(rot)
        vel, omega = np.ascontiguousarray(vel), np.ascontiguousarray(omega)
        _race_frames(pos, rot, vel, omega, self.slots, self.local_pos, self.local_rot, con.origin, con.rotation,
                     fixed_omega, w["ro"], w["rr"], w["rv"], w["rw"])
        # C-ordered copies: numba compiles one machine code per memory layout
        c, v, wb = (np.take(x, self.balls, axis=1) for x in (pos, vel, omega))
        # contacts spread over numba's threads from the main thread; a threaded caller (a
        # Dask worker thread) runs them serially (numba's workqueue layer, its fallback when
        # OpenMP is missing, serves one caller at a time)
        run = (kernels.race_contacts_parallel if threading.current_thread() is threading.main_thread()
               else kernels.race_contacts)
        run(c, v, wb, w["ro"], w["rr"], w["rv"], w["rw"], self.groove, self.conformity, self.sign,
            *self.physics, *self.tables, w["force"], w["moment"], w["penetration"],
            w["load"])
        return w

    def _finish(self, pos, rot, vel, omega, w):
        """Cage, drag and the generalized-force assembly of B states whose ball–race
        contacts are in ``w``."""
        con = self.con
        bsz = pos.shape[0]
        c, v = (np.take(x, self.balls, axis=1) for x in (pos, vel))
        s = con.layout["cage"] if self.cage_kind == 1 else 0  # (any slot when there is no cage body)
        cage = [np.ascontiguousarray(x[:, s]) for x in (pos, rot, vel, omega)]
        kernels.cage_and_drag(c, v, self.cage_kind, *cage, con.pocket_angles,
                              con.bearing.pitch_radius, con.cage.clearance, con.cage.stiffness, con.cage_damping,
                              con.axis, con.origin, self.drag_factor, w["cage"], w["drag"])
        n = con.n_nodes
        out = np.empty((bsz, n, 6))
        react = np.empty((bsz, self.balls.shape[0], n, 6))
        _assemble(self.balls, self.slots, self.cage_slot, c, pos, rot, w["force"], w["moment"], w["cage"], w["drag"],
                  out, react)
        return out, react, w["penetration"], w["load"]
