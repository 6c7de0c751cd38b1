"""The candidates of the adversarial worst-case search and their moves (thesis §7.2).

§7.2 asks on which graphs the worst case of Algorithm 3.1 occurs and for bounds in terms of the
diameter and the maximum degree (§7.2).  The search (:mod:`.search`) looks for bad worlds by small changes;
this module says what a candidate is and how it may change, so that every candidate is a valid world:
connected, simple, every degree between 1 and the search's maximum degree D, with a start (vertex, the
neighbour it faces).

* A **general** candidate is a :class:`~topomark.spec.world.World` with vertices ``"0"`` … ``"n-1"``.
  :func:`move_world` changes it by one of: a new cyclic order at one vertex of degree >= 3 (a vertex of degree
  <= 2 has only one), an edge added between two vertices of degree < D, an edge removed that is not a bridge
  (so the world stays connected and no degree falls to 0), or the start moved (:data:`MOVES`); or by one of
  the structural moves of :mod:`.structural` (two edges switched, two neighbours transposed, a rotation at the
  marker redrawn), which keep every degree (:data:`ALL_MOVES`).  :func:`random_world` draws
  one: a random spanning tree of degree <= D, then random extra edges up to a random target m, a random
  clockwise order at each vertex and a random start.
* A **lattice-hole** candidate (:class:`LatticeHoles`) is a rows x cols lattice
  (:func:`~topomark.reference.worlds.deterministic.lattice_graph`, embedded by its drawing as
  :mod:`~topomark.reference.worlds.holes` does, §3.5.3) less a set of removed cells.  :func:`move_lattice`
  toggles one cell — puts back a removed cell that touches the lattice, or removes a cell whose removal leaves
  the rest connected with at least 2 cells — or moves the start.

Every random choice is drawn from the ``random.Random`` handed in, never the global random state.

>>> import random
>>> w = random_world(8, 3, random.Random(1))
>>> w.n, max(w.degree(v) for v in w.vertices) <= 3, w.start is not None
(8, True, True)
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from functools import cached_property

import networkx as nx

from topomark.spec.world import Start, World

from topomark.reference.worlds.deterministic import lattice_graph
from topomark.reference.worlds.embedding import from_positions
from topomark.reference.worstcase.structural import STRUCTURAL_MOVES, structural_move

__all__ = ["random_world", "move_world", "graph_of", "LatticeHoles", "random_lattice", "move_lattice", "MOVES",
           "ALL_MOVES"]

MOVES = ("rotation", "add-edge", "remove-edge", "start")
ALL_MOVES = MOVES + STRUCTURAL_MOVES
"""The moves of the search: these four and the structural ones of :mod:`.structural` (``switch``, ``transpose``,
``marker``)."""
_TRIES = 64  # a move that finds nothing to do (no vertex of degree >= 3, no free pair...) tries another kind


def graph_of(world: World) -> nx.Graph:
    """The world's underlying simple graph."""
    return nx.Graph(world.edges())


def _random_start(rotation: dict[str, list[str]] | dict[str, tuple[str, ...]], rng: random.Random) -> Start:
    at = rng.choice(sorted(rotation, key=int) if all(v.isdigit() for v in rotation) else sorted(rotation))
    return Start(at, rng.choice(list(rotation[at])))


def random_world(n: int, max_degree: int, rng: random.Random) -> World:
    """A random connected world on ``"0"`` … ``str(n-1)`` with degrees <= ``max_degree`` (n >= 2, D >= 2).

    A random spanning tree (each vertex, in a random order, joined to a random earlier one of degree < D),
    then random extra edges between vertices of degree < D until m reaches a target drawn uniformly from
    [n − 1, ⌊nD/2⌋] or a round of tries finds no free pair; a random clockwise order at each vertex; a
    random start."""
    order = [str(v) for v in range(n)]
    rng.shuffle(order)
    adj: dict[str, list[str]] = {v: [] for v in order}
    for k in range(1, n):
        free = [u for u in order[:k] if len(adj[u]) < max_degree]  # a tree of degree <= D >= 2 always has one
        u = rng.choice(free)
        adj[u].append(order[k])
        adj[order[k]].append(u)
    target, m = rng.randint(n - 1, n * max_degree // 2), n - 1
    misses = 0
    while m < target and misses < 4 * n:
        u, v = rng.sample(order, 2)
        if v in adj[u] or len(adj[u]) >= max_degree or len(adj[v]) >= max_degree:
            misses += 1
            continue
        adj[u].append(v)
        adj[v].append(u)
        m += 1
    rotation = {str(v): adj[str(v)] for v in range(n)}
    for ns in rotation.values():
        rng.shuffle(ns)
    return World(rotation, (), _random_start(rotation, rng))


def _new_cyclic_order(ns: tuple[str, ...], rng: random.Random) -> list[str]:
    """A clockwise order of ``ns`` (3 or more neighbours) that is a different cyclic order."""
    rest = list(ns[1:])
    while True:  # fixing the first neighbour, the orders of the rest are the cyclic orders
        rng.shuffle(rest)
        if tuple(rest) != ns[1:]:
            return [ns[0], *rest]


def _with(world: World, rotation: dict[str, list[str]]) -> World:
    """The world of ``rotation`` with ``world``'s start; a start facing a removed edge faces its first exit."""
    start = world.start if world.start is not None else _first_dart(rotation)
    if start.facing not in rotation[start.at]:
        start = Start(start.at, rotation[start.at][0])
    return World(rotation, (), start)


def _first_dart(rotation: dict[str, list[str]]) -> Start:
    at = next(iter(rotation))
    return Start(at, rotation[at][0])


def _try_move(world: World, kind: str, max_degree: int, rng: random.Random) -> World | None:
    if kind in STRUCTURAL_MOVES:
        return structural_move(world, kind, max_degree, rng)
    rot = {v: list(ns) for v, ns in world.rotation.items()}
    vertices = list(world.vertices)
    if kind == "rotation":
        branching = [v for v in vertices if len(rot[v]) >= 3]
        if not branching:
            return None
        v = rng.choice(branching)
        rot[v] = _new_cyclic_order(world.rotation[v], rng)
        return _with(world, rot)
    if kind == "add-edge":
        u, v = rng.sample(vertices, 2)
        if v in rot[u] or len(rot[u]) >= max_degree or len(rot[v]) >= max_degree:
            return None
        rot[u].insert(rng.randint(0, len(rot[u])), v)
        rot[v].insert(rng.randint(0, len(rot[v])), u)
        return _with(world, rot)
    if kind == "remove-edge":
        graph = graph_of(world)
        bridges = {frozenset(e) for e in nx.bridges(graph)}
        edges = sorted(tuple(sorted(e, key=int)) for e in graph.edges if frozenset(e) not in bridges)
        if not edges:
            return None
        u, v = rng.choice(edges)
        rot[u].remove(v)
        rot[v].remove(u)
        return _with(world, rot)
    return World(world.rotation, (), _random_start(world.rotation, rng))


def move_world(world: World, max_degree: int, rng: random.Random, kinds: tuple[str, ...] = MOVES) -> World:
    """``world`` changed by one move of ``kinds`` (:data:`MOVES`, or any of :data:`ALL_MOVES`), drawn at random; the result is a valid world
    of the same vertices with degrees in [1, ``max_degree``] and a start.  A kind that finds nothing to do is
    replaced by another draw; moving the start always can (every vertex has a neighbour)."""
    for _ in range(_TRIES):
        moved = _try_move(world, rng.choice(kinds), max_degree, rng)
        if moved is not None:
            return moved
    return _try_move(world, "start", max_degree, rng)  # type: ignore[return-value]


# -- the lattice-hole family (§3.5.3) -------------------------------------------------------
@dataclass(frozen=True)
class LatticeHoles:
    """A rows x cols lattice less the cells in ``holes``, the robot starting at ``start`` (cell, facing cell)."""

    rows: int
    cols: int
    holes: frozenset[tuple[int, int]]
    start: tuple[tuple[int, int], tuple[int, int]]

    def graph(self) -> nx.Graph:
        graph, _ = lattice_graph(self.rows, self.cols)
        graph.remove_nodes_from(self.holes)
        return graph

    @cached_property
    def world(self) -> World:
        graph, pos = lattice_graph(self.rows, self.cols)
        graph.remove_nodes_from(self.holes)
        (a, b) = self.start
        return from_positions(graph, pos).with_start(Start(_name(a), _name(b)))

    def hole_names(self) -> list[str]:
        return [_name(c) for c in sorted(self.holes)]


def _name(cell: tuple[int, int]) -> str:
    return f"{cell[0]},{cell[1]}"


def _start_in(graph: nx.Graph, rng: random.Random) -> tuple[tuple[int, int], tuple[int, int]]:
    at = rng.choice(sorted(graph.nodes))
    return at, rng.choice(sorted(graph.neighbors(at)))


def random_lattice(rows: int, cols: int, rng: random.Random) -> LatticeHoles:
    """A random hole pattern: a fraction drawn from [0, 0.3) of the cells, tried in a random order, each removed
    if the rest stays connected (with at least 2 cells); a random start."""
    graph, _ = lattice_graph(rows, cols)
    cells = sorted(graph.nodes)
    rng.shuffle(cells)
    want = int(rng.uniform(0.0, 0.3) * len(cells))
    holes: set[tuple[int, int]] = set()
    for cell in cells:
        if len(holes) == want:
            break
        if _removable(graph, cell):
            graph.remove_node(cell)
            holes.add(cell)
    return LatticeHoles(rows, cols, frozenset(holes), _start_in(graph, rng))


def _removable(graph: nx.Graph, cell: tuple[int, int]) -> bool:
    """Whether removing ``cell`` leaves at least 2 cells, all connected."""
    if graph.number_of_nodes() <= 2:
        return False
    rest = graph.subgraph(n for n in graph.nodes if n != cell)
    return nx.is_connected(rest)


def move_lattice(cand: LatticeHoles, rng: random.Random) -> LatticeHoles:
    """``cand`` with one cell toggled (kept connected) or its start moved; a start on a removed cell or facing
    one is moved to a random dart of what remains."""
    graph = cand.graph()
    for _ in range(_TRIES):
        if rng.random() < 0.25:
            return LatticeHoles(cand.rows, cand.cols, cand.holes, _start_in(graph, rng))
        cell = (rng.randrange(cand.rows), rng.randrange(cand.cols))
        if cell in cand.holes:
            full, _ = lattice_graph(cand.rows, cand.cols)
            if not any(w in graph for w in full.neighbors(cell)):
                continue  # it would be cut off
            holes = cand.holes - {cell}
            graph.add_edges_from((cell, w) for w in full.neighbors(cell) if w in graph)
        elif _removable(graph, cell):
            holes = cand.holes | {cell}
            graph.remove_node(cell)
        else:
            continue
        start = cand.start if all(c in graph for c in cand.start) else _start_in(graph, rng)
        return LatticeHoles(cand.rows, cand.cols, frozenset(holes), start)
    return LatticeHoles(cand.rows, cand.cols, cand.holes, _start_in(graph, rng))
