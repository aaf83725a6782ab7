"""The steady balance of one ball under pure axial load (quasi-dynamic, MODEL.md §12).

Under an axisymmetric load all balls behave alike and the cage carries no torque, so every
pocket force vanishes and one ball describes the bearing. In the frame that orbits with the
ball at the cage speed w_c its centre c = (r_c, 0, z_c) is at rest and its absolute angular
velocity w_b is constant, so (MODEL.md §1–§3, §6, §8)

    force on the ball:   F_inner + F_outer + F_drag = -m r_c w_c² e_r
    moment about c:      M_inner + M_outer = I w_c e_z × w_b          (sphere, I = 2/5 m r²)
    inner race, axial:   Z (F_inner · e_z) = F_a

— seven equations in (w_c, w_b, r_c, z_c, axial shift of the inner race). The contact
forces are those of the dynamic model: :func:`contact.kinematics.ball_race_kinematics` and
:func:`contact.ballrace.ball_race_forces` with the same :class:`~contact.ballrace.ContactLaw`
(its fast traction rule), so a settled dynamic run and this balance describe the same
physics; only the integration is gone.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, fields, replace
from typing import NamedTuple

import numpy as np
from scipy.optimize import least_squares

from contact import cage as cage_physics
from contact.ballrace import ball_race_forces
from contact.kinematics import ball_race_kinematics, rolling_cage_speed
from ..contact_records import contact_records
from ..setup import BearingSetup
from ..results.outputs import cage_slip
from ..results.records import units_of
from .newton import damped_newton
from .quasistatic import solve_load_distribution
from .raceway import raceway_control
from .steady_power import by_source, steady_drive_power, steady_losses

__all__ = ["SteadyState", "Solved", "solve_steady", "steady_result"]

MICRON = 1e-6
#: largest scaled residual of the start's partial balances (speeds with the position held,
#: position with the speeds held)
PART_TOLERANCE = 1e-10
_E_Z = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class SteadyState:
    """Result of :func:`steady_state` (SI units; angles in degrees where the name says so)."""

    axial: float  #: applied axial load F_a, N
    rpm: float  #: inner-race speed, rev/min
    kinematic_cage_slip_percent: float  #: (w_kin - w_c) / mean, % (MODEL.md §7)
    cage_slip_percent: float  #: against the nominal pure-rolling cage speed (P19), %
    cage_speed: float  #: w_c, rad/s
    kinematic_cage_speed: float  #: pure-rolling orbital speed for the ball's spin axis, rad/s
    nominal_cage_speed: float  #: P19 with the free contact angle, rad/s
    attitude_xz_deg: float  #: asin(|w_radial| / |w_b|), deg (MODEL.md §7)
    attitude_yz_deg: float  #: asin(|w_circumferential| / |w_b|), deg
    ball_omega: tuple  #: absolute ball angular velocity (radial, circumferential, axial), rad/s
    inner_load: float  #: Q_i, N
    outer_load: float  #: Q_o, N
    inner_contact_angle_deg: float
    outer_contact_angle_deg: float
    inner_max_pressure: float  #: p_max, Pa
    outer_max_pressure: float  #: Pa
    inner_race_shift: float  #: axial displacement of the inner race, m
    ball_orbit_radius: float  #: r_c of the ball centres, m
    ball_axial_position: float  #: z_c of the ball centres, m
    residual: float  #: largest scaled equation residual (force / (F_a/Z sin a0))
    converged: bool
    message: str
    wall_time_s: float
    #: what produced it (:func:`exudyn_bearing.results.records.inputs_record`)
    inputs: dict = field(default_factory=dict, compare=False)
    #: losses by source (traction, rolling_resistance, ball_drag, cage, total), W (MODEL.md §11)
    power_loss_W: dict = field(default_factory=dict)
    #: power the races' drives put in, W (equals the total loss in a steady state)
    drive_power_W: float = math.nan
    #: the thermal network's solution (MODEL.md §14): temperatures_K per node, heat_W per
    #: node and per place, removed_W (oil, ambient), the contacts' oil; None: isothermal
    thermal: dict | None = None

    def to_dict(self) -> dict:
        """JSON-ready: the fields, ``units`` (the unit of every key) and ``inputs``."""
        data = asdict(self)
        data["ball_omega"] = list(self.ball_omega)
        inputs = data.pop("inputs")
        return data | {"units": units_of(data), "inputs": inputs}


class _OutOfBudget(Exception):
    """A start took more residual evaluations than :data:`START_BUDGET`."""


#: residual evaluations one start (continuation and joint solve) may take before the next
#: start axis is tried: converging starts took 160–410 (35-mm bearing, 28 000–72 000 rpm),
#: a runaway continuation 36 000–47 000 (50–60 s)
START_BUDGET = 1500


class _OneBall:
    """The balance equations of one ball at azimuth 0 (x radial, y circumferential, z axial)."""

    def __init__(self, bearing, lubricant, axial, w_i, w_o, drag, law, land=(0.0, 0.0), pocket=(0.0, 0.01),
                 races=None):
        self.b, self.lub, self.law = bearing, lubricant, law
        # the inner and outer contact's oil where they differ (the thermal network, MODEL.md §14):
        # each contact from its own race's records
        self.races = None if races is None else [contact_records(bearing, lub, law, balls=1) for lub in races]
        self.race_lubricants = races
        # guiding-land friction of the cage (MODEL.md §11d): (K, guiding race speed); the
        # pockets pass its torque on to the balls, T/(Z r_c) each against the orbit
        self.land = land
        self.pocket = pocket  # ball–pocket friction (mu, slip scale m/s), MODEL.md §11d
        self.calls, self.budget = 0, math.inf
        self.axial, self.w_i, self.w_o = axial, w_i, w_o
        # inner contact first, then outer: one vectorized evaluation of both
        records = contact_records(bearing, lubricant, law, balls=1)
        self.tube, self.grooves, self.signs, self.params, self.terms = records[:5]
        self.density = 0.0 if drag is None else drag.oil_volume_fraction * lubricant.density
        self.c_d = 0.0 if drag is None else drag.drag_coefficient
        self.drag_linear = 0.0 if drag is None else drag.momentum_factor(bearing, lubricant.density)  # eq. 11c.2
        self.inertia = bearing.ball_inertia
        d = bearing.ball_diameter
        # ~ a ball's contact load (a zero-clearance bearing has no free angle: at least 0.1)
        self.force_scale = max(axial, 1e-3) / (bearing.balls * max(math.sin(bearing.contact_angle), 0.1))
        # unknowns scaled to O(1): speeds by the nominal cage / ball spin speeds, lengths in um
        w_nom = abs(bearing.cage_speed(w_i, w_o)) or 1.0
        self.scale = np.array([w_nom, *[abs(w_i - w_o) * bearing.pitch_diameter / d / 2 or 1.0] * 3,
                               MICRON, MICRON, MICRON])

    def bounds(self):
        """Bounds of the scaled unknowns: the cage between the race speeds, ball spin within
        three times its pure-rolling scale (beyond, the film thickens without bound and
        the traction of a runaway spin tends to zero: a spurious root at infinity),
        positions within the groove play."""
        w = sorted((self.w_i, self.w_o))
        play = 1e6 * (self.tube[0] + self.tube[1])  # um
        lo = np.array([w[0] / self.scale[0] - 1e-3, -3.0, -3.0, -3.0, -play, -play, -play])
        hi = np.array([w[1] / self.scale[0] + 1e-3, 3.0, 3.0, 3.0, play, play, play])
        return lo, hi

    def unpack(self, x):
        x = x * self.scale
        return x[0], x[1:4], np.array([self.b.pitch_radius + x[4], 0.0, x[5]]), x[6]

    def contacts(self, x):
        """(kinematics, forces) of the inner (index 0) and outer (1) contact at the unknowns ``x``."""
        w_c, w_b, c, shift = self.unpack(x)
        both = np.stack([c, c])
        v = np.array([[0.0, w_c * c[0], 0.0]] * 2)
        origin = np.array([[0.0, 0.0, shift], [0.0, 0.0, 0.0]])
        w_r = np.array([self.w_i * _E_Z, self.w_o * _E_Z])
        kin = ball_race_kinematics(both, v, np.stack([w_b, w_b]), origin, np.eye(3), np.zeros(3), w_r,
                                   self.grooves, self.b.ball_radius, self.signs)
        if self.races is None:
            return kin, ball_race_forces(kin, self.params, self.lub, self.law, self.terms)
        inner, outer = (ball_race_forces(kin, r.races, lub, self.law, r.terms)
                        for r, lub in zip(self.races, self.race_lubricants))
        rows = {}
        for name in (f.name for f in fields(inner)):
            a, b = getattr(inner, name), getattr(outer, name)
            rows[name] = None if a is None else np.stack([a[0], b[1]])
        return kin, type(inner)(**rows)

    def pocket_forces(self, c, w_c, w_b):
        """(pocket force, pocket friction, contact point - ball centre) on the ball under the
        land torque T = K (w_land - w_c): the Z pockets pass T on to the balls, so the cage's
        torque balance about the axis, Z (r_c P + (p x F_f)_z) = T with the friction
        F_f = mu |P| g (:func:`contact.cage.pocket_friction`, g from the slip direction at
        p), gives the pocket load P (MODEL.md §11d, §12)."""
        torque = self.land[0] * (self.land[1] - w_c) / self.b.balls
        sign = 1.0 if torque >= 0 else -1.0
        unit = np.array([[0.0, sign, 0.0]])
        mu, slip_scale = self.pocket
        g, point, _ = cage_physics.pocket_friction(unit, c[None], np.array([[0.0, w_c * c[0], 0.0]]), w_b[None],
                                                   np.zeros(3), np.zeros(3), w_c * _E_Z, self.b.ball_radius,
                                                   mu, slip_scale)
        g, point = g[0], point[0]  # friction per newton of pocket load
        load = abs(torque) / (c[0] + sign * np.cross(point, g)[2])
        return load * unit[0], load * g, point - c

    def residual(self, x):
        self.calls += 1
        if self.calls > self.budget:
            raise _OutOfBudget
        w_c, w_b, c, _ = self.unpack(x)
        _, f = self.contacts(x)
        force = f.force[0] + f.force[1] + self.b.ball_mass * c[0] * w_c ** 2 * np.array([1.0, 0.0, 0.0])
        if self.density > 0 or self.drag_linear > 0:
            force += cage_physics.drag_forces(c[None], np.array([[0.0, w_c * c[0], 0.0]]), _E_Z, np.zeros(3),
                                              self.c_d, self.density, self.b.ball_radius, self.drag_linear)[0]
        moment = f.moment[0] + f.moment[1] - self.inertia * w_c * np.cross(_E_Z, w_b)
        if self.land[0] > 0:  # a centred cage (eccentricity 0)
            pocket, friction, arm = self.pocket_forces(c, w_c, w_b)
            force += pocket + friction
            moment += np.cross(arm, friction)
        axial = f.force[0, 2] - self.axial / self.b.balls
        s = self.force_scale
        return np.concatenate([force / s, moment / (s * self.b.ball_radius), [axial / s]])


class Solved(NamedTuple):
    """A steady balance as :func:`solve_steady` left it."""

    ball: "_OneBall"
    x: np.ndarray  #: the scaled unknowns
    worst: float  #: largest scaled residual
    converged: bool
    message: str
    axial: float  #: N
    rpm: float
    w_i: float  #: rad/s
    w_o: float  #: rad/s


def solve_steady(setup: BearingSetup, axial_force: float, rpm: float, outer_rpm: float, tol: float,
                 races=None, land_lubricant=None) -> Solved:
    """The steady balance of :func:`steady_state` (checked inputs); ``races`` = (inner, outer)
    contact lubricants and ``land_lubricant`` the cage land's where they differ from the
    setup's lubricant (MODEL.md §14)."""
    bearing, lubricant, ball_drag, contact_law, cage = (setup.bearing, setup.lubricant, setup.drag, setup.contact_law,
                                                        setup.cage)
    w_i, w_o = rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0
    # the accurate traction rule: the fast rule's ray switching is not smooth enough for a
    # root finder to converge below ~1e-3, while the two rules agree within 1e-2 (MODEL.md §6)
    law = replace(contact_law, fast_quadrature=False, quadrature_order=max(16, contact_law.quadrature_order))
    land = cage.centred_land_load(bearing, land_lubricant or lubricant, w_i, w_o)
    pocket = (cage.pocket_friction, cage.pocket_slip_scale)
    ball = _OneBall(bearing, lubricant, axial_force, w_i, w_o, ball_drag, law, land, pocket, races)
    lo, hi = ball.bounds()
    # the free-angle axis first; at speed, where the gyroscopic moment turns the ball towards
    # outer-raceway control, the continuation from it can run away: then the exact
    # raceway-control axes (MODEL.md §7, §12)
    sol, worst, converged, x, sol_on_bound = None, math.inf, False, np.clip(np.zeros(7), lo, hi), False
    for axis in ("free", "outer", "inner"):
        ball.calls, ball.budget = 0, START_BUDGET
        try:
            x = _start(bearing, ball, axial_force, rpm, outer_rpm, axis=axis)
            root, trial_worst, _ = damped_newton(ball.residual, x, lo, hi, tol)
            on_bound = bool(np.any((root <= lo) | (root >= hi)))
            if trial_worst > tol or on_bound:  # the robust, slower search from the same start
                trial = least_squares(ball.residual, np.clip(x, lo, hi), xtol=1e-14, ftol=1e-14, gtol=1e-14,
                                      method="trf", bounds=(lo, hi), max_nfev=2000)
                root, trial_worst, on_bound = trial.x, float(np.max(np.abs(trial.fun))), bool(np.any(trial.active_mask))
        except _OutOfBudget:
            continue
        if trial_worst < worst:
            sol, worst, sol_on_bound = root, trial_worst, on_bound
        converged = bool(worst <= tol) and not sol_on_bound  # a root on a bound is no root
        if converged:
            break
    ball.budget = math.inf
    if sol is None:  # every start ran out of its budget
        return Solved(ball, x, math.inf, False,
                      f"no steady state found: every start took more than {START_BUDGET} evaluations",
                      axial_force, rpm, w_i, w_o)
    message = "converged" if converged else (
        f"no steady state found (largest scaled residual {worst:.2g} > {tol:g}); below the load where "
        "traction holds the ball attitude the dynamic model may not settle either (a limit cycle)")
    return Solved(ball, sol, worst, converged, message, axial_force, rpm, w_i, w_o)


def _start(bearing, ball, axial, rpm, outer_rpm, tol=1e-2, axis="free"):
    """Pure rolling about the free-angle axis (``axis`` 'free') or with exact inner- or
    outer-raceway control ('inner', 'outer') at the quasi-static position; then, in turn,
    the speeds balanced with the position held and the position balanced (normal forces
    only) against the centrifugal force of the current cage speed, until the cage speed
    changes by less than ``tol`` (relative). Near gross sliding a joint solve from pure
    rolling can land on the wrong branch; this continuation does not."""
    loads = solve_load_distribution(bearing, axial_force=axial, rpm=rpm, outer_rpm=outer_rpm)
    a0 = bearing.contact_angle
    e = np.array([-math.sin(a0), 0.0, math.cos(a0)])
    c = np.array([bearing.pitch_radius + loads.ball_radius_offset[0], 0.0, loads.ball_axial_offset[0]])
    a_i, a_o = loads.inner_contact_angle[0], loads.outer_contact_angle[0]
    r = bearing.ball_radius
    p_in = c - r * np.array([math.cos(a_i), 0.0, math.sin(a_i)])
    p_out = c + r * np.array([math.cos(a_o), 0.0, math.sin(a_o)])
    x = np.zeros(7)
    if axis == "free":
        w_c, spin = rolling_cage_speed(c[None], e[None], p_in[None], p_out[None], ball.w_i, ball.w_o, return_spin=True)
        x[0], x[1:4] = w_c[0], spin[0] * e
    else:
        w_c, omega = raceway_control(c[None], p_in[None], p_out[None], ball.w_i, ball.w_o,
                                     np.array([axis == "inner"]), inner_origin=(0.0, 0.0, loads.displacement[2]))
        x[0], x[1:4] = w_c[0], omega[0]
    x[:4] /= ball.scale[:4]
    x[4:] = np.array([loads.ball_radius_offset[0], loads.ball_axial_offset[0], loads.displacement[2]]) / MICRON
    normal = _OneBall(bearing, ball.lub, ball.axial, ball.w_i, ball.w_o, None, replace(ball.law, traction="none"))
    bounds = ball.bounds()
    speeds, position = np.arange(4), np.arange(4, 7)

    def part(model, x, free, rows):
        def reduced(y):
            full = x.copy()
            full[free] = y
            return model.residual(full)[rows]

        lo, hi = bounds[0][free], bounds[1][free]
        y, worst, _ = damped_newton(reduced, x[free], lo, hi, PART_TOLERANCE)
        if worst <= PART_TOLERANCE:
            return y
        return least_squares(reduced, np.clip(x[free], lo, hi), xtol=1e-12, ftol=1e-12, gtol=1e-12, method="trf",
                             bounds=(lo, hi), max_nfev=400).x

    relaxed = None
    for _ in range(30):
        x[speeds] = part(ball, x, speeds, [1, 3, 4, 5])  # circumferential force and the moments
        w_c = x[0]
        if relaxed is not None and abs(w_c - relaxed) < tol * abs(w_c):
            break
        relaxed = w_c if relaxed is None else 0.5 * (relaxed + w_c)  # under-relaxed: it overshoots
        held = x.copy()
        held[0] = relaxed
        x[position] = part(normal, held, position, [0, 2, 6])  # radial and axial forces, race balance
    return x


def steady_result(solved: Solved, wall: float, inputs: dict, thermal: dict | None = None) -> SteadyState:
    """The :class:`SteadyState` of a solved balance, with its losses and drive power
    (:mod:`~exudyn_bearing.solvers.steady_power`) and the thermal network's record."""
    ball, x, bearing, w_i, w_o = solved.ball, solved.x, solved.ball.b, solved.w_i, solved.w_o
    w_c, w_b, c, shift = ball.unpack(x)
    kin, f = ball.contacts(x)
    v_ball_p = np.array([0.0, w_c * c[0], 0.0]) + np.cross(w_b, kin.point - c)
    surface = [np.atleast_1d(v_ball_p[k] @ kin.rolling[k] + kin.slip_rolling[k]) for k in (0, 1)]
    w_kin = float(rolling_cage_speed(c[None], w_b[None], kin.point[:1], kin.point[1:], w_i, w_o,
                                     surface_speeds=surface)[0])
    nominal = bearing.cage_speed(w_i, w_o)
    norm = max(float(np.linalg.norm(w_b)), 1e-300)
    return SteadyState(
        axial=float(solved.axial), rpm=float(solved.rpm),
        kinematic_cage_slip_percent=float(cage_slip(w_kin, w_c)), cage_slip_percent=float(cage_slip(nominal, w_c)),
        cage_speed=float(w_c), kinematic_cage_speed=w_kin, nominal_cage_speed=float(nominal),
        attitude_xz_deg=math.degrees(math.asin(min(abs(w_b[0]) / norm, 1.0))),
        attitude_yz_deg=math.degrees(math.asin(min(abs(w_b[1]) / norm, 1.0))),
        ball_omega=tuple(float(v) for v in w_b),
        inner_load=float(f.normal_load[0]), outer_load=float(f.normal_load[1]),
        inner_contact_angle_deg=math.degrees(float(kin.contact_angle[0])),
        outer_contact_angle_deg=math.degrees(float(kin.contact_angle[1])),
        inner_max_pressure=float(f.max_pressure[0]), outer_max_pressure=float(f.max_pressure[1]),
        inner_race_shift=float(shift), ball_orbit_radius=float(c[0]), ball_axial_position=float(c[2]),
        residual=solved.worst, converged=solved.converged, message=solved.message, wall_time_s=wall, inputs=inputs,
        power_loss_W=by_source(steady_losses(solved)), drive_power_W=float(steady_drive_power(solved)),
        thermal=thermal)
