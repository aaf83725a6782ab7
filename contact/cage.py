"""Ball–cage interaction and ball drag (MODEL.md §1, §8; paper P9, P10), vectorized.

Pocket normal forces act at the ball centres (a pocket pushes the ball along its
circumferential direction through the centre), so they put no moment on the balls; the
cage receives the opposite force at the same point. Pocket friction (MODEL.md §11d) acts at
the contact point on the ball's surface, so it does.
"""
from __future__ import annotations

import numpy as np

from .kinematics import cross

__all__ = ["pocket_forces", "pocket_friction", "spring_chain_forces", "radial_offset", "land_forces", "drag_forces",
           "jet_momentum_factor"]


def pocket_forces(ball_centre, ball_velocity, cage_origin, cage_rotation, cage_velocity, cage_omega,
                  pocket_angles, pitch_radius, clearance, stiffness, damping):
    """Pocket contact forces on the balls, (n, 3), N.

    Pocket j sits at angle phi_j on the pitch circle of the cage frame; s_j is the ball
    centre's offset from the pocket centre along the pocket's circumferential direction
    e_j. With half-clearance g = clearance/2 the force on the ball is
    -(k (|s| - g) + c ds/dt sign(s)) sign(s) e_j when |s| > g (clipped so a pocket
    never pulls), zero otherwise; clearance 0 gives the paper's bilateral spring.

    Parameters
    ----------
    ball_centre, ball_velocity : ndarray, (..., n, 3)
    cage_origin, cage_velocity, cage_omega : ndarray, (..., 3)
    cage_rotation : ndarray, (..., 3, 3)
        Cage frame -> global; third column is the bearing axis. Leading axes (a batch of
        states) broadcast.
    pocket_angles : ndarray, (n,)
        rad, in the cage frame.
    pitch_radius, clearance : float
        m (clearance: circumferential play of a ball in its pocket).
    stiffness, damping : float
        N/m, N s/m.
    """
    local_centre = np.stack([np.cos(pocket_angles), np.sin(pocket_angles), np.zeros_like(pocket_angles)], axis=1)
    local_dir = np.stack([-np.sin(pocket_angles), np.cos(pocket_angles), np.zeros_like(pocket_angles)], axis=1)
    origin = np.asarray(cage_origin, dtype=float)[..., None, :]
    centre = origin + pitch_radius * np.einsum("...ij,nj->...ni", cage_rotation, local_centre)
    e = np.einsum("...ij,nj->...ni", cage_rotation, local_dir)
    s = np.einsum("...j,...j->...", ball_centre - centre, e)
    v_pocket = np.asarray(cage_velocity, dtype=float)[..., None, :] + cross(
        np.asarray(cage_omega, dtype=float)[..., None, :], centre - origin)
    # ds/dt of s = (c - centre) . e, with e turning with the cage: a ball orbiting with its
    # pocket off the pitch circle keeps s (without the second term the damping would push it)
    omega = np.asarray(cage_omega, dtype=float)[..., None, :]
    s_dot = (np.einsum("...j,...j->...", ball_velocity - v_pocket, e)
             + np.einsum("...j,...j->...", ball_centre - centre, cross(omega, e)))
    gap = 0.5 * clearance
    if gap == 0:
        magnitude = -stiffness * s - damping * s_dot
    else:
        sign = np.sign(s)
        pen = np.abs(s) - gap
        magnitude = np.where(pen > 0, -sign * np.maximum(stiffness * pen + damping * s_dot * sign, 0.0), 0.0)
    return magnitude[..., None] * e


def pocket_friction(pocket_force, ball_centre, ball_velocity, ball_omega, cage_origin, cage_velocity, cage_omega,
                    ball_radius, coefficient, slip_scale):
    """Sliding friction at the ball–pocket contacts (MODEL.md §11d), regularized Coulomb.

    The pocket pushes the ball with N = |F| along n = F/N (``pocket_force`` F from
    :func:`pocket_forces`); the contact lies on the ball at p = c - r n. The ball surface
    slides on the pocket there at v_rel = v_b + w_b x (p - c) - (v_cage + w_cage x (p - o));
    its tangential part v_t = v_rel - (v_rel . n) n meets the friction force

        F_f = -mu N v_t / sqrt(|v_t|² + v_s²)

    (Coulomb with mu = ``coefficient`` beyond the slip scale v_s, viscous below it, so the
    force is smooth for Newton and dissipates at any slip). The cage takes -F_f at p.

    Parameters
    ----------
    pocket_force, ball_centre, ball_velocity, ball_omega : ndarray, (..., n, 3)
        N, m, m/s, rad/s (global frame).
    cage_origin, cage_velocity, cage_omega : ndarray, (..., 3)
    ball_radius, coefficient, slip_scale : float
        m, -, m/s.

    Returns
    -------
    force : ndarray (..., n, 3)
        F_f on the balls, N.
    point : ndarray (..., n, 3)
        Contact points p, m.
    loss : ndarray (..., n)
        Dissipated power -F_f . v_t = mu N |v_t|² / sqrt(|v_t|² + v_s²), W.
    """
    f = np.asarray(pocket_force, dtype=float)
    normal_load = np.linalg.norm(f, axis=-1)
    n = f / np.maximum(normal_load, 1e-300)[..., None]
    arm = -ball_radius * n  # p - c
    point = np.asarray(ball_centre, dtype=float) + arm
    origin = np.asarray(cage_origin, dtype=float)[..., None, :]
    v_ball = np.asarray(ball_velocity, dtype=float) + cross(np.asarray(ball_omega, dtype=float), arm)
    v_cage = np.asarray(cage_velocity, dtype=float)[..., None, :] + cross(
        np.asarray(cage_omega, dtype=float)[..., None, :], point - origin)
    v_rel = v_ball - v_cage
    v_t = v_rel - np.einsum("...j,...j->...", v_rel, n)[..., None] * n
    speed2 = np.einsum("...j,...j->...", v_t, v_t)
    scale = coefficient * normal_load / np.sqrt(speed2 + slip_scale ** 2)
    return -scale[..., None] * v_t, point, scale * speed2


def spring_chain_forces(ball_centre, axis, pitch_radius, stiffness, origin=(0.0, 0.0, 0.0)):
    """The paper's cage (P9, P10): springs between neighbouring balls, (n, 3), N.

    Each spring j (ball j to ball j + 1) is strained by the azimuth difference of its balls,
    dpsi_j = psi_(j+1) - psi_j - 2 pi / Z, and acts as a torsional spring about the bearing
    axis of torque T_j = k r_p² dpsi_j (k in N/m: k times the arc length at r_p): ball j gets
    T_j / r_j along its circumferential direction e_psi, ball j + 1 gets -T_j / r_(j+1).
    So the chain holds the balls' spacing only — no radial force at any orbit radius (a
    chord-length spring is a hoop that pulls balls orbiting outside r_p inward) — and puts
    no net moment about the axis on the balls.
    """
    c = np.asarray(ball_centre, dtype=float) - np.asarray(origin, dtype=float)  # (..., n, 3)
    axis = np.asarray(axis, dtype=float)
    planar = c - (c @ axis)[..., None] * axis
    radius = np.linalg.norm(planar, axis=-1)
    e_psi = np.cross(axis, planar) / radius[..., None]
    nxt = np.roll(planar, -1, axis=-2)
    turn = np.arctan2(np.cross(planar, nxt) @ axis, np.einsum("...i,...i->...", planar, nxt))
    torque = stiffness * pitch_radius ** 2 * (turn - 2.0 * np.pi / c.shape[-2])  # spring j, stretched > 0
    return (torque / radius)[..., None] * e_psi - (np.roll(torque, 1, axis=-1) / radius)[..., None] * e_psi


def radial_offset(point, origin, axis):
    """Offset of ``point`` from the axis through ``origin`` (unit ``axis``), projected on
    the plane normal to the axis, (..., 3), m."""
    axis = np.asarray(axis, dtype=float)
    d = np.asarray(point, dtype=float) - origin
    return d - np.einsum("...j,...j->...", d, axis)[..., None] * axis


def land_forces(cage_origin, cage_velocity, race_origin, race_velocity, axis, radial_clearance, stiffness,
                damping):
    """Guiding-land contact of a race-guided cage (MODEL.md §1), force on the cage (..., 3), N.

    The cage ring runs in the race's guiding land (a cylinder about ``axis``) with radial
    play g = ``radial_clearance``. With the eccentricity e (the cage centre's offset from
    the race centre, projected on the bearing plane) and n = e/|e|, the force on the cage
    is -max(k (|e| - g) + c d|e|/dt, 0) n when |e| > g (a land pushes, never pulls), zero
    otherwise; the race receives the opposite force. Radial, through both centres: no
    moment about the cage centre. Land friction is not modelled.

    Parameters
    ----------
    cage_origin, cage_velocity, race_origin, race_velocity : ndarray, (..., 3)
        m, m/s (the race velocity of its frame origin).
    axis : ndarray, (..., 3)
        Unit race axis.
    radial_clearance : float
        g, m (half the diametral guiding clearance).
    stiffness, damping : float
        N/m, N s/m.
    """
    e_vec = radial_offset(cage_origin, race_origin, axis)
    e = np.linalg.norm(e_vec, axis=-1)
    n = e_vec / np.where(e > 0, e, 1.0)[..., None]
    e_dot = np.einsum("...j,...j->...", np.asarray(cage_velocity, dtype=float) - race_velocity, n)
    pen = e - radial_clearance
    magnitude = np.where(pen > 0, np.maximum(stiffness * pen + damping * contact_ramp(pen) * e_dot, 0.0), 0.0)
    return -magnitude[..., None] * n


#: penetration over which the guiding land's damping rises from zero to its full value, m
#: (contact_ramp): the contact force then starts from zero at any approach speed
LAND_DAMPING_DEPTH = 10e-6


def contact_ramp(penetration, depth=LAND_DAMPING_DEPTH):
    """Cubic step 3 u² − 2 u³ of u = penetration / depth, clipped to [0, 1]: the share of the
    damping active at that penetration (the ramp of MSC Adams' IMPACT function; MODEL.md §11d),
    so a contact closing at speed starts with zero force instead of c times the speed."""
    u = np.clip(np.asarray(penetration, dtype=float) / depth, 0.0, 1.0)
    return u * u * (3.0 - 2.0 * u)


def land_friction_constant(viscosity, radius, width, radial_clearance):
    """K = 2 π η0 R³ L / c of :func:`land_friction_torque`, N m s (MODEL.md §11d)."""
    return 2.0 * np.pi * viscosity * radius ** 3 * width / radial_clearance


def land_friction_torque(constant, slip_speed, eccentricity_ratio, max_ratio=0.95):
    """Friction torque of a guiding land's oil film on the cage, N m (MODEL.md §11d): the
    shear (Petroff) term of the short journal bearing,
    T = K (w_land - w_cage) / √(1 - ε²), K = 2 π η0 R³ L / c (Hamrock, Schmid & Jacobson,
    Fundamentals of Machine Elements / Fluid Film Lubrication, short-bearing theory; Harris &
    Kotzalas use it for the cage land), ε = e / c capped at ``max_ratio`` (the film's
    thinnest point; contact beyond is the land force's business). Positive drags the cage
    forward; the land takes the opposite."""
    eps = np.minimum(np.abs(np.asarray(eccentricity_ratio, dtype=float)), max_ratio)
    return constant * np.asarray(slip_speed, dtype=float) / np.sqrt(1.0 - eps ** 2)


def drag_forces(ball_centre, ball_velocity, axis, origin, drag_coefficient, density, ball_radius, linear=0.0):
    """Drag against each ball's orbital motion (MODEL.md §8, §11c), (n, 3), N: the sphere's
    F_D = 1/2 C_D rho pi r² v² through still oil plus, with ``linear`` k (kg/s, from
    :func:`jet_momentum_factor`), the jet oil's momentum k v; v the circumferential
    ball-centre speed about ``axis``."""
    rel = np.asarray(ball_centre, dtype=float) - origin
    e_psi = cross(axis, rel)
    e_psi /= np.linalg.norm(e_psi, axis=-1, keepdims=True)
    v = np.einsum("...j,...j->...", ball_velocity, e_psi)
    return (-(0.5 * drag_coefficient * density * np.pi * ball_radius ** 2 * np.abs(v) + linear) * v)[..., None] * e_psi


def jet_momentum_factor(oil_flow, density, pitch_radius, exit_radius, balls):
    """k = rho Q r_x² / (Z r_p²), kg/s, of the jet oil's momentum (Euler) loss on each ball
    (MODEL.md §11c, eq. 11c.2): oil entering at Q (m³/s) without swirl and leaving at the
    balls' orbital angular speed at radius r_x (m) takes the torque rho Q r_x² ω_c; shared by
    the Z balls at the pitch radius r_p (m) it is k v on each (v = ω_c r_p), power
    rho Q (ω_c r_x)² in all."""
    return density * oil_flow * exit_radius ** 2 / (balls * pitch_radius ** 2)
