"""Barus viscosity (P11) and Hamrock–Dowson film thickness (P17)."""
import math

import numpy as np
import pytest

from contact import film
from contact.lubricant import REFERENCE_LUBRICANT as OIL, Lubricant


def test_barus():
    assert OIL.viscosity_at(0.0) == pytest.approx(0.04)
    assert OIL.viscosity_at(1e9) == pytest.approx(0.04 * math.exp(17.5), rel=1e-12)
    # 20 degC hotter: exp(-0.05 * 20) thinner
    assert OIL.viscosity_at(0.0, 50.0) == pytest.approx(0.04 * math.exp(-1.0), rel=1e-12)


@pytest.mark.parametrize("field,value", [("viscosity", -1.0), ("thermal_conductivity", 0.0),
                                         ("pressure_viscosity", float("nan")), ("density", -5.0)])
def test_lubricant_validation(field, value):
    kwargs = dict(viscosity=0.04, reference_temperature=30.0, pressure_viscosity=1.75e-8,
                  temperature_viscosity=0.05, thermal_conductivity=0.14, density=860.0)
    kwargs[field] = value
    with pytest.raises(ValueError, match=field):
        Lubricant(**kwargs)


def test_hamrock_dowson_by_hand_and_scaling():
    e_prime, r_x, k, q, u = 2.3077e11, 10.46e-3, 8.0, 125.0, 7.0
    hand_u = 0.04 * u / (e_prime * r_x)
    hand_g = 1.75e-8 * e_prime
    hand_w = q / (e_prime * r_x ** 2)
    hand = r_x * 2.69 * hand_u ** 0.67 * hand_g ** 0.53 * hand_w ** -0.067 * (1 - 0.61 * math.exp(-0.73 * k))
    h_c = film.central_film_thickness(u, q, r_x, k, e_prime, OIL)
    assert h_c == pytest.approx(hand, rel=1e-12)
    assert 0.1e-6 < h_c < 2e-6  # the sub-micrometre films of rolling bearings
    speeds = np.array([1.0, 2.0])
    h = film.central_film_thickness(speeds, q, r_x, k, e_prime, OIL)
    assert h[1] / h[0] == pytest.approx(2 ** 0.67, rel=1e-12)
    h_min = film.minimum_film_thickness(u, q, r_x, k, e_prime, OIL)
    assert 0.4 * h_c < h_min < h_c  # h_min/h_c is typically 0.6-0.8
    with pytest.raises(ValueError, match="load"):
        film.central_film_thickness(u, -1.0, r_x, k, e_prime, OIL)
