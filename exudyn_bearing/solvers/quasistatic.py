"""Quasi-static load distribution of an angular-contact ball bearing (MODEL.md §4, P4–P6).

Two modes:

``geometric`` (default)
    Rigid rings, Hertz balls. Each ball centre is free in its meridional plane (its
    azimuth is held by the cage, which takes any circumferential force); the inner and
    outer contact angles follow from the displaced groove-centre circles (torus
    geometry of MODEL.md §2), and the full centrifugal force m r_c w_c² enters each
    ball's own force balance. The inner race moves by (dx, dy, dz) and, if a tilting
    moment is given, tilts by (theta_x, theta_y).
``fixed-angle``
    The paper's P4–P6: every ball keeps the free contact angle a0, the ball load is
    K_eff delta^(3/2) with delta projected on the fixed contact line, and half the
    centrifugal force, projected on that line, is subtracted in the inner-race balance
    (:mod:`exudyn_bearing.solvers.fixed_angle`).

Frames: bearing axis z, the radial force acts along +x on the inner race, the axial
force along +z (towards the side that loads the inner contacts), ball j sits at
azimuth psi_j = 2 pi j / Z (ball 0 at +x, the most loaded under radial load). The
outer race is fixed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, asdict

import numpy as np

from contact import geometry
from ..bearing import Bearing
from ..bearingfile import as_setup
from ..errors import QuasiStaticError
from ..jacobian.differences import central_jacobian
from ..renamed import accepts_old_names
from ..results.records import units_of
from ..setup import FROM_SETUP, BearingSetup, refuse_surface
from .fixed_angle import fixed_angle_balance

__all__ = ["LoadDistribution", "QuasiStaticError", "solve_load_distribution"]




@dataclass(frozen=True)
class LoadDistribution:
    """Per-ball result of :func:`solve_load_distribution` (arrays of length Z, SI units)."""

    mode: str  #: 'geometric' or 'fixed-angle'
    azimuth: np.ndarray  #: ball position angles psi_j, rad
    inner_load: np.ndarray  #: Q_i, N
    outer_load: np.ndarray  #: Q_o, N
    inner_contact_angle: np.ndarray  #: rad, positive as the free angle
    outer_contact_angle: np.ndarray  #: rad
    inner_deflection: np.ndarray  #: Hertz approach delta_i, m (negative: gap)
    outer_deflection: np.ndarray  #: m
    ball_radius_offset: np.ndarray  #: orbit radius of the ball centre minus r_p, m
    ball_axial_offset: np.ndarray  #: axial ball-centre position, m
    displacement: np.ndarray  #: inner-race (dx, dy, dz), m
    tilt: np.ndarray  #: inner-race (theta_x, theta_y), rad
    reaction_moment: np.ndarray  #: (M_x, M_y) the shaft must supply when tilt is held, N m
    centrifugal_force: float  #: m r_p w_c² per ball, N (an array when the cage speed is per ball)
    cage_speed: float  #: cage speed used for it, rad/s (or per ball)
    cage_force: np.ndarray  #: circumferential force the cage puts on each ball, N (along +psi)
    ball_residual: np.ndarray  #: |force balance of each ball| / (max contact load), -
    iterations: int
    #: force the balls apply to the inner race, (F_x, F_y, F_z) in N, bearing frame
    race_force: np.ndarray = None
    #: their moment about the bearing centre, (M_x, M_y, M_z) in N m, bearing frame
    race_moment: np.ndarray = None

    @property
    def max_load(self) -> float:
        """Largest contact load in the bearing, N."""
        return float(max(self.inner_load.max(), self.outer_load.max()))

    def to_dict(self) -> dict:
        """JSON-ready dictionary (the CLI's ``loads --json``): this class's field names and SI
        values (angles in rad), the angles also in degrees (``*_deg``), the inner race's axial
        and radial displacement, and ``units``, the unit of every key."""
        out = {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in asdict(self).items()}
        for name in ("azimuth", "inner_contact_angle", "outer_contact_angle"):
            out[f"{name}_deg"] = np.degrees(getattr(self, name)).tolist()
        dx, dy, dz = self.displacement
        out["axial_displacement"], out["radial_displacement"] = float(dz), float(math.hypot(dx, dy))
        out["units"] = units_of(out)
        return out


def _rotation(theta_x: float, theta_y: float) -> np.ndarray:
    """Rotation matrix of the rotation vector (theta_x, theta_y, 0) (Rodrigues)."""
    v = np.array([theta_x, theta_y, 0.0])
    angle = np.linalg.norm(v)
    if angle < 1e-300:
        return np.eye(3)
    k = v / angle
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx


def _check_load(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating)) or not math.isfinite(value):
        raise ValueError(f"{name} must be a finite number, got {value!r}")
    if value < 0:
        raise ValueError(f"{name} must be non-negative, got {value!r}: it acts along the bearing axis (+z of the "
                         "bearing frame); for a load the other way mount the bearing the other way round (in a "
                         "scene: rotationMatrix=np.diag([1, -1, -1]))" if name == "axial_force" else
                         f"{name} must be non-negative, got {value!r} (reverse the frame instead)")
    return float(value)


class _Geometric:
    """Ball and race force balances of the geometric mode for one operating point."""

    def __init__(self, bearing: Bearing, centrifugal: float, hertz_method: str):
        self.b = bearing
        self.z = bearing.balls
        self.psi = 2.0 * np.pi * np.arange(self.z) / self.z
        self.e_r = np.stack([np.cos(self.psi), np.sin(self.psi), np.zeros(self.z)], axis=1)
        self.e_z = np.array([0.0, 0.0, 1.0])
        (self.ri, self.zi), (self.ro, self.zo) = bearing.groove_centres()
        self.ti = (bearing.inner_conformity - 0.5) * bearing.ball_diameter
        self.to = (bearing.outer_conformity - 0.5) * bearing.ball_diameter
        self.fc = centrifugal  # at the pitch radius, N
        # the ball orbits at r_p + offset: m w_c² per metre of orbit radius
        self.fc_rate = centrifugal / bearing.pitch_radius
        self.method = hertz_method

    def centres(self, offsets: np.ndarray) -> np.ndarray:
        return (self.b.pitch_radius + offsets[:, :1]) * self.e_r + offsets[:, 1:2] * self.e_z

    def contacts(self, offsets, x):
        """Loads, normals (global), deflections, angles, stiffness-matrix factors."""
        c = self.centres(offsets)
        rot = _rotation(x[3], x[4])
        inner = geometry.groove_contact((c - x[:3]) @ rot, self.ri, self.zi, self.ti, "inner")
        outer = geometry.groove_contact(c, self.ro, self.zo, self.to, "outer")
        out = {}
        for name, con, n in (("inner", inner, inner.normal @ rot.T), ("outer", outer, outer.normal)):
            k = self.b.hertz(con.contact_angle, name, self.method).stiffness
            pen = np.maximum(con.penetration, 0.0)
            load = k * pen ** 1.5
            out[name] = dict(load=load, normal=n, deflection=con.penetration, angle=con.contact_angle,
                             dload=1.5 * k * np.sqrt(pen), distance=con.distance)
        return out, c

    def ball_residual(self, offsets, x):
        con, _ = self.contacts(offsets, x)
        force = (np.reshape(self.fc_rate, (-1, 1)) * (self.b.pitch_radius + offsets[:, :1])) * self.e_r
        for side in con.values():
            force = force - side["load"][:, None] * side["normal"]
        return np.stack([np.einsum("ij,ij->i", force, self.e_r), force[:, 2]], axis=1), con

    def ball_jacobian(self, con):
        """d(residual)/d(offsets), shape (Z, 2, 2): minus the contact stiffness matrices
        S = Q' n nT + Q/|d| (I - n nT), projected on (e_r, e_z)."""
        basis = np.stack([self.e_r, np.broadcast_to(self.e_z, self.e_r.shape)], axis=2)  # (Z,3,2)
        jac = np.zeros((self.z, 2, 2))
        for side in con.values():
            n = side["normal"]
            nn = n[:, :, None] * n[:, None, :]
            s = side["dload"][:, None, None] * nn + (side["load"] / side["distance"])[:, None, None] * (np.eye(3) - nn)
            jac -= np.einsum("zia,zij,zjb->zab", basis, s, basis)
        jac[:, 0, 0] += self.fc_rate  # the centrifugal force grows with the orbit radius (scalar or per ball)
        return jac

    def initial_offsets(self, x) -> np.ndarray:
        """Balls on the line between the groove centres, deflections split by stiffness
        (exact without centrifugal force up to the angle dependence of K); balls only
        touching the outer race are pushed onto it by the centrifugal force."""
        rot = _rotation(x[3], x[4])
        offsets = np.zeros((self.z, 2))
        g_i = (self.ri * self.e_r + self.zi * self.e_z) @ rot.T + x[:3]
        g_o = self.ro * self.e_r + self.zo * self.e_z
        sep_vec = g_i - g_o
        sep = np.linalg.norm(sep_vec, axis=1)
        u = sep_vec / sep[:, None]
        total = sep - (self.ti + self.to)
        ki = self.b.hertz(self.b.contact_angle, "inner", self.method).stiffness
        ko = self.b.hertz(self.b.contact_angle, "outer", self.method).stiffness
        share_o = 1.0 / (1.0 + (ko / ki) ** (2.0 / 3.0))  # delta_o / delta_total at equal loads
        c = g_o + (self.to + np.where(total > 0, total * share_o, 0.5 * total))[:, None] * u
        if np.any(self.fc > 0):
            ko_r = self.b.hertz(0.0, "outer", self.method).stiffness
            c_out = g_o + (self.to + (np.reshape(self.fc, (-1, 1)) / ko_r) ** (2.0 / 3.0)) * self.e_r
            # where the centrifugal position clears the inner groove the ball rides on the
            # outer race alone; starting it between both races at ~zero load (total ~ 0, a
            # race just touching) leaves Newton with a near-singular stiffness
            clear = np.linalg.norm(c_out - g_i, axis=1) >= self.ti
            c = np.where((clear | (total <= 0))[:, None], c_out, c)
        offsets[:, 0] = np.einsum("ij,ij->i", c, self.e_r) - self.b.pitch_radius
        offsets[:, 1] = c[:, 2]
        return offsets

    def solve_balls(self, x, offsets=None, tol=1e-10, max_iter=60):
        """Newton on each ball's 2-D force balance (vectorized over balls). ``tol`` is
        relative to the ball's largest load; rounding of the ball position (1e-17 m times
        a contact stiffness of ~4e7 N/m) puts the floor near 1e-11."""
        if offsets is None:
            offsets = self.initial_offsets(x)
        offsets = offsets.copy()
        max_step = 0.25 * min(self.ti, self.to)
        for it in range(max_iter):
            res, con = self.ball_residual(offsets, x)
            scale = np.maximum(np.maximum(con["inner"]["load"], con["outer"]["load"]), self.fc) + 1e-300
            norm = np.linalg.norm(res, axis=1)
            # all balls share the rounding floor of the heaviest one: positions ~0.1 m round
            # at ~2e-17 m, times a contact stiffness dQ/d(delta) of up to ~1e8 N/m that is
            # ~2e-9 N however lightly the bearing is loaded
            active = norm > tol * max(float(scale.max()), 100.0)
            if not np.any(active):
                return offsets, con, it
            jac = self.ball_jacobian(con)
            det = np.linalg.det(jac)
            singular = np.abs(det) < 1e-300
            # A ball touching neither race with no centrifugal force carries nothing:
            # any position between the grooves is an equilibrium.
            loose = singular & (self.fc == 0)
            active &= ~loose
            if not np.any(active):
                return offsets, con, it
            if np.any(singular & active):
                offsets[singular & active] = self.initial_offsets(x)[singular & active] + np.array([1e-9, 0.0])
                continue
            step = -np.linalg.solve(jac[active], res[active][:, :, None])[:, :, 0]
            length = np.linalg.norm(step, axis=1)
            step *= np.minimum(1.0, max_step / np.maximum(length, 1e-300))[:, None]
            # backtracking: accept the largest of 1, 1/2, 1/4, ... that reduces |residual|
            lam = np.ones(active.sum())
            trial = offsets.copy()
            for _ in range(30):
                trial[active] = offsets[active] + lam[:, None] * step
                new_norm = np.linalg.norm(self.ball_residual(trial, x)[0][active], axis=1)
                worse = new_norm > norm[active] * (1 - 1e-4 * lam)
                if not np.any(worse):
                    break
                lam = np.where(worse, 0.5 * lam, lam)
            offsets = trial
        res, con = self.ball_residual(offsets, x)
        raise QuasiStaticError(
            f"ball force balance did not converge in {max_iter} Newton iterations "
            f"(largest residual {np.abs(res).max():.3g} N at ball {int(np.abs(res).max(axis=1).argmax())})")

    def race_forces(self, con, centres):
        """Force and moment (about the bearing centre) the balls apply to the inner race."""
        q, n = con["inner"]["load"], con["inner"]["normal"]
        f = q[:, None] * n
        points = centres + self.b.ball_radius * n
        return f.sum(axis=0), np.cross(points, f).sum(axis=0)


#: Free contact angles up to this (rad) are deep-groove bearings: both shoulders are high, so
#: a radial load alone is carried with the grooves centred (contact angles near zero). Above
#: it the bearing is an angular-contact one, whose low shoulder the full-groove model does
#: not have: its fixed-angle start then fails under a radial load, and the geometric balance
#: carries the load at centred grooves, as for a radial load alone.
DEEP_GROOVE_MAX_ANGLE = math.radians(20.0)


def _centred_radial_start(bearing: Bearing, radial: float, hertz_method: str) -> np.ndarray:
    """Inner-race start (dx, dy, dz) for a radial load alone (MODEL.md §4): groove centres
    aligned axially (full toroidal grooves carry it at contact angles near zero, as a
    deep-groove bearing does) and the race moved radially by the clearance plus the
    deflections of Stribeck's most heavily loaded ball, Q = 5 F_r / Z."""
    (r_i, z_i), (r_o, z_o) = bearing.groove_centres()
    t = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * bearing.ball_diameter
    clearance = t - (r_i - r_o)  # radial play at aligned grooves, m
    q = 5.0 * radial / bearing.balls
    deflection = sum((q / bearing.hertz(0.0, race, hertz_method).stiffness) ** (2.0 / 3.0)
                     for race in ("inner", "outer"))
    if radial == 0:
        return np.array([0.0, 0.0, z_o - z_i])
    return np.array([max(clearance, 0.0) + deflection, 0.0, z_o - z_i])


def _axial_shift_estimate(bearing: Bearing, axial: float, hertz_method: str) -> float:
    """Axial inner-race shift from the centred grooves that carries ``axial`` on a bearing
    without radial play, m: with A = (f_i + f_o - 1) D the groove-centre distance, a shift s
    gives sin a ~ s/A and a deflection ~ s²/(2A); Q = F_a/(Z sin a) = K (s²/2A)^1.5 gives
    s = (F_a A (2A)^1.5 / (Z K))^(1/4), K the series Hertz stiffness at a = 0."""
    if axial <= 0:
        return 0.0
    a = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * bearing.ball_diameter
    k_i, k_o = (bearing.hertz(0.0, race, hertz_method).stiffness for race in ("inner", "outer"))
    k = (k_i ** (-2.0 / 3.0) + k_o ** (-2.0 / 3.0)) ** -1.5
    return (axial * a * (2.0 * a) ** 1.5 / (bearing.balls * k)) ** 0.25


@accepts_old_names
def solve_load_distribution(bearing: Bearing | BearingSetup | str, axial_force: float = 0.0, radial_force: float = 0.0,
                            rpm: float = 0.0, *, moment: tuple[float, float] | None = None, mode: str = "geometric",
                            hold_axial: bool = False, hertz_method: str = FROM_SETUP, tol: float = 1e-10,
                            max_iter: int = 60, outer_rpm: float = 0.0,
                            displacement=None, cage_speed=None) -> LoadDistribution:
    """Quasi-static load distribution (MODEL.md §4).

    Parameters
    ----------
    bearing : Bearing, BearingSetup or path
        A setup's contact law gives the Hertz method unless ``hertz_method`` is passed; its
        lubricant, drag and cage do not enter a quasi-static balance (MODEL.md §4), its
        defects and waviness are refused (a perfect bearing's distribution).
    axial_force, radial_force : float
        Applied forces on the inner race, N (axial along +z, radial along +x), >= 0.
    rpm : float
        Inner-race speed, rev/min (outer race fixed); sets the cage speed and the
        centrifugal force m r_p w_c² per ball. 0: no centrifugal force.
    moment : (M_x, M_y), optional
        Applied tilting moment on the inner race about the bearing centre, N m. If
        given, the inner race tilts until it is balanced; otherwise its tilt is held at
        zero and the moment the shaft must supply is returned as ``reaction_moment``.
    mode : {'geometric', 'fixed-angle'}
        See the module docstring.
    hold_axial : bool
        Hold the axial inner-race displacement at zero (the axial force becomes a
        reaction), e.g. pure radial load on a single angular-contact bearing.
    hertz_method : {'fit', 'exact'}
        Brewe–Hamrock fits or exact elliptic integrals for the Hertz stiffness (default:
        the setup's contact law's, 'fit' for a plain Bearing).
    tol : float
        Relative force-balance tolerance of the Newton–Raphson iterations.
    outer_rpm : float
        Outer-race speed, rev/min (enters the cage speed only).
    displacement : (dx, dy, dz[, theta_x, theta_y]), optional
        Prescribe the inner-race displacement (m) and tilt (rad) instead of balancing
        the applied loads (geometric mode): only the balls are solved; the loads are
        then ignored.
    cage_speed : float or array of Z floats, optional
        Cage (ball orbital) speed for the centrifugal force, rad/s, e.g. the one a dynamic
        run measured, or each ball's own orbital speed (geometric mode); default: the
        nominal pure-rolling speed at ``rpm`` (P19, nominal contact angle).

    Raises
    ------
    ValueError
        Bad input (negative or NaN load, unknown mode).
    QuasiStaticError
        Newton–Raphson did not converge (e.g. a radial load with no axial force on a
        bearing that cannot carry it).
    """
    if not isinstance(bearing, Bearing):  # (the builder's hot loop passes a Bearing)
        setup = as_setup(bearing)
        refuse_surface(setup, "solve_load_distribution", "simulate or vibration")
        bearing = setup.bearing
        hertz_method = setup.contact_law.hertz_method if hertz_method is FROM_SETUP else hertz_method
    if hertz_method is FROM_SETUP:
        hertz_method = "fit"
    axial_force, radial_force = _check_load("axial_force", axial_force), _check_load("radial_force", radial_force)
    rpm = _check_load("rpm", rpm)
    if not math.isfinite(outer_rpm):
        raise ValueError(f"outer_rpm must be finite, got {outer_rpm!r}")
    if moment is not None:
        moment = tuple(float(m) for m in moment)
        if len(moment) != 2 or not all(math.isfinite(m) for m in moment):
            raise ValueError(f"moment must be two finite numbers (M_x, M_y) in N m, got {moment!r}")
    if mode not in ("geometric", "fixed-angle"):
        raise ValueError(f"mode must be 'geometric' or 'fixed-angle', got {mode!r}")
    if axial_force == 0 and radial_force == 0 and moment is None and not hold_axial and displacement is None:
        raise ValueError("axial_force, radial_force: at least one load is needed for a load distribution")
    if axial_force == 0 and radial_force > 0 and not hold_axial and mode == "fixed-angle":
        raise ValueError("axial: with fixed contact angles an angular-contact bearing has no equilibrium under "
                         "radial load alone; give an axial force or hold_axial=True")
    if cage_speed is None:
        cage = bearing.cage_speed(rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0)
    elif isinstance(cage_speed, (int, float, np.floating)) and math.isfinite(cage_speed):
        cage = float(cage_speed)
    elif (mode == "geometric" and np.ndim(cage_speed) == 1 and len(cage_speed) == bearing.balls
          and np.all(np.isfinite(np.asarray(cage_speed, dtype=float)))):
        cage = np.asarray(cage_speed, dtype=float)  # per ball (geometric mode)
    else:
        raise ValueError(f"cage_speed must be a finite angular speed in rad/s (or, geometric mode, one per ball), "
                         f"got {cage_speed!r}")
    centrifugal = bearing.ball_mass * bearing.pitch_radius * cage ** 2
    z = bearing.balls
    psi = 2.0 * np.pi * np.arange(z) / z

    if mode == "fixed-angle":
        if moment is not None:
            raise ValueError("moment: the fixed-angle mode (paper P4) has no tilt; use mode='geometric'")
        x, qi, qo, di, do, it, k_eff, delta = fixed_angle_balance(bearing, axial_force, radial_force, centrifugal, hold_axial,
                                                           hertz_method, tol, max_iter)
        alpha = np.full(z, bearing.contact_angle)
        zeros = np.zeros(z)
        line = np.stack([np.cos(psi) * np.cos(alpha), np.sin(psi) * np.cos(alpha), np.sin(alpha)], axis=1)
        # P6's inner-race balance: every loaded ball pushes back with Q - 1/2 F_c cos(a0), which
        # may be negative for light balls (the reported inner loads are clipped at 0)
        balance = np.where(qo > 0, qo - centrifugal * math.cos(bearing.contact_angle), 0.0)
        force = -(balance[:, None] * line)
        points = bearing.pitch_radius * np.stack([np.cos(psi), np.sin(psi), zeros], axis=1)
        return LoadDistribution("fixed-angle", psi, qi, qo, alpha, alpha.copy(), np.where(qi > 0, di, delta),
                                np.where(qo > 0, do, delta), zeros, zeros.copy(), x, np.zeros(2), np.zeros(2),
                                centrifugal, cage, zeros.copy(), zeros.copy(), it, force.sum(axis=0),
                                np.cross(points, force).sum(axis=0))

    model = _Geometric(bearing, centrifugal, hertz_method)
    # start from the fixed-angle answer without centrifugal force
    x = np.zeros(5)
    if displacement is not None:
        given = np.asarray(displacement, dtype=float)
        if given.shape not in ((3,), (5,)) or not np.all(np.isfinite(given)):
            raise ValueError(f"displacement must be 3 or 5 finite numbers, got {displacement!r}")
        x[:len(given)] = given
        max_iter = 0
        offsets, con, _ = model.solve_balls(x)
    elif axial_force > 0 or hold_axial:
        try:
            x[:3] = fixed_angle_balance(bearing, axial_force, radial_force, 0.0, hold_axial, hertz_method, 1e-6, max_iter)[0]
        except (QuasiStaticError, ZeroDivisionError):
            # fixed angles cannot carry this radial load (or there is no free angle: zero
            # clearance), full grooves may: start centred and let the geometric balance move
            if bearing.contact_angle > DEEP_GROOVE_MAX_ANGLE:
                raise
            x[:3] = _centred_radial_start(bearing, radial_force, hertz_method)
            x[2] = 0.0 if hold_axial else x[2] + _axial_shift_estimate(bearing, axial_force, hertz_method)
    elif radial_force > 0:
        # a radial load alone: the full grooves carry it centred, at contact angles near zero,
        # on any bearing (an angular-contact one, from x = 0, took ~30 Newton steps to get there)
        x[:3] = _centred_radial_start(bearing, radial_force, hertz_method)
    free = [0, 1] + ([] if hold_axial else [2]) + ([3, 4] if moment is not None else [])
    target = np.concatenate([[radial_force, 0.0, axial_force], moment if moment is not None else [0.0, 0.0]])
    length = bearing.pitch_radius  # moments scaled to forces
    steps = np.array([1e-9, 1e-9, 1e-9, 1e-9 / length, 1e-9 / length])
    scale = max(axial_force, radial_force, 1.0, *(abs(m) / length for m in (moment or ())))
    state = {"offsets": None}

    def race_residual(xx, keep=False):
        offsets, con, _ = model.solve_balls(xx, state["offsets"])
        if keep:
            state["offsets"] = offsets
        force, mom = model.race_forces(con, model.centres(offsets))
        r = np.concatenate([force, mom[:2] / length]) + target * np.array([1, 1, 1, 1 / length, 1 / length])
        return r[free], offsets, con

    history = [0.0]
    it = 0
    for it in range(max_iter):
        res, offsets, con = race_residual(x, keep=True)
        history.append(float(np.linalg.norm(res)))
        if history[-1] < tol * scale:
            break
        jac = central_jacobian(lambda xx: race_residual(xx)[0], x, steps, free)
        try:
            step = np.linalg.solve(jac, -res)
        except np.linalg.LinAlgError:
            raise QuasiStaticError("geometric solve: singular race stiffness (no ball carries load in some "
                                   "direction; add axial load or hold_axial=True)") from None
        lam = 1.0
        for _ in range(40):
            trial = x.copy()
            trial[free] += lam * step
            try:
                if np.linalg.norm(race_residual(trial)[0]) < history[-1] * (1 - 1e-4 * lam):
                    break
            except QuasiStaticError:
                pass
            lam *= 0.5
        x = trial
    else:
        if max_iter == 0:  # prescribed displacement: nothing to balance
            return _geometric_result(model, psi, offsets, x, moment, centrifugal, cage, 0)
        hint = " (radial load alone: give an axial force or hold_axial=True)" if axial_force == 0 else ""
        raise QuasiStaticError(f"geometric Newton–Raphson did not converge in {max_iter} iterations; "
                               f"force residual {history[-1]:.3g} N{hint}")
    return _geometric_result(model, psi, offsets, x, moment, centrifugal, cage, it)


def _geometric_result(model, psi, offsets, x, moment, centrifugal, cage, it):
    z = len(psi)
    res, con = model.ball_residual(offsets, x)
    force, mom = model.race_forces(con, model.centres(offsets))
    reaction = np.zeros(2) if moment is not None else -mom[:2]
    # a radially displaced inner race tilts its meridional planes: the inner normal gets a
    # small circumferential part, which the cage (holding the azimuth) takes
    e_psi = np.stack([-np.sin(psi), np.cos(psi), np.zeros(z)], axis=1)
    cage_force = np.einsum("ij,ij->i", con["inner"]["load"][:, None] * con["inner"]["normal"], e_psi)
    q_scale = np.maximum(np.maximum(con["inner"]["load"], con["outer"]["load"]), 1e-300)
    return LoadDistribution(
        "geometric", psi, con["inner"]["load"], con["outer"]["load"], con["inner"]["angle"], con["outer"]["angle"],
        con["inner"]["deflection"], con["outer"]["deflection"], offsets[:, 0].copy(), offsets[:, 1].copy(),
        x[:3].copy(), x[3:].copy(), reaction, centrifugal, cage, cage_force, np.linalg.norm(res, axis=1) / q_scale, it,
        force, mom)
