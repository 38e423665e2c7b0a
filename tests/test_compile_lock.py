"""Two processes that need the same cached kernel at the same moment compile it once (jit/compile_lock.py)."""
from __future__ import annotations

import multiprocessing as mp
import textwrap

KERNEL = textwrap.dedent('''
    import numpy as np
    from numba import njit


    @njit(cache=True)
    def kernel(a, n):
        """Enough loops and branches that compiling it takes a good fraction of a second."""
        s = 0.0
        for i in range(n):
            for j in range(a.shape[0]):
                if a[j] > i:
                    s += np.sin(a[j]) * np.cos(i) + np.exp(-a[j] * a[j])
                elif a[j] < -i:
                    s -= np.tanh(a[j]) * np.log1p(abs(a[j]))
                else:
                    s += np.sqrt(abs(a[j])) + np.arctan2(a[j], 1.0 + i)
        return s
''')


def _compile_in_child(module_dir, cache_dir, use_lock, barrier, out):
    import os
    import sys

    os.environ["NUMBA_CACHE_DIR"] = cache_dir
    sys.path.insert(0, module_dir)
    import numba
    import numpy as np
    from numba.core import event as ev

    numba.config.CACHE_DIR = cache_dir
    if use_lock:
        from bench_myriapoda.jit import compile_lock

        compile_lock.install()
    import lockdemo

    compiled = []

    class Rec(ev.Listener):
        def on_start(self, event):
            if event.data["dispatcher"].py_func is lockdemo.kernel.py_func:
                compiled.append(1)

        def on_end(self, event):
            pass

    ev.register("numba:compile", Rec())
    barrier.wait()
    value = lockdemo.kernel(np.linspace(-2.0, 2.0, 7), 3)
    out.put((len(compiled), value))


def _run_pair(tmp_path, use_lock):
    mod = tmp_path / "mod"
    mod.mkdir()
    (mod / "lockdemo.py").write_text(KERNEL)
    cache = tmp_path / "cache"
    cache.mkdir()
    ctx = mp.get_context("spawn")
    barrier, out = ctx.Barrier(2), ctx.Queue()
    procs = [ctx.Process(target=_compile_in_child, args=(str(mod), str(cache), use_lock, barrier, out))
             for _ in range(2)]
    for p in procs:
        p.start()
    results = [out.get(timeout=300) for _ in procs]
    for p in procs:
        p.join(timeout=60)
        assert p.exitcode == 0
    return results


def test_two_workers_compile_a_shared_kernel_once(tmp_path):
    # without the lock both processes miss the cache and compile (checked when this test was written; not
    # asserted, since it depends on the two compiles overlapping in time)
    results = _run_pair(tmp_path, use_lock=True)
    assert sorted(n for n, _ in results) == [0, 1]  # one compiled it, the other loaded it from the cache
    assert results[0][1] == results[1][1]

