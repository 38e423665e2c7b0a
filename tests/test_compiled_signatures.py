"""Every project kernel the quick matrix compiles has exactly one signature (issue 13: the cold start compiles
"fewer, smaller signatures").  ``tests/kernel_signatures.py`` says how it is checked; it runs in a fresh
interpreter so that no other test's direct kernel calls add signatures."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def signature_report() -> dict:
    """``tests/kernel_signatures.py``'s report, run once for this module's tests (tens of CPU s)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")]))
    out = subprocess.run([sys.executable, str(REPO / "tests" / "kernel_signatures.py")], cwd=REPO, env=env,
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_quick_matrix_kernels_have_one_signature_each(signature_report):
    report = {k: v for k, v in signature_report.items() if k != "signatures"}
    assert report["kernels"] >= 100, report  # the groups ran and were re-typed (about 150 kernels)
    assert report["typed"] >= report["kernels"]
    assert report["extra"] == {}, report["extra"]
    # the per-body list stays exact: a kernel that no longer runs once per body model leaves it
    assert report["per_body"] == report["per_body_expected"], report["per_body"]


def test_recorded_compile_plans_hold_only_signatures_the_quick_matrix_compiles(signature_report):
    """A compile plan (``jit/compile_plans.json``, issue 31) recorded before a kernel changed names a
    signature nothing asks for any more: idle workers would compile it for nothing (or fail to, and the case
    compiles its own).  Every recorded project-kernel signature must be one the quick matrix's groups compile
    now; when this fails, record the plans again (``python -m bench_myriapoda.harness.cold_compile --record
    quick --write``, docs/guide/scheduling.md)."""
    import numba

    from bench_myriapoda.jit.compile_plan import shipped_plans

    data = shipped_plans()
    if numba.__version__.split(".")[:2] != data.numba_version.split(".")[:2]:
        pytest.skip(f"plans recorded with numba {data.numba_version}, not used with {numba.__version__}")
    now = set(signature_report["signatures"])
    recorded = {(name, ev[1]) for name, plan in data.plans.items() for ev in plan["events"]
                if ev[0].startswith("bench_myriapoda.")}
    assert len(recorded) >= 100  # six groups' kernels (about 60 each, many shared)
    stale = sorted(f"{name}: {sig}" for name, sig in recorded if sig not in now)
    assert stale == [], "\n".join(stale)
