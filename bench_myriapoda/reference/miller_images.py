"""Miller's Images 1 to 4 (Miller 1988, "The motion dynamics of snakes and worms", Sec. 4) as checks.

The paper describes, image by image, what its creatures do.  Each described behaviour becomes
one measurable check on a recorded run: a function ``(series, case, metrics) -> ImageCheck``
with the measured value, what is expected and whether it passed.  ``RUNS`` says which run each
check reads (creature, scenario, gait, duration, overrides: the suite's presets); a caller runs
it on any body (``harness.runner.run_case(core.config.resolve_case(...))``) and calls
``evaluate(run_key, series, case, metrics)``.  This module never runs a body itself.

Images and checks (Miller's words in quotes):

* Image 1, the worm on a book (scenario ``cliff``: a slab with a rounded edge):
  1a "in free-fall colliding with the constraint ... The nose slides forwards on impact":
     the head's forward travel in the ``IMPACT_WINDOW_S`` after the first contact > 0.
  1b "the body mostly in contact": share of segments touching in the second after landing >= 0.5.
  1c "wriggling towards a vertical edge. The front begins to bend downwards under the weight":
     the head drops below the book's top by more than the worm's height while its tail is still
     on the book.
  1d "sliding off the edge. The tail flops over": at the end the whole worm is past the edge and
     rests on the floor (centre of mass within one body height of it).
* Image 2, horizontal undulatory progression (snake, ``flat``):
  2b/2c "The head-end has stayed virtually fixed while the tail is dragged forwards as the coils
     form" and "Image 2c shows the snake with the coils fully formed.  Little forward motion of the
     head-end has been achieved": from the start until the coils are fully formed, the head's
     largest displacement along x is below a quarter of the tail's forward travel.  The coils are
     fully formed at the first sample where the body's own ground curvature amplitude (peak
     curvature x body length, ``metrics.body_shape``) reaches ``COILS_FORMED`` of its steady value
     (the run's ``curvature_amplitude`` metric).  The window is measured per body because the
     bodies form their coils at different speeds under the same 2 s ramp: fem and hybrid at
     1.9-2.2 s, the heavily damped lattice (Miller's D = 3.5) at 3.0 s.  A fixed window (it was
     ramp_s + half a period = 3 s) ends at the lattice's formation but reaches 1 s into the
     progression of the other two (Image 2d's stage; their head had moved 15 / 24 cm by then).
  2d "The segments are now all very nearly following each other along the same path":
     ``path_following_error_bl`` < ``FOLLOW_MAX_BL`` while the snake advances
     (``speed_bl_per_cycle`` > ``ADVANCE_MIN_BL``).
* Image 3, the sidewinder (snake, gait ``sidewinding``, ``flat``):
  3a "The back arches and the contact with the ground is localised" (Sec. 4: the vertical
     flexing lifts "all but a small portion of the snake off the ground"):
     ``segment_contact_fraction`` < 0.5.
  3d "The diagonal nature of the locomotion is apparent": it travels (``speed`` over the
     ground > ``ADVANCE_MIN_BL`` per cycle) at a travel angle from its mean body axis between
     ``DIAGONAL_DEG``.  And its cross-sections do not roll over: ``roll_max_deg`` < 90.
* Image 4, the caterpillar (``arching``):
  4b "the caterpillar arching its back" (``flat``): the highest segment centre rises more than
     one body height above its resting height.  The preset's DORSAL wave alone, followed
     perfectly, rises 2 kappa / k^2 = 3.65 cm (kappa = 2 x 0.2 / 5 cm, wavelength 0.3 m), under
     one body height: the lattice and the fem pass through Miller's stick rule on their
     deformable bellies (a held segment that the AXIAL wave lengthens can only lengthen its back,
     so it bends upward); the hybrid's rigid box bellies cannot, and it arches 2.1 cm (README,
     validate: the measurements).
  "the ability to scale steep gradients both up the slope and down" (``slope`` at +45 and -45
  degrees, facing +x): it advances along the slope in the direction it faces by more than
  ``ADVANCE_MIN_BL`` per cycle, keeps some segment on the surface at every sample after the
  first contact (it never lets go) and never turns over end on end (its head stays ahead of its
  tail along the slope).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Mapping

import numpy as np

IMPACT_WINDOW_S = 0.1  # after the first contact: the impact, before the crawl moves the head
LANDED_WINDOW_S = (0.1, 1.1)  # after the first contact: "mostly in contact"
MOSTLY = 0.5
HEAD_TAIL_COIL_RATIO = 0.25  # "virtually fixed": head travel below a quarter of the tail's
COILS_FORMED = 0.9  # share of the steady curvature amplitude at which the coils count as "fully formed"
FOLLOW_MAX_BL = 0.05  # "very nearly following each other along the same path"
ADVANCE_MIN_BL = 0.05  # per gait cycle: "progression ... take[s] effect"
LOCALISED_CONTACT = 0.5  # "all but a small portion ... off the ground": a minority touches
DIAGONAL_DEG = (15.0, 75.0)  # |travel angle| from the mean body axis: neither along nor across it
ROLL_MAX_DEG = 90.0
STEEP_SLOPE_DEG = 45.0


@dataclass(frozen=True)
class ImageCheck:
    """One described behaviour, measured: ``passed`` when ``measured`` meets ``expected``."""

    image: str
    name: str
    measured: float
    expected: str
    passed: bool
    unit: str = ""
    quote: str = ""

    def line(self) -> str:
        mark = "pass" if self.passed else "FAIL"
        return f"Image {self.image} {self.name}: {self.measured:.4g} {self.unit} (expected {self.expected}) {mark}"


@dataclass(frozen=True)
class ImageRun:
    """The run a group of checks reads: ``resolve_case(creature, body, scenario, gait,
    duration=duration_s, overrides=overrides)`` on the body under test."""

    creature: str
    scenario: str
    gait: str | None
    duration_s: float
    overrides: tuple[str, ...] = field(default_factory=tuple)


RUNS: dict[str, ImageRun] = {
    "worm-book": ImageRun("worm", "cliff", None, 15.0),
    "snake-undulation": ImageRun("snake", "flat", "lateral-undulation", 12.0),
    "sidewinder": ImageRun("snake", "flat", "sidewinding", 12.0),
    "caterpillar-arch": ImageRun("caterpillar", "flat", None, 6.0),
    "caterpillar-up": ImageRun("caterpillar", "slope", None, 12.0, (f"scenario.slope_deg={STEEP_SLOPE_DEG}",)),
    "caterpillar-down": ImageRun("caterpillar", "slope", None, 12.0, (f"scenario.slope_deg={-STEEP_SLOPE_DEG}",)),
}


def _first_contact(series) -> int:
    touching = series.segment_contact.any(axis=1)
    if not touching.any():
        raise ValueError("the body never touched the ground")
    return int(np.argmax(touching))


def _window(series, start: int, t0: float, t1: float) -> slice:
    t = series.t
    return slice(int(np.searchsorted(t, t[start] + t0)), int(np.searchsorted(t, t[start] + t1, side="right")))


def _body_length(case, metrics) -> float:
    return float(metrics.get("body_length_m", case.creature.body_length_m))


# ----------------------------------------------------------------------------- Image 1: the worm

def worm_nose_slides_forward(series, case, metrics) -> ImageCheck:
    k = _first_contact(series)
    w = _window(series, k, 0.0, IMPACT_WINDOW_S)
    dx = float(series.head[w.stop - 1, 0] - series.head[k, 0])
    return ImageCheck("1a", "nose slides forward on impact", dx, "> 0", dx > 0.0, "m",
                      "The nose slides forwards on impact.")


def worm_mostly_in_contact(series, case, metrics) -> ImageCheck:
    k = _first_contact(series)
    share = float(series.segment_contact[_window(series, k, *LANDED_WINDOW_S)].mean())
    return ImageCheck("1b", "body mostly in contact after landing", share, f">= {MOSTLY}", share >= MOSTLY,
                      "share of segments", "Image 1b shows the body mostly in contact.")


def worm_front_bends_over_edge(series, case, metrics) -> ImageCheck:
    sc = case.scenario
    top = sc.ground_height_m + sc.slab_height_m
    tail_on_book = series.tail[:, 0] < sc.slab_edge_x_m
    drop = np.where(tail_on_book, top - series.head[:, 1], -np.inf)
    measured = float(drop.max()) if tail_on_book.any() else float("nan")
    need = case.creature.height_m
    return ImageCheck("1c", "front bends down over the edge while the tail is on the book", measured,
                      f"> {need:g} (the worm's height)", measured > need, "m",
                      "The front begins to bend downwards under the weight.")


def worm_slides_off_edge(series, case, metrics) -> ImageCheck:
    sc = case.scenario
    past = bool(series.segment_centers[-1][:, 0].min() > sc.slab_edge_x_m)
    height = float(series.com[-1, 1] - sc.ground_height_m)
    need = case.creature.height_m
    ok = past and height < need
    return ImageCheck("1d", "slid off the edge onto the floor", height,
                      f"< {need:g} above the floor, every segment past the edge", ok, "m",
                      "Image 1d shows the worm sliding off the edge.")


# ----------------------------------------------------------------------------- Image 2: undulation

def coils_formed_index(series, case, metrics) -> int:
    """Index of the first sample at which the coils are fully formed (Image 2c): the ground
    curvature amplitude, sqrt(2) x the RMS over the interior segment centres of the curvature
    [1/m] x body length [m], reaches ``COILS_FORMED`` x the run's steady ``curvature_amplitude``.
    Without that metric (or if never reached) the old fixed window end, ramp_s + half a period."""
    from ..metrics.body_shape import ground_curvature, pitch_stride

    g = case.gait
    fallback = min(int(np.searchsorted(series.t, g.ramp_s + 0.5 * g.period_s)), len(series.t) - 1)
    steady = float(metrics.get("curvature_amplitude", float("nan")))
    if series.segment_centers is None or series.segment_centers.shape[1] < 4 or not steady > 0:
        return fallback
    # through the same points as the steady figure (one segment pitch apart: the hybrid's boxes; every centre
    # where the case names no pitch)
    centers = series.segment_centers
    pitch = getattr(case.creature, "segment_length_m", None)
    stride = pitch_stride(centers[0], float(pitch)) if pitch else 1
    kappa, _ = ground_curvature(centers[:, ::stride])
    amp = math.sqrt(2.0) * np.sqrt((kappa ** 2).mean(axis=1)) * _body_length(case, metrics)
    formed = amp >= COILS_FORMED * steady
    return int(np.argmax(formed)) if formed.any() else fallback


def snake_head_fixed_while_coils_form(series, case, metrics) -> ImageCheck:
    k = coils_formed_index(series, case, metrics)
    head = np.abs(series.head[:k + 1, 0] - series.head[0, 0]).max()  # "stayed virtually fixed": at every sample
    tail = float(series.tail[k, 0] - series.tail[0, 0])
    ratio = float(head) / tail if tail > 0 else float("inf")
    return ImageCheck("2b", "head virtually fixed, tail dragged forward as the coils form", ratio,
                      f"< {HEAD_TAIL_COIL_RATIO} (head's largest / tail's forward travel until the coils "
                      f"formed at {series.t[k]:.2f} s)",
                      ratio < HEAD_TAIL_COIL_RATIO, "",
                      "The head-end has stayed virtually fixed while the tail is dragged forwards as the coils form.")


def snake_segments_follow_one_path(series, case, metrics) -> ImageCheck:
    err = float(metrics.get("path_following_error_bl", float("nan")))
    speed = float(metrics.get("speed_bl_per_cycle", float("nan")))
    ok = err < FOLLOW_MAX_BL and speed > ADVANCE_MIN_BL
    return ImageCheck("2d", "segments follow each other along the same path", err,
                      f"< {FOLLOW_MAX_BL} BL while advancing > {ADVANCE_MIN_BL} BL/cycle (speed {speed:.3g})",
                      ok, "BL", "The segments are now all very nearly following each other along the same path.")


# ----------------------------------------------------------------------------- Image 3: sidewinding

def sidewinder_contact_localised(series, case, metrics) -> ImageCheck:
    share = float(metrics.get("segment_contact_fraction", float("nan")))
    return ImageCheck("3a", "contact with the ground is localised", share, f"< {LOCALISED_CONTACT}",
                      share < LOCALISED_CONTACT, "share of segments",
                      "The back arches and the contact with the ground is localised.")


def sidewinder_travels_diagonally(series, case, metrics) -> ImageCheck:
    ang = float(metrics.get("travel_angle_deg", float("nan")))
    fwd = float(metrics.get("speed_bl_per_cycle", float("nan")))
    lat = float(metrics.get("lateral_speed_m_per_s", float("nan"))) * case.gait.period_s / _body_length(case, metrics)
    ground = math.hypot(fwd, lat)
    lo, hi = DIAGONAL_DEG
    ok = lo < abs(ang) < hi and ground > ADVANCE_MIN_BL
    return ImageCheck("3d", "diagonal travel", ang,
                      f"{lo:g} < |angle| < {hi:g} deg at > {ADVANCE_MIN_BL} BL/cycle (ground speed {ground:.3g})",
                      ok, "deg", "The diagonal nature of the locomotion is apparent.")


def sidewinder_does_not_roll(series, case, metrics) -> ImageCheck:
    roll = float(metrics.get("roll_max_deg", float("nan")))
    return ImageCheck("3", "cross-sections do not roll over", roll, f"< {ROLL_MAX_DEG:g}", roll < ROLL_MAX_DEG,
                      "deg", "A vertical sinusoidal flexing ... lifting all but a small portion of the snake off the ground.")


# ----------------------------------------------------------------------------- Image 4: the caterpillar

def _slope_frame(case) -> tuple[np.ndarray, np.ndarray]:
    """(unit vector up the slope's line of greatest slope toward +x, unit surface normal)."""
    a = math.radians(case.scenario.slope_deg) if case.scenario.terrain == "slope" else 0.0
    return np.array([math.cos(a), math.sin(a), 0.0]), np.array([-math.sin(a), math.cos(a), 0.0])


def caterpillar_arches(series, case, metrics) -> ImageCheck:
    _, n = _slope_frame(case)
    h = series.segment_centers @ n
    rise = float((h.max(axis=1) - h[0].max()).max())
    need = case.creature.height_m
    return ImageCheck("4b", "arches its back", rise, f"> {need:g} (one body height)", rise > need, "m",
                      "Image 4b shows the caterpillar arching its back.")


def caterpillar_on_steep_slope(series, case, metrics) -> ImageCheck:
    along, _ = _slope_frame(case)
    L = _body_length(case, metrics)
    k = _first_contact(series)
    cycles = (series.t[-1] - series.t[k]) / case.gait.period_s
    progress = float((series.com[-1] - series.com[k]) @ along) / L / max(cycles, 1e-9)
    holds = bool(series.segment_contact[k:].any(axis=1).all())
    head_first = bool((((series.head - series.tail)[k:] @ along) > 0.0).all())
    up = case.scenario.slope_deg > 0
    ok = progress > ADVANCE_MIN_BL and holds and head_first
    what = "up" if up else "down"
    return ImageCheck("4", f"scales a {abs(case.scenario.slope_deg):g} degree slope {what}", progress,
                      f"> {ADVANCE_MIN_BL} BL/cycle along the slope, never letting go (holds: {holds}), "
                      f"head first (kept: {head_first})", ok, "BL/cycle",
                      "This gives the caterpillar the ability to scale steep gradients both up the slope and down.")


CheckFn = Callable[..., ImageCheck]
CHECKS: dict[str, tuple[CheckFn, ...]] = {
    "worm-book": (worm_nose_slides_forward, worm_mostly_in_contact, worm_front_bends_over_edge, worm_slides_off_edge),
    "snake-undulation": (snake_head_fixed_while_coils_form, snake_segments_follow_one_path),
    "sidewinder": (sidewinder_contact_localised, sidewinder_travels_diagonally, sidewinder_does_not_roll),
    "caterpillar-arch": (caterpillar_arches,),
    "caterpillar-up": (caterpillar_on_steep_slope,),
    "caterpillar-down": (caterpillar_on_steep_slope,),
}


def evaluate(run_key: str, series, case, metrics: Mapping[str, float]) -> list[ImageCheck]:
    """Every check of run ``run_key`` (a key of ``RUNS``) on a recorded run: ``series``
    (``core.series.Series`` with segment_contact), its ``case`` and its ``metrics``."""
    if run_key not in CHECKS:
        raise ValueError(f"unknown Miller image run {run_key!r}; choose one of {', '.join(CHECKS)}")
    return [fn(series, case, metrics) for fn in CHECKS[run_key]]
