"""The outputs take each recorded state's contact traction from the run that computed it
(exudyn_bearing.model.recorded_traction; issue 52, item 2): the same numbers as the fast rule
computed again on the recorded states, and never another state's."""
import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from contact.ballrace import ContactLaw  # noqa: E402
from exudyn_bearing import CreateAngularContactBearing, races, run_solver  # noqa: E402
from exudyn_bearing.bearing import BallDrag  # noqa: E402
from exudyn_bearing.presets import CWRU_6205_BEARING, SPINDLE_40MM_BEARING  # noqa: E402
from exudyn_bearing.simulation.runner import SolverSettings, with_surface_step  # noqa: E402

TRACTION_FIELDS = ("traction_rolling", "traction_transverse", "spin_moment", "heat")


def _run(bearing=None, rpm=1800.0, axial=1300.0, radial=0.0, end=0.005, **kw):
    mbs = exu.SystemContainer().AddSystem()
    args = () if bearing is None else (bearing,)
    h = CreateAngularContactBearing(mbs, *args, innerRace=races.Driven(rpm), axialForce=axial, radialForce=radial,
                                    show=False, **kw)
    mbs.Assemble()
    run_solver(mbs, [h], end, with_surface_step(SolverSettings(progress=False), h, rpm))
    return mbs, h


def _recomputed(h, mbs, stride=1):
    """The outputs with the fast rule run again on every recorded state (the kept traction set
    aside for the call)."""
    kept, h.connector.recorded = h.connector.recorded, None
    try:
        return h.Results(mbs, stride=stride)
    finally:
        h.connector.recorded = kept


def _assert_same_traction(got, want, rtol=1e-9):
    for race in ("inner", "outer"):
        for name in TRACTION_FIELDS:
            a, b = getattr(got, race)[name], getattr(want, race)[name]
            scale = max(float(np.max(np.abs(b))), 1e-300)
            assert np.max(np.abs(a - b)) <= rtol * scale, (race, name)


@pytest.mark.parametrize("case", ["reference", "combined", "deep groove", "spindle"])
def test_every_recorded_state_keeps_the_traction_the_run_computed(case):
    """Reference bearing (1.3 kN; 2.2 kN + 2 kN radial), the 6205 deep-groove bearing at
    1 kN radial and the 40-mm spindle at 12 000 rpm: every recorded state is kept, and the
    outputs' traction, spin moment and heat equal the fast rule's on the recorded states."""
    bearing, rpm, axial, radial = {"reference": (None, 1800.0, 1300.0, 0.0),
                                   "combined": (None, 1800.0, 2200.0, 2000.0),
                                   "deep groove": (CWRU_6205_BEARING, 1800.0, 200.0, 1000.0),
                                   "spindle": (SPINDLE_40MM_BEARING, 12000.0, 1000.0, 0.0)}[case]
    mbs, h = _run(bearing, rpm, axial, radial)
    t, _, _ = h.States(mbs)
    assert len(h.connector.recorded) == len(t)
    got = h.Results(mbs)
    want = _recomputed(h, mbs)
    _assert_same_traction(got, want)
    assert np.max(np.abs(got.inner["heat"])) > 0.0  # the traction acts
    assert got.summary()["power_loss_W"]["traction"] == pytest.approx(want.summary()["power_loss_W"]["traction"],
                                                                     rel=1e-9)


def test_a_state_the_run_did_not_evaluate_last_is_not_kept_nor_served():
    """The state sensor keeps only the state the compiled path evaluated last, at its time; a
    state one ulp away, or the same state at another time, finds nothing; an evaluation
    elsewhere before the state is recorded again drops what it kept."""
    from exudyn_bearing.model.sensors import node_rows

    mbs, h = _run(end=0.002)
    con = h.connector
    t, q, q_t = h.States(mbs)
    rows = node_rows(mbs, h.nodeNumbers)
    exact_q = np.asarray(mbs.systemData.GetODE2Coordinates())[rows]  # the end state as the kernel saw it
    exact_v = np.asarray(mbs.systemData.GetODE2Coordinates_t())[rows]
    row = np.concatenate([q[-1], q_t[-1]])
    assert con.recorded.keep(t[-1], row, exact_q, exact_v)  # the last evaluation was this state
    assert not con.recorded.keep(t[-1] + 1e-9, row, exact_q, exact_v)  # at another time: not that evaluation
    assert con.recorded.keep(t[-1], row, exact_q, exact_v)
    assert con.recorded.lookup(t[-1:], q[-1:], q_t[-1:]) is not None
    assert con.recorded.lookup(t[-1:] + 1e-4, q[-1:], q_t[-1:]) is None
    moved = q_t[-1:].copy()
    ball = 6 * con.layout["balls"][0]
    moved[0, ball] = np.nextafter(moved[0, ball], np.inf)
    assert con.recorded.lookup(t[-1:], q[-1:], moved) is None
    both = con.recorded.lookup(np.repeat(t[-1:], 2), np.vstack([q[-1:], q[-1:]]), np.vstack([q_t[-1:], moved]))
    assert np.any(np.isfinite(both[0])) and np.all(np.isnan(both[1]))
    # an evaluation elsewhere, then the state recorded again: not kept, and the old one dropped
    con.residual_forces(t[-1], exact_q, moved[0])
    assert not con.recorded.keep(t[-1], row, exact_q, exact_v)
    assert con.recorded.lookup(t[-1:], q[-1:], q_t[-1:]) is None


def test_other_oils_find_nothing_and_the_runs_own_find_the_kept_traction():
    """The key holds the physics: with a thinner oil set after the run the outputs compute the
    traction with that oil (and it changes); with the run's oil set back, they take the kept
    one again, bit for bit."""
    from dataclasses import replace

    mbs, h = _run(end=0.002)
    con = h.connector
    before = h.Results(mbs)
    own = con.oils
    thin = replace(con.lubricant, viscosity=0.5 * con.lubricant.viscosity)
    con.set_oils(thin, thin)
    changed = h.Results(mbs)
    _assert_same_traction(changed, _recomputed(h, mbs))
    assert np.max(np.abs(changed.inner["heat"] - before.inner["heat"])) > 1e-3 * np.max(before.inner["heat"])
    con.set_oils(*own)
    _assert_same_traction(h.Results(mbs), before, rtol=0.0)


def test_plain_solve_dynamic_keeps_the_written_states():
    """A plain ``exu.SolveDynamic`` with Exudyn's defaults (full Newton) and a sensor period of
    ten steps: the written states are kept, and the outputs match the recomputation."""
    mbs = exu.SystemContainer().AddSystem()
    h = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    ss = exu.SimulationSettings()
    ss.timeIntegration.endTime = 0.004
    ss.timeIntegration.numberOfSteps = 40
    ss.timeIntegration.verboseMode = 0
    ss.solution.file.write = False
    ss.solution.sensors.writePeriod = 1e-3
    assert exu.SolveDynamic(mbs, ss)
    t, _, _ = h.States(mbs)
    assert len(t) == 5 and len(h.connector.recorded) == len(t)
    _assert_same_traction(h.Results(mbs), _recomputed(h, mbs))


def test_the_numpy_path_keeps_nothing():
    """A law on the numpy path (no compiled kernel) records no traction and its outputs
    compute it, as before."""
    mbs, h = _run(end=0.001, contactLaw=ContactLaw(compiled=False), ballDrag=BallDrag())
    assert h.connector.recorded is None
    assert np.max(h.Results(mbs).inner["heat"]) > 0.0
