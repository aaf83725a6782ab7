"""Newton's method for the square balance systems of the steady and quasi-dynamic solvers
(MODEL.md §12, §12a).

Both solve n equations in n scaled unknowns of order one within box bounds, from a start
near the root (a continuation step). SciPy's bounded trust-region least squares took tens
of iterations per step there (docs/DEVELOPMENT.md, 'Start states'); plain Newton with a
backtracking line search on the residual norm takes a handful.
"""
from __future__ import annotations

import numpy as np

from ..jacobian.differences import forward_jacobian

__all__ = ["damped_newton"]


#: with ``reuse_jacobian``, a Jacobian is kept while each full step shrinks the largest
#: residual entry at least this much (a chord step costs one residual, a Jacobian n of them)
CHORD_CONTRACTION = 0.25


def damped_newton(fun, x, lo, hi, tol, jac=None, max_iterations=25, reuse_jacobian=False):
    """Newton's method on ``fun`` (n equations, n unknowns) from ``x``, kept within the bounds
    (lo, hi) by clipping, with a backtracking line search on the residual norm (step halved
    down to 1/64 until the squared norm falls).

    Parameters
    ----------
    fun : callable
        Residual vector of the unknowns.
    x, lo, hi : ndarray
        Start and bounds of the (scaled) unknowns.
    tol : float
        Largest residual entry accepted.
    jac : callable, optional
        Jacobian of ``fun``; forward differences (:func:`forward_jacobian`) if None.
    max_iterations : int
        Most Jacobians evaluated.
    reuse_jacobian : bool
        Keep a Jacobian for the next step (a chord step) while full steps shrink the largest
        residual entry by :data:`CHORD_CONTRACTION` or more; a fresh one where they do not or
        where its direction does not descend. For an expensive Jacobian near the root.

    Returns
    -------
    (x, worst, iterations) : the last iterate, its largest residual entry (above ``tol``
    where Newton stopped without converging: no descent or ``max_iterations``) and the
    number of Jacobians whose steps were taken (the Newton steps, without reuse).
    """
    x = np.clip(np.asarray(x, dtype=float), lo, hi)
    f = fun(x)
    worst = float(np.max(np.abs(f)))
    matrix, fresh, jacobians, used = None, False, 0, 0
    for _ in range((4 if reuse_jacobian else 1) * max_iterations):  # chord steps are cheap, not endless
        if worst <= tol:
            break
        if matrix is None:
            if jacobians == max_iterations:
                break
            matrix = forward_jacobian(fun, x, f) if jac is None else jac(x)
            fresh, jacobians = True, jacobians + 1
        try:
            dx = np.linalg.solve(matrix, -f)
        except np.linalg.LinAlgError:
            dx = np.linalg.lstsq(matrix, -f, rcond=None)[0]
        norm, lam = float(f @ f), 1.0
        while lam >= 1.0 / 64.0:
            trial = np.clip(x + lam * dx, lo, hi)
            f_trial = fun(trial)
            if float(f_trial @ f_trial) < (1.0 - 1e-4 * lam) * norm:
                break
            lam *= 0.5
        else:
            if fresh:
                break  # no descent along the Newton direction
            matrix = None  # the kept Jacobian's direction: a fresh one
            continue
        used += fresh
        last = worst
        x, f = trial, f_trial
        worst = float(np.max(np.abs(f)))
        fresh = False
        if not reuse_jacobian or lam < 1.0 or worst > CHORD_CONTRACTION * last:
            matrix = None
    return x, worst, used
