"""exudyn-bearing: skidding of angular-contact ball bearings in Exudyn.

Physics lives in the ``contact`` package (pure numpy/scipy); this package describes
bearings, solves the quasi-static load distribution and builds Exudyn models.
"""
from .bearing import BallDrag, Bearing, Material, STEEL
from .bearingfile import BearingFile, dumps_bearing, load_bearing, loads_bearing, save_bearing
from .presets import REFERENCE_BEARING, REFERENCE_DRAG, REFERENCE_LUBRICANT, REFERENCE_SPEED_RPM
from .quasistatic import LoadDistribution, QuasiStaticError, solve_load_distribution

__version__ = "0.1.0"
