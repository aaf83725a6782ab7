"""The bearing's outputs as Exudyn sensors (BearingHandle.AddSensors), for PlotSensor and
live views, at no cost unless asked for."""
import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

from exudyn.utilities import SensorNode  # noqa: E402

from exudyn_bearing import CreateAngularContactBearing, races  # noqa: E402


def _solve(mbs, end_time, steps, write_period):
    """Exudyn's own SolveDynamic, quiet, sensors written every ``write_period`` s."""
    ss = exu.SimulationSettings()
    ss.timeIntegration.endTime = end_time
    ss.timeIntegration.numberOfSteps = steps
    ss.timeIntegration.verboseMode = 0
    ss.solution.file.write = False
    ss.solution.sensors.writePeriod = write_period
    exu.SolveDynamic(mbs, ss)


def test_sensors_follow_the_run_and_cost_nothing_unless_added():
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=2200.0, radialForce=2000.0,
                                         show=False)
    assert mbs.systemData.NumberOfSensors() == 1  # the state recorder only
    sensors = handle.AddSensors(mbs)
    # Exudyn's own node sensor of the cage: an independent reading of the cage speed
    node = mbs.AddSensor(SensorNode(nodeNumber=handle.cageNode, storeInternal=True,
                                    outputVariableType=exu.OutputVariableType.AngularVelocity))
    mbs.Assemble()
    _solve(mbs, 0.005, 50, 1e-3)
    data = {name: np.asarray(mbs.GetSensorStoredData(s)) for name, s in sensors.items()}
    omega = np.asarray(mbs.GetSensorStoredData(node))
    np.testing.assert_allclose(data["cageSpeed"][:, 1], omega[:, 3], rtol=1e-9)  # bearing axis = global z
    res = handle.Results(mbs)
    for name, series in (("kinematicCageSlip", res.kinematic_cage_slip_percent), ("cageSlip", res.cage_slip_percent),
                         ("attitudeXZ", np.degrees(res.attitude_xz.mean(axis=1)))):
        at = np.searchsorted(res.time, data[name][-1, 0] - 1e-12)
        assert data[name][-1, 1] == pytest.approx(series[at], rel=1e-9), name
    # the balls' forces on the races: the recorded outputs at the same time, and the load path
    # (they carry the applied load, up to the races' and balls' inertia and the cage's land
    # force in this 5-ms run: within 3 %)
    at = np.searchsorted(res.time, data["outerRaceForce"][-1, 0] - 1e-12)
    np.testing.assert_allclose(data["outerRaceForce"][-1, 1:], res.outer_race_force[at], rtol=1e-9)
    np.testing.assert_allclose(data["innerRaceForce"][-1, 1:], res.inner_race_force[at], rtol=1e-9)
    applied = np.array([2000.0, 0.0, 2200.0])
    np.testing.assert_allclose(data["outerRaceForce"][-1, 1:], applied, rtol=0, atol=0.03 * 2200.0)
    np.testing.assert_allclose(data["innerRaceForce"][-1, 1:], -applied, rtol=0, atol=0.03 * 2200.0)
    with pytest.raises(ValueError, match="outputs"):
        handle.AddSensors(mbs, outputs=("cageVelocity",))


def test_plotted_sensors_say_what_they_are_and_their_unit(tmp_path):
    """Exudyn's PlotSensor labels a user-function sensor 'UserFunction': PlotSensors puts the
    output's name and unit on the axis and in the legend."""
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800), axialForce=1300.0, show=False)
    sensors = handle.AddSensors(mbs, outputs=("kinematicCageSlip", "cageSlip", "cageSpeed"))
    mbs.Assemble()
    _solve(mbs, 0.002, 20, 5e-4)
    _, _, ax, _ = handle.PlotSensors(mbs, sensors, ["kinematicCageSlip"], closeAll=True)
    assert ax.get_ylabel() == "kinematic cage slip, %" and ax.get_xlabel() == "time, s"
    assert [line.get_label() for line in ax.get_lines()] == ["kinematic cage slip (%)"]
    _, _, ax, _ = handle.PlotSensors(mbs, sensors, ["kinematicCageSlip", "cageSlip"], closeAll=True)
    assert ax.get_ylabel() == "%"
    _, _, ax, _ = handle.PlotSensors(mbs, sensors, ["kinematicCageSlip", "cageSpeed"], closeAll=True)
    assert ax.get_ylabel() == "% / rad/s"
    with pytest.raises(ValueError, match="outputs"):
        handle.PlotSensors(mbs, sensors, ["attitudeXZ"])
