"""The contacts' traction a run computed at the states it recorded (issue 52, item 2).

A run's outputs (:func:`exudyn_bearing.results.outputs.compute_results`) need each recorded
state's traction: f_x, f_y, M_z and heat at every ball–race contact (MODEL.md §6), the
costliest part of recomputing them (the fast rule again, ~0.1 s per 0.1 s of the reference
bearing on one core). The run has computed them already. Exudyn records a state after its
step's Newton iteration has converged there, and that iteration's last force evaluation is at
the state it accepts. So when the bearing's state sensor records a state equal, bit for bit, to
the one the compiled force path evaluated last (:meth:`CompiledForces.single`), the traction of
that evaluation is the recorded state's, and is kept.

A state is found again by its bytes: a 128-bit BLAKE2 digest of its absolute coordinates and
velocities as the state sensor stores them. A traction is never served for another state, and
a state recorded again (a new solve through the same start) keeps the latest. States the
sensor recorded after another evaluation (a step that was cut, an evaluation by the numpy
path) are not kept: the outputs compute theirs.
"""
from __future__ import annotations

import hashlib

import numpy as np

__all__ = ["RecordedTraction"]


def _digest(row: np.ndarray) -> bytes:
    """The key of one state: its absolute coordinates and velocities as one float64 row."""
    return hashlib.blake2b(np.ascontiguousarray(row, dtype=np.float64).tobytes(), digest_size=16).digest()


class RecordedTraction:
    """The traction (2, Z, 4) per race, ball and (f_x N, f_y N, M_z N m, heat W) of the
    states a bearing's state sensor recorded, where the compiled force path ``compiled``
    (:class:`~exudyn_bearing.model.compiled.CompiledForces`) had evaluated them last."""

    def __init__(self, compiled):
        self.compiled = compiled
        self._kept = {}

    def __len__(self) -> int:
        return len(self._kept)

    def keep(self, row, q, q_t) -> bool:
        """Keep the last evaluation's traction for the recorded state ``row`` (absolute
        coordinates then velocities, float64, as stored) if that evaluation was at ``q``
        (without the reference) and ``q_t``, the state's own; returns whether it was."""
        comp = self.compiled
        if not (np.array_equal(q, comp.last_q) and np.array_equal(q_t, comp.last_q_t)):
            return False
        self._kept[_digest(row)] = comp.traction.copy()
        return True

    def lookup(self, q, q_t) -> np.ndarray | None:
        """The kept traction (B, 2, Z, 4) of B states (absolute coordinates and velocities,
        (B, 6 n_nodes) each), NaN for a state without one; None when none has one."""
        q, q_t = np.atleast_2d(q), np.atleast_2d(q_t)
        found = [self._kept.get(_digest(np.concatenate([a, v]))) for a, v in zip(q, q_t)]
        if all(f is None for f in found):
            return None
        out = np.full((len(found),) + self.compiled.traction.shape, np.nan)
        for k, f in enumerate(found):
            if f is not None:
                out[k] = f
        return out
