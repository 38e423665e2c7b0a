"""The hybrid body (paper Sec. 3): rigid boxes joined by FEM links with staggered coupling.

Order (ARCHITECTURE habit 4): conservation laws the coupling must satisfy exactly,
the kernel against a Python composition of the FEMSystem / RigidBoxes operations,
the analytic hanging chain, then the paper's Fig. 4 drop and the command line.
The chain is ``models/chain.toml``: 5 boxes of 1 m, 4 links of 0.5 m at 3x3x3 nodes,
the App. A material (E = 4000 Pa, nu = 0.4, rho = 1 kg/m^3, gamma = 50), dt = 1/3000 s.
"""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from bench_myriapoda.bodies.contact_kernels import collide_path, contact_friction
from bench_myriapoda.bodies.fem.system import FEMSystem
from bench_myriapoda.bodies.friction_kernels import CONTACT_DISTANCE
from bench_myriapoda.bodies.hybrid import kernels as K
from bench_myriapoda.bodies.hybrid.body import BodyHybrid
from bench_myriapoda.bodies.rigid import RigidBoxes
from bench_myriapoda.cli import main
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.harness.runner import run_case
from bench_myriapoda.world.terrain_kernels import signed_distance
from bench_myriapoda.world.world import build_world

DT = 1.0 / 3000.0                 # [s] the paper's time step (App. A)
MOMENTUM_REL_TOL = 1e-12          # |P - (P0 + M g t)| / (|P0| + M g t): exact up to round-off (seen: 2e-15)
ANGULAR_REL_TOL = 1e-12           # |L(t) - L0| / |L0| about the COM, undamped links (seen: 1e-14)
REF_TOL = 1e-12                   # one kernel step vs the Python composition [m, m/s, rad/s, -]
ATTACH_TOL = 1e-13                # attached nodes vs the box transform of their body-frame points [m, m/s]
RESIDUAL_MAX_FRAC = 0.01          # coupling residual (max over the drop) / link length, at dt = 1/3000 s
HANG_REL_TOL = 0.05               # hanging elongation vs the static estimate (nu = 0, strain ~1 %)
SETTLED_SPEED = 1e-3              # [m/s] fastest box or node at the end of the drop
SETTLED_PEN = 1e-3                # [m] deepest box corner or node at the end of the drop
IMPACT_STRAIN_MIN = 0.01          # the links must deform by at least 1 % on impact ...
STATIC_STRAIN_MAX = 0.005         # ... and be back under 0.5 % (their sag on the ground) at the end

FREE_FLIGHT = """
[scenario]
name = "free-flight"
description = "no ground, gravity on: a tumbling chain"
terrain = "none"
start_height_m = 10.0
perturbation_m = 0.01
duration_s = 0.4
"""


def spin_up(body: BodyHybrid, V, W) -> None:
    """Give the whole body the rigid velocity field V + W x (x - com), boxes included."""
    com = body.observe(0.0).com
    rb = body.rigid
    rb.v[:] = V + np.cross(W, rb.c - com)
    rb.w[:] = W
    body.v[body.free] = V + np.cross(W, body.x[body.free] - com)
    body.sync_attached()


@pytest.fixture
def free_flight(tmp_path):
    path = tmp_path / "free-flight.toml"
    path.write_text(FREE_FLIGHT)
    return str(path)


def drive(body: BodyHybrid, n_steps: int, chunk: int, check) -> None:
    done = 0
    while done < n_steps:
        k, code = body.advance(done * body.dt, min(chunk, n_steps - done))
        assert code == K.OK, body.status_text(code)
        done += k
        check(done * body.dt)


# ------------------------------------------------------------------------------------
# Conservation: the coupling forces cancel exactly (Sec. 3 steps 1-2)
# ------------------------------------------------------------------------------------
def test_free_flight_linear_momentum_is_p0_plus_mg_t_at_every_sample(free_flight):
    # Damped links (gamma = 50): the damping reaction -(D v)_p on the boxes must use the
    # same prescribed v_p as the solve, else momentum leaks; a sign error or a missing
    # reaction (elastic or damping) shows up at the first sample.
    case = resolve_case("chain", "hybrid", free_flight)
    body = BodyHybrid(case, build_world(case))
    spin_up(body, V=np.array([0.5, 2.0, -0.3]), W=np.array([0.4, 1.5, -0.7]))
    M = body.total_mass
    P0, _ = body.momenta()
    g = body.gravity

    def check(t):
        P, _ = body.momenta()
        expected = P0 + M * g * t
        assert np.linalg.norm(P - expected) <= MOMENTUM_REL_TOL * (np.linalg.norm(P0) + M * np.linalg.norm(g) * t)

    drive(body, int(round(0.4 / DT)), 30, check)
    # the links really worked: they vibrate from the perturbed start and stretch under the spin
    assert body.fem.elastic_energy() > 1e-4


def test_free_flight_angular_momentum_about_the_com_is_constant(free_flight):
    # gamma = 0: eq. 13's damping pulls each tet's node velocities to their mean, so it
    # also brakes a rigid rotation of a link (f_i = -gamma V w x (x_i - x_mean)) and takes
    # angular momentum out of a spinning body; that is the paper's model, not a coupling
    # error.  Without it the elastic forces at x^n carry no net torque, the boxes get
    # the reactions at the same points, symplectic Euler and the boxes' L-conserving
    # rotation keep the rest exact, and gravity exerts no torque about the COM.
    case = resolve_case("chain", "hybrid", free_flight, overrides=["body.damping_gamma=0"])
    body = BodyHybrid(case, build_world(case))
    spin_up(body, V=np.array([0.0, 1.0, 0.0]), W=np.array([0.4, 1.5, -0.7]))
    _, L0 = body.momenta()

    def check(t):
        _, L = body.momenta()
        assert np.linalg.norm(L - L0) <= ANGULAR_REL_TOL * np.linalg.norm(L0), t

    drive(body, int(round(0.4 / DT)), 30, check)
    R = body.rotation_matrices()
    assert not np.allclose(R[0], R[-1])  # the chain did turn


# ------------------------------------------------------------------------------------
# One coupled step against a Python composition of the shared operations
# ------------------------------------------------------------------------------------
def reference_step(b: BodyHybrid):
    """Sec. 3 steps 1-3 composed from FEMSystem, the point contact and RigidBoxes (slow)."""
    cfg, dt, g = b.case.body, b.dt, b.gravity
    fem = FEMSystem(b.fem.X, b.fem.tets, E=cfg.youngs_modulus_pa, nu=cfg.poisson_ratio, rho=cfg.density_kg_m3,
                    gamma=cfg.damping_gamma)
    fem.set_fixed(b.mesh.attached)
    fem.x[:], fem.v[:], fem.q_ws[:] = b.x, b.v, b.fem.q_ws
    x0 = b.x.copy()
    # (1) FEM step with the attached nodes prescribed (eq. 14), no terrain ...
    assert fem.advance(1, dt=dt, gravity=g).ok
    f_att = fem.fixed_node_forces()  # f_E(x^n) - (D v^{n+1})_p, in sorted node order = b.fixed
    # ... then the shared point contact of the free nodes from x^n with v^{n+1}
    c = b.rigid.c
    x1, v1 = fem.x.copy(), fem.v.copy()
    for i in b.free:
        k = b.mesh.node_link[i]
        s = (c[k] - c[k + 1]) / np.linalg.norm(c[k] - c[k + 1])
        p, v = x0[i], fem.v[i]
        phi = signed_distance(b.terr_kind, b.terr, *p)
        if phi < b.fric[CONTACT_DISTANCE]:
            v = np.array(contact_friction(b.terr_kind, b.terr, b.fric_model, b.fric, b.phys[K.R_N], tuple(p),
                                          tuple(v), tuple(s), phi, tuple(dt * v)))
        q = p + dt * v
        phi_q = signed_distance(b.terr_kind, b.terr, *q)
        if phi_q < 0.0:
            r = collide_path(b.terr_kind, b.terr, b.phys[K.R_N], b.phys[K.R_T], *p, phi, *q, phi_q, *v)
            q, v = np.array(r[:3]), np.array(r[3:6])
        x1[i], v1[i] = q, v
    # (2) the boxes under the reactions at the attached points of state n, plus gravity
    rb = RigidBoxes(b.rigid.half_extents, b.rigid.mass)
    for name in ("c", "q", "v", "w", "impulse_cache", "kinematic"):
        getattr(rb, name)[...] = getattr(b.rigid, name)
    rb.apply_forces_at_points(b.att_body, f_att, x0[b.fixed])
    n, status = rb.advance(1, dt, gravity=g, terrain_kind=b.terr_kind, terrain_params=b.terr, contact=b.contact,
                           max_speed=1e3)
    assert status == 0
    # (3) the attached nodes on the boxes' new state
    x1[b.fixed] = rb.points_to_world(b.att_body, b.att_local)
    v1[b.fixed] = rb.point_velocities(b.att_body, x1[b.fixed])
    return x1, v1, rb


@pytest.mark.parametrize("t_state", [0.2, 0.452], ids=["in-flight", "at-impact"])
def test_one_kernel_step_matches_the_python_composition(t_state):
    case = resolve_case("chain", "hybrid", "fig4-drop")
    b = BodyHybrid(case, build_world(case))
    assert b.advance(0.0, int(round(t_state / DT)))[1] == K.OK
    # stir the state: deformed links, sliding and spinning boxes, so every term acts
    rng = np.random.default_rng(7)
    b.x[b.free] += rng.normal(scale=0.01, size=(len(b.free), 3))
    b.v[b.free] += rng.normal(scale=0.3, size=(len(b.free), 3))
    b.rigid.v[:] += rng.normal(scale=0.3, size=b.rigid.v.shape)
    b.rigid.w[:] += rng.normal(scale=0.5, size=b.rigid.w.shape)
    b.sync_attached()
    if t_state > 0.45:  # the boxes are on the ground and the friction acts
        assert b.box_corners()[:, 1].min() < 0.0 and b.x[b.free, 1].min() < b.fric[CONTACT_DISTANCE]
    x_ref, v_ref, rb = reference_step(b)
    assert b.advance(0.0, 1)[1] == K.OK
    np.testing.assert_allclose(b.x, x_ref, rtol=0, atol=REF_TOL * 10)  # positions ~ 5 m
    np.testing.assert_allclose(b.v, v_ref, rtol=0, atol=REF_TOL)
    for name in ("c", "q", "v", "w"):
        np.testing.assert_allclose(getattr(b.rigid, name), getattr(rb, name), rtol=0, atol=REF_TOL * 10, err_msg=name)


def test_place_attached_and_momenta_kernels_match_numpy():
    case = resolve_case("chain", "hybrid", "fig4-drop")
    b = BodyHybrid(case, build_world(case))
    rng = np.random.default_rng(3)
    rb = b.rigid
    q = rng.normal(size=rb.q.shape)
    rb.q[:] = q / np.linalg.norm(q, axis=1, keepdims=True)
    rb.v[:], rb.w[:] = rng.normal(size=rb.v.shape), rng.normal(size=rb.w.shape)
    b.v[b.free] = rng.normal(size=(len(b.free), 3))
    b.sync_attached()
    R = b.rotation_matrices()
    p = rb.c[b.att_body] + np.einsum("kij,kj->ki", R[b.att_body], b.att_local)
    np.testing.assert_allclose(b.x[b.fixed], p, rtol=0, atol=ATTACH_TOL)
    np.testing.assert_allclose(b.v[b.fixed], rb.v[b.att_body] + np.cross(rb.w[b.att_body], p - rb.c[b.att_body]),
                               rtol=0, atol=ATTACH_TOL)
    o = np.array([0.3, -1.0, 2.0])
    m = b.fem.mass[b.free]
    P = rb.mass @ rb.v + m @ b.v[b.free]
    spin = np.einsum("nij,nj->ni", R, rb.inertia_body * np.einsum("nji,nj->ni", R, rb.w))
    L = (np.cross(rb.c - o, rb.mass[:, None] * rb.v).sum(0) + spin.sum(0)
         + np.cross(b.x[b.free] - o, m[:, None] * b.v[b.free]).sum(0))
    P_k, L_k = b.momenta(origin=o)
    np.testing.assert_allclose(P_k, P, rtol=1e-13)
    np.testing.assert_allclose(L_k, L, rtol=1e-13)


def test_compile_snapshot_restores_every_dynamic_array_by_name():
    """``compile``'s save/restore (``HybridDynamicState``): every named array written after the snapshot is
    back to its saved value, in place (the kernels' packs hold the live arrays)."""
    case = resolve_case("chain", "hybrid", "fig4-drop")
    b = BodyHybrid(case, build_world(case))
    saved = b._state()
    live = b._state_arrays()
    ids = {name: id(a) for name, a in live._asdict().items()}
    for a in live:
        a[...] = a + 1 if a.dtype != bool else ~a
    b._restore(saved)
    for name, a in b._state_arrays()._asdict().items():
        assert id(a) == ids[name], name
        np.testing.assert_array_equal(a, getattr(saved, name), err_msg=name)
        assert not np.shares_memory(a, getattr(saved, name)), name


# ------------------------------------------------------------------------------------
# Fig. 4: the chain dropped onto a slippery plane
# ------------------------------------------------------------------------------------
def test_fig4_drop_attached_nodes_stay_on_the_boxes_and_the_residual_is_small():
    case = resolve_case("chain", "hybrid", "fig4-drop")
    b = BodyHybrid(case, build_world(case))
    link = b.layout.link_length
    assert b.advance(0.0, int(round(0.44 / DT)))[1] == K.OK
    for _ in range(60):  # step by step through the impact at ~0.45 s
        assert b.advance(0.0, 1)[1] == K.OK
        p = b.rigid.points_to_world(b.att_body, b.att_local)
        np.testing.assert_allclose(b.x[b.fixed], p, rtol=0, atol=ATTACH_TOL)
        np.testing.assert_allclose(b.v[b.fixed], b.rigid.point_velocities(b.att_body, p), rtol=0, atol=ATTACH_TOL)
    res_max, res_mean = b.coupling_residual()
    assert b.box_corners()[:, 1].min() < 0.0  # the impact happened inside the stepped window
    assert 0.0 < res_mean < res_max < RESIDUAL_MAX_FRAC * link


def test_coupling_residual_grows_with_the_time_step():
    # At an impact a box's velocity jumps by dv within one step, so the attached nodes
    # predicted with the old velocity miss the box by ~dt dv: the residual scales with dt.
    res = {}
    for mult in (1, 4):
        r = run_case(resolve_case("chain", "hybrid", "fig4-drop", dt=mult * DT, duration=1.0))
        assert r.status == "ok", r.message
        res[mult] = (r.metrics["coupling_residual_max_m"], r.metrics["coupling_residual_mean_m"])
    link = 0.5
    assert res[1][0] < RESIDUAL_MAX_FRAC * link
    assert res[4][0] > 2.0 * res[1][0] and res[4][1] > 2.0 * res[1][1]


def test_fig4_drop_lands_deforms_recovers_and_settles():
    case = resolve_case("chain", "hybrid", "fig4-drop")
    body = BodyHybrid(case, build_world(case))
    impact_strain, t, chunk = 0.0, 0.0, 15  # tet quality every 5 ms
    while t < case.duration - 1e-9:
        k, code = body.advance(t, chunk)
        assert code == K.OK, body.status_text(code)
        t += k * DT
        body.observe(t)
        if t < 1.0:
            impact_strain = max(impact_strain, body.tet_quality()[2])
    m = body.extra_metrics()
    min_J, inverted, strain = body.tet_quality()
    assert impact_strain > IMPACT_STRAIN_MIN            # the links deform on impact
    assert strain < STATIC_STRAIN_MAX                   # ... and recover
    assert inverted == 0 and m["inverted_elements_max"] == 0 and m["min_J"] > 0.5
    assert m["max_strain"] >= impact_strain             # observe() folded the samples in
    assert m["coupling_residual_max_m"] < RESIDUAL_MAX_FRAC * body.layout.link_length
    # settled on the plane: at rest, not sunk in, lying flat at half a box height
    assert body.box_corners()[:, 1].min() > -SETTLED_PEN and body.x[:, 1].min() > -SETTLED_PEN
    assert np.abs(body.rigid.v).max() < SETTLED_SPEED and np.abs(body.v).max() < SETTLED_SPEED
    np.testing.assert_allclose(body.rigid.c[:, 1], 0.5 * body.layout.rigid_height, atol=SETTLED_PEN)


# ------------------------------------------------------------------------------------
# Fig. 10: hanging from the head, the body elongates
# ------------------------------------------------------------------------------------
def test_hanging_elongation_matches_the_static_estimate():
    # nu = 0 so that a link glued to two boxes is in plain uniaxial tension (with nu = 0.4
    # the glued faces cannot contract and the short links are ~1.6x stiffer than E A / L).
    # Link k carries everything below it: the boxes and free nodes of the lower links,
    # and the middle node layer of its own (free mass of link k at L/2) over half its
    # length.  Strain ~1 %: small.
    case = resolve_case("chain", "hybrid", "hang", overrides=["body.poisson_ratio=0"], duration=4.0)
    r = run_case(case)
    assert r.status == "ok", r.message
    body = BodyHybrid(case, build_world(case))
    lay, g = body.layout, case.scenario.gravity_m_s2
    m_box = body.rigid.mass[0]
    m_link = np.array([body.fem.mass[body.free][body.node_link[body.free] == k].sum() for k in range(lay.n_rigid - 1)])
    EA = case.body.youngs_modulus_pa * lay.link_width * lay.link_height
    estimate = 0.0
    for k in range(lay.n_rigid - 1):
        below = (lay.n_rigid - 1 - k) * m_box + m_link[k + 1:].sum() + 0.5 * m_link[k]
        estimate += g * below * lay.link_length / EA
    assert estimate / (lay.n_rigid - 1) / lay.link_length < 0.02  # small strain
    assert r.metrics["hanging_elongation_m"] == pytest.approx(estimate, rel=HANG_REL_TOL)
    # the head box is held: it never moves
    head = r.series.segment_centers[:, 0]
    np.testing.assert_array_equal(head, np.broadcast_to(head[0], head.shape))
    # hangs straight down along -y from the head
    axis = r.series.tail[-1] - r.series.head[-1]
    assert axis[1] < 0 and np.hypot(axis[0], axis[2]) < 1e-3 * abs(axis[1])


# ------------------------------------------------------------------------------------
# Configuration and command line
# ------------------------------------------------------------------------------------
def test_two_node_resolution_is_rejected_as_bad_input(capsys):
    code = main(["run", "--creature", "chain", "--body", "hybrid", "--scenario", "fig4-drop", "--no-store",
                 "--set", "body.resolution=2"])
    err = capsys.readouterr().err
    assert code == 2 and "bodies.hybrid" in err and "resolution" in err and ">= 3 nodes" in err


def test_cli_run_fig4_drop_json_reports_the_hybrid_metrics(capsys):
    code = main(["run", "--creature", "chain", "--body", "hybrid", "--scenario", "fig4-drop", "--duration", "1.0",
                 "--json", "--no-store"])
    out = capsys.readouterr().out
    assert code == 0
    d = json.loads(out)
    assert d["status"] == "ok"
    assert d["case"]["body"]["name"] == "hybrid" and d["case"]["dt"] == pytest.approx(DT)
    m = d["metrics"]
    for name in ("min_J", "inverted_elements_max", "max_strain", "coupling_residual_max_m",
                 "coupling_residual_mean_m", "max_penetration_m", "contact_fraction"):
        assert name in m and m[name] is not None and math.isfinite(m[name]), name
    assert 0.0 < m["min_J"] < 1.0 and m["inverted_elements_max"] == 0
    assert 0.0 < m["coupling_residual_mean_m"] < m["coupling_residual_max_m"]
    assert 0.0 < m["contact_fraction"] < 1.0


def test_cli_stable_dt_brackets_the_limit_of_a_short_chain_drop(capsys):
    code = main(["stable-dt", "--creature", "chain", "--body", "hybrid", "--scenario", "fig4-drop",
                 "--duration", "0.6", "--json", "--no-store", "--max-runs", "8"])
    d = json.loads(capsys.readouterr().out)
    assert code == 0
    lo, hi = d["metrics"]["stable_dt_max_s"], d["metrics"]["unstable_dt_min_s"]
    # the paper's dt is stable; doubling from it reaches an unstable dt below the ceiling (0.03 s)
    assert DT <= lo < hi < 0.03
    statuses = {t["status"] for t in d["trials"]}
    assert statuses == {"ok", "unstable"}


def test_body_length_metrics_count_the_links():
    from bench_myriapoda.core.config import resolve_case
    from bench_myriapoda.harness.runner import run_case
    case = resolve_case("chain", "hybrid", "fig4-drop", duration=0.05)
    r = run_case(case)
    cre = case.creature
    assert r.metrics["body_length_m"] > cre.segments * cre.segment_length_m  # the links add length
    assert r.metrics["body_length_m"] == pytest.approx(
        abs(r.series.head[0] - r.series.tail[0]).max(), rel=1e-6)  # equals the built head-to-tail distance
