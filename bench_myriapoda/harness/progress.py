"""Progress bars on stderr (tqdm) for runs and matrices started from a terminal.

A run's bar counts simulated seconds and shows the step rate; it starts at the
runner's first report, which comes after the body's kernels are compiled, so
neither the rate nor the time left counts compilation.  A matrix's bar counts
cases and shows how many failed; each finished case is also one line above it.
"""
from __future__ import annotations

import sys
import time

from tqdm import tqdm

RUN_FORMAT = "{desc} {percentage:3.0f}%|{bar}| {n:.3g}/{total:.3g} s simulated [{elapsed}<{remaining}{postfix}]"
MATRIX_FORMAT = "{desc} {n}/{total} cases|{bar}| [{elapsed}<{remaining}{postfix}]"


class ProgressBar:
    """One run: ``label  42%|####      | 4.2/10 s simulated [00:03<00:04, 1.2e+04 steps/s]``.

    ``update(fraction)`` takes the fraction of the run done (the runner's ``progress``
    hook); ``total_s`` [s] and ``dt`` [s] are the case's duration and time step (without
    them the bar counts the fraction and shows no step rate).  Disabled, it draws nothing.
    """

    def __init__(self, enabled: bool, label: str = "", width: int = 30, stream=None,
                 total_s: float | None = None, dt: float | None = None):
        self.enabled = enabled
        self.label = label
        self.width = width
        self.stream = stream or sys.stderr
        self.total_s = float(total_s) if total_s else 1.0
        self.dt = dt
        self._bar: tqdm | None = None
        self._t0 = self._f0 = 0.0

    def update(self, fraction: float) -> None:
        if not self.enabled:
            return
        now = time.perf_counter()
        if self._bar is None:
            # started at the first report, i.e. after compilation: rate and time left count stepping only
            self._bar = tqdm(total=self.total_s, initial=fraction * self.total_s, desc=self.label, file=self.stream,
                             bar_format=RUN_FORMAT, ncols=None if self.stream.isatty() else 100,
                             dynamic_ncols=self.stream.isatty(), mininterval=0.1, leave=True)
            self._t0, self._f0 = now, fraction
            if fraction >= 1.0:
                self._bar.refresh()
            return
        if self.dt and now > self._t0:
            steps_per_s = (fraction - self._f0) * self.total_s / self.dt / (now - self._t0)
            self._bar.set_postfix_str(f"{steps_per_s:.3g} steps/s", refresh=False)
        self._bar.update(fraction * self.total_s - self._bar.n)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None


class MatrixProgress:
    """A matrix: ``matrix quick 7/20 cases|###   | [00:41<01:16, failed 1]`` and one line per finished case."""

    def __init__(self, enabled: bool, total: int, label: str = "matrix", stream=None):
        self.enabled = enabled
        self.failed = 0
        self.done = 0
        self._bar = (tqdm(total=total, desc=label, file=stream or sys.stderr, bar_format=MATRIX_FORMAT,
                          dynamic_ncols=True, mininterval=0.1, postfix="failed 0") if enabled else None)

    def case_done(self, label: str, status: str, message: str = "") -> None:
        """Count one finished case (``error`` and ``timeout`` count as failed) and print its line."""
        self.done += 1
        self.failed += status in ("error", "timeout")
        if self._bar is None:
            return
        self._bar.write(f"{label}: {status}" + (f" ({message})" if message else ""), file=self._bar.fp)
        self._bar.set_postfix_str(f"failed {self.failed}", refresh=False)
        self._bar.update(1)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None
