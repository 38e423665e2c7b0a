"""The documentation (issue 29): the README as a front door, the reference generated from the code, the
tutorials' code, the gallery's examples, the metric table, and the command line's help.

The Sphinx build itself (warnings as errors) runs in ``.ci/run`` after the tests.
"""
from __future__ import annotations

import argparse
import os
import re
import runpy
import shlex
import sqlite3
import sys
import tomllib
from pathlib import Path

import pytest

from bench_myriapoda.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
README = ROOT / "README.md"
sys.path.insert(0, str(DOCS / "_ext"))

import reference_pages  # noqa: E402

EXAMPLES = sorted((ROOT / "examples").glob("plot_*.py"))
TUTORIALS = sorted(p for p in (DOCS / "tutorials").glob("*.md") if p.name != "index.md")
# guide pages whose Python blocks are runnable too (the others show fragments of output or options)
RUNNABLE_GUIDES = [DOCS / "guide" / "first-run.md", DOCS / "guide" / "results-store.md", DOCS / "guide" / "python-api.md"]
GENERATED = {DOCS / p for p in reference_pages.GENERATED}
PAGES = sorted(p for p in DOCS.rglob("*.md") if p not in GENERATED and "_build" not in p.parts)
FENCE = re.compile(r"^```(\w+)[^\n]*\n(.*?)^```", re.S | re.M)


def code_blocks(path: Path) -> list[tuple[str, str]]:
    """``[(language, code), ...]`` of every fenced block of a Markdown page, in order."""
    return [(m.group(1), m.group(2)) for m in FENCE.finditer(path.read_text(encoding="utf-8"))]


def shell_commands(code: str) -> list[str]:
    """The commands of a shell block, continuation lines joined."""
    return [c.strip() for c in code.replace("\\\n", " ").splitlines() if c.strip() and not c.startswith("#")]


def cli_argv(command: str) -> list[str] | None:
    """The arguments of a ``bench-myriapoda ...`` command line (comments and anything after a pipe dropped),
    or None for another command."""
    words = shlex.split(command, comments=True)
    if not words or words[0] != "bench-myriapoda":
        return None
    return words[1:words.index("|")] if "|" in words else words[1:]


# --------------------------------------------------------------------------- README

def test_readme_is_a_front_door_of_at_most_200_lines():
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 200
    for section in ("## Set-up", "## From Python", "## Commands", "## Documentation", "## How to cite"):
        assert section in text, section
    assert "doi.org/10.1145/2485895.2485899" in text and "doi.org/10.1145/378456.378508" in text
    assert "python3 -m sphinx -W --keep-going -b html docs docs/_build/html" in text


def test_readme_has_exactly_the_two_set_up_commands_ci_extracts():
    text = README.read_text(encoding="utf-8")
    for marker, command in (("<!-- main-command -->", "python3 -m pip install -e . && bench-myriapoda"),
                            ("<!-- test-command -->", 'python3 -m pip install -e ".[test]" && python3 -m pytest')):
        assert text.count(marker) == 1
        block = text.split(marker, 1)[1].split("```bash\n", 1)[1].split("```", 1)[0]
        assert block.strip() == command
    # .ci/run's extraction, as it is written there
    ci = (ROOT / ".ci" / "run").read_text()
    assert "/<!-- test-command -->/{found=1; next} found && /^python3 /{print; exit}" in ci
    assert "python3 -m sphinx -W --keep-going -b html docs docs/_build/html" in ci


def test_readme_links_and_pictures_exist():
    text = README.read_text(encoding="utf-8")
    targets = re.findall(r"\]\(([^)#]+?)\)", text)
    local = [t for t in targets if not t.startswith(("http://", "https://"))]
    assert local, "the README links into the documentation"
    for t in local:
        assert (ROOT / t).exists(), t
    assert any(t.endswith(".png") for t in local)


def test_the_command_table_lists_every_subcommand():
    text = README.read_text(encoding="utf-8")
    table = text.split("## Commands", 1)[1].split("\n\n", 2)[1]
    for name in reference_pages.cli_commands():
        if name:
            assert f"`bench-myriapoda {name}" in table, name


# --------------------------------------------------------------------------- the generated reference

def _names_in_first_column(page: str) -> list[str]:
    return re.findall(r"^\| `([^`]+)`", page, re.M)


def test_the_reference_lists_every_set_key():
    from bench_myriapoda.core.keys import config_keys

    page = reference_pages.keys_page()
    assert sorted(set(_names_in_first_column(page))) == sorted({r["key"] for r in config_keys()})


def test_the_reference_lists_every_metric_of_the_table():
    from bench_myriapoda.metrics.definitions import METRICS

    page = reference_pages.metrics_page()
    names = _names_in_first_column(page)
    assert sorted(names) == sorted(METRICS) and len(names) == len(set(names))
    for m in METRICS.values():
        assert m.unit and m.definition, m.name


def test_the_reference_lists_every_validate_check():
    from bench_myriapoda.validation.registry import CHECKS

    page = reference_pages.checks_page()
    assert _names_in_first_column(page) == [c.name for c in CHECKS]
    for family in {c.family for c in CHECKS}:
        assert f"## `{family}`" in page


def test_the_reference_lists_every_subcommand_with_its_help():
    page = reference_pages.cli_page()
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    listed = re.findall(r"^## `bench-myriapoda ?([a-z-]*)`", page, re.M)
    assert listed == ["", *sub.choices]
    for name in sub.choices:
        assert f"usage: bench-myriapoda {name}" in page


def test_the_validation_results_page_comes_from_a_recorded_run():
    runs = reference_pages.validation_runs()
    assert runs, "docs/_data/ holds no validate --json output"
    page = reference_pages.validation_results_page()
    from bench_myriapoda.validation.registry import CHECKS

    names = {c.name for c in CHECKS}
    for _, doc in runs:
        for r in doc["rows"]:
            assert r["check"] in names, f"{r['check']}: recorded but no longer in the registry; rerun validate"
            assert f"`{r['check']}`" in page


def test_the_api_page_documents_every_public_name():
    import bench_myriapoda

    page = (DOCS / "reference" / "api.md").read_text()
    for name in bench_myriapoda.__all__:
        if name != "__version__":
            assert f"bench_myriapoda.api.{name}" in page, name


# --------------------------------------------------------------------------- the metric table and the store

# metric names the code writes from a template rather than as a literal
TEMPLATES = {"brain_avoidance_fraction": 'f"brain_{name}_fraction"', "brain_trophotropism_fraction":
             'f"brain_{name}_fraction"'}


def test_every_metric_of_the_table_is_written_by_the_code():
    from bench_myriapoda.metrics.definitions import METRICS

    sources = "\n".join(p.read_text() for p in (ROOT / "bench_myriapoda").rglob("*.py")
                        if p.name != "definitions.py")
    for name in METRICS:
        assert f'"{name}"' in sources or TEMPLATES.get(name, "\0") in sources, f"{name}: no code writes it"


@pytest.mark.slow
def test_every_metric_the_store_holds_is_in_the_table(tmp_path):
    """Legless and legged runs on every body model, a suspended one and a stable-dt search, stored:
    each metric name in the store's ``metrics`` table (and each metric column of ``load_results``) has a
    row in the metric table."""
    import bench_myriapoda as bm
    from bench_myriapoda.metrics.definitions import METRICS

    store = tmp_path / "r.sqlite"
    for creature, body, scenario, duration in (("worm", "massspring", "flat", 2.0), ("worm", "fem", "flat", 1.0),
                                               ("worm", "hybrid", "flat", 1.0),
                                               ("centipede", "hybrid", "walk", 2.5),
                                               ("centipede", "hybrid", "hang", 1.0)):
        r = bm.run(creature, body, scenario, duration=duration, store=store)
        assert r.status == "ok", (creature, body, r.message)
    assert main(["stable-dt", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duration",
                 "0.3", "--max-runs", "4", "--store", str(store)]) == 0
    stored = {n for (n,) in sqlite3.connect(store).execute("SELECT DISTINCT name FROM metrics")}
    assert {"stable_dt_max_s", "min_J", "duty_factor_mean", "curvature_amplitude", "hanging_elongation_m",
            "coupling_residual_max_m"} <= stored
    assert not stored - set(METRICS), f"stored but not in metrics/definitions.py: {sorted(stored - set(METRICS))}"
    df = bm.load_results(store)
    assert set(METRICS) & set(df.columns) == stored


# --------------------------------------------------------------------------- tutorials and guide pages

@pytest.mark.slow
@pytest.mark.parametrize("page", TUTORIALS + RUNNABLE_GUIDES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_code_block_of_the_page_runs_or_parses(page, tmp_path, monkeypatch):
    """Python blocks run in order in one namespace (in a scratch directory); every ``bench-myriapoda``
    command of a shell block parses with the command line's parser; TOML blocks parse, and a matrix
    resolves every case. Other shell lines (pip, pytest, dask) and YAML are shown, not run."""
    from bench_myriapoda.harness.matrix import expand_matrix

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    blocks = code_blocks(page)
    assert blocks, page
    namespace = {"__name__": "tutorial"}
    parser = build_parser()
    for i, (lang, code) in enumerate(blocks):
        if lang == "python":
            exec(compile(code, f"{page.name}:block{i}", "exec"), namespace)
        elif lang == "bash":
            for command in shell_commands(code):
                argv = cli_argv(command)
                if argv is not None and "--help" not in argv and "--version" not in argv:
                    parser.parse_args(argv or ["quick"])
        elif lang == "toml":
            data = tomllib.loads(code)
            if "matrix" in data:
                path = tmp_path / f"block{i}.toml"
                path.write_text(code)
                assert expand_matrix(path).cases
        else:
            assert lang in ("yaml", "text", "bibtex"), (page.name, lang)


@pytest.mark.parametrize("page", PAGES + [README], ids=lambda p: str(p.relative_to(ROOT)))
def test_every_command_line_on_the_page_parses(page):
    """Every ``bench-myriapoda`` command in a shell block of any documentation page (and the README) is one
    the command line's parser accepts: no removed flag, no misspelt subcommand."""
    parser = build_parser()
    for lang, code in code_blocks(page):
        if lang != "bash":
            continue
        for command in shell_commands(code):
            argv = cli_argv(command)
            if argv is None or "--help" in argv or "--version" in argv:
                continue
            try:
                parser.parse_args(argv or ["quick"])
            except Exception as exc:  # InputError: one line naming the flag
                pytest.fail(f"{page.name}: {command}: {exc}")


# --------------------------------------------------------------------------- the gallery

@pytest.mark.slow
@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_every_gallery_example_runs_and_draws_its_figure(example, tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    text = example.read_text()
    assert re.match(r'"""\n[^\n]+\n=+\n', text), "a gallery example starts with a title (sphinx-gallery)"
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("BENCH_MYRIAPODA_EXAMPLE_SCALE", "0.5")
    monkeypatch.setattr(plt, "show", lambda *a, **k: None)
    plt.close("all")
    runpy.run_path(str(example), run_name="__main__")
    figures = [plt.figure(n) for n in plt.get_fignums()]
    assert figures, "the example drew no figure"
    for k, fig in enumerate(figures):
        assert any(ax.has_data() for ax in fig.axes)
        out = tmp_path / f"figure{k}.png"
        fig.savefig(out)
        assert out.stat().st_size > 10_000
    plt.close("all")


def test_there_are_at_least_eight_gallery_examples_and_the_two_scripts():
    assert len(EXAMPLES) >= 8
    assert (ROOT / "examples" / "gaits_top_view.py").exists() and (ROOT / "examples" / "speed_controller.py").exists()


# --------------------------------------------------------------------------- command-line help

def _help(capsys, *argv) -> str:
    with pytest.raises(SystemExit) as exc:
        main([*argv, "--help"])
    assert exc.value.code == 0
    return capsys.readouterr().out


def test_every_subcommand_help_has_a_paragraph_and_ends_with_examples(capsys):
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for name in sub.choices:
        out = _help(capsys, name)
        head = out.split("\n\n")[1]
        assert len(head.split()) >= 25, (name, head)   # a paragraph, not a line
        tail = out[out.rindex("examples:"):].splitlines()[1:]
        assert tail and all(ln.strip().startswith(("bench-myriapoda", "--set")) for ln in tail if ln.strip()), name


def test_validate_help_lists_every_check_family_and_the_run_times(capsys):
    from bench_myriapoda.validation.registry import CHECKS

    out = _help(capsys, "validate")
    for c in CHECKS:
        assert c.name in out
    for family in {c.family for c in CHECKS}:
        assert family in out
    assert "--quick runs" in out and "full set" in out and "minutes" in out


@pytest.mark.parametrize("argv,suggestion,where", [
    (["rn"], "(did you mean 'run'?)", "argument command"),
    (["valdiate", "--quick"], "(did you mean 'validate'?)", "argument command"),
    (["run", "--creature", "worm", "--body", "massspring", "--scenario", "flat", "--duraton", "3"],
     "(did you mean '--duration'?)", "run: unrecognized arguments"),
    (["validate", "--quik"], "(did you mean '--quick'?)", "validate: unrecognized arguments"),
])
def test_a_misspelt_subcommand_or_flag_gets_a_suggestion_and_the_program_is_named_once(capsys, argv, suggestion,
                                                                                       where):
    assert main(argv) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and suggestion in lines[0] and where in lines[0], lines
    assert lines[0].count("bench-myriapoda") == 1 or "choose from" in lines[0]
    assert lines[0].startswith("bench-myriapoda: error: ")
    assert "bench-myriapoda: error: bench-myriapoda" not in lines[0]
