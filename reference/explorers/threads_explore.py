"""Mapping with a thread laid closest-first: Algorithm 6.7 (l = c(G)) and Algorithm 6.8 (l < c(G),
explore-explore) (thesis §6.3.2–6.3.3, Figures 6.19, 6.21).

The robot ties the thread at v_s (first v0) and lays it along every edge it
explores, holding the free end, so the thread is a simple path of S from v_s
to the robot — a depth-first stack: each step explores an unexplored edge of
the vertex where the thread ends (the closest one, §6.3.2), and "the robot
retraces its steps along the thread by picking up and rewinding the thread"
after a loop edge or when the current place is fully explored (§6.3.2,
Algorithm 6.7 lines 8–9 and 14).  At v_u (Algorithm 6.8 lines 6–15):

* **the thread lay here already** (more than e is sensed: ``T`` or a second
  ``S-p``) — v_u is a vertex on the thread.  The robot compares what it
  senses with its own record of the thread: every thread vertex w of v_u's
  degree and open exit j whose marks, read from j with e added at j, are the
  ones sensed is a hypothesis (w, j).  **Ours**: one hypothesis needs no
  motion (``thread-circumference-listing``, :class:`ListingThreadExplorer`, and ``thread-explore-listing``,
  :class:`ListingExploreExplorer`, leave this out and search every time, as line 11 of Algorithm 6.7 and
  line 7 of Algorithm 6.8 say).  Otherwise "the robot searches back along the thread looking for
  the vertex that has one more marked edge" (line 7, §6.3.2): it leaves the
  free end at v_u, goes back over e to v_k and walks the thread back toward
  v_s; the vertex with one more thread-marked edge than its record is v_k' =
  v_u, that edge is e'.  There it takes the free end and rewinds e to v_k
  (ours: lines 11–12 of Algorithm 6.7, do not say where the free
  end waits; rewinding e before v_k' is found would lose the mark).
* **no thread** — in Algorithm 6.7 v_u is new (every visited vertex that is
  not fully explored lies on the thread, §6.3.2).  In Algorithm 6.8 v_u may be
  a visited vertex the robot rewound from when l was reached (§6.3.3): line 11
  searches "non-thread vertices on S that has unexplored edges and has the
  same degree as v_u, looking for the vertex containing the thread's free
  end" (the candidates of the movable marker explorer, minus the thread's
  vertices, visited in the same order; **ours**: not v_k's neighbours, which a
  simple world rules out, §3.1.1 — ``thread-explore-listing`` visits them too),
  leaving the free end at v_u.  Found
  at v_k': the thread's one edge there is e'; take the end, rewind e.  Not
  found: v_u is new; walk back to v_k, cross e and take the end (ours: line 11,
  Algorithm 6.8, does not say how the robot gets back to the free end).

After the step (lines 16–21) the robot rewinds until it stands at a vertex
that is not fully explored and the thread is shorter than l; when it reaches
v_s fully explored, it unties the thread there, walks S to the closest not
fully explored (frontier) vertex (**ours**: the choice is open, §6.3.3) and
ties the thread again there (line 21).  When U is empty the thread is all
rewound and untied, so the final world carries no thread and S shows none.
Between steps S shows the thread where it lies (``show_thread``: the robot
laid every edge of it, so its record says what it would sense at each place;
the checker compares that with the world after every step).

Decisions where the thesis is silent:

* **Algorithm 6.7 and the length.** The robot of Algorithm 6.7 is only
  "assured" that it does not run out (§6.3.2); it is given no length and
  never rewinds because of one.  Told a length (option ``thread-length``),
  it knows when l is reached (§6.3.3, ``spec.thread``'s decision) and stops
  with the failed outcome "out of thread" instead of laying beyond it —
  Algorithm 6.7 has no rule for that case.
* **Which edge.** "A closest edge" (line 4) is, with the robot at the
  thread's end, an unexplored exit of the current vertex (distance 0); the
  lowest-numbered one.
* The robot never needs to be told n or m; the ``edge`` policy does not apply (closest-first is the
  algorithm, §6.3.2).

Cost purposes: ``new`` (over e), ``retrace`` (back over e, every rewind),
``validation`` (the searches), ``other`` (back to v_u for the free end),
``travel`` (to a new v_s).

Examples
--------
>>> ThreadExplorer.name, CircumferenceThreadExplorer.name, ListingThreadExplorer.name, ListingExploreExplorer.name
('thread-explore', 'thread-circumference', 'thread-circumference-listing', 'thread-explore-listing')
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Callable, TypeVar, cast

from topomark.spec.errors import AlgorithmFailed, ExplorerFault
from topomark.spec.kit import ThreadOp
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature, ThreadMark

from topomark.reference.explorers.policies import Policies, bfs, in_preorder
from topomark.reference.explorers.walker import MapWalker, StepRecord, places_like

__all__ = ["ThreadIteration", "ThreadWalker", "ThreadExplorer", "ListingExploreExplorer", "CircumferenceThreadExplorer",
           "ListingThreadExplorer"]

TIE, UNTIE, LEAVE, TAKE = ThreadOp("tie"), ThreadOp("untie"), ThreadOp("leave"), ThreadOp("take")


@dataclass
class ThreadIteration(StepRecord):
    """One step: the edge e explored, what was sensed at v_u, how it was resolved, the thread after it (no
    hypotheses)."""

    how: str = ""  # "new", "sensed", "thread search", "off-thread search", "knots", "probe"
    candidates: list[int] = field(default_factory=list)
    laid: int = 0  # edges of thread laid after the step
    tied: int | None = None  # where the thread is tied after the step

    def to_json(self) -> dict:
        return {"iteration": self.number, "edge": list(self.edge), "signature": str(self.signature),
                "augmentation": self.kind, "joined": self.joined_json(),
                "resolved": self.how, "candidates": self.candidates, "laid": self.laid, "tied": self.tied}


It = TypeVar("It", bound=ThreadIteration)  # a step's record, a ThreadIteration or one of its kinds


class ThreadWalker(MapWalker):
    """S, U and the believed pose (a :class:`~.walker.MapWalker`'s start, termination, walks and augmentations;
    the thread is tied in the first step), and the robot's record of its thread: tied at ``tied`` (map
    vertex), laid along ``laid`` (darts of S, from the tied vertex out), free end ``held`` or lying at the laid
    end.  Walks of S (:meth:`~.walker.MapWalker.walk`) are made with the thread untied or its free end left
    behind; a move holding the free end of a tied thread lays it (:meth:`lay`)."""

    name = "thread"
    loop_check = "thread loop"
    loop_proof = "the thread's closest-first validation (§6.3.2)"

    def __init__(self, robot, policies: Policies | None = None,
                 observer: Callable[[object, ThreadIteration], None] | None = None, options: dict | None = None):
        super().__init__(robot, policies, observer)
        self.options = options or {}
        length = self.options.get("thread-length")  # an integer, or "n": not told (Algorithm 6.7's default)
        self.length: int | None = length if isinstance(length, int) else None
        self.tied: int | None = None
        self.laid: list[MapDart] = []
        self.held = True
        self.knots: dict[int, int] = {}  # position along ``laid`` ↦ knots tied there (thread-knots)

    def finish(self, it: It) -> It:
        """End a step: the thread recorded in ``it`` and shown in S, then the step recorded."""
        it.laid, it.tied = len(self.laid), self.tied
        self.show_thread()
        return self.record(it)

    # -- the thread ----------------------------------------------------------------------
    def show_thread(self) -> None:
        """S shows the thread where it lies now, from the robot's record of it (it laid every edge of it), so
        S and the world agree between steps (the checker judges S against the live world): each map vertex's
        :class:`ThreadMark` set, and cleared where the thread was rewound."""
        now: dict[int, ThreadMark] = {}
        if self.tied is not None:
            walk, edges = self.on_thread(), self.thread_edges()
            knots: dict[int, int] = {}
            for pos, k in self.knots.items():
                knots[walk[pos]] = knots.get(walk[pos], 0) + k
            end = walk[-1] if not self.held else None
            now = {v: ThreadMark(v == self.tied, None, tuple(sorted(edges.get(v, {}).items())), v == end,
                                 knots.get(v, 0)) for v in dict.fromkeys(walk)}
        S = self.S
        for v in set(S.thread_marks) | set(now):
            if S.thread_marks.get(v) != now.get(v):
                if v in now:
                    S.mark_as_sensed(v, Signature(S.degree(v), thread=now[v]), 0)  # absolute exits: entry 0
                else:
                    del S.thread_marks[v]
                    S.journal.append(("mark", v))  # PartialMap has no unmark: journal it as mark_as_sensed does

    def knot(self, count: int) -> None:
        self.robot.operate(ThreadOp("knot", count=count))
        self.knots[len(self.laid)] = self.knots.get(len(self.laid), 0) + count

    def tie(self) -> None:
        self.robot.operate(TIE)
        self.tied, self.laid, self.held, self.knots = self.position[0], [], True, {}

    def leave_and_return(self, it: ThreadIteration) -> None:
        """Leave the free end at v_u and go back over e to v_k (not holding it, the move lays nothing)."""
        self.robot.operate(LEAVE)
        self.held = False
        self.robot.move(0, "retrace")
        self.position = it.edge

    def take(self) -> None:
        self.robot.operate(TAKE)
        self.held = True

    def untie(self) -> None:
        self.robot.operate(UNTIE)
        self.tied, self.held, self.knots = None, True, {}

    def open_exit(self, v: int) -> int | None:
        """The lowest unexplored exit of ``v`` (the closest edge, the robot standing there), or None."""
        exits = self.open_exits(v)
        return exits[0] if exits else None

    def can_lay(self) -> bool:
        return self.length is None or len(self.laid) < self.length

    def lay(self, exit_: int, purpose: str) -> Signature:
        """Follow ``exit_`` of the current vertex holding the free end: the thread is laid along it."""
        if not self.can_lay():
            raise AlgorithmFailed(f"out of thread: the thread's {self.length} edges are all laid, from map vertex "
                                  f"{self.tied} to map vertex {self.position[0]}, and this algorithm has no rule for "
                                  "running out (Algorithm 6.7 assumes l = c(G) suffices, §6.3.2)")
        sig = self.take_exit(exit_, purpose)
        self.laid.append((self.position[0], exit_))
        return sig

    def rewind(self, purpose: str = "retrace") -> None:
        """Move back along the last laid edge, picking it up; the robot enters its near end by that edge."""
        self.robot.rewind(purpose)
        self.knots.pop(len(self.laid), None)  # knots beyond the rewound point come up with it (spec.thread)
        self.position = self.laid.pop()

    def on_thread(self, upto: int | None = None) -> list[int]:
        """The thread's vertices in order from the tied one (the laid darts ``laid[:upto]``)."""
        return [cast(int, self.tied)] + [self.S.target(d)[0] for d in self.laid[:upto]]  # the thread is tied

    def thread_edges(self, upto: int | None = None) -> dict[int, dict[int, int]]:
        """Map vertex ↦ exit ↦ how often the thread lies along it (``laid[:upto]``, as recorded)."""
        out: dict[int, dict[int, int]] = {}
        target = self.S.target
        for d in self.laid[:upto]:
            for v, x in (d, target(d)):
                at = out.setdefault(v, {})
                at[x] = at.get(x, 0) + 1
        return out


def _sensed_edges(sig: Signature, entry: int) -> Counter:
    """The thread-marked exits sensed, in absolute exits of a vertex entered by ``entry``."""
    return Counter({(entry + p) % sig.degree: k for p, k in sig.thread.edges}) if sig.thread else Counter()


class ThreadExplorer(ThreadWalker):
    """Algorithm 6.8, explore-explore (§6.3.3), with a thread of ``thread-length`` edges."""

    name = "thread-explore"
    retie = True
    literal = False  # True: the listing as written, every search it lists (lines 7 and 11), no shortcut
    iteration_type: type = ThreadIteration  # the record of one step (the fallback adds its phase)

    def step(self) -> ThreadIteration:
        """Lines 4–21: lay the thread along the closest unexplored edge, resolve v_u, rewind / retie."""
        if self.tied is None:
            self.tie()
        vk = self.position[0]
        i = cast(int, self.open_exit(vk))  # an unexplored edge leaves vk
        self.S.unexplored.remove((vk, i))
        it = self.iteration_type(len(self.iterations) + 1, (vk, i))
        it.signature = sig = self.lay(i, "new")
        t = cast(ThreadMark, sig.thread)  # the thread was just laid in here
        if t.tied or len(t.edges) > 1 or t.knots:  # lines 6-9: the thread lay at v_u already
            self.loop_on_thread(it, sig)
        elif self.retie:  # lines 10-15
            self.off_thread(it, sig)
        else:  # Algorithm 6.7 line 6: no thread, so v_u is new
            it.how = "new"
            self.non_loop_augment(it, sig)
        self.settle()
        return self.finish(it)

    def loop_on_thread(self, it: ThreadIteration, sig: Signature) -> None:
        """v_u is a vertex of the thread: which one, and by which exit e' (hypotheses, else the search back)."""
        vk, i = it.edge
        marks = self.thread_edges(-1)
        near = {vk} | {t[0] for t in self.S.links(vk) if t is not None}
        hyps = [(w, j) for w in dict.fromkeys(self.on_thread(-1)) if w not in near and self.S.degree(w) == sig.degree
                for j in self.open_exits(w) if self._reads(w, j, marks, sig)]
        it.candidates = sorted({w for w, _ in hyps})
        if len(hyps) == 1 and not self.literal:  # ours: the listing searches even then (line 11)
            it.how = "sensed"
            self.rewind()
            return self.loop_augment(it, hyps[0])
        it.how = "thread search"
        self.leave_and_return(it)
        found = None
        for d in reversed(self.laid[:-1]):  # line 7: back along the thread from v_k toward v_s
            self.walk([self.S.target(d)], "validation")
            w, entry = self.position
            extra = _sensed_edges(self.robot.sense(), entry) - Counter(marks.get(w, {}))
            if w in it.candidates and sum(extra.values()) == 1:
                found = (w, next(iter(extra)))
                break
        if found is None:
            # v_u entered a thread-marked place, so it is on the thread, "the one that has one more thread-marked
            # edge than it should have" (§6.3.2): not finding it is a bug, not an outcome.
            raise ExplorerFault(f"thread search: no vertex on the thread has one more thread-marked edge at "
                                f"iteration {it.number}, which §6.3.2 rules out: a bug in the explorer")
        self.take()
        self.rewind()
        self.loop_augment(it, found)

    def _reads(self, w: int, j: int, marks: dict[int, dict[int, int]], sig: Signature) -> bool:
        """Whether w entered by exit j, the thread as recorded plus e at j, senses the thread ``sig`` shows."""
        d = self.S.degree(w)
        edges = sorted([((x - j) % d, k) for x, k in marks.get(w, {}).items()] + [(0, 1)])
        t = cast(ThreadMark, sig.thread)  # asked of places the thread shows
        return (t.tied, t.head, t.end, t.knots, t.edges) == (w == self.tied, None, False, 0, tuple(edges))

    def off_thread(self, it: ThreadIteration, sig: Signature) -> None:
        """Line 11: search the known vertices off the thread that could be v_u for the free end left there."""
        vk, i = it.edge
        thread = set(self.on_thread(-1))
        if self.literal:  # line 11 as listed: every vertex off the thread with an unexplored edge and v_u's degree
            like = in_preorder(self.S, vk, {v for v in self.S.unexplored.ends() if self.S.degree(v) == sig.degree})
        else:  # ours: not v_k's neighbours either, which a simple world rules out (§3.1.1)
            like = places_like(self.S, vk, sig.degree)
        it.candidates = [w for w in like if w not in thread]
        if not it.candidates:
            it.how = "new"
            self.non_loop_augment(it, sig)
            return
        it.how = "off-thread search"
        self.leave_and_return(it)

        def free_end(w: int, entry: int, seen: Signature) -> bool:
            return seen.thread is not None and seen.thread.end

        for target in it.candidates:
            found = self.walk_to(target, "validation", free_end)
            if found is not None:  # v_k' = v_u: the thread's one edge there is e'
                w, entry, seen = found
                self.take()
                self.rewind()
                return self.loop_augment(it, (w, next(iter(_sensed_edges(seen, entry)))))
        self.walk_to(vk, "other")  # v_u is new: back to it for the free end
        self.take_exit(i, "other")
        self.take()
        self.non_loop_augment(it, sig)

    def settle(self) -> None:
        """Lines 16–21: rewind to a not fully explored vertex where the thread can still be laid; at v_s fully
        explored, untie and (Algorithm 6.8) retie at the closest frontier vertex."""
        while True:
            if self.open_exit(self.position[0]) is not None and (self.can_lay() or not self.retie):
                return
            if self.laid:
                self.rewind()
                continue
            self.untie()
            if not self.S.unexplored:
                return
            if not self.retie:
                # "the closest-first exploration ensures that each visited vertex that is not fully explored yet
                # has been marked with the thread" (Algorithm 6.7, §6.3.2): a vertex off it is a bug.
                raise ExplorerFault("thread stack: a vertex not fully explored is off the thread, which Algorithm 6.7 "
                                    "rules out (§6.3.2): a bug in the explorer")
            dist = bfs(self.S, self.position[0])[0]
            frontier = min((v for v in dist if self.open_exit(v) is not None), key=lambda v: (dist[v], v))
            self.walk_to(frontier, "travel")
            self.tie()
            return


class CircumferenceThreadExplorer(ThreadExplorer):
    """Algorithm 6.7 (§6.3.2): never retied; v_u without thread is new; stops "out of thread"
    if told a length it reaches."""

    name = "thread-circumference"
    retie = False


class ListingThreadExplorer(CircumferenceThreadExplorer):
    """Algorithm 6.7 as listed (§6.3.2): at a vertex the thread lay at already, the robot "searches back along
    the thread looking for the vertex that has one more marked edge" (lines 11–12) every time, even where its
    record of the thread leaves one vertex it can be — the search ``thread-circumference`` skips then."""

    name = "thread-circumference-listing"
    literal = True


class ListingExploreExplorer(ThreadExplorer):
    """Algorithm 6.8 as listed (§6.3.3): at a vertex the thread lay at already, the robot "searches back along the
    thread looking for the vertex having one more stringed edge" (line 7) every time, even where its record of the
    thread leaves one vertex it can be; and line 11 searches every "non-thread vertex on S that has unexplored
    edges and has the same degree as v_u", v_k's neighbours too — the two shortcuts ``thread-explore`` takes.

    Where the listing is silent the decisions are ``thread-explore``'s (§6.3.3): the closest edge is the lowest
    unexplored exit where the thread ends; line 11 visits the candidates in the preorder of a breadth-first
    tree of S rooted at v_k, along shortest paths, and ends at the first place entered that shows the free end;
    not found, the robot walks back to v_k and over e for the free end; the new v_s (line 21) is the closest
    frontier vertex."""

    name = "thread-explore-listing"
    literal = True
