"""Analytic checks of the FEM body (VALIDATION.md): hanging bar, cantilever, rigid
rotation, inversion recovery, the damping step, ground contact.

Static states are reached by a damped relaxation run of the real time stepper.  The
static answer depends on neither the mass nor the damping, so both are chosen for a
fast relaxation: the damping of eq. 13 acts like a mesh Laplacian scaled by
gamma h^2, as does the elastic stiffness (scaled by lambda + 2 mu), so
gamma ~ (lambda + 2 mu) dt / h^2 overdamps every mode at about the same rate while
keeping the explicit elastic update stable.
"""
import numpy as np
import pytest

from bench_myriapoda.bodies.fem.mesh import box_grid
from bench_myriapoda.bodies.fem.system import DT_PAPER, FEMSystem
from bench_myriapoda.bodies.fem.analytic_systems import one_step_map_eigenvalues, single_node_tet
from bench_myriapoda.validation.references import cantilever_ratio, hanging_bar, rotation
from bench_myriapoda.world import terrain_kernels as T

BAR_TOL = 0.05              # hanging bar: relative error of the bottom displacement
BAR_NU0_TOL = 0.01          # nu = 0: linear tets + lumped load are nearly exact on any mesh
FIXED_FORCE_TOL = 1e-3      # fixed-node forces vs the weight they carry, relative
CANTILEVER_TOL = 0.05       # tip deflection vs Timoshenko beam theory, relative
RIGID_TOL = 1e-10           # |f| / (mu V^(2/3)) under a rigid motion
RECOVERY_TOL = 0.02         # node error after recovery / edge length of the cube
DAMPING_EXACT_TOL = 1e-10   # backward-Euler factor of a pure damping mode
DAMPING_OSC_TOL = 1e-6      # per-step amplitude factor of an oscillating damped mode
FRICTION_TOL = 0.05         # sliding distance vs v0^2 / (2 mu g)


# ------------------------------------------------------------------------------------
# Hanging bar under its own weight: u(bottom) = rho g L^2 / (2 E)
# ------------------------------------------------------------------------------------
def test_hanging_bar_converges_to_analytic_and_fixed_nodes_carry_the_weight():
    # nu = 0.3 with the top face clamped: the discretisation error is visible and
    # must shrink with refinement (measured ratios 0.945, 0.967, 0.979).  With
    # nu = 0 the problem is one-dimensional and linear tets with the lumped load
    # reproduce it on any mesh; checked below.
    ratios = []
    for n in (4, 8, 16):
        s, ratio = hanging_bar(n, nu=0.3)
        ratios.append(ratio)
        weight = s.mass[~s.fixed_mask].sum() * 9.81
        total = s.fixed_node_forces().sum(axis=0)
        # the mesh pulls the fixed nodes down with the weight of everything below them
        assert abs(total[1] + weight) < FIXED_FORCE_TOL * weight
        assert np.abs(total[[0, 2]]).max() < FIXED_FORCE_TOL * weight
    errors = [abs(1.0 - r) for r in ratios]
    assert errors[0] > errors[1] > errors[2], ratios
    assert all(r < 1.0 for r in ratios)  # linear tets converge from the stiff side
    assert errors[-1] < BAR_TOL, ratios
    _s, ratio0 = hanging_bar(4, nu=0.0)
    assert abs(1.0 - ratio0) < BAR_NU0_TOL


# ------------------------------------------------------------------------------------
# Cantilever with a tip load: P L^3 / (3 E I) + P L / (kappa G A)
# ------------------------------------------------------------------------------------
def test_cantilever_tip_deflection_converges_to_beam_theory():
    # Linear tets lock in bending: refine through the depth and along the length.
    # Measured tip ratios: 0.754, 0.925, 0.979 (1 cell across the width, nu = 0).
    ratios = [cantilever_ratio(c) for c in ((15, 3, 1), (30, 6, 1), (60, 12, 1))]
    errors = [abs(1.0 - r) for r in ratios]
    assert errors[0] > errors[1] > errors[2], ratios
    assert errors[-1] < CANTILEVER_TOL, ratios


# ------------------------------------------------------------------------------------
# Rigid motions produce no elastic force
# ------------------------------------------------------------------------------------
@pytest.mark.parametrize("tets_per_cell", [5, 6])
def test_rigid_rotation_gives_zero_force(tets_per_cell):
    nodes, tets = box_grid((1.0, 0.6, 0.4), (3, 2, 2), tets_per_cell=tets_per_cell)
    s = FEMSystem(nodes, tets)
    scale = s.mu.max() * s.vol.max() ** (2 / 3)
    rng = np.random.default_rng(11)
    for angle in (1e-3, 0.4, 2.0, np.pi - 1e-6):  # small ones by Newton, large by the SVD fallback
        R = rotation(rng.normal(size=3), angle)
        s.x[:] = nodes @ R.T + rng.normal(size=3)
        assert np.abs(s.elastic_forces()).max() < RIGID_TOL * scale
        # and from the warm start, after a further small rotation
        s.x[:] = s.x @ rotation(rng.normal(size=3), 0.01).T
        assert np.abs(s.elastic_forces()).max() < RIGID_TOL * scale
        assert s.elastic_energy() < (RIGID_TOL * scale) ** 2


# ------------------------------------------------------------------------------------
# Inversion recovery (paper presets)
# ------------------------------------------------------------------------------------
def kabsch_error(X, x):
    """Largest node distance between x and the best rigid placement of X."""
    Xc = X - X.mean(axis=0)
    xc = x - x.mean(axis=0)
    U, _s, Vt = np.linalg.svd(xc.T @ Xc)
    d = np.sign(np.linalg.det(U @ Vt))
    R = U @ np.diag([1.0, 1.0, d]) @ Vt
    return np.abs(xc - Xc @ R.T).max()


@pytest.mark.parametrize("how", ["flat", "folded", "scrambled"])
def test_squashed_or_inverted_mesh_recovers_its_rest_shape(how):
    nodes, tets = box_grid((1.0, 1.0, 1.0), (3, 3, 3))
    s = FEMSystem(nodes, tets)  # E = 4000, nu = 0.4, rho = 1, gamma = 50
    if how == "flat":  # every tet has J = 0
        s.x[:, 1] = 0.5
    elif how == "folded":  # the top half mirrored onto the bottom half: J = -1
        s.x[:, 1] = np.where(nodes[:, 1] > 0.5, 1.0 - nodes[:, 1], nodes[:, 1])
    else:
        s.x += 0.3 * np.random.default_rng(0).normal(size=s.x.shape)
    assert s.count_inverted() > 0
    r = s.advance(1500, dt=DT_PAPER, gravity=(0.0, 0.0, 0.0))
    assert r.ok
    assert np.all(np.isfinite(s.x))
    assert s.count_inverted() == 0 and s.min_J() > 0.9
    assert kabsch_error(nodes, s.x) < RECOVERY_TOL * 1.0
    assert s.max_principal_strain() < RECOVERY_TOL


# ------------------------------------------------------------------------------------
# The damping step of eqs. 13-14
# ------------------------------------------------------------------------------------
def test_backward_euler_damping_factor_of_a_pure_damping_mode():
    """v^{n+1} = (M + h D)^-1 M v^n: a generalised eigenvector D phi = lam M phi
    decays by exactly 1 / (1 + lam h) per step (at the rest shape f_E = 0)."""
    from scipy.linalg import eigh

    nodes, tets = box_grid((1.0, 0.5, 0.5), (2, 1, 1))
    s = FEMSystem(nodes, tets, gamma=300.0)
    mask = np.isclose(nodes[:, 0], 0.0)
    s.set_fixed(mask)
    free = ~mask
    Dff = s.D.toarray()[np.ix_(free, free)]
    lam_d, phi = eigh(Dff, np.diag(s.mass[free]))
    h = 1e-3
    for k in (0, len(lam_d) // 2, len(lam_d) - 1):
        s.x[:] = nodes
        s.v[:] = 0.0
        s.v[free, 2] = phi[:, k]
        s.advance(1, dt=h, gravity=(0.0, 0.0, 0.0))
        factor = s.v[free, 2] / phi[:, k]
        np.testing.assert_allclose(factor, 1.0 / (1.0 + lam_d[k] * h), rtol=DAMPING_EXACT_TOL)


def test_per_step_amplitude_factor_of_an_oscillating_damped_mode():
    """One free node on a tet whose other nodes are fixed.  The step
    v' = (v - h k x) / (1 + h c), x' = x + h v' (elastic explicit, damping implicit)
    has det = 1 / (1 + h c), so every underdamped mode decays by 1 / sqrt(1 + c h)
    per step, with c = M^-1 D = 3 gamma / rho for this node.

    VALIDATION.md lists 1 / sqrt(1 + (omega h)^2); that is the backward-Euler factor
    of an undamped oscillator and does not describe this scheme.  The parameters
    below make the two differ by far more than the tolerance.
    """
    rho, gamma, h = 1.0, 40.0, 1e-3
    c = 3.0 * gamma / rho
    # Linearised one-step map of (x3, v3) by central differences.
    ev = one_step_map_eigenvalues(single_node_tet(rho=rho, gamma=gamma, E=2.0e4, nu=0.3), node=3, h=h)
    assert np.all(np.abs(ev.imag) > 0)  # all three modes oscillate
    expected = 1.0 / np.sqrt(1.0 + c * h)
    np.testing.assert_allclose(np.abs(ev), expected, rtol=DAMPING_OSC_TOL)
    omega = np.abs(np.angle(ev)) / h
    assert np.all(np.abs(1.0 / np.sqrt(1.0 + (omega * h) ** 2) - expected) > 100 * DAMPING_OSC_TOL)


# ------------------------------------------------------------------------------------
# Ground contact: resting and Coulomb sliding
# ------------------------------------------------------------------------------------
def test_block_lands_rests_and_slides_the_coulomb_distance():
    nodes, tets = box_grid((0.2, 0.2, 0.2), (2, 2, 2))
    terrain = (T.PLANE, np.zeros(T.N_TERRAIN_PARAMS))
    mu_f, g = 0.5, 9.81
    s = FEMSystem(nodes, tets)
    s.x[:, 1] += 0.05
    r = s.advance(3000, dt=DT_PAPER, terrain=terrain, friction=mu_f)
    assert r.ok
    assert s.x[:, 1].min() >= 0.0
    assert np.abs(s.v).max() < 1e-6  # at rest on the ground
    assert abs(s.x[:, 1].mean() - 0.1) < 1e-3  # sagging under its own weight only slightly
    x0 = s.x[:, 0].mean()
    v0 = 1.0
    s.v[:, 0] = v0
    r = s.advance(3000, dt=DT_PAPER, terrain=terrain, friction=mu_f)
    assert r.ok and np.abs(s.v).max() < 1e-6
    dist = s.x[:, 0].mean() - x0
    assert abs(dist / (v0**2 / (2 * mu_f * g)) - 1.0) < FRICTION_TOL


def test_fixed_nodes_follow_their_prescribed_velocity():
    nodes, tets = box_grid((1.0, 0.5, 0.5), (2, 1, 1))
    s = FEMSystem(nodes, tets)
    mask = np.isclose(nodes[:, 0], 0.0)
    s.set_fixed(mask)
    s.v[mask] = [0.0, 0.3, 0.0]
    x0 = s.x[mask].copy()
    s.advance(30, dt=DT_PAPER, gravity=(0.0, 0.0, 0.0))
    np.testing.assert_allclose(s.x[mask], x0 + 30 * DT_PAPER * np.array([0.0, 0.3, 0.0]), rtol=1e-13)
    np.testing.assert_allclose(s.v[mask], [[0.0, 0.3, 0.0]] * mask.sum())
    assert s.kinetic_energy() > 0.0
