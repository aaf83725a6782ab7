"""Bearing description: geometry, materials and ball drag (MODEL.md §2, §3, §8).

All quantities SI (m, kg, Pa, rad). Files use degrees for angles (see
:mod:`exudyn_bearing.bearingfile`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from contact import geometry, hertz
from contact.cage import jet_momentum_factor
from contact.thermal_expansion import HeatedGeometry, heated_geometry


def _finite(name: str, value, *, positive: bool = True) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"{name} must be a finite number, got {value!r}")
    if positive and value <= 0:
        raise ValueError(f"{name} must be positive, got {value!r}")


@dataclass(frozen=True)
class Material:
    """Isotropic elastic material: E (Pa), nu (-), density (kg/m^3)."""

    youngs_modulus: float = 210e9
    poisson_ratio: float = 0.3
    density: float = 7850.0

    def __post_init__(self) -> None:
        _finite("youngs_modulus", self.youngs_modulus)
        _finite("poisson_ratio", self.poisson_ratio, positive=False)
        if not -1.0 < self.poisson_ratio < 0.5:
            raise ValueError(f"poisson_ratio must lie in (-1, 0.5), got {self.poisson_ratio!r}")
        _finite("density", self.density)


STEEL = Material(210e9, 0.3, 7850.0)


@dataclass(frozen=True)
class BallDrag:
    """Drag on each ball's orbital motion (MODEL.md §8, §11c): the sphere's
    F_D = 1/2 C_D rho_eff pi r² v² and, with ``oil_flow``, the jet oil's momentum.

    Parameters
    ----------
    drag_coefficient : float
        C_D (sphere, Re ~ 1e3–1e5: 0.5).
    oil_volume_fraction : float
        Oil fraction of the oil–air mixture in the bearing, in [0, 1];
        rho_eff = fraction * lubricant density. 0 switches the sphere drag off.
    oil_flow : float
        Jet oil through the bearing, m^3/s; > 0 adds its momentum (Euler) loss, the oil
        entering without swirl and leaving at the balls' orbital speed at the outer raceway
        (MODEL.md §11c, eq. 11c.2). 0 (default): none, as the paper. With a ``[thermal]``
        section it must be the network's ``oil_flow`` (one oil).
    """

    drag_coefficient: float = 0.5
    oil_volume_fraction: float = 1.0
    oil_flow: float = 0.0

    def __post_init__(self) -> None:
        _finite("drag_coefficient", self.drag_coefficient, positive=False)
        if self.drag_coefficient < 0:
            raise ValueError(f"drag_coefficient must be non-negative, got {self.drag_coefficient!r}")
        _finite("oil_volume_fraction", self.oil_volume_fraction, positive=False)
        if not 0.0 <= self.oil_volume_fraction <= 1.0:
            raise ValueError(f"oil_volume_fraction must lie in [0, 1], got {self.oil_volume_fraction!r}")
        _finite("oil_flow", self.oil_flow, positive=False)
        if self.oil_flow < 0:
            raise ValueError(f"oil_flow must be non-negative (m^3/s), got {self.oil_flow!r}")

    def __repr__(self) -> str:
        # without a jet, the repr from before the jet: result folders record their inputs by
        # it (studies.grid.guard_folder), and the physics of those is unchanged
        jet = f", oil_flow={self.oil_flow!r}" if self.oil_flow else ""
        return (f"BallDrag(drag_coefficient={self.drag_coefficient!r}, "
                f"oil_volume_fraction={self.oil_volume_fraction!r}{jet})")

    @property
    def active(self) -> bool:
        """Whether any drag acts (the sphere's or the jet's)."""
        return self.drag_coefficient * self.oil_volume_fraction > 0 or self.oil_flow > 0

    def force(self, speed, ball_radius, lubricant_density):
        """Sphere drag force magnitude, N, for the ball-centre speed ``speed`` (m/s) through still oil."""
        rho = self.oil_volume_fraction * lubricant_density
        return 0.5 * self.drag_coefficient * rho * math.pi * ball_radius ** 2 * np.square(speed)

    def momentum_factor(self, bearing, lubricant_density) -> float:
        """k, kg/s, of the jet's momentum force k v on each ball (:func:`contact.cage.jet_momentum_factor`;
        MODEL.md eq. 11c.2), the oil leaving at the outer raceway, r_p + D/2; 0 without ``oil_flow``."""
        if self.oil_flow == 0:
            return 0.0
        return jet_momentum_factor(self.oil_flow, lubricant_density, bearing.pitch_radius,
                                   bearing.pitch_radius + bearing.ball_radius, bearing.balls)


@dataclass(frozen=True)
class Bearing:
    """An angular-contact ball bearing (MODEL.md §2).

    Parameters
    ----------
    balls : int
        Number of balls Z (>= 3).
    ball_diameter : float
        D, m.
    pitch_diameter : float
        d_m, m.
    inner_conformity, outer_conformity : float
        Groove radius / D, each > 0.5.
    contact_angle : float
        Free (unloaded) contact angle a0, rad, in [0, pi/2). Equivalent to the diametral
        clearance, see :attr:`diametral_clearance` and :meth:`from_clearance`.
    ball_material, race_material : Material
    ball_mass : float, optional
        kg; computed from the ball material density if omitted.
    """

    balls: int
    ball_diameter: float
    pitch_diameter: float
    inner_conformity: float
    outer_conformity: float
    contact_angle: float
    ball_material: Material = STEEL
    race_material: Material = STEEL
    ball_mass: float | None = field(default=None)

    def __post_init__(self) -> None:
        if isinstance(self.balls, bool) or not isinstance(self.balls, (int, np.integer)) or self.balls < 3:
            raise ValueError(f"balls must be an integer >= 3, got {self.balls!r}")
        _finite("ball_diameter", self.ball_diameter)
        _finite("pitch_diameter", self.pitch_diameter)
        if self.ball_diameter >= self.pitch_diameter:
            raise ValueError(f"ball_diameter {self.ball_diameter} m must be smaller than pitch_diameter {self.pitch_diameter} m")
        for name in ("inner_conformity", "outer_conformity"):
            value = getattr(self, name)
            _finite(name, value)
            if value <= 0.5:
                raise ValueError(f"{name} must be > 0.5 (groove radius larger than the ball radius), got {value!r}")
        _finite("contact_angle", self.contact_angle, positive=False)
        if not 0.0 <= self.contact_angle < math.pi / 2:
            raise ValueError(f"contact_angle must lie in [0, 90) degrees, got {math.degrees(self.contact_angle)!r} degrees")
        chord = self.pitch_diameter * math.sin(math.pi / self.balls)
        if chord <= self.ball_diameter:
            raise ValueError(
                f"balls: {self.balls} balls of diameter {self.ball_diameter} m overlap on the pitch circle "
                f"(neighbour spacing {chord:.6g} m); at most {self._max_balls()} fit")
        for name in ("ball_material", "race_material"):
            if not isinstance(getattr(self, name), Material):
                raise ValueError(f"{name} must be a Material, got {getattr(self, name)!r}")
        if self.ball_mass is None:
            object.__setattr__(self, "ball_mass", self.ball_material.density * math.pi * self.ball_diameter ** 3 / 6.0)
        _finite("ball_mass", self.ball_mass)

    def _max_balls(self) -> int:
        return max(int(math.pi / math.asin(min(1.0, self.ball_diameter / self.pitch_diameter))) - 1, 0)

    @classmethod
    def from_clearance(cls, *, diametral_clearance: float, **kwargs) -> "Bearing":
        """Build from the diametral clearance P_d (m) instead of the free contact angle."""
        _finite("diametral_clearance", diametral_clearance, positive=False)
        if diametral_clearance < 0:
            raise ValueError(f"diametral_clearance must be non-negative, got {diametral_clearance!r}")
        for name in ("ball_diameter", "inner_conformity", "outer_conformity"):
            _finite(name, kwargs.get(name, float("nan")))
        try:
            angle = geometry.free_contact_angle(diametral_clearance, kwargs["inner_conformity"],
                                                kwargs["outer_conformity"], kwargs["ball_diameter"])
        except ValueError as err:
            raise ValueError(f"diametral_clearance: {err}") from None
        return cls(contact_angle=angle, **kwargs)

    # ---- derived quantities -------------------------------------------------------
    @property
    def ball_radius(self) -> float:
        """r = D/2, m."""
        return 0.5 * self.ball_diameter

    @property
    def pitch_radius(self) -> float:
        """r_p = d_m/2, m."""
        return 0.5 * self.pitch_diameter

    @property
    def inner_groove_radius(self) -> float:
        """f_i D, m."""
        return self.inner_conformity * self.ball_diameter

    @property
    def outer_groove_radius(self) -> float:
        """f_o D, m."""
        return self.outer_conformity * self.ball_diameter

    @property
    def diametral_clearance(self) -> float:
        """P_d, m (MODEL.md §2)."""
        return float(geometry.diametral_clearance(self.contact_angle, self.inner_conformity,
                                                  self.outer_conformity, self.ball_diameter))

    @property
    def groove_centre_distance(self) -> float:
        """A = (f_i + f_o - 1) D, distance of the two groove centres when unloaded, m."""
        return (self.inner_conformity + self.outer_conformity - 1.0) * self.ball_diameter

    @property
    def ball_inertia(self) -> float:
        """Moment of inertia of a ball about its centre, 2/5 m r², kg m²."""
        return 0.4 * self.ball_mass * self.ball_radius ** 2

    @cached_property
    def effective_modulus(self) -> float:
        """E' of the ball–race pair, Pa (MODEL.md §3)."""
        m1, m2 = self.ball_material, self.race_material
        return float(hertz.effective_modulus(m1.youngs_modulus, m1.poisson_ratio, m2.youngs_modulus, m2.poisson_ratio))

    def groove_centres(self):
        """Inner and outer groove-centre circles ((radius, z), (radius, z)), m; see
        :func:`contact.geometry.groove_centres`."""
        return geometry.groove_centres(self.pitch_radius, self.ball_diameter, self.contact_angle,
                                       self.inner_conformity, self.outer_conformity)

    def curvature_radii(self, contact_angle, race: str):
        """(R_x, R_y) of the ``race`` contact at ``contact_angle`` (rad), m."""
        conformity = self.inner_conformity if race == "inner" else self.outer_conformity
        return geometry.curvature_radii(self.ball_diameter, self.pitch_diameter, contact_angle, conformity, race)

    def hertz(self, contact_angle, race: str, method: str = "fit") -> hertz.HertzContact:
        """Hertz constants of the ``race`` contact at ``contact_angle`` (rad)."""
        r_x, r_y = self.curvature_radii(contact_angle, race)
        return hertz.hertz_contact(r_x, r_y, self.effective_modulus, method=method)

    def cage_speed(self, inner_speed: float, outer_speed: float = 0.0, contact_angle: float | None = None) -> float:
        """Pure-rolling cage speed with the nominal angle, rad/s (P19 generalized):
        w_c = w_i/2 (1 - g) + w_o/2 (1 + g), g = D cos a / d_m."""
        angle = self.contact_angle if contact_angle is None else contact_angle
        gamma = self.ball_diameter * math.cos(angle) / self.pitch_diameter
        return 0.5 * inner_speed * (1.0 - gamma) + 0.5 * outer_speed * (1.0 + gamma)

    def expanded(self, rise_inner: float, rise_outer: float, rise_balls: float, ring_expansion: float,
                 ball_expansion: float) -> "Bearing":
        """This bearing at running temperatures (MODEL.md §14f, eq. 14.9): the rings and balls
        grown by their linear expansion coefficients (1/K) times their rises above the assembly
        temperature (K); the ball mass kept. A ValueError where the expansion closes the
        clearance (:func:`contact.thermal_expansion.heated_geometry`)."""
        return self.grown(heated_geometry(self.ball_diameter, self.pitch_diameter, self.contact_angle,
                                          self.inner_conformity, self.outer_conformity, rise_inner, rise_outer,
                                          rise_balls, ring_expansion, ball_expansion))

    def grown(self, geometry: HeatedGeometry) -> "Bearing":
        """This bearing with the sizes of ``geometry`` (:func:`contact.thermal_expansion.heated_geometry`
        of this bearing, MODEL.md §14f), its ball mass and materials kept."""
        return replace(self, ball_diameter=geometry.ball_diameter, pitch_diameter=geometry.pitch_diameter,
                       inner_conformity=geometry.inner_conformity, outer_conformity=geometry.outer_conformity,
                       contact_angle=geometry.contact_angle, ball_mass=self.ball_mass)
