"""What the paper's kinematic stance costs in fidelity (issue 43): the same myriapod walk with the paper's
kinematic stance (supported segments carried to their targets, Fang et al. 2013 Sec. 3) and with the
dynamic stance (``legs.stance = "dynamic"``: legs that push through friction-limited feet,
docs/explanation/dynamic-stance.md), compared.

The measured value, the error axis a scorecard can rank the bodies' kinematic runs by, is the
deviation of the kinematic walk's head path from the dynamic walk's: the largest ground-plane distance
between the heads at the same sample, in body lengths.  Figures: the speed ratio (the dynamic walk's
centre-of-mass speed over the kinematic one's), the lateral undulation amplitudes of both
(``metrics.undulation``) and their difference, and the share of leg-state timeline samples on which
both walks' legs are in the same state.  The verdict is INFO: the deviation is a measure of the
shortcut, not a pass or a fail (the dynamic stance is a model too, with its own defaults).

The runs: the creature on the ``straight`` CONTROL walk (0.5 m/s, no turns), 4 s with ``--quick``, else
10 s, its default size, each body's default time step; the dynamic run with the dynamic stance's
defaults (10 Hz, critical damping, the scenario's friction, the Follower's speed feedforward:
``controller.follower_feedforward`` 'auto').  The scorecard ranks the myriapods' bodies by the measured value
(``report.scorecard.shortcut_error``).
"""
from __future__ import annotations

import numpy as np

from .core import INFO, Context, Outcome, failed_run

SCENARIO = "straight"
DYNAMIC = ("legs.stance=dynamic",)
# every myriapod scenario (the worlds of tests/test_dynamic_stance_walk.py), for ``worlds_shortcut``
WORLDS = ("walk", "straight", "control", "drop-adjust", "hang", "terrain", "fig13-cylinders", "foraging",
          "fig12-water-foraging")
WORLDS_DURATION_S = 4.0  # each world's pair of walks [s]: the paper's brains turn, forage and avoid within it
WORLDS_QUICK_S = 1.5  # with --quick (tests): every world built and walked in both stances


def _deviation(kin, dyn) -> tuple[float, float]:
    """(largest head distance [m] at common samples, share of equal leg states at common timeline rows)."""
    sk, sd = kin.series, dyn.series
    n = min(len(sk.t), len(sd.t))
    path = float(np.linalg.norm((sk.head[:n] - sd.head[:n])[:, [0, 2]], axis=1).max()) if n else float("nan")
    _, st_k, _ = kin.extra["leg_timeline"]
    _, st_d, _ = dyn.extra["leg_timeline"]
    m = min(len(st_k), len(st_d))
    agree = float((np.asarray(st_k[:m]) == np.asarray(st_d[:m])).mean()) if m else float("nan")
    return path, agree


def _shortcut(ctx: Context, creature: str, body: str) -> Outcome:
    duration = 4.0 if ctx.quick else 10.0
    reference = "the dynamic stance's walk (deviation 0)"
    kin = ctx.run(creature, body, SCENARIO, duration=duration)
    if kin.status != "ok":
        return failed_run(kin, reference)
    dyn = ctx.run(creature, body, SCENARIO, duration=duration, overrides=DYNAMIC)
    if dyn.status != "ok":
        return failed_run(dyn, reference)
    path, agree = _deviation(kin, dyn)
    length = float(kin.metrics.get("body_length_m", float("nan")))
    vk, vd = kin.metrics.get("speed_m_per_s"), dyn.metrics.get("speed_m_per_s")
    ratio = vd / vk if vk else float("nan")
    uk, ud = kin.metrics.get("undulation_amplitude_bl"), dyn.metrics.get("undulation_amplitude_bl")
    dev_bl = path / length
    detail = (f"kinematic against dynamic stance over {duration:g} s: heads {path:.3g} m apart at most "
              f"({dev_bl:.3g} BL), speed ratio dynamic/kinematic {ratio:.3g}, undulation {uk:.3g} vs {ud:.3g} BL, "
              f"leg states equal on {100 * agree:.0f} % of the timeline")
    return Outcome(INFO, dev_bl, 0.0, "- (a measure of the shortcut, INFO)", detail, "BL",
                   {"path_deviation_m": path, "speed_ratio_dynamic_over_kinematic": ratio,
                    "undulation_kinematic_bl": uk, "undulation_dynamic_bl": ud,
                    "undulation_difference_bl": (ud - uk) if uk is not None and ud is not None else float("nan"),
                    "leg_state_agreement": agree})


def centipede_shortcut(ctx: Context, body: str) -> Outcome:
    """The centipede's kinematic stance against its dynamic stance (module docstring)."""
    return _shortcut(ctx, "centipede", body)


def millipede_shortcut(ctx: Context, body: str) -> Outcome:
    """The millipede's kinematic stance against its dynamic stance (module docstring)."""
    return _shortcut(ctx, "millipede", body)


def worlds_shortcut(ctx: Context, body: str) -> Outcome:
    """The centipede's kinematic stance against its dynamic stance in every myriapod scenario (``WORLDS``: flat
    and straight walks, CONTROL's turn, the drop and the hang, the heightfield terrain, the cylinders, foraging,
    shallow water), ``WORLDS_DURATION_S`` each (``WORLDS_QUICK_S`` with ``--quick``).  The measured value is the largest head path deviation over the
    worlds [BL]; the figures give each world's deviation, speed ratio and leg-state agreement.  A world whose
    walk fails in either stance is named in the detail and left out of the largest value; the row fails only
    when no world gives a pair of walks."""
    reference = "the dynamic stance's walk in each world (deviation 0)"
    duration = WORLDS_QUICK_S if ctx.quick else WORLDS_DURATION_S
    figures: dict[str, float] = {}
    worst, worst_world, failed, first_failure = -1.0, "", [], None
    for world in WORLDS:
        kin = ctx.run("centipede", body, world, duration=duration)
        dyn = ctx.run("centipede", body, world, duration=duration, overrides=DYNAMIC) \
            if kin.status == "ok" else kin
        if kin.status != "ok" or dyn.status != "ok":
            bad = kin if kin.status != "ok" else dyn
            failed.append(f"{world} ({'kinematic' if bad is kin else 'dynamic'}: {bad.status})")
            first_failure = first_failure or bad
            for name in ("deviation_bl", "speed_ratio", "leg_state_agreement"):
                figures[f"{world}_{name}"] = float("nan")
            continue
        path, agree = _deviation(kin, dyn)
        dev_bl = path / float(kin.metrics.get("body_length_m", float("nan")))
        vk, vd = kin.metrics.get("speed_m_per_s"), dyn.metrics.get("speed_m_per_s")
        figures[f"{world}_deviation_bl"] = dev_bl
        figures[f"{world}_speed_ratio"] = vd / vk if vk else float("nan")
        figures[f"{world}_leg_state_agreement"] = agree
        if dev_bl > worst:
            worst, worst_world = dev_bl, world
    if worst < 0.0:
        return failed_run(first_failure, reference)
    detail = (f"kinematic against dynamic stance, {duration:g} s in each of {len(WORLDS)} worlds: heads "
              f"{worst:.3g} BL apart at most ({worst_world}); "
              + ", ".join(f"{w} {figures[w + '_deviation_bl']:.3g}" for w in WORLDS
                          if figures[w + "_deviation_bl"] == figures[w + "_deviation_bl"])
              + (f"; not compared: {', '.join(failed)}" if failed else ""))
    return Outcome(INFO, worst, 0.0, "- (a measure of the shortcut, INFO)", detail, "BL", figures)
