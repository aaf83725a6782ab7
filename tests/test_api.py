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
    assert scripts.get("exudyn-bearing") == "exudyn_bearing.studies.cli:run"
    out = subprocess.run([sys.executable, "-c", "import sys; sys.argv[:] = ['exudyn-bearing', '--help']; "
                          "from exudyn_bearing.studies.cli import run; sys.exit(run())"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0 and out.stdout.startswith("usage: exudyn-bearing")


def _snake(name):
    return "".join("_" + c.lower() if c.isupper() else c for c in name)


def test_one_name_per_input_across_the_builder_and_the_functions():
    """Every input of simulate and the solvers that the builder also takes has the builder's
    words in snake_case (axialForce / axial_force, ballDrag / ball_drag, contactLaw /
    contact_law, initialState / initial_state)."""
    import inspect

    builder = {_snake(p): p for p in inspect.signature(exudyn_bearing.CreateAngularContactBearing).parameters}
    same_input = {"axial_force", "radial_force", "ball_drag", "contact_law", "initial_state", "cage", "bearing",
                  "lubricant"}
    assert same_input <= set(builder)
    old_words = {"axial", "radial", "drag", "law", "contactLaw", "ballDrag"}
    for func in (exudyn_bearing.simulate, exudyn_bearing.steady_state, exudyn_bearing.combined_load_state,
                 exudyn_bearing.skid_map, exudyn_bearing.solve_load_distribution):
        params = set(inspect.signature(func).parameters)
        assert not params & old_words, (func.__name__, params & old_words)


def test_an_old_input_name_still_works_with_a_warning():
    from exudyn_bearing import REFERENCE_BEARING

    new = exudyn_bearing.solve_load_distribution(REFERENCE_BEARING, axial_force=1300.0)
    with pytest.warns(FutureWarning, match="axial_force"):
        old = exudyn_bearing.solve_load_distribution(REFERENCE_BEARING, axial=1300.0)
    assert old.inner_load.tolist() == new.inner_load.tolist()
    with pytest.raises(TypeError, match="axial= and axial_force="):
        exudyn_bearing.solve_load_distribution(REFERENCE_BEARING, axial=1.0, axial_force=1.0)
