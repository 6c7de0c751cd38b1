"""Indistinguishability of two marked worlds by robot experiments (thesis §3.2, §3.7, §6.1).

§3.2 calls two worlds (with markers and start states) *indistinguishable*
when every motion sequence ``M`` yields the same perception sequence ``P`` in
both (Figures 3.3, 3.4, 3.21, 6.1).  The robot of :mod:`topomark.spec.robot`
is a deterministic Mealy machine — state ``(vertex, entry)``, input the motion
``l`` in ``range(deg)``, output the signature of the vertex reached — so
indistinguishability is *bisimilarity* of the two machines from their starts.
We also demand equal signatures at the two starts: the robot senses where it
starts (§3.1.1), although that signature is not part of ``P``.

* :func:`distinguishing_sequence` searches the product of the two machines
  breadth-first from the start pair and returns the *shortest* distinguishing
  motion sequence, or None.
* :func:`bisimulation` returns the reachable product relation when the worlds
  are indistinguishable — a certificate that :func:`check_relation` verifies
  independently of the search.
* :func:`is_counterexample`: indistinguishable yet not extended-isomorphic
  with markers preserved (§3.1.3) — a witness that a marker class is not
  sufficient.

Examples
--------
>>> from topomark.spec.world import World, Start
>>> c3 = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, start=Start("a", "b"))
>>> c4 = World({"p": ["q", "s"], "q": ["r", "p"], "r": ["s", "q"], "s": ["p", "r"]}, start=Start("p", "q"))
>>> indistinguishable(c3, c4), is_counterexample(c3, c4)
(True, True)
>>> len(bisimulation(c3, c4))
24
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Iterable

from topomark.spec.errors import Violation, clip
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.robot import State, sense, step
from topomark.spec.signature import Signature
from topomark.spec.world import World

__all__ = [
    "Distinction",
    "Pair",
    "distinguishing_sequence",
    "bisimulation",
    "check_relation",
    "indistinguishable",
    "is_counterexample",
]

Pair = tuple[State, State]


@dataclass(frozen=True, repr=False)
class Distinction:
    """A motion sequence ``M`` after which the robot perceives different things in A and B.

    ``perceptions_a``/``perceptions_b`` are the perception sequences ``P`` of
    ``M`` (start vertex excluded, §3.1.1); they agree except at the last entry.
    When the two *start* signatures already differ, ``motions == ()`` and each
    perception tuple holds the one start signature instead.
    """

    motions: tuple[int, ...]
    perceptions_a: tuple[Signature, ...]
    perceptions_b: tuple[Signature, ...]

    def __repr__(self) -> str:
        """``Distinction(motions=(1, 0, 2), last perceptions [3,V,A] and [3,-,A])``: the sequence (cut when
        long) and the perceptions that differ."""
        motions = clip(repr(self.motions), 300, note="")
        a = clip(str(self.perceptions_a[-1]), 200) if self.perceptions_a else "-"
        b = clip(str(self.perceptions_b[-1]), 200) if self.perceptions_b else "-"
        return f"Distinction(motions={motions}, last perceptions {a} and {b})"


def _path(parent: dict[Pair, tuple[Pair, int] | None], pair: Pair) -> list[int]:
    """The motions leading from the start pair to ``pair`` in the BFS tree."""
    motions: list[int] = []
    while (step := parent[pair]) is not None:
        pair, motion = step
        motions.append(motion)
    motions.reverse()
    return motions


def _distinction(a: World, b: World, motions: list[int]) -> Distinction:
    """Replay ``motions`` in both worlds to record the perception sequences."""
    sa, sb = a.start_state(), b.start_state()
    pa, pb = [], []
    for motion in motions:
        sa, sb = step(a, sa, motion), step(b, sb, motion)
        pa.append(sense(a, sa))
        pb.append(sense(b, sb))
    return Distinction(tuple(motions), tuple(pa), tuple(pb))


def _explore(a: World, b: World) -> tuple[Distinction | None, set[Pair]]:
    """BFS over the product machine: (shortest distinction or None, the pairs reached)."""
    start = (a.start_state(), b.start_state())
    sig_a, sig_b = sense(a, start[0]), sense(b, start[1])
    if sig_a != sig_b:
        return Distinction((), (sig_a,), (sig_b,)), {start}
    parent: dict[Pair, tuple[Pair, int] | None] = {start: None}
    todo = deque([start])
    while todo:
        pair = todo.popleft()
        sa, sb = pair
        for motion in range(a.degree(sa[0])):  # equal signatures ⇒ equal degrees
            nxt = (step(a, sa, motion), step(b, sb, motion))
            if nxt in parent:
                continue
            parent[nxt] = (pair, motion)
            if sense(a, nxt[0]) != sense(b, nxt[1]):
                return _distinction(a, b, _path(parent, nxt)), set(parent)
            todo.append(nxt)
    return None, set(parent)


def distinguishing_sequence(a: World, b: World) -> Distinction | None:
    """The shortest motion sequence whose perceptions differ in ``a`` and ``b``, or None.

    BFS expands product states level by level, so the first differing pair
    found lies at minimal depth.  Ties are broken by the smallest motions
    first (motions are tried in increasing order).
    """
    return _explore(a, b)[0]


def bisimulation(a: World, b: World) -> frozenset[Pair] | None:
    """The reachable product relation when ``a`` and ``b`` are indistinguishable, else None."""
    distinction, reached = _explore(a, b)
    return None if distinction is not None else frozenset(reached)


def check_relation(a: World, b: World, relation: Iterable[Pair]) -> Violation | None:
    """Verify a claimed bisimulation certificate; None when it holds.

    Checks, without reusing the search: the start pair is related, every
    related pair has equal signatures, and every motion from a related pair
    leads to a related pair.
    """
    rel = set(relation)
    start = (a.start_state(), b.start_state())
    if start not in rel:
        return Violation("bisimulation", "start pair", f"{start} in the relation", "missing")
    for sa, sb in sorted(rel):
        ga, gb = sense(a, sa), sense(b, sb)
        if ga != gb:
            return Violation("bisimulation", f"pair {(sa, sb)}", f"equal signatures", f"{ga} vs {gb}")
        for motion in range(a.degree(sa[0])):
            nxt = (step(a, sa, motion), step(b, sb, motion))
            if nxt not in rel:
                return Violation("bisimulation", f"pair {(sa, sb)} motion {motion}",
                                 f"successor {nxt} in the relation", "missing")
    return None


def indistinguishable(a: World, b: World) -> bool:
    """True when no motion sequence tells ``a`` and ``b`` apart (§3.2)."""
    return distinguishing_sequence(a, b) is None


def is_counterexample(a: World, b: World) -> bool:
    """Indistinguishable but not extended-isomorphic with markers preserved (§3.1.3, §3.2)."""
    return indistinguishable(a, b) and not find_isomorphism(a, b, markers=True).isomorphic
