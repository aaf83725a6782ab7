"""A race spall's length from the vibration signal alone, by its double impulse (MODEL.md §13e,
eq. 13.10; after Sawalhi & Randall 2011).

A ball rolling over a spall unloads as it rolls down the entry edge: the housing, at rest
until then, starts to respond (the *entry*, an onset with little high-frequency content). It
is loaded again where the exit edge comes back up to it: the *strike*, whose response is
strongest in a high band. The two come Δt apart; the ball's speed over the race turns Δt into
a length, and eq. 13.8's offsets (where the contact starts to unload, x_e after the entry edge;
where it is struck, u before the exit edge) complete it (:func:`contact.defect_passage.length_from_spacing`).

Steps, from the signal and the passages' frequency f (the run's actual fault frequency):

1. *Strikes by a synchronous fold.* The high band's squared envelope averaged over the
   passages at every phase of the period T = 1/f; the strike is its largest; each passage is
   then aligned to the passages' average high band by cross-correlation (three passes), and the
   average's envelope maximum sets the common origin. No per-passage maximum is read (it jumps
   between the strike and the ring before it).
2. *Synchronous average* of the signal, the passages aligned at their strikes: what repeats
   every passage stays, noise and other sources fall as 1/√(passages).
3. *Entry*: in the half period before the strike, the earliest time the average's trailing rms
   (over :data:`RMS_WINDOW_S`) exceeds :data:`ENTRY_SHARE` of its largest value and
   :data:`BASELINE_FACTOR` times its median over the quiet first half of that window, where the
   rms over :data:`CONFIRM_WINDOW_S` passes its own such level within that window after it
   (a ring follows an onset; a noise spike is alone).

What limits it: the spacing must be below a quarter period (the quiet baseline), the previous
strike's ring must have died before the next entry (low speed or a damped housing), and the
ball must lose its load over the spall (its reach at least its approach; a shallow dent has no
double impulse).
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field

import numpy as np

from contact.defect_passage import length_from_spacing
from contact.geometry import contact_path_radius

from .passages import ball_approach
from .signals import bandpass, check_band

__all__ = ["DoubleImpulse", "double_impulse", "spall_size", "HIGH_BAND_HZ", "MIN_SAMPLE_RATE_HZ", "ENTRY_SHARE",
           "BASELINE_FACTOR", "RMS_WINDOW_S"]

#: the strikes' band, Hz: above the housing's and the rings' resonances (a few kHz), below the
#: anti-aliasing corner (0.4 x the sample rate) of a 50-kHz record
HIGH_BAND_HZ = (8000.0, 19000.0)
#: the least sample rate :func:`spall_size` reads (checked at 50 kHz; at 20–40 kHz, with the band
#: at the same shares of the rate, the lengths spread from −48 to +19 %: docs/DEVELOPMENT.md)
MIN_SAMPLE_RATE_HZ = 50000.0
#: the share of the synchronous average's largest trailing rms that marks the entry's onset
ENTRY_SHARE = 0.02
#: the entry's onset must also exceed this multiple of the quiet baseline's rms (noise)
BASELINE_FACTOR = 3.0
#: the trailing rms window, s
RMS_WINDOW_S = 5e-5
#: the longer trailing rms window that confirms an onset (a ring, not a noise spike), s
CONFIRM_WINDOW_S = 2e-4
#: cross-correlation passes that align the passages to their average
ALIGN_PASSES = 3


@dataclass(frozen=True)
class DoubleImpulse:
    """The double impulse read from a signal (:func:`double_impulse`)."""

    spacing_s: float | None  #: entry to strike, s; None where no entry stood out (see ``message``)
    strikes_s: np.ndarray = field(repr=False)  #: the passages' strike times, s of the signal
    profile_t_s: np.ndarray = field(repr=False)  #: the synchronous average's time from the strike, s
    profile: np.ndarray = field(repr=False)  #: the synchronous average of the signal
    passages: int = 0  #: passages averaged
    message: str = ""  #: why no spacing was read ('' where one was)


def _trailing_rms(x, sample_rate, window, quiet):
    """The rms of ``x`` over the trailing ``window`` s (it rises at an onset, not before it) and
    the level an onset must pass: :data:`ENTRY_SHARE` of its largest value and
    :data:`BASELINE_FACTOR` times its median where ``quiet``."""
    k = max(1, int(round(window * sample_rate)))
    rms = np.sqrt(np.convolve(x ** 2, np.ones(k) / k)[:x.size])
    return rms, max(ENTRY_SHARE * rms.max(), BASELINE_FACTOR * float(np.median(rms[quiet])))


def _segments(x, sample_rate, starts, lags):
    """``x`` at ``starts[k] + lags`` s (linear interpolation), one row per start."""
    t = np.arange(x.size) / sample_rate
    return np.array([np.interp(s + lags, t, x) for s in starts])


def _peak(values) -> float:
    """The index of the largest of ``values``, refined by a parabola through its neighbours."""
    i = int(np.argmax(values))
    if 0 < i < len(values) - 1:
        a, b, c = values[i - 1], values[i], values[i + 1]
        den = a - 2.0 * b + c
        if den < 0:
            return i + 0.5 * (a - c) / den
    return float(i)


def _fold_strikes(high, envelope, sample_rate, period):
    """Step 1: the passages' strike times, s (a synchronous fold, then cross-correlation)."""
    n = int(math.floor(envelope.size / sample_rate / period)) - 1
    phases = np.arange(int(round(period * sample_rate))) / sample_rate
    folded = _segments(envelope, sample_rate, period * np.arange(n), phases).mean(axis=0)
    strikes = phases[int(np.argmax(folded))] + period * np.arange(n + 1)
    last = envelope.size / sample_rate
    strikes = strikes[(strikes > 0.25 * period) & (strikes < last - 0.25 * period)]
    half = int(round(0.2 * period * sample_rate))
    shift = int(round(0.05 * period * sample_rate))
    window = np.arange(-half, half + 1) / sample_rate
    wide = np.arange(-half - shift, half + shift + 1) / sample_rate
    for _ in range(ALIGN_PASSES):
        template = _segments(high, sample_rate, strikes, window).mean(axis=0)
        rows = _segments(high, sample_rate, strikes, wide)
        strikes = strikes + np.array([(_peak(np.correlate(r, template, "valid")) - shift) / sample_rate
                                      for r in rows])
    # the common origin: the aligned average envelope's largest value
    near = np.arange(-shift, shift + 1) / sample_rate
    mean_env = _segments(envelope, sample_rate, strikes, near).mean(axis=0)
    return strikes + (_peak(mean_env) - shift) / sample_rate


def double_impulse(signal, sample_rate: float, fault_hz: float, high_band: tuple | None = None) -> DoubleImpulse:
    """The spacing of a race defect's double impulse in ``signal`` (m/s², sampled at
    ``sample_rate`` Hz) whose passages come at ``fault_hz`` (the run's actual fault frequency,
    e.g. BPFO) (eq. 13.10, module docstring); ``high_band`` Hz for the strikes (default
    :data:`HIGH_BAND_HZ`). Raises ValueError where the signal holds fewer than four passages,
    the band does not lie below half the sample rate or the inputs are not finite."""
    from scipy.signal import hilbert

    x = np.asarray(signal, dtype=float)
    if x.ndim != 1 or not np.all(np.isfinite(x)):
        raise ValueError("signal must be a finite 1-D array")
    for name, value in (("sample_rate", sample_rate), ("fault_hz", fault_hz)):
        if not (isinstance(value, numbers.Real) and math.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be a positive number, got {value!r}")
    period = 1.0 / fault_hz
    if x.size / sample_rate < 4.5 * period:
        raise ValueError(f"double_impulse: need at least 4 passages at {fault_hz:g} Hz, the signal holds "
                         f"{x.size / sample_rate * fault_hz:.1f}")
    band = check_band(high_band or HIGH_BAND_HZ, sample_rate, "high_band")
    x = x - np.mean(x)
    high = bandpass(x, sample_rate, band)
    strikes = _fold_strikes(high, np.abs(hilbert(high)) ** 2, sample_rate, period)
    before, after = int(round(0.5 * period * sample_rate)), int(round(0.1 * period * sample_rate))
    lags = np.arange(-before, after) / sample_rate
    keep = (strikes - 0.5 * period >= 0) & (strikes + 0.1 * period <= x.size / sample_rate)
    strikes = strikes[keep]
    if strikes.size < 3:
        raise ValueError("double_impulse: fewer than 3 whole passages in the signal")
    profile = _segments(x, sample_rate, strikes, lags).mean(axis=0)
    quiet = (lags >= -0.5 * period + CONFIRM_WINDOW_S) & (lags < -0.25 * period)
    short, level = _trailing_rms(profile, sample_rate, RMS_WINDOW_S, quiet)
    long, long_level = _trailing_rms(profile, sample_rate, CONFIRM_WINDOW_S, quiet)
    reach = int(round(CONFIRM_WINDOW_S * sample_rate))
    search = np.flatnonzero((lags >= -0.5 * period + CONFIRM_WINDOW_S) & (lags < -2 * RMS_WINDOW_S) & (short > level))
    # a noise spike lifts the short rms alone: the entry's ring lifts the longer one after it too
    search = [i for i in search if long[i:i + reach + 1].max() > long_level]
    spacing, message = None, ""
    if not search:
        message = "no entry stands out of the quiet part of the synchronous average before the strike"
    elif lags[search[0]] < -0.25 * period:
        message = (f"the average is not quiet a quarter period before the strike ({-lags[search[0]] * 1e3:.3f} ms): "
                   "the previous strike still rings, or the spall is longer than the method reads")
    else:
        i = search[0]  # the crossing interpolated between samples
        frac = (level - short[i - 1]) / (short[i] - short[i - 1]) if short[i] > short[i - 1] else 0.0
        spacing = float(-(lags[i - 1] + frac / sample_rate))
    return DoubleImpulse(spacing, strikes, lags, profile, int(strikes.size), message)


def spall_size(signal, sample_rate: float, bearing, surface, *, bpfo_hz: float, loads) -> dict | None:
    """The outer-race spall of ``surface`` sized from ``signal`` alone (eq. 13.10): its double
    impulse's spacing (:func:`double_impulse` at the run's actual ``bpfo_hz``) times the contact's
    speed over the race, v = 2π (BPFO / Z) ρ_o, plus eq. 13.8's offsets at the ball's quasi-static
    load at the spall (``loads``, the perfect bearing's :class:`LoadDistribution` at the run's
    load, interpolated at the spall's azimuth). None unless the surface holds exactly one race
    defect and it is on the outer race (an inner-race spall turns through the load zone, a
    ball's pit strikes both races: not read). Returns {"length_m", "true_length_m",
    "error_percent", "spacing_s", "speed_m_s", "ball_load_N", "approach_m", "passages",
    "high_band_Hz", "message"}; the length and error are None where no spacing was read."""
    defects = () if surface is None else surface.defects
    if len(defects) != 1 or defects[0].race != "outer" or loads is None:
        return None
    d = defects[0]
    try:
        if sample_rate < MIN_SAMPLE_RATE_HZ:
            raise ValueError(f"not read: sizing reads the strikes in {HIGH_BAND_HZ[0]:g}-{HIGH_BAND_HZ[1]:g} Hz and "
                             f"needs a sample rate of at least {MIN_SAMPLE_RATE_HZ:g} Hz (given {sample_rate:g} Hz)")
        found = double_impulse(signal, sample_rate, bpfo_hz)
    except ValueError as e:  # a short or coarse record: said, not raised (the rest of the analysis stands)
        found = DoubleImpulse(None, np.zeros(0), np.zeros(0), np.zeros(0), 0, str(e))
    rho = float(contact_path_radius(bearing.ball_diameter, bearing.pitch_diameter, bearing.contact_angle, "outer"))
    speed = 2.0 * math.pi * bpfo_hz / bearing.balls * rho
    load = float(np.interp(math.radians(d.angle_deg), np.asarray(loads.azimuth, dtype=float),
                           np.asarray(loads.outer_load, dtype=float), period=2.0 * math.pi))
    approach = ball_approach(bearing, load)
    r_x = float(bearing.curvature_radii(bearing.contact_angle, "outer")[0])
    length = None
    if found.spacing_s is not None and approach > 0:
        length = length_from_spacing(found.spacing_s, speed, r_x, approach)
    return {"length_m": length, "true_length_m": d.length,
            "error_percent": None if length is None else 100.0 * (length - d.length) / d.length,
            "spacing_s": found.spacing_s, "speed_m_s": speed, "ball_load_N": load, "approach_m": approach,
            "passages": found.passages, "high_band_Hz": list(HIGH_BAND_HZ),
            "message": found.message or ("" if approach > 0 else "no ball load at the spall's azimuth")}
