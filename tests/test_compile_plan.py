"""Issue 31, item 3: kernels compiled ahead by idle workers (jit/compile_plan.py, the executor's kernel jobs)."""
from __future__ import annotations

import multiprocessing as mp
import textwrap

import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness import cold_compile as CC
from bench_myriapoda.jit import compile_plan as CP
from bench_myriapoda.harness.executors import CompileScheduler, compile_group

# A caller with two cached callees, one of which calls a third: the shape of a fused chunk kernel and its
# controller and body steps, small enough to compile in a second.
MODULE = textwrap.dedent('''
    import numpy as np
    from numba import njit


    @njit(cache=True)
    def leaf(a):
        s = 0.0
        for i in range(a.shape[0]):
            s += np.sin(a[i]) * np.cos(a[i])
        return s


    @njit(cache=True)
    def left(a, k):
        return leaf(a) * k


    @njit(cache=True)
    def right(a):
        out = np.empty_like(a)
        for i in range(a.shape[0]):
            out[i] = np.tanh(a[i]) + np.exp(-a[i])
        return out


    @njit(cache=True)
    def caller(a, k):
        return left(a, k) + right(a).sum()
''')


def _child(module_dir, cache_dir, what, out):
    """In a fresh process on ``cache_dir``: ``record`` the caller's compile, ``ahead`` compile a plan's tasks, or
    ``caller`` compile the caller counting which kernels numba compiled (not loaded)."""
    import os
    import sys

    os.environ["NUMBA_CACHE_DIR"] = cache_dir
    sys.path.insert(0, module_dir)
    import numba
    import numpy as np
    from numba.core import event as ev

    numba.config.CACHE_DIR = cache_dir
    from bench_myriapoda.jit import compile_lock
    from bench_myriapoda.jit import compile_plan as cp

    compile_lock.install()
    import planmod

    a = np.linspace(0.0, 1.0, 8)
    if what == "record":
        with cp.recording() as events:
            planmod.caller(a, 2.0)
        out.put([(e.kernel, e.signature(), e.depth, e.parent, e.inclusive_s, e.self_s, e.cached, e.can_cache)
                 for e in events])
        out.put(cp._encode_args([e.args for e in events]))
        return
    if what == "ahead":
        plan, out = out
        tasks = cp.group_tasks(plan)
        cp.compile_kernels([(t.kernel, t.args) for t in tasks])
        out.put([t.kernel for t in tasks])
        return
    compiled = []

    class Rec(ev.Listener):
        def on_start(self, event):
            f = event.data["dispatcher"].py_func
            if f.__module__ == "planmod":  # not numba's own overloads (compiled in every process)
                compiled.append(f.__name__)

        def on_end(self, event):
            pass

    with ev.install_listener("numba:compile", Rec()):
        planmod.caller(a, 2.0)
    out.put(compiled)


def _run(ctx, module_dir, cache_dir, what):
    q = ctx.Queue()
    p = ctx.Process(target=_child, args=(str(module_dir), str(cache_dir), what, q))
    p.start()
    res = [q.get(timeout=300)]
    if what == "record":
        res.append(q.get(timeout=60))
    p.join(timeout=60)
    assert p.exitcode == 0
    return res


def test_a_recorded_plan_compiled_ahead_leaves_the_caller_only_its_own_compile(tmp_path):
    """The plan's signatures are exactly those the caller asks for: after another process compiled them ahead,
    the caller's compile loads its callees from the cache and compiles only itself."""
    (tmp_path / "mod").mkdir()
    (tmp_path / "mod" / "planmod.py").write_text(MODULE)
    ctx = mp.get_context("spawn")
    events, args = _run(ctx, tmp_path / "mod", tmp_path / "cache-record", "record")
    # numba's own overloads (np.empty_like, .sum()) are dispatchers too, without a disk cache
    ours = [e for e in events if e[0].startswith("planmod.")]
    assert all(e[7] for e in ours) and not any(e[7] for e in events if e not in ours)
    names = [e[0].rsplit(".", 1)[1] for e in ours]
    assert names == ["caller", "left", "leaf", "right"]  # depth first in call order
    depth = dict(zip(names, (e[2] for e in ours)))
    assert depth == {"caller": 0, "left": 1, "leaf": 2, "right": 1}
    for e in events:
        assert 0.0 <= e[5] <= e[4] and not e[6]
    caller = events[0]
    callees = [e for e in events if e[3] == 0]
    assert caller[4] == pytest.approx(caller[5] + sum(e[4] for e in callees), rel=1e-9)  # inclusive = self + callees
    plan = {"case": "planmod", "events": [tuple(e) for e in events], "args": args}
    # every callee, whatever its size, for this test
    old = CP.MIN_TASK_S
    CP.MIN_TASK_S = 0.0
    try:
        tasks = CP.group_tasks(plan)
    finally:
        CP.MIN_TASK_S = old
    # the last callee's subtree first, leaves before their callers; the top-level kernel is the case's own
    assert [t.kernel.rsplit(".", 1)[1] for t in tasks] == ["right", "leaf", "left"]
    # a fresh cache: the caller compiles all four
    assert sorted(_run(ctx, tmp_path / "mod", tmp_path / "cache-cold", "caller")[0]) == ["caller", "leaf", "left", "right"]
    # the plan's tasks compiled ahead in one process, then the caller in another: only the caller compiles
    fresh = tmp_path / "cache-fresh"
    assert _run_ahead(ctx, tmp_path / "mod", fresh, plan) == [t.kernel for t in tasks]
    assert _run(ctx, tmp_path / "mod", fresh, "caller")[0] == ["caller"]


def _run_ahead(ctx, module_dir, cache_dir, plan):
    """The plan's tasks (every size) compiled in a fresh process on ``cache_dir``; the kernels it compiled."""
    q_in, q_out = ctx.Queue(), ctx.Queue()
    q_in.put(plan)
    p = ctx.Process(target=_ahead_child, args=(str(module_dir), str(cache_dir), q_in, q_out))
    p.start()
    res = q_out.get(timeout=300)
    p.join(timeout=60)
    assert p.exitcode == 0
    return res


def _ahead_child(module_dir, cache_dir, q_in, q_out):
    from bench_myriapoda.jit import compile_plan as cp

    cp.MIN_TASK_S = 0.0
    plan = q_in.get()
    _child(module_dir, cache_dir, "ahead", (plan, q_out))


def test_group_tasks_leave_out_the_main_kernel_small_ones_and_unpicklable_signatures():
    events = [("m.chunk", "m.chunk(a)", 0, None, 10.0, 2.0, False, True),
              ("m.ctrl", "m.ctrl(a)", 1, 0, 5.0, 1.0, False, True),
              ("m.ik", "m.ik(a)", 2, 1, 4.0, 4.0, False, True),
              ("m.tiny", "m.tiny(a)", 2, 1, 0.01, 0.01, False, True),
              ("m.body", "m.body(a)", 1, 0, 3.0, 3.0, False, True),
              ("m.fn_arg", "m.fn_arg(f)", 1, 0, 1.0, 1.0, False, True),  # its args could not be pickled
              ("m.helper", "m.helper(a)", 1, 0, 1.0, 1.0, False, False),  # no cache=True: compiled into each caller
              ("m.terrain", "m.terrain(a)", 0, None, 2.0, 2.0, False, True)]
    args = [("a",)] * len(events)
    args[5] = None
    tasks = CP.group_tasks({"events": events, "args": CP._encode_args(args)})
    # the other top-level kernel first (the case reaches it last), then the chunk's callees from the last
    assert [t.kernel for t in tasks] == ["m.terrain", "m.body", "m.ik", "m.ctrl"]
    assert all(t.args == ("a",) for t in tasks)


def _task(name, self_s=1.0):
    return CP.KernelTask(f"m.{name}", ("a",), f"m.{name}(a)", self_s, self_s)


def test_idle_workers_get_kernels_of_groups_not_yet_warm_each_kernel_once():
    worm = resolve_case("worm", "massspring", "flat")
    worm_2 = resolve_case("worm", "massspring", "flat", duration=1.0)
    fem = resolve_case("worm", "fem", "flat")
    g_ms, g_fem = CP.group_name(compile_group(worm)), CP.group_name(compile_group(fem))
    assert g_ms == "massspring-legless-dry"
    plans = {g_ms: [_task("ms_step", 5.0), _task("terrain", 1.0)],
             g_fem: [_task("fem_step", 2.0), _task("terrain", 1.0)]}
    s = CompileScheduler([worm, worm_2, fem], plans=plans)
    assert s.next_job()[0] == 0 and s.next_job()[0] == 2  # both groups compile
    assert s.next_job() is None  # worm_2 waits for its group's kernels: a kernel job instead
    assert s.next_kernel_job().kernel == "m.ms_step"  # the group with the most compile time left
    assert s.next_kernel_job().kernel == "m.fem_step"  # now the FEM group has more left (terrain is shared)
    assert s.next_kernel_job().kernel == "m.terrain"
    assert s.next_kernel_job() is None and not s.kernel_jobs_left()  # the shared kernel went out once
    assert s.kernel_jobs == 3
    s2 = CompileScheduler([worm, worm_2], plans=plans)
    s2.next_job()
    s2.warmed(0)  # the group's kernels are in the cache: nothing to compile ahead
    assert s2.next_kernel_job() is None and not s2.kernel_jobs_left()
    assert CompileScheduler([worm], plans={}).next_kernel_job() is None  # no plan: compile as before


def _plan(events):
    args = [("a",)] * len(events)
    return {"case": "x", "events": events, "args": CP._encode_args(args)}


def test_simulated_cold_matrix_compiles_a_groups_independent_kernels_side_by_side():
    """One group whose case compiles a chunk (self 4 s) over two callees of 10 s each: serial, 24 s before the
    case runs; with kernels compiled ahead on three workers, 14 s (the chunk after the slower callee)."""
    cases = [resolve_case("worm", "massspring", "flat", duration=d) for d in (1.0, 2.0, 3.0)]
    name = CP.group_name(compile_group(cases[0]))
    plans = {name: _plan([("m.chunk", "m.chunk(a)", 0, None, 24.0, 4.0, False, True),
                          ("m.ctrl", "m.ctrl(a)", 1, 0, 10.0, 10.0, False, True),
                          ("m.body", "m.body(a)", 1, 0, 10.0, 10.0, False, True)])}
    run = [1.0, 2.0, 3.0]
    costs = [1.0, 2.0, 3.0]
    before = CC.simulate_cold(cases, run, 3, plans, ahead=False, costs=costs)
    after = CC.simulate_cold(cases, run, 3, plans, ahead=True, costs=costs)
    # before: the cheapest case compiles all 24 s, then the three cases run on three workers: 24 + 3
    assert before == pytest.approx(27.0)
    # ahead: two idle workers compile the callees while the case's worker waits for them, then the chunk 4 s
    assert after == pytest.approx(10.0 + 4.0 + 3.0)
    # one worker: nothing idle, the same 24 s of compile plus 6 s of cases either way
    assert CC.simulate_cold(cases, run, 1, plans, ahead=True, costs=costs) == pytest.approx(30.0)
    assert CC.simulate_cold(cases, run, 1, plans, ahead=False, costs=costs) == pytest.approx(30.0)
    # two workers on one core share it: no faster than one worker
    assert CC.simulate_cold(cases, run, 2, plans, ahead=True, costs=costs, cores=1) == pytest.approx(30.0)


def test_recorded_plans_load_and_name_kernels_that_exist():
    """The shipped plans (jit/compile_plans.json) decode with this numba and name importable dispatchers."""
    plans = CP.load_plans()
    import numba

    data = CP.shipped_plans()
    if numba.__version__.split(".")[:2] != data.numba_version.split(".")[:2]:
        pytest.skip(f"plans recorded with numba {data.numba_version}")
    assert set(plans) == set(data.plans)
    for name, tasks in plans.items():
        assert tasks, name
        for t in tasks:
            assert hasattr(CP.dispatcher_of(t.kernel), "compile")


def test_kernels_compiled_ahead_change_no_result_and_the_switch_turns_them_off(tmp_path, monkeypatch):
    """Two workers, one compile group: the second worker compiles the group's kernels ahead while the first case
    compiles (a kernel job); with BENCH_MYRIAPODA_COMPILE_PLAN=off it waits.  Metrics bit for bit the same."""
    import math

    from bench_myriapoda.harness.executors import run_matrix

    if not CP.load_plans().get("massspring-legless-dry"):
        pytest.skip("no compile plan for this numba version")
    cases = [resolve_case("worm", "massspring", "flat", duration=d) for d in (0.2, 0.3, 0.4)]
    runs, stats = {}, {}
    for setting in ("on", "off"):
        monkeypatch.setenv(CP.ENV_SWITCH, setting)
        stats[setting] = {}
        runs[setting] = {r.case.case_hash(): r for r in run_matrix(
            cases, "local", workers=2, store_path=tmp_path / f"{setting}.sqlite", matrix="m", stats=stats[setting])}
    assert stats["on"]["kernel_jobs"] >= 1 and stats["off"]["kernel_jobs"] == 0
    assert len(runs["on"]) == len(runs["off"]) == 3
    for h, r in runs["on"].items():
        o = runs["off"][h]
        assert r.status == o.status == "ok" and r.metrics.keys() == o.metrics.keys()
        assert all(v == o.metrics[k] or (isinstance(v, float) and math.isnan(v) and math.isnan(o.metrics[k]))
                   for k, v in r.metrics.items())


def test_a_stale_plan_signature_is_skipped_not_compiled(monkeypatch):
    """A plan recorded before a kernel was renamed or given other parameters: load_plans leaves those
    signatures out (a worker would spend a compile that fails), keeps the rest, and stale_signatures names
    them.  The shipped plans have none (tests/test_compiled_signatures.py also checks their argument types)."""
    from numba.core import types

    data = CP.shipped_plans()
    assert CP.stale_signatures() == []
    ok = "bench_myriapoda.bodies.fem.kernels.lumped_mass"
    f64 = types.float64[::1]
    assert CP.stale_reason(ok, (types.int64[:, ::1], f64, f64, f64)) is None
    events = [("bench_myriapoda.fused.legged_walk.hybrid_chunk", "gone(a)", 0, None, 9.0, 1.0, False, True),
              (ok, f"{ok}(a, b)", 1, 0, 4.0, 4.0, False, True),  # two arguments recorded, four taken
              (ok, f"{ok}(a, b, c, d)", 1, 0, 4.0, 4.0, False, True),
              ("bench_myriapoda.jit.compile_plan.stale_reason", "x(a, b)", 1, 0, 4.0, 4.0, False, True),
              ("bench_myriapoda.bodies.fem.kernels.rest_shape", "r(a)", 0, None, 2.0, 2.0, False, True)]
    args = [("a",), ("a", "b"), ("a", "b", "c", "d"), ("a", "b"), ("a",)]
    plan = {"case": "x", "events": events, "args": CP._encode_args(args)}
    why = CP.stale_signatures({"g": plan})
    assert len(why) == 4 and all(w.startswith("g: ") for w in why)
    assert "hybrid_chunk: not found" in why[0]
    assert "recorded with 2 arguments, takes 4" in why[1]
    assert "not a numba dispatcher" in why[2]
    assert "recorded with 1 arguments, takes 4" in why[3]
    monkeypatch.setattr(data, "plans", {"g": plan})
    monkeypatch.setattr(data, "numba_version", __import__("numba").__version__)
    monkeypatch.setenv(CP.ENV_SWITCH, "on")
    assert [t.key for t in CP.load_plans()["g"]] == [f"{ok}(a, b, c, d)"]


def test_the_plans_are_a_data_file_written_and_read_back_whole(tmp_path):
    """The shipped plans are JSON (``jit/compile_plans.json``), read strictly by ``read_plans``; ``write_plans``
    writes what it is given and reads back the same plans (events as lists); a file that is not one is a
    ValueError naming it and the command that writes it, and the executor then uses no plans."""
    shipped = CP.read_plans(CP.PLANS_FILE)
    assert CP.PLANS_FILE.name == "compile_plans.json" and CP.PLANS_FILE.is_file()
    assert shipped.numba_version and shipped.plans
    assert CP.shipped_plans().plans.keys() == shipped.plans.keys()
    out = tmp_path / "plans.json"
    CP.write_plans(shipped.plans, "a note", out, numba_version="0.1.2")
    back = CP.read_plans(out)
    assert (back.numba_version, back.note) == ("0.1.2", "a note")
    assert {n: [tuple(e) for e in p["events"]] for n, p in back.plans.items()} == \
        {n: [tuple(e) for e in p["events"]] for n, p in shipped.plans.items()}
    assert {n: (p["case"], p["args"]) for n, p in back.plans.items()} == \
        {n: (p["case"], p["args"]) for n, p in shipped.plans.items()}
    assert len(out.read_text().splitlines()) > sum(len(p["events"]) for p in shipped.plans.values())  # a line each
    bad = tmp_path / "bad.json"
    bad.write_text('{"plans": {}}')
    with pytest.raises(ValueError, match="bad.json.*cold_compile --record quick --write"):
        CP.read_plans(bad)
