"""Cost and step convergence of the vibration run (MODEL.md §13c; issue 33).

    python benchmarks/vibration.py [--quick]

Prints, in one session (ratios are what to compare; the host is shared):
1. the defective CWRU 6205 (0.18-mm, 0.28-mm-deep outer-race notch) at 1797 rpm, 300 N radial,
   housing at 3 kHz, 20 kHz output: wall time for 1 s simulated;
2. the same at steps of 1, 1/2, ... 1/16 of the sample period (--quick: 1/4) over 0.3 s: the
   strongest envelope line (frequency, amplitude), its change per halving (the half-step error
   estimate) and each step's difference from the finest;
3. the reference bearing at 1300 N, 1800 rpm, 0.1 s on its housing: clean vs outer-race
   waviness (orders 15, 16, 17 at 0.1 um), wall-time ratio;
4. a hard strike: the spindle bearing's 0.5-mm, 5-um outer spall at 12 000 rpm, 500 N axial,
   0.1 s: the bounce number, the BPFO line at the passage rule's 12.5 us and at the default
   (strike) step with its half-step error bound, against a run at a quarter of that step
   (--quick: no quarter-step run);
5. a second of signal (--quick: 0.2 s) where the strike step holds only near the passages
   (MODEL.md §13c, issue 49 item 6): a 12-ball bearing (the 6205's balls on a 54-mm pitch) with
   a 0.8-mm, 0.3-mm-deep outer notch at 600 rpm, 500 N radial (target 1 s <= 60 s on 2 cores),
   and the same at the strike step throughout over a tenth of the time (wall-time ratio per
   simulated second, the strongest envelope line of both).
"""
from __future__ import annotations

import sys
import time
from dataclasses import replace

from contact.surface import Defect, SurfaceModel, Waviness
from exudyn_bearing import CWRU_6205_BEARING, REFERENCE_BEARING
from exudyn_bearing.presets import SPINDLE_40MM_BEARING
from exudyn_bearing.simulation.runner import SolverSettings
from exudyn_bearing.studies.vibration import vibration

NOTCH = SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),))


def main(quick: bool) -> None:
    length = 0.2 if quick else 1.0
    t0 = time.perf_counter()
    r = vibration(CWRU_6205_BEARING, rpm=1797, radial_force=300.0, time=length, surface=NOTCH)
    print(f"1. CWRU 6205 notch, {length:g} s at 20 kHz: run {r.wall_time_s:.1f} s, whole call "
          f"{time.perf_counter() - t0:.1f} s; envelope line {r.envelope_peaks[0][0]:.2f} Hz "
          f"({r.envelope_peaks[0][1]:.4g} m/s^2), actual BPFO {r.fault_frequencies['actual']['BPFO']:.3f} Hz, "
          f"{len(r.defect_events)} passages; step {r.solver['step_s']:g} s, {r.solver['steps']} steps "
          f"({r.solver['extra_steps']} beyond the plan; {r.solver['step_cuts']} step cuts, after "
          f"{r.solver['passages_cut']} of the {r.solver['passages']} passages)", flush=True)
    base, amplitudes = None, {}
    for div in (1, 2, 4) if quick else (1, 2, 4, 8, 16):
        step = 5e-5 / div
        r = vibration(CWRU_6205_BEARING, rpm=1797, radial_force=300.0, time=0.3, surface=NOTCH,
                      settings=SolverSettings(step=step))
        f, a = r.envelope_peaks[0]
        change = "" if base is None else f"; change {100 * (a - base) / base:+.2f} % of the amplitude"
        print(f"2. step {step * 1e6:.1f} us: envelope line {f:.3f} Hz, {a:.5g} m/s^2, run {r.wall_time_s:.1f} s, "
              f"{r.solver['extra_steps']} steps beyond the plan, {r.solver['step_cuts']} cuts{change}", flush=True)
        base = amplitudes[step] = a
    finest = min(amplitudes)
    for step, a in amplitudes.items():  # the half-step change against the error to the finest step
        if step != finest:
            print(f"2. step {step * 1e6:.1f} us: amplitude {100 * (a - amplitudes[finest]) / amplitudes[finest]:+.2f} % "
                  f"against {finest * 1e6:.3g} us", flush=True)
    walls = {}
    for name, surface in (("clean", None), ("waviness", SurfaceModel(waviness=Waviness(
            outer=((15, 0.1e-6, 0.0), (16, 0.1e-6, 0.0), (17, 0.1e-6, 0.0)))))):
        r = vibration(REFERENCE_BEARING, rpm=1800, axial_force=1300.0, time=0.1, surface=surface or SurfaceModel())  # (perfect: bit for bit)
        walls[name] = r.wall_time_s
        print(f"3. reference bearing {name}: run {r.wall_time_s:.2f} s", flush=True)
    print(f"3. waviness / clean wall time: {walls['waviness'] / walls['clean']:.2f}")
    spall = SurfaceModel((Defect("outer", 0.0, 0.5e-3, 5e-6),))
    runs = {}
    for name, step, estimate in (("passage rule", 12.5e-6, False), ("default", None, True), ("quarter", "quarter", False)):
        if step == "quarter":
            if quick:
                break
            step = 0.25 * runs["default"].solver["step_s"]
        r = runs[name] = vibration(SPINDLE_40MM_BEARING, rpm=12000, axial_force=500.0, time=0.1, surface=spall,
                                   settings=SolverSettings(step=step), error_estimate=estimate)
        f, a = r.envelope_peaks[0]
        bound = f", half-step change {r.error_estimate['envelope_amplitude_percent']:.2f} %, bound " \
                f"{r.error_estimate['envelope_amplitude_bound_percent']:.2f} %" if estimate else ""
        print(f"4. spindle spall, {name} step {r.solver['step_s'] * 1e6:.3g} us (strike number "
              f"{r.solver['strike_number']:.2f}): line {f:.2f} Hz, {a:.5g} m/s^2{bound}; run {r.wall_time_s:.1f} s", flush=True)
    if "quarter" in runs:
        ref = runs["quarter"].envelope_peaks[0][1]
        for name in ("passage rule", "default"):
            print(f"4. {name}: amplitude {100 * (runs[name].envelope_peaks[0][1] - ref) / ref:+.1f} % against the "
                  f"quarter step", flush=True)

    small = replace(CWRU_6205_BEARING, balls=12, pitch_diameter=54e-3)
    deep = SurfaceModel((Defect("outer", 0.0, 0.8e-3, 0.3e-3),))
    t0 = time.perf_counter()
    r = vibration(small, rpm=600, radial_force=500.0, time=length, surface=deep)
    whole = time.perf_counter() - t0
    sv = r.solver
    print(f"5. 12-ball notch, {length:g} s: run {r.wall_time_s:.1f} s, whole call {whole:.1f} s; step "
          f"{sv['step_s'] * 1e6:.3g} us near passages ({100 * sv['passage_time_share']:.1f} % of the time), "
          f"{sv['coarse_step_s'] * 1e6:.3g} us elsewhere; {sv['steps']} steps, {sv['step_cuts']} cuts after "
          f"{sv['passages_cut']} of {sv['passages']} passages; line {r.envelope_peaks[0][0]:.2f} Hz "
          f"({r.envelope_peaks[0][1]:.4g} m/s^2)", flush=True)
    u = vibration(small, rpm=600, radial_force=500.0, time=0.1 * length + 0.02, surface=deep,
                  settings=SolverSettings(step=sv["step_s"]))
    print(f"5. the strike step throughout, {0.1 * length + 0.02:g} s: run {u.wall_time_s:.1f} s; per simulated "
          f"second {u.wall_time_s / (0.1 * length + 0.02) / (r.wall_time_s / length):.2f} x the windowed run's; "
          f"line {u.envelope_peaks[0][0]:.2f} Hz ({u.envelope_peaks[0][1]:.4g} m/s^2)", flush=True)


if __name__ == "__main__":
    main("--quick" in sys.argv)
