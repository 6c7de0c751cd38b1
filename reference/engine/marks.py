"""The compiled robot's undirected markers: a kit, drops on edges and at places, and what is sensed of them
(thesis §6.2.1, §3.1.1–3.1.2).

The robot of :mod:`.robot` carries one directional vertex marker (the
lighthouse of §3.3).  The footprint searches of §6.2.1 (:mod:`.footprints`)
drop undirected markers instead — E-markers on the edge the robot entered by,
V-markers where it stands — from a kit of so many vertex, edge and
vertex-or-edge markers (:class:`~topomark.spec.kit.Kit`).  This module keeps
them beside the robot in a second int64 array, the *marks*: the kit's
markers left (its own per kind, then the vertex-or-edge pool, drawn as
:meth:`~topomark.spec.kit.Kit.draw` draws them, own kind first), the markers
lying on each dart of the world (an edge marker shows at both ends, so it is
counted on both darts) and at each place.  Like :mod:`.robot` it reads the
world's arrays; the explorer kernel passes the robot and the marks to these
functions only and never looks inside.

A drop costs nothing and is counted and logged as the reference's simulator
does (§3.1.2; the action codes of :mod:`.digest`).  A drop the kit cannot
cover changes nothing and returns False: the reference's robot refuses it
(:class:`~topomark.spec.errors.OutOfMarkers`) before anything changes.

Examples
--------
>>> from topomark.spec.world import World
>>> from topomark.proofs.world_arrays import to_arrays
>>> from topomark.reference.engine.robot import make_robot, move
>>> arrays = to_arrays(World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}))
>>> r, k = make_robot(arrays, 0, 0), new_marks(arrays, 0, 2, 0)
>>> move(r, 0, 1), drop_edge(r, k, 0, 2), drop_edge(r, k, 1, 1), drop_place(r, k)
((2, 0), True, False, False)
>>> out = np.zeros(2, dtype=np.int64); sensed_edges(r, k, out); out.tolist(), place_marks(r, k)
([2, 0], 0)
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.world_arrays import WorldArrays

from topomark.reference.engine.compiled import kernel, step
from topomark.reference.engine.robot import BACK, COUNTS, CUR, DROPS, ENTRY, NBR, OFFSETS, log_action
from topomark.reference.engine.digest import pack_op

__all__ = ["new_marks", "reset_marks", "drop_edge", "drop_place", "sensed_edges", "place_marks", "KIT_VERTEX",
           "KIT_EDGE", "KIT_EITHER"]

KIT_VERTEX, KIT_EDGE, KIT_EITHER, DARTS, PLACES, HEADER = 0, 1, 2, 3, 4, 8
"""Header entries: the kit's vertex, edge and vertex-or-edge markers left; where the per-dart and per-place
counts begin."""

_pack_op = step(pack_op)


def new_marks(arrays: WorldArrays, vertex: int, edge: int, either: int) -> np.ndarray:
    """The marks of a robot on ``arrays`` with a kit of ``vertex``, ``edge`` and ``either`` markers, none dropped."""
    marks = np.zeros(HEADER + len(arrays.nbr) + arrays.n, dtype=np.int64)
    marks[DARTS], marks[PLACES] = HEADER, HEADER + len(arrays.nbr)
    reset_marks(marks, vertex, edge, either)
    return marks


@kernel
def reset_marks(marks: np.ndarray, vertex: int, edge: int, either: int) -> None:
    """No marker dropped; the kit full again."""
    marks[HEADER:] = 0
    marks[KIT_VERTEX], marks[KIT_EDGE], marks[KIT_EITHER] = vertex, edge, either


@step
def _draw(marks: np.ndarray, kind: int, count: int) -> bool:
    """Take ``count`` markers of ``kind`` from the kit, its own first, then the pool; False (nothing taken) if
    the kit cannot cover them."""
    own = min(count, marks[kind])
    if count - own > marks[KIT_EITHER]:
        return False
    marks[kind] -= own
    marks[KIT_EITHER] -= count - own
    return True


@step
def _dropped(robot: np.ndarray, code: int) -> None:
    robot[robot[COUNTS] + DROPS] += 1
    log_action(robot, code)


@step
def drop_edge(robot: np.ndarray, marks: np.ndarray, exit_: int, count: int) -> bool:
    """Drop ``count`` undirected edge markers on relative exit ``exit_`` where the robot stands (both ends of
    the edge show them); False if the kit cannot cover them."""
    v = robot[CUR]
    first = robot[robot[OFFSETS] + v]
    dart = first + (robot[ENTRY] + exit_) % (robot[robot[OFFSETS] + v + 1] - first)
    if not _draw(marks, KIT_EDGE, count):
        return False
    far = robot[robot[OFFSETS] + robot[robot[NBR] + dart]] + robot[robot[BACK] + dart]
    marks[marks[DARTS] + dart] += count
    marks[marks[DARTS] + far] += count
    _dropped(robot, _pack_op(0, 1, count, exit_ + 1, 0))
    return True


@step
def drop_place(robot: np.ndarray, marks: np.ndarray) -> bool:
    """Drop one undirected vertex marker where the robot stands; False if the kit has none left."""
    if not _draw(marks, KIT_VERTEX, 1):
        return False
    marks[marks[PLACES] + robot[CUR]] += 1
    _dropped(robot, _pack_op(0, 0, 1, 0, 0))
    return True


@step
def sensed_edges(robot: np.ndarray, marks: np.ndarray, out: np.ndarray) -> None:
    """The edge markers sensed where the robot stands: ``out[l]``, the count on relative exit ``l``."""
    v = robot[CUR]
    first = robot[robot[OFFSETS] + v]
    degree = robot[robot[OFFSETS] + v + 1] - first
    for p in range(degree):
        out[p] = marks[marks[DARTS] + first + (robot[ENTRY] + p) % degree]


@step
def place_marks(robot: np.ndarray, marks: np.ndarray) -> int:
    """The vertex markers sensed where the robot stands."""
    return marks[marks[PLACES] + robot[CUR]]
