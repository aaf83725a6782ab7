"""A scalar law applied element by element to broadcast arrays, through a compiled loop.

The laws the compiled kernels share are scalar numba functions; the array functions of
:mod:`contact` apply them here. Each was a cached ``numba.vectorize`` ufunc until session 42:
a cached ufunc still rebuilds its loop in LLVM when its module is imported (~45 ms each, 11 of
them ~0.5 s of every process's start), where a cached ``njit`` loop is only loaded.

A loop reads its inputs with :func:`at`, so a one-element input stands for every element (the
common call: arrays of the contacts beside scalar constants) without being copied out.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["apply", "at"]


@njit(inline="always")
def at(a, i):
    """``a[i]``, or ``a[0]`` for a one-element input (broadcast along the loop)."""
    return a[i] if a.shape[0] > 1 else a[0]


def apply(loop, *arrays, flags=(), outputs=1):
    """``loop(*out, *flat, *flags)`` over ``arrays`` (array_like, broadcast together, as float)
    with ``flags`` passed as they are; the result (``outputs`` of them, a tuple for more than
    one) has the broadcast shape, a numpy float for scalar inputs (as a ufunc's). ``loop`` is
    a compiled function filling ``out[i]`` from :func:`at` of its flat float64 inputs (each
    of the broadcast size or of one element)."""
    arrays = [np.asarray(a, dtype=float) for a in arrays]
    shape = None
    for a in arrays:
        if a.size != 1:
            if shape is None:
                shape = a.shape
            elif a.shape != shape:
                shape = False  # a true broadcast: below
                break
    if shape is None or shape is False or any(a.ndim > len(shape) for a in arrays if a.size == 1):
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
        size = math.prod(shape)
        # owned buffers of the broadcast size (a broadcast view is read-only to numba)
        flat = [a.reshape(-1).copy() if a.size == 1 else np.array(np.broadcast_to(a, shape)).reshape(-1)
                for a in arrays] if size != 1 else [a.reshape(-1) for a in arrays]
    else:
        size = math.prod(shape)
        flat = [a.reshape(-1) for a in arrays]
    # a read-only input (one the caller broadcast) is copied: numba would type it apart
    flat = [a if a.flags.writeable else a.copy() for a in flat]
    out = [np.empty(size) for _ in range(outputs)]
    loop(*out, *flat, *flags)
    res = [o.reshape(shape) if shape else o[0] for o in out]
    return res[0] if outputs == 1 else tuple(res)
