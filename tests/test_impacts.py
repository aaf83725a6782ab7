"""Impacts from the dynamics (MODEL.md eq. 13.8, issue 49 item 3): the geometric marks against
their derivation, the reading of a contact-load history against a synthetic one whose marks
are known, and the simulated entry-to-impact time against the geometry on notches of three
lengths."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from contact.defect_passage import passage_marks, series_approach
from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING
from exudyn_bearing.studies.passages import _read_one, impact_summary

R_X, DELTA = 4.5e-3, 7.5e-6  # m: an outer contact's rolling radius, a ball's two approaches


def _load(g):
    """Eq. 13.8's quasi-static load share at a drop g: (1 − g/δ_t)^{3/2}, 0 beyond."""
    return np.clip(1.0 - g / DELTA, 0.0, None) ** 1.5


def _path(x, length, reach):
    """The centre's drop over a notch (eq. 13.2, exact circles), x from the entry edge."""
    s = lambda u: R_X - np.sqrt(R_X ** 2 - np.clip(u, 0.0, R_X) ** 2)  # noqa: E731
    return np.where((x > 0) & (x < length), np.minimum(np.minimum(s(x), s(length - x)), reach), 0.0)


def test_series_approach_adds_the_two_hertz_approaches():
    q, k_i, k_o = 150.0, 3.1e10, 2.6e10
    assert series_approach(q, k_i, k_o) == pytest.approx((q / k_i) ** (2 / 3) + (q / k_o) ** (2 / 3), rel=1e-12)
    with pytest.raises(ValueError, match="outer_stiffness"):
        series_approach(q, k_i, 0.0)


@pytest.mark.parametrize("reach", [2e-6, 5e-6])
def test_shallow_defect_marks_are_where_the_quasi_static_load_turns(reach):
    """Below δ_t: x_e where the path's load has lost 5 %, x_i where it rises fastest, both read
    off eq. 13.8's load along a finely sampled eq. 13.2 path."""
    length = 1e-3
    x = np.linspace(0.0, length, 400001)
    q = _load(_path(x, length, reach))
    x_e, x_i = passage_marks(length, reach, R_X, DELTA)
    assert x_e == pytest.approx(x[np.argmax(q < 0.95)], abs=5e-9)
    rate = np.diff(q)
    assert x_i == pytest.approx(x[np.argmax(rate) + 1], abs=5e-8)  # (u* from the parabolic sag: 16 nm)


def test_deep_defect_is_struck_where_the_exit_circle_meets_the_unloaded_ball():
    length, reach = 1.2e-3, 0.3e-3
    x = np.linspace(0.0, length, 400001)
    g = _path(x, length, reach)
    _, x_i = passage_marks(length, reach, R_X, DELTA)
    # the last point of zero load: the exit circle rises back to δ_t there
    zero = np.flatnonzero(_load(g) == 0.0)
    assert x_i == pytest.approx(x[zero[-1]], abs=1e-8)
    with pytest.raises(ValueError, match="approach"):
        passage_marks(length, reach, R_X, -1.0)


def test_reading_a_load_history_finds_its_unloading_and_its_strike():
    """A load at 180 N that falls linearly to 0 from t = 1.0 to 1.2 ms, stays there, and
    jumps back at 1.6 ms with an overshoot to 200 N: entry (5 % lost) at 1.01 ms, impact at
    the jump, the peak 200 N; one state in a hundred."""
    t = np.arange(0.0, 3e-3, 1e-6)
    load = np.interp(t, [0, 1.0e-3, 1.2e-3, 1.6e-3, 1.601e-3, 1.65e-3, 3e-3], [180, 180, 0, 0, 200, 180, 180])
    marks = _read_one(t, load, edge=1.0e-3, exit_=1.8e-3, span=0.8e-3, share=0.05)
    assert marks["entry_s"] == pytest.approx(1.01e-3, abs=1e-9)
    assert marks["impact_s"] == pytest.approx(1.6005e-3, abs=1e-9)
    assert marks["peak_N"] == pytest.approx(200.0) and marks["load_before_N"] == pytest.approx(180.0)
    summary = impact_summary([{**marks, "entry_estimate_s": 1.0e-3, "impact_estimate_s": 1.5e-3}])
    assert summary["entry_to_impact_s"] == pytest.approx(0.5905e-3, abs=1e-9)
    assert summary["entry_to_impact_estimate_s"] == pytest.approx(0.5e-3)


@pytest.mark.slow
def test_simulated_entry_to_impact_follows_the_geometry_on_three_notch_lengths():
    """A 12-ball bearing (the 6205's balls on a 54-mm pitch), 500 N radial, 600 rpm, 0.3-mm
    deep outer notches of 0.8, 1.2 and 1.6 mm: the ball loses its load over each; the median
    entry-to-impact time read from the simulated contact load lies within 5 % of eq. 13.8's,
    grows with the length at the contact's speed, and the peak exceeds the load before."""
    from exudyn_bearing.studies.vibration import vibration

    small = replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3)
    read = []
    for length in (0.8e-3, 1.2e-3, 1.6e-3):
        r = vibration(small, rpm=600, radial_force=500.0, time=0.045, settle=0.01,
                      surface=SurfaceModel((Defect("outer", 0.0, length, 0.3e-3),)))
        imp = r.impacts
        assert imp["passages_read"] >= 2
        assert imp["entry_to_impact_s"] == pytest.approx(imp["entry_to_impact_estimate_s"], rel=0.05)
        e = r.defect_events[0]
        assert imp["peak_N"] > e["load_before_N"]
        read.append((length, imp["entry_to_impact_s"], (e["exit_s"] - e["edge_s"]) / length))
    (l0, t0, per_m), (l1, t1, _), (l2, t2, _) = read
    assert (t1 - t0) == pytest.approx((l1 - l0) * per_m, rel=0.05)
    assert (t2 - t1) == pytest.approx((l2 - l1) * per_m, rel=0.05)
