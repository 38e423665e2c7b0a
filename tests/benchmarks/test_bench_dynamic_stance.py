"""The dynamic stance's cost (issue 43 target: a walking hybrid centipede in dynamic stance at most 1.5x its
kinematic walk per step; fused path, one core, dt = 1/3000 s, 18 segments); the fem centipede's ratio measured
the same way (no target: its blocks' push is measured, not bounded).

Both walks are timed in the same run, chunk against chunk alternately (so that a machine's load falls on
both alike), and the ratio of the medians goes into the benchmark's extra_info:
    python -m pytest tests/benchmarks/test_bench_dynamic_stance.py --benchmark-enable --benchmark-only -s
"""
import statistics
import time

from bench_myriapoda.harness.throughput_suite import CENTIPEDE_WALK_IN_STEPS as WALK_IN_STEPS
from bench_myriapoda.harness.throughput_suite import walking_centipede

STEPS_PER_CALL = 300
ROUNDS = 8


def dynamic_against_kinematic(benchmark, body: str, target: str = "") -> float:
    """Time the 18-segment ``body`` centipede's walk in both stances alternately; returns the ratio of the medians
    (dynamic / kinematic per step) and puts both into the benchmark's extra_info."""
    walks = {stance: walking_centipede(18, body, sets=(f"legs.stance={stance}",))
             for stance in ("kinematic", "dynamic")}
    t = {stance: WALK_IN_STEPS * case.dt for stance, (case, _) in walks.items()}
    times = {stance: [] for stance in walks}

    def chunk(stance):
        case, b = walks[stance]
        start = time.thread_time()
        done, status = b.advance(t[stance], STEPS_PER_CALL)
        times[stance].append((time.thread_time() - start) / STEPS_PER_CALL)
        t[stance] += done * case.dt
        assert status == 0

    def both():
        chunk("kinematic")
        chunk("dynamic")

    benchmark.pedantic(both, rounds=ROUNDS, iterations=1, warmup_rounds=1)
    kin, dyn = statistics.median(times["kinematic"]), statistics.median(times["dynamic"])
    ratio = dyn / kin
    print(f"\n{body} centipede, 18 segments: kinematic {kin * 1e6:.1f} us/step, dynamic {dyn * 1e6:.1f} us/step, "
          f"ratio {ratio:.2f}{target}")
    if benchmark.stats is not None:
        benchmark.extra_info.update(kinematic_us_per_step=kin * 1e6, dynamic_us_per_step=dyn * 1e6,
                                    dynamic_over_kinematic=ratio)
    return ratio


def test_hybrid_centipede_dynamic_against_kinematic_stance(benchmark):
    dynamic_against_kinematic(benchmark, "hybrid", " (target <= 1.5)")


def test_fem_centipede_dynamic_against_kinematic_stance(benchmark):
    dynamic_against_kinematic(benchmark, "fem")
