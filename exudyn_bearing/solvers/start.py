"""The state a bearing starts from (MODEL.md §7, §12, §12a): the steady rolling state under
axial load, the quasi-dynamic state under combined or radial load, or None for pure rolling
with raceway control (:mod:`exudyn_bearing.solvers.raceway`)."""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .quasidynamic import AzimuthStates, combined_load_state, pose_state, seed_axial_load
from .steady import steady_state

__all__ = ["steady_start", "mirrored", "continuation_budget", "continuation_step"]

#: the mirror y -> -y of the bearing frame on a pose (dx, dy, dz, theta_x, theta_y): the
#: displacement is a vector, the tilt a pseudovector
MIRROR_POSE = np.array([1.0, -1.0, 1.0, -1.0, 1.0])


def mirrored(state: AzimuthStates) -> AzimuthStates:
    """The mirror image (y -> -y of the bearing frame) of a quasi-dynamic state: the state of
    the bearing turning the other way. Ball j sits where the mirror puts ball (Z - j) mod Z;
    in its azimuth frame the angular velocity (a pseudovector) keeps its circumferential
    component and flips the others, the pocket force (a vector) flips its circumferential one."""
    z = len(state.azimuth)
    j = (-np.arange(z)) % z
    return replace(state, cage_speed=-state.cage_speed, orbit_radius=state.orbit_radius[j],
                   axial_position=state.axial_position[j], omega=state.omega[j] * np.array([-1.0, 1.0, -1.0]),
                   pocket_force=-state.pocket_force[j], displacement=state.displacement * MIRROR_POSE[:3],
                   tilt=tuple(np.asarray(state.tilt) * MIRROR_POSE[3:]),
                   cage_offset=tuple(np.asarray(state.cage_offset) * MIRROR_POSE[:3]))


#: kinematic cage slip of the axial load alone, %, above which the combined-load start's
#: continuation keeps to steps of a tenth of the axial load: a skidding bearing has several
#: balances, and only small steps stay on the one the dynamic model holds (MODEL.md §12a)
SKIDDING_START_PERCENT = 1.0
#: continuation steps (and their halvings) the 'auto' start spends on the quasi-dynamic state
#: before it falls back to pure rolling: ~0.1 s each on the reference bearing
AUTO_CONTINUATION_STEPS = 40


def continuation_budget(initial_state: str) -> int | None:
    """Continuation steps the start may spend: :data:`AUTO_CONTINUATION_STEPS` for 'auto',
    no limit for 'steady'."""
    return AUTO_CONTINUATION_STEPS if initial_state == "auto" else None


def continuation_step(steady, axial_force: float, radial_force: float) -> float | None:
    """The combined-load start's largest continuation step, N, from the seed's axial
    ``steady`` state: a bearing that rolls under its axial load alone (kinematic slip <=
    :data:`SKIDDING_START_PERCENT`) has one balance, so the continuation may take steps of an
    eighth of the radial load; a skidding one is held to tenths of the axial load, its
    branch (None: :func:`~exudyn_bearing.solvers.quasidynamic.combined_load_state`'s default)."""
    if steady.kinematic_cage_slip_percent > SKIDDING_START_PERCENT:
        return None
    return max(0.1 * seed_axial_load(axial_force, radial_force), abs(radial_force) / 8)


def steady_start(bearing, lubricant, initial_state, *, axial_force, radial_force, rpm_i, rpm_o, sense, inner,
                 displaced, contact_law, ball_drag, cage=None, pose=None):
    """The settled state to start from: the :class:`~exudyn_bearing.solvers.steady.SteadyState` for a
    pure axial load, the :class:`~exudyn_bearing.solvers.quasidynamic.AzimuthStates` under combined
    or pure radial load (continued from the axial steady state, or from that at a seed axial
    load; 'auto' gives it :data:`AUTO_CONTINUATION_STEPS` steps), or None for the
    pure-rolling start ('rolling', or 'auto' where neither applies or converges). Loads given as functions of time start
    from their values at t = 0, as the quasi-static start. An inner race on the user's body
    (``races.OnBody``) starts from the state for its start load (the loads given here), or,
    with ``pose`` (its (dx, dy, dz, theta_x, theta_y) relative to the outer race, m and rad),
    from the quasi-dynamic balance with the races where they are
    (:func:`~exudyn_bearing.solvers.quasidynamic.pose_state`)."""
    if initial_state not in ("auto", "steady", "rolling"):
        raise ValueError(f"initialState must be 'auto', 'steady' or 'rolling', got {initial_state!r}")
    if initial_state == "rolling":
        return None
    why = None
    on_body = inner.kind == "body"
    if pose is not None:
        if rpm_i == sense * rpm_o:
            why = "the races turn at the same speed"
        else:
            # a race turning backwards in the bearing frame is the mirror image of one turning forwards
            pose = np.asarray(pose, dtype=float) * (MIRROR_POSE if sense < 0 else 1.0)
            state = pose_state(bearing, lubricant, pose=pose, rpm=sense * rpm_i, outer_rpm=sense * rpm_o,
                               ball_drag=ball_drag, contact_law=contact_law, cage=cage,
                               max_steps=AUTO_CONTINUATION_STEPS if initial_state == "auto" else None)
            if state.converged:
                return state if sense > 0 else mirrored(state)
            why = state.message
    elif axial_force <= 0 and radial_force == 0:
        why = "it needs a load"
    elif not (inner.kind in ("driven", "free") or on_body) or displaced:
        why = "it needs a Driven, Free or OnBody inner race (no innerRaceDisplacement)"
    elif rpm_i == sense * rpm_o:
        why = "the races turn at the same speed"
    elif radial_force != 0 and axial_force < 0:
        why = "under radial load it needs an axial load >= 0"
    elif radial_force != 0 and sense < 0:
        why = "under radial load it needs a positive inner-race speed"
    if why is None:
        seed = seed_axial_load(axial_force, radial_force)  # a pure radial load continues from a seed axial load
        state = steady_state(bearing, lubricant, axial_force=seed, rpm=sense * rpm_i, outer_rpm=sense * rpm_o,
                             ball_drag=ball_drag, contact_law=contact_law, cage=cage)
        if not state.converged:
            why = state.message
        elif radial_force == 0:
            return state
        else:
            combined = combined_load_state(bearing, lubricant, axial_force=axial_force, radial_force=radial_force,
                                           rpm=rpm_i, outer_rpm=rpm_o, ball_drag=ball_drag, contact_law=contact_law,
                                           cage=cage, steady=state, max_steps=continuation_budget(initial_state),
                                           max_step=continuation_step(state, axial_force, radial_force))
            if combined.converged:
                return combined
            why = combined.message
    if initial_state == "steady":
        raise ValueError(f"initialState: no steady start here, {why}; use initialState='rolling'")
    return None
