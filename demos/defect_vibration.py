"""Race faults and the vibration a condition-monitoring engineer reads (MODEL.md §13).

1. The Case Western Reserve 6205 at 1797 rpm under 300 N radial on a housing (3 kHz): an
   outer-race notch (0.18 mm long, 0.28 mm deep, their EDM fault), an inner-race spall
   (1 mm, 20 um) and a pit on a ball (their 0.18-mm ball fault): housing acceleration, spectrum and envelope spectrum with the nominal,
   kinematic and actual fault frequencies; figure and table under docs/.
2. A plain Exudyn scene solved by ``mbs.SolveDynamic``: the gearbox high-speed shaft of
   demos/hss_shaft.py whose bearing 0 has an outer-race spall and sits on a ``races.Housing``;
   the housing's envelope spectrum against that bearing's actual BPFO, at the step the spall
   asks for (``handle.RecommendedSurfaceStep``).

    python demos/defect_vibration.py [--time 0.5] [--scene-time 0.1] [--out docs]
"""
import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING, races
from exudyn_bearing.studies.signals import envelope_spectrum, sampled_signal, spectral_peaks
from exudyn_bearing.studies.vibration import actual_fault_frequencies, vibration
from exudyn_bearing.studies.vibration_plot import plot_vibration

FAULTS = {"outer-race notch": SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),)),
          "inner-race spall": SurfaceModel((Defect("inner", 0.0, 1.0e-3, 20e-6),)),
          "ball pit": SurfaceModel((Defect("ball", 0.0, 0.18e-3, 0.28e-3, ball=0),))}
#: the gearbox shaft's speed in the scene, rpm
RPM = 1800.0
#: the line each fault is read at: (fault frequency, factor)
LINES = {"outer-race notch": ("BPFO", 1), "inner-race spall": ("BPFI", 1), "ball pit": ("BSF", 2)}


def cwru(run_time, out):
    rows = []
    for name, surface in FAULTS.items():
        r = vibration(CWRU_6205_BEARING, rpm=1797, radial_force=300.0, time=run_time, surface=surface)
        png = out / f"defect_vibration_{name.split('-')[0].split()[0]}.png"
        plot_vibration(r, png, title=f"CWRU 6205, {name}, 300 N radial, 1797 rpm")
        key, factor = LINES[name]
        f = {kind: {k: factor * v for k, v in lines.items()} for kind, lines in r.fault_frequencies.items()}
        key = key if factor == 1 else f"{factor} {key}"
        peaks = ", ".join(f"{p:.2f}" for p, _ in r.envelope_peaks[:4])
        rows.append(f"| {name} | {key} | {f['nominal'][LINES[name][0]]:.3f} | {f['kinematic'][LINES[name][0]]:.3f} "
                    f"| {f['actual'][LINES[name][0]]:.3f} "
                    f"| {r.envelope_peaks[0][0]:.2f} | {peaks} | {r.kinematic_cage_slip_percent:.3f} "
                    f"| {r.band[0]:.0f}–{r.band[1]:.0f} ({r.band_from}) "
                    f"| {r.wall_time_s:.1f} | {r.solver['step_s'] * 1e6:.3g} µs, {r.solver['extra_steps']} |")
        k = LINES[name][0]
        print(f"{name}: {key} nominal {f['nominal'][k]:.3f} Hz, kinematic {f['kinematic'][k]:.3f}, actual "
              f"{f['actual'][k]:.3f}; envelope peaks (Hz) {peaks}; shaft {1797 / 60:.3f} Hz, "
              f"FTF {r.fault_frequencies['actual']['FTF']:.3f} Hz; "
              f"{len(r.defect_events)} passages; run {r.wall_time_s:.1f} s -> {png}", flush=True)
    table = ("| fault | line | nominal Hz | kinematic Hz | actual Hz | strongest envelope line Hz | "
             "envelope peaks Hz | kinematic cage slip % | envelope band Hz | run s | step, steps beyond the plan |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|\n"
             + "\n".join(rows) + "\n")
    return table


def scene(run_time):
    """The hss_shaft scene, bearing 0 with a spall on a housing, solved by mbs.SolveDynamic."""
    import exudyn as exu

    sys.path.insert(0, str(Path(__file__).parent))
    from hss_shaft import build

    surface = SurfaceModel((Defect("outer", 0.0, 2e-3, 10e-6),))
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    _body, handles, _loads = build(mbs, rpm=RPM, outer_races=[races.Housing(), None], surfaces=[surface, None])
    sensors = handles[0].AddVibrationSensors(mbs, outputs=("Acceleration",))
    mbs.Assemble()
    fs = 10000.0
    # the step the bearing and its spall ask for (the balls strike the spall's exit edge hard:
    # MODEL.md §13c), a whole number per sample
    step = min(handles[0].RecommendedStep(), handles[0].RecommendedSurfaceStep(RPM), 1.0 / fs)
    per_sample = math.ceil(1.0 / (fs * step) - 1e-9)
    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = run_time
    settings.timeIntegration.numberOfSteps = int(round(run_time * fs)) * per_sample
    settings.timeIntegration.generalizedAlpha.spectralRadius = 0.5
    settings.timeIntegration.newton.relativeTolerance = 1e-4
    settings.timeIntegration.newton.absoluteTolerance = handles[0].RecommendedAbsoluteTolerance()
    settings.solution.sensors.writePeriod = run_time / settings.timeIntegration.numberOfSteps  # every step
    settings.solution.file.write = False
    settings.timeIntegration.verboseMode = 0
    start = time.perf_counter()
    mbs.SolveDynamic(settings)
    wall = time.perf_counter() - start
    data = np.asarray(mbs.GetSensorStoredData(sensors["Acceleration"]))
    t, radial = sampled_signal(data[:, 0], data[:, 1], fs)  # global x: the gear's radial direction
    keep = t >= 0.01  # the housing starts unloaded (no applied force on the bearing): its first ring-down
    f, a = envelope_spectrum(radial[keep], fs, (1800.0, 4000.0))  # below the 4-kHz anti-aliasing corner
    peaks = spectral_peaks(f, a, 4, min_hz=20.0, max_hz=1500.0)
    res = handles[0].Results(mbs)
    bpfo = actual_fault_frequencies(res)["BPFO"]
    step = 1.0 / (fs * per_sample)
    print(f"scene (mbs.SolveDynamic, {run_time:g} s at {step * 1e6:.3g} us in {wall:.0f} s): bearing 0's actual "
          f"BPFO {bpfo:.2f} Hz, kinematic cage slip {np.mean(res.kinematic_cage_slip_percent):.3f} %; housing "
          f"envelope peaks (Hz, m/s^2) " + ", ".join(f"{p:.1f} ({a:.3g})" for p, a in peaks), flush=True)
    return bpfo, peaks, wall, step


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.5, help="simulated time of each 6205 run, s")
    parser.add_argument("--scene-time", type=float, default=0.1, help="simulated time of the shaft scene, s")
    parser.add_argument("--out", default="docs", help="folder of the figures and table")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    table = cwru(args.time, out)
    bpfo, peaks, wall, step = scene(args.scene_time)
    text = (f"# Race faults: the 6205 of the CWRU data (demos/defect_vibration.py)\n\n"
            f"300 N radial, 1797 rpm ({1797 / 60:.3f} Hz shaft), housing 2 kg at 3 kHz, 5 % damping, 20 kHz "
            f"output, {args.time:g} s per run (first 0.02 s left out). Envelope band from the signal "
            f"(the fast kurtogram's band of the largest spectral kurtosis, MODEL.md eq. 13.9). Amplitudes "
            f"uncalibrated (MODEL.md §13c).\n\n{table}\n"
            f"Gearbox shaft scene (`mbs.SolveDynamic`, {args.scene_time:g} s, {wall:.0f} s): bearing 0 with a "
            f"2-mm, 10-um outer-race spall on a housing; its actual BPFO {bpfo:.2f} Hz; the housing's envelope "
            f"peaks (10 kHz) {', '.join(f'{p:.1f} Hz ({a:.3g} m/s^2)' for p, a in peaks)}. The step, "
            f"{step * 1e6:.3g} us, is the one the spall asks for (`handle.RecommendedSurfaceStep`: its balls "
            f"strike the exit edge hard, MODEL.md §13c).\n")
    (out / "defect_vibration.md").write_text(text, encoding="utf-8")
    print(f"wrote {out / 'defect_vibration.md'}; total {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
