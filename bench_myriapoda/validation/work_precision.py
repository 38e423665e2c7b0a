"""Work-precision diagrams: error against a reference vs cost, per body model, log-log.

For each quantity (``QUANTITIES``) and body model the case runs over a sweep of dt (the body's
default dt times ``DT_FACTORS``; the fem and hybrid bodies also over ``body.resolution`` at the
finest dt).  Error is |q - q_ref| / |q_ref| with q_ref

* analytic where one exists (the worm's eps * Lambda; the fem hanging worm's rho g L^2 / (2 E)), else
* the same body refined in dt: dt / 8 (quick: dt / 4); the change between the last two dt levels
  is reported (``ref_change``; converged when < 0.5 %).  The fem and hybrid bodies also run at
  resolution - 1 and + 1 at the finest dt, their error taken against resolution + 1
  (``resolution_change``: how much the default resolution is off), drawn as open markers.

Cost is CPU seconds per simulated second (``time.process_time`` around the run, minus the JIT
compilation the runner times).  This module computes (``work_precision_data``); ``report.work_precision``
draws one PNG per quantity, one curve per body (the dt sweep, solid; the resolution points are open
markers of the same colour) and writes ``work_precision.json`` with every point, so tests assert on the
data, not on pixels.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Callable

from ..core import registry
from ..core.errors import InputError
from .core import all_bodies, clean

DT_FACTORS = (2.0, 1.0, 0.5, 0.25)
REF_DT_FACTOR = 0.125
QUICK_DT_FACTORS = (2.0, 1.0, 0.5)
QUICK_REF_DT_FACTOR = 0.25
CONVERGED_CHANGE = 0.005   # the refined reference counts as converged when refining changes it < 0.5 %
HANG_GRAVITY = 1.0         # [m/s^2] hanging worm: strain ~2.4 % on the fem body, small enough for linear theory


@dataclass(frozen=True)
class Quantity:
    name: str           # file stem
    title: str
    creature: str
    scenario: str
    gait: str | None
    metric: str
    duration: float     # [s], full
    quick_duration: float
    overrides: tuple[str, ...] = ()


QUANTITIES = (
    Quantity("worm_displacement", "worm displacement per cycle", "worm", "flat", None, "displacement_per_cycle_m",
             16.0, 10.0),
    Quantity("hanging_elongation", "hanging worm elongation", "worm", "hang", None, "hanging_elongation_m",
             3.0, 2.0, (f"scenario.gravity_m_s2={HANG_GRAVITY}",)),
    # 8 s: two steady cycles after the 2 s ramp and 2 warm-up cycles (a shorter run's speed is not a number)
    Quantity("snake_speed", "snake forward speed", "snake", "flat", "lateral-undulation", "speed_m_per_s",
             8.0, 8.0),
)


def _probes(body: str):
    """The body model's ``BodySpec.probes`` (``core.specs.BodyProbes``; plugins' bodies included)."""
    registry.load_all()
    return registry.BODIES[body].probes


def analytic_reference(q: Quantity, case) -> float | None:
    """The analytic value of ``q`` for this case, or None when there is none for its body model."""
    from .references import hanging_bar_displacement, worm_displacement_per_cycle

    if q.name == "worm_displacement":
        return worm_displacement_per_cycle(case.gait.amplitude, case.gait.wavelength_bl * case.creature.body_length_m)
    continuum = _probes(case.body.name).density_and_modulus  # a continuum body's (rho, E), else None
    if q.name == "hanging_elongation" and continuum is not None:
        rho, E = continuum(case)
        return hanging_bar_displacement(rho, case.scenario.gravity_m_s2, case.creature.body_length_m, E)
    return None


def measure(q: Quantity, body: str, dt_factor: float, resolution: int | None, quick: bool) -> dict:
    """One point: the quantity and the cost of the case at dt = default * dt_factor (and resolution)."""
    from ..core.config import resolve_case
    from ..harness.runner import run_case

    over = list(q.overrides) + ([f"body.resolution={resolution}"] if resolution is not None else [])
    base = resolve_case(q.creature, body, q.scenario, q.gait, overrides=over)
    dur = q.quick_duration if quick else q.duration
    case = resolve_case(q.creature, body, q.scenario, q.gait, duration=dur, dt=base.dt * dt_factor, overrides=over)
    c0 = time.process_time()
    r = run_case(case)
    cpu = time.process_time() - c0 - (r.timings.get("compile_s") or 0.0)
    value = r.metrics.get(q.metric, math.nan) if r.status == "ok" else math.nan
    return {"body": body, "dt": case.dt, "dt_factor": dt_factor, "resolution": resolution, "status": r.status,
            "value": value, "cpu_s_per_sim_s": max(cpu, 1e-6) / dur, "case": case}


def _default_resolution(q: Quantity, body: str) -> int | None:
    """The body's default ``body.resolution`` for ``q``'s case, or None for a body without that key (the
    lattice: one cube per segment)."""
    from ..core.config import resolve_case
    res = getattr(resolve_case(q.creature, body, q.scenario, q.gait, overrides=list(q.overrides)).body,
                  "resolution", None)
    return None if res is None else int(res)


def _warm_up(q: Quantity, body: str) -> None:
    """Compile the body's and controller's kernels before anything is timed (numba caches them)."""
    from ..core.config import resolve_case
    from ..harness.runner import run_case

    base = resolve_case(q.creature, body, q.scenario, q.gait, overrides=list(q.overrides))
    run_case(resolve_case(q.creature, body, q.scenario, q.gait, duration=20 * base.dt, overrides=list(q.overrides)))


def sweep(q: Quantity, body: str, quick: bool, progress: Callable[[str], None] | None = None) -> dict:
    """Every point of one body's curve for ``q``, with the references and the errors.

    The curve (``dt_points``) runs over dt at the body's default resolution; its reference is the
    analytic value where one exists, else the same case at dt * ``REF_DT_FACTOR``.  The resolution
    points run at that finest dt over resolution - 1 and + 1, their error taken against resolution + 1:
    the spatial error the dt curve does not include (``resolution_change``: default vs finer).
    """
    factors = QUICK_DT_FACTORS if quick else DT_FACTORS
    ref_factor = QUICK_REF_DT_FACTOR if quick else REF_DT_FACTOR
    res0 = _default_resolution(q, body)
    _warm_up(q, body)
    pts = []
    for f in factors:
        if progress:
            progress(f"{q.name} on {body}: dt x {f:g}")
        pts.append(measure(q, body, f, res0, quick))
    fine = measure(q, body, ref_factor, res0, quick)
    res_pts = []
    if res0 is not None:
        for res in (res0 - 1, res0 + 1):
            if progress:
                progress(f"{q.name} on {body}: resolution {res}")
            try:
                res_pts.append(measure(q, body, ref_factor, res, quick))
            except InputError:  # below the body's smallest resolution (the hybrid needs >= 3 nodes)
                continue
    finer = next((p for p in res_pts if p["resolution"] == res0 + 1), None) if res0 is not None else None
    analytic = analytic_reference(q, fine["case"])
    if analytic is not None:
        ref, kind = analytic, "analytic"
    else:
        ref, kind = fine["value"], f"refined: dt x {ref_factor:g}"
    dt_change = abs(fine["value"] - pts[-1]["value"]) / abs(fine["value"]) if fine["value"] else math.nan
    res_change = math.nan
    if finer is not None and math.isfinite(finer["value"]) and finer["value"]:
        res_change = abs(fine["value"] - finer["value"]) / abs(finer["value"])
    for p in pts + [fine]:
        p["error"] = abs(p["value"] - ref) / abs(ref) if math.isfinite(p["value"]) and ref else math.nan
    for p in res_pts:
        r = finer["value"] if finer is not None else math.nan
        p["error"] = abs(p["value"] - r) / abs(r) if math.isfinite(p["value"]) and r else math.nan
    for p in pts + [fine] + res_pts:
        p.pop("case", None)
    return {"body": body, "reference": ref, "reference_kind": kind, "ref_change": dt_change,
            "resolution_change": res_change, "converged": bool(dt_change < CONVERGED_CHANGE),
            "dt_points": pts + ([fine] if analytic is not None else []), "resolution_points": res_pts,
            "reference_point": fine}


def work_precision_data(bodies=None, quick: bool = False, progress: Callable[[str], None] | None = None,
                        quantities=QUANTITIES) -> dict:
    """Every quantity's sweep on every body of ``bodies`` (default all): ``{quantity name: {"title", "metric",
    "curves": [one ``sweep`` per body]}}``.  Drawn and written by ``report.work_precision``."""
    bodies = all_bodies() if bodies is None else bodies
    return {q.name: {"title": q.title, "metric": q.metric, "curves": [sweep(q, b, quick, progress)
                                                                     for b in all_bodies() if b in bodies]}
            for q in quantities}
