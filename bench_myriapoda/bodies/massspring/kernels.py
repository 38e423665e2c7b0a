"""Numba kernels of Miller's mass-spring body (Miller 1988 Sec. 3-4).

``advance`` runs many time steps per call.  One step:

1. the step's muscle activation: row k of the actuation buffer written by the
   controller (``core.protocols.Actuation``; the kernel knows no gait);
2. spring rest lengths from the activation (``family_rest_lengths``, the rules of
   ``lattice_rest_lengths``);
3. spring forces f = k (L - l) - D dl/dt along each spring (Miller Sec. 3), plus gravity
   (``family_spring_forces``);
4. velocity update, then ground friction for masses within the contact
   distance (``friction_kernels.ground_friction``); under Miller's caterpillar
   rule (``stick``) only masses of segments in contact, a face of the cube on
   the surface (see ``advance``);
5. position update: semi-implicit (symplectic) Euler x += dt v_new, or
   Miller's Euler x += dt v + a dt^2 / 2 (here written dt (v_old + v_new) / 2
   so that friction's velocity change also applies to the position);
6. collisions as in Miller Sec. 3, Fig. 1 (``contact_kernels``): the path of a
   mass over the step is intersected with the terrain and the part beyond the
   surface is reflected with r_n along the normal and kept with r_t along the tangent;
7. blow-up checks: non-finite values, a mass faster than a limit, a mass deeper
   inside the terrain than a limit.

Layout of the step loop.  Within one ``advance`` call node positions, velocities and forces live
in a corner-major layout (3, 4, stride) (positions and velocities with a fifth, padding row; stride
= ``lattice.face_stride``: the faces and at least one padding column, a multiple of 8), copied in at
the start of the call and back at its end or on a blow-up.  A spring family (``lattice.spring_families``:
all springs joining corner a of face t to corner b of face t + shift) then joins flat index i of a
row to i + (b - a) stride + shift.  The cube lattice has the same 18 families for every length
(``lattice.CUBE_FAMILIES``), so the step (``_column_forces_flat``) takes the family table and each
corner's summation order (``lattice.CUBE_PLAN``) as compile-time constants and runs two loops over the
faces: one computes the rest length and force of all 18 families' springs of a face (written out spring
by spring in the generated ``column_loop.py``), one forms the 12
force sums (4 corners x 3 axes) of a face.  Both vectorise across faces (sqrt and divisions in SIMD
lanes, 8 faces per 512-bit vector; the divider bounds the first at about 45 ns per segment), and they
replace the 8 spring-group loops and 12 sum loops of a previous layout (spring groups: families merged
into flat loops over whole corner rows; removed), whose loop starts made most of the fixed cost per step
(about 50 ns each).  The forces pass through a stack buffer (``_chunk_buffer``, chunks of
``CHUNK_FACES`` faces), so that LLVM needs no run-time alias checks between the 54 force rows and the
arrays the loop reads: with the forces in an argument array it stayed scalar ("too many memory checks").
Each node sums its spring forces in the order of the per-family reference kernels ``family_rest_lengths``
and ``family_spring_forces`` (bitwise the same forces).  Per spring the arithmetic is that of
``spring_forces``; only the order in which a node's spring forces are summed differs (by family, not by
spring index), so results agree to round-off (~1e-16 relative), not bitwise.  ``spring_forces`` and
``lattice_rest_lengths`` stay the per-spring references (and serve the energy and the legged chain).

The node block (steps 4-7) is ``_nodes_general``, node by node.  Under anisotropic Coulomb friction
on a plane or slope without obstacles (Miller's snake) ``_nodes_coulomb_flat`` (``_node_rows`` in the step
loop) runs it instead, bitwise the same results: every node's velocity, signed distance and normal
impulse in one vectorised loop over the four corner rows taken as one flat row, then the friction
(``coulomb_friction_batch``'s arithmetic) over whole corner rows that hold a touching node (a node
without an impulse keeps its velocity exactly, so the touching nodes need no gather), then positions,
collisions and checks (``_positions_flat``).  Called node by node the friction was 45 % of the snake's
step; gathering the touching nodes cost about 21 ns per segment and 0.35 us per step on a short body.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from llvmlite import ir as llvm_ir
from numba import njit, types
from numba.extending import intrinsic
from numba.np.numpy_support import carray

from ...world.terrain_kernels import H_NOBST, PLANE, SLOPE, signed_distance, surface_normal
from ...world.world import StepWorld
from ..contact_kernels import collide_path, contact_friction, reflect_beyond, reflect_velocity
from ..friction_kernels import CONTACT_DISTANCE, COULOMB, MU_B, MU_F, MU_T, MUS_B, MUS_F, MUS_T, STICK
from ..step_status import (ACC_CONTACT_SUM, ACC_MAX_PEN, ACC_STEPS, DEEP_PENETRATION, NONFINITE, OK,  # noqa: F401
                           RUNAWAY_SPEED, STATUS_TEXT)
from . import column_loop
from .column_loop import family_springs_chunk, node_sums_chunk
from .lattice import (AXIAL, CROSS, CUBE_FAMILIES, CUBE_PLAN, FAM_A, FAM_B, FAM_CA, FAM_CB, FAM_KIND, FAM_SHIFT,
                      PAR_D, PAR_K, PAR_L0, PAR_LC, SIDE_FACES)

# scalar parameter vector layout (``phys``): the body's own constants.  Gravity and the time step are not here: the
# world (``world.world.StepWorld``) and dt are plain arguments of the step (``advance``).
RAMP_S, VOLUME, R_N, R_T, MAX_SPEED, MAX_PEN, INTEGRATOR = range(7)
N_PHYS = 8
SYMPLECTIC, EULER = 0, 1


MIN_STRETCH = 0.1  # a fibre never shortens below 10 % of its rest length (keeps springs non-degenerate)


@njit(cache=True)
def fibre_stretch(act, i, c):
    """Stretch of the fibre at corner c of segment i: 1 + axial + lateral z_s + dorsal y_s."""
    zs = 1.0 if (c & 1) else -1.0
    ys = 1.0 if (c & 2) else -1.0
    s = 1.0 + act[i, 0] + act[i, 1] * zs + act[i, 2] * ys
    return max(s, MIN_STRETCH)


@njit(cache=True, error_model="numpy")
def face_scales(act, volume_conserving, face_scale):
    """Overwrite ``face_scale`` (n_seg + 1,) with each cross-section face's circumferential scale.

    Miller Sec. 4: 1 / sqrt(mean axial stretch of the face's segments) when
    ``volume_conserving``, else 1.  act (n_seg, 3): the step's muscle strains.
    """
    n_seg = act.shape[0]
    for j in range(n_seg + 1):
        if volume_conserving:
            tot = 0.0
            cnt = 0
            if j > 0:
                tot += max(1.0 + act[j - 1, 0], MIN_STRETCH)
                cnt += 1
            if j < n_seg:
                tot += max(1.0 + act[j, 0], MIN_STRETCH)
                cnt += 1
            face_scale[j] = 1.0 / math.sqrt(tot / cnt)
        else:
            face_scale[j] = 1.0


@njit(cache=True, error_model="numpy")
def lattice_rest_lengths(act, volume_conserving, kind, seg, ca, cb, L0, Lc, face_scale, stretch, out):
    """Overwrite ``out`` (n_springs,) with spring rest lengths [m] for activation ``act`` (n_seg, 3).

    face_scale (n_seg + 1,) is overwritten with each cross-section face's
    circumferential scale: 1 / sqrt(mean axial stretch of its segments) when
    ``volume_conserving`` (Miller Sec. 4), else 1.  stretch (n_seg, 4) is
    overwritten with the fibre stretches (computed once per segment, used by
    every spring of the segment).
    """
    n_seg = act.shape[0]
    for i in range(n_seg):
        for c in range(4):
            stretch[i, c] = fibre_stretch(act, i, c)
    face_scales(act, volume_conserving, face_scale)
    for e in range(kind.shape[0]):
        k = kind[e]
        i = seg[e]
        if k == AXIAL:
            out[e] = L0[e] * stretch[i, ca[e]]
        elif k == CROSS:
            out[e] = Lc[e] * face_scale[i]
        else:
            axial = L0[e] * 0.5 * (stretch[i, ca[e]] + stretch[i, cb[e]])
            cross = Lc[e] * 0.5 * (face_scale[i] + face_scale[i + 1])
            out[e] = math.sqrt(axial * axial + cross * cross)


@njit(cache=True, error_model="numpy")
def spring_forces(x, v, springs, stiffness, damping, rest, out):
    """Accumulate spring forces f = k (L - l) - D dl/dt [N] into ``out`` (n_nodes, 3).

    x, v: (n_nodes, 3) [m], [m/s]; springs: (n_springs, 2); stiffness [N/m],
    damping [N s/m], rest [m]: (n_springs,).
    """
    for e in range(springs.shape[0]):
        i = springs[e, 0]
        j = springs[e, 1]
        dx = x[j, 0] - x[i, 0]
        dy = x[j, 1] - x[i, 1]
        dz = x[j, 2] - x[i, 2]
        length = math.sqrt(dx * dx + dy * dy + dz * dz)
        if length < 1e-12:
            continue
        ux, uy, uz = dx / length, dy / length, dz / length
        ldot = (v[j, 0] - v[i, 0]) * ux + (v[j, 1] - v[i, 1]) * uy + (v[j, 2] - v[i, 2]) * uz
        f = stiffness[e] * (rest[e] - length) - damping[e] * ldot
        out[i, 0] -= f * ux
        out[i, 1] -= f * uy
        out[i, 2] -= f * uz
        out[j, 0] += f * ux
        out[j, 1] += f * uy
        out[j, 2] += f * uz


@njit(cache=True)
def spine_vectors(x, n_faces, out):
    """Overwrite ``out`` (n_faces, 3) with the unit spine vector of each face.

    Miller Sec. 4: s = (x_{p+1} - x_{p-1}) / |...| from the centres of the next
    and last segments; here the faces ahead and behind, pointing toward the head
    (face 0).  The end faces use themselves in place of the missing neighbour.
    """
    for j in range(n_faces):
        a = j - 1 if j > 0 else 0
        b = j + 1 if j < n_faces - 1 else n_faces - 1
        sx = sy = sz = 0.0
        for c in range(4):
            sx += x[4 * a + c, 0] - x[4 * b + c, 0]
            sy += x[4 * a + c, 1] - x[4 * b + c, 1]
            sz += x[4 * a + c, 2] - x[4 * b + c, 2]
        nrm = math.sqrt(sx * sx + sy * sy + sz * sz)
        if nrm > 0.0:
            out[j, 0], out[j, 1], out[j, 2] = sx / nrm, sy / nrm, sz / nrm
        else:
            out[j, 0], out[j, 1], out[j, 2] = 1.0, 0.0, 0.0


@njit(cache=True, error_model="numpy", inline="always")
def _face_spine_c(xc, j, n_faces):
    """The unit spine vector (x, y, z) of face j of n_faces from corner-major positions xc (3, >= 4,
    >= n_faces): ``spine_vectors``' sums in the same order, (1, 0, 0) where they vanish."""
    a = j - 1 if j > 0 else 0
    b = j + 1 if j < n_faces - 1 else n_faces - 1
    sx = sy = sz = 0.0
    for c in range(4):
        sx += xc[0, c, a] - xc[0, c, b]
        sy += xc[1, c, a] - xc[1, c, b]
        sz += xc[2, c, a] - xc[2, c, b]
    nrm = math.sqrt(sx * sx + sy * sy + sz * sz)
    if nrm > 0.0:
        return sx / nrm, sy / nrm, sz / nrm
    return 1.0, 0.0, 0.0


@njit(cache=True)
def spine_vectors_c(xc, out):
    """``spine_vectors`` from corner-major positions xc (3, 4, >= n_faces) into out (n_faces, 3): the same
    sums in the same order."""
    n_faces = out.shape[0]
    for j in range(n_faces):
        out[j, 0], out[j, 1], out[j, 2] = _face_spine_c(xc, j, n_faces)


@njit(cache=True)
def _corner_major(a, ac):
    """Copy a (n_nodes, 3) into ac (3, 4, >= n_faces) (node 4 f + c at [:, c, f]; padding columns untouched)."""
    for f in range(a.shape[0] // 4):
        for c in range(4):
            for d in range(3):
                ac[d, c, f] = a[4 * f + c, d]


@njit(cache=True)
def _node_major(ac, a):
    """Copy ac (3, 4, >= n_faces) back into a (n_nodes, 3)."""
    for f in range(a.shape[0] // 4):
        for c in range(4):
            for d in range(3):
                a[4 * f + c, d] = ac[d, c, f]


@njit(cache=True, error_model="numpy")
def family_rest_lengths(act, volume_conserving, fam, params, stretch, face_scale, rest):
    """Overwrite ``rest`` (n_fam, n_faces) with the rest length [m] of every family spring.

    act (n_seg, 3): the step's muscle strains; fam, params: ``lattice.SpringFamilies``
    index and params.  stretch (4, n_seg) and face_scale (n_faces,) are overwritten with
    the fibre stretches (corner-major) and the faces' circumferential scales.  Same
    arithmetic as ``lattice_rest_lengths`` (bitwise the same rest lengths).
    """
    n_seg = act.shape[0]
    for c in range(4):
        for i in range(n_seg):
            stretch[c, i] = fibre_stretch(act, i, c)
    face_scales(act, volume_conserving, face_scale)
    for q in range(fam.shape[0]):
        kind = fam[q, FAM_KIND]
        count = n_seg + 1 - fam[q, FAM_SHIFT]
        out = rest[q]
        L0 = params[PAR_L0, q]
        Lc = params[PAR_LC, q]
        if kind == AXIAL:
            sa = stretch[fam[q, FAM_CA]]
            for t in range(count):
                out[t] = L0[t] * sa[t]
        elif kind == CROSS:
            for t in range(count):
                out[t] = Lc[t] * face_scale[t]
        else:
            sa = stretch[fam[q, FAM_CA]]
            sb = stretch[fam[q, FAM_CB]]
            for t in range(count):
                axial = L0[t] * 0.5 * (sa[t] + sb[t])
                cross = Lc[t] * 0.5 * (face_scale[t] + face_scale[t + 1])
                out[t] = math.sqrt(axial * axial + cross * cross)


@njit(cache=True, error_model="numpy")
def family_spring_forces(xc, vc, fam, params, rest, dfs, fc):
    """Accumulate spring forces f = k (L - l) - D dl/dt [N] into ``fc`` (3, 4, n_faces), family by family.

    The reference of ``column_spring_forces`` and of the step's column loops: its summation order is the one
    they reproduce, bit for bit (tests/test_massspring_kernels.py).
    xc, vc: (3, 4, n_faces) corner-major positions [m] and velocities [m/s] (node 4 t + c at
    [:, c, t]); fam, params: ``lattice.SpringFamilies``; rest (n_fam, n_faces) [m]; dfs
    (3, n_faces) scratch.  Per spring the arithmetic of ``spring_forces`` (a spring shorter
    than 1e-12 m pulls nothing), written as selects so the loop vectorises.
    """
    n_faces = xc.shape[2]
    for q in range(fam.shape[0]):
        a = fam[q, FAM_A]
        b = fam[q, FAM_B]
        s = fam[q, FAM_SHIFT]
        count = n_faces - s
        k = params[PAR_K, q]
        d = params[PAR_D, q]
        r = rest[q]
        xa0, xa1, xa2 = xc[0, a], xc[1, a], xc[2, a]
        xb0, xb1, xb2 = xc[0, b, s:], xc[1, b, s:], xc[2, b, s:]
        va0, va1, va2 = vc[0, a], vc[1, a], vc[2, a]
        vb0, vb1, vb2 = vc[0, b, s:], vc[1, b, s:], vc[2, b, s:]
        g0, g1, g2 = dfs[0], dfs[1], dfs[2]
        for t in range(count):
            dx = xb0[t] - xa0[t]
            dy = xb1[t] - xa1[t]
            dz = xb2[t] - xa2[t]
            length = math.sqrt(dx * dx + dy * dy + dz * dz)
            ux, uy, uz = dx / length, dy / length, dz / length
            ldot = (vb0[t] - va0[t]) * ux + (vb1[t] - va1[t]) * uy + (vb2[t] - va2[t]) * uz
            f = k[t] * (r[t] - length) - d[t] * ldot
            live = length >= 1e-12
            g0[t] = f * ux if live else 0.0
            g1[t] = f * uy if live else 0.0
            g2[t] = f * uz if live else 0.0
        for c in range(3):
            fa = fc[c, a]
            g = dfs[c]
            for t in range(count):
                fa[t] -= g[t]
        for c in range(3):
            fb = fc[c, b, s:]
            g = dfs[c]
            for t in range(count):
                fb[t] += g[t]


N_FAMILIES = len(CUBE_FAMILIES)  # 18
if column_loop.CUBE_FAMILIES != CUBE_FAMILIES or column_loop.CUBE_PLAN != CUBE_PLAN:  # today's tables
    raise ImportError("bodies/massspring/column_loop.py was generated from other lattice tables; "
                      "regenerate it: python3 -m bench_myriapoda.bodies.massspring.column_codegen")
# Faces per chunk of the column loops (``_column_forces_flat``): the families' forces of one chunk live in a
# stack buffer of N_FAMILIES * 3 rows of CHUNK_ROW doubles (28 kB), column 0 holding the springs of the face
# before the chunk.
CHUNK_FACES = 64
CHUNK_ROW = CHUNK_FACES + 1
CHUNK_ROWS = 3 * N_FAMILIES
# the families with shift 1 (12 of 18); an array, which numba reads as a constant (a tuple iterated at run time
# compiles to a switch)
SHIFTED_FAMILIES = np.array([q for q, fam in enumerate(CUBE_FAMILIES) if fam[FAM_SHIFT]], dtype=np.int64)


@intrinsic
def _chunk_buffer(typingctx):
    """A pointer to CHUNK_ROWS * CHUNK_ROW float64 on the stack (a fixed-size alloca in the function's entry
    block, 64-byte aligned; its contents undefined: the caller writes before it reads).

    Why the stack: LLVM then knows that the column loop's stores cannot alias any array it reads (positions,
    velocities, params, stretches), and its rows lie a compile-time distance apart, so the loop of all 18
    families vectorises without run-time alias checks; with the forces in an argument array it needed some
    1,500 checks and stayed scalar ("too many memory checks needed")."""
    sig = types.CPointer(types.float64)()

    def codegen(context, builder, signature, args):
        # in the entry block, as numba's cgutils.alloca_once, but without its zero fill (a 28 kB memset per call)
        with builder.goto_entry_block():
            buf = builder.alloca(llvm_ir.ArrayType(llvm_ir.DoubleType(), CHUNK_ROWS * CHUNK_ROW))
        buf.align = 64
        return builder.gep(buf, [llvm_ir.Constant(llvm_ir.IntType(32), 0), llvm_ir.Constant(llvm_ir.IntType(32), 0)])

    return sig, codegen


@njit(cache=True, error_model="numpy", inline="always")
def _face_factors(act_buf, row, volume_conserving, stride, face_scale, st, fs):
    """The fibre stretches and face scales of the step's muscle strains (row ``row`` of act_buf (n_rows, n_seg, 3),
    read in place): ``fibre_stretch`` and ``face_scales``' operations in one loop over the faces.  Writes
    face_scale[t] (n_faces,), st[c * stride + t] (corner c's fibre of segment t) and the face scale again to
    fs[t] (the column loops read fs[t] and fs[t + 1] up to t + 1 = stride, so fs is longer than stride)."""
    n_seg = act_buf.shape[1]
    n_faces = n_seg + 1
    for t in range(n_faces):
        if volume_conserving:  # face_scales: Miller Sec. 4
            tot = 0.0
            cnt = 0
            if t > 0:
                tot += max(1.0 + act_buf[row, t - 1, 0], MIN_STRETCH)
                cnt += 1
            if t < n_seg:
                tot += max(1.0 + act_buf[row, t, 0], MIN_STRETCH)
                cnt += 1
            scale = 1.0 / math.sqrt(tot / cnt)
        else:
            scale = 1.0
        face_scale[t] = scale
        fs[t] = scale
        if t < n_seg:  # fibre_stretch of the four corners' fibres of segment t
            a0, a1, a2 = act_buf[row, t, 0], act_buf[row, t, 1], act_buf[row, t, 2]
            st[t] = max(1.0 + a0 + a1 * -1.0 + a2 * -1.0, MIN_STRETCH)
            st[stride + t] = max(1.0 + a0 + a1 * 1.0 + a2 * -1.0, MIN_STRETCH)
            st[2 * stride + t] = max(1.0 + a0 + a1 * -1.0 + a2 * 1.0, MIN_STRETCH)
            st[3 * stride + t] = max(1.0 + a0 + a1 * 1.0 + a2 * 1.0, MIN_STRETCH)


@njit(cache=True, error_model="numpy")
def column_spring_forces(act, volume_conserving, xc, vc, fparams, face_scale, st, fs, fc):
    """Overwrite ``fc`` (3, 4, stride) [N] with the lattice's spring forces: ``family_rest_lengths`` and
    ``family_spring_forces`` (fc zeroed first) in two loops over the faces, bitwise the same forces.

    act (n_seg, 3): the step's muscle strains; xc, vc (3, 5, stride) corner-major positions [m] and
    velocities [m/s] (stride = ``lattice.face_stride``; row 4 is padding, read by the last springs);
    fparams: ``SpringFamilies.params`` (4, 18, stride) of a cube lattice (``lattice.CUBE_FAMILIES``).
    Scratch: face_scale (n_faces,); st, fs (4 stride,).  See ``_column_forces_flat``.
    """
    stride = xc.shape[2]
    act_buf = act.reshape((1, act.shape[0], act.shape[1]))
    _column_forces_flat(act_buf, np.int64(0), volume_conserving, xc.reshape(xc.size), vc.reshape(vc.size),
                        np.uint64(xc.shape[1] * stride), stride, fparams.reshape(fparams.size), face_scale, st, fs,
                        fc.reshape(fc.size))


@njit(cache=True, error_model="numpy")
def _column_forces_flat(act_buf, row, volume_conserving, xf, vf, dim, stride, pf, face_scale, st, fs, fcf):
    """``column_spring_forces`` on flat arrays made once per ``advance`` call: xf, vf the (3, 5, stride)
    positions and velocities (axis stride ``dim``, uint64), pf the families' params, fcf the (3, 4, stride)
    forces; the step's muscle strains are row ``row`` of act_buf (n_rows, n_seg, 3), read in place.

    Why this layout: the cube lattice's family table is the same for every length (``lattice.CUBE_FAMILIES``,
    compile-time constants here), so one loop over the faces computes all 18 families' springs of a face
    (pass 1: ``column_loop.family_springs_chunk``, generated from the table with its numbers as literals, which
    numba compiles in a third of the time that 18 calls of an inlined per-family helper took) and one loop
    forms all 12 sums (4 corners x 3 axes, ``lattice.CUBE_PLAN``) of a face (pass 2, ``node_sums_chunk``, also
    generated),
    both vectorised across faces (8 faces per 512-bit vector), chunk by chunk of CHUNK_FACES faces (one chunk
    up to 63 segments).  The previous layout's spring groups ran 8 spring loops and 12 sum loops per
    step, each start (set-up, run-time alias checks, the first iterations' latency) about 50 ns.  Pass 1
    writes the forces to a stack buffer (``_chunk_buffer``): family q's axis e in row 3 q + e, face t0 + j of
    the chunk starting at face t0 in column 1 + j, column 0 the face before the chunk (-0.0 before face 0),
    carried over from the last chunk's last column.  The arithmetic per spring and the order of each node's
    sum are those of the families (module docstring), so the forces are the same bits; a spring that does
    not exist is an exact no-op, +0.0 where subtracted and -0.0 where added."""
    n_faces = act_buf.shape[1] + 1
    _face_factors(act_buf, row, volume_conserving, stride, face_scale, st, fs)
    gq = carray(_chunk_buffer(), (CHUNK_ROWS * CHUNK_ROW,))
    for r in range(CHUNK_ROWS):
        gq[r * CHUNK_ROW] = -0.0
    ps = np.uint64(stride)
    for t0 in range(0, stride, CHUNK_FACES):
        if t0 > 0:  # the b ends on face t0 read the springs of face t0 - 1, the last chunk's last column
            for r in range(CHUNK_ROWS):
                gq[r * CHUNK_ROW] = gq[r * CHUNK_ROW + CHUNK_FACES]
        t1 = min(t0 + CHUNK_FACES, stride)  # range(t0, t1): with t0 + range(m) LLVM left pass 1 scalar
        family_springs_chunk(xf, vf, dim, pf, ps, st, fs, gq, np.uint64(CHUNK_ROW), t0, t1)
        if t0 <= n_faces - 1 < t1:  # the shifted families have no spring on the last face: its a ends subtract +0.0
            last = (n_faces - 1 - t0) + 1
            for i in range(SHIFTED_FAMILIES.shape[0]):
                q = SHIFTED_FAMILIES[i]
                gq[3 * q * CHUNK_ROW + last] = 0.0
                gq[(3 * q + 1) * CHUNK_ROW + last] = 0.0
                gq[(3 * q + 2) * CHUNK_ROW + last] = 0.0
        node_sums_chunk(gq, fcf, ps, np.uint64(CHUNK_ROW), t0, t1)


# rows of the batched node pass's work array (``advance``: n_nodes columns)
W_VX, W_VY, W_VZ, W_PHI, W_PEN, B_VX, B_VY, B_VZ, B_SX, B_SY, B_SZ, B_JN = range(12)
N_WORK = 12


@njit(cache=True, error_model="numpy", inline="always")
def _coulomb_lane(mus_f, mus_b, mus_t, mu_f, mu_b, mu_t, nx, ny, nz, ax, ay, az, sx, sy, sz, j):
    """One mass of ``coulomb_friction_batch``: velocity (ax, ay, az) [m/s] after friction, spine s, normal
    impulse per unit mass j [m/s] (j <= 0: unchanged); the batch's arithmetic, operation by operation (inlined
    into both of its loops, so they give the same bits)."""
    vn = ax * nx + ay * ny + az * nz
    tx, ty, tz = ax - vn * nx, ay - vn * ny, az - vn * nz
    # tangent frame: f = spine projected on the tangent plane, q = n x f
    sn = sx * nx + sy * ny + sz * nz
    fx, fy, fz = sx - sn * nx, sy - sn * ny, sz - sn * nz
    fl = math.sqrt(fx * fx + fy * fy + fz * fz)
    small = fl < 1e-12  # spine along the normal: isotropic transverse friction
    fx = 0.0 if small else fx / fl
    fy = 0.0 if small else fy / fl
    fz = 0.0 if small else fz / fl
    qx, qy, qz = ny * fz - nz * fy, nz * fx - nx * fz, nx * fy - ny * fx
    va = tx * fx + ty * fy + tz * fz
    vq = tx * qx + ty * qy + tz * qz
    vq = math.sqrt(tx * tx + ty * ty + tz * tz) if small else vq
    va = 0.0 if small else va
    speed = math.sqrt(va * va + vq * vq)
    ua, uq = va / speed, vq / speed
    fwd = va > 0.0
    mus_a = mus_f if fwd else mus_b
    mus = math.sqrt((mus_a * ua) ** 2 + (mus_t * uq) ** 2)
    mu_a = mu_f if fwd else mu_b
    da = mu_a * j * abs(ua)
    dq = mu_t * j * abs(uq)
    wa = 0.0 if abs(va) <= da else va - math.copysign(da, va)
    wq = 0.0 if abs(vq) <= dq else vq - math.copysign(dq, vq)
    stuck = speed <= mus * j  # static friction holds the mass
    wa = 0.0 if stuck else wa
    wq = 0.0 if stuck else wq
    scale = wq / speed if speed > 0 else 0.0
    rx = vn * nx + tx * scale if small else vn * nx + wa * fx + wq * qx
    ry = vn * ny + ty * scale if small else vn * ny + wa * fy + wq * qy
    rz = vn * nz + tz * scale if small else vn * nz + wa * fz + wq * qz
    at_rest = speed <= 0.0
    rx = vn * nx if at_rest else rx
    ry = vn * ny if at_rest else ry
    rz = vn * nz if at_rest else rz
    loose = j <= 0.0  # not pressed into the surface: no friction
    return (ax if loose else rx), (ay if loose else ry), (az if loose else rz)


@njit(cache=True, error_model="numpy")
def coulomb_friction_batch(p, nx, ny, nz, vx, vy, vz, sx, sy, sz, jn, count):
    """``friction_kernels.ground_friction``'s COULOMB model for ``count`` masses at once, on one normal.

    p: the friction parameter vector; n: the unit surface normal, the same for every mass (a plane
    or slope without obstacles); vx, vy, vz (>= count,) [m/s]: velocities after the step's forces,
    overwritten with the velocities after friction; s (sx, sy, sz): unit spine vectors toward the
    head; jn [m/s]: normal impulses per unit mass.  The arithmetic, operation by operation, of
    ``ground_friction`` (Hu et al. 2009 anisotropic Coulomb friction; module docstring there), with
    its early returns and branches written as selects computed after both sides, so that the loop
    vectorises (IEEE sqrt and division give the same bits in SIMD lanes): bitwise the same
    velocities (tests/test_massspring_kernels.py).  On the 50-segment snake half of the masses
    touch the plane every step, and this model cost 45 % of the step called mass by mass.
    """
    mus_f, mus_b, mus_t = p[MUS_F], p[MUS_B], p[MUS_T]
    mu_f, mu_b, mu_t = p[MU_F], p[MU_B], p[MU_T]
    for k in range(count):
        vx[k], vy[k], vz[k] = _coulomb_lane(mus_f, mus_b, mus_t, mu_f, mu_b, mu_t, nx, ny, nz, vx[k], vy[k], vz[k],
                                            sx[k], sy[k], sz[k], jn[k])


@njit(cache=True, error_model="numpy", inline="always")
def _node_scalars(phys, fric, g_dt):
    """The node blocks' step constants: (gravity [m/s^2], dt [s], r_n, r_t [-], Euler integrator (bool), contact
    distance [m], max penetration [m], max speed^2 [m^2/s^2]) from phys, fric and g_dt = (g [m/s^2], dt [s]), the
    step's world and time step (``advance``'s arguments)."""
    return (g_dt[0], g_dt[1], phys[R_N], phys[R_T], phys[INTEGRATOR] == EULER, fric[CONTACT_DISTANCE],
            phys[MAX_PEN], phys[MAX_SPEED] * phys[MAX_SPEED])


@njit(cache=True, error_model="numpy", inline="always")
def _nodes_general(xc, vc, fc, inv_mass, spine, stick, seg_held, fric_model, fric, terr_kind, terr, phys, acc, g_dt):
    """One step of every free node (any friction model and terrain): ``advance``'s node block.

    Velocity update from the forces fc, contact friction (under ``stick`` only for the corners of
    segments in ``seg_held``), position update, Miller's collision and the blow-up checks, node by
    node.  xc, vc, fc (3, 4, >= n_faces); inv_mass (n_nodes,); g_dt (g [m/s^2], dt [s]).  Returns (nodes within
    the contact distance, status).
    """
    n_faces = inv_mass.shape[0] // 4
    n_seg = n_faces - 1
    g, dt, r_n, r_t, euler, contact_dist, _, max_speed2 = _node_scalars(phys, fric, g_dt)
    n_contact = 0
    status = OK
    for f in range(n_faces):
        for c in range(4):
            n = 4 * f + c
            im = inv_mass[n]
            if im == 0.0:  # held in place (e.g. a suspended head): no forces, no gravity, no motion
                continue
            ox, oy, oz = vc[0, c, f], vc[1, c, f], vc[2, c, f]
            vx = ox + dt * fc[0, c, f] * im
            vy = oy + dt * (fc[1, c, f] * im - g)
            vz = oz + dt * fc[2, c, f] * im
            # The other backends call contact_kernels.advance_point for this block; here it stays
            # written out, deliberately: measured in one process, the call costs this (cheap) lattice step 13 %.
            px, py, pz = xc[0, c, f], xc[1, c, f], xc[2, c, f]
            phi = signed_distance(terr_kind, terr, px, py, pz)
            if phi < contact_dist:
                n_contact += 1
            if phi < contact_dist and (not stick or (f > 0 and seg_held[f - 1]) or (f < n_seg and seg_held[f])):
                if euler:
                    dx, dy, dz = 0.5 * dt * (ox + vx), 0.5 * dt * (oy + vy), 0.5 * dt * (oz + vz)
                else:
                    dx, dy, dz = dt * vx, dt * vy, dt * vz
                vx, vy, vz = contact_friction(terr_kind, terr, fric_model, fric, r_n, (px, py, pz), (vx, vy, vz),
                                              (spine[f, 0], spine[f, 1], spine[f, 2]), phi, (dx, dy, dz))
            if euler:
                qx = px + 0.5 * dt * (ox + vx)
                qy = py + 0.5 * dt * (oy + vy)
                qz = pz + 0.5 * dt * (oz + vz)
            else:
                qx, qy, qz = px + dt * vx, py + dt * vy, pz + dt * vz
            phi_q = signed_distance(terr_kind, terr, qx, qy, qz)
            if phi_q < 0.0:
                qx, qy, qz, vx, vy, vz, pen = collide_path(terr_kind, terr, r_n, r_t, px, py, pz, phi,
                                                           qx, qy, qz, phi_q, vx, vy, vz)
                if pen > acc[ACC_MAX_PEN]:
                    acc[ACC_MAX_PEN] = pen
                if pen > phys[MAX_PEN]:
                    status = DEEP_PENETRATION
            xc[0, c, f], xc[1, c, f], xc[2, c, f] = qx, qy, qz
            vc[0, c, f], vc[1, c, f], vc[2, c, f] = vx, vy, vz
            # Blow-up checks (status codes, never an exception); the step still finishes.
            if not math.isfinite(qx + qy + qz + vx + vy + vz):
                status = NONFINITE
            elif vx * vx + vy * vy + vz * vz > max_speed2:
                status = RUNAWAY_SPEED
    return n_contact, status


@njit(cache=True, error_model="numpy", inline="always")
def _flat_phi(plane, h, ms, cs, x, y):
    """``signed_distance`` of a plane (``plane``: y - h) or a slope (ms x + cs (y - h), with ms = -sin and
    cs = cos of its angle) without obstacles: the same operations, so the same bits, as a select."""
    return y - h if plane else ms * x + cs * (y - h)


@njit(cache=True, error_model="numpy")
def _positions_flat(xf, vf, wf, im, cd, pen0, n_flat, xd, wl, ground, step):
    """Pass (3) of ``_nodes_coulomb_flat``: position update, Miller's collision and the blow-up checks of the
    n_flat nodes of the flat corner-major arrays xf, vf (axis stride xd), velocities and signed distances
    from the work array wf (row length wl), written as selects so that the loop vectorises (its own
    function: in the node pass's body numba joined its variables with those of the (since removed) gather
    pass, and LLVM left it scalar, about 13 ns per node against 3).  pen0: the largest penetration so far [m].
    ground: ``_flat_ground``'s tuple; step: the tuple of scalars (dt [s], euler (bool), r_n, r_t [-], max_pen
    [m], max_speed2 [m^2/s^2]).
    Writes each node's penetration (NaN: none) to wf's W_PEN row and status to cd; returns (nodes whose
    penetration exceeds pen0, nodes with a status other than OK)."""
    plane, h, ms, cs, nx, ny, nz = ground
    dt, euler, r_n, r_t, max_pen, max_speed2 = step
    xd2 = xd + xd
    ovx, ovy, ovz = np.uint64(W_VX) * wl, np.uint64(W_VY) * wl, np.uint64(W_VZ) * wl
    ophi, open_ = np.uint64(W_PHI) * wl, np.uint64(W_PEN) * wl
    n_pen = 0
    n_bad = 0
    for t in range(n_flat):
        n = np.uint64(t)
        px, py, pz = xf[n], xf[xd + n], xf[xd2 + n]
        ox, oy, oz = vf[n], vf[xd + n], vf[xd2 + n]
        vx, vy, vz = wf[ovx + n], wf[ovy + n], wf[ovz + n]
        phi = wf[ophi + n]
        held = im[n] == 0.0  # held in place: no forces, no gravity, no motion
        qx = px + 0.5 * dt * (ox + vx) if euler else px + dt * vx
        qy = py + 0.5 * dt * (oy + vy) if euler else py + dt * vy
        qz = pz + 0.5 * dt * (oz + vz) if euler else pz + dt * vz
        phi_q = _flat_phi(plane, h, ms, cs, qx, qy)
        # contact_kernels.collide_path: crossing point, reflection of the part beyond, push-out
        s = 0.0 if phi <= 0.0 else phi / (phi - phi_q)
        ix, iy, iz = px + s * (qx - px), py + s * (qy - py), pz + s * (qz - pz)
        rx, ry, rz = reflect_beyond(ix, iy, iz, qx, qy, qz, nx, ny, nz, r_n, r_t)
        vn = vx * nx + vy * ny + vz * nz
        into = vn < 0.0
        bx, by, bz = reflect_velocity(vx, vy, vz, vn, nx, ny, nz, r_n, r_t)  # taken where into (selects below)
        bx = bx if into else vx
        by = by if into else vy
        bz = bz if into else vz
        phi_r = _flat_phi(plane, h, ms, cs, rx, ry)
        inside = phi_r < 0.0
        rx = rx - phi_r * nx if inside else rx
        ry = ry - phi_r * ny if inside else ry
        rz = rz - phi_r * nz if inside else rz
        hit = phi_q < 0.0
        qx = px if held else (rx if hit else qx)
        qy = py if held else (ry if hit else qy)
        qz = pz if held else (rz if hit else qz)
        vx = ox if held else (bx if hit else vx)
        vy = oy if held else (by if hit else vy)
        vz = oz if held else (bz if hit else vz)
        xf[n], xf[xd + n], xf[xd2 + n] = qx, qy, qz
        vf[n], vf[xd + n], vf[xd2 + n] = vx, vy, vz
        valid = hit & (not held)  # & rather than and: a short-circuit branch stops the vectoriser
        pen = -phi_r if inside else 0.0
        wf[open_ + n] = pen if valid else math.nan  # NaN: no collision (never raises the maximum)
        n_pen += 1 if (valid & (pen > pen0)) else 0
        st = DEEP_PENETRATION if (valid & (pen > max_pen)) else OK
        st = RUNAWAY_SPEED if vx * vx + vy * vy + vz * vz > max_speed2 else st
        st = NONFINITE if not math.isfinite(qx + qy + qz + vx + vy + vz) else st
        st = OK if held else st
        cd[n] = st
        n_bad += 1 if st != OK else 0
    return n_pen, n_bad


@njit(cache=True, error_model="numpy")
def spine_rows(xc, n_faces, wf, osx, wl):
    """``spine_vectors_c`` written to three rows of the flat work array wf: the unit spine vector of face f
    at wf[osx + f], wf[osx + wl + f], wf[osx + 2 wl + f] (uint64 osx, wl: rows B_SX, B_SY, B_SZ of
    ``_node_rows``' work array); the same sums in the same order, so the same bits.  xc (3, >= 4, >= n_faces)."""
    osy = osx + wl
    osz = osy + wl
    for j in range(n_faces):
        u = np.uint64(j)
        wf[osx + u], wf[osy + u], wf[osz + u] = _face_spine_c(xc, j, n_faces)


@njit(cache=True, error_model="numpy")
def _flat_ground(terr_kind, terr):
    """The constants of a plane or slope without obstacles that ``_node_rows`` uses: (plane, h, ms, cs, nx, ny,
    nz), ``_flat_phi``'s plane flag, height [m], -sin and cos of the slope angle, and the unit surface normal
    (``surface_normal``: the same for every point; the caller checks that there are no obstacles)."""
    nx, ny, nz = surface_normal(terr_kind, terr, 0.0, 0.0, 0.0)
    return terr_kind == PLANE, terr[0], -math.sin(terr[1]), math.cos(terr[1]), nx, ny, nz


@njit(cache=True, error_model="numpy")
def _node_rows(xf, vf, ff, im, wf, cd, n_faces, stride, xd, fd, wl, fric, ground, phys, acc, g_dt):
    """``_nodes_coulomb_flat`` on flat arrays: xf, vf (axis stride xd), ff (axis stride fd), im (4 stride,),
    wf the work array taken flat (row length wl; the spine vectors of the faces already in rows B_SX, B_SY,
    B_SZ), cd (4 stride,) int64; ground: ``_flat_ground``'s constants of the plane or slope, computed once per
    ``advance`` call (a sine, a cosine and the normal's call per step were a fixed cost of the step); g_dt
    (g [m/s^2], dt [s]).  Returns (nodes within the contact distance, status)."""
    n_flat = 4 * stride
    g, dt, r_n, r_t, euler, contact_dist, max_pen, max_speed2 = _node_scalars(phys, fric, g_dt)
    plane, h, ms, cs, nx, ny, nz = ground
    xd2, fd2 = xd + xd, fd + fd
    ovx, ovy, ovz, ophi = np.uint64(W_VX) * wl, np.uint64(W_VY) * wl, np.uint64(W_VZ) * wl, np.uint64(W_PHI) * wl
    ojn, open_ = np.uint64(B_JN) * wl, np.uint64(W_PEN) * wl
    # (1) velocities after forces, signed distances, and the touching free nodes' normal impulse
    # (contact_kernels.contact_friction; 0 for the others, which friction then leaves unchanged)
    count = 0
    lo = n_flat
    hi = -1
    for t in range(n_flat):
        n = np.uint64(t)
        imn = im[n]
        ox, oy, oz = vf[n], vf[xd + n], vf[xd2 + n]
        cvx = ox + dt * ff[n] * imn
        cvy = oy + dt * (ff[fd + n] * imn - g)
        cvz = oz + dt * ff[fd2 + n] * imn
        cphi = _flat_phi(plane, h, ms, cs, xf[n], xf[xd + n])
        wf[ovx + n], wf[ovy + n], wf[ovz + n], wf[ophi + n] = cvx, cvy, cvz, cphi
        cdx = 0.5 * dt * (ox + cvx) if euler else dt * cvx
        cdy = 0.5 * dt * (oy + cvy) if euler else dt * cvy
        cdz = 0.5 * dt * (oz + cvz) if euler else dt * cvz
        cvn = cvx * nx + cvy * ny + cvz * nz
        reaches = cphi + cdx * nx + cdy * ny + cdz * nz < 0.0
        touching = (cphi < contact_dist) & (imn != 0.0)  # & rather than and: no short-circuit branch
        wf[ojn + n] = -(1.0 + r_n) * cvn if (touching & (cvn < 0.0) & reaches) else 0.0
        count += 1 if touching else 0
        lo = min(lo, t if touching else n_flat)
        hi = max(hi, t if touching else -1)
    # (2) friction of the corner rows that hold a touching node, every column (coulomb_friction_batch's lanes)
    if count > 0:
        mus_f, mus_b, mus_t = fric[MUS_F], fric[MUS_B], fric[MUS_T]
        mu_f, mu_b, mu_t = fric[MU_F], fric[MU_B], fric[MU_T]
        osx, osy, osz = np.uint64(B_SX) * wl, np.uint64(B_SY) * wl, np.uint64(B_SZ) * wl
        for c in range(lo // stride, hi // stride + 1):
            base = np.uint64(c * stride)
            for f in range(stride):
                u = np.uint64(f)
                n = base + u
                wf[ovx + n], wf[ovy + n], wf[ovz + n] = _coulomb_lane(
                    mus_f, mus_b, mus_t, mu_f, mu_b, mu_t, nx, ny, nz, wf[ovx + n], wf[ovy + n], wf[ovz + n],
                    wf[osx + u], wf[osy + u], wf[osz + u], wf[ojn + n])
    # (3) positions, collisions, checks
    n_pen, n_bad = _positions_flat(xf, vf, wf, im, cd, acc[ACC_MAX_PEN], n_flat, xd, wl, ground,
                                   (dt, euler, r_n, r_t, max_pen, max_speed2))
    if n_pen > 0:  # a collision left a penetration above the maximum so far: raise it in node order
        for f in range(n_faces):
            for c in range(4):
                pen = wf[open_ + np.uint64(c * stride + f)]
                if pen > acc[ACC_MAX_PEN]:
                    acc[ACC_MAX_PEN] = pen
    status = OK
    if n_bad > 0:  # the node loop's status: the last node (node order 4 f + c) that set one
        for f in range(n_faces):
            for c in range(4):
                if cd[c * stride + f] != OK:
                    status = cd[c * stride + f]
    return count, status


@njit(cache=True, error_model="numpy")
def _nodes_coulomb_flat(xc, vc, fc, imc, spine, fric, terr_kind, terr, phys, acc, work, code, g_dt):
    """One step of every free node under COULOMB friction on a plane or slope without obstacles.

    ``_nodes_general``'s arithmetic, operation by operation, in three passes that vectorise along
    the corner-major rows: (1) each node's velocity after forces, signed distance and, for the nodes
    within the contact distance, the normal impulse of ``contact_kernels.contact_friction`` (0 for the
    others); (2) the friction (``coulomb_friction_batch``'s lanes; the surface normal is the same for
    every node here) of every node of the corner rows that hold a touching node: a lane without an
    impulse keeps its velocity exactly, so no gather of the touching nodes is needed; (3) position
    update, Miller's collision (``contact_kernels.collide_path`` with the plane's exact crossing
    fraction of ``path_surface_fraction``) and the blow-up checks, branches written as selects
    (``_positions_flat``).  Passes (1) and (3) are one loop over the four corner rows taken as one
    flat row (rows of a short body's few faces are too short to vectorise one by one).
    The step's status is that of the last node in node order with a problem, as in the node loop.
    xc, vc, fc (3, 4, stride) with stride >= n_faces (padding columns are held nodes: imc 0);
    imc (4, stride): inverse masses [1/kg], corner-major (0: held in place); spine (n_faces, 3);
    work (N_WORK, >= 4 stride); code (4, stride) int64 scratch; g_dt (g [m/s^2], dt [s]).
    Returns (nodes within the contact distance, status).
    """
    n_faces = spine.shape[0]
    stride = xc.shape[2]
    wl = work.shape[1]
    for f in range(n_faces):
        work[B_SX, f], work[B_SY, f], work[B_SZ, f] = spine[f, 0], spine[f, 1], spine[f, 2]
    return _node_rows(xc.reshape(xc.size), vc.reshape(vc.size), fc.reshape(fc.size), imc.reshape(imc.size),
                      work.reshape(work.size), code.reshape(code.size), n_faces, stride,
                      np.uint64(xc.shape[1] * stride), np.uint64(fc.shape[1] * stride), np.uint64(wl),
                      fric, _flat_ground(terr_kind, terr), phys, acc, g_dt)


# ``advance``'s work arrays, packed (numba compiles a namedtuple of arrays as a struct of them).  The body hands
# them over as a plain tuple in these fields' order: numba types a plain tuple of arrays in its C dispatcher, a
# namedtuple in Python (``bodies.rigid_chain``).  Shapes in ``advance``.
LatticeWork = namedtuple("LatticeWork", "xc vc fc st fs face_scale spine")


@njit(cache=True, error_model="numpy")
def advance(x, v, inv_mass, fparams, act_buf, fric_model, fric, phys, work, act, acc, world, dt, n_steps):
    """Advance the lattice ``n_steps`` steps of dt [s] in world (the run's ``world.world.StepWorld`` as a plain
    tuple: gravity, terrain); return (steps done, status).  The legless lattice's one step function
    (``BodySpec.legless_step``).

    State x, v: (n_nodes, 3) [m], [m/s] are updated in place.  fparams: the lattice's
    ``SpringFamilies.params`` (4, 18, stride), its families those of ``lattice.CUBE_FAMILIES``
    (the caller checks).  act_buf (n_rows, n_seg, 3): the muscle strains of step k in row k
    (rows past the last repeat it).  ``act`` (n_seg, 3) is overwritten with row n_steps (the
    actuation at the end time, which ``energy`` uses), or the last row.  work = ``LatticeWork``
    (xc, vc, fc, st, fs, face_scale, spine): xc, vc (3, 5, stride) and fc (3, 4, stride) with
    stride = ``lattice.face_stride`` (padding columns and xc, vc's fifth row zero); st, fs
    (4 stride,); face_scale (n_faces,); spine (n_faces, 3).
    ``acc`` accumulates statistics (contact count, steps, max penetration).
    A step that ends in a blow-up stops the loop and returns its status code.
    """
    xc, vc, fc, st, fs, face_scale, spine = work
    W = StepWorld(*world)
    terr_kind, terr = W.terr_kind, W.terr
    g_dt = (-W.gravity[1], dt)  # g [m/s^2] (the world's gravity is (0, -g, 0)) and the time step
    n_nodes = x.shape[0]
    n_faces = n_nodes // 4
    stride = xc.shape[2]
    volume = phys[VOLUME] != 0.0
    contact_dist = fric[CONTACT_DISTANCE]
    n_rows = act_buf.shape[0]
    last = act_buf[min(n_steps, n_rows - 1)]
    for i in range(act.shape[0]):  # element-wise: a slice copy compiles numba's shape-error formatting
        for j in range(act.shape[1]):
            act[i, j] = last[i, j]
    _corner_major(x, xc)
    _corner_major(v, vc)
    stick = fric_model == STICK
    n_seg = n_faces - 1
    seg_held = np.zeros(max(n_seg, 1), dtype=np.bool_)
    # Anisotropic Coulomb friction on a plane or slope without obstacles (the snake's scene): the
    # node block runs batched (``_nodes_coulomb_flat``), bitwise the same as ``_nodes_general``.
    batched = fric_model == COULOMB and (terr_kind == PLANE or terr_kind == SLOPE) and terr[H_NOBST] <= 0.0
    wl = 4 * stride if batched else 0
    work = np.zeros(N_WORK * wl)  # ``_node_rows``' work rows, flat
    code = np.zeros(wl, dtype=np.int64)
    imc = np.zeros(4 * stride)  # corner-major; the padding columns are held nodes
    for f in range(n_faces):
        for c in range(4):
            imc[c * stride + f] = inv_mass[4 * f + c]
    # flat views for the column loops and the batched node pass, made once per call (a view costs a reference count)
    xf, vf, ff = xc.reshape(xc.size), vc.reshape(vc.size), fc.reshape(fc.size)
    xd, fd, wlu = np.uint64(xc.shape[1] * stride), np.uint64(fc.shape[1] * stride), np.uint64(wl)
    osx = np.uint64(B_SX) * wlu
    # per call, not per step: the terrain does not change within one (only the batched pass uses it)
    ground = _flat_ground(terr_kind, terr) if batched else (False, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0)
    pf = fparams.reshape(fparams.size)
    for step in range(n_steps):
        _column_forces_flat(act_buf, min(step, n_rows - 1), volume, xf, vf, xd, stride, pf, face_scale, st, fs, ff)
        if not batched:
            spine_vectors_c(xc, spine)
        if stick:
            # Miller's caterpillar rule (Sec. 4, Image 4) holds the *segments* in contact with the
            # surface: segment i is in contact when the centre of one of its four side faces is
            # within the contact distance, i.e. a face of the cube rests on the surface.  Only the
            # corners of such segments are held (``contact_friction``).  A cube that touches along
            # one edge only is not held: held corner by corner, the head cube on the 45 degree
            # descent stood on its front ventral edge -- a cube on a 45 degree slope held at its
            # downhill edge has its centre of mass right above that edge -- and the arch behind
            # rolled it over the held edge; the body somersaulted over its head and let go at
            # 11.7 s (issue 11).  Corners of segments not in contact feel only the collision.
            for i in range(n_seg):
                seg_held[i] = False
                for ca, cb in SIDE_FACES:
                    mx = 0.25 * (xc[0, ca, i] + xc[0, cb, i] + xc[0, ca, i + 1] + xc[0, cb, i + 1])
                    my = 0.25 * (xc[1, ca, i] + xc[1, cb, i] + xc[1, ca, i + 1] + xc[1, cb, i + 1])
                    mz = 0.25 * (xc[2, ca, i] + xc[2, cb, i] + xc[2, ca, i + 1] + xc[2, cb, i + 1])
                    if signed_distance(terr_kind, terr, mx, my, mz) < contact_dist:
                        seg_held[i] = True
        if batched:
            spine_rows(xc, n_faces, work, osx, wlu)
            n_contact, status = _node_rows(xf, vf, ff, imc, work, code, n_faces, stride, xd, fd, wlu, fric, ground,
                                           phys, acc, g_dt)
        else:
            n_contact, status = _nodes_general(xc, vc, fc, inv_mass, spine, stick, seg_held, fric_model, fric,
                                               terr_kind, terr, phys, acc, g_dt)
        acc[ACC_CONTACT_SUM] += n_contact / n_nodes
        acc[ACC_STEPS] += 1.0
        if status != OK:
            _node_major(xc, x)
            _node_major(vc, v)
            return step + 1, status
    _node_major(xc, x)
    _node_major(vc, v)
    return n_steps, OK


@njit(cache=True)
def lattice_energy(x, v, mass, springs, stiffness, rest, g):
    """(kinetic, elastic, gravitational) energy [J]; gravitational measured from y = 0."""
    ke = 0.0
    pe_g = 0.0
    for n in range(x.shape[0]):
        ke += 0.5 * mass[n] * (v[n, 0] ** 2 + v[n, 1] ** 2 + v[n, 2] ** 2)
        pe_g += mass[n] * g * x[n, 1]
    pe_el = 0.0
    for e in range(springs.shape[0]):
        i = springs[e, 0]
        j = springs[e, 1]
        length = math.sqrt((x[j, 0] - x[i, 0]) ** 2 + (x[j, 1] - x[i, 1]) ** 2 + (x[j, 2] - x[i, 2]) ** 2)
        pe_el += 0.5 * stiffness[e] * (length - rest[e]) ** 2
    return ke, pe_el, pe_g
