"""Named presets: the reference bearing of Jain & Hunt (2011), table 1 (MODEL.md §8), and the
high-speed bearings and ester oil of MODEL.md §11."""
from __future__ import annotations

import math

from contact.lubricant import REFERENCE_LUBRICANT, Lubricant
from .bearing import STEEL, BallDrag, Bearing, Material

__all__ = ["REFERENCE_BEARING", "REFERENCE_LUBRICANT", "REFERENCE_DRAG", "REFERENCE_SPEED_RPM", "Lubricant",
           "M50_STEEL", "HIGH_SPEED_35MM_BEARING", "SPINDLE_40MM_BEARING", "ESTER_TURBINE_OIL", "HIGH_SPEED_DRAG",
           "CWRU_6205_BEARING"]

REFERENCE_BEARING = Bearing(
    balls=16,  # paper table 1a
    ball_diameter=25e-3,  # ball radius 12.5 mm (table 1a)
    pitch_diameter=155e-3,  # pitch radius 77.5 mm (table 1a)
    # The paper gives no groove radii; 0.52 is a typical angular-contact conformity
    # (0.515–0.53). It sets the groove-centre distance (f_i + f_o - 1) D = 1 mm.
    inner_conformity=0.52,
    outer_conformity=0.52,
    contact_angle=math.radians(40.0),  # table 1a; equals P_d = 0.468 mm with f = 0.52
    ball_material=STEEL,  # E = 210 GPa, nu = 0.3 (table 1a, "steel")
    race_material=STEEL,
    ball_mass=0.064,  # 64 g (table 1a); steel density would give 64.2 g
)

#: Fully flooded: the paper lists the oil density but no drag law; sphere drag with
#: C_D = 0.5 in undiluted oil is the upper bound and, without drag, a purely axially
#: loaded bearing never skids (MODEL.md §8 "Ball drag").
REFERENCE_DRAG = BallDrag(drag_coefficient=0.5, oil_volume_fraction=1.0)

#: Inner-race speed of the paper's results, rpm (outer race fixed).
REFERENCE_SPEED_RPM = 1800.0

#: AISI M-50 bearing steel (E 203 GPa, nu 0.28, 7830 kg/m^3; Harris & Kotzalas, Essential
#: Concepts of Bearing Technology, 5th ed., table 20.1 class values).
M50_STEEL = Material(203e9, 0.28, 7830.0)

#: A 35-mm-bore high-speed angular-contact bearing (issue 19, case g; the turbine-engine
#: bearing class studied up to DN 2.5 million): 16 balls of 7.144 mm on a 46.5-mm pitch
#: circle, conformity 0.535/0.535, free contact angle 24 deg, M-50 balls and races.
HIGH_SPEED_35MM_BEARING = Bearing(balls=16, ball_diameter=7.144e-3, pitch_diameter=46.5e-3, inner_conformity=0.535,
                                  outer_conformity=0.535, contact_angle=math.radians(24.0), ball_material=M50_STEEL,
                                  race_material=M50_STEEL)

#: A 40-mm-bore spindle bearing (issue 19, case h): 14 balls of 8.731 mm, d_m 55 mm,
#: conformity 0.52 inner / 0.53 outer, free contact angle 20 deg, M-50 steel.
SPINDLE_40MM_BEARING = Bearing(balls=14, ball_diameter=8.731e-3, pitch_diameter=55e-3, inner_conformity=0.52,
                               outer_conformity=0.53, contact_angle=math.radians(20.0), ball_material=M50_STEEL,
                               race_material=M50_STEEL)

#: MIL-PRF-23699 ester turbine oil with the oil in at 121 degC (MODEL.md §11): 27.6 cSt at
#: 40 degC and 5.1 cSt at 100 degC give by Walther's relation (ASTM D341) 3.5 cSt x 919 kg/m^3
#: = 3.2 mPa s at 121 degC, local slope d ln(eta)/dT = -0.016 1/K; c_etaP 1.5e-8 1/Pa;
#: conductivity 0.15 W/(m K) (typical of esters).
# Lambda and kappa assumed equal to the mineral oil's (0.047, 0.2953): no published limiting
# shear or film modulus of a MIL-PRF-23699 oil was available; esters and higher temperatures
# usually give a lower tau_L / p, so the traction cap is rather an upper estimate (MODEL.md §6a).
ESTER_TURBINE_OIL = Lubricant(viscosity=3.2e-3, reference_temperature=121.0, pressure_viscosity=1.5e-8,
                              temperature_viscosity=0.016, thermal_conductivity=0.15, density=919.0,
                              limiting_shear_coefficient=0.047, film_shear_modulus_coefficient=0.2953,
                              kinematic_viscosity_40=27.6e-6, kinematic_viscosity_100=5.1e-6)

#: Jet- or mist-lubricated high-speed bearing: 0.5 % oil in the oil-air mixture (issue 19).
HIGH_SPEED_DRAG = BallDrag(drag_coefficient=0.5, oil_volume_fraction=0.005)

#: The drive-end 6205-2RS JEM SKF deep-groove bearing of the Case Western Reserve University
#: bearing data (MODEL.md §13d): 9 balls of 7.94 mm on a 39.04-mm pitch circle, 0 deg (their
#: fault-frequency table: BPFO 3.5848, BPFI 5.4152, BSF 2.357, FTF 0.39828 x shaft speed).
# The groove radii are not published: 0.515 / 0.525 are typical deep-groove conformities;
# the zero contact angle means zero clearance.
CWRU_6205_BEARING = Bearing(balls=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3, inner_conformity=0.515,
                            outer_conformity=0.525, contact_angle=0.0)
