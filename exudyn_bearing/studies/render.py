"""Render a run: simulate a bearing with its renderer graphics and write PNG frames (the CLI's
``render`` command; headless with Xvfb/OpenGL or Exudyn's raytracer)."""
from __future__ import annotations

import numpy as np

from ..model.builder import CreateAngularContactBearing
from ..races import Driven, Fixed, node_rows
from ..renamed import accepts_old_names
from ..results.graphics import AddBearingGraphics, render_frames, write_animation
from ..simulation.runner import SolverSettings, run_solver

__all__ = ["render_run"]


@accepts_old_names
def render_run(out_dir, *, axial_force=1300.0, radial_force=0.0, rpm=1800.0, time=0.002, frames=4, size=(800, 600),
               backend="auto", contact_law=None, bearing=None, lubricant=None, animation=None, cage=None,
               ball_drag="default"):
    """Simulate ``bearing`` (default: the reference bearing; ``lubricant`` likewise; inner race
    driven at ``rpm``, outer race fixed) for
    ``time`` s with :func:`AddBearingGraphics` and write ``frames`` PNG frames spread over
    the run (the CLI's ``render`` command), each labelled with its time and the slip colour
    scale; ``contact_law`` a :class:`contact.ballrace.ContactLaw` (default: the builder's);
    ``animation``: also write the frames as an animated GIF to this path; ``cage`` a
    :class:`~exudyn_bearing.cage.CageModel` and ``ball_drag`` a ball drag (None: none) where
    not the builder's defaults. Returns the written paths (frames, then the animation)."""
    import exudyn as exu

    if not (isinstance(frames, int) and frames >= 1):
        raise ValueError(f"frames must be a positive integer, got {frames!r}")
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    kw = {} if contact_law is None else dict(contactLaw=contact_law)
    kw.update({k: v for k, v in (("bearing", bearing), ("lubricant", lubricant), ("cage", cage)) if v is not None})
    if ball_drag != "default":
        kw["ballDrag"] = ball_drag
    h = CreateAngularContactBearing(mbs, innerRace=Driven(rpm), outerRace=Fixed(), axialForce=axial_force,
                                    radialForce=radial_force, **kw)
    AddBearingGraphics(mbs, h)
    mbs.Assemble()
    run_solver(mbs, [h], time, SolverSettings())
    t, q, q_t = h.States(mbs)
    idx = node_rows(mbs, h.nodeNumbers)
    n_sys = len(mbs.systemData.GetODE2Coordinates())
    picks = np.unique(np.linspace(0, len(t) - 1, frames).round().astype(int))
    states = []
    for k in picks:
        qs, vs = np.zeros(n_sys), np.zeros(n_sys)
        qs[idx], vs[idx] = q[k] - h.connector.reference, q_t[k]
        states.append((float(t[k]), qs, vs))
    written = render_frames(SC, mbs, out_dir, steps=states, size=size, backend=backend)
    if animation is not None:
        written.append(write_animation(written, animation))
    return written
