"""Headless rendering (issue 5): one frame with the raytracer (no X server needed) and,
where Xvfb is installed, one through the OpenGL renderer under xvfb-run; neither blank."""
import shutil
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("exudyn")
plt = pytest.importorskip("matplotlib.pyplot")

from exudyn_bearing.studies.render import render_run  # noqa: E402


def assert_not_blank(path):
    image = plt.imread(path)[..., :3]
    assert image.shape[0] > 100 and image.shape[1] > 100
    colours = np.unique((image.reshape(-1, 3) * 255).astype(int), axis=0)
    assert len(colours) > 50  # races, balls, arrows: many shades, not a flat background
    assert image.std() > 0.05


def test_raytracer_frame(tmp_path):
    files = render_run(tmp_path, axial_force=2200.0, radial_force=2000.0, time=0.0005, frames=1, backend="raytracer")
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
    files = render_run(tmp_path, axial_force=1300.0, time=0.0004, frames=2, backend="raytracer", size=(400, 300),
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


@pytest.mark.parametrize("mass", [None, 3.0])
def test_race_graphics_are_the_modelled_ring(mass):
    """The drawn inner ring (contour's radial extent and width) has the mass of the race body
    Exudyn integrates: rho pi (r_out^2 - r_in^2) w = m, with the default ring and with a
    user-given mass."""
    import exudyn as exu

    from exudyn_bearing import CreateAngularContactBearing, REFERENCE_BEARING, races
    from exudyn_bearing.results.graphics import _race_contour

    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    brg = CreateAngularContactBearing(mbs, innerRace=races.Driven(rpm=1800, mass=mass), axialForce=1300)
    body_mass = mbs.GetObject(brg.innerRaceBody)["mass"]
    contour = np.array(_race_contour(REFERENCE_BEARING, "inner", mass))
    width = np.ptp(contour[:, 0])
    r_in, r_out = contour[:, 1].min(), contour[:, 1].max()
    drawn = REFERENCE_BEARING.race_material.density * np.pi * (r_out ** 2 - r_in ** 2) * width
    assert drawn == pytest.approx(body_mass, rel=1e-9)
    if mass is not None:
        assert body_mass == pytest.approx(mass)
    # the groove is cut into the ring: its bottom lies f_i D below the groove centre circle
    (r_centre, _), _ = REFERENCE_BEARING.groove_centres()
    inside = contour[np.abs(contour[:, 0]) < 0.25 * width]
    assert inside[:, 1].min() == pytest.approx(r_centre - REFERENCE_BEARING.inner_groove_radius, rel=1e-3)
