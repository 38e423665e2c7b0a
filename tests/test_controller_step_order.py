"""The leg controller's step order is stated once (``controller.STEP_ORDER``) and both of its
implementations follow it: ``MyriapodController.step`` (the Python path, the reference) and
``compiled.controller_step`` (the fused path's port, without ``compiled.PYTHON_ONLY``).

Each implementation's calls are read from its source in execution order (the body's statements
top to bottom, an ``if``'s test before its branches) and each call that performs a stage is named
by the table below; the named sequence must be ``STEP_ORDER``.  Moving a stage in one of the two
functions only fails here (``test_a_stage_moved_in_one_place_fails`` checks that it does).  The
bit-for-bit equality of the two paths' results is tests/test_fused_walk.py's.
"""
from __future__ import annotations

import ast
import inspect
import textwrap

from bench_myriapoda.controllers.myriapod import compiled as CC
from bench_myriapoda.controllers.myriapod.controller import STEP_ORDER, MyriapodController

# the call that performs each stage, as each implementation spells it (``L.stance_ik_and_fk``: two stages)
PYTHON_CALLS = {
    "self.record_tracking": ("tracking",),
    "L.legs_forward_kinematics": ("forward_kinematics",),
    "self.antennae.step": ("antennae",),
    "self._sense_food": ("food",),
    "L.tips_touching": ("touching",),
    "self._switch_brain": ("brain",),
    "self._head_command": ("head",),
    "TG.segments_supported": ("supported",),
    "TG.targeter_step": ("targeter",),
    "TG.keep_clear_of_walls": ("walls",),
    "self._apply_body_wave": ("body_wave",),
    "SW.switcher_step": ("switcher",),
    "self._stop_legs_at_surfaces": ("stop_legs",),
    "SW.fix_stance_tips": ("stance_tips",),
    "LC.surface_touchdown_tips": ("touchdown",),
    "SW.stance_inverse_kinematics": ("stance_ik",),
    "self._legs_after_kinematics": ("knees_and_penetration",),
}
COMPILED_CALLS = {
    "numpy_sum": ("tracking",),
    "L.legs_forward_kinematics": ("forward_kinematics",),
    "AN.antennae_step": ("antennae",),
    "L.tips_touching": ("touching",),
    "_switch_brain": ("brain",),
    "_head_command": ("head",),
    "TG.segments_supported": ("supported",),
    "TG.targeter_step": ("targeter",),
    "TG.keep_clear_of_walls": ("walls",),
    "SW.switcher_step": ("switcher",),
    "LC.stop_swinging_legs": ("stop_legs",),
    "SW.fix_stance_tips": ("stance_tips",),
    "LC.surface_touchdown_tips": ("touchdown",),
    "L.stance_ik_and_fk": ("stance_ik", "forward_kinematics"),
    "LC.knees_inside_and_penetration": ("knees_and_penetration",),
}


def _calls_in_order(node: ast.AST):
    """The calls under ``node`` in execution order: a call's arguments before it, a statement's parts left
    to right, an ``if``'s test before its body and its ``else``."""
    for child in ast.iter_child_nodes(node):
        yield from _calls_in_order(child)
    if isinstance(node, ast.Call):
        yield node


def stages(source: str, table: dict[str, tuple[str, ...]]) -> list[str]:
    """The stages that the function in ``source`` performs, in order (``table``: call -> stages)."""
    fn = ast.parse(textwrap.dedent(source)).body[0]
    out = []
    for call in _calls_in_order(fn):
        out.extend(table.get(ast.unparse(call.func), ()))
    return out


def python_source() -> str:
    return inspect.getsource(MyriapodController.step)


def compiled_source() -> str:
    return inspect.getsource(CC.controller_step.py_func)


def test_the_python_step_runs_the_stages_in_the_stated_order():
    assert stages(python_source(), PYTHON_CALLS) == list(STEP_ORDER)


def test_the_compiled_step_runs_the_same_stages_in_the_same_order():
    assert set(CC.PYTHON_ONLY) <= set(STEP_ORDER)
    assert stages(compiled_source(), COMPILED_CALLS) == [s for s in STEP_ORDER if s not in CC.PYTHON_ONLY]


def test_every_stage_is_performed_by_one_named_call():
    named = {s for calls in PYTHON_CALLS.values() for s in calls}
    assert named == set(STEP_ORDER)
    assert {s for calls in COMPILED_CALLS.values() for s in calls} == set(STEP_ORDER) - set(CC.PYTHON_ONLY)


def test_a_stage_moved_in_one_place_fails():
    # the touchdown of the new STANCE tips moved before their placement, in the compiled step only
    src = compiled_source()
    a = "    SW.fix_stance_tips(entered, c_T, R_T, geom, angles, tips)\n"
    b = "    if collide:\n        LC.surface_touchdown_tips(entered, tips, kind, terr)\n"
    assert a in src and b in src
    moved = src.replace(a + b, b + a)
    assert moved != src
    assert stages(moved, COMPILED_CALLS) != [s for s in STEP_ORDER if s not in CC.PYTHON_ONLY]
    # the walls before the Targeter, in the Python step only
    src = python_source()
    lines = src.splitlines(keepends=True)
    i = next(k for k, ln in enumerate(lines) if "TG.targeter_step(" in ln)
    j = next(k for k, ln in enumerate(lines) if "if self.terr_walls[TK.H_NOBST] > 0" in ln)
    targeter, walls = lines[i:j], lines[j:j + 3]
    moved = "".join(lines[:i] + walls + targeter + lines[j + 3:])
    assert stages(moved, PYTHON_CALLS) != list(STEP_ORDER)
