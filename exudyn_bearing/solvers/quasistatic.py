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

from ..bearing import Bearing
from ..bearingfile import as_setup
from ..errors import QuasiStaticError
from ..renamed import accepts_old_names
from ..results.records import units_of
from ..setup import FROM_SETUP, BearingSetup, refuse_surface, refuse_thermal
from .fixed_angle import fixed_angle_balance
from .geometric import Geometric, geometric_balance, geometric_start

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


def _check_load(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating)) or not math.isfinite(value):
        raise ValueError(f"{name} must be a finite number, got {value!r}")
    if value < 0:
        raise ValueError(f"{name} must be non-negative, got {value!r}: it acts along the bearing axis (+z of the "
                         "bearing frame); for a load the other way mount the bearing the other way round (in a "
                         "scene: rotationMatrix=np.diag([1, -1, -1]))" if name == "axial_force" else
                         f"{name} must be non-negative, got {value!r} (reverse the frame instead)")
    return float(value)


@accepts_old_names
def solve_load_distribution(bearing: Bearing | BearingSetup | str, axial_force: float = 0.0, radial_force: float = 0.0,
                            rpm: float = 0.0, *, moment: tuple[float, float] | None = None, mode: str = "geometric",
                            hold_axial: bool = False, hertz_method: str = FROM_SETUP, tol: float = 1e-10,
                            max_iter: int = 60, outer_rpm: float = 0.0,
                            displacement=None, cage_speed=None, start_pose=None) -> LoadDistribution:
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
    start_pose : (dx, dy, dz[, theta_x, theta_y]), optional
        Inner-race pose (m, rad) to start the balance from (geometric mode, not with
        ``displacement``), e.g. the solution at a nearby load or cage speed; its tilt only
        where a ``moment`` frees it, its axial part not with ``hold_axial``; default: the
        fixed-angle answer (§4).

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
        refuse_thermal(setup, "solve_load_distribution (no temperatures: grow the bearing with Bearing.expanded)")
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
    if start_pose is not None and (mode != "geometric" or displacement is not None):
        raise ValueError("start_pose starts the geometric balance; "
                         + ("the fixed-angle mode has no pose to start from" if mode != "geometric" else
                            "with a prescribed displacement there is nothing to balance"))
    if start_pose is not None and moment is None and len(start_pose) == 5:
        start_pose = (*start_pose[:3], 0.0, 0.0)  # without a moment the tilt is held at zero
    cage = _cage_speed(bearing, cage_speed, rpm, outer_rpm, mode)
    centrifugal = bearing.ball_mass * bearing.pitch_radius * cage ** 2
    z = bearing.balls
    psi = 2.0 * np.pi * np.arange(z) / z

    if mode == "fixed-angle":
        return _fixed_angle_distribution(bearing, axial_force, radial_force, centrifugal, cage, hold_axial, moment,
                                         hertz_method, tol, max_iter)

    model = Geometric(bearing, centrifugal, hertz_method)
    x, offsets = geometric_start(model, bearing, axial_force, radial_force, hold_axial, hertz_method, max_iter,
                                  displacement, start_pose)
    if displacement is not None:  # prescribed displacement: nothing to balance
        return _geometric_result(model, psi, offsets, x, moment, centrifugal, cage, 0)
    x, offsets, it = geometric_balance(model, x, axial_force, radial_force, moment, hold_axial, tol, max_iter)
    return _geometric_result(model, psi, offsets, x, moment, centrifugal, cage, it)


def _cage_speed(bearing, cage_speed, rpm, outer_rpm, mode):
    """The balls' orbital speed for the centrifugal force, rad/s: ``cage_speed`` checked (a
    number, or one per ball in geometric mode), else the nominal one at ``rpm``/``outer_rpm``."""
    if cage_speed is None:
        return bearing.cage_speed(rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0)
    elif isinstance(cage_speed, (int, float, np.floating)) and math.isfinite(cage_speed):
        return float(cage_speed)
    elif (mode == "geometric" and np.ndim(cage_speed) == 1 and len(cage_speed) == bearing.balls
          and np.all(np.isfinite(np.asarray(cage_speed, dtype=float)))):
        return np.asarray(cage_speed, dtype=float)  # per ball (geometric mode)
    else:
        raise ValueError(f"cage_speed must be a finite angular speed in rad/s (or, geometric mode, one per ball), "
                         f"got {cage_speed!r}")


def _fixed_angle_distribution(bearing, axial_force, radial_force, centrifugal, cage, hold_axial, moment,
                              hertz_method, tol, max_iter):
    """The :class:`LoadDistribution` at the free contact angle (paper P4–P6, mode 'fixed-angle')."""
    z = bearing.balls
    psi = 2.0 * np.pi * np.arange(z) / z
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
