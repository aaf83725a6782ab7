"""The reference bearing of Jain & Hunt (2011), table 1 (MODEL.md §8), as named presets."""
from __future__ import annotations

import math

from contact.lubricant import REFERENCE_LUBRICANT, Lubricant
from .bearing import STEEL, BallDrag, Bearing

__all__ = ["REFERENCE_BEARING", "REFERENCE_LUBRICANT", "REFERENCE_DRAG", "REFERENCE_SPEED_RPM", "Lubricant"]

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
