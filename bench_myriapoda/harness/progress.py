"""A plain text progress bar on stderr for runs started from a terminal."""
from __future__ import annotations

import sys
import time


class ProgressBar:
    """Draws ``label [#####-----]  42%  eta 3s`` on stderr; does nothing when disabled."""

    def __init__(self, enabled: bool, label: str = "", width: int = 30, stream=None):
        self.enabled = enabled
        self.label = label
        self.width = width
        self.stream = stream or sys.stderr
        self.t0 = time.perf_counter()
        self._last = -1.0

    def update(self, fraction: float) -> None:
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self._last < 0.1 and fraction < 1.0:  # redraw at most 10 times a second
            return
        self._last = now
        done = int(self.width * fraction)
        eta = (now - self.t0) * (1 - fraction) / fraction if fraction > 0 else float("nan")
        self.stream.write(f"\r{self.label} [{'#' * done}{'-' * (self.width - done)}] {fraction:4.0%}  eta {eta:4.0f}s")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()
