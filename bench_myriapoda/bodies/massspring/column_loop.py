"""The cube lattice's column loops, spring by spring and term by term (GENERATED: do not edit).

Made by ``column_codegen.py`` from ``lattice.CUBE_FAMILIES`` and ``CUBE_PLAN``; regenerate with
``python3 -m bench_myriapoda.bodies.massspring.column_codegen`` (a test checks that this file is current).
Each spring's operations are those of the per-family kernels ``kernels.family_rest_lengths`` and
``family_spring_forces``, in their order; see ``family_springs_chunk`` and ``node_sums_chunk``.
"""
import math

import numpy as np
from numba import njit

from .lane_select import select

# the tables this file was generated from (``lattice.CUBE_FAMILIES``, ``lattice.CUBE_PLAN``)
CUBE_FAMILIES = (
    (0, 0, 1, 0, 0, 0), (0, 1, 0, 1, 0, 1), (0, 1, 1, 2, 0, 1), (0, 2, 0, 1, 0, 2), (0, 2, 1, 2, 0, 2),
    (0, 3, 0, 1, 0, 3), (1, 0, 1, 2, 0, 1), (1, 1, 1, 0, 1, 1), (1, 2, 0, 1, 1, 2), (1, 3, 0, 1, 1, 3),
    (1, 3, 1, 2, 1, 3), (2, 0, 1, 2, 0, 2), (2, 2, 1, 0, 2, 2), (2, 3, 0, 1, 2, 3), (2, 3, 1, 2, 2, 3),
    (3, 1, 1, 2, 1, 3), (3, 2, 1, 2, 2, 3), (3, 3, 1, 0, 3, 3),
)
CUBE_PLAN = (
    ((0, -1, 0), (0, 1, 1), (1, -1, 0), (2, -1, 0), (3, -1, 0),
     (4, -1, 0), (5, -1, 0), (6, 1, 1), (11, 1, 1),),
    ((1, 1, 0), (2, 1, 1), (6, -1, 0), (7, -1, 0), (7, 1, 1),
     (8, -1, 0), (9, -1, 0), (10, -1, 0), (15, 1, 1),),
    ((3, 1, 0), (4, 1, 1), (8, 1, 0), (11, -1, 0), (12, -1, 0),
     (12, 1, 1), (13, -1, 0), (14, -1, 0), (16, 1, 1),),
    ((5, 1, 0), (9, 1, 0), (10, 1, 1), (13, 1, 0), (14, 1, 1),
     (15, -1, 0), (16, -1, 0), (17, -1, 0), (17, 1, 1),),
)


@njit(cache=True, error_model="numpy", inline="always")
def family_springs_chunk(xf, vf, dim, pf, ps, st, fs, gq, row, t0, t1):
    """Pass 1 of ``kernels._column_forces_flat`` for the faces t0 <= t < t1 (one chunk): spring t of each
    cube family q (``CUBE_FAMILIES[q]`` = (a, b, shift, kind, ca, cb)), its rest length [m] and its force
    f u [N], written to gq[(3 q + e) row + 1 + t - t0] for the axes e (gq: the chunk buffer, row: its row
    length).  xf, vf: the (3, 5, stride) corner-major positions [m] and velocities [m/s] taken flat (axis
    stride ``dim``); pf: the families' params (4, 18, stride) flat (ps = stride); st, fs: the fibre
    stretches by corner row and the face scales (row 0 of fs, read at t + 1 too).  Springs past a family's
    last face get what their zero params give (the caller overwrites the one a real node reads).  dim, ps,
    row: uint64, as every index here (numba tests a signed index for wrap-around); the offsets are made
    once, before the loop, as uint64 sums (a literal per offset would be typed one by one).
    """
    dim2 = dim + dim
    one = np.uint64(1)
    # corner row c of a flat (.., stride) array starts at c ps
    r1 = ps
    r2 = r1 + ps
    r3 = r2 + ps
    # params row r (= PAR * 18 + q: PAR_K 0, PAR_D 1, PAR_L0 2, PAR_LC 3) starts at r ps
    p1 = ps
    p2 = p1 + ps
    p3 = p2 + ps
    p4 = p3 + ps
    p5 = p4 + ps
    p6 = p5 + ps
    p7 = p6 + ps
    p8 = p7 + ps
    p9 = p8 + ps
    p10 = p9 + ps
    p11 = p10 + ps
    p12 = p11 + ps
    p13 = p12 + ps
    p14 = p13 + ps
    p15 = p14 + ps
    p16 = p15 + ps
    p17 = p16 + ps
    p18 = p17 + ps
    p19 = p18 + ps
    p20 = p19 + ps
    p21 = p20 + ps
    p22 = p21 + ps
    p23 = p22 + ps
    p24 = p23 + ps
    p25 = p24 + ps
    p26 = p25 + ps
    p27 = p26 + ps
    p28 = p27 + ps
    p29 = p28 + ps
    p30 = p29 + ps
    p31 = p30 + ps
    p32 = p31 + ps
    p33 = p32 + ps
    p34 = p33 + ps
    p35 = p34 + ps
    p36 = p35 + ps
    p37 = p36 + ps
    p38 = p37 + ps
    p39 = p38 + ps
    p40 = p39 + ps
    p41 = p40 + ps
    p42 = p41 + ps
    p43 = p42 + ps
    p44 = p43 + ps
    p45 = p44 + ps
    p46 = p45 + ps
    p47 = p46 + ps
    p48 = p47 + ps
    p49 = p48 + ps
    p50 = p49 + ps
    p51 = p50 + ps
    p52 = p51 + ps
    p53 = p52 + ps
    p54 = p53 + ps
    p55 = p54 + ps
    p56 = p55 + ps
    p57 = p56 + ps
    p58 = p57 + ps
    p59 = p58 + ps
    p60 = p59 + ps
    p61 = p60 + ps
    p62 = p61 + ps
    p63 = p62 + ps
    p64 = p63 + ps
    p65 = p64 + ps
    p66 = p65 + ps
    p67 = p66 + ps
    p68 = p67 + ps
    p69 = p68 + ps
    p70 = p69 + ps
    # the chunk buffer's rows: family q's axis e at row 3 q + e, face t0 + j in column 1 + j
    g0x = one
    g0y = g0x + row
    g0z = g0y + row
    g1x = g0z + row
    g1y = g1x + row
    g1z = g1y + row
    g2x = g1z + row
    g2y = g2x + row
    g2z = g2y + row
    g3x = g2z + row
    g3y = g3x + row
    g3z = g3y + row
    g4x = g3z + row
    g4y = g4x + row
    g4z = g4y + row
    g5x = g4z + row
    g5y = g5x + row
    g5z = g5y + row
    g6x = g5z + row
    g6y = g6x + row
    g6z = g6y + row
    g7x = g6z + row
    g7y = g7x + row
    g7z = g7y + row
    g8x = g7z + row
    g8y = g8x + row
    g8z = g8y + row
    g9x = g8z + row
    g9y = g9x + row
    g9z = g9y + row
    g10x = g9z + row
    g10y = g10x + row
    g10z = g10y + row
    g11x = g10z + row
    g11y = g11x + row
    g11z = g11y + row
    g12x = g11z + row
    g12y = g12x + row
    g12z = g12y + row
    g13x = g12z + row
    g13y = g13x + row
    g13z = g13y + row
    g14x = g13z + row
    g14y = g14x + row
    g14z = g14y + row
    g15x = g14z + row
    g15y = g15x + row
    g15z = g15y + row
    g16x = g15z + row
    g16y = g16x + row
    g16z = g16y + row
    g17x = g16z + row
    g17y = g17x + row
    g17z = g17y + row
    for t in range(t0, t1):
        u = np.uint64(t)
        j = np.uint64(t - t0)
        un = u + one
        # the nodes of face t (corner c at c ps + u) and of face t + 1 (suffix n)
        i0 = u
        i1 = r1 + u
        i2 = r2 + u
        i3 = r3 + u
        i0n = un
        i1n = r1 + un
        i2n = r2 + un
        i3n = r3 + un
        # x<e><c>, v<e><c>: axis e of the position and velocity of corner c on face t, x<e><c>n on face t + 1,
        # each loaded where a spring first needs it (all 48 loaded up front: the loop ran about 4 % slower)
        # family 0: corner 0 of face t to corner 0 of face t + 1, AXIAL
        st0 = st[u]
        xx0 = xf[i0]
        xx0n = xf[i0n]
        xy0 = xf[dim + i0]
        xy0n = xf[dim + i0n]
        xz0 = xf[dim2 + i0]
        xz0n = xf[dim2 + i0n]
        vx0 = vf[i0]
        vx0n = vf[i0n]
        vy0 = vf[dim + i0]
        vy0n = vf[dim + i0n]
        vz0 = vf[dim2 + i0]
        vz0n = vf[dim2 + i0n]
        k_0 = pf[u]
        d_0 = pf[p18 + u]
        rest_0 = pf[p36 + u] * st0
        dx_0 = xx0n - xx0
        dy_0 = xy0n - xy0
        dz_0 = xz0n - xz0
        length_0 = math.sqrt(dx_0 * dx_0 + dy_0 * dy_0 + dz_0 * dz_0)
        ux_0 = dx_0 / length_0
        uy_0 = dy_0 / length_0
        uz_0 = dz_0 / length_0
        ldot_0 = (vx0n - vx0) * ux_0 + (vy0n - vy0) * uy_0 + (vz0n - vz0) * uz_0
        f_0 = k_0 * (rest_0 - length_0) - d_0 * ldot_0
        live_0 = length_0 >= 1e-12
        gq[g0x + j] = select(live_0, f_0 * ux_0, 0.0)
        gq[g0y + j] = select(live_0, f_0 * uy_0, 0.0)
        gq[g0z + j] = select(live_0, f_0 * uz_0, 0.0)
        # family 1: corner 0 of face t to corner 1 of face t + 0, CROSS
        fs0 = fs[u]
        xx1 = xf[i1]
        xy1 = xf[dim + i1]
        xz1 = xf[dim2 + i1]
        vx1 = vf[i1]
        vy1 = vf[dim + i1]
        vz1 = vf[dim2 + i1]
        k_1 = pf[p1 + u]
        d_1 = pf[p19 + u]
        rest_1 = pf[p55 + u] * fs0
        dx_1 = xx1 - xx0
        dy_1 = xy1 - xy0
        dz_1 = xz1 - xz0
        length_1 = math.sqrt(dx_1 * dx_1 + dy_1 * dy_1 + dz_1 * dz_1)
        ux_1 = dx_1 / length_1
        uy_1 = dy_1 / length_1
        uz_1 = dz_1 / length_1
        ldot_1 = (vx1 - vx0) * ux_1 + (vy1 - vy0) * uy_1 + (vz1 - vz0) * uz_1
        f_1 = k_1 * (rest_1 - length_1) - d_1 * ldot_1
        live_1 = length_1 >= 1e-12
        gq[g1x + j] = select(live_1, f_1 * ux_1, 0.0)
        gq[g1y + j] = select(live_1, f_1 * uy_1, 0.0)
        gq[g1z + j] = select(live_1, f_1 * uz_1, 0.0)
        # family 2: corner 0 of face t to corner 1 of face t + 1, SIDE_DIAG
        st1 = st[r1 + u]
        fs1 = fs[un]
        xx1n = xf[i1n]
        xy1n = xf[dim + i1n]
        xz1n = xf[dim2 + i1n]
        vx1n = vf[i1n]
        vy1n = vf[dim + i1n]
        vz1n = vf[dim2 + i1n]
        k_2 = pf[p2 + u]
        d_2 = pf[p20 + u]
        axial_2 = pf[p38 + u] * 0.5 * (st0 + st1)
        cross_2 = pf[p56 + u] * 0.5 * (fs0 + fs1)
        rest_2 = math.sqrt(axial_2 * axial_2 + cross_2 * cross_2)
        dx_2 = xx1n - xx0
        dy_2 = xy1n - xy0
        dz_2 = xz1n - xz0
        length_2 = math.sqrt(dx_2 * dx_2 + dy_2 * dy_2 + dz_2 * dz_2)
        ux_2 = dx_2 / length_2
        uy_2 = dy_2 / length_2
        uz_2 = dz_2 / length_2
        ldot_2 = (vx1n - vx0) * ux_2 + (vy1n - vy0) * uy_2 + (vz1n - vz0) * uz_2
        f_2 = k_2 * (rest_2 - length_2) - d_2 * ldot_2
        live_2 = length_2 >= 1e-12
        gq[g2x + j] = select(live_2, f_2 * ux_2, 0.0)
        gq[g2y + j] = select(live_2, f_2 * uy_2, 0.0)
        gq[g2z + j] = select(live_2, f_2 * uz_2, 0.0)
        # family 3: corner 0 of face t to corner 2 of face t + 0, CROSS
        xx2 = xf[i2]
        xy2 = xf[dim + i2]
        xz2 = xf[dim2 + i2]
        vx2 = vf[i2]
        vy2 = vf[dim + i2]
        vz2 = vf[dim2 + i2]
        k_3 = pf[p3 + u]
        d_3 = pf[p21 + u]
        rest_3 = pf[p57 + u] * fs0
        dx_3 = xx2 - xx0
        dy_3 = xy2 - xy0
        dz_3 = xz2 - xz0
        length_3 = math.sqrt(dx_3 * dx_3 + dy_3 * dy_3 + dz_3 * dz_3)
        ux_3 = dx_3 / length_3
        uy_3 = dy_3 / length_3
        uz_3 = dz_3 / length_3
        ldot_3 = (vx2 - vx0) * ux_3 + (vy2 - vy0) * uy_3 + (vz2 - vz0) * uz_3
        f_3 = k_3 * (rest_3 - length_3) - d_3 * ldot_3
        live_3 = length_3 >= 1e-12
        gq[g3x + j] = select(live_3, f_3 * ux_3, 0.0)
        gq[g3y + j] = select(live_3, f_3 * uy_3, 0.0)
        gq[g3z + j] = select(live_3, f_3 * uz_3, 0.0)
        # family 4: corner 0 of face t to corner 2 of face t + 1, SIDE_DIAG
        st2 = st[r2 + u]
        xx2n = xf[i2n]
        xy2n = xf[dim + i2n]
        xz2n = xf[dim2 + i2n]
        vx2n = vf[i2n]
        vy2n = vf[dim + i2n]
        vz2n = vf[dim2 + i2n]
        k_4 = pf[p4 + u]
        d_4 = pf[p22 + u]
        axial_4 = pf[p40 + u] * 0.5 * (st0 + st2)
        cross_4 = pf[p58 + u] * 0.5 * (fs0 + fs1)
        rest_4 = math.sqrt(axial_4 * axial_4 + cross_4 * cross_4)
        dx_4 = xx2n - xx0
        dy_4 = xy2n - xy0
        dz_4 = xz2n - xz0
        length_4 = math.sqrt(dx_4 * dx_4 + dy_4 * dy_4 + dz_4 * dz_4)
        ux_4 = dx_4 / length_4
        uy_4 = dy_4 / length_4
        uz_4 = dz_4 / length_4
        ldot_4 = (vx2n - vx0) * ux_4 + (vy2n - vy0) * uy_4 + (vz2n - vz0) * uz_4
        f_4 = k_4 * (rest_4 - length_4) - d_4 * ldot_4
        live_4 = length_4 >= 1e-12
        gq[g4x + j] = select(live_4, f_4 * ux_4, 0.0)
        gq[g4y + j] = select(live_4, f_4 * uy_4, 0.0)
        gq[g4z + j] = select(live_4, f_4 * uz_4, 0.0)
        # family 5: corner 0 of face t to corner 3 of face t + 0, CROSS
        xx3 = xf[i3]
        xy3 = xf[dim + i3]
        xz3 = xf[dim2 + i3]
        vx3 = vf[i3]
        vy3 = vf[dim + i3]
        vz3 = vf[dim2 + i3]
        k_5 = pf[p5 + u]
        d_5 = pf[p23 + u]
        rest_5 = pf[p59 + u] * fs0
        dx_5 = xx3 - xx0
        dy_5 = xy3 - xy0
        dz_5 = xz3 - xz0
        length_5 = math.sqrt(dx_5 * dx_5 + dy_5 * dy_5 + dz_5 * dz_5)
        ux_5 = dx_5 / length_5
        uy_5 = dy_5 / length_5
        uz_5 = dz_5 / length_5
        ldot_5 = (vx3 - vx0) * ux_5 + (vy3 - vy0) * uy_5 + (vz3 - vz0) * uz_5
        f_5 = k_5 * (rest_5 - length_5) - d_5 * ldot_5
        live_5 = length_5 >= 1e-12
        gq[g5x + j] = select(live_5, f_5 * ux_5, 0.0)
        gq[g5y + j] = select(live_5, f_5 * uy_5, 0.0)
        gq[g5z + j] = select(live_5, f_5 * uz_5, 0.0)
        # family 6: corner 1 of face t to corner 0 of face t + 1, SIDE_DIAG
        k_6 = pf[p6 + u]
        d_6 = pf[p24 + u]
        axial_6 = pf[p42 + u] * 0.5 * (st0 + st1)
        cross_6 = pf[p60 + u] * 0.5 * (fs0 + fs1)
        rest_6 = math.sqrt(axial_6 * axial_6 + cross_6 * cross_6)
        dx_6 = xx0n - xx1
        dy_6 = xy0n - xy1
        dz_6 = xz0n - xz1
        length_6 = math.sqrt(dx_6 * dx_6 + dy_6 * dy_6 + dz_6 * dz_6)
        ux_6 = dx_6 / length_6
        uy_6 = dy_6 / length_6
        uz_6 = dz_6 / length_6
        ldot_6 = (vx0n - vx1) * ux_6 + (vy0n - vy1) * uy_6 + (vz0n - vz1) * uz_6
        f_6 = k_6 * (rest_6 - length_6) - d_6 * ldot_6
        live_6 = length_6 >= 1e-12
        gq[g6x + j] = select(live_6, f_6 * ux_6, 0.0)
        gq[g6y + j] = select(live_6, f_6 * uy_6, 0.0)
        gq[g6z + j] = select(live_6, f_6 * uz_6, 0.0)
        # family 7: corner 1 of face t to corner 1 of face t + 1, AXIAL
        k_7 = pf[p7 + u]
        d_7 = pf[p25 + u]
        rest_7 = pf[p43 + u] * st1
        dx_7 = xx1n - xx1
        dy_7 = xy1n - xy1
        dz_7 = xz1n - xz1
        length_7 = math.sqrt(dx_7 * dx_7 + dy_7 * dy_7 + dz_7 * dz_7)
        ux_7 = dx_7 / length_7
        uy_7 = dy_7 / length_7
        uz_7 = dz_7 / length_7
        ldot_7 = (vx1n - vx1) * ux_7 + (vy1n - vy1) * uy_7 + (vz1n - vz1) * uz_7
        f_7 = k_7 * (rest_7 - length_7) - d_7 * ldot_7
        live_7 = length_7 >= 1e-12
        gq[g7x + j] = select(live_7, f_7 * ux_7, 0.0)
        gq[g7y + j] = select(live_7, f_7 * uy_7, 0.0)
        gq[g7z + j] = select(live_7, f_7 * uz_7, 0.0)
        # family 8: corner 1 of face t to corner 2 of face t + 0, CROSS
        k_8 = pf[p8 + u]
        d_8 = pf[p26 + u]
        rest_8 = pf[p62 + u] * fs0
        dx_8 = xx2 - xx1
        dy_8 = xy2 - xy1
        dz_8 = xz2 - xz1
        length_8 = math.sqrt(dx_8 * dx_8 + dy_8 * dy_8 + dz_8 * dz_8)
        ux_8 = dx_8 / length_8
        uy_8 = dy_8 / length_8
        uz_8 = dz_8 / length_8
        ldot_8 = (vx2 - vx1) * ux_8 + (vy2 - vy1) * uy_8 + (vz2 - vz1) * uz_8
        f_8 = k_8 * (rest_8 - length_8) - d_8 * ldot_8
        live_8 = length_8 >= 1e-12
        gq[g8x + j] = select(live_8, f_8 * ux_8, 0.0)
        gq[g8y + j] = select(live_8, f_8 * uy_8, 0.0)
        gq[g8z + j] = select(live_8, f_8 * uz_8, 0.0)
        # family 9: corner 1 of face t to corner 3 of face t + 0, CROSS
        k_9 = pf[p9 + u]
        d_9 = pf[p27 + u]
        rest_9 = pf[p63 + u] * fs0
        dx_9 = xx3 - xx1
        dy_9 = xy3 - xy1
        dz_9 = xz3 - xz1
        length_9 = math.sqrt(dx_9 * dx_9 + dy_9 * dy_9 + dz_9 * dz_9)
        ux_9 = dx_9 / length_9
        uy_9 = dy_9 / length_9
        uz_9 = dz_9 / length_9
        ldot_9 = (vx3 - vx1) * ux_9 + (vy3 - vy1) * uy_9 + (vz3 - vz1) * uz_9
        f_9 = k_9 * (rest_9 - length_9) - d_9 * ldot_9
        live_9 = length_9 >= 1e-12
        gq[g9x + j] = select(live_9, f_9 * ux_9, 0.0)
        gq[g9y + j] = select(live_9, f_9 * uy_9, 0.0)
        gq[g9z + j] = select(live_9, f_9 * uz_9, 0.0)
        # family 10: corner 1 of face t to corner 3 of face t + 1, SIDE_DIAG
        st3 = st[r3 + u]
        xx3n = xf[i3n]
        xy3n = xf[dim + i3n]
        xz3n = xf[dim2 + i3n]
        vx3n = vf[i3n]
        vy3n = vf[dim + i3n]
        vz3n = vf[dim2 + i3n]
        k_10 = pf[p10 + u]
        d_10 = pf[p28 + u]
        axial_10 = pf[p46 + u] * 0.5 * (st1 + st3)
        cross_10 = pf[p64 + u] * 0.5 * (fs0 + fs1)
        rest_10 = math.sqrt(axial_10 * axial_10 + cross_10 * cross_10)
        dx_10 = xx3n - xx1
        dy_10 = xy3n - xy1
        dz_10 = xz3n - xz1
        length_10 = math.sqrt(dx_10 * dx_10 + dy_10 * dy_10 + dz_10 * dz_10)
        ux_10 = dx_10 / length_10
        uy_10 = dy_10 / length_10
        uz_10 = dz_10 / length_10
        ldot_10 = (vx3n - vx1) * ux_10 + (vy3n - vy1) * uy_10 + (vz3n - vz1) * uz_10
        f_10 = k_10 * (rest_10 - length_10) - d_10 * ldot_10
        live_10 = length_10 >= 1e-12
        gq[g10x + j] = select(live_10, f_10 * ux_10, 0.0)
        gq[g10y + j] = select(live_10, f_10 * uy_10, 0.0)
        gq[g10z + j] = select(live_10, f_10 * uz_10, 0.0)
        # family 11: corner 2 of face t to corner 0 of face t + 1, SIDE_DIAG
        k_11 = pf[p11 + u]
        d_11 = pf[p29 + u]
        axial_11 = pf[p47 + u] * 0.5 * (st0 + st2)
        cross_11 = pf[p65 + u] * 0.5 * (fs0 + fs1)
        rest_11 = math.sqrt(axial_11 * axial_11 + cross_11 * cross_11)
        dx_11 = xx0n - xx2
        dy_11 = xy0n - xy2
        dz_11 = xz0n - xz2
        length_11 = math.sqrt(dx_11 * dx_11 + dy_11 * dy_11 + dz_11 * dz_11)
        ux_11 = dx_11 / length_11
        uy_11 = dy_11 / length_11
        uz_11 = dz_11 / length_11
        ldot_11 = (vx0n - vx2) * ux_11 + (vy0n - vy2) * uy_11 + (vz0n - vz2) * uz_11
        f_11 = k_11 * (rest_11 - length_11) - d_11 * ldot_11
        live_11 = length_11 >= 1e-12
        gq[g11x + j] = select(live_11, f_11 * ux_11, 0.0)
        gq[g11y + j] = select(live_11, f_11 * uy_11, 0.0)
        gq[g11z + j] = select(live_11, f_11 * uz_11, 0.0)
        # family 12: corner 2 of face t to corner 2 of face t + 1, AXIAL
        k_12 = pf[p12 + u]
        d_12 = pf[p30 + u]
        rest_12 = pf[p48 + u] * st2
        dx_12 = xx2n - xx2
        dy_12 = xy2n - xy2
        dz_12 = xz2n - xz2
        length_12 = math.sqrt(dx_12 * dx_12 + dy_12 * dy_12 + dz_12 * dz_12)
        ux_12 = dx_12 / length_12
        uy_12 = dy_12 / length_12
        uz_12 = dz_12 / length_12
        ldot_12 = (vx2n - vx2) * ux_12 + (vy2n - vy2) * uy_12 + (vz2n - vz2) * uz_12
        f_12 = k_12 * (rest_12 - length_12) - d_12 * ldot_12
        live_12 = length_12 >= 1e-12
        gq[g12x + j] = select(live_12, f_12 * ux_12, 0.0)
        gq[g12y + j] = select(live_12, f_12 * uy_12, 0.0)
        gq[g12z + j] = select(live_12, f_12 * uz_12, 0.0)
        # family 13: corner 2 of face t to corner 3 of face t + 0, CROSS
        k_13 = pf[p13 + u]
        d_13 = pf[p31 + u]
        rest_13 = pf[p67 + u] * fs0
        dx_13 = xx3 - xx2
        dy_13 = xy3 - xy2
        dz_13 = xz3 - xz2
        length_13 = math.sqrt(dx_13 * dx_13 + dy_13 * dy_13 + dz_13 * dz_13)
        ux_13 = dx_13 / length_13
        uy_13 = dy_13 / length_13
        uz_13 = dz_13 / length_13
        ldot_13 = (vx3 - vx2) * ux_13 + (vy3 - vy2) * uy_13 + (vz3 - vz2) * uz_13
        f_13 = k_13 * (rest_13 - length_13) - d_13 * ldot_13
        live_13 = length_13 >= 1e-12
        gq[g13x + j] = select(live_13, f_13 * ux_13, 0.0)
        gq[g13y + j] = select(live_13, f_13 * uy_13, 0.0)
        gq[g13z + j] = select(live_13, f_13 * uz_13, 0.0)
        # family 14: corner 2 of face t to corner 3 of face t + 1, SIDE_DIAG
        k_14 = pf[p14 + u]
        d_14 = pf[p32 + u]
        axial_14 = pf[p50 + u] * 0.5 * (st2 + st3)
        cross_14 = pf[p68 + u] * 0.5 * (fs0 + fs1)
        rest_14 = math.sqrt(axial_14 * axial_14 + cross_14 * cross_14)
        dx_14 = xx3n - xx2
        dy_14 = xy3n - xy2
        dz_14 = xz3n - xz2
        length_14 = math.sqrt(dx_14 * dx_14 + dy_14 * dy_14 + dz_14 * dz_14)
        ux_14 = dx_14 / length_14
        uy_14 = dy_14 / length_14
        uz_14 = dz_14 / length_14
        ldot_14 = (vx3n - vx2) * ux_14 + (vy3n - vy2) * uy_14 + (vz3n - vz2) * uz_14
        f_14 = k_14 * (rest_14 - length_14) - d_14 * ldot_14
        live_14 = length_14 >= 1e-12
        gq[g14x + j] = select(live_14, f_14 * ux_14, 0.0)
        gq[g14y + j] = select(live_14, f_14 * uy_14, 0.0)
        gq[g14z + j] = select(live_14, f_14 * uz_14, 0.0)
        # family 15: corner 3 of face t to corner 1 of face t + 1, SIDE_DIAG
        k_15 = pf[p15 + u]
        d_15 = pf[p33 + u]
        axial_15 = pf[p51 + u] * 0.5 * (st1 + st3)
        cross_15 = pf[p69 + u] * 0.5 * (fs0 + fs1)
        rest_15 = math.sqrt(axial_15 * axial_15 + cross_15 * cross_15)
        dx_15 = xx1n - xx3
        dy_15 = xy1n - xy3
        dz_15 = xz1n - xz3
        length_15 = math.sqrt(dx_15 * dx_15 + dy_15 * dy_15 + dz_15 * dz_15)
        ux_15 = dx_15 / length_15
        uy_15 = dy_15 / length_15
        uz_15 = dz_15 / length_15
        ldot_15 = (vx1n - vx3) * ux_15 + (vy1n - vy3) * uy_15 + (vz1n - vz3) * uz_15
        f_15 = k_15 * (rest_15 - length_15) - d_15 * ldot_15
        live_15 = length_15 >= 1e-12
        gq[g15x + j] = select(live_15, f_15 * ux_15, 0.0)
        gq[g15y + j] = select(live_15, f_15 * uy_15, 0.0)
        gq[g15z + j] = select(live_15, f_15 * uz_15, 0.0)
        # family 16: corner 3 of face t to corner 2 of face t + 1, SIDE_DIAG
        k_16 = pf[p16 + u]
        d_16 = pf[p34 + u]
        axial_16 = pf[p52 + u] * 0.5 * (st2 + st3)
        cross_16 = pf[p70 + u] * 0.5 * (fs0 + fs1)
        rest_16 = math.sqrt(axial_16 * axial_16 + cross_16 * cross_16)
        dx_16 = xx2n - xx3
        dy_16 = xy2n - xy3
        dz_16 = xz2n - xz3
        length_16 = math.sqrt(dx_16 * dx_16 + dy_16 * dy_16 + dz_16 * dz_16)
        ux_16 = dx_16 / length_16
        uy_16 = dy_16 / length_16
        uz_16 = dz_16 / length_16
        ldot_16 = (vx2n - vx3) * ux_16 + (vy2n - vy3) * uy_16 + (vz2n - vz3) * uz_16
        f_16 = k_16 * (rest_16 - length_16) - d_16 * ldot_16
        live_16 = length_16 >= 1e-12
        gq[g16x + j] = select(live_16, f_16 * ux_16, 0.0)
        gq[g16y + j] = select(live_16, f_16 * uy_16, 0.0)
        gq[g16z + j] = select(live_16, f_16 * uz_16, 0.0)
        # family 17: corner 3 of face t to corner 3 of face t + 1, AXIAL
        k_17 = pf[p17 + u]
        d_17 = pf[p35 + u]
        rest_17 = pf[p53 + u] * st3
        dx_17 = xx3n - xx3
        dy_17 = xy3n - xy3
        dz_17 = xz3n - xz3
        length_17 = math.sqrt(dx_17 * dx_17 + dy_17 * dy_17 + dz_17 * dz_17)
        ux_17 = dx_17 / length_17
        uy_17 = dy_17 / length_17
        uz_17 = dz_17 / length_17
        ldot_17 = (vx3n - vx3) * ux_17 + (vy3n - vy3) * uy_17 + (vz3n - vz3) * uz_17
        f_17 = k_17 * (rest_17 - length_17) - d_17 * ldot_17
        live_17 = length_17 >= 1e-12
        gq[g17x + j] = select(live_17, f_17 * ux_17, 0.0)
        gq[g17y + j] = select(live_17, f_17 * uy_17, 0.0)
        gq[g17z + j] = select(live_17, f_17 * uz_17, 0.0)


@njit(cache=True, error_model="numpy", inline="always")
def node_sums_chunk(gq, fcf, ps, row, t0, t1):
    """Pass 2 of ``kernels._column_forces_flat`` for the faces t0 <= t < t1: the spring force [N] on the
    node of corner c of face t, axis e, written to fcf[(4 e + c) ps + t] (fcf: the (3, 4, stride) forces
    flat, ps = stride): the 9 terms (family q, sign s, shift b) of ``CUBE_PLAN[c]`` in their order,
    starting from 0.0, each s * (family q's axis e in the chunk buffer gq, row length ``row``, at column
    1 + t - t0 - b): the per-family kernel's sum term by term (x + (-1.0 * y) == x - y exactly).  A b end
    reads its spring one column back (column 0: the face before the chunk, -0.0 before face 0: an exact
    no-op).  ps, row: uint64.
    """
    one = np.uint64(1)
    # fcf's row 4 e + c starts at (4 e + c) ps
    o1 = ps
    o2 = o1 + ps
    o3 = o2 + ps
    o4 = o3 + ps
    o5 = o4 + ps
    o6 = o5 + ps
    o7 = o6 + ps
    o8 = o7 + ps
    o9 = o8 + ps
    o10 = o9 + ps
    o11 = o10 + ps
    # the chunk buffer's rows: family q's axis e at row 3 q + e (h<q><e>: its start)
    h0x = row - row
    h0y = h0x + row
    h0z = h0y + row
    h1x = h0z + row
    h1y = h1x + row
    h1z = h1y + row
    h2x = h1z + row
    h2y = h2x + row
    h2z = h2y + row
    h3x = h2z + row
    h3y = h3x + row
    h3z = h3y + row
    h4x = h3z + row
    h4y = h4x + row
    h4z = h4y + row
    h5x = h4z + row
    h5y = h5x + row
    h5z = h5y + row
    h6x = h5z + row
    h6y = h6x + row
    h6z = h6y + row
    h7x = h6z + row
    h7y = h7x + row
    h7z = h7y + row
    h8x = h7z + row
    h8y = h8x + row
    h8z = h8y + row
    h9x = h8z + row
    h9y = h9x + row
    h9z = h9y + row
    h10x = h9z + row
    h10y = h10x + row
    h10z = h10y + row
    h11x = h10z + row
    h11y = h11x + row
    h11z = h11y + row
    h12x = h11z + row
    h12y = h12x + row
    h12z = h12y + row
    h13x = h12z + row
    h13y = h13x + row
    h13z = h13y + row
    h14x = h13z + row
    h14y = h14x + row
    h14z = h14y + row
    h15x = h14z + row
    h15y = h15x + row
    h15z = h15y + row
    h16x = h15z + row
    h16y = h16x + row
    h16z = h16y + row
    h17x = h16z + row
    h17y = h17x + row
    h17z = h17y + row
    for t in range(t0, t1):
        u = np.uint64(t)
        j = np.uint64(t - t0)  # a b end's column (its spring's face is t - 1)
        j1 = j + one  # an a end's column (face t)
        # corner 0, axis x (in parentheses, still summed left to right)
        fcf[u] = (0.0 + -1.0 * gq[h0x + j1] + 1.0 * gq[h0x + j] + -1.0 * gq[h1x + j1]
                 + -1.0 * gq[h2x + j1] + -1.0 * gq[h3x + j1] + -1.0 * gq[h4x + j1]
                 + -1.0 * gq[h5x + j1] + 1.0 * gq[h6x + j] + 1.0 * gq[h11x + j])
        # corner 1, axis x (in parentheses, still summed left to right)
        fcf[o1 + u] = (0.0 + 1.0 * gq[h1x + j1] + 1.0 * gq[h2x + j] + -1.0 * gq[h6x + j1]
                      + -1.0 * gq[h7x + j1] + 1.0 * gq[h7x + j] + -1.0 * gq[h8x + j1]
                      + -1.0 * gq[h9x + j1] + -1.0 * gq[h10x + j1] + 1.0 * gq[h15x + j])
        # corner 2, axis x (in parentheses, still summed left to right)
        fcf[o2 + u] = (0.0 + 1.0 * gq[h3x + j1] + 1.0 * gq[h4x + j] + 1.0 * gq[h8x + j1]
                      + -1.0 * gq[h11x + j1] + -1.0 * gq[h12x + j1] + 1.0 * gq[h12x + j]
                      + -1.0 * gq[h13x + j1] + -1.0 * gq[h14x + j1] + 1.0 * gq[h16x + j])
        # corner 3, axis x (in parentheses, still summed left to right)
        fcf[o3 + u] = (0.0 + 1.0 * gq[h5x + j1] + 1.0 * gq[h9x + j1] + 1.0 * gq[h10x + j]
                      + 1.0 * gq[h13x + j1] + 1.0 * gq[h14x + j] + -1.0 * gq[h15x + j1]
                      + -1.0 * gq[h16x + j1] + -1.0 * gq[h17x + j1] + 1.0 * gq[h17x + j])
        # corner 0, axis y (in parentheses, still summed left to right)
        fcf[o4 + u] = (0.0 + -1.0 * gq[h0y + j1] + 1.0 * gq[h0y + j] + -1.0 * gq[h1y + j1]
                      + -1.0 * gq[h2y + j1] + -1.0 * gq[h3y + j1] + -1.0 * gq[h4y + j1]
                      + -1.0 * gq[h5y + j1] + 1.0 * gq[h6y + j] + 1.0 * gq[h11y + j])
        # corner 1, axis y (in parentheses, still summed left to right)
        fcf[o5 + u] = (0.0 + 1.0 * gq[h1y + j1] + 1.0 * gq[h2y + j] + -1.0 * gq[h6y + j1]
                      + -1.0 * gq[h7y + j1] + 1.0 * gq[h7y + j] + -1.0 * gq[h8y + j1]
                      + -1.0 * gq[h9y + j1] + -1.0 * gq[h10y + j1] + 1.0 * gq[h15y + j])
        # corner 2, axis y (in parentheses, still summed left to right)
        fcf[o6 + u] = (0.0 + 1.0 * gq[h3y + j1] + 1.0 * gq[h4y + j] + 1.0 * gq[h8y + j1]
                      + -1.0 * gq[h11y + j1] + -1.0 * gq[h12y + j1] + 1.0 * gq[h12y + j]
                      + -1.0 * gq[h13y + j1] + -1.0 * gq[h14y + j1] + 1.0 * gq[h16y + j])
        # corner 3, axis y (in parentheses, still summed left to right)
        fcf[o7 + u] = (0.0 + 1.0 * gq[h5y + j1] + 1.0 * gq[h9y + j1] + 1.0 * gq[h10y + j]
                      + 1.0 * gq[h13y + j1] + 1.0 * gq[h14y + j] + -1.0 * gq[h15y + j1]
                      + -1.0 * gq[h16y + j1] + -1.0 * gq[h17y + j1] + 1.0 * gq[h17y + j])
        # corner 0, axis z (in parentheses, still summed left to right)
        fcf[o8 + u] = (0.0 + -1.0 * gq[h0z + j1] + 1.0 * gq[h0z + j] + -1.0 * gq[h1z + j1]
                      + -1.0 * gq[h2z + j1] + -1.0 * gq[h3z + j1] + -1.0 * gq[h4z + j1]
                      + -1.0 * gq[h5z + j1] + 1.0 * gq[h6z + j] + 1.0 * gq[h11z + j])
        # corner 1, axis z (in parentheses, still summed left to right)
        fcf[o9 + u] = (0.0 + 1.0 * gq[h1z + j1] + 1.0 * gq[h2z + j] + -1.0 * gq[h6z + j1]
                      + -1.0 * gq[h7z + j1] + 1.0 * gq[h7z + j] + -1.0 * gq[h8z + j1]
                      + -1.0 * gq[h9z + j1] + -1.0 * gq[h10z + j1] + 1.0 * gq[h15z + j])
        # corner 2, axis z (in parentheses, still summed left to right)
        fcf[o10 + u] = (0.0 + 1.0 * gq[h3z + j1] + 1.0 * gq[h4z + j] + 1.0 * gq[h8z + j1]
                       + -1.0 * gq[h11z + j1] + -1.0 * gq[h12z + j1] + 1.0 * gq[h12z + j]
                       + -1.0 * gq[h13z + j1] + -1.0 * gq[h14z + j1] + 1.0 * gq[h16z + j])
        # corner 3, axis z (in parentheses, still summed left to right)
        fcf[o11 + u] = (0.0 + 1.0 * gq[h5z + j1] + 1.0 * gq[h9z + j1] + 1.0 * gq[h10z + j]
                       + 1.0 * gq[h13z + j1] + 1.0 * gq[h14z + j] + -1.0 * gq[h15z + j1]
                       + -1.0 * gq[h16z + j1] + -1.0 * gq[h17z + j1] + 1.0 * gq[h17z + j])
