"""The passage step only near defect passages (MODEL.md §13c, issue 49 item 6): the stepper's
bookkeeping against the steps Exudyn takes, the windows against where the balls stand, and a
run stepped fine only near the passages against one stepped fine throughout."""
from __future__ import annotations

import math
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING
from exudyn_bearing.simulation.stepping import PassageStepper

exu = pytest.importorskip("exudyn")

#: a small 12-ball bearing (the 6205's balls on a 54-mm pitch) with a deep EDM notch in its
#: outer race: the ball's contact opens over it, the strike step applies
SMALL = replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3)
NOTCH = SurfaceModel((Defect("outer", 0.0, 0.8e-3, 0.3e-3),))


class _Stepper(PassageStepper):
    """The stepper with ``near`` from a script of times (no bearing)."""

    def __init__(self, windows_in_time, **kw):
        super().__init__([], [], **kw)
        self.spans = windows_in_time

    def near(self, mbs):
        return any(a <= self._now < b for a, b in self.spans)

    def __call__(self, solver, mbs, settings):
        self._now = float(solver.it.currentTime)
        return super().__call__(solver, mbs, settings)


def _drive(stepper, end, fail_at=()):
    """Exudyn's step loop (CSolverBase::SolveSteps with adaptive steps): UpdateCurrentTime,
    then a step that fails once where its end passes a time in ``fail_at`` (the time is reset
    and the step halved, as ReduceStepSize does)."""
    it = SimpleNamespace(currentTime=0.0, currentStepSize=stepper.coarse, endTime=end)
    solver, taken, failing = SimpleNamespace(it=it), [], list(fail_at)
    while it.currentTime < end - 1e-12:
        start = it.currentTime
        stepper(solver, None, None)
        if failing and start < failing[0] <= it.currentTime:
            failing.pop(0)
            it.currentTime, it.currentStepSize = start, 0.5 * it.currentStepSize
            continue
        taken.append((start, it.currentTime - start))
    return taken


def test_stepper_takes_the_fine_step_inside_windows_and_the_coarse_elsewhere():
    stepper = _Stepper([(1e-3, 2e-3)], coarse=1e-4, fine=1e-5)
    taken = _drive(stepper, 3e-3)
    starts, steps = np.array(taken).T
    inside = (starts >= 1e-3 - 1e-12) & (starts < 2e-3 - 1e-12)
    assert np.allclose(steps[inside], 1e-5) and np.allclose(steps[~inside], 1e-4)
    assert math.fsum(steps) == pytest.approx(3e-3, abs=1e-15)
    assert stepper.fine_time == pytest.approx(1e-3, rel=1e-9) and stepper.fine_steps == 100


def test_a_cut_step_stays_short_until_it_has_recovered():
    """A cut at 0.5 ms (coarse region): the retry takes Exudyn's halved step, and with the 9
    after it 10 converged steps keep it (Exudyn's adaptiveStepRecoverySteps), then it doubles back to the coarse step; the end time is met exactly."""
    stepper = _Stepper([], coarse=1e-4, fine=1e-5, recovery_steps=10)
    taken = _drive(stepper, 3e-3, fail_at=(0.55e-3,))
    starts, steps = np.array(taken).T
    after = starts >= 0.5e-3 - 1e-12
    assert np.allclose(steps[~after], 1e-4)
    assert np.allclose(steps[after][:10], 0.5e-4) and np.allclose(steps[after][10:], 1e-4)
    assert starts[-1] + steps[-1] == pytest.approx(3e-3, abs=1e-15)


def test_stepper_refuses_a_passage_step_above_the_coarse_one():
    with pytest.raises(ValueError, match="passage step"):
        PassageStepper([], [], coarse=1e-5, fine=2e-5)


def test_windows_cover_the_defect_its_contact_and_the_ringing():
    """The window of the notch: half angle (L/2 + √(2 R_x δ) + v (τ + 2 h)) / ρ, each part from
    the geometry here; a ball at the notch's edge and one half a window beyond it."""
    from exudyn_bearing.model.builder import CreateAngularContactBearing
    from exudyn_bearing.races import Driven, HousingModel
    from exudyn_bearing.setup import BearingSetup

    mbs = exu.SystemContainer().AddSystem()
    h = CreateAngularContactBearing(mbs, BearingSetup(SMALL, surface=NOTCH), innerRace=Driven(600),
                                    outerRace=HousingModel().race(), radialForce=500.0, show=False)
    mbs.Assemble()
    coarse = 25e-6
    (race, centre, half), = h.PassageWindows(600, 0, coarse)
    b = SMALL
    r, alpha = 0.5 * b.ball_diameter, b.contact_angle
    rho = 0.5 * b.pitch_diameter + r * math.cos(alpha)  # the outer contact's path radius
    r_x = 1.0 / (1.0 / r - math.cos(alpha) / rho)  # ball against the concave race, along the path
    loads = h.initialLoads
    delta = float(np.max(loads.outer_deflection))
    w_i = 600 * math.pi / 30
    v = 0.5 * w_i * (1 - b.ball_diameter * math.cos(alpha) / b.pitch_diameter) * rho  # the cage's speed ρ
    k = sum(1.5 * np.asarray(q_) / np.where(np.asarray(d_) > 0, d_, np.inf)
            for q_, d_ in ((loads.inner_load, loads.inner_deflection), (loads.outer_load, loads.outer_deflection)))
    tau = math.log(100) / (0.05 * math.sqrt(float(np.max(k)) / b.ball_mass))  # ring down to 1 % at ζ = 0.05
    assert (race, centre) == (1.0, 0.0)
    assert half * rho == pytest.approx(0.4e-3 + math.sqrt(2 * r_x * delta) + v * (tau + 2 * coarse), rel=1e-6)
    stepper = PassageStepper([h], [h.PassageWindows(600, 0, coarse)], coarse, 2.5e-6)
    assert stepper.near(mbs)  # a ball sits at azimuth 0, on the notch
    q = np.array(mbs.systemData.GetODE2Coordinates())
    # turn every ball about the axis by half a ball spacing: no ball within a window then
    con = h.connector
    from exudyn_bearing.races import node_rows
    rows = node_rows(mbs, h.nodeNumbers).reshape(-1, 6)
    turn = math.pi / b.balls
    assert half < turn
    c, s = math.cos(turn), math.sin(turn)
    for slot in con.layout["balls"]:
        p = q[rows[slot, :3]] + con.reference[6 * slot:6 * slot + 3] - con.origin
        local = p @ con.rotation
        local[:2] = c * local[0] - s * local[1], s * local[0] + c * local[1]
        q[rows[slot, :3]] = con.rotation @ local + con.origin - con.reference[6 * slot:6 * slot + 3]
    mbs.systemData.SetODE2Coordinates(q.tolist())
    assert not stepper.near(mbs)


@pytest.mark.slow
def test_fine_near_passages_reads_the_envelope_line_of_fine_throughout():
    """The 12-ball bearing's deep notch (600 rpm, 500 N radial, 0.06 s): stepped at the
    strike step only in the passage windows, the strongest envelope line is that of the run at
    the strike step throughout, within the half-step change the run reports, at a fraction of
    its steps."""
    from exudyn_bearing.simulation.runner import SolverSettings
    from exudyn_bearing.studies.vibration import vibration

    kw = dict(rpm=600, radial_force=500.0, time=0.08, surface=NOTCH, settle=0.01)
    windowed = vibration(SMALL, error_estimate=True, **kw)
    fine = windowed.solver["step_s"]
    assert windowed.solver["coarse_step_s"] >= 5 * fine and windowed.solver["passage_time_share"] < 0.2
    throughout = vibration(SMALL, settings=SolverSettings(step=fine), **kw)
    (f0, a0), (f1, a1) = windowed.envelope_peaks[0], throughout.envelope_peaks[0]
    assert f0 == pytest.approx(f1, abs=0.05)
    assert abs(a0 - a1) / a1 <= windowed.error_estimate["envelope_amplitude_bound_percent"] / 100
    assert windowed.solver["steps"] < 0.3 * throughout.solver["steps"]
