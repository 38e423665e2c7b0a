"""How a body with legs takes part in the fused legged walk: four kernels on one argument pack.

The fused legged walk (``fused.legged_walk``) runs a legged body and its leg controller for many
time steps in one compiled call.  Each step is, in this order (the Python path's order: the
runner's ``body.sense`` -> ``controller.step`` -> ``body.apply_support`` -> the legged monitor's
sample -> ``body.advance(t, 1)``):

1. ``poses(P) -> (c, R)``: the segments' current poses, c (n_seg, 3) [m] and R (n_seg, 3, 3),
   as the body's ``segment_poses`` gives them (arrays of P, read by the controller's step);
2. the controller's step (not the body's business);
3. ``carry(P, kinematic, c_T, R_T)``: the body's ``set_support`` on the controller's support,
   kinematic (n_seg,) bool, c_T (n_seg, 3) [m], R_T (n_seg, 3, 3); the fused walk calls it through
   ``carry_feet(P, kinematic, c_T, R_T, states, tips) -> bool``, which a body with a dynamic stance
   (``bodies.dynamic_stance``) registers to read the leg states (n_legs,) and move the STANCE feet tips
   (n_legs, 3) [m] that slide, returning whether it may have moved one (any other body: ``carry``, False);
4. ``sample(P, c_out, R_out, links_out)``: on a step the timeline records, the poses after the
   support into c_out (n_seg, 3) [m] and R_out (n_seg, 3, 3), and the links' centres (what the
   body's ``segment_centers`` gives at odd rows) into links_out (n_seg - 1, 3) [m];
5. ``step(P) -> (steps done, status code)``: one step of the body's own kernel
   (``step_status`` codes).

The interface: a body offers the fused path by a method ``legged_pack() -> P`` (``LeggedChunkBody``),
P a namedtuple of a class its own module declares and hands to ``register`` with its four
implementations.  ``register`` makes them what the four functions below compile to for that class
(one numba overload each, declared here once, so the order in which bodies register cannot matter),
so the fused kernel is written once against this interface, compiled once per body's pack type
(numba's cache keeps each), and never names a body.  The implementations run the same kernels on the
same arrays as the body's Python methods, so the two paths give the same doubles (tests/test_fused_walk.py).
"""
from __future__ import annotations

from typing import Protocol, runtime_checkable

from numba import njit
from numba.core import types
from numba.extending import overload


@runtime_checkable
class LeggedChunkBody(Protocol):
    """A body that the fused legged walk can drive (module docstring)."""

    def legged_pack(self) -> tuple:
        """The argument pack P of this body's four kernels: a namedtuple of a ``register``-ed class,
        referring to the body's own arrays (no copy), current for the next chunk of steps."""


def poses(P):
    """Step 1 (module docstring); compiled code only."""
    raise NotImplementedError("legged_chunk.poses runs in compiled code, on a registered pack")


def carry(P, kinematic, c_T, R_T):
    """Step 3 (module docstring); compiled code only."""
    raise NotImplementedError("legged_chunk.carry runs in compiled code, on a registered pack")


def carry_feet(P, kinematic, c_T, R_T, states, tips):
    """Step 3 with the feet (module docstring); compiled code only."""
    raise NotImplementedError("legged_chunk.carry_feet runs in compiled code, on a registered pack")


def sample(P, c_out, R_out, links_out):
    """Step 4 (module docstring); compiled code only."""
    raise NotImplementedError("legged_chunk.sample runs in compiled code, on a registered pack")


def step(P):
    """Step 5 (module docstring); compiled code only."""
    raise NotImplementedError("legged_chunk.step runs in compiled code, on a registered pack")


# The pack's class -> its four implementations (poses, carry, sample, step), filled by ``register``; and its
# ``carry_feet`` where it has one.
_IMPLS: dict[type, tuple] = {}
_FEET: dict[type, object] = {}


def _impl(P, which: int):
    """The registered implementation number ``which`` for pack type P (None: not a registered pack)."""
    if isinstance(P, types.BaseNamedTuple):
        impls = _IMPLS.get(P.instance_class)
        if impls is not None:
            return impls[which]
    return None


def register(cls, poses_impl, carry_impl, sample_impl, step_impl, carry_feet_impl=None) -> None:
    """Make the four plain functions (same parameters as ``poses``, ``carry``, ``sample``, ``step``)
    the implementations for packs of namedtuple class ``cls``.  Inlined into the caller (numba IR
    inlining), as the fused kernel's own helpers are.  A numba dispatcher counts as its Python function.

    Registering only fills a table: each of the four functions has ONE numba overload, declared below
    when this module is imported, which picks the implementation by the pack's class when a kernel is
    typed.  An overload per body (as before) made numba's type of ``poses`` a new ``Function`` (the
    old one's templates plus the new) each time a body module was imported; a body module can be
    imported in the middle of typing a kernel (loading a callee from the numba cache unpickles its
    cached signatures, which imports the module of each pack class in them), and the next nested
    compile's refresh then gave ``legged_chunk`` two types for ``LC.poses``: "Cannot unify
    Function(<function poses>) and Function(<function poses>)" (tests/test_legged_chunk_registration.py)."""
    _IMPLS[cls] = tuple(getattr(f, "py_func", f) for f in (poses_impl, carry_impl, sample_impl, step_impl))
    if carry_feet_impl is not None:  # the parameters of ``carry_feet`` (a body with a dynamic stance)
        _FEET[cls] = getattr(carry_feet_impl, "py_func", carry_feet_impl)


@overload(poses, inline="always")
def _poses(P):
    return _impl(P, 0)


@overload(carry, inline="always")
def _carry(P, kinematic, c_T, R_T):
    return _impl(P, 1)


def _carry_without_feet(P, kinematic, c_T, R_T, states, tips):
    """``carry_feet`` of a body that registered none: its ``carry``; no foot moved."""
    carry(P, kinematic, c_T, R_T)
    return False


@overload(carry_feet, inline="always")
def _carry_feet(P, kinematic, c_T, R_T, states, tips):
    if isinstance(P, types.BaseNamedTuple):
        if P.instance_class in _FEET:
            return _FEET[P.instance_class]
        if P.instance_class in _IMPLS:
            return _carry_without_feet
    return None


@overload(sample, inline="always")
def _sample(P, c_out, R_out, links_out):
    return _impl(P, 2)


@overload(step, inline="always")
def _step(P):
    return _impl(P, 3)


# The rows are copied element-wise, not as out[:] = a: an array assigned to a slice compiles numba's
# shape-mismatch message (string formatting, seconds of compile per process; README Development notes).
@njit(cache=True, error_model="numpy", inline="always")
def copy_rows(a, out):
    """out[i, k] = a[i, k] for a, out (n, 3)."""
    for i in range(a.shape[0]):
        out[i, 0], out[i, 1], out[i, 2] = a[i, 0], a[i, 1], a[i, 2]


@njit(cache=True, error_model="numpy", inline="always")
def copy_frames(R, out):
    """out[i] = R[i] for R, out (n, 3, 3)."""
    for i in range(R.shape[0]):
        for r in range(3):
            out[i, r, 0], out[i, r, 1], out[i, r, 2] = R[i, r, 0], R[i, r, 1], R[i, r, 2]
