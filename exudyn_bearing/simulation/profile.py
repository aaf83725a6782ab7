"""Where a call's time goes: a clock that counts and times named calls, and the connector's
force evaluations and Jacobians counted and timed (``simulate(profile=True)``, the CLI's
``--profile``, benchmarks/call_profile.py; issue 52 item 1)."""
from __future__ import annotations

import time as _time
from contextlib import contextmanager

__all__ = ["Clock", "EvaluationClock"]


class Clock:
    """Seconds and calls per name."""

    def __init__(self):
        self.seconds, self.calls = {}, {}

    @contextmanager
    def phase(self, name):
        start = _time.perf_counter()
        try:
            yield
        finally:
            self.add(name, _time.perf_counter() - start)

    def add(self, name, seconds):
        self.seconds[name] = self.seconds.get(name, 0.0) + seconds
        self.calls[name] = self.calls.get(name, 0) + 1

    def wrap(self, name, function):
        """``function`` timed under ``name``."""
        def timed(*args, **kw):
            start = _time.perf_counter()
            try:
                return function(*args, **kw)
            finally:
                self.add(name, _time.perf_counter() - start)
        return timed


class EvaluationClock(Clock):
    """Counts and times a connector's force evaluations and Jacobians (``simulate(profile=True)``):
    Exudyn's user functions look both up on the connector at each call."""

    def __init__(self, connector):
        super().__init__()
        connector.residual_forces = self.wrap("force_evaluations", connector.residual_forces)
        connector.jacobian = self.wrap("jacobians", connector.jacobian)

    def split(self, steps: int, integration_s: float) -> dict:
        """The integration's parts: counts, s, per step and each."""
        n_f, n_j = self.calls.get("force_evaluations", 0), self.calls.get("jacobians", 0)
        t_f, t_j = self.seconds.get("force_evaluations", 0.0), self.seconds.get("jacobians", 0.0)
        return {"steps": steps, "force_evaluations": n_f, "force_evaluations_per_step": n_f / max(steps, 1),
                "force_evaluations_s": t_f, "force_evaluation_us": 1e6 * t_f / max(n_f, 1), "jacobians": n_j,
                "jacobians_s": t_j, "jacobian_ms": 1e3 * t_j / max(n_j, 1),
                "exudyn_and_glue_s": integration_s - t_f - t_j}
