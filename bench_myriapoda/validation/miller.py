"""Miller 1988, image by image, and the kinematic slithering reference (Hu et al. 2009).

Image 1 (worm on the book and over the edge), Image 2 (the undulating snake: coils form and the
segments follow one path), Image 3 (the sidewinder travels diagonally and reverses with the phase),
Image 4 (the caterpillar climbs a slope without sliding back).

Helper branch i11a adds ``bench_myriapoda/reference/miller_images.py`` (per-image check functions)
and ``bench_myriapoda/reference/slithering.py`` (``steady_slithering``).  When they are present the
checks use them; the image checks otherwise use the criteria below (from tests/ and
shared/reference/VALIDATION.md), and the slithering check reports NOT APPLICABLE with the reason.
"""
from __future__ import annotations

import importlib
import math

import numpy as np

from .core import Context, Outcome, failed_run, holds, not_applicable, relative

MILLER = "Miller 1988"
PATH_FOLLOWING_MAX_BL = 0.05      # Image 2: segments within 5 % of a body length of the head's path
SNAKE_MIN_BL_PER_CYCLE = 0.02     # ... while it really moves (VALIDATION.md: isotropic snake stays below this)
SIDEWINDER_MIN_ANGLE_DEG = 45.0   # Image 3: diagonal travel
SIDEWINDER_REVERSAL_RATIO = 0.5   # the reversed gait's sideways speed at least half the forward one's
SLITHERING_REL_TOL = 0.25         # dynamic snake vs the inertia-free kinematic model (Fr small, not zero)
SLITHERING_RATIOS = (2.0, 4.0, 8.0)  # mu_t / mu_f of the sweep
SLITHERING_MU_F = 0.1


def optional_reference(module: str):
    """``bench_myriapoda.reference.<module>`` or None when it is not there (helper branch i11a)."""
    try:
        return importlib.import_module(f"bench_myriapoda.reference.{module}")
    except ImportError:
        return None


def _external(name: str, result, body: str) -> Outcome | None:
    """Use i11a's image check ``name`` when ``reference.miller_images`` provides it."""
    mod = optional_reference("miller_images")
    fn = getattr(mod, name, None) if mod is not None else None
    if fn is None:
        return None
    out = fn(result)
    ok = bool(getattr(out, "passed", getattr(out, "ok", out)))
    return holds(ok, getattr(out, "measured", None), getattr(out, "reference", None),
                 getattr(out, "tolerance", "reference.miller_images"), str(getattr(out, "detail", "")))


# --------------------------------------------------------------------------- Image 1

def image1_worm_book(ctx: Context, body: str) -> Outcome:
    """Image 1: the worm lands on the book, crawls to its edge and slides off onto the floor."""
    ref = "ends below half the book height, past the edge (Image 1 a-d)"
    r = ctx.run("worm", body, "cliff", duration=20.0 if ctx.quick else 30.0)
    if r.status != "ok":
        return failed_run(r, ref)
    ext = _external("image1_worm_book", r, body)
    if ext is not None:
        return ext
    return judge_worm_book(r.series.com, r.case.scenario)


def judge_worm_book(com, sc) -> Outcome:
    """Image 1 criteria on the centre of mass path com (T, 3) [m] and the cliff scenario ``sc``."""
    ref = "ends below half the book height, past the edge (Image 1 a-d)"
    com = np.asarray(com)
    ok = com[0, 1] > sc.slab_height_m and com[-1, 1] < 0.5 * sc.slab_height_m and com[-1, 0] > sc.slab_edge_x_m
    return holds(bool(ok), f"COM height {com[-1, 1] * 100:.1f} cm at x = {com[-1, 0] * 100:+.1f} cm", ref,
                 f"height < {0.5 * sc.slab_height_m * 100:g} cm, x > edge",
                 f"started at height {com[0, 1] * 100:.1f} cm; book {sc.slab_height_m * 100:g} cm",
                 final_height_m=float(com[-1, 1]), final_x_m=float(com[-1, 0]))


# --------------------------------------------------------------------------- Image 2

def image2_snake_coils(ctx: Context, body: str) -> Outcome:
    """Image 2: once the coils form the snake moves forward and its segments follow one path."""
    ref = f"path-following error <= {PATH_FOLLOWING_MAX_BL:g} BL while moving >= {SNAKE_MIN_BL_PER_CYCLE:g} BL/cycle"
    r = ctx.run("snake", body, "flat", "lateral-undulation", duration=8.0 if ctx.quick else 16.0)
    if r.status != "ok":
        return failed_run(r, ref)
    ext = _external("image2_snake_coils", r, body)
    if ext is not None:
        return ext
    return judge_snake_coils(r.metrics)


def judge_snake_coils(m: dict) -> Outcome:
    """Image 2 criteria on a snake run's metrics."""
    ref = f"path-following error <= {PATH_FOLLOWING_MAX_BL:g} BL while moving >= {SNAKE_MIN_BL_PER_CYCLE:g} BL/cycle"
    pf = m.get("path_following_error_bl", math.nan)
    v = m.get("speed_bl_per_cycle", math.nan)
    ok = pf <= PATH_FOLLOWING_MAX_BL and v >= SNAKE_MIN_BL_PER_CYCLE
    return holds(bool(ok), f"{pf:.3f} BL at {v:.3f} BL/cycle", ref, "both bounds",
                 f"speed {m.get('speed_m_per_s', math.nan):.4f} m/s", "",
                 path_following_error_bl=pf, speed_bl_per_cycle=v)


# --------------------------------------------------------------------------- Image 3

def image3_sidewinder(ctx: Context, body: str) -> Outcome:
    """Image 3: the sidewinder travels diagonally; flipping the phase of the vertical wave reverses it."""
    ref = f"|travel angle| > {SIDEWINDER_MIN_ANGLE_DEG:g} deg, reverses with the phase (Image 3; Astley et al. 2015)"
    dur = 8.0 if ctx.quick else 16.0
    plus = ctx.run("snake", body, "flat", "sidewinding", duration=dur)
    minus = ctx.run("snake", body, "flat", "sidewinding", duration=dur, overrides=("gait.vertical_phase_deg=-90",))
    for r in (plus, minus):
        if r.status != "ok":
            return failed_run(r, ref)
    ext = _external("image3_sidewinder", plus, body)
    if ext is not None:
        return ext
    ang = plus.metrics.get("travel_angle_deg", math.nan)
    lp, lm = plus.metrics.get("lateral_speed_m_per_s", math.nan), minus.metrics.get("lateral_speed_m_per_s", math.nan)
    reverses = lp * lm < 0 and min(abs(lp), abs(lm)) > SIDEWINDER_REVERSAL_RATIO * max(abs(lp), abs(lm))
    ok = abs(ang) > SIDEWINDER_MIN_ANGLE_DEG and reverses
    return holds(bool(ok), f"{ang:+.1f} deg", f"> {SIDEWINDER_MIN_ANGLE_DEG:g} deg, reversing", "angle and reversal",
                 f"sideways speed {lp:+.4f} m/s, with the phase flipped {lm:+.4f} m/s", "deg",
                 travel_angle_deg=ang, lateral_plus=lp, lateral_minus=lm)


# --------------------------------------------------------------------------- Image 4

def image4_caterpillar_slope(ctx: Context, body: str) -> Outcome:
    """Image 4: with no tangential motion in contact the caterpillar climbs a 30 degree slope every cycle."""
    ref = "progress up the slope in every gait cycle after the ramp (Image 4; VALIDATION.md)"
    r = ctx.run("caterpillar", body, "slope", duration=10.0 if ctx.quick else 16.0,
                overrides=("scenario.slope_deg=30",))
    if r.status != "ok":
        return failed_run(r, ref)
    ext = _external("image4_caterpillar_slope", r, body)
    if ext is not None:
        return ext
    return judge_caterpillar_slope(r.series.t, r.series.com, r.case.gait.period_s, 30.0,
                                   r.metrics.get("speed_bl_per_cycle", math.nan))


def judge_caterpillar_slope(t, com, period_s: float, slope_deg: float, speed_bl_per_cycle: float = math.nan) -> Outcome:
    """Image 4 criterion: progress up the slope in every gait cycle after the first two."""
    a = math.radians(slope_deg)
    progress = np.asarray(com) @ np.array([math.cos(a), math.sin(a), 0.0])
    t = np.asarray(t)
    idx = [int(np.searchsorted(t, k * period_s)) for k in range(2, int(t[-1] / period_s))]
    per_cycle = np.diff(progress[idx]) if len(idx) > 1 else np.array([])
    if per_cycle.size == 0:
        return not_applicable(f"the run ({t[-1]:.1f} s) holds no complete cycle after two {period_s:g} s cycles")
    ok = bool(np.all(per_cycle > 0.0))
    worst = float(per_cycle.min())
    return holds(ok, f"min {worst * 1000:+.1f} mm/cycle", "> 0 every cycle", "> 0",
                 f"{per_cycle.size} cycles on {slope_deg:g} deg; speed {speed_bl_per_cycle:.3f} BL/cycle", "m",
                 min_progress_per_cycle_m=worst)


# --------------------------------------------------------------------------- slithering reference

def slithering(ctx: Context, body: str) -> Outcome:
    """The snake's forward speed over a mu_t / mu_f sweep against the kinematic model of Hu et al. 2009."""
    mod = optional_reference("slithering")
    src = "Hu et al. 2009 kinematic model (reference.slithering.steady_slithering)"
    if mod is None or not hasattr(mod, "steady_slithering"):
        return not_applicable("bench_myriapoda.reference.slithering (helper branch i11a) is not on this branch",
                              src, f"{100 * SLITHERING_REL_TOL:g} % relative")
    ratios = SLITHERING_RATIOS[1:] if ctx.quick else SLITHERING_RATIOS
    measured, reference = [], []
    for ratio in ratios:
        over = ("friction.model=coulomb", f"friction.mu_forward={SLITHERING_MU_F}", "friction.mu_backward=0.3",
                f"friction.mu_transverse={ratio * SLITHERING_MU_F}")
        r = ctx.run("snake", body, "flat", "lateral-undulation", duration=8.0 if ctx.quick else 16.0, overrides=over)
        if r.status != "ok":
            return failed_run(r, src)
        g = r.case.gait
        curvature = getattr(g, "curvature_amplitude", None)
        if curvature is None:  # the lateral fibre strain a of a body of width w bends it with curvature 2 a / w
            curvature = 2.0 * g.amplitude / r.case.creature.width_m * r.case.creature.body_length_m
        ref = mod.steady_slithering(curvature, g.wavelength_bl, SLITHERING_MU_F, 0.3,
                                    ratio * SLITHERING_MU_F).speed_bl_per_cycle
        measured.append(r.metrics["speed_bl_per_cycle"])
        reference.append(float(ref))
    err = max(abs(m - f) / abs(f) for m, f in zip(measured, reference))
    out = relative(measured[-1], reference[-1], SLITHERING_REL_TOL, "BL/cycle",
                   detail="mu_t/mu_f " + ", ".join(f"{q:g}: {m:.3f} vs {f:.3f}" for q, m, f in
                                                    zip(ratios, measured, reference)) + f"; worst {err:.2f}")
    ok = err <= SLITHERING_REL_TOL
    return Outcome("PASS" if ok else "FAIL", measured[-1], reference[-1], out.tolerance, out.detail, out.unit,
                   {"worst_rel_error": err})
