"""Start solutions kept within one call (exudyn_bearing.model.start_memo): a second bearing
built from equal inputs inside :func:`kept_starts` starts where a fresh solve starts, without
solving again; other inputs, or no scope, solve again; what a caller does with its result
cannot change a later one."""
import numpy as np
import exudyn as exu

from exudyn_bearing import BearingSetup, CreateAngularContactBearing, REFERENCE_BEARING, races
from exudyn_bearing.model import start_memo, start_state
from exudyn_bearing.model.start_memo import kept_starts, remembered
from tests.helpers import record_keyword


def _counted(monkeypatch):
    """The builder's calls of the steady start solver, counted."""
    return record_keyword(monkeypatch, start_state, "steady_start", "axial_force")


def _start(rpm=1800.0, axial=1300.0, setup=None):
    """The start coordinates and velocities of a freshly built reference bearing."""
    mbs = exu.SystemContainer().AddSystem()
    CreateAngularContactBearing(mbs, setup or BearingSetup(REFERENCE_BEARING), innerRace=races.Driven(rpm),
                                axialForce=axial, show=False)
    mbs.Assemble()
    return np.concatenate([mbs.systemData.GetODE2Coordinates(), mbs.systemData.GetODE2Coordinates_t()])


def test_a_second_build_in_the_scope_starts_where_a_fresh_solve_does(monkeypatch):
    calls = _counted(monkeypatch)
    fresh = _start()
    assert len(calls) == 1
    with kept_starts():
        first, again = _start(), _start()
    assert len(calls) == 2  # the scope's second build solved nothing
    np.testing.assert_array_equal(first, fresh)
    np.testing.assert_array_equal(again, fresh)
    assert not np.all(fresh[fresh.size // 2:] == 0)  # (a start that turns)
    _start()  # outside a scope nothing is kept
    assert len(calls) == 3


def test_other_inputs_solve_again(monkeypatch):
    from dataclasses import replace

    calls = _counted(monkeypatch)
    with kept_starts():
        base = _start()
        faster = _start(rpm=2400.0)
        loaded = _start(axial=1500.0)
        setup = BearingSetup(REFERENCE_BEARING)
        oil = _start(setup=setup.replace(lubricant=replace(setup.lubricant, viscosity=1.5 * setup.lubricant.viscosity)))
    assert len(calls) == 4
    for other in (faster, loaded, oil):
        assert not np.array_equal(other, base)


def test_the_kept_result_is_a_copy():
    made = []

    def compute():
        made.append(1)
        return {"speeds": np.arange(3.0)}

    with kept_starts():
        first = remembered(("a solver", 1.0), compute)
        first["speeds"][:] = -1.0  # the caller's own copy
        second = remembered(("a solver", 1.0), compute)
        other = remembered(("a solver", 2.0), compute)
        unpicklable = [remembered(("a solver", lambda: 0), compute) for _ in range(2)]
    assert len(made) == 1 + 1 + 2
    np.testing.assert_array_equal(second["speeds"], np.arange(3.0))
    assert other is not second and all(u is not second for u in unpicklable)
    assert start_memo._LOCAL.kept is None  # the scope's results are gone with it
