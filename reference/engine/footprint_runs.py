"""Runs of the compiled footprint searches of §6.2.1: one world's arrays, many starts, one call (thesis §6.2.1,
§7.2).

:mod:`.runs` for :mod:`.footprints`: the robot (:mod:`.robot`) and its
undirected markers (:mod:`.marks`) are built on the world's arrays once, the
kit each start begins with is the one the algorithm's registration gives the
world (:meth:`~topomark.reference.algorithms.algorithm_spec.AlgorithmSpec.kit_for`,
no ``--markers``: what ``topomark worst-case`` runs), and each start's run is
reported as the rows :class:`~.runs.EngineRun` reads (:func:`~.runs.run_starts`
and :func:`~.runs.run_logged` call :func:`rows` and :func:`logged` for these
algorithms), as the reference's unchecked
:class:`~topomark.reference.run.outcome.Outcome` reports it.  Only the edge
policy applies (Case 4 chooses the nearest edge whatever it is given, as its
reference does).

Examples
--------
>>> from topomark.reference.worlds.generators import cycle
>>> from topomark.proofs.world_arrays import to_arrays
>>> code, counts, tallies, actions = logged("case-2", to_arrays(cycle(4)), (0, 0), ("nearest", "fifo", "shortest"))
>>> code, counts[16], len(actions), tallies[:3]
(0, 8, 12, [4, 1, 3])
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.world_arrays import WorldArrays

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.engine.algorithm31 import new_scratch
from topomark.reference.engine.compiled import kernel
from topomark.reference.engine.footprints import CASES, explore, new_footprint_scratch
from topomark.reference.engine.mapstate import new_map
from topomark.reference.engine.marks import new_marks, reset_marks
from topomark.reference.engine.robot import ACTIONS, COST, COUNTS, log, make_robot, reset
from topomark.reference.explorers.policies import EDGE_POLICIES

__all__ = ["kit_of", "rows", "logged"]


def kit_of(algorithm: str, arrays: WorldArrays) -> tuple[int, int, int]:
    """The (vertex, edge, vertex-or-edge) markers the registration of ``algorithm`` gives the robot on this world."""
    kit = algorithm_spec(algorithm).kit_for(arrays.n, arrays.m, {})
    return kit.vertex, kit.edge, kit.either


def _sizes(arrays: WorldArrays) -> tuple[int, int, int]:
    """Buffer sizes: the map can need no more vertices, degree or entries of U than the world has."""
    return max(arrays.n, 1), max(int(np.diff(arrays.offsets).max(initial=1)), 1), max(2 * arrays.m, 1)


@kernel
def _run_all(robot: np.ndarray, marks: np.ndarray, kit: tuple, starts: np.ndarray, case: int, edge: int,
             sizes: tuple, codes: np.ndarray, counts: np.ndarray, tallies: np.ndarray) -> None:
    vcap, dcap, ucap = sizes
    S, W, F = new_map(vcap, dcap, ucap), new_scratch(vcap, ucap), new_footprint_scratch(vcap, dcap)
    for s in range(starts.shape[0]):
        reset(robot, starts[s, 0], starts[s, 1])
        reset_marks(marks, kit[0], kit[1], kit[2])
        codes[s] = explore(robot, marks, S, W, F, case, edge, tallies[s])
        counts[s, :16] = robot[robot[COUNTS]:robot[COUNTS] + 16]
        counts[s, 16] = robot[COST]


def _call(algorithm: str, arrays: WorldArrays, starts: list[tuple[int, int]], policies: tuple[str, str, str],
          log_size: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    kit = kit_of(algorithm, arrays)
    robot, marks = make_robot(arrays, 0, 0, log_size), new_marks(arrays, *kit)
    codes, counts = np.zeros(len(starts), dtype=np.int64), np.zeros((len(starts), 17), dtype=np.int64)
    tallies = np.zeros((len(starts), 8), dtype=np.int64)
    _run_all(robot, marks, kit, np.array(starts, dtype=np.int64).reshape(-1, 2), CASES[algorithm],
             EDGE_POLICIES.index(policies[0]), _sizes(arrays), codes, counts, tallies)
    return robot, codes, counts, tallies


def rows(algorithm: str, arrays: WorldArrays, starts: list[tuple[int, int]],
         policies: tuple[str, str, str]) -> list[tuple[int, list[int], list[int]]]:
    """Every start of ``starts`` on the world of ``arrays`` by the footprint search ``algorithm``, in one call:
    per start its outcome code, its counts (traversals per purpose, drops, cost) and its tallies."""
    if not starts:
        return []
    _, codes, counts, tallies = _call(algorithm, arrays, starts, policies, 0)
    return list(zip(codes.tolist(), counts.tolist(), tallies.tolist()))


def logged(algorithm: str, arrays: WorldArrays, start: tuple[int, int], policies: tuple[str, str, str],
           log_size: int = 4096) -> tuple[int, list[int], list[int], np.ndarray]:
    """One start, its actions kept (the log grows until every action fits): :func:`rows`'s row and the actions."""
    while True:
        robot, codes, counts, tallies = _call(algorithm, arrays, [start], policies, log_size)
        if int(robot[ACTIONS]) <= log_size:
            return int(codes[0]), counts[0].tolist(), tallies[0].tolist(), log(robot).copy()
        log_size = int(robot[ACTIONS])
