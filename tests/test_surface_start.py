"""The start with surfaces (exudyn_bearing/solvers/surface_start.py, MODEL.md §13d) on defects
deeper than a ball's approach, where the perfect start's forces cannot be carried (issue 49,
item 5), and the package's warnings in one line."""
from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from contact.surface import Defect, SurfaceModel  # noqa: E402
from exudyn_bearing import NumpyPathWarning, SurfaceStartWarning, races  # noqa: E402
from exudyn_bearing.bearingfile import BearingFile, save_bearing  # noqa: E402
from exudyn_bearing.presets import CWRU_6205_BEARING  # noqa: E402
from exudyn_bearing.races import HousingModel  # noqa: E402

#: a 2-mm, 20-um outer-race spall under ball 0 of the Case Western 6205 (its approach ~ 3 um)
SPALL = SurfaceModel((Defect("outer", 0.0, 2e-3, 20e-6),))


def _spall_scene(**kw):
    mbs = exu.SystemContainer().AddSystem()
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        h = mbs.CreateAngularContactBearing(CWRU_6205_BEARING, innerRace=races.Driven(1797), radialForce=300.0,
                                            outerRace=HousingModel().race(), surface=SPALL, show=False, **kw)
    return mbs, h, said


def test_a_ball_over_a_deep_spall_starts_placed_not_from_the_perfect_state():
    """Ball 0 over a spall 7x deeper than its approach sinks into it: from the pure-rolling
    start the forces along the moved directions at t = 0 (read back from the model's initial
    coordinates, with and without the surface) are within 1 % of what the perfect placement
    leaves, and the one warning names the ball that holds the rest. (From the quasi-dynamic
    start, 'auto' since session 41, the placement converges: below.)"""
    mbs, h, said = _spall_scene(initialState="rolling")
    con = h.connector
    info = con.surface_start
    assert info["placed"] and not info["converged"]
    named = [w for w in said if issubclass(w.category, SurfaceStartWarning)]
    assert len(named) == 1 and "ball 0" in str(named[0].message)
    q = con.reference + np.concatenate([mbs.GetNodeParameter(n, "initialCoordinates") for n in h.nodeNumbers])
    qt = np.concatenate([mbs.GetNodeParameter(n, "initialVelocities") for n in h.nodeNumbers])
    moved = q.copy()
    for slot, move in info["moves"].items():
        moved[6 * slot:6 * slot + 3] -= move  # back to the perfect placement
    ball = con.layout["balls"][0]
    rows = slice(6 * ball, 6 * ball + 3)
    perfect = con.numpy_forces(0.0, moved[None], qt[None], surface=False)[0][rows]
    unplaced = con.numpy_forces(0.0, moved[None], qt[None], surface=True)[0][rows] - perfect
    placed = con.numpy_forces(0.0, q[None], qt[None], surface=True)[0][rows] - perfect
    radial = np.array([1.0, 0.0, 0.0])  # ball 0 sits on the bearing frame's x axis
    axial = con.axis
    left = [abs(placed @ d) for d in (radial, axial)]
    before = max(abs(unplaced @ d) for d in (radial, axial))
    assert before > 50.0  # the perfect placement leaves ball 0 on one contact
    assert max(left) < 0.01 * before


def test_from_the_balanced_start_the_ball_over_the_spall_is_placed_unloaded():
    """From the quasi-dynamic start ('auto': every ball in its own balance, MODEL.md §12a) the
    perfect state's forces on the balls are their orbits' own, and over the 20-um spall they
    can be kept: ball 0 sinks by more than its approach and carries almost nothing (its inner
    contact open), the inner race drops towards the load and the other balls take it. The
    placement converges to 1e-3 N, and the model's initial state has those forces."""
    mbs, h, _said = _spall_scene()
    con = h.connector
    info = con.surface_start
    assert info["converged"] and info["residual_N"] <= 1e-3
    q = con.reference + np.concatenate([mbs.GetNodeParameter(n, "initialCoordinates") for n in h.nodeNumbers])
    qt = np.concatenate([mbs.GetNodeParameter(n, "initialVelocities") for n in h.nodeNumbers])
    ball = con.layout["balls"][0]
    assert info["moves"][ball][0] > 3.2e-6  # outwards along the load, by more than the ~3.2-um approach
    s = con.states(np.zeros(1), q[None], qt[None])
    loads = s.inner_forces.normal_load[0]
    assert loads[0] < 0.01 * np.max(loads) and np.max(loads) > 50.0


def test_the_packages_warnings_print_in_one_line():
    for category in (SurfaceStartWarning, NumpyPathWarning):
        text = warnings.formatwarning("something", category, "/somewhere/x.py", 12, "source line")
        assert text == f"exudyn-bearing: {category.__name__}: something\n"
    other = warnings.formatwarning("something", UserWarning, "/somewhere/x.py", 12, "source line")
    assert "x.py:12" in other  # Python's own format for everyone else's


def test_the_vibration_command_says_the_surface_start_once(tmp_path):
    path = tmp_path / "spall.toml"
    save_bearing(BearingFile(CWRU_6205_BEARING, surface=SPALL), path)
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "vibration", "--bearing", str(path), "--rpm", "1797",
                           "--radial", "300", "--time", "0.004", "--settle", "0", "--out", str(tmp_path / "vib")],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    text = proc.stdout + proc.stderr
    assert text.count("surface start") == 1 and "bodies placed, moved by up to" in text
    assert ".py:" not in text  # no file and line of a warning
    # the defect's outline and reach: 20 um over the 6205's largest outer approach (~3.2 um)
    assert "2 mm long, across the whole track (no width given), 20 um deep; a ball reaches 20 um of it, 6.2 x" in text
