"""The skid results a user reads, guarded by numbers the package does not produce.

The dynamic model runs with the package's presets (``REFERENCE_BEARING``,
``REFERENCE_LUBRICANT``, ``REFERENCE_DRAG``); the numbers it is compared with are written out
here from the paper's table 1 and MODEL.md §8 (oil, drag law) and computed by closed forms
(pure-rolling cage speed) or by the reduced steady balance of ``tests/reduced_balance.py``
(one ball's force and moment balance with gyroscopic moment and drag, independent of the
connector, builder and ``contact.kinematics``). So a changed preset, a broken drag or
traction term, or a broken solver makes a test here fail.

These runs go to settled states (0.1-2 s simulated, ~2 min wall in all): marked ``slow``,
run by CI all the same.
"""
import dataclasses
import math
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("exudyn")

sys.path.insert(0, str(Path(__file__).parent))

from contact.lubricant import Lubricant  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING  # noqa: E402
from exudyn_bearing.solvers.quasistatic import solve_load_distribution  # noqa: E402
from exudyn_bearing.simulation.runner import simulate  # noqa: E402
from reduced_balance import solve_balance  # noqa: E402

pytestmark = pytest.mark.slow

RPM = 1800.0
W_INNER = RPM * math.pi / 30
#: Jain & Hunt (2011) table 1b, with the two values the OCR lost as MODEL.md §8 fixes them
#: (c_etaP 1.75e-8 1/Pa, K_c 0.14 W/(m K)).
PAPER_OIL = Lubricant(viscosity=0.04, reference_temperature=30.0, pressure_viscosity=1.75e-8,
                      temperature_viscosity=0.05, thermal_conductivity=0.14, density=860.0)
#: MODEL.md §8: sphere drag, C_D = 0.5, fully flooded (rho_eff = 860 kg/m³).
DRAG_COEFFICIENT, OIL_DENSITY = 0.5, 860.0
#: MODEL.md §6a: the default law caps Crook's stress smoothly at Lambda p, Lambda = 0.047, a
#: representative mineral-oil value (measured 0.03-0.1: Höglund & Jacobson 1986; Wikström &
#: Höglund 1994; not traced to a primary table).
LIMITING_SHEAR = 0.047
#: MODEL.md §6b: and adds the film's elastic shear compliance (Maxwell), G = kappa p, kappa
#: 0.2953 chosen so that tau_L/G = 1/(2 pi), the ratio approached with pressure in Proc. R. Soc.
#: Lond. A 372 (1980) 155 (an input of its own, not rescaled with Lambda).
FILM_MODULUS = 0.2953


def run(axial, time, **kw):
    return simulate(axial_force=axial, rpm=RPM, time=time, **kw)


def test_without_drag_the_cage_runs_at_the_pure_rolling_speed():
    """3 kN, no drag (the traction holds every ball): the settled cage speed equals the
    pure-rolling (raceway-control) cage speed of each ball's own contact angles and spin
    axis, w_c = w_i r_A / (r_c [1 + cos(a_i - b)/cos(a_o - b)]), r_A = r_c - r cos a_i
    (MODEL.md §7; zero rolling slip at both contact centres, outer race fixed), to 0.05 %."""
    res = run(3000.0, 0.1, ball_drag=None).results
    assert res.settled()
    last = res.last()
    b = REFERENCE_BEARING
    w = res.ball_omega_orbiting[last]  # (circumferential, radial, axial)
    beta = np.arctan2(-w[..., 1], w[..., 2])  # absolute spin axis from the bearing axis, towards -e_r
    a_i, a_o = res.inner["contact_angle"][last], res.outer["contact_angle"][last]
    qs = solve_load_distribution(b, axial_force=3000.0, rpm=RPM, cage_speed=float(np.mean(res.cage_speed[last])))
    r_c = b.pitch_radius + float(np.mean(qs.ball_radius_offset))
    r_a = r_c - b.ball_radius * np.cos(a_i)
    w_roll = W_INNER * r_a / (r_c * (1.0 + np.cos(a_i - beta) / np.cos(a_o - beta)))
    cage = float(np.mean(res.cage_speed[last]))
    assert cage == pytest.approx(float(np.mean(w_roll)), rel=5e-4)
    assert abs(float(np.mean(res.kinematic_cage_slip_percent[last]))) < 0.05


@pytest.fixture(scope="module")
def balance():
    cache = {}

    def get(axial, lubricant=PAPER_OIL, drag_coefficient=DRAG_COEFFICIENT):
        key = (axial, lubricant, drag_coefficient)
        if key not in cache:
            cache[key] = solve_balance(REFERENCE_BEARING, lubricant, axial, RPM, drag_coefficient, OIL_DENSITY,
                                       LIMITING_SHEAR, FILM_MODULUS)
        return cache[key]

    return get


def check_against_balance(summary, bal, slip_rel):
    """Settled dynamic summary vs the steady balance: kinematic cage slip within ``slip_rel``
    relative, cage speed within 0.1 %, ball attitude within 0.5 deg."""
    assert summary.kinematic_cage_slip_percent == pytest.approx(bal.kinematic_cage_slip_percent, rel=slip_rel)
    assert summary.cage_speed == pytest.approx(bal.cage_speed, rel=1e-3)
    assert summary.details["attitude_xz_deg"] == pytest.approx(math.degrees(bal.attitude_xz), abs=0.5)
    assert summary.details["attitude_yz_deg"] == pytest.approx(math.degrees(bal.attitude_yz), abs=0.5)


def test_light_load_gross_sliding_matches_the_steady_balance(balance):
    """400 N with drag: the balls slide grossly (kinematic cage slip ~71 %). From the
    pure-rolling start (not the package's steady start: this is the check that the dynamics
    are attracted to the balance) the cage speed drifts by less than 0.1 % per 0.33 s only
    after ~1.7 s; it must come out ``settled`` and agree with the steady balance within 2 %
    relative (the balance neglects nothing the model has; the remaining transient at 2 s is
    ~0.03 % of the slip, the step error ~1e-3 pp)."""
    summary = run(400.0, 2.0, initial_state="rolling")
    assert summary.settled
    bal = balance(400.0)
    assert bal.kinematic_cage_slip_percent > 50  # gross sliding, not a near-rolling state
    check_against_balance(summary, bal, 0.02)
    # the film the model runs on: Hamrock-Dowson with the paper's oil (eta0 and c_etaP
    # enter as eta0^0.67 c_etaP^0.53), at the balance's entrainment and load
    film = summary.results.inner["film"][summary.results.last()]
    assert float(np.mean(film)) == pytest.approx(bal.film_inner, rel=0.01)


def test_slip_near_the_threshold_matches_the_steady_balance(balance):
    """2 kN with drag: kinematic cage slip ~1 %, at the threshold, where the ball attitude is
    set by the balance of drag, traction, spin and gyroscopic moments. Within 3 % relative of
    the balance after 0.1 s from the package's steady start (the dynamic model integrates the
    capped law with the fast rule, ~0.7 % of the traction scale, the balance with the
    accurate rule)."""
    summary = run(2000.0, 0.1)
    bal = balance(2000.0)
    assert 0.5 < bal.kinematic_cage_slip_percent < 2.0
    check_against_balance(summary, bal, 0.03)
    film = summary.results.inner["film"][summary.results.last()]
    assert float(np.mean(film)) == pytest.approx(bal.film_inner, rel=0.01)


@pytest.mark.parametrize("change", ["reference", "c_etaP 1.5e-8"])
def test_threshold_moves_the_right_way(balance, change):
    """The 1 % threshold of the reference bearing at 1800 rpm lies below 2.2 kN; lowering the
    pressure-viscosity coefficient (less traction) moves it above 2.2 kN. The slip at 2.2 kN
    (0.1 s from the package's steady start) agrees with the balance for the same inputs
    within 5 %, and sits on the stated side of 1 %.

    (Doubling the drag instead is the other lever; with the paper's law at 1.6 kN that run
    left the axisymmetric state — balls loaded up to 410 N, 65 000 steps for 1 s — so it is
    not used here; the drag itself is guarded by the tests above.)"""
    lubricant, kw = PAPER_OIL, {}
    if change != "reference":
        lubricant = dataclasses.replace(PAPER_OIL, pressure_viscosity=1.5e-8)
        kw["lubricant"] = lubricant
    summary = run(2200.0, 0.1, **kw)
    bal = balance(2200.0, lubricant)
    assert summary.kinematic_cage_slip_percent == pytest.approx(bal.kinematic_cage_slip_percent, rel=0.05)
    if change == "reference":
        assert summary.kinematic_cage_slip_percent < 1.0
    else:
        assert summary.kinematic_cage_slip_percent > 1.1
