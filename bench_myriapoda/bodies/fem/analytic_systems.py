"""The FEM method's own small systems that validation's analytic checks measure (``core.specs.BodyProbes``).

Each builds a ``FEMSystem`` on a box mesh, drives it and returns the measured quantity in SI units; the
closed-form answers it is compared with live in ``validation.references`` (a reference shares no code with
what it checks).  Moved here from ``validation/references.py`` so that validation names no body (issue 42).

Static states are reached by a damped relaxation run of the real time stepper.  The static answer depends
on neither the mass nor the damping, so both are chosen for a fast relaxation: the damping of eq. 13 acts
like a mesh Laplacian scaled by gamma h^2, as does the elastic stiffness (scaled by lambda + 2 mu), so
gamma ~ (lambda + 2 mu) dt / h^2 overdamps every mode at about the same rate while keeping the explicit
elastic update stable.
"""
from __future__ import annotations

import numpy as np

from .mesh import box_grid, lame_parameters
from .system import FEMSystem


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


def one_node_step_eigenvalues(rho: float, gamma: float, h: float) -> np.ndarray:
    """``one_step_map_eigenvalues`` of ``single_node_tet(rho, gamma)``'s free node (``BodyProbes``)."""
    return one_step_map_eigenvalues(single_node_tet(rho=rho, gamma=gamma), node=3, h=h)


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


def bar_under_own_weight(n_len: int, nu: float, E: float = 1e4, rho: float = 1.0, g: float = 9.81, L: float = 1.0,
                         a: float = 0.2) -> tuple[FEMSystem, float]:
    """Bar along y, top face fixed, cells (n/4, n, n/4); strain rho g L / E ~ 1e-3.

    Returns the relaxed system and the bottom face's mean downward displacement [m].
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
    return s, u


def cantilever_tip(cells, P: float, E: float = 1e4, nu: float = 0.0, L: float = 0.5, H: float = 0.1,
                   W: float = 0.1) -> float:
    """Tip deflection [m] of a beam along x clamped at x = 0 under a tip load -P y [N] over the tip nodes."""
    nodes, tets = box_grid((L, H, W), cells)
    lam, mu = lame_parameters(E, nu)
    dt = 1e-3
    h = min(L / cells[0], H / cells[1], W / cells[2])
    s = FEMSystem(nodes, tets, E=E, nu=nu, rho=30.0, gamma=2.0 * (lam + 2 * mu) * dt / h**2)
    s.set_fixed(np.isclose(nodes[:, 0], 0.0))
    tip = np.isclose(nodes[:, 0], L)
    f_ext = np.zeros_like(nodes)
    f_ext[tip, 1] = -P / tip.sum()
    return relax(s, dt, 200, 20000, lambda: -(s.x[tip, 1] - nodes[tip, 1]).mean(), rtol=2e-5,
                 gravity=(0.0, 0.0, 0.0), f_ext=f_ext)


def rigid_motion_residual(build, angles, draw) -> float:
    """Largest |elastic force| / (mu V^(2/3)) of box meshes (5 and 6 tets per cell) moved rigidly by
    ``draw(angle) -> (R (3, 3), t (3,))`` for each of ``angles`` [rad]: zero for the fixed-corotational element
    (Newton for small angles, the SVD fallback for large ones).  ``build`` (a built body) is not needed: the
    element is checked on its own meshes."""
    worst = 0.0
    for tpc in (5, 6):
        nodes, tets = box_grid((1.0, 0.6, 0.4), (3, 2, 2), tets_per_cell=tpc)
        s = FEMSystem(nodes, tets)
        scale = s.mu.max() * s.vol.max() ** (2 / 3)
        for angle in angles:
            R, t = draw(angle)
            s.x[:] = nodes @ R.T + t
            worst = max(worst, np.abs(s.elastic_forces()).max() / scale)
    return worst


def pure_damping_modes(gamma: float, h: float) -> list[tuple[float, np.ndarray]]:
    """For three generalized eigenvectors D phi = lam M phi (the softest, a middle one, the stiffest) of a
    2-cell box clamped at x = 0: (lam [1/s], the free nodes' z-velocity after one step of h over before it)."""
    from scipy.linalg import eigh

    nodes, tets = box_grid((1.0, 0.5, 0.5), (2, 1, 1))
    s = FEMSystem(nodes, tets, gamma=gamma)
    mask = np.isclose(nodes[:, 0], 0.0)
    s.set_fixed(mask)
    free = ~mask
    lam_d, phi = eigh(s.D.toarray()[np.ix_(free, free)], np.diag(s.mass[free]))
    out = []
    for k in (0, len(lam_d) // 2, len(lam_d) - 1):
        s.x[:] = nodes
        s.v[:] = 0.0
        s.v[free, 2] = phi[:, k]
        s.advance(1, dt=h, gravity=(0.0, 0.0, 0.0))
        out.append((float(lam_d[k]), s.v[free, 2] / phi[:, k]))
    return out
