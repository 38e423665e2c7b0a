"""The main job's second half: the fidelity and stability of every creature x body pair of the quick matrix.

After the matrix has run (``cli.matrix.cmd_matrix``), ``fidelity_phase`` writes two files into its output directory:

``stable_dt.json``   the [largest stable, smallest unstable] dt of every headline pair, bisected to 10 % on
                     1 s runs (``harness.stable_dt.brackets_for_cases``; kept by case and source hash, so a
                     rerun of the same code bisects nothing);
``validation.json``  the ``validate --quick`` checks that apply to the matrix's pairs (``main_job_checks``):
                     each body's own checks and the checks of the matrix's creatures on the matrix's bodies,
                     less those the matrix's own headline cases answer (their verdicts are judged on those cases
                     by ``report.scorecard_verdicts``: the same runs, not simulated twice).  Written as
                     ``validate --out DIR`` writes it, with the source hash: a rerun of the same code and the same
                     checks keeps it.

Both run on one process pool of the matrix's workers: the check groups (one per body, so that checks sharing
a simulation share it, as in one ``validate`` run) first, the bisections after.  ``same_code_rerun`` lets
the main job keep the cases of an earlier complete run of the same code (``MARKER_NAME``).
"""
from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Callable

# validate checks whose run is a headline case of the quick matrix: the report judges them on that case
# (report.scorecard_verdicts), so the main job does not simulate them again
ANSWERED_BY_MATRIX = ("paper.fig10d-walk", "paper.wave-centipede", "paper.wave-millipede", "throughput.sec6-headline")
MARKER_NAME = "main_job.json"


def headline_cases(exp) -> list:
    """The first case of every creature x body pair outside the sweeps (no grid key among its axes)."""
    seen, out = set(), []
    for m in exp.cases:
        if any(k in m.axes for k in exp.grid_keys):
            continue
        pair = (m.axes["creature"], m.axes["body"])
        if pair not in seen:
            seen.add(pair)
            out.append(m.case)
    return out


def main_job_checks(creatures: set[str], bodies: tuple[str, ...]) -> list[tuple[str, str]]:
    """(check name, body) of the ``validate --quick`` set that apply to pairs of ``creatures`` on ``bodies``:
    a body's own checks (``report.scorecard.BODY_CHECKS``) and the checks of one of ``creatures``, less
    ``ANSWERED_BY_MATRIX``; cross-body rows are no pair's."""
    from .scorecard import check_creature
    from ..validation.core import CROSS
    from ..validation.run import select

    pairs, _ = select(None, bodies, True)
    out = []
    for check, body in pairs:
        if body == CROSS or check.name in ANSWERED_BY_MATRIX:
            continue
        concerns = check_creature(check.name)
        if concerns is None or concerns in creatures:
            out.append((check.name, body))
    return out


def run_check_group(names: list[str], body: str) -> list[dict]:
    """``validation.run.run_checks`` of checks ``names`` on ``body`` in one ``Context`` (quick sizes): rows as dicts."""
    from ..validation.registry import BY_NAME
    from ..validation.run import run_checks

    return [r.to_dict() for r in run_checks([(BY_NAME[n], body) for n in names], True, (body,))]


def _group_rows(future, names: list[str], body: str) -> list[dict]:
    """A check group's rows; a group whose worker failed is a FAIL row per check naming the failure (as
    ``validation.run.run_checks`` records a check that raises)."""
    from ..validation.core import FAIL, Row
    from ..validation.registry import BY_NAME

    try:
        return future.result()
    except Exception as exc:  # the worker process died (BrokenProcessPool) or the rows did not come back
        return [Row(n, BY_NAME[n].family, body, BY_NAME[n].quantity, None, None, BY_NAME[n].source, "-", FAIL,
                    f"the worker process failed: {type(exc).__name__}: {exc}").to_dict() for n in names]


def _read_json(path: Path) -> dict | None:
    try:
        doc = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    return doc if isinstance(doc, dict) else None


def fidelity_phase(exp, out: Path, workers: int | None,
                   progress: Callable[[str], None] | None = None) -> dict:
    """Bisect the headline pairs' stable dt and run the checks that apply; write ``out/stable_dt.json`` and
    ``out/validation.json``.  Returns {"brackets": n, "checks": n, "validation_kept": bool, "cpu_s"...}."""
    import os
    from concurrent.futures import ProcessPoolExecutor

    from ..validation.core import clean
    from ..validation.registry import CHECKS
    from ..validation.run import JSON_NAME, summary, write_json
    from ..validation.core import Row
    from ..harness.stable_dt import brackets_for_cases, source_hash
    from ..jit.worker_start import worker_context

    t0 = time.perf_counter()
    code = source_hash()
    heads = headline_cases(exp)
    creatures = {c.creature.name for c in heads}
    bodies = tuple(dict.fromkeys(c.body.name for c in heads))
    checks = main_job_checks(creatures, bodies)
    vpath = out / JSON_NAME
    old = _read_json(vpath)
    want = sorted([list(p) for p in checks])
    keep = old is not None and old.get("code") == code and old.get("checks") == want and old.get("main_job")
    groups: dict[str, list[str]] = {}
    for name, body in checks:
        groups.setdefault(body, []).append(name)
    n = max(1, min(workers or os.cpu_count() or 1, 64))
    with ProcessPoolExecutor(max_workers=n, mp_context=worker_context()) as pool:
        futures = {} if keep else {b: pool.submit(run_check_group, names, b) for b, names in groups.items()}
        if futures and progress is not None:
            progress(f"validate --quick: {len(checks)} checks that apply to the matrix's pairs")
        brackets = brackets_for_cases(heads, out, n, progress, pool=pool)
        rows = {b: _group_rows(f, groups[b], b) for b, f in futures.items()}
    if not keep:
        order = {c.name: i for i, c in enumerate(CHECKS)}
        body_order = {b: i for i, b in enumerate(bodies)}
        dicts = sorted((r for rs in rows.values() for r in rs), key=lambda r: (order[r["check"]],
                                                                              body_order.get(r["body"], 99)))
        counts = summary([Row(**{k: v for k, v in r.items() if k in Row.__dataclass_fields__}) for r in dicts])
        doc = clean({"quick": True, "bodies": list(bodies), "wall_s": time.perf_counter() - t0, "counts": counts,
                     "rows": dicts, "work_precision": None, "run_id": None, "main_job": True, "code": code,
                     "checks": want})
        write_json(out, doc)
    return {"brackets": len(brackets), "checks": len(checks), "validation_kept": bool(keep),
            "wall_s": time.perf_counter() - t0}


def same_code_rerun(out: Path, matrix: str) -> bool:
    """True when ``out`` holds a complete run of ``matrix`` by this very code (``MARKER_NAME``)."""
    from ..harness.stable_dt import source_hash

    doc = _read_json(out / MARKER_NAME)
    return bool(doc) and doc.get("code") == source_hash() and doc.get("matrix") == matrix \
        and (out / "results.sqlite").is_file()


def write_marker(out: Path, matrix: str) -> None:
    """Mark ``out`` as a complete run of ``matrix`` by this code (see ``same_code_rerun``)."""
    from ..harness.stable_dt import source_hash

    path = out / MARKER_NAME
    tmp = path.with_suffix(".json.tmp")
    tmp.write_text(json.dumps({"code": source_hash(), "matrix": matrix,
                               "timestamp": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}))
    tmp.replace(path)
