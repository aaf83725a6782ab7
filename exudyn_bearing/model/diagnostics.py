"""Why a bearing's run failed, as sentences for its error messages (MODEL.md §10): the most
demanding contact of a state, whether the applied load overloads the bearing, and where a
state first became non-finite. Mixed into :class:`~exudyn_bearing.model.connector.BearingConnector`."""
from __future__ import annotations

import numpy as np

__all__ = ["ConnectorDiagnostics"]


class ConnectorDiagnostics:
    """The connector's failure messages (uses its ``evaluate``, ``layout``, ``bearing``,
    ``lubricant``, ``rotation``, ``applied_force``, ``max_penetration`` and ``z``)."""

    def diagnose(self, t, q, q_t) -> str:
        """The most demanding contact of a (finite) state, as a sentence for error messages:
        the heaviest ball–race contact with its load, p_max, Barus exponent c_etaP p_max
        (MODEL.md §6, §10: the traction stiffness grows like its exponential) and the largest
        spin moment."""
        try:
            s = self.evaluate(t, q, q_t, details=True)
        except Exception as err:  # a diagnosis must never mask the original failure
            return f"(state not evaluable: {err})"
        loads = np.concatenate([s.inner_forces.normal_load, s.outer_forces.normal_load])
        if not np.all(np.isfinite(loads)):
            return "non-finite contact loads"
        k = int(np.argmax(loads))
        race, ball = ("inner", "outer")[k // self.z], k % self.z
        f = s.inner_forces if race == "inner" else s.outer_forces
        p_max = float(f.max_pressure[ball])
        mz = np.abs(np.concatenate([s.inner_forces.spin_moment, s.outer_forces.spin_moment]))
        return (f"t = {t:.6g} s: heaviest contact {race} race / ball {ball}: Q = {loads[k]:.4g} N, "
                f"p_max = {p_max / 1e9:.3g} GPa, Barus exponent c_etaP p_max = "
                f"{self.lubricant.pressure_viscosity * p_max:.3g}; largest spin moment {mz.max():.3g} N m")

    #: p_max above which a bearing steel contact is overloaded (plastic flow; ISO 76's static
    #: limit for ball bearings is 4.2 GPa), Pa
    overload_pressure = 4.0e9

    def capacity(self, t) -> str:
        """Whether the forces applied at ``t`` overload the bearing, as a sentence: the
        quasi-static load distribution (MODEL.md §4) for them, its heaviest ball load and
        p_max against :attr:`overload_pressure` and its elastic approach against
        :attr:`max_penetration`. Empty where no forces are applied through the bearing."""
        from ..solvers.quasistatic import QuasiStaticError, solve_load_distribution

        force = self.rotation.T @ np.asarray(self.applied_force(t), dtype=float)
        axial, radial = float(force[2]), float(np.hypot(force[0], force[1]))
        if axial <= 0 and radial <= 0:
            return ""
        what = f"the applied load ({axial:.4g} N axial, {radial:.4g} N radial)"
        try:
            qs = solve_load_distribution(self.bearing, axial_force=max(axial, 0.0), radial_force=radial)
        except (QuasiStaticError, ValueError) as err:
            return f"{what} has no quasi-static equilibrium ({err}): the bearing cannot carry it"
        worst = []
        for race, loads, angles in (("inner", qs.inner_load, qs.inner_contact_angle),
                                    ("outer", qs.outer_load, qs.outer_contact_angle)):
            k = int(np.argmax(loads))
            con = self.bearing.hertz(angles[k], race)
            worst.append((float(con.max_pressure(loads[k])), float(con.deflection(loads[k])), race, float(loads[k])))
        p_max, approach, race, q = max(worst)
        if p_max > self.overload_pressure or approach > self.max_penetration * self.bearing.ball_diameter:
            return (f"{what} overloads the bearing: quasi-statically {q:.4g} N on the heaviest {race} contact, "
                    f"p_max {p_max / 1e9:.3g} GPa (limit {self.overload_pressure / 1e9:g} GPa), elastic approach "
                    f"{1e3 * approach:.3g} mm")
        return (f"{what} is within the bearing's capacity (quasi-statically p_max {p_max / 1e9:.3g} GPa < "
                f"{self.overload_pressure / 1e9:g} GPa): the solver, not the bearing, failed")

    def _non_finite(self, t, pos, vel, omega) -> str:
        """Where the state first became non-finite, as a sentence."""
        names = {s: f"ball {i}" for i, s in enumerate(self.layout["balls"])}
        names.update({self.layout[k]: f"{k} race" if k != "cage" else "cage" for k in ("cage", "inner", "outer")
                      if self.layout[k] is not None})
        for what, arr in (("position", pos), ("velocity", vel), ("angular velocity", omega)):
            bad = np.flatnonzero(~np.all(np.isfinite(arr), axis=1))
            if bad.size:
                return f"t = {t:.6g} s: non-finite {what} of {names.get(int(bad[0]), f'node slot {bad[0]}')}"
        return f"t = {t:.6g} s: non-finite state"
