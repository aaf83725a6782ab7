"""Errors raised by bearing simulations."""


class BearingSimulationError(RuntimeError):
    """A run diverged or left the physically meaningful range; the message says where
    (which ball, contact or quantity) and what to change."""
