"""Mapping with a single directional immovable vertex marker: Algorithm 3.1 (thesis §3.3) as a template.

The robot drops its directional marker at the start vertex v0, pointing at the
exit it faces, so v0 becomes a *directional lighthouse*: entering it reveals
both the place and the back-link.  Every iteration takes an unexplored edge
e = (v_k, v_u) from U, walks S to v_k, follows e, and senses v_u:

* the marker is there — v_u is v0, and the entry index is read off the
  marker's direction: loop augmentation at once;
* otherwise every unexplored dart e' = (v_k', i') of U whose known end shows
  v_u's signature (v_k' ≠ v_k) is a hypothesis h' = (e', v_k').  For each, the
  simple path in S from v_k' to v0 gives a motion sequence M and expected
  perceptions P^E; the robot executes M and stops at the first mismatch —
  case (1) during, case (2) at the end (reject, retrace by the reverse motions
  and re-align to e) — or completes it with every perception matching —
  case (3) (confirm: loop augmentation);
* no hypothesis confirmed — non-loop augmentation: v_u joins S with e as its
  exit 0 and its other exits, numbered clockwise, join U.

:meth:`LighthouseExplorer.iterate` is the loop body (lines 5–28) written once.
Chapter 4's listings modify it at named points, the **hooks**; each does
nothing (or Algorithm 3.1's own step) here:

===================  ==============================================================  ==========================
hook                 where in the listing                                            modified by
===================  ==============================================================  ==========================
``on_enter``         after line 7: the robot has followed e and sensed v_u           Alg. 4.5 line 7 (expand v_u)
``hypotheses``       lines 8, 11–12: H with every M and P^E                          —
``validate``         lines 8–20: H tested with motion, one hypothesis at a time     Alg. 4.1–4.5 (stages 1, 2)
``arrival``          lines 19–20: where the robot is once M completed (case 3)       the execution trie's offset
``after_non_loop``   after lines 27–28: v_u joined S as a new vertex                 Alg. 4.4 line 22 (expand it)
``after_join``       after line 25 or 28 (and the marker's join): S augmented        Alg. 4.3 lines 36–37 (T)
===================  ==============================================================  ==========================

The explorer sees only a :class:`~topomark.reference.explorers.robot.Robot`.  It keeps
the iteration records the checker and the trace read.  What every family of
explorers shares — S, U and the believed pose, recording an iteration, walking
S (line 6) and the two augmentations (lines 24–28) — is the
:class:`~topomark.reference.explorers.walker.MapWalker`'s; this module adds the
lighthouse, H, and the test of its hypotheses (:func:`validate_in_turn`, which
Case 5's phase II runs too).

Correspondence with Algorithm 3.1 (``basic`` follows it step by step; the audit is ``docs/bounds.md``):

* lines 1–3 → :meth:`LighthouseExplorer.start`; line 4 → :meth:`~.walker.MapWalker.done`;
* line 5 → ``policies.choose_edge``; line 6 → ``travel_to``; line 7 → ``take_exit`` (the marker's case, §3.3,
  → ``lighthouse_entry`` and loop augmentation at once);
* lines 8, 11–12 → :meth:`LighthouseExplorer.hypotheses` (:func:`hypothesis_darts`); lines 9–10, 13–20 →
  :func:`validate_in_turn` (line 13 :func:`walk_hypothesis`, cases (1)/(2) its first mismatch, line 17
  :func:`retrace_motions`, the re-alignment to e the next motion's turn);
* lines 22–25 → :meth:`LighthouseExplorer.loop_augment`; lines 26–28 → :meth:`LighthouseExplorer.non_loop_augment`.

Choices the listing leaves open (§3.3): which e leaves U (line 5, the edge policy, default ``nearest``), the path
of line 6 and the simple path of line 11 (the path policy, default shortest: one breadth-first tree to v0 per
iteration), the order of H (line 10, the hypothesis policy, default U's order).  H leaves out v_k itself, as
§3.3's text does ("Every vertex (except v_k) in S could potentially correspond to v_u"); it keeps v_k's known
neighbours, as the text does.

References
----------
Algorithm 3.1 and §3.3–3.4 of *Exploring topological environments*; the
basic approach of Dudek et al. [26] (§3.1.3).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature, reads_as, signature_at

from topomark.reference.explorers.policies import Policies, bfs, tree_to_v0
from topomark.reference.explorers.robot import Robot
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Beacon, Lighthouse
from topomark.reference.explorers.walker import MapWalker, StepRecord

__all__ = ["Hypothesis", "Iteration", "LighthouseExplorer", "V0", "hypothesis_darts", "walk_hypothesis",
           "retrace_motions", "validate_in_turn"]

V0 = 0


@dataclass
class Hypothesis:
    """h' = (e', v_k'): with its motion sequence M, expected perceptions P^E and what happened."""

    dart: MapDart
    motions: tuple[int, ...]
    expected: tuple[Signature, ...]
    arrival: MapDart = (0, 0)  # (v0, entry) where M ends if h' holds
    outcome: str = "untested"  # "case 1", "case 2", "case 3" or "untested"
    perceived: tuple[Signature, ...] = ()
    walked: int = 0  # the motions the robot made to test it (its validation walk; the cost breakdown's share)

    def to_json(self) -> dict:
        return {"dart": list(self.dart), "motions": list(self.motions),
                "expected": [str(s) for s in self.expected], "outcome": self.outcome,
                "perceived": [str(s) for s in self.perceived]}


@dataclass
class Iteration(StepRecord):
    """One pass through the loop body of Algorithm 3.1; its ``hypotheses`` are :class:`Hypothesis` records."""

    by_marker: bool = False

    def to_json(self) -> dict:
        return {"iteration": self.number, "edge": list(self.edge), "signature": str(self.signature),
                "hypotheses": [h.to_json() for h in self.hypotheses], "augmentation": self.kind,
                "joined": self.joined_json(), "by_marker": self.by_marker}


def hypothesis_darts(S: PartialMap, g, sig: Signature, vk: int) -> list[MapDart]:
    """The darts e' = (v_k', i) of U, in U's order, with v_k' ≠ ``vk`` and whose known end, entered by them, reads
    ``sig`` in ``g`` (S as perceived): line 8's H.  Only the entries at places of ``sig``'s degree are looked at
    (:meth:`~topomark.spec.unexplored.Unexplored.at`), which ``reads_as`` would reject first anyway."""
    U, reads = S.unexplored, reads_as(g, sig)
    return [d for d in U.at([v for v in U.ends() if v != vk and g.degree(v) == sig.degree]) if reads(*d)]


def walk_hypothesis(robot: Robot, h: Hypothesis, degree: int, heading: int) -> tuple[list[int], list[int]]:
    """Execute h's motions M from v_u (lines 11-16), comparing each perception with P^E; stop at the first
    mismatch, which makes h case 1 (before the end of M) or case 2 (at its end); record what was perceived.

    ``heading`` is the robot's entry edge at v_u counted from e (a rejected hypothesis's retrace leaves it
    there), so the first motion is turned by it.  Returns the motions done and the degrees passed, for the
    retrace (line 17).
    """
    done, degrees, perceived = [], [degree], []
    for step, (motion, want) in enumerate(zip(h.motions, h.expected)):
        physical = (motion - heading) % degree if step == 0 else motion
        got = robot.move(physical, "validation")
        done.append(physical)
        degrees.append(got.degree)
        perceived.append(got)
        if got != want:
            h.outcome = "case 2" if step == len(h.motions) - 1 else "case 1"
            break
    h.perceived, h.walked = tuple(perceived), len(done)
    return done, degrees


def retrace_motions(robot: Robot, done: list[int], degrees: list[int]) -> None:
    """Execute the reverse of the motions ``done`` (line 17): 0, then −l mod deg back to v_u (``degrees``: the
    degrees of the places passed, v_u's first)."""
    robot.move(0, "retrace")
    for t in range(len(done) - 1, 0, -1):
        robot.move((-done[t]) % degrees[t], "retrace")


def validate_in_turn(robot: Robot, hypotheses: list[Hypothesis], degree: int,
                     retrace: Callable[[list[int], list[int]], None],
                     confirms: Callable[[Hypothesis], bool] = lambda h: True) -> tuple[Hypothesis | None, int]:
    """Test ``hypotheses`` one at a time from v_u (of ``degree``), the robot entered by e (lines 8–20).

    Each is walked (:func:`walk_hypothesis`); one whose perceptions matched P^E throughout and that
    ``confirms`` accepts is case 3, and is returned with the robot at its end; any other is retraced
    (``retrace(done, degrees)``, line 17) and the next one is turned by the heading the retrace left.
    Returns the confirmed hypothesis (or None) and the robot's heading at v_u: its entry edge counted from e.
    """
    heading = 0  # the physical entry edge, counted from e (e = exit 0 of v_u)
    for h in hypotheses:
        done, degrees = walk_hypothesis(robot, h, degree, heading)
        if h.outcome == "untested" and confirms(h):
            h.outcome = "case 3"
            return h, heading
        retrace(done, degrees)
        heading = (heading + done[0]) % degree
    return None, heading


class LighthouseExplorer(MapWalker):
    """Algorithm 3.1 on a robot; ``observer(explorer, iteration)`` runs after every iteration."""

    name = "basic"
    loop_check = "Algorithm 3.1"
    hypothesis_type: type = Hypothesis  # the record of one h' (Chapter 4 adds how it was rejected)
    iteration_type: type = Iteration  # the record of one iteration (Chapter 4 adds its counters)

    def __init__(self, robot: Robot, policies: Policies | None = None,
                 observer: Callable[["LighthouseExplorer", Iteration], None] | None = None,
                 lighthouse: Lighthouse = LIGHTHOUSES["directional-vertex"]):
        super().__init__(robot, policies, observer)  # S, position (v0, exit 0), iterations
        self.lighthouse = lighthouse
        self.P = self.S  # S as the explorer perceives it (a probing lighthouse's v0 carries its virtual head)
        self.beacon: Beacon | None = None
        self._v0_entries: dict[Signature, int] = {}
        self._v0_sigs: list[Signature] = []

    # -- lines 1-3 -----------------------------------------------------------
    def start(self) -> None:
        """Establish the lighthouse at v0 (line 1: Algorithm 3.1 drops its directional marker pointing at the
        faced exit; a searched lighthouse walks to its v0 first); S = {v0}; U = its exits; the robot at v0,
        entered by exit 0."""
        self.beacon = self.lighthouse.establish(self.robot, self.S)
        self.robot = self.beacon.robot(self.robot)  # probes at v0 if its back-link needs them (Figure 3.21(b), §5.1)
        self.P = self.beacon.perceived
        self._v0_entries = self.beacon.table
        degree = self.S.degree(V0)
        self._v0_sigs = [signature_at(self.P, V0, e) for e in range(degree)]  # P^E's last perception (§3.3)
        self.S.unexplored = [(V0, i) for i in range(degree)]
        self.position = (V0, 0)

    def lighthouse_entry(self, sig: Signature) -> int | None:
        """The exit of v0 the robot entered by, if ``sig`` is the lighthouse's (§3.3: place and back-link)."""
        return self._v0_entries.get(sig)

    # -- the explorer contract: start, step (done, models: the walker's) -------------
    def step(self) -> Iteration:
        """One step of the algorithm: for Algorithm 3.1, one iteration of lines 5–28."""
        return self.iterate()

    def explore(self) -> PartialMap:
        """Run to termination (U empty) and return S."""
        self.start()
        while not self.done():
            self.step()
        return self.S

    # -- lines 5-28: the template ------------------------------------------------
    def iterate(self) -> Iteration:
        """One pass through lines 5–28, calling the hooks at the points Chapter 4 modifies."""
        _, _, parent = tree = bfs(self.S, self.position[0])
        it = self.iteration_type(len(self.iterations) + 1, self.policies.choose_edge(self.S, tree[0]))  # line 5
        vk, i = it.edge
        self.travel_to(vk, parent)  # line 6
        it.signature = sig = self.take_exit(i, "new")  # line 7
        entry = self.lighthouse_entry(sig)
        if entry is not None:  # the marker: place and back-link at once (§3.3)
            self.loop_augment(it, (V0, entry), by_marker=True)
        else:
            self.on_enter(it, sig)
            confirmed, heading = self.validate(it, sig)  # lines 8-20
            if confirmed is not None:  # lines 22-25
                self.loop_augment(it, confirmed.dart)
                self.position = self.arrival(confirmed)
            else:  # lines 26-28
                self.non_loop_augment(it, sig, heading)
                self.after_non_loop(it)
        self.after_join(it)
        return self.record(it)

    # -- the hooks (Algorithm 3.1: nothing, or its own step) -----------------------
    def on_enter(self, it: Iteration, sig: Signature) -> None:
        """After line 7, before H: the robot stands at v_u, entered by e (Algorithm 3.1: nothing more)."""

    def arrival(self, h: Hypothesis) -> MapDart:
        """Where the robot is once h' is confirmed (lines 19–20): v0, entered as P^E's last perception says."""
        return h.arrival

    def after_non_loop(self, it: Iteration) -> None:
        """After lines 27–28: v_u is S's newest vertex and the robot stands there (Algorithm 3.1: nothing)."""

    def after_join(self, it: Iteration) -> None:
        """After S is augmented by ``it.joined`` (lines 24–25, 27–28 or the marker's join; Algorithm 3.1: nothing)."""

    # -- lines 8-20 --------------------------------------------------------------
    def hypotheses(self, it: Iteration, sig: Signature) -> list[Hypothesis]:
        """H: unexplored darts (v_k' ≠ v_k) whose known end shows v_u's signature, with M and P^E (lines 8, 11-12).

        One tree to v0 per iteration serves every hypothesis: the path from
        v_k' is its first motion (which depends on e') followed by the tree
        path from v_k''s parent, computed once per vertex.
        """
        found, lengths = [], []
        toward: dict[int, int] | None = None
        tails: dict[int, tuple] = {}
        make = self.hypothesis_type
        for dart in hypothesis_darts(self.S, self.P, sig, it.edge[0]):  # P: S with a virtual v0
            v, i = dart
            if toward is None:
                toward = tree_to_v0(self.S, self.policies)
            motions, expected, arrival = self._tail(v, toward, tails)
            first = (toward[v] - i) % self.S.degree(v)
            found.append(make(dart, (first,) + motions, expected, arrival))
            lengths.append(len(motions) + 1)
        return self.policies.order_hypotheses(found, lengths)

    def _tail(self, v: int, toward: dict[int, int], tails: dict[int, tuple]) -> tuple:
        """Motions and expected signatures after leaving ``v`` toward v0, and the arrival dart at v0."""
        if v in tails:
            return tails[v]
        path = []
        x = v
        while x != V0 and x not in tails:
            y, entry = self.S.target((x, toward[x]))
            path.append((x, y, entry))
            x = y
        motions, expected, arrival = ((), (), None) if x == V0 else tails[x]
        for x, y, entry in reversed(path):
            if y == V0:
                motions, expected, arrival = (), (self._v0_sigs[entry],), (y, entry)
            else:
                motions = ((toward[y] - entry) % self.S.degree(y),) + motions
                expected = (signature_at(self.S, y, entry),) + expected
            tails[x] = (motions, expected, arrival)
        return tails[v]

    def validate(self, it: Iteration, sig: Signature) -> tuple[Hypothesis | None, int]:
        """Test hypotheses in turn (lines 8-20).

        Returns the confirmed hypothesis (the robot is then at v0), or None and
        the robot's heading at v_u: its entry edge counted from e.
        """
        it.hypotheses = self.hypotheses(it, sig)
        return validate_in_turn(self.robot, it.hypotheses, sig.degree, self.retrace)

    def retrace(self, done: list[int], degrees: list[int]) -> None:
        """Execute the reverse of the motions ``done`` (line 17): 0, then −l mod deg back to v_u."""
        retrace_motions(self.robot, done, degrees)

    # -- lines 22-28 -----------------------------------------------------------
    def loop_augment(self, it: Iteration, far: MapDart, by_marker: bool = False) -> None:
        """Add e/e' = (v_k, v_k') with the existing indices; remove e' from U; the robot stands at v_k', entered
        by e' (the marker's join, ``by_marker``, or the caller sets the pose M ends at)."""
        super().loop_augment(it, far)
        it.by_marker = by_marker
        self.position = far

    def non_loop_augment(self, it: Iteration, sig: Signature, heading: int = 0, sensed: bool = True) -> int:
        """Add v_u and e; e is v_u's exit 0, the rest numbered clockwise and added to U; S records the markers
        seen at v_u (e.g. the far end of a marked edge, §6.1)."""
        return super().non_loop_augment(it, sig, heading, sensed)
