"""The public API: the names users need at the top level, ``mbs.CreateAngularContactBearing``
registered on Exudyn's MainSystem, and the installed ``exudyn-bearing`` command."""
import subprocess
import sys
from importlib import metadata

import pytest

import exudyn_bearing


def test_all_names_exist_and_the_names_users_need_are_there():
    assert sorted(set(exudyn_bearing.__all__)) == sorted(exudyn_bearing.__all__)  # no duplicates
    missing = [name for name in exudyn_bearing.__all__ if not hasattr(exudyn_bearing, name)]
    assert missing == []
    for name in ("Lubricant", "BearingResults", "SimulationSummary", "skid_map", "solve_shaft",
                 "TractionCoefficientWarning", "CreateAngularContactBearing", "simulate", "steady_state",
                 "gyroscopic_minimum_axial", "hirano_minimum_axial", "BearingSimulationError"):
        assert name in exudyn_bearing.__all__, name


def test_create_is_a_method_of_exudyns_main_system():
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import races

    assert exu.MainSystem.CreateAngularContactBearing is exudyn_bearing.CreateAngularContactBearing
    mbs = exu.SystemContainer().AddSystem()
    handle = mbs.CreateAngularContactBearing(innerRace=races.Driven(rpm=1800), axialForce=1300.0, show=False)
    assert isinstance(handle, exudyn_bearing.BearingHandle)
    assert mbs.GetObject(handle.contactObject)["objectType"] == "GenericODE2"


def test_the_installed_command_is_the_cli():
    scripts = {ep.name: ep.value for ep in metadata.entry_points(group="console_scripts")}
    assert scripts.get("exudyn-bearing") == "exudyn_bearing.studies.cli:main"
    out = subprocess.run([sys.executable, "-c", "import sys; sys.argv[0] = 'exudyn-bearing'; "
                          "from exudyn_bearing.studies.cli import main; sys.exit(main(['--help']))"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0 and out.stdout.startswith("usage: exudyn-bearing")
