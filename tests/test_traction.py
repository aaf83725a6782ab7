"""Tests of contact.traction: Crook thermal EHD traction over the Hertz ellipse.

MODEL.md §5, §6 and "Traction quadrature with spin" in §8.  Every check compares with an
independent number: a closed form, a symmetry, central finite differences, or an adaptive
scipy integration over the ellipse split at the spin pole (``_scipy_reference``, coded here
from the equations, not from the module).
"""
import math

import numpy as np
import pytest
from scipy import integrate, optimize

from contact.lubricant import REFERENCE_LUBRICANT as REF
from contact.lubricant import Lubricant
from contact.traction import Traction, crook_traction, newtonian_slope, thermal_factor
from tests.helpers import _scipy_reference  # noqa: E402,F401

# reference bearing contacts (MODEL.md §8): p_max = 3Q/(2π a b)
HEAVY = dict(a=2.2e-3, b=0.14e-3, p_max=1.0e9)  # ≈ 650 N, inner race, combined load
LIGHT = dict(a=1.27e-3, b=0.083e-3, p_max=0.57e9)  # ≈ 125 N
H = 0.5e-6  # film thickness, m

# same oil, pressure-independent viscosity (c_ηP = 0): closed forms exist
ISO = Lubricant(viscosity=0.04, reference_temperature=30.0, pressure_viscosity=0.0,
                temperature_viscosity=0.05, thermal_conductivity=0.14, density=860.0)


def _forces(t):
    return np.array([t.fx, t.fy, t.mz, t.heat], dtype=float)


def _rel_errors(F, R, a, b):
    """|Δf|/|f|, |Δmz| / max(|mz|, 1 % of |f|·√(ab)), |Δheat|/heat."""
    fn = math.hypot(R[0], R[1]) + abs(R[2]) / math.sqrt(a * b)
    ef = math.hypot(F[0] - R[0], F[1] - R[1]) / fn
    em = abs(F[2] - R[2]) / max(abs(R[2]), 1e-2 * fn * math.sqrt(a * b))
    eh = abs(F[3] - R[3]) / R[3]
    return ef, em, eh


# ---------------------------------------------------------------------------------------
# 1. Newtonian small-slip limit
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("geo", [HEAVY, LIGHT, dict(a=1e-3, b=1e-3, p_max=0.3e9)])
def test_small_slip_equals_newtonian_slope(geo):
    a, b, pm = geo["a"], geo["b"], geo["p_max"]
    lam = REF.pressure_viscosity * pm
    # ∬ η dA = 2π a b η0 ∫_0^1 s e^{λ s} ds  (s = √(1 − r²)), integrated numerically here
    integral = 2 * math.pi * a * b * REF.viscosity * integrate.quad(
        lambda s: s * math.exp(lam * s), 0, 1, epsabs=0, epsrel=1e-13)[0]
    slope = integral / H
    assert newtonian_slope(a, b, pm, H, REF) == pytest.approx(slope, rel=1e-12)
    # the closed form quoted in MODEL.md/brief
    assert slope == pytest.approx(2 * math.pi * a * b * REF.viscosity
                                  * ((lam - 1) * math.exp(lam) + 1) / lam ** 2 / H, rel=1e-12)
    u = 1e-9  # ψ ≈ 1e-13: isothermal
    t = crook_traction(3 * u, -2 * u, 0.0, a, b, pm, H, REF)
    assert t.fx == pytest.approx(slope * 3 * u, rel=1e-5)
    assert t.fy == pytest.approx(slope * -2 * u, rel=1e-5)
    jac = crook_traction(0.0, 0.0, 0.0, a, b, pm, H, REF, derivatives=True).jacobian
    np.testing.assert_allclose(np.diag(jac)[:2], [slope, slope], rtol=1e-5)


def test_newtonian_slope_uniform_viscosity_limit():
    a, b = 2.0e-3, 0.5e-3
    exact = math.pi * a * b * 0.04 / H  # λ → 0: ∬ η0 dA = π a b η0
    assert newtonian_slope(a, b, 1e9, H, ISO) == pytest.approx(exact, rel=1e-14)
    assert newtonian_slope(a, b, 1e3, H, REF) == pytest.approx(exact, rel=1e-4)  # λ = 1.75e-5
    lam = np.array([1e-6, 0.3, 0.49, 0.51, 2.0])
    got = newtonian_slope(a, b, lam / REF.pressure_viscosity, H, REF)
    ref = [2 * math.pi * a * b * 0.04 / H * integrate.quad(lambda s: s * math.exp(x * s), 0, 1,
                                                           epsrel=1e-14)[0] for x in lam]
    np.testing.assert_allclose(got, ref, rtol=1e-13)


# ---------------------------------------------------------------------------------------
# 2. Signs
# ---------------------------------------------------------------------------------------
def test_traction_on_ball_points_along_race_minus_ball_slip():
    rng = np.random.default_rng(3)
    ux = rng.choice([-1, 1], 40) * 10 ** rng.uniform(-4, 0, 40)
    uy = rng.choice([-1, 1], 40) * 10 ** rng.uniform(-4, -1, 40)
    t = crook_traction(ux, uy, 0.0, **HEAVY, h=H, lubricant=REF)
    assert np.all(np.sign(t.fx) == np.sign(ux))
    assert np.all(np.sign(t.fy) == np.sign(uy))
    # a race surface faster than the ball (u_x > 0) drags the ball forward
    assert crook_traction(0.3, 0.0, 0.0, **LIGHT, h=H, lubricant=REF).fx > 0
    # with spin: dissipation, and the spin moment drags the ball's spin towards the race's
    w = rng.uniform(-300, 300, 40)
    t = crook_traction(ux, uy, w, **HEAVY, h=H, lubricant=REF)
    assert np.all(t.heat > 0)
    t = crook_traction(0.0, 0.0, w, **HEAVY, h=H, lubricant=REF)
    assert np.all(np.sign(t.mz) == np.sign(w))


# ---------------------------------------------------------------------------------------
# 3. Thermal traction curve
# ---------------------------------------------------------------------------------------
def test_thermal_factor():
    assert thermal_factor(0.0) == 1.0
    s = np.array([1e-12, 1e-4, 0.01, 0.2, 1.0, 1.51, 30.0, 1e6])
    exact = np.array([math.asinh(v) / (v * math.sqrt(1 + v * v)) for v in s])
    np.testing.assert_allclose(thermal_factor(s ** 2), exact, rtol=1e-13)
    # H = G'(s)/s against a central difference of the closed form
    g, h = thermal_factor(s[1:-1] ** 2, derivative=True)
    np.testing.assert_allclose(g, exact[1:-1], rtol=1e-13)
    v = s[2:-1]
    d = 1e-5 * v
    G = lambda z: np.arcsinh(z) / (z * np.sqrt(1 + z * z))  # noqa: E731
    np.testing.assert_allclose(h[1:], (G(v + d) - G(v - d)) / (2 * d) / v, rtol=1e-6)
    # small s: G = 1 − (2/3)s² + (8/15)s⁴ − …, so G'(s)/s = −4/3 + (32/15)s² − …
    assert h[0] == pytest.approx(-4.0 / 3.0 + 32.0 / 15.0 * 1e-8, rel=1e-12)
    assert thermal_factor(0.0, derivative=True)[1] == pytest.approx(-4.0 / 3.0, rel=1e-15)
    # the stress s G(s) = asinh(s)/sqrt(1 + s²) peaks where its derivative vanishes,
    # s asinh(s) = sqrt(1 + s²); MODEL.md §6 prints it as s ≈ 1.51
    peak = optimize.brentq(lambda v: v * math.asinh(v) - math.sqrt(1 + v * v), 0.5, 3.0, xtol=1e-14)
    assert abs(peak - 1.51) <= 0.005
    grid = np.linspace(0.5, 3.0, 25001)
    assert grid[np.argmax(grid * thermal_factor(grid ** 2))] == pytest.approx(peak, abs=2e-4)


def _uniform_viscosity_curve():
    """(u, closed-form |f|) for c_ηP = 0, no spin: f = π a b (1/h) √(8 K η/c_ηT)
    asinh(s)/√(1+s²), s = c1 |u|, over the heavy contact's ellipse."""
    a, b = HEAVY["a"], HEAVY["b"]
    eta, k, c = 0.04, 0.14, 0.05
    c1 = math.sqrt(eta * c / (8 * k))
    for u in [1e-3, 1.0, 1.51 / c1, 100.0, 1e4]:
        s = c1 * u
        yield u, math.pi * a * b / H * math.sqrt(8 * k * eta / c) * math.asinh(s) / math.sqrt(1 + s * s)


def test_uniform_viscosity_closed_form_curve():
    """c_ηP = 0: f = π a b (1/h) √(8 K η/c_ηT) asinh(s)/√(1+s²), s = c1 |u| (no spin)."""
    a, b = HEAVY["a"], HEAVY["b"]
    for u, exact in _uniform_viscosity_curve():
        t = crook_traction(0.6 * u, -0.8 * u, 0.0, a, b, 1e9, H, ISO)
        assert math.hypot(t.fx, t.fy) == pytest.approx(exact, rel=1e-10)
        assert t.fy / t.fx == pytest.approx(-0.8 / 0.6, rel=1e-12)
        assert t.heat == pytest.approx(exact * u, rel=1e-10)


def test_traction_curve_rises_peaks_and_falls():
    u = np.logspace(-5, 1.5, 60)
    f = crook_traction(u, 0.0, 0.0, **HEAVY, h=H, lubricant=REF).fx
    i = int(np.argmax(f))
    assert 5 < i < len(u) - 5
    assert np.all(np.diff(f[:i + 1]) > 0)
    assert np.all(np.diff(f[i:]) < 0)
    assert f[-1] < 0.1 * f[i]  # thermal softening: negative slope at high slip
    # traction coefficient at the peak exceeds 1 (no limiting shear, MODEL.md §8 caveat)
    load = 2 * math.pi * HEAVY["a"] * HEAVY["b"] * HEAVY["p_max"] / 3
    assert f[i] / load > 1.0


# ---------------------------------------------------------------------------------------
# 4. Spin moment
# ---------------------------------------------------------------------------------------
def test_no_spin_no_moment():
    rng = np.random.default_rng(5)
    ux, uy = rng.normal(0, 0.1, 20), rng.normal(0, 0.01, 20)
    t = crook_traction(ux, uy, 0.0, **HEAVY, h=H, lubricant=REF)
    scale = np.hypot(t.fx, t.fy) * HEAVY["a"]
    assert np.all(np.abs(t.mz) <= 1e-13 * scale)


def test_spin_moment_is_odd():
    """Mirror y → −y maps (u_x, u_y, ω) to (u_x, −u_y, −ω): fx even, fy and mz odd."""
    rng = np.random.default_rng(11)
    ux, uy, w = rng.normal(0, 0.05, 12), rng.normal(0, 0.01, 12), rng.uniform(-300, 300, 12)
    t1 = crook_traction(ux, uy, w, **HEAVY, h=H, lubricant=REF)
    t2 = crook_traction(ux, -uy, -w, **HEAVY, h=H, lubricant=REF)
    np.testing.assert_allclose(t2.fx, t1.fx, rtol=1e-12)
    np.testing.assert_allclose(t2.fy, -t1.fy, rtol=1e-12, atol=1e-12 * np.abs(t1.fx).max())
    np.testing.assert_allclose(t2.mz, -t1.mz, rtol=1e-12)
    ws = np.array([1.0, 50.0, 400.0])
    np.testing.assert_allclose(crook_traction(0.0, 0.0, -ws, **HEAVY, h=H, lubricant=REF).mz,
                               -crook_traction(0.0, 0.0, ws, **HEAVY, h=H, lubricant=REF).mz,
                               rtol=1e-12)


def test_pure_spin_isothermal_closed_form():
    """u = 0, c_ηP = 0, small ω: τ = (η/h) ω (−y, x), so M_z = +(η/h) ω ∬ (x² + y²) dA
    = +(η/h) ω π a b (a² + b²)/4.  The sign is + with the stated conventions (τ on the ball
    along race-minus-ball slip, ω_s = race − ball): a race spinning faster than the ball
    about n drags the ball's spin along (the brief's "−" does not fit those conventions)."""
    a, b = HEAVY["a"], HEAVY["b"]
    for w in [1e-3, -2e-3]:
        t = crook_traction(0.0, 0.0, w, a, b, 1e9, H, ISO)
        exact = 0.04 / H * w * math.pi * a * b * (a * a + b * b) / 4
        assert t.mz == pytest.approx(exact, rel=1e-10)
        assert abs(t.fx) < 1e-12 * abs(t.mz) / b and abs(t.fy) < 1e-12 * abs(t.mz) / b


def test_pure_spin_thermal_against_scipy():
    a, b = LIGHT["a"], LIGHT["b"]
    w = 400.0  # c1 ω a ≈ 0.1 ... thermal at the tips
    R = _scipy_reference(0.0, 0.0, w, a, b, 1e9, H, lub=ISO)
    t = crook_traction(0.0, 0.0, w, a, b, 1e9, H, ISO)
    assert t.mz == pytest.approx(R[2], rel=1e-8)
    assert t.heat == pytest.approx(R[3], rel=1e-8)


# ---------------------------------------------------------------------------------------
# 5. Quadrature convergence against adaptive scipy integration (≈ 1 s per case)
# ---------------------------------------------------------------------------------------
CONVERGENCE_CASES = {
    # name: (u_x, u_y, ω_s, geometry); pole (x_p, y_p) = (−u_y/ω, u_x/ω)
    "no spin": (0.01, 0.002, 0.0, HEAVY),
    "pole inside, thermal length 30 µm": (0.002, 0.01, 100.0, HEAVY),  # x_p = −0.71 b
    "pole near centre": (1e-4, 0.0, 150.0, HEAVY),
    "pole inside near tip": (0.0213, -0.001, 10.0, HEAVY),  # y_p = 0.97 a
    "pole just outside, x side": (0.002, -0.0143, 100.0, HEAVY),  # x_p = 1.02 b
    "pole just outside, y tip": (0.2222, 0.0005, 100.0, HEAVY),  # y_p = 1.01 a
    "light load, pole inside": (0.01, 0.002, -150.0, LIGHT),
}


@pytest.mark.parametrize("name", list(CONVERGENCE_CASES))
def test_quadrature_converges_to_scipy_reference(name):
    ux, uy, w, geo = CONVERGENCE_CASES[name]
    a, b = geo["a"], geo["b"]
    R = _scipy_reference(ux, uy, w, **geo, h=H)
    F = _forces(crook_traction(ux, uy, w, **geo, h=H, lubricant=REF))
    ef, em, eh = _rel_errors(F, R, a, b)
    assert max(ef, em, eh) < 1e-3, (name, ef, em, eh)
    # and the error falls with the order
    F32 = _forces(crook_traction(ux, uy, w, **geo, h=H, lubricant=REF, order=32))
    assert max(_rel_errors(F32, R, a, b)) < 1e-5


def test_self_convergence_random_poles():
    """Default order against order 40 over random poles in/near a 1.2 GPa contact."""
    rng = np.random.default_rng(21)
    n = 40
    a, b, pm = 2.5e-3, 0.16e-3, 1.2e9
    r = np.sqrt(rng.uniform(0, 1.3, n))
    th = rng.uniform(0, 2 * np.pi, n)
    w = rng.choice([-1, 1], n) * 10 ** rng.uniform(1, 2.5, n)
    xp, yp = b * r * np.cos(th), a * r * np.sin(th)
    args = (w * yp, -w * xp, w, a, b, pm, 0.4e-6, REF)
    F = _forces(crook_traction(*args)).T
    R = _forces(crook_traction(*args, order=40)).T
    err = np.array([max(_rel_errors(f, g, a, b)) for f, g in zip(F, R)])
    assert err.max() < 1e-3


# ---------------------------------------------------------------------------------------
# 6. Derivatives
# ---------------------------------------------------------------------------------------
def _fd_jacobian(q, geo, **kw):
    step = np.array([1e-6, 1e-6, 1e-3]) * np.maximum(1.0, np.abs(q))
    J = np.empty((3, 3))
    for j in range(3):
        e = np.zeros(3)
        e[j] = step[j]
        fp = crook_traction(*(q + e), **geo, h=H, lubricant=REF, **kw)
        fm = crook_traction(*(q - e), **geo, h=H, lubricant=REF, **kw)
        J[:, j] = (_forces(fp)[:3] - _forces(fm)[:3]) / (2 * step[j])
    return J


@pytest.mark.parametrize("q", [
    (0.02, 0.001, 0.0),  # no spin, beyond the traction peak (negative slope)
    (2e-4, 1e-4, 0.0),  # no spin, rising part
    (0.002, 0.01, 100.0),  # pole inside
    (0.0021, 0.001, 1.0),  # pole far outside
    (0.5, 0.05, -150.0),  # large slip with spin
    (0.002, -0.0143, 100.0),  # pole just outside (chords from the pole)
])
def test_jacobian_matches_finite_differences(q):
    q = np.array(q, dtype=float)
    J = crook_traction(*q, **HEAVY, h=H, lubricant=REF, derivatives=True).jacobian
    Jfd = _fd_jacobian(q, HEAVY)
    scale = np.abs(J).max(axis=1, keepdims=True)
    assert np.all(np.abs(J - Jfd) <= 1e-3 * scale)
    # f is the gradient of a dissipation potential in (u_x, u_y, ω_s): symmetric Jacobian
    np.testing.assert_allclose(J, J.T, rtol=1e-12, atol=1e-14 * scale.max())


def test_jacobian_with_limiting_shear_integrates_to_the_forces():
    """With the cap the integrand has a kink where |τ| reaches Λ p, so finite differences of
    the quadrature are noisy; check instead that the Jacobian integrated along a path
    (24-point Gauss) reproduces the change of (fx, fy, mz)."""
    x, w = np.polynomial.legendre.leggauss(24)
    x, w = 0.5 * (x + 1), 0.5 * w
    kw = dict(**HEAVY, h=H, lubricant=REF, limiting_shear=0.08, order=32)
    for q0, q1 in [((0.01, 0.002, 30.0), (0.013, 0.0015, 40.0)),
                   ((0.003, 0.0005, 0.0), (0.004, 0.001, 20.0)),
                   ((0.05, 0.01, -100.0), (0.03, 0.012, -80.0))]:
        q0, q1 = np.array(q0), np.array(q1)
        q = q0 + x[:, None] * (q1 - q0)
        jac = crook_traction(q[:, 0], q[:, 1], q[:, 2], derivatives=True, **kw).jacobian
        integral = np.einsum("k,kij,j->i", w, jac, q1 - q0)
        f0, f1 = _forces(crook_traction(*q0, **kw)), _forces(crook_traction(*q1, **kw))
        fs = math.hypot(*f0[:2])
        assert np.all(np.abs(integral[:2] - (f1 - f0)[:2]) <= 1e-2 * fs)
        assert abs(integral[2] - (f1 - f0)[2]) <= 1e-2 * (abs(f0[2]) + abs(f1[2]))


# ---------------------------------------------------------------------------------------
# 7. Vectorisation, shapes, zero slip
# ---------------------------------------------------------------------------------------
def _random_contacts(n, seed=8):
    """n generic contacts: no spin on the first three, zero slip on the fourth, the fifth
    unloaded (a = 0)."""
    rng = np.random.default_rng(seed)
    ux = rng.normal(0, 0.05, n)
    uy = rng.normal(0, 0.01, n)
    w = rng.uniform(-300, 300, n)
    w[:3] = 0.0
    ux[3], uy[3] = 0.0, 0.0
    a = rng.uniform(0.8e-3, 2.5e-3, n)
    b = a / rng.uniform(8, 16, n)
    pm = rng.uniform(0.3e9, 1.2e9, n)
    a[4] = 0.0
    h = rng.uniform(0.3e-6, 1e-6, n)
    return ux, uy, w, a, b, pm, h


def test_batch_equals_one_by_one():
    n = 14
    ux, uy, w, a, b, pm, h = _random_contacts(n)
    batch = crook_traction(ux, uy, w, a, b, pm, h, REF, derivatives=True)
    for i in range(n):
        one = crook_traction(ux[i], uy[i], w[i], a[i], b[i], pm[i], h[i], REF, derivatives=True)
        np.testing.assert_allclose(_forces(one), _forces(batch)[:, i], rtol=1e-13, atol=0)
        np.testing.assert_allclose(one.jacobian, batch.jacobian[i], rtol=1e-13, atol=0)
    assert _forces(batch)[:, 4].tolist() == [0.0, 0.0, 0.0, 0.0]


def test_shapes_and_broadcasting():
    t = crook_traction(0.01, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, derivatives=True)
    assert isinstance(t, Traction)
    assert np.shape(t.fx) == () and t.jacobian.shape == (3, 3)
    ux = np.linspace(-0.01, 0.01, 12).reshape(3, 4)
    t = crook_traction(ux, 0.001, np.array([0.0, 10.0, -100.0, 200.0]), **HEAVY, h=H,
                       lubricant=REF, derivatives=True)
    assert t.fx.shape == (3, 4) and t.mz.shape == (3, 4) and t.jacobian.shape == (3, 4, 3, 3)
    assert crook_traction(0.01, 0.0, 0.0, **HEAVY, h=H, lubricant=REF).jacobian is None


def test_zero_slip_zero_spin_is_exactly_zero_with_finite_jacobian():
    t = crook_traction([0.0, 0.0], 0.0, 0.0, **HEAVY, h=H, lubricant=REF, derivatives=True)
    assert np.all(_forces(t) == 0.0)
    assert np.all(np.isfinite(t.jacobian))
    slope = newtonian_slope(**HEAVY, h=H, lubricant=REF)
    np.testing.assert_allclose(np.diagonal(t.jacobian, axis1=-2, axis2=-1)[:, :2], slope, rtol=1e-5)
    t = crook_traction(0.0, 0.0, 1e-300, **HEAVY, h=H, lubricant=REF, derivatives=True)
    assert np.all(np.isfinite(_forces(t))) and np.all(np.isfinite(t.jacobian))


def test_transverse_axis_shorter_is_a_rotation():
    """a < b is the same problem rotated by 90° (x' = y, y' = −x)."""
    ux, uy, w = 0.002, 0.01, 100.0
    t1 = crook_traction(ux, uy, w, 2.2e-3, 0.14e-3, 1e9, H, REF)
    t2 = crook_traction(-uy, ux, w, 0.14e-3, 2.2e-3, 1e9, H, REF)  # u' = R u, R = rot(+90°)
    assert t2.fx == pytest.approx(-t1.fy, rel=1e-4)
    assert t2.fy == pytest.approx(t1.fx, rel=1e-4)
    assert t2.mz == pytest.approx(t1.mz, rel=1e-4)


def test_temperature_lowers_viscosity():
    t0 = crook_traction(1e-9, 0.0, 0.0, **LIGHT, h=H, lubricant=ISO)
    t1 = crook_traction(1e-9, 0.0, 0.0, **LIGHT, h=H, lubricant=ISO, temperature=50.0)
    assert t1.fx / t0.fx == pytest.approx(math.exp(-0.05 * 20.0), rel=1e-9)


# ---------------------------------------------------------------------------------------
# 8. Limiting shear and bad input
# ---------------------------------------------------------------------------------------
def test_limiting_shear_caps_traction():
    lam = 0.08
    load = 2 * math.pi * HEAVY["a"] * HEAVY["b"] * HEAVY["p_max"] / 3  # ∬ p dA
    u = np.logspace(-4, 1, 11)
    t = crook_traction(u, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, limiting_shear=lam)
    free = crook_traction(u, 0.0, 50.0, **HEAVY, h=H, lubricant=REF)
    assert np.all(np.hypot(t.fx, t.fy) <= lam * load * (1 + 1e-9))
    assert np.all(np.hypot(t.fx, t.fy) <= np.hypot(free.fx, free.fy) * (1 + 1e-12))
    assert np.all(t.heat > 0)
    big = crook_traction(u, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, limiting_shear=1e6)
    # a cap a million times the pressure leaves Crook's law (tanh(x)/x = 1 - x²/3: ~1e-20 here, the blend itself rounds at ~1e-11);
    # compared on the force scale, since the transverse force is round-off (~1e-14 N)
    ref = _forces(free)
    np.testing.assert_allclose(_forces(big), ref, rtol=1e-10, atol=1e-12 * np.abs(ref).max())


@pytest.mark.parametrize("name, kwargs", [
    ("h", dict(h=-1e-6)),
    ("h", dict(h=0.0)),
    ("a", dict(a=-1e-3)),
    ("b", dict(b=-1e-4)),
    ("p_max", dict(p_max=-1e9)),
    ("p_max", dict(p_max=np.nan)),
    ("u_x", dict(u_x=np.nan)),
    ("u_y", dict(u_y=np.inf)),
    ("omega_s", dict(omega_s=[0.0, np.nan])),
    ("temperature", dict(temperature=np.nan)),
    ("order", dict(order=2)),
    ("limiting_shear", dict(limiting_shear=-0.1)),
])
def test_bad_input_raises(name, kwargs):
    args = dict(u_x=0.01, u_y=0.0, omega_s=10.0, a=2.2e-3, b=0.14e-3, p_max=1e9, h=H, lubricant=REF)
    args.update(kwargs)
    with pytest.raises(ValueError, match=rf"^{name} "):
        crook_traction(**args)


def test_newtonian_slope_bad_input():
    with pytest.raises(ValueError, match="^h "):
        newtonian_slope(1e-3, 1e-4, 1e9, -1.0, REF)
    with pytest.raises(ValueError, match="^a "):
        newtonian_slope(np.nan, 1e-4, 1e9, 1e-6, REF)


# ---------------------------------------------------------------------------------------
# 9. Fast rule (fast=True) for the dynamic model
# ---------------------------------------------------------------------------------------
def _reference_contact(race, load, angle_deg):
    """(a, b, p_max, h) of a reference-bearing contact (MODEL.md §8: D = 25 mm, d_m = 155 mm,
    conformity 0.52, steel), Hamrock–Dowson film at 6 m/s entrainment."""
    from contact import film, hertz
    from contact.ballrace import RaceContact

    e_mod = hertz.effective_modulus(210e9, 0.3, 210e9, 0.3)
    r_x, con = RaceContact(0.025, 0.155, 0.52, race, e_mod, 0.064).hertz(math.radians(angle_deg))
    a, b = con.semi_axes(load)
    h = film.central_film_thickness(6.0, load, r_x, con.ellipticity, e_mod, REF)
    return float(a), float(b), float(con.max_pressure(load)), float(h)


def _dynamic_states():
    """Typical states of the dynamic model (reference bearing, 1800 rpm): inner contacts
    15–900 N with ω_s −200…−350 rad/s, outer 40–920 N with +30…+120 rad/s, slips up to
    0.5 m/s (rolling) and 0.012 m/s (transverse); spin pole at the centre, inside, near the
    edge, just outside and far outside, and no spin."""
    poles = [(0.0, 0.0), (0.02, 0.001), (0.3, 0.1), (-0.6, 0.5), (0.95, 0.0), (0.0, -0.97),
             (0.7, 0.7), (1.03, 0.0), (0.0, 1.05), (-1.3, 0.2), (0.5, 2.0), (3.0, 0.0)]
    rows = []
    for race, loads, spins in (("inner", (15.0, 150.0, 900.0), (-200.0, -350.0)),
                               ("outer", (40.0, 300.0, 920.0), (30.0, 120.0))):
        for load in loads:
            for angle in (38.0, 55.0):
                a, b, pm, h = _reference_contact(race, load, angle)
                for w in spins:
                    for xp, yp in poles:  # pole (x_p/b, y_p/a) = (−u_y/ω, u_x/ω)/(b, a)
                        ux, uy = w * yp * a, -w * xp * b
                        if abs(ux) <= 0.5 and abs(uy) <= 0.012:
                            rows.append((ux, uy, w, a, b, pm, h))
                for ux, uy in ((1e-5, 0.0), (0.01, 0.002), (0.3, -0.005)):
                    rows.append((ux, uy, 0.0, a, b, pm, h))
    return [np.array(c) for c in zip(*rows)]


def test_fast_rule_agrees_with_accurate_rule_on_dynamic_states():
    ux, uy, w, a, b, pm, h = _dynamic_states()
    assert ux.size > 150
    ref = crook_traction(ux, uy, w, a, b, pm, h, REF, order=24)
    t = crook_traction(ux, uy, w, a, b, pm, h, REF, fast=True)  # default order 16
    sab = np.sqrt(a * b)
    scale = np.hypot(ref.fx, ref.fy) + np.abs(ref.mz) / sab
    err = (np.hypot(t.fx - ref.fx, t.fy - ref.fy) + np.abs(t.mz - ref.mz) / sab) / scale
    assert err.max() < 1e-3, (err.max(), int(np.argmax(err)))
    np.testing.assert_allclose(t.heat, ref.heat, rtol=1e-3)
    # the error falls with the order of the fast rule
    t24 = crook_traction(ux, uy, w, a, b, pm, h, REF, fast=True, order=24)
    err24 = (np.hypot(t24.fx - ref.fx, t24.fy - ref.fy) + np.abs(t24.mz - ref.mz) / sab) / scale
    assert err24.max() < 3e-4


def test_fast_rule_jacobian():
    ux, uy, w, a, b, pm, h = _dynamic_states()
    ref = crook_traction(ux, uy, w, a, b, pm, h, REF, order=24, derivatives=True).jacobian
    t = crook_traction(ux, uy, w, a, b, pm, h, REF, fast=True, derivatives=True)
    J = t.jacobian
    np.testing.assert_array_equal(J, np.swapaxes(J, -1, -2))  # symmetric
    # in units of force: (u_x, u_y, √(ab) ω_s) → (f_x, f_y, M_z/√(ab))
    sc = np.stack([np.ones_like(a), np.ones_like(a), np.sqrt(a * b)], -1)
    Jn = lambda m: m / sc[:, :, None] * sc[:, None, :]  # noqa: E731
    err = np.abs(Jn(J) - Jn(ref)).max((1, 2)) / np.abs(Jn(ref)).max((1, 2))
    assert err.max() < 1e-2 and np.median(err) < 1e-5, (err.max(), np.median(err))
    # the forces do not depend on derivatives=True
    t0 = crook_traction(ux, uy, w, a, b, pm, h, REF, fast=True)
    np.testing.assert_array_equal(_forces(t0), _forces(t))


def test_fast_rule_jacobian_matches_finite_differences():
    """Central differences of the accurate rule (order 24) at typical heavy states."""
    for q, geo in (((0.002, 0.004, -300.0), _reference_contact("inner", 700.0, 45.0)),
                   ((0.05, -0.008, 60.0), _reference_contact("outer", 700.0, 40.0)),
                   ((0.02, 0.001, 0.0), _reference_contact("inner", 300.0, 50.0))):
        q = np.array(q)
        a, b, pm, h = geo
        J = crook_traction(*q, a, b, pm, h, REF, fast=True, derivatives=True).jacobian
        step = np.array([1e-6, 1e-6, 1e-3]) * np.maximum(1.0, np.abs(q))
        Jfd = np.empty((3, 3))
        for j in range(3):
            e = np.zeros(3)
            e[j] = step[j]
            fp = _forces(crook_traction(*(q + e), a, b, pm, h, REF, order=24))[:3]
            fm = _forces(crook_traction(*(q - e), a, b, pm, h, REF, order=24))[:3]
            Jfd[:, j] = (fp - fm) / (2 * step[j])
        assert np.all(np.abs(J - Jfd) <= 1e-2 * np.abs(Jfd).max(axis=1, keepdims=True))


def test_fast_rule_batch_shapes_and_unloaded_contacts():
    n = 14
    ux, uy, w, a, b, pm, h = _random_contacts(n)
    batch = crook_traction(ux, uy, w, a, b, pm, h, REF, derivatives=True, fast=True)
    assert _forces(batch)[:, 4].tolist() == [0.0, 0.0, 0.0, 0.0]
    for i in range(n):
        one = crook_traction(ux[i], uy[i], w[i], a[i], b[i], pm[i], h[i], REF, derivatives=True,
                             fast=True)
        scale = np.abs(_forces(batch)[:, i]).max() + 1e-300
        np.testing.assert_allclose(_forces(one), _forces(batch)[:, i], rtol=0, atol=1e-5 * scale)
        np.testing.assert_allclose(one.jacobian, batch.jacobian[i], rtol=0,
                                   atol=1e-5 * np.abs(batch.jacobian[i]).max())
    t = crook_traction(np.linspace(-0.01, 0.01, 12).reshape(3, 4), 0.001,
                       np.array([0.0, 10.0, -100.0, 200.0]), **HEAVY, h=H, lubricant=REF,
                       derivatives=True, fast=True)
    assert t.fx.shape == (3, 4) and t.jacobian.shape == (3, 4, 3, 3)
    t = crook_traction(0.01, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, fast=True)
    assert np.shape(t.fx) == () and t.jacobian is None
    with pytest.raises(ValueError, match="^h "):
        crook_traction(0.01, 0.0, 50.0, **HEAVY, h=-1.0, lubricant=REF, fast=True)


def test_fast_rule_closed_forms():
    a, b = HEAVY["a"], HEAVY["b"]
    for u, exact in _uniform_viscosity_curve():  # see test_uniform_viscosity_closed_form_curve
        t = crook_traction(0.6 * u, -0.8 * u, 0.0, a, b, 1e9, H, ISO, fast=True)
        assert math.hypot(t.fx, t.fy) == pytest.approx(exact, rel=1e-5)
        assert t.heat == pytest.approx(exact * u, rel=1e-5)
    # isothermal pure spin: M_z = (η/h) ω π a b (a² + b²)/4
    for w in [1e-3, -2e-3]:
        t = crook_traction(0.0, 0.0, w, a, b, 1e9, H, ISO, fast=True)
        assert t.mz == pytest.approx(0.04 / H * w * math.pi * a * b * (a * a + b * b) / 4,
                                     rel=1e-5)
    # Newtonian limit with the pressure–viscosity effect, and exact zero at zero slip
    slope = newtonian_slope(**HEAVY, h=H, lubricant=REF)
    t = crook_traction(3e-9, -2e-9, 0.0, **HEAVY, h=H, lubricant=REF, fast=True)
    assert t.fx == pytest.approx(slope * 3e-9, rel=1e-4)
    assert t.fy == pytest.approx(slope * -2e-9, rel=1e-4)
    t = crook_traction([0.0, 0.0], 0.0, [0.0, 1e-300], **HEAVY, h=H, lubricant=REF,
                       derivatives=True, fast=True)
    assert np.all(np.abs(_forces(t)) < 1e-250) and np.all(np.isfinite(t.jacobian))
    np.testing.assert_allclose(t.jacobian[0, [0, 1], [0, 1]], slope, rtol=1e-4)


def test_fast_rule_signs_and_limiting_shear():
    rng = np.random.default_rng(3)
    ux = rng.choice([-1, 1], 40) * 10 ** rng.uniform(-4, 0, 40)
    uy = rng.choice([-1, 1], 40) * 10 ** rng.uniform(-4, -1, 40)
    t = crook_traction(ux, uy, 0.0, **HEAVY, h=H, lubricant=REF, fast=True)
    assert np.all(np.sign(t.fx) == np.sign(ux)) and np.all(np.sign(t.fy) == np.sign(uy))
    w = rng.uniform(-300, 300, 40)
    assert np.all(crook_traction(ux, uy, w, **HEAVY, h=H, lubricant=REF, fast=True).heat > 0)
    t = crook_traction(0.0, 0.0, w, **HEAVY, h=H, lubricant=REF, fast=True)
    assert np.all(np.sign(t.mz) == np.sign(w))
    lam = 0.08
    load = 2 * math.pi * HEAVY["a"] * HEAVY["b"] * HEAVY["p_max"] / 3
    u = np.logspace(-4, 1, 11)
    t = crook_traction(u, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, limiting_shear=lam, fast=True)
    free = crook_traction(u, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, fast=True)
    assert np.all(np.hypot(t.fx, t.fy) <= lam * load * (1 + 1e-6))
    assert np.all(np.hypot(t.fx, t.fy) <= np.hypot(free.fx, free.fy) * (1 + 1e-6))
    acc = crook_traction(u, 0.0, 50.0, **HEAVY, h=H, lubricant=REF, limiting_shear=lam, order=32)
    np.testing.assert_allclose(t.fx, acc.fx, rtol=0, atol=1e-2 * np.abs(acc.fx).max())


def test_fast_rule_falls_back_beyond_float32_range():
    """c_ηP p_max > 40 (2.3 GPa for the reference oil) with derivatives: the accurate rule."""
    args = (0.01, 0.001, 100.0, 1.5e-3, 0.15e-3, 3e9, H, REF)
    t = crook_traction(*args, fast=True, derivatives=True)
    ref = crook_traction(*args, derivatives=True)
    np.testing.assert_array_equal(_forces(t), _forces(ref))
    np.testing.assert_array_equal(t.jacobian, ref.jacobian)
