"""Which path a contact law runs on: the compiled kernels (:mod:`exudyn_bearing.model.compiled`)
cover the registered traction laws that have a kernel and the Brewe–Hamrock Hertz fits; the
rest runs on the numpy functions of :mod:`contact`, said once (NumpyPathWarning)."""
from __future__ import annotations

import warnings

from contact.traction_laws import traction_model
from ..errors import NumpyPathWarning

__all__ = ["supports", "uncompiled_part", "say_numpy_path"]

#: how much slower a force evaluation is on the numpy path (the cost per residual in
#: docs/REFERENCE.md, "Races and physics options")
NUMPY_PATH_COST = "6.8-20x"
_SAID = set()  # the laws NumpyPathWarning has named in this process


def uncompiled_part(law) -> str | None:
    """What of this :class:`contact.ballrace.ContactLaw` the compiled kernels do not compute
    (None: they compute all of it): they cover the registered traction laws with a kernel
    (:data:`contact.traction_laws.TRACTION_LAWS`; Crook laws by the fast rule) and the
    Brewe–Hamrock Hertz fits."""
    model = traction_model(law.traction)
    if model.kernel is None:
        return f"traction {law.traction!r}"
    if model.crook and not law.fast_quadrature:
        return f"traction {law.traction!r} by the accurate rule (fast_quadrature=False)"
    if law.hertz_method != "fit":
        return f"hertz_method {law.hertz_method!r}"
    return None


def supports(law) -> bool:
    """Whether the compiled path computes this :class:`contact.ballrace.ContactLaw`
    (:func:`uncompiled_part`); other laws use the numpy path."""
    return uncompiled_part(law) is None


def say_numpy_path(law) -> None:
    """A :class:`~exudyn_bearing.errors.NumpyPathWarning` naming what of ``law`` has no
    compiled form and the cost, once per law and process."""
    part = uncompiled_part(law)
    if part is not None and part not in _SAID:
        _SAID.add(part)
        warnings.warn(f"{part} has no compiled form: the contacts are evaluated by the numpy functions, "
                      f"{NUMPY_PATH_COST} slower per force evaluation (ContactLaw(compiled=False) chooses that "
                      "path without this warning)", NumpyPathWarning, stacklevel=4)
