"""The thermal network's physics without Exudyn (MODEL.md §14): closed forms, limits and
conservation, never the code's own output."""
import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from contact.bearing_thermal import HEAT_SPLIT, NODES, OperatingPoint, ThermalModel, bearing_network, place_heat
from contact.heat_transfer import cylinder_conduction, film_conduction, spot_conductance
from contact.lubricant import Lubricant, walther
from contact.thermal_network import ThermalNetwork
from exudyn_bearing import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, REFERENCE_LUBRICANT


def test_a_chain_matches_its_series_resistances():
    """Node a -- G1 -- node b -- G2 -- ambient, heat Q into a: T_b = T0 + Q/G2, T_a = T_b + Q/G1."""
    q, g1, g2, t0 = 37.0, 2.5, 0.8, 300.0
    net = ThermalNetwork(("a", "b"), np.ones(2), {("a", "b"): g1}, {"ambient": t0}, {("b", "ambient"): g2})
    t = net.steady({"a": q})
    assert t["b"] == pytest.approx(t0 + q / g2, rel=1e-12)
    assert t["a"] == pytest.approx(t0 + q / g2 + q / g1, rel=1e-12)
    assert net.to_boundaries(t)["ambient"] == pytest.approx(q, rel=1e-12)


def test_a_random_network_against_a_direct_balance():
    """Kirchhoff's law at every node, written independently of ThermalNetwork.matrix: the net
    heat into each node (source + links) vanishes at the steady temperatures."""
    rng = np.random.default_rng(5)
    names = tuple(f"n{i}" for i in range(6))
    links = {(names[i], names[j]): float(rng.uniform(0.1, 5)) for i in range(6) for j in range(i + 1, 6)
             if rng.random() < 0.6}
    boundary = {"amb": 290.0, "inlet": 350.0}
    blinks = {("n0", "amb"): 1.5, ("n4", "inlet"): 3.0}
    heat = {n: float(rng.uniform(0, 40)) for n in names}
    net = ThermalNetwork(names, np.ones(6), links, boundary, blinks)
    t = net.steady(heat)
    for n in names:
        flow = heat[n]
        for (a, b), g in links.items():
            if n in (a, b):
                other = b if a == n else a
                flow += g * (t[other] - t[n])
        for (a, b), g in blinks.items():
            if a == n:
                flow += g * (boundary[b] - t[n])
        assert abs(flow) < 1e-9 * sum(heat.values())
    removed = net.to_boundaries(t)
    assert sum(removed.values()) == pytest.approx(sum(heat.values()), rel=1e-12)


def test_two_node_transient_has_the_time_constant_c_over_g():
    """One node of capacity C on a boundary through G, heated by Q from T0: T(t) = T_inf -
    (T_inf - T0) exp(-t G / C), T_inf = T_b + Q/G; integrated from the network's rates."""
    c, g, q, tb = 450.0, 3.0, 60.0, 300.0
    net = ThermalNetwork(("ring",), [c], {}, {"ambient": tb}, {("ring", "ambient"): g})
    tau = c / g
    sol = solve_ivp(lambda t, y: net.rates(y, [q]), (0.0, 3 * tau), [tb], rtol=1e-10, atol=1e-10,
                    t_eval=[tau, 2 * tau, 3 * tau])
    t_inf = tb + q / g
    expected = t_inf - (t_inf - tb) * np.exp(-np.array([1.0, 2.0, 3.0]))
    assert np.allclose(sol.y[0], expected, rtol=1e-7)


def test_network_rejects_a_floating_node_and_bad_inputs():
    net = ThermalNetwork(("a", "b"), np.ones(2), {}, {"ambient": 300.0}, {("a", "ambient"): 1.0})
    with pytest.raises(ValueError, match="no path to a boundary"):
        net.steady({"a": 1.0})
    with pytest.raises(ValueError, match="links"):
        ThermalNetwork(("a",), [1.0], {("a", "a"): 1.0}, {"ambient": 300.0}, {})
    with pytest.raises(ValueError, match="capacity"):
        ThermalNetwork(("a",), [0.0], {}, {"ambient": 300.0}, {})
    with pytest.raises(ValueError, match="not a node"):
        net.heat_vector({"c": 1.0})


def test_cylinder_conduction_against_the_integral_of_its_resistance():
    r1, r2, length, k = 0.0175, 0.0205, 0.014, 40.0
    resistance = quad(lambda r: 1.0 / (2 * math.pi * k * r * length), r1, r2)[0]
    assert cylinder_conduction(r1, r2, length, k) == pytest.approx(1.0 / resistance, rel=1e-10)


def test_spot_conductance_has_archards_two_limits():
    """At rest Holm's 4 k r; at high Peclet number Archard's mean temperature 0.308 Q/(k r)
    (kappa/(V r))^(1/2), i.e. G = k r (V r/kappa)^(1/2) / 0.308."""
    k, kappa, r = 40.0, 1.1e-5, 3e-4
    assert float(spot_conductance(r, r, k)) == pytest.approx(4 * k * r, rel=1e-12)
    v = 1e4 * kappa / r  # Peclet V r / kappa = 1e4
    assert float(spot_conductance(r, r, k, v, kappa)) == pytest.approx(k * r * 100 / 0.308, rel=2e-3)
    # an ellipse as the circle of equal area; across the film k pi a b / h
    assert float(spot_conductance(4 * r, r / 4, k)) == pytest.approx(4 * k * r, rel=1e-12)
    assert float(film_conduction(2e-4, 1e-4, 5e-7, 0.15)) == pytest.approx(0.15 * math.pi * 2e-8 / 5e-7, rel=1e-12)


def test_heat_into_the_nodes_equals_the_losses():
    losses = {"inner_contacts": 143.7, "outer_contacts": 12.25, "rolling_resistance": 612.5, "ball_drag": 440.3,
              "land_outer": 69.4, "pockets": 3.3, "land_inner": 0.0}
    heat = place_heat(losses)
    assert set(heat) == set(NODES)
    assert sum(heat.values()) == pytest.approx(sum(losses.values()), rel=1e-12)
    for place, shares in HEAT_SPLIT.items():
        assert sum(shares.values()) == pytest.approx(1.0, abs=1e-15)
    with pytest.raises(ValueError, match="no heat split"):
        place_heat({"bearing": 1.0})


def test_walther_reproduces_the_oils_data_sheet_and_its_preset():
    """ESTER_TURBINE_OIL: 27.6 cSt at 40 degC, 5.1 cSt at 100 degC (the data points), and at
    121 degC 3.5 cSt x 919 kg/m^3 = 3.2 mPa s with slope 0.016 1/K, as its preset states
    (the preset's own values, computed from ASTM D341 when it was made); the oil at another
    temperature keeps its own viscosity at its reference and Walther's ratio elsewhere."""
    for t, nu in ((40.0, 27.6e-6), (100.0, 5.1e-6)):
        assert walther(27.6e-6, 5.1e-6, t)[0] == pytest.approx(nu, rel=1e-10)
    assert walther(27.6e-6, 5.1e-6, 121.0)[0] * 919.0 == pytest.approx(3.2e-3, rel=0.01)
    oil = ESTER_TURBINE_OIL.at_temperature(121.0)
    assert oil.viscosity == pytest.approx(ESTER_TURBINE_OIL.viscosity, rel=1e-12)
    assert oil.temperature_viscosity == pytest.approx(ESTER_TURBINE_OIL.temperature_viscosity, rel=0.01)
    ratio = walther(27.6e-6, 5.1e-6, 100.0)[0] / walther(27.6e-6, 5.1e-6, 121.0)[0]
    assert ESTER_TURBINE_OIL.at_temperature(100.0).viscosity == pytest.approx(3.2e-3 * ratio, rel=1e-12)
    # the local slope is the derivative of ln(nu): central difference
    h = 0.01
    slope = -(math.log(walther(27.6e-6, 5.1e-6, 121 + h)[0]) - math.log(walther(27.6e-6, 5.1e-6, 121 - h)[0])) / (2 * h)
    assert oil.temperature_viscosity == pytest.approx(slope, rel=1e-6)


def test_an_oil_without_walther_points_follows_its_exponential_law():
    oil = REFERENCE_LUBRICANT.at_temperature(55.0)
    assert oil.viscosity == pytest.approx(0.04 * math.exp(-0.05 * 25.0), rel=1e-12)
    assert oil.temperature_viscosity == REFERENCE_LUBRICANT.temperature_viscosity
    assert oil.reference_temperature == 55.0


@pytest.mark.parametrize("kwargs, name", [
    ({"kinematic_viscosity_40": 30e-6}, "kinematic_viscosity_40, kinematic_viscosity_100"),
    ({"kinematic_viscosity_40": 5e-6, "kinematic_viscosity_100": 6e-6}, "kinematic_viscosity_40 must exceed"),
    ({"kinematic_viscosity_100": -1e-6, "kinematic_viscosity_40": 3e-5}, "kinematic_viscosity_100"),
])
def test_bad_walther_points_are_refused_by_name(kwargs, name):
    base = dict(viscosity=0.01, reference_temperature=40.0, pressure_viscosity=2e-8, temperature_viscosity=0.03,
                thermal_conductivity=0.14, density=870.0)
    with pytest.raises(ValueError, match=name):
        Lubricant(**base, **kwargs)


@pytest.mark.parametrize("kwargs, name", [
    ({"oil_inlet_temperature": 121.0}, "oil_inlet_temperature is in kelvin"),
    ({"oil_flow": -1e-5}, "oil_flow"),
    ({"ambient_temperature": float("nan")}, "ambient_temperature"),
    ({"bore": 0.0}, "bore"),
])
def test_bad_thermal_inputs_are_refused_by_name(kwargs, name):
    with pytest.raises(ValueError, match=name):
        ThermalModel(**kwargs)


def test_impossible_ring_sizes_are_refused_by_name():
    b = HIGH_SPEED_35MM_BEARING
    with pytest.raises(ValueError, match="bore"):
        ThermalModel(bore=45e-3).geometry(b, 0.01)
    with pytest.raises(ValueError, match="outside_diameter"):
        ThermalModel(outside_diameter=48e-3).geometry(b, 0.01)


def test_the_oil_carries_off_rho_v_cp_per_kelvin():
    """With the rest insulated, all heat leaves with the oil: T_oil - T_in = Q / (rho V c_p)."""
    b = HIGH_SPEED_35MM_BEARING
    model = ThermalModel(oil_flow=1.2667e-5, oil_inlet_temperature=394.0, ambient_convection=1e-12)
    geometry = model.geometry(b, 0.01)._replace(
        shaft_length=1e12)
    point = OperatingPoint(7540.0, 0.0, 3300.0, 40000.0, (1e-3, 1e-4, 5e-7, 80.0), (1.2e-3, 1.5e-4, 5e-7, 90.0))
    net = bearing_network(model, geometry, point, ESTER_TURBINE_OIL, 0.005, 394.0)
    q = 800.0
    t = net.steady({"balls": q})
    rho_v_cp = 1.2667e-5 * ESTER_TURBINE_OIL.density * model.oil_specific_heat
    assert t["oil"] - 394.0 == pytest.approx(q / rho_v_cp, rel=1e-6)
    assert all(t[n] > t["oil"] for n in ("balls", "inner_ring", "outer_ring"))
