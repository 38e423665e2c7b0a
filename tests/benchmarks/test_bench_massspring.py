"""Throughput of Miller's 50-segment snake step loop (issue target: >= 50,000 steps/s on one core).

Time it with:
    python -m pytest tests/benchmarks/test_bench_massspring.py --benchmark-enable --benchmark-only
In the normal test run (--benchmark-disable) it runs once as a smoke test.
"""
from bench_myriapoda.bodies.massspring.benchmarks import SNAKE, SNAKE_SETTLE_STEPS
from bench_myriapoda.harness.throughput_suite import settled_creature

STEPS_PER_CALL = 5000


def test_snake_50_segment_step_loop(benchmark):
    # lateral undulation, anisotropic Coulomb friction; compiled, and settled into a moving gait first
    # so the timed steps see contacts, friction and muscles (the scene of `bench-myriapoda regress`)
    case, body, t_settled = settled_creature("massspring", SNAKE)
    assert case.creature.segments == 50 and t_settled == SNAKE_SETTLE_STEPS * case.dt
    t = [t_settled]

    def chunk():
        done, status = body.advance(t[0], STEPS_PER_CALL)
        t[0] += done * case.dt
        assert status == 0

    benchmark.pedantic(chunk, rounds=15, iterations=1, warmup_rounds=2)
    if benchmark.stats is not None:
        median = benchmark.stats.stats.median
        benchmark.extra_info["steps_per_s"] = STEPS_PER_CALL / median
        benchmark.extra_info["ns_per_spring_step"] = median / STEPS_PER_CALL / body.lattice.n_springs * 1e9
