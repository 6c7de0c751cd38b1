"""Signatures: what the robot senses at a vertex (thesis §3.1.1, Figure 3.2; §6.1).

A signature is the pair of edge-related perception (the degree) and
marker-related perception, written ``[degree, V#-dir, otherInfo]``:

* ``A`` — no vertex marker; ``V`` — one undirected marker; ``V2`` — two;
* ``V-h`` — a directional marker pointing at the exit ``h`` places to the
  left of the entry edge (clockwise enumeration), i.e. ``(head - entry) mod deg``;
* ``otherInfo`` — ``A`` or, for edge markers (§6.1, Figure 6.1), one item per
  marked incident edge: ``E-p`` (undirected) or ``E-p-H`` / ``E-p-T``
  (directional: the head/tail of the marker points at this vertex), ``p`` the
  marked exit relative to the entry edge; ``E2-p`` for two markers;
* thread items (§6.3, :mod:`topomark.spec.thread`), after the edge part and
  only where the thread lies at this vertex: ``T`` — the thread is tied here,
  ``T-p`` tied here and laid out toward relative exit ``p`` (the direction of
  an l = ε thread, §6.3.1: "whether the thread is present at the vertex and
  the direction of the thread"); ``S-p`` — the thread lies along the edge at
  relative exit ``p`` (a "thread-marked" or "stringed" edge, §6.3.2, Algorithm 6.8 line 7),
  ``S2-p`` twice; ``F`` — the thread's free end lies here (§6.3.2); ``K`` —
  a knot is tied here, ``K3`` three (Figure 6.20).  In that order, edges by
  exit: e.g. ``[3,A,A,T-0,F]`` (an l = ε thread tied here, toward the
  entry edge) or ``[4,A,A,S-0,S-2,K2]``.

"The marks at v" are what :func:`signature_at` reads — ``vertex_mark(v)``,
``dart_marks(v)`` and, on anything that has them, ``thread_marks`` (a
mapping vertex ↦ :class:`~topomark.spec.thread.ThreadMark`) — so
isomorphism, the census and every check that compares marks derive them
from it.

Examples
--------
>>> str(Signature(3))
'[3,A,A]'
>>> str(Signature(4, vertex_count=1, vertex_direction=1))
'[4,V-1,A]'
>>> str(Signature(2, vertex_count=2))
'[2,V2,A]'
>>> str(Signature(3, edges=((1, 1, "H"),)))
'[3,A,E-1-H]'
>>> Signature.parse("[4,V-1,E-1-H,E-3-T]") == Signature(4, 1, 1, ((1, 1, "H"), (3, 1, "T")))
True
>>> str(Signature(3, thread=ThreadMark(tied=True, head=0, end=True)))
'[3,A,A,T-0,F]'
>>> Signature.parse("[4,A,E-1,S-0,S2-2,K3]").thread
ThreadMark(tied=False, head=None, edges=((0, 1), (2, 2)), end=False, knots=3)
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Callable, Iterable, Protocol, Sequence

from topomark.spec.errors import InvalidInput, Violation, clip
from topomark.spec.thread import ThreadMark, shifted
from topomark.spec.world import MAX_DEGREE, DartMark, VertexMark

__all__ = ["Signature", "signature_at", "depends_on_entry", "KeptSignatures", "reads_as", "back_link_table", "Marked",
           "Embedded", "ThreadMark"]  # ThreadMark: the thread part of a signature, for explorers


class Marked(Protocol):
    """Anything with degrees and marks: a :class:`World` or a partial map."""

    def degree(self, v: Any) -> int: ...

    def vertex_mark(self, v: Any) -> VertexMark | None: ...

    def dart_marks(self, v: Any) -> tuple[DartMark, ...]: ...


class Embedded(Marked, Protocol):
    """A marked embedded graph with its darts: a complete :class:`World` or a (partial) map; ``arc`` is the
    dart at the other end of a dart's edge (None where a map has not joined it)."""

    @property
    def vertices(self) -> Sequence[Any]: ...

    def arc(self, dart: Any) -> Any: ...


@dataclass(frozen=True, order=True)
class Signature:
    """An immutable signature; ``edges`` holds (relative exit, count, "H"/"T"/None), sorted."""

    degree: int
    vertex_count: int = 0
    vertex_direction: int | None = None
    edges: tuple[tuple[int, int, str | None], ...] = ()
    thread: ThreadMark | None = None  # relative exits; None where no thread lies

    def __str__(self) -> str:
        if self.vertex_count == 0:
            vpart = "A"
        else:
            vpart = "V" + (str(self.vertex_count) if self.vertex_count > 1 else "")
            if self.vertex_direction is not None:
                vpart += f"-{self.vertex_direction}"
        if not self.edges:
            epart = "A"
        else:
            items = []
            for pos, count, end in self.edges:
                item = "E" + (str(count) if count > 1 else "") + f"-{pos}"
                items.append(item + (f"-{end}" if end else ""))
            epart = ",".join(items)
        if self.thread is not None:
            epart += "".join("," + item for item in _thread_items(self.thread))
        return f"[{self.degree},{vpart},{epart}]"

    __repr__ = __str__

    @property
    def marked(self) -> bool:
        """True if any marker is sensed here."""
        return self.vertex_count > 0 or bool(self.edges) or self.thread is not None

    _V = re.compile(r"V([0-9]*)(?:-([0-9]+))?")
    _E = re.compile(r"E([0-9]*)-([0-9]+)(?:-([HT]))?")

    @classmethod
    def parse(cls, text: str) -> "Signature":
        """Read thesis notation back; raises :class:`InvalidInput` on anything else.

        Only ASCII digits are numbers (``"²".isdigit()`` is true, but it is no
        degree).  The degree is at most :data:`~topomark.spec.world.MAX_DEGREE`
        (no world has a larger one) and every number at most 18 digits, both
        checked before anything is built, so parsing costs time and memory in
        proportion to the length of ``text``, never to the values it names.
        """
        if not isinstance(text, str):
            raise InvalidInput(f"a signature must be a string, got {type(text).__name__}")
        body = text.strip()
        if not (body.startswith("[") and body.endswith("]")):
            raise InvalidInput(f"signature {_shown(text)} is not of the form [degree,V...,...]")
        parts = [p.strip() for p in body[1:-1].split(",")]
        if len(parts) < 3 or not _DIGITS.fullmatch(parts[0]):
            raise InvalidInput(f"signature {_shown(text)} is not of the form [degree,V...,...]")
        degree = _number(parts[0], "degree", text)
        if not 1 <= degree <= MAX_DEGREE:
            raise InvalidInput(f"signature {_shown(text)}: degree must be 1..{MAX_DEGREE} (MAX_DEGREE: no world "
                               "has a larger one)")
        count, direction = 0, None
        if parts[1] != "A":
            mv = cls._V.fullmatch(parts[1])
            if not mv:
                raise InvalidInput(f"signature {_shown(text)}: cannot read vertex part {_shown(parts[1])}")
            count = _number(mv.group(1) or "1", "marker count", text)
            direction = _number(mv.group(2), "direction", text) if mv.group(2) is not None else None
        edges = []
        items = parts[2:]
        thread_from = next((k for k, item in enumerate(items) if k > 0 and item[:1] in "TSFK"), len(items))
        thread = _parse_thread(items[thread_from:], text) if thread_from < len(items) else None
        items = items[:thread_from]
        if items != ["A"]:
            for item in items:
                me = cls._E.fullmatch(item)
                if not me:
                    raise InvalidInput(f"signature {_shown(text)}: cannot read edge part {_shown(item)}")
                edges.append((_number(me.group(2), "edge exit", text), _number(me.group(1) or "1", "marker count",
                                                                             text), me.group(3)))
        if direction is not None and direction >= degree:
            raise InvalidInput(f"signature {_shown(text)}: direction V-{direction} needs an exit < degree {degree}")
        positions = [e[0] for e in edges]
        if any(p >= degree for p in positions) or len(set(positions)) != len(positions):
            raise InvalidInput(f"signature {_shown(text)}: edge markers need distinct exits < degree {degree}")
        if thread is not None and (any(x >= degree for x, _ in thread.edges)
                                   or (thread.head is not None and thread.head >= degree)):
            raise InvalidInput(f"signature {_shown(text)}: thread exits must be < degree {degree}")
        sig = cls(degree, count, direction, tuple(sorted(edges, key=lambda e: e[0])), thread)
        if str(sig) != body.replace(" ", ""):
            raise InvalidInput(f"signature {_shown(text)} is not in canonical thesis notation (expected {sig})")
        return sig


_DIGITS = re.compile(r"[0-9]+")
_MAX_DIGITS = 18  # as for every JSON integer (topomark.spec.jsontext.MAX_INT_DIGITS)


def _shown(text: str, limit: int = 60) -> str:
    """``repr(text)`` cut to ``limit`` characters: a hostile signature can be megabytes long."""
    return clip(text, limit, quote=True)


def _number(digits: str, what: str, text: str) -> int:
    """The value of an ASCII digit string of at most 18 digits (longer ones are refused, not converted)."""
    if len(digits) > _MAX_DIGITS:
        raise InvalidInput(f"signature {_shown(text)}: {what} of {len(digits)} digits is out of range "
                           f"(at most {_MAX_DIGITS})")
    return int(digits)


_T = re.compile(r"T(?:-([0-9]+))?")
_S = re.compile(r"S([0-9]*)-([0-9]+)")
_K = re.compile(r"K([0-9]*)")


def _thread_items(t: ThreadMark) -> list[str]:
    """A :class:`ThreadMark` (relative exits) in thesis-style notation: ``T[-p]``, ``S[k]-p``, ``F``, ``K[k]``."""
    items = []
    if t.tied:
        items.append("T" if t.head is None else f"T-{t.head}")
    items += [f"S{k if k > 1 else ''}-{x}" for x, k in t.edges]
    if t.end:
        items.append("F")
    if t.knots:
        items.append("K" + (str(t.knots) if t.knots > 1 else ""))
    return items


def _parse_thread(items: list[str], text: str) -> ThreadMark:
    tied, head, edges, end, knots = False, None, [], False, 0
    for item in items:
        mt, ms, mk = _T.fullmatch(item), _S.fullmatch(item), _K.fullmatch(item)
        if mt:
            tied, head = True, (_number(mt.group(1), "thread direction", text) if mt.group(1) else None)
        elif ms:
            edges.append((_number(ms.group(2), "thread edge exit", text),
                          _number(ms.group(1) or "1", "thread count", text)))
        elif item == "F":
            end = True
        elif mk:
            knots = _number(mk.group(1) or "1", "knot count", text)
        else:
            raise InvalidInput(f"signature {_shown(text)}: cannot read thread part {_shown(item)}")
    if len({x for x, _ in edges}) != len(edges):
        raise InvalidInput(f"signature {_shown(text)}: thread edges need distinct exits")
    return ThreadMark(tied, head, tuple(sorted(edges)), end, knots)


def signature_at(g: Marked, v: Any, entry: int) -> Signature:
    """The signature sensed at ``v`` by a robot whose entry edge is exit ``entry`` (§3.1.1).

    A directional marker pointing at exit ``h`` reads ``V-((h - entry) mod deg)``;
    an edge marker on exit ``x`` reads ``E-((x - entry) mod deg)``.
    """
    d = g.degree(v)
    mark = g.vertex_mark(v)
    marks = g.dart_marks(v)
    thread_marks = getattr(g, "thread_marks", None)  # worlds and maps without a thread need not have them
    tm = thread_marks.get(v) if thread_marks else None
    if mark is None and not marks and tm is None:
        return _plain(d)
    count, direction = 0, None
    if mark is not None:
        count = mark.count
        if mark.head is not None:
            direction = (mark.head - entry) % d
    edges = tuple(sorted(((dm.exit - entry) % d, dm.count, dm.end) for dm in marks))
    return Signature(d, count, direction, edges, None if tm is None else shifted(tm, entry, d))


def depends_on_entry(g: Marked, v: Any) -> bool:
    """Whether :func:`signature_at` may differ between entries of ``v``: only a directional
    vertex marker, an edge marker or a thread's direction or edges is read relative to the entry edge (§3.1.1)."""
    mark = g.vertex_mark(v)
    thread_marks = getattr(g, "thread_marks", None)
    tm = thread_marks.get(v) if thread_marks else None
    return ((mark is not None and mark.head is not None) or bool(g.dart_marks(v))
            or (tm is not None and (tm.head is not None or bool(tm.edges))))


class KeptSignatures:
    """:func:`signature_at` of one world or map, kept per vertex and entry until its owner forgets the vertex
    (:meth:`forget`: its marks or thread changed) — for a caller that asks the same places again and again."""

    __slots__ = ("_at",)

    def __init__(self) -> None:
        self._at: dict[Any, dict[int, Signature]] = {}  # v -> entry -> Signature

    def get(self, g: Marked, v: Any, entry: int) -> Signature:
        at = self._at.get(v)
        if at is None:
            at = self._at[v] = {}
        sig = at.get(entry)
        if sig is None:
            sig = at[entry] = signature_at(g, v, entry)
        return sig

    def forget(self, vertices: Iterable[Any] | None = None) -> None:
        """Drop what was kept at ``vertices`` (None: everywhere)."""
        if vertices is None:
            self._at.clear()
        else:
            for v in vertices:
                self._at.pop(v, None)


def reads_as(g: Marked, sig: Signature) -> Callable[[Any, int], bool]:
    """``reads(v, entry)``: whether a robot entering ``v`` by ``entry`` senses ``sig`` in ``g`` — asked of every
    unexplored dart; a vertex whose signature is the same from every entry (:func:`depends_on_entry`) is
    compared once."""
    same: dict[Any, bool] = {}

    def reads(v: Any, entry: int) -> bool:
        match = same.get(v)
        if match is None:
            match = g.degree(v) == sig.degree and signature_at(g, v, entry) == sig
            if not depends_on_entry(g, v):
                same[v] = match
        return match
    return reads


def back_link_table(g: Marked, v: Any, where: str) -> tuple[dict[Signature, int], Violation | None]:
    """What a robot entering ``v`` senses ↦ the entry it came by, and whether that is a function.

    ``v`` gives *explicit back-link information* (§3.2.2) exactly when its
    signatures from its d entries are d different ones; a lighthouse must
    (§3.3).  Returns the table and None, or the table and the violation named
    at ``where``.
    """
    table = {signature_at(g, v, e): e for e in range(g.degree(v))}
    if len(table) == g.degree(v):
        return table, None
    return table, Violation("lighthouse", where, f"{g.degree(v)} different signatures, one per entry", f"{len(table)}",
                            "the markers give no explicit back-link information at v0 (§3.2.2)")


_PLAIN: dict[int, Signature] = {}


def _plain(d: int) -> Signature:
    """The signature ``[d,A,A]`` of an unmarked vertex, shared (signatures are immutable)."""
    sig = _PLAIN.get(d)
    if sig is None:
        sig = _PLAIN[d] = Signature(d)
    return sig
