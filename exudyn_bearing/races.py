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
``Housing(frequency=3000, mass=2, dampingRatio=0.05)``
    The outer race on a housing (vibration, MODEL.md §13a): a new body of ``mass`` (kg,
    ring included) whose rotation is held and whose centre sits on isotropic spring-dampers
    to ground, tuned to ``frequency`` (Hz; or an explicit ``stiffness`` N/m) at
    ``dampingRatio`` of critical, so that impacts ring a resonance as on a machine. The
    springs start preloaded by the bearing's applied forces (no start transient).
``OnBody(bodyNumber, localPosition, localRotation)``
    An existing Exudyn rigid body (shaft, housing, gear) with any rigid-body node type; the
    race frame sits at ``localPosition`` with ``localRotation`` (its third column is the
    race axis) in the body frame. Contact forces go to that body with their true lever arms.

The builder turns them into Exudyn bodies with the functions below the factories: the
modelled ring (:func:`race_ring_section`, its mass and inertia) and, for a body whose node
is not a rotation-vector Lie-group node, a light adapter body joined to it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from .bearing import Bearing

__all__ = ["Race", "Fixed", "Driven", "Free", "Housing", "HousingModel", "OnBody", "race_ring_section"]


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
    support: tuple | None = None  #: (stiffness N/m, damping N s/m) of a housing's springs to ground

    def __post_init__(self) -> None:
        if self.kind not in ("fixed", "driven", "free", "body", "housing"):
            raise ValueError(f"kind must be 'fixed', 'driven', 'free', 'body' or 'housing', got {self.kind!r}")
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


def Housing(frequency: float = 3000.0, mass: float = 2.0, dampingRatio: float = 0.05,
            stiffness: float | None = None) -> Race:
    """Outer race on a housing of ``mass`` (kg, ring included) carried by isotropic
    spring-dampers to ground: stiffness ``stiffness`` (N/m) or m (2π ``frequency``)² for a
    resonance at ``frequency`` Hz, damping 2 ``dampingRatio`` √(k m) (MODEL.md §13a). Its
    rotation is held; it does not turn."""
    for key, value in (("frequency", frequency), ("mass", mass), ("dampingRatio", dampingRatio)):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0 \
                or (value == 0 and key != "dampingRatio"):
            raise ValueError(f"Housing: {key} must be {'>= 0' if key == 'dampingRatio' else 'positive'}, got {value!r}")
    if stiffness is not None and not (isinstance(stiffness, (int, float)) and math.isfinite(stiffness)
                                      and stiffness > 0):
        raise ValueError(f"Housing: stiffness must be positive, got {stiffness!r}")
    k = float(stiffness) if stiffness is not None else mass * (2.0 * math.pi * frequency) ** 2
    return Race("housing", mass=float(mass), support=(k, 2.0 * dampingRatio * math.sqrt(k * mass)))


@dataclass(frozen=True)
class HousingModel:
    """The housing a bearing setup's outer race sits on (MODEL.md §13a; a bearing file's
    ``[housing]``): ``mass`` kg, resonance ``frequency`` Hz (or ``stiffness`` N/m) at
    ``damping_ratio`` of critical; :meth:`race` is its :func:`Housing` mount."""

    frequency: float = 3000.0
    mass: float = 2.0
    damping_ratio: float = 0.05
    stiffness: float | None = None

    def __post_init__(self) -> None:
        self.race()  # Housing's checks, each naming its parameter

    def race(self) -> Race:
        """The outer race on this housing (:func:`Housing`)."""
        return Housing(self.frequency, self.mass, self.damping_ratio, self.stiffness)


def OnBody(bodyNumber: int, localPosition=(0.0, 0.0, 0.0), localRotation=np.eye(3)) -> Race:
    """Race fixed to an existing Exudyn rigid body: any rigid-body node of Exudyn's
    ``CreateRigidBody`` (Euler parameters, its default; Tait–Bryan angles; rotation vector).
    A rotation-vector Lie-group node carries the race frame itself; others get a light race
    body joined rigidly to them (:func:`race_adapter`; implicit solvers)."""
    return Race("body", body=int(bodyNumber), local_position=tuple(float(v) for v in localPosition),
                local_rotation=tuple(tuple(float(v) for v in row) for row in np.asarray(localRotation)))


# ---- race bodies: the modelled ring, and adapters for the user's node types ------------
def ring_inertia(mass, r_in, r_out, width):
    """(I_radial, I_axial) of a ring of ``mass`` kg, radii and width in m, kg m²."""
    i_axial = 0.5 * mass * (r_in ** 2 + r_out ** 2)
    i_radial = 0.25 * mass * (r_in ** 2 + r_out ** 2) + mass * width ** 2 / 12
    return i_radial, i_axial


#: node types a race may sit on (races.OnBody) -> (rotation matrix, local G matrix) of
#: their rotation coordinates; Lie-group nodes are the connector's own, others get an adapter
NODE_KINEMATICS = {
    "RigidBodyRotVecLG": ("RotationVector2RotationMatrix", None),
    "RigidBodyEP": ("EulerParameters2RotationMatrix", "EulerParameters2GLocal"),
    "RigidBodyRxyz": ("RotXYZ2RotationMatrix", "RotXYZ2GLocal"),
}

#: an adapter race body's mass and inertia as a fraction of the default ring's (it only
#: carries the race frame; the user's body carries the mass)
ADAPTER_MASS_FRACTION = 1e-3


def node_state(mbs, node):
    """(position m, rotation matrix, velocity m/s, GLOBAL angular velocity rad/s) of a rigid-body
    node's initial state (reference + initial coordinates), for the node types of
    :data:`NODE_KINEMATICS`."""
    import exudyn.rigidBodyUtilities as rbu

    kind = mbs.GetNode(node)["nodeType"]
    ref = np.asarray(mbs.GetNodeParameter(node, "referenceCoordinates"), dtype=float)
    init = np.asarray(mbs.GetNodeParameter(node, "initialCoordinates"), dtype=float)
    init_t = np.asarray(mbs.GetNodeParameter(node, "initialVelocities"), dtype=float)
    to_matrix, to_g = NODE_KINEMATICS[kind]
    params = ref[3:] + init[3:]
    rot = np.asarray(getattr(rbu, to_matrix)(params), dtype=float)
    if to_g is None:  # Lie-group nodes: velocity coordinates are the local angular velocity
        w_local = init_t[3:]
    else:
        w_local = np.asarray(getattr(rbu, to_g)(params), dtype=float) @ init_t[3:]
    return ref[:3] + init[:3], rot, init_t[:3], rot @ w_local


#: the inverse of :data:`NODE_KINEMATICS`' rotation maps: rotation matrix -> coordinates
NODE_PARAMETERS = {"RigidBodyRotVecLG": "RotationMatrix2RotationVector",
                   "RigidBodyEP": "RotationMatrix2EulerParameters", "RigidBodyRxyz": "RotationMatrix2RotXYZ"}


def move_body(mbs, node, shift, rotation=None) -> None:
    """Move a rigid-body node's initial state by ``shift`` (global, m) and turn it by
    ``rotation`` (global rotation matrix, applied before its present one), through its
    initial coordinates; its reference and velocities stay."""
    import exudyn.rigidBodyUtilities as rbu

    kind = mbs.GetNode(node)["nodeType"]
    ref = np.asarray(mbs.GetNodeParameter(node, "referenceCoordinates"), dtype=float)
    init = np.asarray(mbs.GetNodeParameter(node, "initialCoordinates"), dtype=float).copy()
    init[:3] += np.asarray(shift, dtype=float)
    if rotation is not None:
        _, rot, _, _ = node_state(mbs, node)
        params = np.asarray(getattr(rbu, NODE_PARAMETERS[kind])(np.asarray(rotation) @ rot), dtype=float)
        init[3:] = params - ref[3:]
    mbs.SetNodeParameter(node, "initialCoordinates", init.tolist())


def node_rows(mbs, nodes) -> np.ndarray:
    """Rows of the 6 ODE2 coordinates (displacement, rotation vector) of each of the
    Lie-group rigid-body ``nodes`` in the system vectors of an assembled ``mbs``, node by node."""
    starts = np.array([mbs.GetNodeODE2Index(n) for n in nodes], dtype=np.intp)
    return (starts[:, None] + np.arange(6)).ravel()


def race_adapter(mbs, bearing, race, which, node_type):
    """A race frame on a body whose node is not a rotation-vector Lie-group node: a light
    race body with such a node (:data:`ADAPTER_MASS_FRACTION` of the default ring), joined
    rigidly to the user's body at the race position by an ``ObjectJointGeneric`` (all six
    axes); returns its (body, node). The joint passes the bearing's forces to the user's body
    (Exudyn's implicit solvers; its explicit ones refuse the constraint, as they refuse
    Euler-parameter nodes)."""
    from exudyn.utilities import MarkerBodyRigid, ObjectJointGeneric, RigidBodyInertia

    pos_node, rot_node, v_node, w_node = node_state(mbs, mbs.GetObject(race.body)["nodeNumber"])
    local_p = np.asarray(race.local_position, dtype=float)
    local_r = np.asarray(race.local_rotation, dtype=float)
    mass, (i_r, i_a) = default_race_body(bearing, race, which)
    f = ADAPTER_MASS_FRACTION
    d = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=f * mass, inertiaTensor=np.diag([f * i_r, f * i_r, f * i_a])),
                            referencePosition=pos_node + rot_node @ local_p, referenceRotationMatrix=rot_node @ local_r,
                            initialVelocity=v_node + np.cross(w_node, rot_node @ local_p),
                            initialAngularVelocity=w_node, nodeType=node_type, returnDict=True)
    import exudyn as exu

    # marker 0 carries the race frame on the user's body (Exudyn 1.13: rotation in its localHT)
    m_user = mbs.AddMarker(MarkerBodyRigid(bodyNumber=race.body,
                                           localHT=exu.HT(rotation=local_r.tolist(), translation=local_p.tolist())))
    m_race = mbs.AddMarker(MarkerBodyRigid(bodyNumber=d["bodyNumber"], localPosition=[0.0, 0.0, 0.0]))
    mbs.AddObject(ObjectJointGeneric(markerNumbers=[m_user, m_race], constrainedAxes=[1] * 6))
    return d["bodyNumber"], d["nodeNumber"]


def race_ring_section(bearing: Bearing, which: str, mass: float | None = None):
    """(bore radius, outside radius, width) of the race ring the model uses, m: a steel ring
    1.5 D wide next to the groove (shoulder 0.3 D from the pitch circle), 0.6 D thick,
    or as thick as ``mass`` (kg) makes it at that width. Both the default mass and inertia
    and the renderer's race graphics come from it, so the drawn ring is the modelled one."""
    d = bearing.ball_diameter
    width = 1.5 * d
    area = None if mass is None else mass / (bearing.race_material.density * math.pi * width)
    if which == "inner":
        r_out = bearing.pitch_radius - 0.3 * d
        # a ring heavier than a solid disc of this width is drawn as that disc
        r_in = r_out - 0.6 * d if area is None else math.sqrt(max(r_out ** 2 - area, 0.0))
    else:
        r_in = bearing.pitch_radius + 0.3 * d
        r_out = r_in + 0.6 * d if area is None else math.sqrt(r_in ** 2 + area)
    return r_in, r_out, width


def default_race_body(bearing: Bearing, race: Race, which: str):
    """Mass and inertia of the race ring (:func:`race_ring_section`), unless the Race gives them."""
    r_in, r_out, width = race_ring_section(bearing, which, race.mass)
    mass = race.mass or bearing.race_material.density * math.pi * (r_out ** 2 - r_in ** 2) * width
    inertia = race.inertia or ring_inertia(mass, r_in, r_out, width)
    return mass, inertia
