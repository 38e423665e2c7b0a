"""Each body's own map from a commanded body curvature to its muscle strain, measured and cached.

A gait that commands a shape (``gait.curvature_amplitude``: peak curvature x body length,
dimensionless) must produce the same shape on every body model.  The same LATERAL fibre strain
does not: the lattice's fibres sit at the corners of the cross-section (curvature = 2 strain /
width), the FEM body samples the strain at tet centroids inside the section, the hybrid body
bends only in its links.  So each body measures its own gain here:

1. the body is built weightless (gravity 0) with no ground (``terrain = "none"``), so nothing
   but its own elasticity shapes it;
2. every muscle segment gets the same LATERAL strain ``CAL_STRAIN``, ramped in over
   ``CAL_RAMP_S`` and then held;
3. once the segment centres stop moving, a circle fitted to them (interior segments, seen from
   above) gives the curvature kappa [1/m] the strain produces (a body still swinging after
   ``CAL_MAX_S`` gives the mean over the second half of the run: it swings about its equilibrium);
4. the gain is ``CAL_STRAIN / (kappa * L)`` [strain per unit of curvature x body length], L the
   creature's body length: a controller multiplies a commanded ``curvature_amplitude`` by it.

The result is cached on disk (``calibration_cache_dir()``), keyed by everything that shapes it:
the body's configuration, the creature's geometry and mass, the time step and the volume rule.
This module runs a body through the ``core.protocols`` interface only; it does not know any
controller (the runner passes the gain to the controller through ``body_info``).
"""
from __future__ import annotations

import dataclasses
import hashlib
import json
import math
import os
from pathlib import Path
from typing import Any, Callable

import numpy as np

from ..core.paths import cache_root
from ..core.protocols import LATERAL, Actuation, Observation

CAL_FORMAT = "curvature-cal-v1"
CAL_SEGMENTS = 10        # segments of the calibration body
CAL_STRAIN = 0.03        # fibre strain of the calibration bend: linear range, bends a snake by < 2 pi
CAL_RAMP_S = 0.3         # ramp the strain in over this time [s] (no jolt)
CAL_MAX_S = 3.0          # give up waiting for rest after this time [s]
CAL_CHUNK_S = 0.02       # strain held constant over chunks of this length [s]
CAL_SETTLE_REL = 2e-3    # rest: curvature changes by less than this fraction over one check interval
CAL_CHECK_S = 0.05       # check interval [s]
CAL_STEADY_CHECKS = 3    # consecutive steady checks that make rest


def calibration_cache_dir() -> Path:
    """``calibration/`` under ``core.paths.cache_root()``."""
    return cache_root() / "calibration"


def circle_curvature(points_xz: np.ndarray) -> float:
    """Curvature [1/m] of the least-squares circle through (n, 2) points (Kasa fit); 0 for a line."""
    p = np.asarray(points_xz, float)
    A = np.column_stack([p[:, 0], p[:, 1], np.ones(len(p))])
    b = -(p[:, 0] ** 2 + p[:, 1] ** 2)
    sol, _, rank, _ = np.linalg.lstsq(A, b, rcond=None)
    if rank < 3:  # collinear points: a straight line
        return 0.0
    D, E, F = sol
    r2 = 0.25 * (D * D + E * E) - F
    if not np.isfinite(r2) or r2 <= 0.0:
        return 0.0
    return 1.0 / math.sqrt(r2)


def _calibration_case(case):
    """The case of the calibration run: weightless, no ground, no perturbation, muscles only, and a
    short body of ``CAL_SEGMENTS`` segments of the creature's own segment size and mass per segment.

    The gain is local (strain per curvature of one segment); a long weightless body has slow,
    lightly damped free-free bending modes (a 50-segment lattice snake still swings after 3 s),
    a short one comes to rest in a fraction of a second."""
    sc = dataclasses.replace(case.scenario, terrain="none", gravity_m_s2=0.0, suspended=False, passive=False,
                             perturbation_m=0.0, start_height_m=0.0, slope_deg=0.0)
    cre = case.creature
    n = min(cre.segments, CAL_SEGMENTS)
    cre = dataclasses.replace(cre, segments=n, mass_kg=cre.mass_kg * n / cre.segments)
    return dataclasses.replace(case, scenario=sc, creature=cre)


def calibration_key(case) -> str:
    """sha256 over everything that changes the measured gain."""
    cre = case.creature
    data = {"format": CAL_FORMAT, "body": dataclasses.asdict(case.body),
            "creature": {k: getattr(cre, k) for k in ("segments", "segment_length_m", "width_m", "height_m",
                                                       "mass_kg")},
            "dt": case.dt, "volume_conserving": bool(case.gait.volume_conserving),
            "strain": CAL_STRAIN, "ramp": CAL_RAMP_S, "settle": CAL_SETTLE_REL}
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()


def measure_lateral_gain(factory: Callable[[Any, Any], Any], case, world) -> dict[str, float]:
    """Run the calibration bend (module docstring) on ``factory(case', world')`` (a ``BodySpec.factory``):
    case' the calibration case, world' the run's ``world`` less its ground, obstacles and food
    (``World.without_ground``: the gain is measured off the ground, and its cache key holds none of the
    scenario); return {"strain_per_curvature": gain [-], "curvature_m": kappa [1/m], "t_rest_s": time to rest [s]}."""
    cal = _calibration_case(case)
    body = factory(cal, world.without_ground(cal.scenario))
    body.compile()
    dt = cal.dt
    L = float(case.creature.body_length_m)  # the full creature's: the command is kappa x its length
    n_chunk = max(1, int(round(CAL_CHUNK_S / dt)))
    act = Actuation.for_body(body, rows=1)
    act.muscles_on = True
    obs = Observation()
    n_seg = body.n_segments
    inner = slice(2, n_seg - 2) if n_seg >= 8 else slice(0, n_seg)  # the ends bend less
    t, kappa_prev, t_check, n_steady = 0.0, None, CAL_RAMP_S, 0
    history = []
    kappa = 0.0
    while t < CAL_MAX_S:
        ramp = min(1.0, (t + n_chunk * dt) / CAL_RAMP_S)
        act.muscle[:, :, :] = 0.0
        act.muscle[:, :, LATERAL] = CAL_STRAIN * ramp
        k, code = body.advance(t, n_chunk, act)
        t += k * dt
        if code != 0:
            raise RuntimeError(f"curvature calibration of body {case.body.name!r} blew up at t = {t:.3f} s: "
                               f"{body.status_text(code)}")
        if t + 1e-12 >= t_check:
            body.sense(obs, t)
            kappa = circle_curvature(obs.seg_pos[inner][:, [0, 2]])
            steady = kappa_prev is not None and abs(kappa - kappa_prev) <= CAL_SETTLE_REL * max(kappa, 1e-12)
            n_steady = n_steady + 1 if steady else 0
            if n_steady >= CAL_STEADY_CHECKS:  # several in a row: not a turning point of an oscillation
                break
            kappa_prev = kappa
            history.append((t, kappa))
            t_check += CAL_CHECK_S
    else:
        # no rest within CAL_MAX_S (a lightly damped body still swings about its equilibrium):
        # the mean over the second half of the run
        kappa = float(np.mean([k for tt, k in history if tt >= 0.5 * (CAL_RAMP_S + CAL_MAX_S)]))
    if kappa <= 0.0:
        raise RuntimeError(f"curvature calibration of body {case.body.name!r}: the body did not bend")
    return {"strain_per_curvature": CAL_STRAIN / (kappa * L), "curvature_m": kappa, "t_rest_s": t}


def _read_cached(path: Path, fmt: int | None = None) -> dict[str, Any] | None:
    """The JSON entry at ``path`` (with ``"format"`` equal to ``fmt`` when given), or None: missing, damaged or of
    another format (then measured again)."""
    if not path.exists():
        return None
    try:
        res = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    return res if isinstance(res, dict) and (fmt is None or res.get("format") == fmt) else None


def _write_cached(path: Path, res: dict[str, Any]) -> None:
    """Write ``res`` to ``path`` atomically: a concurrent reader never sees half a file."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f"{path.stem}.{os.getpid()}.tmp")
    tmp.write_text(json.dumps(res))
    os.replace(tmp, path)


def lateral_gain(factory: Callable[[Any, Any], Any], case, world, cache: bool = True) -> float:
    """Strain per unit of (curvature x body length) of ``case``'s body, measured once and cached
    (``factory``, ``world``: as ``measure_lateral_gain``)."""
    path = calibration_cache_dir() / f"{calibration_key(case)}.json"
    held = _read_cached(path) if cache else None
    if held is not None:
        try:
            return float(held["strain_per_curvature"])
        except (KeyError, TypeError, ValueError):
            pass  # a damaged entry is measured again
    res = measure_lateral_gain(factory, case, world)
    if cache:
        _write_cached(path, {**res, "body": case.body.name})
    return float(res["strain_per_curvature"])


# ----------------------------------------------------------------------------- the plant of the shape loop
#
# The closed loop (``controllers.shape_tracking``) corrects the commanded wave's amplitude and phase at each muscle
# by integrating the error's in-phase and quadrature parts; that converges where the body's response to its command
# lags it by less than 90 degrees of the correction's lead, and diverges elsewhere.  The body's own lag depends on
# everything it moves against: its inertia at the gait frequency, the ground's friction, the wavelength.  So the
# plant is identified on the case itself: the body, on its own ground and in its own world, runs the calibrated open
# loop (the feed-forward the tracker starts from) for the ramp and PLANT_SETTLE_CYCLES periods, and over the next
# PLANT_FIT_CYCLES periods the ground curvature at each interior segment is fitted with the command's phase
# theta = k s - omega t + phi: kappa ~ Im(c e^{i theta}) + const.  The plant at that point is G = c / c_cmd, c_cmd
# the command's own coefficient: |G| the share of the commanded amplitude the open loop reaches, -arg G its lag.

PLANT_FORMAT = "plant-response-v2"  # v2: the open loop's harmonic content
PLANT_SETTLE_CYCLES = 1.0    # open-loop periods after the ramp before the fit (the friction's transient)
PLANT_FIT_CYCLES = 1.0       # periods fitted
PLANT_SAMPLES_PER_CYCLE = 40


def plant_key(case, scale: float = 1.0) -> str:
    """sha256 over everything that changes the open loop's response: the body, the creature, the world (scenario,
    friction), the gait's wave (not its shape-control gains), the time step and the calibrated gain's own key; and
    the command's scale over the feed-forward when it is not 1 (``operating_plant``)."""
    g = case.gait
    wave = {k: v for k, v in dataclasses.asdict(g).items() if not k.startswith(("shape_", "max_muscle"))}
    data = {"format": PLANT_FORMAT, "gain": calibration_key(case), "body": dataclasses.asdict(case.body),
            "creature": dataclasses.asdict(case.creature), "scenario": dataclasses.asdict(case.scenario),
            "friction": dataclasses.asdict(case.friction), "gait": wave, "dt": case.dt, "seed": case.seed,
            "settle": PLANT_SETTLE_CYCLES, "fit": PLANT_FIT_CYCLES, "samples": PLANT_SAMPLES_PER_CYCLE}
    if scale != 1.0:  # the feed-forward's own identification keeps the key it always had
        data["scale"] = float(scale)
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()


def fit_wave_response(s: np.ndarray, t: np.ndarray, kappa: np.ndarray, wavenumber: float, omega: float,
                      phase: float, commanded: float) -> np.ndarray:
    """(n,) complex G at each point: the least-squares coefficient c of kappa (T, n) [1/m] at rest arc lengths
    s (n,) [m] and times t (T,) [s] on Im(c e^{i theta}) + const, theta = wavenumber s - omega t + phase, over
    ``commanded`` (the command's own coefficient, signed [1/m])."""
    out = np.zeros(s.shape[0], dtype=complex)
    for j in range(s.shape[0]):
        th = wavenumber * s[j] - omega * t + phase
        basis = np.column_stack([np.sin(th), np.cos(th), np.ones_like(t)])
        coef, *_ = np.linalg.lstsq(basis, kappa[:, j], rcond=None)
        out[j] = (coef[0] + 1j * coef[1]) / commanded
    return out


def wave_harmonic_content(s: np.ndarray, t: np.ndarray, kappa: np.ndarray, wavenumber: float, omega: float,
                          phase: float, commanded: float, max_harmonic: int = 5) -> float:
    """RMS over the points s (n,) [m] of the temporal harmonics 2 to ``max_harmonic`` of kappa (T, n) [1/m] at times
    t (T,) [s], least-squares fitted in the command's phase theta = wavenumber s - omega t + phase (with the
    fundamental and a constant), over |commanded| [1/m]: the open loop's own share of the waveform that is not a
    travelling sine, as ``metrics.shape_tracking.shape_harmonic_content`` measures a run's."""
    h = np.arange(1, max_harmonic + 1)
    power = np.zeros(s.shape[0])
    for j in range(s.shape[0]):
        th = wavenumber * s[j] - omega * t + phase
        basis = np.concatenate([np.sin(np.outer(th, h)), np.cos(np.outer(th, h)), np.ones((t.shape[0], 1))], axis=1)
        coef, *_ = np.linalg.lstsq(basis, kappa[:, j], rcond=None)
        power[j] = np.sum(coef[1:max_harmonic] ** 2 + coef[max_harmonic + 1:2 * max_harmonic] ** 2)
    return float(np.sqrt(np.mean(power)) / abs(commanded))


def measure_plant_response(make_body: Callable[[Any], Any], case, fill: Callable, wave: tuple,
                           scale: float = 1.0) -> dict[str, Any]:
    """Identify the open loop's response (the block comment above) on ``make_body(case)`` driven by
    ``fill(t0, dt, n_rows, act)`` (the calibrated open loop's actuation) with its LATERAL strain times ``scale``
    [-] (1: the feed-forward itself; ``operating_plant``), the response read against the scaled command.
    wave: (wavenumber [rad/m], omega [rad/s], phase [rad], commanded ground curvature coefficient [1/m], ramp [s]).
    Returns {"s": (n,) [m], "gain": (n,) |G|, "lag_deg": (n,) -arg G [deg], "harmonic_content": the open loop's
    harmonics 2 to 5 over the command [-] (``wave_harmonic_content``), "status": "ok" or why not}."""
    from ..kinematics.centre_lines import ground_curvature  # noqa: PLC0415 (the metrics' own curvature)

    k, om, ph, kappa_cmd, ramp = wave
    kappa_cmd = kappa_cmd * scale
    if scale != 1.0:
        feed_forward = fill

        def fill(t0, dt_, n_rows, act_):  # noqa: E306 (the feed-forward's LATERAL strain, scaled)
            feed_forward(t0, dt_, n_rows, act_)
            act_.muscle[:n_rows, :, LATERAL] *= scale
    body = make_body(case)
    body.compile()
    dt = case.dt
    period = 2.0 * math.pi / om
    t_fit = ramp + PLANT_SETTLE_CYCLES * period
    t_end = t_fit + PLANT_FIT_CYCLES * period
    n_chunk = max(1, int(round(period / PLANT_SAMPLES_PER_CYCLE / dt)))
    act = Actuation.for_body(body)
    obs = Observation()
    t, times, curves, s = 0.0, [], [], None
    fill(0.0, dt, 1, act)
    body.advance(0.0, 0, act)
    while t < t_end - 0.5 * n_chunk * dt:
        fill(t, dt, n_chunk + 1, act)
        done, code = body.advance(t, n_chunk, act)
        t += done * dt
        if code != 0:
            return {"s": [], "gain": [], "lag_deg": [], "status": f"the open loop blew up at t = {t:.3f} s: "
                                                                    f"{body.status_text(code)}"}
        if t + 1e-12 >= t_fit:
            body.sense(obs, t)
            pts = np.asarray(obs.seg_pos, float)
            if s is None:
                pitch = float(body.segment_pitch_m)
                s = float(obs.seg_half[0, 0]) + pitch * np.arange(pts.shape[0], dtype=float)
            kappa, _ = ground_curvature(pts[None])
            times.append(t)
            curves.append(kappa[0])
    if s is None or len(times) < 8 or s.shape[0] < 5:
        return {"s": [], "gain": [], "lag_deg": [], "status": "too few samples or segments to fit"}
    G = fit_wave_response(s[1:-1], np.asarray(times), np.asarray(curves), k, om, ph, kappa_cmd)
    content = wave_harmonic_content(s[1:-1], np.asarray(times), np.asarray(curves), k, om, ph, kappa_cmd)
    return {"s": s[1:-1].tolist(), "gain": np.abs(G).tolist(), "lag_deg": (-np.degrees(np.angle(G))).tolist(),
            "harmonic_content": content, "status": "ok"}


def plant_response(make_body: Callable[[Any], Any], case, fill: Callable, wave: tuple,
                   cache: bool = True, scale: float = 1.0) -> dict[str, Any]:
    """``measure_plant_response`` of ``case`` (at ``scale`` times the feed-forward), measured once and cached by
    ``plant_key``."""
    path = calibration_cache_dir() / f"plant-{plant_key(case, scale)}.json"
    held = _read_cached(path, PLANT_FORMAT) if cache else None
    if held is not None:
        return held
    res = {**measure_plant_response(make_body, case, fill, wave, scale), "format": PLANT_FORMAT,
           "body": case.body.name, "scale": float(scale)}
    if cache:
        _write_cached(path, res)
    return res


# ----------------------------------------------------------------------------- the plant at the loop's own amplitude
#
# Under Coulomb friction the open loop's response does not grow in proportion to its command: a bend costs a friction
# moment that does not grow with the bend, so the body hardly bends until the muscles' moment passes the friction's,
# and then bends like the free body.  The closed loop commands whatever amplitude makes the body reach the command,
# so its plant is the body's response at THAT amplitude (a describing function): the amplitude s* times the
# feed-forward at which the open loop reaches the command, s* |G(s*)| = 1, G(s) the response to s times the
# feed-forward read against the scaled command (``measure_plant_response``'s ``scale``).  Measured on the lattice's
# slithering grid (docs/explanation/shape-tracking.md, "How the gains are derived"): at mu_t / mu_f = 3, 5 and 10
# |G| is 0.58, 0.20 and 0.03 at s = 1 and 0.91, 0.86 and 0.82 at s = 2 (lags 12-13 degrees), so s* lies between 1
# and 2 there, where |G| changes fourfold to thirtyfold; beyond, |G| is near 1 (0.98-1.05 at s = 4 and 8).
#
# ``operating_plant`` finds s* in [OPERATING_S_MIN, OPERATING_S_MAX] from the feed-forward's identification
# (s = 1, already measured for the margin and the guard) and at most OPERATING_MAX_RUNS more, each a whole
# identification run (the ramp and two periods): none where the feed-forward already reaches the command within
# OPERATING_TOL (or overshoots it: s* = 1, the bound), else s = OPERATING_FIRST_S, doubled until the response passes
# the command (a bracket), then one secant step inside the bracket.  s* is the secant's root of y(s) = s |G(s)| - 1
# on the last bracket; there |G(s*)| = 1 / s* by definition, and the lag is interpolated linearly in s between the
# bracket's ends (or read at a run whose y is within OPERATING_TOL of 1).  Cached by the case's plant key.

OPERATING_FORMAT = "operating-plant-v1"
OPERATING_S_MIN = 1.0
OPERATING_S_MAX = 8.0
OPERATING_FIRST_S = 2.0   # past the friction's threshold at mu_t / mu_f 3 to 10 on the lattice's grid (above)
OPERATING_TOL = 0.1       # |s |G(s)| - 1| within which s is taken as the operating amplitude
OPERATING_MAX_RUNS = 1    # identification runs beyond the feed-forward's (test time: issue 41, see the docs)


def _median_response(res: dict[str, Any]) -> tuple[float, float] | None:
    """(median |G|, median lag [deg]) of an identification, or None when it is not ok."""
    if not res or res.get("status") != "ok" or not res.get("gain"):
        return None
    return float(np.median(res["gain"])), float(np.median(res["lag_deg"]))


def operating_amplitude(points: list[tuple[float, float, float]]) -> tuple[float, float, float] | None:
    """The operating amplitude from identified points (s [-], median |G(s)| [-], median lag [deg]), s ascending:
    (s* [-], |G(s*)| [-], lag(s*) [deg]) where y(s) = s |G(s)| reaches 1 (the block comment above), or None when
    the points do not reach the command (no bracket).  A point whose y is within ``OPERATING_TOL`` of 1 is taken as
    it is; the first point already at or above 1 (within the tolerance or beyond) gives s* = that s; else the secant
    of y between the last point below 1 and the first above it."""
    prev = None
    for s, g, lag in points:
        y = s * g
        if abs(y - 1.0) <= OPERATING_TOL:
            return s, g, lag
        if y > 1.0:
            if prev is None:  # the first point overshoots the command: the bound
                return s, g, lag
            s0, g0, lag0 = prev
            y0 = s0 * g0
            s_star = s0 + (1.0 - y0) * (s - s0) / (y - y0)
            w = (s_star - s0) / (s - s0)
            return s_star, 1.0 / s_star, (1.0 - w) * lag0 + w * lag
        prev = (s, g, lag)
    return None


def operating_key(case) -> str:
    """sha256 of the case's plant key (the feed-forward's identification the search starts from) and the search's
    own constants."""
    data = {"format": OPERATING_FORMAT, "plant": plant_key(case), "s": [OPERATING_S_MIN, OPERATING_S_MAX,
            OPERATING_FIRST_S], "tol": OPERATING_TOL, "runs": OPERATING_MAX_RUNS}
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


def measure_operating_plant(make_body: Callable[[Any], Any], case, fill: Callable, wave: tuple,
                            base: dict[str, Any], cache: bool = True) -> dict[str, Any]:
    """Find the operating amplitude (the block comment above) from ``base``, the feed-forward's identification
    (``plant_response`` at scale 1), and at most ``OPERATING_MAX_RUNS`` more identifications (``plant_response`` at
    s times the feed-forward, each cached).  Returns {"s_star": s* [-], "gain": |G(s*)| [-], "lag_deg": [deg],
    "points": [[s, median |G|, median lag], ...] measured, "runs": identifications beyond the feed-forward's,
    "status": "ok" or why not}."""
    first = _median_response(base)
    if first is None:
        why = base.get("status", "none") if base else "none"
        return {"status": f"the feed-forward's identification is not ok: {why}", "points": [], "runs": 0}
    points = [(OPERATING_S_MIN, *first)]
    runs, s = 0, OPERATING_FIRST_S
    found = operating_amplitude(points)
    while found is None and runs < OPERATING_MAX_RUNS and s <= OPERATING_S_MAX:
        res = _median_response(plant_response(make_body, case, fill, wave, cache=cache, scale=s))
        runs += 1
        if res is None:
            return {"status": f"the identification at {s:g} x the feed-forward is not ok", "points": points,
                    "runs": runs}
        points.append((s, *res))
        found = operating_amplitude(points)
        s *= 2.0
    if found is None:
        y = ", ".join(f"{p[0] * p[1]:.3f} at s = {p[0]:g}" for p in points)
        return {"status": f"the open loop did not reach the command up to {points[-1][0]:g} x the feed-forward "
                          f"(s |G(s)|: {y})", "points": points, "runs": runs}
    s_star, g, lag = found
    return {"s_star": s_star, "gain": g, "lag_deg": lag, "points": points, "runs": runs, "status": "ok"}


def operating_plant(make_body: Callable[[Any], Any], case, fill: Callable, wave: tuple, base: dict[str, Any],
                    cache: bool = True) -> dict[str, Any]:
    """``measure_operating_plant`` of ``case``, cached by ``operating_key``."""
    path = calibration_cache_dir() / f"operating-{operating_key(case)}.json"
    held = _read_cached(path, OPERATING_FORMAT) if cache else None
    if held is not None:
        return held
    res = {**measure_operating_plant(make_body, case, fill, wave, base, cache=cache), "format": OPERATING_FORMAT,
           "body": case.body.name, "max_runs": OPERATING_MAX_RUNS}
    if cache:
        _write_cached(path, res)
    return res
