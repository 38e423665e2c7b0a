"""Colours and helpers shared by the 2-D (``animate``) and 3-D (``animate3d``) animation views."""
from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from ..bodies import scene as SC
from ..core import registry
from ..core.specs import SurfaceStyle
from ..metrics.gait import STATE_COLORS, STATE_NAMES
from ..world.terrain_kernels import terrain_phi_numpy

DEFAULT_COLOR = "#aaaaaa"
DEFAULT_STYLE = SurfaceStyle(DEFAULT_COLOR)  # a kind nobody declares: grey with dark edges
GROUND_COLOR, GROUND_EDGE, SLAB_COLOR = "#ece2cf", "#8c7a5b", "#d2bf99"
ANTENNA_COLOR = (0.35, 0.2, 0.05, 1.0)
ANTENNA_CONTACT_COLOR = (0.85, 0.1, 0.1, 1.0)


def surface_styles() -> dict[str, SurfaceStyle]:
    """Kind -> ``SurfaceStyle`` of every kind of triangle surface a scene may hold: the kinds the bodies share
    (``bodies.scene.SHARED_SURFACE_KINDS``) and each catalogued body's own (``BodySpec.surface_kinds``), so
    that the drawing names no body (issue 42)."""
    registry.load_all()
    styles = dict(SC.SHARED_SURFACE_KINDS)
    for spec in registry.BODIES.values():
        for kind, style in spec.surface_kinds.items():
            styles.setdefault(kind, style)
    return styles


def surface_style(kind: str) -> SurfaceStyle:
    """How ``kind`` is drawn (``surface_styles``; ``DEFAULT_STYLE`` for a kind nobody declares)."""
    return surface_styles().get(kind, DEFAULT_STYLE)


def surface_height(kind: int, f: np.ndarray, x: np.ndarray, z: float = 0.0) -> np.ndarray:
    """Height y [m] of the terrain surface (phi = 0) above each x (n,) [m] on the line z [m].

    Vectorised bisection on ``terrain_phi_numpy``: phi grows with y along every
    vertical line of a height-field terrain (plane, slope, slab), so the surface
    is where it changes sign.  Bracketed by widening a search interval around
    f[0]; NaN where no sign change is found (no ground below that x).
    """
    x = np.asarray(x, dtype=float)

    def phi(y):
        return terrain_phi_numpy(kind, f, np.column_stack([x, y, np.full_like(x, z)]))

    lo, hi = np.full_like(x, f[0] - 1.0), np.full_like(x, f[0] + 1.0)
    for _ in range(40):  # widen until phi(lo) <= 0 <= phi(hi) everywhere (or give up: a 1e12 m interval)
        below, above = phi(lo) > 0, phi(hi) < 0
        if not (below.any() or above.any()):
            break
        lo = np.where(below, lo - 2.0 * (hi - lo), lo)
        hi = np.where(above, hi + 2.0 * (hi - lo), hi)
    found = (phi(lo) <= 0) & (phi(hi) >= 0)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        up = phi(mid) > 0
        hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
    return np.where(found, 0.5 * (lo + hi), np.nan)


def add_leg_state_legend(fig) -> None:
    """The leg-state colours (``metrics.gait.STATE_COLORS``) as one legend row at the bottom of ``fig``."""
    handles = [Line2D([0], [0], color=c, lw=2.5, label=n) for c, n in zip(STATE_COLORS, STATE_NAMES)]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles) + 1, fontsize=9, frameon=False,
               title="leg state:", title_fontsize=9, alignment="left", borderaxespad=0.2)
