"""Settled starts of shaft assemblies: a user's shaft placed at its quasi-static equilibrium
on its bearings before the bearings are added (MODEL.md §4, §12a)."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..races import NODE_KINEMATICS, move_body, node_state
from ..solvers.geometric import rotation as _rotation
from ..solvers.shaft import ShaftEquilibrium, solve_shaft

__all__ = ["SettleShaft"]


def SettleShaft(mbs, shaftBody: int, bearings, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0),
                rpm: float | None = None) -> ShaftEquilibrium:
    """Move ``shaftBody`` to its quasi-static equilibrium on ``bearings`` under ``force`` and
    ``moment`` (:func:`~exudyn_bearing.solvers.shaft.solve_shaft`: each bearing's share of the
    shaft's forces and moments, preload included) and return that solution.

    Call it after creating the shaft and before adding its bearings with
    ``CreateAngularContactBearing(..., innerRace=races.OnBody(shaftBody, ...))``: each
    bearing then starts from the quasi-dynamic balance of its balls with its races where the
    settled shaft puts them (:func:`~exudyn_bearing.solvers.quasidynamic.pose_state`), so the
    run starts without a settling transient.

    Parameters
    ----------
    mbs : exudyn.MainSystem
    shaftBody : int
        The shaft's rigid body (any node type of :data:`exudyn_bearing.races.NODE_KINEMATICS`);
        its axis is the global z axis, its reference point the body's position.
    bearings : sequence of ShaftBearing
        The bearings as they will be added (same positions, frames and inner-race positions
        relative to the shaft's reference point, m).
    force : (3,) float
        Force on the shaft at its reference point at t = 0, global, N.
    moment : (M_x, M_y) float
        Moment on the shaft about its reference point at t = 0, global, N m.
    rpm : float, optional
        Shaft speed for the balls' centrifugal forces, rev/min; default: the shaft's initial
        angular velocity about z.

    Raises
    ------
    ValueError
        Bad input, e.g. a body the bearings cannot sit on.
    QuasiStaticError
        No equilibrium (e.g. no bearing takes the axial force).
    """
    node = mbs.GetObject(shaftBody)["nodeNumber"]
    kind = mbs.GetNode(node)["nodeType"]
    if kind not in NODE_KINEMATICS:
        raise ValueError(f"shaftBody: body {shaftBody} sits on a {kind} node; the shaft takes rigid-body nodes of type "
                         + ", ".join(NODE_KINEMATICS))
    where, rot, _, w = node_state(mbs, node)
    if not np.allclose(rot[:, 2], (0.0, 0.0, 1.0), atol=1e-9):
        raise ValueError("shaftBody: its axis (third column of its rotation) must be the global z axis at the start")
    if rpm is None:
        rpm = abs(float(w[2])) * 30.0 / math.pi
    # solve_shaft puts the shaft's reference point at the origin: the housing relative to it
    bearings = [replace(b, position=tuple(np.asarray(b.position, dtype=float) - where)) for b in bearings]
    eq = solve_shaft(bearings, force, moment, rpm=rpm)
    move_body(mbs, node, eq.displacement, _rotation(*eq.tilt))
    return eq
