"""Race surfaces that are not perfect: local defects (spall, EDM notch), race waviness and
ball-diameter variation (MODEL.md §13; beyond the paper).

A surface enters a ball–race contact as a **height** h of the race surface toward the ball
at the contact (m; > 0 raises the surface, more elastic approach): the approach becomes
δ + h and its rate dδ/dt + (dh/dθ) θ̇, θ the contact's azimuth in the race's own frame (an
inner-race defect turns with the shaft) and θ̇ the ball's orbital speed relative to that
race. The law is :func:`race_height`, a scalar numba function that both force paths call
per contact through :func:`contact.terms.surface_height` (stage 0 of the extension point).

* **Waviness** of a race: h = Σ A_k cos(k θ + φ_k) (MODEL.md eq. 13.1).
* **Ball-diameter variation**: ball j's radius is larger by ΔD_j / 2 at both its contacts.
* **Local defect** of length L (along the rolling direction), depth d, width w (across), at
  azimuth θ_d: the ball has finite size, so over the defect its centre follows the geometric
  path of a ball resting on the edges (Sawalhi & Randall 2011, MSSP 25, 846). Ball and race
  are both curved along the rolling direction, so the ball sinks into a gap between the
  edges as a sphere of the contact's reduced radius R_x = (1/r ± 1/R_race)⁻¹ sinks into a gap
  in a flat surface (to second order in the gap; a flat race gives R_x = r):

      drop(x) = min(p(x), s(x), s(L − x)),   s(u) = R_x − √(R_x² − u²),  h = −drop   (13.2)

  x the contact's arc position from the entry edge, p(x) the depth profile (d; with an edge
  ramp of length e: d min(1, x/e, (L − x)/e)). The ball unloads gradually past the entry
  edge and is re-stressed at the exit edge; over a notch shorter than 2√(d (2 R_x − d)) it
  never reaches the bottom (its reach is s(L/2), :meth:`Defect.reach`). The contact normal
  stays the groove's (the edge's own normal is not modelled).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from numba import njit

from .geometry import contact_path_radius

__all__ = ["Defect", "Waviness", "SurfaceModel", "SurfaceRecord", "NO_SURFACE", "surface_record", "race_height",
           "race_heights", "sag"]

RACES = ("inner", "outer")


def _number(key: str, value, *, positive: bool = True, allow_zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)) \
            or not math.isfinite(value):
        raise ValueError(f"{key} must be a finite number, got {value!r}")
    if positive and (value < 0 or (value == 0 and not allow_zero)):
        raise ValueError(f"{key} must be {'>= 0' if allow_zero else 'positive'}, got {value!r}")
    return float(value)


def sag(u: float, radius: float) -> float:
    """Drop of a sphere of ``radius`` (m; the contact's reduced radius R_x) resting on an edge at
    horizontal distance ``u`` (m): R − √(R² − u²) (eq. 13.2), R for u ≥ R."""
    return radius if u >= radius else radius - math.sqrt(radius * radius - u * u)


@dataclass(frozen=True)
class Defect:
    """A local defect (spall, EDM notch) on a race (MODEL.md eq. 13.2).

    Parameters
    ----------
    race : {'inner', 'outer'}
    angle_deg : float
        Azimuth of its centre in the race's own frame, degrees (an inner-race defect turns
        with the inner race).
    length : float
        Along the rolling direction, m (arc length on the contact path).
    depth : float
        m. A ball reaches s(L/2) of it (:meth:`reach`); a deeper notch is allowed and stated.
    width : float or None
        Across the raceway, m (arc length on the groove section); None: the whole raceway.
    offset : float
        Across the raceway, of its centre line from the nominal contact path, m (arc length on
        the groove section, toward larger contact angles).
    edge : float
        Length of the depth ramp at each edge, m; 0: a sharp edge (an EDM notch).
    """

    race: str
    angle_deg: float
    length: float
    depth: float
    width: float | None = None
    offset: float = 0.0
    edge: float = 0.0

    def __post_init__(self) -> None:
        if self.race == "ball":
            raise ValueError("defect.race: a defect on a ball is not modelled yet (races 'inner' or 'outer'); "
                             "model an oversize ball with waviness.ball_diameter_variation")
        if self.race not in RACES:
            raise ValueError(f"defect.race must be 'inner' or 'outer', got {self.race!r}")
        _number("defect.angle_deg", self.angle_deg, positive=False)
        _number("defect.length", self.length)
        _number("defect.depth", self.depth)
        if self.width is not None:
            _number("defect.width", self.width)
        _number("defect.offset", self.offset, positive=False)
        _number("defect.edge", self.edge, allow_zero=True)
        if 2.0 * self.edge > self.length:
            raise ValueError(f"defect.edge: two edge ramps of {self.edge} m do not fit the length {self.length} m")

    def reach(self, radius: float) -> float:
        """Deepest point a ball reaches in this defect, m: min(d, s(L/2)) (eq. 13.2) with
        ``radius`` the contact's reduced radius R_x along the rolling direction, m
        (:func:`contact.geometry.curvature_radii`)."""
        return min(self.depth, sag(0.5 * self.length, radius))


def _waviness_rows(key: str, rows) -> tuple:
    out = []
    for row in rows:
        if len(row) != 3:
            raise ValueError(f"{key}: each entry is [order, amplitude_m, phase_deg], got {row!r}")
        order, amplitude, phase = row
        if isinstance(order, bool) or not isinstance(order, (int, np.integer)) or order < 2:
            raise ValueError(f"{key}: waviness order must be an integer >= 2 (orders 0 and 1 are a size and "
                             f"a shift of the race), got {order!r}")
        _number(f"{key}: amplitude", amplitude)
        _number(f"{key}: phase_deg", phase, positive=False)
        out.append((int(order), float(amplitude), float(phase)))
    return tuple(out)


@dataclass(frozen=True)
class Waviness:
    """Race waviness and ball-diameter variation (MODEL.md eq. 13.1).

    Parameters
    ----------
    inner, outer : sequence of (order, amplitude_m, phase_deg)
        h(θ) = Σ A cos(k θ + φ), θ the azimuth in the race's own frame; order k >= 2,
        amplitude A > 0 (m).
    ball_diameter_variation : sequence of float
        ΔD of each ball, m (> 0: oversize), one per ball; empty: none.
    """

    inner: tuple = ()
    outer: tuple = ()
    ball_diameter_variation: tuple = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "inner", _waviness_rows("waviness.inner", self.inner))
        object.__setattr__(self, "outer", _waviness_rows("waviness.outer", self.outer))
        variation = tuple(_number("waviness.ball_diameter_variation", v, positive=False)
                          for v in self.ball_diameter_variation)
        object.__setattr__(self, "ball_diameter_variation", variation)

    @property
    def active(self) -> bool:
        return bool(self.inner or self.outer or any(self.ball_diameter_variation))


@dataclass(frozen=True)
class SurfaceModel:
    """The surfaces of a bearing: local ``defects`` and ``waviness``. ``SurfaceModel()`` is a
    perfect bearing (costs nothing)."""

    defects: tuple = ()
    waviness: Waviness = field(default_factory=Waviness)

    def __post_init__(self) -> None:
        defects = tuple(self.defects)
        for d in defects:
            if not isinstance(d, Defect):
                raise ValueError(f"defects must be Defect records, got {d!r}")
        object.__setattr__(self, "defects", defects)
        if not isinstance(self.waviness, Waviness):
            raise ValueError(f"waviness must be a Waviness record, got {self.waviness!r}")

    @property
    def active(self) -> bool:
        return bool(self.defects) or self.waviness.active


class SurfaceRecord(NamedTuple):
    """A :class:`SurfaceModel` as the kernels read it (empty arrays: off)."""

    waviness: np.ndarray  #: (n, 4): race (0 inner, 1 outer), order, amplitude m, phase rad
    #: (n, 8): race, azimuth rad, length m, depth m, half width m (inf: all), offset m, edge m,
    #: groove radius f D m (the arc across the raceway per radian of contact angle)
    defects: np.ndarray
    ball_excess: np.ndarray  #: (Z,) radius excess ΔD/2 of each ball, m; (0,): none
    nominal_angle: float  #: the bearing's contact angle, rad (the defects' offset is from it)


NO_SURFACE = SurfaceRecord(np.zeros((0, 4)), np.zeros((0, 8)), np.zeros(0), 0.0)


def surface_record(surface: SurfaceModel | None, bearing) -> SurfaceRecord:
    """The :class:`SurfaceRecord` of ``surface`` on ``bearing`` (anything with ``balls``,
    ``ball_diameter``, ``pitch_diameter``, ``inner_conformity``, ``outer_conformity``,
    ``contact_angle``), checked against its geometry: a defect longer than its race's
    circumference or wider than the groove, a wrong number of ball-diameter variations."""
    if surface is None or not surface.active:
        return NO_SURFACE
    if not isinstance(surface, SurfaceModel):
        raise ValueError(f"surface must be a SurfaceModel, got {surface!r}")
    diam, dm, alpha = float(bearing.ball_diameter), float(bearing.pitch_diameter), float(bearing.contact_angle)
    rows = []
    for d in surface.defects:
        k = RACES.index(d.race)
        conformity = bearing.inner_conformity if k == 0 else bearing.outer_conformity
        circumference = 2.0 * math.pi * contact_path_radius(diam, dm, alpha, d.race)
        if d.length >= circumference:
            raise ValueError(f"defect.length: {d.length} m is longer than the {d.race} race's circumference "
                             f"{circumference:.6g} m")
        groove_arc = math.pi * conformity * diam  # the half torus of the groove section
        if d.width is not None and d.width > groove_arc:
            raise ValueError(f"defect.width: {d.width} m is wider than the {d.race} groove ({groove_arc:.6g} m of arc)")
        half = math.inf if d.width is None else 0.5 * d.width
        rows.append((k, math.radians(d.angle_deg), d.length, d.depth, half, d.offset, d.edge, conformity * diam))
    w = surface.waviness
    waves = [(k, order, amp, math.radians(phase)) for k, name in enumerate(RACES)
             for order, amp, phase in getattr(w, name)]
    excess = np.zeros(0)
    if any(w.ball_diameter_variation):
        if len(w.ball_diameter_variation) != bearing.balls:
            raise ValueError(f"waviness.ball_diameter_variation: one value per ball ({bearing.balls}), got "
                             f"{len(w.ball_diameter_variation)}")
        excess = 0.5 * np.asarray(w.ball_diameter_variation, dtype=float)
        if np.any(excess <= -0.5 * diam):
            raise ValueError("waviness.ball_diameter_variation: a ball would have no diameter")
    return SurfaceRecord(np.array(waves, dtype=float).reshape(-1, 4), np.array(rows, dtype=float).reshape(-1, 8),
                         excess, alpha)


@njit(cache=True, error_model="numpy")
def race_height(surface, race, theta, contact_angle, point_radius, ball, rolling_radius):
    """(h, dh/dθ) of ``race`` (0 inner, 1 outer) at the contact of ``ball`` (MODEL.md §13):
    h the surface height toward the ball, m (eq. 13.1, 13.2, the ball's radius excess);
    θ the contact's azimuth in the race frame (rad), ``contact_angle`` rad,
    ``point_radius`` the contact point's distance from the race axis (m),
    ``rolling_radius`` the contact's reduced radius R_x along the rolling direction (m)."""
    h = 0.0
    dh = 0.0
    waves = surface.waviness
    for i in range(waves.shape[0]):
        if int(waves[i, 0]) == race:
            arg = waves[i, 1] * theta + waves[i, 3]
            h += waves[i, 2] * math.cos(arg)
            dh -= waves[i, 2] * waves[i, 1] * math.sin(arg)
    if surface.ball_excess.shape[0] > 0:
        h += surface.ball_excess[ball]
    defects = surface.defects
    for i in range(defects.shape[0]):
        if int(defects[i, 0]) != race:
            continue
        length, depth, edge = defects[i, 2], defects[i, 3], defects[i, 6]
        # arc position from the entry edge (the defect's lower azimuth), wrapped to [-pi, pi)
        rel = (theta - defects[i, 1] + math.pi) % (2.0 * math.pi) - math.pi
        x = rel * point_radius + 0.5 * length
        if x <= 0.0 or x >= length:
            continue
        across = defects[i, 7] * (contact_angle - surface.nominal_angle) - defects[i, 5]
        if abs(across) > defects[i, 4]:
            continue
        drop = depth
        slope = 0.0  # d drop / dx
        if edge > 0.0:
            ramp = min(x, length - x)
            if ramp < edge:
                drop = depth * ramp / edge
                slope = depth / edge if x < length - x else -depth / edge
        u = min(x, length - x)  # the nearer edge carries the ball (eq. 13.2)
        if u < rolling_radius:
            s = rolling_radius - math.sqrt(rolling_radius * rolling_radius - u * u)
            if s < drop:
                drop = s
                slope = u / (rolling_radius - s)
                if x > length - x:
                    slope = -slope
        h -= drop
        dh -= slope * point_radius
    return h, dh


@njit(cache=True, error_model="numpy")
def _race_heights(surface, race, theta, contact_angle, point_radius, ball, rolling_radius, out):
    for i in range(theta.shape[0]):
        out[0, i], out[1, i] = race_height(surface, race[i], theta[i], contact_angle[i], point_radius[i], ball[i],
                                           rolling_radius[i])


def race_heights(surface: SurfaceRecord, race, theta, contact_angle, point_radius, ball, rolling_radius) -> np.ndarray:
    """:func:`race_height` for n contacts (arrays (n,) or scalars; the numpy path): rows (h m,
    dh/dθ m/rad), (2, n)."""
    theta = np.ascontiguousarray(theta, dtype=float)
    n = theta.shape[0]

    def arr(x, dtype=float):
        return np.ascontiguousarray(np.broadcast_to(np.asarray(x, dtype=dtype), (n,)))

    out = np.empty((2, n))
    _race_heights(surface, arr(race, np.int64), theta, arr(contact_angle), arr(point_radius), arr(ball, np.int64),
                  arr(rolling_radius), out)
    return out
