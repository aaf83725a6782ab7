"""The band from the signal (issue 50 item 1; MODEL.md eq. 13.9): spectral kurtosis against its
closed forms, the fast kurtogram's choice on a signal whose impulses ring a resonance under a
stronger sine and noise, and the band as the CLI takes it."""
from __future__ import annotations

import numpy as np
import pytest

from exudyn_bearing.studies.kurtogram import kurtogram, spectral_kurtosis
from exudyn_bearing.studies.vibration import envelope_spectrum, spectral_peaks

FS = 20000.0


def test_spectral_kurtosis_of_noise_a_tone_and_impulses():
    """Complex Gaussian noise: E|c|⁴ = 2 (E|c|²)², K = 0; a steady tone: |c| constant, K = −1;
    one impulse in n samples: K = n − 2."""
    rng = np.random.default_rng(3)
    noise = rng.standard_normal(200000) + 1j * rng.standard_normal(200000)
    assert spectral_kurtosis(noise) == pytest.approx(0.0, abs=0.03)
    assert spectral_kurtosis(np.exp(1j * np.linspace(0, 100, 5000))) == pytest.approx(-1.0, abs=1e-12)
    spike = np.zeros(1000, dtype=complex)
    spike[10] = 1.0
    assert spectral_kurtosis(spike) == pytest.approx(998.0)


def test_kurtogram_finds_the_ringing_band_under_a_stronger_tone():
    """Impulses at 107 Hz ringing a 5-kHz resonance (decay 800/s), Gaussian noise, and a 3-kHz
    sine three times stronger: the band chosen contains 5 kHz and not 3 kHz, and the envelope
    spectrum in it has its strongest line at the impulse rate."""
    rng = np.random.default_rng(1)
    t = np.arange(int(2 * FS)) / FS
    rate = 107.0
    since = (t * rate) % 1.0 / rate
    x = np.exp(-since * 800.0) * np.sin(2 * np.pi * 5000.0 * since)
    x += 3.0 * np.sin(2 * np.pi * 3000.0 * t) + 0.5 * rng.standard_normal(t.size)
    chart = kurtogram(x, FS, min_hz=500.0, max_hz=0.4 * FS, min_width=300.0)
    low, high = chart.band
    assert low <= 5000.0 <= high and not low <= 3000.0 <= high
    assert chart.band_kurtosis > 0.2  # well above noise (0) and the tone's band (about −1)
    f, a = envelope_spectrum(x, FS, chart.band)
    (hz, _), = spectral_peaks(f, a, 1, min_hz=1.0, max_hz=high - low)
    assert hz == pytest.approx(rate, abs=0.1)
    # the paving: level k has 2^k bands, level k + 0.585 has 3·2^(k−1)
    counts = {round(level, 3): len(row) for level, row in zip(chart.levels, chart.kurtosis)}
    assert counts[0.0] == 1 and counts[1.0] == 2 and counts[1.585] == 3 and counts[2.585] == 6 and counts[7.0] == 128


def test_kurtogram_refuses_what_it_cannot_choose():
    with pytest.raises(ValueError, match="no band"):
        kurtogram(np.random.default_rng(0).standard_normal(4000), FS, min_hz=9000.0, max_hz=9500.0, min_width=2000.0)
    with pytest.raises(ValueError, match="NaN"):
        kurtogram(np.full(1000, np.nan), FS)


def test_band_words_of_the_cli():
    from exudyn_bearing.studies.cli import _band

    assert _band(["auto"]) == "auto" and _band(["housing"]) is None
    assert _band(["1800:4200"]) == (1800.0, 4200.0) == _band(["1800", "4200"])
    with pytest.raises(ValueError, match="reversed"):
        _band(["4000", "1000"])
    with pytest.raises(ValueError, match="reversed"):
        envelope_spectrum(np.zeros(100), FS, (4000.0, 1000.0))
    with pytest.raises(ValueError, match="LOW:HIGH"):
        _band(["wide"])
