"""Kinematic reference model of slithering (Hu, Nirody, Scott and Shelley 2009, PNAS 106:10081).

A snake is an inextensible curve whose shape is prescribed by a travelling curvature wave

    kappa(s, t) * L = A sin(2 pi (s / lambda - t / T)),

s the arc length from the head (0) to the tail (1) in body lengths, lambda the wavelength in
body lengths, T the gait period.  The wave travels from head to tail.  The ground acts on every
point with Hu et al.'s anisotropic Coulomb friction per unit length (uniform weight rho g):

    f = -rho g [ mu_t (u_hat . n) n + mu_{f|b} (u_hat . a) a ],

u_hat the unit sliding velocity of the point, a the unit tangent toward the head, n the
normal; mu_f applies when the point slides forward (u_hat . a > 0), mu_b backward.  The shape is
given; the unknowns are the rigid-body velocity of the body frame (translation V and rotation
rate Omega), fixed by the balance of friction forces and torque.

Two limits of Hu et al.'s equations (Froude number Fr = L / (T^2 g mu_f), inertia / friction):

* ``method="quasistatic"`` (default; Fr -> 0, what Hu et al. solve and what a body at Fr = 0.1
  is close to): no inertia, so force and torque vanish at every instant.  The balance is solved
  at ``n_time`` phases of a period and the rigid motion integrated over the period on SE(2); the
  result is the net displacement and rotation per cycle.
* ``method="averaged"`` (Fr -> infinity): inertia holds the rigid velocity constant over a
  cycle, so only the period-averaged force and torque vanish; one balance for (V, Omega).
* ``method="dynamic"``: Hu et al.'s equations with inertia at Froude number ``froude``: the
  centre of mass accelerates by the net friction force (dV/dt = F / (m Fr) in body lengths and
  periods) and the angular momentum about it, I(t) Omega + h(t) with h the shape's own, changes
  by the friction torque; explicit steps, ``dynamic_cycles`` cycles from rest, the last
  ``dynamic_measure_cycles`` measured.  It checks the other two: at Fr = 0.01 it matches the
  quasistatic speed (0.2568 vs 0.2567 BL/cycle at A = 7, lambda = 1, mu_t / mu_f = 3), at
  Fr = 0.1 it is 0.9 % faster.

A body of width w (``width_bl`` > 0, in body lengths) rests on the two edges of its belly, lines at
+-w/2 along the normal, each with half the weight, as a flat-bottomed body on a flat ground does
(the lattice's and the hybrid's bottom corners sit there).  The cross-sections turn with the
tangent, so the edge at +h n moves relative to the centre line by h dn/dt = -h (dtheta/dt) a: the
two edges slide along the body in opposite directions at +-h dtheta/dt.  Coulomb friction depends
on the direction of slip only, so where a section turns faster than it slides along the body the
edges' pulls along the body cancel (sliding along the body is nearly free), while a sideways slip
tilts both edges' slip the same way and is resisted: the turning sections add to the belly's
anisotropy, which the zero-width line of Hu et al. lacks (the effect is there with mu_b = mu_f too).
At A = 7, lambda = 1, mu_b = 1.5 mu_f and w = 0.05 BL it adds 0.014 BL/cycle at mu_t = mu_f and
0.018 (+19 %) at mu_t = 1.5 mu_f, and little at large ratios (+2.7 % at 3, +0.5 % at 10), where the
sideways grip already dominates (issue 11).

Coulomb friction does not depend on the sliding speed, so the model is rate independent: speeds
come out in body lengths per cycle and do not depend on T, g or the size of the coefficients,
only on A, lambda and the ratios mu_b / mu_f and mu_t / mu_f.

Units: lengths in body lengths (BL), time in gait periods, angles in radians.
Frame: x along the mean body axis toward the head (the mean over the cycle of the unit vector
from tail to head, as ``metrics.locomotion`` takes it), y to the body's left (seen from above);
``lateral_speed_bl_per_cycle`` is positive to the body's right (as ``metrics.locomotion``'s
``lateral_speed_m_per_s``), ``angular_velocity_rad_per_cycle`` positive for a turn to the left
(counter-clockwise seen from above).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import root
from scipy.special import j0


@dataclass(frozen=True)
class SlitheringResult:
    """Steady slithering of the kinematic model (all per gait period T, lengths in body lengths).

    speed_bl_per_cycle: displacement of the centre of mass along the mean body axis per cycle (the
        mean over the cycle of the unit tail-to-head vector, as metrics.locomotion measures it).
    lateral_speed_bl_per_cycle: displacement to the body's right per cycle.
    angular_velocity_rad_per_cycle: rotation of the body frame per cycle (+ = to the left).
    travel_angle_deg: atan2(lateral, forward), as metrics.locomotion's travel_angle_deg.
    no_slip_speed_bl_per_cycle: the speed when no point slides sideways (mu_t / mu_f -> inf):
        the body glides along its own serpenoid at the wave speed lambda, so the centre advances
        lambda * J0(A lambda / 2 pi) per cycle (the mean cosine of the tangent angle along a wave).
    slip: 1 - speed / no_slip_speed (0: every point follows the path of the ones ahead).
    wave_speed_bl_per_cycle: lambda, the speed of the curvature wave along the body.
    max_force_residual: largest |force| or |torque| balance residual over the solves, relative to
        the total weight times the largest friction coefficient (NaN for the dynamic method).
    method: "quasistatic", "averaged" or "dynamic".
    """

    speed_bl_per_cycle: float
    lateral_speed_bl_per_cycle: float
    angular_velocity_rad_per_cycle: float
    travel_angle_deg: float
    no_slip_speed_bl_per_cycle: float
    slip: float
    wave_speed_bl_per_cycle: float
    max_force_residual: float
    method: str


def _dynamic(curvature_amplitude: float, wavelength_bl: float, mus: tuple, froude: float, n_points: int,
             steps: int, cycles: int, measure: int, delta: float,
             width_bl: float = 0.0) -> tuple[np.ndarray, float, list]:
    """Integrate the rigid motion with inertia from rest: (displacement over the last ``measure``
    cycles in world axes [BL], rotation over them [rad], [(heading psi, shape X) per step measured])."""
    mu_f = mus[0]
    rel = tuple(m / mu_f for m in mus)  # accelerations in units of g mu_f: 1 / Fr per unit force
    P = np.zeros(2)
    V = np.zeros(2)
    psi = H = 0.0
    h = 1.0 / steps
    start = (cycles - measure) * steps
    P0, psi0, frames = None, 0.0, []
    for k in range(cycles * steps):
        if k == start:
            P0, psi0 = P.copy(), psi
        X, W, a, w = body_shape(curvature_amplitude, wavelength_bl, ((k + 0.5) * h) % 1.0, n_points, width_bl)
        inertia = w @ (X * X).sum(axis=1)
        own = w @ (X[:, 0] * W[:, 1] - X[:, 1] * W[:, 0])
        om = (H - own) / inertia
        c, s_ = math.cos(psi), math.sin(psi)
        Vb = np.array([c * V[0] + s_ * V[1], -s_ * V[0] + c * V[1]])
        f = friction_density(Vb[None, :] + om * np.column_stack([-X[:, 1], X[:, 0]]) + W, a, *rel, delta)
        F = w @ f
        V = V + (h / froude) * np.array([c * F[0] - s_ * F[1], s_ * F[0] + c * F[1]])
        H += (h / froude) * (w @ (X[:, 0] * f[:, 1] - X[:, 1] * f[:, 0]))
        P = P + h * V
        if k >= start:
            frames.append((psi + 0.5 * h * om, X))
        psi += h * om
    return P - P0, psi - psi0, frames


def body_shape(curvature_amplitude: float, wavelength_bl: float, phase_cycles: float,
               n_points: int, width_bl: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Shape and shape velocity in the body frame at phase t/T.

    Returns (X (m, 2) [BL], W (m, 2) [BL per cycle]: velocity of each point relative to the body
    frame, a (m, 2): unit tangent toward the head, w (m,): quadrature weights summing to 1), with
    m = n_points on the centre line (width_bl = 0), else m = 2 n_points: the belly's left edge
    (X + (w/2) n, head to tail) then its right edge (X - (w/2) n), each with half the weight and
    the shape velocity of its place on the turning cross-section (module doc).
    The body frame has its origin at the centre of mass and its x axis along the mean tangent
    angle, so W carries no net translation or rotation of the mean axis.
    """
    s = np.linspace(0.0, 1.0, n_points)
    w = np.full(n_points, 1.0 / (n_points - 1))
    w[0] = w[-1] = 0.5 / (n_points - 1)
    k = 2.0 * math.pi / wavelength_bl
    phi = 2.0 * math.pi * phase_cycles
    c = curvature_amplitude / k
    # tangent angle theta(s) = int_0^s kappa; its phase derivative (per cycle) in closed form
    theta = c * (math.cos(phi) - np.cos(k * s - phi))
    theta_t = 2.0 * math.pi * c * (-math.sin(phi) - np.sin(k * s - phi))
    theta -= w @ theta
    theta_t -= w @ theta_t
    a = np.column_stack([np.cos(theta), np.sin(theta)])
    da = np.column_stack([-np.sin(theta), np.cos(theta)]) * theta_t[:, None]
    # X' = -a (arc length runs from head to tail); trapezoid cumulative integral
    X = -_cumtrapz(a, s)
    W = -_cumtrapz(da, s)
    X -= w @ X
    W -= w @ W
    if width_bl <= 0.0:
        return X, W, a, w
    h = 0.5 * width_bl
    n = np.column_stack([-a[:, 1], a[:, 0]])
    dW = h * theta_t[:, None] * a  # h dn/dt = -h theta_t a at the left edge, +h theta_t a at the right
    return (np.vstack([X + h * n, X - h * n]), np.vstack([W - dW, W + dW]), np.vstack([a, a]),
            np.concatenate([w, w]) * 0.5)


def _head_to_tail(X: np.ndarray, n_points: int) -> np.ndarray:
    """Centre-line vector from the tail to the head of a ``body_shape`` X (either layout)."""
    if len(X) == n_points:
        return X[0] - X[-1]
    return 0.5 * (X[0] + X[n_points]) - 0.5 * (X[n_points - 1] + X[-1])


def _cumtrapz(y: np.ndarray, s: np.ndarray) -> np.ndarray:
    out = np.zeros_like(y)
    out[1:] = np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(s)[:, None], axis=0)
    return out


def friction_density(u: np.ndarray, a: np.ndarray, mu_f: float, mu_b: float, mu_t: float,
                     delta: float) -> np.ndarray:
    """Friction force per unit weight (n, 2) on points sliding at u (n, 2) with head tangents a.

    delta: velocity regularisation [BL per cycle]: u_hat = u / sqrt(|u|^2 + delta^2), so the
    force is continuous through u = 0 (Coulomb's law is set valued there)."""
    norm = np.sqrt(np.einsum("ij,ij->i", u, u) + delta * delta)
    n = np.column_stack([-a[:, 1], a[:, 0]])
    ua = np.einsum("ij,ij->i", u, a) / norm
    un = np.einsum("ij,ij->i", u, n) / norm
    mu_a = np.where(ua > 0.0, mu_f, mu_b)
    return -(mu_t * un)[:, None] * n - (mu_a * ua)[:, None] * a


def _balance(x, X, W, a, w, mus, delta):
    V, om = x[:2], x[2]
    u = V[None, :] + om * np.column_stack([-X[:, 1], X[:, 0]]) + W
    f = friction_density(u, a, *mus, delta)
    F = w @ f
    tq = w @ (X[:, 0] * f[:, 1] - X[:, 1] * f[:, 0])
    return np.array([F[0], F[1], tq])


def _solve(fun, x0: np.ndarray) -> tuple[np.ndarray, float]:
    best = None
    for method in ("hybr", "lm"):
        sol = root(fun, x0, method=method, tol=1e-12)
        res = float(np.max(np.abs(fun(sol.x))))
        if best is None or res < best[1]:
            best = (sol.x, res)
        if res < 1e-9:
            break
    return best


def steady_slithering(curvature_amplitude: float, wavelength_bl: float, mu_f: float, mu_b: float,
                      mu_t: float, n_points: int = 200, n_time: int = 96,
                      method: str = "quasistatic", velocity_regularization: float = 1e-6,
                      froude: float = 0.1, dynamic_steps_per_cycle: int = 4000, dynamic_cycles: int = 6,
                      dynamic_measure_cycles: int = 3, width_bl: float = 0.0) -> SlitheringResult:
    """Steady slithering of a prescribed curvature wave on anisotropic Coulomb friction.

    curvature_amplitude: A = peak curvature x body length (dimensionless).
    wavelength_bl: wavelength of the curvature wave in body lengths.
    mu_f, mu_b, mu_t: forward, backward, transverse kinetic friction coefficients (> 0).
    n_points: quadrature points along the body; n_time: phases per period (quasistatic).
    method: "quasistatic" (Fr -> 0, Hu et al.), "averaged" (Fr -> inf) or "dynamic" (inertia at
        Froude number ``froude``, a few seconds); see the module doc.
    velocity_regularization: delta of ``friction_density`` relative to the wave speed lambda
        (the dynamic method uses at least 1e-4: explicit steps chatter at the stick points).
    froude, dynamic_*: the dynamic method's Froude number, steps per cycle, cycles run from
        rest and cycles measured at the end (per cycle figures are their mean).
    width_bl: the belly's width in body lengths (0: Hu et al.'s line; > 0: two contact lines at
        the edges, module doc).
    Raises ValueError on a non-positive coefficient, wavelength or resolution, or a negative width.
    """
    if min(mu_f, mu_b, mu_t) <= 0.0:
        raise ValueError(f"friction coefficients must be > 0, got mu_f={mu_f}, mu_b={mu_b}, mu_t={mu_t}")
    if wavelength_bl <= 0.0 or curvature_amplitude < 0.0:
        raise ValueError(f"need wavelength_bl > 0 and curvature_amplitude >= 0, got {wavelength_bl}, "
                         f"{curvature_amplitude}")
    if not 0.0 <= width_bl < 0.5:
        raise ValueError(f"need 0 <= width_bl < 0.5 (body lengths), got {width_bl}")
    if n_points < 8 or n_time < 4:
        raise ValueError(f"need n_points >= 8 and n_time >= 4, got {n_points}, {n_time}")
    if method not in ("quasistatic", "averaged", "dynamic"):
        raise ValueError(f"method must be 'quasistatic', 'averaged' or 'dynamic', got {method!r}")
    if method == "dynamic" and (froude <= 0.0 or dynamic_steps_per_cycle < 100
                                or not 1 <= dynamic_measure_cycles <= dynamic_cycles):
        raise ValueError(f"dynamic method: need froude > 0, dynamic_steps_per_cycle >= 100 and "
                         f"1 <= dynamic_measure_cycles <= dynamic_cycles, got {froude}, "
                         f"{dynamic_steps_per_cycle}, {dynamic_measure_cycles}, {dynamic_cycles}")
    mus = (mu_f, mu_b, mu_t)
    delta = velocity_regularization * wavelength_bl
    scale = max(mus)
    phases = (np.arange(n_time) + 0.5) / n_time
    shapes = [body_shape(curvature_amplitude, wavelength_bl, p, n_points, width_bl) for p in phases]

    if method == "dynamic":
        d, turn, frames = _dynamic(curvature_amplitude, wavelength_bl, mus, froude, n_points,
                                   dynamic_steps_per_cycle, dynamic_cycles, dynamic_measure_cycles,
                                   max(delta, 1e-4 * wavelength_bl), width_bl)
        disp, turn = d / dynamic_measure_cycles, turn / dynamic_measure_cycles
        psis = np.array([p for p, _ in frames])
        shapes = [(X, None, None, None) for _, X in frames]
        max_res = float("nan")  # not a balance: inertia carries the rest
    elif method == "averaged":
        # one constant rigid velocity in a frame that does not turn with the body's mean axis
        def fun(x):
            return np.mean([_balance(x, *sh, mus, delta) for sh in shapes], axis=0)
        x, res = _solve(fun, np.zeros(3))
        V, om = x[:2], x[2]
        disp, turn = V, om
        # a constant twist over one cycle: exact SE(2) exponential
        if abs(turn) > 1e-12:
            sx, cx = math.sin(turn) / turn, (1.0 - math.cos(turn)) / turn
            disp = np.array([sx * V[0] - cx * V[1], cx * V[0] + sx * V[1]])
        max_res = res / scale
        psis = turn * phases
    else:
        pos = np.zeros(2)
        psi = 0.0
        x = np.zeros(3)
        max_res = 0.0
        h = 1.0 / n_time
        psis = np.zeros(n_time)
        for i, sh in enumerate(shapes):
            x, res = _solve(lambda y: _balance(y, *sh, mus, delta), x)
            max_res = max(max_res, res / scale)
            V, om = x[:2], x[2]
            # exact exponential of the (constant over the sub-interval) body twist, then to world
            th = om * h
            if abs(th) > 1e-12:
                sx, cx = math.sin(th) / th, (1.0 - math.cos(th)) / th
            else:
                sx, cx = 1.0, 0.5 * th
            d = h * np.array([sx * V[0] - cx * V[1], cx * V[0] + sx * V[1]])
            c, s_ = math.cos(psi), math.sin(psi)
            pos += np.array([c * d[0] - s_ * d[1], s_ * d[0] + c * d[1]])
            psis[i] = psi + 0.5 * th
            psi += th
        disp, turn = pos, psi
    # forward and lateral along the mean body axis over the cycle, as metrics.locomotion measures
    # them: the mean of the unit tail-to-head vectors (the head-tail line swings within a cycle)
    axes = []
    for (X, _, _, _), p in zip(shapes, psis):
        ht = _head_to_tail(X, n_points)
        ht = ht / np.linalg.norm(ht)
        c, s_ = math.cos(p), math.sin(p)
        axes.append([c * ht[0] - s_ * ht[1], s_ * ht[0] + c * ht[1]])
    ax = np.mean(axes, axis=0)
    ax = ax / np.linalg.norm(ax)
    disp = np.array([disp @ ax, ax[0] * disp[1] - ax[1] * disp[0]])
    forward, lateral = float(disp[0]), float(-disp[1])
    no_slip = wavelength_bl * float(j0(curvature_amplitude * wavelength_bl / (2.0 * math.pi)))
    return SlitheringResult(
        speed_bl_per_cycle=forward,
        lateral_speed_bl_per_cycle=lateral,
        angular_velocity_rad_per_cycle=float(turn),
        travel_angle_deg=math.degrees(math.atan2(lateral, forward)) if math.hypot(forward, lateral) > 0 else 0.0,
        no_slip_speed_bl_per_cycle=no_slip,
        slip=1.0 - forward / no_slip if no_slip > 0 else float("nan"),
        wave_speed_bl_per_cycle=float(wavelength_bl),
        max_force_residual=float(max_res),
        method=method,
    )


def recorded_shape_speed(points: np.ndarray, t: np.ndarray, period_s: float, body_length_m: float,
                         mu_f: float, mu_b: float, mu_t: float, width_bl: float = 0.0,
                         velocity_regularization: float = 1e-6) -> tuple[float, float]:
    """The kinematic model fed a RECORDED body: its speed from the recorded shape, against the recorded speed.

    points: (T, n, 2) [m] the body's centre line on the ground, head first, x and y with y to the body's left
    (from above); t: (T,) [s], evenly or unevenly spaced, at least 3 samples; period_s: the gait period [s].
    At every interior sample the points' velocities are central differences; the rigid part (translation and
    rotation about the centre of the points, weighted by length) is fitted and removed, what is left is the
    shape's own motion, and the model's force and torque balance (``friction_density``, uniform weight along
    the length: each point carries half of each adjacent chord) gives the rigid velocity that this shape
    would move with on Hu et al.'s anisotropic Coulomb friction (quasi-static, as ``steady_slithering``).
    width_bl > 0: the belly's two edges, as ``body_shape``.

    Returns (recorded, predicted) [BL per cycle]: the mean velocity of the centre of the points along the mean
    head axis over the samples, recorded and predicted.  Equal when the simulation's friction and weight act
    as the model's on the shape the body really took; so a body slower than ``steady_slithering`` at the
    commanded shape, but as fast as predicted here, is slow because of its shape, not its friction.
    """
    P = np.asarray(points, dtype=np.float64) / body_length_m
    t = np.asarray(t, dtype=np.float64)
    if P.ndim != 3 or P.shape[2] != 2 or P.shape[0] != t.shape[0] or P.shape[0] < 3 or P.shape[1] < 3:
        raise ValueError(f"need points (T >= 3, n >= 3, 2) and t (T,), got {P.shape} and {t.shape}")
    mus = (mu_f, mu_b, mu_t)
    delta = velocity_regularization
    h = 0.5 * width_bl

    def tangents(X):
        a = np.empty_like(X)
        a[1:-1] = X[:-2] - X[2:]
        a[0], a[-1] = X[0] - X[1], X[-2] - X[-1]
        return a / np.linalg.norm(a, axis=1)[:, None]

    rec, pred, axes = [], [], []
    for k in range(1, len(t) - 1):
        X = P[k]
        dt_cycles = (t[k + 1] - t[k - 1]) / period_s
        U = (P[k + 1] - P[k - 1]) / dt_cycles
        ln = np.linalg.norm(np.diff(X, axis=0), axis=1)
        w = np.zeros(len(X))
        w[:-1] += 0.5 * ln
        w[1:] += 0.5 * ln
        w /= w.sum()
        a = tangents(X)
        Xc = X - w @ X
        V = w @ U
        om = (w @ (Xc[:, 0] * (U[:, 1] - V[1]) - Xc[:, 1] * (U[:, 0] - V[0]))) / (w @ (Xc * Xc).sum(axis=1))
        W = U - V - om * np.column_stack([-Xc[:, 1], Xc[:, 0]])
        if h > 0.0:
            a0, a1 = tangents(P[k - 1]), tangents(P[k + 1])
            theta_t = np.arctan2(a0[:, 0] * a1[:, 1] - a0[:, 1] * a1[:, 0], (a0 * a1).sum(axis=1)) / dt_cycles
            n = np.column_stack([-a[:, 1], a[:, 0]])
            dW = h * theta_t[:, None] * a
            Xc, W = np.vstack([Xc + h * n, Xc - h * n]), np.vstack([W - dW, W + dW])
            a, w = np.vstack([a, a]), 0.5 * np.concatenate([w, w])
        x, _ = _solve(lambda y: _balance(y, Xc, W, a, w, mus, delta), np.array([V[0], V[1], om]))
        ax = X[0] - X[-1]
        axes.append(ax / np.linalg.norm(ax))
        rec.append(V)
        pred.append(x[:2])
    ax = np.mean(axes, axis=0)
    ax /= np.linalg.norm(ax)
    return float(np.mean(np.array(rec) @ ax)), float(np.mean(np.array(pred) @ ax))
