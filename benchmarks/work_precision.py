"""Work-precision study: error against wall time for every solver the package supports
(MODEL.md §10, issue 4).

Cases (reference bearing, inner race 1800 rpm, outer race fixed, started from the
quasi-static state, ``--time`` simulated):
  (a) pure axial 1.3 kN;  (b) F_a 2.2 kN + F_r 2 kN.
Errors, against a converged reference run, of: cage slip (P19) and kinematic cage slip in
percentage points (means over the last third), mean ball spin speed (rad/s, last third)
and peak contact load (N, last third). The reference is the finest setting of the
reference solver; the next finest is run too and their difference is printed as the
reference's own error (it must sit well below the smallest error in the table).
A Jacobian comparison (the connector's batched block finite differences vs Exudyn's
numerical differentiation) is included for generalized-alpha at the default step.

    python benchmarks/work_precision.py [--case a|b|both] [--time 0.01] [--out out/work_precision]

Writes work_precision.md, work_precision.json and work_precision.png to ``--out``.
"""
from __future__ import annotations

import argparse
import json
import time as _time
from pathlib import Path

import numpy as np

from contact.ballrace import ContactLaw
from exudyn_bearing.errors import BearingSimulationError
from exudyn_bearing.simulation.runner import SolverSettings, simulate

CASES = {"a": dict(axial_force=1300.0, radial_force=0.0), "b": dict(axial_force=2200.0, radial_force=2000.0)}
QUANTITIES = ("cage_slip_pp", "kinematic_cage_slip_pp", "ball_spin_rad_s", "peak_load_n")


def measures(summary) -> dict:
    res = summary.results
    last = res.last()
    spin = np.linalg.norm(res.ball_omega_orbiting[last], axis=-1).mean()
    peak = max(res.inner["load"][last].max(), res.outer["load"][last].max())
    return {"cage_slip_pp": summary.cage_slip_percent, "kinematic_cage_slip_pp": summary.kinematic_cage_slip_percent,
            "ball_spin_rad_s": float(spin), "peak_load_n": float(peak)}


def settings_grid(case: str):
    """(label, SolverSettings[, ContactLaw]) for every solver family over a range of
    steps/tolerances, and the numpy contact path against the compiled one. Every setting
    is spelled out (not taken from the defaults), so the table says what was run."""
    ga = dict(solver="generalized-alpha", spectral_radius=0.5)
    grid = [("GA rho=0.5", SolverSettings(**ga, step=h, relative_tolerance=1e-4, output_step=max(h, 1e-4)))
            for h in (2e-4, 1e-4, 5e-5, 2.5e-5)]
    grid += [("GA rho=0.5, Newton tolerance", SolverSettings(**ga, step=1e-4, relative_tolerance=tol))
             for tol in (1e-3, 1e-5, 1e-6)]
    for rho in (0.8, 0.0):
        grid += [(f"GA rho={rho:g}", SolverSettings("generalized-alpha", step=h, spectral_radius=rho,
                                                    relative_tolerance=1e-4)) for h in (1e-4, 5e-5, 2.5e-5)]
    grid += [("trapezoidal", SolverSettings("trapezoidal", step=h, relative_tolerance=1e-4))
             for h in (1e-4, 5e-5, 2.5e-5)]
    grid += [("GA rho=0.5, numpy contacts", SolverSettings(**ga, step=1e-4, relative_tolerance=1e-4),
              ContactLaw(compiled=False))]
    grid += [("GA rho=0.5, Exudyn Jacobian", SolverSettings(**ga, step=1e-4, relative_tolerance=1e-4,
                                                            jacobian="exudyn"))]
    if case == "a":  # explicit solvers cannot follow case (b)'s 1e7-1e8 1/s traction modes
        grid += [("RK44 (Lie group)", SolverSettings("rk44", step=h)) for h in (4e-5, 2e-5, 1e-5)]
        grid += [("DOPRI5 (Lie group)", SolverSettings("dopri5", step=1e-5, relative_tolerance=tol,
                                                      absolute_tolerance=tol)) for tol in (1e-4, 1e-5, 1e-6)]
    return grid


def reference_settings(case: str):
    """Two finest settings of the reference solver (the second is the reference)."""
    if case == "a":
        return [SolverSettings("rk44", step=h) for h in (5e-6, 2.5e-6)]
    # 1.25e-5 / 6.25e-6 s disagreed by 2.5e-2 pp; 6.25e-6 / 3.125e-6 s agree to 1.4e-3 pp. A
    # tighter Newton tolerance (1e-8) fails at both steps (Newton does not get there by t = 0.16 ms)
    return [SolverSettings("generalized-alpha", step=h, spectral_radius=0.8, relative_tolerance=1e-6)
            for h in (6.25e-6, 3.125e-6)]


def run_case(case: str, sim_time: float, log) -> dict:
    kw = CASES[case]
    out = {"case": case, **kw, "rpm": 1800.0, "time": sim_time, "runs": []}
    refs = []
    for s in reference_settings(case):
        t0 = _time.perf_counter()
        summary = simulate(time=sim_time, settings=s, **kw)
        refs.append((s, measures(summary), _time.perf_counter() - t0))
        log(f"  reference {s.solver} step {s.step:g}: {refs[-1][1]} ({refs[-1][2]:.1f} s)")
    ref = refs[-1][1]
    out["reference"] = {"solver": refs[-1][0].solver, "step": refs[-1][0].step, "values": ref,
                        "self_error": {k: abs(refs[0][1][k] - ref[k]) for k in QUANTITIES}}
    for label, s, *law in settings_grid(case):
        t0 = _time.perf_counter()
        row = {"label": label, "solver": s.solver, "step": s.step, "spectral_radius": s.spectral_radius,
               "relative_tolerance": s.relative_tolerance, "jacobian": s.jacobian}
        try:
            summary = simulate(time=sim_time, settings=s, contact_law=law[0] if law else ContactLaw(), **kw)
            m = measures(summary)
            row.update(wall_time_s=summary.wall_time_s, steps=summary.steps, newton_iterations=summary.newton_iterations,
                       jacobian_updates=summary.jacobian_updates, values=m,
                       errors={k: abs(m[k] - ref[k]) for k in QUANTITIES})
        except BearingSimulationError as err:
            row.update(wall_time_s=_time.perf_counter() - t0, failed=str(err)[:200])
        out["runs"].append(row)
        log(f"  {label:28s} step {s.step:8.3g} tol {s.relative_tolerance:7.1g}: "
            + (f"wall {row['wall_time_s']:6.1f} s, kin. slip error {row['errors']['kinematic_cage_slip_pp']:.2e} pp"
               if "errors" in row else f"FAILED {row['failed'][:80]}"))
    return out


def markdown(results: list[dict]) -> str:
    lines = []
    for r in results:
        lines += [f"### Case ({r['case']}): F_a {r['axial_force']:g} N, F_r {r['radial_force']:g} N, 1800 rpm, "
                  f"{r['time']:g} s simulated", "",
                  f"Reference: {r['reference']['solver']} step {r['reference']['step']:g} s; its own error "
                  f"(vs the next coarser reference run): "
                  + ", ".join(f"{k} {v:.1e}" for k, v in r["reference"]["self_error"].items()), "",
                  "| solver | step (s) | rel. tol | wall (s) | wall per 0.1 s (s) | Newton its | Jacobians | "
                  "cage slip err (pp) | kin. slip err (pp) | ball spin err (rad/s) | peak load err (N) |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for row in r["runs"]:
            if "errors" not in row:
                lines.append(f"| {row['label']} | {row['step']:g} | {row['relative_tolerance']:g} | "
                             f"{row['wall_time_s']:.1f} | | | | failed | | | |")
                continue
            e = row["errors"]
            lines.append(f"| {row['label']} | {row['step']:g} | {row['relative_tolerance']:g} | {row['wall_time_s']:.1f} | "
                         f"{row['wall_time_s'] / r['time'] * 0.1:.1f} | {row['newton_iterations'] or ''} | "
                         f"{row['jacobian_updates'] or ''} | {e['cage_slip_pp']:.1e} | {e['kinematic_cage_slip_pp']:.1e} | "
                         f"{e['ball_spin_rad_s']:.1e} | {e['peak_load_n']:.1e} |")
        lines.append("")
    return "\n".join(lines)


def plot(results: list[dict], path: Path) -> None:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed (pip install -e .[plot]): no plot")
        return
    fig, axes = plt.subplots(1, len(results), figsize=(6.5 * len(results), 4.8), squeeze=False)
    for ax, r in zip(axes[0], results):
        families = {}
        for row in r["runs"]:
            if "errors" in row:
                families.setdefault(row["label"], []).append(
                    (row["wall_time_s"] / r["time"] * 0.1, max(row["errors"]["kinematic_cage_slip_pp"], 1e-8)))
        for label, pts in families.items():
            pts.sort()
            ax.loglog(*zip(*pts), "o-", label=label)
        ax.axhline(0.1, color="k", ls=":", lw=1)
        ax.set(xlabel="wall time per 0.1 s simulated (s)", ylabel="kinematic cage slip error (pp)",
               title=f"case ({r['case']}): F_a {r['axial_force']:g} N, F_r {r['radial_force']:g} N")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=("a", "b", "both"), default="both")
    parser.add_argument("--time", type=float, default=0.01, help="simulated time per run, s")
    parser.add_argument("--time-b", type=float, default=0.002, help="simulated time for case (b), s")
    parser.add_argument("--out", default="out/work_precision")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    results = []
    for case in (("a", "b") if args.case == "both" else (args.case,)):
        print(f"case ({case}) {CASES[case]}", flush=True)
        results.append(run_case(case, args.time if case == "a" else args.time_b,
                                lambda line: print(line, flush=True)))
    (out / "work_precision.json").write_text(json.dumps(results, indent=1))
    md = markdown(results)
    (out / "work_precision.md").write_text(md)
    plot(results, out / "work_precision.png")
    print(md)
    print(f"wrote {out}/work_precision.md, .json, .png")


if __name__ == "__main__":
    main()
