"""The smooth limiting shear stress of the traction law (MODEL.md §6a):
|τ| = τ_L tanh(|τ_Crook|/τ_L), τ_L = Λ p, along the local slip.

Checked against independent numbers: the bounds Λ Q and ∬ Λ p r dA (closed forms, one
cross-checked by scipy), pure Crook where τ ≪ τ_L, monotonicity in slip, finite
differences of the local law, and a brute-force scipy integral of the capped stress written
here from the equations (``_capped_reference``), not from the module.  Then the compiled
kernels against the numpy rule, and where Λ lives: Lubricant, TOML, ContactLaw, CLI.
"""
import math

import numpy as np
import pytest
from scipy import integrate, special

from contact import ballrace
from contact.ballrace import ContactLaw, RaceContact, ball_race_forces
from contact.kinematics import ContactKinematics
from contact.lubricant import REFERENCE_LUBRICANT as REF
from contact.lubricant import Lubricant
from contact.traction import crook_traction
from contact.traction_law import limit_shear, thermal_factor
from tests.helpers import _contacts  # reference-bearing contact states
from tests.helpers import _scipy_reference

LAM = 0.047  # the reference oil's Λ (MODEL.md §6a)
# heavily loaded contacts of the reference bearing (MODEL.md §9): (a transverse, b rolling, p_max, h)
HEAVY = (2.2e-3, 0.14e-3, 1.0e9, 0.5e-6)  # ≈ 650 N inner
HARD = (2.0e-3, 0.25e-3, 1.4e9, 0.3e-6)  # ≈ 2 kN, 1.4 GPa
OUTER = (1.63e-3, 0.212e-3, 0.9e9, 1.05e-6)  # outer contact, spin pole near the short-axis edge
LIGHT = (1.27e-3, 0.083e-3, 0.3e9, 0.5e-6)  # lightly loaded


def _load(a, b, p_max):
    """Q = ∬ p dA = 2π a b p_max / 3 (Hertz)."""
    return 2.0 * math.pi * a * b * p_max / 3.0


def _moment_bound(lam, a, b, p_max):
    """∬ Λ p r dA over the ellipse, r = √(x² + y²): in X = x/b, Y = y/a polar coordinates
    Λ p_max a b ∫₀¹ R² √(1 − R²) dR ∫₀^{2π} √(b² cos²θ + a² sin²θ) dθ
    = Λ p_max a b (π/16) 4 a E(1 − b²/a²) for a ≥ b (E: complete elliptic integral, 2nd kind)."""
    lo, hi = min(a, b), max(a, b)
    return lam * p_max * a * b * math.pi / 16.0 * 4.0 * hi * special.ellipe(1.0 - (lo / hi) ** 2)


def _capped_reference(ux, uy, w, a, b, p_max, h, lam, lub=REF, eps=1e-6):
    """∬ (τ_x, τ_y, x τ_y − y τ_x, τ·u) dA of the capped Crook stress by nested adaptive scipy
    quadrature, both levels split at the spin-pole lines (MODEL.md §6, §6a, §8)."""
    return _scipy_reference(ux, uy, w, a, b, p_max, h, lub=lub, eps=eps, lam=lam, limit=400)


def _rel_error(t, ref, a, b):
    """Error relative to the force scale |f| + |M_z|/√(ab) (as benchmarks/traction_speed.py)."""
    sab = math.sqrt(a * b)
    fx, fy, mz = (float(np.ravel(v)[0]) for v in t[:3])
    scale = math.hypot(ref[0], ref[1]) + abs(ref[2]) / sab
    return (math.hypot(fx - ref[0], fy - ref[1]) + abs(mz - ref[2]) / sab) / scale


# ---------------------------------------------------------------------------------------
# The local law and its derivative
# ---------------------------------------------------------------------------------------
def _crook_law(v, h=0.5e-6, p=1.0e9, lub=REF):
    """Crook's g and k (τ = g u, ∂τ/∂u = g I + k u uᵀ) at speed v, from thermal_factor."""
    eta = lub.viscosity * math.exp(lub.pressure_viscosity * p)
    c12 = eta * lub.temperature_viscosity / (8.0 * lub.thermal_conductivity)
    G, H = thermal_factor(c12 * v * v, derivative=True)
    return eta / h * G, eta / h * H * c12


@pytest.mark.parametrize("tau_l", [1e5, 4.7e7, 1e12])
def test_local_law_and_exact_derivative(tau_l):
    """T(v) = g' v equals τ_L tanh(T_C/τ_L) and T'(v) = g' + v² k' its central difference;
    from v = 0 (series branch) through the cap to far beyond."""
    for v in [0.0, 1e-12, 1e-8, 1e-6, 1e-5, 1e-4, 1e-3, 0.02, 0.3, 5.0]:
        g, k = _crook_law(v)
        gl, kl = limit_shear(np.array(g), np.array(v), np.array(tau_l), np.array(k))
        t_c = g * v
        assert float(gl) * v == pytest.approx(tau_l * math.tanh(t_c / tau_l), rel=1e-12, abs=1e-300)
        assert float(gl) <= g * (1 + 1e-15)
        dv = 1e-6 * max(v, 1e-6)

        def T(s):
            gs, _ = _crook_law(s)
            return tau_l * math.tanh(gs * s / tau_l)

        lo = max(v - dv, 0.0)
        slope = (T(v + dv) - T(lo)) / (v + dv - lo)
        exact = float(gl) + v * v * float(kl)
        assert exact == pytest.approx(slope, rel=1e-5, abs=1e-9 * abs(g))


def test_local_law_edges_are_finite():
    """v → 0 gives Crook's g with k' = k − (2/3) g³/τ_L²; τ_L = 0 (the ellipse edge) gives
    τ = 0, k' = 0; float32 stays float32 and finite."""
    g = np.array([2.0, 3.0, 5.0, 7.0])
    v = np.array([0.0, 0.0, 1e-3, 0.0])
    tl = np.array([1.0, 0.0, 0.0, 1e30])
    k = np.array([-1.0, -1.0, -1.0, -1.0])
    gl, kl = limit_shear(g, v, tl, k)
    np.testing.assert_allclose(gl, [2.0, 0.0, 0.0, 7.0])
    np.testing.assert_allclose(kl, [-1.0 - 2.0 / 3.0 * 8.0, 0.0, 0.0, -1.0])
    g32, k32 = limit_shear(g.astype(np.float32), v.astype(np.float32), tl.astype(np.float32),
                           k.astype(np.float32))
    assert g32.dtype == np.float32 and k32.dtype == np.float32
    assert np.all(np.isfinite(g32)) and np.all(np.isfinite(k32))
    assert limit_shear(g, v, tl)[1] is None


# ---------------------------------------------------------------------------------------
# (a) bounds
# ---------------------------------------------------------------------------------------
def test_moment_bound_closed_form_matches_quadrature():
    a, b, pm = HEAVY[:3]
    num = integrate.dblquad(lambda y, x: pm * math.sqrt(max(1 - (x / b) ** 2 - (y / a) ** 2, 0.0)) * math.hypot(x, y),
                            -b, b, lambda x: -a * math.sqrt(max(1 - (x / b) ** 2, 0.0)),
                            lambda x: a * math.sqrt(max(1 - (x / b) ** 2, 0.0)), epsrel=1e-6)[0]
    assert _moment_bound(1.0, a, b, pm) == pytest.approx(num, rel=1e-6)


@pytest.mark.parametrize("geo", [HEAVY, HARD, OUTER], ids=["1 GPa", "1.4 GPa", "outer 0.9 GPa"])
@pytest.mark.parametrize("fast", [False, True], ids=["accurate", "fast"])
def test_traction_and_spin_moment_never_exceed_the_limit(geo, fast):
    """|f| ≤ Λ Q and |M_z| ≤ ∬ Λ p r dA with and without spin, from rolling to gross sliding
    and pure spin; the pure Crook law exceeds Λ Q by far at these pressures."""
    a, b, pm, h = geo
    rng = np.random.default_rng(11)
    n = 60
    ux = rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(-6, 0.5, n)
    uy = rng.normal(0.0, 0.01, n)
    w = rng.choice([0.0, 1.0], n) * rng.normal(0.0, 300.0, n)
    ux[:5], uy[:5], w[:5] = 0.0, 0.0, [50.0, -300.0, 1000.0, 3000.0, 1e4]  # pure spin
    t = crook_traction(ux, uy, w, a, b, pm, h, REF, limiting_shear=LAM, fast=fast)
    # the quadrature integrates p with a relative error far below 1e-6 (tested in test_traction)
    assert np.all(np.hypot(t.fx, t.fy) <= LAM * _load(a, b, pm) * (1 + 1e-6))
    assert np.all(np.abs(t.mz) <= _moment_bound(LAM, a, b, pm) * (1 + 1e-6))
    assert np.all(t.heat > 0)
    free = crook_traction(ux, uy, w, a, b, pm, h, REF, fast=fast)
    assert np.max(np.hypot(free.fx, free.fy)) > 5 * LAM * _load(a, b, pm)
    # saturated: the limit is approached, not merely respected
    assert np.max(np.hypot(t.fx, t.fy)) > 0.9 * LAM * _load(a, b, pm)
    assert np.max(np.abs(t.mz)) > 0.8 * _moment_bound(LAM, a, b, pm)


# ---------------------------------------------------------------------------------------
# (b) pure Crook where τ ≪ τ_L
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("fast", [False, True], ids=["accurate", "fast"])
def test_equals_crook_where_the_stress_is_far_below_the_limit(fast):
    """0.3 GPa and slips ≤ 0.1 mm/s, spin ≤ 0.2 rad/s: |τ_C|/τ_L ≲ 1e-3, so the cap changes
    the result by ≲ (τ_C/τ_L)²/3."""
    a, b, pm, h = LIGHT
    ux = np.array([1e-5, -1e-4, 3e-5, 0.0, 1e-6])
    uy = np.array([0.0, 2e-5, -1e-5, 0.0, 1e-6])
    w = np.array([0.0, 0.1, -0.2, 0.05, 0.0])
    t = crook_traction(ux, uy, w, a, b, pm, h, REF, limiting_shear=LAM, fast=fast, derivatives=True)
    free = crook_traction(ux, uy, w, a, b, pm, h, REF, fast=fast, derivatives=True)
    scale = np.hypot(free.fx, free.fy) + np.abs(free.mz) / math.sqrt(a * b)
    for got, want in ((t.fx, free.fx), (t.fy, free.fy), (t.mz / math.sqrt(a * b), free.mz / math.sqrt(a * b))):
        assert np.all(np.abs(got - want) <= 1e-6 * scale)
    np.testing.assert_allclose(t.heat, free.heat, rtol=1e-6)
    np.testing.assert_allclose(t.jacobian, free.jacobian, rtol=1e-5, atol=1e-6 * np.abs(free.jacobian).max())


# ---------------------------------------------------------------------------------------
# (c) monotone in slip
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("geo", [HEAVY, HARD], ids=["1 GPa", "1.4 GPa"])
def test_pure_sliding_traction_rises_with_slip(geo):
    """Pure sliding from 0.1 um/s to 1 m/s at 1 and 1.4 GPa: the limited traction rises all
    the way (Crook's falling branch is gone) while the pure Crook law peaks and falls inside
    this range. Beyond ~2 m/s even Crook's stress drops below Λ p and the thermal fall
    returns (MODEL.md §6a)."""
    a, b, pm, h = geo
    u = np.logspace(-7, 0, 120)
    free = crook_traction(u, 0.0, 0.0, a, b, pm, h, REF, order=24).fx
    assert np.any(np.diff(free) < 0)
    for kw in (dict(order=24), dict(fast=True)):
        f = crook_traction(u, 0.0, 0.0, a, b, pm, h, REF, limiting_shear=LAM, **kw).fx
        assert np.all(np.diff(f) > 0), kw
        assert f[-1] > 0.95 * LAM * _load(a, b, pm)
    # the Jacobian (slope) is positive all along as well: no negative damping
    jac = crook_traction(u, 0.0, 0.0, a, b, pm, h, REF, limiting_shear=LAM, order=24, derivatives=True).jacobian
    assert np.all(jac[:, 0, 0] > 0)


# ---------------------------------------------------------------------------------------
# (d) the rules against a brute-force integral of the capped stress
# ---------------------------------------------------------------------------------------
# (slip u_x, u_y, spin) and contact: no spin at rolling slip and sliding, spin pole inside
# (centre, near the short-axis edge), pole outside, pure spin, 1.4 GPa
BRUTE_CASES = [((1e-3, 0.0, 0.0), HEAVY), ((0.05, 0.002, 0.0), HEAVY), ((0.01, 0.002, 30.0), HEAVY),
               ((1.1e-5, -8.8e-3, 47.0), OUTER), ((0.5, 0.0, 100.0), HEAVY), ((0.1, 0.0, 0.0), HARD),
               ((0.0, 0.0, 300.0), HEAVY)]
# Tolerances relative to |f| + |M_z|/√(ab), from the measured errors (MODEL.md §6a table):
# the tanh transition where |τ_C| ≈ Λ p is about twice as sharp in p as Crook's own thermal
# transition, so the rules lose accuracy with the cap (the fast rule at order 16: ≤ 7.5e-3
# here, 6.8e-3 worst on benchmarks/traction_speed.py's states; without the cap 4.6e-4).
TOLERANCE = {("accurate", 24): 3e-4, ("accurate", 16): 2e-3, ("fast", 16): 1e-2, ("fast", 24): 1e-3}


@pytest.fixture(scope="module")
def brute_force():
    return [_capped_reference(*u, *geo, LAM) for u, geo in BRUTE_CASES]


@pytest.mark.parametrize("rule, order", list(TOLERANCE))
def test_rules_match_a_brute_force_integral_of_the_capped_stress(brute_force, rule, order):
    errors = []
    for (u, geo), ref in zip(BRUTE_CASES, brute_force):
        t = crook_traction(*u, *geo, REF, limiting_shear=LAM, order=order, fast=rule == "fast")
        errors.append(_rel_error((t.fx, t.fy, t.mz), ref, *geo[:2]))
        assert float(t.heat) == pytest.approx(ref[3], rel=5 * TOLERANCE[rule, order])
    assert max(errors) < TOLERANCE[rule, order], errors


def test_compiled_kernel_matches_the_brute_force_integral(brute_force):
    compiled = pytest.importorskip("contact.kernels")
    for (u, geo), ref in zip(BRUTE_CASES, brute_force):
        got = compiled.crook_fast(*([v] for v in u + geo), REF, limiting_shear=LAM)
        assert _rel_error(got[:3, 0], ref, *geo[:2]) < TOLERANCE["fast", 16]


def test_jacobian_with_the_cap_matches_finite_differences():
    """The accurate rule's analytic Jacobian (limit_shear's exact derivative under the
    integral) against central differences of the forces; symmetric as before."""
    kw = dict(a=HEAVY[0], b=HEAVY[1], p_max=HEAVY[2], h=HEAVY[3], lubricant=REF, limiting_shear=LAM, order=32)
    for q in [(0.01, 0.002, 30.0), (1e-4, 0.0, 0.0), (0.003, 0.0005, 0.0), (0.05, 0.01, -100.0)]:
        q = np.array(q)
        J = crook_traction(*q, derivatives=True, **kw).jacobian
        Jfd = np.empty((3, 3))
        for j in range(3):
            d = np.zeros(3)
            d[j] = 1e-4 * max(abs(q[j]), (1e-3, 1e-3, 10.0)[j])
            fp, fm = crook_traction(*(q + d), **kw), crook_traction(*(q - d), **kw)
            Jfd[:, j] = (np.array([fp.fx, fp.fy, fp.mz]) - np.array([fm.fx, fm.fy, fm.mz])) / (2 * d[j])
        scale = np.abs(J).max(axis=1, keepdims=True)
        assert np.all(np.abs(J - Jfd) <= 2e-3 * scale), (q, np.max(np.abs(J - Jfd) / scale))
        np.testing.assert_allclose(J, J.T, rtol=1e-12, atol=1e-14 * scale.max())


# ---------------------------------------------------------------------------------------
# (e) compiled = numpy with the cap
# ---------------------------------------------------------------------------------------
def test_compiled_kernel_is_the_numpy_fast_rule_with_the_cap():
    compiled = pytest.importorskip("contact.kernels")
    ux, uy, om, a, b, pm, h = _contacts(200, seed=4)
    got = compiled.crook_fast(ux, uy, om, a, b, pm, h, REF, limiting_shear=LAM)
    ref = crook_traction(ux, uy, om, a, b, pm, h, REF, fast=True, limiting_shear=LAM)
    hi = np.maximum(a, b)
    scale = np.hypot(ref.fx, ref.fy) + np.abs(ref.mz) / hi
    # same nodes; float32 rays with a rational tanh(x)/x there, numpy's tanh here
    assert np.max(np.abs(got[0] - ref.fx) / scale) < 3e-4
    assert np.max(np.abs(got[1] - ref.fy) / scale) < 3e-4
    assert np.max(np.abs(got[2] - ref.mz) / (scale * hi)) < 3e-4
    np.testing.assert_allclose(got[3], ref.heat, rtol=3e-4)
    # the cap is active in these states, and None/0 give the pure Crook kernel
    pure = compiled.crook_fast(ux, uy, om, a, b, pm, h, REF)
    assert np.max(np.abs(pure[0] - got[0]) / scale) > 0.1
    np.testing.assert_array_equal(compiled.crook_fast(ux, uy, om, a, b, pm, h, REF, limiting_shear=0.0), pure)


def test_compiled_rational_tanh_is_accurate():
    """The kernel's tanh (x P(x²)/Q(x²) up to CAP_X, tanh(CAP_X) beyond) against numpy:
    relative error below 3e-6, and exactly Crook's law as x -> 0."""
    compiled = pytest.importorskip("contact.kernels.float32")
    x = np.concatenate([[0.0, 1e-30], np.logspace(-8, 3, 3000)])
    xc = np.minimum(x, compiled.CAP_X)
    th = xc * np.polyval(compiled.CAP_P[::-1], xc * xc) / np.polyval(compiled.CAP_Q[::-1], xc * xc)
    assert np.max(np.abs(th[1:] / np.tanh(x[1:]) - 1.0)) < 3e-6
    assert compiled.CAP_P[0] == compiled.CAP_Q[0] == 1.0 and th[0] == 0.0
    # tanh(x)/x = 1 − x²/3 + …: the fit's x² term is within 2e-6 of −1/3
    assert compiled.CAP_P[1] - compiled.CAP_Q[1] == pytest.approx(-1.0 / 3.0, abs=2e-6)


@pytest.mark.slow
def test_the_default_law_runs_compiled_and_matches_the_numpy_path():
    """A scene with the default law (Crook with the oil's Λ) takes the compiled path, and its
    forces equal the numpy path's (same state, as tests/test_compiled.py)."""
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import races
    from exudyn_bearing.model.builder import CreateAngularContactBearing

    forces = []
    for compiled_path in (True, False):
        sc = exu.SystemContainer()
        mbs = sc.AddSystem()
        brg = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=2200.0, radialForce=2000.0,
                                          contactLaw=ContactLaw(compiled=compiled_path), show=False)
        mbs.Assemble()
        con = brg.connector
        assert (con._compiled is not None) == compiled_path
        q = np.asarray(mbs.systemData.GetODE2Coordinates())
        qt = np.asarray(mbs.systemData.GetODE2Coordinates_t())
        rng = np.random.default_rng(5)
        forces.append(np.asarray(con.residual_forces(0.01, q + rng.normal(0, 1e-7, q.size),
                                                     qt * (1 + rng.normal(0, 1e-3, q.size)))).copy())
    np.testing.assert_allclose(forces[0], forces[1], rtol=0, atol=1e-6 * np.abs(forces[1]).max())


# ---------------------------------------------------------------------------------------
# (f) where Λ lives: Lubricant, TOML, ContactLaw, CLI
# ---------------------------------------------------------------------------------------
def _oil(**kw):
    base = dict(viscosity=0.04, reference_temperature=30.0, pressure_viscosity=1.75e-8, temperature_viscosity=0.05,
                thermal_conductivity=0.14, density=860.0)
    base.update(kw)
    return Lubricant(**base)


@pytest.mark.parametrize("value", [-0.01, math.nan, math.inf, "0.05", True, None])
def test_lubricant_rejects_a_bad_coefficient(value):
    with pytest.raises(ValueError, match="^limiting_shear_coefficient "):
        _oil(limiting_shear_coefficient=value)


def test_lubricant_default_and_reference_value():
    assert REF.limiting_shear_coefficient == 0.047
    assert _oil().limiting_shear_coefficient == 0.047  # a mineral-oil value unless given
    assert _oil(limiting_shear_coefficient=0).limiting_shear_coefficient == 0


def test_bearing_file_round_trips_the_coefficient():
    from exudyn_bearing import REFERENCE_BEARING
    from exudyn_bearing.bearingfile import BearingFile, dumps_bearing, loads_bearing

    setup = BearingFile(REFERENCE_BEARING, _oil(limiting_shear_coefficient=0.035))
    text = dumps_bearing(setup)
    assert "limiting_shear_coefficient = 0.035" in text
    back = loads_bearing(text)
    assert back.lubricant == setup.lubricant
    # absent key: the default; bad value: the key's name in the error
    no_key = "\n".join(line for line in text.splitlines() if not line.startswith("limiting_shear_coefficient"))
    assert loads_bearing(no_key).lubricant.limiting_shear_coefficient == 0.047
    with pytest.raises(ValueError, match="limiting_shear_coefficient"):
        loads_bearing(text.replace("limiting_shear_coefficient = 0.035", "limiting_shear_coefficient = -1.0"))


def test_contact_law_models_and_the_effective_coefficient():
    assert ContactLaw().traction == "crook-limited"
    assert "crook" in ballrace.TRACTION_MODELS and "crook-limited" in ballrace.TRACTION_MODELS
    assert ContactLaw().limiting_shear_for(REF) == 0.047
    assert ContactLaw().limiting_shear_for(_oil(limiting_shear_coefficient=0.0)) is None
    assert ContactLaw(traction="crook").limiting_shear_for(REF) is None  # the paper's law
    assert ContactLaw(limiting_shear=0.07).limiting_shear_for(REF) == 0.07  # explicit override
    assert ContactLaw(traction="crook", limiting_shear=0.07).limiting_shear_for(REF) == 0.07
    assert ContactLaw(traction="newtonian").limiting_shear_for(REF) is None
    with pytest.raises(ValueError, match="^traction "):
        ContactLaw(traction="crook-capped")


def _kinematics(n=6, seed=2):
    """Loaded ball–inner-race contacts of the reference bearing, sliding and spinning."""
    rng = np.random.default_rng(seed)
    normal = np.tile([0.0, -math.sin(0.7), -math.cos(0.7)], (n, 1))
    rolling = np.tile([1.0, 0.0, 0.0], (n, 1))
    transverse = np.cross(normal, rolling)
    return ContactKinematics(
        penetration=rng.uniform(5e-6, 3e-5, n), penetration_rate=np.zeros(n), normal=normal,
        rolling=rolling, transverse=transverse, point=np.zeros((n, 3)),
        contact_angle=np.full(n, 0.7), slip_rolling=rng.normal(0, 0.05, n), slip_transverse=rng.normal(0, 0.005, n),
        spin=rng.normal(0, 200, n), entrainment=np.full(n, 6.0), orbit_radius=np.full(n, 0.0775),
        point_radius=np.full(n, 0.0655))


def test_paper_law_reproduces_the_plain_crook_call_exactly():
    """traction='crook' is the pure Crook law of the paper: the contact forces equal a direct
    crook_traction(..., limiting_shear=None) call bit for bit; the default law differs."""
    from exudyn_bearing import REFERENCE_BEARING as B
    from contact import film

    params = RaceContact(B.ball_diameter, B.pitch_diameter, B.inner_conformity, "inner", B.effective_modulus,
                         B.ball_mass)
    kin = _kinematics()
    law = ContactLaw(traction="crook", damping_ratio=0.0)
    frc = ball_race_forces(kin, params, REF, law)
    r_x, contact = params.hertz(kin.contact_angle)
    load = contact.stiffness * kin.penetration ** 1.5
    a, b = contact.semi_axes(load)
    h = np.maximum(film.central_film_thickness(kin.entrainment, load, r_x, contact.ellipticity,
                                               params.effective_modulus, REF), law.min_film_thickness)
    direct = crook_traction(kin.slip_rolling, kin.slip_transverse, kin.spin, a, b, contact.max_pressure(load), h, REF,
                            limiting_shear=None, fast=True)
    np.testing.assert_array_equal(frc.traction_rolling, direct.fx)
    np.testing.assert_array_equal(frc.traction_transverse, direct.fy)
    np.testing.assert_array_equal(frc.spin_moment, direct.mz)
    capped = ball_race_forces(kin, params, REF, ContactLaw(damping_ratio=0.0))
    assert np.max(np.abs(capped.traction_rolling - direct.fx)) > 1e-3 * np.max(np.abs(direct.fx))
    assert np.all(np.hypot(capped.traction_rolling, capped.traction_transverse) <= LAM * load * (1 + 1e-6))


@pytest.mark.parametrize("command", ["simulate", "skid-map", "render"])
def test_cli_traction_option(command, monkeypatch, tmp_path):
    """--traction on simulate, skid-map and render: default the bearing file's law, else
    crook-limited; every model accepted, the chosen law reaches the run (the run itself is
    replaced by a stub)."""
    from exudyn_bearing import as_setup
    from exudyn_bearing.simulation import runner
    from exudyn_bearing.studies import cli, render, skidmap

    seen = []

    class Stop(Exception):
        pass

    def stub(*args, bearing=None, **kw):  # the law travels in the setup the command passes
        seen.append(as_setup(bearing if bearing is not None else args[0]).contact_law)
        raise Stop

    monkeypatch.setattr(runner, "simulate", stub)
    monkeypatch.setattr(skidmap, "skid_map", stub)
    monkeypatch.setattr(render, "render_run", stub)
    base = {"simulate": ["simulate", "--axial", "1300"], "skid-map": ["skid-map", "--out", str(tmp_path)],
            "render": ["render", "--out", str(tmp_path)]}[command]
    parser = cli.build_parser()
    assert parser.parse_args(base).traction is None  # the file's law, or ContactLaw()'s
    with pytest.raises(Stop):
        cli.main(base)
    assert seen[-1].traction == "crook-limited"
    for model in ballrace.TRACTION_MODELS:
        with pytest.raises(Stop):
            cli.main(base + ["--traction", model])
        assert seen[-1].traction == model
    with pytest.raises(SystemExit):
        parser.parse_args(base + ["--traction", "capped"])
