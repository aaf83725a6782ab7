"""Issue 34 as its user met it: a 7205-type bearing in the user's own bearing file, through
the CLI and a user's scene script, each in a subprocess as the user runs them (item 8; item
1's scenes are in tests/test_assembly_start.py). The file's oil and drag differ from the
package's defaults, so a silent fallback to the reference oil or drag would show."""
import json
import re
import subprocess
import sys

import pytest

from tests.helpers import BEARING_7205

#: the user's file: 7205 geometry, a thinner oil and a 5 % oil-air drag
USER_FILE = BEARING_7205 + """
[lubricant]
viscosity = 0.02
reference_temperature = 40.0
pressure_viscosity = 1.6e-08
temperature_viscosity = 0.04
thermal_conductivity = 0.14
density = 870.0

[drag]
drag_coefficient = 0.5
oil_volume_fraction = 0.05
"""

#: the user's scene: their file handed to the builder in one call, the README's way
SCENE = """\
import json, sys
import exudyn as exu
import exudyn_bearing
from exudyn_bearing import races

SC = exu.SystemContainer(); mbs = SC.AddSystem()
brg = mbs.CreateAngularContactBearing("my7205.toml", innerRace=races.Driven(rpm=1800), axialForce=300)
inputs = brg.Inputs()
try:
    mbs.CreateAngularContactBearing("my7205.toml", innerRace=races.Driven(rpm=1800), axialForce=-300)
    refused = ""
except ValueError as err:
    refused = str(err)
print(json.dumps({"lubricant": inputs["lubricant"], "drag": inputs["drag"], "refused": refused}))
"""


@pytest.fixture(scope="module")
def user_dir(tmp_path_factory):
    path = tmp_path_factory.mktemp("user")
    (path / "my7205.toml").write_text(USER_FILE)
    (path / "scene.py").write_text(SCENE)
    return path


@pytest.fixture(scope="module")
def scene(user_dir):
    """The user's scene script, run once: what its handle records, and the refusal it met."""
    proc = run(user_dir, "scene.py")
    assert proc.returncode == 0, proc.stderr[-2000:]
    return json.loads(proc.stdout.strip().splitlines()[-1])


def run(user_dir, *args):
    return subprocess.run([sys.executable, *args], cwd=user_dir, capture_output=True, text=True, timeout=600)


@pytest.fixture(scope="module")
def short_run(user_dir):
    """`simulate --bearing my7205.toml --axial 300 --radial 200 --time 0.004`: text and JSON."""
    base = ["-m", "exudyn_bearing", "simulate", "--bearing", "my7205.toml", "--axial", "300", "--radial", "200",
            "--time", "0.004"]
    text = run(user_dir, *base)
    data = run(user_dir, *base, "--json")
    assert text.returncode == 0 and data.returncode == 0, text.stderr[-2000:] + data.stderr[-2000:]
    return text.stdout, json.loads(data.stdout)


def test_item2_the_file_reaches_the_scene_whole(scene):
    out = scene
    assert "viscosity=0.02" in out["lubricant"] and "oil_volume_fraction=0.05" in out["drag"], out


@pytest.mark.slow
def test_item2_and_7_the_cli_run_states_the_files_oil_and_drag(short_run):
    text, data = short_run
    assert data["assumptions"]["oil_volume_fraction"] == 0.05
    assert "viscosity=0.02" in data["inputs"]["lubricant"]
    assert re.search(r"ball drag C_D 0.5 at oil fraction 0.05", text), text


def test_item3_a_short_run_is_too_short_to_judge(short_run):
    text, data = short_run
    assert data["settled"] is None
    assert re.search(r"settled\s+too short to judge", text) and "still drifting" not in text
    assert "settled: the integrator" not in text  # the energy line does not claim it settled


@pytest.mark.slow
def test_item4_commands_agree(user_dir):
    radial_only = run(user_dir, "-m", "exudyn_bearing", "simulate", "--bearing", "my7205.toml", "--radial", "300",
                      "--time", "0.002")
    assert radial_only.returncode == 0, radial_only.stderr[-2000:]
    steady = run(user_dir, "-m", "exudyn_bearing", "steady", "--bearing", "my7205.toml", "--axial", "300", "--radial",
                 "200")
    # steady solves every ball's balance under the combined load (MODEL.md §12a), or says it
    # found none and where to go
    assert steady.returncode in (0, 1) and "Quasi-dynamic state under combined load" in steady.stdout, steady.stderr
    assert steady.returncode == 0 or ("NOT CONVERGED" in steady.stdout and "simulate" in steady.stdout)
    negative = run(user_dir, "-m", "exudyn_bearing", "skid-map", "--bearing", "my7205.toml", "--axial", "-300,300",
                   "--rpm", "1800", "--out", "m")
    assert negative.returncode != 0 and "expected one argument" not in negative.stderr
    assert "axial" in negative.stderr and "other way" in negative.stderr, negative.stderr[-2000:]


def test_item5_the_skid_measure_comes_first(short_run):
    text, data = short_run
    assert text.index("kinematic cage slip") < text.index("paper's P19")
    keys = list(data)
    assert keys.index("kinematic_cage_slip_percent") < keys.index("cage_slip_percent")


def test_item6_a_load_the_other_way_says_how(scene):
    out = scene
    assert "rotationMatrix" in out["refused"] and "+z of the bearing frame" in out["refused"], out["refused"]
