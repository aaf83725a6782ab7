"""Edge forces from the edge (MODEL.md eq. 13.7, issue 49 item 2): a frictionless, undamped
ball carried slowly over a defect does no net work on a closed path — the contact force is the
gradient of the Hertz energy of the approach δ + h, so its tilt is dh/dθ over the ball centre's
radius ρ_c (the edge-to-centre line), not over the contact point's ρ_p."""
from __future__ import annotations

import math

import numpy as np
import pytest

from contact.ballrace import ContactLaw, ball_race_forces, with_surface
from contact.kinematics import ball_race_kinematics
from contact.surface import Defect, SurfaceModel, surface_record
from exudyn_bearing import CWRU_6205_BEARING, REFERENCE_LUBRICANT
from exudyn_bearing.contact_records import contact_records

B = CWRU_6205_BEARING
FRICTIONLESS = ContactLaw(traction="none", damping_ratio=0.0, rolling_resistance=False, compiled=False)


def _forces_along(race, surface, path):
    """Force on the ball (n, 3) N of one ball of ``B`` at the centres ``path`` (n, 3) m, at rest,
    against ``race`` with ``surface`` (numpy path)."""
    rec = contact_records(B, REFERENCE_LUBRICANT, FRICTIONLESS, balls=1, surface=surface_record(surface, B))
    k = 0 if race == "inner" else 1
    groove = tuple(g[k] for g in rec.grooves)
    n = len(path)
    kin = ball_race_kinematics(path, np.zeros((n, 3)), np.zeros((n, 3)), np.zeros(3), np.eye(3), np.zeros(3),
                               np.zeros(3), groove, B.ball_radius, race)
    kin = with_surface(kin, rec.terms, np.full(n, k), np.zeros(n, dtype=int), B.ball_diameter, B.pitch_diameter)
    params = rec.races
    one = type(params)(params.ball_diameter, params.pitch_diameter, np.full(n, params.conformity[k]),
                       np.full(n, params.race[k]), params.effective_modulus, params.ball_mass)
    return ball_race_forces(kin, one, REFERENCE_LUBRICANT, FRICTIONLESS, rec.terms).force


def _centres(race, theta, approach):
    """Ball centres at azimuths ``theta`` with the Hertz ``approach`` (m) against ``race`` (0°)."""
    (r_gi, _), (r_go, _) = B.groove_centres()
    d = B.ball_diameter
    if race == "outer":
        rho = r_go + (B.outer_conformity - 0.5) * d + approach
    else:
        rho = r_gi - (B.inner_conformity - 0.5) * d - approach
    theta, rho = np.broadcast_arrays(theta, rho)
    return np.stack([rho * np.cos(theta), rho * np.sin(theta), np.zeros_like(theta)], axis=-1)


def _work(race, surface, legs):
    """Work of the contact force on the ball along the polyline through ``legs`` (each (n, 3)), J,
    trapezoidal, per leg."""
    out = []
    for path in legs:
        f = _forces_along(race, surface, path)
        out.append(float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(path, axis=0))))
    return out


@pytest.mark.parametrize("race", ["outer", "inner"])
def test_ball_carried_round_a_loop_over_a_spall_does_no_net_work(race):
    """Into the middle of a 2-mm spall 1.5 um deep at a 3-um approach, pressed to 6 um there,
    carried out at 6 um and released outside: the loop's work is below 1 % of what the first
    leg stores (the old tilt over ρ_p left 0.17 x and 0.25 x the loop's non-conservative part
    on the 6205's outer and inner race: tens of percent)."""
    surface = SurfaceModel((Defect(race, 0.0, 2e-3, 1.5e-6),))
    (r_gi, _), (r_go, _) = B.groove_centres()
    rho_p = r_go + (B.outer_conformity - 0.5) * B.ball_diameter + B.ball_radius if race == "outer" else \
        r_gi - (B.inner_conformity - 0.5) * B.ball_diameter - B.ball_radius
    start, middle = -1.5e-3 / rho_p, 0.0  # 0.5 mm before the entry edge, and the spall's middle
    n = 6001
    d1, d2 = 3e-6, 6e-6
    legs = [_centres(race, np.linspace(start, middle, n), d1),
            _centres(race, middle, np.linspace(d1, d2, n)),
            _centres(race, np.linspace(middle, start, n), d2),
            _centres(race, start, np.linspace(d2, d1, n))]
    work = _work(race, surface, legs)
    assert abs(work[0]) > 1e-8  # the first leg does work: the ball sinks 1.5 um into the spall
    assert abs(sum(work)) < 0.01 * abs(work[0]), work


def _pit_work(race, surface, angles, approaches):
    """Work of one contact on a ball of ``B`` held at azimuth 0 and turned about the race axis
    e_z through ``angles`` (rad) at ``approaches`` (m; both (n,)): the moment's work about e_z
    plus the force's as the centre moves radially, J (trapezoidal)."""
    from contact.kinematics import rotation_matrices

    rec = contact_records(B, REFERENCE_LUBRICANT, FRICTIONLESS, balls=1, surface=surface_record(surface, B))
    k = 0 if race == "inner" else 1
    groove = tuple(g[k] for g in rec.grooves)
    n = len(angles)
    path = _centres(race, 0.0, approaches)
    rot = rotation_matrices(np.stack([np.zeros(n), np.zeros(n), angles], axis=1))
    kin = ball_race_kinematics(path, np.zeros((n, 3)), np.zeros((n, 3)), np.zeros(3), np.eye(3), np.zeros(3),
                               np.zeros(3), groove, B.ball_radius, race)
    kin = with_surface(kin, rec.terms, np.full(n, k), np.zeros(n, dtype=int), B.ball_diameter, B.pitch_diameter,
                       ball_rotation=rot, ball_omega=np.zeros((n, 3)), race_axis=np.tile([0.0, 0.0, 1.0], (n, 1)),
                       race_omega=np.zeros((n, 3)))
    params = rec.races
    one = type(params)(params.ball_diameter, params.pitch_diameter, np.full(n, params.conformity[k]),
                       np.full(n, params.race[k]), params.effective_modulus, params.ball_mass)
    f = ball_race_forces(kin, one, REFERENCE_LUBRICANT, FRICTIONLESS, rec.terms)
    return float(np.sum(0.5 * (f.moment[1:, 2] + f.moment[:-1, 2]) * np.diff(angles))
                 + np.sum(0.5 * (f.force[1:] + f.force[:-1]) * np.diff(path, axis=0)))


@pytest.mark.parametrize("race", ["outer", "inner"])
def test_ball_turned_round_a_loop_over_its_own_pit_does_no_net_work(race):
    """A 1-mm pit, 1.5 um deep, on a ball held against one race at a 3-um approach: the ball
    turned until the pit lies under the contact, pressed to 6 um, turned back and released:
    the loop's work (the pit's moment −Q ∂h/∂φ about the ball centre, eq. 13.7b, and the radial
    force) is below 1 % of what the first leg stores. (A force through the centre, as before
    session 29, does no work while the ball turns: the loop kept the whole difference.)"""
    surface = SurfaceModel((Defect("ball", 0.0 if race == "outer" else 180.0, 1e-3, 1.5e-6, ball=0),))
    start, n = -0.75e-3 / B.ball_radius, 6001  # the pit 0.25 mm before its edge reaches the contact
    d1, d2 = 3e-6, 6e-6
    legs = [(np.linspace(start, 0.0, n), np.full(n, d1)), (np.zeros(n), np.linspace(d1, d2, n)),
            (np.linspace(0.0, start, n), np.full(n, d2)), (np.full(n, start), np.linspace(d2, d1, n))]
    work = [_pit_work(race, surface, a, d) for a, d in legs]
    assert abs(work[0]) > 1e-8  # turning the pit under the contact stores work: the ball sinks into it
    assert abs(sum(work)) < 0.01 * abs(work[0]), work
