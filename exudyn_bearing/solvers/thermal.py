"""The steady state with its temperatures: the steady balance (MODEL.md §12), or the
quasi-dynamic one under combined load (§12a), and the bearing's thermal network (§14) iterated
to a fixed point, heat -> temperatures -> viscosities -> heat.

Each ball–race contact takes its oil at the mean of its race's and the balls' temperatures,
the cage land at the mean of the cage's and its guiding ring's (Walther's relation or the
lubricant's exponential law, :meth:`contact.lubricant.Lubricant.at_temperature`).
"""
from __future__ import annotations

import math
import time as _time
from typing import NamedTuple

import numpy as np

from contact.bearing_thermal import NODES, OperatingPoint, bearing_network, inlet_temperature, place_heat
from contact.thermal_expansion import heated_geometry
from .steady_balance import solve_steady, steady_result
from .steady_power import steady_losses

__all__ = ["thermal_steady_state", "fixed_point", "FixedPointPass", "thermal_geometry", "contact_oils", "heated",
           "axial_pressing", "TEMPERATURE_TOLERANCE_K", "MAX_ITERATIONS"]

#: the fixed point is reached when no node's temperature changes by more than this, K
TEMPERATURE_TOLERANCE_K = 0.01
#: fixed-point iterations before the solver gives up (converging runs took 5–12)
MAX_ITERATIONS = 60


def contact_oils(lubricant, temperatures: dict, guidance: str) -> tuple:
    """(inner contact's, outer contact's, cage land's) lubricant at the node ``temperatures``
    (K): each at the mean of the two surfaces that shear it (MODEL.md §14b)."""
    def at(a, b):
        return lubricant.at_temperature(0.5 * (temperatures[a] + temperatures[b]) - 273.15)

    ring = "outer_ring" if guidance == "outer" else "inner_ring"
    return at("inner_ring", "balls"), at("outer_ring", "balls"), at("cage", ring)


def operating_point(solved) -> OperatingPoint:
    """The speeds and contact sizes the network's conductances depend on (eq. 14.4, 14.5)."""
    ball = solved.ball
    w_c, w_b, _, _ = ball.unpack(solved.x)
    kin, f = ball.contacts(solved.x)
    _, hertz = ball.params.hertz(kin.contact_angle, ball.law.hertz_method)
    a, b = hertz.semi_axes(f.normal_load)
    contacts = [(float(a[k]), float(b[k]), float(f.film_thickness[k]), abs(float(kin.entrainment[k])))
                for k in (0, 1)]
    return OperatingPoint(solved.w_i, solved.w_o, float(w_c), float(np.linalg.norm(w_b)), *contacts)


def thermal_geometry(setup):
    """The network's :class:`~contact.bearing_thermal.ThermalGeometry` of ``setup`` (its
    bearing, cage mass and guiding land)."""
    bearing, cage = setup.bearing, setup.cage
    land = None
    if cage.guided and cage.land_width > 0:
        land = (cage.guidance, cage.land_radius_for(bearing), float(cage.land_width), 0.5 * float(cage.guide_clearance))
    return setup.thermal.geometry(bearing, cage.mass_for(bearing), land)


def heated(setup, temperatures: dict):
    """``setup`` with its bearing grown to the node ``temperatures`` (K) from the thermal
    model's assembly temperature (MODEL.md §14f); a ValueError where that closes the clearance."""
    m = setup.thermal
    return setup.replace(bearing=setup.bearing.expanded(*_rises(m, temperatures), m.ring_expansion, m.ball_expansion))


def axial_pressing(setup, temperatures: dict) -> float:
    """δ_a = A sin α0 − A' sin α0', m: how much further rings held at their axial places since
    assembly press the balls once ``setup``'s bearing is grown to the node ``temperatures`` (K)
    (MODEL.md §14f, eq. 14.9); a ValueError where the growth closes the clearance."""
    m, b = setup.thermal, setup.bearing
    return heated_geometry(b.ball_diameter, b.pitch_diameter, b.contact_angle, b.inner_conformity,
                           b.outer_conformity, *_rises(m, temperatures), m.ring_expansion,
                           m.ball_expansion).axial_interference


def _rises(model, temperatures: dict) -> tuple:
    """(inner ring, outer ring, balls) temperature rises above the assembly temperature, K."""
    return tuple(temperatures[k] - model.assembly_temperature for k in ("inner_ring", "outer_ring", "balls"))


class FixedPointPass(NamedTuple):
    """One balance solved at a fixed point iterate's temperatures (:func:`fixed_point`)."""

    state: object  #: what the balance's solver returned
    failure: str | None  #: why it has no state to use (None: converged)
    losses: dict | None  #: W by place (HEAT_SPLIT's names), where converged
    point: OperatingPoint | None  #: the network's operating point, where converged


def fixed_point(setup, solve) -> tuple:
    """The bearing's balance and thermal network iterated to a fixed point (MODEL.md §14d):
    ``solve(running, oils)`` solves the balance of ``running`` (``setup`` grown to the
    iterate's temperatures) with the (inner, outer, land) ``oils`` and returns a :class:`FixedPointPass`.
    Returns (the last pass's state, why it is not a result or None, the ``thermal`` record)."""
    model, lubricant = setup.thermal, setup.lubricant
    geometry = thermal_geometry(setup)
    oil_fraction = 1.0 if setup.drag is None else setup.drag.oil_volume_fraction
    t_in = inlet_temperature(model, lubricant)
    temperatures = {name: t_in for name in NODES}
    relax, last_change, history, solved = 1.0, math.inf, [], None
    for iteration in range(1, MAX_ITERATIONS + 1):
        oils = contact_oils(lubricant, temperatures, setup.cage.guidance)
        try:
            running = heated(setup, temperatures)
        except ValueError as err:  # the clearance closed: no steady state at these temperatures
            if solved is None:  # already at the inlet temperature: no state to report, the error says why
                raise
            why, grown = err, None
        else:
            solved = solve(running, oils)
            why, grown = solved.failure, running.bearing
        if why is not None:
            return solved.state, f"thermal iteration {iteration}: {why}", _record(
                None, None, temperatures, oils, iteration, False, history, bearing=grown)
        losses = solved.losses
        network = bearing_network(model, geometry, solved.point, lubricant, oil_fraction, temperatures["oil"])
        new = network.steady(place_heat(losses))
        change = max(abs(new[k] - temperatures[k]) for k in NODES)
        history.append(change)
        if change < TEMPERATURE_TOLERANCE_K:
            temperatures = new
            break
        if change > last_change:  # oscillating: damp the update
            relax = max(0.25 * relax, 0.05)
        last_change = change
        temperatures = {k: temperatures[k] + relax * (new[k] - temperatures[k]) for k in NODES}
        if not all(math.isfinite(v) for v in temperatures.values()):
            raise ValueError(f"the thermal fixed point diverged at iteration {iteration} "
                             f"(temperatures {temperatures})")
    converged = history[-1] < TEMPERATURE_TOLERANCE_K
    failure = None if converged else (f"thermal fixed point not reached in {MAX_ITERATIONS} iterations "
                                      f"(last change {history[-1]:.3g} K)")
    record = _record(network, losses, temperatures, oils, len(history), converged, history,
                     bearing=running.bearing, cold=setup.bearing)
    return solved.state, failure, record


def thermal_steady_state(setup, axial_force, rpm, outer_rpm, tol, start, inputs):
    """The :class:`~exudyn_bearing.solvers.steady.SteadyState` of ``setup`` (with its
    ``thermal`` model) and its temperatures (MODEL.md §14d); called by
    :func:`~exudyn_bearing.steady_state` with checked inputs."""
    def solve(running, oils):
        inner, outer, land = oils
        solved = solve_steady(running, axial_force, rpm, outer_rpm, tol, races=(inner, outer), land_lubricant=land)
        if not solved.converged:
            return FixedPointPass(solved, solved.message, None, None)
        return FixedPointPass(solved, None, steady_losses(solved), operating_point(solved))

    solved, failure, record = fixed_point(setup, solve)
    if failure is not None:
        solved = solved._replace(converged=False, message=failure)
    return steady_result(solved, _time.perf_counter() - start, inputs, thermal=record)


def _record(network, losses, temperatures, oils, iterations, converged, history, *, bearing, cold=None) -> dict:
    """The SteadyState's ``thermal`` dictionary (JSON-ready, units by suffix); ``bearing`` the
    geometry at the temperatures (None where the clearance closed), ``cold`` as given."""
    out = {"temperatures_K": dict(temperatures),
           "contact_oil_temperature_K": {k: oil.reference_temperature + 273.15
                                         for k, oil in zip(("inner", "outer", "land"), oils)},
           "contact_viscosity_Pa_s": {k: oil.viscosity for k, oil in zip(("inner", "outer", "land"), oils)},
           "iterations": iterations, "converged": converged, "temperature_change_K": [float(v) for v in history]}
    if bearing is not None:
        out["running_geometry"] = {"free_contact_angle_deg": math.degrees(bearing.contact_angle),
                                   "diametral_clearance_m": bearing.diametral_clearance,
                                   "ball_diameter_m": bearing.ball_diameter, "pitch_diameter_m": bearing.pitch_diameter}
        if cold is not None:
            out["running_geometry"]["diametral_clearance_change_m"] = (bearing.diametral_clearance
                                                                       - cold.diametral_clearance)
    if network is None:
        return out
    heat = place_heat(losses)
    removed = network.to_boundaries(temperatures)
    made = sum(losses.values())
    out |= {"heat_W": heat, "heat_by_place_W": {place: float(w) for place, w in losses.items()},
            "removed_W": removed,
            "heat_balance_percent": 100.0 * (made - sum(removed.values())) / made if made > 0 else 0.0,
            "conductance_W_per_K": {f"{a}-{b}": float(g) for (a, b), g in
                                    (network.links | network.boundary_links).items()},
            "oil_inlet_K": network.boundary["oil_inlet"]}
    return out
