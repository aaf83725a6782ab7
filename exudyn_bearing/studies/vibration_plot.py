"""The vibration run's figure (MODEL.md §13b): the housing's signal, its spectrum, the envelope
spectrum with the fault lines and their sidebands, and the kurtogram the band came from."""
from __future__ import annotations

import numpy as np

from .vibration import VibrationResult, amplitude_spectrum, envelope_spectrum

__all__ = ["plot_vibration"]


def plot_vibration(result: VibrationResult, path, title: str = "", envelope_max_hz: float | None = None) -> None:
    """Time signal, spectrum and envelope spectrum with the fault frequencies: kinematic
    (dashed) and actual (solid), BPFO/BPFI and their first harmonics, 2 BSF, FTF, and the
    sidebands a diagnostician looks for (dotted: BPFI ± the shaft, 2 BSF ± FTF, of the actual
    frequencies); the envelope spectrum up to ``envelope_max_hz`` (default 5 x the highest of
    BPFO, BPFI, 2 BSF); the kurtogram with the chosen band where the band came from it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    settle = float(result.inputs.get("settle", 0.0))
    keep = result.time >= settle
    load = np.array([float(result.inputs.get("radial_force", 0.0)), 0.0, float(result.inputs.get("axial_force", 0.0))])
    x = result.acceleration[keep] @ (load / np.linalg.norm(load))  # along the load, as analysed
    chart = result.kurtogram
    fig, ax = plt.subplots(3 + (chart is not None), 1, figsize=(9, 9 + 3 * (chart is not None)))
    ax[0].plot(result.time[keep], x, lw=0.5)
    ax[0].set(xlabel="t (s)", ylabel="housing acceleration along the load (m/s²)", title=title)
    f, a = amplitude_spectrum(x, result.sample_rate)
    ax[1].semilogy(f, np.maximum(a, 1e-12), lw=0.6)
    ax[1].axvspan(*result.band, color="0.9")
    ax[1].set(xlabel="f (Hz)", ylabel="amplitude (m/s²)", xlim=(0, 0.5 * result.sample_rate))
    fe, ae = envelope_spectrum(x, result.sample_rate, result.band)
    ax[2].plot(fe, ae, lw=0.7, color="k")
    kin = result.fault_frequencies["kinematic"]
    fmax = envelope_max_hz or 5.0 * max(kin["BPFI"], kin["BPFO"], 2.0 * kin["BSF"])
    colors = {"BPFO": "tab:red", "BPFI": "tab:blue", "BSF": "tab:green", "FTF": "tab:orange"}
    for kind, style in (("kinematic", "--"), ("actual", "-")):
        for name, value in result.fault_frequencies[kind].items():
            mult = (2,) if name == "BSF" else (1, 2, 3) if name in ("BPFO", "BPFI") else (1,)
            for m in mult:
                ax[2].axvline(m * value, ls=style, lw=0.8, color=colors[name], alpha=0.8,
                              label=f"{'2 ' if name == 'BSF' else ''}{name} {kind}" if m == mult[0] else None)
    actual, shaft = result.fault_frequencies["actual"], float(result.inputs.get("rpm", 0.0)) / 60.0
    for centre, offset, name in ((actual["BPFI"], shaft, "BPFI ± shaft"), (2.0 * actual["BSF"], actual["FTF"],
                                                                          "2 BSF ± FTF")):
        for k, sign in enumerate((-1.0, 1.0)):
            ax[2].axvline(centre + sign * offset, ls=":", lw=0.8, color="0.4", label=name if k == 0 else None)
    ax[2].set(xlabel="f (Hz)", ylabel="envelope amplitude (m/s²)", xlim=(0, fmax),
              title=f"envelope spectrum, band {result.band[0]:.0f}–{result.band[1]:.0f} Hz")
    ax[2].legend(fontsize=7, ncol=4)
    if chart is not None:
        _plot_kurtogram(ax[3], chart)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _plot_kurtogram(ax, chart) -> None:
    """The kurtogram: spectral kurtosis (eq. 13.9) per level (rows) and band, the chosen band boxed."""
    from matplotlib.patches import Rectangle

    columns = 768  # each level's bands spread over a common frequency grid
    image = np.array([np.asarray(row)[(np.arange(columns) * len(row)) // columns] for row in chart.kurtosis])
    nyquist = 0.5 * chart.sample_rate
    shown = ax.imshow(image, aspect="auto", origin="upper", extent=(0, nyquist, len(chart.levels) - 0.5, -0.5),
                      cmap="viridis", interpolation="nearest")
    ax.set_yticks(range(len(chart.levels)), [f"{level:.1f}" for level in chart.levels])
    row = chart.levels.index(chart.level)
    ax.add_patch(Rectangle((chart.band[0], row - 0.5), chart.band[1] - chart.band[0], 1.0, fill=False, ec="red",
                           lw=1.5))
    ax.set(xlabel="f (Hz)", ylabel="level", title=f"kurtogram (spectral kurtosis, Antoni 2007): band "
           f"{chart.band[0]:.0f}–{chart.band[1]:.0f} Hz, K = {chart.band_kurtosis:.3g}")
    ax.figure.colorbar(shown, ax=ax, label="spectral kurtosis")
