"""Bodies are closed (issue 42, item 4): no module outside ``bodies/<name>/`` and ``catalog.py`` names a body model
or imports from a specific body subpackage; what the rest of the package needs of a body (masses, cost
estimates, benchmark scenes, references) is declared in its ``BodySpec`` or published by the body.

A module names a body model when its code (docstrings and comments are prose and do not count) holds a string
that is a body's name or starts with one and a dash (a throughput-suite entry such as ``"fem-worm"``), imports
from ``bench_myriapoda.bodies.<name>``, or reads one of a body's internals (``BODY_INTERNALS``) off an object.
The generated compile data (``jit/compile_plans.json``) is data, not a module, and is not read.  What remains would
be listed in ``KNOWN_NAMING`` with what removes it: a new one fails the test and a listed one that is gone fails it
too, so the list only shrinks (a ratchet; empty since issue 42 item 4).
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

# What still names a body outside its subpackage, each with what removes it (issue 42).  Empty since issue 42
# item 4: the scene's surface kinds are the bodies' (BodySpec.surface_kinds), the SVD is a shared kernel module
# (bodies/svd_kernels.py), and the throughput suite's, the peers' and the worker-cost probe's scenes are published
# by the bodies (BodySpec.benchmarks).  A new naming fails the test.
KNOWN_NAMING: set[tuple[str, str]] = set()


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


# The entry names of the throughput suite and the peers as regress_history stores them: the history compares by
# name, so publishing the scenes from the bodies (BodySpec.benchmarks) must keep every one.
SUITE_ENTRIES = {"massspring-snake", "fem-chain", "fem-worm", "hybrid-chain", "hybrid-centipede",
                 "hybrid-centipede-python", "massspring-centipede", "fem-centipede", "rigid-boxes"}
PEER_ENTRIES = ["peer:mujoco-flex-816", "ours:fem-chain-816", "peer:mujoco-flex-2754", "ours:fem-chain-2754",
                "peer:pyelastica-snake", "ours:massspring-snake"]


def test_the_suite_and_the_peers_list_the_bodies_published_entries_under_their_old_names():
    from bench_myriapoda.harness import peers as P
    from bench_myriapoda.harness import throughput_suite as TS

    assert set(TS.SUITE) == SUITE_ENTRIES
    entries = P.peer_entries()
    assert list(entries) == PEER_ENTRIES  # each peer, then ours of its group
    assert P.peer_pairs(entries) == {"peer:mujoco-flex-816": "ours:fem-chain-816",
                                     "peer:mujoco-flex-2754": "ours:fem-chain-2754",
                                     "peer:pyelastica-snake": "ours:massspring-snake"}
    # ours of the snake group is the regress entry's own scene, at the snake's own time step
    from bench_myriapoda.bodies.massspring import benchmarks as MB
    from bench_myriapoda.core.config import resolve_case

    snake = entries["ours:massspring-snake"]
    assert snake.dt == resolve_case("snake", "massspring", "flat").dt and snake.elements == 50
    assert MB.BENCHMARKS.peers[0].case is MB.SNAKE
    assert set(TS.scaling_cases()) == {"snake", "centipede"}


def test_the_worker_cost_probe_takes_the_case_a_body_declares():
    from bench_myriapoda.harness import worker_costs as W

    assert W.probe_case() == ("worm", "massspring", "flat")


def test_each_kind_of_scene_surface_has_one_style():
    """The animations read the styles from the specs and the shared kinds (report.scene_style): a kind two bodies
    declare must be drawn alike, and no body redeclares a shared kind."""
    from bench_myriapoda.bodies import scene as SC
    from bench_myriapoda.core import registry
    from bench_myriapoda.report.scene_style import surface_style

    registry.load_all()
    seen = {}
    for name, spec in registry.BODIES.items():
        assert spec.surface_kinds, name
        for kind, style in spec.surface_kinds.items():
            assert kind not in SC.SHARED_SURFACE_KINDS
            assert seen.setdefault(kind, style) == style, kind
            assert surface_style(kind) == style
    assert surface_style(SC.RIGID_BOX).edges_in_face_color
    assert surface_style("no-such-kind").color == "#aaaaaa"
