"""Time series of a run's observation samples, as the runner records them and metrics read them."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class Series:
    """Stacked observations: t (T,) [s]; com, head, tail (T, 3) [m];
    segment_centers (T, n_c, 3) [m]; energy (T, 3) [J]; nodes (T, n_nodes, 3) or None;
    segment_positions (T, n_seg, 3) [m], segment_rotations (T, n_seg, 3, 3) (segment -> world;
    columns: the body axis toward the head, dorsal, right) and segment_contact (T, n_seg) bool
    (a segment touches the ground), or None when the body did not report them."""

    t: np.ndarray
    com: np.ndarray
    head: np.ndarray
    tail: np.ndarray
    segment_centers: np.ndarray
    energy: np.ndarray
    nodes: np.ndarray | None
    segment_positions: np.ndarray | None = None
    segment_rotations: np.ndarray | None = None
    segment_contact: np.ndarray | None = None
