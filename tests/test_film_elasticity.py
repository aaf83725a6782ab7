"""The film's elastic shear compliance (MODEL.md §6b) against closed forms."""
import numpy as np
import pytest

from contact.film_elasticity import compliance_factor, elastic_stress, maxwell_streamline


def ellipse_nodes(a, b, n=200):
    """Gauss nodes and weights over x²/b² + y²/a² ≤ 1 (x = b r cos t, y = a r sin t)."""
    r, wr = np.polynomial.legendre.leggauss(n)
    r, wr = 0.5 * (r + 1), 0.5 * wr
    t = 2 * np.pi * (np.arange(4 * n) + 0.5) / (4 * n)
    R, T = np.meshgrid(r, t, indexing="ij")
    W = np.outer(wr * r, np.full(t.size, 2 * np.pi / t.size)) * a * b
    return b * R * np.cos(T), a * R * np.sin(T), W


@pytest.mark.parametrize("entrainment", [3.0, -2.0])
def test_elastic_traction_of_a_non_spinning_contact(entrainment):
    """No spin: τ_e = G ξ u/(|ū| h), ∬ ξ dA = (8/3) a b² (ξ from the inlet edge), so
    |f| = (8/3) G a b² |u| / (|ū| h) — STIFFNESS.md's elastic initial slope."""
    a, b, h, G = 1.4e-3, 0.2e-3, 0.3e-6, 1e9
    u = np.array([1e-3, -4e-4])
    x, y, W = ellipse_nodes(a, b)
    tau = elastic_stress(x, y, a, b, u[0], u[1], 0.0, entrainment, h, G)
    force = np.sum(W * tau)
    assert force == pytest.approx(8 / 3 * G * a * b ** 2 * np.hypot(*u) / (abs(entrainment) * h), rel=1e-6)


def test_stress_grows_from_the_inlet_edge():
    a, b = 1e-3, 0.5e-3
    x = np.linspace(-b, b, 5)
    tau = elastic_stress(x, 0.0, a, b, 1.0, 0.0, 0.0, 1.0, 1e-6, 1e9)  # inlet at x = -b for u > 0
    assert tau[0] == 0 and np.all(np.diff(tau) > 0)
    tau_rev = elastic_stress(x, 0.0, a, b, 1.0, 0.0, 0.0, -1.0, 1e-6, 1e9)  # inlet at +b
    assert tau_rev[-1] == 0 and np.allclose(tau_rev, tau[::-1])


def test_spin_term_is_the_integral_of_the_slip_field():
    """With spin, ∫ u dx' from the inlet at a point equals the closed form's vector."""
    a, b, om, ux, uy = 1e-3, 0.4e-3, 30.0, 2e-3, -1e-3
    x, y = 0.1e-3, 0.3e-3
    x_in = -b * np.sqrt(1 - (y / a) ** 2)
    s = np.linspace(x_in, x, 20001)
    def trapezoid(f):
        return float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(s)))

    vx = trapezoid(ux - om * y + 0 * s)
    vy = trapezoid(uy + om * s)
    expect = 1e9 * np.hypot(vx, vy) / (2.0 * 1e-6)
    got = elastic_stress(x, y, a, b, ux - om * y, uy + om * x, om, 2.0, 1e-6, 1e9)
    assert got == pytest.approx(expect, rel=1e-8)


def test_compliance_limits():
    """τ = τ_v (1 − e^(−|τ_e|/τ_v)): the elastic stress where it is the smaller, Crook's where
    the elastic limit is far (or infinite), 0 at the inlet edge."""
    g = np.array([1e12, 1e12, 1e12, 5.0, 1e12, 3.0])
    slip = np.array([1e-9, 1.0, 0.0, 1.0, 1e-3, 0.0])
    elastic = np.array([1e-3, 1e3, 0.0, np.inf, 1e9, 2.0])
    f = compliance_factor(g, slip, elastic)
    assert g[0] * slip[0] * f[0] == pytest.approx(1e-3, rel=1e-6)  # |τ_e| ≪ τ_v: |τ| = |τ_e|
    assert g[1] * slip[1] * f[1] == pytest.approx(1e3, rel=1e-6)
    assert f[2] == 1.0 and f[3] == 1.0 and f[5] == 1.0
    assert f[4] == pytest.approx(1 - np.exp(-1.0), rel=1e-12)  # |τ_e| = τ_v
    assert np.all((f >= 0) & (f <= 1))


# ---------------------------------------------------------------------------------------
# The compliance in the traction rules (accurate, numpy fast, compiled fast)
# ---------------------------------------------------------------------------------------
import dataclasses  # noqa: E402

from contact import kernels as compiled  # noqa: E402
from contact.ballrace import ContactLaw  # noqa: E402
from contact.lubricant import REFERENCE_LUBRICANT as REF  # noqa: E402
from contact.traction import crook_traction  # noqa: E402

KAPPA = 0.2953  # G/p, chosen so that Λ/κ = 0.047/0.2953 = 1/(2π) (MODEL.md §6b)
CONTACT = (1.4e-3, 0.2e-3, 1.7e9, 0.3e-6)  # a (transverse), b (rolling), p_max, h: STIFFNESS.md's contact
STIFF_OIL = dataclasses.replace(REF, viscosity=1e4)  # viscous stress >> elastic everywhere


def _rules(ux, uy, om, a, b, pm, h, lub, ent, lam=None):
    """(fx, fy, mz) by the accurate rule (order 32), the numpy fast rule and the compiled one."""
    kw = dict(limiting_shear=lam, film_modulus=KAPPA, entrainment=ent)
    acc = crook_traction(ux, uy, om, a, b, pm, h, lub, order=32, **kw)
    fast = crook_traction(ux, uy, om, a, b, pm, h, lub, fast=True, **kw)
    comp = compiled.crook_fast(*([v] for v in (ux, uy, om, a, b, pm, h)), lub, **kw)
    return {"accurate": (float(acc.fx), float(acc.fy), float(acc.mz)),
            "fast": (float(fast.fx), float(fast.fy), float(fast.mz)),
            "compiled": tuple(float(v[0]) for v in comp[:3])}


@pytest.mark.parametrize("entrainment", [3.0, -2.0])
def test_rules_reach_the_elastic_slope_of_a_pressure_proportional_modulus(entrainment):
    """G = κ p, p = p_max √(1 − X² − Y²): ∬ p ξ dA = p_max a b² ∫ (π/2)(1 − Y²)^{3/2} dY
    = (3π²/16) p_max a b², so in the elastic limit f = κ (3π²/16) p_max a b² u/(|ū| h)."""
    a, b, pm, h = CONTACT
    u = (2e-6, -1e-6)
    slope = KAPPA * 3 * np.pi ** 2 / 16 * pm * a * b ** 2 / (abs(entrainment) * h)
    for name, (fx, fy, _) in _rules(u[0], u[1], 0.0, a, b, pm, h, STIFF_OIL, entrainment).items():
        # the viscous compliance left (η 1e4 Pa s) is ~1e-4 of the elastic one
        assert fx == pytest.approx(slope * u[0], rel=2e-3), name
        assert fy == pytest.approx(slope * u[1], rel=2e-3), name


def _elastic_spin_moment(om, a, b, pm, h, ent, n=160):
    """M_z of the elastic stress |τ_e| = κ p |ξ| |w|/(|ū| h), w = (−ω y, ω x − ω ξ/2) the
    strain integrated from the inlet edge x_in = −sign(ū) b √(1 − y²/a²), ξ = x − x_in,
    directed along the local slip u = ω (−y, x) as the series law puts it (MODEL.md §6b),
    written here by Gauss quadrature."""
    r, wr = np.polynomial.legendre.leggauss(n)
    r, wr = 0.5 * (r + 1), 0.5 * wr
    t = 2 * np.pi * (np.arange(4 * n) + 0.5) / (4 * n)
    R, T = np.meshgrid(r, t, indexing="ij")
    W = np.outer(wr * r, np.full(t.size, 2 * np.pi / t.size)) * a * b
    x, y = b * R * np.cos(T), a * R * np.sin(T)
    p = pm * np.sqrt(np.maximum(1 - R ** 2, 0))
    xi = x + np.sign(ent) * b * np.sqrt(np.maximum(1 - (y / a) ** 2, 0))
    mag = KAPPA * p * np.abs(xi) / (abs(ent) * h) * np.hypot(om * y, om * x - 0.5 * om * xi)
    ux, uy = -om * y, om * x
    speed = np.hypot(ux, uy)
    tx, ty = mag * ux / speed, mag * uy / speed
    return float(np.sum(W * (x * ty - y * tx)))


@pytest.mark.parametrize("entrainment", [3.0, -2.0])
def test_rules_reach_the_elastic_spin_moment(entrainment):
    """Pure spin in the elastic limit: the spin moment of the rules equals the moment of the
    elastic stress integrated by brute force (the quadratures follow the spin pole, which
    here sits at the centre)."""
    a, b, pm, h = CONTACT
    om = 1e-3  # rad/s: small enough for the elastic limit at η 1e4 Pa s
    ref = _elastic_spin_moment(om, a, b, pm, h, entrainment)
    for name, (fx, fy, mz) in _rules(0.0, 0.0, om, a, b, pm, h, STIFF_OIL, entrainment).items():
        assert mz == pytest.approx(ref, rel=5e-3), name
        assert abs(fx) < 1e-3 * abs(ref) / b  # no net force from a centred spin


def test_slow_entrainment_leaves_the_crook_law():
    """|τ_e| ∝ 1/|ū|: at ū → 0 the oil stays in the contact and the law is Crook's (capped)."""
    a, b, pm, h = CONTACT
    for q in ((1e-3, 2e-4, 0.0), (0.02, -0.01, 40.0)):
        crook = crook_traction(*q, a, b, pm, h, REF, order=32, limiting_shear=0.047)
        for name, got in _rules(*q, a, b, pm, h, REF, 1e-9, lam=0.047).items():
            assert got[0] == pytest.approx(float(crook.fx), rel=5e-3, abs=1e-6), name
            assert got[1] == pytest.approx(float(crook.fy), rel=5e-3, abs=1e-6), name


def test_elastic_film_lowers_the_initial_slope_by_orders_and_keeps_the_plateau():
    """At 1 um/s of slip the capped Crook law already gives most of its plateau (STIFFNESS.md:
    51 of 70 N); with the film in series the force is ~1e-3 of it, and at 0.1 m/s both sit
    on the plateau (below Λ Q)."""
    a, b, pm, h = CONTACT
    cap = 0.047 * 2 * np.pi * a * b * pm / 3
    for rule in ("accurate", "fast", "compiled"):
        small = _rules(1e-6, 0.0, 0.0, a, b, pm, h, REF, 3.0, lam=0.047)[rule][0]
        big = _rules(0.1, 0.0, 0.0, a, b, pm, h, REF, 3.0, lam=0.047)[rule][0]
        crook_small = float(crook_traction(1e-6, 0.0, 0.0, a, b, pm, h, REF, limiting_shear=0.047).fx)
        assert 0 < small < 2e-3 * crook_small, rule
        assert 0.95 * cap < big <= cap * (1 + 1e-3), rule


def test_traction_is_monotone_in_slip_and_below_the_cap():
    a, b, pm, h = CONTACT
    cap = 0.047 * 2 * np.pi * a * b * pm / 3
    u = np.geomspace(1e-7, 1.0, 60)
    n = u.size
    got = compiled.crook_fast(u, np.zeros(n), np.full(n, 5.0), np.full(n, a), np.full(n, b), np.full(n, pm),
                              np.full(n, h), REF, limiting_shear=0.047, film_modulus=KAPPA, entrainment=3.0)
    assert np.all(np.diff(got[0]) > 0)
    assert np.all(np.hypot(got[0], got[1]) <= cap * (1 + 1e-3))
    assert np.all(got[3] >= 0)  # heat


def test_compiled_rule_matches_the_accurate_rule_on_reference_states():
    """Fast rule (compiled, order 16) against the accurate rule (order 32) on the reference
    bearing's contact states, random entrainment: worst error ~5e-3 of the force scale
    (the capped law alone: 6.8e-3, MODEL.md §6a), median ~5e-5."""
    from tests.helpers import _contacts, _scale

    ux, uy, om, a, b, pm, h = _contacts(200, seed=3)
    rng = np.random.default_rng(5)
    ent = rng.uniform(1, 8, ux.size) * rng.choice([-1, 1], ux.size)
    kw = dict(limiting_shear=0.047, film_modulus=KAPPA, entrainment=ent)
    got = compiled.crook_fast(ux, uy, om, a, b, pm, h, REF, **kw)
    ref = crook_traction(ux, uy, om, a, b, pm, h, REF, order=32, **kw)
    fast = crook_traction(ux, uy, om, a, b, pm, h, REF, fast=True, **kw)
    scale = _scale(ref.fx, ref.fy, ref.mz, np.maximum(a, b))
    err = (np.abs(got[0] - ref.fx) + np.abs(got[1] - ref.fy) + np.abs(got[2] - ref.mz) / np.maximum(a, b)) / scale
    assert np.max(err) < 1e-2 and np.median(err) < 3e-4
    # the numpy fast rule has the same nodes: agreement to float32 precision
    same = (np.abs(got[0] - fast.fx) + np.abs(got[2] - fast.mz) / np.maximum(a, b)) / scale
    assert np.max(same) < 2e-5


def test_where_the_compliance_lives():
    """κ is a lubricant property (TOML key); the default law applies it, the paper's law not."""
    from exudyn_bearing.bearingfile import BearingFile, dumps_bearing, loads_bearing
    from exudyn_bearing.presets import REFERENCE_BEARING

    oil = dataclasses.replace(REF, film_shear_modulus_coefficient=0.21)
    text = dumps_bearing(BearingFile(REFERENCE_BEARING, oil))
    assert "film_shear_modulus_coefficient = 0.21" in text
    assert loads_bearing(text).lubricant.film_shear_modulus_coefficient == 0.21
    assert ContactLaw().film_modulus_for(REF) == KAPPA
    # κ is an input of its own: a changed Λ leaves it
    assert ContactLaw().film_modulus_for(dataclasses.replace(REF, limiting_shear_coefficient=0.03)) == KAPPA
    assert ContactLaw(traction="crook").film_modulus_for(REF) is None
    assert ContactLaw(traction="crook", film_elasticity=True).film_modulus_for(REF) == REF.film_shear_modulus_coefficient
    assert ContactLaw(film_elasticity=False).film_modulus_for(REF) is None
    assert ContactLaw(traction="none").film_modulus_for(REF) is None
    with pytest.raises(ValueError, match="film_shear_modulus_coefficient"):
        dataclasses.replace(REF, film_shear_modulus_coefficient=0.0)
    with pytest.raises(ValueError, match="film_elasticity"):
        ContactLaw(film_elasticity="yes")
    with pytest.raises(ValueError, match="film_modulus"):
        crook_traction(0.1, 0, 0, *CONTACT, REF, film_modulus=-1.0, entrainment=1.0)
    with pytest.raises(ValueError, match="entrainment"):
        crook_traction(0.1, 0, 0, *CONTACT, REF, film_modulus=0.3)


# ---------------------------------------------------------------------------------------
# The Maxwell equation solved along the streamlines (the reference of MODEL.md §6b)
# ---------------------------------------------------------------------------------------
def _streamlines(a, b, pm, n_y, steps):
    """Gauss lines y = a Y across the ellipse, steps in θ (x = c sin θ) from the inlet edge:
    path (m), pressure (Pa), the weights of ∬ · dA, and ∫ p dx' from the inlet (Pa m,
    the circular segment's area (c/2)(θ + sin θ cos θ + π/2) p_max √(1 − Y²))."""
    Y, wy = np.polynomial.legendre.leggauss(n_y)
    sy = np.sqrt(1 - Y ** 2)
    c = b * sy
    th = np.linspace(-np.pi / 2, np.pi / 2, steps + 1)[:, None]
    path = c * (np.sin(th) + 1)
    pressure = pm * sy * np.cos(th)
    weight = c * np.cos(th) * (th[1, 0] - th[0, 0]) * a * wy
    integral = pm * sy * c / 2 * (th + np.sin(th) * np.cos(th) + np.pi / 2)
    return path, pressure, weight, integral


@pytest.mark.parametrize("z", [1.0, 3.0, 10.0])
def test_streamline_solution_against_the_closed_form(z):
    """Newtonian film of constant viscosity η, G = κ p: (|ū| h/G) dτ/dx = v − τ h/η integrates
    to τ = (η v/h)(1 − exp(−κ ∫ p dx'/(η |ū|))); in the transition z = 2 κ p_max b/(η |ū|)
    = 1, 3, 10 the solver (Richardson of two step sizes) meets it along every streamline."""
    a, b, pm, h = CONTACT
    ent, v = 3.0, 1e-3
    eta = 2 * KAPPA * pm * b / (z * ent)
    got = []
    for steps in (400, 800):
        path, p, _, integral = _streamlines(a, b, pm, 8, steps)
        got.append(maxwell_streamline(lambda s, _p: eta * s / h, path, p, v, ent, h, KAPPA)[::steps // 400])
    tau = 2 * got[1] - got[0]
    path, p, _, integral = _streamlines(a, b, pm, 8, 400)
    exact = eta * v / h * -np.expm1(-KAPPA * integral / (eta * ent))
    assert np.max(np.abs(tau - exact)) < 2e-4 * eta * v / h
    assert exact[-1].min() < 0.99 * eta * v / h  # the elastic part matters (z ≤ 10)


def _limited_crook(s, p, h, oil=REF, lam=0.047):
    """Crook's thermal stress (MODEL.md §6) with the smooth limit Λ p tanh(τ_C/(Λ p)) (§6a),
    written out here: η = η0 e^(c_ηP p), ψ = η c_ηT s²/(8 K)."""
    eta = oil.viscosity * np.exp(oil.pressure_viscosity * p)
    psi = eta * oil.temperature_viscosity * s * s / (8 * oil.thermal_conductivity)
    with np.errstate(invalid="ignore", divide="ignore"):
        g = np.where(psi > 1e-10, np.arcsinh(np.sqrt(psi)) / np.sqrt(psi * (1 + psi)), 1 - psi / 3)
        tau_l = lam * p
        return np.where(tau_l > 0, tau_l * np.tanh(eta / h * s * g / np.where(tau_l > 0, tau_l, 1)), 0.0)


def test_rules_against_the_solved_maxwell_film_in_the_transition():
    """The rules' pointwise law (exponential, cap after; MODEL.md §6b) against the Maxwell
    equation solved along the streamlines with the model's limited Crook law, at z ≈ 1.7
    (1.7 GPa, ū 10 m/s, 2 mm/s of slip), where benchmarks/film_maxwell.py measured −3.0 %
    (the series form used before: −3.5 %; −25 % for the exponential form with ∫G dx and the
    limit inside, −33 % for the series with the limit inside)."""
    a, b, pm, h = CONTACT
    ent, v = 10.0, 2.08e-3
    forces = []
    for steps in (300, 600):
        path, p, weight, _ = _streamlines(a, b, pm, 24, steps)
        tau = maxwell_streamline(lambda s, pp: _limited_crook(s, pp, h), path, p, v, ent, h, KAPPA)
        forces.append(float(np.sum(weight * tau)))
    ref = 2 * forces[1] - forces[0]
    for name, (fx, fy, _) in _rules(v, 0.0, 0.0, a, b, pm, h, REF, ent, lam=0.047).items():
        assert fx == pytest.approx(ref, rel=0.04), name


# ---------------------------------------------------------------------------------------
# The Maxwell film over whole contacts, with spin (the reference at a bearing's contacts)
# ---------------------------------------------------------------------------------------
from scipy.integrate import solve_ivp  # noqa: E402

from contact.film_elasticity import crook_viscous, maxwell_traction  # noqa: E402


def _linear_film_by_ode(ux, uy, om, a, b, pm, h, ent, eta, lines):
    """Force and spin moment of a Newtonian film of constant viscosity η with G = κ p, each
    streamline's linear equation dτ/dθ = R'(θ) ((η/h) v − τ), R' = κ p (dx/dθ)/(|ū| η),
    integrated by scipy's DOP853 (with the force and moment as extra states)."""
    yg, wy = np.polynomial.legendre.leggauss(lines)
    side = 1.0 if ent > 0 else -1.0
    total = np.zeros(3)
    for yj, wj in zip(a * yg, wy):
        c = b * np.sqrt(1 - (yj / a) ** 2)
        peak = pm * np.sqrt(1 - (yj / a) ** 2)

        def rhs(th, z):
            x = side * c * np.sin(th)
            v = np.array([ux - om * yj, uy + om * x])
            dx = c * np.cos(th)
            rate = KAPPA * peak * np.cos(th) * dx / (abs(ent) * eta)
            dtau = rate * (eta / h * v - z[:2])
            return [dtau[0], dtau[1], z[0] * dx, z[1] * dx, (x * z[1] - yj * z[0]) * dx]

        sol = solve_ivp(rhs, (-np.pi / 2, np.pi / 2), np.zeros(5), method="DOP853", rtol=1e-11, atol=1e-14)
        total += a * wj * sol.y[2:, -1]
    return total


@pytest.mark.parametrize("entrainment", [3.0, -2.0])
def test_maxwell_contact_solution_with_spin_against_an_ode_solver(entrainment):
    """A Newtonian film of constant properties (linear equation) with the spin pole inside the
    contact, z = 2 κ p_max b/(η |ū|) = 2: force and moment of the solver (backward Euler,
    Richardson) against each streamline's equation integrated by an explicit high-order
    method to 1e-11."""
    a, b, pm, h = 1.0e-3, 0.3e-3, 1.0e9, 0.5e-6
    ux, uy, om = 2e-3, -1e-3, 20.0  # pole at (x, y) = (50, 100) µm
    eta = 2 * KAPPA * pm * b / (2.0 * abs(entrainment))
    tr = maxwell_traction(ux, uy, om, a, b, pm, h, entrainment,
                          lambda s, p: (eta / h * s, np.full_like(s, eta / h)), KAPPA, lines=8, steps=400)
    fx, fy, mz = _linear_film_by_ode(ux, uy, om, a, b, pm, h, entrainment, eta, lines=8)
    scale = np.hypot(fx, fy)
    # second order (Richardson on backward Euler): 2.2e-5 at 400 steps, 5.4e-6 at 800
    assert abs(tr.fx[0] - fx) < 4e-5 * scale and abs(tr.fy[0] - fy) < 4e-5 * scale
    assert tr.mz[0] == pytest.approx(mz, rel=4e-5)
    # the elastic compliance matters here: below the viscous film's ∬ η v/h dA
    assert scale < 0.9 * eta / h * np.pi * a * b * np.hypot(ux, uy)


def test_maxwell_contact_solution_without_spin_equals_the_streamline_solver():
    """No spin: the contact solver (Newton in the viscous slip) and :func:`maxwell_streamline`
    (bisection) on the same streamlines with the limited Crook law agree."""
    a, b, pm, h = CONTACT
    ent, v = 10.0, 2.08e-3
    viscous = crook_viscous(REF, np.array([h]), 0.047)
    tr = maxwell_traction(v, 0.0, 0.0, a, b, pm, h, ent, viscous, KAPPA, lines=12, steps=300)
    forces = []
    for steps in (150, 300):
        path, p, weight, _ = _streamlines(a, b, pm, 12, steps)
        tau = maxwell_streamline(lambda s, pp: _limited_crook(s, pp, h), path, p, v, ent, h, KAPPA)
        forces.append(float(np.sum(weight * tau)))
    assert tr.fx[0] == pytest.approx(2 * forces[1] - forces[0], rel=1e-7)
    assert abs(tr.fy[0]) < 1e-12 and abs(tr.mz[0]) < 1e-12


def test_the_compiled_compliance_has_no_cancellation():
    """The float32 kernel's 1 − e^(−x) (2t/(1 + t), t = tanh(x/2) by the rational fit) against
    numpy's expm1 from x = 1e-8 to 100 and at inf: relative 2e-6, where 1 − e^(−x) in float32
    would lose 1e-7/x."""
    from contact.kernels.float32 import one_minus_exp_neg32

    x = np.geomspace(1e-8, 100.0, 400)
    got = np.array([one_minus_exp_neg32(np.float32(v)) for v in x], dtype=float)
    exact = -np.expm1(-x.astype(np.float32).astype(float))
    assert np.max(np.abs(got / exact - 1)) < 2e-6
    assert one_minus_exp_neg32(np.float32(np.inf)) == pytest.approx(1.0, abs=2e-6)
