"""The steady state's power balance and its thermal fixed point (MODEL.md §12, §14), from the
Python API, a bearing file and the CLI, on the reference, 35-mm high-speed, 40-mm spindle and
6205 deep-groove bearings."""
import dataclasses
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from contact.bearing_thermal import ThermalModel
from exudyn_bearing import (Bearing, CWRU_6205_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG,
                            SPINDLE_40MM_BEARING, BearingSetup, CageModel, ContactLaw, dumps_bearing, loads_bearing,
                            solve_load_distribution, steady_state)

LAW = ContactLaw(rolling_resistance=True, thermal_film=True)
CAGE = CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3, pocket_friction=0.1)
#: NASA TP-2275's jet: 760 cm^3/min at 394 K
TP2275 = ThermalModel(oil_flow=760e-6 / 60, oil_inlet_temperature=394.0, bore=35e-3)
HIGH_SPEED = BearingSetup(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, CAGE, LAW)


@pytest.mark.parametrize("setup, axial, rpm", [
    (None, 1300.0, 1800.0),  # the reference bearing (default setup)
    (HIGH_SPEED, 667.0, 48000.0),
    (BearingSetup(SPINDLE_40MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, CAGE, LAW), 1000.0, 20000.0),
])
def test_the_drive_power_equals_the_losses(setup, axial, rpm):
    """Nothing accelerates in a steady state: the races' drive power (from their torques) equals
    the losses (each force's power against the motion it resists), computed independently."""
    state = steady_state(*(() if setup is None else (setup,)), axial_force=axial, rpm=rpm)
    assert state.converged
    loss = state.power_loss_W
    assert loss["total"] == pytest.approx(sum(v for k, v in loss.items() if k != "total"), rel=1e-12)
    # within the power of the balance's residual (1e-8 of the contact force scale, ~1e-5 here)
    assert state.drive_power_W == pytest.approx(loss["total"], rel=2e-5)
    if setup is not None:  # every source on
        assert min(loss[k] for k in ("traction", "rolling_resistance", "ball_drag", "cage")) > 0


def test_an_oil_whose_viscosity_ignores_temperature_gives_the_isothermal_state():
    """The thermal path's per-race oils with c_etaT -> 0 are the lubricant itself: the state
    must equal the isothermal one (the plumbing of per-contact oils, land and losses)."""
    flat = dataclasses.replace(ESTER_TURBINE_OIL, temperature_viscosity=1e-12, kinematic_viscosity_40=0.0,
                               kinematic_viscosity_100=0.0)
    setup = HIGH_SPEED.replace(lubricant=flat)
    iso = steady_state(setup, axial_force=667.0, rpm=28000.0)
    rigid = dataclasses.replace(TP2275, ring_expansion=0.0, ball_expansion=0.0)  # the geometry as given
    hot = steady_state(setup.replace(thermal=rigid), axial_force=667.0, rpm=28000.0)
    assert hot.converged and hot.thermal["converged"]
    assert hot.thermal["temperatures_K"]["balls"] > 394.0 + 5.0  # it did heat up
    assert hot.kinematic_cage_slip_percent == pytest.approx(iso.kinematic_cage_slip_percent, rel=1e-7)
    for k, v in iso.power_loss_W.items():
        assert hot.power_loss_W[k] == pytest.approx(v, rel=1e-7, abs=1e-9)


def test_the_hot_bearing_balances_its_heat_and_loses_less_than_the_cold_one():
    cold = steady_state(HIGH_SPEED, axial_force=667.0, rpm=72000.0)
    state = steady_state(HIGH_SPEED.replace(thermal=TP2275), axial_force=667.0, rpm=72000.0)
    th = state.thermal
    assert state.converged and th["converged"]
    made = state.power_loss_W["total"]
    assert sum(th["heat_W"].values()) == pytest.approx(made, rel=1e-9)
    assert sum(th["heat_by_place_W"].values()) == pytest.approx(made, rel=1e-9)
    assert sum(th["removed_W"].values()) == pytest.approx(made, rel=1e-3)
    assert abs(th["heat_balance_percent"]) < 0.1
    temps = th["temperatures_K"]
    assert min(temps.values()) > 293.15 and temps["oil"] > 394.0
    # the oil heats by what it carries off over rho V c_p (eq. 14.7)
    rho_v_cp = TP2275.oil_flow * ESTER_TURBINE_OIL.density * TP2275.oil_specific_heat
    assert temps["oil"] - 394.0 == pytest.approx(th["removed_W"]["oil_inlet"] / rho_v_cp, rel=1e-9)
    # thinner oil at the contacts: less rolling resistance and traction than at the inlet's viscosity
    assert th["contact_viscosity_Pa_s"]["outer"] < ESTER_TURBINE_OIL.viscosity
    assert state.power_loss_W["rolling_resistance"] < cold.power_loss_W["rolling_resistance"]
    assert made < cold.power_loss_W["total"]
    data = state.to_dict()
    assert data["units"]["thermal"]["temperatures_K"]["balls"] == "K"
    assert data["units"]["thermal"]["contact_viscosity_Pa_s"]["inner"] == "Pa s"
    assert json.loads(json.dumps(data))["thermal"]["removed_W"]["oil_inlet"] > 0


def test_a_deep_groove_bearing_reaches_its_thermal_fixed_point():
    """The 6205 with 15 um of diametral clearance (a normal clearance for its size) under
    [thermal]: the fixed point, its heat balance, and the clearance it runs with (eq. 14.9)
    equal to Harris's ΔP_d = α(ΔT_o d_o − ΔT_i d_i − 2 ΔT_b D) at its node temperatures."""
    fields = {f.name: getattr(CWRU_6205_BEARING, f.name) for f in dataclasses.fields(CWRU_6205_BEARING)
              if f.name != "contact_angle"}
    with_play = Bearing.from_clearance(diametral_clearance=15e-6, **fields)
    model = ThermalModel(oil_inlet_temperature=313.15)
    state = steady_state(BearingSetup(with_play, thermal=model), axial_force=300.0, rpm=1800.0)
    assert state.converged and state.thermal["converged"]
    assert abs(state.thermal["heat_balance_percent"]) < 0.1
    assert state.drive_power_W == pytest.approx(state.power_loss_W["total"], rel=2e-5)
    t = {k: v - model.assembly_temperature for k, v in state.thermal["temperatures_K"].items()}
    b = with_play
    d_i = b.pitch_diameter - b.ball_diameter * (2 * b.inner_conformity - (2 * b.inner_conformity - 1)
                                                * np.cos(b.contact_angle))
    d_o = b.pitch_diameter + b.ball_diameter * (2 * b.outer_conformity - (2 * b.outer_conformity - 1)
                                                * np.cos(b.contact_angle))
    harris = model.ring_expansion * (t["outer_ring"] * d_o - t["inner_ring"] * d_i) \
        - 2 * model.ball_expansion * t["balls"] * b.ball_diameter
    # the state was solved with the geometry of its last iterate, within the fixed point's 0.01 K
    bound = model.ring_expansion * 0.01 * (d_o + d_i + 2 * b.ball_diameter)
    assert state.thermal["running_geometry"]["diametral_clearance_change_m"] == pytest.approx(harris, abs=bound)
    assert abs(harris) > 1e-8  # it did change


def test_the_thermal_section_round_trips_and_is_refused_where_no_temperatures_are_modelled():
    setup = HIGH_SPEED.replace(thermal=TP2275)
    again = loads_bearing(dumps_bearing(setup))
    assert again.thermal == TP2275 and again.lubricant == ESTER_TURBINE_OIL
    with pytest.raises(ValueError, match=r"\[thermal\].*solve_load_distribution"):
        solve_load_distribution(setup, axial_force=667.0)
    with pytest.raises(ValueError, match=r"\[thermal\] oil_inlet_temperature is in kelvin"):
        loads_bearing(dumps_bearing(HIGH_SPEED).replace("[drag]", "[thermal]\noil_inlet_temperature = 121.0\n\n[drag]"))


def test_the_cli_steady_reports_temperatures(tmp_path):
    path = tmp_path / "spindle.toml"
    path.write_text(dumps_bearing(BearingSetup(SPINDLE_40MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG, CAGE, LAW)))
    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "steady", "--bearing", str(path), "--axial", "1000",
                          "--rpm", "20000", "--thermal", "--json"], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    th = data["thermal"]
    assert set(th["temperatures_K"]) == {"shaft", "inner_ring", "balls", "cage", "outer_ring", "housing", "oil"}
    assert th["oil_inlet_K"] == pytest.approx(121.0 + 273.15)  # the lubricant's reference temperature
    assert math.isclose(sum(th["heat_W"].values()), data["power_loss_W"]["total"], rel_tol=1e-9)
    assert "thermal" in data["inputs"]
