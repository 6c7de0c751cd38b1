"""Lighthouses: how a Chapter 3–4 algorithm establishes v0 and recognises it (thesis §3.3, §3.7, §6.1–6.3).

Algorithm 3.1 needs one place that gives *explicit place and back-link
information* (§3.2.2): on entering it, the robot knows it is at v0 *and* by
which exit it came in.  The thesis names several marker kits that establish
such a place, "equivalent to" its directional vertex marker:

=========================  ==========================================================  =====================
name                       what the robot drops at v0, facing exit 0                   thesis
=========================  ==========================================================  =====================
directional-vertex         a directional vertex marker pointing at exit 0              §3.3, Algorithm 3.1
directional-edge           a directional edge marker on exit 0, its head at v0         §6.1, Figure 6.1(b)
vertex-and-edge            an undirected marker at v0 and one on exit 0                §6.2
three-undirected-edge      one undirected marker on exit 0, two on exit 1              §6.2
=========================  ==========================================================  =====================

A :class:`Lighthouse` drops its markers, then records in S what it senses at
v0 (:meth:`~topomark.spec.mapstate.PartialMap.mark_as_sensed`), so the
expected perceptions P^E of every hypothesis (which read S) include the
markers "at the incident edges of each visited vertex and the direction of
the marker if the marker is present" (§6.1).  Recognition is the same for
every lighthouse: the signature just sensed equals v0's signature read from
exactly one entry — that entry is the back-link.  :meth:`Lighthouse.establish`
asserts the thesis's condition that makes this work: v0's signatures from
its d entries are d different ones (explicit back-link information).

Decisions (the thesis is silent):

* §6.1 does not say which way a directional edge marker points; the head at
  v0 matches its example ``[3, A, E-2-H]`` at the lighthouse end.
* §6.2 names one marker on one edge of v0 and two on another without saying
  which edges; we take the faced exit and the next one clockwise, so a start
  vertex of degree 1 cannot hold this lighthouse (bad input, checked before
  the run).
* The lighthouses of Figure 3.21(b) (three undirected vertex markers, whose
  back-link needs "extra traversals looking for the marked neighbors") and of
  §6.3 (a thread of length ε) are not here yet: the first needs a probing
  step in validation, the second threads in the robot.

Examples
--------
>>> LIGHTHOUSES["directional-edge"].kit.to_json()
{'directional-edge': 1}
>>> [op.to_json() for op in LIGHTHOUSES["three-undirected-edge"].ops]
[{'op': 'drop', 'kind': 'edge', 'count': 1, 'exit': 0}, {'op': 'drop', 'kind': 'edge', 'count': 2, 'exit': 1}]
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature, back_link_table

__all__ = ["Lighthouse", "LIGHTHOUSES", "lighthouse"]


@dataclass(frozen=True)
class Lighthouse:
    """A way to make v0 a place of explicit place and back-link information."""

    name: str
    thesis: str
    kit: Kit
    ops: tuple[MarkerOp, ...]
    drops: str  # what the robot drops, in words
    min_degree: int = 1

    def establish(self, robot, S: PartialMap, v0: int) -> dict[Signature, int]:
        """Drop the markers at v0 (the robot stands there, facing exit 0) and record them in S.

        Returns the recognition table: v0's signature from each entry ↦ that entry.
        """
        for op in self.ops:
            robot.operate(op)
        S.mark_as_sensed(v0, robot.sense(), 0)
        table, bad = back_link_table(S, v0, f"v0 (lighthouse {self.name})")
        if bad is not None:
            raise CheckFailure(bad)
        return table


def _edge(exit: int, count: int = 1, direction: str | None = None) -> MarkerOp:
    return MarkerOp("edge", exit=exit, direction=direction, count=count)


LIGHTHOUSES: dict[str, Lighthouse] = {h.name: h for h in (
    Lighthouse("directional-vertex", "§3.3, Algorithm 3.1", Kit(vertex=1, directional=True),
               (MarkerOp("vertex", direction=0),), "a directional vertex marker pointing at the faced exit"),
    Lighthouse("directional-edge", "§6.1, Figure 6.1(b)", Kit(edge=1, directional=True), (_edge(0, direction="H"),),
               "a directional edge marker on the faced edge, its head at v0"),
    Lighthouse("vertex-and-edge", "§6.2", Kit(vertex=1, edge=1), (MarkerOp("vertex"), _edge(0)),
               "an undirected vertex marker and an undirected edge marker on the faced edge"),
    Lighthouse("three-undirected-edge", "§6.2", Kit(edge=3), (_edge(0), _edge(1, 2)),
               "one undirected edge marker on the faced edge and two on the next exit clockwise", min_degree=2),
)}
"""The lighthouses by name; ``directional-vertex`` is Algorithm 3.1's own and the default."""


def lighthouse(name: str) -> Lighthouse:
    """The lighthouse called ``name``; an unknown name is bad input listing the known ones."""
    if name not in LIGHTHOUSES:
        raise InvalidInput(f"unknown lighthouse {name!r} (choose from {', '.join(LIGHTHOUSES)})")
    return LIGHTHOUSES[name]
