"""Shallow water after Kass and Miller 1990 (bench_myriapoda.world.water, issue 6 "Shallow water").

World frame y up, SI units.  Courant number C = sqrt(g d) dt / dx throughout.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from bench_myriapoda.world import water_kernels as wk
from bench_myriapoda.world.terrain_kernels import N_TERRAIN_PARAMS, SLOPE
from bench_myriapoda.world.water import ShallowWater

G = 9.81


# ---------------------------------------------------------------------------------------- helpers

def ring_radius(water: ShallowWater, xc: float, zc: float, level: float, r_max: float) -> float:
    """Radius [m] of the crest of the azimuthally averaged surface elevation about (xc, zc).

    Elevation averaged over rings one cell wide, the largest ring mean below r_max,
    refined by a parabola through it and its two neighbours.
    """
    X, Z = np.meshgrid(water.x, water.z, indexing="ij")
    r = np.hypot(X - xc, Z - zc).ravel()
    k = (r / water.dx).astype(int)
    n = int(r_max / water.dx)
    eta = (water.h - level).ravel()
    sums = np.bincount(k, weights=eta, minlength=n + 2)[: n + 2]
    rad = np.bincount(k, weights=r, minlength=n + 2)[: n + 2]
    cnt = np.bincount(k, minlength=n + 2)[: n + 2]
    prof = sums / np.maximum(cnt, 1)
    mean_r = rad / np.maximum(cnt, 1)
    m = int(np.argmax(prof[1:n])) + 1
    y0, y1, y2 = prof[m - 1], prof[m], prof[m + 1]
    den = y0 - 2.0 * y1 + y2
    off = 0.5 * (y0 - y2) / den if den < 0.0 else 0.0
    return float(mean_r[m] + off * water.dx)


def dense_tridiagonal(kface: np.ndarray) -> np.ndarray:
    """I + K for one line of n cells with face coefficients kface (n-1,): K&M's matrix."""
    n = kface.size + 1
    a = np.eye(n)
    for i, k in enumerate(kface):
        a[i, i] += k
        a[i + 1, i + 1] += k
        a[i, i + 1] -= k
        a[i + 1, i] -= k
    return a


# ------------------------------------------------------------------------------- the scheme itself

@pytest.mark.parametrize("parity", [0, 1])
def test_adi_step_is_the_factorised_implicit_solve(parity):
    """One step equals (I + dt^2 K_a)(I + dt^2 K_b) h(n) = h(n-1) + keep (h(n-1) - h(n-2)),
    solved densely, on an odd, non-square grid with dry cells (zero-depth faces)."""
    rng = np.random.default_rng(3)
    nx, nz, dx, dt, g, keep = 7, 10, 0.02, 0.03, G, 0.9
    b = rng.uniform(-0.06, -0.03, (nx, nz))
    b[2, 3:6] = 0.05  # dry: above the water
    hp = np.maximum(rng.uniform(-0.002, 0.002, (nx, nz)), b)
    h = np.maximum(hp + rng.uniform(-0.001, 0.001, (nx, nz)), b)
    hp[b > 0] = h[b > 0] = b[b > 0]
    coef = g * dt * dt / dx ** 2

    def face(ha, hb, ba, bb):
        return coef * np.maximum(np.maximum(ha, hb) - np.maximum(ba, bb), 0.0)

    kx = face(h[:-1], h[1:], b[:-1], b[1:])  # from level n-1, the h passed in
    kz = face(h[:, :-1], h[:, 1:], b[:, :-1], b[:, 1:])
    rhs = h + keep * (h - hp)

    def sx(f):
        return np.stack([np.linalg.solve(dense_tridiagonal(kx[:, j]), f[:, j]) for j in range(nz)], axis=1)

    def sz(f):
        return np.stack([np.linalg.solve(dense_tridiagonal(kz[i]), f[i]) for i in range(nx)], axis=0)

    expect = sz(sx(rhs)) if parity == 0 else sx(sz(rhs))
    h_old = h.copy()
    hk, hpk = h.copy(), hp.copy()
    new_parity, fixed = wk.adi_steps(hk, hpk, b, dt, 1, g, dx, keep, parity, np.zeros((nx, nz)), np.zeros(16))
    assert new_parity == 1 - parity
    assert fixed == 0.0  # nothing went below its bed here
    np.testing.assert_allclose(hk, expect, rtol=0, atol=1e-14)
    np.testing.assert_array_equal(hpk, h_old)
    assert abs(np.sum(hk) - np.sum(rhs)) < 1e-13  # unit column sums: volume


# ------------------------------------------------------------------------------------- wave speed

@pytest.mark.parametrize("depth", [0.02, 0.05])
def test_single_disturbance_spreads_as_a_ring_at_sqrt_gd(depth):
    """A small Gaussian bump in still water on a flat bed spreads as a ring at c = sqrt(g d).

    256 x 256 cells of 4 mm, bump sigma = 4 cells, amplitude 1 % of the depth,
    Courant number C = 0.5 (the implicit scheme's phase and group-speed errors
    for waves of ~sigma are about 2 %).  The crest radius of the azimuthal mean
    is fitted over c t in [0.12, 0.42] m (before it reaches the walls at 0.51 m);
    the same measurement on the exact linear solution gives 0.1 %.
    """
    dx, n = 0.004, 256
    c = math.sqrt(G * depth)
    courant = 0.5
    dt = courant * dx / c
    w = ShallowWater(n * dx, n * dx, dx, depth_m=depth)
    assert w.courant_number(dt) == pytest.approx(courant, rel=0.02)
    w.add_gaussian_bump(0.0, 0.0, 0.01 * depth, 4 * dx)
    v0 = w.volume()
    ts, rs = [], []
    while c * w.t < 0.42:
        w.step(dt, 1)
        if c * w.t >= 0.12:
            ts.append(w.t)
            rs.append(ring_radius(w, 0.0, 0.0, depth, 0.48))
    speed = np.polyfit(ts, rs, 1)[0]
    assert abs(speed / c - 1.0) < 0.10, (speed, c)
    assert abs(w.volume() / v0 - 1.0) < 1e-9
    # A progressive wave carries as much kinetic as potential energy: checks the
    # kinetic-energy estimate from dh/dt.
    pe, ke = w.energy_components()
    assert pe > 0.0 and ke == pytest.approx(pe, rel=0.25)


# ------------------------------------------------------------------------ conservation, stillness

def island_bed(X, Z):
    """A bed sloping up toward +x, with a round island standing out of the water."""
    return np.where(np.hypot(X - 0.15, Z + 0.1) < 0.12, 0.08, -0.05 - 0.02 * X)


@pytest.mark.parametrize("courant, damping", [(0.5, 0.0), (8.0, 0.0), (2.0, 2.0)])
def test_volume_conserved_and_energy_never_grows(courant, damping):
    """No source: volume to 1e-9 relative over many steps, energy non-increasing at every step,
    with and without damping, at C = 0.5 and far beyond explicit limits (C = 8)."""
    dx = 0.015
    w = ShallowWater(0.96, 0.96, dx, level_m=0.0, bed=island_bed, damping=damping)
    assert (~w.wet()).sum() > 40  # the island is dry
    for xc, zc, a in [(-0.2, 0.1, 0.004), (0.1, 0.25, -0.003), (0.3, -0.3, 0.002)]:
        w.add_gaussian_bump(xc, zc, a, 0.04)
    dt = courant * dx / math.sqrt(G * w.depth().max())
    v0 = w.volume()
    energies = [w.wake_energy()]
    for _ in range(150):
        w.step(dt, 1)
        energies.append(w.wake_energy())
        assert np.all(np.isfinite(w.h))
    e = np.array(energies)
    assert abs(w.volume() / v0 - 1.0) < 1e-9
    assert e[1] > 0.0
    assert np.all(np.diff(e) <= 1e-12 * e[0]), np.diff(e).max()
    assert e[-1] < e[1]  # dissipated, not merely bounded
    assert np.all(w.h >= w.b)


def test_still_water_stays_still():
    """Still water over a sloping bed with an island and a dry bank does not move."""
    dx = 0.01
    w = ShallowWater(0.96, 0.64, dx, level_m=0.0, bed=lambda X, Z: np.where(X > 0.35, 0.02, island_bed(X, Z)))
    assert np.sum(w.b > 0.0) > 500  # island and bank dry
    h0 = w.h.copy()
    w.step(0.01, 500)
    assert np.max(np.abs(w.h - h0)) < 1e-12
    assert w.wake_energy() < 1e-18


def test_still_water_has_no_kinetic_energy_and_no_potential_solve(monkeypatch):
    """A step that moved the surface by round-off only (``ShallowWater.surface_moved``) has kinetic energy 0,
    without the velocity-potential solve (on round-off its conjugate gradients ran to their 20,000-iteration
    cap: 9.4 CPU s at the end of every short fig12 run); a wave a millimetre high still gets the solve and a
    kinetic energy near its potential one."""
    from bench_myriapoda.world import water_kernels as wk

    calls = []
    solve = wk.velocity_potential
    monkeypatch.setattr(wk, "velocity_potential", lambda *a: calls.append(1) or solve(*a))
    w = ShallowWater(0.96, 0.64, 0.01, level_m=0.0, bed=island_bed)
    w.step(0.01, 50)
    assert not w.surface_moved()
    pe, ke = w.energy_components()
    assert ke == 0.0 and pe < 1e-18 and calls == []
    w.add_gaussian_bump(-0.2, 0.1, 0.001, 0.04)
    w.step(0.01, 20)
    assert w.surface_moved()
    pe, ke = w.energy_components()
    assert calls == [1] and pe > 0.0 and ke == pytest.approx(pe, rel=0.5)


# ---------------------------------------------------------------------------------------- dry cells

def test_water_stays_out_of_dry_ground_and_depth_never_negative():
    """Waves running onto a beach and around an island: no negative depth anywhere, the
    ground that stands above every wave stays exactly dry, volume is conserved, and the
    positivity fix (thin layers) is exercised."""
    dx, level, amp = 0.01, 0.0, 0.01

    def bed(X, Z):
        b = -0.04 + 0.08 * np.clip((X + 0.1) / 0.5, 0.0, 1.0)  # beach rising to +4 cm
        return np.where(np.hypot(X + 0.3, Z) < 0.08, 0.03, b)  # island 3 cm high

    w = ShallowWater(1.2, 0.6, dx, level_m=level, bed=bed)
    high = w.b > level + 2.0 * amp
    assert high.sum() > 1000 and not np.any(w.wet()[high])
    wet0 = w.wet()
    w.add_gaussian_bump(-0.05, 0.0, amp, 0.05)
    v0 = w.volume()
    dt = 0.5 * dx / math.sqrt(G * 0.04)
    for _ in range(60):
        w.step(dt, 10)
        assert np.all(w.h - w.b >= 0.0)
        assert np.all(w.h[high] == w.b[high])
    assert abs(w.volume() / v0 - 1.0) < 1e-9
    assert w.positivity_fix_m3 > 0.0  # thin layers did go below their bed and were fixed
    assert np.sum(w.wet() & ~wet0) > 10  # the wave ran up the beach


# ------------------------------------------------------------------------------ creature coupling

def test_disturb_signs_and_volume():
    """A point moving down digs a dimple and raises a ring; one moving along +x raises water
    ahead and lowers it behind; a point above the water or on dry ground does nothing;
    water volume is unchanged."""
    dx, depth = 0.005, 0.02
    w = ShallowWater(0.4, 0.4, dx, depth_m=depth, bed=lambda X, Z: np.where(X > 0.15, 0.05, 0.0))
    v0 = w.volume()
    i0, j0 = w.cell_index(0.0, 0.0)

    n = w.disturb([[0.0, 0.01, 0.0]], [[0.0, -0.5, 0.0]], 0.004, 0.01)
    assert n == 1
    eta = w.h - depth
    assert eta[i0, j0] < 0.0 and eta[i0 + 3, j0] > 0.0 and eta[i0, j0 - 3] > 0.0
    assert np.array_equal(w.h, w.h_prev)  # a displacement, not an impulse
    assert abs(w.volume() / v0 - 1.0) < 1e-12

    w = ShallowWater(0.4, 0.4, dx, depth_m=depth)
    v0 = w.volume()
    w.disturb(np.array([[0.0, 0.005, 0.0]]), np.array([[0.3, 0.0, 0.0]]), np.array([0.004]), 0.01)
    eta = w.h - depth
    assert eta[i0, j0] > 0.0 and eta[i0 + 1, j0] > 0.0  # ahead: cell centres at x = 2.5, 7.5 mm
    assert eta[i0 - 1, j0] < 0.0 and eta[i0 - 2, j0] < 0.0  # behind
    assert abs(eta[i0 + 1, j0 + 1] - eta[i0 + 1, j0 - 2]) < 1e-15  # symmetric about the path
    assert abs(w.volume() / v0 - 1.0) < 1e-12

    w = ShallowWater(0.4, 0.4, dx, depth_m=depth, bed=lambda X, Z: np.where(X > 0.1, 0.05, 0.0))
    h0 = w.h.copy()
    assert w.disturb([[0.0, depth + 0.01, 0.0]], [[0.3, -0.3, 0.0]], 0.004, 0.01) == 0  # above the water
    assert w.disturb([[0.15, 0.052, 0.0]], [[0.3, -0.3, 0.0]], 0.004, 0.01) == 0  # on the dry bank
    assert w.disturb([[5.0, 0.0, 0.0]], [[0.3, -0.3, 0.0]], 0.004, 0.01) == 0  # off the grid
    assert np.array_equal(w.h, h0)


def test_disturb_never_takes_more_water_than_a_cell_holds():
    """A fast, wide point in a thin film: the transfer is scaled, depths stay >= 0."""
    w = ShallowWater(0.2, 0.2, 0.005, depth_m=0.0005)
    v0 = w.volume()
    w.disturb([[0.0, 0.0, 0.0]], [[3.0, -3.0, 1.0]], 0.01, 0.05)
    assert np.all(w.h >= w.b)
    assert np.min(w.h - w.b) < 1e-12  # some cell was emptied: the limit acted
    assert abs(w.volume() / v0 - 1.0) < 1e-12


def test_point_moving_through_water_leaves_a_wake_behind_it():
    """A leg-like point (r = 3 mm) wading at 0.2 m/s through 1 cm of water (c = 0.31 m/s) for
    1.5 s, coupled once per water step: more wave energy behind it than ahead, volume kept."""
    dx, depth, speed, r = 0.005, 0.01, 0.2, 0.003
    w = ShallowWater(1.5, 1.0, dx, depth_m=depth)
    dt = 0.5 * dx / math.sqrt(G * depth)  # C = 0.5
    v0 = w.volume()
    x = -0.5
    for _ in range(int(1.5 / dt)):
        # the point's centre 2 mm above the bed, moving along +x
        w.disturb(np.array([[x, 0.002, 0.0]]), np.array([[speed, 0.0, 0.0]]), r, dt)
        w.step(dt, 1)
        x += speed * dt
    X, _ = np.meshgrid(w.x, w.z, indexing="ij")
    behind, ahead = w.wake_energy(X < x), w.wake_energy(X >= x)
    assert behind + ahead == pytest.approx(w.wake_energy(), rel=1e-12)
    assert behind > 1e-7  # a wake of a fraction of a microjoule: it is there
    assert behind > 2.0 * ahead, (behind, ahead)
    assert abs(w.volume() / v0 - 1.0) < 1e-9
    assert np.all(w.h >= w.b)


# --------------------------------------------------------------------------------- set-up, queries

def test_bed_from_a_terrain_and_bilinear_queries():
    f = np.zeros(N_TERRAIN_PARAMS)
    f[0], f[1] = -0.02, math.radians(5.0)  # slope through (0, -0.02, 0) rising toward +x
    w = ShallowWater(0.5, 0.3, 0.01, level_m=0.0, bed=(SLOPE, f))
    np.testing.assert_allclose(w.b, (-0.02 + np.tan(f[1]) * w.x)[:, None] * np.ones(w.nz), atol=1e-10)
    assert np.all(w.wet() == (w.b < 0.0))
    # bilinear in the cell centres: exact for a field linear in x and z
    w.h[...] = 0.1 + 0.3 * w.x[:, None] - 0.2 * w.z[None, :]
    xs, zs = np.array([-0.1, 0.013, 0.2]), np.array([0.05, -0.07, 0.0])
    np.testing.assert_allclose(w.surface_height(xs, zs), 0.1 + 0.3 * xs - 0.2 * zs, atol=1e-14)
    assert isinstance(w.surface_height(0.0, 0.0), float)
    assert w.surface_height(10.0, 0.0) == pytest.approx(w.surface_height(w.x[-1], 0.0))  # clamped
    assert w.bed_height(0.1, 0.0) == pytest.approx(-0.02 + np.tan(f[1]) * 0.1, abs=1e-10)


def test_bad_arguments_raise():
    with pytest.raises(ValueError):
        ShallowWater(1.0, 1.0, 0.01)  # neither depth nor level
    with pytest.raises(ValueError):
        ShallowWater(1.0, 1.0, 0.0, depth_m=0.01)
    with pytest.raises(ValueError):
        ShallowWater(1.0, 1.0, 0.01, depth_m=0.01, damping=-1.0)
    w = ShallowWater(0.1, 0.1, 0.01, depth_m=0.01)
    with pytest.raises(ValueError):
        w.step(0.0)
    with pytest.raises(ValueError):
        w.disturb(np.zeros((2, 3)), np.zeros((3, 3)), 0.01, 0.01)


def test_changing_dt_keeps_the_surface_velocity():
    """Halving dt mid-run (h_prev rescaled) follows the same waves as a constant dt."""
    dx, depth = 0.01, 0.05
    dt = 0.5 * dx / math.sqrt(G * depth)
    runs = []
    for halve in (False, True):
        w = ShallowWater(0.64, 0.64, dx, depth_m=depth)
        w.add_gaussian_bump(0.0, 0.0, 0.001, 0.04)
        w.step(dt, 20)
        if halve:
            w.step(0.5 * dt, 40)
        else:
            w.step(dt, 20)
        assert w.t == pytest.approx(40 * dt)
        runs.append(w.h - depth)
    amp = np.abs(runs[0]).max()
    assert amp > 1e-4
    # the schemes dissipate differently at C = 0.5 and 0.25 (8 %); without the rescaling: 340 %
    assert np.abs(runs[1] - runs[0]).max() < 0.25 * amp


def test_advance_splits_a_chunk_into_equal_steps():
    w = ShallowWater(0.2, 0.2, 0.01, depth_m=0.01)
    assert w.advance(0.1, 0.03) == 4
    assert w.t == pytest.approx(0.1) and w.steps == 4
    assert w.advance(0.09, 0.03) == 3
    assert w.advance(0.0, 0.03) == 0
