"""The block Jacobian's compiled parts (MODEL.md §10): the perturbed states of all columns at
once, the difference quotients, and the chain-rule columns (a ball's rotation columns from its
angular-velocity columns, a race's translation columns from the balls')."""
from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["jacobian_states", "jacobian_assemble", "ball_rotation_columns", "race_translation_columns"]


@njit(cache=True, error_model="numpy")
def jacobian_states(pos, rot, vel, w_local, columns, eps, turn, states):
    """The block Jacobian's states (:func:`exudyn_bearing.jacobian.block_jacobian`): state 0 the
    base, state i + 1 column i's perturbation of every node of its group — position ``eps[0]``,
    rotation A -> A turn[k - 3] (``turn`` = exp(eps[1] e_k~)), velocity ``eps[2]``, local
    angular velocity ``eps[3]``. ``columns`` = (group, coordinate k, velocity column?, group
    mask (groups, n)) per column; writes ``states`` = (p2, r2, v2 and the GLOBAL angular
    velocities w2), B = 1 + columns; returns the step of each column."""
    col_group, col_k, col_v, group_mask = columns
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
    for i in range(ncol):
        k = col_k[i]
        steps[i] = (eps[2] if k < 3 else eps[3]) if col_v[i] else (eps[0] if k < 3 else eps[1])
        for s in range(n):
            if not group_mask[col_group[i], s]:
                continue
            if col_v[i]:
                if k < 3:
                    v2[i + 1, s, k] += eps[2]
                else:
                    wl[i + 1, s, k - 3] += eps[3]
            elif k < 3:
                p2[i + 1, s, k] += eps[0]
            else:
                a = r2[i + 1, s].copy()
                e = turn[k - 3]
                for r in range(3):
                    for c in range(3):
                        r2[i + 1, s, r, c] = a[r, 0] * e[0, c] + a[r, 1] * e[1, c] + a[r, 2] * e[2, c]
    for b in range(ncol + 1):
        for s in range(n):
            for r in range(3):
                w2[b, s, r] = r2[b, s, r, 0] * wl[b, s, 0] + r2[b, s, r, 1] * wl[b, s, 1] + r2[b, s, r, 2] * wl[b, s, 2]
    return steps


@njit(cache=True, error_model="numpy")
def jacobian_assemble(out, react, steps, columns, f_q, f_qt, jac):
    """-(f_q dF/dq + f_qt dF/dq_t) from the forces of :func:`jacobian_states`' states
    (out (B, n, 6), per-ball race/cage parts react (B, Z, n, 6)) into ``jac`` (6n, 6n):
    a column of a block group (the balls, each coupled only to itself and the races/cage)
    fills each ball's own block and that ball's part of the race/cage rows; any other
    column is the whole force change. ``columns`` = (group, coordinate k, velocity column?)
    per column, (block group?, slot) per group, the balls' slots and the other slots."""
    col_group, col_k, col_v, group_block, group_slot, balls, others = columns
    jac[:] = 0.0
    n = out.shape[1]
    for i in range(col_group.shape[0]):
        fac = (f_qt if col_v[i] else f_q) / steps[i]
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
def race_translation_columns(react, steps, tcol, chain, chain_rows, balls, pos, rot, f_q, f_qt, jac):
    """Adds the translation columns of the races ``chain`` (node slots) to ``jac`` from the
    balls' translation columns of :func:`jacobian_states`' states (``tcol[0, k]``, ``tcol[1, k]``:
    the ball group's position and velocity column k) instead of six more perturbed states per
    race. A ball-race contact depends on the ball's and the race's positions (and velocities)
    only through their differences, so moving race s by e_k changes ball j's contact as moving
    ball j by -e_k: its force F and moment M on the ball (ball rows: -(dF, A_b^T dM)) and its
    reaction G = -(F, A_s^T (l x F + M)), l = c_j - x_s, on the race (race rows: -dG). ``react``
    (B, Z, len(chain), 6): each ball's reaction on each chain race before held components were
    zeroed; ``chain_rows``: 6, or 3 for a race held in rotation (its moment rows stay zero)."""
    for m in range(chain.shape[0]):
        s = chain[m]
        A = rot[s]
        for kind in range(2):
            for k in range(3):
                i = tcol[kind, k]
                fac = (f_q if kind == 0 else f_qt) / steps[i]
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
                    if kind == 0:
                        e = np.zeros(3)
                        e[k] = steps[i]
                        dM[0] -= e[1] * F[2] - e[2] * F[1]
                        dM[1] -= e[2] * F[0] - e[0] * F[2]
                        dM[2] -= e[0] * F[1] - e[1] * F[0]
                    for r in range(3):
                        jac[6 * b + r, col] += fac * dF[r]
                        jac[6 * b + 3 + r, col] += fac * (Ab[0, r] * dM[0] + Ab[1, r] * dM[1] + Ab[2, r] * dM[2])
                    for r in range(chain_rows[m]):
                        jac[6 * s + r, col] += fac * (react[i + 1, jb, m, r] - react[0, jb, m, r])
