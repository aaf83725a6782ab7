"""Headless rendering (issue 5): one frame with the raytracer (no X server needed) and,
where Xvfb is installed, one through the OpenGL renderer under xvfb-run; neither blank."""
import shutil
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("exudyn")
plt = pytest.importorskip("matplotlib.pyplot")

from exudyn_bearing.graphics import render_run  # noqa: E402


def assert_not_blank(path):
    image = plt.imread(path)[..., :3]
    assert image.shape[0] > 100 and image.shape[1] > 100
    colours = np.unique((image.reshape(-1, 3) * 255).astype(int), axis=0)
    assert len(colours) > 50  # races, balls, arrows: many shades, not a flat background
    assert image.std() > 0.05


def test_raytracer_frame(tmp_path):
    files = render_run(tmp_path, axial=2200.0, radial=2000.0, time=0.0005, frames=1, backend="raytracer")
    assert len(files) == 1 and files[0].exists()
    assert_not_blank(files[0])


@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="Xvfb not installed (Debian package xvfb)")
def test_opengl_frame_under_xvfb(tmp_path):
    cmd = ["xvfb-run", "-a", sys.executable, "-m", "exudyn_bearing", "render", "--time", "0.0005", "--frames", "1",
           "--backend", "opengl", "--out", str(tmp_path)]
    subprocess.run(cmd, check=True, timeout=300)
    files = sorted(tmp_path.glob("*.png"))
    assert len(files) == 1
    assert_not_blank(files[0])
