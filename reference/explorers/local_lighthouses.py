"""Marker-less lighthouses: a place chosen by its local signature after a random walk (thesis §5.2.1).

Without any marker the robot "cannot map a world deterministically" (§5.2).
§5.2.1 "uses local signatures or slightly expanded local signatures to
select a 'likely' directional lighthouse, and then maps the world using the
single directional marker algorithm or one of its enhancements" (§5.2.1):
"we first have the robot conduct a random walk for a certain number of
steps, and then select the traversed vertex whose local signature is
believed to be (most likely) unique and that also provides back-link
information".  Two selection schemes, both here as lighthouse strategies with
an empty kit (any Chapter 3–4 algorithm runs with them):

* ``local-pair`` — scheme A (§5.2.1): "record the pair of degrees of adjacent
  vertices that the robot encounters during its random walk … the pair of
  degrees that was encountered the least number of times … If the least
  number of visits is below a threshold then this pair of degrees is
  selected … Otherwise the algorithm terminates reporting failure … the
  robot returns to a pair of adjacent vertices that has the selected degree
  pair, where one of the adjacent vertices is used as the lighthouse and the
  other is used to establish the back-link information".  No probe during
  the walk: each step's pair is the degree left and the degree reached.
  Recognised by :func:`first_of_degree`: at a vertex of v0's degree a, the
  first neighbour of degree b clockwise from the entry edge is v0's exit 0
  (the edge's orientation is the back-link); no neighbour of degree b: not
  v0.
* ``local-degree-list`` — scheme B (§5.2.1): "At each vertex visited during
  random walk, the robot visits all the neighbors and establishes a list
  D … we collect the lists that contain explicit back-link information,
  using the rotation equivalence test … we treat lists that are cyclic
  rotations of each other as the same list and add up their visit counts …
  If the minimal associated visit count is below a threshold, then the
  vertex that contains this list is selected".  Recognised by
  :func:`matches_list`: probing v0's neighbours (:mod:`.probing`) until no
  entry agrees (not v0) or every neighbour agrees with D from exactly one
  entry (v0, and that entry).  ``neighbourhood`` d widens D to the views to
  distance d, as for §5.1 (§5.2.1: "this approach might be improved using
  signatures of neighbor distance d > 1").

v0's recognised perception is written as a directional lighthouse's,
``[d,V-r,A]`` (r the relative exit of v0's exit 0): the *virtual* head of
:class:`VirtualMap`.  S itself keeps no mark (the world has none), so the
checker compares the map with the world as it is.

Neither scheme can guarantee the lighthouse's place (both) nor its back-link
(scheme A) (§5.2.1).  The outcomes are the thesis's list (§5.2.1):

* ``failed`` — "No potential lighthouse may be identified": no candidate in
  the walk, or the least count not below the threshold; or the algorithm
  "detects some signature inconsistencies (due to wrong loop closing)": a
  new edge arrives at v0 by an entry already explored
  (:class:`LocalProbingRobot`).  Both raise
  :class:`~topomark.spec.errors.AlgorithmFailed`, the reason given.
* ``correct`` — "The selected lighthouse happens to be unique and the
  back-link information is also explicit" (the truth side:
  :func:`topomark.reference.run.local_places.unique_place`).
* ``wrong-map`` — "terminates with an incorrect world model", or would
  "never terminate": the checker, which sees the truth, stops the run at the
  first wrong join (exit 1).  "Without additional information about the world
  … we cannot determine whether it is a correct model or not": the algorithm
  itself claims ``correct``.  (Unchecked, ``--no-check``, such a run may end
  with a wrong map or, if S never closes, not end.)

Decisions (the thesis is silent, §5.2.1):

* Walk: ``walk_limit`` steps (default 200 — the thesis gives no length for
  §5.2.1; 200 is its only walk threshold, §5.1), each by a uniformly
  random exit drawn from ``seed`` (:class:`~.lighthouse_search.SplitMix`).
  Scheme B tests the start and the vertices after steps 1..walk_limit
  (walk_limit + 1 visits); scheme A counts the walk_limit traversed edges.
* Pairs are unordered (an edge is the same pair whichever way it is
  walked); a pair of equal degrees is never chosen — both of its ends would
  show it, so it gives neither one place nor an orientation.
* ``threshold``: the least count must be *below* it (§5.2.1).  No value
  is given; the default is the number of observations (walk_limit for
  scheme A, walk_limit + 1 for B), i.e. a candidate is refused only if the
  walk saw it at every step and nothing rarer (a star, K2).
* Ties in "least-seen": the candidate whose last sighting is latest in the
  walk — the shortest way back, for the robot returns by retracing its walk
  (the only way it knows).  The walk back is ``establish`` moves; the
  lighthouse's ``walk_steps`` is the walk alone (the whole walk when no
  lighthouse is chosen).
* Scheme A: the lighthouse is the end of smaller degree (fewer neighbours to
  probe and to confuse the back-link), entered from the other end, so that
  edge is v0's exit 0.  Recognition stops at the first neighbour of degree b
  (§5.1: "only as many as necessary"), so a v0 with two neighbours of
  degree b gives an entry that depends on where the robot came from — the
  back-link the thesis says scheme A cannot guarantee.
* Scheme B: v0's exit 0 is the edge the robot entered it by on its way back.
  Unlike §5.1, recognising needs *every* neighbour (the place itself is only
  known from its list), except that it stops at the first disagreement.
* Probes during the walk and at recognition are ``probe`` moves (cost), as
  for §5.1.
* The smallest worlds where a run maps wrong (networkx's atlas, planar
  embeddings, every start, seeds 0–2, walk 50; tests/test_local_lighthouses.py):
  scheme B, K4 minus an edge (its two degree-3 vertices both show (2, 3, 2));
  scheme A, a 5-vertex, 6-edge world whose only degree-2 vertex has two
  neighbours of degree 3 (the back-link depends on the entry).

Examples
--------
>>> canonical((3, 2, 3)) == canonical((2, 3, 3)) == canonical((3, 3, 2)) == (2, 3, 3)
True
>>> canonical((2, 3, 6)) == canonical((3, 6, 2))
True
>>> least_seen({(2, 3): 3, (3, 4): 1, (2, 4): 1}, {(2, 3): 9, (3, 4): 4, (2, 4): 7})
(2, 4)
"""

from __future__ import annotations

from collections import Counter
from typing import Any

from topomark.spec.errors import AlgorithmFailed
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature

from topomark.reference.explorers.lighthouse_search import SplitMix
from topomark.reference.explorers.probing import PerceivedMap, ProbingRobot, VirtualHead, aperiodic, view_here, views_around

__all__ = ["search_pair", "search_degree_list", "first_of_degree", "matches_list", "canonical", "least_seen",
           "virtual", "VirtualMap", "LocalProbingRobot"]


def canonical(D: tuple) -> tuple:
    """The representative of D's rotation class (§5.2.1: rotations "considered the same list"): its least rotation."""
    return min(D[r:] + D[:r] for r in range(len(D)))


def least_seen(counts: dict, last: dict) -> Any:
    """The least-seen candidate; on a tie, the one last seen latest in the walk (the shortest way back)."""
    return min(counts, key=lambda c: (counts[c], -last[c]))


def virtual(sig: Signature, entry: int) -> Signature:
    """v0's perception from ``entry``: a directional lighthouse's, ``[d,V-r,A]``, r the relative exit of exit 0."""
    return Signature(sig.degree, 1, (-entry) % sig.degree)


class LocalProbingRobot(ProbingRobot):
    """The probing robot of a virtual lighthouse: a new edge that arrives at v0 by an entry already explored is
    a "signature inconsistenc[y] (due to wrong loop closing)" — the algorithm "cannot proceed reporting failure"
    (§5.2.1): :class:`~topomark.spec.errors.AlgorithmFailed`."""

    __slots__ = ("_S",)

    def __init__(self, robot, recognise, raw, S: PartialMap):
        super().__init__(robot, recognise, raw)
        self._S = S

    def move(self, motion: int, purpose: str = "other") -> Signature:
        sig = super().move(motion, purpose)
        if purpose == "new" and sig.vertex_direction is not None:
            entry = (-sig.vertex_direction) % sig.degree
            if (0, entry) not in self._S.unexplored:
                raise AlgorithmFailed(f"a new edge arrived at the lighthouse by its exit {entry}, already explored: "
                                      "its local signature is not unique (§5.2.1)")
        return sig


def _beacon(light, S: PartialMap, v0: int, steps: int, recognise):
    beacon = light.beacon(S, v0, steps, recognise)
    beacon.prober = lambda robot, rec, raw: LocalProbingRobot(robot, rec, raw, S)
    return beacon


class VirtualMap(PerceivedMap):
    """S as the explorer perceives it: v0 carries a virtual head at exit 0 though no marker lies there."""

    def vertex_mark(self, v):
        return VirtualHead(1) if v == self._v0 else self._S.vertex_mark(v)


def _face_back(robot, d: int, f: int) -> None:
    """After probing (the robot faces relative exit ``f``): out by the entry edge and back, to face it again."""
    if f:
        robot.move((-f) % d, "probe")
        robot.move(0, "probe")


def first_of_degree(robot, sig: Signature, b: int, came_from: int) -> int | None:
    """Scheme A's recognition: the entry j such that v0's exit 0 (the first neighbour of degree ``b`` clockwise
    from the entry edge) is relative exit −j; None if no neighbour has degree ``b``.  The robot faces its entry
    edge again afterwards."""
    if came_from == b:
        return 0
    d, f, found = sig.degree, 0, None
    for r in range(1, d):
        got = robot.move((r - f) % d, "probe")
        robot.move(0, "probe")
        f = r
        if got.degree == b:
            found = (-r) % d
            break
    _face_back(robot, d, f)
    return found


def matches_list(robot, sig: Signature, D: list, known0, depth: int) -> int | None:
    """Scheme B's recognition: the one entry j from which every neighbour's view agrees with D (D[(j + r) mod d]
    at relative exit r), or None — probing stops at the first view no entry agrees with.  ``known0`` is the
    view behind the entry edge if known (depth 1: the degree just left).  The robot faces its entry edge again."""
    d = sig.degree
    J = [j for j in range(d) if known0 is None or D[j] == known0]
    f, r = 0, (0 if known0 is None else 1)
    while J and r < d:
        got = robot.move((r - f) % d, "probe")
        seen, g = view_here(robot, got, depth - 1)
        robot.move((-g) % got.degree, "probe")
        f = r
        J = [j for j in J if D[(j + r) % d] == seen]
        r += 1
    _face_back(robot, d, f)
    return J[0] if len(J) == 1 else None


def _walk_back(robot, degrees: list[int], exits: list[int], c: int, t: int) -> int:
    """Retrace the walk from its last vertex (facing offset ``c``) to vertex ``t``; ``exits[q]`` is the exit taken
    from vertex q, counted from the edge q was entered by.  Returns the facing offset at vertex t."""
    for q in range(len(degrees) - 1, t, -1):
        robot.move((-c) % degrees[q], "establish")
        c = exits[q - 1]
    return c


def _threshold(light, observations: int) -> int:
    return light.threshold if light.threshold is not None else observations


def _refuse(light, what: str, count: int, observations: int, line: str) -> None:
    threshold = _threshold(light, observations)
    if count >= threshold:
        raise AlgorithmFailed(f"the least-seen {what} was seen {count} times in a walk of {light.walk_limit} steps, "
                              f"not below the threshold {threshold} ({line})", walk_steps=light.walk_limit)


def search_pair(light, robot, S: PartialMap):
    """Scheme A: walk, choose the least-seen pair {a, b} (a < b), go back to it; v0 is its degree-a end, exit 0 the
    edge to the degree-b end."""
    rng, L = SplitMix(light.seed), light.walk_limit
    degrees, exits = [robot.sense().degree], []
    for _ in range(L):
        exits.append(rng.below(degrees[-1]))
        degrees.append(robot.move(exits[-1], "establish").degree)
    counts: Counter[Any] = Counter()
    last: dict[Any, int] = {}
    for s in range(1, L + 1):
        pair = tuple(sorted((degrees[s - 1], degrees[s])))
        if pair[0] != pair[1]:
            counts[pair] += 1
            last[pair] = s
    if not counts:
        raise AlgorithmFailed(f"no edge whose ends have different degrees in a walk of {L} steps: no pair of "
                              "degrees gives a lighthouse and its back-link (§5.2.1)", walk_steps=L)
    a, b = pair = least_seen(counts, last)
    _refuse(light, f"pair of adjacent degrees {pair}", counts[pair], L, "§5.2.1")
    s = last[pair]
    c = _walk_back(robot, degrees, exits, 0, s)  # at vertex s; the edge to s - 1 is at offset -c
    if degrees[s] == b:  # v0 is vertex s - 1: cross the pair's edge into it
        robot.move((-c) % b, "establish")
    elif c:  # v0 is vertex s, entered from s + 1: out to s - 1 and back
        robot.move((-c) % a, "establish")
        robot.move(0, "establish")
    v0 = S.add_vertex(a)
    S.mark_as_sensed(v0, robot.sense(), 0)

    def recognise(robot, sig: Signature, previous: Signature) -> Signature:
        entry = first_of_degree(robot, sig, b, previous.degree)
        return sig if entry is None else virtual(sig, entry)

    return _beacon(light, S, v0, L, recognise)


def search_degree_list(light, robot, S: PartialMap):
    """Scheme B: walk probing D at every vertex, choose the least-seen rotation class of an aperiodic D, go back
    to its latest vertex; v0 is that vertex, exit 0 the edge it is entered by."""
    rng, L, depth = SplitMix(light.seed), light.walk_limit, light.neighbourhood
    sig, known0 = robot.sense(), None
    degrees, exits, lists, f = [], [], [], 0
    for t in range(L + 1):
        views, f = views_around(robot, sig, depth, known0)
        degrees.append(sig.degree)
        lists.append(tuple(views))
        if t == L:
            break
        move = rng.below(sig.degree)
        exits.append((f + move) % sig.degree)
        known0 = sig.degree if depth == 1 else None
        sig = robot.move(move, "establish")
    counts: Counter[Any] = Counter()
    last: dict[Any, int] = {}
    for t, seen_list in enumerate(lists):
        if aperiodic(seen_list):
            counts[canonical(seen_list)] += 1
            last[canonical(seen_list)] = t
    if not counts:
        raise AlgorithmFailed(f"no vertex whose neighbour {'degrees' if depth == 1 else 'views'} D (distance "
                              f"{depth}) have no proper cyclic rotation onto themselves in a walk of {L} steps "
                              "(§5.2.1)", walk_steps=L)
    chosen = least_seen(counts, last)
    _refuse(light, f"neighbour list {chosen} (rotations merged)", counts[chosen], L + 1, "§5.2.1")
    t = last[chosen]
    c = _walk_back(robot, degrees, exits, f, t)
    d, seen = degrees[t], lists[t]
    D = [seen[(c + j) % d] for j in range(d)]  # by v0's exits, exit 0 the edge the robot stands entered by
    v0 = S.add_vertex(d)
    S.mark_as_sensed(v0, robot.sense(), 0)

    def recognise(robot, sig: Signature, previous: Signature) -> Signature:
        entry = matches_list(robot, sig, D, previous.degree if depth == 1 else None, depth)
        return sig if entry is None else virtual(sig, entry)

    return _beacon(light, S, v0, L, recognise)
