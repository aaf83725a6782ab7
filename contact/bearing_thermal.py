"""A ball bearing's thermal network: its inputs, nodes, conductances from geometry and
correlations, and where each loss's heat goes (MODEL.md §14).

Nodes: shaft, inner ring, balls (all together), cage, outer ring, housing, oil (the
cavity's oil, leaving at its temperature); boundaries: the ambient air and the oil inlet.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .heat_transfer import (cylinder_conduction, enthalpy_flow, film_conduction, mixture_properties, plate_convection,
                            rod_conduction, spot_conductance)
from .lubricant import _check_positive
from .thermal_network import ThermalNetwork

__all__ = ["ThermalModel", "ThermalGeometry", "OperatingPoint", "NODES", "HEAT_SPLIT", "bearing_network",
           "mean_contact", "place_heat", "inlet_temperature"]

NODES = ("shaft", "inner_ring", "balls", "cage", "outer_ring", "housing", "oil")

#: where each loss's heat goes, {location: {node: share}} (MODEL.md §14c): the traction and
#: spin heat of a ball–race contact half to the ball, half to the race; drag and the rolling
#: resistance's inlet shear heat the oil (both as in ADORE-V2's network, kernel.jl), and so does
#: the jet oil's momentum loss (MODEL.md §11c: all of it, a choice); the land's
#: shear half the cage, half the guiding ring; the pocket's friction half the balls, half the cage
HEAT_SPLIT = {
    "inner_contacts": {"balls": 0.5, "inner_ring": 0.5},
    "outer_contacts": {"balls": 0.5, "outer_ring": 0.5},
    "rolling_resistance": {"oil": 1.0},
    "ball_drag": {"oil": 1.0},
    "jet_momentum": {"oil": 1.0},
    "land_outer": {"cage": 0.5, "outer_ring": 0.5},
    "land_inner": {"cage": 0.5, "inner_ring": 0.5},
    "pockets": {"balls": 0.5, "cage": 0.5},
}


@dataclass(frozen=True)
class ThermalModel:
    """Inputs of a bearing's thermal network (the bearing file's ``[thermal]``; SI units,
    temperatures in kelvin; MODEL.md §14). Sizes left at None are estimated from the
    bearing (:meth:`geometry`).

    Parameters
    ----------
    oil_flow : float
        Oil through the bearing, m^3/s (jet or circulation; default 1e-5, 0.6 L/min).
    oil_inlet_temperature : float or None
        K; None: the lubricant's reference temperature.
    ambient_temperature : float
        Air around the housing and the shaft's far end, K (293.15).
    oil_specific_heat : float
        c_p of the oil, J/(kg K) (2000: mineral and ester oils at 40–120 degC lie within
        1.8–2.2 kJ/(kg K)).
    bore, outside_diameter, width : float or None
        The rings' sizes, m; None: d_m -/+ 1.7 D and 1.8 D (the 6205, 7007 and 7207 lie
        within 5 % of those).
    housing_outside_diameter, housing_width : float or None
        A steel housing ring, m; None: twice the bearing's.
    shaft_length : float or None
        Solid steel shaft of the bore's diameter from the bearing to where it is held at
        ambient, m; None: five widths.
    steel_conductivity, steel_specific_heat : float
        W/(m K), J/(kg K) of rings, balls, shaft, housing (40 and 460: bearing steels).
    ambient_convection : float
        Housing surface to still air, W/(m^2 K) (10: natural convection, 2–25).
    assembly_temperature : float
        K at which the bearing's dimensions are given (293.15); the rings and balls grow
        from it (MODEL.md §14f).
    ring_expansion, ball_expansion : float
        Linear thermal expansion coefficients of the rings and balls, 1/K (11.9e-6: AISI
        52100; silicon nitride balls 2.8e-6; 0: no growth).
    """

    oil_flow: float = 1e-5
    oil_inlet_temperature: float | None = None
    ambient_temperature: float = 293.15
    oil_specific_heat: float = 2000.0
    bore: float | None = None
    outside_diameter: float | None = None
    width: float | None = None
    housing_outside_diameter: float | None = None
    housing_width: float | None = None
    shaft_length: float | None = None
    steel_conductivity: float = 40.0
    steel_specific_heat: float = 460.0
    ambient_convection: float = 10.0
    assembly_temperature: float = 293.15
    ring_expansion: float = 11.9e-6
    ball_expansion: float = 11.9e-6

    def __post_init__(self) -> None:
        for name in ("oil_flow", "ambient_temperature", "oil_specific_heat", "steel_conductivity",
                     "steel_specific_heat", "ambient_convection"):
            _check_positive(name, getattr(self, name))
        for name in ("oil_inlet_temperature", "bore", "outside_diameter", "width", "housing_outside_diameter",
                     "housing_width", "shaft_length"):
            if getattr(self, name) is not None:
                _check_positive(name, getattr(self, name))
        for name in ("ring_expansion", "ball_expansion"):
            _check_positive(name, getattr(self, name), allow_zero=True)
            if getattr(self, name) > 1e-4:
                raise ValueError(f"{name} is a linear expansion coefficient in 1/K (steel 1.2e-5), got "
                                 f"{getattr(self, name)!r}")
        _check_positive("assembly_temperature", self.assembly_temperature)
        for name in ("oil_inlet_temperature", "ambient_temperature", "assembly_temperature"):
            value = getattr(self, name)
            if value is not None and not 200.0 < value < 1000.0:
                raise ValueError(f"{name} is in kelvin and must lie in (200, 1000) K, got {value!r}")

    def geometry(self, bearing, cage_mass: float, land=None) -> "ThermalGeometry":
        """The network's :class:`ThermalGeometry` of ``bearing`` (a record with ``balls``,
        ``ball_diameter`` and ``pitch_diameter`` m, ``contact_angle`` rad, as
        :class:`exudyn_bearing.Bearing`), its cage's mass (kg) and its guiding ``land`` =
        (guidance 'outer'/'inner', radius m, width m, radial play m) or None."""
        balls, contact_angle = bearing.balls, bearing.contact_angle
        d_m, d = bearing.pitch_diameter, bearing.ball_diameter
        bore = self.bore or d_m - 1.7 * d
        outside = self.outside_diameter or d_m + 1.7 * d
        width = self.width or 1.8 * d
        r_in = 0.5 * (d_m - d * math.cos(contact_angle))
        r_out = 0.5 * (d_m + d * math.cos(contact_angle))
        if not 0 < 0.5 * bore < r_in:
            raise ValueError(f"bore must lie inside the inner raceway (diameter < {2 * r_in!r} m), got {bore!r}")
        if not 0.5 * outside > r_out:
            raise ValueError(f"outside_diameter must exceed the outer raceway's {2 * r_out!r} m, got {outside!r}")
        housing = self.housing_outside_diameter or 2.0 * outside
        if housing <= outside:
            raise ValueError(f"housing_outside_diameter must exceed outside_diameter {outside!r} m, got {housing!r}")
        return ThermalGeometry(int(balls), d, d_m, 0.5 * bore, r_in, r_out, 0.5 * outside, width, 0.5 * housing,
                               self.housing_width or 2.0 * width, self.shaft_length or 5.0 * width, float(cage_mass),
                               land)


class ThermalGeometry(NamedTuple):
    """Sizes the network is built from, m and kg (:meth:`ThermalModel.geometry`)."""

    balls: int
    ball_diameter: float
    pitch_diameter: float
    bore_radius: float
    inner_raceway_radius: float  #: contact radius on the inner ring at the free angle
    outer_raceway_radius: float
    outside_radius: float
    width: float
    housing_radius: float
    housing_width: float
    shaft_length: float
    cage_mass: float
    land: tuple | None  #: (guidance, radius m, width m, radial play m) of a guiding land


class OperatingPoint(NamedTuple):
    """What the conductances depend on (SI): race and cage speeds rad/s, the balls' spin
    speed |omega_b| rad/s, and of the inner and outer contact (semi-axes a, b m, central
    film m, rolling speed m/s)."""

    inner_speed: float
    outer_speed: float
    cage_speed: float
    ball_spin: float
    inner_contact: tuple
    outer_contact: tuple


def mean_contact(a, b, film, speed, load) -> tuple:
    """One race's contact for :class:`OperatingPoint`: the mean semi-axes a, b (m), central
    film (m) and rolling speed (m/s) of its loaded contacts (``load`` > 0, N); zeros where
    none is loaded."""
    loaded = np.asarray(load) > 0.0
    if not np.any(loaded):
        return 0.0, 0.0, 0.0, 0.0
    return tuple(float(np.mean(np.asarray(v)[loaded])) for v in (a, b, film, speed))


def bearing_network(model: ThermalModel, geometry: ThermalGeometry, point: OperatingPoint, lubricant,
                    oil_fraction: float, oil_temperature: float) -> ThermalNetwork:
    """The bearing's :class:`~contact.thermal_network.ThermalNetwork` at an operating point
    (MODEL.md §14a, eqs. 14.2–14.7). ``lubricant`` (a :class:`contact.lubricant.Lubricant`)
    at the oil node's ``oil_temperature`` (K) gives the cavity fluid with the oil volume
    fraction ``oil_fraction`` of the oil–air mixture."""
    g, k_s, c_s = geometry, model.steel_conductivity, model.steel_specific_heat
    rho_s = 7800.0  # bearing steels 7.75–7.85 t/m^3
    z, d = g.balls, g.ball_diameter
    # heat capacities, J/K (eq. 14.8): steel annuli and spheres; the cavity's oil film
    ring_in = math.pi * (g.inner_raceway_radius ** 2 - g.bore_radius ** 2) * g.width
    ring_out = math.pi * (g.outside_radius ** 2 - g.outer_raceway_radius ** 2) * g.width
    housing = math.pi * (g.housing_radius ** 2 - g.outside_radius ** 2) * g.housing_width
    shaft = math.pi * g.bore_radius ** 2 * g.shaft_length
    balls = z * math.pi * d ** 3 / 6.0
    oil = lubricant.at_temperature(oil_temperature - 273.15)
    fluid = mixture_properties(oil_fraction, oil.density, oil.viscosity, oil.thermal_conductivity,
                               model.oil_specific_heat)
    cavity = math.pi * (g.outer_raceway_radius ** 2 - g.inner_raceway_radius ** 2) * g.width - balls
    capacity = [rho_s * c_s * v for v in (shaft, ring_in, balls)]
    capacity += [max(g.cage_mass, 1e-6) * 380.0]  # brass or bronze 380 J/(kg K)
    capacity += [rho_s * c_s * ring_out, rho_s * c_s * housing,
                 max(fluid["density"] * fluid["specific_heat"] * cavity, 1e-3)]
    # convection in the cavity (eq. 14.5): the mixture turns at the mean of the race speeds
    # (Couette flow between the rings); each ball passage restarts the boundary layer
    w_fluid = 0.5 * (point.inner_speed + point.outer_speed)
    pitch_length = math.pi * g.pitch_diameter / z

    def h(speed, length):
        return plate_convection(abs(speed), length, fluid["conductivity"], fluid["kinematic_viscosity"],
                                fluid["prandtl"])

    area_ring_in = 2.0 * math.pi * g.inner_raceway_radius * g.width
    area_ring_out = 2.0 * math.pi * g.outer_raceway_radius * g.width
    area_cage = 2.0 * 2.0 * math.pi * 0.5 * g.pitch_diameter * 0.8 * g.width
    links = {
        ("shaft", "inner_ring"): cylinder_conduction(g.bore_radius, g.inner_raceway_radius, g.width, k_s),
        ("outer_ring", "housing"): 1.0 / (1.0 / cylinder_conduction(g.outer_raceway_radius, g.outside_radius,
                                                                      g.width, k_s)
                                          + 1.0 / cylinder_conduction(g.outside_radius, g.housing_radius,
                                                                      g.housing_width, k_s)),
        # each ball touches each race once: ball side, film and race side in series (eq. 14.4)
        ("inner_ring", "balls"): z * _contact_conductance(point.inner_contact, k_s, k_s / (rho_s * c_s), oil),
        ("outer_ring", "balls"): z * _contact_conductance(point.outer_contact, k_s, k_s / (rho_s * c_s), oil),
        ("inner_ring", "oil"): h((point.inner_speed - w_fluid) * g.inner_raceway_radius, pitch_length) * area_ring_in,
        ("outer_ring", "oil"): h((point.outer_speed - w_fluid) * g.outer_raceway_radius, pitch_length) * area_ring_out,
        ("balls", "oil"): h(point.ball_spin * 0.5 * d, math.pi * d / 2.0) * z * math.pi * d ** 2,
        ("cage", "oil"): h((point.cage_speed - w_fluid) * 0.5 * g.pitch_diameter, pitch_length) * area_cage,
    }
    if g.land is not None:  # conduction across the land's oil film
        guidance, radius, width, play = g.land
        links[("cage", f"{guidance}_ring")] = oil.thermal_conductivity * 2.0 * math.pi * radius * width / play
    boundary = {"ambient": model.ambient_temperature, "oil_inlet": inlet_temperature(model, lubricant)}
    area_housing = (2.0 * math.pi * g.housing_radius * g.housing_width
                    + 2.0 * math.pi * (g.housing_radius ** 2 - g.outside_radius ** 2))
    boundary_links = {
        ("housing", "ambient"): model.ambient_convection * area_housing,
        ("shaft", "ambient"): rod_conduction(g.bore_radius, g.shaft_length, k_s),
        # the oil carries rho V c_p (T_oil - T_in) off (eq. 14.7)
        ("oil", "oil_inlet"): enthalpy_flow(model.oil_flow, oil.density, model.oil_specific_heat),
    }
    return ThermalNetwork(NODES, capacity, links, boundary, boundary_links)


def _contact_conductance(contact, conductivity, diffusivity, oil) -> float:
    """One ball–race contact, W/K: the spot into the ball, across the film, into the race."""
    a, b, film, speed = contact
    if a <= 0 or b <= 0:
        return 0.0
    spot = float(spot_conductance(a, b, conductivity, speed, diffusivity))
    return 1.0 / (2.0 / spot + 1.0 / float(film_conduction(a, b, film, oil.thermal_conductivity)))


def inlet_temperature(model: ThermalModel, lubricant) -> float:
    """The oil's inlet temperature, K: the model's, else the lubricant's reference."""
    if model.oil_inlet_temperature is not None:
        return float(model.oil_inlet_temperature)
    return float(lubricant.reference_temperature) + 273.15


def place_heat(losses: dict) -> dict:
    """{node: W} of the losses {location: W} by :data:`HEAT_SPLIT` (MODEL.md §14c); an
    unknown location raises ValueError. The shares of each location sum to one, so the
    heat into the nodes equals the losses."""
    heat = {name: 0.0 for name in NODES}
    for location, watts in losses.items():
        if location not in HEAT_SPLIT:
            raise ValueError(f"place_heat: no heat split for {location!r} (known: {', '.join(HEAT_SPLIT)})")
        for node, share in HEAT_SPLIT[location].items():
            heat[node] += share * watts
    return heat
