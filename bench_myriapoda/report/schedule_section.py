"""The report's "Matrix schedule" section: how well the run used its workers (issue 31).

Reads the ``schedule`` key that ``bench-myriapoda matrix`` adds to ``DIR/matrix.json`` after a run
(``harness.schedule.run_summary``): the parallel efficiency (sum of the cases' wall times over
workers x matrix wall), the critical path (the longest case), and how well the predicted case costs
that ordered the run matched the measured ones.  A directory without it gets a one-line note.
"""
from __future__ import annotations

import json
from pathlib import Path

import pandas as pd


def load_schedule(out_dir: Path | str) -> dict | None:
    """``matrix.json``'s ``schedule`` section, or None (no file, no run recorded, unreadable)."""
    p = Path(out_dir) / "matrix.json"
    try:
        return json.loads(p.read_text()).get("schedule") if p.is_file() else None
    except (OSError, ValueError, AttributeError):
        return None


def section(page, out_dir: Path | str) -> None:
    """Append the section to ``page`` (``report.build._Page``) when the run recorded its schedule."""
    sched = load_schedule(out_dir)
    page.section("schedule", "Matrix schedule: parallel efficiency and critical path")
    if not sched or "efficiency" not in sched:
        page.p("No schedule recorded: matrix.json has none (a run before issue 31, or nothing ran in the last "
               "--resume).", "note")
        return
    e = sched["efficiency"]
    page.p(sched.get("line", ""))
    r = sched.get("predicted_vs_measured_r")
    rows = {"workers": e.get("workers"), "cases run": e.get("cases"),
            "matrix wall [s]": _round(e.get("matrix_wall_s")), "sum of case walls [s]": _round(e.get("case_wall_sum_s")),
            "parallel efficiency": _round(e.get("parallel_efficiency"), 3),
            "critical path [s]": _round(e.get("critical_path_s")), "critical case": e.get("critical_case"),
            "predicted vs measured case cost (Pearson r)": "-" if r is None else _round(r, 3),
            "cost sources": ", ".join(f"{k}: {v}" for k, v in sorted(sched.get("cost_sources", {}).items())) or "-",
            # kernels idle workers compiled (or loaded) ahead of their cases (jit/compile_plan.py)
            "kernels compiled ahead": sched.get("kernel_jobs", "-")}
    page.table(pd.DataFrame({"quantity": list(rows), "value": [str(v) for v in rows.values()]}))


def _round(x, digits: int = 2):
    return "-" if x is None else round(float(x), digits)
