"""Terrain queries callable from numba kernels.

A terrain is described to kernels by an integer kind and a float64 parameter
vector ``f``, so that every body backend can query it inside its step loop
without a Python call.  The surface is represented by a signed distance
function phi (positive above / outside the terrain, negative inside) and its
unit outward normal.

World frame (see PAPER-NOTES.md): y is up, gravity along -y, lengths in metres.

The three queries the myriapod paper asks of a terrain (Sec. 5.1) map to:
inside test ``phi < 0``, height above the surface ``phi``, and the surface
normal below a point ``surface_normal``.  ``path_surface_fraction`` adds where
a straight path first meets the surface (Miller Sec. 3).

The parameter vector ``f``
--------------------------
``f`` is one float64 array: an 8-value header, then data blocks of the kinds
that need more than the header.  Counts and indices are stored as float64
(exact for any array that fits in memory).  A vector of 8 zeros is the plane
y = 0 without obstacles, so older callers that pass ``np.zeros(8)`` with a few
leading values keep working.

Header::

    f[0]  ground height [m] (PLANE, SLOPE, SLAB, HEIGHTFIELD; MESH: optional ground plane)
    f[1]  SLOPE: angle [rad]; SLAB: top height [m]; MESH: 1.0 when the ground plane y = f[0] is
          part of the terrain as well as the mesh, 0.0 for the mesh alone
    f[2]  SLAB: x of the edge [m]
    f[3]  SLAB: edge radius [m]
    f[4]  H_DATA   index in f of the kind's data block (HEIGHTFIELD, MESH); 0: none
    f[5]  H_NDATA  HEIGHTFIELD: number of Gaussians; MESH: length of the mesh block
    f[6]  H_OBST   index in f of the obstacle block; 0: none
    f[7]  H_NOBST  number of obstacles (records of OBST_STRIDE values)

Kinds:

* ``PLANE``  -- horizontal ground at height ``f[0]``.
* ``SLOPE``  -- a plane through (0, f[0], 0) inclined by angle ``f[1]`` [rad]
  about the z axis, rising toward +x (a creature facing +x climbs).
* ``SLAB``   -- Miller's book (Sec. 3, Image 1): ground at height ``f[0]`` plus a
  slab of top height ``f[1]`` occupying x <= ``f[2]`` whose top edge is
  rounded with radius ``f[3]``.
* ``HEIGHTFIELD`` -- the paper's Gaussian-mixture terrain (Sec. 6.2):
  y = h(x, z) = f[0] + sum_k a_k exp(-((x - cx_k)^2 + (z - cz_k)^2) / (2 s_k^2)).
  Block at f[4], f[5] Gaussians of HF_STRIDE = 5 values: ``cx, cz, a, s, 1/(2 s^2)``;
  a Gaussian is skipped beyond 8.5 s from its centre (exp(-36) = 2.3e-16: below
  float64's resolution of its amplitude), so a query costs one exp per nearby Gaussian.
  phi = (y - h) / sqrt(1 + |grad h|^2): y - h is not a distance (on a slope of
  gradient g it overestimates the distance by sqrt(1 + g^2)); divided by the
  gradient norm it is the first-order distance, exact on the surface (where
  its gradient is the unit normal) and for planar h, with an error of order
  curvature * phi^2 off the surface.  Its sign is the sign of y - h exactly.
  Normal: (-h_x, 1, -h_z) / sqrt(1 + h_x^2 + h_z^2) at (x, z).
* ``MESH`` -- a closed (watertight, consistently oriented) triangle mesh, queried
  through a uniform-grid spatial hash (Sec. 5.1) built once per mesh by
  ``bench_myriapoda.world.meshes`` (cells of h = a few mean edge lengths, each
  listing the triangles whose bounding box overlaps it).  Three zones:

  - |phi| < exact band (default h / 4; ``meshes.mesh_block(exact_cells=...)``):
    phi is the exact signed Euclidean distance to the nearest triangle
    (``mesh_exact``: a ring search of the hash around p), its sign from the
    angle-weighted pseudo-normal of the closest feature (face, edge or vertex;
    Baerentzen & Aanaes 2005), the normal (p - c)/|p - c| times the sign with c
    the closest point (the gradient of phi; the pseudo-normal on the surface).
  - up to the band (default a tenth of the bounding-box diagonal): the far
    field, the trilinear interpolation of exact distances stored at the grid
    corners, with its normalised gradient as the normal.  Its sign is exact;
    the value is accurate to O(h^2 x curvature) (on the default 101,568-triangle
    skull: median 0.25 %, 99th percentile 1.5 % of the distance; never off by
    more than sqrt(3) h, the field being 1-Lipschitz).  A point is in the far
    field only when the 8 corners of its cell share a sign and
    max_k (|phi_k| - |p - x_k|) >= exact band, so every point nearer than the
    exact band gets the exact distance.  With exact band = band
    (``exact_cells=inf``) every distance within the band is exact.
  - beyond the band: phi is clamped to +band outside and -band inside (a body
    far from the mesh is outside/above it: +band), the normal points from the
    mesh centroid to p.  Points outside the hash grid, which extends band + h
    beyond the mesh's bounding box, get +band at once.  Beyond the band the
    side comes from the inside/outside flag of the cell centre, which is on the
    same side as any point of the cell more than a cell size from the surface.

  ``mesh_down`` is minus the normal: "down" toward the nearest surface (Fig. 1).
  Mesh block at m = f[4] (offsets inside it are relative to m)::

      m+0  h, cell size [m]       m+1  1/h           m+2..4  grid origin (x, y, z) [m]
      m+5..7  cells (nx, ny, nz)  m+8  band [m]      m+9  triangles T     m+10 vertices V
      m+11 cells table offset (CELL_STRIDE = 4 per cell, cell (i, j, k) at (i*ny + j)*nz + k:
           first list entry, triangle count, inside (-1) / outside (+1) of the centre,
           Chebyshev distance in cells to the nearest occupied cell)
      m+12 triangle list offset (triangle indices of every cell, concatenated)
      m+13 triangle offset (TRI_STRIDE = 16 per triangle: a, b, c, unit face normal,
           bounding sphere centre and radius)
      m+14 edge pseudo-normal offset (T x 9: edges ab, bc, ca, unit)
      m+15 triangle vertex indices offset (T x 3)
      m+16 vertex pseudo-normal offset (V x 3, angle-weighted, unit)
      m+17..19 area-weighted centroid of the mesh [m]
      m+20 corner offset (CORNER_STRIDE = 2 per corner, corner (i, j, k) at
           (i*(ny+1) + j)*(nz+1) + k: signed distance clamped to +-band, nearest
           triangle or -1)
      m+21 exact band [m]
      m+22 triangle adjacency offset (T x 3: the triangle across edge ab, bc, ca)
      m+23 vertex ring pointer offset (V + 1), m+24 vertex ring offset (3 T triangles)
      m+25..31 reserved

Obstacles (any kind): phi = min(phi_base, phi of every obstacle) -- exact
outside the union of solids.  Block at f[6], f[7] records of OBST_STRIDE = 10::

    cylinder (vertical):  OBST_CYLINDER, cx, cz, radius, y_bottom, y_top, 0, 0, 0, 0
    box (yaw about +y):   OBST_BOX, cx, cy, cz, half_x, half_y, half_z, cos(yaw), sin(yaw), 0

The box's local x axis is (cos yaw, 0, -sin yaw) in the world (a rotation by
yaw about +y).

Obstacle grid: ``with_obstacles`` appends, right after the records, a uniform
grid over the x-z plane built once per terrain, so that a query examines the
obstacles near p and not all of them (``obstacles_below``).  Each record has
an x-z footprint square (a cylinder: centre +- radius; a box: centre +-
sqrt(half_x^2 + half_z^2), the square its yaw can sweep); each cell has two
lists: the records whose square overlaps it, and those whose square widened
by the reach D = GRID_REACH_CELLS cells overlaps it.  A query inside the grid
whose cutoff (the base terrain's phi) is at most D -- a body or leg point
within D of the ground, the common case -- reads the widened list of p's own
cell and nothing else: every record nearer than the cutoff is on it.
Otherwise it visits the plain lists of rings of cells around p's cell (p
projected onto the grid when outside it) and stops when the ring's Chebyshev
distance from p exceeds the nearest obstacle found -- a lower bound of every
obstacle not yet visited.  The answer
is the brute-force loop's to the bit (``obstacles_below_brute``; ties go to
the lowest record, as the loop's strict ``<`` does).  Block at
g = f[6] + OBST_STRIDE * f[7] (absolute offsets)::

    g+0  cell size h [m]   g+1  1/h   g+2, g+3  grid origin (x0, z0) [m]
    g+4, g+5  cells (nx, nz)   g+6  cells table offset (GRID_CELL_STRIDE = 4 per cell,
    cell (i, k) at i*nz + k: first list entry and record count of the plain list, then of
    the widened list)   g+7  list offset
    (the first f-index of every listed record, cell after cell)   g+8  reach D [m]
    g+9  cell tops offset (one value per cell, i*nz + k: the highest top [m] of the records on
    its widened list, raised by GRID_TOP_MARGIN; -inf for an empty list)

Threshold queries: ``distance_at_least(kind, f, p, d)`` answers ``signed_distance >= d``
(the same boolean, NaN included) without searching the obstacles where none can be
nearer than d: p inside the grid at least d above its cell's top, or p outside the grid
(every footprint is then farther than D).  Issue 30: the walking hybrid centipede asks
about 620 terrain queries a step, most of them "is this point clear of the ground?" for
body nodes and box corners 0.65 m up, above obstacles at most 0.4 m high; each went
through the grid search (about 80 ns) where a cell-top comparison answers it.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

PLANE = 0
SLOPE = 1
SLAB = 2
HEIGHTFIELD = 3
MESH = 4
KIND_NAMES = {PLANE: "plane", SLOPE: "slope", SLAB: "slab", HEIGHTFIELD: "heightfield", MESH: "mesh"}

N_TERRAIN_PARAMS = 8  # header length; f may be longer
H_DATA = 4
H_NDATA = 5
H_OBST = 6
H_NOBST = 7

HF_STRIDE = 5

OBST_STRIDE = 10
OBST_CYLINDER = 1
OBST_BOX = 2
GRID_HDR = 10
GRID_REACH_CELLS = 1.5       # a cell also lists the records within this many cells of it (module docstring)
GRID_CELL_STRIDE = 4
GRID_CELL_DIAMETERS = 1.0    # cell size = this x the mean footprint width (each record overlaps ~4 cells)
GRID_MAX_CELLS_PER_RECORD = 16  # coarser cells when the obstacles are so sparse that the grid would be larger
GRID_MIN_CELLS = 64
# the ring bound and the footprint rasterisation are computed in float64: both are given this slack
# [in cells] so that rounding can only make the search visit more, never fewer, cells than needed
GRID_SLACK_CELLS = 1e-7
# a cell's top is raised by this (relative to max(1, |top|)) so that the cell-top comparison of
# ``distance_at_least`` stays a lower bound of every listed record's computed phi after rounding
GRID_TOP_MARGIN = 1e-9

# mesh block header (relative to the block start)
MB_H, MB_INVH, MB_ORIGIN, MB_DIMS, MB_BAND, MB_NTRI, MB_NVERT = 0, 1, 2, 5, 8, 9, 10
MB_CELLS, MB_LIST, MB_TRI, MB_EDGEN, MB_TRIV, MB_VERTN, MB_CENTROID = 11, 12, 13, 14, 15, 16, 17
MB_CORNERS, MB_EXACT, MB_ADJ, MB_RINGPTR, MB_RING = 20, 21, 22, 23, 24
CORNER_STRIDE = 2
MESH_HDR = 32
CELL_STRIDE = 4
TRI_STRIDE = 16

# closest-feature codes of ``closest_point_triangle``
FEAT_FACE, FEAT_A, FEAT_B, FEAT_C, FEAT_AB, FEAT_BC, FEAT_CA = 0, 1, 2, 3, 4, 5, 6


# --------------------------------------------------------------------------- slab

@njit(cache=True, error_model="numpy", inline="always")
def _slab_parts(f, x, y):
    """(ground's phi, slab's phi, qx, qy) at (x, y): the rounded quarter-infinite box is the sharp box shrunk
    by r, then offset by r; q is p relative to the shrunk box's corner."""
    ground = y - f[0]
    top, edge, r = f[1], f[2], f[3]
    qx = x - (edge - r)
    qy = y - (top - r)
    ox = max(qx, 0.0)
    oy = max(qy, 0.0)
    return ground, math.sqrt(ox * ox + oy * oy) + min(max(qx, qy), 0.0) - r, qx, qy


@njit(cache=True, error_model="numpy")
def _slab_phi(f, x, y):
    """Signed distance to the union of the ground and a rounded-edge slab (2D in x-y)."""
    ground, slab, _, _ = _slab_parts(f, x, y)
    return min(ground, slab)


@njit(cache=True, error_model="numpy")
def _slab_normal(f, x, y):
    ground, slab, qx, qy = _slab_parts(f, x, y)
    if ground <= slab:
        return 0.0, 1.0, 0.0
    if qx > 0.0 and qy > 0.0:
        nrm = math.sqrt(qx * qx + qy * qy)
        return qx / nrm, qy / nrm, 0.0
    if qx > qy:
        return 1.0, 0.0, 0.0
    return 0.0, 1.0, 0.0


# --------------------------------------------------------------------------- height field

@njit(cache=True, error_model="numpy")
def heightfield_height(f, x, z):
    """(h, dh/dx, dh/dz) of a HEIGHTFIELD terrain at (x, z) [m, -, -]."""
    off = int(f[H_DATA])
    n = int(f[H_NDATA])
    h = f[0]
    hx = 0.0
    hz = 0.0
    for k in range(n):
        j = off + HF_STRIDE * k
        dx = x - f[j]
        dz = z - f[j + 1]
        c = f[j + 4]
        q = c * (dx * dx + dz * dz)
        if q < 36.0:  # beyond 8.5 s: exp(-36) = 2.3e-16, below float64's resolution of a
            e = f[j + 2] * math.exp(-q)
            h += e
            hx -= 2.0 * c * dx * e
            hz -= 2.0 * c * dz * e
    return h, hx, hz


@njit(cache=True, error_model="numpy")
def _hf_phi(f, x, y, z):
    h, hx, hz = heightfield_height(f, x, z)
    return (y - h) / math.sqrt(1.0 + hx * hx + hz * hz)


@njit(cache=True, error_model="numpy")
def _hf_normal(f, x, y, z):
    h, hx, hz = heightfield_height(f, x, z)
    inv = 1.0 / math.sqrt(1.0 + hx * hx + hz * hz)
    return -hx * inv, inv, -hz * inv


# --------------------------------------------------------------------------- obstacles

@njit(cache=True, error_model="numpy")
def _obstacle_phi(f, j, x, y, z):
    """Exact signed distance to obstacle record j (index of its first value in f)."""
    if f[j] == OBST_CYLINDER:
        dx = x - f[j + 1]
        dz = z - f[j + 2]
        dr = math.sqrt(dx * dx + dz * dz) - f[j + 3]
        dy = max(f[j + 4] - y, y - f[j + 5])
        a = max(dr, 0.0)
        b = max(dy, 0.0)
        return math.sqrt(a * a + b * b) + min(max(dr, dy), 0.0)
    # box: p in the box frame (rotation by -yaw about y)
    c, s = f[j + 7], f[j + 8]
    px, py, pz = x - f[j + 1], y - f[j + 2], z - f[j + 3]
    lx = c * px - s * pz
    lz = s * px + c * pz
    qx = abs(lx) - f[j + 4]
    qy = abs(py) - f[j + 5]
    qz = abs(lz) - f[j + 6]
    a = max(qx, 0.0)
    b = max(qy, 0.0)
    d = max(qz, 0.0)
    return math.sqrt(a * a + b * b + d * d) + min(max(qx, max(qy, qz)), 0.0)


@njit(cache=True, error_model="numpy")
def _obstacle_normal(f, j, x, y, z):
    """Unit outward normal (gradient of the signed distance) of obstacle record j at p."""
    if f[j] == OBST_CYLINDER:
        dx = x - f[j + 1]
        dz = z - f[j + 2]
        rho = math.sqrt(dx * dx + dz * dz)
        if rho > 0.0:
            ux, uz = dx / rho, dz / rho
        else:
            ux, uz = 1.0, 0.0
        dr = rho - f[j + 3]
        dtop = y - f[j + 5]
        dbot = f[j + 4] - y
        dy = max(dtop, dbot)
        sy = 1.0 if dtop >= dbot else -1.0
        if dr > 0.0 and dy > 0.0:
            nrm = math.sqrt(dr * dr + dy * dy)
            return ux * dr / nrm, sy * dy / nrm, uz * dr / nrm
        if dr > dy:
            return ux, 0.0, uz
        return 0.0, sy, 0.0
    c, s = f[j + 7], f[j + 8]
    px, py, pz = x - f[j + 1], y - f[j + 2], z - f[j + 3]
    lx = c * px - s * pz
    lz = s * px + c * pz
    sx = 1.0 if lx >= 0.0 else -1.0
    sy = 1.0 if py >= 0.0 else -1.0
    sz = 1.0 if lz >= 0.0 else -1.0
    qx = abs(lx) - f[j + 4]
    qy = abs(py) - f[j + 5]
    qz = abs(lz) - f[j + 6]
    if qx > 0.0 or qy > 0.0 or qz > 0.0:
        a = max(qx, 0.0)
        b = max(qy, 0.0)
        d = max(qz, 0.0)
        nrm = math.sqrt(a * a + b * b + d * d)
        nx, ny, nz = sx * a / nrm, sy * b / nrm, sz * d / nrm
    elif qx >= qy and qx >= qz:
        nx, ny, nz = sx, 0.0, 0.0
    elif qy >= qz:
        nx, ny, nz = 0.0, sy, 0.0
    else:
        nx, ny, nz = 0.0, 0.0, sz
    # back to the world frame (rotation by +yaw about y)
    return c * nx + s * nz, ny, -s * nx + c * nz


@njit(cache=True, error_model="numpy")
def obstacle_normal(f, j, x, y, z):
    """Unit outward normal of obstacle record j (the f-index ``obstacles_below`` returns) at p."""
    return _obstacle_normal(f, j, x, y, z)


@njit(cache=True, error_model="numpy")
def obstacles_phi(f, x, y, z):
    """(phi, record index) of the nearest obstacle; (inf, -1) without obstacles."""
    return obstacles_below(f, x, y, z, np.inf)


@njit(cache=True, error_model="numpy", inline="always")
def _obstacle_bound(f, j, x, y, z):
    """Cheap lower bound of obstacle j's phi at p: per axis against its footprint square and y range."""
    if f[j] == OBST_CYLINDER:
        return max(max(abs(x - f[j + 1]), abs(z - f[j + 2])) - f[j + 3], max(f[j + 4] - y, y - f[j + 5]))
    return max(max(abs(x - f[j + 1]), abs(z - f[j + 3])) - math.sqrt(f[j + 4] ** 2 + f[j + 6] ** 2),
               abs(y - f[j + 2]) - f[j + 5])


@njit(cache=True, error_model="numpy", inline="always")
def _scan_cell(f, c, lst, x, y, z, best, arg):
    """(best, arg, records examined) after the records of the grid cell at f-index c."""
    s0 = int(f[c])
    m = int(f[c + 1])
    for e in range(s0, s0 + m):
        j = int(f[lst + e])
        lb = _obstacle_bound(f, j, x, y, z)
        # skip as the loop would, except that an equal bound may still tie with a lower record
        if lb > best or (lb == best and (arg < 0 or j >= arg)):
            continue
        d = _obstacle_phi(f, j, x, y, z)
        if d < best or (d == best and arg >= 0 and j < arg):
            best = d
            arg = j
    return best, arg, m


@njit(cache=True, error_model="numpy")
def obstacles_below(f, x, y, z, best):
    """(phi, record index) of the nearest obstacle if it is nearer than ``best``, else (best, -1).

    Through the obstacle grid (module docstring); the result equals
    ``obstacles_below_brute``'s bit for bit.  A point that the grid's cell tops show to be at least
    ``best`` from every obstacle (``_obstacles_clear``: a small cutoff above the obstacles, as the
    obstacle-penetration metric's 0 for body points) gets (best, -1) without the search: what the search
    returns there, since only a record nearer than best changes it.
    """
    if f[H_NOBST] > 0.0 and _obstacles_clear(f, x, y, z, best):
        return best, -1
    d, j, _ = _grid_below(f, x, y, z, best)
    return d, j


@njit(cache=True, error_model="numpy")
def obstacles_below_counted(f, x, y, z, best):
    """``obstacles_below`` plus the number of obstacle records it examined (grid entries visited).

    The count is the query's cost, independent of the machine: tests assert that it
    does not grow with the number of obstacles of a scene of a given density.
    """
    return _grid_below(f, x, y, z, best)


@njit(cache=True, error_model="numpy", inline="always")
def _grid_below(f, x, y, z, best):
    """``obstacles_below_counted``'s search, inlined into each of the few kernels that answer a terrain query
    (``_min_obstacles``, ``_obstacle_or_base_normal``, ``_phi_at_least``, ``distance_and_normal``,
    ``obstacles_below``): one call per query instead of
    a chain of three (each call passes f and updates its reference count; issue 30 measured the chain at
    about two thirds of an obstacle query's cost when no obstacle is near)."""
    off = int(f[H_OBST])
    n = int(f[H_NOBST])
    g = off + OBST_STRIDE * n
    h, invh, x0, z0 = f[g], f[g + 1], f[g + 2], f[g + 3]
    nx, nz = int(f[g + 4]), int(f[g + 5])
    cells, lst = int(f[g + 6]), int(f[g + 7])
    reach = f[g + 8]
    arg = -1
    examined = 0
    # p in cell units, projected onto the grid (a per-axis clamp: it brings p no farther from any
    # point of the grid, so distances from the projection are lower bounds of distances from p)
    u = (x - x0) * invh
    v = (z - z0) * invh
    if not (u == u and v == v):  # nan: no answer the loop would trust either
        d, j = obstacles_below_brute(f, x, y, z, best)
        return d, j, n
    qu = min(max(u, 0.0), float(nx))
    qv = min(max(v, 0.0), float(nz))
    out = max(max(u - qu, qu - u), max(v - qv, qv - v)) * h  # Chebyshev distance of p from the grid [m]
    slack = GRID_SLACK_CELLS * h
    # outside the grid, every footprint is at least out + reach away (the grid holds the widened squares);
    # inside it, p may be inside an obstacle (best < 0)
    if out > 0.0 and out + reach - slack > best:
        return best, -1, 0
    ci = min(int(qu), nx - 1)
    ck = min(int(qv), nz - 1)
    if out == 0.0 and best <= reach - slack:
        # every record with a bound below best has its footprint within reach of p: listed in p's cell's
        # widened list; and in its plain list when p is at least best (+ the slack) inside the cell, since
        # such a footprint then overlaps the cell (a near-ground query: a leg's tip, a cutoff of 0).  Either
        # list holds every record that can change (best, -1), so both give the same answer; the plain one is
        # about a fifth as long at Fig. 13's density
        fu = qu - ci
        fv = qv - ck
        inner = min(min(fu, 1.0 - fu), min(fv, 1.0 - fv)) - GRID_SLACK_CELLS
        c0 = cells + GRID_CELL_STRIDE * (ci * nz + ck)
        best, arg, m = _scan_cell(f, c0 if (inner >= 0.0 and best * invh <= inner) else c0 + 2, lst, x, y, z,
                                  best, arg)
        return best, arg, m
    kmax = max(max(ci, nx - 1 - ci), max(ck, nz - 1 - ck))
    for ring in range(kmax + 1):
        if ring > 0:
            # every record not yet listed lies outside the (2 ring - 1)^2 cells around (ci, ck)
            side = min(min(qu - (ci - ring + 1), (ci + ring) - qu), min(qv - (ck - ring + 1), (ck + ring) - qv))
            if max(side * h, out) - slack > best:
                break
        for i in range(max(ci - ring, 0), min(ci + ring, nx - 1) + 1):
            if i == ci - ring or i == ci + ring:  # a whole column of the ring
                for k in range(max(ck - ring, 0), min(ck + ring, nz - 1) + 1):
                    best, arg, m = _scan_cell(f, cells + GRID_CELL_STRIDE * (i * nz + k), lst, x, y, z, best, arg)
                    examined += m
            else:  # the ring's two ends of this column
                if ck - ring >= 0:
                    best, arg, m = _scan_cell(f, cells + GRID_CELL_STRIDE * (i * nz + ck - ring), lst, x, y, z,
                                              best, arg)
                    examined += m
                if ring > 0 and ck + ring <= nz - 1:
                    best, arg, m = _scan_cell(f, cells + GRID_CELL_STRIDE * (i * nz + ck + ring), lst, x, y, z,
                                              best, arg)
                    examined += m
    return best, arg, examined


@njit(cache=True, error_model="numpy")
def obstacles_within(f, x, y, z, radius, out):
    """Record indices j (f-index, ascending) of the obstacles with phi_j(p) < radius, written to out; how many.

    The set and order of the loop ``for j in records: if phi_j < radius`` (the antennae's
    near list), through the grid: only the plain lists of the cells within radius of p
    (Chebyshev, in x-z) are read, since phi_j >= the footprint's Chebyshev distance.
    out: (>= number of obstacles,) int64.
    """
    off = int(f[H_OBST])
    n = int(f[H_NOBST])
    if n == 0:
        return 0
    g = off + OBST_STRIDE * n
    h, invh, x0, z0 = f[g], f[g + 1], f[g + 2], f[g + 3]
    nx, nz = int(f[g + 4]), int(f[g + 5])
    cells, lst = int(f[g + 6]), int(f[g + 7])
    r = radius + GRID_SLACK_CELLS * h
    i0 = max(int(math.floor((x - r - x0) * invh)), 0)
    i1 = min(int(math.floor((x + r - x0) * invh)), nx - 1)
    k0 = max(int(math.floor((z - r - z0) * invh)), 0)
    k1 = min(int(math.floor((z + r - z0) * invh)), nz - 1)
    m = 0
    for i in range(i0, i1 + 1):
        for k in range(k0, k1 + 1):
            c = cells + GRID_CELL_STRIDE * (i * nz + k)
            s0 = int(f[c])
            for e in range(s0, s0 + int(f[c + 1])):
                j = int(f[lst + e])
                seen = False
                for q in range(m):
                    if out[q] == j:
                        seen = True
                        break
                if seen or not _obstacle_phi(f, j, x, y, z) < radius:
                    continue
                # insert in ascending order: the loop's order
                q = m
                while q > 0 and out[q - 1] > j:
                    out[q] = out[q - 1]
                    q -= 1
                out[q] = j
                m += 1
    return m


@njit(cache=True, error_model="numpy")
def obstacles_below_brute(f, x, y, z, best):
    """The reference of ``obstacles_below``: every obstacle, in record order.

    An obstacle whose cheap lower bound (per axis, against its bounding box)
    is not below the best so far is skipped: near the ground (best = the base
    terrain's phi, small) almost every obstacle is.
    """
    off = int(f[H_OBST])
    n = int(f[H_NOBST])
    arg = -1
    for k in range(n):
        j = off + OBST_STRIDE * k
        lb = _obstacle_bound(f, j, x, y, z)
        if lb >= best:
            continue
        d = _obstacle_phi(f, j, x, y, z)
        if d < best:
            best = d
            arg = j
    return best, arg


# --------------------------------------------------------------------------- closed meshes

@njit(cache=True, error_model="numpy")
def closest_point_triangle(px, py, pz, ax, ay, az, bx, by, bz, cx, cy, cz):
    """Closest point of triangle abc to p and its feature code (Ericson, RTCD 5.1.5)."""
    # Deliberately unrolled, as Ericson writes it: the vertex and edge regions are tested one after another in
    # straight-line code (``duplicates`` pairs its alike blocks; a loop over the regions would reorder the tests)
    abx, aby, abz = bx - ax, by - ay, bz - az
    acx, acy, acz = cx - ax, cy - ay, cz - az
    apx, apy, apz = px - ax, py - ay, pz - az
    d1 = abx * apx + aby * apy + abz * apz
    d2 = acx * apx + acy * apy + acz * apz
    if d1 <= 0.0 and d2 <= 0.0:
        return ax, ay, az, FEAT_A
    bpx, bpy, bpz = px - bx, py - by, pz - bz
    d3 = abx * bpx + aby * bpy + abz * bpz
    d4 = acx * bpx + acy * bpy + acz * bpz
    if d3 >= 0.0 and d4 <= d3:
        return bx, by, bz, FEAT_B
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
        v = d1 / (d1 - d3)
        return ax + v * abx, ay + v * aby, az + v * abz, FEAT_AB
    cpx, cpy, cpz = px - cx, py - cy, pz - cz
    d5 = abx * cpx + aby * cpy + abz * cpz
    d6 = acx * cpx + acy * cpy + acz * cpz
    if d6 >= 0.0 and d5 <= d6:
        return cx, cy, cz, FEAT_C
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
        w = d2 / (d2 - d6)
        return ax + w * acx, ay + w * acy, az + w * acz, FEAT_CA
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and (d4 - d3) >= 0.0 and (d5 - d6) >= 0.0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return bx + w * (cx - bx), by + w * (cy - by), bz + w * (cz - bz), FEAT_BC
    denom = 1.0 / (va + vb + vc)
    v = vb * denom
    w = vc * denom
    return ax + abx * v + acx * w, ay + aby * v + acy * w, az + abz * v + acz * w, FEAT_FACE


@njit(cache=True, error_model="numpy")
def _pseudo_normal(f, m, t, feat):
    """Unit angle-weighted pseudo-normal of feature ``feat`` of triangle t."""
    if feat == FEAT_FACE:
        j = m + int(f[m + MB_TRI]) + TRI_STRIDE * t + 9
        return f[j], f[j + 1], f[j + 2]
    if feat >= FEAT_AB:
        j = m + int(f[m + MB_EDGEN]) + 9 * t + 3 * (feat - FEAT_AB)
        return f[j], f[j + 1], f[j + 2]
    v = int(f[m + int(f[m + MB_TRIV]) + 3 * t + (feat - FEAT_A)])
    j = m + int(f[m + MB_VERTN]) + 3 * v
    return f[j], f[j + 1], f[j + 2]


@njit(cache=True, error_model="numpy")
def _cell_tris(f, m, cell, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat):
    """Test the triangles listed in a cell; return the updated best candidate."""
    cb = m + int(f[m + MB_CELLS]) + CELL_STRIDE * cell
    n = int(f[cb + 1])
    if n == 0:
        return best2, bqx, bqy, bqz, bt, bfeat
    lst = m + int(f[m + MB_LIST]) + int(f[cb])
    tri0 = m + int(f[m + MB_TRI])
    bd = math.sqrt(best2)
    for q in range(n):
        t = int(f[lst + q])
        j = tri0 + TRI_STRIDE * t
        # lower bounds of the distance to the triangle: to its bounding sphere, to its plane
        sx, sy, sz = px - f[j + 12], py - f[j + 13], pz - f[j + 14]
        rb = bd + f[j + 15]
        if sx * sx + sy * sy + sz * sz >= rb * rb:
            continue
        ax, ay, az = f[j], f[j + 1], f[j + 2]
        pd = (px - ax) * f[j + 9] + (py - ay) * f[j + 10] + (pz - az) * f[j + 11]
        if pd * pd >= best2:
            continue
        qx, qy, qz, feat = closest_point_triangle(px, py, pz, ax, ay, az, f[j + 3], f[j + 4], f[j + 5],
                                                  f[j + 6], f[j + 7], f[j + 8])
        dx, dy, dz = px - qx, py - qy, pz - qz
        d2 = dx * dx + dy * dy + dz * dz
        if d2 < best2:
            best2, bqx, bqy, bqz, bt, bfeat = d2, qx, qy, qz, t, feat
            bd = math.sqrt(d2)
    return best2, bqx, bqy, bqz, bt, bfeat


@njit(cache=True, error_model="numpy")
def mesh_exact(f, m, px, py, pz, band, t0):
    """Exact signed distance and outward normal of the closed mesh whose block starts at f[m].

    Returns (phi, nx, ny, nz, exact, triangle): exact is True when |phi| < band and
    phi is the signed Euclidean distance to the nearest triangle (whose index is
    returned); otherwise phi = +-band (and triangle -1).  The hash is searched
    in Chebyshev rings of cells around p's cell, starting at the first ring that
    can hold a triangle, skipping cells farther than the best candidate, and
    stopping once no unsearched cell can be nearer.  t0: a triangle to start
    from (-1: none); it only speeds the search up.
    """
    h = f[m + MB_H]
    invh = f[m + MB_INVH]
    nx = int(f[m + MB_DIMS])
    ny = int(f[m + MB_DIMS + 1])
    nz = int(f[m + MB_DIMS + 2])
    ox, oy, oz = f[m + MB_ORIGIN], f[m + MB_ORIGIN + 1], f[m + MB_ORIGIN + 2]
    gx = (px - ox) * invh
    gy = (py - oy) * invh
    gz = (pz - oz) * invh
    ccx, ccy, ccz = f[m + MB_CENTROID], f[m + MB_CENTROID + 1], f[m + MB_CENTROID + 2]
    if not (gx >= 0.0 and gx < nx and gy >= 0.0 and gy < ny and gz >= 0.0 and gz < nz):
        # outside the grid (or not finite): farther than band from the mesh, outside it
        dx, dy, dz = px - ccx, py - ccy, pz - ccz
        rr = math.sqrt(dx * dx + dy * dy + dz * dz)
        if rr > 0.0:
            return band, dx / rr, dy / rr, dz / rr, False, -1
        return band, 0.0, 1.0, 0.0, False, -1
    ci, cj, ck = int(gx), int(gy), int(gz)
    fx, fy, fz = gx - ci, gy - cj, gz - ck
    wall = min(min(min(fx, 1.0 - fx), min(fy, 1.0 - fy)), min(fz, 1.0 - fz)) * h
    cell = (ci * ny + cj) * nz + ck
    cb = m + int(f[m + MB_CELLS]) + CELL_STRIDE * cell
    side = f[cb + 2]
    r0 = int(f[cb + 3])
    best2 = np.inf
    bqx, bqy, bqz = px, py, pz
    # np.int64, not a literal: a literal argument would compile _candidate and _descend a second time
    bt = np.int64(-1)
    bfeat = np.int64(0)
    # nothing within (r0 - 1) h + wall of p: clamp
    if r0 >= 1 and (r0 - 1) * h + wall >= band:
        r = -1
    else:
        r = r0
        if t0 >= 0:  # warm start: a nearby triangle, walked to a local minimum, makes the scan mostly pruning
            best2, bqx, bqy, bqz, bt, bfeat = _candidate(f, m, t0, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat)
            best2, bqx, bqy, bqz, bt, bfeat = _descend(f, m, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat)
    while r >= 0:
        if r == 0:
            best2, bqx, bqy, bqz, bt, bfeat = _cell_tris(f, m, cell, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat)
        else:
            for i in range(max(ci - r, 0), min(ci + r, nx - 1) + 1):
                di = abs(i - ci)
                bx0 = ox + i * h
                ex = max(max(bx0 - px, px - bx0 - h), 0.0)
                for j in range(max(cj - r, 0), min(cj + r, ny - 1) + 1):
                    dj = abs(j - cj)
                    by0 = oy + j * h
                    ey = max(max(by0 - py, py - by0 - h), 0.0)
                    exy = ex * ex + ey * ey
                    if exy >= best2:
                        continue
                    if di == r or dj == r:
                        k = max(ck - r, 0)
                        kstep = 1
                    else:
                        k = ck - r
                        kstep = 2 * r
                    kend = min(ck + r, nz - 1)
                    while k <= kend:
                        if k >= 0:
                            bz0 = oz + k * h
                            ez = max(max(bz0 - pz, pz - bz0 - h), 0.0)
                            if exy + ez * ez < best2:
                                best2, bqx, bqy, bqz, bt, bfeat = _cell_tris(
                                    f, m, (i * ny + j) * nz + k, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat)
                        k += kstep
        bound = r * h + wall  # no unsearched cell is nearer than this
        lim = min(best2, band * band)
        if bound * bound >= lim:
            break
        r += 1
    if bt >= 0 and best2 < band * band:
        d = math.sqrt(best2)
        sx, sy, sz = _pseudo_normal(f, m, bt, bfeat)
        dx, dy, dz = px - bqx, py - bqy, pz - bqz
        sgn = 1.0 if dx * sx + dy * sy + dz * sz >= 0.0 else -1.0
        if d > 1e-12 * h:
            inv = sgn / d
            return sgn * d, dx * inv, dy * inv, dz * inv, True, bt
        return sgn * d, sx, sy, sz, True, bt
    dx, dy, dz = px - ccx, py - ccy, pz - ccz
    rr = math.sqrt(dx * dx + dy * dy + dz * dz)
    if rr > 0.0:
        return side * band, dx / rr, dy / rr, dz / rr, False, -1
    return side * band, 0.0, 1.0, 0.0, False, -1


@njit(cache=True, error_model="numpy")
def triangle_distance2(f, m, t, px, py, pz):
    """Squared distance from p to triangle t of the mesh block at f[m]."""
    j = m + int(f[m + MB_TRI]) + TRI_STRIDE * t
    qx, qy, qz, _ = closest_point_triangle(px, py, pz, f[j], f[j + 1], f[j + 2], f[j + 3], f[j + 4], f[j + 5],
                                           f[j + 6], f[j + 7], f[j + 8])
    return (px - qx) ** 2 + (py - qy) ** 2 + (pz - qz) ** 2


@njit(cache=True, error_model="numpy")
def _candidate(f, m, t, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat):
    """Closest point of triangle t to p; replaces the best (d^2, q, triangle, feature) if nearer."""
    j = m + int(f[m + MB_TRI]) + TRI_STRIDE * t
    qx, qy, qz, feat = closest_point_triangle(px, py, pz, f[j], f[j + 1], f[j + 2], f[j + 3], f[j + 4], f[j + 5],
                                              f[j + 6], f[j + 7], f[j + 8])
    d2 = (px - qx) ** 2 + (py - qy) ** 2 + (pz - qz) ** 2
    if d2 < best2:
        return d2, qx, qy, qz, t, feat
    return best2, bqx, bqy, bqz, bt, bfeat


@njit(cache=True, error_model="numpy")
def _descend(f, m, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat):
    """Walk from the best candidate to a local minimum of the distance over the surface.

    While the closest point is on an edge (vertex) of triangle bt, the
    triangle across that edge (the triangles around that vertex) may be nearer:
    take the nearest of them and repeat.  Ends on a triangle whose closest
    point no neighbour improves.
    """
    adj0 = m + int(f[m + MB_ADJ])
    ptr0 = m + int(f[m + MB_RINGPTR])
    ring0 = m + int(f[m + MB_RING])
    tv0 = m + int(f[m + MB_TRIV])
    for _ in range(64):
        t, feat = bt, bfeat
        if feat >= FEAT_AB:
            nb = int(f[adj0 + 3 * t + (feat - FEAT_AB)])
            best2, bqx, bqy, bqz, bt, bfeat = _candidate(f, m, nb, px, py, pz, best2, bqx, bqy, bqz, bt, bfeat)
        elif feat >= FEAT_A:
            vtx = int(f[tv0 + 3 * t + (feat - FEAT_A)])
            for q in range(int(f[ptr0 + vtx]), int(f[ptr0 + vtx + 1])):
                nb = int(f[ring0 + q])
                if nb != t:
                    best2, bqx, bqy, bqz, bt, bfeat = _candidate(f, m, nb, px, py, pz, best2, bqx, bqy, bqz,
                                                                 bt, bfeat)
        if bt == t:
            break
    return best2, bqx, bqy, bqz, bt, bfeat


@njit(cache=True, error_model="numpy")
def mesh_query(f, m, px, py, pz):
    """Signed distance and outward normal of the closed mesh whose block starts at f[m].

    Returns (phi, nx, ny, nz, exact).  Every grid corner stores its signed
    distance (clamped to +-band) and its nearest triangle.  The field is
    1-Lipschitz, so |phi(p)| >= max_k (|phi_k| - |p - x_k|) over the corners x_k
    of p's cell when they share a sign (and then p is on their side).  Where
    that bound reaches the exact band, phi is the trilinear interpolation of the
    corner values (the far field; error O(h^2 * curvature), at most sqrt(3) h)
    and the normal its normalised gradient.  Elsewhere the hash gives the exact
    distance (``mesh_exact``), warm-started from the nearest corner's triangle.
    """
    h = f[m + MB_H]
    invh = f[m + MB_INVH]
    nx = int(f[m + MB_DIMS])
    ny = int(f[m + MB_DIMS + 1])
    nz = int(f[m + MB_DIMS + 2])
    ox, oy, oz = f[m + MB_ORIGIN], f[m + MB_ORIGIN + 1], f[m + MB_ORIGIN + 2]
    gx = (px - ox) * invh
    gy = (py - oy) * invh
    gz = (pz - oz) * invh
    band = f[m + MB_BAND]
    if not (gx >= 0.0 and gx < nx and gy >= 0.0 and gy < ny and gz >= 0.0 and gz < nz):
        return mesh_exact(f, m, px, py, pz, band, np.int64(-1))[:5]  # outside the grid: +band at once
    ci, cj, ck = int(gx), int(gy), int(gz)
    u, v, w = gx - ci, gy - cj, gz - ck
    nyc, nzc = ny + 1, nz + 1
    b000 = m + int(f[m + MB_CORNERS]) + CORNER_STRIDE * ((ci * nyc + cj) * nzc + ck)
    b010 = b000 + CORNER_STRIDE * nzc
    b100 = b000 + CORNER_STRIDE * nyc * nzc
    b110 = b100 + CORNER_STRIDE * nzc
    c000, c001 = f[b000], f[b000 + CORNER_STRIDE]
    c010, c011 = f[b010], f[b010 + CORNER_STRIDE]
    c100, c101 = f[b100], f[b100 + CORNER_STRIDE]
    c110, c111 = f[b110], f[b110 + CORNER_STRIDE]
    lo = min(min(min(c000, c001), min(c010, c011)), min(min(c100, c101), min(c110, c111)))
    hi = max(max(max(c000, c001), max(c010, c011)), max(max(c100, c101), max(c110, c111)))
    u1, v1, w1 = 1.0 - u, 1.0 - v, 1.0 - w
    if lo > 0.0 or hi < 0.0:
        uu, vv, ww, uu1, vv1, ww1 = u * u, v * v, w * w, u1 * u1, v1 * v1, w1 * w1
        bound = max(max(max(abs(c000) - h * math.sqrt(uu + vv + ww), abs(c001) - h * math.sqrt(uu + vv + ww1)),
                        max(abs(c010) - h * math.sqrt(uu + vv1 + ww), abs(c011) - h * math.sqrt(uu + vv1 + ww1))),
                    max(max(abs(c100) - h * math.sqrt(uu1 + vv + ww), abs(c101) - h * math.sqrt(uu1 + vv + ww1)),
                        max(abs(c110) - h * math.sqrt(uu1 + vv1 + ww), abs(c111) - h * math.sqrt(uu1 + vv1 + ww1))))
        if bound >= f[m + MB_EXACT]:
            c00 = c000 + (c100 - c000) * u
            c01 = c001 + (c101 - c001) * u
            c10 = c010 + (c110 - c010) * u
            c11 = c011 + (c111 - c011) * u
            c0 = c00 + (c10 - c00) * v
            c1 = c01 + (c11 - c01) * v
            phi = c0 + (c1 - c0) * w
            d0 = ((c100 - c000) * v1 + (c110 - c010) * v) * w1 + ((c101 - c001) * v1 + (c111 - c011) * v) * w
            d1 = (c10 - c00) * w1 + (c11 - c01) * w
            d2 = c1 - c0
            gn = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
            if gn > 0.0:
                return phi, d0 / gn, d1 / gn, d2 / gn, False
            dx, dy, dz = px - f[m + MB_CENTROID], py - f[m + MB_CENTROID + 1], pz - f[m + MB_CENTROID + 2]
            rr = math.sqrt(dx * dx + dy * dy + dz * dz)
            if rr > 0.0:
                return phi, dx / rr, dy / rr, dz / rr, False
            return phi, 0.0, 1.0, 0.0, False
    # the nearest corner's triangle warm-starts the exact search
    bn = b000
    if u >= 0.5:
        bn += CORNER_STRIDE * nyc * nzc
    if v >= 0.5:
        bn += CORNER_STRIDE * nzc
    if w >= 0.5:
        bn += CORNER_STRIDE
    return mesh_exact(f, m, px, py, pz, band, int(f[bn + 1]))[:5]


@njit(cache=True, error_model="numpy")
def _mesh_phi_normal(f, x, y, z):
    m = int(f[H_DATA])
    phi, nx, ny, nz, _ = mesh_query(f, m, x, y, z)
    if f[1] != 0.0:
        g = y - f[0]
        if g < phi:
            return g, 0.0, 1.0, 0.0
    return phi, nx, ny, nz


@njit(cache=True, error_model="numpy")
def mesh_down(f, x, y, z):
    """Unit "down" at p on a MESH terrain: toward the nearest mesh surface (minus its normal).

    Ignores the optional ground plane and obstacles: it is the direction of the
    closed mesh's own "gravity" (Fig. 1).
    """
    _, nx, ny, nz, _ = mesh_query(f, int(f[H_DATA]), x, y, z)
    return -nx, -ny, -nz


# --------------------------------------------------------------------------- the queries
#
# signed_distance and surface_normal are thin dispatchers inlined into every caller
# (numba inline="always"): the plane and the slope stay a few instructions in the
# callers' step loops, and everything else is a call on a branch those loops
# never take for them.

@njit(cache=True, error_model="numpy")
def _other_phi(kind, f, x, y, z):
    if kind == SLAB:
        return _slab_phi(f, x, y)
    elif kind == HEIGHTFIELD:
        return _hf_phi(f, x, y, z)
    return _mesh_phi_normal(f, x, y, z)[0]


@njit(cache=True, error_model="numpy")
def _other_normal(kind, f, x, y, z):
    if kind == SLAB:
        return _slab_normal(f, x, y)
    elif kind == HEIGHTFIELD:
        return _hf_normal(f, x, y, z)
    _, nx, ny, nz = _mesh_phi_normal(f, x, y, z)
    return nx, ny, nz


@njit(cache=True, error_model="numpy", inline="always")
def _base_phi(kind, f, x, y, z):
    if kind == PLANE:
        return y - f[0]
    elif kind == SLOPE:
        return -math.sin(f[1]) * x + math.cos(f[1]) * (y - f[0])
    return _other_phi(kind, f, x, y, z)


@njit(cache=True, error_model="numpy")
def _min_obstacles(f, phi, x, y, z):
    return _grid_below(f, x, y, z, phi)[0]



@njit(cache=True, error_model="numpy", inline="always")
def _base_normal(kind, f, x, y, z):
    """The base terrain's unit normal at p (``surface_normal`` without obstacles)."""
    if kind == PLANE:
        return 0.0, 1.0, 0.0
    elif kind == SLOPE:
        return -math.sin(f[1]), math.cos(f[1]), 0.0
    return _other_normal(kind, f, x, y, z)


@njit(cache=True, error_model="numpy")
def _obstacle_or_base_normal(kind, f, x, y, z):
    _, j, _ = _grid_below(f, x, y, z, _base_phi(kind, f, x, y, z))
    if j >= 0:
        return _obstacle_normal(f, j, x, y, z)
    return _base_normal(kind, f, x, y, z)


@njit(cache=True, error_model="numpy", inline="always")
def signed_distance(kind, f, x, y, z):
    """phi(p) [m]: distance of point p above the terrain surface (negative inside)."""
    if kind == PLANE:
        phi = y - f[0]
    elif kind == SLOPE:
        phi = -math.sin(f[1]) * x + math.cos(f[1]) * (y - f[0])
    else:
        phi = _other_phi(kind, f, x, y, z)
    if f[H_NOBST] > 0.0:
        phi = _min_obstacles(f, phi, x, y, z)
    return phi


@njit(cache=True, error_model="numpy", inline="always")
def _grid_scalars(f):
    """What ``_grid_cell`` reads of f's obstacle grid (module docstring): (D - slack [m], origin x0, z0 [m],
    1/h [1/m], cells nx, nz (floats), nz (int), cell tops offset (int)).  f must have obstacles."""
    g = int(f[H_OBST]) + OBST_STRIDE * int(f[H_NOBST])
    return (f[g + 8] - GRID_SLACK_CELLS * f[g], f[g + 2], f[g + 3], f[g + 1], f[g + 4], f[g + 5], int(f[g + 5]),
            int(f[g + 9]))


# ``_grid_cell``'s answers besides a cell top's f-index (>= 0)
CELL_OUTSIDE = -1    # p outside the grid: no obstacle nearer than d
CELL_UNKNOWN = -2    # d beyond the reach D, or p NaN: the grid cannot tell
CELL_FLAT = -3       # (``clearance_cell``) the plane without obstacles


@njit(cache=True, error_model="numpy", inline="always")
def _grid_cell(G, x, z, d):
    """Where ``_obstacles_clear`` looks, from f's grid scalars G (``_grid_scalars``) and scalars only: the f-index
    of p's cell top (no obstacle nearer than d iff y - that top >= d), CELL_OUTSIDE or CELL_UNKNOWN."""
    reach, x0, z0, invh, fnx, fnz, nz, tops = G
    if not d <= reach:
        return CELL_UNKNOWN
    u = (x - x0) * invh
    v = (z - z0) * invh
    if u >= 0.0 and u < fnx and v >= 0.0 and v < fnz:
        return tops + int(u) * nz + int(v)
    return CELL_OUTSIDE if (u == u and v == v) else CELL_UNKNOWN


@njit(cache=True, error_model="numpy", inline="always")
def _obstacles_clear(f, x, y, z, d):
    """True when no obstacle of f is nearer than d [m] to p, read from the grid's cell tops (module docstring):
    p inside the grid at least d above its cell's top (every listed record's phi >= y - its top, since its
    vertical distance bounds it; every unlisted one is farther than the reach D), or p outside the grid
    (every footprint farther than D).  Only for d <= D; False when it cannot tell (also for NaN)."""
    k = _grid_cell(_grid_scalars(f), x, z, d)
    return (y - f[k] >= d) if k >= 0 else k == CELL_OUTSIDE


@njit(cache=True, error_model="numpy")
def _phi_at_least(kind, f, x, y, z, d):
    """``signed_distance(kind, f, x, y, z) >= d`` for a terrain with obstacles: min(base phi, every obstacle's
    phi) >= d iff the base's phi is and no obstacle is nearer than d, so the search stops at d (not at the
    base's phi: fewer records pass its lower bounds) and is not made when the base's phi is below d.  The same
    boolean, NaN included: a NaN base phi fails the first test as it fails ``>= d``, and a search whose
    cutoff or point is NaN finds no obstacle either way."""
    if not _base_phi(kind, f, x, y, z) >= d:
        return False
    return _grid_below(f, x, y, z, d)[1] < 0


@njit(cache=True, error_model="numpy", inline="always")
def distance_at_least(kind, f, x, y, z, d):
    """``signed_distance(kind, f, x, y, z) >= d`` -- the same boolean for every p, NaN included -- without
    the obstacle search where the grid's cell tops show that no obstacle is nearer than d [m] (module
    docstring, "Threshold queries"): phi = min(base phi, obstacles' phi) >= d then iff the base's is.

    For the hot loops' "is this point clear of the terrain?" tests (a node's contact test, a box corner's).
    On the plane without obstacles callers still test ``flat_ground`` first (its docstring says why)."""
    if f[H_NOBST] > 0.0 and not _obstacles_clear(f, x, y, z, d):
        return _phi_at_least(kind, f, x, y, z, d)
    return _base_phi(kind, f, x, y, z) >= d


# ``clearance``'s modes (``clearance_view``)
CLEAR_FLAT = 0       # the plane without obstacles: phi = y - ground
CLEAR_PLANE_GRID = 1  # the plane with obstacles: the grid's cell tops, then y - ground
CLEAR_ASK = 2        # any other terrain: ``distance_at_least``
CLEAR_UNKNOWN = -1   # ``clearance``: ask ``distance_at_least``


@njit(cache=True, error_model="numpy", inline="always")
def clearance_view(kind, f):
    """V = (mode, ground h = f[0] [m], the obstacle grid's scalars): what ``clearance_cell`` and ``clearance``
    read of terrain (kind, f), read once before a loop of point tests (scalars in registers, not reloaded per
    point)."""
    if kind == PLANE and f[H_NOBST] > 0.0:
        return CLEAR_PLANE_GRID, f[0], _grid_scalars(f)
    return (CLEAR_FLAT if kind == PLANE else CLEAR_ASK), f[0], (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0)


@njit(cache=True, error_model="numpy", inline="always")
def clearance_cell(V, x, z, d):
    """Step 1 of ``clearance``: the f-index of p's obstacle-grid cell top to read (>= 0), or CELL_FLAT,
    CELL_OUTSIDE, CELL_UNKNOWN (also for a terrain that only ``distance_at_least`` answers)."""
    mode, _, G = V
    if mode == CLEAR_FLAT:
        return CELL_FLAT
    if mode != CLEAR_PLANE_GRID:
        return CELL_UNKNOWN
    return _grid_cell(G, x, z, d)


@njit(cache=True, error_model="numpy", inline="always")
def clearance(V, top, y, d, k):
    """``distance_at_least(kind, f, x, y, z, d)`` where the grid's cell tops answer it without a search: 1 (phi
    >= d) or 0 (phi < d), else CLEAR_UNKNOWN (ask ``distance_at_least``).  V = ``clearance_view(kind, f)``,
    k = ``clearance_cell(V, x, z, d)``, top = f[k] where k >= 0 (read by the caller).

    For the hot loops of point tests (a node's contact test, a box corner's), written at the call as
    ``k = clearance_cell(V, x, z, d)``, ``c = clearance(V, f[k] if k >= 0 else 0.0, y, d, k)``, ``(c > 0) if
    c >= 0 else distance_at_least(kind, f, x, y, z, d)``.  Both steps take scalars only: an inlined function
    that takes f takes and drops a reference to it per point (two atomic updates, which numba's pruning left
    in the walking centipede's loops, ``flat_ground``), and the grid's scalars are read once per loop.  The
    same answers: ``distance_at_least``'s operations on the same doubles (y - f[0] is the plane's phi)."""
    if k == CELL_FLAT or k == CELL_OUTSIDE or (k >= 0 and y - top >= d):
        return 1 if y - V[1] >= d else 0
    return CLEAR_UNKNOWN


@njit(cache=True, error_model="numpy", inline="always")
def flat_ground(kind, f):
    """(flat, h): flat = the terrain is the plane without obstacles, where ``signed_distance`` is
    exactly y - h, h = f[0] [m] (the same operation).

    For a hot loop of point queries: it computes y - h itself where flat and calls ``signed_distance``
    only otherwise.  Why: ``signed_distance`` is inlined, and each inlined call takes and drops a
    reference to f (two atomic reference-count updates) that numba's reference-count pruning leaves
    in place because the function's branches hold calls; in a loop over hundreds of points per step
    those updates cost more than the query.
    """
    return (kind == PLANE) and not (f[H_NOBST] > 0.0), f[0]


@njit(cache=True, error_model="numpy", inline="always")
def surface_normal(kind, f, x, y, z):
    """Unit outward normal (nx, ny, nz) of the terrain surface nearest to p."""
    if f[H_NOBST] > 0.0:
        return _obstacle_or_base_normal(kind, f, x, y, z)
    if kind == PLANE:
        return 0.0, 1.0, 0.0
    elif kind == SLOPE:
        return -math.sin(f[1]), math.cos(f[1]), 0.0
    return _other_normal(kind, f, x, y, z)


@njit(cache=True, error_model="numpy")
def distance_and_normal(kind, f, x, y, z):
    """(``signed_distance``, *``surface_normal``) at p from one obstacle search instead of two: both search the
    obstacles below the base's phi, the distance keeps the nearest one's phi, the normal is its normal (the
    base's when none is nearer).  The same doubles as the two calls (the Targeter's Balancer asks both at
    each carried segment's centre).  Not inlined: one call, where the two inlined queries each took and
    dropped a reference to f (``flat_ground``)."""
    phi = _base_phi(kind, f, x, y, z)
    if f[H_NOBST] > 0.0:
        phi, j, _ = _grid_below(f, x, y, z, phi)
        if j >= 0:
            nx, ny, nz = _obstacle_normal(f, j, x, y, z)
            return phi, nx, ny, nz
    nx, ny, nz = _base_normal(kind, f, x, y, z)
    return phi, nx, ny, nz


@njit(cache=True, error_model="numpy")
def terrain_down(kind, f, x, y, z):
    """Unit "down" at p: minus the surface normal (toward the nearest surface)."""
    nx, ny, nz = surface_normal(kind, f, x, y, z)
    return -nx, -ny, -nz


@njit(cache=True, error_model="numpy")
def segment_surface_intersection(kind, f, x0, y0, z0, x1, y1, z1):
    """Fraction s in [0, 1] along p0 -> p1 where the path first meets the surface.

    Miller Sec. 3, Fig. 1: a point's path over one step is intersected with the
    constraint surface.  p0 is assumed outside (phi >= 0) and p1 inside.  For the
    planar kinds without obstacles the root is exact; otherwise the signed
    distance is piecewise smooth, so bisection-secant (Illinois) iterations on
    the bracket [0, 1] resolve it to 1e-13 m.
    """
    return path_surface_fraction(kind, f, x0, y0, z0, x1, y1, z1, signed_distance(kind, f, x0, y0, z0),
                                 signed_distance(kind, f, x1, y1, z1))


@njit(cache=True, error_model="numpy")
def path_surface_fraction(kind, f, x0, y0, z0, x1, y1, z1, phi0, phi1):
    """``segment_surface_intersection`` given the end points' signed distances phi0 >= 0 > phi1."""
    if phi0 <= 0.0:
        return 0.0
    if (kind == PLANE or kind == SLOPE) and f[H_NOBST] <= 0.0:
        return phi0 / (phi0 - phi1)
    lo, hi = 0.0, 1.0
    flo, fhi = phi0, phi1
    s = 0.0
    for _ in range(80):
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


# --------------------------------------------------------------------------- packing (Python)

def header(ground_m: float = 0.0, p1: float = 0.0, p2: float = 0.0, p3: float = 0.0) -> np.ndarray:
    """An 8-value header with no data block and no obstacles."""
    f = np.zeros(N_TERRAIN_PARAMS)
    f[0], f[1], f[2], f[3] = ground_m, p1, p2, p3
    return f


def heightfield_params(ground_m: float, centres_xz, amplitudes_m, widths_m) -> np.ndarray:
    """f of a HEIGHTFIELD: ground height plus Gaussians (centres (n, 2) [m], amplitudes (n,), widths s (n,))."""
    c = np.asarray(centres_xz, dtype=float).reshape(-1, 2)
    a = np.asarray(amplitudes_m, dtype=float).reshape(-1)
    s = np.asarray(widths_m, dtype=float).reshape(-1)
    if not (len(c) == len(a) == len(s)):
        raise ValueError("centres, amplitudes and widths differ in length")
    if np.any(~(s > 0)):
        raise ValueError("Gaussian widths must be > 0")
    block = np.column_stack([c[:, 0], c[:, 1], a, s, 1.0 / (2.0 * s * s)]).reshape(-1)
    f = header(ground_m)
    f[H_DATA] = N_TERRAIN_PARAMS if len(a) else 0.0
    f[H_NDATA] = len(a)
    return np.concatenate([f, block])


def with_data_block(f: np.ndarray, block: np.ndarray, n_data: int) -> np.ndarray:
    """Append a kind's data block (e.g. a mesh block) to f; f must have none yet."""
    f = np.asarray(f, dtype=float)
    if f[H_DATA] != 0.0 or f[H_NOBST] != 0.0:
        raise ValueError("attach the data block before the obstacles, once")
    out = np.concatenate([f, np.asarray(block, dtype=float)])
    out[H_DATA] = len(f)
    out[H_NDATA] = n_data
    return out


def cylinder_record(cx: float, cz: float, radius: float, y_bottom: float, y_top: float) -> np.ndarray:
    """Obstacle record of a vertical cylinder (axis along y through (cx, cz)) [m]."""
    if not (radius > 0 and y_top > y_bottom):
        raise ValueError("a cylinder needs radius > 0 and y_top > y_bottom")
    r = np.zeros(OBST_STRIDE)
    r[:6] = OBST_CYLINDER, cx, cz, radius, y_bottom, y_top
    return r


def box_record(cx: float, cy: float, cz: float, hx: float, hy: float, hz: float, yaw_rad: float = 0.0) -> np.ndarray:
    """Obstacle record of a box: centre, half extents [m], yaw about +y [rad]."""
    if not (hx > 0 and hy > 0 and hz > 0):
        raise ValueError("a box needs positive half extents")
    r = np.zeros(OBST_STRIDE)
    r[:9] = OBST_BOX, cx, cy, cz, hx, hy, hz, math.cos(yaw_rad), math.sin(yaw_rad)
    return r


def with_obstacles(f: np.ndarray, records) -> np.ndarray:
    """f with an obstacle block of ``records`` (rows of OBST_STRIDE) and its grid appended; replaces none."""
    f = np.asarray(f, dtype=float)
    if len(f) < N_TERRAIN_PARAMS:
        f = np.concatenate([f, np.zeros(N_TERRAIN_PARAMS - len(f))])
    if f[H_NOBST] != 0.0:
        raise ValueError("f already has obstacles")
    rec = np.asarray(records, dtype=float).reshape(-1, OBST_STRIDE)
    if len(rec) == 0:
        return f.copy()
    off = len(f)
    grid = obstacle_grid(rec, off + OBST_STRIDE * len(rec))
    out = np.concatenate([f, rec.reshape(-1), grid])
    out[H_OBST] = off
    out[H_NOBST] = len(rec)
    return out


def obstacle_footprints(rec: np.ndarray) -> np.ndarray:
    """(n, 3) x-z footprint squares (cx, cz, half width) [m] of obstacle records (n, OBST_STRIDE).

    The squares ``_obstacle_bound`` measures against: a cylinder's radius, a box's
    sqrt(half_x^2 + half_z^2) (any yaw stays inside it).
    """
    cyl = rec[:, 0] == OBST_CYLINDER
    cx = rec[:, 1]
    cz = np.where(cyl, rec[:, 2], rec[:, 3])
    w = np.where(cyl, rec[:, 3], np.sqrt(rec[:, 4] ** 2 + rec[:, 6] ** 2))
    return np.column_stack([cx, cz, w])


def obstacle_grid(rec: np.ndarray, start: int, cell_m: float | None = None) -> np.ndarray:
    """The obstacle grid block (module docstring) of records ``rec`` for a block placed at f-index ``start``.

    The record at row r sits at f-index ``start - OBST_STRIDE * (n - r)`` (the records
    precede the grid).  Cells of ``cell_m`` [m], by default GRID_CELL_DIAMETERS x the
    mean footprint width, coarsened so that the footprints' bounding square holds at most
    max(GRID_MIN_CELLS, GRID_MAX_CELLS_PER_RECORD x n) cells; the grid covers that square
    widened by the reach.
    """
    n = len(rec)
    fp = obstacle_footprints(rec)
    lo0 = np.array([np.min(fp[:, 0] - fp[:, 2]), np.min(fp[:, 1] - fp[:, 2])])
    hi0 = np.array([np.max(fp[:, 0] + fp[:, 2]), np.max(fp[:, 1] + fp[:, 2])])
    span0 = np.maximum(hi0 - lo0, 1e-9)
    h = float(cell_m) if cell_m is not None else GRID_CELL_DIAMETERS * 2.0 * float(fp[:, 2].mean())
    cap = max(GRID_MIN_CELLS, GRID_MAX_CELLS_PER_RECORD * n)
    h = max(h, float(np.sqrt(span0[0] * span0[1] / cap)), float(span0.max()) / cap)
    reach = GRID_REACH_CELLS * h
    lo, hi = lo0 - reach, hi0 + reach  # the grid holds the widened squares
    nx, nz = (int(v) for v in np.maximum(np.ceil((hi - lo) / h), 1))
    first = start - OBST_STRIDE * n
    plain: list[list[int]] = [[] for _ in range(nx * nz)]
    wide: list[list[int]] = [[] for _ in range(nx * nz)]
    for lists, grow in ((plain, 0.0), (wide, reach)):
        for r in range(n):
            cx, cz, w = fp[r]
            w += grow
            i0 = max(int(np.floor((cx - w - lo[0]) / h - GRID_SLACK_CELLS)), 0)
            i1 = min(int(np.floor((cx + w - lo[0]) / h + GRID_SLACK_CELLS)), nx - 1)
            k0 = max(int(np.floor((cz - w - lo[1]) / h - GRID_SLACK_CELLS)), 0)
            k1 = min(int(np.floor((cz + w - lo[1]) / h + GRID_SLACK_CELLS)), nz - 1)
            for i in range(i0, i1 + 1):
                for k in range(k0, k1 + 1):
                    lists[i * nz + k].append(first + OBST_STRIDE * r)
    seq = [c for pair in zip(plain, wide) for c in pair]  # cell by cell: plain, widened
    counts = np.array([len(c) for c in seq], dtype=float)
    firsts = np.concatenate([[0.0], np.cumsum(counts)[:-1]])
    cells = np.column_stack([firsts, counts]).reshape(-1)
    flat = np.array([j for c in seq for j in c], dtype=float)
    # the highest point of each record (a cylinder's y_top, a box's centre y + half_y: its yaw is about y)
    top = np.where(rec[:, 0] == OBST_CYLINDER, rec[:, 5], rec[:, 2] + rec[:, 5])
    top = top + GRID_TOP_MARGIN * np.maximum(1.0, np.abs(top))
    tops = np.array([max((top[(j - first) // OBST_STRIDE] for j in c), default=-np.inf) for c in wide])
    lists = start + GRID_HDR + len(cells)
    hdr = np.array([h, 1.0 / h, lo[0], lo[1], nx, nz, start + GRID_HDR, lists, reach, lists + len(flat)])
    return np.concatenate([hdr, cells, flat, tops])


def obstacle_records(f: np.ndarray) -> np.ndarray:
    """The (n, OBST_STRIDE) obstacle records of f."""
    off, n = int(f[H_OBST]), int(f[H_NOBST])
    return np.asarray(f[off: off + OBST_STRIDE * n]).reshape(n, OBST_STRIDE)


def heightfield_gaussians(f: np.ndarray) -> np.ndarray:
    """(n, 4) array of a HEIGHTFIELD's Gaussians: cx, cz, amplitude, width s [m]."""
    off, n = int(f[H_DATA]), int(f[H_NDATA])
    return np.asarray(f[off: off + HF_STRIDE * n]).reshape(n, HF_STRIDE)[:, :4].copy()


def heightfield_numpy(f: np.ndarray, x, z) -> np.ndarray:
    """h(x, z) of a HEIGHTFIELD for arrays x, z (broadcast) [m]."""
    x = np.asarray(x, dtype=float)
    z = np.asarray(z, dtype=float)
    h = np.full(np.broadcast(x, z).shape, float(f[0]))
    for cx, cz, a, s in heightfield_gaussians(f):
        h = h + a * np.exp(-((x - cx) ** 2 + (z - cz) ** 2) / (2.0 * s * s))
    return h


def terrain_phi_numpy(kind: int, f: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Slow reference of ``signed_distance`` for an array of points p: (n, 3) [m].

    Plane, slope and slab (without obstacles) only; other kinds call the kernel.
    """
    p = np.asarray(p, dtype=float)
    x, y = p[:, 0], p[:, 1]
    if kind not in (PLANE, SLOPE, SLAB) or (len(f) > H_NOBST and f[H_NOBST] > 0):
        ff = np.ascontiguousarray(f, dtype=float)
        return np.array([signed_distance(kind, ff, *q) for q in p])
    if kind == PLANE:
        return y - f[0]
    if kind == SLOPE:
        return -np.sin(f[1]) * x + np.cos(f[1]) * (y - f[0])
    qx = x - (f[2] - f[3])
    qy = y - (f[1] - f[3])
    slab = np.hypot(np.maximum(qx, 0), np.maximum(qy, 0)) + np.minimum(np.maximum(qx, qy), 0) - f[3]
    return np.minimum(y - f[0], slab)
