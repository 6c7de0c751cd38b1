"""Marker kits: what a robot carries, and the marker operations it may do with them (thesis §3.1.1,
§6.1–6.3, §2.3.1).

A :class:`Kit` is what the robot is given before it sets out: how many vertex
markers and edge markers, how many markers it may drop at a vertex *or* on an
edge as it needs (``either``: §6.2.1 Case 1b's pool of m + 1 homogeneous
V-E-markers), whether they are directional, whether they may be
picked up again (the movable marker of Dudek et al., §2.3.1), and a thread of
some length (§6.3).  A :class:`MarkerOp` is one operation as the robot states
it, relative to its entry edge.  The simulator refuses any operation the kit
does not allow (:meth:`Kit.refusal` says why); the protocol's ``hello``
carries :meth:`Kit.to_json`.  Where the kits of the thesis's marker classes
are placed in worlds is :mod:`topomark.spec.markerclass`.

Decision (the thesis is silent): a kit's markers are all directional or all
undirected — every marker class of the thesis is homogeneous in that respect
(Figure 3.21, §6.1, §6.2) — and a thread's length is in edges, 0 meaning the
thesis's l = ε (tied at v0, never laid along an edge; §6.3).

Decision (§6.2.1 Case 1b, footnote 16: "exactly 1 marker is dropped (either on
the vertex or on the edge …)"; the thesis counts Case 1b's markers as one
homogeneous pool): a drop is drawn from its kind's own markers first, then
from the pool (:meth:`Kit.draw`), so a kit without a pool behaves exactly as
before; running out of both is the simulator's ``OutOfMarkers``.  A pool is
never movable (bad input): no thesis algorithm picks pooled markers up — the
movable marker is Dudek et al.'s single one (§2.3.1) — and so no rule is
needed for which count a picked-up pooled marker returns to.

This module imports nothing that can see a world: explorers may use it.

Examples
--------
>>> Kit(vertex=1, directional=True).to_json()
{'directional-vertex': 1}
>>> Kit.from_json({"directional-vertex": 1}) == Kit(vertex=1, directional=True)
True
>>> Kit(vertex=1).refusal("edge", directional=False, count=1, held=0)
'the kit (1 undirected vertex marker) has no edge marker'
>>> pool = Kit(either=2)
>>> pool.to_json(), Kit.from_json(pool.to_json()) == pool, pool.describe()
({'undirected-either': 2}, True, '2 undirected vertex-or-edge markers')
>>> pool.refusal("edge", directional=False, count=1, held=0, pooled=2)
'the kit (2 undirected vertex-or-edge markers) holds 0 edge and 2 vertex-or-edge marker(s): none left, 1 asked for'
>>> Kit(vertex=1, either=2).draw("vertex", count=2, held=0)  # the kind's own first, then the pool
(1, 1)
>>> MarkerOp("edge", exit=2, direction="H").to_json()
{'op': 'drop', 'kind': 'edge', 'count': 1, 'exit': 2, 'direction': 'H'}
>>> ThreadOp("tie", direction=0).to_json()
{'op': 'tie', 'kind': 'thread', 'count': 1, 'direction': 0}
>>> Kit(vertex=1).thread_refusal()
'the kit (1 undirected vertex marker) has no thread'
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from topomark.spec.errors import InvalidInput, clip

__all__ = ["Kit", "MarkerOp", "ThreadOp", "THREAD_OPS", "MAX_COUNT", "MAX_THREAD"]

MAX_COUNT = 10 ** 6
"""The most markers of one kind a kit given from outside may hold (``--kit``, a protocol ``hello``), and the most
markers one protocol operation or snapshot mark may state (``spec/protocol.md``)."""
MAX_THREAD = MAX_COUNT
"""The longest thread, in edges, a kit given from outside may hold, and a thread option may ask for: the same cap."""


@dataclass(frozen=True)
class Kit:
    """What the robot carries: ``vertex`` vertex markers, ``edge`` edge markers, ``either`` markers it may
    drop at a vertex or on an edge, optionally a thread.

    ``directional`` applies to every marker of the kit, the pool's included;
    ``movable`` means a dropped marker may be picked up again (never with a
    pool, see the module docstring); ``thread`` is a thread length in edges
    (0 for l = ε) or ``None`` for no thread; ``either`` (last, so positional
    kits read as before) is the pool, drawn after the kind's own count.
    """

    vertex: int = 0
    edge: int = 0
    directional: bool = False
    movable: bool = False
    thread: int | None = None
    either: int = 0

    def __post_init__(self) -> None:
        for name in ("vertex", "edge", "either"):
            value = getattr(self, name)
            if not isinstance(value, int) or isinstance(value, bool) or value < 0:
                raise InvalidInput(f"kit: {name} markers must be a non-negative integer, got {clip(repr(value), 60)}")
        thread = self.thread  # bool is an int subclass: true is no length
        if thread is not None and (not isinstance(thread, int) or isinstance(thread, bool) or thread < 0):
            raise InvalidInput(f"kit: thread length must be a non-negative integer, got {clip(repr(thread), 60)}")
        if self.movable and self.either:
            raise InvalidInput("kit: vertex-or-edge markers cannot be movable (no thesis algorithm picks a pooled "
                               "marker up; §2.3.1's movable marker is a single one)")

    def cap_refusal(self) -> str | None:
        """Why this kit is past the caps of a kit given from outside (:data:`MAX_COUNT`, :data:`MAX_THREAD`), or
        None."""
        for name in ("vertex", "edge", "either"):
            if getattr(self, name) > MAX_COUNT:
                return f"{name} markers: at most {MAX_COUNT:,}, got {getattr(self, name):,}"
        if self.thread is not None and self.thread > MAX_THREAD:
            return f"a thread is at most {MAX_THREAD:,} edges long (the cap of a marker count), got {self.thread:,}"
        return None

    def count(self, kind: str) -> int:
        """How many markers of ``kind`` (``"vertex"`` or ``"edge"``) the kit holds, its pool (``either``) apart."""
        return {"vertex": self.vertex, "edge": self.edge}[kind]

    def draw(self, kind: str, count: int, held: int) -> tuple[int, int]:
        """How a drop of ``count`` markers of ``kind``, ``held`` of its own already dropped, is drawn:
        (from the kind's own markers, from the pool) — its own first."""
        own = max(0, min(count, self.count(kind) - held))
        return own, count - own

    def describe(self) -> str:
        word = "directional" if self.directional else "undirected"
        movable = " movable" if self.movable else ""
        parts = [f"{n} {word}{movable} {kind} marker{'s' if n != 1 else ''}"
                 for kind, n in (("vertex", self.vertex), ("edge", self.edge), ("vertex-or-edge", self.either)) if n]
        if self.thread is not None:
            parts.append("a thread of length ε" if self.thread == 0 else f"a thread of length {self.thread}")
        return ", ".join(parts) or "no marker"

    def refusal(self, kind: str, directional: bool, count: int, held: int, pooled: int = 0) -> str | None:
        """Why dropping ``count`` markers of ``kind`` is not allowed, or None: ``held`` of the kind's own
        markers and ``pooled`` of the pool already dropped."""
        have = self.count(kind)
        if have + self.either == 0:
            return f"the kit ({self.describe()}) has no {kind} marker"
        if directional != self.directional:
            want = "directional" if self.directional else "undirected"
            return f"the kit ({self.describe()}) holds {want} markers only"
        left = max(0, have - held) + self.either - pooled
        if count > left:
            holds = f"{have} {kind}" if not self.either else f"{have} {kind} and {self.either} vertex-or-edge"
            return f"the kit ({self.describe()}) holds {holds} marker(s): {left or 'none'} left, {count} asked for"
        return None

    def thread_refusal(self) -> str | None:
        """Why a thread operation is not allowed with this kit (it has no thread), or None."""
        return None if self.thread is not None else f"the kit ({self.describe()}) has no thread"

    def to_json(self) -> dict[str, Any]:
        """The kit as the protocol's ``hello.markers`` object, e.g. ``{"directional-vertex": 1}``."""
        word = "directional" if self.directional else "undirected"
        out: dict[str, Any] = {f"{word}-{k}": n for k, n in (("vertex", self.vertex), ("edge", self.edge),
                                                             ("either", self.either)) if n}
        if self.movable:
            out["movable"] = True
        if self.thread is not None:
            out["thread"] = self.thread
        return out

    @classmethod
    def from_json(cls, obj: Any) -> "Kit":
        """Inverse of :meth:`to_json`; anything else is :class:`InvalidInput` naming the key."""
        if not isinstance(obj, dict):
            raise InvalidInput(f"kit must be an object, got {clip(repr(obj), 60)}")
        counts: dict[str, int] = {}
        words = set()
        for key, value in obj.items():
            word, _, kind = key.partition("-")
            if key in ("movable", "thread"):
                continue
            if word not in ("directional", "undirected") or kind not in ("vertex", "edge", "either"):
                raise InvalidInput(f"kit: unknown key {clip(key, 60, quote=True)}")
            words.add(word)
            counts[kind] = value
        if len(words) > 1:
            raise InvalidInput("kit: directional and undirected markers cannot be mixed")
        movable = obj.get("movable", False)
        if not isinstance(movable, bool):
            raise InvalidInput(f"kit: movable must be true or false, got {clip(repr(movable), 60)}")
        return cls(counts.get("vertex", 0), counts.get("edge", 0), words == {"directional"}, movable,
                   obj.get("thread"), counts.get("either", 0))


@dataclass(frozen=True)
class MarkerOp:
    """A marker operation as the robot states it, relative to its entry edge (§3.1.1).

    ``kind`` is ``"vertex"`` or ``"edge"``; ``exit`` (edge markers only) is the
    marked exit counted clockwise from the entry edge, like a motion;
    ``direction`` is, for a vertex marker, the relative exit it points at, and
    for an edge marker ``"H"`` or ``"T"`` — its head or tail at this vertex —
    and ``None`` for an undirected marker; ``pick_up`` takes markers instead.
    """

    kind: str = "vertex"
    exit: int | None = None
    direction: int | str | None = None
    count: int = 1
    pick_up: bool = False

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"op": "pick_up" if self.pick_up else "drop", "kind": self.kind, "count": self.count}
        if self.exit is not None:
            out["exit"] = self.exit
        if self.direction is not None:
            out["direction"] = self.direction
        return out


THREAD_OPS = ("tie", "untie", "leave", "take", "knot", "rewind")
"""The thread operations (§6.3, :mod:`topomark.spec.thread` says what each does)."""


@dataclass(frozen=True)
class ThreadOp:
    """A thread operation as the robot states it, relative to its entry edge (§6.3).

    ``op`` is one of :data:`THREAD_OPS`: ``tie`` the thread here (``direction``:
    the relative exit it is laid out toward, the l = ε thread's direction, or
    None), ``untie`` it, ``leave`` its free end here, ``take`` the free end
    lying here, tie ``count`` knots here (``knot``), ``rewind`` (a move back
    along the last laid edge, picking it up; see ``Robot.rewind``).  Its JSON
    form has the shape of :meth:`MarkerOp.to_json` with ``kind`` ``"thread"``.
    """

    op: str
    direction: int | None = None
    count: int = 1

    kind = "thread"

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"op": self.op, "kind": "thread", "count": self.count}
        if self.direction is not None:
            out["direction"] = self.direction
        return out
