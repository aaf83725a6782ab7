"""The cage of a bearing model (MODEL.md §1, §11d): how it is modelled, guided and loaded.
The forces themselves are :mod:`contact.cage`'s; :class:`~exudyn_bearing.model.connector.BearingConnector`
applies them."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact import cage as cage_physics
from contact import land_film
from .bearing import Bearing

__all__ = ["CageModel"]


@dataclass(frozen=True)
class CageModel:
    """Ball–cage interaction (MODEL.md §1).

    Parameters
    ----------
    kind : {'rigid', 'spring-chain', 'none'}
        A rigid cage body with Z pockets, the paper's springs between neighbouring balls
        (P9, P10), or no cage at all.
    stiffness : float
        Pocket (or chain spring) stiffness, N/m (paper: 1e8).
    damping : float or None
        N s/m; None: 5 % of critical for a ball on the pocket stiffness.
    clearance : float
        Circumferential pocket play, m (rigid cage).
    mass : float or None
        Cage mass, kg; None: a brass ring of width D and thickness 0.3 D, half of it
        pockets.
    guidance : {'outer', 'inner', 'balls'}
        Rigid cage: what centres it radially. 'outer'/'inner': the cage ring runs in that
        race's guiding land with diametral play ``guide_clearance`` (contact stiffness
        ``guide_stiffness``, damping ``guide_damping``; radial force through the centres,
        no land friction). 'balls': only the pockets hold it; the ring can then drift
        radially without bound — at medium axial loads (0.7–1 kN at 1800 rpm) the skidding
        balls drive a growing whirl that reaches millimetres by 0.5 s and wrecks the run.
    guide_clearance : float
        Diametral land play, m (default 0.4 mm: an assumed, typical order for a 155 mm
        pitch diameter; the paper has no cage body).
    guide_stiffness : float
        Land contact stiffness, N/m.
    guide_damping : float or None
        N s/m; None: 20 % of critical for the cage mass on ``guide_stiffness``. It rises from
        zero over the first ``contact.cage.LAND_DAMPING_DEPTH`` (10 um) of penetration, so a
        cage closing on its land at speed meets a force that starts from zero.
    land_width : float
        Axial width L of the guiding land, m; > 0 adds the oil film's friction torque between
        cage and land (MODEL.md §11d: the short-journal shear torque
        2 π η0 R³ L (w_race - w_cage) / (c √(1 - ε²))). 0 (default): no land friction.
    land_film : bool
        With ``land_width`` > 0: the land's oil film also carries the cage radially, Ocvirk's
        short journal bearing (MODEL.md §11d, eq. 11d.1), so the eccentricity ratio ε follows
        from the cage's radial load (ε taken at most 0.995). False: only the contact beyond
        the play carries it, and the torque takes ε at most 0.95 (the model before session 34).
    land_radius : float or None
        Radius R of the guiding land, m; None: r_p + D/2 (outer guidance) or r_p - D/2 (inner),
        the land at the balls' edge.
    pocket_friction : float
        Sliding friction coefficient mu at the ball–pocket contacts (rigid cage; MODEL.md
        §11d: regularized Coulomb at the contact point, so it resists the balls' spin and
        drags the cage). 0 (default): frictionless pockets, as the paper.
    pocket_slip_scale : float
        Slip speed v_s, m/s, below which the pocket friction is viscous (mu N v / v_s).
    """

    kind: str = "rigid"
    stiffness: float = 1e8
    damping: float | None = None
    clearance: float = 0.0
    mass: float | None = None
    guidance: str = "outer"
    guide_clearance: float = 0.4e-3
    guide_stiffness: float = 1e7
    guide_damping: float | None = None
    land_width: float = 0.0
    land_film: bool = True
    land_radius: float | None = None
    pocket_friction: float = 0.0
    pocket_slip_scale: float = 0.01

    def __post_init__(self) -> None:
        if self.kind not in ("rigid", "spring-chain", "none"):
            raise ValueError(f"kind must be 'rigid', 'spring-chain' or 'none', got {self.kind!r}")
        if self.guidance not in ("outer", "inner", "balls"):
            raise ValueError(f"guidance must be 'outer', 'inner' or 'balls', got {self.guidance!r}")
        for name in ("stiffness", "clearance", "guide_clearance", "guide_stiffness", "land_width", "pocket_friction"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value >= 0):
                raise ValueError(f"{name} must be finite and >= 0, got {value!r}")
        for name in ("damping", "guide_damping"):
            value = getattr(self, name)
            if value is not None and not (np.isfinite(value) and value >= 0):
                raise ValueError(f"{name} must be finite and >= 0, got {value!r}")
        if not isinstance(self.land_film, (bool, np.bool_)):
            raise ValueError(f"land_film must be True or False, got {self.land_film!r}")
        if self.mass is not None and not (np.isfinite(self.mass) and self.mass > 0):
            raise ValueError(f"mass must be positive, got {self.mass!r}")
        if self.land_radius is not None and not (np.isfinite(self.land_radius) and self.land_radius > 0):
            raise ValueError(f"land_radius must be positive, got {self.land_radius!r}")
        if self.land_width > 0 and (self.kind != "rigid" or self.guidance == "balls"):
            raise ValueError("land_width: land friction needs a rigid cage guided by a race land "
                             "(kind='rigid', guidance='inner' or 'outer')")
        if not (np.isfinite(self.pocket_slip_scale) and self.pocket_slip_scale > 0):
            raise ValueError(f"pocket_slip_scale must be positive, got {self.pocket_slip_scale!r}")
        if self.pocket_friction > 0 and self.kind != "rigid":
            raise ValueError("pocket_friction: pocket friction needs a rigid cage (kind='rigid')")
        if self.land_width > 0 and self.guide_clearance <= 0:
            raise ValueError("land_width: the land friction needs a guide_clearance > 0 (its oil film)")

    def land_friction_constant(self, bearing, lubricant) -> float:
        """K = 2 π η0 R³ L / c of the guiding land's friction torque K (w_land - w_cage) /
        √(1 - ε²), N m s (MODEL.md §11d); 0 without land friction."""
        if self.land_width <= 0 or not self.guided:
            return 0.0
        return float(cage_physics.land_friction_constant(lubricant.viscosity, self.land_radius_for(bearing),
                                                         self.land_width, 0.5 * self.guide_clearance))

    def land_film_constant(self, bearing, lubricant) -> float:
        """K = η0 R L³ / c² of the land film's short-bearing force (MODEL.md §11d, eq. 11d.1),
        N s; 0 without it (no land width, or ``land_film`` False)."""
        if self.land_width <= 0 or not self.guided or not self.land_film:
            return 0.0
        return float(land_film.film_constant(lubricant.viscosity, self.land_radius_for(bearing), self.land_width,
                                             0.5 * self.guide_clearance))

    @property
    def land_max_ratio(self) -> float:
        """The largest ε the land's friction torque (and film force) take: 0.995 with the film's
        force, whose ε follows from the load; 0.95 without (the cage then rides its land)."""
        return land_film.LAND_FILM_MAX_RATIO if self.land_film else 0.95

    def land_radius_for(self, bearing) -> float:
        """R of the guiding land, m: ``land_radius`` or the balls' edge r_p ± D/2."""
        side = 1.0 if self.guidance == "outer" else -1.0
        return float(self.land_radius or bearing.pitch_radius + side * bearing.ball_radius)

    def centred_land_load(self, bearing, lubricant, inner_speed: float, outer_speed: float) -> tuple:
        """(K of :meth:`land_friction_constant`, the guiding race's speed rad/s) for the
        steady and quasi-dynamic solvers, whose centred cage takes the land torque
        K (w_land - w_cage); (0, 0) without land friction."""
        friction = self.land_friction_constant(bearing, lubricant)
        if friction <= 0:
            return 0.0, 0.0
        return friction, outer_speed if self.guidance == "outer" else inner_speed

    def damping_for(self, ball_mass: float) -> float:
        return 2 * 0.05 * np.sqrt(self.stiffness * ball_mass) if self.damping is None else self.damping

    def mass_for(self, bearing: Bearing) -> float:
        """Cage mass, kg (``mass`` or the default brass ring)."""
        d = bearing.ball_diameter
        return self.mass or 8500.0 * 2 * np.pi * bearing.pitch_radius * (0.3 * d) * d * 0.5

    def land_seat(self, force, film: float = 0.0, spin_sum: float = 0.0) -> np.ndarray:
        """Where a land-guided cage sits under the net radial ``force`` its pockets put on it
        (bearing frame, N), m; the centre for a cage without a land or without a force. With
        the land film's constant ``film`` K > 0 (N s, :meth:`land_film_constant`) and the
        surfaces' speeds ``spin_sum`` ω_cage + ω_land (rad/s): where Ocvirk's film carries it
        (MODEL.md §11d, eq. 11d.1: ε from W(ε) = |F|, the offset turned from the force by the
        attitude angle); else, or where the film cannot carry the force, on its land in the
        force's direction, pressed in by force / stiffness (:func:`contact.cage.land_forces`).
        Under combined load the pockets push the cage there within a few milliseconds (0.2 mm
        in 7 ms on the reference bearing at 2.8 kN + 0.85 kN)."""
        radial = np.array([force[0], force[1], 0.0], dtype=float)
        size = float(np.linalg.norm(radial))
        if not self.guided or size == 0.0:
            return np.zeros(3)
        u = radial / size
        if film > 0 and spin_sum != 0:
            eps = land_film.steady_eccentricity(size, film, spin_sum, self.land_max_ratio)
            if eps is not None:
                f_r, f_t = land_film.short_bearing_force(eps, 0.0, 0.0, spin_sum, film, self.land_max_ratio)
                beta = math.atan2(f_t, f_r)  # film force −F_r n + F_t (e_z × n) = −force
                turned = math.cos(beta) * u + math.sin(beta) * np.array([-u[1], u[0], 0.0])
                return turned * eps * 0.5 * self.guide_clearance
        return u * (0.5 * self.guide_clearance + size / self.guide_stiffness)

    @property
    def guided(self) -> bool:
        """A rigid cage centred by a race land."""
        return self.kind == "rigid" and self.guidance != "balls"
