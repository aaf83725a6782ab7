"""Renderer graphics for visual run debugging (issue 5), and headless rendering to PNG.

:func:`AddBearingGraphics` adds one ground object whose graphics user function draws, at
every redraw, from the current (visualization) state of the bearing:

* inner and outer race as solids of revolution with their grooves (torus sections of
  radius f D around the groove centres, MODEL.md §2),
* the cage as Z bars between the pockets,
* contact-force arrows at every loaded ball–race contact, length proportional to the
  normal load, colour from green (rolling) to red (slip >= ``slipScale`` m/s),
* load-zone shading: a thin arc behind each ball, blue (unloaded) to red (heaviest inner
  contact).

The balls themselves carry a sphere and a body-fixed triad (created by the builder with
``show=True``), so their spin is visible.

:func:`render_frames` renders a run headless: the OpenGL renderer when an X display is
available (e.g. under ``xvfb-run``), else Exudyn's raytracer.
"""
from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from ..races import node_rows

__all__ = ["AddBearingGraphics", "annotate_frame", "render_frames", "slip_color", "write_animation"]


def slip_color(slip, scale):
    """RGBA from green (0 m/s) to red (>= ``scale`` m/s)."""
    x = float(np.clip(slip / scale, 0.0, 1.0))
    return [x, 0.8 * (1.0 - x), 0.0, 1.0]


def _load_color(ratio):
    x = float(np.clip(ratio, 0.0, 1.0))
    return [x, 0.2, 1.0 - x, 0.5]


def _race_contour(bearing, which, mass=None, n_arc=24):
    """(axial, radial) contour of a race cross-section with its groove, m, in the race
    frame (groove centre at the bearing-frame position of MODEL.md §2): the modelled ring
    of :func:`exudyn_bearing.races.race_ring_section` (``mass``: the race body's, kg)."""
    from ..races import race_ring_section

    (ri, zi), (ro, zo) = bearing.groove_centres()
    d = bearing.ball_diameter
    r_in, r_out, width = race_ring_section(bearing, which, mass)
    if which == "inner":
        rc, zc, rg = ri, zi, bearing.inner_conformity * d
        shoulder, bore = r_out, r_in
    else:
        rc, zc, rg = ro, zo, bearing.outer_conformity * d
        shoulder, bore = r_in, r_out
    # groove arc between the two points where it meets the shoulder radius
    half = math.acos(min(1.0, abs(shoulder - rc) / rg))
    centre_angle = math.pi if which == "inner" else 0.0  # the groove is cut into the ring, away from the ball
    angles = np.linspace(centre_angle - half, centre_angle + half, n_arc)
    arc = [(zc + rg * math.sin(a), rc + rg * math.cos(a)) for a in angles]
    arc.sort()
    contour = [(-width / 2, bore), (-width / 2, shoulder)]
    contour += [p for p in arc if -width / 2 < p[0] < width / 2]
    contour += [(width / 2, shoulder), (width / 2, bore), (-width / 2, bore)]
    return contour


def AddBearingGraphics(mbs, handle, *, races: bool = True, cage: bool = True, contactForces: bool = True,
                       loadZone: bool = True, forceScale: float | None = None, slipScale: float = 0.5):
    """Add renderer graphics of a bearing created by
    :func:`exudyn_bearing.model.builder.CreateAngularContactBearing`; returns the ground object.

    Parameters
    ----------
    races, cage, contactForces, loadZone : bool
        Which parts to draw (module docstring).
    forceScale : float, optional
        Arrow length per newton, m/N; default: the heaviest initial contact load is one
        ball diameter long.
    slipScale : float
        Slip speed drawn fully red, m/s.
    """
    import exudyn as exu
    import exudyn.graphics as graphics
    from exudyn.utilities import ObjectGround

    con = handle.connector
    b = con.bearing
    d = b.ball_diameter
    loads0 = handle.initialLoads
    q_max0 = max(float(np.max(loads0.inner_load)), float(np.max(loads0.outer_load)), 1.0) if loads0 is not None else 100.0
    scale = forceScale if forceScale is not None else d / q_max0
    contours = {w: _race_contour(b, w, con.races[w].mass) for w in ("inner", "outer")}
    nodes = handle.nodeNumbers
    indices = []
    grey = [0.6, 0.6, 0.65, 0.35]
    brass = [0.8, 0.6, 0.2, 0.6]

    def draw(mbs_, itemNumber):
        if not indices:
            indices.extend(node_rows(mbs_, nodes))
        cfg = exu.ConfigurationType.Visualization
        q = np.asarray(mbs_.systemData.GetODE2Coordinates(configuration=cfg))[indices] + con.reference
        q_t = np.asarray(mbs_.systemData.GetODE2Coordinates_t(configuration=cfg))[indices]
        t = mbs_.systemData.GetTime(cfg)
        s = con.evaluate(t, q, q_t, details=True)
        pos, rot, _, _ = con.decode(q, q_t)
        out = []
        if races:
            for which in ("inner", "outer"):
                origin, r = con.race_frame(which, t, q, q_t)
                out.append(graphics.SolidOfRevolution(pAxis=origin.tolist(), vAxis=r[:, 2].tolist(),
                                                      contour=[list(p) for p in contours[which]], color=grey,
                                                      nTiles=64))
        if cage and con.cage.kind == "rigid":
            slot = con.layout["cage"]
            c0, rc = pos[slot], rot[slot]
            gap = 1.1 * d / b.pitch_radius  # pocket opening angle
            for j in range(con.z):
                a0 = con.pocket_angles[j] + gap / 2
                a1 = con.pocket_angles[(j + 1) % con.z] + (2 * np.pi if j == con.z - 1 else 0.0) - gap / 2
                bar = graphics.Cylinder(pAxis=[0, 0, -0.5 * d], vAxis=[0, 0, d], radius=b.pitch_radius + 0.15 * d,
                                        radiusInner=b.pitch_radius - 0.15 * d, angleRange=[a0, a1], color=brass,
                                        nTiles=8)
                out.append(graphics.Move(bar, c0.tolist(), rc))
        if contactForces or loadZone:
            q_ref = max(float(np.max(s.inner_forces.normal_load)), 1e-9)
            for kin, frc in ((s.inner, s.inner_forces), (s.outer, s.outer_forces)):
                for j in np.flatnonzero(frc.normal_load > 0):
                    if not contactForces:
                        break
                    length = frc.normal_load[j] * scale
                    slip = math.hypot(kin.slip_rolling[j], kin.slip_transverse[j])
                    # the race pushes the ball: arrow from outside the ball onto the contact point
                    start = kin.point[j] + length * kin.normal[j]
                    out.append(graphics.Arrow(pAxis=start.tolist(), vAxis=(-length * kin.normal[j]).tolist(),
                                              radius=0.04 * d, color=slip_color(slip, slipScale)))
            if loadZone:
                frame, origin = con.rotation, con.origin
                for j in range(con.z):
                    rel = frame.T @ (s.ball_position[j] - origin)
                    psi = math.atan2(rel[1], rel[0])
                    arc = graphics.Cylinder(pAxis=[0, 0, -0.8 * d], vAxis=[0, 0, 0.02 * d],
                                            radius=b.pitch_radius + 0.9 * d, radiusInner=b.pitch_radius - 0.9 * d,
                                            angleRange=[psi - np.pi / con.z, psi + np.pi / con.z],
                                            color=_load_color(s.inner_forces.normal_load[j] / q_ref), nTiles=6)
                    out.append(graphics.Move(arc, origin.tolist(), frame))
        return out

    from exudyn.utilities import VObjectGround

    return mbs.AddObject(ObjectGround(visualization=VObjectGround(show=True, graphicsDataUserFunction=draw)))


def annotate_frame(path, t, slip_scale=0.5):
    """Label a rendered PNG with its simulated time and the slip colour scale of the contact
    arrows (:func:`slip_color`: green rolling, red at >= ``slip_scale`` m/s), in place
    (Pillow, which matplotlib brings)."""
    from PIL import Image, ImageDraw, ImageFont

    image = Image.open(path).convert("RGB")
    draw = ImageDraw.Draw(image)
    try:
        font = ImageFont.load_default(size=14)
    except TypeError:  # Pillow < 10.1: the fixed bitmap font
        font = ImageFont.load_default()
    w, h = image.size
    draw.rectangle([0, 0, 190, 22], fill=(255, 255, 255))
    draw.text((6, 3), f"t = {t:.5f} s", fill=(0, 0, 0), font=font)
    # legend: a colour bar from 0 to slip_scale m/s along the bottom edge
    x0, x1, y0, y1 = 10, min(210, w - 10), h - 36, h - 24
    draw.rectangle([x0 - 4, y0 - 16, x1 + 60, h - 4], fill=(255, 255, 255))
    for x in range(x0, x1):
        r, g, b, _ = slip_color((x - x0) / (x1 - x0) * slip_scale, slip_scale)
        draw.line([x, y0, x, y1], fill=(int(255 * r), int(255 * g), int(255 * b)))
    draw.text((x0, y0 - 16), "contact slip (arrows)", fill=(0, 0, 0), font=font)
    draw.text((x0, y1 + 1), "0", fill=(0, 0, 0), font=font)
    draw.text((x1 - 10, y1 + 1), f">= {slip_scale:g} m/s", fill=(0, 0, 0), font=font)
    image.save(path)
    return path


def write_animation(frames, path, seconds_per_frame=0.4):
    """An animated GIF of PNG ``frames`` (Pillow), returns its path."""
    from PIL import Image

    images = [Image.open(f).convert("RGB") for f in frames]
    if not images:
        raise ValueError("write_animation: no frames")
    images[0].save(path, save_all=True, append_images=images[1:], duration=int(1000 * seconds_per_frame), loop=0)
    return Path(path)


def render_frames(SC, mbs, out_dir, *, steps=None, size=(800, 600), backend="auto", prefix="frame",
                  annotate=True, slip_scale=0.5):
    """Write PNG frames of a finished run (its stored solution, or the current state).

    Parameters
    ----------
    SC, mbs : Exudyn SystemContainer and MainSystem
    out_dir : str or Path
    steps : list of (t, q, q_t), optional
        System ODE2 coordinates (without reference values) and velocities to replay, one
        frame each; default: one frame of the current state.
    backend : {'auto', 'opengl', 'raytracer'}
        'auto': OpenGL when an X display is available (``DISPLAY``), else the raytracer.
    annotate : bool
        Label each frame with its time and the slip colour scale (:func:`annotate_frame`).

    Returns
    -------
    list of Path
    """
    import exudyn as exu

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if backend == "auto":
        backend = "opengl" if os.environ.get("DISPLAY") else "raytracer"
    if backend not in ("opengl", "raytracer"):
        raise ValueError(f"backend must be 'auto', 'opengl' or 'raytracer', got {backend!r}")
    vs = SC.visualizationSettings
    vs.general.autoFitScene = True
    # Exudyn's own solver text shows the run's last time on every replayed frame: each frame
    # gets its own time label instead (annotate_frame)
    vs.general.showSolverInformation = False
    vs.general.showSolverTime = False
    vs.view0.window.renderWindowSize = list(size)
    vs.openGL.advanced.initialModelRotation = (np.eye(3)).tolist()
    frames = steps if steps is not None else [None]
    written = []
    if backend == "opengl":
        SC.renderer.Start()
        SC.renderer.DoIdleTasks(0.1)
    try:
        for k, state in enumerate(frames):
            if state is not None:
                t, q, q_t = state
                # the raytracer draws the current configuration, OpenGL the visualization one
                for config in (exu.ConfigurationType.Current, exu.ConfigurationType.Visualization):
                    mbs.systemData.SetODE2Coordinates(list(q), configuration=config)
                    mbs.systemData.SetODE2Coordinates_t(list(q_t), configuration=config)
                    mbs.systemData.SetTime(t, config)
                mbs.SendRedrawSignal()
            path = out / f"{prefix}{k:04d}.png"
            if backend == "opengl":
                SC.renderer.ZoomAll()
                vs.exportImages.saveImageFileName = str(out / f"{prefix}{k:04d}")
                vs.exportImages.saveImageFormat = "PNG"
                vs.exportImages.saveImageSingleFile = True
                SC.renderer.RedrawAndSaveImage()
            else:
                import matplotlib
                matplotlib.use("Agg")
                import matplotlib.pyplot as plt
                SC.renderer.ZoomAll()
                image = SC.renderer.RedrawAndGetImage(useRaytracer=True)
                plt.imsave(path, image)
            if annotate:
                annotate_frame(path, float(mbs.systemData.GetTime(exu.ConfigurationType.Visualization))
                               if state is None else float(state[0]), slip_scale)
            written.append(path)
    finally:
        if backend == "opengl":
            SC.renderer.Stop()
    return written
