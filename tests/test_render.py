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


def test_frames_are_labelled_and_animated(tmp_path):
    """Frames spread over the run carry their time (the label strip differs between frames,
    the scenes differ too) and the slip legend (a bar running from green to red at the
    bottom); ``animation`` writes them as a GIF with one image per frame."""
    from PIL import Image

    gif = tmp_path / "run.gif"
    files = render_run(tmp_path, axial=1300.0, time=0.0004, frames=2, backend="raytracer", size=(400, 300),
                       animation=gif)
    frames, anim = files[:2], files[2]
    a, b = (plt.imread(f)[..., :3] for f in frames)
    assert not np.array_equal(a[:22, :190], b[:22, :190])  # "t = ..." labels differ
    assert not np.array_equal(a[30:-40], b[30:-40])  # and so do the scenes
    bar = a[a.shape[0] - 30, 10:210]  # one row through the legend bar
    assert bar[0, 1] > 0.6 and bar[0, 0] < 0.1  # green at 0
    assert bar[-1, 0] > 0.9 and bar[-1, 1] < 0.1  # red at the slip scale
    with Image.open(anim) as image:
        assert image.n_frames == 2
