"""Embedding a graph as a world: a rotation system from a drawing or a planar embedding (thesis §3.1.1).

The generators (:mod:`topomark.reference.worlds.generators`) build networkx graphs
and turn them into :class:`~topomark.spec.world.World` objects here.

* :func:`from_positions` embeds a graph drawn in the plane: each vertex gets a
  point and lists its neighbours clockwise by the angle at which it sees them,
  starting from north (the enumeration rule of §3.1.1).
* :func:`planar` takes the planar (genus 0) embedding networkx finds;
  :func:`from_networkx` chooses between the two.
* :func:`from_embedding` takes a given networkx ``PlanarEmbedding`` and :func:`from_rotation` a mapping of
  each vertex to its neighbours in clockwise order, as they are.
* Vertex names are strings (tuples joined by commas, ``(2, 3)`` -> ``"2,3"``)
  and the rotation dict lists them in natural order (:func:`natural_key`).
"""

from __future__ import annotations

import math
import re
from typing import Any, Hashable, Iterable, Mapping, cast

import networkx as nx

from topomark.spec.errors import InvalidInput
from topomark.spec.world import World

__all__ = ["natural_key", "from_positions", "circle_positions", "on_circle", "planar", "from_networkx",
           "from_embedding", "from_rotation"]

_TWO_PI = 2.0 * math.pi


# -- names ----------------------------------------------------------------------
def natural_key(name: str) -> tuple:
    """Sort key putting digit runs in numeric order: ``"2" < "10"``, ``"1,9" < "1,10"``.

    >>> sorted(["10", "2", "1,10", "1,9"], key=natural_key)
    ['1,9', '1,10', '2', '10']
    """
    parts = re.split(r"(\d+)", name)
    # even positions are text, odd positions digit runs: comparisons never mix types
    return tuple(int(p) if i % 2 else p for i, p in enumerate(parts)) + (name,)


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


# -- embedding a drawing --------------------------------------------------------
def _clockwise_from_north(dx: float, dy: float) -> float:
    angle = round((math.pi / 2 - math.atan2(dy, dx)) % _TWO_PI, 9)
    return 0.0 if angle >= round(_TWO_PI, 9) else angle


def _graph_of(graph_or_edges: nx.Graph | Iterable[tuple[Hashable, Hashable]]) -> nx.Graph:
    """The simple graph given as is, or built from an edge list (a duplicate edge is refused)."""
    if isinstance(graph_or_edges, nx.Graph):
        return _simple_graph(graph_or_edges, "from_positions")
    graph: nx.Graph[Hashable] = nx.Graph()
    for edge in graph_or_edges:
        try:
            u, v = edge
        except (TypeError, ValueError):
            raise InvalidInput(f"an edge must be a pair of vertices, got {edge!r}") from None
        if graph.has_edge(u, v):
            raise InvalidInput(f"edge ({u!r}, {v!r}) is listed twice")
        graph.add_edge(u, v)
    return graph


def _points(graph: nx.Graph, pos: Mapping[Hashable, tuple[float, float]],
            names: Mapping[Hashable, str]) -> dict[Hashable, tuple[float, float]]:
    """Every node's position as a finite point ``(x, y)`` of floats."""
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
    return points


def _clockwise(graph: nx.Graph, v: Hashable, points: Mapping[Hashable, tuple[float, float]],
               names: Mapping[Hashable, str]) -> list:
    """The neighbours of ``v`` clockwise from north, ties broken by name in natural order."""
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
    return [w for _, _, w in sorted(keyed, key=lambda t: (t[0], t[1]))]


def from_positions(graph_or_edges: nx.Graph | Iterable[tuple[Hashable, Hashable]],
                   pos: Mapping[Any, tuple[float, float]]) -> World:
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
    graph = _graph_of(graph_or_edges)
    if graph.number_of_nodes() == 0:
        raise InvalidInput("the graph has no vertices")
    names = _names(graph.nodes)
    points = _points(graph, pos, names)
    order = {v: _clockwise(graph, v, points, names) for v in graph.nodes}
    return _world_from_neighbours(names, order)


def circle_positions(n: int) -> dict[int, tuple[float, float]]:
    """Vertex ``k`` of ``0..n-1`` at angle ``2πk/n`` on the unit circle (vertex 0 due east)."""
    return {k: (math.cos(_TWO_PI * k / n), math.sin(_TWO_PI * k / n)) for k in range(n)}


def on_circle(n: int, edges: Iterable[tuple[int, int]]) -> World:
    graph: nx.Graph[int] = nx.Graph()
    graph.add_nodes_from(range(n))
    graph.add_edges_from(edges)
    return from_positions(graph, circle_positions(n))


# -- a planar embedding -----------------------------------------------------------
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
    embedding = cast("nx.PlanarEmbedding[Hashable]", embedding)  # planar: the embedding, not a counterexample
    order = {v: list(embedding.neighbors_cw_order(v)) if graph.degree(v) else [] for v in graph.nodes}
    return _world_from_neighbours(names, order)


def from_networkx(graph: nx.Graph, pos: Mapping[Hashable, tuple[float, float]] | None = None) -> World:
    """A world from a networkx graph: :func:`from_positions` if ``pos`` is given, else :func:`planar`."""
    if pos is None:
        return planar(graph)
    return from_positions(graph, pos)


# -- an embedding given ------------------------------------------------------------
def from_embedding(embedding: "nx.PlanarEmbedding[Any]") -> World:
    """The world of a networkx ``PlanarEmbedding``: each vertex's neighbours in the embedding's clockwise order.

    networkx keeps the order as half-edge attributes: ``cw`` of (u, v) is the neighbour of u that follows v
    clockwise, ``ccw`` the one before it; ``neighbors_cw_order`` follows ``cw``.  Drawn by networkx
    (``combinatorial_embedding_to_pos``, y pointing north) that order is clockwise, so it is the rotation of
    §3.1.1 as :func:`from_positions` reads a drawing.  (Beware ``add_half_edge``'s keywords: ``cw=r`` inserts
    the new half-edge just *counter*-clockwise of the reference r, ``ccw=r`` just clockwise of it.)  The list
    of each vertex starts where networkx starts it.  An embedding whose structure networkx itself refuses
    (``check_structure``) is InvalidInput; node names become strings as in :func:`from_positions`.

    A star drawn with leaves north, east and west of its centre (clockwise: n, e, w):

    >>> emb = nx.PlanarEmbedding()
    >>> emb.add_half_edge("c", "n"); emb.add_half_edge("c", "e", ccw="n"); emb.add_half_edge("c", "w", cw="n")
    >>> for leaf in "new":
    ...     emb.add_half_edge(leaf, "c")
    >>> from_embedding(emb).rotation["c"]  # n, e, w in cyclic order
    ('w', 'n', 'e')
    """
    if not isinstance(embedding, nx.PlanarEmbedding):
        raise InvalidInput(f"from_embedding needs a networkx PlanarEmbedding, got {type(embedding).__name__}")
    if embedding.number_of_nodes() == 0:
        raise InvalidInput("the embedding has no vertices")
    try:
        embedding.check_structure()
    except nx.NetworkXException as exc:
        raise InvalidInput(f"the PlanarEmbedding is not a valid embedding: {exc}") from None
    names = _names(embedding.nodes)
    order = {v: list(embedding.neighbors_cw_order(v)) for v in embedding.nodes}
    return _world_from_neighbours(names, order)


def from_rotation(rotation: Mapping[Any, Any]) -> World:
    """The world whose rotation is ``rotation``: each vertex mapped to the list of its neighbours in clockwise
    order, kept in the mapping's order.  Names that are not strings become strings as in :func:`from_positions`;
    an unordered collection of neighbours (a set) is refused, since it gives no clockwise order.

    >>> from_rotation({0: [1, 2], 1: [2, 0], 2: [0, 1]}).rotation
    {'0': ('1', '2'), '1': ('2', '0'), '2': ('0', '1')}
    """
    names = _names(rotation)
    out: dict[str, list[str]] = {}
    for v, around in rotation.items():
        if isinstance(around, (str, bytes)) or not isinstance(around, (list, tuple)):
            raise InvalidInput(f"the neighbours of vertex {names[v]!r} are given as a {type(around).__name__}, "
                               "which has no order: give them as a list in clockwise order")
        out[names[v]] = [names[w] if _hashable(w) and w in names else _node_name(w) for w in around]
    return World(out)


def _hashable(x: Any) -> bool:
    try:
        hash(x)
    except TypeError:
        return False
    return True
