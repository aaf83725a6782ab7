"""Labelled vibration data sets (MODEL.md §13b): :func:`~exudyn_bearing.studies.vibration.vibration`
over a grid of fault type, fault size, load and speed, each signal written with its labels
— the fault, its size, the run's actual fault frequencies, its slip and the passages' impact
times — as one NPZ per case, indexed by one CSV and recorded with the inputs that made it.

The grid runs on the skid map's machinery (:mod:`~exudyn_bearing.studies.grid`): progress
lines, a journal that an interrupted set resumes from (refused when the inputs changed),
local processes or a Dask cluster. Loading: ``pandas.read_csv(out / "index.csv")`` and
``numpy.load(out / row.file)``.
"""
from __future__ import annotations

import csv
import itertools
import json
import math
import os
import time as _time
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path

import numpy as np

from contact.surface import Defect, SurfaceModel
from contact.terms import TERMS, applied_terms, register_term
from ..bearing import Bearing
from ..bearingfile import as_setup
from ..presets import REFERENCE_BEARING
from ..results.records import setup_inputs
from ..setup import BearingSetup, refuse_thermal
from .grid import check_picklable, grid_values, guard_folder, read_journal, run_cases
from .masking import Fluctuation, Masking
from .vibration import FAULTS

__all__ = ["FAULT_NAMES", "CaseSettings", "DatasetCase", "Dataset", "dataset", "fault_surface"]

#: the fault types of a data set: a perfect bearing, a defect on a race, a pit on a ball
FAULT_NAMES = ("none", "outer", "inner", "ball")
#: the index's names of the case's fields whose unit the name alone does not say
INDEX_UNITS = {"size": "size_m", "axial": "axial_N", "radial": "radial_N"}
#: the index's columns after the case's own (:class:`DatasetCase`): the actual fault frequencies
INDEX_FREQUENCIES = tuple(f"{name}_Hz" for name in FAULTS)


@dataclass(frozen=True)
class CaseSettings:
    """What every case of a data set shares (SI units; :func:`~exudyn_bearing.studies.vibration.vibration`'s
    arguments of the same names).

    Parameters
    ----------
    time : float
        Simulated time per case, s.
    sample_rate : float
        Hz.
    settle : float
        Start left out of the spectra, s (the signal keeps it).
    band : "auto", None or (low, high)
        The envelope band (for the labels' envelope lines).
    depth : float
        Depth of every fault, m (a notch's or a spall's below the race, a pit's below the ball).
    masking : Masking or None
        Measurement noise and machine lines; each case's seed is ``masking.seed`` + the case's
        place in the grid, so the cases carry different noise, reproducibly.
    fluctuation : Fluctuation or None
        The shaft speed's and the load's random fluctuation, seeded like ``masking``.
    """

    time: float = 0.2
    sample_rate: float = 20000.0
    settle: float = 0.02
    band: object = "auto"
    depth: float = 0.2e-3
    masking: Masking | None = None
    fluctuation: Fluctuation | None = None

    def __post_init__(self) -> None:
        from .vibration import check_band_choice

        for name in ("time", "sample_rate", "depth"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not (math.isfinite(value) and value > 0):
                raise ValueError(f"settings.{name} must be a positive number, got {value!r}")
        if not (isinstance(self.settle, (int, float)) and 0 <= self.settle < self.time):
            raise ValueError(f"settings.settle must lie in [0, time = {self.time:g} s), got {self.settle!r}")
        object.__setattr__(self, "band", check_band_choice(self.band, self.sample_rate))
        if self.masking is not None and not isinstance(self.masking, Masking):
            raise ValueError(f"settings.masking must be a Masking(...) or None, got {self.masking!r}")
        if self.fluctuation is not None and not isinstance(self.fluctuation, Fluctuation):
            raise ValueError(f"settings.fluctuation must be a Fluctuation(...) or None, got {self.fluctuation!r}")

    def seeded(self, offset: int) -> "CaseSettings":
        """These settings with the masking's and the fluctuation's seeds moved on by ``offset``."""
        def move(record):
            return None if record is None else replace(record, seed=record.seed + offset)

        return replace(self, masking=move(self.masking), fluctuation=move(self.fluctuation))


@dataclass
class DatasetCase:
    """One case of a data set and its labels (SI units; slips in %, speeds in rpm)."""

    fault: str  #: one of :data:`FAULT_NAMES`
    size: float  #: the fault's length along the rolling direction (a pit's diameter), m; 0: none
    axial: float  #: N
    radial: float  #: N
    rpm: float  #: inner-race speed, rev/min
    #: the masking's seed of this case, its own + the case's place in the grid (the fluctuation's:
    #: its own + the same place); None: neither given
    seed: int | None = None
    file: str | None = None  #: the case's NPZ in the data set's folder
    #: the run's actual fault frequencies (its cage and ball speeds, with the skid), Hz
    fault_frequencies: dict | None = None
    kinematic_cage_slip_percent: float | None = None
    passages: int | None = None  #: defect passages in the run
    entry_to_impact_s: float | None = None  #: median over the passages read from the contact load
    envelope_line: list | None = None  #: the strongest envelope line [Hz, m/s²]
    wall_time_s: float | None = None
    error: str | None = None

    @property
    def key(self):
        return (self.fault, self.size, self.axial, self.radial, self.rpm)

    @property
    def name(self) -> str:
        """The case's file name stem: fault, size in µm, loads in N, speed in rpm."""
        return (f"{self.fault}_{1e6 * self.size:.0f}um_Fa{self.axial:g}N_Fr{self.radial:g}N_{self.rpm:g}rpm"
                .replace(".", "p"))


def fault_surface(base: SurfaceModel, fault: str | Defect, size: float, depth: float) -> SurfaceModel:
    """``base`` (its waviness) with one fault of ``size`` m and ``depth`` m: 'none', 'outer'
    or 'inner' (a notch across the track at azimuth 0, where the radial load presses), 'ball'
    (a round pit on ball 0), or a :class:`~contact.surface.Defect` template whose length and
    depth are replaced."""
    if isinstance(fault, Defect):
        defect = replace(fault, length=size, depth=depth)
    elif fault == "none":
        return base
    elif fault in FAULT_NAMES:
        defect = Defect(fault, 0.0, size, depth, ball=0 if fault == "ball" else None)
    else:
        raise ValueError(f"faults: each must be one of {FAULT_NAMES} or a Defect, got {fault!r}")
    return replace(base, defects=(defect,))


def _run_case(args) -> dict:
    """Worker: one case run and written; never raises (errors are reported in the case)."""
    case, template, setup, settings, folder, registered = args
    start = _time.perf_counter()
    try:
        from ..simulation.runner import SolverSettings
        from .vibration import vibration

        for name, term in registered:  # (a worker process: the terms its parent registered)
            if name not in TERMS:
                register_term(name, term)
        surface = fault_surface(setup.surface, template, case.size, settings.depth)
        result = vibration(setup.replace(surface=surface), rpm=case.rpm, axial_force=case.axial,
                           radial_force=case.radial, time=settings.time, sample_rate=settings.sample_rate,
                           settle=settings.settle, band=settings.band, masking=settings.masking,
                           fluctuation=settings.fluctuation, settings=SolverSettings(progress=False))
        done = replace(case, file=case.name + ".npz", fault_frequencies=result.fault_frequencies["actual"],
                       kinematic_cage_slip_percent=result.kinematic_cage_slip_percent,
                       passages=len(result.defect_events),
                       entry_to_impact_s=result.impacts.get("entry_to_impact_s"),
                       envelope_line=result.envelope_peaks[0] if result.envelope_peaks else None)
        _write_case(Path(folder) / done.file, done, result, settings)
    except Exception as err:  # a failed case is reported, the set goes on
        done = replace(case, error=f"{type(err).__name__}: {err}".splitlines()[0][:300])
    done.wall_time_s = _time.perf_counter() - start
    return asdict(done)


def _write_case(path: Path, case: DatasetCase, result, settings: CaseSettings) -> None:
    """The case's NPZ, written whole or not at all (a temporary file renamed)."""
    events = result.defect_events

    def times(key):
        return np.array([np.nan if e.get(key) is None else e[key] for e in events], dtype=float)

    load = np.array([case.radial, 0.0, case.axial])
    labels = {"fault": case.fault, "size_m": case.size, "depth_m": settings.depth, "axial_N": case.axial,
              "radial_N": case.radial, "rpm": case.rpm, "seed": case.seed,
              "fault_frequencies_Hz": result.fault_frequencies,  # actual, kinematic, nominal
              "kinematic_cage_slip_percent": case.kinematic_cage_slip_percent, "passages": case.passages,
              "entry_to_impact_s": case.entry_to_impact_s, "envelope_band_Hz": list(result.band),
              "envelope_peaks_Hz": result.envelope_peaks[:5], "amplitudes": "uncalibrated (MODEL.md §13c)"}
    temporary = path.with_suffix(".partial.npz")
    np.savez_compressed(
        temporary, t_s=result.time, acceleration_m_s2=result.acceleration,
        signal_m_s2=result.acceleration @ (load / np.linalg.norm(load)), sample_rate_Hz=result.sample_rate,
        fault=case.fault, size_m=case.size, depth_m=settings.depth, rpm=case.rpm, axial_N=case.axial,
        radial_N=case.radial, **{f"actual_{k}_Hz": v for k, v in result.fault_frequencies["actual"].items()},
        kinematic_cage_slip_percent=result.kinematic_cage_slip_percent,
        passage_ball=np.array([e["ball"] for e in events], dtype=int), passage_edge_s=times("edge_s"),
        passage_entry_s=times("entry_s"), passage_impact_s=times("impact_s"), passage_exit_s=times("exit_s"),
        labels=json.dumps(labels), inputs=json.dumps(result.inputs, default=str))
    os.replace(temporary, path)


@dataclass
class Dataset:
    """Result of :func:`dataset`: its cases (labels, files) and where they are."""

    folder: Path
    cases: list = field(default_factory=list)
    inputs: dict | None = None

    def write_index(self) -> Path:
        """``index.csv``: one row per case (the :class:`DatasetCase` fields, the actual fault
        frequencies as BPFO_Hz ... FTF_Hz, the strongest envelope line; SI units, slips in %)."""
        names = [n for n in DatasetCase.__dataclass_fields__ if n not in ("fault_frequencies", "envelope_line")]
        path = self.folder / "index.csv"
        with open(path, "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow([INDEX_UNITS.get(n, n) for n in names] + list(INDEX_FREQUENCIES)
                            + ["envelope_line_Hz", "envelope_line_m_s2"])
            for c in self.cases:
                freqs = [(c.fault_frequencies or {}).get(k) for k in FAULTS]
                writer.writerow([getattr(c, n) for n in names] + freqs + (c.envelope_line or [None, None]))
        return path


def dataset(bearing: Bearing | BearingSetup | str = REFERENCE_BEARING, *, out, faults=FAULT_NAMES,
            sizes=(0.5e-3, 1.0e-3), axial_force=(1300.0,), radial_force=(500.0,), rpm=(1800.0,),
            settings: CaseSettings = CaseSettings(), workers: int | None = None, client=None,
            progress=print) -> Dataset:
    """Run :func:`~exudyn_bearing.studies.vibration.vibration` over faults × sizes (m) ×
    axial × radial (N) × rpm and write each case to ``out``: ``<case>.npz`` (the signal
    ``t_s``, ``acceleration_m_s2`` (T, 3), ``signal_m_s2`` along the load; the labels as
    arrays and as JSON; the passages' ``passage_edge_s``/``entry_s``/``impact_s``/``exit_s``;
    the run's ``inputs``), ``index.csv`` (one row per case) and ``inputs.json`` (the bearing
    setup and ``settings``). A 'none' fault has one case per load and speed (size 0).

    The folder is a journal: an interrupted set resumes where it stopped and reruns its
    failed cases; a folder made from other inputs is refused. ``bearing``: a Bearing,
    BearingSetup or file; its waviness is kept in every case, defects of its own are refused
    (each case's fault is its label). ``workers``, ``client``, ``progress`` as for
    :func:`~exudyn_bearing.studies.skidmap.skid_map`."""
    setup = as_setup(bearing)
    refuse_thermal(setup, "vibration_dataset")
    if setup.surface.defects:
        raise ValueError("bearing: its file holds defects; a data set gives each case its own fault (the label), "
                         "so remove the [[defect]] tables (waviness is kept)")
    if not isinstance(settings, CaseSettings):
        raise ValueError(f"settings must be a CaseSettings(...), got {settings!r}")
    templates = _templates(faults)
    values = {name: grid_values(name, [given] if isinstance(given, (int, float)) else given, strict=strict)
              for name, given, strict in (("sizes", sizes, True), ("axial_force", axial_force, False),
                                          ("radial_force", radial_force, False), ("rpm", rpm, True))}
    if any(a == 0 and r == 0 for a in values["axial_force"] for r in values["radial_force"]):
        raise ValueError("axial_force, radial_force: a case with neither load has no load distribution")
    grid = []
    for label, n, r, a in itertools.product(templates, values["rpm"], values["radial_force"], values["axial_force"]):
        for size in ([0.0] if label == "none" else values["sizes"]):
            grid.append(DatasetCase(label, size, a, r, n))
    seeded = settings.masking or settings.fluctuation
    if seeded is not None:  # each case its own noise and fluctuation, by its place in the grid
        grid = [replace(c, seed=seeded.seed + i) for i, c in enumerate(grid)]
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    record = setup_inputs(setup, dataset_settings=settings, faults=[str(t) for t in templates.values()])
    guard_folder(folder, record, "a data set", "cases.jsonl")
    journal = folder / "cases.jsonl"
    done = {k: c for k, c in read_journal(journal, lambda d: DatasetCase(**d)).items()
            if c.file and (folder / c.file).exists()}  # (a case's file deleted: run again)
    result = Dataset(folder, [done[c.key] for c in grid if c.key in done], record)
    todo = [c for c in grid if c.key not in done]
    registered = applied_terms(setup.contact_law)
    check_picklable(registered, workers, client)
    jobs = [(c, templates[c.fault], setup, settings if c.seed is None else settings.seeded(c.seed - seeded.seed),
             str(folder), registered) for c in todo]
    if progress and done:
        progress(f"resuming: {len(done)} of {len(grid)} cases already in {folder}")
    start = _time.perf_counter()

    def finished(data):
        case = DatasetCase(**data)
        result.cases.append(case)
        with open(journal, "a") as fh:
            fh.write(json.dumps(data) + "\n")
        if progress:
            count = len(result.cases) - len(done)
            elapsed = _time.perf_counter() - start
            state = f"FAILED ({case.error})" if case.error else (
                f"slip {case.kinematic_cage_slip_percent:.3f} %, {case.passages} passages")
            progress(f"[{len(result.cases)}/{len(grid)}] {case.fault} {1e3 * case.size:g} mm, F_a {case.axial:g} N, "
                     f"F_r {case.radial:g} N, {case.rpm:g} rpm: {state}; {elapsed:.0f} s elapsed, "
                     f"~{elapsed / count * (len(todo) - count):.0f} s left")

    run_cases(_run_case, jobs, finished, workers=workers, client=client)
    order = {c.key: i for i, c in enumerate(grid)}
    result.cases.sort(key=lambda c: order[c.key])
    result.write_index()
    return result


def _templates(faults) -> dict:
    """{label: fault} of ``faults`` (names of :data:`FAULT_NAMES` or Defect templates, one per place)."""
    if isinstance(faults, (str, Defect)):
        faults = [faults]
    out = {}
    for f in faults:
        label = f.race if isinstance(f, Defect) else f
        if not isinstance(label, str) or label not in FAULT_NAMES:
            raise ValueError(f"faults: each must be one of {FAULT_NAMES} or a Defect, got {f!r}")
        if label in out:
            raise ValueError(f"faults: {label!r} given twice (one fault per place: its label)")
        out[label] = f
    if not out:
        raise ValueError("faults: none given")
    return out
