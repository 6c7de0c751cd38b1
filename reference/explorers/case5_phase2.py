"""Phase II of §6.2.1 Case 5: hypothesis-based validation once the robot has run out of markers (thesis
Algorithm 6.4 lines 16–35, Algorithm 6.5 lines 14–28 and 34–37), after Algorithm 3.1 (§3.3).

Both versions of Case 5 fall back, when a place cannot be told by its markers
any more, on Algorithm 3.1's test: every unexplored dart e' = (v_k', i') of U
whose known end shows v_u's signature (v_k' ≠ v_k) is a hypothesis h'; the
robot executes the motion sequence M_h' that would, if h' held, take it along
a simple path of S from v_k' to a place it can recognise *with its back-link*,
comparing each perception with the expected P^E_h'; the first mismatch rejects
h' (retrace to v_u, Algorithm 6.4 line 28 "back to v_u"), a full match confirms
it (loop augmentation), and no confirmed hypothesis means v_u is new.

What "a place it can recognise with its back-link" is differs per version, so
the explorer holding phase II (a :class:`PhaseTwo` object, composed in as
Chapter 4's techniques are) gives ``lighthouse_path(v)``: the darts of S to
follow from v_k' (Version-1: to the closest uniquely marked v_l, then on to a
marked neighbour v_n, Algorithm 6.4 lines 21–24; Version-2: to the
double-marked v0, whose double-marked edge gives the entry, Algorithm 6.5 and
§6.2.1 Case 5), and ``confirms(h)``, its listing's reading of a full match (Algorithm
6.4 line 29, Algorithm 6.5 line 23).  :class:`Host` lists all it needs.

Decision: phase II is implemented here rather than by handing the state to
:class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer`, whose
hypotheses always end at its one lighthouse v0 and whose S has no marks other
than the lighthouse's; the loop body (execute, compare, retrace, keep the
robot's heading at v_u) is Algorithm 3.1's
(:func:`~topomark.reference.explorers.algorithm31.validate_in_turn`), run over
a :class:`~topomark.reference.explorers.marker_walk.MarkerWalk`'s map, and the
records are Algorithm 3.1's :class:`~topomark.reference.explorers.algorithm31.Hypothesis`
(so ``explore`` counts hypotheses, rejections and confirmations as for Chapter 3).

Phase II's share of the cost: every traversal made while testing H (the
hypothesis walks and their retraces, purposes ``validation`` and ``retrace``)
is also counted in the host's ``phase_two_moves``
(:func:`counting`), so a report can say how much of the cost phase II
accounts for.  The travel to v_k and the new edge of a phase-II iteration are
the exploration's own (every version pays them) and are not counted there.

Examples
--------
>>> expected_walk.__name__
'expected_walk'
"""

from __future__ import annotations

from typing import Protocol, cast

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.mapstate import MapDart, PartialMap
from topomark.spec.signature import Signature, signature_at

from topomark.reference.explorers.algorithm31 import Hypothesis, hypothesis_darts, retrace_motions, validate_in_turn
from topomark.reference.explorers.marker_walk import MarkerStep
from topomark.reference.explorers.robot import Robot

__all__ = ["PhaseTwo", "Host", "PHASE_TWO", "TwoPhases", "expected_walk", "path_walk", "PhaseStep", "counting"]


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
    v = path[0][0]
    entry: int | None = None
    for x, exit_ in path:
        if x != v:
            raise AlgorithmFailed(f"internal: the path {path} is not a walk of S")
        if entry is not None:
            motions.append((exit_ - entry) % M.degree(x))
        v, entry = M.target((x, exit_))
        expected.append(signature_at(M, v, entry))
    return tuple(motions), tuple(expected), (v, cast(int, entry))  # the path has an edge


def counting(robot: Robot, host: "Host") -> Robot:
    """``robot``, each of whose moves also adds one to ``host.phase_two_moves``."""
    def move(motion: int, purpose: str = "other") -> Signature:
        host.phase_two_moves += 1
        return robot.move(motion, purpose)
    return Robot(move, robot.sense, robot.operate)


class Host(Protocol):
    """What a :class:`PhaseTwo` needs of the explorer holding it: a
    :class:`~topomark.reference.explorers.marker_walk.MarkerWalk` (``M``, ``robot``, ``position``, ``loop``,
    ``non_loop_augment``) with the version's two answers."""

    M: PartialMap
    robot: Robot
    position: MapDart
    phase_two_moves: int  # traversals made testing phase II's hypotheses

    def lighthouse_path(self, v: int) -> list[MapDart]:
        """The darts of S from v_k' = ``v`` to a place recognised with its back-link (a simple path)."""

    def confirms(self, h: Hypothesis) -> bool:
        """Whether a hypothesis whose perceptions matched P^E throughout is confirmed (the listing's reading)."""

    def loop(self, it: MarkerStep, far: MapDart) -> None: ...

    def non_loop_augment(self, it: MarkerStep, sig: Signature, heading: int = 0, sensed: bool = False) -> int: ...


class PhaseTwo:
    """Algorithm 3.1's hypothesis test over a :class:`Host`'s map, with the host's lighthouse path."""

    def hypotheses(self, host: Host, it: MarkerStep, sig: Signature) -> list[Hypothesis]:
        """H: unexplored darts (v_k' ≠ v_k) whose known end, entered by them, shows ``sig`` (same signature:
        marks and degree, Algorithm 6.4 lines 17–18, Algorithm 6.5 lines 15–16, 35–36)."""
        M = host.M
        found, paths = [], {}  # v_k' -> (its lighthouse path, the walk along it)
        for dart in hypothesis_darts(M, M, sig, it.edge[0]):
            v, i = dart
            if v not in paths:
                path = host.lighthouse_path(v)
                paths[v] = path, (path_walk(M, path) if path else None)
            found.append(expected_walk(M, dart, *paths[v]))
        return found

    def run(self, host: Host, it: MarkerStep, sig: Signature) -> None:
        """Test H (the robot at v_u, entered by e); loop augmentation on the confirmed h', else non-loop.

        A hypothesis is confirmed when it matched throughout and ``host.confirms`` it (Algorithm 6.5 line 23,
        corrected); each other one is retraced, "reject the hypothesis, back to v_u" (Algorithm 6.4 line 28).
        """
        it.hypotheses = self.hypotheses(host, it, sig)
        robot = counting(host.robot, host)
        h, heading = validate_in_turn(robot, it.hypotheses, sig.degree,
                                      lambda done, degrees: retrace_motions(robot, done, degrees), host.confirms)
        if h is not None:
            host.loop(it, h.dart)
            host.position = h.arrival
            return
        # Algorithm 6.4 line 35, Algorithm 6.5 line 28: v_u joins S unmarked, e its exit 0, the marks v_u showed
        # on arrival (Version-2: e0, or a loop edge of phase I) recorded in that frame, the robot at (v_u, heading)
        host.non_loop_augment(it, sig, heading, sensed=True)


PHASE_TWO = PhaseTwo()
"""The phase II every version of Case 5 holds."""


class TwoPhases:
    """What a counted-marker explorer with a phase II keeps (mixed in before it): the phase it is in, the iteration
    that ended phase I, and phase II's traversals, which :attr:`stats` reports for the bench's share of the cost."""

    step_type: type = PhaseStep  # the step's record keeps phase II's hypotheses
    phase_two = PHASE_TWO

    def __init__(self, robot, policies=None, observer=None, options=None):
        super().__init__(robot, policies, observer, options)
        self.phase = 1
        self.phase_two_moves = 0  # traversals testing phase II's hypotheses
        self.phase_two_from: int | None = None  # the iteration that ended phase I

    @property
    def stats(self) -> dict:
        """Phase II's traversals (hypothesis walks and retraces)."""
        return {"phase_two": self.phase_two_moves}
