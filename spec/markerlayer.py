"""The marker layer: markers dropped and picked up during a run, over a world's immutable rotation
(thesis §3.1.1, §6.1–6.2, §2.3.1).

A :class:`World` is immutable: its rotation system never changes while a
robot explores it.  Its *markers* do — Algorithm 3.1 drops one at v0, the
algorithms of §6.2 drop many while exploring, and the movable marker of
Dudek et al. (§2.3.1) is picked up again.  A :class:`MarkerLayer` holds the
markers of a run in mutable dictionaries over the world's rotation, offers
the same queries as a world (``degree``, ``target``, ``vertex_mark``,
``dart_marks``), so :func:`~topomark.spec.robot.sense` and
:func:`~topomark.spec.robot.step` work on it unchanged, and builds a
:class:`World` carrying the current markers only when asked
(:meth:`MarkerLayer.world`), never per drop.

Rules (each refusal is an :class:`~topomark.spec.errors.InvalidInput` naming
the place; the simulator reports it as the explorer's fault):

* markers dropped where markers of the same kind already lie join them (the
  count grows), which is how the thesis stacks homogeneous markers (``V#``,
  ``E#``; §6.2, Figure 6.8); a directional marker joins only markers pointing
  the same way — one place cannot point two ways (the world format holds one
  head per vertex and one per edge);
* a pick-up takes markers that are there, and no more;
* the thread (§6.3) is a :class:`~topomark.spec.thread.ThreadState` in the
  same layer (:attr:`MarkerLayer.thread`): :func:`apply_op` carries out a
  :class:`~topomark.spec.kit.ThreadOp`, :meth:`MarkerLayer.pull` is what a
  move does to it, :meth:`MarkerLayer.thread_mark` what lies at a vertex,
  and :meth:`MarkerLayer.world` a
  :class:`~topomark.spec.thread.ThreadedWorld` while the thread is tied.

Examples
--------
>>> from topomark.spec.world import World
>>> layer = MarkerLayer(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}))
>>> layer.drop_vertex("a", 1, head=1)
>>> layer.vertex_mark("a")
VertexMark(count=1, head=1)
>>> layer.drop_edge("b", 0, 2, end=None)
>>> layer.dart_marks("c")  # b is exit 1 of c
(DartMark(exit=1, count=2, end=None),)
>>> [m.__class__.__name__ for m in layer.world().markers]
['VertexMarker', 'EdgeMarker']
>>> layer.pick_up_vertex("a", 1)
>>> layer.vertex_mark("a") is None
True
"""

from __future__ import annotations

from typing import Iterator, TypeVar

from topomark.spec.errors import InvalidInput
from topomark.spec.kit import MarkerOp, ThreadOp
from topomark.spec.marker import EdgeMarker, Marker, VertexMarker
from topomark.spec.signature import KeptSignatures, Signature
from topomark.spec.thread import ThreadedWorld, ThreadMark, ThreadState
from topomark.spec.world import DartMark, VertexMark, World

__all__ = ["MarkerLayer", "apply_op"]

_FLIP = {"H": "T", "T": "H", None: None}
P = TypeVar("P", str, frozenset[str])  # a place: a vertex or an edge
M = TypeVar("M", VertexMarker, EdgeMarker)


def _exit(mark: DartMark) -> int:
    return mark.exit


class MarkerLayer:
    """Mutable markers over ``world``'s rotation; starts with the world's own markers."""

    __slots__ = ("base", "_vmarks", "_emarks", "_dmarks", "_world", "degree", "target", "neighbour", "thread",
                 "thread_marks", "_vobjects", "_eobjects", "lying", "_sensed")

    def __init__(self, world: World):
        self.base = world
        # The rotation's queries are the world's own (bound here, not forwarded: they are on the robot's hot path).
        self.degree, self.target, self.neighbour = world.degree, world.target, world.neighbour
        self._vmarks: dict[str, VertexMark] = {v: mark for v in world.vertices
                                               if (mark := world.vertex_mark(v)) is not None}
        # edge -> (tail-side dart (v, exit), count, end seen from that dart); insertion order kept
        self._emarks: dict[frozenset[str], tuple[tuple[str, int], int, str | None]] = {}
        for v in world.vertices:
            for dm in world.dart_marks(v):
                key = frozenset((v, world.neighbour(v, dm.exit)))
                self._emarks.setdefault(key, ((v, dm.exit), dm.count, dm.end))
        self._dmarks: dict[str, tuple[DartMark, ...]] = {v: world.dart_marks(v) for v in world.vertices
                                                         if world.dart_marks(v)}
        # place -> the Marker lying there, kept per change so a snapshot is O(markers) at C speed, not a rebuild
        self._vobjects: dict[str, VertexMarker] = {}
        self._eobjects: dict[frozenset[str], EdgeMarker] = {}
        self.lying = 0  # the number of markers now lying in the world (the sum of the counts of markers())
        self._sensed = KeptSignatures()  # what is sensed at each vertex, until it changes there
        for v in self._vmarks:
            self._place_changed(v)
        for key in self._emarks:
            self._place_changed(key)
        self._world: World | None = world  # after _place_changed, which forgets the snapshot
        thread = getattr(world, "thread", None)
        self.thread = ThreadState() if thread is None else thread.state(world)
        self.thread_marks = self.thread.marks(world)  # vertex -> ThreadMark, what signature_at reads

    # -- the queries of a world (degree, target and neighbour are bound in __init__) ----
    @property
    def vertices(self) -> tuple[str, ...]:
        return self.base.vertices

    def vertex_mark(self, v: str) -> VertexMark | None:
        return self._vmarks.get(v)

    def dart_marks(self, v: str) -> tuple[DartMark, ...]:
        return self._dmarks.get(v, ())

    def thread_mark(self, v: str) -> ThreadMark | None:
        """What of the thread lies at ``v`` (absolute exits), or None."""
        return self.thread_marks.get(v)

    def pull(self, state: tuple[str, int], motion: int, length: int) -> bool:
        """What a move from ``state`` by ``motion`` does to the thread (:meth:`ThreadState.pull`):
        True if it rewinds an edge; a lay beyond ``length`` edges is refused before the robot moves."""
        if self.thread.tied is None or not self.thread.held:
            return False
        self._forget()
        try:
            return self.thread.pull(self.base, state, motion, length)
        finally:
            self.thread_marks = self.thread.marks(self.base)

    def sensed(self, state: tuple[str, int]) -> Signature:
        """What a robot in ``state`` = (vertex, entry) senses: :func:`~topomark.spec.robot.sense` of this layer,
        kept until the marks or the thread at that vertex change (the simulator's robot senses once per move)."""
        return self._sensed.get(self, state[0], state[1])

    def _forget(self, *vertices: str) -> None:
        """After a change at ``vertices`` (none named: the thread, anywhere): the world snapshot and what was
        sensed there are stale."""
        self._world = None
        self._sensed.forget(vertices or None)

    def _place_changed(self, place: str | frozenset[str]) -> None:
        """Rebuild the one :class:`Marker` at ``place`` (a vertex, or an edge's frozenset) after a change.

        ``_vobjects``/``_eobjects`` keep the order of ``_vmarks``/``_emarks`` (a count change keeps a place's
        position, a place emptied and marked again goes last, as in those dicts)."""
        self._forget(*([place] if isinstance(place, str) else place))
        if isinstance(place, str):
            mark = self._vmarks.get(place)
            vobj = None if mark is None else VertexMarker(
                place, mark.count, None if mark.head is None else self.base.neighbour(place, mark.head))
            self.lying += _put(self._vobjects, place, vobj)
        else:
            entry, eobj = self._emarks.get(place), None
            if entry is not None:
                (v, exit), count, end = entry
                w = self.base.neighbour(v, exit)
                eobj = EdgeMarker((v, w), count, None if end is None else (v if end == "H" else w))
            self.lying += _put(self._eobjects, place, eobj)

    def _refresh(self, v: str, exit: int) -> None:
        """Redo the dart mark of the edge at exit ``exit`` of ``v`` at both its ends after a change (the world is
        simple: the edge is that one exit at each end); the other dart marks there stay, in exit order."""
        w, j = self.base.target((v, exit))
        key = frozenset((v, w))
        self._place_changed(key)
        entry = self._emarks.get(key)
        for x, i in ((v, exit), (w, j)):
            marks = [dm for dm in self._dmarks.get(x, ()) if dm.exit != i]
            if entry is not None:
                (tail, _), count, end = entry
                marks.append(DartMark(i, count, end if tail == x else _FLIP[end]))
                marks.sort(key=_exit)
            if marks:
                self._dmarks[x] = tuple(marks)
            else:
                self._dmarks.pop(x, None)

    # -- operations ----------------------------------------------------------
    def drop_vertex(self, v: str, count: int, head: int | None) -> None:
        """Add ``count`` markers at ``v``, pointing at exit ``head`` (None: undirected)."""
        _positive(count)
        old = self._vmarks.get(v)
        if old is not None and old.head != head:
            raise InvalidInput(f"vertex {v!r} already holds markers {_vertex_words(old.head)}; a marker "
                               f"{_vertex_words(head)} cannot join them")
        self._vmarks[v] = VertexMark(count + (old.count if old else 0), head)
        self._place_changed(v)

    def drop_edge(self, v: str, exit: int, count: int, end: str | None) -> None:
        """Add ``count`` markers on the edge at exit ``exit`` of ``v``; ``end`` is "H"/"T" as seen from ``v``."""
        _positive(count)
        key = frozenset((v, self.base.neighbour(v, exit)))
        old = self._emarks.get(key)
        if old is None:
            self._emarks[key] = ((v, exit), count, end)
        else:
            (tail, texit), have, old_end = old
            seen = old_end if tail == v else _FLIP[old_end]
            if seen != end:
                raise InvalidInput(f"the edge at exit {exit} of {v!r} already holds markers with end {seen!r} "
                                   f"here; markers with end {end!r} cannot join them")
            self._emarks[key] = ((tail, texit), have + count, old_end)
        self._refresh(v, exit)

    def pick_up_vertex(self, v: str, count: int) -> None:
        """Take ``count`` markers from ``v``."""
        _positive(count)
        old = self._vmarks.get(v)
        if old is None or old.count < count:
            raise InvalidInput(f"cannot pick up {count} marker(s) at vertex {v!r}: {old.count if old else 0} there")
        if old.count == count:
            del self._vmarks[v]
        else:
            self._vmarks[v] = VertexMark(old.count - count, old.head)
        self._place_changed(v)

    def pick_up_edge(self, v: str, exit: int, count: int) -> None:
        """Take ``count`` markers from the edge at exit ``exit`` of ``v``."""
        _positive(count)
        key = frozenset((v, self.base.neighbour(v, exit)))
        old = self._emarks.get(key)
        if old is None or old[1] < count:
            there = old[1] if old else 0
            raise InvalidInput(f"cannot pick up {count} marker(s) on the edge at exit {exit} of {v!r}: {there} there")
        if old[1] == count:
            del self._emarks[key]
        else:
            self._emarks[key] = (old[0], old[1] - count, old[2])
        self._refresh(v, exit)

    # -- the world as it is now ------------------------------------------------
    def markers(self) -> Iterator[Marker]:
        """The markers now lying in the world, vertex markers then edge markers, in the order first placed."""
        yield from self._vobjects.values()
        yield from self._eobjects.values()

    def _snapshot(self) -> tuple[Marker, ...]:
        return tuple(self._vobjects.values()) + tuple(self._eobjects.values())

    def world(self) -> World:
        """A :class:`World` with the current markers (built once per change, on demand)."""
        if self._world is None:
            if self.thread.tied is None:
                self._world = World.of_layer(self.base, self._snapshot(), self._vmarks, self._dmarks)
            else:  # a snapshot, not re-validated: this layer's operations keep the world and the thread valid
                self._world = ThreadedWorld.of_layer(self.base, self._snapshot(), self._vmarks, self._dmarks,
                                                     self.thread)
        return self._world


def _put(objects: dict[P, M], place: P, obj: M | None) -> int:
    """Make ``obj`` the marker at ``place`` in ``objects`` (None: none); the change in the count lying there."""
    old = objects.get(place)
    if obj is None:
        objects.pop(place, None)
    else:
        objects[place] = obj
    return (obj.count if obj else 0) - (old.count if old else 0)


def apply_op(layer: MarkerLayer, state: tuple[str, int], op: MarkerOp | ThreadOp) -> None:
    """Carry out ``op`` by a robot in ``state`` = (vertex, entry); refusals are InvalidInput naming why."""
    if isinstance(op, ThreadOp):
        layer._forget()
        try:
            layer.thread.apply(layer.base, state, op, 0)
            return
        finally:
            layer.thread_marks = layer.thread.marks(layer.base)
    v, entry = state
    d = layer.degree(v)
    if op.kind == "vertex":
        if op.exit is not None:
            raise InvalidInput("a vertex marker takes no exit")
        if op.pick_up:
            return layer.pick_up_vertex(v, op.count)
        if op.direction is not None and not (isinstance(op.direction, int) and 0 <= op.direction < d):
            raise InvalidInput(f"direction {op.direction!r} is not an exit of a vertex of degree {d}")
        return layer.drop_vertex(v, op.count, None if op.direction is None else (entry + op.direction) % d)
    if op.kind != "edge":
        raise InvalidInput(f"unknown marker kind {op.kind!r} (vertex or edge)")
    if not (isinstance(op.exit, int) and not isinstance(op.exit, bool) and 0 <= op.exit < d):
        raise InvalidInput(f"edge marker exit {op.exit!r} is not an exit of a vertex of degree {d}")
    if op.pick_up:
        return layer.pick_up_edge(v, (entry + op.exit) % d, op.count)
    if op.direction not in (None, "H", "T"):
        raise InvalidInput(f"an edge marker's direction is \"H\", \"T\" or null, got {op.direction!r}")
    return layer.drop_edge(v, (entry + op.exit) % d, op.count, op.direction)


def _positive(count: int) -> None:
    if not isinstance(count, int) or isinstance(count, bool) or count < 1:
        raise InvalidInput(f"a marker count must be a positive integer, got {count!r}")


def _vertex_words(head: int | None) -> str:
    return "without a direction" if head is None else f"pointing at exit {head}"
