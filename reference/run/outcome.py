"""The outcome of one exploration: its map, cost, counts and verdict (thesis §3.3, §3.4).

:func:`topomark.reference.run.explore.explore` returns an :class:`Outcome`; ``topomark explore --json``
prints its :meth:`~Outcome.summary`.  Its ``repr`` is one short line saying what the run was and how it
ended; the trace, the explorer and the counts stay available as attributes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from topomark.spec.errors import clip
from topomark.spec.world import World

__all__ = ["Outcome"]


@dataclass(repr=False)
class Outcome:
    """One exploration of a world by an algorithm of the registry, and its verdict.

    ``outcome`` is how the run ended (``correct``, ``wrong-map``, ``failed``, ``limit``, or ``unchecked``
    without the checker; :data:`topomark.spec.errors.OUTCOMES`), ``claimed`` what the algorithm itself
    claimed, ``verified`` whether the checker saw every invariant hold, ``violation`` the first one that
    did not (or None) and ``reason`` why a stopped algorithm stopped.  ``cost`` counts edge traversals
    (§3.5), ``by_purpose`` splits it (``breakdown`` splits it further, by iteration and hypothesis outcome), ``checks`` counts the checks passed, ``n`` and ``m`` are the world's
    size.  :attr:`map` is the explored map as a world; ``trace`` the trace records (empty when they went
    to a file or were not kept); ``explorer`` the explorer itself, with its iterations.
    """

    n: int
    m: int
    cost: int
    verified: bool
    iterations: int
    loop_iterations: int
    nonloop_iterations: int
    hypotheses: int
    hypotheses_rejected: int
    hypotheses_confirmed: int
    checks: int
    by_purpose: dict[str, int]
    upper_bound: int | None  # the entry's exact cost bound on this world (None: asymptotic or none stated)
    # whose ``upper_bound`` is and what it bounds (AlgorithmSpec.bound_whose): the thesis's, or topomark's for the
    # thesis's listing or for its own variant (docs/bounds.md)
    drop_trips: int = 0  # traversals made only to drop markers (part of cost; the simulator's accounting rule)
    lighthouse: str | None = "directional-vertex"
    marker_operations: dict[str, int] = field(default_factory=dict)
    explorer: Any = None
    trace: list[dict[str, Any]] = field(default_factory=list)
    violation: Any = None
    outcome: str = "correct"
    claimed: str = "correct"
    reason: str | None = None
    kit: str = ""
    walk_steps: int | None = None  # a lighthouse algorithm: the walk that found v0, or gave up (§5.1, §6.1)
    lighthouse_at: str | None = None  # a lighthouse algorithm: the world vertex v0 is (the truth; the robot never knows)
    extra: dict[str, Any] = field(default_factory=dict)  # the algorithm's own counts (its registry's summary_fn)
    bound_checked: bool = False  # the run was held to ``upper_bound`` (the ``cost-bound`` check)
    algorithm: str = ""  # the registry name of the algorithm that ran
    bound_whose: str | None = None  # whose ``upper_bound`` is and what it bounds (above)
    breakdown: Any = None  # the cost split by iteration and kind (:class:`~topomark.reference.run.breakdown.CostBreakdown`)

    def __repr__(self) -> str:
        """``Outcome(algorithm='basic', world n=90 m=146, cost=6868, correct, verified, 738 checks)``: what ran,
        on what, and how it ended, in one line of at most a few hundred characters (never the trace)."""
        parts = [f"algorithm={self.algorithm!r}", f"world n={self.n} m={self.m}", f"cost={self.cost}",
                 self.outcome, "verified" if self.verified else "not verified", f"{self.checks} checks"]
        if self.violation is not None:
            parts.append(f"violation: {clip(str(self.violation), 300)}")
        if self.reason:
            parts.append(f"reason: {clip(self.reason, 300)}")
        if self.trace:
            parts.append(f"{len(self.trace)} trace records")
        return f"Outcome({', '.join(parts)})"

    @property
    def map(self) -> World | None:
        """The explored map as a world (the markers the robot left included), or None when there is none.

        The map is the explorer's S once the algorithm claims a correct end (a ``wrong-map`` run's map is
        returned all the same: it is what the algorithm claims, to be compared with the world).  None when
        the algorithm stopped (outcome ``failed`` or ``limit``), when the checker stopped the run before the
        algorithm finished, or when the explorer keeps no single completed map (``model-tree`` keeps models).
        """
        S = getattr(self.explorer, "S", None)
        if self.claimed != "correct" or S is None or not S.complete():
            return None
        return S.to_world()

    def summary(self) -> dict[str, Any]:
        out = {k: getattr(self, k) for k in (
            "n", "m", "cost", "drop_trips", "verified", "iterations", "loop_iterations", "nonloop_iterations", "hypotheses",
            "hypotheses_rejected", "hypotheses_confirmed", "checks", "by_purpose", "upper_bound", "bound_whose", "lighthouse",
            "marker_operations", "outcome", "claimed", "reason", "bound_checked")}
        if self.lighthouse is not None:
            out.update(walk_steps=self.walk_steps, lighthouse_at=self.lighthouse_at)
        out.update(self.extra)
        out["cost_per_m"] = round(self.cost / self.m, 3)
        if self.violation is not None:
            out["violation"] = self.violation.to_json()
        return out
