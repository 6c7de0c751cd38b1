"""World generators: the graph classes of thesis §3.5.3 and the examples of §3.2.2.

Every generator returns a :class:`~topomark.spec.world.World` (a rotation
system, §3.1.1) with no markers and no start, except the Figure 3.4/3.6 wheel
pair, which carries the marker the thesis places on it.  Generators are
deterministic: random choices come from ``random.Random(seed)`` only, never
from the global random state.  Impossible parameters raise
:class:`~topomark.spec.errors.InvalidInput` with a message naming the
parameter.

Size: every generator computes n and m from its parameters and refuses, before
building anything, a world above :data:`~topomark.spec.world.MAX_VERTICES`
vertices or :data:`~topomark.spec.world.MAX_EDGES` edges (for ``lattice-hole``
and ``complete-hole`` the full graph they start from; for ``small-world`` the
most edges it can get), so ``lattice:rows=3000,cols=3000`` fails at once with
a message naming the limit instead of running into MemoryError.

Conventions
-----------
* Vertex names are strings: ``"0"``, ``"1"``, ... for numbered vertices and
  ``"r,c"`` for lattice cells (row ``r``, column ``c``).
* The rotation dict lists vertices in natural order (``"2" < "10"``,
  ``"1,2" < "1,10" < "2,0"``), see :func:`natural_key`.
* Geometric worlds are embedded by :func:`from_positions`: each vertex gets a
  point in the plane, and its neighbours are listed clockwise by the angle at
  which they are seen, starting from north.
* "round" below is Python's built-in :func:`round` (halves go to the even
  integer: ``round(2.5) == 2``).

Examples
--------
>>> lattice(3, 4).n, lattice(3, 4).m
(12, 17)
>>> lattice(2, 2).rotation["0,0"]
('0,1', '1,0')
>>> generate("complete", n=5).m
10
"""

from __future__ import annotations

import bisect
import math
import random
import re
from collections import deque
from collections.abc import Sequence
from numbers import Integral, Real
from typing import Any, Callable, Hashable, Iterable, Mapping

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.marker import VertexMarker
from topomark.spec.world import Start, World, check_size

__all__ = [
    "natural_key",
    "from_positions",
    "circle_positions",
    "cycle",
    "chain",
    "lattice",
    "lattice_hole",
    "complete",
    "complete_hole",
    "small_world",
    "random_graph",
    "wheel_pair",
    "wheel_pair_directional",
    "wheel_a",
    "wheel_b",
    "WHEEL_A_ROTATION",
    "WHEEL_B_ROTATION",
    "planar",
    "from_networkx",
    "GENERATORS",
    "PARAMETERS",
    "generate",
    "DEFAULT_WORLD",
]

_TWO_PI = 2.0 * math.pi


# -- small helpers ------------------------------------------------------------
def natural_key(name: str) -> tuple:
    """Sort key putting digit runs in numeric order: ``"2" < "10"``, ``"1,9" < "1,10"``.

    >>> sorted(["10", "2", "1,10", "1,9"], key=natural_key)
    ['1,9', '1,10', '2', '10']
    """
    parts = re.split(r"(\d+)", name)
    # even positions are text, odd positions digit runs: comparisons never mix types
    return tuple(int(p) if i % 2 else p for i, p in enumerate(parts)) + (name,)


def _integer(name: str, value: Any, minimum: int) -> int:
    """``value`` as an int of at most 18 digits (like every JSON and CLI integer) and ``>= minimum``."""
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise InvalidInput(f"{name} must be an integer, got {value!r}")
    if abs(value) >= 10**18:  # checked first: a 5,000-digit int cannot even be printed in the message
        raise InvalidInput(f"{name} is out of range (at most 18 digits)")
    if value < minimum:
        raise InvalidInput(f"{name} must be >= {minimum}, got {value}")
    return int(value)


def _real(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value):
        raise InvalidInput(f"{name} must be a finite number, got {value!r}")
    return float(value)


def _fraction(value: Any, name: str = "fraction") -> float:
    f = _real(name, value)
    if not 0.0 <= f < 1.0:
        raise InvalidInput(f"{name} must be in [0, 1), got {value!r}")
    return f


def _seed(value: Any) -> int:
    return _integer("seed", value, -(2**63))


def _node_name(node: Hashable) -> str:
    """String name of a networkx node: strings as is, tuples joined by commas."""
    if isinstance(node, str):
        return node
    if isinstance(node, tuple):
        return ",".join(str(x) for x in node)
    return str(node)


def _names(nodes: Iterable[Hashable]) -> dict[Hashable, str]:
    names: dict[Hashable, str] = {}
    seen: dict[str, Hashable] = {}
    for node in nodes:
        name = _node_name(node)
        if name in seen:
            raise InvalidInput(f"nodes {seen[name]!r} and {node!r} both have the vertex name {name!r}")
        seen[name] = node
        names[node] = name
    return names


def _simple_graph(graph: Any, who: str) -> nx.Graph:
    if not isinstance(graph, nx.Graph):
        raise InvalidInput(f"{who} needs a networkx graph, got {type(graph).__name__}")
    if graph.is_directed():
        raise InvalidInput(f"{who} needs an undirected graph, got a directed {type(graph).__name__}")
    if graph.is_multigraph():
        raise InvalidInput(f"{who} needs a simple graph, got a {type(graph).__name__} (multi-edges are not allowed, §3.1.1)")
    return graph


def _world_from_neighbours(names: Mapping[Hashable, str], order: Mapping[Hashable, list]) -> World:
    rotation = {names[v]: [names[w] for w in order[v]] for v in names}
    return World({v: rotation[v] for v in sorted(rotation, key=natural_key)})


# -- embeddings ---------------------------------------------------------------
def _clockwise_from_north(dx: float, dy: float) -> float:
    angle = round((math.pi / 2 - math.atan2(dy, dx)) % _TWO_PI, 9)
    return 0.0 if angle >= round(_TWO_PI, 9) else angle


def from_positions(graph_or_edges: nx.Graph | Iterable[tuple[Hashable, Hashable]],
                   pos: Mapping[Hashable, tuple[float, float]]) -> World:
    """Embed a graph drawn in the plane: neighbours listed clockwise by angle (§3.1.1).

    ``graph_or_edges`` is an undirected simple networkx graph or an iterable of
    edges ``(u, v)``; ``pos`` maps every node to a point ``(x, y)`` (y points
    north).  At each vertex ``v`` the neighbour ``w`` is seen at the angle
    ``atan2(y_w - y_v, x_w - x_v)``; the rotation lists the neighbours by
    *decreasing* angle (clockwise, the enumeration rule of §3.1.1), starting
    from the one closest to north measured clockwise (a neighbour due north
    comes first, one just west of north comes last).  Equal angles (angles are
    compared after rounding to 1e-9 rad) are broken by the neighbours' names in
    natural order.  Node names become strings (tuples are joined by commas,
    e.g. ``(2, 3)`` -> ``"2,3"``).

    A drawing without crossings gives a planar (genus 0) rotation system; with
    crossings the result is still a valid rotation system, only of higher genus.

    Raises InvalidInput for a missing or non-finite position, two adjacent
    vertices at the same point, duplicate edges in an edge list, or a graph
    that is not a valid world (disconnected, isolated node, self-loop).

    >>> from_positions([("c", "n"), ("c", "e"), ("c", "w")],
    ...                {"c": (0, 0), "n": (0, 1), "e": (1, 0), "w": (-1, 0)}).rotation["c"]
    ('n', 'e', 'w')
    """
    if isinstance(graph_or_edges, nx.Graph):
        graph = _simple_graph(graph_or_edges, "from_positions")
    else:
        graph = nx.Graph()
        for edge in graph_or_edges:
            try:
                u, v = edge
            except (TypeError, ValueError):
                raise InvalidInput(f"an edge must be a pair of vertices, got {edge!r}") from None
            if graph.has_edge(u, v):
                raise InvalidInput(f"edge ({u!r}, {v!r}) is listed twice")
            graph.add_edge(u, v)
    if graph.number_of_nodes() == 0:
        raise InvalidInput("the graph has no vertices")
    names = _names(graph.nodes)
    points: dict[Hashable, tuple[float, float]] = {}
    for node in graph.nodes:
        if node not in pos:
            raise InvalidInput(f"no position for vertex {names[node]!r}")
        try:
            x, y = pos[node]
            point = (float(x), float(y))
        except (TypeError, ValueError):
            raise InvalidInput(f"position of vertex {names[node]!r} is not a point (x, y): {pos[node]!r}") from None
        if not all(math.isfinite(c) for c in point):
            raise InvalidInput(f"position of vertex {names[node]!r} is not finite: {pos[node]!r}")
        points[node] = point
    order: dict[Hashable, list] = {}
    for v in graph.nodes:
        xv, yv = points[v]
        keyed = []
        for w in graph.neighbors(v):
            if w == v:
                raise InvalidInput(f"self-loop at vertex {names[v]!r}")
            dx, dy = points[w][0] - xv, points[w][1] - yv
            if dx == 0.0 and dy == 0.0:
                raise InvalidInput(
                    f"adjacent vertices {names[v]!r} and {names[w]!r} are at the same position {points[v]}"
                )
            keyed.append((_clockwise_from_north(dx, dy), natural_key(names[w]), w))
        order[v] = [w for _, _, w in sorted(keyed, key=lambda t: (t[0], t[1]))]
    return _world_from_neighbours(names, order)


def circle_positions(n: int) -> dict[int, tuple[float, float]]:
    """Vertex ``k`` of ``0..n-1`` at angle ``2πk/n`` on the unit circle (vertex 0 due east)."""
    return {k: (math.cos(_TWO_PI * k / n), math.sin(_TWO_PI * k / n)) for k in range(n)}


def _on_circle(n: int, edges: Iterable[tuple[int, int]]) -> World:
    graph = nx.Graph()
    graph.add_nodes_from(range(n))
    graph.add_edges_from(edges)
    return from_positions(graph, circle_positions(n))


def planar(graph: nx.Graph) -> World:
    """A planar (genus 0) rotation system of a planar networkx graph.

    Uses :func:`networkx.check_planarity` and the embedding's
    ``neighbors_cw_order``.  The graph must be a valid world (connected, simple,
    every degree >= 1).  Raises InvalidInput if it is not planar.
    """
    graph = _simple_graph(graph, "planar")
    if graph.number_of_nodes() == 0:
        raise InvalidInput("the graph has no vertices")
    is_planar, embedding = nx.check_planarity(graph)
    if not is_planar:
        raise InvalidInput(
            f"the graph is not planar ({graph.number_of_nodes()} vertices, {graph.number_of_edges()} edges); "
            "give node positions to embed it anyway"
        )
    names = _names(graph.nodes)
    order = {v: list(embedding.neighbors_cw_order(v)) if graph.degree(v) else [] for v in graph.nodes}
    return _world_from_neighbours(names, order)


def from_networkx(graph: nx.Graph, pos: Mapping[Hashable, tuple[float, float]] | None = None) -> World:
    """A world from a networkx graph: :func:`from_positions` if ``pos`` is given, else :func:`planar`."""
    if pos is None:
        return planar(graph)
    return from_positions(graph, pos)


# -- basic families -----------------------------------------------------------
def cycle(n: int) -> World:
    """The cycle C_n (n >= 3), the indistinguishable worlds of Figure 3.3 (§3.2.1).

    Vertex ``k`` is joined to ``k±1 (mod n)``; drawn on a circle.
    """
    n = _integer("n", n, 3)
    check_size(n, n, f"cycle:n={n}")
    return _on_circle(n, ((k, (k + 1) % n) for k in range(n)))


def chain(n: int) -> World:
    """The path ("chain") of n >= 2 vertices ``0 - 1 - ... - n-1``, drawn on a horizontal line."""
    n = _integer("n", n, 2)
    check_size(n, n - 1, f"chain:n={n}")
    return from_positions([(k, k + 1) for k in range(n - 1)], {k: (float(k), 0.0) for k in range(n)})


def _lattice_graph(rows: int, cols: int) -> tuple[nx.Graph, dict]:
    graph = nx.grid_2d_graph(rows, cols)
    return graph, {(r, c): (float(c), float(-r)) for r, c in graph.nodes}


def _lattice_size(rows: Any, cols: Any) -> tuple[int, int]:
    rows = _integer("rows", rows, 1)
    cols = _integer("cols", cols, 1)
    if rows * cols < 2:
        raise InvalidInput(f"a {rows}x{cols} lattice has a single vertex of degree 0; it needs at least 2 cells")
    check_size(rows * cols, rows * (cols - 1) + cols * (rows - 1), f"the {rows}x{cols} lattice")
    return rows, cols


def lattice(rows: int, cols: int) -> World:
    """The rows x cols lattice (grid) graph of §3.5.3 (Figure 3.10(a)).

    Cell ``"r,c"`` is drawn at x = c, y = -r (row 0 at the top), so the
    clockwise order at a cell is north, east, south, west (those present).
    n = rows*cols and m = rows*(cols-1) + cols*(rows-1); the embedding is planar.
    """
    rows, cols = _lattice_size(rows, cols)
    graph, pos = _lattice_graph(rows, cols)
    return from_positions(graph, pos)


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


def lattice_hole(rows: int, cols: int, fraction: float = 0.1, remove: str = "vertices", seed: int = 0) -> World:
    """A lattice with holes, §3.5.3 (Figure 3.8(a), Figure 3.10(c)).

    Starts from :func:`lattice` and removes ``round(fraction * N)`` randomly
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
    rows, cols = _lattice_size(rows, cols)
    fraction = _fraction(fraction)
    if remove not in ("vertices", "edges"):
        raise InvalidInput(f"remove must be 'vertices' or 'edges', got {remove!r}")
    rng = random.Random(_seed(seed))
    graph, pos = _lattice_graph(rows, cols)
    what = f"the {rows}x{cols} lattice"
    if remove == "vertices":
        _remove_vertices(graph, round(fraction * graph.number_of_nodes()), rng, what)
    else:
        _remove_edges(graph, round(fraction * graph.number_of_edges()), rng, what)
    return from_positions(graph, pos)


def complete(n: int) -> World:
    """The complete graph K_n (n >= 2), a densely connected world of §3.5.3 (Figure 3.10(b)).

    Embedding rule: vertex ``k`` sits on the unit circle at angle 2πk/n
    (:func:`circle_positions`) and each vertex lists its neighbours clockwise by
    the angle at which it sees them (:func:`from_positions`).  At vertex k the
    neighbours are thus ordered by position around the circle.  The embedding
    is planar for n <= 3 only.
    """
    n = _integer("n", n, 2)
    check_size(n, n * (n - 1) // 2, f"K_{n}")
    return _on_circle(n, ((i, j) for i in range(n) for j in range(i + 1, n)))


def complete_hole(n: int, fraction: float = 0.1, seed: int = 0) -> World:
    """K_n with ``round(fraction * n(n-1)/2)`` random edges removed, §3.5.3 (Figure 3.8(b), 3.10(d)).

    Edges are tried in a random order from ``random.Random(seed)``; an edge
    whose removal would disconnect the graph is skipped.  Same circle
    embedding as :func:`complete`.  Raises InvalidInput for n < 2, fraction
    outside [0, 1), or more removals than a connected graph allows.
    """
    n = _integer("n", n, 2)
    check_size(n, n * (n - 1) // 2, f"K_{n} (built before its edges are removed)")
    fraction = _fraction(fraction)
    rng = random.Random(_seed(seed))
    graph = nx.complete_graph(n)
    _remove_edges(graph, round(fraction * graph.number_of_edges()), rng, f"K_{n}")
    return from_positions(graph, circle_positions(n))


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
    clockwise by angle (as :func:`complete`).
    """
    n = _integer("n", n, 3)
    k = _integer("k", k, 2)
    if k % 2:
        raise InvalidInput(f"k must be even (k/2 nearest neighbours on each side of the ring), got {k}")
    if k >= n:
        raise InvalidInput(f"k must be < n (k={k}, n={n}): a ring of {n} vertices has only {n - 1} other vertices")
    p = _real("p", p)
    if not 0.0 <= p <= 1.0:
        raise InvalidInput(f"p must be a probability in [0, 1], got {p!r}")
    check_size(n, min(n * k, n * (n - 1) // 2) if p > 0 else n * k // 2, f"small-world:n={n},k={k},p={p!r}")
    rng = random.Random(_seed(seed))
    ring = [(u, (u + j) % n) for u in range(n) for j in range(1, k // 2 + 1)]
    graph = nx.Graph()
    graph.add_nodes_from(range(n))
    graph.add_edges_from(ring)
    for u, _v in ring:
        if rng.random() < p:
            w = rng.randrange(n)
            if w != u and not graph.has_edge(u, w):
                graph.add_edge(u, w)
    return from_positions(graph, circle_positions(n))


class _OtherPairs(Sequence):
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

    def __getitem__(self, k: int) -> tuple[int, int]:
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
    all other vertex pairs (:class:`_OtherPairs`).  Embedding: vertices on a
    circle, clockwise by angle (as :func:`complete`).  Raises InvalidInput if
    n < 2, fraction is outside (0, 1], the edge count is below n - 1 (no
    connected graph) or the world exceeds the size limits (checked first).
    """
    n = _integer("n", n, 2)
    f = _real("fraction", fraction)
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
    rng = random.Random(_seed(seed))
    order = list(range(n))
    rng.shuffle(order)
    edges = {tuple(sorted((order[i], order[rng.randrange(i)]))) for i in range(1, n)}
    edges.update(rng.sample(_OtherPairs(n, edges), count - len(edges)))
    return _on_circle(n, sorted(edges))


# -- the Figure 3.4 / 3.6 wheel pair -------------------------------------------
WHEEL_A_ROTATION: dict[str, tuple[str, ...]] = {
    "0": ("1", "2", "3", "4"),
    "1": ("0", "4", "2"),
    "2": ("0", "1", "3"),
    "3": ("0", "2", "4"),
    "4": ("0", "3", "1"),
}
"""Figure 3.4(a): the planar wheel W4 (centre "0", corners "1".."4" clockwise)."""

WHEEL_B_ROTATION: dict[str, tuple[str, ...]] = {
    "0": ("1", "2", "3", "4"),
    "1": ("0", "2", "4"),
    "2": ("0", "3", "1"),
    "3": ("0", "4", "2"),
    "4": ("0", "1", "3"),
}
"""Figure 3.4(b): the same graph with every corner's rotation reversed (genus 1)."""


def wheel_pair() -> tuple[World, World]:
    """The two embedded graphs of Figure 3.4 (§3.2.2), each with an undirected marker at v0.

    Both are the wheel W4: a centre v0 = ``"0"`` (degree 4) joined to four
    corners ``"1".."4"`` (degree 3) that form the 4-cycle 1-2-3-4-1.  The
    centre's clockwise order is (1, 2, 3, 4) in both.

    * (a) :data:`WHEEL_A_ROTATION`, the ordinary planar wheel: corner ``c``
      lists (centre, previous corner, next corner), e.g. 1: (0, 4, 2) -- genus 0.
    * (b) :data:`WHEEL_B_ROTATION`, the twisted wheel: every corner lists
      (centre, next corner, previous corner), e.g. 1: (0, 2, 4) -- genus 1.

    How they were derived: the §3.2.2 proof (Figure 3.5) only fixes that both
    are a marked degree-4 centre with four degree-3 corners forming a cycle,
    and that they differ in the rotations at the corners.  We enumerated every
    world with centre order (1, x, y, z) and each of the 2^4 corner
    orientations, kept those not extended-isomorphic to (a) (no vertex
    bijection with cyclic relabelling of exits; mirror images not allowed),
    and checked robot indistinguishability by a BFS over pairs of robot states
    (vertex, entry) from the marked centre, comparing degree and marker
    presence after every motion.  Up to extended isomorphism exactly one
    embedding survives: all corners reversed, (b).  For it every starting
    facing in (a) is indistinguishable from every starting facing in (b), and
    M = (x, 1, 2, 2, 1) yields degrees 3, 3, 3, 3, 4 with the marker seen
    only at the end, as in the Figure 3.4 caption.  A mixed orientation (some
    corners reversed) is distinguishable from (a).

    Both worlds start at v0 facing corner "1" (any facing gives the same
    perceptions, both worlds being symmetric under rotating the corners).
    """
    marker = (VertexMarker("0"),)
    start = Start("0", "1")
    return World(WHEEL_A_ROTATION, marker, start), World(WHEEL_B_ROTATION, marker, start)


def wheel_pair_directional() -> tuple[World, World]:
    """Figure 3.6: the wheel pair with a directional marker at v0, pointing at corner "1".

    The robot starts at v0 facing the marker head (``Start("0", "1")``).  A
    directional marker whose head is exit h, read by a robot that entered
    through exit j, reads V-((h - j) mod deg).  With the motion convention of
    §3.1.1 (motion l leaves through exit (entry + l) mod deg, l = 0 goes back
    / leaves through the faced exit):

    * M = (0, 1, 2, 2, 1) (Figure 3.6 caption) ends at v0 reading V-3 on (a)
      and V-1 on (b);
    * M = (0, 1, 1) (§3.3 text) ends at v0 reading V-1 on (a) and V-3 on (b).

    The thesis lists V-1 first in both places; under one fixed reading
    convention the two examples cannot both list the left graph first, so the
    caption's order of the two perception sequences is taken as unspecified.
    The readings do not depend on which corner the head points to (both
    worlds are symmetric under rotating the corners).
    """
    marker = (VertexMarker("0", points_to="1"),)
    start = Start("0", "1")
    return World(WHEEL_A_ROTATION, marker, start), World(WHEEL_B_ROTATION, marker, start)


def wheel_a() -> World:
    """Figure 3.4(a), the planar wheel with an undirected marker at v0 (see :func:`wheel_pair`)."""
    return wheel_pair()[0]


def wheel_b() -> World:
    """Figure 3.4(b), the twisted wheel with an undirected marker at v0 (see :func:`wheel_pair`)."""
    return wheel_pair()[1]


# -- registry for the CLI ------------------------------------------------------
GENERATORS: dict[str, Callable[..., World]] = {
    "cycle": cycle,
    "chain": chain,
    "lattice": lattice,
    "lattice-hole": lattice_hole,
    "complete": complete,
    "complete-hole": complete_hole,
    "small-world": small_world,
    "random": random_graph,
    "wheel-a": wheel_a,
    "wheel-b": wheel_b,
}
"""CLI name -> generator function."""

PARAMETERS: dict[str, dict[str, Any]] = {
    "cycle": {"n": 8},
    "chain": {"n": 8},
    "lattice": {"rows": 5, "cols": 5},
    "lattice-hole": {"rows": 10, "cols": 10, "fraction": 0.1, "remove": "vertices", "seed": 0},
    "complete": {"n": 5},
    "complete-hole": {"n": 8, "fraction": 0.1, "seed": 0},
    "small-world": {"n": 20, "k": 4, "p": 0.1, "seed": 0},
    "random": {"n": 10, "fraction": 0.3, "seed": 0},
    "wheel-a": {},
    "wheel-b": {},
}
"""CLI name -> {parameter name: default}.  The default's type is the parameter's type
(int, float or str); ``generate`` fills in missing parameters from here."""


_CLI_NUMBER = {int: re.compile(r"[+-]?[0-9]+"),
               float: re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")}
_CLI_DIGITS = 18  # as for JSON integers (topomark.spec.jsontext.MAX_INT_DIGITS)


def _shown(value: str, limit: int = 40) -> str:
    """``repr(value)`` cut to ``limit`` characters, for messages about hostile parameters."""
    return repr(value) if len(value) <= limit else repr(value[:limit]) + f"... ({len(value):,} characters)"


def _coerce(generator: str, param: str, value: Any, default: Any) -> Any:
    """A parameter value as the type of its default; a string (from the CLI) must be a plain ASCII
    number (no ``nan``, ``1_000`` or non-ASCII digits) of at most 18 digits before the point,
    so no conversion ever costs more than the text is long."""
    kind = type(default)
    if isinstance(value, str) and kind is not str:
        if not _CLI_NUMBER[kind].fullmatch(value):
            raise InvalidInput(f"{generator}: parameter {param} must be {kind.__name__}, got {_shown(value)}")
        mantissa = re.split(r"[.eE]", value.lstrip("+-"))[0]
        if len(mantissa) > _CLI_DIGITS:
            raise InvalidInput(f"{generator}: parameter {param} = {_shown(value)} is out of range "
                               f"(at most {_CLI_DIGITS} digits)")
        return kind(value)
    if kind is float and isinstance(value, Integral) and not isinstance(value, bool):
        return float(value)
    return value


def generate(name: str, **params: Any) -> World:
    """Build the world named ``name`` (a key of GENERATORS) with ``params``.

    Missing parameters take their PARAMETERS defaults; string values (as a CLI
    gives them) are converted to the parameter's type.  Raises InvalidInput
    naming an unknown generator or parameter.

    >>> generate("lattice", rows="3", cols=4).n
    12
    """
    if name not in GENERATORS:
        raise InvalidInput(f"unknown generator {name!r}; known generators: {', '.join(GENERATORS)}")
    defaults = PARAMETERS[name]
    unknown = sorted(set(params) - set(defaults))
    if unknown:
        accepted = ", ".join(defaults) if defaults else "none"
        raise InvalidInput(
            f"generator {name!r} has no parameter {', '.join(map(repr, unknown))} (accepted: {accepted})"
        )
    args = {p: _coerce(name, p, params.get(p, d), d) for p, d in defaults.items()}
    return GENERATORS[name](**args)


def DEFAULT_WORLD() -> World:  # noqa: N802 - the name is part of the CLI contract
    """Quick-start world: a 5x5 lattice with round(0.1 * 25) = 2 cells removed (seed 1), 23 vertices."""
    return lattice_hole(5, 5, fraction=0.1, remove="vertices", seed=1)
