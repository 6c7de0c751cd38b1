"""The compiled robot: the world's arrays, the true pose, motions, perceptions and marker drops (thesis §3.1.1–3.1.2).

The engine's counterpart of :class:`~topomark.reference.run.simulator.Simulator`
behind a :class:`~topomark.reference.explorers.robot.Robot`: this module is the
only engine code that reads a world's arrays
(:func:`topomark.proofs.world_arrays.to_arrays`).  A *robot* is one int64
array: a header (the true vertex and entry exit, where the directional marker
lies, the cost, the number of actions, a fault, and where each part begins),
then the world (``offsets``, ``nbr``, ``back``), the traversals per purpose and
the marker drops (``counts``), and the action codes of :mod:`.digest` (``log``,
as many as it has room for).  One array, not a tuple of them: a compiled
function pays for every array it takes out of a tuple, and the robot is
asked something at every step.  An explorer kernel is handed the array and
passes it only to :func:`move`, :func:`sense` and :func:`drop_vertex`,
which return what the reference robot returns, as two integers: the degree
sensed and the code of the marks there (:mod:`.signature`: 0 where there
are none), counted from the entry edge (§3.1.1, Figure 3.2).  A lighthouse's
kit is put down by :func:`operate` (vertex and edge markers, the ε thread),
one operation at a time, as the reference robot's ``operate``.

Accounting as the simulator's (§3.1.2): every traversal costs one, counted
under its purpose; a drop costs nothing and is counted apart.  A motion that
names no exit, or a second drop from a kit of one marker, is a fault
(:data:`FAULT_MOTION`, :data:`FAULT_KIT`) and the move does nothing: the
reference raises there (a failed check of the robot interface, or
:class:`~topomark.spec.errors.OutOfMarkers`), so the kernel must stop; a
refused motion returns degree 0, which no place has.

Examples
--------
>>> from topomark.spec.world import World
>>> from topomark.proofs.world_arrays import to_arrays
>>> r = make_robot(to_arrays(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})), 0, 0, 8)
>>> drop_vertex(r, 0); sense(r) == (2, encode(1, 0, 0))
True
>>> move(r, 1, PURPOSE_NEW), move(r, 1, PURPOSE_NEW), move(r, 1, PURPOSE_NEW) == (2, encode(1, 0, 0))
((2, 0), (2, 0), True)
>>> int(r[COST]), [describe(int(c)) for c in log(r)[:2]]
(3, ['drop 1 vertex marker(s) pointing at relative exit 0', 'move 1 (new)'])
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.world_arrays import WorldArrays

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.digest import PURPOSE, describe, move_code, pack_op
from topomark.reference.engine.signature import add_edge_mark, edge_mark, encode, rotate, thread_of, with_thread

__all__ = ["make_robot", "reset", "move", "sense", "drop_vertex", "operate", "fault", "counts", "log", "CUR", "ENTRY",
           "MARKER_AT", "MARKER_HEAD", "COST", "ACTIONS", "FAULT", "FAULT_MOTION", "FAULT_KIT", "DROPS",
           "TIES", "LEAVES", "OP_MOVE", "OP_VERTEX", "OP_EDGE", "OP_TIE", "OP_LEAVE", "PURPOSE_DROP",
           "PURPOSE_TRAVEL", "PURPOSE_NEW", "PURPOSE_VALIDATION", "PURPOSE_RETRACE", "describe", "log_action"]

CUR, ENTRY, MARKER_AT, MARKER_HEAD, COST, ACTIONS, FAULT, OFFSETS, NBR, BACK, COUNTS, LOG, LOG_SIZE, MARKS = range(14)
"""Header entries: the true vertex and entry, the directional vertex marker's vertex (-1: not dropped) and world
exit, the cost, the number of actions, the fault (0: none); where ``offsets``, ``nbr``, ``back``, ``counts``,
``log`` and ``marks`` (each place's code from world exit 0, :mod:`.signature`) begin, and the log's size."""
HEADER = 16
FAULT_MOTION, FAULT_KIT = 1, 2
LEAVES, TIES, DROPS = 13, 14, 15
"""Indices in ``counts`` of the thread's leave and tie operations and the marker drops (0..12: the traversals per
purpose index)."""
OP_MOVE, OP_VERTEX, OP_EDGE, OP_TIE, OP_LEAVE = range(5)
"""The kinds of a lighthouse's script items (:func:`operate`): a drop trip's motion, a vertex marker drop, an edge
marker drop, tying the thread, leaving its free end."""
PURPOSE_TRAVEL, PURPOSE_NEW, PURPOSE_DROP = PURPOSE["travel"], PURPOSE["new"], PURPOSE["drop"]
PURPOSE_VALIDATION, PURPOSE_RETRACE = PURPOSE["validation"], PURPOSE["retrace"]

_move_code = step(move_code)
_pack_op = step(pack_op)


def make_robot(arrays: WorldArrays, vertex: int, facing: int, log_size: int = 0) -> np.ndarray:
    """A robot on ``arrays`` at vertex index ``vertex``, its faced exit ``facing`` playing the entry edge
    (:meth:`~topomark.spec.world.World.start_state`), keeping the first ``log_size`` action codes."""
    parts = (arrays.offsets, arrays.nbr, arrays.back, np.zeros(16, dtype=np.int64), np.zeros(log_size, dtype=np.int64),
             np.zeros(arrays.n, dtype=np.int64))
    robot = np.zeros(HEADER + sum(len(p) for p in parts), dtype=np.int64)
    at = HEADER
    for field, part in zip((OFFSETS, NBR, BACK, COUNTS, LOG, MARKS), parts):
        robot[field], robot[at:at + len(part)] = at, part
        at += len(part)
    robot[LOG_SIZE] = log_size
    reset(robot, vertex, facing)
    return robot


def counts(robot: np.ndarray) -> np.ndarray:
    """The traversals per purpose index and (at :data:`DROPS`) the drops: a view."""
    return robot[robot[COUNTS]:robot[COUNTS] + 16]


def log(robot: np.ndarray) -> np.ndarray:
    """The action codes kept: a view."""
    return robot[robot[LOG]:robot[LOG] + min(robot[ACTIONS], robot[LOG_SIZE])]


@kernel
def reset(robot: np.ndarray, vertex: int, facing: int) -> None:
    """Put ``robot`` back at a fresh start on the same world: no marker dropped, nothing counted or logged."""
    robot[CUR], robot[ENTRY], robot[MARKER_AT], robot[MARKER_HEAD] = vertex, facing, -1, 0
    robot[COST], robot[ACTIONS], robot[FAULT] = 0, 0, 0
    robot[robot[COUNTS]:robot[COUNTS] + 16] = 0
    robot[robot[MARKS]:robot[MARKS] + robot[NBR] - robot[OFFSETS] - 1] = 0  # n places: none marked


@step
def _log(robot: np.ndarray, code: int) -> None:
    if robot[ACTIONS] < robot[LOG_SIZE]:
        robot[robot[LOG] + robot[ACTIONS]] = code
    robot[ACTIONS] += 1


log_action = _log
"""Log one action code (a marker operation of another kit, :mod:`.marks`), as every move and drop is logged."""


@step
def sense(robot: np.ndarray) -> tuple:
    """What the robot senses where it stands: (degree, the code of the marks there from the entry edge)."""
    v = robot[CUR]
    degree = robot[robot[OFFSETS] + v + 1] - robot[robot[OFFSETS] + v]
    return degree, rotate(robot[robot[MARKS] + v], degree, robot[ENTRY])


@step
def move(robot: np.ndarray, motion: int, purpose: int) -> tuple:
    """Leave through exit ``motion`` counted clockwise from the entry edge, for ``purpose`` (its index); what is
    sensed at the far end.  A motion naming no exit sets :data:`FAULT_MOTION`, moves nothing, returns (0, -1)."""
    v = robot[CUR]
    first = robot[robot[OFFSETS] + v]
    degree = robot[robot[OFFSETS] + v + 1] - first
    if motion < 0 or motion >= degree:
        robot[FAULT] = FAULT_MOTION
        return 0, 0
    dart = first + (robot[ENTRY] + motion) % degree
    robot[CUR], robot[ENTRY] = robot[robot[NBR] + dart], robot[robot[BACK] + dart]
    robot[COST] += 1
    robot[robot[COUNTS] + purpose] += 1
    _log(robot, _move_code(motion, purpose))
    return sense(robot)


@kernel
def drop_vertex(robot: np.ndarray, direction: int) -> None:
    """Drop the kit's one directional vertex marker here, pointing at relative exit ``direction`` (§3.3); a
    second drop sets :data:`FAULT_KIT` (the kit holds one)."""
    if robot[MARKER_AT] >= 0:
        robot[FAULT] = FAULT_KIT
        return
    operate(robot, OP_VERTEX, 1, direction, 0, _pack_op(0, 0, 1, 0, direction + 3))


@kernel
def operate(robot: np.ndarray, kind: int, a: int, b: int, c: int, code: int) -> None:
    """One item of a lighthouse's script, relative to the entry edge, logged as ``code`` (:mod:`.digest`):
    :data:`OP_MOVE` (motion ``a``, a drop trip's), :data:`OP_VERTEX` (``a`` vertex markers, pointing at exit
    ``b`` or undirected: -1), :data:`OP_EDGE` (``b`` edge markers on exit ``a``, ``c`` 1: directional, its head
    here and its tail at the far end; 0: undirected), :data:`OP_TIE` (the thread tied here toward exit ``a``),
    :data:`OP_LEAVE` (its free end left here).  More marks than a code holds set :data:`FAULT_KIT`."""
    if kind == OP_MOVE:
        move(robot, a, PURPOSE_DROP)
        return
    v, entry, marks = robot[CUR], robot[ENTRY], robot[MARKS]
    degree = robot[robot[OFFSETS] + v + 1] - robot[robot[OFFSETS] + v]
    here = robot[marks + v]
    if kind == OP_VERTEX:
        head = -1 if b < 0 else (entry + b) % degree
        if here % 4 + a > 3:
            robot[FAULT] = FAULT_KIT
            return
        here = here - here % 4 - 4 * (here // 4 % 4096) + encode(here % 4 + a, head, 0)
        if head >= 0:
            robot[MARKER_AT], robot[MARKER_HEAD] = v, head
    elif kind == OP_EDGE:
        dart = robot[robot[OFFSETS] + v] + (entry + a) % degree
        far, far_exit = robot[robot[NBR] + dart], robot[robot[BACK] + dart]
        there = add_edge_mark(robot[marks + far], far_exit, edge_mark(b, 2 if c == 1 else 0))
        here = add_edge_mark(here, (entry + a) % degree, edge_mark(b, c))
        if here < 0 or there < 0:
            robot[FAULT] = FAULT_KIT
            return
        robot[marks + far] = there
    elif kind == OP_TIE:
        here = with_thread(here, (entry + a) % degree, 0)
    else:
        here = with_thread(here, thread_of(here)[0], 1)
    robot[marks + v] = here
    robot[robot[COUNTS] + (DROPS if kind <= OP_EDGE else TIES if kind == OP_TIE else LEAVES)] += 1
    _log(robot, code)


@step
def fault(robot: np.ndarray) -> int:
    """The robot's fault (0: none): a kernel stops at the first."""
    return robot[FAULT]
