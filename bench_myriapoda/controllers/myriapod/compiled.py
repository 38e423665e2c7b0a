"""The leg controller's step (``controller.MyriapodController.step``) as one numba kernel on flat arrays.

``MyriapodController.step`` is the reference: it sequences the numba kernels of the
Targeter, the Switcher, the leg kinematics, the leg collisions and the antennae from
Python, once per time step (paper Sec. 6 order, documented there).  ``controller_step``
below runs the same kernels in the same order on the same arrays, with the head's
Python logic (brain modes, head command, turn memory, CONTROL heading, tracking error)
ported line for line, so that a caller can run the controller and a body's step inside
one compiled loop (``bench_myriapoda.fused``) and enter Python only at the sample rate.

What it covers (``unsupported_reason`` says why a controller is not covered):

* brain modes ADJUSTMENT, AVOIDANCE, RANDOM-WALK and CONTROL; antennae on or off; legs
  colliding with the terrain or not; any terrain of ``world.terrain_kernels``;
* not covered: food (TROPHOTROPISM, eating), the lateral body wave
  (``body_wave_amplitude`` > 0), a controller ticking slower than every step.

State: the controller's own arrays are used in place (no copy), so its attributes
stay current.  Its scalars travel in two vectors, ``fs`` (float64, ``F_*``) and
``ints`` (int64, ``I_*``), built by ``ControllerState.pack`` before a chunk of steps and
written back by ``ControllerState.unpack`` after it.

Random numbers: the controller draws a new random-walk turn from ``controller.rng``
(``Generator.uniform(-turn_max, turn_max)``) and the antennae draw new root targets from
their own generator.  numpy computes ``uniform(lo, hi)`` as ``lo + (hi - lo) u`` with u the
generator's next double, so a chunk pre-draws the doubles it might need (``rng.random``),
uses them in order, and the generator is then rewound and advanced by exactly the number
used (``ControllerState.draws`` / ``settle``): both paths consume the same stream.
"""
from __future__ import annotations

import math
from collections import namedtuple
from operator import attrgetter

import numpy as np
from numba import njit

from ...core.kernel_records import plain
from ...kinematics import legs as L
from . import antennae as AN
from . import leg_collision as LC
from . import switcher as SW
from . import targeter as TG

# brain modes, as controller.py (which imports this module's users, not the reverse)
ADJUSTMENT, AVOIDANCE, TROPHOTROPISM, RANDOM_WALK, CONTROL = range(5)

# float scalars (``fs``): parameters, then state
(F_DT, F_CONTACT_DIST, F_THETA_MIN, F_MAJORITY, F_HEAD_SPEED, F_TURN_MAX, F_TURN_RATE, F_AVOID_RATE,
 F_AVOID_HOLD, F_AVOID_SPEED, F_MAX_BODY_TURN, F_TURN_MEMORY_LENGTH,
 F_AVOID_DIR, F_TURN_MEMORY, F_AVOID_UNTIL, F_TURN_LEFT, F_T_WALK, F_TOUCH_AT_WALK, F_TRACKING_SUM,
 F_HEADING_CMD, F_HEADING_ERR_SUM, F_LEG_PEN_MAX, F_ANT_T) = range(23)
N_FS = 23
# int scalars (``ints``)
(I_TERR_KIND, I_MIN_STANCE, I_WALK_MODE, I_RECORD_EVERY, I_COLLIDE, I_HAS_ANTENNAE, I_PRIORITY_LEFT,
 I_BRAIN, I_STEP, I_TRACKING_N, I_HEADING_ERR_N, I_LEG_STOPS, I_LEG_STUCK, I_CONTACT_EVENTS, I_TARGETS_DRAWN,
 I_RECORDED, I_RND_USED, I_ANT_RND_USED, I_ANT_DEFER, I_ANT_PENDING, I_TIP_PHI_OK, I_WALL_PUSHES) = range(22)
N_INTS = 22
# I_ANT_DEFER = 1: on a terrain without obstacles the antennae's links (wave angles, frames, points beyond
# the roots) are computed only once per chunk, by ``finish_chunk`` after its last step, for that step's time
# F_ANT_T (``antennae.antennae_step``'s ``links``): within a chunk nothing reads them, so the state after the
# chunk is the same doubles.  I_ANT_PENDING: a step left them to ``finish_chunk``.  I_TIP_PHI_OK: the tips'
# signed distances in ``ControllerArrays.tip_phi`` are those of the tips as they stand (measured at the end of the
# last step; the tips move only in the controller's step), so the next step's contact test reuses them.

# The controller's arrays that ``controller_step`` works on (its ``A``), by name (issue 42): the controller's own
# arrays (the leg states to the height target; ``O``, ``M`` the legs' origins and knees, ``prev_angles`` and
# ``stopped`` the leg collisions' scratch), the CONTROL brain's schedule (``Schedule``), the antennae's arrays
# (``AntennaArrays``: ``antennae.antennae_step``'s parameters and state; typed stand-ins, never read, without
# antennae), the tips' signed distances (``I_TIP_PHI_OK``), the terrain's walls and the segments' half sizes.
# ``ControllerState.pack`` builds it by field name; it crosses into compiled code as a plain tuple of its fields
# (``core.kernel_records.plain``: numba's dispatcher types a plain tuple of arrays several times faster than a
# namedtuple), and the kernels name it again, ``ControllerArrays(*A)`` (compiled code: no cost).  Caution: numba's
# dead-code elimination, which runs on a kernel that inlines overloads, does not see that such a record aliases A
# and drops stores into its arrays whose results nothing reads later (``fused.legged_walk`` lost its timeline so);
# ``controller_step`` and ``finish_chunk`` inline none, and tests/test_fused_walk.py compares every array they
# write with the Python path's, bit for bit.
_OWN = ("states angles tips O M touching airborne ik_failed entered supported kinematic c_T R_T prev_angles stopped "
        "brain_steps geom sw_params tg_params terr terr_walk link_rest height_target").split()
Schedule = namedtuple("Schedule", "sched_t sched_speed sched_rate")
AntennaArrays = namedtuple("AntennaArrays", "ant_params ant_f nominal offsets root_target root_omega retracting "
                           "contact rising contact_point contact_normal contact_depth arrived points frames")
_TAIL = ("tip_phi", "terr_walls", "seg_half")
ControllerArrays = namedtuple("ControllerArrays", _OWN + list(Schedule._fields) + list(AntennaArrays._fields)
                              + list(_TAIL))
# ``ControllerState.pack`` reads each part by name with one getter (a plain tuple in the fields' order, at the
# cost of the positional tuple it replaces: building the namedtuple by keyword took three times as long per
# chunk): the controller's attribute of the field's name (but those named here), the antennae's likewise
_OWN_OF_CONTROLLER = attrgetter(*({"O": "_O", "M": "_M", "prev_angles": "_prev_angles",
                                   "stopped": "_stopped"}.get(f, f) for f in _OWN))
_ANTENNAE_OF_ANTENNAE = attrgetter(*({"ant_params": "params", "ant_f": "f"}.get(f, f)
                                     for f in AntennaArrays._fields))
# positions in the plain tuple ``A`` of the fields a caller that does not name it reads (from the record's fields)
A_STATES, A_TIPS, A_KINEMATIC, A_C_T, A_R_T, A_CONTACT = (
    ControllerArrays._fields.index(f) for f in ("states", "tips", "kinematic", "c_T", "R_T", "contact"))

# (controller attribute, fs index) of the float scalars, (attribute, ints index) of the int ones
_FLOATS = (("dt", F_DT), ("contact_distance", F_CONTACT_DIST), ("theta_min", F_THETA_MIN),
           ("majority", F_MAJORITY), ("head_speed", F_HEAD_SPEED), ("turn_max", F_TURN_MAX),
           ("turn_rate", F_TURN_RATE), ("avoid_rate", F_AVOID_RATE), ("avoid_hold", F_AVOID_HOLD),
           ("avoid_speed", F_AVOID_SPEED), ("max_body_turn", F_MAX_BODY_TURN),
           ("turn_memory_length", F_TURN_MEMORY_LENGTH), ("_avoid_dir", F_AVOID_DIR),
           ("_turn_memory", F_TURN_MEMORY), ("_avoid_until", F_AVOID_UNTIL), ("_turn_left", F_TURN_LEFT),
           ("t_walk", F_T_WALK), ("touch_fraction_at_walk", F_TOUCH_AT_WALK), ("tracking_sq_sum", F_TRACKING_SUM),
           ("heading_cmd", F_HEADING_CMD), ("heading_err_sum", F_HEADING_ERR_SUM),
           ("leg_penetration_max", F_LEG_PEN_MAX))
_STATE_FLOATS = _FLOATS[12:]   # written back after a chunk
_INTS = (("terr_kind", I_TERR_KIND), ("min_stance", I_MIN_STANCE), ("walk_mode", I_WALK_MODE),
         ("record_every", I_RECORD_EVERY), ("collide", I_COLLIDE), ("brain", I_BRAIN), ("_step", I_STEP),
         ("tracking_n", I_TRACKING_N), ("heading_err_n", I_HEADING_ERR_N), ("leg_stops", I_LEG_STOPS),
         ("leg_stuck", I_LEG_STUCK), ("wall_pushes", I_WALL_PUSHES))
_STATE_INTS = _INTS[5:]


# the stages of ``controller.STEP_ORDER`` that this kernel does not run (``unsupported_reason``)
PYTHON_ONLY = ("food", "body_wave")


def unsupported_reason(controller) -> str | None:
    """Why ``controller_step`` cannot stand in for ``controller.step`` (None when it can)."""
    if controller.has_food:
        return "food (TROPHOTROPISM, eating) is not compiled"
    if controller.wave_amp > 0.0:
        return "the lateral body wave (body_wave_amplitude > 0) is not compiled"
    return None


class ControllerState:
    """The flat-array view of one ``MyriapodController`` that ``controller_step`` works on.

    ``arrays`` is the tuple of the controller's own arrays (layout of ``controller_step``'s
    ``A``) -- rebuilt by ``pack`` so that it always refers to the controller's current arrays.
    """

    def __init__(self, controller):
        if unsupported_reason(controller) is not None:
            raise ValueError(f"controller not compilable: {unsupported_reason(controller)}")
        self.ctrl = controller
        self.fs = np.zeros(N_FS)
        self.ints = np.zeros(N_INTS, dtype=np.int64)
        c = controller
        ant = c.antennae
        if ant is None:  # typed stand-ins, never read (I_HAS_ANTENNAE = 0)
            n = 1
            self._ant = plain(AntennaArrays(
                ant_params=np.zeros(AN.N_ANTENNA_PARAMS), ant_f=np.zeros(len(c.terr)), nominal=np.zeros((2, n, 2)),
                offsets=np.zeros((2, n, 2)), root_target=np.zeros((2, 2)), root_omega=np.zeros(2),
                retracting=np.zeros(2, np.bool_), contact=np.zeros(2, np.bool_), rising=np.zeros(2, np.bool_),
                contact_point=np.zeros((2, 3)), contact_normal=np.zeros((2, 3)), contact_depth=np.zeros(2),
                arrived=np.zeros(2, np.bool_), points=np.zeros((2, n + 1, 3)), frames=np.zeros((2, n + 1, 3, 3))))
        times, speed, rate = c.schedule
        self._schedule = plain(Schedule(sched_t=np.ascontiguousarray(times, dtype=np.float64),
                                        sched_speed=np.ascontiguousarray(speed, dtype=np.float64),
                                        sched_rate=np.ascontiguousarray(rate, dtype=np.float64)))
        self.rnd = np.zeros(1)
        self.ant_rnd = np.zeros(1)
        self.tip_phi = np.zeros(c.n_legs)  # the tips' signed distances [m] (I_TIP_PHI_OK)

    def pack(self) -> tuple:
        """Scalars into ``fs``/``ints``; returns the arrays ``A``, a ``ControllerArrays`` as a plain tuple (the
        kernels name it again)."""
        c = self.ctrl
        fs, ints = self.fs, self.ints
        for name, k in _FLOATS:
            fs[k] = getattr(c, name)
        for name, k in _INTS:
            ints[k] = int(getattr(c, name))
        ant = c.antennae
        ints[I_HAS_ANTENNAE] = ant is not None
        ints[I_PRIORITY_LEFT] = c.avoid_priority == "left"
        ints[I_CONTACT_EVENTS] = ant.contact_events if ant is not None else 0
        ints[I_TARGETS_DRAWN] = ant.targets_drawn if ant is not None else 0
        ints[I_RECORDED] = c.recorded
        ints[I_RND_USED] = 0
        ints[I_ANT_RND_USED] = 0
        ints[I_ANT_DEFER] = 1   # the chunk kernels call finish_chunk
        ints[I_ANT_PENDING] = 0
        ints[I_TIP_PHI_OK] = 0   # measured afresh in a chunk's first step: the caller may have moved the tips
        a = _ANTENNAE_OF_ANTENNAE(ant) if ant is not None else self._ant
        # the parts in ControllerArrays' order (_OWN, Schedule, AntennaArrays, _TAIL)
        return _OWN_OF_CONTROLLER(c) + self._schedule + a + (self.tip_phi, c.terr_walls, c.seg_half)

    def draws(self, n_steps: int) -> None:
        """Pre-draw the doubles a chunk of ``n_steps`` steps may use (at most one random-walk turn and two
        antenna targets of two draws each per step), remembering where each generator stood."""
        c = self.ctrl
        self._rng_state = c.rng.bit_generator.state
        self.rnd = c.rng.random(n_steps)
        ant = c.antennae
        if ant is not None:
            self._ant_state = ant.rng.bit_generator.state
            self.ant_rnd = ant.rng.random(4 * n_steps)

    def settle(self) -> None:
        """Rewind the generators to the chunk's start and advance them by the draws actually used."""
        c = self.ctrl
        c.rng.bit_generator.state = self._rng_state
        if self.ints[I_RND_USED]:
            c.rng.random(int(self.ints[I_RND_USED]))
        ant = c.antennae
        if ant is not None:
            ant.rng.bit_generator.state = self._ant_state
            if self.ints[I_ANT_RND_USED]:
                ant.rng.random(int(self.ints[I_ANT_RND_USED]))

    def unpack(self) -> None:
        """The chunk's scalars back into the controller."""
        c = self.ctrl
        fs, ints = self.fs, self.ints
        for name, k in _STATE_FLOATS:
            setattr(c, name, float(fs[k]))
        for name, k in _STATE_INTS:
            setattr(c, name, int(ints[k]))
        c.recorded = bool(ints[I_RECORDED])
        ant = c.antennae
        if ant is not None:
            ant.contact_events = int(ints[I_CONTACT_EVENTS])
            ant.targets_drawn = int(ints[I_TARGETS_DRAWN])


@njit(cache=True)
def _block_sum(a, start, n):
    """numpy's pairwise_sum on a[start:start + n] for n <= 128: eight partial sums (sequential below 8)."""
    if n < 8:
        res = 0.0
        for i in range(start, start + n):
            res += a[i]
        return res
    r0, r1, r2, r3 = a[start], a[start + 1], a[start + 2], a[start + 3]
    r4, r5, r6, r7 = a[start + 4], a[start + 5], a[start + 6], a[start + 7]
    i = 8
    while i < n - n % 8:
        r0 += a[start + i]
        r1 += a[start + i + 1]
        r2 += a[start + i + 2]
        r3 += a[start + i + 3]
        r4 += a[start + i + 4]
        r5 += a[start + i + 5]
        r6 += a[start + i + 6]
        r7 += a[start + i + 7]
        i += 8
    res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
    while i < n:
        res += a[start + i]
        i += 1
    return res


@njit(cache=True)
def numpy_sum(a, n):
    """Sum of a[:n] in numpy's order (``np.add.reduce`` on a contiguous float64 array: blocks of up to
    128 summed with eight partial sums, larger ranges split in two halves, a multiple of 8 first, and
    the halves' sums added), so a sum the reference takes with numpy is the same double.

    numba's on-disk cache does not load recursive functions reliably, so the halving is an explicit
    post-order walk: ``lo``/``ln`` hold the pending ranges, ``val`` the finished partial sums.
    """
    if n <= 128:
        return _block_sum(a, np.int64(0), n)  # np.int64: a literal 0 compiles a second signature
    # stack of (start, length, visited) ranges; a visited range pops its two children's sums
    st = np.empty(128, np.int64)
    ln = np.empty(128, np.int64)
    vis = np.zeros(128, np.bool_)
    val = np.empty(128)
    top, nv = 0, 0
    st[0], ln[0], vis[0] = 0, n, False
    top = 1
    while top > 0:
        top -= 1
        s0, m, seen = st[top], ln[top], vis[top]
        if m <= 128:
            val[nv] = _block_sum(a, s0, m)
            nv += 1
        elif seen:
            nv -= 1
            val[nv - 1] = val[nv - 1] + val[nv]
        else:
            m2 = m // 2
            m2 -= m2 % 8
            st[top], ln[top], vis[top] = s0, m, True
            st[top + 1], ln[top + 1], vis[top + 1] = s0 + m2, m - m2, False   # right, evaluated second
            st[top + 2], ln[top + 2], vis[top + 2] = s0, m2, False            # left, evaluated first
            top += 3
    return val[0]


@njit(cache=True)
def _avoidance_turn(left, right, priority_left):
    """``controller.avoidance_turn``: +1 turn left, -1 right, 0 without contact."""
    if left and right:
        return -1.0 if priority_left else 1.0
    if left:
        return -1.0
    if right:
        return 1.0
    return 0.0


@njit(cache=True)
def finish_chunk(fs, ints, A):
    """After the last ``controller_step`` of a chunk (and before anything reads the antennae): the antennae's
    links the chunk's steps left to it (``I_ANT_DEFER``), for the last step's time."""
    if ints[I_ANT_PENDING] != 0:
        ca = ControllerArrays(*A)
        AN.antennae_links(ca.ant_params, fs[F_ANT_T], ca.nominal, ca.offsets, ca.points, ca.frames)
        ints[I_ANT_PENDING] = 0


@njit(cache=True, inline="always")
def _switch_brain(brain, t, fs, ints, has_ant, contact):
    """``MyriapodController._switch_brain`` (without TROPHOTROPISM): the brain mode after this step's contacts."""
    if brain != ADJUSTMENT and brain != CONTROL:
        left = has_ant and contact[0]
        right = has_ant and contact[1]
        if left or right:
            if brain != AVOIDANCE or (left and right):
                fs[F_AVOID_DIR] = _avoidance_turn(left, right, ints[I_PRIORITY_LEFT] != 0)
            fs[F_AVOID_UNTIL] = t + fs[F_AVOID_HOLD]
            brain = AVOIDANCE
        elif brain == AVOIDANCE and t < fs[F_AVOID_UNTIL]:
            pass
        else:
            brain = RANDOM_WALK
    return brain


@njit(cache=True, inline="always")
def _head_command(brain, t, dt, fs, ints, rnd, sched_t, sched_speed, sched_rate):
    """``MyriapodController._head_command`` (without TROPHOTROPISM): (speed [m/s], turn rate [rad/s], turn
    direction +1 left / -1 right / 0) of the head; a RANDOM-WALK target drawn from rnd."""
    speed, rate, turn_dir = 0.0, 0.0, 0.0
    if brain == AVOIDANCE:
        speed, rate, turn_dir = fs[F_AVOID_SPEED], fs[F_AVOID_RATE], fs[F_AVOID_DIR]
    elif brain == CONTROL:
        k = 0  # np.searchsorted(times, t, side="right") - 1, at least 0
        while k < sched_t.shape[0] and sched_t[k] <= t:
            k += 1
        k = max(k - 1, 0)
        r = sched_rate[k]
        speed, rate = sched_speed[k], abs(r)
        turn_dir = math.copysign(1.0, r) if r != 0 else 0.0
    elif brain == RANDOM_WALK:
        turn_rate = fs[F_TURN_RATE]
        if abs(fs[F_TURN_LEFT]) <= turn_rate * dt:
            u = rnd[ints[I_RND_USED]]
            ints[I_RND_USED] += 1
            lo, hi = -fs[F_TURN_MAX], fs[F_TURN_MAX]
            fs[F_TURN_LEFT] = lo + (hi - lo) * u
        tl = fs[F_TURN_LEFT]
        st = math.copysign(min(abs(tl), turn_rate * dt), tl)
        fs[F_TURN_LEFT] = tl - st
        speed, rate = fs[F_HEAD_SPEED], turn_rate
        turn_dir = math.copysign(1.0, st) if st != 0 else 0.0
    return speed, rate, turn_dir


@njit(cache=True)
def controller_step(c, R, t, fs, ints, A, rnd, ant_rnd, err_scratch):
    """One ``MyriapodController.step`` for the step starting at t [s], its stages in the order of
    ``controller.STEP_ORDER`` (but those of ``PYTHON_ONLY``; tests/test_controller_step_order.py).

    c (n_seg, 3) [m], R (n_seg, 3, 3): the segments' current poses (read only).  fs, ints: the
    scalars (``F_*``, ``I_*``), updated.  A: the controller's arrays (``ControllerArrays`` as a plain tuple,
    ``ControllerState.pack``), updated in place -- afterwards ``kinematic``, ``c_T``, ``R_T`` are the
    support the body must carry this step.  rnd, ant_rnd: pre-drawn doubles of the controller's and
    the antennae's generators, consumed from ints[I_RND_USED], ints[I_ANT_RND_USED].
    err_scratch: (n_seg,) scratch.  Returns whether this step is recorded in the timeline.
    With ints[I_ANT_DEFER] = 1 (``ControllerState.pack`` sets it) the caller calls ``finish_chunk``
    after its last step.
    """
    ca = ControllerArrays(*A)
    # the arrays used more than once, as locals (each read by name)
    states, angles, tips, touching, supported = ca.states, ca.angles, ca.tips, ca.touching, ca.supported
    kinematic, c_T, R_T, geom, terr, entered = ca.kinematic, ca.c_T, ca.R_T, ca.geom, ca.terr, ca.entered
    O, M, ant_f, root_target, arrived, ant_params = ca.O, ca.M, ca.ant_f, ca.root_target, ca.arrived, ca.ant_params
    dt = fs[F_DT]
    kind = ints[I_TERR_KIND]
    n_seg = c.shape[0]
    n_legs = states.shape[0]
    step = ints[I_STEP]
    if step > 0:  # record_tracking: how well the body followed the last step's targets
        m = np.int64(0)  # not the literal 0: it would compile a second signature of numpy_sum
        for i in range(n_seg):
            if supported[i]:
                dx = c[i, 0] - c_T[i, 0]
                dy = c[i, 1] - c_T[i, 1]
                dz = c[i, 2] - c_T[i, 2]
                err_scratch[m] = math.sqrt(dx * dx + dy * dy + dz * dz)
                m += 1
        fs[F_TRACKING_SUM] += numpy_sum(err_scratch, m)
        ints[I_TRACKING_N] += m
    if step == 0:
        L.legs_forward_kinematics(c, R, geom, angles, O, M, tips)
        ints[I_TIP_PHI_OK] = 0
    # 1. antennae (food is not compiled)
    has_ant = ints[I_HAS_ANTENNAE] != 0
    if has_ant:
        links = ints[I_ANT_DEFER] == 0 or ant_f[AN.H_NOBST] > 0.0
        # the antennae's state as the plain tuples that ``antennae_step`` is compiled for (its AntennaMotion,
        # AntennaContact and AntennaShape fields, in their order)
        n_rising, any_arrived = AN.antennae_step(c[0], R[0], t, dt, ant_params, ant_f,
                                                 (ca.nominal, ca.offsets, root_target, ca.root_omega, ca.retracting),
                                                 (ca.contact, ca.rising, ca.contact_point, ca.contact_normal,
                                                  ca.contact_depth, arrived), (ca.points, ca.frames), links)
        if not links:
            fs[F_ANT_T] = t
            ints[I_ANT_PENDING] = 1
        ints[I_CONTACT_EVENTS] += n_rising
        if any_arrived:
            for a in range(2):
                if arrived[a]:  # Antennae._draw: uniform(theta range), then uniform(phi range)
                    u = ant_rnd[ints[I_ANT_RND_USED]]
                    lo, hi = ant_params[AN.P_TH_LO], ant_params[AN.P_TH_HI]
                    root_target[a, 0] = lo + (hi - lo) * u
                    u = ant_rnd[ints[I_ANT_RND_USED] + 1]
                    lo, hi = ant_params[AN.P_PH_LO], ant_params[AN.P_PH_HI]
                    root_target[a, 1] = lo + (hi - lo) * u
                    ints[I_ANT_RND_USED] += 2
                    ints[I_TARGETS_DRAWN] += 1
    # 2. head: brain mode
    if ints[I_TIP_PHI_OK] != 0:  # legs.tips_touching on the tips' distances measured after they last moved
        cd = fs[F_CONTACT_DIST]
        for k in range(n_legs):
            touching[k] = ca.tip_phi[k] <= cd
    else:
        L.tips_touching(kind, terr, tips, fs[F_CONTACT_DIST], touching)
    n_touch = 0
    for k in range(n_legs):
        if touching[k]:
            n_touch += 1
    frac = n_touch / n_legs
    brain = ints[I_BRAIN]
    if brain == ADJUSTMENT and frac > fs[F_MAJORITY]:
        brain = ints[I_WALK_MODE]
        fs[F_T_WALK] = t
        fs[F_TOUCH_AT_WALK] = frac
    brain = _switch_brain(brain, t, fs, ints, has_ant, ca.contact)
    ints[I_BRAIN] = brain
    ca.brain_steps[brain] += 1
    speed, rate, turn_dir = _head_command(brain, t, dt, fs, ints, rnd, ca.sched_t, ca.sched_speed, ca.sched_rate)
    turn = turn_dir * rate * dt
    tm = fs[F_TURN_MEMORY]
    if ((brain == AVOIDANCE or brain == TROPHOTROPISM) and abs(tm + turn) > fs[F_MAX_BODY_TURN]
            and abs(tm + turn) > abs(tm)):
        rate, turn_dir, turn = 0.0, 0.0, 0.0
    fs[F_TURN_MEMORY] = tm * math.exp(-speed * dt / fs[F_TURN_MEMORY_LENGTH]) + turn
    if brain == CONTROL:
        heading = math.atan2(-R[0, 2, 0], R[0, 0, 0])
        if math.isnan(fs[F_HEADING_CMD]):
            fs[F_HEADING_CMD] = heading
        err = (heading - fs[F_HEADING_CMD] + math.pi) % (2 * math.pi) - math.pi
        fs[F_HEADING_ERR_SUM] += abs(err)
        ints[I_HEADING_ERR_N] += 1
        fs[F_HEADING_CMD] += turn_dir * rate * dt
    # 3. rigid segments
    TG.segments_supported(states, ints[I_MIN_STANCE], supported)
    for i in range(n_seg):
        kinematic[i] = supported[i]
    kinematic[0] = brain != ADJUSTMENT
    TG.targeter_step(c, R, kinematic, kind, ca.terr_walk, ca.tg_params, ca.link_rest, ca.height_target, speed, rate,
                     turn_dir, dt, c_T, R_T)
    if ca.terr_walls[TG.H_NOBST] > 0.0:  # no call (and no reference counts) on a terrain without walls
        ints[I_WALL_PUSHES] += TG.keep_clear_of_walls(c_T, R_T, kinematic, ca.terr_walls, ca.seg_half)
    # 4. legs
    collide = ints[I_COLLIDE] != 0
    if collide:
        # element-wise, not prev_angles[:, :] = angles: an array copied into a slice compiles numba's
        # shape-mismatch message (string formatting, seconds of compile per process; README Development notes)
        for k in range(n_legs):
            for a in range(angles.shape[1]):
                ca.prev_angles[k, a] = angles[k, a]
    SW.switcher_step(states, angles, ca.airborne, touching, ca.ik_failed, ca.sw_params, dt, entered)
    if collide:
        ints[I_LEG_STUCK] += LC.stop_swinging_legs(states, ca.prev_angles, angles, c_T, R_T, geom, kind, terr,
                                                   ca.stopped)
        for k in range(n_legs):
            if ca.stopped[k]:
                ints[I_LEG_STOPS] += 1
    SW.fix_stance_tips(entered, c_T, R_T, geom, angles, tips)
    if collide:
        LC.surface_touchdown_tips(entered, tips, kind, terr)
    # the STANCE legs' IK, theta_min (rule 3), the FK of all legs with planted tips kept: the controller's
    # stance_inverse_kinematics, its theta_min test and legs_forward_kinematics in one pass (same doubles)
    L.stance_ik_and_fk(states, SW.STANCE, c_T, R_T, geom, tips, angles, ca.ik_failed, fs[F_THETA_MIN], O, M)
    # stance_knees_inside (with collisions) and legs_penetration, each knee's distance taken once; the tips'
    # distances kept for the next step's contact test
    fs[F_LEG_PEN_MAX] = max(fs[F_LEG_PEN_MAX], LC.knees_inside_and_penetration(states, M, tips, kind, terr, collide,
                                                                               ca.ik_failed, ca.tip_phi))
    ints[I_TIP_PHI_OK] = 1
    recorded = step % ints[I_RECORD_EVERY] == 0
    ints[I_RECORDED] = recorded
    ints[I_STEP] = step + 1
    return recorded
