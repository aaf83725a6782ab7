"""Add a complete angular-contact ball bearing to an Exudyn ``mbs`` (MODEL.md §1–§9).

Example (importing the package registers ``mbs.CreateAngularContactBearing`` on Exudyn's
``MainSystem``, as Exudyn registers its own ``Create...`` functions; the free function
``CreateAngularContactBearing(mbs, ...)`` is the same)::

    import exudyn as exu
    import exudyn_bearing
    from exudyn_bearing import races

    SC = exu.SystemContainer(); mbs = SC.AddSystem()
    brg = mbs.CreateAngularContactBearing(innerRace=races.Driven(rpm=1800), axialForce=1300)
    mbs.Assemble()
    ...  # exu.SolveDynamic(mbs, settings) or exudyn_bearing.simulation.runner
    res = brg.Results(mbs)
    res.cage_slip_percent, res.kinematic_cage_slip_percent
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from contact.ballrace import ContactLaw
from contact.lubricant import Lubricant
from contact.surface import SurfaceModel, surface_record
from ..bearing import BallDrag, Bearing
from ..bearingfile import as_setup
from ..setup import FROM_SETUP, BearingSetup
from ..presets import REFERENCE_BEARING
from ..races import (NODE_KINEMATICS, Driven, Fixed, Race, default_race_body, move_body, node_rows, node_state,
                     race_adapter, ring_inertia)
from ..solvers.quasidynamic import AzimuthStates
from ..solvers.quasistatic import solve_load_distribution
from ..solvers.raceway import choose_inner_control, jones_axis_start, raceway_control
from ..solvers.start import steady_start
from ..solvers.surface_start import surface_start
from .connector import BearingConnector, CageModel
from .handle import SENSOR_LABELS, SENSOR_OUTPUTS, BearingHandle  # noqa: F401 (re-exported)
from .predictor import install_predictor

__all__ = ["CreateAngularContactBearing", "BearingHandle"]


def _ball_circles(frame, outer_contact, e_z, omega, orbit):
    """(Z, 2, 3): per ball, the zero direction and spin axis about which a ball defect's
    ``angle_deg`` turns it (contact.surface.ball_circles), in the ball's body frame (= global
    at t = 0): the direction of its outer-race contact (``outer_contact``, bearing frame) and
    the axis of its start spin relative to the cage."""
    out = np.empty((len(outer_contact), 2, 3))
    for j in range(len(outer_contact)):
        spin = omega[j] - orbit[j] * e_z
        axis = spin / np.linalg.norm(spin) if np.linalg.norm(spin) > 1e-9 else e_z
        out[j] = frame @ (outer_contact[j] / np.linalg.norm(outer_contact[j])), frame @ axis
    return out


def _settle_surfaces(mbs, connector, nodes, layout, inner, held):
    """Moves the balls (and an inner race the builder made, free in translation) so that the
    surfaces at t = 0 carry the perfect start's forces (:func:`surface_start`); the outcome is
    ``connector.surface_start``, and a start that does not converge warns and keeps the
    perfect bearing's state."""
    init = [np.asarray(mbs.GetNodeParameter(n, "initialCoordinates"), dtype=float) for n in nodes]
    vel = [np.asarray(mbs.GetNodeParameter(n, "initialVelocities"), dtype=float) for n in nodes]
    q = connector.reference + np.concatenate(init)
    axis = connector.axis
    moves = []
    for slot in layout["balls"]:  # radially and axially: its place in its pocket is kept
        radial = q[6 * slot:6 * slot + 3] - connector.origin
        radial = radial - (radial @ axis) * axis
        moves.append((slot, np.stack([radial / np.linalg.norm(radial), axis])))
    s = layout["inner"]
    if s is not None and inner.kind in ("driven", "free") and held.get(s) != "all":
        moves.append((s, np.eye(3)))
    moved, info = surface_start(connector, q, np.concatenate(vel), moves)
    for slot, _ in moves:
        start = (moved - connector.reference)[6 * slot:6 * slot + 6]
        mbs.SetNodeParameter(nodes[slot], "initialCoordinates", start.tolist())
    connector.surface_start = info
    if not info["converged"]:
        warnings.warn(info["message"], stacklevel=3)


def _check_frame(position, rotation):
    position = np.asarray(position, dtype=float)
    rotation = np.asarray(rotation, dtype=float)
    if position.shape != (3,) or not np.all(np.isfinite(position)):
        raise ValueError(f"position must be 3 finite numbers, got {position!r}")
    if rotation.shape != (3, 3) or not np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-9) \
            or np.linalg.det(rotation) < 0:
        raise ValueError("rotationMatrix must be a proper 3x3 rotation matrix")
    return position, rotation


def _check_force(name, value):
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


def _check_start_load(value, inner):
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


def _check_races(mbs, innerRace, outerRace, setup):
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


def _race_pose(mbs, inner, outer, origin, frame):
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


def _add_state_sensor(mbs, nodes, connector):
    """A user-function sensor storing the bearing's absolute node coordinates and velocities
    at every sensor write (the source of :meth:`BearingHandle.Results`); it also reports
    progress where the runner asked for it."""
    from exudyn.utilities import SensorUserFunction

    ref = connector.reference
    indices = []

    def record(mbs_, t, sensorNumbers, factors, configuration):
        if not indices:
            indices.extend(node_rows(mbs_, nodes))
        if connector.progress is not None:
            connector.progress(t)
        q = mbs_.systemData.GetODE2Coordinates(configuration=configuration)
        q_t = mbs_.systemData.GetODE2Coordinates_t(configuration=configuration)
        return np.concatenate([np.asarray(q)[indices] + ref, np.asarray(q_t)[indices]]).tolist()

    return mbs.AddSensor(SensorUserFunction(sensorUserFunction=record, storeInternal=True, writeToFile=False))


def CreateAngularContactBearing(mbs, bearing: Bearing | BearingSetup | str = REFERENCE_BEARING,
                                lubricant: Lubricant = FROM_SETUP,
                                *, innerRace: Race | None = None, outerRace: Race | None = None,
                                axialForce: float = 0.0, radialForce: float = 0.0, startLoad=None,
                                position=(0.0, 0.0, 0.0), rotationMatrix=np.eye(3),
                                contactLaw: ContactLaw = FROM_SETUP, cage: CageModel = FROM_SETUP,
                                ballDrag: BallDrag | None = FROM_SETUP, surface: SurfaceModel = FROM_SETUP,
                                innerRaceDisplacement=None,
                                initialControl: str = "auto", initialState: str = "auto",
                                recordStates: bool = True, show: bool = True) -> BearingHandle:
    """Add an angular-contact ball bearing (Z ball bodies, races, cage, one contact
    connector) to ``mbs`` and return its :class:`BearingHandle`.

    Parameters
    ----------
    mbs : exudyn.MainSystem
    bearing : Bearing, BearingSetup or path
        Geometry and materials (default: the paper's reference bearing). A setup
        (:class:`~exudyn_bearing.setup.BearingSetup`, e.g. from
        :func:`~exudyn_bearing.bearingfile.load_bearing`) or a bearing file's path also gives
        the lubricant, ball drag, cage, contact law, surfaces and housing, each unless
        passed here explicitly.
    lubricant : contact.lubricant.Lubricant
        Default: the setup's, else the reference oil.
    innerRace, outerRace : Race
        See :mod:`exudyn_bearing.races`; defaults ``Driven(1800 rpm)`` and, for the outer
        race, the setup's housing (``HousingModel.race()``), else ``Fixed()``.
    axialForce, radialForce : float or callable
        Forces on the inner race (a ``Driven``/``Free`` race body), N, constant or a
        function of time t in s (load steps, gusts): axial along +bearing axis (loading the
        inner contacts), radial along the bearing frame's first axis. The initial state
        balances the values at t = 0.
    startLoad : (axial, radial), optional
        For an inner race on your body (``races.OnBody``), whose load you apply to that
        body: the load this bearing carries at the start, N, in the directions of
        ``axialForce`` and ``radialForce``. The bearing starts settled for it, as a created
        race under those forces would, and moves your body by the bearing's deflection
        under it (micrometres; its initial coordinates). Not applied. Without it, an
        ``OnBody`` bearing starts from the balance of its balls with the races where your
        bodies are (:func:`~exudyn_bearing.solvers.quasidynamic.pose_state`): place a shaft on
        several bearings first with :func:`~exudyn_bearing.model.assembly.SettleShaft` (a
        ``startLoad`` on each would move the shaft once per bearing).
    position, rotationMatrix
        Bearing frame in global coordinates; its third column is the bearing axis.
    contactLaw : contact.ballrace.ContactLaw
        Normal, traction and spin-moment physics of the ball–race contacts (default: the
        bearing file's, else ``ContactLaw()``).
    cage : CageModel
        Rigid cage (default: the bearing file's, else centred by the outer race land, 0.4 mm
        diametral play), the paper's spring chain, or none.
    ballDrag : BallDrag or None
        Sphere drag on the balls' orbital motion (MODEL.md §8; default: the bearing file's,
        else fully flooded); None: off.
    surface : contact.surface.SurfaceModel
        Race and ball defects, race and ball waviness and ball-diameter variation (MODEL.md
        §13; default: the bearing file's ``[[defect]]`` and ``[waviness]``, else perfect
        surfaces, which cost nothing). The start state is the perfect bearing's with the
        balls (and a created inner race free in translation) placed so that the surfaces
        carry its forces at t = 0 (§13d; ``handle.connector.surface_start`` says what moved).
    innerRaceDisplacement : (dx, dy, dz), optional
        Start a created (``Driven``/``Free``) inner race displaced by this much from the
        outer race, m, in the bearing frame, with the balls in quasi-static balance for
        that position (no applied forces then), e.g. a preload by interference.
    initialControl : {'auto', 'inner', 'outer'}
        Pure-rolling start: 'inner'/'outer' is raceway control (Jones) by that contact —
        each ball's absolute spin axis solved for zero spin there and zero rolling slip at
        both contacts (:func:`exudyn_bearing.solvers.raceway.raceway_control`); 'auto' takes Jones' angle of the contact
        with the larger Newtonian spin resistance as the absolute axis (see
        ``raceway.jones_axis_start``: measured to start combined loads with the fewest step cuts).
    initialState : {'auto', 'steady', 'rolling'}
        'steady': every ball, the cage and the inner race start in the steady rolling state
        of :func:`exudyn_bearing.steady_state` (pure axial load on a created inner race:
        the balance of traction, spin, drag, centrifugal and gyroscopic forces, MODEL.md
        §12), so a run does not spend seconds of simulated time settling; under combined
        or radial load, every ball in its own quasi-dynamic balance at one cage
        speed, each where its pocket carries that balance's circumferential force
        (:func:`exudyn_bearing.solvers.quasidynamic.combined_load_state`, MODEL.md §12a; ~2–3 s
        to solve under combined load, up to 8–16 s under a pure radial one, after which the run
        holds its cage speed instead of drifting for seconds; a path longer than the budget
        below is not started).
        'rolling': the quasi-static position with pure-rolling speeds (see Notes). 'auto'
        (default): 'steady' where it applies (``Driven``/``Free`` inner race, no
        ``innerRaceDisplacement``, a load, the solve converged within
        ``start.AUTO_CONTINUATION_STEPS`` radial-load steps), else 'rolling'.
    recordStates : bool
        Add a sensor storing the bearing's node states at every sensor write period, from
        which :meth:`BearingHandle.Results` computes all outputs afterwards (costs nothing
        while integrating beyond storing one vector).
    show : bool
        Add simple graphics (balls).

    Notes
    -----
    The initial state comes from the quasi-static solution (:func:`solve_load_distribution`
    with the applied forces and speeds, or with the races where they are) with
    pure-rolling velocities: each ball's spin axis by raceway control (``initialControl``)
    and the orbital and spin speeds with zero rolling slip at both contacts (MODEL.md §7).
    """
    import exudyn as exu
    import exudyn.graphics as graphics
    from exudyn.utilities import InertiaSphere, ObjectGenericODE2, RigidBodyInertia

    if surface is None:
        surface = SurfaceModel()
    setup = as_setup(bearing, lubricant=lubricant, contact_law=contactLaw, cage=cage, drag=ballDrag, surface=surface)
    bearing, lubricant, contactLaw, cage = setup.bearing, setup.lubricant, setup.contact_law, setup.cage
    ballDrag, surface = setup.drag, setup.surface
    surface_record(surface, bearing)  # its checks against this bearing's geometry, before mbs is touched
    inner, outer = _check_races(mbs, innerRace, outerRace, setup)
    axial_of_t, radial_of_t = _check_force("axialForce", axialForce), _check_force("radialForce", radialForce)
    axial, radial = float(axial_of_t(0.0)), float(radial_of_t(0.0))
    loaded = bool(axial or radial) or callable(axialForce) or callable(radialForce)
    if loaded and (inner.kind not in ("driven", "free") or inner.fixed_translation):
        raise ValueError("axialForce/radialForce act on a Driven or Free inner race with free translation; "
                         "with other mounts load the body the race sits on")
    start_load = _check_start_load(startLoad, inner)
    origin, frame = _check_frame(position, rotationMatrix)
    axis = frame[:, 2]

    # -- initial configuration from the quasi-static solution ----------------------------
    relative, (w_i, w_o) = _race_pose(mbs, inner, outer, origin, frame)
    rpm_i, rpm_o = w_i * 30 / math.pi, w_o * 30 / math.pi
    if innerRaceDisplacement is not None:
        shift = np.asarray(innerRaceDisplacement, dtype=float)
        if shift.shape != (3,) or not np.all(np.isfinite(shift)):
            raise ValueError(f"innerRaceDisplacement must be 3 finite numbers in m, got {innerRaceDisplacement!r}")
        if inner.kind not in ("driven", "free") or loaded:
            raise ValueError("innerRaceDisplacement needs a Driven or Free inner race and no applied forces")
        relative[:3] = shift
    # the quasi-static solver takes a non-negative inner speed; only |cage speed| matters
    sense = -1.0 if rpm_i < 0 else 1.0
    speeds = dict(rpm=abs(rpm_i), outer_rpm=sense * rpm_o, hertz_method=contactLaw.hertz_method)
    if initialControl not in ("auto", "inner", "outer"):
        raise ValueError(f"initialControl must be 'auto', 'inner' or 'outer', got {initialControl!r}")
    z = bearing.balls
    e_z = np.array([0.0, 0.0, 1.0])
    cage_speed = None
    # the quasi-static centrifugal force at each ball's own pure-rolling orbit (not the
    # nominal cage speed: 200 N would start 13.5 N out of radial balance on a 15 N load)
    where = relative.copy()  # where the races are: a start load moves the user's body from there
    if start_load is not None:
        axial, radial = start_load
    for _ in range(20):
        if loaded or start_load is not None:
            loads = solve_load_distribution(bearing, axial_force=axial, radial_force=radial, cage_speed=cage_speed,
                                            **speeds)
            relative[:3] = loads.displacement
        else:
            loads = solve_load_distribution(bearing, displacement=relative, cage_speed=cage_speed, **speeds)
        psi = loads.azimuth
        e_r = np.stack([np.cos(psi), np.sin(psi), np.zeros(z)], axis=1)
        r_c = bearing.pitch_radius + loads.ball_radius_offset
        c_loc = r_c[:, None] * e_r + loads.ball_axial_offset[:, None] * e_z
        a_i, a_o = loads.inner_contact_angle, loads.outer_contact_angle
        p_in = c_loc - bearing.ball_radius * (np.cos(a_i)[:, None] * e_r + np.sin(a_i)[:, None] * e_z)
        p_out = c_loc + bearing.ball_radius * (np.cos(a_o)[:, None] * e_r + np.sin(a_o)[:, None] * e_z)
        inner_controls = choose_inner_control(bearing, lubricant, loads, w_i, w_o, initialControl)
        if initialControl == "auto":
            w_c, omega_loc = jones_axis_start(bearing, c_loc, p_in, p_out, a_i, a_o, e_r, w_i, w_o, inner_controls,
                                              inner_origin=relative[:3])
        else:
            w_c, omega_loc = raceway_control(c_loc, p_in, p_out, w_i, w_o, inner_controls, inner_origin=relative[:3])
        orbit = np.abs(w_c)
        if cage_speed is not None and np.max(np.abs(orbit - cage_speed)) <= 1e-6 * np.max(orbit):
            break
        # one speed for a pure axial load (all balls alike), each ball's own otherwise
        cage_speed = orbit if radial or not (loaded or start_load) else float(np.mean(orbit))
    on_body = inner.kind == "body"
    steady = steady_start(bearing, lubricant, initialState, axial_force=axial, radial_force=radial, rpm_i=rpm_i,
                          rpm_o=rpm_o, sense=sense, inner=inner, displaced=innerRaceDisplacement is not None,
                          contact_law=contactLaw, ball_drag=ballDrag, cage=cage,
                          pose=where if on_body and start_load is None else None)
    e_psi = np.stack([-np.sin(psi), np.cos(psi), np.zeros(z)], axis=1)
    quasi, cage_offset = None, np.zeros(3)
    if isinstance(steady, AzimuthStates):  # combined load: each ball in its own balance, one cage speed
        quasi, steady = steady, None
        c_loc = quasi.orbit_radius[:, None] * e_r + quasi.axial_position[:, None] * e_z
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
        omega_loc = quasi.omega[:, :1] * e_r + quasi.omega[:, 1:2] * e_psi + quasi.omega[:, 2:] * e_z
        relative[:3] = quasi.displacement
    if steady is not None:
        c_loc = steady.ball_orbit_radius * e_r + steady.ball_axial_position * e_z
        w_c = np.full(z, sense * steady.cage_speed)
        # a reversed bearing is the mirror image in the meridional plane: the pseudovector
        # keeps its circumferential component and flips the others
        w_b = np.asarray(steady.ball_omega) * np.array([sense, 1.0, sense])
        omega_loc = w_b[0] * e_r + w_b[1] * e_psi + w_b[2] * e_z
        relative[:3] = (0.0, 0.0, steady.inner_race_shift)
    if start_load is not None:  # the user's body to where the start state has its race
        move_body(mbs, mbs.GetObject(inner.body)["nodeNumber"], frame @ (relative[:3] - where[:3]))

    # -- bodies -----------------------------------------------------------------------
    node_type = exu.NodeType.RotationRotationVector
    ball_bodies, ball_nodes = [], []
    ball_graphics = [graphics.Sphere(radius=bearing.ball_radius, color=graphics.color.grey, nTiles=16),
                     graphics.Basis(length=1.3 * bearing.ball_radius)] if show else []
    for j in range(z):
        c = origin + frame @ c_loc[j]
        v = frame @ (w_c[j] * np.cross(e_z, c_loc[j] - cage_offset))  # with its pocket, about the cage centre
        d = mbs.CreateRigidBody(inertia=InertiaSphere(mass=bearing.ball_mass, radius=bearing.ball_radius),
                                referencePosition=c, initialVelocity=v,
                                initialAngularVelocity=frame @ omega_loc[j],
                                nodeType=node_type, graphicsDataList=ball_graphics, returnDict=True)
        ball_bodies.append(d["bodyNumber"])
        ball_nodes.append(d["nodeNumber"])
    nodes = list(ball_nodes)
    layout = {"balls": list(range(z)), "cage": None, "inner": None, "outer": None}
    cage_body = cage_node = None
    if cage.kind == "rigid":
        width, thick = bearing.ball_diameter, 0.3 * bearing.ball_diameter
        mass = cage.mass_for(bearing)
        i_r, i_a = ring_inertia(mass, bearing.pitch_radius - thick / 2, bearing.pitch_radius + thick / 2, width)
        d = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=mass, inertiaTensor=np.diag([i_r, i_r, i_a])),
                                referencePosition=origin + frame @ cage_offset, referenceRotationMatrix=frame,
                                initialAngularVelocity=float(np.mean(w_c)) * axis, nodeType=node_type,
                                returnDict=True)
        cage_body, cage_node = d["bodyNumber"], d["nodeNumber"]
        layout["cage"] = len(nodes)
        nodes.append(cage_node)
    race_items = {"inner": (None, None), "outer": (None, None)}
    race_frames, held, driven = {}, {}, {}
    housing_spring = None
    for name, race, shift in (("inner", inner, relative[:3]), ("outer", outer, np.zeros(3))):
        if race.kind == "fixed":
            continue
        if race.kind == "body" and mbs.GetNode(mbs.GetObject(race.body)["nodeNumber"])["nodeType"] != "RigidBodyRotVecLG":
            body, node = race_adapter(mbs, bearing, race, name, node_type)
            race_frames[name] = (np.zeros(3), np.eye(3))
        elif race.kind == "body":
            body = race.body
            node = mbs.GetObject(body)["nodeNumber"]
            race_frames[name] = (np.asarray(race.local_position, dtype=float), np.asarray(race.local_rotation, dtype=float))
        else:
            mass, (i_r, i_a) = default_race_body(bearing, race, name)
            d = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=mass, inertiaTensor=np.diag([i_r, i_r, i_a])),
                                    referencePosition=origin + frame @ shift, referenceRotationMatrix=frame,
                                    initialAngularVelocity=race.speed(0.0) * axis, nodeType=node_type,
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
                preload = -frame @ np.array([radial_of_t(0.0), 0.0, axial_of_t(0.0)]) / stiffness
                housing_spring = mbs.CreateCartesianSpringDamper(
                    itemNumbers=[mbs.CreateGround(referencePosition=list(origin), show=False), body],
                    stiffness=[stiffness] * 3, damping=[damping] * 3, offset=list(preload), show=False)
        race_items[name] = (body, node)
        layout[name] = len(nodes)
        nodes.append(node)
    connector = BearingConnector(setup, {"inner": inner, "outer": outer}, layout, origin, frame, race_frames,
                                 lambda t: frame @ np.array([radial_of_t(t), 0.0, axial_of_t(t)]), held,
                                 driven=driven, ball_circles=_ball_circles(frame, p_out - c_loc, e_z, omega_loc, w_c))
    connector.reference = np.concatenate([np.asarray(mbs.GetNodeParameter(n, "referenceCoordinates"), dtype=float)
                                          for n in nodes])
    if connector.surface is not None:  # the start carries the surfaces at t = 0 (MODEL.md §13d)
        _settle_surfaces(mbs, connector, nodes, layout, inner, held)
    ref = connector.reference

    def force_user_function(mbs_, t, itemNumber, q, q_t):
        return connector.residual_forces(t, q, q_t)

    def jacobian_user_function(mbs_, t, itemNumber, q, q_t, f_q, f_qt):
        return connector.jacobian(t, np.asarray(q) + ref, np.asarray(q_t), f_q, f_qt)

    # the block Jacobian is installed here, so a scene solved by Exudyn's own SolveDynamic
    # (implicit solvers) gets it too; run_solver(jacobian='exudyn') removes it
    contact = mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes, forceUserFunction=force_user_function,
                                              jacobianUserFunction=jacobian_user_function))
    # the Newton start from the previous acceleration (MODEL.md §10b), for plain SolveDynamic
    # scenes too; SolverSettings(predictor=False) turns it off for a run_solver run
    install_predictor(mbs, nodes, steady_start=steady is not None)
    sensor = _add_state_sensor(mbs, nodes, connector) if recordStates else None
    return BearingHandle(bearing, ball_bodies, ball_nodes, cage_body, cage_node, race_items["inner"][0],
                         race_items["inner"][1], race_items["outer"][0], race_items["outer"][1], contact, sensor,
                         connector, nodes, loads, steady, quasi, housing_spring)


def _register_on_main_system():
    """Bind :func:`CreateAngularContactBearing` as ``MainSystem.CreateAngularContactBearing``
    through Exudyn's extension registry (``exudyn.misc.extensionRegistry``, Exudyn 1.13), the
    mechanism of Exudyn's own ``mbs.Create...`` functions; a name Exudyn already has is not
    replaced (the registry raises, and the free function stays)."""
    try:
        import exudyn as exu
        from exudyn.misc.extensionRegistry import extends, install
    except ImportError:  # an Exudyn without the registry: the free function only
        return
    extends(exu.MainSystem, name="CreateAngularContactBearing")(CreateAngularContactBearing)
    install()


_register_on_main_system()

