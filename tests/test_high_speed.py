"""High-speed bearings (issue 19, MODEL.md §10a, §11, §12): the steady state where centrifugal
force and the gyroscopic moment dominate, the default step's orbit limit, and a dynamic run
at DN 2.5 million against the steady state it starts from."""
import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from exudyn_bearing import simulate, steady_state  # noqa: E402
from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG  # noqa: E402
from exudyn_bearing.solvers.quasistatic import solve_load_distribution  # noqa: E402
from exudyn_bearing.model.steprule import orbit_step_limit, recommended_step  # noqa: E402
from reduced_balance import solve_balance  # noqa: E402

B, OIL, DRAG = HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_DRAG
AXIAL = 667.0
#: the default law's constants (MODEL.md §6a, §6b) and the drag's effective density, written
#: out so that a changed preset shows up as a difference
LIMITING_SHEAR, FILM_MODULUS = 0.047, 0.2953  # Λ; κ: τ_L/G = 1/(2π) (MODEL.md §6b)
DRAG_DENSITY = 0.005 * 919.0


def test_preset_is_the_issue_bearing():
    """The 35-mm bearing of MODEL.md §11: 16 balls of 7.144 mm on 46.5 mm, f 0.535, 24 deg, M-50;
    ester oil 3.2 mPa s at 121 degC (not the 0.86 mPa s of an exponential extrapolation)."""
    assert (B.balls, B.ball_diameter, B.pitch_diameter) == (16, 7.144e-3, 46.5e-3)
    assert B.inner_conformity == B.outer_conformity == 0.535
    assert math.degrees(B.contact_angle) == pytest.approx(24.0)
    assert B.ball_mass == pytest.approx(7830.0 * math.pi / 6 * 7.144e-3 ** 3)
    assert (OIL.viscosity, OIL.reference_temperature, OIL.temperature_viscosity) == (3.2e-3, 121.0, 0.016)


def test_steady_state_at_72000_rpm_is_the_independent_balance():
    """DN 2.5 million: the free-angle start runs away here (the gyroscopic moment turns the
    ball to outer-raceway control); the package still finds the steady state, and it equals
    the reduced balance of ``tests/reduced_balance.py`` (own kinematics, accurate rule at
    order 24) started from the outer-control axis, within 1e-3."""
    got = steady_state(B, OIL, axial_force=AXIAL, rpm=72000.0, ball_drag=DRAG)
    ref = solve_balance(B, OIL, AXIAL, 72000.0, 0.5, DRAG_DENSITY, LIMITING_SHEAR, FILM_MODULUS, start_axis="outer")
    assert got.converged, got.message
    assert got.cage_speed == pytest.approx(ref.cage_speed, rel=1e-5)
    assert got.kinematic_cage_slip_percent == pytest.approx(ref.kinematic_cage_slip_percent, rel=2e-3)
    assert got.inner_load == pytest.approx(ref.inner_load, rel=1e-3)
    assert got.outer_load == pytest.approx(ref.outer_load, rel=1e-3)


def test_high_speed_steady_state_follows_jones():
    """Jones' high-speed picture (Harris & Kotzalas, vol. 2, ch. 3): centrifugal force opens
    the inner angle and closes the outer one, the outer load exceeds the inner by about
    m r_c w_c² along the radius, and the outer race controls the ball, whose spin axis then
    stands perpendicular to the outer contact normal (pitch angle = outer contact angle)."""
    s = steady_state(B, OIL, axial_force=AXIAL, rpm=72000.0, ball_drag=DRAG)
    a_i, a_o = math.radians(s.inner_contact_angle_deg), math.radians(s.outer_contact_angle_deg)
    assert s.outer_contact_angle_deg < 24.0 < s.inner_contact_angle_deg
    centrifugal = B.ball_mass * s.ball_orbit_radius * s.cage_speed ** 2
    assert s.outer_load * math.cos(a_o) - s.inner_load * math.cos(a_i) == pytest.approx(centrifugal, rel=0.02)
    assert B.balls * s.inner_load * math.sin(a_i) == pytest.approx(AXIAL, rel=0.02)
    assert s.attitude_xz_deg == pytest.approx(s.outer_contact_angle_deg, abs=0.5)


def test_orbit_limit_of_the_default_step():
    """The predictor's centripetal shortfall c h² r_c w_c² stays within 2 outer deflections
    (MODEL.md §10a) at the recommended step, which is a whole fraction of 1e-4 s; hand
    computed for the 72 000 rpm start state."""
    loads = solve_load_distribution(B, axial_force=AXIAL, rpm=72000.0)
    c = 0.25 * (0.5 + 1 / 3 + 0.5) ** 2 * (2 / 3)  # generalized-alpha, rho_inf 0.5: beta (1-af)/(1-am)
    r_c = B.pitch_radius + loads.ball_radius_offset
    by_hand = np.min(np.sqrt(2.0 * loads.outer_deflection / (c * r_c * loads.cage_speed ** 2)))
    assert orbit_step_limit(B, loads) == pytest.approx(by_hand, rel=1e-12)
    h = recommended_step(B, loads)
    assert h <= by_hand and (1e-4 / h) == pytest.approx(round(1e-4 / h), abs=1e-9)
    assert 1e-4 / h - 1 < 1e-4 / by_hand  # the largest such fraction


def test_dynamic_run_at_72000_rpm_holds_the_steady_state():
    """DN 2.5 million, from the steady state: the default step holds with no step cut, and
    the cage speed stays within 0.1 % of the steady solver's over 3 ms (a drift would mean
    the dynamic model and the steady balance disagree, or a start that is not a rest
    state)."""
    run = simulate(B, OIL, axial_force=AXIAL, rpm=72000.0, time=0.003, ball_drag=DRAG)
    steady = run.initial_steady_state
    assert steady is not None and steady.converged
    nominal = round(0.003 / run.solver["step"])
    assert run.steps <= nominal + 1
    assert run.cage_speed == pytest.approx(steady.cage_speed, rel=1e-3)
    assert run.kinematic_cage_slip_percent == pytest.approx(steady.kinematic_cage_slip_percent, abs=0.1)
