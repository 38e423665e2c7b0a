"""The measured kinematics and posture of a legless creature, as the runner adds them to a run's metrics."""
from __future__ import annotations

from ..core.series import Series
from .body_shape import body_shape_metrics
from .locomotion import measurement_window
from .posture import posture_metrics
from .shape_tracking import shape_tracking_metrics
from .spline_departure import spline_departure_metrics


def legless_metrics(series: Series, case, body_length_m: float, world) -> dict[str, float]:
    """curvature_amplitude, body_wavelength_bl, heading_drift_deg_per_cycle (steady window),
    roll_max_deg, segment_contact_fraction, lift_max_m, airborne_max_s, posture_fault, and for a gait that
    commands its shape shape_tracking_error and shape_not_achieved, and for a bending gait tail_swing_ratio and
    sideways_slip_ratio (``metrics.body_shape``, ``metrics.posture``, ``metrics.shape_tracking``,
    ``metrics.spline_departure``).  body_length_m: rest length head to tail [m]; world: the run's
    ``world.world.World``."""
    if len(series.t) < 3:
        return {}
    period = case.gait.period_s
    i0, i1 = measurement_window(series, period, case.metrics.warmup_cycles)
    out = body_shape_metrics(series, i0, i1, period, body_length_m, pitch_m=case.creature.segment_length_m)
    out.update(posture_metrics(series, case.scenario, i0, i1, world))
    out.update(shape_tracking_metrics(series, case, i0, i1))
    if case.gait.commands_curvature() and not case.scenario.passive:
        out.update(spline_departure_metrics(series, i0, i1, pitch_m=case.creature.segment_length_m))
    return out
