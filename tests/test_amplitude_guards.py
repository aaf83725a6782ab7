"""Amplitudes guarded (issue 49 item 7): every input that sets an envelope amplitude or an
impact time reaches the model at its own scale — a factor 2 in how the code uses it fails a
test here (or in the test named beside it, docs/DEVELOPMENT.md 'Amplitude guards'):

- housing mass, stiffness, damping: the housing as built is the single-degree-of-freedom
  oscillator of its inputs (here);
- contact damping: the normal load's rate part is ζ of critical at the linearized Hertz
  stiffness and the ball's mass (here; the compiled path equals the numpy one,
  tests/test_contact_records.py);
- the defect's depth and outline: the drop over it (tests/test_surface.py,
  tests/test_defect_outline.py) and the entry-to-impact time (tests/test_impacts.py);
- the peak reading: a sine's line (tests/test_vibration.py) and an envelope's line (here), the
  impact's peak load (tests/test_impacts.py).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from contact.ballrace import ContactLaw, RaceContact, ball_race_forces
from contact.kinematics import ball_race_kinematics
from exudyn_bearing import CWRU_6205_BEARING, REFERENCE_LUBRICANT
from exudyn_bearing.studies.vibration import envelope_spectrum, spectral_peaks

exu = pytest.importorskip("exudyn")


def test_housing_as_built_is_the_oscillator_of_its_inputs():
    """Housing(2500 Hz, 1.5 kg, 8 %): its body weighs 1.5 kg, its support is k = m (2π f)² and
    c = 2 ζ √(k m) in every direction, so it rings at 2500 Hz with 8 % damping."""
    from exudyn_bearing import CreateAngularContactBearing, races

    mbs = exu.SystemContainer().AddSystem()
    h = CreateAngularContactBearing(mbs, CWRU_6205_BEARING, innerRace=races.Driven(1797), radialForce=300.0,
                                    outerRace=races.Housing(frequency=2500.0, mass=1.5, dampingRatio=0.08), show=False)
    spring = mbs.GetObject(h.housingSpring)
    mass = mbs.GetObject(h.outerRaceBody)["mass"]
    k, c = np.asarray(spring["stiffness"]), np.asarray(spring["damping"])
    assert mass == pytest.approx(1.5, rel=1e-12)
    np.testing.assert_allclose(k, 1.5 * (2 * math.pi * 2500.0) ** 2, rtol=1e-12)
    np.testing.assert_allclose(c, 2 * 0.08 * math.sqrt(k[0] * 1.5), rtol=1e-12)
    frequency = math.sqrt(k[0] / mass) / (2 * math.pi)
    assert frequency == pytest.approx(2500.0, rel=1e-12) and c[0] / (2 * math.sqrt(k[0] * mass)) == pytest.approx(0.08)


@pytest.mark.parametrize("ratio", [0.05, 0.3])
def test_contact_damping_is_its_ratio_of_critical(ratio):
    """A ball pressed 4 um into the 6205's outer race and moving into it at 2 mm/s: the load's
    rate part is 2 ζ √(k m) δ̇, k = 3 Q_e / (2 δ) the Hertz law's slope at δ and m the ball's mass."""
    b = CWRU_6205_BEARING
    (_, _), (r_go, z_go) = b.groove_centres()
    tube = (b.outer_conformity - 0.5) * b.ball_diameter
    delta, rate = 4e-6, 2e-3
    centre = np.array([[r_go + tube + delta, 0.0, z_go]])
    moving = np.array([[rate, 0.0, 0.0]])
    params = RaceContact(b.ball_diameter, b.pitch_diameter, np.array([b.outer_conformity]), np.array([1.0]),
                         b.effective_modulus, b.ball_mass)
    loads = []
    for v in (np.zeros((1, 3)), moving):
        kin = ball_race_kinematics(centre, v, np.zeros((1, 3)), np.zeros(3), np.eye(3), np.zeros(3), np.zeros(3),
                                   (r_go, z_go, tube), b.ball_radius, "outer")
        loads.append(float(ball_race_forces(kin, params, REFERENCE_LUBRICANT,
                                            ContactLaw(traction="none", damping_ratio=ratio, compiled=False)).normal_load[0]))
    elastic, damped = loads
    k = 1.5 * elastic / delta
    assert damped - elastic == pytest.approx(2 * ratio * math.sqrt(k * b.ball_mass) * rate, rel=1e-9)


def test_envelope_line_reads_the_modulation_amplitude():
    """A 3-kHz carrier of amplitude 2 m/s² modulated at 1 + 0.4 cos(2π 107 t): its envelope is
    2 (1 + 0.4 cos 2π 107 t), so the envelope spectrum's line at 107 Hz reads 0.8 m/s²."""
    fs = 20000.0
    t = np.arange(int(fs)) / fs
    x = 2.0 * (1 + 0.4 * np.cos(2 * np.pi * 107.0 * t)) * np.sin(2 * np.pi * 3000.0 * t)
    f, a = envelope_spectrum(x, fs, (2000.0, 4000.0))
    (hz, amp), = spectral_peaks(f, a, 1, min_hz=50.0)
    assert hz == pytest.approx(107.0, abs=0.05) and amp == pytest.approx(0.8, rel=0.01)
