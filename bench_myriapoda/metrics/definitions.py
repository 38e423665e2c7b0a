"""The one table of every metric a run can store: name -> unit, definition, who produces it.

The documentation's metric reference is generated from ``METRICS`` (``docs/_ext/reference_pages.py``)
and ``tests/test_metric_definitions.py`` holds it to the code both ways: every metric a stored run
carries is in the table, and every name in the table is written by the package's code. Adding a
metric means adding its row here; the test says which one is missing.

Units are SI unless the name says otherwise (``_bl``: body lengths, ``_deg``: degrees,
``_per_cycle``: per gait period). ``-`` marks a dimensionless number, ``count`` a whole number
stored as a float.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class MetricDefinition:
    """One row of the metric table."""

    name: str
    unit: str
    definition: str
    group: str     # which runs carry it (the reference page's sections)


# A data table, one row a metric: the rows are alike by design (``duplicates`` pairs them by shape; deliberate).
_ROWS: tuple[tuple[str, str, str, str], ...] = (
    # ---- every run (harness/runner.py, metrics/locomotion.py)
    ("speed_m_per_s", "m/s", "forward speed of the centre of mass along the mean body axis over the steady window "
     "(after `metrics.warmup_cycles` gait cycles)", "every run"),
    ("speed_bl_per_s", "BL/s", "`speed_m_per_s` divided by the body's rest length", "every run"),
    ("speed_bl_per_cycle", "BL/cycle", "forward distance per gait period in body lengths", "every run"),
    ("displacement_per_cycle_m", "m", "forward distance per gait period", "every run"),
    ("lateral_speed_m_per_s", "m/s", "speed of the centre of mass perpendicular to the mean body axis, positive "
     "to the creature's right", "every run"),
    ("travel_angle_deg", "deg", "signed angle from the mean body axis to the direction of travel", "every run"),
    ("slip_ratio", "-", "1 - speed / wave speed (NaN without a travelling wave)", "every run"),
    ("path_following_error_bl", "BL", "mean distance of the segments from the path the head has travelled "
     "since t = 0, counted once the head has travelled a segment's rest distance behind it", "every run"),
    ("cycles_measured", "cycles", "length of the steady window in gait periods", "every run"),
    ("com_height_change_m", "m", "height of the centre of mass at the end minus at the start", "every run"),
    ("energy_drift_rel", "-", "change of total mechanical energy over the run relative to its start "
     "(meaningful for passive, undamped cases)", "every run"),
    ("energy_max_dev_rel", "-", "largest deviation of total mechanical energy from its start, relative",
     "every run"),
    ("contact_fraction", "-", "mean share of the body's nodes touching the ground", "every run"),
    ("max_penetration_m", "m", "deepest penetration of a node into the terrain", "every run"),
    ("body_length_m", "m", "the body's rest length from head to tail (a hybrid body's links included)",
     "every run"),
    ("wave_speed_m_per_s", "m/s", "speed of the commanded muscle wave along the body (0 without one)",
     "every run"),
    ("t_fail_s", "s", "time at which the run became unstable (non-finite state, runaway speed, deep "
     "penetration); NaN when it stayed stable", "every run"),
    ("path_length_m", "m", "length of the path the head travelled", "every run"),
    ("terrain_clearance_min_m", "m", "smallest signed distance of a segment centre (legged: a box corner or "
     "leg tip) above the terrain; negative inside", "every run"),
    ("hanging_elongation_m", "m", "elongation of a suspended body: head-to-tail distance over the last samples "
     "minus at t = 0", "suspended scenarios"),
    # ---- legless creatures (metrics/body_shape.py, metrics/posture.py)
    ("curvature_amplitude", "-", "peak curvature x body length of the ground projection of the centre line: "
     "sqrt(2) x the RMS of each interior point's curvature over the steady window, median over the points",
     "legless creatures"),
    ("body_wavelength_bl", "BL", "body wavelength from the phase of each point's curvature at the gait "
     "frequency; NaN for a body that does not bend", "legless creatures"),
    ("heading_drift_deg_per_cycle", "deg/cycle", "rotation of the mean body axis per gait period "
     "(least squares over the window; + = left)", "legless creatures"),
    ("roll_max_deg", "deg", "largest rotation of a cross-section about the body axis (dorsal axis against the "
     "vertical, pitch excluded) over segments and the run", "legless creatures"),
    ("segment_contact_fraction", "-", "mean share of segments touching the ground over the window",
     "legless creatures"),
    ("lift_max_m", "m", "how far the lowest segment centre rose above the ground beneath it after the first "
     "contact (the whole body leaving the ground)", "legless creatures"),
    ("airborne_max_s", "s", "longest time with no segment in contact after the first contact",
     "legless creatures"),
    ("posture_fault", "0/1", "1 when the body flipped (roll_max_deg > 90 on flat ground) or left the ground "
     "(airborne_max_s > 0.3 s, not in suspended scenarios), else 0; `run --strict` exits 1 on it",
     "legless creatures"),
    # ---- body models' own figures (bodies/*/body.py: extra_metrics)
    ("min_J", "-", "smallest det F of any tetrahedron seen during the run", "fem and hybrid bodies"),
    ("inverted_elements_max", "count", "most tetrahedra with det F <= 0 at once", "fem and hybrid bodies"),
    ("inverted_elements_final", "count", "tetrahedra with det F <= 0 at the end of the run", "hybrid body"),
    ("max_strain", "-", "largest |sigma - 1| over the principal stretches of any tetrahedron",
     "fem and hybrid bodies"),
    ("n_tets", "count", "tetrahedra in the mesh", "fem body"),
    ("n_nodes", "count", "nodes in the mesh", "fem body"),
    ("coupling_residual_max_m", "m", "largest distance the staggered deformable step moves an attached node "
     "from where its rigid segment puts it", "hybrid body, legged mass-spring body"),
    ("coupling_residual_mean_m", "m", "mean of that distance over attached nodes and steps",
     "hybrid body, legged mass-spring body"),
    # ---- legged creatures (metrics/gait.py, harness/legged.py)
    ("duty_factor_mean", "-", "mean share of a stride a stepping leg spends in STANCE", "legged creatures"),
    ("duty_factor_std", "-", "standard deviation of the duty factor over stepping legs", "legged creatures"),
    ("stride_frequency_hz", "Hz", "mean stride frequency of the stepping legs", "legged creatures"),
    ("phase_lag_mean", "cycles", "circular mean of the stance-onset lag of each leg behind the leg in front, "
     "in (-0.5, 0.5]; positive = retrograde wave", "legged creatures"),
    ("phase_lag_cv", "-", "RMS deviation of the lags from their mean divided by |phase_lag_mean|",
     "legged creatures"),
    ("legs_per_wave", "legs", "1 / |phase_lag_mean|: legs per wavelength along one side", "legged creatures"),
    ("lr_phase_diff", "cycles", "phase of the right leg's stance onset in the left leg's stride, per segment, "
     "|circular mean| in [0, 0.5] (0 in phase, 0.5 antiphase)", "legged creatures"),
    ("stance_fraction_min", "-", "smallest share of legs in STANCE at any sample of the gait window",
     "legged creatures"),
    ("stance_fraction_mean", "-", "time-weighted mean share of legs in STANCE over the gait window",
     "legged creatures"),
    ("stride_length_bl", "BL", "distance the centre of mass travels per stride, in body lengths",
     "legged creatures"),
    ("speed_bl_per_stride", "BL/stride", "forward speed per stride period, in body lengths", "legged creatures"),
    ("foot_slip_mean_m", "m", "mean distance a leg tip slides while in STANCE", "legged creatures"),
    ("stepping_leg_fraction", "-", "share of legs that complete at least one stride in the gait window",
     "legged creatures"),
    ("walking_cycle_leg_fraction", "-", "share of legs whose dominant state cycle is SF1 -> SF2 -> STANCE in at "
     "least 80 % of at least two complete cycles (paper Fig. 10 D)", "legged creatures"),
    ("heading_error_deg", "deg", "mean |heading error| of the head against the commanded heading",
     "legged creatures"),
    ("body_undulation_amp_bl", "BL", "mean half-width of the segment centres' sideways spread about the "
     "head-tail line", "legged creatures"),
    ("time_to_walk_s", "s", "when the head's ADJUSTMENT mode ended (NaN if it never did)", "legged creatures"),
    ("touch_fraction_at_walk", "-", "share of leg tips touching the ground when ADJUSTMENT ended",
     "legged creatures"),
    ("tracking_error_mean_m", "m", "mean distance of supported segments from their kinematic targets after the "
     "body's step", "legged creatures"),
    ("brain_mode_final", "code", "the head's mode at the end: 0 ADJUSTMENT, 1 AVOIDANCE, 2 TROPHOTROPISM, "
     "3 RANDOM-WALK, 4 CONTROL (the JSON's `labels` names it)", "legged creatures"),
    ("brain_avoidance_fraction", "-", "share of controller steps in AVOIDANCE", "legged creatures"),
    ("brain_trophotropism_fraction", "-", "share of controller steps in TROPHOTROPISM", "legged creatures"),
    ("leg_penetration_max_m", "m", "deepest knee or leg tip inside the terrain over the run", "legged creatures"),
    ("leg_stops", "count", "swing moves cut at a surface, summed over legs and steps", "legged creatures"),
    ("leg_stuck", "count", "leg-steps left inside a surface with no way out", "legged creatures"),
    ("wall_pushes", "count", "segment-steps a carried segment was moved out of a wall", "legged creatures"),
    ("obstacle_contacts", "count", "antenna contact events with obstacles", "legged creatures"),
    ("obstacle_penetration_max_m", "m", "deepest penetration of the body or a leg into an obstacle",
     "legged creatures"),
    ("obstacle_penetration_body_max_m", "m", "deepest penetration of a body box corner into an obstacle",
     "legged creatures"),
    ("obstacle_penetration_legs_max_m", "m", "deepest penetration of a leg into an obstacle", "legged creatures"),
    ("food_reached", "count", "food sources eaten", "legged creatures"),
    ("time_to_first_food_s", "s", "when the first food source was eaten (NaN if none)", "legged creatures"),
    ("food_sources", "count", "food sources in the scenario", "legged creatures"),
    # ---- the body's lateral undulation over the gait window (metrics/undulation.py, harness/legged.py)
    ("undulation_amplitude_bl", "BL", "mean over segments of sqrt(2) x the RMS sideways position across the "
     "window's travel direction, less each segment's linear trend in time", "legged creatures"),
    ("undulation_frequency_hz", "Hz", "peak frequency of the segments' sideways positions' summed power spectrum",
     "legged creatures"),
    ("undulation_wavelength_bl", "BL", "2 pi / |k| of the linear fit phi = phi_0 - k s of the segments' phases "
     "at the undulation frequency against their distance s from the head (NaN for a standing sway)",
     "legged creatures"),
    ("undulation_direction", "-", "+1 when the undulation travels head to tail (k > 0), -1 tail to head",
     "legged creatures"),
    ("undulation_leg_phase_rad", "rad", "circular mean of the head's undulation phase theta (y = A sin theta) at "
     "the stance onsets of the head's left leg, in [0, 2 pi)", "legged creatures"),
    ("head_yaw_osc_deg", "deg", "sqrt(2) x the RMS of the head's heading (segment 1 to head) less its linear "
     "trend over the gait window", "legged creatures"),
    # ---- the dynamic stance (legs.stance = "dynamic"; bodies/dynamic_stance.py, harness/legged.py)
    ("stance_foot_slip_m", "m", "distance the STANCE feet slid, summed over feet and steps of the run",
     "dynamic stance (hybrid, massspring)"),
    ("stance_slide_fraction", "-", "share of STANCE foot-steps in which the foot slid (its friction cone did "
     "not hold)", "dynamic stance (hybrid, massspring)"),
    ("stance_slip_per_stride_m", "m", "`stance_foot_slip_m` / the strides of all legs over the run (stride "
     "frequency x duration x legs)", "dynamic stance (hybrid, massspring)"),
    ("leg_force_mean_n", "N", "mean magnitude of a STANCE foot's force over foot-steps", "dynamic stance (hybrid, "
     "massspring)"),
    ("leg_force_max_n", "N", "largest magnitude of a STANCE foot's force", "dynamic stance (hybrid, massspring)"),
    ("leg_work_positive_j", "J", "positive mechanical work of the legs' force and moment on the segments over "
     "the run", "dynamic stance (hybrid, massspring)"),
    ("cost_of_transport", "-", "`leg_work_positive_j` / (creature weight x net distance of the segments' mean "
     "centre over the run): the legs' mechanical cost of transport", "dynamic stance (hybrid, massspring)"),
    # ---- the commanded shape, achieved or not (metrics/shape_tracking.py, controllers/shape_tracking.py)
    ("shape_tracking_error", "-", "RMS over the steady window and the interior centre-line points of (measured - "
     "commanded ground curvature) x body length / commanded amplitude (`gait.curvature_amplitude`); 0.71 for a "
     "straight body", "bending gaits"),
    ("shape_not_achieved", "0/1", "1 when `shape_tracking_error` is above 0.10: the body did not make the "
     "commanded shape, so its locomotion is not comparable across bodies", "bending gaits"),
    ("shape_harmonic_content", "-", "RMS over the interior centre-line points of the measured curvature's temporal "
     "harmonics 2 to 5 over the steady window x body length / commanded amplitude: 0 for a travelling sine of any "
     "amplitude and phase (the waveform, not the amplitude or lag)", "bending gaits"),
    ("muscle_saturation_fraction", "-", "share of steady-window (segment, control tick) strain commands clipped at "
     "`gait.max_muscle_strain` (closed-loop shape control only)", "bending gaits"),
    ("muscle_strain_peak", "-", "largest |lateral strain| commanded in the steady window (closed-loop shape control "
     "only)", "bending gaits"),
    ("shape_control_backoffs", "count", "times the closed loop's guard found the loop had lost its margin (the "
     "body bent beyond 1.2 x the command or most muscles held at `gait.max_muscle_strain`: backed off to the "
     "calibrated open loop; the bend's harmonic content over the last period above 0.15 and the open loop's own + "
     "0.05: the loop's integrals switched off the first time, backed off after) (`gait.shape_guard`, closed-loop "
     "shape control only)", "bending gaits"),
    ("shape_control_gain_scale", "-", "the closed loop's gains at the end of the run over its own: 1 when the guard "
     "never acted, halved at each back-off, 0 when it stayed in the calibrated open loop (the proportional gain's: "
     "after a waveform trip the integrals are off, which the run's message says)", "bending gaits"),
    ("shape_control_backoff_s", "s", "when the guard first backed the loop off (NaN when it never did)",
     "bending gaits"),
    ("shape_control_open_loop_trim", "-", "the smallest amplitude, over the calibrated open loop's, the guard gave the "
     "open loop while it held the loop off after a back-off for a bend beyond the command: lowered from the centre "
     "line's bend against the command, never below 0.7 nor above 1 (1: never trimmed) (`gait.shape_guard`, "
     "closed-loop shape control only)", "bending gaits"),
    ("shape_plant_gain", "-", "median over the interior segments of the curvature amplitude the calibrated open loop "
     "reached on the case's own ground over the commanded one (identified before the run, "
     "bodies/curvature_calibration.py plant_response; closed-loop shape control with gait.shape_guard; not "
     "identified for a run shorter than half a gait period, harness/calibration.py uses_the_plant)",
     "bending gaits"),
    ("shape_plant_lag_deg", "deg", "median over the interior segments of the open loop's curvature lag behind the "
     "commanded wave, from the same identification", "bending gaits"),
    ("shape_loop_margin_deg", "deg", "phase margin of the loop's amplitude-and-phase integral on the identified open "
     "loop at the gains the run started with (before any back-off): 90 - the largest |arg H| over the segments, "
     "H = rho G / (1 + K_p rho G) (G the identified response, K_p the proportional gain used, rho the smoothing's "
     "response to the commanded wave; a linear plant converges above 0); measured, not acted on: under Coulomb "
     "friction it does not predict the closed loop (docs/explanation/shape-tracking.md)", "bending gaits"),
    ("shape_loop_rate_per_cycle", "-", "the same integral's convergence per gait cycle at the gains used: "
     "`gait.shape_gain_i_per_cycle` x Re H, the median over the segments (e-foldings of a linear plant's error per "
     "cycle; 0 or below: no convergence)", "bending gaits"),
    ("shape_gain_p_used", "-", "the closed loop's proportional gain the run started with: `gait.shape_gain_p`, or "
     "the body's own (BodySpec.shape_gain_p) at -1 (closed-loop shape control only)", "bending gaits"),
    ("shape_gain_i_per_cycle_used", "-", "the closed loop's amplitude-and-phase integral gain per gait cycle the run "
     "started with: `gait.shape_gain_i_per_cycle`, or at -1 0.65 / Re H from the plant measured at the loop's "
     "operating amplitude (between 0.5 and 4), or the constant 2 where that plant was not found "
     "(docs/explanation/shape-tracking.md, \"How the gains are derived\")", "bending gaits"),
    ("shape_gain_i_from_plant", "0/1", "1 when `shape_gain_i_per_cycle_used` came from the measured plant at the "
     "loop's operating amplitude, 0 when from the key or the fallback constant (the run's label `shape_gains` says "
     "which and why)", "bending gaits"),
    ("shape_operating_amplitude", "-", "the loop's operating amplitude s*, over the feed-forward: where the "
     "calibrated open loop commanding s* times the feed-forward reaches the commanded curvature, s* |G(s*)| = 1, "
     "found in [1, 8] at calibration (bodies/curvature_calibration.py operating_plant); NaN when not found or not "
     "sought", "bending gaits"),
    ("tail_swing_ratio", "-", "RMS lateral excursion of the tail over that of the mid-body (median over the middle "
     "third of the centres) over the steady window, each across the mean body axis less a line fitted in time: 1 for a kinematic snake whose every point "
     "follows the head's path, above 1 for a tail that swishes wider (Miller Sec. 4)", "bending gaits"),
    ("sideways_slip_ratio", "-", "RMS ground velocity across the local centre line over the RMS ground speed, over "
     "the steady window and the interior centre-line points: 0 for a body that moves along itself, 1 for one "
     "moving straight across itself (Miller Sec. 4: segments slide sideways when grip is poor)", "bending gaits"),
    # ---- emergent walking measures (metrics/walk.py): a walk's speed is commanded, these are not
    ("body_speed_ratio", "-", "centre-of-mass ground speed over the commanded head speed "
     "(`controller.head_speed_m_s`)", "legged creatures"),
    ("lateral_sway_bl", "BL", "RMS sideways deviation of the centre of mass from its line of travel",
     "legged creatures"),
    ("body_stretch_rel", "-", "mean relative change of the head-to-tail distance from t = 0", "legged creatures"),
    ("cost_of_transport_mech", "-", "positive increments of total mechanical energy over (m g distance "
     "travelled)", "legged creatures"),
    # ---- shallow water (world/water_coupling.py)
    ("wake_energy", "J", "energy of the water's motion at the end: potential plus kinetic", "water scenarios"),
    ("wake_energy_max", "J", "largest sampled estimate of the wake's energy during the run", "water scenarios"),
    ("water_points_submerged_mean", "count", "mean number of body points under the water surface",
     "water scenarios"),
    # ---- measured over enough of the gait (harness/runner.py, metrics/locomotion.py)
    ("steady_cycles", "cycles", "steady gait periods (walks: strides) in the window the locomotion metrics are "
     "measured over, after the ramp and `metrics.warmup_cycles`; under `metrics.min_steady_cycles` they are "
     "reported as too short", "every run"),
    # ---- energy of a dropped or passive body (metrics/locomotion.py)
    ("energy_drift_free_rel", "-", "change of total mechanical energy from t = 0 to the last sample before the "
     "first contact, relative (the integrator's drift where no contact removes energy)", "every run"),
    ("impact_energy_loss_rel", "-", "change of total mechanical energy from the first contact to the end of the "
     "run, relative to its start (energy lost at impact)", "every run"),
    # ---- stable-dt (harness/stable_dt.py; stored with command = 'stable-dt')
    ("stable_dt_max_s", "s", "largest time step for which the case stayed stable over its duration (NaN when even "
     "the smallest tried was unstable)", "stable-dt"),
    ("unstable_dt_min_s", "s", "smallest time step found unstable (NaN when none up to the ceiling)", "stable-dt"),
    ("stable_dt_runs", "count", "runs the bisection took", "stable-dt"),
)

METRICS: dict[str, MetricDefinition] = {name: MetricDefinition(name, unit, text, group)
                                        for name, unit, text, group in _ROWS}

GROUPS: tuple[str, ...] = tuple(dict.fromkeys(group for *_, group in _ROWS))


def metric_names() -> list[str]:
    """Every metric name in the table, in table order."""
    return list(METRICS)
