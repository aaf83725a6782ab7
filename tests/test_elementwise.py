"""contact.elementwise.apply: a compiled scalar law over broadcast arrays, as the ufuncs it
replaced: the broadcast shape (a numpy float for scalars), element for element the scalar
law, and no warning from NumPy for broadcast or non-contiguous inputs."""
import math
import warnings

import numpy as np
import pytest

from contact import hertz
from contact.elementwise import apply


@pytest.mark.parametrize("load, a, b", [
    (100.0, 1e-3, 2e-4),  # scalars
    (np.array([100.0]), 1e-3, np.array(2e-4)),  # one element against scalars and 0-d
    (np.array([100.0, 0.0, 50.0]), np.array([1e-3]), 2e-4),
    (np.arange(6.0).reshape(2, 3), np.array([1e-3, 2e-3, 3e-3]), np.full((2, 1), 2e-4)),
    (np.arange(12.0)[::2], 1e-3, 2e-4),  # not contiguous
])
def test_apply_is_the_scalar_law_over_the_broadcast_shape(load, a, b):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = apply(hertz._max_pressure, load, a, b)
    shape = np.broadcast_shapes(np.shape(load), np.shape(a), np.shape(b))
    assert np.shape(got) == shape and isinstance(got, (np.ndarray, np.floating))
    flat = [np.broadcast_to(v, shape).ravel() for v in (load, a, b)]
    expected = [1.5 * q / (math.pi * x * y) if q > 0 else 0.0 for q, x, y in zip(*flat)]
    assert np.array_equal(np.ravel(got), expected)


def test_a_flag_passes_unbroadcast():
    parts = (np.array([10.0, 20.0]), 2.0, 1.0, 0.01, 2.3e11)
    a, b = apply(hertz._semi_axis, *parts, flags=(True,)), apply(hertz._semi_axis, *parts, flags=(False,))
    assert np.allclose(a / b, 2.0, rtol=1e-14)  # a/b = k
