"""Cost and accuracy of the smooth limiting shear (MODEL.md §6a) on the dynamic model's states.

Same states as ``benchmarks/traction_speed.py`` (32 contacts of the reference bearing per
call). Prints, for pure Crook and the limited law (Λ of the reference oil): the worst and
99th-percentile error of the accurate and fast rules against the accurate rule at order 32
of the same law, and the time per call of the compiled kernel (``contact.kernels.
_crook_many``, the fast rule of the dynamic model's traction), median over ``--reps`` calls,
both laws alternated in one run so the ratio is fair on a shared machine.

    python benchmarks/limiting_shear.py [--calls 40] [--reps 2000]
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from contact import kernels as compiled
from contact.kernels import crook
from contact.lubricant import REFERENCE_LUBRICANT as LUB
from contact.traction import crook_traction
from traction_speed import rel_errors, typical_states


def kernel_times(calls, lam, reps):
    """Median and minimum time (us) of one compiled call of 32 contacts: the kernel
    (``contact.kernels._crook_many``) with its tables prepared once, as the connector has
    them (``crook_fast`` would rebuild the tables on every call)."""
    tables = compiled.crook_tables(16)
    law = compiled.traction_record(LUB, lam)
    calls = [tuple(np.ascontiguousarray(v, dtype=float) for v in st) for st in calls]
    out = np.empty((4, calls[0][0].size))

    def run(st):
        crook._crook_many(*st, np.zeros(st[0].size), law, tables, out)

    for st in calls:
        run(st)
    ts = np.empty(reps)
    for i in range(reps):
        st = calls[i % len(calls)]
        t0 = time.perf_counter()
        run(st)
        ts[i] = time.perf_counter() - t0
    return 1e6 * float(np.median(ts)), 1e6 * float(ts.min())


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--calls", type=int, default=40, help="random calls for the error columns")
    ap.add_argument("--reps", type=int, default=2000, help="timed kernel calls per law and round")
    args = ap.parse_args(argv)
    calls = [typical_states(s) for s in range(args.calls)]
    allx = tuple(np.concatenate(z) for z in zip(*calls))
    a, b = allx[3], allx[4]
    lam = LUB.limiting_shear_coefficient
    print(f"errors over {allx[0].size} contacts against the accurate rule at order 32 of the same law")
    print(f"{'law':>16} {'rule':>9} {'order':>5} {'worst':>8} {'99%':>8}")
    for name, lam_s in (("pure Crook", None), (f"limited {lam:g}", lam)):
        ref = crook_traction(*allx, LUB, order=32, limiting_shear=lam_s)
        for fast, order in ((False, 16), (False, 24), (True, 16), (True, 20), (True, 24)):
            t = crook_traction(*allx, LUB, order=order, fast=fast, limiting_shear=lam_s)
            e = rel_errors(t, ref, a, b)
            rule = "fast" if fast else "accurate"
            print(f"{name:>16} {rule:>9} {order:5d} {e.max():8.1e} {np.percentile(e, 99):8.1e}")
    print(f"compiled kernel, {calls[0][0].size} contacts per call (median / min over {args.reps} calls, us):")
    for rnd in range(3):
        pure = kernel_times(calls, None, args.reps)
        capped = kernel_times(calls, lam, args.reps)
        print(f"  round {rnd + 1}: pure Crook {pure[0]:.1f} / {pure[1]:.1f}, limited {capped[0]:.1f} / {capped[1]:.1f};"
              f" ratio {capped[0] / pure[0]:.3f}")


if __name__ == "__main__":
    main()
