"""What a result file carries besides its numbers: the unit of every name and the inputs
that produced it (bearing, lubricant, drag, contact law, package version).

Names follow the Python attributes; a suffix states the unit where the name alone does
not (``_percent``, ``_deg``, ``_s``, ``_W``, ``_K``, ``_Pa_s``, ``_W_per_K``), and :func:`units_of` gives the unit of every
key of a result dictionary (SI; ``'-'``: dimensionless or a count/flag/text).
"""
from __future__ import annotations

#: unit of a result name without a unit suffix
UNITS = {
    "axial": "N", "radial": "N", "rpm": "rev/min", "time": "s", "step": "s", "output_step": "s",
    "simulated_time": "s",
    "cage_speed": "rad/s", "cage_speed_nominal": "rad/s", "kinematic_cage_speed": "rad/s",
    "nominal_cage_speed": "rad/s", "ball_omega": "rad/s",
    "inner_load": "N", "outer_load": "N", "max_inner_load": "N", "max_outer_load": "N",
    "max_inner_slip": "m/s", "peak_ball_slip": "m/s",
    "inner_max_pressure": "Pa", "outer_max_pressure": "Pa",
    "inner_race_shift": "m", "ball_orbit_radius": "m", "ball_axial_position": "m",
    "absolute_tolerance": "N", "relative_tolerance": "-", "reference_step": "s",
    "minimum_axial": "N", "bracket": "N", "steady_curve": "[N, %]", "dynamic_minimum_axial": "N", "dynamic_slips": "%",
    "hirano_minimum_axial": "N", "gyroscopic_minimum_axial": "N",
    # the quasi-static load distribution (LoadDistribution.to_dict)
    "azimuth": "rad", "inner_contact_angle": "rad", "outer_contact_angle": "rad", "inner_deflection": "m",
    "outer_deflection": "m", "ball_radius_offset": "m", "ball_axial_offset": "m", "displacement": "m", "tilt": "rad",
    "reaction_moment": "N m", "centrifugal_force": "N", "cage_force": "N", "race_force": "N", "race_moment": "N m",
    "axial_displacement": "m", "radial_displacement": "m",
    # the quasi-dynamic state (AzimuthStates.to_dict)
    "orbit_radius": "m", "axial_position": "m", "omega": "rad/s", "pocket_force": "N", "cage_offset": "m",
}

#: unit suffixes of result names
SUFFIXES = {"_percent": "%", "_deg": "deg", "_Pa_s": "Pa s", "_W_per_K": "W/K", "_m3_s": "m^3/s", "_us": "us",
            "_ms": "ms", "_s": "s", "_W": "W", "_K": "K", "_m": "m"}


def unit_of(name: str) -> str:
    """Unit of one result name ('-' if none)."""
    for suffix, unit in SUFFIXES.items():
        if name.endswith(suffix):
            return unit
    return UNITS.get(name, "-")


def units_of(data: dict, parent: str | None = None) -> dict:
    """Units of the keys of a result dictionary, nested like it; a nested dictionary under a
    name with a unit suffix (e.g. ``power_loss_W``) takes that unit for all its entries."""
    out = {}
    for key, value in data.items():
        if isinstance(value, dict):
            inherited = unit_of(key) if any(key.endswith(s) for s in SUFFIXES) else None
            out[key] = {k: inherited for k in value} if inherited else units_of(value, key)
        else:
            out[key] = unit_of(key)
    return out


def inputs_record(bearing, **inputs) -> dict:
    """What a result depends on besides its load and speed: the bearing and the other inputs
    given as keywords (lubricant, drag, contact law, settings; their full reprs), and the
    package version."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        package = version("exudyn-bearing")
    except PackageNotFoundError:
        package = "unknown"
    return {"bearing": repr(bearing)} | {k: repr(v) for k, v in inputs.items()} | {"version": package}


def _function_name(function) -> str:
    """module.name of a (numba-compiled) function, without the process's addresses."""
    f = getattr(function, "py_func", function)
    return f"{getattr(f, '__module__', '?')}.{getattr(f, '__qualname__', repr(f))}"


def setup_inputs(setup, **settings) -> dict:
    """:func:`inputs_record` of a :class:`~exudyn_bearing.setup.BearingSetup` and ``settings``:
    every part, the surfaces and housing where the setup has them (a perfect bearing on a
    fixed outer race is recorded as before they existed)."""
    from contact.terms import applied_terms

    extra = {"surface": setup.surface} if setup.surface.active else {}
    if setup.housing is not None:
        extra["housing"] = setup.housing
    if setup.thermal is not None:
        extra["thermal"] = setup.thermal
    registered = applied_terms(setup.contact_law)  # (contact.terms.register_term; none: not recorded)
    if registered:
        extra["registered_terms"] = [f"{name}: {_function_name(term.film_factor)}, "
                                     f"{_function_name(term.contact_loads)}, parameter {term.parameter!r}"
                                     for name, term in registered]
    return inputs_record(setup.bearing, lubricant=setup.lubricant, drag=setup.drag, contact_law=setup.contact_law,
                         cage=setup.cage, **extra, **settings)


def assumptions_record(drag=None, contact_law=None, lubricant=None) -> dict:
    """The physics choices a reader needs beside the numbers (issue 34): the ball drag's
    coefficient, oil volume fraction and jet oil flow (m^3/s; None: no drag), whether rolling resistance and the
    thermal film are on, and the traction law with its lubricant constants."""
    out = {"ball_drag_coefficient": None if drag is None else float(drag.drag_coefficient),
           "oil_volume_fraction": None if drag is None else float(drag.oil_volume_fraction),
           "jet_oil_flow_m3_s": None if drag is None else float(drag.oil_flow)}
    if contact_law is not None:
        out |= {"traction": contact_law.traction, "rolling_resistance": bool(contact_law.rolling_resistance),
                "thermal_film": bool(contact_law.thermal_film)}
        if lubricant is not None:
            out |= {"limiting_shear_coefficient": contact_law.limiting_shear_for(lubricant),
                    "film_shear_modulus_coefficient": contact_law.film_modulus_for(lubricant)}
    return out


def assumptions_line(assumptions: dict) -> str:
    """One line of text for :func:`assumptions_record`."""
    x = assumptions.get("oil_volume_fraction")
    drag = ("no ball drag" if x is None else
            f"ball drag C_D {assumptions['ball_drag_coefficient']:g} at oil fraction {x:g}"
            + (" (fully flooded)" if x == 1 else ""))
    parts = [drag]
    if assumptions.get("jet_oil_flow_m3_s"):
        parts.append(f"jet oil momentum at {assumptions['jet_oil_flow_m3_s'] * 6e7:g} cm3/min")
    if "rolling_resistance" in assumptions:
        parts.append(f"rolling resistance {'on' if assumptions['rolling_resistance'] else 'off'}")
        parts.append(f"thermal film {'on' if assumptions['thermal_film'] else 'off'}")
        parts.append(f"traction {assumptions['traction']}")
    return "; ".join(parts)
