"""Bearing outputs from recorded node states (MODEL.md §7).

Everything is recomputed after the run from the stored states with the same connector
the solver used, so a scene pays for outputs only when it asks for them.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from contact.cage import drag_forces
from contact.kinematics import cross, rolling_cage_speed
from ..errors import TractionCoefficientWarning

__all__ = ["BearingResults", "compute_results", "body_losses", "cage_slip", "settled", "settled_label",
           "MINIMUM_JUDGING_TIME", "TRACTION_COEFFICIENT_LIMIT", "TractionCoefficientWarning"]

#: Traction coefficient |f|/Q above which no real oil transmits the traction (MODEL.md §8:
#: measured EHL traction coefficients stay below ~0.1-0.15); a run above it gets a warning.
TRACTION_COEFFICIENT_LIMIT = 0.15


def cage_slip(reference_speed, cage_speed):
    """Cage slip (P19), %: (w_ref - w_c) / ((w_c + w_ref)/2) * 100; 0 when both speeds are 0
    (a bearing at rest does not slip)."""
    reference_speed, cage_speed = np.broadcast_arrays(np.asarray(reference_speed, dtype=float),
                                                      np.asarray(cage_speed, dtype=float))
    mean = 0.5 * (cage_speed + reference_speed)
    safe = np.where(mean == 0, 1.0, mean)
    return np.where(mean == 0, 0.0, 100.0 * (reference_speed - cage_speed) / safe)


#: shortest run whose settling is judged, s: :meth:`BearingResults.settled` is None below it
MINIMUM_JUDGING_TIME = 0.05


def settled_label(value) -> str:
    """'yes', 'no' or 'too short to judge' for a :meth:`BearingResults.settled` value."""
    return "too short to judge" if value is None else ("yes" if value else "no")


def settled(time, values, tolerance, window=1 / 6):
    """True when the mean of ``values`` over the last ``window`` of the run differs from
    the mean over the window before it by less than ``tolerance`` (same units)."""
    time = np.asarray(time)
    span = time[-1] - time[0]
    last = time >= time[-1] - window * span
    previous = (time >= time[-1] - 2 * window * span) & ~last
    if last.sum() < 2 or previous.sum() < 2:
        return False
    return bool(abs(np.mean(values[last]) - np.mean(values[previous])) < tolerance)


@dataclass
class BearingResults:
    """Outputs per recorded step (first axis: time; then ball index). SI units, angles in rad.

    Speeds are about the bearing axis; the orbiting frame of a ball has x circumferential,
    y radial, z axial (paper P8/P18).
    """

    time: np.ndarray
    inner_speed: np.ndarray  #: rad/s
    outer_speed: np.ndarray  #: rad/s
    cage_speed: np.ndarray  #: rad/s (rigid cage body; else mean ball orbital speed)
    cage_speed_nominal: np.ndarray  #: w_c^th of P19 (nominal angle), rad/s
    cage_slip_percent: np.ndarray  #: P19, %
    kinematic_cage_speed: np.ndarray  #: per ball, (T, Z), rad/s (MODEL.md §7)
    kinematic_cage_slip_percent: np.ndarray  #: mean over balls, %
    ball_position_angle: np.ndarray  #: (T, Z)
    ball_orbital_speed: np.ndarray  #: (T, Z), rad/s
    ball_omega_orbiting: np.ndarray  #: absolute ball angular velocity in the orbiting frame, (T, Z, 3)
    attitude_yz: np.ndarray  #: beta_YZ = asin(|w_x|/|w|), (T, Z)
    attitude_xz: np.ndarray  #: beta_XZ = asin(|w_y|/|w|), (T, Z)
    inner: dict  #: per-contact arrays (T, Z): load, contact_angle, slip_rolling, slip_transverse, slip, spin, film, traction_rolling, traction_transverse, spin_moment, heat, max_pressure
    outer: dict
    #: force all balls apply to the inner race (normal + traction), bearing frame, (T, 3), N
    inner_race_force: np.ndarray = None
    #: their moment about the bearing centre, bearing frame, (T, 3), N m
    inner_race_moment: np.ndarray = None
    #: force all balls apply to the outer race (the housing reaction), bearing frame, (T, 3), N
    outer_race_force: np.ndarray = None
    #: rigid cage centre off its guiding race's axis (unguided: the outer race's), (T,), m
    cage_eccentricity: np.ndarray = None
    #: guiding land's force on the cage (contact and film, MODEL.md §11d), magnitude (T,), N
    cage_land_force: np.ndarray = None
    #: largest traction coefficient |f|/Q of any loaded contact over the run (MODEL.md §8)
    max_traction_coefficient: float = 0.0
    #: where it exceeded TRACTION_COEFFICIENT_LIMIT (also issued as a warning), else None
    traction_warning: str | None = None
    #: moment all balls apply to the outer race about the bearing centre, bearing frame, (T, 3), N m
    outer_race_moment: np.ndarray = None
    #: power the ball drag takes from the balls, (T,), W (the sphere's, MODEL.md eq. 11c.1)
    drag_loss: np.ndarray = None
    #: power dissipated in the ball–pocket contacts (pocket damping; springs average out), (T,), W
    cage_loss: np.ndarray = None
    #: power dissipated at the cage's guiding land (its force pair and its film's shear), (T,), W
    land_loss: np.ndarray = None
    #: power the guiding race puts into the cage through its land (film torque and force), (T,), W
    land_drive: np.ndarray = None
    #: power the jet oil's momentum takes from the balls, (T,), W (MODEL.md eq. 11c.2; zero without a jet)
    jet_loss: np.ndarray = None

    def last(self, fraction=1 / 3):
        """Boolean mask of the last ``fraction`` of the run."""
        return self.time >= self.time[-1] - fraction * (self.time[-1] - self.time[0])

    def summary(self, fraction=1 / 3, settle_tolerance_percent=0.1) -> dict:
        """Means over the last ``fraction`` of the run and :meth:`settled`."""
        m = self.last(fraction)
        return {
            "kinematic_cage_slip_percent": float(np.mean(self.kinematic_cage_slip_percent[m])),
            "cage_slip_percent": float(np.mean(self.cage_slip_percent[m])),
            "cage_speed": float(np.mean(self.cage_speed[m])),
            "cage_speed_nominal": float(np.mean(self.cage_speed_nominal[m])),
            "attitude_yz_deg": float(np.degrees(np.mean(self.attitude_yz[m]))),
            "attitude_xz_deg": float(np.degrees(np.mean(self.attitude_xz[m]))),
            "max_inner_load": float(np.max(self.inner["load"][m])),
            "max_outer_load": float(np.max(self.outer["load"][m])),
            "max_inner_slip": float(np.max(self.inner["slip"][m])),
            "max_traction_coefficient": float(self.max_traction_coefficient),
            "power_loss_W": {k: float(np.mean(v[m])) for k, v in self.power_loss().items()},
            "drive_power_W": float(np.mean(self.drive_power()[m])),
            "energy_balance_percent": self.energy_balance_percent(fraction),
            "settled": self.settled(settle_tolerance_percent),
        }

    def energy_balance_percent(self, fraction=1 / 3) -> float:
        """(drive power - total loss) / drive power over the last ``fraction``, % (MODEL.md §11):
        near 0 in a settled run; what remains is kinetic energy still changing or the
        integrator's numerical damping — a check of the run's accuracy."""
        m = self.last(fraction)
        drive = float(np.mean(self.drive_power()[m]))
        loss = float(np.mean(self.power_loss()["total"][m]))
        return 100.0 * (drive - loss) / drive if drive else float("nan")

    def power_loss(self) -> dict:
        """Power lost by source, W, as time series (T,) (MODEL.md §11): 'traction' (traction
        and spin moment at all ball–race contacts, §6), 'rolling_resistance' (§11b),
        'contact_damping' (the normal contact damping, §3), 'ball_drag' (§8, eq. 11c.1),
        'jet_momentum' (the jet oil's, eq. 11c.2), 'cage'
        (ball–pocket contacts with their friction, guiding land), and their 'total'. Sources
        a scene does not model are zero. Compare :meth:`drive_power`."""
        zero = np.zeros_like(self.time)

        def both(name):
            return (np.sum(self.inner[name], axis=1) + np.sum(self.outer[name], axis=1)) if name in self.inner else zero

        out = {"traction": both("heat"), "rolling_resistance": both("rolling_loss"),
               "contact_damping": both("damping_loss"),
               "ball_drag": zero if self.drag_loss is None else self.drag_loss,
               "jet_momentum": zero if self.jet_loss is None else self.jet_loss,
               "cage": (zero if self.cage_loss is None else self.cage_loss)
               + (zero if self.land_loss is None else self.land_loss)}
        out["total"] = sum(out.values())
        return out

    def drive_power(self) -> np.ndarray:
        """Power the races put into the bearing, (T,), W: -(M_z w) of the balls' moment on each
        race about the bearing axis, plus what a guiding race puts into the cage through its
        land (its film's torque and force). In a settled run it equals the total of :meth:`power_loss`
        (energy balance; race translation neglected)."""
        if self.inner_race_moment is None:  # results assembled without the race reactions
            return np.full_like(self.time, np.nan, dtype=float)
        p = -self.inner_race_moment[:, 2] * self.inner_speed
        if self.outer_race_moment is not None:
            p = p - self.outer_race_moment[:, 2] * self.outer_speed
        if self.land_drive is not None:
            p = p + self.land_drive
        return p

    def settled(self, tolerance_percent=0.1, minimum_time=MINIMUM_JUDGING_TIME) -> bool | None:
        """True when neither the cage speed (in % of itself) nor the kinematic cage slip (in
        percentage points) drifted by more than ``tolerance_percent`` between the last sixth
        of the run and the sixth before it, False when one did; None — too short to judge —
        for a run shorter than ``minimum_time`` s (its sixths would hide slow drifts)."""
        if self.time[-1] - self.time[0] < minimum_time:
            return None
        cage_percent = 100.0 * self.cage_speed / max(abs(float(np.mean(self.cage_speed))), 1e-300)
        return (settled(self.time, cage_percent, tolerance_percent)
                and settled(self.time, self.kinematic_cage_slip_percent, tolerance_percent))


_CONTACT_FIELDS = ("load", "contact_angle", "slip_rolling", "slip_transverse", "slip", "spin", "film",
                   "traction_rolling", "traction_transverse", "spin_moment", "heat", "max_pressure", "rolling_loss",
                   "damping_loss")


def compute_results(handle, time, q, q_t, chunk: int = 256) -> BearingResults:
    """Evaluate the connector on the recorded states (times (T,) s, absolute coordinates and
    velocities (T, 6 n_nodes)) and derive the outputs; ``chunk`` states go through the
    connector's numpy path at once."""
    time = np.asarray(time, dtype=float)
    parts = [_outputs(handle.connector, time[part], q[part], q_t[part]) for part in _chunks(handle, time, chunk)]
    out = {name: (np.concatenate([p[name] for p in parts]) if not isinstance(parts[0][name], dict) else
                  {f: np.concatenate([p[name][f] for p in parts]) for f in parts[0][name]})
           for name in parts[0]}
    mu_max, warning = _traction_coefficient(time, {"inner": out["inner"], "outer": out["outer"]})
    nominal = out["nominal"]
    cage = out["cage_speed"]
    kin_slip = np.mean(cage_slip(out["kin"], cage[:, None]), axis=1)
    return BearingResults(time, out["inner_speed"], out["outer_speed"], cage, nominal, cage_slip(nominal, cage),
                          out["kin"], kin_slip, out["psi"], out["orbit"], out["w_orb"], out["byz"], out["bxz"],
                          out["inner"], out["outer"], out["inner_race_force"], out["inner_moment"],
                          out["outer_race_force"], out["cage_eccentricity"], out["land_force"], mu_max, warning,
                          out["outer_moment"], out["drag_loss"], out["cage_loss"], out["land_loss"], out["land_drive"],
                          out["jet_loss"])


def _chunks(handle, time, chunk):
    """Slices of at most ``chunk`` recorded states; with temperatures in the solve (MODEL.md
    §14g), each within one update of the contacts' oils and sizes, which are set for it here
    (every state is evaluated with the oils and sizes it ran with; the last update's are left
    set)."""
    temperatures = getattr(handle, "temperatures", None)
    if temperatures is None or not temperatures.updates:
        yield from (slice(k, k + chunk) for k in range(0, len(time), chunk))
        return
    update = temperatures.oils_at(time)
    edges = np.flatnonzero(np.diff(update)) + 1
    for lo, hi in zip(np.concatenate([[0], edges]), np.concatenate([edges, [len(time)]])):
        _set_update(handle.connector, temperatures.updates[update[lo]])
        yield from (slice(k, min(k + chunk, hi)) for k in range(lo, hi, chunk))
    _set_update(handle.connector, temperatures.updates[-1])


def _set_update(con, update) -> None:
    """The oils and sizes of one thermal ``update`` set on the connector ``con``."""
    con.set_oils(*update["oils"])
    con.set_geometry(update["bearing"])


def _outputs(con, time, q, q_t) -> dict:
    """The per-state outputs of B recorded states (:meth:`BearingConnector.states`): arrays
    with a leading axis B, the contact arrays per race in dicts."""
    s = con.states(time, q, q_t)
    frame, origin, axis = con.rotation, con.origin, con.axis
    b, z = s.ball_position.shape[:2]
    rel = (s.ball_position - origin) @ frame  # bearing frame
    vel = s.ball_velocity @ frame
    omega = s.ball_omega @ frame
    radius = np.hypot(rel[..., 0], rel[..., 1])
    e_r = np.stack([rel[..., 0] / radius, rel[..., 1] / radius, np.zeros((b, z))], axis=-1)
    e_psi = np.stack([-e_r[..., 1], e_r[..., 0], np.zeros((b, z))], axis=-1)
    orbit = np.einsum("bij,bij->bi", vel, e_psi) / radius
    w_orb = np.stack([np.einsum("bij,bij->bi", omega, e_psi), np.einsum("bij,bij->bi", omega, e_r), omega[..., 2]],
                     axis=-1)
    norm = np.maximum(np.linalg.norm(omega, axis=-1), 1e-300)
    w_i, w_o = s.inner_omega @ axis, s.outer_omega @ axis
    cage = s.cage_omega @ axis if s.cage_omega is not None else np.mean(orbit, axis=1)
    # race surface speed along the rolling direction at each contact centre
    surface = []
    for kin in (s.inner, s.outer):
        v_ball_p = s.ball_velocity + cross(s.ball_omega, kin.point - s.ball_position)
        surface.append((np.einsum("bij,bij->bi", v_ball_p, kin.rolling) + kin.slip_rolling).ravel())
    p_in, p_out = (s.inner.point - origin) @ frame, (s.outer.point - origin) @ frame
    kinematic = rolling_cage_speed(rel.reshape(-1, 3), omega.reshape(-1, 3), p_in.reshape(-1, 3),
                                   p_out.reshape(-1, 3), np.repeat(w_i, z), np.repeat(w_o, z),
                                   surface_speeds=surface).reshape(b, z)
    out = {"inner_speed": w_i, "outer_speed": w_o, "cage_speed": cage, "psi": np.arctan2(rel[..., 1], rel[..., 0]),
           "orbit": orbit, "w_orb": w_orb, "kin": kinematic,
           "byz": np.arcsin(np.minimum(np.abs(w_orb[..., 0]) / norm, 1.0)),
           "bxz": np.arcsin(np.minimum(np.abs(w_orb[..., 1]) / norm, 1.0)),
           "cage_eccentricity": s.cage_eccentricity,
           "land_force": np.zeros(b) if s.cage_land_force is None else np.linalg.norm(s.cage_land_force, axis=-1),
           "land_drive": s.land_drive_power}
    out["drag_loss"], out["cage_loss"], out["land_loss"] = body_losses(s)
    # the drag force holds the sphere's and the jet's parts: the jet's apart (zero without one)
    out["jet_loss"] = jet_losses(s, con.axis, con.origin, con.cage_record.drag_linear)
    out["drag_loss"] = out["drag_loss"] - out["jet_loss"]
    # the nominal cage speed with the sizes these states ran with (a run's temperatures grow them)
    out["nominal"] = np.array([con.bearing.cage_speed(wi, wo) for wi, wo in zip(w_i, w_o)])
    for race, kin, f in (("inner", s.inner, s.inner_forces), ("outer", s.outer, s.outer_forces)):
        # a race receives -F at each contact point and -M_z n: about the bearing centre o that
        # is -[(c - o) x F + (moment on the ball about its centre)]
        out[f"{race}_moment"] = -np.sum(cross(s.ball_position - origin, f.force) + f.moment, axis=1) @ frame
        out[f"{race}_race_force"] = -f.force.sum(axis=1) @ frame
        c = {"load": f.normal_load, "contact_angle": kin.contact_angle, "slip_rolling": kin.slip_rolling,
             "slip_transverse": kin.slip_transverse, "slip": np.hypot(kin.slip_rolling, kin.slip_transverse),
             "spin": kin.spin, "film": f.film_thickness, "traction_rolling": f.traction_rolling,
             "traction_transverse": f.traction_transverse, "spin_moment": f.spin_moment, "heat": f.heat,
             "max_pressure": f.max_pressure}
        for name in ("rolling_loss", "damping_loss"):
            c[name] = np.zeros((b, z)) if getattr(f, name) is None else getattr(f, name)
        out[race] = {name: np.asarray(c[name], dtype=float) for name in _CONTACT_FIELDS}
    return out


def jet_losses(s, axis, origin, factor) -> np.ndarray:
    """The jet oil's momentum loss of B states (a batched :class:`ConnectorState`), (B,) W:
    Σ_j k v_j², v_j each ball's speed along its orbit about ``axis`` through ``origin`` and k
    the jet's ``factor`` (kg/s; MODEL.md eq. 11c.2): minus the power of the drag law's jet
    part alone (:func:`contact.cage.drag_forces`); zeros for k = 0."""
    if factor == 0:
        return np.zeros(s.ball_position.shape[0])
    force = drag_forces(s.ball_position, s.ball_velocity, axis, origin, 0.0, 0.0, 0.0, linear=factor)
    return -np.sum(force * s.ball_velocity, axis=(1, 2))


def body_losses(s) -> tuple:
    """(ball drag, cage pocket (damping and friction), guiding land) power losses of B states
    (a batched :class:`ConnectorState`), (B,) W each: minus the power of each force pair over
    the velocities of the points it acts on (the pocket reaction acts on the cage at the
    ball centre, the land force at the cage centre)."""
    drag = -np.sum(s.drag_force * s.ball_velocity, axis=(1, 2))
    pocket = land = np.zeros(len(drag))
    if s.cage_position is not None:
        v_pocket = s.cage_velocity[:, None] + cross(s.cage_omega[:, None], s.ball_position - s.cage_position[:, None])
        # + the pocket friction's, -F_f . v_t at the contact points (MODEL.md §11d)
        pocket = -np.sum(s.cage_force * (s.ball_velocity - v_pocket), axis=(1, 2)) + s.pocket_friction_loss
        if s.cage_land_force is not None:  # its force pair, and its film's shear (MODEL.md §11d)
            land = s.land_force_loss + s.land_friction_loss
    elif s.cage_force is not None:
        pocket = -np.sum(s.cage_force * s.ball_velocity, axis=(1, 2))  # spring chain: balls only
    return drag, pocket, land


def _traction_coefficient(time, contacts, threshold=None):
    """Largest |f|/Q over the loaded contacts (Q > 0.1 % of the heaviest) and, above
    ``threshold`` (default :data:`TRACTION_COEFFICIENT_LIMIT`), a sentence saying where; the
    sentence is also issued once as a :class:`TractionCoefficientWarning`."""
    threshold = TRACTION_COEFFICIENT_LIMIT if threshold is None else threshold
    best = (0.0, None)
    for race, c in contacts.items():
        load = c["load"]
        loaded = load > 1e-3 * max(float(np.max(load, initial=0.0)), 1e-300)
        mu = np.where(loaded, np.hypot(c["traction_rolling"], c["traction_transverse"]) / np.where(loaded, load, 1.0),
                      0.0)
        k = np.unravel_index(int(np.argmax(mu)), mu.shape) if mu.size else None
        if k is not None and mu[k] > best[0]:
            best = (float(mu[k]), (race, k, float(load[k]), float(c["max_pressure"][k])))
    mu_max, where = best
    if mu_max <= threshold or where is None:
        return mu_max, None
    race, (step, ball), load, p_max = where
    text = (f"traction coefficient {mu_max:.3g} > {threshold:g} at the {race} race, ball {ball}, t = "
            f"{time[step]:.6g} s (Q = {load:.4g} N, p_max = {p_max / 1e9:.3g} GPa): no real oil transmits "
            "that much; the pure Crook law has no limiting shear stress (MODEL.md §6a, §8)")
    warnings.warn(text, TractionCoefficientWarning, stacklevel=3)
    return mu_max, text
