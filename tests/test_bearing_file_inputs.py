"""One call from a bearing file to a scene, a run, a steady state or a skid map (issue 34,
item 2): the file's lubricant, drag, cage and contact law come with it, an input passed
explicitly wins, and nothing falls back to the reference oil or drag while the file gives one."""
import json
import subprocess
import sys
from dataclasses import replace

import pytest

from contact.ballrace import ContactLaw
from exudyn_bearing import (REFERENCE_BEARING, REFERENCE_DRAG, REFERENCE_LUBRICANT, BallDrag, BearingFile, CageModel,
                            load_bearing, loads_bearing, save_bearing, simulate, steady_state)
from exudyn_bearing.bearingfile import FILE_DRAG, FILE_LUBRICANT, dumps_bearing, file_inputs

#: every part differs from the package's default
OIL = replace(REFERENCE_LUBRICANT, viscosity=0.02, limiting_shear_coefficient=0.06)
DRAG = BallDrag(drag_coefficient=0.4, oil_volume_fraction=0.05)
CAGE = CageModel(guidance="inner", guide_clearance=0.3e-3)
LAW = ContactLaw(traction="crook", rolling_resistance=True)
SETUP = BearingFile(REFERENCE_BEARING, OIL, DRAG, CAGE, LAW)


@pytest.fixture
def path(tmp_path):
    p = tmp_path / "my.toml"
    save_bearing(SETUP, p)
    return p


def test_the_file_round_trips_its_contact_law_and_checks_it():
    assert loads_bearing(dumps_bearing(SETUP)) == SETUP
    assert "[contact_law]" not in dumps_bearing(BearingFile(REFERENCE_BEARING))  # the default is not written
    text = dumps_bearing(BearingFile(REFERENCE_BEARING))
    with pytest.raises(ValueError, match=r"contact_law.rolling_resistance must be true or false"):
        loads_bearing(text + "\n[contact_law]\nrolling_resistance = 1\n")
    with pytest.raises(ValueError, match=r"unknown key\(s\) in \[contact_law\]: tracton"):
        loads_bearing(text + "\n[contact_law]\ntracton = \"crook\"\n")
    with pytest.raises(ValueError, match=r"\[contact_law\] traction must be one of"):
        loads_bearing(text + "\n[contact_law]\ntraction = \"dry\"\n")


def test_file_inputs_take_the_files_parts_unless_given(path):
    parts = dict(lubricant=FILE_LUBRICANT, ball_drag=FILE_DRAG)
    assert file_inputs(REFERENCE_BEARING, **parts) == (REFERENCE_BEARING, (REFERENCE_LUBRICANT, REFERENCE_DRAG))
    assert file_inputs(path, **parts) == (REFERENCE_BEARING, (OIL, DRAG))
    assert file_inputs(str(path), **parts) == (REFERENCE_BEARING, (OIL, DRAG))
    assert file_inputs(SETUP, lubricant=FILE_LUBRICANT, ball_drag=None) == (REFERENCE_BEARING, (OIL, None))


def test_a_scene_from_the_file_gets_every_part(path):
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


def test_steady_state_from_the_file_is_the_one_of_its_parts(path):
    from_file = steady_state(path, axial_force=1300.0, rpm=1800.0).to_dict()
    by_parts = steady_state(REFERENCE_BEARING, OIL, axial_force=1300.0, rpm=1800.0, ball_drag=DRAG, cage=CAGE,
                            contact_law=LAW).to_dict()
    reference = steady_state(axial_force=1300.0, rpm=1800.0).to_dict()
    for d in (from_file, by_parts, reference):
        d.pop("wall_time_s")
    assert from_file == by_parts
    assert from_file["kinematic_cage_slip_percent"] != reference["kinematic_cage_slip_percent"]


def test_a_run_from_the_file_records_the_files_parts(path):
    run = simulate(path, axial_force=1300.0, time=0.002)
    assert run.inputs["lubricant"] == repr(OIL) and run.inputs["drag"] == repr(DRAG)
    assert run.inputs["cage"] == repr(CAGE) and run.inputs["contact_law"] == repr(LAW)


def test_the_cli_reads_the_files_contact_law_and_its_options_override_it(path):
    def run(*extra):
        proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", "steady", "--axial", "1300", "--rpm", "1800",
                               "--bearing", str(path), "--json", *extra], capture_output=True, text=True, timeout=600)
        assert proc.returncode == 0, proc.stderr
        return json.loads(proc.stdout)

    assert run()["inputs"]["contact_law"] == repr(LAW)
    assert run("--traction", "crook-limited")["inputs"]["contact_law"] == repr(replace(LAW, traction="crook-limited"))
