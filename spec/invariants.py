"""The loop invariants I-1 and I-2 of Algorithm 3.1 (thesis §3.4).

* **I-1** S is isomorphic to G_s, the explored subgraph of the world G.
* **I-2** U contains a set of edges that may be bijectively mapped to the set
  of unexplored edges in G that have at least one incident vertex in G_s, with
  edge indices with respect to the end vertices in S satisfying the
  edge-index condition.

Both are pure functions of (S, U, world, φ).  The correspondence φ from S to G
is not taken on trust from an explorer: S is connected, so φ is fixed by the
image of one dart (the *anchor*, for Algorithm 3.1 the directional marker's
head dart at v0), and :func:`correspondence` propagates it through S's
explored edges.  A failure to propagate *is* an I-1 violation.

Each check returns ``None`` or a :class:`~topomark.spec.errors.Violation`
naming the invariant, the offending vertex or dart, and expected vs found.

Examples
--------
>>> from topomark.spec.world import World
>>> from topomark.spec.marker import VertexMarker
>>> from topomark.spec.mapstate import PartialMap
>>> w = World({"a": ["b"], "b": ["a"]}, [VertexMarker("a", points_to="b")])
>>> S = PartialMap(); v0 = S.add_vertex(1); S.mark_vertex(v0, head=0); S.unexplored = [(0, 0)]
>>> check_invariants(S, w, ((0, 0), ("a", 0))) is None
True
>>> S.unexplored = []
>>> print(check_invariants(S, w, ((0, 0), ("a", 0))))
I-2 violated at world dart ('a', 0): expected an entry in U (the edge 'a'-'b' is unexplored), found none
"""

from __future__ import annotations

from collections import Counter

from .errors import Violation
from .isomorphism import IsoResult, Witness, anchored
from .mapstate import MapDart, PartialMap
from .world import Dart, World

__all__ = ["Anchor", "correspondence", "check_I1", "check_I2", "check_invariants", "lighthouse_anchor",
           "explored_world_darts"]

Anchor = tuple[MapDart, Dart]


def lighthouse_anchor(S: PartialMap, world: World) -> Anchor | None:
    """The anchor fixed by a directional vertex marker: the map's head dart ↦ the world's head dart."""
    mapped = [(v, S.vertex_mark(v)) for v in S.vertices if S.vertex_mark(v) and S.vertex_mark(v).head is not None]
    real = [(v, world.vertex_mark(v)) for v in world.vertices
            if world.vertex_mark(v) and world.vertex_mark(v).head is not None]
    if len(mapped) != 1 or len(real) != 1:
        return None
    return ((mapped[0][0], mapped[0][1].head), (real[0][0], real[0][1].head))


def correspondence(S: PartialMap, world: World, anchor: Anchor) -> IsoResult:
    """φ: the embedding of S's explored part into the world, propagated from ``anchor``."""
    return anchored(S, world, anchor[0], anchor[1], markers=True, partial=True)


def check_I1(S: PartialMap, world: World, anchor: Anchor, phi: IsoResult | None = None) -> Violation | None:
    """I-1: S is (extended-)isomorphic to G_s under the φ that ``anchor`` fixes (``phi``: that φ, if computed)."""
    if S.n == 0:
        return Violation("I-1", "S", "at least the start vertex v0", "an empty map")
    phi = phi or correspondence(S, world, anchor)
    if not phi.isomorphic:
        m = phi.mismatch
        return Violation("I-1", m.where, m.expected, m.found, m.detail or "S is not isomorphic to G_s")
    missing = [v for v in S.vertices if v not in phi.witness.vertex_map]
    if missing:
        return Violation("I-1", f"map vertex {missing[0]}", "connected to v0 through explored edges",
                         "not connected", "S must be connected")
    return None


def explored_world_darts(S: PartialMap, phi: Witness) -> set[Dart]:
    """φ(E_S) as world darts (both directions of each explored edge)."""
    f, r = phi.vertex_map, phi.offsets
    out = set()
    for v in S.vertices:
        d, fv, rv = S.degree(v), f[v], r[v]
        out.update((fv, (i + rv) % d) for i in range(d) if S.arc((v, i)) is not None)
    return out


def check_I2(S: PartialMap, world: World, phi: Witness) -> Violation | None:
    """I-2: U ↔ unexplored world edges at G_s vertices, bijectively, with the edge-index condition.

    An unexplored edge with both ends in G_s is listed once from each end (the
    thesis's e and e' of a loop edge), so the bijection is between entries of
    U and unexplored *darts* leaving G_s.  The entry (v, i) must name exit
    ``(i + r_v) mod deg`` of φ(v) — the edge-index condition.
    """
    counts = Counter(S.unexplored)
    for dart, k in counts.items():
        v, i = dart
        if not (0 <= v < S.n and 0 <= i < S.degree(v)):
            return Violation("I-2", f"U entry {dart}", "a dart of S", "no such vertex or exit")
        if k > 1:
            return Violation("I-2", f"U entry {dart}", "listed once", f"listed {k} times")
    explored = explored_world_darts(S, phi)
    gs = set(phi.vertex_map.values())
    expected = {(x, i) for x in gs for i in range(world.degree(x))} - explored
    images: dict[Dart, MapDart] = {}
    for dart in S.unexplored:
        img = phi.image(S, dart)
        if S.arc(dart) is not None or img in explored:
            w = world.neighbour(*img)
            return Violation("I-2", f"U entry {dart}", "an unexplored edge",
                             f"world dart {img} (edge {img[0]!r}-{w!r}) is already explored in S",
                             "an explored edge was left in U")
        images[img] = dart
    for dart in sorted(expected - set(images), key=str):
        w = world.neighbour(*dart)
        return Violation("I-2", f"world dart {dart}", f"an entry in U (the edge {dart[0]!r}-{w!r} is unexplored)",
                         "none")
    return None


def check_invariants(S: PartialMap, world: World, anchor: Anchor) -> Violation | None:
    """I-1 then I-2; the first violation found, or None."""
    phi = correspondence(S, world, anchor)
    v = check_I1(S, world, anchor, phi)
    if v is not None:
        return v
    return check_I2(S, world, phi.witness)
