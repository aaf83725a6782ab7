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
  tilts with the centre's path: the load acts along −(n + (dh/dθ)/ρ_c t1), ρ_c the ball
  centre's radius — the line from the edge to the centre — through the ball centre (eq. 13.7;
  the kernels apply it, this module gives dh/dθ).

Pits and waviness on a ball, which turn with the ball's material, are in
:mod:`contact.ball_surface` (eq. 13.3, 13.6).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from numba import njit

from .geometry import contact_path_radius

__all__ = ["Defect", "Waviness", "SurfaceModel", "SurfaceRecord", "NO_SURFACE", "surface_record", "race_height",
           "race_heights", "path_drop", "rim_drop", "ball_circles", "sag", "SHAPES"]

RACES = ("inner", "outer")
PLACES = RACES + ("ball",)


def _number(key: str, value, *, positive: bool = True, allow_zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)) \
            or not math.isfinite(value):
        raise ValueError(f"{key} must be a finite number, got {value!r}")
    if positive and (value < 0 or (value == 0 and not allow_zero)):
        raise ValueError(f"{key} must be {'>= 0' if allow_zero else 'positive'}, got {value!r}")
    return float(value)


@njit(cache=True, error_model="numpy")
def sag(u, radius):
    """Drop of a sphere of ``radius`` (m; a contact's reduced radius, R_x along the rolling
    direction, R_y across it) resting on an edge at horizontal distance ``u`` (m):
    R − √(R² − u²) (eq. 13.2), R for u ≥ R."""
    if u >= radius:
        return radius
    return radius - math.sqrt(radius * radius - u * u)


#: the outlines of a race defect (:class:`Defect`)
SHAPES = ("rectangle", "ellipse")


@dataclass(frozen=True)
class Defect:
    """A local defect (spall, EDM notch) on a race, or a pit on a ball (MODEL.md eq. 13.2, 13.3).

    Parameters
    ----------
    race : {'inner', 'outer', 'ball'}
    angle_deg : float
        On a race: azimuth of its centre in the race's own frame, degrees (an inner-race
        defect turns with the inner race). On a ball: degrees from the ball's outer-race
        contact at the start about its start spin axis relative to the cage, i.e. on the
        circle that contact traces on the ball (:func:`ball_circles`). The inner contact
        traces the same circle only where the contact line is perpendicular to the spin axis
        (a deep-groove bearing under radial load): there the pit meets both races.
    length : float
        Along the rolling direction, m (arc length on the contact path); on a ball, the
        diameter of a round pit (arc length on the ball, eq. 13.3).
    depth : float
        m. A ball reaches s(L/2) of it (:meth:`reach`); a deeper notch is allowed and stated.
    width : float or None
        Across the raceway, m (arc length on the groove section); None: a rectangle crosses
        the whole track (the vibration command says so), an ellipse is round (width = length).
        Not for a ball (a round pit).
    offset : float
        Across the raceway, of its centre line from the nominal contact path, m (arc length on
        the groove section, toward larger contact angles). Not for a ball.
    edge : float
        Length of the depth ramp at each edge, m; 0: a sharp edge (an EDM notch).
    ball : int or None
        Index of the ball (0 .. Z - 1) for ``race = 'ball'``; None otherwise.
    shape : {'rectangle', 'ellipse'}
        The outline on a race: a rectangle (an EDM notch, a line spall) or an ellipse (a round
        pit). Over either the ball sinks until it rests on the outline's edges, along and
        across the groove (eq. 13.2, 13.2b): a defect narrower than the contact is bridged.
    """

    race: str
    angle_deg: float
    length: float
    depth: float
    width: float | None = None
    offset: float = 0.0
    edge: float = 0.0
    ball: int | None = None
    shape: str = "rectangle"

    def __post_init__(self) -> None:
        if self.race not in PLACES:
            raise ValueError(f"defect.race must be 'inner', 'outer' or 'ball', got {self.race!r}")
        if self.shape not in SHAPES:
            raise ValueError(f"defect.shape must be one of {SHAPES}, got {self.shape!r}")
        if self.race == "ball" and self.shape != "rectangle":
            raise ValueError("defect.shape: a ball defect is a round pit of diameter `length`; shape is for a race")
        if self.race == "ball":
            if isinstance(self.ball, bool) or not isinstance(self.ball, (int, np.integer)) or self.ball < 0:
                raise ValueError(f"defect.ball: a ball defect needs the ball's index (an integer >= 0), got "
                                 f"{self.ball!r}")
            if self.width is not None or self.offset != 0.0:
                raise ValueError("defect.width: a ball defect is a round pit of diameter `length`; width and "
                                 "offset are for a race")
        elif self.ball is not None:
            raise ValueError(f"defect.ball: only a ball defect (race = 'ball') has a ball index, got {self.ball!r}")
        _number("defect.angle_deg", self.angle_deg, positive=False)
        _number("defect.length", self.length)
        _number("defect.depth", self.depth)
        if self.width is not None:
            _number("defect.width", self.width)
        _number("defect.offset", self.offset, positive=False)
        _number("defect.edge", self.edge, allow_zero=True)
        if 2.0 * self.edge > self.length:
            raise ValueError(f"defect.edge: two edge ramps of {self.edge} m do not fit the length {self.length} m")
        if self.shape == "ellipse" and self.edge > 0.0:
            raise ValueError("defect.edge: an elliptical pit has sharp edges (eq. 13.2c); edge ramps are for a "
                             "rectangle")

    def reach(self, radius: float, across_radius: float = math.inf) -> float:
        """Deepest point a ball reaches in this defect, m, with ``radius`` the contact's
        reduced radius R_x along the rolling direction and ``across_radius`` R_y across the
        groove, m (:func:`contact.geometry.curvature_radii`): a rectangle min(d, s_x(L/2),
        s_y(W/2)) (eq. 13.2, 13.2b), an ellipse min(d, (L/2)²/(2 R_x), (W/2)²/(2 R_y)) (13.2c)."""
        if self.shape == "ellipse" or (self.race == "ball" and self.edge == 0.0):  # (a ball's pit is round)
            half = 0.5 * (self.length if self.width is None else self.width)
            return min(self.depth, 0.125 * self.length ** 2 / radius, 0.5 * half * half / across_radius)
        across = math.inf if self.width is None else sag(0.5 * self.width, across_radius)
        return min(self.depth, sag(0.5 * self.length, radius), across)


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
    ball : sequence of (ball, order, amplitude_m, phase_deg)
        Waviness of a ball (eq. 13.6): h = Σ A cos(k φ + φ_k), φ the contact's longitude about
        the ball's start spin axis relative to the cage, from its start outer contact (the
        circle of a ball defect's ``angle_deg``); ball index 0 .. Z - 1, order k >= 2.
    """

    inner: tuple = ()
    outer: tuple = ()
    ball_diameter_variation: tuple = ()
    ball: tuple = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "inner", _waviness_rows("waviness.inner", self.inner))
        object.__setattr__(self, "outer", _waviness_rows("waviness.outer", self.outer))
        variation = tuple(_number("waviness.ball_diameter_variation", v, positive=False)
                          for v in self.ball_diameter_variation)
        object.__setattr__(self, "ball_diameter_variation", variation)
        rows = []
        for row in self.ball:
            if len(row) != 4:
                raise ValueError(f"waviness.ball: each entry is [ball, order, amplitude_m, phase_deg], got {row!r}")
            index = row[0]
            if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or index < 0:
                raise ValueError(f"waviness.ball: the ball index must be an integer >= 0, got {index!r}")
            rows.append((int(index),) + _waviness_rows("waviness.ball", (row[1:],))[0])
        object.__setattr__(self, "ball", tuple(rows))

    @property
    def active(self) -> bool:
        return bool(self.inner or self.outer or any(self.ball_diameter_variation) or self.ball)


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
    #: (n, 10): race, azimuth rad, length m, depth m, half width m (inf: all), offset m, edge m,
    #: groove radius f D m (the arc across the raceway per radian of contact angle), the
    #: contact's reduced radius across the groove R_y m, 1 for an ellipse (else 0)
    defects: np.ndarray
    ball_excess: np.ndarray  #: (Z,) radius excess ΔD/2 of each ball, m; (0,): none
    nominal_angle: float  #: the bearing's contact angle, rad (the defects' offset is from it)
    #: (n, 9): ball, unit direction of the pit's centre in the ball's body frame (3), diameter m,
    #: depth m, edge m, the contact's reduced radius across the groove R_y at the inner and the
    #: outer race m (eq. 13.3)
    ball_defects: np.ndarray = np.zeros((0, 9))
    #: (n, 10): ball, order, amplitude m, phase rad, zero direction (3) and spin axis (3) of its
    #: circle in the ball's body frame (eq. 13.6)
    ball_waviness: np.ndarray = np.zeros((0, 10))

    @property
    def material(self) -> bool:
        """Whether a force depends on where a ball's material is (a ball defect or waviness):
        the ball's orientation enters the contacts (and the Jacobian's rotation columns)."""
        return self.ball_defects.shape[0] + self.ball_waviness.shape[0] > 0


NO_SURFACE = SurfaceRecord(np.zeros((0, 4)), np.zeros((0, 10)), np.zeros(0), 0.0, np.zeros((0, 9)), np.zeros((0, 10)))


def ball_circles(bearing) -> np.ndarray:
    """(Z, 2, 3): per ball, the zero direction and the spin axis (unit vectors in the ball's
    body frame) about which a ball defect's ``angle_deg`` turns it, for balls that start at
    azimuths 2π j / Z in a frame equal to their body frames, spinning about the bearing axis:
    zero = e_r (the outer contact at 0°), axis = e_z. The builder passes its start state's
    (zero: the outer-race contact direction, axis: the spin relative to the cage)."""
    psi = 2.0 * np.pi * np.arange(bearing.balls) / bearing.balls
    out = np.zeros((bearing.balls, 2, 3))
    out[:, 0, 0], out[:, 0, 1], out[:, 1, 2] = np.cos(psi), np.sin(psi), 1.0
    return out


def surface_record(surface: SurfaceModel | None, bearing, circles=None) -> SurfaceRecord:
    """The :class:`SurfaceRecord` of ``surface`` on ``bearing`` (anything with ``balls``,
    ``ball_diameter``, ``pitch_diameter``, ``inner_conformity``, ``outer_conformity``,
    ``contact_angle``), checked against its geometry: a defect longer than its race's
    circumference or wider than the groove, a ball index out of range, a wrong number of
    ball-diameter variations. ``circles``: the balls' start circles (:func:`ball_circles`,
    its default) on which a ball defect's ``angle_deg`` is measured."""
    if surface is None or not surface.active:
        return NO_SURFACE
    if not isinstance(surface, SurfaceModel):
        raise ValueError(f"surface must be a SurfaceModel, got {surface!r}")
    diam, dm, alpha = float(bearing.ball_diameter), float(bearing.pitch_diameter), float(bearing.contact_angle)
    circles = np.asarray(ball_circles(bearing) if circles is None else circles, dtype=float)
    rows, pits = [], []
    for d in surface.defects:
        if d.race == "ball":
            if d.ball >= bearing.balls:
                raise ValueError(f"defect.ball: {d.ball} is not a ball of this bearing (0 .. {bearing.balls - 1})")
            if d.length >= 0.5 * math.pi * diam:
                raise ValueError(f"defect.length: {d.length} m is longer than half the ball's circumference "
                                 f"{0.5 * math.pi * diam:.6g} m")
            zero, axis = circles[d.ball]
            zero = zero / np.linalg.norm(zero)
            axis = axis / np.linalg.norm(axis)
            phi = math.radians(d.angle_deg)  # zero turned about the axis (Rodrigues)
            direction = (math.cos(phi) * zero + math.sin(phi) * np.cross(axis, zero)
                         + (1.0 - math.cos(phi)) * (axis @ zero) * axis)
            across = [f * diam / (2.0 * f - 1.0) for f in (bearing.inner_conformity, bearing.outer_conformity)]
            pits.append((d.ball, *direction, d.length, d.depth, d.edge, *across))
            continue
        k = RACES.index(d.race)
        conformity = bearing.inner_conformity if k == 0 else bearing.outer_conformity
        circumference = 2.0 * math.pi * contact_path_radius(diam, dm, alpha, d.race)
        if d.length >= circumference:
            raise ValueError(f"defect.length: {d.length} m is longer than the {d.race} race's circumference "
                             f"{circumference:.6g} m")
        groove_arc = math.pi * conformity * diam  # the half torus of the groove section
        if d.width is not None and d.width > groove_arc:
            raise ValueError(f"defect.width: {d.width} m is wider than the {d.race} groove ({groove_arc:.6g} m of arc)")
        ellipse = d.shape == "ellipse"
        half = 0.5 * (d.length if d.width is None else d.width) if ellipse else (
            math.inf if d.width is None else 0.5 * d.width)
        # the reduced radius across the groove R_y = f D / (2 f - 1) (MODEL.md §2): a ball
        # spans a defect's width as a sphere of radius R_y spans a gap
        across_radius = conformity * diam / (2.0 * conformity - 1.0)
        rows.append((k, math.radians(d.angle_deg), d.length, d.depth, half, d.offset, d.edge, conformity * diam,
                     across_radius, 1.0 if ellipse else 0.0))
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
    ball_waves = []
    for j, order, amp, phase in w.ball:
        if j >= bearing.balls:
            raise ValueError(f"waviness.ball: {j} is not a ball of this bearing (0 .. {bearing.balls - 1})")
        zero, axis = circles[j]
        ball_waves.append((j, order, amp, math.radians(phase), *(zero / np.linalg.norm(zero)),
                           *(axis / np.linalg.norm(axis))))
    return SurfaceRecord(np.array(waves, dtype=float).reshape(-1, 4), np.array(rows, dtype=float).reshape(-1, 10),
                         excess, alpha, np.array(pits, dtype=float).reshape(-1, 9),
                         np.array(ball_waves, dtype=float).reshape(-1, 10))


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
        half = defects[i, 4]
        if abs(across) > half:
            continue
        if defects[i, 9] > 0.0:  # an ellipse: the ball rests on its rim (eq. 13.2c)
            a = 0.5 * length
            if (x - a) * (x - a) / (a * a) + across * across / (half * half) >= 1.0:
                continue
            drop, slope, _ = rim_drop(x - a, across, a, half, depth, rolling_radius, defects[i, 8])
        else:
            drop, slope = path_drop(x, length, depth, edge, rolling_radius)
            if half < math.inf:  # a width: the ball also rests on the side edges (eq. 13.2b)
                side = sag(half - abs(across), defects[i, 8])
                if side < drop:
                    drop, slope = side, 0.0
        h -= drop
        dh -= slope * point_radius
    return h, dh


#: rim points sampled before the lowest one is refined (:func:`rim_drop`)
RIM_SAMPLES = 64


@njit(cache=True, error_model="numpy")
def rim_drop(x, y, a, b, depth, rolling_radius, across_radius):
    """(drop m, d drop/dx, d drop/dy) of a contact at (``x`` along, ``y`` across; m from the centre) over an
    elliptical defect of semi-axes ``a`` (along) and ``b`` (across), m, and ``depth``: the ball's
    sag surface (x'²/(2 R_x) + y'²/(2 R_y)) meets the rim at its lowest point, or the floor
    (eq. 13.2c). The rim's lowest point: the least of RIM_SAMPLES points, then golden-section
    refinement to 1e-10 rad."""
    best = np.inf
    t_best = 0.0
    for k in range(RIM_SAMPLES):
        t = 2.0 * math.pi * k / RIM_SAMPLES
        dx, dy = a * math.cos(t) - x, b * math.sin(t) - y
        f = dx * dx / (2.0 * rolling_radius) + dy * dy / (2.0 * across_radius)
        if f < best:
            best, t_best = f, t
    lo, hi = t_best - 2.0 * math.pi / RIM_SAMPLES, t_best + 2.0 * math.pi / RIM_SAMPLES
    g = 0.5 * (math.sqrt(5.0) - 1.0)
    while hi - lo > 1e-10:
        t1, t2 = hi - g * (hi - lo), lo + g * (hi - lo)
        d1x, d1y = a * math.cos(t1) - x, b * math.sin(t1) - y
        d2x, d2y = a * math.cos(t2) - x, b * math.sin(t2) - y
        if (d1x * d1x / rolling_radius + d1y * d1y / across_radius
                < d2x * d2x / rolling_radius + d2y * d2y / across_radius):
            hi = t2
        else:
            lo = t1
    t = 0.5 * (lo + hi)
    dx, dy = a * math.cos(t) - x, b * math.sin(t) - y
    f = dx * dx / (2.0 * rolling_radius) + dy * dy / (2.0 * across_radius)
    if depth <= f:
        return depth, 0.0, 0.0
    return f, -dx / rolling_radius, -dy / across_radius  # (the rim point held: its sag's gradient)


@njit(cache=True, error_model="numpy")
def path_drop(x, length, depth, edge, rolling_radius):
    """(drop m, d drop/dx) of the contact at ``x`` (m from the entry edge) over a defect of
    ``length``, ``depth`` and ``edge`` ramps (m), R_x = ``rolling_radius`` (m): eq. 13.2."""
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
    return drop, slope


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
