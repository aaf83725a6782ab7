"""Branches users reach but the main tests do not: a rotating outer race (cage speed and
P19 against Harris's closed form written out here) and the Barus-exponent cap on the
traction pressure (against the traction functions called with the capped pressure),
numpy and compiled paths alike."""
from __future__ import annotations

import math

import numpy as np
import pytest

from contact.ballrace import ContactLaw, ball_race_forces
from contact.kinematics import ball_race_kinematics
from contact.terms import term_record
from contact.traction import crook_traction
from exudyn_bearing import REFERENCE_BEARING as B
from exudyn_bearing import REFERENCE_LUBRICANT as LUB
from exudyn_bearing.results.outputs import cage_slip

# the paper's bearing (table 1a), typed here rather than read from the preset
D, D_M, ALPHA = 25e-3, 155e-3, math.radians(40.0)
GAMMA = D * math.cos(ALPHA) / D_M


def harris_cage_speed(w_i, w_o, alpha=ALPHA):
    """Pure-rolling cage speed (Harris): w_c = w_i/2 (1 - g) + w_o/2 (1 + g), g = D cos a / d_m."""
    g = D * math.cos(alpha) / D_M
    return 0.5 * w_i * (1 - g) + 0.5 * w_o * (1 + g)


def p19(reference, cage):
    """P19 cage slip, %: (w_ref - w_c) / ((w_ref + w_c) / 2) * 100."""
    return 100.0 * (reference - cage) / (0.5 * (reference + cage))


# ---------------------------------------------------------------------------------------
# rotating outer race: Bearing.cage_speed and P19
# ---------------------------------------------------------------------------------------
def test_reference_bearing_is_the_papers():
    assert (B.ball_diameter, B.pitch_diameter) == (D, D_M)
    assert B.contact_angle == pytest.approx(ALPHA, rel=1e-15)


@pytest.mark.parametrize("rpm_i,rpm_o", [
    (1800.0, 0.0),  # the paper's case
    (0.0, 1800.0),  # stationary inner race, rotating outer race
    (0.0, -600.0),
    (1800.0, -600.0),  # counter-rotation
    (-1800.0, 600.0),
    (1800.0, 600.0),  # co-rotation
])
def test_cage_speed_closed_form_with_rotating_outer_race(rpm_i, rpm_o):
    w_i, w_o = rpm_i * RPM, rpm_o * RPM
    assert B.cage_speed(w_i, w_o) == pytest.approx(harris_cage_speed(w_i, w_o), rel=1e-13, abs=1e-12)
    alpha = math.radians(30.0)
    assert B.cage_speed(w_i, w_o, contact_angle=alpha) == pytest.approx(harris_cage_speed(w_i, w_o, alpha),
                                                                         rel=1e-13, abs=1e-12)


def test_cage_speed_limits():
    """Both races at the same speed: the bearing turns as a rigid body, cage included.
    Counter-rotating at w_o = -w_i (1 - g)/(1 + g): the cage stands still. Stationary inner
    race: the cage turns with the outer race at (1 + g)/2 of its speed, faster than
    (1 - g)/2 of an inner race at the same speed."""
    w = 150.0
    assert B.cage_speed(w, w) == pytest.approx(w, rel=1e-14)
    assert B.cage_speed(w, -w * (1 - GAMMA) / (1 + GAMMA)) == pytest.approx(0.0, abs=1e-12)
    assert B.cage_speed(0.0, w) / w == pytest.approx((1 + GAMMA) / 2, rel=1e-14)
    assert B.cage_speed(0.0, w) > B.cage_speed(w, 0.0)


@pytest.mark.parametrize("rpm_i,rpm_o", [(0.0, 1800.0), (1800.0, -600.0), (1800.0, 600.0)])
def test_p19_with_rotating_outer_race(rpm_i, rpm_o):
    """P19 of a cage 3 % slower and 2 % faster than Harris's pure-rolling speed."""
    w_th = harris_cage_speed(rpm_i * RPM, rpm_o * RPM)
    nominal = B.cage_speed(rpm_i * RPM, rpm_o * RPM)
    for factor in (0.97, 1.02):
        w_c = factor * w_th
        assert float(cage_slip(nominal, w_c)) == pytest.approx(p19(w_th, w_c), rel=1e-12)
        assert float(cage_slip(nominal, w_c)) == pytest.approx(200 * (1 - factor) / (1 + factor), rel=1e-12)


exu = pytest.importorskip("exudyn")

from exudyn_bearing import races  # noqa: E402
from exudyn_bearing.model.builder import CreateAngularContactBearing  # noqa: E402
from exudyn_bearing.simulation.runner import SolverSettings, run_solver  # noqa: E402
from tests.helpers import INNER, RPM, R_I, R_O, TUBE_I, TUBE_O, W_RACE, Z_I, Z_O, _inner_contacts  # noqa: E402,F401


@pytest.mark.parametrize("rpm_i,rpm_o", [(0.0, 600.0), (1800.0, -600.0)],
                         ids=["stationary inner, outer 600 rpm", "inner 1800, outer -600 rpm"])
def test_dynamic_run_with_rotating_outer_race(rpm_i, rpm_o):
    """5 ms at 3 kN axial, no drag: the traction holds (kinematic slip ~0), so the cage runs
    at the pure-rolling speed of the actual contact angles. Harris's closed form takes the
    nominal 40 deg; at 3 kN the angles sit within 1.5 deg of it, which moves the rolling
    speed by at most |w_i - w_o|/2 D/d_m max|cos a - cos 40 deg| (computed from the run's
    angles, below 0.6 % of w_c here); with 0.2 % for slip the cage stays within 1 % of the
    closed form. The reported nominal speed and P19 are the closed form's."""
    w_i, w_o = rpm_i * RPM, rpm_o * RPM
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    handle = CreateAngularContactBearing(mbs, B, LUB, innerRace=races.Driven(rpm_i), outerRace=races.Fixed(rpm=rpm_o),
                                         axialForce=3000.0, ballDrag=None, show=False)
    mbs.Assemble()
    run_solver(mbs, [handle], 0.005, SolverSettings())
    res = handle.Results(mbs)
    np.testing.assert_allclose(res.inner_speed, w_i, rtol=0, atol=1e-9 * (abs(w_i) + abs(w_o)))
    np.testing.assert_allclose(res.outer_speed, w_o, rtol=0, atol=1e-9 * (abs(w_i) + abs(w_o)))
    w_th = harris_cage_speed(w_i, w_o)
    # the reported nominal speed and P19 are the closed form's
    np.testing.assert_allclose(res.cage_speed_nominal, w_th, rtol=1e-12)
    np.testing.assert_allclose(res.cage_slip_percent, p19(w_th, res.cage_speed), rtol=1e-9, atol=1e-9)
    # why the measured cage speed must sit within 1 % of it
    angles = np.concatenate([res.inner["contact_angle"].ravel(), res.outer["contact_angle"].ravel()])
    assert np.max(np.abs(angles - ALPHA)) < math.radians(1.5)
    angle_shift = 0.5 * abs(w_i - w_o) * D / D_M * np.max(np.abs(np.cos(angles) - math.cos(ALPHA)))
    tolerance = angle_shift + 0.002 * abs(w_th)
    assert tolerance < 0.01 * abs(w_th)
    assert np.max(np.abs(res.kinematic_cage_slip_percent)) < 0.1  # the traction holds
    second_half = res.time >= 0.5 * res.time[-1]
    assert np.max(np.abs(res.cage_speed[second_half] - w_th)) < tolerance
    assert np.max(np.abs(res.cage_slip_percent[second_half])) < 100 * tolerance / abs(w_th) * 1.01


# 20 um: p_max ~1.9 GPa, below the cap; 100 um: ~4.2 GPa, above 60 / c_etaP = 3.43 GPa
APPROACHES = (20e-6, 100e-6)


def _traction_reference(kin, forces, law, cap):
    """The traction functions called directly: with p_max replaced by min(p_max, cap), and
    with the raw p_max; a, b from the Hertz fits at the contact's angle and load."""
    _r_x, contact = INNER.hertz(kin.contact_angle, law.hertz_method)
    a, b = contact.semi_axes(forces.normal_load)
    np.testing.assert_allclose(forces.max_pressure, 1.5 * forces.normal_load / (math.pi * a * b), rtol=1e-12)
    args = (kin.slip_rolling, kin.slip_transverse, kin.spin, a, b)
    kw = dict(order=law.quadrature_order, fast=law.fast_quadrature)
    capped = crook_traction(*args, np.minimum(forces.max_pressure, cap), forces.film_thickness, LUB, **kw)
    raw = crook_traction(*args, forces.max_pressure, forces.film_thickness, LUB, **kw)
    return capped, raw


@pytest.mark.parametrize("exponent", [60.0, 40.0])
def test_barus_cap_numpy_path(exponent):
    law = ContactLaw(traction="crook", max_barus_exponent=exponent)  # the cap alone, no limiting shear
    assert ContactLaw().max_barus_exponent == 60.0
    cap = exponent / LUB.pressure_viscosity
    c, v, w = _inner_contacts(APPROACHES)
    kin = ball_race_kinematics(c, v, w, np.zeros(3), np.eye(3), np.zeros(3), W_RACE, (R_I, Z_I, TUBE_I),
                               B.ball_radius, "inner")
    forces = ball_race_forces(kin, INNER, LUB, law)
    p_max = forces.max_pressure
    assert p_max[0] < cap < p_max[1] and p_max[1] > 1.15 * cap
    capped, raw = _traction_reference(kin, forces, law, cap)
    for got, ref_capped, ref_raw in ((forces.traction_rolling, capped.fx, raw.fx),
                                     (forces.traction_transverse, capped.fy, raw.fy),
                                     (forces.spin_moment, capped.mz, raw.mz)):
        np.testing.assert_allclose(got, ref_capped, rtol=1e-12)
        # below the cap nothing changes; above it the uncapped traction is >10 % larger
        assert ref_raw[0] == ref_capped[0]
        assert abs(ref_raw[1]) > 1.1 * abs(ref_capped[1])
        assert abs(got[1] - ref_raw[1]) > 0.1 * abs(ref_raw[1])


@pytest.mark.parametrize("exponent", [60.0, 40.0])
def test_barus_cap_compiled_kernel(exponent):
    """contact.kernels.race_contacts on the same states: the traction read back from the
    force (F . t1, F . t2) and the moment (M . n) matches the capped reference within the
    fast rule's float32 agreement with the numpy rule (3e-4 of the force scale), far from
    the uncapped value."""
    compiled = pytest.importorskip("contact.kernels")
    law = ContactLaw(traction="crook", max_barus_exponent=exponent)
    cap = exponent / LUB.pressure_viscosity
    c, v, w = _inner_contacts(APPROACHES)
    kin = ball_race_kinematics(c, v, w, np.zeros(3), np.eye(3), np.zeros(3), W_RACE, (R_I, Z_I, TUBE_I),
                               B.ball_radius, "inner")
    forces = ball_race_forces(kin, INNER, LUB, law)
    z = len(APPROACHES)
    ro, rv, rw = np.zeros((1, 2, 3)), np.zeros((1, 2, 3)), np.zeros((1, 2, 3))
    rw[0, 0] = W_RACE
    rr = np.repeat(np.eye(3)[None, None], 2, axis=1).copy()
    force, moment = np.zeros((1, 2, z, 3)), np.zeros((1, 2, z, 3))
    penetration, load = np.zeros((1, 2, z)), np.zeros((1, 2, z))
    geometry = compiled.RaceGeometry(np.array([[R_I, Z_I, TUBE_I], [R_O, Z_O, TUBE_O]]),
                                     np.array([B.inner_conformity, B.outer_conformity]), np.array([-1.0, 1.0]),
                                     B.ball_radius, B.pitch_diameter, B.effective_modulus, B.ball_mass)
    compiled.race_contacts(compiled.BallStates(c[None], v[None], w[None], np.empty((1, 0, 3, 3))), compiled.RaceFrames(ro, rr, rv, rw),
                           geometry, (compiled.law_record(law, LUB),) * 2, compiled.crook_tables(law.quadrature_order),
                           term_record(law, LUB, B.ball_diameter),
                           compiled.ContactOutputs(force, moment, penetration, load, np.zeros((1, 2, z, 4))))
    np.testing.assert_allclose(load[0, 0], forces.normal_load, rtol=1e-12)
    assert np.all(load[0, 1] == 0.0)  # clear of the outer race
    f_in, m_in = force[0, 0], moment[0, 0]
    got = (np.einsum("ij,ij->i", f_in, kin.rolling), np.einsum("ij,ij->i", f_in, kin.transverse),
           np.einsum("ij,ij->i", m_in, kin.normal))
    capped, raw = _traction_reference(kin, forces, law, cap)
    scale = np.hypot(capped.fx, capped.fy)
    a_long = np.maximum(*INNER.hertz(kin.contact_angle)[1].semi_axes(forces.normal_load))
    for name, g, ref_capped, ref_raw, s in (("fx", got[0], capped.fx, raw.fx, scale),
                                            ("fy", got[1], capped.fy, raw.fy, scale),
                                            ("mz", got[2], capped.mz, raw.mz, scale * a_long)):
        assert np.all(np.abs(g - ref_capped) < 3e-4 * s), name
        assert abs(g[1] - ref_raw[1]) > 0.1 * abs(ref_raw[1]), name
