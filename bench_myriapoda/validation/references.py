"""Analytic references and the small static solves they are compared with.

Moved here from ``tests/fem/test_fem_physics.py`` and ``tests/test_stable_dt.py`` so that
``validate`` shows what the test suite checks (the tests import them from here).  Every
function returns plain numbers; SI units.

Static states are reached by a damped relaxation run of the real time stepper.  The static
answer depends on neither the mass nor the damping, so both are chosen for a fast relaxation:
the damping of eq. 13 acts like a mesh Laplacian scaled by gamma h^2, as does the elastic
stiffness (scaled by lambda + 2 mu), so gamma ~ (lambda + 2 mu) dt / h^2 overdamps every mode
at about the same rate while keeping the explicit elastic update stable.
"""
from __future__ import annotations

import numpy as np

from ..bodies.fem.mesh import box_grid, lame_parameters
from ..bodies.fem.system import FEMSystem


# --------------------------------------------------------------------------- formulas

def hanging_bar_displacement(rho: float, g: float, L: float, E: float) -> float:
    """Bottom displacement [m] of a bar of length L hanging under its own weight, top fixed: rho g L^2 / (2 E)."""
    return rho * g * L**2 / (2 * E)


def cantilever_tip_deflection(P: float, L: float, E: float, I: float, nu: float, A: float) -> float:
    """Tip deflection [m] of a clamped beam under a tip load P [N]: P L^3 / (3 E I) + P L / (kappa G A).

    The shear term (Timoshenko) matters for stocky beams; kappa = 10 (1 + nu) / (12 + 11 nu) for a
    rectangular section.
    """
    G = E / (2 * (1 + nu))
    kappa = 10 * (1 + nu) / (12 + 11 * nu)
    return P * L**3 / (3 * E * I) + P * L / (kappa * G * A)


def worm_displacement_per_cycle(eps: float, wavelength_m: float) -> float:
    """Rectilinear worm with perfect anchoring: D = Lambda (mean(lambda) - min(lambda)) = eps Lambda [m]."""
    return eps * wavelength_m


def symplectic_euler_dt_limit(omega_max: float) -> float:
    """Largest stable step [s] of symplectic Euler for an undamped oscillator of angular frequency omega_max."""
    return 2.0 / omega_max


def backward_euler_damping_factor(lam: float, h: float) -> float:
    """Per-step velocity factor of a pure damping mode (D phi = lam M phi) under the implicit damping step."""
    return 1.0 / (1.0 + lam * h)


def semi_implicit_oscillator_factor(c: float, h: float) -> float:
    """Per-step amplitude factor of an underdamped mode of the App. A step (elasticity explicit, damping
    implicit): the one-step map has determinant 1 / (1 + c h), so |eigenvalue| = 1 / sqrt(1 + c h)."""
    return 1.0 / np.sqrt(1.0 + c * h)


def single_node_tet(rho: float = 1.0, gamma: float = 40.0, E: float = 2.0e4, nu: float = 0.3) -> FEMSystem:
    """One unit corner tet (4 nodes, m) whose nodes 0-2 are fixed: only node 3 moves.

    The smallest system on which the per-step map of App. A can be linearised by hand."""
    nodes = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    s = FEMSystem(nodes, np.array([[0, 1, 2, 3]]), E=E, nu=nu, rho=rho, gamma=gamma)
    s.set_fixed(np.array([True, True, True, False]))
    return s


def one_step_map_eigenvalues(s: FEMSystem, node: int, h: float, eps: float = 1e-7) -> np.ndarray:
    """Eigenvalues (6,) complex of the linearised one-step map of one free node's (x, v), by central differences.

    ``s`` is reset to its rest positions ``s.X`` (m) with zero velocity before every probe; each probe
    perturbs one of the node's 3 position (m) or 3 velocity (m/s) components by +-eps and takes one step
    of h (s) without gravity.  |eigenvalue| is the per-step amplitude factor of that mode."""
    rest = s.X.copy()
    J = np.zeros((6, 6))
    for j in range(6):
        out = []
        for sign in (1.0, -1.0):
            s.x[:] = rest
            s.v[:] = 0.0
            if j < 3:
                s.x[node, j] += sign * eps
            else:
                s.v[node, j - 3] += sign * eps
            s.advance(1, dt=h, gravity=(0.0, 0.0, 0.0))
            out.append(np.concatenate([s.x[node] - rest[node], s.v[node]]))
        J[:, j] = (out[0] - out[1]) / (2 * eps)
    return np.linalg.eigvals(J)


# --------------------------------------------------------------------------- static solves

def relax(s: FEMSystem, dt: float, chunk: int, max_steps: int, probe, rtol: float = 1e-6, **kw) -> float:
    """Advance in chunks until the probed displacement changes by < rtol per chunk; return it."""
    prev = probe()
    cur = prev
    for _ in range(max_steps // chunk):
        r = s.advance(chunk, dt=dt, **kw)
        if not r.ok:
            raise RuntimeError(f"relaxation blew up ({r.status_name})")
        cur = probe()
        if abs(cur - prev) < rtol * abs(cur):
            return cur
        prev = cur
    raise RuntimeError(f"no static state after {max_steps} steps (last change {abs(cur - prev) / abs(cur):.2e})")


def hanging_bar(n_len: int, nu: float, E: float = 1e4, rho: float = 1.0, g: float = 9.81, L: float = 1.0,
                a: float = 0.2) -> tuple[FEMSystem, float]:
    """Bar along y, top face fixed, cells (n/4, n, n/4); strain rho g L / E ~ 1e-3.

    Returns the relaxed system and the bottom displacement / ``hanging_bar_displacement``.
    """
    nc = max(1, n_len // 4)
    nodes, tets = box_grid((a, L, a), (nc, n_len, nc))
    lam, mu = lame_parameters(E, nu)
    dt = 1e-3
    h = min(a / nc, L / n_len)
    s = FEMSystem(nodes, tets, E=E, nu=nu, rho=rho, gamma=4.0 * (lam + 2 * mu) * dt / h**2)
    s.set_fixed(np.isclose(nodes[:, 1], L))
    bottom = np.isclose(nodes[:, 1], 0.0)
    u = relax(s, dt, 100, 20000, lambda: -(s.x[bottom, 1] - nodes[bottom, 1]).mean(), gravity=(0.0, -g, 0.0))
    return s, u / hanging_bar_displacement(rho, g, L, E)


def cantilever_ratio(cells, E: float = 1e4, nu: float = 0.0, L: float = 0.5, H: float = 0.1, W: float = 0.1) -> float:
    """Tip deflection / beam theory of a beam along x clamped at x = 0, tip load -P y over the tip nodes.

    L/H = 5 is stocky, so the shear term (2.3 %) is included.  The load gives a tip deflection of
    1e-4 L, small enough for the corotational model to act linearly.  nu = 0 keeps the clamped face
    from adding Poisson constraint that beam theory does not have.
    """
    I = W * H**3 / 12
    A = W * H
    P = 3 * E * I * 1e-4 * L / L**3
    ref = cantilever_tip_deflection(P, L, E, I, nu, A)
    nodes, tets = box_grid((L, H, W), cells)
    lam, mu = lame_parameters(E, nu)
    dt = 1e-3
    h = min(L / cells[0], H / cells[1], W / cells[2])
    s = FEMSystem(nodes, tets, E=E, nu=nu, rho=30.0, gamma=2.0 * (lam + 2 * mu) * dt / h**2)
    s.set_fixed(np.isclose(nodes[:, 0], 0.0))
    tip = np.isclose(nodes[:, 0], L)
    f_ext = np.zeros_like(nodes)
    f_ext[tip, 1] = -P / tip.sum()
    u = relax(s, dt, 200, 20000, lambda: -(s.x[tip, 1] - nodes[tip, 1]).mean(), rtol=2e-5,
              gravity=(0.0, 0.0, 0.0), f_ext=f_ext)
    return u / ref


def rotation(axis, angle: float) -> np.ndarray:
    """(3, 3) rotation matrix about ``axis`` by ``angle`` [rad] (Rodrigues)."""
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    Kx = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1 - np.cos(angle)) * Kx @ Kx


def lattice_omega_max(body) -> float:
    """Largest angular eigenfrequency [rad/s] of a mass-spring lattice linearized at rest: sqrt(max eig(M^-1 K)).

    ``body``: a ``bodies.massspring.body.BodyMassSpring``; the stiffness matrix by central differences
    of the spring forces (damping off).
    """
    from ..bodies.massspring import kernels as K

    lat = body.lattice
    x0 = lat.rest_nodes.copy()
    n = x0.size
    h = 1e-7
    kmat = np.zeros((n, n))
    zero_v = np.zeros_like(x0)
    for col in range(n):
        xp, xm = x0.copy(), x0.copy()
        xp.flat[col] += h
        xm.flat[col] -= h
        fp, fm = np.zeros_like(x0), np.zeros_like(x0)
        K.spring_forces(xp, zero_v, lat.springs, body.stiffness, np.zeros(lat.n_springs), lat.rest_length, fp)
        K.spring_forces(xm, zero_v, lat.springs, body.stiffness, np.zeros(lat.n_springs), lat.rest_length, fm)
        kmat[:, col] = -(fp - fm).ravel() / (2 * h)
    minv = np.repeat(1.0 / body.mass, 3)
    return float(np.sqrt(np.max(np.linalg.eigvals(minv[:, None] * kmat).real)))
