"""The chorded cycle: 4-regular, simple and reproducible by its seed; the robot walks the cycle first; its
diameter is that of a random 4-regular graph, not Θ(n)."""

import networkx as nx
import pytest

from first_walk import new_edge_ends

from topomark.spec.errors import InvalidInput
from topomark.reference.run.explore import explore
from topomark.reference.worlds.chorded_cycle import CHORDED_FROM, chorded_cycle
from topomark.reference.worlds.expensive import circulant


def _graph(world):
    return nx.Graph((v, w) for v in world.vertices for w in world.rotation[v])


@pytest.mark.parametrize("n", [CHORDED_FROM, 20, 101])
@pytest.mark.parametrize("seed", range(4))
def test_it_is_4_regular_simple_with_chords_off_the_cycle(n, seed):
    world = chorded_cycle(n, seed)
    graph = _graph(world)
    assert (world.n, world.m, graph.number_of_edges()) == (n, 2 * n, 2 * n)
    assert all(len(world.rotation[v]) == 4 == len(set(world.rotation[v])) for v in world.vertices)
    for i in range(n):
        listed = world.rotation[str(i)]
        assert listed[:2] == (str((i - 1) % n), str((i + 1) % n))
        assert all((int(c) - i) % n not in (0, 1, n - 1) for c in listed[2:])


def test_the_seed_decides_the_chords():
    assert chorded_cycle(30, 4) == chorded_cycle(30, 4) != chorded_cycle(30, 5)


@pytest.mark.parametrize("seed", range(3))
def test_the_robot_walks_the_cycle_first(seed):
    """The first n − 1 iterations are non-loop and their new edges (replayed by the spec's motion rule) reach
    1, 2, …, n − 1 in turn."""
    n = 20
    world = chorded_cycle(n, seed)
    out = explore(world, "basic")
    assert out.claimed == "correct" and out.violation is None
    assert [row[1] for row in out.breakdown.rows()[1:n]] == ["non-loop"] * (n - 1)
    assert new_edge_ends(world, out.trace)[:n - 1] == [str(k) for k in range(1, n)]


def test_its_diameter_is_logarithmic_where_the_circulants_is_linear():
    assert all(nx.diameter(_graph(chorded_cycle(200, seed))) <= 8 for seed in range(5))
    assert nx.diameter(_graph(circulant(200, 2))) == 50


def test_too_small_a_cycle_is_bad_input():
    with pytest.raises(InvalidInput, match=f"n must be >= {CHORDED_FROM}"):
        chorded_cycle(CHORDED_FROM - 1)
