"""Ball–race contact forces: Hertz normal force, EHD film and traction, spin moment
(MODEL.md §3, §5, §6), vectorized over contacts.

Given the kinematics of :mod:`contact.kinematics`, :func:`ball_race_forces` returns the
force on each ball (acting at the contact centre p) and the moment on the ball about
its centre, (p - c) x F + M_z n. The race receives -F at p and -M_z n.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from . import film, geometry, hertz
from .kinematics import ContactKinematics, cross
from .lubricant import Lubricant
from .terms import TermRecord, contact_terms, surface_terms, term_record
from .traction_laws import TRACTION_LAWS, traction_model
from .ball_surface import ball_heights

__all__ = ["RaceContact", "ContactLaw", "ContactForces", "ball_race_forces", "with_surface", "TRACTION_MODELS"]

#: the traction laws' names (:data:`contact.traction_laws.TRACTION_LAWS`, at import)
TRACTION_MODELS = tuple(TRACTION_LAWS)


@dataclass(frozen=True)
class RaceContact:
    """Geometry and material of one race's contacts (MODEL.md §2–§3).

    Parameters
    ----------
    ball_diameter, pitch_diameter : float
        D and d_m, m (for the curvature radii).
    conformity : float
        Groove radius / D of this race.
    race : {'inner', 'outer'}
    effective_modulus : float
        E', Pa.
    ball_mass : float
        kg; scales the normal contact damping.
    """

    ball_diameter: float
    pitch_diameter: float
    conformity: float
    race: str
    effective_modulus: float
    ball_mass: float

    def hertz(self, contact_angle, method="fit"):
        r_x, r_y = geometry.curvature_radii(self.ball_diameter, self.pitch_diameter, contact_angle,
                                            self.conformity, self.race)
        return r_x, hertz.hertz_contact(r_x, r_y, self.effective_modulus, method)


@dataclass(frozen=True)
class ContactLaw:
    """Which physics a ball–race contact computes.

    Parameters
    ----------
    traction : {'crook-limited', 'crook', 'newtonian', 'coulomb', 'none'}
        'crook-limited' (default): Crook thermal EHD traction with the smooth limiting shear
        stress |tau| = tau_L tanh(|tau_Crook| / tau_L), tau_L = Lambda p (MODEL.md §6a), Lambda
        the lubricant's ``limiting_shear_coefficient`` (0.047 for the reference oil), and the
        film's elastic shear compliance (``film_elasticity``, MODEL.md §6b);
        'crook': the paper's pure Crook law (MODEL.md §6); its isothermal Newtonian limit
        (:func:`contact.traction.newtonian_traction`, small slip only); regularized dry
        Coulomb friction (:func:`contact.friction.coulomb_traction`); or normal forces only.
        Models not chosen cost nothing.
    spin_moment : bool
        Apply the traction spin moment M_z (P16).
    quadrature_order : int
        Order of the traction quadrature (:func:`contact.traction.crook_traction`).
    fast_quadrature : bool
        The fixed-size fast rule (worst error 4.6e-4 of the force scale at order 16 on
        reference-bearing states for pure Crook, 6.8e-3 with the limiting shear, ~5x
        cheaper; ``benchmarks/traction_speed.py``, MODEL.md §6a) or the accurate adaptive
        rule.
    damping_ratio : float
        Normal contact damping as a fraction of critical for the ball mass on the
        linearized Hertz stiffness (damps the ~0.2 ms contact oscillations; the EHD film
        damps them in reality). 0: none. The default 0.05 is assumed, not measured: no
        per-contact EHL value could be read; where balls strike defect edges hard the
        vibration amplitude depends on it (MODEL.md §13c).
    min_film_thickness : float
        Floor on the Hamrock–Dowson film thickness, m (the formula gives 0 at zero
        entrainment speed, e.g. a start from rest).
    limiting_shear : float or None
        Explicit limiting shear-stress coefficient Lambda of the smooth cap (MODEL.md §6a),
        overriding the lubricant's ``limiting_shear_coefficient`` for 'crook-limited' and
        applied to 'crook' too; None: the lubricant's value ('crook-limited') or no cap
        ('crook'). See :meth:`limiting_shear_for`.
    film_elasticity : bool or None
        Add the film's elastic shear compliance to the Crook law (MODEL.md §6b,
        Johnson & Tevaarwerk's Maxwell film, shear modulus G = kappa p with kappa the
        lubricant's ``film_shear_modulus_coefficient``): bounds the traction's initial slope
        by the film's stiffness instead of the Newtonian film's near-infinite one. None
        (default): on for 'crook-limited', off for 'crook' (the paper's law).
    hertz_method : {'fit', 'exact'}
    friction_coefficient, friction_regularization : float
        μ and the slip speed u_r (m/s) that smooths stick–slip, for ``traction='coulomb'``.
    rolling_resistance : bool
        Apply the hydrodynamic (EHL) rolling resistance of Biboulet & Houpert (2010) at each
        loaded contact as an equal and opposite couple on ball and race about the transverse
        axis (MODEL.md §11b; beyond the paper, off by default). Crook laws only.
    thermal_film : bool
        Reduce the film thickness (and the rolling resistance) by the inlet-shear-heating
        factor φ_T of Zhu & Cheng (MODEL.md §11e; beyond the paper, off by default). Crook
        laws only.
    compiled : bool
        Evaluate the bearing's contacts with the numba-compiled kernels
        (:mod:`contact.kernels`, the same equations without per-call numpy overhead, ~4x
        faster) where they cover the law: Crook (with or without the limiting shear) by the
        fast rule or no traction, Hertz fits. Otherwise, or with False, the numpy functions
        of this package.
    max_barus_exponent : float
        Bound on the Barus exponent c_etaP p of the traction viscosity (MODEL.md §6): the
        traction is evaluated with p_max <= max_barus_exponent / c_etaP (3.4 GPa for the
        reference oil at 60, above the 100 kN case's 2.4 GPa and near ISO 76's 4.2 GPa static
        limit). Below the cap nothing changes; above it the Newtonian slope is already
        ~e^60 eta0/h, far beyond any slip the thermal Crook law lets through, so the force
        is unaffected while absurd Newton trial states (tens of GPa) can no longer overflow
        exp() into inf/NaN.
    """

    traction: str = "crook-limited"
    spin_moment: bool = True
    quadrature_order: int = 16
    fast_quadrature: bool = True
    damping_ratio: float = 0.05
    min_film_thickness: float = 1e-8
    limiting_shear: float | None = None
    film_elasticity: bool | None = None
    hertz_method: str = "fit"
    max_barus_exponent: float = 60.0
    compiled: bool = True
    friction_coefficient: float = 0.05
    friction_regularization: float = 1e-3
    rolling_resistance: bool = False
    thermal_film: bool = False

    def __post_init__(self) -> None:
        traction_model(self.traction)  # a registered law, else a ValueError naming them
        if not (isinstance(self.quadrature_order, int) and self.quadrature_order >= 2):
            raise ValueError(f"quadrature_order must be an integer >= 2, got {self.quadrature_order!r}")
        if not (np.isfinite(self.damping_ratio) and self.damping_ratio >= 0):
            raise ValueError(f"damping_ratio must be >= 0, got {self.damping_ratio!r}")
        if not (np.isfinite(self.min_film_thickness) and self.min_film_thickness > 0):
            raise ValueError(f"min_film_thickness must be positive, got {self.min_film_thickness!r}")
        for name in ("friction_coefficient", "friction_regularization"):
            if not (np.isfinite(getattr(self, name)) and getattr(self, name) > 0):
                raise ValueError(f"{name} must be positive, got {getattr(self, name)!r}")
        if not (np.isfinite(self.max_barus_exponent) and 0 < self.max_barus_exponent <= 80):
            raise ValueError(f"max_barus_exponent must lie in (0, 80], got {self.max_barus_exponent!r}")
        if self.limiting_shear is not None and not (np.isfinite(self.limiting_shear) and self.limiting_shear > 0):
            raise ValueError(f"limiting_shear must be positive or None, got {self.limiting_shear!r}")
        for name in ("rolling_resistance", "thermal_film"):
            if getattr(self, name) not in (True, False):
                raise ValueError(f"{name} must be True or False, got {getattr(self, name)!r}")
        if self.film_elasticity not in (None, True, False):
            raise ValueError(f"film_elasticity must be True, False or None, got {self.film_elasticity!r}")

    @property
    def crook(self) -> bool:
        """Whether the traction is a Crook law (:func:`contact.traction.crook_traction`)."""
        return traction_model(self.traction).crook

    def limiting_shear_for(self, lubricant) -> float | None:
        """Lambda of the smooth limiting shear this law applies with ``lubricant``
        (MODEL.md §6a), or None for no cap: ``limiting_shear`` if given (Crook laws), else the
        lubricant's ``limiting_shear_coefficient`` for 'crook-limited' (0 = none)."""
        if not self.crook:
            return None
        if self.limiting_shear is not None:
            return float(self.limiting_shear)
        if self.traction == "crook-limited":
            lam = float(getattr(lubricant, "limiting_shear_coefficient", 0.0))
            return lam if lam > 0.0 else None
        return None

    def film_modulus_for(self, lubricant) -> float | None:
        """kappa = G/p of the film's elastic compliance this law applies with ``lubricant``
        (MODEL.md §6b), or None for none: with ``film_elasticity`` True, or None and
        'crook-limited', the lubricant's ``film_shear_modulus_coefficient``."""
        if not self.crook:
            return None
        on = self.traction == "crook-limited" if self.film_elasticity is None else self.film_elasticity
        return float(lubricant.film_shear_modulus_coefficient) if on else None


@dataclass(frozen=True)
class ContactForces:
    """Per-contact forces and states (global frame, SI units)."""

    force: np.ndarray  #: force on the ball at the contact centre, (n, 3), N
    moment: np.ndarray  #: moment on the ball about its centre, (n, 3), N m
    normal_load: np.ndarray  #: Q (Hertz + damping, >= 0), N
    traction_rolling: np.ndarray  #: f_x on the ball along t1, N
    traction_transverse: np.ndarray  #: f_y on the ball along t2, N
    spin_moment: np.ndarray  #: M_z on the ball about n, N m
    film_thickness: np.ndarray  #: h_c, m (0 where unloaded)
    max_pressure: np.ndarray  #: p_max, Pa
    heat: np.ndarray  #: integral of tau . u over the patch, W
    #: rolling-resistance moment on the ball about t2 (the race takes the opposite), N m (§11b),
    #: with the couples of registered terms (contact.terms.register_term)
    rolling_moment: np.ndarray = None
    #: power the rolling resistance (and the registered terms' stage 2) dissipates, W (>= 0)
    rolling_loss: np.ndarray = None
    #: power the normal contact damping dissipates, W
    damping_loss: np.ndarray = None


def ball_race_forces(kin: ContactKinematics, params: RaceContact, lubricant: Lubricant,
                     law: ContactLaw = ContactLaw(), terms: TermRecord | None = None,
                     compiled: bool = False, known_traction: np.ndarray | None = None) -> ContactForces:
    """Forces of n ball–race contacts from their kinematics (MODEL.md §3, §5, §6).

    Normal: Q = K delta^(3/2) + c d(delta)/dt, c = 2 zeta sqrt(1.5 K delta^(1/2) m),
    clipped at 0 (a contact cannot pull). Traction on the loaded contacts from the
    law's model (Crook, by default with the smooth limiting shear of MODEL.md §6a) with the
    Hamrock–Dowson central film (at least ``min_film_thickness``). ``terms``: the per-contact
    terms (:func:`contact.terms.term_record` of ``law`` and ``lubricant``, built once by the
    caller's :func:`exudyn_bearing.contact_records.contact_records`; built here if None).
    ``compiled``: a Crook law's traction by the compiled fast rule
    (:func:`contact.kernels.crook.crook_law`; the same rule, ~20x cheaper for many contacts)
    where the law uses the fast rule, else by its numpy form. ``known_traction`` (n, 4): where
    a row is not NaN, that compiled rule's f_x, f_y (N), M_z (N m) and heat (W) of the contact
    as already computed (a run's own, exudyn_bearing.model.recorded_traction), taken as they are.
    """
    n_con = kin.penetration.shape[0]
    r_x, contact = params.hertz(kin.contact_angle, law.hertz_method)
    delta = np.maximum(kin.penetration, 0.0)
    elastic = contact.stiffness * delta ** 1.5
    load = elastic
    if law.damping_ratio > 0:
        damping = 2.0 * law.damping_ratio * np.sqrt(1.5 * contact.stiffness * np.sqrt(delta) * params.ball_mass)
        load = load + damping * kin.penetration_rate
    load = np.where(kin.penetration > 0, np.maximum(load, 0.0), 0.0)
    # the damping part of Q times the approach rate (the elastic part stores energy)
    damping_loss = np.where(load > 0, (load - elastic) * kin.penetration_rate, 0.0)
    rolling = np.zeros(n_con)
    rolling_push = np.zeros(n_con)  # rolling resistance's net force on the ball along t1
    rolling_loss = np.zeros(n_con)
    fx = np.zeros(n_con)
    fy = np.zeros(n_con)
    mz = np.zeros(n_con)
    heat = np.zeros(n_con)
    h = np.zeros(n_con)
    p_max = contact.max_pressure(load)
    loaded = load > 0
    model = traction_model(law.traction)
    stage_2 = False  # the per-contact terms' force and couple apply (MODEL.md §11b; registered terms)
    if model.evaluate is not None and np.any(loaded):
        idx = np.flatnonzero(loaded)
        a, b = contact.semi_axes(load)
        a, b = a[idx], b[idx]
        p_traction = p_max[idx]
        if model.film:
            h_c = film.central_film_thickness(kin.entrainment[idx], load[idx], r_x[idx], contact.ellipticity[idx],
                                              params.effective_modulus, lubricant)
            # the per-contact terms (contact.terms): thermal film factor, rolling resistance
            if terms is None:
                terms = term_record(law, lubricant, params.ball_diameter)
            phi_t, push, couple = 1.0, 0.0, 0.0
            if terms.per_contact:
                r_y = geometry.curvature_radii(params.ball_diameter, params.pitch_diameter, kin.contact_angle,
                                               params.conformity, params.race)[1]
                rate = np.zeros(n_con) if kin.rolling_rate is None else kin.rolling_rate
                phi_t, push, couple = contact_terms(
                    terms, load=load[idx], a=a, b=b, max_pressure=p_max[idx], film=h_c, r_x=r_x[idx],
                    r_y=np.broadcast_to(r_y, (n_con,))[idx], slip=kin.slip_rolling[idx],
                    entrainment=kin.entrainment[idx], rolling_rate=rate[idx], ball_radius=0.5 * params.ball_diameter,
                    e_prime=params.effective_modulus, viscosity=lubricant.viscosity)
            h[idx] = np.maximum(phi_t * h_c, law.min_film_thickness)
            stage_2 = law.rolling_resistance or len(terms.registered) > 0
            if stage_2:
                rolling[idx], rolling_push[idx] = couple, push
                # the couple's power and the force pair's at the contact point (u = race − ball)
                rolling_loss[idx] = -rolling[idx] * kin.rolling_rate[idx] + rolling_push[idx] * kin.slip_rolling[idx]
            if lubricant.pressure_viscosity > 0:
                p_traction = np.minimum(p_traction, law.max_barus_exponent / lubricant.pressure_viscosity)
        # spin still shapes the local slip field when its moment is switched off
        evaluate = model.evaluate
        if compiled and model.crook and model.kernel == 1 and law.fast_quadrature:
            from .kernels.crook import crook_law  # the same fast rule, compiled

            evaluate = crook_law
            if known_traction is not None:  # the contacts whose traction the run computed
                done = idx[~np.isnan(known_traction[idx, 0])]
                fx[done], fy[done], heat[done] = (known_traction[done, i] for i in (0, 1, 3))
                if law.spin_moment:
                    mz[done] = known_traction[done, 2]
                rest = np.isnan(known_traction[idx, 0])
                idx, a, b, p_traction = idx[rest], a[rest], b[rest], p_traction[rest]
        if idx.size:
            tr = evaluate((kin.slip_rolling[idx], kin.slip_transverse[idx], kin.spin[idx]), a, b, p_traction,
                          load[idx], h[idx], kin.entrainment[idx], lubricant, law)
            fx[idx], fy[idx], heat[idx] = tr.fx, tr.fy, tr.heat
            if law.spin_moment:
                mz[idx] = tr.mz
    force = -load[:, None] * kin.normal + (fx + rolling_push)[:, None] * kin.rolling + fy[:, None] * kin.transverse
    # lever arm p - c = r n: the normal force has no moment about the ball centre
    moment = 0.5 * params.ball_diameter * cross(kin.normal, force) + mz[:, None] * kin.normal
    if stage_2 or law.rolling_resistance:
        moment = moment + rolling[:, None] * kin.transverse
    if kin.surface_slope is not None:  # the tilted common normal, through the ball centre (eq. 13.7)
        force = force - (load * kin.surface_slope)[:, None] * kin.rolling
    if kin.surface_turn is not None:  # the ball's own surface turns it (eq. 13.7b)
        moment = moment - load[:, None] * kin.surface_turn
    return ContactForces(force, moment, load, fx, fy, mz, h, p_max, heat, rolling, rolling_loss, damping_loss)


def with_surface(kin: ContactKinematics, terms, race, ball, ball_diameter, pitch_diameter, ball_rotation=None,
                 ball_omega=None, race_axis=None, race_omega=None) -> ContactKinematics:
    """``kin`` with the surfaces of ``terms`` (stage 0 of :mod:`contact.terms`, MODEL.md §13):
    approach δ + h, its rate + dh/dt, and the slope dh/ds that tilts the force (eq. 13.7);
    ``race`` (0 inner, 1 outer) and ``ball`` index of each contact; D and d_m in m (the
    contacts' reduced radii R_x, §2). A ball's own surface (eq. 13.3, 13.6) needs per contact
    the ball's ``ball_rotation`` (n, 3, 3) and ``ball_omega`` (n, 3) rad/s, and the race's
    ``race_axis`` (n, 3) and ``race_omega`` (n, 3) rad/s."""
    race = np.asarray(race)
    r_x = geometry.rolling_radius(ball_diameter, pitch_diameter, kin.contact_angle, 2.0 * race - 1.0)
    h, slope = surface_terms(terms, race, kin.azimuth, kin.contact_angle, kin.point_radius, ball, r_x)
    rate = kin.penetration_rate + slope * kin.orbit_rate
    tilt = slope / kin.orbit_radius  # dh/dθ over the ball centre's radius (eq. 13.7)
    turn = None
    if terms.surface.material:
        if ball_rotation is None:
            raise ValueError("with_surface: a ball defect needs ball_rotation, ball_omega, race_axis and race_omega")
        orbit = np.einsum("ij,ij->i", race_omega, race_axis) + kin.orbit_rate
        pit = ball_heights(terms.surface, ball, race, ball_rotation, kin.normal, kin.rolling, kin.transverse,
                           ball_omega - orbit[:, None] * race_axis, 0.5 * ball_diameter, r_x)
        h = h + pit[0]
        rate = rate + pit[1]
        turn = pit[2:].T
        # the contact frame turns with the centre's azimuth: −Q (e·G)/ρ_c along t1 (eq. 13.7b)
        tilt = tilt - np.einsum("ij,ij->i", turn, race_axis) / kin.orbit_radius
    return replace(kin, penetration=kin.penetration + h, penetration_rate=rate, surface_slope=tilt,
                   surface_turn=turn)


def _contacts_where(record, mask, n):
    """``record`` (a dataclass of per-contact arrays of length ``n`` and scalars) for the
    contacts ``mask`` only."""
    return replace(record, **{f.name: value[mask] for f in fields(record)
                              if isinstance(value := getattr(record, f.name), np.ndarray)
                              and value.shape[:1] == (n,)})


def ball_race_forces_by_race(kin: ContactKinematics, params: RaceContact, lubricants: tuple, law: ContactLaw,
                             terms: tuple, compiled: bool = False,
                             known_traction: np.ndarray | None = None) -> ContactForces:
    """:func:`ball_race_forces` with each race's contacts (``params.race`` −1 inner, +1 outer)
    in its own oil: ``lubricants`` and ``terms`` (inner, outer), e.g. the thermal network's
    contact oils (MODEL.md §14b)."""
    n = kin.penetration.shape[0]
    inner = np.asarray(params.race) < 0
    parts = [(mask, ball_race_forces(_contacts_where(kin, mask, n), _contacts_where(params, mask, n), lub, law,
                                     term, compiled=compiled,
                                     known_traction=None if known_traction is None else known_traction[mask]))
             for mask, lub, term in zip((inner, ~inner), lubricants, terms) if np.any(mask)]
    merged = {}
    for f in fields(ContactForces):
        values = [getattr(part, f.name) for _, part in parts]
        if all(v is None for v in values):
            merged[f.name] = None
            continue
        out = np.zeros((n, *np.shape(values[0])[1:]))
        for (mask, _), value in zip(parts, values):
            out[mask] = value
        merged[f.name] = out
    return ContactForces(**merged)
