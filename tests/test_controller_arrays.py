"""The fused walk's controller arrays by name (issue 42 item 1): ``compiled.ControllerState.pack`` hands
``controller_step`` the controller's own arrays as a plain tuple in ``compiled.ControllerArrays``' field order,
read there by name (``ControllerArrays(*A)``).  The pack is assembled part by part with getters (for speed), so
this checks, field by field, that each position holds the array its name says, with and without antennae.
Python only: nothing is compiled here (tests/test_fused_walk.py runs the kernels, bit for bit)."""
from __future__ import annotations

import numpy as np
import pytest

from bench_myriapoda.controllers.myriapod import compiled as CC
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import Creature

# ControllerArrays' fields that are the controller's (or its antennae's) attribute of another name
CONTROLLER_ATTRIBUTE = {"O": "_O", "M": "_M", "prev_angles": "_prev_angles", "stopped": "_stopped"}
ANTENNA_ATTRIBUTE = {"ant_params": "params", "ant_f": "f"}


def _controller(antennae: bool):
    sets = [] if antennae else ["antennae.enabled=false"]
    case = resolve_case("centipede", "massspring", "walk", overrides=["creature.segments=6", *sets])
    return Creature(case, fused=True).controller


@pytest.mark.parametrize("antennae", [True, False])
def test_pack_puts_every_named_array_at_its_field(antennae):
    c = _controller(antennae)
    assert (c.antennae is not None) == antennae
    cs = CC.ControllerState(c)
    A = cs.pack()
    assert type(A) is tuple and len(A) == len(CC.ControllerArrays._fields)  # plain, for the dispatcher
    a = CC.ControllerArrays(*A)
    for f in CC.ControllerArrays._fields[:len(CC._OWN)]:
        assert getattr(a, f) is getattr(c, CONTROLLER_ATTRIBUTE.get(f, f)), f
    times, speed, rate = c.schedule
    for got, want in zip((a.sched_t, a.sched_speed, a.sched_rate), (times, speed, rate)):
        np.testing.assert_array_equal(got, want)
    for f in CC.AntennaArrays._fields:
        if antennae:
            assert getattr(a, f) is getattr(c.antennae, ANTENNA_ATTRIBUTE.get(f, f)), f
        else:
            assert getattr(a, f) is getattr(CC.AntennaArrays(*cs._ant), f), f
    assert a.tip_phi is cs.tip_phi and a.terr_walls is c.terr_walls and a.seg_half is c.seg_half
    # the positions a caller that does not name the tuple reads
    for f in ("states", "tips", "kinematic", "c_T", "R_T", "contact"):
        assert A[getattr(CC, "A_" + f.upper())] is getattr(a, f), f
