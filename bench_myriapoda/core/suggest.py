"""'Did you mean ...' for a misspelt name or key in an error message."""
from __future__ import annotations

import difflib
from typing import Iterable


def did_you_mean(word: str, choices: Iterable[str], cutoff: float = 0.6) -> str:
    """`` (did you mean 'worm'?)`` for the closest of ``choices`` to ``word``, or ``""`` when none is close.

    A dotted key (``friction.mu_transversal``) is also matched on its last part, so a
    misspelt key finds its neighbour even when the section name makes the strings long.
    """
    choices = [c for c in dict.fromkeys(choices) if c != word]
    if not word or not choices:
        return ""
    best = difflib.get_close_matches(word, choices, n=1, cutoff=cutoff)
    if not best and "." in word:
        tail = word.rsplit(".", 1)[1]
        tails = {c.rsplit(".", 1)[-1]: c for c in choices if c.startswith(word.rsplit(".", 1)[0] + ".")}
        close = difflib.get_close_matches(tail, list(tails), n=1, cutoff=cutoff)
        best = [tails[close[0]]] if close else []
    return f" (did you mean {best[0]!r}?)" if best else ""
