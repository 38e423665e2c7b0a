"""Same command, same motion: lateral undulation on every body model against the kinematic reference.

Issue 11.  One wave per body, commanded curvature x body length 7 (``gait.curvature_amplitude``,
each body's own strain gain from ``bodies/curvature_calibration.py``), Froude number 0.1 and
mu_b = 1.5 mu_f.  The snake is a short one (20 segments, 1 m, its own mass per length) with a 4 s
period: Fr = 0.1 then gives mu_f = L / (T^2 g Fr) = 0.064, so the muscles' bending moment is
large against friction at every ratio (a 2.5 m snake at Fr = 0.1 and T = 2 s would meet
mu_f = 0.64) and the runs stay short: half a period of ramp, one period of warm-up, two measured.

* The body shape: measured curvature amplitude within 10 % of the command on massspring, fem
  and hybrid (the hybrid's centre line is measured through its rigid boxes only: its bending
  sits in the links, and alternating box and link centres make the discrete curvature uneven).
* Forward speed [BL/cycle] within 15 % of the kinematic reference model for mu_t / mu_f = 1.5, 2, 3,
  5, 10 and below 0.03 at ratio 1; the three bodies within 10 % of each other at every ratio from 1.5
  to 10.  The reference is ``reference.slithering.steady_slithering`` evaluated at the body's own belly
  width (``width_bl`` = creature.width_m / body length = 0.05: two contact lines at the belly's edges,
  where the lattice's bottom nodes and the boxes' bottom corners are); the lattice and the hybrid
  must also stay within 10 % of it.  Measured at this commit at each body's default dt (BL/cycle at
  ratios 1.5, 2, 3, 5, 10; ratio 1 in brackets):
  reference, width 0.05 BL: 0.112, 0.171, 0.263, 0.388, 0.524 (0.022);
  reference, zero width (Hu et al.'s line): 0.094, 0.159, 0.257, 0.384, 0.522 (0.0085);
  massspring 0.114, 0.178, 0.273, 0.397, 0.539 (0.018): +1 to +4 % of its width's reference;
  fem 0.111, 0.183, 0.285, 0.419, 0.574 (0.001): -1 to +9 %;
  hybrid 0.113, 0.175, 0.272, 0.404, 0.557 (0.023): +1 to +6 %;
  spread (max - min) / mean 2.7, 4.5, 4.7, 5.4, 6.3 %.
  Measured curvature at ratio 3: massspring 6.89, fem 6.98, hybrid boxes 6.74.

  The zero-width line is not the model of these bodies (no test compares with it): a bending body's
  cross-sections turn, so the belly's two edges slide along the body in opposite directions at
  +-(w/2) dtheta/dt; Coulomb friction depends on the slip direction only, so where a section turns
  faster than it slides along the body the edges' pulls along it cancel while a sideways slip is
  still resisted, which adds to the belly's anisotropy (with mu_b = mu_f too).  Every body is
  18-20 % above the line at ratio 1.5 and 0.01-0.02 BL/cycle above it at every ratio, as the
  reference of the body's width is.  A lattice of half the width (stiffness x 4, the same bending
  stiffness) slows to 0.103 at ratio 1.5 (that reference: 0.101; the full-width lattice at
  stiffness x 4: 0.116).

  Artefacts fixed (issue 11), with the figures before:
  - a node hovering inside the contact distance while moving down got friction with no normal
    impulse (the fem speed fell with dt: ratio 5 0.467, 0.392, 0.112 at 1/3000, 1/6000, 1/12000 s);
  - the hybrid's boxes took the maximum-dissipation point of the friction ellipse, which resists
    sideways slip mu_t / mu_f times harder than Hu et al.'s law (ratio 5: 0.622);
  - the six-tet (Kuhn) split of the fem body and of the hybrid's links, not symmetric about the
    horizontal plane.  On the fem a segment's ground load swung by +-53 % of its weight with the
    curvature (speeds 0.119, 0.205, 0.320, 0.470, 0.643; ratio 1: -0.022); on the hybrid a lateral
    bend pitched the boxes nose down onto the links (at ratio 3 a middle box carried 0.06 N of its
    0.15 N weight on its two front corners, the head and tail boxes 0.27 and 0.39 N: 0.104, 0.193,
    0.311, 0.456, 0.622; ratio 1: -0.042).  Both now use the symmetric five-tet split;
  - the fem's per-tet lumped masses (eq. 12).  The five-tet split gives its central tet, a third of
    the cell, to four alternate corners, so the belly nodes' masses varied 10-fold along the body for
    the same share of the weight; a node's contact stops its sliding whenever its slip speed is
    below mu times its normal impulse per unit mass (~ mu g dt x load / mass), so the light nodes
    stuck where they should slide, a time-step error: 0.113, 0.187, 0.292, 0.432, 0.599 (ratio 1:
    0.001), 9-14 % above the reference of the body's width and 10.6 % apart from the lattice at
    ratio 10.  The snake's fem body now lumps an eighth of every grid cell's mass on each corner
    (``body.mass_lumping = "cells"``).  Ratio 5 at dt 1/3000, 1/6000, 1/12000 s: per-tet masses
    0.432, 0.418, 0.412, per-cell 0.419, 0.412, 0.409 (both first order in dt, extrapolated limit 0.405; the
    lattice 0.397 and 0.396 at its default 1/7500 s and half of it).  What remains at 1/3000 s is
    that dt error (+3.5 %) and the coarse section (2 x 2 cells, +2.3 %): with 4 x 4 x 4 cells per
    segment ratio 5 gives 0.407 and 0.402 at 1/6000 and 1/12000 s with per-tet masses, 0.410 and
    0.403 per cell, both extrapolated to 0.396, the lattice's speed (a finer mesh costs 8 x the tets and a
    smaller step: not the default).
    Not the section's roll: the fem's sections roll less than the lattice's (roll_max_deg at ratio
    5: 0.49 against 1.24, at ratio 10: 0.72 against 1.66): computed from the parameters, the fem
    section's shear stiffness G L w / h = 2.0 kN/m per segment is ~10 x that of the lattice's two
    cross-section diagonals (k_s = k fps^2 m_node = 0.21 kN/m).  Poisson's ratio moves it a little,
    with the roll: ratio 5 gives 0.409, 0.419, 0.420 at nu = 0.1, 0.3 (models/snake.toml), 0.45 (roll
    0.11, 0.49, 0.75 degrees); nothing in the lattice fixes nu, so it stays.
"""
from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.metrics.body_shape import ground_curvature
from bench_myriapoda.metrics.locomotion import measurement_window
from bench_myriapoda.reference.slithering import steady_slithering

pytestmark = pytest.mark.slow

BODIES = ("massspring", "fem", "hybrid")
RATIOS = (1.5, 2.0, 3.0, 5.0, 10.0)
COMMAND = 7.0
CURVATURE_REL_TOL = 0.10
SPEED_REL_TOL = 0.15
ISOTROPIC_MAX_BL_PER_CYCLE = 0.03
BODIES_REL_SPREAD = 0.10
MU_B_OVER_MU_F = 1.5
SETTINGS = ("creature.segments=20", "creature.mass_kg=0.4", "gait.wavelength_bl=1.0",
            f"gait.curvature_amplitude={COMMAND}", "gait.frequency_hz=0.25", "gait.ramp_s=2.0",
            "metrics.warmup_cycles=1", "friction.froude=0.1", "friction.mu_forward=1",
            f"friction.mu_backward={MU_B_OVER_MU_F}",
            # issue 27: this file measures the open-loop calibrated gain (bodies/curvature_calibration.py) at a load
            # it reaches the shape under, with the figures above; the closed loop is tests/test_shape_tracking.py's
            "gait.shape_control=open_loop")
DURATION_S = 12.0  # 3 periods: ramp within the first, warm-up, two measured


@functools.lru_cache(maxsize=None)
def slither(body: str, ratio: float):
    case = resolve_case("snake", body, "flat", "lateral-undulation", duration=DURATION_S,
                        overrides=list(SETTINGS) + [f"friction.mu_transverse={ratio}"])
    r = run_case(case)
    assert r.status == "ok", r.message
    return case, r


def measured_curvature(case, r) -> float:
    """Peak curvature x body length over the steady window (metrics.body_shape's estimate; the
    hybrid through its rigid boxes only)."""
    s = r.series
    centers = s.segment_centers[:, ::2] if case.body.name == "hybrid" else s.segment_centers
    i0, i1 = measurement_window(s, case.gait.period_s, case.metrics.warmup_cycles)
    kappa, _ = ground_curvature(centers[i0:i1 + 1])
    amp = math.sqrt(2.0) * np.sqrt((kappa ** 2).mean(axis=0))
    return float(np.median(amp) * r.metrics["body_length_m"])


@pytest.mark.parametrize("body", BODIES)
def test_commanded_curvature_is_the_measured_curvature_on_every_body(body):
    case, r = slither(body, 3.0)
    got = measured_curvature(case, r)
    assert got == pytest.approx(COMMAND, rel=CURVATURE_REL_TOL), (body, got)


@pytest.mark.parametrize("body", BODIES)
def test_isotropic_friction_gives_almost_no_progress_on_every_body(body):
    _, r = slither(body, 1.0)
    assert abs(r.metrics["speed_bl_per_cycle"]) < ISOTROPIC_MAX_BL_PER_CYCLE, (body, r.metrics)


def width_reference(case, r, ratio: float) -> float:
    """The kinematic reference [BL/cycle] of a belly as wide as the body's (module doc)."""
    width_bl = case.creature.width_m / r.metrics["body_length_m"]
    return steady_slithering(COMMAND, 1.0, 1.0, MU_B_OVER_MU_F, ratio, width_bl=width_bl).speed_bl_per_cycle


def assert_speed_near_the_width_reference(body, ratio, rel):
    """The body's slithering speed within ``rel`` of the kinematic reference of its own width."""
    case, r = slither(body, ratio)
    ref = width_reference(case, r, ratio)
    assert r.metrics["speed_bl_per_cycle"] == pytest.approx(ref, rel=rel), (body, ratio, ref)


@pytest.mark.parametrize("body", BODIES)
@pytest.mark.parametrize("ratio", RATIOS)
def test_speed_matches_the_kinematic_reference(body, ratio):
    assert_speed_near_the_width_reference(body, ratio, SPEED_REL_TOL)


@pytest.mark.parametrize("ratio", RATIOS)
def test_the_three_bodies_agree(ratio):
    speeds = [slither(body, ratio)[1].metrics["speed_bl_per_cycle"] for body in BODIES]
    assert max(speeds) - min(speeds) <= BODIES_REL_SPREAD * np.mean(speeds), speeds


# The lattice's belly is its bottom nodes at the two bottom edges, the hybrid's mostly its boxes' bottom
# corners there: the reference of the body's own width is their kinematic model, and they keep closer to it.
EDGE_BELLIES = ("massspring", "hybrid")
WIDTH_REL_TOL = 0.10  # measured: lattice within 4 %, hybrid within 7 % at every ratio


@pytest.mark.parametrize("body", EDGE_BELLIES)
@pytest.mark.parametrize("ratio", RATIOS)
def test_speed_matches_the_kinematic_reference_of_the_bodys_own_width(body, ratio):
    assert_speed_near_the_width_reference(body, ratio, WIDTH_REL_TOL)
