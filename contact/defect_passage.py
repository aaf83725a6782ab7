"""Where a ball's contact unloads and is struck on a defect passage, from the geometry alone
(MODEL.md eq. 13.8): the estimate the simulated passage events are checked against.

The ball sits between its two races on two Hertz contacts in series: their approaches add,
δ_t = δ_i + δ_o = (K_i^{-2/3} + K_o^{-2/3}) Q^{2/3}, so where a defect lowers one race by g
under the ball (the race held by the other balls) the ball carries

    Q = Q₀ (1 − g/δ_t)^{3/2}.                                                   (13.8)

Along the rolling direction x from the entry edge the drop g is the entry edge's circle
s(x) ≈ x²/(2 R_x) (eq. 13.2), then at most the defect's reach r, then the exit edge's circle
s(L − x); R_x is the defective race's contact radius along the rolling direction.

* The contact **starts to unload** where it has lost the share σ of its load:
  g = δ_t (1 − (1 − σ)^{2/3}), x_e = √(g (2 R_x − g)).
* Where the reach is at least δ_t the ball **loses its load** over the defect and is struck
  where the exit edge's circle comes back up to it, g = δ_t: u = L − x_i = √(δ_t (2 R_x − δ_t)).
  The ball falls into the gap far faster than it crosses it (the other contact pushes it with
  ~Q, tens of thousands of m/s² on a gram), so it waits there, unloaded, for the edge.
* Shallower, it keeps part of its load and follows the path; its load rises fastest on the exit
  circle where d/du [u √(1 − u²/(2 R_x δ_t))] = 0, u* = √(R_x δ_t) (sunk δ_t/2), or, where the
  reach is below δ_t/2, where the exit circle starts, u_r = √(r (2 R_x − r)):
  L − x_i = min(u*, u_r).
"""
from __future__ import annotations

import math

__all__ = ["UNLOAD_SHARE", "series_approach", "passage_marks", "length_from_spacing"]

#: the share of its load a contact has lost where it "starts to unload" (eq. 13.8)
UNLOAD_SHARE = 0.05


def series_approach(load: float, inner_stiffness: float, outer_stiffness: float) -> float:
    """δ_t = (K_i^{-2/3} + K_o^{-2/3}) Q^{2/3}: a ball's two Hertz approaches at the load Q N
    on both contacts, K N/m^1.5 (eq. 13.8), m."""
    if not (math.isfinite(load) and load >= 0):
        raise ValueError(f"load must be >= 0, got {load!r}")
    for name, value in (("inner_stiffness", inner_stiffness), ("outer_stiffness", outer_stiffness)):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be positive, got {value!r}")
    return (inner_stiffness ** (-2.0 / 3.0) + outer_stiffness ** (-2.0 / 3.0)) * load ** (2.0 / 3.0)


def passage_marks(length: float, reach: float, rolling_radius: float, approach: float,
                  unload_share: float = UNLOAD_SHARE):
    """(x_e, x_i): where a contact starts to unload and where it is struck, m from the defect's
    entry edge along the rolling direction (eq. 13.8, module docstring); x_e is None where the
    defect's ``reach`` (m, :meth:`contact.surface.Defect.reach`) is too shallow to take
    ``unload_share`` of the load. ``length`` L m, ``rolling_radius`` R_x m of the defective race,
    ``approach`` δ_t m (:func:`series_approach` before the defect)."""
    for name, value in (("length", length), ("rolling_radius", rolling_radius), ("approach", approach)):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be positive, got {value!r}")
    if not (math.isfinite(reach) and reach >= 0):
        raise ValueError(f"reach must be >= 0, got {reach!r}")
    if not 0 < unload_share < 1:
        raise ValueError(f"unload_share must lie in (0, 1), got {unload_share!r}")
    g = approach * (1.0 - (1.0 - unload_share) ** (2.0 / 3.0))
    x_e = math.sqrt(g * (2.0 * rolling_radius - g)) if reach >= g else None
    if reach >= approach:  # unloaded over the defect: struck where the exit circle meets the ball
        u = math.sqrt(approach * (2.0 * rolling_radius - approach))
    else:
        u = min(math.sqrt(rolling_radius * approach), math.sqrt(reach * (2.0 * rolling_radius - reach)))
    return x_e, length - min(u, 0.5 * length)


def length_from_spacing(spacing: float, speed: float, rolling_radius: float, approach: float,
                        unload_share: float = UNLOAD_SHARE) -> float:
    """The length L m of a spall over which a ball loses its load, from the time ``spacing`` s
    between its unloading and its strike at the contact's ``speed`` m/s over the race: eq. 13.8
    inverted (eq. 13.10), v Δt = x_i − x_e with x_e = √(g (2R_x − g)) and L − x_i =
    min(u, L/2), u = √(δ_t (2R_x − δ_t)): L = v Δt + x_e + u, or 2 (v Δt + x_e) where that is
    shorter than 2u (the ball struck at the middle). ``rolling_radius`` R_x m of the race,
    ``approach`` δ_t m (:func:`series_approach` at the ball's load before the spall)."""
    for name, value in (("spacing", spacing), ("speed", speed), ("rolling_radius", rolling_radius),
                        ("approach", approach)):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be positive, got {value!r}")
    if approach >= rolling_radius:
        raise ValueError(f"approach {approach!r} m must be below rolling_radius {rolling_radius!r} m")
    x_e, _ = passage_marks(1.0, 1.0, rolling_radius, approach, unload_share)  # reach >= δ_t: unloaded
    u = math.sqrt(approach * (2.0 * rolling_radius - approach))
    travel = speed * spacing + x_e
    return travel + u if travel >= u else 2.0 * travel
