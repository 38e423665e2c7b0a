"""Terrain queries callable from numba kernels.

A terrain is described to kernels by an integer kind and a float64 parameter
vector, so that every body backend can query it inside its step loop without a
Python call.  The surface is represented by a signed distance function phi
(positive above / outside the terrain, negative inside) and its unit normal.

World frame (see PAPER-NOTES.md): y is up, gravity along -y, lengths in metres.

Kinds and their parameter vectors ``f`` (float64, length >= 8):

* ``PLANE``  -- horizontal ground at height ``f[0]``.
* ``SLOPE``  -- a plane through (0, f[0], 0) inclined by angle ``f[1]`` [rad]
  about the z axis, rising toward +x (a creature facing +x climbs).
* ``SLAB``   -- Miller's book (Sec. 3, Image 1): ground at height ``f[0]`` plus a
  slab of top height ``f[1]`` occupying x <= ``f[2]`` whose top edge is
  rounded with radius ``f[3]``.

The three queries the myriapod paper asks of a terrain (Sec. 5.1) map to:
inside test ``phi < 0``, height above the surface ``phi``, and the surface
normal below a point ``surface_normal``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

PLANE = 0
SLOPE = 1
SLAB = 2

N_TERRAIN_PARAMS = 8


@njit(cache=True, error_model="numpy")
def _slab_phi(f, x, y):
    """Signed distance to the union of the ground and a rounded-edge slab (2D in x-y)."""
    ground = y - f[0]
    top, edge, r = f[1], f[2], f[3]
    # Rounded quarter-infinite box: the sharp box shrunk by r, then offset by r.
    qx = x - (edge - r)
    qy = y - (top - r)
    ox = max(qx, 0.0)
    oy = max(qy, 0.0)
    slab = math.sqrt(ox * ox + oy * oy) + min(max(qx, qy), 0.0) - r
    return min(ground, slab)


@njit(cache=True, error_model="numpy")
def signed_distance(kind, f, x, y, z):
    """phi(p) [m]: distance of point p above the terrain surface (negative inside)."""
    if kind == PLANE:
        return y - f[0]
    elif kind == SLOPE:
        s = math.sin(f[1])
        c = math.cos(f[1])
        return -s * x + c * (y - f[0])
    else:
        return _slab_phi(f, x, y)


@njit(cache=True, error_model="numpy")
def surface_normal(kind, f, x, y, z):
    """Unit outward normal (nx, ny, nz) of the terrain surface nearest to p."""
    if kind == PLANE:
        return 0.0, 1.0, 0.0
    elif kind == SLOPE:
        return -math.sin(f[1]), math.cos(f[1]), 0.0
    else:
        ground = y - f[0]
        top, edge, r = f[1], f[2], f[3]
        qx = x - (edge - r)
        qy = y - (top - r)
        ox = max(qx, 0.0)
        oy = max(qy, 0.0)
        slab = math.sqrt(ox * ox + oy * oy) + min(max(qx, qy), 0.0) - r
        if ground <= slab:
            return 0.0, 1.0, 0.0
        if qx > 0.0 and qy > 0.0:
            nrm = math.sqrt(qx * qx + qy * qy)
            return qx / nrm, qy / nrm, 0.0
        if qx > qy:
            return 1.0, 0.0, 0.0
        return 0.0, 1.0, 0.0


@njit(cache=True, error_model="numpy")
def segment_surface_intersection(kind, f, x0, y0, z0, x1, y1, z1):
    """Fraction s in [0, 1] along p0 -> p1 where the path first meets the surface.

    Miller Sec. 3, Fig. 1: a point's path over one step is intersected with the
    constraint surface.  p0 is assumed outside (phi >= 0) and p1 inside.  For the
    planar kinds the root is exact; for the slab the signed distance is piecewise
    smooth, so a few bisection-secant (Illinois) iterations resolve it to 1e-12 m.
    """
    return path_surface_fraction(kind, f, x0, y0, z0, x1, y1, z1, signed_distance(kind, f, x0, y0, z0),
                                 signed_distance(kind, f, x1, y1, z1))


@njit(cache=True, error_model="numpy")
def path_surface_fraction(kind, f, x0, y0, z0, x1, y1, z1, phi0, phi1):
    """``segment_surface_intersection`` given the end points' signed distances phi0 >= 0 > phi1."""
    if phi0 <= 0.0:
        return 0.0
    if kind != SLAB:
        return phi0 / (phi0 - phi1)
    lo, hi = 0.0, 1.0
    flo, fhi = phi0, phi1
    s = 0.0
    for _ in range(60):
        s = lo + (hi - lo) * flo / (flo - fhi)
        fs = signed_distance(kind, f, x0 + s * (x1 - x0), y0 + s * (y1 - y0), z0 + s * (z1 - z0))
        if abs(fs) < 1e-13 or hi - lo < 1e-14:
            break
        if fs > 0.0:
            lo, flo = s, fs
            fhi *= 0.5
        else:
            hi, fhi = s, fs
            flo *= 0.5
    return s


def terrain_phi_numpy(kind: int, f: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Slow reference of ``signed_distance`` for an array of points p: (n, 3) [m]."""
    p = np.asarray(p, dtype=float)
    x, y = p[:, 0], p[:, 1]
    if kind == PLANE:
        return y - f[0]
    if kind == SLOPE:
        return -np.sin(f[1]) * x + np.cos(f[1]) * (y - f[0])
    qx = x - (f[2] - f[3])
    qy = y - (f[1] - f[3])
    slab = np.hypot(np.maximum(qx, 0), np.maximum(qy, 0)) + np.minimum(np.maximum(qx, qy), 0) - f[3]
    return np.minimum(y - f[0], slab)
