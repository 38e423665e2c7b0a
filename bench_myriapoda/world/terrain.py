"""Terrains of a scenario as the (kind, parameters) pair that kernels query.

``terrain_from_scenario(sc)`` builds ``(kind, f)`` (layout in ``terrain_kernels``)
from the ``[scenario]`` keys:

* ``terrain``: plane, slope, slab, heightfield, mesh, or none.
* heightfield (the paper's generator, Sec. 6.2): ``heightfield_count`` Gaussians
  with amplitudes and widths uniform in ``heightfield_amplitude_m`` and
  ``heightfield_width_m`` ([lo, hi]), centres uniform in |x|, |z| <=
  ``heightfield_extent_m``, drawn from ``numpy.random.default_rng([terrain_seed, 0])``.
* mesh: ``mesh`` = "skull" (``meshes.skull_mesh(mesh_subdivisions)``) or a mesh
  file, scaled by ``mesh_scale`` and moved by ``mesh_translate_m``; with
  ``mesh_ground`` also the plane y = ``ground_height_m``; ``mesh_band_m``.
* obstacles on any terrain: ``obstacle_cylinders`` random vertical cylinders
  (Fig. 13; radii, heights uniform in ``obstacle_radius_m``, ``obstacle_height_m``,
  centres uniform in ``obstacle_region_m``, none within
  ``obstacle_clear_radius_m`` of the origin, from
  ``default_rng([terrain_seed, 1])``), plus explicit ``obstacle_cylinder_list``
  and ``obstacle_box_list``.  Obstacles stand on the base surface: a cylinder
  of height H rises to H above the surface at its centre and reaches down
  below the lowest surface point of its footprint; a box's centre height is
  given above the surface at its centre.  On a mesh (or no ground) they stand
  on y = ``ground_height_m``.

``terrain_description(sc)`` returns what a plot needs (height function,
Gaussians, obstacles, mesh).  Building a mesh terrain takes a second or two
for 10^5 triangles; it is cached per process.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from ..core.errors import InputError
from . import meshes, terrain_cache
from . import terrain_kernels as TK
from .terrain_kernels import HEIGHTFIELD, MESH, N_TERRAIN_PARAMS, PLANE, SLAB, SLOPE

TERRAIN_KINDS = {"plane": PLANE, "slope": SLOPE, "slab": SLAB, "heightfield": HEIGHTFIELD, "mesh": MESH,
                 "none": PLANE}
NO_GROUND_HEIGHT_M = -1.0e9  # terrain "none": a plane so far below that nothing ever reaches it
MAX_PLACEMENT_TRIES = 1000  # per random cylinder


def _source(sc) -> str:
    return f"scenario {sc.name!r}" if getattr(sc, "name", "") else "scenario"


def heightfield_gaussians_from(sc) -> np.ndarray:
    """(n, 4) Gaussians (cx, cz, amplitude, width) of the scenario's seeded height field."""
    rng = np.random.default_rng([int(sc.terrain_seed), 0])
    n = int(sc.heightfield_count)
    e = float(sc.heightfield_extent_m)
    c = rng.uniform(-e, e, size=(n, 2))
    a = rng.uniform(*sc.heightfield_amplitude_m, size=n)
    s = rng.uniform(*sc.heightfield_width_m, size=n)
    return np.column_stack([c, a, s])


@functools.lru_cache(maxsize=4)
def _mesh_params_cached(mesh: str, subdivisions: int, scale: float, translate: tuple, band_m: float,
                        cell_edges: float = meshes.DEFAULT_CELL_EDGES) -> np.ndarray:
    if mesh == "skull":
        m = meshes.transformed(meshes.skull_mesh(subdivisions), scale, translate)
        name = f"skull({subdivisions})"
    else:
        m = meshes.load_closed_mesh(mesh, scale, translate)
        name = mesh
    band = band_m if band_m > 0 else None
    k = terrain_cache.key((np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)),
                          (cell_edges, band_m))
    # built once per machine (``terrain_cache``: 6.6 CPU s for the Fig. 1 skull in every new process otherwise)
    f = terrain_cache.cached(k, lambda: meshes.mesh_terrain_params(m, None, cell_edges=cell_edges, band_m=band,
                                                                   name=name))
    f.setflags(write=False)
    return f


def no_ground_terrain() -> tuple[int, np.ndarray]:
    """(kind, f) of no ground at all: the plane far below (``NO_GROUND_HEIGHT_M``) that ``terrain = "none"`` builds."""
    f = np.zeros(N_TERRAIN_PARAMS)
    f[0] = NO_GROUND_HEIGHT_M
    return TERRAIN_KINDS["none"], f


def _base_terrain(sc) -> tuple[int, np.ndarray]:
    kind = TERRAIN_KINDS[sc.terrain]
    if kind == HEIGHTFIELD:
        g = heightfield_gaussians_from(sc)
        return kind, TK.heightfield_params(sc.ground_height_m, g[:, :2], g[:, 2], g[:, 3])
    if kind == MESH:
        try:
            fm = _mesh_params_cached(sc.mesh, int(sc.mesh_subdivisions), float(sc.mesh_scale),
                                     tuple(float(t) for t in sc.mesh_translate_m), float(sc.mesh_band_m),
                                     float(sc.mesh_cell_edges))
        except meshes.MeshError as exc:
            raise InputError(_source(sc), "scenario.mesh", str(exc)) from None
        f = np.array(fm)  # a private, writable copy
        f[0] = sc.ground_height_m
        f[1] = 1.0 if sc.mesh_ground else 0.0
        return kind, f
    f = np.zeros(N_TERRAIN_PARAMS)
    f[0] = NO_GROUND_HEIGHT_M if sc.terrain == "none" else sc.ground_height_m
    if kind == SLOPE:
        f[1] = math.radians(sc.slope_deg)
    elif kind == SLAB:
        f[1] = sc.ground_height_m + sc.slab_height_m
        f[2] = sc.slab_edge_x_m
        f[3] = min(sc.slab_edge_radius_m, sc.slab_height_m)
    return kind, f


def base_height(sc, kind: int, f: np.ndarray, x, z) -> np.ndarray:
    """Height [m] of the base surface (without obstacles) at (x, z) on which obstacles stand."""
    x = np.asarray(x, dtype=float)
    z = np.asarray(z, dtype=float)
    shape = np.broadcast(x, z).shape
    if sc.terrain in ("none", "mesh"):
        return np.full(shape, float(sc.ground_height_m))
    if kind == SLOPE:
        return np.broadcast_to(f[0] + x * math.tan(f[1]), shape).copy()
    if kind == SLAB:
        return np.broadcast_to(np.where(x <= f[2], f[1], f[0]), shape).copy()
    if kind == HEIGHTFIELD:
        return TK.heightfield_numpy(f, x, z)
    return np.full(shape, float(f[0]))


def _footprint_heights(sc, kind, f, cx, cz, r) -> np.ndarray:
    """Base heights under cylinders (n,) centred at cx, cz [m] of radius r [m]: (n, 33), column 0 at
    the centre, then 16 points on the rim and 16 at half the radius.  One call for all cylinders: a
    height field's Gaussians are summed once over every point, not once per cylinder (issue 15:
    2,000 cylinders on 2,000 Gaussians took minutes one by one)."""
    a = np.linspace(0.0, 2 * np.pi, 16, endpoint=False)
    cx, cz, r = (np.asarray(v, dtype=float)[:, None] for v in (cx, cz, r))
    xs = np.concatenate([cx, cx + r * np.cos(a), cx + 0.5 * r * np.cos(a)], axis=1)
    zs = np.concatenate([cz, cz + r * np.sin(a), cz + 0.5 * r * np.sin(a)], axis=1)
    return base_height(sc, kind, f, xs, zs)


def random_cylinders(sc) -> np.ndarray:
    """(n, 4) random cylinders (x, z, radius, height) of a scenario, reproducible per terrain_seed.

    Centres uniform in ``obstacle_region_m``; a draw whose cylinder comes
    within ``obstacle_clear_radius_m`` of the origin is redrawn (Fig. 13 keeps
    the start area free).  Overlapping cylinders are allowed (a paved surface).
    """
    n = int(sc.obstacle_cylinders)
    out = np.zeros((n, 4))
    if n == 0:
        return out
    rng = np.random.default_rng([int(sc.terrain_seed), 1])
    x0, x1, z0, z1 = sc.obstacle_region_m
    clear = float(sc.obstacle_clear_radius_m)
    for i in range(n):
        for _ in range(MAX_PLACEMENT_TRIES):
            r = rng.uniform(*sc.obstacle_radius_m)
            hgt = rng.uniform(*sc.obstacle_height_m)
            cx, cz = rng.uniform(x0, x1), rng.uniform(z0, z1)
            if math.hypot(cx, cz) - r >= clear:
                out[i] = cx, cz, r, hgt
                break
        else:
            raise InputError(_source(sc), "scenario.obstacle_clear_radius_m",
                             f"no room for random cylinders: the clear disc of radius {clear} m covers "
                             f"obstacle_region_m {list(sc.obstacle_region_m)}")
    return out


def obstacle_records_from(sc, kind: int, f: np.ndarray) -> np.ndarray:
    """(n, OBST_STRIDE) obstacle records of a scenario standing on the base terrain (kind, f)."""
    recs = []
    v = sc.obstacle_cylinder_list
    cyl = np.concatenate([random_cylinders(sc), np.reshape(np.asarray(v, dtype=float), (-1, 4))])
    if len(cyl):
        h = _footprint_heights(sc, kind, f, cyl[:, 0], cyl[:, 1], cyl[:, 2])
        for (cx, cz, r, hgt), hc in zip(cyl, h):
            top = float(hc[0]) + hgt
            bottom = min(float(hc.min()) - r, top - hgt - r)
            recs.append(TK.cylinder_record(cx, cz, r, bottom, top))
    v = sc.obstacle_box_list
    for i in range(0, len(v), 7):
        x, y, z, hx, hy, hz, yaw = v[i: i + 7]
        recs.append(TK.box_record(x, float(base_height(sc, kind, f, x, z)) + y, z, hx, hy, hz, math.radians(yaw)))
    return np.array(recs).reshape(-1, TK.OBST_STRIDE)


def terrain_from_scenario(sc) -> tuple[int, np.ndarray]:
    """(kind code, float64 parameter vector) of a ``ScenarioConfig``'s terrain (see terrain_kernels)."""
    kind, f = _base_terrain(sc)
    recs = obstacle_records_from(sc, kind, f)
    if len(recs):
        f = TK.with_obstacles(f, recs)
    return kind, f


def placement_terrain(sc) -> tuple[int, np.ndarray]:
    """The surface a body is placed above at t = 0.

    The scenario's terrain, except for ``none``: its stand-in plane lies far
    below (``NO_GROUND_HEIGHT_M``), and a body placed above it would sit where
    float64 cannot resolve a time step's motion, so ``none`` places bodies above
    ``ground_height_m`` instead.
    """
    kind, f = terrain_from_scenario(sc)
    return placement_from(sc, kind, f)


def placement_from(sc, kind: int, f: np.ndarray) -> tuple[int, np.ndarray]:
    """``placement_terrain`` of a scenario whose terrain (kind, f) is built already (``world.World``)."""
    if sc.terrain == "none":
        f = f.copy()
        f[0] = sc.ground_height_m
    return kind, f


@dataclass
class TerrainDescription:
    """What a plot or animation needs to draw a scenario's terrain (world frame, metres).

    height(x, z): the base surface height for arrays x, z (None for a mesh);
    gaussians: (n, 4) cx, cz, amplitude, width of a height field;
    cylinders: dicts x, z, radius, y_bottom, y_top; boxes: dicts centre,
    half_extents, yaw_deg; mesh: (vertices, faces) of a mesh terrain.
    """

    terrain: str
    kind: int
    f: np.ndarray
    ground_height_m: float | None
    height: Callable[[Any, Any], np.ndarray] | None = None
    gaussians: np.ndarray | None = None
    cylinders: list = field(default_factory=list)
    boxes: list = field(default_factory=list)
    mesh: tuple | None = None

    @property
    def obstacles(self) -> list:
        return [dict(type="cylinder", **c) for c in self.cylinders] + [dict(type="box", **b) for b in self.boxes]


def terrain_description(sc, terrain: tuple[int, np.ndarray] | None = None) -> TerrainDescription:
    """The scenario's terrain as plot data (see ``TerrainDescription``); ``terrain``: its (kind, f) when built
    already (``world.World.terrain``), built here when None."""
    kind, f = terrain_from_scenario(sc) if terrain is None else terrain
    ground = None if sc.terrain == "none" or (sc.terrain == "mesh" and not sc.mesh_ground) else float(sc.ground_height_m)
    d = TerrainDescription(terrain=sc.terrain, kind=kind, f=f, ground_height_m=ground)
    if kind != MESH and sc.terrain != "none":
        d.height = functools.partial(base_height, sc, kind, f)
    if kind == HEIGHTFIELD:
        d.gaussians = TK.heightfield_gaussians(f)
    if kind == MESH:
        d.mesh = meshes.mesh_arrays(f)
    for r in TK.obstacle_records(f) if f[TK.H_NOBST] > 0 else ():
        r = [float(v) for v in r]
        if r[0] == TK.OBST_CYLINDER:
            d.cylinders.append(dict(x=r[1], z=r[2], radius=r[3], y_bottom=r[4], y_top=r[5]))
        else:
            d.boxes.append(dict(centre=(r[1], r[2], r[3]), half_extents=(r[4], r[5], r[6]),
                                yaw_deg=math.degrees(math.atan2(r[8], r[7]))))
    return d
