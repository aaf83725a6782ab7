"""Bearing files (TOML, SI units, angles in degrees) that round-trip every field.

Example::

    [bearing]
    balls = 16
    ball_diameter = 25e-3
    pitch_diameter = 155e-3
    inner_conformity = 0.52          # or inner_groove_radius = 13e-3 (m)
    outer_conformity = 0.52          # or outer_groove_radius = 13e-3 (m)
    contact_angle = 40.0             # free angle, degrees; or diametral_clearance (m)
    ball_mass = 0.064                # optional; else from the ball material density
    [material]                       # ball and races; [ball_material]/[race_material] override
    youngs_modulus = 210e9
    poisson_ratio = 0.3
    density = 7850
    [lubricant]                      # optional; reference oil if absent
    viscosity = 0.04
    reference_temperature = 30.0     # degC
    pressure_viscosity = 1.75e-8
    temperature_viscosity = 0.05
    thermal_conductivity = 0.14
    density = 860
    limiting_shear_coefficient = 0.047   # tau_L / p (MODEL.md §6a); 0: no limit
    film_shear_modulus_coefficient = 0.2953  # G / p of the film (MODEL.md §6b)
    [drag]                           # optional; fully flooded sphere drag if absent
    drag_coefficient = 0.5
    oil_volume_fraction = 1.0
    oil_flow = 0.0                   # m^3/s of jet oil; > 0: its momentum loss (MODEL.md §11c)
    [cage]                           # optional; CageModel() if absent (MODEL.md §1, §11d)
    kind = "rigid"                   # or "spring-chain", "none"
    guidance = "outer"               # or "inner", "balls"
    guide_clearance = 0.4e-3         # diametral land play, m
    land_width = 0.0                 # m; > 0: the land's oil film (friction torque and radial force)
    land_film = true                 # false: the film's friction torque only, no radial force
    pocket_friction = 0.0            # ball-pocket friction coefficient
    [contact_law]                    # optional; ContactLaw() if absent (MODEL.md §6, §11)
    traction = "crook-limited"       # or "crook" (the paper's law), "newtonian", "coulomb", "none"
    rolling_resistance = false
    thermal_film = false
    [[defect]]                       # optional, any number (MODEL.md §13): a spall or notch
    race = "outer"                   # or "inner" (turns with the inner race)
    angle_deg = 0.0                  # centre, in the race's own frame
    length = 0.18e-3                 # along the rolling direction, m
    depth = 0.28e-3                  # m
    width = 1e-3                     # across the raceway, m; absent: the whole raceway
    shape = "rectangle"              # or "ellipse" (a round pit; width absent: width = length)
    [[defect]]                       # a pit on a ball: round, `length` its diameter
    race = "ball"
    ball = 3                         # which ball, 0 .. Z - 1
    angle_deg = 0.0                  # from the ball's outer contact at the start, about its spin axis
    length = 0.5e-3
    depth = 10e-6
    [waviness]                       # optional: [order, amplitude_m, phase_deg] per line
    outer = [[17, 0.2e-6, 0.0]]
    inner = []
    ball_diameter_variation = []     # m per ball (> 0 oversize)
    ball = [[0, 6, 0.1e-6, 0.0]]     # [ball, order, amplitude_m, phase_deg]: a ball's waviness

    [housing]                        # optional: the outer race on a housing (MODEL.md §13a)
    frequency = 3000.0               # resonance, Hz (or stiffness = ... N/m)
    mass = 2.0                       # kg, ring included
    damping_ratio = 0.05             # of critical

    [thermal]                        # optional: the thermal network (MODEL.md §14): steady, simulate
    oil_flow = 1.27e-5               # m^3/s through the bearing
    oil_inlet_temperature = 394.0    # K; absent: the lubricant's reference temperature
    ambient_temperature = 293.15     # K
    bore = 35e-3                     # m; absent: estimated (outside_diameter, width likewise)
    ring_expansion = 11.9e-6         # 1/K (ball_expansion likewise); from assembly_temperature, 293.15 K

A file reads into a :class:`~exudyn_bearing.setup.BearingSetup`. A function that takes a
``bearing`` takes it too, or its path, and then every part the file gives unless that part
is passed explicitly (:func:`as_setup`); a part a function cannot use is refused by name.
"""
from __future__ import annotations

import math
import os
from dataclasses import fields
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from contact.ballrace import ContactLaw
from contact.bearing_thermal import ThermalModel
from contact.lubricant import Lubricant
from .bearing import BallDrag, Bearing, Material
from .cage import CageModel
from contact.surface import Defect, SurfaceModel, Waviness
from .presets import REFERENCE_DRAG, REFERENCE_LUBRICANT
from .races import HousingModel
from .setup import BearingSetup

__all__ = ["BearingFile", "as_setup", "load_bearing", "loads_bearing", "dumps_bearing", "save_bearing"]


#: the name bearing files were read into before the setup record (issue 48); the same class
BearingFile = BearingSetup


def as_setup(bearing, **given) -> BearingSetup:
    """The :class:`BearingSetup` of a function's ``bearing`` argument — a setup, a plain
    :class:`Bearing` (the package defaults for the other parts) or a bearing file's path —
    with the inputs ``given`` explicitly (not ``FROM_SETUP``) in place of its parts.
    The one conversion every entry point makes."""
    if isinstance(bearing, (str, os.PathLike)):
        try:
            setup = load_bearing(bearing)
        except OSError as err:
            raise ValueError(f"bearing: cannot read the bearing file {str(bearing)!r} ({err.strerror or err}); "
                             "give a Bearing, a BearingSetup or a bearing file's path") from None
    elif isinstance(bearing, BearingSetup):
        setup = bearing
    elif isinstance(bearing, Bearing):
        setup = BearingSetup(bearing)
    else:
        raise ValueError(f"bearing must be a Bearing, a BearingSetup or a bearing file's path, "
                         f"got {type(bearing).__name__}")
    return setup.replace(**given)


_SECTIONS = {"bearing", "material", "ball_material", "race_material", "lubricant", "drag", "cage", "contact_law",
             "defect", "waviness", "housing", "thermal"}
#: [cage] keys whose values are words, not numbers, and those that are true or false
_CAGE_WORDS = {"kind", "guidance"}
_CAGE_FLAGS = {f.name for f in fields(CageModel) if f.type == "bool"}
#: [contact_law] keys whose values are words, and those that are true or false: from the
#: ContactLaw's own fields, so a new switch of the law is a key of the file without an edit here
_LAW_WORDS = {f.name for f in fields(ContactLaw) if f.type == "str"}
_LAW_FLAGS = {f.name for f in fields(ContactLaw) if f.type in ("bool", "bool | None")}
_BEARING_KEYS = {"balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity",
                 "inner_groove_radius", "outer_groove_radius", "contact_angle", "diametral_clearance",
                 "ball_mass"}


def _table(data: dict, name: str, allowed: set[str], words=frozenset(), flags=frozenset()) -> dict:
    table = data.get(name, {})
    if not isinstance(table, dict):
        raise ValueError(f"[{name}] must be a table")
    unknown = set(table) - allowed
    if unknown:
        raise ValueError(f"unknown key(s) in [{name}]: {', '.join(sorted(unknown))} "
                         f"(allowed: {', '.join(sorted(allowed))})")
    for key, value in table.items():
        if key in words:
            if not isinstance(value, str):
                raise ValueError(f"{name}.{key} must be a string, got {value!r}")
        elif key in flags:
            if not isinstance(value, bool):
                raise ValueError(f"{name}.{key} must be true or false, got {value!r}")
        elif isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"{name}.{key} must be a number, got {value!r}")
    return dict(table)


def _one_of(table: dict, a: str, b: str) -> str:
    present = [k for k in (a, b) if k in table]
    if len(present) != 1:
        raise ValueError(f"[bearing] needs exactly one of {a} or {b}, got {present or 'neither'}")
    return present[0]


def _dataclass_from(cls, data: dict, name: str):
    allowed = {f.name for f in fields(cls)}
    return cls(**_table(data, name, allowed)) if name in data else None


def loads_bearing(text: str) -> BearingSetup:
    """Parse a bearing file from a TOML string; unknown sections or keys raise ValueError."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise ValueError(f"bearing file is not valid TOML: {err}") from None
    unknown = set(data) - _SECTIONS
    if unknown:
        raise ValueError(f"unknown section(s) {', '.join(sorted(unknown))} (allowed: {', '.join(sorted(_SECTIONS))})")
    if "bearing" not in data:
        raise ValueError("bearing file needs a [bearing] section")
    b = _table(data, "bearing", _BEARING_KEYS)
    material = _dataclass_from(Material, data, "material") or Material()
    kwargs = dict(
        balls=b.get("balls"),
        ball_diameter=b.get("ball_diameter"),
        pitch_diameter=b.get("pitch_diameter"),
        ball_material=_dataclass_from(Material, data, "ball_material") or material,
        race_material=_dataclass_from(Material, data, "race_material") or material,
        ball_mass=b.get("ball_mass"),
    )
    for name in ("balls", "ball_diameter", "pitch_diameter"):
        if kwargs[name] is None:
            raise ValueError(f"[bearing] needs {name}")
    if isinstance(kwargs["balls"], float):
        raise ValueError(f"balls must be an integer, got {kwargs['balls']!r}")
    for race in ("inner", "outer"):
        key = _one_of(b, f"{race}_conformity", f"{race}_groove_radius")
        value = b[key]
        if key.endswith("groove_radius"):
            if not kwargs["ball_diameter"] > 0:
                raise ValueError(f"ball_diameter must be positive, got {kwargs['ball_diameter']!r}")
            value = value / kwargs["ball_diameter"]
        kwargs[f"{race}_conformity"] = value
    if _one_of(b, "contact_angle", "diametral_clearance") == "contact_angle":
        bearing = Bearing(contact_angle=math.radians(b["contact_angle"]), **kwargs)
    else:
        bearing = Bearing.from_clearance(diametral_clearance=b["diametral_clearance"], **kwargs)
    lubricant = _dataclass_from(Lubricant, data, "lubricant") or REFERENCE_LUBRICANT
    drag = _dataclass_from(BallDrag, data, "drag") or REFERENCE_DRAG
    cage = CageModel()
    if "cage" in data:
        table = _table(data, "cage", {f.name for f in fields(CageModel)}, _CAGE_WORDS, _CAGE_FLAGS)
        try:
            cage = CageModel(**table)
        except ValueError as err:
            raise ValueError(f"[cage] {err}") from None
    law = ContactLaw()
    if "contact_law" in data:
        table = _table(data, "contact_law", {f.name for f in fields(ContactLaw)}, _LAW_WORDS, _LAW_FLAGS)
        try:
            law = ContactLaw(**table)
        except ValueError as err:
            raise ValueError(f"[contact_law] {err}") from None
    parts = {}
    for name, cls in (("housing", HousingModel), ("thermal", ThermalModel)):  # None where absent
        try:
            parts[name] = _dataclass_from(cls, data, name)
        except ValueError as err:
            raise ValueError(f"[{name}] {err}") from None
    return BearingSetup(bearing, lubricant, drag, cage, law, _surface(data), **parts)


def _surface(data: dict) -> SurfaceModel:
    """The [[defect]] tables and the [waviness] section (MODEL.md §13)."""
    defects = data.get("defect", [])
    if not isinstance(defects, list):
        raise ValueError("defect: write each defect as a [[defect]] table")
    allowed = {f.name for f in fields(Defect)}
    records = []
    for i, table in enumerate(defects):
        if not isinstance(table, dict):
            raise ValueError("defect: write each defect as a [[defect]] table")
        table = _table({"defect": table}, "defect", allowed, {"race", "shape"})
        missing = {"race", "angle_deg", "length", "depth"} - set(table)
        if missing:
            raise ValueError(f"[[defect]] number {i + 1} needs {', '.join(sorted(missing))}")
        try:
            records.append(Defect(**table))
        except ValueError as err:
            raise ValueError(f"[[defect]] number {i + 1}: {err}") from None
    waviness = Waviness()
    if "waviness" in data:
        table = data["waviness"]
        if not isinstance(table, dict):
            raise ValueError("[waviness] must be a table")
        unknown = set(table) - {f.name for f in fields(Waviness)}
        if unknown:
            raise ValueError(f"unknown key(s) in [waviness]: {', '.join(sorted(unknown))} "
                             "(allowed: ball, ball_diameter_variation, inner, outer)")
        for key, value in table.items():
            if not isinstance(value, list):
                raise ValueError(f"waviness.{key} must be a list, got {value!r}")
            if key != "ball_diameter_variation" and not all(isinstance(row, list) for row in value):
                entry = "[ball, order, amplitude_m, phase_deg]" if key == "ball" else "[order, amplitude_m, phase_deg]"
                raise ValueError(f"waviness.{key}: each entry is {entry}, got {value!r}")
        waviness = Waviness(**{k: tuple(tuple(r) if isinstance(r, list) else r for r in v) for k, v in table.items()})
    return SurfaceModel(tuple(records), waviness)


def _surface_text(surface: SurfaceModel) -> str:
    text = ""
    for d in surface.defects:
        text += "\n" + _section("[defect]", d) + "\n"
    w = surface.waviness
    if w != Waviness():
        rows = {k: "[" + ", ".join(f"[{o}, {a!r}, {p!r}]" for o, a, p in getattr(w, k)) + "]" for k in ("inner", "outer")}
        balls = "[" + ", ".join(f"[{j}, {o}, {a!r}, {p!r}]" for j, o, a, p in w.ball) + "]"
        text += (f"\n[waviness]\ninner = {rows['inner']}\nouter = {rows['outer']}\n"
                 f"ball_diameter_variation = [{', '.join(repr(v) for v in w.ball_diameter_variation)}]\n"
                 f"ball = {balls}\n")
    return text


def load_bearing(path) -> BearingSetup:
    """Read a bearing file (see the module docstring for the format)."""
    return loads_bearing(Path(path).read_text(encoding="utf-8"))


def _section(name: str, obj) -> str:
    lines = [f"[{name}]"]
    for f in fields(obj):
        value = getattr(obj, f.name)
        if value is None and f.default is None:  # TOML has no null: an absent key takes the default
            continue
        if value is None:
            raise ValueError(f"{name}.{f.name} = None has no TOML form (its default is {f.default!r})")
        if isinstance(value, str):
            text = f'"{value}"'
        else:  # TOML writes true/false
            text = str(value).lower() if isinstance(value, bool) else repr(value)
        lines.append(f"{f.name} = {text}")
    return "\n".join(lines)


def _degrees_exact(angle: float) -> float:
    """Degrees value whose math.radians() gives back ``angle`` bit for bit (the plain
    conversion is off by one ulp for some angles)."""
    deg = math.degrees(angle)
    for candidate in (deg, *(math.nextafter(deg, d) for d in (math.inf, -math.inf))):
        if math.radians(candidate) == angle:
            return candidate
    return deg


def dumps_bearing(setup: BearingSetup | Bearing) -> str:
    """TOML text for a bearing (and lubricant, drag, and a cage and contact law other than the
    defaults).

    :func:`loads_bearing` inverts it exactly, except that a free contact angle that no
    float number of degrees maps onto (about 1 in 10 arbitrary radian values) comes back
    within one ulp; a bearing read from a file always round-trips bit for bit.
    """
    if isinstance(setup, Bearing):
        setup = BearingSetup(setup)
    b = setup.bearing
    parts = ["[bearing]", f"balls = {b.balls}", f"ball_diameter = {b.ball_diameter!r}",
             f"pitch_diameter = {b.pitch_diameter!r}", f"inner_conformity = {b.inner_conformity!r}",
             f"outer_conformity = {b.outer_conformity!r}",
             f"contact_angle = {_degrees_exact(b.contact_angle)!r}  # free contact angle, degrees"]
    parts.append(f"ball_mass = {b.ball_mass!r}")
    text = "\n".join(parts) + "\n\n"
    if b.ball_material == b.race_material:
        text += _section("material", b.ball_material) + "\n\n"
    else:
        text += _section("ball_material", b.ball_material) + "\n\n" + _section("race_material", b.race_material) + "\n\n"
    if setup.drag is None:
        raise ValueError("drag: a setup without ball drag (drag=None) has no bearing-file form; pass "
                         "ball_drag=None to the command instead")
    text += _section("lubricant", setup.lubricant) + "\n\n" + _section("drag", setup.drag) + "\n"
    if setup.cage != CageModel():
        text += "\n" + _section("cage", setup.cage) + "\n"
    if setup.contact_law != ContactLaw():
        text += "\n" + _section("contact_law", setup.contact_law) + "\n"
    if setup.housing is not None:
        text += "\n" + _section("housing", setup.housing) + "\n"
    if setup.thermal is not None:
        text += "\n" + _section("thermal", setup.thermal) + "\n"
    return text + _surface_text(setup.surface)


def save_bearing(setup: BearingSetup | Bearing, path) -> None:
    """Write a bearing file."""
    Path(path).write_text(dumps_bearing(setup), encoding="utf-8")
