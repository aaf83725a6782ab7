"""The "settled" flag every result carries (README, MODEL.md §7): ``outputs.settled`` and
``BearingResults.settled``/``summary`` on synthetic series whose answer is known in
closed form (window means of a ramp and of a sine, the spread of a mean of white noise),
never on numbers the code produced.

``settled(time, values, tolerance, window)`` compares the mean over the last ``window``
of the run with the mean over the window before it. ``BearingResults.settled`` applies it
to the cage speed in % of its run mean and to the kinematic cage slip in percentage
points, with the default tolerance 0.1, on runs of at least 50 ms.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from exudyn_bearing.results.outputs import BearingResults, settled

T = 0.3  # s, run length of the synthetic series
N = 6001  # samples: 1000 per sixth of the run
TIME = np.linspace(0.0, T, N)
W = 1 / 6  # the default window


def window_means(f, window=W, t_end=T):
    """Exact means of f over the last window and the one before it (continuous time):
    (mean over [t_end - w T, t_end], mean over [t_end - 2 w T, t_end - w T]) for f given
    as its antiderivative F."""
    span = window * t_end
    last = (f(t_end) - f(t_end - span)) / span
    previous = (f(t_end - span) - f(t_end - 2 * span)) / span
    return last, previous


# ---------------------------------------------------------------------------------------
# outputs.settled
# ---------------------------------------------------------------------------------------
def test_steady_series_is_settled():
    rng = np.random.default_rng(1)
    values = 82.6 + 1e-6 * rng.standard_normal(N)
    assert settled(TIME, values, 1e-3)
    # an offset alone is no drift
    assert settled(TIME, values + 1e3, 1e-3)


def test_linear_drift_threshold():
    """values = s t: the window means differ by exactly s w T (continuous time; 1000
    samples per window move it by 0.05 %), so the threshold slope is tol / (w T)."""
    tol = 0.01
    s_star = tol / (W * T)
    last, previous = window_means(lambda t: 0.5 * s_star * t * t)
    assert last - previous == pytest.approx(tol, rel=1e-12)  # the closed form itself
    assert not settled(TIME, 1.03 * s_star * TIME, tol)
    assert settled(TIME, 0.97 * s_star * TIME, tol)
    assert not settled(TIME, -1.03 * s_star * TIME, tol)  # falling drifts count too
    assert settled(TIME, -0.97 * s_star * TIME, tol)


def test_window_argument_is_used():
    """The same ramp drifts twice as much between windows twice as long."""
    tol = 0.01
    slope = 0.75 * tol / (W * T)
    assert settled(TIME, slope * TIME, tol, window=W)
    assert not settled(TIME, slope * TIME, tol, window=2 * W)  # 1.5 tol


def test_slow_oscillation_is_not_settled():
    """A sine with a period of the whole run (6 windows): its window means differ by a
    fixed fraction of the amplitude, computed here; 3x the tolerance is not settled,
    0.3x is."""
    tol = 0.01
    omega = 2 * math.pi / T
    last, previous = window_means(lambda t: -np.cos(omega * t) / omega)  # amplitude 1
    step = abs(last - previous)
    assert step > 0.4  # a slow sine moves its window means by a large part of its amplitude
    amplitude = 3 * tol / step
    assert not settled(TIME, amplitude * np.sin(omega * TIME), tol)
    assert settled(TIME, 0.1 * amplitude * np.sin(omega * TIME), tol)


def test_fast_oscillation_averages_out():
    """Ten periods in each window: both window means are 0 (closed form), so even an
    amplitude 100x the tolerance is settled; the sampled means differ from 0 only by the
    endpoint samples, ~amplitude / 1000."""
    tol = 0.01
    omega = 2 * math.pi * 10 / (W * T)
    last, previous = window_means(lambda t: -np.cos(omega * t) / omega)
    assert abs(last - previous) < 1e-9
    assert settled(TIME, 100 * tol * np.sin(omega * TIME), tol)


def test_zero_mean_noise_is_settled():
    """White noise with sigma = 10x the tolerance: each sample misses the tolerance, but
    the difference of two window means of n samples has spread sigma sqrt(2/n), here
    22 times below the tolerance."""
    tol = 0.01
    sigma = 10 * tol
    n_total = 600_001
    time = np.linspace(0.0, T, n_total)
    n_window = (n_total - 1) // 6
    spread = sigma * math.sqrt(2.0 / n_window)
    assert tol > 20 * spread
    rng = np.random.default_rng(12345)
    values = sigma * rng.standard_normal(n_total)
    assert np.mean(np.abs(np.diff(values)) > tol) > 0.9  # sample to sample it never looks settled
    assert settled(time, values, tol)
    # the same noise on a drift of 2x the tolerance between windows is not
    assert not settled(time, values + 2 * tol / (W * T) * time, tol)


def test_too_few_samples_is_not_settled():
    """Fewer than two samples in a window: no evidence, not settled."""
    time = np.linspace(0.0, T, 6)  # one sample per sixth
    assert not settled(time, np.full(6, 1.0), 1.0)
    time = np.linspace(0.0, T, 13)  # two per sixth
    assert settled(time, np.full(13, 1.0), 1.0)


# ---------------------------------------------------------------------------------------
# BearingResults.settled / summary
# ---------------------------------------------------------------------------------------
def results(time, cage_speed, kinematic_slip=None, z=4):
    """A BearingResults with the given cage speed and kinematic cage slip; the other
    arrays are zeros of the documented shapes."""
    steps = len(time)
    if kinematic_slip is None:
        kinematic_slip = np.zeros(steps)
    zeros = np.zeros(steps)
    per_ball = np.zeros((steps, z))
    contact = {name: per_ball.copy() for name in ("load", "contact_angle", "slip_rolling", "slip_transverse", "slip",
                                                  "spin", "film", "traction_rolling", "traction_transverse",
                                                  "spin_moment", "heat", "max_pressure")}
    return BearingResults(np.asarray(time, dtype=float), zeros, zeros, np.asarray(cage_speed, dtype=float), zeros,
                          zeros, per_ball, np.asarray(kinematic_slip, dtype=float), per_ball, per_ball,
                          np.zeros((steps, z, 3)), per_ball, per_ball, contact, dict(contact))


def cage_ramp_threshold(tolerance_percent, window=W, t_end=T):
    """Relative slope k of a cage speed w0 (1 + k t) whose drift in % of its run mean
    between the windows equals the tolerance: 100 k w T / (1 + k T / 2) = tol."""
    return tolerance_percent / (t_end * (100.0 * window - 0.5 * tolerance_percent))


def test_cage_speed_drift_threshold_in_percent():
    k_star = cage_ramp_threshold(0.1)
    w0 = 82.6
    mean = w0 * (1 + k_star * T / 2)
    last, previous = window_means(lambda t: w0 * (t + 0.5 * k_star * t * t))
    assert 100 * (last - previous) / mean == pytest.approx(0.1, rel=1e-12)  # the closed form
    assert not results(TIME, w0 * (1 + 1.03 * k_star * TIME)).settled()
    assert results(TIME, w0 * (1 + 0.97 * k_star * TIME)).settled()
    # relative: the same relative drift at another speed level gives the same answer
    assert not results(TIME, 7.0 * (1 + 1.03 * k_star * TIME)).settled()
    assert results(TIME, 7.0 * (1 + 0.97 * k_star * TIME)).settled()


def test_kinematic_slip_drift_threshold_in_points():
    """The kinematic slip is compared in percentage points (not relative to itself)."""
    s_star = 0.1 / (W * T)  # points per second
    cage = np.full(N, 82.6)
    assert not results(TIME, cage, 5.0 + 1.03 * s_star * TIME).settled()
    assert results(TIME, cage, 5.0 + 0.97 * s_star * TIME).settled()
    assert results(TIME, cage, 50.0 + 0.97 * s_star * TIME).settled()  # level does not matter


def test_default_tolerance_is_a_tenth_of_a_percent():
    """A drift of 0.2 % of the cage speed, or of 0.2 points of kinematic slip, between the
    last two sixths is unsettled with the default tolerance and in ``summary`` (a default
    of 10 would call both settled); a tolerance passed in is honoured."""
    cage = 82.6 * (1 + 2 * cage_ramp_threshold(0.1) * TIME)
    drifting_cage = results(TIME, cage)
    assert not drifting_cage.settled()
    assert drifting_cage.summary()["settled"] is False
    assert drifting_cage.settled(tolerance_percent=0.3)
    assert drifting_cage.summary(settle_tolerance_percent=0.3)["settled"] is True
    drifting_slip = results(TIME, np.full(N, 82.6), 1.0 + 0.2 / (W * T) * TIME)
    assert not drifting_slip.settled()
    assert drifting_slip.summary()["settled"] is False
    assert drifting_slip.settled(tolerance_percent=0.3)
    steady = results(TIME, np.full(N, 82.6), np.full(N, 1.0))
    assert steady.settled() and steady.summary()["settled"] is True


def test_noisy_cage_speed_is_settled():
    """Cage speed with white noise of 1 % (10x the tolerance) around a constant: the
    window-mean difference has spread 1 % sqrt(2/n), 14 times below 0.1 %."""
    rng = np.random.default_rng(7)
    n_total = 240_001
    time = np.linspace(0.0, T, n_total)
    spread = 1.0 * math.sqrt(2.0 / ((n_total - 1) // 6))
    assert 0.1 > 10 * spread
    cage = 82.6 * (1 + 0.01 * rng.standard_normal(n_total))
    slip = 2.0 + 1.0 * rng.standard_normal(n_total)
    assert results(time, cage, slip).settled()


def test_short_runs_are_not_settled():
    """Shorter than ``minimum_time`` (50 ms by default): too short to judge (None) however
    flat, a distinct value from False (drifting)."""
    for span, expected in ((0.049, None), (0.051, True)):
        time = np.linspace(0.0, span, 601)
        assert results(time, np.full(601, 82.6)).settled() is expected
    time = np.linspace(0.0, 0.03, 601)
    assert results(time, np.full(601, 82.6)).settled(minimum_time=0.02)
    assert results(time, np.full(601, 82.6)).settled(minimum_time=0.04) is None
    # the window is measured from the first recorded time, not from 0
    time = 1.0 + np.linspace(0.0, 0.049, 601)
    assert results(time, np.full(601, 82.6)).settled() is None
