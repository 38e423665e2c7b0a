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
    dpi = max(dpi, MIN_WIDTH_PX / width_in + 0.5)
    layout_once(fig, path, dpi)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def finish_plot(fig, ax, path, xlabel: str, ylabel: str, legend_loc: str = "best", dpi: int = DPI) -> Path:
    """A one-panel figure's last steps: axis labels, a light grid, the legend at ``legend_loc``, a tight layout,
    saved to ``path`` (``save_figure``); returns the path."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc=legend_loc)
    fig.tight_layout()
    return save_figure(fig, path, dpi=dpi)


def figure_section(page, sid: str, title: str, filename: str, plot, df, caption: str) -> None:
    """A report section of one figure (``report.build``'s page): its heading, ``plot(df, path)`` drawn into the
    figures folder as ``filename``, and the figure with its caption."""
    page.section(sid, title)
    path = page.fig_dir / filename
    page.draw(path, plot, df, path)
    page.figure(path, caption)


def layout_once(fig, path, dpi: float) -> None:
    """Run ``fig``'s layout engine now, at the saving ``dpi``, and detach it, so that ``savefig`` draws once.

    With any layout engine attached (``layout="constrained"``, or the placeholder ``tight_layout()``
    leaves behind), ``savefig`` draws the whole figure twice: once with rendering switched off, only to
    run the engine, then for the pixels.  The first pass costs as much Python as the second (every
    tick and text laid out again), a third of a report figure's time.  Running the engine here with
    the renderer ``savefig`` would use (same dpi) gives the same positions, and the saved image is the
    same byte for byte (tests/test_report.py compares).  ``path``: the file it will be saved to (only a
    ``.png`` is laid out here: a vector format measures text with its own renderer); ``dpi``: its dpi.
    """
    engine = fig.get_layout_engine()
    if engine is None or Path(path).suffix.lower() != ".png":
        return
    fig.dpi = dpi  # the layout measures text in pixels: measure it as savefig would
    engine.execute(fig)  # a no-op for tight_layout()'s placeholder: that layout is done already
    # None (not "none", which leaves a placeholder that savefig still draws for); with these rc values
    # off, set_layout_engine(None) detaches the engine instead of making a new one
    with plt.rc_context({"figure.autolayout": False, "figure.constrained_layout.use": False}):
        fig.set_layout_engine(None)


def show_png(path) -> None:
    """Show the PNG file ``path`` as a figure of its own pixel size, without axes: the example gallery shows
    the figures a script opens, so a script that wrote a report figure to a file shows it this way."""
    image = plt.imread(path)
    fig, ax = plt.subplots(figsize=(image.shape[1] / DPI, image.shape[0] / DPI), dpi=DPI)
    ax.imshow(image)
    ax.axis("off")
    fig.tight_layout(pad=0)
    plt.show()
