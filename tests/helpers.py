"""Helpers the test modules share (contact states, scenes, closed forms, demos), so that no
test module imports another (issue 48, item 7)."""
from __future__ import annotations

import functools
import importlib.util
import math
from pathlib import Path

import exudyn as exu
import numpy as np
from scipy import integrate, optimize

from contact.ballrace import ContactLaw, RaceContact
from contact.lubricant import REFERENCE_LUBRICANT as REF
from contact.surface import Defect, SurfaceModel, Waviness
from exudyn_bearing import REFERENCE_BEARING as B
from exudyn_bearing import races
from exudyn_bearing.bearing import BallDrag
from exudyn_bearing.cage import CageModel
from exudyn_bearing.model.builder import CreateAngularContactBearing



def record_keyword(monkeypatch, owner, name: str, keyword: str) -> list:
    """Replaces ``owner.name`` (a function of a module or class) for the test by one that
    calls it unchanged and first appends each call's ``keyword`` argument to the list
    returned (how often, and with what, a solver was called)."""
    calls, original = [], getattr(owner, name)

    def recording(*args, **kwargs):
        calls.append(kwargs[keyword])
        return original(*args, **kwargs)

    monkeypatch.setattr(owner, name, recording)
    return calls


# (from tests/test_compiled.py)
def _contacts(n, seed=0):
    """Contact states of the reference bearing's range (MODEL.md §9): semi-axes 0.8–1.8 mm
    across and 0.15–0.35 mm along the rolling direction, 0.3–1.4 GPa, films 0.05–0.5 um,
    rolling/transverse slip up to ~1 m/s and spin up to 500 rad/s, so the spin pole lies
    inside, near and outside the ellipse; some contacts without spin."""
    rng = np.random.default_rng(seed)
    a = rng.uniform(0.8e-3, 1.8e-3, n)
    b = rng.uniform(0.15e-3, 0.35e-3, n)
    om = rng.normal(0.0, 200.0, n)
    om[: n // 10] = 0.0
    ux = rng.normal(0.0, 0.3, n) * rng.choice([0.01, 0.1, 1.0], n)
    uy = rng.normal(0.0, 0.1, n) * rng.choice([0.01, 0.1, 1.0], n)
    pm = rng.uniform(0.3e9, 1.4e9, n)
    h = rng.uniform(5e-8, 5e-7, n)
    return ux, uy, om, a, b, pm, h


# (from tests/test_compiled.py)
def _scale(fx, fy, mz, a):
    """Per contact: the traction magnitude plus the spin moment over the long semi-axis."""
    return np.hypot(fx, fy) + np.abs(mz) / a


# (from tests/test_compiled.py)
def _scene(law=ContactLaw(), **kw):
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    kw.setdefault("innerRace", races.Driven(1800))
    brg = CreateAngularContactBearing(mbs, contactLaw=law, show=False, **kw)
    mbs.Assemble()
    q = np.asarray(mbs.systemData.GetODE2Coordinates())
    qt = np.asarray(mbs.systemData.GetODE2Coordinates_t())
    idx = np.concatenate([np.arange(mbs.GetNodeODE2Index(n), mbs.GetNodeODE2Index(n) + 6) for n in brg.nodeNumbers])
    rng = np.random.default_rng(5)
    con = brg.connector
    # generic state: every contact slides and spins, positions off the quasi-static ones
    q_abs = q[idx] + con.reference + rng.normal(0, 1e-6, idx.size)
    return sc, con, q_abs, qt[idx] * (1 + rng.normal(0, 1e-3, idx.size))


def quasi_dynamic_power_gap(balance, x):
    """(drive power, summed losses, the contacts' normal work), W, of the quasi-dynamic state
    ``x`` of ``balance`` (MODEL.md §12a). Its balls move at w_c about the cage centre, not
    along their orbit's radial changes, so each contact's load Q works on its approach rate:
    the drive power is the losses less sum Q dp/dt, exactly where the accounting is right (the
    inner race's torque about its own centre, the balls' and drag's powers on the same
    velocities)."""
    from exudyn_bearing.solvers.azimuth_power import azimuth_drive_power, azimuth_losses

    kin, f = balance.contacts(x)
    normal = float(np.sum(np.sum(f.force * kin.normal, axis=1) * kin.penetration_rate))
    return azimuth_drive_power(balance, x), sum(azimuth_losses(balance, x).values()), normal


# (from tests/test_compiled.py)
SCENES = {
    "axial, rigid cage, drag": dict(axialForce=1300.0),
    "combined load": dict(axialForce=2200.0, radialForce=2000.0),
    "spring chain, no drag": dict(axialForce=300.0, cage=CageModel(kind="spring-chain"), ballDrag=None),
    "pocket play, free outer race": dict(axialForce=600.0, cage=CageModel(clearance=2e-6), outerRace=races.Free()),
    "no traction": dict(axialForce=1300.0, law=ContactLaw(traction="none")),
    # MODEL.md eq. 11c.2: the jet oil's momentum beside a quarter-flooded sphere drag
    "jet momentum": dict(axialForce=1300.0, ballDrag=BallDrag(0.5, 0.25, oil_flow=2e-4)),
    # MODEL.md §11d: the outer land's friction torque on the cage (and its reaction)
    "land friction, outer-guided cage": dict(axialForce=1300.0, cage=CageModel(land_width=0.01)),
    # MODEL.md §11d: ball–pocket friction at the contact points (the state's 1-um noise loads the pockets)
    "pocket friction": dict(axialForce=1300.0, cage=CageModel(land_width=0.01, pocket_friction=0.3)),
    # MODEL.md §11b, §11e: the rolling-resistance couple and the thermal film factor
    "rolling resistance, thermal film, combined load": dict(
        axialForce=2200.0, radialForce=2000.0, law=ContactLaw(rolling_resistance=True, thermal_film=True)),
    "no spin moment, Fixed inner translation": dict(innerRace=races.Driven(1800, translation="fixed"),
                                                    law=ContactLaw(spin_moment=False)),
    # MODEL.md §13: defects on both races (one under ball 0), waviness, an oversize ball
    "race surfaces, combined load": dict(axialForce=2200.0, radialForce=2000.0, surface=SurfaceModel(
        (Defect("outer", 0.0, 1.0e-3, 5e-6), Defect("inner", 90.0, 2e-3, 20e-6, edge=0.2e-3)),
        Waviness(inner=((5, 0.5e-6, 30.0),), outer=((17, 0.3e-6, 0.0), (15, 0.2e-6, 45.0)),
                 ball_diameter_variation=(1e-6,) + (0.0,) * 15))),
    # MODEL.md eq. 13.3, 13.6: pits under the outer contacts of balls 0 and 3, the contacts on
    # their edge paths, and two balls' waviness: the contacts read the balls' rotations
    "ball defects, combined load": dict(axialForce=2200.0, radialForce=2000.0, surface=SurfaceModel(
        (Defect("ball", -0.5, 1.0e-3, 5e-6, ball=0), Defect("ball", -2.0, 1.2e-3, 8e-6, ball=3, edge=0.1e-3)),
        Waviness(ball=((0, 6, 0.3e-6, 10.0), (4, 3, 0.2e-6, 0.0))))),
    # driven-speed torque (feed-forward of the ramp + feedback) and an inner-land cage
    "speed ramp, inner-guided cage, turning outer race": dict(
        innerRace=races.Driven(lambda t: 900.0 + 30000.0 * t), outerRace=races.Fixed(lambda t: -100.0 * t),
        cage=CageModel(guidance="inner"), axialForce=800.0, radialForce=300.0),
}


# (from tests/test_compiled.py)
def _both_paths(con, q, qt, t=0.01):
    """(single-state compiled path (the force user function), batch compiled path, numpy
    path) of one state, each (n_nodes, 6)."""
    single = con.residual_forces(t, q - con.reference, qt).reshape(-1, 6)
    fast = con.evaluate(t, q, qt).reshape(-1, 6)
    kernel, con._compiled = con._compiled, None
    try:
        ref = con.evaluate(t, q, qt).reshape(-1, 6)
    finally:
        con._compiled = kernel
    return single, fast, ref


# (from tests/test_traction.py)
def _jacobian_paths(con, q, qt, t=0.01):
    """(compiled Jacobian from the main thread, from a worker thread, numpy path's Jacobian)
    of one state: the compiled batch path (numba's parallel loop) and its serial twin, and
    the reference."""
    import threading

    main = con.jacobian(t, q, qt, 1.0, 1e-4)
    box = {}
    worker = threading.Thread(target=lambda: box.setdefault("j", con.jacobian(t, q, qt, 1.0, 1e-4)))
    worker.start()
    worker.join()
    kernel, con._compiled = con._compiled, None
    try:
        ref = con.jacobian(t, q, qt, 1.0, 1e-4)
    finally:
        con._compiled = kernel
    return main, box["j"], ref


def _assert_jacobian_matches_numpy(fast, ref, con):
    """The compiled Jacobian ``fast`` equals the numpy one ``ref`` to finite-difference noise:
    2e-4 of the largest entry, 1e-3 in the races' translation columns that the compiled path
    takes from the balls' (tests/test_compiled.py explains both)."""
    from exudyn_bearing.jacobian import jacobian_columns

    chain = np.zeros(ref.shape[1], dtype=bool)
    for s in jacobian_columns(con)["chain"]:
        chain[6 * s:6 * s + 3] = True
    scale = np.max(np.abs(ref))
    assert np.max(np.abs(fast - ref)[:, ~chain]) < 2e-4 * scale
    assert np.max(np.abs(fast - ref)[:, chain], initial=0.0) < 1e-3 * scale


def _scipy_reference(ux, uy, w, a, b, p_max, h, lub=REF, eps=1e-6, lam=None, limit=10000):
    """∬ (τ_x, τ_y, x τ_y − y τ_x, τ·u) dA by nested adaptive quadrature (scipy quad_vec),
    both levels split at the spin pole lines x = x_p, y = y_p (MODEL.md §8); with ``lam`` the
    Crook stress capped smoothly, |τ| = Λ p tanh(|τ_C|/(Λ p)) (MODEL.md §6a)."""
    c1c = lub.temperature_viscosity / (8.0 * lub.thermal_conductivity)
    xp, yp = (-uy / w, ux / w) if w != 0 else (math.inf, math.inf)

    def inner(x):
        ym = a * math.sqrt(max(1.0 - (x / b) ** 2, 0.0))

        def f(y):
            p = p_max * math.sqrt(max(1.0 - (x / b) ** 2 - (y / a) ** 2, 0.0))
            eta = lub.viscosity * math.exp(lub.pressure_viscosity * p)
            vx, vy = ux - w * y, uy + w * x
            v = math.hypot(vx, vy)
            s = math.sqrt(eta * c1c) * v
            g = eta / h * (math.asinh(s) / (s * math.sqrt(1.0 + s * s)) if s > 0 else 1.0)  # Crook: τ = g u
            if lam is not None and g * v > 0:  # |τ| = τ_L tanh(|τ_C|/τ_L) (0 where p = 0)
                t_c, t_l = g * v, lam * p
                g *= t_l * math.tanh(t_c / t_l) / t_c if t_l > 0 else 0.0
            return np.array([g * vx, g * vy, g * (x * vy - y * vx), g * v * v])

        pts = [yp] if -ym < yp < ym else None
        return integrate.quad_vec(f, -ym, ym, epsrel=eps, epsabs=0, points=pts, limit=limit)[0]

    pts = [xp] if -b < xp < b else None
    return integrate.quad_vec(inner, -b, b, epsrel=eps, epsabs=0, points=pts, limit=limit)[0]


# (from tests/test_quasistatic.py)
# ---------------------------------------------------------------------------------------
# Jones–Harris equilibrium of the geometric mode, written out here from MODEL.md §2–§4
# (nothing from contact/ or exudyn_bearing/): reference bearing as typed in the paper's
# table 1a plus f = 0.52 and steel (MODEL.md §8)
# ---------------------------------------------------------------------------------------
JH_Z, JH_D, JH_DM, JH_F, JH_A0, JH_MASS = 16, 25e-3, 155e-3, 0.52, math.radians(40.0), 0.064


# (from tests/test_quasistatic.py)
JH_E = 210e9 / (1 - 0.3 ** 2)  # E' of steel on steel: 2 / (2 (1 - nu²) / E)


# (from tests/test_quasistatic.py)
JH_TUBE = (JH_F - 0.5) * JH_D  # ball centre to groove centre when touching


# (from tests/test_quasistatic.py)
JH_RP = JH_DM / 2


# (from tests/test_quasistatic.py)
E_Z = np.array([0.0, 0.0, 1.0])


# (from tests/test_quasistatic.py)
def jh_hertz_k(alpha, race):
    """Brewe–Hamrock K = pi k E' sqrt(E R / (4.5 F³)) at contact angle alpha (MODEL.md §2, §3)."""
    r_x = JH_D * (JH_DM + (-1.0 if race == "inner" else 1.0) * JH_D * math.cos(alpha)) / (2 * JH_DM)
    r_y = JH_F * JH_D / (2 * JH_F - 1)
    ratio = r_y / r_x
    first, second = 1.5277 + 0.6023 * math.log(ratio), 1.0003 + 0.5968 / ratio
    radius = 1 / (1 / r_x + 1 / r_y)
    return math.pi * 1.0339 * ratio ** 0.6360 * JH_E * math.sqrt(second * radius / (4.5 * first ** 3))


# (from tests/test_quasistatic.py)
def _newton(fun, x, tol, step=1e-4, max_iter=60):
    """Damped Newton with a central-difference Jacobian; stops at |fun(x)| < tol."""
    r = fun(x)
    for _ in range(max_iter):
        if np.linalg.norm(r) < tol:
            return x
        jac = np.column_stack([(fun(x + h) - fun(x - h)) / (2 * step) for h in np.eye(len(x)) * step])
        dx = np.linalg.solve(jac, -r)
        lam = 1.0
        while True:
            trial = x + lam * dx
            r_trial = fun(trial)
            if np.linalg.norm(r_trial) < (1 - 1e-4 * lam) * np.linalg.norm(r) or lam < 1e-6:
                break
            lam *= 0.5
        x, r = trial, r_trial
    assert np.linalg.norm(r) < tol, f"Newton: |residual| {np.linalg.norm(r):.3g}"
    return x


# (from tests/test_quasistatic.py)
def _jh_grooves(psi, s, shift):
    """Ball centre and groove centres relative to (r_p e_r): ball offset s = (radial,
    axial) in its meridional plane at azimuth psi, inner race shifted by (dx, 0, dz); the
    inner groove centre lies in the INNER race's meridional plane through the ball."""
    e_r = np.array([math.cos(psi), math.sin(psi), 0.0])
    rel = (JH_RP + s[0]) * e_r - np.array([shift[0], 0.0, 0.0])
    e_rho = np.array([rel[0], rel[1], 0.0]) / math.hypot(rel[0], rel[1])
    c, ca, sa = s[0] * e_r + s[1] * E_Z, math.cos(JH_A0), math.sin(JH_A0)
    g_i = np.array([shift[0], 0.0, shift[1]]) + JH_RP * (e_rho - e_r) + JH_TUBE * (ca * e_rho + sa * E_Z)
    g_o = -JH_TUBE * (ca * e_r + sa * E_Z)
    return e_r, e_rho, c, g_i, g_o


# (from tests/test_quasistatic.py)
def _jh_contacts(psi, s, shift):
    """((Q, alpha, n) inner, (Q, alpha, n) outer, e_r); n from groove centre through the
    ball centre to the contact, Q = K(alpha) (|c - g| - (f - 1/2) D)^1.5."""
    e_r, e_rho, c, g_i, g_o = _jh_grooves(psi, s, shift)
    out = []
    for race, g, radial, sgn in (("inner", g_i, e_rho, -1.0), ("outer", g_o, e_r, 1.0)):
        n = (c - g) / np.linalg.norm(c - g)
        alpha = math.atan2(sgn * n[2], sgn * (n @ radial))
        out.append((jh_hertz_k(alpha, race) * max(np.linalg.norm(c - g) - JH_TUBE, 0.0) ** 1.5, alpha, n))
    return out[0], out[1], e_r


# (from tests/test_quasistatic.py)
def _jh_ball(psi, shift, rate):
    """Ball at psi in equilibrium of its two contact loads and its centrifugal force
    m r_c w_c² = ``rate`` r_c at its own orbit radius r_c (the cage holds its azimuth):
    (Q_i, Q_o, alpha_i, alpha_o, n_i)."""
    fc = rate * JH_RP
    e_r, _, _, g_i, g_o = _jh_grooves(psi, np.zeros(2), shift)
    overlap = np.linalg.norm(g_i - g_o) - 2 * JH_TUBE
    if overlap <= 0 and fc == 0:
        return 0.0, 0.0, JH_A0, JH_A0, np.zeros(3)  # a loose ball carries nothing
    if overlap > 0:  # start on the groove-centre line, overlap halved
        start = g_o + (JH_TUBE + 0.5 * overlap) * (g_i - g_o) / np.linalg.norm(g_i - g_o)
    else:  # off the inner race, pressed into the outer one
        start = g_o + (JH_TUBE + (fc / jh_hertz_k(0.0, "outer")) ** (2 / 3)) * e_r

    def residual(s_um):
        (q_i, _, n_i), (q_o, _, n_o), e_r = _jh_contacts(psi, s_um * 1e-6, shift)
        force = rate * (JH_RP + s_um[0] * 1e-6) * e_r - q_i * n_i - q_o * n_o
        return np.array([force @ e_r, force[2]])

    s_um = _newton(residual, np.array([start @ e_r, start[2]]) * 1e6, tol=1e-9 * max(fc, 100.0))
    (q_i, a_i, n_i), (q_o, a_o, _), _ = _jh_contacts(psi, s_um * 1e-6, shift)
    return q_i, q_o, a_i, a_o, n_i


# (from tests/test_quasistatic.py)
@functools.lru_cache(maxsize=None)
def jones_harris(axial, radial=0.0, rpm=0.0):
    """Jones–Harris equilibrium (rigid rings, Hertz balls, no tilt): the inner-race shift
    (dx, dz) for which the balls' contact forces balance (radial, 0, axial), each ball in
    equilibrium with the centrifugal force m r_c w_c² at Harris's nominal cage speed
    w_c = w/2 (1 - D cos a0 / d_m). Returns (Q_i, Q_o, alpha_i, alpha_o) per ball (ball 0
    at +x, the radial load's direction) and the shift (m)."""
    w_c = rpm * math.pi / 30 / 2 * (1 - JH_D * math.cos(JH_A0) / JH_DM)
    rate = JH_MASS * w_c ** 2
    psi = 2 * np.pi * np.arange(JH_Z) / JH_Z

    def balls(x_um):
        return [_jh_ball(p, x_um * 1e-6, rate) for p in psi]

    def residual(x_um):
        force = sum(b[0] * b[4] for b in balls(x_um))  # the balls' push on the inner race
        return np.array([force[0] + radial, force[2] + axial])

    # the axial shift alone first (the axial residual falls monotonically with it)
    x = np.array([0.0, optimize.brentq(lambda z: residual(np.array([0.0, z]))[1], -500.0, 200.0, xtol=1e-12)])
    if radial > 0:
        x = _newton(residual, np.array([10.0, x[1]]), tol=1e-8 * max(axial, radial))
    per_ball = balls(x)
    return tuple(np.array([b[k] for b in per_ball]) for k in range(4)) + (x * 1e-6,)


# (from tests/test_shaft.py)
def _demo():
    path = Path(__file__).resolve().parents[1] / "demos" / "hss_shaft.py"
    spec = importlib.util.spec_from_file_location("hss_shaft_demo", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# (from tests/test_assembly_start.py)
#: a user's 7205-type bearing file (13 balls of 7.938 mm, d_m 38.5 mm, 25 degrees), as in issue 34
BEARING_7205 = """\
[bearing]
balls = 13
ball_diameter = 0.007938
pitch_diameter = 0.0385
inner_conformity = 0.52
outer_conformity = 0.53
contact_angle = 25.0
"""  # tests/test_user_path.py adds its own oil and drag to it


# (from tests/test_branches.py)
RPM = math.pi / 30


# (from tests/test_branches.py)
# ---------------------------------------------------------------------------------------
# Barus-exponent cap on the traction pressure
# ---------------------------------------------------------------------------------------
(R_I, Z_I), (R_O, Z_O) = B.groove_centres()


# (from tests/test_branches.py)
TUBE_I = (B.inner_conformity - 0.5) * B.ball_diameter


# (from tests/test_branches.py)
TUBE_O = (B.outer_conformity - 0.5) * B.ball_diameter


# (from tests/test_branches.py)
W_RACE = np.array([0.0, 0.0, 1800 * RPM])


# (from tests/test_branches.py)
INNER = RaceContact(B.ball_diameter, B.pitch_diameter, B.inner_conformity, "inner", B.effective_modulus, B.ball_mass)


# (from tests/test_branches.py)
def _inner_contacts(approaches, u_x=0.3, u_y=0.05, spin=20.0, w_c=82.6):
    """Balls at azimuth 0 pressed into the inner groove by ``approaches`` (m) along the
    free-angle normal (clear of the outer race), orbiting at w_c, with the given slip
    (m/s) and spin (rad/s) at the contact centre: (c, v, w) of shape (n, 3)."""
    n = np.array([-math.cos(B.contact_angle), 0.0, -math.sin(B.contact_angle)])  # groove centre -> ball -> contact
    t1 = np.array([0.0, 1.0, 0.0])
    t2 = np.cross(n, t1)
    centres, velocities, omegas = [], [], []
    for delta in approaches:
        c = np.array([R_I, 0.0, Z_I]) + (TUBE_I + delta) * n
        p = c + B.ball_radius * n
        v = np.cross([0.0, 0.0, w_c], c)
        # ball surface velocity at p = race velocity minus the slip: w x n fixes w across n,
        # the spin fixes its part along n
        m = (np.cross(W_RACE, p) - (u_x * t1 + u_y * t2) - v) / B.ball_radius
        centres.append(c)
        velocities.append(v)
        omegas.append(np.cross(n, m) + (W_RACE @ n - spin) * n)
    return np.array(centres), np.array(velocities), np.array(omegas)




# (from tests/test_scene_cli.py and tests/test_spall_size.py)
def housed_scene_signal(bearing, surface, rpm, radial, end, sample_rate):
    """The README's vibration scene: the shaft held at ``rpm``, ``radial`` N, the outer race on a
    3-kHz, 2-kg housing, solved by ``mbs.SolveDynamic`` at the handle's recommended step (at most
    the sample period) and tolerance and the package's spectral radius 0.5, the housing's
    acceleration written at every step and
    recorded by ``sampled_signal``. Returns (t s, the acceleration along the radial load m/s²,
    the step s, the handle, mbs)."""
    from exudyn_bearing.studies.vibration import sampled_signal

    mbs = exu.SystemContainer().AddSystem()
    h = CreateAngularContactBearing(mbs, bearing, innerRace=races.Driven(rpm), radialForce=radial,
                                    outerRace=races.Housing(frequency=3000, mass=2), surface=surface, show=False)
    acc = h.AddVibrationSensors(mbs, outputs=("Acceleration",))["Acceleration"]
    mbs.Assemble()
    step = min(h.RecommendedStep(), h.RecommendedSurfaceStep(rpm), 1 / sample_rate)
    s = exu.SimulationSettings()
    s.timeIntegration.endTime = end
    s.timeIntegration.numberOfSteps = round(end / step)
    s.timeIntegration.newton.absoluteTolerance = h.RecommendedAbsoluteTolerance()
    s.timeIntegration.generalizedAlpha.spectralRadius = 0.5  # the package's (SolverSettings)
    s.timeIntegration.verboseMode = 0
    s.solution.sensors.writePeriod = step
    s.solution.file.write = False
    mbs.SolveDynamic(s)
    data = np.asarray(mbs.GetSensorStoredData(acc))
    t, x = sampled_signal(data[:, 0], data[:, 1], sample_rate)  # x: along the radial load
    return t, x, step, h, mbs
