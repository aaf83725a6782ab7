"""Ball–pocket and guiding-land contacts of the rigid cage (contact/cage.py, MODEL.md §1) and
their compiled twins: the pocket's damping acts on the rate of the ball's offset in its
pocket; the land's damping rises from zero with the penetration."""
import numpy as np
import pytest

from contact.cage import pocket_forces

PITCH = 0.0775
STIFFNESS, DAMPING = 1e8, 250.0


def _co_rotating(w=82.0, radial_offset=60e-6, s=0.0, z=8):
    """Balls orbiting with the cage at w, radial_offset outside the pitch circle, s ahead of
    their pocket centres (cage frame = bearing frame at t = 0)."""
    psi = 2 * np.pi * np.arange(z) / z
    e_r = np.stack([np.cos(psi), np.sin(psi), np.zeros(z)], axis=1)
    e_p = np.stack([-np.sin(psi), np.cos(psi), np.zeros(z)], axis=1)
    c = (PITCH + radial_offset) * e_r + s * e_p
    v = np.cross(np.array([0.0, 0.0, w]), c)
    return psi, c, v, np.array([0.0, 0.0, w])


def test_balls_orbiting_with_their_pockets_feel_no_damping():
    """s does not change for a ball that orbits with its pocket, whatever its orbit radius, so
    a ball at the pocket centre feels nothing; one held s ahead feels the spring -k s only.
    (Differentiating s without the turning of the pocket's direction gave a damping force
    -c w dr: 1.2 N here.)"""
    psi, c, v, w = _co_rotating()
    f = pocket_forces(c, v, np.zeros(3), np.eye(3), np.zeros(3), w, psi, PITCH, 0.0, STIFFNESS, DAMPING)
    np.testing.assert_allclose(f, 0.0, atol=1e-9)
    psi, c, v, w = _co_rotating(s=2e-8)
    f = pocket_forces(c, v, np.zeros(3), np.eye(3), np.zeros(3), w, psi, PITCH, 0.0, STIFFNESS, DAMPING)
    e_p = np.stack([-np.sin(psi), np.cos(psi), np.zeros(psi.size)], axis=1)
    np.testing.assert_allclose(np.einsum("ij,ij->i", f, e_p), -STIFFNESS * 2e-8, rtol=1e-6)


def test_damping_acts_on_the_relative_circumferential_speed():
    """A ball 1 mm/s faster than its pocket along the orbit: -c * 1e-3 N from the damper."""
    psi, c, v, w = _co_rotating()
    e_p = np.stack([-np.sin(psi), np.cos(psi), np.zeros(psi.size)], axis=1)
    f = pocket_forces(c, v + 1e-3 * e_p, np.zeros(3), np.eye(3), np.zeros(3), w, psi, PITCH, 0.0, STIFFNESS, DAMPING)
    np.testing.assert_allclose(np.einsum("ij,ij->i", f, e_p), -DAMPING * 1e-3, rtol=1e-7)


def test_compiled_pocket_forces_match():
    kernels = pytest.importorskip("contact.kernels")
    psi, c, v, w = _co_rotating(s=3e-8)
    rng = np.random.default_rng(3)
    v = v + 1e-3 * rng.standard_normal(v.shape)
    cage_o, cage_v = np.array([[1e-6, -2e-6, 0.0]]), np.array([[1e-3, 0.0, 0.0]])
    rot = np.eye(3)[None]
    expected = pocket_forces(c[None], v[None], cage_o, rot, cage_v, w[None], psi, PITCH, 0.0, STIFFNESS, DAMPING)
    cage_force, drag_force = np.zeros((1, psi.size, 3)), np.zeros((1, psi.size, 3))
    params = kernels.CageRecord(1, psi, PITCH, 0.0, STIFFNESS, DAMPING, np.array([0.0, 0.0, 1.0]), np.zeros(3), 0.0)
    kernels.cage_and_drag(c[None], v[None], params, kernels.BodyStates(cage_o, rot, cage_v, w[None]), cage_force,
                          drag_force)
    np.testing.assert_allclose(cage_force, expected, rtol=1e-9, atol=1e-12)


def test_land_force_starts_from_zero_at_any_approach_speed():
    """A cage closing on its land at 0.2 m/s: the force is continuous at contact (zero at the
    land, not c * 0.2 m/s), has its full damping beyond the ramp's 10 um, and pushes only."""
    from contact.cage import LAND_DAMPING_DEPTH, land_forces

    k, c, play = 1e7, 160.0, 0.2e-3
    axis, race = np.array([0.0, 0.0, 1.0]), np.zeros(3)
    v = np.array([0.2, 0.0, 0.0])

    def force(pen, speed=v):
        return land_forces(np.array([play + pen, 0.0, 0.0]), speed, race, race, axis, play, k, c)[0]

    assert abs(force(1e-12)) < 1e-4 and force(-1e-6) == 0.0
    assert force(2 * LAND_DAMPING_DEPTH) == pytest.approx(-(k * 2 * LAND_DAMPING_DEPTH + c * 0.2))
    small = force(0.1 * LAND_DAMPING_DEPTH)
    assert -(k * 0.1 * LAND_DAMPING_DEPTH + c * 0.2) < small < -k * 0.1 * LAND_DAMPING_DEPTH
    # leaving the land fast, the damping never makes it pull
    assert force(2 * LAND_DAMPING_DEPTH, -50 * v) == 0.0
    kernels = pytest.importorskip("contact.kernels")
    for pen in (1e-12, 0.1 * LAND_DAMPING_DEPTH, 0.7 * LAND_DAMPING_DEPTH, 2 * LAND_DAMPING_DEPTH):
        out, ecc = np.zeros((1, 3)), np.zeros(1)
        kernels.land_forces(np.array([[play + pen, 0.0, 0.0]]), v[None], race[None], race[None], axis[None], play, k, c,
                            0.0, np.zeros(1), out, ecc)
        np.testing.assert_allclose(out[0], [force(pen), 0.0, 0.0], rtol=1e-12, atol=1e-12)
