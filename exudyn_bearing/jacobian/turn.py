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

import math

from numba import njit

__all__ = ["turn_ball_blocks"]


@njit(cache=True, error_model="numpy")
def turn_ball_blocks(jac, q_t, ball_rows, tau):
    """Turns, in place, the rotation rows and columns of each ball of ``jac`` (6 n)² as the
    ball turns over ``tau`` s at its local angular velocity (rows ``ball_rows[j]`` to
    ``ball_rows[j] + 2`` of ``q_t``, rad/s): rows R^T J, columns J R, R = exp(ω̃ τ) (Rodrigues).
    Turned so, a ball's generalized moments and the difference quotients by its rotation
    coordinates are those at its turned orientation (MODEL.md §10c)."""
    n = jac.shape[0]
    tmp = [0.0, 0.0, 0.0]
    for j in range(ball_rows.shape[0]):
        r0 = ball_rows[j]
        x, y, z = q_t[r0] * tau, q_t[r0 + 1] * tau, q_t[r0 + 2] * tau
        angle2 = x * x + y * y + z * z
        if angle2 == 0.0:
            continue
        if angle2 < 1e-12:
            c1 = 1.0 - angle2 / 6.0
            c2 = 0.5 - angle2 / 24.0
        else:
            angle = math.sqrt(angle2)
            c1 = math.sin(angle) / angle
            c2 = (1.0 - math.cos(angle)) / angle2
        # R = I + c1 S + c2 S², S the skew matrix of (x, y, z)
        r00 = 1.0 + c2 * (x * x - angle2)
        r11 = 1.0 + c2 * (y * y - angle2)
        r22 = 1.0 + c2 * (z * z - angle2)
        r01 = -c1 * z + c2 * x * y
        r10 = c1 * z + c2 * x * y
        r02 = c1 * y + c2 * x * z
        r20 = -c1 * y + c2 * x * z
        r12 = -c1 * x + c2 * y * z
        r21 = c1 * x + c2 * y * z
        for col in range(n):  # rows: R^T J
            a, b, c = jac[r0, col], jac[r0 + 1, col], jac[r0 + 2, col]
            tmp[0] = r00 * a + r10 * b + r20 * c
            tmp[1] = r01 * a + r11 * b + r21 * c
            tmp[2] = r02 * a + r12 * b + r22 * c
            jac[r0, col], jac[r0 + 1, col], jac[r0 + 2, col] = tmp[0], tmp[1], tmp[2]
        for row in range(n):  # columns: J R
            a, b, c = jac[row, r0], jac[row, r0 + 1], jac[row, r0 + 2]
            tmp[0] = a * r00 + b * r10 + c * r20
            tmp[1] = a * r01 + b * r11 + c * r21
            tmp[2] = a * r02 + b * r12 + c * r22
            jac[row, r0], jac[row, r0 + 1], jac[row, r0 + 2] = tmp[0], tmp[1], tmp[2]
