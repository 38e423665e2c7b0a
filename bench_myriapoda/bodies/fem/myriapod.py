"""``fem`` for legged creatures: one FEM mesh, stiff blocks where the rigid segments were.

The centipede of ``models/centipede.toml`` with every part deformable: a single
connected structured tet mesh (``mesh.box_grid`` with its x coordinates
remapped, like ``chain_grid`` but with alternating block and link lengths)
along -x from the head face at x = 0.  Block s (the rigid segment s of the
hybrid) spans x in [-s P - L_rigid, -s P], link k the gap between block k and
k + 1 (P = L_rigid + L_link).  Tets in a block have Young's modulus
E * ``rigid_stiffness_factor`` and density ``block_density_kg_m3`` (default: what
makes the whole body weigh ``creature.mass_kg``); link tets are the App. A material (E, nu, gamma,
``density_kg_m3``, default 1 kg/m^3).  Each part has the hybrid's cells along x
(``resolution``), so a link is meshed exactly like the hybrid's link.

What it shares with the rigid segment chain (issue 30 item 4)
-------------------------------------------------------------
The hybrid and the legged mass-spring bodies are one chain of rigid boxes with a pluggable link element
(``rigid_chain``: the boxes' step, corner contacts and friction, the attached link nodes; ``carried_boxes``:
the legs' support of a box).  This body shares what its segments have in common with theirs: the legged
body's interface and support sequence (``segment_chain.LeggedSegments``: ``apply_support``, ``sense``, the
segments' corner contact for the observation), the fused walk's interface (``legged_chunk``), the suite's
point contact for every node (``contact_kernels.advance_point``, as the chain's free link nodes), the
placement (``placement.place_points``), the case's contact scalars (``case_scalars``) and the element
quality metrics (``element_quality``, with the hybrid's links).  It does not share the rigid boxes, by
design: its segments ARE the deformable mesh's stiff blocks (a rigid box joined to FEM links is the hybrid
body), so there is no box state (c, q, v, w) to step or carry.  A segment's pose is its nodes' best fit,
not a state; its support is a penalty on its leg-attachment nodes (below), not a kinematic box; its ground
contact is per node, not per box corner.  Boxes bolted onto it would make it the hybrid again.

Imposing a supported segment's target pose (paper Sec. 4.1)
-----------------------------------------------------------
Choice: stiff penalty springs, integrated implicitly per node, NOT Dirichlet
nodes.  With 18 segments the supported set changes every few steps and takes
far more than the 16 factorizations ``FEMSystem`` caches, so Dirichlet masks
would refactor (M + dt D)_ff constantly.  Instead the whole mesh is free (one
factorization for the run) and after the velocity solve of eq. 14 every
leg-attachment node p of a supported block (its nodes on the two side faces
z = +-w/2, where the legs attach) gets a spring k_p toward its target x_T,
integrated with backward Euler on that node alone.  The target is the
node's current offset from the block's best-fit pose carried rigidly to the
target pose, x_T = c_T + R_T R^T (x_p - c) (a deformed block keeps its
deformation instead of being snapped to its rest shape in one step, which
makes nodes jump by deformation / dt and blew the walk up):

    v_p = (m_p v*_p + dt k_p (x_T - x_p)) / (m_p + dt^2 k_p)

so x_p + dt v_p = x_T up to the factor m_p / (m_p + dt^2 k_p) of the
remaining error (about 1 % for k_p = 1e7 N/m, dt = 1/3000 s and the ~0.01 kg
nodes), unconditionally stable and without refactorization.  The rest of the
block follows elastically; the segment's pose is its nodes' best fit, so a
supported segment tracks its target within a tracking error that the tests
report (not exactly, unlike the rigid bodies).

In the dynamic stance (``legs.stance = "dynamic"``) the penalty holds a held block only: the STANCE legs push
every other supported block through friction-limited feet, their impulse given to its leg-attachment nodes
(``pushed_blocks``; ``push_support``, and the fused path's ``carry_feet``).

``segment_poses`` returns each block's best-fit rigid pose: the centroid of
its nodes and the polar rotation of sum (x_i - c)(X_i - X_c)^T (rest shape X).
The kernel (``advance_chain``) runs n steps per call: elastic forces (eqs.
7-11) + gravity, the velocity solve, the support penalty, ground contact of
every node (the suite's point-mass contact), x += dt v, blow-up checks.
"""
from __future__ import annotations

import math
from collections import namedtuple
from functools import cached_property

import numpy as np
from numba import njit

from ..case_scalars import contact_scalars
from ...world.terrain_kernels import distance_at_least, flat_ground
from ...world.world import StepWorld
from .. import step_status as S
from ..contact_kernels import advance_point
from ..friction_kernels import CONTACT_DISTANCE, friction_params, spine_between
from ..legged_chunk import LeggedPackOps, carry, chain_step, copy_frames, copy_rows, register
from ...core.kernel_records import plain
from ...core.protocols import Actuation, Observation
from ..placement import place_points
from ..segment_chain import LeggedSegments
from ..scene import Scene, compact, tet_boundary_faces
from .surfaces import FEM_BLOCK_SURFACE, FEM_SURFACE
from . import kernels as FK
from .kernels import elastic_forces_gathered, semi_implicit_velocity
from .element_quality import ElementQuality
from .mesh import box_grid, segment_cells, signed_volumes
from .system import FEMSystem
from .pushed_blocks import block_inertia, push_blocks, pushed_blocks
from ..dynamic_stance import stance_arrays, stance_params, stance_statistics

# Scalar parameters (``phys``).  No time step: dt is the step's argument (``advance_chain``).
R_N, R_TAN, MAX_SPEED, MAX_PEN, K_SUPPORT = range(5)
N_PHYS = 5

# ``advance_chain``'s records (namedtuples: numba compiles each as a struct of its fields, read by name).
# The chain's arrays: x, v (n_nodes, 3) [m], [m/s] UPDATED; mass (n_nodes,) [kg]; tets, inc_ptr, inc_off, coef,
# q_ws (UPDATED), F_work, H_work as ``fem.kernels.elastic_forces_gathered``; perm, sky_first, sky_ptr, sky_L, fp_ptr,
# fp_col, fp_val the factor of (M + dt D) with no fixed node (``FEMSystem.solver``); block_nodes (n_blocks, k) node
# ids of each block; node_spine (n_nodes,) the block whose spine a node's friction uses; att_nodes (n_att,)
# leg-attachment node ids, att_block (n_att,) their block, att_target (n_att, 3) [m] their targets at the end of
# the step (supported blocks only); support (n_blocks,) bool; scratch f_work (n_nodes, 3), b_work (n_nodes, 3),
# cent, spine (n_blocks, 3).
BlockChain = namedtuple("BlockChain", "x v mass tets inc_ptr inc_off coef q_ws F_work H_work perm sky_first sky_ptr "
                                      "sky_L fp_ptr fp_col fp_val block_nodes node_spine att_nodes att_block "
                                      "att_target support f_work b_work cent spine")
# The chain's constant contact parameters: fric_model, fric (``friction_kernels``); phys (N_PHYS,) the scalars above.
# The world (gravity, terrain: ``world.world.StepWorld``) and dt are the step's plain arguments, not here.
BlockChainParams = namedtuple("BlockChainParams", "fric_model fric phys")


def chain_mesh(n_blocks, block_length, link_length, height, width, cells, tets_per_cell=6):
    """Alternating blocks and links along -x from the head face at x = 0, axis on y = z = 0.

    cells: (cx, cy, cz) cells of one block and of one link (cx along the body).
    Returns nodes (n, 3) [m], tets (m, 4), tet_block (m,) block of a tet or -1
    for a link tet, node_block (n,) block a node belongs to (-1: inside a link).
    """
    cx, cy, cz = cells
    n_cells_x = n_blocks * cx + (n_blocks - 1) * cx
    nodes, tets = box_grid((float(n_cells_x), height, width), (n_cells_x, cy, cz),
                           origin=(0.0, -0.5 * height, -0.5 * width), tets_per_cell=tets_per_cell)
    # grid line i -> x: from the tail (i = 0) to the head, block / link cells alternating
    widths = []
    for part in range(2 * n_blocks - 1):
        widths += [(block_length if part % 2 == 0 else link_length) / cx] * cx
    xs = np.concatenate([[0.0], np.cumsum(widths)])
    xs -= xs[-1]
    i = np.rint(nodes[:, 0]).astype(np.int64)
    nodes[:, 0] = xs[i]  # monotone along x: tets keep their orientation
    P = block_length + link_length
    tol = 1e-9 * P

    def block_of(x):
        s = np.floor(-x / P + tol).astype(np.int64)
        inside = (-x - s * P) <= block_length + tol
        return np.where(inside & (s >= 0) & (s < n_blocks), s, -1)

    tet_block = block_of(nodes[tets].mean(axis=1)[:, 0])
    node_block = block_of(nodes[:, 0])
    # a node on block s's back face also touches link s (fine: it belongs to the block)
    return nodes, tets, tet_block, node_block


@njit(cache=True, error_model="numpy")
def block_centroids(x, block_nodes, out):
    """OVERWRITE out (n_blocks, 3) [m] with the mean of each block's nodes; block_nodes (n_blocks, k)."""
    k = block_nodes.shape[1]
    for s in range(block_nodes.shape[0]):
        sx = sy = sz = 0.0
        for a in range(k):
            i = block_nodes[s, a]
            sx += x[i, 0]
            sy += x[i, 1]
            sz += x[i, 2]
        out[s, 0], out[s, 1], out[s, 2] = sx / k, sy / k, sz / k


@njit(cache=True, error_model="numpy")
def block_poses(x, block_nodes, rest_offsets, c, A, R):
    """Best-fit rigid pose of every block: c (n_blocks, 3) [m] centroid, R (n_blocks, 3, 3) the polar
    rotation of A = sum_i (x_i - c)(X_i - X_c)^T; rest_offsets (n_blocks, k, 3) [m] = X_i - X_c.
    OVERWRITES c, A (n_blocks, 3, 3) scratch and R."""
    block_centroids(x, block_nodes, c)
    for s in range(block_nodes.shape[0]):
        for i in range(3):
            for j in range(3):
                A[s, i, j] = 0.0
        for a in range(block_nodes.shape[1]):
            p = block_nodes[s, a]
            for i in range(3):
                d = x[p, i] - c[s, i]
                for j in range(3):
                    A[s, i, j] += d * rest_offsets[s, a, j]
        FK.polar_rotation(A[s], R[s])


@njit(cache=True, error_model="numpy")
def advance_chain(chain, params, acc, world, dt, n_steps):
    """Advance the FEM chain ``n_steps`` steps of dt [s] in world (module docstring); return (steps, status).

    chain: a ``BlockChain`` B, params: a ``BlockChainParams`` M (the fields above them), world: the run's
    ``world.world.StepWorld`` W (gravity, terrain), as plain tuples (``core.kernel_records``: the call's cost),
    named here.  dt must be the one B's factor of (M + dt D) was built for (the body's ``dt``).
    B.x, B.v (n_nodes, 3) [m], [m/s] UPDATED; mass (n_nodes,) [kg]; tets, inc_ptr,
    inc_off, coef, q_ws (UPDATED), F_work, H_work as
    ``fem.kernels.elastic_forces_gathered``;
    perm, sky_*, fp_* the factor of (M + dt D) with no fixed node
    (``FEMSystem.solver``).  block_nodes (n_blocks, k) node ids of each block;
    node_spine (n_nodes,) the block whose spine a node's friction uses;
    att_nodes (n_att,) leg-attachment node ids, att_block (n_att,) their
    block, att_target (n_att, 3) [m] their target positions at the end of the
    step (used for supported blocks only); support (n_blocks,) bool.  gravity (3,) [m/s^2];
    terr_kind, terr; fric_model, fric; phys (N_PHYS,): r_n, r_t,
    limits [m/s], [m], k_p [N/m].  Scratch: f_work (n_nodes, 3), b_work
    (n_nodes, 3), cent, spine (n_blocks, 3).  acc (S.N_ACC,) ACCUMULATES the
    shared statistics (contact fraction sum, steps, deepest penetration).
    """
    B, M, W = BlockChain(*chain), BlockChainParams(*params), StepWorld(*world)
    x, v, mass, tets, inc_ptr, inc_off, coef, q_ws = B.x, B.v, B.mass, B.tets, B.inc_ptr, B.inc_off, B.coef, B.q_ws
    F_work, H_work, perm, sky_first, sky_ptr, sky_L = B.F_work, B.H_work, B.perm, B.sky_first, B.sky_ptr, B.sky_L
    fp_ptr, fp_col, fp_val, block_nodes, node_spine = B.fp_ptr, B.fp_col, B.fp_val, B.block_nodes, B.node_spine
    att_nodes, att_block, att_target, support = B.att_nodes, B.att_block, B.att_target, B.support
    f_work, b_work, cent, spine = B.f_work, B.b_work, B.cent, B.spine
    gravity, terr_kind, terr, fric_model, fric, phys = W.gravity, W.terr_kind, W.terr, M.fric_model, M.fric, M.phys
    n_nodes = x.shape[0]
    n_blocks = block_nodes.shape[0]
    r_n = phys[R_N]
    r_t = phys[R_TAN]
    vmax2 = phys[MAX_SPEED] * phys[MAX_SPEED]
    max_pen = phys[MAX_PEN]
    kp = phys[K_SUPPORT]
    contact_dist = fric[CONTACT_DISTANCE]
    gx, gy, gz = gravity[0], gravity[1], gravity[2]
    # on the plane without obstacles the free nodes' distances are y - ground (``flat_ground``: what
    # ``signed_distance`` computes there, without its reference-count updates per call)
    flat, ground = flat_ground(terr_kind, terr)
    for step in range(n_steps):
        status = S.OK
        f_work[:, :] = 0.0
        elastic_forces_gathered(x, tets, coef, q_ws, F_work, H_work, inc_ptr, inc_off, f_work)
        for i in range(n_nodes):
            m = mass[i]
            f_work[i, 0] += m * gx
            f_work[i, 1] += m * gy
            f_work[i, 2] += m * gz
        semi_implicit_velocity(v, mass, f_work, dt, perm, sky_first, sky_ptr, sky_L, fp_ptr, fp_col, fp_val, b_work)
        # implicit penalty of supported blocks' leg-attachment nodes toward their targets
        for a in range(att_nodes.shape[0]):
            if not support[att_block[a]]:
                continue
            p = att_nodes[a]
            m = mass[p]
            den = m + dt * dt * kp
            for d in range(3):
                v[p, d] = (m * v[p, d] + dt * kp * (att_target[a, d] - x[p, d])) / den
        # spines from the block centroids (toward the head)
        block_centroids(x, block_nodes, cent)
        for s in range(n_blocks):
            spine_between(cent, s - 1 if s > 0 else 0, s + 1 if s < n_blocks - 1 else n_blocks - 1, spine, s)
        n_contact = 0
        for i in range(n_nodes):
            # A node clear of the terrain at both ends of its step (phi >= the contact distance now,
            # phi >= 0 after x += dt v) is what ``advance_point`` reduces to for it: no friction, no
            # collision, x += dt v and the blow-up checks.  Done here with the same arithmetic (so
            # bit for bit the same), it skips the call's cost for the walking body's many nodes in the
            # air; any other node (also a NaN distance) goes through ``advance_point``.  Deliberately
            # unrolled: a call of ``contact_kernels.advance_point_if_clear`` (the same doubles) measured
            # -9 % on `fem-centipede` and -4 % on `fem-worm` (regress, 4 alternating rounds, 2026-11-24),
            # and about -16 % and -18 % in its flat-ground form (3 alternating rounds, 2026-11-27).
            px, py, pz = x[i, 0], x[i, 1], x[i, 2]
            vx, vy, vz = v[i, 0], v[i, 1], v[i, 2]
            # (``distance_at_least``: the same tests as phi >= ..., answered among obstacles without their search
            # for the nodes high above them)
            if (py - ground >= contact_dist) if flat else distance_at_least(terr_kind, terr, px, py, pz, contact_dist):
                qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
                if (qy - ground >= 0.0) if flat else distance_at_least(terr_kind, terr, qx, qy, qz, 0.0):
                    x[i, 0], x[i, 1], x[i, 2] = qx, qy, qz
                    if not math.isfinite(qx + qy + qz + vx + vy + vz):
                        status = S.NONFINITE
                    elif vx * vx + vy * vy + vz * vz > vmax2:
                        status = S.RUNAWAY_SPEED
                    continue
            s = node_spine[i]
            touching, st = advance_point(x, v, i, (vx, vy, vz), (spine[s, 0], spine[s, 1], spine[s, 2]),
                                         terr_kind, terr, fric_model, fric, (dt, r_n, r_t, contact_dist, max_pen,
                                         vmax2), acc, False, (0.0, 0.0, 0.0))
            n_contact += touching
            if st != S.OK:
                status = st
        acc[S.ACC_CONTACT_SUM] += n_contact / n_nodes
        acc[S.ACC_STEPS] += 1.0
        if status != S.OK:
            return step + 1, status
    return n_steps, S.OK


@njit(cache=True, error_model="numpy")
def carry_blocks(x, att_nodes, att_block, held, kinematic, c, R, c_T, R_T, att_target, support):
    """``BodyFEMChain.set_support`` on the blocks' current poses c (n, 3) [m], R (n, 3, 3): OVERWRITES support
    (n,) with kinematic | held, and att_target (n_att, 3) [m] of every leg-attachment node p of a kinematic,
    not held block b with x_T = c_T[b] + R_T[b] R[b]^T (x_p - c[b]) (held blocks keep their starting targets).

    numpy's einsum "nij,nj->ni" (which this replaced, and which the goldens were recorded with) adds the
    three products as (j=0 + j=2) + j=1, and "nji,nj->ni" in order (checked on this numpy by
    tests/test_fused_walk.py): kept so, bit for bit."""
    for i in range(support.shape[0]):
        support[i] = kinematic[i] or held[i]
    for e in range(att_nodes.shape[0]):
        b = att_block[e]
        if not kinematic[b] or held[b]:
            continue
        p = att_nodes[e]
        d0, d1, d2 = x[p, 0] - c[b, 0], x[p, 1] - c[b, 1], x[p, 2] - c[b, 2]
        r0 = R[b, 0, 0] * d0 + R[b, 1, 0] * d1 + R[b, 2, 0] * d2
        r1 = R[b, 0, 1] * d0 + R[b, 1, 1] * d1 + R[b, 2, 1] * d2
        r2 = R[b, 0, 2] * d0 + R[b, 1, 2] * d1 + R[b, 2, 2] * d2
        for i in range(3):
            att_target[e, i] = c_T[b, i] + ((R_T[b, i, 0] * r0 + R_T[b, i, 2] * r2) + R_T[b, i, 1] * r1)


# the fused legged walk's pack (``legged_chunk``): blocks a ``Blocks``, chain ``advance_chain``'s body arguments
# (a ``BlockChain``, a ``BlockChainParams``, acc; world, dt and n_steps are the fused walk's), each as a plain tuple (``core.kernel_records``), named
# where read; push the dynamic stance's ``pushed_blocks.PushedBlocks``
BlockChainLegs = namedtuple("BlockChainLegs", "blocks chain push")
# the blocks as the legs carry them: x (n_nodes, 3) [m]; block_nodes (n, k); rest_offsets (n, k, 3) [m]; att_nodes,
# att_block (n_att,); held (n,) bool; att_target (n_att, 3) [m] and support (n,) bool (``carry_blocks`` writes them);
# the poses' scratch c (n, 3) [m], A, R (n, 3, 3)
Blocks = namedtuple("Blocks", "x block_nodes rest_offsets att_nodes att_block held att_target support c A R")


def _block_poses(P):
    """``legged_chunk.poses``: the blocks' best-fit poses (``block_poses``), as ``segment_poses``."""
    B = Blocks(*P.blocks)
    block_poses(B.x, B.block_nodes, B.rest_offsets, B.c, B.A, B.R)
    return B.c, B.R


def _carry_blocks(P, kinematic, c_T, R_T):
    """``legged_chunk.carry`` after ``_block_poses``: ``set_support`` on the poses it left (the nodes have not
    moved since)."""
    B = Blocks(*P.blocks)
    carry_blocks(B.x, B.att_nodes, B.att_block, B.held, kinematic, B.c, B.R, c_T, R_T, B.att_target, B.support)


def _sample_blocks(P, c_out, R_out, links_out):
    """``legged_chunk.sample``: the nodes do not move before the step, so the poses are the sensed ones; a
    link's centre is the mean of its two blocks' centroids (``segment_centers``)."""
    B = Blocks(*P.blocks)
    c, R = B.c, B.R
    copy_rows(c, c_out)
    copy_frames(R, R_out)
    for li in range(c.shape[0] - 1):
        for i in range(3):
            links_out[li, i] = 0.5 * (c[li, i] + c[li + 1, i])


def _carry_blocks_feet(P, kinematic, c_T, R_T, states, tips):
    """``legged_chunk.carry_feet`` after ``_block_poses``: in dynamic stance the legs push the blocks
    (``pushed_blocks.push_blocks``, on the poses ``_block_poses`` left; returns True: feet may have slid), else
    ``_carry_blocks`` (False)."""
    if P.push.stance.params.dynamic != 0.0:
        B = Blocks(*P.blocks)
        push_blocks(P.push, B.c, B.R, kinematic, c_T, R_T, states, tips)
        return True
    carry(P, kinematic, c_T, R_T)   # (the registered ``_carry_blocks``: a plain function compiles only so)
    return False


# The chain's one step function: ``advance`` calls it with a chunk's n steps, the fused legged walk with one
# (``legged_chunk.chain_step``; not inlined, as before: the fused chunk calls the chain's compiled kernel)
STEP = advance_chain
STEP_CHAIN_ITEMS = 3  # STEP's body arguments: chain, params, acc (the pack's chain); then world, dt, n_steps
register(BlockChainLegs, _block_poses, _carry_blocks, _sample_blocks, chain_step(STEP, STEP_CHAIN_ITEMS), _carry_blocks_feet)


class BodyFEMChain(LeggedPackOps, LeggedSegments):
    """The centipede as one FEM mesh (module docstring), with the segment interface.

    State: ``x``, ``v`` (n_nodes, 3) [m], [m/s] (the ``FEMSystem``'s arrays).  Its segment interface
    (``segment_poses``, ``set_support``, ``push_support``, ``legged_sample``) is ``legged_chunk.LeggedPackOps``: the
    functions registered for ``BlockChainLegs`` above, which the fused walk runs.
    """

    name = "fem"
    def __init__(self, case, world):
        cre = case.creature
        cfg = case.body
        sc = case.scenario
        if cre.segments < 2:
            raise ValueError("a legged FEM chain needs at least 2 segments")
        self.case = case
        n, lr, w, h = cre.segments, cre.segment_length_m, cre.width_m, cre.height_m
        ll = cfg.link_length_m if cfg.link_length_m > 0 else 0.5 * lr
        self.n_blocks, self.block_length, self.link_length = n, lr, ll
        self.n_segments = n
        self.segment_pitch_m = lr + ll
        self.segment_half_extents = np.tile(0.5 * np.array([lr, h, w]), (n, 1))
        self.dt = float(case.dt)
        self.pitch = lr + ll
        cells = segment_cells(cfg.resolution, cfg.resolution_unit)
        nodes, tets, tet_block, node_block = chain_mesh(n, lr, ll, h, w, cells, cfg.tets_per_cell)
        self.rest = nodes
        self.tet_block = tet_block
        # materials: links App. A; blocks stiffer and as heavy as the creature's mass requires
        vol = signed_volumes(nodes, tets)
        rho_link = cfg.density_kg_m3 if cfg.density_kg_m3 > 0 else 1.0
        in_block = tet_block >= 0
        m_links = rho_link * vol[~in_block].sum()
        if cfg.block_density_kg_m3 > 0:
            rho_block = cfg.block_density_kg_m3
        else:
            rho_block = (cre.mass_kg - m_links) / vol[in_block].sum()
        if rho_block <= 0.0:
            raise ValueError(f"creature.mass_kg = {cre.mass_kg} kg is less than the links' mass {m_links:.4g} kg")
        E = np.where(in_block, cfg.youngs_modulus_pa * cfg.rigid_stiffness_factor, cfg.youngs_modulus_pa)
        rho = np.where(in_block, rho_block, rho_link)
        self.fem = fem = FEMSystem(nodes, tets, E=E, nu=cfg.poisson_ratio, rho=rho, gamma=cfg.damping_gamma)
        self.solver = fem.solver(case.dt)  # no fixed node: one factorization for the whole run
        self.block_nodes = np.ascontiguousarray(np.stack([np.flatnonzero(node_block == s) for s in range(n)]))
        self.rest_centroids = nodes[self.block_nodes].mean(axis=1)
        self.rest_offsets = np.ascontiguousarray(nodes[self.block_nodes] - self.rest_centroids[:, None, :])
        # nodes of links take the spine of the nearest block
        self.node_spine = np.clip(np.rint(-(nodes[:, 0] + 0.5 * lr) / self.pitch), 0, n - 1).astype(np.int64)
        side = node_block >= 0
        side &= np.isclose(np.abs(nodes[:, 2]), 0.5 * w)
        self.att_nodes = np.flatnonzero(side).astype(np.int64)
        self.att_block = node_block[self.att_nodes].astype(np.int64)
        self.gravity = np.array([0.0, -sc.gravity_m_s2, 0.0])
        # the run's world (``world.world``: built once by the runner; a body builds none of its own)
        self.world = world
        self.terr_kind, self.terr = self.world.terrain
        self.fric_model, self.fric = friction_params(case.friction)
        phys = np.zeros(N_PHYS)
        contact_scalars(phys, (R_N, R_TAN, MAX_SPEED, MAX_PEN), case)
        phys[K_SUPPORT] = cfg.support_stiffness_n_m
        self.phys = phys
        fem.x[:] = place_points(nodes, case, self.world)
        fem.v[:] = 0.0
        self.x, self.v = fem.x, fem.v
        self.support = np.zeros(n, dtype=np.bool_)
        self._held = np.zeros(n, dtype=np.bool_)
        if sc.suspended:
            self.support[0] = True  # the head block is held where it starts, whatever the controller asks
            self._held[0] = True
        self.att_target = self.x[self.att_nodes].copy()
        self._f_work = np.zeros_like(self.x)
        self._b_work = np.zeros((len(self.solver.perm), 3))
        self._cent = np.zeros((n, 3))
        self._spine = np.zeros((n, 3))
        self.acc = np.zeros(S.N_ACC)
        self.quality = ElementQuality(len(tets))
        self.total_mass = float(fem.mass.sum())
        self._setup_stance(case)

    def _setup_stance(self, case) -> None:
        """The dynamic stance (``legs.stance``, ``pushed_blocks``): ``self.dynamic_stance``, ``self.stance``
        (``dynamic_stance.StanceArrays`` of the blocks: lumped masses, rest inertia) and ``self._push``."""
        params = stance_params(case.legs, case.friction)
        self.dynamic_stance = params.dynamic != 0.0
        node_mass = self.fem.mass[self.block_nodes]
        n = self.n_blocks
        self.stance = stance_arrays(params, node_mass.sum(axis=1), block_inertia(self.rest_offsets, node_mass),
                                    self.gravity, np.zeros((n, 3)), np.zeros((n, 3)), self.terr_kind, self.terr)
        self._push = pushed_blocks(self.x, self.v, self.fem.mass, self.block_nodes, self.att_nodes, self.att_block,
                                   self._f_work, self.support, self._held, self.stance, self.dt)

    # ------------------------------------------------------------------ stepping
    def advance(self, t0: float, n_steps: int, act: Actuation | None = None) -> tuple[int, int]:
        """``n_steps`` steps in one kernel call; return (steps done, status code).  t0 unused; the links
        have no muscles (supported blocks are pulled to their targets, ``apply_support``)."""
        return STEP(*self._chain_args, self.acc, self.world.step_world, self.dt, int(n_steps))

    @cached_property
    def _chain_args(self) -> tuple:
        """``advance_chain``'s records (``BlockChain``: the chain's arrays, ``BlockChainParams``) as plain tuples
        (``core.kernel_records``: the call's cost), built once by field name: they refer to the body's own arrays,
        which are changed in place only."""
        f, s = self.fem, self.solver
        chain = BlockChain(x=self.x, v=self.v, mass=f.mass, tets=f.tets, inc_ptr=f.inc_ptr, inc_off=f.inc_off,
                           coef=f.coef, q_ws=f.q_ws, F_work=f.F_work, H_work=f.H_work, perm=s.perm,
                           sky_first=s.sky_first, sky_ptr=s.sky_ptr, sky_L=s.sky_L, fp_ptr=s.fp_ptr, fp_col=s.fp_col,
                           fp_val=s.fp_val, block_nodes=self.block_nodes, node_spine=self.node_spine,
                           att_nodes=self.att_nodes, att_block=self.att_block, att_target=self.att_target,
                           support=self.support, f_work=self._f_work, b_work=self._b_work, cent=self._cent,
                           spine=self._spine)
        return plain(chain), plain(BlockChainParams(fric_model=self.fric_model, fric=self.fric, phys=self.phys))

    def legged_pack(self) -> "BlockChainLegs":
        """The fused legged walk's pack (``legged_chunk``): the blocks and the step's arguments."""
        n = self.n_blocks
        blocks = Blocks(x=self.x, block_nodes=self.block_nodes, rest_offsets=self.rest_offsets,
                        att_nodes=self.att_nodes, att_block=self.att_block, held=self._held,
                        att_target=self.att_target, support=self.support, c=np.zeros((n, 3)), A=np.zeros((n, 3, 3)),
                        R=np.zeros((n, 3, 3)))
        return BlockChainLegs(plain(blocks), self._chain_args + (self.acc,), self._push)

    def _state_arrays(self):
        return (self.x, self.v, self.fem.q_ws, self.support, self.att_target, self.acc, self._f_work, self.stance.acc)

    def _state(self):
        return [a.copy() for a in self._state_arrays()]

    def _restore(self, saved) -> None:
        for dst, src in zip(self._state_arrays(), saved):
            dst[...] = src

    def compile(self) -> None:
        saved = self._state()
        self.advance(0.0, 1)
        self.observe(0.0)
        if self.dynamic_stance:
            n = self.n_blocks
            self.push_support(np.zeros(n, bool), *self.segment_poses(), np.zeros(2 * n, np.int64), np.zeros((2 * n, 3)))
        self._restore(saved)
        self.quality.reset()

    # ------------------------------------------------------------------ the dynamic stance
    def stance_statistics(self) -> dict[str, float]:
        """The dynamic stance's statistics of the run so far (``dynamic_stance.stance_statistics``; empty in
        kinematic stance)."""
        if not self.dynamic_stance:
            return {}
        return stance_statistics(self.stance.acc)

    def centre_of_mass(self) -> np.ndarray:
        """(3,) [m]: the nodes' mass centre."""
        m = self.fem.mass
        return m @ self.x / self.total_mass

    @staticmethod
    def status_text(code: int) -> str:
        return S.STATUS_TEXT.get(code, f"status {code}")

    # ------------------------------------------------------------------ segment interface
    def segment_velocities(self) -> np.ndarray:
        """(n_blocks, 3) [m/s]: the mean velocity of each block's nodes."""
        out = np.empty((self.n_blocks, 3))
        block_centroids(self.v, self.block_nodes, out)
        return out

    def support_error(self) -> float:
        """Max distance [m] of a supported block's leg-attachment node from its target (current state)."""
        sel = self.support[self.att_block]
        if not sel.any():
            return 0.0
        return float(np.linalg.norm(self.x[self.att_nodes[sel]] - self.att_target[sel], axis=1).max())

    @property
    def body_length_m(self) -> float:
        return self.n_blocks * self.block_length + (self.n_blocks - 1) * self.link_length

    # ------------------------------------------------------------------ observation
    def segment_centers(self) -> np.ndarray:
        """(2 n - 1, 3) [m]: block 0, link 0, block 1, ... (block centroids; link = mean of its two blocks' faces)."""
        c = self.segment_poses()[0]
        out = np.empty((2 * self.n_blocks - 1, 3))
        out[0::2] = c
        out[1::2] = 0.5 * (c[:-1] + c[1:])
        return out

    @cached_property
    def _surfaces(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        """[(boundary node ids, outward triangles indexing them, kind)] of the blocks' and the links'
        boundary faces (one mesh; split so that a drawing can tell the stiff segments from the links); static."""
        faces, owner = tet_boundary_faces(self.fem.tets)
        in_block = self.tet_block[owner] >= 0
        return [(*compact(faces[sel]), kind) for sel, kind in ((in_block, FEM_BLOCK_SURFACE), (~in_block, FEM_SURFACE))
                if sel.any()]

    def scene(self) -> Scene:
        """Boundary triangles of the blocks and of the links, world coordinates [m] (``bodies.scene``)."""
        return Scene(triangles=[(self.x[nodes], faces, kind) for nodes, faces, kind in self._surfaces])

    def observe(self, t: float, with_nodes: bool = False) -> Observation:
        m = self.fem.mass
        com = m @ self.x / m.sum()
        head = self.x[self.rest[:, 0] >= -1e-9].mean(axis=0)
        tail = self.x[self.rest[:, 0] <= self.rest[:, 0].min() + 1e-9].mean(axis=0)
        self.quality.sample(self.x, self.fem.tets, self.fem.Dm_inv)
        obs = Observation(t=t, segment_centers=self.segment_centers(), com=com, head=head, tail=tail,
                          energy=np.array(self.energy(t)), nodes=self.x.copy() if with_nodes else None)
        return self._observe_segments(obs, t)

    def energy(self, t: float = 0.0) -> tuple[float, float, float]:
        """(kinetic, elastic (eq. 6), gravitational from y = 0) [J]."""
        m = self.fem.mass
        kinetic = float(0.5 * np.einsum("i,ij,ij->", m, self.v, self.v))
        return kinetic, self.fem.elastic_energy(), float(-self.gravity[1] * (m @ self.x[:, 1]))

    def extra_metrics(self) -> dict[str, float]:
        return {"min_J": self.quality.min_J, "inverted_elements_max": float(self.quality.inverted_max),
                **self.stance_statistics()}

    def contact_fraction_mean(self) -> float:
        return float(self.acc[S.ACC_CONTACT_SUM] / max(self.acc[S.ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        return float(self.acc[S.ACC_MAX_PEN])

