"""Worlds a robot cannot tell apart, from Python (thesis §3.2, §3.7 and Figure 3.4; §6.1's marker classes).

Two worlds are *indistinguishable* when every motion sequence gives the same perceptions in both (§3.2); a
marker class suffices for mapping only if no two non-isomorphic worlds carrying it are (§3.7).

* :func:`distinguish` — the shortest motion sequence whose perceptions differ (``topomark distinguish``), or
  None, in which case the bisimulation certifying it is re-checked first;
* :func:`search` and :func:`prove` — Z3 looks for an indistinguishable, non-isomorphic pair carrying a marker
  class within size bounds, or shows there is none (``topomark search [--prove]``);
* :func:`census` — every world up to a size, every placement of the class and every start, grouped by the
  robot's language (``topomark census``).

The marker classes are those of :data:`topomark.spec.markerclass.MARKER_CLASSES`: ``none``,
``undirected-vertex``, ``directional-vertex``, ...

Examples
--------
>>> found = search("undirected-vertex", max_vertices=5, max_degree=4)
>>> found.found, distinguish(*found.worlds) is None
(True, True)
>>> prove("directional-vertex", max_vertices=3, max_degree=2).proved  # Theorem 1's kit, bounded
True
"""

from __future__ import annotations

import os
import tempfile
from typing import Callable, cast

from topomark.proofs import z3search
from topomark.proofs.bisim import Distinction, bisimulation, check_relation, distinguishing_sequence
from topomark.proofs.census import CensusResult
from topomark.proofs.census_run import sharded_census
from topomark.proofs.enumerate import MAX_VERTICES
from topomark.proofs.z3results import ProofReport, SearchResult
from topomark.reference.cli.args import MAX_JOBS
from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.markerclass import marker_class
from topomark.spec.world import World
from topomark.worlds import WorldLike, resolve

__all__ = ["distinguish", "search", "prove", "census", "Distinction", "SearchResult", "ProofReport",
           "CensusResult"]


def _started(world: WorldLike, name: str) -> World:
    the_world = resolve(world)
    if the_world.start is None:
        raise InvalidInput(f"world {name} has no start (distinguish compares the two robots' starts)")
    return the_world


def distinguish(a: WorldLike, b: WorldLike) -> Distinction | None:
    """The shortest motion sequence after which a robot perceives differently in ``a`` and ``b``, or None.

    Both worlds need a start.  The result's ``motions`` is the sequence M (empty when the start signatures
    already differ) and ``perceptions_a``/``perceptions_b`` the perceptions P in each world (§3.1.1).
    None means indistinguishable; the bisimulation relation behind that answer is checked independently
    first (CheckFailure if the check disagrees).

    Examples
    --------
    >>> d = distinguish("wheel-a:marker=undirected", "wheel-a:marker=directional")
    >>> d.motions, str(d.perceptions_a[0]) != str(d.perceptions_b[0])
    ((), True)
    >>> pair = search("none", max_vertices=4, max_degree=3).worlds
    >>> distinguish(*pair) is None
    True
    """
    first, second = _started(a, "A"), _started(b, "B")
    found = distinguishing_sequence(first, second)
    if found is not None:
        return found
    # indistinguishable: a bisimulation exists
    relation = cast("frozenset[tuple[tuple[str, int], tuple[str, int]]]", bisimulation(first, second))
    violation = check_relation(first, second, relation)
    if violation is not None:
        raise CheckFailure(violation)
    return None


def search(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
           planar: bool = False) -> SearchResult:
    """Z3's search for two worlds carrying ``marker`` that no motion sequence tells apart but that are not
    extended-isomorphic, smallest sizes first.

    ``result.found`` tells; ``result.worlds`` is the pair (re-checked: indistinguishable and not isomorphic),
    ``result.motions`` and ``result.perceptions`` a walk covering both.  ``outcome`` is ``none`` when there
    is no pair within the bounds and ``unknown`` when ``timeout`` seconds ran out.  ``planar=True`` keeps
    to genus-0 embeddings, like the thesis's drawings.

    Examples
    --------
    >>> r = search("none", max_vertices=4, max_degree=3)
    >>> r.outcome, [w.n for w in r.worlds]
    ('found', [3, 4])
    """
    return z3search.search(marker, max_vertices, max_degree, timeout, planar=planar)


def prove(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
          planar: bool = False) -> ProofReport:
    """A bounded proof that ``marker`` has no indistinguishable non-isomorphic pair: Z3 finds every size pair
    unsatisfiable.  ``report.proved`` tells; ``report.outcome`` is ``proved``, ``counterexample`` or
    ``unknown``, and ``report.search`` the search behind it.

    Examples
    --------
    >>> prove("none", max_vertices=4, max_degree=3).outcome
    'counterexample'
    """
    return z3search.prove(marker, max_vertices, max_degree, timeout, planar)


def census(marker: str, max_vertices: int, max_degree: int, jobs: int = 1,
           shards: str | os.PathLike[str] | None = None, scheduler: str | None = None,
           progress: Callable[[str], None] | None = None) -> CensusResult:
    """Every world of 2..``max_vertices`` vertices and degree at most ``max_degree`` (up to isomorphism), with
    every placement of ``marker`` and every start, grouped by the language the robot perceives.

    ``result.smallest_counterexample`` is the smallest indistinguishable non-isomorphic pair (re-checked), or
    None; ``result.rows`` counts worlds, placements and languages per size.  The census runs as map and
    reduce over shards: in ``jobs`` processes, or on a Dask ``scheduler``; ``shards`` keeps them in a
    directory so that an interrupted census resumes (a temporary directory otherwise).  ``progress`` is
    called with a line of text now and then.

    Examples
    --------
    >>> census("none", max_vertices=4, max_degree=3).smallest_counterexample is not None
    True
    >>> census("directional-vertex", max_vertices=4, max_degree=3).smallest_counterexample is None
    True
    """
    marker_class(marker)
    if not 2 <= max_vertices <= MAX_VERTICES:
        raise InvalidInput(f"max_vertices must be 2 to {MAX_VERTICES} (the census enumerates worlds of at most "
                           f"{MAX_VERTICES} vertices), not {max_vertices}")
    if max_degree < 1:
        raise InvalidInput(f"max_degree must be at least 1, not {max_degree}")
    if not 1 <= jobs <= MAX_JOBS:
        raise InvalidInput(f"jobs must be 1 to {MAX_JOBS} worker processes, not {jobs}")
    if shards is not None:
        return sharded_census(marker, max_vertices, max_degree, shards, jobs=jobs, scheduler=scheduler,
                              progress=progress)
    with tempfile.TemporaryDirectory(prefix="topomark-census-") as root:
        return sharded_census(marker, max_vertices, max_degree, root, jobs=jobs, scheduler=scheduler,
                              progress=progress)
