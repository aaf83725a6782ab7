"""The contacts' traction a run computed at the states it recorded (issue 52, item 2).

A run's outputs (:func:`exudyn_bearing.results.outputs.compute_results`) need each recorded
state's traction: f_x, f_y, M_z and heat at every ball–race contact (MODEL.md §6), the
costliest part of recomputing them (the fast rule again, ~0.1 s per 0.1 s of the reference
bearing on one core). The run has computed them already. Exudyn records a state after its
step's Newton iteration has converged there, and that iteration's last force evaluation is at
the state it accepts. So when the bearing's state sensor records a state equal, bit for bit, to
the one the compiled force path evaluated last, at the same time
(:meth:`~exudyn_bearing.model.compiled.CompiledForces.single`), the traction of that
evaluation is the recorded state's, and is kept.

A kept traction is found again by everything it was computed from: a 128-bit BLAKE2 digest of
the state (absolute coordinates and velocities as the sensor stores them), its time, the
kinematic races' angular velocities then, and the contact physics the connector held (its
geometry, both races' laws and oils, the per-contact terms: a fingerprint of the compiled
path's records, taken again whenever ``set_oils`` or ``set_geometry`` changes them). A state
recorded under other physics, at another time or one ulp away finds nothing, and its traction
is computed. States the sensor recorded after another evaluation (a step that was cut, the
numpy path) are not kept, nor are contacts the kernel found unloaded (the outputs decide
those themselves).
"""
from __future__ import annotations

import hashlib

import numpy as np

__all__ = ["RecordedTraction", "physics_fingerprint"]


def _feed(hasher, item) -> None:
    """Every number and array of a nested record into ``hasher`` (functions by name)."""
    if isinstance(item, np.ndarray):
        hasher.update(f"{item.dtype.str}{item.shape}".encode())
        hasher.update(np.ascontiguousarray(item).tobytes())
    elif isinstance(item, (tuple, list)):
        hasher.update(f"({len(item)}".encode())
        for x in item:
            _feed(hasher, x)
    elif isinstance(item, (bool, int, float, np.number, np.bool_, str)) or item is None:
        hasher.update(repr(item).encode())
    else:  # a registered term's function
        name = getattr(item, "__qualname__", type(item).__name__)
        hasher.update(f"{getattr(item, '__module__', '')}.{name}".encode())


def physics_fingerprint(physics) -> bytes:
    """A 128-bit digest of the compiled path's contact physics (its plain ``Physics`` tuple)."""
    hasher = hashlib.blake2b(digest_size=16)
    _feed(hasher, physics)
    return hasher.digest()


class RecordedTraction:
    """The traction (2, Z, 4) per race, ball and (f_x N, f_y N, M_z N m, heat W) of the
    states a bearing's state sensor recorded, where the compiled force path ``compiled``
    (:class:`~exudyn_bearing.model.compiled.CompiledForces`) had evaluated them last; NaN for a
    contact the kernel found unloaded."""

    def __init__(self, compiled):
        self.compiled = compiled
        self._rows = {}  # digest -> row of _store
        self._store = np.empty((0,) + compiled.traction.shape)
        self._physics = (None, b"")  # (the physics tuple, its fingerprint)

    def __len__(self) -> int:
        return len(self._rows)

    def _key(self, row, t, race_speeds=None) -> bytes:
        """The digest of a state ``row`` at ``t`` s with the kinematic races' ``race_speeds``
        (2, 3) rad/s (None: computed) and the physics now."""
        comp = self.compiled
        if self._physics[0] is not comp._physics_tuple:
            self._physics = (comp._physics_tuple, physics_fingerprint(comp._physics_tuple))
        hasher = hashlib.blake2b(np.ascontiguousarray(row, dtype=np.float64).tobytes(), digest_size=16)
        hasher.update(np.float64(t).tobytes())
        hasher.update((comp.fixed_omega(t) if race_speeds is None else race_speeds).tobytes())
        hasher.update(self._physics[1])
        return hasher.digest()

    def keep(self, t, row, q, q_t) -> bool:
        """Keep the last evaluation's traction for the state ``row`` (absolute coordinates then
        velocities, float64, as stored) recorded at ``t`` s if that evaluation was at ``t``,
        ``q`` (without the reference) and ``q_t``, the state's own; returns whether it was. A
        state not kept drops what an earlier recording of it kept."""
        comp = self.compiled
        inputs = comp._time_inputs  # ((t, force function), the races' speeds then, ...) of the last evaluation
        key = self._key(row, t, inputs[1] if len(inputs) > 1 and inputs[0][0] == t else None)
        # byte for byte (a failed evaluation left NaN there, which equals nothing)
        if not (t == comp.last_t and np.asarray(q, dtype=np.float64).tobytes() == comp.last_q.tobytes()
                and np.asarray(q_t, dtype=np.float64).tobytes() == comp.last_q_t.tobytes()):
            self._rows.pop(key, None)
            return False
        index = self._rows.setdefault(key, len(self._rows))
        if index >= len(self._store):  # grow by doubling
            self._store = np.concatenate([self._store, np.empty((max(16, len(self._store)),) + self._store.shape[1:])])
        self._store[index] = comp.traction
        self._store[index][comp.load.reshape(comp.traction.shape[:2]) <= 0.0] = np.nan
        return True

    def lookup(self, t, q, q_t) -> np.ndarray | None:
        """The kept traction (B, 2, Z, 4) of B states at times ``t`` (B,) s (absolute
        coordinates and velocities, (B, 6 n_nodes) each), NaN for a state or contact without
        one; None when no state has one."""
        t, q, q_t = np.atleast_1d(t), np.atleast_2d(q), np.atleast_2d(q_t)
        found = [self._rows.get(self._key(np.concatenate([a, v]), s)) for s, a, v in zip(t, q, q_t)]
        if all(f is None for f in found):
            return None
        out = np.full((len(found),) + self._store.shape[1:], np.nan)
        for k, f in enumerate(found):
            if f is not None:
                out[k] = self._store[f]
        return out
