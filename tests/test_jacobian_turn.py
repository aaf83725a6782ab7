"""The Jacobian handed to Exudyn with the balls' rotation blocks turned ahead (MODEL.md §10c):
its blocks are the block Jacobian at the state whose balls have turned about their own angular
velocity, a state with the same forces in the global frame."""
import numpy as np
import pytest

from exudyn_bearing import ContactLaw
from exudyn_bearing.model.predictor import compose_rotation_vectors
from exudyn_bearing.model.start_residual import StartResidual
from tests.helpers import _scene


def _turned_state(con, q, qt, tau):
    """q with every ball's rotation composed with exp(ω̃ τ), ω its local angular velocity."""
    q2 = q.copy().reshape(-1, 6)
    w = qt.reshape(-1, 6)[:, 3:]
    balls = np.asarray(con.layout["balls"])
    q2[balls, 3:] = compose_rotation_vectors(q2[balls, 3:], w[balls] * tau)
    return q2.ravel()


def _rotation_rows(con):
    balls = np.asarray(con.layout["balls"])
    return (6 * balls[:, None] + 3 + np.arange(3)).ravel()


@pytest.mark.filterwarnings("ignore::exudyn_bearing.NumpyPathWarning")
def test_turned_blocks_are_the_block_jacobian_at_the_turned_balls():
    """A smooth law (Newtonian traction, the numpy path): the float32 Crook rule's difference
    quotients carry noise of the size of the turn itself in a ball's rotation columns (its
    position columns are its angular-velocity columns times ω, ~550 rad/s here)."""
    _, con, q, qt = _scene(law=ContactLaw(traction="newtonian", compiled=False), axialForce=1300.0)
    f_q, f_qt = 1.0, 1500.0  # τ = f_q/f_qt: the balls (~600 rad/s) turn by ~0.4 rad
    tau = f_q / f_qt
    q2 = _turned_state(con, q, qt, tau)
    rows = _rotation_rows(con)
    # the premise: the turned balls' forces are the same in the global frame, their moments
    # (body frame) turned
    f1 = con.residual_forces(0.01, q - con.reference, qt)
    f2 = con.residual_forces(0.01, q2 - con.reference, qt)
    keep = np.setdiff1d(np.arange(f1.size), rows)
    assert np.allclose(f2[keep], f1[keep], rtol=1e-9, atol=1e-9 * np.max(np.abs(f1)))
    assert not np.allclose(f2[rows], f1[rows], rtol=1e-3)

    start = StartResidual(con)
    turned = start.jacobian(0.01, q - con.reference, qt, f_q, f_qt)
    at_turned = con.jacobian(0.01, q2, qt, f_q, f_qt)
    plain = con.jacobian(0.01, q, qt, f_q, f_qt)
    block = np.ix_(np.arange(f1.size), rows), np.ix_(rows, np.arange(f1.size))
    for part in block:
        scale = np.max(np.abs(at_turned[part]))
        error = np.max(np.abs(turned[part] - at_turned[part])) / scale
        unturned = np.max(np.abs(plain[part] - at_turned[part])) / scale
        assert error < 1e-6 and unturned > 0.1, (error, unturned)
    # the rest is the block Jacobian as it is
    rest = np.setdiff1d(np.arange(f1.size), rows)
    assert np.array_equal(turned[np.ix_(rest, rest)], plain[np.ix_(rest, rest)])


def test_no_turn_without_a_velocity_term():
    _, con, q, qt = _scene(axialForce=1300.0)
    start = StartResidual(con)
    assert np.array_equal(start.jacobian(0.01, q - con.reference, qt, 1.0, 0.0), con.jacobian(0.01, q, qt, 1.0, 0.0))
