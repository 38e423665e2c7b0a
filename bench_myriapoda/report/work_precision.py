"""Work-precision diagrams drawn: log-log relative error against cost, one PNG per quantity.

``validation.work_precision`` computes the sweeps (what each point means is said there); this
module draws them and writes ``work_precision.json`` beside the PNGs, so validation computes and
the report draws (the layers of ARCHITECTURE.md: validation sits below report).
"""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Callable

from ..validation.core import clean
from ..validation.work_precision import QUANTITIES, work_precision_data
from .figure_files import save_figure


def plot(title: str, curves: list[dict], path: Path) -> Path:
    """Log-log error vs cost, one solid curve per body (dt sweep), open markers for the resolution sweep.

    ``curves``: ``validation.work_precision.sweep`` results; ``title``: the quantity's title."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for i, c in enumerate(curves):
        color = f"C{i}"
        pts = [p for p in c["dt_points"] if math.isfinite(p["error"]) and p["error"] > 0]
        if pts:
            ax.loglog([p["cpu_s_per_sim_s"] for p in pts], [p["error"] for p in pts], "o-", color=color,
                      label=f"{c['body']} (dt sweep; ref {c['reference_kind']})")
            for p in pts:
                ax.annotate(f"dt x{p['dt_factor']:g}", (p["cpu_s_per_sim_s"], p["error"]), fontsize=6,
                            xytext=(3, 3), textcoords="offset points")
        rp = [p for p in c["resolution_points"] if math.isfinite(p["error"]) and p["error"] > 0]
        if rp:
            ax.loglog([p["cpu_s_per_sim_s"] for p in rp], [p["error"] for p in rp], "s", mfc="none", color=color,
                      linestyle="none", label=f"{c['body']} (resolution {', '.join(str(p['resolution']) for p in rp)})")
    ax.set_xlabel("cost [CPU s per simulated s]")
    ax.set_ylabel("relative error")
    ax.set_title(f"Work-precision: {title}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    return save_figure(fig, path)


def run_work_precision(out_dir: Path, bodies=None, quick: bool = False,
                       progress: Callable[[str], None] | None = None, quantities=QUANTITIES) -> dict:
    """Sweep (``validation.work_precision``), plot and write ``out_dir/work_precision_*.png`` and
    ``out_dir/work_precision.json``; returns the JSON document."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    data = work_precision_data(bodies, quick, progress, quantities)
    figures = [str(plot(d["title"], d["curves"], out_dir / f"work_precision_{name}.png")) for name, d in data.items()]
    doc = clean({"quick": quick, "quantities": data, "figures": figures})
    (out_dir / "work_precision.json").write_text(json.dumps(doc, indent=1))
    return doc
