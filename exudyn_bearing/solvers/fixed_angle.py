"""The paper's quasi-static load distribution at a fixed contact angle (MODEL.md §4, P4–P6):
the ``fixed-angle`` mode of :func:`exudyn_bearing.solvers.quasistatic.solve_load_distribution`
and the start of its geometric mode."""
from __future__ import annotations

import math

import numpy as np

from contact.hertz import effective_ball_stiffness
from ..bearing import Bearing
from ..errors import QuasiStaticError

__all__ = ["fixed_angle_balance"]


def _radial_hint(axial, radial, alpha, hold_axial) -> str:
    """Why a single-row angular-contact bearing may have no equilibrium: a radial load
    induces an axial force ~1.25 F_r tan(a) that the axial load must hold."""
    if hold_axial or radial <= 0 or axial >= 1.25 * radial * math.tan(alpha):
        return ""
    return (f"; radial={radial:g} N needs about axial >= 1.25 radial tan(a0) = "
            f"{1.25 * radial * math.tan(alpha):.0f} N on a single angular-contact bearing "
            f"(axial={axial:g} N): the radial load's induced axial force pushes the races apart")


def fixed_angle_balance(bearing: Bearing, axial, radial, centrifugal, hold_axial, method, tol, max_iter):
    """The inner race's balance with every ball at the free contact angle a0 (paper P4–P6;
    translations only): ball load K_eff delta^(3/2), delta projected on the fixed contact
    line, half the centrifugal force ``centrifugal`` (N) on that line subtracted (P6).
    Loads in N; ``hold_axial`` keeps the axial displacement at zero; damped Newton to ``tol``
    of the largest load. Returns (displacement (3,) m, inner and outer loads (Z,) N, their
    approaches (Z,) m, iterations, K_eff N/m^1.5, approach along each contact line (Z,) m)."""
    z, alpha = bearing.balls, bearing.contact_angle
    psi = 2.0 * np.pi * np.arange(z) / z
    e = np.stack([np.cos(psi) * math.cos(alpha), np.sin(psi) * math.cos(alpha), np.full(z, math.sin(alpha))], axis=1)
    k_i = bearing.hertz(alpha, "inner", method).stiffness
    k_o = bearing.hertz(alpha, "outer", method).stiffness
    k_eff = float(effective_ball_stiffness(k_i, k_o))
    free = [0, 1] if hold_axial else [0, 1, 2]
    target = np.array([radial, 0.0, axial])
    fc_line = 0.5 * centrifugal * math.cos(alpha)  # P6: 1/2 m r_p w_c² cos(beta)

    def residual(x):
        delta = e @ x
        q = k_eff * np.maximum(delta, 0.0) ** 1.5
        loaded = delta > 0
        force = ((q - fc_line) * loaded) @ e
        dq = 1.5 * k_eff * np.sqrt(np.maximum(delta, 0.0))
        jac = (e * dq[:, None]).T @ e
        return force - target, jac, q, delta

    # start: every ball loaded by the axial force, the radial one as Stribeck's 5 F_r/(Z cos a)
    q0 = (axial / (z * math.sin(alpha)) if axial > 0 else 0.0) + fc_line
    x = np.zeros(3)
    x[2] = 0.0 if hold_axial else (max(q0, 1e-3) / k_eff) ** (2 / 3) / math.sin(alpha)
    if radial > 0:
        x[0] = (5 * radial / (z * math.cos(alpha) * k_eff)) ** (2 / 3) / math.cos(alpha)
    scale = max(axial, radial, 1.0)
    for it in range(max_iter):
        res, jac, q, delta = residual(x)
        if np.linalg.norm(res[free]) < tol * scale:
            break
        try:
            step = np.linalg.solve(jac[np.ix_(free, free)], -res[free])
        except np.linalg.LinAlgError:
            raise QuasiStaticError("fixed-angle solve: no ball in contact (singular Jacobian)"
                                   + _radial_hint(axial, radial, alpha, hold_axial)) from None
        lam, norm0 = 1.0, np.linalg.norm(res[free])
        for _ in range(40):
            trial = x.copy()
            trial[free] += lam * step
            if np.linalg.norm(residual(trial)[0][free]) < norm0 * (1 - 1e-4 * lam):
                break
            lam *= 0.5
        x = trial
    else:
        raise QuasiStaticError(f"fixed-angle Newton–Raphson did not converge in {max_iter} iterations "
                               f"(residual {np.linalg.norm(res[free]):.3g} N)"
                               + _radial_hint(axial, radial, alpha, hold_axial))
    res, jac, q, delta = residual(x)
    q_inner = np.where(q > 0, np.maximum(q - fc_line, 0.0), 0.0)  # below fc_line the ball leaves the inner race
    q_outer = np.where(q > 0, q + fc_line, 0.0)
    return x, q_inner, q_outer, (q_inner / k_i) ** (2 / 3), (q_outer / k_o) ** (2 / 3), it, k_eff, delta
