"""tests/compile_ahead.py: what a cold test session compiles ahead, and that it would start at all."""
from __future__ import annotations

import numba
import pytest

from compile_ahead import ahead_signatures, enabled

from bench_myriapoda.jit import compile_plan as cp


def test_every_recorded_groups_kernels_are_compiled_ahead_once_the_longest_group_first():
    data = cp.shipped_plans()
    if numba.__version__.split(".")[:2] != data.numba_version.split(".")[:2]:
        pytest.skip(f"plans recorded with numba {data.numba_version}, not used with {numba.__version__}")
    tasks = ahead_signatures()
    sigs = [f"{kernel}({', '.join(str(a) for a in args)})" for kernel, args in tasks]
    assert len(sigs) == len(set(sigs))  # a signature several groups share is compiled once
    recorded = {ev[1] for plan in data.plans.values() for ev in plan["events"] if ev[7]}
    assert set(sigs) == recorded  # every cacheable recorded signature, nothing else
    # the longest group first, its leaves before its callers: the first task is a leaf of that group
    serial = {n: sum(ev[4] for ev in p["events"] if ev[2] == 0) for n, p in data.plans.items()}
    first = data.plans[max(serial, key=serial.get)]["events"]
    assert not any(ev[3] is not None and first[ev[3]][1] == sigs[0] for ev in first)


def test_the_switch_turns_it_off(monkeypatch):
    monkeypatch.setenv("BENCH_TEST_COMPILE_AHEAD", "off")
    assert not enabled()
    monkeypatch.setenv("BENCH_TEST_COMPILE_AHEAD", "on")
    assert enabled()
    monkeypatch.setenv("BENCH_MYRIAPODA_COMPILE_PLAN", "off")  # no plans: nothing to compile ahead
    assert ahead_signatures() == []
