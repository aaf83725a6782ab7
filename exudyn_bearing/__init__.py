"""exudyn-bearing: skidding of angular-contact ball bearings in Exudyn.

Physics lives in the ``contact`` package (pure numpy/scipy); this package describes
bearings, solves the quasi-static load distribution and builds Exudyn models::

    import exudyn as exu
    from exudyn_bearing import CreateAngularContactBearing, races, run_solver

    SC = exu.SystemContainer(); mbs = SC.AddSystem()
    brg = CreateAngularContactBearing(mbs, innerRace=races.Driven(rpm=1800), axialForce=1300)
    mbs.Assemble()
    run_solver(mbs, [brg], 0.1)
    print(brg.Results(mbs).summary())
"""
from contact.ballrace import ContactLaw
from . import races
from .bearing import BallDrag, Bearing, Material, STEEL
from .bearingfile import BearingFile, dumps_bearing, load_bearing, loads_bearing, save_bearing
from .builder import BearingHandle, CreateAngularContactBearing
from .cage import CageModel
from .presets import REFERENCE_BEARING, REFERENCE_DRAG, REFERENCE_LUBRICANT, REFERENCE_SPEED_RPM
from .quasistatic import LoadDistribution, QuasiStaticError, solve_load_distribution
from .runner import BearingSimulationError, SolverSettings, run_solver, simulate
from .steady import SteadyState, gyroscopic_minimum_axial, steady_state

__version__ = "0.1.0"
