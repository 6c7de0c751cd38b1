"""Replaying the algorithm layer of Algorithm 3.1's family: S and U rebuilt from the iterations (``spec/trace.md``).

The family ``algorithm-3.1`` (``basic`` and the Chapter 4 enhancements) has
one algorithm-layer record, the ``iteration``.  :class:`Algorithm31Layer`
rebuilds the map S and the unexplored darts U from them, on top of the robot
layer (:class:`~topomark.reference.replay.robot_layer.RobotLayer`), and raises
:class:`~topomark.reference.replay.divergence.Diverged` at the first false claim:

* the start: the lighthouse is established before any move — trace@1's one
  ``drop`` of the directional vertex marker, or trace@2's ``op`` records,
  exactly the header's lighthouse's operations
  (:data:`~topomark.reference.explorers.lighthouses.LIGHTHOUSES`) and none
  after them; S = v0 with what the robot sensed there after them recorded
  (:meth:`~topomark.spec.mapstate.PartialMap.mark_as_sensed`), and the
  recognition table: v0's perception from each entry ↦ that entry (for a
  lighthouse recognised by probing, read on S as perceived,
  :meth:`~topomark.reference.explorers.lighthouses.Lighthouse.perceive`);
  a lighthouse that moves to establish (Figure 3.21(b)'s script, §5.1/§6.1's
  walk) makes ``establish`` (and, searching, ``probe``) moves first, v0 is
  where the robot then stands, and φ is anchored there;
* ``probe`` moves only after the new edge, for a lighthouse recognised by
  probing; an iteration's ``signature`` at v0 may be its probed perception
  of the new move's raw one;
* every move's ``purpose`` fits the loop body: ``travel`` moves, then exactly
  one ``new`` move whose perception is the iteration's ``signature``, then
  ``validation``/``retrace`` (only in an iteration with hypotheses) and
  ``expansion`` (only for Enhancements 4/5, as many as the iteration's
  ``enhancement.expansion``); ``other`` anywhere after the start;
* every ``iteration``: ``by_marker`` is true exactly when v_u showed the
  lighthouse's signature (the table holds it: then no hypotheses and a loop
  join); its hypotheses re-checked on the rebuilt S by
  :func:`~topomark.reference.replay.hypotheses.check_hypotheses`; S and U rebuilt from
  the joins (a non-loop join adds a vertex of the ``signature``'s degree with
  the marks it shows, its other exits join U; a loop join removes e' from U;
  e itself is taken from U) — or U taken from the optional ``unexplored`` —
  and I-1 and I-2 (§3.4) must hold, φ anchored at v0 (map v0 exit 0 ↦
  the robot's state once v0 is established, as the checker anchors it;
  :class:`~topomark.spec.invariants.IncrementalInvariants`; a wrong join is
  reported before hypothesis records that contradict it);
* the ``end``: m iterations, U empty, S extended-isomorphic to the world with
  the markers dropped (§3.1.3).
"""

from __future__ import annotations

import json
from typing import Any, cast

from topomark.spec.errors import CheckFailure, Violation
from topomark.spec.invariants import IncrementalInvariants
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature, back_link_table, signature_at
from topomark.spec.world import World

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.replay.divergence import Diverged, diverge
from topomark.reference.explorers.lighthouses import Lighthouse
from topomark.reference.replay.hypotheses import check_hypotheses
from topomark.reference.run.map_check import check_map
from topomark.reference.replay.robot_layer import RobotLayer, marker_op
from topomark.reference.trace.header import header_policies
from topomark.reference.trace.reader import signature

__all__ = ["Algorithm31Layer"]


class Algorithm31Layer:
    """S, U and the loop body's bookkeeping, rebuilt record by record."""

    def __init__(self, robot: RobotLayer, world: World, header: dict[str, Any], lighthouse: Lighthouse, source: str):
        self.robot = robot
        self.trace2 = "family" in header  # a trace@2: the start is op records, not trace@1's drop
        self.world = world
        self.lighthouse = lighthouse
        self.policies = header_policies(header["policies"], f"{source} line 1")
        self.enhancement = getattr(algorithm_spec(header["algorithm"]).factory, "enhancement", None)
        self.S: PartialMap | None = None
        self.table: dict[Signature, int] = {}  # v0's signature from each entry -> that entry
        self.ops: list[dict] = []  # the start's op records so far (trace@2)
        self.iterations = 0
        self.new_perception: str | None = None  # the perception of this iteration's new move, once made
        self.purposes: dict[str, int] = {}  # this iteration's moves by purpose
        self.invariants: IncrementalInvariants | None = None
        self.P: PartialMap | None = None  # S as the explorer perceives it (lighthouses.Lighthouse.perceive)
        self.raw: set[str] = set()  # v0's own signatures, for a lighthouse recognised by probing
        self.anchor = robot.start
        self.establishing = 0  # establish moves before v0 is established

    # -- the start: the lighthouse --------------------------------------------------
    def drop(self, rec: dict) -> None:
        """trace@1's drop of the directional vertex marker (Algorithm 3.1 line 1)."""
        if self.S is not None:
            diverge("drop", "one marker drop (Algorithm 3.1 line 1)", "a second drop")
        v, _ = self.robot.sim.state
        degree = self.robot.sim.world.degree(v)
        if not 0 <= rec["direction"] < degree:
            diverge("drop", f"a direction 0..{degree - 1}", str(rec["direction"]))
        self.robot.robot.drop_marker(rec["direction"])
        got = str(self.robot.robot.sense())
        if rec["signature"] != got:
            diverge("drop", f"signature {got}", rec["signature"])
        self.establish(got)

    def op(self, rec: dict, sensed: str) -> None:
        """A trace@2 op, already carried out on the world: it must be the lighthouse's next operation."""
        where = f"op {self.robot.ops}"
        ops = self.lighthouse.ops
        if self.S is not None or len(self.ops) == len(ops):
            diverge(where, f"no marker operation after the {self.lighthouse.name} lighthouse's {len(ops)} "
                           "(Algorithm 3.1 establishes it at the start only, line 1)",
                    json.dumps(marker_op(rec).to_json()), check="marker")
        want = ops[len(self.ops)]
        if marker_op(rec) != want:
            diverge(where, f"the {self.lighthouse.name} lighthouse's operation {len(self.ops) + 1} of {len(ops)}: "
                           f"{json.dumps(want.to_json())}", json.dumps(marker_op(rec).to_json()), check="marker")
        self.ops.append(rec)

    def ready(self, where: str, before: str, expected_1: str, found_1: str) -> PartialMap:
        """S, once the lighthouse is established (a trace@2's ops, once all made, establish it here); else a
        divergence: trace@1's words ``expected_1``/``found_1``, or the lighthouse's operations ``before`` what."""
        light = self.lighthouse
        if self.S is None and self.trace2 and len(self.ops) == len(light.ops):
            motions = sum(isinstance(x, int) for x in light.script)
            if light.script and self.establishing != motions:
                diverge(where, f"the {light.name} lighthouse's {motions} establish move(s) (its script)",
                        str(self.establishing), check="marker")
            moved = light.script or light.search  # v0 is where the robot stands now, not where it dropped last
            self.establish(str(self.robot.robot.sense()) if moved else self.ops[-1]["signature"])
        if self.S is None and not self.trace2:
            diverge(where, expected_1, found_1)
        if self.S is None:
            diverge(where, f"the {self.lighthouse.name} lighthouse's {len(self.lighthouse.ops)} marker operation(s) "
                           f"before {before} (Algorithm 3.1 line 1)", f"{len(self.ops)}")
        return self.S

    def establish(self, sensed: str) -> None:
        v, _ = self.robot.sim.state
        degree = self.robot.sim.world.degree(v)
        S = PartialMap()
        v0 = S.add_vertex(degree)
        S.mark_as_sensed(v0, signature(sensed, "v0"), 0)
        self.P = self.lighthouse.perceive(S)  # a probing lighthouse's v0 as the explorer perceives it
        self.table, bad = back_link_table(self.P, v0, f"v0 (lighthouse {self.lighthouse.name})")
        if bad is not None:
            raise Diverged(bad)
        self.raw = {str(signature_at(S, v0, e)) for e in range(degree)} if self.lighthouse.probing else set()
        self.anchor = self.robot.sim.state  # φ: map v0 exit 0 ↦ the robot's state once v0 is established
        S.unexplored = [(v0, i) for i in range(degree)]
        self.S = S

    # -- the loop body ---------------------------------------------------------------
    def purpose(self, purpose: str, where: str) -> None:
        """The move's purpose fits the loop body: travel*, then the one new edge, then the rest (lines 5-28);
        before them only the lighthouse's own moves, if it moves to establish: a search's ``establish``/``probe``
        moves, a script's drop trip (``drop``; ``establish`` in traces written before drop trips were tagged)."""
        light = self.lighthouse
        if self.S is None and purpose in ("establish", "probe", "drop") and (light.script or light.search):
            if purpose == "probe" and not light.search or purpose == "drop" and not light.script:
                diverge(where, f"the {light.name} lighthouse's establish moves only before the first iteration",
                        f"a {purpose} move")
            self.establishing += purpose in ("establish", "drop")
            return
        self.ready(where, "any move", "the marker drop before any move (Algorithm 3.1 line 1)", f"a {purpose} move")
        after_new = self.new_perception is not None
        if purpose in ("establish", "drop"):
            diverge(where, f"{purpose} moves only before the first iteration (line 1)", "one after it")
        if purpose == "probe" and not (after_new and light.probing):
            diverge(where, "probe moves only after the new edge, for a lighthouse recognised by probing "
                           "(Figure 3.21(b), §5.1)", f"a probe move ({light.name})")
        if purpose == "new" and after_new:
            diverge(where, f"one new move in iteration {self.iterations + 1}", "a second new move")
        if purpose == "travel" and after_new:
            diverge(where, "travel to v_k only before the new edge (line 6)", "a travel move after it")
        if purpose in ("validation", "retrace", "expansion") and not after_new:
            diverge(where, f"{purpose} moves only after the new edge of iteration {self.iterations + 1}",
                    f"a {purpose} move before it")
        enh = self.enhancement
        if purpose == "expansion" and not (enh is not None and (enh.expand_new or enh.expand_place)):
            diverge(where, "no expansion moves (only Enhancements 4 and 5 expand signatures)", "an expansion move")
        self.purposes[purpose] = self.purposes.get(purpose, 0) + 1

    def moved(self, rec: dict, perception: str) -> None:
        """The move was replayed on the world and sensed ``perception``."""
        if rec["purpose"] == "new":
            self.new_perception = perception

    def iteration(self, rec: dict, where: str) -> None:
        self.iterations += 1
        it = f"iteration {self.iterations}"
        S = self.ready(it, "the first iteration", "the marker drop before the first iteration", "no drop")
        if rec["iteration"] != self.iterations:
            diverge(it, f"iteration number {self.iterations}", str(rec["iteration"]))
        if self.new_perception is None:
            diverge(it, "the new move (purpose \"new\", line 7) before its iteration record", "none")
        sig = signature(rec["signature"], where)
        probed = sig in self.table and self.new_perception in self.raw  # v0, perceived after probing
        if rec["signature"] != self.new_perception and not probed:
            diverge(it, f"v_u's signature {self.new_perception} (perceived on the new edge)", rec["signature"])
        self.claims(rec, sig, it)
        e = tuple(rec["edge"])
        if e not in S.unexplored:
            diverge(it, f"e = {list(e)} taken from U", "an edge not in U", "Algorithm 3.1 line 5")
        S.unexplored.remove(e)
        # H is judged on S and U as they were before the join, reported after I-1/I-2: a wrong join outranks
        # records that contradict it.
        false = None if rec["by_marker"] else check_hypotheses(cast(PartialMap, self.P), rec, sig, self.policies, self.enhancement, it,
                                                               where)
        self.new_perception, self.purposes = None, {}
        self.join(rec, sig, it)
        if "unexplored" in rec:
            S.unexplored = [tuple(d) for d in rec["unexplored"]]
        if self.invariants is None:
            self.invariants = IncrementalInvariants(S, self.robot.sim.world, ((0, 0), self.anchor))
        bad = self.invariants.update()
        if bad is not None:
            raise Diverged(Violation(bad.check, bad.where, bad.expected, bad.found,
                                     f"{it}" + (f"; {bad.detail}" if bad.detail else "")))
        if false is not None:
            raise Diverged(false)

    def claims(self, rec: dict, sig: Signature, it: str) -> None:
        """The iteration's claims about itself: by_marker, its enhancement counters, moves that need hypotheses."""
        shows = sig in self.table
        if rec["by_marker"] != shows:
            diverge(it, f"by_marker {str(shows).lower()} (v_u's signature {sig} {'is' if shows else 'is not'} "
                        f"the {self.lighthouse.name} lighthouse's: v0's from one of its entries)",
                    f"by_marker {str(rec['by_marker']).lower()}")
        if shows and (rec["hypotheses"] or rec["augmentation"] != "loop"):
            diverge(it, "v_u recognised as v0 by its marker: a loop join at once, no hypotheses (line 4)",
                    f"{len(rec['hypotheses'])} hypotheses, a {rec['augmentation']} join")
        if "enhancement" in rec and self.enhancement is None:
            diverge(it, "no enhancement counters (the header's algorithm is basic)", "an enhancement object")
        counters = rec.get("enhancement")
        expansion = self.purposes.get("expansion", 0)
        if counters is not None and counters["expansion"] != expansion:
            diverge(it, f"enhancement.expansion = {expansion} (the expansion moves since the last iteration)",
                    str(counters["expansion"]))
        tested = self.purposes.get("validation", 0) + self.purposes.get("retrace", 0)
        if tested and not rec["hypotheses"]:
            diverge(it, "validation and retrace moves only to test hypotheses", f"{tested} moves, no hypotheses")

    def join(self, rec: dict, sig: Signature, it: str) -> None:
        S = cast(PartialMap, self.S)  # ready: v0 is established
        e = tuple(rec["edge"])
        a, b = tuple(rec["joined"][0]), tuple(rec["joined"][1])
        if a != e:
            diverge(it, f"the join to start at e = {list(e)}", str(list(a)))
        if rec["augmentation"] == "non-loop":
            if b[0] != S.n:
                diverge(it, f"a non-loop join to the new vertex {S.n}", f"a join to vertex {b[0]}")
            if not 0 <= b[1] < sig.degree:
                diverge(it, f"an exit 0..{sig.degree - 1} of the new vertex", str(b[1]))
            u = S.add_vertex(sig.degree)
            S.mark_as_sensed(u, sig, b[1])  # the marks v_u showed, entered by exit b[1] (e.g. a marked edge's end)
            S.unexplored.extend((u, j) for j in range(sig.degree) if j != b[1])
        else:
            if b not in S.unexplored:
                diverge(it, f"e' = {list(b)} in U", "a dart not in U", "Algorithm 3.1 line 25")
            S.unexplored.remove(b)
        try:
            S.add_edge(a, b)
        except CheckFailure as exc:
            diverge(it, "a join of two open darts of S", str(exc))

    def end(self, rec: dict) -> None:
        if "outcome" in rec:  # the run stopped (failed, limit) before it had a map
            if self.S is not None and self.iterations == self.world.m and not self.S.unexplored:
                diverge("end", f"a run that stopped ({rec['outcome']}) before its map was complete",
                        f"S complete after all m = {self.world.m} iterations: the algorithm had finished",
                        check="trace claim")
            return
        S = self.ready("end", "the end", "a marker drop and m iterations", "no drop")
        world = self.world
        if self.iterations != world.m:
            diverge("end", f"m = {world.m} iterations", str(self.iterations))
        if self.new_perception is not None:
            diverge("end", "every new move followed by its iteration record", "a new move without one")
        if S.unexplored or not S.complete():
            diverge("end", "U empty and S complete", f"U = {S.unexplored[:5]}")
        verdict = check_map(self.robot.sim.world.with_start(world.start), S.to_world())
        if not verdict.isomorphic:
            m = cast(Violation, verdict.result.mismatch)  # not isomorphic: the mismatch
            raise Diverged(Violation("extended isomorphism", m.where, m.expected, m.found, "the final map"))
