"""Ball–race geometry of an angular-contact ball bearing (MODEL.md §2).

Each race groove is a torus: its curvature centres lie on a circle of radius
``centre_radius`` at axial position ``centre_z`` around the race axis (the local z
axis). For a ball centre c, g is the groove centre in the meridional plane through c
and d = c - g; the penetration is |d| - (f - 1/2) D and the unit normal n = d/|d|
points from the groove centre through the ball centre to the contact point.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "race_sign", "curvature_radii", "rolling_radius", "contact_path_radius", "free_contact_angle", "diametral_clearance",
    "groove_centres", "GrooveContact", "groove_contact",
]


def race_sign(race):
    """+1 for 'outer', -1 for 'inner'; an array of +-1 (one per contact) passes through."""
    if isinstance(race, str):
        sign = {"inner": -1.0, "outer": 1.0}.get(race)
        if sign is None:
            raise ValueError(f"race must be 'inner' or 'outer', got {race!r}")
        return sign
    sign = np.asarray(race, dtype=float)
    if not np.all(np.abs(sign) == 1.0):
        raise ValueError("race must be 'inner', 'outer' or an array of -1 (inner) / +1 (outer)")
    return sign


def contact_path_radius(ball_diameter, pitch_diameter, contact_angle, race):
    """Radius of a race's contact path about its axis, m: (d_m - D cos a)/2 inner,
    (d_m + D cos a)/2 outer (MODEL.md §2)."""
    return 0.5 * (pitch_diameter + race_sign(race) * ball_diameter * np.cos(contact_angle))


def rolling_radius(ball_diameter, pitch_diameter, contact_angle, race):
    """The reduced radius along the rolling direction R_x of :func:`curvature_radii`, m."""
    cos_a = np.cos(np.asarray(contact_angle, dtype=float))
    return ball_diameter * (pitch_diameter + race_sign(race) * ball_diameter * cos_a) / (2.0 * pitch_diameter)


def curvature_radii(ball_diameter, pitch_diameter, contact_angle, conformity, race):
    """Principal relative curvature radii (R_x rolling, R_y transverse), m (MODEL.md §2).

    inner: R_x = D (d_m - D cos a) / (2 d_m); outer: R_x = D (d_m + D cos a) / (2 d_m);
    both: R_y = f D / (2 f - 1).

    Parameters
    ----------
    ball_diameter, pitch_diameter : float
        D and d_m, m.
    contact_angle : array_like
        rad.
    conformity : float or array_like
        Groove radius / D of this race (> 0.5).
    race : {'inner', 'outer'} or array_like of -1/+1
        See :func:`race_sign`.
    """
    r_x = rolling_radius(ball_diameter, pitch_diameter, contact_angle, race)
    conformity = np.asarray(conformity, dtype=float)
    r_y = conformity * ball_diameter / (2.0 * conformity - 1.0) * np.ones_like(r_x)
    return r_x, r_y


def free_contact_angle(clearance, inner_conformity, outer_conformity, ball_diameter):
    """Free contact angle from the diametral clearance P_d, rad (MODEL.md §2):
    cos a0 = 1 - P_d / (2 (f_i + f_o - 1) D)."""
    cos_a = 1.0 - clearance / (2.0 * (inner_conformity + outer_conformity - 1.0) * ball_diameter)
    if not -1.0 <= cos_a <= 1.0:
        raise ValueError(f"diametral_clearance {clearance!r} m is larger than the grooves allow")
    return float(np.arccos(cos_a))


def diametral_clearance(contact_angle, inner_conformity, outer_conformity, ball_diameter):
    """Diametral clearance P_d for the free contact angle a0, m (inverse of
    :func:`free_contact_angle`)."""
    return 2.0 * (inner_conformity + outer_conformity - 1.0) * ball_diameter * (1.0 - np.cos(contact_angle))


def groove_centres(pitch_radius, ball_diameter, contact_angle, inner_conformity, outer_conformity):
    """Radius and axial position of the inner and outer groove-centre circles, m.

    Unloaded reference position: ball centre on the pitch circle at z = 0 touching both
    grooves at the free contact angle a0 with zero deflection; the inner contact is on
    the -z side, so an inner race pushed towards +z (or an outer race towards -z)
    loads the bearing.

    Returns
    -------
    (inner_radius, inner_z), (outer_radius, outer_z)
    """
    c, s = np.cos(contact_angle), np.sin(contact_angle)
    ri = (inner_conformity - 0.5) * ball_diameter
    ro = (outer_conformity - 0.5) * ball_diameter
    return (pitch_radius + ri * c, ri * s), (pitch_radius - ro * c, -ro * s)


@dataclass(frozen=True)
class GrooveContact:
    """Result of :func:`groove_contact` for n ball centres (arrays of shape (n,) or (n, 3))."""

    penetration: np.ndarray  #: delta = |d| - (f - 1/2) D, m (> 0 in contact)
    normal: np.ndarray  #: unit n, groove centre -> ball centre -> contact point, race frame
    distance: np.ndarray  #: |d|, m
    groove_centre: np.ndarray  #: g, m, race frame
    radial: np.ndarray  #: unit radial direction of the meridional plane, race frame
    contact_angle: np.ndarray  #: angle of n from the radial plane, rad, positive as a0


def groove_contact(ball_centre, centre_radius, centre_z, tube_clearance, race):
    """Penetration of balls into a toroidal groove (MODEL.md §2), vectorized.

    Parameters
    ----------
    ball_centre : array_like, shape (n, 3)
        Ball centres in the race frame (race axis = z), m.
    centre_radius, centre_z : float or array_like (n,)
        Groove-centre circle, m (:func:`groove_centres`).
    tube_clearance : float or array_like (n,)
        (f - 1/2) D, m: groove radius minus ball radius.
    race : {'inner', 'outer'} or array_like of -1/+1
        Only fixes the sign of the reported contact angle (the inner normal points
        inwards and to -z at the free angle).
    """
    c = np.atleast_2d(np.asarray(ball_centre, dtype=float))
    rho = np.hypot(c[:, 0], c[:, 1])
    radial = np.zeros_like(c)
    radial[:, 0] = c[:, 0] / rho
    radial[:, 1] = c[:, 1] / rho
    g = np.asarray(centre_radius, dtype=float)[..., None] * radial
    g[:, 2] = centre_z
    d = c - g
    dist = np.linalg.norm(d, axis=1)
    n = d / dist[:, None]
    sign = race_sign(race)
    angle = np.arctan2(sign * n[:, 2], sign * np.einsum("ij,ij->i", n, radial))
    return GrooveContact(dist - tube_clearance, n, dist, g, radial, angle)
