"""The compiled execution trie of one iteration: the motion sequences executed from v_u (thesis §4.1).

The engine's counterpart of :class:`~topomark.reference.explorers.execution_trie.ExecutionTrie`:
"beginning from v_u the same motion sequence (relative doors) visits the
same edges and vertices in the environment" (§4.1), so every motion sequence
the robot executes from v_u while validating e — each motion relative to the
node's canonical entry, the first relative to e — is a path of one trie
rooted at v_u, each node holding the perception sensed at its end.

A trie is a tuple of arrays, nodes numbered in the order they are added
(a parent before its children): ``parent``, ``motion``, ``degree`` and
``code`` (the perception, :mod:`.signature`), ``depth``, and the children as
a list (``first`` child, ``next`` sibling, in the order added); ``meta``
holds the node count, the robot's node and its *offset* — its physical entry
edge counted from the node's canonical one: 0 after moving forward, the
child's motion after moving back (line 17's reverse motion), as the
reference's.  The robot is moved only through :func:`forward` and
:func:`back`, which call :func:`~.robot.move`.

Examples
--------
>>> T = new_trie(8)
>>> start_trie(T, 3, 0); add_child(T, 0, 2, 4, 0), find_child(T, 0, 2), find_child(T, 0, 1), depth_of(T, 1)
(1, 1, -1, 1)
"""

from __future__ import annotations

import numpy as np

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.robot import fault, move

__all__ = ["new_trie", "start_trie", "add_child", "find_child", "depth_of", "forward", "back", "goto", "path_to",
           "PARENT", "MOTION", "DEGREE", "CODE", "DEPTH", "FIRST", "NEXT", "META", "COUNT", "AT", "OFFSET", "FULL"]

PARENT, MOTION, DEGREE, CODE, DEPTH, FIRST, NEXT, META = range(8)
COUNT, AT, OFFSET, FULL = range(4)
"""``meta``: the number of nodes, the robot's node and offset, and 1 once a node found no room."""


@kernel
def new_trie(capacity: int) -> tuple:
    """An empty trie with room for ``capacity`` nodes."""
    return (np.zeros(capacity, dtype=np.int64), np.zeros(capacity, dtype=np.int64),
            np.zeros(capacity, dtype=np.int64), np.zeros(capacity, dtype=np.int64),
            np.zeros(capacity, dtype=np.int64), np.zeros(capacity, dtype=np.int64),
            np.zeros(capacity, dtype=np.int64), np.zeros(4, dtype=np.int64))


@step
def start_trie(T: tuple, degree: int, code: int) -> None:
    """The trie of a new iteration: its root v_u, sensed (``degree``, ``code``) on entering by e; the robot there."""
    T[PARENT][0], T[MOTION][0], T[DEGREE][0], T[CODE][0], T[DEPTH][0] = -1, -1, degree, code, 0
    T[FIRST][0], T[NEXT][0] = -1, -1
    T[META][COUNT], T[META][AT], T[META][OFFSET], T[META][FULL] = 1, 0, 0, 0


@step
def find_child(T: tuple, node: int, motion: int) -> int:
    """The child of ``node`` reached by canonical ``motion``, or -1."""
    c = T[FIRST][node]
    while c >= 0:
        if T[MOTION][c] == motion:
            return c
        c = T[NEXT][c]
    return -1


@step
def add_child(T: tuple, node: int, motion: int, degree: int, code: int) -> int:
    """A perception known at the end of ``motion`` from ``node``: the new node (the last child), or -1 when full."""
    n = T[META][COUNT]
    if n >= T[PARENT].shape[0]:
        T[META][FULL] = 1
        return -1
    T[PARENT][n], T[MOTION][n], T[DEGREE][n], T[CODE][n] = node, motion, degree, code
    T[DEPTH][n], T[FIRST][n], T[NEXT][n] = T[DEPTH][node] + 1, -1, -1
    c = T[FIRST][node]
    if c < 0:
        T[FIRST][node] = n
    else:
        while T[NEXT][c] >= 0:
            c = T[NEXT][c]
        T[NEXT][c] = n
    T[META][COUNT] = n + 1
    return n


@step
def depth_of(T: tuple, node: int) -> int:
    return T[DEPTH][node]


@kernel
def forward(robot: np.ndarray, T: tuple, motion: int, purpose: int) -> tuple:
    """Move along canonical ``motion`` from the robot's node and sense; the node reached (new or known) becomes
    the robot's, offset 0.  Returns what was sensed; a full trie stops the robot there (``FULL``)."""
    node, meta = T[META][AT], T[META]
    got = move(robot, (motion - meta[OFFSET]) % T[DEGREE][node], purpose)
    if fault(robot):
        return got
    child = find_child(T, node, motion)
    if child < 0:
        child = add_child(T, node, motion, got[0], got[1])
        if child < 0:
            return got
    meta[AT], meta[OFFSET] = child, 0
    return got


@kernel
def back(robot: np.ndarray, T: tuple, purpose: int) -> None:
    """The reverse motion (line 17): back to the parent, facing the exit the robot came back through."""
    node, meta = T[META][AT], T[META]
    move(robot, (-meta[OFFSET]) % T[DEGREE][node], purpose)
    meta[AT], meta[OFFSET] = T[PARENT][node], T[MOTION][node]


@kernel
def goto(robot: np.ndarray, T: tuple, depth: int, purpose: int) -> None:
    """Retrace up the robot's path to its node at ``depth``."""
    while T[DEPTH][T[META][AT]] > depth and not fault(robot):
        back(robot, T, purpose)


@kernel
def path_to(T: tuple, node: int, out: np.ndarray) -> int:
    """The motions from v_u to ``node`` into ``out``; their number."""
    n = T[DEPTH][node]
    x = node
    for k in range(n - 1, -1, -1):
        out[k] = T[MOTION][x]
        x = T[PARENT][x]
    return n
