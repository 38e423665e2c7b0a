"""Per-frame meshes of a run for Blender or Maya: ``bench-myriapoda run ... --export-frames DIR``.

One file per recorded sample, ``DIR/frame_00000.obj`` (10 decimals) or ``.ply``
(binary, float32 positions as trimesh writes them), each one triangle mesh in
world coordinates [m] (y up, as Blender's and Maya's OBJ importers expect by
default): the triangle surfaces of the body's ``Scene`` (``bodies.scene``:
rigid boxes, FEM boundaries, lattice faces), in the scene's order, followed by
every leg as two closed hexagonal tubes (root -> knee, knee -> tip) and every
antenna link as a thinner tube.  An OBJ names the parts as groups (``g body``,
``g leg_00`` ..., ``g antenna_0``, ``g antenna_1``: ``part_groups``) so Blender
can shade them apart; a PLY has no groups.  The
surfaces' vertices come first, in order and unmerged, so vertex i of every
frame is the same material point: the sequence can drive a mesh-cache /
blend-shape animation.
``DIR/frames.json`` lists the frame times [s], the files and the resolved case.

The directory appears complete or not at all: everything is written into a
temporary directory next to DIR, which is renamed to DIR at the end (and
removed on failure).
"""
from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from ..bodies.scene import Scene

FORMATS = ("obj", "ply")
TUBE_SECTIONS = 6            # hexagonal legs: light files, still round enough at a leg's scale
LEG_RADIUS_FRACTION = 0.04   # tube radius / median leg link length (femur, tibia)


def _tube_template(sections: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed prism along +z from z = 0 to 1, radius 1: vertices (2 s + 2, 3), outward faces (4 s, 3)."""
    a = 2.0 * np.pi * np.arange(sections) / sections
    ring = np.column_stack([np.cos(a), np.sin(a)])
    verts = np.vstack([np.column_stack([ring, np.zeros(sections)]), np.column_stack([ring, np.ones(sections)]),
                       [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]])
    k = np.arange(sections)
    k1 = (k + 1) % sections
    b, t, cb, ct = k, sections + k, 2 * sections, 2 * sections + 1
    faces = np.concatenate([
        np.column_stack([b, k1, sections + k1]), np.column_stack([b, sections + k1, t]),  # side, outward
        np.column_stack([np.full(sections, cb), k1, b]),                                     # bottom cap (-z)
        np.column_stack([np.full(sections, ct), t, sections + k1]),                          # top cap (+z)
    ])
    return verts, faces.astype(np.int64)


_TUBE_VERTS, _TUBE_FACES = _tube_template(TUBE_SECTIONS)


def tubes(p0: np.ndarray, p1: np.ndarray, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Closed hexagonal tubes from p0 to p1 (n, 3) [m] of ``radius`` [m]: vertices (n (2 s + 2), 3), faces.

    Vectorised (one template carried by a right-handed frame per tube), so a
    centipede's 72 leg links cost no more than one numpy call per frame.
    Faces are outward: the frame (u, w, axis) has u x w = axis.
    """
    p0, p1 = np.asarray(p0, dtype=float), np.asarray(p1, dtype=float)
    n = len(p0)
    if n == 0:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)
    d = p1 - p0
    length = np.linalg.norm(d, axis=1)
    axis = np.where(length[:, None] > 0, d / np.where(length > 0, length, 1.0)[:, None], [0.0, 1.0, 0.0])
    ref = np.where(np.abs(axis[:, [0]]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    u = np.cross(axis, ref)
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    w = np.cross(axis, u)
    tv = _TUBE_VERTS
    verts = (p0[:, None, :] + radius * (tv[None, :, 0:1] * u[:, None, :] + tv[None, :, 1:2] * w[:, None, :])
             + tv[None, :, 2:3] * d[:, None, :])
    faces = _TUBE_FACES[None] + len(tv) * np.arange(n)[:, None, None]
    return verts.reshape(-1, 3), faces.reshape(-1, 3)


def leg_radius(scene: Scene) -> float:
    """Tube radius for the legs [m]: a small fraction of the median femur / tibia length."""
    legs = scene.legs
    links = np.concatenate([np.linalg.norm(legs[:, 1] - legs[:, 0], axis=1),
                            np.linalg.norm(legs[:, 2] - legs[:, 1], axis=1)])
    links = links[np.isfinite(links) & (links > 0)]
    return LEG_RADIUS_FRACTION * float(np.median(links)) if len(links) else 0.0


def scene_mesh(scene: Scene, radius: float | None = None):
    """One ``trimesh.Trimesh`` of a scene: its triangle surfaces (vertices in order) then the leg tubes.

    radius: leg tube radius [m]; default ``leg_radius(scene)``.  Not processed
    (no vertex merging), so vertex i is vertex i of the scene's surfaces.
    """
    import trimesh

    verts, faces, offset = [], [], 0
    for v, f, _ in scene.triangles:
        verts.append(v)
        faces.append(f + offset)
        offset += len(v)
    if scene.legs is not None and len(scene.legs):
        r = leg_radius(scene) if radius is None else radius
        legs = scene.legs
        v, f = tubes(np.concatenate([legs[:, 0], legs[:, 1]]), np.concatenate([legs[:, 1], legs[:, 2]]), r)
        verts.append(v)
        faces.append(f + offset)
        offset += len(v)
    if scene.antennae is not None and len(scene.antennae):
        # antennae as thinner tubes, one per link
        r = 0.5 * (leg_radius(scene) if radius is None else radius)
        a = scene.antennae
        v, f = tubes(a[:, :-1].reshape(-1, 3), a[:, 1:].reshape(-1, 3), r)
        verts.append(v)
        faces.append(f + offset)
    if not verts:
        return trimesh.Trimesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64), process=False)
    return trimesh.Trimesh(np.concatenate(verts), np.concatenate(faces), process=False)


def part_groups(scene: Scene, mesh) -> list[tuple[str, np.ndarray]]:
    """(name, face indices) of each part of ``scene_mesh(scene)``: ``body`` (every surface), ``leg_NN``
    (leg k = 2 segment + side: its root-knee and knee-tip tubes) and ``antenna_A`` (0 left, 1 right: its
    link tubes), in face order of the mesh.  Names are zero-padded so they sort in leg order."""
    n_body = sum(len(f) for _, f, _ in scene.triangles)
    groups = [("body", np.arange(n_body))] if n_body else []
    per_tube = len(_TUBE_FACES)
    start = n_body
    if scene.legs is not None and len(scene.legs):
        n = len(scene.legs)
        width = max(2, len(str(n - 1)))
        tube = np.arange(per_tube)
        for k in range(n):  # tubes: all root-knee tubes, then all knee-tip tubes
            groups.append((f"leg_{k:0{width}d}", np.concatenate([start + k * per_tube + tube,
                                                                 start + (n + k) * per_tube + tube])))
        start += 2 * n * per_tube
    if scene.antennae is not None and len(scene.antennae):
        links = scene.antennae.shape[1] - 1
        for a in range(len(scene.antennae)):
            groups.append((f"antenna_{a}", start + a * links * per_tube + np.arange(links * per_tube)))
    assert sum(len(g) for _, g in groups) == len(mesh.faces), "parts do not cover the mesh"
    return groups


def obj_text(scene: Scene, mesh, digits: int = 10) -> str:
    """The mesh as Wavefront OBJ text with one named group (``g NAME``) per part (``part_groups``).

    Vertices first, in mesh order (no normals or texture coordinates: vertex i in the file is vertex i of
    the mesh on import); then each group's faces (1-based indices).  Blender's OBJ importer turns the
    groups into separate objects (with "Split by Group") or vertex groups, so body, legs and antennae
    can be given their own materials.
    """
    v = np.asarray(mesh.vertices, dtype=float)
    f = np.asarray(mesh.faces, dtype=np.int64) + 1
    out = [f"# bench-myriapoda frame: {len(v)} vertices, {len(f)} triangles, units m, y up\n"]
    out.append("".join(f"v {x:.{digits}f} {y:.{digits}f} {z:.{digits}f}\n" for x, y, z in v))
    for name, idx in part_groups(scene, mesh):
        out.append(f"g {name}\n")
        out.append("".join(f"f {a} {b} {c}\n" for a, b, c in f[idx]))
    return "".join(out)


def check_out_dir(out_dir) -> None:
    """Raise ValueError if ``out_dir`` exists and is not an empty directory (nothing may be overwritten)."""
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise ValueError(f"{out} exists and is not a directory")
    if out.is_dir() and any(out.iterdir()):
        raise ValueError(f"{out} exists and is not empty")


def export_frames(frames: Sequence[Scene], times: Sequence[float], case_dict: dict[str, Any], out_dir,
                  fmt: str = "obj") -> dict[str, Any]:
    """Write one mesh per frame into ``out_dir`` (created; must not exist or be empty) and frames.json.

    frames: Scenes; times: (n,) [s]; case_dict: the resolved case
    (``Case.to_dict()``); fmt: "obj" or "ply".  Returns the frames.json data.
    """
    if fmt not in FORMATS:
        raise ValueError(f"frame format must be one of {FORMATS}, got {fmt!r}")
    if len(frames) != len(times):
        raise ValueError(f"{len(frames)} frames but {len(times)} times")
    out = Path(out_dir)
    check_out_dir(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    # A leg radius fixed for the whole sequence: tubes must not swell or shrink from frame to frame.
    with_legs = [s for s in frames if s.legs is not None and len(s.legs)]
    radius = leg_radius(with_legs[0]) if with_legs else 0.0
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.tmp-", dir=out.parent))
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o777 & ~umask)  # mkdtemp's private 0700 would otherwise become DIR's mode
        files = []
        for i, scene in enumerate(frames):
            name = f"frame_{i:05d}.{fmt}"
            mesh = scene_mesh(scene, radius)
            if fmt == "obj":
                (tmp / name).write_text(obj_text(scene, mesh))
            else:
                (tmp / name).write_bytes(mesh.export(file_type="ply", encoding="binary"))
            files.append(name)
        meta = {"format": fmt, "units": "m", "up_axis": "y", "forward_axis": "x",
                "n_frames": len(files), "times_s": [float(t) for t in times], "files": files,
                "leg_tube_radius_m": radius,
                "contents": "per frame one triangle mesh: the body's surfaces (rigid boxes, FEM boundary, "
                            "lattice faces) with their vertices first and in a fixed order, then two tubes "
                            "per leg (root-knee, knee-tip), then one tube per antenna link; OBJ files name "
                            "the parts as groups: body, leg_00 ..., antenna_0 ...",
                "case": case_dict}
        (tmp / "frames.json").write_text(json.dumps(meta, indent=1))
        if out.is_dir():
            out.rmdir()  # empty (checked above): the rename below takes its place
        os.replace(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return meta
