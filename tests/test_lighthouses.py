"""Lighthouse strategies (reference/explorers/lighthouses.py, thesis §3.3, §6.1, §6.2) under every
Chapter 3–4 algorithm."""

from __future__ import annotations

import copy
import functools
from collections import Counter

import pytest

from topomark.reference.algorithms.expectation import as_expected
from topomark.reference.algorithms.registry import algorithm_spec, in_family
from topomark.reference.explorers.lighthouses import LIGHTHOUSES, Lighthouse
from topomark.reference.explorers.probing import ProbingRobot
from topomark.spec.mapstate import PartialMap
from topomark.spec.signature import Signature
from topomark.reference.worlds.generators import generate, wheel_a
from topomark.reference.run.simulator import Simulator
from topomark.spec.errors import ExplorerFault
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.kit import Kit, MarkerOp, ThreadOp
from topomark.spec.signature import signature_at
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.world import World
from topomark.spec.worldfile import dumps_world, load_world
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.run.local_places import unique_place

ALGORITHMS = {name: spec.factory for name, spec in in_family("algorithm-3.1").items()}
"""Algorithm 3.1's family, as registered: ``basic`` and the Chapter 4 enhancements, name ↦ explorer class."""

from conftest import FIGURE_3_4, make_world

RANDOM, COMPLETE_HOLE = "random:n=8,fraction=0.4,seed=1", "complete-hole:n=6,seed=2"
WORLDS = ("lattice-hole:rows=4,cols=5,seed=3", RANDOM, COMPLETE_HOLE, "small-world:n=10,k=2,p=0.2,seed=4",
          *FIGURE_3_4)
"""One world of each family, and the Figure 3.4 pair: each is explored by every lighthouse with every algorithm."""


@functools.cache
def _holds(text: str, name: str) -> bool:
    """Whether the lighthouse must map the world: always, but §5.2.1's only where the place they chose is unique
    (reference/run/local_places.py).  Elsewhere any outcome but a crash (tests/test_local_lighthouses.py)."""
    light = LIGHTHOUSES[name]
    if light.certain:
        return True
    w = make_world(text)
    bare = World(w.rotation, (), w.start)
    sim = Simulator(bare, bare.start_state(), light.kit)
    ALGORITHMS["basic"](sim.robot(), None, None, light).start()
    return unique_place(bare, name, sim.state, light.neighbourhood)


def _any_outcome(text: str, name: str, algorithm: str) -> None:
    w = make_world(text)
    out = explore(World(w.rotation, (), w.start), algorithm, lighthouse=name, record=False)
    expected, _ = algorithm_spec(algorithm).expectation(None, name)  # may-fail: §5.2.1's outcomes, limit included
    assert as_expected(expected, out.outcome) and out.verified == (out.outcome == "correct")


def _run(world: World, lighthouse: Lighthouse, algorithm: str):
    bare = World(world.rotation, (), world.start)
    sim = Simulator(bare, bare.start_state(), lighthouse.kit)
    explorer = ALGORITHMS[algorithm](sim.robot(), None, None, lighthouse)
    return sim, explorer.explore()


@pytest.mark.parametrize("text", WORLDS)
@pytest.mark.parametrize("name", sorted(LIGHTHOUSES))
@pytest.mark.parametrize("algorithm", list(ALGORITHMS))
def test_every_lighthouse_maps_every_world_with_every_algorithm(text, name, algorithm):
    """The map equals the world with the markers where the robot dropped them (extended isomorphism)."""
    if not _holds(text, name):
        return _any_outcome(text, name, algorithm)
    sim, S = _run(make_world(text), LIGHTHOUSES[name], algorithm)
    result = find_isomorphism(S.to_world(), sim.world)
    assert result.isomorphic, result.mismatch
    ops = LIGHTHOUSES[name].ops
    assert sum(m.count for m in sim.world.markers) == sum(op.count for op in ops if isinstance(op, MarkerOp))
    assert (getattr(sim.world, "thread", None) is not None) == any(isinstance(op, ThreadOp) for op in ops)


@pytest.mark.parametrize("text", WORLDS)
@pytest.mark.parametrize("name", sorted(LIGHTHOUSES))
@pytest.mark.parametrize("algorithm", list(ALGORITHMS))
def test_every_pair_is_verified_by_the_checker(text, name, algorithm):
    """Issue 10: every lighthouse with every Chapter 3–4 algorithm, every check after every iteration."""
    if not _holds(text, name):
        return _any_outcome(text, name, algorithm)
    w = make_world(text)
    outcome = explore(World(w.rotation, (), w.start), algorithm, lighthouse=name, record=False)
    assert outcome.verified, outcome.violation
    assert outcome.marker_operations == Counter(getattr(op, "op", "drop") for op in LIGHTHOUSES[name].ops)


def test_the_map_file_shows_the_markers_where_the_robot_dropped_them(tmp_path, capsys):
    w = generate("lattice-hole", rows=4, cols=4, seed=5)
    (tmp_path / "w.json").write_text(dumps_world(w))
    code = main(["explore", str(tmp_path / "w.json"), "--lighthouse", "vertex-and-edge", "--map",
                 str(tmp_path / "m.json"), "--quiet"])
    assert code == 0, capsys.readouterr().err
    drawn = load_world(tmp_path / "m.json")
    assert sorted(type(m).__name__ for m in drawn.markers) == ["EdgeMarker", "VertexMarker"]
    v0, facing = w.start_state()
    faced = w.neighbour(v0, facing)
    truth = World(w.rotation, [VertexMarker(v0), EdgeMarker((v0, faced))], w.start)
    assert find_isomorphism(drawn, truth).isomorphic
    assert not find_isomorphism(drawn, World(w.rotation, [VertexMarker(v0)], w.start)).isomorphic


@pytest.mark.parametrize("argv, message", [
    (["cycle:n=5", "--lighthouse", "sideways"], "unknown lighthouse 'sideways'"),
    (["chain:n=3", "--lighthouse", "three-undirected-edge"], "needs a start vertex of degree >= 2"),
    (["wheel-a:marker=undirected", "--lighthouse", "vertex-and-edge"], "carries 1 of the 2 markers"),
    (["wheel-a:marker=undirected", "--lighthouse", "directional-edge"], "cannot use the marker"),
])
def test_a_lighthouse_the_world_cannot_take_is_bad_input(argv, message, capsys):
    assert main(["explore", *argv, "--quiet"]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.splitlines()) == 1


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
    """§3.2.2: one undirected marker gives no back-link at v0; establishing it is refused, naming why.  A lighthouse
    of explicit place and back-link that gives none is defined wrongly: a bug (exit 3), not the checker's verdict."""
    fake = Lighthouse("undirected-vertex", "§3.2.2", Kit(vertex=1), (MarkerOp("vertex"),), "an undirected marker")
    world = generate("cycle", n=5)
    with pytest.raises(ExplorerFault, match="no explicit back-link"):
        _run(world, fake, "basic")


# -- lighthouses recognised by probing (Figure 3.21(b), §5.1; reference/explorers/probing.py) ------------------
def _at_v0_from(world: World, light: Lighthouse, neighbour: str):
    """A robot that established ``light`` at the start v0, then stands at ``neighbour`` and moves into v0."""
    bare = World(world.rotation, (), world.start)
    sim = Simulator(bare, bare.start_state(), light.kit)
    beacon = light.establish(sim.robot(), PartialMap())
    v0 = sim.state[0]
    sim.state = (neighbour, 0)
    sig = sim.robot().move(bare.index(neighbour, v0), "new")
    return sim, beacon, sig


def test_three_undirected_vertex_probes_only_until_it_knows_the_entry_and_faces_it_again():
    """Figure 3.21(b): from the two-marker neighbour no probe; from another, probes clockwise until one entry
    is left (entering from '2', the two probes that find no marker rule out the rest), then faces the entry
    edge again (2 traversals per probe, 2 to face it); the perception is V-r, r the marked neighbour's exit."""
    world = wheel_a()  # v0 = '0' (degree 4) faces '1': '1' gets the two markers
    light = LIGHTHOUSES["three-undirected-vertex"]
    for neighbour, probes in (("1", 0), ("4", 1 * 2 + 2), ("3", 2 * 2 + 2), ("2", 2 * 2 + 2)):
        sim, beacon, sig = _at_v0_from(world, light, neighbour)
        assert str(sig) == "[4,V,A]" and sig in beacon.raw
        state, cost = sim.state, sim.cost
        got = beacon.recognise(sim.robot(), sig, signature_at(sim.world, neighbour, 0))
        entry = world.index("0", neighbour)
        assert got == Signature(4, 1, (0 - entry) % 4) and beacon.table[got] == entry
        assert sim.state == state and sim.cost - cost == probes and sim.by_purpose["probe"] == probes


def test_the_default_lighthouse_pays_nothing_for_probing():
    """Only a probing lighthouse wraps the robot; the others drive it directly and perceive S itself."""
    w = make_world(RANDOM)
    plain = explore(World(w.rotation, (), w.start), "enh3", record=False)
    assert "probe" not in plain.by_purpose and "establish" not in plain.by_purpose
    assert plain.explorer.P is plain.explorer.S and not isinstance(plain.explorer.robot, ProbingRobot)
    probed = explore(World(w.rotation, (), w.start), "enh3", lighthouse="three-undirected-vertex", record=False)
    assert probed.verified and isinstance(probed.explorer.robot, ProbingRobot)
    assert probed.by_purpose["drop"] == probed.drop_trips == 2 and probed.cost == sum(probed.by_purpose.values())


def test_a_probing_lighthouse_keeps_lemma_1_with_its_probed_perception():
    """Expected perceptions at v0 carry the probed entry (V-r), so (M, P^E) stay unique (Lemma 1) even where
    two hypotheses share M; the lemma-1 check runs after every iteration of every algorithm."""
    w = make_world(COMPLETE_HOLE)
    for algorithm in ("basic", "enh1"):
        out = explore(World(w.rotation, (), w.start), algorithm, lighthouse="three-undirected-vertex")
        assert out.verified, out.violation
        at_v0 = [h for r in out.trace if r["event"] == "iteration" for h in r["hypotheses"] if "V-" in h["expected"][-1]]
        assert at_v0 and all("V-" in h["expected"][-1] and "V2" not in h["expected"][-1] for h in at_v0)


def test_replay_rejects_a_probe_move_where_no_probe_belongs():
    from topomark.reference.replay.replay import replay

    w = make_world(COMPLETE_HOLE)
    bare = World(w.rotation, (), w.start)
    trace = explore(bare, "basic", lighthouse="three-undirected-vertex").trace
    assert replay(bare, iter(copy.deepcopy(trace))).ok
    k = next(k for k, r in enumerate(trace) if r["event"] == "move" and r["purpose"] == "travel")
    bad = copy.deepcopy(trace)
    bad[k]["purpose"] = "probe"
    result = replay(bare, iter(bad))
    assert not result.ok and "probe moves only after the new edge" in result.divergence.expected
    late = copy.deepcopy(trace)
    late[k]["purpose"] = "establish"
    assert "establish moves only before the first iteration" in replay(bare, iter(late)).divergence.expected
