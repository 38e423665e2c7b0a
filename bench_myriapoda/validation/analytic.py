"""Analytic checks (shared/reference/VALIDATION.md, "Analytic"): closed-form answers the body
models must reproduce.  Formulas in ``references``; tolerances here, one constant each, so a
test can break one on purpose.
"""
from __future__ import annotations

import numpy as np

from ..core import registry
from . import references as R
from .core import Context, Outcome, at_most, failed_run, holds, not_applicable, relative

WORM_REL_TOL = 0.05          # eps * Lambda within 5 % once the gait is steady (VALIDATION.md)
BAR_REL_TOL = 0.05           # hanging bar on a converged mesh (VALIDATION.md)
CANTILEVER_REL_TOL = 0.05    # tip deflection, converged (VALIDATION.md)
RIGID_REL_TOL = 1e-10        # |f| / (mu V^(2/3)) under a rigid motion (VALIDATION.md)
MOMENTUM_REL_TOL = 1e-10     # |P - (P0 + M g t)| / (|P0| + M g t) in free flight (round-off: ~1e-14 seen)
STABLE_DT_REL_TOL = 0.08     # bisection bracket 2 % plus the finite duration growth needs to show
DAMPING_EXACT_TOL = 1e-10    # backward-Euler factor of a pure damping mode (linear algebra)
DAMPING_OSC_TOL = 1e-6       # |eigenvalue| of the linearized one-step map (finite differences)


def _probes(body: str):
    """The body model's ``BodySpec.probes`` (``core.specs.BodyProbes``; plugins' bodies included)."""
    registry.load_all()
    return registry.BODIES[body].probes


# --------------------------------------------------------------------------- the worm: eps * Lambda

def worm_eps_lambda(ctx: Context, body: str) -> Outcome:
    """The rectilinear worm's displacement per cycle against eps * Lambda (perfect anchoring)."""
    duration = 16.0 if ctx.quick else 30.0
    r = ctx.run("worm", body, "flat", duration=duration)
    case = r.case
    ref = R.worm_displacement_per_cycle(case.gait.amplitude, case.gait.wavelength_bl * case.creature.body_length_m)
    if r.status != "ok":
        return failed_run(r, ref)
    return relative(r.metrics["displacement_per_cycle_m"], ref, WORM_REL_TOL, "m",
                    cycles=r.metrics.get("cycles_measured"), duration_s=duration,
                    travel_angle_deg=r.metrics.get("travel_angle_deg"))


# --------------------------------------------------------------------------- FEM statics

def hanging_bar(ctx: Context, body: str) -> Outcome:
    """FEM bar hanging under its own weight (nu = 0.3, top face clamped) against rho g L^2 / (2 E)."""
    probes = _probes(body)
    if probes.bar_under_own_weight is None:
        return not_applicable("the body publishes no hanging bar (BodyProbes.bar_under_own_weight)", None,
                              "rho g L^2 / (2 E)")
    n = 8 if ctx.quick else 16
    _s, ratio = R.hanging_bar(n, nu=0.3, solve=probes.bar_under_own_weight)
    E, rho, g, L = 1e4, 1.0, 9.81, 1.0
    ref = R.hanging_bar_displacement(rho, g, L, E)
    return relative(ratio * ref, ref, BAR_REL_TOL, "m", detail=f"{n} cells along the bar; ratio {ratio:.4f} "
                    "(linear tets converge from the stiff side)", cells_along=n, ratio=ratio)


def cantilever(ctx: Context, body: str) -> Outcome:
    """FEM cantilever with a tip load against P L^3 / (3 E I) + P L / (kappa G A)."""
    probes = _probes(body)
    if probes.cantilever_tip is None:
        return not_applicable("the body publishes no cantilever (BodyProbes.cantilever_tip)", None,
                              "P L^3 / (3 E I) + P L / (kappa G A)")
    cells = (40, 8, 1) if ctx.quick else (60, 12, 1)
    ratio = R.cantilever_ratio(cells, solve=probes.cantilever_tip)
    return relative(ratio, 1.0, CANTILEVER_REL_TOL, "x beam theory",
                    detail=f"cells {cells}; linear tets lock in bending and converge from the stiff side",
                    cells=str(cells))


def rigid_rotation(ctx: Context, body: str) -> Outcome:
    """Elastic force of a rotated (and translated) rest shape: zero for a fixed-corotational mesh and for
    the lattice's springs (the body's ``BodyProbes.rigid_motion_residual``)."""
    probes = _probes(body)
    if probes.rigid_motion_residual is None:
        return not_applicable(probes.rigid_motion_not_applicable, 0.0, f"< {RIGID_REL_TOL:g}")
    rng = np.random.default_rng(11)
    angles = (1e-3, 0.4, 2.0, np.pi - 1e-6)  # small ones by Newton, large by the SVD fallback (FEM)

    def draw(angle):  # a random axis, then a random translation [m], in this order (rng's sequence)
        rot = R.rotation(rng.normal(size=3), angle)
        return rot, rng.normal(size=3)

    def build():
        from ..core.config import resolve_case
        from ..harness.runner import build_body
        return build_body(resolve_case("worm", body, "flat", overrides=["creature.segments=4"]))

    worst = probes.rigid_motion_residual(build, angles, draw)
    return at_most(worst, RIGID_REL_TOL, "", reference=0.0,
                   detail=f"max |f| relative to {probes.rigid_motion_scale} over 4 rotations")


# --------------------------------------------------------------------------- dynamics

def free_fall_momentum(ctx: Context, body: str) -> Outcome:
    """A tumbling, vibrating body in free flight (no ground): P(t) = P0 + M g t at every sample."""
    from ..core.config import resolve_case
    from ..harness.runner import Creature

    duration = 0.3 if ctx.quick else 1.0
    case = resolve_case("worm", body, "drop", duration=duration, overrides=[
        "scenario.terrain=none", "scenario.passive=true", "scenario.perturbation_m=0.005", "creature.segments=6"])
    probes = _probes(body)
    if probes.linear_momentum is None:
        return not_applicable("the body publishes no momentum probe (BodyProbes.linear_momentum)", None,
                              "P0 + M g t")
    cr = Creature(case)
    cr.compile()
    b = cr.body
    probes.add_velocity(b, np.array([0.3, 1.0, -0.2]))  # a moving start: P0 != 0
    M, g = probes.total_mass(b), np.array([0.0, -case.scenario.gravity_m_s2, 0.0])
    P0 = probes.linear_momentum(b)
    worst, done, chunk = 0.0, 0, max(1, int(round(0.01 / case.dt)))
    while done < case.steps:
        k, code = cr.advance(done * case.dt, min(chunk, case.steps - done))
        if code != 0:
            return Outcome("FAIL", None, "P0 + M g t", f"< {MOMENTUM_REL_TOL:g} relative", b.status_text(code))
        done += k
        t = done * case.dt
        err = np.linalg.norm(probes.linear_momentum(b) - (P0 + M * g * t)) / (np.linalg.norm(P0) + M * np.linalg.norm(g) * t)
        worst = max(worst, err)
    return at_most(worst, MOMENTUM_REL_TOL, reference="P0 + M g t",
                   detail=f"max relative error over {done} steps ({duration:g} s, 6 segments, no ground)")


def stable_dt(ctx: Context, body: str) -> Outcome:
    """``stable-dt`` on an undamped 3-segment worm of a body that publishes its highest eigenfrequency
    (``BodyProbes.omega_max``; the lattice) against symplectic Euler's limit 2 / omega_max."""
    from ..core.config import resolve_case
    from ..harness.runner import build_body, run_world
    from ..harness.stable_dt import find_stable_dt

    probes = _probes(body)
    if probes.omega_max is None:
        return not_applicable("the body publishes no highest eigenfrequency (BodyProbes.omega_max)", None,
                              "2 / omega_max")
    case = resolve_case("worm", body, "drop", duration=1.0 if ctx.quick else 2.0, overrides=[
        "creature.segments=3", "scenario.passive=true", "scenario.gravity_m_s2=0", "scenario.start_height_m=1",
        *probes.undamped, "scenario.perturbation_m=1e-6"])
    world = run_world(case)  # one world for the body measured here and every trial run
    expected = R.symplectic_euler_dt_limit(probes.omega_max(build_body(case, world)))
    res = find_stable_dt(case, rel_tol=0.02, world=world)
    return relative(res.stable_dt_max_s, expected, STABLE_DT_REL_TOL, "s",
                    detail=f"bracket [{res.stable_dt_max_s:.4g}, {res.unstable_dt_min_s:.4g}] s",
                    unstable_dt_min_s=res.unstable_dt_min_s)


def damping_pure_mode(ctx: Context, body: str) -> Outcome:
    """v' = (M + h D)^-1 M v: a generalized eigenvector D phi = lam M phi decays by 1 / (1 + lam h) per step
    (the body's ``BodyProbes.pure_damping_modes``)."""
    probes = _probes(body)
    if probes.pure_damping_modes is None:
        return not_applicable("the body publishes no damping modes (BodyProbes.pure_damping_modes)", None,
                              "1 / (1 + lambda h)")
    h = 1e-3
    modes = probes.pure_damping_modes(300.0, h)
    worst = max(float(np.max(np.abs(factor / R.backward_euler_damping_factor(lam, h) - 1.0)))
                for lam, factor in modes)
    ref = R.backward_euler_damping_factor(modes[-1][0], h)
    return at_most(worst, DAMPING_EXACT_TOL, reference=ref,
                   detail=f"max relative error of the per-step factor over 3 modes (stiffest: {ref:.6f} per step)")


def damping_oscillating_mode(ctx: Context, body: str) -> Outcome:
    """One free node on a tet: every underdamped mode of the App. A step decays by 1 / sqrt(1 + c h) per step,
    c = 3 gamma / rho, from the eigenvalues of the linearized one-step map."""
    probes = _probes(body)
    if probes.one_node_step_eigenvalues is None:
        return not_applicable("the body publishes no one-node step map (BodyProbes.one_node_step_eigenvalues)",
                              None, "1 / sqrt(1 + c h)")
    rho, gamma, h = 1.0, 40.0, 1e-3
    ev = probes.one_node_step_eigenvalues(rho, gamma, h)
    expected = R.semi_implicit_oscillator_factor(3.0 * gamma / rho, h)
    oscillating = bool(np.all(np.abs(ev.imag) > 0))
    err = float(np.max(np.abs(np.abs(ev) / expected - 1.0)))
    if not oscillating:
        return holds(False, float(np.abs(ev).max()), expected, "all modes underdamped", "a mode is overdamped")
    return at_most(err, DAMPING_OSC_TOL, reference=expected,
                   detail=f"max relative error of |eigenvalue| over 6 eigenvalues; expected {expected:.8f} per step "
                          f"(c = 3 gamma / rho = {3 * gamma / rho:g} 1/s, h = {h:g} s)")
