"""Randomly connected worlds of thesis §3.5.3: small-world graphs (Figure 3.9(a)) and random graphs (Figure 3.9(b)).

Both are drawn on a circle and embedded clockwise by angle
(:func:`~topomark.reference.worlds.embedding.from_positions`, as
:func:`~topomark.reference.worlds.deterministic.complete`).  Random choices come from
``random.Random(seed)`` only, never from the global random state; the size
limits are checked before anything is built.
"""

from __future__ import annotations

import bisect
import math
import random
from collections.abc import Sequence
from typing import Iterable

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World, check_size

from topomark.reference.worlds.embedding import circle_positions, from_positions, on_circle
from topomark.reference.worlds.deterministic import integer_param, real_param, seed_param

__all__ = ["small_world", "random_graph", "OtherPairs"]


def small_world(n: int, k: int, p: float, seed: int = 0) -> World:
    """A small-world graph as built in §3.5.3 (after Watts and Strogatz [68], Figure 3.9(a)).

    1. A ring over vertices ``0..n-1`` where each vertex is joined to its k
       nearest neighbours, k/2 on each side.  k must be even (an odd k has no
       symmetric "k nearest neighbours" on a ring, so it is rejected) with
       2 <= k < n (larger k would create multi-edges).
    2. Shortcuts: for each ring edge ``(u, u+j mod n)``, in the order
       u = 0..n-1, j = 1..k/2, with probability p (``rng.random() < p``) a
       random vertex ``w = rng.randrange(n)`` is drawn and the edge (u, w) is
       added -- unless w == u or (u, w) is already an edge (ring edge or an
       earlier shortcut), in which case nothing is added (no redraw).

    So n*k/2 <= m <= min(n*k, n(n-1)/2); the upper bound (n*k/2 if p = 0)
    is what is checked against the size limits, before anything is built.  Embedding: vertices on a circle,
    clockwise by angle (as :func:`~topomark.reference.worlds.deterministic.complete`).
    """
    n = integer_param("n", n, 3)
    k = integer_param("k", k, 2)
    if k % 2:
        raise InvalidInput(f"k must be even (k/2 nearest neighbours on each side of the ring), got {k}")
    if k >= n:
        raise InvalidInput(f"k must be < n (k={k}, n={n}): a ring of {n} vertices has only {n - 1} other vertices")
    p = real_param("p", p)
    if not 0.0 <= p <= 1.0:
        raise InvalidInput(f"p must be a probability in [0, 1], got {p!r}")
    check_size(n, min(n * k, n * (n - 1) // 2) if p > 0 else n * k // 2, f"small-world:n={n},k={k},p={p!r}")
    rng = random.Random(seed_param(seed))
    ring = [(u, (u + j) % n) for u in range(n) for j in range(1, k // 2 + 1)]
    graph: nx.Graph[int] = nx.Graph()
    graph.add_nodes_from(range(n))
    graph.add_edges_from(ring)
    for u, _v in ring:
        if rng.random() < p:
            w = rng.randrange(n)
            if w != u and not graph.has_edge(u, w):
                graph.add_edge(u, w)
    return from_positions(graph, circle_positions(n))


def _pair(u: int, v: int) -> tuple[int, int]:
    """The pair sorted."""
    return (u, v) if u < v else (v, u)


class OtherPairs(Sequence[tuple[int, int]]):
    """The vertex pairs ``(i, j)``, ``i < j < n``, in lexicographic order, minus the sorted ``taken`` ones.

    Equal, element by element, to the list of those pairs, but computed on
    demand: ``random.Random.sample`` draws the same indices from it as from
    the list (it uses only ``len`` and indexing), so :func:`random_graph` picks
    the same edges while using memory in proportion to the edges it keeps,
    not to the n(n-1)/2 pairs.
    """

    def __init__(self, n: int, taken: Iterable[tuple[int, int]]):
        self.n = n
        ranks = sorted(self._rank(i, j) for i, j in taken)
        self._gaps = [r - t for t, r in enumerate(ranks)]  # kept pairs before the t-th taken one
        self._len = n * (n - 1) // 2 - len(ranks)

    def _start(self, i: int) -> int:
        return i * (2 * self.n - i - 1) // 2

    def _rank(self, i: int, j: int) -> int:
        return self._start(i) + j - i - 1

    def __len__(self) -> int:
        return self._len

    def __getitem__(self, k: int) -> tuple[int, int]:  # type: ignore[override]  # indices only (no slices)
        if not 0 <= k < self._len:
            raise IndexError(k)
        r = k + bisect.bisect_right(self._gaps, k)
        b = 2 * self.n - 1
        i = max(0, (b - math.isqrt(b * b - 8 * r)) // 2 - 1)
        while self._start(i + 1) <= r:
            i += 1
        return i, r - self._start(i) + i + 1


def random_graph(n: int, fraction: float, seed: int = 0) -> World:
    """A randomly connected graph, §3.5.3 (Figure 3.9(b)): ``round(fraction * n(n-1)/2)`` edges.

    Connectivity is guaranteed by construction: first a random spanning tree
    (vertices in a random order, each joined to a uniformly chosen earlier
    one), then the remaining edges drawn uniformly without replacement from
    all other vertex pairs (:class:`OtherPairs`).  Embedding: vertices on a
    circle, clockwise by angle (as :func:`~topomark.reference.worlds.deterministic.complete`).  Raises InvalidInput if
    n < 2, fraction is outside (0, 1], the edge count is below n - 1 (no
    connected graph) or the world exceeds the size limits (checked first).
    """
    n = integer_param("n", n, 2)
    f = real_param("fraction", fraction)
    if not 0.0 < f <= 1.0:
        raise InvalidInput(f"fraction must be in (0, 1], got {fraction!r}")
    total = n * (n - 1) // 2
    count = round(f * total)
    check_size(n, count, f"random:n={n},fraction={fraction!r}")
    if count < n - 1:
        raise InvalidInput(
            f"fraction {fraction!r} gives {count} edges, fewer than the {n - 1} a connected graph "
            f"on {n} vertices needs (fraction >= {(n - 1) / total:.4g})"
        )
    rng = random.Random(seed_param(seed))
    order = list(range(n))
    rng.shuffle(order)
    edges = {_pair(order[i], order[rng.randrange(i)]) for i in range(1, n)}
    edges.update(rng.sample(OtherPairs(n, edges), count - len(edges)))
    return on_circle(n, sorted(edges))

