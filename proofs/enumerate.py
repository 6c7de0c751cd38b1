"""Every small embedded world, once up to extended isomorphism (thesis §3.1.1, §3.1.3).

The sufficiency questions of §3.2, §3.7 and §6.1 range over all worlds: all
connected simple graphs, each with every rotation system (clockwise order of
the edges at each vertex).  Two worlds count as the same when they are
extended-isomorphic (§3.1.3: a vertex bijection plus, at each vertex, a cyclic
relabelling of its exits; mirror images differ).

* :func:`connected_graphs` lists connected simple graphs up to graph
  isomorphism: networkx's graph atlas for n ≤ 7 and
  :func:`topomark.proofs.geng.graph_classes` (nauty's geng where installed,
  else :mod:`topomark.proofs.graphs`' vertex augmentation; the same list
  either way) for 8 ≤ n ≤ :data:`MAX_VERTICES`.  Decision: the atlas stays
  for n ≤ 7, although all three give the same classes (tests/test_graphs.py,
  tests/test_geng.py), because the atlas fixes the order of graphs and so of
  worlds, and the census's smallest counterexamples and pinned figures at
  n ≤ 7 come from that order.
* :func:`embedded_worlds` gives, per graph, one rotation system of every orbit
  of the graph's automorphism group acting on its ``∏ (deg v - 1)!`` rotation
  systems — exactly the extended-isomorphism classes on that graph, since
  worlds on non-isomorphic graphs are never extended-isomorphic.  The
  representative is the orbit's least rotation system (in product order),
  found by comparing each with its images: no set of seen systems, so memory
  stays flat at n = 8 (up to 6^8 rotation systems on one graph).
  :mod:`topomark.proofs.burnside` counts the same orbits without listing them.
* :func:`canonical_form` is an independent canonical code of a world with its
  markers (and start, if any): the least code over admissible anchor darts of
  a breadth-first relabelling that starts at the anchor (the standard
  canonical form of connected maps, O(m) per anchor).  Two worlds have equal
  codes iff they are extended-isomorphic preserving markers (and start).

Examples
--------
>>> [sum(1 for w in embedded_worlds(n, 3, min_vertices=n)) for n in (2, 3, 4)]
[1, 2, 9]
"""

from __future__ import annotations

import itertools
from collections import Counter, deque
from typing import Iterator

import networkx as nx
from networkx.algorithms.isomorphism import GraphMatcher

from topomark.proofs.geng import graph_classes
from topomark.spec.errors import InvalidInput
from topomark.spec.signature import signature_at
from topomark.spec.world import World

__all__ = ["connected_graphs", "rotation_systems", "embedded_worlds", "canonical_form", "count_by_size",
           "ATLAS_MAX_VERTICES", "MAX_VERTICES",
           "graph_automorphisms", "world_of_rotation", "check_bounds"]

ATLAS_MAX_VERTICES = 7
MAX_VERTICES = 10
"""Largest n enumerated: n = 10 at max degree 3 is 62,612 worlds, n = 8 at max degree 4 already 7,149,942."""
_END = {None: 0, "H": 1, "T": 2}


# -- graphs up to isomorphism ---------------------------------------------------
def _atlas(n: int, max_degree: int) -> list[nx.Graph]:
    return [g for g in nx.graph_atlas_g()
            if g.number_of_nodes() == n and nx.is_connected(g)
            and max(d for _, d in g.degree()) <= max_degree]


def connected_graphs(n: int, max_degree: int) -> list[nx.Graph]:
    """Connected simple graphs on ``n`` vertices (labelled 0..n-1) with max degree ≤ ``max_degree``."""
    if not 1 <= n <= MAX_VERTICES:
        raise InvalidInput(f"graphs are enumerated for 1..{MAX_VERTICES} vertices, not {n}")
    if n <= ATLAS_MAX_VERTICES:
        return _atlas(n, max_degree)
    return [c.graph() for c in graph_classes(n, max_degree)]


# -- rotation systems up to automorphism ------------------------------------------
def _normal(cycle: list[int]) -> tuple[int, ...]:
    """A cyclic order written from its least element."""
    k = cycle.index(min(cycle))
    return tuple(cycle[k:] + cycle[:k])


def rotation_systems(g: nx.Graph) -> Iterator[tuple[tuple[int, ...], ...]]:
    """Every rotation system of ``g`` (vertices 0..n-1), each cyclic order written from its least neighbour."""
    choices = []
    for v in range(g.number_of_nodes()):
        first, *rest = sorted(g[v])
        choices.append([(first, *perm) for perm in itertools.permutations(rest)])
    return itertools.product(*choices)


def graph_automorphisms(g: nx.Graph) -> list[dict[int, int]]:
    return list(GraphMatcher(g, g).isomorphisms_iter())


def _image(rot: tuple[tuple[int, ...], ...], sigma: dict[int, int]) -> tuple[tuple[int, ...], ...]:
    out: list[tuple[int, ...]] = [()] * len(rot)
    for v, ns in enumerate(rot):
        out[sigma[v]] = _normal([sigma[w] for w in ns])
    return tuple(out)


def _image_is_smaller(rot: tuple[tuple[int, ...], ...], sigma: list[int], inverse: list[int]) -> bool:
    """Whether ``_image(rot, sigma) < rot``, comparing vertex by vertex and stopping at the first difference."""
    for u, mine in enumerate(rot):
        image = _normal([sigma[w] for w in rot[inverse[u]]])
        if image != mine:
            return image < mine
    return False


def _orbit_representatives(g: nx.Graph) -> Iterator[tuple[tuple[int, ...], ...]]:
    """The least rotation system (in product order) of every Aut(g)-orbit.

    Product order is lexicographic order on the tuples: at each vertex the
    choices are equal-length tuples in lexicographic order, and images are
    written the same way (:func:`_normal`).
    """
    n = g.number_of_nodes()
    maps = []
    for sigma in graph_automorphisms(g):
        if any(k != v for k, v in sigma.items()):
            inverse = [0] * n
            for k, v in sigma.items():
                inverse[v] = k
            maps.append(([sigma[v] for v in range(n)], inverse))
    for rot in rotation_systems(g):
        if not any(_image_is_smaller(rot, sigma, inverse) for sigma, inverse in maps):
            yield rot


def world_of_rotation(rot: tuple[tuple[int, ...], ...]) -> World:
    return World({f"v{v}": [f"v{w}" for w in ns] for v, ns in enumerate(rot)})


def check_bounds(max_vertices: int, max_degree: int) -> None:
    """Refuse (bad input) sizes the enumeration does not list."""
    if max_vertices > MAX_VERTICES:
        raise InvalidInput(f"worlds are enumerated up to {MAX_VERTICES} vertices, not {max_vertices}")
    if max_degree < 1:
        raise InvalidInput(f"max degree must be at least 1, not {max_degree}")


def embedded_worlds(max_vertices: int, max_degree: int, min_vertices: int = 2) -> Iterator[World]:
    """Every connected world with ``min_vertices ≤ n ≤ max_vertices`` and degrees ≤ ``max_degree``.

    One world per extended-isomorphism class, vertices named ``v0, v1, ...``,
    in a fixed order (by n, then graph, then rotation system), without markers
    or start.
    """
    check_bounds(max_vertices, max_degree)
    for n in range(max(min_vertices, 2), max_vertices + 1):
        for g in connected_graphs(n, max_degree):
            for rot in _orbit_representatives(g):
                yield world_of_rotation(rot)


def count_by_size(max_vertices: int, max_degree: int, min_vertices: int = 2) -> dict[int, int]:
    """How many embedded worlds there are with n vertices, for each n."""
    counts = Counter(w.n for w in embedded_worlds(max_vertices, max_degree, min_vertices))
    return {n: counts.get(n, 0) for n in range(max(min_vertices, 2), max_vertices + 1)}


# -- canonical form ---------------------------------------------------------------
def _vertex_key(world: World, v: str, markers: bool) -> tuple[int, ...]:
    """An extended-isomorphism invariant of a vertex (ints only)."""
    key = [world.degree(v)]
    if markers:
        sig = signature_at(world, v, 0)
        key += [sig.vertex_count, int(sig.vertex_direction is not None)]
        key += sorted(count * 3 + _END[end] for _, count, end in sig.edges)
    key += sorted(world.degree(w) for w in world.rotation[v])
    return tuple(key)


def _dart_key(world: World, dart: tuple[str, int], markers: bool) -> tuple[int, ...]:
    v, i = dart
    extra = (0, 0)
    if markers:
        sig = signature_at(world, v, i)  # read from the dart itself: relative exit 0 is exit i
        edge = next(((count, end) for x, count, end in sig.edges if x == 0), None)
        extra = (int(sig.vertex_direction == 0), 0 if edge is None else edge[0] * 3 + _END[edge[1]])
    return _vertex_key(world, v, markers) + extra


def _anchors(world: World, markers: bool) -> list[tuple[str, int]]:
    """The darts the canonical form is minimised over (an isomorphism-invariant choice).

    With a start: the start dart alone.  Otherwise: the rarest vertex class
    (ties broken by the class key), then the rarest dart class at those vertices.
    """
    if world.start is not None:
        return [world.start_state()]
    vclasses: dict[tuple[int, ...], list[str]] = {}
    for v in world.vertices:
        vclasses.setdefault(_vertex_key(world, v, markers), []).append(v)
    best_v = min(vclasses, key=lambda k: (len(vclasses[k]), k))
    classes: dict[tuple[int, ...], list[tuple[str, int]]] = {}
    for v in vclasses[best_v]:
        for i in range(world.degree(v)):
            classes.setdefault(_dart_key(world, (v, i), markers), []).append((v, i))
    best = min(classes, key=lambda k: (len(classes[k]), k))
    return classes[best]


def _marks_code(world: World, v: str, offset: int) -> tuple[int, ...]:
    sig = signature_at(world, v, offset)
    code = [sig.vertex_count, -1 if sig.vertex_direction is None else sig.vertex_direction, len(sig.edges)]
    for x, count, end in sig.edges:
        code.extend((x, count, _END[end]))
    return tuple(code)


def _code_from(world: World, anchor: tuple[str, int], markers: bool) -> tuple[int, ...]:
    """Breadth-first relabelling from ``anchor``: vertex labels by discovery, exit 0 = discovery edge."""
    v0, i0 = anchor
    label = {v0: 0}
    offset = {v0: i0}
    order = [v0]
    code: list[int] = [world.n]
    todo = deque([v0])
    while todo:
        v = todo.popleft()
        d = world.degree(v)
        code.append(d)
        for k in range(d):
            w, j = world.target((v, (offset[v] + k) % d))
            if w not in label:
                label[w] = len(order)
                offset[w] = j
                order.append(w)
                todo.append(w)
            code.append(label[w])
        if markers:
            code.extend(_marks_code(world, v, offset[v]))
    return tuple(code)


def canonical_form(world: World, markers: bool = True) -> tuple[int, ...]:
    """A code (tuple of ints) equal for two worlds iff they are extended-isomorphic (§3.1.3).

    With ``markers=True`` markers are part of the code, so isomorphisms must
    preserve them.  If ``world`` has a start, the code is anchored at the
    start dart only, so isomorphisms must also map start to start; drop the
    start (``world.with_start(None)``) to compare placements as marked worlds.
    """
    flag = 1 if world.start is not None else 0
    return (flag,) + min(_code_from(world, a, markers) for a in _anchors(world, markers))
