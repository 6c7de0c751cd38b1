"""The marks a folded walk shows: what each visit would sense if the walk's identifications were the world (§3.1.1,
§6.1).

A program's marker operations happen at visits of its walk (:mod:`~topomark.reference.oracle.walk_folding`): a
vertex marker dropped or picked up at a visit, an edge marker at one of its exits, ``count`` at a time, a
directional one pointing at an exit (§3.1.1, ``V-k``) or with its head or tail at that end (§6.1, ``E-p-H``).  A
:class:`~topomark.reference.oracle.folding.Folding` says which visits are one vertex and which exits one edge; the
marks at a place are then the sum of the operations at every visit of that place, as the marker layer stacks
homogeneous markers (``V#``, ``E#``, Figure 6.8).  :func:`scan` replays the operations on the folding's places in
time order and compares what each visit would sense with what the robot sensed there:

* while every visit so far senses exactly what the robot sensed, every place holds a count of at least zero (a
  pick-up is preceded by a visit that sensed what it takes), so identifying more visits — a coarser folding — only
  adds markers to a place: a visit that would sense **more** than the robot did, or a marker pointing another way,
  rules out every coarser folding too (the branch is cut);
* the first visit that would sense **less** is a *deficit*: any world giving the observations identifies that visit
  (or the edge at that exit) with a place now holding markers; :class:`Deficit` lists the ways (each place, with the
  rotation or the edge end the reading forces), so the caller can branch on them; a lack no place can mend cuts the
  branch, and a lack only one way can mend is *forced* — every world takes it, and the caller takes all those of
  one scan at once instead of one a scan.  Past it, counts stay at least
  zero until the next pick-up (only drops are added), so the scan goes on looking for an excess that cuts the
  branch until then;
* when no visit senses more or less, the folding shows every observation.

Decision (the thesis is silent: it has no oracle): a place's markers are a count and one direction, as the marker
layer holds them; an identification that would make one place point two ways while markers lie there is no world.

Examples
--------
>>> from topomark.reference.oracle.folding import Folding
>>> f = Folding([2, 2, 2, 2])  # a walk round a square and back to the start
>>> all(f.join(i, 1, i + 1, 0) for i in range(3))
True
>>> ops = [(0, "vertex", None, None, 1)]  # an undirected marker dropped at the start
>>> seen, unseen = ({"vertex": (1, None)}, {}), ({}, {})
>>> events = [(0, 0, unseen), (1, 0, seen), (1, 1, unseen), (1, 2, unseen), (1, 3, seen)]  # seen again
>>> found = scan(f, ops, events)
>>> found.event, found.exit, found.options  # the fourth visit is the start's vertex, at some rotation
(4, None, [('union', 3, 0, 0, 0), ('union', 3, 0, 0, 1)])
>>> f.union(3, 0, 0, 0) and scan(f, ops, events) is None
True
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from topomark.reference.oracle.folding import Folding

__all__ = ["VERTEX_KINDS", "EDGE_KINDS", "Op", "Observed", "Event", "Option", "Deficit", "PRUNED", "scan", "take"]

FLIP = {"H": "T", "T": "H", None: None}

VERTEX_KINDS = ("vertex", "tied", "end", "knot")
"""Marks of a place: vertex markers (§3.1.1), and of the thread (§6.3) where it is tied (with the exit it is laid
out toward), its free end lying there, the knots tied there."""
EDGE_KINDS = ("edge", "thread")
"""Marks of an edge: edge markers (§6.1) and the thread laid along it (§6.3.2: a "stringed" edge, with how often)."""

Op = tuple[int, str, int | None, int | str | None, int]
"""An operation at a visit: (visit, kind — one of :data:`VERTEX_KINDS` or :data:`EDGE_KINDS` —, exit or None,
direction, signed count)."""
Observed = tuple[dict[str, tuple[int, int | None]], dict[tuple[str, int], tuple[int, str | None]]]
"""What a visit sensed, relative to its entry: each vertex kind's (count, head) and each marked exit's (count, end)
by kind."""
Event = tuple[int, int, Observed]
"""A sensing: (operations done before it, visit, what was sensed)."""

PRUNED = False
""":func:`scan`'s answer when no coarser folding gives the observations."""


Option = tuple[str, int, int, int, int]
"""One way to give a visit the markers it lacks: ``("union", a, ra, b, rb)`` — exit ``ra`` of visit ``a`` is exit
``rb`` of node ``b`` — or ``("join", a, ra, b, rb)`` — the edge at exit ``ra`` of ``a`` leads to exit ``rb`` of
``b`` (:class:`~topomark.reference.oracle.folding.Folding`)."""


@dataclass(frozen=True)
class Deficit:
    """The first visit (``event``) that would sense fewer markers than the robot did — at its vertex (``exit`` None)
    or on the edge at ``exit`` — with the ways to give them to it (``options``: one of them holds in every world that
    gives the observations), and ``forced``: the options every such world takes, each the only way to mend a
    later visit's lack where nothing can have been picked up before it."""

    event: int
    exit: int | None
    options: list[Option]
    forced: list[Option]


def scan(f: Folding, ops: Sequence[Op], events: Sequence[Event]) -> Deficit | bool | None:
    """Compare what ``f``'s places would show at each sensing with what was sensed (module docstring): None when
    every sensing agrees, :data:`PRUNED` when a sensing would show more (or another direction) or lacks marks no
    place can give, else the first :class:`Deficit`."""
    deg = f.degree
    roots = [f.find(a) for a in range(len(deg))]
    vmarks: dict[int, dict[str, tuple[int, int | None]]] = {}  # root -> kind -> (count, head in the root's exits)
    dmarks: dict[int, dict[tuple[str, int], tuple[int, str | None]]] = {}  # root -> (kind, its exit) -> (count, end)
    done, first = 0, None
    forced: list[Option] = []
    for number, (before, j, (vertex, darts)) in enumerate(events):
        while done < before:
            if not _apply(ops[done], f, roots, vmarks, dmarks):
                return PRUNED if first is None else first
            if ops[done][4] < 0 and first is not None:
                return first  # a removal past a deficit: counts may be short there, an excess proves nothing
            done += 1
        root, s = roots[j]
        d = deg[root]
        lacks: list[tuple[int | None, list[Option]]] = []
        here = vmarks.get(root, {})
        for kind, (c, h) in here.items():
            oc, oh = vertex.get(kind, (0, None))
            if c > oc or (c > 0 and h is not None and oh is not None and (h - s) % d != oh):
                return PRUNED
        for kind, (oc, oh) in vertex.items():
            if here.get(kind, (0, None))[0] < oc and (first is None or len(vmarks) <= 2):
                lacks.append((None, [o for r, marks in vmarks.items() if r != root and marks.get(kind, (0,))[0] > 0
                                     for o in _vertex_options(f, j, oh, r, marks[kind][1])]))
        ends = dmarks.get(root)
        if ends or darts:
            ends = ends or {}
            sensed = {(kind, (p + s) % d): mark for (kind, p), mark in darts.items()}
            for key, (c, e) in ends.items():
                if c > 0 and (c > sensed.get(key, (0, None))[0] or e != sensed[key][1]):
                    return PRUNED
            if first is None or len(dmarks) <= 2:
                for (kind, x), (oc, oe) in sensed.items():
                    if ends.get((kind, x), (0, None))[0] < oc:
                        far = _far(f, roots, root, x)
                        mine, p = {(root, x), far}, (x - s) % d
                        lacks.append((p, [o for r, marks in dmarks.items() for (k, y), (n, end) in marks.items()
                                          if k == kind and n > 0 and (r, y) not in mine
                                          for o in _edge_options(f, j, p, oe, r, y, end)]))
        for exit_, options in lacks:
            if not options:
                return PRUNED  # no place holds the marks the visit lacks, in any coarser folding
            if first is None:
                first = Deficit(number, exit_, options, forced)
            if len(options) == 1:
                forced.append(options[0])
    return first


def _vertex_options(f: Folding, j: int, head: int | None, root: int, how: int | None) -> list[Option]:
    """Visit ``j`` is the vertex ``root``: with the head it read at ``root``'s head, or at every rotation."""
    if f.degree[root] != f.degree[j]:
        return []
    if head is not None and how is not None:
        return [("union", j, head, root, how)]
    return [("union", j, 0, root, r) for r in range(f.degree[j])]


def _edge_options(f: Folding, j: int, p: int, end: str | None, root: int, x: int, how: str | None) -> list[Option]:
    """The edge at exit ``p`` of visit ``j`` is the one at exit ``x`` of ``root``: the same dart, or its far end
    while no visit crossed it — as the ends read (``end`` at ``j``, ``how`` at ``root``) allow."""
    out: list[Option] = []
    if how == end and f.degree[root] == f.degree[j]:
        out.append(("union", j, p, root, x))
    if FLIP[how] == end and f.edges[root].get(x) is None:
        out.append(("join", j, p, root, x))
    return out


def take(f: Folding, option: Option) -> bool:
    """Do ``option`` to ``f``; False on a conflict."""
    kind, a, ra, b, rb = option
    return f.union(a, ra, b, rb) if kind == "union" else f.join(a, ra, b, rb)


def _far(f: Folding, roots: list[tuple[int, int]], root: int, x: int) -> tuple[int, int] | None:
    """The dart at the other end of exit ``x`` of ``root``, in its root's exits, or None while no visit crossed it."""
    there = f.edges[root].get(x)
    if there is None:
        return None
    root2, s2 = roots[there[0]]
    return root2, (there[1] + s2) % f.degree[root2]


def _apply(op: Op, f: Folding, roots: list[tuple[int, int]], vmarks: dict, dmarks: dict) -> bool:
    """Add ``op`` to its place; False when it would make the place point two ways while marks lie there."""
    visit, kind, exit_, direction, count = op
    root, s = roots[visit]
    d = f.degree[root]
    if kind in VERTEX_KINDS:
        at = vmarks.setdefault(root, {})
        c, h = at.get(kind, (0, None))
        if count > 0 and isinstance(direction, int):
            head = (direction + s) % d
            if c > 0 and h is not None and h != head:
                return False
            h = head
        c += count
        at[kind] = (c, h if c > 0 else None)
        return True
    assert exit_ is not None and kind in EDGE_KINDS, "an edge mark is at an exit (§6.1, §6.3.2)"
    x = (exit_ + s) % d
    c, e = dmarks.get(root, {}).get((kind, x), (0, None))
    if count > 0:
        if c > 0 and e != direction:
            return False
        e = direction
    c += count
    dmarks.setdefault(root, {})[kind, x] = (c, e if c > 0 else None)
    far = _far(f, roots, root, x)
    if far is not None:
        dmarks.setdefault(far[0], {})[kind, far[1]] = (c, FLIP[e] if c > 0 else None)
    return True
