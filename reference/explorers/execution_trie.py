"""The execution trie of one iteration: every motion sequence executed from v_u, and the robot's place in it (§4.1).

The observation behind Enhancement-1 (§4.1, "capturing overlap of execution
paths"): "beginning from v_u the same motion sequence (relative doors) visits
the same edges and vertices in the environment".  So every motion sequence the
robot executes from v_u while validating e — relative exits, the first one
relative to e — is a path of one trie rooted at v_u, each node holding the
perception sensed at its end.  Every Chapter 4 technique reads this trie:
stage 1 compares it with P^E, Enhancements 2/3 trace it on S and T,
Enhancement-3 records it into T, Enhancements 4/5 add their expansion
traversals to it.

The robot's position is a node plus its *offset*: the physical entry edge
counted from the node's canonical entry edge (the one the node's path
entered by).  It moves forward along a child, or back to the parent by the
reverse motion of line 17 of Algorithm 3.1, after which it faces the parent's
exit it came back through: the offset is that exit.

Nodes that are not moves: ``virtual`` (motion 0 from v_u reaches v_k, known
because the robot came that way; Enhancements 4/5) and ``recorded`` (grafted
from T before any motion; Enhancement-3).
"""

from __future__ import annotations

from typing import cast

from topomark.spec.signature import Signature

from topomark.reference.explorers.inconsistency import inconsistent

__all__ = ["TrieNode", "ExecutionTrie", "common_prefix"]


class TrieNode:
    """A node of the execution trie: the place reached by the motions from v_u to here."""

    __slots__ = ("sig", "parent", "motion", "children", "depth", "kind")

    def __init__(self, sig: Signature, parent: "TrieNode | None", motion: int | None, kind: str):
        self.sig, self.parent, self.motion, self.kind = sig, parent, motion, kind
        self.children: dict[int, TrieNode] = {}
        self.depth: int = 0 if parent is None else parent.depth + 1

    def path(self) -> list[int]:
        """The motions from v_u to this node."""
        out: list[int] = []
        x = self
        while x.parent is not None:
            out.append(cast(int, x.motion))  # every node but v_u has its motion
            x = x.parent
        return out[::-1]

    def first(self) -> int | None:
        """The first motion of the path from v_u to this node (None at v_u)."""
        node = self
        while node.depth > 1:
            node = cast(TrieNode, node.parent)  # below depth 1, a node has its parent
        return node.motion


class ExecutionTrie:
    """The trie of the current iteration, the robot's node and offset in it, and the nodes added since a check."""

    __slots__ = ("robot", "root", "at", "offset", "new", "light")

    def __init__(self, robot, sig: Signature, light=None):
        self.robot = robot
        self.light = light  # the lighthouse, which decides what a contradiction is (:meth:`forward`)
        self.root = self.at = TrieNode(sig, None, None, "root")
        self.offset = 0
        self.new: list[TrieNode] = []  # nodes added since the techniques last looked

    def add(self, node: TrieNode, m: int, sig: Signature, kind: str) -> TrieNode:
        """A perception known at the end of motion ``m`` from ``node``."""
        child = node.children[m] = TrieNode(sig, node, m, kind)
        self.new.append(child)
        return child

    def graft(self, node: TrieNode, rec) -> int:
        """Add the record tree ``rec``'s children below ``node`` as known perceptions; return how many were new."""
        added = 0
        for m, child in rec.children.items():
            known = node.children.get(m)
            if known is None:
                known = self.add(node, m, child.sig, "recorded")
                added += 1
            added += self.graft(known, child)
        return added

    def forward(self, m: int, purpose: str) -> Signature:
        """Move along motion ``m`` (relative to the node's canonical entry) and sense."""
        node = self.at
        sig = self.robot.move((m - self.offset) % node.sig.degree, purpose)
        child = node.children.get(m)
        if child is None:
            child = self.add(node, m, sig, purpose)
        elif child.sig != sig:
            # The world is fixed and a motion from a place always leads to the same place (§3.1.1):
            # the robot's own perceptions never disagree, so only a node grafted from T (a record placed by the
            # map) can; with an explicit lighthouse the map is right (Lemma 1, §3.4), with another it may not be
            # (§5.2.1): see :func:`~topomark.reference.explorers.inconsistency.inconsistent`.
            raise inconsistent(self.light, f"execution trie: the motions {child.path()} from v_u sensed {sig}, "
                                           f"where {child.kind} perception {child.sig} is known", "§3.1.1 and Lemma 1")
        self.at, self.offset = child, 0
        return sig

    def back(self, purpose: str) -> None:
        """The reverse motion (line 17): back to the parent, facing the exit the robot came back through."""
        node = self.at
        self.robot.move((-self.offset) % node.sig.degree, purpose)
        self.at, self.offset = cast(TrieNode, node.parent), cast(int, node.motion)  # the robot is not at v_u

    def goto(self, depth: int, purpose: str = "retrace") -> None:
        """Retrace up the robot's path to the node at ``depth``."""
        while self.at.depth > depth:
            self.back(purpose)


def common_prefix(a, b) -> int:
    """The number of leading motions two sequences share: the overlap of their execution paths."""
    k = 0
    for x, y in zip(a, b):
        if x != y:
            break
        k += 1
    return k
