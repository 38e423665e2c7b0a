"""The local executor hands out the first case of every compile group first (compile once, not once per worker)."""
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.executors import compile_first_order, compile_group


def test_first_case_of_every_compile_group_goes_first_and_the_rest_keep_their_order():
    worm_ms = resolve_case("worm", "massspring", "flat")
    snake_ms = resolve_case("snake", "massspring", "flat")
    worm_fem = resolve_case("worm", "fem", "flat")
    centipede = resolve_case("centipede", "hybrid", "walk")
    cases = [worm_ms, snake_ms, worm_fem, centipede, resolve_case("worm", "fem", "flat", duration=1.0)]
    assert compile_group(worm_ms) == compile_group(snake_ms) != compile_group(worm_fem)
    assert compile_group(centipede)[1] and not compile_group(worm_ms)[1]
    order = [i for i, _ in compile_first_order(cases)]
    assert order == [0, 2, 3, 1, 4]


def test_a_group_sharing_kernels_with_a_compiling_one_waits_behind_warm_cases():
    from bench_myriapoda.harness.executors import CompileScheduler, shares_kernels

    chain = resolve_case("chain", "hybrid", "fig4-drop")  # hybrid, legless
    walk_h = resolve_case("centipede", "hybrid", "walk")  # hybrid, legged: the same body kernels
    worm = resolve_case("worm", "massspring", "flat")
    worm_2 = resolve_case("worm", "massspring", "flat", duration=1.0)
    walk_fem = resolve_case("centipede", "fem", "walk")  # legged: the same leg-controller kernels as walk_h
    assert shares_kernels(compile_group(chain), compile_group(walk_h))
    assert not shares_kernels(compile_group(chain), compile_group(worm))
    s = CompileScheduler([worm, chain, walk_h, worm_2, walk_fem])
    assert s.next_job()[0] == 0  # the worm's kernels start compiling
    s.finished(0)
    assert s.next_job()[0] == 1  # the chain compiles the hybrid body ...
    assert s.next_job()[0] == 4  # ... the FEM walk shares nothing with it: it compiles in parallel
    assert s.next_job()[0] == 3  # the hybrid walk shares kernels with both: the warm worm case goes first
    assert s.next_job()[0] == 2  # no warm work left: the hybrid walk starts (better than an idle worker)
    assert s.next_job() is None and not s.pending


def test_scheduler_waits_only_when_every_pending_case_is_in_a_compiling_group():
    from bench_myriapoda.harness.executors import CompileScheduler

    worm = resolve_case("worm", "massspring", "flat")
    worm_2 = resolve_case("worm", "massspring", "flat", duration=1.0)
    s = CompileScheduler([worm, worm_2])
    assert s.next_job()[0] == 0
    assert s.next_job() is None  # worm_2 waits for the worm's kernels to reach the cache
    s.finished(0)
    assert s.next_job()[0] == 1
    assert s.next_job() is None and not s.pending



def test_the_extra_compile_worker_compiles_a_cold_group_and_leaves_its_case_to_the_workers():
    from bench_myriapoda.harness.executors import CompileScheduler

    worm = resolve_case("worm", "massspring", "flat")
    worm_2 = resolve_case("worm", "massspring", "flat", duration=1.0)
    chain = resolve_case("chain", "hybrid", "fig4-drop")
    snake_fem = resolve_case("snake", "fem", "flat")
    s = CompileScheduler([worm, worm_2, chain, snake_fem])
    assert s.next_job()[0] == 0  # a worker starts the worm's compile
    assert s.next_compile_job()[0] == 2  # the extra worker compiles the chain's group, shares nothing with it
    assert s.next_job()[0] == 3  # another worker: the FEM group (worm_2 waits for the worm, the chain compiles)
    assert s.cold_groups_pending() is False
    assert s.next_compile_job() is None  # nothing left to compile: the extra worker stops
    s.compiled(2)  # the chain's kernels are in the cache; its case is a warm case now, still pending
    assert s.next_job()[0] == 2
    s.finished(0)
    assert s.next_job()[0] == 1
    assert s.next_job() is None and not s.pending


def test_a_failed_compile_only_job_leaves_its_group_cold():
    from bench_myriapoda.harness.executors import CompileScheduler

    chain = resolve_case("chain", "hybrid", "fig4-drop")
    s = CompileScheduler([chain])
    assert s.next_compile_job()[0] == 0 and s.next_job() is None
    s.compiled(0, ok=False)
    assert s.cold_groups_pending() and s.next_job()[0] == 0
