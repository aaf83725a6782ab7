"""The quasi-dynamic balance of all balls, the cage and the inner race at one load or pose
(MODEL.md §12a): the equations :func:`~exudyn_bearing.solvers.quasidynamic.combined_load_state`
and :func:`~exudyn_bearing.solvers.quasidynamic.pose_state` solve, their Jacobian, and the
spectral derivative of the balls' spin transport along the orbit."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from contact import cage as cage_physics
from contact.ballrace import ball_race_forces, ball_race_forces_by_race
from contact.kinematics import ball_race_kinematics
from ..contact_records import contact_records

MICRON = 1e-6
_E_Z = np.array([0.0, 0.0, 1.0])


class _Balance:
    """The balance equations of all balls, the cage and the inner race, vectorized."""

    def __init__(self, bearing, lubricant, w_i, w_o, drag, law, land, axial, radial, pose=None, cage_offset=None,
                 oils=None):
        z = bearing.balls
        self.b, self.lub, self.law, self.z = bearing, lubricant, law, z
        # the inner and outer contacts' and the land's oils where they differ (the thermal
        # network, MODEL.md §14b): (inner, outer, land) or None
        self.oils = oils
        self.land_lubricant = lubricant if oils is None else oils[2]
        self.race_terms = None if oils is None else tuple(contact_records(bearing, lub, law, balls=z).terms
                                                          for lub in oils[:2])
        self.land, self.applied = land, np.array([radial, 0.0, axial])
        self.psi = 2.0 * np.pi * np.arange(z) / z
        self.e_r = np.stack([np.cos(self.psi), np.sin(self.psi), np.zeros(z)], axis=1)
        self.e_p = np.stack([-np.sin(self.psi), np.cos(self.psi), np.zeros(z)], axis=1)
        self.race_omega = np.concatenate([np.tile(w_i * _E_Z, (z, 1)), np.tile(w_o * _E_Z, (z, 1))])
        records = contact_records(bearing, lubricant, law, balls=z)
        self.tube, self.grooves, self.signs, self.params, self.terms = records[:5]
        self.density = 0.0 if drag is None else drag.oil_volume_fraction * lubricant.density
        self.c_d = 0.0 if drag is None else drag.drag_coefficient
        self.drag_linear = 0.0 if drag is None else drag.momentum_factor(bearing, lubricant.density)  # eq. 11c.2
        self.inertia = bearing.ball_inertia
        d = bearing.ball_diameter
        self.force_scale = max(axial, abs(radial), 1e-3) / (z * max(math.sin(bearing.contact_angle), 0.1))
        w_scale = abs(w_i - w_o) * bearing.pitch_diameter / d / 2 or 1.0
        self.scale = np.concatenate([np.tile([self.force_scale, w_scale, w_scale, w_scale, MICRON, MICRON], z),
                                     [abs(bearing.cage_speed(w_i, w_o)) or 1.0], [MICRON] * 3])
        self.w_bounds = sorted((w_i, w_o))
        # the balls orbit with their pockets about the cage centre, which its land holds off
        # the bearing's (MODEL.md §12a): its offset along each ball's e_r and e_psi
        e = np.zeros(3) if cage_offset is None else np.asarray(cage_offset, dtype=float)
        self.cage_offset = e
        self.offset_r, self.offset_p = self.e_r @ e, self.e_p @ e
        # a ball's spin changes along its orbit: I dw/dt = I w_c dw/dpsi in the orbiting frame
        # (MODEL.md §12a), the derivative over the Z balls' azimuths taken spectrally
        self.transport = self.inertia * spectral_derivative(z) / (self.force_scale * bearing.ball_radius)
        # a prescribed inner-race pose (pose_state): its displacement replaces the race's force
        # balance, and a small tilt theta moves each ball's inner groove centre by
        # theta x (r_gi e_r + z_gi e_z), the first-order rigid rotation of the groove circle
        self.pose, self.groove_shift = None, np.zeros((z, 3))
        if pose is not None:
            self.pose = np.asarray(pose[:3], dtype=float)
            (r_gi, z_gi), _ = bearing.groove_centres()
            theta = np.array([pose[3], pose[4], 0.0])
            shift = np.cross(theta, r_gi * self.e_r + z_gi * _E_Z)
            self.groove_shift = np.stack([np.einsum("ij,ij->i", shift, self.e_r),
                                          np.einsum("ij,ij->i", shift, self.e_p), shift[:, 2]], axis=1)

    def unpack(self, x):
        """(P (Z,), w_b (Z, 3), centres (Z, 3), w_c, race displacement (3,)) of the scaled unknowns."""
        y = x * self.scale
        per = y[:6 * self.z].reshape(self.z, 6)
        centre = np.stack([self.b.pitch_radius + per[:, 4], np.zeros(self.z), per[:, 5]], axis=1)
        return per[:, 0], per[:, 1:4], centre, y[6 * self.z], y[-3:]

    def parts(self, x):
        """Scaled per-ball forces and moments (Z, 3 each), the cage's torque and each ball's
        share of the inner race's force balance (Z, 3), bearing frame."""
        return self.parts_of_many(x[None, :])[0]

    def parts_of_many(self, xs):
        """:meth:`parts` of B unknown vectors ``xs`` (B, 6 Z + 4): their ball–race contacts in
        one call (each contact's forces do not depend on the others', so each state's parts
        are those of :meth:`parts` alone, bit for bit), the rest state by state."""
        z = self.z
        states = [self._motion(x) for x in xs]
        b = len(states)
        stack = lambda k: np.concatenate([state[k] for state in states])  # noqa: E731
        _, f = self._contacts(stack, b)
        return [self._balance(state, f.force[2 * z * i:2 * z * (i + 1)], f.moment[2 * z * i:2 * z * (i + 1)])
                for i, state in enumerate(states)]

    def contacts(self, x):
        """(kinematics, forces) of the 2 Z ball–race contacts (inner, then outer) at ``x``."""
        state = self._motion(x)
        return self._contacts(lambda k: state[k], 1)

    def _contacts(self, stack, b):
        """(kinematics, forces) of the contacts of ``b`` states, ``stack(key)`` their inputs."""
        grooves, signs, params = self.contacts_of(b)
        kin = ball_race_kinematics(stack("both"), stack("v"), stack("w"), stack("origin"), np.eye(3), np.zeros(3),
                                   np.tile(self.race_omega, (b, 1)), grooves, self.b.ball_radius, signs)
        if self.oils is None:
            return kin, ball_race_forces(kin, params, self.lub, self.law, self.terms)
        return kin, ball_race_forces_by_race(kin, params, self.oils[:2], self.law, self.race_terms)

    def contacts_of(self, b):
        """(groove records, race signs, :class:`~contact.ballrace.RaceContact`) of the
        contacts of ``b`` states at once: each race record repeated per state."""
        if b == 1:
            return self.grooves, self.signs, self.params
        p = self.params
        return (tuple(np.tile(g, b) for g in self.grooves), np.tile(self.signs, b),
                replace(p, conformity=np.tile(p.conformity, b), race=np.tile(p.race, b)))

    def _motion(self, x):
        """The unknowns ``x`` unpacked with the balls' contact inputs (both races' contacts)."""
        pocket, w_b, c, w_c, d = self.unpack(x)
        z = self.z
        inner_origin = np.stack([self.e_r @ d, self.e_p @ d, np.full(z, d[2])], axis=1) + self.groove_shift
        # v = w_c e_z x (c - e): circular motion about the cage centre e
        arm = np.tile(np.stack([c[:, 0] - self.offset_r, -self.offset_p], axis=1), (2, 1))
        return dict(pocket=pocket, w_b=w_b, c=c, w_c=w_c, arm=arm,
                    origin=np.concatenate([inner_origin, np.zeros((z, 3))]), both=np.concatenate([c, c]),
                    v=np.stack([-w_c * arm[:, 1], w_c * arm[:, 0], np.zeros(2 * z)], axis=1),
                    w=np.concatenate([w_b, w_b]))

    def _balance(self, state, contact_force, contact_moment):
        """:meth:`parts` of one state from its contacts' forces and moments (2 Z, 3)."""
        z = self.z
        pocket, w_b, c, w_c, arm, v = (state[k] for k in ("pocket", "w_b", "c", "w_c", "arm", "v"))
        force = contact_force[:z] + contact_force[z:]
        force[:, :2] += self.b.ball_mass * w_c ** 2 * arm[:z]  # -m a = m w_c^2 (c - e)
        force[:, 1] += pocket
        if self.density > 0 or self.drag_linear > 0:
            force += cage_physics.drag_forces(c, v[:z], _E_Z, np.zeros(3), self.c_d, self.density, self.b.ball_radius,
                                              self.drag_linear)
        moment = contact_moment[:z] + contact_moment[z:] - self.inertia * w_c * np.cross(_E_Z, w_b)
        s = self.force_scale
        torque = self.land[0] * (self.land[1] - w_c) - float(np.sum(pocket * (c[:, 0] - self.offset_r)))
        fi = contact_force[:z]  # the inner race takes minus each ball's inner contact force
        race = -(fi[:, :1] * self.e_r + fi[:, 1:2] * self.e_p + fi[:, 2:] * _E_Z)
        if self.pose is not None:  # the race is held at its pose: no force balance to share
            race = np.zeros_like(race)
        return force / s, moment / (s * self.b.ball_radius), torque / (s * self.b.pitch_radius), race / s

    def orbit_inertia(self, x):
        """Scaled moment each ball needs to change its spin along the orbit, (Z, 3)."""
        _, w_b, _, w_c, _ = self.unpack(x)
        return w_c * (self.transport @ w_b)

    def residual(self, x):
        return self._residual(x, self.parts(x))

    def _residual(self, x, parts):
        """:meth:`residual` of ``x`` from its :meth:`parts`."""
        force, moment, torque, race = parts
        moment = moment - self.orbit_inertia(x)
        if self.pose is None:
            tail = race.sum(axis=0) + self.applied / self.force_scale
        else:
            tail = (x[-3:] * self.scale[-3:] - self.pose) / MICRON
        return np.concatenate([np.concatenate([force, moment], axis=1).ravel(), [torque], tail])

    def jacobian(self, x, step=1e-6):
        """Per-ball blocks (and their shares of the race rows) from one perturbation of the
        same unknown of every ball; the cage speed and race columns one at a time; the cage
        torque row exact."""
        z, n = self.z, 6 * self.z + 4
        # the base state, one perturbation of the same unknown of every ball (k = 0..5) and
        # the cage speed and race columns one at a time: one batch of contacts
        states = np.repeat(x[None, :], 1 + 6 + (n - 6 * z), axis=0)
        for k in range(6):
            states[1 + k, k:6 * z:6] += step
        for col in range(6 * z, n):
            states[7 + col - 6 * z, col] += step
        parts = self.parts_of_many(states)
        f0, m0, _, r0 = parts[0]
        jac = np.zeros((n, n))
        rows = np.arange(6 * z).reshape(z, 6)
        race_rows = np.arange(6 * z + 1, n)
        for k in range(6):
            f, m, _, r = parts[1 + k]
            d = np.concatenate([f - f0, m - m0], axis=1) / step
            for i in range(6):
                jac[rows[:, i], rows[:, k]] = d[:, i]
            jac[race_rows[:, None], rows[:, k][None, :]] = ((r - r0) / step).T
        base = self._residual(x, parts[0])
        for col in range(6 * z, n):
            xc = states[7 + col - 6 * z]
            jac[:, col] = (self._residual(xc, parts[7 + col - 6 * z]) - base) / step
        pocket, _, c, _, _ = self.unpack(x)
        norm = self.force_scale * self.b.pitch_radius
        # the orbit transport couples the balls' spins: its part of the spin columns exactly
        # (the cage-speed column, differenced from the residual, has it already)
        w_c = self.unpack(x)[3]
        coupling = -w_c * self.transport * self.scale[1]
        for i in range(3):
            jac[rows[:, 3 + i][:, None], rows[:, 1 + i][None, :]] += coupling
        jac[6 * z] = 0.0
        jac[6 * z, 0:6 * z:6] = -(c[:, 0] - self.offset_r) * self.force_scale / norm
        jac[6 * z, 4:6 * z:6] = -pocket * MICRON / norm
        jac[6 * z, 6 * z] = -self.land[0] * self.scale[6 * z] / norm
        return jac

    def bounds(self):
        play = 1e6 * (self.tube[0] + self.tube[1])  # um
        w = self.w_bounds
        lo = np.concatenate([np.tile([-np.inf, -3.0, -3.0, -3.0, -play, -play], self.z),
                             [w[0] / self.scale[6 * self.z] - 1e-3], [-np.inf] * 3])
        hi = np.concatenate([np.tile([np.inf, 3.0, 3.0, 3.0, play, play], self.z),
                             [w[1] / self.scale[6 * self.z] + 1e-3], [np.inf] * 3])
        return lo, hi


def spectral_derivative(n: int) -> np.ndarray:
    """Matrix D with (D f)_j = df/dpsi at psi_j = 2 pi j / n for a periodic f sampled there,
    exact for trigonometric polynomials of degree below n / 2 (Trefethen, Spectral Methods
    in MATLAB, 2000, ch. 3: cot for even n, csc for odd n)."""
    j = np.arange(n)
    k = j[:, None] - j[None, :]
    half = np.pi * k / n
    with np.errstate(divide="ignore"):
        entries = 0.5 * (-1.0) ** k / (np.tan(half) if n % 2 == 0 else np.sin(half))
    entries[k == 0] = 0.0
    return entries
