"""Skid criteria in closed form: the smallest axial load that keeps the balls rolling
(MODEL.md §9, §12). The model's own answer is the skid map (``skidmap.py``) and the steady
state (``steady.py``); these are the classical estimates it is compared with."""
from __future__ import annotations

import math

from .bearing import Bearing
from .presets import REFERENCE_BEARING

__all__ = ["gyroscopic_minimum_axial", "hirano_minimum_axial"]


def gyroscopic_minimum_axial(bearing: Bearing = REFERENCE_BEARING, rpm: float = 1800.0, *,
                             traction_coefficient: float = 0.047, outer_rpm: float = 0.0) -> float:
    """Jones' gyroscopic criterion (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed.,
    vol. 2, ch. 2): the smallest axial load at which the contact traction can hold the ball's
    spin axis against the gyroscopic moment, M_g <= mu (Q_i + Q_o) D / 2, N.

    Evaluated for pure rolling at the free contact angle a0 with the ball's absolute spin
    axis perpendicular to the contact line (beta = a0), where the two rolling conditions give
    w_c = P19's cage speed and the absolute spin W = (w_o (r_p + r cos a0) - w_c r_p) / r, so
    M_g = (m D²/10) w_c |W| sin a0 (MODEL.md §12), and with the fixed-angle loads
    Q_i = Q_o = F_a / (Z sin a0) (no centrifugal force: the criterion is a light-load one).

    ``traction_coefficient`` mu: the largest traction coefficient the film transmits; the
    default is the limiting-shear coefficient of the reference oil (MODEL.md §6a).
    """
    if not (isinstance(traction_coefficient, (int, float)) and math.isfinite(traction_coefficient)
            and traction_coefficient > 0):
        raise ValueError(f"traction_coefficient must be positive, got {traction_coefficient!r}")
    for name, value in (("rpm", rpm), ("outer_rpm", outer_rpm)):
        if not math.isfinite(value):
            raise ValueError(f"{name} must be finite, got {value!r}")
    w_i, w_o = rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0
    a0, r, r_p = bearing.contact_angle, bearing.ball_radius, bearing.pitch_radius
    w_c = bearing.cage_speed(w_i, w_o)
    spin = (w_o * (r_p + r * math.cos(a0)) - w_c * r_p) / r
    m_g = bearing.ball_mass * bearing.ball_diameter ** 2 / 10.0 * abs(w_c * spin) * math.sin(a0)
    # mu (Q_i + Q_o) D / 2 = mu F_a D / (Z sin a0) >= M_g
    return m_g * bearing.balls * math.sin(a0) / (traction_coefficient * bearing.ball_diameter)


def hirano_minimum_axial(bearing: Bearing, rpm: float) -> float:
    """Hirano's criterion as the paper quotes it: gross sliding when Z F_c / F_a > 0.1,
    i.e. F_a,min = 10 Z F_c with F_c = m r_p w_c² at the nominal cage speed, N."""
    cage = bearing.cage_speed(rpm * math.pi / 30.0)
    return 10.0 * bearing.balls * bearing.ball_mass * bearing.pitch_radius * cage ** 2
