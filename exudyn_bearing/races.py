"""Where a bearing's races live in an Exudyn model (MODEL.md §1).

Use the factory functions:

``Fixed(rpm=0)``
    A kinematic race frame (no Exudyn node): fixed in space, turning about the bearing
    axis at ``rpm`` (a number or a function of time t in s returning rpm). Ground-fixed
    outer race, or a speed-driven race whose shaft is held in place.
``Driven(rpm, translation='free')``
    A new rigid body whose rotation is held at ``rpm`` (a number, or a function of time t
    in s returning rpm, e.g. a run-up ramp; any solver) and whose translation is free
    (loaded by the bearing's applied forces) or ``'fixed'``.
``Free(rpm=0)``
    A new, unconstrained rigid body (initial speed ``rpm``).
``OnBody(bodyNumber, localPosition, localRotation)``
    An existing Exudyn rigid body (shaft, housing, gear) with a ``NodeRigidBodyRotVecLG``
    node; the race frame sits at ``localPosition`` with ``localRotation`` (its third column
    is the race axis) in the body frame. Contact forces go to that body with their true
    lever arms.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

__all__ = ["Race", "Fixed", "Driven", "Free", "OnBody"]


@dataclass(frozen=True)
class Race:
    """How one race is represented; build it with :func:`Fixed`, :func:`Driven`,
    :func:`Free` or :func:`OnBody`."""

    kind: str  #: 'fixed', 'driven', 'free' or 'body'
    rpm: float | Callable[[float], float] = 0.0
    fixed_translation: bool = False
    body: int | None = None
    local_position: tuple = (0.0, 0.0, 0.0)
    local_rotation: tuple = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    mass: float | None = None  #: kg, created bodies; default from the ring's size
    inertia: tuple | None = None  #: (I_radial, I_axial), kg m², created bodies

    def __post_init__(self) -> None:
        if self.kind not in ("fixed", "driven", "free", "body"):
            raise ValueError(f"kind must be 'fixed', 'driven', 'free' or 'body', got {self.kind!r}")
        if not callable(self.rpm) and not (isinstance(self.rpm, (int, float)) and math.isfinite(self.rpm)):
            raise ValueError(f"rpm must be a finite number or a function of time, got {self.rpm!r}")
        if callable(self.rpm) and self.kind not in ("fixed", "driven"):
            raise ValueError("rpm: a time-varying speed needs a Fixed or Driven race")
        if self.mass is not None and not (math.isfinite(self.mass) and self.mass > 0):
            raise ValueError(f"mass must be positive, got {self.mass!r}")
        rot = np.asarray(self.local_rotation, dtype=float)
        if rot.shape != (3, 3) or not np.allclose(rot @ rot.T, np.eye(3), atol=1e-9):
            raise ValueError("local_rotation (localRotation of OnBody) must be a 3x3 rotation matrix")

    @property
    def has_node(self) -> bool:
        return self.kind != "fixed"

    def speed(self, t: float = 0.0) -> float:
        """Angular speed about the race axis at time t, rad/s."""
        rpm = self.rpm(t) if callable(self.rpm) else self.rpm
        return rpm * math.pi / 30.0


def Fixed(rpm=0.0) -> Race:
    """Kinematic race: fixed in space, turning at ``rpm`` (number or function of t)."""
    return Race("fixed", rpm=rpm)


def Driven(rpm, translation: str = "free", mass: float | None = None, inertia=None) -> Race:
    """New race body turning at a held ``rpm`` (number or function of t in s);
    ``translation`` 'free' (loaded by the bearing's applied forces) or 'fixed'."""
    if translation not in ("free", "fixed"):
        raise ValueError(f"translation must be 'free' or 'fixed', got {translation!r}")
    return Race("driven", rpm=rpm, fixed_translation=translation == "fixed", mass=mass, inertia=inertia)


def Free(rpm: float = 0.0, mass: float | None = None, inertia=None) -> Race:
    """New, unconstrained race body with initial speed ``rpm``."""
    return Race("free", rpm=rpm, mass=mass, inertia=inertia)


def OnBody(bodyNumber: int, localPosition=(0.0, 0.0, 0.0), localRotation=np.eye(3)) -> Race:
    """Race fixed to an existing Exudyn rigid body: any rigid-body node of Exudyn's
    ``CreateRigidBody`` (Euler parameters, its default; Tait–Bryan angles; rotation vector).
    A rotation-vector Lie-group node carries the race frame itself; others get a light race
    body joined rigidly to them (``builder._race_adapter``; implicit solvers)."""
    return Race("body", body=int(bodyNumber), local_position=tuple(float(v) for v in localPosition),
                local_rotation=tuple(tuple(float(v) for v in row) for row in np.asarray(localRotation)))
