"""Lighthouse strategies (reference/explorers/lighthouses.py, thesis §3.3, §6.1, §6.2) under every
Chapter 3–4 algorithm."""

from __future__ import annotations

import doctest

import pytest

from topomark.reference.algorithms import ALGORITHMS
from topomark.reference.explorers import lighthouses as lighthouses_module
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse
from topomark.reference.generators import generate, wheel_a, wheel_b
from topomark.reference.simulator import Simulator
from topomark.spec.errors import CheckFailure
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.signature import signature_at
from topomark.spec.world import World

WORLDS = {
    "lattice-hole": lambda: generate("lattice-hole", rows=4, cols=5, seed=3),
    "random": lambda: generate("random", n=8, fraction=0.4, seed=1),
    "complete-hole": lambda: generate("complete-hole", n=6, seed=2),
    "small-world": lambda: generate("small-world", n=10, k=2, p=0.2, seed=4),
    "figure-3.4-a": wheel_a,
    "figure-3.4-b": wheel_b,
}


def _run(world: World, lighthouse: Lighthouse, algorithm: str):
    bare = World(world.rotation, (), world.start)
    sim = Simulator(bare, bare.start_state(), lighthouse.kit)
    explorer = ALGORITHMS[algorithm](sim.robot(), None, None, lighthouse)
    return sim, explorer.explore()


@pytest.mark.parametrize("world", sorted(WORLDS))
@pytest.mark.parametrize("name", sorted(LIGHTHOUSES))
@pytest.mark.parametrize("algorithm", list(ALGORITHMS))
def test_every_lighthouse_maps_every_world_with_every_algorithm(world, name, algorithm):
    """The map equals the world with the markers where the robot dropped them (extended isomorphism)."""
    sim, S = _run(WORLDS[world](), LIGHTHOUSES[name], algorithm)
    result = find_isomorphism(S.to_world(), sim.world)
    assert result.isomorphic, result.mismatch
    assert sum(m.count for m in sim.world.markers) == sum(op.count for op in LIGHTHOUSES[name].ops)


def test_the_default_lighthouse_reproduces_algorithm_3_1_move_for_move():
    """Recognising v0 by table lookup is the thesis's reading of the marker's direction: same moves."""
    world = generate("lattice-hole", rows=5, cols=5, seed=1)
    moves = []
    bare = World(world.rotation, (), world.start)
    sim = Simulator(bare, bare.start_state(), {"directional-vertex": 1},
                    listener=lambda motion, purpose, sig, state: moves.append((motion, str(sig))))
    ALGORITHMS["basic"](sim.robot()).explore()
    again = []
    sim2 = Simulator(bare, bare.start_state(), LIGHTHOUSES["directional-vertex"].kit,
                     listener=lambda motion, purpose, sig, state: again.append((motion, str(sig))))
    ALGORITHMS["basic"](sim2.robot(), None, None, LIGHTHOUSES["directional-vertex"]).explore()
    assert moves == again and len(moves) > 100


def test_the_directional_edge_lighthouse_reads_the_head_at_v0_and_the_tail_at_its_neighbour():
    """§6.1, Figure 6.1(b): the head end is v0, the tail end senses ``E-p-T``."""
    world = wheel_a()
    sim, S = _run(world, LIGHTHOUSES["directional-edge"], "basic")
    (marker,) = sim.world.markers
    assert marker.head == world.start.at and set(marker.between) == {world.start.at, world.start.facing}
    tails = [v for v in S.vertices if "-T" in str(signature_at(S, v, 0))]
    heads = [v for v in S.vertices if "-H" in str(signature_at(S, v, 0))]
    assert heads == [0] and len(tails) == 1


def test_an_undirected_vertex_marker_is_no_lighthouse():
    """§3.2.2: one undirected marker gives no back-link at v0; establishing it is refused, naming why."""
    fake = Lighthouse("undirected-vertex", "§3.2.2", Kit(vertex=1), (MarkerOp("vertex"),))
    world = generate("cycle", n=5)
    with pytest.raises(CheckFailure, match="no explicit back-link"):
        _run(world, fake, "basic")


def test_docstring_examples():
    assert doctest.testmod(lighthouses_module).failed == 0
