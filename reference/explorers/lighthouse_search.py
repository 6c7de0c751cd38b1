"""Lighthouses found by a random walk: one undirected vertex marker (§5.1) or one undirected edge marker (§6.1).

One undirected immovable marker gives explicit place information but no
back-link (§3.2.2).  The thesis makes it a directional lighthouse by putting
it where the world itself supplies the back-link:

* ``undirected-vertex`` (§5.1): "the robot first conduct[s] a
  random walk searching for an appropriate vertex.  Upon entering a vertex,
  the robot traverses each other incident edge … retrieving the sequence D of
  the degree information of the neighbors", and drops the marker at the first
  vertex where "it is not the case that there exists a cyclic rotation of D …
  that maps onto D, except for a complete rotation".  ``neighbourhood`` d
  widens D to each neighbour's view to distance d (§5.1: "More situations
  exist if we further extend the local signature"; d = 1 in the thesis's
  experiments, §5.1).  Recognising it later probes "only as many [edges] as
  necessary" (§5.1; :func:`~topomark.reference.explorers.probing.identify`).
* ``undirected-edge`` (§6.1): walk "searching for an edge
  incident on two vertices with different degrees … drop the marker in the
  edge, and designate[s] either one of the end vertices as the directional
  lighthouse vertex".  No probe is needed: the marker is sensed relative to
  the entry edge at both ends, and the ends' degrees tell them apart.

Both give up after ``walk_limit`` walk steps (§5.1: "A threshold of 200
steps is set for the random walk … the algorithm terminates reporting
failure") with :class:`~topomark.spec.errors.AlgorithmFailed`, its
``walk_steps`` the steps walked (the run reports them as it reports a found
lighthouse's walk): on a regular
world §6.1 always does, and §5.1 does wherever every vertex's D is periodic
(a vertex-transitive world such as a cycle).

Decisions (the thesis is silent):

* The walk starts where the robot stands and tests that vertex first (§5.1:
  "either at the initial location or otherwise within a few steps"); a walk
  step leaves by a uniformly random exit (the vertex just left included),
  drawn from ``seed`` by :class:`SplitMix` (explorer modules import no
  ``random``: tests/test_wall.py).  ``walk_limit`` counts walk steps only;
  probes are counted as cost (purpose ``probe``), not as steps.  §5.1 tests the
  start and the vertices reached by steps 1..walk_limit; §6.1 tests the edges
  of steps 1..walk_limit.
* §5.1: the vertex just left is not probed again — its degree is known
  (d = 1).  v0's exit 0 is the edge the robot faces once D is complete (no
  move to face another).
* §6.1: v0 is the end the robot arrives at (either end serves): the
  marker goes on the edge just traversed, which is v0's exit 0.
* The options apply to the search only; the believed pose after it is
  (v0, exit 0), and the checker anchors φ there.

Examples
--------
>>> SplitMix(5).below(10) == SplitMix(5).below(10)
True
>>> rng = SplitMix(0)
>>> sorted({rng.below(3) for _ in range(50)})
[0, 1, 2]
"""

from __future__ import annotations

from topomark.spec.errors import AlgorithmFailed, ExplorerFault
from topomark.spec.kit import MarkerOp
from topomark.spec.mapstate import PartialMap

from topomark.reference.explorers.probing import aperiodic, identify, perceived, views_around

__all__ = ["SplitMix", "search_vertex", "search_edge", "after_search"]

_MASK = (1 << 64) - 1


class SplitMix:
    """SplitMix64: a small deterministic generator, the same numbers on every platform for a seed."""

    def __init__(self, seed: int):
        self.state = seed & _MASK

    def next(self) -> int:
        self.state = (self.state + 0x9E3779B97F4A7C15) & _MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK
        return z ^ (z >> 31)

    def below(self, n: int) -> int:
        """A number in 0..n−1 (n ≤ 2^32: the bias of the modulus is below 2^-32)."""
        return self.next() % n


def after_search(S, v0):
    """The recognition of a searched lighthouse is made by its search (a placeholder for ``recognition``)."""
    raise ExplorerFault("a searched lighthouse is recognised by what its search returns (§5.1; §6.1): "
                        "its placeholder recognition was called, a bug in the explorer")


def search_vertex(light, robot, S: PartialMap):
    """§5.1: walk until a vertex whose neighbourhood views D are aperiodic; drop the marker there."""
    rng, depth = SplitMix(light.seed), light.neighbourhood
    sig, known0, steps = robot.sense(), None, 0
    while True:
        views, f = views_around(robot, sig, depth, known0)
        if aperiodic(views):
            break
        if steps >= light.walk_limit:
            raise AlgorithmFailed(f"no vertex whose neighbour {'degrees' if depth == 1 else 'views'} D (distance "
                                  f"{depth}) have no proper cyclic rotation onto themselves within {light.walk_limit} "
                                  "walk steps (§5.1)", walk_steps=steps)
        left = sig.degree
        sig = robot.move(rng.below(sig.degree), "establish")
        known0, steps = (left if depth == 1 else None), steps + 1
    robot.operate(MarkerOp("vertex"))
    d = sig.degree
    v0 = S.add_vertex(d)
    S.mark_as_sensed(v0, robot.sense(), 0)  # exit 0: the edge the robot faces now, relative exit f
    D = [views[(f + j) % d] for j in range(d)]

    def recognise(robot, sig, previous):
        known = previous.degree if depth == 1 else None
        return perceived(sig, identify(robot, sig, lambda j, r: D[(j + r) % d], known, depth))

    return light.beacon(S, v0, steps, recognise)


def search_edge(light, robot, S: PartialMap):
    """§6.1: walk until an edge whose ends have different degrees; mark it; v0 is the end reached."""
    rng = SplitMix(light.seed)
    sig, steps = robot.sense(), 0
    while True:
        if steps >= light.walk_limit:
            raise AlgorithmFailed(f"no edge whose two ends have different degrees within {light.walk_limit} walk "
                                  "steps (§6.1)", walk_steps=steps)
        got = robot.move(rng.below(sig.degree), "establish")
        steps += 1
        if got.degree != sig.degree:
            break
        sig = got
    robot.operate(MarkerOp("edge", exit=0))
    v0 = S.add_vertex(got.degree)
    S.mark_as_sensed(v0, robot.sense(), 0)
    return light.beacon(S, v0, steps)
