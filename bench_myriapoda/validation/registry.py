"""The explicit table of validation checks (like ``catalog.py``: one entry per check, no import side effects).

Each entry names the check, its family (the module its measure function lives in), the quantity,
the reference's source and its measure function; ``cross=True``: one row comparing all bodies (only
in the full set).  Which body models a check runs on, and whether ``validate --quick`` does, is
declared by each body backend (``BodySpec.checks``, ``bodies/<name>/body.py``): this table names
no body.
"""
from __future__ import annotations

from . import analytic as A
from . import cross_body as X
from . import miller as M
from . import paper as P
from . import shortcut as SC
from . import throughput as T
from .core import Check

CHECKS: tuple[Check, ...] = (
    # ---- analytic (shared/reference/VALIDATION.md, "Analytic")
    Check("analytic.worm-eps-lambda", "analytic", "worm displacement per cycle [m]",
          "D = eps * Lambda (perfect anchoring; VALIDATION.md)", A.worm_eps_lambda),
    Check("analytic.hanging-bar", "analytic", "bottom displacement of a hanging bar [m]",
          "rho g L^2 / (2 E), linear elasticity", A.hanging_bar),
    Check("analytic.cantilever", "analytic", "cantilever tip deflection / beam theory",
          "P L^3 / (3 E I) + P L / (kappa G A) (Timoshenko)", A.cantilever),
    Check("analytic.rigid-rotation", "analytic", "elastic force under a rigid rotation (relative)",
          "0 (fixed corotational elasticity; springs)", A.rigid_rotation),
    Check("analytic.free-fall-momentum", "analytic", "linear momentum in free flight (relative error)",
          "P(t) = P0 + M g t (internal forces cancel)", A.free_fall_momentum),
    Check("analytic.stable-dt", "analytic", "largest stable dt of the undamped lattice [s]",
          "2 / omega_max (symplectic Euler)", A.stable_dt),
    Check("analytic.damping-pure-mode", "analytic", "per-step factor of a pure damping mode (relative error)",
          "1 / (1 + lambda h) (implicit damping, App. A eqs. 13-14)", A.damping_pure_mode),
    Check("analytic.damping-oscillating-mode", "analytic", "per-step amplitude factor of an underdamped mode",
          "1 / sqrt(1 + c h) (eigenvalues of the linearized step)", A.damping_oscillating_mode),
    Check("analytic.slithering", "analytic", "snake forward speed over mu_t/mu_f [BL/cycle]",
          "Hu et al. 2009 kinematic model at the commanded shape", M.slithering),
    Check("analytic.slithering-measured-shape", "analytic", "snake forward speed over mu_t/mu_f [BL/cycle] (INFO)",
          "Hu et al. 2009 kinematic model at the body's measured shape", M.slithering_measured_shape),
    # ---- Miller 1988, image by image
    Check("miller.image1-worm-book", "miller", "worm on the book: impact, contact, bending over, sliding off",
          "Miller 1988 Images 1a-1d", M.image_run("worm-book")),
    Check("miller.image2-snake-coils", "miller", "snake: head fixed while coils form, segments on one path",
          "Miller 1988 Images 2a-2d", M.image_run("snake-undulation")),
    Check("miller.image3-sidewinder", "miller", "sidewinder: localised contact, diagonal travel, no roll, reversal",
          "Miller 1988 Images 3a-3d; Astley et al. 2015", M.image_run("sidewinder", True)),
    Check("miller.image4-caterpillar-arch", "miller", "caterpillar arches its back",
          "Miller 1988 Image 4b", M.image_run("caterpillar-arch")),
    Check("miller.image4-caterpillar-up", "miller", "caterpillar climbs a 45 degree slope",
          "Miller 1988 Image 4, Sec. 4 (steep gradients, up)", M.image_run("caterpillar-up")),
    Check("miller.image4-caterpillar-down", "miller", "caterpillar descends a 45 degree slope",
          "Miller 1988 Image 4, Sec. 4 (steep gradients, down)", M.image_run("caterpillar-down")),
    # ---- the myriapod paper
    Check("paper.fig4-drop", "paper", "link strain on impact and at rest",
          "Fang et al. 2013 Fig. 4", P.fig4_drop),
    Check("paper.fig10a-hang", "paper", "leg state cycle and elongation when hanging",
          "Fang et al. 2013 Fig. 10 A, Sec. 3, 4.2", P.fig10a_hang),
    Check("paper.fig10d-walk", "paper", "share of legs in SF1 -> SF2 -> STANCE (10 s walk)",
          "Fang et al. 2013 Fig. 10 D, Sec. 4.2", P.fig10d_walk),
    Check("paper.wave-centipede", "paper", "centipede leg wave direction",
          "Kuroda et al. 2014; Fang et al. 2013 Sec. 4", P.centipede_wave),
    Check("paper.wave-millipede", "paper", "millipede leg wave direction",
          "Kuroda et al. 2014; Fang et al. 2013 Sec. 4", P.millipede_wave),
    Check("paper.control-turn", "paper", "CONTROL: turn of the head's path [deg]",
          "Fang et al. 2013 Sec. 4.3 (commanded 40 deg)", P.control_turn),
    Check("paper.foraging", "paper", "TROPHOTROPISM: time to reach food [s]",
          "Fang et al. 2013 Sec. 4.3, 6.2", P.foraging),
    Check("paper.avoidance", "paper", "AVOIDANCE: body penetration into cylinders [m]",
          "Fang et al. 2013 Sec. 4.3, 6.2", P.avoidance),
    Check("paper.kinematic-shortcut-centipede", "paper",
          "head path deviation of the kinematic from the dynamic stance [BL] (INFO)",
          "the same walk in dynamic stance (issue 43; Fang et al. 2013 Sec. 3's shortcut)", SC.centipede_shortcut),
    Check("paper.kinematic-shortcut-millipede", "paper",
          "head path deviation of the kinematic from the dynamic stance [BL] (INFO)",
          "the same walk in dynamic stance (issue 43; Fang et al. 2013 Sec. 3's shortcut)", SC.millipede_shortcut),
    Check("paper.kinematic-shortcut-worlds", "paper",
          "largest head path deviation of the kinematic from the dynamic stance over every myriapod scenario [BL] "
          "(INFO)", "the same walks in dynamic stance (issue 43; Fang et al. 2013 Sec. 3's shortcut)",
          SC.worlds_shortcut),
    # ---- throughput
    Check("throughput.sec6-headline", "throughput", "steps/s, 18-segment centipede, dt = 1/3000 s",
          "Fang et al. 2013 Sec. 6: 1.7e4 steps/s on 6 cores", T.sec6_headline),
    # ---- cross-body agreement
    Check("cross_body.worm-speed", "cross_body", "worm speed spread over bodies",
          "eps * Lambda * f holds on every body", X.worm_speed, cross=True),
    Check("cross_body.centipede-speed", "cross_body", "centipede speed spread over bodies",
          "the leg controller sets the speed", X.centipede_speed, cross=True),
    Check("cross_body.centipede-phase-lag", "cross_body", "centipede phase lag spread over bodies [cycles]",
          "the leg controller sets the lag", X.centipede_phase_lag, cross=True),
    Check("cross_body.hang-elongation", "cross_body", "hanging elongation fem / hybrid (expected difference)",
          "each body's hanging bar (rho g L^2 / 2E over its own pieces and masses)", X.hang_elongation_difference, cross=True),
)

BY_NAME: dict[str, Check] = {c.name: c for c in CHECKS}
