"""The checker: every loop condition of §3.4 that applies, after every iteration, against the truth.

The checker sees what the explorer may not — the world and the simulator's
true state — and judges the explorer's public state (S, U, its believed
position and its iteration records) with the spec's own predicates.  Which
checks run is named by the algorithm's registry entry
(:data:`topomark.reference.algorithms.algorithm_spec.CHECKS`):

* ``pose`` — the explorer's believed position is where the robot really is:
  φ is anchored at the start, the explorer's believed pose (v0, exit 0)
  ↦ the robot's true state, so no check needs to find a marker;
* ``I-1`` and ``I-2`` (with the edge-index condition), via
  :mod:`topomark.spec.invariants`, φ propagated from that anchor;
* ``bound-function`` — t = |E_G| − |E_S| strictly decreases and stays ≥ 0;
* ``lemma-1`` — each hypothesis's pair (M, P^E) is unique in its iteration;
* ``marker`` — no marker was dropped, moved or picked up after the start
  (the lighthouse is immovable; the kit itself is enforced by the simulator);
* ``marker-budget`` — never more markers in the world (counts summed) than
  the algorithm's stated marker bound for this n and m (its registry
  entry's ``marker_bound_fn``), after every step;
* ``cost-bound`` — at termination, the cost (edge traversals, §3.1.2) is
  at most the entry's exact bound for this n and m (``bound_fn``, named by
  its ``bound_formula``), not counting the move purposes the bound leaves
  out (``bound_excludes``: a lighthouse's search walk and probes for
  Algorithm 3.1's (3.1)+(3.2)); an entry whose bound is asymptotic only
  names no such check;
* ``models`` — for an explorer holding several models (§5.2.2, Algorithm
  5.1): after every step one of ``explorer.models()`` — (map, believed pose)
  pairs, each naming the start place as ``explorer.position`` named it at
  the start — still maps into the world with its pose on the robot's true
  state.  The truth voided by topomark's own explorer is a fault of topomark
  (:class:`~topomark.spec.errors.TopomarkFault`, exit 3); by an
  explorer under test (``registry.variant``), a check failure;
* ``iterations`` — n − 1 non-loop and m − n + 1 loop iterations;
* ``isomorphism`` — at termination U is empty and S ≅ G by extended
  isomorphism, every marker in the world (dropped ones included) shown in
  the map.

A failure raises :class:`~topomark.spec.errors.CheckFailure` whose violation
names the iteration.

``mode="full"`` evaluates I-1 and I-2 from scratch after every iteration
(O(n + m) each); ``mode="incremental"`` (the default) uses
:class:`~topomark.spec.invariants.IncrementalInvariants`, which checks each
journalled addition to S against φ.  ``mode="both"`` runs both and requires
them to agree.  The end-of-run verdict always uses the full predicates.
"""

from __future__ import annotations

from typing import Any, NoReturn, cast

from topomark.spec.errors import CheckFailure, TopomarkFault, Violation
from topomark.spec.invariants import Anchor, IncrementalInvariants, check_I1, check_I2, check_lemma1, correspondence
from topomark.spec.isomorphism import Witness, anchored, verify_witness

from topomark.reference.algorithms.algorithm_spec import ALGORITHM_3_1_CHECKS, CHECKS

__all__ = ["Checker", "ALL_CHECKS"]

ALL_CHECKS = ALGORITHM_3_1_CHECKS
"""Algorithm 3.1's checks, the default (:data:`~topomark.reference.algorithms.algorithm_spec.ALGORITHM_3_1_CHECKS`);
:data:`~topomark.reference.algorithms.algorithm_spec.CHECKS` lists every one."""


class Checker:
    """Checks one exploration; ``passed`` counts the individual checks that held.

    ``checks`` names the checks that apply (default: all of Algorithm 3.1's).
    I-1, I-2 and ``pose`` share φ, so any of them computes it.
    """

    MODES = ("incremental", "full", "both")

    def __init__(self, simulator, mode: str = "incremental", checks=ALL_CHECKS, spec=None):
        unknown = set(checks) - set(CHECKS)
        if unknown:
            raise ValueError(f"unknown checks {sorted(unknown)}")
        self.sim = simulator
        self.world = simulator.world
        self.t_prev = simulator.world.m
        self.markers: tuple[Any, ...] | None = None
        self.passed = 0
        self.mode = mode
        self.checks = frozenset(checks)
        self.anchor: Anchor = cast(Anchor, None)  # φ's anchor, fixed by after_start before any check reads it
        self.incremental: IncrementalInvariants | None = None
        self.spec = spec  # the algorithm's registry entry: its marker bound, and whether it is topomark's own

    def _fail(self, it: Any, violation: Violation) -> NoReturn:
        detail = f"iteration {it}" + (f"; {violation.detail}" if violation.detail else "")
        raise CheckFailure(Violation(violation.check, violation.where, violation.expected, violation.found, detail,
                                     {"iteration": it}))

    def _ok(self, it, violation: Violation | None) -> None:
        if violation is not None:
            self._fail(it, violation)
        self.passed += 1

    def after_start(self, explorer) -> None:
        """The lighthouse is established: the world now carries its markers; anchor φ at the believed pose."""
        self.world = self.sim.world
        self.markers = _marks(self.sim.world)
        self.anchor = (explorer.position, self.sim.state)
        if self.checks & {"pose", "I-1", "I-2"}:
            self.check_state(explorer, 0)
        self.check_kit_use(explorer, 0)

    def after_iteration(self, explorer, it) -> None:
        n = it.number
        if "lemma-1" in self.checks:  # Lemma 1: (M, P^E) unique among this iteration's hypotheses
            self._ok(n, check_lemma1(it.hypotheses))
        if "bound-function" in self.checks:  # t = |E_G| - |E_S|
            edges = explorer.S.edge_count if self.mode == "incremental" else explorer.S.explored_edges()
            t = self.world.m - edges
            self._ok(n, None if 0 <= t < self.t_prev else Violation(
                "bound function", "t = |E_G| - |E_S|", f"0 <= t < {self.t_prev}", str(t)))
            self.t_prev = t
        if "marker" in self.checks:  # nothing dropped, moved or picked up after the lighthouse
            now = _marks(self.sim.world)
            self._ok(n, None if now == self.markers else Violation(
                "immovable marker", "world markers and thread", str(self.markers), str(now)))
        if self.checks & {"pose", "I-1", "I-2"}:
            self.check_state(explorer, n)
        self.check_kit_use(explorer, n)

    def check_kit_use(self, explorer, n: int) -> None:
        """``marker-budget`` and ``models``, where the algorithm's entry names them."""
        if "marker-budget" in self.checks:
            world = self.sim.world
            bound = self.spec.marker_bound_fn(world.n, world.m)
            used = self.sim.layer.lying  # the sum of the counts of world.markers, kept per change
            self._ok(n, None if used <= bound else Violation(
                "marker budget", "world markers", f"at most {bound} (the algorithm's stated bound: "
                f"{self.spec.markers}, at n = {world.n}, m = {world.m})", str(used)))
        if "models" in self.checks:
            self.check_models(explorer, n)

    def check_models(self, explorer, n: int) -> None:
        """The true world survives among the live models (§5.2.2): one maps into it, its pose on the truth."""
        models = list(explorer.models())
        for S, pose in models:
            phi = correspondence(S, self.sim.world, self.anchor)
            if check_I1(S, self.sim.world, self.anchor, phi) is None and phi.witness is not None and \
                    phi.witness.image(S, pose) == self.sim.state:
                self.passed += 1
                return
        violation = Violation("models", f"step {n}", "the true world among the live models",
                              f"none of {len(models)} live model(s) maps into it")
        if self.spec is not None and self.spec.own:
            raise TopomarkFault(f"step {n}: topomark's own explorer {self.spec.name} voided the true world: "
                                f"{violation}", check="models")
        self._fail(n, violation)

    def check_state(self, explorer, n: int) -> None:
        S, anchor = explorer.S, self.anchor
        self.world = self.sim.world  # markers dropped during the run are part of the world from then on
        if self.incremental is None:
            self.incremental = IncrementalInvariants(S, self.world, anchor)
        phi: Witness | IncrementalInvariants | None = None
        if self.mode in ("incremental", "both"):
            quick = self.incremental.rebase(self.world) or self.incremental.update("I-2" in self.checks)
            if self.mode == "incremental":
                self._ok(n, quick)
                phi = self.incremental
        if self.mode in ("full", "both"):
            result = correspondence(S, self.world, anchor)
            full = check_I1(S, self.world, anchor, result)
            if full is None and "I-2" in self.checks:
                full = check_I2(S, self.world, cast(Witness, result.witness))  # I-1 holds: φ exists
            if self.mode == "both" and (quick is None) != (full is None):
                raise TopomarkFault(f"iteration {n}: topomark's incremental and full I-1/I-2 checks disagree "
                                    f"(full: {full}; incremental: {quick})", check="incremental and full I-1/I-2 agree")
            self._ok(n, full)
            phi = result.witness
        if "pose" not in self.checks:
            return
        believed = phi.image(explorer.position) if isinstance(phi, IncrementalInvariants) \
            else cast(Witness, phi).image(S, explorer.position)
        self._ok(n, None if believed == self.sim.state else Violation(
            "position", f"map dart {explorer.position}", f"the robot at world state {believed}",
            f"the robot at {self.sim.state}", "the explorer does not know where it is"))

    def at_end(self, explorer) -> None:
        S, world = explorer.S, self.sim.world  # the world as it is now: every dropped marker in it
        n = len(explorer.iterations)
        if "isomorphism" in self.checks:
            self._ok(n, None if not S.unexplored else Violation("termination", "U", "empty", str(S.unexplored[:5])))
            result = anchored(S, world, self.anchor[0], self.anchor[1], markers=True, partial=False)
            self._ok(n, result.mismatch)
            bad = verify_witness(S, world, cast(Witness, result.witness))  # _ok raised on a mismatch
            if bad is not None:
                raise TopomarkFault(f"the isomorphism's witness fails re-verification: {bad}",
                                    check="witness re-verification")
            self.passed += 1
        if "iterations" in self.checks:
            kinds = [it.kind for it in explorer.iterations]
            for kind, want in (("non-loop", world.n - 1), ("loop", world.m - world.n + 1)):
                self._ok(n, None if kinds.count(kind) == want else Violation(
                    "iteration count", f"{kind} iterations", str(want), str(kinds.count(kind))))
        if "cost-bound" in self.checks:
            self._ok(n, self.cost_violation())

    def cost_violation(self) -> Violation | None:
        """``cost-bound``: the run's cost, less the moves its bound does not count, against the exact bound."""
        spec, world, sim = self.spec, self.sim.world, self.sim
        bound = spec.bound_for(world.n, world.m)
        cost = spec.counted_cost(sim.cost, sim.by_purpose)
        skipped = sim.cost - cost
        if cost <= bound:
            return None
        counted = f"{cost}" + (f" ({sim.cost} less {skipped} {' and '.join(spec.bound_excludes)} moves)"
                               if skipped else "")
        return Violation("cost bound", "edge traversals (§3.1.2)",
                         f"at most {bound} = {spec.bound_formula}, at n = {world.n}, m = {world.m}", counted)


def _marks(world) -> tuple:
    """What the ``marker`` check keeps still: the world's markers and its thread (§6.3), if any."""
    return world.markers, getattr(world, "thread", None)
