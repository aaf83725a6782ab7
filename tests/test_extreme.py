"""Stiff and extreme cases (issue 4): each either finishes with a finite, physically
bounded state or stops with a BearingSimulationError naming what failed. Short simulated
times here (1-4 ms); the full cases (10-60 ms) are in ``benchmarks/extreme.py``.

Bounds come from independent numbers: the applied loads, the centrifugal force
m r_p w_c², the prescribed speed ramp, and the kinetic energy of balls rolling at the
inner-race speed.
"""
import dataclasses
import math

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from exudyn_bearing import REFERENCE_BEARING, REFERENCE_LUBRICANT  # noqa: E402
from exudyn_bearing.builder import CreateAngularContactBearing  # noqa: E402
from exudyn_bearing.connector import CageModel  # noqa: E402
from exudyn_bearing.errors import BearingSimulationError  # noqa: E402
from exudyn_bearing.quasistatic import QuasiStaticError, solve_load_distribution  # noqa: E402
from exudyn_bearing.races import Driven, Fixed  # noqa: E402
from exudyn_bearing.runner import SolverSettings, run_solver  # noqa: E402

B = REFERENCE_BEARING
RPM = 1800.0


def run(time, rpm=RPM, lubricant=REFERENCE_LUBRICANT, **kw):
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    kw.setdefault("innerRace", Driven(rpm))
    h = CreateAngularContactBearing(mbs, B, lubricant, outerRace=Fixed(), show=False, **kw)
    mbs.Assemble()
    run_solver(mbs, [h], time, SolverSettings())
    return h.Results(mbs)


def assert_bounded(res, axial, w_inner_max):
    """Finite outputs, race loads within what the applied axial load and the centrifugal
    force can produce, cage between the races, ball kinetic energy below that of balls
    orbiting at the inner-race speed and spinning at d_m/D times it."""
    for name in ("cage_speed", "kinematic_cage_slip_percent", "ball_omega_orbiting"):
        assert np.all(np.isfinite(getattr(res, name))), name
    for race in (res.inner, res.outer):
        for key, arr in race.items():
            assert np.all(np.isfinite(arr)), key
    f_c = B.ball_mass * B.pitch_radius * w_inner_max ** 2  # orbit at the inner speed: an upper bound
    bound = axial / math.sin(B.contact_angle) + 2 * f_c
    assert res.inner["load"].max() < bound and res.outer["load"].max() < bound
    assert np.all(res.cage_speed > -1e-6) and np.all(res.cage_speed < w_inner_max * 1.001)
    w_ball = np.linalg.norm(res.ball_omega_orbiting, axis=-1)
    inertia = 0.4 * B.ball_mass * B.ball_radius ** 2
    energy = 0.5 * inertia * w_ball ** 2 + 0.5 * B.ball_mass * (res.ball_orbital_speed * B.pitch_radius) ** 2
    limit = 0.5 * inertia * (w_inner_max * B.pitch_diameter / B.ball_diameter) ** 2 \
        + 0.5 * B.ball_mass * (w_inner_max * B.pitch_radius) ** 2
    assert energy.max() < limit


W = RPM * math.pi / 30


def test_very_stiff_traction():
    lub = dataclasses.replace(REFERENCE_LUBRICANT, pressure_viscosity=2e-8)
    res = run(0.003, lubricant=lub, axialForce=1300.0)
    assert_bounded(res, 1300.0, W)
    assert abs(res.cage_speed[-1] / res.cage_speed_nominal[-1] - 1) < 0.05


def test_near_zero_load():
    res = run(0.003, axialForce=20.0)
    assert_bounded(res, 20.0, W)


def test_unloaded_zone_combined_load():
    """Slow speed: the balls opposite the radial load (almost) leave the inner race."""
    rpm = 100.0
    res = run(0.003, rpm=rpm, axialForce=2200.0, radialForce=2000.0)
    assert_bounded(res, 2200.0 + 2000.0, rpm * math.pi / 30)
    qs = solve_load_distribution(B, axial=2200.0, radial=2000.0, rpm=rpm)
    assert res.inner["load"][-1].min() < 1.0  # unloaded zone
    assert res.inner["load"][-1].max() == pytest.approx(qs.inner_load.max(), rel=0.05)


def test_10000_rpm():
    w = 10000 * math.pi / 30
    res = run(0.001, rpm=10000.0, axialForce=1300.0)
    assert_bounded(res, 1300.0, w)
    # centrifugal dominance: the outer contacts carry more than the inner ones
    assert res.outer["load"][-1].mean() > res.inner["load"][-1].mean() + 0.5 * B.ball_mass * B.pitch_radius \
        * (0.4 * w) ** 2


def test_speed_ramp_from_rest():
    ramp = 0.05  # 0 -> 1800 rpm in 50 ms

    def rpm(t):
        return RPM * min(max(t, 0.0) / ramp, 1.0)

    res = run(0.004, innerRace=Driven(rpm), axialForce=1300.0)
    assert_bounded(res, 1300.0, W)
    expected = np.array([rpm(t) for t in res.time]) * math.pi / 30
    assert np.allclose(res.inner_speed, expected, rtol=0, atol=1e-3 * W)


def test_axial_load_step():
    """0.2 -> 3 kN at 1 ms: the inner race rings on the contact stiffness, but averaged over
    the 2.5 ms after the step the inner contacts carry the new load axially (the race's
    momentum change over the window is small against 3 kN x 2.5 ms)."""
    step_time = 0.001

    def axial(t):
        return 200.0 if t < step_time else 3000.0

    res = run(0.004, axialForce=axial)
    assert_bounded(res, 3000.0, W)
    after = res.time > step_time + 0.0005
    carried = (res.inner["load"] * np.sin(res.inner["contact_angle"])).sum(axis=1)[after].mean()
    assert carried == pytest.approx(3000.0, rel=0.1)


def test_stiff_cage():
    res = run(0.003, cage=CageModel(stiffness=1e9), axialForce=1300.0)
    assert_bounded(res, 1300.0, W)
    assert abs(res.cage_speed[-1] / res.cage_speed_nominal[-1] - 1) < 0.05


def test_very_heavy_load_stops_with_a_diagnosis():
    """100 kN (~9 kN per ball, p_max ~2.2-2.4 GPa, Barus exponent ~40 below its bound of
    60): the traction's stiffness defeats Newton at 0.1 ms; the run must stop naming the
    contact and the Barus exponent, not return garbage."""
    try:
        res = run(0.002, axialForce=1e5)
    except BearingSimulationError as err:
        msg = str(err)
        assert "heaviest contact" in msg and "Barus exponent" in msg and "smaller step" in msg
    else:  # if it ever runs, it must be bounded
        assert_bounded(res, 1e5, W)


def test_impossible_load_pushes_a_ball_out():
    def axial(t):
        return 1300.0 if t < 0.001 else 1e8

    with pytest.raises(BearingSimulationError, match="pushed out of its groove"):
        run(0.004, axialForce=axial)


def test_infeasible_radial_load_explained():
    with pytest.raises(QuasiStaticError, match="induced axial force"):
        solve_load_distribution(B, axial=300.0, radial=3000.0, rpm=RPM)
