"""The traction laws' registry (contact/traction_laws.py): the one list of laws that the
contact law, the numpy force path, the compiled path's coverage, the command line and the
bearing file read; a law registered from here reaches all of them, and a law without a
compiled form says so once (NumpyPathWarning)."""
from __future__ import annotations

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from contact.ballrace import ContactLaw  # noqa: E402
from contact.traction_laws import TRACTION_LAWS, TractionModel, register_traction  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING, NumpyPathWarning  # noqa: E402
from exudyn_bearing.bearingfile import dumps_bearing, loads_bearing  # noqa: E402
from exudyn_bearing.setup import BearingSetup  # noqa: E402
from exudyn_bearing.studies.cli import build_parser  # noqa: E402
from tests.helpers import _scene  # noqa: E402

#: a viscous traction f = -c u on the ball per unit slip (N s/m): linear, so its forces are known
VISCOUS = 40.0


def _viscous(slip, a, b, p_max, load, h, entrainment, lubricant, law):
    u_x, u_y, spin = slip
    calls.append(len(load))
    return SimpleNamespace(fx=VISCOUS * u_x, fy=VISCOUS * u_y, mz=np.zeros_like(u_x),
                           heat=VISCOUS * (u_x ** 2 + u_y ** 2))


calls = []


@pytest.fixture
def viscous():
    """The toy law registered for one test, removed afterwards."""
    register_traction(TractionModel("test-viscous", "a linear viscous traction (tests only)", _viscous))
    try:
        yield "test-viscous"
    finally:
        del TRACTION_LAWS["test-viscous"]


def _choices(parser, option):
    for action in parser._subparsers._group_actions[0].choices["simulate"]._actions:
        if option in action.option_strings:
            return tuple(action.choices)
    raise AssertionError(option)


def test_the_built_in_laws_and_their_compiled_forms():
    assert tuple(TRACTION_LAWS) == ("crook-limited", "crook", "newtonian", "coulomb", "none")
    assert {n for n, m in TRACTION_LAWS.items() if m.crook} == {"crook-limited", "crook"}
    assert {n for n, m in TRACTION_LAWS.items() if m.kernel is None} == {"newtonian", "coulomb"}
    with pytest.raises(ValueError, match="registered already"):
        register_traction(TRACTION_LAWS["crook"])
    with pytest.raises(ValueError, match="traction must be one of"):
        ContactLaw(traction="hertz")


def test_a_registered_law_reaches_the_law_the_file_and_the_command_line(viscous):
    law = ContactLaw(traction=viscous)
    assert not law.crook and law.limiting_shear_for(None) is None
    setup = BearingSetup(REFERENCE_BEARING, contact_law=law)
    assert loads_bearing(dumps_bearing(setup)).contact_law.traction == viscous  # the file accepts it
    with pytest.raises(ValueError, match=viscous):  # and lists it when refusing another
        loads_bearing(dumps_bearing(setup).replace(f'"{viscous}"', '"bogus"'))
    assert _choices(build_parser(), "--traction") == tuple(TRACTION_LAWS)
    assert build_parser().parse_args(["simulate", "--traction", viscous]).traction == viscous


def test_a_registered_law_runs_on_the_numpy_path_and_says_so_once(viscous):
    """Its forces are the numpy path's: the generalized forces with the viscous law minus
    those without traction, on the same (pure-rolling) state, are the law's c u on the
    loaded contacts; the NumpyPathWarning names it once for two scenes."""
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        _sc, con, q, qt = _scene(law=ContactLaw(traction=viscous), axialForce=1300.0, initialState="rolling")
        _scene(law=ContactLaw(traction=viscous), axialForce=1300.0, initialState="rolling")
    named = [w for w in said if issubclass(w.category, NumpyPathWarning)]
    assert len(named) == 1 and viscous in str(named[0].message) and "slower" in str(named[0].message)
    assert con._compiled is None
    calls.clear()
    with_law = con.evaluate(0.01, q, qt).reshape(-1, 6)
    assert calls and calls[0] > 0  # called with the loaded contacts
    _sc, plain, q0, qt0 = _scene(law=ContactLaw(traction="none"), axialForce=1300.0, initialState="rolling")
    np.testing.assert_array_equal(q0, q)
    without = plain.evaluate(0.01, q0, qt0).reshape(-1, 6)
    traction = with_law - without
    assert np.max(np.abs(traction[:, :3])) > 0.0
    # the balls' slips are ~mm/s at a pure-rolling start: |f| <= c |u| with |u| < 1 m/s per contact, two contacts a ball
    assert np.max(np.abs(traction[con.layout["balls"], :3])) < 2 * VISCOUS * 1.0


def test_the_compiled_path_covers_exactly_the_laws_with_a_kernel():
    from exudyn_bearing.model.coverage import supports, uncompiled_part

    assert supports(ContactLaw()) and supports(ContactLaw(traction="none"))
    assert uncompiled_part(ContactLaw(traction="coulomb")) == "traction 'coulomb'"
    assert "accurate rule" in uncompiled_part(ContactLaw(fast_quadrature=False))
    assert uncompiled_part(ContactLaw(hertz_method="exact")) == "hertz_method 'exact'"
