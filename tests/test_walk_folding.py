"""No credit for a guess, decided exactly: the walk's folding (:mod:`topomark.reference.oracle.walk_folding`).

* the folding itself: conflicts, loops and multiple edges, the square closed;
* §3.2.2's pair (Figure 3.4): with one undirected marker a program cannot tell K4's two embeddings apart — no
  subdivision or two-fold cover shows it, the exact decision does, and an independent brute force over every world
  of at most four vertices finds the other K4;
* the quotient step finds the triangle under a hexagon, and the marker rules it out when it was seen;
* cross-checked against that brute force on seeded random walks (directional, undirected, movable marker): every
  world of ≤ 4 vertices that gives the observations and is not the map is found by the decision as some witness,
  and a map the decision calls determined has no such world;
* the runtime cross-check with the covers (exit 3 when they disagree) and the scope (edge markers: not exact).
"""

from __future__ import annotations

import random

import pytest

from topomark.proofs.enumerate import embedded_worlds
from topomark.reference.oracle import determination as d
from topomark.reference.oracle import folded_marks as fm
from topomark.reference.oracle import walk_folding as wf
from topomark.reference.oracle.folding import Folding
from topomark.reference.run.simulator import Simulator
from topomark.reference.worlds.deterministic import cycle
from topomark.spec.errors import CheckFailure, InvalidInput, TopomarkFault
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.kit import Kit, MarkerOp, ThreadOp
from topomark.spec.world import Start, World

UNDIRECTED = Kit(vertex=1)
DROP = MarkerOp("vertex")
# K4 in one of its two embeddings (§3.2.2, Figure 3.4), and a walk with one undirected marker that crosses every
# edge and sees the marker again, found by a random search: the other embedding shows the same
K4 = World({"v0": ["v1", "v2", "v3"], "v1": ["v0", "v3", "v2"], "v2": ["v0", "v1", "v3"], "v3": ["v0", "v2", "v1"]},
           (), Start("v2", "v0"))
K4_WALK = [DROP, 0, 1, 2, 2, 2, 1, 0, 0, 2, 1, 2, 1, 0]


def _without_exact(monkeypatch):
    monkeypatch.setattr(d, "_decided", lambda *args: None)


def _at(world: World, v: str, i: int) -> World:
    return World(world.rotation, (), Start(v, world.rotation[v][i]))


def _brute(truth: World, kit: Kit, actions, worlds) -> World | None:
    """Every start of every world in ``worlds``: one that gives the observations and is not the map, or None."""
    start = truth.start_state()
    target = wf._left(truth, start, kit, actions)
    for world in worlds:
        for v in world.rotation:
            for i in range(world.degree(v)):
                candidate = _at(world, v, i)
                if d.agrees(candidate, (v, i), truth, start, kit, actions)[0] and (
                        candidate.n != target.n or not find_isomorphism(
                            wf._left(candidate, (v, i), kit, actions), target, markers=True).isomorphic):
                    return candidate
    return None


def test_a_folding_refuses_what_no_rotation_system_has():
    f = Folding([2, 3])
    assert not f.union(0, 0, 1, 0)  # degrees differ
    g = Folding([2, 2, 2, 2, 2])
    assert all(g.join(i, 1, i + 1, 0) for i in range(4)) and g.union(4, 0, 0, 0)
    assert not g.copy().union(4, 0, 0, 1)  # one vertex, two rotations
    built = g.world(1)
    assert built is not None and built[0].n == 4 and not built[2]
    loop = Folding([2, 2])
    assert loop.join(0, 1, 1, 0) and loop.union(1, 1, 0, 0)  # two vertices joined twice: a multiple edge
    assert loop.world(1) is None


def test_the_undirected_marker_cannot_tell_k4_s_embeddings_apart_and_only_the_exact_decision_sees_it(monkeypatch):
    found = d.determination(K4, K4.start_state(), UNDIRECTED, K4_WALK, K4)
    assert found.witness is not None and found.exact and found.how in ("unvisited exit", "finer world")
    assert d.agrees(found.witness, found.witness.start_state(), K4, K4.start_state(), UNDIRECTED, K4_WALK)[0]
    other = _brute(K4, UNDIRECTED, K4_WALK, list(embedded_worlds(4, 3, min_vertices=4)))
    assert other is not None and other.n == 4  # the other embedding of K4
    _without_exact(monkeypatch)  # the seeded fault: the sound tests alone let the guess through
    assert d.determination(K4, K4.start_state(), UNDIRECTED, K4_WALK, K4).witness is None


def test_the_same_walk_with_a_directional_marker_rules_out_the_other_k4_but_not_a_larger_world():
    kit = Kit(vertex=1, directional=True)
    walk = [MarkerOp("vertex", direction=0)] + K4_WALK[1:]
    assert _brute(K4, kit, walk, list(embedded_worlds(4, 3))) is None  # no world of ≤ 4 vertices shows it
    found = d.determination(K4, K4.start_state(), kit, walk, K4)
    assert found.exact and found.witness is not None and found.witness.n > 4  # an exit no visit told apart
    assert d.agrees(found.witness, found.witness.start_state(), K4, K4.start_state(), kit, walk)[0]


def test_the_quotient_step_finds_the_triangle_under_a_hexagon_and_the_marker_rules_it_out(monkeypatch):
    hexagon = cycle(6)
    kit = Kit(vertex=1, directional=True)
    walk = [MarkerOp("vertex", direction=0)] + [1] * 6  # once round, the marker seen again: a closed hexagon
    assert wf.decide(hexagon, hexagon.start_state(), kit, walk) is None  # on a triangle it is seen after 3
    found = wf.decide(hexagon, hexagon.start_state(), kit, walk, agrees=lambda candidate, at: True)
    assert found is not None and found.how == "quotient" and found.world.n in (2, 3)
    assert found.world.n == 3 and find_isomorphism(found.world, cycle(3), markers=False).isomorphic
    monkeypatch.setattr(wf, "_quotient", lambda *args: None)  # the seeded fault: no quotient step
    assert wf.decide(hexagon, hexagon.start_state(), kit, walk, agrees=lambda candidate, at: True) is None


def _random_walk(rng: random.Random, truth: World, kit: Kit, length: int) -> list:
    """Random motions, marker and thread operations the kit allows (one the simulator refuses is left out)."""
    sim, actions = Simulator(truth, truth.start_state(), kit), []
    for _ in range(length):
        action = _random_action(rng, kit, truth.degree(sim.state[0]))
        try:
            d._act(sim, action)
        except (InvalidInput, CheckFailure):  # refused: start again from the actions kept
            sim = Simulator(truth, truth.start_state(), kit)
            for kept in actions:
                d._act(sim, kept)
            continue
        actions.append(action)
    return actions


def _random_action(rng: random.Random, kit: Kit, degree: int):
    r = rng.random()
    if r < 0.2 and (kit.vertex or kit.either):
        return MarkerOp("vertex", direction=rng.randrange(degree) if kit.directional else None)
    if r < 0.32 and (kit.edge or kit.either):
        return MarkerOp("edge", exit=rng.randrange(degree), direction=rng.choice("HT") if kit.directional else None)
    if r < 0.4 and kit.movable:
        return rng.choice([MarkerOp("vertex", pick_up=True), MarkerOp("edge", exit=rng.randrange(degree),
                                                                          pick_up=True)])
    if r < 0.6 and kit.thread is not None:
        return rng.choice([ThreadOp("tie", direction=rng.choice([None, rng.randrange(degree)])), d.REWIND,
                           ThreadOp("leave"), ThreadOp("take"), ThreadOp("knot", count=rng.randint(1, 2)),
                           ThreadOp("untie")])
    return rng.randrange(degree)


KITS = {"directional": Kit(vertex=1, directional=True), "undirected": UNDIRECTED,
        "movable": Kit(vertex=1, movable=True), "two undirected": Kit(vertex=2),
        "three directional": Kit(vertex=3, directional=True), "edge": Kit(edge=2),
        "directional edge": Kit(edge=2, directional=True), "vertex and edge": Kit(vertex=1, edge=1),
        "movable two": Kit(vertex=2, movable=True), "movable edge": Kit(edge=2, movable=True),
        "vertex-or-edge pool": Kit(either=3), "l = ε thread": Kit(thread=0),
        "thread and marker": Kit(thread=4, vertex=1)}


def _cross_check(kit: Kit, walks: int = 60) -> dict[str, int]:
    """Seeded random walks on every world of ≤ 4 vertices: how often the decision and the brute force say what."""
    worlds = list(embedded_worlds(4, 3))
    rng = random.Random(2026)
    tally = {"determined": 0, "witness": 0, "small witness": 0, "missed": 0}
    for _ in range(walks):
        world = rng.choice(worlds)
        v = rng.choice(sorted(world.rotation))
        truth = _at(world, v, rng.randrange(world.degree(v)))
        actions = _random_walk(rng, truth, kit, rng.randint(0, 20))
        try:
            found = wf.decide(truth, truth.start_state(), kit, actions)
        except ValueError:  # back along an edge the thread lay on twice, without a rewind: outside the decision
            tally["outside"] = tally.get("outside", 0) + 1
            continue
        small = _brute(truth, kit, actions, worlds)
        if found is None:
            tally["missed" if small is not None else "determined"] += 1  # determined: no small world shows it
        else:
            assert d.agrees(found.world, found.world.start_state(), truth, truth.start_state(), kit, actions)[0]
            tally["witness"] += 1
            tally["small witness"] += small is not None
    return tally


@pytest.mark.parametrize("kit", list(KITS.values()), ids=list(KITS))
def test_the_decision_agrees_with_a_brute_force_over_every_small_world(kit):
    tally = _cross_check(kit)
    assert tally.pop("missed") == 0 and tally.pop("outside", 0) < 30
    assert min(tally.values()) > 0, tally  # the sample reaches every verdict


def test_an_edge_marker_seen_from_the_far_end_of_an_uncrossed_edge_is_a_way_the_decision_must_try(monkeypatch):
    kept = fm._edge_options

    def same_dart_only(*args):
        return [option for option in kept(*args) if option[0] != "join"]

    monkeypatch.setattr(fm, "_edge_options", same_dart_only)  # the seeded fault: the far end never tried
    assert _cross_check(KITS["edge"])["missed"] > 0


def test_covers_that_find_a_witness_the_decision_missed_are_topomark_s_fault(monkeypatch):
    three = cycle(3)
    monkeypatch.setattr(d, "_decided", lambda *args: False)  # the seeded fault: the decision says determined
    with pytest.raises(TopomarkFault, match="disagrees with itself"):
        d.determination(three, three.start_state(), d.LIGHTHOUSE, [1, 1, 1], three)


# Two undirected edge markers dropped at the start, a short walk: no subdivision or two-fold cover shows another
# world, the exact decision does (found by a random search over the worlds of five vertices)
EDGE_WORLD = World({"v0": ["v1"], "v1": ["v0", "v3", "v4"], "v2": ["v3", "v4"], "v3": ["v1", "v4", "v2"],
                    "v4": ["v1", "v3", "v2"]}, (), Start("v4", "v1"))
EDGE_WALK = [MarkerOp("edge", exit=2), MarkerOp("edge", exit=1), 0, 1, 0, 1, 2]


def test_edge_markers_a_guess_only_the_exact_decision_sees(monkeypatch):
    kit, start = Kit(edge=2), EDGE_WORLD.start_state()
    found = d.determination(EDGE_WORLD, start, kit, EDGE_WALK, EDGE_WORLD)
    assert found.exact and found.witness is not None
    assert d.agrees(found.witness, found.witness.start_state(), EDGE_WORLD, start, kit, EDGE_WALK)[0]
    other = _brute(EDGE_WORLD, kit, EDGE_WALK, list(embedded_worlds(5, 3, min_vertices=5)))
    assert other is not None and other.n == 5  # another world of five vertices gives every observation
    _without_exact(monkeypatch)  # the seeded fault: the sound tests alone let the guess through
    assert d.determination(EDGE_WORLD, start, kit, EDGE_WALK, EDGE_WORLD).witness is None


def test_a_folding_that_puts_a_mark_where_none_was_sensed_is_cut_and_one_short_of_a_mark_branches():
    three = cycle(3)
    walk = wf.walk(three, three.start_state(), UNDIRECTED, [DROP, 1, 1, 1])  # round the triangle, seen again
    base = Folding(walk.degree)
    assert all(base.join(i, ri, j, rj) for i, ri, j, rj in walk.edges)
    short = fm.scan(base, walk.ops, walk.events)  # the last visit saw the marker: it must be the start's vertex
    assert isinstance(short, fm.Deficit) and short.event == len(walk.events) - 1 and short.exit is None
    assert {option[3] for option in short.options} == {0} and not short.forced  # undirected: two rotations
    wrong = base.copy()
    assert wrong.union(1, 0, 0, 0)  # the first step's vertex made the start's: it would have seen the marker
    assert fm.scan(wrong, walk.ops, walk.events) is fm.PRUNED
    right = base.copy()
    assert right.union(3, 0, 0, 0) and fm.scan(right, walk.ops, walk.events) is None


def test_a_move_back_along_the_thread_is_decided_unless_the_edge_held_it_twice():
    three = cycle(3)
    kit = Kit(thread=6)
    tie = ThreadOp("tie")
    assert wf.walk(three, three.start_state(), kit, [tie, 1, d.REWIND]).scope is None
    back = [tie, 1, 0]  # a motion back along the one laid edge: the robot senses it empty, so in every world
    assert wf.walk(three, three.start_state(), kit, back).scope is None
    assert wf.decide(three, three.start_state(), kit, back) is not None  # one edge seen: a guess, decided exactly
    twice = [tie, 1, 1, 1, 1, 0]  # a lap and one more edge: the thread lies twice on the first edge
    assert wf.walk(three, three.start_state(), kit, twice).scope == \
        "a move went back along an edge the thread lay on twice, without a rewind operation"
    with pytest.raises(ValueError):
        wf.decide(three, three.start_state(), kit, twice)
    assert not d.determination(three, three.start_state(), kit, twice, three).exact  # the sound tests alone


def test_untying_takes_the_free_end_left_lying_with_it(monkeypatch):
    kept = wf._Thread.op

    def keeps_the_end(self, out, now, op):  # the seeded fault: the free end stays in the model after untie
        left = self.left
        kept(self, out, now, op)
        if op.op == "untie" and left:
            out.ops.pop()

    assert _cross_check(KITS["l = ε thread"], 150)["missed"] == 0
    monkeypatch.setattr(wf._Thread, "op", keeps_the_end)
    assert _cross_check(KITS["l = ε thread"], 150)["missed"] > 0


def test_a_walk_past_the_branch_bound_is_not_decided_exactly(monkeypatch):
    monkeypatch.setattr(wf, "MAX_BRANCHES", 0)
    with pytest.raises(OverflowError):
        wf.decide(K4, K4.start_state(), UNDIRECTED, K4_WALK)
    assert not d.determination(K4, K4.start_state(), UNDIRECTED, K4_WALK, K4).exact
