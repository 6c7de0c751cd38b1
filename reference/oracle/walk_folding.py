"""The identifications a program's observations force: whether they determine its map, decided exactly (§3.1, §3.3).

A program's walk visits *occurrences* — the vertex it stands on after each motion — and all it knows of them is what
it sensed (§3.1.1: the degree, the markers, relative to the entry edge).  Which occurrences are one vertex is what a
map decides; a map is *determined* when every world that shows the same observations to the same actions identifies
them alike, up to isomorphism.  This module decides it by folding the walk (the identifications a rotation system
forces, as in Stallings' folding of graphs):

1. **the walk's own identifications.**  A motion through the same exit of the same vertex arrives at the same vertex
   by the same edge; so occurrences are joined by their edges, and two edges leaving one vertex by one exit are one
   edge (congruence, with the exits' rotation offsets);
2. **what the marks force.**  A visit that senses marks (§3.1.1 ``V-k``, ``V#``; §6.1 ``E-p``, ``E-p-H``; §6.3 the
   thread tied, laid along an edge, its free end, knots) stands where they were put and still lie:
   :mod:`~topomark.reference.oracle.folded_marks` sums the operations over the folding's places — a thread laid
   along the edge the robot crossed, picked up by a rewind, which arrives where that edge was laid from — and finds
   the first visit that would sense fewer than it did; each place that then holds such marks is a way to mend it
   (a directional reading fixes the rotation, an undirected one leaves each open; an edge mark is the same dart
   or, on an edge no visit crossed, its far end) — a branch each — and a lack only one way can mend is taken
   without branching;
3. **the leaves.**  Each branch closed under (1) and (2) is the *finest* world the observations allow along it: a
   world with an exit no occurrence used (completed with new leaves), or one not isomorphic to the map, that gives
   every observation is a witness of a guess.  When the finest world is the map, every other world that gives the
   observations is a *quotient* of it by a covering (every consistent identification contains the finest; a
   covering of connected graphs has fibres of one size, so the start's fibre holds another vertex): each is tried
   by identifying the start with each vertex of its degree, at each rotation, and closing.

Why this is complete (the decision, where the thesis is silent on how an oracle tells knowledge from luck): while
the visits so far sense exactly what the robot did, no place holds fewer than zero markers, so identifying more
only adds markers — a visit that would sense *more* rules out every coarser world, and a world that gives the
observations, followed branch by branch, passes through one of the ways each lack lists; so it is a quotient of a
leaf, and the leaf gives the observations too.  A move back along the last laid edge by a motion rather than a
``rewind`` picks the thread up; where that leaves no thread on the edge the robot senses so, and in any world
that gives the observations the move picked it up too; where the thread lay on that edge twice, another world
could have laid it a third time instead: such a run is outside the decision and judged by the sound tests of
:mod:`topomark.reference.oracle.determination` alone (:func:`walk`'s ``scope`` says why); so are runs past
:data:`MAX_BRANCHES` branches.

Every witness found here is replayed by the simulator and compared signature by signature
(:func:`~topomark.reference.oracle.agreement.agrees`) before it is reported.

Examples
--------
>>> from topomark.spec.kit import Kit, MarkerOp
>>> from topomark.reference.worlds.deterministic import cycle
>>> three, kit = cycle(3), Kit(vertex=1, directional=True)
>>> drop = MarkerOp("vertex", direction=1)
>>> print(decide(three, three.start_state(), kit, [drop, 1, 1, 1]))  # the marker seen again: a triangle
None
>>> decide(three, three.start_state(), kit, [drop, 1, 1]).how  # it never comes back: an exit unused
'unvisited exit'
"""

from __future__ import annotations

from array import array
from dataclasses import dataclass, field
from typing import Iterator, Sequence

from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.kit import THREAD_OPS, Kit, MarkerOp, ThreadOp
from topomark.spec.thread import shifted
from topomark.spec.world import World

from topomark.reference.oracle.agreement import REWIND, act, agrees as replayed, matches
from topomark.reference.oracle.folded_marks import PRUNED, Deficit, Event, Observed, Op, scan, take
from topomark.reference.oracle.folding import Folding
from topomark.reference.run.simulator import Simulator

__all__ = ["Walk", "Found", "walk", "folding_scope", "decide", "MAX_BRANCHES"]

MAX_BRANCHES = 4096
"""The most branches (rotations left open by undirected sightings) searched before the decision gives up as inexact."""


@dataclass
class Walk:
    """A run as visits: each visit's degree, the walk's edges ``(i, exit, j, exit)`` in each visit's own frame
    (relative to its entry, §3.1.1), the marker operations and what each sensing showed
    (:mod:`~topomark.reference.oracle.folded_marks`)."""

    degree: list[int] = field(default_factory=list)
    edges: list[tuple[int, int, int, int]] = field(default_factory=list)
    unions: list[tuple[int, int, int, int]] = field(default_factory=list)  # (i, exit, j, exit): a rewind's arrival
    ops: list[Op] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    seen: array = field(default_factory=lambda: array("q"))  # a hash of each signature sensed, the start's first
    left: World | None = None  # the world with the markers the actions leave in it
    scope: str | None = None  # why the run is outside the exact decision, or None


def folding_scope(kit: Kit) -> str | None:
    """Why a run with ``kit`` cannot be decided exactly here before it is even looked at, or None (every kit can)."""
    return None


def _observed(sim: Simulator) -> Observed:
    """What the robot in ``sim`` senses of the markers and the thread, relative to its entry (§3.1.1, §6.3)."""
    v, entry = sim.state
    layer, deg = sim.layer, sim.layer.degree(v)
    vertex: dict[str, tuple[int, int | None]] = {}
    mark = layer.vertex_mark(v)
    if mark is not None:
        vertex["vertex"] = (mark.count, None if mark.head is None else (mark.head - entry) % deg)
    darts = {("edge", (m.exit - entry) % deg): (m.count, m.end) for m in layer.dart_marks(v)}
    thread = layer.thread_mark(v)
    if thread is not None:
        thread = shifted(thread, entry, deg)
        for kind, count, head in (("tied", int(thread.tied), thread.head), ("end", int(thread.end), None),
                                  ("knot", thread.knots, None)):
            if count:
                vertex[kind] = (count, head)
        darts.update((("thread", x), (times, None)) for x, times in thread.edges)
    return vertex, darts


class _Thread:
    """The thread as the walk laid it: its laid edges ``(visit, exit, visit)`` and the knots at each length."""

    def __init__(self) -> None:
        self.laid: list[tuple[int, int, int]] = []
        self.knots: dict[int, list[tuple[int, int]]] = {}
        self.left = False  # the free end lies where it was left

    def op(self, out: Walk, now: int, op: ThreadOp) -> None:
        """Record ``op`` at visit ``now`` as the marks it adds or removes."""
        if op.op == "tie":
            out.ops.append((now, "tied", None, op.direction, 1))
        elif op.op == "untie":  # the thread goes, with its knots and its free end
            out.ops.append((now, "tied", None, None, -1))
            out.ops.extend((at, "knot", None, None, -k) for at, k in self.knots.pop(0, []))
            if self.left:
                out.ops.append((now, "end", None, None, -1))
            self.left = False
        elif op.op in ("leave", "take"):
            self.left = op.op == "leave"
            out.ops.append((now, "end", None, None, 1 if self.left else -1))
        else:
            assert op.op == "knot", f"a thread operation is one of {THREAD_OPS}"
            out.ops.append((now, "knot", None, None, op.count))
            self.knots.setdefault(len(self.laid), []).append((now, op.count))

    def rewound(self, out: Walk) -> tuple[int, int]:
        """The last laid edge picked up (its knots beyond with it): the visit and exit it was laid from."""
        out.ops.extend((at, "knot", None, None, -k) for at, k in self.knots.pop(len(self.laid), []))
        i, p, _ = self.laid.pop()
        out.ops.append((i, "thread", p, None, -1))
        return i, p


def walk(truth: World, start: tuple[str, int], kit: Kit, actions: Sequence) -> Walk:
    """Replay ``actions`` on ``truth`` once and record the walk (:class:`Walk`); a run that leaves the scope is
    recorded with ``scope`` saying why."""
    out = Walk(scope=folding_scope(kit))
    sim, thread = Simulator(truth, start, kit), _Thread()
    out.seen.append(hash(str(sim.robot().sense())))
    out.degree.append(truth.degree(start[0]))
    out.events.append((0, 0, _observed(sim)))
    now = 0
    for action in actions:
        laid = len(sim.layer.thread.laid)
        out.seen.append(hash(str(act(sim, action))))
        if isinstance(action, int) or action == REWIND:
            out.degree.append(truth.degree(sim.state[0]))
            new = len(out.degree) - 1
            back = len(sim.layer.thread.laid) < laid
            if back and action != REWIND and ("thread", 0) in _observed(sim)[1]:
                out.scope = "a move went back along an edge the thread lay on twice, without a rewind operation"
                return out
            if back:  # a rewind, or a move along the last laid edge that leaves no thread there: one in any world
                i, p = thread.rewound(out)
                out.unions.append((new, 0, i, p))  # back along the laid edge: to the visit it was laid from
            if action != REWIND:
                out.edges.append((now, action % out.degree[now], new, 0))
                if len(sim.layer.thread.laid) > laid:  # laid along the edge crossed
                    thread.laid.append((now, action % out.degree[now], new))
                    out.ops.append((now, "thread", action % out.degree[now], None, 1))
            now = new
        elif isinstance(action, MarkerOp):
            out.ops.append((now, action.kind, action.exit, action.direction,
                            -action.count if action.pick_up else action.count))
        else:
            assert isinstance(action, ThreadOp), "an action is a motion, an operation or a rewind"
            thread.op(out, now, action)
        out.events.append((len(out.ops), now, _observed(sim)))
    out.left = sim.world.with_start(truth.start)
    return out


@dataclass(frozen=True)
class Found:
    """A world that gives every observation and is not isomorphic to the map, and how it was found."""

    world: World
    how: str  # "unvisited exit", "finer world" or "quotient"


def _leaves(w: Walk) -> Iterator[Folding]:
    """The finest foldings of the walk that show every sensing, one per way of placing the markers the robot saw
    (:func:`~topomark.reference.oracle.folded_marks.scan`'s deficits); raises OverflowError past
    :data:`MAX_BRANCHES` branches."""
    base = Folding(w.degree)
    for i, ri, j, rj in w.edges:
        if not base.join(i, ri, j, rj):
            return  # the walk itself is no rotation system: cannot happen for a replayed run
    for i, ri, j, rj in w.unions:
        if not base.union(i, ri, j, rj):
            return
    first = scan(base, w.ops, w.events)
    stack: list[tuple[Folding, object]] = [] if first is PRUNED else [(base, first)]
    branches = 0
    while stack:
        f, status = stack.pop()
        if status is None:
            yield f
            continue
        assert isinstance(status, Deficit)
        if status.forced:  # every world giving the observations takes these: no branch
            g = f.copy()
            if all(take(g, option) for option in status.forced) and (found := scan(g, w.ops, w.events)) is not PRUNED:
                stack.append((g, found))
            continue
        children = []
        for option in status.options:
            g = f.copy()
            if take(g, option) and (found := scan(g, w.ops, w.events)) is not PRUNED:
                children.append((g, found))
        branches += max(0, len(children) - 1)
        if branches > MAX_BRANCHES:
            raise OverflowError(f"more than {MAX_BRANCHES} branches")
        stack.extend(children)


def _left(world: World, at: tuple[str, int], kit: Kit, actions: Sequence) -> World:
    """``world`` with the markers ``actions`` leave in it, from ``at``."""
    sim = Simulator(world, at, kit)
    for action in actions:
        act(sim, action)
    return sim.world.with_start(world.start)


def _differs(candidate: World, at: tuple[str, int], kit: Kit, actions: Sequence, map_: World) -> bool:
    """Whether ``candidate``, with the markers the actions leave in it, is not extended-isomorphic to ``map_``."""
    if candidate.n != map_.n:
        return True
    return not find_isomorphism(_left(candidate, at, kit, actions), map_, markers=True).isomorphic


def decide(truth: World, start: tuple[str, int], kit: Kit, actions: Sequence, agrees=None) -> Found | None:
    """A witness that the observations of ``actions`` on ``truth`` from ``start`` do not determine the map (``truth``
    with the markers the actions leave, which a map judged right is isomorphic to), or None when they do.
    ``agrees(candidate, at)`` confirms a candidate gives every observation (default: :func:`~topomark.reference.oracle.agreement.agrees` against ``truth``).

    Raises ValueError when the run is outside the exact decision (:func:`walk`'s scope) and OverflowError past
    :data:`MAX_BRANCHES`.
    """
    w = walk(truth, start, kit, actions)
    if w.scope:
        raise ValueError(w.scope)
    map_ = w.left
    assert map_ is not None, "a walk in scope is replayed to its end"
    if agrees is None:
        def agrees(candidate: World, at: tuple[str, int]) -> bool:  # the hashes first, each signature to confirm
            return matches(candidate, at, kit, actions, w.seen)[0] is True and bool(
                replayed(candidate, at, truth, start, kit, actions)[0])
    for leaf in _leaves(w):
        for fill in (1, 2):  # a dangling exit completed by a new leaf, or by a path of two
            built = leaf.world(fill)
            if built is None:
                break  # a loop or a multiple edge: no simple world along this branch, nor any coarser one
            candidate, at, dangling = built
            if not agrees(candidate, at):
                break  # the marker seen where it is not, or not seen where it is: coarser worlds too (docstring)
            if _differs(candidate, at, kit, actions, map_):
                return Found(candidate, "unvisited exit" if dangling else "finer world")
            if not dangling:
                found = _quotient(candidate, at, kit, actions, map_, agrees)
                if found is not None:
                    return found
                break
    return None


def _quotient(world: World, at: tuple[str, int], kit: Kit, actions: Sequence, map_: World,
              agrees) -> Found | None:
    """A quotient of the complete finest ``world`` by a covering that gives every observation (docstring, 3)."""
    names = list(world.rotation)
    index = {v: k for k, v in enumerate(names)}
    base = Folding([world.degree(v) for v in names])
    for v in names:
        for i, x in enumerate(world.rotation[v]):
            base.join(index[v], i, index[x], world.index(x, v))
    s, facing = index[at[0]], at[1]
    for other in range(len(names)):
        if other == s or base.degree[other] != base.degree[s]:
            continue
        for r in range(base.degree[s]):
            g = base.copy()
            if not g.union(s, facing, other, r):
                continue
            built = g.world(1, (s, facing))
            if built is None or built[2]:
                continue
            candidate, cat, _ = built
            if agrees(candidate, cat) and _differs(candidate, cat, kit, actions, map_):
                return Found(candidate, "quotient")
    return None
