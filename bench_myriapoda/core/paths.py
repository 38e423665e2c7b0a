"""Where the data folders (models/, scenarios/) are.

They are data, not Python packages (ARCHITECTURE.md): in a source checkout they
sit beside ``bench_myriapoda/``; ``BENCH_MYRIAPODA_ROOT`` points elsewhere.
"""
from __future__ import annotations

import os
from pathlib import Path


def project_root() -> Path:
    env = os.environ.get("BENCH_MYRIAPODA_ROOT")
    if env:
        return Path(env)
    return Path(__file__).resolve().parents[2]


def models_dir() -> Path:
    return project_root() / "models"


def scenarios_dir() -> Path:
    return project_root() / "scenarios"
