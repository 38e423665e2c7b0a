"""The package's import graph: bodies and controllers never import each other, and no module
imports itself through a loop (ARCHITECTURE.md; issue "controllers as a layer of their own").

Every ``import`` / ``from ... import`` statement counts, at module level or inside a function."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "bench_myriapoda"


def module_name(path: Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def imports_of(path: Path, modules: set[str]) -> set[str]:
    """The package's modules that ``path`` imports (a package import counts as its __init__;
    importing one's own ancestor package, which Python has initialised first, is not an edge)."""
    me = module_name(path)
    package = me if path.name == "__init__.py" else me.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[:len(base) - (node.level - 1)]
                root = ".".join(base + ([node.module] if node.module else []))
            else:
                root = node.module or ""
            # ``from pkg import name``: the submodule when ``name`` is one, else pkg itself
            subs = [f"{root}.{a.name}" for a in node.names]
            names = [n for n in subs if n in modules]
            if len(names) < len(subs):
                names.append(root)
        else:
            continue
        for name in names:
            # the longest prefix that is one of our modules
            parts = name.split(".")
            for k in range(len(parts), 0, -1):
                cand = ".".join(parts[:k])
                if cand in modules:
                    if cand != me and not me.startswith(cand + "."):
                        found.add(cand)
                    break
    return found


def import_graph() -> dict[str, set[str]]:
    paths = sorted(PACKAGE.rglob("*.py"))
    modules = {module_name(p) for p in paths}
    return {module_name(p): imports_of(p, modules) for p in paths}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in graph:
        if v not in index:
            visit(v)
    return out


def test_the_graph_sees_known_imports():
    g = import_graph()
    assert "bench_myriapoda.kinematics.legs" in g["bench_myriapoda.controllers.myriapod.switcher"]
    assert "bench_myriapoda.core.protocols" in g["bench_myriapoda.bodies.massspring.body"]
    assert "bench_myriapoda.bodies.fem.body" in g["bench_myriapoda.catalog"]


def test_cycle_finder_finds_a_loop():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


@pytest.mark.parametrize("src, dst", [("bodies", "controllers"), ("controllers", "bodies")])
def test_bodies_and_controllers_never_import_each_other(src, dst):
    bad = [(m, i) for m, imps in import_graph().items() if m.startswith(f"bench_myriapoda.{src}")
           for i in imps if i.startswith(f"bench_myriapoda.{dst}")]
    assert not bad, f"{src}/ imports {dst}/: {bad}"


def test_the_package_has_no_import_cycle():
    assert cycles(import_graph()) == []


# --------------------------------------------------------------------------- layers (issue 30, item 7)

# The package's layers, lowest first: a module may import its own layer and the ones below, never one above,
# at module level or inside a function.  One name per top-level module or subpackage of bench_myriapoda.
LAYERS = (
    ("core",),
    ("jit",),
    ("kinematics", "world"),
    ("bodies", "controllers"),
    ("catalog", "fused", "metrics", "reference"),
    ("harness",),
    ("validation",),
    ("report",),
    ("api",),
    ("cli", "__init__"),
)
LAYER_OF = {name: level for level, names in enumerate(LAYERS) for name in names}

# Upward imports that remain, each with what removes it; a new one fails the test, and a listed one that is
# gone fails it too (so the list only shrinks).  Empty since issue 30 items 1 and 7 (the mesh-file check in
# core/mesh_files.py, the work-precision diagrams drawn in report/).
KNOWN_UPWARD: set[tuple[str, str]] = set()


def layer(module: str) -> int:
    parts = module.split(".")
    return LAYER_OF["__init__" if len(parts) == 1 else parts[1]]


def upward_imports(graph: dict[str, set[str]]) -> set[tuple[str, str]]:
    return {(m, i) for m, imps in graph.items() for i in imps if layer(i) > layer(m)}


def test_layers_name_every_top_level_module():
    tops = {m.split(".")[1] if "." in m else "__init__" for m in import_graph()}
    assert tops <= set(LAYER_OF), tops - set(LAYER_OF)


def test_the_layer_check_finds_an_import_inside_a_function(tmp_path):
    src = tmp_path / "bench_myriapoda" / "core"
    src.mkdir(parents=True)
    (src / "x.py").write_text("def f():\n    from ..harness import runner\n")
    modules = {"bench_myriapoda.core.x", "bench_myriapoda.harness.runner"}
    global PACKAGE
    saved, PACKAGE = PACKAGE, tmp_path / "bench_myriapoda"
    try:
        found = imports_of(src / "x.py", modules)
    finally:
        PACKAGE = saved
    assert upward_imports({"bench_myriapoda.core.x": found}) == {("bench_myriapoda.core.x",
                                                                "bench_myriapoda.harness.runner")}


def test_no_import_runs_up_the_layers():
    found = upward_imports(import_graph())
    assert found - KNOWN_UPWARD == set(), "imports up the layers (LAYERS): " + repr(sorted(found - KNOWN_UPWARD))
    assert KNOWN_UPWARD - found == set(), "gone: remove from KNOWN_UPWARD: " + repr(sorted(KNOWN_UPWARD - found))


# --------------------------------------------------------------------------- private attributes across packages

def private_names_read(tree: ast.AST) -> set[str]:
    """Every ``obj._name`` read in ``tree`` where ``obj`` is not ``self`` / ``cls`` and ``_name`` starts with one
    underscore: a read of some other object's private state."""
    out = set()
    for node in ast.walk(tree):
        if not isinstance(node, ast.Attribute) or not isinstance(node.ctx, ast.Load):
            continue
        if not node.attr.startswith("_") or node.attr.startswith("__"):
            continue
        if isinstance(node.value, ast.Name) and node.value.id in ("self", "cls"):
            continue
        out.add(node.attr)
    return out


def package_of(module: str) -> str:
    """``bench_myriapoda.X``, except that each body model's subpackage is a package of its own
    (``bench_myriapoda.bodies.fem``, issue 42): one body reading another's private state is a read across
    packages, as a harness module reading a body's is.  The shared modules of ``bodies/`` stay ``bench_myriapoda.bodies``."""
    parts = module.split(".")
    if len(parts) >= 3 and parts[1] == "bodies" and (PACKAGE / "bodies" / parts[2]).is_dir():
        return ".".join(parts[:3])
    return ".".join(parts[:2])


def defined_private_names() -> dict[str, set[str]]:
    """Per package (``bench_myriapoda.X``): the ``_names`` its modules define (functions, classes, assignments,
    attributes set on ``self``)."""
    out: dict[str, set[str]] = {}
    for p in PACKAGE.rglob("*.py"):
        names = out.setdefault(package_of(module_name(p)), set())
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.ClassDef, ast.AsyncFunctionDef)):
                names.add(node.name)
            elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                names.add(node.id)
            elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
                names.add(node.attr)
            elif isinstance(node, ast.alias):
                names.add(node.asname or node.name.split(".")[-1])
    return out


def cross_package_private_reads() -> set[tuple[str, str]]:
    """(module, ``_name``) for a private attribute read in a module of one package (``bench_myriapoda.X``) that
    only other packages define: another package's private state.  Reads of a package's own private names
    (a sibling module's helper, a class's own attribute on another instance) are allowed."""
    defined = defined_private_names()
    found = set()
    for p in PACKAGE.rglob("*.py"):
        me = module_name(p)
        own = defined.get(package_of(me), set())
        for name in private_names_read(ast.parse(p.read_text(encoding="utf-8"))):
            if name not in own and any(name in names for pkg, names in defined.items() if pkg != package_of(me)):
                found.add((me, name))
    return found


# Private reads that remain, each with what removes it; a new one fails the test, and a listed one that is gone
# fails it too (so the list only shrinks).
KNOWN_PRIVATE: set[tuple[str, str]] = set()   # empty since issue 30 item 3: a legged body publishes its fused
# pack (bodies.legged_chunk) and the FEM system its rotation workspace (FEMSystem.q_ws); and since issue 42, with
# each body subpackage a package of its own, the FEM system publishes the rest of what the hybrid's links step
# with (FEMSystem.F_work, H_work, inc_ptr, inc_off)


def test_each_body_subpackage_is_a_package_of_its_own():
    assert package_of("bench_myriapoda.bodies.hybrid.body") == "bench_myriapoda.bodies.hybrid"
    assert package_of("bench_myriapoda.bodies.fem") == "bench_myriapoda.bodies.fem"
    assert package_of("bench_myriapoda.bodies.scene") == "bench_myriapoda.bodies"
    assert package_of("bench_myriapoda.harness.runner") == "bench_myriapoda.harness"


def test_the_private_read_check_finds_one():
    tree = ast.parse("def f(body, self, cls):\n    return body._state + self._mine + cls._ours + body.__class__\n")
    assert private_names_read(tree) == {"_state"}


def test_no_private_attribute_is_read_across_packages():
    found = cross_package_private_reads()
    assert found - KNOWN_PRIVATE == set(), "private attributes read across packages: " + repr(sorted(found - KNOWN_PRIVATE))
    assert KNOWN_PRIVATE - found == set(), "gone: remove from KNOWN_PRIVATE: " + repr(sorted(KNOWN_PRIVATE - found))


# --------------------------------------------------------------------------- the results store

STORE = "bench_myriapoda.harness.store"


def store_access(tree: ast.AST) -> set[str]:
    """What in ``tree`` talks to a database directly: ``import sqlite3``, a ``.execute`` / ``.executescript`` /
    ``read_sql`` call, or a string that starts as an SQL statement (upper-case keywords, as every query here is written)."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
            found |= {f"import {n}" for n in names if n.split(".")[0] == "sqlite3"}
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and node.func.attr in ("execute", "executemany", "executescript", "read_sql", "read_sql_query"):
            if not (isinstance(node.func.value, ast.Name) and node.func.value.id == "engine"):  # matplotlib's
                found.add(f".{node.func.attr}()")
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and node.value.lstrip().startswith(("SELECT ", "INSERT ", "CREATE TABLE", "UPDATE ", "DELETE ")):
            found.add(f"SQL {node.value.strip()[:30]!r}")
    return found


def test_the_store_check_finds_sql():
    tree = ast.parse("import sqlite3\ndef f(con):\n    return con.execute('SELECT 1')\n")
    assert store_access(tree) == {"import sqlite3", ".execute()", "SQL 'SELECT 1'"}


def test_only_the_store_module_talks_to_the_database():
    bad = {module_name(p): sorted(found) for p in PACKAGE.rglob("*.py")
           if module_name(p) != STORE and (found := store_access(ast.parse(p.read_text(encoding="utf-8"))))}
    assert bad == {}, f"store access outside {STORE}: {bad}"


# --------------------------------------------------------------------------- the legged record (issue 30, item 6)

def test_harness_and_metrics_never_import_a_controller():
    # they read a legged controller through core.leg_timeline's records, whichever controller it is
    bad = [(m, i) for m, imps in import_graph().items()
           if m.startswith(("bench_myriapoda.harness", "bench_myriapoda.metrics"))
           for i in imps if i.startswith("bench_myriapoda.controllers")]
    assert not bad, f"harness/ or metrics/ imports controllers/: {bad}"


def controller_reads(tree: ast.AST) -> set[str]:
    """Attributes read of a controller in ``tree``: ``controller.X``, ``self.controller.X``, ``ctrl.X`` / ``c.X``
    where ``ctrl`` / ``c`` was assigned from a controller."""
    aliases = {"controller"}
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Attribute) and node.value.attr == "controller":
            aliases |= {t.id for t in node.targets if isinstance(t, ast.Name)}
    out = set()
    for node in ast.walk(tree):
        if not isinstance(node, ast.Attribute) or not isinstance(node.ctx, ast.Load):
            continue
        v = node.value
        if (isinstance(v, ast.Name) and v.id in aliases) or (isinstance(v, ast.Attribute) and v.attr == "controller"):
            out.add(node.attr)
    return out


def test_the_controller_read_check_finds_one():
    tree = ast.parse("def f(self, controller):\n    ctrl = self.controller\n"
                     "    return controller.a, self.controller.b, ctrl.c, self.body.d\n")
    assert controller_reads(tree) == {"a", "b", "c"}


def test_the_legged_harness_reads_only_the_declared_records():
    # harness/legged.py reads of a controller only what core.leg_timeline.LeggedController declares
    from bench_myriapoda.core.leg_timeline import LeggedController
    declared = set(LeggedController.__annotations__) | {n for n in vars(LeggedController) if not n.startswith("_")}
    found = controller_reads(ast.parse((PACKAGE / "harness" / "legged.py").read_text(encoding="utf-8")))
    assert found, "the check sees no read at all: it no longer finds the controller"
    assert found <= declared, f"harness/legged.py reads undeclared controller attributes: {sorted(found - declared)}"
