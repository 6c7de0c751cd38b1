"""Hypothesis strategies for random worlds, and extended-isomorphic copies of worlds.

:func:`worlds` draws valid :class:`~topomark.spec.world.World` objects
(§3.1.1: connected, simple, every degree >= 1) with random clockwise orders,
optionally with markers and a start.  :func:`relabelled` and :func:`rotated`
make copies that are isomorphic under the extended definition of §3.1.3
(vertex renaming; exits relabelled from a different reference edge), which a
correct mapper must not be able to tell apart from the original.

Examples
--------
>>> from hypothesis import given
>>> @given(worlds(max_vertices=5))
... def test(w):
...     assert 2 <= w.n <= 5
>>> test()
"""

from __future__ import annotations

import random
from numbers import Integral
from typing import Mapping

from hypothesis import strategies as st

from topomark.spec.errors import InvalidInput
from topomark.spec.marker import EdgeMarker, Marker, VertexMarker
from topomark.spec.world import Start, World

from topomark.reference.worlds.generators import natural_key

__all__ = ["worlds", "relabelled", "rotated", "MARKER_KINDS"]

MARKER_KINDS = (None, "undirected-vertex", "directional-vertex", "any")


@st.composite
def _worlds(draw, min_vertices: int, max_vertices: int, max_degree: int | None,
            markers: str | None, with_start: bool) -> World:
    n = draw(st.integers(min_vertices, max_vertices))
    names = [str(i) for i in range(n)]
    neighbours: list[list[int]] = [[] for _ in range(n)]

    def free(v: int) -> bool:
        return max_degree is None or len(neighbours[v]) < max_degree

    # a random spanning tree: vertex i joins an earlier vertex with spare degree
    for i in range(1, n):
        open_ = [v for v in range(i) if free(v)]  # never empty when max_degree >= 2 (a leaf has degree 1)
        parent = open_[draw(st.integers(0, len(open_) - 1))]
        neighbours[parent].append(i)
        neighbours[i].append(parent)
    # extra edges, skipping self-loops, repeats and degree overflows
    if n >= 3:
        extra = draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)), max_size=n * (n - 1) // 2))
        for u, v in extra:
            if u != v and v not in neighbours[u] and free(u) and free(v):
                neighbours[u].append(v)
                neighbours[v].append(u)
    # random clockwise orders
    rotation = {
        names[v]: [names[w] for w in draw(st.permutations(sorted(neighbours[v])))] for v in range(n)
    }
    world = World(rotation)

    placed: list[Marker] = []
    if markers in ("undirected-vertex", "directional-vertex"):
        at = draw(st.sampled_from(names))
        head = draw(st.sampled_from(rotation[at])) if markers == "directional-vertex" else None
        placed.append(VertexMarker(at, points_to=head))
    elif markers == "any":
        for v in draw(st.lists(st.sampled_from(names), unique=True, max_size=n)):
            head = draw(st.none() | st.sampled_from(rotation[v]))
            placed.append(VertexMarker(v, count=draw(st.integers(1, 3)), points_to=head))
        edges = list(world.edges())
        for u, v in draw(st.lists(st.sampled_from(edges), unique=True, max_size=len(edges))):
            head = draw(st.sampled_from((None, u, v)))
            placed.append(EdgeMarker((u, v), count=draw(st.integers(1, 3)), head=head))
    start = None
    if with_start:
        at = draw(st.sampled_from(names))
        start = Start(at, draw(st.sampled_from(rotation[at])))
    return World(rotation, placed, start)


def worlds(min_vertices: int = 2, max_vertices: int = 8, max_degree: int | None = None,
           markers: str | None = None, with_start: bool = False) -> st.SearchStrategy[World]:
    """A hypothesis strategy for valid random worlds with ``min_vertices..max_vertices`` vertices.

    Construction: a random spanning tree (so the world is connected), extra
    random edges (no self-loops or multi-edges), then a random clockwise order
    (a permutation) of each vertex's neighbours.  Vertices are named
    ``"0".."n-1"``.

    * ``min_vertices``: a world needs at least 2 vertices (every degree >= 1),
      so 1 is accepted and means 2.
    * ``max_degree``: no vertex gets more neighbours.  With ``max_degree=1``
      the only world is a single edge, so ``max_vertices`` is capped at 2.
    * ``markers``: None (no markers); ``"undirected-vertex"`` (one undirected
      vertex marker at a random vertex); ``"directional-vertex"`` (one
      directional vertex marker pointing at a random neighbour); ``"any"`` (any
      number, possibly zero, of vertex markers and edge markers, each
      undirected or directional, with counts 1-3, at most one entry per vertex
      or edge).
    * ``with_start``: add a random ``Start`` (a vertex and a neighbour it faces).

    Raises InvalidInput for impossible bounds or an unknown marker kind.
    """
    for name, value in (("min_vertices", min_vertices), ("max_vertices", max_vertices)):
        if isinstance(value, bool) or not isinstance(value, Integral):
            raise InvalidInput(f"{name} must be an integer, got {value!r}")
    if min_vertices < 1:
        raise InvalidInput(f"min_vertices must be >= 1, got {min_vertices}")
    if max_degree is not None:
        if isinstance(max_degree, bool) or not isinstance(max_degree, Integral) or max_degree < 1:
            raise InvalidInput(f"max_degree must be a positive integer or None, got {max_degree!r}")
        if max_degree == 1:
            max_vertices = min(max_vertices, 2)
    min_vertices = max(min_vertices, 2)
    if max_vertices < min_vertices:
        raise InvalidInput(
            f"no world has between {min_vertices} and {max_vertices} vertices"
            + (f" with max_degree={max_degree}" if max_degree == 1 else "")
            + " (every world has at least 2 vertices)"
        )
    if markers not in MARKER_KINDS:
        raise InvalidInput(f"markers must be one of {MARKER_KINDS}, got {markers!r}")
    return _worlds(int(min_vertices), int(max_vertices), max_degree, markers, bool(with_start))


def relabelled(world: World, rng_or_permutation: random.Random | Mapping[str, str]) -> World:
    """An extended-isomorphic copy of ``world`` with its vertices renamed.

    ``rng_or_permutation`` is either a mapping old name -> new name (a
    bijection on the vertices; the new names may be any distinct strings) or a
    ``random.Random``, which shuffles the existing names.  Rotations, marker
    positions, marker heads and the start are renamed; the clockwise order at
    every vertex is kept.  The copy lists vertices in natural order of their
    new names.
    """
    old = list(world.vertices)
    if isinstance(rng_or_permutation, random.Random):
        new = old[:]
        rng_or_permutation.shuffle(new)
        mapping = dict(zip(old, new))
    elif isinstance(rng_or_permutation, Mapping):
        mapping = dict(rng_or_permutation)
        missing = [v for v in old if v not in mapping]
        if missing:
            raise InvalidInput(f"the renaming does not name vertex {missing[0]!r}")
        extra = [v for v in mapping if v not in world.rotation]
        if extra:
            raise InvalidInput(f"the renaming names {extra[0]!r}, which is not a vertex")
        images = [mapping[v] for v in old]
        if not all(isinstance(x, str) for x in images):
            raise InvalidInput("new vertex names must be strings")
        if len(set(images)) != len(images):
            raise InvalidInput("the renaming is not one-to-one")
    else:
        raise InvalidInput(f"expected a random.Random or a mapping, got {type(rng_or_permutation).__name__}")

    def rn(v: str | None) -> str | None:
        return None if v is None else mapping[v]

    rotation = {mapping[v]: [mapping[w] for w in ns] for v, ns in world.rotation.items()}
    rotation = {v: rotation[v] for v in sorted(rotation, key=natural_key)}
    markers: list[Marker] = []
    for m in world.markers:
        if isinstance(m, VertexMarker):
            markers.append(VertexMarker(mapping[m.at], m.count, rn(m.points_to)))
        else:
            u, v = m.between
            markers.append(EdgeMarker((mapping[u], mapping[v]), m.count, rn(m.head)))
    start = None if world.start is None else Start(mapping[world.start.at], mapping[world.start.facing])
    return World(rotation, markers, start)


def rotated(world: World, offsets: random.Random | Mapping[str, int]) -> World:
    """An extended-isomorphic copy of ``world`` with each vertex's exits renumbered.

    Vertex ``v``'s clockwise list is rotated left by ``offsets[v]`` (so exit
    ``offsets[v] mod deg`` becomes exit 0); vertices not in ``offsets`` keep
    theirs.  A ``random.Random`` draws a random offset per vertex.  Markers
    and the start refer to vertices by name, so they are unchanged -- a
    directional marker still points at the same neighbour.
    """
    if isinstance(offsets, random.Random):
        rng = offsets
        offsets = {v: rng.randrange(world.degree(v)) for v in world.vertices}
    elif not isinstance(offsets, Mapping):
        raise InvalidInput(f"expected a random.Random or a mapping, got {type(offsets).__name__}")
    for v, k in offsets.items():
        if v not in world.rotation:
            raise InvalidInput(f"offset given for {v!r}, which is not a vertex")
        if isinstance(k, bool) or not isinstance(k, Integral):
            raise InvalidInput(f"offset of {v!r} must be an integer, got {k!r}")
    rotation = {}
    for v, ns in world.rotation.items():
        k = offsets.get(v, 0) % len(ns)
        rotation[v] = ns[k:] + ns[:k]
    return World(rotation, world.markers, world.start)
