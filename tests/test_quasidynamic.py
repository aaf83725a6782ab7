"""The quasi-dynamic start under combined load (MODEL.md §12a, exudyn_bearing/quasidynamic.py)
against the axial steady state (a separate solver) and against the dynamic model."""
import numpy as np
import pytest

pytest.importorskip("exudyn")

from exudyn_bearing import REFERENCE_BEARING as B, REFERENCE_DRAG, REFERENCE_LUBRICANT, simulate, steady_state  # noqa: E402
from exudyn_bearing.quasidynamic import combined_load_state  # noqa: E402
from exudyn_bearing.runner import SolverSettings  # noqa: E402


def test_vanishing_radial_load_is_the_axial_steady_state():
    """400 N axial (the balls skid: ~71 % kinematic slip) with 1 N radial: every ball's balance
    at its azimuth, the cage and the inner race as one system gives the cage speed, ball spin
    and race shift of the one-ball steady-state solver (MODEL.md §12) to 0.1 %."""
    steady = steady_state(axial=400.0, rpm=1800.0)
    state = combined_load_state(B, REFERENCE_LUBRICANT, axial=400.0, radial=1.0, rpm=1800.0, drag=REFERENCE_DRAG,
                                steady=steady)
    assert state.converged, state.message
    assert state.cage_speed == pytest.approx(steady.cage_speed, rel=1e-3)
    np.testing.assert_allclose(state.omega, np.tile(steady.ball_omega, (B.balls, 1)), rtol=0,
                               atol=2e-3 * np.linalg.norm(steady.ball_omega))
    assert state.displacement[2] == pytest.approx(steady.inner_race_shift, rel=0.05)
    # the radial load pushes the inner race along +x; the pockets' forces balance the cage
    assert state.displacement[0] > 0
    assert abs(np.sum(state.pocket_force * state.orbit_radius)) < 1e-6 * np.max(np.abs(state.pocket_force)) + 1e-9


def test_dynamic_run_from_the_combined_start_holds_its_cage_speed():
    """400 N + 100 N radial at 1800 rpm: from initialState='steady' (the quasi-dynamic start)
    the cage speed stays within 0.2 % of the start over 30 ms, where the pure-rolling start
    drifts by more than 5 % (it needs seconds to settle)."""
    settings = SolverSettings(progress=False)
    run = simulate(axial=400.0, radial=100.0, rpm=1800.0, time=0.03, initial_state="steady", settings=settings)
    res = run.results
    assert run.initial_steady_state is None  # the combined start is no axial steady state
    start = res.cage_speed[0]
    assert np.max(np.abs(res.cage_speed - start)) < 2e-3 * start
    rolling = simulate(axial=400.0, radial=100.0, rpm=1800.0, time=0.03, initial_state="rolling",
                       settings=settings).results
    assert abs(rolling.cage_speed[-1] - rolling.cage_speed[0]) > 0.05 * rolling.cage_speed[0]


def test_auto_takes_the_combined_start_where_the_axial_load_skids():
    """'auto' starts a skidding combined load (400 N + 100 N: ~71 % slip under the axial load
    alone) from the quasi-dynamic state and keeps pure rolling where the axial load alone does
    not skid (2.2 kN + 2 kN), where the explicit 'steady' refuses; a continuation given too
    few steps says so and is not used."""
    import exudyn as exu

    from exudyn_bearing import CreateAngularContactBearing

    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, axialForce=400.0, radialForce=100.0, show=False)
    assert handle.initialQuasiDynamicState is not None and handle.initialSteadyState is None
    assert handle.initialQuasiDynamicState.converged
    other = CreateAngularContactBearing(exu.SystemContainer().AddSystem(), axialForce=2200.0, radialForce=2000.0,
                                        show=False)
    assert other.initialQuasiDynamicState is None and other.initialSteadyState is None
    with pytest.raises(ValueError, match="skids"):
        CreateAngularContactBearing(exu.SystemContainer().AddSystem(), axialForce=2200.0, radialForce=2000.0,
                                    initialState="steady", show=False)
    short = combined_load_state(B, REFERENCE_LUBRICANT, axial=400.0, radial=300.0, rpm=1800.0, drag=REFERENCE_DRAG,
                                max_steps=2)
    assert not short.converged and "after 2 steps" in short.message


def test_cli_start_flag_takes_the_combined_start(tmp_path):
    """`simulate --start steady` under combined load starts from the quasi-dynamic state (the
    cage speed of the Python API's start) and records it in the result's inputs."""
    import json
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--axial", "400", "--radial", "100",
                          "--time", "0.002", "--start", "steady", "--json"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]
    data = json.loads(out.stdout)
    assert data["inputs"]["initial_state"] == "'steady'"
    state = combined_load_state(B, REFERENCE_LUBRICANT, axial=400.0, radial=100.0, rpm=1800.0, drag=REFERENCE_DRAG)
    assert data["cage_speed"] == pytest.approx(state.cage_speed, rel=2e-3)
