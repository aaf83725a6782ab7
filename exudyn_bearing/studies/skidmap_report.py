"""The skid map's report: its markdown tables and its plot (:class:`~exudyn_bearing.studies.skidmap.SkidMap`)."""
from __future__ import annotations

import math
import threading

from ..criteria import hirano_minimum_axial
from ..results.outputs import settled_label

__all__ = ["skid_map_markdown", "plot_skid_map", "load_plotting"]


def _note(p) -> str:
    """How long point ``p`` ran, and why where it did not settle."""
    length = p.simulated_time if p.simulated_time is not None else p.time
    if p.time is None and p.settled is False:
        return f"not settled after {length:g} s (the cap)"
    if p.time is None and p.settled is None and p.error is None:
        return f"too short to judge at the cap ({length:g} s)"
    return f"{length:g} s simulated" if length is not None else ""


def skid_map_markdown(result) -> str:
    """The points and thresholds of a :class:`~exudyn_bearing.studies.skidmap.SkidMap` as markdown tables."""
    lines = ["| rpm | F_r (N) | F_a (N) | kinematic cage slip (%) | steady state (%) | paper's P19 (%) | "
             "peak ball slip (m/s) | settled | note |",
             "|---:|---:|---:|---:|---:|---:|---:|:---:|---|"]
    for p in sorted(result.points, key=lambda p: (p.rpm, p.radial, p.axial)):
        if p.error:
            lines.append(f"| {p.rpm:g} | {p.radial:g} | {p.axial:g} | – | – | – | – | – | failed: {p.error} |")
        else:
            steady = p.steady_kinematic_cage_slip_percent
            lines.append(f"| {p.rpm:g} | {p.radial:g} | {p.axial:g} | {p.kinematic_cage_slip_percent:.3f} | "
                         f"{'–' if steady is None else f'{steady:.3f}'} | {p.cage_slip_percent:.3f} | "
                         f"{p.peak_ball_slip:.4f} | {settled_label(p.settled)} | {_note(p)} |")
    lines += ["", "| rpm | F_r (N) | min. F_a for kinematic slip < 1 % (N) | bracket (N) | how | "
                  "dynamic at the bracket (%) | Hirano 10 Z F_c (N) | Jones, gyroscopic (N) |",
              "|---:|---:|---:|---|---|---|---:|---:|"]
    for t in result.refined or result.thresholds():
        est = f"{t['minimum_axial']:.0f}" if t["minimum_axial"] is not None else "–"
        bracket = "{:.0f}–{:.0f}".format(*t["bracket"]) if "bracket" in t else "–"
        dyn = "–"
        if "dynamic_slips" in t:
            dyn = "{:.3f} / {:.3f}".format(*t["dynamic_slips"])
            if t["dynamic_minimum_axial"] is not None:
                dyn += f": crossing {t['dynamic_minimum_axial']:.0f} N"
            dyn += "" if t["dynamic_confirms"] else " (NOT confirmed)"
        lines.append(f"| {t['rpm']:g} | {t['radial']:g} | {est} | {bracket} | {t['note']} | {dyn} | "
                     f"{t['hirano_minimum_axial']:.0f} | {t['gyroscopic_minimum_axial']:.0f} |")
    return "\n".join(lines)


def _import_pyplot():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot  # noqa: F401
    except ImportError:
        pass


def load_plotting() -> threading.Thread:
    """Import matplotlib's pyplot on a background thread (started, returned): the map's main
    process only waits while its workers run the points, and the import (~0.3 s) would
    otherwise come after them, before :func:`plot_skid_map` can draw."""
    thread = threading.Thread(target=_import_pyplot, name="load matplotlib", daemon=True)
    thread.start()
    return thread


def plot_skid_map(result, path) -> bool:
    """Kinematic cage slip against axial load per speed (log scale), the 1 % level, the
    thresholds (refined ones with their brackets and the steady states the bisection
    evaluated, through which the threshold's 1 % crossing runs) and Hirano's load where
    it falls in the range; False when matplotlib is missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    loads = [p.axial for p in result.points if p.error is None]
    x_lo, x_hi = (min(loads), max(loads)) if loads else (0.0, 1.0)
    thresholds = {(t["rpm"], t["radial"]): t for t in (result.refined or result.thresholds())}
    hirano_outside = []
    for rpm in sorted({p.rpm for p in result.points}):
        for radial in sorted({p.radial for p in result.points}):
            pts = sorted((p for p in result.points if p.rpm == rpm and p.radial == radial and p.error is None),
                         key=lambda p: p.axial)
            if not pts:
                continue
            # log axis: slips at or below zero (pure rolling within rounding) sit on its floor
            slip = [max(p.kinematic_cage_slip_percent, 1e-3) for p in pts]
            line, = ax.plot([p.axial for p in pts], slip, "o-", label=f"{rpm:g} rpm, F_r {radial:g} N")
            unsettled = [(p.axial, v) for p, v in zip(pts, slip) if p.settled is False]
            if unsettled:
                ax.plot(*zip(*unsettled), "x", color="red", ms=10)
            t = thresholds.get((rpm, radial))
            if t and t["minimum_axial"] is not None:
                if "bracket" in t:
                    ax.axvspan(*t["bracket"], color=line.get_color(), alpha=0.25, lw=0)
                if t.get("steady_curve"):  # what the refined threshold comes from, not the grid's chords
                    ax.plot(*zip(*t["steady_curve"]), "d--", color=line.get_color(), ms=4, lw=0.8,
                            label=f"{rpm:g} rpm: steady state of the bisection")
                ax.axvline(t["minimum_axial"], color=line.get_color(), lw=1)
                ax.annotate(f"{t['minimum_axial']:.0f} N", (t["minimum_axial"], 1.0), xytext=(4, 6),
                            textcoords="offset points", color=line.get_color(), fontsize=8)
            hirano = hirano_minimum_axial(result.bearing, rpm)
            if x_lo <= hirano <= x_hi:
                ax.axvline(hirano, color=line.get_color(), ls=":", lw=1)
            else:
                hirano_outside.append(f"{rpm:g} rpm: {hirano:.0f} N")
    ax.axhline(1.0, color="grey", lw=0.8)
    ax.annotate("1 % (skid threshold)", (x_lo, 1.0), xytext=(2, -11), textcoords="offset points", fontsize=8,
                color="grey")
    ax.set_yscale("log")
    pad = 0.03 * (x_hi - x_lo) if x_hi > x_lo else 0.1 * max(abs(x_lo), 1.0)
    ax.set_xlim(x_lo - pad, x_hi + pad)
    b = result.bearing
    lengths = sorted({p.simulated_time or p.time or 0.0 for p in result.points})
    time = [lengths[0], lengths[-1]] if len(lengths) > 2 else lengths
    ax.set(xlabel="axial load F_a (N)", ylabel="kinematic cage slip (%)",
           title=f"Skid-risk map: Z {b.balls}, D {b.ball_diameter * 1e3:g} mm, d_m {b.pitch_diameter * 1e3:g} mm, "
                 f"free angle {math.degrees(b.contact_angle):.1f}°; {'–'.join(f'{t:g}' for t in time)} s per point")
    ax.title.set_fontsize(9)
    note = "solid line: threshold (band: bracket); dotted: Hirano 10 Z F_c; x: not settled"
    if hirano_outside:
        note += "\nHirano beyond the range: " + ", ".join(hirano_outside)
    ax.text(0.01, 0.01, note, transform=ax.transAxes, fontsize=7, va="bottom")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True
