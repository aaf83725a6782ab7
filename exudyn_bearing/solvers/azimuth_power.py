"""Where the power goes in a quasi-dynamic state under combined load (MODEL.md §11, §12a): the
losses of every ball at its azimuth, by place, the power the races' drives put in, and the
operating point the thermal network's conductances read (§14a).

The quasi-dynamic state is steady in the cage's frame: nothing accelerates but the balls'
spins, carried along the orbit without loss. The drive power (from the race torques, each
race about its own centre) and the losses (each force's power over the velocities it acts
against) are computed independently, as for the axial steady state
(:mod:`exudyn_bearing.solvers.steady_power`). They differ by the contacts' normal work
Σ Q ṗ: the balance moves each ball at ω_c about the cage centre, not along its orbit's
radial changes, so the loads work on their approach rates (MODEL.md §14d: 2.9e-4 of the
losses on the reference bearing at 2.2 kN + 2 kN, 0.13 % on the 6205 at 1 kN radial).
"""
from __future__ import annotations

import numpy as np

from contact.bearing_thermal import OperatingPoint, mean_contact

__all__ = ["azimuth_losses", "azimuth_drive_power", "azimuth_operating_point"]


def azimuth_losses(balance, x) -> dict:
    """Losses of the whole bearing in the quasi-dynamic state ``x`` (scaled unknowns) of
    ``balance`` (:class:`~exudyn_bearing.solvers.azimuth_balance._Balance`), W, by place as
    :data:`contact.bearing_thermal.HEAT_SPLIT` names them: each race's contacts (traction and
    spin, ∫ τ·u, §11a), ``rolling_resistance`` (§11b), ``ball_drag`` (§11c), ``jet_momentum``
    (eq. 11c.2), the guiding
    race's land (K Δω², §11d; the race turning at the land's speed, as
    :func:`~exudyn_bearing.solvers.steady_power.steady_losses` names it) and ``pockets``
    (none: the balls orbit with their pockets, which have no friction in this balance)."""
    z = balance.z
    _, f = balance.contacts(x)
    state = balance._motion(x)
    out = {"inner_contacts": float(np.sum(f.heat[:z])), "outer_contacts": float(np.sum(f.heat[z:])),
           "rolling_resistance": 0.0 if f.rolling_loss is None else float(np.sum(f.rolling_loss))}
    speed = np.abs(state["v"][:z, 1])  # about the bearing axis, as the drag acts (contact.cage.drag_forces)
    out["ball_drag"] = float(np.sum(0.5 * balance.c_d * balance.density * np.pi * balance.b.ball_radius ** 2
                                    * speed ** 3))
    out["jet_momentum"] = float(np.sum(balance.drag_linear * speed ** 2))  # eq. 11c.2 (0 without a jet)
    k_land, w_land = balance.land
    outer = w_land == balance.race_omega[z, 2]
    out["land_outer" if outer else "land_inner"] = float(k_land * (w_land - state["w_c"]) ** 2)
    out["pockets"] = 0.0
    return out


def azimuth_drive_power(balance, x) -> float:
    """Power the races' drives put in, W: each race turns at its speed about its own centre
    o against the torque the balls put on it, −Σ_j ((c_j − o) × F_j + M_j)_z (F, M the
    contact's force and moment about the ball centre on the ball, in each ball's azimuth
    frame; o where the kinematics turn the race about: the inner race's displacement with its
    groove's tilt shift, the outer race's origin), so its drive puts in
    Σ_j ((c_j − o) × F_j + M_j)_z times its speed; and the guiding race against the land's."""
    z = balance.z
    _, f = balance.contacts(x)
    motion = balance._motion(x)
    # about the bearing's axis instead, a radially loaded race's few-nm sideways shift times
    # its load missed 4 % of the 6205's losses
    torque = (np.cross(motion["both"] - motion["origin"], f.force) + f.moment)[:, 2]
    w_i, w_o = balance.race_omega[0, 2], balance.race_omega[z, 2]
    k_land, w_land = balance.land
    w_c = motion["w_c"]
    return float(np.sum(torque[:z])) * w_i + float(np.sum(torque[z:])) * w_o + k_land * (w_land - w_c) * w_land


def azimuth_operating_point(balance, x) -> OperatingPoint:
    """The network's :class:`OperatingPoint` (eq. 14.4, 14.5): race and cage speeds, the balls'
    mean spin speed, and per race its loaded contacts' mean Hertz semi-axes, central film and
    rolling speed (as the dynamic run's, :func:`exudyn_bearing.model.thermal_nodes.operating_point_of`)."""
    z = balance.z
    kin, f = balance.contacts(x)
    state = balance._motion(x)
    _, hertz = balance.params.hertz(kin.contact_angle, balance.law.hertz_method)
    a, b = hertz.semi_axes(f.normal_load)
    speed = np.abs(kin.entrainment)
    contacts = [mean_contact(a[part], b[part], f.film_thickness[part], speed[part], f.normal_load[part])
                for part in (slice(0, z), slice(z, 2 * z))]
    spin = float(np.mean(np.linalg.norm(state["w_b"], axis=1)))
    return OperatingPoint(float(balance.race_omega[0, 2]), float(balance.race_omega[z, 2]), float(state["w_c"]),
                          spin, *contacts)
