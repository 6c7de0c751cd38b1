"""World models of Algorithm 5.1 with shared structure: :class:`Shape` (a partial embedded map) and
:class:`Model` (a shape with the robot's believed pose) (thesis §5.2.2, Figure 5.2).

Algorithm 5.1 keeps many world models, and each step makes children of
them: a *pass* child (same map, new pose), *loop augmentation* children (one
new edge between known darts) and the *non-loop* child (a new vertex and
edge).  Copying every model each step would make the model tree cost
O(models × size) memory per step; here a :class:`Shape` is immutable, a pass
child shares its parent's shape object, and an augmented child shares every
adjacency row it does not change (only the outer tuple and the one or two
rows touched are new) — "models with shared structure (no deep
copy of every model each step)".

Numbering is that of :class:`~topomark.spec.mapstate.PartialMap`: vertex 0 is
the start, whose exit 0 is the exit the robot faced at the start; a vertex
added by a non-loop augmentation has the explored edge as its exit 0, its
other exits numbered clockwise.  So every model names the start place as
(0, 0), the anchor the checker's ``models`` check uses.

This module imports nothing that can see a world.

Examples
--------
>>> s = Shape.start(2)                    # a cycle's start vertex
>>> s = s.add_vertex(2, (0, 0))           # explored exit 0: a new vertex of degree 2
>>> s = s.add_vertex(2, (1, 1))
>>> s.open_darts()
[(0, 1), (2, 1)]
>>> t = s.join((2, 1), (0, 1))            # close the triangle
>>> t.complete(), t.n, t.edges, t.genus(), t.diameter()
(True, 3, 3, 0, 1)
>>> s.complete(), s.rows[0] is t.rows[0]  # the parent is unchanged; untouched rows are shared
(False, False)
>>> s.rows[1] is t.rows[1]
True
"""

from __future__ import annotations

from collections import deque
from typing import cast

from topomark.spec.mapstate import MapDart, PartialMap

__all__ = ["Shape", "Model", "walk_equivalent"]


class Shape:
    """An immutable partial map: ``rows[v][i]`` is the dart exit ``i`` of ``v`` is joined to, or None."""

    __slots__ = ("rows", "edges", "open", "_partial")

    def __init__(self, rows: tuple[tuple[MapDart | None, ...], ...], edges: int, open_: int):
        self.rows, self.edges, self.open = rows, edges, open_
        self._partial: PartialMap | None = None

    @classmethod
    def start(cls, degree: int) -> "Shape":
        """The model before any step: the start vertex (0) with ``degree`` unexplored exits."""
        return cls(((None,) * degree,), 0, degree)

    # -- queries ------------------------------------------------------------------
    @property
    def n(self) -> int:
        return len(self.rows)

    def degree(self, v: int) -> int:
        return len(self.rows[v])

    def arc(self, dart: MapDart) -> MapDart | None:
        return self.rows[dart[0]][dart[1]]

    def target(self, dart: MapDart) -> MapDart:
        """Where an explored ``dart`` leads (the caller knows it is joined)."""
        return cast(MapDart, self.rows[dart[0]][dart[1]])

    def complete(self) -> bool:
        """No unexplored exit: a "completed model" (§5.2.2)."""
        return self.open == 0

    def open_darts(self) -> list[MapDart]:
        return [(v, i) for v, row in enumerate(self.rows) for i, x in enumerate(row) if x is None]

    def adjacent(self, v: int, w: int) -> bool:
        return any(x is not None and x[0] == w for x in self.rows[v])

    # -- augmentations (new shapes; this one is unchanged) ----------------------------
    def join(self, a: MapDart, b: MapDart) -> "Shape":
        """Loop augmentation: the unexplored darts ``a`` and ``b`` joined by an edge."""
        rows = list(self.rows)
        row = list(rows[a[0]])
        row[a[1]] = b
        rows[a[0]] = tuple(row)
        row = list(rows[b[0]])
        row[b[1]] = a
        rows[b[0]] = tuple(row)
        return Shape(tuple(rows), self.edges + 1, self.open - 2)

    def add_vertex(self, degree: int, at: MapDart) -> "Shape":
        """Non-loop augmentation: a new vertex of ``degree`` whose exit 0 is joined to the unexplored dart ``at``."""
        new = len(self.rows)
        rows = list(self.rows)
        row = list(rows[at[0]])
        row[at[1]] = (new, 0)
        rows[at[0]] = tuple(row)
        rows.append((at,) + (None,) * (degree - 1))
        return Shape(tuple(rows), self.edges + 1, self.open - 1 + degree - 1)

    # -- properties the §5.3 cues test ---------------------------------------------
    def genus(self) -> int:
        """The genus of the rotation system, an unexplored exit counted as an edge to a leaf of its own (which
        changes no face count): a sub-embedding of the world has genus ≤ the world's, so a model of genus > 0
        cannot be part of a planar (genus-0) world.  Faces traced as :meth:`World.faces` does: (v, i) → (w, j+1)."""
        seen: set[MapDart] = set()
        faces = 0
        for v, row in enumerate(self.rows):
            for i in range(len(row)):
                if (v, i) in seen:
                    continue
                faces += 1
                d = (v, i)
                while d not in seen:
                    seen.add(d)
                    x = self.rows[d[0]][d[1]]
                    w, j = (d[0], d[1]) if x is None else x  # an unexplored exit: out to its leaf and back
                    d = (w, (j + 1) % len(self.rows[w]))
        return (2 - self.n + self.edges - faces) // 2

    def distances(self, source: int) -> list[int]:
        """Hop distances from ``source`` over explored edges (-1 where unreachable)."""
        dist = [-1] * self.n
        dist[source] = 0
        queue = deque([source])
        while queue:
            v = queue.popleft()
            for x in self.rows[v]:
                if x is not None and dist[x[0]] < 0:
                    dist[x[0]] = dist[v] + 1
                    queue.append(x[0])
        return dist

    def diameter(self) -> int:
        return max(max(self.distances(v)) for v in range(self.n))

    # -- the contract's view -------------------------------------------------------
    def partial_map(self) -> PartialMap:
        """This shape as a :class:`PartialMap` (U in dart order), built once and shared: read it, never mutate it."""
        if self._partial is None:
            S = PartialMap()
            for row in self.rows:
                S.add_vertex(len(row))
            for v, row in enumerate(self.rows):
                for i, x in enumerate(row):
                    if x is not None and (v, i) < x:
                        S.add_edge((v, i), x)
            S.unexplored = self.open_darts()
            self._partial = S
        return self._partial


class Model:
    """One world model of the model tree: a shape and the robot's believed pose (map vertex, entry exit)."""

    __slots__ = ("shape", "pose")

    def __init__(self, shape: Shape, pose: MapDart):
        self.shape, self.pose = shape, pose

    def __repr__(self) -> str:
        return f"Model(n={self.shape.n}, edges={self.shape.edges}, open={self.shape.open}, pose={self.pose})"


def walk_equivalent(a: Shape, pose_a: MapDart, b: Shape, pose_b: MapDart) -> bool:
    """No walk tells the completed ``a`` (robot at ``pose_a``) from the completed ``b`` (at ``pose_b``): every
    motion sequence senses the same degrees in both (a breadth-first search over pairs of robot states, as
    the Figure 3.4 pair was checked in :mod:`topomark.proofs.wheels`)."""
    start = (pose_a, pose_b)
    seen = {start}
    queue = deque([start])
    while queue:
        (va, ea), (vb, eb) = queue.popleft()
        d = a.degree(va)
        if d != b.degree(vb):
            return False
        for k in range(d):
            pair = (a.target((va, (ea + k) % d)), b.target((vb, (eb + k) % d)))
            if pair not in seen:
                seen.add(pair)
                queue.append(pair)
    return True
