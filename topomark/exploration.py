"""Exploring from Python: a checked run, its map judged, extended isomorphism, trace replay (thesis §3.1.3, §3.3).

:func:`explore` is ``topomark explore``: the algorithm of the registry (Algorithm 3.1 by default, §3.3) runs
over the robot interface only, and the checker, which sees the world, checks every invariant the algorithm's
registry entry names after every iteration.  The returned
:class:`~topomark.reference.run.explore.Outcome` carries ``map`` (the explored map as a world, or None when
the run ended without one), ``cost`` (edge traversals), ``outcome`` (``correct``, ``wrong-map``, ``failed``,
``limit``...), ``verified`` and ``violation``.

:func:`isomorphic` decides extended isomorphism (§3.1.3) and returns its witness — the vertex bijection and
each vertex's rotation offset, re-verified by an independent check — or None.  :func:`check_map` judges a map
against the world it was made in, deciding which markers take part as ``topomark check-map`` does (a map
carries the lighthouse the robot dropped; the world file usually does not).

Examples
--------
>>> run = explore("cycle:n=5")
>>> run.outcome, run.cost > 0, run.map.n
('correct', True, 5)
>>> replay("cycle:n=5", run.trace).ok
True
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping
from typing import Any, cast

from topomark.arguments import flag, keywords_checked, path, text
from topomark.keywords import check_keywords
from topomark.reference.algorithms.registry import AlgorithmSpec, Listed, algorithm_spec, listing
from topomark.reference.explorers.lighthouses import Lighthouse
from topomark.reference.explorers.policies import Policies
from topomark.reference.files.overwrite import claim_file
from topomark.reference.replay.replay import ReplayResult, parse_records, replay as _replay
from topomark.reference.run.explore import Outcome, explore as _explore
from topomark.reference.run.map_check import MapVerdict, check_map as _check_map
from topomark.reference.trace.reader import load_trace
from topomark.reference.trace.sink import FileSink
from topomark.spec.errors import CheckFailure, InvalidInput, clip
from topomark.spec.isomorphism import Witness, find_isomorphism, verify_witness
from topomark.worlds import WorldLike, resolve

__all__ = ["explore", "check_map", "isomorphic", "replay", "algorithms", "policies_of", "Outcome", "MapVerdict",
           "Witness", "ReplayResult", "AlgorithmSpec", "Listed", "Policies"]


@keywords_checked
def explore(world: WorldLike, algorithm: str = "basic", lighthouse: str | Lighthouse | None = None,
            policies: Policies | Mapping[str, str] | None = None, check: bool = True, *,
            trace: str | os.PathLike[str] | None = None, record: bool = True, force: bool = False,
            **options: Any) -> Outcome:
    """Explore ``world`` with ``algorithm`` and return the outcome, as ``topomark explore`` does.

    ``world`` is a World, a world file or a generator text (``"lattice:rows=3,cols=3"``).  ``lighthouse``
    names the strategy of a lighthouse algorithm (default ``directional-vertex``, §3.3); ``policies`` the
    edge, hypothesis and path policies (a :class:`~topomark.reference.explorers.policies.Policies` or a
    mapping such as ``{"edge": "lifo"}``).  ``check=False`` runs without the checker (``verified`` is then
    False and ``outcome`` ``unchecked``).  The trace goes to the file ``trace`` if given (a file already there is refused,
    before the run, unless ``force=True``, as ``--trace`` is without ``--force``), else it is kept in
    ``outcome.trace`` unless ``record=False``.  Other keywords are the algorithm's own options
    (``topomark algorithms``), an underscore standing for the option's hyphen: ``max_models=50``.

    ``world`` may also be a networkx ``PlanarEmbedding`` (its clockwise order is the rotation) or a mapping
    of each vertex to its neighbours in clockwise order (:func:`topomark.worlds.resolve`).

    A violated invariant does not raise: it ends the run with ``outcome.violation`` set (exit 1 in the CLI).
    Bad input raises InvalidInput before the run: an unknown algorithm, lighthouse or policy, a world the
    lighthouse cannot use or that is not a world, ``check`` or ``record`` other than True or False, a
    ``trace`` that is not a path or names a file already there (without ``force=True``), an option's value of the wrong type (None, a str or a bool for a count) or
    out of its range; a keyword that is neither explore's nor an option of the algorithm raises its subclass
    InvalidKeyword, which is also a TypeError, as Python's own unexpected keywords are.

    Examples
    --------
    >>> run = explore("wheel-a", algorithm="enh3", policies={"edge": "lifo"})
    >>> run.verified, run.violation is None, isomorphic(run.map, resolve("wheel-a"), markers=False) is not None
    (True, True, True)
    >>> explore("cycle:n=4", algorithm="model-tree", max_steps=10).map is None  # stopped: no map
    True
    >>> explore("cycle:n=4", algoritm="basic")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidKeyword: explore() got an unexpected keyword argument 'algoritm'; did you mean ...
    """
    spec = algorithm_spec(text("algorithm", algorithm, "an algorithm's name"))
    _check_options(spec, options)
    given = {name.replace("_", "-"): value for name, value in options.items()}
    chosen = policies_of(policies, spec.name)
    if not (lighthouse is None or isinstance(lighthouse, (str, Lighthouse))):
        text("lighthouse", lighthouse, "a lighthouse strategy's name")
    check, record, force = flag("check", check), flag("record", record), flag("force", force)
    the_world = resolve(world)
    if trace is None:
        return _explore(the_world, spec, chosen, check, record=record, lighthouse=lighthouse, options=given)
    claim_file(path("trace", trace), "trace", force)  # before the run: a long exploration must not be lost
    with FileSink(path("trace", trace)) as sink:
        return _explore(the_world, spec, chosen, check, sink=sink, lighthouse=lighthouse, options=given)


EXPLORE_KEYWORDS = ("world", "algorithm", "lighthouse", "policies", "check", "trace", "record", "force")
"""The keywords of :func:`explore` itself; the others are the algorithm's options."""


def _check_options(spec: AlgorithmSpec, options: Mapping[str, Any]) -> None:
    """Refuse a keyword that is neither explore's nor an option of ``spec`` (underscores for hyphens), and a
    value of the wrong type: a word for an option with choices, an int (not a bool) for a count.  The command
    line gives every value as text; from Python, ``"10"`` for a count is a mistake, and None would stand for
    the option not given (for ``max_steps``, no limit at all)."""
    takes = [p.name.replace("-", "_") for p in spec.parameters]
    own = f"the algorithm {spec.name}'s options: {', '.join(takes) or 'none'}"
    check_keywords("explore", {k.replace("-", "_"): v for k, v in options.items()}, takes,
                   f"explore() takes {', '.join(EXPLORE_KEYWORDS)}; {own}", suggest=EXPLORE_KEYWORDS)
    for parameter in spec.parameters:
        name = parameter.name.replace("-", "_")
        value = options.get(name, options.get(parameter.name, ...))
        if value is ...:
            continue
        if parameter.choices:
            text(name, value, f"one of {', '.join(parameter.choices)}")
        elif isinstance(value, bool) or not isinstance(value, int):
            bound = f" and at most {parameter.maximum:,}" if parameter.maximum is not None else ""
            raise InvalidInput(f"{name} must be an integer >= {parameter.minimum}{bound}, not "
                               f"{type(value).__name__} ({clip(repr(value), 60)})")


def policies_of(policies: Policies | Mapping[str, str] | None, algorithm: str) -> Policies | None:
    """A Policies from a mapping ``{"edge": ..., "hypothesis": ..., "path": ...}`` (a kind given at most once); a
    kind it leaves out takes ``algorithm``'s default (its registration's edge policy, if it names one).  Anything
    else, an unknown kind, or a policy's name that is not a str, is InvalidInput."""
    if policies is None or isinstance(policies, Policies):
        return policies
    if not isinstance(policies, Mapping):
        raise InvalidInput(f"policies must be a Policies or a mapping of edge, hypothesis and path policies, "
                           f"not {type(policies).__name__}")
    unknown = sorted((repr(kind) for kind in set(policies) - {"edge", "hypothesis", "path"}))
    if unknown:
        raise InvalidInput(f"unknown policy kind {clip(', '.join(unknown), 200)} (the kinds: edge, hypothesis, path)")
    for kind, name in policies.items():
        text(f"the {kind} policy", name, "a policy's name")
    return algorithm_spec(algorithm).policies(policies)


@keywords_checked
def isomorphic(a: WorldLike, b: WorldLike, markers: bool = True) -> Witness | None:
    """The extended isomorphism from ``a`` to ``b`` (§3.1.3), or None when they are not isomorphic.

    The witness maps every vertex of ``a`` to one of ``b`` (``witness.vertex_map``) and shifts each vertex's
    exit indices by ``witness.offsets[v]``; it is checked against the definition by a second implementation
    before it is returned (CheckFailure if the two disagree).  With ``markers=False`` the embedded graphs
    are compared and the markers ignored (a map carries the lighthouse its robot dropped; the world it was
    made in usually does not).  A world that is not one, or ``markers`` other than True or False, is
    InvalidInput.

    Examples
    --------
    >>> w = isomorphic("lattice:rows=2,cols=2", "cycle:n=4")
    >>> sorted(w.vertex_map.values())
    ['0', '1', '2', '3']
    >>> isomorphic("cycle:n=4", "chain:n=4") is None
    True
    """
    markers = flag("markers", markers)
    first, second = resolve(a), resolve(b)
    result = find_isomorphism(first, second, markers=markers)
    if not result.isomorphic:
        return None
    bad = verify_witness(first, second, cast(Witness, result.witness), markers=markers)  # isomorphic: witnessed
    if bad is not None:
        raise CheckFailure(bad)
    return result.witness


@keywords_checked
def check_map(world: WorldLike, map_: WorldLike) -> MapVerdict:
    """Is ``map_`` extended-isomorphic to ``world``?  The verdict of ``topomark check-map``.

    Which markers take part follows one rule (``spec/protocol.md``, "Judging a map"): the world's own
    markers if it has any; else, when the map carries one directional marker, Algorithm 3.1's lighthouse at
    the world's start; else none.  ``verdict.isomorphic``, ``verdict.rule`` and ``verdict.words()`` tell.
    Either argument not a world (:data:`~topomark.worlds.WorldLike`) is InvalidInput.

    Examples
    --------
    >>> run = explore("lattice:rows=2,cols=3")
    >>> verdict = check_map("lattice:rows=2,cols=3", run.map)
    >>> verdict.isomorphic, verdict.rule  # a generated world has no start: the graphs are compared
    (True, 'graph')
    >>> check_map("cycle:n=6", run.map).isomorphic
    False
    """
    return _check_map(resolve(world), resolve(map_))


@keywords_checked
def replay(world: WorldLike, trace: str | os.PathLike[str] | Iterable[dict[str, Any]]) -> ReplayResult:
    """Re-check every claim of a recorded trace against ``world`` (``topomark replay``).

    ``trace`` is a trace file or its records (``explore(...).trace``, or any iterable of them, a generator
    too); records are read back through the trace format's reader one at a time, so they are checked exactly
    as a file's lines are, and a stream of records is never held whole: one record at a time, and at most
    :data:`~topomark.reference.trace.reader.MAX_TRACE_RECORDS` (100,000,000) of them, as from a file: an endless
    generator is refused there.  ``result.ok`` is the verdict,
    ``result.message`` says what was verified or where the trace first diverges from the world.

    Bad input raises InvalidInput: a world that is not one, a ``trace`` that is neither a path nor an
    iterable of records (a dict, a str of JSON), and the first record the trace format refuses (what
    cannot be JSON, NaN, a missing header, a second header, a record past the 100,000,000th, ...).

    Examples
    --------
    >>> run = explore("cycle:n=4")
    >>> bad = [dict(r) for r in run.trace]
    >>> bad[-1]["cost"] += 1
    >>> replay("cycle:n=4", bad).ok
    False
    """
    the_world = resolve(world)
    if isinstance(trace, (str, os.PathLike)):
        return _replay(the_world, load_trace(path("trace", trace)), os.fspath(trace))
    if isinstance(trace, (bytes, bytearray, Mapping)) or not isinstance(trace, Iterable):
        raise InvalidInput(f"trace must be a trace file or an iterable of its records (dicts), "
                           f"not {type(trace).__name__}")
    return _replay(the_world, parse_records(trace, "<records>"), "<records>")


@keywords_checked
def algorithms() -> list[AlgorithmSpec | Listed]:
    """Every algorithm of the registry, in ``topomark algorithms`` order (Algorithm 3.1 first).

    Each entry has its ``name``, ``thesis`` reference, marker ``kit``, stated bounds, options and checks;
    the thesis's algorithms that cannot be implemented from it are listed too (``status``, with the reason).

    Examples
    --------
    >>> specs = algorithms()
    >>> specs[0].name, specs[0].thesis
    ('basic', '§3.3, Algorithm 3.1')
    """
    return listing()
