"""Build step: ship the top-level data folders inside the package.

``models/`` and ``scenarios/`` stay at the top of the repository (they are data,
not Python packages: ARCHITECTURE.md).  A wheel must still carry them, so
``build_py`` copies every ``*.toml`` of both folders into
``bench_myriapoda/_data/models`` and ``bench_myriapoda/_data/scenarios`` of the
build tree; ``bench_myriapoda.core.paths`` looks there when it is not running
from a checkout.  Everything else is declared in ``pyproject.toml``.
"""
from __future__ import annotations

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
DATA_DIRS = ("models", "scenarios")
DATA_PATTERN = "*.toml"


def _data_files() -> list[tuple[Path, Path]]:
    """(source file, path relative to bench_myriapoda/_data) for every shipped data file."""
    out = []
    for d in DATA_DIRS:
        for src in sorted((HERE / d).rglob(DATA_PATTERN)):
            out.append((src, src.relative_to(HERE)))
    return out


class BuildPyWithData(build_py):
    """build_py that also copies models/ and scenarios/ into bench_myriapoda/_data/."""

    def run(self):
        super().run()
        if getattr(self, "editable_mode", False):  # an editable install reads the checkout's folders directly
            return
        for src, rel in _data_files():
            dst = Path(self.build_lib) / "bench_myriapoda" / "_data" / rel
            dst.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dst)

    def get_outputs(self, include_bytecode=True):
        outs = list(super().get_outputs(include_bytecode))
        if not getattr(self, "editable_mode", False):
            outs += [str(Path(self.build_lib) / "bench_myriapoda" / "_data" / rel) for _, rel in _data_files()]
        return outs


setup(cmdclass={"build_py": BuildPyWithData})
