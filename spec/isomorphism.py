"""Extended isomorphism of embedded graphs (thesis §3.1.3, following Dudek et al. [26]).

Map S and world G are *extended-isomorphic* iff there is a graph isomorphism
``f`` and, for every vertex ``v``, a relabelling of its exits that keeps the
same (clockwise) enumeration but may start from a different reference edge:
``index(f(e), f(v)) = (index(e, v) + r_v) mod deg(v)``.  Mirror images are not
isomorphic: the enumeration rule is fixed.

A :class:`Witness` holds ``f`` and the rotation offsets ``r``.  Because the
graphs are connected, an isomorphism is fixed by the image of a single dart;
:func:`anchored` propagates that choice in O(n + m) and explains the first
mismatch in words.  :func:`find_isomorphism` tries every admissible anchor.
:func:`verify_witness` checks a witness against the definition directly and
shares no code with the search.  An independent implementation on networkx
lives in :mod:`topomark.spec.dartgraph`.

With ``markers=True`` the isomorphism must also preserve markers: a marked
vertex maps to a vertex with the same count; a directional marker's head dart
maps to the head dart; a marked edge maps to a marked edge with the same count
and head.

Examples
--------
>>> from topomark.spec.world import World
>>> a = World({"x": ["y", "z"], "y": ["z", "x"], "z": ["x", "y"]})
>>> b = World({"1": ["3", "2"], "2": ["1", "3"], "3": ["2", "1"]})
>>> r = find_isomorphism(a, b)
>>> r.isomorphic, verify_witness(a, b, r.witness) is None
(True, True)
"""

from __future__ import annotations

from collections import Counter, deque
from dataclasses import dataclass
from typing import Any, Hashable

from topomark.spec.errors import Violation, clip
from topomark.spec.signature import Embedded, Marked, signature_at

__all__ = ["Witness", "IsoResult", "anchored", "find_isomorphism", "verify_witness", "local_class", "marks_at",
           "describe_marks"]


@dataclass(frozen=True, repr=False)
class Witness:
    """An extended isomorphism: ``vertex_map[v] = f(v)``; exit i of v ↦ exit (i + offsets[v]) mod deg."""

    vertex_map: dict[Any, Any]
    offsets: dict[Any, int]

    def __repr__(self) -> str:
        """``Witness(4 vertices: '0'->'a' +1, '1'->'b' +0, ...)``: the first pairs of the map, in one short line."""
        pairs = ", ".join(f"{v!r}->{w!r} +{self.offsets.get(v, 0)}" for v, w in self.vertex_map.items())
        return f"Witness({len(self.vertex_map)} vertices: {clip(pairs, 400, note='')})"

    def image(self, g_a: Marked, dart: tuple[Any, int]) -> tuple[Any, int]:
        v, i = dart
        return (self.vertex_map[v], (i + self.offsets[v]) % g_a.degree(v))

    def to_json(self) -> dict[str, Any]:
        return {
            "vertex_map": {str(k): str(v) for k, v in self.vertex_map.items()},
            "offsets": {str(k): r for k, r in self.offsets.items()},
        }


@dataclass(frozen=True, repr=False)
class IsoResult:
    """A verdict with its certificate: a witness when isomorphic, else the first mismatch."""

    isomorphic: bool
    witness: Witness | None = None
    mismatch: Violation | None = None
    mapped: int = 0  # how many vertices the (best) attempt had matched

    def __repr__(self) -> str:
        """The verdict and its certificate in one short line."""
        if self.isomorphic:
            return f"IsoResult(isomorphic, {self.witness!r})"
        return f"IsoResult(not isomorphic, {self.mapped} vertices mapped, mismatch: {clip(str(self.mismatch), 500)})"

    def __bool__(self) -> bool:
        return self.isomorphic


def _mismatch(where: str, expected: str, found: str, detail: str = "") -> Violation:
    return Violation("extended isomorphism", where, expected, found, detail)


def marks_at(g: Marked, v: Any, r: int) -> tuple[Any, ...]:
    """The marks at ``v`` with exit indices shifted by ``r`` (for comparison across graphs).

    Derived from what a robot senses (:func:`~topomark.spec.signature.signature_at`): exit
    ``x`` shifted by ``r`` is exit ``x`` read from the entry ``-r``.
    """
    sig = signature_at(g, v, (-r) % g.degree(v))
    vpart = None if sig.vertex_count == 0 else (sig.vertex_count, sig.vertex_direction)
    return (vpart, sig.edges) if sig.thread is None else (vpart, sig.edges, sig.thread)


def describe_marks(marks: tuple[Any, ...]) -> str:
    vpart, dpart = marks[:2]
    parts = [] if len(marks) == 2 else [f"the thread ({marks[2]})"]
    if vpart is not None:
        parts.append(f"{vpart[0]} vertex marker(s)" + ("" if vpart[1] is None else f" pointing at exit {vpart[1]}"))
    for x, count, end in dpart:
        parts.append(f"{count} edge marker(s) on exit {x}" + ("" if end is None else f" ({end})"))
    return ", ".join(parts) or "no markers"


def _marks_mismatch(a: Marked, b: Marked, v: Any, fv: Any, rv: int) -> Violation | None:
    """The mismatch if the marks at ``v`` (exits shifted by ``rv``) differ from those at its image ``fv``."""
    ma, mb = marks_at(a, v, rv), marks_at(b, fv, 0)
    if ma == mb:
        return None
    return _mismatch(f"vertex {v!r} (image {fv!r})", describe_marks(ma), describe_marks(mb),
                     "markers are not preserved")


def _edge_mismatch(a: Marked, v: Any, i: int, w: Any, j: int, k: int, fv: Any, bw: Any, bj: int,
                   f: dict[Any, Any], r: dict[Any, int]) -> Violation:
    """Why the dart (v, i) to the matched vertex ``w`` does not land where ``f`` says: wrong vertex or index."""
    if f[w] != bw:
        return _mismatch(f"vertex {v!r} exit {i}",
                         f"the edge to {w!r}, i.e. to {f[w]!r} through exit {k} of {fv!r}",
                         f"exit {k} of {fv!r} leads to {bw!r}")
    return _mismatch(f"edge {v!r}-{w!r} at {w!r}",
                     f"exit {(j + r[w]) % a.degree(w)} of {bw!r} (from exit {j} of {w!r})",
                     f"exit {bj} of {bw!r}", "the edge's index at its far end is not preserved")


def _new_vertex_mismatch(a: Marked, b: Marked, v: Any, i: int, w: Any, bw: Any, inv: dict[Any, Any]) -> Violation:
    """Why the unmatched vertex ``w`` cannot map to ``bw``: already an image, or another degree."""
    if bw in inv:
        return _mismatch(f"vertex {v!r} exit {i}", f"a vertex not yet matched (it leads to {w!r})",
                         f"{bw!r}, already the image of {inv[bw]!r}", "two vertices would map to one")
    return _mismatch(f"vertex {v!r} exit {i}", f"a vertex of degree {a.degree(w)} (like {w!r})",
                     f"{bw!r} of degree {b.degree(bw)}")


def _not_bijective(a: Embedded, b: Embedded, f: dict[Any, Any]) -> Violation | None:
    """The mismatch if the propagated map ``f`` misses a vertex of ``b`` or of ``a``."""
    if len(f) != len(b.vertices):
        return _mismatch("the vertex sets", f"{len(b.vertices)} vertices reached from the anchor", f"{len(f)}")
    if len(f) != len(a.vertices):
        lost = next(v for v in a.vertices if v not in f)
        return _mismatch(f"vertex {lost!r}", "reachable from the anchor", "unreachable")
    return None


def anchored(a: Embedded, b: Embedded, a_dart: tuple[Any, int], b_dart: tuple[Any, int], markers: bool = True,
             partial: bool = False) -> IsoResult:
    """Extend ``a_dart ↦ b_dart`` to an extended isomorphism from ``a`` to ``b``.

    ``a`` and ``b`` are worlds or partial maps (anything with ``degree``,
    ``arc``, ``vertex_mark``, ``dart_marks`` and ``vertices``).  With
    ``partial=True`` unexplored darts of ``a`` are skipped and the result is an
    embedding of the explored part of ``a`` into ``b`` (an isomorphism onto
    the explored subgraph G_s of §3.4); otherwise it must be a bijection.
    Vertices are matched breadth-first from the anchor: a dart to a matched
    vertex must land on its image at the right index, a dart to a new vertex
    matches it if its image is new and of the same degree.  (The loop stays
    inline, on the checker's hot path; the helpers only explain a mismatch.)
    """
    v0, i0 = a_dart
    w0, j0 = b_dart
    if a.degree(v0) != b.degree(w0):
        return IsoResult(False, mismatch=_mismatch(
            f"vertex {v0!r}", f"degree {a.degree(v0)} at its image {w0!r}", f"degree {b.degree(w0)}"))
    f = {v0: w0}
    inv = {w0: v0}
    r = {v0: (j0 - i0) % a.degree(v0)}
    todo = deque([v0])
    a_arc, b_arc, a_deg, b_deg = a.arc, b.arc, a.degree, b.degree
    a_thread, b_thread = getattr(a, "thread_marks", None) or {}, getattr(b, "thread_marks", None) or {}  # §6.3
    threads = bool(a_thread or b_thread)
    while todo:
        v = todo.popleft()
        fv, d, rv = f[v], a_deg(v), r[v]
        if markers and (a.vertex_mark(v) or a.dart_marks(v) or b.vertex_mark(fv) or b.dart_marks(fv)
                        or (threads and (v in a_thread or fv in b_thread))):
            violation = _marks_mismatch(a, b, v, fv, rv)
            if violation is not None:
                return IsoResult(False, mismatch=violation, mapped=len(f))
        for i in range(d):
            t = a_arc((v, i))
            if t is None:
                if partial:
                    continue
                return IsoResult(False, mismatch=_mismatch(f"vertex {v!r} exit {i}", "an explored edge",
                                                           "an unexplored dart"), mapped=len(f))
            w, j = t
            k = (i + rv) % d
            bw, bj = b_arc((fv, k))
            fw = f.get(w)
            if fw is not None:
                if fw != bw or (j + r[w]) % a_deg(w) != bj:
                    return IsoResult(False, mismatch=_edge_mismatch(a, v, i, w, j, k, fv, bw, bj, f, r), mapped=len(f))
                continue
            dw = a_deg(w)
            if bw in inv or dw != b_deg(bw):
                return IsoResult(False, mismatch=_new_vertex_mismatch(a, b, v, i, w, bw, inv), mapped=len(f))
            f[w], inv[bw], r[w] = bw, w, (bj - j) % dw
            todo.append(w)
    violation = None if partial else _not_bijective(a, b, f)
    if violation is not None:
        return IsoResult(False, mismatch=violation, mapped=len(f))
    return IsoResult(True, Witness(f, r), mapped=len(f))


def local_class(g: Marked, v: Any, markers: bool = True) -> tuple[Any, ...]:
    """What any extended isomorphism preserves at a single vertex (degree and marks, rotation-free).

    With ``markers=False`` only the degree: marks are then not part of the isomorphism.
    """
    if not markers:
        return (g.degree(v), None, ())
    sig = signature_at(g, v, 0)  # what the robot senses, with every exit index dropped
    vpart = None if sig.vertex_count == 0 else (sig.vertex_count, sig.vertex_direction is not None)
    return (sig.degree, vpart, tuple(sorted((count, end or "") for _, count, end in sig.edges)))


def _summary(g: Embedded, markers: bool) -> dict[str, Any]:
    degrees = Counter(g.degree(v) for v in g.vertices)
    out: dict[str, Any] = {
        "vertices": len(g.vertices),
        "edges": sum(degrees[d] * d for d in degrees) // 2,
        "degree histogram": dict(sorted(degrees.items())),
    }
    if markers:
        out["markers"] = sorted(Counter(_marker_words(c) for v in g.vertices
                                        if (c := local_class(g, v))[1] is not None or c[2]).items())
    return out


def _render_markers(summary: list[tuple[str, int]]) -> str:
    return "; ".join(f"{k}× {words}" for words, k in summary) or "no markers"


def _marker_words(cls: tuple[Any, ...]) -> str:
    """A vertex's local class in words, e.g. 'a degree-4 vertex with 1 directional vertex marker'."""
    degree, vpart, dpart = cls
    parts = []
    if vpart is not None:
        parts.append(f"{vpart[0]} {'directional' if vpart[1] else 'undirected'} vertex marker(s)")
    for count, end in dpart:
        parts.append(f"{count} {'directional' if end else 'undirected'} edge marker(s)" + (f" ({end} end)" if end else ""))
    return f"a degree-{degree} vertex with " + " and ".join(parts)


def find_isomorphism(a: Embedded, b: Embedded, markers: bool = True) -> IsoResult:
    """Decide extended isomorphism of two complete worlds by anchored propagation.

    Returns an :class:`IsoResult` carrying a witness, or the mismatch of the
    attempt that matched most vertices before failing.
    """
    sa, sb = _summary(a, markers), _summary(b, markers)
    for key in sa:
        if sa[key] != sb[key]:
            render = _render_markers if key == "markers" else str
            return IsoResult(False, mismatch=Violation("extended isomorphism", key, render(sa[key]), render(sb[key]),
                                                       "the worlds differ in an isomorphism invariant"))
    classes_b: dict[Hashable, list[Any]] = {}
    for w in b.vertices:
        classes_b.setdefault(local_class(b, w, markers), []).append(w)
    # Anchor at the vertex of A whose class is rarest in B; prefer a directional head dart.
    v = min(a.vertices, key=lambda x: len(classes_b.get(local_class(a, x, markers), ())))
    mark = a.vertex_mark(v) if markers else None
    head = mark.head if mark is not None else None
    i = 0 if head is None else head
    best: IsoResult | None = None
    for w in classes_b.get(local_class(a, v, markers), ()):
        bmark = b.vertex_mark(w) if head is not None else None
        bhead = bmark.head if bmark is not None else None
        for j in ([bhead] if bhead is not None else range(b.degree(w))):
            res = anchored(a, b, (v, i), (w, j), markers=markers)
            if res.isomorphic:
                return res
            if best is None or res.mapped > best.mapped:
                best = res
    if best is None:
        return IsoResult(False, mismatch=Violation("extended isomorphism", f"vertex {v!r}",
                                                   "a vertex of the same degree and markers", "none"))
    return best


def verify_witness(a: Embedded, b: Embedded, witness: Witness, markers: bool = True) -> Violation | None:
    """Check ``witness`` against the definition of extended isomorphism; None if it holds.

    Independent of the search: every dart of ``a`` must land where the witness says.
    """
    f, r = witness.vertex_map, witness.offsets
    if set(f) != set(a.vertices) or sorted(map(str, f.values())) != sorted(map(str, b.vertices)) \
            or len(set(f.values())) != len(f):
        return Violation("witness", "vertex map", "a bijection between the vertex sets", str(f))
    for v in a.vertices:
        d = a.degree(v)
        if b.degree(f[v]) != d:
            return Violation("witness", f"vertex {v!r}", f"degree {d}", f"degree {b.degree(f[v])}")
        for i in range(d):
            w, j = a.arc((v, i))
            expected = (f[w], (j + r[w]) % a.degree(w))
            found = b.arc((f[v], (i + r[v]) % d))
            if found != expected:
                return Violation("witness", f"dart ({v!r}, {i})", str(expected), str(found))
        if markers and marks_at(a, v, r[v]) != marks_at(b, f[v], 0):
            return Violation("witness", f"vertex {v!r}", describe_marks(marks_at(a, v, r[v])),
                             describe_marks(marks_at(b, f[v], 0)))
    return None
