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
