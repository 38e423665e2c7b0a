"""Every FEM kernel against a slow numpy reference, each at a named tolerance."""
import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from bench_myriapoda.bodies.fem import kernels as K
from bench_myriapoda.bodies.fem.mesh import box_grid, lame_parameters
from bench_myriapoda.bodies.fem.system import FEMSystem, build_solver, damping_matrix
from bench_myriapoda.world import terrain_kernels as T

SVD_REL_TOL = 1e-12          # singular values and R, well-conditioned F
SVD_RECON_TOL = 1e-13        # |U S V^T - F| / |F|, any F
ORTHO_TOL = 1e-13            # |U U^T - I|
NEWTON_ROT_TOL = 1e-12       # Newton rotation vs SVD rotation (sigma_2 + sigma_3 > 0.1 sigma_1)
FORCE_REF_TOL = 1e-10        # kernel forces vs numpy per-tet reference, relative to max |f|
FD_GRAD_TOL = 1e-6           # forces vs central-difference energy gradient, relative
SOLVE_TOL = 1e-12            # skyline solve vs scipy spsolve, relative
STEP_TOL = 1e-10             # advance(1 step) vs numpy step, relative
DAMPING_TOL = 1e-12          # damping kernel vs assembled matrix


# ------------------------------------------------------------------------------------
# numpy references
# ------------------------------------------------------------------------------------
def signed_svd_np(F):
    """numpy SVD converted to the signed convention: U, V proper, smallest sigma signed."""
    U, s, Vt = np.linalg.svd(F)
    V = Vt.T
    if np.linalg.det(U) < 0:
        U[:, 2] *= -1
        s[2] *= -1
    if np.linalg.det(V) < 0:
        V[:, 2] *= -1
        s[2] *= -1
    return U, s, V


def forces_np(x, tets, Dm_inv, vol, mu, lam):
    """Per-tet fixed-corotational forces in plain numpy (eq. 8 with J F^-T, eqs. 9-11)."""
    f = np.zeros_like(x)
    for e, t in enumerate(tets):
        Ds = np.stack([x[t[1]] - x[t[0]], x[t[2]] - x[t[0]], x[t[3]] - x[t[0]]], axis=1)
        F = Ds @ Dm_inv[e]
        U, _s, V = signed_svd_np(F)
        R = U @ V.T
        J = np.linalg.det(F)
        P = 2 * mu[e] * (F - R) + lam[e] * J * (J - 1) * np.linalg.inv(F).T
        H = -vol[e] * P @ Dm_inv[e].T
        f[t[1:]] += H.T
        f[t[0]] -= H.sum(axis=1)
    return f


def energy_np(x, tets, Dm_inv, vol, mu, lam):
    E = 0.0
    for e, t in enumerate(tets):
        Ds = np.stack([x[t[1]] - x[t[0]], x[t[2]] - x[t[0]], x[t[3]] - x[t[0]]], axis=1)
        _U, s, _V = signed_svd_np(Ds @ Dm_inv[e])
        E += vol[e] * (mu[e] * np.sum((s - 1) ** 2) + 0.5 * lam[e] * (np.prod(s) - 1) ** 2)
    return E


def random_matrices(rng, n):
    """Well-conditioned, near-identity, rotated, inverted, near-singular and flat 3x3 F."""
    out = []
    for i in range(n):
        kind = i % 6
        if kind == 0:
            F = rng.normal(size=(3, 3))
        elif kind == 1:
            F = np.eye(3) + 1e-3 * rng.normal(size=(3, 3))
        elif kind == 2:
            Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
            F = Q @ np.diag(rng.uniform(0.5, 2, 3))
        elif kind == 3:  # inverted
            F = rng.normal(size=(3, 3))
            if np.linalg.det(F) > 0:
                F[:, 0] *= -1
        elif kind == 4:  # near-singular: third column almost in the span of the others
            F = rng.normal(size=(3, 3))
            F[:, 2] = 0.3 * F[:, 0] - 0.7 * F[:, 1] + 1e-9 * rng.normal(size=3)
        else:  # exactly flat
            F = rng.normal(size=(3, 3))
            F[2] = 0.0
        out.append(F)
    return np.array(out)


# ------------------------------------------------------------------------------------
# SVD and rotations
# ------------------------------------------------------------------------------------
def test_svd_matches_numpy_with_sign_convention():
    rng = np.random.default_rng(0)
    Fs = random_matrices(rng, 600)
    U = np.empty_like(Fs)
    V = np.empty_like(Fs)
    s = np.empty((len(Fs), 3))
    K.svd3_batch(Fs, U, s, V)
    for F, u, sg, v in zip(Fs, U, s, V):
        assert np.linalg.det(u) > 0 and np.linalg.det(v) > 0
        assert np.abs(u @ u.T - np.eye(3)).max() < ORTHO_TOL
        assert np.abs(v @ v.T - np.eye(3)).max() < ORTHO_TOL
        scale = np.abs(F).max()
        assert np.abs(u @ np.diag(sg) @ v.T - F).max() < SVD_RECON_TOL * scale
        assert sg[0] >= sg[1] >= abs(sg[2])
        assert (sg[2] < 0) == (np.linalg.det(F) < -1e-12 * scale ** 3) or abs(sg[2]) < 1e-12 * scale
        Ur, sr, Vr = signed_svd_np(F)
        assert np.abs(sg - sr).max() < SVD_REL_TOL * abs(sr[0])
        if sr[1] + sr[2] > 0.1 * sr[0]:  # R is well defined
            assert np.abs(u @ v.T - Ur @ Vr.T).max() < SVD_REL_TOL


def test_polar_rotation_is_uv_transpose():
    rng = np.random.default_rng(10)
    R = np.empty((3, 3))
    for F in random_matrices(rng, 60):
        K.polar_rotation(F, R)
        Ur, sr, Vr = signed_svd_np(F)
        assert abs(np.linalg.det(R) - 1.0) < 1e-13
        if sr[1] + sr[2] > 0.1 * sr[0]:
            assert np.abs(R - Ur @ Vr.T).max() < SVD_REL_TOL
        if sr[2] > 0.1 * sr[0]:  # F = R S with S symmetric positive definite
            S = R.T @ F
            assert np.abs(S - S.T).max() < 1e-12 * sr[0] and np.linalg.eigvalsh(0.5 * (S + S.T)).min() > 0


def test_svd_degenerate_inputs():
    U = np.empty((3, 3))
    V = np.empty((3, 3))
    s = np.empty(3)
    K.svd3(np.zeros((3, 3)), U, s, V)
    assert np.all(s == 0) and np.linalg.det(U) > 0.999 and np.linalg.det(V) > 0.999
    K.svd3(np.diag([1.0, 0.0, 1.0]), U, s, V)  # flat
    np.testing.assert_allclose(s, [1, 1, 0], atol=1e-15)
    np.testing.assert_allclose(U @ V.T, np.eye(3), atol=1e-15)
    K.svd3(np.diag([1.0, -0.5, 1.0]), U, s, V)  # inverted: R stays the identity
    np.testing.assert_allclose(s, [1, 1, -0.5], atol=1e-15)
    np.testing.assert_allclose(U @ V.T, np.eye(3), atol=1e-15)
    F = np.outer([1.0, 2.0, 3.0], [0.3, 0.1, -1.0])  # rank one
    K.svd3(F, U, s, V)
    np.testing.assert_allclose(U @ np.diag(s) @ V.T, F, atol=1e-14)


@pytest.mark.parametrize("warm", [False, True])
def test_newton_rotation_matches_svd(warm):
    rng = np.random.default_rng(1)
    Fs = random_matrices(rng, 600)
    R = np.empty((3, 3))
    n_fallback = 0
    for F in Fs:
        Ur, sr, Vr = signed_svd_np(F)
        Rr = Ur @ Vr.T
        if warm:  # start within ~0.05 rad, as after a time step
            w = 0.05 * rng.normal(size=3)
            q0 = np.array(K._rot_to_quat(*Rr.ravel()))
            dq = np.array([1.0, *(w / 2)])
            q = np.array([q0[0] * dq[0] - q0[1:] @ dq[1:], *(q0[0] * dq[1:] + dq[0] * q0[1:] + np.cross(q0[1:], dq[1:]))])
        else:
            q = np.array([1.0, 0.0, 0.0, 0.0])
        it = K.fcr_rotation(F, q, R)
        n_fallback += it < 0
        assert abs(np.linalg.det(R) - 1) < 1e-12
        if sr[1] + sr[2] > 0.1 * sr[0]:
            assert np.abs(R - Rr).max() < NEWTON_ROT_TOL
    if warm:  # a warm start must not need the SVD for well-conditioned F
        assert n_fallback < len(Fs) // 3


def test_one_newton_step_is_accepted_exactly_when_the_error_it_leaves_is_below_newton_err():
    # The element pass accepts a tet after one Newton step when twice the error it estimates is below
    # NEWTON_ERR (``_newton_step_h``: the leading term -2 (h.H h) H^-1 h of the error left).  From the SVD's
    # rotation turned by 1e-6 to 3e-3 rad (the step leaves 1e-19 to 1e-8 rad): every accepted step's
    # rotation is within NEWTON_ERR of the SVD's, and every step that left less than NEWTON_ERR / 4 is
    # accepted (the estimate is within a factor 2 of the error, not a loose bound that sends good steps
    # to a second one), on stretched, sheared and near-rest F.
    rng = np.random.default_rng(11)
    n_acc = n_rej = 0
    for i in range(400):
        kind = i % 3
        Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        if kind == 0:
            F = np.eye(3) + 1e-3 * rng.normal(size=(3, 3))
        elif kind == 1:
            F = Q @ np.diag(rng.uniform(0.5, 2.0, 3)) @ Q.T @ _rodrigues(rng.normal(size=3), 1.0)
        else:
            F = np.eye(3) + 0.2 * rng.normal(size=(3, 3))
        Ur, sr, Vr = signed_svd_np(F)
        if sr[1] + sr[2] < 0.3 * sr[0]:
            continue
        Rr = Ur @ Vr.T
        theta = 10.0 ** rng.uniform(-6.0, np.log10(3e-3))
        R0 = Rr @ _rodrigues(rng.normal(size=3), theta)
        q = K._rot_to_quat(*R0.ravel())
        nw, nx, ny, nz, _hh, ok, _hx, _hy, _hz, small = K._newton_step_h(*F.ravel(), *q)
        assert ok
        R1 = np.array(K._quat_to_rot(nw, nx, ny, nz)).reshape(3, 3)
        E = R1.T @ Rr
        err = 0.5 * np.linalg.norm([E[2, 1] - E[1, 2], E[0, 2] - E[2, 0], E[1, 0] - E[0, 1]])
        if small:
            n_acc += 1
            assert err < K.NEWTON_ERR
        else:
            n_rej += 1
            assert err >= 0.25 * K.NEWTON_ERR
    assert n_acc > 100 and n_rej > 50


def test_first_piola_cofactor_form_matches_eq8_and_is_finite_when_flat():
    rng = np.random.default_rng(2)
    mu, lam = 3.0, 7.0
    P = np.empty((3, 3))
    for F in random_matrices(rng, 60):
        J = np.linalg.det(F)
        K.first_piola(F, mu, lam, P)
        assert np.all(np.isfinite(P))
        if abs(J) > 1e-3:
            U, _s, V = signed_svd_np(F)
            ref = 2 * mu * (F - U @ V.T) + lam * J * (J - 1) * np.linalg.inv(F).T
            assert np.abs(P - ref).max() < 1e-11 * max(1.0, np.abs(ref).max())
    K.first_piola(np.diag([1.0, 0.0, 1.0]), mu, lam, P)  # J = 0: the volume term pushes y open
    np.testing.assert_allclose(P, np.diag([0.0, -(2 * mu + lam), 0.0]), atol=1e-14)


# ------------------------------------------------------------------------------------
# Elastic forces, energy, active strain
# ------------------------------------------------------------------------------------
def _perturbed_system(seed=3, amp=0.3):
    nodes, tets = box_grid((1.0, 0.8, 0.6), (2, 2, 2))
    sysm = FEMSystem(nodes, tets, E=1000.0, nu=0.3)
    rng = np.random.default_rng(seed)
    sysm.x += amp * rng.normal(size=sysm.x.shape)
    return sysm


def test_elastic_forces_match_numpy_reference_with_inverted_tets():
    s = _perturbed_system()
    assert s.count_inverted() > 0
    f = s.elastic_forces()
    ref = forces_np(s.x, s.tets, s.Dm_inv, s.vol, s.mu, s.lam)
    assert np.abs(f - ref).max() < FORCE_REF_TOL * np.abs(ref).max()
    assert np.abs(f.sum(axis=0)).max() < 1e-12 * np.abs(f).max()  # eq. 10: no net force
    # second call: warm-started rotations give the same forces
    assert np.abs(s.elastic_forces() - ref).max() < FORCE_REF_TOL * np.abs(ref).max()


def _rodrigues(axis, angle):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    return np.eye(3) + np.sin(angle) * k + (1.0 - np.cos(angle)) * (k @ k)


def _tet_rows(ws, row, n, nt):
    """Rows row..row+n-1 of a blocked per-tet array (n_blocks, k LANES) as (n_tets, n)."""
    L = K.LANES
    return ws[:, row * L:(row + n) * L].reshape(-1, n, L).transpose(0, 2, 1).reshape(-1, n)[:nt]


def _quat_mul(a, b):
    """Row-wise quaternion products a b of (n, 4) arrays (w, x, y, z)."""
    w = a[:, 0] * b[:, 0] - np.sum(a[:, 1:] * b[:, 1:], axis=1)
    v = a[:, :1] * b[:, 1:] + b[:, :1] * a[:, 1:] + np.cross(a[:, 1:], b[:, 1:])
    return np.column_stack([w, v])


@pytest.mark.parametrize("spin", [2e-3, 0.05])  # [rad] per call: a fast tet's turn per step, and 25 times that
def test_predicted_rotation_follows_a_steady_spin(spin):
    # A deformed mesh turned by the same angle at every call, as a spinning body between steps: from the
    # third call on, the predicted rotation (last rotation times last increment) is within NEWTON_TOL of
    # the answer, so one Newton step is accepted for every tet and nothing takes the slow path; the kept
    # increment is the half-angle of the turn.  Then the turn speeds up by 2 % (the prediction is off by
    # 1 % of the turn).  At every call the forces match the SVD reference and every tet's rotation the
    # SVD's to NEWTON_ROT_TOL, whichever path it took.
    nodes, tets = box_grid((1.0, 0.8, 0.6), (2, 2, 2))
    s = FEMSystem(nodes, tets, E=1000.0, nu=0.3)
    base = s.X + 0.02 * np.random.default_rng(8).normal(size=s.X.shape)  # strains of a few per cent
    axis = np.array([0.3, 1.0, -0.4])
    nt = s.n_tets
    angle_k = 0.0
    for k in range(8):
        q0 = _tet_rows(s.q_ws, 0, 4, nt)
        pred = _quat_mul(q0, np.column_stack([np.ones(nt), _tet_rows(s.q_ws, K.Q_D, 3, nt)]))
        angle_k += 0.0 if k == 0 else (spin if k < 6 else 1.02 * spin)
        s.x[:] = base @ _rodrigues(axis, angle_k).T
        f = np.zeros_like(s.x)
        n_slow = K.elastic_forces(s.x, s.tets, s.Dm_inv_eff, s.coef, s.q_ws, s.F_work, s.H_work, f)
        ref = forces_np(s.x, s.tets, s.Dm_inv, s.vol, s.mu, s.lam)
        assert np.abs(f - ref).max() < FORCE_REF_TOL * np.abs(ref).max()
        q = _tet_rows(s.q_ws, 0, 4, nt)
        for e, t in enumerate(s.tets):
            Ds = np.stack([s.x[t[1]] - s.x[t[0]], s.x[t[2]] - s.x[t[0]], s.x[t[3]] - s.x[t[0]]], axis=1)
            U, _s, V = signed_svd_np(Ds @ s.Dm_inv[e])
            R = np.array(K._quat_to_rot(*q[e])).reshape(3, 3)
            assert np.abs(R - U @ V.T).max() < NEWTON_ROT_TOL
        if 2 <= k < 6:
            assert n_slow == 0
            rel = _quat_mul(pred * np.array([1.0, -1.0, -1.0, -1.0]), _tet_rows(s.q_ws, 0, 4, nt))
            angle = 2.0 * np.arctan2(np.linalg.norm(rel[:, 1:], axis=1), np.abs(rel[:, 0]))
            assert angle.max() < K.NEWTON_TOL
            d = _tet_rows(s.q_ws, K.Q_D, 3, nt)
            np.testing.assert_allclose(np.linalg.norm(d, axis=1), np.tan(spin / 2), rtol=1e-6)


def test_deformation_gradient_and_metric_kernels_match_numpy():
    s = _perturbed_system(seed=5)
    F = np.empty((s.n_tets, 3, 3))
    K.deformation_gradients(s.x, s.tets, s.Dm_inv, F)
    p = s.x[s.tets]
    Ds = np.stack([p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]], axis=2)
    np.testing.assert_allclose(F, Ds @ s.Dm_inv, rtol=0, atol=1e-13 * np.abs(F).max())
    J = np.linalg.det(F)
    sig = np.array([signed_svd_np(f)[1] for f in F])
    assert s.min_J() == pytest.approx(J.min(), rel=1e-12)
    assert s.count_inverted() == np.count_nonzero(J <= 0)
    assert s.max_principal_strain() == pytest.approx(np.abs(sig - 1).max(), rel=1e-12)


def test_elastic_forces_are_minus_the_energy_gradient():
    s = _perturbed_system(seed=4)
    f = s.elastic_forces()
    assert abs(s.elastic_energy() - energy_np(s.x, s.tets, s.Dm_inv, s.vol, s.mu, s.lam)) < 1e-12 * s.elastic_energy()
    x0 = s.x.copy()
    h = 1e-6
    grad = np.zeros_like(f)
    for i in range(len(x0)):
        for d in range(3):
            s.x[:] = x0
            s.x[i, d] += h
            ep = s.elastic_energy()
            s.x[i, d] -= 2 * h
            grad[i, d] = (ep - s.elastic_energy()) / (2 * h)
    s.x[:] = x0
    assert np.abs(f + grad).max() < FD_GRAD_TOL * np.abs(f).max()


def test_active_strain_rest_shape_has_zero_force_and_energy():
    nodes, tets = box_grid((1.0, 0.5, 0.5), (2, 1, 1))
    s = FEMSystem(nodes, tets, E=1000.0, nu=0.3)
    axis = np.tile([1.0, 0.0, 0.0], (s.n_tets, 1))
    A = np.empty((s.n_tets, 3, 3))
    K.axial_active_strain(axis, np.full(s.n_tets, 0.8), np.full(s.n_tets, 1.0 / np.sqrt(0.8)), A)
    np.testing.assert_allclose(A[0], np.diag([0.8, 1 / np.sqrt(0.8), 1 / np.sqrt(0.8)]), rtol=1e-15)
    s.set_active_strain(A)
    # Current shape = A times rest: the elastic part F A^-1 is the identity.
    s.x[:] = nodes @ A[0].T
    f = s.elastic_forces()
    assert np.abs(f).max() < 1e-12 * s.mu[0] * s.vol.max() ** (2 / 3)
    assert s.elastic_energy() < 1e-24
    # At the passive rest shape the energy is sum V Psi(A^-1), over the rest volume.
    s.x[:] = nodes
    sig = np.sort(1 / np.diag(A[0]))[::-1]
    psi = s.mu[0] * np.sum((sig - 1) ** 2) + 0.5 * s.lam[0] * (np.prod(sig) - 1) ** 2
    assert abs(s.elastic_energy() - psi * s.vol.sum()) < 1e-12 * psi * s.vol.sum()
    # ... and the muscle pulls: the forces are those of the numpy reference with Dm^-1 A^-1.
    ref = forces_np(s.x, s.tets, s.Dm_inv_eff, s.vol, s.mu, s.lam)
    assert np.abs(s.elastic_forces() - ref).max() < FORCE_REF_TOL * np.abs(ref).max()
    s.set_active_strain(None)
    assert np.abs(s.elastic_forces()).max() < 1e-12


# ------------------------------------------------------------------------------------
# Mass, damping, linear solve
# ------------------------------------------------------------------------------------
def test_lumped_mass_and_damping_force_match_the_matrix():
    nodes, tets = box_grid((1.0, 2.0, 0.5), (2, 3, 2), tets_per_cell=5)
    s = FEMSystem(nodes, tets, rho=3.0, gamma=7.0)
    assert abs(s.mass.sum() - 3.0 * 1.0) < 1e-12  # eq. 12 conserves rho * V
    v = np.random.default_rng(5).normal(size=nodes.shape)
    f = np.zeros_like(v)
    K.damping_forces(v, s.tets, s.vol, s.gamma, f)
    np.testing.assert_allclose(f, -(s.D @ v), atol=DAMPING_TOL * np.abs(f).max())
    np.testing.assert_allclose(s.D @ np.ones(len(nodes)), 0.0, atol=1e-12)  # no damping of translation


def test_skyline_cholesky_solve_matches_spsolve():
    nodes, tets = box_grid((3.0, 1.0, 1.0), (6, 2, 2))
    s = FEMSystem(nodes, tets, gamma=40.0)
    mask = np.isclose(nodes[:, 0], 0.0)
    solver = build_solver(s.mass, s.D, mask, 1e-3)
    A = (sp.diags(s.mass) + 1e-3 * s.D).tocsr()[solver.perm][:, solver.perm]
    b = np.random.default_rng(6).normal(size=(len(solver.perm), 3))
    x = b.copy()
    K.skyline_solve(solver.sky_first, solver.sky_ptr, solver.sky_L, x)
    ref = spl.spsolve(A.tocsc(), b)
    assert np.abs(x - ref).max() < SOLVE_TOL * np.abs(ref).max()


def test_skyline_cholesky_reports_indefinite_matrix():
    first = np.array([0, 0], dtype=np.int64)
    ptr = np.array([0, 1, 3], dtype=np.int64)
    val = np.array([1.0, 2.0, 1.0])  # [[1, 2], [2, 1]] is indefinite
    assert K.skyline_cholesky(first, ptr, val) == 2


# ------------------------------------------------------------------------------------
# One step of the advance kernel against a numpy step
# ------------------------------------------------------------------------------------
def numpy_step(s, dt, g, f_ext, mask):
    """Eqs. 14-15 with dense linear algebra; fixed nodes move with their velocity."""
    n = s.n_nodes
    free = ~mask
    fE = forces_np(s.x, s.tets, s.Dm_inv, s.vol, s.mu, s.lam)
    f = fE + s.mass[:, None] * g + f_ext
    D = s.D.toarray()
    A = np.diag(s.mass) + dt * D
    v_new = s.v.copy()
    rhs = s.mass[free, None] * s.v[free] + dt * f[free] - dt * D[np.ix_(free, mask)] @ s.v[mask]
    v_new[free] = np.linalg.solve(A[np.ix_(free, free)], rhs)
    x_new = s.x + dt * v_new
    f_fixed = fE[mask] - D[mask] @ v_new
    assert n == len(x_new)
    return x_new, v_new, f_fixed


def test_advance_one_step_matches_numpy_step():
    nodes, tets = box_grid((1.0, 0.5, 0.5), (3, 2, 2))
    s = FEMSystem(nodes, tets, E=500.0, nu=0.35, rho=2.0, gamma=30.0)
    rng = np.random.default_rng(7)
    s.x += 0.05 * rng.normal(size=s.x.shape)
    s.v[:] = rng.normal(size=s.v.shape)
    mask = np.isclose(nodes[:, 0], 0.0)
    s.set_fixed(mask)
    f_ext = rng.normal(size=nodes.shape)
    g = np.array([0.0, -9.81, 0.0])
    dt = 1e-3
    x_ref, v_ref, ff_ref = numpy_step(s, dt, g, f_ext, mask)
    r = s.advance(1, dt=dt, gravity=g, f_ext=f_ext)
    assert r.ok and r.steps == 1
    assert np.abs(s.v - v_ref).max() < STEP_TOL * np.abs(v_ref).max()
    assert np.abs(s.x - x_ref).max() < STEP_TOL * np.abs(x_ref).max()
    ff = s.fixed_node_forces()
    assert np.abs(ff - ff_ref).max() < STEP_TOL * np.abs(ff_ref).max()


def test_factor_is_cached_per_mask_and_dt():
    nodes, tets = box_grid((1.0, 1.0, 1.0), (2, 2, 2))
    s = FEMSystem(nodes, tets)
    a = s.solver(1e-3)
    assert s.solver(1e-3) is a
    assert s.solver(2e-3) is not a
    s.set_fixed(np.isclose(nodes[:, 1], 1.0))
    b = s.solver(1e-3)
    assert b is not a and len(b.fixed) == 9
    s.set_fixed(np.zeros(len(nodes), dtype=bool))
    assert s.solver(1e-3) is a


# ------------------------------------------------------------------------------------
# Contact and instability
# ------------------------------------------------------------------------------------
def test_ground_contact_projection_and_coulomb_friction():
    f = np.zeros(T.N_TERRAIN_PARAMS)
    x = np.array([[0.0, -0.1, 0.0], [1.0, -0.2, 0.0], [2.0, 0.3, 0.0], [3.0, -0.1, 0.0]])
    v = np.array([[1.0, -2.0, 0.0], [0.5, -2.0, 0.0], [1.0, -2.0, 0.0], [1.0, 3.0, 0.0]])
    K.ground_contact_coulomb(x, v, np.arange(4, dtype=np.int64), T.PLANE, f, 0.4)
    np.testing.assert_allclose(x[:, 1], [0.0, 0.0, 0.3, 0.0])
    np.testing.assert_allclose(v[0], [1.0 - 0.4 * 2.0, 0.0, 0.0])  # slides, slowed by mu |v_n|
    np.testing.assert_allclose(v[1], [0.0, 0.0, 0.0])  # |v_t| < mu |v_n|: sticks
    np.testing.assert_allclose(v[2], [1.0, -2.0, 0.0])  # not in contact
    np.testing.assert_allclose(v[3], [1.0, 3.0, 0.0])  # leaving: projected, velocity kept
    # slope: the normal is tilted, the node ends on the plane
    fs = f.copy()
    fs[1] = 0.3
    p = np.array([[1.0, 0.0, 0.0]])
    vv = np.array([[0.0, -1.0, 0.0]])
    K.ground_contact_coulomb(p, vv, np.zeros(1, dtype=np.int64), T.SLOPE, fs, 0.0)
    assert abs(T.signed_distance(T.SLOPE, fs, *p[0])) < 1e-15
    n = np.array(T.surface_normal(T.SLOPE, fs, *p[0]))
    assert abs(vv[0] @ n) < 1e-15


def test_instability_is_reported_not_raised():
    nodes, tets = box_grid((0.1, 0.1, 0.1), (2, 2, 2))
    s = FEMSystem(nodes, tets, E=4000.0, nu=0.4, rho=1.0, gamma=0.0)
    s.x[:, 1] *= 1.2
    r = s.advance(500, dt=0.01, gravity=(0, 0, 0))  # far above the explicit limit
    assert not r.ok and r.steps < 500 and r.status_name == "unstable"
    s2 = FEMSystem(nodes, tets)
    s2.v[0] = [50.0, 0.0, 0.0]
    r2 = s2.advance(10, dt=1e-4, gravity=(0, 0, 0), v_limit=10.0)
    assert r2.status == K.STATUS_RUNAWAY and r2.steps == 0
    s3 = FEMSystem(nodes, tets)
    s3.x[3, 0] = np.nan
    r3 = s3.advance(10, dt=1e-4)
    assert r3.status == K.STATUS_NONFINITE and r3.steps == 0


def test_lame_parameters_footnote3():
    lam, mu = lame_parameters(4000.0, 0.4)
    assert lam == pytest.approx(4000 * 0.4 / (1.4 * 0.2))
    assert mu == pytest.approx(4000 / 2.8)
    with pytest.raises(ValueError):
        lame_parameters(1.0, 0.5)
    s = FEMSystem(*box_grid((1, 1, 1), (1, 1, 1)), E=np.arange(1.0, 7.0), nu=0.25)
    np.testing.assert_allclose(s.mu, np.arange(1.0, 7.0) / 2.5)
    assert damping_matrix(s.tets, s.vol, 2.0, s.n_nodes).shape == (8, 8)
