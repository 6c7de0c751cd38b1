"""Threads: a thread tied at a vertex, laid along the edges the robot traverses, rewound, untied (thesis §6.3).

The thesis's robot "can 'tie' one end of the thread at a vertex and play that
thread out as it moves through the graph, and perceive the thread when
encountering the thread at a given vertex" (§6.3).  This module is the
thread as a piece of world state, in world names and absolute exits:

* :class:`ThreadMark` — what lies at one vertex, in absolute exits: whether
  the thread is *tied* here and the exit it is laid out toward (the direction
  of an l = ε thread, §6.3.1), the incident edges it lies along and how often
  (its "thread-marked" or "stringed" edges, §6.3.2, Algorithm 6.8 line 7), whether its *free
  end* lies here (§6.3.2, Algorithm 6.8 line 11) and how many *knots* are tied
  here (Figure 6.20).  :func:`~topomark.spec.signature.signature_at` reads it
  (through ``thread_marks``) relative to the entry edge, in the notation
  documented in :mod:`topomark.spec.signature`.
* :class:`ThreadState` — the thread of one run (held by
  :class:`~topomark.spec.markerlayer.MarkerLayer`): where it is tied, the walk
  of darts laid from there, whether the robot holds the free end, the knots
  along it.  :meth:`ThreadState.apply` carries out a
  :class:`~topomark.spec.kit.ThreadOp`; :meth:`ThreadState.pull` is what a
  move does to it.
* :class:`Thread` — a laid thread in world names (a world or map file's
  ``thread`` field); :class:`ThreadedWorld` — a :class:`World` with one.

Decisions (the thesis describes the operations only in words, §6.3):

* **Length.** The thread's length is counted in edges laid; the kit's
  ``thread`` is that length, 0 being l = ε (only long enough to be tied and
  "laid out in some direction", §6.3.1).  Carrying the free end, a move lays
  the thread along the edge traversed; a move that would make the laid walk
  longer than the kit's length is refused (an :class:`InvalidInput` naming
  the kit) — the robot "rewinds the thread from the current vertex when
  thread length l is reached" (§6.3.3), so reaching l is something it knows.
* **Rewinding** is retracing along the thread while picking it up (§6.3.2:
  "retraces its steps along the thread by picking up and rewinding the
  thread"): carrying the free end, a move back along the edge the thread was
  last laid on picks that edge's thread up instead of laying it twice.  A
  rewind moves the robot, so it costs its traversal (§3.1.2); the simulator
  also logs it as a ``rewind`` operation.  Knots beyond the rewound point are
  picked up with it (Figure 6.20: knots of vertices not yet fully explored
  survive because rewinding follows the stack).
* **Free end.** The robot holds the free end while it lays the thread; it may
  ``leave`` it where it stands (Algorithm 6.7, §6.3.2: "the robot leaves the
  thread (free end) there") and ``take`` it up again there.  A free end lying
  at a vertex is sensed there; one in the robot's hand is not.
* **Tie / untie.** ``tie`` needs the thread in hand and not tied; its optional
  direction is the exit the thread is laid out toward (l = ε, §6.3.1: "tied
  ... and then laid out in some direction").  ``untie`` needs the whole thread
  rewound to the tied vertex (Algorithm 6.8 line 20: "traverses to v_s, unties
  the thread"); its knots are undone with it.
* **Knots** are tied where the robot stands, on the thread it holds (at the
  laid walk's current end, Figure 6.20: "Tie different number of knots when
  entering a new place the first time").

Examples
--------
>>> from topomark.spec.world import World
>>> from topomark.spec.kit import ThreadOp
>>> w = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})
>>> t = ThreadState()
>>> t.apply(w, ("a", 0), ThreadOp("tie"), length=2)
>>> t.pull(w, ("a", 0), 0, length=2)  # a -> b lays the edge a-b
False
>>> t.marks(w)["b"]
ThreadMark(tied=False, head=None, edges=((1, 1),), end=False, knots=0)
>>> t.pull(w, ("b", 1), 0, length=2)  # straight back along it: a rewind
True
>>> t.laid
[]
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Mapping, NamedTuple, Sequence

from topomark.spec.errors import InvalidInput
from topomark.spec.kit import ThreadOp
from topomark.spec.marker import Marker
from topomark.spec.world import DartMark, Start, VertexMark, World

__all__ = ["ThreadMark", "ThreadState", "Thread", "ThreadedWorld", "shifted"]


class ThreadMark(NamedTuple):
    """The thread at one vertex: ``tied`` here, toward exit ``head`` (or None), along ``edges``
    ((exit, times), sorted), its free ``end`` lying here, ``knots`` tied here."""

    tied: bool = False
    head: int | None = None
    edges: tuple[tuple[int, int], ...] = ()
    end: bool = False
    knots: int = 0


def shifted(mark: ThreadMark, entry: int, degree: int) -> ThreadMark:
    """``mark`` with every exit read relative to ``entry`` (as a robot entering by it senses it)."""
    head = None if mark.head is None else (mark.head - entry) % degree
    edges = tuple(sorted(((x - entry) % degree, k) for x, k in mark.edges))
    return ThreadMark(mark.tied, head, edges, mark.end, mark.knots)


def unshifted(mark: ThreadMark, entry: int, degree: int) -> ThreadMark:
    """The inverse of :func:`shifted`: relative exits read from ``entry`` back to absolute ones."""
    return shifted(mark, -entry % degree, degree)


class ThreadState:
    """The thread of one run: ``tied`` (vertex or None), ``head`` (absolute exit there or None),
    ``laid`` (darts laid from the tied vertex, in order), ``held`` (the robot holds the free end),
    ``knots`` (position along ``laid`` ↦ knots tied there).

    Its marks (:meth:`marks`) are kept up to date as it changes, not rebuilt: a lay or a rewind touches
    the two ends of one edge, a knot, a leave or a take the free end's vertex, so each change recomputes
    the :class:`ThreadMark` of those vertices only (from per-vertex counts of laid edges, walk visits and
    knots).  Change the thread only through :meth:`apply`, :meth:`pull` and :meth:`restore`."""

    __slots__ = ("tied", "head", "laid", "held", "knots", "_walk", "_visits", "_edges", "_knot_at", "_marks")

    def __init__(self) -> None:
        self.tied: str | None = None
        self.head: int | None = None
        self.laid: list[tuple[str, int]] = []
        self.held = True
        self.knots: dict[int, int] = {}
        self._walk: list[str] = []  # the laid walk's vertices, from the tied one
        self._visits: dict[str, int] = {}  # vertex -> times the walk passes it
        self._edges: dict[str, dict[int, int]] = {}  # vertex -> exit -> times the thread lies along it
        self._knot_at: dict[str, int] = {}  # vertex -> knots tied there
        self._marks: dict[str, ThreadMark] = {}

    def end_vertex(self, world: World) -> str | None:
        """Where the free end is (at the robot when held): the laid walk's last vertex."""
        if self.tied is None:
            return None
        return self.tied if not self.laid else world.target(self.laid[-1])[0]

    def apply(self, world: World, state: tuple[str, int], op: ThreadOp, length: int) -> None:
        """Carry out ``op`` by a robot in ``state``; refusals are :class:`InvalidInput` saying why."""
        v, entry = state
        d = world.degree(v)
        kind = op.op
        if kind != "knot" and op.count != 1:
            raise InvalidInput(f"a {kind} takes no count (only a knot does), got count {op.count!r}")
        if kind == "tie":
            _need(self.tied is None, f"the thread is already tied at a vertex; untie it before tying it at {v!r}")
            if op.direction is not None and not (_int(op.direction) and 0 <= op.direction < d):
                raise InvalidInput(f"thread direction {op.direction!r} is not an exit of a vertex of degree {d}")
            self.restore(world, v, None if op.direction is None else (entry + op.direction) % d, (), True, {})
        elif kind == "untie":
            _need(self.tied == v and not self.laid, "untie needs the robot at the tied vertex with the whole "
                                                    "thread rewound to it")
            self.restore(world, None, None, (), True, {})
        elif kind == "leave":
            _need(self.tied is not None and self.held, "leave needs a tied thread whose free end the robot holds")
            self.held = False
            self._touch(self._walk[-1])
        elif kind == "take":
            _need(self.tied is not None and not self.held and self.end_vertex(world) == v,
                  f"take needs the thread's free end lying at {v!r}, where the robot is")
            self.held = True
            self._touch(v)
        elif kind == "knot":
            _need(self.tied is not None and self.held, "a knot is tied on a tied thread whose free end the robot holds")
            if not (_int(op.count) and op.count >= 1):
                raise InvalidInput(f"a knot count must be a positive integer, got {op.count!r}")
            self._knot(len(self.laid), op.count)
        elif kind == "rewind":
            raise InvalidInput("rewind moves the robot: it is a move back along the thread (Robot.rewind)")
        else:
            raise InvalidInput(f"unknown thread operation {kind!r}")

    def rewind_exit(self, world: World, state: tuple[str, int]) -> int:
        """The motion that rewinds the last laid edge from ``state``; InvalidInput if there is none."""
        _need(self.tied is not None and self.held and bool(self.laid), "rewind needs a laid thread whose free end "
                                                                       "the robot holds")
        v, exit_ = world.target(self.laid[-1])
        return (exit_ - state[1]) % world.degree(v)

    def pull(self, world: World, state: tuple[str, int], motion: int, length: int) -> bool:
        """What leaving ``state`` by ``motion`` does to the thread; True if it rewinds an edge.

        Holding the free end of a tied thread, the move lays the thread (refused beyond ``length``
        edges) or, back along the last laid edge, picks it up.
        """
        if self.tied is None or not self.held:
            return False
        v, entry = state
        dart = (v, (entry + motion) % world.degree(v))
        if self.laid and world.target(self.laid[-1]) == dart:
            k = self.knots.pop(len(self.laid), None)
            if k:
                self._knot_at[self._walk[-1]] -= k
            self._unlay(world)
            return True
        if len(self.laid) >= length:
            what = "l = ε: it is only long enough to be tied" if length == 0 else f"{len(self.laid)} edges laid"
            raise InvalidInput(f"the thread would run out: the kit's thread has length {length or 'ε'} ({what}); "
                               "rewind or leave the free end first")
        self._lay(world, dart)
        return False

    def marks(self, world: World) -> dict[str, ThreadMark]:
        """Every vertex the thread touches ↦ its :class:`ThreadMark` (kept up to date; do not mutate it)."""
        return self._marks

    def restore(self, world: World, tied: str | None, head: int | None, laid: Iterable[tuple[str, int]],
                held: bool, knots: dict[int, int]) -> None:
        """Set the whole thread at once (tie, untie, a thread read from a file) and build its marks."""
        self.tied, self.head, self.laid, self.held, self.knots = tied, head, [], True, {}
        self._marks.clear()  # in place: holders of marks() see the thread as it is now
        self._walk, self._visits, self._edges, self._knot_at = [], {}, {}, {}
        if tied is None:
            return
        self._walk.append(tied)
        self._visits[tied] = 1
        for dart in laid:
            self._lay(world, dart)
        for pos, k in knots.items():
            self._knot(pos, k)
        self.held = held
        self._touch(tied, self._walk[-1])

    # -- keeping the marks: each change recomputes the ThreadMark of the vertices it touches ----
    def _lay(self, world: World, dart: tuple[str, int]) -> None:
        w, j = world.target(dart)
        self.laid.append(dart)
        self._walk.append(w)
        self._visits[w] = self._visits.get(w, 0) + 1
        for x, e in (dart, (w, j)):
            at = self._edges.setdefault(x, {})
            at[e] = at.get(e, 0) + 1
        self._touch(dart[0], w)

    def _unlay(self, world: World) -> None:
        dart = self.laid.pop()
        w = self._walk.pop()
        self._visits[w] -= 1
        for x, e in (dart, world.target(dart)):
            at = self._edges[x]
            at[e] -= 1
            if not at[e]:
                del at[e]
        self._touch(dart[0], w)

    def _knot(self, pos: int, count: int) -> None:
        self.knots[pos] = self.knots.get(pos, 0) + count
        v = self._walk[pos]
        self._knot_at[v] = self._knot_at.get(v, 0) + count
        self._touch(v)

    def _touch(self, *vertices: str) -> None:
        end = self._walk[-1] if not self.held else None
        for v in vertices:
            if not self._visits.get(v):
                self._marks.pop(v, None)
                continue
            edges = self._edges.get(v)
            self._marks[v] = ThreadMark(v == self.tied, self.head if v == self.tied else None,
                                        tuple(sorted(edges.items())) if edges else (), v == end,
                                        self._knot_at.get(v, 0))


def _need(cond: bool, why: str) -> None:
    if not cond:
        raise InvalidInput(why)


def _int(x: Any) -> bool:
    return isinstance(x, int) and not isinstance(x, bool)


@dataclass(frozen=True)
class Thread:
    """A laid thread in world names: tied at ``walk[0]`` toward ``points_to``, laid along ``walk``,
    its free end lying at ``walk[-1]`` (``end_left``) or held, ``knots`` = ((position, count), ...)."""

    walk: tuple[str, ...]
    points_to: str | None = None
    end_left: bool = True
    knots: tuple[tuple[int, int], ...] = field(default=())

    def state(self, world: World) -> ThreadState:
        """The :class:`ThreadState` this thread is in ``world``; InvalidWorld-style InvalidInput if it does not fit."""
        v0 = self.walk[0]
        _need(v0 in world.rotation, f"thread tied at {v0!r}, which is not a vertex")
        head = None
        if self.points_to is not None:
            _need(self.points_to in world.rotation[v0], f"thread at {v0!r} points to {self.points_to!r}, "
                                                         f"not a neighbour")
            head = world.index(v0, self.points_to)
        laid = []
        for a, b in zip(self.walk, self.walk[1:]):
            _need(b in world.rotation.get(a, ()), f"thread laid from {a!r} to {b!r}, which is not an edge")
            laid.append((a, world.index(a, b)))
        knots: dict[int, int] = {}
        for pos, k in self.knots:
            _need(_int(pos) and 0 <= pos < len(self.walk) and _int(k) and k >= 1,
                  f"thread knot [{pos!r}, {k!r}]: a position 0..{len(self.walk) - 1} and a count >= 1")
            knots[pos] = knots.get(pos, 0) + k
        t = ThreadState()
        t.restore(world, v0, head, laid, not self.end_left, knots)
        return t

    @classmethod
    def of(cls, world: World, t: ThreadState) -> "Thread | None":
        """The laid thread of ``t`` in world names (None when untied)."""
        if t.tied is None:
            return None
        walk = (t.tied,) + tuple(world.target(d)[0] for d in t.laid)
        head = None if t.head is None else world.neighbour(t.tied, t.head)
        return cls(walk, head, not t.held, tuple(sorted(t.knots.items())))


# What ThreadedWorld.of_layer keeps to make its Thread when asked: base, tied, head, laid, held, knots
_Snapshot = tuple[World, str, "int | None", tuple[tuple[str, int], ...], bool, tuple[tuple[int, int], ...]]


class ThreadedWorld(World):
    """A :class:`World` with a laid :class:`Thread` in it; :meth:`thread_mark` is what lies at ``v``.

    Built from a rotation and a :class:`Thread` (a file, a map), it is validated like any world.
    :meth:`of_layer` is the marker layer's snapshot of a run (:meth:`MarkerLayer.world`): the layer's
    own operations keep the world valid, so nothing is re-validated and the :class:`Thread` in world
    names is made only when asked for (:attr:`thread`)."""

    __slots__ = ("_thread", "_snapshot", "thread_marks")

    def __init__(self, rotation: Mapping[str, Sequence[str]], markers: Iterable[Marker] = (),
                 start: Start | None = None, thread: Thread | None = None) -> None:
        super().__init__(rotation, markers, start)
        self._thread = thread
        self._snapshot: _Snapshot | None = None
        state = thread.state(self) if thread is not None else ThreadState()
        self.thread_marks = state.marks(self)

    @classmethod
    def of_layer(  # type: ignore[override]  # a threaded snapshot also takes the layer's thread state
            cls, base: World, markers: tuple[Marker, ...], vmarks: dict[str, VertexMark],
            dmarks: dict[str, tuple[DartMark, ...]], state: ThreadState) -> "ThreadedWorld":
        """A snapshot of a run: ``base``'s rotation and start, the layer's markers (``vmarks``/``dmarks``
        in :class:`World`'s form, already checked by the layer) and its tied thread ``state`` — copied,
        never re-validated (the layer's operations keep every invariant of §3.1.1 and of the thread)."""
        w = cls.__new__(cls)
        w.rotation, w._index, w.start, w._m = base.rotation, base._index, base.start, base.m
        w.markers, w._vmarks, w._dmarks = markers, dict(vmarks), dict(dmarks)
        w._thread = None
        assert state.tied is not None, "a threaded snapshot is of a tied thread"
        w._snapshot = (base, state.tied, state.head, tuple(state.laid), state.held, tuple(sorted(state.knots.items())))
        w.thread_marks = dict(state.marks(base))
        return w

    @property
    def thread(self) -> Thread | None:
        """The laid thread in world names."""
        if self._thread is None and self._snapshot is not None:
            base, tied, head, laid, held, knots = self._snapshot
            walk = (tied,) + tuple(base.target(d)[0] for d in laid)
            self._thread = Thread(walk, None if head is None else base.neighbour(tied, head), not held, knots)
            self._snapshot = None
        return self._thread

    def thread_mark(self, v: str) -> ThreadMark | None:
        return self.thread_marks.get(v)

    def with_markers(self, markers: Iterable[Marker], start: Start | None = None) -> World:
        return ThreadedWorld(self.rotation, markers, start, self.thread)

    def with_start(self, start: Start | None) -> World:
        return ThreadedWorld(self.rotation, self.markers, start, self.thread)

    def __eq__(self, other: object) -> bool:
        same = World.__eq__(self, other)
        return same if same is NotImplemented else same and getattr(other, "thread", None) == self.thread

    def __hash__(self) -> int:
        return hash((World.__hash__(self), self.thread))

    def __repr__(self) -> str:
        return World.__repr__(self)[:-1] + f", thread={self.thread!r})"


def walk_from_marks(neighbour: Callable[[Any, int], Any], marks: Mapping[Any, ThreadMark],
                    tied: Any) -> tuple[Any, ...]:
    """The walk a thread's per-vertex marks describe, followed from ``tied`` along its stringed edges.

    ``neighbour(v, exit)`` names the far end.  Only a thread that lies along each edge once and
    never branches is drawn unambiguously; anything else is InvalidInput.
    """
    walk, used = [tied], set()
    while True:
        v = walk[-1]
        ahead = [x for x, k in marks[v].edges if frozenset((v, neighbour(v, x))) not in used]
        if not ahead:
            return tuple(walk)
        _need(len(ahead) == 1 and all(k == 1 for _, k in marks[v].edges),
              f"the thread's marks at {v!r} do not describe one simple walk; it cannot be drawn")
        w = neighbour(v, ahead[0])
        used.add(frozenset((v, w)))
        walk.append(w)
