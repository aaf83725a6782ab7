"""Does the vibration run's step rule (MODEL.md §13c) hold beyond the cases it was set on?

    python benchmarks/strike_rule.py [--quick] [case ...]

For each case (a bearing, a defect, a speed and load; none of them among the cases the rule's
constants were measured on) it prints the bounce number B, how deep a ball sinks into the
defect as a share of its approach (the opening criterion), and the strongest envelope line's amplitude at the rule's step h (what
``vibration()`` picks), at h/2 (its error estimate), at h/4 and, where the rule picked a shorter
step than the passage rule alone would, at that passage step too. From h, h/2, h/4 it
estimates the order p and the Richardson limit and says whether the error estimate's bound
(twice the half-step change) covers the run's error against that limit. --quick: the first
three cases only. Convergence, not timing: run it while other work shares the cores.
"""
from __future__ import annotations

import math
import sys

from contact.surface import Defect, SurfaceModel
from exudyn_bearing import CWRU_6205_BEARING, REFERENCE_BEARING
from exudyn_bearing.model import steprule
from exudyn_bearing.presets import SPINDLE_40MM_BEARING
from exudyn_bearing.simulation.runner import SolverSettings
from exudyn_bearing.studies.vibration import vibration

S, R, C = SPINDLE_40MM_BEARING, REFERENCE_BEARING, CWRU_6205_BEARING
#: amplitude changes below this, %, are at the Newton tolerance's resolution
RESOLUTION = 0.1


def _outer(length, depth):
    return SurfaceModel((Defect("outer", 0.0, length, depth),))


#: name: (bearing, surface, rpm, loads N, simulated s, settle s)
CASES = {
    "spindle outer 0.5 mm x 1 um, 1500 rpm": (S, _outer(0.5e-3, 1e-6), 1500, dict(axial_force=500.0), 0.12, 0.02),
    "spindle outer 0.5 mm x 1 um, 3000 rpm": (S, _outer(0.5e-3, 1e-6), 3000, dict(axial_force=500.0), 0.07, 0.01),
    "spindle outer 0.5 mm x 2 um, 12000 rpm": (S, _outer(0.5e-3, 2e-6), 12000, dict(axial_force=500.0), 0.04, 0.01),
    "spindle inner 0.5 mm x 5 um, 12000 rpm": (S, SurfaceModel((Defect("inner", 0.0, 0.5e-3, 5e-6),)), 12000,
                                               dict(axial_force=500.0), 0.04, 0.01),
    "spindle outer 0.5 mm x 5 um, 6000 rpm, +300 N radial": (S, _outer(0.5e-3, 5e-6), 6000,
                                                             dict(axial_force=500.0, radial_force=300.0), 0.06, 0.01),
    "spindle ball pit 0.3 mm x 5 um, 6000 rpm": (S, SurfaceModel((Defect("ball", 0.0, 0.3e-3, 5e-6, ball=0),)), 6000,
                                                 dict(axial_force=500.0), 0.06, 0.01),
    "reference inner 1 mm x 5 um, 1800 rpm": (R, SurfaceModel((Defect("inner", 0.0, 1e-3, 5e-6),)), 1800,
                                              dict(axial_force=1300.0), 0.15, 0.02),
    "CWRU 6205 outer 1 mm x 2 um, 1797 rpm": (C, _outer(1e-3, 2e-6), 1797, dict(radial_force=300.0), 0.12, 0.02),
    "CWRU 6205 outer 1 mm x 2 um, 2700 rpm": (C, _outer(1e-3, 2e-6), 2700, dict(radial_force=300.0), 0.1, 0.02),
    "CWRU 6205 outer 1 mm x 2 um, 3600 rpm": (C, _outer(1e-3, 2e-6), 3600, dict(radial_force=300.0), 0.1, 0.02),
    "CWRU 6205 outer 1 mm x 1 um, 3600 rpm": (C, _outer(1e-3, 1e-6), 3600, dict(radial_force=300.0), 0.1, 0.02),
    "CWRU 6205 outer 1 mm x 4 um, 1797 rpm": (C, _outer(1e-3, 4e-6), 1797, dict(radial_force=300.0), 0.12, 0.02),
}


def _line(result, near=None):
    """(frequency Hz, amplitude m/s²) of the strongest envelope line, or of the strongest of the
    ten listed lines within 2 Hz of ``near``."""
    if near is not None:
        lines = [p for p in result.envelope_peaks if abs(p[0] - near) < 2.0]
        if lines:
            return lines[0]
    return result.envelope_peaks[0]


def run_case(name):
    bearing, surface, rpm, loads, length, settle = CASES[name]
    common = dict(rpm=rpm, time=length, settle=settle, surface=surface, **loads)
    rule = vibration(bearing, **common, settings=SolverSettings(progress=False))
    h = rule.solver["step_s"]
    half, quarter = (vibration(bearing, **common, settings=SolverSettings(step=k * h, progress=False))
                     for k in (0.5, 0.25))
    f_ref, _ = _line(quarter)
    a = [_line(r, f_ref)[1] for r in (rule, half, quarter)]
    # the error estimate of vibration(error_estimate=True): the half-step change and twice it
    change = 100 * abs(a[0] - a[1]) / a[1]
    bound = 2 * change
    d1, d2 = a[0] - a[1], a[1] - a[2]
    p = math.log2(d1 / d2) if d1 * d2 > 0 else math.nan
    if p >= 1.0:  # the bound's premise holds over h ... h/4: extrapolate
        limit = a[2] - d2 / (2 ** p - 1)
        how = f"order {p:.2f}, Richardson limit {limit:.5g}"
    else:
        limit, how = a[2], f"{'order %.2f' % p if p == p else 'not monotone'}: against h/4"
    error = 100 * abs(a[0] - limit) / limit
    # changes below RESOLUTION are the Newton tolerance's, not the step's
    if max(abs(d1), abs(d2)) < 1e-2 * RESOLUTION * a[2]:
        how += f" (changes below {RESOLUTION} %: the solver's resolution)"
    print(f"{name}: B {rule.solver['strike_number']:.3f}, reach/approach {rule.solver['reach_share']:.2f}, "
          f"step {h * 1e6:.3g} us ({rule.solver['step_cuts']} cuts, "
          f"after {rule.solver['passages_cut']} of {rule.solver['passages']} passages); line {f_ref:.1f} Hz: "
          f"{a[0]:.5g} / {a[1]:.5g} / {a[2]:.5g} m/s^2 at h, h/2, h/4; {how}; half-step change {change:.2f} %, "
          f"bound {bound:.2f} %, error {error:.2f} % -> {_verdict(error, bound)}", flush=True)
    out = dict(name=name, B=rule.solver["strike_number"], share=rule.solver["reach_share"], step=h, amplitudes=a, limit=limit, order=p,
               change=change, bound=bound, error=error)
    # the step vibration() takes without the strike rule (it rounds it to whole steps per sample)
    passage = min(steprule.passage_step(bearing, surface, rpm), 1.0 / rule.sample_rate,
                  _plain_step(bearing, surface, rpm, loads))
    if passage > 1.5 * h:  # what the passage rule alone would have read
        coarse = vibration(bearing, **common, settings=SolverSettings(step=passage, progress=False))
        a_p = _line(coarse, f_ref)[1]
        out["passage"] = (coarse.solver["step_s"], 100 * (a_p - limit) / limit)
        print(f"{name}: without the strike step ({coarse.solver['step_s'] * 1e6:.3g} us, "
              f"{coarse.solver['step_cuts']} cuts): {a_p:.5g} m/s^2, {out['passage'][1]:+.2f} % against the limit",
              flush=True)
    return out


def _verdict(error, bound):
    if error <= bound:
        return "covered"
    return "within the resolution" if error < RESOLUTION else "NOT covered"


def _plain_step(bearing, surface, rpm, loads):
    """The bearing's own ``RecommendedStep()`` at these loads (the step without any surface rule), s."""
    return _handle(bearing, surface, rpm, loads).RecommendedStep()


def _handle(bearing, surface, rpm, loads):
    """The bearing as vibration() builds it (its start's quasi-static loads)."""
    import exudyn as exu

    from exudyn_bearing.model.builder import CreateAngularContactBearing
    from exudyn_bearing.races import Driven, Housing

    mbs = exu.SystemContainer().AddSystem()
    return CreateAngularContactBearing(mbs, bearing, innerRace=Driven(rpm), outerRace=Housing(), surface=surface,
                                       axialForce=loads.get("axial_force", 0.0),
                                       radialForce=loads.get("radial_force", 0.0), show=False)


def main(names):
    rows = [run_case(n) for n in names]
    print("\ncase | B | reach / approach | step us | change % | bound % | error % | covered | passage-rule step: error %")
    for r in rows:
        passage = f"{r['passage'][0] * 1e6:.3g} us: {r['passage'][1]:+.1f}" if "passage" in r else "-"
        print(f"{r['name']} | {r['B']:.3f} | {r['share']:.2f} | {r['step'] * 1e6:.3g} | {r['change']:.2f} | {r['bound']:.2f} | "
              f"{r['error']:.2f} | {_verdict(r['error'], r['bound'])} | {passage}")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--quick"]
    chosen = [n for n in CASES if any(a in n for a in args)] if args else list(CASES)
    main(chosen[:3] if "--quick" in sys.argv else chosen)
