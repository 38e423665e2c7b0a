"""dt and the world are plain arguments of each body's one step (issue 42 item 2).

Every body model's step function has the form ``step(*records, world, dt, n_steps)``: the body's own records, then
the run's world (``world.world.StepWorld`` as a plain tuple, ``World.step_world``) and the time step, given by whoever
runs it (``Body.advance`` with the world and dt the runner built the body with; the fused legged walk with its own).
Checked here: statically, that no body kernel reads dt or gravity from a parameter vector again (no ``DT`` or
``GRAVITY`` index, nothing ``dt`` written into a ``phys``); that each spec's declared steps (``BodySpec.step``,
``BodySpec.legless_step``) take the world and dt last, before n_steps, and are what each built body's ``advance``
calls; and, running the lattice's steps, that the dt and the world the step is given are the ones it uses.
"""
from __future__ import annotations

import ast
import dataclasses
import inspect
import sys
from pathlib import Path

import numpy as np
import pytest

from bench_myriapoda import catalog
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import build_body
from bench_myriapoda.world.world import build_world

BODIES_DIR = Path(__file__).resolve().parents[1] / "bench_myriapoda" / "bodies"
# the index names a parameter vector held the time step and gravity under, before issue 42 item 2
BANNED_INDEX = {"DT", "GRAVITY"}


def _name(node) -> str | None:
    """``x`` of a Name x or an Attribute a.x, else None."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return None


def _targets(node) -> list:
    if isinstance(node, ast.Assign):
        return node.targets
    if isinstance(node, (ast.AugAssign, ast.AnnAssign)):
        return [node.target]
    return []


def _flat(target) -> list:
    if isinstance(target, (ast.Tuple, ast.List)):
        return [t for e in target.elts for t in _flat(e)]
    return [target]


def _mentions_dt(node) -> bool:
    return any(_name(n) == "dt" for n in ast.walk(node))


def offences(source: str) -> list[str]:
    """Where ``source`` keeps the time step or gravity in a parameter vector: a ``DT`` or ``GRAVITY`` index declared or
    subscripted, or a ``phys`` entry assigned from an expression that names ``dt``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        value = getattr(node, "value", None)
        # an index: a name given an int, or one of a layout unpacked from range(...)
        index_like = isinstance(value, ast.Constant) and type(value.value) is int or (
            isinstance(value, ast.Call) and _name(value.func) == "range")
        for target in (t for tt in _targets(node) for t in _flat(tt)):
            if index_like and _name(target) in BANNED_INDEX and not isinstance(target, ast.Subscript):
                found.append(f"line {node.lineno}: declares the index {_name(target)}")
            if isinstance(target, ast.Subscript) and _name(target.value) == "phys" and _mentions_dt(node.value):
                found.append(f"line {node.lineno}: writes dt into phys")
        if isinstance(node, ast.Subscript):
            index = node.slice
            names = [_name(index)] + ([_name(e) for e in index.elts] if isinstance(index, ast.Tuple) else [])
            if BANNED_INDEX & set(n for n in names if n):
                found.append(f"line {node.lineno}: reads {ast.unparse(node)}")
    return found


def test_the_static_check_finds_dt_in_a_parameter_vector():
    """The check itself: each way dt (or gravity) went into a body's parameters before is found."""
    assert offences("DT, R_N = range(2)\n")
    assert offences("GRAVITY = 0\n")
    assert not offences("GRAVITY = (0.0, -9.81, 0.0)\n")  # a default vector, not an index
    assert offences("dt = phys[DT]\n")
    assert offences("g = W.phys[K.GRAVITY]\n")
    assert offences("phys[3] = case.dt\n")
    assert offences("self.phys[i_dt] = dt\n")
    assert offences("carry(B, self.phys[K.DT])\n")
    assert not offences("r_n = phys[R_N]\nphys[MUSCLES_ON] = 1.0\nx = dt * v\n")


def test_no_body_kernel_reads_dt_or_gravity_from_a_parameter_vector():
    found = {}
    for path in sorted(BODIES_DIR.rglob("*.py")):
        bad = offences(path.read_text())
        if bad:
            found[str(path.relative_to(BODIES_DIR))] = bad
    assert found == {}, found


def _steps():
    """(body, which, function) of every step function the catalog's specs declare."""
    for name, spec in sorted(catalog.BODIES.items()):
        for which in ("step", "legless_step"):
            f = getattr(spec, which)
            if f is not None:
                yield name, which, f


def test_every_spec_declares_a_step_for_each_body_model_it_builds():
    for name, spec in catalog.BODIES.items():
        assert spec.step is not None, f"{name}: no BodySpec.step"
    # the two specs that build a legless body and a legged chain declare both steps
    for name in ("massspring", "fem"):
        assert catalog.BODIES[name].legless_step is not None, name
        assert catalog.BODIES[name].legless_step is not catalog.BODIES[name].step, name


@pytest.mark.parametrize("name,which,f", list(_steps()), ids=lambda v: v if isinstance(v, str) else "")
def test_a_step_takes_the_world_and_dt_as_its_last_arguments_before_n_steps(name, which, f):
    params = list(inspect.signature(getattr(f, "py_func", f)).parameters)
    assert params[-3:] == ["world", "dt", "n_steps"], (name, which, params)


@pytest.mark.parametrize("name", sorted(catalog.BODIES))
@pytest.mark.parametrize("creature,scenario,gait,legs", [("worm", "flat", "rectilinear", False),
                                                         ("centipede", "walk", None, True)])
def test_a_built_body_advances_through_its_declared_step(name, creature, scenario, gait, legs):
    spec = catalog.BODIES[name]
    body = build_body(resolve_case(creature, name, scenario, gait, overrides=["creature.segments=4"]))
    expected = spec.step if legs else (spec.legless_step or spec.step)
    module = sys.modules[type(body).__module__]
    called = [getattr(module, n) for n in type(body).advance.__code__.co_names if hasattr(module, n)]
    assert any(f is expected for f in called), (name, creature, type(body).__name__)
    # and hands it the world it was built in, as the step takes it
    assert "step_world" in type(body).advance.__code__.co_names


def _worm(dt=None):
    return resolve_case("worm", "massspring", "flat", "rectilinear", dt=dt, overrides=["creature.segments=4"])


def _advance(body, n):
    code = body.advance(0.0, n)
    return code, body.x.copy(), body.v.copy()


def test_the_step_uses_the_dt_it_is_given():
    """Two lattices built alike, one given twice the time step by its runner (its ``dt``, which ``advance`` passes
    to the step): they part after one step, and the one given 2 dt for n steps is the lattice built at 2 dt."""
    case = _worm()
    world = build_world(case)
    a, b = build_body(case, world), build_body(case, world)
    assert a.phys.tobytes() == b.phys.tobytes()
    b.dt = 2.0 * a.dt
    ca, xa, va = _advance(a, 20)
    cb, xb, vb = _advance(b, 20)
    assert ca == cb == (20, 0)
    assert not np.array_equal(xa, xb)
    c = build_body(_worm(2.0 * case.dt), world)  # built at 2 dt: the same parameters, so the same doubles
    assert c.phys.tobytes() == a.phys.tobytes()
    cc, xc, vc = _advance(c, 20)
    assert cc == (20, 0) and np.array_equal(xb, xc) and np.array_equal(vb, vc)


def test_the_step_uses_the_world_it_is_given():
    """The lattice given another world (its gravity halved) by its runner falls differently; the world's step record
    is its terrain and its scenario's gravity."""
    case = _worm()
    world = build_world(case)
    a, b = build_body(case, world), build_body(case, world)
    light = dataclasses.replace(world, scenario=dataclasses.replace(world.scenario,
                                                                    gravity_m_s2=0.5 * world.scenario.gravity_m_s2))
    assert light.step_world[1] == world.step_world[1] and light.step_world[2] is world.step_world[2]
    b.world = light
    _, xa, _ = _advance(a, 20)
    _, xb, _ = _advance(b, 20)
    assert not np.array_equal(xa, xb)
    assert build_world(case).step_world[0].tolist() == [0.0, -case.scenario.gravity_m_s2, 0.0]
