"""Worlds with holes, thesis §3.5.3 (Figure 3.8, Figure 3.10(c)/(d)): lattices and complete graphs thinned at random.

:func:`lattice_hole` removes random cells or edges from a lattice and
:func:`complete_hole` random edges from K_n, always keeping the graph
connected: candidates are tried in an order drawn from
``random.Random(seed)`` (never the global random state) and a removal that
would disconnect the graph is skipped.  The size limits are checked on the
full graph, before it is built.
"""

from __future__ import annotations

import random
from collections import deque
from typing import Hashable

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World, check_size

from topomark.reference.worlds.embedding import circle_positions, from_positions
from topomark.reference.worlds.deterministic import fraction_param, integer_param, lattice_graph, lattice_size, seed_param

__all__ = ["lattice_hole", "complete_hole"]


# -- random removal keeping the graph connected -------------------------------
def _reaches_all(graph: nx.Graph, source: Hashable, targets: set) -> bool:
    """Whether every node of ``targets`` is reachable from ``source`` (stops early)."""
    missing = set(targets)
    missing.discard(source)
    seen = {source}
    todo = deque([source])
    while todo and missing:
        for w in graph.neighbors(todo.popleft()):
            if w not in seen:
                seen.add(w)
                missing.discard(w)
                todo.append(w)
    return not missing


def _remove_edges(graph: nx.Graph, count: int, rng: random.Random, what: str) -> None:
    """Remove ``count`` random non-bridge edges (a bridge stays a bridge, so one pass suffices)."""
    if count > graph.number_of_edges() - (graph.number_of_nodes() - 1):
        raise InvalidInput(
            f"cannot remove {count} of the {graph.number_of_edges()} edges of {what} and keep it connected: "
            f"at most {graph.number_of_edges() - graph.number_of_nodes() + 1} can go"
        )
    candidates = sorted(graph.edges, key=lambda e: (e[0], e[1]))
    rng.shuffle(candidates)
    removed = 0
    for u, v in candidates:
        if removed == count:
            break
        graph.remove_edge(u, v)
        if _reaches_all(graph, u, {v}):
            removed += 1
        else:  # (u, v) is a bridge: skip it
            graph.add_edge(u, v)
    if removed < count:  # cannot happen: a connected graph with a cycle has a non-bridge
        raise InvalidInput(f"could only remove {removed} of {count} edges of {what} keeping it connected")


def _remove_vertices(graph: nx.Graph, count: int, rng: random.Random, what: str) -> None:
    """Remove ``count`` random vertices whose removal keeps the graph connected.

    Candidates are tried in one random order; a vertex whose removal would
    disconnect the graph is skipped and retried in a later pass (removing other
    vertices can make it removable), until ``count`` are gone or a whole pass
    removes nothing.
    """
    if count > graph.number_of_nodes() - 2:
        raise InvalidInput(
            f"cannot remove {count} of the {graph.number_of_nodes()} vertices of {what}: "
            "at least 2 vertices must remain"
        )
    pending = sorted(graph.nodes)
    rng.shuffle(pending)
    removed = 0
    while removed < count:
        skipped = []
        for v in pending:
            if removed == count:
                break
            neighbours = list(graph.neighbors(v))
            graph.remove_node(v)
            if _reaches_all(graph, neighbours[0], set(neighbours)):
                removed += 1
            else:
                graph.add_node(v)
                graph.add_edges_from((v, w) for w in neighbours)
                skipped.append(v)
        if removed < count and len(skipped) == len(pending):
            raise InvalidInput(f"could only remove {removed} of {count} vertices of {what} keeping it connected")
        pending = skipped


# -- the two world families -----------------------------------------------------------
def lattice_hole(rows: int, cols: int, fraction: float = 0.1, remove: str = "vertices", seed: int = 0) -> World:
    """A lattice with holes, §3.5.3 (Figure 3.8(a), Figure 3.10(c)).

    Starts from :func:`~topomark.reference.worlds.deterministic.lattice` and removes
    ``round(fraction * N)`` randomly
    chosen vertices (``remove="vertices"``, N = rows*cols) or edges
    (``remove="edges"``, N = number of lattice edges), keeping the graph
    connected: candidates are tried in a random order drawn from
    ``random.Random(seed)`` and a choice that would disconnect the graph is
    skipped (and, for vertices, retried later).  Surviving cells keep their
    names and positions, so the clockwise order stays geometric (planar).

    Raises InvalidInput if ``fraction`` is outside [0, 1), ``remove`` is
    unknown, or that many removals cannot keep the graph connected with at
    least 2 vertices.
    """
    rows, cols = lattice_size(rows, cols)
    fraction = fraction_param(fraction)
    if remove not in ("vertices", "edges"):
        raise InvalidInput(f"remove must be 'vertices' or 'edges', got {remove!r}")
    rng = random.Random(seed_param(seed))
    graph, pos = lattice_graph(rows, cols)
    what = f"the {rows}x{cols} lattice"
    if remove == "vertices":
        _remove_vertices(graph, round(fraction * graph.number_of_nodes()), rng, what)
    else:
        _remove_edges(graph, round(fraction * graph.number_of_edges()), rng, what)
    return from_positions(graph, pos)


def complete_hole(n: int, fraction: float = 0.1, seed: int = 0) -> World:
    """K_n with ``round(fraction * n(n-1)/2)`` random edges removed, §3.5.3 (Figure 3.8(b), 3.10(d)).

    Edges are tried in a random order from ``random.Random(seed)``; an edge
    whose removal would disconnect the graph is skipped.  Same circle
    embedding as :func:`~topomark.reference.worlds.deterministic.complete`.  Raises
    InvalidInput for n < 2, fraction outside [0, 1), or more removals than a
    connected graph allows.
    """
    n = integer_param("n", n, 2)
    check_size(n, n * (n - 1) // 2, f"K_{n} (built before its edges are removed)")
    fraction = fraction_param(fraction)
    rng = random.Random(seed_param(seed))
    graph = nx.complete_graph(n)
    _remove_edges(graph, round(fraction * graph.number_of_edges()), rng, f"K_{n}")
    return from_positions(graph, circle_positions(n))
