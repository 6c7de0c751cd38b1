"""Seeded faults: Algorithm 3.1 explorers with one mistake each that a real implementer could make (§3.3–3.4).

Each is a :class:`~topomark.reference.explorers.algorithm31.LighthouseExplorer` subclass
overriding the smallest method that contains the mistake.  They use only the
robot interface (motions, perceptions, the marker drop): none of them peeks
at the world.  ``tests/test_seeded_faults.py`` checks that the checker
(:class:`~topomark.reference.run.checker.Checker`) catches every one.
"""

from __future__ import annotations

from topomark.reference.explorers.algorithm31 import V0, LighthouseExplorer

__all__ = ["FAULTS"]


class TrustsFirstHypothesis(LighthouseExplorer):
    """Accepts the first loop-closing hypothesis without walking its path (lines 11-20 skipped)."""

    def validate(self, it, sig):
        it.hypotheses = self.hypotheses(it, sig)
        if not it.hypotheses:
            return None, 0
        it.hypotheses[0].outcome = "case 3"
        return it.hypotheses[0], 0


class ConfirmsOnPartialMatch(LighthouseExplorer):
    """Walks M but compares only the perceptions before the last: case (2) is taken for case (3)."""

    def validate(self, it, sig):
        it.hypotheses = self.hypotheses(it, sig)
        heading = 0
        for h in it.hypotheses:
            done, degrees, perceived = [], [sig.degree], []
            for step, (motion, want) in enumerate(zip(h.motions, h.expected)):
                physical = (motion - heading) % sig.degree if step == 0 else motion
                got = self.robot.move(physical, "validation")
                done.append(physical)
                degrees.append(got.degree)
                perceived.append(got)
                if got != want and step < len(h.motions) - 1:  # BUG: the final perception is never compared
                    h.outcome = "case 1"
                    break
            h.perceived = tuple(perceived)
            if h.outcome == "untested":
                h.outcome = "case 3"
                return h, heading
            self.retrace(done, degrees)
            heading = (heading + done[0]) % sig.degree
        return None, heading


class OffByOneRelativeExit(LighthouseExplorer):
    """Converts an absolute exit to a motion as (exit - entry - 1) when walking S to v_k."""

    def travel_to(self, target, parent):
        path = []
        x = target
        while x != self.position[0]:
            path.append(parent[x])
            x = parent[x][0]
        v, entry = self.position
        for u, exit_ in reversed(path):
            self.robot.move((exit_ - entry - 1) % self.S.degree(v), "travel")  # BUG: - 1
            v, entry = self.S.arc((u, exit_))
        self.position = (v, entry)


class WrongReverseMotion(LighthouseExplorer):
    """Retraces with the same motions instead of their reverses (l instead of -l mod deg)."""

    def retrace(self, done, degrees):
        self.robot.move(0, "retrace")
        for t in range(len(done) - 1, 0, -1):
            self.robot.move(done[t] % degrees[t], "retrace")  # BUG: should be (-done[t]) % degrees[t]


class NoRealign(LighthouseExplorer):
    """Does not re-align to the entry edge e after retracing: assumes it still faces e."""

    def validate(self, it, sig):
        confirmed, heading = super().validate(it, sig)
        return confirmed, 0  # BUG: the heading accumulated over retraces is dropped


class KeepsLoopDartInU(LighthouseExplorer):
    """Forgets to remove e' from U on a loop closure (line 25)."""

    def loop_augment(self, it, far, by_marker=False):
        self.S.add_edge(it.edge, far)  # BUG: no self.S.unexplored.remove(far)
        it.kind, it.joined, it.by_marker = "loop", (it.edge, far), by_marker
        self.position = far


class NewVertexWrongReference(LighthouseExplorer):
    """Numbers the new vertex's exits from the robot's current entry edge but puts e at +heading, not -heading."""

    def non_loop_augment(self, it, sig, heading):
        d = sig.degree
        e_exit = heading % d  # BUG: relative to the current entry, e is exit (-heading) mod d
        u = self.S.add_vertex(d)
        self.S.add_edge(it.edge, (u, e_exit))
        self.S.unexplored.extend((u, i) for i in range(d) if i != e_exit)
        it.kind, it.joined = "non-loop", (it.edge, (u, e_exit))
        self.position = (u, 0)


class UndirectedMarker(LighthouseExplorer):
    """Treats the directional marker as undirected: knows it is at v0, guesses the back-link (first open exit)."""

    def loop_augment(self, it, far, by_marker=False):
        if by_marker:  # BUG: the marker's direction gives the entry exit; this ignores it
            far = next(d for d in self.S.unexplored if d[0] == V0)
        super().loop_augment(it, far, by_marker)


class MisindexedLoopEdge(LighthouseExplorer):
    """Joins a confirmed loop edge at the next open exit of v_k' instead of e' itself."""

    def loop_augment(self, it, far, by_marker=False):
        if not by_marker:
            opens = sorted(d for d in self.S.unexplored if d[0] == far[0])
            far = opens[(opens.index(far) + 1) % len(opens)]  # BUG: off by one among v_k''s open exits
        super().loop_augment(it, far, by_marker)


class OneDartPerVertex(LighthouseExplorer):
    """Considers only one unexplored dart per candidate vertex: misses the other back-links."""

    def hypotheses(self, it, sig):
        seen, kept = set(), []
        for h in super().hypotheses(it, sig):
            if h.dart[0] not in seen:  # BUG: a vertex with two open exits gives two hypotheses
                seen.add(h.dart[0])
                kept.append(h)
        return kept


FAULTS = {cls.__name__: cls for cls in (
    TrustsFirstHypothesis, ConfirmsOnPartialMatch, OffByOneRelativeExit, WrongReverseMotion, NoRealign,
    KeepsLoopDartInU, NewVertexWrongReference, UndirectedMarker, MisindexedLoopEdge, OneDartPerVertex,
)}
