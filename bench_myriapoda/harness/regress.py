"""``bench-myriapoda regress``: throughput history and regression check.

Each entry of the fixed suite (``throughput_suite.SUITE``) is set up (JIT compile or
cache load), warmed up with one untimed repetition, then timed ``repeats`` times; the
REFERENCE kernel (``throughput_suite.reference_ops``) is timed right before every
repetition.  Times are CPU seconds of the timing thread (``time.thread_time``): on a
shared machine a process that waits for a core does not look slower.  Per entry:

- ``steps_per_s``: median of the repetitions' steps/s, ``spread``: MAD / median of them;
- ``reference_ops_per_s`` and ``reference_spread`` likewise for the reference runs;
- ``normalized = steps_per_s / reference_ops_per_s``: the figure that is compared, so a
  slower, faster or busier machine (CPU clock, thermal state) does not read as a change.

A comparison with a baseline run flags an entry as a ``regression`` when its normalized
figure dropped by more than ``max(threshold, NOISE_K * noise)``, where ``noise`` combines
the relative spreads of both runs (entry and reference, root sum of squares).
"""
from __future__ import annotations

import json
import math
import re
import statistics
import subprocess
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from ..core.errors import InputError
from .store import read_regress_history

DEFAULT_REPEATS = 7
DEFAULT_THRESHOLD = 0.10
NOISE_K = 3.0
MIN_REPEATS, MAX_REPEATS = 3, 1000

HISTORY_COLUMNS = ("run_id", "entry", "git_commit", "git_dirty", "machine_json", "timestamp", "steps_per_rep",
                   "repeats", "steps_per_s", "spread", "reference_ops_per_s", "reference_spread", "normalized",
                   "samples_json")


def relative_mad(values: Sequence[float]) -> float:
    """Median absolute deviation divided by the median (0 for a single value)."""
    med = statistics.median(values)
    return statistics.median([abs(v - med) for v in values]) / med if med else math.inf


@dataclass
class EntryResult:
    """The timings of one suite entry in one regress run."""

    name: str
    steps_per_rep: int
    repeats: int
    steps_per_s: float
    spread: float
    reference_ops_per_s: float
    reference_spread: float
    samples: dict = field(default_factory=dict)

    @property
    def normalized(self) -> float:
        return self.steps_per_s / self.reference_ops_per_s

    @property
    def noise(self) -> float:
        """Relative spread of the normalized figure: entry and reference spreads, root sum of squares."""
        return math.hypot(self.spread, self.reference_spread)

    def row(self) -> dict:
        return {"entry": self.name, "steps_per_rep": self.steps_per_rep, "repeats": self.repeats,
                "steps_per_s": self.steps_per_s, "spread": self.spread,
                "reference_ops_per_s": self.reference_ops_per_s, "reference_spread": self.reference_spread,
                "normalized": self.normalized, "samples_json": json.dumps(self.samples)}


# --------------------------------------------------------------------------- input checks

def check_suite_names(names: Sequence[str] | None) -> list[str]:
    """The entries to run (all of the suite when None), in order, without repeats; InputError for unknown names."""
    from .throughput_suite import SUITE

    if not names:
        return list(SUITE)
    unknown = [n for n in names if n not in SUITE]
    if unknown:
        raise InputError("--suite", None, f"unknown entry {unknown[0]!r}; known: {', '.join(SUITE)}")
    return list(dict.fromkeys(names))


def check_repeats(repeats: int) -> int:
    if not MIN_REPEATS <= repeats <= MAX_REPEATS:
        raise InputError("--repeats", None, f"{repeats} is out of range; must be {MIN_REPEATS} to {MAX_REPEATS}")
    return repeats


def check_threshold(threshold: float) -> float:
    if not (math.isfinite(threshold) and 0.0 <= threshold < 1.0):
        raise InputError("--threshold", None, f"{threshold} is out of range; must be a fraction >= 0 and < 1")
    return threshold


# --------------------------------------------------------------------------- running the suite

def run_suite(names: Sequence[str], repeats: int = DEFAULT_REPEATS,
              progress: Callable[[str], None] | None = None, suite: dict | None = None) -> list[EntryResult]:
    """Time every named entry ``repeats`` times, the reference kernel before each repetition.

    ``suite``: name -> ``SuiteEntry`` to take the entries from (default ``throughput_suite.SUITE``;
    ``peers`` passes its own)."""
    from . import throughput_suite as TS

    suite = TS.SUITE if suite is None else suite
    clock, wall = time.thread_time, time.perf_counter
    TS.reference_ops(100)  # compile (or load) the reference kernel
    results = []
    for name in names:
        entry = suite[name]
        if progress:
            progress(f"{name}: setup (compile or cache load)")
        step, steps = entry.setup()
        step(steps)  # warm-up repetition, untimed
        TS.reference_ops()
        if progress:
            progress(f"{name}: {repeats} repetitions of {steps} steps")
        sps, ref, sps_wall, ref_wall = [], [], [], []
        for _ in range(repeats):
            c0, w0 = clock(), wall()
            ops = TS.reference_ops()
            c1, w1 = clock(), wall()
            step(steps)
            c2, w2 = clock(), wall()
            ref.append(ops / max(c1 - c0, 1e-9))
            sps.append(steps / max(c2 - c1, 1e-9))
            ref_wall.append(ops / max(w1 - w0, 1e-9))
            sps_wall.append(steps / max(w2 - w1, 1e-9))
        results.append(EntryResult(
            name=name, steps_per_rep=int(steps), repeats=repeats,
            steps_per_s=statistics.median(sps), spread=relative_mad(sps),
            reference_ops_per_s=statistics.median(ref), reference_spread=relative_mad(ref),
            samples={"steps_per_s": sps, "reference_ops_per_s": ref,
                     "steps_per_s_wall": sps_wall, "reference_ops_per_s_wall": ref_wall}))
    return results


# --------------------------------------------------------------------------- history

def load_history(path: Path | str) -> pd.DataFrame:  # noqa: F821
    """The ``regress_history`` table of a results store as a DataFrame, one row per (run, entry).

    Adds ``commit_short`` (7 characters, ``+`` when the tree was dirty), ``label`` (``run N
    commit_short``) and ``time`` (parsed timestamp).  Empty (with the columns) when the store
    or the table does not exist.  Opens the store read-only: it never creates or changes it.
    """
    import pandas as pd

    path = Path(path)
    df = pd.DataFrame(columns=list(HISTORY_COLUMNS))
    if path.is_file():
        stored = read_regress_history(path, tuple(HISTORY_COLUMNS))
        if stored is not None:
            df = stored
    df["commit_short"] = [(c[:7] if isinstance(c, str) else "?") + ("+" if d == 1 else "")
                          for c, d in zip(df["git_commit"], df["git_dirty"])]
    df["label"] = [f"run {r} {c}" for r, c in zip(df["run_id"], df["commit_short"])]
    _check_history_rows(df, path)
    df["time"] = pd.to_datetime(df["timestamp"], utc=True, format="ISO8601") if len(df) else \
        pd.Series(dtype="datetime64[ns, UTC]")
    return df


def _check_history_rows(df, path: Path) -> None:
    """Every stored row has a timestamp this suite writes (ISO 8601) and its figures; a store edited by
    hand or by another program is an InputError naming the store, run and column, not a traceback."""
    import pandas as pd

    for col in ("run_id", "timestamp", "steps_per_s", "reference_ops_per_s", "normalized"):
        bad = df[df[col].isna()]
        if len(bad):
            raise InputError(str(path), f"regress_history.{col}", f"run {bad.iloc[0].run_id} entry "
                                                                  f"{bad.iloc[0].entry!r} has no value (NULL)")
    stamps = pd.to_datetime(df["timestamp"], utc=True, format="ISO8601", errors="coerce")
    if stamps.isna().any():
        row = df[stamps.isna()].iloc[0]
        raise InputError(str(path), "regress_history.timestamp", f"run {row.run_id} entry {row.entry!r}: "
                                                                 f"{str(row.timestamp)[:40]!r} is not a timestamp "
                                                                 "(YYYY-MM-DDTHH:MM:SSZ)")


regress_history = load_history  # the name the CLI docs use


@dataclass
class Baseline:
    run_id: int
    git_commit: str | None
    git_dirty: bool | None
    timestamp: str
    rows: dict  # entry name -> history row (dict)

    def describe(self) -> str:
        c = (self.git_commit or "?")[:7] + ("+" if self.git_dirty else "")
        return f"run {self.run_id} at {c} ({self.timestamp})"


def _baseline_of(hist, run_id: int) -> Baseline:
    sel = hist[hist.run_id == run_id]
    first = sel.iloc[0]
    dirty = first.git_dirty
    return Baseline(int(run_id), first.git_commit if isinstance(first.git_commit, str) else None,
                    None if dirty is None or math.isnan(dirty) else bool(dirty),  # NULL reads as None or NaN
                    first.timestamp, {r["entry"]: r for r in sel.to_dict("records")})


def _git_resolve(spec: str) -> str | None:
    """The full hash git gives for spec (a ref such as HEAD~1 or a prefix), or None."""
    here = Path(__file__).resolve().parent
    try:
        r = subprocess.run(["git", "rev-parse", "--verify", "--quiet", f"{spec}^{{commit}}"], cwd=here,
                           capture_output=True, text=True, timeout=10, check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    return r.stdout.strip() if r.returncode == 0 and r.stdout.strip() else None


def resolve_baseline(store: Path | str, spec: str | None, machine_json: str, names: Sequence[str]) -> Baseline | None:
    """The run to compare against, read from ``store`` (which this never creates).

    ``spec`` None: the most recent run in the store on the same machine fingerprint that holds any
    of ``names`` (None when there is none yet).  Otherwise a regress run id, or a git commit (a hash
    prefix of at least 4 characters, or any name git resolves such as ``HEAD~1``) with a run in the
    store; of several runs at that commit the latest on this machine, else the latest.  InputError
    when ``spec`` names nothing in the history.
    """
    hist = load_history(store)
    if spec is None:
        mine = hist[(hist.machine_json == machine_json) & hist.entry.isin(list(names))]
        return None if mine.empty else _baseline_of(hist, int(mine.run_id.max()))
    spec = spec.strip()
    if hist.empty:
        raise InputError("--baseline", None, f"{spec!r}: the store {store} has no regress run yet")
    if re.fullmatch(r"[0-9]+", spec) and int(spec) in {int(r) for r in hist.run_id}:  # ASCII digits ('²'.isdigit())
        return _baseline_of(hist, int(spec))
    commits = hist.git_commit.fillna("")
    match = hist.iloc[0:0]
    low = spec.lower()
    if re.fullmatch(r"[0-9a-f]{4,40}", low):
        match = hist[commits.str.startswith(low)]
    if match.empty:
        full = _git_resolve(spec)
        if full:
            match = hist[commits == full]
    if match.empty:
        runs = sorted({int(r) for r in hist.run_id})
        raise InputError("--baseline", None,
                         f"{spec!r} is neither a regress run id ({runs[0]} to {runs[-1]}) nor a git commit "
                         f"with a regress run in {store}")
    if match.git_commit.nunique() > 1:
        raise InputError("--baseline", None, f"{spec!r} matches several commits: "
                         + ", ".join(sorted(c[:12] for c in match.git_commit.unique())))
    here = match[match.machine_json == machine_json]
    return _baseline_of(hist, int((here if not here.empty else match).run_id.max()))


# --------------------------------------------------------------------------- comparison

def compare(now: Sequence[EntryResult], base: Baseline | None, threshold: float = DEFAULT_THRESHOLD,
            k: float = NOISE_K) -> list[dict]:
    """One dict per entry: entry, steps_per_s, now (normalized), baseline (normalized or None), change
    (fraction), noise, threshold (fraction), verdict: ``regression``, ``faster``, ``ok``, or ``new``
    (no baseline figure for this entry)."""
    out = []
    for e in now:
        d = {"entry": e.name, "steps_per_s": e.steps_per_s, "spread": e.spread,
             "reference_ops_per_s": e.reference_ops_per_s, "reference_spread": e.reference_spread,
             "now": e.normalized, "baseline": None, "baseline_steps_per_s": None, "change": None,
             "noise": None, "threshold": None, "verdict": "new"}
        b = base.rows.get(e.name) if base is not None else None
        if b is not None:
            noise = math.sqrt(e.noise ** 2 + b["spread"] ** 2 + b["reference_spread"] ** 2)
            thr = max(threshold, k * noise)
            change = e.normalized / b["normalized"] - 1.0
            d.update(baseline=float(b["normalized"]), baseline_steps_per_s=float(b["steps_per_s"]), change=change,
                     noise=noise, threshold=thr,
                     verdict="regression" if change < -thr else ("faster" if change > thr else "ok"))
        out.append(d)
    return out


def format_table(rows: list[dict]) -> list[str]:
    """The comparison as aligned text lines."""
    def pct(v):
        return "-" if v is None else f"{100 * v:+.1f}%"

    head = ["entry", "steps/s", "baseline", "now", "change", "threshold", "verdict"]
    table = [head] + [[r["entry"], f"{r['steps_per_s']:,.0f}",
                       "-" if r["baseline"] is None else f"{r['baseline']:.4e}", f"{r['now']:.4e}",
                       pct(r["change"]), "-" if r["threshold"] is None else f"{100 * r['threshold']:.1f}%",
                       r["verdict"]] for r in rows]
    widths = [max(len(row[i]) for row in table) for i in range(len(head))]
    return ["  ".join(v.ljust(w) if i in (0, 6) else v.rjust(w) for i, (v, w) in enumerate(zip(row, widths)))
            for row in table]
