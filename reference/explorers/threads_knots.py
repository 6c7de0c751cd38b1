"""Mapping with a very long thread and knots, l ≫ m (thesis §6.3.2, Figure 6.20): O(m).

"With a l ≫ m thread, which guarantees that the robot does not run out of
thread during exploration, the robot plays out the thread as it explores,
even when the thread forms a loop ... allow the robot to tie knots at each
unknown place v_u it visits ... Thus place validation for v_u is never
needed, but when entering a thread-marked (visited) vertex v_k' the robot
may still need to conduct back-link validation ... the robot can just
traverse any one of thread marked edges to the other end vertex, which must
be a known neighbor that is identified by its unique knot count" (§6.3.2).
Figure 6.20: "Explore in a closest-first manner. Play the thread out
as it explores. Tie different number of knots when entering a new place the
first time ... Rewinds the thread only when the current place is fully
explored".

So the thread is a walk from v0 used as a stack: each step lays it along
the lowest unexplored exit of the vertex where it ends; a vertex with no
unexplored exit is left by rewinding.  Map vertex k (v0 = 0) gets k + 1
knots when first entered (v0 too, so that every visited place shows a knot).
At v_u:

* **no knot** — a new place (non-loop augmentation), knots tied;
* **c knots** — known vertex c − 1 = v_k'.  If v_k' has one unexplored exit,
  it is e' (**ours**: no motion needed, as in the movable marker explorer).
  Otherwise the back-link validation of §6.3.2: follow the lowest thread-marked
  exit other than e (relative p), which lays the thread along it; the knots
  at its far end name the known neighbour w, whose exit back to v_k' is
  known in S, so the edge's exit x at v_k' is known and e' = x − p; rewind back.

Decisions (the thesis gives no listing):

* **Length** (registry): the walk is the stack of edges being explored — at
  most the n − 1 tree edges and m − n + 1 loop edges, plus one probe edge —
  so m + 1 edges never run out; the kit is given exactly that and the
  simulator refuses more, so the claim is checked on every run.
* **Knots survive** where needed (Figure 6.20: "Rewinds the thread only
  when the current place is fully explored"): a vertex's knots are
  tied at its first position on the walk and picked up only by rewinding out
  of that position, which happens only when it is fully explored; a loop edge
  or a probe leads only to a vertex that is not fully explored or lies on the
  walk, so every vertex the robot can reach by laying shows its knots.
* **Cost** is exactly 2m + 2p, p the probed loop edges (each edge laid once
  and rewound once; a probe out and back): at most 4m − 2n + 2 — under 3m
  whenever p < m/2.  At the end the whole thread is rewound to v0 and
  untied, so the final world carries no thread and S shows none.

Examples
--------
>>> KnotThreadExplorer.name
'thread-knots'
"""

from __future__ import annotations

from typing import cast

from topomark.spec.errors import ExplorerFault
from topomark.spec.signature import Signature, ThreadMark

from topomark.reference.explorers.threads_explore import ThreadIteration, ThreadWalker

__all__ = ["KnotThreadExplorer"]


class KnotThreadExplorer(ThreadWalker):
    """The l ≫ m thread with knots (§6.3.2, Figure 6.20)."""

    name = "thread-knots"

    def step(self) -> ThreadIteration:
        """Lay the thread along the closest unexplored edge; knots name v_u; rewind out of explored places."""
        if self.tied is None:
            self.tie()
            self.knot(1)  # v0 = map vertex 0
        vk = self.position[0]
        i = cast(int, self.open_exit(vk))  # the closest unexplored edge leaves vk
        self.S.unexplored.remove((vk, i))
        it = ThreadIteration(len(self.iterations) + 1, (vk, i))
        it.signature = sig = self.lay(i, "new")
        thread = cast(ThreadMark, sig.thread)  # the thread was just laid in here
        if not thread.knots:
            it.how = "new"
            self.non_loop_augment(it, sig)
            self.knot(self.position[0] + 1)
        else:
            w = thread.knots - 1
            self.check_knots(it, w, sig)
            opens = self.open_exits(w)
            if len(opens) == 1:
                it.how = "knots"
                self.position = far = (w, opens[0])
            else:
                it.how = "probe"
                far = (w, self.probe(it, w, sig))  # the robot at w, entered by the probed edge
            self.loop_augment(it, far)
        while self.laid and self.open_exit(self.position[0]) is None:
            self.rewind()
        if not self.S.unexplored:
            self.untie()
        return self.finish(it)

    def check_knots(self, it: ThreadIteration, w: int, sig: Signature) -> None:
        if not (0 <= w < self.S.n and self.S.degree(w) == sig.degree and self.open_exit(w) is not None):
            # Each visited place carries its own knot count and every place not fully explored stays on the
            # thread (§6.3.2): knots that name no such place are a bug, not an outcome.
            raise ExplorerFault(f"thread knots: {sig} at iteration {it.number} names no known vertex that is not "
                                "fully explored, which the knots rule out (§6.3.2): a bug in the explorer")

    def probe(self, it: ThreadIteration, w: int, sig: Signature) -> int:
        """§6.3.2: over the lowest thread-marked exit p ≠ e to a known neighbour (its knots say which) and back;
        returns e' (absolute exit of w); the robot ends at w entered by that probed edge."""
        p = min(x for x, _ in cast(ThreadMark, sig.thread).edges if x != 0)  # the thread lies at w
        seen = self.robot.move(p, "probe")
        t = seen.thread.knots - 1 if seen.thread is not None else -1
        back = [y for y, link in enumerate(self.S.links(t)) if link is not None and link[0] == w] if t >= 0 else []
        if len(back) != 1:
            # "the other end vertex, which must be a known neighbor that is identified by its unique knot count"
            # (§6.3.2): anything else is a bug, not an outcome.
            raise ExplorerFault(f"thread probe: {seen} at iteration {it.number} is no known neighbour of map vertex "
                                f"{w} by its knots, which §6.3.2 rules out: a bug in the explorer")
        x = self.S.target((t, back[0]))[1]  # the probed edge's exit at w
        self.laid.append((w, x))
        self.position = (t, back[0])
        self.rewind("probe")
        return (x - p) % self.S.degree(w)
