"""Ball–race contact kinematics (MODEL.md §2, §6, §7), vectorized over contacts.

Everything is in one (global) frame. A race is a rigid body with a frame (origin ``o``,
rotation ``A`` whose third column is the race axis) in which its groove torus is
described (:func:`contact.geometry.groove_contact`), and a velocity field
v(x) = v_o + w_r x (x - o).

Contact frame (MODEL.md §6): n is the outward normal of the ball (groove centre ->
ball centre -> contact point), t1 the rolling direction (the race's circumferential
direction at the ball), t2 = n x t1. Slip u = race surface velocity minus ball surface
velocity at the contact centre; spin w_s = (w_race - w_ball) . n.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import geometry

__all__ = ["ContactKinematics", "ball_race_kinematics", "rolling_cage_speed", "rotation_matrices", "cross"]


def cross(a, b):
    """Cross product over the last axis; numpy's ``np.cross`` costs ~10 us of axis
    bookkeeping per call, which dominates on the (n, 3) arrays of a bearing."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


def rotation_matrices(rotation_vectors):
    """Rotation matrices of rotation vectors (Rodrigues), shape (n, 3) -> (n, 3, 3); valid
    for any angle (no wrapping needed)."""
    nu = np.asarray(rotation_vectors, dtype=float)
    angle2 = _dot(nu, nu)
    angle = np.sqrt(angle2)
    small = angle2 < 1e-12
    safe = np.where(small, 1.0, angle)
    # series below 1e-6 rad keep the coefficients exact to rounding
    c1 = np.where(small, 1.0 - angle2 / 6.0, np.sin(safe) / safe)
    c2 = np.where(small, 0.5 - angle2 / 24.0, (1.0 - np.cos(safe)) / np.where(small, 1.0, angle2))
    s = np.zeros(nu.shape[:-1] + (3, 3))
    s[..., 0, 1], s[..., 0, 2], s[..., 1, 2] = -nu[..., 2], nu[..., 1], -nu[..., 0]
    s[..., 1, 0], s[..., 2, 0], s[..., 2, 1] = nu[..., 2], -nu[..., 1], nu[..., 0]
    return np.eye(3) + c1[..., None, None] * s + c2[..., None, None] * (s @ s)


@dataclass(frozen=True)
class ContactKinematics:
    """State of n ball–race contacts (global frame, SI units). See the module docstring."""

    penetration: np.ndarray  #: delta, m (> 0 in contact)
    penetration_rate: np.ndarray  #: d delta / dt, m/s
    normal: np.ndarray  #: n, (n, 3)
    rolling: np.ndarray  #: t1, (n, 3)
    transverse: np.ndarray  #: t2 = n x t1, (n, 3)
    point: np.ndarray  #: contact centre p = c + r n, (n, 3), m
    contact_angle: np.ndarray  #: rad (MODEL.md §2)
    slip_rolling: np.ndarray  #: u_x, m/s
    slip_transverse: np.ndarray  #: u_y, m/s
    spin: np.ndarray  #: w_s, rad/s
    entrainment: np.ndarray  #: mean surface speed relative to the moving contact, m/s
    orbit_radius: np.ndarray  #: distance of the ball centre from the race axis, m
    point_radius: np.ndarray  #: distance of the contact centre from the race axis, m
    #: relative rolling rotation (w_ball - w_race) . t2, rad/s (MODEL.md §11b)
    rolling_rate: np.ndarray = None
    #: azimuth of the contact in the race's own frame, rad (MODEL.md §13)
    azimuth: np.ndarray = None
    #: the ball's orbital speed relative to the race, d(azimuth)/dt, rad/s
    orbit_rate: np.ndarray = None
    #: slope dh/ds of the surfaces' height along t1 at the contact (MODEL.md eq. 13.7); None: flat
    surface_slope: np.ndarray = None
    #: G = ∂h/∂φ (n, 3) m/rad of the ball's own surface: the load turns the ball by −Q G (eq. 13.7b)
    surface_turn: np.ndarray = None


def ball_race_kinematics(ball_centre, ball_velocity, ball_omega, race_origin, race_rotation,
                         race_velocity, race_omega, groove, ball_radius, race):
    """Contact kinematics of n balls against one race (MODEL.md §2, §6).

    Parameters
    ----------
    ball_centre, ball_velocity, ball_omega : ndarray, shape (n, 3)
        Ball centres (m), centre velocities (m/s), absolute angular velocities (rad/s).
    race_origin, race_velocity, race_omega : ndarray, shape (3,) or (n, 3)
        Race-frame origin (m), its velocity (m/s), race angular velocity (rad/s).
    race_rotation : ndarray, shape (3, 3) or (n, 3, 3)
        Race frame -> global rotation; its third column is the race axis.
    groove : (centre_radius, centre_z, tube_clearance)
        Groove-centre circle in the race frame and (f - 1/2) D, m.
    ball_radius : float
        m.
    race : {'inner', 'outer'}
    """
    c = np.asarray(ball_centre, dtype=float)
    rot = np.broadcast_to(np.asarray(race_rotation, dtype=float), c.shape[:-1] + (3, 3))
    rel = c - race_origin
    local = np.einsum("nji,nj->ni", rot, rel)
    con = geometry.groove_contact(local, *groove, race)
    n = np.einsum("nij,nj->ni", rot, con.normal)
    t1 = np.einsum("nij,nj->ni", rot, cross([0.0, 0.0, 1.0], con.radial))
    t2 = cross(n, t1)
    p = c + ball_radius * n
    w_b = np.asarray(ball_omega, dtype=float)
    w_r = np.broadcast_to(np.asarray(race_omega, dtype=float), c.shape)
    v_o = np.broadcast_to(np.asarray(race_velocity, dtype=float), c.shape)
    v_ball_p = ball_velocity + cross(w_b, p - c)
    v_race_p = v_o + cross(w_r, p - race_origin)
    slip = v_race_p - v_ball_p
    g = np.einsum("nij,nj->ni", rot, con.groove_centre) + race_origin
    v_groove = v_o + cross(w_r, g - race_origin)
    rate = _dot(ball_velocity - v_groove, n)
    rho_c = np.hypot(local[:, 0], local[:, 1])
    p_local = local + ball_radius * con.normal
    rho_p = np.hypot(p_local[:, 0], p_local[:, 1])
    # the contact moves with the ball's orbit about the race axis, relative to the race:
    orbit_rel = _dot(ball_velocity - (v_o + cross(w_r, rel)), t1) / rho_c
    u_x = _dot(slip, t1)
    entrainment = -0.5 * u_x - orbit_rel * rho_p
    return ContactKinematics(con.penetration, rate, n, t1, t2, p, con.contact_angle, u_x, _dot(slip, t2),
                             _dot(w_r - w_b, n), entrainment, rho_c, rho_p, _dot(w_b - w_r, t2),
                             np.arctan2(local[:, 1], local[:, 0]), orbit_rel)


def rolling_cage_speed(ball_centre, spin_axis, inner_point, outer_point, inner_speed, outer_speed,
                       return_spin=False, surface_speeds=None, inner_origin=(0.0, 0.0, 0.0)):
    """Pure-rolling (kinematic) orbital speed of each ball for its actual geometry and
    spin-axis direction (MODEL.md §7), rad/s.

    Solves, per ball, for the orbital speed w_c and spin magnitude W with zero
    rolling-direction slip at both contact centres:
    w_c r_c + W (e x (p - c)) . t1 = w_race rho_p, for the inner and the outer contact.
    All positions in a frame whose z axis is the bearing axis with origin on it; the inner
    race turns about its own centre ``inner_origin`` (a radially displaced race), the outer
    about the origin.

    Parameters
    ----------
    ball_centre, spin_axis, inner_point, outer_point : ndarray, shape (n, 3)
        Ball centres, direction of the absolute ball angular velocity (any length),
        inner and outer contact centres, m.
    inner_speed, outer_speed : float
        Race angular speeds about +z, rad/s.

    surface_speeds : (ndarray, ndarray), optional
        Race surface speeds along t1 at the inner and outer contact centres, m/s; they
        replace w_race rho_p (e.g. for a race displaced from the bearing axis).
    return_spin : bool
        Also return W, the spin speed about ``spin_axis`` (rad/s).
    inner_origin : (3,), optional
        Centre of the inner race, m (its axis parallel to z).

    Returns
    -------
    w_c : ndarray, shape (n,)
    W : ndarray, shape (n,), only with ``return_spin``
    """
    c = np.asarray(ball_centre, dtype=float)
    e = np.asarray(spin_axis, dtype=float)
    norm = np.linalg.norm(e, axis=-1, keepdims=True)
    # a ball at rest has no spin axis; any axis gives W = 0 there, take the bearing axis
    e = np.where(norm > 0, e / np.where(norm > 0, norm, 1.0), [0.0, 0.0, 1.0])
    r_c = np.hypot(c[:, 0], c[:, 1])
    t1 = np.stack([-c[:, 1], c[:, 0], np.zeros(len(c))], axis=1) / r_c[:, None]
    rows = []
    rhs = []
    races = ((inner_point, inner_speed, inner_origin), (outer_point, outer_speed, (0.0, 0.0, 0.0)))
    for i, (p, speed, o) in enumerate(races):
        p = np.asarray(p, dtype=float)
        rows.append(np.stack([r_c, _dot(cross(e, p - c), t1)], axis=1))
        if surface_speeds is None:  # race surface speed w rho_p about the race's own centre
            rhs.append(speed * _dot(cross([0.0, 0.0, 1.0], p - np.asarray(o, dtype=float)), t1))
        else:
            rhs.append(np.asarray(surface_speeds[i], dtype=float))
    a = np.stack(rows, axis=1)  # (n, 2, 2)
    b = np.stack(rhs, axis=1)
    sol = np.linalg.solve(a, b[..., None])[..., 0]
    return (sol[:, 0], sol[:, 1]) if return_spin else sol[:, 0]
