"""Measure each body's response to a short bending wave, the waves that limit the shape loop's proportional gain
(issue 44 item 2; docs/explanation/shape-tracking.md, "How the gains are derived").

    python tools/short_wave_response.py --body massspring fem hybrid
    python tools/short_wave_response.py --body fem --periods 6 8 10.7 --json out.json

The shape loop's proportional term acts on the error smoothed along the body (8 binomial passes: a profile of P
muscle segments passes at rho(P) = cos(pi / P)^16).  The body's own short bending waves are lightly damped and fast
(tens of hertz); what the loop feeds back of them is K_p rho(P) |G_short|, |G_short| the body's response to a
P-segment wave at its resonance.  A gain-margin rule sets K_p = m / max_P (rho(P) |G_short(P)|).

For each body and wave length P [muscle pitches]: the default snake (``snake``, its 50 segments, the body's default
dt), weightless on no ground (the curvature calibration's world: the least damping the body's own waves get), every
muscle segment given a standing LATERAL strain pattern A sin(2 pi s / (P pitch)), ramped in over RAMP_S and held to
HOLD_S, then released (strain 0).  The curvature the loop reads (the segment frames, ``measured_curvature``) at the
muscle positions, less its two end muscles at each end, is projected on the pattern: q(t) [1/m].

- G0: q at the end of the hold over the commanded curvature A / (g L) (g the body's calibrated strain per curvature x
  body length): 1 when the pattern bends the body as the calibrated gain predicts;
- the ring-down after the release: its frequency f_n [Hz] (half periods between zero crossings) and damping ratio
  zeta (the logarithmic decrement of the extrema between crossings, delta per half period, the slope of their
  logarithm fitted over the record: zeta = delta / sqrt(pi^2 + delta^2));
- the resonance's gain |G_short| = G0 / (2 zeta sqrt(1 - zeta^2)) (1 for zeta >= 1/sqrt(2): no resonance),
  and the loop's gain per unit K_p, rho(P) |G_short|.

Prints one line per (body, P) and, per body, max_P rho |G_short| and the K_p a margin m would give.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys

import numpy as np

AMPLITUDE = 0.01     # strain amplitude of the pattern: small, linear
RAMP_S = 0.2         # ramp in [s]
HOLD_S = 1.0         # the pattern held until this time [s]
RING_S = 2.0         # the ring-down recorded [s]
SAMPLE_S = 0.0005    # sampling interval [s]
END_MUSCLES = 2      # muscles left out at each end (the free ends bend less)


def ring_down(t: np.ndarray, q: np.ndarray) -> tuple[float, float]:
    """(f_n [Hz], zeta) of a decaying oscillation q(t): half periods between zero crossings, log decrement of the
    extrema between them; (nan, nan) when it does not oscillate (fewer than three crossings)."""
    q = q - np.mean(q[-max(3, len(q) // 10):])  # a static residual
    sign = np.signbit(q)
    cross = np.nonzero(sign[1:] != sign[:-1])[0]
    if len(cross) < 3:
        return math.nan, math.nan
    half = np.diff(t[cross])
    f_d = 1.0 / (2.0 * float(np.median(half)))
    ext = np.array([float(np.max(np.abs(q[a:b + 1]))) for a, b in zip(cross[:-1], cross[1:])])
    ext = ext[ext > 0.0]
    if ext.shape[0] < 3:
        return f_d, math.nan
    # the decrement per half period: the slope of the extrema's logarithm over all half periods of the record
    # (two modes beating make successive ratios scatter about it)
    delta = -float(np.polyfit(np.arange(ext.shape[0]), np.log(ext), 1)[0])
    zeta = delta / math.sqrt(math.pi ** 2 + delta ** 2) if delta > 0.0 else 0.0
    f_n = f_d / math.sqrt(max(1e-12, 1.0 - zeta ** 2))
    return f_n, zeta


GROUND = ("friction.model=coulomb", "friction.mu_forward=0.05", "friction.mu_backward=0.075",
          "friction.mu_transverse=0.05")  # the slithering grid's ground at mu_t / mu_f = 1 (its least lateral damping)


def measure(body_name: str, period_pitches: float, ground: bool = False) -> dict:
    """The short-wave response of ``body_name``'s default snake to a P = ``period_pitches`` pattern (module
    docstring); ``ground``: on the slithering grid's ground at mu_t / mu_f = 1 (``GROUND``), under gravity, instead
    of weightless on none."""
    from bench_myriapoda.bodies.curvature_calibration import lateral_gain
    from bench_myriapoda.controllers.shape_tracking import measured_curvature, smoothing_response
    from bench_myriapoda.core import registry
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.core.protocols import LATERAL, Actuation, Observation, body_info
    from bench_myriapoda.harness.runner import run_world

    registry.load_all()
    case = resolve_case("snake", body_name, "flat", "lateral-undulation", duration=1.0,
                        overrides=list(GROUND) if ground else [])
    spec = registry.BODIES[body_name]
    case = dataclasses.replace(case, dt=min(case.dt, spec.default_dt(case.body)))
    world = run_world(case)
    g = lateral_gain(spec.factory, case, world)
    sc = dataclasses.replace(case.scenario, terrain="none", gravity_m_s2=0.0, suspended=False, passive=False,
                             perturbation_m=0.0, start_height_m=0.0, slope_deg=0.0)
    free = case if ground else dataclasses.replace(case, scenario=sc)
    body = spec.factory(free, world if ground else world.without_ground(sc))
    body.compile()
    info = body_info(body, free.dt)
    s_m = np.asarray(info["muscle_s"], float)
    pitch_m = float(np.median(np.diff(s_m)))
    lam = period_pitches * pitch_m
    pattern = np.sin(2.0 * math.pi * s_m / lam)
    inner = slice(END_MUSCLES, len(s_m) - END_MUSCLES)
    basis = pattern[inner]
    L = float(case.creature.body_length_m)
    kappa_cmd = AMPLITUDE / (g * L)
    dt = free.dt
    n_chunk = max(1, int(round(SAMPLE_S / dt)))
    act = Actuation.for_body(body, rows=1)
    act.muscles_on = True
    obs = Observation()
    kappa = np.zeros(len(s_m))
    s_centre = psi = None
    t, times, qs, t_release = 0.0, [], [], HOLD_S
    q_hold = []
    while t < HOLD_S + RING_S:
        ramp = min(1.0, (t + n_chunk * dt) / RAMP_S) if t < t_release else 0.0
        act.muscle[:, :, :] = 0.0
        act.muscle[0, :, LATERAL] = AMPLITUDE * ramp * pattern
        k, code = body.advance(t, n_chunk, act)
        t += k * dt
        if code != 0:
            return {"body": body_name, "P": period_pitches, "status": f"blew up at t = {t:.3f} s: "
                                                                         f"{body.status_text(code)}"}
        body.sense(obs, t)
        if s_centre is None:
            n = obs.seg_rot.shape[0]
            s_centre = float(obs.seg_half[0, 0]) + float(body.segment_pitch_m) * np.arange(n, dtype=float)
            psi = np.zeros(n)
        measured_curvature(np.ascontiguousarray(obs.seg_rot, dtype=np.float64), s_centre, s_m, psi, kappa)
        q = float(np.dot(kappa[inner], basis) / np.dot(basis, basis))
        if t <= t_release:
            if t >= t_release - 0.1:
                q_hold.append(q)
        else:
            times.append(t)
            qs.append(q)
    g0 = abs(float(np.mean(q_hold))) / kappa_cmd
    f_n, zeta = ring_down(np.asarray(times), np.asarray(qs))
    if math.isfinite(zeta) and zeta < 1.0 / math.sqrt(2.0):
        peak = g0 / (2.0 * zeta * math.sqrt(1.0 - zeta ** 2)) if zeta > 0.0 else math.inf
    else:
        peak = g0
    rho = smoothing_response(pitch_m, lam)
    return {"body": body_name, "P": period_pitches, "wavelength_bl": lam / L, "G0": g0, "f_n_hz": f_n, "zeta": zeta,
            "G_short": peak, "rho": rho, "loop_gain_per_kp": rho * peak, "kp_body": float(spec.shape_gain_p),
            "dt": dt, "ground": ground, "status": "ok", "t": times, "q": qs, "q_hold": float(np.mean(q_hold))}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--body", nargs="+", default=["massspring", "fem", "hybrid"])
    ap.add_argument("--periods", nargs="+", type=float, default=[6.0, 8.0, 10.7],
                    help="wave lengths in muscle pitches (the smoothing passes 6, 8, 10.7 at 0.10, 0.28, 0.50)")
    ap.add_argument("--margin", type=float, default=1.0, help="the gain margin m of K_p = m / max rho |G_short|")
    ap.add_argument("--ground", action="store_true",
                    help="on the slithering grid's ground at mu_t / mu_f = 1 under gravity (default: weightless, none)")
    ap.add_argument("--json", default=None, help="write the rows to this file")
    a = ap.parse_args(argv)
    rows = []
    for b in a.body:
        best = None
        for p in a.periods:
            r = measure(b, p, a.ground)
            rows.append(r)
            if r["status"] != "ok":
                print(f"{b} P {p:g}: {r['status']}", flush=True)
                continue
            print(f"{b} P {p:g} ({r['wavelength_bl']:.3f} BL): G0 {r['G0']:.3f} f_n {r['f_n_hz']:.1f} Hz zeta "
                  f"{r['zeta']:.3f} |G_short| {r['G_short']:.2f} rho {r['rho']:.3f} rho|G_short| "
                  f"{r['loop_gain_per_kp']:.3f}", flush=True)
            if best is None or r["loop_gain_per_kp"] > best["loop_gain_per_kp"]:
                best = r
        if best is not None:
            print(f"{b}: max rho |G_short| {best['loop_gain_per_kp']:.3f} at P {best['P']:g}; K_p = m / that = "
                  f"{a.margin / best['loop_gain_per_kp']:.3f} at m = {a.margin:g} (the body's constant: "
                  f"{best['kp_body']:g})", flush=True)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(rows, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
