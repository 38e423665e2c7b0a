"""Cost of the terrain queries inside numba: the plane vs a closed mesh of >= 100,000 triangles.

Each round calls ``signed_distance`` and ``surface_normal`` once each for 10^5
points within 1 cm of the surface, in one numba loop.  ns_per_query in
extra_info is the time of that pair per point.  Orders:

* ``random``: the points in random order over the whole surface: every query
  misses the caches (the cold, worst case);
* ``coherent``: the same points sorted along the hash grid, as a body's nodes
  query the same neighbourhood step after step.

``test_bench_walk_plane_vs_closed_mesh`` is the issue's target: the walking
18-segment hybrid centipede per step on the plane and on a closed mesh with
a flat top at y = 0 (the same physics, >= 100,000 triangles).

    python3 -m pytest tests/benchmarks/test_bench_terrain.py --benchmark-enable --benchmark-only
"""
from __future__ import annotations

import numpy as np
import pytest

from bench_myriapoda.world import meshes as M
from bench_myriapoda.world import terrain_kernels as TK
from walking_hybrid import query_loop, time_walk_chunks, walker

N_POINTS = 100_000
NEAR_M = 0.01  # [m] points within this of the surface (the skull is about 2 m long)


def near_surface_points(mesh, n, near, seed=0, at_least=0.0):
    """n points at distances in [at_least, near] along the normal of random surface points, either side."""
    rng = np.random.default_rng(seed)
    idx = rng.integers(len(mesh.faces), size=n)
    bc = rng.dirichlet([1.0, 1.0, 1.0], size=n)
    surf = (mesh.triangles[idx] * bc[:, :, None]).sum(axis=1)
    off = rng.uniform(at_least, near, size=n) * rng.choice([-1.0, 1.0], size=n)
    return surf + mesh.face_normals[idx] * off[:, None]


def coherent(p, cell):
    key = np.floor((p - p.min(axis=0)) / cell).astype(np.int64)
    return np.ascontiguousarray(p[np.lexsort((key[:, 2], key[:, 1], key[:, 0]))])


@pytest.fixture(scope="module")
def skull():
    mesh = M.skull_mesh(M.SKULL_DEFAULT_SUBDIVISIONS)
    assert len(mesh.faces) >= 100_000
    return mesh, M.mesh_terrain_params(mesh)


@pytest.fixture(scope="module")
def plane_points():
    rng = np.random.default_rng(1)
    return np.column_stack([rng.uniform(-1, 1, N_POINTS), rng.uniform(-NEAR_M, NEAR_M, N_POINTS),
                            rng.uniform(-1, 1, N_POINTS)])


def _report(benchmark, name, n_tris):
    benchmark.extra_info["terrain"] = name
    benchmark.extra_info["triangles"] = n_tris
    benchmark.extra_info["points"] = N_POINTS
    if benchmark.stats is not None:  # None under --benchmark-disable (smoke run)
        benchmark.extra_info["ns_per_query"] = benchmark.stats.stats.median / N_POINTS * 1e9


def test_bench_query_plane(benchmark, plane_points):
    f = np.zeros(TK.N_TERRAIN_PARAMS)
    query_loop(TK.PLANE, f, plane_points[:10])  # compile / cache load
    acc = benchmark.pedantic(query_loop, args=(TK.PLANE, f, plane_points), rounds=20, warmup_rounds=2)
    assert np.isfinite(acc)
    _report(benchmark, "plane", 0)


@pytest.mark.parametrize("order,zone", [("random", "contact"), ("coherent", "contact"), ("coherent", "far")])
def test_bench_query_skull(benchmark, skull, order, zone):
    """zone contact: within NEAR_M (1 cm) of the surface, mostly the exact hash search; far: 3 to 10 cm
    (1 to 3 cells) away, mostly the interpolated far field."""
    mesh, f = skull
    if zone == "contact":
        p = near_surface_points(mesh, N_POINTS, NEAR_M)
    else:
        p = near_surface_points(mesh, N_POINTS, 0.1, at_least=0.03)
    if order == "coherent":
        p = coherent(p, M.mesh_stats(f)["cell_m"])
    query_loop(TK.MESH, f, p[:10])
    acc = benchmark.pedantic(query_loop, args=(TK.MESH, f, p), rounds=5, warmup_rounds=1)
    assert np.isfinite(acc)
    _report(benchmark, f"skull ({zone}, {order} order)", len(mesh.faces))
    benchmark.extra_info.update({k: v for k, v in M.mesh_stats(f).items() if k != "floats"})


# --------------------------------------------------------------------------- per step of a walk

SLAB_HALF_M = 25.0  # [m] half side of the closed slab the centipede walks on
SLAB_MAX_EDGE_M = 0.45  # [m]
WALK_IN_STEPS = 1500


def closed_slab_file(tmp_path_factory):
    """A closed box, 2 m thick, top face at y = 0, remeshed to >= 100,000 triangles (saved as .ply)."""
    import trimesh

    box = trimesh.creation.box(extents=(2 * SLAB_HALF_M, 2.0, 2 * SLAB_HALF_M))
    v, fc = trimesh.remesh.subdivide_to_size(box.vertices, box.faces, max_edge=SLAB_MAX_EDGE_M)
    mesh = trimesh.Trimesh(v - [0.0, 1.0, 0.0], fc, process=True)
    assert mesh.is_watertight and len(mesh.faces) >= 100_000
    path = tmp_path_factory.mktemp("slab") / "slab.ply"
    mesh.export(path)
    return path, len(mesh.faces)


@pytest.fixture(scope="module")
def slab(tmp_path_factory):
    return closed_slab_file(tmp_path_factory)


@pytest.mark.parametrize("ground", ["plane", "closed-mesh", "skull"])
def test_bench_walk_plane_vs_closed_mesh(benchmark, slab, ground):
    """Per step of the walking 18-segment hybrid centipede: flat ground, a flat-topped closed slab of
    >= 100,000 triangles, and the skull of scenario fig1-mesh (101,568 triangles, a curved dome)."""
    path, n_tris = slab
    scenario, overrides = "walk", []
    if ground == "closed-mesh":
        # the slab's triangles are 0.3 m on average: cells of 2 edges suit a body standing 0.6 m above it
        overrides = ["scenario.terrain=mesh", f"scenario.mesh={path}", "scenario.mesh_band_m=4.0",
                     "scenario.mesh_cell_edges=2.0"]
    elif ground == "skull":
        scenario, n_tris = "fig1-mesh", 101_568
    case, b = walker(["creature.segments=18", *overrides], scenario, walk_in_steps=WALK_IN_STEPS)
    benchmark.extra_info["terrain"] = ground
    benchmark.extra_info["triangles"] = n_tris if ground != "plane" else 0
    time_walk_chunks(benchmark, case, b, WALK_IN_STEPS, rounds=6)
