"""Skid-risk map: the dynamic model over a grid of axial load, radial load and speed
(MODEL.md §7, §9), run in parallel local processes or on a Dask cluster.

Each grid point is one :func:`exudyn_bearing.simulation.runner.simulate` run. Results are
appended to ``points.jsonl`` as they arrive, so an interrupted map keeps what it has
and a second call with the same ``out`` directory resumes.
"""
from __future__ import annotations

import csv
import itertools
import json
import math
import time as _time
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path

import numpy as np

from contact.ballrace import ContactLaw
from contact.lubricant import Lubricant
from contact.terms import TERMS, applied_terms, register_term
from ..bearing import BallDrag, Bearing
from ..bearingfile import as_setup
from ..cage import CageModel
from ..criteria import gyroscopic_minimum_axial, hirano_minimum_axial
from ..presets import REFERENCE_BEARING
from ..renamed import accepts_old_names
from ..results.records import setup_inputs, units_of
from ..setup import FROM_SETUP, BearingSetup, refuse_thermal
from ..solvers.steady import steady_state
from .grid import CaseRunner, check_picklable, grid_values, guard_folder, read_journal
from .skidmap_report import load_plotting, plot_skid_map, skid_map_markdown

__all__ = ["SkidPoint", "SkidMap", "skid_map", "parse_range"]

#: Default grid of ``python -m exudyn_bearing skid-map`` (about 5 minutes on 2 cores).
DEFAULT_AXIAL = (300.0, 800.0, 1500.0, 3000.0)
DEFAULT_RPM = (900.0, 1800.0)
DEFAULT_TIME = None
#: Until-settled runs (``time=None``): first length, s, doubled until settled, capped at
#: :data:`MAX_TIME`.
FIRST_TIME, MAX_TIME = 0.1, 2.0


def parse_range(text: str) -> list[float]:
    """'start:stop:count' (inclusive, evenly spaced) or a comma list 'a,b,c'."""
    text = text.strip()
    try:
        if ":" in text:
            start, stop, count = text.split(":")
            n = int(count)
            if n < 1 or float(start) > float(stop):
                raise ValueError
            values = [float(v) for v in np.linspace(float(start), float(stop), n)]
        else:
            values = [float(v) for v in text.split(",") if v.strip()]
        if not values or not all(math.isfinite(v) for v in values):
            raise ValueError
        return values
    except ValueError:
        raise ValueError(f"range must be 'start:stop:count' (start <= stop, count >= 1) or 'a,b,c' of finite "
                         f"numbers, got {text!r}") from None


@dataclass
class SkidPoint:
    """One grid point (SI units; slips in %, speeds in rpm)."""

    axial: float
    radial: float
    rpm: float
    time: float | None  #: requested simulated time, s; None: until settled
    kinematic_cage_slip_percent: float | None = None  #: the skid measure (MODEL.md §7), %
    cage_slip_percent: float | None = None  #: the paper's P19 at the nominal angle, %
    peak_ball_slip: float | None = None  #: largest ball–race slip speed over the last third, m/s
    #: the steady-state solver's kinematic cage slip (pure axial load only, MODEL.md §12), %
    steady_kinematic_cage_slip_percent: float | None = None
    settled: bool | None = None
    wall_time_s: float | None = None
    error: str | None = None
    #: simulated time of the reported run, s (until settled: the last of 0.1, 0.2, ... s)
    simulated_time: float | None = None

    @property
    def key(self):
        return (self.axial, self.radial, self.rpm, self.time)


def _refine_threshold(args) -> tuple:
    """Worker of :meth:`SkidMap.refine_thresholds`: (its index, the refined entry) of one
    threshold ``entry`` whose grid points bracket ``level`` % between the loads ``bracket``:
    the steady-state bisection and, with ``confirm_time``, the dynamic runs at its ends.
    ``known``: {axial N: steady kinematic slip %} of the bracket's grid points, whose runs
    started from that very steady state (:func:`_run_point`), taken instead of solving it again."""
    index, entry, (lo, hi), setup, registered, level, tolerance, confirm_time, known = args
    for name, term in registered:  # (a worker process: the terms its parent registered)
        if name not in TERMS:
            register_term(name, term)
    curve = []  # (axial N, steady kinematic slip %) of every converged evaluation

    def slip(axial):
        if known.get(axial) is not None:
            curve.append([axial, known[axial]])
            return known[axial]
        state = steady_state(setup, axial_force=axial, rpm=entry["rpm"])
        if not state.converged:
            return None
        curve.append([axial, state.kinematic_cage_slip_percent])
        return state.kinematic_cage_slip_percent

    s_lo, s_hi = slip(lo), slip(hi)
    if s_lo is None or s_hi is None or not (s_lo >= level > s_hi):
        return index, dict(entry, note=entry["note"] + "; the steady state does not bracket it")
    while hi - lo > tolerance * lo:
        mid = 0.5 * (lo + hi)
        s_mid = slip(mid)
        if s_mid is None:
            break
        lo, hi = (mid, hi) if s_mid >= level else (lo, mid)
    # (an unconverged midpoint stops the bisection early: the note gives the width reached)
    refined = dict(entry, minimum_axial=0.5 * (lo + hi), bracket=[lo, hi], steady_curve=sorted(curve),
                   note=f"steady-state bisection to ±{100 * (hi - lo) / (hi + lo):.1f} %")
    if confirm_time:
        from ..simulation.runner import simulate

        dyn = [simulate(setup, axial_force=a, rpm=entry["rpm"], time=confirm_time).kinematic_cage_slip_percent
               for a in (lo, hi)]
        # the dynamic model integrates the fast traction rule (within ~1e-2 of the
        # accurate one the steady solver uses): its own crossing, interpolated (or
        # extrapolated) through the two runs, must lie within the bracket's width
        crossing = lo + (dyn[0] - level) * (hi - lo) / (dyn[0] - dyn[1]) if dyn[0] != dyn[1] else None
        refined.update(dynamic_slips=dyn, dynamic_minimum_axial=crossing,
                       dynamic_confirms=bool(crossing is not None
                                             and abs(crossing - refined["minimum_axial"]) <= tolerance * lo))
    return index, refined


def _run_point(args) -> dict:
    """Worker: one dynamic run; never raises (errors are reported in the point)."""
    point, setup, registered = args
    start = _time.perf_counter()
    try:
        from ..model.start_memo import kept_starts
        from ..simulation.runner import SolverSettings, simulate

        for name, term in registered:  # (a worker process: the terms its parent registered)
            if name not in TERMS:
                register_term(name, term)

        # fixed length, or until settled: 0.1, 0.2, 0.4, ... s from the start, capped at 2 s
        # (each run from the start state, solved once for all of them: at most twice the cost of
        # the final run)
        length = point.time if point.time is not None else FIRST_TIME
        with kept_starts():  # a longer run starts from the same start (model.start_memo)
            while True:
                s = simulate(setup, axial_force=point.axial, radial_force=point.radial, rpm=point.rpm, time=length,
                             settings=SolverSettings(progress=False))  # workers in parallel: no progress lines
                if point.time is not None or s.settled or length >= MAX_TIME:
                    break
                length = min(2.0 * length, MAX_TIME)
        res = s.results
        last = res.last(1 / 3)
        peak = float(max(res.inner["slip"][last].max(), res.outer["slip"][last].max()))
        # the run started from the steady state where one exists (pure axial load): no second solve
        steady = s.initial_steady_state.kinematic_cage_slip_percent if s.initial_steady_state is not None else None
        done = replace(point, cage_slip_percent=s.cage_slip_percent,
                       kinematic_cage_slip_percent=s.kinematic_cage_slip_percent, peak_ball_slip=peak,
                       settled=s.settled, steady_kinematic_cage_slip_percent=steady, simulated_time=length)
    except Exception as err:  # a failed point is reported, the map goes on
        done = replace(point, error=f"{type(err).__name__}: {err}".splitlines()[0][:300])
    done.wall_time_s = _time.perf_counter() - start
    return asdict(done)


@dataclass
class SkidMap:
    """Result table of :func:`skid_map`."""

    bearing: Bearing
    points: list = field(default_factory=list)
    #: :meth:`refine_thresholds` of the finished map (set by :func:`skid_map`), or None
    refined: list | None = None
    #: names of the files :func:`skid_map` wrote into ``out``
    files: list = field(default_factory=list)
    #: what produced the map (:func:`exudyn_bearing.results.records.inputs_record`), set by :func:`skid_map`
    inputs: dict | None = None
    #: the :class:`~exudyn_bearing.setup.BearingSetup` of every point (None: ``bearing`` with the defaults)
    setup: BearingSetup | None = None

    def thresholds(self, level: float = 1.0) -> list[dict]:
        """Per (rpm, radial): the smallest axial load with kinematic cage slip below
        ``level`` %, interpolated linearly between the grid loads around the crossing,
        and Hirano's and Jones' (gyroscopic) F_a,min for comparison."""
        out = []
        groups = sorted({(p.rpm, p.radial) for p in self.points})
        for rpm, radial in groups:
            pts = sorted((p for p in self.points if p.rpm == rpm and p.radial == radial and p.error is None),
                         key=lambda p: p.axial)
            estimate, note = None, "no point below the level"
            for lo, hi in zip(pts, pts[1:]):
                if lo.kinematic_cage_slip_percent >= level > hi.kinematic_cage_slip_percent:
                    s0, s1 = lo.kinematic_cage_slip_percent, hi.kinematic_cage_slip_percent
                    estimate = lo.axial + (s0 - level) * (hi.axial - lo.axial) / (s0 - s1)
                    note = "interpolated" + ("" if lo.settled and hi.settled else
                                             " (from unsettled points)" if False in (lo.settled, hi.settled) else
                                             " (from points too short to judge)")
                    break
            else:
                if pts and pts[0].kinematic_cage_slip_percent < level:
                    estimate, note = pts[0].axial, "at or below the lightest load"
            out.append(dict(rpm=rpm, radial=radial, minimum_axial=estimate, note=note,
                            hirano_minimum_axial=hirano_minimum_axial(self.bearing, rpm),
                            gyroscopic_minimum_axial=gyroscopic_minimum_axial(self.bearing, rpm)))
        return out

    def refine_thresholds(self, lubricant: Lubricant = FROM_SETUP, ball_drag: BallDrag | None = FROM_SETUP,
                          contact_law: ContactLaw = FROM_SETUP, level: float = 1.0,
                          tolerance: float = 0.04, confirm_time: float | None = 0.1,
                          cage: CageModel = FROM_SETUP, runner: CaseRunner | None = None) -> list[dict]:
        """:meth:`thresholds`, refined where the steady-state solver applies (radial 0):
        the load at which the steady kinematic cage slip crosses ``level`` %, bisected
        between the bracketing grid loads until the bracket is ``tolerance`` of its load
        wide (the midpoint then within ±tolerance/2, MODEL.md §12). Each refined entry gets
        ``bracket`` (N) and, with ``confirm_time`` (s), dynamic runs of that length at both
        ends of the bracket (``dynamic_slips``), the dynamic model's own crossing through
        them (``dynamic_minimum_axial``) and whether it lies within the bracket's width of
        the steady one (``dynamic_confirms``). The parts not passed are the map's
        :attr:`setup`'s; a setup with defects or waviness has no steady state, and its
        thresholds stay the grid's (noted). ``runner``: a
        :class:`~exudyn_bearing.studies.grid.CaseRunner` that refines the thresholds in
        parallel (:func:`skid_map` passes the one that ran the points); None: one after
        another in this process. Where the setup is the map's own, the bracket's grid points
        give their steady states (the ones their runs started from) instead of solving them again."""
        setup = as_setup(self.setup or self.bearing, lubricant=lubricant, drag=ball_drag, contact_law=contact_law,
                         cage=cage)
        if setup.surface.active:
            return [dict(entry, note=entry["note"] + "; not refined: a defect or waviness has no steady state")
                    for entry in self.thresholds(level)]
        out, jobs = [], []
        same_setup = self.setup is not None and setup == self.setup
        registered = applied_terms(setup.contact_law)
        if runner is not None:
            check_picklable(registered, runner.workers, runner.client)
        for entry in self.thresholds(level):
            pts = sorted((p for p in self.points if p.rpm == entry["rpm"] and p.radial == entry["radial"]
                          and p.error is None), key=lambda p: p.axial)
            bracket = next(((lo, hi) for lo, hi in zip(pts, pts[1:]) if lo.kinematic_cage_slip_percent >= level
                            > hi.kinematic_cage_slip_percent), None)
            if entry["radial"] == 0 and bracket is not None:
                # the grid points' steady states, where they were solved with this very setup (at a
                # negative speed the run's start solves the mirrored bearing: solved again here)
                known = ({p.axial: p.steady_kinematic_cage_slip_percent for p in bracket}
                         if same_setup and entry["rpm"] > 0 else {})
                jobs.append((len(out), entry, (bracket[0].axial, bracket[1].axial), setup, registered, level,
                             tolerance, confirm_time, known))
            out.append(entry)

        def record(done):
            out[done[0]] = done[1]

        if runner is None:
            for job in jobs:
                record(_refine_threshold(job))
        else:
            runner.run(_refine_threshold, jobs, record)
        return out

    def write(self, out: Path) -> list[str]:
        """CSV, markdown and thresholds JSON (with its units and inputs; and a PNG with
        matplotlib); returns the names of the files written. The CSV's columns are the
        :class:`SkidPoint` names: loads in N, rpm in rev/min, times in s, slips in %,
        ``peak_ball_slip`` in m/s."""
        out = Path(out)
        out.mkdir(parents=True, exist_ok=True)
        names = [f for f in SkidPoint.__dataclass_fields__]
        rows = sorted(self.points, key=lambda p: (p.rpm, p.radial, p.axial))
        with open(out / "skid_map.csv", "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow(names)
            for p in rows:
                writer.writerow([("too short" if p.settled is None and p.error is None else "")
                                 if n == "settled" and p.settled is None else getattr(p, n) for n in names])
        (out / "skid_map.md").write_text(self.markdown() + "\n")
        thresholds = self.refined or self.thresholds()
        record = {"thresholds": thresholds, "units": units_of(thresholds[0]) if thresholds else {},
                  "inputs": self.inputs or {"bearing": repr(self.bearing)}}
        (out / "thresholds.json").write_text(json.dumps(record, indent=1))
        written = ["skid_map.csv", "skid_map.md", "thresholds.json"]
        if self.plot(out / "skid_map.png"):
            written.append("skid_map.png")
        return written

    def markdown(self) -> str:
        """The points and the thresholds as markdown tables."""
        return skid_map_markdown(self)

    def plot(self, path) -> bool:
        """Kinematic cage slip against axial load per speed (log scale), the 1 % level, the
        thresholds (refined ones with their brackets and the steady states the bisection
        evaluated, through which the threshold's 1 % crossing runs) and Hirano's load where
        it falls in the range; False when matplotlib is missing."""
        return plot_skid_map(self, path)


def _load_done(path: Path) -> dict:
    return read_journal(path, lambda data: SkidPoint(**data))


def _check_inputs(folder: Path, setup: BearingSetup) -> None:
    """Record the map's inputs in ``folder/inputs.json``; a resume into a folder whose
    points came from other inputs is refused (it would serve results of another bearing,
    oil, law, surface or housing)."""
    guard_folder(folder, setup_inputs(setup), "a skid map", "points.jsonl")


@accepts_old_names
def skid_map(bearing: Bearing | BearingSetup | str = REFERENCE_BEARING, lubricant: Lubricant = FROM_SETUP, *,
             axial_force=DEFAULT_AXIAL, radial_force=(0.0,), rpm=DEFAULT_RPM, time: float | None = DEFAULT_TIME,
             ball_drag: BallDrag | None = FROM_SETUP, out=None, workers: int | None = None, client=None,
             progress=print, contact_law: ContactLaw = FROM_SETUP, refine: bool = True,
             cage: CageModel = FROM_SETUP) -> SkidMap:
    """Run the dynamic model over the grid axial x radial x rpm (N, N, rev/min) and return a
    :class:`SkidMap`. Each point runs ``time`` s, or with ``time=None`` (default) until it
    settles (:meth:`BearingResults.settled`): 0.1 s, then 0.2, 0.4, ... s from the start,
    capped at 2 s (``settled`` False when the cap is hit). Pure axial points start from
    their steady state and settle in the first run.

    Parameters
    ----------
    out : path, optional
        Directory for ``points.jsonl`` (incremental, resumable), CSV, markdown, thresholds
        and PNG.
    workers : int, optional
        Local worker processes (default: CPU count).
    client : dask.distributed.Client, optional
        Run on this Dask cluster instead of local processes.
    progress : callable or None
        Called with one line per finished point (runs done, time left).
    contact_law : contact.ballrace.ContactLaw
        Ball–race physics of every point (default: Crook with the limiting shear, MODEL.md
        §6a). A resumed map reuses the points in ``out`` only if they came from the same
        bearing, lubricant, drag, law, cage and package version (``out/inputs.json``);
        otherwise a ValueError.
    refine : bool
        After the grid, refine each pure-axial threshold with the steady-state solver and
        confirm its bracket dynamically (:meth:`SkidMap.refine_thresholds`).
    cage : CageModel
        The cage of every point (guidance, land and pocket friction, MODEL.md §11d).
    """
    setup = as_setup(bearing, lubricant=lubricant, drag=ball_drag, contact_law=contact_law, cage=cage)
    refuse_thermal(setup, "skid_map (its points are dynamic runs)")
    hint = (" (the axial load acts along the bearing axis; for a load the other way mount the bearing the other "
            "way round)")
    axial_force = grid_values("axial_force", axial_force, hint=hint)
    radial_force, rpm = grid_values("radial_force", radial_force), grid_values("rpm", rpm, low=None)
    if time is not None and not (isinstance(time, (int, float)) and math.isfinite(time) and time > 0):
        raise ValueError(f"time must be a positive number of seconds (or None: until settled), got {time!r}")
    grid = [SkidPoint(float(a), float(r), float(n), None if time is None else float(time))
            for n, r, a in itertools.product(rpm, radial_force, axial_force)]
    if any(p.axial == 0 and p.radial == 0 for p in grid):
        raise ValueError("axial_force, radial_force: a point with neither load has no load distribution")
    journal = Path(out) / "points.jsonl" if out is not None else None
    done = {}
    if journal is not None:
        journal.parent.mkdir(parents=True, exist_ok=True)
        _check_inputs(journal.parent, setup)
        done = _load_done(journal)
    todo = [p for p in grid if p.key not in done]
    result = SkidMap(setup.bearing, [done[p.key] for p in grid if p.key in done], inputs=setup_inputs(setup),
                     setup=setup)
    if progress and done:
        progress(f"resuming: {len(result.points)} of {len(grid)} points already in {journal}")
    start = _time.perf_counter()
    # the terms registered in this process (contact.terms.register_term) go with every point:
    # a worker process registers them again
    registered = applied_terms(setup.contact_law)
    check_picklable(registered, workers, client)
    jobs = [(p, setup, registered) for p in todo]

    def record(data):
        point = SkidPoint(**data)
        result.points.append(point)
        if journal is not None:
            with open(journal, "a") as fh:
                fh.write(json.dumps(data) + "\n")
        if progress:
            finished = len(result.points) - len(done)
            elapsed = _time.perf_counter() - start
            left = elapsed / finished * (len(todo) - finished)
            state = f"FAILED ({point.error})" if point.error else (
                f"kinematic slip {point.kinematic_cage_slip_percent:.3f} %"
                + {True: "", False: " (not settled)", None: " (too short to judge)"}[point.settled])
            progress(f"[{len(result.points)}/{len(grid)}] F_a {point.axial:g} N, F_r {point.radial:g} N, "
                     f"{point.rpm:g} rpm: {state}; {elapsed:.0f} s elapsed, ~{left:.0f} s left")

    if out is not None and todo:
        load_plotting()  # while the workers run
    with CaseRunner(workers, client) as runner:
        runner.run(_run_point, jobs, record)
        order = {p.key: i for i, p in enumerate(grid)}
        result.points.sort(key=lambda p: order[p.key])
        if refine:  # on the same workers, their kernels loaded
            result.refined = result.refine_thresholds(runner=runner)
    if refine and progress:
        for t in result.refined:
            if "bracket" in t:
                progress(f"threshold at {t['rpm']:g} rpm: {t['minimum_axial']:.0f} N (bracket "
                         f"{t['bracket'][0]:.0f}–{t['bracket'][1]:.0f} N, dynamic "
                         f"{'confirms' if t.get('dynamic_confirms') else 'does NOT confirm'} it)")
    if out is not None:
        result.files = result.write(Path(out))
    return result
