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


def damped_newton(fun, x, lo, hi, tol, jac=None, max_iterations=25):
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

    Returns
    -------
    (x, worst, iterations) : the last iterate, its largest residual entry (above ``tol``
    where Newton stopped without converging: no descent or ``max_iterations``) and the
    number of Newton steps taken.
    """
    x = np.clip(np.asarray(x, dtype=float), lo, hi)
    f = fun(x)
    worst = float(np.max(np.abs(f)))
    for iteration in range(max_iterations):
        if worst <= tol:
            return x, worst, iteration
        matrix = forward_jacobian(fun, x, f) if jac is None else jac(x)
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
            return x, worst, iteration  # no descent along the Newton direction
        x, f = trial, f_trial
        worst = float(np.max(np.abs(f)))
    return x, worst, max_iterations
