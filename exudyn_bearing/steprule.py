"""The default time step of a bearing scene (docs/MODEL.md §10a).

The implicit solver holds a step of 1e-4 s on the reference bearing; smaller, lighter balls
at the same or higher pressure need a smaller one. The step needed follows (an empirical
correlation, not a derivation) the ball's vibration between its two races: a ball of mass
m on the linearized Hertz springs k = dQ/dδ = 3Q/(2δ) of its inner and outer contacts rings at

    ω_n = √((k_i + k_o) / m).

Measured (generalized-alpha, default law, docs/heavy_load_matrix.md): the reference bearing
at 1.3, 2.2 + 2 radial and 10 kN runs without a step cut at 1e-4 s, ω_n h = 5.6–7.8; the
deep-groove 6205-size bearing at 1 kN radial + 200 N ran 215 steps for 200 nominal at
2.5e-5 s (ω_n h = 5.4) and 157 for 143 at 3.5e-5 s; the 7-mm-ball spindle bearing at
12 000 rpm held 5e-5 s axial (ω_n h = 12.9) and cut ~6 % of its steps at 2.5e-5 s with
radial load (ω_n h = 7.6). The default step is the nominal 1e-4 s divided by the smallest
whole number that brings ω_n h to 8 or below, so the output period of 1e-4 s stays a
multiple of it; at that step the radially loaded small-ball cases still cut 6–9 % of their
steps.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["NOMINAL_STEP", "MAX_VIBRATION_PHASE", "ball_vibration_frequency", "recommended_step"]

#: the step that holds on the reference bearing, s
NOMINAL_STEP = 1e-4
#: the largest ω_n h at which every step converged in the case matrix, rad
MAX_VIBRATION_PHASE = 8.0


def ball_vibration_frequency(bearing, loads) -> float:
    """Largest ω_n = √((k_i + k_o)/m) over the balls, rad/s, with k = 3Q/(2δ) the linearized
    Hertz stiffness of each loaded contact of the quasi-static ``loads``
    (:class:`exudyn_bearing.quasistatic.LoadDistribution`); 0 when no ball is loaded."""
    def stiffness(load, deflection):
        load, deflection = np.asarray(load, dtype=float), np.asarray(deflection, dtype=float)
        safe = np.where(deflection > 0, deflection, 1.0)
        return np.where((deflection > 0) & (load > 0), 1.5 * load / safe, 0.0)

    k = stiffness(loads.inner_load, loads.inner_deflection) + stiffness(loads.outer_load, loads.outer_deflection)
    return float(np.sqrt(k.max() / bearing.ball_mass)) if k.size else 0.0


def recommended_step(bearing, loads, nominal: float = NOMINAL_STEP) -> float:
    """``nominal`` / n, n the smallest whole number with ω_n h <= :data:`MAX_VIBRATION_PHASE`
    (:func:`ball_vibration_frequency`), s."""
    w_n = ball_vibration_frequency(bearing, loads)
    n = max(1, math.ceil(w_n * nominal / MAX_VIBRATION_PHASE - 1e-9))
    return nominal / n
