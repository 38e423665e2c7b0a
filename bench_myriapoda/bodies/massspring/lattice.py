"""Miller's cube lattice (Miller 1988 Sec. 3): topology and rest geometry.

Each body segment is a cube of point masses; consecutive segments share a
face.  Face j (j = 0 is the head end, n_seg the tail end) has four corner
masses, corner order c = 0..3: (ventral, left), (ventral, right),
(dorsal, left), (dorsal, right) -- see ``muscle_waves.CORNER_Y/Z``.  Node
index = 4 j + c.  In the body's rest frame the head points to +x, y is up
and z points to the creature's right.

Springs run along every cube edge and across the diagonals of every face.
Each spring has a kind that tells the kernel how muscles animate its rest
length L:

* ``AXIAL``      -- an edge along the body: L = L0 * stretch of its fibre;
* ``CROSS``      -- an edge or diagonal of a cross-section face j (shared by
  the two segments at that face): L = Lc * circumferential scale of face j
  (Miller's volume-conserving bulge);
* ``SIDE_DIAG``  -- a diagonal of a side face of segment i, spanning fibres a
  and b: L = sqrt((L0 * mean stretch)^2 + (Lc * mean face scale)^2).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.specs import SurfaceStyle
from ..scene import orient_outward, static_topology

# The lattice's kind of triangle surface in a scene (its outer faces, quads split in two) and how the
# animations draw it (``BodySpec.surface_kinds``): dark triangle edges, which show the lattice
LATTICE_SURFACE = "lattice-surface"
SURFACE_KINDS = {LATTICE_SURFACE: SurfaceStyle("#e39c9c")}

AXIAL, CROSS, SIDE_DIAG = 0, 1, 2

# The four side faces of a segment, each spanned by two axial fibres (corners).
SIDE_FACES = ((0, 1), (2, 3), (0, 2), (1, 3))  # ventral, dorsal, left, right
# Edges and diagonals of a cross-section face, as corner pairs.
CROSS_EDGES = ((0, 1), (2, 3), (0, 2), (1, 3), (0, 3), (1, 2))


@dataclass(frozen=True)
class Lattice:
    """Rest geometry and spring table of an n-segment cube lattice.

    rest_nodes: (4 (n_seg+1), 3) [m]; springs: (n_springs, 2) node indices;
    kind, seg, corner_a, corner_b: (n_springs,) ints (seg is the face index for
    CROSS springs); L0, Lc: (n_springs,) [m] undeformed axial and cross-section
    extents used to recompute rest lengths; rest_length: (n_springs,) [m].
    """

    n_seg: int
    rest_nodes: np.ndarray
    springs: np.ndarray
    kind: np.ndarray
    seg: np.ndarray
    corner_a: np.ndarray
    corner_b: np.ndarray
    L0: np.ndarray
    Lc: np.ndarray
    rest_length: np.ndarray

    @property
    def n_nodes(self) -> int:
        return self.rest_nodes.shape[0]

    @property
    def n_springs(self) -> int:
        return self.springs.shape[0]


def build_lattice(n_seg: int, seg_len: float, width: float, height: float) -> Lattice:
    """The lattice of a straight body lying along -x from the head at the origin, underside at y = 0."""
    ys = np.array([0.0, 0.0, height, height])
    zs = np.array([-width / 2, width / 2, -width / 2, width / 2])
    nodes = np.zeros((4 * (n_seg + 1), 3))
    for j in range(n_seg + 1):
        nodes[4 * j:4 * j + 4, 0] = -j * seg_len
        nodes[4 * j:4 * j + 4, 1] = ys
        nodes[4 * j:4 * j + 4, 2] = zs
    rows = []  # (i, j, kind, seg, a, b, L0, Lc)
    for j in range(n_seg + 1):
        for a, b in CROSS_EDGES:
            lc = float(np.linalg.norm(nodes[4 * j + a] - nodes[4 * j + b]))
            rows.append((4 * j + a, 4 * j + b, CROSS, j, a, b, 0.0, lc))
    for i in range(n_seg):
        for c in range(4):
            rows.append((4 * i + c, 4 * (i + 1) + c, AXIAL, i, c, c, seg_len, 0.0))
        for a, b in SIDE_FACES:
            lc = float(np.linalg.norm(nodes[4 * i + a] - nodes[4 * i + b]))
            rows.append((4 * i + a, 4 * (i + 1) + b, SIDE_DIAG, i, a, b, seg_len, lc))
            rows.append((4 * i + b, 4 * (i + 1) + a, SIDE_DIAG, i, a, b, seg_len, lc))
    r = np.array(rows, dtype=float)
    springs = r[:, :2].astype(np.int64)
    rest = np.linalg.norm(nodes[springs[:, 1]] - nodes[springs[:, 0]], axis=1)
    return Lattice(n_seg=n_seg, rest_nodes=nodes, springs=np.ascontiguousarray(springs),
                   kind=r[:, 2].astype(np.int64), seg=r[:, 3].astype(np.int64),
                   corner_a=r[:, 4].astype(np.int64), corner_b=r[:, 5].astype(np.int64),
                   L0=r[:, 6].copy(), Lc=r[:, 7].copy(), rest_length=rest)


FACE_STRIDE_MULTIPLE = 8  # doubles per AVX-512 vector: a loop over whole rows runs no scalar remainder


def face_stride(n_faces: int) -> int:
    """Columns per corner row of the step kernel's corner-major arrays: the faces and at least one padding
    column, rounded up to ``FACE_STRIDE_MULTIPLE``.

    The padding keeps corner rows apart: a spring of the last face's families with shift 1 reads its b end
    in the padding column, not on the first face of the next row; and it makes every loop over whole rows
    a whole number of vectors (a short body's rows of a few faces
    would otherwise run mostly in the scalar remainder, where sqrt and division cost about four times
    as much per spring)."""
    m = FACE_STRIDE_MULTIPLE
    return (n_faces + 1 + m - 1) // m * m


# Columns of ``SpringFamilies.index``.
FAM_A, FAM_B, FAM_SHIFT, FAM_KIND, FAM_CA, FAM_CB = range(6)
# Rows of ``SpringFamilies.params``.
PAR_K, PAR_D, PAR_L0, PAR_LC = range(4)


@dataclass(frozen=True)
class SpringFamilies:
    """The springs of a cube lattice grouped into families the step kernel runs as contiguous vectors.

    Every spring of ``build_lattice`` joins corner a of face t to corner b of face t + shift
    (shift 0: a CROSS edge inside face t; shift 1: an AXIAL edge or a SIDE_DIAG of segment t).
    Springs with the same (a, b, shift, kind, rest corners) form a family with one spring per
    face t = 0 .. n_faces - 1 - shift.  In the kernel's corner-major node layout (3, 4, stride)
    a family then reads two contiguous rows, so its loop vectorises (no index gathers).

    index: (n_fam, 6) int64, columns FAM_A, FAM_B (node corners), FAM_SHIFT, FAM_KIND and
    FAM_CA, FAM_CB (the fibres that set a spring's rest length, ``Lattice.corner_a/b``);
    params: (4, n_fam, stride) float64, rows PAR_K [N/m], PAR_D [N s/m], PAR_L0, PAR_LC [m]
    per spring (padding past n_faces - shift is zero); spring: (n_fam, stride) int64, the
    lattice's spring index of each entry (-1 in the padding).  ``stride`` = n_faces + 1
    (``face_stride``): the step kernel's corner-major arrays (3, 4, stride) carry one padding
    column per corner row.
    """

    index: np.ndarray
    params: np.ndarray
    spring: np.ndarray


def spring_families(lat: Lattice, stiffness: np.ndarray, damping: np.ndarray) -> SpringFamilies:
    """Group the springs of ``lat`` (stiffness [N/m], damping [N s/m] per spring) into families.

    Raises ValueError for a spring table that is not a cube lattice of ``build_lattice``'s kind
    (a spring spanning more than one face, or a family missing a face)."""
    n_faces = lat.n_seg + 1
    i, j = lat.springs[:, 0], lat.springs[:, 1]
    face, shift = i // 4, j // 4 - i // 4
    keys: dict[tuple, list] = {}
    for e in range(lat.n_springs):
        if shift[e] not in (0, 1):
            raise ValueError(f"spring {e} joins faces {face[e]} and {j[e] // 4}: not a cube lattice")
        key = (int(i[e] % 4), int(j[e] % 4), int(shift[e]), int(lat.kind[e]), int(lat.corner_a[e]), int(lat.corner_b[e]))
        keys.setdefault(key, []).append(e)
    n_fam = len(keys)
    index = np.zeros((n_fam, 6), dtype=np.int64)
    params = np.zeros((4, n_fam, face_stride(n_faces)))
    spring = np.full((n_fam, face_stride(n_faces)), -1, dtype=np.int64)
    for q, (key, members) in enumerate(sorted(keys.items())):
        index[q] = key
        count = n_faces - key[FAM_SHIFT]
        faces = face[members]
        if len(members) != count or sorted(faces) != list(range(count)):
            raise ValueError(f"spring family {key} covers faces {sorted(faces)}, not 0..{count - 1}: not a cube lattice")
        spring[q, faces] = members
        params[PAR_K, q, faces] = stiffness[members]
        params[PAR_D, q, faces] = damping[members]
        params[PAR_L0, q, faces] = lat.L0[members]
        params[PAR_LC, q, faces] = lat.Lc[members]
    return SpringFamilies(index=index, params=params, spring=spring)


# Miller's cube lattice's 18 spring families in ``spring_families``' order, one row of its ``index`` each
# (FAM_A, FAM_B, FAM_SHIFT, FAM_KIND, FAM_CA, FAM_CB): the same table for every body length, so the step
# kernel's column loop (``kernels.column_spring_forces``) takes it as a compile-time constant and runs every
# family inside one loop over the faces.  ``spring_families`` of any ``build_lattice`` gives exactly this
# table (checked by the body and tests/test_massspring_kernels.py).
CUBE_FAMILIES = (
    (0, 0, 1, AXIAL, 0, 0), (0, 1, 0, CROSS, 0, 1), (0, 1, 1, SIDE_DIAG, 0, 1), (0, 2, 0, CROSS, 0, 2),
    (0, 2, 1, SIDE_DIAG, 0, 2), (0, 3, 0, CROSS, 0, 3), (1, 0, 1, SIDE_DIAG, 0, 1), (1, 1, 1, AXIAL, 1, 1),
    (1, 2, 0, CROSS, 1, 2), (1, 3, 0, CROSS, 1, 3), (1, 3, 1, SIDE_DIAG, 1, 3), (2, 0, 1, SIDE_DIAG, 0, 2),
    (2, 2, 1, AXIAL, 2, 2), (2, 3, 0, CROSS, 2, 3), (2, 3, 1, SIDE_DIAG, 2, 3), (3, 1, 1, SIDE_DIAG, 1, 3),
    (3, 2, 1, SIDE_DIAG, 2, 3), (3, 3, 1, AXIAL, 3, 3),
)


def cube_plan(families=CUBE_FAMILIES) -> tuple:
    """For each corner c = 0..3 the terms of its nodes' spring force sum, in the order in which
    ``kernels.family_spring_forces`` adds them (families in order; within one, the a end before the b end):
    (family, sign, shift) with sign -1 at the spring's a end and +1 at its b end, and shift the faces
    between the node and the spring's a end (the b end of a spring of face t is on face t + shift)."""
    terms: list[list] = [[] for _ in range(4)]
    for q, (a, b, shift, _kind, _ca, _cb) in enumerate(families):
        terms[a].append((q, -1, 0))
        terms[b].append((q, 1, shift))
    return tuple(tuple(t) for t in terms)


# The cube lattice's force sums (``cube_plan``): every corner sums 9 terms (3 face edges, 2 axial edges,
# 4 side diagonals).  Written out so that the kernels take them as compile-time constants; the test
# checks them against ``cube_plan()`` and the families of ``spring_families``.
CUBE_PLAN = (
    ((0, -1, 0), (0, 1, 1), (1, -1, 0), (2, -1, 0), (3, -1, 0), (4, -1, 0), (5, -1, 0), (6, 1, 1), (11, 1, 1)),
    ((1, 1, 0), (2, 1, 1), (6, -1, 0), (7, -1, 0), (7, 1, 1), (8, -1, 0), (9, -1, 0), (10, -1, 0), (15, 1, 1)),
    ((3, 1, 0), (4, 1, 1), (8, 1, 0), (11, -1, 0), (12, -1, 0), (12, 1, 1), (13, -1, 0), (14, -1, 0), (16, 1, 1)),
    ((5, 1, 0), (9, 1, 0), (10, 1, 1), (13, 1, 0), (14, 1, 1), (15, -1, 0), (16, -1, 0), (17, -1, 0), (17, 1, 1)),
)


def lattice_surface_faces(n_cells: int) -> np.ndarray:
    """(8 n_cells + 4, 3) outward triangles of a Miller cube lattice of n_cells cubes (``build_lattice``).

    Node 4 j + c is corner c of cross-section face j; the four side faces of
    every cube and the two end faces are quads, each split into two triangles.
    The winding is fixed once on the lattice's rest shape: a body's placement is
    a proper rotation, which keeps it outward.
    """
    rest = build_lattice(n_cells, 1.0, 1.0, 1.0).rest_nodes
    tris, inside = [], []
    for i in range(n_cells):
        centre = rest[4 * i:4 * i + 8].mean(axis=0)
        for a, b in SIDE_FACES:
            q = (4 * i + a, 4 * i + b, 4 * (i + 1) + b, 4 * (i + 1) + a)
            tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
            inside += [centre, centre]
    for j, cell in ((0, 0), (n_cells, n_cells - 1)):  # the end caps; corners 0, 1, 3, 2 go around a face
        centre = rest[4 * cell:4 * cell + 8].mean(axis=0)
        q = (4 * j + 0, 4 * j + 1, 4 * j + 3, 4 * j + 2)
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
        inside += [centre, centre]
    return static_topology(orient_outward(rest, np.array(tris, dtype=np.int64), np.array(inside)))
