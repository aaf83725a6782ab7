"""Per-contact terms: the one place where physics beyond the normal load and the traction
rule enters a ball–race contact (the extension point; docs/ARCHITECTURE.md has a worked
example).

A term is a scalar law in its own module, written once as a numba function (e.g.
:func:`contact.thermal_film.film_factor`, :func:`contact.rolling_resistance.rolling_loads`),
and a field of :class:`TermRecord` holding its parameters (0: off). Both force paths call
the stages below for every loaded contact — the compiled kernel
(:func:`contact.kernels.race.race_contacts`) directly, the numpy path
(:func:`contact.ballrace.ball_race_forces`) through :func:`contact_terms` — so a term is
computed once, by the same code, in both. The stages, in the order a contact is evaluated:

0. :func:`surface_height` — the race surface's height toward the ball at the contact (defects,
   waviness, ball-size variation, §13), and :func:`ball_surface_height` the ball's (a pit on
   the ball, which turns with the ball's material): added to the elastic approach before Hertz;
1. :func:`film_factor` — a factor on the isothermal central film h (the thermal film, §11e);
2. :func:`contact_loads` — forces and couples added on the ball (the rolling resistance,
   §11b): a force along the rolling direction t1 at the contact point and a couple about
   the transverse axis t2; the race takes the opposite.

A term that is off costs one comparison per contact.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import literal_unroll, njit
from numba.extending import overload

# the stages call the term laws of other files (a new term's too): contact/__init__.py drops
# this module's numba cache when any of them changed
from .rolling_resistance import hydrodynamic_force, rolling_loads
from .ball_surface import ball_height
from .surface import NO_SURFACE, SurfaceRecord, race_height
from .thermal_film import film_factor as thermal_film_factor

__all__ = ["TermRecord", "ContactState", "Term", "TERMS", "register_term", "applied_terms", "term_record", "surface_height",
           "ball_surface_height", "film_factor", "contact_loads", "contact_terms", "surface_terms", "plain_terms",
           "terms_from_plain", "no_film_factor", "no_contact_loads"]

#: floor of the thermal film factor φ_T (MODEL.md §11e)
THERMAL_FLOOR = 0.05


class TermRecord(NamedTuple):
    """Parameters of the per-contact terms; a term whose parameter is 0 is off.

    The one record field (``surface``) comes first, the scalar parameters after it and the
    registered terms last: so the record crosses into compiled code as a plain tuple (and
    numba's parallel loop as a flat one, :mod:`contact.kernels.race`) and back without naming
    its fields (:func:`plain_terms`, :func:`terms_from_plain`), and a new term is one more
    field here, before ``registered``, with its default, and its value in :func:`term_record`.
    """

    surface: SurfaceRecord  #: defects, waviness, ball sizes (MODEL.md §13); empty arrays: off
    heating: float = 0.0  #: c_ηT / K_c of the thermal film factor (MODEL.md §11e), m/W
    rolling_width: float = 0.0  #: truncation width 𝓛 of the rolling resistance (MODEL.md §11b, the ball diameter), m
    #: the registered terms (:func:`register_term`) that apply to this contact law, as :class:`Term`
    registered: tuple = ()

    @property
    def per_contact(self) -> bool:
        """Whether a stage-1 or stage-2 term is on (the surface is stage 0)."""
        return self.heating > 0.0 or self.rolling_width > 0.0 or len(self.registered) > 0


@njit(cache=True, error_model="numpy")
def no_film_factor(parameter, cs):
    """A registered term's stage 1 when it has none: the factor 1."""
    return 1.0


@njit(cache=True, error_model="numpy")
def no_contact_loads(parameter, cs, phi):
    """A registered term's stage 2 when it has none: no force, no couple."""
    return 0.0, 0.0


class Term(NamedTuple):
    """A per-contact term registered from outside this module (:func:`register_term`): its
    two stages as numba-compiled functions of its ``parameter`` and the contact's
    :class:`ContactState` — ``film_factor(parameter, cs)`` a factor on the film thickness,
    ``contact_loads(parameter, cs, phi)`` (force on the ball along t1 N, couple about t2 N m)
    at film factor ``phi`` — like the built-in stages below."""

    film_factor: object = no_film_factor
    contact_loads: object = no_contact_loads
    parameter: float = 0.0


#: the registered terms by name: (:class:`Term`, which contact laws it applies to: a function
#: of the :class:`contact.ballrace.ContactLaw`, or None for every Crook law)
TERMS: dict = {}


def register_term(name: str, term: Term, applies=None) -> None:
    """Add a per-contact term to every contact evaluated from now on, in both force paths and
    the Jacobian, for the Crook laws (``applies(law)`` True, if given). Its functions must be
    numba-compiled (``@njit``); the kernels are compiled once more for each set of
    registered terms. Remove it with ``del TERMS[name]``."""
    if not isinstance(term, Term):
        raise ValueError(f"register_term takes a contact.terms.Term, got {term!r}")
    if name in TERMS:
        raise ValueError(f"a term {name!r} is registered already")
    TERMS[name] = (term, applies)


def applied_terms(law) -> tuple:
    """(name, :class:`Term`) of the registered terms that apply to the contact ``law``."""
    return tuple((name, term) for name, (term, applies) in TERMS.items()
                 if law.crook and (applies is None or applies(law)))


def _registered_film(registered, cs, phi):
    """phi times the registered terms' film factors (compiled through the overload below)."""
    raise NotImplementedError


def _registered_loads(registered, cs, phi, push, couple):
    """(push, couple) plus the registered terms' stage 2 (compiled through the overload below)."""
    raise NotImplementedError


@overload(_registered_film)
def _registered_film_impl(registered, cs, phi):
    if len(registered) == 0:  # (a term-free bearing compiles to nothing here)
        return lambda registered, cs, phi: phi

    def impl(registered, cs, phi):
        for term in literal_unroll(registered):
            phi *= term.film_factor(term.parameter, cs)
        return phi
    return impl


@overload(_registered_loads)
def _registered_loads_impl(registered, cs, phi, push, couple):
    if len(registered) == 0:
        return lambda registered, cs, phi, push, couple: (push, couple)

    def impl(registered, cs, phi, push, couple):
        for term in literal_unroll(registered):
            f, m = term.contact_loads(term.parameter, cs, phi)
            push += f
            couple += m
        return push, couple
    return impl


class ContactState(NamedTuple):
    """One loaded contact as the terms see it (SI units, the contact frame of MODEL.md §2)."""

    load: float  #: Q, N
    a: float  #: Hertz semi-axis across the rolling direction, m
    b: float  #: along it, m
    max_pressure: float  #: p_max, Pa
    film: float  #: isothermal central film thickness h_c (P17, before any film factor), m
    r_x: float  #: reduced radius along the rolling direction, m
    r_y: float  #: across it, m
    slip: float  #: u_x, race − ball along t1, m/s
    entrainment: float  #: signed mean surface speed relative to the contact, m/s
    rolling_rate: float  #: (ω_ball − ω_race) · t2, rad/s
    ball_radius: float  #: m
    e_prime: float  #: E', Pa
    viscosity: float  #: η0, Pa s


def term_record(law, lubricant, ball_diameter, surface: SurfaceRecord = NO_SURFACE) -> TermRecord:
    """The :class:`TermRecord` of a :class:`contact.ballrace.ContactLaw` with ``lubricant``
    and a ball of ``ball_diameter`` (m): the terms the law switches on (Crook laws only), and
    the bearing's ``surface`` (:func:`contact.surface.surface_record`)."""
    crook = law.crook
    heating = lubricant.shear_heating
    registered = tuple(term for _name, term in applied_terms(law))
    return TermRecord(surface, heating=heating if (crook and law.thermal_film) else 0.0,
                      rolling_width=float(ball_diameter) if (crook and law.rolling_resistance) else 0.0,
                      registered=registered)


def plain_terms(terms: TermRecord) -> tuple:
    """``terms`` as nested plain tuples (numba types those in its C fast path); the kernel
    rebuilds it with :func:`terms_from_plain`."""
    return (tuple(terms.surface), *terms[1:])


@njit(cache=True, error_model="numpy")
def terms_from_plain(plain):
    """The :class:`TermRecord` of :func:`plain_terms`' tuple (inside a kernel)."""
    return TermRecord(SurfaceRecord(*plain[0]), *plain[1:])


# The stages below allocate (or call registered terms that may): ``_nrt=True`` keeps numba's
# reference counting on for them and their callees, which would otherwise inherit the
# ``_nrt=False`` of their caller contact.kernels.race._race_contact.
@njit(cache=True, error_model="numpy", _nrt=True)
def surface_height(terms, race, theta, contact_angle, point_radius, ball, rolling_radius):
    """Stage 0: (h, dh/dθ) of the race surface at the contact of ``ball`` with ``race`` (0 inner,
    1 outer) at race-frame azimuth ``theta`` (rad), reduced radius ``rolling_radius`` R_x (m),
    by :func:`contact.surface.race_height`; (0, 0) for perfect surfaces (one comparison)."""
    s = terms.surface
    if s.waviness.shape[0] + s.defects.shape[0] + s.ball_excess.shape[0] == 0:
        return 0.0, 0.0
    return race_height(s, race, theta, contact_angle, point_radius, ball, rolling_radius)


@njit(cache=True, error_model="numpy", _nrt=True)
def ball_surface_height(terms, ball, race, rotation, normal, rolling, transverse, relative_omega, ball_radius,
                        rolling_radius):
    """Stage 0, the ball's side: (h m, dh/dt m/s, G = ∂h/∂φ (3,) m/rad) of the pits and waviness
    of ``ball`` at its contact with ``race`` by :func:`contact.ball_surface.ball_height` (eq. 13.3, 13.6, 13.7b);
    zeros without."""
    if terms.surface.ball_defects.shape[0] + terms.surface.ball_waviness.shape[0] == 0:
        return 0.0, 0.0, np.zeros(3)
    return ball_height(terms.surface, ball, race, rotation, normal, rolling, transverse, relative_omega, ball_radius,
                       rolling_radius)


@njit(cache=True, error_model="numpy", _nrt=True)
def film_factor(terms, cs, heating):
    """Stage 1: the factor on the isothermal film thickness of contact ``cs``; ``heating`` the
    contact's oil's c_ηT / K_c (m/W; ``terms.heating`` where one oil serves all contacts, 0: off)."""
    phi = 1.0
    if heating > 0.0 and cs.entrainment != 0.0:  # inlet shear heating (MODEL.md §11e)
        phi = thermal_film_factor(cs.entrainment, cs.slip, cs.max_pressure, cs.e_prime, cs.viscosity, heating,
                                  THERMAL_FLOOR)
    return _registered_film(terms.registered, cs, phi)


@njit(cache=True, error_model="numpy", _nrt=True)
def contact_loads(terms, cs, phi):
    """Stage 2: (force on the ball along t1 at the contact point, N; couple on the ball about
    t2, N m) added to contact ``cs`` whose film factor is ``phi``."""
    push = 0.0
    couple = 0.0
    if terms.rolling_width > 0.0 and cs.entrainment != 0.0:  # hydrodynamic rolling resistance (MODEL.md §11b)
        f_r = hydrodynamic_force(cs.load, cs.entrainment, cs.r_x, cs.r_y, cs.a, cs.b, cs.e_prime, cs.viscosity,
                                 terms.rolling_width, phi)
        couple, push = rolling_loads(f_r, cs.r_x, cs.ball_radius, cs.rolling_rate)
    return _registered_loads(terms.registered, cs, phi, push, couple)


@njit(cache=True, error_model="numpy")
def _contact_terms(terms, state, out):
    for i in range(state.load.shape[0]):
        cs = ContactState(state.load[i], state.a[i], state.b[i], state.max_pressure[i], state.film[i], state.r_x[i],
                          state.r_y[i], state.slip[i], state.entrainment[i], state.rolling_rate[i],
                          state.ball_radius[i], state.e_prime[i], state.viscosity[i])
        phi = film_factor(terms, cs, terms.heating)
        out[0, i] = phi
        out[1, i], out[2, i] = contact_loads(terms, cs, phi)


def surface_terms(terms: TermRecord, race, theta, contact_angle, point_radius, ball, rolling_radius) -> np.ndarray:
    """Stage 0 for n contacts (the numpy path; arrays (n,)): rows (h m, dh/dθ m/rad), (2, n)."""
    from .surface import race_heights

    return race_heights(terms.surface, race, theta, contact_angle, point_radius, ball, rolling_radius)


def contact_terms(terms: TermRecord, **state) -> np.ndarray:
    """Both stages for n contacts (the numpy path): ``state`` the fields of
    :class:`ContactState` as arrays (n,) or scalars. Returns rows (film factor, force along t1
    on the ball, couple about t2 on the ball), (3, n)."""
    n = max(np.size(v) for v in state.values())
    arrays = ContactState(*(np.ascontiguousarray(np.broadcast_to(np.asarray(state[k], dtype=float), (n,)))
                            for k in ContactState._fields))
    out = np.empty((3, n))
    _contact_terms(terms, arrays, out)
    return out
