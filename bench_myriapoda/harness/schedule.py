"""Scheduling a matrix by predicted cost: a cost per case before it runs, longest cases first.

A matrix's wall time on ``W`` workers is at least its longest case (the critical path) and at
least the sum of its cases over ``W``; which of the two wins depends on the order the cases are
handed out.  Handed out in file order, a long case that comes last runs alone at the end while
the other workers idle.  Longest-processing-time-first list scheduling (LPT: each free worker
takes the longest case left) keeps the tail of the matrix to short cases; its makespan is within
4/3 of the best possible (Graham 1969).

:class:`CostModel` predicts a case's wall time [s] on one worker with warm kernels as

    fixed_s + steps x per_step_s

where ``per_step_s`` comes, first match wins, from

1. ``store``: earlier runs of the same kind of case (:func:`cost_key`: body model, creature,
   segments, mesh resolution, legs, water) in the matrix's store or the history store: the median
   of their stepping time per step (steps / steps_per_s); a case run before (same ``case_hash``)
   is predicted to run the steps it ran then (an unstable case stops early again); ``fixed_s`` is the
   median over all stored runs of the wall beyond compile and steps (observations, metrics);
2. ``store-scaled``: earlier runs of the same body and creature at another size, scaled by the
   size ratio (:func:`size_of`: segments x mesh nodes per link);
3. ``suite``: the throughput suite's figure for the body and creature (``regress_history``,
   newest run; ``harness/throughput_suite.py``), scaled by size from the suite scene's size;
4. ``default``: :data:`DEFAULT_STEP_S`, per-step costs per unit of size measured on the development
   machine, times the case's size.

The order only changes *when* a case runs, never what it computes: every case is a separate
process-local simulation from its own resolved configuration, so results are identical in any
order (``tests/test_schedule.py`` checks it bit for bit).

:func:`simulate` predicts a matrix's wall time on ``W`` workers by the same list scheduling from
case costs plus fixed per-worker and per-case costs; :func:`efficiency` is the figure a matrix
run ends with (sum of the cases' wall times over workers x matrix wall).
"""
from __future__ import annotations

import heapq
import json
import math
import statistics
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

from .store import StoreReadError, read_case_costs, read_latest_regress_rates, read_matrix_case_walls

# What a case costs when neither the store nor the throughput suite knows its kind: each body model declares
# its per-step cost per size unit (``BodySpec.step_cost_s``) and the suite's scenes of it with their sizes
# (``BodySpec.suite_scenes``), so this module names no body.  Only the ORDER of the cases depends on these: a
# factor of two off changes which case starts first, never a result.
DEFAULT_FIXED_S = 0.05  # per case with warm kernels: kernel lookup, body build, metrics [s]
UNKNOWN_STEP_S = 1.0e-6  # a body model that declares no step cost [s per step per size unit]


def _body_spec(name: str):
    """The catalog's ``BodySpec`` of body model ``name`` (None for one no table holds)."""
    from ..core import registry

    registry.load_all()
    return registry.BODIES.get(name)


def default_step_s(body: str, legged: bool) -> float:
    """Per-step wall [s] per size unit of ``body`` (``BodySpec.step_cost_s``; ``UNKNOWN_STEP_S`` when undeclared)."""
    spec = _body_spec(body)
    return float(spec.step_cost_s.get(legged, UNKNOWN_STEP_S)) if spec is not None else UNKNOWN_STEP_S


def suite_scene(body: str, creature: str) -> tuple[str, float] | None:
    """(throughput-suite entry, its scene's size) of ``body`` with ``creature`` (``BodySpec.suite_scenes``)."""
    spec = _body_spec(body)
    return None if spec is None else spec.suite_scenes.get(creature)


OK_STATUSES = ("ok", "unstable", "controller_unstable")


# --------------------------------------------------------------------------- what a case costs

def _get(d: Any, section: str, key: str, default=None):
    """``d.section.key`` of a Case or of its ``to_dict()``."""
    sec = d.get(section, {}) if isinstance(d, Mapping) else getattr(d, section, None)
    if sec is None:
        return default
    return sec.get(key, default) if isinstance(sec, Mapping) else getattr(sec, key, default)


def cost_key(case: Any) -> tuple:
    """What decides a case's cost per step: (body model, creature, segments, mesh resolution or None, legged,
    water).  ``case``: a :class:`~..core.config.Case` or its ``to_dict()`` (a stored row's ``case_json``)."""
    return (_get(case, "body", "name"), _get(case, "creature", "name"), _get(case, "creature", "segments"),
            _get(case, "body", "resolution"), (_get(case, "creature", "legs_per_segment") or 0) > 0,
            (_get(case, "scenario", "water_depth_m") or 0.0) > 0.0)


def size_of(key: tuple) -> float:
    """A size proxy for scaling a per-step cost between sizes of the same body and creature:
    segments x nodes per FEM link (resolution^3; 1 on the lattice)."""
    _body, _creature, segments, resolution, _legged, _water = key
    return float(segments or 1) * float(resolution or 1) ** 3


def case_steps(case: Any) -> int:
    """Steps a case runs: duration / dt, as ``Case.steps``."""
    if isinstance(case, Mapping):
        return max(1, int(round(case["duration"] / case["dt"])))
    return case.steps


@dataclass(frozen=True)
class Prediction:
    seconds: float  # predicted wall time of the case on one worker with warm kernels [s]
    per_step_s: float
    fixed_s: float
    source: str  # store, store-scaled, suite, default


@dataclass(frozen=True)
class Observed:
    """One earlier run of a case: its key, steps done, wall, compile (kernel load) and stepping times [s].

    ``step_wall_s``: the time in the body's step kernels (steps / steps_per_s; NaN when not recorded).
    The rest of the wall beyond compile is the case's own overhead (observations, metrics, recording)
    and, on a cold cache, kernels compiled on first use after ``compile`` (measured: up to 80 s of a
    3-step case on the development machine), which says nothing about the next run of the case.
    """

    key: tuple
    steps: int
    wall_s: float
    compile_s: float
    step_wall_s: float = float("nan")
    case_hash: str = ""

    @property
    def per_step_s(self) -> float:
        """Wall per step [s]: the stepping time where recorded (free of compiles), else (wall - compile) / steps."""
        if math.isfinite(self.step_wall_s):
            return self.step_wall_s / self.steps
        return max(0.0, self.wall_s - self.compile_s) / self.steps

    @property
    def overhead_s(self) -> float:
        """What the case took besides its compile and its steps [s]: observations, metrics, recording, and on
        a cold cache the kernels compiled on first use after ``compile``."""
        return max(0.0, self.wall_s - self.compile_s - self.per_step_s * self.steps)


class CostModel:
    """Predicts each case's wall time on one warm worker (see the module docstring).

    ``observed``: earlier runs (:func:`observed_runs`); ``suite``: throughput-suite entry -> steps/s
    (:func:`suite_rates`).  Compile time of a cold group is not part of a prediction: which case compiles
    a group is the compile scheduler's choice (``executors.CompileScheduler``), not the order's.
    """

    def __init__(self, observed: Iterable[Observed] = (), suite: Mapping[str, float] | None = None):
        by_key: dict[tuple, list[Observed]] = {}
        steps_done: dict[str, list[int]] = {}
        observed = list(observed)
        for o in observed:
            by_key.setdefault(o.key, []).append(o)
            if o.case_hash:
                steps_done.setdefault(o.case_hash, []).append(o.steps)
        self.step_s = {k: statistics.median(o.per_step_s for o in v) for k, v in by_key.items()}
        # One fixed part for every case: the median over all runs of what a case took besides its compile and
        # its steps.  Per kind it would be one run's, often the cold run that compiled the group's kernels
        # (measured up to 80 s of lazily compiled kernels here), which says nothing about the next run.
        self.fixed = statistics.median(o.overhead_s for o in observed) if observed else DEFAULT_FIXED_S
        # an exact case seen before: the steps it ran (an unstable case stops early, and will again)
        self.steps_done = {h: int(statistics.median(v)) for h, v in steps_done.items()}
        self.suite = dict(suite or {})

    def predict(self, case: Any) -> Prediction:
        key = cost_key(case)
        steps = case_steps(case)
        if not isinstance(case, Mapping) and case.case_hash() in self.steps_done:
            steps = min(steps, self.steps_done[case.case_hash()])
        if key in self.step_s:
            return self._p(steps, self.step_s[key], self.fixed, "store")
        same_kind = [k for k in self.step_s if k[:2] == key[:2] and k[4:] == key[4:]]
        if same_kind:  # the nearest size of the same body and creature, scaled
            near = min(same_kind, key=lambda k: abs(math.log(size_of(k) / size_of(key))))
            return self._p(steps, self.step_s[near] * size_of(key) / size_of(near), self.fixed, "store-scaled")
        scene = suite_scene(key[0], key[1])
        if scene and scene[0] in self.suite and self.suite[scene[0]] > 0:
            per_step = 1.0 / self.suite[scene[0]] * size_of(key) / scene[1]
            return self._p(steps, per_step, self.fixed, "suite")
        return self._p(steps, default_step_s(key[0], key[4]) * size_of(key), self.fixed, "default")

    @staticmethod
    def _p(steps: int, per_step: float, fixed: float, source: str) -> Prediction:
        return Prediction(fixed + steps * per_step, per_step, fixed, source)

    def predict_all(self, cases: Sequence[Any]) -> list[Prediction]:
        return [self.predict(c) for c in cases]


def observed_runs(store_paths: Iterable[Path | str]) -> list[Observed]:
    """Earlier runs with status ok or unstable, at least one step and finite times, from every store that exists.

    Rows of any command (``run``, ``matrix``, ``quick``) count: a case's cost does not depend on what ran it."""
    out: list[Observed] = []
    for p in store_paths:
        if p is None or not Path(p).is_file():
            continue
        try:
            rows = read_case_costs(p, OK_STATUSES)
        except StoreReadError:  # not a store, or an older schema: no history from it
            continue
        for case_json, steps, wall, comp, rate, case_hash in rows:
            if comp is None or not math.isfinite(comp) or not math.isfinite(wall):
                continue
            step_wall = steps / rate if rate is not None and math.isfinite(rate) and rate > 0 else float("nan")
            try:
                out.append(Observed(cost_key(json.loads(case_json)), int(steps), float(wall), float(comp), step_wall,
                                    case_hash or ""))
            except (ValueError, KeyError, TypeError):
                continue
    return out


def suite_rates(store_path: Path | str | None) -> dict[str, float]:
    """The newest ``regress`` run's steps/s per throughput-suite entry in ``store_path`` (empty without one)."""
    if store_path is None or not Path(store_path).is_file():
        return {}
    try:
        rows = read_latest_regress_rates(store_path)
    except StoreReadError:
        return {}
    return {e: float(s) for e, s in rows if s and s > 0}


def cost_model_for(store_paths: Sequence[Path | str | None]) -> CostModel:
    """A :class:`CostModel` from the runs in ``store_paths`` and the newest throughput-suite run among them."""
    suite: dict[str, float] = {}
    for p in store_paths:
        suite = suite or suite_rates(p)
    return CostModel(observed_runs(p for p in store_paths if p is not None), suite)


# --------------------------------------------------------------------------- order

def longest_first(costs: Sequence[float]) -> list[int]:
    """Indices of ``costs`` from the largest to the smallest; ties keep their given order (a stable sort)."""
    return sorted(range(len(costs)), key=lambda i: -costs[i])


# --------------------------------------------------------------------------- simulated schedule

@dataclass(frozen=True)
class Simulated:
    workers: int
    wall_s: float  # predicted matrix wall time [s]
    busy_s: float  # the work scheduled: cases plus per-case fixed costs [s]
    critical_s: float  # the longest single case, with its fixed cost [s]

    @property
    def efficiency(self) -> float:
        return self.busy_s / (self.workers * self.wall_s) if self.wall_s > 0 else float("nan")


def simulate(costs: Sequence[float], workers: int, worker_start_s: float = 0.0, per_case_s: float = 0.0,
             longest_first_order: bool = True) -> Simulated:
    """Predicted wall time [s] of running cases of ``costs`` [s] on ``workers`` workers by list scheduling.

    Every worker starts after ``worker_start_s`` (spawn, imports, body models); each case adds
    ``per_case_s`` (hand-over, result transfer and store write).  Each free worker takes the next case:
    in order of decreasing cost (LPT) with ``longest_first_order``, else in the given order.
    """
    if workers < 1:
        raise ValueError(f"workers must be >= 1, got {workers}")
    order = longest_first(costs) if longest_first_order else list(range(len(costs)))
    free = [worker_start_s] * min(workers, max(1, len(costs)))
    heapq.heapify(free)
    end = worker_start_s
    for i in order:
        t = heapq.heappop(free) + costs[i] + per_case_s
        end = max(end, t)
        heapq.heappush(free, t)
    busy = sum(costs) + per_case_s * len(costs)
    critical = (max(costs) + per_case_s) if len(costs) else 0.0
    return Simulated(workers, end, busy, critical)


# --------------------------------------------------------------------------- what a run gave

@dataclass(frozen=True)
class Efficiency:
    """How well a matrix run used its workers.

    ``parallel_efficiency`` = sum of the cases' wall times / (workers x matrix wall): 1 when every worker
    ran a case all the time; lower from idle workers (a short tail, waits for compiles, worker start) and
    from fixed costs outside the cases.  ``critical_s``: the longest case, the least wall any number of
    workers can reach.
    """

    workers: int
    matrix_wall_s: float
    case_wall_sum_s: float
    critical_s: float
    critical_case: str  # label or hash of the longest case
    cases: int

    @property
    def parallel_efficiency(self) -> float:
        denom = self.workers * self.matrix_wall_s
        return self.case_wall_sum_s / denom if denom > 0 else float("nan")

    def line(self) -> str:
        return (f"parallel efficiency {self.parallel_efficiency:.0%}: {self.case_wall_sum_s:.1f} s of cases on "
                f"{self.workers} worker(s) in {self.matrix_wall_s:.1f} s; critical path {self.critical_s:.1f} s "
                f"({self.critical_case})")

    def to_dict(self) -> dict[str, Any]:
        return {"workers": self.workers, "matrix_wall_s": self.matrix_wall_s, "case_wall_sum_s": self.case_wall_sum_s,
                "parallel_efficiency": self.parallel_efficiency, "critical_path_s": self.critical_s,
                "critical_case": self.critical_case, "cases": self.cases}


def efficiency(case_walls: Mapping[str, float], workers: int, matrix_wall_s: float,
               labels: Mapping[str, str] | None = None) -> Efficiency:
    """:class:`Efficiency` of a run from its cases' wall times [s] by case hash (NaN walls, e.g. a worker
    that died, count as 0) and the matrix wall [s] on ``workers`` workers."""
    walls = {h: (w if w is not None and math.isfinite(w) else 0.0) for h, w in case_walls.items()}
    crit = max(walls, key=walls.get) if walls else ""
    return Efficiency(workers, matrix_wall_s, sum(walls.values()), walls.get(crit, 0.0),
                      (labels or {}).get(crit, crit), len(walls))


def correlation(xs: Sequence[float], ys: Sequence[float]) -> float:
    """Pearson correlation of two equal-length sequences (NaN with fewer than 2 points or no spread)."""
    n = len(xs)
    if n < 2 or n != len(ys):
        return float("nan")
    mx, my = sum(xs) / n, sum(ys) / n
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    sxx = sum((x - mx) ** 2 for x in xs)
    syy = sum((y - my) ** 2 for y in ys)
    return sxy / math.sqrt(sxx * syy) if sxx > 0 and syy > 0 else float("nan")


def run_summary(stats: Mapping[str, Any], results: Sequence[Any], labels: Mapping[str, str] | None = None) -> dict:
    """What ``matrix.json`` keeps of a run's schedule: its :class:`Efficiency` (``efficiency``), the kernels idle
    workers compiled ahead (``kernel_jobs``, local executor; ``compile_plan``), and per case
    of this run its predicted and measured wall time [s] (``cases``), with the correlation of the two
    (``predicted_vs_measured_r``).  ``stats``: ``executors.run_matrix``'s; ``results``: its RunResults."""
    walls = {r.case.case_hash(): float(r.timings.get("wall_s", float("nan"))) for r in results}
    compiles = {r.case.case_hash(): float(r.timings.get("compile_s", float("nan"))) for r in results}
    eff = efficiency(walls, int(stats.get("workers") or 1), float(stats.get("matrix_wall_s", float("nan"))), labels)
    predicted = stats.get("predicted_s", {})
    cases = {h: {"wall_s": _finite(w), "compile_s": _finite(compiles[h]), "predicted_s": predicted.get(h)}
             for h, w in walls.items()}
    pairs = [(predicted[h], w) for h, w in walls.items() if h in predicted and math.isfinite(w)]
    r = correlation([p for p, _ in pairs], [w for _, w in pairs])
    return {"efficiency": eff.to_dict(), "line": eff.line(), "emit_s": stats.get("emit_s"),
            "kernel_jobs": stats.get("kernel_jobs"),
            "cost_sources": stats.get("cost_sources", {}), "predicted_vs_measured_r": r if math.isfinite(r) else None,
            "cases": cases}


def _finite(x: float) -> float | None:
    return x if x is not None and math.isfinite(x) else None


def write_run_summary(manifest: Path | str, summary: Mapping[str, Any]) -> None:
    """Add ``summary`` to ``matrix.json`` as its ``schedule`` key (atomically; the rest of the file unchanged)."""
    import os
    import tempfile

    manifest = Path(manifest)
    doc = json.loads(manifest.read_text()) if manifest.is_file() else {}
    doc["schedule"] = summary
    fd, tmp = tempfile.mkstemp(suffix=".json", dir=manifest.parent)
    with os.fdopen(fd, "w") as fh:
        json.dump(doc, fh, indent=1, sort_keys=True)
    os.replace(tmp, manifest)


# --------------------------------------------------------------------------- command line

def stored_case_walls(out_dir: Path | str, minus_compile: bool = False) -> dict[str, float]:
    """Case hash -> wall time [s] of the newest row of each case in a matrix output directory's store
    (``minus_compile``: without its compile time, what the case costs once its kernels are cached)."""
    rows = read_matrix_case_walls(Path(out_dir) / "results.sqlite")
    out = {}
    for h, w, c in rows:
        if w is None or not math.isfinite(w):
            continue
        if minus_compile and c is not None and math.isfinite(c):
            w = max(0.0, w - c)
        out[h] = float(w)
    return out


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m bench_myriapoda.harness.schedule DIR [DIR2 ...] --workers 1 2 4 8 16``: the matrix wall
    predicted by :func:`simulate` from each directory's stored case wall times, and how the costs the run
    was ordered by compare with them (``matrix.json``'s ``schedule``)."""
    import argparse
    import sys

    ap = argparse.ArgumentParser(prog="python -m bench_myriapoda.harness.schedule", description=main.__doc__)
    ap.add_argument("dirs", nargs="+", metavar="DIR", help="matrix output directories (results.sqlite, matrix.json)")
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2, 4, 8, 16])
    ap.add_argument("--worker-start", type=float, default=0.0, metavar="S",
                    help="fixed cost of starting a worker [s] (harness/worker_costs.py's start_s)")
    ap.add_argument("--per-case", type=float, default=0.0, metavar="S",
                    help="fixed cost per case outside its own wall time [s] (hand-over, result transfer, store)")
    ap.add_argument("--minus-compile", action="store_true",
                    help="case costs without their compile time (to simulate warm runs from a cold run's store)")
    ap.add_argument("--json", action="store_true", help="print JSON instead of a table")
    args = ap.parse_args(argv)
    for flag, v in (("--worker-start", args.worker_start), ("--per-case", args.per_case)):
        if not (math.isfinite(v) and v >= 0):
            print(f"bench-myriapoda: {flag}: {v} is out of range; must be a finite number of seconds >= 0", file=sys.stderr)
            return 2
    if any(w < 1 for w in args.workers):
        print("bench-myriapoda: --workers: every count must be >= 1", file=sys.stderr)
        return 2
    report = []
    for d in args.dirs:
        if not (Path(d) / "results.sqlite").is_file():
            print(f"bench-myriapoda: {d}: no results.sqlite; give a matrix output directory", file=sys.stderr)
            return 2
        walls = stored_case_walls(d, args.minus_compile)
        costs = list(walls.values())
        sims = [simulate(costs, w, args.worker_start, args.per_case) for w in args.workers]
        sched = {}
        m = Path(d) / "matrix.json"
        if m.is_file():
            sched = json.loads(m.read_text()).get("schedule", {}) or {}
        pred = {h: c.get("predicted_s") for h, c in sched.get("cases", {}).items() if c.get("predicted_s")}
        pairs = [(pred[h], w) for h, w in walls.items() if h in pred]
        r = correlation([p for p, _ in pairs], [w for _, w in pairs])
        report.append({"dir": str(d), "cases": len(costs), "sum_s": sum(costs), "critical_s": max(costs, default=0.0),
                       "predicted_vs_measured_r": r if math.isfinite(r) else None, "pairs": len(pairs),
                       "simulated": [{"workers": s.workers, "wall_s": s.wall_s, "efficiency": s.efficiency}
                                     for s in sims]})
    if args.json:
        print(json.dumps(report, indent=1))
        return 0
    for rep in report:
        r = rep["predicted_vs_measured_r"]
        print(f"{rep['dir']}: {rep['cases']} cases, {rep['sum_s']:.1f} s of cases, critical path {rep['critical_s']:.1f} s; "
              f"predicted vs measured case cost r = {'-' if r is None else f'{r:.3f}'} ({rep['pairs']} cases)")
        for s in rep["simulated"]:
            print(f"  {s['workers']:>3} worker(s): {s['wall_s']:7.1f} s  (efficiency {s['efficiency']:.0%})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
