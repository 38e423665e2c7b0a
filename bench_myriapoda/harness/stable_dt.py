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
from .runner import run_case, run_world


@dataclass
class StableDtResult:
    stable_dt_max_s: float          # NaN when even the smallest dt tried was unstable
    unstable_dt_min_s: float        # NaN when no unstable dt was found up to the ceiling
    trials: list[tuple[float, str, float]]  # (dt, status, t_fail_s)
    error: str = ""  # the message of a trial run that ended with status error (the search stopped there)


def find_stable_dt(case: Case, rel_tol: float = 0.05, max_runs: int = 24, dt_floor: float = 1e-7,
                   dt_ceiling: float | None = None,
                   progress: Callable[[float, str], None] | None = None, world=None) -> StableDtResult:
    """Bisect dt for ``case`` (its duration and everything else fixed).  ``world``: the case's
    ``world.world.World`` (it does not depend on dt), built once (``runner.run_world``) when None and shared by every trial."""
    world = run_world(case, None, world)
    ceiling = dt_ceiling if dt_ceiling is not None else case.duration / 20.0
    trials: list[tuple[float, str, float]] = []

    class _TrialError(Exception):
        pass

    def stable(dt: float) -> bool:
        r = run_case(dataclasses.replace(case, dt=dt), world=world)
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
