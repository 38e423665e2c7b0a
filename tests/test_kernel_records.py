"""No kernel takes or unpacks a positional tuple of more than 8 fields (issue 42, item 1): a kernel's inputs
travel in named records (namedtuples, which numba compiles as a struct of their fields, read by name as
``links.x``), not in packs a reader must count to know what field 19 is.

A static test over the package (AST, nothing imported or compiled), so a new kernel or pack is checked without
being listed anywhere.  What counts as a kernel: a function decorated with ``njit``/``jit`` (or
``numba.njit``), a function handed to ``register``/``register_link`` (the legged chunk's and the rigid chain's
implementations, inlined into kernels) and an ``@overload``'s implementation.  What it finds:

* in a kernel, an assignment (or ``for`` target) that unpacks more than 8 names at once (``a, b, ... = P``);
* in a kernel, a tuple literal of more than 8 elements (a pack built to pass on, or returned);
* in the Python code of the packages that hold kernels (``bodies``, ``controllers``, ``fused``,
  ``kinematics``, ``world``), inside a function, a tuple literal of more than 8 elements that is passed,
  assigned or returned (what a body builds to hand to its kernels); a tuple iterated over in place (a
  ``for`` over a table of rows) or written into an array (``r[:9] = ...``) is data, not a pack.

Module-level tuples are constant tables (lattice offsets, the ``range(n)`` layouts of a parameter vector's
named indices) and are not packs.  The kernels ``massspring.column_codegen`` writes at run time are not read.
"""
from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "bench_myriapoda"
MAX_FIELDS = 8
PACK_PACKAGES = ("bodies", "controllers", "fused", "kinematics", "world")
_KERNEL_DECORATORS = {"njit", "jit"}
_REGISTERS = {"register", "register_link"}

# Sites not converted yet, each (file, function, what) with how many times it occurs.  A ratchet: a new site fails
# the test, and so does a listed one that is gone (remove it here), so the list only shrinks.  Empty: every site
# the scan found on 1cefd33 is converted (issue 42 item 1).
NOT_YET_CONVERTED: Counter = Counter()


def _decorator_name(d: ast.expr) -> str:
    f = d.func if isinstance(d, ast.Call) else d
    return f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""


def _registered(tree: ast.Module) -> set[str]:
    """Names of the functions a module hands to ``register``/``register_link`` (compiled where inlined)."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and _decorator_name(node) in _REGISTERS:
            out |= {a.id for a in node.args[1:] if isinstance(a, ast.Name)}
    return out


def _functions(tree: ast.Module):
    """(function node, its dotted name, compiled?) for every function, outermost first."""
    registered = _registered(tree)

    def visit(body, prefix: str, compiled: bool):
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                names = {_decorator_name(d) for d in node.decorator_list}
                # an @overload's body runs in Python (typing); the implementation it returns is compiled
                inner = compiled or bool(names & _KERNEL_DECORATORS) or node.name in registered
                yield node, prefix + node.name, inner
                yield from visit(node.body, prefix + node.name + ".", inner or "overload" in names)
            elif isinstance(node, ast.ClassDef):
                yield from visit(node.body, prefix + node.name + ".", compiled)

    yield from visit(tree.body, "", False)


def _own_nodes(fn: ast.AST):
    """The nodes of fn's body, not those of functions nested in it (checked on their own)."""
    todo = list(ast.iter_child_nodes(fn))
    while todo:
        node = todo.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            continue
        yield node
        todo.extend(ast.iter_child_nodes(node))


def _data(fn: ast.AST) -> set[int]:
    """ids of the tuple literals in fn that are data, not packs: iterated over in place (``for row in (...)``,
    comprehensions), or values written into an array (``r[:9] = a, b, ...``)."""
    out = set()
    for node in _own_nodes(fn):
        if isinstance(node, (ast.For, ast.comprehension)):
            out |= {id(sub) for sub in ast.walk(node.iter) if isinstance(sub, ast.Tuple)}
        if isinstance(node, ast.Assign) and all(isinstance(t, ast.Subscript) for t in node.targets):
            out |= {id(node.value)} if isinstance(node.value, ast.Tuple) else set()
    return out


def positional_packs(root: Path = PACKAGE, limit: int = MAX_FIELDS) -> Counter:
    """Counter of (file relative to the package, function, "unpacks N" / "builds N") over the package."""
    found: Counter = Counter()
    for p in sorted(root.rglob("*.py")):
        rel = p.relative_to(root).as_posix()
        if rel.endswith("compile_plans_data.py"):
            continue
        tree = ast.parse(p.read_text(encoding="utf-8"))
        holds_packs = rel.split("/")[0] in PACK_PACKAGES
        for fn, name, compiled in _functions(tree):
            if not (compiled or holds_packs):
                continue
            data = set() if compiled else _data(fn)
            for node in _own_nodes(fn):
                if compiled and isinstance(node, (ast.Assign, ast.For, ast.AnnAssign, ast.AugAssign)):
                    targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                    for t in targets:
                        if isinstance(t, (ast.Tuple, ast.List)) and len(t.elts) > limit:
                            found[(rel, name, f"unpacks {len(t.elts)}")] += 1
                if (isinstance(node, ast.Tuple) and isinstance(node.ctx, ast.Load) and len(node.elts) > limit
                        and id(node) not in data):
                    found[(rel, name, f"builds {len(node.elts)}")] += 1
    return found


def test_the_scan_finds_packs_in_kernels_and_in_the_code_that_builds_them(tmp_path):
    a = ", ".join(f"a{i}" for i in range(9))
    small = ", ".join(f"a{i}" for i in range(8))
    (tmp_path / "bodies").mkdir()
    (tmp_path / "bodies" / "k.py").write_text(
        "from numba import njit\nimport numba\n\n"
        f"@njit(cache=True)\ndef unpacks(P):\n    {a} = P\n    return a0\n\n"
        f"@numba.njit\ndef small(P):\n    {small} = P\n    return ({small})\n\n"
        f"def impl(P):\n    return ({a})\n\nregister(Cls, impl)\n\n"
        f"def pack(self):\n    return ({a})\n\n"
        f"def table(r):\n    for row in (({a}),):\n        pass\n    r[:9] = {a}\n\n"
        f"ROWS = ({a})\n")
    (tmp_path / "report.py").write_text(f"def row(x):\n    return ({a})\n")  # not a kernel package
    assert positional_packs(tmp_path) == Counter({("bodies/k.py", "unpacks", "unpacks 9"): 1,
                                                  ("bodies/k.py", "impl", "builds 9"): 1,
                                                  ("bodies/k.py", "pack", "builds 9"): 1})


def test_no_kernel_takes_or_unpacks_a_positional_tuple_of_more_than_8_fields():
    found = positional_packs()
    new = {k: n for k, n in found.items() if n > NOT_YET_CONVERTED.get(k, 0)}
    assert not new, (f"positional packs of more than {MAX_FIELDS} fields (use a named record, a namedtuple read "
                     f"by field name): {new}")
    gone = {k: n for k, n in NOT_YET_CONVERTED.items() if found.get(k, 0) < n}
    assert not gone, f"converted: remove from NOT_YET_CONVERTED: {gone}"
