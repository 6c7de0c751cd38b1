"""§6.2.1 Case 5 where phase II does the work (K = 4, 6, 10, as Figure 6.13's few-markers end), Version-2's pool
kept by the simulator, Case 5 with E-markers and Table 6.2's directional "unknown k > 3" row:
reference/explorers/case5_*.py, registrations/markers_case5.py.

Every run is under the checker (pose, I-1, I-2, the marker budget after every step, extended isomorphism with
every dropped marker at the end)."""

from __future__ import annotations

import pytest

from topomark.proofs.enumerate import embedded_worlds
from topomark.reference.algorithms.registry import REGISTRY, variant
from topomark.reference.explorers.case5_v2 import VertexEdgeThenLighthouse
from topomark.reference.explorers.counted_markers import sum_to
from topomark.reference.run.explore import explore
from topomark.spec.world import Start, World

from conftest import FIGURE_3_4, make_world

WORLDS = ("lattice-hole:rows=4,cols=4,seed=1", "complete-hole:n=6,seed=1", "random:n=9,fraction=0.3,seed=2",
          "small-world:n=10,k=4,p=0.2,seed=3") + FIGURE_3_4
CASE_5 = ("case-5-v1", "case-5-v2", "case-5-edge", "case-5-directional")


def in_world(out) -> int:
    """Markers lying in the world at the end."""
    return sum(m.count for m in out.explorer.S.to_world().markers)


@pytest.mark.parametrize("name", CASE_5)
@pytest.mark.parametrize("text", WORLDS)
@pytest.mark.parametrize("k", [4, 6, 10])
def test_few_markers_phase_two_does_work_and_the_map_is_correct(name, text, k):
    w = make_world(text)
    out = explore(w, name, options={"markers": k})
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    assert in_world(out) <= k
    ex = out.explorer
    if k < w.n:  # phase I cannot mark every place: phase II tests hypotheses, and its moves are counted
        assert ex.phase_two_from is not None and ex.stats["phase_two"] > 0
        assert 0 < ex.stats["phase_two"] < out.cost
        assert ex.stats["phase_two"] <= out.by_purpose.get("validation", 0) + out.by_purpose.get("retrace", 0)


@pytest.mark.parametrize("name", CASE_5)
@pytest.mark.parametrize("text", WORLDS)
def test_default_kit_never_reaches_phase_two(name, text):
    out = explore(make_world(text), name)
    assert out.outcome == "correct" and out.hypotheses == 0
    assert out.explorer.phase_two_from is None and out.explorer.stats["phase_two"] == 0


@pytest.mark.slow
@pytest.mark.parametrize("name", ["case-5-edge", "case-5-directional"])
def test_new_versions_map_every_small_world_from_every_start_with_four_markers(name):
    """Every embedded world of 3..5 places and degree ≤ 4, from every start, K = 4 (the least kit, §6.2.1 Case 5)."""
    runs = with_phase_two = 0
    for w in embedded_worlds(5, 4, min_vertices=3):
        for v in w.vertices:
            out = explore(World(w.rotation, (), Start(v, w.rotation[v][0])), name, options={"markers": 4})
            assert out.outcome == "correct", (w.rotation, v, out.reason, out.violation)
            runs += 1
            with_phase_two += out.explorer.stats["phase_two"] > 0
    assert runs > 1000 and with_phase_two > runs // 2


def test_edge_version_with_every_tree_edge_marked_is_case_3b():
    """Enough markers (Σ_{k=1}^{n−1} k): the same moves as Case 3b (§6.2.1 Case 4's O(m)), no hypothesis."""
    w = make_world(WORLDS[0])
    out = explore(w, "case-5-edge")
    assert out.cost == explore(w, "case-3b").cost and in_world(out) <= sum_to(w.n - 1)


def test_directional_version_never_probes_a_marked_place():
    """The direction of a marked place's markers gives its entry edge (§6.2.2): Version-1's probes disappear."""
    w = make_world(WORLDS[1])
    v1, dv = explore(w, "case-5-v1", options={"markers": 6}), explore(w, "case-5-directional", options={"markers": 6})
    assert sum(it.probes for it in v1.explorer.iterations) > 0
    assert sum(it.probes for it in dv.explorer.iterations) == 0


class OverdrawsByOne(VertexEdgeThenLighthouse):
    """A faulty Version-2 that believes it carries one marker more than K."""

    def left(self):
        return None if self.pool is None else self.pool + 1 - self.dropped


@pytest.mark.parametrize("k", [4, 6])
def test_version_2_overdraw_is_refused_by_the_simulator(k):
    """The kit given to the simulator is the pool of K: the K + 1-th marker is refused (OutOfMarkers), so the
    run ends ``failed`` with exactly K markers lying in the world."""
    w = make_world(WORLDS[0])
    spec = variant("v2-overdraw", OverdrawsByOne, like="case-5-v2")
    assert spec.kit_for(w.n, w.m, {"markers": k}).either == k
    out = explore(w, spec, options={"markers": k})
    assert out.outcome == "failed" and "marker" in (out.reason or "")
    assert out.explorer.dropped == k  # the refused drop changed nothing
    assert explore(w, "case-5-v2", options={"markers": k}).outcome == "correct"


def test_registered_kits_and_bounds():
    e, d = REGISTRY["case-5-edge"], REGISTRY["case-5-directional"]
    assert e.kit_for(6, 9, {"markers": None}).edge == sum_to(5) and e.marker_bound_fn(6, 9) == sum_to(5)
    assert d.kit_for(6, 9, {"markers": 7}).directional and d.kit_for(6, 9, {"markers": 7}).vertex == 7
    assert "O(m²n)" in e.bound and "O(m²n)" in d.bound
