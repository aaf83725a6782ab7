"""Pure rolling with raceway control (Jones; MODEL.md §7): which contact controls a ball's
spin, and the orbital and angular velocities that roll without slip at both contacts. Used
by the pure-rolling start and by the steady-state solver's first guess."""
from __future__ import annotations

import numpy as np

from contact import film
from contact.kinematics import rolling_cage_speed

__all__ = ["choose_inner_control", "jones_axis_start", "raceway_control"]


def _spin_resistance(bearing, lubricant, load, angle, race, speed):
    """Newtonian spin resistance (1/h) of the integral of eta (x² + y²) over the Hertz
    ellipse, N m s (MODEL.md §5–§6): the spin moment per unit spin at small spin."""
    r_x, _ = bearing.curvature_radii(angle, race)
    con = bearing.hertz(angle, race)
    a, b = con.semi_axes(load)
    lam = lubricant.pressure_viscosity * con.max_pressure(load)
    h = np.maximum(film.central_film_thickness(speed, load, r_x, con.ellipticity, bearing.effective_modulus,
                                               lubricant), 1e-9)
    # polar: x = b R cos t, y = a R sin t; integral of R^3 exp(lam sqrt(1 - R²)) dR by Gauss
    nodes, weights = np.polynomial.legendre.leggauss(24)
    r = 0.5 * (nodes + 1.0)
    radial = 0.5 * np.sum(weights * r ** 3 * np.exp(np.multiply.outer(lam, np.sqrt(1.0 - r ** 2))), axis=-1)
    return lubricant.viscosity * np.pi * a * b * (a ** 2 + b ** 2) * radial / h


def choose_inner_control(bearing, lubricant, loads, w_i, w_o, control="auto"):
    """Per ball: True where the inner contact controls the spin (raceway control, Jones):
    'auto' takes the contact with the larger Newtonian spin resistance, which under EHD
    traction is usually the smaller, higher-pressure inner contact."""
    if control != "auto":
        return np.full(bearing.balls, control == "inner")
    gamma = bearing.ball_diameter / bearing.pitch_diameter
    speed = max(abs(w_i - w_o), 1e-3) * bearing.pitch_radius * (1 - gamma ** 2) / 2  # entrainment, m/s
    q_i, q_o = np.maximum(loads.inner_load, 1e-9), np.maximum(loads.outer_load, 1e-9)
    m_i = _spin_resistance(bearing, lubricant, q_i, loads.inner_contact_angle, "inner", speed)
    m_o = _spin_resistance(bearing, lubricant, q_o, loads.outer_contact_angle, "outer", speed)
    return m_i > m_o


def jones_axis_start(bearing, c_loc, p_in, p_out, a_i, a_o, e_r, w_i, w_o, inner_controls,
                     inner_origin=(0.0, 0.0, 0.0)):
    """The 'auto' start: Jones' raceway-control angle, tan b = sin a / (cos a -/+ D/d_m) —
    the spin axis relative to the cage — taken as the absolute axis, with zero rolling slip
    at both contacts. Not a raceway-control state (both contacts spin a little), but it lies
    between the inner- and outer-controlled absolute axes and starts the combined-load
    case with the fewest step cuts (0.02 s, reference bearing, 2.2 kN + 2 kN radial: 201
    steps for 200 and 52 Jacobians; exact inner / outer control 494 / 222 steps). The inner
    race's surface speeds are taken about its own centre ``inner_origin`` (bearing frame, m):
    about the bearing axis instead, a race displaced 20 um by a radial load at 3000 rpm
    would start its most loaded balls 6 mm/s off rolling."""
    gamma = bearing.ball_diameter / bearing.pitch_diameter
    beta = np.where(inner_controls, np.arctan2(np.sin(a_i), np.cos(a_i) - gamma),
                    np.arctan2(np.sin(a_o), np.cos(a_o) + gamma))
    axis = -np.sin(beta)[:, None] * e_r + np.cos(beta)[:, None] * np.array([0.0, 0.0, 1.0])
    w_c, spin = rolling_cage_speed(c_loc, axis, p_in, p_out, w_i, w_o, return_spin=True, inner_origin=inner_origin)
    return w_c, spin[:, None] * axis


def raceway_control(centre, inner_point, outer_point, inner_speed, outer_speed, inner_controls, cage_speed=None,
                    inner_origin=(0.0, 0.0, 0.0)):
    """Pure rolling with raceway control (MODEL.md §7): per ball the orbital speed w_c and the
    absolute angular velocity w_b (in the ball's meridional plane) with zero rolling slip at
    both contact centres and zero spin at the controlling contact, (w_race e_z - w_b) . n = 0.

    All three conditions are linear in (w_c, w_b . e_r, w_b . e_z): with d = p - c and the
    race surface speed along the rolling direction e_psi,
    w_c r_c + (w_b x d) . e_psi = w_race ((p - o) . e_r), o the race centre, and
    (w_race e_z - w_b) . n = 0 with
    n = d / |d|. (Jones' tan(beta) formulas give the same axis relative to the cage; used
    as the absolute axis they leave spin at the controlling contact.)

    Parameters
    ----------
    centre, inner_point, outer_point : ndarray (Z, 3)
        Ball centres and contact centres, bearing frame (z the axis), m.
    inner_speed, outer_speed : float
        Race speeds about +z, rad/s.
    inner_controls : ndarray of bool (Z,)
    cage_speed : float, optional
        Impose this orbital speed on every ball (rad/s): the rolling condition of the
        non-controlling contact is then dropped.
    inner_origin : (3,), optional
        Centre of the (displaced) inner race, bearing frame, m.

    Returns
    -------
    w_c : ndarray (Z,), rad/s
    omega : ndarray (Z, 3), rad/s, bearing frame
    """
    c = np.asarray(centre, dtype=float)
    r_c = np.hypot(c[:, 0], c[:, 1])
    e_r = np.stack([c[:, 0] / r_c, c[:, 1] / r_c, np.zeros(len(c))], axis=1)
    e_z = np.array([0.0, 0.0, 1.0])
    w_c = np.empty(len(c))
    omega = np.empty((len(c), 3))
    for j in range(len(c)):
        rows, rhs = [], []
        normals = {}
        for name, p, w_race, o in (("inner", inner_point[j], inner_speed, np.asarray(inner_origin, dtype=float)),
                                   ("outer", outer_point[j], outer_speed, np.zeros(3))):
            d = p - c[j]
            dr, dz = d @ e_r[j], d[2]
            # (w_b x d) . e_psi with w_b = x e_r + y e_z and d = dr e_r + dz e_z: y dr - x dz
            rows.append([r_c[j], -dz, dr])
            rhs.append(w_race * ((p - o) @ e_r[j]))
            normals[name] = (np.array([dr, dz]) / np.hypot(dr, dz), w_race)
        (n_r, n_z), w_race = normals["inner" if inner_controls[j] else "outer"]
        rows.append([0.0, n_r, n_z])
        rhs.append(w_race * n_z)
        if cage_speed is None:
            w_c[j], x, y = np.linalg.solve(np.array(rows), np.array(rhs))
        else:
            keep = [0 if inner_controls[j] else 1, 2]
            a, b = np.array(rows)[keep], np.array(rhs)[keep]
            w_c[j] = cage_speed
            x, y = np.linalg.solve(a[:, 1:], b - a[:, 0] * cage_speed)
        omega[j] = x * e_r[j] + y * e_z
    return w_c, omega
