"""FEMSystem: the constant FEM model, its mutable state, and the calls into the kernels.

Orchestration only; the numerics live in ``kernels.py``.  The model follows the
myriapod paper's App. A (fixed-corotational elasticity, lumped mass, the damping
of eq. 13 and the semi-implicit step of eqs. 14-15).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee

from ...core.kernel_records import plain
from . import kernels as K
from .mesh import lame_parameters, signed_volumes

# Paper presets (App. A).  The paper gives these without units; they are kept as
# its unitless values and read in SI units by this code.
DT_PAPER = 1.0 / 3000.0  # time step [s]
RHO_PAPER = 1.0          # density
E_PAPER = 4000.0         # Young's modulus
NU_PAPER = 0.4           # Poisson's ratio [-]
GAMMA_PAPER = 50.0       # damping coefficient of eq. 13

GRAVITY = (0.0, -9.81, 0.0)  # [m/s^2], y up
V_LIMIT_DEFAULT = 1.0e3      # [m/s] a node faster than this marks the run unstable

STATUS_NAMES = {K.STATUS_OK: "ok", K.STATUS_NONFINITE: "unstable", K.STATUS_RUNAWAY: "unstable"}
_MAX_CACHED_FACTORS = 16


@dataclass(frozen=True)
class AdvanceResult:
    """Outcome of ``FEMSystem.advance``: steps completed and the kernel status code."""

    steps: int
    status: int

    @property
    def ok(self) -> bool:
        return self.status == K.STATUS_OK

    @property
    def status_name(self) -> str:
        return STATUS_NAMES[self.status]


@dataclass(frozen=True)
class _Solver:
    """Factor of (M + dt D)_ff and the coupling blocks for one (fixed mask, dt)."""

    perm: np.ndarray       # (n_free,) node id of each solve row (RCM order)
    sky_first: np.ndarray  # (n_free,) skyline envelope
    sky_ptr: np.ndarray    # (n_free + 1,)
    sky_L: np.ndarray      # Cholesky factor values
    fp_ptr: np.ndarray     # CSR of D_fp: solve rows x fixed node ids
    fp_col: np.ndarray
    fp_val: np.ndarray
    fixed: np.ndarray      # (n_fixed,) fixed node ids
    pf_ptr: np.ndarray     # CSR of D_p*: fixed rows x all node ids
    pf_col: np.ndarray
    pf_val: np.ndarray


def damping_matrix(tets, vol, gamma, n_nodes):
    """Assembled damping matrix D of eq. 13 (scalar, shared by x, y, z): (n, n) CSR [N s/m].

    Element block D_e = gamma V_e (I_4 - 1/4 1 1^T), so f^D = -D v.
    """
    block = gamma * vol[:, None, None] * (np.eye(4)[None] - 0.25)
    rows = np.repeat(tets, 4, axis=1).ravel()
    cols = np.tile(tets, (1, 4)).ravel()
    return sp.csr_matrix((block.ravel(), (rows, cols)), shape=(n_nodes, n_nodes))


def build_solver(mass, D, fixed_mask, dt):
    """Factorize (M + dt D) restricted to the free nodes; built once per (mask, dt).

    Reverse Cuthill-McKee ordering keeps the skyline envelope narrow; the Cholesky
    factorization itself runs in numba (``kernels.skyline_cholesky``).
    """
    free = np.flatnonzero(~fixed_mask)
    fixed = np.flatnonzero(fixed_mask)
    A = (sp.diags(mass) + dt * D).tocsr()
    Aff = A[free][:, free]
    order = reverse_cuthill_mckee(Aff.tocsr(), symmetric_mode=True).astype(np.int64)
    perm = free[order]
    low = sp.tril(Aff[order][:, order]).tocoo()
    n = len(free)
    first = np.arange(n, dtype=np.int64)
    np.minimum.at(first, low.row, low.col.astype(np.int64))
    ptr = np.zeros(n + 1, dtype=np.int64)
    ptr[1:] = np.cumsum(np.arange(n) - first + 1)
    val = np.zeros(ptr[-1])
    np.add.at(val, ptr[low.row] + low.col - first[low.row], low.data)
    info = K.skyline_cholesky(first, ptr, val)
    if info != 0:
        raise np.linalg.LinAlgError(f"(M + dt D)_ff is not positive definite at row {info - 1}")
    diag = ptr[1:] - 1
    val[diag] = 1.0 / val[diag]  # ``skyline_solve`` multiplies by the inverted diagonal
    Dfp = D[perm][:, fixed].tocsr()
    Dfp.sort_indices()
    Dp = D[fixed].tocsr()
    Dp.sort_indices()
    return _Solver(
        perm=perm, sky_first=first, sky_ptr=ptr, sky_L=val,
        fp_ptr=Dfp.indptr.astype(np.int64), fp_col=fixed[Dfp.indices].astype(np.int64),
        fp_val=Dfp.data.astype(np.float64),
        fixed=fixed.astype(np.int64),
        pf_ptr=Dp.indptr.astype(np.int64), pf_col=Dp.indices.astype(np.int64),
        pf_val=Dp.data.astype(np.float64),
    )


class FEMSystem:
    """A tetrahedral fixed-corotational FEM body (paper App. A).

    nodes: (n_nodes, 3) rest positions [m]; tets: (n_tets, 4), positively oriented.
    E [Pa], nu [-], rho [kg/m^3]: scalars or per-tet arrays; gamma: damping
    coefficient of eq. 13 [N s/m^4].  Defaults are the paper's presets.
    State: ``x``, ``v`` (n_nodes, 3) [m], [m/s], modified in place by ``advance``.
    mass: (n_nodes,) lumped nodal masses [kg] in place of eq. 12's per-tet lumping (None: eq. 12).
    Fixed (Dirichlet) nodes: ``set_fixed(mask)``; their x and v are prescribed by
    the caller (write ``x[fixed_nodes]``, ``v[fixed_nodes]``) and during a call to
    ``advance`` they move with their velocity.
    """

    def __init__(self, nodes, tets, *, E=E_PAPER, nu=NU_PAPER, rho=RHO_PAPER, gamma=GAMMA_PAPER, mass=None):
        self.X = np.array(nodes, dtype=np.float64, order="C")  # copies: the rest shape is owned
        self.tets = np.array(tets, dtype=np.int64, order="C")
        n, m = len(self.X), len(self.tets)
        if self.tets.ndim != 2 or self.tets.shape[1] != 4 or self.tets.min() < 0 or self.tets.max() >= n:
            raise ValueError("tets must be (n_tets, 4) indices into nodes")
        if np.any(signed_volumes(self.X, self.tets) <= 0.0):
            raise ValueError("every tet needs positive volume; fix the orientation with mesh.orient_tets")
        self.Dm_inv = np.empty((m, 3, 3))
        self.vol = np.empty(m)
        K.rest_shape(self.X, self.tets, self.Dm_inv, self.vol)
        self.Dm_inv_eff = self.Dm_inv.copy()
        lam, mu = lame_parameters(E, nu)
        # writeable copies: a read-only broadcast view (E given per tet) would give the kernels taking
        # them a second compiled signature
        self.lam = np.array(np.broadcast_to(lam, (m,)), dtype=np.float64)
        self.mu = np.array(np.broadcast_to(mu, (m,)), dtype=np.float64)
        self.rho = np.array(np.broadcast_to(np.asarray(rho, dtype=float), (m,)))
        self.gamma = float(gamma)
        self.mass = np.empty(n)
        if mass is None:
            K.lumped_mass(self.tets, self.vol, self.rho, self.mass)
        else:  # a caller's own lumping (``mesh.cell_lumped_mass``)
            self.mass[:] = np.broadcast_to(np.asarray(mass, dtype=float), (n,))
        if np.any(self.mass <= 0.0):
            raise ValueError("every node must belong to a tet with positive mass")
        self.D = damping_matrix(self.tets, self.vol, self.gamma, n)

        self.coef = np.zeros((K.n_tet_blocks(m), K.N_COEF * K.LANES))
        K.pack_tet_coefficients(self.Dm_inv_eff, self.vol, self.mu, self.lam, self.coef)

        self.x = self.X.copy()
        self.v = np.zeros((n, 3))
        # Public, for the bodies that step this system inside their own kernels (the fem chain, the hybrid's
        # links).  q_ws (n_tet_blocks, N_Q LANES): the per-tet rotations (quaternions) that warm-start the
        # corotational Newton solve: part of the dynamic state, since each step's solve starts from the last
        # one's, so whoever saves and restores the state (a benchmark repeating a run) saves and restores it
        # too (in place).  F_work, H_work: the blocked scratch of the element pass (``kernels.new_tet_workspace``).
        self.q_ws, self.F_work, self.H_work = K.new_tet_workspace(m)
        # inc_ptr, inc_off: each node's entries of H_work, for the node-by-node force sums of the step
        self.inc_ptr, self.inc_off = K.node_incidence(self.tets, n)
        self._f_work = np.zeros((n, 3))
        self._f_ext_zero = np.zeros((n, 3))
        self._solvers: dict[tuple[bytes, float], _Solver] = {}
        self.set_fixed(np.zeros(n, dtype=bool))

    # ---- configuration -------------------------------------------------------------
    @property
    def n_nodes(self) -> int:
        return len(self.X)

    @property
    def n_tets(self) -> int:
        return len(self.tets)

    def set_fixed(self, mask):
        """Choose the fixed (Dirichlet) nodes: mask (n_nodes,) bool.  Factors are cached per mask."""
        mask = np.asarray(mask, dtype=bool)
        if mask.shape != (self.n_nodes,):
            raise ValueError(f"fixed mask must have shape ({self.n_nodes},), got {mask.shape}")
        if mask.all():
            raise ValueError("at least one node must be free")
        self.fixed_mask = mask.copy()
        self.fixed_nodes = np.flatnonzero(mask).astype(np.int64)
        self.free_nodes = np.flatnonzero(~mask).astype(np.int64)
        self._f_fixed = np.zeros((len(self.fixed_nodes), 3))
        self._b_work = np.zeros((len(self.free_nodes), 3))

    def set_active_strain(self, A=None):
        """Per-tet active deformation A: (n_tets, 3, 3) of the rest shape, or None for passive.

        The elastic deformation becomes F A^-1 (see kernels module docstring).
        """
        if A is None:
            self.Dm_inv_eff[:] = self.Dm_inv
        else:
            A = np.ascontiguousarray(np.broadcast_to(A, (self.n_tets, 3, 3)), dtype=np.float64)
            if np.any(np.linalg.det(A) <= 0.0):
                raise ValueError("active strain A must have det A > 0")
            K.active_dm_inv(self.Dm_inv, A, self.Dm_inv_eff)
        K.pack_tet_coefficients(self.Dm_inv_eff, self.vol, self.mu, self.lam, self.coef)

    def solver(self, dt) -> _Solver:
        """The factorization for the current fixed mask and dt (built on first use, then cached)."""
        key = (np.packbits(self.fixed_mask).tobytes(), float(dt))
        s = self._solvers.get(key)
        if s is None:
            if len(self._solvers) >= _MAX_CACHED_FACTORS:
                self._solvers.pop(next(iter(self._solvers)))
            s = build_solver(self.mass, self.D, self.fixed_mask, float(dt))
            self._solvers[key] = s
        return s

    # ---- time stepping -------------------------------------------------------------
    def advance(self, n_steps, dt=DT_PAPER, gravity=GRAVITY, f_ext=None, terrain=None,
                friction=0.5, v_limit=V_LIMIT_DEFAULT) -> AdvanceResult:
        """Advance ``n_steps`` semi-implicit steps of ``dt`` [s] in one numba call.

        gravity: (3,) [m/s^2]; f_ext: (n_nodes, 3) [N] constant over the call or None;
        terrain: None or (kind, params) from ``world.terrain_kernels`` for ground
        contact of the free nodes with Coulomb coefficient ``friction``;
        v_limit [m/s]: runaway speed.  Returns an ``AdvanceResult``.
        """
        s = self.solver(dt)
        g = np.ascontiguousarray(gravity, dtype=np.float64)
        fe = self._f_ext_zero if f_ext is None else np.ascontiguousarray(f_ext, dtype=np.float64)
        if fe.shape != (self.n_nodes, 3):
            raise ValueError(f"f_ext must have shape ({self.n_nodes}, 3)")
        if terrain is None:
            contact, kind, params = False, 0, np.zeros(8)
        else:
            contact, kind, params = True, int(terrain[0]), np.ascontiguousarray(terrain[1], dtype=np.float64)
        mesh = K.FEMMesh(tets=self.tets, inc_ptr=self.inc_ptr, inc_off=self.inc_off, coef=self.coef, mass=self.mass)
        solve = K.FEMSolve(perm=s.perm, sky_first=s.sky_first, sky_ptr=s.sky_ptr, sky_L=s.sky_L, fp_ptr=s.fp_ptr,
                           fp_col=s.fp_col, fp_val=s.fp_val, fixed=s.fixed, pf_ptr=s.pf_ptr, pf_col=s.pf_col,
                           pf_val=s.pf_val)
        ground = K.FEMGround(contact=contact, terrain_kind=kind, terrain_params=params, mu_friction=float(friction),
                             v_limit=float(v_limit))
        work = K.FEMWork(q_ws=self.q_ws, f_fixed=self._f_fixed, f_work=self._f_work, b_work=self._b_work,
                         F_work=self.F_work, H_work=self.H_work)
        steps, status = K.advance(self.x, self.v, plain(mesh), g, fe, float(dt), int(n_steps), plain(solve),
                                  plain(ground), plain(work))
        return AdvanceResult(int(steps), int(status))

    def elastic_forces(self):
        """Elastic nodal forces at the current x, (n_nodes, 3) [N] (eqs. 7-11)."""
        f = np.zeros((self.n_nodes, 3))
        K.elastic_forces(self.x, self.tets, self.Dm_inv_eff, self.coef, self.q_ws,
                         self.F_work, self.H_work, f)
        return f

    def fixed_node_forces(self):
        """Elastic + damping force [N] the mesh exerts on each fixed node, (n_fixed, 3)
        in ``fixed_nodes`` order, averaged over the last ``advance`` call (Sec. 3 step 2)."""
        return self._f_fixed.copy()

    # ---- energies and metrics ------------------------------------------------------
    def elastic_energy(self) -> float:
        """Elastic energy [J] of the current state (with the active strain, if any)."""
        return float(K.elastic_energy(self.x, self.tets, self.Dm_inv_eff, self.vol, self.mu, self.lam))

    def kinetic_energy(self) -> float:
        """Kinetic energy 1/2 sum m_i |v_i|^2 [J]."""
        return float(0.5 * np.einsum("i,ij,ij->", self.mass, self.v, self.v))

    def gravity_energy(self, gravity=GRAVITY) -> float:
        """Potential energy of gravity, -sum m_i g . x_i [J]."""
        return float(-np.einsum("i,ij,j->", self.mass, self.x, np.asarray(gravity, dtype=float)))

    def _invariants(self):
        J = np.empty(self.n_tets)
        sigma = np.empty((self.n_tets, 3))
        K.tet_invariants(self.x, self.tets, self.Dm_inv, J, sigma)
        return J, sigma

    def min_J(self) -> float:
        """Smallest det F over the tets (F measured from the passive rest shape)."""
        return float(self._invariants()[0].min())

    def count_inverted(self) -> int:
        """Number of tets with det F <= 0."""
        return int(np.count_nonzero(self._invariants()[0] <= 0.0))

    def max_principal_strain(self) -> float:
        """Largest principal (Biot) strain magnitude max |sigma_i - 1| over the tets [-]."""
        return float(np.abs(self._invariants()[1] - 1.0).max())
