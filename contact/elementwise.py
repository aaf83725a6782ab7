"""A scalar law applied element by element to broadcast arrays, through a compiled loop.

The laws the compiled kernels share are scalar numba functions; the array functions of
:mod:`contact` apply them here. Each was a cached ``numba.vectorize`` ufunc until session 42:
a cached ufunc still rebuilds its loop in LLVM when its module is imported (~45 ms each, 11 of
them ~0.5 s of every process's start), where a cached ``njit`` loop is only loaded.
"""
from __future__ import annotations

import numpy as np

__all__ = ["apply"]


def apply(loop, *arrays, flags=()):
    """``loop(out, *flat, *flags)`` over ``arrays`` (array_like, broadcast together, as float)
    with ``flags`` passed as they are; the result has the broadcast shape, a numpy float for
    scalar inputs (as a ufunc's). ``loop`` is a compiled function filling ``out[i]`` from the
    i-th elements of its flat, contiguous float64 inputs."""
    arrays = [np.asarray(a, dtype=float) for a in arrays]
    shape = np.broadcast_shapes(*(a.shape for a in arrays))
    # owned contiguous buffers: a broadcast view numba would type as read-only (and
    # broadcast_arrays' views warn when numba reads their flags)
    flat = [a.reshape(-1) if a.shape == shape and a.flags.c_contiguous and a.flags.writeable
            else np.array(np.broadcast_to(a, shape)).reshape(-1) for a in arrays]
    out = np.empty(flat[0].size)
    loop(out, *flat, *flags)
    return out.reshape(shape) if shape else out[0]
