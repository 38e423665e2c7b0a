"""The lattice's own quantities that validation's analytic checks measure (``core.specs.BodyProbes``).

Moved here from ``validation/`` so that validation names no body and reads none of its internals
(issue 42); the closed-form answers stay in ``validation.references``.
"""
from __future__ import annotations

import numpy as np

from . import kernels as K


def _spring_forces(body, x: np.ndarray) -> np.ndarray:
    """The lattice's spring forces [N] (n_nodes, 3) at positions x [m], at rest velocity, damping off."""
    lat = body.lattice
    f = np.zeros_like(x)
    K.spring_forces(x, np.zeros_like(x), lat.springs, body.stiffness, np.zeros(lat.n_springs), lat.rest_length, f)
    return f


def rigid_motion_residual(build, angles, draw) -> float:
    """Largest |spring force| / (k L) of a built lattice (``build()``) with its rest nodes moved rigidly by
    ``draw(angle) -> (R (3, 3), t (3,))`` for each of ``angles`` [rad]: zero for springs of rest length L."""
    body = build()
    lat = body.lattice
    x0 = lat.rest_nodes
    scale = float(np.max(body.stiffness)) * float(np.max(lat.rest_length))
    worst = 0.0
    for angle in angles:
        R, t = draw(angle)
        worst = max(worst, np.abs(_spring_forces(body, x0 @ R.T + t)).max() / scale)
    return worst


def omega_max(body) -> float:
    """Largest angular eigenfrequency [rad/s] of a built lattice linearized at rest: sqrt(max eig(M^-1 K)), the
    stiffness matrix by central differences of the spring forces (damping off)."""
    lat = body.lattice
    x0 = lat.rest_nodes.copy()
    n = x0.size
    h = 1e-7
    kmat = np.zeros((n, n))
    for col in range(n):
        xp, xm = x0.copy(), x0.copy()
        xp.flat[col] += h
        xm.flat[col] -= h
        kmat[:, col] = -(_spring_forces(body, xp) - _spring_forces(body, xm)).ravel() / (2 * h)
    minv = np.repeat(1.0 / body.mass, 3)
    return float(np.sqrt(np.max(np.linalg.eigvals(minv[:, None] * kmat).real)))
