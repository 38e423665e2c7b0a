"""Travelling muscle waves: Miller's gaits as a backend-agnostic activation.

A muscle activation gives every body segment three strains:

* ``AXIAL``   -- lengthening of the whole segment (rectilinear crawling, Miller Sec. 4);
* ``LATERAL`` -- right fibres lengthen, left fibres shorten: bends the body
  toward the left for a positive value (lateral undulation);
* ``DORSAL``  -- dorsal fibres lengthen, ventral shorten: arches the body
  upward for a positive value (sidewinding's vertical wave, caterpillar).

A fibre at corner (y_s, z_s) of a segment cross-section (y_s = -1 ventral,
+1 dorsal; z_s = -1 left, +1 right) has stretch
``1 + axial + lateral * z_s + dorsal * y_s``.  The mass-spring body maps that
to spring rest lengths, the FEM body to the rest shape of its tetrahedra.

Each channel is a travelling wave ``A * shape(k s - omega t + phi)`` where s
is the rest arc length of the segment centre from the head [m], k = +-2 pi /
wavelength [rad/m] (positive: the wave travels from head to tail), omega = 2 pi
f [rad/s].  The wave table is a (3, 5) float64 array so that numba kernels
evaluate the activation at every substep without calling Python.

:class:`MuscleWaveController` is the open-loop controller of these gaits: for every chunk of
steps it fills the actuation buffer (one row per step, ``fill_activation``), and the body's
kernel reads row k at step k, knowing nothing of gait names or wave tables.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..core.protocols import AXIAL, DORSAL, LATERAL, MUSCLES, N_CHANNELS, Actuation, Observation  # noqa: F401
from ..core.schema import GaitConfig, rng
# wave table columns
AMP, WAVENUMBER, OMEGA, PHASE, PROFILE = 0, 1, 2, 3, 4
PROFILE_SINE, PROFILE_RAISED = 0.0, 1.0

# Corner sign tables of a cube cross-section, in corner order c = 0..3:
# (ventral, left), (ventral, right), (dorsal, left), (dorsal, right).
CORNER_Y = np.array([-1.0, -1.0, 1.0, 1.0])
CORNER_Z = np.array([-1.0, 1.0, -1.0, 1.0])

GAIT_DESCRIPTIONS = {
    "rectilinear": "Miller's worm: a sine compression wave travels head to tail (AXIAL channel)",
    "lateral-undulation": "left and right fibres 180 degrees out of phase: a bending wave (LATERAL channel)",
    "sidewinding": "lateral undulation plus a vertical wave 90 degrees out of phase, wavelength = length / 1.4",
    "arching": "caterpillar: a one-sided arching wave travelling tail to head (DORSAL) with coupled contraction (AXIAL)",
}


CURVATURE_GAITS = ("lateral-undulation", "sidewinding")


def _check_harmonics(v) -> str | None:
    if not all(float(h).is_integer() for h in v) or len(set(v)) != len(v):
        return "expected distinct whole numbers (temporal harmonics of the wave frequency, e.g. [3, 5])"
    return None


@dataclass(frozen=True)
class MuscleWaveConfig(GaitConfig):
    """``[gaits.<muscle wave>]``: GaitConfig's keys (the wave on the main channel) and the muscle waves' own:
    the commanded shape of a bending wave, sidewinding's vertical wave, arching's axial wave and profile, and
    the shape control (``controllers.shape_tracking``).  A bending gait (``CURVATURE_GAITS``) with a
    commanded curvature asks the runner for the body's strain per curvature (``commands_curvature``)."""

    curvature_amplitude: float = rng(0.0, ge=0.0, le=60.0,
                                     doc="lateral undulation, sidewinding: commanded peak curvature x body length "
                                         "[-]; each body turns it into its own strain (bodies/curvature_calibration.py); "
                                         "0: use the raw strain 'amplitude'")
    vertical_amplitude: float = rng(0.0, ge=0.0, lt=0.95, doc="sidewinding: vertical wave strain amplitude")
    vertical_curvature_amplitude: float = rng(0.0, ge=0.0, le=60.0,
                                              doc="sidewinding: commanded peak vertical curvature x body length [-], "
                                                  "turned into strain with the body's own gain as "
                                                  "curvature_amplitude; 0: use the raw 'vertical_amplitude'")
    vertical_phase_deg: float = rng(90.0, doc="sidewinding: phase of the vertical wave relative to the lateral wave [deg]")
    axial_amplitude: float = rng(0.0, ge=0.0, lt=0.95, doc="arching: axial strain amplitude of the contraction coupled to the arch")
    axial_phase_deg: float = rng(180.0, doc="arching: phase of the axial wave relative to the arch (180: arched segments are shortest)")
    profile: str = rng("sine", choices=("sine", "raised"), doc="'raised' keeps the wave one-sided (arching only upward)")
    # Shape control of a commanded bending wave (curvature_amplitude > 0; controllers/muscle_waves.py,
    # docs/explanation/shape-tracking.md).
    shape_control: str = rng("closed_loop", choices=("closed_loop", "open_loop"),
                             doc="lateral undulation, sidewinding with curvature_amplitude > 0: 'closed_loop' (default) "
                                 "measures the ground curvature of the segment frames at shape_control_rate_hz and "
                                 "corrects each segment's LATERAL strain (calibrated feed-forward + proportional + "
                                 "per-segment integral of the wave's in-phase and quadrature error); 'open_loop': the "
                                 "calibrated gain alone, bit for bit as before issue 27 "
                                 "(docs/explanation/shape-tracking.md)")
    shape_guard: bool = rng(True, doc="closed_loop: protect the loop from running away: identify the body's open-loop "
                                      "response on the case's ground and store the loop's margin at its gains "
                                      "(PlantMargin; measured, not acted on), and watch the run (the body bent 20 % "
                                      "beyond the command while the loop pushes, or most muscles held at "
                                      "max_muscle_strain: back off to the open loop, resume at half the gains; the "
                                      "waveform's harmonics growing past 0.15 and the open loop's own: the integrals "
                                      "off; a segment rolled more than 15 degrees from the body's median roll while "
                                      "the loop commands 1.5x the feed-forward: the open loop for good, status "
                                      "controller_unstable; a commanded wave the loop's smoothing passes under half "
                                      "of (fewer than about 11 muscle segments a wave): the open loop from the start; "
                                      "LoopGuard, WaveformWatch; controllers/shape_tracking.py); false: the loop "
                                      "as it was before issue 44, at the body's constant gains")
    shape_control_rate_hz: float = rng(250.0, gt=0.0, le=10000.0,
                                       doc="closed_loop: control ticks per simulated second (strain held between ticks) [Hz]")
    shape_gain_p: float = rng(-1.0, ge=-1.0, le=100.0,
                              doc="closed_loop: proportional gain, strain correction per unit of strain-equivalent "
                                  "curvature error [-]; -1 (default): the body model's own (BodySpec.shape_gain_p: "
                                  "2 on massspring, 0.5 on fem, 0.25 on hybrid)")
    shape_gain_i_per_cycle: float = rng(2.0, ge=-1.0, le=100.0,
                                        doc="closed_loop: integral gain of the wave's amplitude and phase error per "
                                            "gait cycle [-] (rate = this x frequency_hz); -1: from the body's plant "
                                            "measured at the loop's operating amplitude (with shape_guard; 0.65 / "
                                            "Re H per cycle, between 0.5 and 4), the constant 2 where that plant is "
                                            "not found (the run's label shape_gains says which; not the default: "
                                            "docs/explanation/shape-tracking.md, \"How the gains are derived\")")
    shape_harmonics: list = rng((3.0,), ge=2, le=15, check=_check_harmonics,
                                doc="closed_loop: temporal harmonics h of the wave frequency whose error each segment also "
                                    "corrects, amplitude and phase, like the fundamental's, when the harmonic gain "
                                    "(shape_harmonic_gain_per_cycle) is > 0 [-]")
    shape_harmonic_gain_per_cycle: float = rng(-1.0, ge=-1.0, le=100.0,
                                               doc="closed_loop: integral gain of each shape_harmonics correction per "
                                                   "gait cycle [-]; -1 (default): the body model's own "
                                                   "(BodySpec.shape_harmonic_gain_per_cycle: 1 on massspring and fem, "
                                                   "0.5 on hybrid); 0: no harmonic corrected")
    shape_harmonic_lead_deg: float = rng(90.0, ge=-180.0, le=180.0,
                                         doc="closed_loop: phase lead [deg] by which each shape_harmonics correction's "
                                             "update is rotated, the command-to-curvature lag it compensates (90: "
                                             "measured on the three bodies, docs/explanation/shape-tracking.md)")
    max_muscle_strain: float = rng(0.3, gt=0.0, lt=0.95,
                                   doc="closed_loop: muscle strength, the largest active fibre strain a muscle can "
                                       "produce [-]; a command beyond it is clipped and counted in "
                                       "muscle_saturation_fraction")

    def commands_curvature(self) -> bool:
        return self.name in CURVATURE_GAITS and (self.curvature_amplitude > 0.0
                                                 or self.vertical_curvature_amplitude > 0.0)


def wave_table(gait: GaitConfig, body_length_m: float, passive: bool = False,
               strain_per_curvature: float | None = None) -> np.ndarray:
    """The (3, 5) wave table [amplitude, wavenumber rad/m, omega rad/s, phase rad, profile] of a gait.

    A bending gait with ``gait.curvature_amplitude`` > 0 commands its shape: the LATERAL amplitude
    is curvature_amplitude x ``strain_per_curvature`` (the body's own gain, strain per unit of
    curvature x body length, measured by the body and passed in ``body_info``); without the gain
    the raw strain ``amplitude`` is used (a table built before the body is known).  Sidewinding's
    DORSAL amplitude is likewise ``vertical_curvature_amplitude`` x the same gain when both are
    given: the gain is measured in the lateral plane, and the bodies' cross-sections are square
    (width = height, the same fibre layout about both axes), so it holds in the vertical plane too.
    """
    table = np.zeros((N_CHANNELS, 5))
    if passive or gait.name == "passive":
        return table
    direction = 1.0 if gait.direction == "head-to-tail" else -1.0
    k = direction * 2.0 * math.pi / (gait.wavelength_bl * body_length_m)
    omega = 2.0 * math.pi * gait.frequency_hz
    phase = math.radians(gait.phase_deg)
    profile = PROFILE_RAISED if gait.profile == "raised" else PROFILE_SINE
    main = {"rectilinear": AXIAL, "lateral-undulation": LATERAL, "sidewinding": LATERAL, "arching": DORSAL}.get(gait.name)
    if main is None:  # a gait without muscles (legs, or none at all)
        return table
    amplitude = gait.amplitude
    if gait.name in CURVATURE_GAITS and gait.curvature_amplitude > 0.0 and strain_per_curvature is not None:
        amplitude = gait.curvature_amplitude * strain_per_curvature
    table[main] = (amplitude, k, omega, phase, profile)
    if gait.name == "sidewinding":
        vertical = gait.vertical_amplitude
        if gait.vertical_curvature_amplitude > 0.0 and strain_per_curvature is not None:
            vertical = gait.vertical_curvature_amplitude * strain_per_curvature
        table[DORSAL] = (vertical, k, omega, phase + math.radians(gait.vertical_phase_deg), PROFILE_SINE)
    if gait.name == "arching":
        # Lifted segments shorten and reach forward while the others hold (Miller: "the underside is
        # lifted and thrust forward and then placed down again"); with 180 degrees the arched segments
        # are the shortest, so a wave travelling tail to head carries the body forward.
        table[AXIAL] = (gait.axial_amplitude, k, omega, phase + math.radians(gait.axial_phase_deg), PROFILE_SINE)
    return table


@njit(cache=True, error_model="numpy")
def segment_activation(waves, ramp_s, s_seg, t, out):
    """Overwrite ``out`` (n_seg, 3) with the channel strains of every segment at time t [s].

    waves: (3, 5) wave table; s_seg: (n_seg,) rest arc length of segment centres [m].
    The amplitude ramps linearly from 0 over ``ramp_s`` so a gait starts without a jolt.
    """
    r = 1.0
    if ramp_s > 0.0 and t < ramp_s:
        r = max(t, 0.0) / ramp_s
    for i in range(s_seg.shape[0]):
        for c in range(3):
            a = waves[c, AMP]
            if a == 0.0:
                out[i, c] = 0.0
                continue
            val = math.sin(waves[c, WAVENUMBER] * s_seg[i] - waves[c, OMEGA] * t + waves[c, PHASE])
            if waves[c, PROFILE] == PROFILE_RAISED and val < 0.0:
                val = 0.0
            out[i, c] = r * a * val


def segment_activation_numpy(waves: np.ndarray, ramp_s: float, s_seg: np.ndarray, t: float) -> np.ndarray:
    """Slow reference of :func:`segment_activation`: (n_seg, 3) strains."""
    r = 1.0 if ramp_s <= 0 or t >= ramp_s else max(t, 0.0) / ramp_s
    theta = waves[:, WAVENUMBER][None, :] * s_seg[:, None] - waves[:, OMEGA][None, :] * t + waves[:, PHASE][None, :]
    val = np.sin(theta)
    raised = waves[:, PROFILE][None, :] == PROFILE_RAISED
    val = np.where(raised & (val < 0), 0.0, val)
    return r * waves[:, AMP][None, :] * val


@njit(cache=True, error_model="numpy")
def fill_activation(waves, ramp_s, s_seg, t0, dt, n_rows, out):
    """Overwrite rows 0..n_rows-1 of ``out`` (>= n_rows, n_seg, 3) with the activation at t0 + k dt [s].

    The time of row k is computed as ``t0 + k * dt``, as the body kernels count their steps, so a
    buffered activation is bitwise the one a kernel would have evaluated itself.
    """
    for k in range(n_rows):
        segment_activation(waves, ramp_s, s_seg, t0 + k * dt, out[k])


class MuscleWaveController:
    """Miller's travelling muscle waves (rectilinear, lateral undulation, sidewinding, arching;
    ``wave_table``).  Works on any body with muscles: the waves are evaluated at the body's own muscle
    segments (``body_info["muscle_s"]``, rest arc length from the head [m]), with the wavelength
    measured in the creature's body length.

    Open loop (every gait without a commanded curvature, and any gait with ``gait.shape_control =
    "open_loop"``): the controller fills whole chunks (``fill``).  A bending gait that commands its
    shape (``curvature_amplitude`` > 0) with ``shape_control = "closed_loop"`` is a closed-loop
    controller instead (``open_loop`` False, ``rate_hz`` = ``gait.shape_control_rate_hz``): at every
    tick ``step`` measures the ground curvature of the segment frames and corrects each segment's
    LATERAL strain (``controllers.shape_tracking``); the other channels stay the open-loop waves."""

    requires = frozenset({MUSCLES})
    open_loop = True
    rate_hz = 0.0

    def __init__(self, case):
        self.case = case
        self.waves = wave_table(case.gait, case.creature.body_length_m, passive=case.scenario.passive)
        self.ramp_s = float(case.gait.ramp_s)
        self.s_seg = np.zeros(0)
        self.tracker = None
        gait = case.gait
        if (gait.shape_control == "closed_loop" and gait.name in CURVATURE_GAITS and gait.curvature_amplitude > 0.0
                and not case.scenario.passive):
            from .shape_tracking import ShapeTracker  # noqa: PLC0415 (one concept per module; no cycle)
            self.tracker = ShapeTracker(case)
            self.open_loop = False
            self.rate_hz = float(gait.shape_control_rate_hz)

    def reset(self, case, body_info, rng=None) -> None:
        self.s_seg = np.ascontiguousarray(body_info["muscle_s"], dtype=np.float64)
        gait = case.gait
        if gait.commands_curvature():
            gain = body_info.get("strain_per_curvature")
            if gain is None:
                # a reset outside the runner (a bare core.protocols.body_info): the raw strain amplitude
                warnings.warn("gait.curvature_amplitude without the body's strain_per_curvature in body_info "
                              "(harness.calibration.calibrated_body_info): using the raw strain amplitude",
                              stacklevel=2)
                return
            self.waves = wave_table(gait, case.creature.body_length_m, passive=case.scenario.passive,
                                    strain_per_curvature=float(gain))
            if self.tracker is not None:
                self.tracker.reset(body_info, float(gain))

    def plant_wave(self, case) -> tuple[float, float, float, float, float]:
        """The wave ``bodies.curvature_calibration.plant_response`` drives to identify the open loop's response
        (``harness.calibration.identified_plant``): the lateral row's columns 1-3 of this controller's wave
        table after ``reset`` (the calibrated open loop), the commanded ground curvature [1/m] and the ramp
        [s]. Here, so that the harness reads the gait's wave without importing the controller's module."""
        from ..core.protocols import LATERAL_GROUND_SIGN

        g, L = case.gait, float(case.creature.body_length_m)
        row = self.waves[LATERAL]
        return (float(row[1]), float(row[2]), float(row[3]), LATERAL_GROUND_SIGN * g.curvature_amplitude / L,
                float(g.ramp_s))

    def metrics(self) -> dict[str, float]:
        """The closed loop's muscle figures (``shape_tracking.ShapeTracker.metrics``); none in open loop."""
        return self.tracker.metrics() if self.tracker is not None and self.tracker.ready else {}

    def labels(self) -> dict[str, str]:
        """The closed loop's labels (``shape_tracking.ShapeTracker.labels``: where its gains came from); none in
        open loop."""
        return self.tracker.labels() if self.tracker is not None and self.tracker.ready else {}

    def run_status(self) -> tuple[str, str] | None:
        """(status, message) when the closed loop had to be backed off (``shape_tracking.ShapeTracker.run_status``:
        ``controller_unstable``); None otherwise."""
        return self.tracker.run_status() if self.tracker is not None and self.tracker.ready else None

    def fill(self, t0: float, dt: float, n_steps: int, act: Actuation) -> None:
        act.ensure_rows(n_steps)
        fill_activation(self.waves, self.ramp_s, self.s_seg, t0, dt, n_steps, act.muscle)
        act.muscles_on = bool(np.any(self.waves[:, AMP] != 0.0))

    def step(self, obs: Observation, t: float, act: Actuation) -> None:
        if self.tracker is not None and self.tracker.ready:
            act.ensure_rows(1)
            segment_activation(self.waves, self.ramp_s, self.s_seg, t, act.muscle[0])
            self.tracker.command(obs, t, self.waves, self.ramp_s, self.s_seg, act.muscle[0])
            act.muscles_on = True
            return
        self.fill(t, 0.0, 1, act)


class PassiveController:
    """No actuation at all: the body only falls, hangs and collides (the paper's Fig. 4 chain)."""

    requires = frozenset()
    open_loop = True
    rate_hz = 0.0

    def __init__(self, case=None):
        pass

    def reset(self, case, body_info, rng=None) -> None:
        pass

    def fill(self, t0: float, dt: float, n_steps: int, act: Actuation) -> None:
        act.ensure_rows(n_steps)
        act.muscle[:n_steps] = 0.0
        act.muscles_on = False

    def step(self, obs: Observation, t: float, act: Actuation) -> None:
        self.fill(t, 0.0, 1, act)
