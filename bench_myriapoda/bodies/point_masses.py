"""Momentum probes of a body whose state is point masses (``core.specs.BodyProbes``): the lattice, the FEM mesh's
nodes, a plugin's point chain.  ``validation``'s free-fall check reads a body's momentum through these, not
through the body's attributes (issue 42)."""
from __future__ import annotations

from typing import Any, Callable

import numpy as np


def point_mass_momentum_probes(mass_of: Callable[[Any], np.ndarray]) -> dict[str, Callable]:
    """``linear_momentum``, ``total_mass`` and ``add_velocity`` of a body with velocities ``body.v`` (n, 3) [m/s]
    and point masses ``mass_of(body)`` (n,) [kg]: keyword arguments of ``BodyProbes``."""

    def linear_momentum(body) -> np.ndarray:
        return (mass_of(body)[:, None] * body.v).sum(axis=0)

    def total_mass(body) -> float:
        return float(mass_of(body).sum())

    def add_velocity(body, dv) -> None:
        body.v[:] += np.asarray(dv, dtype=float)

    return {"linear_momentum": linear_momentum, "total_mass": total_mass, "add_velocity": add_velocity}
