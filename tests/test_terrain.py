"""Terrain kinds answered inside numba: height field, obstacles, closed meshes (paper Sec. 5.1, 6.2).

References are independent of the kernels: dense sampling of the height field,
closed-form / trimesh box geometry for obstacles, and for closed meshes trimesh
(exact closest points over all triangles, ``mesh.contains``) with a
generalized winding number as the inside test where rtree (which
``mesh.contains`` needs) is not installed.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from bench_myriapoda.core.errors import InputError
from bench_myriapoda.core.schema import ScenarioConfig, check_section
from bench_myriapoda.world import meshes as M
from bench_myriapoda.world import terrain_kernels as TK
from bench_myriapoda.world.terrain import (random_cylinders, terrain_description, terrain_from_scenario)

try:
    import rtree  # noqa: F401  (trimesh's contains / proximity need it)
    HAVE_RTREE = True
except ImportError:
    HAVE_RTREE = False

HF_REL_TOL = 0.03        # first-order distance vs brute force, relative, for |d| <= 3 mm on slopes up to ~1.3
SAMPLE_ABS_TOL = 2e-6    # [m] dense-sampling error of the brute force reference
MESH_REL_TOL = 1e-9      # mesh distance vs trimesh, relative
NORMAL_FD_TOL = 1e-6


def phis(kind, f, p):
    return np.array([TK.signed_distance(kind, f, *q) for q in p])


def normals(kind, f, p):
    return np.array([TK.surface_normal(kind, f, *q) for q in p])


# --------------------------------------------------------------------------- height field

GAUSS = np.array([  # cx, cz, amplitude, width: steep enough (|grad h| up to ~1.3) that y - h is far from a distance
    [0.0, 0.0, 0.5, 0.35],
    [0.6, -0.3, -0.3, 0.25],
    [-0.5, 0.4, 0.4, 0.3],
    [0.3, 0.7, 0.25, 0.5],
])
GROUND = 0.1


@pytest.fixture(scope="module")
def hf():
    return TK.heightfield_params(GROUND, GAUSS[:, :2], GAUSS[:, 2], GAUSS[:, 3])


def h_direct(x, z):
    """h(x, z) written out from the Gaussians (independent of the packed layout)."""
    x, z = np.asarray(x, float), np.asarray(z, float)
    out = np.full(np.broadcast(x, z).shape, GROUND)
    for cx, cz, a, s in GAUSS:
        out = out + a * np.exp(-((x - cx) ** 2 + (z - cz) ** 2) / (2 * s * s))
    return out


def brute_distance(p, R):
    """Nearest-sample distance from p to the surface sampled densely within R of p horizontally."""
    n = 301
    xs = np.linspace(p[0] - R, p[0] + R, n)
    zs = np.linspace(p[2] - R, p[2] + R, n)
    X, Z = np.meshgrid(xs, zs, indexing="ij")
    Y = h_direct(X, Z)
    return np.sqrt((X - p[0]) ** 2 + (Y - p[1]) ** 2 + (Z - p[2]) ** 2).min()


def test_heightfield_height_matches_the_gaussian_mixture(hf):
    rng = np.random.default_rng(0)
    xz = rng.uniform(-1.2, 1.2, size=(200, 2))
    h = np.array([TK.heightfield_height(hf, x, z)[0] for x, z in xz])
    np.testing.assert_allclose(h, h_direct(xz[:, 0], xz[:, 1]), rtol=0, atol=1e-14)
    np.testing.assert_allclose(TK.heightfield_numpy(hf, xz[:, 0], xz[:, 1]), h, atol=1e-14)
    np.testing.assert_array_equal(TK.heightfield_gaussians(hf), GAUSS)


def test_heightfield_signed_distance_against_dense_sampling(hf):
    rng = np.random.default_rng(1)
    n = 120
    xz = rng.uniform(-0.9, 0.9, size=(n, 2))
    d = rng.uniform(2e-4, 3e-3, size=n) * rng.choice([-1.0, 1.0], size=n)
    h0 = h_direct(xz[:, 0], xz[:, 1])
    p = np.column_stack([xz[:, 0], h0 + d, xz[:, 1]])
    phi = phis(TK.HEIGHTFIELD, hf, p)
    ref = np.array([brute_distance(q, abs(dd) * 1.02) for q, dd in zip(p, d)])  # nearest point within |y - h|
    assert np.all(np.sign(phi) == np.sign(d)), "sign of phi must be the side of the surface"
    err = np.abs(np.abs(phi) - ref)
    assert np.all(err <= HF_REL_TOL * ref + SAMPLE_ABS_TOL), (err / ref).max()
    # the test has teeth: the vertical offset y - h is off by far more than the tolerance on the slopes
    assert np.max(np.abs(np.abs(d) - ref) / ref) > 5 * HF_REL_TOL


def test_heightfield_normal_matches_finite_differences(hf):
    rng = np.random.default_rng(2)
    xz = rng.uniform(-1.0, 1.0, size=(100, 2))
    y = h_direct(xz[:, 0], xz[:, 1]) + rng.uniform(-0.05, 0.05, size=100)
    p = np.column_stack([xz[:, 0], y, xz[:, 1]])
    n = normals(TK.HEIGHTFIELD, hf, p)
    e = 1e-6
    hx = (h_direct(xz[:, 0] + e, xz[:, 1]) - h_direct(xz[:, 0] - e, xz[:, 1])) / (2 * e)
    hz = (h_direct(xz[:, 0], xz[:, 1] + e) - h_direct(xz[:, 0], xz[:, 1] - e)) / (2 * e)
    ref = np.column_stack([-hx, np.ones_like(hx), -hz])
    ref /= np.linalg.norm(ref, axis=1)[:, None]
    np.testing.assert_allclose(n, ref, atol=NORMAL_FD_TOL)
    # on the surface phi's gradient is the normal (phi is the first-order distance there)
    ps = np.column_stack([xz[:, 0], h_direct(xz[:, 0], xz[:, 1]), xz[:, 1]])
    g = np.zeros_like(ps)
    for k in range(3):
        dp = np.zeros(3)
        dp[k] = 1e-6
        g[:, k] = (phis(TK.HEIGHTFIELD, hf, ps + dp) - phis(TK.HEIGHTFIELD, hf, ps - dp)) / 2e-6
    np.testing.assert_allclose(g, normals(TK.HEIGHTFIELD, hf, ps), atol=1e-5)


def test_heightfield_from_scenario_is_seeded():
    sc = ScenarioConfig(terrain="heightfield", heightfield_count=7, heightfield_amplitude_m=(-0.2, 0.4),
                        heightfield_width_m=(0.5, 1.5), heightfield_extent_m=3.0, terrain_seed=5, ground_height_m=0.2)
    k1, f1 = terrain_from_scenario(sc)
    k2, f2 = terrain_from_scenario(sc)
    assert k1 == TK.HEIGHTFIELD and np.array_equal(f1, f2)
    g = TK.heightfield_gaussians(f1)
    assert g.shape == (7, 4) and f1[0] == 0.2
    assert np.all(np.abs(g[:, :2]) <= 3.0) and np.all((g[:, 2] >= -0.2) & (g[:, 2] <= 0.4))
    assert np.all((g[:, 3] >= 0.5) & (g[:, 3] <= 1.5))
    _, f3 = terrain_from_scenario(ScenarioConfig(**{**sc.__dict__, "terrain_seed": 6}))
    assert not np.array_equal(f1, f3)
    d = terrain_description(sc)
    np.testing.assert_allclose(d.height(np.array([0.3]), np.array([-0.2])),
                               [TK.heightfield_height(f1, 0.3, -0.2)[0]], atol=1e-14)


# --------------------------------------------------------------------------- obstacles

CYL = (0.5, -0.2, 0.3, -0.1, 0.4)  # cx, cz, r, y_bottom, y_top
BOX = (-0.6, 0.15, 0.3, 0.4, 0.15, 0.2, math.radians(35.0))  # centre, half extents, yaw


@pytest.fixture(scope="module")
def obst():
    return TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(*CYL), TK.box_record(*BOX)])


def box_mesh():
    cx, cy, cz, hx, hy, hz, yaw = BOX
    T = np.eye(4)
    c, s = math.cos(yaw), math.sin(yaw)
    T[:3, :3] = [[c, 0, s], [0, 1, 0], [-s, 0, c]]  # rotation by yaw about +y
    T[:3, 3] = cx, cy, cz
    return trimesh.creation.box(extents=(2 * hx, 2 * hy, 2 * hz), transform=T)


def exact_mesh_distance(mesh, p):
    """Unsigned distance from each p to a mesh: closest points over all triangles (trimesh), chunked."""
    tri = mesh.triangles
    out = np.empty(len(p))
    for i, q in enumerate(p):
        c = trimesh.triangles.closest_point(tri, np.repeat(q[None, :], len(tri), axis=0))
        out[i] = np.linalg.norm(c - q, axis=1).min()
    return out


def test_obstacles_inside_outside_and_distance_match_geometry(obst):
    rng = np.random.default_rng(3)
    p = rng.uniform([-1.3, -0.2, -0.8], [1.2, 0.7, 0.6], size=(3000, 3))
    phi = phis(TK.PLANE, obst, p)
    cx, cz, r, yb, yt = CYL
    in_cyl = (np.hypot(p[:, 0] - cx, p[:, 2] - cz) < r) & (p[:, 1] > yb) & (p[:, 1] < yt)
    bm = box_mesh()
    lp = p - np.array(BOX[:3])
    c, s = math.cos(BOX[6]), math.sin(BOX[6])
    lx, lz = c * lp[:, 0] - s * lp[:, 2], s * lp[:, 0] + c * lp[:, 2]
    in_box = (np.abs(lx) < BOX[3]) & (np.abs(lp[:, 1]) < BOX[4]) & (np.abs(lz) < BOX[5])
    inside = in_cyl | in_box | (p[:, 1] < 0.0)
    assert in_cyl.sum() > 50 and in_box.sum() > 50
    np.testing.assert_array_equal(phi < 0, inside)
    if HAVE_RTREE:
        np.testing.assert_array_equal(bm.contains(p), in_box)
    # exact distance outside everything: min(plane, cylinder, box) with the box from trimesh triangles
    out = np.flatnonzero(~inside)[:300]
    q = p[out]
    rho = np.hypot(q[:, 0] - cx, q[:, 2] - cz)
    dr, dy = rho - r, np.maximum(yb - q[:, 1], q[:, 1] - yt)
    d_cyl = np.where((dr > 0) & (dy > 0), np.hypot(dr, dy), np.maximum(dr, dy))
    ref = np.minimum(np.minimum(q[:, 1], d_cyl), exact_mesh_distance(bm, q))
    np.testing.assert_allclose(phi[out], ref, rtol=0, atol=1e-12)


def test_obstacle_normals_are_unit_gradients(obst):
    rng = np.random.default_rng(4)
    p = rng.uniform([-1.3, 0.05, -0.8], [1.2, 0.7, 0.6], size=(400, 3))
    phi = phis(TK.PLANE, obst, p)
    p = p[np.abs(phi) > 1e-3]
    n = normals(TK.PLANE, obst, p)
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-12)
    g = np.zeros_like(p)
    for k in range(3):
        dp = np.zeros(3)
        dp[k] = 1e-7
        g[:, k] = (phis(TK.PLANE, obst, p + dp) - phis(TK.PLANE, obst, p - dp)) / 2e-7
    ok = np.abs(np.linalg.norm(g, axis=1) - 1.0) < 1e-4  # away from creases, where phi is not differentiable
    assert ok.mean() > 0.9
    np.testing.assert_allclose(n[ok], g[ok], atol=1e-4)


def obstacle_scenario(seed=3, **kw):
    base = dict(terrain="plane", obstacle_cylinders=25, obstacle_radius_m=(0.1, 0.3), obstacle_height_m=(0.05, 0.2),
                obstacle_region_m=(-3.0, 3.0, -2.0, 2.0), obstacle_clear_radius_m=1.0, terrain_seed=seed)
    base.update(kw)
    return ScenarioConfig(**base)


def test_random_cylinders_are_reproducible_and_keep_the_start_clear():
    a, b, c = (random_cylinders(obstacle_scenario(s)) for s in (3, 3, 4))
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)
    for cyl in (a, c):
        assert cyl.shape == (25, 4)
        assert np.all(np.hypot(cyl[:, 0], cyl[:, 1]) - cyl[:, 2] >= 1.0)
        assert np.all((cyl[:, 0] >= -3) & (cyl[:, 0] <= 3) & (cyl[:, 1] >= -2) & (cyl[:, 1] <= 2))
        assert np.all((cyl[:, 2] >= 0.1) & (cyl[:, 2] <= 0.3) & (cyl[:, 3] >= 0.05) & (cyl[:, 3] <= 0.2))
    kind, f = terrain_from_scenario(obstacle_scenario(3))
    assert kind == TK.PLANE and f[TK.H_NOBST] == 25
    d = terrain_description(obstacle_scenario(3))
    np.testing.assert_allclose([(o["x"], o["z"], o["radius"], o["y_top"]) for o in d.cylinders],
                               np.column_stack([a[:, :3], a[:, 3]]))
    # the start area is plain ground: within 0.5 m of the origin and below 0.3 m (nearer the ground than any
    # cylinder, all >= 1 m away) phi is the plane's
    rng = np.random.default_rng(5)
    ang, rad = rng.uniform(0, 2 * np.pi, 200), rng.uniform(0, 0.5, 200)
    p = np.column_stack([rad * np.cos(ang), rng.uniform(0.0, 0.3, 200), rad * np.sin(ang)])
    np.testing.assert_array_equal(phis(kind, f, p), p[:, 1])
    # and the cylinders are there: just inside each one's top centre
    tops = np.column_stack([a[:, 0], a[:, 3] - 1e-3, a[:, 1]])
    assert np.all(phis(kind, f, tops) < 0)


def test_obstacles_stand_on_a_heightfield_and_explicit_lists():
    sc = ScenarioConfig(terrain="heightfield", heightfield_count=5, heightfield_extent_m=2.0, terrain_seed=2,
                        obstacle_cylinder_list=(1.0, 0.5, 0.2, 0.3), obstacle_box_list=(-1.0, 0.1, 0.0, 0.3, 0.1, 0.2, 45))
    kind, f = terrain_from_scenario(sc)
    assert kind == TK.HEIGHTFIELD and f[TK.H_NOBST] == 2
    d = terrain_description(sc)
    (cyl,), (box,) = d.cylinders, d.boxes
    h_c = TK.heightfield_height(f, 1.0, 0.5)[0]
    assert cyl["y_top"] == pytest.approx(h_c + 0.3) and cyl["y_bottom"] < h_c - 0.2
    assert box["centre"][1] == pytest.approx(TK.heightfield_height(f, -1.0, 0.0)[0] + 0.1)
    assert box["yaw_deg"] == pytest.approx(45.0)
    assert TK.signed_distance(kind, f, 1.0, h_c + 0.3 + 0.01, 0.5) == pytest.approx(0.01, abs=1e-12)
    assert TK.surface_normal(kind, f, 1.0, h_c + 0.3 + 0.01, 0.5) == pytest.approx((0.0, 1.0, 0.0))


# --------------------------------------------------------------------------- closed meshes

def winding_inside(mesh, p):
    """Generalized winding number > 1/2 (exact inside test for a closed, outward-wound mesh)."""
    tri = mesh.triangles
    out = np.empty(len(p), dtype=bool)
    for i, q in enumerate(p):
        a, b, c = tri[:, 0] - q, tri[:, 1] - q, tri[:, 2] - q
        la, lb, lc = (np.linalg.norm(v, axis=1) for v in (a, b, c))
        num = np.einsum("ij,ij->i", a, np.cross(b, c))
        den = la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", a, c) * lb \
            + np.einsum("ij,ij->i", b, c) * la
        out[i] = np.sum(2 * np.arctan2(num, den)) / (4 * np.pi) > 0.5
    return out


def reference_inside(mesh, p):
    return mesh.contains(p) if HAVE_RTREE else winding_inside(mesh, p)


def band_points(mesh, band, n, seed):
    rng = np.random.default_rng(seed)
    idx = rng.integers(len(mesh.faces), size=n)
    bc = rng.dirichlet([1.0, 1.0, 1.0], size=n)
    surf = (mesh.triangles[idx] * bc[:, :, None]).sum(axis=1)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    return surf + d * rng.uniform(0.0, band, size=n)[:, None]


MESHES = {
    "icosphere": lambda: trimesh.Trimesh(*(lambda m: (m.vertices * 0.5 + [0.2, 0.6, -0.1], m.faces))(
        trimesh.creation.icosphere(subdivisions=3)), process=False),
    "skull": lambda: M.transformed(M.skull_mesh(14), 0.7, (0.0, 0.9, 0.3)),
    "spiky": lambda: spiky_mesh(),
}


def spiky_mesh():
    """A star-shaped ball with random radii per vertex: sharp ridges and deep creases, where a face normal
    gives the wrong side and only the pseudo-normal of the closest edge or vertex is right."""
    m = trimesh.creation.icosphere(subdivisions=2)
    r = np.random.default_rng(21).uniform(0.45, 1.0, size=len(m.vertices))
    return trimesh.Trimesh(m.vertices * r[:, None], m.faces, process=False)


@pytest.fixture(scope="module", params=sorted(MESHES))
def mesh_case(request):
    """A mesh and its terrain with the exact band as wide as the band (every distance in it exact)."""
    mesh = MESHES[request.param]()
    f = M.mesh_terrain_params(mesh, exact_cells=np.inf)
    return request.param, mesh, f


def test_mesh_hash_against_trimesh(mesh_case):
    name, mesh, f = mesh_case
    assert mesh.is_watertight
    band = M.mesh_stats(f)["band_m"]
    assert M.mesh_stats(f)["exact_band_m"] == band
    p = band_points(mesh, 2.0 * band, 400, seed=7)
    phi = phis(TK.MESH, f, p)
    n = normals(TK.MESH, f, p)
    dist = exact_mesh_distance(mesh, p)
    inside = reference_inside(mesh, p)
    inb = dist < band * (1 - 1e-9)
    assert inb.sum() > 200 and (~inb).sum() > 5
    np.testing.assert_allclose(np.abs(phi[inb]), dist[inb], rtol=MESH_REL_TOL, atol=0)
    np.testing.assert_array_equal(phi < 0, inside)  # 100 % sign agreement, in and beyond the band
    np.testing.assert_array_equal(np.abs(phi[~inb]), band)  # clamped beyond the band
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-12)
    # the normal points from the closest point to p: p - phi n lies on the surface, at trimesh's closest point
    q = p[inb] - phi[inb, None] * n[inb]
    assert np.abs(phis(TK.MESH, f, q)).max() < 1e-12
    if HAVE_RTREE:
        cp, d_tm, _ = trimesh.proximity.closest_point(mesh, p[inb])
        # trimesh's rtree candidate search can miss the nearest triangle; the hash never does worse
        assert np.all(np.abs(phi[inb]) <= d_tm * (1 + MESH_REL_TOL))
        np.testing.assert_allclose(np.abs(trimesh.proximity.signed_distance(mesh, p[inb])), d_tm, rtol=1e-12)


@pytest.mark.parametrize("name", sorted(MESHES) + ["skull-30"])
def test_mesh_default_exact_near_the_surface_and_interpolated_beyond(name):
    """Default: exact within the exact band (a quarter cell), the corner samples' trilinear far field beyond."""
    mesh = M.skull_mesh(30) if name == "skull-30" else MESHES[name]()
    f = M.mesh_terrain_params(mesh)
    st = M.mesh_stats(f)
    band, exact, h = st["band_m"], st["exact_band_m"], st["cell_m"]
    assert exact == pytest.approx(M.DEFAULT_EXACT_CELLS * h)
    p = np.concatenate([band_points(mesh, 1.5 * exact, 250, seed=13), band_points(mesh, 1.3 * band, 250, seed=14)])
    phi = phis(TK.MESH, f, p)
    dist = exact_mesh_distance(mesh, p)
    near = dist < exact * (1 - 1e-9)
    far = (dist >= exact) & (dist < band * (1 - 1e-9))
    assert near.sum() > 100 and far.sum() > 100
    np.testing.assert_allclose(np.abs(phi[near]), dist[near], rtol=MESH_REL_TOL, atol=0)
    np.testing.assert_array_equal(phi < 0, reference_inside(mesh, p))  # signs exact everywhere
    err = np.abs(np.abs(phi[far]) - dist[far])
    assert err.max() <= 0.5 * h  # (the 1-Lipschitz worst case is sqrt(3) h)
    if name == "skull-30":  # a mesh finer than the cells: the far field is accurate
        assert np.median(err / dist[far]) < 0.02 and err.max() < 0.25 * h
    assert np.all(np.abs(phi) <= band)
    np.testing.assert_allclose(np.linalg.norm(normals(TK.MESH, f, p), axis=1), 1.0, atol=1e-12)


def test_mesh_far_points_and_down(mesh_case):
    name, mesh, f = mesh_case
    band = M.mesh_stats(f)["band_m"]
    c = mesh.vertices.mean(axis=0)
    lo, hi = mesh.bounds
    far_out = np.array([[c[0], hi[1] + 5 * band, c[2]], [lo[0] - 100.0, c[1], c[2]], [np.inf, 0, 0]])
    assert np.all(phis(TK.MESH, f, far_out) == band)
    deep = mesh.centroid  # inside each of these meshes: -min(distance, band)
    d_deep = exact_mesh_distance(mesh, deep[None, :])[0]
    assert TK.signed_distance(TK.MESH, f, *deep) == pytest.approx(-min(d_deep, band), rel=1e-12)
    if name == "icosphere":
        assert d_deep > band  # the clamped case is covered
    p = band_points(mesh, band, 50, seed=8)
    for q in p:
        dn = np.array(TK.mesh_down(f, *q))
        np.testing.assert_allclose(dn, -np.array(TK.surface_normal(TK.MESH, f, *q)), atol=0)
        np.testing.assert_allclose(dn, np.array(TK.terrain_down(TK.MESH, f, *q)), atol=0)


def test_mesh_with_ground_plane_and_inverted_winding():
    mesh = MESHES["icosphere"]()
    f = M.mesh_terrain_params(mesh, ground_m=0.3)
    assert TK.signed_distance(TK.MESH, f, 2.0, 0.5, 2.0) == pytest.approx(0.2)
    assert TK.surface_normal(TK.MESH, f, 2.0, 0.5, 2.0) == (0.0, 1.0, 0.0)
    flipped = M.mesh_terrain_params((mesh.vertices, mesh.faces[:, ::-1]))  # inside out: flipped back
    p = band_points(mesh, 0.1, 50, seed=9)
    np.testing.assert_array_equal(phis(TK.MESH, flipped, p), phis(TK.MESH, M.mesh_terrain_params(mesh), p))


def test_skull_is_closed_and_large_at_the_default_resolution():
    small = M.skull_mesh(10)
    assert len(small.faces) == 1200 and small.is_watertight and small.is_winding_consistent and small.volume > 0
    v, fc = M._skull_arrays(M.SKULL_DEFAULT_SUBDIVISIONS)
    assert len(fc) == 12 * M.SKULL_DEFAULT_SUBDIVISIONS ** 2 >= 100_000
    M.check_closed(v, fc)  # watertight, consistently and outward wound, no degenerate triangles
    np.testing.assert_array_equal(M.skull_mesh(10).vertices, small.vertices)  # deterministic


def test_non_watertight_mesh_raises_a_clear_error(tmp_path):
    mesh = trimesh.creation.icosphere(subdivisions=2)
    holed = trimesh.Trimesh(mesh.vertices, mesh.faces[1:], process=False)
    with pytest.raises(M.MeshError, match="not watertight"):
        M.mesh_terrain_params(holed)
    path = tmp_path / "holed.stl"
    holed.export(path)
    with pytest.raises(M.MeshError, match="not watertight"):
        M.load_closed_mesh(path)
    with pytest.raises(InputError) as exc:
        check_section(ScenarioConfig, {"mesh": str(path)}, "s.toml", "scenario")
    assert exc.value.key == "scenario.mesh" and "not watertight" in str(exc.value)
    ok = tmp_path / "ball.obj"
    mesh.export(ok)
    m = M.load_closed_mesh(ok, scale=2.0, translate=(0.0, 1.0, 0.0))
    np.testing.assert_allclose(m.bounds, mesh.bounds * 2.0 + [0.0, 1.0, 0.0], atol=1e-9)


def test_mesh_terrain_from_scenario():
    sc = ScenarioConfig(terrain="mesh", mesh="skull", mesh_subdivisions=12, mesh_scale=2.0,
                        mesh_translate_m=(0.0, 1.5, 0.0), mesh_ground=True, ground_height_m=-0.5,
                        obstacle_cylinder_list=(4.0, 0.0, 0.3, 0.5))
    kind, f = terrain_from_scenario(sc)
    assert kind == TK.MESH and f[TK.H_NOBST] == 1 and f[0] == -0.5 and f[1] == 1.0
    d = terrain_description(sc)
    v, faces = d.mesh
    assert len(faces) == 12 * 12 ** 2 and d.ground_height_m == -0.5
    np.testing.assert_allclose(v, M.skull_mesh(12).vertices * 2.0 + [0, 1.5, 0], atol=1e-12)
    assert d.cylinders[0]["y_top"] == pytest.approx(0.0)  # stands on the ground plane
    assert TK.signed_distance(kind, f, 0.0, 1.5, 0.0) < 0  # inside the skull
    top = v[:, 1].max()
    assert TK.signed_distance(kind, f, *v[np.argmax(v[:, 1])] + [0, 0.01, 0]) == pytest.approx(0.01, abs=1e-3)
    assert top > 2.5


# --------------------------------------------------------------------------- path crossings

def crossing_cases():
    hf = TK.heightfield_params(GROUND, GAUSS[:, :2], GAUSS[:, 2], GAUSS[:, 3])
    obst = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(*CYL), TK.box_record(*BOX)])
    mesh = MESHES["skull"]()
    return [("heightfield", TK.HEIGHTFIELD, hf, None), ("obstacles", TK.PLANE, obst, None),
            ("mesh", TK.MESH, M.mesh_terrain_params(mesh), mesh),
            ("slope+obstacles", TK.SLOPE, TK.with_obstacles(TK.header(0.0, 0.2), [TK.cylinder_record(*CYL)]), None)]


@pytest.mark.parametrize("case", crossing_cases(), ids=lambda c: c[0])
def test_path_surface_fraction_finds_the_crossing(case):
    name, kind, f, mesh = case
    rng = np.random.default_rng(11)
    found = 0
    for _ in range(4000):
        if mesh is not None:
            p0 = band_points(mesh, 0.08, 1, seed=int(rng.integers(1 << 30)))[0]
        else:
            p0 = rng.uniform([-1.0, -0.1, -0.8], [1.0, 0.6, 0.6])
        p1 = p0 + rng.normal(size=3) * 0.05
        phi0, phi1 = TK.signed_distance(kind, f, *p0), TK.signed_distance(kind, f, *p1)
        if not (phi0 > 0 > phi1):
            continue
        s = TK.path_surface_fraction(kind, f, *p0, *p1, phi0, phi1)
        assert 0.0 <= s <= 1.0
        q = p0 + s * (p1 - p0)
        assert abs(TK.signed_distance(kind, f, *q)) < 1e-9, (name, p0, p1, s)
        assert TK.segment_surface_intersection(kind, f, *p0, *p1) == s
        found += 1
        if found == 60:
            break
    assert found == 60


# --------------------------------------------------------------------------- scenario keys

@pytest.mark.parametrize("key,value,expected", [
    ("terrain", "moon", "heightfield, mesh"),
    ("heightfield_amplitude_m", [0.5, 0.1], "lo <= hi"),
    ("heightfield_width_m", [0.0, 1.0], "> 0.0"),
    ("heightfield_width_m", [1.0], "exactly 2"),
    ("heightfield_count", -1, ">= 0"),
    ("heightfield_extent_m", 0.0, "> 0.0"),
    ("terrain_seed", -3, ">= 0"),
    ("mesh", "no/such/file.stl", "file not found"),
    ("mesh_scale", 0.0, "> 0.0"),
    ("mesh_translate_m", [0.0, 1.0], "exactly 3"),
    ("mesh_subdivisions", 0, ">= 1"),
    ("obstacle_cylinders", 1.5, "integer"),
    ("obstacle_radius_m", [0.3, -0.1], "lo <= hi"),
    ("obstacle_height_m", "tall", "list of numbers"),
    ("obstacle_region_m", [1.0, 0.0, -1.0, 1.0], "x_min < x_max"),
    ("obstacle_clear_radius_m", -1.0, ">= 0"),
    ("obstacle_cylinder_list", [1.0, 2.0, 3.0], "groups of 4"),
    ("obstacle_cylinder_list", [1.0, 2.0, 0.0, 1.0], "radius and height"),
    ("obstacle_box_list", [0, 0, 0, 1, 0, 1, 0], "half extents"),
])
def test_bad_terrain_keys_raise_input_error_naming_the_key(key, value, expected):
    with pytest.raises(InputError) as exc:
        check_section(ScenarioConfig, {key: value}, "scn.toml", "scenario")
    assert exc.value.key == f"scenario.{key}" and expected in str(exc.value), str(exc.value)
    assert str(exc.value).startswith("scn.toml: scenario." + key)


def test_bad_terrain_key_on_the_command_line_exits_2(capsys, tmp_path, monkeypatch):
    from bench_myriapoda.cli import main

    monkeypatch.chdir(tmp_path)
    code = main(["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat",
                 "--set", "scenario.heightfield_width_m=[2.0, 1.0]"])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "scenario.heightfield_width_m" in err and "lo <= hi" in err
    assert list(tmp_path.iterdir()) == []


def test_random_cylinders_with_no_room_raise_input_error():
    sc = obstacle_scenario(obstacle_region_m=(-1.0, 1.0, -1.0, 1.0), obstacle_clear_radius_m=5.0)
    with pytest.raises(InputError, match="obstacle_clear_radius_m"):
        terrain_from_scenario(sc)


# --------------------------------------------------------------------------- old kinds unchanged

def test_plane_slope_slab_unchanged_and_short_vectors_still_work():
    rng = np.random.default_rng(12)
    p = rng.uniform(-1, 1, size=(200, 3))
    for kind, f in ((TK.PLANE, [0.1] + [0.0] * 7), (TK.SLOPE, [0.0, 0.5] + [0.0] * 6),
                    (TK.SLAB, [0.0, 0.3, 0.2, 0.05, 0, 0, 0, 0])):
        f = np.array(f)
        np.testing.assert_allclose(phis(kind, f, p), TK.terrain_phi_numpy(kind, f, p), rtol=0, atol=1e-15)
    f = np.array([0.0, 0.5] + [0.0] * 6)
    np.testing.assert_allclose(normals(TK.SLOPE, f, p), np.tile([-math.sin(0.5), math.cos(0.5), 0.0], (200, 1)))
    k, f = terrain_from_scenario(ScenarioConfig(terrain="slab"))
    assert k == TK.SLAB and len(f) == TK.N_TERRAIN_PARAMS and f[TK.H_NOBST] == 0


def test_flat_ground_is_the_plane_without_obstacles_and_its_height_gives_signed_distance_bit_for_bit(obst, hf):
    # flat_ground lets a hot loop compute a point's distance itself (y - h) where the terrain is the plane
    # without obstacles: there it must be signed_distance's value to the last bit; every other terrain
    # (slope, slab, height field, the plane with obstacles) must say not flat, so the loop asks signed_distance.
    rng = np.random.default_rng(13)
    p = rng.uniform(-2, 2, size=(500, 3))
    for height in (0.0, 0.37, -1.25):
        f = TK.header(height)
        flat, h = TK.flat_ground(TK.PLANE, f)
        assert flat and h == height
        assert np.array_equal(p[:, 1] - h, phis(TK.PLANE, f, p))
    for kind, f in ((TK.SLOPE, np.array([0.0, 0.5] + [0.0] * 6)), (TK.SLAB, np.array([0.0, 0.3, 0.2, 0.05, 0, 0, 0, 0])),
                    (TK.HEIGHTFIELD, hf), (TK.PLANE, obst)):
        assert not TK.flat_ground(kind, f)[0], kind


def test_rigid_box_rests_on_a_cylinder_obstacle_through_the_full_parameter_vector():
    """RigidBoxes.advance takes a full vector (header + obstacle block), not just an 8-value header."""
    from bench_myriapoda.bodies.rigid import ContactSettings, RigidBoxes

    top = 0.3
    f = TK.with_obstacles(TK.header(0.0), [TK.cylinder_record(0.0, 0.0, 0.5, -0.5, top)])
    assert len(f) > TK.N_TERRAIN_PARAMS
    half = (0.1, 0.05, 0.1)
    boxes = RigidBoxes([half], [1.0])
    boxes.set_pose(0, c=[0.0, top + 0.2, 0.0])
    n_done, status = boxes.advance(3000, 1.0 / 3000.0, terrain_kind=TK.PLANE, terrain_params=f,
                                   contact=ContactSettings(friction=0.5, restitution=0.0))
    assert status == 0 and n_done == 3000
    assert boxes.c[0, 1] == pytest.approx(top + half[1], abs=2e-3)  # on the cylinder, not the ground
    assert np.abs(boxes.v[0]).max() < 1e-3
