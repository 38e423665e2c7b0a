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
5. ``step(P, world, dt) -> (steps done, status code)``: one step of dt [s] of the body's own kernel in the run's
   world (``world.world.StepWorld`` as a plain tuple; ``step_status`` codes).

One implementation (issue 42 item 2): the four registered functions are the body's declaration of its
legged operations, and both paths run them.  The fused walk inlines them into its chunk; a body that
inherits ``LeggedPackOps`` has no Python version of its own: its ``segment_poses``, ``set_support``,
``push_support`` and the legged monitor's sample (``legged_sample``) call them through the small compiled
entries ``poses_now``, ``support_now`` and ``sample_now`` below, on one pack the body keeps (typed once:
``LeggedPackOps._legged_run``).  Its step is
one function too, ``STEP(*P.chain, world, dt, n_steps)`` in its module (the pack's ``chain`` holds the body's own
arguments, its records; the world and the time step are plain arguments given by whoever runs it; the body's
``BodySpec.step``), which ``Body.advance`` calls with the run's world and dt and the chunk's n, and the fused walk,
through the registered ``chain_step(STEP)``, with its world and dt and n = 1.  tests/test_legged_one_implementation.py checks each by identity for every
legged body in the catalog.

The interface: a body offers the fused path by a method ``legged_pack() -> P`` (``LeggedChunkBody``),
P a namedtuple of a class its own module declares and hands to ``register`` with its four
implementations.  ``register`` makes them what the four functions below compile to for that class
(one numba overload each, declared here once, so the order in which bodies register cannot matter),
so the fused kernel is written once against this interface, compiled once per body's pack type
(numba's cache keeps each), and never names a body.  A body whose Python methods are its own (not
``LeggedPackOps``'s) must keep them equal to its registered functions itself; tests/test_fused_walk.py
compares the two paths bit for bit.
"""
from __future__ import annotations

from functools import cached_property
from typing import Protocol, runtime_checkable

import numpy as np
from numba import njit
try:  # numba's own (private) fingerprint of a call's argument types: the typed-once entries key on it
    from numba._dispatcher import compute_fingerprint
except ImportError:  # a numba without it: every call goes through the dispatcher (slower, the same results)
    compute_fingerprint = None
from numba.core import types
from numba.core.typing.typeof import Purpose, typeof
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


def step(P, world, dt):
    """Step 5 (module docstring); compiled code only."""
    raise NotImplementedError("legged_chunk.step runs in compiled code, on a registered pack")


# The pack's class -> its four implementations (poses, carry, sample, step), filled by ``register``; and its
# ``carry_feet`` where it has one.
_IMPLS: dict[type, tuple] = {}
_FEET: dict[type, object] = {}
# The pack's class -> the body's one step function, for a step made by ``chain_step``.
_STEPS: dict[type, object] = {}


def _impl(P, which: int):
    """The registered implementation number ``which`` for pack type P (None: not a registered pack)."""
    if isinstance(P, types.BaseNamedTuple):
        impls = _IMPLS.get(P.instance_class)
        if impls is not None:
            return impls[which]
    return None


def register(cls, poses_impl, carry_impl, sample_impl, step_impl, carry_feet_impl=None) -> None:
    """Make the four plain functions (same parameters as ``poses``, ``carry``, ``sample`` and ``step``, which takes
    (P, world, dt)) the implementations for packs of namedtuple class ``cls``.  Inlined into the caller (numba IR
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
    if getattr(step_impl, "body_step", None) is not None:
        _STEPS[cls] = step_impl.body_step
    if carry_feet_impl is not None:  # the parameters of ``carry_feet`` (a body with a dynamic stance)
        _FEET[cls] = getattr(carry_feet_impl, "py_func", carry_feet_impl)


def registered(cls) -> tuple:
    """(poses, carry, sample, step, carry_feet or None) registered for pack class ``cls`` (the plain functions
    numba compiles), and the body's step function behind ``step`` (``chain_step``) or None."""
    return _IMPLS[cls] + (_FEET.get(cls), _STEPS.get(cls))


def chain_step(body_step, n_chain: int):
    """The fused walk's ``step(P, world, dt)`` of a body whose one step function is ``body_step(*P.chain, world, dt,
    n_steps) -> (steps done, status)`` (the function its ``Body.advance`` calls with the run's world and dt and the
    chunk's n): that function with the fused walk's world and dt and n = 1, so the two paths step through one
    function.  ``n_chain``: the number of items of the pack's ``chain`` (the body's own arguments of the step, before
    world, dt and n_steps), declared by the body beside its step; a wrong count fails the fused walk's first
    compile (a tuple index out of range, or a call with the wrong number of arguments).  ``body_step`` should be ``inline="always"``: a kernel of its own between
    the body's chain and the fused chunk would be optimized and emitted once more on a cold start's longest
    sequence of compiles (docs/guide/scheduling.md, "The longest chain of compiles").

    The call spells out ``P.chain``'s items, written here for ``body_step``'s number of parameters: numba does not
    inline a call with ``*args`` ("Calling a closure with *args is unsupported", numba 0.68.1)."""
    items = "".join(f"c[{i}], " for i in range(int(n_chain)))
    namespace = {"body_step": body_step, "np": np}
    # np.int64: a literal 1 compiles a second signature
    exec(f"def one_step(P, world, dt):\n    c = P.chain\n    return body_step({items}world, dt, np.int64(1))\n",
         namespace)
    one_step = namespace["one_step"]
    one_step.body_step = body_step
    one_step.__doc__ = f"``legged_chunk.step``: one step of ``{getattr(body_step, '__name__', body_step)}``."
    return one_step


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
def _step(P, world, dt):
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



# --------------------------------------------------------------------------- the Python path's entries
# Each compiles the registered functions for the pack's type, as the fused chunk inlines them: the Python path's
# segment interface (``LeggedPackOps``) has no code of its own.
@njit(cache=True, error_model="numpy")
def poses_now(P):
    """``poses(P)`` from Python: (c (n_seg, 3) [m], R (n_seg, 3, 3)), the pack's own arrays."""
    return poses(P)


@njit(cache=True, error_model="numpy")
def support_now(P, kinematic, c_T, R_T, states, tips, feet):
    """Steps 1 and 3 of the module docstring from Python: ``poses(P)``, then ``carry_feet`` (feet True: the
    support with the feet, as the fused walk takes it) or ``carry`` (feet False); returns whether a foot may have
    moved.  The poses again because ``carry`` reads them off the pack (the fused walk sensed them this step; a
    Python caller may not have, and recomputing them from an unchanged state gives the same doubles)."""
    poses(P)
    if feet:
        return carry_feet(P, kinematic, c_T, R_T, states, tips)
    carry(P, kinematic, c_T, R_T)
    return False


@njit(cache=True, error_model="numpy")
def sample_now(P, c_out, R_out, links_out):
    """``sample(P, c_out, R_out, links_out)`` from Python (step 4 of the module docstring)."""
    sample(P, c_out, R_out, links_out)


_NO_STATES = np.zeros(0, np.int64)   # ``set_support``'s leg states and feet: none (``carry`` reads neither)
_NO_TIPS = np.zeros((0, 3))


class LeggedPackOps:
    """The segment interface of a legged body on the Python path, made of its registered functions (module
    docstring, "One implementation"): a mixin placed before the body's other bases.  The body defines
    ``legged_pack()``, ``n_segments`` and ``dt`` [s] (the time step its pack holds)."""

    @cached_property
    def legged_ops_pack(self):
        """The pack the Python path's operations run on, built once (its arrays are the body's, changed in place
        only; its scratch is the pack's own, so the poses ``segment_poses`` senses are what ``set_support``
        carries from, as in the fused walk).  Its ``chain`` (the step's arguments) is left empty: the Python path
        steps through ``Body.advance``, and ``_legged_run`` types the pack once, not on every call."""
        P = self.legged_pack()
        return P._replace(chain=()) if "chain" in P._fields else P

    @cached_property
    def _legged_entries(self) -> dict:
        """(compiled entry, the fingerprint of the arguments after the pack) -> the entry's machine code for them
        and this body's pack (``_legged_run``)."""
        return {}

    def _legged_run(self, entry, *args):
        """``entry(legged_ops_pack, *args)``, the compiled entry's machine code for these argument types called
        directly.

        Why: numba's dispatcher finds a call's signature from the type fingerprint of every argument, computed on
        every call from Python leaf by leaf through nested tuples: the hybrid's pack (33 leaves, a 444-byte
        fingerprint) took about 5 to 10 us a call, the cost of the Python path's poses, support and sample (the
        poses themselves, compiled, take 0.06 us).  The pack never changes type (a tuple built once, of arrays
        changed in place only), so it is typed once, when an entry is first run for the types of the other
        arguments; those few are keyed by numba's own C fingerprint (the dispatcher's key: dtype, number of
        dimensions, layout, read-only), so an argument of another type resolves its own signature, as a
        dispatched call would (a value it has no fingerprint for goes through the dispatcher).  The signature is
        loaded or compiled by the dispatcher's ``compile`` (numba's cache, the compile lock), the one a dispatched
        call would take: the same machine code."""
        P = self.legged_ops_pack
        if compute_fingerprint is None:
            return entry(P, *args)
        try:
            key = (entry, compute_fingerprint(args))
        except NotImplementedError:  # a value numba's C typing does not know (a list): the dispatcher types it
            return entry(P, *args)
        run = self._legged_entries.get(key)
        if run is None:
            run = entry.compile(tuple(typeof(a, Purpose.argument) for a in (P, *args)))
            self._legged_entries[key] = run
        return run(P, *args)

    def segment_poses(self) -> tuple[np.ndarray, np.ndarray]:
        """Centres (n_seg, 3) [m] and rotations (n_seg, 3, 3) of the segments: the registered ``poses``, copied
        (the pack's arrays change with the next call)."""
        c, R = self._legged_run(poses_now)
        return c.copy(), R.copy()

    def set_support(self, kinematic: np.ndarray, c_T: np.ndarray, R_T: np.ndarray, dt: float) -> None:
        """Supported segments (``kinematic`` (n_seg,) bool) are carried to (c_T (n_seg, 3) [m], R_T (n_seg, 3, 3))
        during the next step of dt [s] (paper Sec. 4.1); the others follow the dynamics: the registered
        ``carry``.  dt must be the body's time step (the pack's)."""
        if dt != self.dt:
            raise ValueError(f"set_support: dt = {dt} s is not the body's time step {self.dt} s, the one its "
                             "support kernel carries over")
        self._legged_run(support_now, np.ascontiguousarray(kinematic, dtype=np.bool_),
                         np.ascontiguousarray(c_T, dtype=np.float64), np.ascontiguousarray(R_T, dtype=np.float64),
                         _NO_STATES, _NO_TIPS, False)

    def push_support(self, supported, c_T, R_T, states, tips) -> None:
        """The support with the feet this step (the registered ``carry_feet``; in dynamic stance,
        ``bodies.dynamic_stance``, the STANCE legs push): supported (n_seg,) bool, the targets c_T (n_seg, 3) [m]
        and R_T (n_seg, 3, 3), the leg states (n_legs,) int64 and the feet tips (n_legs, 3) [m], UPDATED where a
        foot slides."""
        self._legged_run(support_now, np.ascontiguousarray(supported, dtype=np.bool_),
                         np.ascontiguousarray(c_T, dtype=np.float64), np.ascontiguousarray(R_T, dtype=np.float64),
                         states, tips, True)

    def legged_sample(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The legged monitor's sample after the support (the registered ``sample``): segment centres c (n_seg, 3)
        [m], rotations R (n_seg, 3, 3) and centres (2 n_seg - 1, 3) [m] of segments and links in body order."""
        n = self.n_segments
        c, R, links = np.empty((n, 3)), np.empty((n, 3, 3)), np.empty((n - 1, 3))
        self._legged_run(sample_now, c, R, links)
        centres = np.empty((2 * n - 1, 3))
        centres[0::2] = c
        centres[1::2] = links
        return c, R, centres
