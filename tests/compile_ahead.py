"""Compile the quick matrix's kernels ahead of a cold test session, on every core, while the tests start.

Run by ``tests/conftest.py`` (``pytest_collection_finish``) in the background, once per test session, when the
session runs the main job (the ``quick_run`` fixture): the main job compiles every kernel group of the quick matrix
anyway (the lattice and FEM worm, the hybrid chain, the three walking centipedes), so compiling them ahead adds no
work; it only moves it.

Why: on a cold JIT cache the first tests of every worker call the same kernels (the leg controller, the rigid
segments, the terrain queries, each body's step).  numba compiles a kernel's callees depth first inside the caller's
compile, and the compile lock (``jit.compile_lock``) lets one process compile each kernel while the others wait for
it, so the test workers queued behind one compile at a time: in a cold run of the whole suite on the 2-core machine
(f725d9b) the pytest processes used 1.0-1.2 cores over the first 300 s (a walking-centipede test took 74.7 s of wall
for 2.8 s of CPU), against 1.9-2.0 afterwards.  Here one process per core takes the recorded kernels
(``jit/compile_plans.json``, ``jit.compile_plan``) from a shared list, leaves first (the last callee of each caller
first, ``compile_plan._reverse_postorder``) and the groups with the longest recorded compile first, so two compiles of
disjoint subtrees run side by side, under the same compile lock as the tests: a kernel is still compiled once, by
whichever process reaches it first, and the others load it from the cache.

``python3 tests/compile_ahead.py [PROCESSES]`` prints one line per kernel and a summary; the exit status is 0 even
when a kernel fails to compile (the test that needs it compiles it itself and reports what fails).
``BENCH_TEST_COMPILE_AHEAD=off`` turns it off for a test session.
"""
from __future__ import annotations

import multiprocessing
import os
import sys
import time

import bench_myriapoda  # noqa: F401 -- first: numba's cache directory (core.source_hash) is set before numba's import

ENV_SWITCH = "BENCH_TEST_COMPILE_AHEAD"


def enabled() -> bool:
    """Whether a test session compiles ahead (not turned off with ``BENCH_TEST_COMPILE_AHEAD=off``)."""
    return os.environ.get(ENV_SWITCH, "on").strip().lower() not in ("off", "0", "no", "false")


def ahead_signatures() -> list[tuple[str, tuple]]:
    """(kernel, numba argument types) of every recorded group's cacheable kernels, each signature once: groups with
    the longest recorded serial compile first, within a group callees before callers, the last callee first.  Empty
    where the plans do not apply (``compile_plan.load_plans``' rules: another numba version, turned off, unreadable);
    a stale signature (``compile_plan.stale_reason``) is left out."""
    import numba

    from bench_myriapoda.jit import compile_plan as cp

    if not cp.plans_enabled():
        return []
    data = cp.shipped_plans()
    if numba.__version__.split(".")[:2] != data.numba_version.split(".")[:2]:
        return []
    seen: set[str] = set()
    out = []
    serial = {name: sum(ev[4] for ev in plan["events"] if ev[2] == 0) for name, plan in data.plans.items()}
    for name in sorted(data.plans, key=lambda n: -serial[n]):
        plan = data.plans[name]
        try:
            args = cp._decode_args(plan["args"])
        except Exception:  # noqa: BLE001 -- pickled by another numba: that group compiles in its tests
            continue
        events = plan["events"]
        for k in cp._reverse_postorder(events):
            kernel, sig, _depth, _parent, _incl, _self, _cached, can_cache = events[k]
            if not can_cache or args[k] is None or sig in seen:
                continue
            seen.add(sig)
            if cp.stale_reason(kernel, tuple(args[k])) is None:
                out.append((kernel, tuple(args[k])))
    return out


def _start_worker() -> None:
    from bench_myriapoda.jit import compile_lock

    compile_lock.install()


def _compile_one(task: tuple[str, tuple]) -> tuple[str, float, str]:
    from bench_myriapoda.jit.compile_plan import compile_kernels

    kernel, args = task
    t0 = time.perf_counter()
    try:
        compile_kernels([task])
        return kernel, time.perf_counter() - t0, ""
    except Exception as exc:  # noqa: BLE001 -- reported; the test that needs the kernel compiles it itself
        return kernel, time.perf_counter() - t0, f"{type(exc).__name__}: {exc}"


def main(processes: int) -> int:
    t0 = time.perf_counter()
    tasks = ahead_signatures()
    failed = 0
    # fork: the workers inherit the imported package (numba's import and the plans' reading are done once)
    with multiprocessing.get_context("fork").Pool(processes, initializer=_start_worker) as pool:
        for kernel, wall, error in pool.imap(_compile_one, tasks, chunksize=1):
            failed += bool(error)
            print(f"{wall:7.2f} s {kernel}{'  FAILED ' + error if error else ''}", flush=True)
    print(f"compile ahead: {len(tasks)} signatures, {failed} failed, {time.perf_counter() - t0:.1f} s wall, "
          f"{processes} processes", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else (len(os.sched_getaffinity(0)) or 1)))
