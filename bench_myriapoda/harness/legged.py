"""A legged creature in a run: what the runner adds when a leg controller drives a segment body.

The body (``bodies/``) and the leg controller (``controllers/``) never see each other;
the runner passes observations and actuation between them (``core.protocols``).  This module
holds the two runner-side pieces of a legged run; of the controller it reads only what
``core.leg_timeline.LeggedController`` declares (its ``LegTimeline``, ``LegsPose`` and
``LeggedSummary``), so any controller that fills those records is measured and drawn alike:

* :class:`LeggedMonitor` samples, at the controller's timeline rate, what the gait and behaviour
  metrics need (centre of mass; body, box-corner and leg-tip points against obstacles), and turns
  the controller's recorded timeline into metrics through ``metrics.gait`` and
  ``metrics.behaviour`` after the run;
* :class:`LeggedView` is the body as drawings and the water see it: its scene with the legs and
  antennae drawn on (``bodies.scene.legs_scene``).
"""
from __future__ import annotations

import numpy as np

from ..bodies.legged_chunk import LeggedPackOps
from ..bodies.scene import Scene, legs_scene
from ..core.leg_timeline import LeggedController
from ..metrics.behaviour import BehaviourSampler
from ..bodies.dynamic_stance import per_stride_and_cost
from ..core.leg_timeline import STANCE
from ..metrics.gait import body_undulation, gait_metrics
from ..metrics.undulation import undulation_metrics

BOX_SIGNS = np.array([[(k & 1) * 2 - 1, (k >> 1 & 1) * 2 - 1, (k >> 2 & 1) * 2 - 1] for k in range(8)], float)


class LeggedView:
    """The body with the controller's legs and antennae: ``scene()`` draws all of them; every
    other attribute is the body's."""

    def __init__(self, body, controller: LeggedController):
        self.body = body
        self.controller = controller
        c, R = body.segment_poses()
        controller.place_on(c, R)  # antennae on the starting head pose: frame 0 of a scene shows them

    def __getattr__(self, name):
        return getattr(self.body, name)

    def scene(self) -> Scene:
        """The segment body's scene plus the legs (``bodies.scene``).

        The controller gives angles, not joint positions (``LegsPose``): O, M, P come from forward
        kinematics (``kinematics.legs.legs_forward_kinematics``) of its current angles on the segments'
        current poses, so a leg is drawn where its segment is now (a STANCE tip within the
        tracking error of where it was planted).
        """
        scene = self.body.scene()
        c, R = self.body.segment_poses()
        pose = self.controller.legs_pose()
        scene.legs, scene.leg_states = legs_scene(c, R, pose.geom, pose.angles, pose.states)
        if pose.antenna_points is not None:
            scene.antennae = pose.antenna_points
            scene.antenna_contact = pose.antenna_contact
        return scene


class LeggedMonitor:
    """Samples a legged run at the controller's timeline steps and measures it afterwards."""

    def __init__(self, case, body, controller: LeggedController, terrain: tuple[int, np.ndarray]):
        """``terrain``: (kind, f) of the run's terrain (``world.world.World.terrain``), which the
        behaviour metrics sample against."""
        self.case = case
        self.body = body
        self.timeline = controller.leg_timeline
        self.controller = controller
        self._com: list[np.ndarray] = []  # mean segment centre at each timeline sample [m]
        self.behaviour = BehaviourSampler(terrain[0], terrain[1], case.scenario.terrain == "none")
        self.labels: dict[str, str] = {}

    def after_control(self, obs) -> None:
        """Called after every controller step (and after the body took the new support): sample
        when the controller recorded this step in its timeline (the timeline has a row more than
        this monitor has samples); the leg tips are that row's."""
        if len(self.timeline) == len(self._com):
            return
        if isinstance(self.body, LeggedPackOps):  # the body's registered sample, which the fused walk runs
            c, R, centres = self.body.legged_sample()
        else:
            c, R = self.body.segment_poses()
            centres = self.body.segment_centers()
        self.sample(c, R, centres, self.timeline.tips[-1])

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

    # ------------------------------------------------------------------ after the run
    def leg_timeline(self):
        """(t (T,), states (T, n_legs) int8, tips (T, n_legs, 3)) of the run."""
        return self.timeline.legs()

    def gait_window_start(self, t0: float) -> float:
        """When the gait is measured from [s]: once walking has settled, one second after it started
        (``LeggedSummary.t_walk_s``), or one second after ``t0`` [s] when it never started."""
        t_walk = self.controller.summary().t_walk_s
        return (t_walk if np.isfinite(t_walk) else t0) + 1.0

    def metrics(self) -> dict[str, float]:
        """Gait (``metrics.gait``), walking, tracking and behaviour metrics of the run, and the controller's
        own (``LeggedSummary.metrics``)."""
        out: dict[str, float] = {}
        t, states, tips = self.leg_timeline()
        run = self.controller.summary()
        length = float(self.body.body_length_m)
        if len(t) > 2:
            warm = self.gait_window_start(t[0]) - t[0]
            m, labels = gait_metrics(t, states, tips=tips, com=np.array(self._com[:len(t)]),
                                     body_length=length, warmup_s=warm)
            out.update({k: v for k, v in m.items() if isinstance(v, float)})
            self.labels = dict(labels)
        if run.heading_error_deg is not None:
            out["heading_error_deg"] = run.heading_error_deg
        if len(self.timeline) > 2:
            out["body_undulation_amp_bl"] = body_undulation(self.timeline.centre_array()) / length
        if len(t) > 2:
            out.update(self._emergent(t, states, length, out.get("stride_frequency_hz", float("nan"))))
        out["time_to_walk_s"] = run.t_walk_s
        out["touch_fraction_at_walk"] = run.touch_fraction_at_walk
        out["tracking_error_mean_m"] = run.tracking_error_mean_m
        out["brain_mode_final"] = float(run.mode_final)
        out.update(self.behaviour.metrics())
        out.update(run.metrics)
        for name, fraction in run.mode_fractions.items():
            out[f"brain_{name}_fraction"] = fraction
        return out

    def _emergent(self, t: np.ndarray, states: np.ndarray, length: float, stride_hz: float) -> dict[str, float]:
        """The body's lateral undulation over the gait window (``metrics.undulation``; the head's left leg's
        stance onsets for its phase), and in dynamic stance the feet's slip per stride and the legs' cost of
        transport (``bodies.dynamic_stance.per_stride_and_cost``)."""
        i0 = int(np.searchsorted(t, self.gait_window_start(t[0])))
        out: dict[str, float] = {}
        if len(t) - i0 >= 8:
            leg0 = states[i0:, 0] == STANCE
            onsets = t[i0:][1:][leg0[1:] & ~leg0[:-1]]
            out.update(undulation_metrics(t[i0:], self.timeline.centre_array()[i0:], length, onsets))
        stats = getattr(self.body, "stance_statistics", lambda: {})()
        if stats:
            com = np.array(self._com[:len(t)])
            dist = float(np.linalg.norm((com[-1] - com[0])[[0, 2]]))
            duration = float(t[-1] - t[0])
            strides = stride_hz * duration * states.shape[1] if np.isfinite(stride_hz) else 0.0
            weight = float(getattr(self.body, "total_mass", 0.0)) * float(self.case.scenario.gravity_m_s2)
            out.update(per_stride_and_cost(stats, weight, dist, strides))
        return out

    def labels_dict(self) -> dict[str, str]:
        labels = dict(self.labels)
        run = self.controller.summary()
        labels["brain_mode_final"] = run.mode_names[run.mode_final]
        return labels

    def extra(self) -> dict:
        """What the recorder, store and report keep of a legged run."""
        return {"leg_timeline": self.leg_timeline(), "labels": self.labels_dict(),
                "brain_timeline": self.timeline.mode_array()}
