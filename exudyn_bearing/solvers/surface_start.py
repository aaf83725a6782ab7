"""The start with imperfect surfaces (MODEL.md §13d): each ball (and a free inner race) moved
so that the surfaces at t = 0 carry the same forces as the perfect bearing's start.

The start solvers (:mod:`exudyn_bearing.solvers.start`) balance a perfect bearing. A surface
height h at a contact at t = 0 (a ball over a defect, waviness, an oversize ball, a pit)
changes that contact's approach by h; without a correction the run would start with those
contacts off their loads (Q ∝ δ^1.5: 0.1 µm on a 10-µm approach is 1.5 %) and ring. Here the
balls' centres (radially and axially, as the start solvers place them; a ball's place in its
pocket is kept) and, when the builder made it and its translation is free, the inner race's
are moved by u so that the connector's generalized forces on them along those directions
with the surfaces equal those of the perfect start: P F_s(q + Pᵀ u) = P F_0(q), solved by
Newton with a finite-difference Jacobian of the numpy force path (all columns in one batched
call). Velocities are kept.

Where that balance does not exist — a ball over a defect deeper than its approach sinks into
it and cannot keep both contacts' loads with its two directions, the inner race being shared
by all balls — the iterate with the smallest force left is kept (the least-squares start) and
the message names the body that holds it; only a start that leaves more force than the
perfect state falls back to that state.
"""
from __future__ import annotations

import numpy as np

__all__ = ["SurfaceStart", "surface_start"]

#: translation step of the finite-difference Jacobian, m
STEP = 1e-9
#: largest move per Newton iteration, m: a ball over a defect loses a contact and the
#: Jacobian its stiffness there
MAX_MOVE = 2e-6


class SurfaceStart(dict):
    """What :func:`surface_start` did: ``moves`` (slot -> (3,) m, global), ``iterations``,
    ``residual_N`` (largest force left along the moved directions), ``converged``, ``placed``
    (not converged, but the least-squares placement kept), ``message``."""


def surface_start(con, q, q_t, moves, tolerance=1e-3, max_iter=30) -> tuple:
    """(q corrected, :class:`SurfaceStart`) for the connector ``con`` with a surface, absolute
    coordinates ``q`` and velocities ``q_t`` (6 per node slot) at t = 0. ``moves``: per node
    slot that moves, the unit directions (k, 3) (global) along which it moves and its force
    is balanced (a ball: radially and axially, as the start solvers; a free race: all three);
    ``tolerance`` in N."""
    slots = [int(s) for s, _ in moves]
    basis = np.zeros((sum(len(d) for _, d in moves), q.size))  # generalized translation per unknown
    i = 0
    for s, dirs in moves:
        for d in np.atleast_2d(dirs):
            basis[i, 6 * s:6 * s + 3] = d
            i += 1
    target = basis @ con.numpy_forces(0.0, q[None], q_t[None], surface=False)[0]
    owner = np.repeat(slots, [len(np.atleast_2d(d)) for _, d in moves])  # the slot of each unknown
    u = np.zeros(len(basis))
    best = (np.inf, u.copy(), None)  # (force left N, u, residual) of the best iterate
    info = SurfaceStart(iterations=0, converged=False)
    for it in range(max_iter + 1):
        states = q + (u @ basis) + np.vstack([np.zeros(q.size), STEP * basis])
        forces = con.numpy_forces(0.0, states, np.broadcast_to(q_t, states.shape), surface=True) @ basis.T
        residual = forces[0] - target
        info.update(iterations=it, residual_N=float(np.max(np.abs(residual))))
        if info["residual_N"] < best[0]:
            best = (info["residual_N"], u.copy(), residual)
        if it == 0:
            perfect_N = info["residual_N"]  # the force the perfect state leaves
        if info["residual_N"] <= tolerance:
            info["converged"] = True
            break
        if it == max_iter or not np.all(np.isfinite(residual)):
            break
        jac = (forces[1:] - forces[0]).T / STEP
        delta = np.linalg.lstsq(jac, -residual, rcond=1e-12)[0]
        largest = np.max(np.abs(delta))
        u += delta * min(1.0, MAX_MOVE / largest) if largest > 0 else 0.0
    if not info["converged"]:
        left, u, residual = best
        info["residual_N"] = left
        if not left < 0.5 * perfect_N:  # no better than the perfect state: keep that one
            u = np.zeros(len(basis))
            info["message"] = (f"surface start: no placement carries the surfaces' forces better than the perfect "
                               f"bearing's state ({perfect_N:.3g} N left there), which the run starts from")
    moved = q + u @ basis
    info["moves"] = {s: moved[6 * s:6 * s + 3] - q[6 * s:6 * s + 3] for s in slots}
    largest = max(np.linalg.norm(v) for v in info["moves"].values())
    if info["converged"]:
        info["message"] = (f"surface start: {len(slots)} bodies placed, moved by up to {largest * 1e6:.3g} um "
                           f"({info['iterations']} iterations)")
    elif np.any(u):
        info["placed"] = True
        holder = int(owner[int(np.argmax(np.abs(residual)))])
        who = f"ball {con.layout['balls'].index(holder)}" if holder in con.layout["balls"] else "the inner race"
        info["message"] = (f"surface start: {len(slots)} bodies placed, moved by up to {largest * 1e6:.3g} um; "
                           f"{left:.3g} N of the perfect start's forces left on {who} (of {perfect_N:.3g} N "
                           f"unplaced): a ball over a defect deeper than its approach sinks into it and cannot "
                           f"keep both contacts' loads")
    return moved, info
