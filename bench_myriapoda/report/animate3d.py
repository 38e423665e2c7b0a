"""The 3-D view of an animation (``run --animate FILE --view 3d``): shaded, in perspective, the camera following.

``write_animation(..., view="3d")`` draws each recorded ``Scene`` with
matplotlib's mplot3d:

* the camera looks from the creature's front right and above (``ELEV``,
  ``AZIM``) in perspective (``FOCAL``: about a 60 degree field of view); its
  window is a box of fixed size (from the largest body extent over the run)
  centred on the body's mean point of each frame, so it follows the creature
  and the body keeps its size on screen;
* body surfaces (rigid boxes, FEM boundaries, lattice faces) flat-shaded by a
  fixed light from above (Lambert, with an ambient floor), faces turned away
  from the camera culled, painter-sorted by mplot3d; legs as polylines root ->
  knee -> tip in their Switcher state colours (the 2-D view's colours and
  legend), the right legs (near the camera) drawn over the body, the left ones
  under it; antennae dark brown, red while touching;
* the ground: a checkerboard of cells fixed in the world (so that motion shows
  against it) on the terrain's surface (``animate.surface_height``), shaded by
  the same light; the obstacles' cylinders and boxes as shaded solids.

World axes are x forward, y up, z to the creature's right; mplot3d's are
(x, -z, y), so its vertical axis is y and the picture is not mirrored.
"""
from __future__ import annotations

import math
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

from ..bodies.scene import Scene  # noqa: E402
from ..world.terrain_kernels import H_NOBST, OBST_CYLINDER, SLAB, obstacle_records  # noqa: E402
from .scene_style import (  # noqa: E402
    ANTENNA_COLOR, ANTENNA_CONTACT_COLOR, DEFAULT_COLOR, GROUND_COLOR,
    add_leg_state_legend, surface_height, surface_style,
)
from ..metrics.gait import STATE_COLORS  # noqa: E402

DEFAULT_SIZE = (1040, 720)            # [px] without --size
ELEV, AZIM = 24.0, -62.0              # [deg] camera elevation and azimuth (mplot3d's convention)
FOCAL = 1.2                           # perspective focal length (1 / tan(half field of view)): ~80 degrees
WINDOW_SCALE = 0.5                    # camera window half-width / the largest body extent of the run
GROUND_CELLS = 12                     # ground cells across the window
GROUND_REACH = 2.6                    # the ground is drawn this many window half-widths around the body
ZOOM = 1.5                            # mplot3d box zoom
LIGHT = np.array([-0.35, 1.0, 0.45]) / np.linalg.norm([-0.35, 1.0, 0.45])  # toward the light, world axes
AMBIENT = 0.35                        # shade of a face turned away from the light
GROUND_DARK = "#d8ccb4"               # the checkerboard's second colour
CYLINDER_SIDES = 16
OBSTACLE_3D_COLOR = "#a4a4a4"         # lighter than the 2-D view's grey: the shading darkens it


def _to_plot(p: np.ndarray) -> np.ndarray:
    """World (..., 3) (x, y up, z right) -> mplot3d (x, -z, y): vertical stays vertical, right-handed."""
    return np.stack([p[..., 0], -p[..., 2], p[..., 1]], axis=-1)


def camera_direction(elev: float = ELEV, azim: float = AZIM) -> np.ndarray:
    """Unit vector from the scene toward the camera, world axes."""
    e, a = math.radians(elev), math.radians(azim)
    plot = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])
    return np.array([plot[0], plot[2], -plot[1]])


def shade(normals: np.ndarray, rgb, light: np.ndarray = LIGHT) -> np.ndarray:
    """RGBA (F, 4) of faces with unit ``normals`` (F, 3) lit by ``light``: ambient + Lambert."""
    lam = np.clip(normals @ light, 0.0, 1.0)
    k = AMBIENT + (1.0 - AMBIENT) * lam
    base = np.broadcast_to(np.asarray(rgb, dtype=float).reshape(-1, 3), (len(normals), 3))
    return np.column_stack([k[:, None] * base, np.ones(len(normals))])


def _unit_normals(tris: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(unit normals (F, 3), finite mask (F,)) of triangles or planar polygons (F, >=3, 3)."""
    n = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    norm = np.linalg.norm(n, axis=1)
    ok = np.isfinite(norm) & (norm > 0) & np.all(np.isfinite(tris), axis=(1, 2))
    return n / np.where(ok, norm, 1.0)[:, None], ok


def body_polygons(scene: Scene, toward_camera: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The scene's triangles facing the camera (N, 3, 3) [m, world] and their shaded colours (N, 4)."""
    polys, colors = [], []
    for verts, faces, kind in scene.triangles:
        if not len(faces):
            continue
        p = verts[faces]
        n, ok = _unit_normals(p)
        # a little slack: with perspective, faces near the silhouette are seen although they turn slightly away
        keep = ok & (n @ toward_camera > -0.15)
        polys.append(p[keep])
        colors.append(shade(n[keep], to_rgb(surface_style(kind).color)))
    if not polys:
        return np.zeros((0, 3, 3)), np.zeros((0, 4))
    return np.concatenate(polys), np.concatenate(colors)


def ground_cells(terrain, xlim, zlim, step: float) -> tuple[list, np.ndarray]:
    """Ground cells on the terrain surface within x in ``xlim``, z in ``zlim`` [m]: quads (list of (4, 3)
    [m, world]) and their colours (N, 4), a checkerboard of pitch ``step`` [m] fixed in the world.

    Heights from ``surface_height`` on the cell corners; cells without ground below (NaN) are left out.
    A slab's edge is a cell boundary, so the step shows as a wall.
    """
    kind, f = terrain
    if f.shape[0] > H_NOBST and f[H_NOBST] > 0:  # the ground alone: obstacles are drawn as solids
        f = f.copy()
        f[H_NOBST] = 0.0
    xe = np.arange(math.floor(xlim[0] / step), math.ceil(xlim[1] / step) + 1) * step
    xe = np.clip(xe, *xlim)
    if kind == SLAB and xlim[0] < f[2] < xlim[1]:  # the book's edge: a near-vertical cell of width 1e-6 step
        xe = np.concatenate([xe, [f[2] - 1e-6 * step, f[2] + 1e-6 * step]])
    xe = np.unique(xe)
    ze = np.unique(np.clip(np.arange(math.floor(zlim[0] / step), math.ceil(zlim[1] / step) + 1) * step, *zlim))
    h = np.stack([surface_height(kind, f, xe, float(z)) for z in ze], axis=1)  # (nx, nz)
    quads, colors = [], []
    light_rgb, dark_rgb = np.asarray(to_rgb(GROUND_COLOR)), np.asarray(to_rgb(GROUND_DARK))
    for i in range(len(xe) - 1):
        for j in range(len(ze) - 1):
            y = (h[i, j], h[i + 1, j], h[i + 1, j + 1], h[i, j + 1])
            if not np.all(np.isfinite(y)):
                continue
            # corners counter-clockwise seen from above (+y): normal up
            q = np.array([[xe[i], y[0], ze[j]], [xe[i], y[3], ze[j + 1]], [xe[i + 1], y[2], ze[j + 1]],
                          [xe[i + 1], y[1], ze[j]]])
            quads.append(q)
            cx, cz = 0.5 * (xe[i] + xe[i + 1]), 0.5 * (ze[j] + ze[j + 1])
            colors.append(light_rgb if (math.floor(cx / step) + math.floor(cz / step)) % 2 == 0 else dark_rgb)
    if not quads:
        return [], np.zeros((0, 4))
    n, _ = _unit_normals(np.array(quads))
    return quads, shade(n, np.array(colors))


def obstacle_polygons(terrain, xlim, zlim, toward_camera: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The obstacles (cylinders, yawed boxes) within the window as shaded polygons: (N, 4, 3) [m], (N, 4)."""
    kind, f = terrain
    if f.shape[0] <= H_NOBST or f[H_NOBST] <= 0:
        return np.zeros((0, 4, 3)), np.zeros((0, 4))
    quads = []
    for r in obstacle_records(f):
        if r[0] == OBST_CYLINDER:
            cx, cz, rad, y0, y1 = r[1:6]
            if not (xlim[0] - rad < cx < xlim[1] + rad and zlim[0] - rad < cz < zlim[1] + rad):
                continue
            a = 2 * np.pi * np.arange(CYLINDER_SIDES + 1) / CYLINDER_SIDES
            ring = np.column_stack([cx + rad * np.cos(a), cz + rad * np.sin(a)])
            for k in range(CYLINDER_SIDES):  # side quads, outward
                (xa, za), (xb, zb) = ring[k], ring[k + 1]
                quads.append([[xa, y0, za], [xa, y1, za], [xb, y1, zb], [xb, y0, zb]])
            # the top as a fan of quads (centre, two ring points, centre): one polygon shape for all
            for k in range(CYLINDER_SIDES):
                (xa, za), (xb, zb) = ring[k], ring[k + 1]
                quads.append([[cx, y1, cz], [xb, y1, zb], [xa, y1, za], [cx, y1, cz]])
        else:
            cx, cy, cz, hx, hy, hz, c_, s_ = r[1:9]
            if not (xlim[0] - hx - hz < cx < xlim[1] + hx + hz and zlim[0] - hx - hz < cz < zlim[1] + hx + hz):
                continue
            ax_x, ax_z = np.array([c_, 0.0, -s_]), np.array([s_, 0.0, c_])  # the box's own x and z, yawed
            centre = np.array([cx, cy, cz])
            axes = (hx * ax_x, np.array([0.0, hy, 0.0]), hz * ax_z)
            for d in range(3):
                u, v, w = axes[d], axes[(d + 1) % 3], axes[(d + 2) % 3]
                for sgn in (1.0, -1.0):
                    c0 = centre + sgn * u
                    quad = [c0 - v - w, c0 + v - w, c0 + v + w, c0 - v + w]
                    quads.append(quad if sgn > 0 else quad[::-1])
    if not quads:
        return np.zeros((0, 4, 3)), np.zeros((0, 4))
    q = np.asarray(quads, dtype=float)
    n, ok = _unit_normals(q)
    # the fan tops and the flipped box faces are not all wound alike: shade both sides alike (each normal
    # turned toward the camera) and cull nothing -- mplot3d's depth sort hides the far faces
    n = np.where((n @ toward_camera < 0)[:, None], -n, n)
    return q[ok], shade(n[ok], to_rgb(OBSTACLE_3D_COLOR))


def nice_step(target: float) -> float:
    """The smallest of 1, 2, 5 x 10^k [m] at least ``target`` [m]: checkerboard cells of a round size."""
    base = 10.0 ** math.floor(math.log10(target))
    return next(m * base for m in (1.0, 2.0, 5.0, 10.0) if m * base >= target * (1 - 1e-9))


def camera_window(frames: Sequence[Scene]) -> tuple[float, float]:
    """(half-width R [m] of the horizontal window, height V [m] of the vertical window) for the whole run."""
    ext_h, ext_v = 0.0, 0.0
    for s in frames:
        lo, hi = s.bounds()
        if np.all(np.isfinite(lo)) and np.all(np.isfinite(hi)):
            ext_h = max(ext_h, float(hi[0] - lo[0]), float(hi[2] - lo[2]))
            ext_v = max(ext_v, float(hi[1] - lo[1]))
    r = WINDOW_SCALE * max(ext_h, ext_v, 1e-3)
    return r, max(r, 1.2 * ext_v)


def figure_3d(frames: Sequence[Scene], terrain, title: str, dpi: float, size_in):
    """The 3-D picture and its per-frame ``draw(scene, t, k)`` (see the module docstring).

    size_in: (width, height) [in] of the figure.
    """
    fig = plt.figure(figsize=size_in, dpi=dpi)
    has_legs = any(s.legs is not None for s in frames)
    bottom = 0.5 / size_in[1] if has_legs else 0.0
    ax = fig.add_axes((0.0, bottom, 1.0, 1.0 - bottom - 0.3 / size_in[1]), projection="3d")
    ax.set_proj_type("persp", focal_length=FOCAL)
    ax.view_init(elev=ELEV, azim=AZIM)
    ax.set_axis_off()
    ax.computed_zorder = False  # our layer order: ground, far legs, body and obstacles, near legs, antennae
    R, V = camera_window(frames)
    ax.set_box_aspect((2 * R, 2 * R, V), zoom=ZOOM)
    toward = camera_direction()
    step = nice_step(2 * R / GROUND_CELLS)

    ground = ax.add_collection3d(Poly3DCollection([], linewidths=0.0, zorder=0), autolim=False)
    legs_far = ax.add_collection3d(Line3DCollection([], linewidths=1.8, zorder=1), autolim=False)
    solids = ax.add_collection3d(Poly3DCollection([], linewidths=0.2, zorder=2), autolim=False)
    springs = ax.add_collection3d(Line3DCollection([], colors=[(0.2, 0.2, 0.2, 0.35)], linewidths=0.4, zorder=2.5),
                                  autolim=False)
    legs_near = ax.add_collection3d(Line3DCollection([], linewidths=1.8, zorder=3), autolim=False)
    antennae = ax.add_collection3d(Line3DCollection([], linewidths=1.3, zorder=4), autolim=False)
    for coll in (ground, legs_far, solids, springs, legs_near, antennae):
        coll.set_clip_on(False)  # mplot3d clips to a square box inside the axes; the picture is wider
    head = fig.text(0.5, 1.0 - 0.08 / size_in[1], "", ha="center", va="top", fontsize=11,
                    bbox=dict(facecolor="white", edgecolor="none", alpha=0.8))
    if has_legs:
        add_leg_state_legend(fig)

    def draw(scene: Scene, t: float, k: int) -> None:
        pts = scene.points()
        pts = pts[np.all(np.isfinite(pts), axis=1)]
        c = pts.mean(axis=0) if len(pts) else np.zeros(3)
        xlim, zlim = (c[0] - R, c[0] + R), (c[2] - R, c[2] + R)
        ax.set_xlim(*xlim)
        ax.set_ylim(-zlim[1], -zlim[0])
        ax.set_zlim(c[1] - 0.45 * V, c[1] + 0.55 * V)
        if terrain is not None:
            # the floor reaches past the window (mplot3d does not clip): it fills the picture to the horizon
            reach = GROUND_REACH * R
            gx, gz = (c[0] - reach, c[0] + reach), (c[2] - reach, c[2] + reach)
            quads, qcol = ground_cells(terrain, gx, gz, step)
            ground.set_verts([_to_plot(q) for q in quads])
            ground.set_facecolor(qcol)
            obst, ocol = obstacle_polygons(terrain, gx, gz, toward)
        else:
            obst, ocol = np.zeros((0, 4, 3)), np.zeros((0, 4))
        tris, tcol = body_polygons(scene, toward)
        # body and obstacles in one collection, so that mplot3d's depth sort puts each in front of the other
        # where it belongs
        polys = [_to_plot(p) for p in tris] + [_to_plot(q) for q in obst]
        solids.set_verts(polys)
        colors = np.concatenate([tcol, ocol]) if len(polys) else np.zeros((0, 4))
        solids.set_facecolor(colors)
        solids.set_edgecolor(np.column_stack([0.6 * colors[:, :3], np.full(len(colors), 0.6)])
                             if len(colors) else colors)
        springs.set_segments(_to_plot(scene.springs) if scene.springs is not None else [])
        for side, coll in ((1, legs_near), (0, legs_far)):
            if scene.legs is None:
                coll.set_segments([])
                continue
            legs, states = scene.legs[side::2], scene.leg_states[side::2]
            coll.set_segments([_to_plot(leg) for leg in legs])
            coll.set_color([STATE_COLORS[int(s)] if 0 <= s < len(STATE_COLORS) else DEFAULT_COLOR for s in states])
        if scene.antennae is not None:
            touching = scene.antenna_contact if scene.antenna_contact is not None else np.zeros(2, bool)
            antennae.set_segments([_to_plot(a) for a in scene.antennae])
            antennae.set_color([ANTENNA_CONTACT_COLOR if touching[i] else ANTENNA_COLOR
                                for i in range(len(scene.antennae))])
        head.set_text(f"{title}   t = {t:.3f} s" if title else f"t = {t:.3f} s")

    return fig, draw
