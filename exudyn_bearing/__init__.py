"""exudyn-bearing: skidding of angular-contact ball bearings in Exudyn.

Physics lives in the ``contact`` package (pure numpy/scipy); this package describes
bearings, solves the quasi-static load distribution and builds Exudyn models::

    import exudyn as exu
    from exudyn_bearing import races, run_solver   # registers mbs.CreateAngularContactBearing

    SC = exu.SystemContainer(); mbs = SC.AddSystem()
    brg = mbs.CreateAngularContactBearing(innerRace=races.Driven(rpm=1800), axialForce=1300)
    mbs.Assemble()
    run_solver(mbs, [brg], 0.1)
    print(brg.Results(mbs).summary())
"""
from contact.ballrace import ContactLaw
from contact.lubricant import Lubricant
from . import races
from .bearing import BallDrag, Bearing, Material, STEEL
from .bearingfile import BearingFile, as_setup, dumps_bearing, load_bearing, loads_bearing, save_bearing
from .setup import BearingSetup
from .cage import CageModel
from .criteria import gyroscopic_minimum_axial, hirano_minimum_axial
from .errors import (BearingSimulationError, NumpyPathWarning, QuasiStaticError, SurfaceStartWarning,
                     ThermalGrowthWarning, TractionCoefficientWarning)
from .model.assembly import SettleShaft
from .model.builder import BearingHandle, CreateAngularContactBearing
from .presets import (CWRU_6205_BEARING, ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG, M50_STEEL, REFERENCE_BEARING,
                      REFERENCE_DRAG, REFERENCE_LUBRICANT, REFERENCE_SPEED_RPM, SPINDLE_40MM_BEARING)
from .results.outputs import BearingResults, settled_label
from .results.plots import plot_run, plot_skid_curve
from .simulation.runner import RunInfo, SimulationSummary, SolverSettings, run_solver, simulate
from .solvers.quasidynamic import AzimuthStates, combined_load_state
from .solvers.quasistatic import LoadDistribution, solve_load_distribution
from .solvers.shaft import ShaftBearing, ShaftEquilibrium, solve_shaft
from .solvers.steady import SteadyState, steady_state
from .studies.skidmap import SkidMap, skid_map

__version__ = "0.1.0"

__all__ = [
    # building a scene (also mbs.CreateAngularContactBearing once the package is imported)
    "CreateAngularContactBearing", "BearingHandle", "SettleShaft", "races", "run_solver", "SolverSettings", "RunInfo",
    # bearings, lubricants, physics options and presets
    "Bearing", "Material", "STEEL", "M50_STEEL", "Lubricant", "BallDrag", "CageModel", "ContactLaw",
    "REFERENCE_BEARING", "REFERENCE_LUBRICANT", "REFERENCE_DRAG", "REFERENCE_SPEED_RPM",
    "HIGH_SPEED_35MM_BEARING", "SPINDLE_40MM_BEARING", "ESTER_TURBINE_OIL", "HIGH_SPEED_DRAG", "CWRU_6205_BEARING",
    # bearing setups and files
    "BearingSetup", "as_setup", "BearingFile", "load_bearing", "loads_bearing", "save_bearing", "dumps_bearing",
    # solvers without time integration
    "solve_load_distribution", "LoadDistribution", "steady_state", "SteadyState", "combined_load_state",
    "AzimuthStates", "solve_shaft", "ShaftBearing", "ShaftEquilibrium",
    # runs, results and studies
    "simulate", "SimulationSummary", "BearingResults", "settled_label", "skid_map", "SkidMap", "plot_run",
    "plot_skid_curve",
    # skid criteria
    "gyroscopic_minimum_axial", "hirano_minimum_axial",
    # errors and warnings
    "BearingSimulationError", "NumpyPathWarning", "QuasiStaticError", "SurfaceStartWarning",
    "ThermalGrowthWarning", "TractionCoefficientWarning",
    "__version__",
]
