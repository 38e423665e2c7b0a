"""Closed triangle meshes as terrains (paper Sec. 5.1, 6.2, Fig. 1).

* ``skull_mesh(subdivisions)``: a procedurally generated, closed, skull-like
  mesh shipped with the project (no download): a spherified cube with
  ``subdivisions`` cells per cube edge (12 subdivisions^2 triangles), its
  vertices moved radially to a skull-like star-shaped surface: an ellipsoidal
  cranium, a brow ridge, two deep eye sockets, a nasal dent, cheekbones, a
  jaw bulge and a flattened base.  Star-shaped (every vertex is r(u) u with
  r > 0 a smooth function of the direction u), so it is watertight and free of
  self-intersections at every resolution.  Facing +x, y up, about 2 m long
  (x in [-1, 1] roughly) at scale 1; ``mesh_scale`` scales it.
* ``load_closed_mesh(path, scale, translate)``: any mesh file trimesh loads;
  it must be watertight and consistently wound (else ``MeshError``); an
  inside-out mesh is flipped.
* ``mesh_block(vertices, faces)``: the spatial hash the numba queries use
  (layout and query zones in ``terrain_kernels``): a uniform grid of cells of
  ``cell_edges`` mean edge lengths, each listing the triangles whose bounding
  box overlaps it, built once per mesh; plus per triangle its face and edge
  pseudo-normals, per vertex its angle-weighted pseudo-normal (Baerentzen &
  Aanaes 2005), per cell the side (inside/outside) of its centre and its
  Chebyshev distance to the nearest occupied cell, and per grid corner the
  signed distance and nearest triangle (the far field).  About 3 s for the
  default 101,568-triangle skull.
* ``mesh_terrain_params(...)``: the terrain vector f of kind MESH.

Far-field corners: corners of occupied cells get exact hash queries; the
others take the nearest of their neighbours' nearest triangles, propagated by
fast sweeping (exact except next to the medial axis, and always an upper
bound), with the side of the empty cells around them (a flood fill of the empty
cells from the grid boundary; enclosed empty regions take the side of one exact
query).
"""
from __future__ import annotations

import functools
import math

import numpy as np
from numba import njit

# a mesh file's loading and checking runs while a scenario is loaded (``core.schema``), so it lives in the core;
# re-exported here, where the terrain builders and the tests have always found it
from ..core.mesh_files import MeshError, check_closed, load_closed_mesh, mesh_file_problem, transformed  # noqa: F401
from . import terrain_kernels as TK

SKULL_DEFAULT_SUBDIVISIONS = 92  # 12 * 92^2 = 101,568 triangles
# Hash cell size in mean edge lengths.  Smaller cells tighten the far-field bound, so points a few
# decimetres off the surface (a walking body's box corners and nodes) take the cheap interpolated
# distance instead of the exact search: measured on the 18-segment centipede walking over the 101,568-
# triangle skull, 2.0 gave 2.4x the flat-ground time per step, 1.4 gave 1.5x (13 s to build the hash
# instead of 7 s), 1.0 gave 1.6x (40 s).
DEFAULT_CELL_EDGES = 1.4
DEFAULT_BAND_FRACTION = 0.1  # default band: this fraction of the bounding-box diagonal
DEFAULT_EXACT_CELLS = 0.25  # exact band in cells: nearer the surface than this, phi is the exact distance


# --------------------------------------------------------------------------- the skull

def _cube_sphere(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Unit sphere from a cube with n x n cells per face, two triangles per cell; outward winding."""
    if n < 1:
        raise ValueError("subdivisions must be >= 1")
    t = np.linspace(-1.0, 1.0, n + 1)
    faces_def = [  # (normal, U, V) with U x V = normal
        ((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0)),
    ]
    uu, vv = np.meshgrid(t, t, indexing="ij")
    pts, tris = [], []
    idx = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    for k, (N, U, V) in enumerate(faces_def):
        N, U, V = (np.array(w, dtype=float) for w in (N, U, V))
        p = N[None, :] + uu.reshape(-1, 1) * U[None, :] + vv.reshape(-1, 1) * V[None, :]
        off = k * (n + 1) ** 2
        pts.append(p)
        tris.append(np.column_stack([a, b, c]) + off)
        tris.append(np.column_stack([a, c, d]) + off)
    p = np.concatenate(pts)
    f = np.concatenate(tris)
    # seam vertices are bitwise equal (same linspace values, exact +-1): merge them
    uniq, inv = np.unique(p, axis=0, return_inverse=True)
    f = inv.reshape(-1)[f]
    x, y, z = uniq[:, 0], uniq[:, 1], uniq[:, 2]
    # spherified cube: near-uniform triangles (x' = x sqrt(1 - y^2/2 - z^2/2 + y^2 z^2 / 3), ...)
    s = np.column_stack([
        x * np.sqrt(1 - y * y / 2 - z * z / 2 + y * y * z * z / 3),
        y * np.sqrt(1 - z * z / 2 - x * x / 2 + z * z * x * x / 3),
        z * np.sqrt(1 - x * x / 2 - y * y / 2 + x * x * y * y / 3),
    ])
    s /= np.linalg.norm(s, axis=1)[:, None]
    return s, f.astype(np.int64)


def _bump(u: np.ndarray, centre, width: float, scale=(1.0, 1.0, 1.0)) -> np.ndarray:
    """Smooth bump on the unit sphere: exp(-|S (u - c)|^2 / (2 w^2)), c normalised, S diagonal."""
    c = np.asarray(centre, dtype=float)
    c = c / np.linalg.norm(c)
    d = (u - c[None, :]) * np.asarray(scale, dtype=float)[None, :]
    return np.exp(-np.einsum("ij,ij->i", d, d) / (2.0 * width * width))


def skull_radius(u: np.ndarray) -> np.ndarray:
    """Radius r(u) > 0 of the skull surface along unit directions u (n, 3): +x front, +y up, z sideways."""
    ux, uy, uz = u[:, 0], u[:, 1], u[:, 2]
    ax, ay, az = 1.0, 0.82, 0.74  # cranium half-lengths
    r = 1.0 / np.sqrt((ux / ax) ** 2 + (uy / ay) ** 2 + (uz / az) ** 2)
    r += 0.10 * _bump(u, (-0.5, 0.8, 0.0), 0.45)                           # high, rounded back of the cranium
    r += 0.07 * _bump(u, (0.93, 0.30, 0.0), 0.07, scale=(1.0, 1.0, 0.22))  # brow ridge (long in z)
    for side in (1.0, -1.0):
        r -= 0.26 * _bump(u, (0.86, 0.06, 0.36 * side), 0.13)               # eye sockets
        r += 0.06 * _bump(u, (0.55, -0.12, 0.80 * side), 0.16)              # cheekbones
        r -= 0.05 * _bump(u, (0.05, 0.25, 1.0 * side), 0.22)                # temporal dents
        r += 0.08 * _bump(u, (0.45, -0.70, 0.45 * side), 0.20)              # jaw angles
    r -= 0.10 * _bump(u, (1.0, -0.16, 0.0), 0.06, scale=(1.0, 0.7, 1.4))    # nasal opening
    r += 0.16 * _bump(u, (0.78, -0.60, 0.0), 0.24, scale=(1.0, 1.0, 0.7))   # jaw / teeth bulge
    base = np.clip((-uy - 0.55) / 0.45, 0.0, 1.0)
    r *= 1.0 - 0.22 * base * base * (3.0 - 2.0 * base)                      # flattened base
    return r


@functools.lru_cache(maxsize=4)
def _skull_arrays(subdivisions: int) -> tuple[np.ndarray, np.ndarray]:
    u, faces = _cube_sphere(int(subdivisions))
    v = u * skull_radius(u)[:, None]
    v.setflags(write=False)
    faces.setflags(write=False)
    return v, faces


def skull_mesh(subdivisions: int = SKULL_DEFAULT_SUBDIVISIONS):
    """The procedural closed skull as a ``trimesh.Trimesh`` with 12 subdivisions^2 triangles (deterministic)."""
    import trimesh

    v, faces = _skull_arrays(int(subdivisions))
    return trimesh.Trimesh(vertices=v.copy(), faces=faces.copy(), process=False)


# --------------------------------------------------------------------------- the spatial hash

@njit(cache=True)
def _tri_cell_range(tri, t, ox, oy, oz, invh, nx, ny, nz, eps):
    """Inclusive cell index ranges (i0, i1, j0, j1, k0, k1) that triangle t's bounding box, widened by
    eps [m], overlaps; tri: (T, 9) corner coordinates a, b, c."""
    lo0 = min(tri[t, 0], min(tri[t, 3], tri[t, 6])) - eps
    hi0 = max(tri[t, 0], max(tri[t, 3], tri[t, 6])) + eps
    lo1 = min(tri[t, 1], min(tri[t, 4], tri[t, 7])) - eps
    hi1 = max(tri[t, 1], max(tri[t, 4], tri[t, 7])) + eps
    lo2 = min(tri[t, 2], min(tri[t, 5], tri[t, 8])) - eps
    hi2 = max(tri[t, 2], max(tri[t, 5], tri[t, 8])) + eps
    return (max(int(math.floor((lo0 - ox) * invh)), 0), min(int(math.floor((hi0 - ox) * invh)), nx - 1),
            max(int(math.floor((lo1 - oy) * invh)), 0), min(int(math.floor((hi1 - oy) * invh)), ny - 1),
            max(int(math.floor((lo2 - oz) * invh)), 0), min(int(math.floor((hi2 - oz) * invh)), nz - 1))


@njit(cache=True)
def _count_cells(tri, ox, oy, oz, invh, nx, ny, nz, eps, counts):
    for t in range(tri.shape[0]):
        i0, i1, j0, j1, k0, k1 = _tri_cell_range(tri, t, ox, oy, oz, invh, nx, ny, nz, eps)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                for k in range(k0, k1 + 1):
                    counts[(i * ny + j) * nz + k] += 1


@njit(cache=True)
def _fill_cells(tri, ox, oy, oz, invh, nx, ny, nz, eps, starts, fill, lst):
    for t in range(tri.shape[0]):
        i0, i1, j0, j1, k0, k1 = _tri_cell_range(tri, t, ox, oy, oz, invh, nx, ny, nz, eps)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                for k in range(k0, k1 + 1):
                    c = (i * ny + j) * nz + k
                    lst[starts[c] + fill[c]] = t
                    fill[c] += 1


@njit(cache=True)
def _signs_at(f, m, pts, out):
    """Sign of the exact (unclamped) signed distance at pts (n, 3)."""
    for i in range(pts.shape[0]):
        phi = TK.mesh_exact(f, m, pts[i, 0], pts[i, 1], pts[i, 2], np.inf, -1)[0]
        out[i] = 1.0 if phi >= 0.0 else -1.0


@njit(cache=True)
def _corner_values(f, m, ox, oy, oz, h, nx, ny, nz, band, counts, side, ring, out):
    """Signed distance, clamped to +-band, and nearest triangle (-1: none found) at every grid corner.

    Corner (i, j, k) is out[2 c], out[2 c + 1] with c = (i*(ny+1) + j)*(nz+1) + k.

    Corners of occupied cells: exact (``mesh_exact``).  The others: the distance
    to the nearest triangle among those nearest to their neighbours, propagated
    by fast sweeping in the 8 diagonal orders until nothing changes (exact
    unless the nearest triangle of a corner is nearest to none of its
    neighbours, which happens only next to the medial axis), with the side of
    the empty cells around them.  Corners farther than band + 2 cells from any
    occupied cell are +-band at once.
    """
    nyc, nzc = ny + 1, nz + 1
    nc = (nx + 1) * nyc * nzc
    best = np.full(nc, np.inf)
    tri = np.full(nc, -1, dtype=np.int64)
    near = np.zeros(nc, dtype=np.bool_)
    active = np.zeros(nc, dtype=np.bool_)
    cside = np.ones(nc)
    far_ring = band / h + 2.0
    for i in range(nx + 1):
        for j in range(ny + 1):
            for k in range(nz + 1):
                c = (i * nyc + j) * nzc + k
                occ = False
                rmin = 1e18
                for a in range(max(i - 1, 0), min(i, nx - 1) + 1):
                    for b in range(max(j - 1, 0), min(j, ny - 1) + 1):
                        for d in range(max(k - 1, 0), min(k, nz - 1) + 1):
                            cell = (a * ny + b) * nz + d
                            if counts[cell] > 0:
                                occ = True
                            else:
                                cside[c] = side[cell]
                            rmin = min(rmin, ring[cell])
                if occ:
                    phi, _, _, _, _, t = TK.mesh_exact(f, m, ox + i * h, oy + j * h, oz + k * h, np.inf, -1)
                    near[c] = True
                    best[c] = phi * phi
                    tri[c] = t
                    out[2 * c] = min(max(phi, -band), band)
                    out[2 * c + 1] = t
                elif rmin <= far_ring:
                    active[c] = True
                else:
                    out[2 * c] = cside[c] * band
                    out[2 * c + 1] = -1.0
    for _ in range(8):
        changed = False
        for sweep in range(8):
            si = 1 if sweep & 1 else -1
            sj = 1 if sweep & 2 else -1
            sk = 1 if sweep & 4 else -1
            for ii in range(nx + 1):
                i = ii if si > 0 else nx - ii
                for jj in range(ny + 1):
                    j = jj if sj > 0 else ny - jj
                    for kk in range(nz + 1):
                        k = kk if sk > 0 else nz - kk
                        c = (i * nyc + j) * nzc + k
                        if not active[c]:
                            continue
                        px, py, pz = ox + i * h, oy + j * h, oz + k * h
                        for a in range(2):
                            ni = i - si * a
                            if ni < 0 or ni > nx:
                                continue
                            for b in range(2):
                                nj = j - sj * b
                                if nj < 0 or nj > ny:
                                    continue
                                for d in range(2):
                                    nk = k - sk * d
                                    if (a == 0 and b == 0 and d == 0) or nk < 0 or nk > nz:
                                        continue
                                    t = tri[(ni * nyc + nj) * nzc + nk]
                                    if t < 0 or t == tri[c]:
                                        continue
                                    d2 = TK.triangle_distance2(f, m, t, px, py, pz)
                                    if d2 < best[c]:
                                        best[c] = d2
                                        tri[c] = t
                                        changed = True
        if not changed:
            break
    for c in range(nc):
        if active[c]:
            out[2 * c] = cside[c] * min(math.sqrt(best[c]), band)
            out[2 * c + 1] = tri[c]


def _normalise(a: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(a, axis=1)
    if np.any(n == 0):
        raise MeshError("mesh: a pseudo-normal vanishes (two faces folded onto each other)")
    return a / n[:, None]


MAX_HASH_CELLS = 50_000_000  # 400 MB of int64 cell starts; beyond it the build itself takes minutes


def hash_grid(v: np.ndarray, fc: np.ndarray, cell_edges: float, band_m: float | None):
    """(h [m], band [m], origin (3,) [m], dims (3,) int) of a mesh's spatial hash: cells of ``cell_edges``
    mean edge lengths over the bounding box padded by the band and a cell.  v: (V, 3); fc: (T, 3)."""
    tri = v[fc]
    e = np.concatenate([tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 1], tri[:, 0] - tri[:, 2]])
    mean_edge = float(np.linalg.norm(e, axis=1).mean())
    h = float(cell_edges) * mean_edge
    vmin, vmax = v.min(axis=0), v.max(axis=0)
    diag = float(np.linalg.norm(vmax - vmin))
    band = DEFAULT_BAND_FRACTION * diag if band_m is None or band_m <= 0 else float(band_m)
    band = max(band, 2.0 * h)
    pad = band + h
    dims = np.ceil((vmax - vmin + 2 * pad) / h).astype(np.int64) + 1
    return h, band, vmin - pad, dims


def skull_hash_cells(subdivisions: int, scale: float, cell_edges: float, band_m: float) -> float:
    """About how many cells the skull terrain's hash grid has at ``subdivisions``, without building that
    mesh: the grid's cells per axis grow linearly with the subdivisions (the mean edge, so the cell, shrinks
    as 1 / subdivisions while the padded box stays), so they are counted on 16- and 32-subdivision skulls
    and extrapolated per axis (a given band_m [m] is scaled like the mesh: the count is scale-free)."""
    n = int(subdivisions)
    band = band_m / scale if band_m > 0 else None

    def dims(k: int) -> np.ndarray:
        m = skull_mesh(k)
        return hash_grid(np.asarray(m.vertices, dtype=float), np.asarray(m.faces), cell_edges, band)[3].astype(float)

    if n <= 32:
        return float(np.prod(dims(n)))
    d16, d32 = dims(16), dims(32)
    return float(np.prod(d32 + (d32 - d16) * (n - 32) / 16.0))


def mesh_block(vertices, faces, cell_edges: float | None = None, band_m: float | None = None,
               name: str = "mesh", exact_cells: float | None = None) -> np.ndarray:
    """The MESH data block (layout in ``terrain_kernels``) of a closed mesh, offsets relative to its start.

    cell_edges: hash cell size h in mean edge lengths; band_m: the band [m] beyond
    which phi is clamped to +-band (None: DEFAULT_BAND_FRACTION of the
    bounding-box diagonal; at least two cells); exact_cells: the exact band in
    cells (|phi| below exact_cells * h is always the exact distance).
    """
    from scipy import ndimage

    cell_edges = DEFAULT_CELL_EDGES if cell_edges is None else float(cell_edges)
    exact_cells = DEFAULT_EXACT_CELLS if exact_cells is None else float(exact_cells)
    v, fc = check_closed(vertices, faces, name)
    tri = v[fc]  # (T, 3, 3)
    h, band, origin, dims = hash_grid(v, fc, cell_edges, band_m)
    n_cells = int(np.prod(dims))
    if n_cells > MAX_HASH_CELLS:
        raise MeshError(f"{name}: the hash grid would have {n_cells} cells; use a smaller band or larger cells")
    # order triangles along the grid for memory locality (by centroid cell, row-major)
    cen = tri.mean(axis=1)
    cidx = np.floor((cen - origin) / h).astype(np.int64)
    order = np.argsort((cidx[:, 0] * dims[1] + cidx[:, 1]) * dims[2] + cidx[:, 2], kind="stable")
    fc = fc[order]
    tri = tri[order]
    T, V = len(fc), len(v)

    # pseudo-normals
    fn = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    fn = _normalise(fn)
    directed = fc[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    _, inv = np.unique(np.sort(directed, axis=1), axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    en_u = np.zeros((inv.max() + 1, 3))
    np.add.at(en_u, inv, np.repeat(fn, 3, axis=0))
    en = _normalise(en_u)[inv].reshape(T, 9)
    vn = np.zeros((V, 3))
    for c in range(3):
        p0 = tri[:, c]
        a = tri[:, (c + 1) % 3] - p0
        b = tri[:, (c + 2) % 3] - p0
        cosang = np.einsum("ij,ij->i", a, b) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
        ang = np.arccos(np.clip(cosang, -1.0, 1.0))
        np.add.at(vn, fc[:, c], ang[:, None] * fn)
    vn = _normalise(vn)

    # the hash
    t9 = np.ascontiguousarray(tri.reshape(T, 9))
    nx, ny, nz = (int(d) for d in dims)
    invh = 1.0 / h
    eps = 1e-9 * h
    counts = np.zeros(n_cells, dtype=np.int64)
    _count_cells(t9, origin[0], origin[1], origin[2], invh, nx, ny, nz, eps, counts)
    starts = np.zeros(n_cells, dtype=np.int64)
    np.cumsum(counts[:-1], out=starts[1:])
    lst = np.zeros(int(counts.sum()), dtype=np.int64)
    _fill_cells(t9, origin[0], origin[1], origin[2], invh, nx, ny, nz, eps, starts, np.zeros(n_cells, np.int64), lst)
    empty = (counts == 0).reshape(nx, ny, nz)
    ring = ndimage.distance_transform_cdt(empty, metric="chessboard").reshape(-1)

    # assemble (side filled in below)
    off_cells = TK.MESH_HDR
    off_list = off_cells + TK.CELL_STRIDE * n_cells
    off_tri = off_list + len(lst)
    off_en = off_tri + TK.TRI_STRIDE * T
    off_tv = off_en + 9 * T
    off_vn = off_tv + 3 * T
    off_adj = off_vn + 3 * V
    off_ringptr = off_adj + 3 * T
    off_ring = off_ringptr + V + 1
    off_corners = off_ring + 3 * T
    n_corners = (nx + 1) * (ny + 1) * (nz + 1)
    total = off_corners + TK.CORNER_STRIDE * n_corners
    b = np.zeros(total)
    b[TK.MB_H], b[TK.MB_INVH] = h, invh
    b[TK.MB_ORIGIN: TK.MB_ORIGIN + 3] = origin
    b[TK.MB_DIMS: TK.MB_DIMS + 3] = nx, ny, nz
    b[TK.MB_BAND], b[TK.MB_NTRI], b[TK.MB_NVERT] = band, T, V
    b[TK.MB_CELLS], b[TK.MB_LIST], b[TK.MB_TRI] = off_cells, off_list, off_tri
    b[TK.MB_EDGEN], b[TK.MB_TRIV], b[TK.MB_VERTN] = off_en, off_tv, off_vn
    b[TK.MB_CORNERS], b[TK.MB_EXACT] = off_corners, min(float(exact_cells) * h, band)
    b[TK.MB_ADJ], b[TK.MB_RINGPTR], b[TK.MB_RING] = off_adj, off_ringptr, off_ring
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    b[TK.MB_CENTROID: TK.MB_CENTROID + 3] = (cen[order] * area[:, None]).sum(axis=0) / area.sum()
    cells = b[off_cells: off_list].reshape(n_cells, TK.CELL_STRIDE)
    cells[:, 0] = starts
    cells[:, 1] = counts
    cells[:, 2] = 1.0
    cells[:, 3] = ring
    b[off_list: off_tri] = lst
    sph_c = tri.mean(axis=1)
    sph_r = np.linalg.norm(tri - sph_c[:, None, :], axis=2).max(axis=1) * (1.0 + 1e-12)
    b[off_tri: off_en] = np.column_stack([t9, fn, sph_c, sph_r]).reshape(-1)
    b[off_en: off_tv] = en.reshape(-1)
    b[off_tv: off_vn] = fc.reshape(-1)
    b[off_vn: off_adj] = vn.reshape(-1)
    # triangle across each edge (ab, bc, ca): every undirected edge has exactly two (triangle, edge) entries
    order_e = np.argsort(inv, kind="stable")
    pair = order_e.reshape(-1, 2)  # entries t*3 + e, two per edge
    adj = np.empty(3 * T, dtype=np.int64)
    adj[pair[:, 0]] = pair[:, 1] // 3
    adj[pair[:, 1]] = pair[:, 0] // 3
    b[off_adj: off_ringptr] = adj
    # triangles around each vertex (CSR)
    vt = fc.reshape(-1)
    order_v = np.argsort(vt, kind="stable")
    ptr = np.zeros(V + 1, dtype=np.int64)
    np.cumsum(np.bincount(vt, minlength=V), out=ptr[1:])
    b[off_ringptr: off_ring] = ptr
    b[off_ring: off_corners] = order_v // 3

    # inside/outside of every cell centre: exact queries for occupied cells; empty cells
    # take the side of their 6-connected empty component (no surface crosses it)
    ii, jj, kk = np.unravel_index(np.arange(n_cells), (nx, ny, nz))
    centres = origin[None, :] + (np.column_stack([ii, jj, kk]) + 0.5) * h
    side = np.ones(n_cells)
    occ = np.flatnonzero(counts > 0)
    out = np.empty(len(occ))
    _signs_at(b, 0, np.ascontiguousarray(centres[occ]), out)
    side[occ] = out
    labels, n_lab = ndimage.label(empty)
    labels = labels.reshape(-1)
    if n_lab:
        outer = np.zeros(n_lab + 1, dtype=bool)
        lab3 = labels.reshape(nx, ny, nz)
        for face in (lab3[0], lab3[-1], lab3[:, 0], lab3[:, -1], lab3[:, :, 0], lab3[:, :, -1]):
            outer[np.unique(face)] = True
        first = np.full(n_lab + 1, -1, dtype=np.int64)
        nz_idx = np.flatnonzero(labels)
        lab_nz = labels[nz_idx]
        uniq, pos = np.unique(lab_nz, return_index=True)
        first[uniq] = nz_idx[pos]
        lab_side = np.ones(n_lab + 1)
        inner = [lab for lab in range(1, n_lab + 1) if not outer[lab] and first[lab] >= 0]
        if inner:
            reps = np.ascontiguousarray(centres[first[inner]])
            rs = np.empty(len(inner))
            _signs_at(b, 0, reps, rs)
            lab_side[inner] = rs
        e_idx = np.flatnonzero(labels)
        side[e_idx] = lab_side[labels[e_idx]]
    cells[:, 2] = side
    # the far field: exact signed distances at the cell corners, clamped to +-band
    _corner_values(b, 0, origin[0], origin[1], origin[2], h, nx, ny, nz, band, counts, side,
                   ring.astype(np.float64), b[off_corners:])
    return b


def mesh_terrain_params(mesh_or_arrays, ground_m: float | None = None, cell_edges: float | None = None,
                        band_m: float | None = None, name: str = "mesh",
                        exact_cells: float | None = None) -> np.ndarray:
    """Terrain vector f of kind MESH for a trimesh mesh or a (vertices, faces) pair.

    ground_m: also a ground plane y = ground_m (None: the mesh alone).
    """
    if isinstance(mesh_or_arrays, tuple):
        v, fc = mesh_or_arrays
    else:
        v, fc = mesh_or_arrays.vertices, mesh_or_arrays.faces
    block = mesh_block(v, fc, cell_edges, band_m, name, exact_cells)
    f = TK.header(0.0 if ground_m is None else float(ground_m), 0.0 if ground_m is None else 1.0)
    return TK.with_data_block(f, block, len(block))


def mesh_arrays(f: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(vertices (V, 3), faces (T, 3)) of the mesh stored in a MESH terrain vector [m]."""
    m = int(f[TK.H_DATA])
    T, V = int(f[m + TK.MB_NTRI]), int(f[m + TK.MB_NVERT])
    o = m + int(f[m + TK.MB_TRI])
    tri = np.asarray(f[o: o + TK.TRI_STRIDE * T]).reshape(T, TK.TRI_STRIDE)[:, :9].reshape(T, 3, 3)
    o = m + int(f[m + TK.MB_TRIV])
    faces = np.asarray(f[o: o + 3 * T]).reshape(T, 3).astype(np.int64)
    verts = np.zeros((V, 3))
    verts[faces.reshape(-1)] = tri.reshape(-1, 3)
    return verts, faces


def mesh_stats(f: np.ndarray) -> dict:
    """Triangles, vertices, cell size, grid, band and mean triangles per occupied cell of a MESH terrain."""
    m = int(f[TK.H_DATA])
    dims = [int(d) for d in f[m + TK.MB_DIMS: m + TK.MB_DIMS + 3]]
    n_cells = dims[0] * dims[1] * dims[2]
    o = m + int(f[m + TK.MB_CELLS])
    counts = np.asarray(f[o: o + TK.CELL_STRIDE * n_cells]).reshape(n_cells, TK.CELL_STRIDE)[:, 1]
    return dict(triangles=int(f[m + TK.MB_NTRI]), vertices=int(f[m + TK.MB_NVERT]), cell_m=float(f[m + TK.MB_H]),
                grid=dims, band_m=float(f[m + TK.MB_BAND]), exact_band_m=float(f[m + TK.MB_EXACT]),
                tris_per_occupied_cell=float(counts[counts > 0].mean()), floats=int(len(f)))

