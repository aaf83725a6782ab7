"""A wind-turbine gearbox high-speed shaft on a preloaded back-to-back bearing pair.

An ordinary Exudyn scene: the shaft is a rigid body (``NodeRigidBodyRotVecLG``) held at
its speed by a velocity-level coordinate constraint (the generator), loaded by a
helical-gear mesh force (tangential, radial, axial and the tilting moment of the axial
force at the pitch radius), and carried by two reference bearings (MODEL.md §8) whose
inner races sit on the shaft (``races.OnBody``) and whose outer races are fixed in the
housing. The bearing axes point towards each other's side (back-to-back, pressure centres
outside the span); the inner races are pushed ``--preload-um`` into each bearing, which
preloads the pair. The shaft starts settled: ``SettleShaft`` places it at its quasi-static
equilibrium under the gear load before the bearings are added, and each bearing starts
from the quasi-dynamic balance of its balls there (``--ramp`` s ramps the load in instead,
from the preloaded shaft).

At the end the shaft position and both bearings' reactions are compared with the 5-DOF
quasi-static solution of the whole shaft (:func:`exudyn_bearing.solvers.shaft.solve_shaft`).

    python demos/hss_shaft.py                  # 0.04 s, prints the comparison
    python demos/hss_shaft.py --time 0.1 --plot
    python demos/hss_shaft.py --settle none    # start from the unloaded shaft, as before SettleShaft
"""
import argparse
import time
from pathlib import Path

import numpy as np
import exudyn as exu
from exudyn.utilities import InertiaCylinder

from exudyn_bearing import (REFERENCE_BEARING, CreateAngularContactBearing, races, run_solver, SettleShaft,
                            ShaftBearing, solve_shaft, SolverSettings)

SPAN = 0.2  #: bearing centre distance, m
GEAR_Z = 0.03  #: gear mid-plane on the shaft axis, m (off-centre: the bearings share the load unequally)
BACK = np.diag([1.0, -1.0, -1.0])  #: frame of the second bearing: axis along -z


def gear_load(tangential, pitch_radius=0.05, pressure_angle_deg=20.0, helix_angle_deg=12.0):
    """Helical-gear mesh force on the shaft (N) and its moment about the shaft centre (N m),
    global. The mesh point is at +y on the pitch circle; the tangential force drives the
    shaft about +z."""
    f_t = tangential
    f_r = f_t * np.tan(np.radians(pressure_angle_deg)) / np.cos(np.radians(helix_angle_deg))
    f_a = f_t * np.tan(np.radians(helix_angle_deg))
    force = np.array([-f_t, -f_r, f_a])
    moment = np.cross([0.0, pitch_radius, GEAR_Z], force)
    return force, moment


def shaft_bearings(preload):
    """The pair as seen by the quasi-static shaft solver: outer races in the housing at
    z = -+SPAN/2, inner races pushed ``preload`` m along each bearing's axis."""
    half = SPAN / 2
    return [ShaftBearing(REFERENCE_BEARING, (0.0, 0.0, -half), np.eye(3), (0.0, 0.0, -half + preload)),
            ShaftBearing(REFERENCE_BEARING, (0.0, 0.0, half), BACK, (0.0, 0.0, half - preload))]


def build(mbs, rpm=1800.0, tangential=2000.0, preload=5e-6, ramp=0.0, show=False,
          node_type=exu.NodeType.RotationRotationVector, hold_speed=True, settle=True, outer_races=None,
          surfaces=None):
    """Add the shaft, its speed constraint (``hold_speed``), the gear load and both bearings
    to ``mbs``; returns (shaft body, [bearing handles], (force, moment)). ``node_type``: the
    shaft's Exudyn node type (Exudyn's default is Euler parameters; the races then sit on
    light adapter bodies joined to the shaft). ``settle``: place the shaft at its
    quasi-static equilibrium under the load at t = 0 before adding the bearings.
    ``outer_races``, ``surfaces``: per bearing, its outer race (default ``races.Fixed()``) and
    race surfaces (default perfect; demos/defect_vibration.py puts a spall on one)."""
    omega = rpm * np.pi / 30
    shaft = mbs.CreateRigidBody(inertia=InertiaCylinder(density=7850.0, length=0.3, outerRadius=0.045, axis=2),
                                referencePosition=[0.0, 0.0, 0.0], initialAngularVelocity=[0.0, 0.0, omega],
                                nodeType=node_type, returnDict=True)
    body = shaft["bodyNumber"]
    if hold_speed:  # generator: holds the shaft speed (velocity coordinate 5 is the local omega_z)
        if node_type != exu.NodeType.RotationRotationVector:
            raise ValueError("hold_speed needs node_type=exu.NodeType.RotationRotationVector")
        mbs.CreateCoordinateConstraint(itemNumbers=[None, body], coordinates=[None, 5], offset=omega,
                                       velocityLevel=True, show=False)
    force, moment = gear_load(tangential)

    def ramped(vector):
        return lambda mbs_, t, load: list(vector * min(t / ramp, 1.0)) if ramp > 0 else list(vector)

    mbs.CreateForce(itemNumber=body, loadVector=force.tolist(), loadVectorUserFunction=ramped(force), show=False)
    mbs.CreateTorque(itemNumber=body, loadVector=moment.tolist(), loadVectorUserFunction=ramped(moment), show=False)
    if settle:
        at_start = 0.0 if ramp > 0 else 1.0
        SettleShaft(mbs, body, shaft_bearings(preload), at_start * force, at_start * moment[:2], rpm=rpm)
    handles = []
    for k, b in enumerate(shaft_bearings(preload)):
        rot = np.asarray(b.rotation)
        extra = {} if surfaces is None or surfaces[k] is None else {"surface": surfaces[k]}
        handles.append(CreateAngularContactBearing(
            mbs, b.bearing, innerRace=races.OnBody(body, localPosition=b.inner_position, localRotation=rot),
            outerRace=races.Fixed() if outer_races is None or outer_races[k] is None else outer_races[k],
            position=b.position, rotationMatrix=rot, show=show, **extra))
    return body, handles, (force, moment)


def compare(mbs, body, handles, loads, rpm, preload, fraction=0.25):
    """Shaft displacement, the displacement of each inner-race centre and the bearing
    reactions, means over the last ``fraction`` of the run, next to the quasi-static
    shaft solution; returns a dict of both (um, mrad, N) and each bearing's results."""
    from contact.kinematics import rotation_matrices

    force, moment = loads
    pair = shaft_bearings(preload)
    qs = solve_shaft(pair, force, moment[:2], rpm=rpm)
    qs_rot = rotation_matrices(np.array([[qs.tilt[0], qs.tilt[1], 0.0]]))[0]
    t, q, _ = handles[0].States(mbs)
    last = t >= t[-1] - fraction * (t[-1] - t[0])
    slot = [int(n) for n in handles[0].nodeNumbers].index(int(mbs.GetObject(body)["nodeNumber"]))
    u = q[last, 6 * slot:6 * slot + 3]
    rot = rotation_matrices(q[last, 6 * slot + 3:6 * slot + 6])
    axis = rot[:, :, 2].mean(axis=0)  # spin-free: the shaft axis A e_z ~ (theta_y, -theta_x, 1)
    results = [h.Results(mbs) for h in handles]
    reactions = [h.connector.rotation @ res.inner_race_force[res.last(fraction)].mean(axis=0)
                 for h, res in zip(handles, results)]

    def centre_shift(disp, rotation, b):  # inner-race centre minus its unloaded position, m
        p = np.asarray(b.inner_position)
        return disp + rotation @ p - p

    return {
        "quasi_static": {"displacement_um": qs.displacement * 1e6, "tilt_mrad": qs.tilt * 1e3,
                         "race_shift_um": [centre_shift(qs.displacement, qs_rot, b) * 1e6 for b in pair],
                         "reactions_N": list(qs.reaction_force),
                         "inner_load_max_N": [float(lo.inner_load.max()) for lo in qs.loads]},
        "dynamic": {"displacement_um": u.mean(axis=0) * 1e6, "tilt_mrad": np.array([-axis[1], axis[0]]) * 1e3,
                    "race_shift_um": [np.mean([centre_shift(ui, ri, b) for ui, ri in zip(u, rot)], axis=0) * 1e6
                                      for b in pair],
                    "reactions_N": reactions},
        "results": results,
    }


def slip_windows(results, width):
    """Mean kinematic cage slip (%) of ``results`` in consecutive windows of ``width`` s."""
    t, k = results.time, results.kinematic_cage_slip_percent
    edges = np.arange(t[0], t[-1] + 0.5 * width, width)
    return [float(k[(t >= a) & (t < a + width)].mean()) for a in edges[:-1]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time", type=float, default=0.04, help="simulated time, s")
    parser.add_argument("--rpm", type=float, default=1800.0)
    parser.add_argument("--tangential", type=float, default=2000.0, help="gear tangential force, N")
    parser.add_argument("--preload-um", type=float, default=5.0, help="axial interference per bearing, um")
    parser.add_argument("--ramp", type=float, default=0.0, help="gear load ramp time, s (0: full load from a settled start)")
    parser.add_argument("--settle", choices=("shaft", "none"), default="shaft",
                        help="shaft: SettleShaft before the bearings (default); none: the shaft where it was created")
    parser.add_argument("--plot", action="store_true", help="write out/hss_shaft/bearing0.png, bearing1.png (plot extra)")
    args = parser.parse_args()
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    body, handles, loads = build(mbs, args.rpm, args.tangential, args.preload_um * 1e-6, args.ramp,
                                 settle=args.settle == "shaft")
    mbs.Assemble()
    start = time.perf_counter()
    info = run_solver(mbs, handles, args.time, SolverSettings(output_step=2.5e-4))
    print(f"{args.time} s simulated in {time.perf_counter() - start:.0f} s ({info.steps} steps, "
          f"generalized-alpha rho_inf {info.solver['spectral_radius']}, step {info.solver['step']:g} s)")
    out = compare(mbs, body, handles, loads, args.rpm, args.preload_um * 1e-6)
    print("gear force (N):", np.round(loads[0], 1).tolist(), " moment (N m):", np.round(loads[1], 2).tolist())
    dyn, qs = out["dynamic"], out["quasi_static"]
    for key, unit in (("displacement_um", "um"), ("tilt_mrad", "mrad")):
        print(f"shaft {key.split('_')[0]:12s} dynamic {np.round(dyn[key], 3).tolist()} {unit}, "
              f"quasi-static {np.round(qs[key], 3).tolist()} {unit}")
    for k in range(len(handles)):
        print(f"bearing {k}: inner-race centre moved {np.round(dyn['race_shift_um'][k], 3).tolist()} um "
              f"(quasi-static {np.round(qs['race_shift_um'][k], 3).tolist()} um)")
        print(f"           reaction on the shaft {np.round(dyn['reactions_N'][k], 1).tolist()} N "
              f"(quasi-static {np.round(qs['reactions_N'][k], 1).tolist()} N)")
        s = out["results"][k].summary()
        print(f"           kinematic cage slip {s['kinematic_cage_slip_percent']:.3f} %, max inner load "
              f"{s['max_inner_load']:.0f} N (quasi-static {qs['inner_load_max_N'][k]:.0f} N)")
        windows = slip_windows(out["results"][k], args.time / 8)
        print("           kinematic cage slip by window (%):", " ".join(f"{v:.3f}" for v in windows))
    if args.plot:
        from exudyn_bearing.results.plots import plot_run

        path = Path("out/hss_shaft")
        path.mkdir(parents=True, exist_ok=True)
        for k, res in enumerate(out["results"]):
            plot_run(res, path / f"bearing{k}.png", title=f"HSS bearing {k}")
        print(f"wrote {path}/bearing0.png, bearing1.png")


if __name__ == "__main__":
    main()
