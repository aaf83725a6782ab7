"""The bearing's contact connector: Exudyn node states -> contact/ physics -> generalized
forces of one ``ObjectGenericODE2`` (MODEL.md §2–§8).

Node coordinates (``NodeRigidBodyRotVecLG``): position and rotation vector; velocity
coordinates are the global velocity and the LOCAL angular velocity. A global force F
enters as F, a global torque tau as A^T tau (A = node rotation matrix).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from contact import cage as cage_physics
from contact.ballrace import ball_race_forces, ball_race_forces_by_race, with_surface
from contact.kernels.records import law_record
from contact.lubricant import Lubricant
from contact.kinematics import ball_race_kinematics, cross, rotation_matrices
from contact.surface import surface_record
from ..cage import CageModel
from ..contact_records import cage_record, contact_records
from ..jacobian import block_jacobian
from ..races import Race
from .coverage import say_numpy_path, supports
from .diagnostics import ConnectorDiagnostics
from .land import GuidingLand, land_guide
from .recorded_traction import RecordedTraction
from .state import ConnectorState, both_races, first_state, per_race, stacked

__all__ = ["CageModel", "BearingConnector", "ConnectorState"]


class BearingConnector(GuidingLand, ConnectorDiagnostics):
    """Computes the generalized forces of all ball–race, ball–cage and drag interactions.

    Parameters
    ----------
    setup : exudyn_bearing.setup.BearingSetup
        The bearing and its physics — lubricant, contact law, cage, ball drag (None: no
        drag), surfaces (MODEL.md §13; perfect ones cost nothing) — kept as ``bearing``,
        ``lubricant``, ``law``, ``cage``, ``drag`` and ``surface`` (None where perfect).
    races : dict
        ``{'inner': Race, 'outer': Race}``.
    layout : dict
        Node slots in the GenericODE2: ``balls`` (list of slot indices), ``cage``,
        ``inner``, ``outer`` (slot or None).
    frame_origin, frame_rotation : ndarray
        The bearing frame (its third axis is the bearing axis) in global coordinates.
    race_frames : dict
        Per race with a node: (local position, local rotation) of the race frame in the
        node's body frame.
    applied_force : ndarray (3,) or callable
        Global force on the inner race node (e.g. the axial and radial load), N, or a
        function of time t returning it.
    held : dict
        Per race slot: which generalized-force components to drop so the race keeps its
        initial velocity ('rotation' or 'all').
    driven : dict, optional
        Per held race slot with a time-varying speed: (Race, axial moment of inertia in
        kg m²). Its axial torque is I (dw/dt + (w_ref - w)/tau), tau = 1 ms: the
        feed-forward makes the race follow the prescribed speed, the weak feedback removes
        integration drift.
    ball_circles : ndarray (Z, 2, 3), optional
        Per ball, the zero direction and spin axis (ball body frame) of the circle a ball
        defect's ``angle_deg`` is measured on (:func:`contact.surface.ball_circles`, the default).
    """

    speed_tracking_time = 1e-3  #: tau of the driven-speed feedback, s
    #: largest admissible elastic approach, fraction of D (the 100 kN case reaches ~0.3 %)
    max_penetration = 0.02

    def __init__(self, setup, races: dict, layout: dict, frame_origin, frame_rotation, race_frames: dict,
                 applied_force, held: dict, *, driven: dict | None = None, ball_circles=None):
        self.setup = setup
        bearing, lubricant, law, cage = setup.bearing, setup.lubricant, setup.contact_law, setup.cage
        self.bearing, self.lubricant, self.law, self.cage, self.drag = bearing, lubricant, law, setup.cage, setup.drag
        self.surface = setup.surface if setup.surface.active else None
        #: what the builder's surface start did (:class:`exudyn_bearing.solvers.surface_start.SurfaceStart`)
        self.surface_start = None
        #: the contacts' records, both force paths (:func:`exudyn_bearing.contact_records.contact_records`)
        self.records = contact_records(bearing, lubricant, law, surface=surface_record(self.surface, bearing,
                                                                                      ball_circles))
        #: (D, d_m) m the surfaces were laid on (both paths keep them when the sizes change, set_geometry)
        self._surface_sizes = (bearing.ball_diameter, bearing.pitch_diameter)
        self.terms = self.records.terms
        self.races, self.layout = races, layout
        self.origin = np.asarray(frame_origin, dtype=float)
        self.rotation = np.asarray(frame_rotation, dtype=float)
        self.axis = self.rotation[:, 2]
        self.race_frames = race_frames
        if callable(applied_force):
            self.applied_force = applied_force
        else:
            constant = np.asarray(applied_force, dtype=float)
            self.applied_force = lambda t: constant
        self.held = held
        self.driven = driven or {}
        self.z = bearing.balls
        self.n_nodes = 1 + max(s for s in [*layout["balls"], layout["cage"], layout["inner"], layout["outer"]]
                               if s is not None)
        # inner contacts first, then outer: one vectorized evaluation for all 2 Z contacts
        self.groove_all, self.signs, self.params = self.records.grooves, self.records.signs, self.records.races
        #: the cage and drag as both paths read them (:func:`exudyn_bearing.contact_records.cage_record`)
        self.cage_record = cage_record(setup, self.axis, self.origin)
        self.pocket_angles, self.cage_damping = self.cage_record.pocket_angles, self.cage_record.damping
        #: the inner contacts', outer contacts' and cage land's lubricant (:meth:`set_oils`)
        self.oils = (lubricant, lubricant, lubricant)
        self._race_terms = (self.terms, self.terms)
        self.guide = land_guide(bearing, lubricant, cage)
        self.reference = np.zeros(6 * self.n_nodes)  # set by the builder after Assemble
        self.first_non_finite = None  # diagnosis of the first blown-up state, if any
        self.progress = None  # the runner's progress reporter while it runs (called with t)
        self._params_cache = {}
        self._compiled = None
        #: the traction of the states the run recorded, where it computed them (compiled path)
        self.recorded = None
        self._jac_spec = None
        self._land_kernel = None
        self._rotations = rotation_matrices
        if law.compiled:
            if supports(law):
                from . import compiled

                self._compiled = compiled.CompiledForces(self)
                self.recorded = RecordedTraction(self._compiled)
                self._rotations = compiled.kernels.rotation_matrices
                self._land_kernel = compiled.kernels.land_forces
            else:
                say_numpy_path(law)

    def set_oils(self, inner, outer, land=None):
        """From now on each race's contacts take their own lubricant, ``inner`` and ``outer``
        (:class:`contact.lubricant.Lubricant`), and the cage's land ``land`` (None: the
        setup's), e.g. the thermal network's contact oils at the node temperatures (MODEL.md
        §14b); both force paths and the outputs follow."""
        land = self.lubricant if land is None else land
        for name, oil in (("inner", inner), ("outer", outer), ("land", land)):
            if not isinstance(oil, Lubricant):
                raise ValueError(f"set_oils: {name} must be a contact.lubricant.Lubricant, got {oil!r}")
        self.oils = (inner, outer, land)
        heated = self.terms.heating > 0.0  # the thermal film factor reads each oil's c_etaT / K_c
        self._race_terms = tuple(self.terms._replace(heating=oil.shear_heating) if heated else self.terms
                                 for oil in (inner, outer))
        self.records = self.records._replace(laws=(law_record(self.law, inner), law_record(self.law, outer)))
        self.guide = land_guide(self.bearing, land, self.cage)
        if self._compiled is not None:
            self._compiled.set_physics()

    def set_geometry(self, bearing):
        """From now on the contacts take ``bearing``'s sizes (this bearing grown or shrunk with
        its temperatures, :meth:`~exudyn_bearing.Bearing.expanded`, MODEL.md §14f): groove
        radii, groove centres' radii, ball diameter, pitch diameter; both force paths, the land
        and the outputs follow. The groove centres keep their axial places in their races' frames
        (the rings hold their axial positions, §14f: a race held axially then presses the balls
        by the change of the touching distance). Ball count, masses, materials, the cage's pocket
        circle and the surfaces' layout stay as built. The same sizes again: nothing to do."""
        if bearing == self.bearing:
            return
        if bearing.balls != self.bearing.balls:
            raise ValueError(f"set_geometry: the bearing has {bearing.balls} balls, the model {self.bearing.balls}")
        fresh = contact_records(bearing, self.lubricant, self.law)
        z = self.records.grooves[1]
        grooves = (fresh.grooves[0], z, fresh.grooves[2])
        geometry = fresh.geometry._replace(groove=np.column_stack([fresh.geometry.groove[:, 0],
                                                                   self.records.geometry.groove[:, 1],
                                                                   fresh.geometry.groove[:, 2]]))
        self.records = self.records._replace(tube=fresh.tube, grooves=grooves, races=fresh.races, geometry=geometry)
        self.groove_all, self.params = self.records.grooves, self.records.races
        self._params_cache = {}
        self.bearing = bearing
        self.guide = land_guide(bearing, self.oils[2], self.cage)
        # the drag follows the balls' size; the cage's pockets keep their pitch radius (no cage growth)
        self.cage_record = cage_record(self.setup.replace(bearing=bearing), self.axis, self.origin)._replace(
            pitch_radius=self.cage_record.pitch_radius)
        if self._compiled is not None:
            self._compiled.set_physics()

    # -- state of a race frame ---------------------------------------------------------
    def _race_frame(self, name, t, pos, vel, rot, omega):
        """(origin, rotation, velocity, omega, slot) of a race frame for a batch of states
        (leading axis B), global frame."""
        race: Race = self.races[name]
        slot = self.layout[name]
        b = pos.shape[0]
        if slot is None:  # kinematic race; per state for recorded times t (B,)
            w = (race.speed(t) if np.ndim(t) == 0 else np.array([race.speed(x) for x in t])[:, None]) * self.axis
            return (np.broadcast_to(self.origin, (b, 3)), np.broadcast_to(self.rotation, (b, 3, 3)),
                    np.zeros((b, 3)), np.broadcast_to(w, (b, 3)), None)
        r_loc, rot_loc = self.race_frames[name]
        a = rot[:, slot]
        origin = pos[:, slot] + a @ r_loc
        w = omega[:, slot]
        return origin, a @ rot_loc, vel[:, slot] + cross(w, origin - pos[:, slot]), w, slot

    def race_pose(self, name, pos, rot):
        """Origin (3,) m and rotation (3, 3), global, of the ``'inner'`` or ``'outer'`` race frame for
        one state's node positions ``pos`` (n, 3) and rotations ``rot`` (n, 3, 3) (:meth:`decode`)."""
        slot = self.layout[name]
        if slot is None:
            return self.origin, self.rotation
        r_loc, rot_loc = self.race_frames[name]
        return pos[slot] + rot[slot] @ r_loc, rot[slot] @ rot_loc

    def race_frame(self, name, t, q, q_t):
        """Origin (3,) in m and rotation (3, 3) of the ``'inner'`` or ``'outer'`` race frame
        (third column: the race axis), global, for absolute coordinates q and velocities q_t."""
        if name not in ("inner", "outer"):
            raise ValueError(f"name must be 'inner' or 'outer', got {name!r}")
        pos, rot, vel, wl = self.decode(q, q_t)
        omega = np.einsum("nij,nj->ni", rot, wl)
        origin, rotation, _, _, _ = self._race_frame(name, t, pos[None], vel[None], rot[None], omega[None])
        return np.array(origin[0]), np.array(rotation[0])

    def _contact_params(self, batch: int):
        """Per-contact geometry arrays for ``batch`` states (cached: the Jacobian reuses one size)."""
        if batch not in self._params_cache:
            self._params_cache[batch] = (
                tuple(np.tile(g, batch) for g in self.groove_all), np.tile(self.signs, batch),
                replace(self.params, conformity=np.tile(self.params.conformity, batch),
                        race=np.tile(self.signs, batch)))
        return self._params_cache[batch]

    def decode(self, q, q_t):
        """Positions, rotation matrices, velocities and LOCAL angular velocities per node slot."""
        qq = np.asarray(q, dtype=float).reshape(self.n_nodes, 6)
        vv = np.asarray(q_t, dtype=float).reshape(self.n_nodes, 6)
        return qq[:, :3], self._rotations(np.ascontiguousarray(qq[:, 3:])), vv[:, :3], vv[:, 3:]

    def evaluate(self, t, q, q_t, details=False):
        """Generalized forces for absolute coordinates q (with reference) and velocities q_t.

        Returns the force vector (6 per node slot) or, with ``details``, the
        :class:`ConnectorState`.
        """
        return self.forces(t, *self.decode(q, q_t), details=details)

    def residual_forces(self, t, q, q_t):
        """Generalized forces (6 per node slot) for Exudyn's coordinates q (WITHOUT the
        reference) and velocities q_t: the force user function. One compiled call when the
        compiled path applies; a state it cannot take (not finite, a ball out of its groove)
        goes through :meth:`forces`, which records why and returns NaN."""
        if self._compiled is not None:
            status, out = self._compiled.single(t, q, q_t, self.reference)
            if status == 0:
                return out.copy()
        return self.evaluate(t, np.asarray(q) + self.reference, q_t)

    def numpy_forces(self, t, q, q_t, surface=True):
        """Generalized forces (B, 6 n_nodes) of B states (absolute coordinates and velocities,
        (B, 6 n_nodes)) through the numpy path, with the surfaces or, ``surface=False``,
        without them (the surface start, :mod:`exudyn_bearing.solvers.surface_start`)."""
        pos, rot, vel, omega = self._decode_batch(q, q_t)
        out, react, _, _, _ = self._batch_forces(t, pos, rot, vel, omega, details=True, surface=surface)
        return (out + react.sum(axis=1)).reshape(pos.shape[0], -1)

    def states(self, t, q, q_t) -> ConnectorState:
        """Everything the numpy path computes for B recorded states at once (times ``t`` (B,) s,
        absolute coordinates and velocities (B, 6 n_nodes)): a :class:`ConnectorState` whose
        fields, but the bearing frame's, carry a leading axis B; ``generalized`` is None. For
        the outputs of a finished run: the states are not checked as :meth:`forces` does. The
        traction of a run on the compiled path is the run's own where it recorded the state
        (:class:`~exudyn_bearing.model.recorded_traction.RecordedTraction`), else recomputed by
        its compiled rule (the one that ran; ~20x cheaper than the numpy rule)."""
        t = np.asarray(t, dtype=float)
        pos, rot, vel, omega = self._decode_batch(q, q_t)
        known = None if self.recorded is None else self.recorded.lookup(t, q, q_t)
        _, _, parts = self._numpy_forces(t, pos, rot, vel, omega, compiled=self._compiled is not None,
                                         known_traction=known)
        return self._state(t, pos, rot, vel, omega, None, parts)

    def normal_loads(self, t, q, q_t, chunk: int = 256):
        """Normal loads (B, 2, Z) N of B recorded states (``t`` (B,) s, absolute q, q_t (B, 6 n));
        compiled where both races are bodies."""
        t, q, q_t = np.asarray(t, dtype=float), np.atleast_2d(q), np.atleast_2d(q_t)
        if self._compiled is None or self.layout["inner"] is None or self.layout["outer"] is None:
            s = self.states(t, q, q_t)
            return np.stack([s.inner_forces.normal_load, s.outer_forces.normal_load], axis=1)
        pad = -len(t) % chunk  # one batch size for the kernels' work arrays
        q, q_t = (np.pad(x, ((0, pad), (0, 0)), "edge") for x in (q, q_t))
        return np.concatenate([self._compiled.normal_loads(0.0, *self._decode_batch(q[i:i + chunk], q_t[i:i + chunk]))
                               for i in range(0, len(q), chunk)])[:len(t)]

    def _decode_batch(self, q, q_t):
        """:meth:`decode` for B states (B, 6 n_nodes), with GLOBAL angular velocities."""
        q, q_t = np.atleast_2d(q), np.atleast_2d(q_t)
        b, n = q.shape[0], self.n_nodes
        qq, vv = q.reshape(b, n, 6), q_t.reshape(b, n, 6)
        rot = self._rotations(np.ascontiguousarray(qq[:, :, 3:].reshape(-1, 3))).reshape(b, n, 3, 3)
        omega = np.einsum("bnij,bnj->bni", rot, vv[:, :, 3:])
        return np.ascontiguousarray(qq[:, :, :3]), rot, np.ascontiguousarray(vv[:, :, :3]), omega

    def forces(self, t, pos, rot, vel, omega_local, details=False):
        """Generalized forces from decoded node states (see :meth:`decode`): the force
        vector (6 per node slot) or, with ``details``, the :class:`ConnectorState`."""
        omega = np.einsum("nij,nj->ni", rot, omega_local)
        if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(vel)) and np.all(np.isfinite(omega))):
            # a Newton iterate or explicit stage blew up: NaN forces let Exudyn reject the
            # step (and retry smaller); run_solver reports the first occurrence if it fails
            if self.first_non_finite is None:
                self.first_non_finite = self._non_finite(t, pos, vel, omega)
            return np.full(6 * self.n_nodes, np.nan)
        out, react, pen, load, parts = self._batch_forces(t, pos[None], rot[None], vel[None], omega[None],
                                                          details=details)
        out, react, pen, load = out[0], react[0], pen[0].ravel(), load[0].ravel()
        deepest = int(np.argmax(pen))
        if pen[deepest] > self.max_penetration * self.bearing.ball_diameter:
            # Hertz theory and the groove geometry are meaningless here: reject the state
            # like a blown-up one (a trial iterate may recover with a smaller step)
            if self.first_non_finite is None:
                race, ball = ("inner", "outer")[deepest // self.z], deepest % self.z
                self.first_non_finite = (
                    f"t = {t:.6g} s: a solver trial state pushed ball {ball} out of its groove at the {race} race "
                    f"(elastic approach {pen[deepest] * 1e3:.3g} mm > {100 * self.max_penetration:g} % of the "
                    f"ball diameter, Q = {load[deepest]:.4g} N)")
            return np.full(6 * self.n_nodes, np.nan)
        out = out + react.sum(axis=0)
        if not details:
            return out.ravel()
        return first_state(self._state(t, pos[None], rot[None], vel[None], omega[None], out.reshape(1, -1), parts))

    def _state(self, t, pos, rot, vel, omega, generalized, parts) -> ConnectorState:
        """The :class:`ConnectorState` of B states (leading axis) from the numpy path's ``parts``."""
        kin_all, frc_all, cage_force, drag_force, race_omega, friction = parts
        b, z = pos.shape[0], self.z
        (kin_in, kin_out), (frc_in, frc_out) = per_race(kin_all, b, z), per_race(frc_all, b, z)
        rigid = self.cage.kind == "rigid"
        cage, balls = self.layout["cage"], self.layout["balls"]
        return ConnectorState(t, pos[:, balls], vel[:, balls], omega[:, balls], kin_in, kin_out, frc_in, frc_out,
                              cage_force, drag_force, omega[:, cage] if rigid else None,
                              race_omega["inner"], race_omega["outer"], self.rotation, self.origin, generalized,
                              **self._land_details(t, pos, rot, vel, omega),
                              cage_position=pos[:, cage] if rigid else None,
                              cage_velocity=vel[:, cage] if rigid else None,
                              pocket_friction_force=None if friction is None else friction[0],
                              pocket_friction_loss=np.zeros(b) if friction is None else np.sum(friction[1], axis=1))

    def _batch_forces(self, t, pos, rot, vel, omega, details=False, same_contacts=None, raw_reactions=None,
                      surface=True):
        """Forces for a batch of B node states (leading axis; omega GLOBAL): per-slot forces
        without the ball-caused race/cage parts (B, n_nodes, 6), the per-ball contributions
        to the race/cage slots (B, Z, n_nodes, 6), penetration (m) and normal load (N) of
        each contact (B, 2, Z; inner race first), and, from the numpy path, the parts of
        :meth:`_numpy_forces` (None from the compiled path, which is used unless ``details``
        are asked for).
        ``same_contacts`` (compiled path): bool (B,) or (B, 2), states (per race) whose
        ball–race contacts equal state 0's (see :class:`exudyn_bearing.model.compiled.CompiledForces`).
        ``raw_reactions``: a dict with ``slots``, which receives ``react`` of those slots
        (B, Z, len(slots), 6) before the held components are zeroed (the block Jacobian's
        race columns need the contact moments a held race does not take). ``surface=False``
        leaves the surfaces out (numpy path)."""
        if self._compiled is not None and not details and surface:  # all of it in compiled loops
            out, react, pen, load, raw = self._compiled(t, pos, rot, vel, omega, same_contacts,
                                                        None if raw_reactions is None else raw_reactions["slots"])
            if raw_reactions is not None:
                raw_reactions["react"] = raw
            return out, react, pen, load, None
        out, react, parts = self._numpy_forces(t, pos, rot, vel, omega, surface)
        pen = parts[0].penetration.reshape(pos.shape[0], 2, self.z)
        load = parts[1].normal_load.reshape(pos.shape[0], 2, self.z)
        if self.guide is not None:
            self._add_land_force(t, pos, rot, vel, omega, out)
        if self.layout["inner"] is not None:
            out[:, self.layout["inner"], :3] += self.applied_force(t)
        if raw_reactions is not None:
            raw_reactions["react"] = np.ascontiguousarray(react[:, :, raw_reactions["slots"]])
        for slot, what in self.held.items():
            out[:, slot, 3:] = 0.0
            react[:, :, slot, 3:] = 0.0
            if what == "all":
                out[:, slot, :3] = 0.0
                react[:, :, slot, :3] = 0.0
        for slot, inertia, accel, w_ref in self.driven_speeds(t):
            w_axial = np.einsum("bi,bi->b", rot[:, slot, :, 2], omega[:, slot])
            out[:, slot, 5] = inertia * (accel + (w_ref - w_axial) / self.speed_tracking_time)
        return out, react, pen, load, parts

    def driven_speeds(self, t):
        """Per driven race: (slot, axial moment of inertia kg m², prescribed angular
        acceleration rad/s² (centred difference), prescribed speed rad/s) at t."""
        dt = 1e-6
        return [(slot, inertia, (race.speed(t + dt) - race.speed(t - dt)) / (2 * dt), race.speed(t))
                for slot, (race, inertia) in self.driven.items()]

    def _add_pocket_friction(self, normal, pos, rot, vel, omega, out, react):
        """Adds the ball–pocket friction under the pocket forces ``normal`` (B, Z, 3) (MODEL.md
        §11d, :func:`contact.cage.pocket_friction`) to the balls' slots and its reaction (at the
        contact points) to the cage's per-ball parts of ``react``, in place (the numpy path; the
        compiled one in :func:`contact.kernels.pocket_friction`); returns (force on the balls
        (B, Z, 3) N, loss (B, Z) W)."""
        s, balls = self.layout["cage"], self.layout["balls"]
        c, v, w = pos[:, balls], vel[:, balls], omega[:, balls]
        force, point, loss = cage_physics.pocket_friction(normal, c, v, w, pos[:, s], vel[:, s], omega[:, s],
                                                          self.bearing.ball_radius, self.cage.pocket_friction,
                                                          self.cage.pocket_slip_scale)
        out[:, balls, :3] += force
        out[:, balls, 3:] += np.einsum("bzji,bzj->bzi", rot[:, balls], cross(point - c, force))
        react[:, :, s, :3] -= force
        react[:, :, s, 3:] -= np.einsum("bji,bzj->bzi", rot[:, s], cross(point - pos[:, s, None], force))
        return force, loss

    def contact_kinematics(self, t, q, q_t):
        """The ball–race contact kinematics of B recorded states (times ``t`` (B,) s, absolute
        coordinates and velocities (B, 6 n_nodes)) with perfect surfaces (MODEL.md §2): a
        ``ContactKinematics`` of B 2Z contacts (the inner race's Z first in each state), and the
        balls' rotation matrices (B, Z, 3, 3)."""
        pos, rot, vel, omega = self._decode_batch(q, q_t)
        t = np.asarray(t, dtype=float)
        frames = {name: self._race_frame(name, t, pos, vel, rot, omega) for name in ("inner", "outer")}
        return self._kinematics(pos, vel, omega, frames), rot[:, self.layout["balls"]]

    def _kinematics(self, pos, vel, omega, frames):
        """``ball_race_kinematics`` of all B 2Z contacts, race ``frames`` from :meth:`_race_frame`."""
        bsz, balls = pos.shape[0], self.layout["balls"]
        grooves, signs, _ = self._contact_params(bsz)
        st = [stacked(frames, i, shape, bsz, self.z) for i, shape in enumerate(((3,), (3, 3), (3,), (3,)))]
        return ball_race_kinematics(both_races(pos[:, balls]), both_races(vel[:, balls]), both_races(omega[:, balls]),
                                    *st, grooves, self.bearing.ball_radius, signs)

    def _numpy_forces(self, t, pos, rot, vel, omega, surface=True, compiled=False, known_traction=None):
        """The numpy path of :meth:`_batch_forces` (contact/ functions; the reference of
        the compiled path), before the guiding land, applied loads and held races;
        ``surface=False`` without the surfaces; ``compiled``: the traction by the law's compiled
        rule (:func:`contact.ballrace.ball_race_forces`), and where ``known_traction`` (B, 2, Z, 4)
        has it (not NaN), that rule's result as the run computed it. Returns (out, react, (kinematics, forces, cage
        force, drag force, race angular velocities, pocket friction or None))."""
        bsz, z, n_nodes = pos.shape[0], self.z, self.n_nodes
        balls = self.layout["balls"]
        c, v, w = pos[:, balls], vel[:, balls], omega[:, balls]
        force = np.zeros((bsz, n_nodes, 3))
        torque = np.zeros((bsz, n_nodes, 3))
        # per-ball reactions on race and cage slots (force, torque about the slot's node)
        react_f = np.zeros((bsz, z, n_nodes, 3))
        react_t = np.zeros((bsz, z, n_nodes, 3))
        frames = {name: self._race_frame(name, t, pos, vel, rot, omega) for name in ("inner", "outer")}
        kin_all = self._kinematics(pos, vel, omega, frames)
        params = self._contact_params(bsz)[2]
        if surface and self.surface is not None:  # stage 0 of the per-contact terms (MODEL.md §13)
            pits = {}
            if self.terms.surface.material:  # a ball's own surface: where its material is (eq. 13.3, 13.6)
                pits = dict(ball_rotation=np.concatenate([rot[:, balls]] * 2, axis=1).reshape(-1, 3, 3),
                            ball_omega=both_races(w), race_axis=stacked(frames, 1, (3, 3), bsz, z)[:, :, 2],
                            race_omega=stacked(frames, 3, (3,), bsz, z))
            kin_all = with_surface(kin_all, self.terms, np.tile(np.repeat([0, 1], z), bsz), np.tile(np.arange(z), 2 * bsz),
                                   *self._surface_sizes, **pits)
        known = None if known_traction is None else known_traction.reshape(-1, 4)
        if self.oils[0] is self.oils[1]:
            frc_all = ball_race_forces(kin_all, params, self.oils[0], self.law, self._race_terms[0],
                                       compiled=compiled, known_traction=known)
        else:
            frc_all = ball_race_forces_by_race(kin_all, params, self.oils[:2], self.law, self._race_terms,
                                               compiled=compiled, known_traction=known)
        f_con = frc_all.force.reshape(bsz, 2, z, 3)
        m_con = frc_all.moment.reshape(bsz, 2, z, 3)
        for k, name in enumerate(("inner", "outer")):
            slot = frames[name][4]
            if slot is not None:
                # the race gets -F at p and -M_z n: about its node that is
                # -[(c - x_node) x F + moment about the ball centre]
                react_f[:, :, slot] -= f_con[:, k]
                react_t[:, :, slot] -= cross(c - pos[:, slot, None], f_con[:, k]) + m_con[:, k]
        cage_force = np.zeros((bsz, z, 3))
        if self.cage.kind == "rigid":
            s = self.layout["cage"]
            cage_force = cage_physics.pocket_forces(c, v, pos[:, s], rot[:, s], vel[:, s], omega[:, s],
                                                    self.pocket_angles, self.cage_record.pitch_radius, self.cage.clearance,
                                                    self.cage.stiffness, self.cage_damping)
            react_f[:, :, s] -= cage_force
            react_t[:, :, s] -= cross(c - pos[:, s, None], cage_force)
        elif self.cage.kind == "spring-chain":
            cage_force = cage_physics.spring_chain_forces(c, self.axis, self.cage_record.pitch_radius, self.cage.stiffness,
                                                          self.origin)
        drag_force = np.zeros((bsz, z, 3))
        if self.drag is not None and self.drag.active:
            drag_force = cage_physics.drag_forces(c, v, self.axis, self.origin, self.drag.drag_coefficient,
                                                  self.drag.oil_volume_fraction * self.lubricant.density,
                                                  self.bearing.ball_radius, self.cage_record.drag_linear)
        force[:, balls] += f_con.sum(axis=1) + cage_force + drag_force
        torque[:, balls] += m_con.sum(axis=1)
        out = np.empty((bsz, n_nodes, 6))
        out[..., :3] = force
        out[..., 3:] = np.einsum("bnji,bnj->bni", rot, torque)  # A^T tau: local-omega coordinates
        react = np.empty((bsz, z, n_nodes, 6))
        react[..., :3] = react_f
        react[..., 3:] = np.einsum("bnji,bznj->bzni", rot, react_t)
        # (the compiled kernels add the pocket friction themselves)
        friction = self._add_pocket_friction(cage_force, pos, rot, vel, omega, out, react) \
            if self.cage.pocket_friction > 0 else None
        return out, react, (kin_all, frc_all, cage_force, drag_force,
                            {name: fr[3] for name, fr in frames.items()}, friction)

    def jacobian(self, t, q, q_t, f_q, f_qt, **steps):
        """Block finite-difference Jacobian for Exudyn's ``jacobianUserFunction``
        (:func:`exudyn_bearing.jacobian.block_jacobian`)."""
        return block_jacobian(self, t, q, q_t, f_q, f_qt, **steps)
