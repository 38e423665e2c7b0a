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


def resolve(creature: str, body: str, scenario: str, gait: str | None = None, duration: float | None = None,
            dt: float | None = None, seed: int | None = 0, set: Mapping[str, Any] | None = None,
            **overrides: Any) -> Case:
    """The resolved :class:`Case` :func:`run` would simulate (nothing runs)."""
    return resolve_case(creature, body, scenario, gait, duration=duration, dt=dt, seed=seed,
                        overrides=override_items(set, **overrides))


def run(creature: str, body: str, scenario: str, gait: str | None = None, duration: float | None = None,
        dt: float | None = None, seed: int | None = 0, controller: Any = None, store: str | os.PathLike | None = None,
        *, set: Mapping[str, Any] | None = None, keep_nodes: bool = False, **overrides: Any) -> Result:
    """Run one case and return its :class:`Result`.

    ``creature``, ``scenario``: a name (``models/NAME.toml``, ``scenarios/NAME.toml``) or a ``.toml`` path;
    ``body``: a body model; ``gait``: default the creature's; ``duration`` [s], ``dt`` [s], ``seed``: as the
    CLI's flags.  Any other configuration key: ``set={"friction.mu_transverse": 0.2}`` or a keyword with
    ``__`` for the dot, ``friction__mu_transverse=0.2`` (``bench-myriapoda keys`` lists them).
    ``controller``: handed to ``run_case`` to drive the body instead of the gait's own controller.
    ``store``: a results database to record the run in (as ``command = 'api'``); default: not stored.
    ``keep_nodes``: also record every node position (``result.series.nodes``).

    Raises :class:`InputError` for bad input; a failure during the run is status ``error`` with
    ``result.message`` and ``result.traceback``.
    """
    from .harness.runner import run_case

    case = resolve(creature, body, scenario, gait, duration, dt, seed, set, **overrides)
    kwargs: dict[str, Any] = {"keep_nodes": keep_nodes}
    if controller is not None:
        kwargs["controller"] = controller
    raw = run_case(case, **kwargs)
    run_id = None
    if store is not None:
        from .harness.store import record_run

        run_id = record_run(store, raw, command="api")
    return Result(raw, run_id)


# --------------------------------------------------------------------------- matrices

def run_matrix(file_or_name: str | os.PathLike, out: str | os.PathLike | None = None, workers: int | None = None, *,
               executor: str = "local", scheduler: str | None = None, resume: bool = False,
               timeout_per_case: float | None = None, report: bool = False, progress: bool = False):
    """Run a scenario matrix (a ``.toml`` path or a name in ``scenarios/matrix/``); return :func:`load_results`
    of its output directory.

    ``out`` (default ``reports/matrix/NAME``) receives ``results.sqlite``, ``matrix.json`` and
    ``series/``, as ``bench-myriapoda matrix FILE --out DIR`` writes them; ``report=True`` also writes
    ``index.html`` and ``summary.md``.  ``executor``: ``local`` (a process pool of ``workers``) or
    ``dask`` (``scheduler`` address, default a LocalCluster); ``resume`` runs only the cases not yet
    stored; ``timeout_per_case`` [s]; ``progress``: a progress bar on stderr.
    """
    from .harness.executors import EXECUTORS, run_matrix as run_cases
    from .harness.matrix import expand_matrix, locate_matrix, write_matrix_manifest
    from .harness.progress import MatrixProgress

    if workers is not None and workers < 1:
        raise InputError("workers", None, f"{workers} is out of range; must be >= 1")
    if executor not in EXECUTORS:
        raise InputError("executor", None, f"{executor!r} is not allowed; choose one of {', '.join(EXECUTORS)}")
    if timeout_per_case is not None and not timeout_per_case > 0:
        raise InputError("timeout_per_case", None, f"{timeout_per_case} is out of range; must be > 0")
    if executor == "dask":
        try:
            import dask.distributed  # noqa: F401
        except ImportError:
            raise InputError("executor", None, "dask is not installed; pip install 'bench-myriapoda[dask]'") from None
    exp = expand_matrix(locate_matrix(str(file_or_name)))
    out = Path(out) if out is not None else Path("reports") / "matrix" / exp.name
    if out.exists() and not out.is_dir():
        raise InputError("out", None, f"{out} exists and is not a directory")
    if not exp.cases:
        raise InputError(str(exp.path), None, "no case left to run after exclusions and unsupported combinations")
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


def _read_runs(store: Path):
    from .harness.store import StoreReadError, read_runs

    try:
        return read_runs(store)  # read-only: reading never creates a file
    except StoreReadError as exc:
        raise InputError(str(store), None, f"not a bench-myriapoda results store ({exc})") from None


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

    p = Path(store_or_dir)
    manifest = None
    if p.is_dir():
        from .harness.matrix import MANIFEST

        if (p / MANIFEST).is_file():
            try:
                manifest = json.loads((p / MANIFEST).read_text())
                manifest["cases"]
            except (ValueError, KeyError) as exc:
                raise InputError(str(p / MANIFEST), None, f"unreadable matrix manifest: {exc}") from None
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
        runs = runs[runs.case_hash.isin(manifest["cases"])]
    cases = [json.loads(c) for c in runs.case_json]
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
            axes.update({k: v for k, v in manifest["cases"][r.case_hash]["axes"].items() if k in AXES and k != "seed"})
            axes["seed"] = case["seed"]
        row = {"run_id": int(r.id), "case_hash": r.case_hash, **axes, "dt": case["dt"]}
        for k in swept + extra:  # a key this run's body model lacks (a mixed-body sweep): an empty cell
            v = f.get(k)
            row[k] = list(v) if isinstance(v, tuple) else (np.nan if v is None else v)
        row.update({"duration": case["duration"], "status": r.status, "run_kind": kind, "message": r.message or "",
                    "command": r.command, "matrix": r.matrix, "git_commit": r.git_commit, "timestamp": r.timestamp})
        timings = json.loads(r.timings_json)
        for k in ("steps", "steps_per_s", "realtime_factor", "compile_s", "wall_s"):
            row[k] = np.nan if timings.get(k) is None else timings[k]
        for k, v in json.loads(r.metrics_json).items():
            row[k if k not in row else f"metric.{k}"] = np.nan if v is None else v
        for k, v in json.loads(r.labels_json or "{}").items():
            row[f"{k}_label"] = v
        rows.append(row)
    if not rows:
        return pd.DataFrame(columns=["run_id", "case_hash", *AXES, "dt", *swept, *extra, "duration", "status",
                                     "run_kind", "message"])
    return pd.DataFrame(rows)
