"""What the terrain benchmarks (``test_bench_obstacles.py``, ``test_bench_terrain.py``) share: the walking hybrid
centipede, built with its leg controller, compiled and walked in, then timed in chunks of ``STEPS_PER_CALL``
steps; and ``query_loop``, the pair of terrain queries they time per point.

pytest puts this folder on ``sys.path`` (no ``__init__.py``), so the benchmark files import it by name.
"""
from __future__ import annotations

from numba import njit

from bench_myriapoda.harness.throughput_suite import CENTIPEDE_WALK_IN_STEPS
from bench_myriapoda.world import terrain_kernels as TK

STEPS_PER_CALL = 300


def walker(overrides, scenario: str = "walk", walk_in_steps: int = CENTIPEDE_WALK_IN_STEPS):
    """(case, creature): the hybrid centipede in ``scenario`` with ``overrides``, compiled and walked in for
    ``walk_in_steps`` steps (``CENTIPEDE_WALK_IN_STEPS``: ADJUSTMENT is over and the leg wave has formed)."""
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness.runner import Creature

    case = resolve_case("centipede", "hybrid", scenario, overrides=overrides)
    b = Creature(case)  # the hybrid body with its leg controller
    b.compile()
    done, status = b.advance(0.0, walk_in_steps)
    assert status == 0, b.status_text(status)
    return case, b


def time_walk_chunks(benchmark, case, b, walk_in_steps: int, rounds: int) -> None:
    """Benchmark ``rounds`` chunks of ``STEPS_PER_CALL`` steps of a creature ``walker`` walked in for
    ``walk_in_steps`` steps (one warm-up chunk first); the median per step [us] goes to extra_info's
    ``us_per_step``."""
    t = [walk_in_steps * case.dt]

    def chunk():
        done, status = b.advance(t[0], STEPS_PER_CALL)
        t[0] += done * case.dt
        assert status == 0

    benchmark.pedantic(chunk, rounds=rounds, iterations=1, warmup_rounds=1)
    if benchmark.stats is not None:
        benchmark.extra_info["us_per_step"] = benchmark.stats.stats.median / STEPS_PER_CALL * 1e6


@njit(cache=True, error_model="numpy")
def query_loop(kind, f, p):
    """phi and normal at every point p (N, 3) [m]; returns a checksum so nothing is optimised away."""
    acc = 0.0
    for i in range(p.shape[0]):
        phi = TK.signed_distance(kind, f, p[i, 0], p[i, 1], p[i, 2])
        nx, ny, nz = TK.surface_normal(kind, f, p[i, 0], p[i, 1], p[i, 2])
        acc += phi + nx + 2.0 * ny + 3.0 * nz
    return acc
