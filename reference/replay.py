"""``replay``: verify a ``topomark/trace@1`` trace recorded by any implementation (thesis §3.1–3.4).

A trace (``spec/trace.md``) claims a run of Algorithm 3.1: the marker drop,
every motion with the perception it produced and its purpose, every
iteration's hypotheses and join, the cost and the recorder's verdict.
:func:`replay` re-executes it on the world and checks every claim, in order
(well-formedness — the header's algorithm and policies, vocabularies, field
sets, signatures, JSON limits — is :mod:`topomark.reference.tracefile`'s,
exit 2):

* the ``drop`` comes before any move; every ``move``: replaying the motions
  from the world's start (:mod:`topomark.spec.robot`) gives exactly the
  claimed perceptions; the step numbers run 1, 2, ...;
* every move's ``purpose`` fits the loop body: ``travel`` moves, then exactly
  one ``new`` move whose perception is the iteration's ``signature``, then
  ``validation``/``retrace`` (only in an iteration with hypotheses) and
  ``expansion`` (only for Enhancements 4/5, as many as the iteration's
  ``enhancement.expansion``); ``other`` is accepted anywhere after the drop;
* every ``iteration``: ``by_marker`` is true exactly when v_u's signature shows
  the marker (then no hypotheses and a loop join); its hypotheses are
  re-checked on the rebuilt S by :func:`topomark.reference.hypcheck.
  check_hypotheses` (H, the hypothesis policy's order, (M, P^E), Lemma 1,
  outcomes against ``perceived``, the confirmed one the true join, the
  ``pruned``/``without_motion`` counters); S and U are rebuilt from the joins
  (a non-loop join adds a vertex whose degree is that of the iteration's
  ``signature``, its other exits join U; a loop join removes e' from U; e
  itself is taken from U) — or U is taken from the record's optional
  ``unexplored`` field — and I-1 and I-2 (§3.4) must hold, φ anchored at the
  lighthouse (:class:`~topomark.spec.invariants.IncrementalInvariants`, as
  the checker does; a wrong join is reported before hypothesis records that
  contradict it);
* the ``end``: the claimed cost equals the traversals replayed; there were m
  iterations, U is empty and the rebuilt map is extended-isomorphic to the
  world with the dropped marker (§3.1.3); and the recorder's verdict:
  ``verified: true`` claims all of this; ``verified: false`` with a
  ``violation`` claims a failure — if replay finds none that claim is false
  (exit 1, check ``"trace claim"``), if replay diverges the trace is
  *consistent* (it records its own failure: ``recorded_failure``) and the
  verdict is still negative (exit 1); ``verified: false`` with ``violation:
  null`` is an unjudged run (``explore --no-check``, ``drive`` without a
  world) and replay's own verdict stands.  Which check the recorder names is
  not compared with replay's: a recorder stops at its first failure, so
  replay typically finds the run truncated rather than the same check.

Not checked, because the trace does not determine it: which e the edge
policy picks (it needs the explorer's believed position between moves),
the ``known`` counter of Enhancement 3 (perceptions recorded in its private T),
and what :mod:`~topomark.reference.hypcheck` lists.  Nothing else a record
carries is left unchecked.

The first divergence is reported with its line and step or iteration, what
the world (or the spec) expected and what the trace claims.  The trace is read
lazily, line by line (:func:`load_trace`); after a divergence the rest is
still read, because bad input anywhere (:class:`~topomark.spec.errors.
InvalidInput`) outranks a divergence.  A trace recorded on a world of a
different size is bad input too.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Iterable

from topomark.spec.errors import CheckFailure, InvalidInput, Violation
from topomark.spec.invariants import IncrementalInvariants, lighthouse_anchor
from topomark.spec.mapstate import PartialMap
from topomark.spec.world import World

from .algorithms import ALGORITHMS
from .explore import prepare_world
from .hypcheck import check_hypotheses
from .mapcheck import check_map
from .simulator import Simulator
from .tracefile import EVENTS, header_policies, load_trace, parse_trace, signature

__all__ = ["ReplayResult", "replay", "load_trace", "parse_trace", "EVENTS"]


@dataclass(frozen=True)
class ReplayResult:
    ok: bool
    message: str
    cost: int
    iterations: int
    divergence: Violation | None = None
    line: int | None = None
    recorded_failure: bool = False  # the trace's end claims the failure replay found

    def to_json(self) -> dict[str, Any]:
        return {"verified": self.ok, "message": self.message, "cost": self.cost, "iterations": self.iterations,
                "line": self.line, "divergence": None if self.divergence is None else self.divergence.to_json(),
                "recorded_failure": self.recorded_failure}


# -- replaying ------------------------------------------------------------------
class _Diverged(Exception):
    def __init__(self, violation: Violation):
        super().__init__(str(violation))
        self.violation = violation


def _diverge(where: str, expected: str, found: str, detail: str = "", check: str = "replay") -> None:
    raise _Diverged(Violation(check, where, expected, found, detail))


class _Replayer:
    def __init__(self, world: World, header: dict[str, Any], source: str):
        bare, state = prepare_world(world)
        self.world = world
        self.sim = Simulator(bare, state, {"directional-vertex": 1})
        self.robot = self.sim.robot()
        self.source = source
        self.policies = header_policies(header["policies"], f"{source} line 1")
        self.enhancement = getattr(ALGORITHMS[header["algorithm"]], "enhancement", None)
        self.S: PartialMap | None = None
        self.steps = 0
        self.iterations = 0
        self.new_perception: str | None = None  # the perception of this iteration's new move, once made
        self.purposes: dict[str, int] = {}  # this iteration's moves by purpose
        self.invariants: IncrementalInvariants | None = None

    def drop(self, rec: dict) -> None:
        if self.S is not None:
            _diverge("drop", "one marker drop (Algorithm 3.1 line 1)", "a second drop")
        v, entry = self.sim.state
        degree = self.sim.world.degree(v)
        if not 0 <= rec["direction"] < degree:
            _diverge("drop", f"a direction 0..{degree - 1}", str(rec["direction"]))
        self.robot.drop_marker(rec["direction"])
        got = str(self.robot.sense())
        if rec["signature"] != got:
            _diverge("drop", f"signature {got}", rec["signature"])
        self.S = PartialMap()
        v0 = self.S.add_vertex(degree)
        self.S.mark_vertex(v0, head=rec["direction"])
        self.S.unexplored = [(v0, i) for i in range(degree)]

    def move(self, rec: dict) -> None:
        self.steps += 1
        where = f"step {self.steps}"
        if rec["step"] != self.steps:
            _diverge(where, f"step number {self.steps}", str(rec["step"]), "steps must run 1, 2, 3, ...")
        self.purpose(rec["purpose"], where)
        v, _ = self.sim.state
        degree = self.sim.world.degree(v)
        if not 0 <= rec["motion"] < degree:
            _diverge(where, f"a motion 0..{degree - 1} (the robot is at a vertex of degree {degree})",
                     f"motion {rec['motion']}")
        got = str(self.robot.move(rec["motion"], "other"))
        if rec["perception"] != got:
            _diverge(where, f"perception {got} (motion {rec['motion']} on the world)",
                     f"perception {rec['perception']}")
        if rec["purpose"] == "new":
            self.new_perception = got

    def purpose(self, purpose: str, where: str) -> None:
        """The move's purpose fits the loop body: travel*, then the one new edge, then the rest (lines 5-28)."""
        if self.S is None:
            _diverge(where, "the marker drop before any move (Algorithm 3.1 line 1)", f"a {purpose} move")
        after_new = self.new_perception is not None
        if purpose == "new" and after_new:
            _diverge(where, f"one new move in iteration {self.iterations + 1}", "a second new move")
        if purpose == "travel" and after_new:
            _diverge(where, "travel to v_k only before the new edge (line 6)", "a travel move after it")
        if purpose in ("validation", "retrace", "expansion") and not after_new:
            _diverge(where, f"{purpose} moves only after the new edge of iteration {self.iterations + 1}",
                     f"a {purpose} move before it")
        enh = self.enhancement
        if purpose == "expansion" and not (enh is not None and (enh.expand_new or enh.expand_place)):
            _diverge(where, "no expansion moves (only Enhancements 4 and 5 expand signatures)", "an expansion move")
        self.purposes[purpose] = self.purposes.get(purpose, 0) + 1

    def iteration(self, rec: dict, where: str) -> None:
        self.iterations += 1
        it = f"iteration {self.iterations}"
        S = self.S
        if S is None:
            _diverge(it, "the marker drop before the first iteration", "no drop")
        if rec["iteration"] != self.iterations:
            _diverge(it, f"iteration number {self.iterations}", str(rec["iteration"]))
        if self.new_perception is None:
            _diverge(it, "the new move (purpose \"new\", line 7) before its iteration record", "none")
        sig = signature(rec["signature"], where)
        if rec["signature"] != self.new_perception:
            _diverge(it, f"v_u's signature {self.new_perception} (perceived on the new edge)", rec["signature"])
        self.claims(rec, sig, it)
        e = tuple(rec["edge"])
        if e not in S.unexplored:
            _diverge(it, f"e = {list(e)} taken from U", "an edge not in U", "Algorithm 3.1 line 5")
        S.unexplored.remove(e)
        # H is judged on S and U as they were before the join, reported after I-1/I-2: a wrong join outranks
        # records that contradict it.
        false = None if rec["by_marker"] else check_hypotheses(S, rec, sig, self.policies, self.enhancement, it,
                                                               where)
        self.new_perception, self.purposes = None, {}
        self.join(rec, sig, it)
        if "unexplored" in rec:
            S.unexplored = [tuple(d) for d in rec["unexplored"]]
        if self.invariants is None:
            self.invariants = IncrementalInvariants(S, self.sim.world, lighthouse_anchor(S, self.sim.world))
        bad = self.invariants.update()
        if bad is not None:
            raise _Diverged(Violation(bad.check, bad.where, bad.expected, bad.found,
                                      f"{it}" + (f"; {bad.detail}" if bad.detail else "")))
        if false is not None:
            raise _Diverged(false)

    def claims(self, rec: dict, sig, it: str) -> None:
        """The iteration's claims about itself: by_marker, its enhancement counters, moves that need hypotheses."""
        shows = sig.vertex_direction is not None
        if rec["by_marker"] != shows:
            _diverge(it, f"by_marker {str(shows).lower()} (v_u's signature {sig} "
                         f"{'shows' if shows else 'does not show'} the directional marker)",
                     f"by_marker {str(rec['by_marker']).lower()}")
        if shows and (rec["hypotheses"] or rec["augmentation"] != "loop"):
            _diverge(it, "v_u recognised as v0 by its marker: a loop join at once, no hypotheses (line 4)",
                     f"{len(rec['hypotheses'])} hypotheses, a {rec['augmentation']} join")
        if "enhancement" in rec and self.enhancement is None:
            _diverge(it, "no enhancement counters (the header's algorithm is basic)", "an enhancement object")
        counters = rec.get("enhancement")
        expansion = self.purposes.get("expansion", 0)
        if counters is not None and counters["expansion"] != expansion:
            _diverge(it, f"enhancement.expansion = {expansion} (the expansion moves since the last iteration)",
                     str(counters["expansion"]))
        tested = self.purposes.get("validation", 0) + self.purposes.get("retrace", 0)
        if tested and not rec["hypotheses"]:
            _diverge(it, "validation and retrace moves only to test hypotheses", f"{tested} moves, no hypotheses")

    def join(self, rec: dict, sig, it: str) -> None:
        S = self.S
        e = tuple(rec["edge"])
        a, b = tuple(rec["joined"][0]), tuple(rec["joined"][1])
        if a != e:
            _diverge(it, f"the join to start at e = {list(e)}", str(list(a)))
        if rec["augmentation"] == "non-loop":
            if b[0] != S.n:
                _diverge(it, f"a non-loop join to the new vertex {S.n}", f"a join to vertex {b[0]}")
            if not 0 <= b[1] < sig.degree:
                _diverge(it, f"an exit 0..{sig.degree - 1} of the new vertex", str(b[1]))
            u = S.add_vertex(sig.degree)
            S.unexplored.extend((u, j) for j in range(sig.degree) if j != b[1])
        else:
            if b not in S.unexplored:
                _diverge(it, f"e' = {list(b)} in U", "a dart not in U", "Algorithm 3.1 line 25")
            S.unexplored.remove(b)
        try:
            S.add_edge(a, b)
        except CheckFailure as exc:
            _diverge(it, "a join of two open darts of S", str(exc))

    def end(self, rec: dict) -> None:
        world = self.world
        if rec["cost"] != self.steps:
            _diverge("end", f"cost {self.steps} (the traversals replayed)", f"cost {rec['cost']}")
        if self.S is None:
            _diverge("end", "a marker drop and m iterations", "no drop")
        if self.iterations != world.m:
            _diverge("end", f"m = {world.m} iterations", str(self.iterations))
        if self.new_perception is not None:
            _diverge("end", "every new move followed by its iteration record", "a new move without one")
        if self.S.unexplored or not self.S.complete():
            _diverge("end", "U empty and S complete", f"U = {self.S.unexplored[:5]}")
        verdict = check_map(self.sim.world.with_start(world.start), self.S.to_world())
        if not verdict.isomorphic:
            m = verdict.result.mismatch
            raise _Diverged(Violation("extended isomorphism", m.where, m.expected, m.found, "the final map"))


def _claim(end: dict) -> str:
    v = end["violation"]
    return "a verified run" if end["verified"] else "an unjudged run" if v is None else \
        f"a failed run: {Violation(v['check'], v['where'], v['expected'], v['found'], v['detail'])}"


def replay(world: World, records: Iterable[dict[str, Any]], source: str = "<trace>") -> ReplayResult:
    """Verify checked trace records (:func:`load_trace`, :func:`parse_trace`) against ``world``.

    The first divergence, or a positive verdict; a claimed failure replay does
    not reproduce is a divergence.  Bad input anywhere in the trace (even after
    the divergence) is raised as :class:`InvalidInput`.
    """
    records = iter(records)
    header = next(records)
    if (header["n"], header["m"]) != (world.n, world.m):
        raise InvalidInput(f"{source}: the trace was recorded on a world with n={header['n']}, m={header['m']}, "
                           f"but this world has n={world.n}, m={world.m}")
    r = _Replayer(world, header, source)
    line, rec = 1, header
    try:
        for line, rec in enumerate(records, 2):
            kind = rec["event"]
            if kind == "drop":
                r.drop(rec)
            elif kind == "move":
                r.move(rec)
            elif kind == "iteration":
                r.iteration(rec, f"{source} line {line}")
            elif kind == "end":
                r.end(rec)
    except _Diverged as exc:
        for rec in records:  # the rest must still be well-formed: bad input outranks a divergence
            pass
        failed = rec["violation"] is not None
        note = f"; consistent: the trace records its own failure ({_claim(rec)})" if failed else ""
        return ReplayResult(False, f"line {line}: {exc.violation}{note}", r.steps, r.iterations, exc.violation,
                            line, failed)
    if rec["violation"] is not None:
        false = Violation("trace claim", "end", "no violation (replay verifies the run)", _claim(rec),
                          "the trace claims a failure but replay finds none")
        return ReplayResult(False, f"line {line}: {false}", r.steps, r.iterations, false, line)
    note = "" if rec["verified"] else " (the recorder did not judge the run: verified false, no violation)"
    return ReplayResult(True, f"{r.steps} traversals, {r.iterations} iterations, every perception "
                              f"matches the world, every purpose and hypothesis record holds, Lemma 1, I-1/I-2 "
                              f"held after every iteration, the map is extended-isomorphic{note}",
                        r.steps, r.iterations)
