"""How a run is integrated: the solver, its step, tolerances and output (:class:`SolverSettings`;
MODEL.md §10)."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

__all__ = ["SOLVERS", "SolverSettings"]

SOLVERS = ("generalized-alpha", "trapezoidal", "rk44", "dopri5")


@dataclass(frozen=True)
class SolverSettings:
    """Time integration of a bearing model.

    Parameters
    ----------
    solver : {'generalized-alpha', 'trapezoidal', 'rk44', 'dopri5'}
        Exudyn's implicit generalized-alpha (numerical damping ``spectral_radius``), the
        undamped trapezoidal rule (Newmark, rho_inf = 1), explicit Lie-group RK44 at a
        fixed step, or adaptive DOPRI5 (``step`` is the initial/maximum step).
    step : float or None
        Time step, s. None (default): each bearing's ``RecommendedStep()`` (1e-4 s, less for
        small balls at high contact stiffness; :mod:`exudyn_bearing.model.steprule`), the smallest.
    spectral_radius : float
        rho_inf of generalized-alpha. 0.5 by default: with 0.8 a pure-axial 1 kN run grows a
        spurious radial oscillation of the free inner race from ~0.2 s (ball orbital speeds
        spread 33–93 rad/s, balls unloading) and fails near 0.5 s; with 0.5 it stays
        uniform to 0.7 s at about the same cost (docs/work_precision).
    relative_tolerance : float
    absolute_tolerance : float or None
        Newton (implicit; Exudyn's residual norm relative to the step's initial residual,
        and in N) or error (DOPRI5) tolerances; Newton stops at whichever it meets first.
        Relative 1e-4 by default (docs/work_precision, 1.3 kN at 1e-4 s: kinematic cage slip
        error 2.9e-3 pp at 1e-4 and at 1e-6, the step's error dominates; 430 instead of 611
        Newton iterations; 1e-3: 2.5e-2 pp). Absolute None (default): for the implicit
        solvers the smallest ``RecommendedAbsoluteTolerance()`` of the bearings, 3e-5 of
        their largest contact load (the force law's resolution, MODEL.md §10b), else 1e-6.
    jacobian : {'block', 'exudyn'}
        Implicit solvers: the connector's block finite-difference Jacobian or Exudyn's
        own numerical one.
    newton_contractivity : float
        Implicit solvers: modified Newton recomputes the Jacobian when an iteration reduces
        the residual by less than this factor (Exudyn's ``modifiedNewtonContractivity``).
    step_recovery_iterations : int
        Implicit solvers: after a step cut, Exudyn grows the step again only once steps need
        at most this many Newton iterations (its ``adaptiveStepRecoveryIterations``; Exudyn's
        default 7). 5: the 40-mm spindle bearing at 1 kN and 4 000 rpm (a thin ester film),
        whose steps converge at 2e-5 s but not at its default 3.33e-5 s, climbs back to the
        failing step every 10 steps with 7 (63.9 s wall per 0.1 s) and not with 5 (about
        12 s); with 4 the deep-groove case at 1 kN radial stays at the halved step after
        its start transient (2x its steps); docs/DEVELOPMENT.md, 'Solver defaults and the step rule'.
    predictor : bool
        Implicit solvers: start each step's Newton iteration from the previous step's
        acceleration of the bearings' nodes (:mod:`exudyn_bearing.model.predictor`, MODEL.md §10b)
        instead of Exudyn's zero acceleration. Same convergence test, fewer iterations.
    progress : bool
        Print where a run is (simulated time, wall time, time to go) to stderr every
        :data:`PROGRESS_PERIOD` s of wall time; runs shorter than that print nothing.
    output_step : float
        Period of the recorded states, s.
    passage_step : float or None
        Implicit solvers: the step while a ball passes a race defect, s (``step`` elsewhere;
        the passage windows are ``run_solver``'s ``windows``; MODEL.md §13c). None: ``step``
        throughout.
    """

    solver: str = "generalized-alpha"
    step: float | None = None
    spectral_radius: float = 0.5
    relative_tolerance: float = 1e-4
    absolute_tolerance: float | None = None
    jacobian: str = "block"
    output_step: float = 1e-4
    newton_contractivity: float = 0.5
    step_recovery_iterations: int = 5
    predictor: bool = True
    progress: bool = True
    passage_step: float | None = None

    def __post_init__(self) -> None:
        if self.solver not in SOLVERS:
            raise ValueError(f"solver must be one of {SOLVERS}, got {self.solver!r}")
        for name in ("step", "relative_tolerance", "absolute_tolerance", "output_step", "passage_step"):
            value = getattr(self, name)
            if name in ("step", "absolute_tolerance", "passage_step") and value is None:
                continue
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} must be positive, got {value!r}")
        if not 0.0 <= self.spectral_radius <= 1.0:
            raise ValueError(f"spectral_radius must lie in [0, 1], got {self.spectral_radius!r}")
        if not 0.0 < self.newton_contractivity < 1.0:
            raise ValueError(f"newton_contractivity must lie in (0, 1), got {self.newton_contractivity!r}")
        if self.jacobian not in ("block", "exudyn"):
            raise ValueError(f"jacobian must be 'block' or 'exudyn', got {self.jacobian!r}")
        if isinstance(self.step_recovery_iterations, bool) or not (
                isinstance(self.step_recovery_iterations, int) and self.step_recovery_iterations >= 1):
            raise ValueError(f"step_recovery_iterations must be an integer >= 1, got {self.step_recovery_iterations!r}")

    def resolved(self, handles) -> "SolverSettings":
        """These settings with ``step`` None replaced by the smallest ``RecommendedStep()``
        of the bearing ``handles`` (1e-4 s without any), and ``absolute_tolerance`` None by
        the smallest ``RecommendedAbsoluteTolerance()`` (implicit solvers; else 1e-6)."""
        from ..model.steprule import MIN_ABSOLUTE_TOLERANCE, NOMINAL_STEP

        settings = self
        if settings.step is None:
            steps = [h.RecommendedStep() for h in handles if hasattr(h, "RecommendedStep")]
            settings = replace(settings, step=min(steps, default=NOMINAL_STEP))
        if settings.absolute_tolerance is None:
            tolerances = [h.RecommendedAbsoluteTolerance() for h in handles
                          if settings.implicit and hasattr(h, "RecommendedAbsoluteTolerance")]
            settings = replace(settings, absolute_tolerance=min(tolerances, default=MIN_ABSOLUTE_TOLERANCE))
        return settings

    @property
    def implicit(self) -> bool:
        return self.solver in ("generalized-alpha", "trapezoidal")
