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
