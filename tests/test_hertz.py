"""Hertz contact (MODEL.md §3) against the exact elliptic solution and classical limits."""
import numpy as np
import pytest

from contact import hertz

E_PRIME = float(hertz.effective_modulus(210e9, 0.3))


def _both(ratio, r_x=5e-3):
    r_y = ratio * r_x
    return hertz.hertz_contact(r_x, r_y, E_PRIME, "fit"), hertz.hertz_contact(r_x, r_y, E_PRIME, "exact")


@pytest.mark.parametrize("ratio", np.geomspace(2.0, 40.0, 12))
def test_brewe_hamrock_within_3_percent_of_exact(ratio):
    fit, exact = _both(ratio)
    load = 300.0
    assert fit.stiffness == pytest.approx(exact.stiffness, rel=0.03)
    for got, ref in zip(fit.semi_axes(load), exact.semi_axes(load)):
        assert got == pytest.approx(ref, rel=0.03)


def test_fit_drifts_at_ends_of_range_as_documented():
    """docs/hertz.md tabulates the fit error; its worst figures are at alpha_r = 1 and 100."""
    errors = []
    for ratio in (1.0, 100.0):
        fit, exact = _both(ratio)
        errors.append(max(abs(fit.stiffness / exact.stiffness - 1),
                          *(abs(g / r - 1) for g, r in zip(fit.semi_axes(100.0), exact.semi_axes(100.0)))))
    assert 0.03 < max(errors) < 0.10


def test_exact_solution_is_sphere_on_flat_when_radii_equal():
    rho, load = 7e-3, 250.0
    contact = hertz.hertz_contact(rho, rho, E_PRIME, "exact")
    e_star = E_PRIME / 2  # 1/E* = sum (1 - nu²)/E
    a_ref = (3 * load * rho / (4 * e_star)) ** (1 / 3)  # Hertz 1881 (Johnson eq. 4.22)
    delta_ref = a_ref ** 2 / rho
    a, b = contact.semi_axes(load)
    assert a == pytest.approx(a_ref, rel=1e-10) and b == pytest.approx(a_ref, rel=1e-10)
    assert contact.deflection(load) == pytest.approx(delta_ref, rel=1e-10)
    assert contact.max_pressure(load) == pytest.approx(3 * load / (2 * np.pi * a_ref ** 2), rel=1e-10)
    assert contact.load(delta_ref) == pytest.approx(load, rel=1e-10)


def test_exact_ellipticity_satisfies_hertz_shape_relation():
    """Independent check of the root-find: the surface displacement of the Hertz
    ellipsoidal pressure, integrated numerically, has the curvature ratio alpha_r."""
    from scipy import integrate

    ratio = 10.0
    k, _, _ = hertz.exact_ellipticity(ratio)
    e2 = 1 - 1 / k ** 2
    # Dyson/Hertz potential: the surface displacement of p0 sqrt(1 - x²/b² - y²/a²) is
    # quadratic with coefficients proportional to int dw / ((s² + w) sqrt((a²+w)(b²+w)w)),
    # s = a for the y term and s = b for the x term (Johnson §3.6); here a = k, b = 1.
    def integral(s2):
        return integrate.quad(lambda w: 1 / ((s2 + w) * np.sqrt((k ** 2 + w) * (1 + w) * w)), 0, np.inf, limit=200)[0]
    ia, ib = integral(k ** 2), integral(1.0)
    assert ib / ia == pytest.approx(ratio, rel=1e-8)
    assert 0 < e2 < 1


def test_load_deflection_inverse_and_ball_series_stiffness():
    inner = hertz.hertz_contact(4.5e-3, 0.325, E_PRIME)
    outer = hertz.hertz_contact(7.0e-3, 0.325, E_PRIME)
    k_eff = hertz.effective_ball_stiffness(inner.stiffness, outer.stiffness)
    load = np.array([10.0, 125.0, 890.0])
    total = inner.deflection(load) + outer.deflection(load)  # springs in series, same load
    np.testing.assert_allclose(k_eff * total ** 1.5, load, rtol=1e-12)
    np.testing.assert_allclose(inner.load(inner.deflection(load)), load, rtol=1e-12)
    assert inner.load(-1e-6) == 0.0


def test_bad_input():
    with pytest.raises(ValueError, match="r_x"):
        hertz.hertz_contact(-1e-3, 1e-2, E_PRIME)
    with pytest.raises(ValueError, match="r_y"):
        hertz.hertz_contact(1e-2, 1e-3, E_PRIME)
    with pytest.raises(ValueError, match="load"):
        hertz.hertz_contact(1e-3, 1e-2, E_PRIME).deflection(np.nan)
    with pytest.raises(ValueError, match="poisson_ratio"):
        hertz.effective_modulus(210e9, 0.7)
