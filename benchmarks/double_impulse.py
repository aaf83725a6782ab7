"""Study, not a feature (issue 50 item 2, not built; docs/DEVELOPMENT.md): a spall's length from
the vibration signal alone by its double impulse (after Sawalhi & Randall 2011): the ball's entry into the spall (a gradual unloading: low
frequencies) and its strike on the exit edge (an impulse: high frequencies) come a time Δt
apart; Δt read from the signal, converted to a length with the run's actual contact speed and
eq. 13.8's offsets.

Steps: the signal is pre-whitened (its spectrum's magnitude set to one: the discrete lines
and the housing's resonance no longer dominate, every band's impulses show); the strikes are
the maxima of the squared envelope of a high band, one per fault period; the squared envelope
of a low band is averaged over the passages aligned at their strikes; the entry is the
earliest peak of that average, within half a period before the strike, that reaches half its
largest value.
"""
from __future__ import annotations

import math

import numpy as np

from contact.defect_passage import UNLOAD_SHARE, passage_marks


#: the band in which the entry's unloading shows, Hz (studied on 1–3-mm spalls, docs/DEVELOPMENT.md)
LOW_BAND_HZ = (200.0, 2000.0)
#: the strikes' band as shares of the sample rate: up to just below the anti-aliasing corner
HIGH_BAND_SHARE = (0.16, 0.38)
#: the share of the averaged low-band envelope's largest value the entry's peak must reach
ENTRY_SHARE = 0.5


def _band_envelope(x, sample_rate, band):
    """Squared Hilbert envelope of ``x`` band-passed to ``band`` Hz (4th-order Butterworth, both ways)."""
    from scipy.signal import butter, hilbert, sosfiltfilt

    sos = butter(4, band, btype="bandpass", fs=sample_rate, output="sos")
    return np.abs(hilbert(sosfiltfilt(sos, x))) ** 2


def double_impulse(signal, sample_rate: float, fault_hz: float, low_band=LOW_BAND_HZ,
                   high_band=None) -> dict:
    """The spacing of a defect's double impulse in ``signal`` (sampled at ``sample_rate`` Hz)
    with passages at ``fault_hz`` (e.g. BPFO read from the envelope spectrum); ``low_band`` Hz
    for the entry, ``high_band`` Hz for the strikes (default :data:`HIGH_BAND_SHARE` of the
    sample rate): {"spacing_s": entry to strike, s (None: no entry found), "strikes": the passages
    averaged, "profile_t_s", "profile": the averaged low-band squared envelope, time from the
    strike}. Raises ValueError where the signal holds fewer than four passages."""
    from scipy.signal import find_peaks

    x = np.asarray(signal, dtype=float)
    period = int(round(sample_rate / fault_hz))
    if not (math.isfinite(fault_hz) and fault_hz > 0) or x.size < 4 * period:
        raise ValueError(f"double_impulse: need at least 4 passages at {fault_hz!r} Hz in {x.size} samples")
    spectrum = np.fft.rfft(x - np.mean(x))
    white = np.fft.irfft(spectrum / np.maximum(np.abs(spectrum), 1e-300), x.size)  # pre-whitened
    high = _band_envelope(white, sample_rate, high_band or tuple(s * sample_rate for s in HIGH_BAND_SHARE))
    low = _band_envelope(white, sample_rate, low_band)
    # the strikes: the first the largest of the first period, each next the largest a quarter
    # period about one period on (the passages' spacing drifts with the slip)
    strikes = [int(np.argmax(high[:period]))]
    while strikes[-1] + period + period // 4 < x.size:
        lo = strikes[-1] + period - period // 4
        strikes.append(lo + int(np.argmax(high[lo:lo + period // 2])))
    before, after = period // 2, period // 10
    rows = [low[s - before:s + after] for s in strikes if s - before >= 0 and s + after <= x.size]
    if len(rows) < 3:
        raise ValueError("double_impulse: fewer than 3 whole passages in the signal")
    profile = np.mean(rows, axis=0)
    lag = (np.arange(profile.size) - before) / sample_rate
    peaks, _ = find_peaks(profile)
    early = [p for p in peaks if lag[p] < -1e-4 and profile[p] >= ENTRY_SHARE * profile.max()]
    return dict(spacing_s=float(-lag[early[0]]) if early else None, strikes=len(rows),
                         profile_t_s=lag, profile=profile)


def spall_length(spacing_s: float, speed: float, rolling_radius: float, approach: float,
                 unload_share: float = UNLOAD_SHARE) -> float:
    """The length L m of a spall whose entry and strike come ``spacing_s`` s apart at the contact's
    ``speed`` over the race m/s: eq. 13.8 inverted, L = v Δt + u + x_e, where x_e is where the
    contact starts to unload and L − u where it is struck (:func:`contact.defect_passage.passage_marks`
    for a ball unloaded over the spall; ``rolling_radius`` R_x m, ``approach`` δ_t m)."""
    x_e, x_i = passage_marks(1.0, 1.0, rolling_radius, approach, unload_share)  # L = 1 m (1 m deep): u = 1 − x_i
    return speed * spacing_s + (1.0 - x_i) + x_e


def main():
    """The 12-ball bearing (the 6205's balls on a 54-mm pitch), 600 rpm, 500 N radial, outer-race
    spalls 1, 2, 3 mm long and 0.5 mm deep, 0.3 s at 50 kHz: the double impulse's spacing read
    from the signal against the contact load's, and the length it gives (about 2 min)."""
    from dataclasses import replace

    from contact.geometry import contact_path_radius
    from contact.defect_passage import series_approach
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import CWRU_6205_BEARING
    from exudyn_bearing.studies.vibration import vibration

    small = replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3)
    rho = contact_path_radius(small.ball_diameter, small.pitch_diameter, small.contact_angle, "outer")
    r_x = float(small.curvature_radii(small.contact_angle, "outer")[0])
    stiffness = [float(small.hertz(small.contact_angle, k).stiffness) for k in ("inner", "outer")]
    print("L mm | spacing from the signal ms | from the contact load ms | eq. 13.8 ms | length from the signal mm")
    for length in (1e-3, 2e-3, 3e-3):
        r = vibration(small, rpm=600, radial_force=500.0, time=0.3, sample_rate=50000.0,
                      surface=SurfaceModel((Defect("outer", 0.0, length, 0.5e-3),)))
        bpfo = r.fault_frequencies["actual"]["BPFO"]
        keep = r.time >= 0.02
        found = double_impulse(r.acceleration[keep, 0], r.sample_rate, bpfo)
        loads = [e["load_before_N"] for e in r.defect_events if e.get("load_before_N")]
        speed = 2 * math.pi * bpfo / small.balls * rho  # the contact's speed over the outer race
        est = spall_length(found["spacing_s"], speed, r_x, series_approach(float(np.median(loads)), *stiffness))
        imp = r.impacts
        print(f"{length * 1e3:g} | {found['spacing_s'] * 1e3:.3f} | {imp['entry_to_impact_s'] * 1e3:.3f} | "
              f"{imp['entry_to_impact_estimate_s'] * 1e3:.3f} | {est * 1e3:.3f} ({100 * (est - length) / length:+.0f} %)",
              flush=True)


if __name__ == "__main__":
    main()
