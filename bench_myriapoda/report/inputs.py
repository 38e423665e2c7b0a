"""What ``report`` and ``scorecard`` read, checked before anything is drawn or written.

A matrix output directory (``harness.matrix``'s ``matrix.json``, the ``runs`` rows of its
``results.sqlite``, ``series/*.npz``), a ``validation.json`` and the history store are files a user
can edit, copy half-way or point at the wrong thing.  Each reader of the report and the scorecard
calls the checks here, so that anything it could not use is one ``InputError`` naming the file (and
the key or row) and what is allowed -- exit code 2, nothing written -- instead of a traceback deep in
a plot, a silently wrong table, or a read that blocks forever:

* JSON is parsed with a depth limit (``MAX_JSON_DEPTH``; Python's parser recurses, so a file
  nested 100,000 deep would raise ``RecursionError``) and a size limit, and only from regular files;
* the manifest's cases have string axes, a seed that is an integer or null, grid values that are
  finite numbers, strings or lists of numbers, and grid keys that are configuration keys;
* each ``runs`` row has a known status, a resolved case with its sections, metrics that are numbers
  (or null), timings that are numbers and labels that are strings;
* ``validation.json`` is an object whose ``rows`` are the rows ``validate`` writes;
* a recording that exists but is not a regular file (a FIFO would block ``open`` forever) is refused
  without being opened;
* the history store (``--history-store``, default ``reports/results.sqlite``) gets one check for
  both commands (:func:`check_history_store`).
"""
from __future__ import annotations

import json
import math
import os
import stat
from pathlib import Path
from typing import Any

from ..core.errors import InputError

MAX_JSON_DEPTH = 64  # objects and arrays nested deeper than anything the suite writes (case_json: 4)
MAX_JSON_BYTES = 512_000_000  # a 20,000-case matrix.json is a few MB; a results row a few kB
STATUSES = ("ok", "unstable", "error", "timeout", "controller_unstable")  # runner.RunResult.status (the shape guard's
# "controller_unstable", issue 44), and executors' "timeout"
AXES = ("creature", "body", "gait", "scenario", "seed")
CASE_SECTIONS = ("creature", "body", "gait", "scenario")  # Case.to_dict() sections the report reads


# --------------------------------------------------------------------------- JSON

def _depth_problem(value: Any) -> bool:
    """True when ``value`` nests objects and arrays deeper than MAX_JSON_DEPTH (checked without recursion)."""
    stack = [(value, 0)]
    while stack:
        v, depth = stack.pop()
        if isinstance(v, (dict, list)):
            if depth >= MAX_JSON_DEPTH:
                return True
            stack.extend((x, depth + 1) for x in (v.values() if isinstance(v, dict) else v))
    return False


def parse_json(text: str, src: str, key: str | None = None, what: str = "JSON") -> Any:
    """``text`` as JSON; an ``InputError`` naming ``src`` (and ``key``; "unreadable ``what``") when it does not
    parse or nests deeper than ``MAX_JSON_DEPTH``."""
    if not isinstance(text, str):
        raise InputError(src, key, f"unreadable {what}: expected JSON text, got {type(text).__name__}")
    try:
        value = json.loads(text)
    except RecursionError:
        value = None
        deep = True
    except ValueError as exc:
        raise InputError(src, key, f"unreadable {what}: not valid JSON ({str(exc)[:120]})") from None
    else:
        deep = _depth_problem(value)
    if deep:
        raise InputError(src, key, f"unreadable {what}: JSON nested deeper than {MAX_JSON_DEPTH} levels; not "
                                   "written by bench-myriapoda")
    return value


def check_regular_file(path: Path, src: str | None = None) -> bool:
    """True when ``path`` is a regular file (or a link to one), False when nothing is there; an
    ``InputError`` when something else is (a FIFO or a device would block or never end a read, and is
    never opened)."""
    src = src or str(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        if os.path.islink(path):
            raise InputError(src, None, "a dangling symbolic link; delete it or rerun the command that "
                                        "writes it") from None
        return False
    except OSError as exc:
        raise InputError(src, None, f"cannot read ({exc.strerror or exc})") from None
    if not stat.S_ISREG(st.st_mode):
        kind = "a directory" if stat.S_ISDIR(st.st_mode) else "not a regular file (a FIFO, socket or device)"
        raise InputError(src, None, f"{kind}; expected a file written by bench-myriapoda")
    return True


def read_json_file(path: Path, what: str) -> Any:
    """The JSON document in the regular file ``path`` (``what`` names it in messages); InputError otherwise."""
    src = str(path)
    if not check_regular_file(path, src):
        raise InputError(src, None, f"no such file ({what})")
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_JSON_BYTES + 1)
    except OSError as exc:
        raise InputError(src, None, f"cannot read {what} ({exc.strerror or exc})") from None
    if len(raw) > MAX_JSON_BYTES:
        raise InputError(src, None, f"larger than {MAX_JSON_BYTES:,} bytes; not a {what}")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError(src, None, f"unreadable {what}: not UTF-8") from None
    return parse_json(text, src, None, what)


# --------------------------------------------------------------------------- matrix.json

def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _grid_value_ok(v: Any) -> bool:
    """A grid value as ``harness.matrix`` writes it: a finite number, a string, a boolean or a list of numbers."""
    if isinstance(v, (str, bool)):
        return True
    if _is_number(v):
        return math.isfinite(v)
    return isinstance(v, list) and all(_is_number(x) and math.isfinite(x) for x in v)


def _known_keys() -> set[str]:
    """Every dotted key ``--set`` (and so a matrix grid) accepts, plugins' body models included."""
    from ..core import registry
    from ..core.keys import config_keys

    registry.load_all()
    return {r["key"] for r in config_keys()}


def check_manifest(meta: Any, src: str) -> dict:
    """``matrix.json`` with the shape ``harness.matrix.write_matrix_manifest`` writes, or InputError."""
    if not isinstance(meta, dict):
        raise InputError(src, None, f"expected a JSON object, got {type(meta).__name__}")
    for key, tp in (("name", str), ("cases", dict)):
        if not isinstance(meta.get(key), tp):
            raise InputError(src, key, f"expected {'a string' if tp is str else 'an object'}, "
                                       f"got {meta.get(key)!r:.80}")
    for key, tp in (("description", str), ("grid_keys", list), ("unsupported", list)):
        if key in meta and not isinstance(meta[key], tp):
            raise InputError(src, key, f"expected {'a string' if tp is str else 'a list'}, got {meta[key]!r:.80}")
    for i, u in enumerate(meta.get("unsupported", [])):
        if not isinstance(u, str):
            raise InputError(src, f"unsupported[{i}]", f"expected a string, got {u!r:.80}")
    grid_keys = meta.get("grid_keys", [])
    known = _known_keys() if grid_keys else set()  # an axis outside grid_keys is refused below
    for i, k in enumerate(grid_keys):
        if not isinstance(k, str) or k not in known:
            raise InputError(src, f"grid_keys[{i}]", f"{k!r:.80} is not a configuration key (`bench-myriapoda "
                                                     "keys` lists them)")
    for h, info in meta["cases"].items():
        where = f"cases.{h}"
        if not (isinstance(info, dict) and isinstance(info.get("label"), str) and isinstance(info.get("axes"), dict)):
            raise InputError(src, where, "expected an object with a string 'label' and an object 'axes'")
        axes = info["axes"]
        for a in AXES[:4]:
            if not isinstance(axes.get(a), str) or not axes[a]:
                raise InputError(src, f"{where}.axes.{a}", f"expected a name (a non-empty string), "
                                                           f"got {axes.get(a)!r:.80}")
        seed = axes.get("seed")
        if seed is not None and not (isinstance(seed, int) and not isinstance(seed, bool) and seed >= 0):
            raise InputError(src, f"{where}.axes.seed", f"expected an integer >= 0 or null, got {seed!r:.80}")
        for k, v in axes.items():
            if k in AXES:
                continue
            if k not in grid_keys:
                raise InputError(src, f"{where}.axes.{k}", "not among the manifest's grid_keys "
                                                           f"({', '.join(map(str, grid_keys)) or 'none'})")
            if not _grid_value_ok(v):
                raise InputError(src, f"{where}.axes.{k}", f"expected a finite number, a string, true/false or a "
                                                           f"list of finite numbers, got {v!r:.80}")
    return meta


# --------------------------------------------------------------------------- runs rows

def check_run_row(row, store: str) -> tuple[dict, dict, dict, dict]:
    """(case, metrics, timings, labels) of one ``runs`` row, each checked; an InputError naming the store
    and ``runs.id=N`` otherwise.  Metrics come back with None as NaN; timings as floats (NaN when absent)."""
    where = f"runs.id={row.id}"

    def bad(what: str) -> InputError:
        return InputError(store, where, f"unreadable row: {what}; not written by bench-myriapoda matrix")

    if row.status not in STATUSES:
        raise bad(f"status {row.status!r:.40} is not one of {', '.join(STATUSES)}")
    parsed = {}
    for col, default in (("case_json", None), ("metrics_json", None), ("timings_json", None), ("labels_json", "{}")):
        text = getattr(row, col)
        text = default if (text is None or text == "") and default is not None else text
        if text is None:
            raise bad(f"{col} is empty")
        value = parse_json(text, store, where, f"row ({col})")
        if not isinstance(value, dict):
            raise bad(f"{col} is {type(value).__name__}, expected a JSON object")
        parsed[col] = value
    case, metrics, timings, labels = (parsed[c] for c in ("case_json", "metrics_json", "timings_json", "labels_json"))
    for section in CASE_SECTIONS:
        if not isinstance(case.get(section), dict) or not isinstance(case[section].get("name"), str):
            raise bad(f"case_json has no {section} section with a name")
    for key in ("dt", "duration"):
        v = case.get(key)
        if not (_is_number(v) and math.isfinite(v) and v > 0):
            raise bad(f"case_json {key} is {v!r:.40}, expected a number > 0")
    for k, v in metrics.items():
        if v is not None and not _is_number(v):
            raise bad(f"metric {k!r:.40} is {v!r:.40}, expected a number or null")
    for k, v in timings.items():
        if v is not None and not _is_number(v):
            raise bad(f"timing {k!r:.40} is {v!r:.40}, expected a number or null")
    for k, v in labels.items():
        if not isinstance(v, str):
            raise bad(f"label {k!r:.40} is {v!r:.40}, expected a string")
    metrics = {k: (math.nan if v is None else v) for k, v in metrics.items()}
    timings = {k: (math.nan if timings.get(k) is None else float(timings[k]))
               for k in ("steps_per_s", "realtime_factor", "compile_s", "wall_s")}
    return case, metrics, timings, labels


# --------------------------------------------------------------------------- validation.json

VALIDATION_TEXT = ("check", "family", "body", "quantity", "source", "tolerance", "verdict")  # strings, required
VALIDATION_OPTIONAL_TEXT = ("detail", "unit")  # strings or null when present


def read_validation_json(path: Path) -> dict | None:
    """``validate --out DIR``'s ``validation.json``, checked (None when there is none); InputError otherwise."""
    from ..validation.core import FAIL, INFO, NA, PASS

    if not check_regular_file(path):
        return None
    src = str(path)
    doc = read_json_file(path, "validation.json")
    if not isinstance(doc, dict):
        raise InputError(src, None, f"expected a JSON object with a list 'rows', got {type(doc).__name__}")
    rows = doc.get("rows", [])
    if not isinstance(rows, list):
        raise InputError(src, "rows", f"expected a list of row objects, got {rows!r:.80}")
    verdicts = (PASS, FAIL, NA, INFO)
    for i, r in enumerate(rows):
        where = f"rows[{i}]"
        if not isinstance(r, dict):
            raise InputError(src, where, f"expected a row object, got {r!r:.80}")
        for k in VALIDATION_TEXT:
            if not isinstance(r.get(k), str):
                raise InputError(src, f"{where}.{k}", f"expected a string, got {r.get(k)!r:.80}")
        for k in VALIDATION_OPTIONAL_TEXT:
            if r.get(k) is not None and not isinstance(r[k], str):
                raise InputError(src, f"{where}.{k}", f"expected a string, got {r[k]!r:.80}")
        if r["verdict"] not in verdicts:
            raise InputError(src, f"{where}.verdict", f"{r['verdict']!r:.40} is not one of {', '.join(verdicts)}")
        if r.get("seconds") is not None and not _is_number(r["seconds"]):
            raise InputError(src, f"{where}.seconds", f"expected a number or null, got {r['seconds']!r:.80}")
    if "wall_s" in doc and doc["wall_s"] is not None and not _is_number(doc["wall_s"]):
        raise InputError(src, "wall_s", f"expected a number or null, got {doc['wall_s']!r:.80}")
    return doc


# --------------------------------------------------------------------------- the history store

def check_history_store(store: Path | str | None, flag: str = "--history-store") -> Path | None:
    """The results store ``report`` and ``scorecard`` read history from (validate verdicts, stable-dt
    results, the regress history): ``store`` as given, or the default ``reports/results.sqlite``.

    One check for both commands, before anything is read.  The default store not being there is no
    history (None; the report says so); a store named with the flag must exist (a mistyped path would
    otherwise read as "no history"); one that is there must be a non-empty results store of this suite --
    a garbage file, another program's database, a foreign ``validation`` table, an empty file, a FIFO or
    a directory is refused, naming the flag (or the default path when none was given).
    """
    from ..harness.store import DEFAULT_STORE, check_store

    given = store is not None
    path = Path(store) if given else DEFAULT_STORE
    label = flag if given else f"{flag} (default {DEFAULT_STORE})"
    if not os.path.lexists(path):
        if given:
            raise InputError(label, None, f"{path} does not exist; give an existing results store "
                                          f"(written by `bench-myriapoda validate`, `regress` or `run --store`) "
                                          f"or leave the flag out")
        return None
    check_store(path, label, write=False)
    if check_regular_file(path, str(path)) and os.path.getsize(path) == 0:
        raise InputError(label, None, f"{path} is an empty file, not a results store")
    return path
