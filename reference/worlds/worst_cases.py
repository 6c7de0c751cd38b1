"""The worst worlds found: the exhaustive and adversarial argmax worlds of ``topomark worst-case`` (thesis §7.2).

The thesis asks (§7.2) whether the worst cases of its bounds
exist and on which worlds.  ``topomark worst-case`` answers it for small sizes
exactly and past them by search; the worlds it found are kept here, with the
start the worst run began from, as stress cases: the conformance suites run
them (:mod:`topomark.reference.oracle.conformance.cases`) and
``topomark world worst-case:case=NAME`` generates them.

Each world is a ``topomark/world@1`` file in ``worst/``; ``worst/index.json``
says, per name, which algorithm it is worst for, how it was found
(``exhaustive``: the largest cost over every world of its size and degree
bound, proved by enumeration; ``search``: the largest found, a lower bound on
the worst case), its size and degree bound, and the cost.  An entry with
``"stress": false`` (a world too large to run checked in every suite, n ≥ 30, or kept for the report only)
is kept for the worst-case report to name, and left out of the stress cases; so is every world a search found
for a footprint search of §6.2.1 (their suites keep the exhaustive worst worlds).

Examples
--------
>>> w = worst_case_world("basic-n5-d4")
>>> (w.n, w.m, w.start is not None)
(5, 10, True)
>>> WORST_CASES["basic-n5-d4"]["how"], WORST_CASES["basic-n5-d4"]["cost"]
('exhaustive', 89)
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World
from topomark.spec.worldfile import world_from_json

__all__ = ["WORST_DIR", "WORST_CASES", "worst_case_world", "worst_case_worlds", "describe"]

WORST_DIR = Path(__file__).resolve().parent / "worst"
WORST_CASES: dict[str, dict[str, Any]] = json.loads((WORST_DIR / "index.json").read_text(encoding="utf-8"))
"""name ↦ {"algorithm", "how", "n", "m", "max_degree", "cost", "file"} and, for a world left out of the stress
cases, ``"stress": false``."""


def worst_case_world(case: str) -> World:
    """The worst world ``case`` of :data:`WORST_CASES`, with its start."""
    if case not in WORST_CASES:
        raise InvalidInput(f"unknown worst-case world {case!r}; known: {', '.join(WORST_CASES)}")
    return world_from_json(json.loads((WORST_DIR / WORST_CASES[case]["file"]).read_text(encoding="utf-8")))


def describe(name: str) -> str:
    """One line saying what the world is worst for, and how that is known."""
    e = WORST_CASES[name]
    how = ("the largest cost over every world of its size (exhaustive)" if e["how"] == "exhaustive"
           else "the largest cost the adversarial search found (a lower bound)")
    return (f"worst case of {e['algorithm']} at n = {e['n']}, degree <= {e['max_degree']}: cost {e['cost']}, "
            f"{how}")


def worst_case_worlds(algorithm: str | None = None) -> list[tuple[str, str, World]]:
    """(name, description, world) of every kept worst world that is a stress case, or those found for
    ``algorithm``."""
    return [(f"worst-{name}", describe(name), worst_case_world(name)) for name, e in WORST_CASES.items()
            if (algorithm is None or e["algorithm"] == algorithm) and e.get("stress", True)]
