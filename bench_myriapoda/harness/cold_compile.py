"""Compile plans recorded and a cold matrix simulated: the command line of ``compile_plan``.

``python -m bench_myriapoda.harness.cold_compile --record quick --write`` compiles every compile group of a
matrix in a fresh process with an empty numba cache (``record_groups``), each group's first case as the
executor starts it, records every signature compiled with its compile time (``compile_plan.recording``) and
writes the plans the executor uses (``compile_plan.write_plans``: the data file ``jit/compile_plans.json``, shipped
with the package).
``--simulate DIR`` predicts a cold matrix's wall for 1 to 16 workers with and without kernels compiled
ahead (:func:`simulate_cold`, the local executor's ``CompileScheduler`` replayed on the recorded compile
times and the case times of a run in DIR).  Apart from ``compile_plan`` because it needs the executor,
which needs ``compile_plan``.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping, Sequence

from ..jit.compile_plan import (PLANS_FILE, CompileEvent, _encode_args, compact, critical_chain, group_name,
                                group_tasks, kernel_graph, read_plans, recording, shipped_plans, write_plans)

def record_case(case) -> list[CompileEvent]:
    """Compile ``case``'s kernels in this process (``executors.compile_case``) and return what compiled."""
    from .executors import compile_case

    with recording() as events:
        compile_case(case)
    return events


MODULE = "bench_myriapoda.harness.cold_compile"


def record_groups(cases: Sequence[Any], timeout_s: float = 900.0,
                  groups: Sequence[str] | None = None) -> dict[str, dict]:
    """Each compile group's kernels: the group's first case (its cheapest, as the executor starts it) compiled in
    a fresh process with a fresh numba cache, so every kernel of the group compiles and is timed.  Group name ->
    ``{"case": label, "events": [(kernel, signature, depth, parent, inclusive_s, self_s, cached, can_cache)],
    "args": the events' argument types, pickled}``.  ``groups``: only these group names (default: all)."""
    import os
    import pickle
    import subprocess
    import sys
    import tempfile

    from .executors import compile_group

    firsts: dict[tuple, Any] = {}
    for c in sorted(cases, key=lambda c: c.steps):
        if groups is None or group_name(compile_group(c)) in groups:
            firsts.setdefault(compile_group(c), c)
    out = {}
    for group, case in firsts.items():
        with tempfile.TemporaryDirectory(prefix="bench-compile-plan-") as tmp:
            cp, ep = os.path.join(tmp, "case.pkl"), os.path.join(tmp, "events.pkl")
            with open(cp, "wb") as fh:
                pickle.dump(case, fh)
            env = dict(os.environ, NUMBA_CACHE_DIR=os.path.join(tmp, "numba-cache"))
            subprocess.run([sys.executable, "-m", MODULE, "--record-one", cp, ep], env=env, check=True,
                           timeout=timeout_s)
            with open(ep, "rb") as fh:
                rows = pickle.load(fh)  # (kernel, signature, args, inclusive, self, cached, depth, parent, can_cache)
        label = f"{case.creature.name}/{case.body.name}/{case.scenario.name}"
        out[group_name(group)] = compact({
            "case": label,
            "events": [(r[0], r[1], r[6], r[7], round(r[3], 3), round(r[4], 3), r[5], r[8]) for r in rows],
            "args": _encode_args([r[2] for r in rows])})
        print(f"{group_name(group)}: {label}: {sum(r[3] for r in rows if r[6] == 0):.1f} s, "
              f"{len(rows)} signatures", file=sys.stderr, flush=True)
    return out


def _record_one(case_path: str, out_path: str) -> None:
    """In a fresh process (``--record-one``): compile the pickled case's kernels, write the events (pickle)."""
    import pickle

    from ..core import registry
    from .executors import worker_process_settings

    registry.load_all()
    worker_process_settings()
    with open(case_path, "rb") as fh:
        case = pickle.load(fh)
    events = record_case(case)
    with open(out_path, "wb") as fh:  # plain tuples: this module runs as __main__ here
        pickle.dump([(e.kernel, e.signature(), _picklable(e.args), e.inclusive_s, e.self_s, e.cached, e.depth,
                      e.parent, e.can_cache) for e in events], fh)


def _picklable(args: tuple) -> tuple | None:
    """``args``, or None where a type cannot be pickled (a function passed as an argument: its type is a class
    numba makes on the fly); such a signature is left to the case (:func:`group_tasks`)."""
    import pickle

    try:
        pickle.loads(pickle.dumps(args, protocol=4))
    except Exception:  # noqa: BLE001 -- pickling can fail in many ways; the plan just leaves the kernel out
        return None
    return args


def _simulate_main(args) -> int:
    import json
    import math
    import sys

    from ..core import registry
    from .matrix import expand_matrix, locate_matrix
    from .store import read_matrix_case_walls

    store = Path(args.simulate) / "results.sqlite"
    if not store.is_file():
        print(f"bench-myriapoda: {args.simulate}: no results.sqlite; give a matrix output directory", file=sys.stderr)
        return 2
    registry.load_all()
    walls = {h: (w, c) for h, w, c in read_matrix_case_walls(store)}
    cases, run = [], []
    predicted: dict[str, int] = {}
    model = None
    for mc in expand_matrix(locate_matrix(args.matrix)).cases:
        h = mc.case.case_hash()
        if h in walls and walls[h][0] is not None and math.isfinite(walls[h][0]):
            w, c = walls[h]
            cases.append(mc.case)
            run.append(max(0.0, w - (c if c is not None and math.isfinite(c) else 0.0)))
        elif args.predict_missing:  # the cost model on DIR's runs: same kind, or another size of it scaled
            if model is None:
                from .schedule import cost_model_for

                model = cost_model_for([store])
            p = model.predict(mc.case)
            cases.append(mc.case)
            run.append(p.seconds)
            predicted[p.source] = predicted.get(p.source, 0) + 1
    plans = read_plans(Path(args.plans)).plans if args.plans else shipped_plans().plans
    rows = []
    for n in args.workers:
        kw = dict(costs=run, worker_start_s=args.worker_start, per_case_s=args.per_case)
        rows.append({"workers": n, "before_s": simulate_cold(cases, run, n, plans, ahead=False, **kw),
                     "after_s": simulate_cold(cases, run, n, plans, ahead=True, **kw),
                     "warm_s": _warm(run, n, args)})
    chains = critical_chain(plans)
    if args.json:
        print(json.dumps({"cases": len(cases), "predicted": predicted, "run_sum_s": sum(run), "rows": rows,
                          "groups": {k: {"serial_s": a, "chain_s": b} for k, (a, b) in chains.items()}}, indent=1))
        return 0
    print(f"{args.matrix}: {len(cases)} cases, {sum(run):.1f} s of cases with warm kernels; "
          f"compile plans of {len(plans)} groups"
          + (f"; predicted (no stored wall): {predicted}" if predicted else ""))
    for name, (serial, chain) in sorted(chains.items(), key=lambda kv: -kv[1][0]):
        print(f"  {name:24s} compile {serial:6.1f} s serial, {chain:6.1f} s along its longest chain of callees")
    print("workers  cold before  cold after  warm")
    for r in rows:
        print(f"{r['workers']:>7}  {r['before_s']:9.1f} s  {r['after_s']:8.1f} s  {r['warm_s']:5.1f} s")
    return 0


def _warm(run: Sequence[float], workers: int, args) -> float:
    from .schedule import simulate

    return simulate(run, workers, args.worker_start, args.per_case).wall_s


def main(argv: Sequence[str] | None = None) -> int:
    import argparse
    import sys

    ap = argparse.ArgumentParser(prog=f"python -m {MODULE}", description=__doc__.splitlines()[0])
    ap.add_argument("--record-one", nargs=2, metavar=("CASE_PICKLE", "OUT_PICKLE"), help=argparse.SUPPRESS)
    ap.add_argument("--record", nargs="+", metavar="MATRIX",
                    help="record every compile group of these matrices (one fresh process and numba cache each)")
    ap.add_argument("--write", action="store_true", help=f"write the recorded plans to {PLANS_FILE.name} (package data "
                    "beside bench_myriapoda/jit/compile_plan.py)")
    ap.add_argument("--groups", nargs="+", metavar="GROUP", help="with --record: only these compile groups "
                    "(massspring-legged-dry, ...); with --write the file's other groups are kept")
    ap.add_argument("--out", metavar="FILE", help=f"with --write: write this file instead of {PLANS_FILE.name} "
                    "(--simulate --plans FILE reads it)")
    ap.add_argument("--plans", metavar="FILE", help="with --simulate: the plans of this file (default: the "
                    "shipped ones)")
    ap.add_argument("--note", default="", help="how and where the plans were recorded (the file's \"note\")")
    ap.add_argument("--simulate", metavar="DIR", help="a matrix output directory (results.sqlite) whose case wall "
                    "times minus compile are the cases' warm costs: the cold matrix's wall predicted with and "
                    "without kernels compiled ahead, from the recorded plans")
    ap.add_argument("--matrix", default="quick", help="the matrix DIR ran (with --simulate)")
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2, 4, 8, 16])
    ap.add_argument("--worker-start", type=float, default=0.0, metavar="S", help="worker start [s] (--simulate)")
    ap.add_argument("--per-case", type=float, default=0.0, metavar="S", help="fixed cost per case [s] (--simulate)")
    ap.add_argument("--json", action="store_true", help="--simulate: print JSON")
    ap.add_argument("--predict-missing", action="store_true", help="--simulate: a case DIR has no wall for gets "
                    "the cost model's prediction from DIR's runs (harness/schedule.py: the same kind of case, or "
                    "another size of it scaled; the sources are printed)")
    args = ap.parse_args(argv)
    if args.simulate:
        return _simulate_main(args)
    if args.record_one:
        _record_one(*args.record_one)
        return 0
    if args.record:
        from ..core import registry
        from .matrix import expand_matrix, locate_matrix

        registry.load_all()
        cases = [mc.case for m in args.record for mc in expand_matrix(locate_matrix(m)).cases]
        plans = record_groups(cases, groups=args.groups)
        for name, p in plans.items():
            print(f"== {name} ({p['case']})")
            for kernel, sig, depth, _parent, incl, self_s, cached, _cc in p["events"]:
                if incl >= 0.3 or depth == 0:
                    print(f"{incl:7.2f} {self_s:7.2f} {'cached' if cached else '':6s} {'  ' * depth}{kernel}")
        if args.write:
            out = Path(args.out) if args.out else PLANS_FILE
            # --groups: the other groups' plans stay as they were recorded
            kept = read_plans(out).plans if args.groups and out.is_file() else {}
            write_plans({**kept, **plans}, args.note, out)
        return 0
    ap.print_usage(sys.stderr)
    return 2


def simulate_cold(cases: Sequence[Any], run_s: Sequence[float], workers: int, plans: Mapping[str, Mapping[str, Any]],
                  ahead: bool = True, costs: Sequence[float] | None = None, worker_start_s: float = 0.0,
                  per_case_s: float = 0.0, cores: int | None = None) -> float:
    """Predicted wall time [s] of a matrix on a cold numba cache with the local executor's policy.

    ``cases``: the matrix's cases; ``run_s``: each one's wall time with warm kernels [s]; ``plans``: recorded
    compile plans (group name -> ``PLANS`` entry), whose per-kernel self times [s] and call trees are the
    compile work.  The executor's ``CompileScheduler`` decides which worker takes what: a group's first case
    compiles the group's kernels depth first (a kernel another worker is compiling is waited for, as the
    compile lock makes it), then runs; the rest of the group waits until then; the extra compile worker
    (``_run_local``) compiles cold groups; with ``ahead``, idle workers compile the planned kernels ahead
    (``next_kernel_job``), without it they wait (the executor before compile plans).  ``cores`` (default
    ``workers``): processes beyond it share the cores equally.
    """
    from .executors import CompileScheduler

    nodes, roots = kernel_graph(plans)
    tasks = {n: group_tasks(p) for n, p in plans.items()} if ahead else {}
    sched = CompileScheduler(cases, costs, tasks)
    names = [group_name(g) for g in sched.groups]
    cores = cores or workers
    n = max(1, min(workers, len(cases)))
    extra = 1 if n >= 2 and len(set(sched.groups)) > n else 0
    done: set[str] = set()
    claimed: set[str] = set()

    def compile_tree(sig):
        if sig in done:
            return
        if sig in claimed:
            yield ("wait", sig)
            return
        claimed.add(sig)
        for c in nodes[sig].children:
            yield from compile_tree(c)
        yield ("work", nodes[sig].self_s)
        done.add(sig)
        yield ("done", sig)

    def case_job(i):
        g = sched.groups[i]
        if g not in sched.warm:
            for r in roots.get(names[i], ()):
                yield from compile_tree(r)
            yield ("warm", i)
        yield ("work", run_s[i] + per_case_s)
        yield ("finished", i)

    def compile_job(i):
        for r in roots.get(names[i], ()):
            yield from compile_tree(r)
        yield ("compiled", i)

    slots = [{"gen": None, "left": 0.0, "wait": None, "extra": k >= n, "retired": False} for k in range(n + extra)]
    t, end = worker_start_s, worker_start_s
    running = [0]  # case jobs on workers

    def hand_out() -> bool:
        """Give every free worker a job, as _run_local's loop; whether any got one."""
        given = False
        for s in slots:
            if s["gen"] is not None or s["retired"]:
                continue
            if s["extra"] and not sched.cold_groups_pending():
                s["retired"] = True
                continue
            job = None
            if sched.pending:
                job = sched.next_compile_job() if s["extra"] else sched.next_job()
            if job is not None:
                s["gen"] = compile_job(job[0]) if s["extra"] else case_job(job[0])
                s["case"] = not s["extra"]
                running[0] += 0 if s["extra"] else 1
            else:
                task = None if s["extra"] else sched.next_kernel_job()  # the extra worker only compiles groups
                if task is None:
                    continue
                s["gen"], s["case"] = compile_tree(task.key), False
            s["left"], s["wait"] = 0.0, None
            given = True
        return given

    def progress() -> bool:
        """Run every worker's job until it works, waits or ends; whether anything happened."""
        moved = False
        for s in slots:
            while s["gen"] is not None and s["left"] <= 0 and (s["wait"] is None or s["wait"] in done):
                s["wait"] = None
                moved = True
                try:
                    kind, x = next(s["gen"])
                except StopIteration:
                    s["gen"] = None
                    running[0] -= 1 if s["case"] else 0
                    break
                if kind == "work":
                    s["left"] = x
                elif kind == "wait":
                    s["wait"] = x
                elif kind == "warm":
                    sched.warmed(x)
                elif kind == "finished":
                    sched.finished(x)
                elif kind == "compiled":
                    sched.compiled(x)
        return moved

    while True:
        while hand_out() | progress():
            pass
        if not sched.pending and running[0] == 0:
            return end
        working = [s for s in slots if s["gen"] is not None and s["left"] > 0]
        if not working:
            raise RuntimeError("simulate_cold: no worker can progress (a wait that never ends)")
        rate = min(1.0, cores / len(working))
        dt = min(s["left"] for s in working) / rate
        t += dt
        end = t
        for s in working:
            s["left"] -= dt * rate
            if s["left"] < 1e-12:
                s["left"] = 0.0


if __name__ == "__main__":
    raise SystemExit(main())
