"""Quasi-dynamic state under combined load, the start of radially loaded runs (MODEL.md §12a).

Every ball is in its own force and moment balance at its azimuth (normal, traction, spin,
drag, centrifugal and gyroscopic, with the dynamic model's contact functions); all balls
orbit at one cage speed, the pockets taking the difference as a circumferential force P_j;
the cage is in torque balance (sum_j P_j r_cj = the land's friction torque) and the inner
race in force balance with the applied load. Unknowns: per ball P_j, its angular velocity
and its centre (r_cj, z_cj) in its azimuth plane, the cage speed and the inner race's
displacement (6 Z + 4); each ball's equations depend on its own unknowns, the cage speed and
the race only, so the Jacobian is differenced in 6 + 4 evaluations, plus the exact coupling
of the balls' spins by the orbital transport I w_c dw/dpsi (each ball carries its spin from
azimuth to azimuth; spectral derivative over the balls). A land-guided cage is then seated
on its land where the pockets push it, the balls orbiting about its centre (fixed point,
:func:`_seat_cage`). :func:`pose_state` holds the race at a given pose instead of balancing
it (races on the user's bodies).

Light radial loads on a skidding bearing have several balances; the one the dynamic model
settles near is reached by continuation in the radial load from the axial steady state
(:func:`exudyn_bearing.steady_state`), in steps of at most a tenth of the axial load
(docs/DEVELOPMENT.md, 'Start states'); a pure radial load from the steady state at a seed
axial load, which is then taken back to zero (same section). Each step is solved by Newton's
method with a line search (:mod:`exudyn_bearing.solvers.newton`). The equations themselves
and their Jacobian: :mod:`exudyn_bearing.solvers.azimuth_balance`.
"""
from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass, fields, replace

import numpy as np

from contact.ballrace import ContactLaw
from contact.kinematics import rolling_cage_speed
from ..bearing import Bearing
from ..bearingfile import as_setup
from ..cage import CageModel
from ..renamed import accepts_old_names
from ..setup import FROM_SETUP, refuse_surface
from .continuation import STEP_JACOBIANS, continue_path
from .newton import damped_newton
from .quasistatic import solve_load_distribution
from .azimuth_balance import _Balance
from ..results.outputs import cage_slip
from ..results.records import units_of
from .azimuth_power import azimuth_drive_power, azimuth_losses, azimuth_operating_point
from .steady_power import by_source
from .steady import check_finite, steady_state
from .steady_balance import solve_steady, steady_result
from .thermal import FixedPointPass, fixed_point

__all__ = ["AzimuthStates", "combined_load_state", "pose_state", "seed_axial_load", "solve_combined", "failed_states"]



@dataclass(frozen=True)
class AzimuthStates:
    """Result of :func:`combined_load_state` (SI units; per-ball arrays in each ball's azimuth
    frame: x radial, y circumferential, z axial)."""

    cage_speed: float  #: common orbital speed w_c, rad/s
    azimuth: np.ndarray  #: psi_j, rad
    orbit_radius: np.ndarray  #: r_cj, m
    axial_position: np.ndarray  #: z_cj, m
    omega: np.ndarray  #: (Z, 3) absolute ball angular velocities, rad/s
    pocket_force: np.ndarray  #: P_j, circumferential force of its pocket on each ball, N
    displacement: np.ndarray  #: inner race displacement (x, y, z), bearing frame, m
    residual: float  #: largest scaled equation residual
    converged: bool
    message: str
    wall_time_s: float
    #: inner race tilt (theta_x, theta_y) it was solved at, rad (:func:`pose_state`; zero otherwise)
    tilt: tuple = (0.0, 0.0)
    #: cage centre, bearing frame, m: on its land where the pockets push it (CageModel.land_seat)
    cage_offset: tuple = (0.0, 0.0, 0.0)
    #: with the setup's thermal network: its temperatures and heat, as :attr:`SteadyState.thermal`
    #: (MODEL.md §14d); else None
    thermal: dict | None = None
    #: each ball's inner and outer contact load (Z,), N, and contact angle (Z,), rad (None where
    #: no balance was found)
    inner_load: np.ndarray | None = None
    outer_load: np.ndarray | None = None
    inner_contact_angle: np.ndarray | None = None
    outer_contact_angle: np.ndarray | None = None
    nominal_cage_speed: float | None = None  #: rad/s, the pure-rolling cage speed of the nominal geometry
    cage_slip_percent: float | None = None  #: the paper's P19 cage slip against it, %
    #: the mean over the balls of the cage slip against each ball's own pure-rolling orbital
    #: speed (MODEL.md §7, the dynamic results' skid measure), %
    kinematic_cage_slip_percent: float | None = None
    #: losses by source (traction, rolling_resistance, ball_drag, jet_momentum, cage, total), W,
    #: and the power the races' drives put in, W: the losses less ``normal_work_W``
    #: (:mod:`.azimuth_power`)
    power_loss_W: dict | None = None
    drive_power_W: float | None = None
    #: Σ Q ṗ, W: the contacts' loads times their approach rates in this balance's kinematics
    #: (each ball at ω_c about the cage centre, not along its orbit's radial changes;
    #: 1e-4–1e-3 of the losses, MODEL.md §14d)
    normal_work_W: float | None = None

    def to_dict(self) -> dict:
        """JSON-ready: the fields (arrays as lists) and ``units`` (the unit of every key)."""
        data = {f.name: _plain(getattr(self, f.name)) for f in fields(self)}
        return data | {"units": units_of(data)}


def _plain(value):
    """``value`` with its arrays and numpy numbers as lists and floats (JSON)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return float(value) if isinstance(value, np.floating) else value


def failed_states(z: int, message: str, start: float, displacement=(np.nan,) * 3, tilt=(0.0, 0.0)) -> AzimuthStates:
    """The :class:`AzimuthStates` of ``z`` balls where no balance was found: NaN numbers,
    ``converged`` False and the ``message``; ``start`` the call's perf_counter."""
    return AzimuthStates(float("nan"), 2.0 * np.pi * np.arange(z) / z, np.full(z, np.nan), np.full(z, np.nan),
                         np.full((z, 3), np.nan), np.full(z, np.nan), np.asarray(displacement, dtype=float).copy(),
                         float("inf"), False, message, _time.perf_counter() - start, np.array(tilt, dtype=float))


#: a pure radial load is reached from the steady state at an axial load of this fraction of
#: the radial load, which is then taken back to zero (MODEL.md §12a)
RADIAL_SEED_FRACTION = 0.1


#: the seed's axial load is taken back to zero in at least this many steps
RETURN_STEPS = 4
def seed_axial_load(axial: float, radial: float) -> float:
    """The axial load, N, whose steady state the continuation starts from: ``axial`` itself,
    or :data:`RADIAL_SEED_FRACTION` of the radial load where there is no axial load."""
    return axial if axial > 0 else RADIAL_SEED_FRACTION * abs(radial)


@accepts_old_names
def combined_load_state(bearing, lubricant=FROM_SETUP, *, axial_force: float, radial_force: float, rpm: float,
                        outer_rpm: float = 0.0,
                        ball_drag=FROM_SETUP, contact_law: ContactLaw = FROM_SETUP, cage=FROM_SETUP, steady=None,
                        tol: float = 1e-8, max_steps: int | None = None,
                        max_step: float | None = None) -> AzimuthStates:
    """The quasi-dynamic state under ``axial_force`` + ``radial_force`` load (N; radial along the bearing
    frame's x axis), continued in radial load from the axial steady state ``steady``
    (:func:`exudyn_bearing.steady_state` of the same bearing, oil, drag, law and speeds at
    ``axial_force``, or at :data:`RADIAL_SEED_FRACTION` of the radial load where ``axial_force`` is 0;
    solved here if None) in steps of at most ``max_step`` N (None: a tenth of the axial
    load, which keeps a skidding bearing on the dynamic model's branch), halved where a step
    does not converge (module docstring, MODEL.md §12a), each solved by a damped Newton from
    the secant extrapolation of the two before; under pure radial load the seed's axial load
    is then taken back to zero the same way. ``converged`` False with a ``message`` where the
    continuation stalls or has taken ``max_steps`` steps (None: no limit); its numbers must
    then not be used. ``max_step`` may also be a function of the seed's steady state giving
    it. ``bearing`` a Bearing, a setup or a bearing file's path: the setup's
    lubricant, drag, law and cage unless passed (a plain Bearing: no cage unless passed);
    its defects and waviness are refused (they have no steady state). A setup with a
    ``thermal`` model is solved with its network (MODEL.md §14d; ``steady`` must then be None):
    each iterate's temperatures give the contacts' oils and the grown bearing, its balance the
    heat, and the result's ``thermal`` the temperatures and where the heat went."""
    start = _time.perf_counter()
    plain = isinstance(bearing, Bearing)
    setup = as_setup(bearing, lubricant=lubricant, drag=ball_drag, contact_law=contact_law,
                     cage=CageModel() if cage is None else cage)
    refuse_surface(setup, "combined_load_state", "simulate or vibration")
    check_finite(axial_force=axial_force, radial_force=radial_force, rpm=rpm, outer_rpm=outer_rpm)
    if axial_force < 0:
        raise ValueError(f"axial_force must be >= 0 (the balance's races are pressed one way), got {axial_force!r}")
    if rpm == outer_rpm:
        raise ValueError("rpm, outer_rpm: the races turn at the same speed; nothing rolls")
    cage = None if cage is None or (plain and cage is FROM_SETUP) else setup.cage
    if setup.thermal is not None:
        if steady is not None:
            raise ValueError("steady: a setup with a thermal model solves its own seed state at each temperature "
                             "(MODEL.md §14d); pass steady=None")
        return _thermal_combined(setup, cage, axial_force=axial_force, radial_force=radial_force, rpm=rpm,
                                 outer_rpm=outer_rpm, tol=tol, max_steps=max_steps, max_step=max_step, start=start)
    seed = seed_axial_load(axial_force, radial_force)
    if steady is None:
        steady = steady_state(setup.bearing, setup.lubricant, axial_force=seed, rpm=rpm, outer_rpm=outer_rpm,
                              ball_drag=setup.drag, contact_law=setup.contact_law, cage=cage)
    return solve_combined(setup, cage, axial_force=axial_force, radial_force=radial_force, rpm=rpm, outer_rpm=outer_rpm,
                          steady=steady, tol=tol, start=start, max_steps=max_steps, max_step=max_step)[0]


def solve_combined(setup, cage, *, axial_force, radial_force, rpm, outer_rpm, steady, tol, start, max_steps=None,
                   max_step=None, oils=None, warm=None, near=None) -> tuple:
    """(:class:`AzimuthStates`, the last balance, its scaled unknowns, the unscaled unknowns of
    its centred cage) of :func:`combined_load_state` (checked inputs; ``cage`` None: no cage)
    from the seed's axial ``steady`` state; ``oils`` (inner contacts', outer contacts', land's
    lubricant) where they differ from the setup's (the thermal network's, MODEL.md §14b).
    ``warm``: instead, Newton at the load from these unknowns of a centred cage (a nearby
    balance's, e.g. the thermal fixed point's last iterate) and the cage seated from there;
    where it fails and ``near`` gives that balance's (bearing, oils), a continuation from them
    to these (each size and oil property along the straight line, :func:`_blend`); not
    converged where that fails too (``steady`` is then not used)."""
    bearing, lubricant, ball_drag, contact_law = setup.bearing, setup.lubricant, setup.drag, setup.contact_law
    seed = seed_axial_load(axial_force, radial_force)
    law, w_i, w_o, land = _balance_inputs(bearing, lubricant if oils is None else oils[2], contact_law, cage, rpm,
                                          outer_rpm)
    make = lambda load, offset=None: _Balance(bearing, lubricant, w_i, w_o, ball_drag, law, land,  # noqa: E731
                                              *load, cage_offset=offset, oils=oils)
    load = (axial_force, radial_force)
    if warm is not None:
        balance = make(load)
        x, worst, _ = damped_newton(balance.residual, warm / balance.scale, *balance.bounds(), tol, balance.jacobian,
                                    max_iterations=STEP_JACOBIANS, reuse_jacobian=True)
        y, message = x * balance.scale, None if worst <= tol else f"Newton from the nearby balance: {worst:.2g}"
        if message is not None and near is not None:
            y, worst, message, balance = _continue_from_near(make, load, warm, setup=setup, near=near, oils=oils,
                                                             cage=cage, rpm=rpm, outer_rpm=outer_rpm, tol=tol)
    else:
        y = _steady_unknowns(bearing, steady)
        max_step = max_step(steady) if callable(max_step) else max_step
        largest = max(0.1 * seed, 1e-3 * abs(radial_force)) if max_step is None else max_step
        pure_radial = axial_force <= 0 < abs(radial_force)
        y, worst, message, balance, left = continue_path(make, y, (seed, 0.0), (seed, radial_force), largest, tol,
                                                     max_steps, _load_text, reserve=RETURN_STEPS if pure_radial else 0)
        if message is None and pure_radial:
            y, worst, message, balance, left = continue_path(make, y, (seed, radial_force), (0.0, radial_force),
                                                         seed / RETURN_STEPS, tol, left, _load_text)
        if balance is None:  # no load step: the steady state itself
            balance = make((axial_force, 0.0))
    centred = y.copy()
    if message is None:
        y, worst, message, balance = _seat_cage(make, load, y, cage, tol, worst)
    converged = message is None
    return _states(balance, y, worst, converged, message or "converged", start), balance, y / balance.scale, centred


def _continue_from_near(make, load, warm, *, setup, near, oils, cage, rpm, outer_rpm, tol) -> tuple:
    """(unscaled unknowns, worst residual, None or why not, the last balance) of the
    continuation from the ``warm`` unknowns of a centred cage at the nearby balance's
    (bearing, oils) ``near`` to ``setup``'s bearing and ``oils`` at ``load``: the path's points
    blend every size and oil property linearly (its end is ``make(load)`` itself). A
    zero-clearance bearing whose clearance turns with each kelvin needs it where Newton from
    the nearby balance fails (the CWRU 6205 under radial load, MODEL.md §14d)."""
    near_bearing, near_oils = near

    def blended(point):
        s = float(point[0])
        if s >= 1.0:
            return make(load)
        bearing = _blend(near_bearing, setup.bearing, s)
        blend_oils = tuple(_blend(p, q, s) for p, q in zip(near_oils, oils))
        law, w_i, w_o, land = _balance_inputs(bearing, blend_oils[2], setup.contact_law, cage, rpm, outer_rpm)
        return _Balance(bearing, setup.lubricant, w_i, w_o, setup.drag, law, land, *load, oils=blend_oils)

    y, worst, message, balance, _ = continue_path(blended, warm, (0.0,), (1.0,), NEAR_STEP, tol, None,
                                                  lambda p: f"{100 * float(p[0]):.0f} % of the way from the nearby "
                                                            "balance's sizes and oils")
    return y, worst, message, balance


#: the continuation from a nearby balance's sizes and oils: its largest step, a share of the way
NEAR_STEP = 0.25


def _blend(a, b, s: float):
    """The dataclass ``b`` with each float field moved back towards ``a``'s by 1 − ``s``:
    a + s (b − a) (fields that are not floats, or equal, are ``b``'s)."""
    changes = {}
    for f in fields(b):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, float) and isinstance(y, float) and x != y:
            changes[f.name] = x + s * (y - x)
    return replace(b, **changes) if changes else b


def _thermal_combined(setup, cage, *, axial_force, radial_force, rpm, outer_rpm, tol, max_steps, max_step, start):
    """:func:`combined_load_state` of a ``setup`` with a ``thermal`` model: the balance and the
    network iterated to a fixed point (:func:`~exudyn_bearing.solvers.thermal.fixed_point`,
    MODEL.md §14d). The first iterate's balance is continued from the seed's axial steady
    state at its temperatures and oils; each later one is Newton's from the iterate before
    (the continuation again where that fails). The result's ``thermal`` as the steady state's."""
    seed = seed_axial_load(axial_force, radial_force)
    last = {}  # the centred unknowns of the last iterate's balance

    def solve(running, oils):
        kw = dict(axial_force=axial_force, radial_force=radial_force, rpm=rpm, outer_rpm=outer_rpm, tol=tol,
                  start=start, max_steps=max_steps, max_step=max_step, oils=oils)
        found = None
        if "centred" in last:
            found = solve_combined(running, cage, steady=None, warm=last["centred"], near=last["near"], **kw)
        if found is None or not found[0].converged:
            inner, outer, land = oils
            solved = solve_steady(running.replace(cage=CageModel() if cage is None else cage), seed, rpm, outer_rpm,
                                  tol, races=(inner, outer), land_lubricant=land)
            if not solved.converged:
                return FixedPointPass(None, f"the axial steady state at {seed:g} N: {solved.message}", None, None)
            found = solve_combined(running, cage, steady=steady_result(solved, 0.0, {}), **kw)
        states, balance, x, last["centred"] = found
        last["near"] = (running.bearing, oils)
        if not states.converged:
            return FixedPointPass(states, states.message, None, None)
        return FixedPointPass(states, None, azimuth_losses(balance, x), azimuth_operating_point(balance, x))

    states, failure, record = fixed_point(setup, solve)
    if states is None:  # no balance at any iterate
        states = failed_states(setup.bearing.balls, failure, start)
    if failure is not None:
        states = replace(states, converged=False, message=failure)
    return replace(states, thermal=record, wall_time_s=_time.perf_counter() - start)


def _states(balance, y, worst, converged, message, start, tilt=(0.0, 0.0)) -> AzimuthStates:
    """The :class:`AzimuthStates` of the unscaled unknowns ``y`` of ``balance``, with its
    contacts' loads and angles, its losses and drive power (not where ``y`` is not finite)."""
    x = y / balance.scale
    pocket, w_b, c, w_c, d = balance.unpack(x)
    states = AzimuthStates(float(w_c), balance.psi.copy(), c[:, 0].copy(), c[:, 2].copy(), w_b.copy(),
                           pocket.copy(), d.copy(), worst, converged, message, 0.0, tilt,
                           tuple(float(e) for e in balance.cage_offset))
    if not np.all(np.isfinite(x)):
        return replace(states, converged=False, wall_time_s=_time.perf_counter() - start)
    kin, f = balance.contacts(x)
    z = balance.z
    w_i, w_o = float(balance.race_omega[0, 2]), float(balance.race_omega[z, 2])
    nominal = float(balance.b.cage_speed(w_i, w_o))
    # each ball's pure-rolling orbit for its geometry and spin axis (MODEL.md §7), the races'
    # surface speeds at its contacts as the ball's surface speed there less the slip
    v = balance._motion(x)["v"][:z]
    surface = [np.einsum("ij,ij->i", v + np.cross(w_b, kin.point[part] - c), kin.rolling[part])
               + kin.slip_rolling[part] for part in (slice(0, z), slice(z, 2 * z))]
    w_kin = rolling_cage_speed(c, w_b, kin.point[:z], kin.point[z:], w_i, w_o, surface_speeds=surface)
    return replace(states, inner_load=f.normal_load[:z].copy(), outer_load=f.normal_load[z:].copy(),
                   inner_contact_angle=kin.contact_angle[:z].copy(), outer_contact_angle=kin.contact_angle[z:].copy(),
                   nominal_cage_speed=nominal, cage_slip_percent=float(cage_slip(nominal, w_c)),
                   kinematic_cage_slip_percent=float(np.mean(cage_slip(w_kin, w_c))),
                   power_loss_W=by_source(azimuth_losses(balance, x)), drive_power_W=azimuth_drive_power(balance, x),
                   normal_work_W=float(np.sum(np.sum(f.force * kin.normal, axis=1) * kin.penetration_rate)),
                   wall_time_s=_time.perf_counter() - start)


def _balance_inputs(bearing, lubricant, contact_law, cage, rpm, outer_rpm):
    """(law, w_i, w_o, the cage land's load) of the balances: the land's from ``lubricant``."""
    # the accurate traction rule (smooth for the root finder); order 8 gives the order-16 cage
    # speed to 2e-5 (400 N + 300 N: 46.149 / 46.150 rad/s) at 60 % of its cost
    law = replace(contact_law, fast_quadrature=False, quadrature_order=8)
    w_i, w_o = rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0
    land = (0.0, 0.0) if cage is None else cage.centred_land_load(bearing, lubricant, w_i, w_o)
    return law, w_i, w_o, land


def _steady_unknowns(bearing, steady):
    """The unscaled unknowns of the axial ``steady`` state: every ball in its balance, the
    continuation's start."""
    z = bearing.balls
    y = np.zeros(6 * z + 4)
    per = y[:6 * z].reshape(z, 6)
    per[:, 1:4] = np.asarray(steady.ball_omega)
    per[:, 4] = steady.ball_orbit_radius - bearing.pitch_radius
    per[:, 5] = steady.ball_axial_position
    y[6 * z] = steady.cage_speed
    y[-1] = steady.inner_race_shift
    return y


#: continuation steps from the steady state's pose to a prescribed one (:func:`pose_state`):
#: the path is cut into at least this many, as the load path into tenths of the axial load
POSE_STEPS = 10


def pose_state(bearing, lubricant, *, pose, rpm: float, outer_rpm: float = 0.0, ball_drag=None,
               contact_law: ContactLaw = ContactLaw(), cage=None, tol: float = 1e-8,
               max_steps: int | None = None) -> AzimuthStates:
    """The quasi-dynamic state with the inner race held at ``pose`` (dx, dy, dz[, theta_x,
    theta_y]) relative to the outer race, m and rad, bearing frame: every ball in its own
    balance (MODEL.md §12a) between races that sit where a user's shaft and housing put them
    (``races.OnBody``), instead of where a load balance puts them.

    The load the races carry there comes from the quasi-static solution at the pose
    (:func:`~exudyn_bearing.solvers.quasistatic.solve_load_distribution`); the continuation
    starts from the steady state at its axial part (or at :data:`RADIAL_SEED_FRACTION` of its
    radial part) and moves the inner race along the straight path to ``pose`` in at least
    :data:`POSE_STEPS` steps; a tilt enters each ball's inner groove to first order.
    ``converged`` False with a ``message`` where the balls carry nothing at the pose, or the
    continuation stalls or runs out of ``max_steps``."""
    start = _time.perf_counter()
    pose = np.asarray(pose, dtype=float)
    if pose.shape == (3,):
        pose = np.concatenate([pose, [0.0, 0.0]])
    if pose.shape != (5,) or not np.all(np.isfinite(pose)):
        raise ValueError(f"pose must be 3 or 5 finite numbers (m, rad), got {pose!r}")
    z = bearing.balls

    def failed(message):
        return failed_states(z, message, start, pose[:3], pose[3:])

    qs = solve_load_distribution(bearing, displacement=pose, rpm=rpm, outer_rpm=outer_rpm)
    if not np.any(qs.inner_load > 0) or not np.any(qs.outer_load > 0):
        return failed("the balls carry no load where the races are (give the bearing a start load, or place the "
                      "shaft at its loaded position)")
    applied = -np.asarray(qs.race_force)  # the load the race must be given to sit there
    axial, radial = max(float(applied[2]), 0.0), float(math.hypot(applied[0], applied[1]))
    seed = seed_axial_load(axial, radial)
    steady = steady_state(bearing, lubricant, axial_force=seed, rpm=rpm, outer_rpm=outer_rpm, ball_drag=ball_drag,
                          contact_law=contact_law, cage=cage)
    if not steady.converged:
        return failed(steady.message)
    law, w_i, w_o, land = _balance_inputs(bearing, lubricant, contact_law, cage, rpm, outer_rpm)
    y = _steady_unknowns(bearing, steady)
    radius = bearing.pitch_radius  # tilts travel the path as the arc they move at the pitch circle
    scale = np.array([1.0, 1.0, 1.0, radius, radius])
    make = lambda point, offset=None: _Balance(bearing, lubricant, w_i, w_o, ball_drag, law, land,  # noqa: E731
                                               axial, radial, pose=point / scale, cage_offset=offset)
    begin = np.array([0.0, 0.0, steady.inner_race_shift, 0.0, 0.0])
    end = pose * scale
    span = float(np.linalg.norm(end - begin))
    y, worst, message, balance, _ = continue_path(make, y, begin, end, span / POSE_STEPS, tol, max_steps,
                                              lambda point: _pose_text(point, radius))
    if balance is None:  # the steady state sits at the pose already
        balance = make(end)
    if message is None:
        y, worst, message, balance = _seat_cage(make, end, y, cage, tol, worst)
    if message is not None:
        return failed(message)
    return _states(balance, y, worst, True, "converged", start, tuple(pose[3:]))


#: the cage seat's fixed point stops when the cage moves less than this fraction of its land play
#: (2 um of the reference cage's 0.2 mm: the kinematic slip then moves by < 0.005 pp)
SEAT_TOLERANCE = 1e-2
#: ... and gives up where a round moves it more than this fraction of the round before (the
#: reference bearing at 2.8 kN + 0.85 kN contracts by 0.75, then ~0.25 a round)
SEAT_CONTRACTION = 1.0


#: the seat's continuation: the whole move first (steps of up to twice the play), halved where
#: Newton fails, at most this many steps a round (then the centred balance stays). Against
#: quarter-play steps without a limit: the same seats, 1.0-1.7 s less per start (reference
#: bearing at 400 + 100, 800 + 500, 2800 + 850 N; a 7205 at 12 000 rpm)
SEAT_STEP = 2.0
SEAT_STEPS = 6


def _seat_cage(make, point, y, cage, tol, worst, max_rounds=10):
    """The balance at ``point`` with a land-guided cage on its land where the balls' pocket
    forces push it (:meth:`CageModel.land_seat`; the balls orbiting about its centre), by
    fixed-point iteration from the centred cage's balance ``y``: each round seats the cage
    under the last pocket forces and continues the balance there in the cage's offset
    (:data:`SEAT_STEP`, :data:`SEAT_STEPS`). Where the seat has no fixed point (the
    pockets' net force turns with the cage's offset: a cage that whirls in its land, e.g. a
    7205 at 12 000 rpm) or its balance is not found, the centred cage's balance is kept.
    Returns (y, worst residual, None, the balance)."""
    balance = make(point)
    if cage is None or not cage.guided:
        return y, worst, None, balance
    centred = (y, worst, None, balance)
    offset = np.zeros(3)
    play = 0.5 * cage.guide_clearance
    moved = np.inf
    film = cage.land_film_constant(balance.b, balance.land_lubricant)
    for _ in range(max_rounds):
        pocket, _, _, w_c, _ = balance.unpack(y / balance.scale)
        seat = cage.land_seat(-(pocket[:, None] * balance.e_p).sum(axis=0), film, w_c + balance.land[1])
        move = float(np.linalg.norm(seat - offset))
        if move <= SEAT_TOLERANCE * play:
            return y, worst, None, balance
        if move > SEAT_CONTRACTION * moved:
            return centred
        moved = move
        y, worst, message, last, _ = continue_path(lambda e: make(point, e), y, offset, seat, SEAT_STEP * play, tol,
                                               SEAT_STEPS, lambda e: f"the cage {np.linalg.norm(e) * 1e6:.3g} um off centre")
        if message is not None:
            return centred
        offset, balance = seat, last
    return centred


def _load_text(load):
    return f"{load[0]:g} N axial + {abs(load[1]):g} N radial"


def _pose_text(point, radius):
    d = point[:3] * 1e6
    tilt = point[3:] / radius * 1e3
    return (f"the inner race at ({d[0]:.3g}, {d[1]:.3g}, {d[2]:.3g}) um, tilt ({tilt[0]:.3g}, {tilt[1]:.3g}) mrad")
