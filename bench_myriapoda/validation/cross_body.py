"""Cross-body agreement: the same creature, gait and scenario on every body model.

Where the physics should agree (the worm's speed follows eps * Lambda f on any body that anchors
its compressed points; the centipede's speed and phase lag are set by the leg controller, which
carries the supported segments kinematically), the bodies must agree within a stated tolerance.
Where it should not (a hanging centipede: the fem body's blocks are elastic, 20x stiffer than
the links and twice as long, while the hybrid's boxes are rigid), the expected difference is stated
and checked.
"""
from __future__ import annotations

import math

from .core import ALL_BODIES, Context, Outcome, failed_run, holds, not_applicable
from .paper import WALK_DURATION_S

WORM_SPEED_REL_SPREAD = 0.15      # (max - min) / max of speed_bl_per_cycle over the bodies
CENTIPEDE_SPEED_REL_SPREAD = 0.10
PHASE_LAG_ABS_SPREAD = 0.03       # [cycles]
# fem / hybrid hanging elongation: the fem blocks add compliance 2 (length) / 20 (stiffness) = 10 %
# of the links'; the ratio must lie in this range (the extra head-block compliance allows up to 30 %)
HANG_RATIO_RANGE = (1.0, 1.3)


def _bodies(ctx: Context) -> tuple[str, ...]:
    return tuple(b for b in ALL_BODIES if b in ctx.bodies)


def _spread(ctx: Context, metric: str, runs: dict, tol: float, relative_spread: bool, unit: str) -> Outcome:
    vals = {}
    for b, r in runs.items():
        if r.status != "ok":
            return failed_run(r)
        vals[b] = r.metrics.get(metric, math.nan)
    if len(vals) < 2:
        return not_applicable("needs at least two body models (--body)")
    hi, lo = max(vals.values()), min(vals.values())
    spread = (hi - lo) / abs(hi) if relative_spread else hi - lo
    tol_txt = f"spread <= {100 * tol:g} % of the largest" if relative_spread else f"spread <= {tol:g} {unit}"
    return holds(math.isfinite(spread) and spread <= tol, round(spread, 4), 0.0, tol_txt,
                 "; ".join(f"{b} {v:.4g}" for b, v in vals.items()), "" if relative_spread else unit,
                 **{f"{metric}.{b}": v for b, v in vals.items()})


def worm_speed(ctx: Context, body: str) -> Outcome:
    """The rectilinear worm's speed [BL/cycle] agrees across body models."""
    dur = 16.0 if ctx.quick else 30.0
    runs = {b: ctx.run("worm", b, "flat", duration=dur) for b in _bodies(ctx)}
    return _spread(ctx, "speed_bl_per_cycle", runs, WORM_SPEED_REL_SPREAD, True, "BL/cycle")


def centipede_speed(ctx: Context, body: str) -> Outcome:
    """The walking centipede's speed [m/s] agrees across body models."""
    runs = {b: ctx.run("centipede", b, "walk", duration=WALK_DURATION_S) for b in _bodies(ctx)}
    return _spread(ctx, "speed_m_per_s", runs, CENTIPEDE_SPEED_REL_SPREAD, True, "m/s")


def centipede_phase_lag(ctx: Context, body: str) -> Outcome:
    """The walking centipede's mean phase lag [cycles] agrees across body models."""
    runs = {b: ctx.run("centipede", b, "walk", duration=WALK_DURATION_S) for b in _bodies(ctx)}
    return _spread(ctx, "phase_lag_mean", runs, PHASE_LAG_ABS_SPREAD, False, "cycles")


HANG_SETTLE_S = 0.5  # the static elongation: the time mean after the first quarter-oscillation


def static_elongation(r, settle_s: float = HANG_SETTLE_S) -> float:
    """Static elongation of a body hanging by its head [m]: the time mean, from ``settle_s`` on, of
    the head-to-tail segment distance minus its value at t = 0.

    Released at its rest length, the body oscillates about its static stretch between about 0
    and twice it: App. A's gamma / E = 1/80 s damps the chain's axial mode (period ~0.8 s for the
    centipede) by a few percent per period.  ``hanging_elongation_m`` (the mean over the last
    10 % of the samples) then reads a phase of that oscillation: the 6.9x fem / hybrid ratio this
    check used to report was one (fem 31 cm near a crest, hybrid 4.6 cm near a trough; issue 11).
    """
    import numpy as np

    s = r.series
    d = np.linalg.norm(s.segment_centers[:, 0] - s.segment_centers[:, -1], axis=1)
    t = np.asarray(s.t)
    keep = t >= settle_s
    return float(d[keep].mean() - d[0]) if keep.any() else math.nan


def hang_elongation_difference(ctx: Context, body: str) -> Outcome:
    """Expected difference: hanging by the head, the fem centipede stretches 10-30 % more than the hybrid
    (static elongations, ``static_elongation``)."""
    if not {"fem", "hybrid"} <= set(ctx.bodies):
        return not_applicable("compares the fem and hybrid bodies; select both (--body)")
    rf = ctx.run("centipede", "fem", "hang", duration=3.0)
    rh = ctx.run("centipede", "hybrid", "hang", duration=3.0)
    for r in (rf, rh):
        if r.status != "ok":
            return failed_run(r)
    ef, eh = static_elongation(rf), static_elongation(rh)
    ratio = ef / eh if eh else math.nan
    lo, hi = HANG_RATIO_RANGE
    return holds(lo <= ratio <= hi, round(ratio, 3), f"{lo:g} to {hi:g}", "inside the range",
                 f"static elongation fem {ef * 100:.2f} cm, hybrid {eh * 100:.2f} cm (rigid boxes vs 20x stiffer "
                 f"blocks)",
                 fem_m=ef, hybrid_m=eh)
