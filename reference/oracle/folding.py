"""Folding: identifying vertices of a partial rotation system and closing under what a rotation system forces (§3.1.1).

Nodes carry a degree and their own numbering of exits.  :meth:`Folding.union` says that exit ``ra`` of node ``a`` and
exit ``rb`` of node ``b`` are one exit of one vertex — so the two nodes are one vertex, their exit numberings one
rotation apart (§3.1.1: exits are counted clockwise, so a vertex is known up to where counting starts).
:meth:`Folding.join` records an edge between two exits.  Closing is congruence: one exit of one vertex has one edge,
so two edges recorded at it are one edge, and their other ends are identified in turn (Stallings' folding).  A
union of nodes of different degrees, or of one vertex with itself at another rotation, is a conflict: no rotation
system has it.

Examples
--------
>>> f = Folding([2, 2, 2, 2, 2])  # a walk once round a square: five visits, the last not yet known to be the first
>>> all(f.join(i, 1, i + 1, 0) for i in range(4))  # each step leaves by exit 1, arrives by exit 0
True
>>> f.union(4, 0, 0, 0)  # the last visit is the start, arrived at by the start's exit 0
True
>>> built = f.world(1)
>>> built[0].n, built[2]  # four vertices, no exit left unused
(4, False)
"""

from __future__ import annotations

from topomark.spec.errors import InvalidWorld
from topomark.spec.world import Start, World

__all__ = ["Folding"]


class Folding:
    """A union-find over nodes with rotation offsets and, at each class, its exits' edges (module docstring)."""

    def __init__(self, degree: list[int]):
        assert all(d >= 1 for d in degree), "every node has an exit (§3.1.1: every degree is at least 1)"
        self.degree = list(degree)
        self.parent = list(range(len(degree)))
        self.shift = [0] * len(degree)  # exit r of a node is exit (r + shift) of its parent
        self.edges: list[dict[int, tuple[int, int]]] = [{} for _ in degree]  # at a root: exit -> (node, its exit)
        self.owned: set[int] | None = None  # after a copy, the nodes whose edges this folding may change in place

    def copy(self) -> "Folding":
        """A folding that starts as this one; its edges are shared until either changes them (copy on write)."""
        other = Folding.__new__(Folding)
        other.degree, other.parent, other.shift = self.degree, list(self.parent), list(self.shift)
        other.edges, other.owned, self.owned = list(self.edges), set(), set()
        return other

    def _mine(self, node: int) -> dict[int, tuple[int, int]]:
        """``node``'s edges, copied first if another folding shares them."""
        if self.owned is not None and node not in self.owned:
            self.edges[node] = dict(self.edges[node])
            self.owned.add(node)
        return self.edges[node]

    def find(self, a: int) -> tuple[int, int]:
        """The root of ``a`` and the offset from ``a``'s exits to the root's."""
        path = []
        while self.parent[a] != a:
            path.append(a)
            a = self.parent[a]
        root, total = a, 0
        for node in reversed(path):  # compress: each node on the path points at the root
            total = (total + self.shift[node]) % self.degree[node]
            self.parent[node], self.shift[node] = root, total
        return root, (self.shift[path[0]] if path else 0)

    def same(self, a: int, b: int) -> bool:
        return self.find(a)[0] == self.find(b)[0]

    def holds(self, a: int, b: int, r: int | None) -> bool:
        """Whether ``a`` is already ``b``'s vertex — with ``a``'s exit 0 at ``b``'s exit ``r`` unless ``r`` is None."""
        (ra, sa), (rb, sb) = self.find(a), self.find(b)
        return ra == rb and (r is None or sa % self.degree[ra] == (r + sb) % self.degree[rb])

    def join(self, a: int, ra: int, b: int, rb: int) -> bool:
        """Record the edge from exit ``ra`` of ``a`` to exit ``rb`` of ``b``; False on a conflict."""
        return self._close([], [(a, ra, b, rb), (b, rb, a, ra)])

    def union(self, a: int, ra: int, b: int, rb: int) -> bool:
        """Exit ``ra`` of ``a`` is exit ``rb`` of ``b``; close; False on a conflict."""
        return self._close([(a, ra, b, rb)], [])

    def _close(self, unions: list, half: list) -> bool:
        while unions or half:
            if half:
                a, ra, b, rb = half.pop()
                root, s = self.find(a)
                x = (ra + s) % self.degree[root]
                there = self.edges[root].get(x)
                if there is None:
                    self._mine(root)[x] = (b, rb)
                else:
                    unions.append((there[0], there[1], b, rb))
                continue
            a, ra, b, rb = unions.pop()
            (A, sa), (B, sb) = self.find(a), self.find(b)
            d = self.degree[A]
            if A == B:
                if (ra + sa) % d != (rb + sb) % d:
                    return False
                continue
            if self.degree[B] != d:
                return False
            offset = (ra + sa - rb - sb) % d  # exit x of B is exit x + offset of A
            self.parent[B], self.shift[B] = A, offset
            moved = self.edges[B]
            self.edges[B] = {}
            if self.owned is not None:
                self.owned.add(B)
            half.extend((A, (x + offset) % d, k, rk) for x, (k, rk) in moved.items())
        return True

    def world(self, fill: int, start: tuple[int, int] = (0, 0)) -> tuple[World, tuple[str, int], bool] | None:
        """The world of the classes, the start state (node ``start[0]`` facing its exit ``start[1]``) and whether
        an exit was unused (each completed by a new path of ``fill`` vertices); None when it has a loop or a
        multiple edge (§3.1.1 excludes them)."""
        roots = sorted({self.find(a)[0] for a in range(len(self.degree))})
        rotation: dict[str, list[str]] = {f"w{r}": [] for r in roots}
        dangling = False
        for r in roots:
            for x in range(self.degree[r]):
                there = self.edges[r].get(x)
                if there is None:
                    dangling = True
                    path = [f"w{r}.{x}.{k}" for k in range(fill)]
                    rotation[f"w{r}"].append(path[0])
                    for k, v in enumerate(path):
                        rotation[v] = [f"w{r}" if k == 0 else path[k - 1]] + ([path[k + 1]] if k + 1 < fill else [])
                    continue
                rotation[f"w{r}"].append(f"w{self.find(there[0])[0]}")
        node, exit_ = start
        root, s = self.find(node)
        first = rotation[f"w{root}"]
        try:
            world = World(rotation, (), Start(f"w{root}", first[(exit_ + s) % len(first)]))
        except InvalidWorld:
            return None
        return world, world.start_state(), dangling
