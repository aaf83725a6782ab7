"""Difference-quotient Jacobians of small residual functions (the steady, quasi-dynamic,
quasi-static and shaft solvers)."""
from __future__ import annotations

import numpy as np

__all__ = ["forward_jacobian", "central_jacobian"]


def forward_jacobian(fun, x, f0=None, step=1e-6):
    """Forward-difference Jacobian of ``fun`` at ``x`` (columns one unknown at a time; the
    unknowns are scaled to order one, so one absolute ``step`` serves all)."""
    f0 = fun(x) if f0 is None else f0
    jac = np.empty((f0.size, x.size))
    for k in range(x.size):
        xk = x.copy()
        xk[k] += step
        jac[:, k] = (fun(xk) - f0) / step
    return jac


def central_jacobian(fun, x, steps, dofs):
    """Central-difference Jacobian of ``fun`` (vector -> vector) with respect to the entries
    ``dofs`` of ``x``, perturbed by ``steps[dof]``; shape (len(fun(x)), len(dofs))."""
    columns = []
    for dof in dofs:
        xp, xm = x.copy(), x.copy()
        xp[dof] += steps[dof]
        xm[dof] -= steps[dof]
        columns.append((fun(xp) - fun(xm)) / (2 * steps[dof]))
    return np.stack(columns, axis=1)
