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
