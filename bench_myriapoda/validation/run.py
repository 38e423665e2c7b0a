"""Run the registry's checks, format the table, write ``validation.json`` and the store rows.

``select`` turns ``--check`` / ``--body`` into (check, body) pairs (bad names: ``InputError``, nothing
run); ``run_checks`` measures them in one ``Context`` (shared simulation cache), catching a check
that raises as a FAIL row with the exception; ``format_table`` is what ``validate`` prints.
"""
from __future__ import annotations

import json
import time
import traceback
from pathlib import Path
from typing import Callable, Sequence

from ..core.cells import fmt
from ..core.errors import InputError
from .core import CROSS, FAIL, NA, Check, Context, Row, all_bodies
from .registry import BY_NAME, CHECKS

DEFAULT_OUT = Path("reports") / "validation"
JSON_NAME = "validation.json"


def select(check_names: Sequence[str] | None, bodies: Sequence[str] | None,
           quick: bool) -> tuple[list[tuple[Check, str]], tuple[str, ...]]:
    """The (check, body) pairs to run, in registry order, and the selected bodies.

    ``check_names``: full names or family names (``analytic``); ``bodies``: body model names.
    ``quick`` keeps each check's ``quick_bodies`` only, unless the check was named explicitly.
    """
    known = all_bodies()
    bodies = tuple(bodies) if bodies else known
    for b in bodies:
        if b not in known:
            raise InputError("--body", b, f"unknown body model; allowed: {', '.join(known)}")
    families = {c.family for c in CHECKS}
    named: list[Check] = []
    for n in check_names or ():
        if n in BY_NAME:
            named.append(BY_NAME[n])
        elif n in families:
            named.extend(c for c in CHECKS if c.family == n)
        else:
            raise InputError("--check", n, "unknown check; allowed: a family (" + ", ".join(sorted(families))
                             + ") or one of " + ", ".join(BY_NAME))
    chosen = [c for c in CHECKS if c in named] if named else list(CHECKS)
    pairs = []
    for c in chosen:
        on = c.bodies if not quick or named or c.quick_bodies is None else c.quick_bodies
        if c.bodies == (CROSS,):
            if on:  # a cross-body check runs on the selected bodies
                pairs.append((c, CROSS))
            continue
        pairs.extend((c, b) for b in on if b in bodies)
    for n in check_names or ():  # a check named with --check that no selected body has: refused, not 0 rows
        c = BY_NAME.get(n)
        if c is not None and c.bodies != (CROSS,) and not any(b in bodies for b in c.bodies):
            raise InputError("--check", n, f"does not apply to body model {', '.join(bodies)}; it applies to "
                                           f"{', '.join(c.bodies)} (choose one with --body)")
    if not pairs:
        raise InputError("--check", " ".join(check_names or ()) or None,
                         f"no check of this selection applies to body model {', '.join(bodies)}")
    return pairs, bodies


def run_checks(pairs: list[tuple[Check, str]], quick: bool, bodies: tuple[str, ...] | None = None,
               progress: Callable[[str], None] | None = None) -> list[Row]:
    """Measure every (check, body) pair; a check that raises is a FAIL row naming the exception."""
    ctx = Context(quick, bodies)
    rows = []
    for i, (c, body) in enumerate(pairs):
        if progress:
            progress(f"[{i + 1}/{len(pairs)}] {c.name} on {body}")
        t0 = time.perf_counter()
        try:
            out = c.measure(ctx, body)
            row = Row(c.name, c.family, body, c.quantity, out.measured, out.reference, c.source, out.tolerance,
                      out.verdict, out.detail, out.unit, figures=dict(out.figures))
        except Exception as exc:  # a broken check is a failed check, shown with its cause
            row = Row(c.name, c.family, body, c.quantity, None, None, c.source, "-", FAIL,
                      f"{type(exc).__name__}: {exc}", figures={"traceback": traceback.format_exc(limit=3)})
        row.seconds = time.perf_counter() - t0
        rows.append(row)
    return rows


def format_table(rows: list[Row]) -> list[str]:
    """The human-readable table ``validate`` prints: one line per row, then the reason lines."""
    head = ("check", "body", "measured", "reference", "tolerance", "verdict", "s")
    cells = [(r.check, r.body, fmt(r.measured) + (f" {r.unit}" if r.unit and isinstance(r.measured, (int, float)) else ""),
              fmt(r.reference), r.tolerance, r.verdict, f"{r.seconds:.1f}") for r in rows]
    w = [max(len(h), *(len(c[i]) for c in cells)) if cells else len(h) for i, h in enumerate(head)]
    w = [min(x, 48) for x in w]
    out = ["  ".join(h.ljust(w[i]) for i, h in enumerate(head))]
    for c in cells:
        out.append("  ".join(str(x)[:w[i]].ljust(w[i]) for i, x in enumerate(c)))
    for r in rows:
        if r.verdict in (FAIL, NA) and r.detail:
            out.append(f"  {r.check} on {r.body}: {r.verdict}: {r.detail}")
    return out


def summary(rows: list[Row]) -> dict[str, int]:
    counts: dict[str, int] = {}
    for r in rows:
        counts[r.verdict] = counts.get(r.verdict, 0) + 1
    return counts


def write_json(out_dir: Path, doc: dict) -> Path:
    """``out_dir/validation.json`` (written to a temporary name, then renamed)."""
    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / JSON_NAME
    tmp = path.with_suffix(".json.tmp")
    tmp.write_text(json.dumps(doc, indent=1, sort_keys=False))
    tmp.replace(path)
    return path
