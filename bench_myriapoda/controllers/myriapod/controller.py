"""The myriapod's decentralized leg controller and head (paper Sec. 4, update order of Sec. 6).

One ``step`` per time step, in the paper's order:

1. antennae (Sec. 5.2, ``antennae.py``) -- the root links turn toward random
   targets, the other links follow their wave, an antenna touching an obstacle
   retracts and signals a left/right contact; the antenna tips sense the food
   (``world/food.py``), and food within reach of the head is eaten;
2. head -- the brain switches modes (Sec. 4.3): ADJUSTMENT while at most
   ``adjustment_majority`` of the legs touch the ground (the head follows the
   dynamics); then, by priority, AVOIDANCE (an antenna touches an obstacle, or
   touched one less than ``avoid_hold_s`` ago: the head turns away from the
   antenna that touched first, or from the ``avoid_priority`` one while both
   touch, and keeps that direction to the episode's end), TROPHOTROPISM (an
   antenna tip's food signal exceeds ``food.threshold``: the head turns toward
   the stronger tip), RANDOM-WALK otherwise -- or CONTROL throughout when the
   scenario commands it (the head is moved kinematically); the antenna-driven
   turns are limited so that the body cannot fold (``max_body_turn_deg``);
3. rigid segments -- the Targeter (Balancer, then Follower) gives every
   segment a target pose; supported segments (enough legs in STANCE) are
   handed to the body to be moved there kinematically, the rest follow the
   dynamics;
4. legs -- the Switcher updates the states, STANCE legs solve the IK of App. B
   against the target poses (a failure sends the leg to SF1 on the next
   step), the others move by forward kinematics;
5. deformable segments -- the body's dynamic step, which the runner calls after this.

As a ``core.protocols.Controller`` it is closed-loop at every time step (``rate_hz`` = 0): it
reads the segment poses of the observation (``seg_pos``, ``seg_rot``) and writes the supported
segments and their target poses into the actuation (``support_kinematic``, ``support_c``,
``support_R``); the body carries them (``apply_support``) before its step.  It never sees the
body itself, so the same controller drives the hybrid, mass-spring and FEM myriapods.

The kernels (``targeter``, ``switcher``, ``kinematics.legs``) run in numba; this
class only sequences them, a few calls per time step.  ``compiled.controller_step`` is the
same step as one numba kernel on this object's arrays (the runner's fused path,
``bench_myriapoda.fused``, runs it with the body's step in one call per chunk); this class
stays the reference, and the path for what that kernel does not cover (food, the body wave).
"""
from __future__ import annotations

import math

import numpy as np

from ...core.leg_timeline import LeggedSummary, LegsPose, LegTimeline
from ...core.protocols import LEGS, SEGMENTS
from ...kinematics import legs as L
from ...world import terrain_kernels as TK
from ...world.food import FoodField
from ...world.terrain import base_height
from ...world.world import world_of
from . import leg_collision as LC
from . import switcher as SW
from . import targeter as TG
from .antennae import LEFT, RIGHT, Antennae

# The stages of one step, in order (paper Sec. 6; ``MyriapodController.step``'s docstring says what each does).
# This is the one statement of the order: ``MyriapodController.step`` runs these stages in this order and
# ``compiled.controller_step`` (the fused path) all but ``compiled.PYTHON_ONLY`` in the same order, and
# tests/test_controller_step_order.py reads both functions' calls and fails when either departs from it.
STEP_ORDER = (
    "tracking",               # how well the body followed the last step's targets
    "forward_kinematics",     # the tips of the starting pose (first step only)
    "antennae",               # 1. antennae
    "food",                   #    their food signals, eating
    "touching",               # 2. head: which tips touch the ground
    "brain",                  #    the brain mode
    "head",                   #    the head's command
    "supported",              # 3. rigid segments: which are supported
    "targeter",               #    their target poses (Balancer, Follower)
    "walls",                  #    the carried segments kept out of walls
    "body_wave",              #    the lateral body wave on the targets
    "switcher",               # 4. legs: the Switcher
    "stop_legs",              #    swing moves cut at surfaces
    "stance_tips",            #    tips of legs entering STANCE
    "touchdown",              #    those tips onto the surface
    "stance_ik",              #    STANCE legs' IK and theta_min
    "forward_kinematics",     #    the other legs' FK
    "knees_and_penetration",  #    STANCE knees inside lift next step; deepest penetration
)

# brain modes (Sec. 4.3) in priority order
ADJUSTMENT, AVOIDANCE, TROPHOTROPISM, RANDOM_WALK, CONTROL = range(5)
BRAIN_MODE_NAMES = ("ADJUSTMENT", "AVOIDANCE", "TROPHOTROPISM", "RANDOM-WALK", "CONTROL")
# the state of the swing loop SF1 -> SF2 -> SB1 -> SB2 whose target pose each state starts from
SWING_LOOP_PREVIOUS = {SW.SF1: SW.SB2, SW.SF2: SW.SF1, SW.SB1: SW.SF2, SW.SB2: SW.SB1}
TURN_LEFT, TURN_RIGHT = 1.0, -1.0  # turn_dir of the head: + = left (a positive rotation about +y)


def follower_feedforward(case) -> bool:
    """Whether the Targeter's Follower adds the head's commanded speed (``targeter``'s module docstring):
    ``controller.follower_feedforward`` 'on' / 'off', or at 'auto' in the dynamic stance only (the paper's
    kinematic stance keeps the paper's Follower)."""
    mode = case.controller.follower_feedforward
    return mode == "on" or (mode == "auto" and case.legs.stance == "dynamic")


def avoidance_turn(left: bool, right: bool, priority: str) -> float:
    """Turn direction (+1 left, -1 right) for antenna contacts (Sec. 5.2, Braitenberg):
    a left contact turns right, a right contact left; when both touch, the ``priority``
    antenna wins (priority "left": turn right).  0 without contact."""
    if left and right:
        return TURN_RIGHT if priority == "left" else TURN_LEFT
    if left:
        return TURN_RIGHT
    if right:
        return TURN_LEFT
    return 0.0


def _obstacles_by_height(sc, kind: int, f: np.ndarray, max_height_m: float) -> tuple[list, list]:
    """f's obstacle records split into (those rising at most ``max_height_m`` above the base surface, the others)."""
    low, tall = [], []
    for r in TK.obstacle_records(f):
        if r[0] == TK.OBST_CYLINDER:
            top = r[5] - float(base_height(sc, kind, f, r[1], r[2]))
        else:  # box: the highest corner above the base at its centre
            top = r[2] + r[5] - float(base_height(sc, kind, f, r[1], r[3]))
        (low if top <= max_height_m else tall).append(r)
    return low, tall


def _base_only(f: np.ndarray) -> np.ndarray:
    """f's base surface without its obstacle block."""
    base = np.array(f[:int(f[TK.H_OBST])])
    base[TK.H_OBST] = 0.0
    base[TK.H_NOBST] = 0.0
    return base


def walkable_terrain(sc, kind: int, f: np.ndarray, max_height_m: float) -> np.ndarray:
    """f without the obstacles that rise more than ``max_height_m`` above the base surface.

    The Balancer (Sec. 4.1) keeps a segment at its height above the surface below
    it and turns it upright to that surface's normal, through the nearest-surface
    queries of ``terrain_kernels``.  An obstacle lower than the standing height is
    ground the creature walks over (Fig. 13); a taller one is a wall (Sec. 6.2's
    "vertical obstacles"): a segment walking past it within its standing height
    would take the wall for the ground and roll toward it.  So the Targeter sees
    the ground and the low obstacles only; legs and bodies still touch them all.
    """
    if f[TK.H_NOBST] <= 0:
        return f
    keep, _ = _obstacles_by_height(sc, kind, f, max_height_m)
    if len(keep) == f[TK.H_NOBST]:
        return f
    base = _base_only(f)
    return TK.with_obstacles(base, keep) if keep else base


def wall_terrain(sc, kind: int, f: np.ndarray, max_height_m: float) -> np.ndarray:
    """A terrain array holding only f's walls: the obstacles ``walkable_terrain`` leaves out (none: no obstacle
    block: f itself when it has no obstacles).  The Targeter keeps the carried segments' boxes out of them (``targeter.keep_clear_of_walls``)."""
    if f[TK.H_NOBST] <= 0:
        return f
    _, tall = _obstacles_by_height(sc, kind, f, max_height_m)
    base = _base_only(f)
    return TK.with_obstacles(base, tall) if tall else base


def standing_height(geom_row: np.ndarray, params: np.ndarray) -> float:
    """Height of a segment centre above flat ground when a leg stands at (0, alpha_S, beta_S) [m]."""
    O, M, P = np.zeros((1, 3)), np.zeros((1, 3)), np.zeros((1, 3))
    L.legs_forward_kinematics(np.zeros((1, 3)), np.eye(3)[None], geom_row[None].copy(),
                              np.array([[0.0, params[SW.ALPHA_S], params[SW.BETA_S]]]), O, M, P)
    return float(-P[0, 1])


class MyriapodController:
    """Legs, Switchers, Targeters and the head of one myriapod.

    State: ``states`` (n_legs,) leg states; ``angles`` (n_legs, 3) [rad];
    ``tips`` (n_legs, 3) [m] world tip positions (fixed while in STANCE);
    ``brain`` the head's mode.  A timeline of leg states and tips (``leg_timeline``, a
    ``core.leg_timeline.LegTimeline``) is recorded every ``record_every`` steps for the gait metrics;
    ``legs_pose``, ``place_on`` and ``summary`` are the rest of what the harness reads
    (``core.leg_timeline.LeggedController``).
    """

    requires = frozenset({SEGMENTS, LEGS})
    open_loop = False
    rate_hz = 0.0  # every time step, as the paper (Sec. 6)

    def __init__(self, case, n_segments: int | None = None, segment_pitch_m: float | None = None,
                 record_every: int = 10, segment_half_extents: np.ndarray | None = None, world=None):
        self.case = case
        self.record_every = record_every
        # the run's world (``world.world.World``: its terrain and food), built once by the runner; built from
        # the case at set-up when not given (a controller made alone)
        self.world = world
        if n_segments is not None:
            self._setup(case, n_segments, segment_pitch_m, segment_half_extents)

    def reset(self, case, body_info, rng=None) -> None:
        """Build the legs for the body's segments (``body_info``: n_segments, segment_pitch_m, and the boxes'
        segment_half_extents, which keep the carried segments out of walls; without them they are not kept out).

        The controller draws from its own generators seeded by ``case.seed`` (not ``rng``), so a
        run is the same whichever way it is started."""
        self._setup(case, int(body_info["n_segments"]), float(body_info["segment_pitch_m"]),
                    body_info.get("segment_half_extents"))

    def _setup(self, case, n_segments: int, segment_pitch_m: float, segment_half_extents=None) -> None:
        record_every = self.record_every
        lg, ct, sc = case.legs, case.controller, case.scenario
        self.n_seg = n_segments
        self.n_legs = 2 * n_segments
        self.dt = case.dt
        self.geom = L.leg_geometry(n_segments, (lg.root_x_m, lg.root_y_m, lg.root_z_m), lg.femur_m, lg.tibia_m,
                                   math.radians(lg.gamma_deg))
        d = math.radians
        self.sw_params = SW.switcher_params(
            theta_aep=d(ct.theta_aep_deg), theta_pep=d(ct.theta_pep_deg), alpha_s=d(ct.alpha_s_deg),
            beta_s=d(ct.beta_s_deg), alpha_mup=d(ct.alpha_mup_deg), alpha_mdp=d(ct.alpha_mdp_deg),
            adj_d_theta=d(ct.adjust_d_theta_deg), adj_d_alpha=d(ct.adjust_d_alpha_deg),
            adj_d_beta=d(ct.adjust_d_beta_deg), swing_speed=ct.swing_speed_rad_s,
            adjust_from_stance=ct.adjust_from_stance,
            wave_direction=SW.RETROGRADE if ct.wave_direction == "retrograde" else SW.DIRECT)
        self.tg_params = TG.targeter_params(k1=ct.k1, k2=ct.k2, omega_follow=d(ct.omega_follow_deg_s),
                                            omega_balance=d(ct.omega_balance_deg_s),
                                            follow_feedforward=follower_feedforward(case))
        self.world = world_of(case, self.world)
        self.terr_kind, self.terr = self.world.terrain
        self.contact_distance = lg.contact_distance_m
        self.theta_min = self.sw_params[SW.THETA_PEP]
        h = ct.target_height_m if ct.target_height_m >= 0 else standing_height(self.geom[1], self.sw_params)
        self.height_target = np.full(n_segments, h)
        self.terr_walk = walkable_terrain(sc, self.terr_kind, self.terr, h)  # what the Balancer stands on
        # what the carried segments' boxes are kept out of (targeter.keep_clear_of_walls); no walls without the boxes
        self.seg_half = (np.zeros((n_segments, 3)) if segment_half_extents is None
                         else np.ascontiguousarray(segment_half_extents, dtype=float).reshape(n_segments, 3))
        self.terr_walls = (wall_terrain(sc, self.terr_kind, self.terr, h) if segment_half_extents is not None
                           else TK.header())
        self.link_rest = np.full(n_segments, segment_pitch_m)
        self.min_stance = ct.min_stance_legs
        self.majority = ct.adjustment_majority
        self.walk_mode = CONTROL if sc.brain == "control" else RANDOM_WALK
        self.schedule = (np.array(sc.control_times_s), np.array(sc.control_speed_m_s),
                         np.radians(np.array(sc.control_turn_rate_deg_s)))
        self.head_speed = ct.head_speed_m_s
        self.turn_max = d(ct.random_turn_max_deg)
        self.turn_rate = d(ct.random_turn_rate_deg_s)
        self.rng = np.random.default_rng(case.seed)
        # antennae and food (Sec. 5.2); the antennae draw from their own generator, so the legs' and the
        # random walk's draws are the same with or without them
        self.antennae = (Antennae(case.antennae, case.dt, np.random.default_rng([case.seed, 7]), self.terr)
                         if case.antennae.enabled else None)
        self.food = FoodField.from_case(case, self.world.food)
        self.has_food = len(self.food) > 0
        self.food_threshold = case.food.threshold
        self.food_signal = np.zeros(2)   # left, right antenna tip
        self.avoid_rate = d(ct.avoid_turn_rate_deg_s)
        self.avoid_hold = ct.avoid_hold_s
        self.avoid_speed = ct.avoid_speed_factor * ct.head_speed_m_s
        self.avoid_priority = ct.avoid_priority
        self.forage_rate = d(ct.forage_turn_rate_deg_s)
        self.forage_gain = ct.forage_gain
        self._avoid_dir = 0.0            # AVOIDANCE: +1 left / -1 right
        # the head's recent turning [rad]: turns weighted by exp(-path / body length) (see step)
        self._turn_memory = 0.0
        self.turn_memory_length = n_segments * segment_pitch_m
        self.max_body_turn = d(ct.max_body_turn_deg)
        self._avoid_until = -math.inf    # AVOIDANCE lasts until this time [s] after the last contact
        self.brain_steps = np.zeros(len(BRAIN_MODE_NAMES), dtype=np.int64)  # steps spent in each mode
        self.brain = ADJUSTMENT
        self.t_walk = math.nan  # when ADJUSTMENT ended
        self.touch_fraction_at_walk = math.nan
        self._turn_left = 0.0   # RANDOM-WALK: angle still to turn [rad], sign = direction
        # legs start in the air at random points of their swing loop SF1 -> SF2 -> SB1 -> SB2 (seeded):
        # a dropped animal's legs are not in lockstep, and a synchronous start is a fixed point of rule 4
        self.states = self.rng.choice([SW.SF1, SW.SF2, SW.SB1, SW.SB2], size=self.n_legs).astype(np.int64)
        start = np.array([SW.target_pose(SWING_LOOP_PREVIOUS[int(s)], self.sw_params) for s in self.states])
        end = np.array([SW.target_pose(s, self.sw_params) for s in self.states])
        self.angles = start + self.rng.uniform(0.0, 1.0, (self.n_legs, 1)) * (end - start)
        self.tips = np.zeros((self.n_legs, 3))
        self._O, self._M = np.zeros((self.n_legs, 3)), np.zeros((self.n_legs, 3))
        self.touching = np.zeros(self.n_legs, dtype=bool)
        self.airborne = np.ones(self.n_legs, dtype=bool)
        self.ik_failed = np.zeros(self.n_legs, dtype=bool)
        self.entered = np.zeros(self.n_legs, dtype=bool)
        self.supported = np.zeros(n_segments, dtype=bool)
        self.kinematic = np.zeros(n_segments, dtype=bool)
        self.c_T = np.zeros((n_segments, 3))
        self.R_T = np.zeros((n_segments, 3, 3))
        self.record_every = record_every
        self._step = 0
        self.recorded = False  # whether the last step was recorded in the timeline
        # what the harness and the metrics read of the run (core.leg_timeline): one row every record_every steps
        self.leg_timeline = LegTimeline(self.n_legs, n_segments)
        self.tracking_sq_sum = 0.0
        self.tracking_n = 0
        self.heading_cmd = math.nan       # CONTROL: commanded heading [rad] about +y, integrated from the schedule
        self.heading_err_sum = 0.0
        self.heading_err_n = 0
        # legs against the terrain and obstacles (issue 16, leg_collision.py)
        self.collide = lg.collide
        self._prev_angles = np.zeros((self.n_legs, 3))
        self._stopped = np.zeros(self.n_legs, dtype=bool)
        self.leg_stops = 0              # swing moves cut at a surface, summed over legs and steps
        self.leg_stuck = 0              # leg-steps left inside with no way out (see stop_swinging_legs)
        self.wall_pushes = 0            # carried segments moved out of a wall (targeter.keep_clear_of_walls)
        self.leg_penetration_max = 0.0  # deepest knee or tip inside the terrain over the run [m]
        # lateral body wave phase-locked to the leg wave (beyond the paper; see _apply_body_wave)
        self.wave_amp = ct.body_wave_amplitude
        self.wave_offset = ct.body_wave_phase_rad
        # phase lag [rad] of segment i behind the head: body_wave_number waves over the n segments
        self.wave_lag = 2.0 * math.pi * ct.body_wave_number * np.arange(n_segments) / n_segments
        self._wave_yaw = np.zeros(n_segments)   # yaw offset [rad] each segment's pose carries now

    # ------------------------------------------------------------------ the head (Sec. 4.3)
    def _sense_food(self, c: np.ndarray, R: np.ndarray, t: float) -> None:
        """Sec. 6 step 1, after the antennae: their tips' food signals; eat what is in reach."""
        if self.has_food:
            if self.antennae is not None:
                self.food.signals_at_tips(self.antennae.points, self.food_signal)
            self.food.eat(c[0], R[0], t)

    def _switch_brain(self, t: float) -> None:
        """Sec. 4.3 priorities once walking: AVOIDANCE > TROPHOTROPISM > RANDOM-WALK (CONTROL stays)."""
        if self.brain in (ADJUSTMENT, CONTROL):
            return
        ant = self.antennae
        left = ant is not None and bool(ant.contact[LEFT])
        right = ant is not None and bool(ant.contact[RIGHT])
        if left or right:
            # a new episode turns away from the touching antenna (both: from the priority one); the direction
            # then holds to the episode's end, except that both antennae touching at once hand it to the
            # priority antenna -- so a head facing a wall or a post between its antennae does not swing
            # back and forth into it
            if self.brain != AVOIDANCE or (left and right):
                self._avoid_dir = avoidance_turn(left, right, self.avoid_priority)
            self._avoid_until = t + self.avoid_hold
            self.brain = AVOIDANCE
        elif self.brain == AVOIDANCE and t < self._avoid_until:
            pass  # keep turning the same way for avoid_hold_s after the last contact
        elif ant is not None and self.has_food and max(self.food_signal[0],
                                                        self.food_signal[1]) > self.food_threshold:
            self.brain = TROPHOTROPISM
        else:
            self.brain = RANDOM_WALK

    def _head_command(self, t: float) -> tuple[float, float, float]:
        """(speed [m/s], turn rate [rad/s], turn direction +1 left / -1 right / 0) of the head."""
        if self.brain == AVOIDANCE:
            return self.avoid_speed, self.avoid_rate, self._avoid_dir
        if self.brain == TROPHOTROPISM:
            # toward the stronger side, proportionally to the normalized left-right difference
            sl, sr = self.food_signal
            rel = (sl - sr) / (sl + sr)
            return (self.head_speed, self.forage_rate * min(1.0, self.forage_gain * abs(rel)),
                    TURN_LEFT if rel > 0 else TURN_RIGHT if rel < 0 else 0.0)
        if self.brain == CONTROL:
            times, speed, rate = self.schedule
            k = max(int(np.searchsorted(times, t, side="right")) - 1, 0)
            return speed[k], abs(rate[k]), math.copysign(1.0, rate[k]) if rate[k] != 0 else 0.0
        if self.brain == RANDOM_WALK:
            if abs(self._turn_left) <= self.turn_rate * self.dt:
                # target attained: a new random direction and target angle (Sec. 4.3)
                self._turn_left = self.rng.uniform(-self.turn_max, self.turn_max)
            step = math.copysign(min(abs(self._turn_left), self.turn_rate * self.dt), self._turn_left)
            self._turn_left -= step
            return self.head_speed, self.turn_rate, math.copysign(1.0, step) if step != 0 else 0.0
        return 0.0, 0.0, 0.0

    # ------------------------------------------------------------------ one step (Sec. 6)
    def step(self, obs, t: float, act) -> None:
        """Update head, segment targets and legs for the step starting at t; write the supported
        segments and their targets into ``act`` (``core.protocols.Actuation``).

        obs: ``core.protocols.Observation`` with seg_pos (n, 3) [m] and seg_rot (n, 3, 3).
        """
        dt = self.dt
        c, R = obs.seg_pos, obs.seg_rot
        if self._step > 0:  # how well the body followed the last step's targets
            self.record_tracking(c)
        if self._step == 0:  # the tips of the starting pose
            L.legs_forward_kinematics(c, R, self.geom, self.angles, self._O, self._M, self.tips)
        # 1. antennae (and food)
        if self.antennae is not None:
            self.antennae.step(c[0], R[0], t)
        self._sense_food(c, R, t)
        # 2. head: brain mode
        L.tips_touching(self.terr_kind, self.terr, self.tips, self.contact_distance, self.touching)
        if self.brain == ADJUSTMENT and self.touching.mean() > self.majority:
            self.brain = self.walk_mode
            self.t_walk = t
            self.touch_fraction_at_walk = float(self.touching.mean())
        self._switch_brain(t)
        self.brain_steps[self.brain] += 1
        speed, rate, turn_dir = self._head_command(t)
        # The Followers cut a sustained tight turn ever shorter (each segment follows the one ahead on a
        # smaller circle, a tractrix) until the chain folds.  So the antenna-driven turns keep the head's
        # recent turning -- summed over about the last body length of its path, weighted by
        # exp(-distance / body length) -- within max_body_turn_deg; past it the head goes straight on.
        turn = turn_dir * rate * dt
        if (self.brain in (AVOIDANCE, TROPHOTROPISM) and abs(self._turn_memory + turn) > self.max_body_turn
                and abs(self._turn_memory + turn) > abs(self._turn_memory)):
            rate, turn_dir, turn = 0.0, 0.0, 0.0
        self._turn_memory = self._turn_memory * math.exp(-speed * dt / self.turn_memory_length) + turn
        if self.brain == CONTROL:
            heading = math.atan2(-R[0, 2, 0], R[0, 0, 0])  # the head's x axis seen from above (about +y)
            if math.isnan(self.heading_cmd):
                self.heading_cmd = heading
            err = (heading - self.heading_cmd + math.pi) % (2 * math.pi) - math.pi
            self.heading_err_sum += abs(err)
            self.heading_err_n += 1
            self.heading_cmd += turn_dir * rate * dt
        # 3. rigid segments: supported ones are kinematic; the head is kinematic unless adjusting
        TG.segments_supported(self.states, self.min_stance, self.supported)
        self.kinematic[:] = self.supported
        self.kinematic[0] = self.brain != ADJUSTMENT
        TG.targeter_step(c, self._without_body_wave(R), self.kinematic, self.terr_kind, self.terr_walk,
                         self.tg_params, self.link_rest, self.height_target, speed, rate, turn_dir, dt, self.c_T,
                         self.R_T)
        if self.terr_walls[TK.H_NOBST] > 0:  # no kernel call (a numba dispatch of five arrays) without walls
            self.wall_pushes += TG.keep_clear_of_walls(self.c_T, self.R_T, self.kinematic, self.terr_walls,
                                                       self.seg_half)
        if self.wave_amp > 0.0:
            self._apply_body_wave(R)
        act.support_kinematic[:] = self.kinematic
        act.support_c[:] = self.c_T
        act.support_R[:] = self.R_T
        act.support_new = True
        # the feet, for a body in dynamic stance (bodies.dynamic_stance): it reads the STANCE legs' tips after
        # this step and moves those that slide, so it is handed the arrays themselves
        act.support_states = self.states
        act.support_tips = self.tips
        # 4. legs: Switcher, then IK (STANCE) or FK (the others) against the target poses
        if self.collide:
            self._prev_angles[:] = self.angles
        SW.switcher_step(self.states, self.angles, self.airborne, self.touching, self.ik_failed, self.sw_params,
                         dt, self.entered)
        if self.collide:
            self._stop_legs_at_surfaces()
        SW.fix_stance_tips(self.entered, self.c_T, self.R_T, self.geom, self.angles, self.tips)
        if self.collide:
            LC.surface_touchdown_tips(self.entered, self.tips, self.terr_kind, self.terr)
        SW.stance_inverse_kinematics(self.states, self.c_T, self.R_T, self.geom, self.tips, self.angles,
                                     self.ik_failed)
        # App. B's "cannot resolve" includes the leg's joint range: a STANCE leg swept behind its
        # posterior extreme pose (theta < theta_m) must lift (rule 3), as a real leg's range ends there.
        self.ik_failed |= (self.states == SW.STANCE) & (self.angles[:, 0] < self.theta_min)
        stance_tips = self.tips.copy()
        L.legs_forward_kinematics(self.c_T, self.R_T, self.geom, self.angles, self._O, self._M, self.tips)
        in_stance = self.states == SW.STANCE
        self.tips[in_stance] = stance_tips[in_stance]  # a planted tip stays where it touched down
        self._legs_after_kinematics()
        self.recorded = self._step % self.record_every == 0
        if self.recorded:
            self.leg_timeline.append(t, self.states.astype(np.int8), self.tips.copy(), self.brain,
                                     self.antennae.contact.copy() if self.antennae is not None
                                     else np.zeros(2, dtype=bool), c.copy())
        self._step += 1

    # ------------------------------------------------------------------ body wave (beyond the paper)
    def head_leg_phase(self) -> float:
        """Phase [rad] of the head's legs in their cycle: 0 at the AEP, pi at the PEP, 2 pi back at the AEP.

        A leg's phase from its swing angle theta between the PEP (theta_m) and the AEP
        (theta_M): in STANCE pi (theta_M - theta) / (theta_M - theta_m), swinging
        pi + pi (theta - theta_m) / (theta_M - theta_m).  The two head legs' circular mean.
        """
        hi, lo = self.sw_params[SW.THETA_AEP], self.sw_params[SW.THETA_PEP]
        sx = sy = 0.0
        for k in (0, 1):
            u = min(max((self.angles[k, 0] - lo) / (hi - lo), 0.0), 1.0)
            ph = math.pi * (1.0 - u) if self.states[k] == SW.STANCE else math.pi * (1.0 + u)
            sx += math.cos(ph)
            sy += math.sin(ph)
        return math.atan2(sy, sx)

    def _without_body_wave(self, R: np.ndarray) -> np.ndarray:
        """R (n, 3, 3) with each segment's body-wave yaw taken off (R itself without a wave).

        The Targeter then balances and follows the wave-free frames, and the wave is put
        back on its targets (``_apply_body_wave``): the offset does not accumulate and
        the Follower does not fight it.
        """
        if self.wave_amp <= 0.0:
            return R
        Rf = R.copy()
        for i in np.flatnonzero(self._wave_yaw):
            TG.rotate_about_own_axis(Rf[i], 1, -self._wave_yaw[i])
        return Rf

    def _apply_body_wave(self, R: np.ndarray) -> None:
        """Yaw the supported segments' targets toward A sin(psi_head - lag_i + offset) about their own y axes.

        A lateral body wave travelling head to tail like the retrograde leg wave, locked
        to the head legs' phase psi_head (``head_leg_phase``): the Scolopendra body
        wave (about 1.6 waves on the body, best offset near 2.5 rad)
        as a kinematic yaw of the targets, so it works on every body.  Segments
        left to the dynamics keep their current pose (and the yaw it carries).
        """
        psi = self.head_leg_phase()
        goal = self.wave_amp * np.sin(psi - self.wave_lag + self.wave_offset)
        if self.brain == ADJUSTMENT:
            goal[:] = 0.0  # no wave until the creature walks
        # the yaw moves toward the wave at most at the Follower's turn rate: a segment that becomes
        # supported (or the wave that starts) must not snap its body by the whole amplitude in one step
        step = self.tg_params[TG.OMEGA_FOLLOW] * self.dt
        for i in range(self.n_seg):
            if self.kinematic[i]:
                yaw = self._wave_yaw[i] + min(max(goal[i] - self._wave_yaw[i], -step), step)
                TG.rotate_about_own_axis(self.R_T[i], 1, float(yaw))
                self._wave_yaw[i] = yaw
            else:
                self.R_T[i] = R[i]

    # ------------------------------------------------------------------ legs and obstacles (issue 16)
    def _stop_legs_at_surfaces(self) -> None:
        """Cut this step's swing moves where a tip or knee meets the terrain (``leg_collision``)."""
        self.leg_stuck += LC.stop_swinging_legs(self.states, self._prev_angles, self.angles, self.c_T, self.R_T,
                                                self.geom, self.terr_kind, self.terr, self._stopped)
        self.leg_stops += int(self._stopped.sum())

    def _legs_after_kinematics(self) -> None:
        """Deepest knee or tip inside the terrain so far; STANCE knees inside lift their legs next step."""
        if self.collide:
            LC.stance_knees_inside(self.states, self._M, self.terr_kind, self.terr, self.ik_failed)
        self.leg_penetration_max = max(self.leg_penetration_max,
                                       LC.legs_penetration(self.terr_kind, self.terr, self._M, self.tips))

    def leg_metrics(self) -> dict[str, float]:
        """``leg_penetration_max_m`` [m], ``leg_stops`` and ``leg_stuck`` (leg-steps), and ``wall_pushes``
        (segment-steps a carried segment was moved out of a wall) of the run so far."""
        return {"leg_penetration_max_m": self.leg_penetration_max, "leg_stops": float(self.leg_stops),
                "leg_stuck": float(self.leg_stuck), "wall_pushes": float(self.wall_pushes)}

    def record_tracking(self, c: np.ndarray) -> None:
        """Accumulate the squared distance of supported segments from their targets after the body's step."""
        err = np.linalg.norm(c[self.supported] - self.c_T[self.supported], axis=1)
        self.tracking_sq_sum += float(err.sum())
        self.tracking_n += int(err.size)

    # ------------------------------------------------------------------ what the harness reads (core.leg_timeline)
    def legs_pose(self) -> LegsPose:
        """The legs now (``LegsPose``): leg geometry, angles and states, and the antennae's points and contacts."""
        ant = self.antennae
        return LegsPose(self.geom, self.angles, self.states,
                        None if ant is None else ant.points.copy(), None if ant is None else ant.contact.copy())

    def place_on(self, c: np.ndarray, R: np.ndarray) -> None:
        """The antennae on the head's pose c[0], R[0] at t = 0, so that a scene of the starting pose shows
        them (``Antennae.place``: the run's dynamics do not change)."""
        if self.antennae is not None:
            self.antennae.place(c[0], R[0], 0.0)

    def summary(self) -> LeggedSummary:
        """The run so far (``LeggedSummary``): the brain's modes are the summary's modes; ``metrics`` holds the
        legs' surface figures (``leg_metrics``), the food's and the antennae's obstacle contact events."""
        steps = max(int(self.brain_steps.sum()), 1)
        ant = self.antennae
        return LeggedSummary(
            t_walk_s=self.t_walk, touch_fraction_at_walk=self.touch_fraction_at_walk,
            heading_error_deg=float(np.degrees(self.heading_err_sum / self.heading_err_n)) if self.heading_err_n
            else None,
            tracking_error_mean_m=self.tracking_sq_sum / self.tracking_n if self.tracking_n else math.nan,
            mode_final=self.brain, mode_names=BRAIN_MODE_NAMES,
            mode_fractions={name: float(self.brain_steps[mode]) / steps
                            for mode, name in ((AVOIDANCE, "avoidance"), (TROPHOTROPISM, "trophotropism"))},
            metrics={**self.leg_metrics(), **self.food.metrics(),
                     "obstacle_contacts": float(ant.contact_events) if ant is not None else 0.0})

    @property
    def timeline_centers(self) -> list[np.ndarray]:
        """The segment positions (n_seg, 3) [m] of each timeline sample (``LegTimeline.centres``)."""
        return self.leg_timeline.centres

    def contact_timeline(self) -> np.ndarray:
        """Antenna contact (T, 2) bool (left, right) at the timeline's sample times."""
        return self.leg_timeline.contact_array()

    def brain_timeline(self) -> np.ndarray:
        """Brain mode (T,) at the timeline's sample times."""
        return self.leg_timeline.mode_array()

    def timeline(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(t (T,), states (T, n_legs) int8, tips (T, n_legs, 3)) recorded so far."""
        return self.leg_timeline.legs()
