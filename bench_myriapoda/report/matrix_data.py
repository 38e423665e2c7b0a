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
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from ..core.errors import InputError
from ..harness.matrix import MANIFEST
from ..harness.recorder import load_recording
from ..harness.store import StoreReadError, read_matrix_runs
from .inputs import check_manifest, check_regular_file, check_run_row, read_json_file

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
    # each case's world (``world``), built once however many plots draw the case (issue 30 item 1)
    worlds: dict = field(default_factory=dict, repr=False, compare=False)

    def recording(self, case_hash: str) -> dict[str, np.ndarray] | None:
        """The case's compact recording, or None when it has none."""
        path = self.directory / "series" / f"{case_hash}.npz"
        return load_recording(path) if path.is_file() else None

    def case(self, case_hash: str) -> dict:
        """The resolved configuration of a case (``Case.to_dict()``)."""
        return json.loads(self.df.loc[self.df.case_hash == case_hash, "case_json"].iloc[0])

    def world(self, case_hash: str):
        """The case's ``world.world.World`` (terrain, obstacles, food), built from its stored scenario and food
        sections on first use and kept: every plot of the case draws the one world."""
        if case_hash not in self.worlds:
            from ..core.schema import FoodConfig
            from ..world.world import world_from_sections
            from .series_plots import scenario_config, stored_section

            case = self.case(case_hash)
            self.worlds[case_hash] = world_from_sections(scenario_config(case["scenario"]),
                                                         stored_section(FoodConfig, case.get("food")))
        return self.worlds[case_hash]


RECORDING_KEYS = ("t", "com", "head", "tail", "segment_centers", "energy")


def load_matrix_dir(directory: Path | str, flag: str = "DIR") -> MatrixResults:
    """Read a matrix output directory; an ``InputError`` naming ``flag`` (or the bad file) if it is not one.

    Everything the report will read is checked here, before it writes anything: the store is a
    SQLite database with a ``runs`` table, ``matrix.json`` has the manifest's shape, every row's JSON
    parses, and every case's recording is a readable ``.npz`` with the series a report draws.
    """
    from ..harness.store import check_store

    d = Path(directory)
    store, manifest = d / "results.sqlite", d / MANIFEST
    if not d.is_dir():
        raise InputError(flag, None, f"{d}: no such directory; run `bench-myriapoda matrix FILE --out {d}` first")
    for f in (store, manifest):
        if not f.is_file():
            raise InputError(flag, None, f"{d} is not a matrix output directory: {f.name} is missing "
                                         f"(run `bench-myriapoda matrix FILE --out {d}`)")
    meta = _read_manifest(manifest)
    cases = meta["cases"]
    check_store(store, str(store), write=False, need=("runs",))
    try:
        rows = read_matrix_runs(store, meta["name"])
    except StoreReadError as exc:
        raise InputError(str(store), None, f"unreadable results store: {exc}") from None
    rows = rows.drop_duplicates("case_hash", keep="last")
    rows = rows[rows.case_hash.isin(cases)]
    table = []
    for _, r in rows.iterrows():
        info = cases[r.case_hash]
        case, metrics, timings, _ = check_run_row(r, str(store))
        dt, duration = float(case["dt"]), float(case["duration"])
        _check_recording(d, r.case_hash)
        axes = {k: v for k, v in info["axes"].items() if k in AXES}
        grid = {f"grid.{k}": v for k, v in info["axes"].items() if k not in AXES}
        row = {"case_hash": r.case_hash, "label": info["label"], **axes, **grid, "status": r.status,
               "message": r.message or "", "dt": dt, "duration": duration,
               "case_json": r.case_json, "labels_json": r.labels_json,
               **{f"metric.{k}": v for k, v in metrics.items()}, **timings}
        table.append(row)
    df = pd.DataFrame(table)
    if df.empty:
        df = pd.DataFrame(columns=["case_hash", "label", *AXES, "status", "message", "dt", "duration"])
    return MatrixResults(d, meta["name"], meta.get("description", ""), list(meta.get("grid_keys", [])), df,
                         list(meta.get("unsupported", [])))


def _read_manifest(manifest: Path) -> dict:
    """``matrix.json`` with the shape :func:`~..harness.matrix.write_matrix_manifest` writes, or InputError
    (``report.inputs``: depth and size limits, the axes' and grid keys' types)."""
    return check_manifest(read_json_file(manifest, "matrix manifest"), str(manifest))


def _check_recording(d: Path, case_hash: str) -> None:
    """A case's recording, if there is one, loads and has the series the report draws."""
    path = d / "series" / f"{case_hash}.npz"
    if not check_regular_file(path):  # a FIFO there is refused unopened: reading it would block forever
        return
    try:
        rec = load_recording(path)
        missing = [k for k in RECORDING_KEYS if k not in rec]
        if missing:
            raise ValueError(f"no {', '.join(missing)}")
        n = len(rec["t"])
        if any(len(rec[k]) != n for k in RECORDING_KEYS) or ("leg_t" in rec) != ("leg_states" in rec):
            raise ValueError("series of different lengths")
        if "leg_t" in rec and len(rec["leg_t"]) != len(rec["leg_states"]):
            raise ValueError("leg_t and leg_states of different lengths")
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, TypeError) as exc:
        raise InputError(str(path), None, f"unreadable recording ({type(exc).__name__}: {exc}); delete it or "
                                          "rerun the case") from None
