"""The pointwise Maxwell-film laws (MODEL.md §6b) against Johnson & Tevaarwerk's equation
solved along the streamlines, over z = G L/(η ū) from 0.01 to 100.

The rules apply a law point by point: the elastic stress a particle has built up since the
inlet (τ_e = G ξ v/(ū h), or with ∫G dx instead of G ξ) combined with the viscous stress τ_v
(Crook's, limited). Here the Maxwell equation, (|ū| h/G) dτ/dx = v − s with τ = τ_v(s, p) the
stress of the viscous element at its own slip s, τ = 0 at the inlet edge, is integrated along
each streamline of a Hertzian contact (:func:`contact.film_elasticity.maxwell_streamline`)
with the model's viscous law, written out here on its own: Barus viscosity η = η0 e^(c_ηP p),
Crook's thermal stress τ_C = (η/h) v ln(√ψ + √(1 + ψ))/√(ψ(1 + ψ)), ψ = η c_ηT v²/(8 K),
limited as Λ p tanh(τ_C/(Λ p)); G = κ p. No spin (the slip is constant along a streamline).
Backward Euler in θ (x = c sin θ, which clusters steps at both edges), two step sizes and
Richardson's extrapolation; the pointwise laws integrated over the ellipse with the same
nodes, so the differences are the laws', not the quadrature's.

    python benchmarks/film_maxwell.py [--steps 1200] [--json out.json]

z = 2 b κ p_max / (η_eff ū), η_eff = τ_v h / v at the pressure peak: the ratio of the
elastic to the viscous stress a particle carries through the contact.
"""
import argparse
import json

import numpy as np

from contact.film_elasticity import maxwell_streamline
from contact.lubricant import REFERENCE_LUBRICANT as OIL

KAPPA = OIL.film_shear_modulus_coefficient
LAM = OIL.limiting_shear_coefficient


def viscous_stress(v, p, h, oil=OIL, lam=LAM):
    """τ_v(v) of the limited Crook law at pressure p (Pa), slip v ≥ 0 (m/s), film h (m);
    ``lam`` None: Crook's law without the limit."""
    eta = oil.viscosity * np.exp(oil.pressure_viscosity * p)
    psi = eta * oil.temperature_viscosity * v * v / (8.0 * oil.thermal_conductivity)
    sq = np.sqrt(psi)
    with np.errstate(invalid="ignore", divide="ignore"):
        factor = np.where(psi > 1e-12, np.log(sq + np.sqrt(1.0 + psi)) / np.sqrt(psi * (1.0 + psi)), 1.0 - psi / 3.0)
    tau_c = eta / h * v * factor
    if lam is None:
        return tau_c
    tau_l = lam * p
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(tau_l > 0, tau_l * np.tanh(tau_c / np.where(tau_l > 0, tau_l, 1.0)), 0.0)


#: pointwise laws compared: (elastic strain, combination, where the limiting shear enters)
LAWS = {
    "exponential, ∫G dx, limit in τ_v": ("integral", "exponential", "inside"),
    "exponential, G ξ, limit in τ_v": ("local", "exponential", "inside"),
    "exponential, G ξ, limit after": ("local", "exponential", "after"),
    "series, G ξ, limit after": ("local", "series", "after"),
    "series, G ξ, limit in τ_v": ("local", "series", "inside"),
    "series, ∫G dx, limit in τ_v": ("integral", "series", "inside"),
}


def _pointwise(law, v, p, h, strain_integral, strain_local):
    """τ of one pointwise law at the points (MODEL.md §6b)."""
    strain, combine, limit = LAWS[law]
    te = KAPPA * (strain_integral if strain == "integral" else p * strain_local) * v / h
    tv = viscous_stress(v, p, h, lam=LAM if limit == "inside" else None)
    with np.errstate(invalid="ignore", divide="ignore"):
        if combine == "exponential":
            tau = np.where(tv > 0, tv * -np.expm1(-te / np.where(tv > 0, tv, 1.0)), 0.0)
        else:
            tau = np.where(te + tv > 0, te * tv / np.where(te + tv > 0, te + tv, 1.0), 0.0)
        if limit == "after":
            tau = np.where(p > 0, LAM * p * np.tanh(tau / np.where(p > 0, LAM * p, 1.0)), 0.0)
    return tau


def streamline_force(v, a, b, pm, h, ent, n_y=32, steps=1200):
    """Traction ∬ τ dA (N, no spin) of the solved Maxwell film and of each law of LAWS."""
    yg, wy = np.polynomial.legendre.leggauss(n_y)
    s_y = np.sqrt(1.0 - yg ** 2)  # streamline half-length over b
    c = b * s_y
    results = []
    for n in (steps // 2, steps):
        th = np.linspace(-0.5 * np.pi, 0.5 * np.pi, n + 1)[:, None]
        path = c * (np.sin(th) + 1.0)  # from the inlet edge (ū > 0)
        p = pm * s_y * np.cos(th)
        weight = c * np.cos(th) * (th[1, 0] - th[0, 0]) * a * wy  # dx dy, x = c sin θ
        tau = maxwell_streamline(lambda s, pp: viscous_stress(s, pp, h), path, p, v, ent, h, KAPPA)
        integral_p = pm * s_y * c / 2 * (th + np.sin(th) * np.cos(th) + np.pi / 2)  # ∫ p dx'
        sums = [np.sum(weight * tau)]
        for law in LAWS:
            sums.append(np.sum(weight * _pointwise(law, v, p, h, integral_p / abs(ent), path / abs(ent))))
        results.append(np.array(sums))
    return 2 * results[1] - results[0]  # Richardson: backward Euler is first order


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=1200)
    parser.add_argument("--json", default=None)
    args = parser.parse_args()
    cases = [("1.7 GPa, ū 10 m/s", (1.4e-3, 0.2e-3, 1.7e9, 0.3e-6), 10.0),
             ("1.0 GPa, ū 3 m/s", (0.82e-3, 0.118e-3, 1.0e9, 0.2e-6), 3.0)]
    rows = []
    names = list(LAWS)
    print("| contact | slip m/s | z | solved N | " + " | ".join(names) + " |")
    print("|---|---|---|---|" + "---|" * len(names))
    for name, (a, b, pm, h), ent in cases:
        for v in np.geomspace(1e-7, 0.3, 16):
            tv0 = float(viscous_stress(v, pm, h))
            z = 2 * b * KAPPA * pm * v / (ent * tv0 * h)
            forces = streamline_force(v, a, b, pm, h, ent, steps=args.steps)
            errors = {law: forces[1 + i] / forces[0] - 1.0 for i, law in enumerate(names)}
            rows.append(dict(contact=name, slip=v, z=z, solved_N=forces[0], errors=errors))
            print(f"| {name} | {v:.3g} | {z:.3g} | {forces[0]:.5g} | "
                  + " | ".join(f"{e:+.1%}" for e in errors.values()) + " |", flush=True)
    inside = [r for r in rows if 0.01 <= r["z"] <= 100]
    print("\nworst error over z 0.01–100:")
    for law in names:
        worst = max(inside, key=lambda r: abs(r["errors"][law]))
        print(f"- {law}: {worst['errors'][law]:+.1%} (z = {worst['z']:.3g}, {worst['contact']})")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(dict(rows=rows, steps=args.steps, kappa=KAPPA, lam=LAM), fh, indent=1)


if __name__ == "__main__":
    main()
