"""The traction laws of a ball–race contact, in one registry: name → :class:`TractionModel`.

Everything that offers a choice of traction law reads :data:`TRACTION_LAWS`:
:class:`contact.ballrace.ContactLaw` validates its ``traction`` against it,
:func:`contact.ballrace.ball_race_forces` evaluates the chosen law through its
:attr:`TractionModel.evaluate`, the compiled path covers the laws whose
:attr:`TractionModel.kernel` is set, and the command line's ``--traction`` choices and the
bearing file's accepted values are its keys. A new law is one :func:`register_traction` call
(SciPy's ``solve_ivp`` keeps its ``METHODS`` the same way).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

__all__ = ["TractionModel", "TRACTION_LAWS", "register_traction", "traction_model"]


@dataclass(frozen=True)
class TractionModel:
    """One traction law.

    Parameters
    ----------
    name : str
        The value of ``ContactLaw.traction`` (and of ``--traction`` and the bearing file's
        ``[contact_law] traction``).
    summary : str
        One line for help texts, with its MODEL.md section.
    evaluate : callable or None
        The numpy path: ``evaluate(slip, a, b, p_max, load, h, entrainment, lubricant, law)``
        for the n loaded contacts — ``slip`` (u_x m/s, u_y m/s, spin rad/s), semi-axes a
        (transverse) and b (m), p_max (Pa; capped by the law's Barus bound for film laws),
        load Q (N), film h (m), entrainment (m/s), the :class:`~contact.lubricant.Lubricant`
        and the :class:`~contact.ballrace.ContactLaw` — returning an object with ``fx``,
        ``fy``, ``mz`` and ``heat`` arrays (n,) (N, N, N m, W). None: no traction.
    film : bool
        Whether the law shears the EHD film: the film thickness and the per-contact terms
        (:mod:`contact.terms`) are evaluated for it.
    crook : bool
        Whether it is a Crook law (the limiting shear and film elasticity options, the
        per-contact terms of MODEL.md §11b, §11e apply).
    kernel : int or None
        ``LawRecord.traction`` of the compiled kernels (:mod:`contact.kernels`) that compute
        it (with ``ContactLaw.fast_quadrature`` for Crook laws); None: numpy path only.
    """

    name: str
    summary: str
    evaluate: Callable | None
    film: bool = False
    crook: bool = False
    kernel: int | None = None


#: the registered laws by name, in the order help texts list them
TRACTION_LAWS: dict[str, TractionModel] = {}


def register_traction(model: TractionModel) -> TractionModel:
    """Add ``model`` to :data:`TRACTION_LAWS` (a name already there is refused)."""
    if not isinstance(model, TractionModel):
        raise ValueError(f"register_traction takes a TractionModel, got {model!r}")
    if model.name in TRACTION_LAWS:
        raise ValueError(f"traction law {model.name!r} is registered already")
    TRACTION_LAWS[model.name] = model
    return model


def traction_model(name: str) -> TractionModel:
    """The registered law ``name``; a ValueError listing the registered ones otherwise."""
    try:
        return TRACTION_LAWS[name]
    except (KeyError, TypeError):
        raise ValueError(f"traction must be one of {tuple(TRACTION_LAWS)}, got {name!r}") from None


def _crook(slip, a, b, p_max, load, h, entrainment, lubricant, law):
    from .traction import crook_traction

    return crook_traction(*slip, a, b, p_max, h, lubricant, order=law.quadrature_order,
                          limiting_shear=law.limiting_shear_for(lubricant), fast=law.fast_quadrature,
                          film_modulus=law.film_modulus_for(lubricant), entrainment=entrainment)


def _newtonian(slip, a, b, p_max, load, h, entrainment, lubricant, law):
    from .newtonian import newtonian_traction

    return newtonian_traction(*slip, a, b, p_max, h, lubricant)


def _coulomb(slip, a, b, p_max, load, h, entrainment, lubricant, law):
    from .friction import coulomb_traction

    return coulomb_traction(*slip, a, b, load, law.friction_coefficient, law.friction_regularization)


register_traction(TractionModel(
    "crook-limited", "Crook thermal EHD traction with the lubricant's limiting shear stress and the film's "
    "elastic compliance (MODEL.md §6, §6a, §6b; the default)", _crook, film=True, crook=True, kernel=1))
register_traction(TractionModel("crook", "the paper's pure Crook thermal EHD law (MODEL.md §6)", _crook, film=True,
                                crook=True, kernel=1))
register_traction(TractionModel("newtonian", "the isothermal Newtonian limit of the Crook law, small slip only "
                                "(MODEL.md §6)", _newtonian, film=True))
register_traction(TractionModel("coulomb", "regularized dry Coulomb friction, mu and u_r of the contact law",
                                _coulomb))
register_traction(TractionModel("none", "normal forces only", None, kernel=0))

