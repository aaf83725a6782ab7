"""The default time step (docs/MODEL.md §10a) and Newton tolerance (§10b) of a bearing scene.

The implicit solver holds a step of 1e-4 s on the reference bearing; smaller, lighter balls
at the same or higher pressure need a smaller one. The step needed follows (an empirical
correlation, not a derivation) the ball's vibration between its two races: a ball of mass
m on the linearized Hertz springs k = dQ/dδ = 3Q/(2δ) of its inner and outer contacts rings at

    ω_n = √((k_i + k_o) / m).

Measured (generalized-alpha, default law, docs/MODEL.md §10a): the reference bearing
at 1.3, 2.2 + 2 radial and 10 kN runs without a step cut at 1e-4 s, ω_n h = 5.6–7.8; the
deep-groove 6205-size bearing at 1 kN radial + 200 N ran 215 steps for 200 nominal at
2.5e-5 s (ω_n h = 5.4) and 157 for 143 at 3.5e-5 s; the 7-mm-ball spindle bearing at
12 000 rpm held 5e-5 s axial (ω_n h = 12.9) and cut ~6 % of its steps at 2.5e-5 s with
radial load (ω_n h = 7.6). The default step is the nominal 1e-4 s divided by the smallest
whole number that brings ω_n h to 8 or below, so the output period of 1e-4 s stays a
multiple of it; at that step the radially loaded small-ball cases still cut 6–9 % of their
steps.

At speed a second limit takes over: the balls' orbit. Exudyn's implicit solver starts each
step's Newton iteration with zero acceleration (its predictor keeps only the previous step's
share of it), so a ball orbiting at r_c ω_c² begins every step displaced outward by

    e = c h² r_c ω_c²,   c = β (1 − α_f) / (1 − α_m) = 0.296 (generalized-alpha, ρ∞ = 0.5),

into its outer race. Once e is several times the outer contact's Hertz deflection δ_o the
first iterate loads the contact tens of times over (11 kN against 0.5 kN at 72 000 rpm,
h = 2.5e-5 s) and Newton needs 10–25 iterations and several Jacobians per step. Measured
(35-mm bearing, 16 balls of 7.144 mm, 667 N; 40-mm spindle, 14 balls of 8.731 mm, 1 kN
axial, with and without 500 N radial; 5 ms each, wall per 0.1 s): e/δ_o = 2.0 at
28 000 rpm (h = 2.5e-5 s): 5 Newton iterations per step, no cut, 6 s; 48 000 rpm: 4.1 (2.5e-5
s) 15 s, 1.8 (1.67e-5 s) 10 s; 72 000 rpm: 7.9 (2.5e-5 s) 42 s with 10 % of the steps cut,
2.7 / 2.0 / 1.5 / 0.96 (1.67 / 1.43 / 1.25 / 1.0e-5 s) 27 / 19 / 24 / 20 s; the spindle at
55 000 rpm: 3.75 (2.5e-5 s) 42 s with 5 % cut, 1.7 (1.67e-5 s) 11 s, radial 1.5 11 s. The
reference bearing at 1800 rpm and 200 N holds 1e-4 s at e/δ_o = 1.7. The step is therefore
also limited to e <= 2 δ_o (:data:`MAX_ORBIT_PREDICTOR_RATIO`). The package's predicted first
Newton iterate (:mod:`exudyn_bearing.model.predictor`, MODEL.md §10b) removes most of e; the rule is
kept as measured with Exudyn's own start.
"""
from __future__ import annotations

import math

import numpy as np

from contact.geometry import contact_path_radius

__all__ = ["NOMINAL_STEP", "MAX_VIBRATION_PHASE", "MAX_ORBIT_PREDICTOR_RATIO", "ORBIT_PREDICTOR_FACTOR",
           "FORCE_RESOLUTION", "MIN_ABSOLUTE_TOLERANCE", "ball_vibration_frequency", "orbit_step_limit",
           "recommended_step", "recommended_absolute_tolerance", "STEPS_PER_PASSAGE", "passage_step",
           "STRIKE_NUMBER", "STRIKE_PHASE", "OPENING_SHARE", "strike_number", "reach_share", "strike_step",
           "RING_DECAY", "LOOKAHEAD_STEPS", "passage_windows"]

#: the step that holds on the reference bearing, s
NOMINAL_STEP = 1e-4
#: the largest ω_n h at which every step converged in the case matrix, rad
MAX_VIBRATION_PHASE = 8.0
#: beta (1 - alpha_f) / (1 - alpha_m) of generalized-alpha at spectral radius 0.5: the share of
#: h² times a step's acceleration that Exudyn's Newton predictor leaves out
ORBIT_PREDICTOR_FACTOR = 0.25 * (0.5 + 1.0 / 3.0 + 0.5) ** 2 * (2.0 / 3.0)
#: largest c h² r_c ω_c² / δ_o at which the high-speed cases ran without a step cut, -
MAX_ORBIT_PREDICTOR_RATIO = 2.0


#: Newton's absolute tolerance as a share of the largest contact load: the compiled traction
#: rule resolves a contact's traction to ~1e-3 (its rays switch in such steps), i.e. ~3e-5 of
#: the normal load at a traction coefficient of 0.03; a residual asked below that stalls
#: Newton there (MODEL.md §10b)
FORCE_RESOLUTION = 3e-5
#: the absolute tolerance without a loaded contact to scale it, N
MIN_ABSOLUTE_TOLERANCE = 1e-6


def recommended_absolute_tolerance(loads) -> float:
    """:data:`FORCE_RESOLUTION` times the largest inner or outer contact load of the
    quasi-static ``loads``, N, at least :data:`MIN_ABSOLUTE_TOLERANCE`."""
    largest = max(float(np.max(loads.inner_load, initial=0.0)), float(np.max(loads.outer_load, initial=0.0)))
    return max(MIN_ABSOLUTE_TOLERANCE, FORCE_RESOLUTION * largest)


def ball_vibration_frequency(bearing, loads) -> float:
    """Largest ω_n = √((k_i + k_o)/m) over the balls, rad/s, with k = 3Q/(2δ) the linearized
    Hertz stiffness of each loaded contact of the quasi-static ``loads``
    (:class:`exudyn_bearing.solvers.quasistatic.LoadDistribution`); 0 when no ball is loaded."""
    def stiffness(load, deflection):
        load, deflection = np.asarray(load, dtype=float), np.asarray(deflection, dtype=float)
        safe = np.where(deflection > 0, deflection, 1.0)
        return np.where((deflection > 0) & (load > 0), 1.5 * load / safe, 0.0)

    k = stiffness(loads.inner_load, loads.inner_deflection) + stiffness(loads.outer_load, loads.outer_deflection)
    return float(np.sqrt(k.max() / bearing.ball_mass)) if k.size else 0.0


def orbit_step_limit(bearing, loads) -> float:
    """Largest step h with c h² r_c ω_c² <= :data:`MAX_ORBIT_PREDICTOR_RATIO` δ_o (module
    docstring), s, over the balls of the quasi-static ``loads`` with an outer contact: r_c the
    orbit radius, ω_c the cage speed the loads were solved at, δ_o the outer Hertz deflection;
    inf where nothing orbits or no outer contact is loaded."""
    w_c = np.broadcast_to(np.abs(np.asarray(loads.cage_speed, dtype=float)), np.shape(loads.outer_deflection))
    r_c = bearing.pitch_radius + np.asarray(loads.ball_radius_offset, dtype=float)
    delta = np.asarray(loads.outer_deflection, dtype=float)
    accel = r_c * w_c ** 2
    ok = (delta > 0) & (accel > 0)
    if not np.any(ok):
        return math.inf
    return float(np.min(np.sqrt(MAX_ORBIT_PREDICTOR_RATIO * delta[ok] / (ORBIT_PREDICTOR_FACTOR * accel[ok]))))


def recommended_step(bearing, loads, nominal: float = NOMINAL_STEP) -> float:
    """``nominal`` / n, n the smallest whole number with ω_n h <= :data:`MAX_VIBRATION_PHASE`
    (:func:`ball_vibration_frequency`) and h within :func:`orbit_step_limit`, s."""
    w_n = ball_vibration_frequency(bearing, loads)
    n = max(1, math.ceil(w_n * nominal / MAX_VIBRATION_PHASE - 1e-9))
    n = max(n, math.ceil(nominal / orbit_step_limit(bearing, loads) - 1e-9))
    return nominal / n


#: steps per defect passage of the vibration run (MODEL.md §13c)
STEPS_PER_PASSAGE = 2


def passage_step(bearing, surface, inner_rpm: float, outer_rpm: float = 0.0,
                 steps_per_passage: int = STEPS_PER_PASSAGE) -> float:
    """The longest step that puts ``steps_per_passage`` steps into the shortest defect passage of
    ``surface`` (MODEL.md §13c): a defect of length L on a race passes under a contact moving at
    |ω_c − ω_race| ρ over it (ρ = d_m/2 ∓ r cos α, the pure-rolling cage speed ω_c), so
    h = L / (steps_per_passage |ω_c − ω_race| ρ); a pit on a ball passes at the ball's surface
    speed, which rolling makes the races' (the faster of the two); inf without defects."""
    step = math.inf
    for d in surface.defects:
        speed = max(v for _, v in _contact_speeds(bearing, d, inner_rpm, outer_rpm))
        if speed > 0.0:
            step = min(step, d.length / (steps_per_passage * speed))
    return step


def _contact_speeds(bearing, defect, inner_rpm, outer_rpm):
    """(race, v) for each race ``defect`` meets (a pit on a ball: both): v = |ω_c − ω_race| ρ,
    the contact's speed over that race at pure rolling (:func:`passage_step`), m/s."""
    w_i, w_o = inner_rpm * math.pi / 30.0, outer_rpm * math.pi / 30.0
    w_c = bearing.cage_speed(w_i, w_o)
    for race in ("inner", "outer") if defect.race == "ball" else (defect.race,):
        rho = contact_path_radius(bearing.ball_diameter, bearing.pitch_diameter, bearing.contact_angle, race)
        yield race, abs(w_c - (w_i if race == "inner" else w_o)) * float(rho)


#: bounce number above which the ball's rattle after a strike sets the step (MODEL.md §13c):
#: measured, 0.10 needs no finer step (the CWRU 20-um inner spall), 0.13 and above do
STRIKE_NUMBER = 0.12
#: largest ω_b h where a ball strikes a defect's edge hard or its contact opens over it, rad
#: (MODEL.md §13c)
STRIKE_PHASE = 0.7
#: share of a race's approach δ a defect must reach for the ball's unloading and reloading
#: over it to set the strike step (MODEL.md §13c): measured on the CWRU 6205 at the passage
#: rule's 25 us, every or nearly every passage was followed by step cuts at 0.62 and 0.93
#: of δ, one in ten or none at 0.26–0.44
OPENING_SHARE = 0.5


def _strikes(bearing, surface, loads, inner_rpm, outer_rpm):
    """(B, share) of each defect and race it meets: :func:`strike_number`'s B and the defect's
    reach as a share of the race's approach δ (:func:`reach_share`)."""
    w_b = ball_vibration_frequency(bearing, loads)
    if surface is None or not surface.defects or w_b <= 0.0:
        return
    for d in surface.defects:
        for race, speed in _contact_speeds(bearing, d, inner_rpm, outer_rpm):
            delta = float(np.max(loads.inner_deflection if race == "inner" else loads.outer_deflection, initial=0.0))
            if delta <= 0.0:
                continue
            r_x, r_y = (float(v) for v in bearing.curvature_radii(bearing.contact_angle, race))
            reach = d.reach(r_x, r_y)
            sunk = min(reach, delta)
            yield speed * math.sqrt(2.0 * sunk / r_x) / (w_b * delta), reach / delta


def strike_number(bearing, surface, loads, inner_rpm: float, outer_rpm: float = 0.0) -> float:
    """Bounce number B = v_n / (ω_b δ) of the hardest defect strike of ``surface`` (MODEL.md
    §13c), 0 without defects or loaded contacts.

    At a defect's exit edge the ball's centre, sunk by g = min(the defect's reach, δ), is lifted
    along the edge's circle of radius R_x at the contact's speed v = |ω_c − ω_race| ρ over the
    race: it meets the far side at the normal speed v_n = v √(2 g / R_x). ω_b is the ball's
    contact frequency between its races (:func:`ball_vibration_frequency`) and δ the race's
    largest Hertz approach, both of the quasi-static ``loads``. B compares v_n with the speed
    of the contact's own oscillation at amplitude δ: near 1 the ball bounces off the edge and
    rattles between its races. A pit on a ball strikes both races."""
    return max((b for b, _ in _strikes(bearing, surface, loads, inner_rpm, outer_rpm)), default=0.0)


def reach_share(bearing, surface, loads, inner_rpm: float, outer_rpm: float = 0.0) -> float:
    """How deep a ball sinks into the deepest defect of ``surface``, as a share of the race's
    largest Hertz approach δ at the quasi-static ``loads`` (reach / δ; MODEL.md §13c), 0
    without defects: at 1 and above the ball's contact opens over it, from
    :data:`OPENING_SHARE` on it unloads to about a third or less ((1 − 0.5)^1.5) and the
    strike step applies."""
    return max((share for _, share in _strikes(bearing, surface, loads, inner_rpm, outer_rpm)), default=0.0)


def strike_step(bearing, surface, loads, inner_rpm: float, outer_rpm: float = 0.0) -> float:
    """:data:`STRIKE_PHASE` / ω_b where a ball's contact opens or nearly opens over a defect
    (:func:`reach_share` at least :data:`OPENING_SHARE`) or the :func:`strike_number` exceeds
    :data:`STRIKE_NUMBER`: the step then resolves the contact's unloading, the strike and the
    ball's rattle after it (MODEL.md §13c), s; inf otherwise."""
    if (strike_number(bearing, surface, loads, inner_rpm, outer_rpm) <= STRIKE_NUMBER
            and reach_share(bearing, surface, loads, inner_rpm, outer_rpm) < OPENING_SHARE):
        return math.inf
    return STRIKE_PHASE / ball_vibration_frequency(bearing, loads)


#: the share of a strike's ringing a passage window waits out: the ball's contact vibration,
#: damped at the contact's ratio ζ, decays to it in ln(1/RING_DECAY) / (ζ ω_b) (MODEL.md §13c)
RING_DECAY = 0.01
#: coarse steps of look-ahead before a passage window: the fine step starts at least this many
#: coarse steps of the contact's travel before the window proper (MODEL.md §13c)
LOOKAHEAD_STEPS = 2.0


def passage_windows(bearing, surface, loads, inner_rpm: float, outer_rpm: float, coarse_step: float,
                    damping_ratio: float):
    """Where a ball's contact needs the passage step (MODEL.md §13c): per race defect of
    ``surface``, a row (race: 0 inner, 1 outer; the defect's centre azimuth in the race's own
    frame, rad; the window's half angle on the contact path, rad). The window reaches on
    either side of the defect's centre over L/2 + a + v (τ + LOOKAHEAD_STEPS h): a = √(2 R_x δ)
    the contact's reach ahead of its centre at the race's largest approach δ (a sphere's chord
    at that depth, above the Hertz semi-axis), v = |ω_c − ω_race| ρ the contact's speed over
    the race at pure rolling, τ = ln(1/RING_DECAY)/(ζ ω_b) the ringing after the strike
    (``damping_ratio`` ζ of the contact, at least 0.01; ω_b :func:`ball_vibration_frequency`)
    and h the ``coarse_step`` taken elsewhere, s. Returns an (n, 3) array, or None where the
    surface has a pit on a ball (it passes at the ball's rotation, not its orbit: the passage
    step then holds for the whole run)."""
    if surface is None or any(d.race == "ball" for d in surface.defects):
        return None
    w_b = ball_vibration_frequency(bearing, loads)
    ring = math.log(1.0 / RING_DECAY) / (max(damping_ratio, 0.01) * w_b) if w_b > 0 else 0.0
    rows = []
    for d in surface.defects:
        (race, speed), = _contact_speeds(bearing, d, inner_rpm, outer_rpm)
        rho = float(contact_path_radius(bearing.ball_diameter, bearing.pitch_diameter, bearing.contact_angle, race))
        r_x = float(bearing.curvature_radii(bearing.contact_angle, race)[0])
        delta = float(np.max(loads.inner_deflection if race == "inner" else loads.outer_deflection, initial=0.0))
        reach = 0.5 * d.length + math.sqrt(2.0 * r_x * max(delta, 0.0)) + speed * (ring + LOOKAHEAD_STEPS * coarse_step)
        rows.append((0.0 if race == "inner" else 1.0, math.radians(d.angle_deg), min(reach / rho, math.pi)))
    return np.array(rows, dtype=float).reshape(-1, 3)
