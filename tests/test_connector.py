"""The bearing connector's generalized forces, checked against the physics assembled by hand.

Acceptance item: "every contact force/moment term checked against contact/ evaluated
independently on the same state". The reference bearing is built with a ``Free`` inner
race, a ``Free`` outer race and the rigid cage (all bodies have nodes, so every lever arm
matters), put into a deliberately generic state (ball positions perturbed by ~1 µm, all
velocities and angular velocities perturbed so every contact slides and spins, rotation
vectors of arbitrary size incl. |nu| > pi on a ball, the inner race and the cage), and the
connector's output is compared with generalized forces built here from first principles:

* rotation vectors decoded with ``scipy.spatial.transform.Rotation`` (not the package's
  Rodrigues formula);
* groove geometry, Hertz (Brewe–Hamrock fits), normal damping and the Hamrock–Dowson
  film written out from MODEL.md §2, §3, §5; only the traction quadrature itself is
  taken from ``contact.traction.crook_traction`` (it has its own convergence tests);
* the contact force acts on the ball at the contact point p and, reversed, on the race at
  p (true lever arm about the race node), spin moment +-M_z n, drag and pocket forces at
  the ball centre, the pocket reaction on the cage at the ball centre;
* global torques mapped to the local-omega velocity coordinates of NodeRigidBodyRotVecLG
  as A^T tau.

Also: momentum invariants of the internal forces (independent of any implementation) and a
check of the RotVecLG torque convention in Exudyn itself.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

exu = pytest.importorskip("exudyn")

from contact.ballrace import ContactLaw  # noqa: E402
from contact.traction import crook_traction  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING, REFERENCE_DRAG, REFERENCE_LUBRICANT  # noqa: E402
from exudyn_bearing import races  # noqa: E402
from exudyn_bearing.model.builder import CreateAngularContactBearing  # noqa: E402
from exudyn_bearing.cage import CageModel  # noqa: E402

BRG = REFERENCE_BEARING
LUB = REFERENCE_LUBRICANT


# ---------------------------------------------------------------------------------------
# model and generic state
# ---------------------------------------------------------------------------------------
def _frame():
    """A bearing frame that is neither at the origin nor aligned with the global axes."""
    return np.array([0.012, -0.007, 0.021]), Rotation.from_rotvec([0.3, -0.5, 0.2]).as_matrix()


CONFIGS = {
    # preload by displacement, rigid cage without play, drag on, bearing frame rotated
    "displaced": dict(innerRaceDisplacement=(2e-6, -1e-6, 10e-6), cage=CageModel(), ballDrag=REFERENCE_DRAG,
                      frame=True),
    # applied axial + radial force on the inner race, pocket play (some pockets engaged,
    # some not), drag on, global frame
    "loaded": dict(axialForce=2000.0, radialForce=300.0, cage=CageModel(clearance=1e-6), ballDrag=REFERENCE_DRAG,
                   frame=False),
    # races at rest, inner race pushed mostly radially: the balls opposite the load zone are
    # out of contact (quasi-static: 7 of 16 unloaded), the others loaded
    "partly-unloaded": dict(innerRaceDisplacement=(15e-6, 0.0, 3e-6), cage=CageModel(), ballDrag=REFERENCE_DRAG,
                            frame=False, rpm=0.0),
}


def build(config, *, drag=True, law=ContactLaw()):
    cfg = dict(CONFIGS[config])
    use_frame = cfg.pop("frame")
    rpm = cfg.pop("rpm", 1800.0)
    if not drag:
        cfg["ballDrag"] = None
    kwargs = {}
    if use_frame:
        kwargs["position"], kwargs["rotationMatrix"] = _frame()
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    handle = CreateAngularContactBearing(mbs, BRG, LUB, innerRace=races.Free(rpm), outerRace=races.Free(0.0),
                                         contactLaw=law, show=False, **cfg, **kwargs)
    mbs.Assemble()
    return sc, mbs, handle


def _tilted(axis, angle, tilt, rng):
    """Rotation vector of ``angle`` about ``axis`` tilted by ~``tilt`` rad in a random direction."""
    u = np.asarray(axis, dtype=float) + tilt * rng.standard_normal(3)
    return angle * u / np.linalg.norm(u)


def _long(nu):
    """The same rotation as ``nu`` with the rotation vector of length 2 pi - |nu| (> pi)."""
    nu = np.asarray(nu, dtype=float)
    angle = np.linalg.norm(nu)
    return nu - 2 * np.pi * nu / angle


def generic_state(mbs, handle, seed=1, speed_scale=1.0):
    """Absolute node coordinates q and velocities q_t (RotVecLG: local omega) of a generic,
    physically plausible state near the builder's initial one."""
    rng = np.random.default_rng(seed)
    con = handle.connector
    axis = con.axis
    nodes = handle.nodeNumbers
    q = np.concatenate([np.asarray(mbs.GetNodeParameter(n, "referenceCoordinates"), dtype=float)
                        + np.asarray(mbs.GetNodeParameter(n, "initialCoordinates"), dtype=float) for n in nodes])
    q_t = np.concatenate([np.asarray(mbs.GetNodeParameter(n, "initialVelocities"), dtype=float) for n in nodes])
    q, q_t = q.reshape(-1, 6), q_t.reshape(-1, 6)
    omega = np.zeros((len(nodes), 3))  # global angular velocities
    for ball in con.layout["balls"]:
        q[ball, :3] += 1e-6 * rng.standard_normal(3)
        nu = rng.standard_normal(3)
        q[ball, 3:] = rng.uniform(0.2, 2 * np.pi) * nu / np.linalg.norm(nu)
        q_t[ball, :3] += 0.01 * rng.standard_normal(3)
        # initial velocities are global = local at zero rotation; perturb by ~20 rad/s
        omega[ball] = q_t[ball, 3:] + 20.0 * rng.standard_normal(3)
    q[con.layout["balls"][0], 3:] = 5.5 * np.array([1.0, -2.0, 0.5]) / math.sqrt(5.25)  # |nu| > pi
    cage, inner, outer = con.layout["cage"], con.layout["inner"], con.layout["outer"]
    # rotations relative to the bearing frame: the cage by 2e-5 rad (pockets shift ~1.5 µm),
    # the inner race by 4 rad, the outer by 0.3 rad, all about axes tilted ~5e-6 rad; the
    # cage and the inner race get the equivalent rotation vector with |nu| > pi
    for slot, angle, long in ((cage, 2e-5, True), (inner, 4.0, True), (outer, 0.3, False)):
        rel = Rotation.from_rotvec(_tilted([0, 0, 1.0], angle, 5e-6, rng))
        nu = (Rotation.from_matrix(con.rotation) * rel).as_rotvec()
        q[slot, 3:] = _long(nu) if long else nu
        q[slot, :3] += 0.3e-6 * rng.standard_normal(3)
        q_t[slot, :3] = 2e-3 * rng.standard_normal(3)
    omega[cage] = 83.0 * speed_scale * axis + 0.5 * rng.standard_normal(3)
    omega[inner] = 188.5 * speed_scale * axis + 0.5 * rng.standard_normal(3)
    omega[outer] = 3.0 * speed_scale * axis + 0.5 * rng.standard_normal(3)
    for s in range(len(nodes)):
        q_t[s, 3:] = Rotation.from_rotvec(q[s, 3:]).as_matrix().T @ omega[s]
    return q.ravel(), q_t.ravel()


# ---------------------------------------------------------------------------------------
# physics by hand (MODEL.md §2, §3, §5, §6, §8)
# ---------------------------------------------------------------------------------------
def hand_contacts(c, v, w, race_pos, race_rot, race_vel, race_omega, race, law):
    """Per-ball contact force on the ball (at p), spin moment vector on the ball, contact
    point and intermediate values, all global. Race frame = node frame (created race)."""
    d, r = BRG.ball_diameter, BRG.ball_radius
    f = BRG.inner_conformity if race == "inner" else BRG.outer_conformity
    a0 = BRG.contact_angle
    tube = (f - 0.5) * d
    if race == "inner":
        g_radius, g_z = BRG.pitch_radius + tube * math.cos(a0), tube * math.sin(a0)
    else:
        g_radius, g_z = BRG.pitch_radius - tube * math.cos(a0), -tube * math.sin(a0)
    e_prime = BRG.ball_material.youngs_modulus / (1.0 - BRG.ball_material.poisson_ratio ** 2)  # same steel
    out = {k: [] for k in ("force", "moment_spin", "point", "load", "fx", "fy", "mz", "u", "h")}
    for j in range(len(c)):
        loc = race_rot.T @ (c[j] - race_pos)
        radial = np.array([loc[0], loc[1], 0.0]) / math.hypot(loc[0], loc[1])
        g_loc = g_radius * radial + np.array([0.0, 0.0, g_z])
        dist = np.linalg.norm(loc - g_loc)
        n_loc = (loc - g_loc) / dist
        delta = dist - tube
        n = race_rot @ n_loc
        t1 = race_rot @ np.cross([0.0, 0.0, 1.0], radial)
        t2 = np.cross(n, t1)
        p = c[j] + r * n
        g = race_pos + race_rot @ g_loc
        v_race = lambda x: race_vel + np.cross(race_omega, x - race_pos)  # noqa: E731
        v_ball_p = v[j] + np.cross(w[j], p - c[j])
        slip = v_race(p) - v_ball_p
        u_x, u_y = slip @ t1, slip @ t2
        spin = (race_omega - w[j]) @ n
        delta_rate = (v[j] - v_race(g)) @ n  # g slides along its circle, normal to n
        # the contact patch moves with the ball's orbit relative to the race
        orbit = (v[j] - v_race(c[j])) @ t1 / math.hypot(loc[0], loc[1])
        p_loc = race_rot.T @ (p - race_pos)
        v_patch = v_race(p) @ t1 + orbit * math.hypot(p_loc[0], p_loc[1])
        entrain = 0.5 * (v_race(p) + v_ball_p) @ t1 - v_patch
        # Hertz, Brewe–Hamrock (MODEL.md §3)
        cos_a = -(n_loc @ radial) if race == "inner" else n_loc @ radial
        sign = -1.0 if race == "inner" else 1.0
        r_x = d * (BRG.pitch_diameter + sign * d * cos_a) / (2 * BRG.pitch_diameter)
        r_y = f * d / (2 * f - 1)
        ratio = r_y / r_x
        k = 1.0339 * ratio ** 0.6360
        ell_f = 1.5277 + 0.6023 * math.log(ratio)
        ell_e = 1.0003 + 0.5968 / ratio
        rr = 1.0 / (1.0 / r_x + 1.0 / r_y)
        stiff = math.pi * k * e_prime * math.sqrt(ell_e * rr / (4.5 * ell_f ** 3))
        load = 0.0
        if delta > 0:
            damping = 2 * law.damping_ratio * math.sqrt(1.5 * stiff * math.sqrt(delta) * BRG.ball_mass)
            load = max(stiff * delta ** 1.5 + damping * delta_rate, 0.0)
        fx = fy = mz = h = 0.0
        if load > 0:
            a = (6 * k ** 2 * ell_e * load * rr / (math.pi * e_prime)) ** (1 / 3)
            b = (6 * ell_e * load * rr / (math.pi * k * e_prime)) ** (1 / 3)
            p_max = 1.5 * load / (math.pi * a * b)
            # Hamrock–Dowson central film (MODEL.md §5)
            uu = LUB.viscosity * abs(entrain) / (e_prime * r_x)
            gg = LUB.pressure_viscosity * e_prime
            ww = load / (e_prime * r_x ** 2)
            h = r_x * 2.69 * uu ** 0.67 * gg ** 0.53 * ww ** -0.067 * (1 - 0.61 * math.exp(-0.73 * k))
            h = max(h, law.min_film_thickness)
            # same quadrature as the connector: this checks the assembly, not the rule
            # limiting shear (MODEL.md §6a): the law's own Λ, else the oil's for 'crook-limited'
            lam = law.limiting_shear
            if lam is None and law.traction == "crook-limited":
                lam = LUB.limiting_shear_coefficient
            # the film's elastic compliance (MODEL.md §6b): on for 'crook-limited' unless switched
            elastic = law.traction == "crook-limited" if law.film_elasticity is None else law.film_elasticity
            kappa = LUB.film_shear_modulus_coefficient if elastic else None
            tr = crook_traction(u_x, u_y, spin, a, b, p_max, h, LUB, order=law.quadrature_order,
                                limiting_shear=lam, fast=law.fast_quadrature, film_modulus=kappa,
                                entrainment=entrain)
            fx, fy = float(tr.fx), float(tr.fy)
            mz = float(tr.mz) if law.spin_moment else 0.0
        out["force"].append(-load * n + fx * t1 + fy * t2)
        out["moment_spin"].append(mz * n)
        out["point"].append(p)
        for key, val in (("load", load), ("fx", fx), ("fy", fy), ("mz", mz), ("u", (u_x, u_y, spin)), ("h", h)):
            out[key].append(val)
    return {k: np.asarray(val) for k, val in out.items()}


def hand_pockets(c, v, cage_pos, cage_rot, cage_vel, cage_omega, cage):
    """Pocket forces on the balls (at the ball centres), MODEL.md §1."""
    z = len(c)
    k_p = cage.stiffness
    c_p = 2 * 0.05 * math.sqrt(k_p * BRG.ball_mass) if cage.damping is None else cage.damping
    gap = 0.5 * cage.clearance
    forces = np.zeros((z, 3))
    for j in range(z):
        phi = 2 * math.pi * j / z
        centre = cage_pos + cage_rot @ (BRG.pitch_radius * np.array([math.cos(phi), math.sin(phi), 0.0]))
        e = cage_rot @ np.array([-math.sin(phi), math.cos(phi), 0.0])
        s = (c[j] - centre) @ e
        # d/dt of (c - centre) . e, e turning with the cage
        s_dot = (v[j] - cage_vel - np.cross(cage_omega, centre - cage_pos)) @ e + (c[j] - centre) @ np.cross(cage_omega, e)
        if gap == 0:
            mag = -k_p * s - c_p * s_dot
        elif abs(s) > gap:
            # a pocket wall pushes the ball back, never pulls
            mag = -math.copysign(max(k_p * (abs(s) - gap) + c_p * s_dot * math.copysign(1, s), 0.0), s)
        else:
            mag = 0.0
        forces[j] = mag * e
    return forces


def hand_drag(c, v, origin, axis, drag):
    """Sphere drag against the orbital motion at the ball centres (MODEL.md §8)."""
    rho = drag.oil_volume_fraction * LUB.density
    forces = np.zeros_like(c)
    for j in range(len(c)):
        e_psi = np.cross(axis, c[j] - origin)
        e_psi /= np.linalg.norm(e_psi)
        speed = v[j] @ e_psi
        forces[j] = -0.5 * drag.drag_coefficient * rho * math.pi * BRG.ball_radius ** 2 * abs(speed) * speed * e_psi
    return forces


def hand_generalized(handle, q, q_t, law, drag, applied):
    """Generalized forces of all node slots, assembled from the hand physics."""
    con = handle.connector
    n_nodes = len(handle.nodeNumbers)
    qq, vv = q.reshape(n_nodes, 6), q_t.reshape(n_nodes, 6)
    rot = [Rotation.from_rotvec(qq[s, 3:]).as_matrix() for s in range(n_nodes)]
    pos, vel = qq[:, :3], vv[:, :3]
    omega = np.array([rot[s] @ vv[s, 3:] for s in range(n_nodes)])
    balls = con.layout["balls"]
    c, v, w = pos[balls], vel[balls], omega[balls]
    force = np.zeros((n_nodes, 3))
    torque = np.zeros((n_nodes, 3))  # global, about each node
    parts = {}
    for race in ("inner", "outer"):
        s = con.layout[race]
        hc = hand_contacts(c, v, w, pos[s], rot[s], vel[s], omega[s], race, law)
        parts[race] = hc
        for j, b in enumerate(balls):
            f, p, m = hc["force"][j], hc["point"][j], hc["moment_spin"][j]
            force[b] += f
            torque[b] += np.cross(p - c[j], f) + m
            force[s] -= f
            torque[s] += np.cross(p - pos[s], -f) - m
    s = con.layout["cage"]
    pockets = hand_pockets(c, v, pos[s], rot[s], vel[s], omega[s], con.cage)
    parts["pockets"] = pockets
    for j, b in enumerate(balls):
        force[b] += pockets[j]
        force[s] -= pockets[j]
        torque[s] += np.cross(c[j] - pos[s], -pockets[j])
    if con.cage.guided:  # the guiding land: radial through both centres, pushes only
        r = con.layout[con.cage.guidance]
        n_axis = rot[r][:, 2]
        d = pos[s] - pos[r]
        d = d - (d @ n_axis) * n_axis
        e = np.linalg.norm(d)
        play = 0.5 * con.cage.guide_clearance
        land = np.zeros(3)
        if e > play:
            n = d / e
            u = min((e - play) / 10e-6, 1.0)  # the damping's cubic ramp over 10 um
            c_g = con.guide[3]
            e_dot = (vel[s] - vel[r]) @ n
            land = -max(con.cage.guide_stiffness * (e - play) + c_g * u * u * (3 - 2 * u) * e_dot, 0.0) * n
        parts["land"] = land
        force[s] += land
        force[r] -= land
        torque[r] += np.cross(pos[s] - pos[r], -land)
    if drag is not None:
        dr = hand_drag(c, v, con.origin, con.axis, drag)
        parts["drag"] = dr
        force[balls] += dr
    force[con.layout["inner"]] += applied
    gen = np.zeros((n_nodes, 6))
    gen[:, :3] = force
    for k in range(n_nodes):
        gen[k, 3:] = rot[k].T @ torque[k]
    return gen, parts, pos, rot


# ---------------------------------------------------------------------------------------
# tests
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("config", ["displaced", "loaded", "partly-unloaded"])
def test_generalized_forces_match_hand_assembly(config):
    """Every term of the connector's generalized forces against the hand assembly. The
    "partly-unloaded" state (some contacts of a race loaded, others not) raised a
    ValueError in ``contact.ballrace.ball_race_forces`` at commit 2f38baf (semi-axes of the
    loaded subset broadcast against the Hertz constants of all contacts).

    The traction uses the float64 accurate rule here: the fast rule computes in float32,
    so its results move by ~1e-6 with the batch a contact is evaluated in, and this test
    compares the assembly to 1e-7 (the rules' accuracy is tested in test_traction.py)."""
    law = ContactLaw(fast_quadrature=False)
    _, mbs, handle = build(config, law=law)
    con = handle.connector
    cfg = CONFIGS[config]
    q, q_t = generic_state(mbs, handle, speed_scale=cfg.get("rpm", 1800.0) / 1800.0)
    frame = _frame()[1] if cfg["frame"] else np.eye(3)
    applied = frame @ np.array([cfg.get("radialForce", 0.0), 0.0, cfg.get("axialForce", 0.0)])
    expected, parts, _, _ = hand_generalized(handle, q, q_t, law, cfg["ballDrag"], applied)

    # the state is generic: contacts loaded and sliding with spin, pockets and drag active
    for race in ("inner", "outer"):
        hc = parts[race]
        if config == "partly-unloaded":
            assert 4 <= np.count_nonzero(hc["load"] > 10.0) and np.count_nonzero(hc["load"] == 0.0) >= 4
        else:
            assert np.all(hc["load"] > 0.0) and np.count_nonzero(hc["load"] > 50.0) >= 12, (race, hc["load"])
            assert np.count_nonzero(np.hypot(hc["fx"], hc["fy"]) > 1.0) >= 12  # traction, N
            assert np.count_nonzero(np.abs(hc["mz"]) > 1e-6) >= 12  # spin moment, N m
        assert np.all(np.hypot(hc["u"][:, 0], hc["u"][:, 1]) > 0.02), (race, hc["u"])
        assert np.count_nonzero(np.abs(hc["u"][:, 2]) > 1.0) >= 10  # spin, rad/s
    n_pockets = np.count_nonzero(np.linalg.norm(parts["pockets"], axis=1))
    assert n_pockets >= 4 and np.max(np.linalg.norm(parts["pockets"], axis=1)) > 10.0
    if config == "loaded":
        assert n_pockets < BRG.balls  # play: some pockets disengaged
        assert np.linalg.norm(parts["land"]) > 1.0  # the start seats the cage on its land (MODEL.md §12a)
    assert np.all(np.linalg.norm(parts["drag"], axis=1) > 0.0)

    state = con.evaluate(0.0, q, q_t, details=True)
    got = con.evaluate(0.0, q, q_t).reshape(-1, 6)
    # term by term (helps to locate a mismatch)
    for race, kin, frc in (("inner", state.inner, state.inner_forces), ("outer", state.outer, state.outer_forces)):
        hc = parts[race]
        np.testing.assert_allclose(kin.point, hc["point"], rtol=0, atol=1e-12)
        np.testing.assert_allclose(np.stack([kin.slip_rolling, kin.slip_transverse, kin.spin], axis=1), hc["u"],
                                   rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(frc.normal_load, hc["load"], rtol=1e-9)
        np.testing.assert_allclose(frc.film_thickness, hc["h"], rtol=1e-9)
        np.testing.assert_allclose(frc.traction_rolling, hc["fx"], rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(frc.traction_transverse, hc["fy"], rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(frc.spin_moment, hc["mz"], rtol=1e-7, atol=1e-12)
        np.testing.assert_allclose(frc.force, hc["force"], rtol=0, atol=1e-7 * np.max(np.abs(hc["force"])))
    np.testing.assert_allclose(state.cage_force, parts["pockets"], rtol=0, atol=1e-9 * np.max(np.abs(parts["pockets"])))
    np.testing.assert_allclose(state.drag_force, parts["drag"], rtol=1e-12, atol=1e-15)

    # the whole generalized-force vector, node by node, each to 1e-8 of its own size
    # (observed: ~1e-11 or better)
    for k in range(len(expected)):
        for part in (slice(0, 3), slice(3, 6)):
            scale = np.max(np.abs(expected[k, part]))  # 0: e.g. torque on a ball out of contact
            np.testing.assert_allclose(got[k, part], expected[k, part], rtol=0, atol=1e-8 * scale,
                                       err_msg=f"node slot {k}, {'force' if part.start == 0 else 'torque'}")
    np.testing.assert_allclose(np.asarray(state.generalized).reshape(-1, 6), got, rtol=0, atol=0)


def test_torques_need_the_transposed_rotation():
    """Sanity check of the hand reference itself: mapping the race and ball torques with A
    instead of A^T (or dropping the race lever arms) would be detected."""
    law = ContactLaw(quadrature_order=8, fast_quadrature=False)
    _, mbs, handle = build("displaced", law=law)
    q, q_t = generic_state(mbs, handle, seed=3)
    got = handle.connector.evaluate(0.0, q, q_t).reshape(-1, 6)
    expected, _, pos, rot = hand_generalized(handle, q, q_t, law, REFERENCE_DRAG, np.zeros(3))
    wrong = np.array([rot[k] @ rot[k] @ expected[k, 3:] for k in range(len(rot))])  # A tau instead of A^T tau
    scale_t = np.max(np.abs(expected[:, 3:]))
    assert np.max(np.abs(got[:, 3:] - expected[:, 3:])) < 1e-8 * scale_t
    assert np.max(np.abs(got[:, 3:] - wrong)) > 1e-2 * scale_t


@pytest.mark.parametrize("config", ["displaced", "loaded"])
def test_internal_forces_conserve_momentum(config):
    """Drag off, no applied force: the connector's forces are internal, so their sum and
    their total moment about any fixed point vanish (implementation-independent)."""
    cfg = CONFIGS[config]
    law = ContactLaw()
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    kwargs = {}
    if cfg["frame"]:
        kwargs["position"], kwargs["rotationMatrix"] = _frame()
    # same races and cage as the config, but preloaded by displacement (no applied force)
    handle = CreateAngularContactBearing(mbs, BRG, LUB, innerRace=races.Free(1800.0), outerRace=races.Free(0.0),
                                         innerRaceDisplacement=(1e-6, 2e-6, 10e-6), cage=cfg["cage"], ballDrag=None,
                                         contactLaw=law, show=False, **kwargs)
    mbs.Assemble()
    q, q_t = generic_state(mbs, handle, seed=7)
    gen = handle.connector.evaluate(0.0, q, q_t).reshape(-1, 6)
    qq = q.reshape(-1, 6)
    rot = [Rotation.from_rotvec(qq[s, 3:]).as_matrix() for s in range(len(qq))]
    forces = gen[:, :3]
    torques = np.array([rot[s] @ gen[s, 3:] for s in range(len(qq))])  # back to global
    point = np.array([0.05, -0.02, 0.1])  # an arbitrary fixed point
    moments = np.cross(qq[:, :3] - point, forces) + torques
    assert np.max(np.linalg.norm(forces, axis=1)) > 100.0  # something to conserve
    total_f = np.linalg.norm(forces.sum(axis=0))
    total_m = np.linalg.norm(moments.sum(axis=0))
    assert total_f <= 1e-9 * np.abs(forces).sum(), (total_f, np.abs(forces).sum())
    assert total_m <= 1e-9 * np.linalg.norm(moments, axis=1).sum(), (total_m, np.linalg.norm(moments, axis=1).sum())


def test_exudyn_rotveclg_torque_convention():
    """In Exudyn itself: a GenericODE2 on one asymmetric, tumbling RotVecLG rigid body
    returning [F; A^T tau] for a constant GLOBAL torque tau gives dL/dt = tau (and dp/dt =
    F), L = A I A^T omega_global = A I omega_local. Explicit Lie-group RK44, step 1e-4 s,
    0.1 s."""
    from exudyn.utilities import InertiaCuboid, ObjectGenericODE2

    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    inertia = InertiaCuboid(density=7800.0, sideLengths=[0.1, 0.05, 0.02])
    nu0 = np.array([0.4, -0.9, 2.8])  # |nu| ~ 2.97
    omega0_local = np.array([30.0, -12.0, 7.0])
    d = mbs.CreateRigidBody(inertia=inertia, referencePosition=[0.1, 0.2, 0.3],
                            referenceRotationMatrix=Rotation.from_rotvec(nu0).as_matrix(),
                            initialVelocity=[0.5, 0.0, -0.2],
                            initialAngularVelocity=Rotation.from_rotvec(nu0).as_matrix() @ omega0_local,
                            nodeType=exu.NodeType.RotationRotationVector, returnDict=True)
    node = d["nodeNumber"]
    ref = np.asarray(mbs.GetNodeParameter(node, "referenceCoordinates"), dtype=float)
    force = np.array([1.0, -2.0, 0.5])
    tau = np.array([0.02, 0.05, -0.03])

    def user_force(mbs_, t, itemNumber, q, q_t):
        a = Rotation.from_rotvec(np.asarray(q)[3:] + ref[3:]).as_matrix()
        return np.concatenate([force, a.T @ tau]).tolist()

    mbs.AddObject(ObjectGenericODE2(nodeNumbers=[node], forceUserFunction=user_force))
    mbs.Assemble()
    mass = inertia.Mass()
    i_body = np.asarray(inertia.Inertia())

    def momenta():
        q = np.asarray(mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates)) + ref
        q_t = np.asarray(mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates_t))
        a = Rotation.from_rotvec(q[3:]).as_matrix()
        return mass * q_t[:3], a @ i_body @ q_t[3:]

    p0, l0 = momenta()
    # the tumbling body's L turns relative to the body: a wrong convention is visible
    assert np.linalg.norm(np.cross(l0, tau)) > 0.5 * np.linalg.norm(l0) * np.linalg.norm(tau)
    end = 0.1
    s = exu.SimulationSettings()
    s.timeIntegration.endTime = end
    s.timeIntegration.numberOfSteps = 1000
    s.timeIntegration.verboseMode = 0
    s.timeIntegration.explicit.useLieGroupIntegration = True
    s.solution.file.write = False
    exu.SolveDynamic(mbs, s, solverType=exu.DynamicSolverType.RK44)
    p1, l1 = momenta()
    np.testing.assert_allclose(p1 - p0, force * end, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(l1 - l0, tau * end, rtol=0, atol=1e-9 * np.linalg.norm(tau * end))  # observed 3e-15 N m s


@pytest.mark.parametrize("guidance", ["outer", "inner"])
def test_land_guidance_force_by_hand(guidance):
    """A land-guided cage pushed past its radial play: the guiding land's force on the cage
    (MODEL.md §1; penalty k (e - g) + c de/dt through the centres) and its reaction on the
    guiding race node, with the race's moment about its node, against a hand computation.
    The land term is isolated as (guided) - (unguided, guidance='balls') on the same state;
    the sum of all internal forces and moments still vanishes with it."""
    cage_model = CageModel(guidance=guidance, guide_clearance=0.4e-3, guide_stiffness=2e7, guide_damping=300.0)
    forces, handles = {}, {}
    for g in (guidance, "balls"):
        sc = exu.SystemContainer()
        mbs = sc.AddSystem()
        position, rotation = _frame()
        handles[g] = CreateAngularContactBearing(mbs, BRG, LUB, innerRace=races.Free(1800.0),
                                                 outerRace=races.Free(0.0), innerRaceDisplacement=(1e-6, 2e-6, 10e-6),
                                                 cage=replace(cage_model, guidance=g), ballDrag=None, position=position,
                                                 rotationMatrix=rotation, show=False)
        mbs.Assemble()
        q, q_t = generic_state(mbs, handles[g], seed=11)
        con = handles[g].connector
        qq, vv = q.reshape(-1, 6), q_t.reshape(-1, 6)
        cage = con.layout["cage"]
        # cage centre 0.23 mm off the bearing axis (play 0.2 mm), moving outwards at 0.04 m/s
        radial = rotation @ np.array([math.cos(0.7), math.sin(0.7), 0.0])
        qq[cage, :3] = position + 0.23e-3 * radial + 1e-5 * rotation[:, 2]
        vv[cage, :3] = 0.04 * radial + 0.01 * rotation[:, 1]
        forces[g] = con.evaluate(0.0, qq.ravel(), vv.ravel()).reshape(-1, 6)
    con = handles[guidance].connector
    land = forces[guidance] - forces["balls"]

    race = con.layout[guidance]
    rot_race = Rotation.from_rotvec(qq[race, 3:]).as_matrix()
    axis = rot_race[:, 2]  # Free races: the node frame is the race frame
    d = qq[cage, :3] - qq[race, :3]
    e_vec = d - (d @ axis) * axis
    e = np.linalg.norm(e_vec)
    n = e_vec / e
    e_dot = (vv[cage, :3] - vv[race, :3]) @ n
    u = min((e - 0.2e-3) / 10e-6, 1.0)  # the damping's ramp over the first 10 um (MODEL.md §1)
    f_cage = -(2e7 * (e - 0.2e-3) + 300.0 * u * u * (3 - 2 * u) * e_dot) * n
    assert 500.0 < np.linalg.norm(f_cage) < 2000.0  # engaged, damping term visible
    tau_race = np.cross(qq[cage, :3] - qq[race, :3], -f_cage)
    scale = np.linalg.norm(f_cage)
    np.testing.assert_allclose(land[cage, :3], f_cage, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(land[cage, 3:], 0.0, atol=1e-9 * scale * BRG.pitch_radius)
    np.testing.assert_allclose(land[race, :3], -f_cage, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(land[race, 3:], rot_race.T @ tau_race, rtol=0, atol=1e-9 * np.linalg.norm(tau_race))
    others = [s for s in range(len(land)) if s not in (cage, race)]
    assert np.all(land[others] == 0.0)

    # internal forces only (no drag, no applied load): momentum balance with the land term
    gen = forces[guidance]
    rot = [Rotation.from_rotvec(qq[s, 3:]).as_matrix() for s in range(len(qq))]
    torques = np.array([rot[s] @ gen[s, 3:] for s in range(len(qq))])
    moments = np.cross(qq[:, :3], gen[:, :3]) + torques
    assert np.linalg.norm(gen[:, :3].sum(axis=0)) <= 1e-9 * np.abs(gen[:, :3]).sum()
    assert np.linalg.norm(moments.sum(axis=0)) <= 1e-9 * np.linalg.norm(moments, axis=1).sum()

    # a cage inside its play feels no land
    qq[cage, :3] = position + 0.15e-3 * radial
    state = con.evaluate(0.0, qq.ravel(), vv.ravel(), details=True)
    d = qq[cage, :3] - qq[race, :3]
    assert np.all(state.cage_land_force == 0.0)
    assert abs(state.cage_eccentricity - np.linalg.norm(d - (d @ axis) * axis)) < 1e-12
