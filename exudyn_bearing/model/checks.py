"""The checks of :func:`~exudyn_bearing.model.builder.CreateAngularContactBearing`'s
arguments, made before anything is added to the ``mbs``: a bad input gets a ValueError
naming it."""
from __future__ import annotations

import math

import numpy as np

from ..races import NODE_KINEMATICS, Driven, Fixed, Race

__all__ = ["check_frame", "check_force", "check_start_load", "check_races", "check_displacement"]


def check_frame(position, rotation):
    position = np.asarray(position, dtype=float)
    rotation = np.asarray(rotation, dtype=float)
    if position.shape != (3,) or not np.all(np.isfinite(position)):
        raise ValueError(f"position must be 3 finite numbers, got {position!r}")
    if rotation.shape != (3, 3) or not np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-9) \
            or np.linalg.det(rotation) < 0:
        raise ValueError("rotationMatrix must be a proper 3x3 rotation matrix")
    return position, rotation


def check_force(name, value):
    """A constant force (N) or a function of time t in s returning N, as a function of t."""
    at_start = value(0.0) if callable(value) else value
    if not (isinstance(at_start, (int, float, np.floating, np.integer)) and math.isfinite(at_start) and at_start >= 0):
        direction = "" if name != "axialForce" else (
            "; it acts along the bearing axis (+z of the bearing frame): for a load the other way mount the bearing "
            "the other way round (rotationMatrix=np.diag([1, -1, -1]))")
        raise ValueError(f"{name} must be a finite non-negative force in N (or a function of time returning one), "
                         f"got {at_start!r}{direction}")
    if callable(value):
        return value
    return lambda t, v=float(value): v


def check_start_load(value, inner):
    """None, or the (axial, radial) start load in N of an inner race on the user's body."""
    if value is None:
        return None
    try:
        axial, radial = (float(v) for v in value)
    except (TypeError, ValueError):
        raise ValueError(f"startLoad must be (axial, radial) in N, got {value!r}") from None
    if not (math.isfinite(axial) and math.isfinite(radial) and axial >= 0 and radial >= 0):
        raise ValueError(f"startLoad must be two finite non-negative forces (axial, radial) in N, got {value!r}; the "
                         "axial one acts along the bearing axis (+z of the bearing frame)")
    if inner.kind != "body":
        raise ValueError("startLoad is the start load of an inner race on your body (races.OnBody); a Driven or "
                         "Free inner race takes axialForce and radialForce")
    if axial == 0 and radial == 0:
        raise ValueError("startLoad: give a load (axial, radial) in N, or leave it out to start with the races "
                         "where your bodies are")
    return axial, radial


def check_races(mbs, innerRace, outerRace, setup):
    """(inner, outer) :class:`Race` of the builder's arguments: defaults ``Driven(1800 rpm)``
    and the setup's housing, else ``Fixed()``; checked before anything is added to ``mbs``."""
    inner = innerRace if innerRace is not None else Driven(1800.0)
    if outerRace is not None:
        outer = outerRace
    else:
        outer = setup.housing.race() if setup.housing is not None else Fixed()
    for name, race in (("innerRace", inner), ("outerRace", outer)):
        if not isinstance(race, Race):
            raise ValueError(f"{name} must be a races.Race, got {race!r}")
        if race.kind == "body":
            node_type = mbs.GetNode(mbs.GetObject(race.body)["nodeNumber"])["nodeType"]
            if node_type not in NODE_KINEMATICS:
                raise ValueError(f"{name}: OnBody({race.body}) sits on a {node_type} node; the bearing takes rigid-body "
                                 "nodes of type " + ", ".join(NODE_KINEMATICS) + ": create that body with "
                                 "nodeType=exu.NodeType.RotationEulerParameters (Exudyn's default) or "
                                 "RotationRotationVector")
    if inner.kind == "housing":
        raise ValueError("innerRace: Housing() carries an outer race; give it as outerRace")
    return inner, outer


def check_displacement(value, inner, loaded):
    """None, or the inner race's start displacement (dx, dy, dz) in m of ``innerRaceDisplacement``."""
    if value is None:
        return None
    shift = np.asarray(value, dtype=float)
    if shift.shape != (3,) or not np.all(np.isfinite(shift)):
        raise ValueError(f"innerRaceDisplacement must be 3 finite numbers in m, got {value!r}")
    if inner.kind not in ("driven", "free") or loaded:
        raise ValueError("innerRaceDisplacement needs a Driven or Free inner race and no applied forces")
    return shift
