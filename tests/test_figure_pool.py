"""``report.figure_pool`` and ``figure_files.save_figure``: figures drawn once, here or in forked workers."""
from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from bench_myriapoda.report.figure_files import report_style, save_figure  # noqa: E402
from bench_myriapoda.report.figure_pool import FigurePainter, fork_context  # noqa: E402


def _constrained(title: str = "a constrained figure"):
    fig, axes = plt.subplots(2, 2, figsize=(9.0, 5.0), layout="constrained")
    x = np.linspace(0.0, 10.0, 200)
    for k, ax in enumerate(axes.flat):
        ax.plot(x, np.sin(x * (k + 1)), label=f"sin {k + 1}x")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("a long label of the y axis [J]")
        ax.legend(loc="best")
    fig.colorbar(plt.cm.ScalarMappable(cmap="viridis"), ax=list(axes.flat), orientation="horizontal", shrink=0.5)
    fig.suptitle(title)
    return fig


def _tight():
    fig, ax = plt.subplots(figsize=(9.0, 3.0))
    ax.plot([0, 1, 2], [2, 0, 1], "o-")
    ax.set_title("a tight_layout figure")
    fig.tight_layout()
    return fig


@pytest.mark.parametrize("make", [_constrained, _tight])
def test_save_figure_draws_once_and_writes_what_savefig_writes(make, tmp_path, monkeypatch):
    with report_style():
        ref = make()
        ref.savefig(tmp_path / "ref.png", dpi=100)  # matplotlib's own way: a layout draw, then the pixels
        plt.close(ref)
        draws = []
        real_draw = Figure.draw
        monkeypatch.setattr(Figure, "draw", lambda self, r: (draws.append(1), real_draw(self, r))[1])
        save_figure(make(), tmp_path / "ours.png", dpi=100)
    assert len(draws) == 1
    assert (tmp_path / "ours.png").read_bytes() == (tmp_path / "ref.png").read_bytes()


def _draw_line(path, title):
    fig, ax = plt.subplots(figsize=(9.0, 3.0), layout="constrained")
    ax.plot([0, 1], [0, 1])
    ax.set_title(title)
    save_figure(fig, path)


def _fail(path):
    raise ValueError("no data for this figure")


def _write_nothing(path):
    pass


@pytest.mark.parametrize("workers", [1, 2])
def test_painter_draws_every_figure_and_raises_what_a_figure_raised(workers, tmp_path):
    with FigurePainter(workers) as painter:
        paths = [painter.draw(tmp_path / f"f{k}.png", _draw_line, tmp_path / f"f{k}.png", f"figure {k}")
                 for k in range(4)]
        painter.finish()
    assert paths == [tmp_path / f"f{k}.png" for k in range(4)] and all(p.is_file() for p in paths)
    with pytest.raises(ValueError, match="no data"), FigurePainter(workers) as painter:
        painter.draw(tmp_path / "bad.png", _fail, tmp_path / "bad.png")
        painter.finish()
    with pytest.raises(RuntimeError, match="did not write"), FigurePainter(workers) as painter:
        painter.draw(tmp_path / "none.png", _write_nothing, tmp_path / "none.png")
        painter.finish()


def test_painter_uses_forked_workers_on_linux(tmp_path):
    with FigurePainter(2) as painter:
        if fork_context() is None:
            assert painter.workers == 1
        else:
            assert painter.workers == min(2, os.cpu_count())
    with pytest.raises(ValueError):
        FigurePainter(0)
