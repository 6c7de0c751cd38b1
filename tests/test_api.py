"""The public Python API (``import topomark``): every function on small worlds, the README's lines, the package.

The API wraps what the commands run, so these tests hold it to the same answers: the explored map is the
world (markers aside), a tampered trace is refused, Z3's pair is indistinguishable and not isomorphic, and
bad input is one InvalidInput naming what is wrong.
"""

from __future__ import annotations

import subprocess
import sys
from importlib.metadata import version
from importlib.resources import files

import pytest
from hypothesis import given, settings, strategies as st

import topomark
from topomark.proofs.bisim import indistinguishable
from topomark.reference.algorithms.registry import REGISTRY, listing
from topomark.reference.explorers.policies import Policies
from topomark.spec.errors import InvalidInput
from topomark.spec.isomorphism import verify_witness
from topomark.spec.robot import perceive
from topomark.spec.world import Start


def run_python(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, timeout=120)


def test_the_readme_lines_run_unchanged():
    world = topomark.generate("lattice", rows=3, cols=3)
    run = topomark.explore(world, algorithm="basic")
    assert run.verified and topomark.isomorphic(run.map, world, markers=False)
    pair = topomark.search("none", max_vertices=4, max_degree=3).worlds
    assert topomark.distinguish(*pair) is None


def test_version_is_the_installed_distributions():
    assert topomark.__version__ == version("topomark")
    assert topomark.__version__.count(".") >= 2


def test_import_is_lazy_and_every_public_name_resolves():
    code = ("import sys, topomark; heavy = [m for m in ('z3', 'networkx', 'topomark.reference.run.explore') "
            "if m in sys.modules]; print(heavy)")
    assert run_python("-c", code).stdout.strip() == "[]"
    for name in topomark.__all__:
        assert getattr(topomark, name) is not None
    assert set(topomark.__all__) <= set(dir(topomark))
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        topomark.nope  # noqa: B018


def test_python_dash_m_runs_the_command_line():
    help_ = run_python("-m", "topomark", "--help")
    assert help_.returncode == 0 and help_.stdout.startswith("usage: topomark")
    bad = run_python("-m", "topomark", "explore", "torus")
    assert bad.returncode == 2 and "torus" in bad.stderr and "Traceback" not in bad.stderr


def test_the_package_is_marked_typed():
    assert (files("topomark") / "py.typed").is_file()


def test_worlds_round_trip_through_a_file(tmp_path):
    world = topomark.generate("lattice-hole", rows=4, cols=4, seed=3)
    topomark.save_world(world, tmp_path / "w.json")
    back = topomark.load_world(tmp_path / "w.json")
    assert (back.n, back.m, back.rotation) == (world.n, world.m, world.rotation)
    assert topomark.isomorphic(back, world) is not None
    with pytest.raises(InvalidInput, match="missing.json"):
        topomark.load_world(tmp_path / "missing.json")
    with pytest.raises(InvalidInput, match="unexpected keyword argument 'size'"):
        topomark.generate("lattice", size=3)


def test_explore_returns_the_map_with_the_lighthouse_and_its_verdict():
    world = topomark.generate("wheel-a")
    v0 = next(iter(world.rotation))
    started = world.with_start(Start(v0, world.rotation[v0][0]))
    run = topomark.explore(started)
    assert (run.outcome, run.verified, run.violation) == ("correct", True, None)
    assert run.cost > 0 and run.map.n == world.n and len(run.map.markers) == 1
    assert topomark.isomorphic(run.map, started) is None  # the map carries the marker, the world does not
    verdict = topomark.check_map(started, run.map)
    assert (verdict.isomorphic, verdict.rule) == (True, "lighthouse")
    assert not topomark.check_map(topomark.generate("cycle", n=5), run.map).isomorphic


def test_explore_takes_policies_options_and_a_trace_file(tmp_path):
    lifo = topomark.explore("lattice:rows=3,cols=3", policies={"edge": "lifo"}, record=False)
    same = topomark.explore("lattice:rows=3,cols=3", policies=Policies(edge="lifo"), record=False)
    assert lifo.verified and lifo.cost == same.cost and lifo.trace == []
    stopped = topomark.explore("cycle:n=4", algorithm="model-tree", max_steps=10)
    assert stopped.outcome == "limit" and stopped.map is None
    unchecked = topomark.explore("cycle:n=4", check=False)
    assert (unchecked.outcome, unchecked.verified) == ("unchecked", False) and unchecked.map is not None
    topomark.explore("cycle:n=6", trace=tmp_path / "t.jsonl")
    assert topomark.replay("cycle:n=6", tmp_path / "t.jsonl").ok


@pytest.mark.parametrize("call, message", [
    (lambda: topomark.explore("cycle:n=4", colour="red"), "unexpected keyword argument 'colour'"),
    (lambda: topomark.explore("cycle:n=4", policies={"edge": "random"}), "unknown edge policy 'random'"),
    (lambda: topomark.explore("cycle:n=4", policies={"colour": "red"}), "unknown policy kind 'colour'"),
    (lambda: topomark.explore("cycle:n=4", algorithm="dijkstra"), "unknown algorithm 'dijkstra'"),
    (lambda: topomark.explore(42), "not int"),
    (lambda: topomark.census("none", max_vertices=99, max_degree=3), "max_vertices must be an integer from 2 to 10"),
    (lambda: topomark.census("none", max_vertices=3, max_degree=2, jobs=0), "jobs must be an integer from 1 to 256"),
    (lambda: topomark.search("pebbles", max_vertices=3, max_degree=2), "pebbles"),
    (lambda: topomark.distinguish("wheel-a", "wheel-b"), "has no start"),
])
def test_bad_input_is_one_precise_message(call, message):
    with pytest.raises(InvalidInput, match=message):
        call()


def test_a_stopped_run_has_no_map():
    run = topomark.explore("lattice:rows=3,cols=3", algorithm="case-0")
    assert run.outcome == "failed" and run.map is None and run.reason


def test_isomorphic_returns_a_verified_witness_for_a_relabelled_copy():
    world = topomark.generate("lattice-hole", rows=4, cols=4, seed=1)
    names = {v: f"x{i}" for i, v in enumerate(reversed(list(world.rotation)))}
    copy = type(world)({names[v]: [names[w] for w in ws] for v, ws in world.rotation.items()})
    witness = topomark.isomorphic(world, copy)
    assert witness is not None and verify_witness(world, copy, witness) is None
    assert sorted(witness.vertex_map.values()) == sorted(copy.rotation)
    assert topomark.isomorphic(world, topomark.generate("lattice", rows=4, cols=4)) is None


def test_replay_refuses_a_trace_that_claims_a_different_cost():
    run = topomark.explore("cycle:n=5")
    assert topomark.replay("cycle:n=5", run.trace).ok
    tampered = [dict(r) for r in run.trace]
    tampered[-1]["cost"] += 1
    result = topomark.replay("cycle:n=5", tampered)
    assert not result.ok and result.divergence is not None


def test_distinguish_finds_figure_3_6s_sequence_and_certifies_figure_3_4s_pair():
    a, b = topomark.generate("wheel-a", marker="directional"), topomark.generate("wheel-b", marker="directional")
    found = topomark.distinguish(a, b)
    assert found is not None and found.motions
    pa, pb = perceive(a, a.start_state(), found.motions), perceive(b, b.start_state(), found.motions)
    assert pa[:-1] == pb[:-1] and pa[-1] != pb[-1]
    assert topomark.distinguish("wheel-a:marker=undirected", "wheel-b:marker=undirected") is None


def test_search_and_prove():
    found = topomark.search("none", max_vertices=4, max_degree=3)
    a, b = found.worlds
    assert found.found and indistinguishable(a, b) and topomark.isomorphic(a, b) is None
    report = topomark.prove("directional-vertex", max_vertices=3, max_degree=2)
    assert report.proved and report.outcome == "proved"


def test_census_finds_the_pair_only_where_the_marker_class_is_too_weak(tmp_path):
    weak = topomark.census("none", max_vertices=4, max_degree=3)
    a, b = weak.smallest_counterexample
    assert indistinguishable(a, b) and topomark.isomorphic(a, b) is None
    kept = topomark.census("directional-vertex", max_vertices=4, max_degree=3, shards=tmp_path / "shards")
    assert kept.smallest_counterexample is None and kept.languages > 0
    assert any((tmp_path / "shards").iterdir())


def test_algorithms_lists_the_registry():
    specs = topomark.algorithms()
    assert [s.name for s in specs] == [s.name for s in listing()]
    assert specs[0].name == "basic" and set(REGISTRY) <= {s.name for s in specs}


def test_strategies_are_the_reference_strategies():
    import topomark.strategies as strategies
    from topomark.reference.worlds import strategies as reference

    assert topomark.strategies is strategies and strategies.worlds is reference.worlds

    @settings(max_examples=10, deadline=None)
    @given(strategies.worlds(max_vertices=5), st.randoms(use_true_random=False))
    def copies_are_isomorphic(world, rng):
        assert 2 <= world.n <= 5
        copy = strategies.rotated(strategies.relabelled(world, rng), rng)
        witness = topomark.isomorphic(world, copy)
        assert witness is not None and verify_witness(world, copy, witness) is None

    copies_are_isomorphic()


def test_worst_case_gives_the_exact_maxima_and_the_world_that_reaches_them():
    rows = topomark.worst_case("basic", max_vertices=4, max_degree=3)
    last = rows[-1]
    assert [r["n"] for r in rows] == [2, 3, 4] and last["max_ratio_to_bound"] <= 1
    from topomark.spec.worldfile import world_from_json
    run = topomark.explore(world_from_json(last["argmax"]))
    assert run.verified and run.cost == last["max_cost"]


def test_adversarial_search_is_reproducible_from_python():
    a = topomark.adversarial_search("basic", n=8, max_degree=3, evaluations=20, seed=4).to_json()
    b = topomark.adversarial_search("basic", n=8, max_degree=3, evaluations=20, seed=4).to_json()
    assert a["best"]["cost"] == b["best"]["cost"] > 0 and a["best"]["world"] == b["best"]["world"]
