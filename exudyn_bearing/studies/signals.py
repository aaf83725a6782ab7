"""The signal primitives of the vibration and diagnostics studies (MODEL.md §13b): a sensor's
signal as a data-acquisition system samples it, its amplitude spectrum and spectral peaks, a
checked pass band, the band-pass and the envelope spectrum. Each takes any sampled signal
(SI units: s, Hz, the signal's own unit)."""
from __future__ import annotations

import math

import numpy as np

__all__ = ["ANTI_ALIAS_CORNER", "amplitude_spectrum", "sampled_signal", "check_band", "bandpass", "envelope_spectrum",
           "spectral_peaks"]

#: corner of the anti-aliasing low-pass as a fraction of the sample rate (a data-acquisition
#: system's sits at 0.4-0.45: flat below, ~30 dB down at the Nyquist frequency)
ANTI_ALIAS_CORNER = 0.4


def amplitude_spectrum(signal, sample_rate: float):
    """(frequencies Hz, amplitude) of a real signal: Hann window, scaled so that a sine of
    amplitude A at a bin frequency reads A."""
    x = np.asarray(signal, dtype=float)
    x = x - np.mean(x)
    win = np.hanning(len(x))
    amp = 2.0 * np.abs(np.fft.rfft(x * win)) / np.sum(win)
    return np.fft.rfftfreq(len(x), 1.0 / sample_rate), amp


def sampled_signal(times, values, sample_rate: float, step: float | None = None):
    """A sensor's signal as a data-acquisition system records it at ``sample_rate`` Hz
    (MODEL.md §13b): ``values`` (rows at the solver's step ends ``times``, s; a cut step
    shifts them off any grid) interpolated by a cubic spline onto a uniform grid at the
    whole multiple m of ``sample_rate`` nearest the rate of ``step`` (s; default the median
    step, a run's finest where it steps finer near defect passages), low-passed at
    :data:`ANTI_ALIAS_CORNER` × ``sample_rate`` (8th-order Butterworth, forward and backward)
    and taken at every m-th point. Sampling the steps directly instead aliases the contact
    resonances above the Nyquist frequency into the band below it, more of them the finer
    the step. Returns (t s, samples) from t = 0 to the last step end."""
    from scipy.interpolate import CubicSpline
    from scipy.signal import butter, sosfiltfilt

    times, keep = np.unique(np.asarray(times, dtype=float), return_index=True)
    values = np.asarray(values, dtype=float)[keep]
    if times.size < 4:
        raise ValueError(f"sampled_signal: need at least 4 samples, got {times.size}")
    if not np.all(np.isfinite(values)):
        raise ValueError("sampled_signal: values hold NaN or inf (a diverged run?)")
    if not (math.isfinite(sample_rate) and sample_rate > 0):
        raise ValueError(f"sample_rate must be positive, got {sample_rate!r}")
    m = max(1, int(round(1.0 / (sample_rate * (step or float(np.median(np.diff(times))))))))
    fine = np.arange(int(math.floor(times[-1] * sample_rate * m + 1e-6)) + 1) / (sample_rate * m)
    x = CubicSpline(times, values, axis=0)(fine)
    sos = butter(8, ANTI_ALIAS_CORNER * sample_rate, fs=sample_rate * m, output="sos")
    return fine[::m], sosfiltfilt(sos, x, axis=0)[::m]


def check_band(band, sample_rate: float, name: str = "band") -> tuple:
    """(low, high) Hz of a pass band ``band``, refused under ``name`` unless 0 < low < high < the
    Nyquist frequency of ``sample_rate`` Hz (a reversed band with its own message)."""
    low, high = (float(v) for v in band)
    nyquist = 0.5 * sample_rate
    if low >= high:
        raise ValueError(f"{name}: the low edge {low:g} Hz is not below the high edge {high:g} Hz (reversed?); "
                         "give LOW then HIGH")
    if not 0 < low < high < nyquist:
        raise ValueError(f"{name}: ({low}, {high}) Hz must lie inside (0, {nyquist:g}) Hz, the Nyquist frequency")
    return low, high


def bandpass(signal, sample_rate: float, band: tuple):
    """``signal`` (sampled at ``sample_rate`` Hz) band-passed to ``band`` = (low, high) Hz, a
    checked band (:func:`check_band`): 4th-order Butterworth, forward and backward (no phase
    shift)."""
    from scipy.signal import butter, sosfiltfilt

    sos = butter(4, [band[0], band[1]], btype="bandpass", fs=sample_rate, output="sos")
    return sosfiltfilt(sos, np.asarray(signal, dtype=float))


def envelope_spectrum(signal, sample_rate: float, band: tuple):
    """(frequencies Hz, amplitude) of the envelope: band-pass ``band`` (Hz, 4th-order
    Butterworth, forward and backward), Hilbert envelope, its amplitude spectrum."""
    from scipy.signal import hilbert

    env = np.abs(hilbert(bandpass(signal, sample_rate, check_band(band, sample_rate))))
    return amplitude_spectrum(env, sample_rate)


def spectral_peaks(freq, amp, count: int = 10, min_hz: float = 0.0, max_hz: float = math.inf) -> list:
    """The ``count`` strongest local maxima of a spectrum of :func:`amplitude_spectrum` in
    [min_hz, max_hz], strongest first: [[frequency Hz, amplitude], ...], both interpolated: the
    frequency by a parabola through the three bins' log amplitudes, the amplitude as the
    bin's over the Hann window's response at that offset δ bins, sinc(δ)/(1 − δ²) (a line
    between two bins reads up to 15 % low at its bin; within 0.7 % so)."""
    from scipy.signal import find_peaks

    freq, amp = np.asarray(freq), np.asarray(amp)
    idx, _ = find_peaks(amp)
    idx = idx[(freq[idx] >= min_hz) & (freq[idx] <= max_hz)]
    idx = idx[np.argsort(amp[idx])[::-1][:count]]
    out = []
    df = freq[1] - freq[0]
    for i in idx:  # parabolic interpolation of the peak on the log amplitude (Hann window)
        a, b, c = np.log(np.maximum(amp[i - 1:i + 2], 1e-300))
        shift = 0.5 * (a - c) / (a - 2 * b + c) if a - 2 * b + c != 0 else 0.0
        window = np.sinc(shift) / (1.0 - shift * shift)
        out.append([float(freq[i] + shift * df), float(amp[i] / window)])
    return out
