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
   da_i/dt = K_i 2 e_i sin(theta_i), db_i/dt = K_i 2 e_i cos(theta_i), K_i = gain per cycle x f (the gain per cycle
   ``gait.shape_gain_i_per_cycle``, 2 by default; -1: from the body's plant measured at the loop's operating
   amplitude, ``integral_gain_from_plant``):
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
from ..kinematics.centre_lines import ground_bend

# wave table columns (controllers.muscle_waves; repeated here to keep this module free of that import)
_AMP, _WAVENUMBER, _OMEGA, _PHASE = 0, 1, 2, 3
_LATERAL = 1
# Binomial passes of the error along the body before it is used (module docstring, step 3): the response
# cos(pi / P)^16 to a profile of period P segments passes the commanded wave (P = 50 or 25 on the snake:
# 0.97, 0.88) and stops the element-scale bending waves (P = 6: 0.10; P <= 4: < 0.004)
SMOOTHING_PASSES = 8
# The loop corrects a commanded wave its smoothing passes at LOOP_MIN_SMOOTHING or more, half its amplitude:
# cos(pi / P)^16 >= 0.5, P >= 10.7 muscle segments a wave (on n segments: waves of 10.7 / n body lengths or longer).
# Below it the loop sees little of the wave it is to correct, and its terms act mostly on what the body does beyond
# the command.  On 12-segment lattices (BENCH_LONG_TESTS=1 examples of the property test), with the loop closed:
# at 0.3 BL (P = 3.6, passed at 0.001), curvature 14, 1 Hz, Miller's friction, mu_t / mu_f 5, the loop added 6 % to
# the feed-forward, a segment flailed over and the guard's waveform test left harmonic content 1.6 (the calibrated
# open loop: 0.012); at 0.5 BL (P = 6, 0.10), mu_t / mu_f 10, the loop's push at a bend flung the body into flailing
# that the open loop, once backed off to, did not undo: curvature 52.7 of 14 (open loop: 11.3).  So the calibrated
# open loop runs there, and the run says so (``ShapeTracker.run_status``)
LOOP_MIN_SMOOTHING = 0.5


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


def segment_twist_deg(seg_rot) -> float:
    """The largest roll [deg] of a segment about its own axis away from the body's median roll, from the segment frames
    seg_rot (n, 3, 3) segment -> world (x: the body's axis, y: dorsal): the roll of a frame is the angle of its dorsal
    axis from the vertical about the x axis, atan2(-R[1, 2], R[1, 1]) (independent of the segment's pitch).  A body
    lying on a slope rolls as a whole and reads 0."""
    roll = np.degrees(np.arctan2(-seg_rot[:, 1, 2], seg_rot[:, 1, 1]))
    return float(np.max(np.abs(_wrap_deg(roll - np.median(roll))))) if roll.size else 0.0


def _ramp(t: float, ramp_s: float) -> float:
    """The start ramp r(t) [-] (module docstring): t / ramp_s up to 1."""
    return 1.0 if ramp_s <= 0.0 or t >= ramp_s else max(t, 0.0) / ramp_s


def _wrap_deg(x):
    return (np.asarray(x, float) + 180.0) % 360.0 - 180.0


class PlantMargin:
    """The loop's stability margin at the wave frequency, from the body's measured open-loop response and the gains
    the loop runs at.

    ``bodies.curvature_calibration.plant_response`` identifies, at each interior segment, the open loop's curvature
    against the command: the complex gain G (|G| and the lag phi = -arg G).  Seen at the wave frequency (a phasor per
    segment, the body quasi-static over a cycle), the loop of step 3 is: the command u = u_ff + X + K_p rho e, the bend
    G u, the error e = u_ff - G u, smoothed along the body to rho e (``smooth_along_body``'s response to the commanded
    wave's spatial period: rho = cos(pi p / lambda)^(2 passes), p the segment pitch), and the amplitude-and-phase
    integral dX/dt = K_i rho e.  Eliminating e: dX/dt = -K_i H X + const with

        H = rho G / (1 + K_p rho G),

    so the integral converges where Re H > 0, and its phase margin at a segment is 90 - |arg H| [deg]; the loop's,
    ``margin_deg``, is the smallest over the segments.  K_p is the proportional gain the loop actually runs at (the
    body's or the key's), so the margin is that of this run's gains: K_p = 0 gives 90 - max |phi|.  The integral's
    convergence per gait cycle is K_i / f Re H (``rate_per_cycle``, the median over the segments).

    Measured, and not acted on: under Coulomb friction the open loop's response is not the closed loop's plant (the
    bend does not grow in proportion to the command: a friction moment that does not grow with the bend holds the body
    until the muscles' moment passes it).  On the slithering grid (lattice) the open loop reached 0.97, 0.88, 0.76,
    0.58, 0.20 and 0.03 of the command at mu_t / mu_f = 1, 1.5, 2, 3, 5 and 10 with lags whose margins at K_p = 0
    were 25, 21, 11, -10, -88 and -90 degrees, and the closed loop tracks every one of those cells (shape error 0.07
    or less at 35.7 s).  Scheduling the gains by the margin (the open loop where there is none) dropped the grid's
    cells at 5 and 10, and turning the fundamental's update by the median lag (a lead, as step 3b's) took the cells
    at 2 and 3 to shape errors of 0.12 and 0.19 (docs/explanation/shape-tracking.md, "The plant, identified").  The
    guard (``LoopGuard``), which watches the closed loop itself, is what keeps the loop from running away.  The plant
    at the loop's own operating amplitude is another (``bodies.curvature_calibration.operating_plant``): from it
    ``integral_gain_from_plant`` sets the integral gain where ``gait.shape_gain_i_per_cycle = -1``; the margin here
    is always that of the feed-forward's plant, at the gains the run used."""

    def __init__(self, gain, lag_deg, kp: float = 0.0, ki: float = 0.0, frequency_hz: float = 1.0,
                 smoothing: float = 1.0, harmonic_content: float = float("nan")):
        self.gain = np.asarray(gain, float)
        self.lag_deg = _wrap_deg(lag_deg)
        self.kp, self.ki, self.smoothing = float(kp), float(ki), float(smoothing)
        self.harmonic_content = float(harmonic_content)
        g = self.smoothing * self.gain * np.exp(-1j * np.radians(self.lag_deg))
        h = g / (1.0 + self.kp * g)
        self.margin_deg = 90.0 - float(np.max(np.abs(np.degrees(np.angle(h))))) if h.size else float("nan")
        self.rate_per_cycle = float(np.median(self.ki / float(frequency_hz) * h.real)) if h.size else float("nan")

    @classmethod
    def of(cls, response, kp: float = 0.0, ki: float = 0.0, frequency_hz: float = 1.0,
           smoothing: float = 1.0) -> "PlantMargin | None":
        """From ``body_info["plant_response"]`` at the loop's gains kp [-], ki [1/s] (the fundamental's integral) and
        the smoothing's response to the commanded wave [-]; None when the plant was not identified (its status says
        why)."""
        if not response or response.get("status") != "ok" or not response.get("gain"):
            return None
        return cls(response["gain"], response["lag_deg"], kp, ki, frequency_hz, smoothing,
                   response.get("harmonic_content", float("nan")))

    def metrics(self) -> dict[str, float]:
        """shape_plant_gain, shape_plant_lag_deg (medians over the segments), shape_loop_margin_deg, the phase margin
        of the loop's amplitude-and-phase integral at this run's gains, and shape_loop_rate_per_cycle, its
        convergence per gait cycle."""
        return {"shape_plant_gain": float(np.median(self.gain)), "shape_plant_lag_deg": float(np.median(self.lag_deg)),
                "shape_loop_margin_deg": self.margin_deg, "shape_loop_rate_per_cycle": self.rate_per_cycle}


# The fundamental's integral gain from the body's measured plant (``integral_gain_from_plant``;
# ``gait.shape_gain_i_per_cycle = -1``).  INTEGRAL_RATE_PER_CYCLE is the convergence per gait cycle the gain is set
# for: the isotropic snake's, the rate the constant 2 per cycle gave the lattice (K_p = 2) on the slithering grid at
# mu_t / mu_f = 1, where the loop was built (shape_loop_rate_per_cycle 0.66: the free body's plant, G = 1, smoothed at
# rho = 0.97, H = rho / (1 + 2 rho) = 0.33).  The gain is clamped to [INTEGRAL_GAIN_MIN_PER_CYCLE,
# INTEGRAL_GAIN_MAX_PER_CYCLE]: a quarter and twice the constant (15.5 per cycle, from the plant at the
# feed-forward's amplitude at mu_t / mu_f = 5, lost a cell of the grid).  Where the plant at the operating amplitude
# is not found, the constant INTEGRAL_GAIN_FALLBACK_PER_CYCLE runs, and the run says so
INTEGRAL_RATE_PER_CYCLE = 0.65
INTEGRAL_GAIN_MIN_PER_CYCLE = 0.5
INTEGRAL_GAIN_MAX_PER_CYCLE = 4.0
INTEGRAL_GAIN_FALLBACK_PER_CYCLE = 2.0


def integral_gain_from_plant(operating, kp: float, smoothing: float) -> tuple[float | None, str]:
    """The fundamental's integral gain per gait cycle [-] from the plant at the loop's operating amplitude
    (``bodies.curvature_calibration.operating_plant``: s* [-], |G(s*)| [-], its lag [deg]) at the proportional gain
    kp [-] and the smoothing's response to the commanded wave [-]: K_i = INTEGRAL_RATE_PER_CYCLE / Re H,
    H = rho G / (1 + K_p rho G) (``PlantMargin``: the integral's convergence per cycle is K_i Re H), clamped to
    [INTEGRAL_GAIN_MIN_PER_CYCLE, INTEGRAL_GAIN_MAX_PER_CYCLE].  Returns (gain, where it came from), or (None, why
    not) when the plant is not there or leaves the integral no convergence (Re H <= 0)."""
    if not operating or operating.get("status") != "ok":
        why = operating.get("status", "not identified") if operating else "not identified"
        return None, f"the plant at the loop's operating amplitude was not found ({why})"
    g = smoothing * float(operating["gain"]) * complex(math.cos(math.radians(float(operating["lag_deg"]))),
                                                       -math.sin(math.radians(float(operating["lag_deg"]))))
    h = g / (1.0 + kp * g)
    if not h.real > 0.0:
        return None, (f"the plant at the operating amplitude leaves the integral no convergence (Re H = {h.real:.3f} "
                      f"at s* = {float(operating['s_star']):.2f})")
    raw = INTEGRAL_RATE_PER_CYCLE / h.real
    ki = min(INTEGRAL_GAIN_MAX_PER_CYCLE, max(INTEGRAL_GAIN_MIN_PER_CYCLE, raw))
    clamp = "" if ki == raw else f", clamped from {raw:.2f}"
    return ki, (f"K_i {ki:.3f} per cycle from the measured plant at the operating amplitude s* = "
                f"{float(operating['s_star']):.3f} x the feed-forward (|G| {float(operating['gain']):.3f}, lag "
                f"{float(operating['lag_deg']):.1f} deg, Re H {h.real:.3f}, {int(operating.get('runs', 0))} "
                f"identification run(s) beyond the feed-forward's){clamp}")


def smoothing_response(pitch_m: float, wavelength_m: float, passes: int = SMOOTHING_PASSES) -> float:
    """The response [-] of ``smooth_along_body`` (``passes`` binomial passes over muscles ``pitch_m`` apart) to a
    profile of period ``wavelength_m`` [m] along the body: cos(pi pitch / wavelength)^(2 passes); 0 at two pitches."""
    if not wavelength_m > 0.0:
        return 1.0
    c = math.cos(math.pi * min(pitch_m / wavelength_m, 0.5))
    return float(c ** (2 * passes))


def scaled_gains(gains: TrackGains, scale: float, integral_scale: float | None = None) -> TrackGains:
    """``gains`` (``TrackGains``' order) with the loop's gains, the proportional, the fundamental's integral and the
    harmonics' integral ones, times ``scale`` [-]; 0: the calibrated open loop (the feed-forward alone, once the
    integral state is zero).  integral_scale [-], when given, scales the integral gains instead of ``scale``."""
    g = TrackGains(*gains)
    si = scale if integral_scale is None else integral_scale
    return g._replace(kp=g.kp * scale, ki=g.ki * si, ki_h=g.ki_h * si)


# The guard's thresholds (``LoopGuard``): the loop has lost its margin when the body's bend, smoothed like the error,
# exceeds the command by GUARD_AMPLITUDE_RATIO in RMS over the last quarter cycle (under the 25 % a run may overshoot
# by, issue 44), or when more than GUARD_SATURATION of the muscles have been held at their strength over the last
# half cycle ("most muscles saturated") while the body bends at least as commanded.  Each back-off halves the loop's gains (GUARD_BACKOFF) after a period of
# the open loop; after GUARD_MAX_BACKOFFS the open loop stays.
GUARD_AMPLITUDE_RATIO = 1.2
GUARD_SATURATION = 0.5
GUARD_BACKOFF = 0.5
GUARD_MAX_BACKOFFS = 2
# The guard's twist test: a segment rolled about the body's axis by more than GUARD_TWIST_DEG from the body's median
# roll while the loop commands GUARD_TWIST_COMMAND_RATIO times the feed-forward or more, in RMS over the last quarter
# cycle (``segment_twist_deg``; ``LoopGuard``): the loop is driving the body out of its plane, and the calibrated open
# loop stays for the rest of the run.  A body that twists while the loop adds little to the feed-forward twists of
# its own accord, and switching to the open loop there only jolts it
GUARD_TWIST_DEG = 15.0
GUARD_TWIST_COMMAND_RATIO = 1.5
# The guard's strength test (``LoopGuard``): the loop commands a muscle beyond GUARD_STRENGTH_MARGIN of its strength
# (``gait.max_muscle_strain``) and beyond GUARD_STRENGTH_OVER_FEED_FORWARD times the feed-forward's own peak (the
# loop's doing, not the commanded wave's), at any tick, the start ramp included.  The hybrid's FEM links blew up at
# commands of 0.276 to 0.287 peak under a strength of 0.3, in three cells of the tracking map as unlike as the loop
# winding up against mu_t 1.0 (1.5 BL, 2.14 s), a body flailing on nearly isotropic friction (1 BL, mu_t 0.2,
# 5.75 s) and a loop that tracked (shape error 0.08) while its integrals crept from 0.14 to 0.28 (curvature 10,
# 0.5 Hz, 36.0 s); the calibrated open loop commanded to 0.30 (curvature 25) blew up the same way (1.73 s), and ran
# at half the time step (docs/explanation/shape-tracking-map.md).  The slithering grid's most demanding cell (the
# hybrid at mu_t / mu_f 10) peaks at 0.165
GUARD_STRENGTH_MARGIN = 0.85
GUARD_STRENGTH_OVER_FEED_FORWARD = 1.5
# The guard's waveform test (``WaveformWatch``): the centre line's bend, demodulated over the last whole period at
# every interior centre, carries more than GUARD_HARMONIC of the commanded amplitude in the wave's temporal harmonics
# 2 to GUARD_HARMONICS (the run's ``shape_harmonic_content``, on line; the bound is 0.20), more than
# GUARD_HARMONIC_EXCESS above what the calibrated open loop carried on the same ground (the plant identification's
# own harmonic content: the body's and the friction's, not the loop's), and more than at every check of the last
# half period and GUARD_HARMONIC_GROWTH times the least of them (growing: ``WaveformWatch.growing``; a runaway grew
# 1.3 to 1.4 times a check, 1.7 to 2 over a half period; the fem snake settling at mu_t / mu_f = 1, 1.13 at most).
# Checked GUARD_CHECKS_PER_PERIOD times a period.
GUARD_HARMONIC = 0.15
GUARD_HARMONIC_EXCESS = 0.05
GUARD_HARMONICS = 5
GUARD_CHECKS_PER_PERIOD = 4
GUARD_HARMONIC_GROWTH = 1.25
# The open loop's trim (``LoopGuard.trim``): while the guard holds the loop off, the calibrated open loop's command is
# scaled by a trim that follows the centre line's bend against the command, RMS over the last quarter cycle, on a log
# scale at GUARD_TRIM_PER_CYCLE per gait cycle: d ln(trim) / dt = -GUARD_TRIM_PER_CYCLE f (bend / command - 1), held
# between GUARD_TRIM_MIN and 1.  It only ever lowers the open loop's amplitude (raising it is the loop's work, and
# what ran away); it changes nothing of a run the guard never backs off.  Measured on the lattice at 0.75 BL,
# curvature 2, 0.5 Hz, Miller's friction, mu_t / mu_f 5, 25 segments (8 s): the loop's swing outlived its back-offs
# and the untrimmed open loop ended at 2.94 of 2, shape error 0.70, harmonic content 0.09 (the open loop from the
# start: 2.39).  Trimmed at 0.5, 1 and 2 per cycle down to 0.5: 2.58, 2.37 and 2.22, but harmonic content 0.11, 0.13
# and 0.18 (the trim lowers the commanded wave, not the body's other one, docs/explanation/shape-tracking.md); at 2
# per cycle down to 0.7: 2.35, shape error 0.68, harmonic content 0.08
GUARD_TRIM_PER_CYCLE = 2.0
GUARD_TRIM_MIN = 0.7


class WaveformWatch:
    """The harmonic content of the body's bend over the last whole gait period, on line (``LoopGuard``'s waveform test).

    Each tick's bend b_i(t) [strain] at the interior segment centres (the ground curvature of the centre line through
    the segments' centres, ``kinematics.centre_lines.ground_curvature``, as the run's metrics and the plant
    identification read it, times the calibrated gain; unsmoothed: the temporal harmonics of a short wave are
    spatially shorter still, and the smoothing along the body would hide them) goes into a ring of one period.
    The centre line, not the segment frames the loop reads: on the hybrid at 7.5 segments a wave the frames' turn
    carried harmonic content 0.27 in the calibrated open loop, whose centre line carried 0.05.  A check projects the
    ring on the command's phase, c_h,i = (2 / N) sum_t b_i(t) exp(-i h theta_i(t)), theta_i = k s_i - omega t + phi,
    and returns sqrt(mean_i sum_{h=2..H} |c_h,i|^2) / A_s, A_s the commanded strain amplitude: over a whole period
    the harmonics are orthogonal, so a travelling sine reads 0 at any amplitude and phase with no ripple (a filter
    over part of a period ripples at twice the wave frequency, and tripped on the default snake).  A loop still
    settling reads high too (its amplitude changes within the period): on the slithering grid the first checks
    after the ramp read 0.15 to 0.22, so the guard asks that the content be growing as well (``growing``).  Fitting
    the amplitude's drift over the period with the harmonics was tried and read higher (lattice, mu_t / mu_f = 5:
    0.26 at the first check, 0.10 steady, against 0.19 and 0.06 here)."""

    def __init__(self, period_s: float, dt_tick: float):
        self.n = max(8, int(round(period_s / dt_tick)))
        self.period_s = float(period_s)
        self.buf = None
        self.times = np.zeros(self.n)
        self.clear()

    def clear(self) -> None:
        """Forget what was seen (a back-off: the next check waits for a whole period of the loop resumed)."""
        self.checks: list[tuple[float, float]] = []  # (t [s], content [-]) of the checks since
        self.filled = 0
        self.pos = 0
        self.next_check = -math.inf

    def push(self, t: float, bend) -> None:
        """Add the tick at t [s] with the bend (n_p,) [strain]."""
        if self.buf is None or self.buf.shape[1] != bend.shape[0]:
            self.buf = np.zeros((self.n, bend.shape[0]))
        self.buf[self.pos] = bend
        self.times[self.pos] = t
        self.pos = (self.pos + 1) % self.n
        self.filled = min(self.filled + 1, self.n)
        if self.filled == 1:
            self.next_check = t + self.period_s - 0.5 * self.period_s / self.n

    def due(self, t: float) -> bool:
        """True when a whole period is in the ring and a check is due at t [s]."""
        return self.filled == self.n and t >= self.next_check

    def content(self, t: float, waves, s_points) -> float:
        """The harmonic content [-] of the ring (class docstring); schedules the next check."""
        self.next_check = t + self.period_s / GUARD_CHECKS_PER_PERIOD
        amp, k, om, ph = waves[_LATERAL, _AMP], waves[_LATERAL, _WAVENUMBER], waves[_LATERAL, _OMEGA], \
            waves[_LATERAL, _PHASE]
        if amp == 0.0 or self.buf.shape[1] != s_points.shape[0]:
            return 0.0
        theta = k * s_points[None, :] - om * self.times[:, None] + ph  # (N, n_p)
        power = np.zeros(s_points.shape[0])
        for h in range(2, GUARD_HARMONICS + 1):
            c = (2.0 / self.n) * np.sum(self.buf * np.exp(-1j * h * theta), axis=0)
            power += c.real ** 2 + c.imag ** 2
        out = float(np.sqrt(np.mean(power)) / abs(amp))
        self.checks.append((float(t), out))
        return out

    def growing(self) -> bool:
        """True when the last check's content is above every other check's of the last half period (and there is
        one), and ``GUARD_HARMONIC_GROWTH`` times the smallest of them or more: a runaway grows, where a settling
        loop's transient levels off and decays.  On the slithering grid the first checks after the ramp read 0.15 to
        0.22 while the loop brought the bend to the command, and fell to 0.03-0.07 over the next cycles; the fem
        snake at mu_t / mu_f = 1 read 0.245, 0.258, 0.278 (1.05 and 1.08 a check), then 0.228, 0.211 down to 0.05,
        and growth alone had switched its integrals off at the second check (78.5 s: shape error 0.16, flagged, where
        it tracks at 0.04).  The hybrid's runaway read 0.13, 0.18, 0.26, 0.37 a quarter period apart (1.4 a check),
        on 50 segments 0.04 to 0.30 over 8 checks (1.29 a check).  The half period is read with half a check's
        slack, so the check a half period back, whose time drifts by a tick or two, is among them."""
        if len(self.checks) < 2:
            return False
        t, c = self.checks[-1]
        since = t - (0.5 + 0.5 / GUARD_CHECKS_PER_PERIOD) * self.period_s
        before = [cc for tt, cc in self.checks[:-1] if tt >= since]
        return bool(before) and c > max(before) and c >= GUARD_HARMONIC_GROWTH * min(before)


class LoopGuard:
    """Watches the closed loop for a runaway and backs it off to the calibrated open loop (``gait.shape_guard``).

    The tracker's integral and proportional terms assume a plant whose response grows in proportion to the command
    and lags it by less than 90 degrees.  Coulomb friction breaks both: a bend costs a friction moment that does not
    grow with the bend, so the body hardly moves until the muscles' moment passes it and then bends far (the lattice
    snake at 0.5 Hz, one wave per body, mu_t = 0.5: 1.5 of a commanded 10 open loop, 40 closed loop with half its
    muscles at their strength; issue 44).  Once the bend passes the command by ``GUARD_AMPLITUDE_RATIO`` while the
    loop commands more than the feed-forward (the loop's doing: a body that overshoots in open loop is pulled back
    by the loop, and left alone here), or most muscles are held at their strength, the integral state is dropped and
    the command is the feed-forward alone for one gait period; then the loop resumes at ``GUARD_BACKOFF`` times its
    gains, and after ``GUARD_MAX_BACKOFFS`` back-offs the open loop stays.

    The waveform is watched too (``WaveformWatch``): a loop can hold the bend's amplitude and still drive its shape
    away, into the wave's temporal harmonics.  On the hybrid snake at 0.3 BL, curvature 10, 0.5 Hz, Miller's friction
    at mu_t / mu_f = 1 and 25 segments the harmonic content of the centre line grew period by period 0.14, 0.27, 0.52,
    0.67, 0.72, 0.85 (the open loop's: 0.05), with the amplitude short of the command; that is the fundamental's
    amplitude-and-phase integral (without it the loop tracked, shape error 0.06, harmonics 0.02).  When the harmonic
    content over the last period passes ``GUARD_HARMONIC``, and the open loop's own by ``GUARD_HARMONIC_EXCESS``, and
    is growing (``WaveformWatch.growing``: a settling loop's transient decays), the integrals (the fundamental's
    and the harmonics') are dropped and switched off for the rest of the run, and the proportional loop goes on
    (gain scheduling: the part of the loop that lost its margin goes); a second trip of any test backs off as above.

    And the body's roll (``segment_twist_deg``): under a command several times the feed-forward (a Coulomb-friction
    body that hardly bends until the muscles' moment passes the friction's) the lattice at 1.5 BL, 1 Hz rolled its
    middle segments over, 10 to 145 degrees in 0.14 s, while the bend low-passed over a quarter cycle was still short
    of the command, and then onto its back.  A segment rolled ``GUARD_TWIST_DEG`` beyond the body's median roll
    while the loop commands ``GUARD_TWIST_COMMAND_RATIO`` times the feed-forward puts the run in the calibrated open
    loop for good (resumed at half the gains, the loop rolled the same body again a second later).

    And the muscles' load (``GUARD_STRENGTH_MARGIN``): a loop can wind its command up under the muscle's strength,
    unclipped and with the bend short of or at the command, until the body itself fails.  The hybrid's FEM links blew
    up ("runaway speed") at commands of 0.276 to 0.287 under a strength of 0.3 in three cells of the tracking map, and
    its calibrated open loop did so too when commanded to 0.30 (it ran at half the time step): the last of the
    muscle's strength is more than those links carry at their step.  A command beyond ``GUARD_STRENGTH_MARGIN`` of the
    strength and beyond ``GUARD_STRENGTH_OVER_FEED_FORWARD`` times the feed-forward's peak (the loop's doing: a
    commanded wave that needs that strain of itself is the command's, and a muscle too weak for the load is clipped
    at its strength below it and flagged) backs the loop off as the amplitude test does, read from the first tick
    (the start ramp included: the muscles' load is not the shape's).  A trip in the start ramp, on a wave whose
    feed-forward is within the margin, puts the run in the calibrated open loop for good: a loop at that load while
    its reference is a fraction r of the wave needs at least 1 / r of it at the whole wave (more bend costs more
    moment, the friction's included), so no lower gain resumes under the margin.  Of the 21 runs of the tracking maps
    whose first strength trip fell in the ramp, none tracked after resuming (20 ended in the open loop after three
    back-offs, one at half its gains with shape error 0.48).  On the hybrid at 1.5 BL, curvature 14, 0.5 Hz, Coulomb
    friction at mu_t / mu_f 10 and 50 segments the loop tripped in the ramp (0.91 s), and resumed at half and a
    quarter of its gains it tripped again (3.99, 7.50 s); the switching left harmonic content 0.78 in the measured
    window (the open loop's: 0.17).  Trips after the ramp resume as the other tests' (a loop creeping up to the
    margin over tens of seconds tracks at half or a quarter of its gains: docs/explanation/shape-tracking-map.md).

    While it holds the loop off, the open loop's amplitude is trimmed (``trim``, ``GUARD_TRIM_PER_CYCLE``): a body
    whose swing the loop drove past the command can keep it after the loop lets go (under Miller's friction at a small
    bend the lattice kept 2.94 of 2 in the open loop the loop left to it, where the open loop from the start reached
    2.39), so after a back-off for a bend beyond the command (the amplitude, saturation or strength test) the open
    loop's command is lowered, never raised above the feed-forward, until the centre line bends no more than commanded.
    When the loop resumes, the trim is handed to its amplitude integral (the command does not jump), and it goes on
    from there at the next back-off.
    The run's ``shape_control_backoffs``, ``shape_control_gain_scale``, ``shape_control_open_loop_trim`` and
    ``shape_control_backoff_s`` say what it did, and the runner's status ``controller_unstable`` says when it acted
    in the measured window or ended in the open loop (``ShapeTracker.run_status``)."""

    def __init__(self, period_s: float, t_steady: float, dt_tick: float):
        self.period_s, self.t_steady, self.dt_tick = float(period_s), float(t_steady), float(dt_tick)
        self.waveform = WaveformWatch(self.period_s, self.dt_tick)
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
        self.p_line = 0.0          # mean square of the centre line's bend [strain^2], low-passed
        self.trim = 1.0            # the open loop's amplitude while the loop is held off, over the feed-forward's
        self.trim_min = 1.0        # the smallest trim applied
        self.trimming = False      # the trim follows the bend: the last back-off was for a bend beyond the command
        self.reasons: list[str] = []  # what each back-off saw
        self.integral_off = False  # the integrals switched off by a waveform back-off
        self.open_for_good = False  # the twist test, or the strength test in the ramp: the open loop for the rest
        self.harmonic_limit = GUARD_HARMONIC  # the waveform test's threshold (``set_open_loop_harmonics``)
        self.waveform.clear()

    def set_open_loop_harmonics(self, content: float) -> None:
        """The calibrated open loop's own harmonic content on this ground [-] (the plant identification's; NaN when
        not identified): the waveform test trips above it by ``GUARD_HARMONIC_EXCESS``, and never below
        ``GUARD_HARMONIC``."""
        c = float(content)
        self.harmonic_limit = max(GUARD_HARMONIC, c + GUARD_HARMONIC_EXCESS) if math.isfinite(c) else GUARD_HARMONIC

    @property
    def fallen_back(self) -> bool:
        """The open loop for good: the loop lost its margin ``GUARD_MAX_BACKOFFS`` + 1 times."""
        return self.open_for_good or self.backoffs > GUARD_MAX_BACKOFFS

    def gain_scale(self, t: float) -> float:
        """The loop's gain scale at t [s]: 0 while backed off, else the scale it resumed at."""
        return 0.0 if self.fallen_back or t < self.hold_until else self.scale

    def gain_scales(self, t: float) -> tuple[float, float]:
        """(proportional, integral) gain scales at t [s]: ``gain_scale``'s, the integral's 0 once it is off."""
        s = self.gain_scale(t)
        return s, 0.0 if self.integral_off else s

    def watch(self, t: float, ramp_s: float, waves, s_muscle, state, umax: float, bend=None, s_bend=None,
              seg_rot=None) -> bool:
        """Update the guard with the tick just computed at t [s] (``track_tick``'s state: its smoothed error and its
        command; ramp_s [s]: the start ramp; bend: (n_p,) the centre line's bend [strain] at rest arc positions
        s_bend (n_p,) [m], for the waveform test (``WaveformWatch``), or None; seg_rot: (n, 3, 3) the segment frames,
        for the twist test (``segment_twist_deg``), or None); True when the loop lost its margin
        at this tick (the caller drops the integral state)."""
        amp, k, om, ph = waves[_LATERAL, _AMP], waves[_LATERAL, _WAVENUMBER], waves[_LATERAL, _OMEGA], \
            waves[_LATERAL, _PHASE]
        err, lateral = state.err, state.lateral
        r = _ramp(t, ramp_s)
        ref = (r * amp) * np.sin(k * s_muscle - om * t + ph)
        meas = ref - err  # the measured bend, smoothed along the body like the error [strain]
        a_fast = self.dt_tick / (0.25 * self.period_s)
        a_slow = self.dt_tick / (0.5 * self.period_s)
        self.p_meas += a_fast * (float(np.mean(meas * meas)) - self.p_meas)
        self.p_cmd += a_fast * (float(np.mean(ref * ref)) - self.p_cmd)
        self.p_out += a_fast * (float(np.mean(lateral * lateral)) - self.p_out)
        self.sat += a_slow * (float(np.mean(np.abs(lateral) >= umax)) - self.sat)
        if bend is not None:
            self.p_line += a_fast * (float(np.mean(bend * bend)) - self.p_line)
        if self.trimming and self.gain_scale(t) == 0.0:
            self._trim_open_loop(self.p_line if bend is not None else self.p_meas)
        if self.fallen_back or t < self.hold_until:
            return False
        # the body rolled out of its plane while the loop commands well beyond the feed-forward (the roll is read only
        # then: it costs a few microseconds a tick)
        twisted = (seg_rot is not None and self.p_out > GUARD_TWIST_COMMAND_RATIO ** 2 * self.p_cmd
                   and segment_twist_deg(seg_rot) > GUARD_TWIST_DEG)
        # a muscle driven by the loop into the last margin of its strength (``GUARD_STRENGTH_MARGIN``): read during the
        # ramp too, it is the body's load, not the shape's
        peak = float(np.max(np.abs(lateral))) if lateral.size else 0.0
        strained = (peak > GUARD_STRENGTH_MARGIN * umax
                    and peak > GUARD_STRENGTH_OVER_FEED_FORWARD * r * abs(amp))
        if r < 1.0 and not (twisted or strained):
            return False
        harmonic = float("nan")
        if bend is not None:
            self.waveform.push(t, bend)
            if self.waveform.due(t):
                harmonic = self.waveform.content(t, waves, s_bend)
        # the controller's doing: the body bends beyond the command while the loop commands more than the open
        # loop would (a body that overshoots in open loop, which the loop is pulling back, is the body's own)
        overshoot = self.p_meas > GUARD_AMPLITUDE_RATIO ** 2 * self.p_cmd and self.p_out > self.p_cmd
        # most muscles at their strength while the body bends at least as commanded: the loop's doing (a muscle too
        # weak for the load saturates with the body short of the command; that is flagged, not backed off)
        saturated = self.sat > GUARD_SATURATION and self.p_meas > self.p_cmd
        # the waveform: the bend's harmonics over the last period beyond the open loop's own (``WaveformWatch``)
        distorted = harmonic > self.harmonic_limit and self.waveform.growing()
        if not (overshoot or saturated or distorted or twisted or strained):
            return False
        self.backoffs += 1
        self.times.append(float(t))
        self.reasons.append("segments twisted over" if twisted else "bend over the command" if overshoot else
                            "most muscles saturated" if saturated else
                            f"a muscle at {peak / umax:.2f} of its strength" if strained else
                            f"harmonic content {harmonic:.2f} > {self.harmonic_limit:.2f}" +
                            ("" if self.integral_off else ": integrals off"))
        self.waveform.clear()
        self.sat = 0.0
        # the open loop's trim follows the bend after a back-off for a bend beyond the command; after one for a twist
        # or the waveform the body is short of the command or off its plane, and the trim stays where it is (on the
        # lattice at 0.75 BL, curvature 10, trimming after the twist test's back-off lowered the open loop while the
        # loop's last push passed and left the body at 3.4 of 10, where the untrimmed open loop reached 4.3)
        self.trimming = (overshoot or saturated or strained) and not twisted
        # neither goes away at lower gains (the class docstring); a wave whose feed-forward needs the margin of itself
        # (a muscle too weak for the wave) is the command's, and backs off as before
        in_ramp_load = strained and r < 1.0 and abs(amp) < GUARD_STRENGTH_MARGIN * umax
        if twisted or in_ramp_load:
            self.open_for_good = True
            return True
        if distorted and not (overshoot or saturated or strained) and not self.integral_off:
            # the waveform ran away with the bend's amplitude held: the integrals' doing (on the hybrid at 0.3 BL,
            # Miller's friction, mu_t / mu_f 1, the loop without its fundamental's integral tracked, shape error
            # 0.06, and without its proportional term it blew up), so they are switched off and the proportional
            # loop goes on; a second trip backs off as any other
            self.integral_off = True
            return True
        self.scale *= GUARD_BACKOFF
        self.hold_until = t + self.period_s
        return True

    def _trim_open_loop(self, p_bend: float) -> None:
        """One tick of the open loop's trim (class docstring) from the bend's mean square p_bend [strain^2], low-passed
        like the command's."""
        if not self.p_cmd > 0.0:
            return
        ratio = math.sqrt(p_bend / self.p_cmd)
        rate = GUARD_TRIM_PER_CYCLE / self.period_s * self.dt_tick
        self.trim = min(1.0, max(GUARD_TRIM_MIN, self.trim * math.exp(-rate * (ratio - 1.0))))
        self.trim_min = min(self.trim_min, self.trim)

    def acted_in_window(self) -> bool:
        """The guard backed off in the steady window (after ``metrics.warmup_cycles``), held the loop off into it, or
        ended in the open loop or with the loop's integrals off: the loop measured is not the one commanded."""
        return (self.fallen_back or self.integral_off or any(tt >= self.t_steady for tt in self.times)
                or self.hold_until > self.t_steady)

    def recovered_in_warmup(self) -> str | None:
        """What the guard did during the warm-up when the loop recovered before the steady window (it backed off, and
        resumed before ``metrics.warmup_cycles`` were over: ``acted_in_window`` is False): when, why, and the gains it
        resumed at; None when it never acted or acted in the window.  The run stays ``ok`` (the motion measured is
        the closed loop's), and its message says so, because the loop it measured runs at a fraction of its gains."""
        if not self.times or self.acted_in_window():
            return None
        when = ", ".join(f"{t:.2f} s ({why})" for t, why in zip(self.times, self.reasons))
        return (f"the shape loop was backed off during the warm-up at t = {when} and recovered before the steady "
                f"window (from {self.t_steady:.2f} s): it resumed at {self.hold_until:.2f} s at {self.scale:g} of its "
                f"gains, which the measured window ran at")


class ShapeTracker:
    """The closed loop of a commanded bending wave (module docstring) for one run."""

    def __init__(self, case):
        g = case.gait
        self.kp_key = float(g.shape_gain_p)  # < 0: the body's own (``BodySpec.shape_gain_p``), set in ``reset``
        self.kp = max(self.kp_key, 0.0)
        # < 0: from the measured plant at the operating amplitude (``integral_gain_from_plant``), set in ``reset``
        self.ki_key = float(g.shape_gain_i_per_cycle)
        self.ki = max(self.ki_key, 0.0) * float(g.frequency_hz)
        self.ki_per_cycle = max(self.ki_key, 0.0)
        self.ki_from_plant = False
        self.ki_source = "gait.shape_gain_i_per_cycle"
        self.umax = float(g.max_muscle_strain)
        self.ramp_s = float(g.ramp_s)
        self.dt_tick = 1.0 / float(g.shape_control_rate_hz)
        self.t_steady = float(case.metrics.warmup_cycles) * g.period_s
        self.body_length = float(case.creature.body_length_m)
        # < 0: the body's own harmonic gain (``BodySpec.shape_harmonic_gain_per_cycle``), set in ``reset``
        self.kh_key = float(g.shape_harmonic_gain_per_cycle)
        self.harmonic_list = tuple(g.shape_harmonics)
        self.frequency_hz = float(g.frequency_hz)
        self.wavelength_bl = float(g.wavelength_bl)
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

    def _set_integral_gain(self, operating) -> None:
        """The fundamental's integral gain: the key's (>= 0), else from the measured plant at the loop's operating
        amplitude (``integral_gain_from_plant``, at this run's K_p and smoothing), else, where that plant was not
        found, ``INTEGRAL_GAIN_FALLBACK_PER_CYCLE``, and ``ki_source`` says why."""
        self.operating = operating if operating and operating.get("status") == "ok" else None
        if self.ki_key >= 0.0:
            per_cycle, self.ki_from_plant, self.ki_source = self.ki_key, False, "gait.shape_gain_i_per_cycle"
        else:
            per_cycle, why = integral_gain_from_plant(operating, self.kp, self.wave_smoothing)
            self.ki_from_plant = per_cycle is not None
            if per_cycle is None:
                per_cycle = INTEGRAL_GAIN_FALLBACK_PER_CYCLE
                why = f"K_i {per_cycle:g} per cycle, the constant: {why}"
            self.ki_source = why
        self.ki_per_cycle = float(per_cycle)
        self.ki = self.ki_per_cycle * self.frequency_hz

    def reset(self, body_info, strain_per_curvature: float) -> None:
        """Prepare for a body: its muscle arc positions, pitch and the calibrated gain [strain per curvature x L]."""
        self.s_muscle = np.ascontiguousarray(body_info["muscle_s"], dtype=np.float64)
        self.pitch = float(body_info["segment_pitch_m"])
        self.strain_per_kappa = LATERAL_GROUND_SIGN * strain_per_curvature * self.body_length
        self.kp = self.kp_key if self.kp_key >= 0.0 else float(body_info.get("shape_gain_p", 0.0))
        self.kp_source = "gait.shape_gain_p" if self.kp_key >= 0.0 else "the body's (BodySpec.shape_gain_p)"
        self._set_harmonics(self.kh_key if self.kh_key >= 0.0
                            else float(body_info.get("shape_harmonic_gain_per_cycle", 0.0)))
        n = self.s_muscle.shape[0]
        self.kappa = np.zeros(n)
        # the open loop's measured response and the margin of the loop at the gains it runs at: measured and
        # reported, not acted on (``PlantMargin`` says why)
        wavelength_m = float(self.wavelength_bl) * self.body_length
        pitch_m = float(np.median(np.diff(self.s_muscle))) if n > 1 else self.pitch
        self.wave_smoothing = smoothing_response(pitch_m, wavelength_m)
        self.muscles_per_wave = wavelength_m / pitch_m if pitch_m > 0.0 else math.inf
        self._set_integral_gain(body_info.get("operating_plant"))
        self.plant = PlantMargin.of(body_info.get("plant_response"), self.kp, self.ki, self.frequency_hz,
                                    self.wave_smoothing)
        self.gains = TrackGains(ramp_s=self.ramp_s, dt_tick=self.dt_tick, strain_per_kappa=self.strain_per_kappa,
                                kp=self.kp, ki=self.ki, umax=self.umax, passes=SMOOTHING_PASSES,
                                harmonics=self.harmonics, ki_h=self.ki_h, lead_cos=self.lead_cos,
                                lead_sin=self.lead_sin)
        n_h = self.harmonics.shape[0]
        self.state = TrackState(a=np.zeros(n), b=np.zeros(n), lateral=np.zeros(n), counts=np.zeros(3),
                                err=np.zeros(n), tmp=np.zeros(n), ah=np.zeros((n_h, n)), bh=np.zeros((n_h, n)))
        self.s_centre = None
        self._bend = None  # the guard's bend buffer (n - 2,) [strain]
        # a commanded wave the error's smoothing does not pass is not the loop's to correct (``LOOP_MIN_SMOOTHING``):
        # the calibrated open loop, held per tick like a back-off's, and the guard has nothing to watch (part of the
        # loop's protection: ``gait.shape_guard = false`` keeps the loop as it was)
        self.loop_off = self.guard is not None and self.wave_smoothing < LOOP_MIN_SMOOTHING
        if self.loop_off:
            self.gains = scaled_gains(self.gains, 0.0)
        self.full_gains, self.scale = self.gains, (1.0, 1.0)
        if self.guard is not None:
            self.guard.reset()
            self.guard.set_open_loop_harmonics(self.plant.harmonic_content if self.plant is not None else math.nan)
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
        guard = None if self.loop_off else self.guard
        counting = t >= self.t_steady
        trim = 1.0
        if guard is not None:
            scale = guard.gain_scales(t)
            if scale != self.scale:  # the guard backed off or resumes (``LoopGuard``): the loop's gains scaled
                if self.scale[0] == 0.0 and scale[0] > 0.0 and guard.trim != 1.0:
                    # the loop resumes: the open loop's trim is handed to its amplitude integral, which starts from
                    # it (u = trim x the feed-forward), so the command does not jump back to the feed-forward
                    self.state.a[...] = (guard.trim - 1.0) * _ramp(t, self.gains.ramp_s) * waves[_LATERAL, _AMP]
                self.gains, self.scale = scaled_gains(self.full_gains, *scale), scale
            if self.scale[0] == 0.0:
                trim = guard.trim
        if trim != 1.0:
            before = self.state.counts.copy()
        track_tick(self.kappa, self.s_muscle, waves, t, counting, plain(self.gains), plain(self.state))
        if trim != 1.0:
            # the loop held off: its command is the calibrated open loop's, trimmed in amplitude (``LoopGuard``); a
            # trimmed command is below the muscle's strength, so only its peak is counted again
            self.state.lateral[...] *= trim
            if counting:
                self.state.counts[1] = before[1]
                self.state.counts[2] = max(before[2], float(np.max(np.abs(self.state.lateral))))
        bend = None
        if guard is not None and obs.seg_pos.shape[0] >= 3:
            # the centre line's bend at the interior centres [strain], for the guard's waveform test
            pos = np.ascontiguousarray(obs.seg_pos, dtype=np.float64)  # one compiled signature for every body
            if self._bend is None or self._bend.shape[0] != pos.shape[0] - 2:
                self._bend = np.zeros(pos.shape[0] - 2)
            ground_bend(pos, self.strain_per_kappa, self._bend)  # the ring copies it (WaveformWatch.push)
            bend = self._bend
        if guard is not None and guard.watch(t, self.gains.ramp_s, waves, self.s_muscle, self.state, self.umax, bend,
                                             self.s_centre[1:-1], obs.seg_rot):
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
        op = self.operating
        out.update({"shape_gain_p_used": float(self.kp), "shape_gain_i_per_cycle_used": float(self.ki_per_cycle),
                    "shape_gain_i_from_plant": 1.0 if self.ki_from_plant else 0.0,
                    "shape_operating_amplitude": float(op["s_star"]) if op is not None else float("nan")})
        if self.guard is not None:
            gd = self.guard
            out.update({"shape_control_backoffs": float(gd.backoffs),
                        "shape_control_gain_scale": 0.0 if gd.fallen_back or self.loop_off else float(gd.scale),
                        "shape_control_open_loop_trim": float(gd.trim_min),
                        "shape_control_backoff_s": gd.times[0] if gd.times else float("nan")})
        return out

    def labels(self) -> dict[str, str]:
        """{"shape_gains": where the loop's gains came from} (the run's labels: JSON, store)."""
        ki = f"K_i {self.ki_per_cycle:g} per cycle from gait.shape_gain_i_per_cycle" if self.ki_key >= 0.0 \
            else self.ki_source
        return {"shape_gains": f"K_p {self.kp:g} from {self.kp_source}; {ki}"}

    def run_status(self) -> tuple[str, str] | None:
        """("controller_unstable", why) when the guard had to back the loop off in the measured window or for good
        (the open loop, or the integrals off): the motion measured there is the open loop's (or a lower gain's, or
        the proportional loop's), because the loop drove the shape away; ("ok", why) when the loop left a commanded
        wave it cannot see to the calibrated open loop (``LOOP_MIN_SMOOTHING``), or when the guard backed the loop off
        during the warm-up and it recovered before the steady window (``LoopGuard.recovered_in_warmup``: when, why,
        and the gains it resumed at); None otherwise."""
        if self.loop_off:
            return ("ok", f"the shape loop left the commanded wave to the calibrated open loop: "
                          f"{self.muscles_per_wave:.1f} muscle segments a wave, which the loop's smoothing along the "
                          f"body passes at {self.wave_smoothing:.3f}, under {LOOP_MIN_SMOOTHING:g} (it cannot see "
                          f"that wave)")
        gd = self.guard
        if gd is None:
            return None
        recovered = gd.recovered_in_warmup()
        if recovered is not None:
            return ("ok", recovered)
        if not gd.acted_in_window():
            return None
        when = ", ".join(f"{t:.2f} ({why})" for t, why in zip(gd.times, gd.reasons))
        end = "stayed in the calibrated open loop" if gd.fallen_back else \
            f"resumed at {gd.scale:g} of its gains" + (", its integrals off" if gd.integral_off else "")
        if gd.trim_min < 1.0:
            end += (f"; the open loop's amplitude, while the loop was held off, trimmed down to {gd.trim_min:.2f} of "
                    f"the feed-forward by the measured bend")
        return ("controller_unstable",
                f"controller_unstable: the shape tracker drove the body away from the commanded shape (bend over "
                f"{GUARD_AMPLITUDE_RATIO:g} x the command, most muscles at max_muscle_strain, a muscle driven beyond "
                f"{GUARD_STRENGTH_MARGIN:g} of it, segments twisted out of the plane, or the waveform's harmonics "
                f"beyond the open loop's) and was backed off (to the calibrated "
                f"open loop for a period, or its integrals off) at t = {when} s; it {end}")
