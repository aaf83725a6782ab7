"""Shared fixtures and the two test lanes.

Lanes: ``python -m pytest -m "not slow"`` (the fast lane, every module and each door — CLI,
Python API, a plain Exudyn scene — with short runs; under 4 minutes on 2 cores) and
``python -m pytest`` (everything, the README's and CI's command). A test that takes more than
about 4 s on a 2-core host is marked ``@pytest.mark.slow`` (measured with ``--durations``).

Expensive results that several tests compare against are computed once per session here;
helpers the modules share are in ``tests/helpers.py`` (no test module imports another).
"""
import pytest


@pytest.fixture(scope="session")
def reference_steady():
    """The reference bearing's steady rolling state at 1300 N, 1800 rpm (MODEL.md §12), with
    the package's default oil, drag, cage and law; shared, so do not modify it."""
    from exudyn_bearing import steady_state

    return steady_state(axial_force=1300.0, rpm=1800.0)
