"""What a run with its thermal network reports (MODEL.md §14g): the node temperatures, where
the heat was made and where it went, and a plot of the temperatures over the run."""
from __future__ import annotations

import numpy as np

from contact.bearing_thermal import NODES

__all__ = ["thermal_summary", "plot_temperatures"]


def thermal_summary(temperatures, mbs, fraction: float = 1 / 3) -> dict:
    """The ``thermal`` record of a run (JSON-ready, units by suffix) from its
    :class:`~exudyn_bearing.model.thermal_nodes.BearingTemperatures`: start and end node
    temperatures; the heat by place and by node and the heat carried off by the oil and to
    the ambient and the heat the nodes stored (sum C dT / dt), time means over the last
    ``fraction`` of the run (their balance checks the integration); the contacts' oils at the end; the
    clearance's change from the start to the end temperatures (the run's contacts follow the
    temperatures at each update, MODEL.md §14f); and the temperatures at every update
    (``history``)."""
    th = temperatures
    time, temps = th.history(mbs)
    ups = th.updates
    start, end = temps[0], temps[-1]
    lo = min(int(np.searchsorted(time, time[-1] - fraction * (time[-1] - time[0]))), len(time) - 2)
    span = time[-1] - time[lo]
    # time means over the window: heat and losses held over each update's period (as the run
    # held them), the heat to the boundaries by the trapezoid over the recorded temperatures
    # with the network in effect, the stored heat from the temperatures' change
    update = th.oils_at(time)
    weights = np.zeros(len(ups))
    removed = dict.fromkeys(ups[0]["removed_W"], 0.0)
    for k in range(lo + 1, len(time)):
        u, dt = ups[update[k]], time[k] - time[k - 1]
        weights[update[k]] += dt / span
        for j in (k - 1, k):
            for name, watts in u["network"].to_boundaries(dict(zip(NODES, temps[j]))).items():
                removed[name] += 0.5 * dt / span * float(watts)

    def mean(key):
        return {k: float(sum(w * u[key][k] for w, u in zip(weights, ups))) for k in ups[-1][key]}

    stored = float(ups[-1]["network"].capacity @ (end - temps[lo]) / span)
    made = float(sum(mean("heat_W").values()))
    end_k = dict(zip(NODES, (float(v) for v in end)))
    oils = dict(zip(("inner", "outer", "land"), th.connector.oils))
    out = {"start": th.start.kind, "update_period_s": th.update_period,
           "start_temperatures_K": dict(zip(NODES, (float(v) for v in start))), "temperatures_K": end_k,
           "temperature_rise_K": {k: float(e - s) for k, s, e in zip(NODES, start, end)},
           "heat_W": mean("heat_W"), "heat_by_place_W": mean("losses_W"), "removed_W": removed,
           "stored_W": stored,
           # made = removed + stored over the window: what the network's integration conserves
           "heat_balance_percent": 100.0 * (made - sum(removed.values()) - stored) / made if made > 0 else 0.0,
           "contact_oil_temperature_K": {k: oil.reference_temperature + 273.15 for k, oil in oils.items()},
           "contact_viscosity_Pa_s": {k: oil.viscosity for k, oil in oils.items()},
           "history": {"time_s": [u["time_s"] for u in ups],
                       "temperatures_K": {k: [u["temperatures_K"][k] for u in ups] for k in NODES}}}
    try:
        out["diametral_clearance_change_m"] = th.clearance_change(end_k)
    except ValueError as err:  # the end temperatures close the clearance
        out["diametral_clearance_change_m"] = None
        out["clearance_warning"] = str(err)
    return out


def plot_temperatures(record: dict, path=None, title: str | None = None):
    """The node temperatures of a run's ``thermal`` record (:func:`thermal_summary`) against
    time, each as its rise from the start (K); saved as PNG at ``path`` if given."""
    from .plots import _pyplot

    plt = _pyplot()
    hist = record["history"]
    t_ms = 1e3 * np.asarray(hist["time_s"])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for node in NODES:
        values = np.asarray(hist["temperatures_K"][node])
        ax.plot(t_ms, values - values[0], label=f"{node.replace('_', ' ')} (from {values[0]:.1f} K)")
    ax.set(xlabel="time (ms)", ylabel="temperature rise (K)",
           title=title or f"thermal network (MODEL.md §14g), start: {record['start']}")
    ax.legend(fontsize=8)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=110)
    return fig
