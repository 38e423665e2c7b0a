"""A shallow-water layer over the terrain (myriapod paper Sec. 6.2, after Kass and Miller 1990).

The myriapod paper couples the legs of a centipede to "a shallow water simulator
[Kass and Miller 1990]": the water ripples under the legs and a wake forms
behind the creature (Fig. 12).  ``ShallowWater`` is that simulator: a height
field h(x, z) of the water surface over a bed b(x, z) on a regular x-z grid,
advanced with Kass and Miller's implicit, unconditionally stable scheme for the
linearised shallow-water equation h_tt = g d (h_xx + h_zz), d = h - b (K&M Eq. 6;
``water_kernels`` documents the discretisation, the equations it cites and the
choices made).

World frame (PAPER-NOTES.md): y up, gravity along -y, SI units.  The grid
covers [x0, x0 + nx dx] x [z0, z0 + nz dx]; cell (i, j) -- array index [i, j]
of every (nx, nz) field -- has its centre at (x0 + (i + 1/2) dx, z0 + (j + 1/2) dx).
The domain edge is a wall.

Typical use by a body (points per step chunk)::

    water = ShallowWater(2.0, 2.0, 0.01, depth_m=0.01)
    for chunk in chunks:                       # e.g. every 1/100 s of simulated time
        pts, vel, radii = body.submerged_points()          # (k, 3), (k, 3), (k,)
        water.disturb(pts, vel, radii, chunk_duration)
        water.step(dt_water, n_water_steps)                # n dt = chunk_duration
    metrics["wake_energy"] = water.wake_energy()

Stability does not limit dt (K&M); accuracy does: ``courant_number(dt)`` is
C = sqrt(g d_max) dt / dx, and C <= 0.5 keeps the phase speed of waves a few
cells long within a few percent (tests/test_water.py measures the ring speed).
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np

from . import water_kernels as wk

# A step that moves no wet cell's surface by more than this many units in the last place of the largest |h| left
# the water still: the rest is round-off (``ShallowWater.surface_moved``).
ROUNDOFF_ULPS = 64.0

RHO_WATER = 1000.0  # [kg/m^3]
GRAVITY = 9.81  # [m/s^2]

BedSpec = float | np.ndarray | Callable[[np.ndarray, np.ndarray], np.ndarray] | tuple


class ShallowWater:
    """Height-field shallow water after Kass and Miller 1990 on a square-cell x-z grid.

    Parameters
    ----------
    extent_x, extent_z : float
        Size of the water grid along x and z [m]; rounded to whole cells
        (nx = round(extent_x / cell_m), at least 2).
    cell_m : float
        Cell side dx [m].
    depth_m : float, optional
        Still-water depth [m] over flat ground at ``ground_height_m``: the still
        surface is at ``ground_height_m + depth_m``.  Give this or ``level_m``.
    bed : optional
        The bed b(x, z) [m]: ``None`` (flat at ``ground_height_m``), a float
        (flat at that height), an (nx, nz) array of heights at cell centres, a
        callable ``b(X, Z)`` taking and returning (nx, nz) arrays [m], or a
        terrain as its ``(kind, params)`` pair of ``terrain_kernels`` (e.g.
        ``terrain.terrain_from_scenario(sc)``), whose surface height is found
        along each cell centre's vertical.
    level_m : float, optional
        Still-water surface height [m]; overrides ``ground_height_m + depth_m``.
    ground_height_m : float
        Height of the flat ground that ``depth_m`` refers to [m] (default 0).
    origin : (float, float), optional
        (x0, z0) [m] of the grid's corner; default centres the grid on x = z = 0.
    g : float
        Gravitational acceleration [m/s^2].
    damping : float
        Damping rate gamma [1/s] >= 0: each step keeps exp(-gamma dt) of the
        previous step's change (K&M's tau = 1 - exp(-gamma dt)), so the
        damping per second does not depend on dt.  0: only the scheme's own
        numerical dissipation.
    rho : float
        Water density [kg/m^3], for energies.

    State
    -----
    h, h_prev : (nx, nz) float64 water surface height [m] now and one step before.
    b : (nx, nz) float64 bed height [m].  A cell is dry where h - b <= 0; there
    h == b exactly.
    """

    def __init__(self, extent_x: float, extent_z: float, cell_m: float, depth_m: float | None = None,
                 bed: BedSpec | None = None, *, level_m: float | None = None, ground_height_m: float = 0.0,
                 origin: tuple[float, float] | None = None, g: float = GRAVITY, damping: float = 0.0,
                 rho: float = RHO_WATER):
        if not cell_m > 0.0:
            raise ValueError(f"cell_m must be > 0, got {cell_m!r}")
        if not (extent_x > 0.0 and extent_z > 0.0):
            raise ValueError(f"extents must be > 0, got {extent_x!r}, {extent_z!r}")
        if not g > 0.0:
            raise ValueError(f"g must be > 0, got {g!r}")
        if not damping >= 0.0:
            raise ValueError(f"damping must be >= 0 [1/s], got {damping!r}")
        if level_m is None:
            if depth_m is None:
                raise ValueError("give depth_m (still depth over ground_height_m) or level_m")
            level_m = float(ground_height_m) + float(depth_m)
        self.dx = float(cell_m)
        self.nx = max(int(round(extent_x / cell_m)), 2)
        self.nz = max(int(round(extent_z / cell_m)), 2)
        if origin is None:
            origin = (-0.5 * self.nx * self.dx, -0.5 * self.nz * self.dx)
        self.x0, self.z0 = float(origin[0]), float(origin[1])
        self.g = float(g)
        self.damping = float(damping)
        self.rho = float(rho)
        self.level = float(level_m)
        #: (nx,) and (nz,) cell-centre coordinates [m]
        self.x = self.x0 + (np.arange(self.nx) + 0.5) * self.dx
        self.z = self.z0 + (np.arange(self.nz) + 0.5) * self.dx
        self.b = self._bed_array(bed, float(ground_height_m))
        self.h = np.maximum(self.level, self.b)
        self.h_prev = self.h.copy()
        self.t = 0.0  # simulated time [s]
        self.steps = 0
        self.positivity_fix_m3 = 0.0  # water moved by the positivity fix so far [m^3]
        self._parity = 0
        self._last_dt = 0.0
        self._cp = np.zeros((self.nx, self.nz))
        self._kbuf = np.zeros(max(self.nx, self.nz, 8))
        self._phi = np.zeros((self.nx, self.nz))

    # ------------------------------------------------------------------ set-up

    def _bed_array(self, bed, ground: float) -> np.ndarray:
        shape = (self.nx, self.nz)
        if bed is None:
            return np.full(shape, ground)
        if isinstance(bed, (int, float, np.floating)):
            return np.full(shape, float(bed))
        if isinstance(bed, tuple) and len(bed) == 2:
            kind, f = int(bed[0]), np.ascontiguousarray(bed[1], dtype=np.float64)
            out = np.empty(shape)
            span = max(self.nx, self.nz) * self.dx + abs(self.level) + 1.0
            wk.bed_from_terrain(kind, f, self.x, self.z, self.level - 10.0 * span, self.level + 10.0 * span, out)
            return out
        if callable(bed):
            X, Z = np.meshgrid(self.x, self.z, indexing="ij")
            out = np.asarray(bed(X, Z), dtype=np.float64)
            out = np.broadcast_to(out, shape).copy()
        else:
            out = np.array(bed, dtype=np.float64)
            if out.shape != shape:
                raise ValueError(f"bed array must have shape {shape}, got {out.shape}")
        if not np.all(np.isfinite(out)):
            raise ValueError("bed heights must be finite")
        return out

    @property
    def shape(self) -> tuple[int, int]:
        """(nx, nz) of every field."""
        return self.nx, self.nz

    @property
    def cell_area(self) -> float:
        """dx^2 [m^2]."""
        return self.dx * self.dx

    def depth(self) -> np.ndarray:
        """(nx, nz) water depth max(h - b, 0) [m]."""
        return np.maximum(self.h - self.b, 0.0)

    def wet(self) -> np.ndarray:
        """(nx, nz) bool: cells holding water."""
        return self.h > self.b

    def volume(self) -> float:
        """Water volume sum max(h - b, 0) dx^2 [m^3]."""
        return float(np.sum(self.depth()) * self.cell_area)

    def courant_number(self, dt: float) -> float:
        """C = sqrt(g d_max) dt / dx [-] for the deepest water now."""
        return float(np.sqrt(self.g * max(float(self.depth().max()), 0.0)) * dt / self.dx)

    def add_gaussian_bump(self, xc: float, zc: float, amplitude_m: float, sigma_m: float) -> None:
        """Raise the surface of wet cells by amplitude exp(-r^2 / (2 sigma^2)) [m], at rest.

        Adds water (volume about 2 pi sigma^2 amplitude); h and h_prev move
        together, so the bump starts with zero velocity.
        """
        X, Z = np.meshgrid(self.x, self.z, indexing="ij")
        bump = amplitude_m * np.exp(-((X - xc) ** 2 + (Z - zc) ** 2) / (2.0 * sigma_m ** 2))
        bump[~self.wet()] = 0.0
        self.h += bump
        self.h_prev += bump

    # ------------------------------------------------------------------ dynamics

    def step(self, dt: float, n_steps: int = 1) -> None:
        """Advance ``n_steps`` steps of ``dt`` [s] in one numba call (no Python per step).

        Each step solves K&M's implicit system with the alternating-direction
        factorisation (``water_kernels.adi_steps``); unconditionally stable.
        dt may change between calls: h_prev is then rescaled so that the
        surface velocity (h - h_prev) / dt carries over.
        """
        if not dt > 0.0:
            raise ValueError(f"dt must be > 0, got {dt!r}")
        n_steps = int(n_steps)
        if n_steps <= 0:
            return
        if self._last_dt > 0.0 and dt != self._last_dt:
            # The scheme's velocity is (h - h_prev) / dt: keep it across a change of dt.
            self.h_prev[...] = self.h - (self.h - self.h_prev) * (dt / self._last_dt)
        keep = float(np.exp(-self.damping * dt))
        self._parity, fixed = wk.adi_steps(self.h, self.h_prev, self.b, float(dt), n_steps, self.g, self.dx,
                                          keep, self._parity, self._cp, self._kbuf)
        self.positivity_fix_m3 += fixed * self.cell_area
        self.t += n_steps * dt
        self.steps += n_steps
        self._last_dt = float(dt)

    def advance(self, duration_s: float, max_dt: float) -> int:
        """Advance by ``duration_s`` [s] in equal steps of at most ``max_dt`` [s] (one numba call).

        For a body's step chunk: ``disturb(..., duration_s)`` then ``advance(duration_s, max_dt)``.
        Returns the number of steps taken.
        """
        if not max_dt > 0.0:
            raise ValueError(f"max_dt must be > 0, got {max_dt!r}")
        if not duration_s > 0.0:
            return 0
        n = max(int(np.ceil(duration_s / max_dt - 1e-9)), 1)
        self.step(duration_s / n, n)
        return n

    def disturb(self, points, velocities, radii, dt: float, *, vertical_coef: float = 1.0,
                horizontal_coef: float = 1.0, wet_eps_m: float = 1e-6) -> int:
        """Let moving submerged points push the water over a time ``dt`` [s].

        points, velocities: (k, 3) world positions [m] and velocities [m/s] (y up),
        e.g. a body's leg tips or nodes at the start of a step chunk; radii: (k,)
        or a scalar [m].  A point moving vertically moves c_v pi r^2 |v_y| dt of
        water between a disc around it and a ring outside it; one moving
        horizontally moves c_h 2 r s |v_h| dt (s: its immersed height) from
        behind it to ahead of it.  No water is created or destroyed and no depth
        becomes negative: a modelling choice, documented in
        ``water_kernels.disturb_points``.  Returns the number of submerged points.
        """
        pts = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3)
        vel = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 3)
        if vel.shape != pts.shape:
            raise ValueError(f"velocities must have the points' shape {pts.shape}, got {vel.shape}")
        rad = np.ascontiguousarray(np.broadcast_to(np.asarray(radii, dtype=np.float64), (pts.shape[0],)))
        if not dt >= 0.0:
            raise ValueError(f"dt must be >= 0, got {dt!r}")
        if pts.shape[0] == 0 or dt == 0.0:
            return 0
        return int(wk.disturb_points(self.h, self.h_prev, self.b, self.x0, self.z0, self.dx, pts, vel, rad,
                                     float(dt), float(vertical_coef), float(horizontal_coef), float(wet_eps_m)))

    # ------------------------------------------------------------------ queries

    def _interp(self, field: np.ndarray, x, z) -> np.ndarray | float:
        xq = np.asarray(x, dtype=np.float64)
        zq = np.asarray(z, dtype=np.float64)
        xq, zq = np.broadcast_arrays(xq, zq)
        out = np.empty(xq.size)
        wk.bilinear(field, self.x0, self.z0, self.dx, np.ascontiguousarray(xq).reshape(-1),
                    np.ascontiguousarray(zq).reshape(-1), out)
        if xq.ndim == 0:
            return float(out[0])
        return out.reshape(xq.shape)

    def surface_height(self, x, z):
        """Water surface height [m] at (x, z) [m], bilinear in the cell centres.

        Scalars give a float, arrays an array of their broadcast shape.  Outside
        the cell centres' hull the nearest edge value is returned.  Where the
        ground is dry this is the bed height.
        """
        return self._interp(self.h, x, z)

    def bed_height(self, x, z):
        """Bed height [m] at (x, z) [m], bilinear like ``surface_height``."""
        return self._interp(self.b, x, z)

    def rest_level(self) -> float:
        """Height [m] of the flat surface the present volume would settle to.

        The level L with sum max(L - b, 0) dx^2 = volume (by bisection); it is the
        reference of the potential energy (ponds cut off from each other are
        not distinguished).
        """
        vol = float(np.sum(np.maximum(self.h - self.b, 0.0)))
        if vol <= 0.0:
            return float(self.b.min())
        lo = float(self.b.min())
        hi = float(self.b.max()) + vol + 1.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if float(np.sum(np.maximum(mid - self.b, 0.0))) > vol:
                hi = mid
            else:
                lo = mid
            if hi - lo <= 1e-15 * max(1.0, abs(mid)):
                break
        return 0.5 * (lo + hi)

    def surface_rate(self) -> np.ndarray:
        """(nx, nz) dh/dt [m/s] over the last step, (h - h_prev) / dt (zeros before any step)."""
        if self._last_dt <= 0.0:
            return np.zeros_like(self.h)
        return (self.h - self.h_prev) / self._last_dt

    def energy_density(self, *, rtol: float = 1e-10, max_iter: int = 20000) -> tuple[np.ndarray, np.ndarray]:
        """Potential and kinetic energy per unit area of each cell, (nx, nz) each [J/m^2].

        Potential: 1/2 rho g (h - h_rest)^2 on wet cells, h_rest = ``rest_level()``.

        Kinetic: 1/2 rho d |u|^2, where the scheme keeps no velocity, so u is
        estimated from dh/dt: the irrotational flow u = grad phi whose
        convergence gives the last step's dh/dt through continuity (K&M Eq. 4,
        h_t = -div(d u)), i.e. -div(d grad phi) = dh/dt with walls at the edge
        (``water_kernels.velocity_potential``).  Of all flows consistent with the
        observed dh/dt this one has the least kinetic energy; for linear waves
        started from rest (all the waves this model makes) it is the flow.
        dh/dt is the backward difference v/dt, v = h(n) - h(n-1), and the face
        depths are those the last step used.  Then the total is the discrete
        energy of K&M's implicit scheme: with eta = h - h_rest and the scheme
        v(n) - v(n-1) = -dt^2 K eta(n) (K = g K_d / dx^2 symmetric, K_d the
        -div(d grad) stencil), multiplying by K^+ v(n) gives
        E(n) - E(n-1) = -1/2 rho g A |v(n)|^2 - 1/2 rho A (dv/dt) K_d^+ (dv/dt) dx^2 <= 0,
        E = 1/2 rho g A |eta|^2 + 1/2 rho A dx^2 (v/dt) K_d^+ (v/dt) = PE + KE above
        (A = dx^2; exact for one fixed-depth implicit solve, damping only adds
        dissipation).  The alternating-direction factorisation and the depth's
        update from step to step perturb this at second order;
        tests/test_water.py checks that the energy never grows.
        """
        h_rest = self.rest_level()
        wet = self.h > self.b
        pe = np.where(wet, 0.5 * self.rho * self.g * (self.h - h_rest) ** 2, 0.0)
        ke = np.zeros_like(self.h)
        if self._last_dt > 0.0 and self.surface_moved():
            fx = np.empty((self.nx - 1, self.nz))
            fz = np.empty((self.nx, self.nz - 1))
            wk.face_depths(self.h_prev, self.b, fx, fz)
            wk.velocity_potential(self.surface_rate(), fx, fz, self.dx, self._phi, float(rtol), int(max_iter))
            wk.kinetic_energy_density(self._phi, fx, fz, self.rho, self.dx, ke)
        return pe, ke

    def surface_moved(self) -> bool:
        """Whether the last step moved the surface by more than round-off: some wet cell's |h - h_prev| above
        ``ROUNDOFF_ULPS`` units in the last place of the largest |h| [m].

        Below that, dh/dt is the implicit solve's round-off, not a flow: on fig12's 500 x 240 grid, still water (a
        0.05 s worm run that never reaches it) moved by at most 8.3e-17 m in its last step, 12 units in the last
        place of its height, |dh/dt| up to 5e-15 m/s.  The conjugate gradients of ``velocity_potential`` did not
        reach their tolerance on that noise in 20,000 iterations (9.4 CPU s, and a kinetic energy of 8.7e-11 J
        made of that noise), where the wake of a 1 s worm run (the surface moving by up to 4.2 mm a step)
        converged in 1,770 (0.8 CPU s).
        The kinetic energy of still water is 0."""
        wet = self.h > self.b
        if not wet.any():
            return False
        moved = float(np.max(np.abs(self.h[wet] - self.h_prev[wet])))
        return moved > ROUNDOFF_ULPS * np.spacing(float(np.max(np.abs(self.h[wet]))))

    def energy_components(self, mask: np.ndarray | None = None) -> tuple[float, float]:
        """(potential, kinetic) energy [J] of the water's motion, over ``mask`` ((nx, nz) bool) if given."""
        pe, ke = self.energy_density()
        if mask is not None:
            mask = np.asarray(mask, dtype=bool)
            pe = pe[mask]
            ke = ke[mask]
        return float(pe.sum() * self.cell_area), float(ke.sum() * self.cell_area)

    def wake_energy(self, mask: np.ndarray | None = None) -> float:
        """Energy of the water's motion [J]: potential plus kinetic (``energy_density``).

        1/2 rho g sum (h - h_rest)^2 dx^2 + 1/2 rho sum_faces d_f |u_f|^2 dx^2, for the
        whole grid or the cells where ``mask`` ((nx, nz) bool) is true.  Zero for
        still water; the issue's metric ``wake_energy``.
        """
        pe, ke = self.energy_components(mask)
        return pe + ke

    def cell_index(self, x: float, z: float) -> tuple[int, int]:
        """(i, j) of the cell containing (x, z), clamped to the grid."""
        i = int(np.clip(np.floor((x - self.x0) / self.dx), 0, self.nx - 1))
        j = int(np.clip(np.floor((z - self.z0) / self.dx), 0, self.nz - 1))
        return i, j
