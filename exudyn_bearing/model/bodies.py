"""The Exudyn bodies of a bearing: its balls, cage and races (a housing's spring with its
race), created at the :class:`~exudyn_bearing.model.start_state.StartState`; each returns
its item numbers and extends the connector's node ``layout``."""
from __future__ import annotations

import numpy as np

from ..races import default_race_body, race_adapter, ring_inertia

__all__ = ["add_balls", "add_cage", "add_races", "ball_graphics"]


def _node_type():
    import exudyn as exu

    return exu.NodeType.RotationRotationVector


def ball_graphics(bearing, show):
    """The balls' graphics: a sphere and its body axes (none if not ``show``)."""
    import exudyn.graphics as graphics

    return [graphics.Sphere(radius=bearing.ball_radius, color=graphics.color.grey, nTiles=16),
            graphics.Basis(length=1.3 * bearing.ball_radius)] if show else []


def add_balls(mbs, bearing, origin, frame, start, show):
    """(ball body numbers, ball node numbers) of the Z balls at ``start``, each moving with
    its pocket about the cage centre."""
    from exudyn.utilities import InertiaSphere

    e_z = np.array([0.0, 0.0, 1.0])
    bodies, nodes = [], []
    look = ball_graphics(bearing, show)
    for j in range(bearing.balls):
        c = origin + frame @ start.ball_centre[j]
        v = frame @ (start.orbit_speed[j] * np.cross(e_z, start.ball_centre[j] - start.cage_offset))
        d = mbs.CreateRigidBody(inertia=InertiaSphere(mass=bearing.ball_mass, radius=bearing.ball_radius),
                                referencePosition=c, initialVelocity=v,
                                initialAngularVelocity=frame @ start.ball_omega[j],
                                nodeType=_node_type(), graphicsDataList=look, returnDict=True)
        bodies.append(d["bodyNumber"])
        nodes.append(d["nodeNumber"])
    return bodies, nodes


def add_cage(mbs, setup, origin, frame, start):
    """(body, node) of a rigid cage (a ring of the ball's width and 0.3 D thick) turning at
    the balls' mean orbit speed; (None, None) for no cage or the spring chain."""
    from exudyn.utilities import RigidBodyInertia

    bearing, cage = setup.bearing, setup.cage
    if cage.kind != "rigid":
        return None, None
    width, thick = bearing.ball_diameter, 0.3 * bearing.ball_diameter
    mass = cage.mass_for(bearing)
    i_r, i_a = ring_inertia(mass, bearing.pitch_radius - thick / 2, bearing.pitch_radius + thick / 2, width)
    d = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=mass, inertiaTensor=np.diag([i_r, i_r, i_a])),
                            referencePosition=origin + frame @ start.cage_offset, referenceRotationMatrix=frame,
                            initialAngularVelocity=float(np.mean(start.orbit_speed)) * frame[:, 2],
                            nodeType=_node_type(), returnDict=True)
    return d["bodyNumber"], d["nodeNumber"]


def add_races(mbs, bearing, races, origin, frame, inner_shift, applied, nodes, layout):
    """The races' bodies: a created one (``Driven``, ``Free``, ``Housing``) at ``inner_shift``
    (m, bearing frame; the outer at the origin), a user's (``OnBody``, through an adapter body
    where its node type needs one), none for ``Fixed``. ``applied``: the (axial, radial)
    forces at t = 0, N, which preload a housing's spring. Appends the race nodes to ``nodes``
    and their slots to ``layout``. Returns (per race (body, node), race frames in their
    nodes, held slots, driven slots, the housing's spring or None)."""
    from exudyn.utilities import RigidBodyInertia

    items = {"inner": (None, None), "outer": (None, None)}
    race_frames, held, driven = {}, {}, {}
    housing_spring = None
    axis = frame[:, 2]
    for name, shift in (("inner", inner_shift), ("outer", np.zeros(3))):
        race = races[name]
        if race.kind == "fixed":
            continue
        if race.kind == "body" and mbs.GetNode(mbs.GetObject(race.body)["nodeNumber"])["nodeType"] != "RigidBodyRotVecLG":
            body, node = race_adapter(mbs, bearing, race, name, _node_type())
            race_frames[name] = (np.zeros(3), np.eye(3))
        elif race.kind == "body":
            body = race.body
            node = mbs.GetObject(body)["nodeNumber"]
            race_frames[name] = (np.asarray(race.local_position, dtype=float), np.asarray(race.local_rotation, dtype=float))
        else:
            mass, (i_r, i_a) = default_race_body(bearing, race, name)
            d = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=mass, inertiaTensor=np.diag([i_r, i_r, i_a])),
                                    referencePosition=origin + frame @ shift, referenceRotationMatrix=frame,
                                    initialAngularVelocity=race.speed(0.0) * axis, nodeType=_node_type(),
                                    returnDict=True)
            body, node = d["bodyNumber"], d["nodeNumber"]
            race_frames[name] = (np.zeros(3), np.eye(3))
            if race.kind == "driven":
                held[len(nodes)] = "all" if race.fixed_translation else "rotation"
                if callable(race.rpm):
                    driven[len(nodes)] = (race, i_a)
            elif race.kind == "housing":
                held[len(nodes)] = "rotation"
                stiffness, damping = race.support
                # preloaded by the applied forces at t = 0: the housing starts in balance
                # (Exudyn's spring force on its second body is -k (Δp - offset))
                axial, radial = applied
                preload = -frame @ np.array([radial, 0.0, axial]) / stiffness
                housing_spring = mbs.CreateCartesianSpringDamper(
                    itemNumbers=[mbs.CreateGround(referencePosition=list(origin), show=False), body],
                    stiffness=[stiffness] * 3, damping=[damping] * 3, offset=list(preload), show=False)
        items[name] = (body, node)
        layout[name] = len(nodes)
        nodes.append(node)
    return items, race_frames, held, driven, housing_spring
