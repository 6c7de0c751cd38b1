"""Connected graphs up to isomorphism, for any number of vertices (thesis §3.1.1).

The sufficiency questions of §3.2, §3.7 and §6.1 range over every connected
simple graph of a given size; networkx's graph atlas stops at 7 vertices.  This
module generates the connected graphs on ``n`` vertices with maximum degree
``≤ D``, one per isomorphism class, for any ``n``, by *vertex augmentation
with canonical deduplication*:

* every connected graph G on n ≥ 2 vertices has a non-cut vertex v (a leaf of
  a spanning tree), and G - v is connected with maximum degree ≤ that of G; so
  adding a new vertex, joined to a non-empty set S of at most D vertices of
  degree < D, to every class on n - 1 vertices reaches every class on n;
* children are deduplicated by an exact canonical form (:func:`canonical`):
  individualisation-refinement over the whole search tree (equitable
  partition refinement, then every choice of vertex in the first non-singleton
  cell), the certificate being the least relabelled adjacency over all
  leaves.  The leaves reaching the least certificate are exactly the
  automorphisms, so the same search yields the full automorphism group (used
  to skip sets S in one Aut-orbit, and by :mod:`topomark.proofs.burnside`);
* no pruning by automorphisms inside the search: slower than nauty on
  symmetric graphs but simple enough to trust; fine for n ≤ 10.

Where nauty's ``geng`` is installed (Debian's ``nauty`` package),
:mod:`topomark.proofs.geng` lists the graphs with it instead, relabelled by
:func:`canonical` and sorted by :func:`ordered`, so the list is the same
tuple either way; this module is the fallback, and the independent side of
the cross-check.  Why not link nauty?  The PyPI wheel (``pynauty-prebuilt``)
wraps nauty in GPLv3 code while topomark is MIT; geng runs as a separate
program, and without it a pure-Python generator keeps the install as it is.  The counts are checked
against the atlas for n ≤ 7 (tests/test_graphs.py) and against published
figures:

* D = 3: 1, 1, 2, 6, 10, 29, 64, 194, 531, 1733 for n = 1…10, given by
  S. Wolfram, *A New Kind of Science* (2002), notes to chapter 9, section 7,
  "Trivalent networks" (subnetworks with dangling connections, no self or
  multiple connections); the cubic ones among them, 5 on 8 and 19 on 10
  vertices, are OEIS A002851;
* D = 4: 78, 353, 1929, 12207, 89402 for n = 6…10, OEIS A121941 "Number of
  unlabeled connected simple graphs with n nodes of degree 4 or less"; the
  quartic ones, 6 on 8 and 16 on 9 vertices, are OEIS A006820.

All of these were also matched once against nauty (pynauty certificates and
automorphism group orders for every class, D = 3 to n = 10, D = 4 to n = 9),
a one-off cross-check, not a dependency.

Examples
--------
>>> [count(n, 3) for n in range(2, 9)]
[1, 2, 6, 10, 29, 64, 194]
>>> c = classes(4, 3)[-1]           # the complete graph K4
>>> c.edges, len(c.automorphisms)
(6, 24)
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable

import networkx as nx

from topomark.spec.errors import InvalidInput

__all__ = ["GraphClass", "canonical", "classes", "ordered", "generate", "count", "automorphisms", "MAX_VERTICES"]

MAX_VERTICES = 12
"""Largest n :func:`classes` accepts: the pure-Python search is for small graphs (n = 10, D = 4 is 89,402)."""

Adjacency = tuple[int, ...]  # adjacency[v] = bit mask of v's neighbours
Perm = tuple[int, ...]       # vertex v -> perm[v]


@dataclass(frozen=True)
class GraphClass:
    """One isomorphism class, in its canonical labelling, with its whole automorphism group."""

    adjacency: Adjacency
    automorphisms: tuple[Perm, ...]

    @property
    def n(self) -> int:
        return len(self.adjacency)

    @property
    def edges(self) -> int:
        return sum(m.bit_count() for m in self.adjacency) // 2

    def degree(self, v: int) -> int:
        return self.adjacency[v].bit_count()

    def neighbours(self, v: int) -> list[int]:
        return [w for w in range(self.n) if self.adjacency[v] >> w & 1]

    def graph(self) -> nx.Graph:
        g: nx.Graph[int] = nx.Graph()
        g.add_nodes_from(range(self.n))
        g.add_edges_from((v, w) for v in range(self.n) for w in self.neighbours(v) if v < w)
        return g


# -- canonical labelling -------------------------------------------------------------
def _refine(adj: Adjacency, cells: list[tuple[int, ...]]) -> list[tuple[int, ...]]:
    """Split cells by neighbour counts into every cell until stable (an isomorphism-invariant refinement)."""
    while True:
        masks = [sum(1 << v for v in c) for c in cells]
        out: list[tuple[int, ...]] = []
        for c in cells:
            if len(c) == 1:
                out.append(c)
                continue
            parts: dict[tuple[int, ...], list[int]] = {}
            for v in c:
                parts.setdefault(tuple((adj[v] & m).bit_count() for m in masks), []).append(v)
            out.extend(tuple(parts[k]) for k in sorted(parts))
        if len(out) == len(cells):
            return out
        cells = out


def _leaves(adj: Adjacency, cells: list[tuple[int, ...]], out: list[tuple[int, ...]]) -> None:
    """Every leaf (vertex order) of the individualisation-refinement tree below ``cells``."""
    cells = _refine(adj, cells)
    target = next((i for i, c in enumerate(cells) if len(c) > 1), None)
    if target is None:
        out.append(tuple(c[0] for c in cells))
        return
    cell = cells[target]
    for v in cell:
        rest = tuple(w for w in cell if w != v)
        _leaves(adj, cells[:target] + [(v,), rest] + cells[target + 1:], out)


def _relabelled(adj: Adjacency, order: tuple[int, ...]) -> Adjacency:
    position = {v: i for i, v in enumerate(order)}
    return tuple(sum(1 << position[w] for w in range(len(adj)) if adj[v] >> w & 1) for v in order)


def _search(adj: Adjacency) -> tuple[Adjacency, list[tuple[int, ...]]]:
    """The least relabelled adjacency over all leaves, and the leaves (vertex orders) that reach it."""
    degrees: dict[int, list[int]] = {}
    for v in range(len(adj)):
        degrees.setdefault(adj[v].bit_count(), []).append(v)
    leaves: list[tuple[int, ...]] = []
    _leaves(adj, [tuple(degrees[d]) for d in sorted(degrees)], leaves)
    codes = [_relabelled(adj, order) for order in leaves]
    best = min(codes)
    return best, [order for order, code in zip(leaves, codes) if code == best]


def canonical(adj: Adjacency) -> GraphClass:
    """The canonical form of a graph given by bit masks, with its automorphism group.

    Two graphs are isomorphic iff their canonical adjacencies are equal.  The
    automorphisms act on the canonical labelling: leaf orders ``o1, o2`` with
    the least code give the automorphism ``i -> position of o1[i] in o2``.
    """
    if not adj:
        return GraphClass((), ((),))
    best, orders = _search(adj)
    first = orders[0]
    autos = []
    for order in orders:
        position = {v: i for i, v in enumerate(order)}
        autos.append(tuple(position[first[i]] for i in range(len(adj))))
    return GraphClass(best, tuple(sorted(autos)))


def automorphisms(g: nx.Graph) -> list[dict]:
    """The automorphism group of a networkx graph, as vertex maps (every element, identity included)."""
    nodes = sorted(g)
    index = {v: i for i, v in enumerate(nodes)}
    _, orders = _search(tuple(sum(1 << index[w] for w in g[v]) for v in nodes))
    first = orders[0]
    return [{nodes[first[i]]: nodes[order[i]] for i in range(len(nodes))} for order in orders]


# -- augmentation --------------------------------------------------------------------
def _least_in_orbit(mask: int, autos: tuple[Perm, ...]) -> bool:
    """Whether ``mask`` (a vertex set) is the least of its orbit under ``autos``."""
    for sigma in autos:
        image = 0
        m = mask
        while m:
            low = m & -m
            image |= 1 << sigma[low.bit_length() - 1]
            m ^= low
        if image < mask:
            return False
    return True


def _children(parent: GraphClass, max_degree: int):
    """Every graph from ``parent`` plus a vertex joined to a non-empty set of ≤ D unsaturated vertices."""
    n = parent.n
    free = [v for v in range(n) if parent.degree(v) < max_degree]
    for k in range(1, min(max_degree, len(free)) + 1):
        for chosen in itertools.combinations(free, k):
            mask = sum(1 << v for v in chosen)
            if len(parent.automorphisms) > 1 and not _least_in_orbit(mask, parent.automorphisms):
                continue
            yield tuple(a | (1 << n) if mask >> v & 1 else a for v, a in enumerate(parent.adjacency)) + (mask,)


@lru_cache(maxsize=None)
def classes(n: int, max_degree: int) -> tuple[GraphClass, ...]:
    """The connected graphs on ``n`` vertices with max degree ≤ ``max_degree``, one per isomorphism class.

    In canonical labelling, ordered by (edges, sorted degree sequence, adjacency).
    """
    if not 1 <= n <= MAX_VERTICES:
        raise InvalidInput(f"graphs are generated for 1..{MAX_VERTICES} vertices, not {n}")
    if max_degree < 0:
        raise InvalidInput(f"max degree must be at least 0, not {max_degree}")
    if n == 1:
        return (GraphClass((0,), ((0,),)),)
    found: dict[Adjacency, GraphClass] = {}
    for parent in classes(n - 1, max_degree):
        for child in _children(parent, max_degree):
            c = canonical(child)
            found.setdefault(c.adjacency, c)
    return ordered(found.values())


def ordered(found: Iterable[GraphClass]) -> tuple[GraphClass, ...]:
    """Classes in the order :func:`classes` lists them: by edges, sorted degree sequence, canonical adjacency.

    The key depends on the class alone (its canonical form), so any generator
    that finds the same classes lists them in the same order and labelling
    (:mod:`topomark.proofs.geng` relies on this).
    """
    return tuple(sorted(found, key=lambda c: (c.edges, sorted(c.degree(v) for v in range(c.n)), c.adjacency)))


def generate(n: int, max_degree: int) -> list[nx.Graph]:
    """:func:`classes` as networkx graphs on vertices ``0..n-1``."""
    return [c.graph() for c in classes(n, max_degree)]


def count(n: int, max_degree: int) -> int:
    """How many connected graphs on ``n`` vertices have max degree ≤ ``max_degree``."""
    return len(classes(n, max_degree))
