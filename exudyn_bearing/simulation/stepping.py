"""The passage step only where a ball passes a defect (MODEL.md §13c): step control within one
Exudyn solve.

A vibration run needs its fine step (two steps per defect passage; the strike step where a
ball's contact opens over a defect) only while a contact crosses a defect and the strike's
ringing lasts: a few percent of the time. :class:`PassageStepper` is the implicit solver's
``UpdateCurrentTime`` user function: before each step it reads where every ball stands on
each race (the ball centre's azimuth in the race's own frame, the contact's azimuth, MODEL.md
§2) and takes the fine step while one lies inside a passage window
(:func:`exudyn_bearing.model.steprule.passage_windows`), the coarse step elsewhere. The balls'
actual positions decide, so the cage's slip does not shift the windows off the passages.

A step Exudyn cuts after Newton failed (it resets the time and shortens the step) is kept
short until ``recovery_steps`` steps in a row have converged, then doubled back, as Exudyn's
own adaptive step does.
"""
from __future__ import annotations

import math

import numpy as np

from ..races import node_rows

__all__ = ["PassageStepper", "passage_stepper", "solve_with_passages"]


class PassageStepper:
    """``UpdateCurrentTime`` of an ``exu.MainSolverImplicitSecondOrder``: ``coarse`` s away from
    the passage windows, ``fine`` s inside them (module docstring).

    Parameters
    ----------
    handles : list of BearingHandle
    windows : list
        Per handle, its :meth:`~exudyn_bearing.model.handle.BearingHandle.PassageWindows`
        rows (race, centre rad, half angle rad), or None (no windows: that bearing never asks
        for the fine step).
    coarse, fine : float
        The steps, s.
    recovery_steps : int
        Converged steps after a cut before the step doubles back.
    """

    def __init__(self, handles, windows, coarse: float, fine: float, recovery_steps: int = 10):
        if not (0.0 < fine <= coarse):
            raise ValueError(f"the passage step must lie in (0, coarse step {coarse:g} s], got {fine!r}")
        self.coarse, self.fine, self.recovery_steps = float(coarse), float(fine), int(recovery_steps)
        self._bearings = [(h, np.asarray(w, dtype=float)) for h, w in zip(handles, windows)
                          if w is not None and len(w)]
        self._rows = None
        self._limit = math.inf  # the step after a cut, until it has grown back
        self._since_cut = 0
        self._start, self._set = None, math.nan
        self.fine_time = 0.0  # simulated time of the converged steps at the fine step or below, s
        self.fine_steps = 0

    def near(self, mbs) -> bool:
        """Whether a ball of any bearing lies inside a passage window now."""
        if self._rows is None:
            self._rows = [node_rows(mbs, h.nodeNumbers) for h, _ in self._bearings]
        q = np.asarray(mbs.systemData.GetODE2Coordinates())
        for (h, windows), rows in zip(self._bearings, self._rows):
            con = h.connector
            pos, rot, _, _ = con.decode(q[rows] + con.reference, np.zeros(len(rows)))
            balls = pos[con.layout["balls"]]
            for k, name in enumerate(("inner", "outer")):
                mine = windows[windows[:, 0] == k]
                if not len(mine):
                    continue
                origin, frame = con.race_pose(name, pos, rot)
                local = (balls - origin) @ frame  # rows: Rᵀ (c − o)
                theta = np.arctan2(local[:, 1], local[:, 0])
                off = np.abs(np.remainder(theta[:, None] - mine[None, :, 1] + math.pi, 2 * math.pi) - math.pi)
                if np.any(off <= mine[None, :, 2]):
                    return True
        return False

    def __call__(self, solver, mbs, settings) -> bool:
        it = solver.it
        start = float(it.currentTime)
        if self._start is not None and abs(start - self._start) <= 1e-12 * max(1.0, abs(start)):
            # the same step again: Exudyn cut it (its own reduced step is in currentStepSize)
            self._limit, self._since_cut = min(float(it.currentStepSize), self._set), 0
        elif self._start is not None:
            self.finish()  # the last step converged
            if self._limit < math.inf:
                self._since_cut += 1
                if self._since_cut >= self.recovery_steps:
                    self._limit, self._since_cut = 2.0 * self._limit, 0
                    if self._limit >= self.coarse:
                        self._limit = math.inf
        h = min(self.fine if self.near(mbs) else self.coarse, self._limit)
        h = min(h, float(it.endTime) - start)
        self._start, self._set = start, h
        it.currentStepSize = h
        it.currentTime = start + h
        return True

    def finish(self) -> None:
        """Count the step last set as taken (at the fine step or below: into ``fine_time``)."""
        if self._set <= self.fine * (1.0 + 1e-9):
            self.fine_time += self._set
            self.fine_steps += 1
        self._set = math.nan


def passage_stepper(handles, settings, windows):
    """The :class:`PassageStepper` of a run whose ``settings`` (``SolverSettings``) have a passage
    step below their step and whose ``windows`` (per handle) hold one, else None."""
    if settings.passage_step is None or not settings.implicit or settings.passage_step >= settings.step:
        return None
    if windows is None or len(windows) != len(handles):
        raise ValueError("passage_step: give run_solver the windows, one handle's PassageWindows(...) or None each")
    if not any(w is not None and len(w) for w in windows):
        return None
    return PassageStepper(handles, windows, settings.step, settings.passage_step)


def solve_with_passages(mbs, simulation_settings, stepper: PassageStepper) -> bool:
    """``exu.SolveDynamic`` for an implicit solver with ``stepper`` deciding each step (stored
    as ``mbs.sys['dynamicSolver']`` as Exudyn's own function does)."""
    import exudyn as exu

    solver = exu.MainSolverImplicitSecondOrder()
    mbs.sys["dynamicSolver"] = solver
    mbs.sys["simulationSettings"] = simulation_settings
    solver.SetUserFunctionUpdateCurrentTime(mbs, stepper)
    ok = bool(solver.SolveSystem(mbs, simulation_settings))
    if ok:
        stepper.finish()  # the last step
    return ok
