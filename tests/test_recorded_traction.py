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
    """The state sensor keeps only the state the compiled path evaluated last; a state altered
    by one ulp finds nothing, and its traction is computed, not served from its neighbour."""
    mbs, h = _run(end=0.002)
    con = h.connector
    t, q, q_t = h.States(mbs)
    row = np.concatenate([q[-1], q_t[-1]])
    ref = con.reference
    assert con.recorded.keep(row, q[-1] - ref, q_t[-1]) is False  # (q + ref) - ref is not q, bit for bit
    moved = q_t[-1:].copy()
    ball = 6 * con.layout["balls"][0]
    moved[0, ball] = np.nextafter(moved[0, ball], np.inf)
    assert con.recorded.lookup(q[-1:], moved) is None
    both = con.recorded.lookup(np.vstack([q[-1:], q[-1:]]), np.vstack([q_t[-1:], moved]))
    assert np.all(np.isfinite(both[0])) and np.all(np.isnan(both[1]))
    # an evaluation elsewhere after the run: the recorded state is no longer the last one
    con.residual_forces(t[-1], q[-1] - ref, moved[0])
    assert con.recorded.keep(row, q[-1] - ref, q_t[-1]) is False


def test_the_kept_traction_is_the_runs_when_the_oil_changed_later():
    """The outputs report what the run computed: a thinner oil set after the run changes the
    recomputed traction, not the kept one (which equals the recomputation with the run's oil)."""
    from dataclasses import replace

    mbs, h = _run(end=0.002)
    con = h.connector
    before = h.Results(mbs)
    thin = replace(con.lubricant, viscosity=0.5 * con.lubricant.viscosity)
    con.set_oils(thin, thin)
    after = h.Results(mbs)
    _assert_same_traction(after, before, rtol=0.0)
    changed = _recomputed(h, mbs)
    assert np.max(np.abs(changed.inner["heat"] - before.inner["heat"])) > 1e-3 * np.max(before.inner["heat"])


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
