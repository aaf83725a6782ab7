"""What an evaluation of the bearing connector computed, for one node state or a batch of
them (MODEL.md §2–§8, §11): :class:`ConnectorState`, its slicing, and the layout of a batch's
contacts (B 2Z of them: per state the inner race's Z, then the outer race's)."""
from __future__ import annotations

from dataclasses import dataclass, field, fields, replace

import numpy as np

from contact.ballrace import ContactForces
from contact.kinematics import ContactKinematics

__all__ = ["ConnectorState", "per_race", "first_state", "stacked", "both_races"]


@dataclass
class ConnectorState:
    """Everything an evaluation computed (for outputs and tests), global frame, SI units: of
    one state (:meth:`BearingConnector.evaluate`) or, with a leading axis B on every field
    but the bearing frame's, of B states (:meth:`BearingConnector.states`)."""

    t: float
    ball_position: np.ndarray
    ball_velocity: np.ndarray
    ball_omega: np.ndarray
    inner: ContactKinematics
    outer: ContactKinematics
    inner_forces: ContactForces
    outer_forces: ContactForces
    cage_force: np.ndarray  #: on each ball, (Z, 3)
    drag_force: np.ndarray  #: on each ball, (Z, 3)
    cage_omega: np.ndarray | None
    inner_omega: np.ndarray
    outer_omega: np.ndarray
    frame_rotation: np.ndarray  #: bearing (outer race) frame -> global
    frame_origin: np.ndarray
    generalized: np.ndarray = field(repr=False, default=None)
    cage_eccentricity: float = 0.0  #: rigid cage centre off its guiding (else the outer) race's axis, m
    cage_land_force: np.ndarray = None  #: guiding land on the cage, (3,), N (None: not guided)
    cage_position: np.ndarray = None  #: rigid cage centre, (3,), m (None: no rigid cage)
    cage_velocity: np.ndarray = None  #: its velocity, (3,), m/s
    pocket_friction_force: np.ndarray = None  #: pocket friction on each ball, (Z, 3), N (None: off)
    pocket_friction_loss: float = 0.0  #: power the pocket friction dissipates, W
    land_force_loss: float = 0.0  #: power the guiding land's force pair (contact, film pressure) dissipates, W
    land_friction_loss: float = 0.0  #: power the guiding land's oil film dissipates by its shear, W
    land_drive_power: float = 0.0  #: power the guiding race puts into the cage through its land, W


def _take(record, part):
    """The same dataclass with every array field sliced to ``part``."""
    return replace(record, **{f.name: getattr(record, f.name)[part] for f in fields(record)
                              if getattr(record, f.name) is not None})


def per_race(record, b, z):
    """(inner, outer) records with fields (B, Z, ...) from one of B 2Z contacts (inner race
    first in each state)."""
    both = replace(record, **{f.name: getattr(record, f.name).reshape((b, 2, z) + getattr(record, f.name).shape[1:])
                              for f in fields(record) if getattr(record, f.name) is not None})
    return _take(both, (slice(None), 0)), _take(both, (slice(None), 1))


#: ConnectorState fields that describe the bearing, not the states
_FRAME_FIELDS = ("frame_rotation", "frame_origin")
#: ConnectorState fields that are numbers for one state
_SCALAR_FIELDS = ("t", "cage_eccentricity", "pocket_friction_loss", "land_force_loss", "land_friction_loss",
                  "land_drive_power")


def first_state(state: ConnectorState) -> ConnectorState:
    """The first state of a batched :class:`ConnectorState`, without the leading axis."""
    def one(name, value):
        if value is None or name in _FRAME_FIELDS:
            return value
        if isinstance(value, (ContactKinematics, ContactForces)):
            return _take(value, 0)
        return float(np.reshape(value, -1)[0]) if name in _SCALAR_FIELDS else value[0]
    return replace(state, **{f.name: one(f.name, getattr(state, f.name)) for f in fields(state)})


def stacked(frames, i, shape, bsz, z):
    """Item ``i`` of both race frames, (B, ...) each, per contact: (B 2Z, ...), the inner
    race's Z contacts first in each state."""
    per_race = [np.broadcast_to(frames[name][i][:, None], (bsz, z) + shape) for name in ("inner", "outer")]
    return np.concatenate(per_race, axis=1).reshape((-1,) + shape)


def both_races(x):
    """Per-ball vectors (B, Z, 3) per contact, (B 2Z, 3): inner, then outer, in each state."""
    return np.concatenate([x, x], axis=1).reshape(-1, 3)
