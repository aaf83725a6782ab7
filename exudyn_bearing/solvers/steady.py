"""Steady rolling state of a bearing under pure axial load (MODEL.md §12), with its
temperatures where the setup has a thermal network (§14).

The balance itself lives in :mod:`~exudyn_bearing.solvers.steady_balance`, the thermal
fixed point in :mod:`~exudyn_bearing.solvers.thermal`.
"""
from __future__ import annotations

import math
import time as _time

import numpy as np

from contact.ballrace import ContactLaw
from contact.lubricant import Lubricant
from ..bearing import BallDrag, Bearing
from ..bearingfile import as_setup
from ..cage import CageModel
from ..presets import REFERENCE_BEARING
from ..renamed import accepts_old_names
from ..results.records import setup_inputs
from ..setup import FROM_SETUP, BearingSetup, refuse_surface
from .steady_balance import SteadyState, solve_steady, steady_result
from .thermal import thermal_steady_state

__all__ = ["SteadyState", "steady_state", "check_finite"]


def check_finite(**values) -> None:
    """A ValueError naming the first of the loads (N) and speeds (rev/min) ``values`` that is
    not a finite number (the steady and quasi-dynamic solvers' inputs)."""
    for name, value in values.items():
        if not isinstance(value, (int, float, np.floating)) or not math.isfinite(value):
            raise ValueError(f"{name} must be a finite number, got {value!r}")


@accepts_old_names
def steady_state(bearing: Bearing | BearingSetup | str = REFERENCE_BEARING, lubricant: Lubricant = FROM_SETUP, *,
                 axial_force: float, rpm: float, outer_rpm: float = 0.0, ball_drag: BallDrag | None = FROM_SETUP,
                 contact_law: ContactLaw = FROM_SETUP, cage=FROM_SETUP, thermal=FROM_SETUP,
                 tol: float = 1e-8) -> SteadyState:
    """Steady rolling state under pure axial load (MODEL.md §12).

    Parameters
    ----------
    bearing, lubricant
        As for :func:`exudyn_bearing.simulate` (a setup, or a bearing file's path, gives the
        lubricant, ball drag, contact law and cage unless they are passed explicitly). A
        setup with defects or waviness is refused (they have no steady state); its housing
        carries the load without changing the balls' state.
    axial_force : float
        Axial load on the inner race, N (> 0).
    rpm, outer_rpm : float
        Inner- and outer-race speeds, rev/min.
    ball_drag : BallDrag or None
        Ball drag (MODEL.md §8); None: none.
    contact_law : ContactLaw
        Ball–race physics, as in the dynamic model.
    cage : CageModel, optional
        Its guiding land's friction torque (``land_width`` > 0, MODEL.md §11d), with the cage
        centred, loads the balls through the pockets; None or no land friction (the
        default ``CageModel()``): a free cage.
    thermal : contact.bearing_thermal.ThermalModel or None
        The thermal network (MODEL.md §14): the state and the node temperatures solved
        together, each contact's oil at its race's and ball's mean temperature; None: every
        contact at the lubricant's own viscosity.
    tol : float
        Largest scaled residual accepted (forces relative to F_a / (Z sin a0)).

    Returns
    -------
    SteadyState
        ``converged`` False (with ``message``) where no steady state was found — e.g. a
        limit cycle, where the dynamic model does not settle either; the numbers are then
        those of the best iterate and must not be used as a result.

    Raises
    ------
    ValueError
        Non-finite or non-positive ``axial_force``, non-finite speeds.
    """
    start = _time.perf_counter()
    setup = as_setup(bearing, lubricant=lubricant, drag=ball_drag, contact_law=contact_law,
                     cage=CageModel() if cage is None else cage, thermal=thermal)
    refuse_surface(setup, "steady_state", "simulate or vibration")
    check_finite(axial_force=axial_force, rpm=rpm, outer_rpm=outer_rpm)
    if axial_force <= 0:
        raise ValueError("axial_force must be positive (the steady state is for an axially loaded bearing), "
                         f"got {axial_force!r}")
    if rpm == outer_rpm:
        raise ValueError("rpm, outer_rpm: the races turn at the same speed; nothing rolls")
    inputs = setup_inputs(setup, outer_rpm=outer_rpm)
    if setup.thermal is not None:
        return thermal_steady_state(setup, float(axial_force), rpm, outer_rpm, tol, start, inputs)
    solved = solve_steady(setup, float(axial_force), rpm, outer_rpm, tol)
    return steady_result(solved, _time.perf_counter() - start, inputs)
