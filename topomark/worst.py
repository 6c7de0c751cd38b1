"""The worst cost of an algorithm, from Python (thesis §7.2).

:func:`worst_case` is ``topomark worst-case``: the algorithm runs from every start of every embedded world up
to ``max_vertices`` vertices and degree ``max_degree`` (one world per isomorphism class, one start per orbit
of its automorphisms), unchecked, with a seeded sample and every argmax re-run checked; the rows give per n
the largest cost, cost per edge and cost ÷ the algorithm's exact bound, with the world and start that reach
it — exact for those sizes.  :func:`adversarial_search` is ``topomark worst-case --search``: a seeded local
search past them, whose best is a lower bound on the worst case.

Both check every argument before any work (:mod:`topomark.arguments`), with the command's bounds: a bad one —
an unknown algorithm or lighthouse, a size past what the search can hold, NaN for the sample — is
:class:`~topomark.spec.errors.InvalidInput` naming it, never a run with no rows.

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
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from topomark.arguments import (callback, flag, fraction, integer, keywords_checked, largest_degree,
                                optional_text, path, text)
from topomark.exploration import policies_of
from topomark.reference.cli.args import MAX_JOBS, SEED_DIGITS
from topomark.reference.explorers.policies import Policies
from topomark.reference.worstcase.exhaustive import Setup
from topomark.reference.worstcase.limits import (MAX_EVALUATIONS, MAX_EXHAUSTIVE, MAX_SEARCH_PRODUCT,
                                                  MAX_SEARCH_VERTICES)
from topomark.reference.worstcase.result import rows
from topomark.reference.worstcase.resumable import worst_case as _worst_case
from topomark.reference.worstcase.search import AdversarialResult, adversarial_search as _adversarial_search
from topomark.spec.world import MAX_DEGREE

__all__ = ["worst_case", "adversarial_search", "AdversarialResult"]

MAX_SEED = 10 ** SEED_DIGITS - 1
"""The largest seed, as ``--seed`` takes it (at most 18 digits)."""



@keywords_checked
def worst_case(algorithm: str = "basic", max_vertices: int = 5, max_degree: int = 4, *,
               lighthouse: str | None = None, policies: Policies | Mapping[str, str] | None = None, jobs: int = 1,
               sample: float = 0.001, seed: int = 0, shards: str | Path | None = None) -> list[dict[str, Any]]:
    """The exhaustive worst case of ``algorithm``, one row per n (the ``per_n`` of ``topomark worst-case
    --json``).  ``shards`` keeps the tasks on disk so a second call resumes (running again a seeded sample of the kept
    tasks and those holding a maximum: a task file edited since it was written raises InvalidInput naming it); without it they live in a
    temporary directory.  A checked re-run that disagrees with its unchecked run raises
    :class:`~topomark.spec.errors.TopomarkFault`; runs that did not map their world are counted in each row's
    ``outcomes``.

    Raises :class:`~topomark.spec.errors.InvalidInput`, before any run, for an unknown algorithm, lighthouse
    or policy (``policies`` as for :func:`topomark.explore`), a lighthouse given to a kit algorithm,
    ``max_vertices`` outside 2 to 8 (the exhaustive search's sizes: past them use :func:`adversarial_search`),
    ``max_degree`` < 1 or too large for the worlds of ``max_vertices`` vertices to fit in memory (at n = 7 and
    8, at most 4; ``topomark worst-case --help`` gives the table), ``jobs`` outside 1 to 256, ``sample`` not a number from 0 to 1, a seed of more than
    18 digits, a ``shards`` that is not a path, and any argument of the wrong type (a bool or a str for an
    int, NaN); a misspelt keyword raises its subclass :class:`~topomark.spec.errors.InvalidKeyword`.
    """
    setup = _setup(algorithm, lighthouse, policies, sample, seed)
    max_vertices = integer("max_vertices", max_vertices, 2, MAX_EXHAUSTIVE,
                           " (the exhaustive search's sizes; adversarial_search looks past them)")
    max_degree = largest_degree(max_vertices, integer("max_degree", max_degree, 1, MAX_DEGREE))
    jobs = integer("jobs", jobs, 1, MAX_JOBS, " worker processes")
    folder = None if shards is None else path("shards", shards)
    degree = min(max_degree, max_vertices - 1)
    with tempfile.TemporaryDirectory(prefix="topomark-worst-case-") as scratch:
        found = _worst_case(setup, max_vertices, degree, Path(folder or scratch), jobs=jobs)
    return rows(found["tallies"], degree, setup.spec)


def _setup(algorithm: Any, lighthouse: Any, policies: Any, sample: Any, seed: Any) -> Setup:
    """The shared setup of a worst case, every part checked as ``topomark worst-case`` checks its options."""
    from topomark.reference.algorithms.registry import algorithm_spec

    spec = algorithm_spec(text("algorithm", algorithm, "an algorithm's name"))
    lighthouse = optional_text("lighthouse", lighthouse, "a lighthouse strategy's name")
    spec.lighthouse_for(lighthouse)  # an unknown lighthouse, or one for a kit algorithm
    chosen = policies_of(policies, spec.name) or spec.policies()
    return Setup(spec.name, lighthouse, (chosen.edge, chosen.hypothesis, chosen.path), fraction("sample", sample),
                 integer("seed", seed, -MAX_SEED, MAX_SEED))


@keywords_checked
def adversarial_search(algorithm: str = "basic", n: int = 20, max_degree: int = 4, objective: str = "cost",
                       evaluations: int = 200, seed: int = 0, lighthouse: str | None = None,
                       policies: Policies | Mapping[str, str] | None = None, family: str | None = None,
                       progress: Callable[[int, float], None] | None = None,
                       baseline: bool = True) -> AdversarialResult:
    """Search for a world (start included) of ``n`` vertices and degrees <= ``max_degree`` maximising
    ``objective`` (``cost``, ``cost-per-m`` or ``ratio``) for ``algorithm``, in ``evaluations`` runs
    (``topomark worst-case --search``); with ``baseline``, the best of as many random worlds is kept in
    ``.random``.  ``family="lattice-hole"`` searches hole patterns of a lattice instead.  ``policies`` is a
    Policies or a mapping, as for :func:`topomark.explore`.  ``progress(evaluations_done, best_score)`` is
    called after about every 1/20 of the budget.

    Raises :class:`~topomark.spec.errors.InvalidInput`, before any run, for an unknown algorithm, lighthouse,
    policy, objective or family, ``n`` outside 3 to 500, ``max_degree`` outside 2 to the largest degree a
    world can have, ``evaluations`` outside 1 to 100,000 or ``evaluations × n`` past 2,000,000 (the search
    holds a quarter of its runs' worlds at once: the bounds of ``topomark worst-case --search``), a seed of more than 18 digits,
    a ``progress`` that is not callable, and any argument of the wrong type; a misspelt keyword raises its
    subclass :class:`~topomark.spec.errors.InvalidKeyword`.
    """
    setup = _setup(algorithm, lighthouse, policies, 0.0, seed)
    n = integer("n", n, 3, MAX_SEARCH_VERTICES, " vertices")
    evaluations = integer("evaluations", evaluations, 1, min(MAX_EVALUATIONS, MAX_SEARCH_PRODUCT // n),
                          f" at n = {n} (evaluations x n at most {MAX_SEARCH_PRODUCT:,}: the search holds a quarter "
                          f"of its runs' worlds at once)")
    return _adversarial_search(setup.algorithm, n, integer("max_degree", max_degree, 2, MAX_DEGREE),
                               text("objective", objective, "an objective's name"), evaluations, setup.seed,
                               setup.lighthouse, setup.policy(), optional_text("family", family, "a family's name"),
                               callback("progress", progress), flag("baseline", baseline))
