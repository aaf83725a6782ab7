"""The jet oil's momentum loss (MODEL.md §11c, eq. 11c.2) against Euler's turbomachine
equation: oil entering at Q without swirl and leaving at the balls' orbital speed at the outer
raceway takes the power rho Q (w_c r_o)^2, and the races' drive power still equals the losses.
The compiled and numpy force paths agree on it in tests/test_compiled.py ('jet momentum')."""
import dataclasses
import json
import math

import numpy as np
import pytest

from contact.bearing_thermal import ThermalModel
from exudyn_bearing import (CWRU_6205_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG,
                            REFERENCE_BEARING, SPINDLE_40MM_BEARING, BearingSetup, combined_load_state, simulate,
                            steady_state)
from exudyn_bearing.bearing import BallDrag
from exudyn_bearing.bearingfile import dumps_bearing, loads_bearing

OIL_DENSITY = 860.0  # the reference oil, kg/m^3 (MODEL.md §8), written out
FLOW = 760e-6 / 60  # NASA TP-2275's jet, m^3/s


def _euler(density, flow, cage_speed, bearing):
    """rho Q (w_c r_o)^2, W, with r_o = (d_m + D)/2 written from the bearing's diameters."""
    r_o = 0.5 * (bearing.pitch_diameter + bearing.ball_diameter)
    return density * flow * (cage_speed * r_o) ** 2


def test_steady_state_loss_rises_by_the_euler_power_and_the_drive_power_follows():
    """The 35-mm bearing at 667 N, 28 000 rpm (one-ball steady solver, §12): the jet's loss is
    rho Q (w_c r_o)^2 (c/r_p)^2 within 1e-9, c the ball centres' orbit radius (here ~15 um
    outside r_p: 1.3e-3 of the power); the sphere drag beside it is the jet-free state's
    rescaled to the new cage speed as |v|^3 (1e-3); the races' torques times their speeds
    equal the summed losses (1e-6); the jet slows the cage."""
    setup = BearingSetup(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG)
    plain = steady_state(setup, axial_force=667.0, rpm=28000.0)
    jet = steady_state(setup.replace(drag=dataclasses.replace(HIGH_SPEED_DRAG, oil_flow=FLOW)), axial_force=667.0,
                       rpm=28000.0)
    assert plain.converged and jet.converged
    sphere = plain.power_loss_W["ball_drag"] * (jet.cage_speed / plain.cage_speed) ** 3
    euler = _euler(ESTER_TURBINE_OIL.density, FLOW, jet.cage_speed, HIGH_SPEED_35MM_BEARING)
    assert euler > 10.0
    orbit = jet.ball_orbit_radius / HIGH_SPEED_35MM_BEARING.pitch_radius
    assert jet.power_loss_W["jet_momentum"] == pytest.approx(euler * orbit ** 2, rel=1e-9)
    assert jet.power_loss_W["ball_drag"] == pytest.approx(sphere, rel=1e-3)
    assert plain.power_loss_W["jet_momentum"] == 0.0
    assert jet.drive_power_W == pytest.approx(jet.power_loss_W["total"], rel=1e-6)
    assert jet.cage_speed < plain.cage_speed


@pytest.mark.parametrize("bearing, axial, radial, rpm", [
    (REFERENCE_BEARING, 2200.0, 2000.0, 1800.0), (SPINDLE_40MM_BEARING, 1000.0, 500.0, 12000.0),
    (CWRU_6205_BEARING, 0.0, 1000.0, 1800.0)], ids=["reference", "40-mm spindle", "6205 deep groove"])
def test_quasi_dynamic_state_carries_the_jet_on_every_ball(bearing, axial, radial, rpm):
    """Combined or radial load (§12a): each ball pays k v_j^2 of the jet, k = rho Q r_o^2 /
    (Z r_p^2), so in all rho Q (w_c r_o)^2 when the balls orbit with the cage (2e-3); with it
    the races' drive power is the losses less the contacts' normal work
    (:func:`tests.helpers.quasi_dynamic_power_gap`, 2e-5)."""
    from exudyn_bearing.solvers.quasidynamic import seed_axial_load, solve_combined
    from tests.helpers import quasi_dynamic_power_gap

    flow = 1e-4
    drag = BallDrag(0.5, 0.25)
    plain = combined_load_state(bearing, axial_force=axial, radial_force=radial, rpm=rpm, ball_drag=drag)
    jet = combined_load_state(bearing, axial_force=axial, radial_force=radial, rpm=rpm,
                              ball_drag=dataclasses.replace(drag, oil_flow=flow))
    assert plain.converged and jet.converged
    sphere = plain.power_loss_W["ball_drag"] * (jet.cage_speed / plain.cage_speed) ** 3
    euler = _euler(OIL_DENSITY, flow, jet.cage_speed, bearing)
    assert euler > 0.1
    assert jet.power_loss_W["jet_momentum"] == pytest.approx(euler, rel=2e-3)
    assert jet.power_loss_W["ball_drag"] == pytest.approx(sphere, rel=2e-3)
    for state in (plain, jet):  # as the result reports it (the 6205's 78 mW: 3e-5, its balance's tolerance)
        assert state.drive_power_W == pytest.approx(state.power_loss_W["total"] - state.normal_work_W, rel=1e-4)
    setup = BearingSetup(bearing, drag=dataclasses.replace(drag, oil_flow=flow))
    seed = steady_state(setup, axial_force=seed_axial_load(axial, radial), rpm=rpm)
    states, balance, x, _ = solve_combined(setup, setup.cage, axial_force=axial, radial_force=radial, rpm=rpm,
                                           outer_rpm=0.0, steady=seed, tol=1e-8, start=0.0)
    drive, losses, normal = quasi_dynamic_power_gap(balance, x)
    assert states.normal_work_W == pytest.approx(normal, rel=1e-12)
    # within the balance's own tolerance (1e-8 of the force scale: 6.5e-6 of the 6205's 0.35 W);
    # about the bearing axis instead of the race's centre the 6205 was 4.3 % off
    assert drive == pytest.approx(losses - normal, rel=2e-5)


def test_dynamic_run_pays_the_jet_ball_by_ball():
    """A 10-ms run from the steady state (the connector's compiled force path, as a plain
    Exudyn scene sees it): the recorded drag power is, ball by ball, the sphere's
    1/2 C_D x rho pi r^2 |v|^3 (``ball_drag``) and the jet's rho Q r_o^2 / (Z r_p^2) v^2
    (``jet_momentum``) at the balls' orbital speeds (2e-3 each), and the run's drive power
    still equals its losses (1 %)."""
    flow, fraction, b = 1e-4, 0.25, REFERENCE_BEARING
    run = simulate(axial_force=1300.0, rpm=1800.0, time=0.01, ball_drag=BallDrag(0.5, fraction, oil_flow=flow))
    r = run.results
    v = r.ball_orbital_speed * b.pitch_radius
    r_o = 0.5 * (b.pitch_diameter + b.ball_diameter)
    sphere = np.sum(0.5 * 0.5 * fraction * OIL_DENSITY * math.pi * b.ball_radius ** 2 * np.abs(v) ** 3, axis=1)
    euler = np.sum(OIL_DENSITY * flow * r_o ** 2 / (b.balls * b.pitch_radius ** 2) * v ** 2, axis=1)
    assert r.power_loss()["ball_drag"] == pytest.approx(sphere, rel=2e-3)
    assert r.power_loss()["jet_momentum"] == pytest.approx(euler, rel=2e-3)
    m = r.last(1 / 3)
    drive, loss = float(np.mean(r.drive_power()[m])), float(np.mean(r.power_loss()["total"][m]))
    assert loss == pytest.approx(drive, rel=0.01)
    assert run.assumptions["jet_oil_flow_m3_s"] == flow
    from exudyn_bearing.results.records import units_of

    assert units_of({"assumptions": run.assumptions})["assumptions"]["jet_oil_flow_m3_s"] == "m^3/s"


@pytest.mark.parametrize("value", [-1e-5, float("nan"), float("inf")])
def test_a_bad_oil_flow_is_refused_by_name(value):
    with pytest.raises(ValueError, match="oil_flow"):
        BallDrag(oil_flow=value)


def test_the_jet_and_the_thermal_network_share_one_oil_flow():
    """The jet whose momentum the balls supply is the oil that carries the heat: a setup giving
    two different flows is refused, naming both; equal ones (or no jet) pass."""
    thermal = ThermalModel(oil_flow=FLOW)
    with pytest.raises(ValueError, match=r"drag\.oil_flow.*thermal\.oil_flow"):
        BearingSetup(HIGH_SPEED_35MM_BEARING, drag=BallDrag(oil_flow=2 * FLOW), thermal=thermal)
    BearingSetup(HIGH_SPEED_35MM_BEARING, drag=BallDrag(oil_flow=FLOW), thermal=thermal)
    BearingSetup(HIGH_SPEED_35MM_BEARING, drag=BallDrag(), thermal=thermal)


def test_the_bearing_file_carries_the_jet():
    """[drag] oil_flow reaches the setup and survives a round trip; the default file has none."""
    setup = BearingSetup(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, dataclasses.replace(HIGH_SPEED_DRAG,
                                                                                          oil_flow=FLOW))
    text = dumps_bearing(setup)
    assert "oil_flow" in text
    assert loads_bearing(text).drag.oil_flow == FLOW
    assert loads_bearing(dumps_bearing(setup.replace(drag=HIGH_SPEED_DRAG))).drag.oil_flow == 0.0


def test_the_cli_runs_a_jet_bearing_file_with_and_without_the_network(tmp_path):
    """The CLI door: ``steady --bearing`` of a file with ``[drag] oil_flow`` pays the jet (its
    loss within 2e-3 of Euler's power at its cage speed, its sphere drag that of the same file
    without, 1e-3 after the cage speed's change); ``--thermal`` on a file without ``[thermal]``
    takes the jet's flow for the network (one oil) instead of stopping on two flows; the JSON
    records the flow."""
    from tests.test_cli import cli_json

    setup = BearingSetup(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, dataclasses.replace(HIGH_SPEED_DRAG,
                                                                                          oil_flow=FLOW))
    (tmp_path / "jet.toml").write_text(dumps_bearing(setup))
    (tmp_path / "plain.toml").write_text(dumps_bearing(setup.replace(drag=HIGH_SPEED_DRAG)))
    args = ("--axial", "667", "--rpm", "28000")
    jet, _ = cli_json("steady", "--bearing", "jet.toml", *args, cwd=tmp_path)
    plain, _ = cli_json("steady", "--bearing", "plain.toml", *args, cwd=tmp_path)
    euler = _euler(ESTER_TURBINE_OIL.density, FLOW, jet["cage_speed"], HIGH_SPEED_35MM_BEARING)
    assert jet["power_loss_W"]["jet_momentum"] == pytest.approx(euler, rel=2e-3)
    assert plain["power_loss_W"]["jet_momentum"] == 0.0
    ratio = (jet["cage_speed"] / plain["cage_speed"]) ** 3
    assert jet["power_loss_W"]["ball_drag"] == pytest.approx(plain["power_loss_W"]["ball_drag"] * ratio, rel=1e-3)
    assert "oil_flow" in json.dumps(jet["inputs"])
    hot, _ = cli_json("steady", "--bearing", "jet.toml", *args, "--thermal", cwd=tmp_path)
    assert hot["converged"] and hot["thermal"]["temperatures_K"]["oil"] > 300.0
