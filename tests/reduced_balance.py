"""A steady rolling balance of one ball under pure axial load, written for the tests
independently of the dynamic model (no connector, builder or ``contact.kinematics``).

All balls alike and the cage free of torque, so every pocket force vanishes. In the frame
that orbits with the ball at speed w_c the ball centre c = (r_c, 0, z_c) is at rest and its
absolute angular velocity w_b is constant, so (MODEL.md §1–§3, §6, §8)

    force on the ball:   F_inner + F_outer - F_D e_psi = -m r_c w_c² e_r,
                         F_D = 1/2 C_D rho pi r² (w_c r_c)²     (drag against the orbit)
    moment about c:      sum (r n × f_t + M_z n) = dH/dt = I w_c e_z × w_b   (sphere, I = 2/5 m r²)
    inner race, axial:   Z (F_inner . e_z) = F_a

with F = -Q n + f_t, Q = K delta^(3/2) from the groove tori (the inner groove shifted axially
by the race's displacement), f_t the Crook traction along t1 (rolling) and t2 = n × t1: seven
equations in (w_c, w_b, r_c, z_c, inner-race axial displacement). Only the contact kernels of
``contact/`` are shared with the package (Hertz constants, Hamrock–Dowson film, Crook traction
and spin moment — each tested on its own against closed forms and adaptive quadrature); the
traction is evaluated with the accurate adaptive rule, not the fast rule the dynamic model
runs on.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from contact import film
from contact.traction import crook_traction
from exudyn_bearing.solvers.quasistatic import solve_load_distribution

MICRON = 1e-6


@dataclass
class Balance:
    cage_speed: float  #: w_c, rad/s
    ball_omega: np.ndarray  #: absolute ball angular velocity (radial, circumferential, axial), rad/s
    kinematic_cage_speed: float  #: pure-rolling cage speed for the balance's spin axis, rad/s
    kinematic_cage_slip_percent: float
    inner_load: float  #: N
    outer_load: float  #: N
    inner_contact_angle: float  #: rad
    outer_contact_angle: float  #: rad
    film_inner: float  #: central film thickness, m
    residual: float  #: largest scaled residual

    @property
    def attitude_xz(self):
        """beta_XZ = asin(|w_radial| / |w|), rad (MODEL.md §7)."""
        return math.asin(abs(self.ball_omega[0]) / np.linalg.norm(self.ball_omega))

    @property
    def attitude_yz(self):
        """beta_YZ = asin(|w_circumferential| / |w|), rad."""
        return math.asin(abs(self.ball_omega[1]) / np.linalg.norm(self.ball_omega))


def _contact(bearing, lubricant, c, groove, w_c, w_b, w_race, race, limiting_shear=None, film_modulus=None):
    """Normal load, force on the ball and moment about its centre of one contact at
    azimuth 0 (x radial, y circumferential = rolling direction t1, z axial)."""
    r = bearing.ball_radius
    conformity = bearing.inner_conformity if race == "inner" else bearing.outer_conformity
    d = c - groove
    n = d / np.linalg.norm(d)  # groove centre -> ball centre -> contact point
    delta = np.linalg.norm(d) - (conformity - 0.5) * bearing.ball_diameter
    sign = -1.0 if race == "inner" else 1.0
    angle = math.atan2(sign * n[2], sign * n[0])
    con = bearing.hertz(angle, race)
    load = float(con.stiffness) * max(delta, 0.0) ** 1.5
    p = c + r * n
    t1 = np.array([0.0, 1.0, 0.0])
    t2 = np.cross(n, t1)
    v_ball = np.array([0.0, w_c * c[0], 0.0]) + np.cross(w_b, p - c)
    u = np.cross([0.0, 0.0, w_race], p) - v_ball
    spin = (np.array([0.0, 0.0, w_race]) - w_b) @ n
    # mean surface speed relative to the contact, which orbits at w_c
    entrain = 0.5 * ((w_race - w_c) * p[0] + (v_ball @ t1 - w_c * p[0]))
    r_x, _ = bearing.curvature_radii(angle, race)
    a, b = con.semi_axes(load)
    h = max(float(film.central_film_thickness(entrain, load, r_x, con.ellipticity, bearing.effective_modulus,
                                              lubricant)), 1e-8)
    tr = crook_traction(u @ t1, u @ t2, spin, a, b, con.max_pressure(load), h, lubricant, order=24,
                        limiting_shear=limiting_shear, film_modulus=film_modulus, entrainment=entrain)
    tangential = float(tr.fx) * t1 + float(tr.fy) * t2
    moment = r * np.cross(n, tangential) + float(tr.mz) * n
    return -load * n + tangential, moment, p, load, angle, h


def rolling_cage_speed(c, axis, p_in, p_out, w_i):
    """Pure-rolling orbital speed for the absolute spin axis ``axis`` (outer race fixed):
    zero rolling slip at both contact centres, w_c r_c + W (e × (p - c))_y = w_race p_x."""
    e = axis / np.linalg.norm(axis)
    rows = [[c[0], np.cross(e, p - c)[1]] for p in (p_in, p_out)]
    w_c, _ = np.linalg.solve(rows, [w_i * p_in[0], 0.0])
    return w_c


def solve_balance(bearing, lubricant, axial, rpm, drag_coefficient, oil_density, limiting_shear=None,
                  film_modulus=None, start_axis="free") -> Balance:
    """Steady state of a bearing under pure ``axial`` load (N), outer race fixed, inner
    race at ``rpm``, with drag F_D = 1/2 C_D rho pi r² v² for the given C_D and oil
    density (kg/m³; MODEL.md §8) and Crook's traction, capped smoothly at
    ``limiting_shear`` x p (MODEL.md §6a; None: the paper's pure law), with the film's elastic
    compliance G = ``film_modulus`` x p (MODEL.md §6b; None: none).
    ``start_axis``: the first guess of the ball's spin axis, 'free' (tilted by the free angle)
    or 'outer' (perpendicular to the quasi-static outer contact normal: at high speed the
    outer race controls the ball)."""
    w_i = rpm * math.pi / 30
    r, z, m = bearing.ball_radius, bearing.balls, bearing.ball_mass
    inertia = 0.4 * m * r ** 2
    (r_gi, z_gi), (r_go, z_go) = bearing.groove_centres()
    gamma = bearing.ball_diameter * math.cos(bearing.contact_angle) / bearing.pitch_diameter
    w_nom = 0.5 * w_i * (1 - gamma)
    w_spin = w_i * bearing.pitch_diameter / bearing.ball_diameter / 2  # scale of the ball spin
    scale = axial / (z * math.sin(bearing.contact_angle))  # force scale, N

    def unpack(x):  # cage speed, ball omega, ball centre (r, z), inner race axial shift
        return (x[0] * w_nom, x[1:4] * w_spin, np.array([bearing.pitch_radius + x[4] * MICRON, 0.0, x[5] * MICRON]),
                x[6] * MICRON)

    def contacts(x):
        w_c, w_b, c, shift = unpack(x)
        inner = _contact(bearing, lubricant, c, np.array([r_gi, 0.0, z_gi + shift]), w_c, w_b, w_i, "inner",
                         limiting_shear, film_modulus)
        outer = _contact(bearing, lubricant, c, np.array([r_go, 0.0, z_go]), w_c, w_b, 0.0, "outer", limiting_shear,
                         film_modulus)
        return w_c, w_b, c, inner, outer

    def residual(x):
        w_c, w_b, c, (f_i, m_i, *_), (f_o, m_o, *_) = contacts(x)
        drag = 0.5 * drag_coefficient * oil_density * math.pi * r ** 2 * (w_c * c[0]) ** 2
        force = f_i + f_o - np.array([0.0, drag, 0.0]) + np.array([m * c[0] * w_c ** 2, 0.0, 0.0])
        gyro = inertia * w_c * np.cross([0.0, 0.0, 1.0], w_b)
        return np.concatenate([force / scale, (m_i + m_o - gyro) / (scale * r), [(f_i[2] - axial / z) / scale]])

    def solve(x, free):
        def reduced(y):
            full = x.copy()
            full[free] = y
            return residual(full)[free_equations[len(y)]]

        sol = least_squares(reduced, x[free], x_scale=x_scale[free], xtol=1e-15, ftol=1e-15, gtol=1e-15,
                            method="lm", max_nfev=4000)
        out = x.copy()
        out[free] = sol.x
        return out, float(np.max(np.abs(sol.fun)))

    x_scale = np.array([1.0, 1.0, 0.1, 1.0, 10.0, 10.0, 10.0])
    free_equations = {4: [1, 3, 4, 5], 7: list(range(7))}  # speeds: circumferential force, moments
    # Start: pure rolling about the axis tilted by the free angle, at the quasi-static ball
    # position; then the speeds with the position held (the quasi-static state recomputed for
    # the centrifugal force at the balance's cage speed), then everything together.
    a0 = bearing.contact_angle
    e = np.array([-math.sin(a0), 0.0, math.cos(a0)])
    cage_speed = None
    x = None
    for _ in range(40):
        loads = solve_load_distribution(bearing, axial_force=axial, rpm=rpm, cage_speed=cage_speed)
        position = [float(loads.ball_radius_offset[0]) / MICRON, float(loads.ball_axial_offset[0]) / MICRON,
                    float(loads.displacement[2]) / MICRON]
        if x is None:
            if start_axis == "outer":
                a_o = float(loads.outer_contact_angle[0])
                e = np.array([-math.sin(a_o), 0.0, math.cos(a_o)])
            c0 = np.array([bearing.pitch_radius + position[0] * MICRON, 0.0, position[1] * MICRON])
            p_in = c0 - r * np.array([math.cos(loads.inner_contact_angle[0]), 0, math.sin(loads.inner_contact_angle[0])])
            p_out = c0 + r * np.array([math.cos(loads.outer_contact_angle[0]), 0, math.sin(loads.outer_contact_angle[0])])
            rows = [[c0[0], np.cross(e, p - c0)[1]] for p in (p_in, p_out)]
            w_c0, spin0 = np.linalg.solve(rows, [w_i * p_in[0], 0.0])
            x = np.concatenate([[w_c0 / w_nom], spin0 * e / w_spin, position])
        x[4:] = position
        x, _ = solve(x, np.arange(4))
        w_c = x[0] * w_nom
        if cage_speed is not None and abs(w_c - cage_speed) < 1e-6 * abs(w_c):
            break
        # under-relaxed: near gross sliding the position feedback overshoots
        cage_speed = w_c if cage_speed is None else 0.5 * (cage_speed + w_c)
    x, worst = solve(x, np.arange(7))
    if worst > 1e-8:
        raise RuntimeError(f"no balance at {axial} N: residual {worst:.3g}")
    w_c, w_b, c, inner, outer = contacts(x)
    w_kin = rolling_cage_speed(c, w_b, inner[2], outer[2], w_i)
    slip = 100 * (w_kin - w_c) / (0.5 * (w_kin + w_c))
    return Balance(w_c, w_b, w_kin, slip, inner[3], outer[3], inner[4], outer[4], inner[5],
                   worst)
