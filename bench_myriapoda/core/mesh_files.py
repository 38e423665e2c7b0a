"""Closed triangle-mesh files: reading one and checking that it can be a terrain (paper Sec. 5.1, 6.2).

* ``load_closed_mesh(path, scale, translate)``: any mesh file trimesh loads; it must be watertight and
  consistently wound (else ``MeshError``); an inside-out mesh is flipped.
* ``check_closed(vertices, faces)``: that check on arrays; ``mesh_file_problem(path)``: why a path cannot
  be a mesh file, without reading it; ``transformed(mesh, scale, translate)``.

In the core because ``core.schema`` checks a scenario's ``mesh`` file while the scenario is loaded (a bad
file is refused then, naming ``scenario.mesh``), and the core imports nothing from the layers above it;
the terrain built from the mesh (its spatial hash, ``world.meshes``) is the world layer's.
"""
from __future__ import annotations

import functools
from pathlib import Path

import numpy as np


MAX_VERTEX_M = 1.0e6  # vertex coordinates of a mesh file [m], as every length of the configuration (schema)


class MeshError(ValueError):
    """A mesh that cannot be a closed terrain (not watertight, inconsistently wound, degenerate)."""


def check_closed(vertices: np.ndarray, faces: np.ndarray, name: str = "mesh") -> tuple[np.ndarray, np.ndarray]:
    """Validate a closed, consistently wound triangle mesh; return (vertices, faces) wound outward.

    Raises MeshError naming what is wrong.
    """
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces, dtype=np.int64)
    if v.ndim != 2 or v.shape[1] != 3 or f.ndim != 2 or f.shape[1] != 3 or len(f) < 4:
        raise MeshError(f"{name}: not a triangle mesh (need (n, 3) vertices and at least 4 triangles)")
    if not np.all(np.isfinite(v)):
        raise MeshError(f"{name}: vertices are not finite")
    if np.abs(v).max() > MAX_VERTEX_M:  # 1e308 is finite, but its products overflow in every check below
        raise MeshError(f"{name}: a vertex lies beyond +-{MAX_VERTEX_M:g} m")
    if f.min() < 0 or f.max() >= len(v):
        raise MeshError(f"{name}: a face refers to a missing vertex")
    tri = v[f]
    area2 = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    scale = float(np.ptp(v, axis=0).max())
    n_degen = int(np.count_nonzero(area2 <= 1e-14 * scale * scale))
    if n_degen:
        raise MeshError(f"{name}: {n_degen} degenerate (zero-area) triangles; a closed terrain needs proper triangles")
    directed = f[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    und = np.sort(directed, axis=1)
    _, inv, counts = np.unique(und, axis=0, return_inverse=True, return_counts=True)
    bad = int(np.count_nonzero(counts != 2))
    if bad:
        raise MeshError(f"{name}: not watertight: {bad} edges are not shared by exactly two triangles "
                        f"(a closed terrain mesh needs every edge to border exactly two faces; "
                        f"repair it, e.g. with trimesh.repair.fill_holes, first)")
    _, dcounts = np.unique(directed, axis=0, return_counts=True)
    if np.any(dcounts != 1):
        raise MeshError(f"{name}: inconsistent winding: neighbouring triangles are oriented oppositely "
                        f"(trimesh.repair.fix_winding can repair it)")
    vol = float(np.einsum("ij,ij->i", tri[:, 0], np.cross(tri[:, 1], tri[:, 2])).sum()) / 6.0
    if vol < 0.0:  # inside out
        f = f[:, ::-1].copy()
    return v, f


@functools.lru_cache(maxsize=8)
def _load_checked(path: str, mtime_ns: int, size: int) -> tuple[np.ndarray, np.ndarray]:
    import trimesh

    import warnings

    try:  # vertices at 1e308 overflow trimesh's processing: its numpy warnings are not the user's message
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            mesh = trimesh.load(path, force="mesh", process=True)
    except Exception as exc:  # trimesh raises many types for unreadable files
        raise MeshError(f"{path}: trimesh cannot load it ({exc})") from None
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise MeshError(f"{path}: no triangles in the file")
    v, f = check_closed(mesh.vertices, mesh.faces, path)
    v.setflags(write=False)
    f.setflags(write=False)
    return v, f


def load_closed_mesh(path, scale: float = 1.0, translate=(0.0, 0.0, 0.0)):
    """Load any mesh file trimesh reads as a closed terrain mesh: v' = scale * v + translate [m].

    Raises MeshError (a ValueError) when the file cannot be read or the mesh is
    not closed (watertight and consistently wound); an inside-out mesh is flipped.
    A file is read and checked once per process while it is unchanged.
    """
    import trimesh

    path = Path(path)
    if not path.is_file():
        raise MeshError(f"{path}: file not found")
    problem = mesh_file_problem(path)
    if problem:
        raise MeshError(problem)
    st = path.stat()
    v, f = _load_checked(str(path.resolve()), st.st_mtime_ns, st.st_size)
    return transformed(trimesh.Trimesh(vertices=v.copy(), faces=f.copy(), process=False), scale, translate)


def transformed(mesh, scale: float = 1.0, translate=(0.0, 0.0, 0.0)):
    """A copy of a trimesh mesh with vertices scale * v + translate."""
    import trimesh

    if not scale > 0:
        raise MeshError(f"mesh scale must be > 0, got {scale}")
    t = np.asarray(translate, dtype=float).reshape(3)
    return trimesh.Trimesh(vertices=np.asarray(mesh.vertices) * float(scale) + t, faces=np.asarray(mesh.faces).copy(),
                           process=False)


def mesh_file_problem(path) -> str | None:
    """Why ``path`` cannot be a mesh file trimesh loads (not a regular file, a file type trimesh does not
    read), or None; checked on the name and the file's kind without reading it."""
    import os
    import stat

    import trimesh

    try:
        st = os.stat(path)
    except OSError as exc:
        return f"{path}: {exc.strerror or 'cannot be read'}"
    if not stat.S_ISREG(st.st_mode):
        return f"{path}: not a regular file"
    suffix = Path(path).suffix.lower().lstrip(".")
    formats = sorted(trimesh.available_formats())
    if suffix not in formats:
        return f"{path}: the file type {suffix or '(none)'!r} is not a mesh format trimesh reads; one of " + \
            ", ".join(f for f in ("stl", "obj", "ply", "off", "glb", "gltf") if f in formats) + ", ..."
    return None
