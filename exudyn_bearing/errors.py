"""The package's errors and warnings, in one place (docs/ARCHITECTURE.md)."""

__all__ = ["BearingSimulationError", "NumpyPathWarning", "QuasiStaticError", "TractionCoefficientWarning"]


class BearingSimulationError(RuntimeError):
    """A run diverged or left the physically meaningful range; the message says where
    (which ball, contact or quantity) and what to change."""


class QuasiStaticError(RuntimeError):
    """The Newton–Raphson load-distribution solve did not converge."""


class TractionCoefficientWarning(UserWarning):
    """A contact's traction coefficient exceeded
    :data:`exudyn_bearing.results.outputs.TRACTION_COEFFICIENT_LIMIT`."""


class NumpyPathWarning(UserWarning):
    """A contact law has no compiled form: its contacts are evaluated by the numpy functions
    of :mod:`contact` (the same physics, several times slower per force evaluation). Said
    once per law and process; ``ContactLaw(compiled=False)`` chooses that path silently."""
