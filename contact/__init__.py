"""Contact physics of ball bearings, no Exudyn: numpy/scipy vectorized over contacts, and the
same physics compiled with numba for a whole bearing.

Modules: :mod:`contact.geometry` (curvatures, groove torus), :mod:`contact.hertz`
(elliptical Hertz contact), :mod:`contact.lubricant` (Barus viscosity),
:mod:`contact.film` (Hamrock–Dowson film thickness), :mod:`contact.traction` (Crook
thermal EHD traction and spin moment), :mod:`contact.ballrace` (a contact's forces),
:mod:`contact.terms` (the per-contact terms: thermal film, rolling resistance — the
extension point), :mod:`contact.cage` (pockets, spring chain, drag, land) and
:mod:`contact.kernels` (the compiled kernels).
"""
from pathlib import Path

from .kernel_cache import drop_stale

# numba's cache is per file, and the cached functions of these modules call and inline each
# other's (terms -> surface, ball_surface -> surface, ...): drop a module's caches when any
# module of the package changed (contact.kernels does the same for the kernels)
_SOURCES = sorted(Path(__file__).parent.glob("*.py"))
drop_stale(_SOURCES, _SOURCES)
