"""The package's errors and warnings, in one place (docs/ARCHITECTURE.md).

The package's warnings print as one line, ``exudyn-bearing: <Category>: <message>``, without
Python's file, line number and source line: they speak of the bearing, not of where in the
package they were raised (:func:`one_line`, installed on import).
"""
import warnings

__all__ = ["BearingSimulationError", "NumpyPathWarning", "QuasiStaticError", "SurfaceStartWarning",
           "ThermalGrowthWarning", "TractionCoefficientWarning"]


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


class SurfaceStartWarning(UserWarning):
    """The start with surfaces (MODEL.md §13d) could not carry the perfect start's forces: what
    is left and where (``handle.connector.surface_start``)."""


class ThermalGrowthWarning(UserWarning):
    """A run's temperatures would grow the bearing past zero clearance (the balls pinched
    radially), which its free-contact-angle geometry cannot hold (MODEL.md §14f): the contacts
    keep the sizes of the last update that could be grown. Said once per run."""


#: the package's warnings, printed in one line
ONE_LINE = (NumpyPathWarning, SurfaceStartWarning, ThermalGrowthWarning, TractionCoefficientWarning)
_FORMAT = warnings.formatwarning


def one_line(message, category, filename, lineno, line=None):
    """``warnings.formatwarning`` with the package's warnings in one line, the others as before."""
    if isinstance(category, type) and issubclass(category, ONE_LINE):
        return f"exudyn-bearing: {category.__name__}: {message}\n"
    return _FORMAT(message, category, filename, lineno, line)


warnings.formatwarning = one_line
