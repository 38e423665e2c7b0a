"""Compile each numba kernel once across processes: a file lock per (kernel, signature).

The matrix's local workers (``executors._run_local``) share numba's on-disk cache (``cache=True``).
numba looks a signature up in the cache and, on a miss, compiles it and saves it; two workers that
need the same kernel at the same time (the terrain queries every body calls, the rigid segments of
the hybrid and legged bodies, the leg controller of every walking case) both miss and both compile
it, which on a cold start doubled the compile work of the shared kernels (issue 13).
:func:`install` wraps ``Dispatcher.compile``: a cached kernel's signature that this process has not
loaded yet is looked up and compiled under an exclusive ``fcntl`` lock on a file named by the
kernel and signature in ``NUMBA_CACHE_DIR/compile-locks/``, so a second process waits for the
first, then loads the saved machine code instead of compiling it again.

No deadlock: a process holds the locks of the kernels it is compiling, outermost first, along the
call graph, which has no cycles; and a wait gives up after ``WAIT_S`` and compiles anyway.  Locks
die with their process (``flock``).  A file lock is taken inside numba's own compiler lock (one
compile at a time per process), so in a process with several threads compiling (a Dask worker with
``--nthreads`` above 1) only one thread at a time holds file locks; without that, two threads could
each hold one file lock and wait for numba's lock held by the other.  Kernels without ``cache=True`` (numba's own helpers) are
compiled as before.
"""
from __future__ import annotations

import hashlib
import os
import time

WAIT_S = 600.0  # longest wait for another process's compile before compiling anyway [s]
POLL_S = 0.05  # lock poll interval [s]

_held: set[str] = set()  # keys this process holds (a nested compile of the same key does not wait on itself)
_waited = [0.0, 0]  # seconds waited, number of waits (what ``stats`` reports)


def _lock_path(dispatcher, args) -> str:
    import numba

    f = dispatcher.py_func
    key = f"{f.__module__}.{f.__qualname__}:{f.__code__.co_filename}:{args}"
    d = os.path.join(numba.config.CACHE_DIR or ".", "compile-locks")
    os.makedirs(d, exist_ok=True)
    return os.path.join(d, hashlib.sha1(key.encode()).hexdigest()[:20] + ".lock")


def install() -> None:
    """Wrap numba's ``Dispatcher.compile`` in this process (idempotent; without ``fcntl``, e.g. on Windows,
    nothing changes and workers may compile a shared kernel side by side as before)."""
    try:
        import fcntl
    except ImportError:
        return
    from numba.core import dispatcher as nd, sigutils
    from numba.core.caching import NullCache
    from numba.core.compiler_lock import global_compiler_lock

    if getattr(nd.Dispatcher.compile, "_bench_compile_lock", False):
        return
    plain = nd.Dispatcher.compile

    def compile(self, sig):
        if isinstance(self._cache, NullCache) or not self._can_compile:
            return plain(self, sig)
        args, _ = sigutils.normalize_signature(sig)
        if tuple(args) in self.overloads:
            return plain(self, sig)
        path = _lock_path(self, tuple(args))
        with global_compiler_lock:  # re-entrant; numba takes it again inside ``plain``
            if path in _held:
                return plain(self, sig)
            return _locked(path, self, sig)

    def _locked(path, self, sig):
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            t0 = time.monotonic()
            waited = False
            while True:
                try:
                    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                    break
                except BlockingIOError:
                    waited = True
                    if time.monotonic() - t0 > WAIT_S:
                        break  # compile without the lock rather than hang
                    time.sleep(POLL_S)
            if waited:
                _waited[0] += time.monotonic() - t0
                _waited[1] += 1
            _held.add(path)
            try:
                return plain(self, sig)  # a cache hit now if the other process saved it meanwhile
            finally:
                _held.discard(path)
        finally:
            os.close(fd)  # releases the lock

    compile._bench_compile_lock = True
    nd.Dispatcher.compile = compile


def stats() -> tuple[float, int]:
    """(seconds this process waited for other processes' compiles, number of such waits)."""
    return _waited[0], _waited[1]
