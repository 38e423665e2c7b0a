"""Posture of a legless body: roll of the cross-sections, ground contact, lift, posture faults.

From ``Series.segment_rotations`` (T, n_seg, 3, 3) (columns: body axis toward the head, dorsal,
right), ``segment_contact`` (T, n_seg) bool and ``segment_centers``:

* ``roll_max_deg``: rotation of a cross-section about the body axis: the angle between the
  segment's dorsal axis and the vertical projected on the cross-section's plane (so pitching
  along the axis, e.g. a caterpillar's arch, is not roll), followed through time so that a
  segment pitched over backward is not taken for one on its back (``roll_angles_deg``); max
  over segments and the whole run, in [0, 180].  Samples whose axis is within
  ``VERTICAL_AXIS_DEG`` of the vertical (hanging over an edge) are skipped: roll about a
  vertical axis is not a posture.
* ``segment_contact_fraction``: mean share of segments touching the ground over the steady window
  (segments, not nodes: a rolled square on its edge touches with few nodes but one segment).
* ``lift_max_m``: how far the body rose off the ground: the height of its *lowest* segment centre
  above the ground beneath it (the scenario's base surface), max over the run after the first
  ground contact, minus the smallest such clearance after that contact (the resting clearance).
  Parts lifted while another part rests on the ground (a sidewinder's arches) do not count:
  this measures the whole body leaving the ground.
* ``airborne_max_s``: longest time with no segment in contact, after the first contact.
* ``posture_fault`` = 1 when the body flipped (at some sample, the median roll over its segments
  beyond ``ROLL_FAULT_DEG`` on flat ground: terrain plane or slab; one segment twisted over, e.g.
  a flailing head, shows in ``roll_max_deg`` but is not the body on its back) or left the ground entirely (``airborne_max_s`` >
  ``AIRBORNE_FAULT_S``; not in suspended scenarios, whose body never touches ground), else 0.
"""
from __future__ import annotations

import math

import numpy as np

from ..core.series import Series
from ..world.terrain import base_height

ROLL_FAULT_DEG = 90.0  # a cross-section turned beyond 90 degrees lies on its side or back
AIRBORNE_FAULT_S = 0.3  # longer than a free fall of 0.44 m or a hop of 0.11 m
VERTICAL_AXIS_DEG = 20.0  # axis this close to the vertical: roll not defined
FLAT_TERRAINS = ("plane", "slab")
UP = np.array([0.0, 1.0, 0.0])


def roll_angles_deg(rotations: np.ndarray) -> np.ndarray:
    """Roll [deg] in [0, 180] (T, n_seg) of segment frames (T, n_seg, 3, 3) over time; NaN where the
    axis is within ``VERTICAL_AXIS_DEG`` of the vertical.

    The roll of one frame is the angle of its dorsal axis from the vertical projected on the
    cross-section's plane.  One frame cannot tell a segment rolled onto its back from one pitched
    over backward (a head curling back over the body: its axis passes through the vertical and
    then points backward, dorsal side down).  Time tells: the horizontal heading of a segment's
    axis cannot reverse between two samples by turning, only by pitching through the vertical, so
    each such reversal flips the reference by 180 degrees.
    """
    axis = rotations[..., :, 0]
    dorsal = rotations[..., :, 1]
    up_perp = UP - (axis @ UP)[..., None] * axis
    norm = np.linalg.norm(up_perp, axis=-1)
    ok = norm > math.sin(math.radians(VERTICAL_AXIS_DEG))
    up_perp = up_perp / np.where(ok, norm, 1.0)[..., None]
    cos = (dorsal * up_perp).sum(axis=-1)
    sin = (np.cross(up_perp, dorsal) * axis).sum(axis=-1)
    roll = np.degrees(np.arctan2(sin, cos))  # signed, about the body axis
    heading = axis[..., [0, 2]]
    heading = heading / np.maximum(np.linalg.norm(heading, axis=-1), 1e-12)[..., None]
    n_t, n_seg = roll.shape
    flips = np.zeros(n_seg)
    last = np.full((n_seg, 2), np.nan)
    out = np.full((n_t, n_seg), np.nan)
    for k in range(n_t):
        v = ok[k]
        seen = v & np.isfinite(last[:, 0])
        reversed_ = seen & ((heading[k] * last).sum(axis=1) < 0.0)
        flips[reversed_] += 180.0
        last[v] = heading[k][v]
        r = np.mod(roll[k] + flips + 180.0, 360.0) - 180.0
        out[k] = np.where(v, np.abs(r), np.nan)
    return out


def longest_run_s(t: np.ndarray, mask: np.ndarray) -> float:
    """Longest time span [s] over which ``mask`` (T,) holds at consecutive samples t (T,) [s]."""
    best, start = 0.0, None
    for k in range(len(t)):
        if mask[k]:
            start = t[k] if start is None else start
            best = max(best, t[k] - start)
        else:
            start = None
    return float(best)


def ground_clearance(series: Series, scenario, world) -> np.ndarray:
    """Height [m] (T,) of the lowest segment centre above the scenario's base surface beneath it (world: the
    run's ``world.world.World``, its terrain)."""
    c = series.segment_centers
    kind, f = world.terrain
    h = base_height(scenario, kind, f, c[..., 0], c[..., 2])
    return (c[..., 1] - h).min(axis=1)


def posture_metrics(series: Series, scenario, i0: int, i1: int, world) -> dict[str, float]:
    """roll_max_deg, segment_contact_fraction, lift_max_m, airborne_max_s, posture_fault (world: as
    ``ground_clearance``)."""
    nan = float("nan")
    out = {"roll_max_deg": nan, "segment_contact_fraction": nan, "lift_max_m": nan,
           "airborne_max_s": nan, "posture_fault": 0.0}
    body_roll = nan  # the body's roll: median over its segments, max over time
    if series.segment_rotations is not None:
        roll = roll_angles_deg(series.segment_rotations)
        rows = np.isfinite(roll).any(axis=1)
        if rows.any():
            out["roll_max_deg"] = float(np.nanmax(roll))
            body_roll = float(np.nanmedian(roll[rows], axis=1).max())
    contact = series.segment_contact
    if contact is not None and len(contact):
        out["segment_contact_fraction"] = float(contact[i0:i1 + 1].mean())
        touching = contact.any(axis=1)
        if touching.any():
            first = int(np.argmax(touching))
            out["airborne_max_s"] = longest_run_s(series.t[first:], ~touching[first:])
            clear = ground_clearance(series, scenario, world)[first:]
            out["lift_max_m"] = float(clear.max() - clear.min())
    flipped = scenario.terrain in FLAT_TERRAINS and body_roll > ROLL_FAULT_DEG
    airborne = not scenario.suspended and out["airborne_max_s"] > AIRBORNE_FAULT_S
    out["posture_fault"] = 1.0 if (flipped or airborne) else 0.0
    return out
