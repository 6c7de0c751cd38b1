"""The world: an embedded graph given as a rotation system (thesis §3.1.1).

The world G = (V, E) is an undirected graph embedded so that the edges at each
vertex have a consistent (clockwise) order.  We store it as a *rotation
system*: for each vertex, the list of its neighbours in clockwise order.  Exit
index ``i`` at ``v`` is position ``i`` of that list (Figure 3.1); a *dart* is a
pair ``(v, i)``, the edge leaving ``v`` through exit ``i``.

§3.1.1 restricts worlds to graphs with no cycles of length ≤ 2 — no self-loops
and no multi-edges — and the model needs the graph connected (the robot must
reach every place) with every degree ≥ 1.  :class:`World` rejects anything else
with :class:`~topomark.spec.errors.InvalidWorld`, naming the offending vertex or
edge.

Examples
--------
>>> w = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})
>>> w.n, w.m
(3, 3)
>>> w.target(("a", 0))
('b', 1)
"""

from __future__ import annotations

from collections import Counter, deque
from dataclasses import dataclass
from typing import Iterable, Iterator, Mapping, Sequence

from topomark.spec.errors import InvalidWorld, require_input
from topomark.spec.marker import EdgeMarker, Marker, VertexMarker

__all__ = ["World", "Start", "Dart", "VertexMark", "DartMark", "MAX_VERTICES", "MAX_EDGES", "MAX_DEGREE", "MAX_NAME_LENGTH",
           "check_size"]

Dart = tuple[str, int]

MAX_VERTICES = 250_000
"""The most vertices a world may have (generated or loaded).

Why a limit at all: without one, ``lattice-hole:rows=3000,cols=3000`` runs for
a minute and then dies of MemoryError, and a world file can ask for anything.
Why this value: it is far beyond every experiment of the thesis (the
§3.5 figures go up to 360 vertices) and still fits comfortably in memory -- measured
with ``/usr/bin/time``: ``lattice(500, 500)`` (250,000 vertices, 499,000
edges) peaks at about 0.5 GB and ``small_world(250000, 4, 0.1)`` likewise.
Generators and the world loader check it *before* building anything
(:func:`check_size`), so an oversized request fails at once.
"""

MAX_EDGES = 1_000_000
"""The most edges a world may have, for the same reasons as :data:`MAX_VERTICES`.

A dense world reaches memory limits long before the vertex limit: ``K_1415``
(about 1,000,000 edges) peaks at about 0.35 GB while ``complete-hole`` builds
it, and twice the vertex limit in edges covers every lattice and ring of up to
:data:`MAX_VERTICES` vertices.
"""

MAX_DEGREE = MAX_VERTICES - 1
"""The largest degree any valid world can have: a simple graph (§3.1.1) on at most
:data:`MAX_VERTICES` vertices.  A signature read from outside
(:meth:`topomark.spec.signature.Signature.parse`) with a larger degree cannot
describe any world, so it is refused before anything is allocated for it."""


MAX_NAME_LENGTH = 200
"""The longest vertex name, in characters.  Names only label vertices (the
robot never senses them, §3.1.1); a bound keeps every message that quotes a
name one short line however hostile the file."""


def check_size(n: int, m: int, what: str) -> None:
    """Refuse ``what`` (a world about to be built) with ``n`` vertices and ``m`` edges above
    :data:`MAX_VERTICES` / :data:`MAX_EDGES`, with an :class:`InvalidWorld` naming the limit.

    Callers compute ``n`` and ``m`` from their parameters (or count a file's
    rotation) and call this before allocating the world.
    """
    def count(x: int) -> str:  # a 5,000-digit int cannot even be printed (sys.get_int_max_str_digits)
        return f"{x:,}" if x < 10**18 else "more than 10**18"
    if n > MAX_VERTICES:
        _fail(f"{what} has {count(n)} vertices, more than the limit of {MAX_VERTICES:,} "
              "(topomark.spec.world.MAX_VERTICES)")
    if m > MAX_EDGES:
        _fail(f"{what} has {count(m)} edges, more than the limit of {MAX_EDGES:,} "
              "(topomark.spec.world.MAX_EDGES)")


@dataclass(frozen=True)
class Start:
    """The robot's start (§3.1.1): at vertex ``at`` facing neighbour ``facing``.

    The exit it faces plays the role of the entry edge for the first motion.
    """

    at: str
    facing: str


@dataclass(frozen=True)
class VertexMark:
    """What a vertex carries, in exit indices: ``count`` markers, ``head`` = exit pointed at."""

    count: int
    head: int | None


@dataclass(frozen=True)
class DartMark:
    """What an edge marker looks like from one end: exit, count, ``"H"``/``"T"``/None."""

    exit: int
    count: int
    end: str | None


def _fail(message: str) -> None:
    raise InvalidWorld(message)


class World:
    """A valid world: rotation system, markers and (optionally) a start.

    Parameters
    ----------
    rotation : mapping from vertex name to its neighbours in clockwise order.
    markers : vertex and edge markers (at most one entry per vertex or edge;
        use ``count`` for several).
    start : where the robot starts, or None.
    """

    __slots__ = ("rotation", "markers", "start", "_index", "_vmarks", "_dmarks", "_m")

    def __init__(
        self,
        rotation: Mapping[str, Sequence[str]],
        markers: Iterable[Marker] = (),
        start: Start | None = None,
    ):
        self.rotation: dict[str, tuple[str, ...]] = {v: tuple(ns) for v, ns in rotation.items()}
        self.markers: tuple[Marker, ...] = tuple(markers)
        self.start = start
        self._check_rotation()
        self._index = {v: {w: i for i, w in enumerate(ns)} for v, ns in self.rotation.items()}
        self._check_connected()
        self._vmarks: dict[str, VertexMark] = {}
        self._dmarks: dict = {}
        for marker in self.markers:
            self._add_marker(marker)
        self._dmarks = {v: tuple(sorted(ms, key=lambda d: d.exit)) for v, ms in self._dmarks.items()}
        self._check_start()

    @classmethod
    def of_layer(cls, base: "World", markers: tuple[Marker, ...], vmarks: dict, dmarks: dict) -> "World":
        """A snapshot of a run's marker layer (:meth:`topomark.spec.markerlayer.MarkerLayer.world`): ``base``'s
        rotation and start with the layer's markers, ``vmarks``/``dmarks`` already in this class's form and
        checked by the layer's own operations — copied, never re-validated (a marker dropped mid-run would
        otherwise rebuild and re-check the whole world, O(n + m) per drop)."""
        w = cls.__new__(cls)
        w.rotation, w._index, w.start, w._m = base.rotation, base._index, base.start, base.m
        w.markers, w._vmarks, w._dmarks = markers, dict(vmarks), dict(dmarks)
        return w

    # -- validation (§3.1.1) -------------------------------------------------
    def _check_rotation(self) -> None:
        rot = self.rotation
        if not rot:
            _fail("the world has no vertices")
        for v, ns in rot.items():
            require_input(isinstance(v, str), f"vertex name {v!r} is not a string", InvalidWorld)
            if len(v) > MAX_NAME_LENGTH:
                _fail(f"vertex name {v[:40]!r}... has {len(v):,} characters, more than the limit of "
                      f"{MAX_NAME_LENGTH} (topomark.spec.world.MAX_NAME_LENGTH)")
            if not ns:
                _fail(f"vertex {v!r} has degree 0 (every degree must be >= 1)")
            for w in ns:
                if not isinstance(w, str):
                    _fail(f"vertex {v!r} lists neighbour {str(w)[:40]!r}, which is not a string")
                if len(w) > MAX_NAME_LENGTH:
                    _fail(f"vertex {v!r} lists neighbour {w[:40]!r}... of {len(w):,} characters, more than the "
                          f"limit of {MAX_NAME_LENGTH} (topomark.spec.world.MAX_NAME_LENGTH)")
                if w == v:
                    _fail(f"self-loop at vertex {v!r}")
                if w not in rot:
                    _fail(f"vertex {v!r} lists neighbour {w!r}, which is not a vertex")
            dup = [w for w, k in Counter(ns).items() if k > 1]
            if dup:
                _fail(f"multi-edge between {v!r} and {dup[0]!r} ({v!r} lists it {ns.count(dup[0])} times)")
        for v, ns in rot.items():
            for w in ns:
                if v not in rot[w]:
                    _fail(f"asymmetric adjacency: {v!r} lists {w!r} but {w!r} does not list {v!r}")

    def _check_connected(self) -> None:
        first = next(iter(self.rotation))
        seen = {first}
        todo = deque([first])
        while todo:
            for w in self.rotation[todo.popleft()]:
                if w not in seen:
                    seen.add(w)
                    todo.append(w)
        if len(seen) != len(self.rotation):
            lost = next(v for v in self.rotation if v not in seen)
            _fail(f"the world is disconnected: vertex {lost!r} cannot be reached from {first!r}")

    def _add_marker(self, marker: Marker) -> None:
        if not isinstance(marker.count, int) or isinstance(marker.count, bool) or marker.count < 1:
            _fail(f"marker count must be a positive integer, got {marker.count!r}")
        if isinstance(marker, VertexMarker):
            v = marker.at
            if v not in self.rotation:
                _fail(f"vertex marker at {v!r}, which is not a vertex")
            if v in self._vmarks:
                _fail(f"two marker entries at vertex {v!r} (use one entry with a count)")
            head = None
            if marker.points_to is not None:
                if marker.points_to not in self._index[v]:
                    _fail(f"marker at {v!r} points to {marker.points_to!r}, which is not a neighbour of {v!r}")
                head = self._index[v][marker.points_to]
            self._vmarks[v] = VertexMark(marker.count, head)
            return
        if not isinstance(marker, EdgeMarker):
            _fail(f"unknown marker {marker!r}")
        if len(marker.between) != 2:
            _fail(f"edge marker needs exactly two end vertices, got {list(marker.between)!r}")
        u, v = marker.between
        if u not in self.rotation or v not in self._index[u]:
            _fail(f"edge marker on ({u!r}, {v!r}), which is not an edge")
        if marker.head is not None and marker.head not in (u, v):
            _fail(f"edge marker on ({u!r}, {v!r}) has head {marker.head!r}, which is not an end of that edge")
        for a, b in ((u, v), (v, u)):
            if any(d.exit == self._index[a][b] for d in self._dmarks.get(a, ())):
                _fail(f"two marker entries on edge ({u!r}, {v!r}) (use one entry with a count)")
            end = None if marker.head is None else ("H" if marker.head == a else "T")
            self._dmarks.setdefault(a, []).append(DartMark(self._index[a][b], marker.count, end))  # tuples later

    def _check_start(self) -> None:
        s = self.start
        if s is None:
            return
        if s.at not in self.rotation:
            _fail(f"start vertex {s.at!r} is not a vertex")
        if s.facing not in self._index[s.at]:
            _fail(f"start faces {s.facing!r}, which is not a neighbour of {s.at!r}")

    # -- queries -------------------------------------------------------------
    @property
    def vertices(self) -> tuple[str, ...]:
        return tuple(self.rotation)

    @property
    def n(self) -> int:
        return len(self.rotation)

    @property
    def m(self) -> int:
        m = getattr(self, "_m", None)  # counted once: the rotation never changes
        if m is None:
            m = self._m = sum(len(ns) for ns in self.rotation.values()) // 2
        return m

    def degree(self, v: str) -> int:
        return len(self.rotation[v])

    def neighbour(self, v: str, i: int) -> str:
        """The vertex that exit ``i`` of ``v`` leads to."""
        return self.rotation[v][i]

    def index(self, v: str, w: str) -> int:
        """The exit index of neighbour ``w`` at ``v``."""
        return self._index[v][w]

    def target(self, dart: Dart) -> Dart:
        """The reverse dart of ``dart``: where exit ``i`` of ``v`` arrives, and by which entry."""
        v, i = dart
        w = self.rotation[v][i]
        return (w, self._index[w][v])

    arc = target  # the name the isomorphism and invariant checks use for both worlds and maps

    def darts(self) -> Iterator[Dart]:
        for v, ns in self.rotation.items():
            for i in range(len(ns)):
                yield (v, i)

    def edges(self) -> Iterator[tuple[str, str]]:
        """Each edge once, as (u, v) with u listed before v in the rotation."""
        order = {v: k for k, v in enumerate(self.rotation)}
        for v, ns in self.rotation.items():
            for w in ns:
                if order[v] < order[w]:
                    yield (v, w)

    def vertex_mark(self, v: str) -> VertexMark | None:
        return self._vmarks.get(v)

    def dart_marks(self, v: str) -> tuple[DartMark, ...]:
        return self._dmarks.get(v, ())

    def start_state(self) -> tuple[str, int]:
        """The robot state (vertex, entry index) of ``start``; the first vertex facing exit 0 if none."""
        if self.start is None:
            return (self.vertices[0], 0)
        return (self.start.at, self.index(self.start.at, self.start.facing))

    def faces(self) -> int:
        """Number of faces of the embedding, by tracing: from dart (v, i) go to (w, j+1)."""
        seen: set[Dart] = set()
        faces = 0
        for dart in self.darts():
            if dart in seen:
                continue
            faces += 1
            d = dart
            while d not in seen:
                seen.add(d)
                w, j = self.target(d)
                d = (w, (j + 1) % self.degree(w))
        return faces

    def genus(self) -> int:
        """Genus of the orientable surface the rotation system embeds in (Euler: n - m + f = 2 - 2g)."""
        return (2 - self.n + self.m - self.faces()) // 2

    def with_markers(self, markers: Iterable[Marker], start: Start | None = None) -> "World":
        return World(self.rotation, markers, start)

    def with_start(self, start: Start | None) -> "World":
        """This world with another start.  The rotation and markers were checked when this world was made and do
        not change, so only the start is checked (a search runs every start of a world: O(1) per start, not
        O(n + m))."""
        if type(self) is not World:  # a subclass may carry more (a thread): rebuild it whole
            return World(self.rotation, self.markers, start)
        w = World.__new__(World)
        w.rotation, w._index, w.markers, w._vmarks, w._dmarks = (self.rotation, self._index, self.markers,
                                                                 self._vmarks, self._dmarks)
        w._m, w.start = self.m, start
        w._check_start()
        return w

    # -- equality is structural (names matter); isomorphism lives elsewhere ---
    def __eq__(self, other: object) -> bool:
        if not isinstance(other, World):
            return NotImplemented
        return (
            self.rotation == other.rotation
            and set(self.markers) == set(other.markers)
            and self.start == other.start
        )

    def __hash__(self) -> int:
        # order-free, like __eq__ (dict equality ignores insertion order)
        return hash((frozenset(self.rotation.items()), frozenset(self.markers), self.start))

    def __repr__(self) -> str:
        return f"World(n={self.n}, m={self.m}, markers={len(self.markers)}, start={self.start!r})"
