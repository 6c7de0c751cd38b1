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
from topomark.reference.oracle import walk_folding as wf
from topomark.reference.oracle.folding import Folding
from topomark.reference.run.simulator import Simulator
from topomark.reference.worlds.deterministic import cycle
from topomark.spec.errors import TopomarkFault
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.kit import Kit, MarkerOp
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
    sim, actions, lying = Simulator(truth, truth.start_state(), kit), [], None
    for _ in range(length):
        here = sim.state[0]
        if lying is None and rng.random() < 0.3:
            op = MarkerOp("vertex", direction=rng.randrange(truth.degree(here)) if kit.directional else None)
            lying = here
        elif kit.movable and lying == here and rng.random() < 0.4:
            op, lying = MarkerOp("vertex", pick_up=True), None
        else:
            motion = rng.randrange(truth.degree(here))
            sim.robot().move(motion, "other")
            actions.append(motion)
            continue
        sim.robot().operate(op)
        actions.append(op)
    return actions


@pytest.mark.parametrize("kit", [Kit(vertex=1, directional=True), UNDIRECTED, Kit(vertex=1, movable=True)],
                         ids=["directional", "undirected", "movable"])
def test_the_decision_agrees_with_a_brute_force_over_every_small_world(kit):
    worlds = list(embedded_worlds(4, 3))
    rng = random.Random(2026)
    tally = {"determined": 0, "witness": 0, "small witness": 0}
    for _ in range(60):
        world = rng.choice(worlds)
        v = rng.choice(sorted(world.rotation))
        truth = _at(world, v, rng.randrange(world.degree(v)))
        actions = _random_walk(rng, truth, kit, rng.randint(0, 16))
        found = wf.decide(truth, truth.start_state(), kit, actions)
        small = _brute(truth, kit, actions, worlds)
        if found is None:
            assert small is None, (truth.rotation, actions, small.rotation)  # determined: no small world shows it
            tally["determined"] += 1
        else:
            assert d.agrees(found.world, found.world.start_state(), truth, truth.start_state(), kit, actions)[0]
            tally["witness"] += 1
            tally["small witness"] += small is not None
    assert min(tally.values()) > 0, tally  # the sample reaches every verdict


def test_covers_that_find_a_witness_the_decision_missed_are_topomark_s_fault(monkeypatch):
    three = cycle(3)
    monkeypatch.setattr(d, "_decided", lambda *args: False)  # the seeded fault: the decision says determined
    with pytest.raises(TopomarkFault, match="disagrees with itself"):
        d.determination(three, three.start_state(), d.LIGHTHOUSE, [1, 1, 1], three)


def test_edge_markers_and_two_lying_markers_are_outside_the_exact_decision():
    three = cycle(3)
    found = d.determination(three, three.start_state(), Kit(edge=1), [1, 1, 1], three)
    assert not found.exact and found.witness is not None
    assert wf.walk(three, three.start_state(), Kit(edge=1), []).scope == "the kit has edge markers"
    two = Kit(vertex=2)
    assert wf.walk(three, three.start_state(), two, [DROP, 1, DROP]).scope == \
        "two vertex markers lay in the world at once"
    found = d.determination(three, three.start_state(), two, [DROP, 1, DROP, 1, 1], three)
    assert not found.exact and "not decided exactly" in found.words(3)


def test_a_walk_past_the_branch_bound_is_not_decided_exactly(monkeypatch):
    monkeypatch.setattr(wf, "MAX_BRANCHES", 0)
    with pytest.raises(OverflowError):
        wf.decide(K4, K4.start_state(), UNDIRECTED, K4_WALK)
    assert not d.determination(K4, K4.start_state(), UNDIRECTED, K4_WALK, K4).exact
