"""Probing moves: recognising a lighthouse whose back-link needs "extra traversals" (thesis §3.7, §5.1).

Some lighthouses give explicit place information in their own signature but
back-link information only around them:

* Figure 3.21(b), three undirected vertex markers — "the entry edge can be
  established by taking extra traversals looking for the marked neighbors"
  (§3.7);
* §5.1, one undirected vertex marker at a vertex whose neighbour degrees
  D have no proper cyclic rotation onto themselves — recognising it "requires
  visiting adjacent vertices to determine relative orientation to the
  marker", and "the robot does not need to transit to all edges … but only as
  many as necessary" (§5.1).

For both, the robot on sensing v0's signature probes neighbours (out and
back, purpose ``probe``, each a counted edge traversal) until exactly one
entry of v0 agrees with what it saw (:func:`identify`), then walks back to
face the way it came in (out through the entry edge and back: two more
traversals, only if it probed at all).  What it then knows is written as the
thesis writes Figure 3.21's perceptions — ``[3,V-1,A]`` "means that the
marked neighbor is present and is the next on the left" — as a *virtual
head*: v0's signature with ``V-r``, r the relative exit of v0's exit 0
(:func:`perceived`).  Every Chapter 3–4 algorithm then works on those
perceptions unchanged:

* :class:`ProbingRobot` wraps the robot: a move of purpose ``new``,
  ``validation`` or ``expansion`` that senses v0's raw signature returns the
  probed perception instead (travel and retrace moves never need it);
* :class:`PerceivedMap` is S as the explorer perceives it — v0's mark with the
  virtual head — for expected perceptions P^E, tracing and records; S itself
  keeps the true marks, which the checker compares with the world.

Decision (the thesis is silent): the probe of a neighbour is always "out
through the exit, sense, back"; the robot restores its facing after probing
so the explorer's bookkeeping (the retrace of line 17, the execution trie's
offset) holds unchanged.  The vertex just left is never probed: its signature
was sensed when the robot stood there (§5.1: "only as many as necessary").

Examples
--------
>>> aperiodic([4, 3, 3]), aperiodic([3, 3, 3, 3]), aperiodic([2, 3, 2, 3])
(True, False, False)
>>> from topomark.spec.signature import Signature
>>> perceived(Signature(3, 1), 2)
[3,V-1,A]
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any, Callable

from topomark.spec.errors import ExplorerFault
from topomark.spec.signature import Signature

__all__ = ["ProbingRobot", "PerceivedMap", "VirtualHead", "identify", "views_around", "view_here", "aperiodic",
           "perceived", "ENRICHED"]

ENRICHED = frozenset({"new", "validation", "expansion"})
"""The purposes whose perception the explorer compares with S (travel and retrace moves only move)."""


def aperiodic(seq) -> bool:
    """No proper cyclic rotation of ``seq`` maps it onto itself (§5.1: "except for a complete rotation")."""
    k = len(seq)
    return all(any(seq[(i + r) % k] != seq[i] for i in range(k)) for r in range(1, k))


def perceived(sig: Signature, entry: int) -> Signature:
    """v0's probed perception from ``entry``: its signature with the virtual head at v0's exit 0."""
    return replace(sig, vertex_direction=(-entry) % sig.degree)


class VirtualHead:
    """v0's vertex mark as the explorer perceives it: the true count, a head at exit 0 (duck-types VertexMark)."""

    __slots__ = ("count", "head")

    def __init__(self, count: int):
        self.count, self.head = count, 0


class PerceivedMap:
    """S as the explorer perceives it: every query is S's, except v0's vertex mark (a :class:`VirtualHead`)."""

    def __init__(self, S, v0: int = 0):
        self._S, self._v0 = S, v0

    def vertex_mark(self, v):
        mark = self._S.vertex_mark(v)
        return VirtualHead(mark.count) if v == self._v0 and mark is not None else mark

    def __getattr__(self, name: str) -> Any:
        return getattr(self._S, name)


def view_here(robot, sig: Signature, depth: int, look: Callable | None = None) -> tuple[Any, int]:
    """What the robot learns of the place it stands at, to ``depth`` (0: ``look(sig)``, by default the degree),
    seen from its entry edge; the robot stays here.  Returns the view and its facing offset afterwards."""
    if depth == 0:
        return (look(sig) if look else sig.degree), 0
    items, f = [], 0
    for r in range(1, sig.degree):
        got = robot.move((r - f) % sig.degree, "probe")
        sub, g = view_here(robot, got, depth - 1, look)
        robot.move((-g) % got.degree, "probe")
        f = r
        items.append(sub)
    return (sig.degree, tuple(items)), f


def views_around(robot, sig: Signature, depth: int, known0=None) -> tuple[list, int]:
    """The views (depth − 1) of every neighbour, by relative exit from the entry edge; ``known0`` is the view
    behind the entry edge if known (not probed).  Returns them and the robot's facing offset afterwards."""
    views, f = [known0] * sig.degree, 0
    for r in range(sig.degree):
        if r == 0 and known0 is not None:
            continue
        got = robot.move((r - f) % sig.degree, "probe")
        views[r], g = view_here(robot, got, depth - 1)
        robot.move((-g) % got.degree, "probe")
        f = r
    return views, f


def identify(robot, sig: Signature, expect: Callable[[int, int], Any], known0, depth: int,
             look: Callable | None = None) -> int:
    """The entry of v0 the robot came in by: probe relative exits 1, 2, … until one entry j agrees with every
    view seen (``expect(j, r)``: the view at relative exit r if the entry was j), then face the entry again.

    ``known0`` is the view behind the entry edge (the vertex just left), or None if it must be probed.
    """
    d = sig.degree
    J = [j for j in range(d) if known0 is None or expect(j, 0) == known0]
    f, r = 0, 0 if known0 is None else 1
    while len(J) > 1 and r < d:
        got = robot.move((r - f) % d, "probe")
        seen, g = view_here(robot, got, depth - 1, look)
        robot.move((-g) % got.degree, "probe")
        f = r
        J = [j for j in J if expect(j, r) == seen]
        r += 1
    if f:
        robot.move((-f) % d, "probe")
        robot.move(0, "probe")
    if len(J) != 1:
        # Only lighthouses of explicit place and back-link probe here (Figure 3.21(b); §5.1: D has no proper
        # cyclic rotation onto itself): exactly one entry agrees, so another count is a bug.
        raise ExplorerFault(f"{len(J)} entries of v0 agree with the probed neighbours, where an explicit back-link "
                            "(§5.1) gives exactly one: a bug in the explorer")
    return J[0]


class ProbingRobot:
    """The robot as an explorer of a probing lighthouse sees it: v0's raw signature, met by a move the explorer
    compares with S, comes back as the probed perception (``recognise(robot, sig, previous)``)."""

    __slots__ = ("_robot", "_recognise", "_raw", "_here")

    def __init__(self, robot, recognise: Callable[[Any, Signature, Signature], Signature], raw: frozenset):
        self._robot, self._recognise, self._raw = robot, recognise, raw
        self._here = robot.sense()

    def move(self, motion: int, purpose: str = "other") -> Signature:
        previous = self._here
        sig = self._here = self._robot.move(motion, purpose)
        if sig in self._raw and purpose in ENRICHED:
            return self._recognise(self._robot, sig, previous)
        return sig

    def sense(self) -> Signature:
        return self._robot.sense()

    def operate(self, op) -> None:
        self._robot.operate(op)

    def __getattr__(self, name: str) -> Any:
        return getattr(self._robot, name)
