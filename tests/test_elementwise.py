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


def test_two_outputs_and_a_flag():
    """A loop with two outputs (the semi-axes, a/b = k) and one with a flag passed as it is
    (:func:`contact.rolling_resistance` pushes through a plain float)."""
    parts = (np.array([10.0, 20.0]), 2.0, 1.0, 0.01, 2.3e11)
    a, b = apply(hertz._semi_axes, *parts, outputs=2)
    assert a.shape == b.shape == (2,) and np.allclose(a / b, 2.0, rtol=1e-14)
    assert np.array_equal(a, [hertz.semi_axis_of(q, 2.0, 1.0, 0.01, 2.3e11, True) for q in parts[0]])


def test_read_only_and_true_broadcasts():
    """A read-only input (a caller's broadcast view) and a (2, 1) against a (3,) input give the
    ufunc's (2, 3) result."""
    load = np.broadcast_to(np.array([100.0, 50.0, 0.0]), (3,))
    assert not load.flags.writeable
    got = apply(hertz._max_pressure, np.array([[100.0], [50.0]]), load * 0 + 1e-3, 2e-4)
    assert got.shape == (2, 3)
    assert np.array_equal(got[:, 0], [1.5 * q / (math.pi * 1e-3 * 2e-4) for q in (100.0, 50.0)])
    assert np.array_equal(apply(hertz._max_pressure, load, 1e-3, 2e-4)[:2],
                          [1.5 * q / (math.pi * 1e-3 * 2e-4) for q in (100.0, 50.0)])
