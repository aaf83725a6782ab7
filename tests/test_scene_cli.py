"""Scene = CLI (issue 50 item 5): the same bearing, defect, housing and step give the same
envelope line through the CLI, the Python API and a plain Exudyn scene solved by
``mbs.SolveDynamic`` with the handle's recommended step and tolerance, within the half-step
error bound the API reports."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING

exu = pytest.importorskip("exudyn")

RPM, FS, T, BAND = 1797.0, 20000.0, 0.15, (1800.0, 4200.0)
NOTCH = SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),))


def _scene_line():
    """The README's scene (``tests.helpers.housed_scene_signal``) read in the CLI's band."""
    from exudyn_bearing.studies.vibration import envelope_spectrum, spectral_peaks
    from tests.helpers import housed_scene_signal

    t, x, step, _, _ = housed_scene_signal(CWRU_6205_BEARING, NOTCH, RPM, 300.0, T, FS)
    f, a = envelope_spectrum(x[t >= 0.02], FS, BAND)
    return spectral_peaks(f, a, 1, min_hz=1.0, max_hz=BAND[1] - BAND[0])[0], step


@pytest.mark.slow
def test_cli_api_and_plain_scene_read_the_same_envelope_line(tmp_path):
    from exudyn_bearing.bearingfile import BearingFile, save_bearing
    from exudyn_bearing.studies.vibration import vibration

    api = vibration(CWRU_6205_BEARING, rpm=RPM, radial_force=300.0, time=T, surface=NOTCH, band=BAND,
                    error_estimate=True)
    f_api, a_api = api.envelope_peaks[0]
    bound = api.error_estimate["envelope_amplitude_bound_percent"] / 100
    path = tmp_path / "cwru.toml"
    save_bearing(BearingFile(CWRU_6205_BEARING, surface=NOTCH), path)
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "vibration", "--bearing", str(path), "--rpm", "1797",
                           "--radial", "300", "--time", str(T), "--band", "1800:4200", "--out", str(tmp_path / "o")],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    f_cli, a_cli = json.loads((tmp_path / "o" / "vibration.json").read_text())["envelope_peaks_Hz"][0]
    (f_scene, a_scene), step = _scene_line()
    assert step == pytest.approx(api.solver["step_s"])
    assert f_cli == pytest.approx(f_api, abs=0.01) and a_cli == pytest.approx(a_api, rel=1e-6)  # the same run
    assert f_scene == pytest.approx(f_api, abs=0.05)
    assert abs(a_scene - a_api) <= bound * a_api, (a_scene, a_api, bound)
