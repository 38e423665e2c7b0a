"""The fem body's dynamic stance (issue 43; docs/explanation/dynamic-stance.md, "Where the force acts"): the STANCE
legs push the stiff blocks of the FEM mesh through friction-limited feet, instead of the kinematic stance's penalty
that carries a block's leg-attachment nodes to the Targeter's pose.

A block is not a rigid body with a state: its pose is its nodes' best fit (``myriapod.block_poses``).  Per step,
before the body's step (``push_blocks``):

1. each block's rigid motion is read off its nodes: mass M = sum m_i over its nodes (lumped masses), velocity
   v = sum m_i v_i / M, angular velocity w = I_w^-1 sum m_i (x_i - c) x (v_i - v) with I_w = R diag(I) R^T its
   rest inertia about the centroid c turned to the best-fit rotation R; and the other forces on it in its last step,
   read from the chain's force buffer (elastic forces and gravity of that step; the block's own tets' forces cancel
   in the sum, so what is left is the links' force): F_o = sum (f_i - m_i g), tau_o = sum (x_i - c) x (f_i - m_i g);
2. ``dynamic_stance.push_segments`` on those, with the rigid bodies' law and keys: the legs' wrench toward the
   Targeter's pose, cut by the feet's friction cones and the leg's maximum force, as a velocity change
   (dv, dw) of the block; feet that slide move;
3. that change, as the impulse J = M dv, H = I_w dw about c, is given to the block's leg-attachment nodes (the
   nodes of its two side faces, where the legs are rooted; the ones the kinematic stance's penalty pulls) as a
   rigid velocity increment weighted by their lumped masses: du_p = a + alpha x (x_p - c_a), a = J / M_a,
   alpha = I_a^-1 (H - M_a (c_a - c) x a), with M_a, c_a, I_a the attachment nodes' mass, mass centre and inertia
   about it.  Of all the ways to share a wrench among those nodes it is the one that moves them as one rigid
   face (no impulse deforms the block between its own attachment nodes) and gives the block exactly J and H;
   the rest of the block follows through its stiff elements, as it follows the penalty in the kinematic stance.

The body's step then adds the elastic forces, gravity and every node's ground contact, and the attachment nodes
are moved only by those dynamics (the kinematic stance's penalty is off for every block but a held one).
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np
from numba import njit

from ...core.leg_timeline import STANCE
from ..dynamic_stance import push_segments

# The fem chain's dynamic stance arrays: x, v (n_nodes, 3) [m], [m/s] (v UPDATED: the legs' impulse on the
# attachment nodes); mass (n_nodes,) [kg] lumped; block_nodes (n_blocks, k); att_nodes, att_block (n_att,);
# f_work (n_nodes, 3) [N] the chain's force buffer (its last step's elastic forces and gravity, read only);
# support (n_blocks,) bool the penalty's blocks (OVERWRITTEN: the held ones); held (n_blocks,) bool; stance the
# ``dynamic_stance.StanceArrays`` (its force, torque: scratch filled here with F_o, tau_o); scratch vb, wb, dv, dw
# (n_blocks, 3), att_m (n_blocks,), att_c (n_blocks, 3), att_I (n_blocks, 3, 3); dt [s].
PushedBlocks = namedtuple("PushedBlocks", "x v mass block_nodes att_nodes att_block f_work support held stance vb wb "
                                          "dv dw att_m att_c att_I dt")


def pushed_blocks(x, v, mass, block_nodes, att_nodes, att_block, f_work, support, held, stance, dt) -> PushedBlocks:
    """The record of a fem chain's arrays (the body's own, no copy) with fresh scratch."""
    n = block_nodes.shape[0]
    z = np.zeros
    return PushedBlocks(x, v, mass, block_nodes, att_nodes, att_block, f_work, support, held, stance, z((n, 3)),
                        z((n, 3)), z((n, 3)), z((n, 3)), z(n), z((n, 3)), z((n, 3, 3)), float(dt))


def block_inertia(rest_offsets: np.ndarray, node_mass: np.ndarray) -> np.ndarray:
    """(n_blocks, 3) [kg m^2]: each block's lumped-mass inertia about its rest centroid on its body axes
    (the diagonal; the blocks are symmetric boxes, so the off-diagonal terms vanish up to the head's link-free
    face), from rest_offsets (n_blocks, k, 3) [m] = X_i - X_c and node_mass (n_blocks, k) [kg]."""
    d2 = rest_offsets ** 2
    return np.stack([(node_mass * (d2[..., 1] + d2[..., 2])).sum(1), (node_mass * (d2[..., 0] + d2[..., 2])).sum(1),
                     (node_mass * (d2[..., 0] + d2[..., 1])).sum(1)], axis=1)


@njit(cache=True, error_model="numpy", inline="always")
def _pushed(s, supported, held, states):
    """Whether ``push_segments`` pushes block s: supported, not held, a leg in STANCE."""
    return supported[s] and not held[s] and (states[2 * s] == STANCE or states[2 * s + 1] == STANCE)


@njit(cache=True, error_model="numpy")
def push_blocks(B, c, R, supported, c_T, R_T, states, tips):
    """Steps 1-3 of the module docstring on the ``PushedBlocks`` B, the blocks' best-fit poses c (n_blocks, 3) [m],
    R (n_blocks, 3, 3) (as the controller sensed them), supported (n_blocks,) bool, the Targeter's targets c_T
    (n_blocks, 3) [m], R_T (n_blocks, 3, 3), the leg states (n_legs,) and the feet tips (n_legs, 3) [m] (UPDATED
    where a foot slides).  B.v UPDATED on the pushed blocks' attachment nodes; B.support set to B.held (the penalty
    holds a held block only); B.stance.acc ACCUMULATES."""
    S = B.stance
    x, v, mass, f_work = B.x, B.v, B.mass, B.f_work
    gx, gy, gz = S.gravity[0], S.gravity[1], S.gravity[2]
    I = S.inertia_body
    vb, wb, dv, dw = B.vb, B.wb, B.dv, B.dw
    n_blocks, k = B.block_nodes.shape[0], B.block_nodes.shape[1]
    for s in range(n_blocks):
        B.support[s] = B.held[s]
    # 1. each pushed block's rigid motion and the other forces on it
    for s in range(n_blocks):
        vb[s, 0] = vb[s, 1] = vb[s, 2] = 0.0
        wb[s, 0] = wb[s, 1] = wb[s, 2] = 0.0
        S.force[s, 0] = S.force[s, 1] = S.force[s, 2] = 0.0
        S.torque[s, 0] = S.torque[s, 1] = S.torque[s, 2] = 0.0
        if not _pushed(s, supported, B.held, states):
            continue
        M = S.mass[s]
        px = py = pz = 0.0
        for a in range(k):
            i = B.block_nodes[s, a]
            m = mass[i]
            px += m * v[i, 0]
            py += m * v[i, 1]
            pz += m * v[i, 2]
        ux, uy, uz = px / M, py / M, pz / M
        Lx = Ly = Lz = 0.0
        Fx = Fy = Fz = 0.0
        Tx = Ty = Tz = 0.0
        for a in range(k):
            i = B.block_nodes[s, a]
            m = mass[i]
            rx, ry, rz = x[i, 0] - c[s, 0], x[i, 1] - c[s, 1], x[i, 2] - c[s, 2]
            qx, qy, qz = v[i, 0] - ux, v[i, 1] - uy, v[i, 2] - uz
            Lx += m * (ry * qz - rz * qy)
            Ly += m * (rz * qx - rx * qz)
            Lz += m * (rx * qy - ry * qx)
            fx, fy, fz = f_work[i, 0] - m * gx, f_work[i, 1] - m * gy, f_work[i, 2] - m * gz
            Fx += fx
            Fy += fy
            Fz += fz
            Tx += ry * fz - rz * fy
            Ty += rz * fx - rx * fz
            Tz += rx * fy - ry * fx
        vb[s, 0], vb[s, 1], vb[s, 2] = ux, uy, uz
        # w = R diag(1 / I) R^T L
        b0 = (R[s, 0, 0] * Lx + R[s, 1, 0] * Ly + R[s, 2, 0] * Lz) / I[s, 0]
        b1 = (R[s, 0, 1] * Lx + R[s, 1, 1] * Ly + R[s, 2, 1] * Lz) / I[s, 1]
        b2 = (R[s, 0, 2] * Lx + R[s, 1, 2] * Ly + R[s, 2, 2] * Lz) / I[s, 2]
        for d in range(3):
            wb[s, d] = R[s, d, 0] * b0 + R[s, d, 1] * b1 + R[s, d, 2] * b2
        S.force[s, 0], S.force[s, 1], S.force[s, 2] = Fx, Fy, Fz
        S.torque[s, 0], S.torque[s, 1], S.torque[s, 2] = Tx, Ty, Tz
        for d in range(3):
            dv[s, d] = vb[s, d]
            dw[s, d] = wb[s, d]
    # 2. the legs' push (the held blocks and those without a STANCE leg are skipped there too)
    push_segments(c, vb, wb, R, supported, B.held, c_T, R_T, states, tips, S, B.dt)
    for s in range(n_blocks):
        for d in range(3):
            dv[s, d] = vb[s, d] - dv[s, d]
            dw[s, d] = wb[s, d] - dw[s, d]
    # 3. the impulse onto the attachment nodes: their mass, mass centre and inertia per block
    att_m, att_c, att_I = B.att_m, B.att_c, B.att_I
    for s in range(n_blocks):
        att_m[s] = 0.0
        att_c[s, 0] = att_c[s, 1] = att_c[s, 2] = 0.0
        for d in range(3):
            att_I[s, d, 0] = att_I[s, d, 1] = att_I[s, d, 2] = 0.0
    for e in range(B.att_nodes.shape[0]):
        s = B.att_block[e]
        if not _pushed(s, supported, B.held, states):
            continue
        p = B.att_nodes[e]
        m = mass[p]
        att_m[s] += m
        att_c[s, 0] += m * x[p, 0]
        att_c[s, 1] += m * x[p, 1]
        att_c[s, 2] += m * x[p, 2]
    for s in range(n_blocks):
        if att_m[s] > 0.0:
            att_c[s, 0] /= att_m[s]
            att_c[s, 1] /= att_m[s]
            att_c[s, 2] /= att_m[s]
    for e in range(B.att_nodes.shape[0]):
        s = B.att_block[e]
        if not _pushed(s, supported, B.held, states):
            continue
        p = B.att_nodes[e]
        m = mass[p]
        r0, r1, r2 = x[p, 0] - att_c[s, 0], x[p, 1] - att_c[s, 1], x[p, 2] - att_c[s, 2]
        rr = r0 * r0 + r1 * r1 + r2 * r2
        att_I[s, 0, 0] += m * (rr - r0 * r0)
        att_I[s, 1, 1] += m * (rr - r1 * r1)
        att_I[s, 2, 2] += m * (rr - r2 * r2)
        att_I[s, 0, 1] -= m * r0 * r1
        att_I[s, 0, 2] -= m * r0 * r2
        att_I[s, 1, 2] -= m * r1 * r2
    for s in range(n_blocks):
        if not _pushed(s, supported, B.held, states):
            continue
        M = S.mass[s]
        Ma = att_m[s]
        # the block's impulse J = M dv and angular impulse H = I_w dw about c
        ax, ay, az = M * dv[s, 0] / Ma, M * dv[s, 1] / Ma, M * dv[s, 2] / Ma
        b0 = (R[s, 0, 0] * dw[s, 0] + R[s, 1, 0] * dw[s, 1] + R[s, 2, 0] * dw[s, 2]) * I[s, 0]
        b1 = (R[s, 0, 1] * dw[s, 0] + R[s, 1, 1] * dw[s, 1] + R[s, 2, 1] * dw[s, 2]) * I[s, 1]
        b2 = (R[s, 0, 2] * dw[s, 0] + R[s, 1, 2] * dw[s, 1] + R[s, 2, 2] * dw[s, 2]) * I[s, 2]
        Hx = R[s, 0, 0] * b0 + R[s, 0, 1] * b1 + R[s, 0, 2] * b2
        Hy = R[s, 1, 0] * b0 + R[s, 1, 1] * b1 + R[s, 1, 2] * b2
        Hz = R[s, 2, 0] * b0 + R[s, 2, 1] * b1 + R[s, 2, 2] * b2
        # less the angular impulse of the linear one about c: H - M_a (c_a - c) x a
        ex, ey, ez = att_c[s, 0] - c[s, 0], att_c[s, 1] - c[s, 1], att_c[s, 2] - c[s, 2]
        Hx -= Ma * (ey * az - ez * ay)
        Hy -= Ma * (ez * ax - ex * az)
        Hz -= Ma * (ex * ay - ey * ax)
        # alpha = I_a^-1 H (I_a symmetric: its upper triangle holds it; inverse by cofactors)
        i00, i01, i02 = att_I[s, 0, 0], att_I[s, 0, 1], att_I[s, 0, 2]
        i11, i12, i22 = att_I[s, 1, 1], att_I[s, 1, 2], att_I[s, 2, 2]
        c00 = i11 * i22 - i12 * i12
        c01 = i02 * i12 - i01 * i22
        c02 = i01 * i12 - i02 * i11
        c11 = i00 * i22 - i02 * i02
        c12 = i01 * i02 - i00 * i12
        c22 = i00 * i11 - i01 * i01
        det = i00 * c00 + i01 * c01 + i02 * c02
        alx = (c00 * Hx + c01 * Hy + c02 * Hz) / det
        aly = (c01 * Hx + c11 * Hy + c12 * Hz) / det
        alz = (c02 * Hx + c12 * Hy + c22 * Hz) / det
        # kept in the scratch rows for the nodes' loop: a in dv, alpha in dw
        dv[s, 0], dv[s, 1], dv[s, 2] = ax, ay, az
        dw[s, 0], dw[s, 1], dw[s, 2] = alx, aly, alz
    for e in range(B.att_nodes.shape[0]):
        s = B.att_block[e]
        if not _pushed(s, supported, B.held, states):
            continue
        p = B.att_nodes[e]
        r0, r1, r2 = x[p, 0] - att_c[s, 0], x[p, 1] - att_c[s, 1], x[p, 2] - att_c[s, 2]
        v[p, 0] += dv[s, 0] + dw[s, 1] * r2 - dw[s, 2] * r1
        v[p, 1] += dv[s, 1] + dw[s, 2] * r0 - dw[s, 0] * r2
        v[p, 2] += dv[s, 2] + dw[s, 0] * r1 - dw[s, 1] * r0
