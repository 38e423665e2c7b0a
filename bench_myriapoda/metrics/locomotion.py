"""Locomotion and stability metrics of a legless creature, from a recorded run.

All metrics are flat scalars (JSON names as in the issue list).  Locomotion
metrics are measured over a window that skips ``metrics.warmup_cycles`` gait
cycles so the gait is steady; directions are taken relative to the *mean body
axis* over that window (unit vector from tail to head, averaged), so a
sidewinder's diagonal travel shows up as a travel angle.
"""
from __future__ import annotations

import math

import numpy as np

from ..core.series import Series

UP = np.array([0.0, 1.0, 0.0])


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v)
    return v / n if n > 0 else v


def measurement_window(series: Series, period_s: float, warmup_cycles: float) -> tuple[int, int]:
    """Index range [i0, i1] of samples after the warm-up; falls back to the second half of a short run."""
    t = series.t
    i1 = len(t) - 1
    t0 = warmup_cycles * period_s
    if t[-1] - t0 < 0.5 * period_s:
        t0 = 0.5 * t[-1]
    i0 = int(np.searchsorted(t, t0))
    return min(i0, max(i1 - 1, 0)), i1


# The locomotion metrics that need a steady gait: under ``metrics.min_steady_cycles`` steady cycles they are
# NaN and the run's labels say why (``too_short_reason``).
STEADY_METRICS = ("speed_m_per_s", "lateral_speed_m_per_s", "displacement_per_cycle_m", "speed_bl_per_cycle",
                  "speed_bl_per_s", "travel_angle_deg", "slip_ratio", "path_following_error_bl")


def steady_start_s(case) -> float:
    """When the gait is steady [s]: after the amplitude ramp (``gait.ramp_s``) and the warm-up
    (``metrics.warmup_cycles`` periods counted from t = 0), whichever ends later."""
    return max(float(case.gait.ramp_s), float(case.metrics.warmup_cycles) * float(case.gait.period_s))


def steady_cycles(t_end_s: float, case) -> float:
    """Complete or partial gait periods between ``steady_start_s`` and the end of the run (>= 0)."""
    return max(0.0, t_end_s - steady_start_s(case)) / float(case.gait.period_s)


def too_short_reason(t_end_s: float, case) -> str | None:
    """Why a run ending at ``t_end_s`` is too short for its locomotion metrics, or None when it is long enough."""
    n, need = steady_cycles(t_end_s, case), float(case.metrics.min_steady_cycles)
    if n >= need - 1e-9:  # the last sample of an 8 s run is 8 s up to the round-off of steps x dt
        return None
    start, period = steady_start_s(case), float(case.gait.period_s)
    return (f"too short: {n:.2f} steady cycles (of {period:g} s, after the {case.gait.ramp_s:g} s ramp and "
            f"{case.metrics.warmup_cycles:g} warm-up cycles, i.e. from {start:g} s) in a {t_end_s:g} s run; needs "
            f">= {need:g} (run >= {start + need * period:g} s)")


def distance_to_polyline(points: np.ndarray, path: np.ndarray) -> np.ndarray:
    """Distance of each point (m, 3) to the polyline ``path`` (k, 3) [m]."""
    a = path[:-1][None, :, :]
    b = path[1:][None, :, :]
    p = points[:, None, :]
    ab = b - a
    denom = np.einsum("ijk,ijk->ij", ab, ab)
    s = np.clip(np.einsum("ijk,ijk->ij", p - a, ab) / np.where(denom > 0, denom, 1.0), 0.0, 1.0)
    closest = a + s[..., None] * ab
    return np.linalg.norm(p - closest, axis=2).min(axis=1)


def path_following_error(series: Series, i0: int, i1: int, body_length: float, n_eval: int = 25) -> float:
    """Mean distance of the segment centres from the path the head has travelled, in body lengths
    (mean over the evaluated samples of the mean over the measured segments).

    At each of ``n_eval`` samples in [i0, i1], the head's path is its recorded trajectory from
    t = 0 to that sample, projected on the ground plane.  A segment is measured only once the head
    has travelled at least the segment's rest distance behind the head (arc length along the
    body at t = 0): before that, no point of the path can be where the segment should be.  The
    path is not extended backward with the starting body line, which would make a body that
    has not moved yet look perfect.  NaN when no segment qualifies at any evaluated sample.
    """
    flat = np.array([1.0, 0.0, 1.0])
    c0 = series.segment_centers[0] * flat
    behind = np.linalg.norm(series.head[0] * flat - c0[0]) + np.concatenate(
        [[0.0], np.cumsum(np.linalg.norm(np.diff(c0, axis=0), axis=1))])
    head = series.head * flat
    travelled = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(head, axis=0), axis=1))])
    errs = []
    for i in np.unique(np.linspace(i0, i1, n_eval).astype(int)):
        reached = behind[1:] <= travelled[i]
        if i < 1 or not reached.any():
            continue
        path = head[: i + 1]
        if len(path) > 400:  # keep the cost bounded: subsample the path, keep its end points
            path = path[np.unique(np.linspace(0, len(path) - 1, 400).astype(int))]
        pts = series.segment_centers[i][1:][reached] * flat
        errs.append(distance_to_polyline(pts, path).mean())
    if not errs:
        return float("nan")
    return float(np.mean(errs) / body_length)


def locomotion_metrics(series: Series, case, wave_speed_m_s: float, body_length_m: float) -> dict[str, float]:
    """Speed, direction and gait-following metrics over the steady window.

    ``steady_cycles``: the steady gait cycles in the run (``steady_cycles``); under
    ``metrics.min_steady_cycles`` of them the runner blanks the ``STEADY_METRICS`` (``blank_too_short``)
    and stores ``too_short_reason`` in the run's labels.

    body_length_m: the body's rest length from head to tail [m] (the body model
    reports it: a hybrid body's links add to its segments).
    """
    out: dict[str, float] = {}
    if len(series.t) < 3:
        return out
    period = case.gait.period_s
    L = body_length_m
    i0, i1 = measurement_window(series, period, case.metrics.warmup_cycles)
    dt = series.t[i1] - series.t[i0]
    if dt <= 0:
        return out
    axes = np.array([_unit(h - tl) for h, tl in zip(series.head[i0:i1 + 1], series.tail[i0:i1 + 1])])
    axis = _unit(axes.mean(axis=0))
    # the ground's "up" for direction decomposition: perpendicular component of the axis removed
    right = _unit(np.cross(axis, UP)) if abs(axis @ UP) < 0.99 else np.array([0.0, 0.0, 1.0])
    disp = series.com[i1] - series.com[i0]
    forward = float(disp @ axis)
    lateral = float(disp @ right)
    speed = forward / dt
    out["speed_m_per_s"] = speed
    out["lateral_speed_m_per_s"] = lateral / dt
    out["displacement_per_cycle_m"] = speed * period
    out["speed_bl_per_cycle"] = speed * period / L
    out["speed_bl_per_s"] = speed / L
    out["travel_angle_deg"] = math.degrees(math.atan2(lateral, forward)) if math.hypot(forward, lateral) > 0 else 0.0
    out["slip_ratio"] = 1.0 - speed / wave_speed_m_s if wave_speed_m_s > 0 else float("nan")
    out["path_following_error_bl"] = path_following_error(series, i0, i1, L)
    out["cycles_measured"] = dt / period
    out["steady_cycles"] = steady_cycles(float(series.t[-1]), case)
    out["com_height_change_m"] = float(series.com[-1, 1] - series.com[0, 1])
    return out


def blank_too_short(metrics: dict[str, float]) -> None:
    """Set the ``STEADY_METRICS`` present in ``metrics`` to NaN: measured over a gait still building up,
    they are not numbers (the run's ``labels.too_short`` says why)."""
    for k in STEADY_METRICS:
        if k in metrics:
            metrics[k] = float("nan")


def energy_metrics(series: Series) -> dict[str, float]:
    """Relative change of total mechanical energy over the run (meaningful for passive, undamped cases)."""
    e = series.energy.sum(axis=1)
    finite = np.isfinite(e)
    if finite.sum() < 2:
        return {}
    e = e[finite]
    scale = max(abs(e[0]), np.abs(series.energy[finite][0]).sum(), 1e-300)
    out = {"energy_drift_rel": float((e[-1] - e[0]) / scale),
           "energy_max_dev_rel": float(np.max(np.abs(e - e[0])) / scale)}
    out.update(contact_energy_metrics(series))
    return out


def contact_energy_metrics(series: Series) -> dict[str, float]:
    """Energy before and after the first ground contact (relative to the same scale as ``energy_drift_rel``).

    energy_drift_free_rel: change of the total mechanical energy from t = 0 to the last sample before any
        segment touches the ground (``segment_contact``): the integrator's drift where no contact removes
        energy (NaN when the body touches from the start or the body reports no contacts).
    impact_energy_loss_rel: change from that sample to the end of the run (negative: lost in the impact and
        the contact friction after it); NaN when the body never touches the ground.
    """
    out = {"energy_drift_free_rel": float("nan"), "impact_energy_loss_rel": float("nan")}
    contact = series.segment_contact
    if contact is None or len(contact) != len(series.t):
        return out
    e = series.energy.sum(axis=1)
    touching = np.asarray(contact).any(axis=1)
    if not touching.any() or not np.all(np.isfinite(e)):
        return out
    k = int(np.argmax(touching))  # the first sample with a contact
    scale = max(abs(e[0]), np.abs(series.energy[0]).sum(), 1e-300)
    if k >= 2:
        out["energy_drift_free_rel"] = float((e[k - 1] - e[0]) / scale)
        out["impact_energy_loss_rel"] = float((e[-1] - e[k - 1]) / scale)
    return out
