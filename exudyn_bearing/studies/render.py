"""Render a run: simulate a bearing with its renderer graphics and write PNG frames (the CLI's
``render`` command; headless with Xvfb/OpenGL or Exudyn's raytracer)."""
from __future__ import annotations

import numpy as np

from ..bearingfile import as_setup
from ..model.builder import CreateAngularContactBearing
from ..presets import REFERENCE_BEARING
from ..races import Driven, node_rows
from ..renamed import accepts_old_names
from ..results.graphics import AddBearingGraphics, render_frames, write_animation
from ..setup import FROM_SETUP
from ..simulation.runner import SolverSettings, run_solver, with_surface_step

__all__ = ["render_run"]


@accepts_old_names
def render_run(out_dir, *, axial_force=1300.0, radial_force=0.0, rpm=1800.0, time=0.002, frames=4, size=(800, 600),
               backend="auto", contact_law=FROM_SETUP, bearing=REFERENCE_BEARING, lubricant=FROM_SETUP, animation=None,
               cage=FROM_SETUP, ball_drag=FROM_SETUP):
    """Simulate ``bearing`` (a Bearing, setup or bearing file's path; default: the reference
    bearing; inner race driven at ``rpm``, outer race fixed or on the setup's housing) for
    ``time`` s with :func:`AddBearingGraphics` and write ``frames`` PNG frames spread over
    the run (the CLI's ``render`` command), each labelled with its time and the slip colour
    scale. The setup's parts — lubricant, ``contact_law``, ``cage``, ``ball_drag`` (None:
    none), surfaces (the step then resolves the defect passages, as in ``simulate``) and
    housing — unless passed here. ``animation``: also write the frames as an animated GIF
    to this path. Returns the written paths (frames, then the animation)."""
    import exudyn as exu

    if not (isinstance(frames, int) and frames >= 1):
        raise ValueError(f"frames must be a positive integer, got {frames!r}")
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    setup = as_setup(bearing, lubricant=lubricant, contact_law=contact_law, cage=cage, drag=ball_drag)
    # (outer race: the builder's default, the setup's housing or a fixed race)
    h = CreateAngularContactBearing(mbs, setup, innerRace=Driven(rpm), axialForce=axial_force,
                                    radialForce=radial_force)
    AddBearingGraphics(mbs, h)
    mbs.Assemble()
    run_solver(mbs, [h], time, with_surface_step(SolverSettings(), h, rpm))
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
