"""Signatures: what the robot senses at a vertex (thesis §3.1.1, Figure 3.2; §6.1).

A signature is the pair of edge-related perception (the degree) and
marker-related perception, written ``[degree, V#-dir, otherInfo]``:

* ``A`` — no vertex marker; ``V`` — one undirected marker; ``V2`` — two;
* ``V-h`` — a directional marker pointing at the exit ``h`` places to the
  left of the entry edge (clockwise enumeration), i.e. ``(head - entry) mod deg``;
* ``otherInfo`` — ``A`` or, for edge markers (§6.1, Figure 6.1), one item per
  marked incident edge: ``E-p`` (undirected) or ``E-p-H`` / ``E-p-T``
  (directional: the head/tail of the marker points at this vertex), ``p`` the
  marked exit relative to the entry edge; ``E2-p`` for two markers.

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
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Protocol

from .errors import InvalidInput, Violation
from .world import MAX_DEGREE, DartMark, VertexMark

__all__ = ["Signature", "signature_at", "depends_on_entry", "back_link_table", "Marked"]


class Marked(Protocol):
    """Anything with degrees and marks: a :class:`World` or a partial map."""

    def degree(self, v) -> int: ...

    def vertex_mark(self, v) -> VertexMark | None: ...

    def dart_marks(self, v) -> tuple[DartMark, ...]: ...


@dataclass(frozen=True, order=True)
class Signature:
    """An immutable signature; ``edges`` holds (relative exit, count, "H"/"T"/None), sorted."""

    degree: int
    vertex_count: int = 0
    vertex_direction: int | None = None
    edges: tuple[tuple[int, int, str | None], ...] = ()

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
        return f"[{self.degree},{vpart},{epart}]"

    __repr__ = __str__

    @property
    def marked(self) -> bool:
        """True if any marker is sensed here."""
        return self.vertex_count > 0 or bool(self.edges)

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
        if parts[2:] != ["A"]:
            for item in parts[2:]:
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
        sig = cls(degree, count, direction, tuple(sorted(edges, key=lambda e: e[0])))
        if str(sig) != body.replace(" ", ""):
            raise InvalidInput(f"signature {_shown(text)} is not in canonical thesis notation (expected {sig})")
        return sig


_DIGITS = re.compile(r"[0-9]+")
_MAX_DIGITS = 18  # as for every JSON integer (topomark.spec.jsontext.MAX_INT_DIGITS)


def _shown(text: str, limit: int = 60) -> str:
    """``repr(text)`` cut to ``limit`` characters: a hostile signature can be megabytes long."""
    return repr(text) if len(text) <= limit else repr(text[:limit]) + f"... ({len(text):,} characters)"


def _number(digits: str, what: str, text: str) -> int:
    """The value of an ASCII digit string of at most 18 digits (longer ones are refused, not converted)."""
    if len(digits) > _MAX_DIGITS:
        raise InvalidInput(f"signature {_shown(text)}: {what} of {len(digits)} digits is out of range "
                           f"(at most {_MAX_DIGITS})")
    return int(digits)


def signature_at(g: Marked, v, entry: int) -> Signature:
    """The signature sensed at ``v`` by a robot whose entry edge is exit ``entry`` (§3.1.1).

    A directional marker pointing at exit ``h`` reads ``V-((h - entry) mod deg)``;
    an edge marker on exit ``x`` reads ``E-((x - entry) mod deg)``.
    """
    d = g.degree(v)
    mark = g.vertex_mark(v)
    marks = g.dart_marks(v)
    if mark is None and not marks:
        return _plain(d)
    count, direction = 0, None
    if mark is not None:
        count = mark.count
        if mark.head is not None:
            direction = (mark.head - entry) % d
    edges = tuple(sorted(((dm.exit - entry) % d, dm.count, dm.end) for dm in marks))
    return Signature(d, count, direction, edges)


def depends_on_entry(g: Marked, v) -> bool:
    """Whether :func:`signature_at` may differ between entries of ``v``: only a directional
    vertex marker or an edge marker is read relative to the entry edge (§3.1.1)."""
    mark = g.vertex_mark(v)
    return (mark is not None and mark.head is not None) or bool(g.dart_marks(v))


def back_link_table(g: Marked, v, where: str) -> tuple[dict[Signature, int], Violation | None]:
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
