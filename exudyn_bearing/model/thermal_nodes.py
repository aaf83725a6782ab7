"""The bearing's thermal network as first-order states of the Exudyn solve (MODEL.md §14g):
the node temperatures integrated with the bodies, the heat the current state makes put
into them, and each contact's oil set from them.

One ``NodeGenericODE1`` holds the seven node temperatures (K); an ``ObjectGenericODE1``
gives their equation C dT/dt = Q - A T + b (eq. 14.1) as dT/dt = -(A/C) T + (Q + b)/C.
A pre-step function, every ``update_period`` of simulated time, evaluates the bearing at
the step's start state: its losses by place (:func:`place_losses`) become the nodes' heat
Q (:func:`contact.bearing_thermal.place_heat`), its speeds and contacts the conductances A
(:func:`contact.bearing_thermal.bearing_network`), and the node temperatures each race's
and the land's oil (:func:`exudyn_bearing.solvers.thermal.contact_oils`,
:meth:`BearingConnector.set_oils`), and the rings' and balls' temperatures the contacts'
sizes (:func:`exudyn_bearing.solvers.thermal.heated`, :meth:`BearingConnector.set_geometry`,
MODEL.md §14f: the groove centres keep their axial places). Heat, oils and sizes are held over
the period: the coupling is explicit over a period, the network's own conduction implicit in
Exudyn's step.
"""
from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from contact.bearing_thermal import NODES, OperatingPoint, bearing_network, inlet_temperature, mean_contact, place_heat
from contact.surface import SurfaceModel
from ..errors import ThermalGrowthWarning
from ..races import node_rows
from ..solvers.thermal import contact_oils, heated

__all__ = ["BearingTemperatures", "ThermalStart", "thermal_start", "place_losses", "operating_point_of", "add_network",
           "set_network", "UPDATE_PERIOD"]

#: simulated time between two updates of the heat, conductances and oils, s (the network's
#: fastest time constant, that of the cavity's oil, is 2.1 s on the reference bearing, 0.6 s
#: on the 6205 and 3.2–3.5 ms in the 35-mm bearing's oil–air mist; the network itself is
#: integrated implicitly in every step; one update costs about one step)
UPDATE_PERIOD = 1e-3


def place_losses(s, guidance: str, jet=None) -> dict:
    """Losses of one evaluated state ``s`` (a :class:`ConnectorState` of B = 1 states from
    :meth:`BearingConnector.states`) of a cage guided by the ``guidance`` ('inner' or
    'outer') race's land, W by place as :data:`contact.bearing_thermal.HEAT_SPLIT`
    names them (MODEL.md §14c): each race's contacts (traction and spin heat plus the normal
    damping's), rolling resistance, ball drag (the sphere's: ``jet``, (B,) W of
    :func:`~exudyn_bearing.results.outputs.jet_losses`, is the drag force's jet part, placed
    apart), the cage's pockets and its guiding land."""
    from ..results.outputs import body_losses

    out = {}
    for race, f in (("inner", s.inner_forces), ("outer", s.outer_forces)):
        out[f"{race}_contacts"] = float(np.sum(f.heat)) + (0.0 if f.damping_loss is None else
                                                          float(np.sum(f.damping_loss)))
    out["rolling_resistance"] = sum(0.0 if f.rolling_loss is None else float(np.sum(f.rolling_loss))
                                    for f in (s.inner_forces, s.outer_forces))
    drag, pockets, land = (float(np.sum(v)) for v in body_losses(s))
    jet = 0.0 if jet is None else float(np.sum(jet))
    out["ball_drag"], out["jet_momentum"], out["pockets"] = drag - jet, jet, pockets
    out["land_inner" if guidance == "inner" else "land_outer"] = land
    return out


def operating_point_of(con, s) -> OperatingPoint:
    """The network's :class:`OperatingPoint` of one evaluated state ``s`` (B = 1): race and
    cage speeds about the axis, the balls' mean spin speed, and per race the loaded
    contacts' mean Hertz semi-axes, central film and rolling speed (eq. 14.4, 14.5)."""
    axis = con.axis
    w_i, w_o = float(s.inner_omega[0] @ axis), float(s.outer_omega[0] @ axis)
    if s.cage_omega is not None:
        w_c = float(s.cage_omega[0] @ axis)
    else:  # spring-chain cage: the balls' mean orbit
        rel = s.ball_position[0] - con.origin
        w_c = float(np.mean(np.cross(rel, s.ball_velocity[0]) @ axis / np.sum(np.cross(rel, axis) ** 2, axis=1)))
    spin = float(np.mean(np.linalg.norm(s.ball_omega[0], axis=1)))
    angles = np.concatenate([s.inner.contact_angle[0], s.outer.contact_angle[0]])
    loads = np.concatenate([s.inner_forces.normal_load[0], s.outer_forces.normal_load[0]])
    _, hertz = con.params.hertz(angles, con.law.hertz_method)
    a, b = hertz.semi_axes(loads)
    film = np.concatenate([s.inner_forces.film_thickness[0], s.outer_forces.film_thickness[0]])
    speed = np.abs(np.concatenate([s.inner.entrainment[0], s.outer.entrainment[0]]))
    z = len(loads) // 2
    contacts = [mean_contact(a[part], b[part], film[part], speed[part], loads[part])
                for part in (slice(0, z), slice(z, 2 * z))]
    return OperatingPoint(w_i, w_o, w_c, spin, *contacts)


class BearingTemperatures:
    """The thermal network of one bearing in an ``mbs`` (MODEL.md §14g); made by
    :func:`~exudyn_bearing.model.builder.CreateAngularContactBearing` for a setup with a
    ``thermal`` model.

    Attributes
    ----------
    node, object, sensor : int
        The ``NodeGenericODE1`` (the temperatures of :data:`NODES`, K), its
        ``ObjectGenericODE1`` and a sensor storing them at every sensor write.
    updates : list of dict
        Per update: time s, the losses by place W, the heat by node W, the temperatures K,
        the heat leaving through the boundaries W.
    """

    def __init__(self, mbs, connector, nodes, setup, start: "ThermalStart", update_period: float = UPDATE_PERIOD):
        if not update_period > 0:
            raise ValueError(f"thermalUpdatePeriod must be > 0 s, got {update_period!r}")
        self.connector, self.nodes, self.setup, self.lubricant = connector, nodes, setup, setup.lubricant
        self.model, self.geometry, self.start = setup.thermal, start.geometry, start
        self.oil_fraction = 1.0 if setup.drag is None else setup.drag.oil_volume_fraction
        self.update_period = float(update_period)
        self.start_temperatures = {k: float(start.temperatures[k]) for k in NODES}
        self.updates, self._next, self._last, self._rows = [], 0.0, 0.0, []
        self._growth_refused = False  # the growth closed the clearance once (said once)
        # zero rates until the first update (t = 0) sets the network of the start state
        self.node, self.object, self.sensor = add_network(mbs, [self.start_temperatures[k] for k in NODES])
        # the start state's heat before Exudyn's solver computes the start rates (its first
        # step's trapezoid takes them); the first pre-step function redoes it, in case the
        # scene moved the bodies after the bearing was created
        q0 = np.concatenate([mbs.GetNodeParameter(n, "initialCoordinates") for n in nodes]) + connector.reference
        v0 = np.concatenate([mbs.GetNodeParameter(n, "initialVelocities") for n in nodes])
        self._update(mbs, 0.0, q0, v0, self.start_temperatures)
        install_pre_step(mbs, self)

    @property
    def network(self):
        """The :class:`~contact.thermal_network.ThermalNetwork` of the last update."""
        return self.updates[-1]["network"]

    def temperatures(self, mbs) -> dict:
        """The node temperatures now, {node: K}."""
        values = mbs.GetNodeOutput(self.node, _coordinates())
        return dict(zip(NODES, (float(v) for v in values)))

    def __call__(self, mbs, t_end) -> None:
        """The pre-step update (module docstring) from the state at the step's start, at most
        once per ``update_period`` (Exudyn passes the step's end time ``t_end``)."""
        t, self._last = self._last, t_end  # the coordinates are still those at the step's start
        first = not self._rows
        if not first and t < self._next - 1e-12 * max(1.0, abs(t)):
            at = mbs.GetNodeODE1Index(self.node)
            if not np.any(np.asarray(mbs.systemData.GetODE1Coordinates_t())[at:at + len(NODES)]):
                # a new solve between two updates: its stored start rate is zero (set_network)
                temps = self.temperatures(mbs)
                set_network(mbs, self.object, self.network, self.updates[-1]["heat_W"],
                            (self.node, [temps[k] for k in NODES]))
            return
        if first:
            self._rows.extend(node_rows(mbs, self.nodes))
            if self.updates and self.updates[-1]["time_s"] == t:
                self.updates.pop()  # the construction's update of the same start state, redone
        q = np.asarray(mbs.systemData.GetODE2Coordinates())[self._rows] + self.connector.reference
        q_t = np.asarray(mbs.systemData.GetODE2Coordinates_t())[self._rows]
        self._update(mbs, t, q, q_t, self.temperatures(mbs), in_step=True)

    def _update(self, mbs, t, q, q_t, temps, in_step=False) -> None:
        """Heat, conductances and oils from the bearing's state (absolute coordinates and
        velocities ``q``, ``q_t`` of its nodes) at ``t`` s and the node temperatures ``temps``
        (``in_step``: from the pre-step function, at the step's start)."""
        if not all(np.isfinite(v) for v in temps.values()):
            raise ValueError(f"thermal network: a temperature is not finite at t = {t:.6g} s ({temps})")
        self._next = t + self.update_period
        con = self.connector
        s = con.states(np.array([t]), q[None], q_t[None])
        from ..results.outputs import jet_losses

        losses = place_losses(s, self.setup.cage.guidance,
                              jet_losses(s, con.axis, con.origin, con.cage_record.drag_linear))
        network = bearing_network(self.model, self.geometry, operating_point_of(con, s), self.lubricant,
                                  self.oil_fraction, temps["oil"])
        heat = place_heat(losses)
        set_network(mbs, self.object, network, heat, (self.node, [temps[k] for k in NODES]) if in_step else None)
        con.set_oils(*contact_oils(self.lubricant, temps, self.setup.cage.guidance))
        if in_step:  # (the construction's update: the builder grew the bearing to these temperatures)
            self._grow(t, temps)
        self.updates.append({"time_s": float(t), "losses_W": losses, "heat_W": heat, "temperatures_K": temps,
                             "removed_W": network.to_boundaries(temps), "network": network,
                             "oils": con.oils, "bearing": con.bearing})

    def _grow(self, t, temps) -> None:
        """The contacts' sizes at the node temperatures ``temps`` (MODEL.md §14f). Where they
        would close the clearance (the balls pinched radially, which the free-contact-angle
        geometry cannot hold) the contacts keep the last update's sizes, said once
        (:class:`~exudyn_bearing.errors.ThermalGrowthWarning`; the summary's ``clearance_warning``)."""
        try:
            bearing = heated(self.start.cold, temps).bearing
        except ValueError as err:
            if not self._growth_refused:
                self._growth_refused = True
                warnings.warn(f"thermal network at t = {t:.6g} s: {err}; the contacts keep the sizes of the last "
                              "update", ThermalGrowthWarning, stacklevel=2)
            return
        self.connector.set_geometry(bearing)

    def clearance_change(self, temperatures: dict) -> float:
        """The diametral clearance's change, m, from the run's start (the start temperatures')
        to the bearing grown to ``temperatures`` {node: K} (MODEL.md §14f; the run's contacts
        follow at each update); a ValueError where they close the clearance."""
        grown = heated(self.start.cold, temperatures).bearing
        return grown.diametral_clearance - self.setup.bearing.diametral_clearance

    def history(self, mbs):
        """(times (T,) s, temperatures (T, 7) K in the order of :data:`NODES`) recorded by
        the sensor."""
        data = np.asarray(mbs.GetSensorStoredData(self.sensor))
        if data.ndim != 2 or data.shape[0] == 0:
            raise ValueError("no temperatures recorded yet: run a simulation with sensors stored internally")
        return data[:, 0], data[:, 1:1 + len(NODES)]

    def oils_at(self, time) -> np.ndarray:
        """Per recorded state at ``time`` (s), the index into :attr:`updates` whose oils
        computed it: the last update before it (a state at an update's time ends the step
        before it), the first for the start."""
        starts = np.array([u["time_s"] for u in self.updates])
        return np.maximum(np.searchsorted(starts, np.asarray(time, dtype=float), side="left") - 1, 0)


def add_network(mbs, temperatures) -> tuple:
    """(node, object, sensor): a ``NodeGenericODE1`` with the start ``temperatures`` (K, one
    per network node), its ``ObjectGenericODE1`` with zero rates until :func:`set_network`,
    and a sensor storing the temperatures at every sensor write."""
    import exudyn as exu
    from exudyn.utilities import NodeGenericODE1, ObjectGenericODE1, SensorNode

    n = len(temperatures)
    node = mbs.AddNode(NodeGenericODE1(referenceCoordinates=[0.0] * n, numberOfODE1Coordinates=n,
                                       initialCoordinates=[float(v) for v in temperatures]))
    obj = mbs.AddObject(ObjectGenericODE1(nodeNumbers=[node], systemMatrix=np.zeros((n, n)), rhsVector=np.zeros(n)))
    sensor = mbs.AddSensor(SensorNode(nodeNumber=node, storeInternal=True, writeToFile=False,
                                      outputVariableType=exu.OutputVariableType.Coordinates))
    return node, obj, sensor


def set_network(mbs, obj, network, heat: dict, start=None) -> None:
    """Give the ``ObjectGenericODE1`` ``obj`` the equation of ``network`` (a
    :class:`~contact.thermal_network.ThermalNetwork`) under ``heat`` {node: W}:
    C dT/dt = Q - A T + b (eq. 14.1) as Exudyn's dT/dt = M T + f, M = -A/C, f = (Q + b)/C.

    ``start`` = (node, temperatures K), in a pre-step function: also the step's start rate.
    Exudyn's trapezoid takes it from its store — zero at a solve's start (the first step
    would get half its heat), else the last step's under the old heat."""
    a, b = network.matrix()
    c = network.capacity
    q = network.heat_vector(heat)
    mbs.SetObjectParameter(obj, "systemMatrix", -a / c[:, None])
    mbs.SetObjectParameter(obj, "rhsVector", (q + b) / c)
    if start is not None:
        node, temperatures = start
        rates = np.array(mbs.systemData.GetODE1Coordinates_t())
        at = mbs.GetNodeODE1Index(node)
        rates[at:at + len(c)] = network.rates(temperatures, q)
        mbs.systemData.SetODE1Coordinates_t(rates)


def _coordinates():
    import exudyn as exu

    return exu.OutputVariableType.Coordinates


#: key of the pre-step chain in ``mbs.variables`` (one per system, shared by its bearings)
PRE_STEP_VARIABLE = "exudyn_bearing.model.thermal_nodes"


def install_pre_step(mbs, updater) -> None:
    """Register ``updater(mbs, t)`` in the system's pre-step function (one per system; each
    bearing with temperatures adds its own). A pre-step function the scene set before is
    chained; one set after replaces this (the temperatures then stop being updated)."""
    chain = mbs.variables.get(PRE_STEP_VARIABLE) if hasattr(mbs, "variables") else None
    if chain is None:
        chain = []
        mbs.variables[PRE_STEP_VARIABLE] = chain
        previous = mbs.GetPreStepUserFunction()  # {'function': f, 'type': 'Python'}, or 0 where none
        previous = previous.get("function") if isinstance(previous, dict) else None

        def pre_step(mbs_, t):
            for item in chain:
                item(mbs_, t)
            return previous(mbs_, t) if callable(previous) else True

        mbs.SetPreStepUserFunction(pre_step)
    chain.append(updater)


class ThermalStart(NamedTuple):
    """Where a bearing with temperatures starts (:func:`thermal_start`)."""

    kind: str  #: 'steady' (the thermal steady state) or 'inlet' (every node at the oil inlet)
    temperatures: dict  #: {node: K}
    setup: object  #: the setup with its bearing grown to the temperatures (MODEL.md §14f)
    start_setup: object  #: the same with the start's one oil (the start solvers take one)
    #: the thermal :class:`SteadyState` (axial load) or :class:`AzimuthStates` (combined or radial
    #: load) started from, or None
    steady: object
    geometry: object  #: the network's sizes (:func:`~exudyn_bearing.solvers.thermal.thermal_geometry`, as given)
    cold: object  #: the setup as given (its bearing at the assembly temperature)


def thermal_start(setup, initial_temperatures, *, axial, radial, constant_load, rpm_i, rpm_o, inner_kind,
                  initial_state) -> ThermalStart:
    """The start temperatures of a bearing with a ``thermal`` model (MODEL.md §14g):
    'inlet' puts every node at the oil inlet's temperature (one oil everywhere);
    'steady' the thermal steady state (constant loads, a ``Driven``/``Free`` inner race
    turning forwards): under a pure axial load :func:`~exudyn_bearing.steady_state`'s,
    under combined or radial load :func:`~exudyn_bearing.solvers.quasidynamic.combined_load_state`'s
    (continued as the builder's start, :func:`~exudyn_bearing.solvers.start.steady_start`),
    whose mechanical state the run then starts from (that of the bearing without its
    defects and waviness, which have no steady state); 'auto' (default) 'steady' where it
    applies and converges, else 'inlet'."""
    from ..solvers.quasidynamic import combined_load_state
    from ..solvers.start import continuation_budget, continuation_step
    from ..solvers.steady import steady_state
    from ..solvers.thermal import thermal_geometry

    if initial_temperatures not in ("auto", "steady", "inlet"):
        raise ValueError(f"initialTemperatures must be 'auto', 'steady' or 'inlet', got {initial_temperatures!r}")
    why = None
    if not constant_load:
        why = "it needs constant loads"
    elif not (radial != 0 or axial > 0):
        why = "it needs a load"
    elif axial < 0:
        why = "under radial load it needs an axial load >= 0"
    elif inner_kind not in ("driven", "free") or not rpm_i > 0:
        why = "it needs a Driven or Free inner race turning forwards"
    elif initial_state == "rolling":
        why = "initialState='rolling' asks for the pure-rolling start"
    steady = None
    if why is None and initial_temperatures != "inlet":
        # the perfect bearing's: a surface has no steady state, and its own heat comes with the run
        perfect = setup.replace(surface=SurfaceModel())
        if radial == 0:
            steady = steady_state(perfect, axial_force=axial, rpm=rpm_i, outer_rpm=rpm_o)
        else:
            steady = combined_load_state(perfect, axial_force=axial, radial_force=radial, rpm=rpm_i,
                                         outer_rpm=rpm_o, max_steps=continuation_budget(initial_state),
                                         max_step=lambda seed: continuation_step(seed, axial, radial))
        if not steady.converged:
            why, steady = steady.message, None
    if initial_temperatures == "steady" and steady is None:
        raise ValueError(f"initialTemperatures: no thermal steady state to start from, {why}; use 'inlet'")
    lubricant = setup.lubricant
    if steady is not None:
        temperatures = dict(steady.thermal["temperatures_K"])
        grown = heated(setup, temperatures)
        return ThermalStart("steady", temperatures, grown, grown, steady, thermal_geometry(setup), setup)
    t_in = inlet_temperature(setup.thermal, lubricant)
    temperatures = {name: t_in for name in NODES}
    grown = heated(setup, temperatures)
    return ThermalStart("inlet", temperatures, grown,
                        grown.replace(lubricant=lubricant.at_temperature(t_in - 273.15)), None, thermal_geometry(setup),
                        setup)
