"""Bodies are closed (issue 42, item 4): no module outside ``bodies/<name>/`` and ``catalog.py`` names a body model
or imports from a specific body subpackage; what the rest of the package needs of a body (masses, cost
estimates, benchmark scenes, references) is declared in its ``BodySpec`` or published by the body.

A module names a body model when its code (docstrings and comments are prose and do not count) holds a string
that is a body's name or starts with one and a dash (a throughput-suite entry such as ``"fem-worm"``), imports
from ``bench_myriapoda.bodies.<name>``, or reads one of a body's internals (``BODY_INTERNALS``) off an object.
The generated compile data (``jit/compile_plans.json``) is data, not a module, and is not read.  What remains is listed in
``KNOWN_NAMING`` with what removes it: a new one fails the test and a listed one that is gone fails it too, so
the list only shrinks (a ratchet: this is the state at issue 42's first stage, not the goal).
"""
from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "bench_myriapoda"
BODY_PACKAGES = frozenset(p.name for p in (PACKAGE / "bodies").iterdir()
                          if p.is_dir() and (p / "__init__.py").is_file())
EXCLUDED = {"catalog.py"}
# attributes that only a body model has (its own geometry and sub-systems), read off another object
BODY_INTERNALS = frozenset({"layout", "rigid", "fem", "lattice", "system", "free", "stiffness"})

# What still names a body outside its subpackage, each with what removes it (issue 42).
KNOWN_NAMING: set[tuple[str, str]] = {
    # issue 42: the scene's kinds of surface are named after the bodies that draw them; each body should
    # declare its own kinds (and styles) instead
    ("bodies/scene.py", "'fem-block-surface'"),
    ("bodies/scene.py", "'fem-surface'"),
    # issue 42: the segment frames' polar decomposition is the FEM kernels' SVD; it moves to a shared kernel
    # module with the SVD (the compile plans name it, so they are re-recorded with it)
    ("bodies/segment_frames.py", "import fem.kernels"),
    # issue 42: the throughput suite's and the peers' scenes are body-specific benchmarks; each body should
    # publish its own (BodySpec) and the suite list them
    ("harness/peers.py", "'massspring'"),
    ("harness/peers.py", "f'ours:fem-chain-'"),
    ("harness/peers.py", "'ours:massspring-snake'"),
    ("harness/peers.py", "import fem.system"),
    ("harness/throughput_suite.py", "'fem'"),
    ("harness/throughput_suite.py", "'fem-centipede'"),
    ("harness/throughput_suite.py", "'fem-chain'"),
    ("harness/throughput_suite.py", "'fem-worm'"),
    ("harness/throughput_suite.py", "'hybrid'"),
    ("harness/throughput_suite.py", "'hybrid-centipede'"),
    ("harness/throughput_suite.py", "'hybrid-centipede-python'"),
    ("harness/throughput_suite.py", "'hybrid-chain'"),
    ("harness/throughput_suite.py", "'massspring'"),
    ("harness/throughput_suite.py", "'massspring-centipede'"),
    ("harness/throughput_suite.py", "'massspring-snake'"),
    ("harness/throughput_suite.py", "import fem.mesh"),
    ("harness/throughput_suite.py", "import fem.system"),
    ("harness/throughput_suite.py", ".fem"),
    ("harness/throughput_suite.py", ".free"),
    ("harness/throughput_suite.py", ".rigid"),
    ("harness/throughput_suite.py", ".system"),
    # issue 42: the worker-cost probe's case ("the cheapest kernels to load") should be declared by a body
    ("harness/worker_costs.py", "'massspring'"),
}


def _docstrings(tree: ast.AST) -> set[int]:
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body \
                and isinstance(node.body[0], ast.Expr) and isinstance(node.body[0].value, ast.Constant):
            out.add(id(node.body[0].value))
    return out


def _names_a_body(text: str) -> bool:
    return text in BODY_PACKAGES or any(text.startswith((f"{b}-", f"ours:{b}-")) for b in BODY_PACKAGES)


def body_naming(tree: ast.AST, module: str) -> set[str]:
    """What in ``tree`` (the module ``module``, dotted) names a body model: ``import <body>.<module>``, a string
    (repr) or an f-string's literal part (``f'...'``), or ``.<internal>``."""
    docs = _docstrings(tree)
    docs |= {id(v) for node in ast.walk(tree) if isinstance(node, ast.JoinedStr) for v in node.values}  # seen whole
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            mod = node.module or ""
            if node.level:
                mod = ".".join(module.split(".")[:-node.level] + ([mod] if mod else []))
            parts = mod.split(".")
            if len(parts) >= 3 and parts[1] == "bodies" and parts[2] in BODY_PACKAGES:
                found.add("import " + ".".join(parts[2:]))
            elif mod == "bench_myriapoda.bodies":
                found |= {f"import {a.name}" for a in node.names if a.name in BODY_PACKAGES}
        elif isinstance(node, ast.Import):
            for a in node.names:
                parts = a.name.split(".")
                if len(parts) >= 3 and parts[1] == "bodies" and parts[2] in BODY_PACKAGES:
                    found.add("import " + ".".join(parts[2:]))
        elif isinstance(node, ast.JoinedStr):
            found |= {"f" + repr(v.value) for v in node.values
                      if isinstance(v, ast.Constant) and isinstance(v.value, str) and _names_a_body(v.value)}
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docs:
            if _names_a_body(node.value):
                found.add(repr(node.value))
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load) and node.attr in BODY_INTERNALS \
                and not (isinstance(node.value, ast.Name) and node.value.id in ("self", "cls")):
            found.add("." + node.attr)
    return found


def body_naming_outside_bodies() -> set[tuple[str, str]]:
    out = set()
    for p in sorted(PACKAGE.rglob("*.py")):
        rel = p.relative_to(PACKAGE)
        if (rel.parts[0] == "bodies" and len(rel.parts) > 2) or rel.as_posix() in EXCLUDED:
            continue
        module = ".".join(("bench_myriapoda",) + rel.with_suffix("").parts)
        tree = ast.parse(p.read_text(encoding="utf-8"))
        out |= {(rel.as_posix(), what) for what in body_naming(tree, module)}
    return out


def test_the_body_naming_check_finds_each_kind():
    tree = ast.parse('"""A module about the fem body."""\nfrom ..bodies.fem.system import FEMSystem\n'
                     'from ..bodies import hybrid\nNAMES = ("massspring", "fem-worm", "pointchain")\n'
                     'def f(body, self, n):\n    """On massspring."""\n'
                     '    return body.rigid.mass, self.fem, f"ours:fem-chain-{n}"\n')
    found = body_naming(tree, "bench_myriapoda.harness.x")
    assert found == {"import fem.system", "import hybrid", "'massspring'", "'fem-worm'", ".rigid",
                     "f'ours:fem-chain-'"}


def test_every_body_subpackage_is_seen():
    assert {"fem", "hybrid", "massspring"} <= BODY_PACKAGES


def test_no_module_outside_a_body_names_a_body_model():
    found = body_naming_outside_bodies()
    assert found - KNOWN_NAMING == set(), "names a body model outside bodies/<name>/: " + repr(sorted(found - KNOWN_NAMING))
    assert KNOWN_NAMING - found == set(), "gone: remove from KNOWN_NAMING: " + repr(sorted(KNOWN_NAMING - found))


def test_the_specs_declare_what_the_harness_and_validation_read():
    """What moved out of the harness and validation into the bodies' specs: the scheduler's per-step costs and
    the throughput suite's scenes, and the hanging comparison's bodies, masses, pieces and time steps."""
    from bench_myriapoda.core import registry

    registry.load_all()
    for name in ("massspring", "fem", "hybrid"):
        spec = registry.BODIES[name]
        assert set(spec.step_cost_s) == {False, True} and all(v > 0 for v in spec.step_cost_s.values())
        assert spec.suite_scenes and all(entry.startswith(f"{name}-") for entry, _ in spec.suite_scenes.values())
    assert registry.BODIES["fem"].hanging_bar is not None and registry.BODIES["hybrid"].hanging_bar is not None
    assert registry.BODIES["massspring"].hanging_bar is None
    from bench_myriapoda.validation.cross_body import hanging_pair

    assert hanging_pair() == ("fem", "hybrid")  # the hanging comparison's pair, found through the specs
