"""Segment frames of a deformable body: the best-fit rigid pose of each segment's nodes.

A controller reads every body's segments the same way (``core.protocols.Observation``:
seg_pos, seg_rot, seg_vel).  Rigid bodies have them as state; the lattice and the FEM mesh
have nodes, so each segment gets the pose that best fits its nodes' current positions to
their rest positions: the centroid, and the polar rotation of
A = sum_i (x_i - c)(X_i - X_c)^T (the rotation that minimises sum |R (X_i - X_c) - (x_i - c)|^2).
The rest frame is the build frame (body along -x from the head, y up, z to the right), so R
maps segment coordinates (x forward, y dorsal, z right) to world coordinates.
"""
from __future__ import annotations

from functools import cached_property

import numpy as np
from numba import njit

from ..world.terrain_kernels import signed_distance
from ..core.protocols import Actuation
from .svd_kernels import polar_rotation
from .friction_kernels import CONTACT_DISTANCE


def csr_rest_offsets(rest: np.ndarray, ptr: np.ndarray, nodes: np.ndarray) -> np.ndarray:
    """(len(nodes), 3) [m] rest offsets X_i - X_c of every segment's nodes from the segment's rest centroid."""
    out = np.empty((len(nodes), 3))
    for s in range(len(ptr) - 1):
        ids = nodes[ptr[s]:ptr[s + 1]]
        out[ptr[s]:ptr[s + 1]] = rest[ids] - rest[ids].mean(axis=0)
    return out


@njit(cache=True, error_model="numpy")
def best_fit_frames(x, v, ptr, nodes, rest_off, pos, rot, vel, A):
    """OVERWRITE pos (n_seg, 3) [m], rot (n_seg, 3, 3), vel (n_seg, 3) [m/s] of every segment.

    x, v: (n_nodes, 3) [m], [m/s]; ptr (n_seg + 1,), nodes: CSR of each segment's node ids;
    rest_off (len(nodes), 3) [m]: ``csr_rest_offsets``; A (3, 3) scratch.  vel is the mean node
    velocity (the centroid's velocity, equal node weights as for pos).
    """
    for s in range(ptr.shape[0] - 1):
        a0, a1 = ptr[s], ptr[s + 1]
        m = a1 - a0
        cx = cy = cz = 0.0
        ux = uy = uz = 0.0
        for a in range(a0, a1):
            k = nodes[a]
            cx += x[k, 0]
            cy += x[k, 1]
            cz += x[k, 2]
            ux += v[k, 0]
            uy += v[k, 1]
            uz += v[k, 2]
        pos[s, 0], pos[s, 1], pos[s, 2] = cx / m, cy / m, cz / m
        vel[s, 0], vel[s, 1], vel[s, 2] = ux / m, uy / m, uz / m
        for i in range(3):
            for j in range(3):
                A[i, j] = 0.0
        for a in range(a0, a1):
            k = nodes[a]
            for i in range(3):
                d = x[k, i] - pos[s, i]
                for j in range(3):
                    A[i, j] += d * rest_off[a, j]
        polar_rotation(A, rot[s])


@njit(cache=True)
def segments_touching(x, ptr, nodes, terr_kind, terr, distance, out):
    """OVERWRITE out (n_seg,) bool: a segment touches when any of its nodes is within ``distance``
    [m] of the terrain (the friction models' contact distance)."""
    for s in range(ptr.shape[0] - 1):
        out[s] = False
        for a in range(ptr[s], ptr[s + 1]):
            k = nodes[a]
            if signed_distance(terr_kind, terr, x[k, 0], x[k, 1], x[k, 2]) < distance:
                out[s] = True
                break


@njit(cache=True)
def groups_touching(points, group_size, terr_kind, terr, distance, out):
    """OVERWRITE out (n_groups,) bool: group s (points s*group_size ... (s+1)*group_size - 1, e.g. a
    box's 8 corners) touches when any of its points is within ``distance`` [m] of the terrain."""
    for s in range(out.shape[0]):
        out[s] = False
        for a in range(s * group_size, (s + 1) * group_size):
            if signed_distance(terr_kind, terr, points[a, 0], points[a, 1], points[a, 2]) < distance:
                out[s] = True
                break


class NodeSegments:
    """Observation and rest actuation of a body whose segments are groups of nodes (the lattice,
    the FEM mesh).  A subclass sets ``x``, ``v`` (n_nodes, 3), ``case``, ``n_segments``, the CSR
    ``seg_ptr`` / ``seg_nodes`` of each segment's nodes, ``seg_rest_offsets``
    (``csr_rest_offsets``), ``terr_kind`` / ``terr`` and ``fric``."""

    @cached_property
    def _rest_actuation(self) -> Actuation:
        """No muscle strain: what ``advance`` reads when given no actuation."""
        return Actuation.for_body(self)

    def sense(self, obs, t: float) -> None:
        """Control fields of ``obs``: each segment's best-fit frame of its nodes (module docstring)."""
        n = self.n_segments
        if obs.seg_pos is None or obs.seg_pos.shape[0] != n:
            obs.seg_pos, obs.seg_rot, obs.seg_vel = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros((n, 3))
            cre = self.case.creature
            obs.seg_half = np.tile(0.5 * np.array([cre.segment_length_m, cre.height_m, cre.width_m]), (n, 1))
            self._A = np.zeros((3, 3))
        obs.t = t
        best_fit_frames(self.x, self.v, self.seg_ptr, self.seg_nodes, self.seg_rest_offsets, obs.seg_pos,
                        obs.seg_rot, obs.seg_vel, self._A)

    def _observe_segments(self, obs, t: float):
        """Fill the control fields and ``seg_contact`` (any node within the friction contact distance)."""
        self.sense(obs, t)
        obs.seg_contact = np.zeros(self.n_segments, dtype=bool)
        segments_touching(self.x, self.seg_ptr, self.seg_nodes, self.terr_kind, self.terr,
                          self.fric[CONTACT_DISTANCE], obs.seg_contact)
        return obs
