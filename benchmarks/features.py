"""What each optional piece of physics costs (issue 5: a feature a scene does not use must
cost nothing). Times one right-hand-side evaluation of the bearing connector (the force
user function the solver calls; all 32 contacts, the reference bearing at 1.3 kN, 1800 rpm,
its quasi-static start) per builder option, and a short generalized-alpha run with and
without the state sensor. Ratios to the full model are measured in the same run.

    python benchmarks/features.py [--calls 300]
"""
import argparse
import time

import numpy as np
import exudyn as exu

from contact.ballrace import ContactLaw
from exudyn_bearing.model.builder import CreateAngularContactBearing
from exudyn_bearing.cage import CageModel
from exudyn_bearing.simulation.runner import SolverSettings, run_solver

OPTIONS = {
    "full model (Crook EHD with limiting shear, spin moment, rigid cage, drag)": {},
    "pure Crook (the paper's law, no limiting shear)": dict(contactLaw=ContactLaw(traction="crook")),
    "isothermal Newtonian traction": dict(contactLaw=ContactLaw(traction="newtonian")),
    "dry Coulomb traction": dict(contactLaw=ContactLaw(traction="coulomb")),
    "no traction (normal forces only)": dict(contactLaw=ContactLaw(traction="none")),
    "spin moment off": dict(contactLaw=ContactLaw(spin_moment=False)),
    "accurate (adaptive) Crook quadrature": dict(contactLaw=ContactLaw(fast_quadrature=False)),
    "spring-chain cage (P9)": dict(cage=CageModel("spring-chain")),
    "no cage": dict(cage=CageModel("none")),
    "ball drag off": dict(ballDrag=None),
    "everything off (normal forces, no cage, no drag)": dict(contactLaw=ContactLaw(traction="none"),
                                                           cage=CageModel("none"), ballDrag=None),
}


def build(**kw):
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    h = CreateAngularContactBearing(mbs, axialForce=1300.0, show=False, **kw)
    mbs.Assemble()
    return sc, mbs, h


def evaluation_time(calls, **kw):
    sc, mbs, h = build(**kw)
    con = h.connector
    # what the solver calls: the force user function (coordinates without the reference)
    q = np.asarray(mbs.systemData.GetODE2Coordinates())
    v = np.asarray(mbs.systemData.GetODE2Coordinates_t())
    con.residual_forces(0.0, q, v)
    best = np.inf
    for _ in range(3):  # best of three batches: the machine is shared
        t0 = time.perf_counter()
        for _ in range(calls):
            con.residual_forces(0.0, q, v)
        best = min(best, (time.perf_counter() - t0) / calls)
    return best


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=300)
    args = parser.parse_args(argv)
    rows = [(name, evaluation_time(args.calls, **kw)) for name, kw in OPTIONS.items()]
    full = rows[0][1]
    print("| builder option | ms per evaluation | ratio to full |")
    print("|---|---|---|")
    for name, t in rows:
        print(f"| {name} | {1e3 * t:.3f} | {t / full:.2f} |")
    walls = {}
    for record in (True, False):
        sc, mbs, h = build(recordStates=record)
        walls[record] = run_solver(mbs, [h], 0.005, SolverSettings()).wall_time_s
    print(f"\n5 ms generalized-alpha run: with state sensor {walls[True]:.2f} s, without {walls[False]:.2f} s "
          f"(ratio {walls[False] / walls[True]:.2f})")


if __name__ == "__main__":
    main()
