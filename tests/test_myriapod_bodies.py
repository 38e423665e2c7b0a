"""The legged centipede (``models/centipede.toml``) on the two other body models.

``massspring``: the hybrid's rigid boxes joined by Miller spring-cube links
(``bodies/massspring/myriapod.py``); ``fem``: one FEM mesh with stiff blocks
where the rigid segments were, supported blocks pulled to their targets by
implicit penalty springs on their leg-attachment nodes (``bodies/fem/myriapod.py``).

Order: the segment interface (a supported segment reaches its target in one
step), one kernel step against a slow numpy composition, linear momentum in
free fall, then the 10 s walk of each body.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg  # noqa: F401  (sp.linalg)
from scipy.spatial.transform import Rotation

from bench_myriapoda.bodies.fem.myriapod import K_SUPPORT, BodyFEMChain
from bench_myriapoda.bodies.massspring.myriapod import BodyRigidSpringChain
from bench_myriapoda.controllers.myriapod.controller import MyriapodController
from bench_myriapoda.harness.runner import Creature
from bench_myriapoda.bodies.rigid import RigidBoxes
from bench_myriapoda.core import registry
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.world.world import build_world

LIFT_M = 100.0                 # [m] raised this far above the plane: no contact during the short checks
KERNEL_REL_TOL = 1e-10         # kernel step vs numpy composition, relative to the state's scale (seen: 2e-15)
MOMENTUM_REL_TOL = 1e-9        # |P - (P0 + M g t)| / (|P0| + M g t) in free fall (seen: 2e-17)
POSE_EXACT_TOL = 1e-12         # rigid boxes: target rotation reached to round-off (quaternion conversion)
FEM_NODE_STEP_FRAC = 0.03      # fem: attachment-node error / move after one step (penalty: m / (m + dt^2 k_p))
FEM_CENTROID_STEP_FRAC = 0.4    # fem: centroid error / move after one step (interior third lags a step)
FEM_TRACK_TOL_M = 1e-3         # fem: centroid lag [m] of a block moved at 0.5 m/s for 0.1 s
WALK_S = 10.0
MIN_SPEED = 0.2                # [m/s]


def _case(body):
    return resolve_case("centipede", body, "walk", duration=WALK_S)


def _lifted(body_cls, body_name, seed=0):
    """The body (no leg controller) lifted LIFT_M with random node / box velocities of ~0.1 m/s."""
    b = body_cls(case := _case(body_name), build_world(case))
    rng = np.random.default_rng(seed)
    b.x[:, 1] += LIFT_M
    b.v[:] = rng.normal(scale=0.1, size=b.v.shape)
    if isinstance(b, BodyRigidSpringChain):
        b.rigid.c[:, 1] += LIFT_M
        b.rigid.v[:] = rng.normal(scale=0.1, size=b.rigid.v.shape)
        b.rigid.w[:] = rng.normal(scale=0.1, size=b.rigid.w.shape)
        b.sync_attached()
    return b


def _target(c, R, s, rng):
    """A target 0.2 mm and 2e-4 rad away from segment s's pose (c (n,3), R (n,3,3)): one step of a
    fast walk (the head moves 0.5 m/s * dt = 0.17 mm per step)."""
    c_T, R_T = c.copy(), R.copy()
    d = rng.normal(size=3)
    c_T[s] += 2e-4 * d / np.linalg.norm(d)
    a = rng.normal(size=3)
    R_T[s] = Rotation.from_rotvec(2e-4 * a / np.linalg.norm(a)).as_matrix() @ R[s]
    return c_T, R_T


def _three_supported(b, rng):
    """(c (n, 3) [m] of b's segments now, sup (n,) bool: segments 0, 5 and 11, and targets c_T, R_T: ``_target``
    of each of them)."""
    c, R = (a.copy() for a in b.segment_poses())
    sup = np.zeros(len(c), bool)
    sup[[0, 5, 11]] = True
    c_T, R_T = c.copy(), R.copy()
    for s in (0, 5, 11):
        c_T, R_T = _target(c_T, R_T, s, rng)
    return c, sup, c_T, R_T


# ------------------------------------------------------------------ registration
def test_the_factories_give_legged_bodies_for_the_centipede():
    registry.load_all()  # the lookups are filled on first use: this test may be its worker's first to look
    for name, cls in (("massspring", BodyRigidSpringChain), ("fem", BodyFEMChain)):
        spec = registry.BODIES[name]
        assert "legs" in spec.capabilities
        body = Creature(_case(name))  # the factory's body, composed with the gait's controller
        assert isinstance(body.controller, MyriapodController) and isinstance(body.body, cls)
        assert body.body_length_m == pytest.approx(18 * 1.0 + 17 * 0.5)


# ------------------------------------------------------------------ segment interface
def test_massspring_supported_box_is_at_its_target_after_one_step():
    b = BodyRigidSpringChain(case := _case("massspring"), build_world(case))
    rng = np.random.default_rng(1)
    c, sup, c_T, R_T = _three_supported(b, rng)
    b.set_support(sup, c_T, R_T, b.dt)
    assert b.advance(0.0, 1) == (1, 0)
    c1, R1 = b.segment_poses()
    assert np.array_equal(c1[sup], c_T[sup])                     # exactly
    assert np.abs(R1[sup] - R_T[sup]).max() < POSE_EXACT_TOL
    assert np.abs(c1[~sup] - c[~sup]).max() > 0.0               # the others moved under gravity
    # attached nodes sit on the kinematic boxes
    fix = b.att_body
    on = np.isin(fix, np.flatnonzero(sup))
    xw = c_T[fix[on]] + np.einsum("nij,nj->ni", R_T[fix[on]], b.att_local[on])
    assert np.abs(b.x[b.fixed[on]] - xw).max() < 1e-12


def test_fem_supported_block_tracks_its_target():
    """One step: the leg-attachment nodes (2/3 of the block's nodes at 3 nodes across) reach their targets
    up to the penalty's m / (m + dt^2 k_p); the interior nodes follow elastically, so the best-fit centroid
    gets about 2/3 of the way.  Steady motion at the head's 0.5 m/s for 0.1 s: the lag stays small."""
    b = BodyFEMChain(case := _case("fem"), build_world(case))
    rng = np.random.default_rng(2)
    dt = b.case.dt
    c, sup, c_T, R_T = _three_supported(b, rng)
    x0 = b.x.copy()
    b.set_support(sup, c_T, R_T, dt)
    on = sup[b.att_block]
    node_move = np.linalg.norm(b.att_target[on] - x0[b.att_nodes[on]], axis=1).max()
    assert b.advance(0.0, 1) == (1, 0)
    c1, R1 = b.segment_poses()
    err_c = np.linalg.norm(c1[sup] - c_T[sup], axis=1).max()
    err_R = np.abs(R1[sup] - R_T[sup]).max()
    print(f"\nfem one step: attachment nodes {b.support_error():.2e} m of a {node_move:.2e} m move; "
          f"centroid {err_c:.2e} m of a 2.0e-04 m move; rotation {err_R:.2e}")
    assert b.support_error() < FEM_NODE_STEP_FRAC * node_move
    assert err_c < FEM_CENTROID_STEP_FRAC * 2e-4
    # steady: every step the target moves 0.5 m/s * dt along +x
    step = np.array([0.5 * dt, 0.0, 0.0])
    errs = []
    for k in range(300):
        c_T[sup] += step
        b.set_support(sup, c_T, R_T, dt)
        assert b.advance(k * dt, 1) == (1, 0)
        errs.append(np.linalg.norm(b.segment_poses()[0][sup] - c_T[sup], axis=1).max())
    print(f"fem steady 0.5 m/s: centroid lag {errs[-1]:.2e} m after 0.1 s (max over the last half "
          f"{max(errs[150:]):.2e} m)")
    assert max(errs[150:]) < FEM_TRACK_TOL_M


# ------------------------------------------------------------------ one kernel step vs numpy
def _massspring_reference_step(b: BodyRigidSpringChain):
    """Springs, free nodes and the coupling in numpy; the boxes with ``RigidBoxes.advance`` (no contact)."""
    dt, g = b.dt, b.gravity
    x0, v0 = b.x.copy(), b.v.copy()
    i, j = b.springs[:, 0], b.springs[:, 1]
    d = x0[j] - x0[i]
    L = np.linalg.norm(d, axis=1)
    u = d / L[:, None]
    ldot = np.einsum("ij,ij->i", v0[j] - v0[i], u)
    fs = (b.stiffness * (b.rest - L) - b.damping * ldot)[:, None] * u
    f = np.zeros_like(x0)
    np.add.at(f, i, -fs)
    np.add.at(f, j, fs)
    x1, v1 = x0.copy(), v0.copy()
    fr = b.free
    v1[fr] = v0[fr] + dt * (f[fr] / b.mass[fr, None] + g)
    x1[fr] = x0[fr] + dt * v1[fr]
    rb = RigidBoxes(b.rigid.half_extents, b.rigid.mass)
    for name in ("c", "q", "v", "w", "impulse_cache", "kinematic"):
        getattr(rb, name)[...] = getattr(b.rigid, name)
    rb.apply_forces_at_points(b.att_body, f[b.fixed], x0[b.fixed])
    assert rb.advance(1, dt, gravity=g, terrain_kind=b.terr_kind, terrain_params=b.terr, contact=b.contact,
                      max_speed=1e3)[1] == 0
    x1[b.fixed] = rb.points_to_world(b.att_body, b.att_local)
    v1[b.fixed] = rb.point_velocities(b.att_body, x1[b.fixed])
    return x1, v1, rb


def test_massspring_kernel_step_matches_numpy_composition():
    b = _lifted(BodyRigidSpringChain, "massspring")
    b.x[b.free] += np.random.default_rng(3).normal(scale=0.02, size=(len(b.free), 3))  # springs stretched
    x1, v1, rb = _massspring_reference_step(b)
    assert b.advance(0.0, 1) == (1, 0)
    scale_x, scale_v = np.abs(x1).max(), np.abs(v1).max()
    assert np.abs(b.x - x1).max() < KERNEL_REL_TOL * scale_x
    assert np.abs(b.v - v1).max() < KERNEL_REL_TOL * scale_v
    assert np.abs(b.rigid.c - rb.c).max() < KERNEL_REL_TOL * scale_x
    assert np.abs(b.rigid.q - rb.q).max() < KERNEL_REL_TOL
    assert np.abs(b.rigid.w - rb.w).max() < KERNEL_REL_TOL * max(np.abs(rb.w).max(), 1.0)


def test_fem_kernel_step_matches_numpy_composition():
    b = _lifted(BodyFEMChain, "fem")
    rng = np.random.default_rng(4)
    b.x[:] += rng.normal(scale=1e-3, size=b.x.shape)          # deformed
    c, R = (a.copy() for a in b.segment_poses())
    sup = np.zeros(len(c), bool)
    sup[[2, 9]] = True
    c_T, R_T = _target(c, R, 2, rng)
    c_T, R_T = _target(c_T, R_T, 9, rng)
    b.set_support(sup, c_T, R_T, b.case.dt)
    fem, dt, kp = b.fem, b.case.dt, b.phys[K_SUPPORT]
    x0, v0 = b.x.copy(), b.v.copy()
    # reference: f = f_E(x^n) + M g, (M + dt D) v* = M v + dt f, penalty per node, x += dt v
    fem_ref_x = fem.x.copy()
    f = fem.elastic_forces() + fem.mass[:, None] * b.gravity
    fem.x[:] = fem_ref_x
    A = (sp.diags(fem.mass) + dt * fem.D).tocsc()
    v1 = sp.linalg.spsolve(A, fem.mass[:, None] * v0 + dt * f)
    on = sup[b.att_block]
    p, s = b.att_nodes[on], b.att_block[on]
    cb, Rb = c[s], R[s]                                          # poses before the step (set_support saw them)
    xt = c_T[s] + np.einsum("nij,nj->ni", R_T[s], np.einsum("nji,nj->ni", Rb, x0[p] - cb))
    m = fem.mass[p][:, None]
    v1[p] = (m * v1[p] + dt * kp * (xt - x0[p])) / (m + dt * dt * kp)
    x1 = x0 + dt * v1
    assert b.advance(0.0, 1) == (1, 0)
    print(f"\nfem kernel vs numpy: v {np.abs(b.v - v1).max() / np.abs(v1).max():.1e}, "
          f"x {np.abs(b.x - x1).max() / np.abs(x1).max():.1e} (relative)")
    assert np.abs(b.v - v1).max() < 1e-8 * np.abs(v1).max()   # sparse direct vs skyline Cholesky
    assert np.abs(b.x - x1).max() < KERNEL_REL_TOL * np.abs(x1).max()


# ------------------------------------------------------------------ conservation
def test_massspring_free_fall_linear_momentum_is_p0_plus_mg_t():
    b = _lifted(BodyRigidSpringChain, "massspring", seed=5)
    assert not b.rigid.kinematic.any()
    P0 = b.momentum()
    M = b.total_mass
    n_steps = 600
    for k in range(1, 4):
        assert b.advance(0.0, n_steps // 3) == (n_steps // 3, 0)
        t = k * (n_steps // 3) * b.dt
        expect = P0 + M * b.gravity * t
        err = np.abs(b.momentum() - expect).max() / (np.abs(P0).max() + M * np.abs(b.gravity).max() * t)
        assert err < MOMENTUM_REL_TOL
    assert b.energy()[1] > 0.0  # the springs did work: the check is not on a rigidly falling body


# ------------------------------------------------------------------ walking
@pytest.fixture(scope="module")
def walks():
    """The 18-segment centipede walking 10 s on each body model (one run each)."""
    return {body: run_case(_case(body)) for body in ("hybrid", "massspring", "fem")}


SIDE_BY_SIDE = ("speed_m_per_s", "phase_lag_mean", "duty_factor_mean", "stride_frequency_hz",
                "stance_fraction_mean", "foot_slip_mean_m", "tracking_error_mean_m", "body_undulation_amp_bl")


def test_the_centipede_walks_10_s_on_all_three_bodies_side_by_side(walks, capsys):
    for body, r in walks.items():
        assert r.status == "ok", (body, r.message)
        assert r.metrics["speed_m_per_s"] > MIN_SPEED, body
        assert np.isfinite(r.metrics["phase_lag_mean"]) and 0.0 < r.metrics["duty_factor_mean"] < 1.0, body
    with capsys.disabled():
        print("\n" + "metric".ljust(24) + "".join(b.rjust(13) for b in walks))
        for k in SIDE_BY_SIDE + ("steps_per_s",):
            vals = [r.timings[k] if k == "steps_per_s" else r.metrics.get(k, float("nan")) for r in walks.values()]
            print(k.ljust(24) + "".join(f"{v:13.4g}" for v in vals))


def test_supporting_the_all_fem_body_is_the_harder_control_problem(walks):
    # paper Sec. 3: legs on deformable segments have only a local effect; the supported blocks of the
    # fem body miss their targets by more than the rigid segments of the other two bodies
    track = {b: r.metrics["tracking_error_mean_m"] for b, r in walks.items()}
    assert track["fem"] > 3 * max(track["hybrid"], track["massspring"]), track


@pytest.mark.parametrize("body", ["massspring", "fem"])
@pytest.mark.parametrize("segments", [3, 100])
def test_segment_counts_from_3_to_100_run(body, segments):
    r = run_case(resolve_case("centipede", body, "walk", duration=0.3, overrides=[f"creature.segments={segments}"]))
    assert r.status == "ok", r.message


@pytest.mark.parametrize("body", ["massspring", "fem"])
def test_hanging_head_stays_held_and_the_body_elongates(body):
    from bench_myriapoda.controllers.myriapod import switcher as SW
    r = run_case(resolve_case("centipede", body, "hang", duration=2.0))
    assert r.status == "ok", r.message
    assert r.metrics["hanging_elongation_m"] > 0.01
    assert np.abs(r.series.head - r.series.head[0]).max() < 0.05  # the head does not fall
    _, states, _ = r.extra["leg_timeline"]
    assert not np.any(states == SW.STANCE)
