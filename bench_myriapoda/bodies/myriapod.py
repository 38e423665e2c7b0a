"""A legged myriapod: a segment body driven by the decentralized leg controller.

Any body model that exposes the segment interface (``segment_poses``,
``set_support``) plus the runner's body protocol can carry legs: the
controller (``controllers/myriapod/controller.py``) runs the paper's update
order every time step, then the body takes one dynamic step.  So the three
body models of one centipede share the controller code and the creature file.
"""
from __future__ import annotations

import numpy as np

from ..controllers.myriapod.controller import (
    AVOIDANCE,
    BRAIN_MODE_NAMES,
    TROPHOTROPISM,
    MyriapodController,
)
from ..metrics.behaviour import BehaviourSampler
from ..metrics.gait import gait_metrics
from .observation import Observation
from .scene import Scene, legs_scene


def body_undulation(centers: np.ndarray) -> float:
    """Mean half-width [m] of the segment centres' sideways spread about the head-tail line.

    centers: (T, n_seg, 3) [m].  At each sample, the horizontal distance of every
    centre from the line through the head and tail centres (signed, to the
    right); half of max - min, averaged over the samples.
    """
    a = centers[:, 0, [0, 2]]
    b = centers[:, -1, [0, 2]]
    d = a - b
    n = np.stack([-d[:, 1], d[:, 0]], axis=1) / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-12)
    off = np.einsum("tij,tj->ti", centers[:, :, [0, 2]] - b[:, None, :], n)
    return float(np.mean(0.5 * (off.max(axis=1) - off.min(axis=1))))


class BodyMyriapod:
    """The runner's body protocol for a legged creature; ``segments`` does the dynamics."""

    def __init__(self, case, segments, segment_pitch_m: float):
        self.case = case
        self.segments = segments
        self.name = segments.name
        self.controller = MyriapodController(case, len(segments.segment_poses()[0]), segment_pitch_m)
        self._com: list[np.ndarray] = []  # mean segment centre at each timeline sample [m]
        ctrl = self.controller
        self.behaviour = BehaviourSampler(ctrl.terr_kind, ctrl.terr, case.scenario.terrain == "none")
        cr = case.creature
        self._half = 0.5 * np.array([cr.segment_length_m, cr.height_m, cr.width_m])  # boxes of bodies without any

    # ------------------------------------------------------------------ stepping
    def advance(self, t0: float, n_steps: int) -> tuple[int, int]:
        """Controller then one dynamic step, ``n_steps`` times (Sec. 6 order); stop at a blow-up."""
        dt = self.case.dt
        ctrl = self.controller
        for k in range(n_steps):
            t = t0 + k * dt
            recording = ctrl._step % ctrl.record_every == 0
            ctrl.step(self.segments, t)
            if recording:
                self._com.append(self.segments.segment_poses()[0].mean(axis=0))
                self._sample_behaviour()
            done, status = self.segments.advance(t, 1)
            if status != 0:
                return k + done, status
            self.controller.record_tracking(self.segments.segment_poses()[0])
        return n_steps, 0

    def sample_points(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(segment centres (n, 3), rigid box corners (8 n_rigid, 3), leg tips (n_legs, 3)) [m] now.

        Centres: the body's own (rigid and link centres) when it has them; corners:
        the body's rigid boxes, or boxes of the creature's segment size on the
        segment poses for a body without any (the FEM's stiff blocks).
        """
        seg = self.segments
        c, R = seg.segment_poses()
        centres = seg.segment_centers() if hasattr(seg, "segment_centers") else c
        if hasattr(seg, "box_corners"):
            corners = seg.box_corners()
        else:
            signs = np.array([[(k & 1) * 2 - 1, (k >> 1 & 1) * 2 - 1, (k >> 2 & 1) * 2 - 1] for k in range(8)], float)
            corners = (c[:, None, :] + np.einsum("nij,kj->nki", R, signs * self._half)).reshape(-1, 3)
        return centres, corners, self.controller.tips

    def _sample_behaviour(self) -> None:
        centres, corners, tips = self.sample_points()
        self.behaviour.sample(centres, corners, tips, self.segments.segment_poses()[0][0])

    def compile(self) -> None:
        """Compile the body's kernels and the controller's (one step of a throw-away copy)."""
        import copy
        self.segments.compile()
        saved = self.segments._state()
        copy.deepcopy(self.controller).step(self.segments, 0.0)
        self.segments._restore(saved)

    def status_text(self, code: int) -> str:
        return self.segments.status_text(code)

    # ------------------------------------------------------------------ observation and metrics
    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        return self.segments.observe(t, with_nodes)

    def energy(self, t: float):
        return self.segments.energy(t)

    def scene(self) -> Scene:
        """The segment body's scene plus the legs (``bodies.scene``).

        The controller stores angles, not joint positions: O, M, P come from
        forward kinematics (``legs.legs_forward_kinematics``) of its current angles
        on the segments' current poses, so a leg is drawn where its segment is now
        (a STANCE tip within the tracking error of where it was planted).
        """
        scene = self.segments.scene()
        c, R = self.segments.segment_poses()
        ctrl = self.controller
        scene.legs, scene.leg_states = legs_scene(c, R, ctrl.geom, ctrl.angles, ctrl.states)
        if ctrl.antennae is not None:
            scene.antennae = ctrl.antennae.points.copy()
            scene.antenna_contact = ctrl.antennae.contact.copy()
        return scene

    @property
    def body_length_m(self) -> float:
        return float(getattr(self.segments, "body_length_m", self.case.creature.body_length_m))

    def leg_timeline(self):
        """(t (T,), states (T, n_legs) int8, tips (T, n_legs, 3)) of the run so far."""
        return self.controller.timeline()

    def extra_metrics(self) -> dict[str, float]:
        out = dict(self.segments.extra_metrics())
        t, states, tips = self.leg_timeline()
        c = self.controller
        if len(t) > 2:
            # measure the gait once walking has settled: one second after ADJUSTMENT ended
            warm = (c.t_walk if np.isfinite(c.t_walk) else t[0]) + 1.0 - t[0]
            m, labels = gait_metrics(t, states, tips=tips, com=np.array(self._com[:len(t)]),
                                     body_length=self.body_length_m, warmup_s=warm)
            out.update({k: v for k, v in m.items() if isinstance(v, float)})
            self.labels = labels
        if c.heading_err_n:
            out["heading_error_deg"] = float(np.degrees(c.heading_err_sum / c.heading_err_n))
        if len(c.timeline_centers) > 2:
            out["body_undulation_amp_bl"] = body_undulation(np.stack(c.timeline_centers)) / self.body_length_m
        out["time_to_walk_s"] = c.t_walk
        out["touch_fraction_at_walk"] = c.touch_fraction_at_walk
        out["tracking_error_mean_m"] = c.tracking_sq_sum / c.tracking_n if c.tracking_n else float("nan")
        out["brain_mode_final"] = float(c.brain)
        out.update(c.leg_metrics())
        out.update(self.behaviour_metrics())
        return out

    def behaviour_metrics(self) -> dict[str, float]:
        """Food, antenna contacts, obstacle penetration, head path, clearance (``metrics.behaviour``)."""
        c = self.controller
        out = dict(self.behaviour.metrics())
        out.update(c.food.metrics())
        out["obstacle_contacts"] = float(c.antennae.contact_events) if c.antennae is not None else 0.0
        steps = max(int(c.brain_steps.sum()), 1)
        for mode, name in ((AVOIDANCE, "avoidance"), (TROPHOTROPISM, "trophotropism")):
            out[f"brain_{name}_fraction"] = float(c.brain_steps[mode]) / steps
        return out

    def labels_dict(self) -> dict[str, str]:
        labels = dict(getattr(self, "labels", {}))
        labels["brain_mode_final"] = BRAIN_MODE_NAMES[self.controller.brain]
        return labels

    def contact_fraction_mean(self) -> float:
        return self.segments.contact_fraction_mean()

    def max_penetration(self) -> float:
        return self.segments.max_penetration()
