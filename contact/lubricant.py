"""Lubricant properties, the Barus viscosity law (MODEL.md §5, paper P11) and the oil at
another temperature (Walther's relation, MODEL.md §14b)."""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np


def _check_positive(name: str, value: float, allow_zero: bool = False) -> None:
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
        raise ValueError(f"{name} must be a finite number, got {value!r}")
    if value < 0 or (value == 0 and not allow_zero):
        raise ValueError(f"{name} must be {'non-negative' if allow_zero else 'positive'}, got {value!r}")


@dataclass(frozen=True)
class Lubricant:
    """Newtonian lubricant with Barus pressure/temperature viscosity (MODEL.md §5).

    Parameters
    ----------
    viscosity : float
        Dynamic viscosity eta_0 at ``reference_temperature`` and ambient pressure, Pa s.
    reference_temperature : float
        T_R, degrees Celsius.
    pressure_viscosity : float
        Barus pressure-viscosity coefficient c_etaP, 1/Pa.
    temperature_viscosity : float
        Temperature-viscosity coefficient c_etaT, 1/K (= 1/degC).
    thermal_conductivity : float
        K_c, W/(m K); sets the Crook thermal softening (MODEL.md §6).
    density : float
        kg/m^3; used by the ball drag law (MODEL.md §8).
    limiting_shear_coefficient : float
        Lambda = tau_L / p >= 0, the limiting shear stress over the pressure (MODEL.md §6a):
        the traction law ``ContactLaw(traction='crook-limited')`` bounds the local shear
        stress smoothly by tau_L = Lambda p. 0: no limit. Default 0.047, a representative
        mineral-oil value: measured coefficients lie between about 0.03 and 0.1 and depend on
        base-oil chemistry, pressure and temperature (Hoglund & Jacobson 1986, ASME J. Tribol.
        108, 571-577, mineral and synthetic oils to 2.2 GPa and 200 degC; Wikstrom & Hoglund
        1994, ASME J. Tribol. 116, 612-620); 0.047 itself is not traced to a table of a
        primary paper (MODEL.md §6a, docs/lubricant_sensitivity.md for what it moves).
    film_shear_modulus_coefficient : float
        kappa = G / p > 0, the film's elastic shear modulus over the pressure (MODEL.md §6b),
        used where the contact law has ``film_elasticity``: it bounds the traction's initial
        slope. An input of its own, not rescaled when Lambda changes. Default 0.2953, chosen
        so that tau_L / G = 0.047 / 0.2953 = 1/(2 pi), the ratio the limiting shear stress and
        the shear modulus were found to approach with pressure ("The elastic properties of
        films in e.h.l. contacts", Proc. R. Soc. Lond. A 372 (1980) 155-168, four fluids incl.
        a paraffinic cylinder stock, Hertz pressures to 2 GPa: a limit, not a fit); of the
        size Johnson & Roberts (1974, Proc. R. Soc. Lond. A 337, 217) measured for a mineral
        oil at 23 degC, G = 0.1-1 GPa over 1-2 GPa (G/p 0.1-0.5).
    kinematic_viscosity_40, kinematic_viscosity_100 : float
        The oil's kinematic viscosities at 40 and 100 degC, m^2/s (the grades' data-sheet
        values), which fix Walther's relation (ASTM D341) for :meth:`at_temperature` (its
        shape: scaled through ``viscosity`` at ``reference_temperature``); 0 (the
        default): not given, the exponential law of ``temperature_viscosity`` instead. Used
        only where the oil's temperature changes (the thermal network, MODEL.md §14).
    """

    viscosity: float
    reference_temperature: float
    pressure_viscosity: float
    temperature_viscosity: float
    thermal_conductivity: float
    density: float
    limiting_shear_coefficient: float = 0.047
    film_shear_modulus_coefficient: float = 0.2953
    kinematic_viscosity_40: float = 0.0
    kinematic_viscosity_100: float = 0.0

    def __post_init__(self) -> None:
        _check_positive("viscosity", self.viscosity)
        if not isinstance(self.reference_temperature, (int, float)) or not math.isfinite(self.reference_temperature):
            raise ValueError(f"reference_temperature must be finite, got {self.reference_temperature!r}")
        _check_positive("pressure_viscosity", self.pressure_viscosity, allow_zero=True)
        _check_positive("temperature_viscosity", self.temperature_viscosity)
        _check_positive("thermal_conductivity", self.thermal_conductivity)
        _check_positive("density", self.density, allow_zero=True)
        _check_positive("limiting_shear_coefficient", self.limiting_shear_coefficient, allow_zero=True)
        _check_positive("film_shear_modulus_coefficient", self.film_shear_modulus_coefficient)
        _check_positive("kinematic_viscosity_40", self.kinematic_viscosity_40, allow_zero=True)
        _check_positive("kinematic_viscosity_100", self.kinematic_viscosity_100, allow_zero=True)
        if (self.kinematic_viscosity_40 > 0) != (self.kinematic_viscosity_100 > 0):
            raise ValueError("kinematic_viscosity_40, kinematic_viscosity_100: give both (Walther's relation) or "
                             "neither")
        if 0 < self.kinematic_viscosity_40 <= self.kinematic_viscosity_100:
            raise ValueError("kinematic_viscosity_40 must exceed kinematic_viscosity_100 (oil thins as it warms), "
                             f"got {self.kinematic_viscosity_40!r} <= {self.kinematic_viscosity_100!r}")

    @property
    def shear_heating(self) -> float:
        """c_etaT / K_c, m/W: how much the film's shear heating thins the oil, the Crook
        law's thermal parameter (MODEL.md §6, over 8) and the thermal film factor's (§11e)."""
        return float(self.temperature_viscosity / self.thermal_conductivity)

    def viscosity_at(self, pressure, temperature=None):
        """Barus viscosity eta = eta_0 exp(c_etaP p - c_etaT (T - T_R)), Pa s (P11).

        Parameters
        ----------
        pressure : array_like
            Pa.
        temperature : array_like, optional
            Degrees Celsius; ``reference_temperature`` if omitted.
        """
        exponent = self.pressure_viscosity * np.asarray(pressure, dtype=float)
        if temperature is not None:
            exponent = exponent - self.temperature_viscosity * (np.asarray(temperature, dtype=float) - self.reference_temperature)
        return self.viscosity * np.exp(exponent)

    def at_temperature(self, temperature: float) -> "Lubricant":
        """The oil at ``temperature`` (degC) and ambient pressure: its viscosity there, that
        temperature as the reference and the local c_etaT = -d ln(eta)/dT (MODEL.md §14b).

        With both kinematic viscosities given, Walther's relation (ASTM D341),
        log10 log10(nu + 0.7) = A - B log10(T), nu in cSt and T in K, through the two points,
        at constant density, scaled to pass through ``viscosity`` at ``reference_temperature``
        (the oil's own value stays; Walther gives how it changes); else
        eta_0 exp(-c_etaT (T - T_R)) with c_etaT unchanged.
        """
        if not isinstance(temperature, (int, float, np.floating)) or not math.isfinite(temperature):
            raise ValueError(f"temperature must be a finite number (degC), got {temperature!r}")
        if temperature <= -273.15:
            raise ValueError(f"temperature must lie above absolute zero, got {temperature!r} degC")
        if self.kinematic_viscosity_40 <= 0:
            eta = float(self.viscosity_at(0.0, temperature))
            return replace(self, viscosity=eta, reference_temperature=float(temperature))
        nu, slope = walther(self.kinematic_viscosity_40, self.kinematic_viscosity_100, float(temperature))
        nu_ref = walther(self.kinematic_viscosity_40, self.kinematic_viscosity_100, self.reference_temperature)[0]
        return replace(self, viscosity=self.viscosity * nu / nu_ref, reference_temperature=float(temperature),
                       temperature_viscosity=slope)


def walther(nu_40: float, nu_100: float, temperature: float) -> tuple:
    """(nu m^2/s, -d ln(nu)/dT 1/K) at ``temperature`` (degC) by Walther's relation (ASTM D341)
    through the kinematic viscosities ``nu_40`` and ``nu_100`` (m^2/s) at 40 and 100 degC:
    log10 log10(nu + 0.7) = A - B log10(T), nu in cSt, T in K (MODEL.md §14b)."""
    def y(nu):
        return math.log10(math.log10(nu * 1e6 + 0.7))

    x40, x100, x = (math.log10(t + 273.15) for t in (40.0, 100.0, temperature))
    b = (y(nu_40) - y(nu_100)) / (x100 - x40)
    z = 10.0 ** (10.0 ** (y(nu_40) - b * (x - x40)))  # nu + 0.7, cSt
    nu_cst = z - 0.7
    if nu_cst <= 0:
        raise ValueError(f"temperature {temperature!r} degC lies beyond Walther's relation of this oil (nu <= 0)")
    # d/dT of log10 log10 z = -B/(T ln 10)  =>  dz/dT = -B ln(10) z log10(z) / T
    return nu_cst * 1e-6, b * math.log(10.0) * z * math.log10(z) / (nu_cst * (temperature + 273.15))


#: Reference oil of Jain & Hunt (2011), table 1b, with the two values the OCR lost
#: (MODEL.md §8).
REFERENCE_LUBRICANT = Lubricant(
    viscosity=0.04,  # Pa s at 30 degC (paper table 1b)
    reference_temperature=30.0,  # degC (paper table 1b)
    # Lost by the OCR. 1.75e-8 1/Pa is an ordinary mineral-oil value and, with the ball
    # drag of MODEL.md §8 and fixed 40 deg angles, reproduces the paper's 1 % cage-slip
    # threshold at about 1.3 kN (1.5e-8 gives 1.9 kN, 2.0e-8 gives 0.95 kN).
    pressure_viscosity=1.75e-8,
    temperature_viscosity=0.05,  # 1/degC (paper table 1b)
    # Lost by the OCR; 0.14 W/(m K) is typical of mineral oil and matters little.
    thermal_conductivity=0.14,
    density=860.0,  # kg/m^3 (paper table 1b)
    # Not in the paper (its Crook law has no limit; ContactLaw(traction='crook') keeps it).
    # A representative mineral-oil tau_L / p; provenance in the class docstring and MODEL.md §6a.
    limiting_shear_coefficient=0.047,
    film_shear_modulus_coefficient=0.2953,  # tau_L / G = 1/(2 pi) (MODEL.md §6b)
)
