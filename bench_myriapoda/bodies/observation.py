"""What every body backend reports at a sample time, whatever its internals."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class Observation:
    """A snapshot of a body.

    t [s]; segment_centers: (n_seg, 3) [m], segment 0 the head; com: (3,) [m]
    centre of mass; head, tail: (3,) [m] centres of the front and back end
    faces; energy: (3,) [J] kinetic, elastic, gravitational (from y = 0);
    nodes: (n_nodes, 3) [m] or None when not requested.
    """

    t: float
    segment_centers: np.ndarray
    com: np.ndarray
    head: np.ndarray
    tail: np.ndarray
    energy: np.ndarray
    nodes: np.ndarray | None = None
