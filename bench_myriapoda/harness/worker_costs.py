"""The fixed costs of the local executor's workers, measured with the workers' own code (issue 31).

A matrix's wall time on ``W`` workers is its cases' own time plus what the harness adds around
them.  This module measures that part through the real worker (``executors._start_slot`` and its
pipe protocol), on ``N`` workers started at once, with a warm JIT cache:

``start_s``       process start (spawn: a fresh interpreter's imports and body-model registry; forkserver:
                  a fork, plus the server's own imports when it was not running yet), until the worker
                  takes its first job (``"started"``);
``kernel_load_s`` the first case's kernels loaded from numba's disk cache (a compile-only job); with the compile
                  plans on (``compile_plan``), a forked worker finds the recorded groups' top-level kernels
                  loaded by the fork server already, and this is what is left;
``preload_s``     what loading those kernels costs once, in the server (timed in this process at the end,
                  ``compile_plan.preload_cached``), with ``preloaded`` (signatures loaded, recorded);
``case_s``        a short case run in a worker: ``"started"`` to ``"done"`` (build, kernels already
                  loaded, run, metrics, compact recording, result over the pipe), and ``overhead_s``,
                  that minus the case's own stepping time (steps / steps_per_s);
``store_s``       the parent writing one result (recording ``.npz`` and store row), as ``run_matrix`` does;
``stop_s``        a stop request until the worker process has exited.

Run ``python -m bench_myriapoda.harness.worker_costs --workers 1 16`` (one JSON line per measurement on stdout;
``--plans both`` measures each with the compile plans off, then on: the fixed costs before and after the
fork server preloads kernels).
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

from ..core import registry
from ..jit import compile_plan
from ..jit.worker_start import worker_context

PROBE_DURATION_S = 0.2  # [s] simulated: a short case, so the harness's part is visible


def probe_case() -> tuple[str, str, str]:
    """(creature, body, scenario) of the probe: the short case with the cheapest kernels to load, as the first
    catalogued body that declares one publishes it (``BodySpec.benchmarks.probe_scene``; issue 42)."""
    registry.load_all()
    for name, spec in registry.BODIES.items():
        if spec.benchmarks.probe_scene is not None:
            creature, scenario = spec.benchmarks.probe_scene
            return creature, name, scenario
    raise RuntimeError("no catalogued body declares a worker-cost probe case (BodySpec.benchmarks.probe_scene)")


def _server_pid():
    from multiprocessing import forkserver

    return getattr(getattr(forkserver, "_forkserver", None), "_forkserver_pid", None)


def _recv(conn):
    kind, payload = conn.recv()
    return kind, payload, time.perf_counter()


def _await(conn, want: str):
    """Messages until one of kind ``want``: (payload, time received); ``"warm"`` messages are skipped."""
    while True:
        kind, payload, t = _recv(conn)
        if kind == want:
            return payload, t


def measure(workers: int, method: str | None = None, plans: bool | None = None) -> dict:
    """Fixed costs [s] of ``workers`` local workers started at once: medians and maxima over the workers.
    ``method``: how they start (``worker_start.START_METHODS``; default: as the executor starts them);
    ``plans``: the compile plans on or off (``compile_plan.ENV_SWITCH``; default: as they are)."""
    import os

    from ..core.config import resolve_case
    from .executors import _start_slot
    from .recorder import save_recording
    from .store import record_run

    probe = probe_case()
    case = resolve_case(*probe, duration=PROBE_DURATION_S)
    if plans is not None:  # a fork server started with the other setting restarts (worker_context)
        os.environ[compile_plan.ENV_SWITCH] = "on" if plans else "off"
    ctx = worker_context(method)
    server_running = ctx.get_start_method() == "forkserver" and _server_pid() is not None
    t0 = time.perf_counter()  # a fork server not running yet starts with the first worker: its imports count
    slots = [_start_slot(ctx) for _ in range(workers)]
    for k, s in enumerate(slots):
        s.conn.send((k, case, True))  # compile-only: load the kernels
    start, load = [], []
    for s in slots:
        _, t_started = _await(s.conn, "started")
        _, t_compiled = _await(s.conn, "compiled")
        start.append(t_started - t0)
        load.append(t_compiled - t_started)
    for k, s in enumerate(slots):
        s.conn.send((k, case, False))
    case_s, overhead, results = [], [], []
    for s in slots:
        _, t_started = _await(s.conn, "started")
        result, t_done = _await(s.conn, "done")
        results.append(result)
        case_s.append(t_done - t_started)
        steps, rate = result.timings["steps"], result.timings["steps_per_s"]
        overhead.append(t_done - t_started - (steps / rate if rate and rate > 0 else 0.0))
    store_s = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, r in enumerate(results):
            e0 = time.perf_counter()
            rec = r.extra.pop("recording", None)
            if rec is not None:
                save_recording(Path(tmp) / f"{k}.npz", rec)
            record_run(Path(tmp) / "store.sqlite", r, command="matrix", matrix="worker-costs")
            store_s.append(time.perf_counter() - e0)
    s0 = time.perf_counter()
    for s in slots:
        s.request_stop()
    stop = []
    for s in slots:
        s.proc.join(timeout=30)
        stop.append(time.perf_counter() - s0)
        s.stop(kill=True)

    def agg(xs):
        return {"median": statistics.median(xs), "max": max(xs)}

    p0 = time.perf_counter()
    preloaded = compile_plan.preload_cached()  # what the fork server did once (0 of 0 with the plans off)
    preload_s = time.perf_counter() - p0
    return {"workers": workers, "start_method": ctx.get_start_method(), "server_was_running": server_running,
            "plans": compile_plan.plans_enabled(), "start_s": agg(start), "kernel_load_s": agg(load),
            "case_s": agg(case_s), "overhead_s": agg(overhead), "store_s": agg(store_s), "stop_s": agg(stop),
            "preload_s": preload_s, "preloaded": list(preloaded),
            "probe_case": "/".join(probe) + f" {PROBE_DURATION_S} s, {case.steps} steps"}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, nargs="+", default=[1], help="worker counts to measure, each in turn")
    ap.add_argument("--start", choices=("forkserver", "spawn", "both"), default="both",
                    help="how the workers start (both: spawn, then forkserver, for each count)")
    ap.add_argument("--plans", choices=("on", "off", "both"), default="on",
                    help="compile plans (kernels preloaded by the fork server): on, off, or off then on")
    args = ap.parse_args(argv)
    for n in args.workers:
        if not 1 <= n <= 256:
            print(f"bench-myriapoda: --workers: {n} is out of range; must be 1 to 256", file=sys.stderr)
            return 2
    from ..core import registry
    registry.load_all()
    methods = ("spawn", "forkserver") if args.start == "both" else (args.start,)
    plan_settings = (False, True) if args.plans == "both" else (args.plans == "on",)
    for n in args.workers:
        for m in methods:  # one JSON line per measurement, written at once: a run cut short keeps what it measured
            for p in plan_settings:
                print(json.dumps(measure(n, m, p)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
