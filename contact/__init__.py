"""Contact physics of ball bearings: pure numpy/scipy, vectorized over contacts, no Exudyn.

Modules: :mod:`contact.geometry` (curvatures, groove torus), :mod:`contact.hertz`
(elliptical Hertz contact), :mod:`contact.lubricant` (Barus viscosity),
:mod:`contact.film` (Hamrock–Dowson film thickness), :mod:`contact.traction` (Crook
thermal EHD traction and spin moment).
"""
