"""Quasi-static equilibrium of a rigid shaft on several angular-contact bearings (MODEL.md §4).

A preloaded pair is statically indeterminate: the shaft's 5 degrees of freedom (three
translations, two tilts; the spin about its axis is free) are found from the balance of
the applied load with every bearing's nonlinear load–displacement relation, each bearing
solved with :func:`exudyn_bearing.solvers.quasistatic.solve_load_distribution` (geometric mode:
displaced groove centres, Hertz balls, centrifugal force at the running speed) for the
displacement and tilt its inner race gets from the shaft.

Frames: the shaft axis is the global z axis; the shaft's displacement ``u`` and small
rotation ``(theta_x, theta_y)`` are those of its reference point. Each bearing's outer
race is fixed (housing) at ``position`` with ``rotation`` (third column: that bearing's
axis, along which the inner race is pushed to load it); its inner race sits on the shaft
at ``inner_position`` (relative to the shaft's reference point) with the same rotation.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from contact.thermal_expansion import heated_geometry

from ..bearing import Bearing
from ..jacobian import central_jacobian
from .geometric import rotation as _rotation
from .quasistatic import QuasiStaticError, solve_load_distribution

__all__ = ["ShaftBearing", "ShaftEquilibrium", "solve_shaft"]


@dataclass(frozen=True)
class ShaftBearing:
    """One bearing of a shaft (see the module docstring for the frames).

    Parameters
    ----------
    bearing : Bearing
    position : (3,) float
        Outer-race (bearing) centre, global, m.
    rotation : (3, 3) float
        Bearing frame, global; third column the bearing axis (+ or - z).
    inner_position : (3,) float
        Inner-race centre relative to the shaft's reference point in the unloaded shaft,
        m. An axial offset from ``position`` along the bearing axis is a preload by
        interference (positive: the races are pressed together).
    """

    bearing: Bearing
    position: tuple
    rotation: tuple
    inner_position: tuple

    def __post_init__(self) -> None:
        if not isinstance(self.bearing, Bearing):
            raise ValueError(f"bearing must be a Bearing, got {type(self.bearing).__name__}")
        for name in ("position", "inner_position"):
            value = np.asarray(getattr(self, name), dtype=float)
            if value.shape != (3,) or not np.all(np.isfinite(value)):
                raise ValueError(f"{name} must be 3 finite numbers in m, got {getattr(self, name)!r}")
        rot = np.asarray(self.rotation, dtype=float)
        if rot.shape != (3, 3) or not np.allclose(rot @ rot.T, np.eye(3), atol=1e-9) or np.linalg.det(rot) < 0:
            raise ValueError("rotation must be a proper 3x3 rotation matrix")
        if abs(abs(rot[2, 2]) - 1.0) > 1e-9:
            raise ValueError("rotation: the bearing axis (third column) must be the shaft axis, +z or -z")

    def expanded(self, rise_inner: float, rise_outer: float, rise_balls: float, ring_expansion: float = 11.9e-6,
                 ball_expansion: float = 11.9e-6) -> "ShaftBearing":
        """This bearing at running temperatures (MODEL.md §14f): its geometry grown by the rises
        (K) of its inner ring, outer ring and balls times the expansion coefficients (1/K;
        AISI 52100 by default), its inner race pressed further along its axis by the change of
        the touching distance δ_a (eq. 14.9), its races held at their axial places (the shaft's
        and housing's own axial growth between the bearings is not included)."""
        grown = heated_geometry(self.bearing.ball_diameter, self.bearing.pitch_diameter, self.bearing.contact_angle,
                                self.bearing.inner_conformity, self.bearing.outer_conformity, rise_inner, rise_outer,
                                rise_balls, ring_expansion, ball_expansion)
        axis = np.asarray(self.rotation, dtype=float)[:, 2]
        return replace(self, bearing=self.bearing.grown(grown),
                       inner_position=tuple(np.asarray(self.inner_position, dtype=float)
                                            + grown.axial_interference * axis))

    def inner_race_pose(self, shaft_displacement) -> np.ndarray:
        """(dx, dy, dz, theta_x, theta_y) of the inner race relative to the outer race, in
        the bearing frame, for a shaft displacement (u_x, u_y, u_z, theta_x, theta_y)."""
        x = np.asarray(shaft_displacement, dtype=float)
        rot = np.asarray(self.rotation, dtype=float)
        a = _rotation(x[3], x[4])
        centre = x[:3] + a @ np.asarray(self.inner_position, dtype=float)
        tilt = rot.T @ np.array([x[3], x[4], 0.0])  # small rotation vector in the bearing frame
        return np.concatenate([rot.T @ (centre - np.asarray(self.position, dtype=float)), tilt[:2]])


@dataclass(frozen=True)
class ShaftEquilibrium:
    """Result of :func:`solve_shaft` (SI units, global frame unless stated)."""

    displacement: np.ndarray  #: shaft (u_x, u_y, u_z) at its reference point, m
    tilt: np.ndarray  #: shaft (theta_x, theta_y), rad
    loads: list  #: per bearing, its :class:`LoadDistribution` (bearing frame)
    reaction_force: np.ndarray  #: per bearing, force its balls apply to the shaft, (n, 3), N
    reaction_moment: np.ndarray  #: per bearing, their moment about the bearing centre, (n, 3), N m
    residual: float  #: |force balance| / load scale at the solution, -
    iterations: int


def _bearing_reactions(bearings, x, rpm):
    loads, forces, moments = [], [], []
    for b in bearings:
        rot = np.asarray(b.rotation, dtype=float)
        res = solve_load_distribution(b.bearing, displacement=b.inner_race_pose(x), rpm=rpm)
        loads.append(res)
        forces.append(rot @ res.race_force)
        moments.append(rot @ res.race_moment)
    return loads, np.array(forces), np.array(moments)


def solve_shaft(bearings, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0), rpm: float = 0.0, *,
                tol: float = 1e-8, max_iter: int = 50) -> ShaftEquilibrium:
    """5-DOF quasi-static equilibrium of a rigid shaft on its bearings (MODEL.md §4).

    Parameters
    ----------
    bearings : sequence of ShaftBearing
    force : (3,) float
        Applied force on the shaft at its reference point, global, N.
    moment : (M_x, M_y) float
        Applied moment on the shaft about its reference point, global, N m (e.g. a
        helical gear's axial force times its pitch radius).
    rpm : float
        Shaft speed, rev/min (centrifugal ball forces; outer races fixed).
    tol : float
        Relative tolerance on the force and moment balance.

    Raises
    ------
    ValueError
        Bad input.
    QuasiStaticError
        No equilibrium found (e.g. no bearing can carry the axial load).
    """
    bearings = list(bearings)
    if not bearings or not all(isinstance(b, ShaftBearing) for b in bearings):
        raise ValueError("bearings must be a non-empty sequence of ShaftBearing")
    force = np.asarray(force, dtype=float)
    moment = np.asarray(moment, dtype=float)
    if force.shape != (3,) or not np.all(np.isfinite(force)):
        raise ValueError(f"force must be 3 finite numbers in N, got {force!r}")
    if moment.shape != (2,) or not np.all(np.isfinite(moment)):
        raise ValueError(f"moment must be 2 finite numbers (M_x, M_y) in N m, got {moment!r}")
    if not (math.isfinite(rpm) and rpm >= 0):
        raise ValueError(f"rpm must be finite and >= 0, got {rpm!r}")
    length = max(max(abs(float(b.position[2])) for b in bearings), 1e-3)  # moments -> forces

    def residual(x):
        loads, f, m = _bearing_reactions(bearings, x, rpm)
        arms = np.array([b.position for b in bearings], dtype=float) - x[:3]
        total_f = force + f.sum(axis=0)
        total_m = np.concatenate([moment, [0.0]]) + (m + np.cross(arms, f)).sum(axis=0)
        return np.concatenate([total_f, total_m[:2] / length]), (loads, f, m)

    applied = max(float(np.linalg.norm(force)), float(np.linalg.norm(moment)) / length, 1.0)
    x = np.zeros(5)
    steps = np.array([1e-9, 1e-9, 1e-9, 1e-9 / length, 1e-9 / length])
    res, parts = residual(x)
    for it in range(max_iter):
        norm = float(np.linalg.norm(res))
        # the preload forces can dwarf the applied load: the ball solves' rounding scales with them
        scale = max(applied, float(np.linalg.norm(parts[1], axis=1).max()))
        if norm < tol * scale:
            break
        jac = central_jacobian(lambda xx: residual(xx)[0], x, steps, range(5))
        try:
            step = np.linalg.solve(jac, -res)
        except np.linalg.LinAlgError:
            raise QuasiStaticError("shaft: singular stiffness (the bearings leave a shaft direction unsupported, "
                                   "e.g. no bearing takes axial load in that direction)") from None
        # the ball solves fail far from equilibrium: limit the step to ~20 um / 1 mrad and backtrack
        step *= min(1.0, 2e-5 / max(float(np.max(np.abs(step[:3]))), 1e-300),
                    1e-3 / max(float(np.max(np.abs(step[3:]))), 1e-300))
        lam = 1.0
        for _ in range(30):
            trial = x + lam * step
            try:
                trial_res, trial_parts = residual(trial)
                if np.linalg.norm(trial_res) < norm * (1 - 1e-4 * lam):
                    break
            except QuasiStaticError:
                pass
            lam *= 0.5
        else:
            raise QuasiStaticError(f"shaft: line search failed at iteration {it} (force residual {norm:.3g} N)")
        x, res, parts = trial, trial_res, trial_parts
    else:
        raise QuasiStaticError(f"shaft equilibrium did not converge in {max_iter} iterations "
                               f"(force residual {np.linalg.norm(res):.3g} N)")
    loads, f, m = parts
    return ShaftEquilibrium(x[:3].copy(), x[3:].copy(), loads, f, m, float(np.linalg.norm(res)) / scale, it)
