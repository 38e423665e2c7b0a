"""The tetrahedra's quality over a run's observation samples: the ``min_J``, inverted-element and strain
metrics of every body with FEM elements (the FEM worm, the FEM centipede's mesh, the hybrid's links)."""
from __future__ import annotations

import math

import numpy as np

from . import kernels as FK


class ElementQuality:
    """``current`` evaluates the tets of a state; ``sample`` folds it into the extrema since ``reset``:
    min_J (smallest volume ratio det F), inverted_max (most tets with J <= 0 in one sample), inverted_last
    (those of the last sample), max_strain (largest principal strain max |sigma_i - 1|).

    J (n_tets,) and sigma (n_tets, 3) hold the last evaluation (``fem.kernels.tet_invariants``).
    """

    def __init__(self, n_tets: int):
        self.J = np.zeros(n_tets)
        self.sigma = np.zeros((n_tets, 3))
        self.reset()

    def reset(self) -> None:
        self.min_J, self.inverted_max, self.inverted_last, self.max_strain = math.inf, 0, 0, 0.0

    def current(self, x: np.ndarray, tets: np.ndarray, Dm_inv: np.ndarray) -> tuple[float, int, float]:
        """(min J, count of tets with J <= 0, max principal strain) of nodes x (n_nodes, 3) [m], one SVD per
        tet, F from the rest shape's inverse edge matrices Dm_inv (n_tets, 3, 3) [1/m]."""
        FK.tet_invariants(x, tets, Dm_inv, self.J, self.sigma)
        return (float(self.J.min()), int(np.count_nonzero(self.J <= 0.0)),
                float(np.abs(self.sigma - 1.0).max()))

    def sample(self, x: np.ndarray, tets: np.ndarray, Dm_inv: np.ndarray) -> None:
        """Fold ``current`` of this state into the extrema."""
        min_J, inverted, strain = self.current(x, tets, Dm_inv)
        self.min_J = min(self.min_J, min_J)
        self.inverted_last = inverted
        self.inverted_max = max(self.inverted_max, inverted)
        self.max_strain = max(self.max_strain, strain)
