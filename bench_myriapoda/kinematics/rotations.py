"""Small 3x3 rotation helpers for numba kernels (scalars in, tuples out: no allocation).

A rotation ``M`` (3, 3) maps body to world coordinates: p_world = M p_body.
"""
from __future__ import annotations

from numba import njit


@njit(cache=True)
def matvec(M, x, y, z):
    """M (x, y, z): a body vector in world coordinates."""
    return (M[0, 0] * x + M[0, 1] * y + M[0, 2] * z,
            M[1, 0] * x + M[1, 1] * y + M[1, 2] * z,
            M[2, 0] * x + M[2, 1] * y + M[2, 2] * z)


@njit(cache=True)
def mat_t_vec(M, x, y, z):
    """M^T (x, y, z): a world vector in body coordinates."""
    return (M[0, 0] * x + M[1, 0] * y + M[2, 0] * z,
            M[0, 1] * x + M[1, 1] * y + M[2, 1] * z,
            M[0, 2] * x + M[1, 2] * y + M[2, 2] * z)
