"""Algorithm 3.1's template with Chapter 4's techniques plugged into its hooks (thesis §4.1–4.3).

Chapter 4 keeps Algorithm 3.1's loop — H with its M and P^E (Lemma 1),
loop and non-loop augmentation — so every invariant the checker verifies
after each iteration is the same.  What its listings change is *how*
hypotheses are rejected or confirmed and which extra traversals are made.
An :class:`Enhancement` is a named composition of :class:`Technique` objects;
:class:`EnhancedExplorer` fills the template's hooks
(:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`) by
calling each technique's hooks in the composition's order:

========================  =======================================================================
technique hook            where (the listings of Chapter 4)
========================  =======================================================================
``known_on_entering``     on entering v_u, before any motion: what is already known there
                          (v_k behind e, Alg. 4.4 line 7; records of T under e, Alg. 4.3)
``on_enter``              Alg. 4.5 line 7: "explores all the distance d neighbors of v_u"
``prune``                 Alg. 4.4 line 7, 4.5 line 8: H keeps hypotheses whose expanded signature
                          matches
tracer (``rejected_by``)  Alg. 4.1 lines 16–20, 4.2 lines 16–20, 4.3 lines 16–24: reject
                          without motion what the executed paths contradict
``choose``                Alg. 4.1 lines 23–26: the hypothesis to execute next and the overlapped
                          node it starts from (default: line 10, from v_u)
``after_non_loop``        Alg. 4.4 line 22: expand the new vertex
``recorded_depth``        Alg. 4.3 lines 36–37, 4.4 line 22, 4.5 line 23: what to add to T
========================  =======================================================================

Validation runs on the **execution trie**
(:mod:`~topomark.reference.explorers.execution_trie`): with no technique at
all it makes Algorithm 3.1's moves exactly (``tests/test_enhancements.py``).

Cost accounting: ``expansion`` traversals are the investment of
enhancements 4 and 5 (their own purpose in the simulator's ledger);
:attr:`EnhancedExplorer.stats` counts what the techniques saved: ``pruned``
(would-be hypotheses never formed), ``rejected_without_motion``,
``overlap_saved`` (2 traversals per overlapped edge in stage 2, against
returning to v_u and walking out again) and ``recorded`` (perceptions stored
in T).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import cast

from topomark.spec.errors import ExplorerFault
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature

from topomark.reference.explorers.algorithm31 import Hypothesis, Iteration, LighthouseExplorer
from topomark.reference.explorers.execution_trie import ExecutionTrie
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.records import Record, graft, migrate, record_trie

__all__ = ["Technique", "Enhancement", "EnhancedHypothesis", "EnhancedIteration", "EnhancedExplorer"]


class Technique:
    """One Chapter 4 technique.  Every hook's default changes nothing; the class attributes describe it.

    A *tracer* (``rejected_by`` set) also offers ``start(h)`` (its state at
    v_u), ``prepare(new)`` and ``contradiction(explorer, h, state, new, ctx,
    it)`` (the index in M of a contradicted perception, -1 off h's path, or
    None).
    """

    section = ""
    rejected_by = ""  # a tracer's label on the hypotheses it rejects: "overlap" or "map"
    trace = ""  # what a tracer traces on: "path" (P^E along M), "map" (S), "map+T" (S and T)
    prunes = False  # filters H with expanded signatures
    stays = False  # stage 2: the robot remains where it stopped
    expands_new = False  # senses the neighbours of each new vertex
    as_listed = False  # makes its listing's moves to the letter (no records beyond e before motion, no place skipped)

    @property
    def expands_place(self) -> int:
        """Senses the places within this distance of v_u."""
        return 0

    def known_on_entering(self, explorer: "EnhancedExplorer", it: "EnhancedIteration") -> None:
        """Add to the trie what is known at v_u before any motion."""

    def on_enter(self, explorer: "EnhancedExplorer", it: "EnhancedIteration") -> None:
        """Move on entering v_u, before H is formed."""

    def prune(self, explorer: "EnhancedExplorer", it: "EnhancedIteration", found: list) -> list:
        """H as this technique defines it."""
        return found

    def choose(self, explorer: "EnhancedExplorer", remaining: list) -> tuple | None:
        """The next hypothesis and the depth of the overlapped node to start from, or None (line 10)."""
        return None

    def after_non_loop(self, explorer: "EnhancedExplorer", it: "EnhancedIteration") -> None:
        """Move once v_u joined S as a new vertex."""

    def recorded_depth(self, new: bool) -> float:
        """How deep into the execution trie to record into T after the join (0: nothing)."""
        return 0


@dataclass(frozen=True)
class Enhancement:
    """A named composition of techniques (none: Algorithm 3.1), with its thesis reference.

    The properties describe the composition for readers of traces and the
    registry; behaviour lives in the techniques.
    """

    name: str
    techniques: tuple[Technique, ...] = ()
    section: str = ""

    def __post_init__(self):
        if self.stage2 and not self.trace:
            raise ValueError(f"{self.name}: stage 2 of Enhancement-1 executes only the non-overlapped part of M, "
                             "so it needs stage 1 or tracing to have compared the overlapped part (Algorithm 4.1)")

    @property
    def trace(self) -> str:
        return "+".join(t.trace for t in self.techniques if t.trace)

    @property
    def stage2(self) -> bool:
        return any(t.stays for t in self.techniques)

    @property
    def prune(self) -> bool:
        return any(t.prunes for t in self.techniques)

    @property
    def expand_new(self) -> bool:
        return any(t.expands_new for t in self.techniques)

    @property
    def expand_place(self) -> int:
        return max((t.expands_place for t in self.techniques), default=0)

    @property
    def grafts(self) -> bool:
        """Whether T's records beyond e join the trie on entering v_u, before any motion: topomark's change to
        Algorithm 4.3 (its ``changes``), left out where a technique follows its listing to the letter."""
        return not any(t.as_listed for t in self.techniques)


@dataclass
class EnhancedHypothesis(Hypothesis):
    """A hypothesis that may be rejected without motion: ``rejected_by`` says how."""

    rejected_by: str = ""  # "", "motion", "overlap" (stage 1), "map" (traced on S / T)

    def to_json(self) -> dict:
        out = super().to_json()
        if self.rejected_by:
            out["rejected_by"] = self.rejected_by
        return out


@dataclass
class EnhancedIteration(Iteration):
    """An iteration with the enhancements' ledger: pruned hypotheses, motion-free rejections, expansion."""

    pruned: int = 0
    without_motion: int = 0
    expansion: int = 0
    known: int = 0  # perceptions known from T before any motion

    def to_json(self) -> dict:
        out = super().to_json()
        out["enhancement"] = {"pruned": self.pruned, "without_motion": self.without_motion,
                              "expansion": self.expansion, "known": self.known}
        return out


class EnhancedExplorer(LighthouseExplorer):
    """Algorithm 3.1 over the execution trie, with the techniques of ``enhancement`` (a class attribute)."""

    enhancement = Enhancement("basic")
    name = "basic"
    hypothesis_type = EnhancedHypothesis
    iteration_type = EnhancedIteration

    def __init__(self, robot, policies=None, observer=None, lighthouse=LIGHTHOUSES["directional-vertex"]):
        super().__init__(robot, policies, observer, lighthouse)
        self.T: dict[MapDart, Record] = {}
        self.stats: Counter[str] = Counter()
        self.trie: ExecutionTrie = cast(ExecutionTrie, None)  # made on entering v_u (on_enter), before any use
        self.techniques = self.enhancement.techniques
        self._tracers = tuple(t for t in self.techniques if t.rejected_by)
        self._states: dict = {}

    # -- the template's hooks ------------------------------------------------------
    def on_enter(self, it: EnhancedIteration, sig: Signature) -> None:  # type: ignore[override]  # its own iterations
        """Begin the iteration's execution trie at v_u; add what is known; let the techniques move."""
        self.trie = ExecutionTrie(self.robot, sig, self.lighthouse)
        self._states = {}
        for t in self.techniques:
            t.known_on_entering(self, it)
        if self.enhancement.grafts:
            it.known += graft(self.T, self.trie, it.edge, self.lighthouse)
        for t in self.techniques:
            t.on_enter(self, it)

    def validate(  # type: ignore[override]  # its own iterations
            self, it: EnhancedIteration, sig: Signature) -> tuple[EnhancedHypothesis | None, int]:
        """Lines 8–20 on the trie: H (pruned), motion-free rejections after every executed path, the next
        hypothesis from the overlapped node.  Returns the confirmed hypothesis or None, and the robot's
        offset (at v_u, counted from e, when none is confirmed)."""
        trie = self.trie
        found = self.hypotheses(it, sig)
        for t in self.techniques:
            found = t.prune(self, it, found)
        it.hypotheses = found
        remaining = self.reject_without_motion(it, found)
        trie.new = []
        while remaining:
            h, start = self.choose(remaining)
            remaining.remove(h)
            if self.attempt(h, start):
                return h, trie.offset
            remaining = self.reject_without_motion(it, remaining)
            trie.new = []
        trie.goto(0)
        return None, trie.offset

    def arrival(self, h: Hypothesis) -> MapDart:
        v, entry = h.arrival
        return v, (entry + self.trie.offset) % self.S.degree(v)

    def after_non_loop(self, it: EnhancedIteration) -> None:  # type: ignore[override]  # its own iterations
        for t in self.techniques:
            t.after_non_loop(self, it)
        self.position = (self.position[0], self.trie.offset)

    def after_join(self, it: EnhancedIteration) -> None:  # type: ignore[override]  # its own iterations
        """Records under darts just explored move on; the techniques' share of the trie goes into T."""
        migrate(self.P, self.T, self.stats, it.joined, self.lighthouse)
        if it.by_marker:
            return
        depth = max((t.recorded_depth(it.kind == "non-loop") for t in self.techniques), default=0)
        if depth:
            joined = cast("tuple[MapDart, MapDart]", it.joined)  # after a join
            record_trie(self.P, self.T, self.stats, self.trie, joined[1], depth, self.lighthouse)

    # -- validation on the trie --------------------------------------------------------
    def choose(self, remaining: list) -> tuple[EnhancedHypothesis, int]:
        """The first technique's choice, else line 10: the policy's next hypothesis, from v_u."""
        for t in self.techniques:
            picked = t.choose(self, remaining)
            if picked is not None:
                return picked
        return remaining[0], 0

    def attempt(self, h: EnhancedHypothesis, start: int) -> bool:
        """Lines 13–20 from the overlapped node at depth ``start`` (retracing there first): True on case (3)."""
        trie = self.trie
        trie.goto(start)
        perceived = []
        node = trie.root
        for m in h.motions[:start]:
            node = node.children[m]
            perceived.append(node.sig)
        for step in range(start, len(h.motions)):
            got = trie.forward(h.motions[step], "validation")
            perceived.append(got)
            h.walked += 1
            if got != h.expected[step]:
                h.outcome = "case 2" if step == len(h.motions) - 1 else "case 1"
                h.rejected_by = "motion"
                h.perceived = tuple(perceived)
                return False
        for step, got in enumerate(perceived[:start]):
            if got != h.expected[step]:  # pragma: no cover - stage 1 / tracing rejects this earlier
                # stage 1 compared these very perceptions with P^E already: a mismatch now is a bug, not an outcome
                raise ExplorerFault(f"Enhancement-1 stage 2: hypothesis {h.dart}'s overlapped perceptions {perceived} "
                                    "do not match P^E, which stage 1 checked: a bug in the explorer")
        h.perceived = tuple(perceived)
        h.outcome = "case 3"
        return True

    def states(self, tracer, hypotheses: list) -> dict:
        """Per hypothesis, ``tracer``'s state at each trie node traced so far (shared by equal tracers)."""
        states = self._states.get(tracer)
        if states is None:
            root = self.trie.root
            states = self._states[tracer] = {id(h): {root: tracer.start(h)} for h in hypotheses}
        return states

    def reject_without_motion(self, it: EnhancedIteration, remaining: list) -> list:
        """Every tracer rejects the remaining hypotheses the trie's new perceptions contradict."""
        new = self.trie.new
        for tracer in self._tracers:
            ctx = tracer.prepare(new)
            states = self.states(tracer, remaining)
            kept = []
            for h in remaining:
                step = tracer.contradiction(self, h, states[id(h)], new, ctx, it)
                if step is None:
                    kept.append(h)
                    continue
                h.outcome = "case 2" if step == len(h.motions) - 1 else "case 1"
                h.rejected_by = tracer.rejected_by
                it.without_motion += 1
                self.stats["rejected_without_motion"] += 1
            remaining = kept
        return list(remaining)
