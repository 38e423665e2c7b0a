"""``select(c, a, b)``: a if c else b as one LLVM ``select`` instruction, for numba kernels.

Why: numba turns ``a if c else b`` into two basic blocks and a phi.  In a loop body with dozens of such
choices (the generated spring pass, ``column_loop.py``) the blocks made numba's IR inlining deep-copy the
function's whole variable scope once per block (``InlineWorker.inline_ir``: quadratic in the loop body's
size), and its SSA reconstruction and lowering walk them all; LLVM turns the branches back into selects
anyway.  The result is the same value, bit for bit (both operands are computed either way, as before:
they have no side effects).
"""
from numba import types
from numba.extending import intrinsic


@intrinsic
def select(typingctx, c, a, b):
    """a if c else b for a boolean c and two float64 a, b (the operands are evaluated before the choice)."""
    if not (isinstance(c, types.Boolean) and a == types.float64 and b == types.float64):
        return None
    sig = types.float64(types.boolean, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        cond, x, y = args
        return builder.select(context.cast(builder, cond, types.boolean, types.boolean), x, y)

    return sig, codegen
