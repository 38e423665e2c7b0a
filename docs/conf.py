"""Sphinx configuration: MyST Markdown, the PyData theme, autodoc with NumPy-style docstrings (napoleon),
sphinx-gallery for examples/, and reference pages generated from the code (``_ext/reference_pages.py``).

Build (warnings are errors): ``python3 -m sphinx -W --keep-going -b html docs docs/_build/html``.
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))          # this checkout's package, whatever is installed
sys.path.insert(0, str(DOCS / "_ext"))

import reference_pages  # noqa: E402

import bench_myriapoda  # noqa: E402

reference_pages.write_all(DOCS)

# The README's picture (docs/_static/scorecard.png) is the main job's scorecard: re-made here from reports/quick
# when `bench-myriapoda` has written it; without it (a fresh clone, CI) the committed picture stays, so the build
# never runs the main job and never fails for want of it (tools/make_readme_picture.py).
sys.path.insert(0, str(ROOT / "tools"))
import make_readme_picture  # noqa: E402

make_readme_picture.refresh(ROOT / "reports" / "quick", DOCS / "_static" / "scorecard.png")

project = "bench-myriapoda"
author = "the bench-myriapoda developers"
copyright = "2026, the bench-myriapoda developers"
release = version = bench_myriapoda.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.viewcode",
    "sphinx_gallery.gen_gallery",
    "field_docstrings",
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
exclude_patterns = ["_build", "_data", "_ext", "sg_execution_times.rst", "auto_examples/sg_execution_times.rst"]
myst_enable_extensions = ["colon_fence", "deflist"]
myst_heading_anchors = 3

# autodoc: NumPy-style docstrings through napoleon; signatures keep the annotations as written
autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_typehints_format = "short"
napoleon_numpy_docstring = True
napoleon_google_docstring = False

# a broken cross-reference is an error; types from other libraries are not documented here
nitpicky = True
nitpick_ignore_regex = [
    (r"py:.*", r"(np|numpy|pd|pandas|numba|sqlite3|pathlib|os|typing|collections|argparse|dataclasses)\..*"),
    (r"py:class", r"(Path|Any|Callable|Sequence|Iterable|Mapping|ndarray|DataFrame|NDArray|optional|"
                  r"array_like|callable|PathLike|Series|Case|Result|RunResult|Check|Outcome|Context)"),
    (r"py:class", r"bench_myriapoda\..*"),
    (r"py:class", r"InputError"),            # api.run's docstring names it as the module imports it
    (r"py:meth", r"Controller\.fill"),      # protocols' module docstring: OpenLoopController.fill
]

# sphinx-gallery: run every script in examples/ and put its figure in the gallery. BENCH_MYRIAPODA_EXAMPLE_SCALE
# (see examples/README.txt) shortens the runs; the documentation build uses the same reduced durations as the
# test that runs the examples, unless it is set already.
os.environ.setdefault("BENCH_MYRIAPODA_EXAMPLE_SCALE", "0.5")
os.environ.setdefault("MPLBACKEND", "agg")
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": str(DOCS / "auto_examples"),
    "filename_pattern": r"/plot_",
    # the two scripts that predate the gallery keep their command lines; they are not gallery examples
    "ignore_pattern": r"__init__\.py|gaits_top_view\.py|speed_controller\.py",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
}

html_theme = "pydata_sphinx_theme"
html_title = "bench-myriapoda"
html_static_path = ["_static"]
html_css_files = ["custom.css"]
html_theme_options = {
    "navigation_depth": 2,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
}
html_show_sourcelink = False
