"""One conversion from a setup to the contact records (exudyn_bearing/contact_records.py):
every field of the per-contact terms reaches the numpy path, the compiled one-state path, the
compiled batch path and both of the compiled Jacobian's paths (threads and serial).

The numpy path is the reference here as in tests/test_compiled.py; a term that one path
dropped or rebuilt with its default would differ from it by the term's whole size.
"""
from __future__ import annotations

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
pytest.importorskip("numba")

from contact import kernels  # noqa: E402
from contact.ballrace import ContactLaw  # noqa: E402
from contact.surface import Defect, SurfaceModel, Waviness  # noqa: E402
from contact.terms import TermRecord, plain_terms, terms_from_plain  # noqa: E402
from exudyn_bearing import REFERENCE_BEARING, REFERENCE_LUBRICANT  # noqa: E402
from exudyn_bearing.contact_records import contact_records  # noqa: E402
from tests.helpers import _assert_jacobian_matches_numpy, _both_paths, _jacobian_paths, _scene  # noqa: E402

#: every term on: thermal film and rolling resistance (MODEL.md §11b, §11e), race defects on
#: both races, race waviness, ball-size variation, ball pits and ball waviness (§13)
EVERY_TERM = dict(
    axialForce=2200.0, radialForce=2000.0, law=ContactLaw(rolling_resistance=True, thermal_film=True),
    surface=SurfaceModel(
        (Defect("outer", 0.0, 1.0e-3, 5e-6), Defect("inner", 90.0, 2e-3, 20e-6, edge=0.2e-3),
         Defect("ball", -0.5, 1.0e-3, 5e-6, ball=0), Defect("ball", -2.0, 1.2e-3, 8e-6, ball=3, edge=0.1e-3)),
        Waviness(inner=((5, 0.5e-6, 30.0),), outer=((17, 0.3e-6, 0.0),), ball=((0, 6, 0.3e-6, 10.0),),
                 ball_diameter_variation=(1e-6,) + (0.0,) * 15)))


@pytest.fixture(scope="module")
def every_term():
    return _scene(**EVERY_TERM)


def test_every_term_field_is_away_from_its_default(every_term):
    """The scene below sets every field of TermRecord (and of its surface record): a new field
    left at its default here would go unchecked, so this test names the fields it covers."""
    terms = every_term[1].terms
    # (``registered``, the terms registered from outside, is held by tests/test_registered_term.py:
    # a registered term compiles the kernels once more, a slow-lane cost)
    assert TermRecord._fields == ("surface", "heating", "rolling_width", "registered"), \
        "a new term: set it in EVERY_TERM"
    assert terms.heating == pytest.approx(REFERENCE_LUBRICANT.temperature_viscosity
                                          / REFERENCE_LUBRICANT.thermal_conductivity)
    assert terms.rolling_width == REFERENCE_BEARING.ball_diameter
    for name in ("waviness", "defects", "ball_excess", "ball_defects", "ball_waviness"):
        assert getattr(terms.surface, name).size > 0, name
    rebuilt = terms_from_plain(plain_terms(terms))  # the one-state kernel's round trip
    assert rebuilt.heating == terms.heating and rebuilt.rolling_width == terms.rolling_width
    for got, want in zip(rebuilt.surface, terms.surface):
        np.testing.assert_array_equal(got, want)


def test_every_term_reaches_both_force_paths(every_term):
    _sc, con, q, qt = every_term
    single, fast, ref = _both_paths(con, q, qt)
    without = _scene(**{**EVERY_TERM, "law": ContactLaw(), "surface": None})
    assert np.max(np.abs(_both_paths(*without[1:])[2] - ref)) > 1.0  # the terms move the forces by newtons
    for got in (single, fast):
        for part in (slice(0, 3), slice(3, 6)):
            err = np.max(np.abs(got[:, part] - ref[:, part]))
            assert err < 1e-6 * np.max(np.abs(ref[:, part])), (part, err)


def test_every_term_reaches_both_jacobian_paths(every_term):
    """The compiled Jacobian from the main thread (contacts shared over threads) and from a
    worker thread (the serial kernel): the same numbers; both equal the numpy path's Jacobian
    to finite-difference noise (tolerances of tests/test_compiled.py)."""
    _sc, con, q, qt = every_term
    main, serial, ref = _jacobian_paths(con, q, qt)
    np.testing.assert_allclose(serial, main, rtol=0, atol=1e-9 * np.max(np.abs(main)))
    _assert_jacobian_matches_numpy(main, ref, con)


def test_threaded_contacts_equal_the_serial_kernel(every_term):
    """race_contacts_parallel over a batch of perturbed states, all contacts and a subset,
    against race_contacts: bit for bit (each contact is computed by the same function)."""
    _sc, con, q, qt = every_term
    comp = con._compiled
    pos, rot, vel, wl = con.decode(q, qt)
    omega = np.einsum("nij,nj->ni", rot, wl)
    b, z = 9, con.z
    states = [np.repeat(x[None], b, axis=0) for x in (pos, rot, vel, omega)]
    states[0] = states[0] + np.random.default_rng(3).normal(0, 1e-7, states[0].shape)
    w = comp._contacts(0.01, *states)  # the race frames of the batch
    frames = kernels.RaceFrames(w["ro"], w["rr"], w["rv"], w["rw"])
    balls = kernels.BallStates(*(np.ascontiguousarray(np.take(x, comp.balls, axis=1))
                                 for x in (states[0], states[2], states[3], states[1])))
    shapes = [(b, 2, z, 3), (b, 2, z, 3), (b, 2, z), (b, 2, z), (b, 2, z, 4)]
    serial = kernels.ContactOutputs(*(np.empty(s) for s in shapes))
    kernels.race_contacts(balls, frames, *comp.physics[:4], serial)
    for todo in (np.arange(b * 2 * z), np.arange(0, b * 2 * z, 3)):
        out = kernels.ContactOutputs(*(np.full(s, np.nan) for s in shapes))
        kernels.race_contacts_parallel(balls, frames, *comp.physics[:4], out, todo)
        done = np.zeros(b * 2 * z, dtype=bool)
        done[todo] = True
        for got, want in zip(out, serial):
            flat = got.reshape(b * 2 * z, -1)
            np.testing.assert_array_equal(flat[done], want.reshape(b * 2 * z, -1)[done])
            assert np.all(np.isnan(flat[~done]))


def test_solvers_and_connector_read_one_conversion(every_term):
    """The connector's records are contact_records' of its setup (so are the steady and
    quasi-dynamic solvers', which call it for one ball and for Z balls)."""
    con = every_term[1]
    again = contact_records(con.bearing, con.lubricant, con.law)
    for got, want in zip(con.records.grooves + (con.records.signs,), again.grooves + (again.signs,)):
        np.testing.assert_array_equal(got, want)
    assert con.records.laws == again.laws
    assert con.records.terms.heating == again.terms.heating
    np.testing.assert_array_equal(con.records.geometry.groove, again.geometry.groove)
    one = contact_records(con.bearing, con.lubricant, con.law, balls=1)
    np.testing.assert_array_equal(one.grooves[0], again.grooves[0][[0, con.z]])
