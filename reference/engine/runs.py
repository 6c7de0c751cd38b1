"""Runs of the compiled Algorithm 3.1: one world's arrays, many starts, one call (thesis §3.3, §7.2).

The world's side of the engine: it builds the compiled robot on a world's
arrays (:func:`topomark.proofs.world_arrays.to_arrays`, made once per world),
hands it to the compiled explorer (:mod:`.algorithm31`) from each start in
turn, and returns per start what the reference's
:class:`~topomark.reference.run.outcome.Outcome` says of an unchecked run:
what it claimed, the cost and its split by purpose, the marker operations and
the iteration and hypothesis counts (:class:`EngineRun`).  :func:`run_starts`
runs every start in one compiled call (the exhaustive search's path);
:func:`run_logged` runs one start keeping its actions, for the trace digest
(:mod:`.digest`) and the cross-check (:mod:`.compare`).

A start is a dart ``(vertex index, exit)``: the robot at that vertex facing that
exit, which plays the entry edge (:meth:`~topomark.spec.world.World.start_state`),
as :func:`~topomark.reference.worstcase.exhaustive.run_start` starts the
reference.

Examples
--------
>>> from topomark.reference.worlds.generators import cycle
>>> from topomark.proofs.world_arrays import to_arrays
>>> run = run_logged(to_arrays(cycle(4)), (0, 0), ("nearest", "fifo", "shortest"))
>>> run.claimed, run.cost, run.by_purpose, run.marker_operations
('correct', 4, {'new': 4}, {'drop': 1})
"""

from __future__ import annotations

import numpy as np

from topomark.proofs.world_arrays import WorldArrays

from topomark.reference.engine.algorithm31 import (CONFIRMED, HYPOTHESES, ITERATIONS, LOOP, NON_LOOP, OK, REJECTED,
                                                   new_scratch)
from topomark.reference.engine import footprint_runs
from topomark.reference.engine.compiled import kernel
from topomark.reference.engine.digest import digest
from topomark.reference.engine.enhanced import RECORDS, TECHNIQUES, explore_enhanced, new_enhanced
from topomark.reference.engine.lighthouses import explore_lighthouse, script
from topomark.reference.engine.mapstate import new_map
from topomark.reference.engine.robot import ACTIONS, COST, COUNTS, DROPS, LEAVES, TIES, log, make_robot, reset
from topomark.reference.engine.signature import EXITS
from topomark.reference.explorers.policies import EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES
from topomark.reference.explorers.robot import PURPOSES

__all__ = ["EngineRun", "policy_codes", "run_starts", "run_logged", "CODE_NAMES"]

CODE_NAMES = {0: "correct", 1: "e' not in U (Lemma 1, §3.4)", 2: "a self-loop or second edge (§3.1.1)",
              3: "the robot refused a motion or a drop", 4: "the map outgrew its buffers", 10: "failed", 11: "failed"}
"""Each outcome code of :mod:`.algorithm31` in words."""


class EngineRun:
    """What one compiled run did: the outcome code (0: U emptied) and the counts an unchecked
    :class:`~topomark.reference.run.outcome.Outcome` reports (``cost``, ``claimed``, ``by_purpose``,
    ``marker_operations``, ``counts``), read from the kernel's rows when asked; ``actions`` when logged."""

    __slots__ = ("code", "cost", "_counts", "_tallies", "actions")

    def __init__(self, code: int, counts: list[int], tallies: list[int], actions: np.ndarray | None = None):
        self.code, self.cost, self._counts, self._tallies, self.actions = code, counts[16], counts, tallies, actions

    def __repr__(self) -> str:
        return (f"EngineRun(code={self.code}, cost={self.cost}, by_purpose={self.by_purpose}, "
                f"marker_operations={self.marker_operations}, counts={self.counts})")

    @property
    def claimed(self) -> str:
        """What the run claims, as the reference's ``Outcome.claimed``: ``correct`` once U is empty."""
        return "correct" if self.code == OK else CODE_NAMES.get(self.code, f"code {self.code}")

    @property
    def by_purpose(self) -> dict[str, int]:
        """The traversals per purpose, the purposes moved for only, sorted by name (as the reference's)."""
        return dict(sorted((PURPOSES[p], k) for p, k in enumerate(self._counts[:len(PURPOSES)]) if k))

    @property
    def marker_operations(self) -> dict[str, int]:
        """The marker and thread operations made, sorted by name (as the reference's)."""
        made = (("drop", self._counts[DROPS]), ("leave", self._counts[LEAVES]), ("tie", self._counts[TIES]))
        return {op: k for op, k in made if k}

    @property
    def counts(self) -> dict[str, int]:
        """The iteration and hypothesis counts, named as the reference's outcome names them."""
        return dict(zip(_COUNT_NAMES, (self._tallies[k] for k in _COUNT_INDEX)))

    def digest(self) -> int | None:
        """The trace digest of the logged actions (None if not logged)."""
        return None if self.actions is None else digest(self.actions.tolist())


_COUNT_NAMES = ("iterations", "loop_iterations", "nonloop_iterations", "hypotheses", "hypotheses_rejected",
                "hypotheses_confirmed")
_COUNT_INDEX = (ITERATIONS, LOOP, NON_LOOP, HYPOTHESES, REJECTED, CONFIRMED)


def policy_codes(policies: tuple[str, str, str]) -> tuple[int, int, int]:
    """(edge, hypothesis, path) policy names as the kernel's integers; a name it does not run is a ValueError."""
    edge, hypothesis, path = policies
    return EDGE_POLICIES.index(edge), HYPOTHESIS_POLICIES.index(hypothesis), PATH_POLICIES.index(path)


def _sizes(arrays: WorldArrays) -> tuple[int, int, int]:
    """Buffer sizes: the explorer's map can need no more vertices, degree or entries of U than the world has."""
    degrees = np.diff(arrays.offsets)
    dcap = max(int(degrees.max(initial=1)), 1)
    if dcap >= EXITS - 1:
        raise ValueError(f"the engine senses places of degree < {EXITS - 1}, not {dcap} (engine.signature.EXITS)")
    return max(arrays.n, 1), dcap, max(2 * arrays.m, 1)


@kernel
def _run_all(robot: np.ndarray, starts: np.ndarray, rows: np.ndarray, edge: int, hypothesis: int, path: int, vcap: int,
             dcap: int, ucap: int, codes: np.ndarray, counts: np.ndarray, tallies: np.ndarray) -> None:
    S, W = new_map(vcap, dcap, ucap), new_scratch(vcap, ucap)
    for s in range(starts.shape[0]):
        reset(robot, starts[s, 0], starts[s, 1])
        codes[s] = explore_lighthouse(robot, S, W, rows, edge, hypothesis, path, tallies[s])
        counts[s, :16] = robot[robot[COUNTS]:robot[COUNTS] + 16]
        counts[s, 16] = robot[COST]


@kernel
def _run_enhanced(robot: np.ndarray, starts: np.ndarray, rows: np.ndarray, techniques: int, edge: int, hypothesis: int,
                  path: int, vcap: int, dcap: int, ucap: int, codes: np.ndarray, counts: np.ndarray,
                  tallies: np.ndarray) -> None:
    S, W = new_map(vcap, dcap, ucap), new_scratch(vcap, ucap)
    Q, T, R, X = new_enhanced(vcap, dcap, ucap, techniques & RECORDS != 0)
    for s in range(starts.shape[0]):
        reset(robot, starts[s, 0], starts[s, 1])
        codes[s] = explore_enhanced(robot, S, W, T, X, R, Q, rows, techniques, edge, hypothesis, path, tallies[s])
        counts[s, :16] = robot[robot[COUNTS]:robot[COUNTS] + 16]
        counts[s, 16] = robot[COST]


def _run(robot: np.ndarray, starts: np.ndarray, algorithm: str, lighthouse: str | None, policies: tuple[str, str, str],
         sizes: tuple[int, int, int], codes: np.ndarray, counts: np.ndarray, tallies: np.ndarray) -> None:
    """Every start of ``starts`` by ``algorithm``'s kernel (``basic``, or a composition of :mod:`.enhanced`)."""
    if algorithm == "basic":
        _run_all(robot, starts, script(lighthouse), *policy_codes(policies), *sizes, codes, counts, tallies)
    else:
        _run_enhanced(robot, starts, script(lighthouse), TECHNIQUES[algorithm], *policy_codes(policies), *sizes,
                      codes, counts, tallies)


def run_starts(arrays: WorldArrays, starts: list[tuple[int, int]], policies: tuple[str, str, str],
               lighthouse: str | None = None, algorithm: str = "basic") -> list[EngineRun]:
    """Every start of ``starts`` on the world of ``arrays``, in one compiled call, by ``algorithm``
    (:data:`~topomark.reference.engine.ENGINE_ALGORITHMS`) with ``lighthouse`` (None: Algorithm 3.1's directional
    vertex marker; :data:`~topomark.reference.engine.ENGINE_LIGHTHOUSES`), or a footprint search of §6.2.1
    (:mod:`.footprint_runs`, which uses no lighthouse)."""
    if algorithm in footprint_runs.CASES:
        return [EngineRun(*row) for row in footprint_runs.rows(algorithm, arrays, starts, policies)]
    if not starts:
        return []
    vcap, dcap, ucap = _sizes(arrays)
    robot = make_robot(arrays, 0, 0)
    codes = np.zeros(len(starts), dtype=np.int64)
    counts = np.zeros((len(starts), 17), dtype=np.int64)
    tallies = np.zeros((len(starts), 8), dtype=np.int64)
    _run(robot, np.array(starts, dtype=np.int64).reshape(-1, 2), algorithm, lighthouse, policies, (vcap, dcap, ucap),
         codes, counts, tallies)
    return [EngineRun(c, k, t) for c, k, t in zip(codes.tolist(), counts.tolist(), tallies.tolist())]


def run_logged(arrays: WorldArrays, start: tuple[int, int], policies: tuple[str, str, str],
               lighthouse: str | None = None, algorithm: str = "basic", log_size: int = 4096) -> EngineRun:
    """One start, its actions kept (the log grows until every action fits)."""
    if algorithm in footprint_runs.CASES:
        return EngineRun(*footprint_runs.logged(algorithm, arrays, start, policies, log_size))
    vcap, dcap, ucap = _sizes(arrays)
    while True:
        robot = make_robot(arrays, start[0], start[1], log_size)
        codes, counts = np.zeros(1, dtype=np.int64), np.zeros((1, 17), dtype=np.int64)
        tallies = np.zeros((1, 8), dtype=np.int64)
        _run(robot, np.array([start], dtype=np.int64), algorithm, lighthouse, policies, (vcap, dcap, ucap), codes,
             counts, tallies)
        kept = log(robot)
        if int(robot[ACTIONS]) <= log_size:
            return EngineRun(int(codes[0]), counts[0].tolist(), tallies[0].tolist(), kept.copy())
        log_size = int(robot[ACTIONS])
