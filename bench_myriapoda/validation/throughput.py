"""The myriapod paper's Sec. 6 throughput headline set against the measured figure (informational).

The paper: an 18-segment centipede with a 3 x 3 x 3 deformable mesh at dt = 1/3000 s runs at
1.7e4 steps/s on a 6-core 3.2 GHz i7 with OpenMP.  Here: one core of this machine, a single run,
the hybrid centipede's walk (the same run as Fig. 10 D).  Machines differ, so the verdict is INFO.
"""
from __future__ import annotations

import math

from .core import INFO, Context, Outcome, failed_run

PAPER_STEPS_PER_S = 1.7e4
PAPER_CORES = 6


def sec6_headline(ctx: Context, body: str) -> Outcome:
    from .paper import WALK_DURATION_S

    src = f"{PAPER_STEPS_PER_S:.2g} steps/s, 18 segments, dt = 1/3000 s, {PAPER_CORES} cores (Sec. 6)"
    r = ctx.run("centipede", body, "walk", duration=WALK_DURATION_S)
    if r.status != "ok":
        return failed_run(r, src)
    sps = r.timings.get("steps_per_s", math.nan)
    dt = r.case.dt
    seg = r.case.creature.segments
    ratio = sps / PAPER_STEPS_PER_S
    per_core = sps / (PAPER_STEPS_PER_S / PAPER_CORES)
    return Outcome(INFO, round(sps), PAPER_STEPS_PER_S, "informational (other machine, 6 cores vs 1)",
                   f"{seg} segments, dt = {dt:.3g} s, one core: {ratio:.2f} x the paper, {per_core:.2f} x its "
                   f"per-core figure; {sps * dt:.2f} x real time", "steps/s",
                   {"ratio": ratio, "per_core_ratio": per_core, "realtime_factor": sps * dt})
