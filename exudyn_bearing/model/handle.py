"""The handle of a bearing added to an ``mbs``: its item indices, sensors and result
accessors (Exudyn's ``Create...`` style: a small record of what was created)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..bearing import Bearing
from ..races import node_rows
from ..results.records import inputs_record
from .connector import BearingConnector

__all__ = ["BearingHandle", "SENSOR_OUTPUTS", "SENSOR_LABELS"]


#: Outputs :meth:`BearingHandle.AddSensors` can record.
SENSOR_OUTPUTS = ("cageSpeed", "cageSlip", "kinematicCageSlip", "attitudeXZ", "attitudeYZ", "innerRaceForce",
                  "outerRaceForce")
#: what each output is and its unit (MODEL.md §7), for plot axes and legends
SENSOR_LABELS = {"cageSpeed": ("cage speed", "rad/s"), "cageSlip": ("cage slip, the paper's P19", "%"),
                 "kinematicCageSlip": ("kinematic cage slip", "%"), "attitudeXZ": ("ball attitude xz", "deg"),
                 "attitudeYZ": ("ball attitude yz", "deg"),
                 "innerRaceForce": ("force of the balls on the inner race (x, y, z of the bearing frame)", "N"),
                 "outerRaceForce": ("force of the balls on the outer race (x, y, z of the bearing frame)", "N")}


@dataclass
class BearingHandle:
    """Item indices, sensors and result accessors of a bearing added to an ``mbs``."""

    bearing: Bearing
    ballBodies: list
    ballNodes: list
    cageBody: int | None
    cageNode: int | None
    innerRaceBody: int | None
    innerRaceNode: int | None
    outerRaceBody: int | None
    outerRaceNode: int | None
    contactObject: int
    stateSensor: int | None
    connector: BearingConnector = field(repr=False)
    nodeNumbers: list = field(repr=False, default_factory=list)
    initialLoads: object = field(repr=False, default=None)
    #: the :class:`~exudyn_bearing.solvers.steady.SteadyState` the run starts from, or None (pure-rolling start)
    initialSteadyState: object = field(repr=False, default=None)
    #: under combined load, the :class:`~exudyn_bearing.solvers.quasidynamic.AzimuthStates` the run
    #: starts from, or None
    initialQuasiDynamicState: object = field(repr=False, default=None)
    #: the housing's spring-damper to ground (``races.Housing`` outer race), else None
    housingSpring: int | None = None
    #: the thermal network's nodes in the solve (:class:`~exudyn_bearing.model.thermal_nodes.BearingTemperatures`;
    #: a setup with a ``thermal`` model, MODEL.md §14g), else None
    temperatures: object = field(repr=False, default=None)

    def Inputs(self, **settings) -> dict:
        """What this bearing's results depend on (bearing, lubricant, drag, contact law, cage,
        races, package version, and ``settings`` given here), for a result file
        (:func:`exudyn_bearing.results.records.inputs_record`)."""
        con = self.connector
        surface = {} if con.surface is None else {"surface": con.surface}  # (a perfect bearing's record as before)
        bearing, th = self.bearing, self.temperatures
        if th is not None:  # the bearing as given (the run's is grown to its start temperatures)
            bearing = th.start.cold.bearing
            surface |= {"thermal": th.model, "initial_temperatures": th.start.kind,
                        "thermal_update_period_s": th.update_period}
        return inputs_record(bearing, lubricant=con.lubricant, drag=con.drag, contact_law=con.law,
                             cage=con.cage, races=con.races, **surface, **settings)

    def States(self, mbs):
        """Recorded (t, q, q_t) of the bearing's nodes: absolute coordinates, shape
        (steps, 6 * nodes) each, from the state sensor."""
        if self.stateSensor is None:
            raise ValueError("recordStates=False: this bearing records no states")
        data = np.asarray(mbs.GetSensorStoredData(self.stateSensor))
        if data.ndim != 2 or data.shape[0] == 0:
            raise ValueError("no states recorded yet: run a simulation with sensors stored internally")
        n = 6 * len(self.nodeNumbers)
        return data[:, 0], data[:, 1:1 + n], data[:, 1 + n:1 + 2 * n]

    def RecommendedStep(self) -> float:
        """The time step this bearing needs at its start state, s: 1e-4 s, or less for small
        balls at high contact stiffness (:func:`exudyn_bearing.model.steprule.recommended_step`).
        ``run_solver`` uses the smallest over its bearings unless a step is given."""
        from .steprule import NOMINAL_STEP, recommended_step

        return NOMINAL_STEP if self.initialLoads is None else recommended_step(self.bearing, self.initialLoads)

    def RecommendedSurfaceStep(self, innerRpm: float, outerRpm: float = 0.0) -> float:
        """The time step this bearing's defects ask for at races turning at ``innerRpm`` and
        ``outerRpm``, s (inf without defects): two steps per defect passage and, where a ball's
        contact opens (or loses half its approach) over a defect or it strikes the edge hard,
        0.7/ω_b to resolve the contact's unloading and the ball's rattle between the races
        (MODEL.md §13c; :func:`~exudyn_bearing.model.steprule.passage_step`, :func:`~exudyn_bearing.model.
        steprule.strike_step`). A scene that reads vibration amplitudes steps at no more than
        min(:meth:`RecommendedStep`, this, its sample period)."""
        from .steprule import passage_step, strike_step

        surface = self.connector.surface
        if surface is None or not surface.defects:
            return math.inf
        step = passage_step(self.bearing, surface, innerRpm, outerRpm)
        if self.initialLoads is not None:
            step = min(step, strike_step(self.bearing, surface, self.initialLoads, innerRpm, outerRpm))
        return step

    def PassageWindows(self, innerRpm: float, outerRpm: float = 0.0, coarseStep: float = 0.0):
        """Where this bearing's balls need :meth:`RecommendedSurfaceStep`: rows (race 0 inner /
        1 outer, the defect's azimuth rad, the window's half angle rad) of
        :func:`~exudyn_bearing.model.steprule.passage_windows` for races turning at ``innerRpm``
        and ``outerRpm`` and ``coarseStep`` s taken elsewhere (MODEL.md §13c); None with a pit on
        a ball or without the start's loads, an empty array without race defects."""
        from .steprule import passage_windows

        surface = self.connector.surface
        if surface is None or not surface.defects:
            return np.zeros((0, 3))
        if self.initialLoads is None:
            return None
        return passage_windows(self.bearing, surface, self.initialLoads, innerRpm, outerRpm, coarseStep,
                               self.connector.law.damping_ratio)

    def RecommendedAbsoluteTolerance(self) -> float:
        """Newton's absolute tolerance for this bearing, N: 3e-5 of its largest contact load
        at the start state, the resolution of the compiled traction rule (MODEL.md §10b;
        :func:`exudyn_bearing.model.steprule.recommended_absolute_tolerance`). ``run_solver`` uses
        the smallest over its bearings unless one is given; for ``exu.SolveDynamic`` set
        ``timeIntegration.newton.absoluteTolerance`` to it."""
        from .steprule import MIN_ABSOLUTE_TOLERANCE, recommended_absolute_tolerance

        return MIN_ABSOLUTE_TOLERANCE if self.initialLoads is None else recommended_absolute_tolerance(self.initialLoads)

    def AddSensors(self, mbs, outputs=SENSOR_OUTPUTS, storeInternal: bool = True, writeToFile: bool = False,
                   fileNames: dict | None = None) -> dict:
        """Exudyn sensors of the bearing's outputs (``SensorUserFunction``), for
        ``mbs.PlotSensor``, live views and sensor files; nothing is evaluated unless a
        scene asks for them. Outputs (MODEL.md §7): 'cageSpeed' (rad/s), 'cageSlip' (P19,
        %), 'kinematicCageSlip' (%, mean over balls), 'attitudeXZ' and 'attitudeYZ' (ball
        attitude angles, deg, mean over balls), 'innerRaceForce' and 'outerRaceForce' (the
        balls' contact forces on each race, N, x y z of the bearing frame: what the housing
        takes). All requested outputs share one evaluation
        of the connector per written time. Returns {output: sensor number}; call before
        ``mbs.Assemble()``. The write period is ``simulationSettings.solution.sensors.writePeriod``."""
        from exudyn.utilities import SensorUserFunction

        from ..results.outputs import compute_results

        unknown = [o for o in outputs if o not in SENSOR_OUTPUTS]
        if unknown or not outputs:
            raise ValueError(f"outputs: choose from {SENSOR_OUTPUTS}, got {list(outputs)!r}")
        nodes, ref, indices, cache = self.nodeNumbers, self.connector.reference, [], {}

        def evaluate(mbs_, t, configuration):
            key = (float(t), int(configuration))
            if key not in cache:
                if not indices:
                    indices.extend(node_rows(mbs_, nodes))
                q = np.asarray(mbs_.systemData.GetODE2Coordinates(configuration=configuration))[indices] + ref
                q_t = np.asarray(mbs_.systemData.GetODE2Coordinates_t(configuration=configuration))[indices]
                res = compute_results(self, np.array([t]), q[None], q_t[None])
                cache.clear()
                cache[key] = {"cageSpeed": res.cage_speed[0], "cageSlip": res.cage_slip_percent[0],
                              "kinematicCageSlip": res.kinematic_cage_slip_percent[0],
                              "attitudeXZ": float(np.degrees(np.mean(res.attitude_xz[0]))),
                              "attitudeYZ": float(np.degrees(np.mean(res.attitude_yz[0]))),
                              "innerRaceForce": res.inner_race_force[0], "outerRaceForce": res.outer_race_force[0]}
            return cache[key]

        sensors = {}
        for name in outputs:
            def user_function(mbs_, t, sensorNumbers, factors, configuration, name=name):
                return [float(v) for v in np.atleast_1d(evaluate(mbs_, t, configuration)[name])]

            kw = {"fileName": fileNames[name]} if fileNames and name in fileNames else {}
            sensors[name] = mbs.AddSensor(SensorUserFunction(sensorUserFunction=user_function, storeInternal=storeInternal,
                                                             writeToFile=writeToFile, name=f"bearing_{name}", **kw))
        return sensors

    def AddVibrationSensors(self, mbs, outputs=("Acceleration", "Velocity", "Displacement"),
                            storeInternal: bool = True, writeToFile: bool = False) -> dict:
        """Exudyn body sensors of the outer race's body (a ``races.Housing`` or your housing
        through ``races.OnBody``) at the bearing centre, global frame: 'Acceleration' (m/s²),
        'Velocity' (m/s), 'Displacement' (m, from the start), written every
        ``simulationSettings.solution.sensors.writePeriod``. Write them at every step (the
        period the step) and record them at your sample rate with
        :func:`exudyn_bearing.studies.vibration.sampled_signal`, which filters as a
        data-acquisition system does: written at the sample period they are point samples,
        and the contact resonances above the Nyquist frequency alias into the band below it
        (MODEL.md §13b). Returns {output: sensor number}; call before ``mbs.Assemble()``."""
        import exudyn as exu
        from exudyn.utilities import SensorBody

        if self.outerRaceBody is None:
            raise ValueError("AddVibrationSensors: the outer race is a kinematic Fixed() race; give "
                             "outerRace=races.Housing() or races.OnBody(your housing body)")
        allowed = ("Acceleration", "Velocity", "Displacement")
        if not outputs or any(o not in allowed for o in outputs):
            raise ValueError(f"outputs: choose from {allowed}, got {list(outputs)!r}")
        from ..races import node_state

        body = self.outerRaceBody
        frame_pos, frame_rot, _, _ = node_state(mbs, self.outerRaceNode)
        local = frame_rot.T @ (self.connector.origin - frame_pos)  # the bearing centre on that body
        return {name: mbs.AddSensor(SensorBody(bodyNumber=body, localPosition=list(local), storeInternal=storeInternal,
                                               writeToFile=writeToFile, name=f"housing_{name}",
                                               outputVariableType=getattr(exu.OutputVariableType, name)))
                for name in outputs}

    def PlotSensors(self, mbs, sensors: dict, outputs=None, **kwargs):
        """``mbs.PlotSensor`` of sensors from :meth:`AddSensors` (``outputs``: a subset of its
        keys, default all) with what each is and its unit on the y axis and in the legend
        (Exudyn labels a user-function sensor 'UserFunction'); ``kwargs`` go to
        ``mbs.PlotSensor`` and win. Returns what it returns ([plt, fig, ax, line])."""
        names = list(sensors) if outputs is None else list(outputs)
        unknown = [n for n in names if n not in sensors]
        if unknown or not names:
            raise ValueError(f"outputs: choose from the sensors given, {list(sensors)!r}, got {names!r}")
        units = {SENSOR_LABELS[n][1] for n in names}
        y_label = (f"{SENSOR_LABELS[names[0]][0]}, {units.pop()}" if len(names) == 1 else
                   ", ".join(sorted(units)) if len(units) == 1 else " / ".join(SENSOR_LABELS[n][1] for n in names))
        options = dict(yLabel=y_label, labels=[f"{SENSOR_LABELS[n][0]} ({SENSOR_LABELS[n][1]})" for n in names],
                       xLabel="time, s", components=0)
        options.update(kwargs)
        return mbs.PlotSensor(sensorNumbers=[sensors[n] for n in names], **options)

    def Results(self, mbs, stride: int = 1):
        """Bearing outputs per recorded step (:class:`exudyn_bearing.results.outputs.BearingResults`)."""
        from ..results.outputs import compute_results

        t, q, q_t = self.States(mbs)
        return compute_results(self, t[::stride], q[::stride], q_t[::stride])

    def ThermalSummary(self, mbs) -> dict | None:
        """The run's temperatures and where its heat went
        (:func:`exudyn_bearing.results.temperatures.thermal_summary`, MODEL.md §14g); None
        for a bearing without a thermal network."""
        if self.temperatures is None:
            return None
        from ..results.temperatures import thermal_summary

        return thermal_summary(self.temperatures, mbs)
