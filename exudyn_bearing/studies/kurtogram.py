"""The band to demodulate, chosen from the signal (MODEL.md §13b): spectral kurtosis on the
paving of Antoni's fast kurtogram (J. Antoni, "Fast computation of the kurtogram for the
detection of transient faults", Mech. Syst. Signal Process. 21 (2007) 108–124).

The kurtogram tiles (0, f_s/2) at levels k = 0, 1, 1.6, 2, 2.6, … : level k in 2^k bands, level
k + 0.6 (k + log2 3 − 1) in 3·2^(k−1) bands (the fast kurtogram's 1/3-binary tree). In each band the signal's
complex envelope c (the analytic band signal, shifted to base band and decimated to the band's
width: the band's slice of the spectrum, inverse-transformed) gives the spectral kurtosis

    K = E|c|⁴ / (E|c|²)² − 2,                                                        (13.9)

0 for Gaussian noise, negative for a steady sine (−1), large for a train of impulses ringing a
resonance (Antoni 2006, MSSP 20, 282: its definition for complex envelopes). The band of the
largest K is the one whose envelope carries the impulses. Here each band is a band-pass in the
frequency domain, flat over the band with raised-cosine flanks of a quarter of its width on
either side (the fast kurtogram's quasi-analytic FIR filters replaced by the FFT's, same bands
and overlap; the decimation is the slice's length).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Kurtogram", "kurtogram", "spectral_kurtosis"]


def spectral_kurtosis(envelope) -> float:
    """K = E|c|⁴ / (E|c|²)² − 2 of a complex envelope ``c`` (eq. 13.9); 0 for Gaussian noise."""
    power = np.abs(np.asarray(envelope)) ** 2
    mean = float(np.mean(power))
    return float(np.mean(power * power) / (mean * mean) - 2.0) if mean > 0 else 0.0


@dataclass
class Kurtogram:
    """Spectral kurtosis over the fast kurtogram's bands of a signal (see :func:`kurtogram`)."""

    sample_rate: float  #: Hz
    levels: list  #: the levels, 0, 1, 1.6, 2, … (log2 of the number of bands)
    kurtosis: list = field(repr=False)  #: per level, K of each band from 0 Hz up (eq. 13.9)
    band: tuple = ()  #: the chosen band (low, high), Hz
    band_kurtosis: float = math.nan  #: its K
    level: float = math.nan  #: its level

    def bands(self, level_index: int) -> np.ndarray:
        """(n, 2) edges of the bands of ``levels[level_index]``, Hz."""
        n = len(self.kurtosis[level_index])
        edges = np.arange(n + 1) * 0.5 * self.sample_rate / n
        return np.stack([edges[:-1], edges[1:]], axis=1)


def _level_counts(levels: int) -> list:
    """(level, number of bands) of the fast kurtogram's paving down to ``levels``."""
    out = [(0.0, 1)]
    for k in range(1, levels + 1):
        out.append((float(k), 2 ** k))
        if k < levels:
            out.append((k + math.log2(3.0) - 1.0, 3 * 2 ** (k - 1)))  # 3·2^(k−1) bands: level k + 0.585
    return out


def kurtogram(signal, sample_rate: float, levels: int = 7, min_hz: float = 0.0, max_hz: float | None = None,
              min_width: float = 0.0, min_power_share: float = 0.0) -> Kurtogram:
    """Spectral kurtosis (eq. 13.9) of ``signal`` (sampled at ``sample_rate`` Hz) in every band of
    the fast kurtogram's paving down to ``levels``, and the band of the largest one among those
    inside [``min_hz``, ``max_hz``] (default the Nyquist frequency), at least ``min_width`` Hz
    wide and carrying at least ``min_power_share`` of the signal's power in [min_hz, max_hz]
    (spectral kurtosis does not see amplitude: in a signal without a noise floor, such as a
    simulation's, a band of next to nothing can hold the most impulsive content). Raises
    ValueError when no band qualifies or the signal is too short."""
    x = np.asarray(signal, dtype=float)
    if x.ndim != 1 or x.size < 64:
        raise ValueError(f"kurtogram: need a 1-D signal of at least 64 samples, got shape {x.shape}")
    if not np.all(np.isfinite(x)):
        raise ValueError("kurtogram: the signal holds NaN or inf")
    nyquist = 0.5 * sample_rate
    max_hz = nyquist if max_hz is None else min(max_hz, nyquist)
    spectrum = np.fft.rfft(x - np.mean(x))
    freq = np.fft.rfftfreq(x.size, 1.0 / sample_rate)
    power = np.abs(spectrum) ** 2
    total = float(np.sum(power[(freq >= min_hz) & (freq <= max_hz)]))
    names, table = [], []
    best = (-math.inf, None, None)
    for level, count in _level_counts(levels):
        width = nyquist / count
        row = []
        for i in range(count):
            low, high = i * width, (i + 1) * width
            k = spectral_kurtosis(_band_envelope(spectrum, freq, low, high))
            row.append(k)
            share = float(np.sum(power[(freq >= low) & (freq < high)])) / total if total > 0 else 0.0
            if (low >= min_hz and high <= max_hz * (1 + 1e-12) and width >= min_width and share >= min_power_share
                    and k > best[0]):
                best = (k, (low, high), level)
        names.append(level)
        table.append(row)
    if best[1] is None:
        raise ValueError(f"kurtogram: no band of at least {min_width:g} Hz lies inside [{min_hz:g}, {max_hz:g}] Hz")
    return Kurtogram(float(sample_rate), names, table, best[1], float(best[0]), float(best[2]))


def _band_envelope(spectrum, freq, low, high):
    """The complex envelope of the band [low, high] Hz: its slice of the one-sided spectrum, flat
    inside and falling to zero over a quarter of the width on either side (raised cosine, so
    that neighbouring bands overlap as the fast kurtogram's filters do and a line on an edge
    lies in both), at base band, inverse-transformed (decimated)."""
    width = high - low
    flank = 0.25 * width
    inside = np.flatnonzero((freq > low - flank) & (freq < high + flank))
    if inside.size < 4:
        return np.zeros(1)
    f = freq[inside]
    taper = np.ones(f.size)
    below, above = f < low, f > high
    taper[below] = 0.5 + 0.5 * np.cos(np.pi * (low - f[below]) / flank)
    taper[above] = 0.5 + 0.5 * np.cos(np.pi * (f[above] - high) / flank)
    return np.fft.ifft(spectrum[inside] * taper)
