"""The Python path and the fused legged walk are one implementation (issue 42 item 2, ``bodies.legged_chunk``).

For every body in the catalog that builds the centipede with a fused legged walk, checked by identity (nothing is
compiled): its Python segment interface is ``LeggedPackOps``'s, which runs the functions the body registered for
its pack through ``legged_chunk``'s compiled entries, the same generic functions the fused chunk inlines; the
legged monitor samples through it; and its ``advance`` and the fused walk's registered step call one step function.
A body that overrides one of these methods with code of its own, registers a step that is not its ``advance``'s,
or a monitor that samples another way fails here.  That the two paths then give the same doubles is
tests/test_fused_walk.py's.
"""
from __future__ import annotations

import sys

import numpy as np
import pytest

from bench_myriapoda import catalog
from bench_myriapoda.bodies import legged_chunk as LC
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.core.protocols import LEGS
from bench_myriapoda.fused import legged_walk
from bench_myriapoda.harness.legged import LeggedMonitor
from bench_myriapoda.harness.runner import build_body

OPS = ("segment_poses", "set_support", "push_support", "legged_sample")
# LeggedPackOps' method -> the compiled entry it calls; the entry -> the generic functions (the registered
# implementations' overloads) it calls
ENTRY = {"segment_poses": "poses_now", "set_support": "support_now", "push_support": "support_now",
         "legged_sample": "sample_now"}
GENERIC = {"poses_now": {"poses"}, "support_now": {"poses", "carry", "carry_feet"}, "sample_now": {"sample"}}


def _legged_bodies():
    """The package catalog's legged bodies (not a plugin's or a test's: their Python methods may be their own)."""
    return sorted(name for name, spec in catalog.BODIES.items() if LEGS in spec.capabilities)


def _centipede(name):
    return build_body(resolve_case("centipede", name, "walk", overrides=["creature.segments=4"]))


def test_the_catalog_has_legged_bodies():
    assert {"hybrid", "massspring", "fem"} <= set(_legged_bodies())


@pytest.mark.parametrize("name", _legged_bodies())
def test_the_python_segment_interface_is_the_registered_operations(name):
    body = _centipede(name)
    assert isinstance(body, LC.LeggedChunkBody) and isinstance(body, LC.LeggedPackOps), name
    for op in OPS:  # no body-specific Python version of an operation
        assert getattr(type(body), op) is getattr(LC.LeggedPackOps, op), f"{name}.{op} is its own code"
    cls = type(body.legged_pack())
    assert type(body.legged_ops_pack) is cls   # the Python path's pack is of the registered class
    assert cls in LC._IMPLS
    # each method calls its compiled entry, which calls the generic functions the fused chunk calls
    for op, entry in ENTRY.items():
        assert entry in getattr(LC.LeggedPackOps, op).__code__.co_names, op
        assert GENERIC[entry] <= set(getattr(LC, entry).py_func.__code__.co_names), entry
    walk = legged_walk.legged_chunk.py_func.__code__.co_names
    assert {"poses", "carry_feet", "sample", "step"} <= set(walk)
    # and the legged monitor samples through the body's registered ``sample``
    assert "legged_sample" in LeggedMonitor.after_control.__code__.co_names


@pytest.mark.parametrize("name", _legged_bodies())
def test_advance_and_the_fused_step_call_one_step_function(name):
    body = _centipede(name)
    cls = type(body.legged_pack())
    poses, carry, sample, step, feet, body_step = LC.registered(cls)
    assert body_step is not None, f"{name}: the fused step is not chain_step(its step function)"
    assert step.body_step is body_step
    module = sys.modules[type(body).__module__]
    assert module.STEP is body_step                       # the body's one step function ...
    assert "STEP" in type(body).advance.__code__.co_names  # ... is what its Python advance calls
    spec = catalog.BODIES[name]
    if spec.step is not None:                             # a spec that names the step names this one
        assert spec.step is body_step
    assert spec.legged_pack is cls                        # the spec names the pack whose functions are declared


def test_the_support_refuses_a_time_step_that_is_not_the_bodys():
    body = _centipede("hybrid")
    c = np.zeros((body.n_segments, 3))
    R = np.tile(np.eye(3), (body.n_segments, 1, 1))
    with pytest.raises(ValueError, match="time step"):
        body.set_support(np.zeros(body.n_segments, bool), c, R, 2.0 * body.dt)
