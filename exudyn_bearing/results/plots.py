"""Plots of a bearing run in the style of the paper's figures 5 and 6 (``plot`` extra).

:func:`plot_run` takes the :class:`~exudyn_bearing.results.outputs.BearingResults` of any run
(``handle.Results(mbs)``, ``simulate(...).results``); :func:`plot_skid_curve` a load
sweep. Both return the matplotlib figure and, given a path, save it as PNG. Matplotlib is
imported on call only (headless ``Agg`` backend when saving), so the rest of the package
never needs it.
"""
from __future__ import annotations

import numpy as np

__all__ = ["plot_run", "plot_skid_curve"]


def _pyplot():
    try:
        import matplotlib
    except ImportError:  # pragma: no cover - depends on the installation
        raise ImportError("plots need matplotlib: python -m pip install -e '.[plot]'") from None
    if matplotlib.get_backend().lower() not in ("agg", "pdf", "svg", "cairo"):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _orbit(res, values, mask):
    """Position angles (deg, 0..360) and values of all balls over the masked steps, sorted."""
    psi = np.degrees(np.mod(res.ball_position_angle[mask], 2 * np.pi)).ravel()
    order = np.argsort(psi, kind="stable")
    return psi[order], np.asarray(values)[mask].reshape(psi.size, -1)[order]


def plot_run(res, path=None, title: str | None = None, fraction: float = 0.5):
    """Six panels of one run: cage slip (P19 and kinematic, MODEL.md §7) and ball attitude
    angles against time, and over the orbit (all balls, last ``fraction`` of the run):
    ball angular-velocity components in the orbiting frame (paper fig. 6), ball–race slip
    velocities, contact loads and heat per contact, with the heavily loaded zone (inner
    load above its mean) shaded.

    Parameters
    ----------
    res : BearingResults
    path : str or Path, optional
        Save the figure there (PNG).
    title : str, optional
    fraction : float
        Part of the run at its end used for the orbit panels.
    """
    plt = _pyplot()
    mask = res.last(fraction)
    fig, axes = plt.subplots(3, 2, figsize=(11, 10))
    t_ms = 1e3 * res.time
    ax = axes[0, 0]
    ax.plot(t_ms, res.kinematic_cage_slip_percent, label="kinematic cage slip (MODEL.md §7)")
    ax.plot(t_ms, res.cage_slip_percent, "--", label="paper's P19 cage slip (nominal angle)")
    ax.set(xlabel="time (ms)", ylabel="cage slip (%)")
    ax.legend(fontsize=8)
    ax = axes[0, 1]
    ax.plot(t_ms, np.degrees(res.attitude_xz.mean(axis=1)), label="β_XZ (mean over balls)")
    ax.plot(t_ms, np.degrees(res.attitude_yz.mean(axis=1)), label="β_YZ")
    ax.set(xlabel="time (ms)", ylabel="ball attitude angle (deg)")
    ax.legend(fontsize=8)
    psi, w = _orbit(res, res.ball_omega_orbiting, mask)
    _, loads = _orbit(res, np.stack([res.inner["load"], res.outer["load"]], axis=-1), mask)
    heavy = loads[:, 0] > np.mean(loads[:, 0])
    ax = axes[1, 0]
    for k, name in enumerate(("ω_x (circumferential)", "ω_y (radial)", "ω_z (axial)")):
        ax.plot(psi, w[:, k], ".", ms=2, label=name)
    ax.set(ylabel="ball angular velocity (rad/s)")
    ax.legend(fontsize=8, markerscale=4)
    ax = axes[1, 1]
    _, slip = _orbit(res, np.stack([res.inner["slip"], res.outer["slip"]], axis=-1), mask)
    ax.plot(psi, slip[:, 0], ".", ms=2, label="inner race")
    ax.plot(psi, slip[:, 1], ".", ms=2, label="outer race")
    ax.set(ylabel="ball–race slip velocity (m/s)")
    ax.legend(fontsize=8, markerscale=4)
    ax = axes[2, 0]
    ax.plot(psi, loads[:, 0], ".", ms=2, label="inner")
    ax.plot(psi, loads[:, 1], ".", ms=2, label="outer")
    ax.set(xlabel="ball position angle (deg)", ylabel="contact load (N)")
    ax.legend(fontsize=8, markerscale=4)
    ax = axes[2, 1]
    _, heat = _orbit(res, np.stack([res.inner["heat"], res.outer["heat"]], axis=-1), mask)
    ax.plot(psi, heat[:, 0], ".", ms=2, label="inner")
    ax.plot(psi, heat[:, 1], ".", ms=2, label="outer")
    ax.set(xlabel="ball position angle (deg)", ylabel="heat per contact (W)")
    ax.legend(fontsize=8, markerscale=4)
    if np.ptp(loads[:, 0]) > 0.05 * max(float(np.mean(loads[:, 0])), 1e-9):  # a load zone worth marking
        for ax in axes[1:].ravel():
            ax.fill_between(psi, 0, 1, where=heavy, transform=ax.get_xaxis_transform(), color="orange", alpha=0.12,
                            lw=0)
    span = f"orbit panels: last {1e3 * (res.time[-1] - res.time[mask][0]):.1f} ms"
    fig.suptitle((title + " — " if title else "") + span)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=110)
    return fig


def plot_skid_curve(loads, kinematic_slip, p19_slip, attitude_xz=None, attitude_yz=None, settled=None,
                    path=None, title: str = "cage slip against axial load", reference=None):
    """Paper figure 5: cage slip (kinematic and P19, %) and mean ball attitude angles (deg)
    against axial load (N); unsettled points are marked red. ``reference`` = (label, loads,
    kinematic slip) adds another run's kinematic slip (e.g. another traction law), dotted."""
    plt = _pyplot()
    loads = np.asarray(loads, dtype=float)
    with_angles = attitude_xz is not None
    fig, axes = plt.subplots(1, 2 if with_angles else 1, figsize=(10 if with_angles else 5.5, 4), squeeze=False)
    ax1 = axes[0, 0]
    ax1.plot(loads, kinematic_slip, "o-", label="kinematic cage slip (MODEL.md §7)")
    ax1.plot(loads, p19_slip, "s--", label="paper's P19 cage slip (nominal angle)")
    if reference is not None:
        label, ref_loads, ref_slip = reference
        ax1.plot(ref_loads, ref_slip, "^:", color="grey", label=f"kinematic cage slip, {label}")
        ax1.set_yscale("symlog", linthresh=0.1)  # the two curves part near the 1 % threshold
    ax1.axhline(1.0, color="grey", lw=0.8)
    ax1.set(xlabel="axial load (N)", ylabel="cage slip (%)", title=title)
    ax1.legend(fontsize=8)
    if with_angles:
        ax2 = axes[0, 1]
        ax2.plot(loads, attitude_xz, "o-", label="β_XZ")
        ax2.plot(loads, attitude_yz, "s-", label="β_YZ")
        ax2.set(xlabel="axial load (N)", ylabel="ball attitude angle (deg)")
        ax2.legend(fontsize=8)
    if settled is not None:
        for ax in axes.ravel():
            for load, ok in zip(loads, settled):
                if not ok:
                    ax.axvline(load, color="red", alpha=0.15)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig
