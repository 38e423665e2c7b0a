"""Terrain drawn as it is (issue 16, report/terrain_drawing.py): height fields shaded, meshes as silhouettes.

The closed mesh must appear as its projected shape from above and from the side
(every visible triangle, back faces culled, farthest first), covering the mesh's
projected extent but not its bounding box; a height field as filled contours
from above and its skyline from the side; and the animation and top-view
helpers call them.
"""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.path import Path as MplPath  # noqa: E402

from bench_myriapoda.report import terrain_drawing as TD  # noqa: E402
from bench_myriapoda.world import meshes  # noqa: E402
from bench_myriapoda.world import terrain_kernels as TK  # noqa: E402

SKULL_SUBDIVISIONS = 8   # 768 triangles: the same shape, quick to build


def _skull():
    m = meshes.skull_mesh(SKULL_SUBDIVISIONS)
    return np.asarray(m.vertices, float), np.asarray(m.faces)


def _covered_fraction(polys, lo, hi, n=60):
    """Fraction of an n x n grid over the box [lo, hi] inside any polygon."""
    g = np.stack(np.meshgrid(np.linspace(lo[0], hi[0], n), np.linspace(lo[1], hi[1], n)), -1).reshape(-1, 2)
    inside = np.zeros(len(g), bool)
    for p in polys:
        inside |= MplPath(p).contains_points(g, radius=1e-9)
    return inside.mean()


def test_mesh_silhouettes_from_above_and_the_side_are_the_shape_not_its_box():
    v, f = _skull()
    for view, (a, b) in (("top", (0, 2)), ("side", (0, 1))):
        polys, colours = TD.mesh_view_polygons(v, f, view)
        toward = TD.VIEWS[view][0]
        n = np.cross(v[f][:, 1] - v[f][:, 0], v[f][:, 2] - v[f][:, 0])
        assert len(polys) == int(np.sum(n @ toward > 0))     # every front face, no back face
        lo, hi = v[:, [a, b]].min(0), v[:, [a, b]].max(0)
        assert np.allclose(polys.reshape(-1, 2).min(0), lo) and np.allclose(polys.reshape(-1, 2).max(0), hi)
        frac = _covered_fraction(polys, lo, hi)
        assert 0.5 < frac < 0.95, (view, frac)                # a rounded silhouette fills part of its box
        assert np.all((colours[:, :3] > 0) & (colours[:, :3] <= 1))
        depth = v[f][n @ toward > 0].mean(axis=1) @ toward
        assert len(np.unique(colours[:, 0])) > 10              # shaded, not one flat colour
        assert np.all(np.diff(np.sort(depth)) >= 0)


def test_draw_terrain_shape_puts_height_field_contours_and_mesh_triangles_on_both_views():
    hf = TK.heightfield_params(0.0, [[0.0, 0.0], [3.0, 1.0]], [0.5, -0.3], [1.0, 2.0])
    fig, (top, side) = plt.subplots(1, 2)
    assert TD.draw_terrain_shape(top, side, TK.HEIGHTFIELD, hf, (-5, 5), (-1, 2), (-5, 5))
    assert len(top.collections) >= 2 and len(side.collections) >= 1
    xs = np.linspace(-5, 5, 50)
    sky = TD.heightfield_skyline(hf, xs, (-5, 5))
    assert np.all(sky >= TK.heightfield_numpy(hf, xs, np.zeros_like(xs)) - 1e-12)  # at least the mid profile
    X, Z = np.meshgrid(np.linspace(-5, 5, 201), np.linspace(-5, 5, 201))
    assert abs(sky.max() - TK.heightfield_numpy(hf, X, Z).max()) < 0.01   # the summit is on the skyline
    plt.close(fig)
    v, f = _skull()
    fm = meshes.mesh_terrain_params((v, f))
    fig, (top, side) = plt.subplots(1, 2)
    assert TD.draw_terrain_shape(top, side, TK.MESH, fm, (-3, 3), (-3, 3), (-3, 3))
    assert any(isinstance(c, PolyCollection) for c in top.collections)
    assert any(isinstance(c, PolyCollection) for c in side.collections)
    assert not TD.draw_terrain_shape(top, side, TK.PLANE, TK.header(0.0), (-3, 3), (-3, 3), (-3, 3))
    plt.close(fig)
