"""A legged myriapod in a run: what the runner adds when a leg controller drives a segment body.

The body (``bodies/``) and the leg controller (``controllers/myriapod/``) never see each other;
the runner passes observations and actuation between them (``core.protocols``).  This module
holds the two runner-side pieces of a legged run:

* :class:`LeggedMonitor` samples, at the controller's timeline rate, what the gait and behaviour
  metrics need (centre of mass; body, box-corner and leg-tip points against obstacles), and turns
  the controller's recorded timeline into metrics through ``metrics.gait`` and
  ``metrics.behaviour`` after the run;
* :class:`LeggedView` is the body as drawings and the water see it: its scene with the legs and
  antennae drawn on (``bodies.scene.legs_scene``).
"""
from __future__ import annotations

import numpy as np

from ..bodies.scene import Scene, legs_scene
from ..controllers.myriapod.controller import AVOIDANCE, BRAIN_MODE_NAMES, TROPHOTROPISM, MyriapodController
from ..metrics.behaviour import BehaviourSampler
from ..metrics.gait import body_undulation, gait_metrics

BOX_SIGNS = np.array([[(k & 1) * 2 - 1, (k >> 1 & 1) * 2 - 1, (k >> 2 & 1) * 2 - 1] for k in range(8)], float)


class LeggedView:
    """The body with the controller's legs and antennae: ``scene()`` draws all of them; every
    other attribute is the body's."""

    def __init__(self, body, controller: MyriapodController):
        self.body = body
        self.controller = controller
        if controller.antennae is not None:  # antennae on the starting head pose: frame 0 of a scene shows them
            c, R = body.segment_poses()
            controller.antennae.place(c[0], R[0], 0.0)

    def __getattr__(self, name):
        return getattr(self.body, name)

    def scene(self) -> Scene:
        """The segment body's scene plus the legs (``bodies.scene``).

        The controller stores angles, not joint positions: O, M, P come from forward kinematics
        (``kinematics.legs.legs_forward_kinematics``) of its current angles on the segments'
        current poses, so a leg is drawn where its segment is now (a STANCE tip within the
        tracking error of where it was planted).
        """
        scene = self.body.scene()
        c, R = self.body.segment_poses()
        ctrl = self.controller
        scene.legs, scene.leg_states = legs_scene(c, R, ctrl.geom, ctrl.angles, ctrl.states)
        if ctrl.antennae is not None:
            scene.antennae = ctrl.antennae.points.copy()
            scene.antenna_contact = ctrl.antennae.contact.copy()
        return scene


class LeggedMonitor:
    """Samples a legged run at the controller's timeline steps and measures it afterwards."""

    def __init__(self, case, body, controller: MyriapodController):
        self.case = case
        self.body = body
        self.controller = controller
        self._com: list[np.ndarray] = []  # mean segment centre at each timeline sample [m]
        self.behaviour = BehaviourSampler(controller.terr_kind, controller.terr, case.scenario.terrain == "none")
        self.labels: dict[str, str] = {}

    def after_control(self, obs) -> None:
        """Called after every controller step (and after the body took the new support): sample
        when the controller recorded this step in its timeline."""
        if not self.controller.recorded:
            return
        c, R = self.body.segment_poses()
        self.sample(c, R, self.body.segment_centers(), self.controller.tips)

    def sample(self, c: np.ndarray, R: np.ndarray, centres: np.ndarray, tips: np.ndarray) -> None:
        """One timeline sample from the segment poses (c (n, 3) [m], R (n, 3, 3)), the body's centres
        (``segment_centers``) and the leg tips (n_legs, 3) [m] (also fed by ``fused``'s buffered samples)."""
        self._com.append(c.mean(axis=0))
        self.behaviour.sample(centres, self._corners(c, R).reshape(-1, 3), tips, c[0])

    def sample_many(self, c: np.ndarray, R: np.ndarray, centres: np.ndarray, tips: np.ndarray) -> None:
        """k ``sample`` calls at once (c (k, n, 3), R (k, n, 3, 3), centres (k, m, 3), tips (k, n_legs, 3)),
        with the same values (the fused path's replay of a chunk; a row's mean over axis 1 is the
        row's mean over axis 0, checked bitwise by tests/test_fused_walk.py).  The box corners only
        feed the obstacle test: without obstacles they are not computed; with them each row's are
        ``sample``'s expression on that row (the same doubles)."""
        self._com.extend(c.mean(axis=1))
        corners = None
        if self.behaviour.has_obstacles:
            corners = np.stack([self._corners(c[r], R[r]).reshape(-1, 3) for r in range(c.shape[0])]) \
                if c.shape[0] else np.zeros((0, 8 * c.shape[1], 3))
        self.behaviour.sample_many(centres, c[:, 0], corners, tips)

    def _corners(self, c: np.ndarray, R: np.ndarray) -> np.ndarray:
        """(n, 8, 3) [m] corners of boxes of the segments' half extents on the poses c (n, 3), R (n, 3, 3)."""
        return c[:, None, :] + np.einsum("nij,nkj->nki", R, BOX_SIGNS[None] * self.body.segment_half_extents[:, None, :])

    def sample_points(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(segment centres (n, 3), box corners (8 n_seg, 3), leg tips (n_legs, 3)) [m] now.

        Centres: the body's own (rigid and link centres); corners: boxes of each segment's half
        extents on the segment poses (the rigid boxes, or the FEM's stiff blocks).
        """
        body = self.body
        c, R = body.segment_poses()
        corners = (c[:, None, :] + np.einsum("nij,nkj->nki", R, BOX_SIGNS[None] * body.segment_half_extents[:, None, :]))
        return body.segment_centers(), corners.reshape(-1, 3), self.controller.tips

    # ------------------------------------------------------------------ after the run
    def leg_timeline(self):
        """(t (T,), states (T, n_legs) int8, tips (T, n_legs, 3)) of the run."""
        return self.controller.timeline()

    def metrics(self) -> dict[str, float]:
        """Gait (``metrics.gait``), walking, tracking and behaviour metrics of the run."""
        out: dict[str, float] = {}
        t, states, tips = self.leg_timeline()
        c = self.controller
        length = float(self.body.body_length_m)
        if len(t) > 2:
            # measure the gait once walking has settled: one second after ADJUSTMENT ended
            warm = (c.t_walk if np.isfinite(c.t_walk) else t[0]) + 1.0 - t[0]
            m, labels = gait_metrics(t, states, tips=tips, com=np.array(self._com[:len(t)]),
                                     body_length=length, warmup_s=warm)
            out.update({k: v for k, v in m.items() if isinstance(v, float)})
            self.labels = dict(labels)
        if c.heading_err_n:
            out["heading_error_deg"] = float(np.degrees(c.heading_err_sum / c.heading_err_n))
        if len(c.timeline_centers) > 2:
            out["body_undulation_amp_bl"] = body_undulation(np.stack(c.timeline_centers)) / length
        out["time_to_walk_s"] = c.t_walk
        out["touch_fraction_at_walk"] = c.touch_fraction_at_walk
        out["tracking_error_mean_m"] = c.tracking_sq_sum / c.tracking_n if c.tracking_n else float("nan")
        out["brain_mode_final"] = float(c.brain)
        out.update(c.leg_metrics())
        out.update(self.behaviour.metrics())
        out.update(c.food.metrics())
        out["obstacle_contacts"] = float(c.antennae.contact_events) if c.antennae is not None else 0.0
        steps = max(int(c.brain_steps.sum()), 1)
        for mode, name in ((AVOIDANCE, "avoidance"), (TROPHOTROPISM, "trophotropism")):
            out[f"brain_{name}_fraction"] = float(c.brain_steps[mode]) / steps
        return out

    def labels_dict(self) -> dict[str, str]:
        labels = dict(self.labels)
        labels["brain_mode_final"] = BRAIN_MODE_NAMES[self.controller.brain]
        return labels

    def extra(self) -> dict:
        """What the recorder, store and report keep of a legged run."""
        return {"leg_timeline": self.leg_timeline(), "labels": self.labels_dict(),
                "brain_timeline": self.controller.brain_timeline()}
