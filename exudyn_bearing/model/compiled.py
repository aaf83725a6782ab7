"""The connector's compiled path: node states -> race frames -> :mod:`contact.kernels` ->
generalized forces per node slot, for a batch of B states (the Jacobian) or, in one
compiled call from Exudyn's coordinates to the force vector, for one state (the residual,
~7 times per step: the numpy glue between the kernels cost more than the kernels).

Same equations and conventions as :meth:`BearingConnector._batch_forces` (the numpy
path, the reference): a global force F enters as F, a global torque tau of a
``NodeRigidBodyRotVecLG`` as A^T tau (velocity coordinates: local omega).
"""
from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numba import njit

from contact import kernels
from contact.kernel_cache import drop_stale
from contact.terms import TermRecord, plain_terms, terms_from_plain

from . import slot_forces
from .slot_forces import HELD_ALL, HELD_ROTATION, Guide, Mount, applied_held_driven, assemble, batch_tail, land

# the one-state kernel below calls the contact/ kernels: recompile it when they changed
drop_stale(__file__, [__file__, slot_forces.__file__, *kernels.SOURCES])
_ANNOUNCED = []


def _announce_compilation():
    """One line on stderr before the one-time compilation of the kernels (no cache yet)."""
    import sys

    if _ANNOUNCED:
        return
    _ANNOUNCED.append(True)
    cached = [d for d, stem in ((Path(__file__).parent / "__pycache__", "compiled"),
                                (Path(kernels.__file__).parent / "__pycache__", "race"))
              if any(d.glob(f"{stem}.*.nbi"))]
    if len(cached) < 2:
        print("exudyn-bearing: compiling the contact kernels (once, about 20-60 s; cached afterwards)",
              file=sys.stderr, flush=True)
from .coverage import say_numpy_path, supports, uncompiled_part  # noqa: F401 (the compiled path's coverage)

__all__ = ["CompiledForces", "supports", "uncompiled_part", "say_numpy_path"]

@njit(cache=True, error_model="numpy")
def _race_frames(pos, rot, vel, omega, mount, fixed_omega, frames):
    """Origin, rotation, origin velocity and angular velocity of the inner and outer race
    frames (B, 2, ...) into ``frames`` (:class:`~contact.kernels.records.RaceFrames`): on their
    node (slot >= 0 in the :class:`Mount`) or kinematic (fixed frame, given ``fixed_omega``)."""
    slots, local_pos, local_rot = mount.slots, mount.local_pos, mount.local_rot
    fixed_origin, fixed_rot = mount.fixed_origin, mount.fixed_rot
    ro, rr, rv, rw = frames.origin, frames.rotation, frames.velocity, frames.omega
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


OK, NON_FINITE, TOO_DEEP = 0, 1, 2


class Physics(NamedTuple):
    """Everything :func:`_one_state` computes with that does not change in time."""

    geometry: kernels.RaceGeometry
    laws: tuple  #: (inner, outer) kernels.LawRecord: each race's contacts with their oil
    tables: kernels.CrookTables
    terms: TermRecord
    cage: kernels.CageRecord
    pocket: tuple  #: (friction coefficient, slip scale m/s) of the ball–pocket friction (§11d); μ 0: none
    guide: Guide


@njit(cache=True, error_model="numpy")
def _one_state(q, q_t, reference, mount, physics, inputs, max_penetration, out, penetration, load, traction):
    """Generalized forces ``out`` (6 n) of one state from Exudyn's coordinates q (without
    reference) and velocities q_t, as ``BearingConnector.forces``: contacts, cage, drag,
    guiding land, ``inputs`` = (angular velocities of the kinematic races (2, 3) rad/s,
    ``applied`` force (N) on the inner race slot, ``driven`` rows), ``held`` components of
    the ``mount`` dropped, and per ``driven`` row (slot, I_axial kg m², dw_ref/dt rad/s²,
    w_ref rad/s, 1/tau 1/s) the driven race's axial torque I (dw_ref/dt + (w_ref - w)/tau).
    ``mount``, ``physics``: :class:`Mount`, :class:`Physics` as plain tuples. Returns OK,
    NON_FINITE (state not finite; nothing computed) or TOO_DEEP (an elastic approach above
    ``max_penetration`` m); the contacts' δ, Q and traction go to ``penetration``, ``load``
    (2 Z) and ``traction`` (2, Z, 4).
    Serial: a parallel kernel called from here crashed Dask workers (DEVELOPMENT.md, 'Numba cache invalidation')."""
    mount = Mount(*mount)
    balls, slots, cage_slot, held = mount.balls, mount.slots, mount.cage_slot, mount.held
    geometry, laws, tables, terms, cage, pocket, guide = physics
    geometry, tables = kernels.RaceGeometry(*geometry), kernels.CrookTables(*tables)
    laws = (kernels.LawRecord(*laws[0]), kernels.LawRecord(*laws[1]))
    terms, cage = terms_from_plain(terms), kernels.CageRecord(*cage)
    pocket_mu, pocket_slip = pocket
    fixed_omega, applied, driven = inputs
    n = reference.shape[0] // 6
    z = balls.shape[0]
    pos = np.empty((1, n, 3))
    vel = np.empty((1, n, 3))
    omega = np.empty((1, n, 3))
    nu = np.empty((n, 3))
    for s in range(n):
        for i in range(3):
            pos[0, s, i] = q[6 * s + i] + reference[6 * s + i]
            nu[s, i] = q[6 * s + 3 + i] + reference[6 * s + 3 + i]
            vel[0, s, i] = q_t[6 * s + i]
    rot = kernels.rotation_matrices(nu).reshape(1, n, 3, 3)
    for s in range(n):
        for i in range(3):
            omega[0, s, i] = (rot[0, s, i, 0] * q_t[6 * s + 3] + rot[0, s, i, 1] * q_t[6 * s + 4]
                              + rot[0, s, i, 2] * q_t[6 * s + 5])
    for s in range(n):
        for i in range(3):
            if not (abs(pos[0, s, i]) < np.inf and abs(vel[0, s, i]) < np.inf and abs(omega[0, s, i]) < np.inf):
                return NON_FINITE
    ro, rr = np.empty((1, 2, 3)), np.empty((1, 2, 3, 3))
    rv, rw = np.empty((1, 2, 3)), np.empty((1, 2, 3))
    _race_frames(pos, rot, vel, omega, mount, fixed_omega, kernels.RaceFrames(ro, rr, rv, rw))
    c, v, w = np.empty((1, z, 3)), np.empty((1, z, 3)), np.empty((1, z, 3))
    for j in range(z):
        for i in range(3):
            c[0, j, i] = pos[0, balls[j], i]
            v[0, j, i] = vel[0, balls[j], i]
            w[0, j, i] = omega[0, balls[j], i]
    force, moment = np.empty((1, 2, z, 3)), np.empty((1, 2, z, 3))
    # a ball's own surface (a pit, waviness) reads where its material is: the balls' rotations
    zr = z if terms.surface.ball_defects.shape[0] + terms.surface.ball_waviness.shape[0] > 0 else 0
    a = np.empty((1, zr, 3, 3))
    for j in range(zr):
        a[0, j] = rot[0, balls[j]]
    balls_now = kernels.BallStates(c, v, w, a)
    contacts = kernels.ContactOutputs(force, moment, penetration.reshape(1, 2, z), load.reshape(1, 2, z),
                                      traction.reshape(1, 2, z, 4))
    kernels.race_contacts(balls_now, kernels.RaceFrames(ro, rr, rv, rw), geometry, laws, tables, terms, contacts)
    cs = cage_slot if cage_slot >= 0 else 0
    cage_force, drag_force = np.empty((1, z, 3)), np.empty((1, z, 3))
    cage_now = kernels.BodyStates(pos[:, cs].copy(), rot[:, cs].copy(), vel[:, cs].copy(), omega[:, cs].copy())
    kernels.cage_and_drag(c, v, cage, cage_now, cage_force, drag_force)
    friction, point = np.empty((1, z, 3)), np.empty((1, z, 3))
    has_friction = pocket_mu > 0.0 and cage.kind == 1
    if has_friction:
        kernels.pocket_friction(cage_force, balls_now, cage_now, geometry.ball_radius, pocket_mu, pocket_slip,
                                friction, point)
    o6 = out.reshape(n, 6)
    react = np.empty((1, z, n, 6))
    assemble(mount, c, pos, rot, force, moment, (cage_force, drag_force, friction, point, has_friction),
              o6.reshape(1, n, 6), react)
    for j in range(z):
        for s in range(n):
            for i in range(6):
                o6[s, i] += react[0, j, s, i]
    if guide[0] >= 0:
        land((pos, rot, vel, omega), (ro, rr, rv, rw), slots, cage_slot, guide, o6.reshape(1, n, 6))
    applied_held_driven(rot, omega, slots, held, (applied, driven), o6.reshape(1, n, 6))
    deepest = 0.0
    for k in range(penetration.shape[0]):
        deepest = max(deepest, penetration[k])
    return TOO_DEEP if deepest > max_penetration else OK


class CompiledForces:
    """The compiled counterpart of :meth:`BearingConnector._batch_forces` for one connector
    (constant arrays prepared once)."""

    def __init__(self, connector):
        con = connector
        b, law = con.bearing, con.law
        self.con = con
        self.balls = np.asarray(con.layout["balls"], dtype=np.int64)
        self.slots = np.array([-1 if con.layout[k] is None else con.layout[k] for k in ("inner", "outer")],
                              dtype=np.int64)
        self.local_pos = np.zeros((2, 3))
        self.local_rot = np.repeat(np.eye(3)[None], 2, axis=0)
        for k, name in enumerate(("inner", "outer")):
            if name in con.race_frames:
                self.local_pos[k], self.local_rot[k] = con.race_frames[name]
        cage = con.cage_record
        self.cage_kind = cage_kind = cage.kind
        self.cage_slot = con.layout["cage"] if cage_kind == 1 else -1
        # ball–pocket friction (MODEL.md §11d): (mu, slip scale m/s); mu 0: none
        pocket = (float(con.cage.pocket_friction) if cage_kind == 1 else 0.0, float(con.cage.pocket_slip_scale))
        self._tables, self._pocket = kernels.crook_tables(law.quadrature_order), pocket
        self.set_physics()
        held = np.zeros(con.n_nodes, dtype=np.int64)
        for slot, what in con.held.items():
            held[slot] = HELD_ALL if what == "all" else HELD_ROTATION
        self.mount = Mount(self.balls, self.slots, int(self.cage_slot), self.local_pos, self.local_rot,
                           np.ascontiguousarray(con.origin, dtype=float),
                           np.ascontiguousarray(con.rotation, dtype=float),
                           held)
        # plain tuples for the one-state kernel: numba types them in its C fast path
        self._mount_tuple = tuple(self.mount)
        self._work = {}
        self._no_slots = np.zeros(0, dtype=np.int64)
        self._patterns = {}
        self.material = con.terms.surface.material  # a ball's own surface: the contacts read the balls' rotations
        self._no_rotations = {}
        # ((t, force function), race speeds, applied force, driven rows) of the last call
        self._time_inputs = ((math.nan, None),)
        self.kinematic = [(i, con.races[k]) for i, k in enumerate(("inner", "outer")) if self.slots[i] < 0]
        self.no_driven = np.zeros((0, 5))
        self.out = np.empty(6 * con.n_nodes)
        self.penetration, self.load = np.empty(2 * b.balls), np.empty(2 * b.balls)
        self.traction = np.empty((2, b.balls, 4))
        #: t, q (without reference) and q_t of the last :meth:`single` call, whose contacts'
        #: traction is in :attr:`traction` (exudyn_bearing.model.recorded_traction)
        self.last_t, self.last_q, self.last_q_t = math.nan, np.full(6 * con.n_nodes, np.nan), np.empty(6 * con.n_nodes)
        # compile (first use) or load the cached machine code now, not inside the solver's
        # first step (~0.3 s cached, ~20 s the very first time)
        _announce_compilation()
        n = con.n_nodes
        rot = np.repeat(np.eye(3)[None, None], 2 * n, axis=1).reshape(2, n, 3, 3)
        pos = np.zeros((2, n, 3))
        pos[:, self.balls, 0] = b.pitch_radius
        self(0.0, pos, rot, np.zeros((2, n, 3)), np.zeros((2, n, 3)))
        q = np.zeros((n, 6))
        q[:, :3] = pos[0]
        self.single(0.0, q.ravel(), np.zeros(6 * n), np.zeros(6 * n))
        self.last_q[:] = np.nan  # the warm-up's state is not the scene's
        kernels.rotation_matrices(np.zeros((1, 3)))
        self._time_inputs = ((math.nan, None),)  # the warm-up's t = 0 inputs are not the scene's

    def set_physics(self):
        """(Re)reads the connector's records and land into :class:`Physics` (at the start, and
        when :meth:`~exudyn_bearing.model.connector.BearingConnector.set_oils` changes an oil)."""
        con = self.con
        guide = Guide(-1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.95)
        if con.guide is not None:
            guide = Guide(("inner", "outer").index(con.guide[0]), *(float(x) for x in con.guide[1:]))
        records = con.records
        self.physics = Physics(records.geometry, records.laws, self._tables, records.terms, con.cage_record,
                               self._pocket, guide)
        # plain tuples for the one-state kernel: numba types them in its C fast path
        self._physics_tuple = tuple(plain_terms(x) if isinstance(x, TermRecord) else tuple(x) if isinstance(x, tuple)
                                    else x for x in self.physics._replace(laws=tuple(tuple(r) for r in records.laws)))
        # what the batch's tail takes (slot_forces.batch_tail): cage, pocket, guide and the ball radius
        # (the pocket friction's lever, as in _one_state)
        self._tail = (*self._physics_tuple[4:7], float(records.geometry.ball_radius))

    def fixed_omega(self, t):
        """Angular velocities (2, 3) of the kinematic races (zero rows for races on a node)."""
        w = np.zeros((2, 3))
        for i, race in self.kinematic:
            w[i] = race.speed(t) * self.con.axis
        return w

    def _inputs(self, t):
        """((t, force function), angular velocities of the kinematic races (2, 3) rad/s, applied
        force (3,) N, driven rows (slot, I_axial, dw_ref/dt, w_ref, 1/tau)) at ``t`` s, kept
        for the next call: a step's Newton iterations and Jacobians share t."""
        con = self.con
        if (t, con.applied_force) != self._time_inputs[0]:
            driven = self.no_driven
            if con.driven:
                driven = np.array([[*row, 1.0 / con.speed_tracking_time] for row in con.driven_speeds(t)])
            self._time_inputs = ((t, con.applied_force), self.fixed_omega(t),
                                 np.asarray(con.applied_force(t), dtype=float), driven)
        return self._time_inputs

    def single(self, t, q, q_t, reference):
        """Status (:data:`OK`, :data:`NON_FINITE`, :data:`TOO_DEEP`) and the force vector
        (6 n_nodes, reused between calls) of one state from Exudyn's coordinates q (without
        ``reference``) and velocities q_t, in one compiled call (:func:`_one_state`)."""
        con = self.con
        _, fixed_omega, applied, driven = self._inputs(t)
        q, q_t = np.asarray(q, dtype=float), np.asarray(q_t, dtype=float)
        status = _one_state(q, q_t, reference, self._mount_tuple, self._physics_tuple, (fixed_omega, applied, driven),
                            con.max_penetration * con.bearing.ball_diameter, self.out, self.penetration, self.load,
                            self.traction)
        self.last_t = t
        if status == OK:
            self.last_q[:], self.last_q_t[:] = q, q_t
        else:
            self.last_q[:] = np.nan
        return status, self.out

    def _no_rotation(self, bsz):
        """The empty (B, 0, 3, 3) ball rotations of contacts that do not read them."""
        if bsz not in self._no_rotations:
            self._no_rotations[bsz] = np.empty((bsz, 0, 3, 3))
        return self._no_rotations[bsz]

    def _arrays(self, bsz):
        if bsz not in self._work:
            z = self.balls.shape[0]
            self._work[bsz] = dict(
                ro=np.empty((bsz, 2, 3)), rr=np.empty((bsz, 2, 3, 3)), rv=np.empty((bsz, 2, 3)),
                rw=np.empty((bsz, 2, 3)), force=np.empty((bsz, 2, z, 3)), moment=np.empty((bsz, 2, z, 3)),
                penetration=np.empty((bsz, 2, z)), load=np.empty((bsz, 2, z)), traction=np.empty((bsz, 2, z, 4)),
                cage=np.empty((bsz, z, 3)),
                drag=np.empty((bsz, z, 3)), friction=np.empty((bsz, z, 3)), point=np.empty((bsz, z, 3)))
        return self._work[bsz]

    def __call__(self, t, pos, rot, vel, omega, same_contacts=None, raw_slots=None):
        """(out (B, n, 6), react (B, Z, n, 6), penetration (B, 2, Z) m, load (B, 2, Z) N, raw)
        for B node states (omega GLOBAL): as :meth:`BearingConnector._batch_forces`, with the
        guiding land, applied force, held components and driven races; the race/cage parts
        caused by ball j are react[:, j]. ``same_contacts`` (bool, (B,) or (B, 2)) marks states
        whose balls and races (per race: whose balls and race k) equal those of state 0 (e.g.
        only the cage, or only the inner race, perturbed): those ball–race contacts are copied
        from state 0 instead of recomputed. ``raw``: react of the slots ``raw_slots`` before
        the held components are dropped (B, Z, len(raw_slots), 6), or None."""
        pos, rot = np.ascontiguousarray(pos), np.ascontiguousarray(rot)
        vel, omega = np.ascontiguousarray(vel), np.ascontiguousarray(omega)
        w = self._contacts(t, pos, rot, vel, omega, same_contacts)
        _, _, applied, driven = self._inputs(t)
        bsz, n, z = pos.shape[0], self.con.n_nodes, self.balls.shape[0]
        out, react = np.empty((bsz, n, 6)), np.empty((bsz, z, n, 6))
        slots = self._no_slots if raw_slots is None else np.asarray(raw_slots, dtype=np.int64)
        raw = np.empty((bsz, z, slots.shape[0], 6))
        batch_tail((pos, rot, vel, omega), (w["ro"], w["rr"], w["rv"], w["rw"]), tuple(w["balls"]),
                   (w["force"], w["moment"]), (self._mount_tuple, self._tail), (applied, driven),
                   (w["cage"], w["drag"], w["friction"], w["point"]), (slots, raw), out, react)
        return out, react, w["penetration"], w["load"], None if raw_slots is None else raw

    def normal_loads(self, t, pos, rot, vel, omega):
        """Normal loads (B, 2, Z) N (inner race first) of B node states (omega GLOBAL) at time ``t`` s."""
        return self._contacts(t, pos, rot, vel, omega)["load"].copy()

    def _contacts(self, t, pos, rot, vel, omega, same_contacts=None):
        """Ball–race contacts of B states into (and returns) the work arrays of size B."""
        bsz = pos.shape[0]
        w = self._arrays(bsz)
        fixed_omega = self._inputs(t)[1]
        pos, rot = np.ascontiguousarray(pos), np.ascontiguousarray(rot)
        vel, omega = np.ascontiguousarray(vel), np.ascontiguousarray(omega)
        frames = kernels.RaceFrames(w["ro"], w["rr"], w["rv"], w["rw"])
        _race_frames(pos, rot, vel, omega, self.mount, fixed_omega, frames)
        # C-ordered copies: numba compiles one machine code per memory layout
        balls = kernels.BallStates(*(np.take(x, self.balls, axis=1) for x in (pos, vel, omega)),
                                   np.take(rot, self.balls, axis=1) if self.material else self._no_rotation(bsz))
        w["balls"] = balls
        ph = self.physics
        args = (balls, frames, ph.geometry, ph.laws, ph.tables, ph.terms,
                kernels.ContactOutputs(w["force"], w["moment"], w["penetration"], w["load"], w["traction"]))
        # contacts spread over numba's threads from the main thread; a threaded caller (a
        # Dask worker thread) runs them serially (numba's workqueue layer, its fallback when
        # OpenMP is missing, serves one caller at a time)
        if bsz == 1 or threading.current_thread() is not threading.main_thread():
            kernels.race_contacts(*args)
            return w
        todo, b, k = self._reuse_pattern(bsz, self.balls.shape[0], same_contacts)
        kernels.race_contacts_parallel(*args, todo)
        if b.size:
            for key in ("force", "moment", "penetration", "load", "traction"):
                w[key][b, k] = w[key][0, k]
        return w

    def _reuse_pattern(self, bsz, z, same_contacts):
        """(contacts to compute, states and races to copy from state 0) of a ``same_contacts``
        pattern, cached: the Jacobian passes the same pattern every call."""
        key = (bsz, None if same_contacts is None else np.asarray(same_contacts, dtype=bool).tobytes())
        if key not in self._patterns:
            same = np.zeros((bsz, 2), dtype=bool)
            if same_contacts is not None:
                same[:] = np.asarray(same_contacts, dtype=bool).reshape(bsz, -1)
            same[0] = False
            self._patterns[key] = (np.flatnonzero(np.repeat(~same, z, axis=1).ravel()), *np.nonzero(same))
        return self._patterns[key]
