"""Dry (boundary) Coulomb friction at a ball–race contact, regularized: the cheap
alternative to EHD traction (scene option ``ContactLaw(traction='coulomb')``).

F = μ Q u / √(|u|² + u_r²) along the race-minus-ball slip u (the same convention as
:func:`contact.traction.crook_traction`), and a pivoting moment
M_z = (3π/16) μ Q √(ab) v_s / √(v_s² + u_r²), v_s = ω_s √(ab) — the exact Coulomb
pivoting moment of a Hertz pressure on a circle of radius √(ab) (Johnson, Contact
Mechanics, §7.1), used as the approximation for the ellipse. u_r (m/s) smooths the
stick–slip switch so implicit solvers converge.
"""
from __future__ import annotations

import numpy as np

from .traction import Traction

__all__ = ["coulomb_traction"]


def coulomb_traction(u_x, u_y, omega_s, a, b, load, friction_coefficient, regularization=1e-3) -> Traction:
    """Regularized Coulomb traction and pivoting moment on the ball (module docstring).

    Parameters
    ----------
    u_x, u_y : array_like
        Slip velocity components (race minus ball), m/s.
    omega_s : array_like
        Spin (race minus ball) about the contact normal, rad/s.
    a, b : array_like
        Hertz semi-axes, m.
    load : array_like
        Normal load Q, N.
    friction_coefficient : float
        μ (> 0).
    regularization : float
        u_r, m/s (> 0).
    """
    if not (np.isfinite(friction_coefficient) and friction_coefficient > 0):
        raise ValueError(f"friction_coefficient must be positive, got {friction_coefficient!r}")
    if not (np.isfinite(regularization) and regularization > 0):
        raise ValueError(f"regularization must be positive, got {regularization!r}")
    ux, uy, om, a, b, q = (np.asarray(v, dtype=float) for v in (u_x, u_y, omega_s, a, b, load))
    scale = friction_coefficient * q / np.sqrt(ux * ux + uy * uy + regularization ** 2)
    radius = np.sqrt(a * b)
    v_s = om * radius
    mz = (3 * np.pi / 16) * friction_coefficient * q * radius * v_s / np.sqrt(v_s * v_s + regularization ** 2)
    fx, fy = scale * ux, scale * uy
    heat = fx * ux + fy * uy + mz * om
    return Traction(fx, fy, mz, heat, None)
