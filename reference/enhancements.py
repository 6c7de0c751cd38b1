"""Enhancements to the single directional immovable marker algorithm (thesis Chapter 4).

Every enhancement is a *policy* of one checked explorer,
:class:`EnhancedExplorer`, a subclass of
:class:`~topomark.reference.lighthouse.LighthouseExplorer` (Algorithm 3.1):
the iteration structure, the hypotheses H (with their M and P^E, Lemma 1),
loop and non-loop augmentation are the basic algorithm's, so every invariant
the checker verifies after each iteration (I-1, I-2, t, Lemma 1, marker,
believed position) is the same.  What changes is *how* hypotheses are
rejected or confirmed and which extra traversals are made.

The common device is the **execution trie** of the current iteration: every
motion sequence the robot has executed from v_u (relative exits, the first
relative to e, as in §4.1) with the perception sensed at its end.  The world
is deterministic, so equal motion sequences from v_u reach the same place
(the "overlap" observation of Enhancement-1).  The robot's position is a node
of the trie plus its *offset* (the physical entry edge counted from the
node's canonical entry edge); it moves forward along a child or back to the
parent (the reverse motion of line 17 of Algorithm 3.1).

Registered names (``topomark explore --algorithm NAME``):

``enh1`` — Enhancement-1, capturing overlap of execution paths (§4.1,
    Algorithm 4.1).  Stage 1: after a mismatch, every remaining hypothesis
    whose motion sequence shares a prefix with an executed path is compared
    on that prefix and rejected without motion on a mismatch.  Stage 2: the
    robot stays where it stopped and greedily takes the remaining hypothesis
    with the longest overlap with its current path (ties: the hypothesis
    policy's order), retraces only to the last overlapped vertex and executes
    the non-overlapped motions.  Stage 1 is evaluated incrementally against
    *all* paths executed for e; since the thesis compares with the just
    executed path after every rejection, and every executed path was "just
    executed" once, the two are equivalent.
``enh2`` — Enhancement-2, executed paths that map onto S (§4.1, Algorithm
    4.2, stage 2 of Enhancement-1 included).  Assuming h'' = (e'', v_k'') is
    true, every executed path is traced on S from (v_k'', e''); a perception
    at a place of S that differs from S's signature rejects h''.  Choice: the
    hypothesized edge e''/e itself is part of the traced map (it is part of
    S if h'' holds); tracing stops at any other unexplored edge.
``enh3`` — Enhancement-3, also perceptions at unknown places (§4.1,
    Algorithm 4.3).  After each iteration all executed paths are traced from
    the validated (v_u, e); the part beyond an unexplored edge (x, t) of S is
    stored in T as a trie keyed by that dart (``v_x-3-[4,A,A]-2-[2,A,A]...``,
    Figure 4.5).  Tracing (as in enh2) continues into T.  When (x, t) is later
    explored, its record moves to wherever it now leads.  Choice: records
    under the dart e = (v_k, i) describe paths *from v_u*, so they are added
    to the iteration's trie before any motion (known perceptions, not moves;
    the same holds for the D records of enhancements 4/5, which live in T
    too, so a neighbour of v_u already sensed is not walked to again).
``enh4`` — Enhancement-4, expanded signatures of vertices in S (§4.2,
    Algorithm 4.4).  After a non-loop augmentation the robot senses each
    other neighbour of the new vertex (out and back, purpose ``expansion``)
    and records D; e' = (v_k', i') is a hypothesis only if v_k' shows v_u's
    signature *and* the recorded far end of e' shows v_k's signature (seen
    from e).  Choice: a neighbour already sensed during this iteration's
    validation is not visited again.
``enh5-d1``, ``enh5-d2`` — Enhancement-5, expanded signatures of S and of
    the current place (§4.2, Algorithm 4.5).  On entering v_u the robot senses
    every place within distance d of v_u reachable through v_u's other exits
    (d = 2: the neighbours' other neighbours as well), then H keeps only
    hypotheses whose known neighbourhood (S, and the recorded expansions D of
    earlier new vertices) agrees with everything sensed, including the far end
    of e' against v_k.  Choice: v_k's side of v_u's distance-2 neighbourhood is
    not walked (v_k is in S; its known neighbours are not re-sensed).
``enh3+4``, ``enh3+5`` — the combinations of §4.3 (Tables 4.7, 4.8): enh3's
    tracing, recording and stage 2 together with enh4's expansion of new
    vertices, or enh5's expansion of the current place with d = 2 (the
    version the thesis combines).  Expansion perceptions are records in T.

Cost accounting: ``expansion`` traversals are the investment of
enhancements 4 and 5 (their own purpose in the simulator's ledger);
:attr:`EnhancedExplorer.stats` counts what the enhancements saved:
``pruned`` (would-be hypotheses never formed), ``rejected_without_motion``,
``overlap_saved`` (2 traversals per overlapped edge in stage 2, against
returning to v_u and walking out again) and ``recorded`` (perceptions stored
in T).

The explorer still sees only the robot interface.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from topomark.spec.errors import CheckFailure, Violation
from topomark.spec.mapstate import MapDart
from topomark.spec.signature import Signature, signature_at

from .explorers.lighthouses import LIGHTHOUSES
from .lighthouse import V0, Hypothesis, Iteration, LighthouseExplorer
from .policies import bfs

__all__ = ["EnhancedExplorer", "ENHANCEMENTS", "EnhancedHypothesis", "EnhancedIteration"]


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


class _Node:
    """A node of the execution trie: the place reached by the motions from v_u to here."""

    __slots__ = ("sig", "parent", "motion", "children", "depth", "kind")

    def __init__(self, sig: Signature, parent: "_Node | None", motion: int | None, kind: str):
        self.sig, self.parent, self.motion, self.kind = sig, parent, motion, kind
        self.children: dict[int, _Node] = {}
        self.depth = 0 if parent is None else parent.depth + 1

    def path(self) -> list[int]:
        out, x = [], self
        while x.parent is not None:
            out.append(x.motion)
            x = x.parent
        return out[::-1]


class _Record:
    """A record of T: the signature sensed beyond an unexplored dart, and what lies beyond (Figure 4.5)."""

    __slots__ = ("sig", "children")

    def __init__(self, sig: Signature):
        self.sig = sig
        self.children: dict[int, _Record] = {}


@dataclass(frozen=True)
class Enhancement:
    """Which techniques of Chapter 4 are on."""

    name: str
    trace: str = ""  # "", "path" (enh1 stage 1), "map" (enh2), "map+T" (enh3)
    stage2: bool = False  # greedy longest overlap (enh1 stage 2)
    prune: bool = False  # filter H with expanded signatures (enh4, enh5)
    expand_new: bool = False  # enh4: sense the neighbours of each new vertex
    expand_place: int = 0  # enh5: distance d sensed around v_u
    record: str = ""  # "", "all" (enh3), "new:d" (D of enh4/enh5: depth <= d, new vertices only)
    section: str = ""


ENHANCEMENTS: dict[str, Enhancement] = {e.name: e for e in (
    Enhancement("enh1", trace="path", stage2=True, section="§4.1, Enhancement-1, Algorithm 4.1"),
    Enhancement("enh2", trace="map", stage2=True, section="§4.1, Enhancement-2, Algorithm 4.2"),
    Enhancement("enh3", trace="map+T", stage2=True, record="all", section="§4.1, Enhancement-3, Algorithm 4.3"),
    Enhancement("enh4", prune=True, expand_new=True, record="new:1", section="§4.2, Enhancement-4, Algorithm 4.4"),
    Enhancement("enh5-d1", prune=True, expand_place=1, record="new:1", section="§4.2, Enhancement-5, Algorithm 4.5"),
    Enhancement("enh5-d2", prune=True, expand_place=2, record="new:2", section="§4.2, Enhancement-5, Algorithm 4.5"),
    Enhancement("enh3+4", trace="map+T", stage2=True, prune=True, expand_new=True, record="all",
                section="§4.3, Enhancements 3+4, Table 4.8"),
    Enhancement("enh3+5", trace="map+T", stage2=True, prune=True, expand_place=2, record="all",
                section="§4.3, Enhancements 3+5, Table 4.7"),
)}


class EnhancedExplorer(LighthouseExplorer):
    """Algorithm 3.1 with the Chapter 4 techniques selected by ``enhancement`` (a class attribute)."""

    enhancement = Enhancement("basic")
    name = "basic"

    def __init__(self, robot, policies=None, observer=None, lighthouse=LIGHTHOUSES["directional-vertex"]):
        super().__init__(robot, policies, observer, lighthouse)
        self.T: dict[MapDart, _Record] = {}
        self.stats: Counter[str] = Counter()
        self._root: _Node | None = None
        self._at: _Node | None = None
        self._offset = 0
        self._new: list[_Node] = []

    # -- the loop body ---------------------------------------------------------
    def iterate(self) -> Iteration:
        enh = self.enhancement
        _, _, parent = tree = bfs(self.S, self.position[0])
        it = EnhancedIteration(len(self.iterations) + 1, self.policies.choose_edge(self.S, tree[0]))
        vk, i = it.edge
        self.travel_to(vk, parent)
        sig = self.robot.move((i - self.position[1]) % self.S.degree(vk), "new")
        it.signature = sig
        entry = self.lighthouse_entry(sig)
        if entry is not None:
            self.loop_augment(it, (V0, entry), by_marker=True)
            self._migrate((it.edge, (V0, entry)))
        else:
            self._begin(it, sig)
            if enh.expand_place:
                self._expand(it, enh.expand_place)
            confirmed = self._validate(it, sig)
            if confirmed is not None:
                self.loop_augment(it, confirmed.dart)
                v, entry = confirmed.arrival
                self.position = (v, (entry + self._offset) % self.S.degree(v))
                root = confirmed.dart
            else:
                self._goto(0)
                self.non_loop_augment(it, sig, self._offset)
                root = (self.S.n - 1, 0)
                if enh.expand_new:
                    self._expand(it, 1)
                    self.position = (root[0], self._offset)
            self._migrate(it.joined)
            self._record(root, new=confirmed is None)
        self.iterations.append(it)
        if self.observer is not None:
            self.observer(self, it)
        return it

    # -- the execution trie and the robot's place in it -------------------------
    def _begin(self, it: EnhancedIteration, sig: Signature) -> None:
        self._root = self._at = _Node(sig, None, None, "root")
        self._offset = 0
        self._new = []
        vk, i = it.edge
        if self.enhancement.prune:
            # The robot came from v_k through e: motion 0 from v_u reaches v_k entered by exit i (in S).
            self._add(self._root, 0, signature_at(self.S, vk, i), "virtual")
        rec = self.T.get(it.edge)
        if rec is not None:  # perceptions recorded beyond e are perceptions of paths from v_u
            if rec.sig != sig:
                raise CheckFailure(Violation("Enhancement-3 record", f"T[{it.edge}]", str(sig), str(rec.sig),
                                             "a recorded perception contradicts the robot's senses"))
            self._graft(self._root, rec, it)

    def _graft(self, node: _Node, rec: _Record, it: EnhancedIteration) -> None:
        for m, child in rec.children.items():
            known = node.children.get(m)
            if known is None:
                known = self._add(node, m, child.sig, "recorded")
                it.known += 1
            self._graft(known, child, it)

    def _add(self, node: _Node, m: int, sig: Signature, kind: str) -> _Node:
        child = node.children[m] = _Node(sig, node, m, kind)
        self._new.append(child)
        return child

    def _forward(self, m: int, purpose: str) -> Signature:
        node = self._at
        sig = self.robot.move((m - self._offset) % node.sig.degree, purpose)
        child = node.children.get(m)
        if child is None:
            child = self._add(node, m, sig, purpose)
        elif child.sig != sig:
            raise CheckFailure(Violation("execution trie", f"motions {child.path()} from v_u", str(child.sig),
                                         str(sig), "the same motions from v_u sensed different places"))
        self._at, self._offset = child, 0
        return sig

    def _back(self, purpose: str) -> None:
        node = self._at
        self.robot.move((-self._offset) % node.sig.degree, purpose)
        self._at, self._offset = node.parent, node.motion

    def _goto(self, depth: int, purpose: str = "retrace") -> None:
        while self._at.depth > depth:
            self._back(purpose)

    # -- enhancement 4/5: sensing a neighbourhood ------------------------------------
    def _expand(self, it: EnhancedIteration, d: int) -> None:
        """Sense every place reachable from the robot's node by 1..d motions through exits other than the entry."""
        start = self._at

        def missing(node: _Node, depth: int) -> bool:
            if depth == 0:
                return False
            for m in range(1, node.sig.degree):
                child = node.children.get(m)
                if child is None or missing(child, depth - 1):
                    return True
            return False

        def walk(depth: int) -> None:
            node = self._at
            for m in range(1, node.sig.degree):
                child = node.children.get(m)
                if child is not None and not missing(child, depth - 1):
                    continue
                self._forward(m, "expansion")
                it.expansion += 1
                if depth > 1:
                    walk(depth - 1)
                self._back("expansion")
                it.expansion += 1

        walk(d)
        assert self._at is start

    # -- validation ------------------------------------------------------------------
    def hypotheses(self, it: Iteration, sig: Signature) -> list[Hypothesis]:
        return [EnhancedHypothesis(h.dart, h.motions, h.expected, h.arrival) for h in super().hypotheses(it, sig)]

    def _validate(self, it: EnhancedIteration, sig: Signature) -> EnhancedHypothesis | None:
        enh = self.enhancement
        found = self.hypotheses(it, sig)
        states = {id(h): {self._root: self._root_state(h)} for h in found}
        if enh.prune:  # enhancements 4/5: H holds only hypotheses whose expanded signature matches
            kept = [h for h in found if self._consistent(h, states[id(h)], "map+T", it) is None]
            it.pruned = len(found) - len(kept)
            self.stats["pruned"] += it.pruned
            found = kept
        it.hypotheses = found
        remaining = self._filter(found, states, it) if enh.trace else list(found)
        self._new = []
        while remaining:
            if enh.stage2:
                here = self._at.path()
                best, best_len = remaining[0], 0
                for h in remaining:
                    if here and h.motions[0] == here[0]:
                        k = _common(here, h.motions)
                        if k > best_len:
                            best, best_len = h, k
                h, start = best, best_len
                self.stats["overlap_saved"] += 2 * start
            else:
                h, start = remaining[0], 0
            remaining.remove(h)
            self._goto(start)
            perceived = []
            node = self._root
            for m in h.motions[:start]:
                node = node.children[m]
                perceived.append(node.sig)
            for step in range(start, len(h.motions)):
                got = self._forward(h.motions[step], "validation")
                perceived.append(got)
                if got != h.expected[step]:
                    h.outcome = "case 2" if step == len(h.motions) - 1 else "case 1"
                    h.rejected_by = "motion"
                    break
            else:
                for step, got in enumerate(perceived[:start]):
                    if got != h.expected[step]:  # pragma: no cover - stage 1 / tracing rejects this earlier
                        raise CheckFailure(Violation("Enhancement-1 stage 2", f"hypothesis {h.dart}",
                                                     "overlapped perceptions matching P^E", str(perceived)))
                h.perceived = tuple(perceived)
                h.outcome = "case 3"
                return h
            h.perceived = tuple(perceived)
            if enh.trace:
                remaining = self._filter(remaining, states, it)
            self._new = []
            if not enh.stage2:
                self._goto(0)
        return None

    def _root_state(self, h: EnhancedHypothesis):
        return 0 if self.enhancement.trace == "path" else (h.dart, ())

    def _filter(self, remaining: list, states: dict, it: EnhancedIteration) -> list:
        """Reject without motion every remaining hypothesis the new perceptions contradict."""
        kept = []
        path_mode = self.enhancement.trace == "path"
        firsts = {_first(node) for node in self._new} if path_mode else None
        for h in remaining:
            if path_mode and h.motions[0] not in firsts:
                kept.append(h)  # no new perception lies on h's execution path
                continue
            step = self._consistent(h, states[id(h)], self.enhancement.trace, it)
            if step is None:
                kept.append(h)
                continue
            h.outcome = "case 2" if step == len(h.motions) - 1 else "case 1"
            h.rejected_by = "overlap" if self.enhancement.trace == "path" else "map"
            it.without_motion += 1
            self.stats["rejected_without_motion"] += 1
        return kept

    def _consistent(self, h: EnhancedHypothesis, state: dict, mode: str, it: Iteration) -> int | None:
        """Check the trie nodes added since the last check against h (assumed true).

        Returns None if consistent, else the index in M of the contradicted
        perception (-1 if it lies off h's own path).

        ``mode`` "path": compare with P^E where the node lies on M (stage 1 of Enhancement-1);
        "map": trace on S plus the hypothesized edge e''/e (Enhancement-2);
        "map+T": and continue into the records of T (Enhancement-3, and D of Enhancements 4/5).
        """
        S, links, T, traced = self.S, self.S.links, self.T, mode == "map+T"
        link = {h.dart: it.edge, it.edge: h.dart}
        for node in self._new:
            ps = state.get(node.parent)
            if ps is None:
                continue
            m = node.motion
            if mode == "path":
                if isinstance(ps, tuple) or ps >= len(h.motions) or h.motions[ps] != m:
                    continue
                if node.sig != h.expected[ps]:
                    return ps
                state[node] = ps + 1
                continue
            md, recs = ps
            nm, nrecs = None, []
            if md is not None:
                x, entry = md
                row = links(x)
                t = (x, (entry + m) % len(row))
                nm = row[t[1]]
                if nm is None:
                    nm = link.get(t)
                    if traced:
                        rec = T.get(t)
                        if rec is not None:
                            nrecs.append(rec)
                if nm is not None and signature_at(S, nm[0], nm[1]) != node.sig:
                    return -1
            for r in recs:
                rec = r.children.get(m)
                if rec is not None:
                    nrecs.append(rec)
            for rec in nrecs:
                if rec.sig != node.sig:
                    return -1
            if nm is not None or nrecs:
                state[node] = (nm, tuple(nrecs))
        return None

    # -- enhancement 3 (and D of 4/5): recording perceptions at unknown places --------------
    def _record(self, root: MapDart, new: bool) -> None:
        """Trace the iteration's trie from the validated (v_u, e) and store what lies beyond unexplored darts."""
        rule = self.enhancement.record
        if not rule or (rule.startswith("new") and not new):
            return
        limit = int(rule.split(":")[1]) if ":" in rule else None

        def keep(node: _Node) -> bool:
            return node.kind != "virtual" and (limit is None or node.depth <= limit)

        self._absorb(root, self._root, keep)

    def _absorb(self, dart: MapDart, node, keep) -> None:
        """Route ``node``'s children (trie nodes or records) from map dart ``dart`` into S / T."""
        S = self.S
        x, entry = dart
        for m, child in node.children.items():
            if isinstance(child, _Node) and not keep(child):
                continue
            t = (x, (entry + m) % S.degree(x))
            far = S.arc(t)
            if far is not None:
                if signature_at(S, far[0], far[1]) != child.sig:
                    raise CheckFailure(Violation("Enhancement-3 record", f"map dart {far}",
                                                 str(signature_at(S, far[0], far[1])), str(child.sig),
                                                 "a perception contradicts the map"))
                self._absorb(far, child, keep)
            else:
                rec = self.T.get(t)
                if rec is None:
                    rec = self.T[t] = _Record(child.sig)
                    self.stats["recorded"] += 1
                self._merge(rec, child, keep)

    def _merge(self, rec: _Record, node, keep) -> None:
        for m, child in node.children.items():
            if isinstance(child, _Node) and not keep(child):
                continue
            sub = rec.children.get(m)
            if sub is None:
                sub = rec.children[m] = _Record(child.sig)
                self.stats["recorded"] += 1
            self._merge(sub, child, keep)

    def _migrate(self, darts) -> None:
        """Records under darts that just became explored move to where those darts lead."""
        for dart in darts or ():
            rec = self.T.pop(dart, None)
            if rec is not None:
                far = self.S.arc(dart)
                if signature_at(self.S, far[0], far[1]) != rec.sig:
                    raise CheckFailure(Violation("Enhancement-3 record", f"T[{dart}]",
                                                 str(signature_at(self.S, far[0], far[1])), str(rec.sig),
                                                 "a recorded perception contradicts the map"))
                self._absorb(far, rec, lambda _: True)


def _first(node: _Node) -> int | None:
    """The first motion of the path from v_u to ``node``."""
    while node.depth > 1:
        node = node.parent
    return node.motion


def _common(a, b) -> int:
    k = 0
    for x, y in zip(a, b):
        if x != y:
            break
        k += 1
    return k


def _make(enh: Enhancement) -> type:
    cls = type(f"Explorer_{enh.name.replace('+', '_').replace('-', '_')}", (EnhancedExplorer,),
               {"enhancement": enh, "name": enh.name, "__doc__": f"{enh.section}: see the module docstring."})
    return cls


EXPLORERS: dict[str, type] = {name: _make(enh) for name, enh in ENHANCEMENTS.items()}
