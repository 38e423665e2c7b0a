"""No numba kernel takes more than 16 positional parameters (issue 30, item 5): a kernel's arguments travel
in a few named records (namedtuples: numba compiles one as a struct of its fields, and a body builds them
from its own arrays), as the rigid segment chain's (``bodies.rigid_chain``: ``Boxes``, ``Attachment``,
``World``, ``Coupling`` and a link element) and the fused legged path's (``bodies.legged_chunk``) do.

Every function of the package decorated with ``njit`` or ``jit`` is read from the source (AST), so a new
kernel is checked without being listed anywhere."""
from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "bench_myriapoda"
MAX_POSITIONAL = 16

# Kernels still wider than that, each with what it is; a new one fails the test, and one that is gone (or
# narrowed) fails it too, so the list only shrinks.  Empty since the last fourteen were packed (issue 30,
# item 5): the body step loops' arrays in namedtuple-ordered plain tuples, the inlined per-tet and per-point
# helpers' scalars in tuples of scalars.
KNOWN_WIDE: set[tuple[str, str]] = set()


def _is_kernel(fn: ast.FunctionDef) -> bool:
    for d in fn.decorator_list:
        f = d.func if isinstance(d, ast.Call) else d
        name = f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""
        if name in ("njit", "jit"):
            return True
    return False


def wide_kernels(root: Path = PACKAGE, limit: int = MAX_POSITIONAL) -> dict[tuple[str, str], int]:
    """(file relative to the package, kernel name) -> positional parameters, for the kernels above ``limit``."""
    out = {}
    for p in sorted(root.rglob("*.py")):
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef) and _is_kernel(node):
                n = len(node.args.posonlyargs) + len(node.args.args)
                if n > limit:
                    out[(p.relative_to(root).as_posix(), node.name)] = n
    return out


def test_the_scan_finds_a_wide_kernel(tmp_path):
    args = ", ".join(f"a{i}" for i in range(17))
    (tmp_path / "k.py").write_text(f"from numba import njit\n\n@njit(cache=True)\ndef wide({args}):\n    return a0\n\n"
                                   f"@njit\ndef narrow(a, b):\n    return a\n\ndef plain({args}):\n    return a0\n")
    assert wide_kernels(tmp_path) == {("k.py", "wide"): 17}


def test_no_kernel_takes_more_than_16_positional_parameters():
    found = wide_kernels()
    new = {k: n for k, n in found.items() if k not in KNOWN_WIDE}
    assert not new, f"kernels with more than {MAX_POSITIONAL} positional parameters (pack them): {new}"
    gone = KNOWN_WIDE - set(found)
    assert not gone, f"no longer wide: remove from KNOWN_WIDE: {sorted(gone)}"
