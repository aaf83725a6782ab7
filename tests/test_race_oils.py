"""Each race's contacts in their own oil (BearingConnector.set_oils; MODEL.md §14b): the
compiled paths equal the numpy path, the inner film follows its oil by the Hamrock–Dowson
exponent, the land's constants follow the land's oil."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

pytest.importorskip("exudyn")

from contact.ballrace import ContactLaw  # noqa: E402
from exudyn_bearing import REFERENCE_LUBRICANT as LUB  # noqa: E402
from exudyn_bearing.cage import CageModel  # noqa: E402
from tests.helpers import _both_paths, _scene  # noqa: E402

HOT = replace(LUB, viscosity=0.5 * LUB.viscosity, temperature_viscosity=1.3 * LUB.temperature_viscosity)
COLD = replace(LUB, viscosity=1.7 * LUB.viscosity)


@pytest.mark.parametrize("kw", [
    dict(axialForce=2200.0, radialForce=2000.0, law=ContactLaw(rolling_resistance=True, thermal_film=True)),
    dict(axialForce=1300.0, cage=CageModel(land_width=0.01)),
], ids=["thermal film, rolling resistance, combined", "land friction"])
def test_compiled_paths_match_numpy_path_with_an_oil_per_race(kw):
    _sc, con, q, qt = _scene(**kw)
    before = _both_paths(con, q, qt)
    con.set_oils(HOT, COLD, HOT)
    single, fast, ref = _both_paths(con, q, qt)
    assert np.max(np.abs(ref - before[2])) > 1e-3 * np.max(np.abs(ref))  # the oils change the forces
    for got in (single, fast):
        for part in (slice(0, 3), slice(3, 6)):
            err = np.max(np.abs(got[:, part] - ref[:, part]))
            assert err < 1e-6 * np.max(np.abs(ref[:, part])), (part, err)


def test_the_inner_film_follows_its_oil_and_the_outer_keeps_its_own():
    """Hamrock–Dowson: h_c ∝ (η0 u)^0.67 at the same load and speed (MODEL.md P17; the
    thermal film factor off), so the inner films scale by (η_hot/η)^0.67 and the outer ones
    do not move; the land's friction and film constants scale with the land's viscosity."""
    _sc, con, q, qt = _scene(axialForce=1300.0, cage=CageModel(land_width=0.01))
    cold = con.evaluate(0.01, q, qt, details=True)
    guide = con.guide
    con.set_oils(HOT, LUB, COLD)
    hot = con.evaluate(0.01, q, qt, details=True)
    loaded = cold.inner_forces.normal_load > 0
    assert loaded.sum() >= 4
    np.testing.assert_allclose(hot.inner_forces.normal_load, cold.inner_forces.normal_load, rtol=0, atol=0)
    np.testing.assert_allclose(hot.inner_forces.film_thickness[loaded] / cold.inner_forces.film_thickness[loaded],
                               0.5 ** 0.67, rtol=1e-12)
    np.testing.assert_array_equal(hot.outer_forces.film_thickness, cold.outer_forces.film_thickness)
    np.testing.assert_allclose([con.guide[4] / guide[4], con.guide[5] / guide[5]], [1.7, 1.7], rtol=1e-12)
    con.set_oils(LUB, LUB)  # back to the setup's oil: the same forces as never changed
    np.testing.assert_array_equal(con.evaluate(0.01, q, qt), _scene(axialForce=1300.0,
                                                                   cage=CageModel(land_width=0.01))[1].evaluate(0.01, q, qt))


def test_set_oils_refuses_what_is_no_lubricant():
    _sc, con, _q, _qt = _scene(axialForce=1300.0)
    with pytest.raises(ValueError, match="outer"):
        con.set_oils(LUB, 0.02)
