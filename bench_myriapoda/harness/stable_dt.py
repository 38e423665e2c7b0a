"""The largest stable time step of a case, by bracketing and bisection.

A time step is *stable* when the case runs its whole duration with status
``ok`` (no non-finite state, runaway speed or deep penetration).  Starting
from the case's own dt, the search doubles dt until a run fails (or halves it
until one succeeds), then bisects in log space until the bracket is tighter
than ``rel_tol``.  Stability is not always monotone in dt; the result is the
largest stable dt found below the smallest unstable one, as bisection sees it.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Callable

from ..core.config import Case
from ..core.source_hash import SOURCE_HASH
from ..jit.worker_start import worker_context
from .runner import run_case, run_world


@dataclass
class StableDtResult:
    stable_dt_max_s: float          # NaN when even the smallest dt tried was unstable
    unstable_dt_min_s: float        # NaN when no unstable dt was found up to the ceiling
    trials: list[tuple[float, str, float]]  # (dt, status, t_fail_s)
    error: str = ""  # the message of a trial run that ended with status error (the search stopped there)


def find_stable_dt(case: Case, rel_tol: float = 0.05, max_runs: int = 24, dt_floor: float = 1e-7,
                   dt_ceiling: float | None = None,
                   progress: Callable[[float, str], None] | None = None, world=None,
                   known: dict | None = None) -> StableDtResult:
    """Bisect dt for ``case`` (its duration and everything else fixed).  ``world``: the case's
    ``world.world.World`` (it does not depend on dt), built once (``runner.run_world``) when None and shared by
    every trial.  ``known``: dt -> a ``RunResult`` of this case already run at that dt (its trial is not run again)."""
    world = run_world(case, None, world)
    ceiling = dt_ceiling if dt_ceiling is not None else case.duration / 20.0
    trials: list[tuple[float, str, float]] = []

    class _TrialError(Exception):
        pass

    def stable(dt: float) -> bool:
        r = (known or {}).get(dt) or run_case(dataclasses.replace(case, dt=dt), world=world)
        trials.append((dt, r.status, r.metrics.get("t_fail_s", float("nan"))))
        if progress is not None:
            progress(dt, r.status)
        if r.status == "error":  # neither stable nor unstable: the search cannot go on
            raise _TrialError(f"the run at dt = {dt:g} s failed: {r.message}")
        return r.status == "ok"

    try:
        return _search(case, stable, trials, rel_tol, max_runs, dt_floor, ceiling)
    except _TrialError as exc:
        return StableDtResult(math.nan, math.nan, trials, str(exc))


def _search(case: Case, stable, trials, rel_tol: float, max_runs: int, dt_floor: float,
            ceiling: float) -> StableDtResult:
    """Bracket, then bisect (see the module docstring); ``stable(dt)`` runs one trial."""
    lo, hi = math.nan, math.nan
    dt = min(case.dt, ceiling)
    if stable(dt):
        lo = dt
        while len(trials) < max_runs and lo * 2 <= ceiling:
            if stable(lo * 2):
                lo *= 2
            else:
                hi = lo * 2
                break
    else:
        hi = dt
        while len(trials) < max_runs and hi / 2 >= dt_floor:
            if stable(hi / 2):
                lo = hi / 2
                break
            hi /= 2
    if math.isnan(lo) or math.isnan(hi):
        return StableDtResult(lo, hi, trials)
    while hi / lo > 1.0 + rel_tol and len(trials) < max_runs:
        mid = math.sqrt(lo * hi)
        if stable(mid):
            lo = mid
        else:
            hi = mid
    return StableDtResult(lo, hi, trials)


# --------------------------------------------------------------------------- the main job's brackets
# The scorecard's stability cell of every headline pair: [largest stable, smallest unstable] dt, bisected to
# BRACKET_REL_TOL on runs of BRACKET_DURATION_S, and its cost cell: the same run at the default dt, timed
# TIMED_REPEATS times (a blow-up of a too-large dt shows within the first tenths of a
# second; every trial that stays stable costs the whole duration, so the runs are short).  A bracket is kept in
# the matrix directory's BRACKETS_NAME under a key of the trial case's hash and the package's source hash: a
# rerun of the same code finds it and runs nothing, an edit of any source file bisects again.

BRACKET_REL_TOL = 0.10
BRACKET_DURATION_S = 1.0
BRACKET_MAX_RUNS = 12
BRACKETS_NAME = "stable_dt.json"
TIMED_REPEATS = 3  # runs of the trial case at its default dt, timed: the scorecard's cost and its spread


def source_hash() -> str:
    """The hash of every source file of the package (the key of its numba cache directory, ``core.source_hash``)."""
    return SOURCE_HASH


def bracket_case(case: Case) -> Case:
    """The trial case of ``case``'s bracket: the same case, BRACKET_DURATION_S long (never longer than it)."""
    return dataclasses.replace(case, duration=min(case.duration, BRACKET_DURATION_S))


def bracket_key(case: Case, code: str) -> str:
    """The cache key of ``case``'s bracket: the trial case's hash, the tolerance and the source hash ``code``."""
    return f"{bracket_case(case).case_hash()}:{BRACKET_REL_TOL:g}:{TIMED_REPEATS}:{code}"


def bracket_entry(case: Case) -> dict:
    """Time ``bracket_case(case)`` TIMED_REPEATS times at its default dt, then bisect it (the first of those runs
    is the bisection's first trial); return the JSON entry the scorecard reads (dt in s; None: not found).
    Anything that raises is an entry with its ``error`` (never raised: the other pairs' brackets are kept)."""
    try:
        return _bracket_entry(case)
    except Exception as exc:  # a bug or an unforeseen failure: said in the cell, never a crash of the main job
        return failed_entry(case, f"{type(exc).__name__}: {exc}")


def failed_entry(case: Case, error: str) -> dict:
    """The entry of a bracket that could not be found (``error`` says why)."""
    return {"case_hash": case.case_hash(), "creature": case.creature.name, "body": case.body.name,
            "scenario": case.scenario.name, "default_dt_s": float(case.dt),
            "trial_duration_s": float(bracket_case(case).duration), "rel_tol": BRACKET_REL_TOL,
            "stable_dt_max_s": None, "unstable_dt_min_s": None, "trials": [], "error": error,
            "timed_cpu_s_per_sim_s": [], "timed_steps_per_s": [], "cpu_s": 0.0}


def _bracket_entry(case: Case) -> dict:
    import time

    trial = bracket_case(case)
    t0 = time.process_time()
    world = run_world(trial)  # built once, shared by the timed repeats and the bisection
    repeats = [run_case(trial, world=world) for _ in range(TIMED_REPEATS)]
    res = find_stable_dt(trial, rel_tol=BRACKET_REL_TOL, max_runs=BRACKET_MAX_RUNS, world=world,
                         known={trial.dt: repeats[0]})

    def num(x):
        return None if x is None or not math.isfinite(x) else float(x)

    timed = [r for r in repeats if r.status == "ok" and num(r.timings.get("realtime_factor"))]

    return {"case_hash": case.case_hash(), "creature": case.creature.name, "body": case.body.name,
            "scenario": case.scenario.name,
            "default_dt_s": float(case.dt), "trial_duration_s": float(trial.duration), "rel_tol": BRACKET_REL_TOL,
            "stable_dt_max_s": num(res.stable_dt_max_s), "unstable_dt_min_s": num(res.unstable_dt_min_s),
            "trials": [[float(dt), st, num(tf)] for dt, st, tf in res.trials], "error": res.error,
            # the timed repeats: CPU s per simulated s of each run at the default dt (1 / realtime factor; the
            # kernel's stepping time, compile excluded) and its steps/s
            "timed_cpu_s_per_sim_s": [1.0 / float(r.timings["realtime_factor"]) for r in timed],
            "timed_steps_per_s": [float(r.timings["steps_per_s"]) for r in timed],
            "cpu_s": time.process_time() - t0}


def read_brackets(directory) -> dict:
    """The brackets kept in ``directory`` (key -> entry; empty when there is no readable file).  An entry:
    case_hash (the headline case's), creature, body, scenario, default_dt_s, trial_duration_s, rel_tol,
    stable_dt_max_s, unstable_dt_min_s (None: not found), trials [[dt, status, t_fail_s]], error, cpu_s, code."""
    import json
    from pathlib import Path

    path = Path(directory) / BRACKETS_NAME
    try:
        doc = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    entries = doc.get("entries") if isinstance(doc, dict) else None
    return entries if isinstance(entries, dict) else {}


def brackets_for_cases(cases: list[Case], directory, workers: int = 1,
                       progress: Callable[[str], None] | None = None, pool=None) -> dict[str, dict]:
    """The bracket of every case (case_hash -> entry), bisecting the ones ``directory`` does not keep yet on
    ``workers`` processes (or on ``pool``, a ``concurrent.futures`` executor), then writing them all back (to
    a temporary name, then renamed).  Returns the entries of ``cases`` only; other entries in the file stay."""
    import json
    from pathlib import Path

    code = source_hash()
    kept = read_brackets(directory)
    todo = [c for c in cases if bracket_key(c, code) not in kept]
    if todo:
        if progress is not None:
            progress(f"bisecting the stable dt of {len(todo)} pair(s) ({len(cases) - len(todo)} kept)")
        if pool is not None:
            try:
                found = list(pool.map(bracket_entry, todo))
            except Exception as exc:  # a worker died (BrokenProcessPool): every missing bracket says so
                found = [failed_entry(c, f"the worker process failed: {type(exc).__name__}: {exc}") for c in todo]
        elif workers > 1 and len(todo) > 1:
            from concurrent.futures import ProcessPoolExecutor

            with ProcessPoolExecutor(max_workers=min(workers, len(todo)), mp_context=worker_context()) as pool:
                found = list(pool.map(bracket_entry, todo))
        else:
            found = [bracket_entry(c) for c in todo]
        for c, e in zip(todo, found):  # a failed bisection is shown, not kept: the next run tries again
            if not e.get("error"):
                kept[bracket_key(c, code)] = {**e, "code": code}
        path = Path(directory) / BRACKETS_NAME
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".json.tmp")
        tmp.write_text(json.dumps({"entries": kept}, indent=1))
        tmp.replace(path)
    failed = {c.case_hash(): e for c, e in zip(todo, found) if e.get("error")} if todo else {}
    return {c.case_hash(): failed.get(c.case_hash()) or kept[bracket_key(c, code)] for c in cases}


def brackets_by_case(directory) -> dict[str, dict]:
    """The brackets kept in ``directory`` by headline case hash; of several (older code), the current code's."""
    code = source_hash()
    out: dict[str, dict] = {}
    for e in read_brackets(directory).values():
        if not isinstance(e, dict) or "case_hash" not in e:
            continue
        h = e["case_hash"]
        if h not in out or e.get("code") == code:
            out[h] = e
    return out
