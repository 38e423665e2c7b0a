"""The Python API: run cases and matrices, and read results into pandas, from a script or a notebook.

    import bench_myriapoda as bm

    r = bm.run("worm", "massspring", "flat", duration=5.0, friction__mu_transverse=0.2)
    r.metrics["speed_m_per_s"], r.status, r.series_frame()
    df = bm.load_results("reports/results.sqlite")     # one row per run, one column per metric

A case is resolved exactly as the command line resolves it (:func:`core.config.resolve_case`):
the same names, files, layers and checks, and bad input raises
:class:`core.errors.InputError` with the message the CLI prints.
"""
from __future__ import annotations

import html
import json
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from .core.config import Case, resolve_case
from .core.errors import InputError

AXES = ("creature", "body", "gait", "scenario", "seed")


# --------------------------------------------------------------------------- overrides

def _toml_text(v: Any, key: str) -> str:
    """A Python value as the TOML text ``--set KEY=VALUE`` reads."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool):
        v = v.item() if isinstance(v, np.generic) else v
        if isinstance(v, float) and not math.isfinite(v):
            return "nan" if v != v else ("inf" if v > 0 else "-inf")
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_text(x, key) for x in list(v)) + "]"
    raise InputError("set", key, f"cannot use a {type(v).__name__} as a configuration value: {v!r}")


def override_items(set: Mapping[str, Any] | None = None, **overrides: Any) -> list[str]:
    """``KEY=VALUE`` strings for :func:`resolve_case` from a dict of dotted keys and ``section__key`` keywords."""
    items: dict[str, Any] = dict(set or {})
    for k, v in overrides.items():
        items[k.replace("__", ".")] = v
    return [f"{k}={_toml_text(v, k)}" for k, v in items.items()]


# --------------------------------------------------------------------------- one run

class Series:
    """A run's time series as numpy arrays (T samples at ``record.sample_hz``).

    ``t`` (T,) [s]; ``com``, ``head``, ``tail`` (T, 3) [m] (x forward, y up, z right);
    ``segment_centers`` (T, n_seg, 3) [m], segment 0 the head; ``energy`` (T, 3) [J]:
    kinetic, elastic, gravitational; ``nodes`` (T, n_nodes, 3) [m] with ``keep_nodes=True``, else None;
    ``segment_positions`` (T, n, 3) [m], ``segment_rotations`` (T, n, 3, 3) and ``segment_contact`` (T, n)
    of the body's segments (``core.series.Series``).
    """

    ENERGY = ("kinetic_j", "elastic_j", "gravitational_j")

    def __init__(self, series):
        self._s = series
        for name in ("t", "com", "head", "tail", "segment_centers", "energy", "nodes", "segment_positions",
                     "segment_rotations", "segment_contact"):
            setattr(self, name, getattr(series, name))

    def __len__(self) -> int:
        return len(self.t)

    def to_dataframe(self):
        """One row per sample: ``t_s``, ``com_{x,y,z}_m``, ``head_*_m``, ``tail_*_m``, ``kinetic_j``,
        ``elastic_j``, ``gravitational_j``."""
        import pandas as pd

        cols: dict[str, np.ndarray] = {"t_s": np.asarray(self.t)}
        for name in ("com", "head", "tail"):
            a = np.asarray(getattr(self, name))
            for i, ax in enumerate("xyz"):
                cols[f"{name}_{ax}_m"] = a[:, i]
        e = np.asarray(self.energy)
        for i, name in enumerate(self.ENERGY):
            cols[name] = e[:, i]
        return pd.DataFrame(cols)

    def __repr__(self) -> str:
        return f"<Series: {len(self)} samples over {self.t[-1] if len(self) else 0:.3g} s>"


@dataclass
class Result:
    """One run: ``status`` (``ok``, ``unstable``, ``error``), ``metrics``, ``timings``, ``labels``,
    the resolved ``case``, the time ``series`` and, when stored, the store's ``run_id``."""

    raw: Any  # harness.runner.RunResult
    run_id: int | None = None
    unstored: str | None = None  # why ``store`` could not take the run, and which file keeps it (run_id is None)

    @property
    def case(self) -> Case:
        return self.raw.case

    @property
    def status(self) -> str:
        return self.raw.status

    @property
    def message(self) -> str:
        return self.raw.message

    @property
    def metrics(self) -> dict[str, float]:
        return self.raw.metrics

    @property
    def timings(self) -> dict[str, float]:
        return self.raw.timings

    @property
    def labels(self) -> dict[str, str]:
        """Names of coded metrics, e.g. ``{"brain_mode_final": "WALK"}`` (legged creatures)."""
        return dict(self.raw.extra.get("labels", {}))

    @property
    def traceback(self) -> str | None:
        """The traceback of a run that ended with status ``error``."""
        return self.raw.extra.get("traceback")

    @property
    def series(self) -> Series | None:
        """The time series; None when the run failed before its first sample."""
        return None if self.raw.series is None else Series(self.raw.series)

    def series_frame(self):
        """The time series as a pandas DataFrame (:meth:`Series.to_dataframe`)."""
        if self.raw.series is None:
            raise ValueError(f"no time series: the run ended with status {self.status} ({self.message})")
        return Series(self.raw.series).to_dataframe()

    def to_dict(self) -> dict[str, Any]:
        """What ``bench-myriapoda run --json`` prints."""
        return self.raw.to_json_dict()

    def _title(self) -> str:
        c = self.case
        return f"{c.creature.name} / {c.body.name} / {c.gait.name} / {c.scenario.name}"

    def _speed_text(self) -> str:
        """``speed X m/s``; when there is no number, why: the run was too short for its steady cycles (the
        reason the runner put in the labels), it blew up or failed (its message), or no speed is defined."""
        speed = self.metrics.get("speed_m_per_s", float("nan"))
        if isinstance(speed, (int, float)) and math.isfinite(speed):
            return f"speed {speed:.4g} m/s"
        too_short = self.labels.get("too_short")
        if too_short:
            return f"no speed: {too_short}"
        if self.status != "ok" and self.message:
            return f"no speed: {self.message}"
        return "no speed measured"

    def __repr__(self) -> str:
        return f"<Result {self._title()}: {self.status}, {self.timings.get('steps', 0)} steps, {self._speed_text()}>"

    def _repr_html_(self) -> str:
        """A notebook's view: the case, status, timings and every metric (labels for coded ones)."""
        def cell(v):
            if isinstance(v, float):
                return "-" if not math.isfinite(v) else f"{v:.4g}"
            return html.escape(str(v))

        c = self.case
        labels = self.labels
        rows = "".join(f"<tr><td>{html.escape(k)}</td><td>{cell(labels.get(k, v))}</td></tr>"
                       for k, v in sorted(self.metrics.items()))
        t = self.timings
        msg = f" ({html.escape(self.message)})" if self.message else ""
        if self.labels.get("too_short"):  # why the locomotion metrics below are blank
            msg += f"<br>locomotion metrics blank: {html.escape(self.labels['too_short'])}"
        return (f"<div><b>{html.escape(self._title())}</b> &mdash; status <b>{html.escape(self.status)}</b>{msg}<br>"
                f"dt {c.dt:.3g} s, duration {c.duration:.3g} s, seed {c.seed}, case {c.case_hash()}<br>"
                f"{t.get('steps', 0)} steps, {cell(t.get('steps_per_s'))} steps/s, realtime x{cell(t.get('realtime_factor'))}, "
                f"compile {cell(t.get('compile_s'))} s, wall {cell(t.get('wall_s'))} s"
                f"<table><tr><th>metric</th><th>value</th></tr>{rows}</table></div>")


def resolve(creature: str | os.PathLike, body: str, scenario: str | os.PathLike, gait: str | None = None,
            duration: float | None = None, dt: float | None = None, seed: int | None = 0,
            set: Mapping[str, Any] | None = None, **overrides: Any) -> Case:
    """The resolved :class:`Case` :func:`run` would simulate (nothing runs)."""
    a = _checked_case_arguments(creature, body, scenario, gait, duration, dt, seed, set)
    return resolve_case(a["creature"], a["body"], a["scenario"], a["gait"], duration=a["duration"], dt=a["dt"],
                        seed=a["seed"], overrides=override_items(a["set"], **overrides))


# --------------------------------------------------------------------------- argument checks
# The API takes what the command line's flags take, typed: each wrong type is an InputError naming the
# argument and what is allowed, before anything is resolved or run (a number where a name goes would
# otherwise end in an AttributeError deep in the resolver).

def _got(value: Any) -> str:
    """``got 123 (int)``: the value (cut short) and its type, for a message."""
    shown = repr(value)
    return f"got {shown if len(shown) <= 60 else shown[:57] + '...'} ({type(value).__name__})"


def _file_or_name(value: Any, arg: str) -> str:
    """A creature or scenario: a name, or a ``.toml`` path as a str or ``os.PathLike`` (``pathlib.Path``)."""
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if isinstance(value, bytes):
        value = os.fsdecode(value)
    if not isinstance(value, str):
        raise InputError(arg, None, f"{_got(value)}; give a name (a str) or a .toml path (a str or "
                                    "pathlib.Path)")
    return value


def _name(value: Any, arg: str, optional: bool = False) -> str | None:
    """A body model or gait: a name (a str); None where the argument has a default."""
    if value is None and optional:
        return None
    if not isinstance(value, str):
        allowed = "a name (a str)" + (" or None for the default" if optional else "")
        raise InputError(arg, None, f"{_got(value)}; give {allowed}")
    return value


def _real(value: Any, arg: str, what: str) -> float | None:
    """A number (int, float, numpy scalar; not a bool) as a float, or None."""
    import numbers

    if value is None:
        return None
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise InputError(arg, None, f"{_got(value)}; give {what} (a number) or None")
    return float(value)


def _whole(value: Any, arg: str, what: str) -> int | None:
    """A whole number (int, numpy integer; not a bool or a float) as an int, or None."""
    import numbers

    if value is None:
        return None
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise InputError(arg, None, f"{_got(value)}; give {what} (a whole number) or None")
    return int(value)


def _flag(value: Any, arg: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise InputError(arg, None, f"{_got(value)}; give True or False")
    return bool(value)


def _checked_case_arguments(creature, body, scenario, gait, duration, dt, seed, set) -> dict[str, Any]:
    if set is not None and not isinstance(set, Mapping):
        raise InputError("set", None, f"{_got(set)}; give a dict of dotted keys and values, e.g. "
                                      "set={\"friction.mu_transverse\": 0.2}")
    return {"creature": _file_or_name(creature, "creature"), "body": _name(body, "body"),
            "scenario": _file_or_name(scenario, "scenario"), "gait": _name(gait, "gait", optional=True),
            "duration": _real(duration, "duration", "a duration in seconds"),
            "dt": _real(dt, "dt", "a time step in seconds"), "seed": _whole(seed, "seed", "a seed"), "set": set}


def _checked_store(store: Any):
    """``store``: None, or a path (str or ``os.PathLike``) that ``check_store`` lets through: absent, empty or
    this suite's store, writable, not locked, not damaged; checked before the run, as ``run --store``."""
    if store is None:
        return None
    if isinstance(store, os.PathLike):
        store = os.fspath(store)
    if isinstance(store, bytes):
        store = os.fsdecode(store)
    if not isinstance(store, str):
        raise InputError("store", None, f"{_got(store)}; give a path to a SQLite results file (a str or "
                                        "pathlib.Path) or None")
    if not store.strip():
        raise InputError("store", None, "empty path; give a path to a SQLite results file, or None not to store")
    from .harness.store import check_store

    return check_store(store, "store")


def _check_budget(case: Case, source: str, force: bool, memory_budget: Any, max_steps: Any,
                  keep_nodes: bool) -> None:
    """The command line's resource budget (``--max-steps``, ``--memory-budget``, ``--force``), as keywords."""
    from .core.feasibility import check_budget

    force = _flag(force, "force")
    gb = _real(memory_budget, "memory_budget", "a memory budget in GB")
    steps = _real(max_steps, "max_steps", "a number of steps")
    if gb is not None and not (math.isfinite(gb) and gb > 0):
        raise InputError("memory_budget", None, f"{memory_budget} is out of range; must be a number of GB > 0")
    if steps is not None and not (math.isfinite(steps) and steps >= 1):
        raise InputError("max_steps", None, f"{max_steps} is out of range; must be a number >= 1")
    if force:
        n = case.duration / case.dt
        if not math.isfinite(n) or n > 2 ** 62:
            raise InputError(source, None, f"duration {case.duration:g} s / dt {case.dt:g} s: too many steps to "
                                           "count, even with force=True")
        return
    try:
        check_budget(case, source, None if gb is None else gb * 1e9, steps, keep_nodes)
    except InputError as exc:  # the same refusal, in the API's words
        msg = (exc.message.replace("(--max-steps)", "(max_steps=)").replace("(--memory-budget)", "(memory_budget=)")
               .replace("pass --force", "pass force=True"))
        raise InputError(exc.source, exc.key, msg) from None


def run(creature: str | os.PathLike, body: str, scenario: str | os.PathLike, gait: str | None = None,
        duration: float | None = None, dt: float | None = None, seed: int | None = 0, controller: Any = None,
        store: str | os.PathLike | None = None, *, set: Mapping[str, Any] | None = None, keep_nodes: bool = False,
        force: bool = False, memory_budget: float | None = None, max_steps: float | None = None,
        **overrides: Any) -> Result:
    """Run one case and return its :class:`Result`.

    ``creature``, ``scenario``: a name (``models/NAME.toml``, ``scenarios/NAME.toml``) or a ``.toml`` path;
    ``body``: a body model; ``gait``: default the creature's; ``duration`` [s], ``dt`` [s], ``seed``: as the
    CLI's flags.  Any other configuration key: ``set={"friction.mu_transverse": 0.2}`` or a keyword with
    ``__`` for the dot, ``friction__mu_transverse=0.2`` (``bench-myriapoda keys`` lists them).
    ``controller``: handed to ``run_case`` to drive the body instead of the gait's own controller.
    ``store``: a results database to record the run in (as ``command = 'api'``); default: not stored.
    ``keep_nodes``: also record every node position (``result.series.nodes``).
    ``max_steps``, ``memory_budget`` [GB], ``force``: the resource budget, as ``--max-steps``,
    ``--memory-budget`` and ``--force``: by default a case over 1e9 steps or half the memory is refused.

    Raises :class:`InputError` for bad input, before anything runs: a wrong type (``run(123)``, a list
    as ``body``), a bad name or value, a case over the budget, a ``store`` that is not this suite's
    results store (another program's database, a damaged or locked one, a directory, a read-only or
    full file system).  A failure during the run is status ``error`` with ``result.message`` and
    ``result.traceback``.  When ``store`` fails after the run (the disk filled, the file was replaced),
    the result is still returned, with ``run_id`` None and ``unstored`` saying why and naming the JSON
    file in ``unsaved/`` beside the store that keeps it; a ``RuntimeWarning`` says the same.
    """
    from .harness.runner import run_case

    case = resolve(creature, body, scenario, gait, duration, dt, seed, set, **overrides)
    keep_nodes = _flag(keep_nodes, "keep_nodes")
    _check_budget(case, "run", force, memory_budget, max_steps, keep_nodes)
    store_path = _checked_store(store)
    kwargs: dict[str, Any] = {"keep_nodes": keep_nodes}
    if controller is not None:
        kwargs["controller"] = controller
    raw = run_case(case, **kwargs)
    if store_path is None:
        return Result(raw)
    return _stored(raw, store_path)


def _stored(raw, store: Path) -> Result:
    """``raw`` recorded in ``store``; when the insert fails after the run, the result kept in memory and in a
    fallback file (``unsaved/`` beside the store, else the temporary folder), as the command line keeps it."""
    import warnings

    from .harness.store import UnstoredError, record_run, store_or_keep

    try:
        return Result(raw, store_or_keep(store, "run", lambda: record_run(store, raw, command="api"),
                                         raw.to_json_dict))
    except UnstoredError as exc:
        warnings.warn(str(exc), RuntimeWarning, stacklevel=3)
        return Result(raw, None, str(exc))


# --------------------------------------------------------------------------- matrices

def run_matrix(file_or_name: str | os.PathLike, out: str | os.PathLike | None = None, workers: int | None = None, *,
               executor: str = "local", scheduler: str | None = None, resume: bool = False,
               timeout_per_case: float | None = None, report: bool = False, progress: bool = False,
               force: bool = False, memory_budget: float | None = None, max_steps: float | None = None):
    """Run a scenario matrix (a ``.toml`` path or a name in ``scenarios/matrix/``); return :func:`load_results`
    of its output directory.

    ``out`` (default ``reports/matrix/NAME``) receives ``results.sqlite``, ``matrix.json`` and
    ``series/``, as ``bench-myriapoda matrix FILE --out DIR`` writes them; ``report=True`` also writes
    ``index.html`` and ``summary.md``.  ``executor``: ``local`` (a process pool of ``workers``) or
    ``dask`` (``scheduler`` address, default a LocalCluster); ``resume`` runs only the cases not yet
    stored; ``timeout_per_case`` [s], any finite number > 0 (None: no limit); ``progress``: a progress bar
    on stderr.  ``max_steps``, ``memory_budget`` [GB], ``force``: each case's resource budget, as
    :func:`run`'s.

    Raises :class:`InputError` before anything runs or is written for a wrong type (``workers="2"``,
    ``workers=1.5``), a bad matrix file, a case over the budget, or an ``out`` that cannot take the results:
    ``""``, the file-system root, a file, a read-only folder, a ``results.sqlite`` there that is not this
    suite's store.
    """
    from .harness.executors import EXECUTORS, run_matrix as run_cases
    from .harness.matrix import (check_matrix_outputs, check_timeout_per_case, check_workers, expand_matrix,
                                 locate_matrix, write_matrix_manifest)
    from .harness.progress import MatrixProgress

    file_or_name = _file_or_name(file_or_name, "file_or_name")
    workers = check_workers(workers, "workers")
    if not isinstance(executor, str) or executor not in EXECUTORS:
        raise InputError("executor", None, f"{executor!r} is not allowed; choose one of {', '.join(EXECUTORS)}")
    timeout_per_case = check_timeout_per_case(timeout_per_case, "timeout_per_case")
    resume, report, progress = _flag(resume, "resume"), _flag(report, "report"), _flag(progress, "progress")
    if scheduler is not None and not isinstance(scheduler, str):
        raise InputError("scheduler", None, f"{_got(scheduler)}; give an address such as 'tcp://host:8786' or "
                                            "None")
    if out is not None:
        out = _file_or_name(out, "out")
        if not out.strip():
            raise InputError("out", None, "empty path; give a folder, or None for reports/matrix/NAME")
    if executor == "dask":
        try:
            import dask.distributed  # noqa: F401
        except ImportError:
            raise InputError("executor", None, "dask is not installed; pip install 'bench-myriapoda[dask]'") from None
    exp = expand_matrix(locate_matrix(file_or_name))
    out = check_matrix_outputs(out if out is not None else Path("reports") / "matrix" / exp.name, "out")
    if report:
        from .report.build import check_report_outputs
        check_report_outputs(out)
    if not exp.cases:
        raise InputError(str(exp.path), None, "no case left to run after exclusions and unsupported combinations")
    for m in exp.cases:  # the command line's budget, each case (its body's own limits make an error row, as there)
        _check_budget(m.case, f"{exp.path}: case {m.label}", force, memory_budget, max_steps, False)
    write_matrix_manifest(out, exp)
    labels = {m.case.case_hash(): m.label for m in exp.cases}
    bar = MatrixProgress(progress, len(exp.cases), label=f"matrix {exp.name}")
    try:
        run_cases([m.case for m in exp.cases], executor=executor, workers=workers, scheduler=scheduler,
                  timeout_per_case=timeout_per_case, store_path=out / "results.sqlite", matrix=exp.name,
                  resume=resume, series_dir=out / "series",
                  on_result=lambda r, done, total: bar.case_done(labels[r.case.case_hash()], r.status, r.message))
    finally:
        bar.close()
    if report:
        from .harness.store import DEFAULT_STORE
        from .report.build import build_report

        build_report(out, history_store=DEFAULT_STORE)
    return load_results(out)


# --------------------------------------------------------------------------- results

def _flatten_case(case: dict[str, Any]) -> dict[str, Any]:
    """``{"friction.mu_transverse": 0.5, ..., "dt": 0.001}`` from ``Case.to_dict()`` (lists as tuples)."""
    flat = {}
    for k, v in case.items():
        if isinstance(v, dict):
            for kk, vv in v.items():
                flat[f"{k}.{kk}"] = tuple(vv) if isinstance(vv, list) else vv
        else:
            flat[k] = tuple(v) if isinstance(v, list) else v
    return flat


def _swept_keys(flat: list[dict[str, Any]], groups: list[tuple]) -> list[str]:
    """Configuration keys whose value differs between runs of the same (creature, body, gait, scenario).

    Keys that differ only because the creature or body model differs are not "swept".
    """
    by_group: dict[tuple, list[dict]] = {}
    for g, f in zip(groups, flat):
        by_group.setdefault(g, []).append(f)
    keys: list[str] = []
    for rows in by_group.values():
        for k in rows[0]:
            if k in keys or k.endswith(".name") or k in ("seed",):
                continue
            if len({repr(r.get(k)) for r in rows}) > 1:
                keys.append(k)
    return keys


# What a stored run is, for averaging (``load_results``' ``run_kind``): a headline run measures the case as
# configured; a sweep run is one grid point of a stability or scaling sweep (or a stable-dt search); an
# unstable run blew up (its metrics stop at t_fail); a failed run ended in an error or a timeout.
RUN_KINDS = ("headline", "sweep", "unstable", "failed")


def _sibling_manifest(store: Path) -> dict | None:
    """The ``matrix.json`` next to a store (a matrix directory's ``results.sqlite``), or None."""
    from .harness.matrix import MANIFEST

    f = store.parent / MANIFEST
    try:
        doc = json.loads(f.read_text()) if f.is_file() else None
        return doc if isinstance(doc, dict) and isinstance(doc.get("cases"), dict) else None
    except (OSError, ValueError):
        return None


def _run_kinds(runs, flat: list[dict[str, Any]], cases: list[dict[str, Any]], manifest: dict | None) -> list[str]:
    """``RUN_KINDS`` of each row of ``runs`` (the store's rows, ``flat``: their flattened configurations).

    The status decides first (``unstable``; ``error`` and ``timeout`` are ``failed``).  Then: a ``stable-dt``
    row is a sweep (a dt search); a ``matrix`` row is a sweep when its grid point sets a grid key (the
    manifest's axes beyond creature, body, gait, scenario and seed: how ``report`` tells sweeps from
    headline cases) and a headline case otherwise.  Without the manifest of its matrix, a ``matrix`` row
    is a sweep when another row of the same matrix, creature, body, gait, scenario and duration differs
    from it in a configuration key other than the seed (a grid point among others); ``run`` and ``api``
    rows are headline runs.
    """
    by_group: dict[tuple, set[str]] = {}
    keys = []
    for (_, r), c, f in zip(runs.iterrows(), cases, flat):
        k = (r.matrix, *(c[a]["name"] for a in AXES[:4]), c.get("duration"))
        keys.append(k)
        if r.command == "matrix":
            by_group.setdefault(k, set()).add(json.dumps({x: v for x, v in f.items() if x != "seed"},
                                                         sort_keys=True, default=str))
    out = []
    for (_, r), k in zip(runs.iterrows(), keys):
        if r.status == "unstable":
            out.append("unstable")
        elif r.status != "ok":
            out.append("failed")
        elif r.command == "stable-dt":
            out.append("sweep")
        elif r.command != "matrix":
            out.append("headline")
        elif manifest is not None and r.matrix == manifest.get("name") and r.case_hash in manifest["cases"]:
            axes = manifest["cases"][r.case_hash].get("axes", {})
            out.append("sweep" if any(a not in AXES for a in axes) else "headline")
        else:
            out.append("sweep" if len(by_group.get(k, ())) > 1 else "headline")
    return out
# --------------------------------------------------------------------------- reading what a matrix or a store holds
# A matrix directory or a store may have been damaged or written by something else: each part is checked for
# what load_results uses of it, and anything else is one InputError naming the file (and the run), not a
# TypeError or RecursionError from deep in pandas.

MAX_MANIFEST_BYTES = 500_000_000  # 20,000 cases (the matrix limit) of a few kB each fit many times over


def _loads(text: str | bytes, where: str, what: str, key: str | None = None) -> Any:
    """``json.loads`` with every way it can fail (bad JSON, nesting deeper than the interpreter's stack,
    bytes that are not UTF-8) as one InputError naming ``where``."""
    try:
        return json.loads(text)
    except RecursionError:
        raise InputError(where, key, f"{what} is nested too deeply to be one this suite wrote") from None
    except (ValueError, TypeError) as exc:
        raise InputError(where, key, f"{what} is not JSON ({exc})") from None


def _read_manifest(path: Path) -> dict[str, Any]:
    """``matrix.json``: an object whose ``cases`` maps case hashes to ``{"axes": {...}}`` objects, with
    ``grid_keys`` a list of str and ``name`` a str (as ``write_matrix_manifest`` writes them)."""
    where = str(path)
    if not path.is_file():
        raise InputError(where, None, "not a regular file; a matrix directory's matrix.json is a file")
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_MANIFEST_BYTES + 1)
    except OSError as exc:
        raise InputError(where, None, f"cannot read ({exc.strerror or exc})") from None
    if len(raw) > MAX_MANIFEST_BYTES:
        raise InputError(where, None, f"larger than {MAX_MANIFEST_BYTES:,} bytes; not a matrix manifest")
    doc = _loads(raw, where, "unreadable matrix manifest: the file")
    if not isinstance(doc, dict):
        raise InputError(where, None, f"unreadable matrix manifest: expected a JSON object, got {type(doc).__name__}")
    cases = doc.get("cases")
    if not isinstance(cases, dict):
        raise InputError(where, "cases", f"unreadable matrix manifest: expected an object of case hash -> case, got "
                                         f"{type(cases).__name__}")
    for h, c in cases.items():
        if not isinstance(c, dict) or not isinstance(c.get("axes", {}), dict):
            raise InputError(where, f"cases.{h}", "unreadable matrix manifest: a case is an object with an "
                                                  "\"axes\" object")
    keys = doc.get("grid_keys", [])
    if not isinstance(keys, list) or not all(isinstance(k, str) for k in keys):
        raise InputError(where, "grid_keys", "unreadable matrix manifest: expected a list of dotted keys (str)")
    if not isinstance(doc.get("name"), (str, type(None))):
        raise InputError(where, "name", f"unreadable matrix manifest: expected a str, got {type(doc['name']).__name__}")
    return doc


def _row_json(store: Path, r, column: str) -> dict[str, Any]:
    """Column ``column`` of run row ``r``, a JSON object; an InputError naming the store and run otherwise."""
    text = r[column] if column in r and r[column] is not None else "{}"
    where, key = str(store), f"run {r.id}: {column}"
    if not isinstance(text, str):
        raise InputError(where, key, f"expected JSON text, got {type(text).__name__}")
    value = _loads(text, where, "the value", key)
    if not isinstance(value, dict):
        raise InputError(where, key, f"expected a JSON object, got {type(value).__name__}")
    return value


def _check_row_case(store: Path, r, case: dict[str, Any]) -> None:
    """A row's resolved case has what load_results reads: each axis a table with a name, seed, dt, duration."""
    where = str(store)
    for axis in AXES[:4]:
        if not isinstance(case.get(axis), dict) or "name" not in case[axis]:
            raise InputError(where, f"run {r.id}: case_json", f"has no {axis} table with a name; not a case this "
                                                              "suite stored")
    for k in ("seed", "dt", "duration"):
        if k not in case:
            raise InputError(where, f"run {r.id}: case_json", f"has no {k}; not a case this suite stored")


def _read_runs(store: Path):
    from .harness.store import StoreReadError, read_runs

    try:
        runs = read_runs(store)  # read-only: reading never creates a file
    except StoreReadError as exc:
        raise InputError(str(store), None, f"not a bench-myriapoda results store ({exc})") from None
    missing = [c for c in ("id", "case_hash", "status", "message", "case_json", "metrics_json", "timings_json",
                           "git_commit", "timestamp") if c not in runs.columns]
    if missing:
        raise InputError(str(store), None, f"not a bench-myriapoda results store (its runs table has no "
                                           f"{', '.join(missing)})")
    for column, default in (("command", "run"), ("labels_json", "{}"), ("matrix", None)):  # a store of an
        if column not in runs.columns:                                                   # older release
            runs[column] = default
    return runs


def load_results(store_or_dir: str | os.PathLike, keys: list[str] | tuple[str, ...] = ()):
    """The runs of a results store or a matrix output directory as a pandas DataFrame.

    One row per run, one column per metric (named as in ``result.metrics``; a coded metric also has
    ``NAME_label``), and the axes as columns: ``creature``, ``body``, ``gait``, ``scenario``, ``seed``,
    ``dt``, and every swept key under its dotted name (``friction.mu_transverse``, ...).  Also
    ``run_id``, ``case_hash``, ``status``, ``message``, ``command``, ``matrix``, ``duration``, the timings
    (``steps``, ``steps_per_s``, ``realtime_factor``, ``compile_s``, ``wall_s``), ``git_commit`` and
    ``timestamp``.

    ``run_kind`` tells what a row's numbers are before you average them: ``headline`` (the case as
    configured: a ``run``, an API run, a matrix case outside its grids), ``sweep`` (a grid point of a
    matrix's stability or scaling sweep, or a ``stable-dt`` search), ``unstable`` (it blew up: its metrics
    stop at ``t_fail_s``) or ``failed`` (``error`` or ``timeout``).  A matrix's grid points are read from its
    ``matrix.json`` (the directory's, or the one next to a store); without one, a matrix row is a sweep
    when another row of the same matrix, creature, body, gait, scenario and duration differs from it in
    any key but the seed.  ``df[df.run_kind == "headline"]`` keeps the rows a comparison should average.

    ``store_or_dir``: a ``.sqlite`` store (every run in it), or a directory written by ``matrix`` /
    :func:`run_matrix` (its cases, the newest run of each, with the matrix's grid keys as the swept
    keys).  Without a matrix manifest, a swept key is any configuration key whose value differs between
    runs of the same creature, body, gait and scenario.  ``keys``: more configuration keys to add as
    columns (dotted, as ``--set`` takes them).  A key a run does not have (a Young's modulus swept on the
    FEM body next to a lattice body) is an empty cell (NaN) in that run's row; a key no run has is an
    ``InputError``.
    """
    import pandas as pd

    p = Path(_file_or_name(store_or_dir, "store_or_dir"))
    if isinstance(keys, str) or not isinstance(keys, (list, tuple)) or not all(isinstance(k, str) for k in keys):
        raise InputError("keys", None, f"{keys!r}: give a list of dotted configuration keys (str)")
    manifest = None
    if p.is_dir():
        from .harness.matrix import MANIFEST

        if os.path.lexists(p / MANIFEST):
            manifest = _read_manifest(p / MANIFEST)
        p = p / "results.sqlite"
        if not p.is_file():
            raise InputError(str(store_or_dir), None, "no results.sqlite in this directory; give a results store "
                                                      "or a directory written by `bench-myriapoda matrix`")
    elif not p.is_file():
        raise InputError(str(p), None, "no such file or directory; give a results store (.sqlite) or a matrix "
                                       "output directory")
    runs = _read_runs(p)
    kinds_manifest = manifest if manifest is not None else _sibling_manifest(p)
    if manifest is not None:
        runs = runs[(runs.command == "matrix") & (runs.matrix == manifest.get("name"))]
        runs = runs.drop_duplicates("case_hash", keep="last")
        runs = runs[runs.case_hash.isin(list(manifest["cases"]))]
    cases = [_row_json(p, r, "case_json") for _, r in runs.iterrows()]
    for (_, r), case in zip(runs.iterrows(), cases):
        _check_row_case(p, r, case)
    flat = [_flatten_case(c) for c in cases]
    if manifest is not None:
        swept = list(manifest.get("grid_keys", []))
    else:
        swept = _swept_keys(flat, [tuple(c[a]["name"] for a in AXES[:4]) for c in cases])
    swept = [k for k in swept if k not in AXES and k not in ("dt", "duration")]
    extra = [k for k in keys if k not in swept]
    unknown = [k for k in extra if not any(k in f for f in flat)]
    if unknown and flat:  # no run has it: a typo, not a key of another body model
        raise InputError("keys", unknown[0], "not a configuration key of any run here (see `bench-myriapoda keys`)")
    kinds = _run_kinds(runs, flat, cases, kinds_manifest)
    rows = []
    for (_, r), case, f, kind in zip(runs.iterrows(), cases, flat, kinds):
        axes = {"creature": case["creature"]["name"], "body": case["body"]["name"], "gait": case["gait"]["name"],
                "scenario": case["scenario"]["name"], "seed": case["seed"]}
        if manifest is not None:  # the axis values as the matrix names them (a .toml path, not its stem)
            axes.update({k: v for k, v in manifest["cases"][r.case_hash].get("axes", {}).items()
                         if k in AXES and k != "seed"})
            axes["seed"] = case["seed"]
        row = {"run_id": int(r.id), "case_hash": r.case_hash, **axes, "dt": case["dt"]}
        for k in swept + extra:  # a key this run's body model lacks (a mixed-body sweep): an empty cell
            v = f.get(k)
            row[k] = list(v) if isinstance(v, tuple) else (np.nan if v is None else v)
        row.update({"duration": case["duration"], "status": r.status, "run_kind": kind, "message": r.message or "",
                    "command": r.command, "matrix": r.matrix, "git_commit": r.git_commit, "timestamp": r.timestamp})
        timings = _row_json(p, r, "timings_json")
        for k in ("steps", "steps_per_s", "realtime_factor", "compile_s", "wall_s"):
            row[k] = np.nan if timings.get(k) is None else timings[k]
        for k, v in _row_json(p, r, "metrics_json").items():
            row[k if k not in row else f"metric.{k}"] = np.nan if v is None else v
        for k, v in _row_json(p, r, "labels_json").items():
            row[f"{k}_label"] = v
        rows.append(row)
    if not rows:
        return pd.DataFrame(columns=["run_id", "case_hash", *AXES, "dt", *swept, *extra, "duration", "status",
                                     "run_kind", "message"])
    return pd.DataFrame(rows)
