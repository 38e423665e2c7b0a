"""The legged Python path calls its compiled entries without numba's per-call dispatch on the pack
(``bodies.legged_chunk``, ``LeggedPackOps._legged_run``; issue 42: the dispatcher fingerprinted the body's pack, a
namedtuple of namedtuples of arrays, leaf by leaf at every call, 5 to 10 us of each call on the hybrid).

Each operation types the pack and its arguments once, then runs the machine code the dispatcher holds for that
signature (the same entry point, so the same doubles as a dispatched call); arguments of other types resolve a
signature of their own.  That the Python path equals the fused walk is tests/test_fused_walk.py's.
"""
from __future__ import annotations

import numpy as np
from numba._dispatcher import compute_fingerprint

from bench_myriapoda.bodies import legged_chunk as LC
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import build_body


def _counting_typeof(monkeypatch) -> list:
    """Replace ``legged_chunk``'s numba ``typeof`` by one that records every value it types."""
    typed: list = []
    real = LC.typeof

    def typeof(value, purpose):
        typed.append(value)
        return real(value, purpose)

    monkeypatch.setattr(LC, "typeof", typeof)
    return typed


def test_each_operation_types_the_pack_once_and_runs_the_dispatchers_machine_code(monkeypatch):
    body = build_body(resolve_case("centipede", "hybrid", "walk", overrides=["creature.segments=4"]))
    typed = _counting_typeof(monkeypatch)
    P = body.legged_ops_pack
    n = body.n_segments

    c, R = body.segment_poses()
    assert len(typed) == 1 and typed[0] is P              # the pack, typed once ...
    for _ in range(3):
        c, R = body.segment_poses()
    assert len(typed) == 1                                # ... not at every call
    entry = body._legged_entries[(LC.poses_now, compute_fingerprint(()))]
    overloads = [cres.entry_point for cres in LC.poses_now.overloads.values()]
    assert entry in overloads                             # the dispatcher's own machine code for the pack
    c_d, R_d = LC.poses_now(P)                            # and a dispatched call gives the same doubles
    assert np.array_equal(c, c_d) and np.array_equal(R, R_d)

    kinematic = np.zeros(n, bool)
    for _ in range(3):
        body.set_support(kinematic, c, R, body.dt)
    assert len(typed) == 1 + 7                            # the pack and the six arguments of support_now, once
    samples = [body.legged_sample() for _ in range(3)]
    assert len(typed) == 1 + 7 + 4                        # the pack and sample_now's three outputs, once
    for got in samples[1:]:
        assert all(np.array_equal(a, b) for a, b in zip(got, samples[0]))
    c_s, R_s, centres = samples[0]
    assert np.array_equal(centres[0::2], c_s) and centres.shape == (2 * n - 1, 3)


def test_an_argument_of_another_type_resolves_its_own_signature(monkeypatch):
    body = build_body(resolve_case("centipede", "hybrid", "walk", overrides=["creature.segments=4"]))
    c, R = body.segment_poses()
    kinematic = np.zeros(body.n_segments, bool)
    body.set_support(kinematic, c, R, body.dt)
    typed = _counting_typeof(monkeypatch)
    R_readonly = R.copy()
    R_readonly.flags.writeable = False                    # numba types a read-only array as another type
    body.set_support(kinematic, c, R_readonly, body.dt)
    assert len(typed) == 7                                # a new key: the pack and its arguments typed again
    support = [key for key in body._legged_entries if key[0] is LC.support_now]
    assert len(support) == 2
    body.set_support(kinematic, c, R_readonly, body.dt)
    assert len(typed) == 7                                # and that signature, once
