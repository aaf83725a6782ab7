"""The one conversion from a bearing's setup to the records its ball–race contacts are
computed with (MODEL.md §2–§6, §11, §13).

Both force paths (the numpy functions of :mod:`contact` and the compiled kernels of
:mod:`contact.kernels`), both Jacobian paths and the solvers read the records
:func:`contact_records` builds, so no two of them can convert a bearing, a lubricant or a
law differently: the groove geometry and the numpy path's :class:`~contact.ballrace.RaceContact`,
the per-contact terms (:class:`~contact.terms.TermRecord`, with the surface), and the
compiled path's :class:`~contact.kernels.records.RaceGeometry` and
:class:`~contact.kernels.records.LawRecord` (one per race).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from contact.ballrace import ContactLaw, RaceContact
from contact.kernels.records import CageRecord, LawRecord, RaceGeometry, law_record
from contact.surface import NO_SURFACE, SurfaceRecord
from contact.terms import TermRecord, term_record

__all__ = ["ContactRecords", "contact_records", "cage_record"]


class ContactRecords(NamedTuple):
    """A bearing's ball–race contacts as both force paths read them; contacts in the order of
    one vectorized evaluation: the inner contacts of balls 0…n−1, then their outer ones."""

    tube: tuple  #: groove tube radii ((f_i − ½) D, (f_o − ½) D), m
    #: per contact (groove-centre radius m, groove-centre axial position m, tube radius m),
    #: arrays (2n,) (:func:`contact.kinematics.ball_race_kinematics`)
    grooves: tuple
    signs: np.ndarray  #: (2n,): −1 inner, +1 outer
    races: RaceContact  #: the numpy path's geometry and material per contact (MODEL.md §2–§3)
    terms: TermRecord  #: the per-contact terms, both paths (:mod:`contact.terms`)
    geometry: RaceGeometry  #: the compiled path's geometry and material of both races
    #: the compiled path's law with its lubricant, per race (inner, outer; one record twice
    #: where both races see one oil)
    laws: tuple


def contact_records(bearing, lubricant, law: ContactLaw, balls: int | None = None,
                    surface: SurfaceRecord = NO_SURFACE) -> ContactRecords:
    """The :class:`ContactRecords` of ``bearing`` (a :class:`exudyn_bearing.Bearing`) with
    ``lubricant`` and ``law`` for ``balls`` balls (default: all of the bearing's) and a
    surface record (:func:`contact.surface.surface_record`; none by default)."""
    n = bearing.balls if balls is None else int(balls)
    (r_gi, z_gi), (r_go, z_go) = bearing.groove_centres()
    d = bearing.ball_diameter
    tube = ((bearing.inner_conformity - 0.5) * d, (bearing.outer_conformity - 0.5) * d)
    grooves = (np.repeat([r_gi, r_go], n), np.repeat([z_gi, z_go], n), np.repeat(tube, n))
    signs = np.repeat([-1.0, 1.0], n)
    conformity = np.array([bearing.inner_conformity, bearing.outer_conformity])
    races = RaceContact(d, bearing.pitch_diameter, np.repeat(conformity, n), signs, bearing.effective_modulus,
                        bearing.ball_mass)
    geometry = RaceGeometry(np.array([(r_gi, z_gi, tube[0]), (r_go, z_go, tube[1])], dtype=float), conformity,
                            np.array([-1.0, 1.0]), float(bearing.ball_radius), float(bearing.pitch_diameter),
                            float(bearing.effective_modulus), float(bearing.ball_mass))
    record = law_record(law, lubricant)
    return ContactRecords(tube, grooves, signs, races, term_record(law, lubricant, d, surface), geometry,
                          (record, record))


#: CageModel.kind -> CageRecord.kind
CAGE_KINDS = {"none": 0, "rigid": 1, "spring-chain": 2}


def cage_record(setup, axis, origin) -> CageRecord:
    """The compiled path's :class:`~contact.kernels.records.CageRecord` of ``setup``'s cage and
    ball drag in a bearing frame with ``axis`` (3,) and ``origin`` (3,) m (MODEL.md §1, §8):
    pockets evenly spaced from azimuth 0, the drag's factor 1/2 C_D φ ρ π r² (kg/m; 0: none)
    and the jet momentum's k (kg/s, eq. 11c.2; 0: none),
    the pocket damping of :meth:`~exudyn_bearing.cage.CageModel.damping_for`."""
    bearing, cage, drag = setup.bearing, setup.cage, setup.drag
    drag_factor = drag_linear = 0.0
    if drag is not None and drag.drag_coefficient * drag.oil_volume_fraction > 0:
        drag_factor = (0.5 * drag.drag_coefficient * drag.oil_volume_fraction * setup.lubricant.density * np.pi
                       * bearing.ball_radius ** 2)
    if drag is not None:
        drag_linear = drag.momentum_factor(bearing, setup.lubricant.density)
    pockets = 2 * np.pi * np.arange(bearing.balls) / bearing.balls
    return CageRecord(CAGE_KINDS[cage.kind], pockets, float(bearing.pitch_radius), float(cage.clearance),
                      float(cage.stiffness), float(cage.damping_for(bearing.ball_mass)), axis, origin,
                      float(drag_factor), float(drag_linear))
