"""Continuation along a straight path of loads or poses, each point solved by Newton's method
from the secant through the two before (MODEL.md §12a): the path of the quasi-dynamic
balance (:mod:`exudyn_bearing.solvers.quasidynamic`) from the axial steady state to the
combined load, a pose or a seated cage."""
from __future__ import annotations

import math

import numpy as np

from .newton import damped_newton

__all__ = ["continue_path", "PATH_TOLERANCE", "STEP_JACOBIANS", "STALL_FACTOR"]

#: Jacobians a continuation step's Newton may take (a good step takes 1-3)
STEP_JACOBIANS = 12
#: a step whose Newton spends :data:`STEP_JACOBIANS` and ends within this factor of the
#: tolerance has stalled: linear convergence, a near-singular balance
STALL_FACTOR = 1e3


#: the continuation's steps before its end stop at this largest scaled residual: a point on
#: the path is only the next step's start, the end is solved to the caller's tolerance
#: (MODEL.md §12a). Against the caller's 1e-8 at every step: the same end states (the builder's
#: starts within 1.1e-7 rad/s), 74 instead of 96 balances at 2.2 kN + 2 kN; and the CWRU 6205's
#: branch at 30 N axial goes on past 131 N radial, where Newton stalls at 1e-7-1e-6 (near-singular,
#: not a fold: the branch reaches 300 N). At 1e-4 (65 balances) a secant from two loose points
#: left the 40-mm spindle's end (1 kN + 500 N, 12 000 rpm, grown 100 K) at 7.9e-6
PATH_TOLERANCE = 1e-5


def continue_path(make, y, start, end, largest, tol, steps_left, describe, reserve=0):
    """Continuation of the unscaled unknowns ``y`` along the straight path from ``start`` to
    ``end`` (vectors of loads in N, or of a pose in m; ``make(point)`` builds the balance
    there, ``describe(point)`` names it) in steps of at most ``largest`` (same unit), halved
    where Newton fails (stalled below 1/100 of ``largest``), doubled back after an easy step,
    at most ``steps_left`` steps (None: no limit), of which ``reserve`` are needed after this
    path: it stops as soon as the rest cannot be covered in the steps left, even at ``largest``.
    The steps before the end are solved to :data:`PATH_TOLERANCE`, the end to ``tol``. With a
    budget it also stops where Newton stalls (:data:`STALL_FACTOR`) on two attempts in a row:
    a near-singular balance that Newton cannot solve to ``tol`` (MODEL.md §12a).
    Returns (y, worst residual, None or why it stopped, the last balance, steps left)."""
    start, end = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    span = float(np.linalg.norm(end - start))
    if span == 0.0:
        return y, 0.0, None, None, steps_left
    at = lambda t: start + t * (end - start)  # noqa: E731
    done, step, worst, balance = 0.0, min(1.0, largest / span), 0.0, None
    last = None  # (path parameter, state) of the step before, for the secant predictor
    stalls = 0  # stalled attempts in a row (at the default 1e-8 only the end can stall: a stall ends at
    # most STALL_FACTOR x tol = the path's tolerance)
    while done < 1.0:
        if steps_left is not None:
            # the fewest steps the rest takes: a budget that cannot cover them is spent in vain
            need = max(1, math.ceil((1.0 - done) * span / largest - 1e-9)) + reserve
            if steps_left < need:
                return y, worst, (f"continuation stopped: its steps ran out at {describe(at(done))} (the rest "
                                  f"of the path needs at least {need}, {steps_left} are left)"), balance, steps_left
            steps_left -= 1
        target = min(done + step, 1.0)
        aim = tol if target >= 1.0 else max(tol, PATH_TOLERANCE)
        balance = make(at(target))
        lo, hi = balance.bounds()
        guess = y if last is None else y + (y - last[1]) * (target - done) / (done - last[0])
        # a step that needs more Jacobians than this is better halved (a good one takes 1-3);
        # each costs 11 balances, so a Jacobian is kept while it converges (chord steps)
        x, worst, iterations = damped_newton(balance.residual, guess / balance.scale, lo, hi, aim, balance.jacobian,
                                             max_iterations=STEP_JACOBIANS, reuse_jacobian=True)
        if worst > aim and last is not None and iterations == 0:  # the extrapolation overshot: from y
            x, worst, iterations = damped_newton(balance.residual, y / balance.scale, lo, hi, aim, balance.jacobian,
                                                 max_iterations=STEP_JACOBIANS, reuse_jacobian=True)
        if worst <= aim:
            last, y, done, stalls = (done, y), x * balance.scale, target, 0
            if iterations <= 3:  # an easy step: the next may be longer, within the limit
                step = min(2.0 * step, largest / span)
            continue
        stalls = stalls + 1 if iterations >= STEP_JACOBIANS and worst <= STALL_FACTOR * tol else 0
        if stalls >= 2 and steps_left is not None:
            return y, worst, (f"no quasi-dynamic balance found beyond {describe(at(done))}: Newton stalls at "
                              f"{describe(at(target))} (largest scaled residual {worst:.2g} against {tol:.2g}, "
                              f"twice in a row), a near-singular balance"), balance, steps_left
        step *= 0.5
        if step < 0.01 * largest / span:
            return y, worst, (f"no quasi-dynamic balance found beyond {describe(at(done))} (largest "
                              f"scaled residual {worst:.2g} at {describe(at(target))})"), balance, steps_left
    return y, worst, None, balance, steps_left
