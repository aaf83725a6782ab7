"""Parameter records of the compiled kernels: typed named tuples numba compiles like structs.

A kernel takes a few records instead of long positional lists. Records hold SI values and
numpy arrays; numba types each field once, so a field costs nothing at run time. At the
Python-to-compiled boundary of a hot call, pass ``tuple(record)`` and rebuild the record
inside (``RaceGeometry(*geometry)``): numba types a plain tuple in its C fast path, a named
tuple in Python (~1.5 us a record per call, measured with numba 0.68).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..traction_laws import traction_model

__all__ = ["BallStates", "BodyStates", "CageRecord", "ContactOutputs", "CrookScratch", "CrookTables", "LawRecord",
           "RaceFrames", "RaceGeometry", "law_record", "traction_record"]


class RaceGeometry(NamedTuple):
    """Both races' contact geometry and material (MODEL.md §2–§3); index 0 inner, 1 outer."""

    groove: np.ndarray  #: (2, 3): groove-centre radius, axial position (race frame), (f − 1/2) D; m
    conformity: np.ndarray  #: (2,): f, groove radius / D
    sign: np.ndarray  #: (2,): −1 inner, +1 outer (:func:`contact.geometry.curvature_radii`)
    ball_radius: float  #: m
    pitch_diameter: float  #: m
    e_prime: float  #: E', Pa
    ball_mass: float  #: kg (normal contact damping)


class LawRecord(NamedTuple):
    """A :class:`contact.ballrace.ContactLaw` with its lubricant, as the kernels read it."""

    traction: int  #: 0: normal forces only; 1: Crook by the fast rule
    spin_moment: bool  #: apply M_z (P16)
    damping_ratio: float  #: normal contact damping, fraction of critical
    min_film: float  #: floor on the film thickness, m
    eta0: float  #: η0, Pa s
    c_p: float  #: c_ηP, 1/Pa
    max_barus: float  #: bound on c_ηP p_max of the traction
    c1_coef: float  #: c_ηT / (8 K_c) of the Crook law, m/W (MODEL.md §6)
    limiting_shear: float  #: Λ of the smooth cap (§6a); 0: none
    film_modulus: float  #: κ = G/p of the film's elastic compliance (§6b); 0: none


class CrookTables(NamedTuple):
    """The fast rule's node tables (:func:`contact.kernels.crook.crook_tables`)."""

    cos_psi: np.ndarray  #: cosine of the ray angles (n_rays, n_eps)
    sin_psi: np.ndarray  #: sine of the ray angles
    wpsi: np.ndarray  #: ray weights
    rho32: np.ndarray  #: radial nodes, float32
    w32: np.ndarray  #: radial weights, float32
    rho64: np.ndarray  #: radial nodes, float64 (same values)
    w64: np.ndarray  #: radial weights, float64


class BallStates(NamedTuple):
    """The balls of B states, GLOBAL frame: (B, Z, 3) each."""

    position: np.ndarray  #: centres, m
    velocity: np.ndarray  #: m/s
    omega: np.ndarray  #: angular velocities, rad/s
    #: body-to-global rotations (B, Z, 3, 3), read only for a ball's own surface (a pit or
    #: waviness, contact.ball_surface, eq. 13.3, 13.6); (B, 0, 3, 3) otherwise
    rotation: np.ndarray


class BodyStates(NamedTuple):
    """One rigid body (the cage) in B states, GLOBAL frame."""

    position: np.ndarray  #: (B, 3), m
    rotation: np.ndarray  #: (B, 3, 3)
    velocity: np.ndarray  #: (B, 3), m/s
    omega: np.ndarray  #: (B, 3), rad/s


class RaceFrames(NamedTuple):
    """The inner (index 0) and outer (1) race frames of B states."""

    origin: np.ndarray  #: (B, 2, 3), m
    rotation: np.ndarray  #: (B, 2, 3, 3); third column: the axis
    velocity: np.ndarray  #: origin velocity (B, 2, 3), m/s
    omega: np.ndarray  #: angular velocity (B, 2, 3), rad/s


class ContactOutputs(NamedTuple):
    """What :func:`contact.kernels.race.race_contacts` writes, per state, race and ball."""

    force: np.ndarray  #: (B, 2, Z, 3): on each ball at its contact with race k, N
    moment: np.ndarray  #: (B, 2, Z, 3): about the ball centre, N m
    penetration: np.ndarray  #: (B, 2, Z): elastic approach δ, m
    load: np.ndarray  #: (B, 2, Z): normal load Q, N
    #: (B, 2, Z, 4): the traction's f_x, f_y (N), M_z (N m) on the ball and its heat (W),
    #: as :func:`contact.ballrace.ball_race_forces` reports them (zeros where none acts)
    traction: np.ndarray


class CrookScratch(NamedTuple):
    """Work arrays of :func:`contact.kernels.crook.crook_one`, made once per loop over contacts
    (:func:`contact.kernels.crook.crook_scratch`; one per thread) instead of once per contact
    (seven heap allocations, ~9 % of a 32-contact evaluation). The rays' float32 rows keep
    zeros beyond the last ray: padding rays (to a whole number of vectors,
    :data:`contact.kernels.crook.LANES`) have ρ_max = 0."""

    geo: np.ndarray  #: (8, rays) float64: each ray's geometry
    ray4: np.ndarray  #: (4, padded rays) float32: the rule's ray constants
    ray6: np.ndarray  #: (6, padded rays) float32: with the rays' directions (film elasticity)
    sums: np.ndarray  #: (3, padded rays) float32: Σ g W ρ^j per ray
    elastic: np.ndarray  #: (7,) float64: the film elasticity's constants
    elastic32: np.ndarray  #: (7,) float32: the same in float32
    wide: np.ndarray  #: (8,) float64: a ray's constants for its float64 sums


class CageRecord(NamedTuple):
    """Cage and ball drag of :func:`contact.kernels.cage.cage_and_drag` (MODEL.md §1, §8, P9–P10)."""

    kind: int  #: 0: none; 1: rigid cage pockets; 2: spring chain (P9/P10)
    pocket_angles: np.ndarray  #: (Z,): pocket azimuths in the cage frame, rad
    pitch_radius: float  #: m
    clearance: float  #: pocket clearance, m
    stiffness: float  #: N/m (spring chain: per unit arc, as :func:`contact.cage.spring_chain_forces`)
    damping: float  #: N s/m
    axis: np.ndarray  #: (3,): bearing axis
    origin: np.ndarray  #: (3,): bearing centre, m
    drag_factor: float  #: 1/2 C_D ρ π r² (times the oil fraction), kg/m; 0: no drag
    drag_linear: float = 0.0  #: the jet oil's momentum factor k (MODEL.md eq. 11c.2), kg/s; 0: none


def traction_record(lubricant, limiting_shear=None, film_modulus=None) -> LawRecord:
    """A :class:`LawRecord` for the traction alone (:func:`contact.kernels.crook.crook_one`):
    ``lubricant`` with Λ and κ (None: none)."""
    return LawRecord(1, True, 0.0, 0.0, float(lubricant.viscosity), float(lubricant.pressure_viscosity), 0.0,
                     lubricant.shear_heating / 8.0,
                     float(limiting_shear or 0.0), float(film_modulus or 0.0))


def law_record(law, lubricant) -> LawRecord:
    """The :class:`LawRecord` of a :class:`contact.ballrace.ContactLaw` with ``lubricant``."""
    base = traction_record(lubricant, law.limiting_shear_for(lubricant), law.film_modulus_for(lubricant))
    kernel = traction_model(law.traction).kernel  # None: the law runs on the numpy path
    return base._replace(traction=kernel or 0, spin_moment=bool(law.spin_moment),
                         damping_ratio=float(law.damping_ratio), min_film=float(law.min_film_thickness),
                         max_barus=float(law.max_barus_exponent))
