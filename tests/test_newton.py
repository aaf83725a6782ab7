"""The damped Newton of the steady and quasi-dynamic solvers (exudyn_bearing/solvers/newton.py) on
problems with known roots."""
import numpy as np

from exudyn_bearing.jacobian import forward_jacobian
from exudyn_bearing.solvers.newton import damped_newton


def test_line_search_reaches_the_root_where_plain_newton_diverges():
    """atan(10 (x - 1)) from x = 3: the undamped iteration runs away, the damped one converges."""
    fun = lambda x: np.arctan(10.0 * (x - 1.0))  # noqa: E731
    root, worst, iterations = damped_newton(fun, np.array([3.0]), np.array([-np.inf]), np.array([np.inf]), 1e-12)
    assert abs(root[0] - 1.0) < 1e-10 and worst <= 1e-12 and 0 < iterations < 25
    x = 3.0
    for _ in range(5):
        x -= np.arctan(10.0 * (x - 1.0)) * (1.0 + (10.0 * (x - 1.0)) ** 2) / 10.0
    assert abs(x - 1.0) > 10.0


def test_coupled_system_converges_quadratically():
    """x² + y² = 4, x = y: the root (√2, √2) in a few steps from (3, 0.5)."""
    fun = lambda v: np.array([v[0] ** 2 + v[1] ** 2 - 4.0, v[0] - v[1]])  # noqa: E731
    inf = np.full(2, np.inf)
    root, worst, iterations = damped_newton(fun, np.array([3.0, 0.5]), -inf, inf, 1e-12)
    np.testing.assert_allclose(root, [np.sqrt(2.0), np.sqrt(2.0)], atol=1e-10)
    assert iterations <= 8


def test_root_outside_the_bounds_is_not_reported_as_converged():
    root, worst, _ = damped_newton(lambda x: x + 1.0, np.array([2.0]), np.array([0.0]), np.array([5.0]), 1e-10)
    assert worst > 1e-10 and root[0] == 0.0


def test_forward_jacobian_of_a_linear_map_is_the_matrix():
    a = np.array([[2.0, -1.0, 0.5], [0.0, 3.0, 1.0], [1.0, 1.0, -4.0]])
    np.testing.assert_allclose(forward_jacobian(lambda x: a @ x, np.array([0.3, -0.2, 1.0])), a, atol=1e-8)


def test_chord_steps_reach_the_same_root_with_fewer_jacobians():
    """reuse_jacobian keeps a Jacobian while it contracts: the root of the coupled system
    (√2, √2) to the same tolerance with fewer Jacobian evaluations than Newton's."""
    fun = lambda v: np.array([v[0] ** 2 + v[1] ** 2 - 4.0, v[0] - v[1] + 0.1 * np.sin(v[0])])  # noqa: E731
    inf = np.full(2, np.inf)
    counts = {}

    def counted(key):
        def jac(v):
            counts[key] = counts.get(key, 0) + 1
            return forward_jacobian(fun, v)
        return jac

    newton, w1, _ = damped_newton(fun, np.array([1.6, 1.3]), -inf, inf, 1e-12, counted("newton"))
    chord, w2, used = damped_newton(fun, np.array([1.6, 1.3]), -inf, inf, 1e-12, counted("chord"), reuse_jacobian=True)
    assert w1 <= 1e-12 and w2 <= 1e-12
    np.testing.assert_allclose(chord, newton, atol=1e-11)
    assert counts["chord"] < counts["newton"] and used == counts["chord"]


def test_a_stale_jacobian_that_does_not_descend_is_renewed():
    """atan(10 (x - 1)) from x = 3 (the damped case above): steps with a kept slope stall far
    from the root, where a fresh one is taken; the root is reached."""
    fun = lambda x: np.arctan(10.0 * (x - 1.0))  # noqa: E731
    root, worst, _ = damped_newton(fun, np.array([3.0]), np.array([-np.inf]), np.array([np.inf]), 1e-12,
                                   reuse_jacobian=True)
    assert abs(root[0] - 1.0) < 1e-10 and worst <= 1e-12
