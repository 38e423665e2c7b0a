"""Generator of ``column_loop.py``: the cube lattice's two column loops written out spring by spring.

The step kernel's column loops (``kernels._column_forces_flat``) compute the rest length and force of all 18
spring families of a face (pass 1, ``lattice.CUBE_FAMILIES``) and then the 12 force sums of a face (pass 2,
``lattice.CUBE_PLAN``).  Written as 18 and 12 calls of inlined helpers taking each family's row or corner's
plan as a constant tuple, the kernel took about 17 CPU s to compile: numba re-ran its front end on the
helpers at each call and deep-copied their blocks (the branches of ``a if c else b``) with the whole scope,
then reconstructed SSA form and typed the literal-typed integer arithmetic of every call.  The generated
loops hold the same floating-point operations in the same order with the tables' numbers written in: no
helper calls, no tuple indexing, every integer offset a uint64 variable made once before the loop (a
literal per offset would be typed one by one), every name assigned once, and ``lane_select.select``
instead of a branch, so numba types and lowers them as straight-line code.

Regenerate after changing ``lattice.CUBE_FAMILIES`` or ``CUBE_PLAN`` (the kernels refuse to import a file made
from other tables)::

    python3 -m bench_myriapoda.bodies.massspring.column_codegen

``tests/test_massspring_kernels.py`` checks that the checked-in file is what ``render()`` gives today.
The file is a real module rather than an ``exec``'d string so that numba's on-disk cache, keyed by the
function's source file, holds it.
"""
from __future__ import annotations

import sys
from pathlib import Path

from .lattice import AXIAL, CROSS, CUBE_FAMILIES, CUBE_PLAN, PAR_D, PAR_K, PAR_L0, PAR_LC

TARGET = Path(__file__).with_name("column_loop.py")

AXES = "xyz"


def _param(r: int) -> str:
    """The flat index of param row r's element u."""
    return f"p{r} + u" if r else "u"


def _node(c: int, s: int) -> str:
    """Suffix of the node of corner c on face u + s."""
    return f"{c}{'n' if s else ''}"


def render() -> str:
    """The source text of ``column_loop.py`` for today's ``CUBE_FAMILIES``."""
    fams = CUBE_FAMILIES
    n_fam = len(fams)
    out = []
    w = out.append
    w('"""The cube lattice\'s column loops, spring by spring and term by term (GENERATED: do not edit).')
    w("")
    w("Made by ``column_codegen.py`` from ``lattice.CUBE_FAMILIES`` and ``CUBE_PLAN``; regenerate with")
    w("``python3 -m bench_myriapoda.bodies.massspring.column_codegen`` (a test checks that this file is current).")
    w("Each spring's operations are those of the per-family kernels ``kernels.family_rest_lengths`` and")
    w("``family_spring_forces``, in their order; see ``family_springs_chunk`` and ``node_sums_chunk``.")
    w('"""')
    w("import math")
    w("")
    w("import numpy as np")
    w("from numba import njit")
    w("")
    w("from .lane_select import select")
    w("")
    w("# the tables this file was generated from (``lattice.CUBE_FAMILIES``, ``lattice.CUBE_PLAN``)")
    w("CUBE_FAMILIES = (")
    for q in range(0, n_fam, 5):
        w("    " + " ".join(f"{tuple(r)!r}," for r in fams[q:q + 5]))
    w(")")
    w("CUBE_PLAN = (")
    for terms in CUBE_PLAN:
        w("    (" + " ".join(f"{tuple(t)!r}," for t in terms[:5]))
        w("     " + " ".join(f"{tuple(t)!r}," for t in terms[5:]) + "),")
    w(")")
    w("")
    w("")
    w('@njit(cache=True, error_model="numpy", inline="always")')
    w("def family_springs_chunk(xf, vf, dim, pf, ps, st, fs, gq, row, t0, t1):")
    w('    """Pass 1 of ``kernels._column_forces_flat`` for the faces t0 <= t < t1 (one chunk): spring t of each')
    w("    cube family q (``CUBE_FAMILIES[q]`` = (a, b, shift, kind, ca, cb)), its rest length [m] and its force")
    w("    f u [N], written to gq[(3 q + e) row + 1 + t - t0] for the axes e (gq: the chunk buffer, row: its row")
    w("    length).  xf, vf: the (3, 5, stride) corner-major positions [m] and velocities [m/s] taken flat (axis")
    w("    stride ``dim``); pf: the families' params (4, 18, stride) flat (ps = stride); st, fs: the fibre")
    w("    stretches by corner row and the face scales (row 0 of fs, read at t + 1 too).  Springs past a family's")
    w("    last face get what their zero params give (the caller overwrites the one a real node reads).  dim, ps,")
    w("    row: uint64, as every index here (numba tests a signed index for wrap-around); the offsets are made")
    w("    once, before the loop, as uint64 sums (a literal per offset would be typed one by one).")
    w('    """')
    w("    dim2 = dim + dim")
    w("    one = np.uint64(1)")
    w("    # corner row c of a flat (.., stride) array starts at c ps")
    w("    r1 = ps")
    w("    r2 = r1 + ps")
    w("    r3 = r2 + ps")
    needed = []
    for q, (_a, _b, _s, kind, _ca, _cb) in enumerate(fams):
        needed += [PAR_K * n_fam + q, PAR_D * n_fam + q]
        if kind != CROSS:
            needed.append(PAR_L0 * n_fam + q)
        if kind != AXIAL:
            needed.append(PAR_LC * n_fam + q)
    w(f"    # params row r (= PAR * {n_fam} + q: PAR_K {PAR_K}, PAR_D {PAR_D}, PAR_L0 {PAR_L0}, PAR_LC {PAR_LC})"
      " starts at r ps")
    for r in range(1, max(needed) + 1):
        w(f"    p{r} = " + ("ps" if r == 1 else f"p{r - 1} + ps"))
    w("    # the chunk buffer's rows: family q's axis e at row 3 q + e, face t0 + j in column 1 + j")
    prev = "one"
    for q in range(n_fam):
        for e in range(3):
            name = f"g{q}{AXES[e]}"
            w(f"    {name} = {prev}" + ("" if prev == "one" else " + row"))
            prev = name
    w("    for t in range(t0, t1):")
    w("        u = np.uint64(t)")
    w("        j = np.uint64(t - t0)")
    w("        un = u + one")
    w("        # the nodes of face t (corner c at c ps + u) and of face t + 1 (suffix n)")
    for s in (0, 1):
        base = "un" if s else "u"
        for c in range(4):
            idx = base if c == 0 else f"r{c} + {base}"
            w(f"        i{_node(c, s)} = {idx}")
    w("        # x<e><c>, v<e><c>: axis e of the position and velocity of corner c on face t, x<e><c>n on face t + 1,")
    w("        # each loaded where a spring first needs it (all 48 loaded up front: the loop ran about 4 % slower)")
    loaded = set()

    def load(names):
        for name in names:
            if name in loaded:
                continue
            loaded.add(name)
            if name.startswith("st"):
                c = int(name[2])
                w(f"        {name} = st[" + (f"r{c} + u" if c else "u") + "]")
            elif name.startswith("fs"):
                w(f"        {name} = fs[" + ("un" if name == "fs1" else "u") + "]")
            else:
                arr, e, n = name[0], AXES.index(name[1]), name[2:]
                w(f"        {name} = {arr}f[{('', 'dim + ', 'dim2 + ')[e]}i{n}]")

    for q, (a, b, s, kind, ca, cb) in enumerate(fams):
        na, nb = _node(a, 0), _node(b, s)
        kname = {AXIAL: "AXIAL", CROSS: "CROSS"}.get(kind, "SIDE_DIAG")
        w(f"        # family {q}: corner {a} of face t to corner {b} of face t + {s}, {kname}")
        load([f"st{ca}"] if kind == AXIAL else ["fs0"] if kind == CROSS else [f"st{ca}", f"st{cb}", "fs0", "fs1"])
        load([f"{arr}{e}{n}" for arr in "xv" for e in AXES for n in (na, nb)])
        w(f"        k_{q} = pf[{_param(PAR_K * n_fam + q)}]")
        w(f"        d_{q} = pf[{_param(PAR_D * n_fam + q)}]")
        if kind == AXIAL:
            w(f"        rest_{q} = pf[{_param(PAR_L0 * n_fam + q)}] * st{ca}")
        elif kind == CROSS:
            w(f"        rest_{q} = pf[{_param(PAR_LC * n_fam + q)}] * fs0")
        else:
            w(f"        axial_{q} = pf[{_param(PAR_L0 * n_fam + q)}] * 0.5 * (st{ca} + st{cb})")
            w(f"        cross_{q} = pf[{_param(PAR_LC * n_fam + q)}] * 0.5 * (fs0 + fs1)")
            w(f"        rest_{q} = math.sqrt(axial_{q} * axial_{q} + cross_{q} * cross_{q})")
        for e in AXES:
            w(f"        d{e}_{q} = x{e}{nb} - x{e}{na}")
        w(f"        length_{q} = math.sqrt(dx_{q} * dx_{q} + dy_{q} * dy_{q} + dz_{q} * dz_{q})")
        for e in AXES:
            w(f"        u{e}_{q} = d{e}_{q} / length_{q}")
        w(f"        ldot_{q} = (vx{nb} - vx{na}) * ux_{q} + (vy{nb} - vy{na}) * uy_{q} + (vz{nb} - vz{na}) * uz_{q}")
        w(f"        f_{q} = k_{q} * (rest_{q} - length_{q}) - d_{q} * ldot_{q}")
        w(f"        live_{q} = length_{q} >= 1e-12")
        for e in AXES:
            w(f"        gq[g{q}{e} + j] = select(live_{q}, f_{q} * u{e}_{q}, 0.0)")
    _render_sums(w, n_fam)
    return "\n".join(out) + "\n"


def _render_sums(w, n_fam: int) -> None:
    """Pass 2: ``node_sums_chunk``, each node's 9 terms of ``CUBE_PLAN`` as one left-to-right sum."""
    w("")
    w("")
    w('@njit(cache=True, error_model="numpy", inline="always")')
    w("def node_sums_chunk(gq, fcf, ps, row, t0, t1):")
    w('    """Pass 2 of ``kernels._column_forces_flat`` for the faces t0 <= t < t1: the spring force [N] on the')
    w("    node of corner c of face t, axis e, written to fcf[(4 e + c) ps + t] (fcf: the (3, 4, stride) forces")
    w("    flat, ps = stride): the 9 terms (family q, sign s, shift b) of ``CUBE_PLAN[c]`` in their order,")
    w("    starting from 0.0, each s * (family q's axis e in the chunk buffer gq, row length ``row``, at column")
    w("    1 + t - t0 - b): the per-family kernel's sum term by term (x + (-1.0 * y) == x - y exactly).  A b end")
    w("    reads its spring one column back (column 0: the face before the chunk, -0.0 before face 0: an exact")
    w("    no-op).  ps, row: uint64.")
    w('    """')
    w("    one = np.uint64(1)")
    w("    # fcf's row 4 e + c starts at (4 e + c) ps")
    w("    o1 = ps")
    for r in range(2, 12):
        w(f"    o{r} = o{r - 1} + ps")
    w("    # the chunk buffer's rows: family q's axis e at row 3 q + e (h<q><e>: its start)")
    prev = None
    for q in range(n_fam):
        for e in range(3):
            name = f"h{q}{AXES[e]}"
            w(f"    {name} = " + ("row - row" if prev is None else f"{prev} + row"))
            prev = name
    w("    for t in range(t0, t1):")
    w("        u = np.uint64(t)")
    w("        j = np.uint64(t - t0)  # a b end's column (its spring's face is t - 1)")
    w("        j1 = j + one  # an a end's column (face t)")
    for e in range(3):
        for c in range(4):
            r = 4 * e + c
            terms = [f"{float(sg)!r} * gq[h{q}{AXES[e]} + {'j' if b else 'j1'}]" for q, sg, b in CUBE_PLAN[c]]
            w(f"        # corner {c}, axis {AXES[e]} (in parentheses, still summed left to right)")
            head = "        fcf[" + (f"o{r} + u" if r else "u") + "] = ("
            w(f"{head}0.0 + {' + '.join(terms[:3])}")
            w(f"{' ' * (len(head) - 1)}+ {' + '.join(terms[3:6])}")
            w(f"{' ' * (len(head) - 1)}+ {' + '.join(terms[6:])})")


def main(argv=None) -> int:
    text = render()
    if TARGET.exists() and TARGET.read_text() == text:
        print(f"{TARGET.name} is current")
        return 0
    TARGET.write_text(text)
    print(f"wrote {TARGET}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
