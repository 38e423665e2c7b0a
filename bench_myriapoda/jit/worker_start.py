"""How the local executor's worker processes start: forked from a server that imported the package once.

A ``spawn`` worker starts a fresh interpreter and imports numpy, numba, scipy and this package and registers
the body models before its first case: measured with ``python -m bench_myriapoda.harness.worker_costs``,
several seconds of CPU per worker, once per worker (figures in docs/benchmarks.md).  A
``forkserver`` with this package preloaded (``worker_preload``) does that once, in its server process, which
starts at the beginning of ``bench-myriapoda matrix`` (:func:`prestart`) while the parent expands the matrix;
each worker is then a fork of the server.  The server is single-threaded, so forking it is safe even when
the parent runs threads (a progress bar, a Dask client); the parent itself is never forked.

The server keeps the environment and ``sys.path`` it started with, and its workers inherit them: when either
has changed since (a test setting ``NUMBA_CACHE_DIR``), the server is stopped and started again.  Where
there is no ``forkserver`` (Windows, macOS' default is spawn-safe but this keeps one code path), where the
temporary directory's path is too long for the server's Unix socket, or with ``BENCH_MYRIAPODA_WORKER_START=spawn``,
workers are spawned as before.  Results do not depend on it: a
worker runs the same code on the same resolved case either way.
"""
from __future__ import annotations

import multiprocessing as mp
import os
import sys
import tempfile

# What the fork server imports in its own process: the harness's worker code.  Named, not imported: this package
# sits below the harness and starts the workers without knowing what they run.
PRELOAD = "bench_myriapoda.harness.worker_preload"
START_METHODS = ("forkserver", "spawn")
ENV_START = "BENCH_MYRIAPODA_WORKER_START"
_IGNORED_ENV = {"PYTEST_CURRENT_TEST"}  # changes every test; nothing in a worker reads it
_server_key: tuple | None = None  # (environment, sys.path) the running fork server started with
# A Unix socket's path holds at most 107 bytes (Linux's sun_path is 108, one of them the terminating NUL).  The fork
# server listens on ``<temporary directory>/pymp-XXXXXXXX/listener-XXXXXXXX`` (multiprocessing: its per-process folder,
# then the socket), 32 bytes after the temporary directory's own path.
SOCKET_PATH_MAX = 107
FORKSERVER_SOCKET_TAIL = len("/pymp-XXXXXXXX/listener-XXXXXXXX")


def forkserver_socket_fits(temp_dir: str | None = None) -> bool:
    """Whether the fork server's socket, in a folder of ``temp_dir`` (default: this process's temporary directory,
    ``$TMPDIR`` or ``/tmp``), has a path short enough to bind: under a long ``$TMPDIR`` (a test's own folder, a deep
    job directory) ``bind`` failed with "AF_UNIX path too long" before the first case.  Counted in bytes of the
    file system's encoding, and conservatively: multiprocessing may already hold a shorter folder of its own."""
    d = tempfile.gettempdir() if temp_dir is None else temp_dir
    return len(os.fsencode(d)) + FORKSERVER_SOCKET_TAIL <= SOCKET_PATH_MAX


def start_method() -> str:
    """``forkserver`` where available, not turned off with ``BENCH_MYRIAPODA_WORKER_START=spawn`` and with a
    temporary directory short enough for its socket (:func:`forkserver_socket_fits`), else ``spawn``."""
    wanted = os.environ.get(ENV_START, "forkserver")
    if wanted == "spawn" or "forkserver" not in mp.get_all_start_methods() or not forkserver_socket_fits():
        return "spawn"
    from multiprocessing import forkserver

    return "forkserver" if hasattr(forkserver, "_forkserver") and hasattr(forkserver._forkserver, "_stop") else "spawn"


def worker_context(method: str | None = None):
    """The multiprocessing context local workers start from (``method``: ``forkserver`` or ``spawn``;
    default :func:`start_method`).  A fork server started under another environment is restarted."""
    global _server_key
    method = method or start_method()
    if method == "spawn":
        return mp.get_context("spawn")
    from multiprocessing import forkserver

    key = (tuple(sorted((k, v) for k, v in os.environ.items() if k not in _IGNORED_ENV)), tuple(sys.path))
    if _server_key is not None and key != _server_key:
        forkserver._forkserver._stop()  # its workers would inherit the old environment
    ctx = mp.get_context("forkserver")
    ctx.set_forkserver_preload([PRELOAD])
    _server_key = key
    return ctx


def prestart() -> None:
    """Start the fork server now, so its imports run while the caller does other work (no-op with spawn)."""
    ctx = worker_context()
    if ctx.get_start_method() == "forkserver":
        from multiprocessing import forkserver

        forkserver.ensure_running()
