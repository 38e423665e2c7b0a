"""Animations of a run: the body from above (x-z) and from the side (x-y), one frame per recorded sample.

``bench-myriapoda run ... --animate FILE.gif|FILE.mp4`` records ``body.scene()``
(``bodies.scene.Scene``) at the observation samples through the runner's
``on_sample`` hook (``FrameRecorder``) and draws them with ``write_animation``:

* left panel, seen from above: x to the right, z (the creature's right) down
  the page, as ``report/trajectories.py`` draws top views;
* right panel, seen from the creature's right side: x to the right, y up
  (the viewer sits at +z);
* triangle surfaces (rigid boxes, FEM boundaries, lattice faces) filled and
  flat-shaded, back faces culled, painter-sorted by depth; springs as thin
  lines over them; legs as polylines root -> knee -> tip in the colour of their
  Switcher state (``metrics.gait.STATE_COLORS``, the gait diagram's colours, as
  the paper's Figs. 5 and 13 colour legs by state), with a legend;
* the terrain: its surface profile in the side view (from
  ``terrain_kernels.terrain_phi_numpy``) and a ground patch with a grid in the
  top view (the slab of Miller's book drawn darker).

Axis limits are fixed from all frames, so the camera never jumps, with equal
aspect.  At most ``MAX_FRAMES`` frames, played in real time when that needs
no more than ``MAX_FPS`` frames per second (``frame_stride``).
"""
from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Circle, Polygon, Rectangle  # noqa: E402

from ..bodies.scene import Scene  # noqa: E402
from .scene_style import (  # noqa: E402,F401  (re-exported: the tests and callers name them here)
    ANTENNA_COLOR, ANTENNA_CONTACT_COLOR, DEFAULT_COLOR, DEFAULT_STYLE, GROUND_COLOR, GROUND_EDGE, SLAB_COLOR,
    add_leg_state_legend, surface_height, surface_styles,
)
from ..metrics.gait import STATE_COLORS, STATE_NAMES  # noqa: E402
from .terrain_drawing import draw_terrain_shape  # noqa: E402
from ..world.terrain_kernels import (  # noqa: E402
    H_NOBST, OBST_CYLINDER, SLAB, obstacle_records, terrain_phi_numpy,
)

MAX_FRAMES = 150  # frames of an animation at most: a GIF stays a few MB and writes in seconds
MAX_FPS = 30.0    # playback rate cap [frames/s]
GIF_TICK_S = 0.01  # a GIF frame's duration is a whole number of centiseconds
TICK_TOL_S = 1e-6  # a frame interval this close to whole ticks counts as whole (the samples' float times)
MIN_GIF_TICKS = 2  # browsers play GIF frames shorter than 2 cs as 10 cs
SUFFIXES = (".gif", ".mp4")

EDGE_RGBA = (0.0, 0.0, 0.0, 0.35)
OBSTACLE_COLOR = "#6e6e6e"
# directions toward the viewer: the top view looks down -y, the side view looks down -z
VIEWS = {"top": (np.array([0.0, 1.0, 0.0]), (0, 2)), "side": (np.array([0.0, 0.0, 1.0]), (0, 1))}


# --------------------------------------------------------------------------- which samples become frames

def sample_period(case) -> float:
    """Time between two observation samples of ``harness.runner.run_case`` [s].

    The runner steps in chunks of round(1 / (sample_hz dt)) steps (at least 1)
    and samples after each; this mirrors that rule.
    """
    chunk = max(1, int(round(1.0 / (case.record.sample_hz * case.dt))))
    return chunk * case.dt


def expected_samples(case) -> int:
    """Number of samples a run of ``case`` records when it completes (t = 0 and after every chunk)."""
    chunk = max(1, int(round(1.0 / (case.record.sample_hz * case.dt))))
    return 1 + math.ceil(case.steps / chunk)


def frame_stride(n_samples: int, period_s: float, max_frames: int = MAX_FRAMES, max_fps: float = MAX_FPS,
                 tick_s: float | None = None) -> int:
    """Keep every k-th sample: at most ``max_frames`` frames, and frames at least 1 / max_fps apart in
    simulated time, so that playing at 1 / (k period) frames/s is real time within the fps cap.

    tick_s: the player's clock tick [s] (``GIF_TICK_S`` for a GIF, whose frame durations are whole
    centiseconds).  Given, k is the smallest stride from that minimum up to twice it whose frame
    interval k period_s is a whole number of ticks (to ``TICK_TOL_S``), so every frame is shown for
    exactly the simulated time it stands for (60 Hz samples: k = 3, 50 ms = 5 cs, rather than k = 2,
    33.3 ms, which a GIF can only show as 30 or 40 ms).  When no such k exists (a sample period such as
    16.8 ms), the minimum is kept and ``gif_durations_cs`` spreads the rounding over the frames.
    """
    k_frames = math.ceil(n_samples / max_frames)
    k_fps = math.ceil(1.0 / (max_fps * period_s) - 1e-9)  # tolerance: 60 Hz samples give exactly 2
    k_min = max(1, k_frames, k_fps)
    if tick_s is not None:
        for k in range(k_min, 2 * k_min + 1):
            ticks = k * period_s / tick_s
            if abs(ticks - round(ticks)) * tick_s <= TICK_TOL_S and round(ticks) >= MIN_GIF_TICKS:
                return k
    return k_min


def gif_durations_cs(times: Sequence[float], fps: float | None = None) -> list[int]:
    """Display time of each GIF frame [cs] so that playback follows the simulated ``times`` [s].

    A GIF stores frame durations in whole centiseconds.  Frame i is shown from tick round(100 (t_i - t_0))
    to the next frame's tick, so the rounding never accumulates: the animation's total length is the
    simulated time to within 5 ms, and frame intervals that are whole centiseconds are kept exactly.
    The last frame is shown for the median interval.  fps: a fixed playback rate instead (each frame
    1 / fps, rounded to centiseconds the same way).  Every duration is at least ``MIN_GIF_TICKS`` (browsers
    show shorter GIF frames for 100 ms).
    """
    n = len(times)
    if fps is not None:
        t = np.arange(n + 1) / float(fps)
    else:
        t = np.asarray(times, dtype=float) - float(times[0])
        step = float(np.median(np.diff(t))) if n > 1 else 1.0 / MAX_FPS
        t = np.append(t, t[-1] + step)
    ticks = np.round(t / GIF_TICK_S).astype(np.int64)
    return [max(MIN_GIF_TICKS, int(d)) for d in np.diff(ticks)]


class FrameRecorder:
    """The runner's ``on_sample`` hook: stores ``body.scene()`` and t of every ``stride``-th sample.

    frames: list of ``Scene``; times: list of t [s], in sample order.
    """

    def __init__(self, stride: int = 1):
        if stride < 1:
            raise ValueError(f"stride must be >= 1, got {stride}")
        self.stride = int(stride)
        self.frames: list[Scene] = []
        self.times: list[float] = []
        self.water_frames: list[np.ndarray] = []  # (nx, nz) float32 surface minus rest level [m], with water
        self.water_region: tuple[float, float, float, float] | None = None  # x_min, x_max, z_min, z_max [m]
        self._n = 0

    def __call__(self, t: float, body, water=None) -> None:
        if self._n % self.stride == 0:
            self.frames.append(body.scene())
            self.times.append(float(t))
            if water is not None:
                self.water_frames.append(water.surface())
                w = water.water
                nx, nz = w.shape
                self.water_region = (w.x0, w.x0 + nx * w.dx, w.z0, w.z0 + nz * w.dx)
        self._n += 1

    def water(self):
        """(surface frames, region) for ``write_animation``, or None without water."""
        return (self.water_frames, self.water_region) if self.water_frames else None


def playback_fps(times: Sequence[float], max_fps: float = MAX_FPS) -> float:
    """Frames per second that play ``times`` [s] in real time, capped at ``max_fps``."""
    if len(times) < 2:
        return max_fps
    step = float(np.median(np.diff(np.asarray(times, dtype=float))))
    return min(max_fps, 1.0 / step) if step > 0 else max_fps


# --------------------------------------------------------------------------- geometry per view

def _project_triangles(scene: Scene, view: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The scene's visible triangles in one view: polygons (N, 3, 2) [m] painter-sorted, face and edge
    colours (N, 4) RGBA."""
    toward, (a, b) = VIEWS[view]
    depth_axis = 1 if view == "top" else 2
    polys, depth, colors, edges = [], [], [], []
    styles = surface_styles()
    for verts, faces, kind in scene.triangles:
        if not len(faces):
            continue
        p = verts[faces]                                       # (F, 3, 3)
        n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        norm = np.linalg.norm(n, axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            cos = (n @ toward) / norm
        keep = np.isfinite(cos) & (cos > 1e-9) & np.all(np.isfinite(p), axis=(1, 2))  # back faces culled
        if not keep.any():
            continue
        p, cos = p[keep], cos[keep]
        polys.append(p[:, :, [a, b]])
        depth.append(p[:, :, depth_axis].mean(axis=1))
        shade = 0.45 + 0.55 * cos                               # flat shading, light from the viewer
        style = styles.get(kind, DEFAULT_STYLE)
        rgb = np.asarray(to_rgb(style.color))
        face = np.column_stack([shade[:, None] * rgb, np.ones(len(p))])
        colors.append(face)
        # a box face is two triangles: outlined in their own colour, the diagonal does not show; a mesh's
        # triangles keep a dark edge, which shows the mesh (``SurfaceStyle.edges_in_face_color``)
        edges.append(face if style.edges_in_face_color else np.tile(EDGE_RGBA, (len(p), 1)))
    if not polys:
        return np.zeros((0, 3, 2)), np.zeros((0, 4)), np.zeros((0, 4))
    order = np.argsort(np.concatenate(depth), kind="stable")   # far first, near last
    return np.concatenate(polys)[order], np.concatenate(colors)[order], np.concatenate(edges)[order]


def _leg_segments(scene: Scene, view: str, side: int | None = None) -> tuple[np.ndarray, list]:
    """Leg polylines O -> M -> P as segments (2 n, 2, 2) [m] and their state colours; ``side`` 0 / 1
    keeps the left / right legs only (leg k = 2 segment + side)."""
    if scene.legs is None:
        return np.zeros((0, 2, 2)), []
    _, (a, b) = VIEWS[view]
    legs, states = scene.legs, scene.leg_states
    if side is not None:
        legs, states = legs[side::2], states[side::2]
    seg = np.concatenate([legs[:, 0:2], legs[:, 1:3]])[:, :, [a, b]]
    cols = [STATE_COLORS[int(s)] if 0 <= s < len(STATE_COLORS) else DEFAULT_COLOR for s in states]
    return seg, cols + cols




def _antenna_segments(scene: Scene, view: str) -> tuple[list, list]:
    """The antennae as polylines in one view (x-z from above, x-y from the side) and their colours."""
    if scene.antennae is None:
        return [], []
    a, b = (0, 2) if view == "top" else (0, 1)
    touching = scene.antenna_contact if scene.antenna_contact is not None else np.zeros(2, bool)
    return ([scene.antennae[k][:, [a, b]] for k in range(len(scene.antennae))],
            [ANTENNA_CONTACT_COLOR if touching[k] else ANTENNA_COLOR for k in range(len(scene.antennae))])


def _spring_segments(scene: Scene, view: str) -> np.ndarray:
    if scene.springs is None:
        return np.zeros((0, 2, 2))
    _, (a, b) = VIEWS[view]
    return scene.springs[:, :, [a, b]]


# --------------------------------------------------------------------------- terrain




def _draw_terrain(ax_top, ax_side, terrain, xlim, ylim, zlim) -> None:
    kind, f = terrain
    xs = np.linspace(xlim[0], xlim[1], 400)
    h = surface_height(kind, f, xs, 0.5 * (zlim[0] + zlim[1]))  # the profile under the middle of the view
    ax_side.fill_between(xs, h, ylim[0] - (ylim[1] - ylim[0]), color=GROUND_COLOR, zorder=0, lw=0)
    ax_side.plot(xs, h, color=GROUND_EDGE, lw=1.2, zorder=0.5)
    ax_top.add_patch(Rectangle((xlim[0], zlim[0]), xlim[1] - xlim[0], zlim[1] - zlim[0], color=GROUND_COLOR,
                               zorder=0, lw=0))
    draw_terrain_shape(ax_top, ax_side, kind, f, xlim, ylim, zlim)  # height field / mesh as they are
    if kind == SLAB and f[2] > xlim[0]:  # Miller's book occupies x <= f[2]
        ax_top.add_patch(Rectangle((xlim[0], zlim[0]), min(f[2], xlim[1]) - xlim[0], zlim[1] - zlim[0],
                                   color=SLAB_COLOR, zorder=0.1, lw=0))
    # obstacles (cylinders and boxes, Fig. 13): discs / rectangles from above, their silhouettes from the side
    if f.shape[0] > H_NOBST and f[H_NOBST] > 0:
        for r in obstacle_records(f):
            if r[0] == OBST_CYLINDER:
                cx, cz, rad, y0, y1 = r[1:6]
                ax_top.add_patch(Circle((cx, cz), rad, color=OBSTACLE_COLOR, zorder=0.3, lw=0))
                ax_side.add_patch(Rectangle((cx - rad, y0), 2 * rad, y1 - y0, color=OBSTACLE_COLOR, zorder=0.3,
                                            lw=0, alpha=0.6))
            else:  # a box: centre, half extents, cos/sin of its yaw
                cx, cy, cz, hx, hy, hz, cy_, sy_ = r[1:9]
                corners = np.array([[-hx, -hz], [hx, -hz], [hx, hz], [-hx, hz]])
                rot = np.array([[cy_, sy_], [-sy_, cy_]])
                ax_top.add_patch(Polygon(corners @ rot.T + [cx, cz], color=OBSTACLE_COLOR, zorder=0.3, lw=0))
                ext = abs(hx * cy_) + abs(hz * sy_)
                ax_side.add_patch(Rectangle((cx - ext, cy - hy), 2 * ext, 2 * hy, color=OBSTACLE_COLOR, zorder=0.3,
                                            lw=0, alpha=0.6))
    # a fixed ground grid makes motion visible against the fixed camera
    span = max(xlim[1] - xlim[0], zlim[1] - zlim[0])
    step = 10.0 ** math.floor(math.log10(span / 4.0))
    for v in np.arange(math.ceil(xlim[0] / step) * step, xlim[1], step):
        ax_top.axvline(v, color=GROUND_EDGE, lw=0.3, alpha=0.4, zorder=0.2)
    for v in np.arange(math.ceil(zlim[0] / step) * step, zlim[1], step):
        ax_top.axhline(v, color=GROUND_EDGE, lw=0.3, alpha=0.4, zorder=0.2)


# --------------------------------------------------------------------------- limits and layout

def view_limits(frames: Sequence[Scene], terrain=None, min_aspect: float = 0.25):
    """Fixed (xlim, ylim, zlim) [m] covering every frame, padded.

    The vertical extents (z in the top view, y in the side view) are at least
    ``min_aspect`` of the x extent, so a long thin worm still gets panels of a
    sensible shape; the side view includes the ground below the body when it is
    near (not the far-away plane of terrain ``none`` or a body high above it).
    """
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    for s in frames:
        a, b = s.bounds()
        lo, hi = np.fmin(lo, a), np.fmax(hi, b)
    if not np.all(np.isfinite(lo)):
        lo, hi = np.full(3, -1.0), np.full(3, 1.0)
    size = float(max(hi - lo))
    size = size if size > 0 else 1.0
    pad = 0.06 * size
    xlim = (lo[0] - pad, hi[0] + pad)
    if terrain is not None and terrain[0] == SLAB:  # show the book's edge when the body is near it
        edge = float(terrain[1][2])
        if lo[0] - 0.5 * size <= edge <= hi[0] + 0.5 * size:
            xlim = (min(xlim[0], edge - pad), max(xlim[1], edge + pad))
    ground_lo = lo[1]
    if terrain is not None:
        h = surface_height(terrain[0], terrain[1], np.linspace(*xlim, 50), 0.5 * (lo[2] + hi[2]))
        h = h[np.isfinite(h)]
        if len(h) and h.min() > lo[1] - 0.5 * size:
            ground_lo = min(lo[1], float(h.min()))
    ylim = [ground_lo - pad, hi[1] + pad]
    zlim = [lo[2] - pad, hi[2] + pad]
    need = min_aspect * (xlim[1] - xlim[0])
    if ylim[1] - ylim[0] < need:
        ylim[1] = ylim[0] + need  # grow upward: the ground stays at the bottom of the side view
    if zlim[1] - zlim[0] < need:
        c = 0.5 * (zlim[0] + zlim[1])
        zlim = [c - 0.5 * need, c + 0.5 * need]
    # and a body hanging straight down gets panels no narrower than half their height
    need_x = 0.5 * max(ylim[1] - ylim[0], zlim[1] - zlim[0])
    if xlim[1] - xlim[0] < need_x:
        c = 0.5 * (xlim[0] + xlim[1])
        xlim = (c - 0.5 * need_x, c + 0.5 * need_x)
    return xlim, tuple(ylim), tuple(zlim)


# --------------------------------------------------------------------------- the animation

# Layout [inches]: explicit, so that equal-aspect panels fill the figure whatever the creature's shape.
FIG_WIDTH = 13.0                         # [in]; narrower when the panels are tall
MIN_FIG_WIDTH = 7.5                      # room for the leg-state legend
LEFT, GAP, RIGHT = 0.75, 0.95, 0.2       # margins left of, between and right of the two panels
BOTTOM, TOP, LEGEND = 0.5, 0.65, 0.5     # x labels; panel titles and the time line; the leg-state legend
MAX_PANEL_HEIGHT = 6.0
STACK_GAP = 0.75                         # [in] between panels placed one above the other (x labels, title)
DEFAULT_DPI = 80                         # pixels per inch without --size: 13 in = 1040 px
REF_HEIGHT = 6.5                         # [in] the height a --size picture is laid out for (with FIG_WIDTH)
MIN_DPI, MAX_DPI = 40, 300
MIN_SIZE_PX, MAX_SIZE_PX = 160, 7680     # --size limits per side [px]
VIEW_NAMES = ("2d", "3d")


def parse_size(text: str) -> tuple[int, int]:
    """``"WxH"`` -> (W, H) pixels; ValueError naming what is allowed."""
    parts = str(text).lower().split("x")
    try:
        w, h = (int(p) for p in parts)
    except ValueError:
        raise ValueError(f"{text!r}: expected WIDTHxHEIGHT in pixels, e.g. 1280x720") from None
    if not (MIN_SIZE_PX <= w <= MAX_SIZE_PX and MIN_SIZE_PX <= h <= MAX_SIZE_PX):
        raise ValueError(f"{text!r}: width and height must be {MIN_SIZE_PX} to {MAX_SIZE_PX} pixels")
    return w, h


def size_dpi(size: tuple[int, int]) -> float:
    """Pixels per inch for a picture of ``size`` (W, H) [px]: the layout's fonts and margins (in inches and
    points) keep their share of the picture's area as in a FIG_WIDTH x REF_HEIGHT inch picture, within
    MIN_DPI..MAX_DPI (1040 x 720 px: 94 dpi; 1920 x 1080: 157)."""
    w, h = size
    return float(min(MAX_DPI, max(MIN_DPI, math.sqrt(w * h / (FIG_WIDTH * REF_HEIGHT)))))


def _static_figure(xlim, ylim, zlim, terrain, has_legs: bool, dpi: float, size_in=None):
    """The parts of the picture that never change (axes, labels, terrain, legend), and the two panels'
    positions (figure fractions).  Drawn once: re-drawing tick labels for every frame cost most of the
    time of writing an animation.

    size_in: (width, height) [in] of the figure, or None to size it from the panels (FIG_WIDTH wide,
    narrower for tall panels).  Given, the equal-aspect panels are as large as fit and centred.
    """
    xs = xlim[1] - xlim[0]
    ratios = ((zlim[1] - zlim[0]) / xs, (ylim[1] - ylim[0]) / xs)
    bottom = BOTTOM + LEGEND * has_legs
    stacked = False
    if size_in is None:
        pw = 0.5 * (FIG_WIDTH - LEFT - GAP - RIGHT)
        pw = min(pw, MAX_PANEL_HEIGHT / max(ratios))  # a tall view (a hanging body) makes the panels narrower
        width = max(MIN_FIG_WIDTH, LEFT + 2 * pw + GAP + RIGHT)
        height = bottom + pw * max(ratios) + TOP
    else:
        width, height = size_in
        free_h = height - bottom - TOP
        beside = min(0.5 * (width - LEFT - GAP - RIGHT), free_h / max(ratios))
        # one above the other (the top view above) when that makes the panels larger, e.g. a 4:3 picture
        above = min(width - LEFT - RIGHT, (free_h - STACK_GAP) / sum(ratios))
        stacked = above > beside
        pw = max(0.1, above if stacked else beside)
    ph = [pw * r for r in ratios]
    fig = plt.figure(figsize=(width, height), dpi=dpi)
    if stacked:
        left0 = 0.5 * (width - (pw + RIGHT - LEFT))
        b0 = bottom + 0.5 * max(0.0, height - bottom - TOP - sum(ph) - STACK_GAP)
        boxes = [(left0, b0 + ph[1] + STACK_GAP, ph[0]), (left0, b0, ph[1])]
    else:
        left0 = 0.5 * (width - (2 * pw + GAP + RIGHT - LEFT))  # centred when the figure is wider than the panels
        b0 = bottom + 0.5 * max(0.0, height - bottom - TOP - max(ph))  # and vertically when it is taller
        boxes = [(left0, b0, ph[0]), (left0 + pw + GAP, b0, ph[1])]
    axes = []
    for k, (vlim, label, name) in enumerate(((zlim, "z [m]", "from above (x-z)"),
                                             (ylim, "y [m]", "from the right side (x-y)"))):
        left, low, h = boxes[k]
        ax = fig.add_axes((left / width, low / height, pw / width, h / height))
        ax.set_xlim(*xlim)
        ax.set_ylim(*vlim)
        ax.set_xlabel("x [m]", fontsize=9, labelpad=1)
        ax.set_ylabel(label, fontsize=9, labelpad=1)
        ax.set_title(name, fontsize=10, pad=3)
        ax.tick_params(labelsize=8)
        axes.append(ax)
    ax_top, ax_side = axes
    ax_top.invert_yaxis()  # z points to the right of a creature facing +x: down the page, seen from above
    if terrain is not None:
        _draw_terrain(ax_top, ax_side, terrain, xlim, ylim, zlim)
    if has_legs:
        add_leg_state_legend(fig)
    return fig, [ax.get_position().bounds for ax in axes]





def _figure_2d(frames: Sequence[Scene], terrain, title: str, dpi: float, size_in, water):
    """The two-panel picture (from above, from the side) and its per-frame ``draw(scene, t, k)``."""
    xlim, ylim, zlim = view_limits(frames, terrain)
    has_legs = any(s.legs is not None for s in frames)

    # The static picture, rendered once to pixels; every frame is that image plus the moving artists
    # on two bare axes placed exactly over the panels (same limits, same pixels).
    static, boxes = _static_figure(xlim, ylim, zlim, terrain, has_legs, dpi, size_in)
    static.canvas.draw()
    background = np.asarray(static.canvas.buffer_rgba()).copy()
    fig = plt.figure(figsize=static.get_size_inches(), dpi=dpi)
    plt.close(static)
    bg = fig.add_axes((0, 0, 1, 1))
    bg.imshow(background, interpolation="nearest", aspect="auto")
    bg.set_axis_off()
    ax_top, ax_side = (fig.add_axes(b) for b in boxes)
    for ax, vlim in ((ax_top, zlim), (ax_side, ylim)):
        ax.set_xlim(*xlim)
        ax.set_ylim(*vlim)
        ax.set_axis_off()  # no patch, ticks or labels: those are in the background
    ax_top.invert_yaxis()

    def poly():
        return PolyCollection([], linewidths=0.3, zorder=2)

    bodies = {"top": ax_top.add_collection(poly()), "side": ax_side.add_collection(poly())}
    springs = {v: ax.add_collection(LineCollection([], colors=[(0.2, 0.2, 0.2, 0.45)], linewidths=0.4, zorder=2.5))
               for v, ax in (("top", ax_top), ("side", ax_side))}
    legs_top = ax_top.add_collection(LineCollection([], linewidths=1.6, zorder=3))
    # antennae: dark brown, red while touching an obstacle (Sec. 5.2)
    antennae = {v: ax.add_collection(LineCollection([], linewidths=1.2, zorder=3.5))
                for v, ax in (("top", ax_top), ("side", ax_side))}
    # side view: the right legs (+z, toward the viewer) in front of the body, the left ones behind it
    legs_side = {1: ax_side.add_collection(LineCollection([], linewidths=1.6, zorder=3)),
                 0: ax_side.add_collection(LineCollection([], linewidths=1.6, zorder=1.5))}
    head = fig.text(0.5, 1.0 - 0.08 / fig.get_size_inches()[1], "", ha="center", va="top", fontsize=11)
    ripples = None
    if water is not None:
        water_frames, (wx0, wx1, wz0, wz1) = water
        # a robust scale: the feet make sharp dimples; the ripples they spread are what should show
        amp = float(np.percentile(np.abs(np.stack(water_frames[len(water_frames) // 2:])), 99.0)) or 1e-6
        ripples = ax_top.imshow(water_frames[0].T, origin="lower", extent=(wx0, wx1, wz0, wz1), cmap="RdBu_r",
                                vmin=-amp, vmax=amp, alpha=0.65, zorder=1, interpolation="bilinear", aspect="auto")
        ax_top.set_xlim(*xlim)
        ax_top.set_ylim(zlim[1], zlim[0])  # keep the inverted z axis after imshow

    def draw(scene: Scene, t: float, k: int) -> None:
        if ripples is not None:
            ripples.set_data(water[0][min(k, len(water[0]) - 1)].T)
        for view, coll in bodies.items():
            p, c, e = _project_triangles(scene, view)
            coll.set_verts(p)
            coll.set_facecolor(c)
            coll.set_edgecolor(e)
            springs[view].set_segments(_spring_segments(scene, view))
        seg, cols = _leg_segments(scene, "top")
        legs_top.set_segments(seg)
        legs_top.set_color(cols)
        for side, coll in legs_side.items():
            seg, cols = _leg_segments(scene, "side", side)
            coll.set_segments(seg)
            coll.set_color(cols)
        for view, coll in antennae.items():
            seg, cols = _antenna_segments(scene, view)
            coll.set_segments(seg)
            coll.set_color(cols)
        head.set_text(f"{title}   t = {t:.3f} s" if title else f"t = {t:.3f} s")

    return fig, draw


def write_animation(frames: Sequence[Scene], times: Sequence[float], terrain, path, title: str = "",
                    fps: float | None = None, dpi: float | None = None, water=None,
                    size: tuple[int, int] | None = None, view: str = "2d") -> dict:
    """Draw ``frames`` (Scenes) at ``times`` [s] into ``path`` (.gif with Pillow, .mp4 with ffmpeg).

    terrain: ``(kind, f)`` of ``world.terrain.terrain_from_scenario`` or None
    (no ground drawn).  fps: a fixed playback rate; default real time (an mp4 at
    ``playback_fps(times)``; a GIF with each frame shown for the simulated time to
    the next, ``gif_durations_cs``).  size: (W, H) [px] of the picture, or None
    (the 2-D view: 13 in at ``dpi``, its height from the panels; the 3-D view:
    1040 x 720).  dpi: pixels per inch, default ``size_dpi(size)`` or 80.
    view: "2d" (from above and from the side) or "3d" (``report.animate3d``: a
    shaded perspective view whose camera follows the creature).  water: None, or
    (surface frames, region) of ``FrameRecorder.water()``: the water surface's
    deviation from rest drawn from above (blue troughs, red crests) under the
    body (2-D view only).  The file is written under a temporary name in the same
    directory and renamed into place at the end, so a failure leaves no
    half-written animation.  Returns {"path", "frames", "fps", "size"} (fps: the
    mean playback rate; size: (W, H) [px]).
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise ValueError(f"{path}: an animation must end in .gif or .mp4")
    if view not in VIEW_NAMES:
        raise ValueError(f"view must be one of {VIEW_NAMES}, got {view!r}")
    if not len(frames) or len(frames) != len(times):
        raise ValueError(f"need one time per frame and at least one frame, got {len(frames)} frames, "
                         f"{len(times)} times")
    if size is None and view == "3d":
        from .animate3d import DEFAULT_SIZE
        size = DEFAULT_SIZE
    dpi = float(dpi) if dpi is not None else (size_dpi(size) if size is not None else float(DEFAULT_DPI))
    # + 1e-6 px: matplotlib truncates inches x dpi to whole pixels, and W / dpi * dpi may be W - 1e-13
    size_in = None if size is None else ((size[0] + 1e-6) / dpi, (size[1] + 1e-6) / dpi)
    if view == "3d":
        from .animate3d import figure_3d
        fig, draw = figure_3d(frames, terrain, title, dpi, size_in)
    else:
        fig, draw = _figure_2d(frames, terrain, title, dpi, size_in, water)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.stem}.{os.getpid()}.tmp{path.suffix}")  # same suffix: ffmpeg picks the format by it
    try:
        if suffix == ".gif":
            durations = gif_durations_cs(times, fps)
            pixels = _write_gif(fig, draw, frames, times, tmp, durations)
            rate = 100.0 * len(durations) / sum(durations)
        else:
            rate = playback_fps(times) if fps is None else float(fps)
            pixels = _write_mp4(fig, draw, frames, times, tmp, rate, dpi)
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if tmp.exists():
            tmp.unlink()
    return {"path": str(path), "frames": len(frames), "fps": rate, "size": pixels}


def _write_gif(fig, draw, frames, times, path: Path, durations_cs: Sequence[int]) -> tuple[int, int]:
    """Render every frame and write a looping GIF whose frame k is shown ``durations_cs[k]`` centiseconds.

    Written with Pillow directly rather than matplotlib's PillowWriter, which gives every frame
    int(1000 / fps) ms and Pillow then truncates that to centiseconds (33.3 ms -> 3 cs: 10 % fast).
    Each frame is reduced to its own 256-colour palette as it is grabbed (1 byte a pixel held, not 4).
    """
    from PIL import Image

    images = []
    for k, (scene, t) in enumerate(zip(frames, times)):
        draw(scene, t, k)
        fig.canvas.draw()
        rgba = np.asarray(fig.canvas.buffer_rgba())
        images.append(Image.fromarray(np.ascontiguousarray(rgba[..., :3])).quantize(256, Image.Quantize.MEDIANCUT))
    # Pillow takes milliseconds and stores centiseconds: whole centiseconds pass through unchanged
    images[0].save(path, format="GIF", save_all=True, append_images=images[1:], loop=0,
                   duration=[10 * int(d) for d in durations_cs], disposal=1, optimize=False)
    return images[0].size


def _write_mp4(fig, draw, frames, times, path: Path, fps: float, dpi: float) -> tuple[int, int]:
    """Render every frame into an H.264 mp4 at ``fps`` frames per second (ffmpeg)."""
    writer = animation.FFMpegWriter(fps=fps, codec="h264")  # matplotlib adds yuv420p: plays everywhere
    with writer.saving(fig, str(path), dpi):
        for k, (scene, t) in enumerate(zip(frames, times)):
            draw(scene, t, k)
            writer.grab_frame()
    return writer.frame_size
