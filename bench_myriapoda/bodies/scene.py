"""What a body looks like at one instant: triangle surfaces, legs and springs in world coordinates.

Every body model has ``scene() -> Scene``; the animation (``report/animate.py``)
and the per-frame mesh export (``report/export_frames.py``) draw and write
these, so they need not know the body models' internals.

Conventions: world frame (PAPER-NOTES.md), y up, x forward, z to the
creature's right; lengths in metres; float64 positions, int64 indices.  A
scene owns copies of the positions (frames are stored while the body moves on);
the face arrays are static topology, computed once per body and shared
read-only between frames.

This module also holds the topology helpers the bodies share: the outward
triangles of a box (``BOX_FACES``) and of a tetrahedral mesh's boundary
(``tet_boundary_faces``), read-only face arrays (``static_topology``) and their
outward winding (``orient_outward``); a body's own topology lives with it (the
Miller lattice's surface: ``massspring.lattice.lattice_surface_faces``), and so do its
own kinds of surface and their styles (``BodySpec.surface_kinds``): this module
names only the kind the bodies share, the rigid box.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from ..core.specs import SurfaceStyle
from .rigid import CORNER_SIGNS

# The kind of triangle surface the bodies share (the animation colours by kind; each body declares its own
# kinds in ``BodySpec.surface_kinds``): a rigid segment box (``box_triangles``), drawn by every body with boxes.
RIGID_BOX = "rigid-box"
# kind -> style of the shared kinds; a box side is two triangles, outlined in its own colour (no diagonal)
SHARED_SURFACE_KINDS = {RIGID_BOX: SurfaceStyle("#b08850", edges_in_face_color=True)}


@dataclass
class Scene:
    """The geometry of a body at one instant, in world coordinates [m].

    triangles: list of ``(vertices (V, 3) float64 [m], faces (F, 3) int64, kind)``;
      faces index that entry's own vertices and are wound counter-clockwise seen
      from outside (outward normals) for undeformed, uninverted geometry.
    legs: (n_legs, 3, 3) float64 [m] the points root O, knee M and tip P of
      every leg (``kinematics.legs``), leg k = 2 * segment + side; None without legs.
    leg_states: (n_legs,) int64 Switcher state of every leg
      (``controllers.myriapod.switcher``: SF1 ... ADJUST); None without legs.
    springs: (S, 2, 3) float64 [m] end points of every spring of a mass-spring
      body; None for bodies without springs.
    antennae: (2, N + 1, 3) float64 [m] the joint points of the left and right
      antenna, root to tip (``controllers.myriapod.antennae``); None without.
    antenna_contact: (2,) bool, an antenna touching an obstacle; None without.
    """

    triangles: list[tuple[np.ndarray, np.ndarray, str]] = field(default_factory=list)
    legs: np.ndarray | None = None
    leg_states: np.ndarray | None = None
    springs: np.ndarray | None = None
    antennae: np.ndarray | None = None
    antenna_contact: np.ndarray | None = None

    def points(self) -> np.ndarray:
        """(N, 3) [m] every vertex, leg point, spring end and antenna joint of the scene (for bounds)."""
        parts = [v for v, _, _ in self.triangles]
        if self.legs is not None:
            parts.append(self.legs.reshape(-1, 3))
        if self.springs is not None:
            parts.append(self.springs.reshape(-1, 3))
        if self.antennae is not None:
            parts.append(self.antennae.reshape(-1, 3))
        return np.concatenate(parts) if parts else np.zeros((0, 3))

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(lo (3,), hi (3,)) [m] of the finite points (NaN where there is none)."""
        p = self.points()
        p = p[np.all(np.isfinite(p), axis=1)]
        if not len(p):
            return np.full(3, np.nan), np.full(3, np.nan)
        return p.min(axis=0), p.max(axis=0)


def static_topology(a: np.ndarray) -> np.ndarray:
    """A read-only int64 copy: topology shared by every stored frame must never be edited."""
    a = np.array(a, dtype=np.int64, copy=True)
    a.setflags(write=False)
    return a


def orient_outward(vertices: np.ndarray, faces: np.ndarray, inside: np.ndarray) -> np.ndarray:
    """Faces (F, 3) flipped where the normal points toward the interior point ``inside`` (F, 3) [m]."""
    p = vertices[faces]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    flip = np.einsum("ij,ij->i", n, p.mean(axis=1) - inside) < 0.0
    out = faces.copy()
    out[flip] = out[flip][:, ::-1]
    return out


def _box_faces() -> np.ndarray:
    # corner k of a box sits at ``rigid.CORNER_SIGNS[k]`` (bit 0: +x, bit 1: +y, bit 2: +z), the layout of
    # ``box_corners()`` of the rigid-segment bodies; each quad listed around its face
    quads = np.array([[0, 2, 6, 4], [1, 3, 7, 5], [0, 1, 5, 4], [2, 3, 7, 6], [0, 1, 3, 2], [4, 5, 7, 6]])
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    return orient_outward(CORNER_SIGNS, tris, np.zeros((len(tris), 3)))


BOX_FACES = static_topology(_box_faces())  # (12, 3) outward triangles of one box's 8 corners


@lru_cache(maxsize=None)
def boxes_faces(n: int) -> np.ndarray:
    """(12 n, 3) read-only outward triangles of n boxes whose corners are stacked 8 per box; built once per n."""
    return static_topology((BOX_FACES[None, :, :] + 8 * np.arange(n)[:, None, None]).reshape(-1, 3))


def box_triangles(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (8 n, 3) [m] (a copy) and faces (12 n, 3) of n boxes from their corners (8 n, 3) [m]."""
    return np.array(corners, dtype=np.float64, copy=True), boxes_faces(len(corners) // 8)


# The four faces of a positively oriented tet (det(X1-X0, X2-X0, X3-X0) > 0), wound outward.
_TET_FACES = np.array([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]], dtype=np.int64)


def tet_boundary_faces(tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Boundary triangles of a tet mesh: faces (F, 3) node ids, outward, and the tet (F,) each belongs to.

    tets: (m, 4) positively oriented (``fem.mesh``).  A face is on the boundary
    when exactly one tet has it.
    """
    tets = np.asarray(tets, dtype=np.int64)
    faces = tets[:, _TET_FACES].reshape(-1, 3)
    owner = np.repeat(np.arange(len(tets)), 4)
    _, inverse, counts = np.unique(np.sort(faces, axis=1), axis=0, return_inverse=True, return_counts=True)
    keep = counts[inverse.ravel()] == 1
    return faces[keep], owner[keep]


def compact(faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(node ids (V,) used by ``faces``, faces renumbered into them), both read-only: a surface scene
    stores only its surface nodes' positions, not the whole mesh's."""
    used = np.unique(faces)
    remap = np.full(int(used.max()) + 1 if len(used) else 0, -1, dtype=np.int64)
    remap[used] = np.arange(len(used))
    return static_topology(used), static_topology(remap[faces])


def legs_scene(segment_c: np.ndarray, segment_R: np.ndarray, geom: np.ndarray, angles: np.ndarray,
               states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(legs (n_legs, 3, 3) [m] O, M, P; states (n_legs,) int64) by forward kinematics.

    segment_c (n_seg, 3) [m], segment_R (n_seg, 3, 3) segment -> world; geom
    (n_legs, N_LEG_GEOM) and angles (n_legs, 3) [rad] as in ``kinematics.legs``.
    """
    from ..kinematics.legs import legs_forward_kinematics

    n = len(geom)
    O, M, P = np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3))
    legs_forward_kinematics(np.ascontiguousarray(segment_c, dtype=np.float64),
                            np.ascontiguousarray(segment_R, dtype=np.float64), geom,
                            np.ascontiguousarray(angles, dtype=np.float64), O, M, P)
    return np.stack([O, M, P], axis=1), np.array(states, dtype=np.int64, copy=True)
