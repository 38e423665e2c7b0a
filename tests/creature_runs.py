"""Running a built ``Creature`` for a while, as the tests of the dynamic stance do: the fused path in chunks."""
from __future__ import annotations

CHUNK = 500  # steps per fused call


def run_for(cr, dt: float, duration_s: float, each_chunk=None) -> tuple[int, int]:
    """Advance ``cr`` from t = 0 by ``duration_s`` [s] at ``dt`` [s] in chunks of ``CHUNK`` steps, stopping at the
    first non-zero step status; ``each_chunk(done)`` after every chunk.  Returns (steps done, last status)."""
    n = int(round(duration_s / dt))
    done = status = 0
    while done < n and status == 0:
        k, status = cr.advance(done * dt, min(CHUNK, n - done))
        done += k
        if each_chunk is not None:
            each_chunk(done)
    return done, status


def validate_quick_rows(body: str, out_dir, capsys, quick_checks) -> tuple[int, list[dict]]:
    """``bench-myriapoda validate --quick --body BODY --json`` in this process (a plugin body's conformance run):
    its exit code and its rows, after checking that the rows are exactly the body's quick checks and that none of
    them broke on the body (a verdict on the physics, never a traceback)."""
    import json

    from bench_myriapoda.cli import main

    code = main(["validate", "--quick", "--body", body, "--json", "--no-store", "--out", str(out_dir)])
    rows = json.loads(capsys.readouterr().out)["rows"]
    assert {(r["check"], r["body"]) for r in rows} == {(c, body) for c in quick_checks}
    for r in rows:
        assert "traceback" not in r["figures"], r["detail"]
    return code, rows
