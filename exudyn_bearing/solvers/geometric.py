"""The geometric mode of the quasi-static load distribution (MODEL.md §4, §2): each ball's
balance in its meridional plane at the inner race's pose, the races' balance over all balls,
and the damped Newton–Raphson that finds the pose (:func:`~exudyn_bearing.solvers.quasistatic.solve_load_distribution`)."""
from __future__ import annotations

import math

import numpy as np

from contact import geometry
from ..bearing import Bearing
from ..errors import QuasiStaticError
from .fixed_angle import fixed_angle_balance

__all__ = ["Geometric", "DEEP_GROOVE_MAX_ANGLE", "rotation", "geometric_start", "geometric_balance"]


def rotation(theta_x: float, theta_y: float) -> np.ndarray:
    """Rotation matrix of the rotation vector (theta_x, theta_y, 0) (Rodrigues)."""
    v = np.array([theta_x, theta_y, 0.0])
    angle = np.linalg.norm(v)
    if angle < 1e-300:
        return np.eye(3)
    k = v / angle
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx


class Geometric:
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
        rot = rotation(x[3], x[4])
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
        rot = rotation(x[3], x[4])
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
        res, con = self.ball_residual(offsets, x)
        for it in range(max_iter):
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
                res, con = self.ball_residual(offsets, x)
                continue
            step = -np.linalg.solve(jac[active], res[active][:, :, None])[:, :, 0]
            length = np.linalg.norm(step, axis=1)
            step *= np.minimum(1.0, max_step / np.maximum(length, 1e-300))[:, None]
            # backtracking: accept the largest of 1, 1/2, 1/4, ... that reduces |residual|
            lam = np.ones(active.sum())
            trial = offsets.copy()
            for _ in range(30):
                trial[active] = offsets[active] + lam[:, None] * step
                res, con = self.ball_residual(trial, x)  # the accepted trial's: the next iteration's
                worse = np.linalg.norm(res[active], axis=1) > norm[active] * (1 - 1e-4 * lam)
                if not np.any(worse):
                    break
                lam = np.where(worse, 0.5 * lam, lam)
            offsets = trial
        raise QuasiStaticError(
            f"ball force balance did not converge in {max_iter} Newton iterations "
            f"(largest residual {np.abs(res).max():.3g} N at ball {int(np.abs(res).max(axis=1).argmax())})")

    def race_forces(self, con, centres):
        """Force and moment (about the bearing centre) the balls apply to the inner race."""
        f, m = self.ball_race_forces(con, centres)
        return f.sum(axis=0), m.sum(axis=0)

    def ball_race_forces(self, con, centres):
        """Each ball's force and moment (about the bearing centre) on the inner race, (Z, 3) each."""
        q, n = con["inner"]["load"], con["inner"]["normal"]
        f = q[:, None] * n
        points = centres + self.b.ball_radius * n
        return f, np.cross(points, f)

    def race_jacobian(self, x, offsets, steps, length):
        """d(race force, moment / ``length``)/d(pose) (5, 5) with every ball kept in its balance
        (MODEL.md §4): the balls' offsets condensed out, do/dx = −(∂R/∂o)⁻¹ ∂R/∂x per ball,
        the partial derivatives by central differences of the contacts at the balanced
        ``offsets`` (pose steps ``steps``, offset steps 1e-9 m), not of re-solved balances."""
        def parts(o, xx):
            res, con = self.ball_residual(o, xx)
            f, m = self.ball_race_forces(con, self.centres(o))
            return res, np.concatenate([f, m[:, :2] / length], axis=1)

        def central(shift, h):
            (res_p, race_p), (res_m, race_m) = (parts(*shift(+h)), parts(*shift(-h)))
            return (res_p - res_m) / (2 * h), (race_p - race_m) / (2 * h)

        z = self.z
        ball_x, race_x = np.zeros((z, 2, 5)), np.zeros((z, 5, 5))
        for k in range(5):
            e = np.eye(5)[k]
            ball_x[:, :, k], race_x[:, :, k] = central(lambda h: (offsets, x + h * e), steps[k])
        ball_o, race_o = np.zeros((z, 2, 2)), np.zeros((z, 5, 2))
        for a in range(2):
            e = np.eye(2)[a]
            ball_o[:, :, a], race_o[:, :, a] = central(lambda h: (offsets + h * e, x), 1e-9)
        # a ball that touches neither race (no centrifugal force) carries nothing and moves nothing
        carried = np.abs(np.linalg.det(ball_o)) > 1e-300
        moved = np.zeros((z, 2, 5))
        moved[carried] = -np.linalg.solve(ball_o[carried], ball_x[carried])
        return race_x.sum(axis=0) + np.einsum("zia,zak->ik", race_o, moved)


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
    t = bearing.groove_centre_distance
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
    a = bearing.groove_centre_distance
    k_i, k_o = (bearing.hertz(0.0, race, hertz_method).stiffness for race in ("inner", "outer"))
    k = (k_i ** (-2.0 / 3.0) + k_o ** (-2.0 / 3.0)) ** -1.5
    return (axial * a * (2.0 * a) ** 1.5 / (bearing.balls * k)) ** 0.25


def _given_pose(value, name: str) -> np.ndarray:
    """The pose (dx, dy, dz, θx, θy) of a given 3 or 5 numbers (m, rad; the tilt 0 if not
    given); a ValueError naming ``name`` otherwise."""
    given = np.asarray(value, dtype=float)
    if given.shape not in ((3,), (5,)) or not np.all(np.isfinite(given)):
        raise ValueError(f"{name} must be 3 or 5 finite numbers, got {value!r}")
    x = np.zeros(5)
    x[:len(given)] = given
    return x


def geometric_start(model, bearing, axial_force, radial_force, hold_axial, hertz_method, max_iter, displacement,
                    start_pose=None):
    """(inner-race pose (dx, dy, dz, θx, θy) to start the geometric balance from, the balls'
    offsets there or None): the prescribed ``displacement``, else the given ``start_pose``, else
    the fixed-angle answer without centrifugal force, else the grooves carrying a radial load
    centred."""
    # start from the fixed-angle answer without centrifugal force
    x = np.zeros(5)
    if start_pose is not None and displacement is None:
        x = _given_pose(start_pose, "start_pose")
        if hold_axial:
            x[2] = 0.0
    elif displacement is not None:
        x = _given_pose(displacement, "displacement")
        offsets, con, _ = model.solve_balls(x)
    elif axial_force > 0 or hold_axial:
        try:
            x[:3] = fixed_angle_balance(bearing, axial_force, radial_force, 0.0, hold_axial, hertz_method, 1e-6, max_iter)[0]
            # a free angle of a rounding (1e-7 rad: a zero-clearance bearing grown uniformly)
            # puts the fixed-angle answer beyond the grooves: no start either
            beyond = bearing.contact_angle <= DEEP_GROOVE_MAX_ANGLE and \
                np.linalg.norm(x[:3]) >= bearing.groove_centre_distance
        except (QuasiStaticError, ZeroDivisionError):
            # fixed angles cannot carry this radial load (or there is no free angle: zero
            # clearance), full grooves may: start centred and let the geometric balance move
            if bearing.contact_angle > DEEP_GROOVE_MAX_ANGLE:
                raise
            beyond = True
        if beyond:
            x[:3] = _centred_radial_start(bearing, radial_force, hertz_method)
            x[2] = 0.0 if hold_axial else x[2] + _axial_shift_estimate(bearing, axial_force, hertz_method)
    elif radial_force > 0:
        # a radial load alone: the full grooves carry it centred, at contact angles near zero,
        # on any bearing (an angular-contact one, from x = 0, took ~30 Newton steps to get there)
        x[:3] = _centred_radial_start(bearing, radial_force, hertz_method)
    return x, (offsets if displacement is not None else None)


def geometric_balance(model, x, axial_force, radial_force, moment, hold_axial, tol, max_iter):
    """Damped Newton–Raphson on the inner race's balance from pose ``x``: (pose, the balls'
    offsets there, iterations); QuasiStaticError if it does not converge in ``max_iter``."""
    bearing = model.b
    free = [0, 1] + ([] if hold_axial else [2]) + ([3, 4] if moment is not None else [])
    target = np.concatenate([[radial_force, 0.0, axial_force], moment if moment is not None else [0.0, 0.0]])
    length = bearing.pitch_radius  # moments scaled to forces
    steps = np.array([1e-9, 1e-9, 1e-9, 1e-9 / length, 1e-9 / length])
    scale = max(axial_force, radial_force, 1.0, *(abs(m) / length for m in (moment or ())))
    state = {"offsets": None, "last": None}  # the balls' warm start; the line search's last (pose, residual)

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
        last = state["last"]
        if last is not None and np.array_equal(last[0], x):  # the accepted trial, solved from the same warm start
            res, offsets, con = last[1]
            state["offsets"] = offsets
        else:
            res, offsets, con = race_residual(x, keep=True)
        history.append(float(np.linalg.norm(res)))
        if history[-1] < tol * scale:
            break
        jac = model.race_jacobian(x, offsets, steps, length)[np.ix_(free, free)]
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
                state["last"] = (trial, race_residual(trial))
                if np.linalg.norm(state["last"][1][0]) < history[-1] * (1 - 1e-4 * lam):
                    break
            except QuasiStaticError:
                state["last"] = None
            lam *= 0.5
        x = trial
    else:
        hint = " (radial load alone: give an axial force or hold_axial=True)" if axial_force == 0 else ""
        raise QuasiStaticError(f"geometric Newton–Raphson did not converge in {max_iter} iterations; "
                               f"force residual {history[-1]:.3g} N{hint}")
    return x, offsets, it
