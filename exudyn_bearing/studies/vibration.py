"""Vibration of a bearing with race surfaces, the way a condition-monitoring engineer reads it
(MODEL.md §13b): the housing's signal, its spectrum and envelope spectrum, the fault
frequencies twice — kinematic (geometry and contact angle, pure rolling) and actual (the
run's cage speed and ball spin, with the skid in them) — and the defect passage events.

:func:`vibration` runs one bearing on a :func:`~exudyn_bearing.races.Housing`;
the analysis functions take any sampled signal.
"""
from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass, field, replace

import numpy as np

from ..bearing import Bearing
from ..model.start_memo import keeping_starts
from ..results.records import units_of
from ..setup import FROM_SETUP
from .passages import ball_defect_events, defect_events, defect_reaches, impact_summary, passages_cut, read_impacts
from .signals import (ANTI_ALIAS_CORNER, amplitude_spectrum, check_band, envelope_spectrum,  # noqa: F401
                      sampled_signal, spectral_peaks)
from .spall_size import spall_size

__all__ = ["FAULTS", "kinematic_fault_frequencies", "rolling_fault_frequencies", "actual_fault_frequencies", "amplitude_spectrum",
           "sampled_signal", "check_band", "check_band_choice", "envelope_spectrum", "spectral_peaks", "defect_events", "ball_defect_events", "passages_cut", "VibrationResult",
           "vibration"]

#: the fault frequencies, in the order printed
FAULTS = ("BPFO", "BPFI", "BSF", "FTF")
#: what the amplitudes rest on (MODEL.md §13c, 'Contact damping'): stated in every result
AMPLITUDES = ("uncalibrated: no measured amplitude backs them; the contacts' damping ratio is an assumption "
              "(ContactLaw.damping_ratio, 0.05 of critical by default) and the housing the given oscillator")
#: the least share of the signal's power (above 5 x the highest fault frequency) a band must carry
#: for the automatic envelope band: a simulated signal has no noise floor, and spectral kurtosis,
#: blind to amplitude, otherwise picks impulsive bands of 1e-4 m/s² (MODEL.md §13b)
BAND_POWER_SHARE = 0.05
#: Newton's relative tolerance of a vibration run, at most: at the package's 1e-4 (set for the skid,
#: MODEL.md §10b) the Case Western notch's envelope line read 1.7 % off the converged one, more
#: than its half-step change; from 1e-5 down it holds to the last digit, at the same cost (§13c)
RELATIVE_TOLERANCE = 1e-6


def kinematic_fault_frequencies(bearing: Bearing, inner_hz: float, outer_hz: float = 0.0,
                                contact_angle: float | None = None) -> dict:
    """Pure-rolling fault frequencies, Hz (MODEL.md eq. 13.4): with γ = D cos α / d_m and the
    relative speed f_r = f_i − f_o, FTF = f_o + f_r (1 − γ)/2 (the cage), BPFO = Z |FTF − f_o|,
    BPFI = Z |f_i − FTF|, BSF = f_r d_m (1 − γ²) / (2 D) (a ball's spin relative to the cage).
    ``contact_angle`` rad (default: the bearing's)."""
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    gamma = bearing.ball_diameter * math.cos(alpha) / bearing.pitch_diameter
    rel = inner_hz - outer_hz
    ftf = bearing.cage_speed(inner_hz, outer_hz, alpha)  # linear in the speeds: Hz in, Hz out
    return {"BPFO": bearing.balls * abs(ftf - outer_hz), "BPFI": bearing.balls * abs(inner_hz - ftf),
            "BSF": abs(rel) * bearing.pitch_diameter * (1.0 - gamma * gamma) / (2.0 * bearing.ball_diameter),
            "FTF": abs(ftf)}


def rolling_fault_frequencies(results, bearing: Bearing) -> dict:
    """Pure-rolling fault frequencies at the run's own contact geometry, Hz: FTF the mean of
    each ball's pure-rolling orbital speed for its actual contact points and spin axis
    (``kinematic_cage_speed``, MODEL.md §7), BPFO = Z |FTF − f_o|, BPFI = Z |f_i − FTF|, BSF
    by eq. 13.4 at the mean loaded outer contact angle. The actual frequencies sit below
    them by the run's kinematic cage slip."""
    f_c = float(np.mean(results.kinematic_cage_speed)) / (2 * math.pi)
    f_i = float(np.mean(results.inner_speed)) / (2 * math.pi)
    f_o = float(np.mean(results.outer_speed)) / (2 * math.pi)
    load = results.outer["load"]
    alpha = float(np.sum(results.outer["contact_angle"] * load) / max(np.sum(load), 1e-300))
    bsf = kinematic_fault_frequencies(bearing, f_i, f_o, contact_angle=alpha)["BSF"]
    return {"BPFO": bearing.balls * abs(f_c - f_o), "BPFI": bearing.balls * abs(f_i - f_c), "BSF": bsf,
            "FTF": abs(f_c)}


def actual_fault_frequencies(results) -> dict:
    """The fault frequencies of a run, Hz: from its mean cage speed f_c, race speeds and the
    balls' spin relative to the cage (``BearingResults``): BPFO = Z |f_c − f_o|,
    BPFI = Z |f_i − f_c|, BSF = |ω_ball − ω_c e_z| / 2π, FTF = |f_c|."""
    f_c = float(np.mean(results.cage_speed)) / (2 * math.pi)
    f_i = float(np.mean(results.inner_speed)) / (2 * math.pi)
    f_o = float(np.mean(results.outer_speed)) / (2 * math.pi)
    w = results.ball_omega_orbiting.copy()  # (e_psi, e_r, e_z) components
    w[..., 2] -= results.cage_speed[:, None]
    spin = float(np.mean(np.linalg.norm(w, axis=-1))) / (2 * math.pi)
    z = results.ball_orbital_speed.shape[1]
    return {"BPFO": z * abs(f_c - f_o), "BPFI": z * abs(f_i - f_c), "BSF": spin, "FTF": abs(f_c)}


def check_band_choice(band, sample_rate: float):
    """:func:`vibration`'s ``band``: "auto", None, or (low, high) Hz (:func:`check_band`, returned as
    floats); anything else refused by name."""
    if isinstance(band, str):
        if band != "auto":
            raise ValueError(f"band must be 'auto', None or (low, high) Hz, got {band!r}")
        return band
    return None if band is None else check_band(band, sample_rate)


@dataclass
class VibrationResult:
    """One vibration run (SI units; see :func:`vibration`)."""

    time: np.ndarray = field(repr=False)  #: s
    acceleration: np.ndarray = field(repr=False)  #: housing acceleration (T, 3), bearing frame, m/s²
    velocity: np.ndarray = field(repr=False)  #: m/s
    displacement: np.ndarray = field(repr=False)  #: m, from the start
    sample_rate: float  #: Hz
    band: tuple  #: envelope band, Hz
    #: Hz: {"kinematic": pure rolling at the run's contact geometry, "actual": the run's,
    #: "nominal": the catalogue formula at the nominal contact angle}
    fault_frequencies: dict
    envelope_peaks: list  #: [[Hz, m/s²], ...] strongest first
    spectrum_peaks: list
    defect_events: list
    kinematic_cage_slip_percent: float
    wall_time_s: float
    inputs: dict
    results: object = field(repr=False, default=None)  #: the bearing's BearingResults
    #: step s, steps taken, extra_steps (beyond time / step), step_cuts (failed steps tried again
    #: shorter) and their cut_times_s, passages and passages_cut (followed by a cut), Newton
    #: iterations, strike_number (the bounce number B of MODEL.md §13c) and reach_share (the
    #: deepest defect's reach / the ball's approach; >= 0.5: the strike step)
    solver: dict = field(default_factory=dict)
    error_estimate: dict | None = None  #: see :func:`vibration`
    #: the passages as the contact load shows them (:func:`~exudyn_bearing.studies.passages.impact_summary`)
    impacts: dict = field(default_factory=dict)
    #: how the band was chosen: 'kurtogram' (the signal's, eq. 13.9), 'housing' (±40 % about its
    #: resonance) or 'given'; the band's spectral kurtosis; the kurtogram (``studies.kurtogram``)
    band_from: str = "given"
    band_kurtosis: float | None = None
    kurtogram: object = field(repr=False, default=None)
    #: with the setup's thermal network (MODEL.md §14g): temperatures, heat by place and node, heat
    #: carried off and stored (:func:`exudyn_bearing.results.temperatures.thermal_summary`); None without
    thermal: dict | None = None
    #: an outer-race spall sized from the signal alone by its double impulse (MODEL.md eq. 13.10,
    #: :func:`~exudyn_bearing.studies.spall_size.spall_size`) beside its true length; None otherwise
    spall_size: dict | None = None

    def to_dict(self) -> dict:
        return {"fault_frequencies_Hz": self.fault_frequencies, "envelope_peaks_Hz": self.envelope_peaks,
                "spectrum_peaks_Hz": self.spectrum_peaks, "defect_events": self.defect_events,
                "sample_rate_Hz": self.sample_rate, "envelope_band_Hz": list(self.band),
                "envelope_band_from": self.band_from, "envelope_band_kurtosis": self.band_kurtosis,
                "kinematic_cage_slip_percent": self.kinematic_cage_slip_percent, "wall_time_s": self.wall_time_s,
                "solver": self.solver, "error_estimate": self.error_estimate, "impacts": self.impacts,
                "amplitudes": AMPLITUDES, "thermal": self.thermal, "spall_size": self.spall_size,
                "units": {"thermal": None if self.thermal is None else units_of(self.thermal),
                          "fault_frequencies_Hz": "Hz", "envelope_peaks_Hz": "[Hz, m/s^2]",
                          "spectrum_peaks_Hz": "[Hz, m/s^2]", "defect_events": "s; peak_N, load_before_N N", "sample_rate_Hz": "Hz",
                          "envelope_band_Hz": "Hz", "envelope_band_kurtosis": "-", "kinematic_cage_slip_percent": "%", "wall_time_s": "s",
                          "solver": "step_s, cut_times_s in s; counts; strike_number, reach_share -; "
                                    "defect_reach_m [reach, approach] m",
                          "error_estimate": "Hz, %, pp, s", "impacts": "s; N",
                          "spall_size": "length_m, true_length_m, approach_m m; spacing_s s; speed_m_s m/s; "
                                        "ball_load_N N; error_percent %; high_band_Hz Hz",
                          "signal": "t s; acceleration m/s^2, velocity m/s, displacement m (x, y along the "
                                    "bearing frame's radial axes, z axial)"},
                "inputs": self.inputs}


@keeping_starts  # the error estimate's rerun starts from the same start (model.start_memo)
def vibration(bearing, *, rpm: float, axial_force: float = 0.0, radial_force: float = 0.0, time: float = 0.5,
              sample_rate: float = 20000.0, housing=FROM_SETUP, band: tuple | str | None = "auto", settle: float = 0.02,
              surface=FROM_SETUP, settings=None, error_estimate: bool = False, lubricant=FROM_SETUP,
              contact_law=FROM_SETUP, cage=FROM_SETUP, ball_drag=FROM_SETUP, masking=None,
              fluctuation=None, initial_temperatures: str = "auto") -> VibrationResult:
    """Run a bearing (inner race driven at ``rpm``, free translation, loaded by ``axial_force`` and
    ``radial_force`` N; outer race on ``housing``, a ``races.HousingModel`` or ``races.Housing(...)``,
    default the setup's, else ``HousingModel()``) for ``time`` s and
    analyse the housing acceleration recorded at ``sample_rate`` Hz as a data-acquisition
    system records it (sensors written at every step, :func:`sampled_signal`; MODEL.md §13b;
    the time step is at most its period, puts two steps into each defect passage and resolves
    the contact's motion where a ball's contact opens (or loses half its approach) over a
    defect or it strikes the edge hard, a whole number per sample, and the fine steps only near
    the passages; Newton's relative tolerance at most :data:`RELATIVE_TOLERANCE`; §13c):
    spectrum, envelope spectrum in ``band`` — "auto" (default): the band of the largest spectral
    kurtosis (:func:`~exudyn_bearing.studies.kurtogram.kurtogram`, eq. 13.9) at least 3 x the highest
    fault frequency wide and above 5 x it, below the anti-aliasing corner; None: ±40 % about
    the housing resonance; or (low, high) Hz —, fault frequencies, defect
    passages. The first ``settle`` s are left out of the spectra. ``bearing`` a Bearing,
    BearingSetup or path; ``surface`` overrides the setup's (so do ``lubricant``,
    ``contact_law``, ``cage``, ``ball_drag`` and ``housing``). With
    ``error_estimate`` the run is repeated at half the step and ``error_estimate`` holds the
    differences of the strongest envelope line (frequency, amplitude) and of the slip, and twice
    the amplitude's: its error bound where the amplitude converges at order >= 1. ``masking``: a
    :class:`~exudyn_bearing.studies.masking.Masking` (measurement noise, machine lines) added to
    the recorded acceleration before the analysis; None (default): the bearing alone.
    ``fluctuation``: a :class:`~exudyn_bearing.studies.masking.Fluctuation` of the shaft speed
    and the load (the model's own random slip); None: steady. A setup with a ``thermal`` model
    integrates its network with the bodies from ``initial_temperatures`` ('auto', 'steady',
    'inlet'; the builder's ``initialTemperatures``, MODEL.md §14g), and ``thermal`` says where
    the heat went (:func:`~exudyn_bearing.results.temperatures.thermal_summary`). A surface with
    one outer-race spall has it sized from the analysed signal alone in ``spall_size`` (MODEL.md
    eq. 13.10; a ``sample_rate`` of at least 50 kHz)."""
    import exudyn as exu

    from ..bearingfile import as_setup
    from ..model.builder import CreateAngularContactBearing
    from ..races import Driven, HousingModel
    from ..model.steprule import reach_share, strike_number
    from ..simulation.runner import SolverSettings, run_solver
    from .masking import Fluctuation

    _check_inputs(rpm, axial_force, radial_force, time, sample_rate, housing, settle, masking, fluctuation, band)
    setup = as_setup(bearing, lubricant=lubricant, contact_law=contact_law, cage=cage, drag=ball_drag,
                     surface=surface)
    bearing, surface = setup.bearing, setup.surface
    if isinstance(housing, HousingModel):
        housing = housing.race()
    elif housing is FROM_SETUP or housing is None:
        housing = (setup.housing or HousingModel()).race()
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    vary = fluctuation or Fluctuation()
    handle = CreateAngularContactBearing(mbs, setup, innerRace=Driven(vary.speed(rpm)), outerRace=housing,
                                         axialForce=vary.load(axial_force), radialForce=vary.load(radial_force),
                                         initialTemperatures=initial_temperatures, show=False)
    sensors = handle.AddVibrationSensors(mbs)
    mbs.Assemble()
    period = 1.0 / sample_rate
    settings = settings or SolverSettings()
    settings = replace(settings, relative_tolerance=min(settings.relative_tolerance, RELATIVE_TOLERANCE))
    loads = handle.initialLoads
    strike = strike_number(bearing, surface, loads, rpm) if loads is not None else 0.0
    share = reach_share(bearing, surface, loads, rpm) if loads is not None else 0.0
    coarse, step, windows = _steps(handle, settings, rpm, period)
    # the sensors (and the bearing's states) at every step: sampled_signal then records the
    # housing as a data-acquisition system would, through an anti-aliasing filter
    settings = replace(settings, step=coarse, passage_step=step if step < coarse else None, output_step=step)
    wall = _time.perf_counter()
    info = run_solver(mbs, [handle], time, settings, windows=[windows])
    wall = _time.perf_counter() - wall
    fine_time = time if info.fine_time_s is None else info.fine_time_s
    planned = int(round(fine_time / step + (time - fine_time) / coarse))
    frame = handle.connector.rotation
    names = ("Acceleration", "Velocity", "Displacement")
    data = [np.asarray(mbs.GetSensorStoredData(sensors[k])) for k in names]
    # the three sensors are written at the same step ends: one spline and one filter for all
    t, recorded = sampled_signal(data[0][:, 0], np.hstack([d[:, 1:4] for d in data]), sample_rate, step=step)
    acc, vel, disp = (recorded[:, 3 * i:3 * i + 3] @ frame for i in range(3))
    # the bearing's outputs at <= 2 kHz: means and smooth ball angles (1 s of 20-kHz states
    # costs ~90 s through the connector, 10x the run's own post-processing otherwise)
    results = handle.Results(mbs, stride=max(1, int(round(1.0 / step)) // 2000))
    keep = t >= settle
    kept = results.time >= settle
    sub = replace(results, **{k: v[kept] for k, v in vars(results).items()
                              if isinstance(v, np.ndarray) and v.shape[:1] == results.time.shape})
    f_i = rpm / 60.0
    resonance = math.sqrt(housing.support[0] / housing.mass) / (2 * math.pi)
    load = np.array([radial_force, 0.0, axial_force])
    if masking is not None and masking.active:  # the bearing's force on the housing drives its further modes
        k, c = housing.support
        acc = masking.apply(t, acc, load, f_i, settle, force=housing.mass * acc + c * vel + k * disp)
    signal = acc[keep] @ (load / np.linalg.norm(load))  # along the load (x radial, z axial)
    faults = {"kinematic": rolling_fault_frequencies(sub, bearing), "actual": actual_fault_frequencies(sub),
              "nominal": kinematic_fault_frequencies(bearing, f_i)}
    requested = band
    band, band_from, chart = _envelope_band(band, signal, sample_rate, faults["kinematic"], resonance)
    f_env, a_env = envelope_spectrum(signal, sample_rate, band)  # (its lines lie below the band's width)
    f_sp, a_sp = amplitude_spectrum(signal, sample_rate)
    events = _passage_events(handle, mbs, results, surface)
    thermal = handle.ThermalSummary(mbs)
    inputs = handle.Inputs(rpm=rpm, axial_force=axial_force, radial_force=radial_force, time=time,
                           sample_rate=sample_rate, housing=housing, band=requested, settle=settle, step=step,
                           **({} if masking is None else {"masking": masking}),
                           **({} if fluctuation is None else {"fluctuation": fluctuation}))
    out = VibrationResult(t, acc, vel, disp, sample_rate, tuple(band), faults,
                          spectral_peaks(f_env, a_env, 10, min_hz=1.0, max_hz=band[1] - band[0]),
                          spectral_peaks(f_sp, a_sp, 10, min_hz=1.0), events,
                          float(np.mean(sub.kinematic_cage_slip_percent)), wall, inputs, results,
                          {"step_s": step, "coarse_step_s": coarse, "passage_time_share": fine_time / time,
                           "steps": int(info.steps), "extra_steps": int(info.steps) - planned,
                           "step_cuts": len(info.cut_times), "cut_times_s": [float(c) for c in info.cut_times],
                           "passages_cut": passages_cut(events, info.cut_times), "passages": len(events),
                           "newton_iterations": int(info.newton_iterations), "strike_number": strike,
                           "reach_share": share,
                           "defect_reach_m": defect_reaches(bearing, surface, loads) if loads is not None else [],
                           "surface_start": (handle.connector.surface_start or {}).get("message")},
                          impacts=impact_summary(events), band_from=band_from,
                          band_kurtosis=None if chart is None else chart.band_kurtosis, kurtogram=chart,
                          thermal=thermal,
                          spall_size=spall_size(signal, sample_rate, bearing, surface,
                                                bpfo_hz=faults["actual"]["BPFO"], loads=loads))
    if error_estimate:
        finer = vibration(setup, rpm=rpm, axial_force=axial_force, radial_force=radial_force, time=time,
                          sample_rate=sample_rate, housing=housing, band=band, settle=settle, masking=masking,
                          fluctuation=fluctuation, initial_temperatures=initial_temperatures,
                          settings=replace(settings, step=0.5 * coarse,
                                           passage_step=0.5 * step if step < coarse else None))
        out.error_estimate = _error_estimate(out, finer, 0.5 * step)
    return out


def _check_inputs(rpm, axial_force, radial_force, time, sample_rate, housing, settle, masking, fluctuation, band):
    """:func:`vibration`'s inputs, each refused by name before the run where it cannot be run."""
    from ..races import HousingModel
    from .masking import Fluctuation, Masking

    if not (math.isfinite(sample_rate) and sample_rate > 0):
        raise ValueError(f"sample_rate must be positive, got {sample_rate!r}")
    if not (math.isfinite(rpm) and rpm > 0):
        raise ValueError(f"rpm must be positive, got {rpm!r}")
    if not (axial_force or radial_force):
        raise ValueError("no load: give axial_force and/or radial_force, N")
    if housing is not FROM_SETUP and housing is not None and not isinstance(housing, HousingModel) \
            and getattr(housing, "kind", None) != "housing":
        raise ValueError(f"housing must be a races.HousingModel(...) or races.Housing(...), got {housing!r}")
    if masking is not None and not isinstance(masking, Masking):
        raise ValueError(f"masking must be a studies.masking.Masking(...) or None, got {masking!r}")
    if fluctuation is not None and not isinstance(fluctuation, Fluctuation):
        raise ValueError(f"fluctuation must be a studies.masking.Fluctuation(...) or None, got {fluctuation!r}")
    if not (math.isfinite(time) and time > settle >= 0):
        raise ValueError(f"time must exceed the settling time {settle} s, got {time!r}")
    check_band_choice(band, sample_rate)


def _passage_events(handle, mbs, results, surface) -> list:
    """The defect passages of a run (:mod:`~exudyn_bearing.studies.passages`): each ball's over
    each race defect from the outputs, a pit's from the recorded rotations, and what the contact
    load at every recorded step shows of each (entry, impact, peak)."""
    if not surface.defects:
        return []
    events = defect_events(results, handle.bearing, surface)
    states = handle.States(mbs)
    if any(d.race == "ball" for d in surface.defects):
        events = sorted(events + ball_defect_events(handle.connector, *states), key=lambda e: e["edge_s"])
    return read_impacts(handle.connector, events, *states)


def _error_estimate(run, finer, reference_step) -> dict:
    """:func:`vibration`'s ``error_estimate`` from the ``run`` and its rerun at half the step."""
    (f0, a0), (f1, a1) = run.envelope_peaks[0], finer.envelope_peaks[0]
    return {"method": "rerun at half the step", "reference_step_s": reference_step,
            "reference_wall_time_s": finer.wall_time_s,
            "envelope_line_Hz": abs(f1 - f0), "envelope_amplitude_percent": 100 * abs(a1 - a0) / a1,
            # the run's error where the amplitude converges at order >= 1 from its step down: at
            # most change / (1 - 2^-1) (MODEL.md §13c)
            "envelope_amplitude_bound_percent": 200 * abs(a1 - a0) / a1,
            "kinematic_cage_slip_pp": abs(finer.kinematic_cage_slip_percent - run.kinematic_cage_slip_percent)}


def _envelope_band(band, signal, sample_rate, faults, resonance):
    """(band Hz, how it was chosen, the kurtogram or None) of :func:`vibration`'s ``band``: "auto",
    None (the housing's) or (low, high)."""
    corner = ANTI_ALIAS_CORNER * sample_rate
    housing = (0.6 * resonance, min(1.4 * resonance, corner))
    if band is None:
        return housing, "housing", None
    if isinstance(band, str):  # "auto" (_check_inputs refused any other word)
        from .kurtogram import kurtogram

        top = max(faults["BPFO"], faults["BPFI"], 2.0 * faults["BSF"])
        try:
            chart = kurtogram(signal, sample_rate, min_hz=5.0 * top, max_hz=corner, min_width=3.0 * top,
                              min_power_share=BAND_POWER_SHARE)
        except ValueError:  # no band that wide above 5 x the faults below the corner: the housing's
            return housing, "housing", None
        return chart.band, "kurtogram", chart
    return check_band(band, sample_rate), "given", None


def _steps(handle, settings, rpm, period):
    """(coarse step, passage step, passage windows) of a vibration run, s (MODEL.md §13c):
    the bearing's step (or ``settings.step``) at most the sample ``period``, and the surface's
    step (:meth:`~exudyn_bearing.model.handle.BearingHandle.RecommendedSurfaceStep`, or
    ``settings.passage_step``) only inside the passage windows — everywhere where a ball has a
    pit (its passages follow the ball's rotation) or ``settings.step`` alone is given; each a
    whole number per sample."""
    def whole(h):  # a whole number of steps per sample
        return period / math.ceil(period / min(h, period) - 1e-9)

    if settings.step is not None and settings.passage_step is None:
        return whole(settings.step), whole(settings.step), None
    coarse = whole(settings.step or handle.RecommendedStep())
    fine = whole(min(coarse, settings.passage_step or handle.RecommendedSurfaceStep(rpm)))
    windows = handle.PassageWindows(rpm, 0.0, coarse) if fine < coarse else None
    return (coarse if windows is not None else fine), fine, windows


def write_signal(result: VibrationResult, path) -> None:
    """The housing signal as CSV (t s; acceleration m/s², velocity m/s, displacement m; x, y
    radial along the bearing frame, z axial), its inputs on the first line as a comment."""
    import json

    header = "# " + json.dumps(result.inputs, default=str) + "\n"
    cols = ["t_s"] + [f"{q}_{a}_{u}" for q, u in (("acc", "m_s2"), ("vel", "m_s"), ("disp", "m")) for a in "xyz"]
    table = np.column_stack([result.time, result.acceleration, result.velocity, result.displacement])
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(header + ",".join(cols) + "\n")
        np.savetxt(fh, table, delimiter=",", fmt="%.9g")
