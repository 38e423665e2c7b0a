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
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..core.registry import GaitSpec, register_gait
from ..core.schema import GaitConfig

AXIAL, LATERAL, DORSAL = 0, 1, 2
N_CHANNELS = 3
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
for _name, _desc in GAIT_DESCRIPTIONS.items():
    register_gait(GaitSpec(name=_name, description=_desc, requires=frozenset({"muscles"})))
# A creature without muscles or legs (e.g. the paper's Fig. 4 chain) runs the passive gait.
register_gait(GaitSpec(name="passive", description="no actuation: the body only falls, hangs and collides",
                       requires=frozenset()))


def wave_table(gait: GaitConfig, body_length_m: float, passive: bool = False) -> np.ndarray:
    """The (3, 5) wave table [amplitude, wavenumber rad/m, omega rad/s, phase rad, profile] of a gait."""
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
    table[main] = (gait.amplitude, k, omega, phase, profile)
    if gait.name == "sidewinding":
        table[DORSAL] = (gait.vertical_amplitude, k, omega, phase + math.radians(gait.vertical_phase_deg), PROFILE_SINE)
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
