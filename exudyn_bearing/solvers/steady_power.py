"""Where the power goes in a steady rolling state (MODEL.md §11, §12): the losses of one ball
times the balls, by source and by place, and the power the races' drives put in.

In the steady state nothing accelerates, so the drive power equals the losses; the two are
computed independently (the drive from the race torques, the losses from each force's
power over the velocities it acts against) and their difference checks the balance.
"""
from __future__ import annotations

import numpy as np


__all__ = ["steady_losses", "steady_drive_power", "by_source"]

_E_Z = np.array([0.0, 0.0, 1.0])


def steady_losses(solved) -> dict:
    """Losses of the whole bearing in the steady state ``solved``
    (:class:`~exudyn_bearing.solvers.steady.Solved`), W, by place: ``inner_contacts`` and
    ``outer_contacts`` (traction and spin, ∫ τ·u, §11a), ``rolling_resistance`` (§11b),
    ``ball_drag`` (§11c, eq. 11c.1), ``jet_momentum`` (eq. 11c.2), ``land_outer``/``land_inner``
    (the centred land's shear, K Δω², §11d) and ``pockets`` (their friction, §11d)."""
    ball, b = solved.ball, solved.ball.b
    w_c, w_b, c, _ = ball.unpack(solved.x)
    _, f = ball.contacts(solved.x)
    z = b.balls
    out = {"inner_contacts": z * float(f.heat[0]), "outer_contacts": z * float(f.heat[1]),
           "rolling_resistance": z * float(np.sum(f.rolling_loss)) if f.rolling_loss is not None else 0.0}
    v = w_c * c[0]
    out["ball_drag"] = z * 0.5 * ball.c_d * ball.density * np.pi * b.ball_radius ** 2 * abs(v) ** 3
    out["jet_momentum"] = z * ball.drag_linear * v ** 2  # eq. 11c.2 (0 without a jet)
    k_land, w_land = ball.land
    guidance = "land_outer" if w_land == solved.w_o else "land_inner"
    out[guidance] = k_land * (w_land - w_c) ** 2
    pockets = 0.0
    if k_land > 0 and ball.pocket[0] > 0:
        _, friction, arm = ball.pocket_forces(c, w_c, w_b)
        # the ball's surface against the cage's at the pocket contact
        slip = np.cross(w_b - w_c * _E_Z, arm)
        pockets = -z * float(friction @ slip)
    out["pockets"] = pockets
    return out


def steady_drive_power(solved) -> float:
    """Power the races' drives put in, W: each race turns at its speed against the torque
    the balls put on it about the axis, −Z (c × F + M)_z (F, M the contact's force and
    moment about the ball centre on the ball), and the guiding race against the land's."""
    ball = solved.ball
    w_c, _, c, _ = ball.unpack(solved.x)
    _, f = ball.contacts(solved.x)
    z = ball.b.balls
    torque = [z * float((np.cross(c, f.force[k]) + f.moment[k])[2]) for k in (0, 1)]
    k_land, w_land = ball.land
    return torque[0] * solved.w_i + torque[1] * solved.w_o + k_land * (w_land - w_c) * w_land


def by_source(losses: dict) -> dict:
    """The places of :func:`steady_losses` summed by the sources of the dynamic results'
    ``power_loss_W`` (traction, rolling_resistance, ball_drag, jet_momentum, cage, total), W."""
    out = {"traction": losses["inner_contacts"] + losses["outer_contacts"],
           "rolling_resistance": losses["rolling_resistance"], "ball_drag": losses["ball_drag"],
           "jet_momentum": losses.get("jet_momentum", 0.0),
           "cage": losses.get("land_outer", 0.0) + losses.get("land_inner", 0.0) + losses["pockets"]}
    out["total"] = sum(out.values())
    return {k: float(v) for k, v in out.items()}
