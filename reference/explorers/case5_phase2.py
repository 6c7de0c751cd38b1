"""Phase II of §6.2.1 Case 5: hypothesis-based validation once the robot has run out of markers (thesis
L1720–L1722, Algorithm 6.4 lines 16–35, Algorithm 6.5 lines 14–28 and 34–37), after Algorithm 3.1 (§3.3).

Both versions of Case 5 fall back, when a place cannot be told by its markers
any more, on Algorithm 3.1's test: every unexplored dart e' = (v_k', i') of U
whose known end shows v_u's signature (v_k' ≠ v_k) is a hypothesis h'; the
robot executes the motion sequence M_h' that would, if h' held, take it along
a simple path of S from v_k' to a place it can recognise *with its back-link*,
comparing each perception with the expected P^E_h'; the first mismatch rejects
h' (retrace to v_u, Algorithm 6.4 line 28 "back to v_u"), a full match confirms
it (loop augmentation), and no confirmed hypothesis means v_u is new.

What "a place it can recognise with its back-link" is differs per version, so a
version gives :meth:`PhaseTwo.lighthouse_path`: the darts of S to follow from
v_k' (Version-1: to the closest uniquely marked v_l, then on to a marked
neighbour v_n, Algorithm 6.4 lines 21–24; Version-2: to the double-marked v0,
whose double-marked edge gives the entry, Algorithm 6.5 and L1770).

Decision: phase II is implemented here rather than by handing the state to
:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`, whose
hypotheses always end at its one lighthouse v0 and whose S has no marks other
than the lighthouse's; the loop body (execute, compare, retrace, keep the
robot's heading at v_u) is Algorithm 3.1's ``validate``/``retrace``, written
over a :class:`~topomark.reference.explorers.marker_walk.MarkerWalk`'s map, and
the records are Algorithm 3.1's :class:`~topomark.reference.explorers.algorithm31.Hypothesis`
(so ``explore`` counts hypotheses, rejections and confirmations as for Chapter 3).

Examples
--------
>>> expected_walk.__name__
'expected_walk'
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.algorithm31 import Hypothesis, hypothesis_darts, walk_hypothesis
from topomark.reference.explorers.marker_walk import MarkerStep

__all__ = ["PhaseTwo", "expected_walk", "path_walk", "PhaseStep"]


class PhaseStep(MarkerStep):
    """A :class:`MarkerStep` that keeps phase II's hypotheses in its JSON record."""

    def to_json(self) -> dict:
        out = super().to_json()
        out["hypotheses"] = [h.to_json() for h in self.hypotheses]
        return out


def expected_walk(M: PartialMap, dart: MapDart, path: list[MapDart],
                  walk: tuple[tuple[int, ...], tuple[Signature, ...], MapDart] | None = None) -> Hypothesis:
    """h' = ``dart`` = (v_k', i') with the motions that follow ``path`` (darts of S, the first at v_k') when the
    robot stands at v_k' entered by i', and the signatures S says it will sense (P^E).

    Only the first motion depends on i': the rest of the walk (``walk``, :func:`path_walk` of ``path``) is the
    same for every dart at v_k', so :meth:`PhaseTwo.hypotheses` computes it once per vertex."""
    v, entry = dart
    if not path:
        return Hypothesis(dart, (), (), dart)
    if path[0][0] != v:
        raise AlgorithmFailed(f"internal: the path {path} is not a walk of S from {dart}")
    rest, expected, arrival = walk or path_walk(M, path)
    return Hypothesis(dart, ((path[0][1] - entry) % M.degree(v),) + rest, expected, arrival)


def path_walk(M: PartialMap, path: list[MapDart]) -> tuple[tuple[int, ...], tuple[Signature, ...], MapDart]:
    """Along ``path`` (darts of S, non-empty): the motions after the first, the signatures sensed after each
    move, and the dart of arrival."""
    motions, expected = [], []
    v, entry = path[0][0], None
    for x, exit_ in path:
        if x != v:
            raise AlgorithmFailed(f"internal: the path {path} is not a walk of S")
        if entry is not None:
            motions.append((exit_ - entry) % M.degree(x))
        v, entry = M.arc((x, exit_))
        expected.append(signature_at(M, v, entry))
    return tuple(motions), tuple(expected), (v, entry)


class PhaseTwo:
    """Mixin for a :class:`MarkerWalk`: Algorithm 3.1's hypothesis test with a lighthouse path per version."""

    step_type = PhaseStep  # :meth:`MarkerWalk.step`'s record, with its phase-II hypotheses

    def lighthouse_path(self, v: int) -> list[MapDart]:
        """The darts of S from v_k' = ``v`` to a place recognised with its back-link (a simple path)."""
        raise NotImplementedError

    def hypotheses(self, it: MarkerStep, sig: Signature) -> list[Hypothesis]:
        """H: unexplored darts (v_k' ≠ v_k) whose known end, entered by them, shows ``sig`` (same signature:
        marks and degree, Algorithm 6.4 lines 17–18, Algorithm 6.5 lines 15–16, 35–36)."""
        found, paths = [], {}  # v_k' -> (its lighthouse path, the walk along it)
        for dart in hypothesis_darts(self.M, self.M, sig, it.edge[0]):
            v, i = dart
            if v not in paths:
                path = self.lighthouse_path(v)
                paths[v] = path, (path_walk(self.M, path) if path else None)
            found.append(expected_walk(self.M, dart, *paths[v]))
        return found

    def phase_two(self, it: MarkerStep, sig: Signature) -> None:
        """Test H (the robot at v_u, entered by e); loop augmentation on the confirmed h', else non-loop."""
        it.hypotheses = self.hypotheses(it, sig)
        heading = 0  # the robot's entry edge at v_u, counted from e (e is v_u's exit 0 if v_u is new)
        for h in it.hypotheses:
            done, degrees = walk_hypothesis(self.robot, h, sig.degree, heading)
            if h.outcome == "untested" and self.confirms(h):  # matched throughout (Algorithm 6.5 line 23, corrected)
                h.outcome = "case 3"
                self.loop(it, h.dart)
                self.position = h.arrival
                return
            self.retrace(done, degrees)  # Algorithm 6.4 line 28: "reject the hypothesis, back to v_u"
            heading = (heading + done[0]) % sig.degree
        self.join_new(it, sig, heading)  # Algorithm 6.4 line 35, Algorithm 6.5 line 28: v_u joins S unmarked

    def join_new(self, it: MarkerStep, sig: Signature, heading: int) -> None:
        """Non-loop augmentation after rejected hypotheses: e is v_u's exit 0, the marks v_u showed on arrival
        (entered by e) recorded in that frame, the robot's pose (v_u, ``heading``)."""
        u = self.add_vertex(sig.degree)
        self.add_edge(it.edge, (u, 0))
        self.M.unexplored.extend((u, i) for i in range(1, sig.degree))
        it.kind, it.joined = "non-loop", (it.edge, (u, 0))
        if sig.marked:  # a marked edge at an unmarked place (Version-2: e0, or a loop edge of phase I)
            self.M.mark_as_sensed(u, sig, 0)
        self.position = (u, heading)

    def confirms(self, h: Hypothesis) -> bool:
        """Whether a hypothesis whose perceptions matched P^E throughout is confirmed: yes (Algorithm 6.4
        line 29; Algorithm 6.5 line 23 read literally, "do not match throughout", would never confirm one)."""
        return True

    def retrace(self, done: list[int], degrees: list[int]) -> None:
        """The reverse of the motions ``done`` (Algorithm 3.1 line 17): 0, then −l mod deg, back to v_u."""
        self.robot.move(0, "retrace")
        for t in range(len(done) - 1, 0, -1):
            self.robot.move((-done[t]) % degrees[t], "retrace")
