"""Masking, stated and switchable (issue 50 item 3, in part; MODEL.md §13b): the noise at its
signal-to-noise ratio and seed, the machine lines at their amplitudes (amplitude modulation's
closed form for the mesh's sidebands), bad input refused by name, and the kurtogram's band and
the fault line found under noise."""
from __future__ import annotations

import math

import numpy as np
import pytest

from exudyn_bearing.studies.masking import Masking
from exudyn_bearing.studies.vibration import amplitude_spectrum, spectral_peaks

FS = 20000.0
T = np.arange(int(FS)) / FS
SHAFT = 29.95


def _signal():
    acc = np.zeros((T.size, 3))
    acc[:, 0] = 2.0 * np.sin(2 * np.pi * 1000.0 * T)  # RMS √2 along x
    return acc


def test_noise_has_its_signal_to_noise_ratio_and_its_seed():
    clean = _signal()
    a = Masking(snr_db=10.0, seed=7).apply(T, clean, (1.0, 0.0, 0.0), SHAFT)
    b = Masking(snr_db=10.0, seed=7).apply(T, clean, (1.0, 0.0, 0.0), SHAFT)
    c = Masking(snr_db=10.0, seed=8).apply(T, clean, (1.0, 0.0, 0.0), SHAFT)
    noise = a - clean
    want = math.sqrt(2.0) / 10.0 ** 0.5  # RMS / 10^(SNR/20)
    assert np.std(noise[:, 0]) == pytest.approx(want, rel=0.02) and np.std(noise[:, 2]) == pytest.approx(want, rel=0.02)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    assert np.array_equal(clean, _signal())  # the recorded signal itself is not changed in place


def test_machine_lines_read_their_amplitudes():
    """Unbalance 0.3 m/s² at the shaft rate; a 23-tooth mesh of 0.5 m/s² modulated 40 % at the
    shaft rate: A (1 + m cos Ωt) cos zΩt has lines A at zΩ and A m / 2 at zΩ ± Ω."""
    out = Masking(unbalance=0.3, mesh_teeth=23, mesh_amplitude=0.5, mesh_modulation=0.4).apply(
        T, np.zeros((T.size, 3)), (1.0, 0.0, 0.0), SHAFT)
    f, a = amplitude_spectrum(out[:, 0], FS)
    lines = {round(hz, 1): amp for hz, amp in spectral_peaks(f, a, 4, min_hz=1.0)}
    for hz, amp in ((SHAFT, 0.3), (23 * SHAFT, 0.5), (22 * SHAFT, 0.1), (24 * SHAFT, 0.1)):
        near = [v for k, v in lines.items() if abs(k - hz) < 0.2]
        assert near and near[0] == pytest.approx(amp, rel=0.01), (hz, lines)
    assert np.allclose(out[:, 1:], 0.0)  # along the given direction only


@pytest.mark.parametrize("kw, name", [(dict(snr_db=float("nan")), "snr_db"), (dict(unbalance=-1.0), "unbalance"),
                                      (dict(mesh_teeth=20), "mesh_amplitude"), (dict(mesh_modulation=1.5), "mesh_modulation"),
                                      (dict(seed=-1), "seed"), (dict(modes=((5000.0, 0.02),)), r"modes\[0\]"),
                                      (dict(modes=((5000.0, 0.0, 1.0),)), r"modes\[0\] damping"),
                                      (dict(modes=((float("nan"), 0.02, 1.0),)), r"modes\[0\] frequency")])
def test_masking_refuses_bad_input_by_name(kw, name):
    with pytest.raises(ValueError, match=f"masking.{name}"):
        Masking(**kw)


@pytest.mark.parametrize("ratio", [0.6, 1.0, 1.5])
def test_a_housing_mode_answers_a_force_as_its_closed_form(ratio):
    """A sine force F0 sin(2π f t) on a mode (f0, ζ, m): after the start has died away its
    acceleration's amplitude is F0 f² / (m √((f0² − f²)² + (2ζ f0 f)²)), on the force's axis only."""
    from exudyn_bearing.studies.masking import mode_acceleration

    f0, zeta, mass, f = 5000.0, 0.03, 4.0, 5000.0 * ratio
    t = np.arange(20000) / 200000.0  # 0.1 s at 200 kHz (band-limited: one line)
    force = np.zeros((t.size, 3))
    force[:, 1] = 50.0 * np.sin(2 * np.pi * f * t)
    acc = mode_acceleration(t, force, f0, zeta, mass)
    late = t > 0.05  # the start's ringing has decayed by e^(-ζ ω0 t) < 1e-20
    want = 50.0 * f * f / (mass * math.sqrt((f0 * f0 - f * f) ** 2 + (2 * zeta * f0 * f) ** 2))
    # (0.05 s is a whole number of periods at each f: √2 RMS is the amplitude)
    assert math.sqrt(2.0 * np.mean(acc[late, 1] ** 2)) == pytest.approx(want, rel=1e-3)
    assert np.allclose(acc[:, [0, 2]], 0.0)


def test_masking_modes_need_the_force():
    with pytest.raises(ValueError, match="masking.modes"):
        Masking(modes=((5000.0, 0.02, 1.0),)).apply(T, _signal(), (1.0, 0.0, 0.0), SHAFT)


def test_masking_is_off_by_default():
    assert not Masking().active and Masking(snr_db=20.0).active and Masking(modes=((5000.0, 0.02, 1.0),)).active


@pytest.mark.slow
def test_under_noise_the_kurtogram_still_finds_the_notch():
    """The Case Western notch (0.15 s) with noise at 0 dB and a 0.5-m/s² unbalance line: the band
    the kurtogram chooses still gives BPFO as the strongest envelope line."""
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import CWRU_6205_BEARING
    from exudyn_bearing.studies.vibration import vibration

    r = vibration(CWRU_6205_BEARING, rpm=1797, radial_force=300.0, time=0.15,
                  surface=SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),)),
                  masking=Masking(snr_db=0.0, unbalance=0.5, seed=3))
    assert r.band_from == "kurtogram"
    assert r.envelope_peaks[0][0] == pytest.approx(r.fault_frequencies["actual"]["BPFO"], abs=0.5)
    assert "masking" in r.inputs


def test_fluctuation_is_a_band_limited_process_of_its_rms_and_seed():
    """x(t) = √(2/N) Σ cos(2π f_k t + φ_k): unit RMS over a long run (to a few %), nothing above
    the bandwidth, the same seed the same process, speed and load drawn apart."""
    from exudyn_bearing.studies.masking import Fluctuation

    f = Fluctuation(speed_percent=2.0, load_percent=5.0, bandwidth_hz=5.0, components=64, seed=4)
    t = np.arange(0.0, 200.0, 0.01)
    x = np.array([f.process("speed")(v) for v in t])
    assert np.sqrt(np.mean(x * x)) == pytest.approx(1.0, rel=0.05)
    freq, amp = amplitude_spectrum(x, 100.0)
    assert np.max(amp[freq > 6.0]) < 0.01 * np.max(amp)
    assert Fluctuation(seed=4, speed_percent=1.0, components=64).process("speed")(1.23) == f.process("speed")(1.23)
    assert f.process("load")(1.23) != f.process("speed")(1.23)
    rpm = f.speed(1800.0)
    assert rpm(0.7) == pytest.approx(1800.0 * (1 + 0.02 * f.process("speed")(0.7)))
    assert Fluctuation().speed(1800.0) == 1800.0 and f.load(0.0) == 0.0  # none: the steady value itself
    with pytest.raises(ValueError, match="fluctuation.bandwidth_hz"):
        Fluctuation(bandwidth_hz=0.0)
    with pytest.raises(ValueError, match="below 30"):
        Fluctuation(speed_percent=40.0)


@pytest.mark.slow
def test_speed_fluctuation_makes_the_passages_jitter():
    """The Case Western notch, 0.3 s, with the shaft speed fluctuating by 3 % RMS below 20 Hz:
    the spacing of successive passages of one ball spreads well beyond the steady run's, as the
    cage follows the shaft (the model's own random slip)."""
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import CWRU_6205_BEARING
    from exudyn_bearing.studies.masking import Fluctuation
    from exudyn_bearing.studies.vibration import vibration

    notch = SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),))

    def spread(r):
        edges = np.sort([e["edge_s"] for e in r.defect_events])
        gaps = np.diff(edges)
        return float(np.std(gaps) / np.mean(gaps))

    kw = dict(rpm=1797, radial_force=300.0, time=0.3, surface=notch, band=None)
    steady = vibration(CWRU_6205_BEARING, **kw)
    varying = vibration(CWRU_6205_BEARING, fluctuation=Fluctuation(speed_percent=3.0, bandwidth_hz=20.0, seed=1), **kw)
    assert spread(varying) > 5 * spread(steady), (spread(varying), spread(steady))
    assert "fluctuation" in varying.inputs


@pytest.mark.parametrize("kw, name", [(dict(speed_percent=-1.0), "fluctuation.speed_percent"),
                                      (dict(load_percent=float("inf")), "fluctuation.load_percent"),
                                      (dict(components=0), "fluctuation.components")])
def test_fluctuation_refuses_bad_input_by_name(kw, name):
    from exudyn_bearing.studies.masking import Fluctuation

    with pytest.raises(ValueError, match=name):
        Fluctuation(**kw)


@pytest.mark.slow
def test_a_housing_mode_shows_in_the_run_at_its_frequency_and_height():
    """The Case Western notch (0.1 s) with a 6-kHz mode (ζ 0.03, 3 kg) between the seat and the
    sensor: what it adds to the recorded acceleration, over the bearing's force on the housing
    (read from the modelled housing's motion, F = m a + c v + k x), peaks at 6 kHz at
    1 / (2 ζ m) within 10 % (a Welch estimate H1 = S_Fa / S_FF)."""
    from scipy.signal import csd, welch

    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import CWRU_6205_BEARING
    from exudyn_bearing.races import HousingModel
    from exudyn_bearing.studies.vibration import vibration

    kw = dict(rpm=1797, radial_force=300.0, time=0.1, surface=SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),)),
              band=None, housing=HousingModel(frequency=3000.0, mass=2.0, damping_ratio=0.05))
    clean = vibration(CWRU_6205_BEARING, **kw)
    mode = vibration(CWRU_6205_BEARING, masking=Masking(modes=((6000.0, 0.03, 3.0),)), **kw)
    k, m = 2.0 * (2 * math.pi * 3000.0) ** 2, 2.0  # the housing as given, typed in here
    c = 2 * 0.05 * math.sqrt(k * m)
    force = m * clean.acceleration[:, 0] + c * clean.velocity[:, 0] + k * clean.displacement[:, 0]
    added = mode.acceleration[:, 0] - clean.acceleration[:, 0]
    f, s_ff = welch(force, fs=clean.sample_rate, nperseg=512)
    _, s_fa = csd(force, added, fs=clean.sample_rate, nperseg=512)
    h = np.abs(s_fa / s_ff)
    i = int(np.argmax(h * (f > 1000)))
    assert f[i] == pytest.approx(6000.0, abs=2 * (f[1] - f[0]))
    assert h[i] == pytest.approx(1.0 / (2 * 0.03 * 3.0), rel=0.1)
