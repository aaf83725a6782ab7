"""A user's ordinary Exudyn scene: the bearing added to ``mbs`` and solved by Exudyn's own
``exu.SolveDynamic`` with default ``SimulationSettings`` (issue 16). The builder installs
the block Jacobian, so the plain solve runs the fast path (speed: benchmarks/plain_solve.py,
1.0x run_solver); here: it runs, writes Exudyn's solution file, and stays on the steady
state the package computes independently of the integration."""
import pytest

exu = pytest.importorskip("exudyn")

from exudyn_bearing import CreateAngularContactBearing, races  # noqa: E402


def test_plain_solve_dynamic_with_default_settings(tmp_path, reference_steady):
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    assert mbs.GetObjectParameter(handle.contactObject, "jacobianUserFunction") != 0
    mbs.Assemble()
    ss = exu.SimulationSettings()  # Exudyn's defaults: generalized-alpha, Newton tolerance 1e-8
    ss.timeIntegration.endTime = 0.01
    ss.timeIntegration.numberOfSteps = 100
    ss.timeIntegration.verboseMode = 0
    ss.solution.file.name = str(tmp_path / "solution.txt")
    assert exu.SolveDynamic(mbs, ss)
    assert (tmp_path / "solution.txt").stat().st_size > 0  # mbs.SolutionViewer has a solution to show
    slip = handle.Results(mbs).summary()["kinematic_cage_slip_percent"]
    assert slip == pytest.approx(reference_steady.kinematic_cage_slip_percent, abs=0.02)


def test_run_solver_takes_the_users_simulation_settings(tmp_path):
    """run_solver with an ``exu.SimulationSettings``: the user's solution file and sensor
    period are kept, only the end time changes (the step endTime/numberOfSteps is kept)."""
    from exudyn_bearing import run_solver

    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    mbs.Assemble()
    ss = exu.SimulationSettings()
    ss.timeIntegration.endTime = 1.0
    ss.timeIntegration.numberOfSteps = 10000  # step 1e-4 s
    ss.timeIntegration.verboseMode = 0
    ss.solution.file.name = str(tmp_path / "solution.txt")
    ss.solution.sensors.writePeriod = 2e-3
    info = run_solver(mbs, [handle], 0.01, ss)
    assert info.steps <= 101 and info.solver["step"] == pytest.approx(1e-4)  # Exudyn counts the start as a step
    assert (tmp_path / "solution.txt").stat().st_size > 0
    t, _, _ = handle.States(mbs)
    assert t[-1] == pytest.approx(0.01) and len(t) <= 7  # written every 2 ms, not every 0.1 ms
