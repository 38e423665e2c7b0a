"""Typed, validated configuration: the resolved description of one case.

Each section of a case is a frozen dataclass.  Field metadata states the
allowed range (``ge``, ``gt``, ``le``, ``lt``) or the allowed values
(``choices``); :func:`check_section` enforces them with messages that name the
source and the dotted key.  Units are in the field names (``_m``, ``_s``,
``_hz``, ``_deg``) or stated in the comments; everything is SI.

Body-model sections are registered by each backend (see
``bench_myriapoda.core.registry``) because their keys differ per backend.
"""
from __future__ import annotations

import dataclasses
import re
import math
import typing
from dataclasses import dataclass, field
from typing import Any, Mapping

from .errors import InputError
from .suggest import did_you_mean


def rng(default, *, ge=None, gt=None, le=None, lt=None, choices=None, doc="", length=None, multiple=None,
        ordered=False, check=None):
    """A dataclass field with range metadata.

    For a list of numbers, ge/gt/le/lt bound every element; ``length`` is its
    exact length, ``multiple`` a number its length must be a multiple of,
    ``ordered`` asks for non-decreasing elements (a [lo, hi] pair), and
    ``check(value)`` returns an error message or None for anything else.
    """
    return field(default=default, metadata=dict(ge=ge, gt=gt, le=le, lt=lt, choices=choices, doc=doc, length=length,
                                                multiple=multiple, ordered=ordered, check=check))


# Every Gaussian bump and every obstacle is a term of every terrain query (world/terrain_kernels.py): at
# 2,000 of each a scene still sets up in seconds; 100,000 took minutes to set up and would crawl when run.
MAX_TERRAIN_TERMS = 2000


def _check_box_list(v) -> str | None:
    for i in range(0, len(v), 7):
        if min(v[i + 3: i + 6]) <= 0:
            return f"box {i // 7}: half extents (elements 4-6 of each group of 7) must be > 0"
    return None


def _check_cylinder_list(v) -> str | None:
    for i in range(0, len(v), 4):
        if v[i + 2] <= 0 or v[i + 3] <= 0:
            return f"cylinder {i // 4}: radius and height (elements 3 and 4 of each group of 4) must be > 0"
    return None


def _check_increasing(v) -> str | None:
    """A schedule's times: each later than the one before (equal or earlier times would make one command
    silently replace another)."""
    for i in range(1, len(v)):
        if not v[i] > v[i - 1]:
            return f"{list(v)!r}: expected strictly increasing times; element {i} ({v[i]!r}) is not after {v[i - 1]!r}"
    return None


def _check_region(v) -> str | None:
    if not (v[0] < v[1] and v[2] < v[3]):
        return "expected [x_min, x_max, z_min, z_max] with x_min < x_max and z_min < z_max"
    return None


def _check_mesh(v) -> str | None:
    """'skull' or a readable, closed mesh file (loaded once to check it)."""
    if v == "skull":
        return None
    from .mesh_files import MeshError, load_closed_mesh

    try:
        load_closed_mesh(v)
    except MeshError as exc:
        return f"expected 'skull' or a closed mesh file trimesh loads: {exc}"
    return None


@dataclass(frozen=True)
class CreatureConfig:
    """Morphology of a segmented creature; segment 0 is the head."""

    name: str = rng("", doc="creature name")
    description: str = rng("", doc="one line shown by `list`")
    segments: int = rng(10, ge=1, le=1000, doc="number of body segments")
    segment_length_m: float = rng(0.05, gt=0.0, doc="rest length of one segment along the body [m]")
    width_m: float = rng(0.05, gt=0.0, doc="segment width (side to side) [m]")
    height_m: float = rng(0.05, gt=0.0, doc="segment height (belly to back) [m]")
    mass_kg: float = rng(1.0, gt=0.0, doc="total body mass [kg]")
    legs_per_segment: int = rng(0, choices=(0, 2), doc="0 (legless) or 2 (a left/right pair per rigid segment)")
    default_gait: str = rng("", doc="gait used when --gait is not given")
    gaits: tuple = rng((), doc="gaits this creature supports")

    @property
    def body_length_m(self) -> float:
        return self.segments * self.segment_length_m


@dataclass(frozen=True)
class GaitConfig:
    """The keys every gait has: its name, its wave and period, and the volume rule.

    The runner and the metrics read the wave of every gait (``harness.runner.wave_speed``, the gait
    period that sets the metrics' cycles); the bodies read the volume rule.  For a muscle wave (Miller
    Sec. 4) the wave on a channel is ``amplitude * sin(d * 2 pi s / wavelength - 2 pi f t + phase)``
    with s the rest arc length of a segment centre from the head and d = +1 for a wave travelling head
    to tail, -1 tail to head; amplitudes are strains of the muscle fibres (dimensionless).  A gait's
    own keys live in its own subclass next to its controller (``core.specs.GaitSpec.config_cls``): the
    muscle waves' commanded shape, sidewinding's vertical wave, arching's axial wave and the shape
    control are ``controllers.muscle_waves.MuscleWaveConfig``'s.
    """

    name: str = rng("", doc="gait (controller) name")
    amplitude: float = rng(0.2, ge=0.0, lt=0.95, doc="main channel strain amplitude")
    wavelength_bl: float = rng(0.5, gt=0.0, doc="wavelength in body lengths (undeformed)")
    frequency_hz: float = rng(1.0, gt=0.0, doc="wave frequency [Hz]")
    phase_deg: float = rng(0.0, doc="phase offset of the main wave [deg]")
    direction: str = rng("head-to-tail", choices=("head-to-tail", "tail-to-head"),
                         doc="way the wave travels along the body (Miller's worm: head to tail)")
    volume_conserving: bool = rng(False, doc="scale circumferential rest lengths by 1/sqrt(axial stretch) (Miller Sec. 4)")
    ramp_s: float = rng(0.5, ge=0.0, doc="amplitude ramps linearly from 0 over this time [s]")

    @property
    def period_s(self) -> float:
        return 1.0 / self.frequency_hz

    def commands_curvature(self) -> bool:
        """Whether this gait commands a body shape (a curvature) that each body turns into its own strain with
        its measured gain (``harness.calibration``).  A gait's own configuration class says so (the muscle
        waves': ``controllers.muscle_waves.MuscleWaveConfig``); this base class: never.  A class that says so also
        has ``curvature_amplitude``, the commanded lateral peak curvature x body length [-], which the shape
        metrics (``metrics.shape_tracking``) compare the body's shape with."""
        return False


def _minus_one_or_non_negative(v) -> str | None:
    return None if v == -1.0 or v >= 0.0 else "expected -1 (derived) or a value >= 0"


def _minus_one_or_positive(v) -> str | None:
    return None if v == -1.0 or v > 0.0 else "expected -1 (unbounded) or a value > 0"


@dataclass(frozen=True)
class LegsConfig:
    """Kinematic legs of a myriapod (paper Sec. 3, 4.2, Fig. 9): massless, one pair per rigid segment.

    A leg is a femur OM and a tibia MP with a fixed knee bend gamma; its root O
    sits at (root_x, root_y, +-root_z) in the segment frame (x forward, y up, z right).
    """

    femur_m: float = rng(1.0, gt=0.0, doc="|OM| [m]")
    tibia_m: float = rng(1.2, gt=0.0, doc="|MP| [m]")
    gamma_deg: float = rng(28.6479, ge=0.0, lt=180.0, doc="fixed knee bend gamma [deg]")
    root_x_m: float = rng(0.0, doc="root position along the segment [m]")
    root_y_m: float = rng(0.0, doc="root height in the segment frame [m]")
    root_z_m: float = rng(0.5, gt=0.0, doc="root distance from the midline [m]")
    contact_distance_m: float = rng(0.01, ge=0.0, doc="a tip this close to the surface touches it [m]")
    collide: bool = rng(True, doc="a swinging leg's tip or knee stops at the terrain and obstacle surfaces, a "
                                  "STANCE leg whose knee enters one lifts (issue 16); false: the paper's legs, "
                                  "which pass through obstacles")
    # the dynamic stance (issue 43, docs/explanation/dynamic-stance.md)
    stance: str = rng("kinematic", choices=("kinematic", "dynamic"),
                      doc="'kinematic': supported segments carried to their targets (the paper, Sec. 3); 'dynamic': "
                          "STANCE legs push their segments through friction-limited feet (every legged body; fem: on its "
                          "blocks' leg-attachment nodes)")
    stance_frequency_hz: float = rng(10.0, gt=0.0, le=1.0e6,
                                     doc="dynamic stance: natural frequency of a segment on its legs' spring-damper "
                                         "toward the Targeter's pose [Hz] (stiffness m (2 pi f)^2)")
    stance_damping_ratio: float = rng(1.0, ge=0.0, le=1.0e3,
                                      doc="dynamic stance: damping ratio of that spring-damper [-] (1: critical)")
    foot_mu: float = rng(-1.0, ge=-1.0, check=_minus_one_or_non_negative, doc="dynamic stance: Coulomb coefficient of a STANCE foot on the ground [-]; "
                                            "-1: friction.mu_transverse (no sliding for the 'stick' model)")
    max_leg_force_n: float = rng(-1.0, ge=-1.0, check=_minus_one_or_positive, doc="dynamic stance: largest force of one leg [N]; -1: unbounded")


@dataclass(frozen=True)
class ControllerConfig:
    """The decentralized leg controller (paper Sec. 4): Switcher poses, Targeter gains, head."""

    wave_direction: str = rng("retrograde", choices=("retrograde", "direct"),
                              doc="previous leg: anterior (retrograde, centipedes) or posterior (direct, millipedes)")
    theta_aep_deg: float = rng(28.6479, ge=-180.0, le=180.0, doc="theta_M of the anterior extreme pose [deg]")
    theta_pep_deg: float = rng(-28.6479, ge=-180.0, le=180.0, doc="theta_m of the posterior extreme pose [deg]")
    alpha_s_deg: float = rng(17.1887, ge=-180.0, le=180.0, doc="alpha_S of AEP and PEP [deg]")
    beta_s_deg: float = rng(74.4845, ge=-180.0, le=180.0, doc="beta_S of AEP and PEP [deg]")
    alpha_mup_deg: float = rng(34.3775, ge=-180.0, le=180.0, doc="alpha_M of the middle up pose [deg]")
    alpha_mdp_deg: float = rng(-22.9183, ge=-180.0, le=180.0, doc="alpha_m of the middle down pose [deg]")
    adjust_d_theta_deg: float = rng(-17.1887, ge=-180.0, le=180.0, doc="theta_T - theta_M of the ADJUST target [deg]")
    adjust_d_alpha_deg: float = rng(17.1887, ge=-180.0, le=180.0, doc="alpha_T - alpha_S [deg]")
    adjust_d_beta_deg: float = rng(-45.8366, ge=-180.0, le=180.0, doc="beta_T - beta_S [deg]")
    swing_speed_rad_s: float = rng(4.0, gt=0.0, doc="angular speed of a leg outside STANCE [rad/s]")
    adjust_from_stance: bool = rng(True, doc="rule 4 also pulls a leg out of STANCE into ADJUST ('whenever'); "
                                             "false: only swinging legs adjust")
    k1: float = rng(20.0, ge=0.0, doc="Follower gain (footnote 2) [1/(m s)]")
    follower_feedforward: str = rng("auto", choices=("auto", "on", "off"),
                                    doc="the Follower also moves a segment at the head's commanded speed along its "
                                        "link (beyond the paper; docs/explanation/dynamic-stance.md): 'auto': on in "
                                        "legs.stance = 'dynamic', off in the paper's kinematic stance; 'on'; 'off': "
                                        "the paper's Follower, which follows by stretching the link")
    k2: float = rng(10.0, ge=0.0, doc="Balancer gain (footnote 2) [1/s]")
    omega_follow_deg_s: float = rng(114.59, ge=0.0, doc="Follower turn rate [deg/s]")
    omega_balance_deg_s: float = rng(114.59, ge=0.0, doc="Balancer turn rate [deg/s]")
    target_height_m: float = rng(-1.0, doc="segment centre height the Balancer keeps; -1: the standing height of the legs")
    min_stance_legs: int = rng(1, ge=1, le=2, doc="legs in STANCE that make a segment supported")
    head_speed_m_s: float = rng(0.5, ge=0.0, doc="head speed when walking [m/s]")
    random_turn_max_deg: float = rng(30.0, ge=0.0, le=360.0, doc="RANDOM-WALK: largest random target turn [deg]")
    random_turn_rate_deg_s: float = rng(10.0, ge=0.0, doc="RANDOM-WALK: turn rate toward the target [deg/s]")
    adjustment_majority: float = rng(0.5, gt=0.0, le=1.0,
                                     doc="ADJUSTMENT ends when more than this fraction of legs touch the ground")
    avoid_turn_rate_deg_s: float = rng(25.0, ge=0.0,
                                       doc="AVOIDANCE: turn rate away from the touching antenna [deg/s]")
    avoid_hold_s: float = rng(0.5, ge=0.0,
                              doc="AVOIDANCE: keeps turning this long after the last antenna contact [s]")
    avoid_speed_factor: float = rng(1.0, ge=0.0, le=1.0,
                                    doc="AVOIDANCE: head speed as a fraction of head_speed_m_s")
    avoid_priority: str = rng("left", choices=("left", "right"),
                              doc="AVOIDANCE: the antenna that wins when both touch (left: the head turns right)")
    max_body_turn_deg: float = rng(90.0, gt=0.0, le=360.0,
                                   doc="AVOIDANCE and TROPHOTROPISM: the head's turning summed over about the last "
                                       "body length of its path (weighted by exp(-distance / body length)) stays "
                                       "within +-this; past it the head goes straight on [deg]")
    forage_turn_rate_deg_s: float = rng(15.0, ge=0.0,
                                        doc="TROPHOTROPISM: largest turn rate toward the stronger food signal [deg/s]")
    forage_gain: float = rng(4.0, gt=0.0, doc="TROPHOTROPISM: turn rate = forage_turn_rate * min(1, gain * "
                                              "|S_left - S_right| / (S_left + S_right))")
    body_wave_amplitude: float = rng(0.0, ge=0.0, le=1.0,
                                     doc="lateral body wave (beyond the paper, Scolopendra): amplitude of the yaw "
                                         "offset of the supported segments' targets [rad]; 0: no wave")
    body_wave_phase_rad: float = rng(2.5, doc="body wave: phase offset from the leg wave of the head's legs [rad]")
    body_wave_number: float = rng(1.6, ge=0.0, doc="body wave: waves along the body (Scolopendra: about 1.6)")


@dataclass(frozen=True)
class FrictionConfig:
    """Ground friction.

    * ``miller``  -- Miller's rule (Sec. 4): within ``contact_distance_m`` of the
      ground, the backward component of a mass's velocity along the local spine
      vector is removed.  Forward and sideways sliding are resisted only by Coulomb friction
      of coefficient ``miller_mu_slide`` (0: free, Miller's rule alone): a physical coefficient
      whose effect does not depend on the time step, unlike a per-step ``collision.r_t``.
    * ``coulomb`` -- anisotropic Coulomb friction with forward, backward and
      transverse coefficients, static and kinetic (after Hu et al., PNAS 2009).
      A static coefficient of -1 means "same as kinetic".
    * ``stick``   -- Miller's caterpillar: masses in contact get no tangential motion.

    ``froude`` > 0 sets the coefficients from the Froude number of the slithering literature
    (Hu et al. 2009), Fr = L / (T^2 g mu_f): mu_f = L / (T^2 g Fr) with L the creature's body
    length, T the gait period and g the scenario's gravity.  The other coefficients (backward,
    transverse and any static ones given) keep their ratios to mu_forward as written, so a
    file states the anisotropy and Fr its overall level.  ``core.config.apply_froude`` does this
    when the case is resolved, so every body model sees the same coefficients.
    """

    model: str = rng("coulomb", choices=("miller", "coulomb", "stick"),
                     doc="'miller': no backward sliding along the spine; 'coulomb': anisotropic Coulomb; "
                         "'stick': no tangential motion in contact")
    contact_distance_m: float = rng(0.002, ge=0.0, doc="a mass this close to the surface is in contact [m]")
    mu_forward: float = rng(0.1, ge=0.0, doc="coulomb: kinetic coefficient for sliding head-first along the spine")
    mu_backward: float = rng(0.3, ge=0.0, doc="coulomb: kinetic coefficient for sliding tail-first along the spine")
    mu_transverse: float = rng(0.5, ge=0.0, doc="coulomb: kinetic coefficient for sliding sideways (across the spine)")
    mu_static_forward: float = rng(-1.0, ge=-1.0, doc="coulomb: static coefficient head-first; -1: same as mu_forward")
    mu_static_backward: float = rng(-1.0, ge=-1.0, doc="coulomb: static coefficient tail-first; -1: same as mu_backward")
    mu_static_transverse: float = rng(-1.0, ge=-1.0,
                                      doc="coulomb: static coefficient sideways; -1: same as mu_transverse")
    miller_mu_slide: float = rng(0.0, ge=0.0, doc="miller model: Coulomb coefficient against the sliding Miller's "
                                                  "rule leaves free (forward and sideways); 0 = free")
    froude: float = rng(0.0, ge=0.0, doc="Froude number L / (T^2 g mu_f); > 0 sets mu_f from it, keeping the "
                                          "other coefficients' ratios to mu_f (0: coefficients as given)")


@dataclass(frozen=True)
class CollisionConfig:
    """Miller Sec. 3 reflection coefficients for a point crossing a surface."""

    r_n: float = rng(0.0, ge=0.0, le=1.0, doc="normal reflection coefficient (0 = inelastic)")
    r_t: float = rng(1.0, ge=0.0, le=1.0, doc="fraction of the tangential travel kept after impact (1 = frictionless)")


@dataclass(frozen=True)
class ScenarioConfig:
    """Where the creature starts and what it stands on."""

    name: str = rng("", doc="scenario name (default: the file name)")
    description: str = rng("", doc="one line shown by `list`")
    terrain: str = rng("plane", choices=("plane", "slope", "slab", "heightfield", "mesh", "none"),
                       doc="'none': no ground at all; 'heightfield': Gaussian mixture (Sec. 6.2); 'mesh': a closed "
                           "triangle mesh (Fig. 1)")
    ground_height_m: float = rng(0.0, doc="height of the ground plane and of a heightfield's base; still water's depth is measured from it [m]")
    slope_deg: float = rng(0.0, ge=-80.0, le=80.0, doc="slope: incline rising toward +x [deg]")
    slab_height_m: float = rng(0.3, gt=0.0, doc="slab: height of Miller's book [m]")
    slab_edge_x_m: float = rng(0.0, doc="slab: x of the book's edge (slab at x <= edge) [m]")
    slab_edge_radius_m: float = rng(0.02, gt=0.0, doc="slab: radius of the rounded edge [m]")
    terrain_seed: int = rng(0, ge=0, doc="seed of the random height field and random obstacles (not the case seed)")
    heightfield_count: int = rng(20, ge=0, le=MAX_TERRAIN_TERMS,
                                doc="heightfield: number of Gaussians (each is a term of every terrain query)")
    heightfield_amplitude_m: list = rng((0.0, 0.5), length=2, ordered=True,
                                        doc="heightfield: [lo, hi] of the uniform Gaussian amplitudes "
                                            "(negative: pits) [m]")
    heightfield_width_m: list = rng((1.0, 3.0), gt=0.0, length=2, ordered=True,
                                    doc="heightfield: [lo, hi] of the uniform Gaussian widths s (std) [m]")
    heightfield_extent_m: float = rng(20.0, gt=0.0, doc="heightfield: Gaussian centres uniform in |x|, |z| <= this [m]")
    mesh: str = rng("skull", check=_check_mesh,
                    doc="mesh: 'skull' (procedural closed skull shipped with the project) or a path (relative to "
                        "the working directory) to a closed (watertight) mesh file trimesh loads")
    mesh_subdivisions: int = rng(92, ge=1, le=400,
                                 doc="mesh 'skull': cells per cube edge; 12 n^2 triangles (92: 101,568)")
    mesh_scale: float = rng(1.0, gt=0.0, doc="mesh: vertices scaled by this (the skull is about 2 m long at 1)")
    mesh_translate_m: list = rng((0.0, 0.0, 0.0), length=3, doc="mesh: [x, y, z] added after scaling [m]")
    mesh_ground: bool = rng(False, doc="mesh: also a ground plane at ground_height_m")
    mesh_cell_edges: float = rng(1.4, ge=0.5, le=8.0,
                                 doc="mesh: spatial-hash cell size in mean edge lengths; smaller cells make "
                                     "queries a few cells off the surface cheaper but take longer to build "
                                     "(see world/meshes.py)")
    mesh_band_m: float = rng(0.0, ge=0.0, doc="mesh: signed distances within this band (exact within a quarter "
                                              "hash cell of the surface, interpolated from exact samples beyond), "
                                              "+-band farther [m]; 0: a tenth of the mesh's bounding-box diagonal")
    obstacle_cylinders: int = rng(0, ge=0, le=MAX_TERRAIN_TERMS,
                                  doc="number of random vertical cylinders (Fig. 13; each is a term of every "
                                      "terrain query)")
    obstacle_radius_m: list = rng((0.2, 0.5), gt=0.0, length=2, ordered=True,
                                  doc="random cylinders: [lo, hi] of the uniform radii [m]")
    obstacle_height_m: list = rng((0.1, 0.4), gt=0.0, length=2, ordered=True,
                                  doc="random cylinders: [lo, hi] of the uniform heights above the surface [m]")
    obstacle_region_m: list = rng((-10.0, 10.0, -10.0, 10.0), length=4, check=_check_region,
                                  doc="random cylinders: centres uniform in [x_min, x_max, z_min, z_max] [m]")
    obstacle_clear_radius_m: float = rng(2.0, ge=0.0,
                                         doc="random cylinders keep clear of the disc of this radius about the "
                                             "origin (the start area) [m]")
    obstacle_cylinder_list: list = rng((), multiple=4, check=_check_cylinder_list,
                                       doc="explicit cylinders: groups of 4 numbers x, z, radius, height above the "
                                           "surface [m]")
    obstacle_box_list: list = rng((), multiple=7, check=_check_box_list,
                                  doc="explicit boxes: groups of 7 numbers x, y, z, half_x, half_y, half_z [m], "
                                      "yaw [deg]; y: centre height above the surface at (x, z)")
    start_height_m: float = rng(0.0, ge=0.0, doc="clearance of the body's underside above the surface at t=0 [m]")
    start_x_m: float = rng(0.0, doc="x of the head at t=0 (creatures face +x) [m]")
    perturbation_m: float = rng(0.0, ge=0.0, doc="random displacement (std) of every node at t=0, seeded by seed [m]")
    gravity_m_s2: float = rng(9.81, ge=0.0, le=300.0,  # the Sun's surface: 274; Jupiter's 24.8
                             doc="gravitational acceleration, pointing down (-y) [m/s^2]; 0 to 300 (the Sun's "
                                 "surface has 274)")
    passive: bool = rng(False, doc="muscles off (for energy checks)")
    suspended: bool = rng(False, doc="the head is held fixed and the body hangs straight down from it (paper Fig. 10)")
    duration_s: float = rng(10.0, gt=0.0, doc="default duration of the case [s]")
    brain: str = rng("random-walk", choices=("random-walk", "control"),
                     doc="myriapod head after ADJUSTMENT: RANDOM-WALK, or CONTROL by the schedule below (Sec. 4.3)")
    control_times_s: list = rng((0.0,), check=_check_increasing,
                                doc="CONTROL: times [s] at which the commands below take effect (increasing)")
    control_speed_m_s: list = rng((0.5,), doc="CONTROL: head speed from each time on [m/s]")
    control_turn_rate_deg_s: list = rng((0.0,), doc="CONTROL: turn rate from each time on [deg/s], + = left")
    # shallow water over the terrain (Sec. 6.2, Kass and Miller 1990): world/water.py, world/water_coupling.py
    water_depth_m: float = rng(0.0, ge=0.0, le=100.0, doc="shallow water: still depth over ground_height_m [m]; "
                                                           "0: no water")
    water_region_m: list = rng((-5.0, 5.0, -5.0, 5.0), length=4, check=_check_region,
                               doc="shallow water: the grid's [x_min, x_max, z_min, z_max] [m] (walls at its edges)")
    water_cell_m: float = rng(0.05, gt=0.0, doc="shallow water: grid cell size [m]")
    water_damping_per_s: float = rng(0.1, ge=0.0, doc="shallow water: damping rate of the surface velocity [1/s]")
    water_courant: float = rng(0.5, gt=0.0, le=4.0,
                               doc="shallow water: largest Courant number sqrt(g d) dt / dx of its sub-steps "
                                   "(accuracy: 0.5 keeps the wave speed within 2 %)")
    water_point_radius_m: float = rng(0.05, gt=0.0, doc="shallow water: radius of a leg tip or body node as it "
                                                          "pushes water [m]")


def _check_food_list(v) -> str | None:
    for i in range(0, len(v), 4):
        if v[i + 3] <= 0:
            return f"food source {i // 4}: intensity (element 4 of each group of 4) must be > 0"
    return None


@dataclass(frozen=True)
class AntennaeConfig:
    """The two antennae of a myriapod's head (paper Sec. 5.2, Fig. 11).

    Each is a chain of ``n_links`` links with (theta, phi) joints relative to
    the previous link (theta: yaw, positive outward, away from the midline;
    phi: pitch, positive up); the root joint sits on the head at (root_x, root_y,
    -+root_z) in the head frame (x forward, y up, z right; the left antenna at -z).
    The root link turns at ``omega0`` toward random targets drawn in the two
    ranges; links i >= 1 follow A sin(2 pi f t - lambda i) + B.
    """

    enabled: bool = rng(True, doc="false: no antennae (no obstacle contact, no food sensing)")
    n_links: int = rng(12, ge=1, le=100, doc="links per antenna")
    link_length_m: float = rng(0.3, gt=0.0, doc="length of one link [m]")
    root_x_m: float = rng(0.5, doc="root joint along the head (head frame x) [m]")
    root_y_m: float = rng(0.1, doc="root joint height in the head frame [m]")
    root_z_m: float = rng(0.3, ge=0.0, doc="root joint distance from the midline (left at -z, right at +z) [m]")
    root_theta_range_deg: list = rng((-10.0, 60.0), ge=-90.0, le=150.0, length=2, ordered=True,
                                     doc="[lo, hi] of the root link's random yaw targets, outward positive (below 0 "
                                         "the antenna sweeps in front of the head) [deg]")
    root_phi_range_deg: list = rng((-20.0, 15.0), ge=-80.0, le=80.0, length=2, ordered=True,
                                   doc="[lo, hi] of the root link's random pitch targets, up positive [deg]")
    omega0_deg_s: float = rng(90.0, gt=0.0, doc="omega0: root link's turn speed toward its target [deg/s]")
    wave_amplitude_theta_deg: float = rng(6.0, ge=0.0, le=90.0, doc="A_theta of the links' wave [deg]")
    wave_amplitude_phi_deg: float = rng(4.0, ge=0.0, le=90.0, doc="A_phi of the links' wave [deg]")
    wave_base_theta_deg: float = rng(0.0, ge=-90.0, le=90.0, doc="B_theta of the links' wave [deg]")
    wave_base_phi_deg: float = rng(0.0, ge=-90.0, le=90.0, doc="B_phi of the links' wave [deg]")
    wave_frequency_hz: float = rng(1.0, ge=0.0, doc="omega / (2 pi) of the links' wave [Hz]")
    wave_lambda_deg: float = rng(45.0, doc="lambda: phase lag per link of the wave (outward travelling) [deg]")
    contact_margin_m: float = rng(0.02, gt=0.0, doc="a retracted antenna is held this far outside the obstacle; "
                                                    "contact ends when it is more than twice this far [m]")
    retract_angle_deg: float = rng(30.0, gt=0.0, le=180.0,
                                   doc="on contact the root's target moves this far along the obstacle normal [deg]")
    retract_speed_deg_s: float = rng(180.0, gt=0.0, doc="root link's turn speed while retracting [deg/s]")
    retract_relax_s: float = rng(0.5, gt=0.0, doc="time constant with which the retracted links relax back to "
                                                  "their wave [s]")


@dataclass(frozen=True)
class FoodConfig:
    """Food: point sources whose signal at a point is sum intensity / d^2 (paper Sec. 5.2).

    Explicit ``sources`` plus ``count`` random ones (from ``seed``, not the case
    seed); a source within ``reach_radius_m`` of the head is eaten (removed).
    """

    sources: list = rng((), multiple=4, check=_check_food_list,
                        doc="explicit sources: groups of 4 numbers x, y, z [m], intensity; y: height above the "
                            "surface at (x, z)")
    count: int = rng(0, ge=0, le=100000, doc="number of random sources")
    region_m: list = rng((-10.0, 10.0, -10.0, 10.0), length=4, check=_check_region,
                         doc="random sources: uniform in [x_min, x_max, z_min, z_max] [m]")
    clear_radius_m: float = rng(3.0, ge=0.0, doc="random sources keep this far from the origin (the start) [m]")
    obstacle_clearance_m: float = rng(1.0, ge=0.0, doc="random sources keep this far from every obstacle [m]")
    seed: int = rng(0, ge=0, doc="seed of the random sources (not the case seed)")
    intensity: float = rng(1.0, gt=0.0, doc="intensity of a random source [signal m^2]")
    height_m: float = rng(0.0, doc="random sources: height above the surface [m]")
    threshold: float = rng(0.005, ge=0.0, doc="TROPHOTROPISM when an antenna tip's signal exceeds this")
    softening_m: float = rng(0.1, gt=0.0, doc="signal = intensity / max(d, softening)^2 [m]")
    reach_radius_m: float = rng(1.0, gt=0.0, doc="eaten when within this distance of the head centre in the head's "
                                                 "x-z plane (and within twice it along the head's y) [m]")


@dataclass(frozen=True)
class RecordConfig:
    sample_hz: float = rng(60.0, gt=0.0, ge=1.0e-6, doc="observation samples per simulated second (at least one "
                                                      "per 1e6 s)")


@dataclass(frozen=True)
class StabilityConfig:
    """Blow-up detection: a run exceeding these limits ends with status 'unstable'."""

    max_speed_m_s: float = rng(50.0, gt=0.0, doc="any mass faster than this is a blow-up [m/s]")
    max_penetration_m: float = rng(0.05, gt=0.0, doc="a mass deeper than this inside the terrain is a blow-up [m]")


@dataclass(frozen=True)
class MetricsConfig:
    warmup_cycles: float = rng(2.0, ge=0.0, doc="gait cycles skipped before locomotion metrics are measured")
    min_steady_cycles: float = rng(2.0, ge=0.0, doc="fewest steady gait cycles (after the amplitude ramp and the "
                                                   "warm-up) a locomotion metric is measured over; a shorter run "
                                                   "reports it as too short (NaN, reason in labels.too_short)")


SECTIONS: dict[str, type] = {
    "creature": CreatureConfig,
    "legs": LegsConfig,
    "controller": ControllerConfig,
    "antennae": AntennaeConfig,
    "food": FoodConfig,
    "gait": GaitConfig,
    "friction": FrictionConfig,
    "collision": CollisionConfig,
    "scenario": ScenarioConfig,
    "record": RecordConfig,
    "stability": StabilityConfig,
    "metrics": MetricsConfig,
}
MIN_DT = 1e-14  # [s]

TOP_LEVEL_SCALARS = {
    # below 1e-14 s a step is under the float64 spacing of the simulated time after a minute (1.4e-14 s at
    # t = 64 s): the clock would stop advancing, so such a dt is out of range, not a case of 1e298 steps
    "dt": ("float", dict(gt=0.0, le=10.0, check=lambda v: None if v >= MIN_DT else
                         f"{v!r} is out of range; must be >= {MIN_DT} s (below it the simulated clock stops advancing)",
                         doc="time step [s], at least 1e-14; default from the body model")),
    "duration": ("float", dict(gt=0.0, doc="simulated time [s]; default from the scenario")),
    "seed": ("int", dict(ge=0, doc="random seed")),
}


def _type_name(tp) -> str:
    return {float: "a number", int: "an integer", str: "a string", bool: "true or false", tuple: "a list of names",
            list: "a list of numbers"}.get(tp, str(tp))


MAX_INT = 2 ** 63 - 1  # integers reach numpy and numba kernels as int64
MAX_LIST_LENGTH = 100_000
MAX_STRING_LENGTH = 4096


def _short(value: Any, limit: int = 80) -> str:
    """``repr(value)`` cut to one short line: a message stays one line whatever the input."""
    r = repr(value).replace("\n", " ")
    return r if len(r) <= limit else r[: limit - 3] + "..."


def field_types(cls) -> dict[str, Any]:
    hints = typing.get_type_hints(cls)
    return {f.name: hints[f.name] for f in dataclasses.fields(cls)}


def coerce_value(value: Any, tp: Any, source: str, key: str) -> Any:
    """Check ``value`` against type ``tp``; ints are accepted for floats (not floats for ints), lists for tuples."""
    if tp is float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(source, key, f"expected {_type_name(tp)}, got {_short(value)}")
        try:
            value = float(value)
        except OverflowError:  # an integer beyond float range
            raise InputError(source, key, "expected a finite number, got an integer beyond float range") from None
        if value != value or value in (float("inf"), float("-inf")):
            raise InputError(source, key, f"expected a finite number, got {value!r}")
        return value
    if tp is int:
        if isinstance(value, bool) or not isinstance(value, int):  # 3.0 too: TOML tells 3 from 3.0
            raise InputError(source, key, f"expected {_type_name(tp)}, got {_short(value)}")
        if not -MAX_INT <= value <= MAX_INT:
            raise InputError(source, key, f"{value} is out of range; must be within +-{MAX_INT}")
        return value
    if tp is bool:
        if not isinstance(value, bool):
            raise InputError(source, key, f"expected {_type_name(tp)}, got {_short(value)}")
        return value
    if tp is str:
        if not isinstance(value, str):
            raise InputError(source, key, f"expected {_type_name(tp)}, got {_short(value)}")
        if len(value) > MAX_STRING_LENGTH or any(ord(ch) < 32 and ch not in "\t" for ch in value):
            raise InputError(source, key, f"expected a one-line string of at most {MAX_STRING_LENGTH} characters")
        return value
    if tp is list:
        if (not isinstance(value, (list, tuple)) or not value
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)):
            raise InputError(source, key, f"expected a non-empty list of numbers, got {_short(value)}")
        if len(value) > MAX_LIST_LENGTH:
            raise InputError(source, key, f"a list of {len(value)} numbers; at most {MAX_LIST_LENGTH}")
        try:
            out = tuple(float(v) for v in value)
        except OverflowError:  # an integer beyond float range
            raise InputError(source, key, "expected a list of finite numbers, got an integer beyond float range") from None
        bad = [v for v in out if not math.isfinite(v)]
        if bad:
            raise InputError(source, key, f"expected a list of finite numbers, got {bad[0]!r} in it")
        return out
    if tp is tuple:
        if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
            raise InputError(source, key, f"expected a list of names, got {_short(value)}")
        return tuple(value)
    raise TypeError(tp)


# A length (a key ending in ``_m``: positions, sizes, radii, regions, bands) is at most this far from 0 [m]:
# 1,000 km, beyond any scene of this suite.  Lengths of 1e308 m are finite but overflow the first product or
# square taken of them (a region's area, a random centre's range, a radius squared) after the run started.
MAX_LENGTH_M = 1.0e6


def _length_key(key: str, meta: Mapping[str, Any]) -> bool:
    """A key in metres: its doc's unit groups include ``[m]`` (``obstacle_cylinder_list``), or, with none, its
    name ends in ``_m`` and not in a compound unit (``_n_m``: N/m, ``_n_s_m``: N s/m)."""
    units = [u for u in re.findall(r"\[([^\[\]]+)\]", str(meta.get("doc", ""))) if "," not in u]
    if units:
        return "m" in units
    name = key.rsplit(".", 1)[-1]
    return name.endswith("_m") and not name.endswith(("_n_m", "_s_m"))


def check_range(value: Any, meta: Mapping[str, Any], source: str, key: str) -> None:
    choices = meta.get("choices")
    if choices is not None and value not in choices:
        raise InputError(source, key, f"{value!r} is not allowed; choose one of {', '.join(map(str, choices))}")
    is_list = isinstance(value, tuple) and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)
    if is_list:
        n = meta.get("length")
        if n is not None and len(value) != n:
            raise InputError(source, key, f"{list(value)!r}: expected a list of exactly {n} numbers")
        n = meta.get("multiple")
        if n is not None and len(value) % n:
            raise InputError(source, key, f"{list(value)!r}: expected a list of numbers in groups of {n}")
        if meta.get("ordered") and any(b < a for a, b in zip(value, value[1:])):
            raise InputError(source, key, f"{list(value)!r}: expected [lo, hi] with lo <= hi")
    for op, test, word in (("ge", lambda a, b: a >= b, ">="), ("gt", lambda a, b: a > b, ">"),
                           ("le", lambda a, b: a <= b, "<="), ("lt", lambda a, b: a < b, "<")):
        bound = meta.get(op)
        if bound is None:
            continue
        for v in (value if is_list else (value,)):
            if not test(v, bound):
                what = f"{v!r} in {list(value)!r}" if is_list else repr(v)
                raise InputError(source, key, f"{what} is out of range; must be {word} {bound}")
    if _length_key(key, meta) and isinstance(value, (int, float, tuple)) and not isinstance(value, bool):
        for v in (value if isinstance(value, tuple) else (value,)):
            if isinstance(v, (int, float)) and not isinstance(v, bool) and abs(v) > MAX_LENGTH_M:
                what = f"{v!r} in {list(value)!r}" if isinstance(value, tuple) else repr(v)
                raise InputError(source, key, f"{what} is out of range; the numbers of a length key must be "
                                              f"within +-{MAX_LENGTH_M:g} (m)")
    check = meta.get("check")
    if check is not None:
        msg = check(value)
        if msg:
            raise InputError(source, key, msg)


def check_section(cls, data: Mapping[str, Any], source: str, prefix: str) -> dict[str, Any]:
    """Validate a (partial) mapping for section ``cls``; return the coerced mapping.

    Unknown keys, wrong types and out-of-range values raise ``InputError``.
    """
    if not isinstance(data, Mapping):
        raise InputError(source, prefix, f"expected a table of keys, got {data!r}")
    types = field_types(cls)
    metas = {f.name: f.metadata for f in dataclasses.fields(cls)}
    out: dict[str, Any] = {}
    for key, value in data.items():
        dotted = f"{prefix}.{key}" if prefix else key
        if key not in types:
            hint = did_you_mean(dotted, [f"{prefix}.{t}" if prefix else t for t in types])
            raise InputError(source, dotted, f"unknown key{hint}; allowed keys of [{prefix}]: {', '.join(sorted(types))}")
        v = coerce_value(value, types[key], source, dotted)
        check_range(v, metas[key], source, dotted)
        out[key] = v
    return out


def build_section(cls, data: Mapping[str, Any], source: str, prefix: str):
    return cls(**check_section(cls, data, source, prefix))


def describe_section(cls) -> list[dict[str, Any]]:
    """Key, type, default and allowed range of a section, for ``list`` and docs."""
    rows = []
    types = field_types(cls)
    for f in dataclasses.fields(cls):
        m = f.metadata
        allowed = {k: m[k] for k in ("ge", "gt", "le", "lt", "choices", "length", "multiple") if m.get(k) is not None}
        if m.get("ordered"):
            allowed["ordered"] = True
        rows.append(dict(key=f.name, type=_type_name(types[f.name]), default=f.default, allowed=allowed, doc=m.get("doc", "")))
    return rows
