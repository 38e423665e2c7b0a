"""Scenario matrices: a TOML file that expands into many resolved cases.

A matrix file (``scenarios/matrix/NAME.toml``) names axes whose product is the
set of cases to run::

    [matrix]
    name = "demo"                       # optional; default: the file name
    description = "..."
    creatures = ["worm", "snake"]
    bodies = ["massspring", "fem"]
    gaits = ["default"]                 # optional; "default" is each creature's default gait
    scenarios = ["flat"]
    seeds = [0, 1]                      # optional
    duration = 2.0                      # optional, seconds
    set = { "creature.segments" = 6 }   # optional: fixed overrides for every case
    [matrix.grid]                       # optional: any dotted key -> list of values
    "dt" = [0.001, 0.002]
    "friction.mu_transverse" = [0.2, 0.5]

    [[block]]                           # optional: more products, unioned with [matrix]'s;
    creatures = ["chain"]               # a block's keys replace [matrix]'s for that block
    bodies = ["hybrid"]

    [[exclude]]                         # optional: drop every case matching all these keys
    creature = "snake"
    body = "fem"
    "friction.mu_transverse" = 0.5      # a grid key; a list means "any of"

When a ``[[block]]`` is given, the cases are the union of the blocks' products
and ``[matrix]`` only supplies their defaults; without blocks ``[matrix]`` is the
one block.  Every case is resolved with :func:`resolve_case` before anything
runs, so a bad key or value in a grid is reported as an ``InputError`` naming
the matrix file and the key.  A combination that resolution rejects as an
"unsupported combination" (a worm with the sidewinding gait, a worm on the
hybrid body, a ``body.*`` grid key the body model lacks) is not an error: it is
listed in :attr:`Expansion.unsupported` and not run.  Cases that resolve to the
same configuration (equal :meth:`Case.case_hash`) are run once.
"""
from __future__ import annotations

import dataclasses
import itertools
import json
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..core import registry
from ..core.config import Case, creature_names, read_tables, resolve_case, scenario_paths
from ..core.errors import InputError
from ..core.paths import scenarios_dir
from ..core.suggest import did_you_mean
from ..core.userpaths import check_path_text

AXIS_KEYS = {"creatures": "creature", "bodies": "body", "gaits": "gait", "scenarios": "scenario", "seeds": "seed"}
BLOCK_KEYS = set(AXIS_KEYS) | {"grid", "set", "duration"}
MATRIX_KEYS = BLOCK_KEYS | {"name", "description"}
TOP_TABLES = {"matrix", "block", "exclude"}
REQUIRED_AXES = ("creatures", "bodies", "scenarios")
DEFAULT_GAIT = "default"
UNSUPPORTED = "unsupported combination"


@dataclass(frozen=True)
class MatrixCase:
    """One resolved case of a matrix and the axis values that produced it."""

    case: Case
    axes: dict[str, Any]  # creature, body, gait (resolved name), scenario, seed, and every grid key

    @property
    def label(self) -> str:
        a = self.axes
        grid = " ".join(f"{k}={v}" for k, v in a.items() if k not in ("creature", "body", "gait", "scenario", "seed"))
        seed = "" if a.get("seed") is None else f" seed={a['seed']}"
        return f"{a['creature']}/{a['body']}/{a['gait']}/{a['scenario']}{seed}" + (f" {grid}" if grid else "")


@dataclass(frozen=True)
class Unsupported:
    """A combination resolution rejected; listed before the run, never run."""

    creature: str
    body: str
    gait: str
    scenario: str
    reason: str

    def __str__(self) -> str:
        return f"{self.creature}/{self.body}/{self.gait}/{self.scenario}: {self.reason}"


@dataclass
class Expansion:
    """The cases of a matrix file, with what was left out and why."""

    name: str
    path: Path
    description: str
    cases: list[MatrixCase]
    unsupported: list[Unsupported]
    excluded: int = 0  # distinct cases removed by [[exclude]]
    duplicates: int = 0  # grid points that resolved to a case already in the matrix
    grid_keys: list[str] = field(default_factory=list)


# --------------------------------------------------------------------------- loading

def matrix_paths() -> dict[str, Path]:
    """Matrix name -> file, for ``scenarios/matrix/*.toml``."""
    d = scenarios_dir() / "matrix"
    return {p.stem: p for p in sorted(d.glob("*.toml"))} if d.is_dir() else {}


def locate_matrix(name_or_path: str) -> Path:
    """A matrix file from a path or a name in ``scenarios/matrix/``."""
    if not name_or_path.strip():
        raise InputError("matrix", None, "empty matrix name; give a .toml path or a name in scenarios/matrix/")
    p = check_path_text(name_or_path, "matrix")
    if p.suffix.lower() == ".toml" or os.path.lexists(p):
        return p
    known = matrix_paths()
    if name_or_path not in known:
        raise InputError("matrix", None, f"unknown matrix {name_or_path!r}{did_you_mean(name_or_path, known)}; "
                                         f"give a .toml path or one of "
                                         f"{', '.join(sorted(known)) or '(none found)'}")
    return known[name_or_path]


# --------------------------------------------------------------------------- how a matrix runs, where it writes
# The same checks for ``bench-myriapoda matrix`` and the Python API's ``run_matrix``, before anything runs.

MAX_WORKERS = 1024


def check_workers(workers: Any, flag: str) -> int | None:
    """``workers``: None (one per core) or a whole number 1 to ``MAX_WORKERS`` (a numpy integer too; not a
    bool, a float such as 1.5 or a string such as "2")."""
    import numbers

    if workers is None:
        return None
    if isinstance(workers, bool) or not isinstance(workers, numbers.Integral):
        raise InputError(flag, None, f"got {workers!r:.60} ({type(workers).__name__}); must be a whole number of "
                                     f"worker processes, 1 to {MAX_WORKERS}, or None for one per core")
    if not 1 <= int(workers) <= MAX_WORKERS:
        raise InputError(flag, None, f"{workers} is out of range; must be 1 to {MAX_WORKERS}")
    return int(workers)


def check_timeout_per_case(timeout: Any, flag: str) -> float | None:
    """``timeout``: None (no limit) or a finite number of seconds > 0.  Any finite size works (the pool
    waits an hour at a time); infinity is refused, as on the command line: None is "no limit"."""
    import numbers

    if timeout is None:
        return None
    if isinstance(timeout, bool) or not isinstance(timeout, numbers.Real):
        raise InputError(flag, None, f"got {timeout!r:.60} ({type(timeout).__name__}); must be a number of "
                                     "seconds > 0, or None for no limit")
    value = float(timeout)
    if not (math.isfinite(value) and value > 0):
        raise InputError(flag, None, f"{timeout} is out of range; must be a finite number of seconds > 0 (None for "
                                     "no limit)")
    return value


def check_matrix_outputs(out: Path | str, flag: str) -> Path:
    """A matrix output folder that can take ``results.sqlite``, ``matrix.json``, ``results.csv`` and
    ``series/``: not the file-system root, not an empty path,
    writable, its store absent or this suite's (``check_store``), each file a file.  Nothing is written.
    A caller that also writes the report checks its files too (``report.build.check_report_outputs``: the
    report sits above the harness)."""
    from .store import check_store, check_writable_dir

    out = check_path_text(out, flag)
    if out.exists() and not out.is_dir():
        raise InputError(flag, None, f"{out} exists and is not a directory")
    check_writable_dir(out, flag)
    check_store(out / "results.sqlite", flag)
    for name in ("matrix.json", "results.csv", "results.parquet"):
        if (out / name).exists() and not (out / name).is_file():
            raise InputError(flag, None, f"{out / name} exists and is not a file")
    if (out / "series").exists() and not (out / "series").is_dir():
        raise InputError(flag, None, f"{out / 'series'} exists and is not a directory")
    return out


def _check_list(src: str, key: str, value: Any, item_type: type | tuple) -> list:
    if not isinstance(value, list) or not value:
        raise InputError(src, key, f"expected a non-empty list, got {value!r}")
    for v in value:
        if isinstance(v, bool) and item_type is not bool or not isinstance(v, item_type):
            name = item_type.__name__ if isinstance(item_type, type) else " or ".join(t.__name__ for t in item_type)
            raise InputError(src, key, f"expected a list of {name}, got item {v!r}")
    return value


SCALARS = (bool, int, float, str)
MAX_GRID_POINTS = 100_000
# Cases of a whole matrix, counted from its blocks before any is resolved (resolution takes ~1 ms a case,
# a run seconds): 200,000 seeds or 200 blocks of 1,000 duplicate points are refused at once, not expanded.
MAX_MATRIX_CASES = 20_000
SAFE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}")


def _check_value(src: str, key: str, v: Any) -> None:
    """A value of ``set`` or ``grid``: what ``--set KEY=VALUE`` can carry (a scalar or a list of numbers)."""
    ok = isinstance(v, SCALARS) or (isinstance(v, list) and all(isinstance(x, (int, float)) for x in v))
    if not ok:
        raise InputError(src, key, f"expected a number, string, true/false or a list of numbers, got {v!r}")


def _check_name(src: str, key: str, name: Any) -> str:
    """A matrix name becomes a folder name (reports/matrix/NAME): one safe path component."""
    if not isinstance(name, str) or not SAFE_NAME.fullmatch(name) or set(name) == {"."}:
        raise InputError(src, key, f"{name!r} cannot name an output folder; use 1-100 letters, digits, '_', '.' "
                                   "or '-', starting with a letter, digit or '_'")
    return name


def _check_block(src: str, prefix: str, table: Any, allowed: set[str],
                 names: dict[str, list[str]] | None = None) -> dict[str, Any]:
    """Types and names of one ``[matrix]`` or ``[[block]]`` table; ``names``: the known names of each axis
    (``_axis_names``, read once per file, not once per block)."""
    if not isinstance(table, dict):
        raise InputError(src, prefix, "expected a table")
    for key in table:
        if key not in allowed:
            raise InputError(src, f"{prefix}.{key}", f"unknown key{did_you_mean(key, allowed)}; "
                                                     f"allowed: {', '.join(sorted(allowed))}")
    out = dict(table)
    for key in ("creatures", "bodies", "gaits", "scenarios"):
        if key in out:
            _check_list(src, f"{prefix}.{key}", out[key], str)
    if "seeds" in out:
        _check_list(src, f"{prefix}.seeds", out["seeds"], int)
        if any(s < 0 for s in out["seeds"]):
            raise InputError(src, f"{prefix}.seeds", "seeds must be >= 0")
    if "duration" in out:
        d = out["duration"]
        if isinstance(d, bool) or not isinstance(d, (int, float)) or not d > 0:
            raise InputError(src, f"{prefix}.duration", f"expected a number of seconds > 0, got {d!r}")
    for key in ("name", "description"):
        if key in out and not isinstance(out[key], str):
            raise InputError(src, f"{prefix}.{key}", f"expected a string, got {out[key]!r}")
    for kind in ("set", "grid"):  # "dt " and "dt" would both set dt, one silently winning
        for k in out.get(kind, {}) if isinstance(out.get(kind), dict) else ():
            if k != k.strip() or not k:
                raise InputError(src, f"{prefix}.{kind}.{k!r}", "a key with leading or trailing spaces (or "
                                                               "empty); write it without them")
    if "set" in out:
        if not isinstance(out["set"], dict):
            raise InputError(src, f"{prefix}.set", "expected a table of dotted keys and values")
        for k, v in out["set"].items():
            _check_value(src, f"{prefix}.set.{k}", v)
    if "grid" in out:
        if not isinstance(out["grid"], dict) or not out["grid"]:
            raise InputError(src, f"{prefix}.grid", "expected a table of dotted keys and lists of values")
        for k, v in out["grid"].items():
            if not isinstance(v, list) or not v:
                raise InputError(src, f"{prefix}.grid.{k}", f"expected a non-empty list of values, got {v!r}")
            for item in v:
                _check_value(src, f"{prefix}.grid.{k}", item)
        points = math.prod(len(v) for v in out["grid"].values())
        if points > MAX_GRID_POINTS:
            raise InputError(src, f"{prefix}.grid", f"{points:,} grid points; at most {MAX_GRID_POINTS:,}")
    if "name" in out:
        _check_name(src, f"{prefix}.name", out["name"])
    names = names or _axis_names()
    for key, known in names.items():
        for v in out.get(key, ()):
            if v not in known and not (key in ("creatures", "scenarios") and v.lower().endswith(".toml")):
                raise InputError(src, f"{prefix}.{key}", f"unknown {AXIS_KEYS[key]} {v!r}{did_you_mean(v, known)}; "
                                                         f"choose one of {', '.join(known)}")
    return out


def _axis_names() -> dict[str, list[str]]:
    """The names each axis may take: creatures, bodies, gaits (and "default"), scenarios."""
    registry.load_all()
    return {"creatures": creature_names(), "bodies": sorted(registry.BODIES),
            "gaits": sorted(registry.GAITS) + [DEFAULT_GAIT], "scenarios": sorted(scenario_paths())}


def _precount(src: str, data: dict[str, Any]) -> None:
    """The case count of the raw tables, before any block is checked in detail: a matrix of 20,001 blocks or
    seeds is refused at once (checking each block first took seconds per thousand).  A value that is not a
    list counts as one here; the checks that follow name it."""
    def size(v: Any) -> int:
        return len(v) if isinstance(v, list) else 1

    base = data.get("matrix") if isinstance(data.get("matrix"), dict) else {}
    raw = data.get("block") or [None]
    if not isinstance(raw, list):
        return
    total = 0
    for b in raw:
        blk = {**base, **(b if isinstance(b, dict) else {})}
        grid = blk.get("grid") if isinstance(blk.get("grid"), dict) else {}
        n = math.prod(size(blk.get(k)) for k in ("creatures", "bodies", "gaits", "scenarios", "seeds"))
        total += n * math.prod(size(v) for v in grid.values())
        if total > MAX_MATRIX_CASES:
            raise InputError(src, "matrix", f"more than {MAX_MATRIX_CASES:,} cases (every block's product of "
                                            "creatures, bodies, gaits, scenarios, seeds and grid values, before "
                                            "exclusions and duplicates): split the matrix into several files")


def load_matrix(path: Path | str) -> dict[str, Any]:
    """Read and type-check a matrix file; returns ``{"name", "description", "blocks", "exclude"}``.

    Each block is a complete set of axes (``[matrix]``'s keys filled in).
    Raises :class:`InputError` naming the file and the key.
    """
    path = Path(path)
    src = str(path)
    data = read_tables(path, TOP_TABLES, "matrix")
    _precount(src, data)
    names = _axis_names()
    base = _check_block(src, "matrix", data["matrix"], MATRIX_KEYS, names)
    raw_blocks = data.get("block", [])
    if not isinstance(raw_blocks, list):
        raise InputError(src, "block", "expected an array of tables [[block]]")
    blocks = []
    shared = {k: v for k, v in base.items() if k in BLOCK_KEYS}
    for i, b in enumerate(raw_blocks or [None]):
        blk = dict(shared) if b is None else {**shared, **_check_block(src, f"block[{i}]", b, BLOCK_KEYS, names)}
        prefix = "matrix" if b is None else f"block[{i}]"
        for key in REQUIRED_AXES:
            if key not in blk:
                raise InputError(src, f"{prefix}.{key}", "missing axis (give it in [matrix] or in the block)")
        blk.setdefault("gaits", [DEFAULT_GAIT])
        blk["_prefix"] = prefix
        blocks.append(blk)
    _check_case_count(src, blocks)
    excludes = data.get("exclude", [])
    if not isinstance(excludes, list) or not all(isinstance(e, dict) and e for e in excludes):
        raise InputError(src, "exclude", "expected an array of non-empty tables [[exclude]]")
    axis_names = set(AXIS_KEYS.values()) | {k for b in blocks for k in b.get("grid", {})}
    for i, e in enumerate(excludes):
        for k, want in e.items():
            if k not in axis_names:
                raise InputError(src, f"exclude[{i}].{k}", f"not an axis of this matrix; axes: {', '.join(sorted(axis_names))}")
            _check_exclude_value(src, f"exclude[{i}].{k}", k, want, blocks)
    name = base.get("name", path.stem)
    _check_name(src, "matrix.name" if "name" in base else "matrix (file name)", name)
    return {"name": name, "description": base.get("description", ""), "blocks": blocks, "exclude": excludes}


def _check_case_count(src: str, blocks: list[dict]) -> None:
    """The matrix's grid points (before exclusions and duplicates) are at most ``MAX_MATRIX_CASES``."""
    total = 0
    for blk in blocks:
        n = math.prod(len(blk.get(k, [None])) for k in ("creatures", "bodies", "gaits", "scenarios", "seeds"))
        total += n * math.prod(len(v) for v in blk.get("grid", {}).values())
    if total > MAX_MATRIX_CASES:
        raise InputError(src, "matrix", f"{total:,} cases (every block's product of creatures, bodies, gaits, "
                                        f"scenarios, seeds and grid values, before exclusions and duplicates); "
                                        f"at most {MAX_MATRIX_CASES:,}: split the matrix into several files")


def _check_exclude_value(src: str, key: str, axis: str, want: Any, blocks: list[dict]) -> None:
    """An [[exclude]] value: of the axis's type (a name, a seed, a grid value), or a non-empty list of them."""
    options = want if isinstance(want, list) else [want]
    if not options:
        raise InputError(src, key, "expected a value or a non-empty list of values, got []")
    if axis in ("creature", "body", "gait", "scenario"):
        kind, ok = "a name (string)", all(isinstance(o, str) for o in options)
    elif axis == "seed":
        kind, ok = "an integer seed", all(isinstance(o, int) and not isinstance(o, bool) for o in options)
    else:
        values = [v for b in blocks for v in b.get("grid", {}).get(axis, [])]
        types = {type(v) for v in values if not isinstance(v, list)}
        numeric = types and types <= {int, float}
        kind = "a number" if numeric else ("a value like " + ", ".join(sorted({repr(v) for v in values})[:3]))
        ok = all(isinstance(o, SCALARS) and (not numeric or (isinstance(o, (int, float)) and not isinstance(o, bool)))
                 and (numeric or type(o) in types) for o in options)
    if ok and any(isinstance(o, float) and not math.isfinite(o) for o in options):
        kind, ok = "a finite number", False  # NaN matches nothing; inf no grid value
    if not ok:
        raise InputError(src, key, f"expected {kind} (or a list of them), got {want!r}")


# --------------------------------------------------------------------------- expansion

def _toml_value(v: Any) -> str:
    """A value as TOML text, the form ``--set KEY=VALUE`` reads."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if not (isinstance(v, float) and math.isinf(v)) else ("inf" if v > 0 else "-inf")
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {v!r} as TOML")


def _matches(rule: dict[str, Any], axes: dict[str, Any]) -> bool:
    for k, want in rule.items():
        have = axes.get(k)
        options = want if isinstance(want, list) else [want]
        if not any(have == w and isinstance(have, bool) == isinstance(w, bool) for w in options):
            return False
    return True


def _body_fields(body: str) -> set[str]:
    return {f.name for f in dataclasses.fields(registry.BODIES[body].config_cls)}


def expand_matrix(path: Path | str) -> Expansion:
    """Load ``path`` and resolve every case of its product (see the module docstring)."""
    path = Path(path)
    src = str(path)
    spec = load_matrix(path)
    cases: list[MatrixCase] = []
    unsupported: dict[tuple, Unsupported] = {}
    seen: set[str] = set()
    excluded: set[str] = set()  # hashes of excluded cases, so a duplicate is not counted twice
    duplicates = 0
    grid_keys: list[str] = []
    for blk in spec["blocks"]:
        prefix = blk["_prefix"]
        grid: dict[str, list] = blk.get("grid", {})
        fixed: dict[str, Any] = blk.get("set", {})
        grid_keys += [k for k in grid if k not in grid_keys]
        # a body.* key must belong to some body model of the block; bodies without it are unsupported
        for kind, table in (("grid", grid), ("set", fixed)):
            for key in table:
                if key.startswith("body.") and not any(key[5:] in _body_fields(b) for b in blk["bodies"]):
                    raise InputError(src, f"{prefix}.{kind}.{key}", f"unknown key for body models "
                                                                    f"{', '.join(blk['bodies'])}")
        seeds = blk.get("seeds", [None])
        grid_items = list(grid.items())
        for creature, body, gait, scenario, seed in itertools.product(
                blk["creatures"], blk["bodies"], blk["gaits"], blk["scenarios"], seeds):
            for values in itertools.product(*(v for _, v in grid_items)):
                point = dict(zip((k for k, _ in grid_items), values))
                gait_arg = None if gait == DEFAULT_GAIT else gait
                missing = [k for k in list(fixed) + list(point) if k.startswith("body.") and k[5:] not in _body_fields(body)]
                if missing:
                    u = Unsupported(creature, body, gait, scenario, f"{UNSUPPORTED}: body {body!r} has no key "
                                                                    f"{', '.join(missing)}")
                    unsupported.setdefault((creature, body, gait, scenario, u.reason), u)
                    continue
                overrides = [f"{k}={_toml_value(v)}" for k, v in {**fixed, **point}.items()]
                try:
                    case = resolve_case(creature, body, scenario, gait_arg, duration=blk.get("duration"),
                                        seed=seed, overrides=overrides)
                except InputError as exc:
                    if UNSUPPORTED in exc.message:
                        u = Unsupported(creature, body, gait, scenario, exc.message)
                        unsupported.setdefault((creature, body, gait, scenario, exc.message), u)
                        continue
                    raise _in_file(exc, src, prefix, grid, fixed) from None
                axes = {"creature": creature, "body": body, "gait": case.gait.name, "scenario": scenario,
                        "seed": seed, **point}
                h = case.case_hash()
                if h in seen or h in excluded:
                    duplicates += 1
                    continue
                if any(_matches(rule, axes) for rule in spec["exclude"]):
                    excluded.add(h)
                    continue
                seen.add(h)
                cases.append(MatrixCase(case, axes))
    return Expansion(spec["name"], path, spec["description"], cases, list(unsupported.values()), len(excluded),
                     duplicates, grid_keys)


def _in_file(exc: InputError, src: str, prefix: str, grid: dict, fixed: dict) -> InputError:
    """Re-attribute an error of resolution to the matrix file and the key that caused it."""
    flag_axes = {"--creature": "creatures", "--body": "bodies", "--gait": "gaits", "--scenario": "scenarios",
                 "--seed": "seeds", "--duration": "duration"}
    if exc.source.startswith("--"):
        key = exc.key or exc.source.lstrip("-")
        if key in grid:
            key = f"{prefix}.grid.{key}"
        elif key in fixed:
            key = f"{prefix}.set.{key}"
        else:
            key = f"{prefix}.{flag_axes.get(exc.source, key)}"
        return InputError(src, key, exc.message)
    return exc  # an error inside a creature or scenario file already names that file


# --------------------------------------------------------------------------- manifest

MANIFEST = "matrix.json"


def write_matrix_manifest(out_dir: Path, exp: Expansion) -> Path:
    """Write ``out_dir/matrix.json``: the matrix's name, description, grid keys, and each case's axes.

    The report reads it to know which axis values produced each stored case (the store keeps the
    resolved configuration, not the grid point that led to it).  Written atomically before any case runs.
    """
    import os
    import tempfile

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    doc = {"name": exp.name, "description": exp.description, "file": str(exp.path), "grid_keys": exp.grid_keys,
           "cases": {m.case.case_hash(): {"label": m.label, "axes": m.axes} for m in exp.cases},
           "unsupported": [str(u) for u in exp.unsupported]}
    fd, tmp = tempfile.mkstemp(suffix=".json", dir=out_dir)
    with os.fdopen(fd, "w") as fh:
        json.dump(doc, fh, indent=1, sort_keys=True)
    path = out_dir / MANIFEST
    os.replace(tmp, path)
    return path
