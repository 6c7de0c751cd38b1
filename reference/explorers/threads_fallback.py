"""Exploring with a thread of arbitrary length by the phase-I/phase-II fallback (thesis §6.3.3).

"One possible approach is that, as in the arbitrary k markers algorithm, the
robot uses thread to do validations when it possesses thread (phase-I), and
when it runs out of thread (phase-II), it applies the hypothesis-based
traversal strategy developed for the single immovable marker algorithm.  This
approach has an O(m²n) cost bound" (§6.3.3).

* **Phase I** is Algorithm 6.7 (§6.3.2;
  :class:`~topomark.reference.explorers.threads_explore.CircumferenceThreadExplorer`):
  the thread is tied at v0 and laid closest-first, rewound after a loop edge
  or at a fully explored place; a place without thread is new, a place with
  it is found on the thread.  ``thread-fallback`` takes topomark's shortcut
  there (no search back along the thread where the robot's record of it
  leaves one vertex v_u can be); ``thread-fallback-listing``
  (:class:`ListingFallbackThreadExplorer`) runs phase I as Algorithm 6.7 is
  listed, searching at every loop step (lines 11–12).
* **Phase II** starts when the robot stands at a place with an unexplored
  edge and all l edges of its thread are laid.  It leaves the free end there:
  from then on the thread is an immovable mark, tied at v0 and laid along a
  simple path of S (the thread's marks are in S, the robot laid them).  The
  rest is Algorithm 3.1 (§3.3, §3.4;
  :func:`~topomark.reference.explorers.algorithm31.validate_in_turn`) with v0
  as its lighthouse: every unexplored dart e' whose known end, entered by it,
  shows v_u's signature — thread marks included — is a hypothesis, tested by
  walking S's path from v_k' to v0 and comparing every perception.

Decisions where the thesis is silent (§6.3.3 gives the approach in one sentence):

* **Which phase-I algorithm.**  Algorithm 6.7, the thread algorithm that never
  reties: the text falls back once, "when it runs out of thread", and
  "assuming that the robot can pick up the thread and tie it again" is what
  the two O(mn) approaches add (§6.3.3), so the fallback does not retie.
* **Running out** is all l edges laid with an unexplored edge at the robot's
  place: the robot knows l (§6.3.3).  A loop step never runs out, for
  Algorithm 6.7 rewinds before it explores again.
* **The lighthouse.**  "The hypothesis-based traversal strategy developed for
  the single immovable marker algorithm" needs a place that gives place and
  back-link: v0, the only place where the thread is tied, with exactly one
  thread-marked edge (the thread is a simple path there, l ≥ 1), so each of
  its entries reads differently — a directional lighthouse (§3.3, §6.1).
* **The thread stays laid** when U is empty, as Case 5's markers stay where
  they were dropped: phase II may not move it, and the final map
  shows it where it lies.
* Phase II takes Algorithm 3.1's policies (``--policy edge|hypothesis|path``;
  by default the closest edge, hypotheses in U's order, a breadth-first tree
  to v0); phase I is Algorithm 6.7's closest-first and takes none.

Cost purposes: phase I's (``new``, ``retrace``, ``validation``), then
Algorithm 3.1's (``travel``, ``new``, ``validation``, ``retrace``).

Examples
--------
>>> FallbackThreadExplorer.name, ListingFallbackThreadExplorer.name
('thread-fallback', 'thread-fallback-listing')
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, cast

from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.algorithm31 import (V0, Hypothesis, LighthouseExplorer, retrace_motions,
                                                      validate_in_turn)
from topomark.reference.explorers.policies import bfs
from topomark.reference.explorers.threads_explore import LEAVE, CircumferenceThreadExplorer, ThreadIteration

__all__ = ["FallbackIteration", "FallbackThreadExplorer", "ListingFallbackThreadExplorer"]


@dataclass
class FallbackIteration(ThreadIteration):
    """A step with its phase (1: Algorithm 6.7, 2: Algorithm 3.1 over the laid thread) and phase II's
    hypotheses."""

    phase: int = 1

    def to_json(self) -> dict:
        out = super().to_json()
        out["phase"] = self.phase
        out["hypotheses"] = [h.to_json() for h in self.hypotheses]
        return out


class FallbackThreadExplorer(CircumferenceThreadExplorer):
    """Phase I: Algorithm 6.7 with a thread of ``thread-length`` edges; phase II, once it is all laid:
    Algorithm 3.1 with v0, where the thread is tied, as the lighthouse."""

    name = "thread-fallback"
    loop_check = "thread fallback loop"
    loop_proof = "the thread's validation (phase I, §6.3.2) or the tied v0 as lighthouse (phase II, §3.4 Lemma 1)"
    hypothesis_type = Hypothesis
    iteration_type = FallbackIteration  # phase I's steps too, recorded with phase 1
    # Algorithm 3.1's H over S and its path to v0 (lines 8, 11–12)
    hypotheses: Callable[..., list[Hypothesis]] = LighthouseExplorer.hypotheses
    _tail = LighthouseExplorer._tail

    def __init__(self, robot, policies=None, observer=None, options: dict | None = None):
        super().__init__(robot, policies, observer, options)
        self.phase = 1
        self.P = self.S  # S as perceived: the thread's marks are in S itself
        self._v0_sigs: list[Signature] = []
        self._v0_entries: dict[Signature, int] = {}

    def step(self) -> FallbackIteration:
        """One step of phase I, or — the thread all laid at a place with an unexplored edge — of phase II."""
        if self.phase == 1 and self.tied is not None and not self.can_lay():
            self.run_out()
        if self.phase == 2:
            return self.phase_two()
        return cast(FallbackIteration, super().step())  # of this explorer's iteration_type

    def run_out(self) -> None:
        """Leave the free end where the robot stands; v0, tied with one thread edge, becomes the lighthouse."""
        self.robot.operate(LEAVE)
        self.held = False
        self.show_thread()
        self.phase = 2
        self._v0_sigs = [signature_at(self.S, V0, e) for e in range(self.S.degree(V0))]
        self._v0_entries = {s: e for e, s in enumerate(self._v0_sigs)}

    def phase_two(self) -> FallbackIteration:
        """Algorithm 3.1's loop body (lines 5–28) over S with the thread's marks, v0 the lighthouse."""
        dist, _, parent = bfs(self.S, self.position[0])
        it = FallbackIteration(len(self.iterations) + 1, self.policies.choose_edge(self.S, dist), phase=2)
        self.travel_to(it.edge[0], parent)
        it.signature = sig = self.take_exit(it.edge[1], "new")
        entry = self._v0_entries.get(sig)
        if entry is not None:  # v0: place and back-link from the thread tied there
            it.how = "lighthouse"
            self.loop_augment(it, (V0, entry))
            self.position = (V0, entry)
            return self.finish(it)
        it.hypotheses = self.hypotheses(it, sig)
        confirmed, heading = validate_in_turn(self.robot, it.hypotheses, sig.degree,
                                              lambda done, degrees: retrace_motions(self.robot, done, degrees))
        if confirmed is not None:  # lines 22-25
            it.how = "hypothesis"
            self.loop_augment(it, confirmed.dart)
            self.position = confirmed.arrival
        else:  # lines 26-28: off the thread (every thread place is in S), so v_u shows no mark
            it.how = "new"
            self.non_loop_augment(it, sig, heading)
        return self.finish(it)


class ListingFallbackThreadExplorer(FallbackThreadExplorer):
    """The fallback with phase I as Algorithm 6.7 is listed (§6.3.2, lines 11–12): at a vertex the thread lay at
    already the robot searches back along the thread every time (the steps of ``thread-circumference-listing``);
    phase II is unchanged, Algorithm 3.1 (§3.3) with v0 as the lighthouse."""

    name = "thread-fallback-listing"
    literal = True
