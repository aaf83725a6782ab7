"""The residual at the start of a predicted Newton step, from the predicted iterate's forces
and the last Jacobian (MODEL.md §10b).

Exudyn evaluates every force at the zero-acceleration start of a step before its first Newton
iteration. Where the step is predicted (:mod:`exudyn_bearing.model.predictor`), that residual
serves one purpose only: its norm is the reference of the relative convergence test (the
first increment it gives is replaced by the predicted iterate; in an assembly the items that
are not a bearing's keep theirs, which the linearized residual moves a little). The predicted iterate lies one
Exudyn increment δ = a_n/β' from the start, and its forces are the next evaluation anyway. So
:class:`StartResidual` evaluates the bearing at the predicted iterate when Exudyn asks for the
start, returns the start's forces linearized from there with the last block Jacobian,

    F(start) ≈ F(predicted) − (∂F/∂q + γ' ∂F/∂q̇) δ,

and serves the predicted iterate's forces, bit for bit the ones just computed, when Exudyn asks
for them: one evaluation a step fewer, the same Newton path from the predicted iterate on,
and a convergence reference off by the linearization's error (measured in DEVELOPMENT.md,
'The start residual from the predicted iterate'). Steps without a prediction, a Jacobian of
another step size, or a predicted iterate the forces refuse get the exact evaluation.

Its Jacobian function hands Exudyn the block Jacobian with the balls' rotation blocks turned
ahead by about half a step (:mod:`exudyn_bearing.jacobian.turn`, MODEL.md §10c), and keeps the
unturned one for the start residuals.
"""
from __future__ import annotations

import math

import numpy as np

from ..jacobian.turn import turn_ball_blocks

__all__ = ["StartResidual"]


class StartResidual:
    """A connector's force function for Exudyn (``forces``) and its Jacobian function
    (``jacobian``) with the start residual of predicted steps linearized (module docstring).

    ``connector``: the :class:`~exudyn_bearing.model.connector.BearingConnector` (its
    ``reference`` set: Exudyn's user functions see q without it)."""

    def __init__(self, connector):
        self.connector = connector
        #: (t s, predicted q and q̇ without reference, increment δ, γ' 1/s) of the next call
        self._expected = None
        #: (t, q, q̇, forces) of the predicted iterate, served once
        self._predicted = None
        #: (-(∂F/∂q + γ' ∂F/∂q̇), γ') of the last Jacobian
        self._jacobian = None
        #: start residuals linearized, and evaluated exactly instead (counts)
        self.linearized = self.exact = 0
        #: hand Exudyn the Jacobian with the balls' rotation blocks turned ahead (MODEL.md §10c)
        self.turn_ahead = True
        self._ball_rows = 6 * np.asarray(connector.layout["balls"], dtype=np.int64) + 3

    def reset(self):
        """Forget the Jacobian, the expected start and the predicted forces (a new solve)."""
        self._expected = self._predicted = self._jacobian = None

    def expect(self, t, q_predicted, v_predicted, increment, gamma_prime):
        """The next call is the start residual of a predicted step ending at ``t`` s; the step's
        predicted iterate (q without reference, q̇) and the increment δ to it (Exudyn's
        unknowns, m and rad) with γ' = γ/(hβ) 1/s."""
        self._expected = (t, q_predicted, v_predicted, increment, gamma_prime)

    def forces(self, t, q, q_t):
        """Exudyn's ``forceUserFunction``: the connector's generalized forces (6 per node slot)
        for q without reference and q̇."""
        expected, self._expected = self._expected, None
        if expected is not None:
            start = self._linearized(t, expected)
            if start is not None:
                return start
        predicted, self._predicted = self._predicted, None
        if predicted is not None and t == predicted[0] and np.array_equal(q, predicted[1]) \
                and np.array_equal(q_t, predicted[2]):
            return predicted[3]
        return self.connector.residual_forces(t, q, q_t)

    def jacobian(self, t, q, q_t, f_q, f_qt):
        """Exudyn's ``jacobianUserFunction`` (q without reference): the block Jacobian
        -(f_q ∂F/∂q + f_qt ∂F/∂q̇), kept for the start residuals, and handed to Exudyn with the
        balls' rotation blocks turned ahead by τ = f_q/f_qt (about half a step; MODEL.md §10c)."""
        q_t = np.asarray(q_t, dtype=float)
        jac = self.connector.jacobian(t, np.asarray(q) + self.connector.reference, q_t, f_q, f_qt)
        self._jacobian = (jac / f_q, f_qt / f_q) if f_q != 0.0 else None
        if self.turn_ahead and f_q != 0.0 and f_qt != 0.0 and math.isfinite(f_q / f_qt):
            jac = np.ascontiguousarray(jac, dtype=float)  # the block Jacobian's own new array
            turn_ball_blocks(jac, q_t, self._ball_rows, f_q / f_qt)
        return jac

    def _linearized(self, t, expected):
        """The start residual from the predicted iterate, None where it cannot be had."""
        t_expected, q_p, v_p, increment, gamma_prime = expected
        if self._jacobian is None or t != t_expected:
            self.exact += 1
            return None
        stiffness, ratio = self._jacobian
        if not math.isclose(ratio, gamma_prime, rel_tol=1e-12):  # a Jacobian of another step size
            self.exact += 1
            return None
        f_p = np.array(self.connector.residual_forces(t, q_p, v_p), dtype=float)
        if not np.all(np.isfinite(f_p)):  # refused (NaN): Exudyn's own start decides
            self.exact += 1
            return None
        self._predicted = (t, q_p, v_p, f_p)
        self.linearized += 1
        return f_p + stiffness @ increment
