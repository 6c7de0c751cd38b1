"""§6.2.1's footprint-search algorithms with about m undirected markers (reference/explorers/edge_footprints.py,
reference/explorers/closest_first.py, registrations/markers_621.py): Case 1a, Case 1b, Case 2 (Algorithm 6.1) and
the two closest-first extensions of Case 4 (Algorithm 6.3; the extension of Case 2).  Every run is checked (pose,
I-1, I-2 and the marker budget after every step, extended isomorphism with every dropped marker at the end); each
test adds what it proves.  The decisions are shown on the smallest worlds that show them."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest
from hypothesis import given, settings

from families import family_worlds
from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers.policies import Policies
from topomark.reference.algorithms.registrations import markers_621
from topomark.reference.algorithms.registry import REGISTRY
from topomark.spec.kit import Kit

from conftest import SMALL_WORLDS, bare, make_world

ALGORITHMS = ("case-1a", "case-1b", "case-2", "case-4", "case-4-mn")
LATTICE_HOLE, RANDOM, SMALL_WORLD = ("lattice-hole:rows=4,cols=5,seed=1", "random:n=9,fraction=0.4,seed=2",
                                     "small-world:n=12,k=4,p=0.2,seed=3")


def used(out) -> int:
    """Markers lying in the world at the end, as the final map shows them (else the isomorphism fails)."""
    return sum(m.count for m in out.explorer.S.to_world().markers)


def exact_use(name: str, n: int, m: int) -> int | None:
    """What the thesis says each run uses exactly (None: the closest-first ones, at most their bound)."""
    return {"case-1a": m, "case-1b": m + 1, "case-2": m + n - 1}.get(name)


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_each_algorithm_maps_each_world_within_its_marker_and_cost_bounds(name, text):
    w = bare(make_world(text))
    out = explore(w, name)
    spec = REGISTRY[name]
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    assert out.checks > 3 * w.m  # pose/I-1/I-2 and the budget after every iteration
    assert used(out) == out.explorer.dropped <= spec.marker_bound_fn(w.n, w.m)
    assert used(out) == (exact_use(name, w.n, w.m) or used(out))
    assert (out.nonloop_iterations, out.loop_iterations) == (w.n - 1, w.m - w.n + 1)
    assert out.by_purpose["new"] == w.m and out.by_purpose["retrace"] == w.m - w.n + 1  # back to v_k first
    assert w.m <= out.cost <= spec.bound_for(w.n, w.m)


@settings(max_examples=20, deadline=None)
@given(family_worlds(small=True))
def test_every_family_world_is_mapped_within_each_marker_bound(w):
    for name in ALGORITHMS:
        out = explore(w, name, record=False)
        assert out.outcome == "correct", (name, out.violation, out.reason)
        assert used(out) <= REGISTRY[name].marker_bound_fn(w.n, w.m)


@pytest.mark.parametrize("name", ALGORITHMS)
def test_one_marker_fewer_than_a_run_drops_is_the_failed_outcome(name):
    w = make_world(LATTICE_HOLE)
    full = used(explore(w, name))
    short = full - 1 if name != "case-1b" else full - 2  # case-1b: m (one fewer) still maps it (§6.2.1 Case 1b)
    out = explore(w, name, options={"markers": short})
    assert (out.outcome, out.claimed, out.verified) == ("failed", "failed", False)
    assert "out of markers" in out.reason


def test_case_4_needs_m_minus_floor_of_n_minus_1_over_2_on_the_4_cycle():
    """§6.2.1 Case 4 counts m − (n − 1) loop markers and ⌈(n−1)/2⌉ non-loop ones, then says m − ⌊n/2⌋.
    The 4-cycle from v0: (v0, v1) marked (v0 unmarked), (v1, v2) blank (v1 marked), (v2, v3) marked, the loop
    edge (v3, v0) marked — 3 = m − ⌊(n−1)/2⌋; with the thesis's m − ⌊n/2⌋ = 2 the robot runs out."""
    c4 = g.cycle(4)
    out = explore(c4, "case-4")
    assert out.outcome == "correct" and used(out) == 3 == markers_621.case_4_markers(4, 4)
    assert [it.dropped for it in out.explorer.iterations] == [1, 0, 1, 1]
    short = explore(c4, "case-4", options={"markers": 4 - 4 // 2})
    assert short.outcome == "failed" and "out of markers" in short.reason
    chain = explore(g.chain(2), "case-4")  # n = 2: one marker, where m − ⌊n/2⌋ = 0
    assert chain.outcome == "correct" and used(chain) == 1 == markers_621.case_4_markers(2, 1)
    c5 = explore(g.cycle(5), "case-4")  # odd n: both counts agree, and are reached
    assert used(c5) == 5 - 5 // 2 == markers_621.case_4_markers(5, 5)


def test_the_extension_of_case_2_needs_m_plus_1_for_even_n():
    """§6.2.1 Case 4 says m suffice; the 4-cycle takes 2 + 2 on (v0, v1), (v2, v3) and 1 on the loop edge: 5 = m + 1."""
    out = explore(g.cycle(4), "case-4-mn")
    assert out.outcome == "correct" and used(out) == 5 == markers_621.case_4_mn_markers(4, 4)
    assert explore(g.cycle(4), "case-4-mn", options={"markers": 4}).outcome == "failed"
    assert used(explore(g.cycle(5), "case-4-mn")) == 5 == markers_621.case_4_mn_markers(5, 5)  # odd n: m


@pytest.mark.parametrize("name", ["case-4", "case-4-mn"])
def test_closest_first_ignores_the_edge_policy_and_marks_every_vertex_it_may_reenter(name):
    """Rule (1) is the algorithm: fifo or lifo changes nothing.  Every vertex of degree ≥ 2 ends with a marked
    edge (§6.2.1 Case 4: the next edge from an unmarked new vertex is explored at once, and marked)."""
    w = make_world(SMALL_WORLD)
    runs = [explore(w, name, policies=Policies(edge=p)) for p in ("nearest", "fifo", "lifo")]
    assert len({(r.cost, used(r)) for r in runs}) == 1
    S = runs[0].explorer.S
    assert all(S.dart_marks(v) for v in S.vertices if S.degree(v) >= 2)
    assert any(it.dropped == 0 for it in runs[0].explorer.iterations)  # some non-loop edges are left blank


def test_case_2s_candidates_are_case_1as_narrowed_by_c1_and_c2():
    """Same edges in the same order (the search ends where it started the same way); Algorithm 6.1's filter
    (c_1 single-, c_2 double-marked) keeps a subset of Case 1a's candidates (c marked), §6.2.1 Case 2."""
    fewer = 0
    for text in SMALL_WORLDS:
        one, two = (explore(bare(make_world(text)), a).explorer.iterations for a in ("case-1a", "case-2"))
        assert [it.joined for it in one] == [it.joined for it in two]
        assert all(set(b.candidates) <= set(a.candidates) for a, b in zip(one, two))
        fewer += sum(len(a.candidates) - len(b.candidates) for a, b in zip(one, two))
    assert fewer > 0  # the small-world one alone: 41 candidates against 36


def test_the_search_visits_the_candidates_until_the_unexpectedly_marked_edge():
    """Figure 6.4(c, d): on K4 minus nothing, the last loop edges have candidates; v_k' is among them."""
    out = explore(g.complete(4), "case-1a")
    loops = [it for it in out.explorer.iterations if it.kind == "loop"]
    assert loops and all(it.found in it.candidates and it.joined[1][0] == it.found for it in loops)
    assert out.by_purpose.get("validation", 0) > 0


def test_case_1b_with_m_markers_finishes_the_last_iteration_without_a_search():
    """§6.2.1 Case 1b: one marker per iteration, so the robot runs out in the last one.  K4 (last iteration a loop
    edge): one E-marker short, e/e' is the one edge left in U.  A chain (last a new leaf): one V-marker short."""
    spec = REGISTRY["case-1b"]
    full = explore(g.complete(4), spec)
    assert full.outcome == "correct" and used(full) == 7
    k4 = explore(g.complete(4), replace(spec, kit_fn=lambda n, m, o: Kit(vertex=n, edge=m - n)))
    assert k4.outcome == "correct" and used(k4) == 6 and k4.cost < full.cost
    assert k4.explorer.iterations[-1].kind == "loop" and k4.explorer.iterations[-1].candidates == []
    chain = explore(g.chain(3), replace(spec, kit_fn=lambda n, m, o: Kit(vertex=n - 1)))
    assert chain.outcome == "correct" and used(chain) == 2
    assert explore(g.cycle(4), "case-1b", options={"markers": 3}).outcome == "failed"  # short earlier: failed


@pytest.mark.parametrize("text", [LATTICE_HOLE, RANDOM, "complete-hole:n=5,seed=1"])
def test_case_1b_draws_its_markers_from_one_pool(text):
    """§6.2.1 Case 1b, footnote 16: m + 1 homogeneous markers, each dropped at a vertex or on an edge as needed, so the
    default kit is one pool of m + 1 — spent as n at the vertices and m − n + 1 on the loop edges; with m (the
    extension, §6.2.1 Case 1b) the map is still correct; with m − 1 the robot runs out before the last iteration."""
    w = make_world(text)
    assert REGISTRY["case-1b"].kit_for(w.n, w.m, {"markers": None}) == Kit(either=w.m + 1)
    full = explore(w, "case-1b")
    assert (full.outcome, full.verified) == ("correct", True) and used(full) == w.m + 1
    marks = full.explorer.S.to_world().markers
    assert sum(m.count for m in marks if hasattr(m, "at")) == w.n  # a V-marker at every vertex
    assert sum(m.count for m in marks if hasattr(m, "between")) == w.m - w.n + 1  # an E-marker on every loop edge
    extended = explore(w, "case-1b", options={"markers": w.m})
    assert (extended.outcome, extended.verified, extended.violation) == ("correct", True, None)
    assert used(extended) == w.m and extended.cost <= full.cost
    short = explore(w, "case-1b", options={"markers": w.m - 1})
    assert (short.outcome, short.claimed) == ("failed", "failed") and "out of markers" in short.reason


@pytest.mark.parametrize("name", ALGORITHMS)
def test_the_cli_explores_with_each_and_reports_running_out(name, capsys):
    assert main(["explore", "lattice-hole:rows=4,cols=4,seed=2", "--algorithm", name, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["outcome"], data["verified"], data["lighthouse"]) == ("correct", True, None)
    assert main(["explore", "cycle:n=4", "--algorithm", name, "--markers", "1", "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["outcome"] == "failed"


def test_a_marker_count_below_one_is_bad_input(capsys):
    for bad in ("0", "-3", "two"):
        assert main(["explore", "cycle:n=4", "--algorithm", "case-1a", "--markers", bad]) == 2
        assert "--markers must be an integer >= 1" in capsys.readouterr().err
