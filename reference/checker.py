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
"""

from __future__ import annotations

from topomark.spec.errors import CheckFailure, Violation
from topomark.spec.invariants import check_I1, check_I2, correspondence, lighthouse_anchor
from topomark.spec.isomorphism import anchored, verify_witness

__all__ = ["Checker"]


class Checker:
    """Checks one exploration; ``passed`` counts the individual checks that held."""

    def __init__(self, simulator):
        self.sim = simulator
        self.world = simulator.world
        self.t_prev = simulator.world.m
        self.markers = None
        self.passed = 0

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
        # Lemma 1: (M, P^E) unique among this iteration's hypotheses.
        seen = {}
        for h in it.hypotheses:
            key = (h.motions, h.expected)
            if key in seen:
                self._fail(n, Violation("Lemma 1", f"hypotheses {seen[key]} and {h.dart}",
                                        "distinct (M, P^E) pairs", f"both M={list(h.motions)}"))
            seen[key] = h.dart
        self.passed += 1
        # Bound function t = |E_G| - |E_S|.
        t = self.world.m - explorer.S.explored_edges()
        self._ok(n, None if 0 <= t < self.t_prev else Violation(
            "bound function", "t = |E_G| - |E_S|", f"0 <= t < {self.t_prev}", str(t)))
        self.t_prev = t
        # The marker never moved.
        self._ok(n, None if self.sim.world.markers == self.markers else Violation(
            "immovable marker", "world markers", str(self.markers), str(self.sim.world.markers)))
        self.check_state(explorer, n)

    def check_state(self, explorer, n: int) -> None:
        S = explorer.S
        anchor = lighthouse_anchor(S, self.world)
        self._ok(n, None if anchor is not None else Violation(
            "I-1", "v0", "one directional marker in S and in the world", "none or several"))
        result = correspondence(S, self.world, anchor)
        self._ok(n, check_I1(S, self.world, anchor, result))
        phi = result.witness
        self._ok(n, check_I2(S, self.world, phi))
        believed = phi.image(S, explorer.position)
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
