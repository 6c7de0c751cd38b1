"""Algorithm 3.1 (thesis §3.3–3.5): properties of the reference explorer on every family."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from families import family_worlds
from topomark.reference.worlds import generators as g
from topomark.reference.algorithms.bounds import expression_3_1, expression_3_2, upper_bound
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.explorers.policies import EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES, Policies
from topomark.spec.errors import InvalidInput
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.robot import perceive
from topomark.spec.signature import Signature
from topomark.spec.world import Start, World

policies = st.builds(Policies, st.sampled_from(EDGE_POLICIES), st.sampled_from(HYPOTHESIS_POLICIES),
                     st.sampled_from(PATH_POLICIES))


@settings(max_examples=150, deadline=None)
@given(family_worlds(), policies)
def test_map_is_isomorphic_and_cost_within_bounds(world, pol):
    out = explore(world, policies=pol, check_mode="both")
    assert out.violation is None, out.violation
    assert out.verified
    S = out.explorer.S.to_world()
    with_marker = World(world.rotation, [VertexMarker(world.start.at, 1, world.start.facing)])
    assert find_isomorphism(S, with_marker).isomorphic
    assert out.nonloop_iterations == world.n - 1 and out.loop_iterations == world.m - world.n + 1
    assert world.m <= out.cost <= upper_bound(world.n, world.m)
    assert sum(out.by_purpose.values()) == out.cost


@settings(max_examples=40, deadline=None)
@given(family_worlds(small=True), policies)
def test_run_is_deterministic(world, pol):
    a = dump_trace(explore(world, policies=pol).trace)
    b = dump_trace(explore(world, policies=pol).trace)
    assert a == b


@settings(max_examples=40, deadline=None)
@given(family_worlds(small=True))
def test_trace_replays_on_the_world(world):
    """The trace's motions, replayed by the spec's robot from the start, give its perceptions."""
    trace = explore(world).trace
    moves = [r for r in trace if r["event"] == "move"]
    assert [r["step"] for r in moves] == list(range(1, len(moves) + 1))
    marked = World(world.rotation, [VertexMarker(world.start.at, 1, world.start.facing)], world.start)
    got = perceive(marked, marked.start_state(), [r["motion"] for r in moves])
    assert [str(s) for s in got] == [r["perception"] for r in moves]
    assert trace[-1] == {"event": "end", "cost": len(moves), "verified": True, "violation": None}


@pytest.mark.parametrize("n", [3, 4, 7, 12, 30])
def test_cycle_costs_exactly_m(n):
    """§3.5.1: on a cycle every new place is disambiguated at once; cost = m."""
    world = g.cycle(n)
    for v in world.vertices[:3]:
        for facing in world.rotation[v]:
            assert explore(world.with_start(Start(v, facing))).cost == world.m


@pytest.mark.parametrize("n", [2, 3, 6, 11])
def test_chain_from_an_end_costs_m(n):
    world = g.chain(n)
    end = world.vertices[0]
    assert explore(world.with_start(Start(end, world.rotation[end][0]))).cost == world.m


@pytest.mark.parametrize("n", [3, 6, 11])
def test_chain_from_inside_costs_m_plus_d(n):
    """Footnote 10: m + d, d the distance to the end explored first (the one faced, by default)."""
    world = g.chain(n)
    names = world.vertices
    for k in range(1, n - 1):
        ahead, behind = names[k + 1], names[k - 1]
        assert explore(world.with_start(Start(names[k], ahead))).cost == world.m + (n - 1 - k)
        assert explore(world.with_start(Start(names[k], behind))).cost == world.m + k


def test_bound_expressions_match_their_sums():
    """(3.1) and (3.2) evaluated term by term for a small case, by hand: n = 3, m = 3."""
    assert expression_3_1(3, 3) == (1 + 0) + (2 + 2 * 1 * (6 - 2))
    assert expression_3_2(3, 3) == 3 + 2 * 2 * (6 - 4)
    assert upper_bound(3, 3) == 22


def test_default_world_is_explored_and_verified():
    out = explore(g.DEFAULT_WORLD())
    assert out.verified and out.n == 23 and out.m == out.iterations


def test_start_defaults_to_first_vertex_facing_first_exit():
    world = g.lattice(2, 3)
    trace = explore(world).trace
    explicit = explore(world.with_start(Start(world.vertices[0], world.rotation[world.vertices[0]][0]))).trace
    assert dump_trace(trace) == dump_trace(explicit)


def test_agreeing_marker_in_file_is_accepted():
    world = World(g.cycle(5).rotation, [VertexMarker("0", 1, "1")], Start("0", "1"))
    assert explore(world).verified


@pytest.mark.parametrize("marker, words", [
    (VertexMarker("0", 1, "4"), "points to '4', but the robot starts facing '1'"),
    (VertexMarker("0"), "cannot use the marker"),
    (VertexMarker("2", 1, "3"), "cannot use the marker"),
    (EdgeMarker(("0", "1")), "cannot use the marker"),
])
def test_other_markers_are_refused(marker, words):
    world = World(g.cycle(5).rotation, [marker], Start("0", "1"))
    with pytest.raises(InvalidInput, match=words.replace("(", r"\(")):
        explore(world)


def test_unknown_policy_and_algorithm_are_refused():
    with pytest.raises(InvalidInput, match="unknown edge policy 'middle'"):
        Policies(edge="middle")
    with pytest.raises(InvalidInput, match="unknown algorithm"):
        explore(g.cycle(3), algorithm="enh9")


def test_trace_example_in_spec_is_what_explore_writes():
    doc = (Path(__file__).resolve().parents[1] / "spec" / "trace.md").read_text()
    example = doc.split("```\n")[-2]
    world = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, start=Start("a", "b"))
    assert dump_trace(explore(world).trace) == example


def test_hypotheses_are_tested_and_counted():
    out = explore(g.lattice(4, 4))
    tested = out.hypotheses_rejected + out.hypotheses_confirmed
    assert 0 < tested <= out.hypotheses
    assert out.hypotheses_confirmed <= out.loop_iterations
    for it in out.explorer.iterations:
        outcomes = [h.outcome for h in it.hypotheses]
        if it.kind == "loop" and not it.by_marker:
            assert outcomes.count("case 3") == 1
            k = outcomes.index("case 3")
            assert all(o in ("case 1", "case 2") for o in outcomes[:k])
            assert all(o == "untested" for o in outcomes[k + 1:])
        else:
            assert all(o in ("case 1", "case 2") for o in outcomes)


def test_expected_perceptions_end_at_the_lighthouse():
    out = explore(g.lattice(3, 4))
    for it in out.explorer.iterations:
        for h in it.hypotheses:
            assert len(h.motions) == len(h.expected) >= 1
            assert h.expected[-1].vertex_direction is not None
            assert all(not s.marked for s in h.expected[:-1])
            assert isinstance(h.expected[0], Signature)
