"""MODEL.md §8: a run whose traction coefficient |f|/Q exceeds 0.15 (more than any real oil
transmits) says so, once, as a warning and in its results."""
import math
import warnings

import numpy as np
import pytest

from exudyn_bearing.results.outputs import TractionCoefficientWarning, _traction_coefficient

FIELDS = ("load", "traction_rolling", "traction_transverse", "max_pressure")


def contacts(load, fx, fy):
    shape = np.shape(load)
    c = {k: np.zeros(shape) for k in FIELDS}
    c["load"], c["traction_rolling"], c["traction_transverse"] = (np.asarray(v, dtype=float) for v in (load, fx, fy))
    c["max_pressure"] = np.full(shape, 1.2e9)
    return {"inner": c, "outer": {k: np.zeros(shape) for k in FIELDS}}


def test_coefficient_below_the_limit_is_silent():
    load = np.array([[100.0, 200.0], [150.0, 0.0]])
    fx, fy = 0.1 * load, 0.05 * load  # |f|/Q = sqrt(0.1² + 0.05²) = 0.1118
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mu, text = _traction_coefficient(np.array([0.0, 1e-3]), contacts(load, fx, fy))
    assert mu == pytest.approx(math.hypot(0.1, 0.05), rel=1e-12)
    assert text is None


def test_coefficient_above_the_limit_warns_and_says_where():
    load = np.array([[100.0, 200.0], [150.0, 80.0]])
    fx = 0.05 * load
    fx[1, 1] = 0.3 * 80.0  # ball 1 at the second step: |f|/Q = 0.3
    with pytest.warns(TractionCoefficientWarning, match=r"traction coefficient 0\.3 > 0\.15 .*ball 1, t = 0\.001"):
        mu, text = _traction_coefficient(np.array([0.0, 1e-3]), contacts(load, fx, 0 * load))
    assert mu == pytest.approx(0.3)
    assert "inner race" in text


def test_unloaded_contacts_are_ignored():
    """A contact just leaving the load zone (Q -> 0) with a finite traction is no coefficient."""
    load = np.array([[100.0, 1e-6]])
    fx = np.array([[5.0, 1e-3]])  # 1e-3 / 1e-6 would be 1000
    mu, text = _traction_coefficient(np.array([0.0]), contacts(load, fx, 0 * load))
    assert mu == pytest.approx(0.05) and text is None


@pytest.mark.slow
def test_combined_load_with_the_paper_law_warns():
    """Paper's pure Crook law, 2.2 kN + 2 kN radial (p_max ~1 GPa at the heaviest ball):
    the traction coefficient exceeds 0.15 within the first millisecond."""
    pytest.importorskip("exudyn")
    from contact.ballrace import ContactLaw
    from exudyn_bearing.simulation.runner import simulate

    with pytest.warns(TractionCoefficientWarning):
        run = simulate(axial_force=2200.0, radial_force=2000.0, time=0.001, contact_law=ContactLaw(traction="crook"))
    assert run.details["max_traction_coefficient"] > 0.15
    assert run.results.traction_warning is not None
