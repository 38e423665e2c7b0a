"""Drawing the report's figures in worker processes while the report's text is assembled.

A report figure is a pure function of its data: ``plot_*(data..., path)`` writes one PNG.  The
quick matrix's report draws 25 of them, about 4 CPU seconds of matplotlib, in the one process
that also builds the tables; the matrix's worker processes have finished by then, so their cores
are idle.  ``FigurePainter(workers)`` hands each figure to a pool of ``workers`` processes and
returns at once; the report goes on with the next section and calls ``finish()`` before it moves
its files into place.  A figure is the same file whichever process draws it (the same code, data
and matplotlib settings: ``figure_files.report_style`` is applied in the worker too), so the page
does not change, only when its images are written.

Workers are forked (Linux), so they start in milliseconds with matplotlib already imported; a
spawned worker would import it again, about a second of CPU each, most of what it would save.
Elsewhere (macOS, Windows: no safe fork) and with ``workers = 1`` every figure is drawn in this
process, in order, as before.
"""
from __future__ import annotations

import logging
import multiprocessing as mp
import os
import sys
from concurrent.futures import Future, ProcessPoolExecutor
from pathlib import Path
from typing import Any, Callable

from .figure_files import report_style


def fork_context():
    """The ``fork`` multiprocessing context on Linux, else None (figures are then drawn in this process)."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        return mp.get_context("fork")
    except ValueError:  # a platform without fork
        return None


def _draw(fn: Callable[..., Any], args: tuple, kwargs: dict) -> None:
    """In a worker: draw one figure with the report's matplotlib settings (as ``build_report`` sets them)."""
    logging.getLogger("matplotlib.axes._base").setLevel(logging.ERROR)  # see build.build_report
    with report_style():
        fn(*args, **kwargs)


def _check_written(path: Path) -> None:
    if not path.is_file():
        raise RuntimeError(f"the figure function for {path.name} did not write it")


class FigurePainter:
    """Draws figure files, here or in ``workers`` forked processes; ``finish()`` waits for all of them.

    workers: processes drawing figures (>= 1; at most the CPU count are started); 1, or no fork on this
    platform: each figure is drawn when it is submitted, in this process.
    """

    def __init__(self, workers: int = 1):
        if workers < 1:
            raise ValueError(f"workers must be >= 1, got {workers}")
        workers = min(workers, os.cpu_count() or 1)  # more processes than cores only add start-up
        ctx = fork_context() if workers > 1 else None
        self.workers = workers if ctx is not None else 1
        self._pool = ProcessPoolExecutor(max_workers=workers, mp_context=ctx) if ctx is not None else None
        self._pending: list[tuple[Path, Future]] = []

    def draw(self, path: Path | str, fn: Callable[..., Any], *args, **kwargs) -> Path:
        """``fn(*args, **kwargs)`` writes the figure file ``path``; returns ``path``.

        In a pool, ``fn`` must be a module-level function and its arguments picklable; the file
        exists after ``finish()``.  An exception of ``fn`` is raised here (no pool) or by ``finish()``.
        """
        path = Path(path)
        if self._pool is None:
            fn(*args, **kwargs)
            _check_written(path)
        else:
            self._pending.append((path, self._pool.submit(_draw, fn, args, kwargs)))
        return path

    def finish(self) -> None:
        """Wait for every submitted figure; raise the first failure (in submission order).

        Raises RuntimeError when a figure function returned without writing its file.
        """
        pending, self._pending = self._pending, []
        for path, fut in pending:
            fut.result()
            _check_written(path)

    def close(self) -> None:
        """Stop the workers (figures not started yet are cancelled: after an error, nothing waits for them)."""
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None

    def __enter__(self) -> "FigurePainter":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
