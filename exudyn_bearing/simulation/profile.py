"""Where an integration's time goes: the connector's force evaluations and Jacobians counted
and timed (``simulate(profile=True)``, the CLI's ``--profile``; issue 52 item 1)."""
from __future__ import annotations

import time as _time

__all__ = ["EvaluationClock"]


class EvaluationClock:
    """Counts and times a connector's force evaluations and Jacobians (``simulate(profile=True)``):
    Exudyn's user functions look both up on the connector at each call."""

    def __init__(self, connector):
        self.seconds = {"force_evaluations": 0.0, "jacobians": 0.0}
        self.calls = {"force_evaluations": 0, "jacobians": 0}
        connector.residual_forces = self._timed("force_evaluations", connector.residual_forces)
        connector.jacobian = self._timed("jacobians", connector.jacobian)

    def _timed(self, name, function):
        def timed(*args, **kw):
            start = _time.perf_counter()
            try:
                return function(*args, **kw)
            finally:
                self.seconds[name] += _time.perf_counter() - start
                self.calls[name] += 1
        return timed

    def split(self, steps: int, integration_s: float) -> dict:
        """The integration's parts: counts, s, per step and each."""
        n_f, n_j = self.calls["force_evaluations"], self.calls["jacobians"]
        t_f, t_j = self.seconds["force_evaluations"], self.seconds["jacobians"]
        return {"steps": steps, "force_evaluations": n_f, "force_evaluations_per_step": n_f / max(steps, 1),
                "force_evaluations_s": t_f, "force_evaluation_us": 1e6 * t_f / max(n_f, 1), "jacobians": n_j,
                "jacobians_s": t_j, "jacobian_ms": 1e3 * t_j / max(n_j, 1),
                "exudyn_and_glue_s": integration_s - t_f - t_j}
