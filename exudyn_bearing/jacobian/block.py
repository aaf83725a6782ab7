"""The block finite-difference Jacobian of a bearing connector (MODEL.md §10), for Exudyn's
``jacobianUserFunction``: each ball's forces depend on its own state and the races and
cage only, so one perturbation of the same coordinate of all balls gives every ball's block."""
from __future__ import annotations

import math

import numpy as np

from contact.kernels.race import rotation_matrices

from . import kernels

__all__ = ["COMBINED_STEP_LIMIT", "JACOBIAN_VELOCITY_STEP", "block_jacobian", "jacobian_columns"]

#: Velocity step of the block Jacobian's difference quotients per m/s of the balls' mean speed
#: (1e-5 m/s on the reference bearing at 1800 rpm; see :func:`block_jacobian`).
JACOBIAN_VELOCITY_STEP = 1.6e-6
#: largest coordinate step of a combined column, in the coordinate's own steps: its velocity
#: takes its own step, the coordinate f_q/f_qt times that (0.53 nm on the reference bearing at
#: 1e-4 s); above this (time steps above ~1e-3 s there) the columns stay apart (MODEL.md §10)
COMBINED_STEP_LIMIT = 10.0


def block_jacobian(con, t, q, q_t, f_q, f_qt, eps_position=1e-9, eps_rotation=1e-7, eps_velocity=None,
                   eps_angular=None):
    """Block finite-difference Jacobian for Exudyn's ``jacobianUserFunction``:
    -(f_q dF/dq + f_qt dF/dq_t), dense (6 n_nodes)².

    Each ball's forces depend only on its own state (and the races and cage), so one
    perturbation of the same coordinate of all balls at once gives every ball's
    block; race and cage columns are perturbed one at a time. Columns of a held race's
    held coordinates are left out: its rows are zero there, so Newton never changes
    those coordinates and the columns would multiply zero increments. Rotation columns are
    derivatives with respect to a local rotation increment (A -> A exp(d theta~)),
    which is what Exudyn's Lie-group nodes expect. The compiled path takes the balls'
    rotation columns from their angular velocity columns and a race's translation columns
    from the balls' translation columns by the chain rule
    (:func:`~exudyn_bearing.jacobian.kernels.ball_rotation_columns`,
    :func:`~exudyn_bearing.jacobian.kernels.race_translation_columns`; MODEL.md §10); the numpy
    path (the reference) perturbs them.
    Where f_q and f_qt are both non-zero (a dynamic step) the compiled path takes a
    coordinate whose position and velocity columns both remain as one combined column: its
    state moves the velocity by its own step c f_qt and the coordinate by c f_q (at most
    :data:`COMBINED_STEP_LIMIT` times its own step, else the columns stay apart), and the
    quotient is the column itself (MODEL.md §10), one state instead of two.
    Forward differences; all perturbed states go through ONE batched evaluation (per-call
    overhead dominates at 32 contacts). Ball j sits in slot j (the builder's layout), so per-ball reactions index
    like the slots.

    The velocity steps (``eps_velocity`` m/s, ``eps_angular`` rad/s; default
    :data:`JACOBIAN_VELOCITY_STEP` times the balls' mean speed, in m/s and rad/s alike)
    follow the bearing's speed because the traction's knee does (its width scales with
    the entrainment speed, MODEL.md §6b): far below the knee the compiled fast rule's
    ray switching (steps of ~1e-3 of the traction) swamps the difference quotient, far
    above it the secant misses the slope. Measured (0.02 s per case): a fixed 1e-6
    (m/s and rad/s) gave 700 Jacobian updates on the deep groove at 1 kN radial and 852
    on the spindle with radial load, 1e-4 453 and 238 but 1099 steps for 800 on the deep
    groove at 2.5 kN radial and 6x the steps at 100 rpm; 1.6e-6 x the balls' speed
    (1e-5 at 1800 rpm on the reference bearing): 527, 245, 873 for 800, and at 100 rpm no
    worse than 1e-6.
    """
    pos, rot, vel, wl = con.decode(q, q_t)
    if eps_velocity is None or eps_angular is None:
        speed = float(np.mean(np.linalg.norm(vel[con.layout["balls"]], axis=1)))
        step = max(JACOBIAN_VELOCITY_STEP * speed, 1e-7)
        eps_velocity = step if eps_velocity is None else eps_velocity
        eps_angular = step if eps_angular is None else eps_angular
    n6 = 6 * con.n_nodes
    if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(vel)) and np.all(np.isfinite(wl))):
        return np.full((n6, n6), np.nan)
    compiled = con._compiled is not None
    # Exudyn asks for one combination of the two derivatives: a state moving a coordinate and
    # its velocity in that ratio gives its column in one difference quotient (MODEL.md §10).
    # Its step c keeps the velocity steps; where the coordinates would then move by more than
    # COMBINED_STEP_LIMIT times their own steps (long time steps), the columns stay apart
    combine = compiled and f_q != 0.0 and f_qt != 0.0 and math.isfinite(f_q) and math.isfinite(f_qt)
    c_t = eps_velocity / abs(f_qt) if combine else 0.0
    c_r = eps_angular / abs(f_qt) if combine else 0.0
    combine = combine and c_t * abs(f_q) <= COMBINED_STEP_LIMIT * eps_position \
        and c_r * abs(f_q) <= COMBINED_STEP_LIMIT * eps_rotation
    spec = jacobian_columns(con, combined=combine)
    columns, balls, others, ball_slots, coupled = (spec[k] for k in ("columns", "balls", "others", "ball_slots",
                                                                      "coupled"))
    turn = spec["turn"].get(eps_rotation)
    if turn is None:  # exp(eps e_k~), k = 0, 1, 2
        turn = spec["turn"].setdefault(eps_rotation, rotation_matrices(eps_rotation * np.eye(3)))
    if compiled:  # the same in compiled loops (~1.3 ms of numpy per Jacobian)
        arrays = spec["arrays"]  # group, k, kind, group mask, block?, slot, balls, others
        nb = 1 + len(arrays[0])
        p2, r2 = np.empty((nb,) + pos.shape), np.empty((nb,) + rot.shape)
        v2, w2 = np.empty((nb,) + vel.shape), np.empty((nb,) + vel.shape)
        # a combined column's step c: the velocity moves by c f_qt (its own step), the
        # coordinate by c f_q
        turns = np.stack((turn, rotation_matrices(c_r * f_q * np.eye(3)) if combine else turn))
        eps = np.array([eps_position, eps_rotation, eps_velocity, eps_angular, c_t, c_r, f_q, f_qt])
        steps = kernels.jacobian_states(pos, np.ascontiguousarray(rot), vel, np.ascontiguousarray(wl), arrays[:4],
                                        eps, turns, (p2, r2, v2, w2))
        raw = {"slots": spec["chain"]} if spec["chain"].size else None
        out, react, _, _, _ = con._batch_forces(t, p2, r2, v2, w2, same_contacts=spec["same"], raw_reactions=raw)
        jac = np.empty((n6, n6))
        kernels.jacobian_assemble(out, react, steps, arrays[:3] + arrays[4:], f_q, f_qt, jac)
        if not spec["material"]:
            kernels.ball_rotation_columns(out, react, steps, spec["wcol"], arrays[4], spec["ball_group"], arrays[6],
                                          arrays[7], np.ascontiguousarray(wl), f_q, jac)
        if raw is not None:
            kernels.race_translation_columns(raw["react"], steps, spec["tcol"], arrays[2], spec["chain"],
                                             spec["chain_rows"], arrays[6], pos, np.ascontiguousarray(rot), f_q,
                                             f_qt, jac)
        return jac
    nb = 1 + len(columns)
    p2, r2 = np.repeat(pos[None], nb, axis=0), np.repeat(rot[None], nb, axis=0)
    v2, w2 = np.repeat(vel[None], nb, axis=0), np.repeat(wl[None], nb, axis=0)
    steps = np.empty(len(columns))
    for i, (group, k, which) in enumerate(columns, start=1):
        if which == "q" and k < 3:
            steps[i - 1] = eps_position
            p2[i, group, k] += eps_position
        elif which == "q":
            steps[i - 1] = eps_rotation
            r2[i, group] = r2[i, group] @ turn[k - 3]
        else:
            steps[i - 1] = eps_velocity if k < 3 else eps_angular
            (v2 if k < 3 else w2)[i, group, k % 3] += steps[i - 1]
    out, react, _, _, _ = con._batch_forces(t, p2, r2, v2, np.einsum("bnij,bnj->bni", r2, w2),
                                             same_contacts=spec["same"])
    d_out = (out[1:] - out[0]) / steps[:, None, None]
    d_react = (react[1:] - react[0]) / steps[:, None, None, None]
    dq = np.zeros((n6, n6))
    dv = np.zeros((n6, n6))
    ball_rows = (6 * balls[:, None] + np.arange(6)).T  # (6, Z): row i of ball j's block
    for i, (group, k, which) in enumerate(columns):
        target = dq if which == "q" else dv
        if int(group[0]) in ball_slots and not coupled:
            # ball rows: own block only; race/cage rows: that ball's contribution
            cols = 6 * balls + k
            target[ball_rows, cols] = d_out[i, balls].T
            for s in others:
                target[6 * s:6 * s + 6, cols] = d_react[i, balls, s].T
        else:
            target[:, 6 * group[0] + k] = (d_out[i] + d_react[i].sum(axis=0)).ravel()
    return -(f_q * dq + f_qt * dv)

def jacobian_columns(con, combined: bool = False) -> dict:
    """The block Jacobian's columns (group of slots, coordinate k, 'q' or 'v'), fixed by
    the layout and the held races, as lists and as arrays for the compiled loops
    (cached). ``combined``: the compiled loops take a coordinate whose position and velocity
    columns both remain as one combined column ('qv', :data:`~exudyn_bearing.jacobian.kernels.COMBINED`)."""
    if con._jac_spec is None:
        con._jac_spec = {}
    if combined in con._jac_spec:
        return con._jac_spec[combined]
    balls = np.asarray(con.layout["balls"])
    ball_slots = set(balls.tolist())
    coupled = con.cage.kind == "spring-chain"
    others = [s for s in range(con.n_nodes) if s not in ball_slots]
    groups = [balls] if not coupled else [np.array([b]) for b in balls]
    groups += [np.array([s]) for s in others]
    frozen = {s: range(6) if what == "all" else range(3, 6) for s, what in con.held.items()
              if s not in con.driven}
    columns = [(gi, group, k, which) for gi, group in enumerate(groups) for k in range(6)
               for which in ("q", "v") if k not in frozen.get(int(group[0]), ())]
    # the compiled path takes the balls' rotation columns from their angular velocity
    # columns (kernels.ball_rotation_columns): three perturbed states fewer. Not with a pit or
    # waviness on a ball: then the forces depend on where its material is, and they are perturbed
    is_ball = [int(group[0]) in ball_slots for group in groups]
    material = con.terms.surface.material
    kept = [c for c in columns if material or not (is_ball[c[0]] and c[3] == "q" and c[2] >= 3)]
    # ... and a race's translation columns from the balls' translation columns: a ball-race
    # contact depends on the two positions and velocities only through their differences
    # (kernels.race_translation_columns). Not for the race guiding the cage (its land
    # force depends on the race), a race held in translation, or a spring-chain cage (no
    # ball group perturbed as one)
    chain = []
    for name in ("inner", "outer") if not coupled else ():
        slot = con.layout[name]
        if slot is None or con.held.get(slot, "rotation") != "rotation" or (
                con.guide is not None and con.guide[0] == name):
            continue
        chain.append(slot)
    kept = [c for c in kept if not (int(c[1][0]) in chain and c[2] < 3)]
    if combined:  # one 'qv' column where both remain, in the place of the 'q' one
        both = {(c[0], c[2]) for c in kept if c[3] == "q"} & {(c[0], c[2]) for c in kept if c[3] == "v"}
        kept = [(gi, group, k, "qv" if (gi, k) in both else which) for gi, group, k, which in kept
                if not (which == "v" and (gi, k) in both)]
    wcol = -np.ones((len(groups), 3), dtype=np.int64)
    tcol = -np.ones((2, 3), dtype=np.int64)  # the ball group's position and velocity columns
    for i, (gi, _group, k, which) in enumerate(kept):
        if is_ball[gi] and which == "v" and k >= 3:
            wcol[gi, k - 3] = i
        if is_ball[gi] and k < 3 and not coupled:
            for kind in (0, 1) if which == "qv" else (int(which == "v"),):
                tcol[kind, k] = i
    ball_group = np.empty(len(balls), dtype=np.int64)
    index = {int(b): j for j, b in enumerate(balls)}
    for gi, group in enumerate(groups):
        for b in group if is_ball[gi] else ():
            ball_group[index[int(b)]] = gi
    mask = np.zeros((len(groups), con.n_nodes), dtype=np.bool_)
    for gi, group in enumerate(groups):
        mask[gi, group] = True
    block = np.array([int(group[0]) in ball_slots and not coupled for group in groups])
    # a perturbed cage moves no ball and no race: its states reuse the base contacts, and
    # a perturbed race changes its own contacts only (the Crook quadrature is most of an
    # evaluation; of ~31 states here 12 are the cage's and ~12 a race's)
    def unchanged(slot):  # per race: a slot that is not that race's node leaves its contacts alone
        return [slot != con.layout["inner"], slot != con.layout["outer"]]

    same = np.array([[False, False]] + [unchanged(int(group[0])) if int(group[0]) not in ball_slots
                                        else [False, False] for _, group, _, _ in kept])
    kinds = {"q": kernels.POSITION, "v": kernels.VELOCITY, "qv": kernels.COMBINED}
    arrays = (np.array([c[0] for c in kept], dtype=np.int64), np.array([c[2] for c in kept], dtype=np.int64),
              np.array([kinds[c[3]] for c in kept], dtype=np.int64), mask, block,
              np.array([int(g[0]) for g in groups], dtype=np.int64), balls.astype(np.int64),
              np.array(others, dtype=np.int64))
    con._jac_spec[combined] = dict(
        columns=[c[1:] for c in columns], balls=balls, others=others, ball_slots=ball_slots, coupled=coupled,
        same=same, arrays=arrays, wcol=wcol, ball_group=ball_group, turn={}, chain=np.array(chain, dtype=np.int64),
        tcol=tcol, material=material,
        chain_rows=np.array([6 if con.held.get(s_) is None else 3 for s_ in chain], dtype=np.int64))
    return con._jac_spec[combined]
