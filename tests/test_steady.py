"""The steady rolling state (exudyn_bearing.solvers.steady, MODEL.md §12) against numbers it does not
produce: the reduced balance of ``tests/reduced_balance.py`` (its own kinematics, the
accurate traction rule at order 24), closed-form pure rolling, and the dynamic model, which
must stay on a steady state it starts from."""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from contact.kinematics import rolling_cage_speed  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING as B, REFERENCE_LUBRICANT, steady_state  # noqa: E402
from exudyn_bearing.criteria import gyroscopic_minimum_axial  # noqa: E402
from reduced_balance import solve_balance  # noqa: E402

RPM = 1800.0
#: MODEL.md §8 drag (C_D 0.5, fully flooded) and the default law's constants (§6a, §6b),
#: written out here so that a changed preset shows up as a difference
DRAG_COEFFICIENT, OIL_DENSITY = 0.5, 860.0
LIMITING_SHEAR, FILM_MODULUS = 0.047, 0.2953  # Λ; κ: τ_L/G = 1/(2π) (MODEL.md §6b)


@pytest.mark.parametrize("axial", [400.0, 1300.0])
def test_matches_the_independent_reduced_balance(axial):
    """400 N (gross sliding, ~71 %) and 1.3 kN (~3.8 %): slip, cage speed, attitude and
    loads equal the reduced balance's within 1e-3 relative (both use the accurate rule;
    the package at order 16, the balance at 24)."""
    got = steady_state(axial_force=axial, rpm=RPM)
    ref = solve_balance(B, REFERENCE_LUBRICANT, axial, RPM, DRAG_COEFFICIENT, OIL_DENSITY, LIMITING_SHEAR,
                        FILM_MODULUS)
    assert got.converged and got.residual < 1e-8
    assert got.kinematic_cage_slip_percent == pytest.approx(ref.kinematic_cage_slip_percent, rel=1e-3)
    assert got.cage_speed == pytest.approx(ref.cage_speed, rel=1e-5)
    assert got.attitude_xz_deg == pytest.approx(math.degrees(ref.attitude_xz), abs=0.02)
    assert got.attitude_yz_deg == pytest.approx(math.degrees(ref.attitude_yz), abs=0.02)
    assert got.inner_load == pytest.approx(ref.inner_load, rel=1e-4)
    assert got.outer_load == pytest.approx(ref.outer_load, rel=1e-4)
    assert got.wall_time_s < 5.0  # a solve, not a simulation (~0.3 s on the 2-core machine)


@pytest.mark.parametrize("axial", [400.0, 3000.0])
def test_without_drag_the_balls_roll(axial):
    """No drag: nothing resists the orbit, so the balance needs no rolling traction and the
    cage runs at the pure-rolling speed of the balls' own spin axes (MODEL.md §7): kinematic
    cage slip within 0.05 % of zero, and the cage speed equals the closed-form pure-rolling
    speed for the solved axis, w_c r_c + W (e x (p - c))_y = w_race rho_p at both contacts."""
    got = steady_state(axial_force=axial, rpm=RPM, ball_drag=None)
    assert got.converged
    assert abs(got.kinematic_cage_slip_percent) < 0.05
    c = np.array([got.ball_orbit_radius, 0.0, got.ball_axial_position])
    a_i, a_o = math.radians(got.inner_contact_angle_deg), math.radians(got.outer_contact_angle_deg)
    p_in = c - B.ball_radius * np.array([math.cos(a_i), 0.0, math.sin(a_i)])
    p_out = c + B.ball_radius * np.array([math.cos(a_o), 0.0, math.sin(a_o)])
    w_roll = rolling_cage_speed(c[None], np.array([got.ball_omega]), p_in[None], p_out[None], RPM * math.pi / 30, 0.0)
    assert got.cage_speed == pytest.approx(float(w_roll[0]), rel=5e-4)


def test_drag_slows_the_cage_more_at_light_load():
    """With drag the kinematic slip falls with load (MODEL.md §7), from gross sliding at
    200 N to a fraction of a percent at 3 kN."""
    slips = [steady_state(axial_force=fa, rpm=RPM).kinematic_cage_slip_percent for fa in (200.0, 1000.0, 3000.0)]
    assert slips[0] > 50 and slips[2] < 0.5
    assert slips[0] > slips[1] > slips[2]


@pytest.mark.parametrize("axial", [400.0, 1300.0])
def test_dynamic_run_started_from_the_steady_state_stays_on_it(axial):
    """The dynamic model (fast traction rule, every ball, the cage body, Exudyn's integrator)
    started from the steady state keeps its kinematic cage slip within 0.05 pp of it and
    reports the run settled after 0.06 s (from a pure-rolling start 400 N needs ~1.7 s)."""
    from exudyn_bearing import simulate

    state = steady_state(axial_force=axial, rpm=RPM)
    run = simulate(axial_force=axial, rpm=RPM, time=0.06)
    assert run.kinematic_cage_slip_percent == pytest.approx(state.kinematic_cage_slip_percent, abs=0.05)
    assert run.cage_speed == pytest.approx(state.cage_speed, rel=1e-3)
    assert run.settled
    rolling = simulate(axial_force=axial, rpm=RPM, time=0.06, initial_state="rolling")
    assert abs(rolling.kinematic_cage_slip_percent - state.kinematic_cage_slip_percent) > 0.1  # still on its way


def test_gyroscopic_criterion_closed_form():
    """Jones' criterion F_a = M_g Z sin a0 / (mu D), M_g = (m D²/10) |W| w_c sin a0, with the
    pure-rolling spin W and orbit speed w_c of a ball on the fixed-angle geometry computed by
    ``contact.kinematics.rolling_cage_speed`` (two rolling conditions, no formula shared)."""
    a0, r = B.contact_angle, B.ball_radius
    c = np.array([[B.pitch_radius, 0.0, 0.0]])
    n = np.array([math.cos(a0), 0.0, math.sin(a0)])
    axis = np.array([[-math.sin(a0), 0.0, math.cos(a0)]])
    w_c, spin = rolling_cage_speed(c, axis, c - r * n, c + r * n, RPM * math.pi / 30, 0.0, return_spin=True)
    # H = I w_abs of a sphere turns with the orbit: M_g = I w_c |e_z x w_abs| = I w_c |W| sin a0
    m_g = B.ball_mass * B.ball_diameter ** 2 / 10 * abs(spin[0]) * w_c[0] * math.sin(a0)
    expected = m_g * B.balls * math.sin(a0) / (0.047 * B.ball_diameter)
    assert gyroscopic_minimum_axial(B, RPM, traction_coefficient=0.047) == pytest.approx(expected, rel=1e-9)
    with pytest.raises(ValueError, match="traction_coefficient"):
        gyroscopic_minimum_axial(B, RPM, traction_coefficient=0.0)


@pytest.mark.parametrize("kw, name", [(dict(axial_force=-5.0, rpm=RPM), "axial_force"),
                                      (dict(axial_force=float("nan"), rpm=RPM), "axial_force"),
                                      (dict(axial_force=500.0, rpm=float("inf")), "rpm"),
                                      (dict(axial_force=500.0, rpm=0.0), "rpm")])
def test_bad_input_names_the_parameter(kw, name):
    with pytest.raises(ValueError, match=name):
        steady_state(**kw)


def test_steady_start_needs_a_load_and_a_created_inner_race():
    """'steady' refuses what it cannot start (no load, a race the bearing did not create, an
    unknown name); 'auto' then starts from pure rolling."""
    import exudyn as exu

    from exudyn_bearing import CreateAngularContactBearing

    mbs = exu.SystemContainer().AddSystem()
    with pytest.raises(ValueError, match="initialState.*needs a load"):
        CreateAngularContactBearing(mbs, axialForce=0.0, initialState="steady", show=False)
    with pytest.raises(ValueError, match="initialState"):
        CreateAngularContactBearing(mbs, axialForce=1300.0, initialState="quasi", show=False)
    with pytest.raises(ValueError, match="initialState"):
        CreateAngularContactBearing(mbs, innerRaceDisplacement=(0.0, 0.0, 20e-6), initialState="steady", show=False)
    handle = CreateAngularContactBearing(mbs, innerRaceDisplacement=(0.0, 0.0, 20e-6), show=False)
    assert handle.initialSteadyState is None and handle.initialQuasiDynamicState is None


def test_cli_json():
    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "steady", "--axial", "1300", "--json"],
                         capture_output=True, text=True, check=True)
    data = json.loads(out.stdout)
    for key in ("kinematic_cage_slip_percent", "cage_slip_percent", "cage_speed", "attitude_xz_deg",
                "attitude_yz_deg", "inner_load", "outer_load", "inner_contact_angle_deg", "outer_contact_angle_deg",
                "converged", "wall_time_s", "hirano_minimum_axial", "gyroscopic_minimum_axial"):
        assert key in data
    # every key has its unit; the inputs name the bearing that produced it
    assert set(data["units"]) == set(data) - {"units", "inputs"}
    assert data["units"]["cage_speed"] == "rad/s" and data["units"]["inner_max_pressure"] == "Pa"
    assert data["units"]["hirano_minimum_axial"] == "N" and data["units"]["attitude_xz_deg"] == "deg"
    assert "balls=16" in data["inputs"]["bearing"] and data["inputs"]["version"]
    assert data["converged"] is True
    assert 2.0 < data["kinematic_cage_slip_percent"] < 6.0


def test_zero_clearance_deep_groove():
    """No free contact angle (zero clearance): the steady state still solves, with the
    contact angle of the quasi-static solution (the film and traction barely move it)."""
    from exudyn_bearing import Bearing, solve_load_distribution

    brg = Bearing.from_clearance(diametral_clearance=0.0, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                 inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)
    state = steady_state(brg, axial_force=200.0, rpm=3000.0)
    assert state.converged
    qs = solve_load_distribution(brg, axial_force=200.0, rpm=3000.0, cage_speed=state.cage_speed)
    assert state.inner_contact_angle_deg == pytest.approx(math.degrees(qs.inner_contact_angle[0]), abs=0.5)
