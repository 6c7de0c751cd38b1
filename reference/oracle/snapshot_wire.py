"""(S, U) of §3.1.3 on the wire: the ``snapshot`` message of ``topomark/protocol@1`` and ``@2``.

``S`` is ``{"exits": [[dart-or-null, ...] per vertex], "marks": [...]}`` and
``U`` a list of map darts ``[vertex, exit]`` (``spec/protocol.md``).  A mark is

* a vertex mark ``{"vertex": v, "head": exit or null}`` (``head`` omitted
  means null, an undirected marker; ``@2`` also takes an optional
  ``"count"``, default 1), or
* in ``@2`` only, an edge mark ``{"vertex": v, "exit": i, "count": k, "end":
  "H"|"T"|null}`` — ``count`` defaults to 1, ``end`` (the end of a
  directional edge marker at ``v``: ``H`` its head) to null.  An edge mark on
  an explored edge holds at both of its darts (the far end seeing the other
  end of the marker), so listing it once is enough; listing both is fine if
  they agree;
* in ``@2`` only, a thread mark (§6.3) ``{"vertex": v, "thread": {"tied":
  bool, "head": exit or null, "edges": [[exit, times], ...], "end": bool,
  "knots": k}}`` — what of the thread lies at ``v``, in ``v``'s exits
  (:class:`~topomark.spec.thread.ThreadMark`); every field but ``tied``
  optional, at most one per vertex.

A malformed snapshot raises :class:`MalformedSnapshot` (a
:class:`~topomark.spec.errors.CheckFailure`: the program's fault, exit 1)
naming the field, never anything else.

A vertex listed twice in ``S.marks`` (vertex marks) is not malformed but
wrong: a world vertex's markers are one entry with a count
(``spec/world.py``), so no world vertex matches it and I-1 (§3.4: S is
isomorphic to the explored subgraph, markers included) fails; it raises a
:class:`~topomark.spec.errors.CheckFailure` whose violation is ``I-1``.
"""

from __future__ import annotations

import json
from typing import Any

from topomark.spec.errors import CheckFailure, Violation, clip
from topomark.spec.kit import MAX_COUNT
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature
from topomark.spec.thread import ThreadMark
from topomark.spec.world import DartMark


__all__ = ["snapshot_to_map", "map_to_snapshot", "MalformedSnapshot"]



class MalformedSnapshot(CheckFailure):
    """A snapshot not in the protocol's form; its text names the field (``S.marks[2] must be ...``)."""

    def __init__(self, message: str):
        super().__init__(Violation("snapshot", "the snapshot message", "(S, U) in the form of spec/protocol.md",
                                   "a malformed field", message))
        self.args = (self.violation.detail,)


_FLIP = {"H": "T", "T": "H", None: None}


def _int(x: Any) -> bool:
    return isinstance(x, int) and not isinstance(x, bool)


def _dart(x: Any, what: str) -> tuple[int, int]:
    if not (isinstance(x, list) and len(x) == 2 and all(_int(k) for k in x)):
        raise MalformedSnapshot(f"{what} must be a map dart [vertex, exit], got {clip(json.dumps(x))}")
    return (x[0], x[1])


def _exits(S: PartialMap, exits: list) -> None:
    """The vertices and explored edges of ``S.exits``, checked symmetric."""
    for v, row in enumerate(exits):
        if not isinstance(row, list) or not row:
            raise MalformedSnapshot(f"S.exits[{v}] must be a non-empty list (one entry per exit)")
        S.add_vertex(len(row))
    for v, row in enumerate(exits):
        for i, x in enumerate(row):
            if x is None:
                continue
            w, j = _dart(x, f"S.exits[{v}][{i}]")
            if not (0 <= w < len(exits) and 0 <= j < len(exits[w])) or exits[w][j] != [v, i]:
                raise MalformedSnapshot(f"S: exit {i} of vertex {v} leads to {[w, j]}, "
                                        f"which does not lead back to {[v, i]}")
            if (v, i) < (w, j):
                S.add_edge((v, i), (w, j))


def snapshot_to_map(S_obj: dict[str, Any], U: list[Any], version: int = 1) -> PartialMap:
    """Rebuild S and U from a snapshot of protocol ``version``; a malformed one raises MalformedSnapshot, a
    vertex marked twice a CheckFailure for I-1 (the module docstring)."""
    try:
        return _rebuild(S_obj, U, version)
    except CheckFailure as exc:
        if isinstance(exc, MalformedSnapshot) or exc.violation.check != "internal check":
            raise
        raise MalformedSnapshot(f"S: {exc.violation.detail}") from None  # PartialMap's own (a loop, ...)


def _rebuild(S_obj: dict[str, Any], U: list[Any], version: int) -> PartialMap:
    exits = S_obj.get("exits")
    marks = S_obj.get("marks", [])
    if set(S_obj) - {"exits", "marks"} or not isinstance(exits, list) or not isinstance(marks, list):
        raise MalformedSnapshot("S must be {\"exits\": [...], \"marks\": [...]}")
    S = PartialMap()
    _exits(S, exits)
    darts: dict[tuple[int, int], tuple[int, str | None]] = {}
    marked: dict[int, int] = {}  # vertex -> the index in S.marks of its vertex mark
    for k, mark in enumerate(marks):
        if version >= 2 and isinstance(mark, dict) and "thread" in mark:
            _thread_mark(S, k, mark)
        elif version >= 2 and isinstance(mark, dict) and "exit" in mark:
            _edge_mark(S, k, mark, darts)
        else:
            _vertex_mark(S, k, mark, version, marked)
    for (v, i), (count, end) in sorted(darts.items()):
        S.mark_dart(v, DartMark(i, count, end))
    S.unexplored = [_dart(x, f"U[{k}]") for k, x in enumerate(U)]
    return S


def _count(mark: dict, k: int) -> int:
    count = mark.get("count", 1)
    if not (_int(count) and 1 <= count <= MAX_COUNT):
        raise MalformedSnapshot(f"S.marks[{k}]: count must be an integer 1..{MAX_COUNT}, "
                                f"got {clip(json.dumps(count))}")
    return count


def _vertex_mark(S: PartialMap, k: int, mark: Any, version: int, marked: dict[int, int]) -> None:
    keys = {"vertex", "head"} | ({"count"} if version >= 2 else set())
    if not (isinstance(mark, dict) and {"vertex"} <= set(mark) <= keys and _int(mark["vertex"])
            and (mark.get("head") is None or _int(mark["head"])) and 0 <= mark["vertex"] < S.n):
        form = "{\"vertex\": v, \"head\": exit or null}"
        if version >= 2:
            form += " or {\"vertex\": v, \"exit\": i, \"count\": k, \"end\": \"H\", \"T\" or null}"
        raise MalformedSnapshot(f"S.marks[{k}] must be {form} on a vertex of S, got {clip(json.dumps(mark))}")
    head = mark.get("head")
    if head is not None and not 0 <= head < S.degree(mark["vertex"]):
        raise MalformedSnapshot(f"S.marks[{k}]: head {head} is not an exit of vertex {mark['vertex']}")
    v = mark["vertex"]
    if v in marked:
        raise CheckFailure(Violation("I-1", f"map vertex {v}", "one vertex mark, holding all the markers there (a "
                                     "world vertex's markers are one entry with a count)",
                                     f"two: S.marks[{marked[v]}] and S.marks[{k}]"))
    marked[v] = k
    S.mark_vertex(v, _count(mark, k), head=head)


def _edge_mark(S: PartialMap, k: int, mark: dict, darts: dict) -> None:
    """An edge mark at its dart and, if that dart is explored, at the far dart (end seen from there)."""
    v: Any = mark.get("vertex")  # JSON values, checked next
    i: Any = mark.get("exit")
    end = mark.get("end")
    if not (set(mark) <= {"vertex", "exit", "count", "end"} and _int(v) and _int(i) and end in ("H", "T", None)
            and 0 <= v < S.n and 0 <= i < S.degree(v)):
        raise MalformedSnapshot(f"S.marks[{k}] must be an edge mark {{\"vertex\": v, \"exit\": i, \"count\": k, "
                                f"\"end\": \"H\", \"T\" or null}} on an exit of a vertex of S, got "
                                f"{clip(json.dumps(mark))}")
    count = _count(mark, k)
    places = [((v, i), (count, end))]
    far = S.arc((v, i))
    if far is not None:
        places.append((far, (count, end if far[0] == v else _FLIP[end])))  # a loop's ends are one vertex
    for dart, value in places:
        if darts.setdefault(dart, value) != value:
            raise MalformedSnapshot(f"S.marks[{k}]: dart {list(dart)} is marked twice, differently "
                                    f"({darts[dart]} and {value}, as (count, end))")


def _thread_mark(S: PartialMap, k: int, mark: dict) -> None:
    """A thread mark at a vertex of S: the thread as :class:`ThreadMark` says, in that vertex's exits."""
    v: Any = mark.get("vertex")  # JSON values, checked next
    t: Any = mark.get("thread")
    form = ("a thread mark {\"vertex\": v, \"thread\": {\"tied\": bool, \"head\": exit or null, \"edges\": "
            "[[exit, times], ...], \"end\": bool, \"knots\": k}}")
    ok = (set(mark) == {"vertex", "thread"} and _int(v) and 0 <= v < S.n and isinstance(t, dict)
          and set(t) <= {"tied", "head", "edges", "end", "knots"} and isinstance(t.get("tied"), bool))
    if ok:
        d, head, edges = S.degree(v), t.get("head"), t.get("edges", [])
        ok = ((head is None or (_int(head) and 0 <= head < d)) and isinstance(edges, list)
              and all(isinstance(e, list) and len(e) == 2 and _int(e[0]) and 0 <= e[0] < d and _int(e[1])
                      and 1 <= e[1] <= MAX_COUNT for e in edges) and len({e[0] for e in edges}) == len(edges)
              and isinstance(t.get("end", False), bool) and _int(t.get("knots", 0))
              and 0 <= t.get("knots", 0) <= MAX_COUNT and S.thread_mark(v) is None
              and (t["tied"] or edges or t.get("end", False) or t.get("knots", 0)))  # something lies there
    if not ok:
        raise MalformedSnapshot(f"S.marks[{k}] must be {form} on a vertex of S, its exits < its degree, once, "
                                f"showing something, got {clip(json.dumps(mark))}")
    tm = ThreadMark(t["tied"], head, tuple(sorted(tuple(e) for e in edges)), t.get("end", False), t.get("knots", 0))
    S.mark_as_sensed(v, Signature(S.degree(v), thread=tm), 0)


def map_to_snapshot(S: PartialMap, version: int = 1) -> dict[str, Any]:
    """The ``snapshot`` message for (S, U) in protocol ``version`` (edge marks need ``@2``)."""
    exits = [[None if (far := S.arc((v, i))) is None else list(far) for i in range(S.degree(v))]
             for v in S.vertices]
    marks: list[dict[str, Any]] = []
    for v in S.vertices:
        mark = S.vertex_mark(v)
        if mark:
            marks.append({"vertex": v, "head": mark.head, **({"count": mark.count} if version >= 2 else {})})
    if version >= 2:
        marks += [{"vertex": v, "exit": dm.exit, "count": dm.count, "end": dm.end}
                  for v in S.vertices for dm in S.dart_marks(v)]
        marks += [{"vertex": v, "thread": {"tied": t.tied, "head": t.head, "edges": [list(e) for e in t.edges],
                                           "end": t.end, "knots": t.knots}}
                  for v in S.vertices if (t := S.thread_mark(v)) is not None]
    return {"type": "snapshot", "S": {"exits": exits, "marks": marks}, "U": [list(d) for d in S.unexplored]}
