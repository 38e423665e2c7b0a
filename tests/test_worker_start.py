"""How the local matrix workers start (``jit.worker_start``): from a fork server where its Unix socket fits, spawned
where the temporary directory's path is too long for one.  Under a long ``$TMPDIR`` (a test's own folder once the
pytest base directory's number reached three digits) ``bench-myriapoda matrix`` stopped before its first case with a
traceback, "OSError: AF_UNIX path too long"."""
from __future__ import annotations

import os
import subprocess
import sys
import tempfile

from bench_myriapoda.jit import worker_start as W


def test_the_socket_limit_is_counted_in_bytes_to_the_last_one():
    fits = "/" + "t" * (W.SOCKET_PATH_MAX - W.FORKSERVER_SOCKET_TAIL - 1)  # exactly 107 bytes with the socket's tail
    assert W.forkserver_socket_fits(fits) and not W.forkserver_socket_fits(fits + "t")
    assert not W.forkserver_socket_fits("/" + "é" * 38)  # 77 bytes in UTF-8, 39 characters


def test_a_long_temporary_directory_starts_the_workers_by_spawning(tmp_path, monkeypatch):
    monkeypatch.delenv(W.ENV_START, raising=False)
    long_dir = tmp_path / ("d" * 80)
    long_dir.mkdir()
    monkeypatch.setenv("TMPDIR", str(long_dir))
    monkeypatch.setattr(tempfile, "tempdir", None)  # re-read TMPDIR
    assert W.start_method() == "spawn"
    monkeypatch.setenv("TMPDIR", "/tmp")
    monkeypatch.setattr(tempfile, "tempdir", None)
    assert W.forkserver_socket_fits()  # /tmp leaves the socket room: the start method is not forced to spawn


def test_a_matrix_runs_under_a_temporary_directory_too_long_for_a_socket(tmp_path):
    long_dir = tmp_path / ("d" * 90)
    long_dir.mkdir()
    m = tmp_path / "m.toml"
    m.write_text('[matrix]\nname = "longtmp"\ncreatures = ["worm"]\nbodies = ["massspring"]\nscenarios = ["flat"]\n'
                 'duration = 0.05\ngrid = { "friction.mu_transverse" = [0.2, 0.5] }\n')
    env = {k: v for k, v in os.environ.items() if k != W.ENV_START}
    env["TMPDIR"] = str(long_dir)
    code = "import sys; from bench_myriapoda.cli import main; sys.exit(main())"
    p = subprocess.run([sys.executable, "-c", code, "matrix", str(m), "--workers", "2", "--out", str(tmp_path / "o")],
                       cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr[-3000:]
    assert "AF_UNIX" not in p.stderr and (tmp_path / "o" / "results.sqlite").is_file()
