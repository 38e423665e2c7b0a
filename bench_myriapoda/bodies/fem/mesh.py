"""Tetrahedral meshes for the FEM body: structured boxes, segment chains, closed surfaces.

Every function returns ``nodes: (n_nodes, 3) float64 [m]`` and
``tets: (n_tets, 4) int64`` with positive orientation: det(X1-X0, X2-X0, X3-X0) > 0.
Chains follow PAPER-NOTES: x points forward (toward the head), y up, z sideways;
segment 0 is the head (largest x) and indices grow toward the tail.
"""
from __future__ import annotations

import hashlib
import itertools
import os
from pathlib import Path

import numpy as np

from ...core.paths import cache_root

# Local corner index of a hexahedral cell: bit 0 -> +x, bit 1 -> +y, bit 2 -> +z.
_CORNERS = np.array([[(c >> 0) & 1, (c >> 1) & 1, (c >> 2) & 1] for c in range(8)], dtype=np.int64)

# Kuhn / Freudenthal split: one tet per monotone lattice path 000 -> 111 (one per
# axis permutation).  Every cell is split identically, so faces conform.
_KUHN6 = np.array(
    [[0, 1 << a, (1 << a) | (1 << b), 7] for a, b, _ in itertools.permutations(range(3))],
    dtype=np.int64,
)
# Its mirror image across the cell's mid z plane (local corner c -> c ^ 4): used for the cells on
# the left (z < mirror plane) so that a mesh is mirror-symmetric about its sagittal plane.  The
# two splits conform across the mirror plane: both cut the shared z face along its (0,0)-(1,1)
# diagonal in x-y.
_KUHN6_MIRROR = _KUHN6 ^ 4
# 5-tet split: a central tet on four alternate corners plus four corner tets.  Cells
# alternate between the two corner sets by the parity of (i + j + k), so that the
# face diagonals of neighbouring cells coincide.
_FIVE_EVEN = np.array([[1, 2, 4, 7], [0, 1, 2, 4], [3, 1, 2, 7], [5, 1, 4, 7], [6, 2, 4, 7]], dtype=np.int64)
_FIVE_ODD = np.array([[0, 3, 5, 6], [1, 0, 3, 5], [2, 0, 3, 6], [4, 0, 5, 6], [7, 3, 5, 6]], dtype=np.int64)

RESOLUTION_UNITS = ("cells", "nodes")


def lame_parameters(E, nu):
    """Lame parameters (lambda, mu) [Pa] from Young's modulus E [Pa] and Poisson's ratio nu.

    Paper footnote 3: lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
    """
    E = np.asarray(E, dtype=float)
    nu = np.asarray(nu, dtype=float)
    if np.any(nu <= -1.0) or np.any(nu >= 0.5):
        raise ValueError(f"Poisson's ratio must lie in (-1, 0.5), got {nu}")
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = E / (2.0 * (1.0 + nu))
    return lam[()], mu[()]


def signed_volumes(nodes, tets):
    """Signed tet volumes det(X1-X0, X2-X0, X3-X0) / 6: (n_tets,) [m^3]."""
    p = nodes[tets]
    return np.linalg.det(np.stack([p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]], axis=2)) / 6.0


def orient_tets(nodes, tets):
    """Return a copy of ``tets`` with nodes 2 and 3 swapped wherever the volume is negative."""
    tets = np.array(tets, dtype=np.int64, copy=True)
    neg = signed_volumes(nodes, tets) < 0.0
    tets[neg, 2], tets[neg, 3] = tets[neg, 3].copy(), tets[neg, 2].copy()
    return tets


def box_grid(size, cells, origin=(0.0, 0.0, 0.0), tets_per_cell=6, mirror_z=None):
    """Structured tet mesh of the box [origin, origin + size].

    size: (Lx, Ly, Lz) [m]; cells: (nx, ny, nz) cell counts; tets_per_cell: 6
    (Kuhn split) or 5 (alternating parity).  Node (i, j, k) has index
    i * (ny+1) * (nz+1) + j * (nz+1) + k.
    mirror_z [m] (6 tets per cell only): cells whose centre lies at z < mirror_z take the mirror
    image of the Kuhn split, so a box centred on that plane with an even nz is mirror-symmetric
    about it (the plain Kuhn split is not: a bending body would bend more easily to one side).
    Returns nodes (n, 3) float64 [m], tets (m, 4) int64, positively oriented.
    """
    nx, ny, nz = (int(c) for c in cells)
    if min(nx, ny, nz) < 1:
        raise ValueError(f"cells must be >= 1 in every direction, got {cells}")
    if tets_per_cell not in (5, 6):
        raise ValueError(f"tets_per_cell must be 5 or 6, got {tets_per_cell}")
    lx, ly, lz = (float(s) for s in size)
    gx = origin[0] + np.linspace(0.0, lx, nx + 1)
    gy = origin[1] + np.linspace(0.0, ly, ny + 1)
    gz = origin[2] + np.linspace(0.0, lz, nz + 1)
    nodes = np.stack(np.meshgrid(gx, gy, gz, indexing="ij"), axis=-1).reshape(-1, 3)

    ci, cj, ck = np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij")
    ci, cj, ck = ci.ravel(), cj.ravel(), ck.ravel()
    # corner node ids of every cell: (n_cells, 8)
    corner = ((ci[:, None] + _CORNERS[None, :, 0]) * (ny + 1) * (nz + 1)
              + (cj[:, None] + _CORNERS[None, :, 1]) * (nz + 1)
              + (ck[:, None] + _CORNERS[None, :, 2]))
    if tets_per_cell == 6 and mirror_z is not None:
        left = (gz[ck] + 0.5 * (gz[1] - gz[0]) < mirror_z)
        local = np.where(left[:, None, None], _KUHN6_MIRROR[None], _KUHN6[None])
        tets = np.take_along_axis(corner, local.reshape(len(ci), 6 * 4), axis=1).reshape(-1, 4)
    elif tets_per_cell == 6:
        tets = corner[:, _KUHN6].reshape(-1, 4)
    else:
        odd = ((ci + cj + ck) % 2).astype(bool)
        local = np.where(odd[:, None, None], _FIVE_ODD[None], _FIVE_EVEN[None])
        tets = np.take_along_axis(corner, local.reshape(len(ci), 5 * 4), axis=1).reshape(-1, 4)
    return nodes, orient_tets(nodes, tets)


def cell_lumped_mass(tets, vol, rho, tets_per_cell, n_nodes):
    """Nodal masses of a structured grid lumped per hexahedral cell: (n_nodes,) [kg].

    tets: (n_tets, 4) as ``box_grid`` / ``chain_grid`` return them, cell by cell (``tets_per_cell``
    consecutive rows per cell); vol: (n_tets,) [m^3]; rho: (n_tets,) [kg/m^3].  Each cell's mass
    (the sum of rho V over its tets) goes to its eight corners in equal shares, the lumped mass of a
    trilinear hexahedron: every node carries the mass of its dual cell (interior nodes one cell's
    worth, face nodes a half, edge nodes a quarter), whichever way the cell is split into tets.

    Why (issue 11): the per-tet lumping (``kernels.lumped_mass``, eq. 12) inherits the split's
    asymmetry.  The five-tet split gives the central tet (a third of the cell) to four alternate
    corners, so a cell's corners get 5/24 or 1/24 of its mass; on the 2 x 2 section of the snake the
    bottom nodes' masses then vary 10-fold along the belly.  A light belly node carries the same
    share of the body's weight, and the per-node contact (``contact_kernels``) stops its sliding
    whenever its speed is below mu times its normal impulse per unit mass, ~ mu g dt x (load / its
    mass): the light nodes stick at slip speeds that a dual-cell mass would let slide.
    Raises ValueError when a group of ``tets_per_cell`` rows does not span exactly 8 nodes.
    """
    tets = np.asarray(tets, dtype=np.int64)
    n_cells, rest = divmod(len(tets), int(tets_per_cell))
    if rest:
        raise ValueError(f"{len(tets)} tets are not whole cells of {tets_per_cell}")
    cell_mass = (np.asarray(rho, dtype=float) * np.asarray(vol, dtype=float)).reshape(n_cells, tets_per_cell).sum(1)
    corners = np.sort(tets.reshape(n_cells, 4 * tets_per_cell), axis=1)
    distinct = 1 + (np.diff(corners, axis=1) != 0).sum(axis=1)
    if np.any(distinct != 8):
        raise ValueError("tets are not grouped cell by cell (a group spans other than 8 nodes)")
    m = np.zeros(int(n_nodes))
    for c in range(n_cells):  # mesh construction only
        m[np.unique(corners[c])] += cell_mass[c] / 8.0
    return m


def cells_per_segment(resolution: int, unit: str) -> tuple[int, int, int]:
    """Hexahedral cells along each axis of one segment (``segment_cells`` without its checks: for estimates)."""
    c = max(1, int(resolution) - 1) if unit == "nodes" else max(1, int(resolution))
    return c, c, c


def segment_cells(resolution, resolution_unit="nodes"):
    """Cells per segment (nx, ny, nz) from a resolution given in cells or in nodes per edge.

    resolution: int (same in x, y, z) or 3 ints.  With ``resolution_unit="nodes"``
    (default) 3 means 3 x 3 x 3 nodes = 2 x 2 x 2 cells; with "cells" it means
    3 x 3 x 3 cells.  The paper's "3 x 3 x 3 deformable mesh resolution" (Sec. 6)
    does not say which; PAPER-NOTES asks to expose both.
    """
    if resolution_unit not in RESOLUTION_UNITS:
        raise ValueError(f"resolution_unit must be one of {RESOLUTION_UNITS}, got {resolution_unit!r}")
    res = np.broadcast_to(np.asarray(resolution, dtype=np.int64), (3,))
    cells = res - 1 if resolution_unit == "nodes" else res
    if np.any(cells < 1):
        raise ValueError(f"resolution {resolution} {resolution_unit} gives fewer than 1 cell per edge")
    return tuple(int(c) for c in cells)


def chain_grid(n_segments, segment_length, cross_section=(1.0, 1.0), resolution=3,
               resolution_unit="nodes", tets_per_cell=6, shared_faces=True, mirror=False):
    """A chain of box segments along x: segment 0 (the head) at the front (largest x).

    n_segments: number of segments; segment_length [m] along x; cross_section:
    (height along y, width along z) [m]; resolution / resolution_unit: see
    ``segment_cells``.  The chain spans x in [0, n_segments * segment_length],
    y in [0, height], z in [-width/2, width/2].  With ``shared_faces=True`` the
    segments form one connected mesh (neighbours share their end-face nodes);
    with False every segment has its own nodes (as between the rigid segments of
    the hybrid body).  ``mirror``: mirror-symmetric split about the sagittal plane z = 0
    (``box_grid``'s mirror_z; exact for an even cell count across the width).
    Returns nodes (n, 3) [m], tets (m, 4) int64, tet_segment (m,) int64.
    """
    if n_segments < 1:
        raise ValueError(f"n_segments must be >= 1, got {n_segments}")
    cx, cy, cz = segment_cells(resolution, resolution_unit)
    h, w = (float(c) for c in cross_section)
    L = float(segment_length)
    total = n_segments * L
    if shared_faces:
        nodes, tets = box_grid((total, h, w), (n_segments * cx, cy, cz), origin=(0.0, 0.0, -0.5 * w),
                               tets_per_cell=tets_per_cell, mirror_z=0.0 if mirror else None)
        cell_x = nodes[tets].mean(axis=1)[:, 0]
        tet_segment = np.clip(((total - cell_x) // L).astype(np.int64), 0, n_segments - 1)
        return nodes, tets, tet_segment
    all_nodes, all_tets, all_seg = [], [], []
    offset = 0
    for s in range(n_segments):
        nd, tt = box_grid((L, h, w), (cx, cy, cz), origin=(total - (s + 1) * L, 0.0, -0.5 * w),
                          tets_per_cell=tets_per_cell, mirror_z=0.0 if mirror else None)
        all_nodes.append(nd)
        all_tets.append(tt + offset)
        all_seg.append(np.full(len(tt), s, dtype=np.int64))
        offset += len(nd)
    return np.concatenate(all_nodes), np.concatenate(all_tets), np.concatenate(all_seg)


# --------------------------------------------------------------------------------------
# Closed surfaces (pytetwild) with a disk cache
# --------------------------------------------------------------------------------------
_CACHE_FORMAT = "tetmesh-v1"


def tetmesh_cache_dir():
    """Cache directory: ``$BENCH_MYRIAPODA_CACHE`` itself when it is set (as it always was for the tetmeshes),
    else ``tetmesh/`` under ``core.paths.cache_root()`` (which honours ``XDG_CACHE_HOME``)."""
    env = os.environ.get("BENCH_MYRIAPODA_CACHE")
    return Path(env) if env else cache_root() / "tetmesh"


def _load_surface(mesh_or_path):
    if isinstance(mesh_or_path, (str, os.PathLike)):
        import trimesh

        mesh_or_path = trimesh.load_mesh(mesh_or_path, force="mesh")
    if isinstance(mesh_or_path, tuple):
        vertices, faces = mesh_or_path
    else:
        vertices, faces = mesh_or_path.vertices, mesh_or_path.faces
    return (np.ascontiguousarray(vertices, dtype=np.float64),
            np.ascontiguousarray(faces, dtype=np.int32))


def _run_pytetwild(vertices, faces, **params):
    # Lazy: pytetwild imports pyvista, which is slow to import and not needed otherwise.
    import contextlib
    import tempfile

    import pytetwild

    # fTetWild writes a scratch file (__tracked_surface.stl) into the working
    # directory; run it from a temporary one so nothing lands in the user's tree.
    with tempfile.TemporaryDirectory() as scratch, contextlib.chdir(scratch):
        return pytetwild.tetrahedralize(vertices, faces, **params)


def tetrahedralize_surface(mesh_or_path, edge_length_fac=0.05, edge_length_abs=None, optimize=True,
                           epsilon=1e-3, stop_energy=10.0, cache=True):
    """Tetrahedralize a closed triangle surface with fTetWild, cached on disk.

    mesh_or_path: a trimesh.Trimesh, a (vertices, faces) tuple or a file path.
    edge_length_fac, edge_length_abs, optimize, epsilon, stop_energy: passed to
    ``pytetwild.tetrahedralize`` (edge lengths relative to the bounding-box
    diagonal, or absolute [m]).  The result is stored as ``<sha256>.npz`` in
    ``tetmesh_cache_dir()``, keyed by the surface's vertex and face bytes and
    these parameters, so a repeated call never re-runs fTetWild.
    Returns nodes (n, 3) float64 [m], tets (m, 4) int64, positively oriented,
    without unreferenced nodes.
    """
    vertices, faces = _load_surface(mesh_or_path)
    params = dict(edge_length_fac=float(edge_length_fac),
                  edge_length_abs=None if edge_length_abs is None else float(edge_length_abs),
                  optimize=bool(optimize), epsilon=float(epsilon), stop_energy=float(stop_energy))
    h = hashlib.sha256()
    h.update(_CACHE_FORMAT.encode())
    h.update(np.asarray(vertices.shape, dtype=np.int64).tobytes())
    h.update(vertices.tobytes())
    h.update(np.asarray(faces.shape, dtype=np.int64).tobytes())
    h.update(faces.tobytes())
    h.update(repr(sorted(params.items())).encode())
    path = tetmesh_cache_dir() / f"{h.hexdigest()}.npz"
    if cache and path.exists():
        with np.load(path) as data:
            return data["nodes"].astype(np.float64), data["tets"].astype(np.int64)

    nodes, tets = _run_pytetwild(vertices, faces, quiet=True, **params)
    nodes = np.asarray(nodes, dtype=np.float64)
    tets = np.asarray(tets, dtype=np.int64)
    # Drop nodes no tet uses (they would have zero mass) and renumber.
    used = np.unique(tets)
    remap = np.full(len(nodes), -1, dtype=np.int64)
    remap[used] = np.arange(len(used))
    nodes = np.ascontiguousarray(nodes[used])
    tets = orient_tets(nodes, remap[tets])  # fTetWild's orientation is the opposite of ours
    if np.any(signed_volumes(nodes, tets) <= 0.0):
        raise ValueError("fTetWild returned degenerate (zero-volume) tetrahedra")
    if cache:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(f"{path.stem}.{os.getpid()}.tmp.npz")
        np.savez(tmp, nodes=nodes, tets=tets)
        os.replace(tmp, path)  # atomic, so a concurrent reader never sees half a file
    return nodes, tets
