"""``python -m bench_myriapoda.cli``: the ``bench-myriapoda`` command."""
import sys

from .program import main

sys.exit(main())
