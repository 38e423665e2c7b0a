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
cache.  ``python -m bench_myriapoda.harness.cold_compile --record quick --write`` (:data:`RECORD_COMMAND`)
records every compile group of a matrix, each in a fresh process on an empty cache, into the data file
``compile_plans.json`` beside this module (:func:`write_plans`; generated, not edited; the signatures
pickled, as they are numba types; ``cold_compile`` also simulates a cold matrix), shipped as package data
and read once per process (:func:`shipped_plans`).
:func:`load_plans` turns them into :class:`KernelTask` lists, which the local executor hands to workers that would otherwise wait
(``executors.CompileScheduler.next_kernel_job``): they compile a group's kernels with the case's
exact signatures, from the end of the tree the case reaches last, so the case finds them in the
cache.  The compile lock keeps each kernel compiled once per machine.  :func:`preload_cached` loads
the recorded top-level kernels that are cached into the workers' fork server (``worker_preload``).
``cold_compile.simulate_cold`` predicts a cold matrix's wall with and without kernels compiled ahead
(``--simulate DIR``).  ``BENCH_MYRIAPODA_COMPILE_PLAN=off`` turns all of it off.  This module imports
nothing of the executor's (which uses it); what needs the executor is in ``cold_compile``.
"""
from __future__ import annotations

import base64
import contextlib
import functools
import importlib
import inspect
import json
import os
import pickle
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator, Mapping, Sequence

# numba is imported where it is used: importing it costs about 0.26 s of CPU (python -c, time.process_time), which a
# process that only reads, writes or schedules the plans (group_name, read_plans, kernel_graph) does not pay


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


PLANS_FILE = Path(__file__).with_name("compile_plans.json")  # shipped as package data (pyproject.toml)
RECORD_MODULE = "bench_myriapoda.harness.cold_compile"  # the command line that records and simulates
RECORD_COMMAND = f"python -m {RECORD_MODULE} --record quick --write"  # how PLANS_FILE is written


@dataclass
class RecordedPlans:
    """Compile plans as :func:`write_plans` wrote them: ``numba_version``, the numba that compiled them (plans of
    another major.minor version are not used: its types may differ); ``plans``, group name (:func:`group_name`) ->
    ``{"case": label, "events": [(kernel, signature, depth, parent, inclusive_s, self_s, cached, can_cache)],
    "args": the events' argument types, pickled}``; ``note``, how and where they were recorded."""

    numba_version: str
    plans: dict[str, dict]
    note: str = ""


def _encode_args(args_list: list[tuple]) -> str:
    return base64.b64encode(zlib.compress(pickle.dumps(args_list, protocol=4), 9)).decode("ascii")


def _decode_args(blob: str) -> list[tuple]:
    return pickle.loads(zlib.decompress(base64.b64decode(blob)))


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


def read_plans(path: Path = PLANS_FILE) -> RecordedPlans:
    """The plans of a file :func:`write_plans` wrote; ``ValueError`` naming the file when it is not one."""
    try:
        doc = json.loads(Path(path).read_text(encoding="utf-8"))
        return RecordedPlans(str(doc["numba_version"]), dict(doc["plans"]), str(doc.get("note", "")))
    except (ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: not a compile plans file ({type(exc).__name__}: {exc}); write it again with "
                         f"{RECORD_COMMAND}") from None


@functools.lru_cache(maxsize=1)
def shipped_plans() -> RecordedPlans:
    """The plans shipped with the package (``compile_plans.json``), read once per process; none (an empty
    record) when the file is missing or unreadable: every group then compiles as before, in the worker of its
    first case (``tests/test_compile_plan.py`` checks that the shipped file reads)."""
    try:
        return read_plans(PLANS_FILE)
    except (OSError, ValueError):
        return RecordedPlans("", {})


def write_plans(plans: Mapping[str, Mapping[str, Any]], note: str, path: Path = PLANS_FILE,
                numba_version: str | None = None) -> None:
    """Write recorded plans as JSON (``compile_plans.json``: generated by :data:`RECORD_COMMAND`, not edited by hand),
    one event to a line so that a new recording reads as a diff; the file is replaced whole.  ``numba_version``:
    the numba that recorded them (default: this process's)."""
    if numba_version is None:
        import numba

        numba_version = numba.__version__

    def one(value) -> str:
        return json.dumps(value, ensure_ascii=True)

    lines = ["{", f'"generated_by": {one(f"{RECORD_COMMAND} (do not edit)")},',
             f'"numba_version": {one(numba_version)},', f'"note": {one(note)},', '"plans": {']
    groups = sorted(plans.items())
    for k, (name, plan) in enumerate(groups):
        lines += [f" {one(name)}: {{", f'  "case": {one(plan["case"])},', f'  "args": {one(plan["args"])},',
                  '  "events": [']
        events = [list(ev) for ev in plan["events"]]
        lines += [f"   {one(ev)}{',' if i + 1 < len(events) else ''}" for i, ev in enumerate(events)]
        lines += ["  ]", f" }}{',' if k + 1 < len(groups) else ''}"]
    lines += ["}", "}"]
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text("\n".join(lines) + "\n", encoding="utf-8")
    tmp.replace(path)


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
    """The kernels of one recorded group plan (``shipped_plans().plans[name]``) that idle workers compile ahead, in the order they
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
    return os.environ.get(ENV_SWITCH, "on").strip().lower() not in ("off", "0", "no", "false")


def load_plans() -> dict[str, list[KernelTask]]:
    """Group name -> :func:`group_tasks` of the recorded plans (:func:`shipped_plans`); empty where they do not
    apply: recorded with another numba major.minor version (its signatures' types may differ), unreadable, or
    turned off (:func:`plans_enabled`); a signature that no longer fits the code (:func:`stale_reason`) is left
    out.  Without a plan a group compiles as before, in the worker of its first case."""
    if not plans_enabled():
        return {}
    import numba

    data = shipped_plans()
    if numba.__version__.split(".")[:2] != data.numba_version.split(".")[:2]:
        return {}
    out = {}
    for name, plan in data.plans.items():
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
    """Every recorded signature of ``plans`` (default: the shipped ones, :func:`shipped_plans`) that
    :func:`stale_reason` rejects, as ``group: reason`` lines (empty: none is stale)."""
    if plans is None:
        plans = shipped_plans().plans
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
    signatures in call order) from recorded plans (``RecordedPlans.plans``).  A signature several groups compile is one node."""
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
    import numba

    data = shipped_plans()
    if numba.__version__.split(".")[:2] != data.numba_version.split(".")[:2]:
        return 0, 0
    loaded = total = 0
    seen: set[str] = set()
    for plan in data.plans.values():
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
