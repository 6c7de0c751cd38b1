"""Where a run's cost goes: its edge traversals split by loop iteration and by kind of walk (thesis §3.5.2).

§3.5.2 bounds Algorithm 3.1's cost by adding what each iteration spends: the
walk in S to v_k (line 6), the new edge e (line 7), and for each hypothesis
h' its validation walk M (lines 11–16) and, when rejected, the retrace back
to v_u (line 17) — (3.1) for the non-loop iterations, (3.2) for the loop
ones.  :class:`CostBreakdown` measures the same split on a run: each motion's
*kind* is the purpose the explorer tagged it with
(:data:`~topomark.reference.explorers.robot.PURPOSES`), and the validation
motions are further split by the outcome of the hypothesis they tested —
case (1), rejected before the end of M; case (2), rejected at its end; case
(3), confirmed — from the motions each hypothesis record says the robot made
for it (``walked``; a hypothesis rejected without motion, Chapter 4's
techniques, made none).

The split is taken per iteration from the simulator's own per-purpose count
(:attr:`~topomark.reference.run.simulator.Simulator.by_purpose`), read once the
explorer has started and after every iteration: nothing is added to a move, so a run costs what it cost
before.  Row 0 is the start (the lighthouse set up, §3.3, §5.1); a last
row ``end`` holds any motion made after the last iteration.

``topomark explore --json`` always carries the per-kind totals
(``cost_breakdown``: ``cost`` and ``by_kind``, a dozen numbers); the rows, one
per iteration, only with ``--breakdown``, as lists under ``columns`` — they
grow with m.  ``--breakdown-plot`` draws them.

It must add up: the hypotheses' validation motions never exceed the
validation motions the robot made in their iteration, and the rows sum to the
run's cost — otherwise topomark's own accounting disagrees with itself
(:class:`TopomarkFault`, exit 3).

Examples
--------
>>> from topomark.reference.worlds.generators import generate
>>> from topomark.reference.run.explore import explore
>>> o = explore(generate("cycle", n=5), "basic", record=False)
>>> b = o.breakdown
>>> sum(b.by_kind().values()) == o.cost
True
>>> b.by_kind()["new"] == o.m
True
"""

from __future__ import annotations

from typing import Any, Mapping

from topomark.spec.errors import TopomarkFault

__all__ = ["CostBreakdown", "KINDS", "COLUMNS", "CASES"]

CASES = ("case 1", "case 2", "case 3")
"""The outcomes of a tested hypothesis (Algorithm 3.1 lines 13–20)."""

KINDS = ("travel", "new", "validation case 1", "validation case 2", "validation case 3", "validation other",
         "retrace", "expansion", "establish", "probe", "drop", "other")
"""The kinds of walk, in the order the JSON and the plot list them: ``travel`` the walk in S to v_k (line 6),
``new`` the edge e (line 7), ``validation case N`` the validation walks of hypotheses that ended in case (N),
``validation other`` validation motions no hypothesis record accounts for (an explorer whose records keep no
hypotheses), ``retrace`` the walks back to v_u (line 17), ``expansion`` Chapter 4's expansion of places (§4.2),
``establish``/``probe``/``drop`` the lighthouse's and the markers' motions (§5.1, §6.1), ``other`` the rest."""

COLUMNS = ("iteration", "augmentation", "hypotheses", *KINDS)
"""A row of :meth:`CostBreakdown.rows`: the iteration (0: the start), how S grew (``start``, ``non-loop``,
``loop``, ``marker`` — a loop closed by the lighthouse itself — or ``end``), the hypotheses made, and the
motions of each kind."""


class CostBreakdown:
    """The cost of one run split by iteration and kind; fed the simulator's per-purpose counter after every
    iteration (:meth:`after_iteration`) and at the end (:meth:`finish`)."""

    def __init__(self) -> None:
        self._seen: dict[str, int] = {}
        self._rows: list[list[Any]] = []
        self.cost = 0

    def _delta(self, by_purpose: Mapping[str, int]) -> dict[str, int]:
        """The motions of each purpose since the last reading."""
        delta = {p: c - self._seen.get(p, 0) for p, c in by_purpose.items() if c != self._seen.get(p, 0)}
        self._seen = dict(by_purpose)
        return delta

    def _row(self, number: int, augmentation: str, hypotheses: list, delta: dict[str, int]) -> list[Any]:
        """One row: ``delta``'s motions by kind, its validation motions split by the hypotheses' outcomes."""
        kinds = dict.fromkeys(KINDS, 0)
        validation = delta.get("validation", 0)
        for purpose, count in delta.items():
            if purpose != "validation":
                kinds[purpose if purpose in kinds else "other"] += count
        attributed = 0
        for h in hypotheses:
            walked, outcome = getattr(h, "walked", 0), getattr(h, "outcome", "")
            if walked and outcome in CASES:
                kinds[f"validation {outcome}"] += walked
                attributed += walked
        if attributed > validation:
            raise TopomarkFault(f"cost breakdown: iteration {number}'s hypotheses account for {attributed} validation "
                                f"motions, but the robot made {validation}", "cost breakdown")
        kinds["validation other"] = validation - attributed
        return [number, augmentation, len(hypotheses), *(kinds[k] for k in KINDS)]

    def started(self, by_purpose: Mapping[str, int]) -> None:
        """Close the start's row (row 0) from the counter ``by_purpose``, once the explorer has started."""
        self._rows.append(self._row(0, "start", [], self._delta(by_purpose)))

    def after_iteration(self, by_purpose: Mapping[str, int], it) -> None:
        """Close iteration ``it``'s row from the counter ``by_purpose``."""
        if not self._rows:  # an iteration before the start was closed (an explorer's start that iterates)
            self.started({})
        kind = "marker" if getattr(it, "by_marker", False) else (getattr(it, "kind", "") or "other")
        self._rows.append(self._row(it.number, kind, list(getattr(it, "hypotheses", ())), self._delta(by_purpose)))

    def finish(self, by_purpose: Mapping[str, int], cost: int) -> None:
        """The motions after the last iteration (a row ``end`` if any), and the check that the rows add up to
        ``cost``, the simulator's count."""
        delta = self._delta(by_purpose)
        if not self._rows or delta:
            self._rows.append(self._row(len(self._rows), "start" if not self._rows else "end", [], delta))
        self.cost = cost
        total = sum(sum(row[3:]) for row in self._rows)
        if total != cost:
            raise TopomarkFault(f"cost breakdown: the rows add up to {total} motions, but the run cost {cost}",
                                "cost breakdown")

    def rows(self) -> list[list[Any]]:
        """The rows, as lists in :data:`COLUMNS`' order."""
        return [list(row) for row in self._rows]

    def by_kind(self) -> dict[str, int]:
        """Total motions of each kind (every kind, zeros included); they sum to the cost."""
        totals = dict.fromkeys(KINDS, 0)
        for row in self._rows:
            for kind, count in zip(KINDS, row[3:]):
                totals[kind] += count
        return totals

    def to_json(self, rows: bool = False) -> dict[str, Any]:
        """``{"by_kind": {...}, "cost": ...}``; with ``rows``, also ``columns`` and one row per iteration."""
        out: dict[str, Any] = {"cost": self.cost, "by_kind": self.by_kind()}
        if rows:
            out.update(columns=list(COLUMNS), rows=self.rows())
        return out
