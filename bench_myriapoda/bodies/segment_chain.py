"""The layout shared by bodies of rigid segments joined by deformable links.

The hybrid body (FEM links) and the legged mass-spring body (spring-cube links)
lay a creature out the same way: ``n_rigid`` boxes along -x from the head, one
link between each pair of neighbours.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError
from ..core.protocols import LEGS, SEGMENTS

DERIVED = -1.0  # the body configs' "derive from the creature" value

@dataclass(frozen=True)
class SegmentChainLayout:
    """Resolved sizes [m] of a chain of rigid segments and links.

    ``cells``: how a link is discretized -- (nx, ny, nz) cells for an FEM link,
    or the number of spring cubes along a spring link.
    """

    n_rigid: int
    rigid_length: float
    rigid_width: float
    rigid_height: float
    link_length: float
    link_width: float
    link_height: float
    cells: tuple | int

    @property
    def pitch(self) -> float:
        """Distance between consecutive rigid centres [m]."""
        return self.rigid_length + self.link_length

    @property
    def body_length(self) -> float:
        """Head front face to tail back face [m]."""
        return self.n_rigid * self.rigid_length + (self.n_rigid - 1) * self.link_length


def chain_sizes(cfg, creature) -> dict[str, float]:
    """The rigid boxes' and links' sizes [m] of a chain config (-1: derived from the creature, links half a
    segment long), unchecked: lr, wr, hr (rigid length, width, height), ll, wl, hl (link)."""
    def pick(value: float, default: float) -> float:
        return default if value == DERIVED else value
    lr = pick(cfg.rigid_length_m, creature.segment_length_m)
    wr = pick(cfg.rigid_width_m, creature.width_m)
    hr = pick(cfg.rigid_height_m, creature.height_m)
    return dict(lr=lr, wr=wr, hr=hr, ll=pick(cfg.link_length_m, 0.5 * lr), wl=pick(cfg.link_width_m, wr),
                hl=pick(cfg.link_height_m, hr))


SIZE_KEYS = {"lr": "rigid_length_m", "wr": "rigid_width_m", "hr": "rigid_height_m", "ll": "link_length_m",
             "wl": "link_width_m", "hl": "link_height_m"}


def check_chain_segments(case, source: str, what: str) -> None:
    """A chain of rigid segments needs two of them (one link): ``InputError`` naming ``source`` otherwise.
    ``what``: the body in words for the message (``"a hybrid body"``)."""
    if case.creature.segments < 2:
        raise InputError(source, "creature.segments", f"{case.creature.segments}: {what} needs >= 2 segments "
                                                      "(one link)")


def check_legged_gait(case, source: str, what: str) -> None:
    """A legged chain whose only actuation is its legs (``LeggedSegments``: no muscle segments) cannot run a
    gait that needs muscles (a worm given legs with ``--set creature.legs_per_segment=2`` keeps its rectilinear
    gait): ``InputError`` naming ``source`` and the key, before anything is built."""
    from ..core import registry

    missing = registry.GAITS[case.gait.name].requires - LeggedSegments.capabilities
    if missing:
        raise InputError(source, "creature.legs_per_segment",
                         f"{case.creature.legs_per_segment}: {what} has legs and no {', '.join(sorted(missing))}, "
                         f"which gait {case.gait.name!r} needs; unsupported combination (give 0 legs, or a "
                         "gait the legs drive such as leg-wave)")


def check_link_fit(case, source: str) -> None:
    """Every size of the chain positive and the link's cross-section on the rigid face (``InputError``)."""
    lay = chain_sizes(case.body, case.creature)
    for key, v in lay.items():
        if not v > 0:
            raise InputError(source, f"body.{SIZE_KEYS[key]}", f"{v}: must be > 0 (or -1: derived from the "
                                                               "creature)")
    if lay["wl"] > lay["wr"]:
        raise InputError(source, "body.link_width_m", f"{lay['wl']} m is wider than the rigid face "
                                                      f"({lay['wr']} m); must be <= it")
    if lay["hl"] > lay["hr"]:
        raise InputError(source, "body.link_height_m", f"{lay['hl']} m is taller than the rigid face "
                                                       f"({lay['hr']} m); must be <= it")


@dataclass(frozen=True)
class CouplingScratch:
    """Work arrays of ``rigid_chain.rigid_segments_step`` (Sec. 3 steps 2-3), allocated once per body.

    f_att, x_att, x_pred (n_fixed, 3) and residual (n_fixed,): attached nodes' forces, positions,
    predicted positions, coupling residuals; spine (n_rigid - 1, 3); Rb (n_rigid, 3, 3) box
    rotations; the rest is the rigid contact solver's per-box scratch (``rigid_kernels``).
    """

    f_att: np.ndarray
    x_att: np.ndarray
    x_pred: np.ndarray
    residual: np.ndarray
    spine: np.ndarray
    Rb: np.ndarray
    R: np.ndarray
    Iw: np.ndarray
    corner_of: np.ndarray
    lin: np.ndarray
    ang: np.ndarray
    resp: np.ndarray
    kn: np.ndarray
    kt: np.ndarray
    target: np.ndarray
    lam: np.ndarray
    qtmp: np.ndarray

    @classmethod
    def new(cls, n_fixed: int, n_rigid: int, n_corners: int) -> "CouplingScratch":
        z = np.zeros
        return cls(f_att=z((n_fixed, 3)), x_att=z((n_fixed, 3)), x_pred=z((n_fixed, 3)), residual=z(n_fixed),
                   spine=z((n_rigid - 1, 3)), Rb=z((n_rigid, 3, 3)), R=z((3, 3)), Iw=z((3, 3)),
                   corner_of=z(n_corners, dtype=np.int64), lin=z((n_corners, 3, 3)), ang=z((n_corners, 3, 3)),
                   resp=z((n_corners, 3, 3)), kn=z(n_corners), kt=z((n_corners, 6)), target=z(n_corners),
                   lam=z((n_corners, 3)), qtmp=z(4))


class SupportedSegments:
    """The ``SEGMENTS`` capability of a body whose segments the legs carry (paper Sec. 4.1).

    A subclass provides ``segment_poses() -> (c (n, 3) [m], R (n, 3, 3))``,
    ``segment_velocities() -> (n, 3) [m/s]``, ``set_support(kinematic, c_T, R_T, dt)``,
    ``segment_half_extents`` (n, 3) [m], ``dt`` [s], ``terr_kind``/``terr`` and ``fric``.
    """

    def apply_support(self, act) -> None:
        """Carry the supported segments of ``act`` (support_kinematic, support_c, support_R) this step."""
        if act.support_new:
            if getattr(self, "dynamic_stance", False):  # the legs push (bodies.dynamic_stance)
                self.push_support(act.support_kinematic, act.support_c, act.support_R, act.support_states,
                                  act.support_tips)
            else:
                self.set_support(act.support_kinematic, act.support_c, act.support_R, self.dt)
            act.support_new = False

    def sense(self, obs, t: float) -> None:
        """Control fields of ``obs`` (``core.protocols.Observation``) from the segments' poses."""
        c, R = self.segment_poses()
        obs.t = t
        obs.seg_pos, obs.seg_rot = c, R
        obs.seg_vel = self.segment_velocities()
        obs.seg_half = self.segment_half_extents

    def _observe_segments(self, obs, t: float):
        """Fill the control fields and ``seg_contact`` (a box corner within the contact distance)."""
        from .friction_kernels import CONTACT_DISTANCE
        from .rigid import CORNER_SIGNS
        from .segment_frames import groups_touching
        self.sense(obs, t)
        c, R = obs.seg_pos, obs.seg_rot
        corners = (c[:, None, :] + np.einsum("nij,nkj->nki", R, CORNER_SIGNS[None] * obs.seg_half[:, None, :])).reshape(-1, 3)
        obs.seg_contact = np.zeros(len(c), dtype=bool)
        groups_touching(corners, 8, self.terr_kind, self.terr, self.fric[CONTACT_DISTANCE], obs.seg_contact)
        return obs


class LeggedSegments(SupportedSegments):
    """A body whose only actuation is its legs' support of its segments (the legged mass-spring and FEM
    chains): ``SEGMENTS`` and ``LEGS``, no muscle segments."""

    capabilities = frozenset({SEGMENTS, LEGS})
    n_muscle_segments = 0
    muscle_s = np.zeros(0)
