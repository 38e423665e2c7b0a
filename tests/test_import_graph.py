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
