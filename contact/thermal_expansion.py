"""A bearing's geometry at its running temperatures (MODEL.md §14f), pure Python.

The bearing's dimensions are given at its assembly temperature. Each ring grows radially
about the bearing axis by ε = α ΔT at its own temperature rise (its groove radius with it),
the balls by ε_b = α_b ΔT_b. With the groove-centre circles of MODEL.md §2 (inner at
(r_p + r_i cos α0, r_i sin α0), outer at (r_p − r_o cos α0, −r_o sin α0), r = (f − ½) D):

    c_i' = (1 + ε_i) (r_p + r_i cos α0),   c_o' = (1 + ε_o) (r_p − r_o cos α0)   (radii),
    R_i' = (1 + ε_i) f_i D,   R_o' = (1 + ε_o) f_o D,   D' = (1 + ε_b) D,
    A' = R_i' + R_o' − D',   cos α0' = (c_i' − c_o') / A',   r_p' = c_i' − (R_i' − D'/2) cos α0'.   (14.9)

The rings' axial growth about the ball's plane is left out (ε r sin α0 < 0.3 µm for a 35-mm
bearing at 150 K). The diametral clearance then changes by
ΔP_d = α_o ΔT_o d_o − α_i ΔT_i d_i − 2 α_b ΔT_b D (d the groove-bottom diameters; Harris &
Kotzalas, *Essential Concepts of Bearing Technology*, on the thermal change of clearance),
exactly, since the clearance is linear in the ε's,
and rings held at their axial positions (a preloaded pair's spacers) press the balls
further by the change of the touching distance, δ_a = A sin α0 − A' sin α0'.
"""
from __future__ import annotations

import math
from typing import NamedTuple

__all__ = ["HeatedGeometry", "heated_geometry"]


class HeatedGeometry(NamedTuple):
    """A bearing's geometry at its running temperatures (eq. 14.9; m, rad)."""

    ball_diameter: float  #: D', m
    pitch_diameter: float  #: d_m', m
    inner_conformity: float  #: f_i' = R_i'/D'
    outer_conformity: float  #: f_o' = R_o'/D'
    contact_angle: float  #: free contact angle α0', rad
    axial_interference: float  #: δ_a = A sin α0 − A' sin α0', m (> 0: rings at fixed axial places press harder)


def heated_geometry(ball_diameter, pitch_diameter, contact_angle, inner_conformity, outer_conformity,
                    rise_inner, rise_outer, rise_balls, ring_expansion, ball_expansion) -> HeatedGeometry:
    """The geometry of eq. 14.9 for temperature rises (K) of the inner ring, the outer ring and
    the balls above the assembly temperature, with the rings' and the balls' linear expansion
    coefficients (1/K); sizes in m, the free contact angle α0 in rad.

    Raises ValueError where the expansion closes the clearance (α0' would be imaginary: the
    balls are pinched radially, which the free-contact-angle geometry cannot hold).
    """
    for name, value in (("rise_inner", rise_inner), ("rise_outer", rise_outer), ("rise_balls", rise_balls),
                        ("ring_expansion", ring_expansion), ("ball_expansion", ball_expansion)):
        if not math.isfinite(value):
            raise ValueError(f"{name} must be a finite number, got {value!r}")
    d, r_p, alpha = float(ball_diameter), 0.5 * float(pitch_diameter), float(contact_angle)
    eps_i = ring_expansion * rise_inner
    eps_o = ring_expansion * rise_outer
    eps_b = ball_expansion * rise_balls
    r_i, r_o = (inner_conformity - 0.5) * d, (outer_conformity - 0.5) * d
    centre_i = (1.0 + eps_i) * (r_p + r_i * math.cos(alpha))
    centre_o = (1.0 + eps_o) * (r_p - r_o * math.cos(alpha))
    d_new = (1.0 + eps_b) * d
    groove_i, groove_o = (1.0 + eps_i) * inner_conformity * d, (1.0 + eps_o) * outer_conformity * d
    reach = groove_i + groove_o - d_new  # A'
    cosine = (centre_i - centre_o) / reach
    if 1.0 < cosine <= 1.0 + 1e-12:  # a zero-clearance bearing scaled uniformly: rounding
        cosine = 1.0
    if not cosine <= 1.0:
        closed = (centre_i - centre_o - reach) * 2.0
        raise ValueError(
            f"thermal expansion closes the bearing's clearance (inner ring {rise_inner:+.3g} K, outer ring "
            f"{rise_outer:+.3g} K, balls {rise_balls:+.3g} K: {closed * 1e6:.3g} um of diametral interference); "
            "the balls are pinched radially, which the model's geometry cannot hold")
    angle = math.acos(cosine)
    pitch_radius = centre_i - (groove_i - 0.5 * d_new) * cosine
    touching = (r_i + r_o) * math.sin(alpha)
    return HeatedGeometry(d_new, 2.0 * pitch_radius, groove_i / d_new, groove_o / d_new, angle,
                          touching - reach * math.sin(angle))
