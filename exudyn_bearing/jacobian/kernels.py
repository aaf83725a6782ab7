"""The block Jacobian's compiled parts (MODEL.md §10): the perturbed states of all columns at
once, the difference quotients, and the chain-rule columns (a ball's rotation columns from its
angular-velocity columns, a race's translation columns from the balls')."""
from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["POSITION", "VELOCITY", "COMBINED", "jacobian_states", "jacobian_assemble", "ball_rotation_columns",
           "race_translation_columns"]

#: a column's kind: its states move the coordinate, its velocity, or both at once in the ratio
#: f_q : f_qt of the Jacobian Exudyn asks for (MODEL.md §10)
POSITION, VELOCITY, COMBINED = 0, 1, 2


@njit(cache=True, error_model="numpy")
def jacobian_states(pos, rot, vel, w_local, columns, eps, turn, states):
    """The block Jacobian's states (:func:`exudyn_bearing.jacobian.block_jacobian`): state 0 the
    base, state i + 1 column i's perturbation of every node of its group. ``columns`` =
    (group, coordinate k, kind, group mask (groups, n)) per column, kind :data:`POSITION`
    (position ``eps[0]``, rotation A -> A turn[0, k - 3] with turn[0] = exp(eps[1] e_k~)),
    :data:`VELOCITY` (velocity ``eps[2]``, local angular velocity ``eps[3]``) or
    :data:`COMBINED` (step c = ``eps[4]`` (translation) or ``eps[5]`` (rotation): the coordinate
    by c f_q — A -> A turn[1, k - 3] — and its velocity by c f_qt, f_q, f_qt = ``eps[6:8]``);
    writes ``states`` = (p2, r2, v2 and the GLOBAL angular velocities w2), B = 1 + columns;
    returns the step of each column (the divisor of its difference quotient)."""
    col_group, col_k, col_kind, group_mask = columns
    p2, r2, v2, w2 = states
    n = pos.shape[0]
    ncol = col_group.shape[0]
    wl = np.empty((ncol + 1, n, 3))
    for b in range(ncol + 1):
        p2[b] = pos
        r2[b] = rot
        v2[b] = vel
        wl[b] = w_local
    steps = np.empty(ncol)
    f_q, f_qt = eps[6], eps[7]
    for i in range(ncol):
        k = col_k[i]
        kind = col_kind[i]
        if kind == COMBINED:
            steps[i] = eps[4] if k < 3 else eps[5]
        elif kind == VELOCITY:
            steps[i] = eps[2] if k < 3 else eps[3]
        else:
            steps[i] = eps[0] if k < 3 else eps[1]
        move = steps[i] * f_q if kind == COMBINED else steps[i]  # the coordinate's step
        speed = steps[i] * f_qt if kind == COMBINED else steps[i]  # the velocity's step
        for s in range(n):
            if not group_mask[col_group[i], s]:
                continue
            if kind != POSITION:
                if k < 3:
                    v2[i + 1, s, k] += speed
                else:
                    wl[i + 1, s, k - 3] += speed
            if kind == VELOCITY:
                continue
            if k < 3:
                p2[i + 1, s, k] += move
            else:
                a = r2[i + 1, s].copy()
                e = turn[1 if kind == COMBINED else 0, k - 3]
                for r in range(3):
                    for c in range(3):
                        r2[i + 1, s, r, c] = a[r, 0] * e[0, c] + a[r, 1] * e[1, c] + a[r, 2] * e[2, c]
    for b in range(ncol + 1):
        for s in range(n):
            for r in range(3):
                w2[b, s, r] = r2[b, s, r, 0] * wl[b, s, 0] + r2[b, s, r, 1] * wl[b, s, 1] + r2[b, s, r, 2] * wl[b, s, 2]
    return steps


@njit(cache=True, error_model="numpy")
def column_weight(kind, f_q, f_qt):
    """The factor of a column's difference quotient in -(f_q dF/dq + f_qt dF/dq_t): f_q for a
    position column, f_qt for a velocity column, 1 for a combined one (its states moved both
    by the ratio f_q : f_qt)."""
    if kind == POSITION:
        return f_q
    if kind == VELOCITY:
        return f_qt
    return 1.0


@njit(cache=True, error_model="numpy")
def jacobian_assemble(out, react, steps, columns, f_q, f_qt, jac):
    """-(f_q dF/dq + f_qt dF/dq_t) from the forces of :func:`jacobian_states`' states
    (out (B, n, 6), per-ball race/cage parts react (B, Z, n, 6)) into ``jac`` (6n, 6n),
    each column's quotient weighted by :func:`column_weight`:
    a column of a block group (the balls, each coupled only to itself and the races/cage)
    fills each ball's own block and that ball's part of the race/cage rows; any other
    column is the whole force change. ``columns`` = (group, coordinate k, kind) per column,
    (block group?, slot) per group, the balls' slots and the other slots."""
    col_group, col_k, col_kind, group_block, group_slot, balls, others = columns
    jac[:] = 0.0
    n = out.shape[1]
    for i in range(col_group.shape[0]):
        fac = column_weight(col_kind[i], f_q, f_qt) / steps[i]
        k = col_k[i]
        g = col_group[i]
        if group_block[g]:
            for j in range(balls.shape[0]):
                b = balls[j]
                col = 6 * b + k
                for r in range(6):
                    jac[6 * b + r, col] -= fac * (out[i + 1, b, r] - out[0, b, r])
                for s in others:
                    for r in range(6):
                        jac[6 * s + r, col] -= fac * (react[i + 1, j, s, r] - react[0, j, s, r])
        else:
            col = 6 * group_slot[g] + k
            for s in range(n):
                for r in range(6):
                    d = out[i + 1, s, r] - out[0, s, r]
                    for j in range(balls.shape[0]):
                        d += react[i + 1, j, s, r] - react[0, j, s, r]
                    jac[6 * s + r, col] -= fac * d


@njit(cache=True, error_model="numpy")
def ball_rotation_columns(out, react, steps, wcol, group_block, ball_group, balls, others, w_local, f_q, jac):
    """Adds -f_q dF/d theta_k, the balls' rotation columns, to ``jac`` from the local
    angular velocity columns of :func:`jacobian_states`' states (``wcol[g]``: the column
    indices of group g's omega_1..3, -1 where g is no ball group) instead of three more
    perturbed states (MODEL.md §10). A ball's forces depend on its orientation A only
    through omega = A w_l and through the moment rows A^T M, so for A -> A exp(eps e_k~):
    dF/d theta_k = sum_j (e_k x w_l)_j dF/dw_l,j, and the ball's own moment rows take
    -(e_k x A^T M) besides."""
    n = out.shape[1]
    cvec = np.empty(3)
    for jb in range(balls.shape[0]):
        b = balls[jb]
        g = ball_group[jb]
        w = w_local[b]
        m = out[0, b, 3:6]
        for k in range(3):
            if k == 0:
                cvec[0], cvec[1], cvec[2] = 0.0, -w[2], w[1]
            elif k == 1:
                cvec[0], cvec[1], cvec[2] = w[2], 0.0, -w[0]
            else:
                cvec[0], cvec[1], cvec[2] = -w[1], w[0], 0.0
            col = 6 * b + 3 + k
            for s in range(n):
                if group_block[g] and s != b:
                    is_other = False
                    for o in others:
                        if o == s:
                            is_other = True
                    if not is_other:
                        continue
                for r in range(6):
                    d = 0.0
                    for j in range(3):
                        i = wcol[g, j]
                        if group_block[g]:
                            if s == b:
                                diff = out[i + 1, b, r] - out[0, b, r]
                            else:
                                diff = react[i + 1, jb, s, r] - react[0, jb, s, r]
                        else:
                            diff = out[i + 1, s, r] - out[0, s, r]
                            for jj in range(balls.shape[0]):
                                diff += react[i + 1, jj, s, r] - react[0, jj, s, r]
                        d += cvec[j] * diff / steps[i]
                    if s == b and r >= 3:  # -(e_k x A^T M) of the turned moment rows
                        if k == 0:
                            d -= (0.0, -m[2], m[1])[r - 3]
                        elif k == 1:
                            d -= (m[2], 0.0, -m[0])[r - 3]
                        else:
                            d -= (-m[1], m[0], 0.0)[r - 3]
                    jac[6 * s + r, col] -= f_q * d


@njit(cache=True, error_model="numpy")
def race_translation_columns(react, steps, tcol, kinds, chain, chain_rows, balls, pos, rot, f_q, f_qt, jac):
    """Adds the translation columns of the races ``chain`` (node slots) to ``jac`` from the
    balls' translation columns of :func:`jacobian_states`' states (``tcol[0, k]``, ``tcol[1, k]``:
    the ball group's position and velocity column k, both the same column where it is
    :data:`COMBINED`; ``kinds`` the columns' kinds) instead of six more perturbed states per
    race. A ball-race contact depends on the ball's and the race's positions (and velocities)
    only through their differences, so moving race s by e_k changes ball j's contact as moving
    ball j by -e_k: its force F and moment M on the ball (ball rows: -(dF, A_b^T dM)) and its
    reaction G = -(F, A_s^T (l x F + M)), l = c_j - x_s, on the race (race rows: -dG). ``react``
    (B, Z, len(chain), 6): each ball's reaction on each chain race before held components were
    zeroed; ``chain_rows``: 6, or 3 for a race held in rotation (its moment rows stay zero)."""
    for m in range(chain.shape[0]):
        s = chain[m]
        A = rot[s]
        for row in range(2):  # tcol's rows: the position columns, the velocity columns
            for k in range(3):
                i = tcol[row, k]
                if row == 1 and i == tcol[0, k]:  # a combined column: taken once
                    continue
                kind = kinds[i]
                fac = column_weight(kind, f_q, f_qt) / steps[i]
                moved = 0.0 if kind == VELOCITY else steps[i] * (f_q if kind == COMBINED else 1.0)
                col = 6 * s + k
                for jb in range(balls.shape[0]):
                    b = balls[jb]
                    Ab = rot[b]
                    dF = np.empty(3)
                    dG = np.empty(3)
                    F = np.empty(3)
                    lever = np.empty(3)
                    for r in range(3):
                        dF[r] = -(react[i + 1, jb, m, r] - react[0, jb, m, r])
                        dG[r] = react[i + 1, jb, m, 3 + r] - react[0, jb, m, 3 + r]
                        F[r] = -react[i + 1, jb, m, r]  # the perturbed force: exact with the lever's step
                        lever[r] = pos[b, r] - pos[s, r]
                    # dM = -A dG - l x dF (- step e_k x F' for a position step)
                    dM = np.empty(3)
                    for r in range(3):
                        dM[r] = -(A[r, 0] * dG[0] + A[r, 1] * dG[1] + A[r, 2] * dG[2])
                    dM[0] -= lever[1] * dF[2] - lever[2] * dF[1]
                    dM[1] -= lever[2] * dF[0] - lever[0] * dF[2]
                    dM[2] -= lever[0] * dF[1] - lever[1] * dF[0]
                    if moved != 0.0:
                        e = np.zeros(3)
                        e[k] = moved
                        dM[0] -= e[1] * F[2] - e[2] * F[1]
                        dM[1] -= e[2] * F[0] - e[0] * F[2]
                        dM[2] -= e[0] * F[1] - e[1] * F[0]
                    for r in range(3):
                        jac[6 * b + r, col] += fac * dF[r]
                        jac[6 * b + 3 + r, col] += fac * (Ab[0, r] * dM[0] + Ab[1, r] * dM[1] + Ab[2, r] * dM[2])
                    for r in range(chain_rows[m]):
                        jac[6 * s + r, col] += fac * (react[i + 1, jb, m, r] - react[0, jb, m, r])
