"""How one value is written in a table cell: the same in the terminal's tables, the report's and ``validate``'s.

A value smaller than the round-off of its quantity (``ROUND_OFF``) is written as 0: double precision on
metre-scale positions leaves speeds of 1e-15 m/s on a body at rest, travel angles of 1e-13 degrees and
penetrations of 1e-21 m, and such a number printed as data reads as a measurement.
"""
from __future__ import annotations

import math

# magnitudes below which a value is round-off of its quantity (a metric name, as in result.metrics):
# 1e-9 m/s is far below any gait's speed and far above the 1e-15 of a resting body; 1e-12 m of
# penetration is a thousandth of a nanometre, far below any contact's tolerance; a travel angle under
# 1e-9 degrees is the direction of a body that does not travel sideways at all
ROUND_OFF = {"speed_bl_per_cycle": 1e-9, "speed_m_per_s": 1e-9, "speed_bl_per_s": 1e-9,
             "lateral_speed_m_per_s": 1e-9, "travel_angle_deg": 1e-9, "max_penetration_m": 1e-12,
             "t_fail_s": 0.0, "steps_per_s": 0.0}


def fmt(v, quantity: str = "") -> str:
    """A table cell: 4 significant digits, '-' for missing or undefined, 0 under ``quantity``'s round-off
    (``quantity``: a metric name, with or without the ``metric.`` prefix; none: no round-off)."""
    if v is None:
        return "-"
    if isinstance(v, float):
        if not math.isfinite(v):
            return "-"
        if abs(v) < ROUND_OFF.get(quantity.removeprefix("metric."), 0.0):
            return "0"
        return f"{v:.4g}"
    return str(v)
