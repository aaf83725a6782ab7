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

_LOCAL = threading.local()  # .kept: {digest: result} of the innermost scope of this thread, or None


@contextmanager
def kept_starts():
    """Within this scope (this thread), start solutions are kept and served again to equal inputs
    (:func:`remembered`); nested scopes share the outermost one's."""
    outer = getattr(_LOCAL, "kept", None)
    if outer is None:
        _LOCAL.kept = {}
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


def _digest(inputs) -> bytes | None:
    """The digest of ``inputs`` and of the registered contact terms (they act on every contact),
    None where something cannot be pickled."""
    from contact.terms import TERMS

    try:  # the terms by identity: within one scope the same objects
        data = pickle.dumps((inputs, tuple((name, id(entry)) for name, entry in TERMS.items())),
                            protocol=pickle.HIGHEST_PROTOCOL)
    except (pickle.PicklingError, TypeError, AttributeError):
        return None
    return hashlib.blake2b(data, digest_size=32).digest()


def remembered(inputs: tuple, compute):
    """``compute()``, a start solver's result for ``inputs`` (a name and every value it reads),
    or, inside :func:`kept_starts`, a copy of the result kept for equal inputs. The result
    is kept as a copy too: what the caller does with its own cannot change a later one."""
    kept = getattr(_LOCAL, "kept", None)
    key = None if kept is None else _digest(inputs)
    if key is not None and key in kept:
        return copy.deepcopy(kept[key])
    result = compute()
    if key is not None:
        kept[key] = copy.deepcopy(result)
    return result
