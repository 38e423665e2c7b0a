"""Emergent measures of a legged walk whose head speed is commanded.

The paper's leg controller drives the head at ``controller.head_speed_m_s``: the walk's speed
(``speed_m_per_s``) is then the command, the same on every body model, and tells the bodies
nothing (``COMMANDED`` lists such metrics).  What the body model decides is how the rest of the
body follows the head and what the motion costs.  These measures are taken over the gait window
(from ``start_s``: one second after ADJUSTMENT ends, as the gait metrics) on the runner's
recorded series:

``body_speed_ratio``       [-]   the centre of mass's forward speed / the commanded head speed
``lateral_sway_bl``        [BL]  RMS sideways deviation of the centre of mass from its straight
                                 travel line (through its mean ground position, along its net displacement)
``body_stretch_rel``       [-]   mean relative change of the head-to-tail distance from its value at
                                 t = 0 (a soft body stretches behind a commanded head)
``cost_of_transport_mech`` [-]   positive increments of the body's total mechanical energy (kinetic +
                                 elastic + gravitational) over the window / (m g distance travelled):
                                 a lower bound on the work the legs put into the body per unit weight
                                 and distance (work the body dissipates within one sample is not seen)
``steady_cycles``          [strides] strides in the window (window length x stride frequency)

With fewer than ``metrics.min_steady_cycles`` strides the four measures are NaN and
``walk_too_short_reason`` says why.  ``foot_slip_mean_m`` (``metrics.gait``) is not among them: with
the paper's kinematic legs a planted tip is held at its touchdown point, so it is 0 on every body (it
stays a metric, for a controller or body whose feet can slide).
"""
from __future__ import annotations

import math

import numpy as np

# metrics of a legged run that equal (or are set by) a command of the controller: not a result of the body
COMMANDED = {"speed_m_per_s": "controller.head_speed_m_s"}
EMERGENT_WALK_METRICS = ("body_speed_ratio", "lateral_sway_bl", "body_stretch_rel", "cost_of_transport_mech")


def commanded_metric(metric: str, legged: bool) -> str | None:
    """The command a metric of a run equals (a configuration key), or None when the metric is a result.

    Only a legged walk commands its head speed; a legless gait's speed emerges from its muscle wave.
    """
    return COMMANDED.get(metric) if legged else None


def walk_emergent_metrics(t: np.ndarray, com: np.ndarray, head: np.ndarray, tail: np.ndarray,
                          energy: np.ndarray, start_s: float, head_speed_m_s: float, stride_frequency_hz: float,
                          body_length_m: float, mass_kg: float, gravity_m_s2: float,
                          min_steady_cycles: float) -> tuple[dict[str, float], str | None]:
    """The module's measures over the samples with ``t >= start_s``, and the too-short reason (or None).

    Shapes: t (T,) [s]; com, head, tail (T, 3) [m] (y up); energy (T, 3) [J] (kinetic, elastic,
    gravitational).  head_speed_m_s: the commanded head speed [m/s]; stride_frequency_hz: the gait's
    mean stride frequency (NaN when no stride completed); body_length_m: rest length [m].
    """
    t = np.asarray(t, float)
    out = dict.fromkeys(EMERGENT_WALK_METRICS, math.nan)
    i0 = int(np.searchsorted(t, start_s))
    window = float(t[-1] - t[i0]) if i0 < len(t) - 1 else 0.0
    f = stride_frequency_hz if isinstance(stride_frequency_hz, float) and math.isfinite(stride_frequency_hz) else 0.0
    cycles = window * f
    out["steady_cycles"] = cycles
    if cycles < min_steady_cycles - 1e-9:
        need_s = min_steady_cycles / f if f > 0 else math.inf
        return out, (f"too short: {cycles:.2f} strides in the {window:.2f} s gait window (from {start_s:.2f} s: "
                     "one second after ADJUSTMENT ends) at "
                     + (f"{f:.2f} Hz; needs >= {min_steady_cycles:g} (run >= {start_s + need_s:.1f} s)" if f > 0
                        else f"no complete stride; needs >= {min_steady_cycles:g} strides"))
    ground = np.asarray(com, float)[i0:][:, [0, 2]]
    disp = ground[-1] - ground[0]
    dist = float(np.linalg.norm(disp))
    if head_speed_m_s > 0:
        out["body_speed_ratio"] = dist / window / head_speed_m_s
    if dist > 0 and body_length_m > 0:
        u = disp / dist
        rel = ground - ground.mean(axis=0)
        lateral = rel @ np.array([-u[1], u[0]])
        out["lateral_sway_bl"] = float(np.sqrt(np.mean(lateral ** 2))) / body_length_m
    span = np.linalg.norm(np.asarray(head, float) - np.asarray(tail, float), axis=1)
    if span[0] > 0:
        out["body_stretch_rel"] = float(np.mean(span[i0:] / span[0] - 1.0))
    e = np.asarray(energy, float)[i0:].sum(axis=1)
    if dist > 0 and mass_kg > 0 and gravity_m_s2 > 0 and np.all(np.isfinite(e)):
        out["cost_of_transport_mech"] = float(np.clip(np.diff(e), 0.0, None).sum()) / (mass_kg * gravity_m_s2 * dist)
    return out, None
