"""The thermal network integrated by Exudyn with the bearing (MODEL.md §14g): checked
against closed forms, conservation of energy, the loss breakdown and the steady solver,
never against the code's own output."""
import json
import subprocess
import sys
import dataclasses

import exudyn as exu
import numpy as np
import pytest
from scipy.linalg import expm

from contact.bearing_thermal import NODES, ThermalModel, place_heat
from contact.thermal_network import ThermalNetwork
from contact.ballrace import ContactLaw
from contact.lubricant import REFERENCE_LUBRICANT
from exudyn_bearing import (CWRU_6205_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG, Bearing,
                            BearingSetup, CageModel, races, simulate)
from exudyn_bearing.bearingfile import as_setup
from exudyn_bearing.model.builder import CreateAngularContactBearing
from exudyn_bearing.model.thermal_nodes import add_network, set_network
from exudyn_bearing.presets import REFERENCE_BEARING
from exudyn_bearing.solvers.thermal import contact_oils

THERMAL = as_setup(REFERENCE_BEARING).replace(thermal=ThermalModel())


def _settings(end, steps):
    s = exu.SimulationSettings()
    s.timeIntegration.endTime, s.timeIntegration.numberOfSteps = end, steps
    s.timeIntegration.verboseMode = 0
    s.solution.sensors.writePeriod = end / steps
    return s


def _energy(th, mbs):
    """(heat stored, J; integral of heat made - heat to the boundaries, J) of a run: the step
    ending at t[k] ran with update idx[k], its rates taken at both ends of the step."""
    t, temps = th.history(mbs)
    idx = th.oils_at(t)
    made = sum(0.5 * (t[k] - t[k - 1]) * sum(
        sum(th.updates[idx[k]]["heat_W"].values()) - sum(th.updates[idx[k]]["network"].to_boundaries(
            dict(zip(NODES, temps[j]))).values()) for j in (k - 1, k)) for k in range(1, len(t)))
    return float(th.updates[0]["network"].capacity @ (temps[-1] - temps[0])), made


def test_exudyn_integrates_a_two_node_network_to_its_closed_form():
    """Ring (C1) -- G12 -- housing (C2) -- G2a -- ambient, Q into the ring, as the bearing's
    nodes are given to Exudyn (add_network, set_network): T(t) = T_inf + exp(M t)(T0 - T_inf),
    M = -C^-1 A, against the matrix exponential; then the heat doubled (a load step)."""
    c, g12, g2a, ta = np.array([40.0, 90.0]), 3.0, 1.2, 300.0
    net = ThermalNetwork(("ring", "housing"), c, {("ring", "housing"): g12}, {"ambient": ta},
                         {("housing", "ambient"): g2a})
    mbs = exu.SystemContainer().AddSystem()
    node, obj, sensor = add_network(mbs, [ta, ta])
    started, doubled = [], []

    def step(mbs_, t_end):  # Exudyn passes the step's end time; the state is the start's
        if not started:
            started.append(t_end)
            set_network(mbs_, obj, net, {"ring": 25.0}, (node, [ta, ta]))
        if t_end > 30.0 + 1e-9 and not doubled:
            doubled.append(t_end)
            set_network(mbs_, obj, net, {"ring": 50.0}, (node, mbs_.systemData.GetODE1Coordinates()))
        return True

    mbs.SetPreStepUserFunction(step)
    mbs.Assemble()
    exu.SolveDynamic(mbs, _settings(60.0, 6000))
    data = np.asarray(mbs.GetSensorStoredData(sensor))
    a = np.array([[g12, -g12], [-g12, g12 + g2a]])
    m = -a / c[:, None]
    t_inf = np.linalg.solve(a, [25.0, g2a * ta])
    k30 = int(np.argmin(abs(data[:, 0] - 30.0)))
    exact30 = t_inf + expm(m * 30.0) @ (np.array([ta, ta]) - t_inf)
    assert data[k30, 0] == pytest.approx(30.0)
    assert np.allclose(data[k30, 1:], exact30, atol=1e-6 * (exact30[0] - ta))
    t_inf2 = np.linalg.solve(a, [50.0, g2a * ta])
    exact60 = t_inf2 + expm(m * 30.0) @ (exact30 - t_inf2)
    assert np.allclose(data[-1, 1:], exact60, atol=1e-6 * (exact60[0] - ta))
    # the slow mode's time constant, the closed form's eigenvalue, read from the run
    slow = -1.0 / max(np.linalg.eigvals(m).real)
    assert slow > 30.0 / 5  # the check above is not at the steady state already


@pytest.fixture(scope="module")
def inlet_run():
    mbs = exu.SystemContainer().AddSystem()
    brg = CreateAngularContactBearing(mbs, THERMAL, innerRace=races.Free(1800), axialForce=1300.0, show=False,
                                      initialTemperatures="inlet", thermalUpdatePeriod=2.5e-4)
    mbs.Assemble()
    exu.SolveDynamic(mbs, _settings(0.004, 40))
    return mbs, brg


def test_the_heat_into_the_nodes_is_the_loss_breakdown_of_each_state(inlet_run):
    """At every update the nodes' heat sums to the recomputed outputs' total loss at that
    state (results.outputs: by source, each recorded state with the oils it ran with) to
    1e-9: nothing lost between the losses and the nodes, and the outputs see the run's oils."""
    mbs, brg = inlet_run
    res = brg.Results(mbs)
    total = res.power_loss()["total"]
    ups = brg.temperatures.updates
    gaps = np.diff([u["time_s"] for u in ups])  # every 2.5e-4 s at the 1e-4-s steps: at every third step
    assert len(ups) == 14 and np.allclose(gaps, 3e-4)
    for u in ups:
        k = int(np.argmin(abs(res.time - u["time_s"])))
        assert res.time[k] == pytest.approx(u["time_s"], abs=1e-12)
        assert sum(u["heat_W"].values()) == pytest.approx(total[k], rel=1e-9)
        assert sum(u["heat_W"].values()) == pytest.approx(sum(u["losses_W"].values()), rel=1e-12)
    # the oils follow the nodes: the last update's, from its temperatures
    last = ups[-1]
    inner, outer, land = contact_oils(THERMAL.lubricant, last["temperatures_K"], "outer")
    assert brg.connector.oils[0].viscosity == pytest.approx(inner.viscosity, rel=1e-12)
    assert brg.connector.oils[1].viscosity == pytest.approx(outer.viscosity, rel=1e-12)


def test_the_nodes_store_the_heat_not_carried_off(inlet_run):
    """Energy: sum C_i (T_i(end) - T_i(0)) = integral of (heat made - heat to the
    boundaries) dt, the latter by the trapezoid rule over the recorded temperatures with
    each update's network and heat (Exudyn's rule for first-order states), to 1e-6."""
    mbs, brg = inlet_run
    stored, made = _energy(brg.temperatures, mbs)
    assert stored > 0
    assert stored == pytest.approx(made, rel=1e-6)


def test_a_run_from_the_thermal_steady_state_stays_there():
    """initialTemperatures='steady': the start's nodes are the steady solver's, the heat the
    dynamic state makes at t = 0 is the steady solver's loss (0.5 %) and equals the heat
    the network removes there (0.5 %), and 5 ms later no node moved by 1 mK."""
    mbs = exu.SystemContainer().AddSystem()
    brg = CreateAngularContactBearing(mbs, THERMAL, innerRace=races.Free(1800), axialForce=1300.0, show=False,
                                      initialTemperatures="steady")
    mbs.Assemble()
    exu.SolveDynamic(mbs, _settings(0.005, 50))
    th = brg.temperatures
    steady = th.start.steady.thermal
    assert th.start.kind == "steady"
    first = th.updates[0]
    made = sum(first["heat_W"].values())
    assert made == pytest.approx(sum(steady["heat_by_place_W"].values()), rel=5e-3)
    assert made == pytest.approx(sum(first["removed_W"].values()), rel=5e-3)
    _, temps = th.history(mbs)
    assert np.max(np.abs(temps[-1] - np.array([steady["temperatures_K"][k] for k in NODES]))) < 1e-3


def test_bad_thermal_start_inputs_are_refused_by_name():
    for kw, name in (({"initialTemperatures": "cold"}, "initialTemperatures"),
                     ({"initialTemperatures": "steady", "radialForce": lambda t: 500.0}, "initialTemperatures"),
                     ({"thermalUpdatePeriod": 0.0}, "thermalUpdatePeriod")):
        mbs = exu.SystemContainer().AddSystem()
        with pytest.raises(ValueError, match=name):
            CreateAngularContactBearing(mbs, THERMAL, innerRace=races.Free(1800), axialForce=1300.0, show=False,
                                        **kw)


def test_heat_split_places_every_loss_of_a_dynamic_state():
    """place_heat takes every place a dynamic state's losses name (contacts with their
    damping, rolling resistance, drag, pockets, the land) and keeps their sum."""
    losses = {"inner_contacts": 3.0, "outer_contacts": 2.0, "rolling_resistance": 1.0, "ball_drag": 4.0,
              "pockets": 0.5, "land_inner": 0.25}
    assert sum(place_heat(losses).values()) == pytest.approx(sum(losses.values()), rel=1e-15)


# NASA TP-2275's 35-mm bearing at 28 000 rpm, every loss on (as benchmarks/thermal_tp2275.py)
HIGH_SPEED = BearingSetup(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG,
                          CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3),
                          ContactLaw(rolling_resistance=True, thermal_film=True),
                          thermal=ThermalModel(oil_flow=760e-6 / 60, oil_inlet_temperature=394.0, bore=35e-3))


def test_the_spindle_bearing_runs_at_the_thermal_steady_states_loss():
    """Python API (simulate), high-speed bearing from its thermal steady state: the dynamic
    run with each race's own oil loses what the steady solver found with the same oils
    (1 %), its nodes stay (1 mK), and its heat balance holds (0.01 %)."""
    s = simulate(HIGH_SPEED, axial_force=667.0, rpm=28000.0, time=0.004, initial_temperatures="steady")
    th = s.thermal
    steady = s.initial_steady_state
    assert th["start"] == "steady" and steady.thermal["converged"]
    assert s.power_loss_W["total"] == pytest.approx(steady.power_loss_W["total"], rel=1e-2)
    assert max(abs(v) for v in th["temperature_rise_K"].values()) < 1e-3
    assert abs(th["heat_balance_percent"]) < 1e-2
    # the races' oils differ (outer ring and balls run hotter than the inner ring, §14e)
    assert th["contact_oil_temperature_K"]["outer"] > th["contact_oil_temperature_K"]["inner"] + 1.0
    assert th["contact_viscosity_Pa_s"]["outer"] < th["contact_viscosity_Pa_s"]["inner"]


def test_a_cold_start_heats_the_oil_first_and_keeps_its_energy():
    """From the inlet temperature the cavity's oil (the smallest capacity, fed by drag and
    rolling resistance) warms fastest; made = carried off + stored over the window (0.05 %:
    the outputs' trapezoid over recorded temperatures), and the run's record names its start."""
    s = simulate(HIGH_SPEED, axial_force=667.0, rpm=28000.0, time=0.004, initial_temperatures="inlet")
    th = s.thermal
    rise = th["temperature_rise_K"]
    assert th["start"] == "inlet" and set(th["start_temperatures_K"].values()) == {394.0}
    assert rise["oil"] > 1.0 and rise["oil"] == max(rise.values())
    assert abs(th["heat_balance_percent"]) < 5e-2
    assert th["stored_W"] > 0.1 * sum(th["heat_W"].values())
    assert "thermal" in s.inputs and s.inputs["initial_temperatures"] == "'inlet'"


def test_a_deep_groove_bearing_under_radial_load_starts_hot_in_a_plain_scene():
    """Plain SolveDynamic, the Case Western 6205 (15 um play) under radial load, at its
    recommended step and tolerance: 'auto' starts from the thermal steady state under that
    load (the quasi-dynamic balance with the network, MODEL.md §14d; until session 41 every
    node at the inlet), so it stores less than 1 % of the heat it makes; the heat into the
    nodes is each update's loss breakdown, and the stored energy equals the heat made less
    the heat removed to 1e-6 of the heat made."""
    fields = {f.name: getattr(CWRU_6205_BEARING, f.name) for f in dataclasses.fields(CWRU_6205_BEARING)
              if f.name != "contact_angle"}
    setup = BearingSetup(Bearing.from_clearance(diametral_clearance=15e-6, **fields), thermal=ThermalModel())
    mbs = exu.SystemContainer().AddSystem()
    brg = CreateAngularContactBearing(mbs, setup, innerRace=races.Driven(3000), radialForce=300.0, show=False,
                                      thermalUpdatePeriod=5e-4)
    mbs.Assemble()
    settings = _settings(0.002, round(0.002 / brg.RecommendedStep()))
    settings.timeIntegration.newton.absoluteTolerance = brg.RecommendedAbsoluteTolerance()
    exu.SolveDynamic(mbs, settings)
    th = brg.temperatures
    assert th.start.kind == "steady" and th.start.steady.thermal["converged"]
    stored, made = _energy(th, mbs)
    # the steady start stores almost nothing: the balance is held to 1e-6 of the heat made
    heat = 0.002 * sum(th.updates[0]["heat_W"].values())  # J
    assert abs(made) < 1e-2 * heat
    assert stored == pytest.approx(made, abs=1e-6 * heat)


def test_the_cli_simulates_with_temperatures_and_plots_them(tmp_path):
    """CLI door: ``simulate --thermal`` (the reference bearing without a [thermal] section:
    its defaults) reports the nodes, the heat and its balance, and draws the temperatures."""
    png = tmp_path / "run.png"
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--axial", "1300", "--time", "0.003",
                           "--thermal", "--initial-temperatures", "inlet", "--plot", str(png), "--json"],
                          capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    data = json.loads(proc.stdout)
    th = data["thermal"]
    inlet = REFERENCE_LUBRICANT.reference_temperature + 273.15
    assert all(v == pytest.approx(inlet) for v in th["start_temperatures_K"].values())
    assert sum(th["heat_W"].values()) == pytest.approx(sum(th["heat_by_place_W"].values()), rel=1e-9)
    assert abs(th["heat_balance_percent"]) < 5e-2
    assert data["units"]["thermal"]["temperatures_K"]["oil"] == "K" and "thermal" in data["inputs"]
    assert (tmp_path / "run_temperatures.png").stat().st_size > 10_000


def test_a_second_solve_between_updates_keeps_the_energy():
    """A scene solved in two parts, the second starting between two updates (Exudyn's
    stored start rate of first-order coordinates is zero again at a solve's start): the
    energy balance over both holds to 1e-6, as over one solve."""
    mbs = exu.SystemContainer().AddSystem()
    brg = CreateAngularContactBearing(mbs, THERMAL, innerRace=races.Free(1800), axialForce=1300.0, show=False,
                                      initialTemperatures="inlet", thermalUpdatePeriod=1e-3)
    mbs.Assemble()
    s = _settings(0.0015, 15)
    exu.SolveDynamic(mbs, s)
    mbs.systemData.SetSystemState(mbs.systemData.GetSystemState(), configuration=exu.ConfigurationType.Initial)
    s.timeIntegration.startTime, s.timeIntegration.endTime = 0.0015, 0.003
    exu.SolveDynamic(mbs, s)
    stored, made = _energy(brg.temperatures, mbs)
    assert stored == pytest.approx(made, rel=1e-6)


def test_the_vibration_command_reports_the_temperatures(tmp_path):
    """CLI door of ``vibration``: a bearing file with an outer-race notch (the Case Western 6205
    with 15 um of play) run with ``--thermal`` from the inlet reports its temperatures, the heat
    into the nodes equal to the loss by place (1e-9), the energy kept (heat made − carried off =
    stored, 5e-4 %), and draws them; without ``--thermal`` there is nothing to report."""
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing.bearingfile import save_bearing

    fields = {f.name: getattr(CWRU_6205_BEARING, f.name) for f in dataclasses.fields(CWRU_6205_BEARING)
              if f.name != "contact_angle"}
    bearing = Bearing.from_clearance(diametral_clearance=15e-6, **fields)
    save_bearing(BearingSetup(bearing, surface=SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),))),
                 tmp_path / "notch.toml")
    png = tmp_path / "vib.png"
    args = [sys.executable, "-m", "exudyn_bearing", "vibration", "--bearing", str(tmp_path / "notch.toml"),
            "--rpm", "1797", "--radial", "300", "--time", "0.012", "--settle", "0.002", "--out", str(tmp_path)]
    proc = subprocess.run(args + ["--thermal", "--initial-temperatures", "inlet", "--plot", str(png), "--json"],
                          capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    data = json.loads(proc.stdout)
    th = data["thermal"]
    inlet = REFERENCE_LUBRICANT.reference_temperature + 273.15
    assert th["start"] == "inlet"
    assert all(v == pytest.approx(inlet) for v in th["start_temperatures_K"].values())
    made = sum(th["heat_W"].values())
    assert made > 0 and made == pytest.approx(sum(th["heat_by_place_W"].values()), rel=1e-9)
    assert made - sum(th["removed_W"].values()) == pytest.approx(th["stored_W"], abs=5e-6 * made)
    assert data["units"]["thermal"]["temperatures_K"]["oil"] == "K"
    assert "thermal" in data["inputs"] and data["inputs"]["initial_temperatures"] == "'inlet'"
    assert (tmp_path / "vib_temperatures.png").stat().st_size > 10_000
    text = subprocess.run(args + ["--time", "0.004"], capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert text.returncode == 0, text.stderr[-2000:]
    assert "temperatures" not in text.stdout and json.loads((tmp_path / "vibration.json").read_text())["thermal"] is None
