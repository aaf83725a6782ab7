"""Inlet shear heating: the thermal reduction of the EHD film at speed (MODEL.md §11e; beyond
the paper). A per-contact term (:mod:`contact.terms`), written once as a scalar numba
function that the compiled kernels call per contact and the array function applies element
by element (:mod:`contact.elementwise`)."""
from __future__ import annotations

from numba import njit

from .elementwise import apply, at

__all__ = ["thermal_film_factor", "film_factor"]


@njit(cache=True, error_model="numpy")
def film_factor(entrainment, slip, max_pressure, e_prime, viscosity, heating, floor):
    """φ_T in [``floor``, 1] of one contact (MODEL.md §11e), 1 at zero entrainment.

    Zhu & Cheng's fit as given by Zhou & Hoeprich (1991, ASME J. Tribol. 113, 590, eq. 21)
    and Gupta et al. (1992, ASME J. Tribol. 114, 707):

        φ_T = (1 - 13.2 (p_H/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64),
        L = η0 c_ηT u_r² / K,   S = |u_s| / u_r,

    u_r = |``entrainment``| (m/s), u_s = ``slip`` along it (m/s), p_H = ``max_pressure`` and
    E' (Pa), η0 = ``viscosity`` (Pa s), ``heating`` = c_ηT / K (m/W). Clipped to
    [``floor``, 1]: the fit's numerator turns negative far outside its data.
    """
    if entrainment == 0.0:
        return 1.0
    u_r = abs(entrainment)
    l_t = viscosity * heating * u_r * u_r
    s_r = abs(slip) / u_r
    phi = ((1.0 - 13.2 * (max_pressure / e_prime) * l_t ** 0.42)
           / (1.0 + 0.213 * (1.0 + 2.23 * s_r ** 0.83) * l_t ** 0.64))
    return min(max(phi, floor), 1.0)


@njit(cache=True, error_model="numpy")
def _film_factors(out, entrainment, slip, max_pressure, e_prime, viscosity, heating, floor):
    for i in range(out.size):
        out[i] = film_factor(at(entrainment, i), at(slip, i), at(max_pressure, i), at(e_prime, i), at(viscosity, i),
                             at(heating, i), at(floor, i))


def thermal_film_factor(entrainment, slip, max_pressure, e_prime, viscosity, temperature_viscosity,
                        thermal_conductivity, floor=0.05):
    """φ_T of :func:`film_factor` on arrays (broadcast; SI units): ``temperature_viscosity``
    c_ηT (1/K) and ``thermal_conductivity`` K (W/(m K)) of the lubricant."""
    return apply(_film_factors, entrainment, slip, max_pressure, float(e_prime), viscosity,
                 float(temperature_viscosity) / float(thermal_conductivity), float(floor))
