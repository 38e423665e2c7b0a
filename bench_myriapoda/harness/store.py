"""The SQLite results store.

One row per run in ``runs`` (resolved configuration and metrics as JSON, plus
the most-queried fields as columns) and one row per metric in ``metrics``,
written in a single transaction so an interrupted run leaves no partial row.
``regress_history`` holds one row per suite entry of each ``bench-myriapoda regress``
run (``harness/regress.py``), again one transaction per run; ``validation`` one row per check
and body of each ``bench-myriapoda validate`` run (``validation/``), one transaction per run.
Both tables read directly with ``pandas.read_sql``::

    pd.read_sql("SELECT * FROM runs", sqlite3.connect("reports/results.sqlite"))
"""
from __future__ import annotations

import json
import math
import os
import sqlite3
import time
from pathlib import Path
from typing import Any

from ..core.errors import InputError
from .machine import git_commit, machine_fingerprint

DEFAULT_STORE = Path("reports") / "results.sqlite"

SCHEMA = """
CREATE TABLE IF NOT EXISTS runs (
    id INTEGER PRIMARY KEY AUTOINCREMENT,
    case_hash TEXT NOT NULL,
    command TEXT NOT NULL DEFAULT 'run',
    creature TEXT, body TEXT, gait TEXT, scenario TEXT,
    status TEXT NOT NULL,
    message TEXT,
    case_json TEXT NOT NULL,
    metrics_json TEXT NOT NULL,
    labels_json TEXT NOT NULL DEFAULT '{}',
    timings_json TEXT NOT NULL,
    steps INTEGER, steps_per_s REAL, realtime_factor REAL, compile_s REAL, wall_s REAL,
    git_commit TEXT,
    git_dirty INTEGER,
    machine_json TEXT NOT NULL,
    cpu_model TEXT, cpu_count INTEGER, python_version TEXT, numpy_version TEXT, numba_version TEXT,
    timestamp TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS runs_case_hash ON runs(case_hash);
CREATE TABLE IF NOT EXISTS metrics (
    run_id INTEGER NOT NULL REFERENCES runs(id),
    name TEXT NOT NULL,
    value REAL,
    PRIMARY KEY (run_id, name)
);
CREATE TABLE IF NOT EXISTS regress_history (
    run_id INTEGER NOT NULL,              -- one regress run: all its entries share it (1, 2, ... per store)
    entry TEXT NOT NULL,                  -- suite entry name (harness/throughput_suite.py)
    git_commit TEXT,
    git_dirty INTEGER,
    machine_json TEXT NOT NULL,           -- harness/machine.py fingerprint, JSON with sorted keys
    timestamp TEXT NOT NULL,
    steps_per_rep INTEGER NOT NULL,       -- steps of one timed repetition
    repeats INTEGER NOT NULL,
    steps_per_s REAL NOT NULL,            -- median over the repetitions, per CPU second of the timing thread
    spread REAL NOT NULL,                 -- MAD / median of the repetitions' steps/s
    reference_ops_per_s REAL NOT NULL,    -- median of the reference kernel timed before each repetition
    reference_spread REAL NOT NULL,       -- MAD / median of those
    normalized REAL NOT NULL,             -- steps_per_s / reference_ops_per_s
    samples_json TEXT NOT NULL DEFAULT '{}',  -- every repetition: steps/s and reference ops/s (CPU and wall)
    PRIMARY KEY (run_id, entry)
);
CREATE INDEX IF NOT EXISTS regress_history_commit ON regress_history(git_commit);
CREATE TABLE IF NOT EXISTS validation (
    run_id INTEGER NOT NULL,              -- one `validate` run: all its rows share it (1, 2, ... per store)
    check_name TEXT NOT NULL,             -- validation/registry.py name, e.g. analytic.hanging-bar
    family TEXT NOT NULL,
    body TEXT NOT NULL,                   -- a body model, or 'all' for a cross-body row
    quantity TEXT NOT NULL,
    measured_json TEXT,                   -- number or string, JSON
    reference_json TEXT,
    source TEXT NOT NULL,
    tolerance TEXT NOT NULL,
    verdict TEXT NOT NULL,                -- PASS, FAIL, NOT APPLICABLE, INFO
    detail TEXT,
    unit TEXT,
    seconds REAL,                         -- wall time of the check on this body
    figures_json TEXT NOT NULL DEFAULT '{}',
    quick INTEGER NOT NULL,               -- 1 for `validate --quick`
    out_dir TEXT,                         -- where the run wrote validation.json and work-precision PNGs
    git_commit TEXT,
    git_dirty INTEGER,
    machine_json TEXT NOT NULL,
    timestamp TEXT NOT NULL,
    PRIMARY KEY (run_id, check_name, body)
);
"""


def _finite(v: Any) -> Any:
    return None if isinstance(v, float) and not math.isfinite(v) else v


def connect(path: Path | str = DEFAULT_STORE) -> sqlite3.Connection:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    con = sqlite3.connect(path, timeout=60)
    con.executescript(SCHEMA)
    _add_missing_columns(con)
    return con


# The columns a store's tables must have (a store from an older release gains LATER_COLUMNS on open).
REQUIRED_COLUMNS = {
    "runs": {"id", "case_hash", "creature", "body", "gait", "scenario", "status", "message", "case_json",
             "metrics_json", "timings_json", "steps", "steps_per_s", "realtime_factor", "compile_s", "wall_s",
             "git_commit", "git_dirty", "machine_json", "timestamp"},
    "metrics": {"run_id", "name", "value"},
    "regress_history": {"run_id", "entry", "machine_json", "timestamp", "steps_per_rep", "repeats", "steps_per_s",
                        "spread", "reference_ops_per_s", "reference_spread", "normalized"},
}
SQLITE_MAGIC = b"SQLite format 3\x00"


def check_store(path: Path | str, flag: str, *, write: bool = True, need: tuple[str, ...] = ()) -> Path:
    """Check a results store before anything runs; an ``InputError`` naming ``flag`` if it is unusable.

    The path must be a SQLite database whose tables (those present) have this schema's columns, or
    not exist yet; with ``write`` it (or, if it does not exist, its nearest existing folder) must be
    writable.  ``need`` names tables that must exist (a report reading ``runs``).  Nothing is
    created or changed here: the store is opened read-only.
    """
    path = Path(path)
    if str(path) in ("", "."):
        raise InputError(flag, None, "empty path; give the path of a SQLite results file")
    if path.exists() and not path.is_file():
        raise InputError(flag, None, f"{path} exists and is not a file; give the path of a SQLite results file")
    if not path.exists():
        if need:
            raise InputError(flag, None, f"{path}: no such results store")
        if write:
            check_writable_file(path, flag)
        return path
    try:
        with open(path, "rb") as fh:
            head = fh.read(len(SQLITE_MAGIC))
    except OSError as exc:
        raise InputError(flag, None, f"{path}: cannot read ({exc.strerror})") from None
    if head and head != SQLITE_MAGIC:
        raise InputError(flag, None, f"{path} is not a SQLite database (a results store written by bench-myriapoda)")
    if write and (not os.access(path, os.W_OK) or _read_only_mount(path)):
        raise InputError(flag, None, f"{path} is not writable")
    if not head:  # an empty file: SQLite makes it a database on first write
        if need:
            raise InputError(flag, None, f"{path} is an empty file, not a results store")
        return path
    try:
        con = sqlite3.connect(path.resolve().as_uri() + "?mode=ro", uri=True, timeout=60)
        try:
            tables = {n for (n,) in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
            for table, cols in REQUIRED_COLUMNS.items():
                if table not in tables:
                    continue
                have = {row[1] for row in con.execute(f"PRAGMA table_info({table})")}
                missing = sorted(cols - have)
                if missing:
                    raise InputError(flag, None, f"{path}: table {table} lacks columns {', '.join(missing)}; "
                                                 "not a results store of this schema")
        finally:
            con.close()
    except sqlite3.DatabaseError as exc:
        raise InputError(flag, None, f"{path} is not a usable SQLite results store ({exc})") from None
    for table in need:
        if table not in tables:
            raise InputError(flag, None, f"{path} has no {table} table; not a results store of this schema")
    return path


def check_writable_file(path: Path | str, flag: str) -> Path:
    """An output file path that can be created or replaced: not a directory, in a writable folder.

    Checks without writing anything: the nearest existing ancestor folder must be writable (the
    missing folders between it and the file are created later, when the file is written).
    """
    path = Path(path)
    if str(path) in ("", "."):
        raise InputError(flag, None, "empty path; give a file name")
    if path.is_dir():
        raise InputError(flag, None, f"{path} is a directory; give a file name")
    if path.exists() and (not os.access(path, os.W_OK) or _read_only_mount(path)):
        raise InputError(flag, None, f"{path} is not writable")
    check_writable_dir(path.parent, flag, what=f"the folder of {path}")
    return path


def check_writable_dir(path: Path | str, flag: str, what: str | None = None) -> Path:
    """A directory that exists and is writable, or can be created (its nearest existing ancestor is)."""
    path = Path(path)
    what = what or str(path)
    probe = path
    while not probe.exists():
        if probe.parent == probe:
            break
        probe = probe.parent
    if probe.exists() and not probe.is_dir():
        raise InputError(flag, None, f"{what}: {probe} exists and is not a directory")
    if not os.access(probe, os.W_OK | os.X_OK) or _read_only_mount(probe):
        raise InputError(flag, None, f"{what}: {probe} is not writable")
    return path


def _read_only_mount(path: Path) -> bool:
    """True on a read-only file system (where os.access still says yes to root)."""
    try:
        return bool(os.statvfs(path).f_flag & os.ST_RDONLY)
    except OSError:
        return False


# Columns added after the first release of the store; an older database gets them on open.
LATER_COLUMNS = (("command", "TEXT NOT NULL DEFAULT 'run'"), ("labels_json", "TEXT NOT NULL DEFAULT '{}'"),
                 ("matrix", "TEXT DEFAULT NULL"))  # matrix: the matrix name of a ``matrix`` row, else NULL


def _add_missing_columns(con: sqlite3.Connection) -> None:
    have = {row[1] for row in con.execute("PRAGMA table_info(runs)")}
    for name, decl in LATER_COLUMNS:
        if name not in have:
            try:
                with con:
                    con.execute(f"ALTER TABLE runs ADD COLUMN {name} {decl}")
            except sqlite3.OperationalError as exc:  # another process added it first
                if "duplicate column" not in str(exc):
                    raise


def record_run(path: Path | str, result, command: str = "run", matrix: str | None = None) -> int:
    """Insert a ``RunResult`` in one transaction; return its run id.

    ``command`` says what produced the row: ``run``, ``quick``, ``stable-dt``, ``matrix``;
    ``matrix`` is the matrix name of a ``matrix`` row.
    """
    case = result.case.to_dict()
    mach = machine_fingerprint()
    commit, dirty = git_commit()
    metrics = {k: _finite(v) for k, v in result.metrics.items()}
    timings = {k: _finite(v) for k, v in result.timings.items()}
    con = connect(path)
    try:
        with con:  # one transaction: both tables or nothing
            cur = con.execute(
                "INSERT INTO runs (case_hash, command, creature, body, gait, scenario, status, message, case_json, metrics_json,"
                " timings_json, labels_json, steps, steps_per_s, realtime_factor, compile_s, wall_s, git_commit, git_dirty,"
                " machine_json, cpu_model, cpu_count, python_version, numpy_version, numba_version, timestamp, matrix)"
                " VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)",
                (result.case.case_hash(), command, case["creature"]["name"], case["body"]["name"], case["gait"]["name"],
                 case["scenario"]["name"], result.status, result.message, json.dumps(case, sort_keys=True),
                 json.dumps(metrics, sort_keys=True), json.dumps(timings, sort_keys=True),
                 json.dumps(result.extra.get("labels", {}), sort_keys=True), timings.get("steps"),
                 timings.get("steps_per_s"), timings.get("realtime_factor"), timings.get("compile_s"),
                 timings.get("wall_s"), commit, None if dirty is None else int(dirty), json.dumps(mach, sort_keys=True),
                 mach["cpu_model"], mach["cpu_count"], mach["python"], mach["numpy"], mach["numba"],
                 time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), matrix))
            run_id = cur.lastrowid
            con.executemany("INSERT INTO metrics (run_id, name, value) VALUES (?,?,?)",
                            [(run_id, k, v if isinstance(v, (int, float)) else None) for k, v in metrics.items()])
        return run_id
    finally:
        con.close()


def record_validation_run(path: Path | str, rows: list[dict[str, Any]], quick: bool, out_dir: str | None) -> int:
    """Insert the rows of one ``validate`` run (``validation.core.Row.to_dict()``) into ``validation`` in one
    transaction; return its run id (1, 2, ... per store)."""
    mach = json.dumps(machine_fingerprint(), sort_keys=True)
    commit, dirty = git_commit()
    stamp = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    return _insert_numbered_run(
        path, "validation",
        "INSERT INTO validation (run_id, check_name, family, body, quantity, measured_json, reference_json,"
        " source, tolerance, verdict, detail, unit, seconds, figures_json, quick, out_dir, git_commit,"
        " git_dirty, machine_json, timestamp) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)",
        lambda run_id: [(run_id, r["check"], r["family"], r["body"], r["quantity"], json.dumps(_finite(r["measured"])),
                         json.dumps(_finite(r["reference"])), r["source"], r["tolerance"], r["verdict"], r["detail"],
                         r["unit"], _finite(r["seconds"]), json.dumps(r["figures"], sort_keys=True), int(quick),
                         out_dir, commit, None if dirty is None else int(dirty), mach, stamp) for r in rows])


def _insert_numbered_run(path: Path | str, table: str, sql: str, make_rows) -> int:
    """Insert one run's rows into ``table`` under the next run id (1, 2, ... per store), in one transaction.

    ``make_rows(run_id)`` gives the parameter tuples of ``sql``.  BEGIN IMMEDIATE takes the write lock before
    the id is read, so two concurrent writers never share a run id; any failure rolls the whole run back."""
    con = connect(path)
    try:
        con.execute("BEGIN IMMEDIATE")
        try:
            run_id = con.execute(f"SELECT COALESCE(MAX(run_id), 0) + 1 FROM {table}").fetchone()[0]
            con.executemany(sql, make_rows(run_id))
            con.commit()
        except BaseException:
            con.rollback()
            raise
        return int(run_id)
    finally:
        con.close()


REGRESS_FIELDS = ("entry", "steps_per_rep", "repeats", "steps_per_s", "spread", "reference_ops_per_s",
                  "reference_spread", "normalized", "samples_json")


def record_regress_run(path: Path | str, rows: list[dict[str, Any]]) -> int:
    """Insert the entries of one ``regress`` run into ``regress_history`` in one transaction; return its run id.

    Each row holds ``REGRESS_FIELDS``; the commit, machine fingerprint and timestamp are added here.
    Run ids count up from 1 in each store.
    """
    mach = json.dumps(machine_fingerprint(), sort_keys=True)
    commit, dirty = git_commit()
    stamp = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    return _insert_numbered_run(
        path, "regress_history",
        "INSERT INTO regress_history (run_id, git_commit, git_dirty, machine_json, timestamp, "
        + ", ".join(REGRESS_FIELDS) + ") VALUES (?,?,?,?,?," + ",".join("?" * len(REGRESS_FIELDS)) + ")",
        lambda run_id: [(run_id, commit, None if dirty is None else int(dirty), mach, stamp,
                         *(_finite(r[k]) for k in REGRESS_FIELDS)) for r in rows])


# --------------------------------------------------------------------------- reading
# Every query of the store is written in this module; the matrix executor, the regression history, the report
# and the API read through these functions.  The readers open the file read-only (``mode=ro``): reading never
# creates or changes a store.

class StoreReadError(Exception):
    """A store that exists but cannot be read as one (not SQLite, a table missing its columns, ...)."""


def _read_only(path: Path | str) -> sqlite3.Connection:
    return sqlite3.connect(Path(path).resolve().as_uri() + "?mode=ro", uri=True)


def _read_sql(path: Path | str, sql: str, params: tuple = ()):
    """``pandas.read_sql(sql)`` on the store at ``path`` opened read-only; ``StoreReadError`` when unreadable."""
    import pandas as pd

    try:
        con = _read_only(path)
        try:
            return pd.read_sql(sql, con, params=params)
        finally:
            con.close()
    except (sqlite3.Error, pd.errors.DatabaseError) as exc:
        raise StoreReadError(str(exc)) from None


def _has_table(path: Path | str, table: str) -> bool:
    try:
        con = _read_only(path)
        try:
            return con.execute("SELECT 1 FROM sqlite_master WHERE type='table' AND name=?", (table,)).fetchone() \
                is not None
        finally:
            con.close()
    except sqlite3.Error as exc:
        raise StoreReadError(str(exc)) from None


def read_runs(path: Path | str):
    """Every row of ``runs`` as a DataFrame, in the order stored."""
    return _read_sql(path, "SELECT * FROM runs ORDER BY id")


def read_matrix_runs(path: Path | str, matrix: str):
    """The rows of ``runs`` that matrix ``matrix`` stored, as a DataFrame, in the order stored."""
    return _read_sql(path, "SELECT * FROM runs WHERE command = 'matrix' AND matrix = ? ORDER BY id", (matrix,))


def matrix_case_statuses(path: Path | str, matrix: str) -> list[tuple[str, str]]:
    """(case_hash, status) of every row matrix ``matrix`` stored, in the order stored."""
    con = connect(path)
    try:
        return con.execute("SELECT case_hash, status FROM runs WHERE command = 'matrix' AND matrix = ? ORDER BY id",
                           (matrix,)).fetchall()
    finally:
        con.close()


def read_regress_history(path: Path | str, columns: tuple[str, ...]):
    """``columns`` of ``regress_history`` ordered by run and entry, or None when the store has no such table."""
    if not _has_table(path, "regress_history"):
        return None
    return _read_sql(path, "SELECT " + ", ".join(columns) + " FROM regress_history ORDER BY run_id, entry")


def read_latest_validation(path: Path | str):
    """The rows of the newest ``validate`` run in ``validation``, or None when there is none."""
    if not _has_table(path, "validation"):
        return None
    df = _read_sql(path, "SELECT * FROM validation WHERE run_id = (SELECT MAX(run_id) FROM validation)")
    return df if len(df) else None


def _fetch_all(path: Path | str, sql: str, params: tuple = ()) -> list[tuple]:
    """Rows of ``sql`` on the store at ``path`` opened read-only; ``StoreReadError`` when unreadable."""
    try:
        con = _read_only(path)
        try:
            return con.execute(sql, params).fetchall()
        finally:
            con.close()
    except sqlite3.Error as exc:
        raise StoreReadError(str(exc)) from None


def read_case_costs(path: Path | str, statuses: tuple[str, ...]) -> list[tuple]:
    """(case_json, steps, wall_s, compile_s, steps_per_s, case_hash) of every run whose status is one of
    ``statuses`` with at least one step and a positive wall time: what the matrix scheduler learns costs from."""
    marks = ", ".join("?" for _ in statuses)
    return _fetch_all(path, "SELECT case_json, steps, wall_s, compile_s, steps_per_s, case_hash FROM runs "
                            f"WHERE status IN ({marks}) AND steps > 0 AND wall_s > 0", tuple(statuses))


def read_latest_regress_rates(path: Path | str) -> list[tuple[str, float]]:
    """(entry, steps_per_s) of the newest ``regress`` run in ``regress_history``."""
    return _fetch_all(path, "SELECT entry, steps_per_s FROM regress_history WHERE run_id = "
                            "(SELECT MAX(run_id) FROM regress_history)")


def read_matrix_case_walls(path: Path | str) -> list[tuple]:
    """(case_hash, wall_s, compile_s) of every row a matrix stored, in the order stored."""
    return _fetch_all(path, "SELECT case_hash, wall_s, compile_s FROM runs WHERE command = 'matrix' ORDER BY id")


def read_latest_stable_dt(path: Path | str, creature: str, body: str) -> tuple[str, str] | None:
    """(metrics_json, timestamp) of the newest successful ``stable-dt`` run of ``creature`` on ``body``, or None."""
    rows = _fetch_all(path, "SELECT metrics_json, timestamp FROM runs WHERE command = 'stable-dt' AND creature = ? "
                            "AND body = ? AND status = 'ok' ORDER BY id DESC LIMIT 1", (creature, body))
    return rows[0] if rows else None
