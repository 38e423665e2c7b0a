"""Time series of observations gathered during a run, and their .npz export."""
from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..bodies.observation import Observation


@dataclass
class Series:
    """Stacked observations: t (T,) [s]; com, head, tail (T, 3) [m];
    segment_centers (T, n_seg, 3) [m]; energy (T, 3) [J]; nodes (T, n_nodes, 3) or None."""

    t: np.ndarray
    com: np.ndarray
    head: np.ndarray
    tail: np.ndarray
    segment_centers: np.ndarray
    energy: np.ndarray
    nodes: np.ndarray | None


@dataclass
class Recorder:
    keep_nodes: bool = False
    samples: list[Observation] = field(default_factory=list)

    def add(self, obs: Observation) -> None:
        self.samples.append(obs)

    def series(self) -> Series:
        s = self.samples
        nodes = np.stack([o.nodes for o in s]) if self.keep_nodes and s and s[0].nodes is not None else None
        return Series(t=np.array([o.t for o in s]), com=np.stack([o.com for o in s]),
                      head=np.stack([o.head for o in s]), tail=np.stack([o.tail for o in s]),
                      segment_centers=np.stack([o.segment_centers for o in s]),
                      energy=np.stack([o.energy for o in s]), nodes=nodes)


def save_npz(path: Path, series: Series, case_dict: dict, extra: dict | None = None) -> None:
    """Write a recording atomically: a temporary file renamed into place, so no half-written file remains."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    arrays = {k: v for k, v in vars(series).items() if v is not None}
    arrays["case_json"] = np.array(json.dumps(case_dict))
    for k, v in (extra or {}).items():
        arrays[k] = np.asarray(v)
    fd, tmp = tempfile.mkstemp(suffix=".npz", dir=path.parent)
    os.close(fd)
    try:
        np.savez_compressed(tmp, **arrays)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
