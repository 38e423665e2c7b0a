"""Writing a matplotlib figure to a PNG file, the same way for every report module, and the report's type sizes.

The report is read at about 1400 px wide (``build.CSS``: images at their own
pixel size up to the page width).  So every figure is at least ``MIN_WIDTH_PX``
wide and no text is smaller than ``LABEL_PT`` points at ``DPI`` (9 pt at 100
dpi = 12.5 px): ``report_style()`` sets matplotlib's defaults for the report's
figures, and modules use ``LABEL_PT`` / ``TITLE_PT`` where they size text
themselves.
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; never needs a display
import matplotlib.pyplot as plt  # noqa: E402

DPI = 100             # pixels per inch of every report figure
MIN_WIDTH_PX = 800    # no figure narrower: read at 1400 px, an image is shown at its own size
LABEL_PT = 9          # the smallest text: tick labels, legends, annotations [pt]
AXIS_PT = 10          # axis labels [pt]
TITLE_PT = 11         # panel titles [pt]
WIDE_IN = 11.0        # [in] the width of a full-width figure (1100 px at DPI)

STYLE = {"font.size": AXIS_PT, "axes.titlesize": TITLE_PT, "axes.labelsize": AXIS_PT,
         "xtick.labelsize": LABEL_PT, "ytick.labelsize": LABEL_PT, "legend.fontsize": LABEL_PT,
         "legend.title_fontsize": LABEL_PT, "figure.titlesize": TITLE_PT}


def report_style():
    """A context manager: matplotlib's type sizes for the report's figures (``STYLE``)."""
    return plt.rc_context(STYLE)


def save_figure(fig, path, dpi: int = DPI) -> Path:
    """Save ``fig`` to ``path`` (parent folders created), close it, and return the path.

    A figure that would come out narrower than MIN_WIDTH_PX is saved at a higher dpi (its text grows
    with it), so that no report image is shown smaller than its labels need.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    width_in = fig.get_size_inches()[0]
    fig.savefig(path, dpi=max(dpi, MIN_WIDTH_PX / width_in + 0.5))
    plt.close(fig)
    return path
