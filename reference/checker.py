"""The checker: every loop condition of §3.4, after every iteration, against the truth.

The checker sees what the explorer may not — the world and the simulator's
true state — and judges the explorer's public state (S, U, its believed
position and its iteration records) with the spec's own predicates:

* **I-1** and **I-2** (with the edge-index condition), via
  :func:`topomark.spec.invariants.check_invariants`, φ anchored at the
  lighthouse's head dart;
* the bound function t = |E_G| − |E_S| strictly decreases and stays ≥ 0;
* **Lemma 1**: each hypothesis's pair (M, P^E) is unique in its iteration;
* the marker never moved after it was dropped;
* the explorer's believed position is where the robot really is (under φ);
* at termination: U empty, S ≅ G by extended isomorphism (markers included),
  n − 1 non-loop and m − n + 1 loop iterations.

A failure raises :class:`~topomark.spec.errors.CheckFailure` whose violation
names the iteration.

``mode="full"`` evaluates I-1 and I-2 from scratch after every iteration
(O(n + m) each); ``mode="incremental"`` (the default) uses
:class:`~topomark.spec.invariants.IncrementalInvariants`, which checks each
journalled addition to S against φ.  ``mode="both"`` runs both and requires
them to agree.  The end-of-run verdict always uses the full predicates.
"""

from __future__ import annotations

from topomark.spec.errors import CheckFailure, Violation
from topomark.spec.invariants import (IncrementalInvariants, check_I1, check_I2, check_lemma1, correspondence,
                                      lighthouse_anchor)
from topomark.spec.isomorphism import anchored, verify_witness

__all__ = ["Checker"]


class Checker:
    """Checks one exploration; ``passed`` counts the individual checks that held."""

    MODES = ("incremental", "full", "both")

    def __init__(self, simulator, mode: str = "incremental"):
        self.sim = simulator
        self.world = simulator.world
        self.t_prev = simulator.world.m
        self.markers = None
        self.passed = 0
        self.mode = mode
        self.incremental: IncrementalInvariants | None = None

    def _fail(self, it, violation: Violation) -> None:
        detail = f"iteration {it}" + (f"; {violation.detail}" if violation.detail else "")
        raise CheckFailure(Violation(violation.check, violation.where, violation.expected, violation.found, detail,
                                     {"iteration": it}))

    def _ok(self, it, violation: Violation | None) -> None:
        if violation is not None:
            self._fail(it, violation)
        self.passed += 1

    def after_start(self, explorer) -> None:
        self.world = self.sim.world
        self.markers = self.sim.world.markers
        self.check_state(explorer, 0)

    def after_iteration(self, explorer, it) -> None:
        n = it.number
        self._ok(n, check_lemma1(it.hypotheses))  # Lemma 1: (M, P^E) unique among this iteration's hypotheses
        # Bound function t = |E_G| - |E_S|.
        edges = explorer.S.edge_count if self.mode == "incremental" else explorer.S.explored_edges()
        t = self.world.m - edges
        self._ok(n, None if 0 <= t < self.t_prev else Violation(
            "bound function", "t = |E_G| - |E_S|", f"0 <= t < {self.t_prev}", str(t)))
        self.t_prev = t
        # The marker never moved.
        self._ok(n, None if self.sim.world.markers == self.markers else Violation(
            "immovable marker", "world markers", str(self.markers), str(self.sim.world.markers)))
        self.check_state(explorer, n)

    def check_state(self, explorer, n: int) -> None:
        S = explorer.S
        if self.incremental is None or self.mode != "incremental":
            anchor = lighthouse_anchor(S, self.world)
            self._ok(n, None if anchor is not None else Violation(
                "I-1", "v0", "one directional marker in S and in the world", "none or several"))
            if self.incremental is None:
                self.incremental = IncrementalInvariants(S, self.world, anchor)
        phi = None
        if self.mode in ("incremental", "both"):
            quick = self.incremental.update()
            if self.mode == "incremental":
                self._ok(n, quick)
                phi = self.incremental
        if self.mode in ("full", "both"):
            result = correspondence(S, self.world, anchor)
            full = check_I1(S, self.world, anchor, result)
            if full is None:
                full = check_I2(S, self.world, result.witness)
            if self.mode == "both" and (quick is None) != (full is None):
                self._fail(n, Violation("checker agreement", "I-1/I-2", f"full: {full}", f"incremental: {quick}",
                                        "the incremental and full invariant checks disagree"))
            self._ok(n, full)
            phi = result.witness
        believed = phi.image(S, explorer.position) if phi is not self.incremental else phi.image(explorer.position)
        self._ok(n, None if believed == self.sim.state else Violation(
            "position", f"map dart {explorer.position}", f"the robot at world state {believed}",
            f"the robot at {self.sim.state}", "the explorer does not know where it is"))

    def at_end(self, explorer) -> None:
        S, world = explorer.S, self.world
        n = len(explorer.iterations)
        self._ok(n, None if not S.unexplored else Violation("termination", "U", "empty", str(S.unexplored[:5])))
        anchor = lighthouse_anchor(S, world)
        result = anchored(S, world, anchor[0], anchor[1], markers=True, partial=False)
        self._ok(n, result.mismatch)
        self._ok(n, verify_witness(S, world, result.witness))
        kinds = [it.kind for it in explorer.iterations]
        for kind, want in (("non-loop", world.n - 1), ("loop", world.m - world.n + 1)):
            self._ok(n, None if kinds.count(kind) == want else Violation(
                "iteration count", f"{kind} iterations", str(want), str(kinds.count(kind))))
