"""§6.2.1 Case 5 (Version-1, Algorithm 6.4; Version-2, Algorithm 6.5) and Case 0 (the plausible strategy that
fails, Figure 6.3): reference/explorers/case5_*.py, case0_every_vertex.py, registrations/markers_case5.py.

Every run is under the checker (pose, I-1, I-2 and the marker budget after every step, extended isomorphism with
every dropped marker at the end)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from topomark.proofs.enumerate import embedded_worlds
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers.case5_v1 import VertexCountsThenLighthouse
from topomark.reference.explorers.case5_v2 import E0, VertexEdgeThenLighthouse
from topomark.reference.explorers.counted_markers import sum_to
from topomark.reference.explorers.policies import Policies
from topomark.reference.algorithms.registry import REGISTRY, variant
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.world import Start, World
from topomark.spec.worldfile import world_from_json

from conftest import make_world

VECTORS = Path(__file__).parent / "vectors" / "case0"
LATTICE_HOLE, RANDOM = "lattice-hole:rows=4,cols=4,seed=1", "random:n=9,fraction=0.3,seed=2"
SHORT = (LATTICE_HOLE, RANDOM, "small-world:n=10,k=4,p=0.2,seed=3", "complete-hole:n=6,seed=1")
"""Worlds large enough that each K below runs out in phase I (12 can last a 5- or 7-vertex world to the end)."""


def in_world(out) -> int:
    """Markers lying in the world at the end (the map shows the same, or the isomorphism check fails)."""
    return sum(m.count for m in out.explorer.S.to_world().markers)


@pytest.mark.parametrize("name", ["case-5-v1", "case-5-v2"])
@pytest.mark.parametrize("text", SHORT)
@pytest.mark.parametrize("k", [4, 7, 12, None])
def test_both_versions_map_each_world_with_any_k_never_using_more_than_k(name, text, k):
    w = make_world(text)
    out = explore(w, name, options={"markers": k})
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    assert out.checks > 3 * w.m
    assert in_world(out) <= REGISTRY[name].marker_bound_fn(w.n, w.m)
    if k is not None:
        assert in_world(out) <= k  # Version-2's pool of K, kept by the robot, is never overspent
        assert out.explorer.phase_two_from is not None  # K < n here: phase I ran out, phase II finished the map
        assert out.hypotheses_confirmed >= 1


def test_version_1_with_every_place_marked_is_case_3a():
    """§6.2.1 Case 5: "when the robot has sufficient markers to mark each visited vertex, the algorithm behaves as the
    Σ k V-marker algorithm" — same moves, same cost, no hypothesis."""
    w = make_world(LATTICE_HOLE)
    out = explore(w, "case-5-v1")
    assert out.outcome == "correct" and in_world(out) == sum_to(w.n) and out.hypotheses == 0
    assert out.explorer.phase_two_from is None
    assert out.cost == explore(w, "case-3a", options={"markers": sum_to(w.n)}).cost


def test_version_1_phase_1_marks_places_uniquely_then_phase_2_leaves_them_blank():
    w = make_world(LATTICE_HOLE)
    ex = explore(w, "case-5-v1", options={"markers": 12}).explorer
    assert sorted(ex.count_of.values()) == [1, 2, 3, 4]  # 1+2+3+4 = 10 ≤ 12 < 15
    assert ex.phase == 2 and len(ex.count_of) < ex.M.n
    assert [h.outcome for it in ex.iterations for h in it.hypotheses if h.outcome == "case 3"]


def test_version_2_with_every_place_and_loop_edge_marked_needs_no_hypothesis():
    """§6.2.1 Case 5: with enough markers Version-2 behaves like the m V-E-marker algorithm (m + 4 at most)."""
    w = make_world(RANDOM)
    out = explore(w, "case-5-v2")
    assert out.outcome == "correct" and out.hypotheses == 0 and in_world(out) <= w.m + 4
    assert out.explorer.phase_two_from is None


TRIANGLE = World({"a": ("b", "c"), "b": ("a", "c"), "c": ("a", "b")}, (), Start("a", "b"))


class LiteralCounter(VertexCountsThenLighthouse):
    """Algorithm 6.4 as printed: one marker at v0 (line 1), i ← 1 (line 3), i markers at the next place."""

    def next_count(self) -> int:
        return len(self.count_of)


def test_algorithm_6_4_counter_as_printed_gives_two_places_one_marker_and_fails_on_the_triangle():
    """Algorithm 6.4's counter (lines 1, 3, 13, 15; lines 1–15): the smallest world with a loop edge shows the
    printed counter's shared label."""
    literal = explore(TRIANGLE, variant("literal-6.4", LiteralCounter, "case-5-v1"))
    assert literal.outcome == "failed" and "1 marker(s) mark 2 places of the map" in literal.reason
    ours = explore(TRIANGLE, "case-5-v1", options={"markers": 4})
    assert ours.outcome == "correct" and ours.explorer.count_of == {0: 1, 1: 2}


class LiteralLine23(VertexEdgeThenLighthouse):
    """Algorithm 6.5 line 23 as printed: a hypothesis is confirmed when P and P^E "do not match" — line 21 has
    rejected those already, so none ever is."""

    def confirms(self, h) -> bool:
        return False


# the paw: a triangle (x, y, z) with a pendant edge (p, z), the robot at p
PAW = World({"p": ("z",), "x": ("y", "z"), "y": ("x", "z"), "z": ("p", "x", "y")}, (), Start("p", "z"))


def test_algorithm_6_5_line_23_as_printed_confirms_nothing_and_maps_the_paw_wrongly():
    """Algorithm 6.5 line 23: with K = 4 (line 1 spends them all) phase II must close the triangle by a
    hypothesis."""
    literal = explore(PAW, variant("literal-6.5", LiteralLine23, "case-5-v2"), options={"markers": 4})
    assert literal.outcome == "wrong-map" and "two map vertices for one place" in literal.violation.detail
    ours = explore(PAW, "case-5-v2", options={"markers": 4})
    assert ours.outcome == "correct" and ours.hypotheses_confirmed == 1 and in_world(ours) == 4


class E0Last(Policies):
    """The nearest edge, but e0 (v0's exit 0) only when nothing else but e0's other dart is left: with the three
    edge policies of topomark the far end of e0 always takes e0 first (searched: no world of ≤ 5 places)."""

    def choose_edge(self, S, dist):
        U = S.unexplored
        e0_far = {(v, dm.exit) for v in S.vertices if v for dm in S.dart_marks(v) if dm.count == 2}
        rest = [k for k, d in enumerate(U) if d != E0 and d not in e0_far]
        k = min(rest, key=lambda x: (dist[U[x][0]], x)) if rest else U.index(E0) if E0 in U else 0
        return U.pop(k)


def test_version_2_crosses_e0_to_a_known_place_without_a_third_marker():
    """The e0 decision: following the double-marked edge from v0 to its known far end joins it at once, with
    no drop and no search (a third marker on e0 would break the search's "one more marked edge")."""
    seen = 0
    for w in embedded_worlds(4, 3, min_vertices=3):
        for v in w.vertices:
            out = explore(World(w.rotation, (), Start(v, w.rotation[v][0])), "case-5-v2", E0Last())
            assert out.outcome == "correct"
            crossed = [it for it in out.explorer.iterations if it.edge == E0 and it.kind == "loop"]
            seen += len(crossed)
            assert all(it.dropped == 0 and it.signature.vertex_count == 1 for it in crossed)
            assert max(m.count for m in out.explorer.S.to_world().markers) == 2
    assert seen > 0


def test_markers_below_four_or_given_to_case_0_is_bad_input(capsys):
    assert main(["explore", "cycle:n=4", "--algorithm", "case-5-v2", "--markers", "3"]) == 2
    assert "--markers must be an integer >= 4" in capsys.readouterr().err
    assert main(["explore", "cycle:n=4", "--algorithm", "case-0", "--markers", "5"]) == 2


@pytest.mark.parametrize("name", ["case-5-v1", "case-5-v2"])
def test_cli_explore_json_outcome_correct(name, capsys):
    assert main(["explore", "lattice-hole:rows=3,cols=4,seed=2", "--algorithm", name, "--markers", "5",
                 "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["outcome"] == "correct" and report["algorithm"] == name


# -- Case 0 (Figure 6.3) -------------------------------------------------------------------------------

def vector(name: str) -> World:
    return world_from_json(json.loads((VECTORS / f"{name}.json").read_text()))


def perceptions(w: World) -> list:
    """What the robot did and sensed, in order: every motion with its perception, every drop with what it sensed."""
    trace = explore(w, "case-0", check=False).trace
    return [(r["motion"], r["perception"]) if r["event"] == "move" else ("drop", r["kind"], r["signature"])
            for r in trace if r["event"] in ("move", "op")]


@pytest.mark.parametrize("other", ["k4-other", "five-vertices"])
def test_case_0_certified_pair_same_perceptions_different_worlds_both_failed(other):
    """The certificate: the Case 0 robot senses exactly the same on both worlds up to the marked place several
    edges fit, but the worlds are not extended-isomorphic, so no pick there could be right on both (found by
    search over the embedded worlds of ≤ 5 places and degree ≤ 4, every start).  The robot says so: ``failed``
    on both, for the same reason, never a map the checker refutes."""
    a, b = vector("k4-mapped"), vector(other)
    assert perceptions(a) == perceptions(b)
    assert len(perceptions(a)) >= 7
    assert not find_isomorphism(World(a.rotation), World(b.rotation)).isomorphic
    outs = [explore(a, "case-0"), explore(b, "case-0")]
    assert [(o.outcome, o.claimed, o.violation) for o in outs] == [("failed", "failed", None)] * 2
    assert outs[0].reason == outs[1].reason and "edges fit; the robot cannot determine which, §6.2.1 Case 0" in outs[0].reason


@pytest.mark.parametrize("check", [True, False])
def test_case_0_on_k4_fails_where_the_strategy_cannot_tell_the_candidates_apart(check):
    """Figure 6.3(b), §6.2.1 Case 0: entering a marked place of K4, three unexplored edges at marked places fit it; the
    explorer stops with ``failed`` and says so, checked or not (K4 is the smallest world that shows it)."""
    for w in (vector("k4-mapped"), make_world("complete:n=4")):
        out = explore(w, "case-0", check=check)
        assert (out.outcome, out.claimed, out.violation) == ("failed", "failed", None)
        assert "3 edges fit; the robot cannot determine which, §6.2.1 Case 0" in out.reason
        it = out.explorer.undecided
        assert it is not None and len(it.candidates) == 3 and it.number == len(out.explorer.iterations) + 1


@pytest.mark.parametrize("extra", [[], ["--no-check"], ["--json"]])
def test_case_0_cli_on_k4_is_failed_exit_1_with_the_reason(extra, capsys):
    assert main(["explore", "complete:n=4", "--algorithm", "case-0", *extra]) == 1
    out = capsys.readouterr().out
    if extra == ["--json"]:
        report = json.loads(out)
        assert (report["outcome"], report["claimed"]) == ("failed", "failed")
        assert "3 edges fit; the robot cannot determine which, §6.2.1 Case 0" in report["reason"]
    else:
        assert "outcome: failed" in out and "3 edges fit; the robot cannot determine which, §6.2.1 Case 0" in out


def test_case_0_maps_a_world_where_one_edge_always_fits():
    """A single fitting edge is e' itself (e is new, so e' is unexplored at a known place showing what v_u shows):
    on a cycle the explorer joins it and the checker verifies the map."""
    out = explore(make_world("cycle:n=5"), "case-0")
    assert (out.outcome, out.verified) == ("correct", True)


def test_nearest_agrees_with_a_whole_breadth_first_search():
    """policies.nearest (Case 5's lighthouse paths) stops the search after the nearest wanted vertex's layer:
    the vertex is the least-numbered at the least distance of a whole bfs, and its parents are bfs's."""
    import random
    from topomark.reference.worlds import generators
    from topomark.reference.run.explore import explore
    from topomark.reference.explorers.policies import bfs, nearest
    out = explore(generators.lattice_hole(5, 6, 0.1, "vertices", 2), "basic", record=False)
    S = out.explorer.S
    rng = random.Random(5)
    for _ in range(200):
        root, wanted = rng.randrange(S.n), set(rng.sample(range(S.n), rng.randint(1, 4)))
        dist, _, parent = bfs(S, root)
        light, some = nearest(S, root, wanted)
        assert light == min(wanted, key=lambda x: (dist[x], x))
        assert all(parent[x] == some[x] for x in some) and (light == root or light in some)
    assert nearest(S, 0, ()) == (None, bfs(S, 0)[2])
