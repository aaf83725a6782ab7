"""Settled starts on the user's own bodies (issue 34, item 1): a bearing whose inner race sits
on the user's shaft (``races.OnBody``) starts from the state of its start load
(``startLoad``), or, on a shaft placed by ``SettleShaft``, from the quasi-dynamic balance of
its balls with the races where the shaft puts them (``pose_state``). Checked against
numbers the start does not produce: the axial steady-state solver, the load-balanced
quasi-dynamic state, the mirror symmetry of a back-to-back pair, and the CLI's run."""
import json
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from exudyn_bearing import (REFERENCE_BEARING, REFERENCE_LUBRICANT, BallDrag, CageModel,  # noqa: E402
                            CreateAngularContactBearing, SettleShaft, ShaftBearing, races, steady_state)
from exudyn_bearing.solvers.quasidynamic import combined_load_state, pose_state  # noqa: E402
from tests.helpers import BEARING_7205  # noqa: E402,F401


#: a plain Exudyn scene: the user's shaft (speed and tilt held) loaded by the user's force,
#: the bearing's inner race on it, solved by SolveDynamic with the README's settings; prints JSON
SCENE = """\
import json, sys
import numpy as np
import exudyn as exu
from exudyn.utilities import InertiaCylinder
import exudyn_bearing
from exudyn_bearing import races

axial, radial, rpm, t_end, start = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
SC = exu.SystemContainer(); mbs = SC.AddSystem()
w = rpm * np.pi / 30
shaft = mbs.CreateRigidBody(inertia=InertiaCylinder(density=7850.0, length=0.05, outerRadius=0.0125, axis=2),
                            referencePosition=[0, 0, 0], initialAngularVelocity=[0, 0, w],
                            nodeType=exu.NodeType.RotationRotationVector, returnDict=True)["bodyNumber"]
mbs.CreateCoordinateConstraint(itemNumbers=[None, shaft], coordinates=[None, 5], offset=w, velocityLevel=True,
                               show=False)
for c in (3, 4):
    mbs.CreateCoordinateConstraint(itemNumbers=[None, shaft], coordinates=[None, c], show=False)
mbs.CreateForce(itemNumber=shaft, loadVector=[radial, 0, axial], show=False)
extra = {"startLoad": (axial, radial)} if start == "load" else {}
brg = mbs.CreateAngularContactBearing("my7205.toml", innerRace=races.OnBody(shaft), **extra)
mbs.Assemble()
ss = exu.SimulationSettings()
h = brg.RecommendedStep()
ss.timeIntegration.numberOfSteps = int(round(t_end / h))
ss.timeIntegration.endTime = t_end
ss.timeIntegration.newton.relativeTolerance = 1e-4
ss.timeIntegration.newton.absoluteTolerance = brg.RecommendedAbsoluteTolerance()
ss.timeIntegration.adaptiveStepRecoveryIterations = 5
ss.solutionSettings.sensorsWritePeriod = 2e-4
ss.timeIntegration.verboseMode = 0
exu.SolveDynamic(mbs, ss)
res = brg.Results(mbs)
print(json.dumps({"time": res.time.tolist(), "kinematic": res.kinematic_cage_slip_percent.tolist(),
                  "start": "steady" if brg.initialSteadyState is not None else
                           "quasi-dynamic" if brg.initialQuasiDynamicState is not None else "rolling"}))
"""


def _run_scene(tmp_path, *args):
    (tmp_path / "my7205.toml").write_text(BEARING_7205)
    (tmp_path / "scene.py").write_text(SCENE)
    proc = subprocess.run([sys.executable, "scene.py", *map(str, args)], cwd=tmp_path, capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    out = json.loads(proc.stdout.strip().splitlines()[-1])
    return np.array(out["time"]), np.array(out["kinematic"]), out["start"]


def _windows(t, values, width):
    return np.array([values[(t >= a) & (t < a + width)].mean() for a in np.arange(0.0, t[-1] - 0.5 * width, width)])


@pytest.mark.parametrize("cage, rel, radius", [(None, 1e-9, 1e-12), (CageModel(), 1e-5, 1e-9)])
def test_pose_state_at_the_load_balances_displacement_is_that_balance(cage, rel, radius):
    """The balance with the race held where the load balance put it is the load balance: two
    solution paths (continuation in load; in pose from the steady state) meet, exactly
    without a cage, and with the land-guided cage to the seat's fixed-point tolerance (each
    path seats the cage to 1 % of its play, 2 um), the pocket forces to the balances'
    tolerance."""
    kw = dict(rpm=1800.0, ball_drag=BallDrag(), cage=cage)
    loaded = combined_load_state(REFERENCE_BEARING, REFERENCE_LUBRICANT, axial_force=1300.0, radial_force=500.0, **kw)
    held = pose_state(REFERENCE_BEARING, REFERENCE_LUBRICANT, pose=loaded.displacement, **kw)
    assert loaded.converged and held.converged, held.message
    assert abs(held.cage_speed - loaded.cage_speed) < rel * loaded.cage_speed
    assert np.max(np.abs(held.orbit_radius - loaded.orbit_radius)) < radius
    assert np.max(np.abs(held.omega - loaded.omega)) < max(rel, 1e-6) * np.max(np.abs(loaded.omega))
    # the pocket forces to the balances' own tolerance, 1e-8 of the force scale F/(Z sin α)
    # (chord steps stop just inside it; full Newton steps overshoot it by orders)
    force_scale = 1300.0 / (REFERENCE_BEARING.balls * np.sin(REFERENCE_BEARING.contact_angle))
    assert np.max(np.abs(held.pocket_force - loaded.pocket_force)) < max(
        1e-8 * force_scale, 100 * rel * np.max(np.abs(loaded.pocket_force)))
    if cage is not None:  # seated on the land, both the same way
        play = 0.5 * cage.guide_clearance
        assert play < np.linalg.norm(loaded.cage_offset) < 1.1 * play
        assert np.linalg.norm(np.subtract(held.cage_offset, loaded.cage_offset)) < 0.02 * play


@pytest.mark.slow
def test_start_load_on_a_users_shaft_starts_at_the_steady_state(tmp_path):
    """The 7205 on a user's shaft, 300 N axial at 12 000 rpm, plain SolveDynamic: with
    startLoad the kinematic cage slip of every 4-ms window of the first 20 ms is within
    0.02 pp of the steady-state solver's value (issue: within 0.1 pp); without it the
    shaft starts where it was made, with the balls in balance there (the zero-clearance
    geometry's light contact), and the 300 N then move it: the slip starts off."""
    t, slip, start = _run_scene(tmp_path, 300.0, 0.0, 12000.0, 0.02, "load")
    assert start == "steady"
    settled = steady_state(str(tmp_path / "my7205.toml"), axial_force=300.0, rpm=12000.0).kinematic_cage_slip_percent
    windows = _windows(t, slip, 0.004)
    assert len(windows) == 5 and np.max(np.abs(windows - settled)) < 0.02, (windows, settled)
    t, slip, start = _run_scene(tmp_path, 300.0, 0.0, 12000.0, 0.004, "none")
    assert start == "quasi-dynamic"
    assert abs(_windows(t, slip, 0.002)[0] - settled) > 0.1, (_windows(t, slip, 0.002), settled)


@pytest.mark.slow
def test_scene_and_cli_start_alike_under_combined_load(tmp_path):
    """300 N + 200 N on the 7205 at 12 000 rpm: the scene with the bearing on the user's
    shaft and the CLI (the bearing's own race) start from the same quasi-dynamic state, so
    their kinematic cage slips agree over the first 10 ms to 0.02 pp (0.44 pp apart before,
    the scene starting from pure rolling)."""
    t, slip, start = _run_scene(tmp_path, 300.0, 200.0, 12000.0, 0.01, "load")
    assert start == "quasi-dynamic"
    # the CLI's run (simulate --bearing my7205.toml ...) through its Python door, for the time series
    proc = subprocess.run([sys.executable, "-c", textwrap.dedent("""
                              import json
                              from exudyn_bearing import simulate
                              r = simulate("my7205.toml", axial_force=300, radial_force=200, rpm=12000, time=0.01).results
                              print(json.dumps({"t": r.time.tolist(), "k": r.kinematic_cage_slip_percent.tolist()}))
                          """)], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    cli = json.loads(proc.stdout.strip().splitlines()[-1])
    ours = _windows(t, slip, 0.0025)
    theirs = _windows(np.array(cli["t"]), np.array(cli["k"]), 0.0025)
    assert np.max(np.abs(ours - theirs)) < 0.02, (ours, theirs)


def test_a_settled_preloaded_pair_holds_its_slip_and_its_mirror_symmetry():
    """demos/hss_shaft.py without gear load: two reference bearings back to back on one shaft,
    5 um interference each. SettleShaft places the shaft, each bearing starts from its balance
    at that pose (the second one turning backwards in its frame: the mirrored solution). Both
    bearings carry the same preload, so by symmetry their slips are equal; both stay within
    0.01 pp of their start over 10 ms and within 0.05 pp of the axial steady state at the
    preload the run's bearings carry."""
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "demos" / "hss_shaft.py"
    spec = importlib.util.spec_from_file_location("hss_shaft_demo", path)
    demo = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(demo)
    from exudyn_bearing import SolverSettings, run_solver

    mbs = exu.SystemContainer().AddSystem()
    body, handles, _ = demo.build(mbs, tangential=0.0)
    assert all(h.initialQuasiDynamicState is not None for h in handles)
    assert handles[1].initialQuasiDynamicState.cage_speed < 0 < handles[0].initialQuasiDynamicState.cage_speed
    mbs.Assemble()
    run_solver(mbs, handles, 0.01, SolverSettings(output_step=2.5e-4, progress=False))
    results = [h.Results(mbs) for h in handles]
    slips = [r.kinematic_cage_slip_percent for r in results]
    for s in slips:
        assert np.max(np.abs(s - s[0])) < 0.01
    assert abs(slips[0][-1] - slips[1][-1]) < 0.01
    preload = abs(float(np.mean(results[0].inner_race_force[-10:, 2])))
    settled = steady_state(axial_force=preload, rpm=1800.0).kinematic_cage_slip_percent
    assert abs(slips[0][-1] - settled) < 0.05, (slips[0][-1], settled, preload)


def test_settle_shaft_moves_the_shaft_to_the_quasi_static_solution_and_checks_it():
    """SettleShaft puts a shaft (Exudyn's default Euler-parameter node, placed away from the
    origin) where solve_shaft puts the same shaft at the origin, displaced and tilted; a
    shaft whose axis is not z is refused."""
    from exudyn.utilities import InertiaCylinder

    from exudyn_bearing.races import node_state
    from exudyn_bearing.solvers.shaft import solve_shaft

    def pair(at):
        return [ShaftBearing(REFERENCE_BEARING, tuple(at + [0.0, 0.0, -0.1]), np.eye(3), (0.0, 0.0, -0.1 + 5e-6)),
                ShaftBearing(REFERENCE_BEARING, tuple(at + [0.0, 0.0, 0.1]), np.diag([1.0, -1.0, -1.0]),
                             (0.0, 0.0, 0.1 - 5e-6))]

    at = np.array([0.1, 0.2, 0.3])
    mbs = exu.SystemContainer().AddSystem()
    inertia = InertiaCylinder(density=7850.0, length=0.3, outerRadius=0.045, axis=2)
    body = mbs.CreateRigidBody(inertia=inertia, referencePosition=at.tolist(), initialAngularVelocity=[0.0, 0.0, 188.5],
                               returnDict=True)["bodyNumber"]
    eq = SettleShaft(mbs, body, pair(at), force=(500.0, 0.0, 300.0), moment=(0.0, 20.0))
    ref = solve_shaft(pair(np.zeros(3)), force=(500.0, 0.0, 300.0), moment=(0.0, 20.0), rpm=188.5 * 30 / np.pi)
    assert np.linalg.norm(ref.displacement) > 1e-6 and abs(ref.tilt[1]) > 1e-6  # it moves and tilts
    pos, rot, _, _ = node_state(mbs, mbs.GetObject(body)["nodeNumber"])
    assert np.allclose(pos - at, ref.displacement, atol=1e-12) and np.allclose(eq.tilt, ref.tilt)
    assert np.allclose(rot[:, 2], [ref.tilt[1], -ref.tilt[0], 1.0], atol=1e-9)  # axis ~ (theta_y, -theta_x, 1)
    tilted = mbs.CreateRigidBody(inertia=inertia, referencePosition=[0.0, 0.0, 0.0],
                                 referenceRotationMatrix=np.array([[1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]]),
                                 returnDict=True)["bodyNumber"]
    with pytest.raises(ValueError, match="shaftBody: its axis"):
        SettleShaft(mbs, tilted, pair(np.zeros(3)))


def test_start_load_input_is_checked():
    mbs = exu.SystemContainer().AddSystem()
    with pytest.raises(ValueError, match="startLoad is the start load of an inner race on your body"):
        CreateAngularContactBearing(mbs, innerRace=races.Driven(1800.0), startLoad=(300.0, 0.0))
    from exudyn.utilities import InertiaSphere

    body = mbs.CreateRigidBody(inertia=InertiaSphere(mass=1.0, radius=0.02), referencePosition=[0.0, 0.0, 0.0],
                               nodeType=exu.NodeType.RotationRotationVector, returnDict=True)["bodyNumber"]
    with pytest.raises(ValueError, match="startLoad must be two finite non-negative forces"):
        CreateAngularContactBearing(mbs, innerRace=races.OnBody(body), startLoad=(-300.0, 0.0))
    with pytest.raises(ValueError, match=r"startLoad must be \(axial, radial\)"):
        CreateAngularContactBearing(mbs, innerRace=races.OnBody(body), startLoad=300.0)


def test_a_tilted_pose_balances_its_power_about_where_the_race_turns():
    """The quasi-dynamic drive power of a tilted inner race (0.2 mrad: its groove centres move
    by up to 16 um): each contact's torque about the point the kinematics turn the race about
    (its displacement with the groove's tilt shift), so drive = losses - sum Q dp/dt to 1e-8
    (about the displacement alone it missed by 4e-5)."""
    from unittest import mock

    from exudyn_bearing.solvers import quasidynamic
    from tests.helpers import quasi_dynamic_power_gap

    seed = steady_state(REFERENCE_BEARING, REFERENCE_LUBRICANT, axial_force=1300.0, rpm=1800.0)
    seen, states = {}, quasidynamic._states

    def spy(balance, y, *args, **kwargs):
        seen.update(balance=balance, x=y / balance.scale)
        return states(balance, y, *args, **kwargs)

    with mock.patch.object(quasidynamic, "_states", spy):
        state = pose_state(REFERENCE_BEARING, REFERENCE_LUBRICANT, pose=(2e-6, 0.0, seed.inner_race_shift, 2e-4, 0.0),
                           rpm=1800.0)
    assert state.converged, state.message
    assert np.max(np.abs(seen["balance"].groove_shift)) > 1e-5
    drive, losses, normal = quasi_dynamic_power_gap(seen["balance"], seen["x"])
    assert drive == pytest.approx(losses - normal, rel=1e-8)
