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
from ..core.userpaths import check_path_text, is_only_a_suffix, is_root
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


# SQLite's wait for another writer's lock during an insert: concurrent runs take turns in milliseconds, a
# matrix's workers' rows queue behind each other.  The checks before a run wait only LOCK_WAIT_S (below).
WRITE_TIMEOUT_S = 60


def connect(path: Path | str = DEFAULT_STORE) -> sqlite3.Connection:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    con = sqlite3.connect(path, timeout=WRITE_TIMEOUT_S)
    con.executescript(SCHEMA)
    _add_missing_columns(con)
    return con


SQLITE_MAGIC = b"SQLite format 3\x00"
# Objects SQLite makes by itself: the AUTOINCREMENT counter, ANALYZE's statistics, PRIMARY KEY indexes.
SQLITE_INTERNAL = ("sqlite_sequence", "sqlite_stat1", "sqlite_stat2", "sqlite_stat3", "sqlite_stat4")
# Below this much free space on its file system a store is refused before a run: the run's row and the
# journal need a few hundred kB, and a run that cannot be stored after it was computed is a lost run.
MIN_FREE_BYTES = 1 << 20
# How long a check before the run waits for another program's lock on the store before it refuses it
# (a writer holding BEGIN IMMEDIATE for minutes; a normal insert holds the lock for milliseconds).
LOCK_WAIT_S = 3.0
# Folders in an output path: Path.mkdir(parents=True) recurses once per missing folder, so a path of
# thousands of components (a 2.8 kB "a/a/a/...") would end in a RecursionError after the run.
MAX_PATH_DEPTH = 256


def _expected_schema() -> dict[str, Any]:
    """This suite's tables (column -> (declared type, NOT NULL, default, primary-key position)) and indexes
    (name -> table), read from ``SCHEMA`` built in memory (with the columns later releases added)."""
    con = sqlite3.connect(":memory:")
    try:
        con.executescript(SCHEMA)
        _add_missing_columns(con)
        tables = {t: {r[1]: (r[2].upper(), r[3], r[4], r[5]) for r in con.execute(f"PRAGMA table_info({t})")}
                  for (t,) in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")
                  if t not in SQLITE_INTERNAL}
        indexes = {n: t for n, t in con.execute("SELECT name, tbl_name FROM sqlite_master WHERE type = 'index' "
                                                "AND sql IS NOT NULL")}
    finally:
        con.close()
    return {"tables": tables, "indexes": indexes}


def check_store(path: Path | str, flag: str, *, write: bool = True, need: tuple[str, ...] = ()) -> Path:
    """Check a results store before anything runs; an ``InputError`` naming ``flag`` if it is unusable.

    The path must not exist yet, or be an empty file, or a SQLite database that is this suite's store:
    only its tables (``runs``, ``metrics``, ``regress_history``, ``validation``), each with exactly its
    columns, types and NOT NULL constraints (an older store may lack the columns ``connect`` adds), its
    indexes and no other object -- no view, no trigger, no unique index, no other program's table that
    the suite's inserts could fail on or that the suite would extend.  With ``write`` the file and its
    folder (SQLite's journal goes beside it) must be writable and the file system not full.  ``need``
    names tables that must exist (a report reading ``runs``).  Nothing is created or changed here: the
    store is opened read-only.
    """
    path = check_path_text(path, flag)
    if os.path.islink(path) and not path.exists():
        raise InputError(flag, None, f"{path} is a dangling symbolic link (to {os.readlink(path)}); "
                                     "give the path of a SQLite results file")
    if path.is_dir():
        raise InputError(flag, None, f"{path} exists and is not a file; give the path of a SQLite results file")
    if path.exists() and not path.is_file():
        raise InputError(flag, None, f"{path} is not a regular file (a FIFO, socket or device); give the path of "
                                     "a SQLite results file")
    if not path.exists():
        if need:
            raise InputError(flag, None, f"{path}: no such results store")
        if write:
            check_writable_file(path, flag)
        return path
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise InputError(flag, None, f"{path}: cannot read ({exc.strerror})") from None
    # The file is read through SQLite first: closing a plain file handle on it would drop every POSIX lock this
    # process holds on it, a transaction another connection of the caller's has open included (SQLite's own
    # handles keep them).  Only a file SQLite cannot open as a database has its header read directly.
    facts = _page_facts(path) if size else None
    header = None
    if isinstance(facts, tuple) and (size < 100 or facts[1] == 0):
        # SQLite opens a file shorter than its 100-byte header as an empty database (page count 0): such a file is
        # not empty, so it is not a store (nor SQLite's), and writing would overwrite what is in it
        raise InputError(flag, None, f"{path} is not a SQLite database (a results store written by bench-myriapoda)")
    if isinstance(facts, sqlite3.Error):
        if _is_busy(facts):
            raise InputError(flag, None, _locked_message(path))
        try:
            with open(path, "rb") as fh:
                header = fh.read(100)
        except OSError as exc:
            raise InputError(flag, None, f"{path}: cannot read ({exc.strerror})") from None
        if header[: len(SQLITE_MAGIC)] != SQLITE_MAGIC:
            raise InputError(flag, None, f"{path} is not a SQLite database (a results store written by "
                                         "bench-myriapoda)")
    if write:
        if not os.access(path, os.W_OK) or _read_only_mount(path):
            raise InputError(flag, None, f"{path} is not writable")
        check_writable_dir(path.parent, flag, what=f"the folder of {path} (SQLite writes its journal there)")
    if not size:  # an empty file: SQLite makes it a database on first write
        if need:
            raise InputError(flag, None, f"{path} is an empty file, not a results store")
        return path
    if header is not None:
        _check_not_truncated(path, header, flag)
    elif size < facts[0] * facts[1]:
        raise InputError(flag, None, f"{path} is a truncated SQLite file ({size:,} bytes; its header says "
                                     f"{facts[0] * facts[1]:,})")
    problem = _roll_back_hot_journal(path)
    if problem:
        raise InputError(flag, None, f"{path}: {problem}")
    try:
        con = sqlite3.connect(path.resolve().as_uri() + "?mode=ro", uri=True, timeout=LOCK_WAIT_S)
        try:
            tables = {n for (n,) in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
            problem = _schema_problem(con)
            damage = None if problem else _damage(con)
        finally:
            con.close()
    except sqlite3.DatabaseError as exc:
        if _is_busy(exc):
            raise InputError(flag, None, _locked_message(path)) from None
        raise InputError(flag, None, f"{path} is not a usable SQLite results store ({exc})") from None
    for table in need:
        if table not in tables:
            raise InputError(flag, None, f"{path} has no {table} table; not a results store of this schema")
    if problem:
        raise InputError(flag, None, f"{path}: {problem}; not a results store of bench-myriapoda (refused rather "
                                     "than changed: give another path)")
    if damage:
        raise InputError(flag, None, f"{path} is damaged: {damage} (PRAGMA quick_check); refused rather than "
                                     "written into or read: restore it from a copy or give another path")
    if write:
        _check_not_locked(path, flag)
    return path


def _is_busy(exc: sqlite3.Error) -> bool:
    """Another connection holds a lock SQLite waited out (SQLITE_BUSY / SQLITE_LOCKED)."""
    name = getattr(exc, "sqlite_errorname", "") or ""
    return name.startswith(("SQLITE_BUSY", "SQLITE_LOCKED")) or "database is locked" in str(exc)


def _locked_message(path: Path) -> str:
    return f"{path} {_LOCKED}"


_LOCKED = (f"is locked by another program writing to it (waited {LOCK_WAIT_S:g} s for its lock); try again "
           "when it has finished, or give another store")


def _check_not_locked(path: Path, flag: str) -> None:
    """The write lock can be taken now: a store another writer holds (``BEGIN IMMEDIATE`` left open) is
    refused here within ``LOCK_WAIT_S``, not found after the run when the insert waits out its timeout.
    Takes the lock and releases it with nothing written (no journal is made for an empty transaction)."""
    try:
        con = sqlite3.connect(path, timeout=LOCK_WAIT_S, isolation_level=None)
        try:
            con.execute("BEGIN IMMEDIATE")
            con.execute("ROLLBACK")
        finally:
            con.close()
    except sqlite3.DatabaseError as exc:
        if _is_busy(exc):
            raise InputError(flag, None, _locked_message(path)) from None
        raise InputError(flag, None, f"{path} cannot be written ({exc})") from None


def _damage(con: sqlite3.Connection) -> str | None:
    """The first problem ``PRAGMA quick_check`` finds in the store's pages (None: none).

    quick_check reads every page once (it skips integrity_check's index-to-table cross-check, O(N log N)):
    about 150 ms for a 53 MB store of 5,000 runs, warm page cache (integrity_check: 250 ms)."""
    rows = con.execute("PRAGMA quick_check(1)").fetchall()
    if rows == [("ok",)]:
        return None
    text = " ".join(str(r[0]) for r in rows).replace("*** in database main ***", "").strip()
    return text.splitlines()[0] if text else "unknown damage"


def _roll_back_hot_journal(path: Path) -> str | None:
    """Roll back the hot journal a writer that stopped mid-transaction left beside the store (None: done,
    or there was none); a line saying why not otherwise.

    A hot journal is normal SQLite state: the next read-write connection rolls it back and the store is
    as it was before that transaction.  A read-only connection (every check and reader here) cannot, and
    refuses the file ("attempt to write a readonly database"); so one read-write open does it first."""
    journal = Path(str(path) + "-journal")
    try:
        if not journal.is_file() or journal.stat().st_size == 0:
            return None
    except OSError:
        return None
    if not os.access(path, os.W_OK) or not os.access(path.parent, os.W_OK | os.X_OK) or _read_only_mount(path):
        return (f"has a hot journal ({journal.name}) left by a writer that stopped mid-transaction, and it "
                "cannot be rolled back on a read-only file or folder; open it once where it is writable")
    try:
        con = sqlite3.connect(path, timeout=LOCK_WAIT_S)
        try:
            con.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()  # SQLite rolls the journal back here
        finally:
            con.close()
    except sqlite3.DatabaseError as exc:
        if _is_busy(exc):
            return _LOCKED
        return f"has a hot journal ({journal.name}) that SQLite could not roll back ({exc})"
    return None


def _page_facts(path: Path) -> tuple[int, int] | sqlite3.Error:
    """(page size, page count) as SQLite reads them from the header (the count from the file's size when the
    header's is stale), or the error SQLite gives for a file it cannot open as a database."""
    try:
        con = sqlite3.connect(path.resolve().as_uri() + "?mode=ro", uri=True, timeout=LOCK_WAIT_S)
        try:
            pages = con.execute("PRAGMA page_count").fetchone()[0]
            return con.execute("PRAGMA page_size").fetchone()[0], pages
        finally:
            con.close()
    except sqlite3.Error as exc:
        return exc


def _check_not_truncated(path: Path, header: bytes, flag: str) -> None:
    """The file is as long as its header says (page size x page count): a cut copy is refused, not read."""
    if len(header) < 100:
        raise InputError(flag, None, f"{path} is a truncated SQLite file ({len(header)} bytes)")
    page = int.from_bytes(header[16:18], "big")
    page = 65536 if page == 1 else page
    pages = int.from_bytes(header[28:32], "big")
    valid = header[24:28] == header[92:96]  # the page count is valid when the change counters agree
    size = path.stat().st_size
    if valid and pages and size < page * pages:
        raise InputError(flag, None, f"{path} is a truncated SQLite file ({size:,} bytes; its header says "
                                     f"{page * pages:,})")


def _schema_problem(con: sqlite3.Connection) -> str | None:
    """What in an existing database is not this suite's schema (None: nothing)."""
    want = _expected_schema()
    objects = con.execute("SELECT type, name, tbl_name, sql FROM sqlite_master").fetchall()
    # views and triggers first: either can make an insert fail (or do something else) behind the suite's back
    objects.sort(key=lambda o: o[0] not in ("view", "trigger"))
    for kind, name, table, sql in objects:
        if name in SQLITE_INTERNAL or (kind == "index" and sql is None):
            continue  # SQLite's own: the AUTOINCREMENT counter, statistics, PRIMARY KEY indexes
        if kind == "table" and name in want["tables"]:
            continue
        if kind == "index" and want["indexes"].get(name) == table:
            continue
        if kind in ("view", "trigger"):
            return f"has a {kind} {name!r}" + (f" on table {table}" if kind == "trigger" else "") + \
                f" (the suite's store has no {kind}s)"
        if kind == "index":
            return f"has an index {name!r} on table {table} that is not the suite's"
        return f"has a {kind} {name!r} that is not one of the suite's tables ({', '.join(sorted(want['tables']))})"
    for table, cols in want["tables"].items():
        have = {r[1]: (r[2].upper(), r[3], r[4], r[5]) for r in con.execute(f"PRAGMA table_info({table})")}
        if not have:
            continue  # a table a later run adds
        missing = sorted(set(cols) - set(have) - ({n for n, _ in LATER_COLUMNS} if table == "runs" else set()))
        if missing:
            return f"table {table} lacks columns {', '.join(missing)}"
        extra = sorted(set(have) - set(cols))
        if extra:
            return f"table {table} has columns the suite's lacks: {', '.join(extra)}"
        for col, spec in have.items():
            if spec[:2] != cols[col][:2] or bool(spec[3]) != bool(cols[col][3]):
                return (f"column {table}.{col} is {spec[0] or 'untyped'}{' NOT NULL' if spec[1] else ''}"
                        f"{' PRIMARY KEY' if spec[3] else ''}; the suite's is {cols[col][0]}"
                        f"{' NOT NULL' if cols[col][1] else ''}{' PRIMARY KEY' if cols[col][3] else ''}")
    return None


def check_writable_file(path: Path | str, flag: str) -> Path:
    """An output file path that can be created or replaced: a regular file or nothing yet, with a real
    name (not only a suffix such as ``.npz``), in a writable folder on a file system that is not full.

    Checks without writing anything: the nearest existing ancestor folder must be writable (the
    missing folders between it and the file are created later, when the file is written).
    """
    path = check_path_text(path, flag)
    if path.is_dir() or is_root(path):
        raise InputError(flag, None, f"{path} is a directory; give a file name")
    if is_only_a_suffix(path.name):
        raise InputError(flag, None, f"{str(path)!r} is only a suffix; give a file name such as "
                                     f"out{path.name}")
    if os.path.islink(path) and not path.exists():
        raise InputError(flag, None, f"{path} is a dangling symbolic link (to {os.readlink(path)})")
    if path.exists() and not path.is_file():
        raise InputError(flag, None, f"{path} is not a regular file (a FIFO, socket or device); give a file name")
    if path.exists() and (not os.access(path, os.W_OK) or _read_only_mount(path)):
        raise InputError(flag, None, f"{path} is not writable")
    check_writable_dir(path.parent, flag, what=f"the folder of {path}")
    return path


def check_writable_dir(path: Path | str, flag: str, what: str | None = None) -> Path:
    """A directory that exists and is writable, or can be created (its nearest existing ancestor is),
    on a file system that is not full; never the file-system root (an output folder there would spread
    the suite's files into /)."""
    path = check_path_text(path, flag)
    what = what or str(path)
    if len(path.parts) > MAX_PATH_DEPTH:
        raise InputError(flag, None, f"the path is {len(path.parts):,} folders deep; at most {MAX_PATH_DEPTH}")
    if is_root(path):
        raise InputError(flag, None, f"{what}: the file-system root is not an output folder; give a folder "
                                     "such as reports/NAME")
    probe = path
    while not os.path.lexists(probe):
        if probe.parent == probe:
            break
        probe = probe.parent
    if os.path.lexists(probe) and not probe.is_dir():
        raise InputError(flag, None, f"{what}: {probe} exists and is not a directory")
    if not os.access(probe, os.W_OK | os.X_OK) or _read_only_mount(probe):
        raise InputError(flag, None, f"{what}: {probe} is not writable")
    free = _free_bytes(probe)
    if free is not None and free < MIN_FREE_BYTES:
        raise InputError(flag, None, f"{what}: the file system of {probe} is full ({free:,} bytes free); "
                                     f"free some space or write elsewhere")
    return path


def _free_bytes(path: Path) -> int | None:
    """Bytes an unprivileged writer may still use on ``path``'s file system (None when unknown)."""
    try:
        st = os.statvfs(path)
    except OSError:
        return None
    return st.f_bavail * st.f_frsize


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


def _storable(value: Any) -> Any:
    """``value`` as SQLite can store it: a str holding a lone surrogate (a file name that is not UTF-8, as
    Python decodes it: ``"\\udcfe.toml"``) has it written as its byte escape (``"\\xfe.toml"``); SQLite
    only takes valid UTF-8 and would refuse the whole row after the run."""
    if not isinstance(value, str):
        return value
    try:
        value.encode("utf-8")
        return value
    except UnicodeEncodeError:
        try:
            return value.encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
        except UnicodeEncodeError:  # a surrogate no file name makes: its code point, escaped
            return value.encode("utf-8", "backslashreplace").decode("utf-8")


def _storable_row(row: tuple) -> tuple:
    return tuple(_storable(v) for v in row)


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
                " VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)", _storable_row(
                (result.case.case_hash(), command, case["creature"]["name"], case["body"]["name"], case["gait"]["name"],
                 case["scenario"]["name"], result.status, result.message, json.dumps(case, sort_keys=True),
                 json.dumps(metrics, sort_keys=True), json.dumps(timings, sort_keys=True),
                 json.dumps(result.extra.get("labels", {}), sort_keys=True), timings.get("steps"),
                 timings.get("steps_per_s"), timings.get("realtime_factor"), timings.get("compile_s"),
                 timings.get("wall_s"), commit, None if dirty is None else int(dirty), json.dumps(mach, sort_keys=True),
                 mach["cpu_model"], mach["cpu_count"], mach["python"], mach["numpy"], mach["numba"],
                 time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), matrix)))
            run_id = cur.lastrowid
            con.executemany("INSERT INTO metrics (run_id, name, value) VALUES (?,?,?)",
                            [(run_id, _storable(k), v if isinstance(v, (int, float)) else None)
                             for k, v in metrics.items()])
        return run_id
    finally:
        con.close()


def record_validation_run(path: Path | str, rows: list[dict[str, Any]], quick: bool, out_dir: str | None) -> int:
    """Insert the rows of one ``validate`` run (``validation.core.Row.to_dict()``) into ``validation`` in one
    transaction; return its run id (1, 2, ... per store)."""
    mach, commit, dirty, stamp = _run_stamp()
    return _insert_numbered_run(
        path, "validation",
        "INSERT INTO validation (run_id, check_name, family, body, quantity, measured_json, reference_json,"
        " source, tolerance, verdict, detail, unit, seconds, figures_json, quick, out_dir, git_commit,"
        " git_dirty, machine_json, timestamp) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)",
        lambda run_id: [(run_id, r["check"], r["family"], r["body"], r["quantity"], json.dumps(_finite(r["measured"])),
                         json.dumps(_finite(r["reference"])), r["source"], r["tolerance"], r["verdict"], r["detail"],
                         r["unit"], _finite(r["seconds"]), json.dumps(r["figures"], sort_keys=True), int(quick),
                         out_dir, commit, dirty, mach, stamp) for r in rows])


def _run_stamp() -> tuple[str, str | None, int | None, str]:
    """(machine fingerprint JSON, git commit, dirty as 0/1 or None, UTC timestamp) of a numbered run's rows."""
    commit, dirty = git_commit()
    return (json.dumps(machine_fingerprint(), sort_keys=True), commit, None if dirty is None else int(dirty),
            time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()))


def _insert_numbered_run(path: Path | str, table: str, sql: str, make_rows) -> int:
    """Insert one run's rows into ``table`` under the next run id (1, 2, ... per store), in one transaction.

    ``make_rows(run_id)`` gives the parameter tuples of ``sql``.  BEGIN IMMEDIATE takes the write lock before
    the id is read, so two concurrent writers never share a run id; any failure rolls the whole run back."""
    con = connect(path)
    try:
        con.execute("BEGIN IMMEDIATE")
        try:
            run_id = con.execute(f"SELECT COALESCE(MAX(run_id), 0) + 1 FROM {table}").fetchone()[0]
            con.executemany(sql, [_storable_row(r) for r in make_rows(run_id)])
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
    mach, commit, dirty, stamp = _run_stamp()
    return _insert_numbered_run(
        path, "regress_history",
        "INSERT INTO regress_history (run_id, git_commit, git_dirty, machine_json, timestamp, "
        + ", ".join(REGRESS_FIELDS) + ") VALUES (?,?,?,?,?," + ",".join("?" * len(REGRESS_FIELDS)) + ")",
        lambda run_id: [(run_id, commit, dirty, mach, stamp,
                         *(_finite(r[k]) for k in REGRESS_FIELDS)) for r in rows])


# --------------------------------------------------------------------------- reading
# Every query of the store is written in this module; the matrix executor, the regression history, the report
# and the API read through these functions.  The readers open the file read-only (``mode=ro``): reading never
# creates or changes a store.

class StoreReadError(Exception):
    """A store that exists but cannot be read as one (not SQLite, a table missing its columns, ...)."""


def _read_only(path: Path | str) -> sqlite3.Connection:
    problem = _roll_back_hot_journal(Path(path))  # a read-only connection refuses a store with a hot journal
    if problem:
        raise sqlite3.OperationalError(problem)
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


# --------------------------------------------------------------------------- a result the store could not take
# Everything a run computed is kept even when its insert fails after the simulation (a disk that filled, a
# store changed by another program while the run ran): the command prints its result as usual and says where
# this file is, instead of ending in a traceback with the result lost.

# Anything an insert after the run can raise: SQLite's and the file system's errors, a text SQLite will not
# take (UnicodeEncodeError is a ValueError), a path too deep for mkdir (RecursionError), and the rest: a result
# computed is kept whatever made its insert fail.
STORE_WRITE_ERRORS = (Exception,)


class UnstoredError(Exception):
    """A result was computed but could not be stored; ``fallback`` is the file that keeps it (or None)."""

    def __init__(self, store: Path | str, what: str, error: BaseException, fallback: Path | None):
        self.store, self.what, self.error, self.fallback = Path(store), what, error, fallback
        kept = (f"the result is kept in {fallback}" if fallback is not None
                else "it could not be kept in a file either (the result is printed on stdout)")
        super().__init__(f"could not store the {what} in {store} ({type(error).__name__}: {error}); {kept}")


def fallback_dirs(store: Path | str) -> list[Path]:
    """Where an unstored result goes, first that works: ``unsaved/`` beside the store, then the
    temporary directory (``$TMPDIR``), when the store's own folder is the one that is full or read-only."""
    import tempfile

    return [Path(store).parent / "unsaved", Path(tempfile.gettempdir()) / "bench-myriapoda-unsaved"]


def keep_unstored(store: Path | str, what: str, doc: Any, error: BaseException) -> Path | None:
    """Write ``doc`` (JSON-able: the result as ``--json`` prints it) to a fallback file; its path, or None
    when no fallback folder could be written either."""
    stamp = time.strftime("%Y%m%dT%H%M%SZ", time.gmtime())
    body = json.dumps({"store": str(store), "error": f"{type(error).__name__}: {error}", "what": what,
                       "result": doc}, default=str)
    for folder in fallback_dirs(store):
        path = folder / f"{what.replace(' ', '-')}-{stamp}-{os.getpid()}.json"
        tmp = path.with_suffix(".json.tmp")
        try:
            folder.mkdir(parents=True, exist_ok=True)
            tmp.write_text(body)
            os.replace(tmp, path)
            return path
        except (OSError, ValueError, RecursionError):  # a folder that cannot be made: try the next one
            try:
                tmp.unlink()
            except OSError:
                pass
    return None


def store_or_keep(store: Path | str, what: str, write, doc) -> Any:
    """``write()`` (an insert into ``store``); when it fails with a database or file-system error, keep
    ``doc()`` in a fallback file and raise :class:`UnstoredError` naming it."""
    try:
        return write()
    except STORE_WRITE_ERRORS as exc:
        raise UnstoredError(store, what, exc, keep_unstored(store, what, doc(), exc)) from exc
