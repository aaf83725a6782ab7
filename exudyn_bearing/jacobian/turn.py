"""The Jacobian Exudyn keeps, turned ahead with the balls (MODEL.md §10c).

Exudyn's rotation coordinates of a ball and the rows of its moments are the ball's own
(local rotation increments and angular velocity, body-frame moments). A ball's contact
forces depend on its global angular velocity, so its rotation rows and columns turn with the
ball: at 72 000 rpm a ball turns ~0.3 rad a step and those blocks change by ~30 % a step.
Modified Newton keeps a Jacobian over several steps, so :func:`turn_ball_blocks` hands Exudyn
the blocks as they will be a time τ later — the ball turned by exp(ω̃ τ) about its own
angular velocity ω, which leaves its global angular velocity and its forces as they are.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from contact import kernels
from contact.kernel_cache import drop_stale
from contact.kernels.race import rotation_matrices

# turn_ball_blocks calls the contact/ kernels' rotation_matrices: recompile it when they changed
drop_stale(__file__, [__file__, *kernels.SOURCES])

__all__ = ["turn_ball_blocks"]


@njit(cache=True, error_model="numpy")
def turn_ball_blocks(jac, q_t, ball_rows, tau):
    """Turns, in place, the rotation rows and columns of each ball of ``jac`` (6 n)² as the
    ball turns over ``tau`` s at its local angular velocity (rows ``ball_rows[j]`` to
    ``ball_rows[j] + 2`` of ``q_t``, rad/s): rows R^T J, columns J R, R = exp(ω̃ τ) (Rodrigues,
    :func:`contact.kernels.race.rotation_matrices`). Turned so, a ball's generalized moments and
    the difference quotients by its rotation coordinates are those at its turned orientation
    (MODEL.md §10c)."""
    n = jac.shape[0]
    turns = np.empty((ball_rows.shape[0], 3))
    for j in range(ball_rows.shape[0]):
        for i in range(3):
            turns[j, i] = q_t[ball_rows[j] + i] * tau
    rotations = rotation_matrices(turns)
    for j in range(ball_rows.shape[0]):
        r0 = ball_rows[j]
        R = rotations[j]
        for col in range(n):  # rows: R^T J
            a, b, c = jac[r0, col], jac[r0 + 1, col], jac[r0 + 2, col]
            for i in range(3):
                jac[r0 + i, col] = R[0, i] * a + R[1, i] * b + R[2, i] * c
        for row in range(n):  # columns: J R
            a, b, c = jac[row, r0], jac[row, r0 + 1], jac[row, r0 + 2]
            for i in range(3):
                jac[row, r0 + i] = a * R[0, i] + b * R[1, i] + c * R[2, i]
