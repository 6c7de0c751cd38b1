"""Lighthouses found by a random walk (reference/explorers/lighthouse_search.py): §5.1 undirected-vertex, §6.1
undirected-edge — where they land, how they fail, how they are recognised, replayed and configured."""

from __future__ import annotations

import copy
import json

import pytest

from topomark.reference.worlds import generators as g
from topomark.reference.algorithms.registry import in_family
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.explorers.probing import aperiodic, identify
from topomark.reference.replay.replay import replay
from topomark.reference.run.simulator import Simulator
from topomark.spec.errors import AlgorithmFailed
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.world import Start, World

ALGORITHMS = {name: spec.factory for name, spec in in_family("algorithm-3.1").items()}
"""Algorithm 3.1's family, as registered: ``basic`` and the Chapter 4 enhancements, name ↦ explorer class."""

VERTEX, EDGE = LIGHTHOUSES["undirected-vertex"], LIGHTHOUSES["undirected-edge"]


def bare(world: World) -> World:
    return World(world.rotation, (), world.start)


def neighbour_degrees(world: World, v: str) -> list[int]:
    return [world.degree(u) for u in world.rotation[v]]


@pytest.mark.parametrize("light", [VERTEX, EDGE], ids=lambda h: h.name)
def test_the_smallest_vertex_transitive_world_ends_failed_with_the_reason(light):
    """A triangle: every D is (2, 2) and every edge joins equal degrees — the walk gives up after walk_limit
    steps (AlgorithmFailed), and the driver reports ``failed``, never a map."""
    triangle = g.cycle(3)
    sim = Simulator(triangle, triangle.start_state(), light.kit)
    explorer = ALGORITHMS["basic"](sim.robot(), None, None, light.with_options(walk_limit=7))
    with pytest.raises(AlgorithmFailed, match="within 7 walk steps") as raised:
        explorer.start()
    assert sim.by_purpose["establish"] == 7 == raised.value.walk_steps and not sim.world.markers
    out = explore(triangle, "enh3", lighthouse=light, record=False)
    assert (out.outcome, out.verified) == ("failed", False) and "within 200 walk steps" in out.reason
    assert out.walk_steps == 200  # the robot walked its whole limit, and the run says so


@pytest.mark.parametrize("figure", [g.wheel_a, g.wheel_b], ids=["3.4a", "3.4b"])
def test_figure_3_4_always_picks_a_corner_and_maps_correctly(figure):
    """§5.1: on both Figure 3.4 worlds "the robot always selects one of the four corner vertices as the
    lighthouse, because … D = (4, 3, 3) … lacks rotational equivalent" — from every start, for several seeds."""
    world = bare(figure())
    for start in world.vertices:
        for seed in range(3):
            w = world.with_start(Start(start, world.rotation[start][0]))
            sim = Simulator(w, w.start_state(), VERTEX.kit)
            S = ALGORITHMS["basic"](sim.robot(), None, None, VERTEX.with_options(seed=seed)).explore()
            (marker,) = sim.world.markers
            assert world.degree(marker.at) == 3 and sorted(neighbour_degrees(world, marker.at)) == [3, 3, 4]
            assert find_isomorphism(S.to_world(), sim.world).isomorphic


def test_the_walk_tests_the_start_first_and_v0_is_where_the_robot_stands():
    """§5.1 "either at the initial location or otherwise within a few steps": a start whose D is aperiodic
    holds the marker with no walk; elsewhere the believed pose (v0, 0) is the robot's state after the walk,
    where the checker anchors φ (verified runs)."""
    world = bare(g.wheel_a()).with_start(Start("1", "0"))  # a corner: D = (4, 3, 3) from its entry
    sim = Simulator(world, world.start_state(), VERTEX.kit)
    explorer = ALGORITHMS["basic"](sim.robot(), None, None, VERTEX)
    explorer.start()
    assert explorer.beacon.walk_steps == 0 and [m.at for m in sim.world.markers] == ["1"]
    assert explorer.position == (0, 0) and sim.state[0] == "1"
    centre = bare(g.wheel_a())  # the centre: D = (3, 3, 3, 3), periodic
    sim = Simulator(centre, centre.start_state(), VERTEX.kit)
    explorer = ALGORITHMS["basic"](sim.robot(), None, None, VERTEX)
    explorer.start()
    assert explorer.beacon.walk_steps >= 1 and sim.state[0] != "0" and [m.at for m in sim.world.markers] == [
        sim.state[0]]


def test_recognising_v0_probes_only_as_many_neighbours_as_it_takes():
    """§5.1: not every incident edge — entering a (4, 3, 3) corner from the centre no probe at all (the degree
    just left is unique in D); from a corner one probe (2 traversals) and 2 to face the entry again."""
    world = bare(g.wheel_a())
    D = neighbour_degrees(world, "1")  # exits of '1' in order: '0' (4), '4' (3), '2' (3)
    sim = Simulator(world, ("1", 0), VERTEX.kit)
    robot = sim.robot()
    for came_from, probes in (("0", 0), ("4", 4), ("2", 4)):
        entry = world.index("1", came_from)
        sim.state, cost = ("1", entry), sim.cost
        sig = robot.sense()
        got = identify(robot, sig, lambda j, r: D[(j + r) % 3], world.degree(came_from), 1)
        assert got == entry and sim.cost - cost == probes and sim.state == ("1", entry)


def test_the_searched_lighthouses_map_every_family_and_replay(tmp_path, capsys):
    """Both under basic and an enhancement on lattice-hole, random, complete-hole, small-world: verified, and
    the trace (establish and probe moves, v0 away from the start) replays."""
    worlds = {"lattice-hole": g.lattice_hole(4, 4, seed=2), "random": g.generate("random", n=9, fraction=0.4, seed=3),
              "complete-hole": g.generate("complete-hole", n=6, seed=2),
              "small-world": g.generate("small-world", n=10, k=2, p=0.2, seed=4)}
    for name, w in worlds.items():
        for light in (VERTEX, EDGE):
            for algorithm in ("basic", "enh3+5"):
                out = explore(bare(w), algorithm, lighthouse=light.with_options(seed=5))
                assert out.outcome == "correct" and out.verified, (name, light.name, algorithm, out.violation)
                assert replay(bare(w), iter(copy.deepcopy(out.trace))).ok, (name, light.name, algorithm)


def test_undirected_edge_marks_an_edge_of_different_degrees_and_v0_is_the_end_reached():
    """§6.1 ("either one of the end vertices"): v0 is the end the robot walked into, the marker on the
    edge it came by (v0's exit 0); recognised by table, no probes."""
    world = bare(g.wheel_a())  # start at the centre (degree 4): its first step reaches a corner (degree 3)
    sim = Simulator(world, world.start_state(), EDGE.kit)
    explorer = ALGORITHMS["basic"](sim.robot(), None, None, EDGE)
    explorer.start()
    (marker,) = sim.world.markers
    v0, entry = sim.state
    assert explorer.beacon.walk_steps == 1 and world.degree(v0) == 3 and set(marker.between) == {"0", v0}
    assert world.rotation[v0][entry] == "0" and explorer.beacon.recognise is None
    out = explore(world, "enh3", lighthouse=EDGE, record=False)
    assert out.verified and "probe" not in out.by_purpose


def test_never_a_wrong_map_on_small_random_worlds():
    """Issue 11: §5.1 / §6.1 are either correct (verified) or failed, never a wrong map."""
    seen = set()
    for seed in range(8):
        w = bare(g.generate("random", n=7, fraction=0.3, seed=seed))
        for light in (VERTEX, EDGE):
            out = explore(w, "basic", lighthouse=light.with_options(seed=seed, walk_limit=30), record=False)
            assert out.outcome in ("correct", "failed") and out.verified == (out.outcome == "correct")
            seen.add(out.outcome)
    assert "correct" in seen


def test_neighbourhood_two_tests_the_views_to_distance_two():
    """--neighbourhood 2 (§5.1: a larger neighbourhood): more probes, still verified; a regular world still
    fails (its views are equal at every distance)."""
    w = bare(g.lattice_hole(4, 4, seed=2))
    one = explore(w, "basic", lighthouse=VERTEX, record=False)
    two = explore(w, "basic", lighthouse=VERTEX.with_options(neighbourhood=2), record=False)
    assert one.verified and two.verified and two.by_purpose["probe"] > one.by_purpose["probe"]
    assert explore(g.cycle(4), "basic", lighthouse=VERTEX.with_options(neighbourhood=2, walk_limit=5),
                   record=False).outcome == "failed"
    assert aperiodic([(3, (2, 2)), (3, (2, 3)), (3, (2, 2))]) and not aperiodic([(3, (2, 2))] * 2)


@pytest.mark.parametrize("args, message", [
    (["--lighthouse", "undirected-vertex", "--walk-limit", "0"], "--walk-limit must be at least 1, got 0"),
    (["--lighthouse", "undirected-vertex", "--walk-limit", "-4"], "--walk-limit must be at least 1, got -4"),
    (["--lighthouse", "undirected-edge", "--walk-limit", "ten"], "--walk-limit must be an integer, got 'ten'"),
    (["--lighthouse", "undirected-vertex", "--neighbourhood", "0"], "--neighbourhood must be at least 1, got 0"),
    (["--lighthouse", "undirected-edge", "--neighbourhood", "2"], "takes no option --neighbourhood"),
    (["--lighthouse", "directional-edge", "--walk-limit", "5"], "takes no option --walk-limit"),
    (["--walk-limit", "5"], "--walk-limit is an option of a searched lighthouse"),
])
def test_bad_lighthouse_options_are_bad_input(args, message, capsys):
    assert main(["explore", "lattice-hole", *args, "--quiet"]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.splitlines()) == 1


def test_the_cli_reports_failed_with_exit_1_and_seeds_the_walk(capsys):
    assert main(["explore", "cycle:n=4", "--lighthouse", "undirected-vertex", "--walk-limit", "9", "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["outcome"] == "failed" and "within 9 walk steps" in data["reason"]
    assert data["by_purpose"]["establish"] == 9 == data["walk_steps"]
    costs = set()
    for seed in ("1", "2", "3"):
        assert main(["explore", "small-world:n=12,k=2,p=0.2,seed=4", "--lighthouse", "undirected-edge", "--seed",
                     seed, "--json"]) == 0
        costs.add(json.loads(capsys.readouterr().out)["cost"])
    assert len(costs) > 1  # --seed seeds the walk, not the world (given in the generator text)


@pytest.mark.parametrize("light", ["undirected-vertex", "undirected-edge"])
def test_a_failed_search_reports_the_steps_it_walked(light, capsys):
    """cycle:n=6, seed 2: no lighthouse within 200 walk steps; the report's walk_steps is the 200 walked, not 0."""
    assert main(["explore", "cycle:n=6", "--lighthouse", light, "--seed", "2", "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert (data["outcome"], data["walk_steps"], data["lighthouse_at"]) == ("failed", 200, None)
