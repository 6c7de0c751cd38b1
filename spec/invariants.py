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
from typing import Any, Iterable

from topomark.spec.errors import Violation, TopomarkFault
from topomark.spec.isomorphism import IsoResult, Witness, anchored
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.unexplored import Unexplored
from topomark.spec.world import Dart, World

__all__ = ["Anchor", "correspondence", "check_I1", "check_I2", "check_invariants", "lighthouse_anchor",
           "explored_world_darts", "explored_subgraph", "IncrementalInvariants", "check_lemma1"]

Anchor = tuple[MapDart, Dart]


def lighthouse_anchor(S: PartialMap, world: World) -> Anchor | None:
    """The anchor fixed by a directional vertex marker: the map's head dart ↦ the world's head dart."""
    mapped = [(v, m.head) for v in S.vertices if (m := S.vertex_mark(v)) and m.head is not None]
    real = [(v, m.head) for v in world.vertices if (m := world.vertex_mark(v)) and m.head is not None]
    if len(mapped) != 1 or len(real) != 1:
        return None
    return (mapped[0], real[0])


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
        assert m is not None, "a negative IsoResult carries its mismatch"
        return Violation("I-1", m.where, m.expected, m.found, m.detail or "S is not isomorphic to G_s")
    witness = phi.witness
    assert witness is not None, "a positive IsoResult carries its witness"
    missing = [v for v in S.vertices if v not in witness.vertex_map]
    if missing:
        return Violation("I-1", f"map vertex {missing[0]}", "connected to v0 through explored edges",
                         "not connected", "S must be connected")
    return None


def explored_subgraph(S: PartialMap, phi: Witness) -> tuple[frozenset[str], frozenset[frozenset[str]]]:
    """G_s (§3.4): the world vertices φ(V_S) and world edges φ(E_S) explored so far."""
    vertices = frozenset(phi.vertex_map[v] for v in S.vertices)
    edges = frozenset(frozenset((phi.vertex_map[v], phi.vertex_map[t[0]]))
                      for v, i in S.darts() if (t := S.arc((v, i))) is not None)
    return vertices, edges


def explored_world_darts(S: PartialMap, phi: Witness) -> set[Dart]:
    """φ(E_S) as world darts (both directions of each explored edge)."""
    f, r = phi.vertex_map, phi.offsets
    out: set[Dart] = set()
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
    for dart in S.unexplored:
        if not (isinstance(dart, tuple) and len(dart) == 2 and all(isinstance(x, int) for x in dart)):
            return Violation("I-2", f"U entry {dart!r}", "a dart of S: a (vertex, exit) pair of integers",
                             f"{type(dart).__name__} {dart!r}")
        v, i = dart
        if not (0 <= v < S.n and 0 <= i < S.degree(v)):
            return Violation("I-2", f"U entry {dart}", "a dart of S", "no such vertex or exit")
    for dart, k in Counter(S.unexplored).items():
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


def check_lemma1(hypotheses: Iterable[Any]) -> Violation | None:
    """Lemma 1 (§3.4): the pairs (M, P^E) of one iteration's hypotheses are pairwise distinct.

    ``hypotheses`` are objects with ``dart``, ``motions`` and ``expected``
    (tuples); the first pair of hypotheses sharing (M, P^E), or None.
    """
    seen: dict[tuple[Any, ...], list[Any]] = {}  # M -> the hypotheses with that M (P^E compared only when M is shared)
    for h in hypotheses:
        same_m = seen.setdefault(tuple(h.motions), [])
        for other in same_m:
            if tuple(other.expected) == tuple(h.expected):
                return Violation("Lemma 1", f"hypotheses {other.dart} and {h.dart}", "distinct (M, P^E) pairs",
                                 f"both M={list(h.motions)}, P^E={[str(x) for x in h.expected]}")
        same_m.append(h)
    return None


def check_invariants(S: PartialMap, world: World, anchor: Anchor) -> Violation | None:
    """I-1 then I-2; the first violation found, or None."""
    phi = correspondence(S, world, anchor)
    v = check_I1(S, world, anchor, phi)
    if v is not None:
        return v
    assert phi.witness is not None, "I-1 holds, so φ is an embedding"
    return check_I2(S, world, phi.witness)


def _changed_places(a: World, b: World) -> set[str] | None:
    """The world vertices whose marks (vertex, edge, thread) differ between ``a`` and ``b``, two states of one
    run's world (same rotation); None when the rotations differ (then every place must be re-checked)."""
    if a.rotation is not b.rotation and a.rotation != b.rotation:
        return None
    out: set[str] = set()
    for da, db in ((a._vmarks, b._vmarks), (a._dmarks, b._dmarks),
                   (getattr(a, "thread_marks", None) or {}, getattr(b, "thread_marks", None) or {})):
        # a place's marks carried over unchanged are the same object in both (is): compared only otherwise
        out.update(x for x, mark in db.items() if da.get(x) is not mark and da.get(x) != mark)
        out.update(da.keys() - db.keys())
    return out


class IncrementalInvariants:
    """I-1 and I-2 checked per change of S, for long runs (§3.4).

    Algorithm 3.1 only ever *adds* to S — a vertex with its degree, an edge,
    a mark — and :class:`~topomark.spec.mapstate.PartialMap` journals each
    addition.  Given that S before the change satisfied I-1 under φ, S after
    it does iff every journalled edge is consistent with φ: a loop edge joins
    the two map darts whose images are the two ends of one world edge, and a
    non-loop edge maps its new vertex to the far end of that world edge, a
    world vertex not yet in G_s, with the same degree and marks.  I-2 is then
    a set comparison of U with the maintained preimage under φ of the
    unexplored world darts leaving G_s (U must list each exactly once); on a
    mismatch :func:`check_I2` names the fault.  U is counted from its record of
    entries added and removed (:class:`~topomark.spec.unexplored.Unexplored`),
    as S is from its journal, so each update costs O(change) instead of
    O(n + m).  Like S's journal, the record is written by U's own list methods:
    an explorer that goes round them (``list.append(U, x)``) is caught when U's
    length disagrees, and one that also keeps the length (``list.__setitem__``)
    only by ``check_mode="full"`` or ``"both"``, which count U whole.

    Equivalence with :func:`check_I1`/:func:`check_I2` on append-only maps is
    tested on every explorer run in ``tests/test_checker.py``; the final
    verdict of a run always uses the full predicates.
    """

    def __init__(self, S: PartialMap, world: World, anchor: Anchor):
        self.world = world
        (v0, i0), (x0, k0) = anchor
        self.f: dict[int, str] = {}
        self.r: dict[int, int] = {}
        self.inv: dict[str, int] = {}
        self.open: set[Dart] = set()
        self.open_map: set[MapDart] = set()  # the preimage of ``open`` under the correspondence
        self.degrees: dict[int, int] = {}
        self.pos = 0
        self._anchor = (v0, x0, (k0 - i0))
        self.S = S
        self._passed: tuple[int, World | None, set[int]] = (-1, None, set())  # _marks_once's (S, world, passed)
        self._u: Unexplored | None = None  # the U last counted (_count_u), how much of its record was taken in,
        self._u_seen, self._u_len = 0, 0  # and the counts
        self._u_count: Counter[Any] = Counter()
        self._u_off: set[Any] = set()

    def _map_vertex(self, v: int, x: str, r: int) -> Violation | None:
        d = self.degrees.get(v)
        if x in self.inv:
            return Violation("I-1", f"map vertex {v}", f"a place not yet in G_s (it is world vertex {x!r})",
                             f"{x!r}, already map vertex {self.inv[x]}", "two map vertices for one place")
        if d != self.world.degree(x):
            return Violation("I-1", f"map vertex {v}", f"degree {self.world.degree(x)} (world vertex {x!r})",
                             f"degree {d}")
        self.f[v], self.r[v], self.inv[x] = x, r % d, v
        self.open.update((x, k) for k in range(d))
        self.open_map.update((v, i) for i in range(d))
        self._recount([(v, i) for i in range(d)])
        return self._marks_once(v)

    def _marks_once(self, v: int) -> Violation | None:
        """:meth:`_marks`, skipped for a vertex that passed it since S (its journal's length) and the world
        last changed: the same S and world give the same verdict."""
        length, world, passed = self._passed
        if length != len(self.S.journal) or world is not self.world:
            self._passed = length, world, passed = len(self.S.journal), self.world, set()
        if v in passed:
            return None
        bad = self._marks(v)
        if bad is None:
            passed.add(v)
        return bad

    def _marks(self, v: int) -> Violation | None:
        from topomark.spec.isomorphism import describe_marks, marks_at
        x = self.f[v]
        ma, mb = marks_at(self.S, v, self.r[v]), marks_at(self.world, x, 0)
        if ma != mb:
            return Violation("I-1", f"map vertex {v} (world {x!r})", describe_marks(mb), describe_marks(ma),
                             "markers are not preserved")
        return None

    def image(self, dart: MapDart) -> Dart:
        v, i = dart
        return (self.f[v], (i + self.r[v]) % self.degrees[v])

    def rebase(self, world: World) -> Violation | None:
        """Markers dropped or picked up since the last update (§6.2: "markers dropped during a run are part of
        the world from then on"): judge against ``world`` from now on, and re-check the marks of every place
        already mapped — S must show what now lies there."""
        if world is self.world:
            return None
        changed = _changed_places(self.world, world)
        self.world = world
        for v in self.f if changed is None else [self.inv[x] for x in changed if x in self.inv]:
            bad = self._marks_once(v)
            if bad is not None:
                return bad
        return None

    def _edge(self, a: MapDart, b: MapDart) -> Violation | None:
        if a[0] not in self.f:
            a, b = b, a
        if a[0] not in self.f:
            return Violation("I-1", f"map edge {a}-{b}", "an edge touching the explored map", "a detached edge",
                             "S must be connected")
        x, k = self.image(a)
        y, j = self.world.target((x, k))
        if b[0] not in self.f:
            bad = self._map_vertex(b[0], y, j - b[1])
            if bad is not None:
                return bad
        elif self.image(b) != (y, j):
            return Violation("I-1", f"map edge {a}-{b}",
                             f"world edge {x!r}-{y!r}: map dart {b} should be world dart {(y, j)}",
                             f"map dart {b} is world dart {self.image(b)}", "the edge is indexed or placed wrongly")
        self.open.discard((x, k))
        self.open.discard((y, j))
        self.open_map.difference_update((a, b))
        self._recount((a, b))
        return None

    def update(self, check_u: bool = True) -> Violation | None:
        """Consume the journal since the last update; the first I-1 or (``check_u``) I-2 violation, or None."""
        S, journal = self.S, self.S.journal
        for op in journal[self.pos:]:
            self.pos += 1
            bad = None
            if op[0] == "vertex":
                self.degrees[op[1]] = op[2]
                if op[1] == self._anchor[0] and not self.f:
                    bad = self._map_vertex(op[1], self._anchor[1], self._anchor[2])
            elif op[0] == "edge":
                bad = self._edge(op[1], op[2])
            elif op[1] in self.f:
                bad = self._marks_once(op[1])
            if bad is not None:
                return bad
        if len(self.f) != S.n:
            lost = next(v for v in S.vertices if v not in self.f)
            return Violation("I-1", f"map vertex {lost}", "connected to v0 through explored edges", "not connected")
        return self._check_u() if check_u else None

    def _check_u(self) -> Violation | None:
        """I-2 holds iff U lists each open dart exactly once: no dart is listed a number of times other than
        its membership of ``open_map`` (:meth:`_count_u`); else :func:`check_I2` names the fault."""
        try:
            counted = self._count_u()
        except TypeError:  # an entry that is not a dart at all
            counted = False
        if counted:
            return None
        self._u = None  # U is counted whole at the next look (its record may have gone round U)
        return self._diagnose_u()

    def _count_u(self) -> bool:
        """Take in U's changes since the last look (a new U object: all of it); True if no dart is off.

        The count is the checker's own, from U's record of entries added and removed
        (:attr:`~topomark.spec.unexplored.Unexplored.changes`); U's length must agree with it."""
        U = self.S.unexplored
        if not isinstance(U, Unexplored):  # not kept by the spec's list: count it whole
            listed = set(U)
            return len(listed) == len(U) and listed == self.open_map
        if U is not self._u:
            self._u, self._u_seen, self._u_count, self._u_off = U, len(U.changes), Counter(U), set()
            self._u_len = len(U)
            self._recount(list(self._u_count) + list(self.open_map))
        else:
            for sign, dart in U.changes[self._u_seen:]:
                self._u_count[dart] += sign
                self._u_len += sign
                self._recount((dart,))
            self._u_seen = len(U.changes)
        return not self._u_off and self._u_len == len(U)

    def _recount(self, darts: Iterable[Any]) -> None:
        """Note whether each of ``darts`` is listed in U as often as it is open (once, or never)."""
        if self._u is None:
            return
        for dart in darts:
            if self._u_count[dart] != (dart in self.open_map):
                self._u_off.add(dart)
            else:
                self._u_off.discard(dart)

    def _diagnose_u(self) -> Violation:
        """U is not the open darts listed once: name the fault as the full predicate does."""
        found = check_I2(self.S, self.world, self.phi())
        if found is None:
            raise TopomarkFault(f"topomark's incremental I-2 check rejects U ({len(self.S.unexplored)} entries, "
                                f"{len(self.open_map)} open darts) but the full predicate accepts it",
                                check="incremental and full I-2 agree")
        return found

    def phi(self) -> Witness:
        return Witness(dict(self.f), dict(self.r))
