"""A legged myriapod in one compiled call per chunk: leg controller, support and body step.

The reference is the Python path of ``harness.runner.Stepper`` for a closed-loop controller
ticking every step: ``body.sense`` -> ``MyriapodController.step`` -> ``body.apply_support``
-> ``LeggedMonitor.after_control`` -> ``body.advance(t, 1)``, a few dozen compiled calls
sequenced from Python per time step.  ``legged_chunk`` runs k such steps inside one numba call,
with the same kernels in the same order on the same arrays; the body's part of each step is the body's
own (``bodies.legged_chunk``: a body offers it through ``legged_pack``, and this module names no body):

1. sense: the segments' poses (``legged_chunk.poses``);
2. the controller's step (``controllers.myriapod.compiled.controller_step``);
3. the support, the body's ``set_support`` (``legged_chunk.carry_feet``: ``carry``, or in dynamic stance its
   ``push_support``, which may move the STANCE feet);
4. a timeline sample every ``record_every`` steps: the controller's record (states, tips,
   brain mode, antenna contact, segment centres before the support) and the monitor's
   (segment poses and link centres after the support, ``legged_chunk.sample``), into buffers;
5. one body step (``legged_chunk.step``, n = 1) of the chunk's dt in the run's world (plain arguments of the body's
   step, as on the Python path, where ``Body.advance`` gives the same world and dt).

After the last step (or a step that blew up) ``compiled.finish_chunk`` computes the antennae's
links that the chunk's steps left to it on a terrain without obstacles (``compiled.I_ANT_DEFER``).

Python is entered once per chunk (the runner's sample rate): ``FusedLeggedWalk.advance``
packs the controller's scalars, pre-draws its random numbers, calls the kernel, and
replays the buffered timeline samples into the controller's lists and the monitor, so
observations, metrics and series are those of the Python path.  The state after every step
equals the Python path's bit for bit (tests/test_fused_walk.py; numpy's summation order is
reproduced where a sum feeds a metric).

Fused: every body with a ``legged_pack`` -- the three legged bodies ``hybrid`` and ``massspring``
(rigid boxes joined by FEM or spring links, ``bodies.carried_boxes``) and ``fem`` (stiff blocks in
one mesh, their poses sensed from the nodes and their support a penalty target) -- driven by
``MyriapodController`` every time step, on any terrain of ``world.terrain_kernels`` (plane,
slopes, heightfields, obstacles), antennae on or off, leg collisions on or off, brain modes
ADJUSTMENT, AVOIDANCE, RANDOM-WALK and CONTROL, the suspended scenario (held head).  Not fused
(``unsupported_reason``; the runner keeps the Python path): food (TROPHOTROPISM, eating), the
lateral body wave (``body_wave_amplitude`` > 0), muscle actuation of the hybrid's links, a
controller ticking slower than every step, a controller of another class, a body without a pack.
"""
from __future__ import annotations

import hashlib
import sys
import types
from collections import namedtuple
from pathlib import Path

import numpy as np
from numba import njit

from ..bodies import legged_chunk as LC
from ..bodies.legged_chunk import LeggedChunkBody, copy_rows
from ..bodies.step_status import OK
from ..controllers.myriapod import compiled as CC
from ..controllers.myriapod.controller import MyriapodController
from ..core.kernel_records import plain

# The chunk's timeline buffers, one row per sample (step 4), capacity n_steps // record_every + 1 rows: the
# controller's record t [s], states (n_legs,) int8, tips (n_legs, 3) [m], brain mode, antenna contact (2,) bool
# and the segment centres (n_seg, 3) [m] before the support; the monitor's segment poses c (n_seg, 3) [m],
# R (n_seg, 3, 3) and link centres (n_seg - 1, 3) [m] after it.  Crosses into ``legged_chunk`` as a plain tuple
# (``plain``) and is named again there.
Timeline = namedtuple("Timeline", "t states tips brain contact centres c R links")
# Where the controller's fields of a Timeline sit in the plain tuple REC.  ``_control`` stores its row through
# REC's items, not through ``Timeline(*REC)``: numba's dead-code elimination (run on a kernel that inlines
# overloads, as ``legged_chunk`` inlines the body's functions) does not see that a record built in compiled code
# aliases the arrays it was built from, and dropped the stores into them (the timeline came back as zeros; numba
# 0.68.1, its alias analysis follows getitem, not a constructor call).  Reads, and arrays handed to a call
# (``copy_rows``, ``LC.sample``), are not affected.
_REC_T, _REC_STATES, _REC_TIPS, _REC_BRAIN, _REC_CONTACT, _REC_CENTRES = (
    Timeline._fields.index(f) for f in ("t", "states", "tips", "brain", "contact", "centres"))


def unsupported_reason(body, controller, steps_per_tick: int, act) -> str | None:
    """Why this body and controller run on the Python path (None: ``FusedLeggedWalk`` runs them)."""
    if not isinstance(body, LeggedChunkBody):
        return f"body {type(body).__name__} has no fused legged path (no legged_pack, bodies.legged_chunk)"
    if type(controller) is not MyriapodController:
        return f"controller {type(controller).__name__} has no compiled step"
    if steps_per_tick != 1:
        return "the controller ticks slower than every step"
    if act.muscles_on:
        return "muscle actuation of the links is not fused"
    return CC.unsupported_reason(controller)


# _control is inlined into the chunk (numba IR inlining): as a kernel of its own, numba would optimize and emit
# the whole controller's machine code once per layer (each compiled function links its callees' code and
# compiles it again), about 10 s of a cold start (README Development notes).
@njit(cache=True, error_model="numpy", inline="always")
def _control(t, C, ca, c, R, REC, n_rec):
    """Step 2 of the module docstring on the segment poses c (n_seg, 3) [m], R (n_seg, 3, 3) for the step
    starting at t [s], and the controller's half of step 4 (row n_rec of REC); returns whether recorded.

    C = (fs, ints, A, rnd, ant_rnd, err_scratch): the controller (``compiled.controller_step``; A its
    ``ControllerArrays`` as a plain tuple, ca the same named).  REC: the ``Timeline`` as a plain tuple
    (``legged_chunk``), written through its items (``_REC_T``...).
    """
    fs, ints, A, rnd, ant_rnd, err_scratch = C
    states, tips, contact = ca.states, ca.tips, ca.contact
    recorded = CC.controller_step(c, R, t, fs, ints, A, rnd, ant_rnd, err_scratch)
    if recorded:
        rec_t, rec_states, rec_tips = REC[_REC_T], REC[_REC_STATES], REC[_REC_TIPS]
        rec_brain, rec_contact, rec_centres = REC[_REC_BRAIN], REC[_REC_CONTACT], REC[_REC_CENTRES]
        rec_t[n_rec] = t
        for j in range(states.shape[0]):
            rec_states[n_rec, j] = states[j]
            for a in range(3):
                rec_tips[n_rec, j, a] = tips[j, a]
        rec_brain[n_rec] = ints[CC.I_BRAIN]
        rec_contact[n_rec, 0] = ints[CC.I_HAS_ANTENNAE] != 0 and contact[0]
        rec_contact[n_rec, 1] = ints[CC.I_HAS_ANTENNAE] != 0 and contact[1]
        copy_rows(c, rec_centres[n_rec])
    return recorded


@njit(cache=True, error_model="numpy")
def legged_chunk(t0, dt, n_steps, C, W, P, REC):
    """n_steps of the module docstring's steps 1-5 from t0 [s], time step dt [s], in the world W (the run's
    ``world.world.StepWorld`` as a plain tuple, ``World.step_world``).

    C: the controller (``_control``); P: the body's pack (``bodies.legged_chunk``, its ``legged_pack``).
    REC: the timeline buffers, a ``Timeline`` as a plain tuple.
    Returns (steps done, status code, rows recorded); a blow-up ends the chunk after its step.
    """
    ca = CC.ControllerArrays(*C[2])
    seg_kin, c_T, R_T = ca.kinematic, ca.c_T, ca.R_T
    rec = Timeline(*REC)
    n_rec = np.int64(0)
    for k in range(n_steps):
        c, R = LC.poses(P)                                     # 1. sense
        recorded = _control(t0 + k * dt, C, ca, c, R, REC, n_rec)  # 2. controller (and its timeline row)
        if LC.carry_feet(P, seg_kin, c_T, R_T, ca.states, ca.tips):  # 3. support
            # feet slid (dynamic stance): the tips' distances the controller keeps are no longer theirs
            C[1][CC.I_TIP_PHI_OK] = 0
        if recorded:                                           # 4. the monitor's sample
            LC.sample(P, rec.c[n_rec], rec.R[n_rec], rec.links[n_rec])
            n_rec += 1
        done, status = LC.step(P, W, dt)                       # 5. one body step
        if status != OK:
            CC.finish_chunk(C[0], C[1], C[2])
            return k + 1, status, n_rec
    CC.finish_chunk(C[0], C[1], C[2])
    return n_steps, OK, n_rec


# A pack class from outside the package (a plugin's legged body, tests/test_fourth_body_legged.py) gets a copy of
# ``legged_chunk`` with a cache index of its own.  numba keeps one index file per kernel holding every cached
# signature's types, pickled, and reads all of it to look up any one: a plugin's pack class in the package kernel's
# index made every process that cannot import the plugin module fail at its first fused legged run ("No module
# named 'test_fourth_body_legged'", a built-in body's walk from a plain shell).  The copy's index is named after the
# plugin module and a hash of its source: the body's functions are compiled into the chunk, and numba's cache only
# watches this file, so an edited plugin must not load the chunk of its previous version.
_PLUGIN_CHUNKS: dict[str, object] = {}


def chunk_kernel(pack_class: type):
    """The chunk kernel for packs of ``pack_class``: ``legged_chunk``, or for a class outside the package its copy
    (above), compiled and cached like it (the same code, so the same results)."""
    module = pack_class.__module__
    if module == "bench_myriapoda" or module.startswith("bench_myriapoda."):
        return legged_chunk
    if module not in _PLUGIN_CHUNKS:
        source = getattr(sys.modules.get(module), "__file__", None)
        digest = hashlib.sha1(Path(source).read_bytes() if source else module.encode()).hexdigest()[:16]
        f = legged_chunk.py_func
        copy = types.FunctionType(f.__code__, f.__globals__, f.__name__, f.__defaults__, f.__closure__)
        copy.__qualname__ = f"{f.__qualname__}__{module.replace('.', '_')}_{digest}"  # names numba's index file
        copy.__doc__ = f.__doc__
        _PLUGIN_CHUNKS[module] = njit(cache=True, error_model="numpy")(copy)
    return _PLUGIN_CHUNKS[module]


class FusedLeggedWalk:
    """``advance(t0, n) -> (steps done, status)`` of a legged body and its leg controller in one compiled call.

    ``act`` is the stepper's actuation: its support fields are left as the Python path leaves them
    (the last step's support, already taken by the body).  ``monitor``: the run's ``LeggedMonitor``
    or None.  ``world``: the run's ``world.world.World``, which the body's step is given each step (as the body's
    ``advance`` gives it on the Python path).  The time step is the controller's, which must be the body's: a body
    with an implicit solve holds its factor for that dt (``BodySpec.step``).
    """

    def __init__(self, body, controller: MyriapodController, act, monitor=None, *, world):
        if controller.dt != body.dt:
            raise ValueError(f"FusedLeggedWalk: the controller's dt = {controller.dt} s is not the body's time step "
                             f"{body.dt} s")
        self.body, self.controller, self.act, self.monitor = body, controller, act, monitor
        self.world = world
        self.cs = CC.ControllerState(controller)
        n_seg, n_legs = controller.n_seg, controller.n_legs
        self.err_scratch = np.zeros(n_seg)
        self._alloc(1, n_seg, n_legs)
        self._chunk = chunk_kernel(type(body.legged_pack()))

    def _alloc(self, rows: int, n_seg: int, n_legs: int) -> None:
        self.rec_t = np.zeros(rows)
        self.rec_states = np.zeros((rows, n_legs), np.int8)
        self.rec_tips = np.zeros((rows, n_legs, 3))
        self.rec_brain = np.zeros(rows, np.int64)
        self.rec_contact = np.zeros((rows, 2), np.bool_)
        self.rec_centres = np.zeros((rows, n_seg, 3))
        self.rec_c = np.zeros((rows, n_seg, 3))
        self.rec_R = np.zeros((rows, n_seg, 3, 3))
        self.rec_links = np.zeros((rows, n_seg - 1, 3))

    def advance(self, t0: float, n: int) -> tuple[int, int]:
        ctrl, cs = self.controller, self.cs
        rows = n // ctrl.record_every + 1
        if self.rec_t.shape[0] < rows:
            self._alloc(rows, ctrl.n_seg, ctrl.n_legs)
        A = cs.pack()
        cs.draws(n)
        C = (cs.fs, cs.ints, A, cs.rnd, cs.ant_rnd, self.err_scratch)
        REC = plain(Timeline(t=self.rec_t, states=self.rec_states, tips=self.rec_tips, brain=self.rec_brain,
                             contact=self.rec_contact, centres=self.rec_centres, c=self.rec_c, R=self.rec_R,
                             links=self.rec_links))
        k, code, n_rec = self._chunk(float(t0), float(ctrl.dt), int(n), C, self.world.step_world,
                                     self.body.legged_pack(), REC)
        cs.unpack()
        cs.settle()
        self._replay(int(n_rec))
        if k > 0:  # the last step's support, as the Python path's actuation holds it
            act = self.act
            act.support_kinematic[:] = ctrl.kinematic
            act.support_c[:] = ctrl.c_T
            act.support_R[:] = ctrl.R_T
            act.support_new = False
        return int(k), int(code)

    def compile(self) -> None:
        """Compile (or load from the numba cache) the chunk kernel: a chunk of zero steps changes nothing."""
        self.advance(0.0, 0)

    def _replay(self, n_rec: int) -> None:
        """The chunk's timeline samples into the controller's lists and the monitor (as ``step`` and
        ``LeggedMonitor.after_control`` append them).  Each buffer's rows are copied once per chunk and
        the lists get row views of that copy (the Python path appends a copy per row: the same values),
        and the monitor takes the chunk's samples in one ``sample_many`` call: a chunk's replay no
        longer costs Python work per sample (a fixed cost per step that made small bodies slow)."""
        if n_rec == 0:
            return
        ctrl, mon = self.controller, self.monitor
        n_seg = ctrl.n_seg
        tips = self.rec_tips[:n_rec].copy()
        rec_c = self.rec_c[:n_rec]
        ctrl.leg_timeline.extend(self.rec_t[:n_rec], self.rec_states[:n_rec].copy(), tips, self.rec_brain[:n_rec],
                                 self.rec_contact[:n_rec].copy(), self.rec_centres[:n_rec].copy())
        if mon is not None:
            centres = np.empty((n_rec, 2 * n_seg - 1, 3))
            centres[:, 0::2] = rec_c
            centres[:, 1::2] = self.rec_links[:n_rec]
            mon.sample_many(rec_c, self.rec_R[:n_rec], centres, tips)
