"""Ball–race contacts of a whole bearing, compiled, for B states at once (MODEL.md §2–§6).

:func:`race_contacts` computes, contact by contact, what the numpy path computes on arrays:
kinematics (MODEL.md §2, §6; :mod:`contact.kinematics`), the Hertz fits (§3) and the
Hamrock–Dowson film (§5, P17) by the same scalar laws the numpy path applies
(:mod:`contact.hertz`, :mod:`contact.film`), the damped normal load, the Crook traction by the fast rule
(:func:`contact.kernels.crook.crook_one`) and the per-contact terms of :mod:`contact.terms`;
force and moment on the ball as :func:`contact.ballrace.ball_race_forces`.
:func:`race_contacts_parallel` spreads the contacts over numba's threads.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from ..film import central_film
from ..hertz import fit_ellipticity, fit_first_integral, fit_second_integral, max_pressure_of, semi_axis_of, stiffness_of
from ..surface import SurfaceRecord
from ..terms import ContactState, TermRecord, ball_surface_height, contact_loads, film_factor, surface_height
from .crook import crook_one, crook_scratch, thread_chunks
from .records import LawRecord

__all__ = ["race_contacts", "race_contacts_at", "race_contacts_parallel", "rotation_matrices"]


@njit(cache=True, error_model="numpy")
def rotation_matrices(nu):
    """Rodrigues rotation matrices of rotation vectors (n, 3) -> (n, 3, 3), as
    :func:`contact.kinematics.rotation_matrices`."""
    n = nu.shape[0]
    out = np.empty((n, 3, 3))
    for i in range(n):
        x, y, z = nu[i, 0], nu[i, 1], nu[i, 2]
        angle2 = x * x + y * y + z * z
        if angle2 < 1e-12:
            c1 = 1.0 - angle2 / 6.0
            c2 = 0.5 - angle2 / 24.0
        else:
            angle = math.sqrt(angle2)
            c1 = math.sin(angle) / angle
            c2 = (1.0 - math.cos(angle)) / angle2
        # I + c1 S + c2 S², S the skew matrix of nu; S² = nu nuᵀ - |nu|² I
        out[i, 0, 0] = 1.0 + c2 * (x * x - angle2)
        out[i, 1, 1] = 1.0 + c2 * (y * y - angle2)
        out[i, 2, 2] = 1.0 + c2 * (z * z - angle2)
        out[i, 0, 1] = -c1 * z + c2 * x * y
        out[i, 1, 0] = c1 * z + c2 * x * y
        out[i, 0, 2] = c1 * y + c2 * x * z
        out[i, 2, 0] = -c1 * y + c2 * x * z
        out[i, 1, 2] = -c1 * x + c2 * y * z
        out[i, 2, 1] = c1 * x + c2 * y * z
    return out



@njit(cache=True, error_model="numpy", inline="always")
def _contact_kinematics(ib, k, j, balls, frames, geometry, terms):
    """Kinematics of the contact of ball ``j`` with race ``k`` in state ``ib`` (MODEL.md §2, §6)
    with the surfaces' stage 0 (:mod:`contact.terms`, §13): (elastic approach δ m, its rate
    m/s, normal n, rolling direction t1, transverse t2 (3-tuples, global), slips u_x, u_y
    m/s, spin rad/s, entrainment m/s, rolling rate rad/s, the surface's tilt dh/ds, R_x m)."""
    c, v, w = balls.position, balls.velocity, balls.omega
    ro, rr, rv, rw = frames.origin, frames.rotation, frames.velocity, frames.omega
    groove, sign = geometry.groove, geometry.sign
    ball_radius, pitch_diameter = geometry.ball_radius, geometry.pitch_diameter
    diam = 2.0 * ball_radius
    o = ro[ib, k]
    R = rr[ib, k]
    vo = rv[ib, k]
    wr = rw[ib, k]
    ri, zi, tube = groove[k, 0], groove[k, 1], groove[k, 2]
    sgn = sign[k]
    cx, cy, cz = c[ib, j, 0], c[ib, j, 1], c[ib, j, 2]
    rx_, ry_, rz_ = cx - o[0], cy - o[1], cz - o[2]
    # race-frame position (Rᵀ rel) and the groove torus (MODEL.md §2)
    lx = R[0, 0] * rx_ + R[1, 0] * ry_ + R[2, 0] * rz_
    ly = R[0, 1] * rx_ + R[1, 1] * ry_ + R[2, 1] * rz_
    lz = R[0, 2] * rx_ + R[1, 2] * ry_ + R[2, 2] * rz_
    rho_c = math.hypot(lx, ly)
    ex, ey = lx / rho_c, ly / rho_c
    gx, gy, gz = ri * ex, ri * ey, zi
    dx, dy, dz = lx - gx, ly - gy, lz - gz
    dist = math.sqrt(dx * dx + dy * dy + dz * dz)
    nlx, nly, nlz = dx / dist, dy / dist, dz / dist
    angle = math.atan2(sgn * nlz, sgn * (nlx * ex + nly * ey))
    pen = dist - tube
    rho_p = math.hypot(lx + ball_radius * nlx, ly + ball_radius * nly)
    r_x = diam * (pitch_diameter + sgn * diam * math.cos(angle)) / (2.0 * pitch_diameter)
    # stage 0 (contact.terms): the race surface's height at the contact, in the race's own frame
    height, height_slope = surface_height(terms, k, math.atan2(ly, lx), angle, rho_p, j, r_x)
    if height != 0.0 or height_slope != 0.0:  # (a separate branch: a perfect surface stays bit for bit)
        pen += height
    nx = R[0, 0] * nlx + R[0, 1] * nly + R[0, 2] * nlz
    ny = R[1, 0] * nlx + R[1, 1] * nly + R[1, 2] * nlz
    nz = R[2, 0] * nlx + R[2, 1] * nly + R[2, 2] * nlz
    t1x = -R[0, 0] * ey + R[0, 1] * ex  # R (e_z x radial)
    t1y = -R[1, 0] * ey + R[1, 1] * ex
    t1z = -R[2, 0] * ey + R[2, 1] * ex
    t2x = ny * t1z - nz * t1y
    t2y = nz * t1x - nx * t1z
    t2z = nx * t1y - ny * t1x
    # velocities at the contact centre p = c + r n (MODEL.md §6)
    wbx, wby, wbz = w[ib, j, 0], w[ib, j, 1], w[ib, j, 2]
    px, py, pz = ball_radius * nx, ball_radius * ny, ball_radius * nz  # p - c
    qx, qy, qz = rx_ + px, ry_ + py, rz_ + pz  # p - o
    sx = vo[0] + wr[1] * qz - wr[2] * qy - (v[ib, j, 0] + wby * pz - wbz * py)
    sy = vo[1] + wr[2] * qx - wr[0] * qz - (v[ib, j, 1] + wbz * px - wbx * pz)
    sz = vo[2] + wr[0] * qy - wr[1] * qx - (v[ib, j, 2] + wbx * py - wby * px)
    u_x = sx * t1x + sy * t1y + sz * t1z
    u_y = sx * t2x + sy * t2y + sz * t2z
    spin = (wr[0] - wbx) * nx + (wr[1] - wby) * ny + (wr[2] - wbz) * nz
    # groove-centre velocity -> approach rate
    ggx = R[0, 0] * gx + R[0, 1] * gy + R[0, 2] * gz
    ggy = R[1, 0] * gx + R[1, 1] * gy + R[1, 2] * gz
    ggz = R[2, 0] * gx + R[2, 1] * gy + R[2, 2] * gz
    vgx = vo[0] + wr[1] * ggz - wr[2] * ggy
    vgy = vo[1] + wr[2] * ggx - wr[0] * ggz
    vgz = vo[2] + wr[0] * ggy - wr[1] * ggx
    rate = (v[ib, j, 0] - vgx) * nx + (v[ib, j, 1] - vgy) * ny + (v[ib, j, 2] - vgz) * nz
    # the contact moves with the ball's orbit relative to the race
    orx = v[ib, j, 0] - (vo[0] + wr[1] * rz_ - wr[2] * ry_)
    ory = v[ib, j, 1] - (vo[1] + wr[2] * rx_ - wr[0] * rz_)
    orz = v[ib, j, 2] - (vo[2] + wr[0] * ry_ - wr[1] * rx_)
    orbit_rel = (orx * t1x + ory * t1y + orz * t1z) / rho_c
    entrainment = -0.5 * u_x - orbit_rel * rho_p
    tilt = 0.0  # dh/ds along t1: the surface's slope tilts the contact force (eq. 13.7)
    turn = (0.0, 0.0, 0.0)  # G = ∂h/∂φ of the ball's own surface, m/rad: −Q G on the ball (13.7b)
    if height_slope != 0.0:  # the surface under the moving contact rises or falls
        rate += height_slope * orbit_rel
        # over the ball centre's radius: the edge-to-centre line, the gradient of the approach
        # δ + h(θ) with θ the centre's azimuth (eq. 13.7)
        tilt = height_slope / rho_c
    if terms.surface.ball_defects.shape[0] + terms.surface.ball_waviness.shape[0] > 0:  # its own surface (13.3, 13.6)
        orbit = wr[0] * R[0, 2] + wr[1] * R[1, 2] + wr[2] * R[2, 2] + orbit_rel  # absolute, about the race axis
        pit, pit_rate, g = ball_surface_height(
            terms, j, k, balls.rotation[ib, j], (nx, ny, nz), (t1x, t1y, t1z), (t2x, t2y, t2z),
            (wbx - orbit * R[0, 2], wby - orbit * R[1, 2], wbz - orbit * R[2, 2]), ball_radius, r_x)
        if pit != 0.0 or g[0] != 0.0 or g[1] != 0.0 or g[2] != 0.0:
            pen += pit
            rate += pit_rate
            # the contact frame turns with the centre's azimuth: −Q (e·G)/ρ_c along t1 (eq. 13.7b)
            tilt -= (g[0] * R[0, 2] + g[1] * R[1, 2] + g[2] * R[2, 2]) / rho_c
            turn = (g[0], g[1], g[2])
    rolling_rate = (wbx - wr[0]) * t2x + (wby - wr[1]) * t2y + (wbz - wr[2]) * t2z
    return (pen, rate, (nx, ny, nz), (t1x, t1y, t1z), (t2x, t2y, t2z), u_x, u_y, spin, entrainment, rolling_rate,
            tilt, r_x, turn)


@njit(cache=True, error_model="numpy", inline="always")
def _normal_load(pen, rate, r_x, conformity, geometry, law):
    """The damped Hertz load Q (N) of a contact with approach ``pen`` (m), its ``rate`` (m/s)
    and R_x (m) by the Brewe–Hamrock fits (MODEL.md §3), with (k, E, R, R_y) for its traction."""
    e_prime, diam = geometry.e_prime, 2.0 * geometry.ball_radius
    r_y = conformity * diam / (2.0 * conformity - 1.0)
    ratio = max(r_y / r_x, 1.0)
    ell, second = fit_ellipticity(ratio), fit_second_integral(ratio)
    radius = 1.0 / (1.0 / r_x + 1.0 / r_y)
    stiff = stiffness_of(ell, fit_first_integral(ratio), second, radius, e_prime)
    q = 0.0
    if pen > 0.0:
        q = stiff * pen ** 1.5
        if law.damping_ratio > 0.0:
            q += 2.0 * law.damping_ratio * math.sqrt(1.5 * stiff * math.sqrt(pen) * geometry.ball_mass) * rate
        q = max(q, 0.0)
    return q, ell, second, radius, r_y


@njit(cache=True, error_model="numpy", inline="always")
def _contact_traction(q, hertz, r_x, slip, entrainment, rolling_rate, geometry, law, tables, terms, scratch):
    """(f_x, f_y along t1, t2 N, M_z N m, the per-contact terms' force along t1 N and couple
    about t2 N m) on the ball of a loaded contact, and the traction's heat (W): Hamrock–Dowson
    film (P17) with the terms' film factor, the Crook traction by the fast rule, the terms'
    stage 2."""
    ell, second, radius, r_y = hertz
    u_x, u_y, spin = slip
    e_prime, ball_radius, eta0, c_p = geometry.e_prime, geometry.ball_radius, law.eta0, law.c_p
    p_cap = law.max_barus / c_p if c_p > 0.0 else np.inf
    sa = semi_axis_of(q, ell, second, radius, e_prime, True)
    sb = semi_axis_of(q, ell, second, radius, e_prime, False)
    p_max = max_pressure_of(q, sa, sb)
    h = central_film(entrainment, q, r_x, ell, e_prime, eta0, c_p)  # Hamrock–Dowson (P17), floored below
    cs = ContactState(q, sa, sb, p_max, h, r_x, r_y, u_x, entrainment, rolling_rate, ball_radius, e_prime, eta0)
    # the thermal film factor with the race's own oil: c1_coef = c_ηT / (8 K_c) (MODEL.md §6), so
    # 8 c1_coef is its c_ηT / K_c (a power-of-two scaling: the same float as terms.heating)
    heating = 8.0 * law.c1_coef if terms.heating > 0.0 else 0.0
    phi_t = film_factor(terms, cs, heating)  # the per-contact terms (contact.terms), stage 1
    h = max(phi_t * h, law.min_film)
    fx, fy, mz, heat = crook_one(u_x, u_y, spin, sa, sb, min(p_max, p_cap), h, entrainment, law, tables, scratch)
    if not law.spin_moment:
        mz = 0.0
    f_b, m_r = contact_loads(terms, cs, phi_t)  # stage 2
    return fx, fy, mz, f_b, m_r, heat


# Without numba's reference counting (``_nrt=False``): its records of arrays (balls, frames,
# tables, terms, outputs) were increfed and decrefed, atomically, at every field read and call,
# 40 % of a normal-force-only evaluation and ~20 % of a whole one (the reference bearing on a
# 2-core Xeon: 174 -> 145 us; bit for bit the same forces and Jacobians). The callees inherit
# the flag, so nothing reached from here may allocate: those that do (the surfaces, the
# registered terms) sit behind functions that set ``_nrt=True`` (contact.terms), and a new
# allocation here fails to compile rather than run.
@njit(cache=True, error_model="numpy", _nrt=False)
def _race_contact(idx, balls, frames, geometry, laws, tables, terms, out, scratch):
    """Contact ``idx`` (state idx // 2Z, race idx // Z % 2, ball idx % Z) of :func:`race_contacts`
    (``scratch``: the traction's work arrays, :func:`contact.kernels.crook.crook_scratch`)."""
    z = balls.position.shape[1]
    ib = idx // (2 * z)
    k = (idx // z) % 2
    j = idx % z
    law = laws[k]
    pen, rate, normal, t1, t2, u_x, u_y, spin, entrainment, rolling_rate, tilt, r_x, turn = _contact_kinematics(
        ib, k, j, balls, frames, geometry, terms)
    out.penetration[ib, k, j] = pen
    q, ell, second, radius, r_y = _normal_load(pen, rate, r_x, geometry.conformity[k], geometry, law)
    out.load[ib, k, j] = q
    fx = 0.0
    fy = 0.0
    mz = 0.0
    heat = 0.0
    m_r = 0.0  # rolling-resistance couple about t2, on the ball
    f_b = 0.0  # and its net force on the ball along t1 at the contact point
    if law.traction == 1 and q > 0.0:
        fx, fy, mz, f_b, m_r, heat = _contact_traction(q, (ell, second, radius, r_y), r_x, (u_x, u_y, spin),
                                                       entrainment, rolling_rate, geometry, law, tables, terms,
                                                       scratch)
    traction = out.traction
    traction[ib, k, j, 0] = fx
    traction[ib, k, j, 1] = fy
    traction[ib, k, j, 2] = mz
    traction[ib, k, j, 3] = heat
    nx, ny, nz = normal
    t1x, t1y, t1z = t1
    t2x, t2y, t2z = t2
    ball_radius = geometry.ball_radius
    force, moment = out.force, out.moment
    Fx = -q * nx + fx * t1x + fy * t2x
    Fy = -q * ny + fx * t1y + fy * t2y
    Fz = -q * nz + fx * t1z + fy * t2z
    if f_b != 0.0:  # (a separate sum: the contact without rolling resistance stays bit for bit)
        Fx += f_b * t1x
        Fy += f_b * t1y
        Fz += f_b * t1z
    force[ib, k, j, 0] = Fx
    force[ib, k, j, 1] = Fy
    force[ib, k, j, 2] = Fz
    # lever arm r n: the normal part has no moment about the ball centre
    moment[ib, k, j, 0] = ball_radius * (ny * Fz - nz * Fy) + mz * nx + m_r * t2x
    moment[ib, k, j, 1] = ball_radius * (nz * Fx - nx * Fz) + mz * ny + m_r * t2y
    moment[ib, k, j, 2] = ball_radius * (nx * Fy - ny * Fx) + mz * nz + m_r * t2z
    if tilt != 0.0 and q > 0.0:
        # over a slope the load acts along the tilted common normal, through the ball centre
        # (no moment about it): -Q (n + dh/ds t1)
        force[ib, k, j, 0] = Fx - q * tilt * t1x
        force[ib, k, j, 1] = Fy - q * tilt * t1y
        force[ib, k, j, 2] = Fz - q * tilt * t1z
    if q > 0.0 and (turn[0] != 0.0 or turn[1] != 0.0 or turn[2] != 0.0):
        # the ball's own surface turns the ball: -Q ∂h/∂φ (eq. 13.7b)
        moment[ib, k, j, 0] -= q * turn[0]
        moment[ib, k, j, 1] -= q * turn[1]
        moment[ib, k, j, 2] -= q * turn[2]


@njit(cache=True, error_model="numpy")
def race_contacts(balls, frames, geometry, laws, tables, terms, out):
    """Forces of the Z balls of B states against both races (MODEL.md §2–§6).

    Parameters
    ----------
    balls : BallStates
        Ball centres (m), velocities (m/s), GLOBAL angular velocities (rad/s), (B, Z, 3), and
        rotations (B, Z, 3, 3), read only when a ball has a surface of its own (else (B, 0, 3, 3)).
    frames : RaceFrames
        Origin, rotation (third column: axis), origin velocity and angular velocity of the
        inner (index 0) and outer (1) race frames of each state.
    geometry : RaceGeometry
    laws : (LawRecord, LawRecord)
        The inner (index 0) and outer (1) contacts' law with its race's oil (the same record
        twice where both races see one oil); ``traction`` 0: normal forces only; 1: Crook
        (fast rule).
    tables : CrookTables
        :func:`contact.kernels.crook.crook_tables`.
    terms : contact.terms.TermRecord
        The per-contact terms (surface, thermal film, rolling resistance).
    out : ContactOutputs
        Written: force on each ball at its contact with race k (N), moment about the ball
        centre (N m), elastic approach δ (m), normal load Q (N) and the traction with its heat.
    """
    scratch = crook_scratch(tables)
    for idx in range(balls.position.shape[0] * 2 * balls.position.shape[1]):
        _race_contact(idx, balls, frames, geometry, laws, tables, terms, out, scratch)


@njit(cache=True, error_model="numpy")
def race_contacts_at(balls, frames, geometry, laws, tables, terms, out, todo):
    """:func:`race_contacts` for the flat contact indices ``todo`` only (state idx // 2Z, race
    idx // Z % 2, ball idx % Z; int64): the rest of the outputs is left as it is (a Jacobian's
    race columns change one race's contacts only)."""
    scratch = crook_scratch(tables)
    for n in range(todo.shape[0]):
        _race_contact(todo[n], balls, frames, geometry, laws, tables, terms, out, scratch)


#: the fields of one race's law in the laws' flat tuple (:func:`race_contacts_parallel`)
_N_LAW = len(LawRecord._fields)
#: the surface record's fields come first in the terms' flat tuple (:func:`_flat_terms`)
_N_SURFACE = len(SurfaceRecord._fields)
# the flat tuple leaves out the last field, the registered terms (functions); a new field
# therefore goes before it (TermRecord's docstring)
assert TermRecord._fields[-1] == "registered"


def _flat_terms(terms):
    """``terms`` but its registered ones as one flat tuple — the surface's arrays, then the
    scalar fields, by position — for numba's parallel loop, which takes tuples of arrays and
    numbers but not a record inside a record."""
    return (*terms.surface, *terms[1:-1])


@njit(cache=True, error_model="numpy")
def _race_contacts_flat(todo, balls, frames, geometry, flat_laws, tables, flat, out):
    """:func:`race_contacts_at` with the two races' laws rebuilt from one flat tuple (inner's
    fields, then outer's) and the terms from :func:`_flat_terms`' tuple."""
    laws = (LawRecord(*flat_laws[:_N_LAW]), LawRecord(*flat_laws[_N_LAW:]))
    terms = TermRecord(SurfaceRecord(*flat[:_N_SURFACE]), *flat[_N_SURFACE:], ())
    scratch = crook_scratch(tables)
    for n in range(todo.shape[0]):
        _race_contact(todo[n], balls, frames, geometry, laws, tables, terms, out, scratch)


@njit(cache=True, error_model="numpy", parallel=True)
def _race_contacts_prange(balls, frames, geometry, laws, tables, flat, out, todo, chunks):
    """The contacts ``todo`` on numba's threads (:func:`race_contacts_parallel`), in ``chunks``
    pieces (at most the contacts' number)."""
    n = todo.shape[0]
    for c in prange(chunks):
        _race_contacts_flat(todo[c * n // chunks:(c + 1) * n // chunks], balls, frames, geometry, laws, tables, flat,
                            out)


def race_contacts_parallel(balls, frames, geometry, laws, tables, terms, out, todo):
    """:func:`race_contacts_at` with the contacts ``todo`` spread over numba's threads.

    The two laws and the terms cross numba's parallel loop as flat tuples rebuilt per chunk by position
    (:func:`_flat_terms`), never field by field, so no field can be left at its default
    there; registered terms (functions, which cannot cross it) run serially."""
    if len(terms.registered) > 0:
        race_contacts_at(balls, frames, geometry, laws, tables, terms, out, todo)
        return
    _race_contacts_prange(balls, frames, geometry, (*laws[0], *laws[1]), tables, _flat_terms(terms), out, todo,
                          thread_chunks(todo.shape[0]))
