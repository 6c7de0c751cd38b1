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

from topomark.arguments import (callback, flag, integer, keywords_checked, largest_degree, optional_text, path,
                                seconds, text)
from topomark.proofs import z3search
from topomark.proofs.bisim import Distinction, bisimulation, check_relation, distinguishing_sequence
from topomark.proofs.census import CensusResult
from topomark.proofs.census_run import sharded_census
from topomark.proofs.enumerate import MAX_VERTICES
from topomark.proofs.z3results import ProofReport, SearchResult
from topomark.reference.cli.args import MAX_JOBS
from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.markerclass import marker_class
from topomark.spec.world import MAX_DEGREE, World
from topomark.worlds import WorldLike, resolve

__all__ = ["distinguish", "search", "prove", "census", "Distinction", "SearchResult", "ProofReport",
           "CensusResult"]


def _bounds(marker: object, max_vertices: object, max_degree: object, largest: int, what: str) -> tuple[str, int, int]:
    """``marker`` a marker class's name, ``max_vertices`` from 2 to ``largest`` (``what`` enumerates up to it),
    ``max_degree`` from 1 to the largest degree a world can have: each refused as InvalidInput naming it."""
    marker_class(text("marker", marker, "a marker class's name"))
    return (str(marker), integer("max_vertices", max_vertices, 2, largest, f" ({what})"),
            integer("max_degree", max_degree, 1, MAX_DEGREE))


def _started(world: WorldLike, name: str) -> World:
    the_world = resolve(world)
    if the_world.start is None:
        raise InvalidInput(f"world {name} has no start (distinguish compares the two robots' starts)")
    return the_world


@keywords_checked
def distinguish(a: WorldLike, b: WorldLike) -> Distinction | None:
    """The shortest motion sequence after which a robot perceives differently in ``a`` and ``b``, or None.

    Both worlds need a start.  The result's ``motions`` is the sequence M (empty when the start signatures
    already differ) and ``perceptions_a``/``perceptions_b`` the perceptions P in each world (§3.1.1).
    None means indistinguishable; the bisimulation relation behind that answer is checked independently
    first (CheckFailure if the check disagrees).  Either argument not a world, or a world without a start,
    is InvalidInput.

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


@keywords_checked
def search(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
           planar: bool = False) -> SearchResult:
    """Z3's search for two worlds carrying ``marker`` that no motion sequence tells apart but that are not
    extended-isomorphic, smallest sizes first.

    ``result.found`` tells; ``result.worlds`` is the pair (re-checked: indistinguishable and not isomorphic),
    ``result.motions`` and ``result.perceptions`` a walk covering both.  ``outcome`` is ``none`` when there
    is no pair within the bounds and ``unknown`` when ``timeout`` seconds ran out.  ``planar=True`` keeps
    to genus-0 embeddings, like the thesis's drawings.

    Raises InvalidInput before Z3 starts for an unknown marker class, ``max_vertices`` outside 2 to 8 (what
    the solver can take), ``max_degree`` < 1, a ``timeout`` that is not a positive, finite number of seconds
    of at most a week (or None), ``planar`` other than True or False, and any argument of the wrong type.

    Examples
    --------
    >>> r = search("none", max_vertices=4, max_degree=3)
    >>> r.outcome, [w.n for w in r.worlds]
    ('found', [3, 4])
    """
    marker, max_vertices, max_degree = _bounds(marker, max_vertices, max_degree, z3search.MAX_VERTICES,
                                               "what the solver can take")
    return z3search.search(marker, max_vertices, max_degree, seconds("timeout", timeout),
                           planar=flag("planar", planar))


@keywords_checked
def prove(marker: str, max_vertices: int, max_degree: int, timeout: float | None = None,
          planar: bool = False) -> ProofReport:
    """A bounded proof that ``marker`` has no indistinguishable non-isomorphic pair: Z3 finds every size pair
    unsatisfiable.  ``report.proved`` tells; ``report.outcome`` is ``proved``, ``counterexample`` or
    ``unknown``, and ``report.search`` the search behind it.  Bad arguments raise InvalidInput as for
    :func:`search`.

    Examples
    --------
    >>> prove("none", max_vertices=4, max_degree=3).outcome
    'counterexample'
    """
    marker, max_vertices, max_degree = _bounds(marker, max_vertices, max_degree, z3search.MAX_VERTICES,
                                               "what the solver can take")
    return z3search.prove(marker, max_vertices, max_degree, seconds("timeout", timeout), flag("planar", planar))


@keywords_checked
def census(marker: str, max_vertices: int, max_degree: int, jobs: int = 1,
           shards: str | os.PathLike[str] | None = None, scheduler: str | None = None,
           progress: Callable[[str], None] | None = None) -> CensusResult:
    """Every world of 2..``max_vertices`` vertices and degree at most ``max_degree`` (up to isomorphism), with
    every placement of ``marker`` and every start, grouped by the language the robot perceives.

    ``result.smallest_counterexample`` is the smallest indistinguishable non-isomorphic pair (re-checked), or
    None; ``result.rows`` counts worlds, placements and languages per size.  The census runs as map and
    reduce over shards: in ``jobs`` processes, or on a Dask ``scheduler``; ``shards`` keeps them in a
    directory so that an interrupted census resumes (a temporary directory otherwise); a resume computes again
    a seeded sample of what it kept and the records its counterexample rests on, and a record edited since it
    was written raises InvalidInput naming its file (:mod:`topomark.proofs.census_recheck`).  ``progress`` is
    called with a line of text now and then.

    Raises InvalidInput before any work for an unknown marker class, ``max_vertices`` outside 2 to 10 (the
    sizes the enumeration reaches), ``max_degree`` < 1 or too large for the worlds of ``max_vertices``
    vertices to fit in memory (at n = 7 and 8 at most 4, at 9 and 10 at most 3), ``jobs`` outside 1 to 256, a ``shards`` that is not a
    path, a ``scheduler`` that is not an address (a str), a ``progress`` that is not callable, and any
    argument of the wrong type.

    Examples
    --------
    >>> census("none", max_vertices=4, max_degree=3).smallest_counterexample is not None
    True
    >>> census("directional-vertex", max_vertices=4, max_degree=3).smallest_counterexample is None
    True
    """
    marker, max_vertices, max_degree = _bounds(marker, max_vertices, max_degree, MAX_VERTICES,
                                               "the census enumerates worlds up to that size")
    largest_degree(max_vertices, max_degree)
    jobs = integer("jobs", jobs, 1, MAX_JOBS, " worker processes")
    shards = None if shards is None else path("shards", shards)
    scheduler = optional_text("scheduler", scheduler, "a Dask scheduler's address or 'local'")
    progress = callback("progress", progress)
    if shards is not None:
        return sharded_census(marker, max_vertices, max_degree, shards, jobs=jobs, scheduler=scheduler,
                              progress=progress)
    with tempfile.TemporaryDirectory(prefix="topomark-census-") as root:
        return sharded_census(marker, max_vertices, max_degree, root, jobs=jobs, scheduler=scheduler,
                              progress=progress)
