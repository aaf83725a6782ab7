"""Start solutions kept within one call for a second bearing built from the same inputs.

:func:`~exudyn_bearing.simulation.runner.simulate` builds the same bearing twice when it
estimates its error (the rerun at half the step), and a skid map's point is run again for
longer when it has not settled: each time the start solvers (the quasi-static distribution,
the steady or quasi-dynamic balance; ~0.2 s for the reference bearing under axial load,
~0.8 s under 2.2 kN + 2 kN) solve the very same problem. Inside :func:`kept_starts` a start
solved once is served again, as a copy, to a call with equal inputs: every input the solver
reads goes into the key (pickled and hashed; an input that cannot be pickled, such as a
lambda, keeps nothing). Outside such a scope nothing is kept, so a result is never served
across a change the key cannot see (a module constant changed between two calls).
"""
from __future__ import annotations

import copy
import functools
import hashlib
import pickle
import threading
from contextlib import contextmanager

__all__ = ["keeping_starts", "kept_starts", "remembered"]

_LOCAL = threading.local()  # .kept: the open :class:`_Scope` of this thread, or None


class _Scope:
    """What one :func:`kept_starts` scope keeps: results by digest, and the registered terms
    seen (held, so that no new term can take a seen one's id while the scope lasts)."""

    def __init__(self):
        self.results: dict = {}
        self.terms: list = []


@contextmanager
def kept_starts():
    """Within this scope (this thread), start solutions are kept and served again to equal inputs
    (:func:`remembered`); nested scopes share the outermost one's."""
    outer = getattr(_LOCAL, "kept", None)
    if outer is None:
        _LOCAL.kept = _Scope()
    try:
        yield
    finally:
        if outer is None:
            _LOCAL.kept = None


def keeping_starts(function):
    """``function`` run inside :func:`kept_starts` (a call that builds its bearing more than once)."""

    @functools.wraps(function)
    def run(*args, **kwargs):
        with kept_starts():
            return function(*args, **kwargs)

    return run


def _digest(inputs, scope) -> bytes | None:
    """The digest of ``inputs`` and of the registered contact terms (they act on every contact),
    None where something cannot be pickled."""
    from contact.terms import TERMS

    try:  # the terms by identity, held by the scope (an id is unique among live objects)
        terms = tuple(TERMS.items())
        scope.terms.extend(entry for _, entry in terms)
        data = pickle.dumps((inputs, tuple((name, id(entry)) for name, entry in terms)),
                            protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # noqa: BLE001 - whatever cannot be pickled keeps nothing; the call goes on
        return None
    return hashlib.blake2b(data, digest_size=32).digest()


def remembered(inputs: tuple, compute):
    """``compute()``, a start solver's result for ``inputs`` (a name and every value it reads),
    or, inside :func:`kept_starts`, a copy of the result kept for equal inputs. The result
    is kept as a copy too: what the caller does with its own cannot change a later one. A
    result served again is the first solve's, its solver timings included."""
    scope = getattr(_LOCAL, "kept", None)
    key = None if scope is None else _digest(inputs, scope)
    if key is not None and key in scope.results:
        return copy.deepcopy(scope.results[key])
    result = compute()
    if key is not None:
        scope.results[key] = copy.deepcopy(result)
    return result
