"""How one value is written in a table cell, the same in the report's tables and ``validate``'s."""
from __future__ import annotations

import math


def fmt(v) -> str:
    """A table cell: 4 significant digits, '-' for missing or undefined."""
    if v is None:
        return "-"
    if isinstance(v, float):
        if not math.isfinite(v):
            return "-"
        return f"{v:.4g}"
    return str(v)
