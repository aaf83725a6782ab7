"""The thermal steady state under combined load (issue 51; MODEL.md §14d with §12a): the
quasi-dynamic balance and the thermal network iterated to a fixed point, and the dynamic run
that starts from it."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from contact.bearing_thermal import NODES, ThermalModel, inlet_temperature  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING, BearingSetup, simulate, steady_state  # noqa: E402
from exudyn_bearing.bearingfile import BearingFile, save_bearing  # noqa: E402
from exudyn_bearing.solvers.azimuth_power import azimuth_losses  # noqa: E402
from exudyn_bearing.solvers.quasidynamic import combined_load_state, solve_combined  # noqa: E402
from exudyn_bearing.solvers.steady_balance import solve_steady, steady_result  # noqa: E402
from tests.helpers import quasi_dynamic_power_gap  # noqa: E402

HOT = BearingSetup(REFERENCE_BEARING).replace(thermal=ThermalModel())
T_IN = inlet_temperature(HOT.thermal, HOT.lubricant)  # K
#: solve_combined's load, speeds and tolerance for 2.2 kN + 2 kN at 1800 rpm
LOADED = dict(axial_force=2200.0, radial_force=2000.0, rpm=1800.0, outer_rpm=0.0, tol=1e-8, start=0.0)


def test_a_vanishing_radial_load_is_the_axial_thermal_steady_state():
    """At 1300 N axial + 1 N radial the combined-load fixed point (every ball in its own
    balance, 16 balls) lands where the axial steady state's (one ball, a different solver)
    does: node temperatures within 5 mK, the heat of each place within 0.1 %."""
    combined = combined_load_state(HOT, axial_force=1300.0, radial_force=1.0, rpm=1800.0)
    axial = steady_state(HOT, axial_force=1300.0, rpm=1800.0)
    assert combined.converged and axial.converged, (combined.message, axial.message)
    for node in NODES:
        assert combined.thermal["temperatures_K"][node] == pytest.approx(axial.thermal["temperatures_K"][node],
                                                                         abs=5e-3), node
    for place, watts in axial.thermal["heat_by_place_W"].items():
        assert combined.thermal["heat_by_place_W"][place] == pytest.approx(watts, rel=1e-3, abs=1e-6), place
    rise = combined.thermal["temperatures_K"]["balls"] - T_IN
    assert rise > 1.0  # the fixed point moved the temperatures: the comparison is not of two inlet states


def test_the_combined_thermal_state_balances_heat_and_power():
    """2.2 kN + 2 kN: the heat the balance makes leaves through the oil and the housing
    (0.1 %), and in the isothermal quasi-dynamic state the drive power equals the losses
    summed place by place less the contacts' normal work (two independent computations, 1e-7;
    the normal work below 5e-4 of the losses), with and without the cage's land."""
    state = combined_load_state(HOT, axial_force=2200.0, radial_force=2000.0, rpm=1800.0)
    assert state.converged, state.message
    th = state.thermal
    assert abs(th["heat_balance_percent"]) < 0.1
    assert sum(th["heat_W"].values()) == pytest.approx(sum(th["heat_by_place_W"].values()), rel=1e-9)
    assert th["running_geometry"]["diametral_clearance_change_m"] != 0.0
    assert th["contact_oil_temperature_K"]["inner"] > T_IN + 1.0
    for land in (0.0, 4e-3):
        cold = BearingSetup(REFERENCE_BEARING).replace(cage=HOT.cage.__class__(land_width=land))
        seed = steady_state(cold, axial_force=2200.0, rpm=1800.0)
        _, balance, x, _ = solve_combined(cold, cold.cage, steady=seed, **LOADED)
        losses = azimuth_losses(balance, x)
        drive, total, normal = quasi_dynamic_power_gap(balance, x)
        assert drive == pytest.approx(total - normal, rel=1e-7) and abs(normal) < 5e-4 * total
        assert (losses.get("land_outer", 0.0) > 1.0) == (land > 0)
    # each race's contacts and the land on their own oils (the thermal iterates' balances)
    oils = tuple(HOT.lubricant.at_temperature(c) for c in (70.0, 45.0, 55.0))
    solved = solve_steady(HOT, 2200.0, 1800.0, 0.0, 1e-8, races=oils[:2], land_lubricant=oils[2])
    states, balance, x, _ = solve_combined(HOT, HOT.cage, steady=steady_result(solved, 0.0, {}), oils=oils, **LOADED)
    drive, total, normal = quasi_dynamic_power_gap(balance, x)
    assert states.converged and drive == pytest.approx(total - normal, rel=1e-7)
    isothermal = steady_state(BearingSetup(REFERENCE_BEARING), axial_force=2200.0, rpm=1800.0)
    _, base, y, _ = solve_combined(HOT, HOT.cage, steady=isothermal, **LOADED)
    # the films thin as each race's oil: (eta / eta_30C)^0.67 (Hamrock-Dowson) within 10 %
    film, film_30 = (b.contacts(v)[1].film_thickness for b, v in ((balance, x), (base, y)))
    z = REFERENCE_BEARING.balls
    for part, oil in ((slice(0, z), oils[0]), (slice(z, 2 * z), oils[1])):
        ratio = np.mean(film[part]) / np.mean(film_30[part])
        assert ratio == pytest.approx((oil.viscosity / HOT.lubricant.viscosity) ** 0.67, rel=0.1)


def test_bad_inputs_are_refused_by_name():
    for kw, name in ((dict(axial_force=-300.0), "axial_force"), (dict(radial_force=float("nan")), "radial_force"),
                     (dict(rpm=0.0), "outer_rpm"), (dict(steady=object()), "steady")):
        args = dict(axial_force=2200.0, radial_force=2000.0, rpm=1800.0) | kw
        with pytest.raises(ValueError, match=name):
            combined_load_state(HOT, **args)


@pytest.fixture(scope="module")
def runs():
    """0.01 s under 2.2 kN + 2 kN from the combined thermal start ('auto') and from the inlet."""
    return {start: simulate(HOT, axial_force=2200.0, radial_force=2000.0, time=0.01, initial_temperatures=start)
            for start in ("auto", "inlet")}


def test_a_run_from_the_combined_thermal_start_holds_its_temperatures(runs):
    """'auto' under combined load starts from the combined thermal steady state: its nodes
    move by less than 1/100 of what a run from the inlet temperature moves over the same
    0.01 s, and the run's heat by place at its start is the fixed point's within 2 %."""
    hot, inlet = runs["auto"].thermal, runs["inlet"].thermal
    assert hot["start"] == "steady" and inlet["start"] == "inlet"
    state = combined_load_state(HOT, axial_force=2200.0, radial_force=2000.0, rpm=1800.0)
    start = state.thermal["temperatures_K"]
    moved = max(abs(hot["temperatures_K"][n] - start[n]) for n in NODES)
    inlet_moved = max(abs(inlet["temperatures_K"][n] - T_IN) for n in NODES)
    assert moved < 0.01 * inlet_moved
    for place in ("inner_contacts", "outer_contacts", "ball_drag"):
        assert hot["heat_by_place_W"][place] == pytest.approx(state.thermal["heat_by_place_W"][place], rel=0.02)


def test_the_cli_and_a_plain_scene_take_the_combined_thermal_start(tmp_path):
    """The same start from the CLI (a bearing file's [thermal] section) and from a plain
    Exudyn scene solved by SolveDynamic."""
    path = tmp_path / "hot.toml"
    save_bearing(BearingFile(REFERENCE_BEARING, thermal=ThermalModel()), path)
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--bearing", str(path), "--axial",
                           "2200", "--radial", "2000", "--time", "0.002", "--json"], capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    out = json.loads(proc.stdout)
    assert out["thermal"]["start"] == "steady"
    assert out["thermal"]["temperatures_K"]["balls"] > T_IN + 1.0

    mbs = exu.SystemContainer().AddSystem()
    from exudyn_bearing import races

    h = mbs.CreateAngularContactBearing(HOT, innerRace=races.Driven(1800.0), axialForce=2200.0, radialForce=2000.0,
                                        show=False)
    mbs.Assemble()
    s = exu.SimulationSettings()
    s.timeIntegration.endTime, s.timeIntegration.numberOfSteps = 0.002, 20
    s.timeIntegration.verboseMode = 0
    exu.SolveDynamic(mbs, s)
    assert h.temperatures.start.kind == "steady"
    now = h.temperatures.temperatures(mbs)
    assert np.all(np.isfinite(list(now.values())))
    assert now["balls"] == pytest.approx(out["thermal"]["temperatures_K"]["balls"], abs=0.05)


def test_later_iterates_start_from_the_last_balance(monkeypatch):
    """After the first iterate's continuation, each fixed-point iterate's balance is Newton's
    from the last one's: one continuation for 2.2 kN + 2 kN instead of one per iterate, and
    the same fixed point as with a continuation every time (temperatures within its 0.01-K
    test, the cage speed within 1e-6)."""
    from exudyn_bearing.solvers import quasidynamic

    solve = quasidynamic.solve_combined
    calls = []

    def counted(*a, warm=None, **k):
        calls.append(warm is not None)
        return solve(*a, warm=warm, **k)

    monkeypatch.setattr(quasidynamic, "solve_combined", counted)
    warm = combined_load_state(HOT, axial_force=2200.0, radial_force=2000.0, rpm=1800.0)
    assert calls.count(False) == 1 and calls.count(True) == warm.thermal["iterations"] - 1 >= 1
    def continued(*a, warm=None, **k):  # every warm start refused: the continuation each time
        if warm is not None:
            return quasidynamic.failed_states(REFERENCE_BEARING.balls, "refused", 0.0), None, None, None
        return solve(*a, **k)

    monkeypatch.setattr(quasidynamic, "solve_combined", continued)
    cold = combined_load_state(HOT, axial_force=2200.0, radial_force=2000.0, rpm=1800.0)
    for node in NODES:
        assert warm.thermal["temperatures_K"][node] == pytest.approx(cold.thermal["temperatures_K"][node], abs=0.01)
    assert warm.cage_speed == pytest.approx(cold.cage_speed, rel=1e-6)


@pytest.mark.parametrize("radial", [0.0, 2000.0])
def test_a_bearing_with_a_defect_starts_from_its_perfect_twins_thermal_state(radial):
    """A defect has no steady state: 'auto' starts a bearing with one from the thermal steady
    state of the same bearing without it (axial and combined load; until session 41 the
    build stopped at the steady solver's refusal of the surface)."""
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import races

    spalled = HOT.replace(surface=SurfaceModel((Defect("outer", 0.0, 1e-3, 5e-6),)))
    mbs = exu.SystemContainer().AddSystem()
    h = mbs.CreateAngularContactBearing(spalled, innerRace=races.Driven(1800.0), axialForce=2200.0,
                                        radialForce=radial, show=False)
    perfect = (steady_state(HOT, axial_force=2200.0, rpm=1800.0) if radial == 0 else
               combined_load_state(HOT, axial_force=2200.0, radial_force=radial, rpm=1800.0))
    assert h.temperatures.start.kind == "steady"
    for node in NODES:
        assert h.temperatures.start_temperatures[node] == pytest.approx(perfect.thermal["temperatures_K"][node],
                                                                        abs=1e-9)
    assert h.connector.surface is not None and h.connector.surface.defects


def test_a_clearance_that_turns_with_temperature_is_followed_from_the_last_iterate():
    """The CWRU 6205 (zero clearance) at 1 kN radial: its clearance turns with each kelvin, so
    Newton from the last iterate's balance fails at the next iterate's sizes. The continuation
    from that balance's sizes and oils to the new ones (``near``) finds the same fixed point as
    the continuation from the seed's steady state (cage speed within 1e-7 relative, nodes
    within 1e-5 K) with one cold continuation instead of two."""
    from unittest import mock

    from exudyn_bearing import CWRU_6205_BEARING
    from exudyn_bearing.solvers import quasidynamic

    setup = BearingSetup(CWRU_6205_BEARING).replace(thermal=ThermalModel())
    load = dict(axial_force=0.0, radial_force=1000.0, rpm=1800.0)
    cold, solve = [], quasidynamic.solve_combined

    def counting(*args, **kwargs):
        if kwargs.get("warm") is None:
            cold.append(1)
        return solve(*args, **kwargs)

    with mock.patch.object(quasidynamic, "solve_combined", counting):
        followed = combined_load_state(setup, **load)
    assert followed.converged and len(cold) == 1
    def refused(make, load_, warm, **kwargs):  # as before: a failed Newton goes back to the seed
        return warm, 1.0, "not followed", make(load_)

    with mock.patch.object(quasidynamic, "_continue_from_near", refused):
        restarted = combined_load_state(setup, **load)
    assert restarted.converged
    assert followed.cage_speed == pytest.approx(restarted.cage_speed, rel=1e-7)
    for node, value in restarted.thermal["temperatures_K"].items():
        assert followed.thermal["temperatures_K"][node] == pytest.approx(value, abs=1e-5)
