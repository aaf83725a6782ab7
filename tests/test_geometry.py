"""Groove torus geometry and curvature radii (MODEL.md §2)."""
import math

import numpy as np
import pytest

from contact import geometry
from exudyn_bearing import REFERENCE_BEARING as B


def test_curvature_radii_reference_bearing_by_hand():
    alpha = math.radians(40)
    # inner R_x = r (r_p - r cos a) / r_p, with r = 12.5 mm, r_p = 77.5 mm
    r, rp = 12.5e-3, 77.5e-3
    rx_i, ry_i = geometry.curvature_radii(25e-3, 155e-3, alpha, 0.52, "inner")
    rx_o, ry_o = geometry.curvature_radii(25e-3, 155e-3, alpha, 0.52, "outer")
    assert rx_i == pytest.approx(r * (rp - r * math.cos(alpha)) / rp, rel=1e-14)
    assert rx_o == pytest.approx(r * (rp + r * math.cos(alpha)) / rp, rel=1e-14)
    assert ry_i == pytest.approx(13e-3 / 0.04, rel=1e-14) and ry_o == ry_i  # f D / (2f - 1) = 325 mm
    assert 23 < ry_i / rx_i < 31 and 23 < ry_o / rx_o < 31  # MODEL.md: the bearing sits at 23–30


def test_free_angle_and_clearance_are_one_quantity():
    # P_d = 2 (f_i + f_o - 1) D (1 - cos a0); MODEL.md §2 prints 0.468 mm
    p_d = 2 * (0.52 + 0.52 - 1) * 25e-3 * (1 - math.cos(math.radians(40)))
    assert B.diametral_clearance == pytest.approx(p_d, rel=1e-12)
    assert abs(p_d * 1e3 - 0.468) <= 0.0005
    angle = geometry.free_contact_angle(B.diametral_clearance, 0.52, 0.52, 25e-3)
    assert angle == pytest.approx(math.radians(40), rel=1e-12)
    assert geometry.free_contact_angle(0.0, 0.52, 0.53, 11.1e-3) == 0.0  # deep groove, P_d = 0
    with pytest.raises(ValueError, match="clearance"):
        geometry.free_contact_angle(1e-2, 0.52, 0.52, 25e-3)


@pytest.mark.parametrize("race", ["inner", "outer"])
@pytest.mark.parametrize("psi", [0.0, 1.1, 4.0])
def test_torus_penetration_normal_and_angle(race, psi):
    """A ball moved by delta along the contact normal of the free position penetrates
    the groove by exactly delta, at the free contact angle, at any azimuth."""
    (ri, zi), (ro, zo) = B.groove_centres()
    radius, z0 = (ri, zi) if race == "inner" else (ro, zo)
    tube = 0.02 * B.ball_diameter
    a0 = B.contact_angle
    sign = 1.0 if race == "outer" else -1.0
    e_r = np.array([math.cos(psi), math.sin(psi), 0.0])
    n_expected = sign * (math.cos(a0) * e_r + np.array([0, 0, math.sin(a0)]))
    for delta in (-3e-6, 0.0, 7e-6):
        centre = B.pitch_radius * e_r + delta * n_expected
        con = geometry.groove_contact(centre[None], radius, z0, tube, race)
        assert con.penetration[0] == pytest.approx(delta, abs=1e-15)
        np.testing.assert_allclose(con.normal[0], n_expected, atol=1e-12)
        assert con.contact_angle[0] == pytest.approx(a0, abs=1e-9)
        # contact point p = c + r n lies on the groove surface: |p - g| = f D
        point = centre + B.ball_radius * con.normal[0]
        assert np.linalg.norm(point - con.groove_centre[0]) == pytest.approx(tube + B.ball_radius + delta, abs=1e-15)
