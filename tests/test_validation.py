"""Every ValueError a user can get from the public constructors and functions names the
parameter the user typed (issue "tests that guard what users read").

One row per validator that no other test file triggers; the name regex is the argument
as the user spells it (``innerRace``, ``damping_ratio``, ``localRotation``), bounded by
word boundaries so ``damping`` does not pass for ``guide_damping``. Nothing here solves a
dynamic model: the builder checks fire while the bearing is being added, the rest before
any work starts.
"""
import functools

import numpy as np
import pytest

from contact import film, friction, geometry, hertz, traction
from contact.ballrace import ContactLaw
from contact.lubricant import REFERENCE_LUBRICANT, Lubricant
from exudyn_bearing import races
from exudyn_bearing.bearing import BallDrag, Bearing, Material
from exudyn_bearing.bearingfile import loads_bearing
from exudyn_bearing.cage import CageModel
from exudyn_bearing.presets import REFERENCE_BEARING
from exudyn_bearing.solvers.quasistatic import solve_load_distribution
from exudyn_bearing.solvers.shaft import ShaftBearing, solve_shaft
from exudyn_bearing.studies.skidmap import skid_map

NAN, INF = float("nan"), float("inf")
P = functools.partial
BRG = REFERENCE_BEARING
GEOMETRY = dict(balls=16, ball_diameter=25e-3, pitch_diameter=155e-3, inner_conformity=0.52,
                outer_conformity=0.52)
OIL = dict(viscosity=0.04, reference_temperature=30.0, pressure_viscosity=1.75e-8,
           temperature_viscosity=0.05, thermal_conductivity=0.14, density=860.0)
TRACTION = dict(u_x=0.01, u_y=0.0, omega_s=10.0, a=2.2e-3, b=0.14e-3, p_max=1e9, h=1e-7,
                lubricant=REFERENCE_LUBRICANT)
FILE = """
[bearing]
balls = 6
ball_diameter = 11.1e-3
pitch_diameter = 43.5e-3
inner_groove_radius = 5.772e-3
outer_groove_radius = 5.883e-3
diametral_clearance = 10e-6
"""
ABOUT_X_90 = ((1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0))  # proper, bearing axis not +-z


def _shaft_bearing(**kw):
    args = dict(bearing=BRG, position=(0.0, 0.0, 0.0), rotation=np.eye(3), inner_position=(0.0, 0.0, 0.0))
    args.update(kw)
    return ShaftBearing(**args)


def _case(func, kwargs, name, id):
    return pytest.param(func, kwargs, name, id=id)


CASES = [
    # -- contact.hertz ----------------------------------------------------------------
    _case(hertz.effective_modulus, dict(youngs_1=-210e9, poisson_1=0.3), "youngs_1", "hertz-youngs_1"),
    _case(hertz.effective_modulus, dict(youngs_1=210e9, poisson_1=0.3, youngs_2=0.0, poisson_2=0.3), "youngs_2",
          "hertz-youngs_2"),
    _case(hertz.effective_modulus, dict(youngs_1=210e9, poisson_1=0.3, youngs_2=200e9, poisson_2=0.5), "poisson_2",
          "hertz-poisson_2"),
    _case(hertz.exact_ellipticity, dict(radius_ratio=0.5), "radius_ratio", "hertz-radius_ratio"),
    _case(hertz.exact_ellipticity, dict(radius_ratio=NAN), "radius_ratio", "hertz-radius_ratio-nan"),
    _case(hertz.hertz_contact, dict(r_x=1e-3, r_y=1e-2, e_prime=231e9, method="approx"), "method",
          "hertz-method"),
    # -- contact.geometry -------------------------------------------------------------
    _case(geometry.race_sign, dict(race="middle"), "race", "geometry-race-name"),
    _case(geometry.race_sign, dict(race=[1.0, 0.0]), "race", "geometry-race-array"),
    _case(geometry.curvature_radii, dict(ball_diameter=25e-3, pitch_diameter=155e-3, contact_angle=0.7,
                                         conformity=0.52, race="left"), "race", "geometry-curvature-race"),
    # -- contact.film, friction, lubricant, traction ------------------------------------
    _case(film.minimum_film_thickness, dict(entrainment_speed=5.0, load=NAN, r_x=1e-2, ellipticity=8.0,
                                            e_prime=231e9, lubricant=REFERENCE_LUBRICANT), "load", "film-min-load"),
    _case(friction.coulomb_traction, dict(u_x=0.0, u_y=0.0, omega_s=0.0, a=1e-3, b=1e-4, load=100.0,
                                          friction_coefficient=0.05, regularization=0.0), "regularization",
          "friction-regularization"),
    _case(Lubricant, dict(OIL, reference_temperature=NAN), "reference_temperature", "lubricant-reference_temperature"),
    _case(Lubricant, dict(OIL, temperature_viscosity=-0.05), "temperature_viscosity", "lubricant-temperature_viscosity"),
    _case(traction.crook_traction, dict(TRACTION, u_x="fast"), "u_x", "traction-not-numeric"),
    _case(traction.crook_traction, dict(TRACTION, lubricant=object()), "lubricant", "traction-lubricant"),
    _case(traction.newtonian_traction, dict(TRACTION, lubricant=None), "lubricant", "newtonian-lubricant"),
    _case(traction.newtonian_slope, dict(a=2.2e-3, b=0.14e-3, p_max=1e9, h=1e-7, lubricant=REFERENCE_LUBRICANT,
                                         temperature=INF), "temperature", "newtonian-slope-temperature"),
    # -- contact.ballrace.ContactLaw ---------------------------------------------------
    _case(ContactLaw, dict(traction="magic"), "traction", "law-traction"),
    _case(ContactLaw, dict(quadrature_order=1), "quadrature_order", "law-quadrature_order"),
    _case(ContactLaw, dict(quadrature_order=16.0), "quadrature_order", "law-quadrature_order-float"),
    _case(ContactLaw, dict(damping_ratio=-0.05), "damping_ratio", "law-damping_ratio"),
    _case(ContactLaw, dict(min_film_thickness=0.0), "min_film_thickness", "law-min_film_thickness"),
    _case(ContactLaw, dict(friction_coefficient=0.0), "friction_coefficient", "law-friction_coefficient"),
    _case(ContactLaw, dict(friction_regularization=NAN), "friction_regularization", "law-friction_regularization"),
    _case(ContactLaw, dict(max_barus_exponent=100.0), "max_barus_exponent", "law-max_barus_exponent"),
    _case(ContactLaw, dict(limiting_shear=-0.08), "limiting_shear", "law-limiting_shear"),
    # -- Bearing, Material, BallDrag ---------------------------------------------------
    _case(Bearing, dict(GEOMETRY, ball_diameter=0.2, pitch_diameter=0.1, contact_angle=0.7),
          "ball_diameter.*pitch_diameter",
          "bearing-ball-larger-than-pitch"),
    _case(Bearing, dict(GEOMETRY, contact_angle=0.7, ball_material="steel"), "ball_material",
          "bearing-ball_material"),
    _case(Bearing, dict(GEOMETRY, contact_angle=0.7, race_material=None), "race_material", "bearing-race_material"),
    _case(Bearing.from_clearance, dict(GEOMETRY, diametral_clearance=0.1), "diametral_clearance",
          "bearing-clearance-too-large"),
    _case(Bearing.from_clearance, dict(GEOMETRY, diametral_clearance=NAN), "diametral_clearance",
          "bearing-clearance-nan"),
    _case(Material, dict(youngs_modulus=0.0), "youngs_modulus", "material-youngs_modulus"),
    _case(Material, dict(density=NAN), "density", "material-density"),
    _case(BallDrag, dict(drag_coefficient=-0.5), "drag_coefficient", "drag-drag_coefficient"),
    _case(BallDrag, dict(drag_coefficient=INF), "drag_coefficient", "drag-drag_coefficient-inf"),
    _case(BallDrag, dict(oil_volume_fraction=1.5), "oil_volume_fraction", "drag-oil_volume_fraction"),
    # -- races ---------------------------------------------------------------------------
    _case(races.Race, dict(kind="spinning"), "kind", "race-kind"),
    _case(races.Fixed, dict(rpm=NAN), "rpm", "race-rpm-nan"),
    _case(races.Driven, dict(rpm="fast"), "rpm", "race-rpm-text"),
    _case(races.Free, dict(rpm=lambda t: 100.0 * t), "rpm", "race-rpm-function-on-free"),
    _case(races.Driven, dict(rpm=1800.0, mass=-1.0), "mass", "race-mass"),
    _case(races.Free, dict(mass=0.0), "mass", "race-mass-zero"),
    _case(races.Driven, dict(rpm=1800.0, translation="locked"), "translation", "race-translation"),
    _case(races.OnBody, dict(bodyNumber=0, localRotation=np.diag([1.0, 1.0, 2.0])), "localRotation",
          "race-localRotation"),
    # -- CageModel -------------------------------------------------------------------------
    _case(CageModel, dict(kind="cylinder"), "kind", "cage-kind"),
    _case(CageModel, dict(guidance="middle"), "guidance", "cage-guidance"),
    _case(CageModel, dict(stiffness=-1e8), "stiffness", "cage-stiffness"),
    _case(CageModel, dict(clearance=NAN), "clearance", "cage-clearance"),
    _case(CageModel, dict(guide_clearance=-1e-4), "guide_clearance", "cage-guide_clearance"),
    _case(CageModel, dict(guide_stiffness=INF), "guide_stiffness", "cage-guide_stiffness"),
    _case(CageModel, dict(damping=-1.0), "damping", "cage-damping"),
    _case(CageModel, dict(guide_damping=NAN), "guide_damping", "cage-guide_damping"),
    _case(CageModel, dict(mass=0.0), "mass", "cage-mass"),
    # -- bearing files -------------------------------------------------------------------
    _case(loads_bearing, dict(text="material = 3\n" + FILE), "material", "file-section-not-table"),
    _case(loads_bearing, dict(text=FILE.replace("balls = 6", 'balls = "six"')), "balls", "file-value-not-number"),
    _case(loads_bearing, dict(text=FILE.replace("balls = 6", "balls = 6.0")), "balls", "file-balls-float"),
    _case(loads_bearing, dict(text=FILE.replace("pitch_diameter = 43.5e-3\n", "")), "pitch_diameter",
          "file-missing-key"),
    _case(loads_bearing, dict(text=FILE.replace("ball_diameter = 11.1e-3", "ball_diameter = 0")), "ball_diameter",
          "file-groove-radius-without-ball"),
    _case(loads_bearing, dict(text="[material]\ndensity = 7850\n"), r"\[bearing\]", "file-no-bearing-section"),
    _case(loads_bearing, dict(text=FILE + "[drag]\noil_volume_fraction = 2.0\n"), "oil_volume_fraction",
          "file-drag-value"),
    # invalid TOML: the file itself is the offending input; the message says what is wrong with it
    _case(loads_bearing, dict(text="[bearing\nballs = 6\n"), "TOML", "file-not-toml"),
    # -- quasi-static load distribution --------------------------------------------------
    _case(P(solve_load_distribution, BRG), dict(axial_force=1000.0, outer_rpm=NAN), "outer_rpm", "qs-outer_rpm"),
    _case(P(solve_load_distribution, BRG), dict(axial_force=1000.0, moment=(1.0,)), "moment", "qs-moment-length"),
    _case(P(solve_load_distribution, BRG), dict(axial_force=1000.0, moment=(1.0, INF)), "moment", "qs-moment-inf"),
    _case(P(solve_load_distribution, BRG), dict(axial_force=1000.0, mode="exact"), "mode", "qs-mode"),
    _case(P(solve_load_distribution, BRG), dict(), "axial_force", "qs-no-load"),
    _case(P(solve_load_distribution, BRG), dict(axial_force=1000.0, mode="fixed-angle", moment=(1.0, 0.0)), "moment",
          "qs-moment-fixed-angle"),
    _case(P(solve_load_distribution, BRG), dict(displacement=(1e-6, 0.0)), "displacement", "qs-displacement"),
    _case(P(solve_load_distribution, BRG), dict(displacement=(0.0, 0.0, NAN)), "displacement",
          "qs-displacement-nan"),
    # -- shaft -----------------------------------------------------------------------------
    _case(_shaft_bearing, dict(bearing="reference"), "bearing", "shaft-bearing"),
    _case(_shaft_bearing, dict(inner_position=(0.0, 0.0)), "inner_position", "shaft-inner_position"),
    _case(_shaft_bearing, dict(rotation=ABOUT_X_90), "rotation", "shaft-rotation-axis"),
    _case(solve_shaft, dict(bearings=[]), "bearings", "shaft-no-bearings"),
    _case(solve_shaft, dict(bearings=[BRG]), "bearings", "shaft-not-shaft-bearing"),
    _case(P(solve_shaft, [_shaft_bearing()]), dict(moment=(0.0, NAN)), "moment", "shaft-moment"),
    # -- skid map --------------------------------------------------------------------------
    _case(skid_map, dict(axial_force=(), progress=None), "axial_force", "skidmap-empty-grid"),
]


@pytest.mark.parametrize("func, kwargs, name", CASES)
def test_value_error_names_the_parameter(func, kwargs, name):
    with pytest.raises(ValueError, match=rf"(?<!\w){name}(?!\w)"):
        func(**kwargs)


# ---------------------------------------------------------------------------------------
# Exudyn glue: builder, handle, connector, runner, graphics
# ---------------------------------------------------------------------------------------
def _count(mbs):
    d = mbs.systemData
    return d.NumberOfNodes(), d.NumberOfObjects(), d.NumberOfMarkers(), d.NumberOfLoads(), d.NumberOfSensors()


# (kwargs or a function of mbs returning them, name regex, nothing added to mbs)
BUILDER = [
    pytest.param(dict(bearing="reference"), "bearing", True, id="bearing"),
    pytest.param(dict(lubricant=OIL), "lubricant", True, id="lubricant"),
    pytest.param(dict(innerRace="driven"), "innerRace", True, id="innerRace"),
    pytest.param(dict(outerRace=0.0), "outerRace", True, id="outerRace"),
    pytest.param(dict(axialForce=-1300.0), "axialForce", True, id="axialForce-negative"),
    pytest.param(dict(axialForce=lambda t: -1.0), "axialForce", True, id="axialForce-function"),
    pytest.param(dict(radialForce=NAN), "radialForce", True, id="radialForce-nan"),
    pytest.param(dict(radialForce="300"), "radialForce", True, id="radialForce-text"),
    pytest.param(dict(innerRace=races.Fixed(1800.0), axialForce=1300.0), "axialForce", True,
                 id="axialForce-on-Fixed"),
    pytest.param(dict(innerRace=races.Driven(1800.0, translation="fixed"), radialForce=300.0), "radialForce", True,
                 id="radialForce-on-fixed-translation"),
    pytest.param(dict(position=(0.0, 0.0)), "position", True, id="position"),
    pytest.param(dict(position=(0.0, NAN, 0.0)), "position", True, id="position-nan"),
    pytest.param(dict(rotationMatrix=np.diag([1.0, 1.0, -1.0])), "rotationMatrix", True, id="rotationMatrix"),
    pytest.param(dict(innerRaceDisplacement=(1e-6, 0.0)), "innerRaceDisplacement", True,
                 id="innerRaceDisplacement-shape"),
    pytest.param(dict(innerRaceDisplacement=(1e-6, 0.0, 0.0), axialForce=1300.0), "innerRaceDisplacement", True,
                 id="innerRaceDisplacement-with-force"),
    pytest.param(dict(innerRaceDisplacement=(1e-6, 0.0, 0.0), innerRace=races.Fixed(1800.0)),
                 "innerRaceDisplacement", True, id="innerRaceDisplacement-on-Fixed"),
    pytest.param(dict(axialForce=1300.0, initialControl="both"), "initialControl", True, id="initialControl"),
    # a race needs a rigid-body node (any of CreateRigidBody's types): a mass point has no rotation
    pytest.param(lambda mbs: dict(innerRace=races.OnBody(mbs.CreateMassPoint(mass=1.0))), "innerRace.*nodeType",
                 True, id="innerRace-OnBody-mass-point"),
    pytest.param(lambda mbs: dict(outerRace=races.OnBody(mbs.CreateMassPoint(mass=1.0))), "outerRace.*nodeType",
                 True, id="outerRace-OnBody-mass-point"),
]


@pytest.mark.parametrize("kwargs, name, nothing_added", BUILDER)
def test_builder_value_error_names_the_parameter(kwargs, name, nothing_added):
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import CreateAngularContactBearing

    mbs = exu.SystemContainer().AddSystem()
    if callable(kwargs):
        kwargs = kwargs(mbs)
    before = _count(mbs)
    with pytest.raises(ValueError, match=rf"(?<!\w){name}(?!\w)"):
        CreateAngularContactBearing(mbs, show=False, **kwargs)
    if nothing_added:
        assert _count(mbs) == before


@pytest.fixture(scope="module")
def built():
    """One bearing added to a fresh mbs, not solved."""
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import CreateAngularContactBearing

    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, innerRace=races.Driven(1800.0), axialForce=1300.0, show=False)
    return mbs, handle


def test_handle_states_without_recording_names_record_states():
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing import CreateAngularContactBearing

    mbs = exu.SystemContainer().AddSystem()
    handle = CreateAngularContactBearing(mbs, axialForce=1300.0, recordStates=False, show=False)
    with pytest.raises(ValueError, match=r"recordStates=False"):
        handle.States(mbs)
    with pytest.raises(ValueError, match=r"recordStates=False"):
        handle.Results(mbs)


def test_handle_states_before_a_run_says_nothing_is_recorded(built):
    # not a parameter error: the state sensor exists but holds no rows yet
    mbs, handle = built
    with pytest.raises(ValueError, match="no states recorded yet"):
        handle.States(mbs)


def test_connector_race_frame_names_name(built):
    _, handle = built
    q = handle.connector.reference
    with pytest.raises(ValueError, match=r"(?<!\w)name(?!\w)"):
        handle.connector.race_frame("middle", 0.0, q, np.zeros_like(q))


@pytest.mark.parametrize("time", [0.0, -0.01, NAN, INF])
def test_simulate_names_time(time):
    pytest.importorskip("exudyn")
    from exudyn_bearing.simulation.runner import simulate

    with pytest.raises(ValueError, match=r"(?<!\w)time(?!\w)"):
        simulate(time=time)


@pytest.mark.parametrize("frames", [0, 2.0, "4"])
def test_render_run_names_frames(frames, tmp_path):
    pytest.importorskip("exudyn")
    from exudyn_bearing.studies.render import render_run

    with pytest.raises(ValueError, match=r"(?<!\w)frames(?!\w)"):
        render_run(tmp_path, frames=frames)
    assert not any(tmp_path.iterdir())


def test_render_frames_names_backend(tmp_path):
    exu = pytest.importorskip("exudyn")
    from exudyn_bearing.results.graphics import render_frames

    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    with pytest.raises(ValueError, match=r"(?<!\w)backend(?!\w)"):
        render_frames(sc, mbs, tmp_path, backend="vulkan")
