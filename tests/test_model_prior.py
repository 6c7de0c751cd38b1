"""§5.3's priors for the model tree (reference/explorers/model_prior.py, the ``prior`` and ``rank`` options of
reference/explorers/model_tree.py): the single-leaf prior (§5.3) and the ranking of completed models (§5.3)."""

from __future__ import annotations

import pytest

from topomark.reference.cli.main import main
from topomark.reference.explorers.model_prior import posteriors
from topomark.reference.run.explore import explore
from topomark.spec.world import Start, World

from conftest import bare, make_world


def lollipop(k: int, start: Start) -> World:
    """A cycle of k places with one pendant place p at c0: exactly one vertex of degree 1."""
    rot = {f"c{i}": [f"c{(i - 1) % k}", f"c{(i + 1) % k}"] for i in range(k)}
    rot["c0"], rot["p"] = [f"c{k - 1}", "c1", "p"], ["c0"]
    return World(rot, (), start)


@pytest.mark.parametrize("start", [Start("p", "c0"), Start("c2", "c3")])
def test_the_single_leaf_prior_maps_a_cycle_with_a_pendant_that_the_bare_model_tree_never_finishes(start):
    w = lollipop(5, start)
    caps = {"max-models": 500, "max-steps": 60}
    assert explore(w, "model-tree", options=caps).outcome == "limit"  # its cycle can always be longer
    out = explore(w, "model-tree", options={**caps, "prior": "single-leaf"})
    assert out.outcome == "correct" and out.verified and out.extra["completed_models"] == 1


def test_the_single_leaf_prior_is_refused_on_a_world_without_exactly_one_leaf(capsys):
    assert main(["explore", "wheel-a", "--algorithm", "model-tree", "--prior", "single-leaf"]) == 2
    assert "--prior single-leaf is false for this world (it has 0 vertices of degree 1)" in capsys.readouterr().err


def test_posteriors_halve_per_vertex_edge_and_handle_and_sum_to_one():
    ranked = posteriors([(5, 8, 1), (4, 8, 1), (5, 8, 0), (5, 9, 0)])
    assert [k for k, _ in ranked] == [1, 2, 0, 3]  # 2^-13, 2^-13, 2^-14, 2^-14: ties in completion order
    assert ranked[0][1] == ranked[1][1] == 2 * ranked[2][1] and sum(p for _, p in ranked) == pytest.approx(1)


@pytest.mark.parametrize("text,first_is_true", [("wheel-a", True), ("wheel-b", False)])
def test_figure_3_4_ranked_the_planar_model_first_which_is_the_truth_only_for_wheel_a(text, first_is_true):
    """The six completed models of Figure 5.3 (§5.2.2), ranked: one planar, five of genus 1, all n = 5, m = 8.
    The planar one ranks first (2/7); it is wheel-a's map, so on wheel-b the top model is wrong and the true
    one shares the remaining 1/7 with four others."""
    out = explore(bare(make_world(text)), "model-tree", options={"cue-n": 5, "rank": "yes"})
    assert out.outcome == "failed"  # no walk tells the six apart: ranking is all that is left
    ranked = out.extra["ranked_models"]
    assert len(ranked) == 6 and [r["genus"] for r in ranked] == [0, 1, 1, 1, 1, 1]
    assert ranked[0]["posterior"] == pytest.approx(2 / 7, abs=1e-4) and ranked[0]["true"] is first_is_true
    assert sum(r["true"] for r in ranked) == 1
    assert "ranked_models" not in explore(bare(make_world(text)), "model-tree", options={"cue-n": 5}).extra
