"""Running many cases: a local process pool or a Dask cluster, one store row per case.

:func:`run_matrix` runs resolved cases and records each result in the SQLite
store from this (the parent) process only, one transaction per case, tagged
``command = 'matrix'`` and ``matrix = NAME``.  Workers never touch the store.

``local``: ``workers`` long-lived processes, each fed one case at a time over a
pipe, forked from a server that has imported the package once (``worker_start``;
``spawn`` where there is no fork server).  Compile once, not once per worker: cases are grouped by the
kernels they compile (``compile_group``); the first case of every group goes out
first, and the other cases of a group wait until that one has finished, by when
its kernels are in numba's on-disk cache and the other workers load them instead
of compiling them again.  With fewer groups than workers the idle workers start
on the next group's first case, so different kernels compile in parallel; a group
that shares large kernels with one compiling now (same body, or both legged) waits
behind the warm cases (``CompileScheduler``).  Two workers that need the same kernel
at once (the terrain queries, the rigid segments, the leg controller are shared by
several groups) compile it once: the second waits for the first's cache entry
(``compile_lock``).  While groups remain to compile, one extra worker compiles a
cold group's kernels without running its case (``compile_case``; the case then runs
on a worker as a warm case), so a core is not left idle by a waiting worker and no
timed case shares a core with it; it stops when no group is left to compile.  A case that outruns ``timeout_per_case`` (measured from the
moment it is handed to a worker) is recorded with status ``timeout``; its worker
is killed and replaced.  A worker that dies (a segfault, an OOM kill) is
recorded as ``error`` with its exit code and replaced.  A case that raises is
already status ``error`` from :func:`run_case`.

``dask``: the same cases as ``dask.distributed`` tasks on the cluster at
``scheduler`` (``Client(ADDRESS)``), or on a ``LocalCluster`` of ``workers``
single-threaded workers.  The timeout clock starts when the scheduler reports
the task processing on a worker; a case that outruns it is recorded as
``timeout`` and its future cancelled, but Dask cannot stop a running task: the
worker thread stays busy until the case ends (on a LocalCluster with worker
processes the worker is restarted).

Resume (``resume=True``): cases whose ``case_hash`` already has a row for this
matrix in the store are skipped, so an interrupted matrix picks up where it
stopped; a result is stored only once it is complete, so no case is stored
twice and there is no partial row.
"""
from __future__ import annotations

import gc
import multiprocessing as mp
import os
import signal
import sys
import time
from collections import deque
from dataclasses import dataclass
from multiprocessing.connection import wait as mp_wait
from pathlib import Path
from typing import Callable, Sequence

from ..core.config import Case
from ..jit import compile_lock
from ..jit.compile_plan import compile_kernels, group_name, load_plans
from ..jit.worker_start import worker_context
from .recorder import compact_recording, save_recording
from .runner import RunResult, run_case
from .store import (STORE_WRITE_ERRORS, UnstoredError, keep_unstored, matrix_case_statuses, read_matrix_runs,
                    record_run)

EXECUTORS = ("local", "dask")
STARTUP_GRACE_S = 120.0  # a fresh worker's imports before its first case do not count against the timeout
MAX_WAIT_S = 3600.0  # the longest single wait for a worker's message; longer timeouts wait again


def slim_result(result: RunResult) -> RunResult:
    """What crosses a process boundary: the result without its full series and traceback.

    ``extra["recording"]`` carries a :func:`~.recorder.compact_recording` of the run (float32
    series and the leg-state timeline, tens of kB), which the parent saves for the report.
    """
    extra = {"labels": result.extra["labels"]} if "labels" in result.extra else {}
    if result.series is not None:
        extra["recording"] = compact_recording(result.series, result.extra)
    return RunResult(result.case, result.status, result.metrics, result.timings, result.message, None, extra)


def run_case_slim(case: Case) -> RunResult:
    """:func:`run_case` for a worker: never raises; returns the compact recording, not the full series."""
    return slim_result(run_case(case))


def _nan_timings(wall_s: float) -> dict[str, float]:
    nan = float("nan")
    return {"steps": 0, "steps_per_s": nan, "realtime_factor": nan, "compile_s": nan, "wall_s": wall_s}


def timeout_result(case: Case, timeout: float, wall_s: float) -> RunResult:
    return RunResult(case, "timeout", {}, _nan_timings(wall_s),
                     f"outran the per-case timeout of {timeout:g} s; its worker was stopped")


def died_result(case: Case, exitcode: int | None, wall_s: float) -> RunResult:
    how = f"signal {-exitcode}" if exitcode is not None and exitcode < 0 else f"exit code {exitcode}"
    return RunResult(case, "error", {}, _nan_timings(wall_s), f"worker process died ({how}) while running the case")


FAILED = ("error", "timeout")


def done_hashes(store_path: Path | str, matrix: str, retry_failed: bool = False) -> set[str]:
    """Case hashes that already have a row for ``matrix`` in the store (empty when there is no store).

    ``retry_failed``: leave out the cases whose newest row is ``error`` or ``timeout``, so they run again.
    """
    if not Path(store_path).exists():
        return set()
    rows = matrix_case_statuses(store_path, matrix)
    newest = dict(rows)  # later rows overwrite earlier ones: the newest status of each case
    return {h for h, st in newest.items() if not (retry_failed and st in FAILED)}


# --------------------------------------------------------------------------- local

def compile_case(case: Case) -> None:
    """Compile (or load) the kernels ``case`` needs without running it: its creature's, as ``run_case`` does."""
    from .runner import Creature

    creature = Creature(case)
    creature.compile()
    creature.body.observe(0.0)


# Python's cyclic garbage collector in a worker (gen0, gen1, gen2 thresholds; the default is (700, 10, 10)).
# A cold numba compile creates millions of long-lived objects (IR, types, LLVM wrappers); with the default, a
# full collection runs every 100 young ones and walks all of them: measured on the hybrid chain's cold compile
# (one process, 2026-11-24), 6.5 s of 52 CPU s in the collector, 24 full collections.  A full collection every
# 1,000 young ones instead: 2.9 s, with peak memory 473 MB instead of 397 MB (cycles wait longer).  Results do
# not depend on it; the cases still free their memory, full collections still run.
WORKER_GC_THRESHOLDS = (700, 10, 100)


def _worker_process(conn) -> None:
    """A local worker process: ``_worker_main``, then the process ends at once (``_exit_now``)."""
    _worker_main(conn)
    _exit_now()


def _exit_now() -> None:
    """End a worker process whose work is done, without the interpreter's teardown.

    Everything a worker produces has gone to the parent through its pipe (``send`` returns once
    written) and the JIT cache files are written when compiled, so the teardown -- freeing every
    module, compiled kernel and LLVM object one by one -- is only a wait for the parent, which joins
    it: 0.4 s for a worm-only worker, 0.9 s in a profiled quick matrix.  Standard streams are
    flushed first (a warning printed by a case still shows).
    """
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, AttributeError):
            pass
    os._exit(0)


KERNELS = "kernels"  # a worker job's mode: compile a list of kernel signatures (``compile_plan.KernelTask``)


def _worker_main(conn) -> None:
    """A local worker: receive ``(index, case, compile_only)``; send ``("started", index)``, then
    ``("done", slim result)``, or with ``compile_only`` ``("compiled", index)`` after :func:`compile_case`;
    with ``compile_only == KERNELS``, ``case`` is a list of (kernel, argument types) compiled ahead of the
    cases that need them (``compile_plan.compile_kernels``), then ``("compiled", index)``.

    ``None`` ends it.  The body models are imported once, before the first case.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C and stops its workers
    from ..core import registry

    worker_process_settings()  # the compile lock: a kernel another worker is compiling is loaded, not compiled twice
    registry.load_all()
    while True:
        try:
            msg = conn.recv()
        except (EOFError, OSError):
            return
        if msg is None:
            return
        index, case, compile_only = msg
        try:
            conn.send(("started", index))
            if compile_only == KERNELS:  # ``case`` is a list of (kernel, argument types): compile them ahead
                try:
                    compile_kernels(case)
                except Exception:  # noqa: BLE001 -- a signature that does not apply: the case compiles its own
                    pass
                conn.send(("compiled", index))
            elif compile_only:
                try:
                    compile_case(case)
                except Exception:  # noqa: BLE001 -- the case's own run reports the error
                    pass
                conn.send(("compiled", index))
            else:
                conn.send(("done", slim_result(run_case(case, progress=_WarmSignal(conn, index)))))
        except (BrokenPipeError, ConnectionResetError, EOFError):  # the parent is gone (killed): end quietly
            return


class _WarmSignal:
    """``run_case``'s progress callback in a local worker: after the case's first chunk (its kernels compiled
    or loaded, one chunk run) it sends ``("warm", index)`` once, so the parent hands the other cases of its
    compile group to idle workers without waiting for the whole case (``CompileScheduler.warmed``)."""

    def __init__(self, conn, index: int):
        self.conn, self.index, self.sent = conn, index, False

    def __call__(self, _fraction: float) -> None:
        if not self.sent:
            self.sent = True
            self.conn.send(("warm", self.index))


@dataclass
class _Slot:
    proc: mp.Process
    conn: object
    job: tuple[int, Case] | None = None
    started: float = 0.0  # when the case was handed over, then when the worker reported starting it
    running: bool = False
    retired: bool = False  # stopped for good (the extra compile worker, once no group is left to compile)
    compile_only: bool = False  # the job compiles its case's kernels without running it (the extra worker)
    kernel: object = None  # the job compiles this compile_plan.KernelTask ahead of its cases (an idle worker)
    stop_sent: bool = False  # told to exit (request_stop)

    def deadline(self, timeout: float) -> float:
        """A case times out ``timeout`` s after its worker starts it; a worker still starting up gets a grace."""
        return self.started + timeout + (0.0 if self.running else STARTUP_GRACE_S)

    def request_stop(self) -> None:
        """Ask an idle worker to exit (``stop`` then waits for it); a worker that cannot be told is killed."""
        if self.proc.is_alive() and not self.stop_sent:
            try:
                self.conn.send(None)
            except (OSError, ValueError):
                self.proc.kill()
            self.stop_sent = True

    def stop(self, kill: bool = False) -> None:
        if self.proc.is_alive():
            if kill:
                self.proc.kill()
            else:
                self.request_stop()
        self.proc.join(timeout=5)
        if self.proc.is_alive():
            self.proc.kill()
            self.proc.join()
        self.conn.close()


def _start_slot(ctx) -> _Slot:
    parent, child = ctx.Pipe(duplex=True)
    proc = ctx.Process(target=_worker_process, args=(child,), daemon=True, name="bench-myriapoda-matrix-worker")
    proc.start()
    child.close()
    return _Slot(proc, parent)


def compile_group(case: Case) -> tuple:
    """The key of the set of JIT kernels a case compiles: body model, legged or not, water or not.
    (Terrain kinds, gaits and sizes are run-time arguments of the same kernels.)"""
    from ..world.water_coupling import has_water

    return (case.body.name, case.creature.legs_per_segment > 0, has_water(case.scenario))


def compile_first_order(cases: Sequence[Case], costs: Sequence[float] | None = None) -> list[tuple[int, Case]]:
    """(index, case) with the first case of every compile group first, the rest in their order.

    With ``costs`` (predicted wall times [s], ``schedule.CostModel``): a group's first case is its
    cheapest (its kernels reach the cache soonest, which frees the rest of the group), the groups with
    the most predicted work compile first, and the rest follow longest first (``schedule.longest_first``),
    so the tail of the matrix is short cases.
    """
    if costs is None:
        seen: set = set()
        first, rest = [], []
        for i, c in enumerate(cases):
            g = compile_group(c)
            (rest if g in seen else first).append((i, c))
            seen.add(g)
        return first + rest
    from .schedule import longest_first

    groups: dict[tuple, list[int]] = {}
    for i in longest_first(costs):
        groups.setdefault(compile_group(cases[i]), []).append(i)
    heads = sorted(groups.values(), key=lambda members: -sum(costs[i] for i in members))
    first = [members[-1] for members in heads]  # the cheapest of each group (longest_first's last)
    taken = set(first)
    rest = [i for i in longest_first(costs) if i not in taken]
    return [(i, cases[i]) for i in first + rest]


def shares_kernels(g: tuple, h: tuple) -> bool:
    """Whether compile groups g and h compile some of the same large kernels: the same body model's
    step, the leg controller's kernels (both legged) or the water solver (both with water)."""
    return g[0] == h[0] or (g[1] and h[1]) or (g[2] and h[2])


class CompileScheduler:
    """Which pending case a free local worker takes next (compile once, not once per worker).

    ``cases`` in :func:`compile_first_order`.  A case whose group is neither warm (a case of it has
    finished: its kernels are in numba's disk cache) nor compiling (its first case is running) starts
    that group's compile.  Preference, first match wins:

    1. a cold group sharing no large kernels (:func:`shares_kernels`) with a group compiling now: its
       compile runs in parallel with the others without doing any of their work again;
    2. a case of a warm group;
    3. a cold group that shares kernels with a compiling group (better than an idle worker);
    4. nothing: the worker waits for a group to turn warm.

    A worker that would wait compiles a kernel ahead instead (:meth:`next_kernel_job`): ``plans`` (group name
    -> ``compile_plan.KernelTask`` list, ``compile_plan.load_plans``) list the kernels each group's cases
    compile, with the exact signatures, callees before callers; idle workers compile them from the end the
    group's own compile reaches last, so a group's kernels compile on several workers at once and its case
    finds most of them in the cache.
    """

    def __init__(self, cases: Sequence[Case], costs: Sequence[float] | None = None,
                 plans: dict | None = None):
        self.pending = deque(compile_first_order(cases, costs))
        self.groups = [compile_group(c) for c in cases]
        self.compiling: set = set()  # groups whose first case is running: its kernels are not in the cache yet
        self.warm: set = set()  # groups with a finished case
        names = {g: group_name(g) for g in set(self.groups)}
        # each group's kernels to compile ahead, in the order idle workers take them; a kernel several groups
        # need is handed out once (``kernels_out``)
        self.kernel_queue = {g: deque((plans or {}).get(n, ())) for g, n in names.items()}
        self.kernels_out: set[str] = set()
        self.kernel_jobs = 0  # kernel jobs handed out (what the run's stats report)

    def next_kernel_job(self) -> object | None:
        """A kernel (``compile_plan.KernelTask``) of a group not warm yet for an idle worker to compile ahead, or
        None.  From the group with the most recorded compile time still to hand out: the largest compile
        is the one that keeps its cases (and the matrix's end) waiting longest."""
        best, left = None, 0.0
        for g, q in self.kernel_queue.items():
            if g in self.warm:
                continue
            while q and q[0].key in self.kernels_out:
                q.popleft()
            todo = sum(t.self_s for t in q if t.key not in self.kernels_out)
            if q and todo > left:
                best, left = g, todo
        if best is None:
            return None
        task = self.kernel_queue[best].popleft()
        self.kernels_out.add(task.key)
        self.kernel_jobs += 1
        return task

    def kernel_jobs_left(self) -> bool:
        """Whether :meth:`next_kernel_job` would hand out a kernel now."""
        return any(g not in self.warm and any(t.key not in self.kernels_out for t in q)
                   for g, q in self.kernel_queue.items())

    def cold_groups_pending(self) -> bool:
        """Whether a pending case would start a group's compile (its group is neither warm nor compiling)."""
        return any(self.groups[i] not in self.warm and self.groups[i] not in self.compiling for i, _ in self.pending)

    def next_job(self) -> tuple[int, Case] | None:
        """The (index, case) to hand out now, removed from the pending cases; None: wait."""
        best, rank = None, 4
        for k, (i, _c) in enumerate(self.pending):
            g = self.groups[i]
            if g in self.warm:
                r = 2
            elif g in self.compiling:
                continue
            elif any(shares_kernels(g, h) for h in self.compiling):
                r = 3
            else:
                r = 1
            if r < rank:
                best, rank = k, r
                if r == 1:
                    break
        if best is None:
            return None
        job = self.pending[best]
        del self.pending[best]
        g = self.groups[job[0]]
        if g not in self.warm:
            self.compiling.add(g)
        return job

    def next_compile_job(self) -> tuple[int, Case] | None:
        """A case whose group is neither warm nor compiling, left pending, its group now compiling: the extra
        worker compiles its kernels without running it (:func:`compile_case`), then :meth:`compiled`.
        A group sharing no large kernels with a compiling one first (as :meth:`next_job`)."""
        best, rank = None, 3
        for i, c in self.pending:
            g = self.groups[i]
            if g in self.warm or g in self.compiling:
                continue
            r = 2 if any(shares_kernels(g, h) for h in self.compiling) else 1
            if r < rank:
                best, rank = (i, c), r
                if r == 1:
                    break
        if best is not None:
            self.compiling.add(self.groups[best[0]])
        return best

    def compiled(self, index: int, ok: bool = True) -> None:
        """The compile-only job of case ``index`` ended: its group is warm (``ok``) or cold again."""
        g = self.groups[index]
        self.compiling.discard(g)
        if ok:
            self.warm.add(g)

    def warmed(self, index: int) -> None:
        """Case ``index`` has compiled (or loaded) its kernels and run its first chunk: its group is warm,
        the rest of the group may start while it runs on."""
        g = self.groups[index]
        self.warm.add(g)
        self.compiling.discard(g)

    def finished(self, index: int) -> None:
        """Case ``index`` ended (any status): its group's kernels are compiled and cached."""
        g = self.groups[index]
        self.warm.add(g)
        self.compiling.discard(g)


def _run_local(cases: Sequence[Case], workers: int, timeout: float | None, emit: Callable[[RunResult], None],
               costs: Sequence[float] | None = None, plans: dict | None = None, stats: dict | None = None) -> int:
    """Run ``cases`` on ``workers`` local worker processes; return the number of workers that ran cases.
    ``costs``: predicted wall times [s] in the order of ``cases`` (longest first, ``compile_first_order``).
    ``plans``: the kernels idle workers compile ahead (``CompileScheduler``; default ``compile_plan.load_plans``).
    ``stats``: gets ``kernel_jobs``, the number of kernels compiled (or loaded) ahead."""
    ctx = worker_context()
    sched = CompileScheduler(cases, costs, load_plans() if plans is None else plans)
    pending = sched.pending
    next_job = sched.next_job

    n = max(1, min(workers, len(cases)))
    # One extra worker while groups are still to compile: a worker waiting for a kernel another one is compiling
    # (compile_lock) leaves its core idle, which the extra worker's compile fills.  It only compiles (a group's
    # kernels, without running a case: no case's timing shares a core with it beyond the two workers') and stops
    # when no group is left to compile.
    extra = 1 if n >= 2 and len(set(sched.groups)) > n else 0
    slots = [_start_slot(ctx) for _ in range(n + extra)]
    ready: list[RunResult] = []  # results received, to store once their workers have their next case
    try:
        # kernel jobs alone do not keep the matrix going: once every case is done they are stopped (finally)
        while pending or ready or any(s.job and s.kernel is None for s in slots):
            for k, s in enumerate(slots):
                if k >= n and s.job is None and not s.retired and not sched.cold_groups_pending():
                    s.stop()  # the extra compile worker's work is done
                    s.retired = True
                if s.job is None and not s.retired and (pending or (k < n and sched.kernel_jobs_left())):
                    s.compile_only = k >= n
                    s.job = (sched.next_compile_job() if s.compile_only else next_job()) if pending else None
                    mode = s.compile_only
                    # nothing to run now: a worker (not the extra one, which would add a process beyond the cores)
                    # compiles a kernel a group will need (compile_plan)
                    if s.job is None and k < n:
                        s.kernel = sched.next_kernel_job()
                        if s.kernel is not None:
                            s.job, mode = (-1, [(s.kernel.kernel, s.kernel.args)]), KERNELS
                    if s.job is None:
                        continue
                    s.started, s.running = time.monotonic(), False
                    s.conn.send((*s.job, mode))
            # stored only now: a result's SQLite commit and recording (tens of ms, most of it waiting for the
            # disk) no longer keep the worker that sent it waiting for its next case
            while ready:
                emit(ready.pop(0))
            busy = [s for s in slots if s.job]
            if not busy:
                continue
            wait_s = None
            if timeout is not None:
                # at most an hour per wait (the loop waits again): a timeout of 3e6 s or 1e300 s is a deadline
                # select/poll cannot take in one call (OverflowError above about 2.1e6 s)
                wait_s = min(MAX_WAIT_S, max(0.0, min(s.deadline(timeout) for s in busy) - time.monotonic()))
            mp_wait([s.conn for s in busy] + [s.proc.sentinel for s in busy], timeout=wait_s)
            for i, s in enumerate(slots):
                if s.job is None:
                    continue
                _, case = s.job
                result = None
                while result is None and s.conn.poll():
                    try:
                        kind, payload = s.conn.recv()
                    except (EOFError, OSError):
                        break
                    if kind == "started":  # the clock starts when the worker starts the case
                        s.started, s.running = time.monotonic(), True
                    elif kind == "warm":  # its kernels are in the cache: the rest of its group may start
                        sched.warmed(payload)
                    else:  # "done": the slim result; "compiled": the index of a compile-only job
                        result = payload
                if s.kernel is not None:  # a kernel compiled ahead: nothing to record; one that died or outran the
                    # timeout is the case's to compile (the lock dies with the process)
                    if result is None and (not s.proc.is_alive() or (
                            timeout is not None and time.monotonic() >= s.deadline(timeout))):
                        s.stop(kill=True)
                        slots[i] = _start_slot(ctx)
                    elif result is not None:
                        s.job, s.kernel = None, None
                    continue
                if s.compile_only:  # the extra compile worker: no result to record; a compile that died or
                    # outran the timeout leaves its group cold, for a worker to compile with its case
                    if result is None and (not s.proc.is_alive() or (
                            timeout is not None and time.monotonic() >= s.deadline(timeout))):
                        s.stop(kill=True)
                        s.retired = True
                        sched.compiled(s.job[0], ok=False)
                        s.job = None
                    elif result is not None:
                        sched.compiled(s.job[0])
                        s.job = None
                    continue
                elapsed = time.monotonic() - s.started
                if result is None and not s.proc.is_alive():
                    s.proc.join()
                    result = died_result(case, s.proc.exitcode, elapsed)
                    s.stop(kill=True)
                    slots[i] = _start_slot(ctx)
                elif result is None and timeout is not None and time.monotonic() >= s.deadline(timeout):
                    result = timeout_result(case, timeout, elapsed)
                    s.stop(kill=True)
                    slots[i] = _start_slot(ctx)
                if result is not None:
                    sched.finished(s.job[0])
                    slots[i].job = None
                    ready.append(result)
    finally:
        if stats is not None:
            stats["kernel_jobs"] = sched.kernel_jobs
        # results received but not stored yet (an interrupt or error between receiving and storing them):
        # stored now, so nothing computed is lost
        while ready:
            emit(ready.pop(0))
        # every idle worker is told to stop before any is waited for: their exits (about a second each, most
        # of it the interpreter tearing down) overlap instead of adding up
        live = [s for s in slots if not s.retired]
        for s in live:
            if s.job is None:
                s.request_stop()
        for s in live:
            s.stop(kill=s.job is not None)
    return n


# --------------------------------------------------------------------------- dask

def _run_dask(cases: Sequence[Case], workers: int, scheduler: str | None, timeout: float | None,
              emit: Callable[[RunResult], None], processes: bool = True,
              costs: Sequence[float] | None = None) -> int:
    """Run ``cases`` as Dask tasks; return the number of Dask workers (threads) that ran them.
    ``costs``: predicted wall times [s]; a longer case gets a higher task priority, so it starts first."""
    from dask.distributed import wait  # optional dependency: imported only here

    client, cluster = dask_client(scheduler, workers, processes)
    try:
        order = list(range(len(cases)))
        if costs is not None:
            from .schedule import longest_first
            order = longest_first(costs)
        # submitted longest first, with priorities to match: Dask runs higher priorities first
        futures = {client.submit(run_case_slim, cases[i], pure=False, priority=len(order) - rank): cases[i]
                   for rank, i in enumerate(order)}
        n_workers = sum(w.get("nthreads", 1) for w in client.scheduler_info().get("workers", {}).values()) or workers
        started: dict[str, float] = {}
        remaining = set(futures)
        while remaining:
            done, _ = wait(list(remaining), timeout=0.5 if timeout is not None else None, return_when="FIRST_COMPLETED")
            for fut in done:
                remaining.discard(fut)
                case = futures[fut]
                if fut.status == "finished":
                    emit(fut.result())
                else:  # the task failed outside run_case (a worker died, a pickling error)
                    exc = fut.exception()
                    emit(RunResult(case, "error", {}, _nan_timings(float("nan")),
                                   f"dask task {fut.status}: {type(exc).__name__}: {exc}"))
            if timeout is None or not remaining:
                continue
            now = time.monotonic()
            processing = {key: addr for addr, keys in client.processing().items() for key in keys}
            for fut in list(remaining):
                if fut.key in processing:
                    started.setdefault(fut.key, now)
                if fut.key in started and now - started[fut.key] >= timeout:
                    remaining.discard(fut)
                    fut.cancel()
                    emit(timeout_result(futures[fut], timeout, now - started[fut.key]))
                    if cluster is not None and processes:
                        try:
                            client.restart_workers([processing[fut.key]])
                        except Exception:  # best effort: the case is recorded either way
                            pass
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return n_workers


def worker_process_settings() -> None:
    """What every matrix worker process sets before its first case: the compile lock (a kernel another
    worker process is compiling is waited for and loaded from numba's cache, not compiled twice) and
    the garbage collector's thresholds (``WORKER_GC_THRESHOLDS``).  Idempotent."""
    compile_lock.install()
    gc.set_threshold(*WORKER_GC_THRESHOLDS)


def worker_process_state() -> tuple[bool, tuple[int, int, int]]:
    """(compile lock installed, garbage-collector thresholds) of the calling process."""
    from numba.core import dispatcher as nd

    return bool(getattr(nd.Dispatcher.compile, "_bench_compile_lock", False)), gc.get_threshold()


def _worker_setup_plugin():
    """A Dask ``WorkerPlugin`` that runs :func:`worker_process_settings` in every worker, also in
    workers that join or are restarted later (a timed-out case's worker is restarted)."""
    from distributed.diagnostics.plugin import WorkerPlugin

    class WorkerProcessSettings(WorkerPlugin):
        name = "bench-myriapoda-worker-process-settings"

        def setup(self, worker) -> None:
            worker_process_settings()

    return WorkerProcessSettings()


def dask_client(scheduler: str | None, workers: int, processes: bool = True):
    """(client, local cluster or None): a ``Client`` of the cluster at ``scheduler``, or of a new
    ``LocalCluster`` of ``workers`` single-threaded workers (threads of this process when not
    ``processes``).

    Worker processes get :func:`worker_process_settings`, as the local executor's workers do: on a
    cold start the workers of one machine share numba's cache directory, and without the compile
    lock two of them compile the same shared kernel side by side.  Threads of this process are
    left alone: numba compiles one kernel at a time per process anyway, and the settings would
    change the calling process.
    """
    from dask.distributed import Client, LocalCluster

    cluster = None
    if scheduler:
        client = Client(scheduler, timeout=DASK_CONNECT_TIMEOUT_S)
    else:
        cluster = LocalCluster(n_workers=max(1, workers), threads_per_worker=1, processes=processes,
                               dashboard_address=None)
        client = Client(cluster)
    if scheduler or processes:
        try:
            client.register_plugin(_worker_setup_plugin())
        except Exception:
            client.close()
            if cluster is not None:
                cluster.close()
            raise
    return client, cluster


DASK_CONNECT_TIMEOUT_S = 10.0
DASK_PROBE_TIMEOUT_S = 60.0


def probe_worker() -> str:
    """What a Dask worker runs before the matrix: import the package and register the body models."""
    from ..core import registry
    registry.load_all()
    return ",".join(sorted(registry.BODIES))


def check_dask_scheduler(address: str, flag: str = "--scheduler", connect_timeout: float | None = None,
                         probe_timeout: float | None = None) -> None:
    """Connect to the scheduler at ``address`` and run :func:`probe_worker` on a worker, each within its timeout.

    ``InputError`` naming ``flag`` when the scheduler cannot be reached, has no worker that runs the probe in
    time (a worker that cannot import this package never runs it), or the probe raises.  Nothing is written.
    """
    import logging

    from dask.distributed import Client
    from dask.distributed import TimeoutError as DaskTimeout

    from ..core.errors import InputError

    connect_timeout = DASK_CONNECT_TIMEOUT_S if connect_timeout is None else connect_timeout
    probe_timeout = DASK_PROBE_TIMEOUT_S if probe_timeout is None else probe_timeout
    log = logging.getLogger("distributed")
    level = log.level
    log.setLevel(logging.CRITICAL)  # the one-line message below says it all
    try:
        client = Client(address, timeout=connect_timeout)
    except (OSError, TimeoutError, DaskTimeout, ValueError, TypeError) as exc:
        raise InputError(flag, None, f"cannot reach a dask scheduler at {address!r} within {connect_timeout:g} s "
                                     f"({type(exc).__name__}: {exc})") from None
    finally:
        log.setLevel(level)
    try:
        fut = client.submit(probe_worker, pure=False)
        try:
            fut.result(timeout=probe_timeout)
        except (TimeoutError, DaskTimeout):
            n = len(client.scheduler_info().get("workers", {}))
            raise InputError(flag, None, f"no dask worker at {address} ran a test task within {probe_timeout:g} s "
                                         f"({n} worker(s) connected); the workers must be able to import "
                                         "bench_myriapoda") from None
        except Exception as exc:  # the probe raised on the worker (ImportError, a missing dependency)
            raise InputError(flag, None, f"the dask workers at {address} cannot run cases: "
                                         f"{type(exc).__name__}: {exc}") from None
    finally:
        client.close()


# --------------------------------------------------------------------------- entry point

def run_matrix(cases: Sequence[Case], executor: str = "local", workers: int | None = None, scheduler: str | None = None,
               timeout_per_case: float | None = None, store_path: Path | str = "results.sqlite",
               on_result: Callable[[RunResult, int, int], None] | None = None, *, matrix: str = "matrix",
               resume: bool = False, dask_processes: bool = True,
               series_dir: Path | str | None = None, retry_failed: bool = False,
               schedule: str = "cost", history_stores: Sequence[Path | str] = (),
               stats: dict | None = None) -> list[RunResult]:
    """Run ``cases`` and record each result in ``store_path`` as it arrives.

    With ``series_dir``, each case's compact recording is saved as ``series_dir/CASE_HASH.npz``
    (atomically, before its store row, so a stored case always has its recording).

    Returns this call's results in the order they finished.  ``on_result(result,
    done, total)`` is called after each result is stored.  With ``resume``,
    cases already stored for ``matrix`` are skipped (``total`` counts only the
    cases left); with ``retry_failed`` too, those stored as ``error`` or ``timeout``
    run again.  Duplicate cases (equal hashes) run once.

    ``schedule``: ``"cost"`` predicts each case's wall time (``schedule.CostModel`` from the runs in
    ``store_path`` and ``history_stores`` and their throughput-suite figures) and starts the longest
    cases first; ``"file"`` keeps the matrix's order.  Results do not depend on it.
    ``stats``: a dict filled with what the run gave: ``workers``, ``matrix_wall_s`` (from the first case
    handed out to the last result stored), ``predicted_s`` (case hash -> predicted wall [s]),
    ``cost_sources`` (source -> cases) and ``emit_s`` (parent time spent storing results [s]).
    """
    if schedule not in SCHEDULES:
        raise ValueError(f"schedule must be one of {SCHEDULES}, got {schedule!r}")
    if executor not in EXECUTORS:
        raise ValueError(f"executor must be one of {EXECUTORS}, got {executor!r}")
    skip = done_hashes(store_path, matrix, retry_failed) if resume else set()
    todo, seen = [], set(skip)
    for c in cases:
        h = c.case_hash()
        if h not in seen:
            seen.add(h)
            todo.append(c)
    results: list[RunResult] = []
    if not todo:
        return results
    workers = workers or os.cpu_count() or 1

    costs = None
    stats = {} if stats is None else stats
    if schedule == "cost":
        from .schedule import cost_model_for

        predictions = cost_model_for([store_path, *history_stores]).predict_all(todo)
        costs = [p.seconds for p in predictions]
        stats["predicted_s"] = {c.case_hash(): p.seconds for c, p in zip(todo, predictions)}
        sources: dict[str, int] = {}
        for p in predictions:
            sources[p.source] = sources.get(p.source, 0) + 1
        stats["cost_sources"] = sources
    emit_s = [0.0]

    def emit(result: RunResult) -> None:
        e0 = time.perf_counter()
        recording = result.extra.pop("recording", None)
        series = None if series_dir is None else Path(series_dir) / f"{result.case.case_hash()}.npz"
        try:
            if series is not None and recording is not None:
                save_recording(series, recording)
            record_run(store_path, result, command="matrix", matrix=matrix)
        except STORE_WRITE_ERRORS as exc:  # keep the result, leave no recording without its row, stop the matrix
            if series is not None and recording is not None:
                series.unlink(missing_ok=True)
            raise UnstoredError(store_path, f"matrix case {result.case.case_hash()}", exc,
                                keep_unstored(store_path, "matrix case", result.to_json_dict(), exc)) from exc
        emit_s[0] += time.perf_counter() - e0
        results.append(result)
        if on_result is not None:
            on_result(result, len(results), len(todo))

    t0 = time.perf_counter()
    try:
        if executor == "local":
            used = _run_local(todo, workers, timeout_per_case, emit, costs, stats=stats)
        else:
            used = _run_dask(todo, workers, scheduler, timeout_per_case, emit, processes=dask_processes, costs=costs)
    finally:
        stats["matrix_wall_s"] = time.perf_counter() - t0
        stats["emit_s"] = emit_s[0]
    stats["workers"] = used
    return results


SCHEDULES = ("cost", "file")


def matrix_rows(store_path: Path | str, matrix: str):
    """This matrix's rows of ``runs`` as a DataFrame, in the order they were stored."""
    return read_matrix_runs(store_path, matrix)
