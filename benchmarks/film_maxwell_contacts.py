"""The film-elasticity laws at the reference bearing's own contacts, with spin (MODEL.md §6b).

`benchmarks/film_maxwell.py` compares the pointwise laws with Johnson & Tevaarwerk's Maxwell
equation on two made-up contacts without spin. Here the contacts are the reference bearing's
(paper table 1, 1800 rpm) in its steady states near the 1 % skid threshold (1.3–2.4 kN, the
steady solver of MODEL.md §12 with the default law), both races, with their spin, and the
equation is solved over each whole contact (:func:`contact.film_elasticity.maxwell_traction`).
Compared with it, on the same streamline grid (so the differences are the laws'):

* exponential, limit after — the model's law since session 33: τ_v (1 − e^(−|τ_e|/τ_v)), then
  Λp tanh(·/Λp);
* series, limit after — the model's law before: |τ| = |τ_e||τ_v|/(|τ_e| + |τ_v|), then the limit;
* no film elasticity: the limited Crook law alone.

τ_e = G ξ/(ū h)(v_x, v_y − ω ξ/2) (G = κ p), τ_v the unlimited Crook stress, all along the
local slip. Then the 1 % threshold (kinematic cage slip, steady solver, Brent to ±2 N) with each
law, the solved Maxwell film included (registered here as traction laws of their own).

    python benchmarks/film_maxwell_contacts.py [--out docs] [--no-threshold]
"""
import argparse
import json
import time

import numpy as np
from scipy import optimize

from contact.ballrace import ContactLaw
from contact.film_elasticity import compliance_factor, crook_viscous, elastic_stress, maxwell_traction
from contact.lubricant import REFERENCE_LUBRICANT as OIL
from contact.traction import crook_traction
from contact.traction_law import Traction, limit_shear
from contact.traction_laws import TractionModel, register_traction
from exudyn_bearing import steady_state
from exudyn_bearing.presets import REFERENCE_BEARING
from exudyn_bearing.setup import BearingSetup
from exudyn_bearing.solvers.steady_balance import solve_steady

KAPPA = OIL.film_shear_modulus_coefficient
LAM = OIL.limiting_shear_coefficient
LOADS = (1300.0, 1600.0, 2000.0, 2400.0)
RPM = 1800.0
LINES, STEPS = 48, 400  # the check at 96 / 800 is printed


def pointwise(law, ux, uy, om, a, b, pm, h, ent, lines=LINES, steps=STEPS):
    """Traction (n,) of a pointwise law on the streamline grid of :func:`maxwell_traction`
    (Gauss lines in y, θ uniform along x = c sin θ; the same two step sizes and Richardson)."""
    yg, wy = np.polynomial.legendre.leggauss(lines)
    col = (lambda v: np.asarray(v, float)[:, None, None])
    ux, uy, om, a, b, pm, h, ent = (col(v) for v in (ux, uy, om, a, b, pm, h, ent))
    unlimited = crook_viscous(OIL, np.ones(1), None)
    sums = []
    for n in (steps // 2, steps):
        th = np.linspace(-0.5 * np.pi, 0.5 * np.pi, n + 1)[1:, None]
        c = b * np.sqrt(1 - yg ** 2)
        x = c * np.sin(th)
        y = a * yg + 0 * x
        p = pm * np.sqrt(1 - yg ** 2) * np.cos(th)
        w = c * np.cos(th) * (np.pi / n) * a * wy
        vx, vy = ux - om * y, uy + om * x
        speed = np.hypot(vx, vy)
        tv = unlimited(speed.reshape(speed.shape[0], -1), p.reshape(p.shape[0], -1))[0].reshape(speed.shape) / h
        if law == "none":
            mag = tv
        else:
            te = elastic_stress(x, y, a, b, vx, vy, om, ent, h, KAPPA * p)
            with np.errstate(invalid="ignore", divide="ignore"):
                if law == "series":  # the law before session 33 (no longer in the package)
                    mag = np.where(np.isfinite(te), te * tv / np.where(te + tv > 0, te + tv, 1.0), tv)
                else:  # the package's own factor (τ_v = g |v| with g = τ_v, |v| = 1)
                    mag = tv * compliance_factor(tv, 1.0, te)
        mag = limit_shear(mag, 1.0, LAM * p)[0]  # Λp tanh(|τ|/(Λp)), 0 where p = 0 (MODEL.md §6a)
        with np.errstate(invalid="ignore", divide="ignore"):
            tx = np.where(speed > 0, mag * vx / np.where(speed > 0, speed, 1.0), 0.0)
            ty = np.where(speed > 0, mag * vy / np.where(speed > 0, speed, 1.0), 0.0)
        sums.append(np.stack([(w * tx).sum((1, 2)), (w * ty).sum((1, 2)), (w * (x * ty - y * tx)).sum((1, 2)),
                              (w * (tx * vx + ty * vy)).sum((1, 2))]))
    return Traction(*(2 * sums[1] - sums[0]))


def solved(ux, uy, om, a, b, pm, h, ent, lines=LINES, steps=STEPS):
    return maxwell_traction(ux, uy, om, a, b, pm, h, ent, crook_viscous(OIL, np.asarray(h, float), LAM), KAPPA,
                            lines, steps)


def _law(kind):
    def evaluate(slip, a, b, p_max, load, h, entrainment, lubricant, law):
        if kind == "maxwell":
            return solved(*slip, a, b, p_max, h, entrainment)
        return pointwise(kind, *slip, a, b, p_max, h, entrainment)
    return evaluate


LAWS = {"exponential": "crook-limited", "none": "crook-limited, no film elasticity", "series": "bench-series",
        "maxwell": "bench-maxwell"}
register_traction(TractionModel("bench-series", "series pointwise law, limit after (benchmark)", _law("series"),
                                film=True, crook=True))
register_traction(TractionModel("bench-maxwell", "the solved Maxwell film (benchmark)", _law("maxwell"), film=True,
                                crook=True))


def contact_law(kind):
    if kind == "exponential":
        return ContactLaw()  # the package's default law
    if kind == "none":
        return ContactLaw(film_elasticity=False)
    return ContactLaw(traction=LAWS[kind])


def contacts(load):
    """The two contacts (inner, outer) of the steady state at ``load`` N, 1800 rpm."""
    setup = BearingSetup(REFERENCE_BEARING)
    state = solve_steady(setup, load, RPM, 0.0, 1e-8)
    assert state.converged, state.message
    kin, f = state.ball.contacts(state.x)
    r_x, hz = state.ball.params.hertz(kin.contact_angle, state.ball.law.hertz_method)
    a, b = hz.semi_axes(f.normal_load)
    return dict(load=load, ux=kin.slip_rolling, uy=kin.slip_transverse, om=kin.spin, a=a, b=b, pm=f.max_pressure,
                h=f.film_thickness, ent=kin.entrainment, Q=f.normal_load, fx_model=f.traction_rolling)


def slip(kind, load):
    s = steady_state(axial_force=load, rpm=RPM, contact_law=contact_law(kind))
    if not s.converged:
        raise RuntimeError(f"no steady state at {load} N: {s.message}")
    return s.kinematic_cage_slip_percent


def threshold(kind, lo=1600.0, hi=2400.0):
    return optimize.brentq(lambda f: slip(kind, f) - 1.0, lo, hi, xtol=2.0)


def write_markdown(result, path):
    """docs/film_maxwell_contacts.md from the benchmark's result."""
    names = ("exponential", "series", "none")
    lines = ["# The film-elasticity laws at the reference bearing's contacts (MODEL.md §6b)", "",
             "Made by `python benchmarks/film_maxwell_contacts.py --out docs` (reference bearing, paper table 1, "
             f"{result['rpm']:.0f} rpm, steady states of MODEL.md §12 with the default law; {result['lines']} "
             f"streamlines × {result['steps']} steps, Richardson). Johnson & Tevaarwerk's Maxwell film solved over "
             "each whole contact with its spin (`contact.film_elasticity.maxwell_traction`) against the pointwise "
             "laws on the same grid: the force error |f − f_solved|/|f_solved| and the spin moment's relative error. "
             "'grid': the solved film at twice the streamlines and steps; 'rule': the package's accurate rule "
             "(order 32) against the grid's exponential law.", "",
             "| load N | race | Q N | p_max GPa | film µm | ū m/s | u_x, u_y m/s | ω_s rad/s | solved f_x N | "
             "solved M_z N mm | grid | rule | " + " | ".join(f"{n}: force / M_z" for n in names) + " |",
             "|---" * (12 + len(names)) + "|"]
    for r in result["rows"]:
        lines.append(
            f"| {r['load_N']:.0f} | {r['race']} | {r['Q_N']:.0f} | {r['p_max_Pa'] / 1e9:.2f} | {r['film_m'] * 1e6:.2f} | "
            f"{r['entrainment_m_per_s']:.2f} | {r['slip_rolling_m_per_s']:.3g}, {r['slip_transverse_m_per_s']:.3g} | "
            f"{r['spin_rad_per_s']:.3g} | {r['solved_N'][0]:.4g} | {r['solved_moment_N_m'] * 1e3:.4g} | "
            f"{max(r['grid_check'], r['grid_check_moment']):.0e} | {r['rule_vs_grid']:.0e} | "
            + " | ".join(f"{r[f'{n}_force']:.2%} / {r[f'{n}_moment']:+.2%}" for n in names) + " |")
    if "threshold_N" in result:
        lines += ["", "1 % threshold (kinematic cage slip, steady solver, Brent to ±2 N) with each law: "
                  + ", ".join(f"{k} {v:.0f} N" for k, v in result["threshold_N"].items()) + "."]
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=None, help="folder for film_maxwell_contacts.md/.json")
    parser.add_argument("--no-threshold", action="store_true")
    args = parser.parse_args()
    rows = []
    t0 = time.perf_counter()
    for load in LOADS:
        c = contacts(load)
        args_c = [c[k] for k in ("ux", "uy", "om", "a", "b", "pm", "h", "ent")]
        ref = solved(*args_c)
        fine = solved(*args_c, lines=2 * LINES, steps=2 * STEPS)
        laws = {k: pointwise(k, *args_c) for k in ("series", "exponential", "none")}
        rule = crook_traction(*args_c[:6], c["h"], OIL, order=32, limiting_shear=LAM, film_modulus=KAPPA,
                              entrainment=c["ent"])
        for i, race in enumerate(("inner", "outer")):
            scale = float(np.hypot(ref.fx[i], ref.fy[i]))
            mscale = abs(float(ref.mz[i]))
            row = dict(load_N=load, race=race, Q_N=float(c["Q"][i]), p_max_Pa=float(c["pm"][i]),
                       film_m=float(c["h"][i]), entrainment_m_per_s=float(c["ent"][i]),
                       slip_rolling_m_per_s=float(c["ux"][i]), slip_transverse_m_per_s=float(c["uy"][i]),
                       spin_rad_per_s=float(c["om"][i]),
                       solved_N=[float(ref.fx[i]), float(ref.fy[i])], solved_moment_N_m=float(ref.mz[i]),
                       grid_check=max(abs(fine.fx[i] - ref.fx[i]), abs(fine.fy[i] - ref.fy[i])) / scale,
                       grid_check_moment=abs(fine.mz[i] - ref.mz[i]) / mscale,
                       rule_vs_grid=max(abs(rule.fx[i] - laws["exponential"].fx[i]),
                                        abs(rule.fy[i] - laws["exponential"].fy[i])) / scale)
            for k, t in laws.items():
                row[f"{k}_force"] = float(np.hypot(t.fx[i] - ref.fx[i], t.fy[i] - ref.fy[i]) / scale)
                row[f"{k}_fx"] = float(t.fx[i] / ref.fx[i] - 1)
                row[f"{k}_moment"] = float(t.mz[i] / ref.mz[i] - 1)
            rows.append(row)
            print(f"{load:6.0f} N {race}: Q {row['Q_N']:.0f} N, p {row['p_max_Pa'] / 1e9:.2f} GPa, "
                  f"u {row['slip_rolling_m_per_s']:.3g}/{row['slip_transverse_m_per_s']:.3g} m/s, "
                  f"ω {row['spin_rad_per_s']:.3g}: solved |f| {scale:.4g} N, M {ref.mz[i]:.4g} N m "
                  f"(grid {row['grid_check']:.1e}/{row['grid_check_moment']:.1e}, rule {row['rule_vs_grid']:.1e}); "
                  + ", ".join(f"{k} {row[f'{k}_force']:+.2%}/{row[f'{k}_fx']:+.2%}/{row[f'{k}_moment']:+.2%}"
                              for k in laws), flush=True)
    result = dict(rows=rows, kappa=KAPPA, lam=LAM, rpm=RPM, lines=LINES, steps=STEPS,
                  contacts_seconds=time.perf_counter() - t0)
    if not args.no_threshold:
        result["threshold_N"] = {}
        for kind in ("exponential", "series", "none", "maxwell"):
            t1 = time.perf_counter()
            result["threshold_N"][kind] = threshold(kind)
            print(f"1 % threshold, {kind}: {result['threshold_N'][kind]:.0f} N ({time.perf_counter() - t1:.0f} s)",
                  flush=True)
    if args.out:
        with open(f"{args.out}/film_maxwell_contacts.json", "w") as fh:
            json.dump(result, fh, indent=1)
        write_markdown(result, f"{args.out}/film_maxwell_contacts.md")


if __name__ == "__main__":
    main()
