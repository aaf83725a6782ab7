"""The per-contact terms' extension point (contact/terms.py, docs/ARCHITECTURE.md): a toy term
registered from this module — a constant factor on the film thickness — reaches the numpy
force path, the compiled one-state and batch paths, both Jacobian paths and a run, with no
edit anywhere else.

The kernels compile once more for the record that carries the toy term (about a minute),
so the module is in the slow lane; tests/test_contact_records.py keeps the built-in terms
in the fast one.
"""
from __future__ import annotations

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
numba = pytest.importorskip("numba")

from contact.ballrace import ContactLaw  # noqa: E402
from contact.terms import TERMS, Term, register_term  # noqa: E402
from exudyn_bearing import simulate  # noqa: E402
from tests.helpers import _assert_jacobian_matches_numpy, _both_paths, _jacobian_paths, _scene  # noqa: E402

pytestmark = pytest.mark.slow

#: the toy film factor
FACTOR = 0.5
NAME = "test-constant-film"


@numba.njit
def constant_film(parameter, cs):
    """Stage 1 of the toy term: the film thickness times ``parameter``."""
    return parameter


@pytest.fixture(scope="module")
def toy():
    """Scenes built while the toy term is registered: (with it, without it), both from the
    same pure-rolling start (the quasi-static state, which has no film)."""
    plain = _scene(axialForce=2200.0, radialForce=2000.0, initialState="rolling")
    register_term(NAME, Term(film_factor=constant_film, parameter=FACTOR))
    try:
        yield _scene(axialForce=2200.0, radialForce=2000.0, initialState="rolling"), plain
    finally:
        del TERMS[NAME]


def test_the_toy_term_is_on_the_contacts_record(toy):
    (_sc, con, _q, _qt), (_s, plain, _p, _pt) = toy
    assert len(con.terms.registered) == 1 and con.terms.registered[0].parameter == FACTOR
    assert plain.terms.registered == ()
    assert con._compiled is not None  # the compiled path covers it, no numpy fallback


def test_the_toy_term_reaches_both_force_paths(toy):
    (_sc, con, q, qt), (_s, plain, q0, qt0) = toy
    np.testing.assert_array_equal(q, q0)
    single, fast, ref = _both_paths(con, q, qt)
    without = _both_paths(plain, q0, qt0)[2]
    # a thinner film shears harder: the traction forces (~1 N on ~300-N normal loads) change
    assert np.max(np.abs(ref - without)[:, :3]) > 1e-3 * np.max(np.abs(without[con.layout["balls"], :3]))
    for got in (single, fast):
        for part in (slice(0, 3), slice(3, 6)):
            err = np.max(np.abs(got[:, part] - ref[:, part]))
            assert err < 1e-6 * np.max(np.abs(ref[:, part])), (part, err)
    # the numpy path's film is FACTOR times the term-free one at every loaded contact
    for race in ("inner_forces", "outer_forces"):
        films = [getattr(c.states(np.array([0.01]), q[None], qt[None]), race).film_thickness for c in (con, plain)]
        loaded = films[1] > 2e-8
        assert np.count_nonzero(loaded) > 4
        np.testing.assert_allclose(films[0][loaded], FACTOR * films[1][loaded], rtol=1e-12)


def test_the_toy_term_reaches_both_jacobian_paths(toy):
    (_sc, con, q, qt), (_s, plain, _p, _pt) = toy
    main, serial, ref = _jacobian_paths(con, q, qt)
    np.testing.assert_allclose(serial, main, rtol=0, atol=1e-9 * np.max(np.abs(main)))
    _assert_jacobian_matches_numpy(main, ref, con)
    assert np.max(np.abs(main - plain.jacobian(0.01, q, qt, 1.0, 1e-4))) > 1e-6 * np.max(np.abs(ref))


def test_a_run_with_the_toy_term_has_the_thinner_film(toy):
    """Two 5-ms runs of the reference bearing, with and without the term: the loads and
    speeds are set by the applied load and the shaft, so the loaded contacts' mean film is
    FACTOR times the term-free run's (to the few per cent the traction moves the balls)."""
    law = ContactLaw()
    run = simulate(axial_force=1300.0, rpm=1800.0, time=0.005, contact_law=law)  # the fixture's term on
    term = TERMS.pop(NAME)
    try:
        base = simulate(axial_force=1300.0, rpm=1800.0, time=0.005, contact_law=law)
    finally:
        TERMS[NAME] = term
    films = [np.mean(r.results.inner["film"][-1]) for r in (run, base)]
    assert films[0] / films[1] == pytest.approx(FACTOR, rel=0.03)


def test_the_toy_term_is_in_the_inputs_record_and_reaches_the_skid_maps_workers(toy, monkeypatch):
    """A result file names the registered term (without the process's addresses, so a resume
    compares like with like), and a skid-map point carries it to a worker, which registers it
    again where its process lacks it."""
    from exudyn_bearing import BearingSetup, REFERENCE_BEARING
    from exudyn_bearing.results.records import setup_inputs
    from exudyn_bearing.studies import skidmap

    setup = BearingSetup(REFERENCE_BEARING)
    record = setup_inputs(setup)["registered_terms"]
    assert NAME in record and "constant_film" in record and "0x" not in record
    term, applies = TERMS.pop(NAME)
    try:
        assert "registered_terms" not in setup_inputs(setup)  # a term-free run reads as before
        point = skidmap.SkidPoint(1300.0, 0.0, 1800.0, 0.002)
        done = skidmap._run_point((point, setup, ((NAME, term),)))  # a worker without the term
        assert done["error"] is None and NAME in TERMS
    finally:
        TERMS[NAME] = (term, applies)
    jobs = []
    monkeypatch.setattr(skidmap, "_run_point", lambda job: jobs.append(job) or skidmap.asdict(job[0]))
    skidmap.skid_map(setup, axial_force=(1300.0,), rpm=(1800.0,), time=0.002, workers=1, refine=False, progress=None)
    assert jobs and jobs[0][2] == ((NAME, TERMS[NAME][0]),)
