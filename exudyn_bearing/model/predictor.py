"""A predicted start for the Newton iteration of Exudyn's implicit solvers: the previous
step's accelerations, the balls' carried along their orbits (MODEL.md §10b).

Exudyn's generalized-alpha step starts Newton from zero acceleration. The balls orbit and
precess at steady accelerations (hundreds of m/s², ~1e4 rad/s²), so that start lies
a_n/β' inside the stiff Hertz and traction laws (an initial residual of ~57 N on the
deep-groove case of docs/heavy_load_matrix.md, where a converged step leaves 0.006 N) and
Newton crosses the traction's knee on its way back (docs/DEVELOPMENT.md, 'Newton's start and
tolerance').

:class:`NewtonPredictor` replaces Newton's *first iterate* for the bearings' nodes by the
state one Exudyn increment ``δ = a_n / β'`` from the start: q + δ for translations, q ∘ exp(δ)
for the Lie-group rotations (Exudyn's own composition), v + γ'δ, a = a_n. For the balls a_n is
the previous step's acceleration carried along the ball's orbit (:func:`_carry_orbits`): at
72 000 rpm a ball's orbit turns 0.04 rad a step and its body 0.3 rad, and the accelerations
as they were put the iterate ~400 N from the solution, carried ~12 N. Exactly that state:
Newton's later increments move q, v and a together and would keep any mismatch. The first
iterate, not the start, because Exudyn measures convergence relative to the residual at the
start: left at the zero-acceleration start, that residual and so the convergence test are
what they were without the predictor, and only the path to them is shorter.

Not predicted: a solve's first step (its start acceleration is Exudyn's initial M⁻¹f, with
the start state's transients), except the scene's first solve when every bearing starts
from its steady state, and a step tried again after a cut. Installed as the system's
``PreNewtonResidualUserFunction``, so a plain ``exu.SolveDynamic`` gets it too; a function
the scene set before the bearing was created is chained, one set after it replaces the
predictor (results unchanged, slower). Only what moves with the bearing is shifted: the
nodes of its balls, cage and races (Lie-group rotation-vector nodes, 6 coordinates each).
When Exudyn restarts a step's modified Newton from its zero-acceleration start (an iteration
after the second that more than doubled the residual, or a diverged solution), the predicted
iterate is set again, once a step: a second restart, Exudyn's switch to full Newton, starts
from Exudyn's own start.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from contact import kernels
from contact.kernel_cache import drop_stale
from contact.kernels.race import rotation_matrices

from ..races import node_rows

# _carry_orbits calls the contact/ kernels' rotation_matrices: recompile it when they changed
drop_stale(__file__, [__file__, *kernels.SOURCES])

__all__ = ["NewtonPredictor", "compose_rotation_vectors", "install_predictor"]

#: key of the predictor in ``mbs.variables`` (one per system, shared by its bearings)
VARIABLE = "exudyn_bearing.model.predictor"

#: a step attempt that took this many Newton iterations or more on a Jacobian that had served
#: at least REFRESH_MIN_AGE step attempts: the next step takes a fresh Jacobian at its
#: predicted iterate (MODEL.md §10b)
REFRESH_AFTER_ITERATIONS = 4
REFRESH_MIN_AGE = 10


@njit(cache=True)
def _compose(theta, omega, out):
    """Exudyn's ``EXUlie::CompositionRotationVector`` for rows of ``theta`` and ``omega``."""
    for k in range(theta.shape[0]):
        t0, t1, t2 = theta[k, 0], theta[k, 1], theta[k, 2]
        w0, w1, w2 = omega[k, 0], omega[k, 1], omega[k, 2]
        h0 = 0.5 * math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
        h1 = 0.5 * math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
        c0, c1 = math.cos(h0), math.cos(h1)
        s0 = math.sin(h0) / h0 if h0 > 0.0 else 1.0
        s1 = math.sin(h1) / h1 if h1 > 0.0 else 1.0
        x = c0 * c1 - 0.25 * s0 * s1 * (t0 * w0 + t1 * w1 + t2 * w2)
        a, b, c = s0 * c1, c0 * s1, 0.5 * s0 * s1
        r0 = a * t0 + b * w0 + c * (t1 * w2 - t2 * w1)
        r1 = a * t1 + b * w1 + c * (t2 * w0 - t0 * w2)
        r2 = a * t2 + b * w2 + c * (t0 * w1 - t1 * w0)
        norm = math.sqrt(r0 * r0 + r1 * r1 + r2 * r2)
        # (x, rho/2) is the product quaternion: 2 atan2(|rho|/2, x) is Exudyn's angle
        # pi - 2 atan2(x, sqrt(1 - x²)) without its loss of digits at small angles
        angle = 2.0 * math.atan2(0.5 * norm, x)
        scale = angle / norm if norm > 0.0 else 0.0
        out[k, 0], out[k, 1], out[k, 2] = scale * r0, scale * r1, scale * r2


@njit(cache=True)
def _predict_rows(q, v, a_n, starts, ref_rot, beta_prime, gamma_prime, a_out):
    """In place on the full coordinate vectors: the nodes at ``starts`` (6 coordinates each:
    displacement, rotation vector) moved by one Exudyn increment δ = a_n/β' (module
    docstring); their accelerations a_n into ``a_out``. False where a value is not finite."""
    delta = np.empty((1, 3))
    theta = np.empty((1, 3))
    out = np.empty((1, 3))
    for k in range(starts.shape[0]):
        s = starts[k]
        for i in range(6):
            if not (math.isfinite(q[s + i]) and math.isfinite(v[s + i]) and math.isfinite(a_n[s + i])):
                return False
        for i in range(6):
            d = a_n[s + i] / beta_prime
            v[s + i] += gamma_prime * d
            a_out[s + i] = a_n[s + i]
            if i < 3:
                q[s + i] += d
            else:
                delta[0, i - 3] = d
                theta[0, i - 3] = ref_rot[k, i - 3] + q[s + i]
        _compose(theta, delta, out)
        for i in range(3):
            q[s + 3 + i] = out[0, i] - ref_rot[k, i]
    return True


@njit(cache=True)
def _turn_about(x, k, c, s, out):
    """``x`` (3,) turned about the unit axis ``k`` by the angle whose cosine and sine are c, s
    (Rodrigues), into ``out``."""
    kx = (1.0 - c) * (k[0] * x[0] + k[1] * x[1] + k[2] * x[2])
    x0, x1, x2 = x[0], x[1], x[2]  # out may be x
    out[0] = c * x0 + s * (k[1] * x2 - k[2] * x1) + kx * k[0]
    out[1] = c * x1 + s * (k[2] * x0 - k[0] * x2) + kx * k[1]
    out[2] = c * x2 + s * (k[0] * x1 - k[1] * x0) + kx * k[2]


@njit(cache=True)
def _carry_orbits(q0, v0, q, ref, a_n, starts, origin, axis, h, out):
    """In place on ``out`` (a copy of ``a_n``): the accelerations of the ball nodes at
    ``starts`` carried along their orbits over the step h (MODEL.md §10b). The node's orbital
    rate about the bearing axis, Ω = ((r × v)·k)/|r|² with r the ball centre's distance from
    the axis (through ``origin``, along the unit ``axis``) and v its velocity at the step's
    start (``q0`` + ``ref``, ``v0``), turns the translational acceleration by Ω h about k; the
    angular acceleration, local in the body frame A0 at the step's start, is turned by Ω h as
    a global vector and read in the frame A1 of Exudyn's start ``q``:
    ω̇_l' = A1ᵀ R_k(Ω h) A0 ω̇_l. Rotation vectors: ``ref`` + ``q0``, ``ref`` + ``q``. Exact for
    a ball on a uniform orbit whose angular velocity turns with it."""
    nu = np.empty((2, 3))
    g = np.empty(3)
    turned = np.empty(3)
    for j in range(starts.shape[0]):
        s = starts[j]
        k = axis[j]
        r = np.empty(3)
        along = 0.0
        for i in range(3):
            r[i] = q0[s + i] + ref[s + i] - origin[j, i]
            along += r[i] * k[i]
        r2 = 0.0
        for i in range(3):
            r[i] -= along * k[i]
            r2 += r[i] * r[i]
        if not r2 > 0.0:
            continue
        w = ((r[1] * v0[s + 2] - r[2] * v0[s + 1]) * k[0] + (r[2] * v0[s] - r[0] * v0[s + 2]) * k[1]
             + (r[0] * v0[s + 1] - r[1] * v0[s]) * k[2]) / r2
        c, sn = math.cos(w * h), math.sin(w * h)
        _turn_about(a_n[s:s + 3], k, c, sn, out[s:s + 3])
        for i in range(3):
            nu[0, i] = ref[s + 3 + i] + q0[s + 3 + i]
            nu[1, i] = ref[s + 3 + i] + q[s + 3 + i]
        frames = rotation_matrices(nu)
        for i in range(3):
            g[i] = frames[0, i, 0] * a_n[s + 3] + frames[0, i, 1] * a_n[s + 4] + frames[0, i, 2] * a_n[s + 5]
        _turn_about(g, k, c, sn, turned)
        for i in range(3):
            out[s + 3 + i] = frames[1, 0, i] * turned[0] + frames[1, 1, i] * turned[1] + frames[1, 2, i] * turned[2]


def compose_rotation_vectors(theta, omega):
    """Rotation vectors of R(θ) exp(ω̃): the rotations ``theta`` (n, 3) composed with the
    local incremental rotations ``omega`` (n, 3), by the formula of Exudyn's Lie-group
    update (``EXUlie::CompositionRotationVector``, Holzinger 2021), so that the predicted
    state is exactly one Exudyn Newton increment away from the start (MODEL.md §10b)."""
    theta = np.ascontiguousarray(theta, dtype=float).reshape(-1, 3)
    omega = np.ascontiguousarray(omega, dtype=float).reshape(-1, 3)
    out = np.empty_like(theta)
    _compose(theta, omega, out)
    return out


class _Prediction(NamedTuple):
    """A step's predicted iterate (full coordinate vectors) and what comes with it."""

    q: np.ndarray
    v: np.ndarray
    a: np.ndarray
    new_step: bool  #: the step size changed since the last step
    beta_prime: float  #: β' = (1 − α_m)/(h² β (1 − α_f)), 1/s²
    gamma_prime: float  #: γ' = γ/(h β), 1/s
    refresh: bool = False  #: the last step was slow on an old Jacobian


class NewtonPredictor:
    """Exudyn ``PreNewtonResidualUserFunction`` that replaces the first Newton iterate of
    each implicit step (and a restarted one) by the predicted state of the bearings' nodes
    (module docstring). ``enabled`` False leaves Exudyn's iteration untouched. Enabled or not, it
    counts the steps Newton failed and Exudyn tried again at a shorter step (``cut_times``:
    the end time s of each failed attempt)."""

    def __init__(self, chained=None):
        self.nodes: list[int] = []
        self.enabled = True
        self.chained = chained
        self.shifts = 0
        self.cut_times: list[float] = []
        self._attempt = (None, -math.inf)  # (solver, end time) of the last step attempt
        self._indices = None
        self._pending = None
        self._solver = self._constants = None
        self._step_start = self._h = math.nan
        self._first_solve = False
        self.steady_start = True
        #: (StartResidual, its connector's nodes) told of each predicted step
        self.start_residuals: list = []
        #: (ball nodes, origin, unit axis) of each bearing whose balls orbit (:func:`_carry_orbits`)
        self.orbits: list = []
        self._iterations = 0  # Newton iterations of the current step attempt
        self._jacobians = -1  # the solver's Jacobian count at its start
        self._age = 0  # step attempts the current Jacobian has served without another
        self._applied = None  # the step attempt's prediction, once set
        self._last_call = None  # (t, newtonIt, discontinuousIt) of the last call
        #: restarts of Newton from Exudyn's start sent to the predicted iterate instead
        self.restarts = 0

    def add_nodes(self, nodes, steady_start: bool = False, start_residual=None, orbit=None) -> None:
        """Predict ``nodes`` too; each node once (bearings on one shaft share its node, and
        a node moved twice would leave q, v and a inconsistent). ``steady_start``: these
        nodes start from a steady state (their initial accelerations are the motion's).
        ``start_residual``: the :class:`~exudyn_bearing.model.start_residual.StartResidual`
        of the connector on exactly these nodes, told each predicted iterate. ``orbit``:
        (ball nodes, the bearing's origin, its unit axis) — those nodes' accelerations are
        carried along their orbits about that axis (:func:`_carry_orbits`)."""
        self.nodes.extend(n for n in dict.fromkeys(int(n) for n in nodes) if n not in self.nodes)
        self.steady_start = self.steady_start and steady_start
        if start_residual is not None:
            self.start_residuals.append((start_residual, [int(n) for n in nodes]))
        if orbit is not None:
            balls, origin, axis = orbit
            axis = np.asarray(axis, dtype=float)
            self.orbits.append(([int(n) for n in balls], np.asarray(origin, dtype=float),
                                axis / np.linalg.norm(axis)))
        self._indices = None

    def _coordinates(self, mbs):
        if self._indices is None:
            rows = node_rows(mbs, self.nodes)
            starts, rot = rows[::6], rows.reshape(-1, 6)[:, 3:].ravel()
            ref = np.asarray(mbs.systemData.GetODE2Coordinates(configuration=_config().Reference), dtype=float)
            # the bearings' nodes are the whole system (the usual scene): the predicted
            # vectors are set as they are, no other item's Newton iterate to keep
            everything = np.array_equal(np.sort(rows), np.arange(ref.size))
            own = [node_rows(mbs, nodes) for _, nodes in self.start_residuals]
            # per ball: its first coordinate's row, its bearing's origin and axis
            balls = [(row, origin, axis) for nodes, origin, axis in self.orbits for row in node_rows(mbs, nodes)[::6]]
            orbits = (np.array([b[0] for b in balls], dtype=np.int64),
                      np.array([b[1] for b in balls], dtype=float).reshape(-1, 3),
                      np.array([b[2] for b in balls], dtype=float).reshape(-1, 3), ref)
            self._indices = (starts, rows, np.ascontiguousarray(ref[rot].reshape(-1, 3)), everything, own, orbits)
        return self._indices

    def __call__(self, mbs, t, newtonIt, discontinuousIt):
        if self.chained is not None:
            self.chained(mbs, t, newtonIt, discontinuousIt)
        if newtonIt == 0:
            solver = mbs.sys.get("dynamicSolver")
            self._count_cut(solver, t)
        # Exudyn calls again with the same iteration after restarting the step from its start
        restart = newtonIt >= 1 and (t, newtonIt, discontinuousIt) == self._last_call
        self._last_call = (t, newtonIt, discontinuousIt)
        if not self.enabled or not self.nodes:
            return
        if newtonIt == 0:
            self._applied = None
            # the last attempt converged slowly on a Jacobian that had served many steps:
            # refresh it (MODEL.md §10b)
            jacobians = int(solver.it.newtonJacobiCount) if solver is not None else 0
            self._age = self._age + 1 if jacobians == self._jacobians else 0
            slow = self._iterations >= REFRESH_AFTER_ITERATIONS and self._age >= REFRESH_MIN_AGE
            self._iterations, self._jacobians = 0, jacobians
            self._pending = self._predict(mbs, solver, t)
            if self._pending is not None:
                self._pending = self._pending._replace(refresh=slow)
                self._tell_start_residuals(t)
        elif newtonIt == 1 and self._pending is not None:
            pending, self._pending = self._pending, None
            if pending.new_step or pending.refresh:
                # Exudyn keeps the last Jacobian across a change of step size, whose mass
                # part scales with 1/h²: from the predicted iterate that stale matrix
                # diverges (contraction 2 after the step doubled), so take a fresh one here;
                # and after a step that needed many iterations (MODEL.md §10b)
                self._solver.conv.jacobianUpdateRequested = True
            self._apply(mbs, pending)
            self._applied = pending
            self.shifts += 1
        elif restart and self._applied is not None:
            # Exudyn restarts a diverging modified Newton from its zero-acceleration start
            # (with a fresh Jacobian): from the predicted iterate instead, once a step
            # (MODEL.md §10b)
            self._apply(mbs, self._applied)
            self._applied = None
            self.restarts += 1
        else:
            self._pending = None
        self._iterations = max(self._iterations, int(newtonIt))

    def _apply(self, mbs, prediction):
        """Set the bearings' nodes to ``prediction``'s iterate (q, v, a) in Exudyn's current
        configuration."""
        q_new, v_new, a_new = prediction.q, prediction.v, prediction.a
        data = mbs.systemData
        config = _config().Current
        _, rows, _, everything, _, _ = self._indices
        if not everything:  # other items keep Newton's iterate
            q = np.array(data.GetODE2Coordinates(configuration=config), dtype=float)
            v = np.array(data.GetODE2Coordinates_t(configuration=config), dtype=float)
            a = np.array(data.GetODE2Coordinates_tt(configuration=config), dtype=float)
            q[rows], v[rows], a[rows] = q_new[rows], v_new[rows], a_new[rows]
            q_new, v_new, a_new = q, v, a
        data.SetODE2Coordinates(q_new, configuration=config)
        data.SetODE2Coordinates_t(v_new, configuration=config)
        data.SetODE2Coordinates_tt(a_new, configuration=config)

    def _tell_start_residuals(self, t):
        """Tell each connector's start residual its predicted iterate and increment."""
        p = self._pending
        for (start, _), rows in zip(self.start_residuals, self._indices[4]):
            start.expect(t, p.q[rows], p.v[rows], p.a[rows] / p.beta_prime, p.gamma_prime)

    def _count_cut(self, solver, t):
        """A step attempt that ends before the last one of the same solve follows a failed
        one: Exudyn retries a step from its start with a shorter step after Newton fails."""
        end = float(t)
        last_solver, last_end = self._attempt
        if solver is last_solver and end < last_end - 1e-12 * max(1.0, abs(end)):
            self.cut_times.append(last_end)
        self._attempt = (solver, end)

    def _predict(self, mbs, solver, t):
        """The :class:`_Prediction`: the full (q, v, a) vectors with the bearings' nodes at their
        constant-acceleration state (called with Exudyn's zero-acceleration start in place;
        ``solver`` the system's dynamic solver), whether the step size changed, β' and γ';
        None outside a dynamic step."""
        if solver is not self._solver:  # a new solve: its constants and coordinate indices, once
            self._first_solve = self._solver is None
            self._solver, self._constants, self._h = solver, _constants(solver), math.nan
            self._indices = None  # the scene may have been assembled again since the last solve
            for start, _ in self.start_residuals:  # no Jacobian of another solve
                start.reset()
        if self._constants is None:
            return None
        it = solver.it
        h = float(it.currentStepSize)
        if not (h > 0.0) or abs(float(it.currentTime) - t) > 1e-9 * max(1.0, abs(t)):
            return None  # not this solver's step (e.g. a static solve after a dynamic one)
        new_step, self._h = h != self._h, h
        step_start, tiny = t - h, 1e-9 * max(h, abs(t) * 1e-6)
        first = step_start <= float(it.startTime) + tiny
        if (first and not (self._first_solve and self.steady_start)) or abs(step_start - self._step_start) <= tiny:
            # the first step of a solve starts from Exudyn's initial accelerations (M⁻¹f of
            # the start state), the motion's own only where every bearing starts from its
            # steady state and this is the scene's first solve; elsewhere they carry the
            # start's transients. A step tried again after a cut (same start) gets Exudyn's
            # own start: one predicted attempt per step
            self._step_start = step_start
            return None
        self._step_start = step_start
        starts, _, ref_rot, _, _, orbits = self._coordinates(mbs)
        data = mbs.systemData
        config = _config()
        # Exudyn's start: the previous step's q and v advanced, zero acceleration everywhere
        q = np.array(data.GetODE2Coordinates(configuration=config.Current), dtype=float)
        v = np.array(data.GetODE2Coordinates_t(configuration=config.Current), dtype=float)
        a_n = np.asarray(data.GetODE2Coordinates_tt(configuration=config.StartOfStep), dtype=float)
        balls, origins, axes, ref = orbits
        if balls.size:  # the balls' accelerations turn with their orbits (MODEL.md §10b)
            q0 = np.asarray(data.GetODE2Coordinates(configuration=config.StartOfStep), dtype=float)
            v0 = np.asarray(data.GetODE2Coordinates_t(configuration=config.StartOfStep), dtype=float)
            carried = a_n.copy()
            _carry_orbits(q0, v0, q, ref, a_n, balls, origins, axes, h, carried)
            a_n = carried
        a = np.zeros_like(q)
        beta, gamma, alpha_m, alpha_f = self._constants
        beta_prime = (1.0 - alpha_m) / (h * h * beta * (1.0 - alpha_f))
        gamma_prime = gamma / (h * beta)
        if not _predict_rows(q, v, a_n, starts, ref_rot, beta_prime, gamma_prime, a):
            return None
        return _Prediction(q, v, a, new_step, beta_prime, gamma_prime)


def _constants(solver):
    """(β, γ, α_m, α_f) of an implicit second-order Exudyn solver, None for other solvers."""
    import exudyn as exu

    if not isinstance(solver, exu.MainSolverImplicitSecondOrder):
        return None
    return float(solver.newmarkBeta), float(solver.newmarkGamma), float(solver.alphaM), float(solver.alphaF)


def _config():
    import exudyn as exu

    return exu.ConfigurationType


def install_predictor(mbs, nodes, steady_start: bool = False, start_residual=None, orbit=None) -> NewtonPredictor:
    """Add ``nodes`` (Lie-group rotation-vector rigid-body nodes of a bearing) to the
    system's :class:`NewtonPredictor`, creating and installing it as the system's
    ``PreNewtonResidualUserFunction`` on first use (a function already set is chained).
    ``steady_start``: the bearing starts from its steady state (then, if all do, the
    scene's first step is predicted too). ``start_residual``: the bearing's
    :class:`~exudyn_bearing.model.start_residual.StartResidual` (on exactly ``nodes``).
    ``orbit``: (ball nodes, the bearing's origin, its axis), whose accelerations the predictor
    carries along their orbits."""
    predictor = mbs.variables.get(VARIABLE)
    if not isinstance(predictor, NewtonPredictor):
        try:  # Exudyn 1.13: 0, or {'function': f, 'type': 'Python'}
            existing = mbs.GetPreNewtonResidualUserFunction()
        except Exception:  # noqa: BLE001 - older Exudyn without the getter: nothing to chain
            existing = None
        if isinstance(existing, dict):
            existing = existing.get("function")
        predictor = NewtonPredictor(existing if callable(existing) else None)
        mbs.variables[VARIABLE] = predictor
        mbs.SetPreNewtonResidualUserFunction(predictor)
    predictor.add_nodes(nodes, steady_start, start_residual, orbit)
    return predictor
