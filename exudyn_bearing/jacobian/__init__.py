"""Every Jacobian of the package, in one place (MODEL.md §10).

* :mod:`.block` — the bearing connector's block finite-difference Jacobian for Exudyn's
  ``jacobianUserFunction`` (numpy reference and compiled path);
* :mod:`.kernels` — its compiled parts (perturbed states, difference quotients, chain-rule
  columns);
* :mod:`.differences` — forward and central difference quotients of the solvers' small
  residual functions.
"""
from __future__ import annotations

from .block import JACOBIAN_VELOCITY_STEP, block_jacobian, jacobian_columns
from .differences import central_jacobian, forward_jacobian

__all__ = ["JACOBIAN_VELOCITY_STEP", "block_jacobian", "jacobian_columns", "central_jacobian", "forward_jacobian"]
