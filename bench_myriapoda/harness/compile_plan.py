"""Which numba kernels a case compiles, with what signatures and for how long; idle workers compile them ahead.

numba compiles a kernel's callees as kernels of their own: typing a call to another ``@njit``
function compiles that function for the argument types first (``Dispatcher.compile``), and with
``cache=True`` each one is looked up in, loaded from and saved to the on-disk cache separately.  A
caller whose callees are already cached therefore compiles only its own body.  On a cold cache the
first case of a compile group (``executors.compile_group``) compiles its whole tree of kernels
serially -- for the legged walk's chunk kernel the leg controller's step and the body's step, each
tens of seconds -- while other workers wait for the group's kernels.

:func:`recording` wraps ``Dispatcher.compile`` (over the compile lock, ``compile_lock``) and keeps
one :class:`CompileEvent` per signature compiled or loaded: the kernel, the exact argument types,
the wall time with its callees (``inclusive_s``) and without (``self_s``), whether it came from the
cache.  ``python -m bench_myriapoda.harness.compile_plan --record quick --write`` records every
compile group of a matrix, each in a fresh process on an empty cache, into ``compile_plans_data``
(the signatures pickled: they are numba types).  :func:`load_plans` turns them into
:class:`KernelTask` lists, which the local executor hands to workers that would otherwise wait
(``executors.CompileScheduler.next_kernel_job``): they compile a group's kernels with the case's
exact signatures, from the end of the tree the case reaches last, so the case finds them in the
cache.  The compile lock keeps each kernel compiled once per machine.  :func:`preload_cached` loads
the recorded top-level kernels that are cached into the workers' fork server (``worker_preload``).
:func:`simulate_cold` predicts a cold matrix's wall with and without kernels compiled ahead
(``--simulate DIR``).  ``BENCH_MYRIAPODA_COMPILE_PLAN=off`` turns all of it off.
"""
from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator, Mapping, Sequence


@dataclass
class CompileEvent:
    """One ``Dispatcher.compile`` call that compiled or loaded a signature.

    ``kernel``: ``module.qualname``; ``args``: the numba argument types (a tuple, picklable);
    ``inclusive_s`` [s]: the call's wall time, its callees' compiles included; ``self_s`` [s]: without
    them; ``cached``: loaded from numba's disk cache; ``depth``: 0 for a kernel called from Python,
    1 for its callees, ...; ``parent``: the index of the caller's event (None at depth 0).
    """

    kernel: str
    args: tuple
    inclusive_s: float = 0.0
    self_s: float = 0.0
    cached: bool = False
    depth: int = 0
    parent: int | None = None
    can_cache: bool = True  # the kernel has ``cache=True`` (a callee without it is compiled into each caller)
    children: list[int] = field(default_factory=list)

    def signature(self) -> str:
        return f"{self.kernel}({', '.join(str(a) for a in self.args)})"


_events: list[CompileEvent] | None = None  # the recording in progress (None: not recording)
_stack: list[int] = []


def _kernel_name(dispatcher) -> str:
    f = dispatcher.py_func
    return f"{f.__module__}.{f.__qualname__}"


def _install() -> None:
    """Wrap ``Dispatcher.compile`` once per process with the recorder (a no-op while not recording)."""
    from numba.core import dispatcher as nd, sigutils
    from numba.core.caching import NullCache

    if getattr(nd.Dispatcher.compile, "_bench_compile_record", False):
        return
    inner = nd.Dispatcher.compile

    def compile(self, sig):
        if _events is None:
            return inner(self, sig)
        args, _ = sigutils.normalize_signature(sig)
        args = tuple(args)
        if args in self.overloads:  # already in this process: nothing compiled or loaded
            return inner(self, sig)
        ev = CompileEvent(_kernel_name(self), args, depth=len(_stack), parent=_stack[-1] if _stack else None,
                          can_cache=not isinstance(self._cache, NullCache))
        _events.append(ev)
        k = len(_events) - 1
        if ev.parent is not None:
            _events[ev.parent].children.append(k)
        hits = sum(self._cache_hits.values())
        _stack.append(k)
        t0 = time.perf_counter()
        try:
            return inner(self, sig)
        finally:
            ev.inclusive_s = time.perf_counter() - t0
            _stack.pop()
            ev.cached = sum(self._cache_hits.values()) > hits
            ev.self_s = ev.inclusive_s - sum(_events[c].inclusive_s for c in ev.children)

    compile._bench_compile_record = True
    compile._bench_compile_lock = getattr(inner, "_bench_compile_lock", False)  # the lock stays visible
    nd.Dispatcher.compile = compile


@contextlib.contextmanager
def recording() -> Iterator[list[CompileEvent]]:
    """Record every signature compiled or loaded inside the block into the list it yields (this process)."""
    global _events
    _install()
    if _events is not None:
        raise RuntimeError("compile_plan.recording does not nest")
    _events, out = [], []
    try:
        yield out
    finally:
        out.extend(_events)
        _events = None
        _stack.clear()


def dispatcher_of(kernel: str):
    """The numba dispatcher ``module.qualname`` (imported)."""
    import importlib

    mod, _, name = kernel.rpartition(".")
    obj: Any = importlib.import_module(mod)
    return getattr(obj, name)


def compile_kernels(signatures: list[tuple[str, tuple]]) -> list[float]:
    """Compile (or load) each (kernel, argument types) in this process; the wall time of each [s].

    A signature another process is compiling right now is waited for and loaded (``compile_lock``)."""
    out = []
    for kernel, args in signatures:
        t0 = time.perf_counter()
        dispatcher_of(kernel).compile(args)
        out.append(time.perf_counter() - t0)
    return out


def format_tree(events: list[CompileEvent], min_s: float = 0.05) -> str:
    """The events as an indented tree: inclusive and self time [s], cache hit, kernel and signature."""
    lines = []
    for e in events:
        if e.inclusive_s < min_s and e.depth > 0:
            continue
        mark = "cached" if e.cached else ("no-cache" if not e.can_cache else "")
        lines.append(f"{e.inclusive_s:7.2f} {e.self_s:7.2f} {mark:8s} {'  ' * e.depth}{e.kernel}")
    return "\n".join(lines)


# --------------------------------------------------------------------------- recorded plans

def group_name(group: tuple) -> str:
    """A compile group (``executors.compile_group``: body model, legged, water) as a name: ``massspring-legged-dry``."""
    body, legged, water = group
    return f"{body}-{'legged' if legged else 'legless'}-{'water' if water else 'dry'}"


def record_case(case) -> list[CompileEvent]:
    """Compile ``case``'s kernels in this process (``executors.compile_case``) and return what compiled."""
    from .executors import compile_case

    with recording() as events:
        compile_case(case)
    return events


MODULE = "bench_myriapoda.harness.compile_plan"
PLAN_MODULE = Path(__file__).with_name("compile_plans_data.py")


def _encode_args(args_list: list[tuple]) -> str:
    import base64
    import pickle
    import zlib

    return base64.b64encode(zlib.compress(pickle.dumps(args_list, protocol=4), 9)).decode("ascii")


def _decode_args(blob: str) -> list[tuple]:
    import base64
    import pickle
    import zlib

    return pickle.loads(zlib.decompress(base64.b64decode(blob)))


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


def compact(plan: Mapping[str, Any]) -> dict:
    """A recorded group plan with numba's own overloads (no disk cache, compiled again in every process that needs
    them) folded into their nearest cached caller: its self time gets theirs; the rest is unchanged."""
    ev, args = plan["events"], _decode_args(plan["args"])

    def node_of(k: int) -> int:
        while not ev[k][7] and ev[k][3] is not None:
            k = ev[k][3]
        return k

    keep = [k for k in range(len(ev)) if node_of(k) == k]
    new_index = {k: i for i, k in enumerate(keep)}
    extra = {k: 0.0 for k in keep}
    for k in range(len(ev)):
        if node_of(k) != k:
            extra[node_of(k)] += ev[k][5]
    events = []
    for k in keep:
        kernel, sig, depth, parent, incl, self_s, cached, can_cache = ev[k]
        events.append((kernel, sig, depth, None if parent is None else new_index[node_of(parent)], incl,
                       round(self_s + extra[k], 3), cached, can_cache))
    return dict(plan, events=events, args=_encode_args([args[k] for k in keep]))


def read_plan_module(path: Path = PLAN_MODULE) -> dict[str, dict]:
    """The ``PLANS`` of a module :func:`write_plan_module` wrote (empty if there is none)."""
    import importlib.util

    if not Path(path).is_file():
        return {}
    spec = importlib.util.spec_from_file_location("_bench_compile_plans", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return dict(mod.PLANS)


def write_plan_module(plans: Mapping[str, dict], note: str, path: Path = PLAN_MODULE) -> None:
    """Write the recorded plans as a Python module (``compile_plans_data``; generated, not edited by hand)."""
    import numba
    import pprint

    text = (f'"""Compile plans recorded by ``python -m {MODULE} --record``: generated, do not edit.\n\n'
            f"{note}\n\"\"\"\n"
            f"NUMBA_VERSION = {numba.__version__!r}\n"
            f"PLANS = {pprint.pformat(dict(plans), width=118, sort_dicts=True)}\n")
    path.write_text(text)


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


def critical_chain(plans: Mapping[str, Mapping[str, Any]]) -> dict[str, tuple[float, float]]:
    """Group name -> (its recorded serial compile [s], the longest chain of self times from a top-level kernel
    down its callees [s]): the least a group's compile can take however many workers compile its kernels
    (a caller's own compile starts once its callees are compiled)."""
    nodes, roots = kernel_graph(plans)
    memo: dict[str, float] = {}

    def chain(sig: str) -> float:
        if sig not in memo:
            memo[sig] = nodes[sig].self_s + max((chain(c) for c in nodes[sig].children), default=0.0)
        return memo[sig]

    out = {}
    for name, plan in plans.items():
        serial = sum(e[4] for e in plan["events"] if e[2] == 0)
        out[name] = (serial, max((chain(r) for r in roots.get(name, ())), default=0.0))
    return out


def _simulate_main(args) -> int:
    import json
    import math
    import sys

    from ..core import registry
    from . import compile_plans_data as data
    from .matrix import expand_matrix, locate_matrix
    from .store import read_matrix_case_walls

    store = Path(args.simulate) / "results.sqlite"
    if not store.is_file():
        print(f"bench-myriapoda: {args.simulate}: no results.sqlite; give a matrix output directory", file=sys.stderr)
        return 2
    registry.load_all()
    walls = {h: (w, c) for h, w, c in read_matrix_case_walls(store)}
    cases, run = [], []
    for mc in expand_matrix(locate_matrix(args.matrix)).cases:
        h = mc.case.case_hash()
        if h in walls and walls[h][0] is not None and math.isfinite(walls[h][0]):
            w, c = walls[h]
            cases.append(mc.case)
            run.append(max(0.0, w - (c if c is not None and math.isfinite(c) else 0.0)))
    plans = read_plan_module(Path(args.plans)) if args.plans else data.PLANS
    rows = []
    for n in args.workers:
        kw = dict(costs=run, worker_start_s=args.worker_start, per_case_s=args.per_case)
        rows.append({"workers": n, "before_s": simulate_cold(cases, run, n, plans, ahead=False, **kw),
                     "after_s": simulate_cold(cases, run, n, plans, ahead=True, **kw),
                     "warm_s": _warm(run, n, args)})
    chains = critical_chain(plans)
    if args.json:
        print(json.dumps({"cases": len(cases), "run_sum_s": sum(run), "rows": rows,
                          "groups": {k: {"serial_s": a, "chain_s": b} for k, (a, b) in chains.items()}}, indent=1))
        return 0
    print(f"{args.matrix}: {len(cases)} cases with a stored wall, {sum(run):.1f} s of cases with warm kernels; "
          f"compile plans of {len(plans)} groups")
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
    ap.add_argument("--write", action="store_true", help=f"write the recorded plans to {PLAN_MODULE.name}")
    ap.add_argument("--groups", nargs="+", metavar="GROUP", help="with --record: only these compile groups "
                    "(massspring-legged-dry, ...); with --write the file's other groups are kept")
    ap.add_argument("--out", metavar="FILE", help=f"with --write: write this file instead of {PLAN_MODULE.name} "
                    "(--simulate --plans FILE reads it)")
    ap.add_argument("--plans", metavar="FILE", help="with --simulate: the plans of this file (default: the "
                    "shipped ones)")
    ap.add_argument("--note", default="", help="how and where the plans were recorded (the module's docstring)")
    ap.add_argument("--simulate", metavar="DIR", help="a matrix output directory (results.sqlite) whose case wall "
                    "times minus compile are the cases' warm costs: the cold matrix's wall predicted with and "
                    "without kernels compiled ahead, from the recorded plans")
    ap.add_argument("--matrix", default="quick", help="the matrix DIR ran (with --simulate)")
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2, 4, 8, 16])
    ap.add_argument("--worker-start", type=float, default=0.0, metavar="S", help="worker start [s] (--simulate)")
    ap.add_argument("--per-case", type=float, default=0.0, metavar="S", help="fixed cost per case [s] (--simulate)")
    ap.add_argument("--json", action="store_true", help="--simulate: print JSON")
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
            out = Path(args.out) if args.out else PLAN_MODULE
            # --groups: the other groups' plans stay as they were recorded
            write_plan_module({**(read_plan_module(out) if args.groups else {}), **plans}, args.note, out)
        return 0
    ap.print_usage(sys.stderr)
    return 2



# --------------------------------------------------------------------------- what idle workers compile

MIN_TASK_S = 0.3  # a kernel whose recorded compile (callees included) took less is left to the case [s]


@dataclass(frozen=True)
class KernelTask:
    """One kernel signature an idle worker compiles ahead of the case that needs it (``compile_kernels``).

    ``inclusive_s`` / ``self_s`` [s]: the recorded compile with / without its callees; ``key``: the kernel and
    its signature, the same for every group that needs it (a kernel is compiled once, whichever group asks)."""

    kernel: str
    args: tuple
    key: str
    inclusive_s: float
    self_s: float


def _reverse_postorder(events: Sequence[tuple]) -> list[int]:
    """Event indices, callees before their callers, the LAST callee of each caller first.

    A case compiles its kernels depth first in call order; idle workers that start from the other end (the
    kernels the case reaches last, leaves first) rarely want a kernel the case's worker is compiling at that
    moment, and when they do the compile lock makes one wait for the other's cache entry."""
    children: dict[int | None, list[int]] = {}
    for k, ev in enumerate(events):
        children.setdefault(ev[3], []).append(k)
    out: list[int] = []

    def visit(k: int) -> None:
        for c in reversed(children.get(k, [])):
            visit(c)
        out.append(k)

    for root in reversed(children.get(None, [])):
        visit(root)
    return out


def group_tasks(plan: Mapping[str, Any], args: Sequence[tuple] | None = None) -> list[KernelTask]:
    """The kernels of one recorded group plan (``PLANS[name]``) that idle workers compile ahead, in the order they
    take them (:func:`_reverse_postorder`): every cached kernel of at least ``MIN_TASK_S`` but the group's
    largest top-level kernel (the one the case itself compiles first: its compile is the case's, and it
    finds its callees compiled)."""
    events = plan["events"]
    args = _decode_args(plan["args"]) if args is None else args
    roots = [k for k, ev in enumerate(events) if ev[2] == 0]
    main = max(roots, key=lambda k: events[k][4]) if roots else None
    out = []
    for k in _reverse_postorder(events):
        kernel, sig, depth, _parent, incl, self_s, _cached, can_cache = events[k]
        if k == main or not can_cache or incl < MIN_TASK_S or args[k] is None:
            continue
        out.append(KernelTask(kernel, tuple(args[k]), sig, float(incl), float(self_s)))
    return out


ENV_SWITCH = "BENCH_MYRIAPODA_COMPILE_PLAN"  # "off": no kernels compiled ahead, none preloaded (as before issue 31)


def plans_enabled() -> bool:
    """Whether the recorded plans are used (not turned off with ``BENCH_MYRIAPODA_COMPILE_PLAN=off``)."""
    import os

    return os.environ.get(ENV_SWITCH, "on").strip().lower() not in ("off", "0", "no", "false")


def load_plans() -> dict[str, list[KernelTask]]:
    """Group name -> :func:`group_tasks` of the recorded plans (``compile_plans_data``); empty where they do not
    apply: recorded with another numba major.minor version (its signatures' types may differ), unreadable, or
    turned off (:func:`plans_enabled`); a signature that no longer fits the code (:func:`stale_reason`) is left
    out.  Without a plan a group compiles as before, in the worker of its first case."""
    if not plans_enabled():
        return {}
    try:
        import numba

        from . import compile_plans_data as data
    except ImportError:
        return {}
    if numba.__version__.split(".")[:2] != data.NUMBA_VERSION.split(".")[:2]:
        return {}
    out = {}
    for name, plan in data.PLANS.items():
        try:
            tasks = group_tasks(plan)
        except Exception:  # noqa: BLE001 -- a plan pickled by another numba: compile as before
            continue
        out[name] = [t for t in tasks if stale_reason(t.kernel, t.args) is None]
    return out


def stale_reason(kernel: str, args: tuple) -> str | None:
    """Why a recorded signature no longer fits the code (None: it may): the kernel is gone, is no numba
    dispatcher, or takes another number of arguments.  A plan recorded before a kernel was renamed, removed or
    given other parameters would otherwise hand idle workers compiles that fail (caught in the worker: time
    lost) or preload nothing; :func:`load_plans` and :func:`preload_cached` skip such signatures.  A signature
    with the right number of arguments of types the code no longer passes cannot be told apart without
    compiling it: ``tests/test_compiled_signatures.py`` fails on those (every recorded signature must be one
    the quick matrix compiles now), and the plans are recorded again (module docstring)."""
    import inspect

    from numba.core.dispatcher import Dispatcher

    try:
        dispatcher = dispatcher_of(kernel)
    except (ImportError, AttributeError, ValueError) as exc:
        return f"{kernel}: not found ({type(exc).__name__}: {exc})"
    if not isinstance(dispatcher, Dispatcher):
        return f"{kernel}: not a numba dispatcher ({type(dispatcher).__name__})"
    params = inspect.signature(dispatcher.py_func).parameters.values()
    if any(p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD) for p in params):
        return None
    if len(args) != len(params):
        return f"{kernel}: recorded with {len(args)} arguments, takes {len(params)}"
    return None


def stale_signatures(plans: Mapping[str, Mapping[str, Any]] | None = None) -> list[str]:
    """Every recorded signature of ``plans`` (default: the shipped ``compile_plans_data.PLANS``) that
    :func:`stale_reason` rejects, as ``group: reason`` lines (empty: none is stale)."""
    if plans is None:
        from . import compile_plans_data as data

        plans = data.PLANS
    out = []
    for name, plan in plans.items():
        try:
            args = _decode_args(plan["args"])
        except Exception as exc:  # noqa: BLE001 -- pickled by another numba or damaged
            out.append(f"{name}: the signatures cannot be read ({type(exc).__name__}: {exc})")
            continue
        for k, ev in enumerate(plan["events"]):
            why = None if args[k] is None else stale_reason(ev[0], tuple(args[k]))
            if why is not None:
                out.append(f"{name}: {why}")
    return out


# --------------------------------------------------------------------------- simulated cold matrix

@dataclass
class _Kernel:
    self_s: float
    children: list[str]


def kernel_graph(plans: Mapping[str, Mapping[str, Any]]) -> tuple[dict[str, _Kernel], dict[str, list[str]]]:
    """(kernel signature -> its recorded self compile time [s] and callees, group name -> its top-level
    signatures in call order) from recorded plans (``PLANS``).  A signature several groups compile is one node."""
    nodes: dict[str, _Kernel] = {}
    roots: dict[str, list[str]] = {}
    for name, plan in plans.items():
        ev = plan["events"]

        def node_of(k: int) -> int:
            """The event a compile counts under: numba's own overloads (no disk cache) are compiled again in each
            process that needs them, as part of their nearest cached caller."""
            while not ev[k][7] and ev[k][3] is not None:
                k = ev[k][3]
            return k

        mine: set[str] = set()  # nodes this group's events define (another group's copy is the same kernel)
        for k, (_kernel, sig, _depth, parent, _incl, self_s, _cached, _cc) in enumerate(ev):
            at = node_of(k)
            if at != k:
                if ev[at][1] in mine:
                    nodes[ev[at][1]].self_s += float(self_s)
                continue
            if sig not in nodes:
                nodes[sig] = _Kernel(float(self_s), [])
                mine.add(sig)
            if parent is None:
                roots.setdefault(name, []).append(sig)
            elif sig not in nodes[ev[node_of(parent)][1]].children:
                nodes[ev[node_of(parent)][1]].children.append(sig)
    return nodes, roots


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


# --------------------------------------------------------------------------- loading cached kernels once

def load_cached(dispatcher, args: tuple) -> bool:
    """Load ``dispatcher``'s compiled ``args`` signature from numba's disk cache into this process, never
    compiling it; whether it is loaded now.  What ``Dispatcher.compile`` does on a cache hit (numba 0.6x)."""
    from numba.core.compiler_lock import global_compiler_lock

    args = tuple(args)
    with global_compiler_lock:
        if args in dispatcher.overloads:
            return True
        cres = dispatcher._cache.load_overload(args, dispatcher.targetctx)
        if cres is None:
            return False
        dispatcher._cache_hits[args] += 1
        if not cres.objectmode:
            dispatcher.targetctx.insert_user_function(cres.entry_point, cres.fndesc, [cres.library])
        dispatcher.add_overload(cres)
        return True


def preload_cached() -> tuple[int, int]:
    """Load every recorded group's top-level kernels (the ones a case calls from Python) that are in numba's disk
    cache into this process; (signatures loaded, signatures recorded).  The local workers' fork server runs it
    once (``worker_preload``), so every worker forked from it starts with them instead of loading them for its
    first case of each group; on a cold cache nothing is loaded and nothing is compiled."""
    if not plans_enabled():
        return 0, 0
    try:
        import numba

        from . import compile_plans_data as data
    except ImportError:
        return 0, 0
    if numba.__version__.split(".")[:2] != data.NUMBA_VERSION.split(".")[:2]:
        return 0, 0
    loaded = total = 0
    seen: set[str] = set()
    for plan in data.PLANS.values():
        try:
            args = _decode_args(plan["args"])
        except Exception:  # noqa: BLE001 -- pickled by another numba: nothing to preload from this plan
            continue
        for k, (kernel, sig, depth, _parent, _incl, _self, _cached, can_cache) in enumerate(plan["events"]):
            if depth != 0 or not can_cache or args[k] is None or sig in seen or stale_reason(kernel, args[k]):
                continue
            seen.add(sig)
            total += 1
            try:
                loaded += load_cached(dispatcher_of(kernel), args[k])
            except Exception:  # noqa: BLE001 -- a stale or foreign cache entry: the case loads or compiles its own
                continue
    return loaded, total


if __name__ == "__main__":
    raise SystemExit(main())
