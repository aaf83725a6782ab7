"""Conductances of a bearing's thermal network from geometry and textbook correlations
(MODEL.md §14a). Plain functions of SI numbers, W/K; no state.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["cylinder_conduction", "rod_conduction", "spot_conductance", "film_conduction", "plate_convection",
           "mixture_properties", "enthalpy_flow"]


def cylinder_conduction(r_in: float, r_out: float, length: float, conductivity: float) -> float:
    """Radial conduction through a cylindrical shell, 2 pi k L / ln(r_out / r_in), W/K
    (eq. 14.2; Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, eq. 3.33)."""
    if not 0 < r_in < r_out:
        raise ValueError(f"cylinder_conduction: need 0 < r_in < r_out, got {r_in!r}, {r_out!r}")
    return 2.0 * math.pi * conductivity * length / math.log(r_out / r_in)


def rod_conduction(radius: float, length: float, conductivity: float) -> float:
    """Axial conduction along a solid round bar, k pi r^2 / L, W/K (eq. 14.3)."""
    return conductivity * math.pi * radius ** 2 / length


def spot_conductance(a, b, conductivity, speed=0.0, diffusivity=1.0):
    """Conductance of a contact spot of semi-axes ``a``, ``b`` (m) into a half-space of
    ``conductivity`` (W/(m K)) and ``diffusivity`` (m^2/s) whose surface passes it at
    ``speed`` (m/s), W/K (eq. 14.4):

        G = k r sqrt(16 + (1/0.308)^2 V r / kappa),   r = sqrt(a b),

    which joins Archard's mean temperatures of a circular spot (Wear 2 (1959) 438; as in
    Stachowiak & Batchelor, Engineering Tribology, ch. 7): at rest Q/(4 k r) (Holm's
    constriction, G = 4 k r) and at high Peclet number 0.308 Q/(k r) (kappa/(V r))^(1/2).
    The ellipse as the circle of equal area."""
    r = np.sqrt(np.maximum(np.asarray(a, dtype=float), 0.0) * np.maximum(np.asarray(b, dtype=float), 0.0))
    peclet = np.abs(np.asarray(speed, dtype=float)) * r / diffusivity
    return conductivity * r * np.sqrt(16.0 + (1.0 / 0.308) ** 2 * peclet)


def film_conduction(a, b, film, conductivity):
    """Conduction across the oil film of a contact ellipse, k pi a b / h, W/K (eq. 14.4b)."""
    return conductivity * np.pi * np.asarray(a, dtype=float) * np.asarray(b, dtype=float) / np.asarray(film, dtype=float)


def plate_convection(speed: float, length: float, conductivity: float, kinematic_viscosity: float,
                     prandtl: float) -> float:
    """Mean heat-transfer coefficient of a surface swept by a fluid at ``speed`` over
    ``length``, W/(m^2 K) (eq. 14.5): the flat plate's

        h = 0.664 k/L Re^(1/2) Pr^(1/3)   (laminar, Re <= 3e5; Pohlhausen),
        h = 0.037 k/L Re^(4/5) Pr^(1/3)   (turbulent from the leading edge),   Re = u L / nu,

    (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, eqs. 7.30 and 7.38), the
    form Jungnickel's bearing networks use for surfaces in the oil–air mixture (TU Dresden
    2010, as coded in the open thermal library Thermca, ``thermca/lib/forced_conv.py``)."""
    if speed <= 0 or length <= 0:
        return 0.0
    reynolds = speed * length / kinematic_viscosity
    if reynolds <= 3e5:
        return 0.664 * conductivity / length * math.sqrt(reynolds) * prandtl ** (1.0 / 3.0)
    return 0.037 * conductivity / length * reynolds ** 0.8 * prandtl ** (1.0 / 3.0)


def mixture_properties(oil_fraction: float, oil_density: float, oil_viscosity: float, oil_conductivity: float,
                       oil_specific_heat: float, air=(1.2, 1.8e-5, 0.026, 1005.0)) -> dict:
    """Effective properties of the oil–air mixture in the cavity at oil volume fraction X
    (eq. 14.6): density and conductivity volume-weighted, specific heat mass-weighted,
    viscosity volume-weighted (Pouly et al. 2010 take the cavity fluid so); ``air`` =
    (density kg/m^3, viscosity Pa s, conductivity W/(m K), specific heat J/(kg K)) at
    room temperature. Returns density, viscosity, kinematic_viscosity, conductivity,
    specific_heat, prandtl."""
    x = float(oil_fraction)
    rho_a, mu_a, k_a, c_a = air
    rho = x * oil_density + (1.0 - x) * rho_a
    mu = x * oil_viscosity + (1.0 - x) * mu_a
    k = x * oil_conductivity + (1.0 - x) * k_a
    c = (x * oil_density * oil_specific_heat + (1.0 - x) * rho_a * c_a) / rho
    return {"density": rho, "viscosity": mu, "kinematic_viscosity": mu / rho, "conductivity": k,
            "specific_heat": c, "prandtl": mu * c / k}


def enthalpy_flow(flow: float, density: float, specific_heat: float) -> float:
    """rho V c_p, W/K: the heat the oil carries off per kelvin it warms (eq. 14.7)."""
    return float(flow) * float(density) * float(specific_heat)
