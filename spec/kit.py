"""Marker kits and marker classes: what a robot carries, and where a class's markers lie (thesis §3.1.1,
§3.2, §3.3, Figure 3.21, §6.1–6.3, §2.3.1).

A :class:`Kit` is what the robot is given before it sets out: how many vertex
markers and edge markers, whether they are directional, whether they may be
picked up again (the movable marker of Dudek et al., §2.3.1), and a thread of
some length (§6.3).  The robot and the simulator refuse any operation the
kit does not allow (:meth:`Kit.refusal` says why); the protocol's ``hello``
carries :meth:`Kit.to_json`.

A :class:`MarkerClass` is a kit placed in a world: it says which markers the
world carries and where the robot starts.  Searches and the census range
over every world, every placement of the class's markers and every starting
exit; :meth:`MarkerClass.placements` enumerates exactly those.

=========================  ==========================================================  ==========
name                       markers and start                                           thesis
=========================  ==========================================================  ==========
none                       no marker; start anywhere                                   §3.2.1, Fig 3.3
undirected-vertex          one undirected marker at the start vertex                   §3.2.2, Fig 3.4
directional-vertex         one directional marker at the start vertex                  §3.3, Fig 3.6
two-undirected-vertex      one marker each on two adjacent vertices; start at one      Fig 3.21(a)
three-undirected-vertex    one marker on the start vertex, two on a neighbour          Fig 3.21(b)
undirected-edge            one marker on an edge; start at an end of it                §6.1, Fig 6.1(a)
directional-edge           one directional marker on an edge; start at an end          §6.1, Fig 6.1(b)
vertex-and-edge            one marker at the start vertex, one on an incident edge     §6.2
=========================  ==========================================================  ==========

Decision (the thesis is silent): a kit's markers are all directional or all
undirected — every marker class of the thesis is homogeneous in that respect
(Figure 3.21, §6.1, §6.2) — and a thread's length is in edges, 0 meaning the
thesis's l = ε (tied at v0, never laid along an edge; §6.3).

Examples
--------
>>> from topomark.spec.world import World
>>> tri = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})
>>> len(list(MARKER_CLASSES["directional-vertex"].placements(tri)))  # 3 vertices x 2 heads x 2 facings
12
>>> MARKER_CLASSES["directional-vertex"].kit.to_json()
{'directional-vertex': 1}
>>> Kit.from_json({"directional-vertex": 1}) == Kit(vertex=1, directional=True)
True
>>> Kit(vertex=1).refusal("edge", directional=False, count=1, held=0)
'the kit (1 undirected vertex marker) has no edge marker'
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Iterator

from .errors import InvalidInput
from .marker import EdgeMarker, Marker, VertexMarker
from .world import Start, World

__all__ = ["Kit", "MarkerClass", "MARKER_CLASSES", "marker_class"]


@dataclass(frozen=True)
class Kit:
    """What the robot carries: ``vertex`` vertex markers, ``edge`` edge markers, optionally a thread.

    ``directional`` applies to every marker of the kit; ``movable`` means a
    dropped marker may be picked up again; ``thread`` is a thread length in
    edges (0 for l = ε) or ``None`` for no thread.
    """

    vertex: int = 0
    edge: int = 0
    directional: bool = False
    movable: bool = False
    thread: int | None = None

    def __post_init__(self) -> None:
        for name in ("vertex", "edge"):
            value = getattr(self, name)
            if not isinstance(value, int) or isinstance(value, bool) or value < 0:
                raise InvalidInput(f"kit: {name} markers must be a non-negative integer, got {value!r}")
        if self.thread is not None and (not isinstance(self.thread, int) or self.thread < 0):
            raise InvalidInput(f"kit: thread length must be a non-negative integer, got {self.thread!r}")

    def count(self, kind: str) -> int:
        """How many markers of ``kind`` (``"vertex"`` or ``"edge"``) the kit holds."""
        return {"vertex": self.vertex, "edge": self.edge}[kind]

    def describe(self) -> str:
        word = "directional" if self.directional else "undirected"
        movable = " movable" if self.movable else ""
        parts = [f"{n} {word}{movable} {kind} marker{'s' if n != 1 else ''}"
                 for kind, n in (("vertex", self.vertex), ("edge", self.edge)) if n]
        if self.thread is not None:
            parts.append("a thread of length ε" if self.thread == 0 else f"a thread of length {self.thread}")
        return ", ".join(parts) or "no marker"

    def refusal(self, kind: str, directional: bool, count: int, held: int) -> str | None:
        """Why dropping ``count`` markers of ``kind`` is not allowed with ``held`` already dropped, or None."""
        have = self.count(kind)
        if have == 0:
            return f"the kit ({self.describe()}) has no {kind} marker"
        if directional != self.directional:
            want = "directional" if self.directional else "undirected"
            return f"the kit ({self.describe()}) holds {want} markers only"
        if held + count > have:
            left = have - held
            return f"the kit ({self.describe()}) holds {have} {kind} marker(s): {left or 'none'} left, {count} asked for"
        return None

    def to_json(self) -> dict[str, Any]:
        """The kit as the protocol's ``hello.markers`` object, e.g. ``{"directional-vertex": 1}``."""
        word = "directional" if self.directional else "undirected"
        out: dict[str, Any] = {f"{word}-{k}": n for k, n in (("vertex", self.vertex), ("edge", self.edge)) if n}
        if self.movable:
            out["movable"] = True
        if self.thread is not None:
            out["thread"] = self.thread
        return out

    @classmethod
    def from_json(cls, obj: Any) -> "Kit":
        """Inverse of :meth:`to_json`; anything else is :class:`InvalidInput` naming the key."""
        if not isinstance(obj, dict):
            raise InvalidInput(f"kit must be an object, got {obj!r}")
        counts: dict[str, int] = {}
        words = set()
        for key, value in obj.items():
            word, _, kind = key.partition("-")
            if key in ("movable", "thread"):
                continue
            if word not in ("directional", "undirected") or kind not in ("vertex", "edge"):
                raise InvalidInput(f"kit: unknown key {key!r}")
            words.add(word)
            counts[kind] = value
        if len(words) > 1:
            raise InvalidInput("kit: directional and undirected markers cannot be mixed")
        movable = obj.get("movable", False)
        if not isinstance(movable, bool):
            raise InvalidInput(f"kit: movable must be true or false, got {movable!r}")
        return cls(counts.get("vertex", 0), counts.get("edge", 0), words == {"directional"}, movable,
                   obj.get("thread"))


@dataclass(frozen=True)
class MarkerClass:
    """A kit placed in a world: the placements searches and the census range over."""

    name: str
    kit: Kit
    description: str
    section: str
    sufficient: bool  # what the thesis shows: a single class member maps every world
    _layouts: Callable[[World, str], Iterator[list[Marker]]]

    def placements(self, world: World) -> Iterator[World]:
        """Every placement of this class's markers on ``world`` with every starting exit."""
        for v in world.vertices:
            for markers in self._layouts(world, v):
                for facing in world.rotation[v]:
                    yield World(world.rotation, markers, Start(v, facing))


def _none(world, v):
    yield []


def _undirected_vertex(world, v):
    yield [VertexMarker(v)]


def _directional_vertex(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v, 1, w)]


def _two_undirected(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v), VertexMarker(w)]


def _three_undirected(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v), VertexMarker(w, 2)]


def _undirected_edge(world, v):
    for w in world.rotation[v]:
        yield [EdgeMarker((v, w))]


def _directional_edge(world, v):
    for w in world.rotation[v]:
        for head in (v, w):
            yield [EdgeMarker((v, w), 1, head)]


def _vertex_and_edge(world, v):
    for w in world.rotation[v]:
        yield [VertexMarker(v), EdgeMarker((v, w))]


MARKER_CLASSES: dict[str, MarkerClass] = {c.name: c for c in (
    MarkerClass("none", Kit(), "no marker", "§3.2.1", False, _none),
    MarkerClass("undirected-vertex", Kit(vertex=1), "one undirected vertex marker at the start", "§3.2.2", False,
                _undirected_vertex),
    MarkerClass("directional-vertex", Kit(vertex=1, directional=True), "one directional vertex marker at the start",
                "§3.3", True, _directional_vertex),
    MarkerClass("two-undirected-vertex", Kit(vertex=2), "undirected markers on the start and an adjacent vertex",
                "§3.7, Figure 3.21(a)", False, _two_undirected),
    MarkerClass("three-undirected-vertex", Kit(vertex=3), "one undirected marker at the start, two on a neighbour",
                "§3.7, Figure 3.21(b)", True, _three_undirected),
    MarkerClass("undirected-edge", Kit(edge=1), "one undirected edge marker; start at an end",
                "§6.1, Figure 6.1(a)", False, _undirected_edge),
    MarkerClass("directional-edge", Kit(edge=1, directional=True), "one directional edge marker; start at an end",
                "§6.1, Figure 6.1(b)", True, _directional_edge),
    MarkerClass("vertex-and-edge", Kit(vertex=1, edge=1), "one undirected marker at the start and one on an "
                "incident edge", "§6.2", True, _vertex_and_edge),
)}


def marker_class(name: str) -> MarkerClass:
    """The marker class called ``name``; an unknown name is :class:`InvalidInput` listing the known ones."""
    if name not in MARKER_CLASSES:
        raise InvalidInput(f"unknown marker class {name!r} (choose from {', '.join(MARKER_CLASSES)})")
    return MARKER_CLASSES[name]
