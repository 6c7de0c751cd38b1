"""§6.2.2's edgeINFO improvement of Case 1b with directional V-E-markers and of Case 2 with directional
E-markers (reference/explorers/edge_info.py, registrations/markers_622.py).  Every run is checked (pose, I-1,
I-2 and the marker budget after every step, extended isomorphism with every dropped — directional — marker at
the end); each test adds what it proves.  The decisions are shown on the smallest worlds that show them."""

from __future__ import annotations

import json

import pytest

from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers import edge_info
from topomark.reference.algorithms.registry import REGISTRY
from topomark.spec.signature import signature_at

from conftest import SMALL_WORLDS, bare, make_world

NAME = "case-1b-edgeinfo"
BASE = {NAME: "case-1b", "case-2-edgeinfo": "case-2", "case-1a-edgeinfo": "case-1a", "case-4-edgeinfo": "case-4",
        "case-4-mn-edgeinfo": "case-4-mn"}  # each improved algorithm and the one it improves
USES = {NAME: lambda n, m: m + 1, "case-2-edgeinfo": lambda n, m: m + n - 1,  # §6.2.1 Cases 1a–2: exactly
        "case-1a-edgeinfo": lambda n, m: m}  # Case 4 (closest-first): as many as case-4 / case-4-mn, ≤ the bound
K6, LATTICE_HOLE = "complete:n=6", "lattice-hole:rows=4,cols=5,seed=1"
COMPLETE_HOLE_6, COMPLETE_HOLE_7 = "complete-hole:n=6,seed=3", "complete-hole:n=7,seed=1"


def used(out) -> int:
    """Markers lying in the world at the end, as the final map shows them (else the isomorphism fails)."""
    return sum(m.count for m in out.explorer.S.to_world().markers)


@pytest.fixture(scope="module")
def all_runs():
    """Each world explored by each improved algorithm and by the one it improves: (world, plain, directed)."""
    out = {}
    for text in SMALL_WORLDS:
        w = bare(make_world(text))
        for name, base in BASE.items():
            out[text, name] = (w, explore(w, base), explore(w, name))
    return out


@pytest.fixture(scope="module")
def runs(all_runs):
    return {text: all_runs[text, NAME] for text in SMALL_WORLDS}


@pytest.mark.parametrize("name", list(BASE))
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_each_run_is_correct_within_its_marker_and_cost_bounds_and_never_costs_more_than_its_base(all_runs, text,
                                                                                                 name):
    w, plain, directed = all_runs[text, name]
    spec = REGISTRY[name]
    assert (directed.outcome, directed.verified, directed.violation) == ("correct", True, None)
    assert used(directed) == directed.explorer.dropped == used(plain) <= spec.marker_bound_fn(w.n, w.m)
    assert name not in USES or used(directed) == USES[name](w.n, w.m)
    assert all(m.directional for m in directed.explorer.S.to_world().markers)  # every marker directional
    assert w.m <= directed.cost <= plain.cost <= spec.bound_for(w.n, w.m)
    # the same edges in the same order: only the search differs, and its candidates are a subset of the base's
    one, two = plain.explorer.iterations, directed.explorer.iterations
    assert [it.joined for it in one] == [it.joined for it in two]
    assert all(set(b.candidates) <= set(a.candidates) for a, b in zip(one, two))
    assert all(it.found in it.candidates for it in two if it.kind == "loop" and it.candidates)


def test_edgeinfo_is_strictly_cheaper_on_complete_hole_worlds(all_runs):
    """complete-hole n=6 seed 3 (42 → 41 for all five, the smallest generated world where the cost drops); for
    case-1b also n=7 seed 1 (62 → 61), for case-4 also n=7 seed 1 (67 → 66) and, closest-first, lattice-hole 4x5
    seed 1 (82 → 72 for case-4 and case-4-mn)."""
    costs = {key: (plain.cost, directed.cost) for key, (_, plain, directed) in all_runs.items()}
    for name in BASE:
        assert costs[COMPLETE_HOLE_6, name][1] < costs[COMPLETE_HOLE_6, name][0]
    for text, name in ((COMPLETE_HOLE_7, NAME), (COMPLETE_HOLE_7, "case-4-edgeinfo"),
                       (LATTICE_HOLE, "case-4-edgeinfo"), (LATTICE_HOLE, "case-4-mn-edgeinfo")):
        assert costs[text, name][1] < costs[text, name][0], (text, name)


@pytest.mark.parametrize("name, counts", [("case-2-edgeinfo", (2, 2, 1)), ("case-1a-edgeinfo", (1, 1, 1)),
                                          ("case-4-edgeinfo", (1, 0, 1)), ("case-4-mn-edgeinfo", (2, 0, 1))])
def test_every_e_marker_head_points_at_v_u_on_the_triangle(name, counts):
    """The E-only variants (§6.2.2 "in a similar manner"): the markers on a non-loop edge and the one on the loop
    edge all have their head at v_u — the new vertex, or v_k' found by the search (H there, T at the other end).
    The triangle: v0 → v1 → v2 (non-loop), the loop edge v2 → v0.  Closest-first leaves (v1, v2) blank (rule 3,
    §6.2.1 Case 4: v1 already has a marked edge), and a blank edge stays blank at both ends."""
    out = explore(g.cycle(3), name)
    assert out.outcome == "correct" and out.verified and used(out) == sum(counts)
    S = out.explorer.S
    assert [it.kind for it in out.explorer.iterations] == ["non-loop", "non-loop", "loop"]
    for it, count in zip(out.explorer.iterations, counts):
        (vk, i), (u, j) = it.joined
        here = {dm.exit: (dm.count, dm.end) for dm in S.dart_marks(u)}.get(j)
        there = {dm.exit: (dm.count, dm.end) for dm in S.dart_marks(vk)}.get(i)
        assert (here, there) == (((count, "H"), (count, "T")) if count else (None, None))


def test_direction_convention_on_the_triangle():
    """§6.2.2 leaves the exit and the end open.  Decided: each V-marker points at the edge the robot entered by
    when it dropped it (v0: the faced exit, map exit 0; a new vertex: map exit 0 = e), the loop marker's head
    at v_u = v_k' (H there, T at v_k).  The triangle: v0 → v1 → v2, the loop edge back to v0 (found at v0)."""
    out = explore(g.cycle(3), NAME)
    assert out.outcome == "correct" and out.verified
    S = out.explorer.S
    assert [S.vertex_mark(v).head for v in S.vertices] == [0, 0, 0]
    (loop,) = [it for it in out.explorer.iterations if it.kind == "loop"]
    (vk, i), (found, j) = loop.joined
    assert found == 0 and [dm.end for dm in S.dart_marks(found)] == ["H"] and S.dart_marks(found)[0].exit == j
    assert [dm.end for dm in S.dart_marks(vk)] == ["T"] and S.dart_marks(vk)[0].exit == i
    # what the robot sensed at v_u on arrival is what S says it senses at v_k' entered by e', less e's marker
    assert str(loop.signature) == "[2,V-1,A]" and signature_at(S, found, j).vertex_direction == 1


def test_a_unique_candidate_is_still_visited():
    """§6.2.2 spares only the vertices that fail the conditions; the triangle's one candidate, v0, is visited
    anyway (back to v2 over e, then v2 → v1 → v0: the footprint on e is seen there)."""
    out = explore(g.cycle(3), NAME)
    (loop,) = [it for it in out.explorer.iterations if it.kind == "loop"]
    assert loop.candidates == [0] and loop.found == 0
    assert (out.by_purpose["retrace"], out.by_purpose["validation"]) == (1, 2)


def test_edgeinfo_excludes_a_candidate_case_1b_visits_on_k6(runs):
    """K6, iteration 13: case-1b's candidates are v3 and v4 (degree 5, c = 2); the robot senses
    [5,V-1,E-3-T,E-4-H] and only v3 reads that from an unexplored entry (§6.2.2's conditions 1 and 2, enriched)."""
    w, plain, directed = runs[K6]
    a, b = plain.explorer.iterations[12], directed.explorer.iterations[12]
    assert (a.candidates, b.candidates, str(b.signature)) == ([3, 4], [3], "[5,V-1,E-3-T,E-4-H]")
    assert b.found == 3
    M = directed.explorer.S
    # v4 passes Case 1b's test (two single-marked edges), but no entry of it reads what was sensed
    assert edge_info.matching_darts(M, 4, b.signature) == []


def test_the_cli_runs_it_and_refuses_zero_markers(capsys):
    assert main(["explore", "complete-hole:n=6,seed=3", "--algorithm", NAME, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["outcome"], data["verified"], data["cost"]) == ("correct", True, 41)
    assert main(["explore", "cycle:n=4", "--algorithm", NAME, "--markers", "0"]) == 2
    assert "--markers must be an integer >= 1" in capsys.readouterr().err
    assert main(["explore", "cycle:n=4", "--algorithm", NAME, "--markers", "1", "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["outcome"] == "failed"
    for name in BASE:
        assert main(["explore", "cycle:n=4", "--algorithm", name, "--markers", "0"]) == 2, name
        assert "--markers must be an integer >= 1" in capsys.readouterr().err


@pytest.mark.parametrize("name, short", [("case-1a-edgeinfo", 3), ("case-4-edgeinfo", 2), ("case-4-mn-edgeinfo", 4)])
def test_the_e_only_variants_need_their_originals_markers_on_the_4_cycle(capsys, name, short):
    """The kit and the count are the originals' (m; m − ⌊(n−1)/2⌋ = 3, not the stated m − ⌊n/2⌋ = 2, §6.2.1 Case 4;
    m + [n even] = 5, §6.2.1 Case 4): one marker fewer runs out, the ``failed`` outcome (exit 1)."""
    assert main(["explore", "cycle:n=4", "--algorithm", name, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["outcome"] == "correct"
    assert main(["explore", "cycle:n=4", "--algorithm", name, "--markers", str(short), "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["outcome"] == "failed"


def test_they_are_listed_after_the_621_algorithms():
    names = list(REGISTRY)
    for name in BASE:
        assert names.index(name) > max(names.index(n) for n in ("case-1b", "case-2", "case-4-mn", "case-5-v2"))
