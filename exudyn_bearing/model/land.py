"""The guiding land of a race-guided cage (MODEL.md §1, §11d): its constants, and its force,
friction torque and losses for batches of node states. Mixed into
:class:`~exudyn_bearing.model.connector.BearingConnector`."""
from __future__ import annotations

import numpy as np

from contact import cage as cage_physics
from contact.kinematics import cross
from contact.land_film import land_film_forces

__all__ = ["GuidingLand", "land_guide"]


def land_guide(bearing, lubricant, cage):
    """(race, radial play m, stiffness N/m, damping N s/m, friction constant N m s, film
    constant N s, largest ε) of ``cage``'s guiding land, or None for an unguided cage:
    2 π η0 R³ L / c of its land friction, η0 R L³ / c² of its film's force (MODEL.md §11d,
    eq. 11d.1); a ValueError where the land's play would let the cage leave the annulus."""
    if cage.guided and cage.guide_clearance >= 0.25 * bearing.ball_diameter:
        raise ValueError(f"guide_clearance: {cage.guide_clearance:g} m of diametral land play is not below a "
                         f"quarter of the ball diameter ({0.25 * bearing.ball_diameter:g} m); the cage ring "
                         "would leave the annulus between the races")
    if not cage.guided:
        return None
    damping = cage.guide_damping
    if damping is None:
        damping = 2 * 0.2 * np.sqrt(cage.guide_stiffness * cage.mass_for(bearing))
    return (cage.guidance, 0.5 * cage.guide_clearance, cage.guide_stiffness, damping,
            cage.land_friction_constant(bearing, lubricant), cage.land_film_constant(bearing, lubricant),
            cage.land_max_ratio)


class GuidingLand:
    """The land's force, torque and losses (uses the connector's ``guide``, ``layout``,
    ``cage``, ``_race_frame`` and ``_land_kernel``)."""

    def land_force(self, t, pos, rot, vel, omega):
        """Guiding-land force on the cage (B, 3), N, the guiding race's slot (or None) and
        the cage's eccentricity (B,), m, for a batch of node states (omega GLOBAL): the contact
        beyond the play (:func:`contact.cage.land_forces`) and the film's short-bearing force
        (:func:`contact.land_film.land_film_forces`, with its constant > 0)."""
        race, play, stiffness, damping, _, film, _ = self.guide
        s = self.layout["cage"]
        origin, rotation, v_race, w_race, slot = self._race_frame(race, t, pos, vel, rot, omega)
        axis = rotation[..., 2]
        spin = np.einsum("bi,bi->b", omega[:, s] + w_race, axis) if film > 0 else np.zeros(pos.shape[0])
        if self._land_kernel is not None:  # the same in one compiled loop (the numpy calls cost ~0.1 ms)
            c = np.ascontiguousarray
            force, e = np.empty((pos.shape[0], 3)), np.empty(pos.shape[0])
            self._land_kernel(c(pos[:, s]), c(vel[:, s]), c(origin), c(v_race), c(axis), play, stiffness, damping,
                              film, c(spin), force, e)
            return force, slot, e
        force = cage_physics.land_forces(pos[:, s], vel[:, s], origin, v_race, axis, play, stiffness, damping)
        offset = cage_physics.radial_offset(pos[:, s], origin, axis)
        if film > 0:
            rate = vel[:, s] - v_race
            rate = rate - np.einsum("bi,bi->b", rate, axis)[:, None] * axis
            force = force + land_film_forces(offset, rate, axis, spin, film, play)
        return force, slot, np.linalg.norm(offset, axis=-1)

    def _land_details(self, t, pos, rot, vel, omega) -> dict:
        """The :class:`ConnectorState` fields of the cage's land for B states, each (B,) or
        (B, 3): eccentricity (m; an unguided rigid cage's from the outer race axis), land force
        (N, None: not guided), the power its force pair dissipates, −F·(v_cage − v_land) with
        v_land the guiding race's point under the cage centre, and with land friction the power
        its film's shear dissipates, T (w_race − w_cage); the power the race puts in through
        both, T w_race + F·v_land (W)."""
        b = pos.shape[0]
        details = dict(cage_eccentricity=np.zeros(b), land_force_loss=np.zeros(b), land_friction_loss=np.zeros(b),
                       land_drive_power=np.zeros(b))
        if self.guide is None:
            if self.cage.kind == "rigid":
                origin, rotation, _, _, _ = self._race_frame("outer", t, pos, vel, rot, omega)
                details["cage_eccentricity"] = np.linalg.norm(cage_physics.radial_offset(
                    pos[:, self.layout["cage"]], origin, rotation[..., 2]), axis=-1)
            return details
        force, _, e = self.land_force(t, pos, rot, vel, omega)
        s = self.layout["cage"]
        origin, _, v_race, w_race, _ = self._race_frame(self.guide[0], t, pos, vel, rot, omega)
        v_land = v_race + cross(w_race, pos[:, s] - origin)
        drive = np.einsum("bi,bi->b", force, v_land)
        details.update(cage_eccentricity=e, cage_land_force=force, land_drive_power=drive,
                       land_force_loss=-np.einsum("bi,bi->b", force, vel[:, s]) + drive)
        if self.guide[4] > 0:
            torque, axis, w_land = self.land_torque(t, pos, rot, vel, omega, e)
            slip = w_land - np.einsum("bi,bi->b", omega[:, s], axis)
            details.update(land_friction_loss=torque * slip, land_drive_power=drive + torque * w_land)
        return details

    def land_torque(self, t, pos, rot, vel, omega, eccentricity):
        """Friction torque of the guiding land's oil film on the cage about the race axis,
        (B,) N m (MODEL.md §11d; the race takes the opposite), that axis (B, 3) and the land's
        speed about it (B,) rad/s."""
        race, play, _, _, friction, _, max_ratio = self.guide
        _, rotation, _, w_race, _ = self._race_frame(race, t, pos, vel, rot, omega)
        axis = rotation[..., 2]
        w_cage = np.einsum("bi,bi->b", omega[:, self.layout["cage"]], axis)
        w_land = np.einsum("bi,bi->b", w_race, axis)
        torque = cage_physics.land_friction_torque(friction, w_land - w_cage, eccentricity / play, max_ratio)
        return torque, axis, w_land

    def _add_land_force(self, t, pos, rot, vel, omega, out):
        """Adds the guiding-land force (and the land's friction torque) to the cage slot and
        their reactions (at the cage centre) to the guiding race's slot, in place."""
        force, slot, e = self.land_force(t, pos, rot, vel, omega)
        cage = self.layout["cage"]
        out[:, cage, :3] += force
        moment = np.zeros_like(force)
        if self.guide[4] > 0:
            torque, axis, _ = self.land_torque(t, pos, rot, vel, omega, e)
            moment = torque[:, None] * axis
            out[:, cage, 3:] += np.einsum("bji,bj->bi", rot[:, cage], moment)
        if slot is not None:
            out[:, slot, :3] -= force
            torque = cross(pos[:, cage] - pos[:, slot], -force) - moment
            out[:, slot, 3:] += np.einsum("bji,bj->bi", rot[:, slot], torque)
