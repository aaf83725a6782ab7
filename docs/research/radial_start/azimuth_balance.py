"""Research copy of the reverted exudyn_bearing/quasidynamic.py (commit f23ef30; issue 15, session 12).

Quasi-dynamic start under combined load (MODEL.md §12a).

Under radial load no two balls are alike, and a dynamic run from pure rolling needs up to
seconds of simulated time before the cage speed settles. Here every ball is put in its own
force and moment balance at its azimuth (normal, traction, spin, drag, centrifugal and
gyroscopic, with the dynamic model's contact functions), all balls orbit at one common
cage speed, the pockets take the difference as a circumferential force P_j on each ball,
and the cage is in torque balance, sum_j P_j r_cj = T_land (a free cage: zero). The inner
race stays where the quasi-static solution (MODEL.md §4) puts it.

Unknowns: per ball P_j, its absolute angular velocity w_j and its centre (r_cj, z_cj) in its
azimuth plane (6 Z), and the cage speed; equations: per ball 3 force and 3 moment
components, and the cage's torque. One residual evaluates all 2 Z contacts at once, and the
Jacobian's block structure (each ball's equations depend on its own unknowns and the cage
speed only) is differenced in 7 evaluations.
"""
from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import least_squares

from contact import cage as cage_physics
from contact.ballrace import RaceContact, ball_race_forces
from contact.kinematics import ball_race_kinematics

__all__ = ["AzimuthStates", "quasi_dynamic_state"]

MICRON = 1e-6
_E_Z = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class AzimuthStates:
    """Result of :func:`quasi_dynamic_state` (SI units; per-ball arrays in the ball's
    azimuth frame: x radial, y circumferential, z axial)."""

    cage_speed: float  #: common orbital speed w_c, rad/s
    azimuth: np.ndarray  #: psi_j, rad
    orbit_radius: np.ndarray  #: r_cj, m
    axial_position: np.ndarray  #: z_cj, m
    omega: np.ndarray  #: (Z, 3) absolute ball angular velocities, rad/s
    pocket_force: np.ndarray  #: P_j, circumferential force of the pocket on each ball, N
    residual: float  #: largest scaled equation residual
    converged: bool
    message: str
    wall_time_s: float


class _Balls:
    """The balance equations of all Z balls in their azimuth frames, vectorized."""

    def __init__(self, bearing, lubricant, loads, w_i, w_o, drag, law, land):
        z = bearing.balls
        self.b, self.lub, self.law, self.z = bearing, lubricant, law, z
        self.w_i, self.w_o, self.land = w_i, w_o, land
        psi = np.asarray(loads.azimuth, dtype=float)
        self.psi = psi
        d = np.asarray(loads.displacement, dtype=float)
        # inner race centre in each ball's azimuth frame (the race axis stays along z)
        inner_origin = np.stack([d[0] * np.cos(psi) + d[1] * np.sin(psi), -d[0] * np.sin(psi) + d[1] * np.cos(psi),
                                 np.full(z, d[2])], axis=1)
        self.origin = np.concatenate([inner_origin, np.zeros((z, 3))])
        self.race_omega = np.concatenate([np.tile(w_i * _E_Z, (z, 1)), np.tile(w_o * _E_Z, (z, 1))])
        (r_gi, z_gi), (r_go, z_go) = bearing.groove_centres()
        dia = bearing.ball_diameter
        tube = ((bearing.inner_conformity - 0.5) * dia, (bearing.outer_conformity - 0.5) * dia)
        self.tube = tube
        self.grooves = (np.repeat([r_gi, r_go], z), np.repeat([z_gi, z_go], z), np.repeat(tube, z))
        self.signs = np.repeat([-1.0, 1.0], z)
        self.params = RaceContact(dia, bearing.pitch_diameter,
                                  np.repeat([bearing.inner_conformity, bearing.outer_conformity], z), self.signs,
                                  bearing.effective_modulus, bearing.ball_mass)
        self.density = 0.0 if drag is None else drag.oil_volume_fraction * lubricant.density
        self.c_d = 0.0 if drag is None else drag.drag_coefficient
        self.inertia = 0.4 * bearing.ball_mass * bearing.ball_radius ** 2
        # ~ the heaviest ball's contact load: forces are scaled by it
        self.force_scale = max(float(np.max(loads.inner_load)), float(np.max(loads.outer_load)), 1e-3)
        w_nom = abs(bearing.cage_speed(w_i, w_o)) or 1.0
        self.w_scale = abs(w_i - w_o) * bearing.pitch_diameter / dia / 2 or 1.0
        self.scale = np.concatenate([np.tile([self.force_scale, *[self.w_scale] * 3, MICRON, MICRON], z), [w_nom]])

    def unpack(self, x):
        """(P (Z,), w_b (Z, 3), centres (Z, 3), w_c) from the scaled unknowns."""
        y = x * self.scale
        per = y[:-1].reshape(self.z, 6)
        return per[:, 0], per[:, 1:4], self._centres(per[:, 4], per[:, 5]), y[-1]

    def _centres(self, radial_offset, axial_offset):
        return np.stack([self.b.pitch_radius + radial_offset, np.zeros(self.z), axial_offset], axis=1)

    def contacts(self, x):
        """(kinematics, forces) of the 2 Z contacts: inner contacts of balls 0..Z-1, then outer."""
        _, w_b, c, w_c = self.unpack(x)
        return self._contacts(w_b, c, w_c)

    def _contacts(self, w_b, c, w_c):
        both = np.concatenate([c, c])
        v = np.stack([np.zeros(2 * self.z), w_c * both[:, 0], np.zeros(2 * self.z)], axis=1)
        kin = ball_race_kinematics(both, v, np.concatenate([w_b, w_b]), self.origin, np.eye(3), np.zeros(3),
                                   self.race_omega, self.grooves, self.b.ball_radius, self.signs)
        return kin, ball_race_forces(kin, self.params, self.lub, self.law)

    def balance(self, x):
        """Scaled per-ball force (Z, 3) and moment (Z, 3) residuals and the cage's torque."""
        pocket, w_b, c, w_c = self.unpack(x)
        _, f = self._contacts(w_b, c, w_c)
        z = self.z
        force = f.force[:z] + f.force[z:]
        force[:, 0] += self.b.ball_mass * c[:, 0] * w_c ** 2
        force[:, 1] += pocket
        if self.density > 0:
            v = np.stack([np.zeros(z), w_c * c[:, 0], np.zeros(z)], axis=1)
            force += cage_physics.drag_forces(c, v, _E_Z, np.zeros(3), self.c_d, self.density, self.b.ball_radius)
        moment = f.moment[:z] + f.moment[z:] - self.inertia * w_c * np.cross(_E_Z, w_b)
        s = self.force_scale
        torque = self.land[0] * (self.land[1] - w_c) - float(np.sum(pocket * c[:, 0]))
        return force / s, moment / (s * self.b.ball_radius), torque / (s * self.b.pitch_radius)

    def residual(self, x):
        force, moment, torque = self.balance(x)
        return np.concatenate([np.concatenate([force, moment], axis=1).ravel(), [torque]])

    def _torque_row(self, x, pocket_cols, radius_cols):
        """The cage torque's exact derivatives by the pocket forces and orbit radii."""
        pocket, _, c, _ = self.unpack(x)
        row = np.zeros(x.size)
        norm = self.force_scale * self.b.pitch_radius
        row[pocket_cols] = -c[:, 0] * self.force_scale / norm
        row[radius_cols] = -pocket * MICRON / norm
        row[-1] = -self.land[0] * self.scale[-1] / norm
        return row

    def jacobian(self, x, step=1e-6):
        """d residual / d x: each ball's equations depend on its own unknowns and the cage
        speed only, so one perturbation of the same unknown of every ball gives all their
        blocks (6 + 1 evaluations); the cage's torque row is exact."""
        z, n = self.z, 6 * self.z + 1
        f0 = self.residual(x)
        jac = np.zeros((n, n))
        rows = np.arange(6 * z).reshape(z, 6)
        for k in range(6):
            xk = x.copy()
            xk[k:-1:6] += step
            d = (self.residual(xk) - f0) / step
            for i in range(6):  # ball j's row i, column 6 j + k
                jac[rows[:, i], rows[:, k]] = d[rows[:, i]]
        xc = x.copy()
        xc[-1] += step
        jac[:-1, -1] = (self.residual(xc) - f0)[:-1] / step
        jac[-1] = self._torque_row(x, np.arange(0, 6 * z, 6), np.arange(4, 6 * z, 6))
        return jac

    def bounds(self):
        play = 1e6 * (self.tube[0] + self.tube[1])  # um
        w = sorted((self.w_i, self.w_o))
        lo = np.concatenate([np.tile([-np.inf, -3.0, -3.0, -3.0, -play, -play], self.z), [w[0] / self.scale[-1] - 1e-3]])
        hi = np.concatenate([np.tile([np.inf, 3.0, 3.0, 3.0, play, play], self.z), [w[1] / self.scale[-1] + 1e-3]])
        return lo, hi

    def start(self, loads, omega, cage_speed):
        """Scaled unknowns at the quasi-static positions, ``omega`` (Z, 3) and ``cage_speed``."""
        x = np.zeros(6 * self.z + 1)
        per = x[:-1].reshape(self.z, 6)
        per[:, 1:4] = np.asarray(omega, dtype=float) / self.w_scale
        per[:, 4] = np.asarray(loads.ball_radius_offset) / MICRON
        per[:, 5] = np.asarray(loads.ball_axial_offset) / MICRON
        x[-1] = cage_speed / self.scale[-1]
        return x


class _BallsCommonSpin(_Balls):
    """The orbit-averaged variant: every ball spins alike in its azimuth frame (its spin
    cannot follow the load around the orbit when the traction's time constant I w / (mu Q r)
    exceeds the orbit period, i.e. at light load), so the balls' moments balance in sum,
    while each ball's forces balance at its azimuth. Unknowns: per ball P_j, r_cj, z_cj (3 Z),
    the common w (3) and w_c; equations: per ball 3 forces, the summed moment, the cage."""

    def __init__(self, *args):
        super().__init__(*args)
        self.scale = np.concatenate([np.tile([self.force_scale, MICRON, MICRON], self.z), [self.w_scale] * 3,
                                     [self.scale[-1]]])

    def unpack(self, x):
        y = x * self.scale
        z = self.z
        per = y[:3 * z].reshape(z, 3)
        return per[:, 0], np.tile(y[3 * z:3 * z + 3], (z, 1)), self._centres(per[:, 1], per[:, 2]), y[-1]

    def residual(self, x):
        force, moment, torque = self.balance(x)
        return np.concatenate([force.ravel(), moment.sum(axis=0), [torque]])

    def jacobian(self, x, step=1e-6):
        """Per-ball force blocks by perturbing the same unknown of every ball at once (their
        moments too: the summed moment's derivative by ball j's unknowns is ball j's own),
        the common spin and the cage speed one at a time; the torque row exact."""
        z, n = self.z, 3 * self.z + 4
        force0, moment0, _ = self.balance(x)
        jac = np.zeros((n, n))
        rows = np.arange(3 * z).reshape(z, 3)
        for k in range(3):
            xk = x.copy()
            xk[k:3 * z:3] += step
            force, moment, _ = self.balance(xk)
            for i in range(3):
                jac[rows[:, i], rows[:, k]] = (force[:, i] - force0[:, i]) / step
            jac[3 * z:3 * z + 3, rows[:, k]] = ((moment - moment0) / step).T
        for col in range(3 * z, n):
            xc = x.copy()
            xc[col] += step
            force, moment, _ = self.balance(xc)
            jac[:3 * z, col] = ((force - force0) / step).ravel()
            jac[3 * z:3 * z + 3, col] = (moment - moment0).sum(axis=0) / step
        jac[-1] = self._torque_row(x, np.arange(0, 3 * z, 3), np.arange(1, 3 * z, 3))
        return jac

    def bounds(self):
        play = 1e6 * (self.tube[0] + self.tube[1])
        w = sorted((self.w_i, self.w_o))
        lo = np.concatenate([np.tile([-np.inf, -play, -play], self.z), [-3.0] * 3, [w[0] / self.scale[-1] - 1e-3]])
        hi = np.concatenate([np.tile([np.inf, play, play], self.z), [3.0] * 3, [w[1] / self.scale[-1] + 1e-3]])
        return lo, hi

    def start(self, loads, omega, cage_speed):
        x = np.zeros(3 * self.z + 4)
        per = x[:3 * self.z].reshape(self.z, 3)
        per[:, 1] = np.asarray(loads.ball_radius_offset) / MICRON
        per[:, 2] = np.asarray(loads.ball_axial_offset) / MICRON
        x[3 * self.z:3 * self.z + 3] = np.mean(np.asarray(omega, dtype=float), axis=0) / self.w_scale
        x[-1] = cage_speed / self.scale[-1]
        return x


def quasi_dynamic_state(bearing, lubricant, loads, *, rpm: float, outer_rpm: float = 0.0, drag=None,
                        contact_law=None, cage=None, omega=None, cage_speed=None, spin: str = "azimuth",
                        tol: float = 1e-6, max_evaluations: int = 400) -> AzimuthStates:
    """Every ball in force and moment balance at one common cage speed, the cage in torque
    balance (module docstring, MODEL.md §12a), for the inner-race position of the
    quasi-static solution ``loads`` (:func:`exudyn_bearing.solve_load_distribution` at these
    speeds).

    Parameters
    ----------
    bearing, lubricant, drag, contact_law
        As for :func:`exudyn_bearing.steady_state`.
    loads : LoadDistribution
        Quasi-static solution: azimuths, ball positions (start) and the inner race's
        displacement (kept).
    rpm, outer_rpm : float
        Race speeds, rev/min.
    cage : CageModel, optional
        Its guiding land's friction torque (centred cage, MODEL.md §11d) is the cage's load;
        pocket friction is left out of the start.
    omega, cage_speed : optional
        Start: the balls' angular velocities in their azimuth frames (Z, 3), rad/s (default
        zero), and the cage speed, rad/s (default P19's nominal one).
    tol, max_evaluations
        Largest scaled residual accepted; residual evaluations allowed (the Jacobian's
        included).

    Returns
    -------
    AzimuthStates
        ``converged`` False with a ``message`` where no balance was found; its numbers must
        then not be used.
    """
    from contact.ballrace import ContactLaw

    start = _time.perf_counter()
    law = replace(contact_law or ContactLaw(), fast_quadrature=False,
                  quadrature_order=max(16, (contact_law or ContactLaw()).quadrature_order))
    w_i, w_o = rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0
    land = (0.0, 0.0)
    friction = 0.0 if cage is None else cage.land_friction_constant(bearing, lubricant)
    if friction > 0:
        land = (friction, w_o if cage.guidance == "outer" else w_i)
    variant = _BallsCommonSpin if spin == "common" else _Balls
    balls = variant(bearing, lubricant, loads, w_i, w_o, drag, law, land)
    if omega is None:
        omega = np.zeros((bearing.balls, 3))
    x0 = balls.start(loads, omega, cage_speed if cage_speed is not None else bearing.cage_speed(w_i, w_o))
    lo, hi = balls.bounds()
    sol = least_squares(balls.residual, np.clip(x0, lo, hi), jac=balls.jacobian, method="trf",
                        bounds=(lo, hi), xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=max_evaluations)
    worst = float(np.max(np.abs(sol.fun)))
    converged = bool(worst <= tol) and not np.any(sol.active_mask != 0)
    pocket, w_b, c, w_c = balls.unpack(sol.x)
    message = "converged" if converged else (
        f"no quasi-dynamic balance found (largest scaled residual {worst:.2g} > {tol:g} after {sol.nfev} evaluations)")
    return AzimuthStates(float(w_c), balls.psi.copy(), c[:, 0].copy(), c[:, 2].copy(), w_b.copy(), pocket.copy(),
                         worst, converged, message, _time.perf_counter() - start)
