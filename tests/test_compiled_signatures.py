"""Every project kernel the quick matrix compiles has exactly one signature (issue 13: the cold start compiles
"fewer, smaller signatures").  ``tests/kernel_signatures.py`` says how it is checked; it runs in a fresh
interpreter so that no other test's direct kernel calls add signatures."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def test_quick_matrix_kernels_have_one_signature_each():
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")]))
    out = subprocess.run([sys.executable, str(REPO / "tests" / "kernel_signatures.py")], cwd=REPO, env=env,
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr[-3000:]
    report = json.loads(out.stdout.strip().splitlines()[-1])
    assert report["kernels"] >= 100, report  # the groups ran and were re-typed (about 150 kernels)
    assert report["typed"] >= report["kernels"]
    assert report["extra"] == {}, report["extra"]
    # the per-body list stays exact: a kernel that no longer runs once per body model leaves it
    assert report["per_body"] == report["per_body_expected"], report["per_body"]
