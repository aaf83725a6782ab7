"""One setup record from file to kernel (issue 48, items 1 and 2): a bearing file reads into a
BearingSetup; every entry point converts its ``bearing`` once, an input passed explicitly wins,
and each section either reaches the run or is refused by name."""
import json
from dataclasses import replace

import numpy as np
import pytest

from contact.ballrace import ContactLaw
from contact.surface import Defect, SurfaceModel, Waviness
from exudyn_bearing import (CWRU_6205_BEARING, REFERENCE_BEARING, REFERENCE_DRAG, REFERENCE_LUBRICANT, BallDrag,
                            BearingSetup, CageModel, as_setup, combined_load_state, dumps_bearing, load_bearing,
                            loads_bearing, save_bearing, simulate, solve_load_distribution, steady_state)
from exudyn_bearing.races import HousingModel
from exudyn_bearing.setup import FROM_SETUP

#: every part differs from the package's default
OIL = replace(REFERENCE_LUBRICANT, viscosity=0.02, limiting_shear_coefficient=0.06)
DRAG = BallDrag(drag_coefficient=0.4, oil_volume_fraction=0.05)
CAGE = CageModel(guidance="inner", guide_clearance=0.3e-3)
LAW = ContactLaw(traction="crook", rolling_resistance=True)
SETUP = BearingSetup(REFERENCE_BEARING, OIL, DRAG, CAGE, LAW)
NOTCH = SurfaceModel((Defect("outer", 0.0, 0.18e-3, 0.28e-3),))
HOUSING = HousingModel(frequency=2500.0, mass=1.5, damping_ratio=0.08)
#: the Case Western bearing with its outer notch on a housing, as a user's file gives it
FAULTY = BearingSetup(CWRU_6205_BEARING, surface=NOTCH, housing=HOUSING)


class Reached(Exception):
    """Raised by a stand-in builder: what reached it is in ``args``."""


def _stop_at_builder(monkeypatch, module):
    """Replace ``module``'s CreateAngularContactBearing with one that raises :class:`Reached`
    carrying the setup it was given and the outer race the builder makes of it (no model is
    built)."""
    from exudyn_bearing.model.checks import check_races

    def builder(mbs, bearing, *a, **kw):
        setup = as_setup(bearing)
        raise Reached(setup, check_races(None, kw.get("innerRace"), kw.get("outerRace"), setup)[1])

    monkeypatch.setattr(module, "CreateAngularContactBearing", builder)


@pytest.fixture
def path(tmp_path):
    p = tmp_path / "my.toml"
    save_bearing(SETUP, p)
    return p


@pytest.fixture
def faulty(tmp_path):
    p = tmp_path / "faulty.toml"
    save_bearing(FAULTY, p)
    return p


def test_the_file_round_trips_every_section_and_names_a_bad_one():
    for setup in (SETUP, FAULTY, replace(FAULTY, surface=SurfaceModel(waviness=Waviness(outer=((9, 0.1e-6, 0.0),))))):
        assert loads_bearing(dumps_bearing(setup)) == setup
    assert "[contact_law]" not in dumps_bearing(BearingSetup(REFERENCE_BEARING))  # the default is not written
    assert "[housing]" not in dumps_bearing(BearingSetup(REFERENCE_BEARING))
    text = dumps_bearing(BearingSetup(REFERENCE_BEARING))
    with pytest.raises(ValueError, match=r"contact_law.rolling_resistance must be true or false"):
        loads_bearing(text + "\n[contact_law]\nrolling_resistance = 1\n")
    with pytest.raises(ValueError, match=r"unknown key\(s\) in \[contact_law\]: tracton"):
        loads_bearing(text + "\n[contact_law]\ntracton = \"crook\"\n")
    with pytest.raises(ValueError, match=r"\[contact_law\] traction must be one of"):
        loads_bearing(text + "\n[contact_law]\ntraction = \"dry\"\n")
    with pytest.raises(ValueError, match=r"\[housing\] Housing: mass must be positive"):
        loads_bearing(text + "\n[housing]\nmass = -1.0\n")
    with pytest.raises(ValueError, match=r"unknown key\(s\) in \[housing\]: frequncy"):
        loads_bearing(text + "\n[housing]\nfrequncy = 1.0\n")
    with pytest.raises(ValueError, match="drag: a setup without ball drag"):
        dumps_bearing(replace(SETUP, drag=None))


def test_the_record_is_validated_and_replaced_by_name():
    with pytest.raises(ValueError, match="lubricant must be a Lubricant, got float"):
        BearingSetup(REFERENCE_BEARING, lubricant=0.04)
    with pytest.raises(ValueError, match="housing must be a HousingModel or None"):
        BearingSetup(REFERENCE_BEARING, housing=3000.0)
    with pytest.raises(ValueError, match="oil: a bearing setup has no such part"):
        SETUP.replace(oil=OIL)
    assert SETUP.replace(ball_drag=None).drag is None  # the functions' and the builder's names
    assert SETUP.replace(contactLaw=ContactLaw()).contact_law == ContactLaw()
    assert SETUP.replace(lubricant=FROM_SETUP, cage=FROM_SETUP) is SETUP
    with pytest.raises(ValueError, match="Housing: frequency must be positive"):
        HousingModel(frequency=0.0)


def test_as_setup_converts_a_path_a_bearing_or_a_setup_and_an_explicit_input_wins(path):
    assert as_setup(path) == as_setup(str(path)) == as_setup(SETUP) == SETUP
    assert as_setup(REFERENCE_BEARING) == BearingSetup(REFERENCE_BEARING, REFERENCE_LUBRICANT, REFERENCE_DRAG)
    assert as_setup(path, lubricant=REFERENCE_LUBRICANT, drag=FROM_SETUP).lubricant == REFERENCE_LUBRICANT
    assert as_setup(path, drag=None).drag is None
    with pytest.raises(ValueError, match="cannot read the bearing file"):
        as_setup(path.parent / "missing.toml")
    with pytest.raises(ValueError, match="bearing must be a Bearing, a BearingSetup or a bearing file's path"):
        as_setup(42)


# -- every entry point takes the whole setup -----------------------------------------------

def test_a_scene_from_the_file_gets_every_part(path, faulty):
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import races

    mbs = exu.SystemContainer().AddSystem()
    h = mbs.CreateAngularContactBearing(str(path), innerRace=races.Driven(rpm=1800), axialForce=1300.0, show=False)
    con = h.connector
    assert (con.lubricant, con.drag, con.cage, con.law) == (OIL, DRAG, CAGE, LAW)
    inputs = h.Inputs()
    assert repr(OIL) == inputs["lubricant"] and repr(LAW) == inputs["contact_law"]
    # an explicit input wins over the file's
    mbs = exu.SystemContainer().AddSystem()
    h = mbs.CreateAngularContactBearing(load_bearing(path), innerRace=races.Driven(rpm=1800), axialForce=1300.0,
                                        ballDrag=None, contactLaw=ContactLaw(), show=False)
    assert (h.connector.lubricant, h.connector.drag, h.connector.law) == (OIL, None, ContactLaw())
    # the surface and the housing: the defect in the connector, the outer race on the file's housing
    mbs = exu.SystemContainer().AddSystem()
    h = mbs.CreateAngularContactBearing(faulty, innerRace=races.Driven(rpm=1797), radialForce=300.0, show=False)
    assert h.connector.surface == NOTCH
    assert h.connector.races["outer"] == HOUSING.race() and h.housingSpring is not None
    assert h.RecommendedSurfaceStep(1797.0) < 1.0  # (a perfect bearing's is inf)


@pytest.mark.slow  # (two 4-ms runs, ~5 s; the fast lane's CLI test below also runs the file's defect)
def test_simulate_runs_the_files_defect_and_housing(faulty):
    """The bug of issue 48: ``simulate("faulty.toml")`` ran a perfect bearing. Now the defect
    and the housing reach the run: the ball leaving the notch (28 µm deep, far deeper than the
    ~10 µm approach) carries another load than on a perfect race, and the result records both."""
    run = simulate(faulty, radial_force=300.0, rpm=1797.0, time=0.004)
    perfect = simulate(faulty, surface=SurfaceModel(), radial_force=300.0, rpm=1797.0, time=0.004)
    assert run.inputs["surface"] == repr(NOTCH) and run.inputs["housing"] == repr(HOUSING)
    assert "surface" not in perfect.inputs and perfect.inputs["housing"] == repr(HOUSING)
    change = np.abs(run.results.outer["load"] - perfect.results.outer["load"])  # (steps, balls), N
    assert change[:, 0].max() > 0.02 * perfect.results.outer["load"].max()


def test_the_solvers_without_a_surface_refuse_it_by_name(faulty):
    wavy = replace(FAULTY, surface=SurfaceModel(waviness=Waviness(outer=((9, 0.1e-6, 0.0),))))
    for call in (lambda s: steady_state(s, axial_force=300.0, rpm=1797.0),
                 lambda s: combined_load_state(s, axial_force=300.0, radial_force=100.0, rpm=1797.0),
                 lambda s: solve_load_distribution(s, axial_force=300.0)):
        with pytest.raises(ValueError, match=r"^\[\[defect\]\]: \w+ solves a perfect bearing"):
            call(faulty)
        with pytest.raises(ValueError, match=r"^\[waviness\]: \w+ solves a perfect bearing"):
            call(wavy)


def test_the_solvers_use_the_parts_they_have_a_meaning_for(path, reference_steady):
    """The steady state of the file is the one of its parts (its housing carries the load and
    changes nothing); the quasi-static distribution takes the file's Hertz method."""
    from_file = steady_state(path, axial_force=1300.0, rpm=1800.0).to_dict()
    by_parts = steady_state(REFERENCE_BEARING, OIL, axial_force=1300.0, rpm=1800.0, ball_drag=DRAG, cage=CAGE,
                            contact_law=LAW).to_dict()
    housed = steady_state(replace(SETUP, housing=HOUSING), axial_force=1300.0, rpm=1800.0).to_dict()
    reference = reference_steady.to_dict()
    for d in (from_file, by_parts, housed):
        d.pop("wall_time_s")
        d.pop("inputs")
    assert from_file == by_parts == housed
    assert from_file["kinematic_cage_slip_percent"] != reference["kinematic_cage_slip_percent"]
    exact = replace(SETUP, contact_law=replace(LAW, hertz_method="exact"))
    fit, by_file = (solve_load_distribution(s, axial_force=1300.0, radial_force=500.0) for s in (SETUP, exact))
    assert by_file.max_load != fit.max_load
    assert by_file.max_load == solve_load_distribution(REFERENCE_BEARING, axial_force=1300.0, radial_force=500.0,
                                                       hertz_method="exact").max_load


def test_vibration_and_render_take_the_files_housing_and_surface(faulty, monkeypatch, tmp_path):
    from exudyn_bearing.model import builder
    from exudyn_bearing.studies import render, vibration

    _stop_at_builder(monkeypatch, builder)  # (vibration imports it when called)
    with pytest.raises(Reached) as got:
        vibration.vibration(faulty, rpm=1797.0, radial_force=300.0, time=0.05)
    setup, outer = got.value.args
    assert setup.surface == NOTCH and outer == HOUSING.race()
    with pytest.raises(Reached) as got:  # an explicit housing wins
        vibration.vibration(faulty, rpm=1797.0, radial_force=300.0, time=0.05, housing=HousingModel(4000.0))
    assert got.value.args[1] == HousingModel(4000.0).race()
    _stop_at_builder(monkeypatch, render)
    with pytest.raises(Reached) as got:
        render.render_run(tmp_path, bearing=faulty, contact_law=LAW)
    setup, outer = got.value.args
    assert setup.surface == NOTCH and setup.contact_law == LAW and outer == HOUSING.race()


def test_the_skid_map_carries_the_surface_to_its_points_and_its_resume_check(faulty, monkeypatch, tmp_path):
    from exudyn_bearing.studies import skidmap

    seen = []
    monkeypatch.setattr(skidmap, "_run_point", lambda job: seen.append(job[1]) or
                        dict(vars(replace(job[0], kinematic_cage_slip_percent=0.5, cage_slip_percent=0.5,
                                          peak_ball_slip=0.01, settled=True))))
    result = skidmap.skid_map(faulty, axial_force=[300.0], radial_force=[100.0], rpm=[1797.0], time=0.01, workers=1,
                              out=tmp_path / "map", progress=None)
    assert seen == [FAULTY]
    assert json.loads((tmp_path / "map" / "inputs.json").read_text())["surface"] == repr(NOTCH)
    assert "not refined: a defect or waviness has no steady state" in result.refine_thresholds(confirm_time=None)[0][
        "note"]
    with pytest.raises(ValueError, match=r"other inputs \(surface differ\)"):  # a resume never mixes surfaces
        skidmap.skid_map(replace(FAULTY, surface=SurfaceModel()), axial_force=[300.0], radial_force=[100.0],
                         rpm=[1797.0], time=0.01, workers=1, out=tmp_path / "map", progress=None)


def test_every_cli_command_reads_the_files_surface_or_refuses_it(faulty, monkeypatch, capsys, path):
    from exudyn_bearing.studies import cli

    for command in ("steady", "loads"):
        with pytest.raises(SystemExit) as code:
            cli.main([command, "--bearing", str(faulty), "--axial", "300"])
        assert code.value.code == 2
        assert "[[defect]]:" in capsys.readouterr().err
    out = json.loads(_cli_json(cli, capsys, ["simulate", "--bearing", str(faulty), "--radial", "300", "--rpm", "1797",
                                             "--time", "0.002", "--json"]))
    assert out["inputs"]["surface"] == repr(NOTCH) and out["inputs"]["housing"] == repr(HOUSING)
    # the file's contact law with the command's option on top
    steady = json.loads(_cli_json(cli, capsys, ["steady", "--bearing", str(path), "--axial", "1300", "--json",
                                                "--traction", "crook-limited"]))
    assert steady["inputs"]["contact_law"] == repr(replace(LAW, traction="crook-limited"))
    assert steady["inputs"]["lubricant"] == repr(OIL)


def _cli_json(cli, capsys, argv):
    assert cli.main(argv) == 0
    return capsys.readouterr().out
