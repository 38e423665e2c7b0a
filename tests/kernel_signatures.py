"""Which project kernels a fresh compile of the quick matrix's kernel groups types with more than one signature.

Run as a script (``python3 tests/kernel_signatures.py``; ``tests/test_compiled_signatures.py`` runs it in a fresh
interpreter).  Prints one JSON object: {"typed": number of signatures re-typed, "kernels": number of project
kernels with a signature, "extra": {kernel: [signature, ...]} for every kernel with more than one signature or
with a signature that holds a ``Literal`` type or a read-only array; a kernel in ``PER_BODY`` may have one
signature per body model; "signatures": every project kernel's signatures, ``module.name(type, ...)``}.

Why (issue 13, cold start): numba compiles a kernel once per signature, and the whole code under it again.  A
constant passed on to another kernel (``j = -1`` then ``f(j)``) makes numba compile ``f`` for ``Literal[int](-1)``
as well as for int64, a read-only array (a ``np.broadcast_to`` view) a second array type; both only cost compile
time, so nothing else catches them.

How: one 0.02 s case of each of the quick matrix's kernel groups (the lattice and FEM worm, the hybrid chain, the
three walking centipedes, fused) loads or compiles the entry kernels.  A kernel loaded from numba's cache brings
only its own signature, not those its calls resolve to, so every project kernel that has a signature is then
re-typed (numba's type inference alone, as its compile would run it; the calls it types load or compile their
callees' signatures), until no kernel gains a signature.  Takes about 30 to 50 CPU s with a warm cache.
"""
from __future__ import annotations

import json
import sys

from numba.core import compiler, registry, types
from numba.core.compiler import CompilerBase, DefaultPassBuilder, _EarlyPipelineCompletion
from numba.core.compiler_machinery import FunctionPass, register_pass
from numba.core.dispatcher import Dispatcher
from numba.core.typed_passes import NopythonTypeInference

# Kernels written once against a body backend's interface (issue 30: one legged loop and one rigid chain, the
# body's own arrays and numba overloads passed in): numba types them once per body model that runs through
# them, as it would separate per-body kernels, so that many signatures are expected.  One more (a second
# signature for the same body) is still an extra.
PER_BODY = {"bench_myriapoda.fused.legged_walk.legged_chunk": 3,  # the hybrid, lattice and FEM centipedes
            # the Python path's poses (``legged_chunk.LeggedPackOps.segment_poses``, a sample's observation): once
            # per legged body's pack, as the fused chunk
            "bench_myriapoda.bodies.legged_chunk.poses_now": 3,
            "bench_myriapoda.bodies.rigid_chain.advance_chain": 2}  # rigid chains with FEM or spring links

GROUPS = [("worm", "massspring", "flat"), ("worm", "fem", "flat"), ("chain", "hybrid", "fig4-drop"),
          ("centipede", "hybrid", "walk"), ("centipede", "massspring", "walk"), ("centipede", "fem", "walk")]


@register_pass(mutates_CFG=False, analysis_only=True)
class _StopAfterTyping(FunctionPass):
    """Ends numba's pipeline right after type inference (no lowering, no LLVM, nothing cached)."""

    _name = "stop_after_typing"

    def __init__(self):
        FunctionPass.__init__(self)

    def run_pass(self, state):
        raise _EarlyPipelineCompletion(state.typemap)


class _TypeOnly(CompilerBase):
    """numba's nopython pipeline up to and including type inference."""

    def define_pipelines(self):
        pm = DefaultPassBuilder.define_nopython_pipeline(self.state)
        pm.passes = pm.passes[: [p[0] for p in pm.passes].index(NopythonTypeInference) + 1]
        pm.add_pass(_StopAfterTyping, "stop after type inference")
        pm.finalize()
        return [pm]


def project_kernels() -> list[Dispatcher]:
    seen: dict[int, Dispatcher] = {}
    for name, mod in list(sys.modules.items()):
        if name.startswith("bench_myriapoda") and mod is not None:
            for obj in vars(mod).values():
                if isinstance(obj, Dispatcher):
                    seen[id(obj)] = obj
    return list(seen.values())


def retype(kernel: Dispatcher, sig) -> None:
    """numba's type inference of ``kernel`` for ``sig``, with the flags its own compile uses."""
    flags = compiler.Flags()
    kernel.targetdescr.options.parse_as_flags(flags, kernel.targetoptions)
    flags = kernel._compiler._customize_flags(flags)
    compiler.compile_extra(registry.cpu_target.typing_context, registry.cpu_target.target_context,
                           kernel.py_func, sig, None, flags, {}, pipeline_class=_TypeOnly)


def _suspect(sig) -> bool:
    return any(isinstance(t, types.Literal) or (isinstance(t, types.Array) and not t.mutable) for t in sig)


def main() -> dict:
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness.runner import run_case

    for creature, body, scenario in GROUPS:
        status = run_case(resolve_case(creature, body, scenario, None, duration=0.02)).status
        assert status == "ok", (creature, body, scenario, status)
    done: set = set()
    while True:
        todo = [(k, s) for k in project_kernels() for s in k.signatures if (id(k), s) not in done]
        if not todo:
            break
        for kernel, sig in todo:
            done.add((id(kernel), sig))
            if kernel.targetoptions.get("inline") != "always":  # an inlined kernel is typed in its callers
                retype(kernel, sig)
    kernels = [k for k in project_kernels() if k.signatures]
    extra = {}
    for k in kernels:
        name = f"{k.py_func.__module__}.{k.py_func.__qualname__}"
        if len(k.signatures) > PER_BODY.get(name, 1) or any(_suspect(s) for s in k.signatures):
            extra[name] = [str(s) for s in k.signatures]
    per_body = {f"{k.py_func.__module__}.{k.py_func.__qualname__}": len(k.signatures) for k in kernels}
    per_body = {name: per_body.get(name, 0) for name in PER_BODY}
    # every signature, as ``compile_plan`` names them (the recorded compile plans must hold no other)
    signatures = sorted(f"{k.py_func.__module__}.{k.py_func.__qualname__}({', '.join(str(a) for a in s)})"
                        for k in kernels for s in k.signatures)
    return {"typed": len(done), "kernels": len(kernels), "extra": extra, "per_body": per_body,
            "per_body_expected": PER_BODY, "signatures": signatures}


if __name__ == "__main__":
    print(json.dumps(main()))
