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

import warnings

import numpy as np

from contact.ballrace import ContactLaw
from contact.lubricant import Lubricant
from contact.surface import SurfaceModel, surface_record
from ..bearing import BallDrag, Bearing
from ..bearingfile import as_setup
from ..errors import SurfaceStartWarning
from ..setup import FROM_SETUP, BearingSetup
from ..presets import REFERENCE_BEARING
from ..races import Race, move_body
from ..solvers.surface_start import surface_start
from ..solvers.thermal import axial_pressing
from .bodies import add_balls, add_cage, add_races
from .checks import check_displacement, check_force, check_frame, check_races, check_start_load
from .connector import BearingConnector, CageModel
from .handle import SENSOR_LABELS, SENSOR_OUTPUTS, BearingHandle  # noqa: F401 (re-exported)
from .predictor import install_predictor
from .start_residual import StartResidual
from .sensors import add_state_sensor
from .start_state import race_pose, start_state
from .thermal_nodes import UPDATE_PERIOD, BearingTemperatures, thermal_start

__all__ = ["CreateAngularContactBearing", "BearingHandle"]


def _ball_circles(frame, start):
    """(Z, 2, 3): per ball, the zero direction and spin axis about which a ball defect's
    ``angle_deg`` turns it (contact.surface.ball_circles), in the ball's body frame (= global
    at t = 0): the direction of its outer-race contact and the axis of its start spin
    relative to the cage (``start``: the :class:`~exudyn_bearing.model.start_state.StartState`)."""
    outer_contact, omega, orbit = start.outer_contact, start.ball_omega, start.orbit_speed
    e_z = np.array([0.0, 0.0, 1.0])
    out = np.empty((len(outer_contact), 2, 3))
    for j in range(len(outer_contact)):
        spin = omega[j] - orbit[j] * e_z
        axis = spin / np.linalg.norm(spin) if np.linalg.norm(spin) > 1e-9 else e_z
        out[j] = frame @ (outer_contact[j] / np.linalg.norm(outer_contact[j])), frame @ axis
    return out


def _settle_surfaces(mbs, connector, nodes, layout, inner, held):
    """Moves the balls (and an inner race the builder made, free in translation) so that the
    surfaces at t = 0 carry the perfect start's forces (:func:`surface_start`); the outcome is
    ``connector.surface_start``; one that leaves forces unbalanced says so in a
    SurfaceStartWarning."""
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
        warnings.warn(info["message"], SurfaceStartWarning, stacklevel=3)


def CreateAngularContactBearing(mbs, bearing: Bearing | BearingSetup | str = REFERENCE_BEARING,
                                lubricant: Lubricant = FROM_SETUP,
                                *, innerRace: Race | None = None, outerRace: Race | None = None,
                                axialForce: float = 0.0, radialForce: float = 0.0, startLoad=None,
                                position=(0.0, 0.0, 0.0), rotationMatrix=np.eye(3),
                                contactLaw: ContactLaw = FROM_SETUP, cage: CageModel = FROM_SETUP,
                                ballDrag: BallDrag | None = FROM_SETUP, surface: SurfaceModel = FROM_SETUP,
                                innerRaceDisplacement=None,
                                initialControl: str = "auto", initialState: str = "auto",
                                initialTemperatures: str = "auto", thermalUpdatePeriod: float = UPDATE_PERIOD,
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
        Sphere drag on the balls' orbital motion and, with ``oil_flow``, the jet oil's momentum
        (MODEL.md §8, §11c; default: the bearing file's, else fully flooded); None: off.
    surface : contact.surface.SurfaceModel
        Race and ball defects, race and ball waviness and ball-diameter variation (MODEL.md
        §13; default: the bearing file's ``[[defect]]`` and ``[waviness]``, else perfect
        surfaces, which cost nothing). The start state is the perfect bearing's with the
        balls (and a created inner race free in translation) placed so that the surfaces
        carry its forces at t = 0 (§13d; ``handle.connector.surface_start`` says what moved).
    innerRaceDisplacement : (dx, dy, dz), optional
        Start a created (``Driven``/``Free``) inner race displaced by this much from the
        outer race, m, in the bearing frame, with the balls in quasi-static balance for
        that position (no applied forces then), e.g. a preload by interference. With a
        ``thermal`` model it is set at the assembly temperature: the start adds the axial
        pressing δ_a of the growth to the start temperatures (MODEL.md §14f, §14g).
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
    initialTemperatures : {'auto', 'steady', 'inlet'}
        With a setup's ``thermal`` model (MODEL.md §14g; else unused): the thermal network's
        node temperatures are first-order states of the solve, its heat the current state's
        losses, each contact's oil at its race's and the balls' temperatures. 'steady': the
        run starts from the thermal steady state (constant loads: :func:`exudyn_bearing.steady_state`
        under axial load, :func:`~exudyn_bearing.solvers.quasidynamic.combined_load_state` under
        combined or radial load) — temperatures, grown bearing and rolling state; 'inlet': every
        node at the oil inlet's temperature, the bearing grown to it; 'auto': 'steady' where
        it applies and converges, else 'inlet'.
    thermalUpdatePeriod : float
        Simulated time between two updates of the nodes' heat, the network's conductances
        and the contacts' oils, s (default :data:`~exudyn_bearing.model.thermal_nodes.UPDATE_PERIOD`).
    recordStates : bool
        Add a sensor storing the bearing's node states at every sensor write period, from
        which :meth:`BearingHandle.Results` computes all outputs afterwards, with the contacts'
        traction the run computed there (:mod:`exudyn_bearing.model.recorded_traction`): ~10 µs
        and ~1 KB per written state for 16 balls beside the state's ~2 KB. A scene that never
        asks for the results (a vibration scene reading its housing sensors) can pass False.
    show : bool
        Add simple graphics (balls).

    Notes
    -----
    The initial state comes from the quasi-static solution (:func:`solve_load_distribution`
    with the applied forces and speeds, or with the races where they are) with
    pure-rolling velocities: each ball's spin axis by raceway control (``initialControl``)
    and the orbital and spin speeds with zero rolling slip at both contacts (MODEL.md §7).
    """
    if surface is None:
        surface = SurfaceModel()
    setup = as_setup(bearing, lubricant=lubricant, contact_law=contactLaw, cage=cage, drag=ballDrag, surface=surface)
    bearing = setup.bearing
    surface_record(setup.surface, bearing)  # its checks against this bearing's geometry, before mbs is touched
    inner, outer = check_races(mbs, innerRace, outerRace, setup)
    axial_of_t, radial_of_t = check_force("axialForce", axialForce), check_force("radialForce", radialForce)
    axial, radial = float(axial_of_t(0.0)), float(radial_of_t(0.0))
    loaded = bool(axial or radial) or callable(axialForce) or callable(radialForce)
    if loaded and (inner.kind not in ("driven", "free") or inner.fixed_translation):
        raise ValueError("axialForce/radialForce act on a Driven or Free inner race with free translation; "
                         "with other mounts load the body the race sits on")
    start_load = check_start_load(startLoad, inner)
    origin, frame = check_frame(position, rotationMatrix)

    relative, speeds = race_pose(mbs, inner, outer, origin, frame)
    shift = check_displacement(innerRaceDisplacement, inner, loaded)
    if shift is not None:
        relative[:3] = shift
    heat_start, start_setup = None, setup
    if setup.thermal is not None:  # the bearing at its start temperatures (MODEL.md §14g)
        heat_start = thermal_start(setup, initialTemperatures, axial=axial, radial=radial,
                                   constant_load=not (callable(axialForce) or callable(radialForce)) and shift is None
                                   and start_load is None, rpm_i=speeds[0] * 30 / np.pi, rpm_o=speeds[1] * 30 / np.pi,
                                   inner_kind=inner.kind, initial_state=initialState)
        setup, start_setup, bearing = heat_start.setup, heat_start.start_setup, heat_start.setup.bearing
        if shift is not None:  # the rings at their axial places since assembly: pressed by δ_a (MODEL.md §14f)
            relative[2] += axial_pressing(heat_start.cold, heat_start.temperatures)
    start = start_state(start_setup, inner, relative, speeds, axial=axial, radial=radial, loaded=loaded,
                        start_load=start_load, displaced=shift is not None, initial_control=initialControl,
                        initial_state=initialState, steady=None if heat_start is None else heat_start.steady)
    if start_load is not None:  # the user's body to where the start state has its race
        move_body(mbs, mbs.GetObject(inner.body)["nodeNumber"], frame @ (start.relative[:3] - start.where[:3]))

    ball_bodies, ball_nodes = add_balls(mbs, bearing, origin, frame, start, show)
    nodes = list(ball_nodes)
    layout = {"balls": list(range(bearing.balls)), "cage": None, "inner": None, "outer": None}
    cage_body, cage_node = add_cage(mbs, setup, origin, frame, start)
    if cage_node is not None:
        layout["cage"] = len(nodes)
        nodes.append(cage_node)
    race_items, race_frames, held, driven, housing_spring = add_races(
        mbs, bearing, {"inner": inner, "outer": outer}, origin, frame, start.relative[:3], (axial, radial), nodes,
        layout)
    connector = BearingConnector(setup, {"inner": inner, "outer": outer}, layout, origin, frame, race_frames,
                                 lambda t: frame @ np.array([radial_of_t(t), 0.0, axial_of_t(t)]), held,
                                 driven=driven, ball_circles=_ball_circles(frame, start))
    contact = _add_connector(mbs, connector, nodes, layout, inner, held, steady=start.steady is not None)
    sensor = add_state_sensor(mbs, nodes, connector) if recordStates else None
    temperatures = None
    if heat_start is not None:
        temperatures = BearingTemperatures(mbs, connector, nodes, setup, heat_start, thermalUpdatePeriod)
    return BearingHandle(bearing, ball_bodies, ball_nodes, cage_body, cage_node, race_items["inner"][0],
                         race_items["inner"][1], race_items["outer"][0], race_items["outer"][1], contact, sensor,
                         connector, nodes, start.loads, start.steady, start.quasi, housing_spring, temperatures)


def _add_connector(mbs, connector, nodes, layout, inner, held, steady):
    """The connector's ``ObjectGenericODE2`` with its force and block-Jacobian user functions
    and the Newton predictor (``steady``: the run starts from a steady state); the start
    carries the surfaces first (MODEL.md §13d). Returns the object number."""
    from exudyn.utilities import ObjectGenericODE2

    connector.reference = np.concatenate([np.asarray(mbs.GetNodeParameter(n, "referenceCoordinates"), dtype=float)
                                          for n in nodes])
    if connector.surface is not None:  # the start carries the surfaces at t = 0 (MODEL.md §13d)
        _settle_surfaces(mbs, connector, nodes, layout, inner, held)
    start = StartResidual(connector)

    def force_user_function(mbs_, t, itemNumber, q, q_t):
        return start.forces(t, q, q_t)

    def jacobian_user_function(mbs_, t, itemNumber, q, q_t, f_q, f_qt):
        return start.jacobian(t, q, q_t, f_q, f_qt)

    # the block Jacobian is installed here, so a scene solved by Exudyn's own SolveDynamic
    # (implicit solvers) gets it too; run_solver(jacobian='exudyn') removes it
    contact = mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes, forceUserFunction=force_user_function,
                                              jacobianUserFunction=jacobian_user_function))
    # the Newton start from the previous acceleration (MODEL.md §10b), for plain SolveDynamic
    # scenes too; SolverSettings(predictor=False) turns it off for a run_solver run
    install_predictor(mbs, nodes, steady_start=steady, start_residual=start,
                      orbit=([nodes[j] for j in layout["balls"]], connector.origin, connector.axis))
    return contact


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

