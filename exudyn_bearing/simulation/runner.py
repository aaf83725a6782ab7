"""Run an Exudyn model containing bearings with a named solver, and the one-bearing
``simulate`` job of the CLI (MODEL.md §10).
"""
from __future__ import annotations

import math
import sys
import time as _time
from dataclasses import asdict, dataclass, field, replace

import numpy as np

from contact.ballrace import ContactLaw
from ..bearing import BallDrag, Bearing
from ..bearingfile import as_setup
from ..cage import CageModel
from ..errors import BearingSimulationError
from ..model.predictor import VARIABLE as PREDICTOR_VARIABLE
from ..model.start_memo import keeping_starts
from ..model.thermal_nodes import UPDATE_PERIOD
from ..presets import REFERENCE_BEARING
from ..races import node_rows
from ..renamed import accepts_old_names
from ..results.records import assumptions_record, setup_inputs, units_of
from ..setup import FROM_SETUP, BearingSetup
from .profile import EvaluationClock
from .settings import SOLVERS, SolverSettings  # noqa: F401 (SOLVERS: part of this module's API)
from .stepping import passage_stepper, solve_with_passages

__all__ = ["SolverSettings", "RunInfo", "BearingSimulationError", "run_solver", "simulate"]

#: exceptions that mean a bug, passed on as they are instead of being reported as a solver
#: failure with solver advice (Exudyn wraps a user function's own exception in a ModelError
#: saying "Error in Python USER FUNCTION" and naming it: passed on too when it names one)
_PROGRAMMING_ERRORS = (NameError, AttributeError, TypeError, KeyError, IndexError, ImportError)

#: wall time between two progress lines of a run, s
PROGRESS_PERIOD = 5.0


class _Progress:
    """Progress of a run to stderr, at most every ``period`` s of wall time; called with the
    simulated time by each bearing's state recorder (builder)."""

    def __init__(self, end_time, period=None, stream=None):
        self.end, self.stream = end_time, stream
        self.period = PROGRESS_PERIOD if period is None else period
        self.start = self.last = _time.perf_counter()

    def __call__(self, t):
        now = _time.perf_counter()
        if now - self.last < self.period or not t > 0:
            return
        self.last = now
        done, wall = min(t / self.end, 1.0), now - self.start
        print(f"exudyn_bearing: t = {t:.4g} of {self.end:g} s ({100 * done:.0f} %), {wall:.0f} s wall, "
              f"about {wall * (1 - done) / done:.0f} s to go", file=self.stream or sys.stderr, flush=True)


@dataclass
class RunInfo:
    """What a run cost."""

    solver: dict
    wall_time_s: float
    steps: int
    newton_iterations: int | None = None
    jacobian_updates: int | None = None
    #: CPU time of the process over the run (all threads), s: the cost beside the wall time
    cpu_time_s: float | None = None
    #: end times, s, of the steps Newton failed and the solver tried again at a shorter step
    #: (implicit solvers of a scene with a bearing; None where not counted)
    cut_times: tuple | None = None
    #: simulated time and steps at the passage step (runs with one), s and count
    fine_time_s: float | None = None
    fine_steps: int | None = None


def _exudyn_settings(settings: SolverSettings, end_time: float):
    import exudyn as exu

    settings = settings.resolved([])  # a no-op for run_solver's settings, resolved per bearing

    s = exu.SimulationSettings()
    ti = s.timeIntegration
    ti.endTime = end_time
    ti.numberOfSteps = max(1, int(round(end_time / settings.step)))
    ti.verboseMode = 0
    ti.stepInformation = 0
    s.solution.file.write = False
    s.solution.sensors.writePeriod = settings.output_step
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    if settings.implicit:
        ti.solverType = exu.DynamicSolverType.GeneralizedAlpha
        ga = ti.generalizedAlpha
        if settings.solver == "trapezoidal":
            ga.useNewmark = True
            ga.spectralRadius = 1.0
            ga.newmarkBeta, ga.newmarkGamma = 0.25, 0.5
        else:
            ga.spectralRadius = settings.spectral_radius
        ti.newton.relativeTolerance = settings.relative_tolerance
        ti.newton.absoluteTolerance = settings.absolute_tolerance
        ti.newton.useModifiedNewton = True
        ti.newton.modifiedNewtonContractivity = settings.newton_contractivity
        ti.adaptiveStepRecoveryIterations = settings.step_recovery_iterations
    else:
        ti.solverType = exu.DynamicSolverType.RK44 if settings.solver == "rk44" else exu.DynamicSolverType.DOPRI5
        ti.explicit.useLieGroupIntegration = True
        if settings.solver == "dopri5":
            ti.relativeTolerance = settings.relative_tolerance
            ti.absoluteTolerance = settings.absolute_tolerance
            ti.minimumStepSize = 1e-12
            ti.initialStepSize = settings.step
    return s


def _where(handles, mbs=None) -> str:
    """Where a failed run went wrong: the most demanding contact of the last state and the
    first rejected (non-finite or out-of-groove) state, if any."""
    parts = []
    if mbs is not None:
        try:
            q = np.asarray(mbs.systemData.GetODE2Coordinates())
            q_t = np.asarray(mbs.systemData.GetODE2Coordinates_t())
            t = float(mbs.systemData.GetTime())
            for h in handles:
                idx = node_rows(mbs, h.nodeNumbers)
                if np.all(np.isfinite(q[idx])) and np.all(np.isfinite(q_t[idx])):
                    parts.append("last state: " + h.connector.diagnose(t, q[idx] + h.connector.reference, q_t[idx]))
        except Exception:  # noqa: BLE001 - diagnosis is best effort, never masks the failure
            pass
    parts += ["first rejected state: " + h.connector.first_non_finite for h in handles if h.connector.first_non_finite]
    if mbs is not None:
        for h in handles:
            try:
                verdict = h.connector.capacity(float(mbs.systemData.GetTime()))
            except Exception:  # noqa: BLE001 - best effort, as above
                verdict = ""
            if verdict:
                parts.insert(0, verdict)
    return " (" + "; ".join(parts) + ")" if parts else ""


_ADVICE = ("; Newton did not converge: the EHD traction is too stiff for this step. Use a smaller step "
           "(SolverSettings(step=...)) or a limiting shear stress (ContactLaw(limiting_shear=0.07))")


def run_solver(mbs, handles, end_time: float, settings=SolverSettings(), windows=None) -> RunInfo:
    """Integrate an assembled ``mbs`` containing the given bearing handles to
    ``end_time`` s (their connectors carry the block Jacobian from the builder;
    ``jacobian='exudyn'`` removes it) and check the result (raises
    :class:`BearingSimulationError` on divergence).

    ``settings``: :class:`SolverSettings` (the package's solver set-up: no solution file,
    quiet, sensors written every ``output_step``), or the user's own
    ``exu.SimulationSettings``, used as they are — solution file, console output, sensor
    periods, solver and tolerances — except ``endTime`` (= ``end_time``) and
    ``numberOfSteps``, which keeps the step ``endTime / numberOfSteps`` they held.

    ``windows``: per handle, its ``PassageWindows(...)`` (or None); with
    ``settings.passage_step`` the run takes that step while a ball lies in one and
    ``settings.step`` elsewhere (:class:`~exudyn_bearing.simulation.stepping.PassageStepper`);
    ``RunInfo.fine_time_s`` says how long."""
    import exudyn as exu

    if isinstance(settings, exu.SimulationSettings):
        return _run_user_settings(mbs, handles, end_time, settings)
    settings = settings.resolved(handles)
    for h in handles:  # the builder installed the block Jacobian; 'exudyn' takes Exudyn's own
        if settings.jacobian == "exudyn":
            mbs.SetObjectParameter(h.contactObject, "jacobianUserFunction", 0)
    for h in handles:
        h.connector.first_non_finite = None
        h.connector.progress = _Progress(end_time) if settings.progress and h is handles[0] else None
    s = _exudyn_settings(settings, end_time)
    predictor = mbs.variables.get(PREDICTOR_VARIABLE)
    predicting = getattr(predictor, "enabled", None)
    if predictor is not None:
        predictor.enabled = settings.predictor
    counted = len(predictor.cut_times) if predictor is not None else 0
    printing = exu.config.printToConsole
    exu.config.printToConsole = False  # quiet for the run, restored below
    stepper = passage_stepper(handles, settings, windows)
    start, cpu = _time.perf_counter(), _time.process_time()
    try:
        if stepper is None:
            ok = exu.SolveDynamic(mbs, s, solverType=s.timeIntegration.solverType, showHints=False,
                                  showCausingItems=False)
        else:
            ok = solve_with_passages(mbs, s, stepper)
    except Exception as err:  # Exudyn raises on Newton failure or NaN
        text = str(err)
        if isinstance(err, _PROGRAMMING_ERRORS) or ("Error in Python USER FUNCTION" in text and any(
                f"{kind.__name__}:" in text for kind in _PROGRAMMING_ERRORS)):
            raise  # a bug in a user function (ours or the scene's) is not a solver failure
        where = _where(handles, mbs)
        overloaded = "overloads the bearing" in where or "cannot carry it" in where
        raise BearingSimulationError(f"solver {settings.solver} failed at step {settings.step:g} s{where}: {err}"
                                     + (_ADVICE if settings.implicit and not overloaded else "")) from err
    finally:
        exu.config.printToConsole = printing
        if predictor is not None:
            predictor.enabled = predicting
        for h in handles:
            h.connector.progress = None
    wall, cpu = _time.perf_counter() - start, _time.process_time() - cpu
    sol = mbs.sys.get("dynamicSolver")
    it = getattr(sol, "it", None)
    info = RunInfo(asdict(settings), wall, int(getattr(it, "currentStepIndex", 0) or s.timeIntegration.numberOfSteps),
                   getattr(it, "newtonStepsCount", None), getattr(it, "newtonJacobiCount", None), cpu,
                   _cut_times(predictor, counted, settings.implicit))
    if stepper is not None:
        info.fine_time_s, info.fine_steps = stepper.fine_time, stepper.fine_steps
    if not ok:
        raise BearingSimulationError(f"solver {settings.solver} did not finish (step {settings.step:g} s)"
                                     f"{_where(handles, mbs)}; try a smaller step or generalized-alpha")
    q = np.asarray(mbs.systemData.GetODE2Coordinates())
    if not np.all(np.isfinite(q)) or not np.all(np.isfinite(mbs.systemData.GetODE2Coordinates_t())):
        raise BearingSimulationError(f"solver {settings.solver} diverged (step {settings.step:g} s){_where(handles, mbs)}: "
                                     "the contacts are too stiff for this step; use generalized-alpha or a smaller step")
    return info


def _cut_times(predictor, counted, implicit):
    """The step cuts the system's predictor hook recorded after its first ``counted`` (a
    tuple of end times, s), None without the hook or for an explicit solver (no Newton)."""
    return tuple(predictor.cut_times[counted:]) if predictor is not None and implicit else None


def _run_user_settings(mbs, handles, end_time, s) -> RunInfo:
    """:func:`run_solver` with a user's ``exu.SimulationSettings`` (left as they are but the
    end time and the number of steps for the same step)."""
    import exudyn as exu

    if not (math.isfinite(end_time) and end_time > 0):
        raise ValueError(f"end_time must be positive, got {end_time!r}")
    ti = s.timeIntegration
    step = ti.endTime / max(ti.numberOfSteps, 1)
    ti.endTime = end_time
    ti.numberOfSteps = max(1, int(round(end_time / step)))
    for h in handles:
        h.connector.first_non_finite = None
    predictor = mbs.variables.get(PREDICTOR_VARIABLE)
    counted = len(predictor.cut_times) if predictor is not None else 0
    implicit = ti.solverType in (exu.DynamicSolverType.GeneralizedAlpha, exu.DynamicSolverType.TrapezoidalIndex2)
    start, cpu = _time.perf_counter(), _time.process_time()
    try:
        ok = exu.SolveDynamic(mbs, s)
    except Exception as err:  # Exudyn raises on Newton failure or NaN
        raise BearingSimulationError(f"exu.SolveDynamic failed at step {step:g} s{_where(handles, mbs)}: {err}") from err
    wall, cpu = _time.perf_counter() - start, _time.process_time() - cpu
    it = getattr(mbs.sys.get("dynamicSolver"), "it", None)
    info = RunInfo({"solver": str(ti.solverType), "step": step, "user_settings": True}, wall,
                   int(getattr(it, "currentStepIndex", 0) or ti.numberOfSteps),
                   getattr(it, "newtonStepsCount", None), getattr(it, "newtonJacobiCount", None), cpu,
                   _cut_times(predictor, counted, implicit))
    q = np.asarray(mbs.systemData.GetODE2Coordinates())
    if not ok or not np.all(np.isfinite(q)):
        raise BearingSimulationError(f"exu.SolveDynamic did not finish (step {step:g} s){_where(handles, mbs)}")
    return info


#: summary entries that are SimulationSummary fields of their own (not repeated in ``details``)
_SUMMARY_FIELDS = ("settled", "power_loss_W", "drive_power_W", "kinematic_cage_slip_percent", "cage_slip_percent",
                   "cage_speed", "cage_speed_nominal")


@dataclass
class SimulationSummary:
    """Result of :func:`simulate` (the CLI's JSON)."""

    axial: float
    radial: float
    rpm: float
    time: float
    #: the skid measure: cage slip against the pure-rolling speed of the balls' own contact
    #: angles, % (MODEL.md §7)
    kinematic_cage_slip_percent: float
    #: the paper's P19, against the nominal pure-rolling cage speed, %
    cage_slip_percent: float
    cage_speed: float
    cage_speed_nominal: float
    #: True / False; None: too short to judge (shorter than 0.05 s, :meth:`BearingResults.settled`)
    settled: bool | None
    wall_time_s: float
    steps: int
    solver: dict
    newton_iterations: int | None
    jacobian_updates: int | None
    details: dict = field(default_factory=dict)
    error_estimate: dict | None = None
    results: object = field(default=None, repr=False)
    #: the :class:`~exudyn_bearing.solvers.steady.SteadyState` the run started from, or None
    initial_steady_state: object = field(default=None, repr=False)
    #: mean power loss over the summary window by source and 'total', W (MODEL.md §11)
    power_loss_W: dict = field(default_factory=dict)
    #: mean power the races put into the balls, W (equals the total loss when settled)
    drive_power_W: float | None = None

    #: what produced it (:func:`exudyn_bearing.results.records.inputs_record`)
    inputs: dict = field(default_factory=dict)
    #: CPU time of the run, all threads, s (the contact kernels run on numba's threads, so
    #: wall_time_s can be below it)
    cpu_time_s: float | None = None
    #: the physics choices behind the numbers: drag oil fraction, rolling resistance, thermal
    #: film, traction law (:func:`exudyn_bearing.results.records.assumptions_record`)
    assumptions: dict = field(default_factory=dict)
    #: where the whole call's wall time went, s: 'build' (the model with its quasi-static and
    #: steady or quasi-dynamic start), 'assembly', 'integration', 'outputs' (the results from
    #: the recorded states and their summary), 'whole' (the call, the error estimate's rerun
    #: included)
    call_time_s: dict = field(default_factory=dict)
    #: with ``profile``: the integration's force evaluations and Jacobians (counts, s), the
    #: rest (Exudyn's own work and the glue around them, s); else empty
    integration_profile: dict = field(default_factory=dict)
    #: with the setup's thermal network (MODEL.md §14g): node temperatures, heat by place and
    #: node, heat carried off and stored (:func:`exudyn_bearing.results.temperatures.thermal_summary`);
    #: else None
    thermal: dict | None = None

    def to_dict(self) -> dict:
        """JSON-ready: the fields (not the results object), ``units`` (the unit of every key)
        and ``inputs`` last."""
        d = {k: v for k, v in asdict(self).items() if k not in ("results", "initial_steady_state", "inputs")}
        return d | {"units": units_of(d), "inputs": self.inputs}


def with_surface_step(settings: SolverSettings, handle, rpm: float) -> SolverSettings:
    """``settings`` with a step that also resolves the bearing's defect passages at an inner
    race turning at ``rpm`` (``handle.RecommendedSurfaceStep``, MODEL.md §13c), where the
    bearing has defects and ``settings`` leaves the step to the bearing (``step`` None)."""
    if settings.step is not None or handle.connector.surface is None or not handle.connector.surface.defects:
        return settings
    return replace(settings, step=min(handle.RecommendedStep(), handle.RecommendedSurfaceStep(rpm)))


@accepts_old_names
@keeping_starts  # the error estimate's rerun starts from the same start (model.start_memo)
def simulate(bearing: Bearing | BearingSetup | str = REFERENCE_BEARING, lubricant=FROM_SETUP, *,
             axial_force: float = 1300.0, radial_force: float = 0.0, rpm: float = 1800.0, time: float = 0.05,
             settings: SolverSettings = SolverSettings(), ball_drag: BallDrag | None = FROM_SETUP,
             contact_law: ContactLaw = FROM_SETUP, cage: CageModel = FROM_SETUP, surface=FROM_SETUP,
             error_estimate: bool = False, initial_state: str = "auto", profile: bool = False,
             initial_temperatures: str = "auto") -> SimulationSummary:
    """Simulate one bearing (inner race driven at ``rpm`` with free translation under the
    axial and radial force, outer race fixed) for ``time`` s and summarize the last third.

    With ``error_estimate`` the run is repeated at half the step (half the tolerances
    for DOPRI5) and ``error_estimate`` holds, per summary quantity, the difference
    |x(h) - x(h/2)|: for these second-order (or adaptive) solvers a Richardson-type
    estimate of the error of the reported run (its error is ~4/3 of it at order 2).
    ``initial_state``: ``CreateAngularContactBearing(initialState=...)`` — 'auto' starts a
    pure axial load from its steady rolling state (MODEL.md §12). ``bearing`` may be a
    :class:`~exudyn_bearing.setup.BearingSetup` or a bearing file's path: all its parts are
    used — lubricant, ball drag, cage, contact law, surfaces (defects and waviness, MODEL.md
    §13; the step then also resolves the defect passages, ``RecommendedSurfaceStep``) and
    housing (the outer race on it, §13a) — each unless passed explicitly. The summary's
    ``call_time_s`` says where the call's time went; with ``profile`` its
    ``integration_profile`` splits the integration (a timer around each force evaluation and
    Jacobian, ~1 us each). A setup with a ``thermal`` model runs its network with the bodies
    (MODEL.md §14g), from ``initial_temperatures`` (``CreateAngularContactBearing(initialTemperatures=...)``),
    and the summary's ``thermal`` says where the heat went.
    """
    import exudyn as exu

    from ..model.builder import CreateAngularContactBearing
    from ..races import Driven

    called = _time.perf_counter()
    setup = as_setup(bearing, lubricant=lubricant, drag=ball_drag, contact_law=contact_law, cage=cage,
                     surface=surface)
    if not (math.isfinite(time) and time > 0):
        raise ValueError(f"time must be positive, got {time!r}")
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    # (outer race: the builder's default, the setup's housing or a fixed race)
    handle = CreateAngularContactBearing(mbs, setup, innerRace=Driven(rpm), axialForce=axial_force,
                                         radialForce=radial_force, initialState=initial_state,
                                         initialTemperatures=initial_temperatures, show=False)
    clock = EvaluationClock(handle.connector) if profile else None
    built = _time.perf_counter()
    mbs.Assemble()
    assembled = _time.perf_counter()
    info = run_solver(mbs, [handle], time, with_surface_step(settings, handle, rpm))
    integrated = _time.perf_counter()
    results = handle.Results(mbs)
    summary = results.summary()
    thermal = handle.ThermalSummary(mbs)
    done = _time.perf_counter()
    call = {"build": built - called, "assembly": assembled - built, "integration": integrated - assembled,
            "outputs": done - integrated}
    estimate = None
    if error_estimate:
        finer = replace(settings, step=0.5 * info.solver["step"], output_step=settings.output_step,
                        relative_tolerance=0.5 * settings.relative_tolerance,
                        absolute_tolerance=0.5 * info.solver["absolute_tolerance"])
        ref = simulate(setup, axial_force=axial_force, radial_force=radial_force, rpm=rpm, time=time,
                       settings=finer, initial_state=initial_state, initial_temperatures=initial_temperatures)
        keys = ("cage_slip_percent", "kinematic_cage_slip_percent", "cage_speed", "max_inner_load", "max_outer_load",
                "max_inner_slip")
        other = ref.details | {k: getattr(ref, k) for k in ("cage_slip_percent", "kinematic_cage_slip_percent",
                                                              "cage_speed")}
        estimate = {"method": "rerun at half the step (and half the tolerances)", "reference_step": finer.step,
                    "reference_wall_time_s": ref.wall_time_s}
        estimate.update({k: abs(float(summary[k]) - float(other[k])) for k in keys})
    call["whole"] = _time.perf_counter() - called
    return SimulationSummary(axial_force, radial_force, rpm, time, summary["kinematic_cage_slip_percent"],
                             summary["cage_slip_percent"], summary["cage_speed"],
                             summary["cage_speed_nominal"], summary["settled"], info.wall_time_s, info.steps,
                             info.solver, info.newton_iterations, info.jacobian_updates,
                             # details: what the fields above do not already carry
                             {k: v for k, v in summary.items() if k not in _SUMMARY_FIELDS},
                             estimate, results, handle.initialSteadyState, summary["power_loss_W"],
                             summary["drive_power_W"],
                             setup_inputs(setup, initial_state=initial_state,
                                          **({} if thermal is None else {"initial_temperatures": initial_temperatures,
                                                                         "thermal_update_period_s": UPDATE_PERIOD})),
                             info.cpu_time_s, assumptions_record(setup.drag, setup.contact_law, setup.lubricant),
                             call, {} if clock is None else clock.split(info.steps, call["integration"]), thermal)

