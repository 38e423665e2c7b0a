"""Each numba kernel of the mass-spring body against a slow numpy reference at a named tolerance."""
import math

import numpy as np
import pytest

from bench_myriapoda.bodies import friction_kernels as FK
from bench_myriapoda.bodies.massspring import kernels as K
from bench_myriapoda.bodies.massspring.body import BodyMassSpring
from bench_myriapoda.bodies.massspring.lattice import AXIAL, CROSS, SIDE_FACES, build_lattice
from bench_myriapoda.controllers.muscle_waves import (CORNER_Y, CORNER_Z, segment_activation,
                                                      segment_activation_numpy)
from bench_myriapoda.core.config import resolve_case
from bench_myriapoda.world import terrain_kernels as TK
from bench_myriapoda.world.world import build_world

TOL_EXACT = 1e-12        # same arithmetic in a different order
TOL_FD = 1e-6            # central finite differences of the spring energy (relative)

rng = np.random.default_rng(7)


def test_segment_activation_matches_numpy():
    waves = rng.normal(size=(3, 5))
    waves[:, 4] = [0.0, 1.0, 0.0]
    s = np.linspace(0.0, 1.0, 17)
    out = np.zeros((17, 3))
    for t in (0.0, 0.3, 2.7):
        segment_activation(waves, 1.0, s, t, out)
        np.testing.assert_allclose(out, segment_activation_numpy(waves, 1.0, s, t), atol=TOL_EXACT)


def rest_lengths_reference(lat, act, volume):
    """Rest lengths from the lattice's rules, written plainly."""
    n_seg = act.shape[0]
    stretch = np.maximum(1.0 + act[:, :1] + act[:, 1:2] * CORNER_Z[None] + act[:, 2:3] * CORNER_Y[None], K.MIN_STRETCH)
    face = np.ones(n_seg + 1)
    if volume:
        ax = np.maximum(1.0 + act[:, 0], K.MIN_STRETCH)
        for j in range(n_seg + 1):
            adj = [ax[i] for i in (j - 1, j) if 0 <= i < n_seg]
            face[j] = 1.0 / math.sqrt(np.mean(adj))
    out = np.zeros(lat.n_springs)
    for e in range(lat.n_springs):
        i, a, b = lat.seg[e], lat.corner_a[e], lat.corner_b[e]
        if lat.kind[e] == AXIAL:
            out[e] = lat.L0[e] * stretch[i, a]
        elif lat.kind[e] == CROSS:
            out[e] = lat.Lc[e] * face[i]
        else:
            out[e] = math.hypot(lat.L0[e] * 0.5 * (stretch[i, a] + stretch[i, b]), lat.Lc[e] * 0.5 * (face[i] + face[i + 1]))
    return out


@pytest.mark.parametrize("volume", [False, True])
def test_lattice_rest_lengths_match_reference(volume):
    lat = build_lattice(6, 0.05, 0.04, 0.03)
    act = rng.uniform(-0.3, 0.3, size=(6, 3))
    out = np.zeros(lat.n_springs)
    face = np.zeros(7)
    K.lattice_rest_lengths(act, volume, lat.kind, lat.seg, lat.corner_a, lat.corner_b, lat.L0, lat.Lc, face, np.zeros((6, 4)), out)
    np.testing.assert_allclose(out, rest_lengths_reference(lat, act, volume), rtol=TOL_EXACT)


def test_zero_activation_gives_the_rest_lattice():
    lat = build_lattice(5, 0.05, 0.04, 0.03)
    out = np.zeros(lat.n_springs)
    K.lattice_rest_lengths(np.zeros((5, 3)), True, lat.kind, lat.seg, lat.corner_a, lat.corner_b, lat.L0, lat.Lc,
                           np.zeros(6), np.zeros((5, 4)), out)
    np.testing.assert_allclose(out, lat.rest_length, rtol=TOL_EXACT)


def spring_energy(x, springs, k, rest):
    d = np.linalg.norm(x[springs[:, 1]] - x[springs[:, 0]], axis=1)
    return 0.5 * np.sum(k * (d - rest) ** 2)


def test_spring_forces_are_minus_the_energy_gradient():
    lat = build_lattice(3, 0.05, 0.04, 0.03)
    x = lat.rest_nodes + rng.normal(scale=0.005, size=lat.rest_nodes.shape)
    k = rng.uniform(1.0, 3.0, lat.n_springs)
    rest = lat.rest_length * rng.uniform(0.9, 1.1, lat.n_springs)
    f = np.zeros_like(x)
    K.spring_forces(x, np.zeros_like(x), lat.springs, k, np.zeros(lat.n_springs), rest, f)
    h = 1e-7
    grad = np.zeros_like(x)
    for n in range(x.shape[0]):
        for c in range(3):
            xp, xm = x.copy(), x.copy()
            xp[n, c] += h
            xm[n, c] -= h
            grad[n, c] = (spring_energy(xp, lat.springs, k, rest) - spring_energy(xm, lat.springs, k, rest)) / (2 * h)
    np.testing.assert_allclose(f, -grad, rtol=TOL_FD, atol=TOL_FD * np.abs(grad).max())


def test_spring_damping_opposes_relative_velocity():
    x = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    v = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]])  # separating at 2 m/s
    f = np.zeros_like(x)
    K.spring_forces(x, v, np.array([[0, 1]]), np.array([0.0]), np.array([0.5]), np.array([1.0]), f)
    np.testing.assert_allclose(f, [[1.0, 0, 0], [-1.0, 0, 0]], atol=TOL_EXACT)


@pytest.mark.parametrize("model", [FK.MILLER, FK.COULOMB, FK.STICK])
def test_ground_friction_matches_numpy(model):
    _, p = FK.friction_params(resolve_case("snake", "massspring", "flat").friction)
    for _ in range(300):
        v = rng.normal(size=3)
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        s = rng.normal(size=3)
        s /= np.linalg.norm(s)
        jn = abs(rng.normal()) * rng.choice([0.0, 0.3, 3.0])
        got = np.array(FK.ground_friction(model, p, *v, *n, *s, jn))
        np.testing.assert_allclose(got, FK.ground_friction_numpy(model, p, v, n, s, jn), atol=TOL_EXACT)


def test_coulomb_friction_never_reverses_sliding_and_sticks_when_it_can():
    p = np.zeros(FK.N_FRICTION_PARAMS)
    p[FK.MU_F:FK.MUS_T + 1] = 0.5
    n, s = np.array([0.0, 1.0, 0.0]), np.array([1.0, 0.0, 0.0])
    # kinetic: tangential speed 1, impulse budget 0.5 * 0.4 = 0.2 -> 0.8 left, same direction
    v = np.array(FK.ground_friction(FK.COULOMB, p, 0.6, -0.1, 0.8, *n, *s, 0.4))
    np.testing.assert_allclose(v[[0, 2]], [0.48, 0.64], atol=TOL_EXACT)
    # static: budget larger than the speed -> stops
    v = np.array(FK.ground_friction(FK.COULOMB, p, 0.06, -0.1, 0.08, *n, *s, 0.4))
    np.testing.assert_allclose(v[[0, 2]], [0.0, 0.0], atol=TOL_EXACT)


def test_terrain_signed_distance_matches_numpy_and_intersection_lies_on_surface():
    for kind, f in ((TK.PLANE, [0.1, 0, 0, 0, 0, 0, 0, 0]), (TK.SLOPE, [0.0, 0.5, 0, 0, 0, 0, 0, 0]),
                    (TK.SLAB, [0.0, 0.3, 0.2, 0.05, 0, 0, 0, 0])):
        f = np.array(f, float)
        pts = rng.uniform(-1, 1, size=(500, 3))
        got = np.array([TK.signed_distance(kind, f, *p) for p in pts])
        np.testing.assert_allclose(got, TK.terrain_phi_numpy(kind, f, pts), atol=TOL_EXACT)
        for p0, p1 in zip(pts[:-1], pts[1:]):
            if TK.signed_distance(kind, f, *p0) > 0 > TK.signed_distance(kind, f, *p1):
                s = TK.segment_surface_intersection(kind, f, *p0, *p1)
                q = p0 + s * (p1 - p0)
                assert abs(TK.signed_distance(kind, f, *q)) < 1e-9


def reference_step(x, v, inv_mass, lat, k, c, rest, g, dt, fric_model, fric, r_n, r_t, euler=False):
    """One step on a plane at y = 0, written with numpy (symplectic, or Miller's Euler)."""
    f = np.zeros_like(x)
    d = x[lat.springs[:, 1]] - x[lat.springs[:, 0]]
    length = np.linalg.norm(d, axis=1)
    u = d / length[:, None]
    ldot = np.einsum("ij,ij->i", v[lat.springs[:, 1]] - v[lat.springs[:, 0]], u)
    mag = k * (rest - length) - c * ldot
    np.add.at(f, lat.springs[:, 0], -mag[:, None] * u)
    np.add.at(f, lat.springs[:, 1], mag[:, None] * u)
    faces = x.reshape(-1, 4, 3).mean(axis=1)
    nf = faces.shape[0]
    # Miller's stick rule holds the corners of segments in contact: a side face's centre within
    # the contact distance (corner pairs of lattice.SIDE_FACES on faces i and i + 1)
    quads = x.reshape(-1, 4, 3)
    seg_held = [any(quads[i:i + 2][:, [a, b], 1].mean() < fric[FK.CONTACT_DISTANCE] for a, b in SIDE_FACES)
                for i in range(nf - 1)]
    vn = v + dt * (f * inv_mass[:, None] - np.array([0.0, g, 0.0]))
    xn = x.copy()
    for n in range(x.shape[0]):
        j = n // 4
        sp = faces[max(j - 1, 0)] - faces[min(j + 1, nf - 1)]
        sp /= np.linalg.norm(sp)
        held = fric_model != FK.STICK or (j > 0 and seg_held[j - 1]) or (j < nf - 1 and seg_held[j])
        if x[n, 1] < fric[FK.CONTACT_DISTANCE] and held:
            # the normal impulse the collision below delivers: only when the step's path reaches the ground
            travel_y = dt * (0.5 * (v[n, 1] + vn[n, 1]) if euler else vn[n, 1])
            reaches = fric_model == FK.STICK or x[n, 1] + travel_y < 0
            jn = -(1 + r_n) * vn[n, 1] if (vn[n, 1] < 0 and reaches) else 0.0
            vn[n] = FK.ground_friction_numpy(fric_model, fric, vn[n], np.array([0.0, 1.0, 0.0]), sp, jn)
        q = x[n] + dt * (0.5 * (v[n] + vn[n]) if euler else vn[n])
        if q[1] < 0:
            s = x[n, 1] / (x[n, 1] - q[1])
            i = x[n] + s * (q - x[n])
            dd = q - i
            q = i + np.array([r_t * dd[0], -r_n * dd[1], r_t * dd[2]])
            if vn[n, 1] < 0:
                vn[n] = np.array([r_t * vn[n, 0], -r_n * vn[n, 1], r_t * vn[n, 2]])
        xn[n] = q
    return xn, vn


@pytest.mark.parametrize("creature,integrator", [("snake", "symplectic"), ("worm", "symplectic"),
                                                 ("caterpillar", "symplectic"), ("snake", "euler")])
def test_advance_one_step_matches_numpy_step(creature, integrator):
    case = resolve_case(creature, "massspring", "drop", overrides=["scenario.passive=true", "scenario.start_height_m=0.0005",
                                                                   "collision.r_n=0.2", "collision.r_t=0.9",
                                                                   f"body.integrator={integrator}"])
    body = BodyMassSpring(case, build_world(case))
    body.v[:] = rng.normal(scale=0.05, size=body.v.shape)
    body.x[:] += rng.normal(scale=0.0005, size=body.x.shape)
    # every mass starts above the ground (the kernel and the reference treat a start inside
    # differently on purpose); the underside sits within one step's travel so many collide
    bottom = body.x[:, 1] < 0.002
    body.x[bottom, 1] = rng.uniform(0.0, 5e-6, bottom.sum())
    x0, v0 = body.x.copy(), body.v.copy()
    xr, vr = reference_step(x0, v0, body.inv_mass, body.lattice, body.stiffness, body.damping,
                            body.lattice.rest_length, case.scenario.gravity_m_s2, case.dt, body.fric_model, body.fric,
                            0.2, 0.9, euler=integrator == "euler")
    done, status = body.advance(0.0, 1)
    assert (done, status) == (1, K.OK)
    np.testing.assert_allclose(body.x, xr, atol=TOL_EXACT)
    np.testing.assert_allclose(body.v, vr, atol=1e-10)


def test_symplectic_lattice_conserves_energy_without_damping_or_ground():
    case = resolve_case("snake", "massspring", "drop", overrides=[
        "scenario.passive=true", "scenario.gravity_m_s2=0", "body.damping=0", "scenario.start_height_m=1.0"])
    body = BodyMassSpring(case, build_world(case))
    body.v[:] = rng.normal(scale=0.02, size=body.v.shape)
    body.v -= body.v.mean(axis=0)
    e0 = sum(body.energy(0.0))
    energies = []
    for i in range(20):
        body.advance(0.0, 500)
        energies.append(sum(body.energy(0.0)))
    assert max(abs(e - e0) for e in energies) / e0 < 0.01  # symplectic Euler: bounded energy error, no drift


def test_lattice_energy_matches_numpy():
    case = resolve_case("worm", "massspring", "drop", overrides=["scenario.passive=true"])
    body = BodyMassSpring(case, build_world(case))
    body.x[:] += rng.normal(scale=0.002, size=body.x.shape)
    body.v[:] = rng.normal(scale=0.1, size=body.v.shape)
    ke, el, pg = body.energy(0.0)
    lat = body.lattice
    assert ke == pytest.approx(0.5 * np.sum(body.mass[:, None] * body.v ** 2), rel=TOL_EXACT)
    assert el == pytest.approx(spring_energy(body.x, lat.springs, body.stiffness, lat.rest_length), rel=1e-10)
    assert pg == pytest.approx(np.sum(body.mass * case.scenario.gravity_m_s2 * body.x[:, 1]), rel=TOL_EXACT)


def test_miller_presets_fill_unset_constants_only():
    case = resolve_case("snake", "massspring", "flat", overrides=["body.damping=2.0"])
    assert (case.body.stiffness, case.body.damping, case.body.substeps_per_frame) == (0.5, 2.0, 25)
    worm = resolve_case("worm", "massspring", "flat")
    assert (worm.body.stiffness, worm.body.damping, worm.body.substeps_per_frame) == (1.5, 0.9, 10)
    assert worm.dt == pytest.approx(1.0 / (worm.body.frame_rate_hz * 10))


def test_a_mass_above_the_ground_gets_no_friction_until_its_step_reaches_the_ground():
    """Friction is at most mu times the normal impulse the step's collision delivers: a mass inside
    the contact distance that moves down but does not reach the surface this step keeps its
    tangential velocity; one whose step reaches it is braked by mu (1 + r_n) |v_n|."""
    from bench_myriapoda.bodies.contact_kernels import contact_friction

    p = np.zeros(FK.N_FRICTION_PARAMS)
    p[FK.CONTACT_DISTANCE], p[FK.MU_F], p[FK.MU_B], p[FK.MU_T] = 0.005, 0.5, 0.5, 0.5
    p[FK.MUS_F], p[FK.MUS_B], p[FK.MUS_T] = 0.5, 0.5, 0.5
    kind, terr = TK.PLANE, np.zeros(TK.N_TERRAIN_PARAMS)  # the plane y = 0
    dt, v = 1e-3, np.array([0.3, -0.2, 0.0])
    above = contact_friction(kind, terr, FK.COULOMB, p, 0.0, (0.0, 0.002, 0.0), tuple(v), (1.0, 0.0, 0.0),
                             0.002, tuple(dt * v))
    np.testing.assert_allclose(above, v)
    reaching = contact_friction(kind, terr, FK.COULOMB, p, 0.0, (0.0, 0.0001, 0.0), tuple(v), (1.0, 0.0, 0.0),
                                0.0001, tuple(dt * v))
    np.testing.assert_allclose(reaching, [0.3 - 0.5 * 0.2, -0.2, 0.0])


def test_stick_holds_segments_resting_a_face_on_the_ground_not_a_cube_on_one_edge():
    """Miller's caterpillar rule (Sec. 4) holds the segments in contact.  A head cube standing on its
    front ventral edge (its rear face lifted 2 cm) is not in contact: that edge keeps its sliding
    velocity (held, it was the pivot the lattice caterpillar somersaulted over on the 45 degree
    descent; issue 11), while the corners of the segments resting flat behind it are held."""
    case = resolve_case("caterpillar", "massspring", "drop", overrides=[
        "scenario.passive=true", "scenario.start_height_m=0.001", "body.stiffness=0", "body.damping=0"])
    body = BodyMassSpring(case, build_world(case))
    assert body.fric_model == FK.STICK
    body.x[4:8, 1] += 0.02                      # face 1 (rear face of the head cube) lifted
    body.v[:] = [1.0, -0.01, 0.0]               # sliding along +x, pressing toward the ground
    done, status = body.advance(0.0, 1)
    assert (done, status) == (1, K.OK)
    np.testing.assert_allclose(body.v[0:2, 0], 1.0, atol=TOL_EXACT)   # the edge slides on
    assert np.all(body.v[8:, 0][np.tile([True, True, False, False], body.v[8:].shape[0] // 4)] == 0.0)
    np.testing.assert_allclose(body.v[2:4, 0], 1.0, atol=TOL_EXACT)   # dorsal corners: free flight


@pytest.mark.parametrize("segments", [1, 3, 6, 12, 25, 38, 39, 60])
def test_family_spring_forces_bitwise_equal_numpys_three_pass_order(segments):
    # kernels.family_spring_forces gives every node the same doubles as numpy's three passes per family
    # (forces, minus at the a ends, plus at the b ends), short and long lattices alike
    from bench_myriapoda.bodies.massspring.lattice import FAM_A, FAM_B, FAM_SHIFT, PAR_D, PAR_K
    case = resolve_case("snake", "massspring", "flat", overrides=[f"creature.segments={segments}"])
    body = BodyMassSpring(case, build_world(case))
    r = np.random.default_rng(segments)
    x = body.x + r.normal(scale=0.003, size=body.x.shape)
    x[4:8] = x[0:4]  # zero-length axial springs (a spring shorter than 1e-12 m pulls nothing)
    v = r.normal(size=body.x.shape)
    fam = body.families
    xc, vc, fc = body._xc, body._vc, body._fc
    K._corner_major(x, xc)
    K._corner_major(v, vc)
    K.family_rest_lengths(r.normal(scale=0.1, size=(segments, 3)), True, fam.index, fam.params, body._stretch_c,
                          body._face_scale, body._rest_fam)
    fc[:] = 0.0
    K.family_spring_forces(xc, vc, fam.index, fam.params, body._rest_fam, body._dfs, fc)
    ref = np.zeros_like(fc)
    n_faces = xc.shape[2]
    with np.errstate(divide="ignore", invalid="ignore"):
        for q in range(fam.index.shape[0]):
            a, b, s = fam.index[q, FAM_A], fam.index[q, FAM_B], fam.index[q, FAM_SHIFT]
            n = n_faces - s
            d = xc[:, b, s:] - xc[:, a, :n]
            length = np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
            u = d / length
            dv = vc[:, b, s:] - vc[:, a, :n]
            ldot = dv[0] * u[0] + dv[1] * u[1] + dv[2] * u[2]
            f = fam.params[PAR_K, q, :n] * (body._rest_fam[q, :n] - length) - fam.params[PAR_D, q, :n] * ldot
            g = np.where(length >= 1e-12, f * u, 0.0)
            ref[:, a, :n] -= g
            ref[:, b, s:] += g
    assert np.array_equal(fc, ref)


def _family_reference(segments, state):
    """A snake body of ``segments`` segments, a state (x, v) and muscle strains act, and the reference spring
    forces fu (3, 4, n_faces): the per-family kernels on rows of exactly n_faces columns.  ``random``: random
    positions with zero-length axial springs; ``collapsed``: every node at one point (every force +0.0)."""
    case = resolve_case("snake", "massspring", "flat", overrides=[f"creature.segments={segments}"])
    body = BodyMassSpring(case, build_world(case))
    r = np.random.default_rng(100 + segments)
    n_faces = segments + 1
    if state == "random":
        x = body.x + r.normal(scale=0.003, size=body.x.shape)
        x[4:8] = x[0:4]  # zero-length axial springs
        v = r.normal(size=body.x.shape)
    else:
        x = np.zeros_like(body.x) + 0.25
        v = np.zeros_like(body.x)
    act = r.normal(scale=0.1, size=(segments, 3))
    fam = body.families
    xu, vu, fu = (np.zeros((3, 4, n_faces)) for _ in range(3))
    K._corner_major(x, xu)
    K._corner_major(v, vu)
    params = np.ascontiguousarray(fam.params[:, :, :n_faces])
    rest = np.zeros((fam.index.shape[0], n_faces))
    K.family_rest_lengths(act, True, fam.index, params, np.ones((4, segments)), np.ones(n_faces), rest)
    K.family_spring_forces(xu, vu, fam.index, params, rest, np.zeros((3, n_faces)), fu)
    return body, x, v, act, fu


# 63 and 64 segments: the last face's springs at the last column of the first chunk of 64 faces, and at the
# first of the second; 200: four chunks
@pytest.mark.parametrize("segments", [1, 2, 3, 6, 7, 12, 25, 38, 39, 60, 62, 63, 64, 127, 128, 200])
@pytest.mark.parametrize("state", ["random", "collapsed"])
def test_column_spring_forces_bitwise_equal_the_family_kernels(segments, state):
    """The step's column loops (all 18 families of a face in one loop, then all 12 sums of a face, chunk by
    chunk of ``K.CHUNK_FACES`` faces) give every node the bits of the per-family kernels, signed zeros
    included; a second call from the state the first left gives the same (no scratch carried over)."""
    from bench_myriapoda.bodies.massspring.lattice import face_stride
    body, x, v, act, fu = _family_reference(segments, state)
    n_faces = segments + 1
    xc, vc, fc = body._xc, body._vc, body._fc
    stride = xc.shape[2]  # padded corner rows: whole vectors of 8, at least one padding column
    assert stride == face_stride(n_faces) and stride >= n_faces + 1 and stride % 8 == 0
    K._corner_major(x, xc)
    K._corner_major(v, vc)
    for _ in range(2):
        fc[:] = np.nan  # every real column is overwritten
        K.column_spring_forces(act, True, xc, vc, body.families.params, body._face_scale, body._st, body._fs, fc)
        got = np.ascontiguousarray(fc[:, :, :n_faces])
        assert np.array_equal(got.view(np.int64), fu.view(np.int64))
    if state == "collapsed":
        assert np.all(got.view(np.int64) == 0)  # +0.0, not -0.0


def test_cube_lattice_constants():
    """The kernels' compile-time tables are those of the lattice code: ``CUBE_FAMILIES`` is ``spring_families``'
    index of every length, ``CUBE_PLAN`` the families' summation order (``cube_plan``), each term naming a
    family that ends at its corner (a end: no shift; b end: the family's shift), and the shifted families the
    kernel fixes up are the families with shift 1."""
    from bench_myriapoda.bodies.massspring.lattice import (CUBE_FAMILIES, CUBE_PLAN, FAM_A, FAM_B, FAM_SHIFT,
                                                           cube_plan, spring_families)
    for n_seg in (1, 5, 64):
        lat = build_lattice(n_seg, 0.1, 0.05, 0.04)
        fam = spring_families(lat, np.ones(lat.n_springs), np.zeros(lat.n_springs))
        assert tuple(tuple(int(c) for c in row) for row in fam.index) == CUBE_FAMILIES
        for c in range(4):
            for q, sign, shift in CUBE_PLAN[c]:
                row = fam.index[q]
                assert sign in (-1, 1) and c == (row[FAM_A] if sign < 0 else row[FAM_B])
                assert shift == (0 if sign < 0 else row[FAM_SHIFT])
        # every spring end is one term of one corner's sum: the a and b ends of the 18 families
        assert sorted((q, sign) for c in range(4) for q, sign, _ in CUBE_PLAN[c]) == sorted(
            [(q, -1) for q in range(fam.index.shape[0])] + [(q, 1) for q in range(fam.index.shape[0])])
    assert cube_plan() == CUBE_PLAN
    assert list(K.SHIFTED_FAMILIES) == [q for q, row in enumerate(CUBE_FAMILIES) if row[FAM_SHIFT] == 1]


def test_spring_families_of_a_cube_lattice():
    """Miller's cube lattice has 18 spring families (6 cross-section edges and diagonals, 4 axial edges, 8 side
    diagonals), and each of the four corners sums 9 spring forces (3 face edges, 2 axial edges, 4 side
    diagonals); a family's params are set exactly on its springs' faces."""
    from bench_myriapoda.bodies.massspring.lattice import (AXIAL, CROSS, CUBE_PLAN, FAM_KIND, FAM_SHIFT, PAR_K,
                                                           SIDE_DIAG, spring_families)
    lat = build_lattice(5, 0.1, 0.05, 0.04)
    fam = spring_families(lat, np.ones(lat.n_springs), np.zeros(lat.n_springs))
    kinds = list(fam.index[:, FAM_KIND])
    assert fam.index.shape[0] == 18 and (kinds.count(CROSS), kinds.count(AXIAL), kinds.count(SIDE_DIAG)) == (6, 4, 8)
    assert all(len(CUBE_PLAN[c]) == 9 for c in range(4))
    for c in range(4):
        ends = [fam.index[q, FAM_KIND] for q, _, _ in CUBE_PLAN[c]]
        assert (ends.count(CROSS), ends.count(AXIAL), ends.count(SIDE_DIAG)) == (3, 2, 4)
    for q in range(18):  # stiffness only where a spring is: 6 faces without shift, 5 segments with
        assert list(np.nonzero(fam.params[PAR_K, q])[0]) == list(range(6 - fam.index[q, FAM_SHIFT]))
    assert int(np.sum(fam.spring >= 0)) == lat.n_springs


def _coulomb_cases(r, n_cases, n):
    """(v, s, jn) rows for the batched Coulomb friction, with the edge cases of ``ground_friction``:
    no normal impulse, no tangential speed, a spine along the normal, static and kinetic friction."""
    v = r.normal(size=(n_cases, 3))
    s = r.normal(size=(n_cases, 3))
    s /= np.linalg.norm(s, axis=1)[:, None]
    jn = np.abs(r.normal(size=n_cases)) * r.choice([0.0, 0.05, 0.3, 3.0], size=n_cases)
    v[0:8] = v[0:8] @ np.outer(n, n)  # moving along the normal only: zero tangential speed
    s[8:16] = n * r.choice([-1.0, 1.0], size=(8, 1))  # spine along the normal (fl < 1e-12)
    jn[16:20] = 0.0
    jn[20:24] = -0.1
    v[24] = 0.0
    v[25] = [0.0, -0.0, 0.0]
    return v, s, jn


@pytest.mark.parametrize("normal", [(0.0, 1.0, 0.0), (-math.sin(0.4), math.cos(0.4), 0.0)])
def test_coulomb_friction_batch_bitwise_equals_ground_friction(normal):
    """The vectorised friction of the batched node pass gives the bits of ``ground_friction``."""
    r = np.random.default_rng(13)
    _, p = FK.friction_params(resolve_case("snake", "massspring", "flat").friction)
    n = np.array(normal)
    m = 400
    v, s, jn = _coulomb_cases(r, m, n)
    ref = np.array([FK.ground_friction(FK.COULOMB, p, *v[k], *n, *s[k], jn[k]) for k in range(m)])
    got = [np.ascontiguousarray(v[:, d]) for d in range(3)]
    K.coulomb_friction_batch(p, *n, *got, *(np.ascontiguousarray(s[:, d]) for d in range(3)), jn, m)
    assert np.array_equal(np.stack(got, axis=1).view(np.int64), ref.view(np.int64))  # the bits, signed zeros too


@pytest.mark.parametrize("scenario,integrator,blowup", [("flat", "symplectic", ""), ("flat", "euler", ""),
                                                        ("slope", "symplectic", ""), ("flat", "symplectic", "speed"),
                                                        ("slope", "euler", "nan")])
def test_batched_node_pass_bitwise_equals_the_general_node_block(scenario, integrator, blowup):
    """``_nodes_coulomb_flat`` (the snake's node pass) and ``_nodes_general`` give the same bits: friction,
    collisions (nodes started inside and below the plane), held nodes, contact count, statistics and the
    step's status (a runaway speed, a non-finite force)."""
    case = resolve_case("snake", "massspring", scenario, overrides=["creature.segments=12", f"body.integrator={integrator}",
                                                                    "collision.r_n=0.2", "collision.r_t=0.9"])
    body = BodyMassSpring(case, build_world(case))
    assert body.fric_model == FK.COULOMB and body.terr_kind in (TK.PLANE, TK.SLOPE)
    r = np.random.default_rng(11)
    n_nodes = body.x.shape[0]
    phi = np.array([TK.signed_distance(body.terr_kind, body.terr, *p) for p in body.x])
    x = body.x - np.outer(phi, [0.0, 1.0, 0.0]) + np.outer(r.uniform(-2e-5, 0.002, n_nodes), [0.0, 1.0, 0.0])
    x += r.normal(scale=1e-3, size=x.shape) * [1.0, 0.0, 1.0]
    v = r.normal(scale=0.05, size=x.shape)
    normal = np.array(TK.surface_normal(body.terr_kind, body.terr, 0.0, 0.0, 0.0))
    hit = np.arange(0, n_nodes, 5)  # 1e-5 m above the surface, moving into it at 0.1 m/s: they collide
    x[hit] += np.outer(1e-5 - np.array([TK.signed_distance(body.terr_kind, body.terr, *p) for p in x[hit]]), normal)
    v[hit] -= 0.1 * normal
    inv_mass = body.inv_mass.copy()
    inv_mass[[3, 17]] = 0.0  # held nodes are left in place
    xc, vc, fc = (np.zeros((3, 4, n_nodes // 4)) for _ in range(3))
    K._corner_major(x, xc)
    K._corner_major(v, vc)
    fc[:] = r.normal(scale=2.0, size=fc.shape) * body.mass[0]
    spine = r.normal(size=(n_nodes // 4, 3))
    spine /= np.linalg.norm(spine, axis=1)[:, None]
    spine[2] = [0.0, 1.0, 0.0]  # a face standing up
    phys = body.phys.copy()
    if blowup == "speed":
        phys[K.MAX_SPEED] = 0.08  # some nodes, not all, are faster
    elif blowup == "nan":
        fc[1, 2, 5] = np.nan
    acc_a, acc_b = np.zeros(body.acc.shape), np.zeros(body.acc.shape)
    xa, va, xb, vb = xc.copy(), vc.copy(), xc.copy(), vc.copy()
    seg_held = np.zeros(n_nodes // 4 - 1, dtype=np.bool_)
    work = np.zeros((K.N_WORK, n_nodes))
    imc = np.ascontiguousarray(inv_mass.reshape(-1, 4).T)
    code = np.zeros((4, n_nodes // 4), dtype=np.int64)
    g_dt = (case.scenario.gravity_m_s2, case.dt)  # the step's world and time step (plain arguments, issue 42)
    got = K._nodes_coulomb_flat(xa, va, fc, imc, spine, body.fric, body.terr_kind, body.terr, phys, acc_a,
                                work, code, g_dt)
    ref = K._nodes_general(xb, vb, fc, inv_mass, spine, False, seg_held, body.fric_model, body.fric, body.terr_kind,
                           body.terr, phys, acc_b, g_dt)
    assert got == ref and 0 < got[0] < n_nodes
    assert ref[1] == {"": K.OK, "speed": K.RUNAWAY_SPEED, "nan": K.NONFINITE}[blowup]
    assert np.sum((np.einsum("d,dcf->cf", normal, va) > 0.0) & (np.einsum("d,dcf->cf", normal, vc) < 0.0)) > 2  # collided
    assert np.array_equal(xa.view(np.int64), xb.view(np.int64)) and np.array_equal(va.view(np.int64), vb.view(np.int64))
    assert np.array_equal(acc_a.view(np.int64), acc_b.view(np.int64))
    assert np.array_equal(acc_a, acc_b)
    assert np.array_equal(xa[:, 3, 0], xc[:, 3, 0]) and np.array_equal(va[:, 1, 4], vc[:, 1, 4])


@pytest.mark.parametrize("integrator", ["symplectic", "euler"])
def test_batched_node_pass_with_rows_partly_off_the_ground_bitwise_equals_the_general_node_block(integrator):
    """The friction of the batched node pass runs over whole corner rows that hold a touching node; the
    nodes of those rows that are off the ground (beyond the contact distance), and the padding columns of
    the step kernel's layout (stride > n_faces), keep their velocities exactly: the same bits as
    ``_nodes_general`` with the dorsal rows lifted and some ventral nodes off the plane, as on the snake."""
    case = resolve_case("snake", "massspring", "flat", overrides=["creature.segments=9", f"body.integrator={integrator}"])
    body = BodyMassSpring(case, build_world(case))
    r = np.random.default_rng(5)
    n_nodes = body.x.shape[0]
    n_faces = n_nodes // 4
    x = body.x.copy()
    x[:, 1] = 0.0
    x[2::4, 1] = x[3::4, 1] = 0.05  # dorsal rows: far above the contact distance
    contact = body.fric[FK.CONTACT_DISTANCE]
    x[0::4, 1] = r.uniform(-2e-5, 2.0 * contact, n_faces)  # ventral: some touch, some are off the ground
    x[1::4, 1] = r.uniform(-2e-5, 2.0 * contact, n_faces)
    v = r.normal(scale=0.05, size=x.shape)
    v[0::4, 1] = v[1::4, 1] = -0.1  # moving into the plane: normal impulses and collisions
    assert 2 < np.sum(x[:, 1] < contact) < n_nodes // 2 and np.any((x[:, 1] >= contact) & (x[:, 1] < 0.05))
    stride = body._xc.shape[2]
    assert stride > n_faces
    xc, vc = np.zeros((3, 5, stride)), np.zeros((3, 5, stride))
    fc = np.zeros((3, 4, stride))
    K._corner_major(x, xc)
    K._corner_major(v, vc)
    fc[:, :, :n_faces] = r.normal(scale=2.0, size=(3, 4, n_faces)) * body.mass[0]
    spine = r.normal(size=(n_faces, 3))
    spine /= np.linalg.norm(spine, axis=1)[:, None]
    imc = np.zeros((4, stride))
    imc[:, :n_faces] = body.inv_mass.reshape(-1, 4).T
    xa, va, xb, vb = xc.copy(), vc.copy(), xc.copy(), vc.copy()
    acc_a, acc_b = np.zeros(body.acc.shape), np.zeros(body.acc.shape)
    work = np.zeros((K.N_WORK, 4 * stride))
    code = np.zeros((4, stride), dtype=np.int64)
    g_dt = (case.scenario.gravity_m_s2, case.dt)  # the step's world and time step (plain arguments, issue 42)
    got = K._nodes_coulomb_flat(xa, va, fc, imc, spine, body.fric, body.terr_kind, body.terr, body.phys, acc_a,
                                work, code, g_dt)
    ref = K._nodes_general(xb, vb, fc, body.inv_mass, spine, False, np.zeros(n_faces - 1, dtype=np.bool_),
                           body.fric_model, body.fric, body.terr_kind, body.terr, body.phys, acc_b, g_dt)
    assert got == ref and got[0] == np.sum(x[:, 1] < contact)
    assert np.array_equal(xa.view(np.int64), xb.view(np.int64)) and np.array_equal(va.view(np.int64), vb.view(np.int64))
    assert np.array_equal(acc_a.view(np.int64), acc_b.view(np.int64))
    lifted = (x[:, 1] >= contact).reshape(-1, 4).T  # (4, n_faces): off the ground, no friction
    dt, g = g_dt[1], g_dt[0]
    free_fall = vc[1, :4, :n_faces] + dt * (fc[1, :, :n_faces] * imc[:, :n_faces] - g)
    assert np.array_equal(va[1, :4, :n_faces][lifted], free_fall[lifted])


def test_generated_column_loop_is_current():
    """``column_loop.py`` (the column loops written out from ``lattice.CUBE_FAMILIES``) is exactly what its generator
    gives today: a change to the family table or the generator without regenerating fails here (and the kernels'
    import refuses a file made from another table)."""
    from bench_myriapoda.bodies.massspring import column_codegen, column_loop
    from bench_myriapoda.bodies.massspring.lattice import CUBE_FAMILIES, CUBE_PLAN
    assert column_codegen.TARGET.read_text() == column_codegen.render()
    assert column_loop.CUBE_FAMILIES == CUBE_FAMILIES and column_loop.CUBE_PLAN == CUBE_PLAN


def test_lane_select_picks_bit_for_bit():
    """``lane_select.select`` is ``a if c else b`` exactly: signed zeros, NaN and infinities come through unchanged."""
    from numba import njit
    from bench_myriapoda.bodies.massspring.lane_select import select

    @njit
    def pick(c, a, b):
        return select(c, a, b)

    for a, b in ((1.5, -0.0), (-0.0, 0.0), (np.nan, 2.0), (np.inf, -np.inf)):
        for c in (True, False):
            got, want = np.float64(pick(c, a, b)), np.float64(a if c else b)
            assert got.view(np.int64) == want.view(np.int64)
