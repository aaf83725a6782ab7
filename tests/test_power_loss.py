"""Power loss by source (BearingResults.power_loss, MODEL.md §11) against the energy balance
and closed forms: in a settled run the races' drive power equals the sum of all losses."""
import math

import numpy as np
import pytest

from contact.ballrace import ContactLaw
from exudyn_bearing import REFERENCE_BEARING as B, simulate
from exudyn_bearing.bearing import BallDrag
from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG

OIL_DENSITY = 860.0  # reference oil, kg/m^3 (MODEL.md §8), written out


def _means(run):
    res = run.results
    m = res.last(1 / 3)
    return {k: float(np.mean(v[m])) for k, v in res.power_loss().items()}, float(np.mean(res.drive_power()[m]))


@pytest.mark.parametrize("law", [ContactLaw(), ContactLaw(rolling_resistance=True, thermal_film=True)],
                         ids=["paper physics", "rolling resistance and thermal film"])
def test_drive_power_equals_total_loss(law):
    """Energy balance over the last third of a settled run (1.3 kN, 1800 rpm, from the steady
    state): what the inner race puts in leaves through the sources, within 1 %."""
    run = simulate(axial=1300.0, rpm=1800.0, time=0.05, contact_law=law)
    loss, drive = _means(run)
    assert drive > 10.0
    assert loss["total"] == pytest.approx(drive, rel=0.01)
    assert loss["traction"] > 0 and loss["ball_drag"] > 0
    assert (loss["rolling_resistance"] > 0) == law.rolling_resistance
    assert run.power_loss_W["total"] == pytest.approx(loss["total"], rel=1e-12)


def test_switched_off_sources_are_zero_and_drag_is_the_closed_form():
    """No drag and no rolling resistance: both sources are exactly zero. With drag, its loss
    is sum over the balls of 1/2 C_D (x rho) pi r^2 |v|^3 at the balls' orbital speeds
    (MODEL.md §8), so it scales with the oil fraction."""
    bare = simulate(axial=1300.0, rpm=1800.0, time=0.01, drag=None)
    res = bare.results
    assert np.all(res.power_loss()["ball_drag"] == 0.0) and np.all(res.power_loss()["rolling_resistance"] == 0.0)
    for fraction in (1.0, 0.25):
        run = simulate(axial=1300.0, rpm=1800.0, time=0.01, drag=BallDrag(0.5, fraction))
        r = run.results
        radius = B.pitch_radius  # the ball speed along the orbit: w_orbit r_c
        speed = r.ball_orbital_speed * radius
        closed = np.sum(0.5 * 0.5 * fraction * OIL_DENSITY * math.pi * B.ball_radius ** 2 * np.abs(speed) ** 3,
                        axis=1)
        assert r.power_loss()["ball_drag"] == pytest.approx(closed, rel=2e-3)


def test_loss_rises_with_speed():
    """The 35-mm high-speed bearing (MODEL.md §11) at 667 N with every loss switched on: the
    total at 48 000 rpm exceeds that at 28 000 rpm, and so does each speed-driven source."""
    law = ContactLaw(rolling_resistance=True, thermal_film=True)
    low, high = (_means(simulate(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, axial=667.0, rpm=rpm, time=0.004,
                                 drag=HIGH_SPEED_DRAG, contact_law=law))[0] for rpm in (28000.0, 48000.0))
    assert high["total"] > low["total"]
    for source in ("ball_drag", "rolling_resistance"):
        assert high[source] > low[source]
