"""Discoverable CLI: `keys` (every key --set accepts, described), `run --help`, `--version`,
"did you mean" suggestions, the tqdm progress bars, a closed pipe, labels in text output."""
from __future__ import annotations

import dataclasses
import io
import json
import subprocess
import sys
import time
from pathlib import Path

import pytest

from bench_myriapoda import __version__
from bench_myriapoda.cli import main, print_result_table
from bench_myriapoda.core import registry
from bench_myriapoda.core.config import apply_override, creature_names, resolve_case, scenario_paths
from bench_myriapoda.core.errors import InputError
from bench_myriapoda.core.schema import SECTIONS, TOP_LEVEL_SCALARS
from bench_myriapoda.harness.progress import MatrixProgress, ProgressBar
from bench_myriapoda.harness.runner import RunResult
from cli_argv import WORM_RUN, with_flags

ROOT = Path(__file__).resolve().parents[1]


def _accepted_by_set() -> set[str]:
    """Every candidate key of the config tables that apply_override (what --set calls) accepts.

    A key counts as accepted when --set does not reject it as unknown or as a name key; a value
    error for the probe value (an empty list default, say) still means the key itself is known.
    """
    registry.load_all()
    candidates = {k: (None, 1) for k in TOP_LEVEL_SCALARS}
    for section, cls in SECTIONS.items():
        for f in dataclasses.fields(cls):
            candidates[f"{section}.{f.name}"] = (None, f.default)
    for body, spec in registry.BODIES.items():
        for f in dataclasses.fields(spec.config_cls):
            candidates.setdefault(f"body.{f.name}", (body, f.default))
    # a gait's own keys (its GaitSpec.config_cls beyond GaitConfig's) are accepted for a case of that gait
    gait_of: dict[str, str] = {}
    for gait, spec in registry.GAITS.items():
        for f in dataclasses.fields(spec.config_cls):
            if f"gait.{f.name}" not in candidates:
                candidates[f"gait.{f.name}"] = (None, f.default)
                gait_of[f"gait.{f.name}"] = gait
    accepted = set()
    for key, (body, value) in candidates.items():
        value = list(value) if isinstance(value, tuple) else value
        layers = {"gait": {"name": gait_of[key]}} if key in gait_of else {}
        try:
            apply_override(layers, key, value, "--set", body or "massspring")
        except InputError as exc:
            if "unknown" in exc.message or "names are chosen" in exc.message:
                continue
        accepted.add(key)
    return accepted


def test_keys_json_lists_every_key_set_accepts_with_a_description(capsys):
    assert main(["keys", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["keys"]
    listed = {r["key"] for r in rows}
    accepted = _accepted_by_set()
    assert len(accepted) > 150
    assert listed == accepted, (sorted(accepted - listed), sorted(listed - accepted))
    for r in rows:
        assert r["description"].strip(), r["key"]
        assert {"type", "default", "allowed", "unit", "section"} <= set(r)
    by_key = {(r["key"], tuple(r.get("bodies", ()))): r for r in rows}
    mu = by_key[("friction.mu_transverse", ())]
    assert mu["default"] == 0.5 and mu["allowed"] == {"ge": 0.0} and mu["type"] == "a number"
    assert by_key[("scenario.slope_deg", ())]["unit"] == "deg"
    assert by_key[("gait.frequency_hz", ())]["unit"] == "Hz"
    # a body key names the body models that have it, and each of them really has it
    registry.load_all()
    for r in rows:
        for b in r.get("bodies", ()):
            assert r["key"][5:] in {f.name for f in dataclasses.fields(registry.BODIES[b].config_cls)}


def test_keys_text_and_one_section(capsys):
    assert main(["keys", "friction"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("[friction]") and "friction.mu_transverse" in out and "default 0.5" in out
    assert "gait." not in out
    assert main(["keys", "frictoin"]) == 2
    err = capsys.readouterr().err
    assert "did you mean 'friction'?" in err and len(err.strip().splitlines()) == 1


def test_run_help_lists_names_defaults_and_ends_with_examples(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["run", "--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    registry.load_all()
    for name in [*creature_names(), *registry.GAITS, *registry.BODIES, *scenario_paths()]:
        assert name in out, name
    assert "(default 0)" in out and "default: the body model's" in out and "scenario.duration_s" in out
    lines = [ln for ln in out.splitlines() if ln.strip()]
    tail = lines[lines.index("examples:") + 1:]
    assert len(tail) >= 3 and all(ln.strip().startswith(("bench-myriapoda run", "--set")) for ln in tail)


def test_version(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0 and capsys.readouterr().out.strip() == f"bench-myriapoda {__version__}"


RUN = WORM_RUN


@pytest.mark.parametrize("argv, want", [
    (["--creature", "wrom"], "'worm'"),
    (["--body", "masspring"], "'massspring'"),
    (["--gait", "rectilinaer"], "'rectilinear'"),
    (["--scenario", "flta"], "'flat'"),
    (["--set", "friction.mu_transversal=0.2"], "'friction.mu_transverse'"),
    (["--set", "frictoin.mu_transverse=0.2"], "'friction'"),
    (["--set", "body.stifness=3"], "'body.stiffness'"),
    (["--set", "durration=3"], "'duration'"),
])
def test_misspelt_names_and_keys_get_a_suggestion(capsys, argv, want):
    assert main(with_flags(RUN, argv)) == 2
    err = capsys.readouterr().err
    assert f"(did you mean {want}?)" in err and len(err.strip().splitlines()) == 1


def test_misspelt_key_in_a_file_and_a_matrix_name_get_a_suggestion(capsys, tmp_path):
    f = tmp_path / "c.toml"
    f.write_text("[creature]\nsegmnets = 5\n[bodies.massspring]\n")
    assert main(["run", "--creature", str(f), "--body", "massspring", "--scenario", "flat", "--no-store"]) == 2
    err = capsys.readouterr().err
    assert str(f) in err and "creature.segmnets: unknown key (did you mean 'creature.segments'?)" in err
    assert main(["matrix", "quik", "--out", str(tmp_path / "m")]) == 2
    assert "(did you mean 'quick'?)" in capsys.readouterr().err and not (tmp_path / "m").exists()


def test_text_output_prints_labels_instead_of_codes(capsys):
    case = resolve_case("worm", "massspring", "flat", duration=0.1)
    result = RunResult(case, "ok", {"brain_mode_final": 3.0, "speed_m_per_s": 0.25},
                       {"steps": 60, "steps_per_s": 1e4, "realtime_factor": 2.0, "compile_s": 1.0, "wall_s": 1.0},
                       extra={"labels": {"brain_mode_final": "WALK"}})
    print_result_table(result)
    lines = {ln.split()[0]: ln.split()[1:] for ln in capsys.readouterr().out.splitlines()[2:]}
    assert lines["brain_mode_final"] == ["WALK"]
    assert lines["speed_m_per_s"] == ["0.25"]


@pytest.mark.parametrize("argv", [["keys", "--json"], [*RUN, "--duration", "0.05", "--json"]])
def test_closed_pipe_exits_quietly(argv):
    """`bench-myriapoda ... --json | head -c 10`: the reader is gone before the JSON is written."""
    proc = subprocess.Popen([sys.executable, "-m", "bench_myriapoda.cli", *argv], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()  # no reader left: the first write to stdout fails with EPIPE
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=600) == 141
    assert "Traceback" not in err and "BrokenPipeError" not in err and err == ""


class _Tty(io.StringIO):
    def isatty(self):
        return True


def test_run_progress_bar_shows_simulated_time_and_rate_from_the_first_report():
    s = io.StringIO()
    bar = ProgressBar(enabled=True, label="worm/massspring", stream=s, total_s=10.0, dt=0.001)
    assert bar._bar is None  # nothing drawn, no clock started, while the kernels compile
    before = time.time()
    bar.update(0.1)
    assert bar._bar.start_t >= before  # the bar's clock (its rate and time left) starts at the first report
    for f in (0.3, 0.6, 1.0):
        time.sleep(0.11)
        bar.update(f)
    bar.close()
    out = s.getvalue()
    assert "worm/massspring" in out and "s simulated" in out and "steps/s" in out and "100%" in out
    assert "10/10 s simulated" in out
    silent = io.StringIO()
    ProgressBar(enabled=False, stream=silent, total_s=1.0, dt=0.1).update(0.5)
    assert silent.getvalue() == ""


def test_matrix_progress_counts_done_and_failed():
    s = io.StringIO()
    bar = MatrixProgress(True, 3, label="matrix tiny", stream=s)
    bar.case_done("worm/massspring", "ok")
    bar.case_done("worm/fem", "error", "boom")
    bar.case_done("snake/fem", "timeout")
    bar.close()
    out = s.getvalue()
    assert bar.done == 3 and bar.failed == 2
    assert "3/3 cases" in out and "failed 2" in out and "worm/fem: error (boom)" in out


def test_run_on_a_terminal_draws_the_bar_on_stderr(monkeypatch, capsys):
    tty = _Tty()
    monkeypatch.setattr(sys, "stderr", tty)
    assert main([*RUN, "--duration", "0.5"]) == 0
    assert "s simulated" in tty.getvalue() and "100%" in tty.getvalue()
    assert "s simulated" not in capsys.readouterr().out
