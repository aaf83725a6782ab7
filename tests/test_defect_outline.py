"""Defects in both directions (MODEL.md eq. 13.2, 13.2b, 13.2c; issue 49 item 1): the ball sinks
into a race defect until it rests on the outline's edges, along the rolling direction (its
reduced radius R_x) and across the groove (R_y = f D / (2 f − 1)). Closed forms derived here:
a sphere of radius R between two edges a gap 2u apart sinks s(u) = R − √(R² − u²); a
paraboloid x²/(2 R_x) + y²/(2 R_y) centred in an ellipse of semi-axes a, b touches its rim
first where the sag is least, min(a²/(2 R_x), b²/(2 R_y))."""
from __future__ import annotations

import math

import numpy as np
import pytest

from contact.surface import Defect, SurfaceModel, race_height, surface_record
from exudyn_bearing.presets import CWRU_6205_BEARING as B

R = 0.5 * B.ball_diameter
F_D = B.outer_conformity * B.ball_diameter
R_X = R * (B.pitch_diameter + B.ball_diameter * math.cos(B.contact_angle)) / B.pitch_diameter  # outer race
R_Y = F_D / (2.0 * B.outer_conformity - 1.0)
RHO = 0.5 * B.pitch_diameter + R * math.cos(B.contact_angle)  # the contact point's radius
DEEP = 0.3e-3


def _s(u, radius):
    return radius - math.sqrt(radius * radius - u * u)


def _drop(defect, along=0.0, across=0.0):
    """(drop m, d drop/d(arc along) ) of the outer contact at ``along`` m from the defect's
    centre and ``across`` m off its centre line (as a change of contact angle)."""
    rec = surface_record(SurfaceModel((defect,)), B)
    h, dh = race_height(rec, 1, along / RHO, B.contact_angle + across / F_D, RHO, 0, R_X)
    return -h, -dh / RHO


def test_radii_of_the_6205_outer_contact():
    assert R_X == pytest.approx(4.777e-3, rel=1e-3) and R_Y > 10 * R_X


@pytest.mark.parametrize("length, width", [(5e-3, 0.1e-3), (0.2e-3, 5e-3), (0.4e-3, 0.6e-3)])
def test_a_rectangle_is_bridged_by_the_smaller_of_its_two_directions(length, width):
    """A long narrow groove (5 mm x 0.1 mm: the ball bridges it across, 0.015 um), a short wide
    notch (0.2 x 5 mm: along, 1.05 um) and one between: at the centre the ball sinks by the
    smaller of s(L/2) along R_x and s(W/2) across R_y."""
    drop, _ = _drop(Defect("outer", 0.0, length, DEEP, width=width))
    assert drop == pytest.approx(min(DEEP, _s(0.5 * length, R_X), _s(0.5 * width, R_Y)), rel=1e-12)


def test_without_a_width_a_rectangle_crosses_the_track():
    drop, _ = _drop(Defect("outer", 0.0, 0.2e-3, DEEP), across=0.5e-3)
    assert drop == pytest.approx(_s(0.1e-3, R_X), rel=1e-12)


def test_off_the_centre_line_the_nearer_side_edge_holds_the_ball():
    drop, slope = _drop(Defect("outer", 0.0, 5e-3, DEEP, width=1e-3), across=0.3e-3)
    assert drop == pytest.approx(_s(0.2e-3, R_Y), rel=1e-9) and slope == 0.0
    assert _drop(Defect("outer", 0.0, 5e-3, DEEP, width=1e-3), across=0.6e-3)[0] == 0.0  # outside


def test_a_round_pit_narrower_than_the_contact_is_bridged():
    """The Case Western 0.18-mm EDM pit, round: 0.049 um at its centre (across: R_y), where the
    full-track notch of the same length gave 0.85 um (along: R_x)."""
    pit, _ = _drop(Defect("outer", 0.0, 0.18e-3, DEEP, shape="ellipse"))
    assert pit == pytest.approx(min(0.09e-3 ** 2 / (2 * R_X), 0.09e-3 ** 2 / (2 * R_Y)), rel=1e-9)
    assert pit == pytest.approx(0.0486e-6, rel=1e-2)
    notch, _ = _drop(Defect("outer", 0.0, 0.18e-3, DEEP))
    assert notch == pytest.approx(_s(0.09e-3, R_X), rel=1e-12) and notch > 15 * pit


@pytest.mark.parametrize("along, across", [(0.2e-3, 0.0), (0.5e-3, 0.1e-3), (-0.7e-3, -0.2e-3)])
def test_an_elliptical_pit_holds_the_ball_at_its_lowest_rim_point(along, across):
    """Off the centre, against a brute-force minimum over 2 million rim points, and the slope
    along the rolling direction against a difference quotient."""
    a, b = 1.0e-3, 0.4e-3
    d = Defect("outer", 0.0, 2 * a, DEEP, width=2 * b, shape="ellipse")
    drop, slope = _drop(d, along, across)
    t = np.linspace(0.0, 2.0 * np.pi, 2_000_001)
    brute = np.min((a * np.cos(t) - along) ** 2 / (2 * R_X) + (b * np.sin(t) - across) ** 2 / (2 * R_Y))
    assert drop == pytest.approx(brute, rel=1e-9)
    eps = 1e-9
    assert slope == pytest.approx((_drop(d, along + eps, across)[0] - drop) / eps, rel=1e-4)


def test_the_reach_is_the_centres_drop():
    for d in (Defect("outer", 0.0, 0.4e-3, DEEP, width=0.6e-3), Defect("outer", 0.0, 0.18e-3, DEEP, shape="ellipse"),
              Defect("outer", 0.0, 2e-3, 20e-6)):
        assert d.reach(R_X, R_Y) == pytest.approx(_drop(d)[0], rel=1e-12)


def test_bad_shapes_are_refused_by_name():
    with pytest.raises(ValueError, match="defect.shape"):
        Defect("outer", 0.0, 1e-3, 1e-6, shape="circle")
    with pytest.raises(ValueError, match="defect.shape"):
        Defect("ball", 0.0, 1e-3, 1e-6, ball=0, shape="ellipse")
    with pytest.raises(ValueError, match="defect.edge"):  # an edge ramp the ellipse would not use
        Defect("outer", 0.0, 1e-3, 1e-6, edge=0.1e-3, shape="ellipse")


def test_the_shape_reaches_the_file_and_the_vibration_command(tmp_path):
    """The bearing file keeps the shape; the vibration command states the round pit's outline
    and that a ball reaches 0.049 um of it."""
    import subprocess
    import sys

    from exudyn_bearing.bearingfile import BearingFile, load_bearing, save_bearing

    setup = BearingFile(B, surface=SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3, shape="ellipse"),)))
    path = tmp_path / "pit.toml"
    save_bearing(setup, path)
    assert load_bearing(path).surface == setup.surface
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "vibration", "--bearing", str(path), "--rpm", "1797",
                           "--radial", "300", "--time", "0.004", "--settle", "0", "--out", str(tmp_path / "vib")],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "a round pit 0.18 mm across, 280 um deep; a ball reaches 0.0486 um of it" in proc.stdout
