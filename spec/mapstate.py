"""The map state: the partial map S and its unexplored darts U (thesis §3.1.3).

S is an embedded graph that grows one edge per iteration.  Its vertices are
numbered 0, 1, ... in order of discovery (v0 = 0).  Each vertex knows its
degree, because the robot sensed it; each exit either leads to a known
``(vertex, entry)`` of S or is still *unexplored*.  U is kept as an explicit,
ordered list of darts so that an explorer that forgets to remove an entry (or
adds one twice) is caught by invariant I-2 (§3.4) rather than hidden by a
derived value; the list keeps count of its ends and of its changes
(:mod:`topomark.spec.unexplored`).

Marks in S mirror markers in the world in exit indices: the directional
lighthouse of §3.3 at v0 is ``mark_vertex(0, head=h)``.

Examples
--------
>>> S = PartialMap()
>>> v0 = S.add_vertex(3)
>>> v1 = S.add_vertex(2)
>>> S.add_edge((v0, 0), (v1, 0))
>>> S.neighbour((v0, 0)), S.neighbour((v0, 1))
((1, 0), None)
>>> S.explored_edges()
1
"""

from __future__ import annotations

from bisect import insort
from typing import TYPE_CHECKING, Any, Iterable, Iterator, cast

from topomark.spec.errors import require
from topomark.spec.marker import EdgeMarker, Marker, VertexMarker
from topomark.spec.thread import Thread, ThreadedWorld, ThreadMark, unshifted, walk_from_marks
from topomark.spec.unexplored import Unexplored
from topomark.spec.world import DartMark, Start, VertexMark, World

if TYPE_CHECKING:
    from topomark.spec.signature import Signature

__all__ = ["PartialMap", "MapDart"]

MapDart = tuple[int, int]


class PartialMap:
    """The map S (partial embedded graph) together with U, the unexplored darts."""

    def __init__(self) -> None:
        self._adj: list[list[MapDart | None]] = []
        self._joined: list[list[tuple[int, int]]] = []  # per vertex: (exit, neighbour) of each explored exit
        self.journal: list[tuple[Any, ...]] = []  # ("vertex", v, degree) | ("edge", a, b) | ("mark", v): S only grows
        self.edge_count = 0
        self._vmarks: dict[int, VertexMark] = {}
        self._dmarks: dict[int, tuple[DartMark, ...]] = {}
        self.thread_marks: dict[int, ThreadMark] = {}  # map vertex -> its thread mark (absolute exits), §6.3
        self._unexplored = Unexplored()

    @property
    def unexplored(self) -> Unexplored:
        """U (:class:`~topomark.spec.unexplored.Unexplored`, a list).  Assigning a list makes U a copy of it;
        assigning another map's U shares it."""
        return self._unexplored

    @unexplored.setter
    def unexplored(self, entries: Iterable[Any]) -> None:
        self._unexplored = entries if isinstance(entries, Unexplored) else Unexplored(entries)

    # -- building ------------------------------------------------------------
    def add_vertex(self, degree: int) -> int:
        require(degree >= 1, f"a map vertex needs degree >= 1, got {degree}")
        self._adj.append([None] * degree)
        self._joined.append([])
        self.journal.append(("vertex", len(self._adj) - 1, degree))
        return len(self._adj) - 1

    def add_edge(self, a: MapDart, b: MapDart) -> None:
        """Join dart ``a`` and dart ``b`` (both must be unjoined)."""
        require(a[0] != b[0], f"a map edge may not be a self-loop at vertex {a[0]}")
        for v, i in (a, b):
            require(0 <= i < len(self._adj[v]), f"exit {i} does not exist at map vertex {v}")
            require(self._adj[v][i] is None, f"dart {(v, i)} of the map is already joined")
        self._adj[a[0]][a[1]] = b
        self._adj[b[0]][b[1]] = a
        insort(self._joined[a[0]], (a[1], b[0]))
        insort(self._joined[b[0]], (b[1], a[0]))
        self.edge_count += 1
        self.journal.append(("edge", a, b))

    def mark_vertex(self, v: int, count: int = 1, head: int | None = None) -> None:
        self._vmarks[v] = VertexMark(count, head)
        self.journal.append(("mark", v))

    def mark_dart(self, v: int, mark: DartMark) -> None:
        self._dmarks[v] = tuple(sorted(self._dmarks.get(v, ()) + (mark,), key=lambda d: d.exit))
        self.journal.append(("mark", v))

    def mark_as_sensed(self, v: int, sig: Signature, entry: int) -> None:
        """Record at ``v`` the marks in ``sig``, sensed by a robot that entered ``v`` by exit ``entry``.

        The inverse of :func:`~topomark.spec.signature.signature_at`: afterwards
        ``signature_at(self, v, entry) == sig`` (§3.1.1: a relative direction
        ``h`` read from entry ``j`` is exit ``(j + h) mod deg``).
        """
        d = self.degree(v)
        require(sig.degree == d, f"signature {sig} sensed at map vertex {v} of degree {d}")
        if sig.vertex_count:
            head = None if sig.vertex_direction is None else (entry + sig.vertex_direction) % d
            self.mark_vertex(v, sig.vertex_count, head)
        for x, count, end in sig.edges:
            self.mark_dart(v, DartMark((entry + x) % d, count, end))
        if sig.thread is not None:
            self.thread_marks[v] = unshifted(sig.thread, entry, d)
            self.journal.append(("mark", v))

    # -- queries (the same protocol as World, so signature_at works on both) --
    @property
    def vertices(self) -> range:
        return range(len(self._adj))

    @property
    def n(self) -> int:
        return len(self._adj)

    def degree(self, v: int) -> int:
        return len(self._adj[v])

    def arc(self, dart: MapDart) -> MapDart | None:
        """The reverse dart ``dart`` is joined to, or None if unexplored (same name as World.arc)."""
        return self._adj[dart[0]][dart[1]]

    def target(self, dart: MapDart) -> MapDart:
        """Where an explored ``dart`` leads, for a caller that knows it is joined (:meth:`arc` is None on an open
        dart)."""
        return cast(MapDart, self._adj[dart[0]][dart[1]])

    def links(self, v: int) -> list[MapDart | None]:
        """The reverse dart of each exit of ``v`` in index order, None where unexplored.

        The map's own row, for tight loops (breadth-first search); read it, never mutate it.
        """
        return self._adj[v]

    def joined(self, v: int) -> list[tuple[int, int]]:
        """``(exit, neighbour)`` for each explored exit of ``v``, in index order: :meth:`links` without its
        unexplored exits or entry indices, for the tightest loops; read it, never mutate it."""
        return self._joined[v]

    def neighbour(self, dart: MapDart) -> MapDart | None:
        """The reverse dart that ``dart`` is joined to, or None if unexplored."""
        return self._adj[dart[0]][dart[1]]

    def vertex_mark(self, v: int) -> VertexMark | None:
        return self._vmarks.get(v)

    def dart_marks(self, v: int) -> tuple[DartMark, ...]:
        return self._dmarks.get(v, ())

    def thread_mark(self, v: int) -> ThreadMark | None:
        """The thread sensed at ``v`` (a :class:`~topomark.spec.thread.ThreadMark`), or None."""
        return self.thread_marks.get(v)

    def darts(self) -> Iterator[MapDart]:
        for v, row in enumerate(self._adj):
            for i in range(len(row)):
                yield (v, i)

    def open_darts(self) -> list[MapDart]:
        """The darts of S not joined to anything (what U should hold)."""
        return [d for d in self.darts() if self.neighbour(d) is None]

    def explored_edges(self) -> int:
        """|E_S|, counted from the darts (``edge_count`` is the journal's running count)."""
        return sum(1 for d in self.darts() if self.neighbour(d) is not None) // 2

    def complete(self) -> bool:
        return all(x is not None for row in self._adj for x in row)

    def copy(self) -> "PartialMap":
        other = PartialMap()
        other._adj = [list(row) for row in self._adj]
        other._joined = [list(row) for row in self._joined]
        other._vmarks = dict(self._vmarks)
        other._dmarks = dict(self._dmarks)
        other.thread_marks = dict(self.thread_marks)
        other.unexplored = list(self.unexplored)
        other.journal = list(self.journal)
        other.edge_count = self.edge_count
        return other

    # -- conversion ----------------------------------------------------------
    @staticmethod
    def name(v: int) -> str:
        """A map vertex's name in the world file format: ``"s0"``, ``"s1"``, ..."""
        return f"s{v}"

    def to_world(self, start: MapDart | None = None) -> World:
        """The complete map as a :class:`World` (markers included); S must be complete."""
        require(self.complete(), f"the map still has unexplored darts: {self.open_darts()[:5]}")
        rotation = {self.name(v): [self.name(self._far(v, i)) for i in range(len(row))]
                    for v, row in enumerate(self._adj)}
        markers: list[Marker] = []
        for v, mark in sorted(self._vmarks.items()):
            points = None if mark.head is None else self.name(self._far(v, mark.head))
            markers.append(VertexMarker(self.name(v), mark.count, points))
        done: set[frozenset[int]] = set()
        for v, marks in sorted(self._dmarks.items()):
            for dm in marks:
                w = self._far(v, dm.exit)
                if frozenset((v, w)) in done:
                    continue
                done.add(frozenset((v, w)))
                head = None if dm.end is None else self.name(v if dm.end == "H" else w)
                markers.append(EdgeMarker((self.name(v), self.name(w)), dm.count, head))
        s = None if start is None else Start(self.name(start[0]), self.name(self._far(*start)))
        if self.thread_marks:
            return ThreadedWorld(rotation, markers, s, self._thread())
        return World(rotation, markers, s)

    def _far(self, v: int, i: int) -> int:
        """The far end of exit ``i`` of ``v``, a joined dart (S is complete where it is asked)."""
        return cast(MapDart, self._adj[v][i])[0]

    def _thread(self) -> Thread:
        """The thread S's marks show, in map names (one tied vertex, one simple walk from it)."""
        tied = [v for v, t in self.thread_marks.items() if t.tied]
        require(len(tied) == 1, f"the map's thread marks show {len(tied)} tied ends")
        walk = walk_from_marks(self._far, self.thread_marks, tied[0])
        t = self.thread_marks[tied[0]]
        head = None if t.head is None else self.name(self._far(tied[0], t.head))
        knots = tuple((k, self.thread_marks[v].knots) for k, v in enumerate(walk) if self.thread_marks[v].knots)
        return Thread(tuple(self.name(v) for v in walk), head, self.thread_marks[walk[-1]].end, knots)
