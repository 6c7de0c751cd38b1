"""One seeded fault per named check: each violates exactly that check, and the checker must say so.

Every check an algorithm's registry entry can name
(:data:`~topomark.reference.algorithms.algorithm_spec.CHECKS`) has here at
least one fault — an explorer with one mistake, or an entry whose stated
bound its explorer does not keep — and a small world on which it shows.
``tests/test_every_check_can_fail.py`` asserts that the
:class:`~topomark.reference.run.checker.Checker` reports exactly that check,
at the iteration named below, and that with the check disabled
(:func:`disable`) the fault goes undetected: the run is then verified, or
ends with the later check named in the last column.  ``docs/checks.md``
keeps the same table with the thesis references each check states.

==============  =============================  ==================  ====  ===========================
check           fault                          reported as         it.   check disabled: the run
==============  =============================  ==================  ====  ===========================
pose            ReportsStalePosition           position            1     verified
I-1             ReportsWrongLighthouseHead     I-1                 1     verified
I-2             ReportsBeforeRemovingFarEnd    I-2                 4     verified
bound-function  SpinsOnce                      bound function      2     verified
lemma-1         ListsAHypothesisTwice          Lemma 1             5     verified
marker          DropsItsSpareMarker            immovable marker    1     verified
marker-budget   ThesisCase4Bound (case-4)      marker budget       5     verified
marker-budget   OneMarkerTooMany (case-3a)     marker budget       1     verified
cost-bound      OneTraversalTooMany            cost bound          1     verified
models          ReportsNoModelsOnce            models              2     verified
iterations      CountsMarkerLoopsAsNonLoop     iteration count     5     verified
isomorphism     StopsAtTwoEntries              termination         4     iteration count
isomorphism     MarksMapWhenDone               extended isomorph.  5     verified
==============  =============================  ==================  ====  ===========================

The transient faults (pose, I-1, I-2) leave the explorer's public state wrong
only while it reports one iteration, as an explorer that reports before
finishing its bookkeeping would: the run is otherwise correct, so only that
check can see it.  Worlds: :data:`KITE` (K4 less one edge, 4 places, 5
edges: three non-loop iterations, a loop closed by the lighthouse, a loop
closed by a confirmed hypothesis) for Algorithm 3.1 and ``case-4``;
``lattice(2, 3)`` for the model tree, where several models are live; :data:`EDGE`
(one edge, where Algorithm 3.1's cost meets (3.1)+(3.2) = 1 exactly and Case 3a
marks both places with Σ_{k=1}^{2} k = 3 markers, its marker bound).
"""

from __future__ import annotations

from abc import ABC, abstractmethod

import copy
from dataclasses import dataclass, field, replace
from typing import Any, Callable

from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.explorers.algorithm31 import V0, LighthouseExplorer
from topomark.reference.explorers.counted_markers import VertexCounts
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse
from topomark.reference.explorers.model_tree import ModelTreeExplorer
from topomark.reference.run import checker as checker_module
from topomark.reference.run.checker import Checker
from topomark.reference.run.explore import Outcome, explore
from topomark.reference.worlds import generators
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.world import Start, World

__all__ = ["KITE", "EDGE", "REPORTS", "SEEDED", "Seeded", "disable"]

KITE = World({"0": ["1", "2", "3"], "1": ["0", "2"], "2": ["0", "1", "3"], "3": ["0", "2"]}, (), Start("0", "1"))
"""K4 less the edge 1-3, from 0 facing 1: Algorithm 3.1 explores 0-1, 1-2, 2-3 (non-loop), 3-0 (a loop closed
by the lighthouse) and 0-2 (a loop closed by its one hypothesis)."""

EDGE = World({"0": ["1"], "1": ["0"]}, (), Start("0", "1"))
"""One edge: Algorithm 3.1 crosses it once, its whole bound (3.1)+(3.2) at n = 2, m = 1; Case 3a drops 1 marker
at 0 and 2 at 1, Σ_{k=1}^{2} k = 3, its whole marker bound."""

REPORTS: dict[str, tuple[str, ...]] = {
    "pose": ("position",),
    "I-1": ("I-1",),
    "I-2": ("I-2",),
    "bound-function": ("bound function",),
    "lemma-1": ("Lemma 1",),
    "marker": ("immovable marker",),
    "marker-budget": ("marker budget",),
    "cost-bound": ("cost bound",),
    "models": ("models",),
    "iterations": ("iteration count",),
    "isomorphism": ("termination", "extended isomorphism"),
}
"""Each check's name in ``CHECKS`` ↦ the names its violations carry (``Violation.check``, as traces show them)."""


# -- Algorithm 3.1 explorers with one mistake each -------------------------------------------------------------

class _Transient(LighthouseExplorer, ABC):
    """Leaves its public state wrong (``tamper``) while one iteration (``due``) is reported, and puts it right
    as soon as the report is done: the exploration itself stays correct."""

    _undo: Callable[[], None] | None = None

    def due(self, it) -> bool:
        return it.number == 1

    @abstractmethod
    def tamper(self, it) -> Callable[[], None]:
        """Put the public state wrong for iteration ``it``; return what puts it right again."""

    def after_join(self, it) -> None:  # the last hook before the iteration is reported
        super().after_join(it)
        if self.due(it):
            self._undo = self.tamper(it)

    def step(self):
        it = super().step()
        undo, self._undo = self._undo, None
        if undo is not None:
            undo()
        return it


class ReportsStalePosition(_Transient):
    """pose: reports iteration 1 while still believing it stands where it set out from (v_k, by e)."""

    def tamper(self, it):
        position, self.position = self.position, it.edge
        return lambda: setattr(self, "position", position)


class ReportsWrongLighthouseHead(_Transient):
    """I-1: S shows the lighthouse at v0 pointing one exit clockwise of where it points while iteration 1 is
    reported (S is then not extended-isomorphic to G_s: markers are not preserved)."""

    def tamper(self, it):
        mark = self.S.vertex_mark(V0)
        self.S.mark_vertex(V0, mark.count, (mark.head + 1) % self.S.degree(V0))
        return lambda: self.S.mark_vertex(V0, mark.count, mark.head)


class ReportsBeforeRemovingFarEnd(_Transient):
    """I-2: reports its first loop iteration before removing e' from U (line 25 done late)."""

    def due(self, it):
        return it.kind == "loop" and not any(done.kind == "loop" for done in self.iterations)

    def tamper(self, it):
        far = it.joined[1]
        self.S.unexplored.append(far)
        return lambda: self.S.unexplored.remove(far)


class SpinsOnce(LighthouseExplorer):
    """bound-function: spends iteration 2 going out along its entry edge and back, adding nothing to S, so
    t = |E_G| − |E_S| does not decrease — an explorer that can loop past the bound, here only once."""

    def step(self):
        if len(self.iterations) != 1:
            return super().step()
        it = self.iteration_type(len(self.iterations) + 1, self.position)
        self.robot.move(0, "travel")
        self.robot.move(0, "travel")
        self.iterations.append(it)
        if self.observer is not None:
            self.observer(self, it)
        return it


class ListsAHypothesisTwice(LighthouseExplorer):
    """lemma-1: H lists its first hypothesis twice (the copy is walked only if the first is rejected, and then
    rejected again), so two hypotheses share (M, P^E)."""

    def hypotheses(self, it, sig):
        found = super().hypotheses(it, sig)
        return found + [copy.copy(found[0])] if found else found


class DropsItsSpareMarker(LighthouseExplorer):
    """marker: carries a second directional marker and drops it at the first new place (recording it in S,
    so S still shows the world): the lighthouse kit must stay as it was dropped at the start."""

    def after_non_loop(self, it):
        super().after_non_loop(it)
        if it.number == 1:
            self.robot.operate(MarkerOp("vertex", direction=0))  # pointing back along the entry edge
            u, entry = self.position
            self.S.mark_vertex(u, 1, entry)


SPARE = replace(LIGHTHOUSES["directional-vertex"], kit=Kit(vertex=2, directional=True))
"""The directional-vertex lighthouse with one marker more in the kit than the lighthouse drops."""


class CountsMarkerLoopsAsNonLoop(LighthouseExplorer):
    """iterations: records a loop closed by the lighthouse as a non-loop iteration."""

    def loop_augment(self, it, far, by_marker=False):
        super().loop_augment(it, far, by_marker)
        if by_marker:
            it.kind = "non-loop"


class StopsAtTwoEntries(LighthouseExplorer):
    """isomorphism (termination): stops when U holds two entries, taking them for the two darts of one last
    edge without exploring it (line 4's test is ``U`` empty)."""

    def done(self):
        return len(self.S.unexplored) in (0, 2)


class MarksMapWhenDone(LighthouseExplorer):
    """isomorphism (the map): once U is empty, writes into S a vertex marker at its newest place, which it
    never sensed (no iteration is reported after it, so only the final verdict can see it)."""

    def done(self):
        finished = super().done()
        if finished and self.S.vertex_mark(self.S.n - 1) is None:
            self.S.mark_vertex(self.S.n - 1)
        return finished


class OneTraversalTooMany(LighthouseExplorer):
    """cost-bound: once U is empty, crosses one more edge before it stops — one traversal past the bound where
    the bound is tight (no iteration is reported after it, so only the end-of-run checks can see it)."""

    def done(self):
        finished = super().done()
        if finished and not getattr(self, "_extra", False):
            self._extra = True
            self.robot.move(0, "travel")
        return finished


class OneMarkerTooMany(VertexCounts):
    """marker-budget: gives each new place one marker more than Case 3a's count (i + 1 for the i-th; the counts
    stay unique, so the map stays right): on one edge, 1 + 3 markers where Σ_{k=1}^{2} k = 3 are stated."""

    def mark_op(self, count: int) -> MarkerOp:
        return super().mark_op(count + 1 if self.count_of else count)


class ReportsNoModelsOnce(ModelTreeExplorer):
    """models: hands the checker an empty list of live models after step 2 (as one that reports while it
    rebuilds the list would); before and after, its models are right."""

    def models(self):
        return [] if len(self.iterations) == 2 else super().models()


def thesis_case_4_bound(n: int, m: int) -> int:
    """Case 4's marker bound as §6.2.1 states it, m − ⌊n/2⌋: one short of what the explorer needs for even n
    (the registry states the corrected m − ⌊(n−1)/2⌋)."""
    return m - n // 2


# -- the table ------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Seeded:
    """A seeded fault of ``check``: ``fault`` run like the registered ``like`` (``changes``: fields of the
    entry replaced), on ``world``.  The checker must report ``reports`` at iteration ``iteration``, its message
    carrying each of ``says``; with the check disabled the run is verified (``unchecked`` None) or ends with
    the violation named ``unchecked``."""

    check: str
    name: str
    fault: type | None
    reports: str
    iteration: int
    says: tuple[str, ...]
    unchecked: str | None = None
    like: str = "basic"
    world: World = KITE
    options: dict[str, Any] = field(default_factory=dict)
    lighthouse: Lighthouse | None = None
    changes: dict[str, Any] = field(default_factory=dict)

    def spec(self) -> AlgorithmSpec:
        """The faulty entry: the registered one with the fault's explorer (an explorer under test) and changes."""
        spec = algorithm_spec(self.like)
        if self.fault is not None:
            spec = replace(spec, explorer=self.fault)
        return replace(spec, name=self.name, own=False, **self.changes)

    def run(self, mode: str = "incremental", record: bool = True) -> Outcome:
        return explore(self.world, self.spec(), check_mode=mode, record=record, lighthouse=self.lighthouse,
                       options=self.options)


SEEDED: tuple[Seeded, ...] = (
    Seeded("pose", "ReportsStalePosition", ReportsStalePosition, "position", 1,
           ("map dart (0, 0)", "the explorer does not know where it is")),
    Seeded("I-1", "ReportsWrongLighthouseHead", ReportsWrongLighthouseHead, "I-1", 1,
           ("markers are not preserved", "pointing at exit")),
    Seeded("I-2", "ReportsBeforeRemovingFarEnd", ReportsBeforeRemovingFarEnd, "I-2", 4,
           ("U entry (0, 2)", "an unexplored edge", "already explored")),
    Seeded("bound-function", "SpinsOnce", SpinsOnce, "bound function", 2,
           ("t = |E_G| - |E_S|", "0 <= t < 4", "found 4")),
    Seeded("lemma-1", "ListsAHypothesisTwice", ListsAHypothesisTwice, "Lemma 1", 5,
           ("hypotheses (2, 2) and (2, 2)", "distinct (M, P^E) pairs")),
    Seeded("marker", "DropsItsSpareMarker", DropsItsSpareMarker, "immovable marker", 1,
           ("world markers and thread", "VertexMarker(at='1', count=1, points_to='0')"), lighthouse=SPARE),
    Seeded("marker-budget", "ThesisCase4Bound", None, "marker budget", 5,
           ("at most 3 (the algorithm's stated bound: m − ⌊(n−1)/2⌋", "at n = 4, m = 5", "found 4"), like="case-4",
           changes={"marker_bound_fn": thesis_case_4_bound}),
    Seeded("marker-budget", "OneMarkerTooMany", OneMarkerTooMany, "marker budget", 1,
           ("at most 3 (the algorithm's stated bound: Σ_{k=1}^{n−1} k undirected V-markers (Σ_{k=1}^{n} k",
            "at n = 2, m = 1", "found 4"), like="case-3a", world=EDGE, options={"markers": 4}),
    Seeded("cost-bound", "OneTraversalTooMany", OneTraversalTooMany, "cost bound", 1,
           ("edge traversals", "at most 1 = (3.1)+(3.2)", "§3.5.2", "at n = 2, m = 1", "found 2"), world=EDGE),
    Seeded("models", "ReportsNoModelsOnce", ReportsNoModelsOnce, "models", 2,
           ("step 2", "the true world among the live models", "none of 0 live model(s)"), like="model-tree",
           world=generators.lattice(2, 3).with_start(None), options={"window": 1}),
    Seeded("iterations", "CountsMarkerLoopsAsNonLoop", CountsMarkerLoopsAsNonLoop, "iteration count", 5,
           ("non-loop iterations", "expected 3, found 4")),
    Seeded("isomorphism", "StopsAtTwoEntries", StopsAtTwoEntries, "termination", 4,
           ("at U", "expected empty", "[(0, 1), (2, 2)]"), unchecked="iteration count"),
    Seeded("isomorphism", "MarksMapWhenDone", MarksMapWhenDone, "extended isomorphism", 5,
           ("vertex 3 (image '3')", "markers are not preserved")),
)


def disable(monkeypatch, check: str) -> None:
    """Make ``check`` always pass, as if its condition were replaced by ``True``.

    Every verdict of the checker that fails reaches :meth:`Checker._fail`; the patched one lets a violation
    named by ``REPORTS[check]`` pass as holding (``_ok`` then counts it passed), and raises every other.  The
    check's computation runs unchanged (I-1's φ is still built, U still counted), so the other checks see the
    same run.  With ``isomorphism`` disabled there may be no witness to re-verify: none is then re-verified.
    """
    names = REPORTS[check]
    fail = Checker._fail

    def _fail(self, it, violation):
        if violation.check not in names:
            fail(self, it, violation)

    monkeypatch.setattr(Checker, "_fail", _fail)
    if check == "isomorphism":
        verify = checker_module.verify_witness
        monkeypatch.setattr(checker_module, "verify_witness",
                            lambda S, world, witness: None if witness is None else verify(S, world, witness))
