"""Draw the README's picture, docs/_static/scorecard.png, from the main job's output.

    python3 tools/make_readme_picture.py [DIR] [--out PNG] [--history-store PATH]

DIR (default ``reports/quick``, what ``bench-myriapoda`` writes) is read as ``bench-myriapoda scorecard DIR``
reads it (``report.scorecard.scorecard_for_dir``, with the validate verdicts of DIR and of the history store,
default ``reports/results.sqlite``); the picture is the scorecard's table (``scorecard_table``: one row per
creature x body model, a column per group) under each creature's one-line recommendation.  So the README
shows what the code produces now, not a screenshot from an earlier run.

The documentation build calls ``refresh`` (docs/conf.py): with a main-job output in reports/quick it
re-makes the picture; without one (a fresh clone, a CI job that builds only the docs) it keeps the committed
picture and says so in the build's log, so the docs build never runs the main job, never slows down for it
and never fails for want of it.
"""
from __future__ import annotations

import argparse
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_DIR = Path("reports") / "quick"
DEFAULT_OUT = ROOT / "docs" / "_static" / "scorecard.png"
# characters per line of each column's cells (wrapped); other columns get WRAP_OTHER
WRAP = {"creature": 11, "body": 10}
WRAP_OTHER = 30
ROW_PAD = 0.5        # [lines] space between two rows
LINE_IN = 0.17       # [in] one 9 pt line
WIDTH_IN = 14.0      # [in] the picture's width (1400 px at 100 dpi: the report's reading width)


def draw(card):
    """The figure: recommendations on top, then the table (cells wrapped), rows striped per creature."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from bench_myriapoda.report.scorecard import scorecard_table

    table = scorecard_table(card)
    cols = list(table.columns)
    recs = [textwrap.fill(f"{c}: {card.recommendations[c].split(': ', 1)[-1]}", 190)
            for c in sorted(card.recommendations)]
    cells = [[textwrap.fill(str(v), WRAP.get(c, WRAP_OTHER)) for c, v in zip(cols, row)]
             for row in table.itertuples(index=False)]
    heads = [textwrap.fill(c, WRAP.get(c, WRAP_OTHER)) for c in cols]
    head_lines = max(h.count("\n") + 1 for h in heads)
    row_lines = [max(c.count("\n") + 1 for c in r) for r in cells]
    rec_lines = sum(r.count("\n") + 1 for r in recs)
    total = 2 + rec_lines + 1 + head_lines + ROW_PAD + sum(n + ROW_PAD for n in row_lines)
    fig = plt.figure(figsize=(WIDTH_IN, LINE_IN * total + 0.3))
    ax = fig.add_axes((0.005, 0.0, 0.99, 1.0))
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(total, 0)
    widths = [WRAP.get(c, WRAP_OTHER) for c in cols]
    x = [sum(widths[:i]) / sum(widths) for i in range(len(cols))]
    ax.text(0, 0.2, f"Scorecard of {card.source} (bench-myriapoda scorecard; tools/make_readme_picture.py)",
            fontsize=11, weight="bold", va="top")
    y = 1.8
    for r in recs:
        ax.text(0, y, r, fontsize=9, va="top")
        y += r.count("\n") + 1
    y += 0.6
    for xi, h in zip(x, heads):
        ax.text(xi, y, h, fontsize=9, va="top", weight="bold")
    y += head_lines + ROW_PAD / 2
    ax.axhline(y, color="0.3", lw=0.8)
    creatures = [row[0] for row in table.itertuples(index=False)]
    shade = {c: i % 2 for i, c in enumerate(dict.fromkeys(creatures))}
    for creature, row, n in zip(creatures, cells, row_lines):
        if shade[creature]:
            ax.axhspan(y, y + n + ROW_PAD, color="0.94", zorder=0)
        for xi, v in zip(x, row):
            ax.text(xi, y + ROW_PAD / 2, v, fontsize=9, va="top")
        y += n + ROW_PAD
    return fig


def make(directory: Path | str = DEFAULT_DIR, out: Path | str = DEFAULT_OUT,
         history_store: Path | str | None = None) -> Path:
    """Write the picture of ``directory``'s scorecard to ``out``; an ``InputError`` when it is no matrix output."""
    from bench_myriapoda.harness.store import DEFAULT_STORE
    from bench_myriapoda.report.figure_files import save_figure
    from bench_myriapoda.report.scorecard import scorecard_for_dir

    card = scorecard_for_dir(directory, Path(history_store) if history_store else DEFAULT_STORE)
    return save_figure(draw(card), out)


def refresh(directory: Path, out: Path, log=print) -> bool:
    """For the docs build: re-make ``out`` from ``directory`` when that holds a main-job output, else keep the
    committed picture.  Returns whether it was re-made; ``log`` gets one line either way."""
    from bench_myriapoda.core.errors import InputError
    from bench_myriapoda.harness.store import StoreReadError

    if not (directory / "results.sqlite").is_file() or not (directory / "matrix.json").is_file():
        log(f"README picture: no main-job output in {directory} (run `bench-myriapoda`); kept {out}")
        return False
    try:
        make(directory, out, directory.parent / "results.sqlite")
    except (InputError, StoreReadError) as exc:  # an interrupted or older output: the committed picture stays
        log(f"README picture: {directory} is not a readable matrix output ({exc}); kept {out}")
        return False
    log(f"README picture: {out} re-made from {directory}")
    return True


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("dir", nargs="?", default=str(DEFAULT_DIR), help="the main job's output (default reports/quick)")
    p.add_argument("--out", default=str(DEFAULT_OUT), help="the PNG to write (default docs/_static/scorecard.png)")
    p.add_argument("--history-store", default=None, help="validate rows (default reports/results.sqlite)")
    args = p.parse_args(argv)
    from bench_myriapoda.core.errors import InputError

    try:
        path = make(args.dir, args.out, args.history_store)
    except InputError as exc:
        print(f"make_readme_picture: error: {exc}", file=sys.stderr)
        return 2
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
