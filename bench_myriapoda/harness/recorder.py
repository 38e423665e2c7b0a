"""Time series of observations gathered during a run, and their .npz export."""
from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..core.protocols import Observation
from ..core.series import Series  # noqa: F401  (re-exported: the recorder's product)


@dataclass
class Recorder:
    keep_nodes: bool = False
    samples: list[Observation] = field(default_factory=list)

    def series(self) -> Series:
        s = self.samples
        nodes = np.stack([o.nodes for o in s]) if self.keep_nodes and s and s[0].nodes is not None else None

        def stacked(name):
            vals = [getattr(o, name) for o in s]
            return np.stack(vals) if vals and all(v is not None for v in vals) else None
        return Series(t=np.array([o.t for o in s]), com=np.stack([o.com for o in s]),
                      head=np.stack([o.head for o in s]), tail=np.stack([o.tail for o in s]),
                      segment_centers=np.stack([o.segment_centers for o in s]),
                      energy=np.stack([o.energy for o in s]), nodes=nodes,
                      segment_positions=stacked("seg_pos"), segment_rotations=stacked("seg_rot"),
                      segment_contact=stacked("seg_contact"))

    def add(self, obs: Observation) -> None:
        # sense() may hand out views of the body's state (rigid bodies): keep copies
        for name in ("seg_pos", "seg_rot"):
            val = getattr(obs, name)
            if val is not None:
                setattr(obs, name, np.array(val, copy=True))
        self.samples.append(obs)


def compact_recording(series: Series, extra: dict | None = None) -> dict[str, np.ndarray]:
    """What a report needs of a run, small enough to send from a worker process.

    The observation series in float32 (millimetre resolution over kilometres is plenty for plots),
    and for legged creatures the leg-state timeline: ``leg_t`` (T_leg,) [s], ``leg_states``
    (T_leg, n_legs) int8 state codes, and ``brain`` (T_leg,) int8 brain-mode codes.  Leg tip
    positions and node positions are left out: they are what makes a recording large.
    """
    rec = {k: np.asarray(v, dtype=np.float32) for k, v in vars(series).items() if v is not None and k not in ("nodes", "segment_positions", "segment_rotations")}
    rec["t"] = np.asarray(series.t, dtype=np.float64)
    extra = extra or {}
    if "leg_timeline" in extra:
        leg_t, leg_states = extra["leg_timeline"][0], extra["leg_timeline"][1]
        rec["leg_t"] = np.asarray(leg_t, dtype=np.float64)
        rec["leg_states"] = np.asarray(leg_states, dtype=np.int8)
    if "brain_timeline" in extra:
        rec["brain"] = np.asarray(extra["brain_timeline"], dtype=np.int8)
    return rec


def series_from_recording(rec: dict[str, np.ndarray]) -> Series:
    """The :class:`Series` of a compact recording (float64, no nodes)."""
    return Series(**{k: np.asarray(rec[k], dtype=np.float64)
                     for k in ("t", "com", "head", "tail", "segment_centers", "energy")}, nodes=None)


def load_recording(path: Path) -> dict[str, np.ndarray]:
    """A recording written by :func:`save_recording` (or ``run --record``) as a dict of arrays."""
    with np.load(path, allow_pickle=False) as z:
        return {k: z[k] for k in z.files}


def save_recording(path: Path, recording: dict[str, np.ndarray]) -> None:
    """Write a :func:`compact_recording` atomically (a temporary file renamed into place)."""
    _atomic_savez(Path(path), recording)


def _atomic_savez(path: Path, arrays: dict[str, np.ndarray]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(suffix=".npz", dir=path.parent)
    os.close(fd)
    try:
        np.savez_compressed(tmp, **arrays)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def save_npz(path: Path, series: Series, case_dict: dict, extra: dict | None = None) -> None:
    """Write a recording atomically: a temporary file renamed into place, so no half-written file remains."""
    path = Path(path)
    arrays = {k: v for k, v in vars(series).items() if v is not None}
    arrays["case_json"] = np.array(json.dumps(case_dict))
    for k, v in (extra or {}).items():
        arrays[k] = np.asarray(v)
    _atomic_savez(path, arrays)
