"""Closed-loop tracking of a commanded bending wave: the body bends to the commanded shape under load.

A bending gait commands a shape, ``gait.curvature_amplitude`` (peak curvature x body length L) and
``gait.wavelength_bl``: the curvature at rest arc length s from the head is

    kappa_cmd(s, t) = r(t) (A / L) sin(k s - omega t + phi),    r(t) the start ramp (0 -> 1).

The open-loop controller turns it into LATERAL fibre strain with the body's calibrated gain g
(``bodies/curvature_calibration.py``: strain per unit of curvature x L, measured on a weightless body
on no ground).  Under lateral friction the body does not reach that shape: the muscles' bending
moment must also carry the friction's, and a soft body (the lattice snake at mu_t / mu_f = 5) bent
to a fifth of the command (issue 27).  This tracker closes the loop at ``rate_hz`` ticks per second:

1. **measure**: the heading psi_j of every segment frame seen from above (``Observation.seg_rot``,
   the segment's x axis, left turn positive about +y) gives the curvature between neighbouring
   segments, (psi_{j+1} - psi_j) / pitch, at the midpoint of their rest centres; it is interpolated
   to the muscle segments' arc positions (``muscle_s``).  For the hybrid body the midpoints of the
   boxes are exactly its links, where its muscles are.  Nothing here knows which body it drives;
2. **compare**: both are in strain units, e_i = g L (kappa_cmd - kappa_meas)(s_i, t);
3. **correct**: u_i = r A_s sin(theta_i) + a_i sin(theta_i) + b_i cos(theta_i) + K_p e_i, with
   theta_i = k s_i - omega t + phi and A_s = A g the feed-forward (the open loop's own strain).
   (a_i, b_i) integrate the error's in-phase and quadrature components at the wave frequency,
   da_i/dt = K_i 2 e_i sin(theta_i), db_i/dt = K_i 2 e_i cos(theta_i), K_i = gain per cycle x f:
   over a cycle they remove the error in the wave's amplitude and phase, segment by segment, which a
   plain integral of a sinusoidal error cannot (it averages to zero).  The error e_i is first smoothed
   along the body (``smooth_along_body``, ``SMOOTHING_PASSES`` binomial passes): the tracker corrects
   the shape of a few waves per body; finer content is the body's own.  Without it a proportional term
   fed the fem body's element-scale bending waves (about 5 segments long, ~40 Hz, lightly damped by
   eq. 13's damping): the command held over a tick lags them, so the term pushed them in phase with
   their velocity, and the fem snake blew up within 0.4 s at K_p = 2.  K_p (``gait.shape_gain_p``;
   -1, the default, takes the body's own ``BodySpec.shape_gain_p``) is 2 on the lattice, 0.5 on the
   fem body and 0.25 on the hybrid: smoothed, K_p = 2 still made the fem snake curl beyond the command over ~10 s
   until it rolled onto its back, where the muscles' sign on the ground is reversed and the loop locks
   at full strength (docs/explanation/shape-tracking.md);
3b. **the wave's temporal harmonics** (``gait.shape_harmonics``, default the third, at
   ``gait.shape_harmonic_gain_per_cycle``; -1, the default, takes the body's own
   ``BodySpec.shape_harmonic_gain_per_cycle``: 1 on the lattice and the fem body, 0.5 on the hybrid; 0 switches it
   off): Coulomb friction turns with the direction of slip, so its load on the body is close to
   a square wave in time and bends the body with the wave's odd harmonics (the third about 8 % of the
   fundamental at mu_t / mu_f = 1.5, docs/explanation/shape-tracking.md).  For each harmonic h, u_i also gets
   ah_i sin(h theta_i) + bh_i cos(h theta_i), integrated like (a_i, b_i) from e_i sin(h theta_i) and
   e_i cos(h theta_i), with the update rotated by a phase lead delta (``gait.shape_harmonic_lead_deg``):
   d(ah + i bh)/dt = K_h e^{-i delta} 2 e_i e^{i h theta_i}.  Such an integral converges when the plant's phase
   lag at h omega, from command to measured curvature, is within 90 degrees of delta, and diverges otherwise
   (tests/test_shape_tracking.py's model plant); the lag is the body's, measured, not assumed;
4. **muscle strength**: |u_i| is clipped at ``gait.max_muscle_strain``, the largest active fibre
   strain the muscle can produce.  A clipped command stops its integral from growing further
   (anti-windup) and is counted: ``muscle_saturation_fraction`` is the share of (segment, tick)
   commands clipped over the steady window (after ``metrics.warmup_cycles``).  A body that needs a
   stronger muscle to reach the shape says so there, and its ``shape_tracking_error`` (measured from
   the recorded centres, ``metrics.shape_tracking``) flags ``shape_not_achieved``.

The command is held between ticks (one actuation row, ``core.protocols.Actuation``).
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from ..core.kernel_records import plain
from ..core.protocols import LATERAL_GROUND_SIGN

# wave table columns (controllers.muscle_waves; repeated here to keep this module free of that import)
_AMP, _WAVENUMBER, _OMEGA, _PHASE = 0, 1, 2, 3
_LATERAL = 1
# Binomial passes of the error along the body before it is used (module docstring, step 3): the response
# cos(pi / P)^16 to a profile of period P segments passes the commanded wave (P = 50 or 25 on the snake:
# 0.97, 0.88) and stops the element-scale bending waves (P = 6: 0.10; P <= 4: < 0.004)
SMOOTHING_PASSES = 8


@njit(cache=True, error_model="numpy")
def segment_headings(seg_rot, out):
    """OVERWRITE out (n,) with the heading [rad] of each segment's x axis on the ground, right-handed about
    +y (left turn positive), unwrapped along the body.  seg_rot: (n, 3, 3) segment -> world."""
    prev = 0.0
    for j in range(seg_rot.shape[0]):
        psi = math.atan2(-seg_rot[j, 2, 0], seg_rot[j, 0, 0])
        if j > 0:
            while psi - prev > math.pi:
                psi -= 2.0 * math.pi
            while psi - prev < -math.pi:
                psi += 2.0 * math.pi
        out[j] = psi
        prev = psi


@njit(cache=True, error_model="numpy")
def measured_curvature(seg_rot, s_centre, s_muscle, psi, out):
    """OVERWRITE out (n_m,) with the ground curvature [1/m] at the muscle segments' rest arc positions
    s_muscle (n_m,) [m], from the segment frames seg_rot (n, 3, 3) whose rest centres are s_centre (n,) [m]:
    the turn between neighbouring frames over their rest distance, at the midpoint, interpolated linearly
    (held beyond the first and last midpoint).  psi: (n,) scratch."""
    segment_headings(seg_rot, psi)
    n = s_centre.shape[0]
    j = 0
    for i in range(s_muscle.shape[0]):
        s = s_muscle[i]
        # midpoints m_j = (s_j + s_{j+1}) / 2, j = 0 .. n - 2; find m_j <= s < m_{j+1}
        while j < n - 3 and 0.5 * (s_centre[j + 1] + s_centre[j + 2]) <= s:
            j += 1
        k0 = (psi[j + 1] - psi[j]) / (s_centre[j + 1] - s_centre[j])
        if n < 3:
            out[i] = k0
            continue
        k1 = (psi[j + 2] - psi[j + 1]) / (s_centre[j + 2] - s_centre[j + 1])
        m0 = 0.5 * (s_centre[j] + s_centre[j + 1])
        m1 = 0.5 * (s_centre[j + 1] + s_centre[j + 2])
        w = min(1.0, max(0.0, (s - m0) / (m1 - m0)))
        out[i] = (1.0 - w) * k0 + w * k1


@njit(cache=True, error_model="numpy")
def smooth_along_body(x, passes, tmp):
    """Apply ``passes`` times the binomial filter (1, 2, 1) / 4 along the body to x (n,), in place; the end
    points are mirrored (x[-1] = x[1]), so an alternating profile is removed there too.  tmp: (n,) scratch.
    Its response to a profile of period P segments is cos(pi / P)^(2 passes): 0 at P = 2."""
    n = x.shape[0]
    if n < 3:
        return
    for _ in range(passes):
        for i in range(n):
            tmp[i] = x[i]
        x[0] = 0.5 * (tmp[0] + tmp[1])  # the profile mirrored about each end: (1, 2, 1) with x[-1] = x[1]
        x[n - 1] = 0.5 * (tmp[n - 1] + tmp[n - 2])
        for i in range(1, n - 1):
            x[i] = 0.25 * (tmp[i - 1] + 2.0 * tmp[i] + tmp[i + 1])


# ``track_tick``'s arguments, named records (numba compiles a namedtuple as a struct of its fields, read by name).
# The tracker holds them as records and hands them over as plain tuples (``core.kernel_records``: ``track_tick``
# runs 250 times a simulated second, and numba's dispatcher types a namedtuple argument about twice as slowly
# here), which ``track_tick`` names again.
# The harmonics' fields default to none (empty arrays), the fundamental's tracker alone.
_NO_HARMONICS = (np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0), np.zeros(0))
TrackGains = namedtuple("TrackGains", "ramp_s dt_tick strain_per_kappa kp ki umax passes harmonics ki_h lead_cos lead_sin",
                        defaults=_NO_HARMONICS)
TrackState = namedtuple("TrackState", "a b lateral counts err tmp ah bh", defaults=(np.zeros((0, 0)), np.zeros((0, 0))))


@njit(cache=True, error_model="numpy")
def track_tick(kappa, s_muscle, waves, t, counting, track_gains, track_state):
    """One control tick of the tracker (module docstring, steps 2-4).

    kappa: (n_m,) measured ground curvature [1/m]; s_muscle: (n_m,) [m]; waves: (3, 5) wave table whose LATERAL row
    is the feed-forward; t: the tick's time [s]; counting: count this tick's commands (steady window).  track_gains
    = gains (ramp_s [s], dt_tick [s], strain_per_kappa = g L [strain m] (sign included: the strain of a unit ground
    curvature), kp [-], ki [1/s] (the fundamental's), umax [-], passes: binomial smoothing passes of the error along
    the body before the proportional and integral terms (``smooth_along_body``; module docstring, step 3),
    harmonics: (n_h,) int64 temporal harmonics h >= 2 with their own correction (module docstring, step 3b), ki_h:
    (n_h,) their gains [1/s], lead_cos, lead_sin: (n_h,) cos and sin of the phase lead [rad] each correction's
    update is rotated by), a ``TrackGains`` as a plain tuple.  track_state = state (a, b: (n_m,) the fundamental's
    integral state [strain], updated; lateral: (n_m,) OVERWRITTEN with the clipped LATERAL strain; counts: (3,) +=
    (commands, clipped commands, peak |u| so far) when counting; err, tmp: (n_m,) scratch; ah, bh: (n_h, n_m) the
    harmonics' integral state [strain], updated), a ``TrackState`` as a plain tuple.
    """
    gains, state = TrackGains(*track_gains), TrackState(*track_state)
    ramp_s, dt_tick, strain_per_kappa, kp, ki = gains.ramp_s, gains.dt_tick, gains.strain_per_kappa, gains.kp, gains.ki
    umax, passes, harmonics, ki_h = gains.umax, gains.passes, gains.harmonics, gains.ki_h
    lead_cos, lead_sin = gains.lead_cos, gains.lead_sin
    a, b, lateral, counts, err, tmp, ah, bh = state.a, state.b, state.lateral, state.counts, state.err, state.tmp, \
        state.ah, state.bh
    r = 1.0
    if ramp_s > 0.0 and t < ramp_s:
        r = max(t, 0.0) / ramp_s
    amp = waves[_LATERAL, _AMP]
    k = waves[_LATERAL, _WAVENUMBER]
    om = waves[_LATERAL, _OMEGA]
    ph = waves[_LATERAL, _PHASE]
    n = s_muscle.shape[0]
    n_h = harmonics.shape[0]
    for i in range(n):
        th = k * s_muscle[i] - om * t + ph
        err[i] = r * amp * math.sin(th) - strain_per_kappa * kappa[i]
    smooth_along_body(err, passes, tmp)
    for i in range(n):
        th = k * s_muscle[i] - om * t + ph
        sn, cs = math.sin(th), math.cos(th)
        ref = r * amp * sn
        e = err[i]
        u = ref + a[i] * sn + b[i] * cs + kp * e
        for j in range(n_h):
            hth = harmonics[j] * th
            u += ah[j, i] * math.sin(hth) + bh[j, i] * math.cos(hth)
        clipped = abs(u) > umax
        if not clipped or e * u < 0.0:  # anti-windup: a clipped command's integral only unwinds
            a[i] += ki * dt_tick * 2.0 * e * sn
            b[i] += ki * dt_tick * 2.0 * e * cs
            for j in range(n_h):
                hth = harmonics[j] * th
                ea = 2.0 * e * math.sin(hth)
                eb = 2.0 * e * math.cos(hth)
                # the update rotated back by the plant's lag at this harmonic (module docstring, step 3b)
                ah[j, i] += ki_h[j] * dt_tick * (lead_cos[j] * ea + lead_sin[j] * eb)
                bh[j, i] += ki_h[j] * dt_tick * (lead_cos[j] * eb - lead_sin[j] * ea)
        if clipped:
            u = umax if u > 0.0 else -umax
        lateral[i] = u
        if counting:
            counts[0] += 1.0
            if clipped:
                counts[1] += 1.0
            counts[2] = max(counts[2], abs(u))


def _wrap_deg(x):
    return (np.asarray(x, float) + 180.0) % 360.0 - 180.0


class PlantMargin:
    """The loop's stability margin at the wave frequency, from the body's measured open-loop response.

    ``bodies.curvature_calibration.plant_response`` identifies, at each interior segment, the open loop's curvature
    against the command: gain |G| and lag phi.  The fundamental's amplitude-and-phase integral (step 3), its update
    rotated by a lead delta (0 here), converges at a segment where |phi - delta| < 90 degrees for a linear plant (the
    model plant of tests/test_shape_tracking.py), so its phase margin is 90 - max over the segments of |phi - delta|
    [deg].

    Measured, and not acted on: under Coulomb friction the open loop's response is not the closed loop's plant.  On
    the slithering grid (lattice) the open loop reached 0.97, 0.88, 0.76, 0.58, 0.20 and 0.03 of the command at
    mu_t / mu_f = 1, 1.5, 2, 3, 5 and 10, with margins 25, 21, 11, -10, -88 and -90 degrees, and the closed loop
    tracks every one of those cells (shape error 0.07 or less at 35.7 s); the first runaway case of issue 44 reads
    like the cell at 5 (gain 0.15, margin -90), the default snake 0.99 and 53.  Scheduling the gains by the margin
    (the open loop where there is none) dropped the grid's cells at 5 and 10, and turning the fundamental's update by
    the median lag (a lead, as step 3b's) took the cells at 2 and 3 to shape errors of 0.12 and 0.19.  The guard
    (``LoopGuard``), which watches the closed loop itself, is what keeps the loop from running away."""

    def __init__(self, gain, lag_deg):
        self.gain = np.asarray(gain, float)
        self.lag_deg = _wrap_deg(lag_deg)
        self.lead_deg = 0.0
        self.margin_deg = 90.0 - float(np.max(np.abs(_wrap_deg(self.lag_deg - self.lead_deg))))

    @classmethod
    def of(cls, response) -> "PlantMargin | None":
        """From ``body_info["plant_response"]``; None when the plant was not identified (its status says why)."""
        if not response or response.get("status") != "ok" or not response.get("gain"):
            return None
        return cls(response["gain"], response["lag_deg"])

    def metrics(self) -> dict[str, float]:
        """shape_plant_gain, shape_plant_lag_deg (medians over the segments), shape_loop_margin_deg,
        the loop's phase margin on it."""
        return {"shape_plant_gain": float(np.median(self.gain)), "shape_plant_lag_deg": float(np.median(self.lag_deg)),
                "shape_loop_margin_deg": self.margin_deg}


def scaled_gains(gains: TrackGains, scale: float) -> TrackGains:
    """``gains`` with the loop's gains, the proportional, the fundamental's integral and the harmonics' integral
    ones, times ``scale`` [-]; 0: the calibrated open loop (the feed-forward alone, once the integral state is
    zero)."""
    g = TrackGains(*gains)
    return g._replace(kp=g.kp * scale, ki=g.ki * scale, ki_h=g.ki_h * scale)


# The guard's thresholds (``LoopGuard``): the loop has lost its margin when the body's bend, smoothed like the error,
# exceeds the command by GUARD_AMPLITUDE_RATIO in RMS over the last quarter cycle (under the 25 % a run may overshoot
# by, issue 44), or when more than GUARD_SATURATION of the muscles have been held at their strength over the last
# half cycle ("most muscles saturated") while the body bends at least as commanded.  Each back-off halves the loop's gains (GUARD_BACKOFF) after a period of
# the open loop; after GUARD_MAX_BACKOFFS the open loop stays.
GUARD_AMPLITUDE_RATIO = 1.2
GUARD_SATURATION = 0.5
GUARD_BACKOFF = 0.5
GUARD_MAX_BACKOFFS = 2


class LoopGuard:
    """Watches the closed loop for a runaway and backs it off to the calibrated open loop (``gait.shape_guard``).

    The tracker's integral and proportional terms assume a plant whose response grows in proportion to the command
    and lags it by less than 90 degrees.  Coulomb friction breaks both: a bend costs a friction moment that does not
    grow with the bend, so the body hardly moves until the muscles' moment passes it and then bends far (the lattice
    snake at 0.5 Hz, one wave per body, mu_t = 0.5: 1.5 of a commanded 10 open loop, 40 closed loop with half its
    muscles at their strength; issue 44).  Once the bend passes the command by ``GUARD_AMPLITUDE_RATIO`` while the
    loop commands more than the feed-forward (the loop's doing: a body that overshoots in open loop is pulled back
    by the loop, and left alone here), or most muscles are held at their strength, the integral state is dropped and the command is the feed-forward alone for
    one gait period; then the loop resumes at ``GUARD_BACKOFF`` times its gains, and after ``GUARD_MAX_BACKOFFS``
    back-offs the open loop stays.  The run's ``shape_control_backoffs``, ``shape_control_gain_scale`` and
    ``shape_control_backoff_s`` say what it did, and the runner's status ``controller_unstable`` says when it acted
    in the measured window or ended in the open loop (``ShapeTracker.run_status``)."""

    def __init__(self, period_s: float, t_steady: float, dt_tick: float):
        self.period_s, self.t_steady, self.dt_tick = float(period_s), float(t_steady), float(dt_tick)
        self.reset()

    def reset(self) -> None:
        self.scale = 1.0           # the loop's gain scale once resumed
        self.hold_until = -1.0     # open loop until this time [s]
        self.backoffs = 0
        self.times: list[float] = []
        self.p_meas = 0.0          # mean square of the measured bend [strain^2], low-passed
        self.p_cmd = 0.0           # mean square of the commanded bend, the feed-forward [strain^2], low-passed
        self.p_out = 0.0           # mean square of the loop's command [strain^2], low-passed
        self.sat = 0.0             # share of clipped commands, low-passed

    @property
    def fallen_back(self) -> bool:
        """The open loop for good: the loop lost its margin ``GUARD_MAX_BACKOFFS`` + 1 times."""
        return self.backoffs > GUARD_MAX_BACKOFFS

    def gain_scale(self, t: float) -> float:
        """The loop's gain scale at t [s]: 0 while backed off, else the scale it resumed at."""
        return 0.0 if self.fallen_back or t < self.hold_until else self.scale

    def watch(self, t: float, ramp_s: float, waves, s_muscle, state, umax: float) -> bool:
        """Update the guard with the tick just computed at t [s] (``track_tick``'s state: its smoothed error and its
        command; ramp_s [s]: the start ramp); True when the loop lost its margin at this tick (the caller drops the
        integral state)."""
        amp, k, om, ph = waves[_LATERAL, _AMP], waves[_LATERAL, _WAVENUMBER], waves[_LATERAL, _OMEGA], \
            waves[_LATERAL, _PHASE]
        err, lateral = state.err, state.lateral
        r = 1.0 if ramp_s <= 0.0 or t >= ramp_s else max(t, 0.0) / ramp_s
        ref = (r * amp) * np.sin(k * s_muscle - om * t + ph)
        meas = ref - err  # the measured bend, smoothed along the body like the error [strain]
        a_fast = self.dt_tick / (0.25 * self.period_s)
        a_slow = self.dt_tick / (0.5 * self.period_s)
        self.p_meas += a_fast * (float(np.mean(meas * meas)) - self.p_meas)
        self.p_cmd += a_fast * (float(np.mean(ref * ref)) - self.p_cmd)
        self.p_out += a_fast * (float(np.mean(lateral * lateral)) - self.p_out)
        self.sat += a_slow * (float(np.mean(np.abs(lateral) >= umax)) - self.sat)
        if self.fallen_back or t < self.hold_until or r < 1.0:
            return False
        # the controller's doing: the body bends beyond the command while the loop commands more than the open
        # loop would (a body that overshoots in open loop, which the loop is pulling back, is the body's own)
        overshoot = self.p_meas > GUARD_AMPLITUDE_RATIO ** 2 * self.p_cmd and self.p_out > self.p_cmd
        # most muscles at their strength while the body bends at least as commanded: the loop's doing (a muscle too
        # weak for the load saturates with the body short of the command; that is flagged, not backed off)
        runaway = overshoot or (self.sat > GUARD_SATURATION and self.p_meas > self.p_cmd)
        if not runaway:
            return False
        self.backoffs += 1
        self.times.append(float(t))
        self.scale *= GUARD_BACKOFF
        self.hold_until = t + self.period_s
        self.sat = 0.0
        return True

    def acted_in_window(self) -> bool:
        """The guard backed off in the steady window (after ``metrics.warmup_cycles``) or ended in the open loop."""
        return self.fallen_back or any(tt >= self.t_steady for tt in self.times)


class ShapeTracker:
    """The closed loop of a commanded bending wave (module docstring) for one run."""

    def __init__(self, case):
        g = case.gait
        self.kp_key = float(g.shape_gain_p)  # < 0: the body's own (``BodySpec.shape_gain_p``), set in ``reset``
        self.kp = max(self.kp_key, 0.0)
        self.ki = float(g.shape_gain_i_per_cycle) * float(g.frequency_hz)
        self.umax = float(g.max_muscle_strain)
        self.ramp_s = float(g.ramp_s)
        self.dt_tick = 1.0 / float(g.shape_control_rate_hz)
        self.t_steady = float(case.metrics.warmup_cycles) * g.period_s
        self.body_length = float(case.creature.body_length_m)
        # < 0: the body's own harmonic gain (``BodySpec.shape_harmonic_gain_per_cycle``), set in ``reset``
        self.kh_key = float(g.shape_harmonic_gain_per_cycle)
        self.harmonic_list = tuple(g.shape_harmonics)
        self.frequency_hz = float(g.frequency_hz)
        self.lead_rad = math.radians(float(g.shape_harmonic_lead_deg))
        self._set_harmonics(max(self.kh_key, 0.0))
        self.period_s = float(g.period_s)
        self.plant = None
        self.guard = LoopGuard(self.period_s, self.t_steady, self.dt_tick) if g.shape_guard else None
        self.ready = False

    def _set_harmonics(self, gain_per_cycle: float) -> None:
        """The harmonics corrected at ``gain_per_cycle`` [-]; a gain of 0 switches the correction off: none are
        carried (and the loop is the fundamental's alone, bit for bit)."""
        self.harmonics = np.asarray(self.harmonic_list if gain_per_cycle > 0.0 else (), dtype=np.int64).reshape(-1)
        self.ki_h = np.full(self.harmonics.shape[0], gain_per_cycle * self.frequency_hz)
        lead = np.full(self.harmonics.shape[0], self.lead_rad)
        self.lead_cos, self.lead_sin = np.cos(lead), np.sin(lead)

    def reset(self, body_info, strain_per_curvature: float) -> None:
        """Prepare for a body: its muscle arc positions, pitch and the calibrated gain [strain per curvature x L]."""
        self.s_muscle = np.ascontiguousarray(body_info["muscle_s"], dtype=np.float64)
        self.pitch = float(body_info["segment_pitch_m"])
        self.strain_per_kappa = LATERAL_GROUND_SIGN * strain_per_curvature * self.body_length
        self.kp = self.kp_key if self.kp_key >= 0.0 else float(body_info.get("shape_gain_p", 0.0))
        self._set_harmonics(self.kh_key if self.kh_key >= 0.0
                            else float(body_info.get("shape_harmonic_gain_per_cycle", 0.0)))
        n = self.s_muscle.shape[0]
        self.kappa = np.zeros(n)
        # the open loop's measured response and the loop's margin on it: measured and reported, not acted on
        # (``PlantMargin`` says why)
        self.plant = PlantMargin.of(body_info.get("plant_response"))
        self.gains = TrackGains(ramp_s=self.ramp_s, dt_tick=self.dt_tick, strain_per_kappa=self.strain_per_kappa,
                                kp=self.kp, ki=self.ki, umax=self.umax, passes=SMOOTHING_PASSES,
                                harmonics=self.harmonics, ki_h=self.ki_h, lead_cos=self.lead_cos,
                                lead_sin=self.lead_sin)
        n_h = self.harmonics.shape[0]
        self.state = TrackState(a=np.zeros(n), b=np.zeros(n), lateral=np.zeros(n), counts=np.zeros(3),
                                err=np.zeros(n), tmp=np.zeros(n), ah=np.zeros((n_h, n)), bh=np.zeros((n_h, n)))
        self.s_centre = None
        self.full_gains, self.scale = self.gains, 1.0
        if self.guard is not None:
            self.guard.reset()
        self.ready = True

    def command(self, obs, t: float, waves, ramp_s: float, s_seg, row) -> None:
        """Overwrite the LATERAL column of ``row`` (n_m, 3) with the tracked strain for the tick from t [s]."""
        if self.s_centre is None or self.s_centre.shape[0] != obs.seg_rot.shape[0]:
            # rest centres: the head segment's half length, then one pitch apart (the hybrid's boxes too)
            n = obs.seg_rot.shape[0]
            self.s_centre = float(obs.seg_half[0, 0]) + self.pitch * np.arange(n, dtype=np.float64)
            self.psi = np.zeros(n)
        if ramp_s != self.full_gains.ramp_s:  # the caller's ramp wins (the controller's, the gait's by default)
            self.full_gains = self.full_gains._replace(ramp_s=float(ramp_s))
            self.gains = self.gains._replace(ramp_s=float(ramp_s))
        measured_curvature(obs.seg_rot, self.s_centre, self.s_muscle, self.psi, self.kappa)
        if self.guard is not None:
            scale = self.guard.gain_scale(t)
            if scale != self.scale:  # the guard backed off or resumes (``LoopGuard``): the loop's gains scaled
                self.gains, self.scale = scaled_gains(self.full_gains, scale), scale
        track_tick(self.kappa, self.s_muscle, waves, t, t >= self.t_steady, plain(self.gains), plain(self.state))
        if (self.guard is not None
                and self.guard.watch(t, self.gains.ramp_s, waves, self.s_muscle, self.state, self.umax)):
            # the loop lost its margin: its corrections are dropped, and from the next tick the command is the
            # calibrated open loop's until the guard resumes at a lower gain (``LoopGuard``)
            for arr in (self.state.a, self.state.b, self.state.ah, self.state.bh):
                arr[...] = 0.0
        row[:, _LATERAL] = self.lateral

    @property
    def lateral(self) -> np.ndarray:
        """(n_m,) the last tick's clipped LATERAL strain [-]."""
        return self.state.lateral

    @property
    def counts(self) -> np.ndarray:
        """(3,) commands counted, clipped commands, peak |u| [-] (steady window)."""
        return self.state.counts

    def metrics(self) -> dict[str, float]:
        """muscle_saturation_fraction [-]: share of the steady window's (segment, tick) LATERAL commands
        clipped at max_muscle_strain; muscle_strain_peak [-]: the largest |LATERAL strain| commanded there."""
        n, clipped, peak = self.counts
        out = {"muscle_saturation_fraction": float("nan"), "muscle_strain_peak": float("nan")} if n == 0 else \
            {"muscle_saturation_fraction": float(clipped / n), "muscle_strain_peak": float(peak)}
        if self.plant is not None:
            out.update(self.plant.metrics())
        if self.guard is not None:
            gd = self.guard
            out.update({"shape_control_backoffs": float(gd.backoffs),
                        "shape_control_gain_scale": 0.0 if gd.fallen_back else float(gd.scale),
                        "shape_control_backoff_s": gd.times[0] if gd.times else float("nan")})
        return out

    def run_status(self) -> tuple[str, str] | None:
        """("controller_unstable", why) when the guard had to back the loop off in the measured window or for good:
        the motion measured there is the open loop's (or a lower gain's), because the loop drove the shape away;
        None otherwise."""
        gd = self.guard
        if gd is None or not gd.acted_in_window():
            return None
        when = ", ".join(f"{t:.2f}" for t in gd.times)
        end = "stayed in the calibrated open loop" if gd.fallen_back else \
            f"resumed at {gd.scale:g} of its gains"
        return ("controller_unstable",
                f"controller_unstable: the shape tracker drove the body beyond the commanded shape (bend over "
                f"{GUARD_AMPLITUDE_RATIO:g} x the command or most muscles at max_muscle_strain) and backed off to the "
                f"calibrated open loop at t = {when} s; it {end}")
