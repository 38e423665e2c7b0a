"""Terrain drawn as it is (issue 16): height fields as shaded contours, closed meshes as shaded silhouettes.

Used by the animations (``report/animate.py``: from above and from the right
side) and the report's top views (``report/trajectories.py``):

* a height field (the paper's Gaussian mixture, Sec. 6.2): from above, filled
  contours of h(x, z) on an earth colour map with thin contour lines; from the
  side, its skyline -- the highest surface point over the view's depth at each
  x -- behind the profile under the body;
* a closed mesh (Fig. 1's skull): its triangles projected on the view plane,
  back faces culled, painter-sorted (farthest first) and flat-shaded by the
  angle to a light: the silhouette from above and from the side with the
  shape's relief inside it, not a bounding box or one profile line.

Views: "top" looks down -y onto (x, z); "side" looks from +z onto (x, y).
Limits are the axes' data ranges [m]; drawing stays inside them.
"""
from __future__ import annotations

import matplotlib
import numpy as np
from matplotlib.collections import PolyCollection

from ..world import terrain_kernels as TK

HEIGHTFIELD_CMAP = "gist_earth"
HEIGHTFIELD_LEVELS = 12
GRID_POINTS = 160                     # samples per axis of a height field's contours and skyline
SKYLINE_DEPTH_SAMPLES = 61            # across the depth, odd: the middle depth (where animate draws the profile) is one
MESH_RGB = np.array([0.70, 0.66, 0.58])
LIGHT = np.array([0.35, 0.8, 0.5])    # toward the light (world frame), normalised below
AMBIENT = 0.35                        # shade = AMBIENT + (1 - AMBIENT) |n . light|
# view direction toward the viewer and the two world axes drawn (horizontal, vertical)
VIEWS = {"top": (np.array([0.0, 1.0, 0.0]), (0, 2)), "side": (np.array([0.0, 0.0, 1.0]), (0, 1))}


def draw_heightfield_top(ax, f: np.ndarray, xlim, zlim, zorder: float = 0.15, alpha: float = 0.75) -> None:
    """Filled contours of a HEIGHTFIELD terrain's height over x in xlim, z in zlim [m], seen from above."""
    xs = np.linspace(min(xlim), max(xlim), GRID_POINTS)
    zs = np.linspace(min(zlim), max(zlim), GRID_POINTS)
    X, Z = np.meshgrid(xs, zs)
    H = TK.heightfield_numpy(f, X, Z)
    if np.ptp(H) <= 0:
        return
    ax.contourf(X, Z, H, levels=HEIGHTFIELD_LEVELS, cmap=HEIGHTFIELD_CMAP, alpha=alpha, zorder=zorder)
    ax.contour(X, Z, H, levels=HEIGHTFIELD_LEVELS, colors="k", linewidths=0.3, alpha=0.35, zorder=zorder + 0.01)


def heightfield_skyline(f: np.ndarray, xs: np.ndarray, zlim) -> np.ndarray:
    """Highest surface height [m] over z in zlim at each x (n,) [m]: the height field seen from the side."""
    zs = np.linspace(min(zlim), max(zlim), SKYLINE_DEPTH_SAMPLES)
    X, Z = np.meshgrid(np.asarray(xs, dtype=float), zs)
    return TK.heightfield_numpy(f, X, Z).max(axis=0)


def draw_heightfield_side(ax, f: np.ndarray, xlim, ylim, zlim, zorder: float = 0.05) -> None:
    """The height field's skyline over the view's depth zlim, filled down to the bottom of ylim (side view)."""
    xs = np.linspace(min(xlim), max(xlim), GRID_POINTS * 2)
    top = heightfield_skyline(f, xs, zlim)
    cmap = matplotlib.colormaps[HEIGHTFIELD_CMAP]
    ax.fill_between(xs, top, min(ylim) - (max(ylim) - min(ylim)), color=cmap(0.55), alpha=0.5, lw=0, zorder=zorder)
    ax.plot(xs, top, color=cmap(0.3), lw=0.8, alpha=0.8, zorder=zorder + 0.01)


def mesh_view_polygons(vertices: np.ndarray, faces: np.ndarray, view: str, hlim=None, vlim=None):
    """(polygons (m, 3, 2) [m], face colours (m, 4)) of a closed mesh seen in ``view``.

    vertices (V, 3) [m], faces (T, 3) outward-wound.  Back faces (normal away from the
    viewer) are culled, the rest sorted farthest first and shaded; triangles entirely
    outside the limits hlim, vlim (horizontal, vertical axis of the view) are dropped.
    """
    toward, (a, b) = VIEWS[view]
    tri = vertices[faces]                                   # (T, 3, 3)
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    norm = np.linalg.norm(n, axis=1)
    keep = (n @ toward > 0) & (norm > 0)
    p = tri[:, :, [a, b]]
    for lim, col in ((hlim, 0), (vlim, 1)):
        if lim is not None:
            lo, hi = min(lim), max(lim)
            keep &= (p[:, :, col].max(axis=1) >= lo) & (p[:, :, col].min(axis=1) <= hi)
    tri, n, norm, p = tri[keep], n[keep], norm[keep], p[keep]
    order = np.argsort(tri.mean(axis=1) @ toward)           # farthest first: nearer faces paint over
    light = LIGHT / np.linalg.norm(LIGHT)
    shade = AMBIENT + (1.0 - AMBIENT) * np.abs((n[order] / norm[order, None]) @ light)
    colours = np.column_stack([shade[:, None] * MESH_RGB, np.ones(len(order))])
    return p[order], colours


def draw_mesh(ax, vertices: np.ndarray, faces: np.ndarray, view: str, hlim=None, vlim=None,
              zorder: float = 0.15) -> None:
    """The closed mesh's shaded silhouette in ``view`` ("top" or "side") on ``ax``."""
    polys, colours = mesh_view_polygons(np.asarray(vertices, float), np.asarray(faces), view, hlim, vlim)
    if len(polys):
        # edges in the face colour close the hairline gaps antialiasing leaves between triangles
        ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors=colours, linewidths=0.2,
                                         zorder=zorder))


def draw_terrain_shape(ax_top, ax_side, kind: int, f: np.ndarray, xlim, ylim, zlim) -> bool:
    """Height field or closed mesh of terrain (kind, f) on a top and a side view; False for other kinds.

    xlim, ylim, zlim [m]: the views' ranges (top: x-z, side: x-y); either axis may be None.
    """
    if kind == TK.HEIGHTFIELD and f[TK.H_NDATA] > 0:
        if ax_top is not None:
            draw_heightfield_top(ax_top, f, xlim, zlim)
        if ax_side is not None:
            draw_heightfield_side(ax_side, f, xlim, ylim, zlim)
        return True
    if kind == TK.MESH:
        from ..world.meshes import mesh_arrays

        v, fc = mesh_arrays(f)
        if ax_top is not None:
            draw_mesh(ax_top, v, fc, "top", xlim, zlim)
        if ax_side is not None:
            draw_mesh(ax_side, v, fc, "side", xlim, ylim, zorder=0.6)
        return True
    return False
