"""The compiled robot: the world's arrays, the true pose, motions, perceptions and marker drops (thesis §3.1.1–3.1.2).

The engine's counterpart of :class:`~topomark.reference.run.simulator.Simulator`
behind a :class:`~topomark.reference.explorers.robot.Robot`: this module is the
only engine code that reads a world's arrays
(:func:`topomark.proofs.world_arrays.to_arrays`).  A *robot* is a tuple

``(offsets, nbr, back, state, counts, log)``

holding the world (``offsets``, ``nbr``, ``back``) and the run's truth and
accounting (``state``: the true vertex and entry exit, where the directional
marker lies, the cost, the number of actions, a fault; ``counts``: the
traversals per purpose and the marker drops; ``log``: the action codes of
:mod:`.digest`, as many as it has room for).  An explorer kernel is handed the
tuple and passes it only to :func:`move`, :func:`sense` and :func:`drop_vertex`,
which return what the reference robot returns, as two integers: the degree
sensed and the relative direction of the directional marker there (§3.1.1,
Figure 3.2: ``(head - entry) mod deg``), or -1 where there is none — the
signature ``[deg,A,A]`` or ``[deg,V-dir,A]``, all a world with one directional
vertex marker can show.

Accounting as the simulator's (§3.1.2): every traversal costs one, counted
under its purpose; a drop costs nothing and is counted apart.  A motion that
names no exit, or a second drop from a kit of one marker, is a fault
(:data:`FAULT_MOTION`, :data:`FAULT_KIT`) and the move does nothing: the
reference raises there (a failed check of the robot interface, or
:class:`~topomark.spec.errors.OutOfMarkers`), so the kernel must stop.

Examples
--------
>>> from topomark.spec.world import World
>>> from topomark.proofs.world_arrays import to_arrays
>>> r = make_robot(to_arrays(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]})), 0, 0, 8)
>>> drop_vertex(r, 0); sense(r)
(2, 0)
>>> move(r, 1, PURPOSE_NEW), move(r, 1, PURPOSE_NEW), move(r, 1, PURPOSE_NEW)
((2, -1), (2, -1), (2, 1))
>>> int(r[3][COST]), [describe(int(c)) for c in r[5][:2]]
(3, ['drop 1 vertex marker(s) pointing at relative exit 0', 'move 1 (new)'])
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.world_arrays import WorldArrays

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.digest import PURPOSE, describe, move_code, pack_op

__all__ = ["make_robot", "reset", "move", "sense", "drop_vertex", "fault", "CUR", "ENTRY", "MARKER_AT", "MARKER_HEAD", "COST",
           "ACTIONS", "FAULT", "FAULT_MOTION", "FAULT_KIT", "DROPS", "PURPOSE_TRAVEL", "PURPOSE_NEW",
           "PURPOSE_VALIDATION", "PURPOSE_RETRACE", "describe"]

CUR, ENTRY, MARKER_AT, MARKER_HEAD, COST, ACTIONS, FAULT = range(7)
"""Indices of ``state``: the true vertex and entry, the marker's vertex (-1: not dropped) and world exit, the cost,
the number of actions, the fault (0: none)."""
FAULT_MOTION, FAULT_KIT = 1, 2
DROPS = 15
"""Index of ``counts`` holding the marker drops (0..14: the traversals per purpose index)."""
PURPOSE_TRAVEL, PURPOSE_NEW = PURPOSE["travel"], PURPOSE["new"]
PURPOSE_VALIDATION, PURPOSE_RETRACE = PURPOSE["validation"], PURPOSE["retrace"]

_move_code = kernel(move_code)
_pack_op = kernel(pack_op)


def make_robot(arrays: WorldArrays, vertex: int, facing: int, log_size: int = 0) -> tuple:
    """A robot on ``arrays`` at vertex index ``vertex``, its faced exit ``facing`` playing the entry edge
    (:meth:`~topomark.spec.world.World.start_state`), keeping the first ``log_size`` action codes."""
    state = np.zeros(7, dtype=np.int64)
    state[CUR], state[ENTRY], state[MARKER_AT] = vertex, facing, -1
    return (arrays.offsets, arrays.nbr, arrays.back, state, np.zeros(16, dtype=np.int64),
            np.zeros(log_size, dtype=np.int64))


@kernel
def reset(robot: tuple, vertex: int, facing: int) -> None:
    """Put ``robot`` back at a fresh start on the same world: no marker dropped, nothing counted or logged."""
    state, counts = robot[3], robot[4]
    state[:] = 0
    counts[:] = 0
    state[CUR], state[ENTRY], state[MARKER_AT] = vertex, facing, -1


@step
def _log(robot: tuple, code: int) -> None:
    state, log = robot[3], robot[5]
    if state[ACTIONS] < log.shape[0]:
        log[state[ACTIONS]] = code
    state[ACTIONS] += 1


@step
def sense(robot: tuple) -> tuple:
    """What the robot senses where it stands: (degree, the marker's relative direction or -1)."""
    offsets, state = robot[0], robot[3]
    v = state[CUR]
    degree = offsets[v + 1] - offsets[v]
    if v != state[MARKER_AT]:
        return degree, -1
    return degree, (state[MARKER_HEAD] - state[ENTRY]) % degree


@step
def move(robot: tuple, motion: int, purpose: int) -> tuple:
    """Leave through exit ``motion`` counted clockwise from the entry edge, for ``purpose`` (its index); what is
    sensed at the far end.  A motion naming no exit sets :data:`FAULT_MOTION`, moves nothing, returns (0, -1)."""
    offsets, nbr, back, state, counts = robot[0], robot[1], robot[2], robot[3], robot[4]
    v = state[CUR]
    degree = offsets[v + 1] - offsets[v]
    if motion < 0 or motion >= degree:
        state[FAULT] = FAULT_MOTION
        return 0, -1
    dart = offsets[v] + (state[ENTRY] + motion) % degree
    state[CUR], state[ENTRY] = nbr[dart], back[dart]
    state[COST] += 1
    counts[purpose] += 1
    _log(robot, _move_code(motion, purpose))
    return sense(robot)


@kernel
def drop_vertex(robot: tuple, direction: int) -> None:
    """Drop the kit's one directional vertex marker here, pointing at relative exit ``direction`` (§3.3); a
    second drop sets :data:`FAULT_KIT` (the kit holds one)."""
    offsets, state, counts = robot[0], robot[3], robot[4]
    if state[MARKER_AT] >= 0:
        state[FAULT] = FAULT_KIT
        return
    v = state[CUR]
    state[MARKER_AT], state[MARKER_HEAD] = v, (state[ENTRY] + direction) % (offsets[v + 1] - offsets[v])
    counts[DROPS] += 1
    _log(robot, _pack_op(0, 0, 1, 0, direction + 3))


@step
def fault(robot: tuple) -> int:
    """The robot's fault (0: none): a kernel stops at the first."""
    return robot[3][FAULT]
