"""Numba kernels of the shallow-water layer (``water.ShallowWater`` owns the state).

Kass and Miller 1990, "Rapid, stable fluid dynamics for computer graphics"
(SIGGRAPH 90), referred to as K&M.  Their equations as used here.  No copy of
the paper is among ../shared/seeds (only the myriapod paper's reference to it),
so the numbering below is recalled, not checked against the text; each citation
therefore also states the equation, so that a reader with the paper can check it:

* Eq. 1-2 -- the 1-D shallow-water equations: momentum
  u_t + u u_x + g h_x = 0 and continuity d_t + (u d)_x = 0, with h the water
  surface height, b the bed height and d = h - b the depth.
* Eq. 3-4 -- linearised: u_t + g h_x = 0 and h_t + d u_x = 0 (advection dropped,
  d varying slowly in space; h_t = d_t because the bed does not move).
* Eq. 5-6 -- their combination, the wave equation h_tt = g d h_xx, in 2-D
  h_tt = g d (h_xx + h_zz): waves travel at c = sqrt(g d).
* Eq. 7 -- the conservative finite difference on a row of columns,
  h_i'' = -g (d_{i-1} + d_i) / (2 dx^2) (h_i - h_{i-1})
          + g (d_i + d_{i+1}) / (2 dx^2) (h_{i+1} - h_i),
  i.e. h'' = -K h with K symmetric, zero row and column sums.
* The first-order implicit time discretisation that follows it,
  h(n) = 2 h(n-1) - h(n-2) - dt^2 K h(n), i.e. (I + dt^2 K) h(n) = 2 h(n-1) - h(n-2),
  a symmetric, diagonally dominant tridiagonal system per row, unconditionally
  stable; with K&M's damping tau the right-hand side is
  h(n-1) + (1 - tau) (h(n-1) - h(n-2)).

Our choices, each marked where it is made:

* Grid: cell-centred, square cells of side dx, array index [i, j] <-> (x_i, z_j);
  the domain edge is a wall (no flux through it).
* Face depth (K&M average the two cells' depths, Eq. 7): d_f = max(0,
  max(h_i, h_j) - max(b_i, b_j)), the water above the higher bed, taken from the
  higher surface.  For wet flat ground it equals K&M's average to first order
  in the wave amplitude; across a wet/dry edge whose bed stands above the water
  it is 0, so water does not climb a dry bank (K&M's average would drive the
  dry cell's "surface" = its bed into the wet cell and make negative depths).
  d_f is evaluated at level n-1, as K&M do, so each step is linear.
* 2-D: K = K_x + K_z; the system (I + dt^2 K) h(n) = rhs is replaced by the
  alternating-direction factorisation (I + dt^2 K_a)(I + dt^2 K_b) h(n) = rhs,
  a tridiagonal (Thomas) solve along every row and then along every column,
  the order (a, b) = (x, z) or (z, x) alternating from step to step.  The
  factorisation error is dt^4 K_a K_b h = O(C^4) for Courant number
  C = c dt / dx; each factor has unit column sums, so the sum of h -- the water
  volume -- is conserved exactly (up to rounding).
* Positivity: the linear solve can leave a thin layer below its bed; such cells
  are set to their bed and the water so created is removed from all wet cells
  in proportion to their depth (volume stays exact, depths stay >= 0).

All lengths in metres, times in seconds, g in m/s^2.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from .terrain_kernels import signed_distance

# ----------------------------------------------------------------------------------------------
# Time stepping
# ----------------------------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _face_k(coef, ha, hb, ba, bb):
    """dt^2 g d_f / dx^2 [-] of the face between two cells (face depth: see module doc)."""
    d = (ha if ha > hb else hb) - (ba if ba > bb else bb)
    return coef * d if d > 0.0 else 0.0


@njit(cache=True, error_model="numpy")
def _solve_x(h, hp, b, coef, cp, kprev):
    """(I + dt^2 K_x) out = h in place, K_x from the level-(n-1) surface hp.

    Thomas algorithm along axis 0 for all columns j at once (inner loop over the
    contiguous j).  h: (nx, nz) right-hand side in, solution out.  cp: (nx, nz)
    scratch; kprev: (nz,) scratch.  The forward pass stores the eliminated
    right-hand side in h itself.
    """
    nx, nz = h.shape
    if nx == 1:
        return
    for j in range(nz):
        k = _face_k(coef, hp[0, j], hp[1, j], b[0, j], b[1, j])
        inv = 1.0 / (1.0 + k)
        cp[0, j] = -k * inv
        h[0, j] = h[0, j] * inv
        kprev[j] = k
    for i in range(1, nx - 1):
        for j in range(nz):
            km = kprev[j]
            k = _face_k(coef, hp[i, j], hp[i + 1, j], b[i, j], b[i + 1, j])
            # row i: -km x_{i-1} + (1 + km + k) x_i - k x_{i+1} = r_i
            inv = 1.0 / (1.0 + km + k + km * cp[i - 1, j])
            cp[i, j] = -k * inv
            h[i, j] = (h[i, j] + km * h[i - 1, j]) * inv
            kprev[j] = k
    i = nx - 1
    for j in range(nz):
        km = kprev[j]
        inv = 1.0 / (1.0 + km + km * cp[i - 1, j])
        h[i, j] = (h[i, j] + km * h[i - 1, j]) * inv
    for i in range(nx - 2, -1, -1):
        for j in range(nz):
            h[i, j] -= cp[i, j] * h[i + 1, j]


@njit(cache=True, error_model="numpy")
def _solve_z_row(h, hp, b, coef, cp, i):
    """Row i of ``_solve_z`` alone (the last row when nx is odd)."""
    nz = h.shape[1]
    k = _face_k(coef, hp[i, 0], hp[i, 1], b[i, 0], b[i, 1])
    inv = 1.0 / (1.0 + k)
    cp[i, 0] = -k * inv
    h[i, 0] = h[i, 0] * inv
    km = k
    for j in range(1, nz - 1):
        k = _face_k(coef, hp[i, j], hp[i, j + 1], b[i, j], b[i, j + 1])
        inv = 1.0 / (1.0 + km + k + km * cp[i, j - 1])
        cp[i, j] = -k * inv
        h[i, j] = (h[i, j] + km * h[i, j - 1]) * inv
        km = k
    j = nz - 1
    h[i, j] = (h[i, j] + km * h[i, j - 1]) / (1.0 + km + km * cp[i, j - 1])
    for jj in range(nz - 2, -1, -1):
        h[i, jj] -= cp[i, jj] * h[i, jj + 1]


@njit(cache=True, error_model="numpy")
def _solve_z(h, hp, b, coef, cp, kprev):
    """(I + dt^2 K_z) out = h in place: Thomas along axis 1, see ``_solve_x``.

    Two rows at a time with their recurrences interleaved, so that the CPU
    overlaps two independent chains of dependent divisions (one row alone is
    latency-bound; more rows at a 2 KiB stride start to alias in the L1 cache).
    cp: (nx, nz) scratch; kprev unused (same signature as ``_solve_x``).
    """
    nx, nz = h.shape
    if nz == 1:
        return
    if nx % 2 == 1:
        _solve_z_row(h, hp, b, coef, cp, nx - 1)
    for i in range(0, nx - 1, 2):
        i2 = i + 1
        ka = _face_k(coef, hp[i, 0], hp[i, 1], b[i, 0], b[i, 1])
        kb = _face_k(coef, hp[i2, 0], hp[i2, 1], b[i2, 0], b[i2, 1])
        ia = 1.0 / (1.0 + ka)
        ib = 1.0 / (1.0 + kb)
        ca = -ka * ia
        cb = -kb * ib
        cp[i, 0] = ca
        cp[i2, 0] = cb
        da = h[i, 0] * ia
        db = h[i2, 0] * ib
        h[i, 0] = da
        h[i2, 0] = db
        for j in range(1, nz - 1):
            kan = _face_k(coef, hp[i, j], hp[i, j + 1], b[i, j], b[i, j + 1])
            kbn = _face_k(coef, hp[i2, j], hp[i2, j + 1], b[i2, j], b[i2, j + 1])
            ia = 1.0 / (1.0 + ka + kan + ka * ca)
            ib = 1.0 / (1.0 + kb + kbn + kb * cb)
            ca = -kan * ia
            cb = -kbn * ib
            cp[i, j] = ca
            cp[i2, j] = cb
            da = (h[i, j] + ka * da) * ia
            db = (h[i2, j] + kb * db) * ib
            h[i, j] = da
            h[i2, j] = db
            ka = kan
            kb = kbn
        j = nz - 1
        xa = (h[i, j] + ka * da) / (1.0 + ka + ka * ca)
        xb = (h[i2, j] + kb * db) / (1.0 + kb + kb * cb)
        h[i, j] = xa
        h[i2, j] = xb
        for jj in range(nz - 2, -1, -1):
            xa = h[i, jj] - cp[i, jj] * xa
            xb = h[i2, jj] - cp[i2, jj] * xb
            h[i, jj] = xa
            h[i2, jj] = xb


@njit(cache=True, error_model="numpy")
def _keep_nonnegative(h, b):
    """Cells below their bed are set to it; the water so created is taken back
    from the wet cells in proportion to their depth.  Returns that volume / dx^2 [m]."""
    nx, nz = h.shape
    deficit = 0.0
    for i in range(nx):
        for j in range(nz):
            if h[i, j] < b[i, j]:
                deficit += b[i, j] - h[i, j]
                h[i, j] = b[i, j]
    if deficit > 0.0:
        total = 0.0
        for i in range(nx):
            for j in range(nz):
                total += h[i, j] - b[i, j]
        if total > 0.0:
            f = min(deficit / total, 1.0)
            for i in range(nx):
                for j in range(nz):
                    h[i, j] -= f * (h[i, j] - b[i, j])
    return deficit


@njit(cache=True, error_model="numpy")
def adi_steps(h, hp, b, dt, n_steps, g, dx, keep, parity, cp, kbuf):
    """Advance the height field by ``n_steps`` implicit K&M steps of ``dt`` [s].

    h, hp: (nx, nz) surface heights [m] at levels n-1 and n-2 (updated in place
    to the last two levels).  b: (nx, nz) bed heights [m].  keep = 1 - tau [-],
    K&M's damping factor on the previous step's change.  parity: 0 starts with
    the x sweep, 1 with the z sweep; it flips every step.  cp: (nx, nz) scratch,
    kbuf: (max(nx, nz),) scratch.

    Per step: rhs = h(n-1) + keep (h(n-1) - h(n-2)) (K&M's damped form of the
    implicit discretisation of Eq. 7), then (I + dt^2 K_a)(I + dt^2 K_b) h(n) = rhs
    with K from the level n-1 surface (module doc), then the positivity fix.
    Returns (parity after the last step, volume fixed by the positivity step
    over the call / dx^2 [m]).
    """
    nx, nz = h.shape
    coef = g * dt * dt / (dx * dx)
    fixed = 0.0
    for _ in range(n_steps):
        for i in range(nx):
            for j in range(nz):
                cur = h[i, j]
                h[i, j] = cur + keep * (cur - hp[i, j])
                hp[i, j] = cur
        if parity == 0:
            _solve_x(h, hp, b, coef, cp, kbuf)
            _solve_z(h, hp, b, coef, cp, kbuf)
        else:
            _solve_z(h, hp, b, coef, cp, kbuf)
            _solve_x(h, hp, b, coef, cp, kbuf)
        parity = 1 - parity
        fixed += _keep_nonnegative(h, b)
    return parity, fixed


# ----------------------------------------------------------------------------------------------
# Queries
# ----------------------------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _bilinear_cell(fx, fz, nx, nz):
    """Cell corners (i, j, i1, j1) and weights (tx, tz) of the bilinear stencil at fractional cell-centre
    coordinates (fx, fz), clamped to the grid: outside the centres' hull the nearest edge value."""
    fx = min(max(fx, 0.0), nx - 1.0)
    fz = min(max(fz, 0.0), nz - 1.0)
    i = min(int(fx), max(nx - 2, 0))
    j = min(int(fz), max(nz - 2, 0))
    return i, j, min(i + 1, nx - 1), min(j + 1, nz - 1), fx - i, fz - j


@njit(cache=True, error_model="numpy")
def _bilinear(field, i, j, i1, j1, tx, tz):
    """The bilinear interpolation of field (nx, nz) on the stencil of ``_bilinear_cell``."""
    return ((1.0 - tx) * ((1.0 - tz) * field[i, j] + tz * field[i, j1])
            + tx * ((1.0 - tz) * field[i1, j] + tz * field[i1, j1]))


@njit(cache=True, error_model="numpy")
def bilinear(field, x0, z0, dx, xq, zq, out):
    """Bilinear interpolation of a cell-centred field at points (xq, zq) [m].

    field: (nx, nz); cell (i, j) has its centre at (x0 + (i + 1/2) dx, z0 + (j + 1/2) dx).
    xq, zq, out: (k,).  Points outside the centres' hull take the nearest edge value.
    """
    nx, nz = field.shape
    for p in range(xq.shape[0]):
        i, j, i1, j1, tx, tz = _bilinear_cell((xq[p] - x0) / dx - 0.5, (zq[p] - z0) / dx - 0.5, nx, nz)
        out[p] = _bilinear(field, i, j, i1, j1, tx, tz)


@njit(cache=True, error_model="numpy")
def face_depths(h, b, fx, fz):
    """Face depths d_f [m] of the step that starts from surface h (module doc).

    fx: (nx-1, nz) faces between (i, j) and (i+1, j); fz: (nx, nz-1)."""
    nx, nz = h.shape
    for i in range(nx - 1):
        for j in range(nz):
            fx[i, j] = _face_k(1.0, h[i, j], h[i + 1, j], b[i, j], b[i + 1, j])
    for i in range(nx):
        for j in range(nz - 1):
            fz[i, j] = _face_k(1.0, h[i, j], h[i, j + 1], b[i, j], b[i, j + 1])


@njit(cache=True, error_model="numpy")
def _apply_kd(phi, fx, fz, out):
    """out_i = sum over faces f of cell i of d_f (phi_i - phi_j)  (the -div(d grad) stencil * dx^2)."""
    nx, nz = phi.shape
    out[:, :] = 0.0
    for i in range(nx - 1):
        for j in range(nz):
            q = fx[i, j] * (phi[i, j] - phi[i + 1, j])
            out[i, j] += q
            out[i + 1, j] -= q
    for i in range(nx):
        for j in range(nz - 1):
            q = fz[i, j] * (phi[i, j] - phi[i, j + 1])
            out[i, j] += q
            out[i, j + 1] -= q


@njit(cache=True, error_model="numpy")
def velocity_potential(rate, fx, fz, dx, phi, rtol, max_iter):
    """Solve -div(d grad phi) = rate for the velocity potential phi [m^2/s].

    The continuity equation (K&M Eq. 4, h_t = -div(d u)) with u = grad phi: the
    irrotational flow whose convergence produces the observed rate h_t [m/s]
    (rate: (nx, nz)), which is also the flow of least kinetic energy that does.
    Discretely sum_f d_f (phi_i - phi_j) = rate_i dx^2 with walls at the edge;
    fx, fz: face depths (``face_depths``).  Jacobi-preconditioned conjugate
    gradients from the initial guess in phi (updated in place) until the
    residual norm is below rtol times the right-hand side's.  The right-hand
    side's mean over cells with a wet face is removed first (it is zero when the
    volume is conserved).  Returns the number of iterations.
    """
    nx, nz = phi.shape
    diag = np.zeros((nx, nz))
    for i in range(nx - 1):
        for j in range(nz):
            diag[i, j] += fx[i, j]
            diag[i + 1, j] += fx[i, j]
    for i in range(nx):
        for j in range(nz - 1):
            diag[i, j] += fz[i, j]
            diag[i, j + 1] += fz[i, j]
    rhs = np.zeros((nx, nz))
    n_act = 0
    s = 0.0
    for i in range(nx):
        for j in range(nz):
            if diag[i, j] > 0.0:
                rhs[i, j] = rate[i, j] * dx * dx
                s += rhs[i, j]
                n_act += 1
            else:
                phi[i, j] = 0.0
    if n_act == 0:
        return 0
    mean = s / n_act
    bnorm = 0.0
    for i in range(nx):
        for j in range(nz):
            if diag[i, j] > 0.0:
                rhs[i, j] -= mean
                bnorm += rhs[i, j] * rhs[i, j]
    bnorm = math.sqrt(bnorm)
    if bnorm == 0.0:
        phi[:, :] = 0.0
        return 0
    r = np.empty((nx, nz))
    _apply_kd(phi, fx, fz, r)
    z = np.zeros((nx, nz))
    rz = 0.0
    rnorm = 0.0
    for i in range(nx):
        for j in range(nz):
            r[i, j] = rhs[i, j] - r[i, j]
            if diag[i, j] > 0.0:
                z[i, j] = r[i, j] / diag[i, j]
            rz += r[i, j] * z[i, j]
            rnorm += r[i, j] * r[i, j]
    p = z.copy()
    ap = np.empty((nx, nz))
    it = 0
    while it < max_iter and math.sqrt(rnorm) > rtol * bnorm:
        _apply_kd(p, fx, fz, ap)
        pap = 0.0
        for i in range(nx):
            for j in range(nz):
                pap += p[i, j] * ap[i, j]
        if pap <= 0.0:
            break
        alpha = rz / pap
        rz_new = 0.0
        rnorm = 0.0
        for i in range(nx):
            for j in range(nz):
                phi[i, j] += alpha * p[i, j]
                r[i, j] -= alpha * ap[i, j]
                if diag[i, j] > 0.0:
                    z[i, j] = r[i, j] / diag[i, j]
                rz_new += r[i, j] * z[i, j]
                rnorm += r[i, j] * r[i, j]
        beta = rz_new / rz
        rz = rz_new
        for i in range(nx):
            for j in range(nz):
                p[i, j] = z[i, j] + beta * p[i, j]
        it += 1
    return it


@njit(cache=True, error_model="numpy")
def kinetic_energy_density(phi, fx, fz, rho, dx, out):
    """Kinetic energy per cell area [J/m^2] of the flow u = grad phi.

    Face f carries u_f = (phi_j - phi_i) / dx over a dx x dx control area and depth
    d_f: energy 1/2 rho d_f u_f^2 dx^2 = 1/2 rho d_f (phi_j - phi_i)^2 [J], split
    evenly between its two cells.  out: (nx, nz), overwritten.
    """
    nx, nz = phi.shape
    out[:, :] = 0.0
    a = 1.0 / (dx * dx)
    for i in range(nx - 1):
        for j in range(nz):
            dphi = phi[i + 1, j] - phi[i, j]
            e = 0.25 * rho * fx[i, j] * dphi * dphi * a
            out[i, j] += e
            out[i + 1, j] += e
    for i in range(nx):
        for j in range(nz - 1):
            dphi = phi[i, j + 1] - phi[i, j]
            e = 0.25 * rho * fz[i, j] * dphi * dphi * a
            out[i, j] += e
            out[i, j + 1] += e


# ----------------------------------------------------------------------------------------------
# Coupling to creatures
# ----------------------------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def _bump(q):
    """Smooth compact weight (1 - q^2)^2 for q < 1, else 0."""
    if q >= 1.0:
        return 0.0
    t = 1.0 - q * q
    return t * t


@njit(cache=True, error_model="numpy")
def disturb_points(h, hp, b, x0, z0, dx, pts, vel, radii, dt, c_vert, c_horiz, wet_eps):
    """Water pushed by moving submerged points (legs' tips, body nodes).

    Modelling choice (not K&M's object coupling, which displaces the volume an
    object occupies): each point p with radius r is a vertical cylinder of
    radius r through the water column.  Over ``dt`` [s] it moves water between
    cells without creating or destroying any:

    * vertical: V_v = -c_vert v_y pi r^2 dt [m^3] leaves a disc of radius
      R = r + 1.5 dx around the point and is spread over a disc of radius 2 R
      (a "Mexican hat" of zero sum): a point moving down digs a dimple and
      raises a ring, one moving up draws water in.
    * horizontal: V_h = c_horiz |v_h| (2 r) s dt [m^3], the volume the cylinder's
      immersed frontal area (2 r times the immersed height s) sweeps, leaves the
      half-disc of radius R behind the point (weights (1 - q^2)^2 max(0, -cos))
      and is added to the half-disc ahead (max(0, cos)): a bow crest and a
      trough behind.

    Only wet cells (depth > wet_eps [m]) take part; a transfer that would take
    more water from a cell than it holds is scaled down as a whole, so volume
    is conserved to rounding and no depth becomes negative.  A point is
    submerged when its lowest point y - r is below the local surface and the
    water there is deeper than wet_eps.  The change is a displacement (added to
    both h and hp), not an impulse.

    pts, vel: (k, 3) positions [m] and velocities [m/s] in the world frame (y up);
    radii: (k,) [m].  Returns the number of submerged points.
    """
    nx, nz = h.shape
    n_sub = 0
    cell_area = dx * dx
    for p in range(pts.shape[0]):
        x = pts[p, 0]
        y = pts[p, 1]
        z = pts[p, 2]
        r = radii[p]
        fx = (x - x0) / dx - 0.5
        fz = (z - z0) / dx - 0.5
        if fx < -0.5 or fz < -0.5 or fx > nx - 0.5 or fz > nz - 0.5:
            continue
        # local surface and bed (bilinear, clamped)
        i, j, i1, j1, tx, tz = _bilinear_cell(fx, fz, nx, nz)
        hs = _bilinear(h, i, j, i1, j1, tx, tz)
        bs = _bilinear(b, i, j, i1, j1, tx, tz)
        if hs - bs <= wet_eps or y - r >= hs:
            continue
        immersed = min(y + r, hs) - max(y - r, bs)
        if immersed <= 0.0:
            continue
        n_sub += 1
        vx = vel[p, 0]
        vy = vel[p, 1]
        vz = vel[p, 2]
        vh = math.sqrt(vx * vx + vz * vz)
        vol_v = -c_vert * vy * math.pi * r * r * dt
        vol_h = c_horiz * vh * 2.0 * r * immersed * dt
        ex = vx / vh if vh > 0.0 else 0.0
        ez = vz / vh if vh > 0.0 else 0.0
        R1 = r + 1.5 * dx
        R2 = 2.0 * R1
        ilo = max(int(math.floor((x - R2 - x0) / dx)), 0)
        ihi = min(int(math.ceil((x + R2 - x0) / dx)), nx - 1)
        jlo = max(int(math.floor((z - R2 - z0) / dx)), 0)
        jhi = min(int(math.ceil((z + R2 - z0) / dx)), nz - 1)
        # pass 1: kernel sums over wet cells
        sc = 0.0
        sr = 0.0
        sa = 0.0
        sb = 0.0
        for ii in range(ilo, ihi + 1):
            for jj in range(jlo, jhi + 1):
                if h[ii, jj] - b[ii, jj] <= wet_eps:
                    continue
                rx = x0 + (ii + 0.5) * dx - x
                rz = z0 + (jj + 0.5) * dx - z
                s = math.sqrt(rx * rx + rz * rz)
                sc += _bump(s / R1)
                sr += _bump(s / R2)
                w = _bump(s / R1)
                if s > 0.0 and w > 0.0:
                    cosang = (rx * ex + rz * ez) / s
                    if cosang > 0.0:
                        sa += w * cosang
                    else:
                        sb -= w * cosang
        use_v = sc > 0.0 and sr > 0.0 and vol_v != 0.0
        use_h = sa > 0.0 and sb > 0.0 and vol_h != 0.0
        if not (use_v or use_h):
            continue
        reach = PointReach(x, z, R1, R2, ex, ez)
        transfer = PointTransfer(use_v, vol_v, sc, sr, use_h, vol_h, sa, sb)
        # pass 2: largest scale that keeps every depth >= 0
        scale = 1.0
        for ii in range(ilo, ihi + 1):
            for jj in range(jlo, jhi + 1):
                depth = h[ii, jj] - b[ii, jj]
                if depth <= wet_eps:
                    continue
                dv = _cell_change(x0, z0, dx, ii, jj, reach, transfer)
                dh = dv / cell_area
                if dh < 0.0 and -dh * scale > depth * (1.0 - 1e-12):
                    scale = depth * (1.0 - 1e-12) / -dh  # the margin keeps rounding from digging below the bed
        # pass 3: apply as a displacement
        for ii in range(ilo, ihi + 1):
            for jj in range(jlo, jhi + 1):
                if h[ii, jj] - b[ii, jj] <= wet_eps:
                    continue
                dv = _cell_change(x0, z0, dx, ii, jj, reach, transfer)
                dh = scale * dv / cell_area
                h[ii, jj] += dh
                hp[ii, jj] += dh
    return n_sub


# ``_cell_change``'s per-point arguments, built in ``disturb_points`` (numba compiles a namedtuple of scalars as a
# struct of them).  PointReach: the point's x, z [m], its disc radii R1, R2 = 2 R1 [m] and its unit horizontal
# heading ex, ez [-] (0 when it does not move sideways).  PointTransfer: the vertical transfer's use flag, volume
# vol_v [m^3] and kernel sums sc (disc R1), sr (disc R2) [-]; the horizontal transfer's use flag, volume vol_h
# [m^3] and its half-disc sums ahead sa and behind sb [-].
PointReach = namedtuple("PointReach", "x z R1 R2 ex ez")
PointTransfer = namedtuple("PointTransfer", "use_v vol_v sc sr use_h vol_h sa sb")


@njit(cache=True, error_model="numpy")
def _cell_change(x0, z0, dx, ii, jj, reach, transfer):
    """Volume [m^3] that one point's transfer adds to cell (ii, jj) (``disturb_points``); reach a
    ``PointReach``, transfer a ``PointTransfer``."""
    x, z, R1, R2, ex, ez = reach
    use_v, vol_v, sc, sr, use_h, vol_h, sa, sb = transfer
    rx = x0 + (ii + 0.5) * dx - x
    rz = z0 + (jj + 0.5) * dx - z
    s = math.sqrt(rx * rx + rz * rz)
    dv = 0.0
    if use_v:
        dv += vol_v * (_bump(s / R2) / sr - _bump(s / R1) / sc)
    if use_h and s > 0.0:
        w = _bump(s / R1)
        if w > 0.0:
            cosang = (rx * ex + rz * ez) / s
            if cosang > 0.0:
                dv += vol_h * w * cosang / sa
            else:
                dv += vol_h * w * cosang / sb
    return dv


# ----------------------------------------------------------------------------------------------
# Bed from a terrain
# ----------------------------------------------------------------------------------------------

@njit(cache=True, error_model="numpy")
def bed_from_terrain(kind, f, xs, zs, y_lo, y_hi, out):
    """Bed height [m] of a terrain (``terrain_kernels`` kind, params) at cell centres.

    For every (xs[i], zs[j]) the height where the terrain's signed distance
    crosses zero along the vertical between y_lo and y_hi, by bisection to
    1e-12 m (assumes one crossing: a height-field-like terrain).  A column with
    no ground above y_lo gets y_lo; one inside the ground up to y_hi gets y_hi.
    out: (len(xs), len(zs)).
    """
    for i in range(xs.shape[0]):
        for j in range(zs.shape[0]):
            x = xs[i]
            z = zs[j]
            lo = y_lo
            hi = y_hi
            y = y_lo
            # one call site of signed_distance (each site costs compile time):
            # probe y_lo, then y_hi, then bisect
            for it in range(203):
                inside = signed_distance(kind, f, x, y, z) <= 0.0
                if it == 0:
                    if not inside:  # no ground above y_lo
                        break
                    y = y_hi
                    continue
                if it == 1 and inside:  # ground all the way up to y_hi
                    lo = y_hi
                    break
                if inside:
                    lo = y
                else:
                    hi = y
                if hi - lo < 1e-12:
                    break
                y = 0.5 * (lo + hi)
            out[i, j] = lo if lo == y_lo or lo == y_hi else 0.5 * (lo + hi)
