"""A bearing at its running temperatures (MODEL.md §14f, eq. 14.9) against closed forms."""
import dataclasses
import math

import numpy as np
import pytest

from contact.bearing_thermal import ThermalModel
from contact.thermal_expansion import heated_geometry
from exudyn_bearing import CWRU_6205_BEARING, REFERENCE_BEARING, SPINDLE_40MM_BEARING, Bearing, solve_load_distribution
from exudyn_bearing.solvers.shaft import ShaftBearing, solve_shaft

ALPHA = 11.9e-6
BEARINGS = [REFERENCE_BEARING, SPINDLE_40MM_BEARING,
            Bearing.from_clearance(diametral_clearance=15e-6, **{f.name: getattr(CWRU_6205_BEARING, f.name)
                                                                 for f in dataclasses.fields(CWRU_6205_BEARING)
                                                                 if f.name != "contact_angle"})]


def _raceway_diameters(b):
    """Groove-bottom diameters d_i, d_o of MODEL.md §2's geometry, m."""
    c = math.cos(b.contact_angle)
    return (b.pitch_diameter - b.ball_diameter * (2 * b.inner_conformity - (2 * b.inner_conformity - 1) * c),
            b.pitch_diameter + b.ball_diameter * (2 * b.outer_conformity - (2 * b.outer_conformity - 1) * c))


@pytest.mark.parametrize("bearing", BEARINGS, ids=["reference", "spindle", "6205"])
def test_clearance_changes_as_harris_says(bearing):
    """ΔP_d = α_o ΔT_o d_o − α_i ΔT_i d_i − 2 α_b ΔT_b D (Harris & Kotzalas; d the raceway
    diameters), for random rises and coefficients; a uniform rise scales the bearing."""
    rng = np.random.default_rng(7)
    d_i, d_o = _raceway_diameters(bearing)
    for _ in range(5):
        ti, to, tb = rng.uniform(-5.0, 5.0, 3)  # within the 6205's 15 um of play
        ring, ball = rng.uniform(3e-6, 15e-6, 2)
        hot = bearing.expanded(ti, to, tb, ring, ball)
        expect = ring * (to * d_o - ti * d_i) - 2 * ball * tb * bearing.ball_diameter
        assert hot.diametral_clearance - bearing.diametral_clearance == pytest.approx(expect, rel=1e-6, abs=1e-15)
        assert hot.ball_mass == bearing.ball_mass
    same = bearing.expanded(30.0, 30.0, 30.0, ALPHA, ALPHA)
    assert same.contact_angle == pytest.approx(bearing.contact_angle, abs=1e-9)
    assert same.pitch_diameter == pytest.approx(bearing.pitch_diameter * (1 + 30 * ALPHA), rel=1e-12)
    assert same.inner_conformity == pytest.approx(bearing.inner_conformity, rel=1e-12)


def test_the_touching_distance_follows_pythagoras():
    """Rings held at their axial places: the added interference δ_a = T − T' with the touching
    distance T = √(A² − R²), A the groove-centre distance and R its radial part; to first order
    δ_a = −(A δA − R δR)/T, δA = ε_i R_i + ε_o R_o − ε_b D, δR = ε_i c_i − ε_o c_o (c the
    groove centres' radii, R_i, R_o the groove radii)."""
    b = SPINDLE_40MM_BEARING
    ti, to, tb = 0.2, 0.05, 0.12  # first order: δ_a/T ~ 1e-3
    g = heated_geometry(b.ball_diameter, b.pitch_diameter, b.contact_angle, b.inner_conformity, b.outer_conformity,
                        ti, to, tb, ALPHA, ALPHA)
    (c_i, _), (c_o, _) = b.groove_centres()
    a = b.groove_centre_distance
    r = c_i - c_o
    t = math.sqrt(a * a - r * r)
    d_a = ALPHA * (ti * b.inner_groove_radius + to * b.outer_groove_radius - tb * b.ball_diameter)
    d_r = ALPHA * (ti * c_i - to * c_o)
    assert g.axial_interference == pytest.approx(-(a * d_a - r * d_r) / t, rel=2e-3)
    assert g.axial_interference > 0  # the inner ring hotter: pressed harder


def test_a_clearance_that_closes_is_refused():
    with pytest.raises(ValueError, match="closes the bearing's clearance"):
        CWRU_6205_BEARING.expanded(10.0, 0.0, 5.0, ALPHA, ALPHA)  # zero clearance, inner ring hotter
    # rigid rings, growing balls: the zero-clearance 6205 pinches at the oil's inlet temperature
    from exudyn_bearing import BearingSetup, steady_state
    rigid_rings = ThermalModel(oil_inlet_temperature=353.15, ring_expansion=0.0)
    with pytest.raises(ValueError, match=r"closes the bearing's clearance \(inner ring \+60 K"):
        steady_state(BearingSetup(CWRU_6205_BEARING, thermal=rigid_rings), axial_force=300.0, rpm=1800.0)
    with pytest.raises(ValueError, match="ring_expansion"):
        ThermalModel(ring_expansion=-1e-6)
    with pytest.raises(ValueError, match="ball_expansion is a linear expansion coefficient in 1/K"):
        ThermalModel(ball_expansion=12.0)


def _pair(preload, half_span=0.05):
    back = np.diag([1.0, -1.0, -1.0])
    return [ShaftBearing(SPINDLE_40MM_BEARING, (0.0, 0.0, -half_span), np.eye(3), (0.0, 0.0, -half_span + preload)),
            ShaftBearing(SPINDLE_40MM_BEARING, (0.0, 0.0, half_span), back, (0.0, 0.0, half_span - preload))]


def test_a_preloaded_pair_tightens_as_its_inner_rings_heat():
    """The 40-mm spindle pair, 5 um of preload interference each: inner rings +10 / +20 K
    (balls half that, outer rings cold) raise the preload several times over (the thermal
    preload rise), and each bearing's preload is the single bearing's load at the new
    approach δ + δ_a (compatibility, solve_load_distribution's load-controlled path)."""
    preloads = []
    for rise in (0.0, 10.0, 20.0):
        pair = [sb.expanded(rise, 0.0, 0.5 * rise) for sb in _pair(5e-6)]
        sol = solve_shaft(pair)
        load = abs(sol.reaction_force[0, 2])
        approach = pair[0].inner_position[2] + 0.05
        single = solve_load_distribution(pair[0].bearing, axial_force=load).displacement[2]
        assert single == pytest.approx(approach, rel=1e-6)
        preloads.append(load)
    assert preloads[0] < preloads[1] < preloads[2] and preloads[2] > 5 * preloads[0]
