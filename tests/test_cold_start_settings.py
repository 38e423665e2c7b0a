"""Process settings that make a cold start (issue 13) cheaper without touching any result.

* Importing the package turns numba's coloured error messages off (``NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING``):
  numba builds one message per typing template that does not match, and colouring each one runs colorama's
  set-up; a user's own setting of the variable wins.
* A matrix worker (``executors._worker_main``) runs Python's full garbage collections ten times less often
  (``WORKER_GC_THRESHOLDS``) than the default.

Each check runs in a fresh interpreter: both settings act when numba or a worker starts.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]


def _python(code: str, **env) -> str:
    e = {k: v for k, v in os.environ.items() if k != "NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING"}
    e.update(env)
    out = subprocess.run([sys.executable, "-c", code], cwd=REPO, env=e, capture_output=True, text=True, check=True)
    return out.stdout.strip()


def test_import_turns_error_highlighting_off():
    # without colorama numba never highlights, so the check would pass whatever the package did
    pytest.importorskip("colorama")
    code = "import bench_myriapoda, numba.core.errors as e; print(type(e.termcolor()).__name__)"
    assert _python(code) == "NOPColorScheme"


def test_user_setting_of_highlighting_wins():
    pytest.importorskip("colorama")
    code = "import bench_myriapoda, numba.core.errors as e; print(type(e.termcolor()).__name__)"
    assert _python(code, NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING="") == "HighlightColorScheme"


def test_worker_collects_old_generation_less_often():
    code = (
        "import gc, json\n"
        "from bench_myriapoda.harness import executors as ex\n"
        "class Conn:\n"
        "    def recv(self): return None\n"  # no case: the worker sets up and ends
        "default = gc.get_threshold()\n"
        "ex._worker_main(Conn())\n"
        "print(json.dumps([default, gc.get_threshold(), ex.WORKER_GC_THRESHOLDS]))\n"
    )
    import json

    default, applied, declared = json.loads(_python(code))
    assert applied == declared
    assert applied[:2] == default[:2]  # young generations as before
    assert applied[2] >= 10 * default[2]  # full collections at least ten times rarer
