"""Validating a loop-closing hypothesis of Algorithm 5.1 against every known vertex: the "global signature"
(thesis §5.2.2; Algorithm 5.1 lines 17–30).

"For each potential loop closing possibility (hypothesis) … we attempt to
validate it by computing paths from the hypothesized location of the robot to
*each* of the known places in M, and then having the robot traverse each of
the paths. That is, each of the known vertices serves as a 'lighthouse'. …
For a loop closing hypothesis to be accepted, paths to *all* the
'lighthouses' must be completed with no signature mismatch" (§5.2.2).

Decisions:

* **Path overlap** (§5.2.2: "using the technique in Chapter 4, the path
  overlap is captured in the multiple lighthouse traversals"): the paths to
  every known vertex are the branches of one breadth-first tree of the
  hypothesised model M' rooted at the hypothesised place, walked depth-first.
  Every branch is a shortest path from the hypothesised place to its vertex,
  exactly the thesis's path, and every vertex on it is sensed as on that path;
  the walk costs 2(|V_M'| − 1) moves instead of the sum of out-and-back paths.
  The walk is closed (every edge down is walked back up through the edge the
  robot entered by), so the robot ends at v_u, and on a mismatch it climbs
  back up the branch it is on (moving back through the edge it entered by
  is always possible, whatever the model).
* **Expected perception** = the degree of each vertex on the path and, with
  ``entry_check`` (``--entry-check yes``, the default), "the expected entry
  edge information" (§5.2.2) at each vertex whose neighbours are all known in
  M' and whose neighbour degree list D has no proper rotation onto itself
  (:func:`shows_entry`, §5.1's test): the thesis does not say how it is read
  (§5.2.2 names the information only); here the robot visits every neighbour
  out and back (moves tagged ``probe``, as §5.1's probing) and compares each
  degree with M''s at that exit counted from the expected entry.
* **As listed** (:func:`validate_paths`, ``model-tree-listing``): lines 18–23 walk "a path from v_k' to v_l"
  for each known vertex v_l other than v_k' in turn.  Decisions: v_l in the model's vertex order; the path is
  v_l's branch of the same breadth-first tree (a shortest path); each vertex on it is sensed as above (its
  entry probed where it shows one, on every path that reaches it); the path's start being v_k', the robot walks
  back to it by the edges it came down (moves tagged ``validation``; retracing its own edges it senses
  nothing new, so nothing is compared) before the next path.
* ``model-tree`` forms no hypothesis that would make a self-loop or a multi-edge: §3.1.1 forbids both in a
  world; Algorithm 5.1 line 17 does not exclude them, and ``model-tree-listing`` forms the multi-edge ones
  (:mod:`.model_tree`), so a model validated here may have a multi-edge.

:class:`Walker` keeps the robot's frame: after an excursion the robot is back
at v_u but has entered it by another edge; ``turn`` is that offset, applied
to the next motion, so the explorer's motions stay relative to the entry of
the step (Algorithm 3.1's "re-align to e", §3.3).

This module imports nothing that can see a world.
"""

from __future__ import annotations

from topomark.reference.explorers.robot import Robot
from topomark.reference.explorers.model_shapes import Shape

__all__ = ["Walker", "validate", "validate_paths", "shows_entry"]


class Walker:
    """The robot with a logical frame: ``move(k)`` leaves by exit k counted from the logical entry."""

    def __init__(self, robot: Robot, degree: int):
        self.robot = robot
        self.degree = degree  # the degree of the vertex the robot stands on
        self.turn = 0  # the physical entry, counted from the logical entry

    def move(self, k: int, purpose: str) -> int:
        """Leave by logical exit ``k``; return the degree sensed at the vertex reached (entered: turn 0)."""
        sig = self.robot.move((k - self.turn) % self.degree, purpose)
        self.degree, self.turn = sig.degree, 0
        return sig.degree


def validate(walker: Walker, shape: Shape, root: int, entry: int, entry_check: bool = False) -> tuple[bool, int]:
    """Walk a breadth-first tree of ``shape`` from ``root`` (the robot believed there, entered by ``entry``),
    comparing degrees (and, with ``entry_check``, the entry edge where :func:`shows_entry`); return (every
    perception matched, moves made).  The robot ends where it started."""
    children = _bfs_children(shape, root)
    ent = (entry + walker.turn) % shape.degree(root)  # the physical entry, in the shape's exit numbering
    stack: list[tuple[int, int]] = [(root, 0)]  # (vertex, index of its next child)
    back: dict[int, int] = {}  # exit of each walked vertex toward its tree parent
    robot, moves = walker.robot, 0
    ok = True
    if entry_check and shows_entry(shape, root):
        ok, ent, moves = _probe(robot, shape, root, ent)
    while stack and ok:
        v, k = stack[-1]
        if k == len(children[v]):
            stack.pop()
            if stack:  # up to the parent
                robot.move((back[v] - ent) % shape.degree(v), "validation")
                ent = shape.target((v, back[v]))[1]
                moves += 1
            continue
        stack[-1] = (v, k + 1)
        y = children[v][k]
        w, j = shape.target((v, y))
        sig = robot.move((y - ent) % shape.degree(v), "validation")
        moves += 1
        if sig.degree != shape.degree(w):  # mismatch: back through the entry edge, then up the branch
            robot.move(0, "retrace")
            ent, moves, ok = y, moves + 1, False
            break
        back[w], ent = j, j
        stack.append((w, 0))
        if entry_check and shows_entry(shape, w):
            ok, ent, probed = _probe(robot, shape, w, ent)
            moves += probed
    if not ok:  # up the branch the robot is on, by the edges it came down
        for u, _ in reversed(stack[1:]):
            robot.move((back[u] - ent) % shape.degree(u), "retrace")
            ent = shape.target((u, back[u]))[1]
            moves += 1
    walker.turn = (ent - entry) % shape.degree(root)
    return ok, moves


def validate_paths(walker: Walker, shape: Shape, root: int, entry: int, entry_check: bool = False
                   ) -> tuple[bool, int]:
    """:func:`validate` as Algorithm 5.1 lines 18–23 list it: a path from ``root`` to each other vertex in turn,
    out and back (module docstring); the first mismatch rejects.  The robot ends where it started."""
    children = _bfs_children(shape, root)
    up: dict[int, tuple[int, int]] = {}  # vertex -> (its tree parent, the parent's exit to it)
    for v, exits in children.items():
        for y in exits:
            up[shape.target((v, y))[0]] = (v, y)
    ent = (entry + walker.turn) % shape.degree(root)
    robot, moves, ok = walker.robot, 0, True
    if entry_check and shows_entry(shape, root):
        ok, ent, moves = _probe(robot, shape, root, ent)
    for target in range(shape.n):
        if not ok:
            break
        path: list[tuple[int, int]] = []
        v = target
        while v != root:
            path.append(up[v])
            v = up[v][0]
        walked: list[tuple[int, int]] = []  # (vertex entered, its exit back toward the root)
        for v, y in reversed(path):
            w, j = shape.target((v, y))
            sig = robot.move((y - ent) % shape.degree(v), "validation")
            moves += 1
            if sig.degree != shape.degree(w):  # mismatch: back through the entry edge
                robot.move(0, "retrace")
                ent, moves, ok = y, moves + 1, False
                break
            ent = j
            walked.append((w, j))
            if entry_check and shows_entry(shape, w):
                ok, ent, probed = _probe(robot, shape, w, ent)
                moves += probed
                if not ok:
                    break
        for w, j in reversed(walked):  # back to the root by the edges the robot came down
            robot.move((j - ent) % shape.degree(w), "validation" if ok else "retrace")
            ent = shape.target((w, j))[1]
            moves += 1
    walker.turn = (ent - entry) % shape.degree(root)
    return ok, moves


def shows_entry(shape: Shape, v: int) -> bool:
    """§5.2.2: ``v``'s neighbours are all known and their degree list D has no proper rotation onto itself,
    so the robot entering ``v`` can tell its entry edge by visiting them (§5.1's test)."""
    row = [x for x in shape.rows[v] if x is not None]
    if len(row) < shape.degree(v):
        return False
    D = tuple(shape.degree(x[0]) for x in row)
    return all(D[r:] + D[:r] != D for r in range(1, len(D)))


def _probe(robot, shape: Shape, v: int, ent: int) -> tuple[bool, int, int]:
    """Visit every neighbour of ``v`` out and back, comparing degrees (the entry edge, §5.2.2); return (all
    matched, the entry the robot is back at ``v`` by, moves made)."""
    d = shape.degree(v)
    moves = 0
    for x in range(d):
        sig = robot.move((x - ent) % d, "probe")
        robot.move(0, "probe")
        ent, moves = x, moves + 2
        if sig.degree != shape.degree(shape.target((v, x))[0]):
            return False, ent, moves
    return True, ent, moves


def _bfs_children(shape: Shape, root: int) -> dict[int, list[int]]:
    """The exits of each vertex leading to its children in a breadth-first tree of ``shape`` from ``root``."""
    children: dict[int, list[int]] = {root: []}
    order = [root]
    for v in order:
        for i, x in enumerate(shape.rows[v]):
            if x is not None and x[0] not in children:
                children[v].append(i)
                children[x[0]] = []
                order.append(x[0])
    return children
