"""The start state of :func:`~exudyn_bearing.model.builder.CreateAngularContactBearing`, in the
bearing frame: where each ball, the cage and the inner race start and how fast they turn.

The quasi-static load distribution with pure-rolling speeds (MODEL.md §7, raceway control)
is the base; the steady rolling state (pure axial load, MODEL.md §12) or each ball's
quasi-dynamic balance (combined or radial load, §12a) replaces it where the solvers of
:mod:`exudyn_bearing.solvers.start` give one.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..races import node_state
from ..solvers.quasidynamic import AzimuthStates
from ..solvers.quasistatic import solve_load_distribution
from ..solvers.raceway import choose_inner_control, jones_axis_start, raceway_control
from ..solvers.start import steady_start
from .start_memo import remembered

__all__ = ["StartState", "race_pose", "start_state"]

E_Z = np.array([0.0, 0.0, 1.0])


@dataclass
class StartState:
    """Where the bearing's bodies start, bearing frame, SI units."""

    ball_centre: np.ndarray  #: (Z, 3), m
    orbit_speed: np.ndarray  #: (Z,): each ball's orbital speed about the axis, rad/s
    ball_omega: np.ndarray  #: (Z, 3): ball angular velocities, rad/s
    #: the inner race relative to the outer one: (dx, dy, dz) m, (theta_x, theta_y) rad
    relative: np.ndarray
    cage_offset: np.ndarray  #: (3,): the cage centre's offset, m
    outer_contact: np.ndarray  #: (Z, 3): each ball's outer contact point relative to its centre, m
    loads: object  #: the quasi-static :class:`~exudyn_bearing.solvers.quasistatic.LoadDistribution`
    steady: object  #: the steady state started from, or None
    quasi: object  #: the quasi-dynamic :class:`~exudyn_bearing.solvers.quasidynamic.AzimuthStates`, or None
    #: where the races were before a start load moved the user's body ((dx, dy, dz), (theta_x, theta_y))
    where: np.ndarray


def race_pose(mbs, inner, outer, origin, frame):
    """(inner race relative to the outer one in the bearing frame — (dx, dy, dz) m and
    (theta_x, theta_y) rad —, (inner, outer) speed about the axis rad/s): from the user's
    bodies where a race sits on one, else zero and the races' own speeds."""
    axis = frame[:, 2]
    speed = {"inner": inner.speed(0.0), "outer": outer.speed(0.0)}
    relative = np.zeros(5)
    for name, race, sign in (("inner", inner, 1.0), ("outer", outer, -1.0)):
        if race.kind == "body":
            pos_node, rot_node, _, w_node = node_state(mbs, mbs.GetObject(race.body)["nodeNumber"])
            race_origin = pos_node + rot_node @ np.asarray(race.local_position)
            relative[:3] += sign * frame.T @ (race_origin - origin)
            # the race axis in the bearing frame is ~ (theta_y, -theta_x, 1) for a small tilt theta
            race_axis = frame.T @ rot_node @ np.asarray(race.local_rotation)[:, 2]
            relative[3:] += sign * np.array([-race_axis[1], race_axis[0]])
            speed[name] = float(axis @ w_node)
    return relative, (speed["inner"], speed["outer"])


def _pure_rolling(setup, loaded, axial, radial, relative, speeds, w_i, w_o, initial_control, start_load):
    """(loads, ball centres, inner and outer contact points, orbit speeds, ball angular
    velocities) of the quasi-static start with pure-rolling speeds, the centrifugal force
    at each ball's own orbit (iterated to 1e-6 of the orbit speed); ``relative`` is updated
    in place by the loads' displacement."""
    bearing = setup.bearing
    z = bearing.balls
    cage_speed, pose, last = None, None, None
    # the quasi-static centrifugal force at each ball's own pure-rolling orbit (not the
    # nominal cage speed: 200 N would start 13.5 N out of radial balance on a 15 N load)
    for _ in range(20):
        if loaded or start_load is not None:
            # each round from the last round's pose: the orbit speeds change little
            loads = solve_load_distribution(bearing, axial_force=axial, radial_force=radial, cage_speed=cage_speed,
                                            start_pose=pose, **speeds)
            pose = np.concatenate([loads.displacement, loads.tilt])
            relative[:3] = loads.displacement
        else:
            loads = solve_load_distribution(bearing, displacement=relative, cage_speed=cage_speed, **speeds)
        psi = loads.azimuth
        e_r = np.stack([np.cos(psi), np.sin(psi), np.zeros(z)], axis=1)
        r_c = bearing.pitch_radius + loads.ball_radius_offset
        c_loc = r_c[:, None] * e_r + loads.ball_axial_offset[:, None] * E_Z
        a_i, a_o = loads.inner_contact_angle, loads.outer_contact_angle
        p_in = c_loc - bearing.ball_radius * (np.cos(a_i)[:, None] * e_r + np.sin(a_i)[:, None] * E_Z)
        p_out = c_loc + bearing.ball_radius * (np.cos(a_o)[:, None] * e_r + np.sin(a_o)[:, None] * E_Z)
        inner_controls = choose_inner_control(bearing, setup.lubricant, loads, w_i, w_o, initial_control)
        if initial_control == "auto":
            w_c, omega_loc = jones_axis_start(bearing, c_loc, p_in, p_out, a_i, a_o, e_r, w_i, w_o, inner_controls,
                                              inner_origin=relative[:3])
        else:
            w_c, omega_loc = raceway_control(c_loc, p_in, p_out, w_i, w_o, inner_controls, inner_origin=relative[:3])
        orbit = np.abs(w_c)
        if cage_speed is not None and np.max(np.abs(orbit - cage_speed)) <= 1e-6 * np.max(orbit):
            break
        # one speed for a pure axial load (all balls alike), each ball's own otherwise
        image = orbit if radial or not (loaded or start_load) else float(np.mean(orbit))
        guess = image
        if last is not None:
            # secant on the map speeds -> orbits (Anderson's mixing of depth 1): it contracts by
            # 0.12-0.25 a round, so plain rounds took 7 and 10 calls at 2.2 kN + 2 kN and 400 + 100 N
            r, dr = image - cage_speed, (image - cage_speed) - (last[1] - last[0])
            denominator = float(np.sum(dr * dr))
            if denominator > 0.0:
                guess = image - float(np.sum(r * dr)) / denominator * (image - last[1])
        last = None if cage_speed is None else (cage_speed, image)
        cage_speed = guess
    return loads, c_loc, p_out, w_c, omega_loc


def start_state(setup, inner, relative, speeds_rad, *, axial, radial, loaded, start_load, displaced,
                initial_control, initial_state, steady=None) -> StartState:
    """The :class:`StartState` of ``setup`` with the races ``inner`` (a :class:`~exudyn_bearing.races.Race`)
    at ``relative`` ((dx, dy, dz) m, (theta_x, theta_y) rad: the inner race relative to the
    outer one, as :func:`race_pose`), turning at ``speeds_rad`` (inner, outer; rad/s), under
    the forces at t = 0 ``axial`` and ``radial`` (N; a ``start_load`` (axial, radial) in their
    place for a race on the user's body); ``displaced``: the inner race starts displaced
    (``innerRaceDisplacement``). ``initial_control`` and ``initial_state`` as the builder's
    ``initialControl`` and ``initialState``; ``steady``: a steady state solved already (the
    thermal one, MODEL.md §14g) to start from instead of the start solvers'."""
    bearing, law, cage = setup.bearing, setup.contact_law, setup.cage
    w_i, w_o = speeds_rad
    rpm_i, rpm_o = w_i * 30 / math.pi, w_o * 30 / math.pi
    # the quasi-static solver takes a non-negative inner speed; only |cage speed| matters
    sense = -1.0 if rpm_i < 0 else 1.0
    speeds = dict(rpm=abs(rpm_i), outer_rpm=sense * rpm_o, hertz_method=law.hertz_method)
    if initial_control not in ("auto", "inner", "outer"):
        raise ValueError(f"initialControl must be 'auto', 'inner' or 'outer', got {initial_control!r}")
    z = bearing.balls
    where = relative.copy()  # where the races are: a start load moves the user's body from there
    if start_load is not None:
        axial, radial = start_load

    def rolling():  # (its results, relative after it: _pure_rolling updates it in place)
        moved = relative.copy()
        return _pure_rolling(setup, loaded, axial, radial, moved, speeds, w_i, w_o, initial_control,
                             start_load), moved

    # within one call (an error estimate's rerun, a longer run of a map's point) solved once
    # (exudyn_bearing.model.start_memo): every value the solvers read is in the key
    (loads, c_loc, p_out, w_c, omega_loc), relative[:] = remembered(
        ("pure rolling", setup, loaded, axial, radial, relative.copy(), speeds, w_i, w_o, initial_control,
         start_load), rolling)
    on_body = inner.kind == "body"
    if steady is None:
        pose = where if on_body and start_load is None else None
        steady = remembered(
            ("steady start", setup, initial_state, axial, radial, rpm_i, rpm_o, sense, inner.kind, displaced, pose),
            lambda: steady_start(bearing, setup.lubricant, initial_state, axial_force=axial, radial_force=radial,
                                 rpm_i=rpm_i, rpm_o=rpm_o, sense=sense, inner=inner, displaced=displaced,
                                 contact_law=law, ball_drag=setup.drag, cage=cage, pose=pose))
    psi = loads.azimuth
    e_r = np.stack([np.cos(psi), np.sin(psi), np.zeros(z)], axis=1)
    e_psi = np.stack([-np.sin(psi), np.cos(psi), np.zeros(z)], axis=1)
    quasi, cage_offset = None, np.zeros(3)
    if isinstance(steady, AzimuthStates):  # combined load: each ball in its own balance, one cage speed
        quasi, steady = steady, None
        c_loc = quasi.orbit_radius[:, None] * e_r + quasi.axial_position[:, None] * E_Z
        if cage.kind == "rigid":
            # each ball where its pocket pushes it with the balance's P_j (contact.cage.pocket_forces:
            # -k (|s| - g) sign(s) along e_psi), not at the pocket centre: there the pockets would push
            # nothing, and the first steps would start with the balls ringing in their pockets
            p = quasi.pocket_force
            s = -np.sign(p) * (0.5 * cage.clearance + np.abs(p) / cage.stiffness)
            cage_offset = np.asarray(quasi.cage_offset, dtype=float)
            # the pockets move with the cage: each ball by the pocket's circumferential shift
            c_loc = c_loc + (s + e_psi @ cage_offset)[:, None] * e_psi
        w_c = np.full(z, quasi.cage_speed)
        omega_loc = quasi.omega[:, :1] * e_r + quasi.omega[:, 1:2] * e_psi + quasi.omega[:, 2:] * E_Z
        relative[:3] = quasi.displacement
    if steady is not None:
        c_loc = steady.ball_orbit_radius * e_r + steady.ball_axial_position * E_Z
        w_c = np.full(z, sense * steady.cage_speed)
        # a reversed bearing is the mirror image in the meridional plane: the pseudovector
        # keeps its circumferential component and flips the others
        w_b = np.asarray(steady.ball_omega) * np.array([sense, 1.0, sense])
        omega_loc = w_b[0] * e_r + w_b[1] * e_psi + w_b[2] * E_Z
        relative[:3] = (0.0, 0.0, steady.inner_race_shift)
    return StartState(c_loc, w_c, omega_loc, relative, cage_offset, p_out - c_loc, loads, steady, quasi, where)
