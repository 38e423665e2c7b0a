"""Throughput of Miller's 50-segment snake step loop (issue target: >= 50,000 steps/s on one core).

Time it with:
    python -m pytest tests/benchmarks/test_bench_massspring.py --benchmark-enable --benchmark-only
In the normal test run (--benchmark-disable) it runs once as a smoke test.
"""
from bench_myriapoda.bodies.massspring.body import BodyMassSpring
from bench_myriapoda.core.config import resolve_case

STEPS_PER_CALL = 5000


def test_snake_50_segment_step_loop(benchmark):
    case = resolve_case("snake", "massspring", "flat")  # lateral undulation, anisotropic Coulomb friction
    assert case.creature.segments == 50
    body = BodyMassSpring(case)
    body.compile()
    # settle into a moving gait first so the timed steps see contacts, friction and muscles
    body.advance(0.0, 20000)
    t = [20000 * case.dt]

    def chunk():
        done, status = body.advance(t[0], STEPS_PER_CALL)
        t[0] += done * case.dt
        assert status == 0

    benchmark.pedantic(chunk, rounds=15, iterations=1, warmup_rounds=2)
    if benchmark.stats is not None:
        median = benchmark.stats.stats.median
        benchmark.extra_info["steps_per_s"] = STEPS_PER_CALL / median
        benchmark.extra_info["ns_per_spring_step"] = median / STEPS_PER_CALL / body.lattice.n_springs * 1e9
