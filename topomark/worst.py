"""The worst cost of an algorithm, from Python (thesis §7.2).

:func:`worst_case` is ``topomark worst-case``: the algorithm runs from every start of every embedded world up
to ``max_vertices`` vertices and degree ``max_degree`` (one world per isomorphism class, one start per orbit
of its automorphisms), unchecked, with a seeded sample and every argmax re-run checked; the rows give per n
the largest cost, cost per edge and cost ÷ the algorithm's exact bound, with the world and start that reach
it — exact for those sizes.  :func:`adversarial_search` is ``topomark worst-case --search``: a seeded local
search past them, whose best is a lower bound on the worst case.

Examples
--------
>>> rows = worst_case("basic", max_vertices=4, max_degree=3)
>>> [(r["n"], r["max_cost"]) for r in rows]
[(2, 1), (3, 3), (4, 17)]
>>> rows[-1]["argmax"]["start"]
{'at': 'v0', 'facing': 'v2'}
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from topomark.reference.worstcase.exhaustive import Setup
from topomark.reference.worstcase.result import rows
from topomark.reference.worstcase.resumable import worst_case as _worst_case
from topomark.reference.worstcase.search import SearchResult, adversarial_search

__all__ = ["worst_case", "adversarial_search", "SearchResult"]


def worst_case(algorithm: str = "basic", max_vertices: int = 5, max_degree: int = 4, *,
               lighthouse: str | None = None, jobs: int = 1, sample: float = 0.001, seed: int = 0,
               shards: str | Path | None = None) -> list[dict[str, Any]]:
    """The exhaustive worst case of ``algorithm``, one row per n (the ``per_n`` of ``topomark worst-case
    --json``).  ``shards`` keeps the tasks on disk so a second call resumes; without it they live in a
    temporary directory.  A checked re-run that disagrees with its unchecked run raises
    :class:`~topomark.spec.errors.TopomarkFault`; runs that did not map their world are counted in each row's
    ``outcomes``."""
    setup = Setup(algorithm, lighthouse, sample=sample, seed=seed)
    degree = min(max_degree, max_vertices - 1)
    with tempfile.TemporaryDirectory(prefix="topomark-worst-case-") as scratch:
        found = _worst_case(setup, max_vertices, degree, Path(shards or scratch), jobs=jobs)
    return rows(found["tallies"], degree, setup.spec)
