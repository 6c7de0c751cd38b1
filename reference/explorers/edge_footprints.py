"""Mapping with about m undirected immovable markers by searching for footprints: Case 1a (m E-markers),
Case 1b (m + 1 V-E-markers, extendable to m) and Case 2 (m + n E-markers, Algorithm 6.1) (thesis §6.2.1,
Cases 1–2, Figures 6.4, 6.5; the footprints model of [18], §2.3.1).

All three keep S and U (§3.1.3) and take an edge e = (v_k, v_u) from U, walk S
to v_k and follow e (:class:`~topomark.reference.explorers.marker_walk.MarkerWalk`).
A marker at v_u answers "have I been here before?" at once; a marked v_u
is validated "by having the robot search the map S looking for the vertex
which has one more marked edge than is shown on the map":

* **Case 1a** (:class:`EdgeFootprints`): one marker on every
  edge explored.  v_u is new iff none of its other edges is marked.
* **Case 1b** (:class:`VertexEdgeFootprints`): one marker at v0
  and at every new vertex (not on e), one on every loop edge.  v_u is new iff
  it has no vertex marker; c counts its marked (loop) edges only.
* **Case 2** (:class:`DoubleMarkedEdges`, Algorithm 6.1): two
  markers on every non-loop edge, one on every loop edge; candidates must
  show c_1 single- and c_2 double-marked edges.

Correspondence with Algorithm 6.1 (Case 2; Cases 1a and 1b are its text's variants): line 1 →
the walker's S and U; lines 3–4 → the walker's loop; lines 5–8 → :meth:`FootprintSearch.arrive`'s
first branch (:meth:`FootprintSearch.is_new`, :meth:`FootprintSearch.on_new`); lines 9–10 →
:meth:`FootprintSearch.mark_loop_edge` and the move back over e; lines 11–19 →
:meth:`FootprintSearch.search` (:meth:`FootprintSearch.candidates`,
:meth:`FootprintSearch.walk_looking`), then the loop augmentation.

Search (common to the three and to Case 4, :mod:`.closest_first`): on a
marked v_u the robot drops one marker on e (Algorithm 6.1 line 10 "drops a
marker during transit on e"; Figure 6.5(b)), goes back over e to v_k, and
visits the *candidates*: known vertices with the same degree as v_u, an
unexplored edge, and the marks v_u showed (the multiset of marker counts on
its marked edges other than e; Algorithm 6.1 lines 11–12, Algorithm 6.3
line 18).  The one that now senses a marked edge S does not show is v_k',
and that edge is e' (lines 14–18).

Decisions, with the thesis references (each shown in ``tests/test_markers_621.py``):

* **Back to v_k before the search**: Case 1a does not say
  how the robot gets back to S; Figure 6.5(b) and Algorithm 6.1 line 10
  do: "goes back to v_k via e" (purpose ``retrace``).
* **Dropping on e costs nothing extra.**  "during transit on e" (Algorithm
  6.1 line 10, Algorithm 6.3 line 6): the marker on e is dropped from v_u on
  its entry edge after v_u has been sensed, so the sensing excludes e
  ("excluding entry edge e", Algorithm 6.3 line 7), and Algorithm 6.1
  line 7's two markers are dropped while the robot stands at v_u.
* **Which candidates** ("for each other vertex in S", Algorithm 6.1
  line 11): neither v_k nor a known neighbour of v_k (no self-loops, no
  multi-edges, §3.1.1), visited in the preorder of a breadth-first tree of S
  rooted at v_k, each by a shortest path of S; every vertex the robot passes
  is looked at, so one passed on the way is not visited again and the
  search stops wherever v_k' is seen (as in
  :mod:`.movable_marker`).  The walk from v_k through all candidates is at
  most the tree's Euler tour, 2(n − 1) moves (purpose ``validation``).
  This changes the listing's moves (Algorithm 6.1 lines 11–13 visit
  every candidate, v_k's neighbours included, and check each where the
  robot goes): every footprint search's registration says so (``changes``,
  :data:`~topomark.reference.algorithms.registrations.markers_621.SEARCH_CHANGES`).
  ``literal = True`` (the ``-listing`` classes and entries) searches as listed: every vertex of S but v_k
  with an unexplored edge, v_u's degree and its marks, in the same order by the same paths, each checked
  where the robot goes and nowhere on the way.
* **Case 1b with m markers**: the robot learns that it is out
  of markers when a drop is refused (:meth:`MarkerWalk.try_drop`), that is
  *after* walking to v_k and following e in the last iteration, where the
  thesis says "without further motion" (K4: 14 traversals against 12).  The
  walk is needed: an edge never crossed leaves the map undetermined by what
  the robot sensed (a vertex could sit on it; the oracle fails such a map
  with reason ``guess``).  Then v_u new must have degree 1 (left unmarked), or v_u
  marked must be the far end of the one edge e' left in U (S gets e/e'
  unmarked, no search); anything else is the ``failed`` outcome.
* **Case 1b's kit** (a gap in the kernel, reported): the thesis's markers
  are one homogeneous pool dropped at vertices or on edges; the kernel's kit
  counts vertex and edge markers apart.  So ``case-1b`` is given the split
  its m + 1 are spent in (n V-markers, m − n + 1 E-markers, computed by the
  registration from n and m; the robot never sees them).  The m extension
  runs when the last iteration's drop is refused — shown with a kit one
  short in that iteration's kind (K4: n V and m − n E; a chain: n − 1 V).
* **Case 2's count**: titled m + n (Case 2's heading and Algorithm 6.1's title), the text
  counts m + n − 1 ("$m - n + 1$ markers on loop edges and $2(n - 1)$ markers
  on the $n - 1$ non-loop edges", §6.2.1 Case 2); the kit is the assured m + n, the
  marker bound checked is m + n − 1 (every run drops exactly that).

Examples
--------
>>> marks_key(Signature(4, edges=((1, 2, None), (3, 1, None))))
(1, 2)
>>> [c.name for c in (EdgeFootprints, VertexEdgeFootprints, DoubleMarkedEdges)]
['case-1a', 'case-1b', 'case-2']
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed, OutOfMarkers
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.policies import in_preorder, open_ends_beyond, parents_toward
from topomark.reference.explorers.marker_walk import MarkerStep, MarkerWalk

__all__ = ["marks_key", "Marking", "UNDIRECTED", "FootprintSearch", "EdgeFootprints", "VertexEdgeFootprints",
           "DoubleMarkedEdges", "ListingEdgeFootprints", "ListingVertexEdgeFootprints", "ListingDoubleMarkedEdges"]


def marks_key(sig: Signature) -> tuple[int, ...]:
    """What the search matches a vertex by: the marker counts on its marked edges, sorted (c, or c_1 and c_2)."""
    return tuple(sorted(count for _, count, _ in sig.edges))


def map_key(M: PartialMap, v: int) -> tuple[int, ...]:
    """:func:`marks_key` of map vertex ``v`` as the map shows it."""
    return tuple(sorted(dm.count for dm in M.dart_marks(v)))


class Marking:
    """How a footprint search's markers are dropped and read: undirected (Cases 1a, 1b, 2 and 4, §6.2.1).

    Each footprint explorer holds one (``FootprintSearch.marking``, :data:`UNDIRECTED` unless it says
    otherwise); §6.2.2's directional markers are another (:class:`~.edge_info.EdgeInfo`): the heads of the
    markers and which candidates are worth visiting are all that changes (§6.2.2).
    """

    vertex_head: int | None = None  # a V-marker's exit relative to the entry (§6.2.2); None: undirected
    loop_head: str | None = None  # a loop marker's end at v_u ("H"/"T", §6.2.2); None: undirected

    def drop_on_entry(self, walker: "FootprintSearch", it: MarkerStep, count: int) -> None:
        """Drop ``count`` markers on e from v_u (known as map dart (u, 0)); S shows them at both ends."""
        walker.drop(MarkerOp("edge", exit=0, count=count), it)
        walker.note_mark(it.edge, count)

    def candidates(self, walker: "FootprintSearch", it: MarkerStep, places: list[int]) -> list[int]:
        """Of the search's candidates ``places`` (in visiting order), those worth visiting: all of them."""
        return places


UNDIRECTED = Marking()
"""Undirected markers, the footprint searches of §6.2.1."""


class FootprintSearch(MarkerWalk):
    """The footprints loop (Case 1a): a subclass says when v_u is new and what goes on a non-loop edge."""

    name = "footprints"
    loop_markers = 1  # markers on a loop edge (Cases 1a, 1b, 2, 4: one)
    marking: Marking = UNDIRECTED  # how the markers are dropped and read (§6.2.2's directional ones: edge_info)
    literal = False  # True: the search as listed (Algorithm 6.1 lines 11–19): v_k's neighbours too, checked there only

    def is_new(self, sig: Signature) -> bool:
        """v_u has not been visited (E-marker algorithms: no other marked edge, §6.2.1 Case 1a)."""
        return not sig.edges

    def non_loop_markers(self, vk: int) -> int:
        """How many markers go on a non-loop edge e = (v_k, v_u) (0: e is left blank)."""
        raise NotImplementedError

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        it.candidates, it.found = [], None
        if self.is_new(sig):
            count = self.non_loop_markers(it.edge[0])
            u = self.non_loop(it, sig)
            self.on_new(it, u, count)
        else:
            self.validate(it, sig)

    def on_new(self, it: MarkerStep, u: int, count: int) -> None:
        """Non-loop augmentation done (the robot at v_u, entered by e): drop ``count`` markers on e."""
        if count:
            self.marking.drop_on_entry(self, it, count)

    def note_mark(self, dart: MapDart, count: int) -> None:
        """Show ``count`` markers on the edge at map dart ``dart`` (the robot need not stand there)."""
        v, i = dart
        self.M.mark_as_sensed(v, Signature(self.M.degree(v), edges=((i, count, None),)), 0)

    # -- place and back-link validation together (§6.2.1 Case 1a) ------------------------------
    def validate(self, it: MarkerStep, sig: Signature) -> None:
        """v_u is a known place: one marker on e, back to v_k over e, search S for v_k' (Figure 6.4(c, d))."""
        if not self.mark_loop_edge(it, sig):
            return
        self.robot.move(0, "retrace")
        self.position = it.edge
        self.record_marks()  # v_k now shows the marker on e
        x, j, entry = self.search(it, marks_key(sig), sig.degree)
        it.found = x
        self.loop(it, (x, j))
        self.position = (x, entry)
        self.record_marks()  # v_k' now shows the marker on e'

    def mark_loop_edge(self, it: MarkerStep, sig: Signature) -> bool:
        """Drop the loop marker on e from v_u (position unknown: the world changes, S learns it at both
        ends later); False if the step is finished without a search."""
        self.robot.operate(MarkerOp("edge", exit=0, count=self.loop_markers, direction=self.marking.loop_head))
        self.dropped += self.loop_markers
        it.dropped += self.loop_markers
        return True

    def search(self, it: MarkerStep, key: tuple[int, ...], degree: int) -> tuple[int, int, int]:
        """Visit the candidates (those the marking finds worth visiting) until one shows an edge marked that S
        does not show: (v_k', e''s exit, entry)."""
        it.candidates = self.marking.candidates(self, it, self.candidates(it.edge[0], key, degree))
        looked: set[int] = set()
        for target in it.candidates:
            if target in looked:
                continue
            found = self.walk_looking(target, looked)
            if found is not None:
                return found
        raise AlgorithmFailed(f"iteration {it.number}: v_u showed {key} marked edges, but none of the candidates "
                              f"{it.candidates} has one more marked edge than S shows")

    def candidates(self, vk: int, key: tuple[int, ...], degree: int) -> list[int]:
        """Known vertices that could be v_u, in the preorder of a breadth-first tree of S rooted at v_k."""
        M = self.M
        ends = {v for v in M.unexplored.ends() if v != vk} if self.literal else open_ends_beyond(M, vk)
        return in_preorder(M, vk, {v for v in ends if M.degree(v) == degree and map_key(M, v) == key})

    def walk_looking(self, target: int, looked: set[int]) -> tuple[int, int, int] | None:
        """Walk a shortest path of S to ``target``, sensing every vertex entered; at the first one showing a
        marked edge S does not show, stop: (that vertex, the marked exit, the entry)."""
        parent = parents_toward(self.M, self.position[0], target)
        for dart in self.path_to(target, parent):
            sig = self.leave(dart, "validation")
            v, entry = self.position
            if self.literal and v != target:  # as listed: "robot goes there, sensing the marked edges there"
                continue
            looked.add(v)
            shown = self.map_signature(v, entry).edges
            extra = set(sig.edges) - set(shown) if sig.edges != shown else ()  # (the same edges: nothing more)
            if extra:
                (p, count, _), = extra
                j = (entry + p) % self.M.degree(v)
                if count != self.loop_markers or (v, j) not in self.M.unexplored:
                    raise AlgorithmFailed(f"map vertex {v} shows {count} unexpected marker(s) on exit {j}, "
                                          "which is not an unexplored edge carrying the loop marker")
                return v, j, entry
        return None


class EdgeFootprints(FootprintSearch):
    """Case 1a: one undirected E-marker on every edge explored, m in all, O(mn) (Figure 6.4)."""

    name = "case-1a"

    def non_loop_markers(self, vk: int) -> int:
        return 1


class ListingEdgeFootprints(EdgeFootprints):
    """Case 1a with the search as listed (``case-1a-listing``; Algorithm 6.1 lines 11–19)."""

    name, literal = "case-1a-listing", True


class DoubleMarkedEdges(FootprintSearch):
    """Case 2, Algorithm 6.1: two markers on each non-loop edge, one on each loop edge; m + n − 1 in all."""

    name = "case-2"

    def non_loop_markers(self, vk: int) -> int:
        return 2


class ListingDoubleMarkedEdges(DoubleMarkedEdges):
    """Case 2, Algorithm 6.1 as listed (``case-2-listing``): its search as lines 11–19 list it."""

    name, literal = "case-2-listing", True


class VertexEdgeFootprints(FootprintSearch):
    """Case 1b: a V-marker at every vertex, an E-marker on every loop edge; m + 1 in all, m with the
    extension (§6.2.1 Case 1b, Figure 6.5)."""

    name = "case-1b"

    def begin(self) -> None:
        """"Initially the robot drops a marker at its starting vertex v_0" (§6.2.1 Case 1b)."""
        self.drop(MarkerOp("vertex", direction=self.marking.vertex_head))

    def is_new(self, sig: Signature) -> bool:
        """"if v_u does not contain a marker then v_u has not been visited before" (§6.2.1 Case 1b)."""
        return sig.vertex_count == 0

    def non_loop_markers(self, vk: int) -> int:
        return 0  # "(but not on the entry edge e)"

    def on_new(self, it: MarkerStep, u: int, count: int) -> None:
        """A marker at v_u; refused, this is the last iteration (§6.2.1 Case 1b): v_u must have no other edge."""
        marked = self.try_drop(MarkerOp("vertex", direction=self.marking.vertex_head), it)
        if not marked and (self.M.degree(u) != 1 or self.M.unexplored):
            raise AlgorithmFailed(f"out of markers at iteration {it.number}: the new vertex cannot be marked and "
                                  f"exploration is not over ({len(self.M.unexplored)} unexplored edges)")

    def mark_loop_edge(self, it: MarkerStep, sig: Signature) -> bool:
        """The marker on e; refused, the one edge left in U must be e' (§6.2.1 Case 1b): e/e' with no search."""
        try:
            return super().mark_loop_edge(it, sig)
        except OutOfMarkers:
            left = list(self.M.unexplored)
        if len(left) == 1 and signature_at(self.M, *left[0]) == sig:
            self.loop(it, left[0])  # the robot stands at v_k', entered by e'
            return False
        raise AlgorithmFailed(f"out of markers at iteration {it.number}: the loop edge cannot be marked and "
                              f"{len(left)} unexplored edges are left")


class ListingVertexEdgeFootprints(VertexEdgeFootprints):
    """Case 1b with the search as listed (``case-1b-listing``; Algorithm 6.1 lines 11–19, Case 1b's text)."""

    name, literal = "case-1b-listing", True
