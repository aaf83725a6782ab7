"""Bearing description, reference preset and TOML files."""
import dataclasses
import math

import pytest

from exudyn_bearing import (REFERENCE_BEARING, Bearing, BearingFile, Material, dumps_bearing,
                            loads_bearing)
from contact.lubricant import Lubricant

EXAMPLE = """
[bearing]
balls = 6
ball_diameter = 11.1e-3
pitch_diameter = 43.5e-3
inner_groove_radius = 5.772e-3
outer_groove_radius = 5.883e-3
diametral_clearance = 10e-6
[material]
youngs_modulus = 210e9
poisson_ratio = 0.3
density = 7850
[lubricant]
viscosity = 0.04
reference_temperature = 30.0
pressure_viscosity = 1.75e-8
temperature_viscosity = 0.05
thermal_conductivity = 0.14
density = 860
"""


def test_reference_preset_matches_paper_table():
    b = REFERENCE_BEARING
    assert (b.balls, b.ball_radius, b.pitch_radius, b.ball_mass) == (16, 12.5e-3, 77.5e-3, 0.064)
    assert math.degrees(b.contact_angle) == pytest.approx(40.0)
    # 64 g is what steel gives for a 25 mm ball
    assert 7850 * math.pi * 0.025 ** 3 / 6 == pytest.approx(0.064, rel=0.01)


def test_example_file_parses_and_derives_angle_and_mass():
    setup = loads_bearing(EXAMPLE)
    b = setup.bearing
    assert b.inner_conformity == pytest.approx(0.52) and b.outer_conformity == pytest.approx(0.53)
    # cos a0 = 1 - P_d / (2 (f_i + f_o - 1) D)
    assert math.cos(b.contact_angle) == pytest.approx(1 - 10e-6 / (2 * 0.05 * 11.1e-3), rel=1e-12)
    assert b.ball_mass == pytest.approx(7850 * math.pi * 11.1e-3 ** 3 / 6, rel=1e-12)
    assert isinstance(setup.lubricant, Lubricant) and setup.lubricant.density == 860


def test_round_trip_every_field():
    b = dataclasses.replace(REFERENCE_BEARING, balls=13, inner_conformity=0.515, outer_conformity=0.53,
                            race_material=Material(200e9, 0.29, 7800.0), ball_mass=0.0655)
    setup = BearingFile(b, Lubricant(0.03, 40.0, 2e-8, 0.04, 0.13, 870.0))
    again = loads_bearing(dumps_bearing(setup))
    assert again == setup
    example = loads_bearing(EXAMPLE)
    assert loads_bearing(dumps_bearing(example)) == example
    # a cage other than the default: [cage], words and numbers, None-valued keys left out
    from exudyn_bearing.cage import CageModel

    caged = BearingFile(b, cage=CageModel(guidance="inner", guide_clearance=0.3e-3, land_width=5e-3,
                                          pocket_friction=0.15, mass=0.05))
    text = dumps_bearing(caged)
    assert '[cage]' in text and 'guidance = "inner"' in text and "damping" not in text.split("[cage]")[1]
    assert loads_bearing(text) == caged
    assert "[cage]" not in dumps_bearing(setup)  # the default cage is not written


def test_bad_cage_section_names_the_key():
    with pytest.raises(ValueError, match=r"\[cage\] pocket_friction"):
        loads_bearing(EXAMPLE + "\n[cage]\npocket_friction = -0.1\n")
    with pytest.raises(ValueError, match="cage.guidance must be a string"):
        loads_bearing(EXAMPLE + "\n[cage]\nguidance = 1\n")
    with pytest.raises(ValueError, match="unknown key.*pocket_mu"):
        loads_bearing(EXAMPLE + "\n[cage]\npocket_mu = 0.1\n")


BASE = dict(balls=16, ball_diameter=25e-3, pitch_diameter=155e-3, inner_conformity=0.52,
            outer_conformity=0.52, contact_angle=math.radians(40))


@pytest.mark.parametrize("field,value", [
    ("inner_conformity", 0.5), ("outer_conformity", 0.49), ("ball_diameter", -1e-3),
    ("ball_diameter", float("nan")), ("pitch_diameter", 0.0), ("contact_angle", math.radians(90)),
    ("contact_angle", -0.1), ("balls", 2), ("balls", 40), ("ball_mass", -1.0)])
def test_bad_bearing_input_names_parameter(field, value):
    kwargs = dict(BASE, **{field: value})
    with pytest.raises(ValueError, match=field):
        Bearing(**kwargs)


def test_bad_material_and_file_input():
    with pytest.raises(ValueError, match="poisson_ratio"):
        Material(210e9, 0.6, 7850)
    with pytest.raises(ValueError, match="unknown key.*colour"):
        loads_bearing(EXAMPLE.replace("balls = 6", "balls = 6\ncolour = 3"))
    with pytest.raises(ValueError, match="unknown section"):
        loads_bearing(EXAMPLE + "\n[extra]\nx = 1\n")
    with pytest.raises(ValueError, match="diametral_clearance"):
        loads_bearing(EXAMPLE.replace("diametral_clearance = 10e-6", "diametral_clearance = -1e-6"))
    with pytest.raises(ValueError, match="contact_angle or diametral_clearance"):
        loads_bearing(EXAMPLE.replace("diametral_clearance = 10e-6", "contact_angle = 30.0\ndiametral_clearance = 1e-6"))
