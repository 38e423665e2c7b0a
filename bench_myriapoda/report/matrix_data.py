"""The results of one matrix output directory, as the report reads them.

A directory written by ``bench-myriapoda matrix FILE --out DIR`` holds:

* ``results.sqlite`` -- one ``runs`` row per case (status, metrics, timings,
  resolved configuration); the newest row of each case hash counts;
* ``matrix.json`` -- the matrix name, its grid keys, and each case's axis
  values (creature, body, gait, scenario, seed and grid point);
* ``series/CASE_HASH.npz`` -- each case's compact recording (observation
  series and leg-state timeline, ``harness.recorder.compact_recording``).

:func:`load_matrix_dir` joins them into one DataFrame, one row per case, with
the axes as columns (a grid key K as ``grid.K``, NaN for cases of a block
without it), the resolved ``dt`` and ``duration``, ``metric.NAME`` columns and
timings.  Recordings are read on demand with :meth:`MatrixResults.recording`.
"""
from __future__ import annotations

import json
import sqlite3
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ..core.errors import InputError
from ..harness.matrix import MANIFEST
from ..harness.recorder import load_recording

AXES = ("creature", "body", "gait", "scenario", "seed")


@dataclass
class MatrixResults:
    """One matrix directory's cases (``df``) and where their recordings are."""

    directory: Path
    name: str
    description: str
    grid_keys: list[str]
    df: pd.DataFrame  # one row per case: axes, grid keys, status, message, dt, metric.*, steps_per_s, ...
    unsupported: list[str]

    def recording(self, case_hash: str) -> dict[str, np.ndarray] | None:
        """The case's compact recording, or None when it has none."""
        path = self.directory / "series" / f"{case_hash}.npz"
        return load_recording(path) if path.is_file() else None

    def case(self, case_hash: str) -> dict:
        """The resolved configuration of a case (``Case.to_dict()``)."""
        return json.loads(self.df.loc[self.df.case_hash == case_hash, "case_json"].iloc[0])


def load_matrix_dir(directory: Path | str, flag: str = "DIR") -> MatrixResults:
    """Read a matrix output directory; an ``InputError`` naming ``flag`` if it is not one."""
    d = Path(directory)
    store, manifest = d / "results.sqlite", d / MANIFEST
    if not d.is_dir():
        raise InputError(flag, None, f"{d}: no such directory; run `bench-myriapoda matrix FILE --out {d}` first")
    for f in (store, manifest):
        if not f.is_file():
            raise InputError(flag, None, f"{d} is not a matrix output directory: {f.name} is missing "
                                         f"(run `bench-myriapoda matrix FILE --out {d}`)")
    try:
        meta = json.loads(manifest.read_text())
        cases = meta["cases"]
    except (ValueError, KeyError) as exc:
        raise InputError(str(manifest), None, f"unreadable matrix manifest: {exc}") from None
    con = sqlite3.connect(store)
    try:
        rows = pd.read_sql("SELECT * FROM runs WHERE command = 'matrix' AND matrix = ? ORDER BY id", con,
                           params=(meta["name"],))
    finally:
        con.close()
    rows = rows.drop_duplicates("case_hash", keep="last")
    rows = rows[rows.case_hash.isin(cases)]
    table = []
    for _, r in rows.iterrows():
        info = cases[r.case_hash]
        case = json.loads(r.case_json)
        metrics = json.loads(r.metrics_json)
        timings = json.loads(r.timings_json)
        axes = {k: v for k, v in info["axes"].items() if k in AXES}
        grid = {f"grid.{k}": v for k, v in info["axes"].items() if k not in AXES}
        row = {"case_hash": r.case_hash, "label": info["label"], **axes, **grid, "status": r.status,
               "message": r.message or "", "dt": case["dt"], "duration": case["duration"],
               "case_json": r.case_json, "labels_json": r.labels_json,
               **{f"metric.{k}": (np.nan if v is None else v) for k, v in metrics.items()},
               **{k: (np.nan if timings.get(k) is None else timings.get(k))
                  for k in ("steps_per_s", "realtime_factor", "compile_s", "wall_s")}}
        table.append(row)
    df = pd.DataFrame(table)
    if df.empty:
        df = pd.DataFrame(columns=["case_hash", "label", *AXES, "status", "message", "dt", "duration"])
    return MatrixResults(d, meta["name"], meta.get("description", ""), list(meta.get("grid_keys", [])), df,
                         list(meta.get("unsupported", [])))
