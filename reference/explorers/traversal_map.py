"""The traversal map TM of Algorithm 5.1, walked breadth-first (thesis §5.2.2; Algorithm 5.1 lines 1–2).

"Initially TM contains the starting location, but it grows with a new edge
and a vertex in each step … each newly explored edge and end vertex … are
always treated as new places and are added into the traversal map TM
(non-loop augmentation). In each step, according to a BFS on TM, the robot
traverses to a frontier vertex on TM and then explores an 'unexplored' edge
of the frontier" (§5.2.2).  TM is therefore a tree: the breadth-first
unfolding of the world from the start, every path in it physically walkable.

Decision (the thesis is silent on the order within BFS): TM vertices are
expanded in the order they were added (FIFO), each one's unexplored exits in
clockwise order from exit 0 (for a vertex other than the start, exit 0 is the
edge it was reached by, so its exits 1 … d−1).  The robot walks the unique
tree path from where it stands.

Examples
--------
>>> tm = TraversalMap(2)                      # the start of a cycle
>>> tm.frontier()
(0, 0)
>>> tm.add(0, 0, 2), tm.frontier()           # exit 0 explored: TM vertex 1; next, exit 1 of the start
(1, (0, 1))
>>> tm.path(1, 0)                            # from TM vertex 1 (entered by its exit 0) to the start
[(1, 0)]
>>> tm.depth[1]
1
"""

from __future__ import annotations

from typing import cast

from topomark.spec.errors import ExplorerFault
from topomark.spec.mapstate import MapDart

__all__ = ["TraversalMap"]


class TraversalMap:
    """TM: a tree of sensed degrees; ``frontier()`` is the next (TM vertex, exit) BFS explores."""

    def __init__(self, start_degree: int):
        self.degree: list[int] = [start_degree]
        self.parent: list[MapDart | None] = [None]  # (parent TM vertex, its exit) for every vertex but the start
        self.depth: list[int] = [0]
        self.children: dict[MapDart, int] = {}
        self._cursor = 0  # the first TM vertex that may still have an unexplored exit
        self._next = 0  # its next exit to explore

    @property
    def n(self) -> int:
        return len(self.degree)

    def frontier(self) -> MapDart | None:
        """The next unexplored (TM vertex, exit) in breadth-first order, or None when TM is complete (a tree world)."""
        while self._cursor < self.n and self._next >= self.degree[self._cursor]:
            self._cursor += 1
            self._next = 1  # exit 0 of every vertex after the start is its parent edge
        return (self._cursor, self._next) if self._cursor < self.n else None

    def add(self, v: int, exit_: int, degree: int) -> int:
        """Non-loop augmentation of TM (Algorithm 5.1 line 2): exit ``exit_`` of ``v`` leads to a new vertex of
        ``degree``, entered by its exit 0."""
        if (v, exit_) != self.frontier():  # the BFS of §5.2.2 is the explorer's own order: another is a bug
            raise ExplorerFault(f"TM grows in breadth-first order only (§5.2.2), not by {(v, exit_)}: a bug in the "
                                "explorer")
        new = self.n
        self.degree.append(degree)
        self.parent.append((v, exit_))
        self.depth.append(self.depth[v] + 1)
        self.children[(v, exit_)] = new
        self._next += 1
        return new

    def explored_depth(self) -> int:
        """The depth d such that every exit of every TM vertex at depth ≤ d has been explored (−1 if none)."""
        f = self.frontier()
        return max(self.depth) if f is None else self.depth[f[0]] - 1

    def path(self, source: int, target: int) -> list[MapDart]:
        """The exits (TM vertex, exit) the robot leaves by, walking the tree from ``source`` to ``target``."""
        up: list[MapDart] = []
        down: list[MapDart] = []
        a, b = source, target
        while self.depth[a] > self.depth[b]:
            up.append((a, 0))
            a = self._up(a)[0]
        while self.depth[b] > self.depth[a]:
            down.append(self._up(b))
            b = self._up(b)[0]
        while a != b:
            up.append((a, 0))
            a = self._up(a)[0]
            down.append(self._up(b))
            b = self._up(b)[0]
        return up + down[::-1]

    def _up(self, v: int) -> MapDart:
        """The parent edge of ``v``, not the start (only the start has none)."""
        return cast(MapDart, self.parent[v])

    def arrive(self, dart: MapDart) -> MapDart:
        """Where leaving by ``dart`` leads: (TM vertex, entry exit)."""
        v, x = dart
        if x == 0 and v != 0:
            return self._up(v)
        return (self.children[dart], 0)
