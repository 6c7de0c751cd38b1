"""Mapping with Σ_{k=1}^{n−1} k markers, a unique count per place: Case 3a (Algorithm 6.2), Case 3b and the
Σ k directional vertex-marker algorithm (thesis §6.2.1 Cases 3a and 3b, Figures 6.6–6.8; §6.2.2).

The robot is assured Σ_{k=1}^{n−1} k = n(n−1)/2 homogeneous markers and drops a
*different number* of them at each place it discovers (1, 2, 3, ...), so a
marked place names itself.  It never uses n or m.

* **Case 3b** (:class:`EdgeCounts`, E-markers, O(m), §6.2.1 Case 3b): on entering an
  unmarked v_u (no marked edge) e is a non-loop edge: non-loop augmentation, then
  "the robot goes back to (non-loop) edge e, dropping a unique number of markers
  on e" — the i-th non-loop edge gets i markers, so the marked edges form a
  spanning tree of S.  On entering a v_u with marked edges, the marked edges'
  counts and relative exits (``[4,A,E3-1,E4-2]``, Figure 6.8) name v_u and the
  entry edge e' at once: no motion validates anything.  Loop edges and vertices
  are never marked.  The thesis proves the identification unique (§6.2.1 Case 3b,
  Figure 6.8(c) "can *not* happen"); the explorer checks it and reports
  :class:`~topomark.spec.errors.AlgorithmFailed` if it ever is not.
* **Case 3a** (:class:`VertexCounts`, undirected V-markers, Algorithm 6.2,
  O(m·d_max)): the i-th new vertex gets i markers; a marked v_u is known by its
  count, its back-link by probing its other edges until a known neighbour over
  an explored edge is sensed (lines 19–35).
* **Σ k directional V-markers** (:class:`VertexCounts` with ``directional``,
  O(m), §6.2.2): "the robot drops the markers in such a way that the entry edge is
  indicated (all the markers dropped at v_u have the same direction)", so every
  marked place is a directional lighthouse: place and back-link at once.

Decisions, with the thesis references:

* **Dropping on e is a drop trip**, as §6.2.1 Case 3b describes it: "the robot goes
  back to (non-loop) edge e, dropping" (and Algorithm 6.6 line 10, "goes
  back on e, drops i markers on e and back"): Case 3b walks back over e to v_k,
  drops there on e, and walks back to v_u — two traversals per non-loop edge,
  purpose ``drop``, counted in the cost and in the drop-trip sub-count (the
  accounting rule, and why the §6.2 findings compare the cost without them:
  :mod:`topomark.reference.run.simulator`).  Nothing else depends on the trip,
  so the cost without it is exactly the cost of dropping on e from v_u.
* **Σ^{n−1} against Figure 6.6's Σ^{n}** (Case 3a's title and Algorithm
  6.2's say Σ_{k=1}^{n−1} k; Figure 6.6's caption, Σ_{k=1}^{n} k).
  Both hold, for different kits: §6.2.1 Case 3a "The algorithm marks each of the n
  vertices uniquely, so a total of Σ_{k=1}^{n} k V-markers are used", and with
  exactly Σ_{k=1}^{n−1} k "this vertex must be the last vertex that has not been
  visited and the robot can leave the vertex blank" (Algorithm 6.2 lines 10–16).
  The default kit is the class's Σ_{k=1}^{n−1} k (the last new vertex stays
  blank, recognised by its blank label afterwards, §6.2.1 Case 3a); with ``--markers`` ≥
  Σ_{k=1}^{n} k every vertex is marked, so the vertex algorithms' marker bound is
  Σ_{k=1}^{n} k.  Same for the directional variant, whose blank last vertex has
  no direction (§6.2.2 does not discuss it: "each visited vertex is a directional
  lighthouse" holds for the n − 1 marked ones only).
* **The directional variant explores the blank's edges from the blank.**  A loop
  edge *into* the blank needs Algorithm 6.2's probe search for its back-link
  (lines 19–35): up to deg − 1 probes, each out and back, for each of up to
  deg − 1 such edges — Θ(d_max²) on a wheel whose hub is found last
  (``wheel-hub-last``: cost 2,344 at m = 160), which is no O(m).  But when the
  robot leaves the last new vertex blank it knows that every other place is
  already visited and marked (lines 14–16, §6.2.1 Case 3a: "this vertex must be the last
  vertex that has not been visited"), and it knows the blank's exits relative to
  the edge it entered by.  So once the blank is known, :class:`DirectionalVertexCounts`
  takes the blank's unexplored edges first (walking S back to the blank when it
  is elsewhere), whatever the edge policy: each leads to a marked place, a
  directional lighthouse that gives place and back-link at once (§6.2.2), so it
  closes a loop with no probe, and no edge is ever entered at the blank
  unexplored.  This is a choice of which e leaves U (line 5, left open by the
  thesis), so the algorithm is still Algorithm 6.2 with §6.2.2's markers.  The
  blank's edges then cost at most 2 each beyond the rest of the run, and the
  default kit meets the O(m) registered for Table 6.2's row.  The
  undirected Case 3a is unchanged: a marked place tells no back-link there, so
  nothing is saved (its O(m·d_max), §6.2.1 Case 3a).
* **Fewer markers than assured.**  Case 3b: the refused drop is the ``failed``
  outcome.  The vertex algorithms cannot tell the first shortage from the last
  vertex (the thesis's own rule), so a *second* unmarked place found, or a blank
  whose degree or neighbours contradict the map (a probe that would join it to
  itself or to a neighbour a second time included), is reported as "out of
  markers" (AlgorithmFailed) when the robot notices it.
* Algorithm 6.2 line 21 "for each other edge incident in v_k'": the probes leave
  by the relative exits 1, 2, ..., deg−1 in turn (clockwise from the entry edge),
  each failed probe returning at once (line 33, purpose ``retrace``).

Correspondence with Algorithm 6.2 (``case-3a`` follows it step by step): lines 1–3 →
:meth:`VertexCounts.begin` and the walker's S and U; lines 5–7 → the walker's loop (e from U by the edge
policy, S walked to v_k); lines 8–16 → the first branch of :meth:`VertexCounts.arrive` (line 10's "enough
markers" is the drop the kit accepts, ``try_drop``; line 16's flag is ``blank``); line 18 → ``vertex_of``;
lines 19–35 → :meth:`VertexCounts.probe` and :meth:`VertexCounts.explored_exit` (line 25's "c ∈ s": the
sensed count is a known neighbour over an explored edge of v_k').  Left open: which e leaves U (line 6) and the
order of line 21's edges (clockwise from the entry).  ``case-3b`` (no listing) follows §6.2.1 Case 3b's text:
the drop trip, and observation (2)'s identification with no motion (:meth:`EdgeCounts.identify`).
``case-dv-sum`` (§6.2.2, no listing) is Algorithm 6.2 with directional markers; it changes line 6's order once
the blank is known (``changes`` in its registration, the last decision above);
:class:`ListingDirectionalVertexCounts` (``case-dv-sum-listing``) takes line 6 by the edge policy alone.

Examples
--------
>>> sum_to(4)
10
"""

from __future__ import annotations

from typing import cast

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.marker_walk import MarkerStep, MarkerWalk
from topomark.reference.explorers.policies import bfs

__all__ = ["EdgeCounts", "VertexCounts", "DirectionalVertexCounts", "ListingDirectionalVertexCounts", "sum_to"]


def sum_to(k: int) -> int:
    """Σ_{j=1}^{k} j = k(k+1)/2 (0 for k ≤ 0)."""
    return k * (k + 1) // 2 if k > 0 else 0


class EdgeCounts(MarkerWalk):
    """Case 3b: a unique count of undirected E-markers on each non-loop edge, O(m) (§6.2.1 Case 3b)."""

    name = "case-3b"

    def __init__(self, robot, policies=None, observer=None, options=None):
        super().__init__(robot, policies, observer, options)
        self.next_count = 1  # markers for the next non-loop edge
        self.tree: dict[int, tuple[MapDart, MapDart]] = {}  # count -> (dart, dart) of the marked map edge

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if not sig.edges:  # observation (1): no marked edge at v_u iff v_u is new
            u = self.non_loop(it, sig)
            self.mark_tree_edge(it, u)
        else:
            self.loop(it, self.identify(it, sig))

    def mark_tree_edge(self, it: MarkerStep, u: int) -> bool | None:  # None here; Case 5 tells if it dropped
        """A drop trip: back over e to v_k, drop the next count on e (relative exit 0 there), and back to v_u
        (§6.2.1 Case 3b)."""
        count = self.next_count
        self.leave((u, 0), "drop")
        self.drop(MarkerOp("edge", exit=0, count=count), it)
        self.leave(it.edge, "drop")
        self.record_marks()  # v_u now senses the marked e too
        self.tree[count] = cast("tuple[MapDart, MapDart]", it.joined)  # e was joined
        self.next_count += 1
        return None

    def identify(self, it: MarkerStep, sig: Signature) -> tuple[int, int]:
        """Observation (2): the unexplored dart e' = (v_k', j) whose marks, entered by j, read ``sig``."""
        matches = set()
        for p, count, _ in sig.edges:
            edge = self.tree.get(count)
            if edge is None:
                raise AlgorithmFailed(f"iteration {it.number}: {count} markers on an edge at v_u, but no edge of "
                                      f"the map carries {count}")
            for x, t in edge:
                j = (t - p) % self.M.degree(x)
                if self.M.degree(x) == sig.degree and self.M.arc((x, j)) is None \
                        and signature_at(self.M, x, j) == sig:
                    matches.add((x, j))
        if len(matches) != 1:
            raise AlgorithmFailed(f"iteration {it.number}: the marked edges at v_u, {sig}, fit "
                                  f"{len(matches)} unexplored edges of the map {sorted(matches)}, not one "
                                  "(Figure 6.8(c))")
        return matches.pop()


class VertexCounts(MarkerWalk):
    """Case 3a, Algorithm 6.2: the i-th new vertex gets i undirected V-markers; back-link by probing, O(m·d_max)."""

    name = "case-3a"
    directional = False

    def __init__(self, robot, policies=None, observer=None, options=None):
        super().__init__(robot, policies, observer, options)
        self.count_of: dict[int, int] = {}  # map vertex -> its marker count (0: the blank last vertex)
        self.vertex_of: dict[int, int] = {}  # count -> map vertex
        self.blank: int | None = None  # visitedAllVertices (line 4) once set

    def mark_op(self, count: int) -> MarkerOp:
        """``count`` markers here, pointing at the entry edge if directional (§6.2.2)."""
        return MarkerOp("vertex", count=count, direction=0 if self.directional else None)

    def begin(self) -> None:
        """Lines 1–2: one marker at v0 (pointing at the faced exit, the directional variant)."""
        self.drop(self.mark_op(1))
        self.name_vertex(0, 1)

    def name_vertex(self, v: int, count: int) -> None:
        self.count_of[v] = count
        self.vertex_of[count] = v

    def arrive(self, it: MarkerStep, sig: Signature) -> None:
        if sig.vertex_count == 0 and self.blank is None:  # lines 8-16: a new place
            u = self.non_loop(it, sig)
            count = len(self.count_of) + 1
            if self.try_drop(self.mark_op(count), it):  # lines 10-13
                self.name_vertex(u, count)
            else:  # lines 14-16: not enough markers, so this is the last new vertex: leave it blank
                self.blank = u
                self.name_vertex(u, 0)
            return
        place = self.vertex_of.get(sig.vertex_count)  # line 18: the unique count (0: the blank) names v_u
        if place is None or self.M.degree(place) != sig.degree:
            raise AlgorithmFailed(f"out of markers (fewer than the assured Σ k): iteration {it.number} senses "
                                  f"{sig}, which no place of the map shows")
        if sig.vertex_direction is not None:  # a directional lighthouse: the head points at exit 0 (§6.2.2)
            self.loop(it, (place, (0 - sig.vertex_direction) % sig.degree))
        else:
            self.probe(it, place, sig.degree)

    def degenerate(self, it: MarkerStep, far: MapDart) -> Exception:
        """A join that would make a self-loop or a second edge.  Once a place is left blank, with fewer markers
        than assured a second unmarked place is taken for the blank (the robot cannot tell, §6.2.1 Case 3a): that
        is running out of markers, like any neighbour that contradicts the map (:meth:`explored_exit`).  Before
        (every place uniquely marked), and in the explorers that never leave a place blank, it is a bug."""
        if self.blank is None:
            return super().degenerate(it, far)
        return AlgorithmFailed(f"out of markers (fewer than the assured Σ k): iteration {it.number}: joining e = "
                               f"{it.edge} to e' = {far} would make a self-loop or a second edge")

    def probe(self, it: MarkerStep, x: int, degree: int) -> None:
        """Lines 19–35: traverse the other edges of v_k' = ``x`` until a known neighbour over an explored edge."""
        for p in range(1, degree):
            it.probes += 1
            got = self.robot.move(1, "validation")  # relative exit p: one clockwise from the last edge taken
            t = self.explored_exit(x, got)
            if t is not None:  # lines 25-31: e'' is x's exit t, reached by relative exit p; e' is p before it
                self.loop(it, (x, (t - p) % degree))
                self.position = self.M.target((x, t))
                return
            self.robot.move(0, "retrace")  # line 33/35: back to v_k'
        raise AlgorithmFailed(f"out of markers (fewer than the assured Σ k): iteration {it.number}: no edge of "
                              f"map vertex {x} leads to a known neighbour over an explored edge")

    def explored_exit(self, x: int, sig: Signature) -> int | None:
        """The exit of ``x`` over an explored edge to the place whose marks the robot now senses, or None."""
        y = self.vertex_of.get(sig.vertex_count)
        if sig.vertex_count == 0 and self.blank is None:
            return None  # line 34: an unmarked place before the blank was left: a new one
        if y is None or y == x or self.M.degree(y) != sig.degree:
            raise AlgorithmFailed(f"out of markers (fewer than the assured Σ k): a neighbour of map vertex {x} "
                                  f"senses {sig}, which no other place of the map shows")
        if sig.vertex_direction is not None:  # its head names the dart we entered y by
            far = self.M.arc((y, (0 - sig.vertex_direction) % sig.degree))
            if far is not None and far[0] != x:
                raise AlgorithmFailed(f"out of markers (fewer than the assured Σ k): map vertex {y}'s marked "
                                      f"exit leads to {far[0]}, not to {x}")
            return None if far is None else far[1]
        for t in range(self.M.degree(x)):  # line 25: c in s, the counts at the far ends of x's explored edges
            far = self.M.arc((x, t))
            if far is not None and far[0] == y:
                return t
        return None


class DirectionalVertexCounts(VertexCounts):
    """Σ_{k=1}^{n−1} k directional V-markers, each place a directional lighthouse, O(m) (§6.2.2); the
    blank place's edges are explored from the blank (module docstring)."""

    name = "case-dv-sum"
    directional = True
    literal = False  # True: line 6 by the edge policy alone (ListingDirectionalVertexCounts)

    @property
    def edge_policy(self):
        """The edge policy given, except that the blank place's unexplored edges go first once it is known."""
        return self.policies if self.blank is None or self.literal else _BlankFirst(self.policies, self.blank)


class ListingDirectionalVertexCounts(DirectionalVertexCounts):
    """Algorithm 6.2 as listed with §6.2.2's directional markers (``case-dv-sum-listing``): line 6 takes e by the
    edge policy alone, so a loop edge entering the blank has its back-link probed (lines 19–35)."""

    name = "case-dv-sum-listing"
    literal = True


class _BlankFirst:
    """``policies``, but U's first entry at ``blank`` is taken first while there is one (walking S to it)."""

    def __init__(self, policies, blank: int):
        self.policies, self.blank = policies, blank

    def next_edge(self, S, root: int):
        U = S.unexplored
        k = U.first_at((self.blank,))
        if k is None:
            return self.policies.next_edge(S, root)
        return U.pop(k), bfs(S, root)[2]
