"""Research (issue 15, session 12; not part of the package): the per-azimuth balance of
azimuth_balance.py with the inner race's position among the unknowns, continued in radial
load from the axial steady state.

    python docs/research/radial_start/continuation.py 400 1800 0 50 100 125 150 175 200 225 250 275 300
"""
import math
import sys
import time

import numpy as np
from scipy.optimize import least_squares

sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
from azimuth_balance import _Balls, MICRON, _E_Z  # noqa: E402

from contact.ballrace import ContactLaw  # noqa: E402
from dataclasses import replace  # noqa: E402


class BallsRace(_Balls):
    """Unknowns: per ball (P, w(3), r_off, z_off), w_c, race displacement (dx, dy, dz) in um."""

    def __init__(self, bearing, lubricant, loads, w_i, w_o, drag, law, land, axial, radial):
        super().__init__(bearing, lubricant, loads, w_i, w_o, drag, law, land)
        self.applied = np.array([radial, 0.0, axial])  # on the inner race, bearing frame
        self.scale = np.concatenate([self.scale, [MICRON] * 3])
        psi = self.psi
        self.e_r = np.stack([np.cos(psi), np.sin(psi), np.zeros(self.z)], axis=1)
        self.e_p = np.stack([-np.sin(psi), np.cos(psi), np.zeros(self.z)], axis=1)

    def set_race(self, d):
        z = self.z
        inner_origin = np.stack([self.e_r @ d, self.e_p @ d, np.full(z, d[2])], axis=1)
        self.origin = np.concatenate([inner_origin, np.zeros((z, 3))])

    def unpack(self, x):
        y = x * self.scale
        per = y[:6 * self.z].reshape(self.z, 6)
        return per[:, 0], per[:, 1:4], self._centres(per[:, 4], per[:, 5]), y[6 * self.z]

    def balance(self, x):
        self.set_race(x[-3:] * MICRON)
        pocket, w_b, c, w_c = self.unpack(x)
        _, f = self._contacts(w_b, c, w_c)
        z = self.z
        force = f.force[:z] + f.force[z:]
        force[:, 0] += self.b.ball_mass * c[:, 0] * w_c ** 2
        force[:, 1] += pocket
        from contact import cage as cage_physics
        if self.density > 0:
            v = np.stack([np.zeros(z), w_c * c[:, 0], np.zeros(z)], axis=1)
            force += cage_physics.drag_forces(c, v, _E_Z, np.zeros(3), self.c_d, self.density, self.b.ball_radius)
        moment = f.moment[:z] + f.moment[z:] - self.inertia * w_c * np.cross(_E_Z, w_b)
        s = self.force_scale
        torque = self.land[0] * (self.land[1] - w_c) - float(np.sum(pocket * c[:, 0]))
        # inner race: minus the inner contact forces on the balls, to the bearing frame, plus the load
        fi = f.force[:z]
        race_part = -(fi[:, :1] * self.e_r + fi[:, 1:2] * self.e_p + fi[:, 2:] * _E_Z)  # (Z, 3)
        return force / s, moment / (s * self.b.ball_radius), torque / (s * self.b.pitch_radius), race_part / s

    def residual(self, x):
        force, moment, torque, race = self.balance(x)
        return np.concatenate([np.concatenate([force, moment], axis=1).ravel(), [torque],
                               race.sum(axis=0) + self.applied / self.force_scale])

    def jacobian(self, x, step=1e-6):
        z = self.z
        n = 6 * z + 4
        f0, m0, t0, r0 = self.balance(x)
        jac = np.zeros((n, n))
        rows = np.arange(6 * z).reshape(z, 6)
        race_rows = np.arange(6 * z + 1, n)
        for k in range(6):
            xk = x.copy()
            xk[k:6 * z:6] += step
            f, m, t, r = self.balance(xk)
            d = np.concatenate([f - f0, m - m0], axis=1) / step
            for i in range(6):
                jac[rows[:, i], rows[:, k]] = d[:, i]
            jac[race_rows[:, None], rows[:, k][None, :]] = ((r - r0) / step).T
        base = self.residual(x)
        for col in range(6 * z, n):
            xc = x.copy()
            xc[col] += step
            jac[:, col] = (self.residual(xc) - base) / step
        jac[6 * z] = self._torque_row_full(x)
        return jac

    def _torque_row_full(self, x):
        pocket, _, c, _ = self.unpack(x)
        z = self.z
        row = np.zeros(x.size)
        norm = self.force_scale * self.b.pitch_radius
        row[0:6 * z:6] = -c[:, 0] * self.force_scale / norm
        row[4:6 * z:6] = -pocket * MICRON / norm
        row[6 * z] = -self.land[0] * self.scale[6 * z] / norm
        return row

    def bounds(self):
        lo, hi = super().bounds()
        return np.concatenate([lo, [-np.inf] * 3]), np.concatenate([hi, [np.inf] * 3])


def solve(bearing, lubricant, drag, axial, radial, rpm, x0=None, steady=None, law=ContactLaw()):
    from exudyn_bearing import solve_load_distribution
    w_i = rpm * math.pi / 30
    loads = solve_load_distribution(bearing, axial=axial, radial=radial, rpm=rpm,
                                    cage_speed=steady.cage_speed if steady else None)
    law = replace(law, fast_quadrature=False, quadrature_order=16)
    balls = BallsRace(bearing, lubricant, loads, w_i, 0.0, drag, law, (0.0, 0.0), axial, radial)
    if x0 is None:
        z = bearing.balls
        x0 = np.zeros(6 * z + 4)
        per = x0[:6 * z].reshape(z, 6)
        per[:, 1:4] = np.asarray(steady.ball_omega) / balls.w_scale
        per[:, 4] = (steady.ball_orbit_radius - bearing.pitch_radius) / MICRON
        per[:, 5] = steady.ball_axial_position / MICRON
        x0[6 * z] = steady.cage_speed / balls.scale[6 * z]
        x0[-3:] = np.array([0.0, 0.0, steady.inner_race_shift]) / MICRON
    lo, hi = balls.bounds()
    sol = least_squares(balls.residual, np.clip(x0, lo, hi), jac=balls.jacobian, method="trf", bounds=(lo, hi),
                        xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=200)
    worst = float(np.max(np.abs(sol.fun)))
    return sol.x, worst, balls


if __name__ == "__main__":
    from exudyn_bearing import REFERENCE_BEARING as B, REFERENCE_LUBRICANT as L, REFERENCE_DRAG as D, steady_state
    axial, rpm = float(sys.argv[1]), float(sys.argv[2])
    st = steady_state(B, L, axial=axial, rpm=rpm, drag=D)
    print("steady", round(st.cage_speed, 3), "shift um", round(st.inner_race_shift * 1e6, 3))
    x = None
    for radial in [float(v) for v in sys.argv[3:]]:
        t = time.perf_counter()
        x_new, worst, balls = solve(B, L, D, axial, radial, rpm, x0=x, steady=st)
        _, _, _, w_c = balls.unpack(x_new)
        print(f"radial {radial}: worst {worst:.2g}, w_c {w_c:.3f}, race um {np.round(x_new[-3:], 3)}, {time.perf_counter()-t:.1f} s",
              flush=True)
        if worst < 1e-5:
            x = x_new
