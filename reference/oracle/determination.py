"""Whether a program's observations determine its map: no credit for a guess (thesis §3.1).

The robot must *build* a map extended-isomorphic to the world from what it senses (§3.1: degrees, markers, the
thread), so a right map is not enough: the observations the program made must leave it no other answer.  A program
that sends a two-vertex map before moving has the right map of a two-vertex chain, but a three-vertex chain would
have shown it the same thing.

The rule, as the oracle applies it after a map is found extended-isomorphic to the world: the program's actions
(motions, marker and thread operations, in order) are replayed on other worlds; a world on which every signature the
robot senses is the same as in the world played (the robot's own language: :class:`~topomark.spec.signature.
Signature` compared as sensed) and which is not isomorphic to the map is a **witness** that the map was a guess, and
the verdict is ``fail`` with reason ``guess``.  The worlds tried:

* **an untraversed edge subdivided.**  An edge the robot never crossed is replaced by a path of two edges through a
  new vertex of degree 2: every vertex the robot visits keeps its degree and its exits, so nothing it senses
  changes, and the world has one vertex more than the map.  Any map sent before every edge was crossed fails.
* **a two-fold cover.**  Two copies of the world with one edge's ends crossed between the copies (the 2-lift with
  voltage 1 on that edge, tried for each edge in turn).  The robot's walk lifts to it from the first copy of the
  start; where the program never checked a return (a marker it dropped, seen again, tells the copies apart), the
  cover shows it the same signatures, and it has twice the vertices of the map.

Decision (the thesis is silent on how an oracle should tell knowledge from luck): the check is **sound** — a guess
is failed only with a witness world, replayed step by step by the simulator that played the run and seen to give
every signature, which is not isomorphic to the map.  Where the program uses markers or a thread (vertex and edge
markers, any number, directional or not, movable or not; a thread moved back only by ``rewind``) it is also **complete**: :mod:`~topomark.reference.oracle.walk_folding`
decides it exactly, and the subdivisions and covers run beside it as an independent check (a cover witness where the
folding found the map determined is :class:`~topomark.spec.errors.TopomarkFault`).  Elsewhere a map can be
undetermined in ways no subdivision or two-fold cover shows.  The covers' replays are bounded by
:data:`MAX_REPLAY_STEPS` actions in all; a run past that bound is judged on the subdivisions (and the exact decision,
when it applies) alone, and :class:`Determination` says so (``complete=False``; ``exact`` when decided exactly).

Examples
--------
>>> from topomark.reference.worlds.deterministic import chain, cycle
>>> two = chain(2)  # a program that sends the two-vertex chain before it moves
>>> found = determination(two, two.start_state(), LIGHTHOUSE, [], two)
>>> found.witness.n, found.how
(3, 'subdivided')
>>> three = cycle(3)  # once round a triangle, never dropping the marker: a longer cycle looks the same
>>> found = determination(three, three.start_state(), LIGHTHOUSE, [1, 1, 1], three)
>>> found.witness.n, found.how, found.exact
(6, 'two-fold cover', True)
"""

from __future__ import annotations

from array import array
from dataclasses import dataclass
from typing import Sequence

from topomark.spec.errors import InvalidWorld, TopomarkFault
from topomark.spec.kit import Kit
from topomark.spec.world import Start, World

from topomark.reference.run.simulator import Simulator
from topomark.reference.oracle.agreement import REWIND, Action, act as _act, agrees, matches as _matches
from topomark.reference.oracle.walk_folding import decide

__all__ = ["Action", "Determination", "determination", "agrees", "subdivided", "two_fold_cover",
           "MAX_REPLAY_STEPS", "LIGHTHOUSE", "REWIND"]

LIGHTHOUSE = Kit(vertex=1, directional=True)  # Algorithm 3.1's kit, for the example
MAX_REPLAY_STEPS = 2_000_000  # actions replayed on two-fold covers, over all of them, per judged run


@dataclass(frozen=True)
class Determination:
    """What the replays found: a witness world (None: none found), how it was made, what was tried."""

    witness: World | None
    how: str | None  # "subdivided" or "two-fold cover"
    edge: tuple[str, str] | None  # the edge subdivided, or crossed between the copies
    candidates: int  # worlds replayed
    complete: bool  # False: the covers' replay bound was reached before every edge was tried
    exact: bool = False  # True: decided exactly (the walk's folding): no witness means no world shows it

    def words(self, map_n: int) -> str:
        """Why the map was a guess; without a witness, that what the robot sensed determined the map."""
        if self.witness is None:
            if self.exact:
                return ("determined by what the program sensed (decided exactly: every world that gives those "
                        "observations is isomorphic to the map)")
            return (f"determined by what the program sensed (no witness of a guess among {self.candidates} worlds "
                    f"replayed{'' if self.complete else ', the replay bound reached'}; not decided exactly)")
        u, w = self.edge or ("?", "?")
        why = {"subdivided": f"the robot never crossed the edge {u}–{w}; with a vertex added on it",
               "two-fold cover": f"the robot never told apart the two copies of a two-fold cover of the world (the "
                                 f"edge {u}–{w} crossed between them); on it",
               "unvisited exit": "an exit of a vertex the robot stood on was never used by any visit it can tell "
                                 "apart; with a new vertex beyond it",
               "finer world": "nothing it sensed forced two of its visits to be one vertex; on a world that keeps "
                              "them apart",
               "quotient": "nothing it sensed kept two vertices apart; on a world where they are one"}[self.how or ""]
        other = (f"has {self.witness.n} vertices, not {map_n}" if self.witness.n != map_n
                 else "is not isomorphic to the map")
        return (f"the map is right, but the program's observations do not determine it: {why}, every signature the "
                f"robot sensed is the same, and that world {other} (the witness)")

    def to_json(self) -> dict:
        from topomark.spec.worldfile import world_to_json

        return {"witness": None if self.witness is None else world_to_json(self.witness), "how": self.how,
                "edge": None if self.edge is None else list(self.edge), "candidates": self.candidates,
                "complete": self.complete, "exact": self.exact}


def _walk(truth: World, start: tuple[str, int], kit: Kit, actions: Sequence[Action]) -> tuple[set[frozenset], array]:
    """Replay ``actions`` on ``truth`` once: the edges the robot crossed (each as the set of its two darts (vertex,
    exit)) and a hash of each signature it sensed, the start's first, for candidates to be compared against
    (:func:`~topomark.reference.oracle.agreement.matches`)."""
    sim, crossed = Simulator(truth, start, kit), set()
    seen = array("q", [hash(str(sim.robot().sense()))])
    for action in actions:
        before = sim.cost
        seen.append(hash(str(_act(sim, action))))
        if sim.cost != before:
            w, j = sim.state
            u = truth.rotation[w][j]
            crossed.add(frozenset({(w, j), (u, truth.index(u, w))}))
    return crossed, seen


def _edges(world: World) -> list[tuple[str, int, str, int]]:
    return [(v, i, w, world.index(w, v)) for v in world.vertices for i, w in enumerate(world.rotation[v])
            if (v, i) < (w, world.index(w, v))]


def _fresh(taken, name: str) -> str:
    while name in taken:
        name += "'"
    return name


def subdivided(world: World, start: tuple[str, int], u: str, i: int) -> World:
    """``world`` (no markers) with the edge at exit ``i`` of ``u`` replaced by two edges through a new vertex;
    the robot starts where ``start`` says, facing the same exit."""
    w = world.rotation[u][i]
    j = world.index(w, u)
    x = _fresh(world.rotation, f"{u}|{w}")
    rotation = {v: list(ns) for v, ns in world.rotation.items()}
    rotation[u][i], rotation[w][j] = x, x
    rotation[x] = [u, w]
    return World(rotation, (), Start(start[0], rotation[start[0]][start[1]]))


def two_fold_cover(world: World, start: tuple[str, int], u: str, i: int) -> World | None:
    """Two copies of ``world`` (no markers) with the edge at exit ``i`` of ``u`` crossed between them, the robot
    starting in the first copy as ``start`` says; None when the cover is not connected (the edge is a bridge)."""
    w = world.rotation[u][i]
    crossed = {(u, w), (w, u)}
    taken = set(world.rotation)
    names = {(v, s): _fresh(taken, f"{v}~{s}") for v in world.vertices for s in (0, 1)}
    rotation = {names[v, s]: [names[x, s ^ ((v, x) in crossed)] for x in world.rotation[v]]
                for v in world.vertices for s in (0, 1)}
    at = names[start[0], 0]
    try:
        return World(rotation, (), Start(at, rotation[at][start[1]]))
    except InvalidWorld:  # two components: the edge is a bridge
        return None


def determination(truth: World, start: tuple[str, int], kit: Kit, actions: Sequence[Action], map_: World,
                  max_steps: int = MAX_REPLAY_STEPS) -> Determination:
    """Look for a witness that ``map_`` (found extended-isomorphic to ``truth``) was a guess (module docstring).

    ``truth`` is the world played, without markers; ``start`` its start state; ``actions`` what the program did.
    """
    crossed, seen = _walk(truth, start, kit, actions)
    tried = 0
    for u, i, w, j in _edges(truth):
        if frozenset({(u, i), (w, j)}) in crossed:
            continue
        candidate = subdivided(truth, start, u, i)
        tried += 1
        if _matches(candidate, start, kit, actions, seen)[0] and agrees(candidate, start, truth, start, kit,
                                                                          actions)[0]:
            assert candidate.n != map_.n, "a witness has more vertices than the map"
            return Determination(candidate, "subdivided", (u, w), tried, True)
    exact = _decided(truth, start, kit, actions, max_steps)
    covered = _covers(truth, start, kit, actions, seen, map_, max_steps, tried)
    if exact is None:
        return covered
    if exact is False and covered.witness is not None:
        raise TopomarkFault(f"the guess check disagrees with itself: the walk's folding found the map determined, "
                            f"but a two-fold cover (the edge {covered.edge}) gives every observation")
    if covered.witness is not None or exact is False:  # a cover is the plainer witness: it is shown when found
        return Determination(covered.witness, covered.how, covered.edge, covered.candidates, covered.complete,
                             exact=True)
    return Determination(exact.world, exact.how, None, covered.candidates, covered.complete, exact=True)


def _decided(truth: World, start: tuple[str, int], kit: Kit, actions: Sequence[Action], max_steps: int):
    """The exact decision (:mod:`~topomark.reference.oracle.walk_folding`): its witness, False for none (the map is
    determined), None when the run is outside its scope or too long for it."""
    if len(actions) > max_steps:
        return None
    try:
        found = decide(truth, start, kit, actions)
    except (ValueError, OverflowError):
        return None
    return False if found is None else found


def _covers(truth: World, start: tuple[str, int], kit: Kit, actions: Sequence[Action], seen: array, map_: World,
            max_steps: int, tried: int) -> Determination:
    """The two-fold covers (module docstring), within ``max_steps`` replayed actions."""
    budget = max_steps
    for u, i, w, j in _edges(truth):
        cover = two_fold_cover(truth, start, u, i)
        if cover is None:
            continue
        tried += 1
        same, used = _matches(cover, cover.start_state(), kit, actions, seen, budget)
        if same is None:
            return Determination(None, None, None, tried, False)
        budget -= used
        if same and agrees(cover, cover.start_state(), truth, start, kit, actions)[0]:
            assert cover.n != map_.n, "a witness has more vertices than the map"
            return Determination(cover, "two-fold cover", (u, w), tried, True)
    return Determination(None, None, None, tried, True)
