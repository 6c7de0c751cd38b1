"""Table 2.3's classic baselines (reference/explorers/footprints.py, reference/explorers/labelled_graph.py,
registrations/baselines.py): the footprints model with m + n homogeneous markers (§2.3.1) and the labelled graph
explored depth first (§2.3.1).  Every run is checked (pose, I-1, I-2, the bound function and the marker budget after
every step; iterations, cost bound and extended isomorphism, markers included, at the end); each test adds what it
proves.  The decisions are shown on the smallest worlds that show them."""

from __future__ import annotations

import json
import math
from dataclasses import replace

import pytest

from topomark.reference.algorithms.registry import REGISTRY
from topomark.reference.cli.main import main
from topomark.reference.explorers.labelled_graph import LabelledGraphDFS
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators as g
from topomark.reference.worlds.deterministic import from_positions
from topomark.spec.kit import Kit, MarkerOp

from conftest import SMALL_WORLDS, bare, make_world

BASELINES = ("footprints", "labelled-dfs")


def used(out) -> int:
    """Markers lying in the world at the end, as the final map shows them (else the isomorphism fails)."""
    return sum(m.count for m in out.explorer.S.to_world().markers)


@pytest.mark.parametrize("name", BASELINES)
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_each_baseline_maps_each_world_within_its_bounds_and_drops_its_whole_kit(name, text):
    """Lattice-hole, random, complete(-hole), small-world worlds and the Figure 3.4 wheels."""
    w = bare(make_world(text))
    out = explore(w, name)
    spec = REGISTRY[name]
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    assert "cost-bound" in spec.checks and out.checks > 3 * w.m
    assert (out.nonloop_iterations, out.loop_iterations) == (w.n - 1, w.m - w.n + 1)
    assert w.m <= out.cost <= spec.bound_for(w.n, w.m)
    assert used(out) == out.explorer.dropped == spec.marker_bound_fn(w.n, w.m)
    assert spec.kit_for(w.n, w.m, {}) == (Kit(either=w.m + w.n) if name == "footprints"
                                         else Kit(vertex=w.n * (w.n + 1) // 2, directional=True))


def test_footprints_leave_one_marker_on_every_vertex_and_every_edge():
    """§2.3.1: "one for each node or edge", m + n in all, from one homogeneous pool."""
    w = make_world("complete-hole:n=6,seed=1")
    S = explore(w, "footprints").explorer.S
    assert all(S.to_world().markers) and len(S.to_world().markers) == w.n + w.m
    assert {m.count for m in S.to_world().markers} == {1}
    assert sum(1 for m in S.to_world().markers if hasattr(m, "at")) == w.n


def test_footprints_search_every_known_vertex_of_v_us_degree_not_only_those_case_1a_would():
    """§2.3.1: "each (other) known vertex in S which has the same degree as v_u" — the marks v_u shows and an
    unexplored edge narrow Case 1a's candidates (Algorithm 6.1 lines 11–12), not the footprints model's.  Same
    edges in the same order, a superset of candidates at every loop step, and at least as many validation moves."""
    wider = 0
    for text in SMALL_WORLDS[:12]:
        w = bare(make_world(text))
        fp, one = explore(w, "footprints"), explore(w, "case-1a")
        assert [it.joined for it in fp.explorer.iterations] == [it.joined for it in one.explorer.iterations]
        for a, b in zip(fp.explorer.iterations, one.explorer.iterations):
            assert set(b.candidates) <= set(a.candidates)
            assert a.edge[0] not in a.candidates
            wider += len(a.candidates) - len(b.candidates)
        assert fp.by_purpose.get("validation", 0) >= one.by_purpose.get("validation", 0)
    assert wider > 0


def test_footprints_go_back_to_v_k_over_e_before_searching():
    """§2.3.1: "the robot returning to v_k": one retrace move per loop edge, none per new place."""
    w = make_world("random:n=9,fraction=0.4,seed=2")
    out = explore(w, "footprints")
    assert out.by_purpose["retrace"] == w.m - w.n + 1 and out.by_purpose["new"] == w.m


def test_footprints_with_one_marker_short_run_out():
    """Every run drops exactly m + n: a pool one short is the failed outcome (the kit is the whole count)."""
    w = g.cycle(4)
    spec = replace(REGISTRY["footprints"], kit_fn=lambda n, m, o: Kit(either=n + m - 1))
    out = explore(w, spec)
    assert (out.outcome, out.claimed, out.verified) == ("failed", "failed", False)


def test_labelled_dfs_names_the_place_and_the_entry_without_a_move():
    """§2.3.1: the label answers "have I been here" and "by which exit did I arrive": no validation, no retrace,
    no search — only the edge itself and the walks of S between edges."""
    out = explore(make_world("complete:n=6"), "labelled-dfs")
    assert set(out.by_purpose) <= {"new", "travel"}
    labels = sorted((m.at, m.count) for m in out.explorer.S.to_world().markers)
    assert [c for _, c in labels] == sorted(c for _, c in labels) and {c for _, c in labels} == set(range(1, 7))


def test_labelled_dfs_is_depth_first_whatever_policy_is_given():
    w = make_world("small-world:n=12,k=4,p=0.2,seed=3")
    runs = [explore(w, "labelled-dfs", policies=Policies(edge=p)) for p in ("nearest", "fifo", "lifo")]
    assert len({r.cost for r in runs}) == 1


@pytest.mark.parametrize("k", [3, 5, 8])
def test_labelled_dfs_costs_m_on_a_cycle_and_a_chain_and_2m_minus_1_on_a_star_from_its_centre(k):
    """2m is tight up to the last step: from a star's centre every leaf is visited and left but the last (2m − 1);
    round a cycle DFS closes the loop edge and is done (m); along a chain from its end, m."""
    assert explore(g.cycle(k), "labelled-dfs").cost == k
    assert explore(g.chain(k), "labelled-dfs").cost == k - 1
    star = from_positions([(0, i) for i in range(1, k + 1)],
                          {0: (0.0, 0.0), **{i: (math.cos(i), math.sin(i)) for i in range(1, k + 1)}})
    out = explore(star, "labelled-dfs")
    assert (out.outcome, out.cost) == ("correct", 2 * star.m - 1)


def test_a_label_pointing_one_exit_off_is_caught_by_the_checker():
    """The label's direction is the whole back-link answer (§2.3.1): turned one exit clockwise, the robot believes
    it entered by the wrong exit, and the run is not judged correct."""
    class TurnedLabel(LabelledGraphDFS):
        def label(self, v, it):
            _, entry = self.position
            self.drop(MarkerOp("vertex", count=v + 1, direction=(1 - entry) % self.M.degree(v)), it)
    out = explore(make_world("complete-hole:n=6,seed=1"), replace(REGISTRY["labelled-dfs"], explorer=TurnedLabel))
    assert explore(make_world("complete-hole:n=6,seed=1"), "labelled-dfs").outcome == "correct"
    assert out.outcome != "correct" and not out.verified


@pytest.mark.parametrize("name", BASELINES)
def test_the_cli_explores_with_each(name, capsys):
    assert main(["explore", "lattice-hole:rows=4,cols=4,seed=2", "--algorithm", name, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["outcome"], data["verified"], data["lighthouse"]) == ("correct", True, None)
    assert data["upper_bound"] == REGISTRY[name].bound_for(data["n"], data["m"])
