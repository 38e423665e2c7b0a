"""Rigid boxes: the exoskeletal segments of the myriapod body (paper Sec. 3).

Orchestration only: ``RigidBoxes`` owns the state arrays and calls the numba
kernels of ``rigid_kernels`` (which document the integrator and contact model).
The deformable segments push on these bodies through ``apply_forces_at_points``
(Sec. 3, step 2) and read the attached nodes back with ``points_to_world``
(Sec. 3, step 3); a supported segment is moved by the controller with
``set_kinematic`` and ``set_pose`` (Sec. 4.1).

World frame: y up, gravity along -y, SI units.  Quaternions are (w, x, y, z).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple

import numpy as np

from bench_myriapoda.bodies import rigid_kernels as rk
from bench_myriapoda.core.kernel_records import plain
from bench_myriapoda.world.terrain_kernels import N_TERRAIN_PARAMS, PLANE

GRAVITY = (0.0, -9.81, 0.0)  # [m/s^2]

STATUS_OK = rk.STATUS_OK
STATUS_NONFINITE = rk.STATUS_NONFINITE
STATUS_RUNAWAY = rk.STATUS_RUNAWAY


@dataclass(frozen=True)
class ContactSettings:
    """Terrain contact parameters for ``RigidBoxes.advance``.

    friction: Coulomb coefficient mu [-].  restitution: e in [0, 1] [-].
    bounce_threshold [m/s]: impacts slower than this do not bounce; it must
    exceed g dt (the approach speed a resting box gains per step).
    velocity_iterations: most contact-impulse sweeps per step; the sweeps stop
    early once one changes the velocity by at most velocity_tolerance [m/s].
    position_iterations: most penetration-projection sweeps per step.
    position_beta [-] in (0, 1]: fraction of the penetration beyond ``slop`` [m]
    removed per position sweep.
    """

    friction: float = 0.5
    restitution: float = 0.0
    bounce_threshold: float = 0.05
    velocity_iterations: int = 10
    velocity_tolerance: float = 1e-9
    position_iterations: int = 4
    position_beta: float = 0.2
    slop: float = 1e-5

    @cached_property
    def kernel_params(self) -> tuple:
        """These settings as ``rigid_kernels.ContactParams``, a plain tuple (``core.kernel_records``: the call's
        cost), built once (the settings are frozen)."""
        return plain(rk.ContactParams(mu=float(self.friction), restitution=float(self.restitution),
                                      bounce_threshold=float(self.bounce_threshold),
                                      n_velocity_iterations=int(self.velocity_iterations),
                                      velocity_tolerance=float(self.velocity_tolerance),
                                      n_position_iterations=int(self.position_iterations),
                                      beta=float(self.position_beta), slop=float(self.slop)))

    def __post_init__(self) -> None:
        checks = {
            "friction": self.friction >= 0.0,
            "restitution": 0.0 <= self.restitution <= 1.0,
            "bounce_threshold": self.bounce_threshold >= 0.0,
            "velocity_iterations": self.velocity_iterations >= 1,
            "velocity_tolerance": self.velocity_tolerance >= 0.0,
            "position_iterations": self.position_iterations >= 0,
            "position_beta": 0.0 < self.position_beta <= 1.0,
            "slop": self.slop >= 0.0,
        }
        for name, ok in checks.items():
            if not ok:
                raise ValueError(f"ContactSettings.{name} out of range: {getattr(self, name)!r}")


class RigidEnergy(NamedTuple):
    """Energy per body [J], each (n,)."""

    kinetic_linear: np.ndarray
    kinetic_rotational: np.ndarray
    potential: np.ndarray

    def total(self) -> float:
        return float(np.sum(self.kinetic_linear + self.kinetic_rotational + self.potential))


def _vec3(x, name: str) -> np.ndarray:
    a = np.asarray(x, dtype=np.float64).reshape(-1)
    if a.shape != (3,):
        raise ValueError(f"{name} must have 3 components, got shape {np.shape(x)}")
    return a


# Corner k of a box sits at CORNER_SIGNS[k] * half extents in its body frame (bit 0: +x, bit 1: +y, bit 2: +z).
CORNER_SIGNS = np.array([[(k & 1) * 2 - 1, (k >> 1 & 1) * 2 - 1, (k >> 2 & 1) * 2 - 1] for k in range(8)], float)


class RigidBoxes:
    """n solid uniform boxes with rigid-body dynamics and terrain contact.

    Public state arrays (float64, C-contiguous; edit through the methods, or in
    place when you know what you do):
    c (n, 3) [m], q (n, 4) unit (w, x, y, z), v (n, 3) [m/s], w (n, 3) [rad/s]
    world frame, mass (n,) [kg], inertia_body (n, 3) [kg m^2] principal moments,
    half_extents (n, 3) [m], force (n, 3) [N] and torque (n, 3) [N m] external
    load accumulators (about the centre, world frame), kinematic (n,) bool,
    impulse_cache (n, 8, 3) [N s] last step's contact impulses per corner
    (warm start of the contact solver; part of the state for bitwise restarts).
    """

    def __init__(self, half_extents, masses):
        """Boxes at the origin, identity orientation, at rest, all dynamic.

        half_extents: (n, 3) [m], > 0.  masses: (n,) [kg], > 0.
        """
        h = np.ascontiguousarray(np.array(half_extents, dtype=np.float64).reshape(-1, 3))
        m = np.ascontiguousarray(np.array(masses, dtype=np.float64).reshape(-1))
        if m.shape[0] != h.shape[0]:
            raise ValueError(f"{h.shape[0]} boxes but {m.shape[0]} masses")
        if np.any(h <= 0.0) or np.any(m <= 0.0):
            raise ValueError("half extents and masses must be positive")
        n = h.shape[0]
        self.half_extents = h
        self.mass = m
        self.inertia_body = np.empty((n, 3))
        rk.box_inertia(m, h, self.inertia_body)
        self.c = np.zeros((n, 3))
        self.q = np.zeros((n, 4))
        self.q[:, 0] = 1.0
        self.v = np.zeros((n, 3))
        self.w = np.zeros((n, 3))
        self.force = np.zeros((n, 3))
        self.torque = np.zeros((n, 3))
        self.kinematic = np.zeros(n, dtype=np.bool_)
        self.impulse_cache = np.zeros((n, rk.N_CORNERS, 3))

    @property
    def n(self) -> int:
        return self.c.shape[0]

    # -- time stepping ------------------------------------------------------

    def advance(self, n_steps: int, dt: float, gravity=GRAVITY, terrain_kind: int = PLANE,
                terrain_params=None, contact: ContactSettings | None = None,
                max_speed: float = 100.0, clear_forces: bool = True) -> tuple[int, int]:
        """Run n_steps steps of dt [s] inside numba; returns (n_done, status).

        gravity: (3,) [m/s^2].  terrain_kind / terrain_params: see
        ``world.terrain_kernels`` (default: the plane y = 0); a vector of at least
        N_TERRAIN_PARAMS values (header and data blocks) is used as is, a shorter
        one is zero-padded to a header.  The force and
        torque accumulators act as constant loads during the call and are
        zeroed afterwards when ``clear_forces``.  status is STATUS_OK (0), or
        STATUS_NONFINITE (1) / STATUS_RUNAWAY (2) after n_done steps, the
        last of which produced the bad state (a point faster than max_speed [m/s]).
        """
        if n_steps < 0 or not dt > 0.0:
            raise ValueError(f"need n_steps >= 0 and dt > 0, got {n_steps}, {dt}")
        contact = ContactSettings() if contact is None else contact
        f = np.zeros(N_TERRAIN_PARAMS)
        if terrain_params is not None:
            p = np.asarray(terrain_params, dtype=np.float64).reshape(-1)
            if p.shape[0] >= N_TERRAIN_PARAMS:  # a full vector (header + data blocks): used as is
                f = np.ascontiguousarray(p)
            else:  # a short header: zero-padded
                f[: p.shape[0]] = p
        n_done, status = rk.advance(self._box_arrays, self.kinematic, int(n_steps), float(dt),
                                    _vec3(gravity, "gravity"), int(terrain_kind), f, contact.kernel_params,
                                    float(max_speed))
        if clear_forces:
            self.clear_forces()
        return int(n_done), int(status)

    # -- loads ----------------------------------------------------------------

    @cached_property
    def _box_arrays(self) -> tuple:
        """``rigid_kernels.BoxArrays`` of the boxes as a plain tuple (``core.kernel_records``: the call's cost),
        built once by field name: it refers to the boxes' own arrays, which are changed in place only."""
        return plain(rk.BoxArrays(c=self.c, q=self.q, v=self.v, w=self.w, mass=self.mass,
                                  inertia_body=self.inertia_body, half_extents=self.half_extents, force=self.force,
                                  torque=self.torque, impulse_cache=self.impulse_cache))

    def clear_forces(self) -> None:
        """Zero the force and torque accumulators."""
        self.force[:] = 0.0
        self.torque[:] = 0.0

    def apply_force_at_point(self, i: int, force, point) -> None:
        """Accumulate force (3,) [N] at world point (3,) [m] on body i; torque gains r x F."""
        self.apply_forces_at_points(np.array([i]), np.asarray(force, float).reshape(1, 3),
                                    np.asarray(point, float).reshape(1, 3))

    def apply_forces_at_points(self, body, forces, points) -> None:
        """Accumulate forces (k, 3) [N] at world points (k, 3) [m] on bodies body (k,) int."""
        body = np.ascontiguousarray(body, dtype=np.int64).reshape(-1)
        forces = np.ascontiguousarray(forces, dtype=np.float64).reshape(-1, 3)
        points = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3)
        if not (body.shape[0] == forces.shape[0] == points.shape[0]):
            raise ValueError("body, forces and points must have the same length")
        if body.size and (body.min() < 0 or body.max() >= self.n):
            raise IndexError(f"body index out of range 0..{self.n - 1}")
        rk.accumulate_point_forces(body, points, forces, self.c, self.force, self.torque)

    # -- pose -------------------------------------------------------------------

    def set_kinematic(self, i: int, flag: bool) -> None:
        """A kinematic body is not integrated; its pose and velocities come from set_pose."""
        self.kinematic[i] = bool(flag)

    def set_pose(self, i: int, c=None, q=None, v=None, w=None) -> None:
        """Overwrite body i's centre c [m], orientation q (normalized here), v [m/s], w [rad/s].

        A teleported body's cached contact impulses no longer apply: they are reset.
        """
        self.impulse_cache[i] = 0.0
        if c is not None:
            self.c[i] = _vec3(c, "c")
        if q is not None:
            qq = np.asarray(q, dtype=np.float64).reshape(-1)
            nq = np.linalg.norm(qq)
            if qq.shape != (4,) or nq == 0.0:
                raise ValueError(f"q must be a non-zero (w, x, y, z), got {q!r}")
            self.q[i] = qq / nq
        if v is not None:
            self.v[i] = _vec3(v, "v")
        if w is not None:
            self.w[i] = _vec3(w, "w")

    def rotation_matrices(self) -> np.ndarray:
        """(n, 3, 3) rotation matrices, body to world."""
        out = np.empty((self.n, 3, 3))
        rk.quat_to_matrix(self.q, out)
        return out

    def chain_ends(self, R: np.ndarray, length: float) -> tuple[np.ndarray, np.ndarray]:
        """(head, tail) (3,) [m] of a chain of boxes along their x axes, each ``length`` [m] long: the centre of
        the first box's front face and of the last box's back face; R: ``rotation_matrices()``."""
        half_len = 0.5 * length
        return self.c[0] + R[0][:, 0] * half_len, self.c[-1] - R[-1][:, 0] * half_len

    def corners(self) -> np.ndarray:
        """(n * 8, 3) [m] the boxes' corners, corner k of a box at ``CORNER_SIGNS[k]``."""
        local = CORNER_SIGNS[None, :, :] * self.half_extents[:, None, :]
        return (self.c[:, None, :] + np.einsum("nij,nkj->nki", self.rotation_matrices(), local)).reshape(-1, 3)

    def world_points(self, i: int, local_points) -> np.ndarray:
        """World positions (m, 3) [m] of body-frame points local_points (m, 3) of body i."""
        local = np.ascontiguousarray(local_points, dtype=np.float64).reshape(-1, 3)
        return self.points_to_world(np.full(local.shape[0], i, dtype=np.int64), local)

    def points_to_world(self, body, local_points) -> np.ndarray:
        """World positions (k, 3) [m] of points local_points (k, 3) fixed in bodies body (k,)."""
        body = np.ascontiguousarray(body, dtype=np.int64).reshape(-1)
        local = np.ascontiguousarray(local_points, dtype=np.float64).reshape(-1, 3)
        out = np.empty_like(local)
        rk.body_points_to_world(body, local, self.c, self.q, out)
        return out

    def point_velocities(self, body, points) -> np.ndarray:
        """Velocities (k, 3) [m/s] of world points (k, 3) [m] moving with bodies body (k,)."""
        body = np.ascontiguousarray(body, dtype=np.int64).reshape(-1)
        pts = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3)
        out = np.empty_like(pts)
        rk.point_velocities(body, pts, self.c, self.v, self.w, out)
        return out

    def angular_momentum(self) -> np.ndarray:
        """(n, 3) [kg m^2/s] world angular momentum about each centre, L = R I_body R^T w."""
        R = self.rotation_matrices()
        wb = np.einsum("nji,nj->ni", R, self.w)
        return np.einsum("nij,nj->ni", R, self.inertia_body * wb)

    def energy(self, gravity=GRAVITY) -> RigidEnergy:
        """Kinetic (linear, rotational) and gravitational potential energy per body [J]."""
        out = np.empty((self.n, 3))
        rk.energy(self.c, self.q, self.v, self.w, self.mass, self.inertia_body,
                  _vec3(gravity, "gravity"), out)
        return RigidEnergy(out[:, 0].copy(), out[:, 1].copy(), out[:, 2].copy())
