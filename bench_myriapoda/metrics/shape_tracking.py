"""How closely a body followed the commanded bending wave: ``shape_tracking_error`` and ``shape_not_achieved``.

A bending gait with ``gait.curvature_amplitude`` A > 0 commands the ground curvature profile

    kappa_cmd(s, t) = sign r(t) (A / L) sin(k s - omega t + phi)

(``controllers.muscle_waves.wave_table``'s LATERAL wave; ``core.protocols.LATERAL_GROUND_SIGN``, L the
creature's body length, s the rest arc length from the head).  Over the steady window
(``locomotion.measurement_window``) the measured profile is the signed discrete curvature of the
recorded centre line on the ground (``body_shape.ground_curvature``), taken through points one
segment pitch apart (a body whose centres alternate between two kinds, the hybrid's boxes and links,
is read through every other centre: its bends sit in the links, and alternating centres make the
three-point curvature uneven).  Then

* ``shape_tracking_error`` [-] = RMS over the window's samples and the interior points of
  (kappa_meas - kappa_cmd) x L / A: 0 for the commanded shape; 1 / sqrt(2) = 0.71 for a straight
  body; f / sqrt(2) for a wave of the right phase short of a fraction f of its amplitude; sqrt(2)
  sin(delta / 2) for a pure phase lag delta.  The threshold 0.10 is 14 % of the amplitude missing or
  8 degrees of lag: the lag the issue-11 bodies showed open loop at low load stays inside it, the
  lattice's 80 % loss at mu_t / mu_f = 5 (error 0.63) is far outside;
* ``shape_not_achieved`` = 1 when the error exceeds ``SHAPE_ERROR_THRESHOLD`` (0.10): the speed and
  every other locomotion figure of the run are then those of another shape, not comparable with a
  body that bent as commanded.  ``shape_flag_reason`` says why, for the run's message.

The achieved amplitude and wavelength are ``body_shape``'s ``curvature_amplitude`` and
``body_wavelength_bl``.
"""
from __future__ import annotations

import math

import numpy as np

from ..core.protocols import LATERAL_GROUND_SIGN
from ..core.series import Series
from .body_shape import ground_curvature, pitch_stride

SHAPE_ERROR_THRESHOLD = 0.10
HARMONICS_FITTED = 5  # the temporal harmonics ``curvature_harmonics`` fits: the fundamental and 2 to 5


def commands_a_shape(case) -> bool:
    """True for a gait that commands a lateral bending shape: its configuration class says it commands a
    curvature (``GaitConfig.commands_curvature``, so this module names no gait) and the lateral one,
    ``curvature_amplitude``, is > 0."""
    g = case.gait
    return g.commands_curvature() and g.curvature_amplitude > 0.0 and not case.scenario.passive


def shape_control_mode(gait) -> str:
    """Which shape control a gait ran (``gait`` a GaitConfig or its dict): ``closed_loop`` (the commanded shape
    tracked: the mode for comparisons with the kinematic reference), ``open_loop`` (the calibrated gain alone:
    Miller's dynamic snake, its own departures from the command kept), or ``none`` (no commanded curvature)."""
    get = gait.get if isinstance(gait, dict) else (lambda k, d=None: getattr(gait, k, d))
    if not (get("curvature_amplitude", 0.0) or 0.0) > 0.0 or get("name") not in ("lateral-undulation", "sidewinding"):
        return "none"
    return str(get("shape_control", "open_loop"))


def commanded_curvature(case, s: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(T, n) commanded ground curvature [1/m] at rest arc lengths s (n,) [m] and times t (T,) [s]."""
    g = case.gait
    L = float(case.creature.body_length_m)
    direction = 1.0 if g.direction == "head-to-tail" else -1.0
    k = direction * 2.0 * math.pi / (g.wavelength_bl * L)
    omega = 2.0 * math.pi * g.frequency_hz
    ramp = np.ones_like(t) if g.ramp_s <= 0 else np.clip(t / g.ramp_s, 0.0, 1.0)
    theta = k * s[None, :] - omega * t[:, None] + math.radians(g.phase_deg)
    return LATERAL_GROUND_SIGN * ramp[:, None] * (g.curvature_amplitude / L) * np.sin(theta)


def _measured_profile(series: Series, case, i0: int, i1: int):
    """(s (n,) [m], t (T,) [s], kappa (T, n) [1/m]): the measured ground curvature at the interior points one pitch
    apart over samples [i0, i1] (module docstring); None when the run has too few samples or centres."""
    centers = series.segment_centers
    if centers is None or i1 - i0 < 2:
        return None
    stride = pitch_stride(centers[0], case.creature.segment_length_m)
    pts = centers[:, ::stride]
    if pts.shape[1] < 4:
        return None
    # rest arc length of each point from the head: the head end face to the first point, then the chords at t = 0
    first = float(np.linalg.norm(pts[0, 0] - series.head[0]))
    s = first + np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts[0], axis=0), axis=1))])
    kappa, _ = ground_curvature(pts[i0:i1 + 1])
    return s[1:-1], series.t[i0:i1 + 1], kappa


def shape_tracking_error(series: Series, case, i0: int, i1: int) -> float:
    """RMS (measured - commanded) ground curvature x L / A over samples [i0, i1] (module docstring); NaN when
    the run has too few samples or centres."""
    prof = _measured_profile(series, case, i0, i1)
    if prof is None:
        return float("nan")
    s, t, kappa = prof
    diff = kappa - commanded_curvature(case, s, t)
    L = float(case.creature.body_length_m)
    return float(np.sqrt(np.mean(diff ** 2)) * L / case.gait.curvature_amplitude)


def curvature_harmonics(series: Series, case, i0: int, i1: int, max_harmonic: int = HARMONICS_FITTED):
    """(s (n,) [m], c (max_harmonic, n) complex [1/m]): the measured ground curvature's temporal harmonics at
    each interior point over samples [i0, i1], least-squares fitted as sum_h Im(c_h e^{i h theta}) with the
    command's phase theta = k s - omega t + phi (``commanded_curvature``; h = 1 .. max_harmonic, plus a
    constant), so c_1 of the commanded shape is sign A / L; None when the run has too few samples or centres."""
    prof = _measured_profile(series, case, i0, i1)
    if prof is None:
        return None
    s, t, kappa = prof
    g = case.gait
    L = float(case.creature.body_length_m)
    direction = 1.0 if g.direction == "head-to-tail" else -1.0
    k = direction * 2.0 * math.pi / (g.wavelength_bl * L)
    omega = 2.0 * math.pi * g.frequency_hz
    c = np.zeros((max_harmonic, s.shape[0]), dtype=complex)
    for j in range(s.shape[0]):
        theta = k * s[j] - omega * t + math.radians(g.phase_deg)
        h = np.arange(1, max_harmonic + 1)
        basis = np.concatenate([np.sin(np.outer(theta, h)), np.cos(np.outer(theta, h)), np.ones((t.shape[0], 1))],
                               axis=1)
        coef, *_ = np.linalg.lstsq(basis, kappa[:, j], rcond=None)
        c[:, j] = coef[:max_harmonic] + 1j * coef[max_harmonic:2 * max_harmonic]
    return s, c


def shape_harmonic_content(series: Series, case, i0: int, i1: int) -> float:
    """RMS over the interior points of the measured curvature's temporal harmonics 2 to ``HARMONICS_FITTED``
    over the COMMANDED amplitude [-] (``curvature_harmonics``): 0 for a pure travelling sine in time,
    whatever its amplitude and phase; NaN when the window is shorter than a cycle."""
    if series.t[i1] - series.t[i0] < 1.0 / case.gait.frequency_hz:
        return float("nan")
    fit = curvature_harmonics(series, case, i0, i1)
    if fit is None:
        return float("nan")
    _, c = fit
    L = float(case.creature.body_length_m)
    return float(np.sqrt(np.mean(np.sum(np.abs(c[1:]) ** 2, axis=0))) * L / case.gait.curvature_amplitude)


def shape_flag_reason(metrics: dict[str, float], case) -> str:
    """The run message of a ``shape_not_achieved`` run: the error, the achieved shape, the muscles' saturation."""
    err = metrics["shape_tracking_error"]
    parts = [f"shape_not_achieved: shape_tracking_error {err:.3f} > {SHAPE_ERROR_THRESHOLD:g}" if math.isfinite(err)
             else "shape_not_achieved: shape_tracking_error not measured (too few centre-line points one segment pitch "
                  "apart, or too few samples in the steady window)",
             f"curvature_amplitude {metrics.get('curvature_amplitude', float('nan')):.3g} of "
             f"{case.gait.curvature_amplitude:g} commanded"]
    sat = metrics.get("muscle_saturation_fraction")
    if sat is not None and math.isfinite(sat):
        parts.append(f"muscle_saturation_fraction {sat:.3f} at max_muscle_strain {case.gait.max_muscle_strain:g}")
    elif case.gait.shape_control == "open_loop":
        parts.append("open-loop shape control (gait.shape_control)")
    return "; ".join(parts) + ": locomotion metrics are those of another shape, not comparable across bodies"


def shape_tracking_metrics(series: Series, case, i0: int, i1: int) -> dict[str, float]:
    """shape_tracking_error and shape_not_achieved (1.0 / 0.0) of a gait that commands its shape; {} otherwise."""
    if not commands_a_shape(case):
        return {}
    err = shape_tracking_error(series, case, i0, i1)
    return {"shape_tracking_error": err, "shape_harmonic_content": shape_harmonic_content(series, case, i0, i1),
            "shape_not_achieved": float(not (math.isfinite(err) and err <= SHAPE_ERROR_THRESHOLD))}
