"""Enhancement-1: capturing overlap of execution paths (thesis §4.1, Algorithm 4.1).

"For an newly explored edge e and v_u, the execution paths of the
hypotheses may partially or even completely overlap": the same motions from
v_u visit the same places (the execution trie,
:mod:`~topomark.reference.explorers.execution_trie`).  Two stages exploit it:

:class:`OverlapStage1` — Algorithm 4.1 lines 16–20.  After a mismatch,
    every remaining hypothesis h'' whose motion sequence shares a prefix with
    an executed path is compared on that prefix, P^overlap against
    P^{E-overlap}, and rejected without motion on a mismatch.  It is evaluated
    incrementally against *all* paths executed for e; since the thesis
    compares with the just executed path after every rejection, and every
    executed path was "just executed" once, the two are equivalent.
:class:`OverlapStage2` — Algorithm 4.1 lines 15 and 23–26.  The robot
    "stops and remains at the location", greedily takes the remaining
    hypothesis with the longest overlap with its current path (ties: the
    hypothesis policy's order), retraces only to the last overlapped vertex
    and executes the non-overlapped motions.  Enhancements 2 and 3 use this
    stage too (Algorithms 4.2, 4.3).

Correspondence with Algorithm 4.1 (``enh1`` follows it step by step): lines 1–5, 27–30 are Algorithm 3.1's
(:mod:`.algorithm31`); lines 6–7 → ``hypotheses``; lines 8–9, 11–13 →
:meth:`~.enhanced.EnhancedExplorer.attempt`; line 15 → the robot stays (``stays``); lines 16–20 →
:class:`OverlapStage1` (``reject_without_motion``); lines 21–22 → the loop's end in
:meth:`~.enhanced.EnhancedExplorer.validate` (back to v_u by ``goto(0)`` for line 30); lines 23–26 →
:meth:`OverlapStage2.choose` and ``attempt``'s retrace to the overlapped node.  Left open (§4.1): the first
hypothesis (line 8: the hypothesis policy's), ties in line 23 (the policy's order), and, with no overlap, the
next one is the policy's first, walked from v_u ("the robot moves back to v_u", §4.1).
"""

from __future__ import annotations

from dataclasses import dataclass

from topomark.reference.explorers.enhanced import Technique
from topomark.reference.explorers.execution_trie import common_prefix

__all__ = ["OverlapStage1", "OverlapStage2"]


@dataclass(frozen=True)
class OverlapStage1(Technique):
    """Reject h'' without motion when an executed path overlapping M_h'' from v_u contradicts P^E_h''."""

    section = "§4.1, Enhancement-1 stage 1, Algorithm 4.1 lines 16-20"
    rejected_by = "overlap"
    trace = "path"

    def start(self, h) -> int:
        """At v_u the overlap is empty: the next perception to compare is P^E[0]."""
        return 0

    def prepare(self, new) -> set:
        """The first motions of the new perceptions' paths: only hypotheses starting so can overlap them."""
        return {node.first() for node in new}

    def contradiction(self, explorer, h, state: dict, new: list, firsts: set, it) -> int | None:
        """The index in M of the first overlapped perception differing from P^E, or None."""
        if h.motions[0] not in firsts:
            return None  # no new perception lies on h's execution path
        motions, expected = h.motions, h.expected
        for node in new:
            ps = state.get(node.parent)
            if ps is None or ps >= len(motions) or motions[ps] != node.motion:
                continue
            if node.sig != expected[ps]:
                return ps
            state[node] = ps + 1
        return None


@dataclass(frozen=True)
class OverlapStage2(Technique):
    """Remain where the mismatch stopped the robot; execute next the hypothesis overlapping its path longest."""

    section = "§4.1, Enhancement-1 stage 2, Algorithm 4.1 lines 23-26"
    stays = True

    def choose(self, explorer, remaining: list) -> tuple:
        here = explorer.trie.at.path()
        best, best_len = remaining[0], 0
        for h in remaining:
            if here and h.motions[0] == here[0]:
                k = common_prefix(here, h.motions)
                if k > best_len:
                    best, best_len = h, k
        explorer.stats["overlap_saved"] += 2 * best_len
        return best, best_len
