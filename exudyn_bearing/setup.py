"""The bearing setup: one frozen record of everything a bearing file can hold.

A :class:`BearingSetup` carries the bearing (geometry, materials) with its lubricant, ball
drag, cage, contact law, surfaces (defects, waviness; MODEL.md §13) and housing
(MODEL.md §13a). Every function that takes a ``bearing`` takes a setup, a bearing file's
path or a plain :class:`~exudyn_bearing.bearing.Bearing`, and converts it once
(:func:`~exudyn_bearing.bearingfile.as_setup`); an input passed explicitly to that function
replaces the setup's part (``setup.replace(lubricant=...)``). Parts left at :data:`FROM_SETUP` come from the setup,
so nothing a file gives is lost between the file and the kernels.

Example::

    import dataclasses
    from exudyn_bearing import load_bearing, simulate
    setup = load_bearing("my.toml")                 # a BearingSetup
    thinner = setup.replace(lubricant=dataclasses.replace(setup.lubricant, viscosity=0.02))
    simulate(thinner, axial_force=1300, rpm=1800)
"""
from __future__ import annotations

import math

from dataclasses import dataclass, fields
from dataclasses import replace as _replace

from contact.ballrace import ContactLaw
from contact.bearing_thermal import ThermalModel
from contact.lubricant import Lubricant
from contact.surface import SurfaceModel
from .bearing import BallDrag, Bearing
from .cage import CageModel
from .presets import REFERENCE_DRAG, REFERENCE_LUBRICANT
from .races import HousingModel

__all__ = ["BearingSetup", "FROM_SETUP", "refuse_surface", "refuse_thermal"]


class _FromSetup:
    """Default of an input that a :class:`BearingSetup` gives: the setup's part."""

    _instance = None

    def __new__(cls):  # one marker, so that ``is FROM_SETUP`` holds after pickling too
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __reduce__(self):
        return (_FromSetup, ())

    def __repr__(self) -> str:
        return "<the bearing setup's>"


#: default of every input a setup gives: take the setup's (a plain Bearing's: the package default)
FROM_SETUP = _FromSetup()

#: the setup field of each input name (the builder's camelCase and the functions' snake_case)
_ALIASES = {"ball_drag": "drag", "ballDrag": "drag", "contactLaw": "contact_law"}


@dataclass(frozen=True)
class BearingSetup:
    """Everything a bearing file describes (SI units).

    Attributes
    ----------
    bearing : Bearing
        Geometry and materials.
    lubricant : contact.lubricant.Lubricant
        Oil (default: the reference oil, paper table 1).
    drag : BallDrag or None
        Drag on the balls' orbital motion (MODEL.md §8); None: no drag.
    cage : CageModel
        Cage kind, guidance, land and pocket friction (MODEL.md §1, §11d).
    contact_law : contact.ballrace.ContactLaw
        Normal, traction and loss physics of the ball–race contacts (MODEL.md §6, §11).
    surface : contact.surface.SurfaceModel
        Defects, waviness and ball-size variation (MODEL.md §13); perfect by default.
    housing : HousingModel or None
        The outer race on a housing of mass, stiffness and damping (MODEL.md §13a); None:
        a fixed outer race.
    thermal : contact.bearing_thermal.ThermalModel or None
        The thermal network's inputs (MODEL.md §14): oil flow and inlet temperature, ambient,
        ring, housing and shaft sizes; None: every contact at the lubricant's viscosity.
        Used by :func:`~exudyn_bearing.steady_state` and the dynamic model (§14g); refused by those that do not
        model temperatures (:func:`refuse_thermal`).
    """

    bearing: Bearing
    lubricant: Lubricant = REFERENCE_LUBRICANT
    drag: BallDrag | None = REFERENCE_DRAG
    cage: CageModel = CageModel()
    contact_law: ContactLaw = ContactLaw()
    surface: SurfaceModel = SurfaceModel()
    housing: HousingModel | None = None
    thermal: ThermalModel | None = None

    def __post_init__(self) -> None:
        kinds = {"bearing": (Bearing,), "lubricant": (Lubricant,), "drag": (BallDrag, type(None)),
                 "cage": (CageModel,), "contact_law": (ContactLaw,), "surface": (SurfaceModel,),
                 "housing": (HousingModel, type(None)), "thermal": (ThermalModel, type(None))}
        for name, allowed in kinds.items():
            value = getattr(self, name)
            if not isinstance(value, allowed):
                names = " or ".join("None" if t is type(None) else t.__name__ for t in allowed)
                raise ValueError(f"{name} must be a {names}, got {type(value).__name__}")
        flow = 0.0 if self.drag is None else self.drag.oil_flow
        if flow > 0 and self.thermal is not None and not math.isclose(flow, self.thermal.oil_flow, rel_tol=1e-9):
            # one oil: the jet whose momentum the balls supply is the oil that carries the heat
            raise ValueError(f"drag.oil_flow ({flow:g} m^3/s) and thermal.oil_flow ({self.thermal.oil_flow:g} "
                             "m^3/s) are the same jet oil: give them equal")

    def replace(self, **changes) -> "BearingSetup":
        """A copy with ``changes`` (field names, or the builder's ``ballDrag``/``contactLaw``);
        a change left at :data:`FROM_SETUP` keeps the setup's part."""
        known = {f.name for f in fields(self)}
        out = {}
        for name, value in changes.items():
            field_name = _ALIASES.get(name, name)
            if field_name not in known:
                raise ValueError(f"{name}: a bearing setup has no such part (parts: {', '.join(sorted(known))})")
            if value is not FROM_SETUP:
                out[field_name] = value
        return _replace(self, **out) if out else self


def refuse_surface(setup: BearingSetup, where: str, instead: str) -> None:
    """A ValueError naming the surface section a solver without one cannot use (MODEL.md §13):
    a local defect or waviness has no steady or quasi-static state."""
    surface = setup.surface
    parts = (["[[defect]]"] if surface.defects else []) + (["[waviness]"] if surface.waviness.active else [])
    if parts:
        raise ValueError(f"{' and '.join(parts)}: {where} solves a perfect bearing (a defect or waviness has no "
                         f"steady state); run it with {instead}, or give the bearing without its surface "
                         "(setup.replace(surface=SurfaceModel()))")


def refuse_thermal(setup: BearingSetup, where: str) -> None:
    """A ValueError naming the thermal section a command without temperatures cannot use
    (MODEL.md §14: the steady state and the dynamic model solve the network)."""
    if setup.thermal is not None:
        raise ValueError(f"[thermal]: {where} does not model temperatures (the steady state and the dynamic "
                         "model do: steady_state and simulate, or the CLI's 'steady' and 'simulate'); give the "
                         "bearing without its thermal section (setup.replace(thermal=None)) to run it isothermal")
