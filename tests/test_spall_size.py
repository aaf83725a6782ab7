"""A spall's length from the signal alone (issue 50 item 2; MODEL.md eq. 13.10): the double
impulse's reading on synthetic signals of known spacing, the length's inversion of eq. 13.8,
and simulated outer-race spalls of 1, 2 and 3 mm against their true lengths."""
import math

import numpy as np
import pytest

from contact.defect_passage import length_from_spacing, passage_marks
from exudyn_bearing.studies.spall_size import double_impulse

FS = 50000.0


def _ring(t, start, amplitude, freq, decay, rise=0.0):
    """A damped sine from ``start`` s, its amplitude reached over ``rise`` s (a smooth onset)."""
    tau = t - start
    on = tau >= 0
    grow = np.ones_like(t) if rise == 0 else np.clip(tau / rise, 0.0, 1.0)
    return np.where(on, amplitude * grow * np.exp(-np.maximum(tau, 0) / decay) * np.sin(2 * np.pi * freq * tau), 0.0)


def synthetic(spacing, *, entry=True, noise=0.0, seed=1, fault_hz=50.0, time=0.3):
    """Passages at ``fault_hz`` (0.03 % random period jitter): an entry (a 2-kHz ring rising over
    0.1 ms, amplitude 1) ``spacing`` s before each strike (rings at 5 and 12 kHz, amplitude 6 and
    3), a 3010.7-Hz sine of amplitude 2 throughout (a machine line, not a harmonic of the
    passages), and Gaussian noise of rms ``noise``."""
    rng = np.random.default_rng(seed)
    t = np.arange(int(time * FS)) / FS
    x = 2.0 * np.sin(2 * np.pi * 3010.7 * t) + noise * rng.standard_normal(t.size)
    strike = 0.013
    while strike < time:
        if entry:
            x += _ring(t, strike - spacing, 1.0, 2000.0, 1e-3, rise=1e-4)
        x += _ring(t, strike, 6.0, 5000.0, 3e-4) + _ring(t, strike, 3.0, 12000.0, 2e-4)
        strike += (1.0 + 3e-4 * rng.standard_normal()) / fault_hz
    return x


@pytest.mark.parametrize("spacing", [0.8e-3, 2.0e-3, 4.0e-3])
def test_the_spacing_of_a_known_double_impulse_is_read(spacing):
    r = double_impulse(synthetic(spacing), FS, 50.0)
    assert r.passages >= 10
    # the onset within the trailing rms window (50 us) and a sample of the true start
    assert r.spacing_s == pytest.approx(spacing, abs=7e-5)


@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_noise_does_not_move_the_entry(seed):
    # noise of rms 0.3 (the entry's ring 1, the strike's 6), brought down ~4x by the synchronous
    # average of 14 passages; the confirming rms keeps its spikes from being taken for the entry
    r = double_impulse(synthetic(2.0e-3, noise=0.3, seed=seed), FS, 50.0)
    assert r.spacing_s == pytest.approx(2.0e-3, abs=7e-5)


def test_strikes_without_an_entry_give_no_spacing():
    r = double_impulse(synthetic(2.0e-3, entry=False, noise=0.3), FS, 50.0)
    assert r.spacing_s is None and "no entry" in r.message


def test_bad_input_is_refused_by_name():
    x = synthetic(1e-3)
    with pytest.raises(ValueError, match="4 passages"):
        double_impulse(x[:int(0.06 * FS)], FS, 50.0)
    with pytest.raises(ValueError, match="finite"):
        double_impulse(np.r_[x, np.nan], FS, 50.0)
    with pytest.raises(ValueError, match="fault_hz"):
        double_impulse(x, FS, -50.0)
    with pytest.raises(ValueError, match="high_band"):
        double_impulse(x, FS, 50.0, high_band=(8000.0, 30000.0))


@pytest.mark.parametrize("length", [0.3e-3, 1e-3, 3e-3])
def test_the_length_inverts_eq_13_8(length):
    # a spall the ball loses its load over (reach 1 m > the approach): eq. 13.8's marks, then back
    r_x, approach, speed = 4.55e-3, 7.1e-6, 0.83
    x_e, x_i = passage_marks(length, 1.0, r_x, approach)
    assert length_from_spacing((x_i - x_e) / speed, speed, r_x, approach) == pytest.approx(length, rel=1e-12)
    # the closed form: u = sqrt(delta (2 R_x - delta)) before the exit edge where L >= 2u
    u = math.sqrt(approach * (2 * r_x - approach))
    if length >= 2 * u:
        assert x_i == pytest.approx(length - u, rel=1e-12)


def test_the_length_refuses_bad_input_by_name():
    for kwargs, name in (({"spacing": -1e-3}, "spacing"), ({"speed": math.nan}, "speed"),
                         ({"approach": 5e-3}, "approach")):
        args = {"spacing": 1e-3, "speed": 1.0, "rolling_radius": 4.55e-3, "approach": 7e-6, **kwargs}
        with pytest.raises(ValueError, match=name):
            length_from_spacing(**args)


# -- simulated spalls: the length read from the housing signal against the true one ----------

def _twelve_ball():
    from dataclasses import replace

    from exudyn_bearing import CWRU_6205_BEARING

    return replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3)  # the 6205's balls on a 54-mm pitch


@pytest.mark.slow
@pytest.mark.parametrize("length", [1e-3, 2e-3, 3e-3])
def test_simulated_outer_spalls_are_sized_within_15_percent(length):
    """Issue 50 item 2: 12 balls of 7.94 mm, 1200 rpm, 500 N radial, an outer-race spall 0.5 mm
    deep, 0.15 s at 50 kHz (about 25 s): the length read from the signal alone within 15 % of
    the true one, from the run's analysis and from a window starting 3 passages later."""
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing.studies.vibration import vibration

    r = vibration(_twelve_ball(), rpm=1200, radial_force=500.0, time=0.15, sample_rate=50000.0,
                  surface=SurfaceModel((Defect("outer", 0.0, length, 0.5e-3),)))
    size = r.spall_size
    assert size["true_length_m"] == length and size["passages"] >= 8
    assert size["length_m"] == pytest.approx(length, rel=0.15), size
    # the same reading from a later window: the passages' fold, not one passage, sets it
    bpfo = r.fault_frequencies["actual"]["BPFO"]
    later = r.time >= 0.02 + 3.0 / bpfo
    x = r.acceleration[later, 0]  # along the radial load
    spacing = double_impulse(x, r.sample_rate, bpfo).spacing_s
    r_x = float(_twelve_ball().curvature_radii(0.0, "outer")[0])  # deep groove, radial load: 0 deg
    again = length_from_spacing(spacing, size["speed_m_s"], r_x, size["approach_m"])
    assert again == pytest.approx(length, rel=0.15)
    # the dynamic run's own contact load (entry to the fastest rise) agrees with the signal's spacing
    assert size["spacing_s"] == pytest.approx(r.impacts["entry_to_impact_s"], rel=0.3)


@pytest.mark.slow
def test_cli_and_plain_scene_size_the_spall(tmp_path):
    """The other two doors on the 2-mm spall of the test above: ``vibration --json`` from a
    bearing file, and a plain Exudyn scene solved by ``mbs.SolveDynamic`` at the handle's surface
    step whose housing sensor, recorded at 50 kHz by ``sampled_signal``, is read by
    :func:`spall_size` with the run's actual BPFO (about 60 s)."""
    import json
    import subprocess
    import sys

    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing.bearingfile import BearingFile, save_bearing
    from exudyn_bearing.studies.spall_size import spall_size
    from exudyn_bearing.studies.vibration import actual_fault_frequencies
    from tests.helpers import housed_scene_signal

    bearing, length, rpm, fs, end = _twelve_ball(), 2e-3, 1200.0, 50000.0, 0.15
    surface = SurfaceModel((Defect("outer", 0.0, length, 0.5e-3),))
    path = tmp_path / "spall.toml"
    save_bearing(BearingFile(bearing, surface=surface), path)
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "vibration", "--bearing", str(path), "--rpm",
                           str(rpm), "--radial", "500", "--time", str(end), "--sample-rate", str(fs),
                           "--out", str(tmp_path / "o")], capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr
    cli = json.loads((tmp_path / "o" / "vibration.json").read_text())["spall_size"]
    assert cli["length_m"] == pytest.approx(length, rel=0.15) and "spall size from the signal alone" in proc.stdout

    t, x, _, h, mbs = housed_scene_signal(bearing, surface, rpm, 500.0, end, fs)
    results = h.Results(mbs, stride=10)
    bpfo = actual_fault_frequencies(results)["BPFO"]
    scene = spall_size(x[t >= 0.02], fs, bearing, surface, bpfo_hz=bpfo, loads=h.initialLoads)
    assert scene["length_m"] == pytest.approx(length, rel=0.15), scene
