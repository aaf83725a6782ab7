"""Cost and accuracy of contact.traction.crook_traction on the dynamic model's states.

One call = 32 contacts (16 inner + 16 outer) of the reference bearing at 1800 rpm in
typical dynamic states (MODEL.md §10: "every claim of accuracy must come with its cost"):

* inner: Q 15–900 N (p_max ≈ 0.3–1.1 GPa), contact angle 38–55°, ω_s −350…−200 rad/s;
* outer: Q 40–920 N, ω_s +30…+120 rad/s;
* rolling slip |u_x| log-uniform in 1e-5…0.5 m/s (mostly small: spin pole near the centre),
  transverse |u_y| ≤ 0.01 m/s, film h from Hamrock–Dowson at 6 m/s entrainment.

Error of a contact = (|Δf| + |ΔM_z|/√(ab)) / (|f| + |M_z|/√(ab)) against the accurate rule at
order 32 (worst and 99th percentile over the contacts of ``--calls`` random calls); "jac
err" = worst Jacobian error relative to its largest entry in force units.  Time = median of
``time.perf_counter`` over ``--reps`` calls of 32 contacts, without and with the Jacobian;
the machine may be shared, so compare the rows of one run (last column: time relative to
the accurate rule at order 4).  ``nodes`` = nodes per contact (at most, for the accurate
rule, which uses fewer for light or nearly isothermal contacts).

    python benchmarks/traction_speed.py [--calls 40] [--reps 300] [--orders 12,14,16,20,24]
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from contact.film import central_film_thickness
from contact.lubricant import REFERENCE_LUBRICANT as LUB
from contact.traction import crook_traction, fast_rule_size, rule_size
from exudyn_bearing import REFERENCE_BEARING as BEARING


def typical_states(seed, n_inner=16, n_outer=16):
    """(u_x, u_y, ω_s, a, b, p_max, h) arrays of one dynamic-model call (see module doc)."""
    rng = np.random.default_rng(seed)
    parts = []
    for race, n, q_lo, q_hi, w_lo, w_hi in (("inner", n_inner, 15.0, 900.0, -350.0, -200.0),
                                            ("outer", n_outer, 40.0, 920.0, 30.0, 120.0)):
        angle = np.radians(rng.uniform(38.0, 55.0, n))
        load = np.exp(rng.uniform(np.log(q_lo), np.log(q_hi), n))
        con = BEARING.hertz(angle, race)
        a, b = con.semi_axes(load)
        p_max = con.max_pressure(load)
        r_x, _ = BEARING.curvature_radii(angle, race)
        h = central_film_thickness(6.0, load, r_x, con.ellipticity, BEARING.effective_modulus, LUB)
        ux = rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(-5.0, np.log10(0.5), n)
        uy = rng.choice([-1.0, 1.0], n) * rng.uniform(0.0, 0.01, n)
        w = rng.uniform(w_lo, w_hi, n)
        parts.append((ux, uy, w, a, b, p_max, h))
    return tuple(np.concatenate(z) for z in zip(*parts))


def rel_errors(t, ref, a, b):
    """Per-contact error relative to the force scale |f| + |M_z|/√(ab)."""
    sab = np.sqrt(a * b)
    scale = np.hypot(ref.fx, ref.fy) + np.abs(ref.mz) / sab
    return (np.hypot(t.fx - ref.fx, t.fy - ref.fy) + np.abs(t.mz - ref.mz) / sab) / scale


def median_time(call, reps):
    for _ in range(5):
        call()
    ts = np.empty(reps)
    for i in range(reps):
        t0 = time.perf_counter()
        call()
        ts[i] = time.perf_counter() - t0
    return 1e3 * float(np.median(ts))


def jac_errors(jac, ref, a, b):
    """Per-contact Jacobian error relative to its largest entry, in force units
    ((u_x, u_y, √(ab) ω_s) → (f_x, f_y, M_z/√(ab)))."""
    one = np.ones_like(a)
    sc = np.stack([one, one, np.sqrt(a * b)], -1)
    jn, rn = (m / sc[:, :, None] * sc[:, None, :] for m in (jac, ref))
    return np.abs(jn - rn).max((1, 2)) / np.abs(rn).max((1, 2))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--calls", type=int, default=40, help="random calls for the error columns")
    ap.add_argument("--reps", type=int, default=300, help="timed calls per row")
    ap.add_argument("--orders", default="12,14,16,20,24", help="fast-rule orders")
    ap.add_argument("--accurate-orders", default="4,8,16", help="accurate-rule orders")
    args = ap.parse_args(argv)

    calls = [typical_states(s) for s in range(args.calls)]
    allx = tuple(np.concatenate(z) for z in zip(*calls))
    a, b = allx[3], allx[4]
    ref = crook_traction(*allx, LUB, order=32, derivatives=True)
    timed = calls[0]

    rows = []
    for fast, orders in ((False, args.accurate_orders), (True, args.orders)):
        for order in (int(v) for v in orders.split(",") if v):
            t = crook_traction(*allx, LUB, order=order, fast=fast, derivatives=True)
            err = rel_errors(t, ref, a, b)
            jerr = jac_errors(t.jacobian, ref.jacobian, a, b)
            if fast:
                nr, nm, no = fast_rule_size(order)
                nodes = 8 * nr * (nm + no)
            else:
                nodes = rule_size(order)
            ms = median_time(lambda: crook_traction(*timed, LUB, order=order, fast=fast), args.reps)
            msd = median_time(lambda: crook_traction(*timed, LUB, order=order, fast=fast,
                                                     derivatives=True), args.reps)
            rows.append(("fast" if fast else "accurate", order, nodes, err.max(),
                         np.percentile(err, 99), jerr.max(), ms, msd))
    base = [r[6] for r in rows if r[0] == "accurate" and r[1] == 4]
    n_con = allx[0].size
    print(f"crook_traction, {timed[0].size} contacts per call; errors over {n_con} contacts "
          f"against the accurate rule at order 32")
    print(f"{'rule':>9} {'order':>5} {'nodes':>6} {'worst err':>9} {'99% err':>8} "
          f"{'jac err':>8} {'ms/call':>8} {'ms w/ jac':>9}" + ("  (time / accurate 4)" if base else ""))
    for rule, order, nodes, e_max, e99, je, ms, msd in rows:
        rel = f"  ({ms / base[0]:.2f}, {msd / base[0]:.2f})" if base else ""
        print(f"{rule:>9} {order:5d} {nodes:6d} {e_max:9.1e} {e99:8.1e} {je:8.1e} {ms:8.3f} "
              f"{msd:9.3f}{rel}")


if __name__ == "__main__":
    main()
