"""Crook thermal EHD traction integrated over the Hertz contact ellipse.

Implements MODEL.md §6 (paper P12–P16) with the quadrature asked for in MODEL.md §8
("Traction quadrature with spin").  Pure numpy; every function is vectorised over
contacts (arrays of shape ``(n,)`` or scalars, broadcast together).

The local law and the shared pieces (result type, thermal factor, limiting shear, input
checks) are in :mod:`contact.traction_law`, the accurate adaptive rule in
:mod:`contact.traction_accurate`, the fast float32 rule in :mod:`contact.traction_fast` and
the isothermal Newtonian law in :mod:`contact.newtonian`; this module is the public entry
point and re-exports their public names.
"""
from __future__ import annotations

import numpy as np

from .newtonian import _spin_integral, newtonian_slope, newtonian_traction  # noqa: F401
from .traction_accurate import RuleParams, _accurate_crook, rule_size
from .traction_fast import _fast_crook, fast_rule_size
from .traction_law import Traction, _as_array, _lubricant_params, thermal_factor

__all__ = ["Traction", "crook_traction", "newtonian_slope", "newtonian_traction", "thermal_factor", "rule_size",
           "fast_rule_size"]


# ---------------------------------------------------------------------------------------
# Public API
# ---------------------------------------------------------------------------------------
def crook_traction(u_x, u_y, omega_s, a, b, p_max, h, lubricant, *, temperature=None,
                   order=16, derivatives=False, limiting_shear=None, fast=False, film_modulus=None,
                   entrainment=None) -> Traction:
    """Crook thermal EHD traction force and spin moment on the ball (MODEL.md §6, P12–P16).

    Integrates τ = η_m u / h over the Hertz ellipse x²/b² + y²/a² ≤ 1 with pressure
    p = p_max √(1 − x²/b² − y²/a²), viscosity η = η0 exp(c_ηP p − c_ηT (T − T_R)) (P11) and
    local slip u(x, y) = (u_x − ω_s y, u_y + ω_s x) (P14); η_m = η asinh(√ψ)/√(ψ(1+ψ)),
    ψ = η c_ηT |u|²/(8 K_c) (P12, P13); optionally limited smoothly to Λ p (MODEL.md §6a).
    The quadrature follows the spin pole (MODEL.md §8, "Traction quadrature with spin"); see
    :mod:`contact.traction_accurate` and :mod:`contact.traction_fast`.

    Parameters
    ----------
    u_x, u_y : array_like
        Slip velocity at the contact centre, race surface minus ball surface, along t1
        (rolling) and t2 (transverse), m/s.
    omega_s : array_like
        Spin (ω_race − ω_ball)·n, rad/s.
    a, b : array_like
        Hertz semi-axes, m: ``a`` TRANSVERSE (y, across the groove), ``b`` rolling (x).
        A zero semi-axis (unloaded contact) gives zero traction.
    p_max : array_like
        Peak Hertz pressure, Pa (≥ 0).
    h : array_like
        Film thickness, m (> 0), constant over the ellipse (MODEL.md §5).
    lubricant : contact.lubricant.Lubricant
        η0 (Pa s), T_R (°C), c_ηP (1/Pa), c_ηT (1/K), K_c (W/(m K)).
    temperature : array_like, optional
        Film (wall) temperature, °C; T_R if omitted.
    order : int
        Quadrature order (≥ 4).  At most 10·⌈order/2⌉ ray directions with 2·⌈3·order/4⌉
        Gauss nodes each (:func:`rule_size`; 1920 nodes per contact for the default 16);
        contacts with c_ηP p_max ≲ 14 or negligible thermal softening use ¾ or ½ of the
        order.  The default gives relative errors ≤ 3e-4 in the hard cases (spin pole in or
        near a 1–1.2 GPa contact); errors fall roughly tenfold per +4 in order.
    derivatives : bool
        Also return ``jacobian`` = ∂(fx, fy, mz)/∂(u_x, u_y, ω_s), differentiated under the
        integral: ∂τ/∂u = (η/h)[G I + (G'(s)/s) c1² u uᵀ], ∂u/∂ω_s = (−y, x).
    limiting_shear : float, optional
        Λ = τ_L/p ≥ 0 (dimensionless, e.g. 0.047): the local stress magnitude becomes
        Λ p tanh(|τ_Crook|/(Λ p)) along the local slip (MODEL.md §6a,
        :func:`contact.traction_law.limit_shear`; the Jacobian differentiates it exactly).
        ``None`` (default) or 0 = off, the paper's pure Crook law.
    film_modulus : float, optional
        κ = G/p > 0: add the film's elastic shear compliance, shear modulus G = κ p, to the
        (limited) Crook law (MODEL.md §6b, :mod:`contact.film_elasticity`); needs
        ``entrainment``; no ``derivatives``. None (default): no elastic compliance.
    entrainment : array_like, optional
        Signed entrainment speed ū along t1, m/s (with ``film_modulus``): sets the inlet side
        and the time the oil spends in the contact.
    fast : bool
        Use the fast rule meant for the dynamic model's right-hand side (module docstring,
        "Fast rule"): all contacts in one fixed-size float32 block, 4–5× cheaper per call
        for 32 contacts.  Same arguments and outputs; ``order`` sets its size
        (:func:`fast_rule_size`).  Worst error relative to |f| + |M_z|/√(ab) on the
        reference bearing's dynamic states ≈ 6e-4 at order 16 (the recommended order),
        2e-4 at 20, 1e-4 at 24; Jacobian within ≈ 1e-2 of its largest entry.  With the
        limiting shear (Λ 0.047) ≈ 7e-3 at order 16, 2e-3 at 24 (MODEL.md §6a table).

    Returns
    -------
    Traction
        ``fx``, ``fy`` (N), ``mz`` (N m), ``heat`` (W) of the broadcast input shape and, if
        requested, ``jacobian`` of that shape + (3, 3).

    Raises
    ------
    ValueError
        Non-finite input, negative a, b or p_max, non-positive h, bad order or Λ.
    """
    vals = (u_x, u_y, omega_s, a, b, p_max, h)
    flat = _quick_inputs(vals) if temperature is None else None
    if flat is None:
        ux = _as_array("u_x", u_x)
        uy = _as_array("u_y", u_y)
        om = _as_array("omega_s", omega_s)
        a = _as_array("a", a, nonneg=True)
        b = _as_array("b", b, nonneg=True)
        pm = _as_array("p_max", p_max, nonneg=True)
        hh = _as_array("h", h, positive=True)
    eta0, t_ref, c_p, c_t, k_c = _lubricant_params(lubricant)
    if flat is None:
        temp = (np.asarray(t_ref, dtype=float) if temperature is None
                else _as_array("temperature", temperature))
    if isinstance(order, (bool, np.bool_)) or not isinstance(order, (int, np.integer)) or order < 4:
        raise ValueError(f"order must be an integer >= 4, got {order!r}")
    order = int(order)
    lam_s = None
    if limiting_shear is not None:
        try:
            lam_s = float(limiting_shear)
        except (TypeError, ValueError):
            lam_s = float("nan")
        if not np.isfinite(lam_s) or lam_s < 0:
            raise ValueError(f"limiting_shear must be a non-negative number or None, got {limiting_shear!r}")
        if lam_s == 0.0:
            lam_s = None  # no cap
    c1_coef = c_t / (8.0 * k_c)  # c1² = η c1_coef
    if film_modulus is not None:
        ok = isinstance(film_modulus, (int, float, np.floating)) and not isinstance(film_modulus, bool)
        kap = float(film_modulus) if ok else float("nan")
        if not (np.isfinite(kap) and kap > 0):
            raise ValueError(f"film_modulus must be a positive number or None, got {film_modulus!r}")
        if entrainment is None:
            raise ValueError("entrainment is required with film_modulus")
        if derivatives:
            raise ValueError("derivatives are not available with film_modulus")
        ent = _as_array("entrainment", entrainment)

    if flat is None:
        shape = np.broadcast_shapes(ux.shape, uy.shape, om.shape, a.shape, b.shape, pm.shape,
                                    hh.shape, temp.shape)
        ux, uy, om, a, b, pm, hh, temp = (np.broadcast_to(v, shape).reshape(-1)
                                          for v in (ux, uy, om, a, b, pm, hh, temp))
        eta_t = eta0 * np.exp(-c_t * (temp - t_ref))  # viscosity at ambient pressure, Pa s
    else:
        shape, (ux, uy, om, a, b, pm, hh) = flat
        eta_t = np.full(ux.shape[0], eta0)
    elastic = None
    if film_modulus is not None:
        elastic = (kap, np.broadcast_to(ent, shape).reshape(-1))
    rule = RuleParams(c_p, c1_coef, order, derivatives, lam_s, elastic)
    if fast:
        with np.errstate(over="ignore", invalid="ignore"):
            res = _fast_crook(ux, uy, om, a, b, pm, hh, eta_t, rule)  # (4 or 13, n), rows contiguous
        bad = ~np.all(np.isfinite(res), axis=0)
        if bad.any():  # float32 overflow (extreme slip at high pressure): redo in float64
            i = np.flatnonzero(bad)
            el = None if elastic is None else (elastic[0], elastic[1][i])
            res[:, i] = _accurate_crook(ux[i], uy[i], om[i], a[i], b[i], pm[i], hh[i], eta_t[i],
                                        rule._replace(elastic=el)).T
    else:
        res = _accurate_crook(ux, uy, om, a, b, pm, hh, eta_t, rule).T.copy()
    jac = res[4:].T.reshape(shape + (3, 3)) if derivatives else None
    return Traction(res[0].reshape(shape), res[1].reshape(shape), res[2].reshape(shape),
                    res[3].reshape(shape), jac)


def _quick_inputs(vals):
    """Validated flat float64 copies of (u_x, u_y, ω_s, a, b, p_max, h) and their shape when
    they all have one shape and pass every check, else None (the caller then checks them one
    by one, raising the documented errors).  A few numpy calls: this runs on every
    right-hand side of the dynamic model."""
    try:
        st = np.array(vals, dtype=float)
    except (TypeError, ValueError):  # ragged shapes or non-numeric
        return None
    shape = st.shape[1:]
    st = st.reshape(7, -1)
    if st.shape[1] == 0:
        return None
    total = float(st.sum())  # NaN or ±inf if any entry is
    lows = st[3:].min(axis=1)
    if not (total - total == 0.0 and lows[0] >= 0.0 and lows[1] >= 0.0 and lows[2] >= 0.0
            and lows[3] > 0.0):
        return None
    return shape, st
