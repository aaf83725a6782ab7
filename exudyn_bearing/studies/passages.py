"""Defect passages of a vibration run (MODEL.md §13b): when each ball's contact crosses each
defect, how deep a ball reaches into it, and which passages a step cut follows."""
from __future__ import annotations

import math

import numpy as np

from contact.defect_passage import UNLOAD_SHARE, passage_marks, series_approach
from contact.geometry import contact_path_radius
from ..bearing import Bearing

__all__ = ["defect_reaches", "defect_events", "ball_defect_events", "passages_cut", "read_impacts",
           "impact_summary", "ball_approach"]


def ball_approach(bearing: Bearing, load: float) -> float:
    """δ_t m: a ball's two Hertz approaches in series at the load ``load`` N on both contacts,
    at the nominal contact angle (MODEL.md eq. 13.8, :func:`contact.defect_passage.series_approach`)."""
    stiffness = (float(bearing.hertz(bearing.contact_angle, k).stiffness) for k in ("inner", "outer"))
    return series_approach(load, *stiffness)


def defect_reaches(bearing: Bearing, surface, loads) -> list:
    """Per defect of ``surface``: [how deep a ball reaches into it (:meth:`contact.surface.Defect.reach`,
    MODEL.md eq. 13.2–13.2c, R_x and R_y at the nominal contact angle), the race's largest Hertz
    approach δ at the quasi-static ``loads``], m; a ball's pit is read against the outer race,
    which it meets first."""
    out = []
    for d in surface.defects:
        race = "outer" if d.race == "ball" else d.race
        reach = d.reach(*(float(v) for v in bearing.curvature_radii(bearing.contact_angle, race)))
        delta = float(max(loads.inner_deflection if race == "inner" else loads.outer_deflection))
        out.append([reach, delta])
    return out


def defect_events(results, bearing: Bearing, surface) -> list:
    """Each ball's passages over each defect (MODEL.md §13b): [{"defect": index, "ball": j,
    "edge_s": the contact reaches the entry edge, where the ball starts to unload,
    "exit_s": it reaches the exit edge}], in time order (:func:`read_impacts` adds when the
    simulated load shows the unloading and the strike). The ball is struck on the exit side
    and re-stressed at or before ``exit_s``: where the exit edge's circle (eq. 13.2) comes back
    up to the depth the ball had sunk to, at most √(d (2 R_x − d)) before the edge (R_x the
    contact's reduced radius along the rolling direction).

    The contact's azimuth in the race frame is the ball's azimuth minus the race's turned angle
    (the time integral of its recorded speed); edge crossings are interpolated between
    recorded states. A pit on a ball has its events from the recorded states:
    :func:`ball_defect_events`."""
    t = np.asarray(results.time)
    psi = np.unwrap(results.ball_position_angle, axis=0)
    turned = {"inner": _integral(t, results.inner_speed), "outer": _integral(t, results.outer_speed)}
    events = []
    for i, d in enumerate(surface.defects):
        if d.race == "ball":
            continue
        rho = contact_path_radius(bearing.ball_diameter, bearing.pitch_diameter, bearing.contact_angle, d.race)
        half = 0.5 * d.length / rho  # the defect's half angle on the contact path
        for j in range(psi.shape[1]):
            rel = psi[:, j] - turned[d.race] - math.radians(d.angle_deg)
            forward = rel[-1] >= rel[0]  # the contact runs over the race in this sense
            first, second = (-half, half) if forward else (half, -half)
            for n in range(int(np.floor((rel.min() - half) / (2 * math.pi))),
                           int(np.ceil((rel.max() + half) / (2 * math.pi))) + 1):
                exits = _crossings(t, rel, 2 * math.pi * n + second)
                for entry in _crossings(t, rel, 2 * math.pi * n + first):
                    later = [x for x in exits if x > entry]
                    if later:
                        events.append({"defect": i, "ball": j, "edge_s": entry, "exit_s": later[0]})
    return sorted(events, key=lambda e: e["edge_s"])


def ball_defect_events(connector, time, q, q_t) -> list:
    """Each ball pit's passages under its ball's two contacts (MODEL.md eq. 13.3): [{"defect":
    index in the surface's defects, "ball": j, "race": "inner" | "outer", "edge_s": the
    contact reaches the pit's first edge on its path, "exit_s": it leaves the second}], in
    time order. From the recorded states (``time`` (T,) s, absolute coordinates and velocities
    (T, 6 n_nodes), e.g. ``handle.States(mbs)``): the pit's centre's distance from the contact
    along its path (:func:`contact.ball_surface.pit_paths`) against half the chord it crosses
    the pit on, interpolated between states."""
    from contact.ball_surface import pit_paths

    surface, record = connector.surface, connector.terms.surface
    pits = [i for i, d in enumerate(surface.defects if surface is not None else ()) if d.race == "ball"]
    if not pits:
        return []
    time = np.asarray(time, dtype=float)
    kin, rot = connector.contact_kinematics(time, q, q_t)
    frames = [v.reshape(len(time), 2, connector.z, 3) for v in (kin.normal, kin.rolling, kin.transverse)]
    events = []
    for row, i in enumerate(pits):  # the record's pit rows follow the surface's ball defects
        j = surface.defects[i].ball
        for k, race in enumerate(("inner", "outer")):
            along, chord = pit_paths(record, rot[:, j], *(f[:, k, j] for f in frames),
                                     connector.bearing.ball_radius)[:, row]
            u = np.where(chord > 0.0, along / np.where(chord > 0.0, 0.5 * chord, 1.0), np.nan)
            events += [{"defect": i, "ball": j, "race": race, "edge_s": a, "exit_s": b}
                       for a, b in _passages(time, u)]
    return sorted(events, key=lambda e: e["edge_s"])


def passages_cut(events, cut_times) -> int:
    """How many of the defect passages ``events`` (dicts with ``edge_s``) are followed by a
    step cut (``cut_times``, s: end times of failed step attempts) before the next passage's
    entry (any defect; the last one's up to the end of the run; MODEL.md §13c). A strike's
    cut falls after its exit, in the ringing it starts (~0.1 ms on the CWRU notch)."""
    cuts = np.sort(np.asarray(cut_times, dtype=float))
    entries = np.sort([float(e["edge_s"]) for e in events])
    # the cuts before each entry and before the end: a passage holds those in between
    return int(np.count_nonzero(np.diff(np.searchsorted(cuts, np.append(entries, np.inf))) > 0))


def _passages(t, u):
    """(entry, exit) times where u (the position over a defect in its half-lengths, NaN off
    its path) passes through [-1, 1]: each crossing of an edge towards the inside enters, one
    towards the outside exits; crossings interpolated linearly between samples."""
    crossings = []
    for level in (-1.0, 1.0):
        s = u - level
        k = np.flatnonzero(np.isfinite(s[:-1]) & np.isfinite(s[1:]) & (np.signbit(s[:-1]) != np.signbit(s[1:])))
        for i in k:
            inward = (u[i + 1] - u[i]) * level < 0.0  # moving from beyond this edge towards the middle
            crossings.append((float(t[i] + (t[i + 1] - t[i]) * s[i] / (s[i] - s[i + 1])), inward))
    crossings.sort()
    return [(a, b) for (a, into), (b, out) in zip(crossings, crossings[1:]) if into and not out]


def _integral(t, rate):
    return np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(t))])


def _crossings(t, x, level):
    s = x - level
    k = np.flatnonzero(np.signbit(s[:-1]) != np.signbit(s[1:]))
    return [float(t[i] + (t[i + 1] - t[i]) * s[i] / (s[i] - s[i + 1])) for i in k]


def read_impacts(connector, events, time, q, q_t, unload_share: float = UNLOAD_SHARE) -> list:
    """The passages ``events`` (:func:`defect_events`, :func:`ball_defect_events`: "edge_s" the
    contact centre reaching the entry edge) as the simulated contact load shows them (MODEL.md
    eq. 13.8), from the recorded states (``time`` (T,) s, absolute coordinates and velocities
    (T, 6 n_nodes): ``handle.States(mbs)``, recorded every step). Each event gains "entry_s"
    (the load has fallen ``unload_share`` below its value before the passage, the median over
    one passage length before the edge: the contact starts to unload; None where it never
    does), "impact_s" (after
    the load's least value, where it rises fastest: the ball strikes the exit side), "peak_N"
    (the greatest load from that least value to one passage length after the exit),
    "load_before_N", and for a race defect "impact_estimate_s" (eq. 13.8's x_i over the
    passage's own speed L / (exit − edge), from "edge_s"; likewise "entry_estimate_s"; the
    ball's two Hertz approaches at "load_before_N").
    "impact_s" and "peak_N" are None where fewer than 3 states fall inside the passage."""
    time = np.asarray(time, dtype=float)
    spans = [(e, max(e["exit_s"] - e["edge_s"], 0.0)) for e in events]
    keep = np.zeros(time.size, dtype=bool)
    for e, span in spans:
        keep |= (time >= e["edge_s"] - span) & (time <= e["exit_s"] + span)
    idx = np.flatnonzero(keep)
    loads = connector.normal_loads(time[idx], q[idx], q_t[idx]) if idx.size else np.zeros((0, 2, connector.z))
    t_kept = time[idx]
    out = []
    for e, span in spans:
        pit = "race" in e  # a ball's pit names the race it passes; a race defect is on its race
        race = e["race"] if pit else connector.surface.defects[e["defect"]].race
        k = 0 if race == "inner" else 1
        rows = (t_kept >= e["edge_s"] - span) & (t_kept <= e["exit_s"] + span)
        out.append({**e, **_read_one(t_kept[rows], loads[rows, k, e["ball"]], e["edge_s"], e["exit_s"], span,
                                     unload_share), "race": race})
        if not pit:
            out[-1].update(_estimate(connector, e, race, out[-1]["load_before_N"], unload_share))
    return out


def _read_one(t, load, edge, exit_, span, share) -> dict:
    """One passage's dynamic marks from its contact's load history (:func:`read_impacts`)."""
    before = load[(t >= edge - span) & (t <= edge)]
    ref = float(np.median(before)) if before.size else math.nan
    out = {"entry_s": None, "impact_s": None, "peak_N": None, "load_before_N": ref}
    inside = np.flatnonzero((t >= edge) & (t <= exit_))
    if inside.size < 3 or not ref > 0:
        return out
    low = int(inside[np.argmin(load[inside])])
    above = np.flatnonzero(load[:low + 1] >= (1.0 - share) * ref)
    if above.size and above[-1] < low:
        i = int(above[-1])
        level = (1.0 - share) * ref
        out["entry_s"] = float(t[i] + (t[i + 1] - t[i]) * (load[i] - level) / (load[i] - load[i + 1]))
    after = np.arange(low, int(np.searchsorted(t, exit_ + span, side="right")))
    if after.size >= 2:
        rate = np.diff(load[after]) / np.diff(t[after])
        m = int(np.argmax(rate))
        out["impact_s"] = float(0.5 * (t[after[m]] + t[after[m + 1]]))
        out["peak_N"] = float(np.max(load[after]))
    return out


def _estimate(connector, event, race, load_before, share) -> dict:
    """Eq. 13.8's geometric entry and impact times of a race-defect passage (:func:`read_impacts`)."""
    bearing, d = connector.bearing, connector.surface.defects[event["defect"]]
    if not load_before > 0:
        return {"entry_estimate_s": None, "impact_estimate_s": None}
    r_x, r_y = (float(v) for v in bearing.curvature_radii(bearing.contact_angle, race))
    x_e, x_i = passage_marks(d.length, d.reach(r_x, r_y), r_x, ball_approach(bearing, load_before), share)
    per_metre = (event["exit_s"] - event["edge_s"]) / d.length
    return {"entry_estimate_s": None if x_e is None else event["edge_s"] + x_e * per_metre,
            "impact_estimate_s": event["edge_s"] + x_i * per_metre}


def impact_summary(events) -> dict:
    """Median entry-to-impact time of the read passages, s, beside eq. 13.8's (from the same
    passages' edges), and the median and largest impact peak, N; None where none was read."""
    read = [e for e in events if e.get("entry_s") is not None and e.get("impact_s") is not None]
    est = [e for e in read if e.get("impact_estimate_s") is not None and e.get("entry_estimate_s") is not None]
    peaks = [e["peak_N"] for e in events if e.get("peak_N") is not None]

    def median(values):
        return float(np.median(values)) if values else None

    return {"passages_read": len(read),
            "entry_to_impact_s": median([e["impact_s"] - e["entry_s"] for e in read]),
            "entry_to_impact_estimate_s": median([e["impact_estimate_s"] - e["entry_estimate_s"] for e in est]),
            "peak_N": median(peaks), "largest_peak_N": max(peaks) if peaks else None}
