"""Algorithm 5.1, marker-less mapping with a tree of world models (thesis §5.2.2, §5.3; issue 11 items 4-5).

Every run here is checked: after every step the checker asserts that the true
world is among the live models (``models``; topomark's own explorer voiding
it would be exit 3), and the returned model is judged by extended
isomorphism.  Worlds are the smallest that show each outcome.
"""

from __future__ import annotations

import json
import subprocess
import sys
from dataclasses import replace

import pytest

from topomark.reference.worlds import generators
from topomark.reference.run.explore import explore
from topomark.reference.explorers.model_shapes import Shape
from topomark.reference.explorers.model_tree import ModelTreeExplorer
from topomark.reference.explorers.traversal_map import TraversalMap
from topomark.reference.algorithms.registrations.model_tree import check_cues, summary, write_models
from topomark.reference.algorithms.registry import algorithm_spec, variant
from topomark.spec.errors import InvalidInput
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.world import World
from topomark.spec.worldfile import world_from_json


def _run(world: World, **options):
    return explore(world, "model-tree", options=options, record=False)


def _bare(world: World) -> World:
    return World(world.rotation, (), world.start)


@pytest.mark.parametrize("world, options", [
    (generators.chain(5), {}),  # a tree: TM is finite and is the map
    (generators.cycle(3), {"cue-n": 3}),
    (generators.cycle(5), {"cue-n": 5}),
    (generators.cycle(5), {"cue-m": 5}),
    (generators.lattice(2, 3), {"window": 1}),
    (generators.lattice(2, 3), {"window": 1, "signatures": "local"}),
    (generators.random_graph(6, 0.7, 1), {"window": 5}),
    (generators.random_graph(7, 0.7, 1), {"cue-n": 7}),
    (generators.random_graph(5, 0.7, 2), {"cue-diameter": 2}),
    (generators.random_graph(5, 0.5, 2), {"cue-planar": "yes", "window": 3}),
])
def test_small_worlds_are_mapped_correctly_with_every_model_checked(world, options):
    out = _run(world, **options)
    assert (out.outcome, out.claimed, out.violation) == ("correct", "correct", None), out.reason
    assert out.verified and out.checks > len(out.explorer.iterations)  # a models check per step, and the end
    assert out.marker_operations == {} and out.kit == "no marker"
    assert out.explorer.S.to_world().n == world.n


def test_a_cycle_without_a_cue_never_ends_every_longer_cycle_being_as_consistent():
    """All degrees are 2: C3, C4, ... each stays a completed model (no walk tells them apart), so no model is
    ever the only completed one and the run reaches its step cap — the thesis's "never terminates" (§5.2.1)."""
    out = _run(generators.cycle(4), **{"max-steps": 12})
    assert out.outcome == "limit" and "--max-steps 12 reached" in out.reason
    sizes = [S.n for S in out.explorer.completed_models]
    assert sizes == list(range(3, 3 + len(sizes))) and len(sizes) >= 8


def test_the_model_cap_is_the_limit_outcome():
    out = _run(generators.lattice(2, 3), **{"max-models": 3})
    assert out.outcome == "limit" and out.reason.startswith("--max-models 3 exceeded at step")
    assert out.explorer.peak_models <= 3


def test_local_signatures_can_return_a_wrong_map_where_global_ones_do_not():
    """random:n=6,fraction=0.5,seed=2 with a one-step window: accepting every degree-matching loop closing
    leaves a wrong completed model alone for a step; validating against every known vertex does not."""
    world = generators.random_graph(6, 0.5, 2)
    local = _run(world, signatures="local", window=1)
    assert (local.outcome, local.claimed) == ("wrong-map", "correct")
    assert local.violation.check != "models"  # the truth survived among the models; the one returned is wrong
    assert _run(world, signatures="global", window=1).outcome == "correct"


def test_the_figure_3_4_wheels_keep_both_completed_models():
    """§5.2.2: on Figure 3.4(a) the completed models include the correct one and Figure 3.4(b); with no
    marker the two are indistinguishable from the centre, so the run fails saying so once every live model is
    completed (with the n cue; without it the incomplete models grow until a cap)."""
    a, b = (_bare(w) for w in generators.wheel_pair())
    glob = _run(a, **{"cue-n": 5})
    loc = _run(a, **{"cue-n": 5, "signatures": "local"})
    assert glob.outcome == loc.outcome == "failed" and "no walk can tell them apart" in glob.reason
    assert len(glob.explorer.live) == 6  # thesis: "only six world models become completed"
    done = [S.to_world() for S in glob.explorer.completed_models]
    assert [bool(find_isomorphism(S, a, markers=False)) for S in done] == [False] * 5 + [True]  # Fig. 5.3: (f)
    assert bool(find_isomorphism(done[2], b, markers=False))  # one incorrect model is Figure 3.4(b)
    assert len(done) < len(loc.explorer.completed_models)  # global signatures keep fewer (thesis: 6 vs > 50)
    planar = _run(a, **{"cue-n": 5, "cue-planar": "yes"})
    flat = [S.to_world() for S in planar.explorer.completed_models]
    assert flat and not any(find_isomorphism(S, b, markers=False) for S in flat)  # (b) has genus 1


def test_the_diameter_cue_stops_at_depth_d_and_reports_models_it_cannot_tell_apart():
    out = _run(generators.cycle(6), **{"cue-diameter": 3})  # C3 ... C7 all have diameter <= 3
    assert out.outcome == "failed" and "depth 3" in out.reason and "cannot tell apart" in out.reason
    assert _run(generators.random_graph(5, 0.5, 0), **{"cue-diameter": 3}).outcome == "correct"


def test_completed_models_no_walk_tells_apart_end_the_run_as_failed():
    """Decision: once every live model is completed and none can be told from another by any walk, more
    steps cannot help (the window rule would never fire): the run fails, saying so."""
    out = _run(generators.lattice(2, 3), **{"cue-n": 6})
    assert out.outcome == "failed" and out.reason.startswith("2 completed models are left")


def test_a_false_cue_is_bad_input():
    with pytest.raises(InvalidInput, match="--cue-n 4 is false for this world"):
        _run(generators.cycle(5), **{"cue-n": 4})
    with pytest.raises(InvalidInput, match="--cue-diameter 1 is false"):
        check_cues(generators.cycle(5), {"cue-diameter": 1})
    with pytest.raises(InvalidInput, match="genus 1"):
        check_cues(_bare(generators.wheel_pair()[1]), {"cue-planar": "yes"})
    with pytest.raises(InvalidInput, match="--window must be an integer >= 1"):
        _run(generators.cycle(5), window=0)
    with pytest.raises(InvalidInput, match="--signatures must be one of global, local"):
        _run(generators.cycle(5), signatures="both")


class _DropsNonLoop(ModelTreeExplorer):
    """A broken Algorithm 5.1: forgets the non-loop child (line 32) whenever a loop closing was accepted."""

    def _augment(self, record, index, shape, dart, degree, children):
        before = len(children)
        super()._augment(record, index, shape, dart, degree, children)
        if len(children) - before > 1:
            children.pop()


def test_the_models_check_catches_an_explorer_that_voids_the_truth():
    out = explore(generators.lattice(2, 3), replace(variant("broken", _DropsNonLoop, like="model-tree")),
                  options={"window": 1}, record=False)
    assert out.violation is not None and out.violation.check == "models"


def test_models_share_structure():
    s = Shape.start(3).add_vertex(3, (0, 0)).add_vertex(2, (0, 1))
    joined = s.join((1, 1), (2, 1))
    assert joined.rows[0] is s.rows[0] and s.open == 4 and joined.open == 2
    out = _run(generators.lattice(2, 3), window=1)
    rows = [row for m in out.explorer.live for row in m.shape.rows]
    assert len({id(r) for r in rows}) < len(rows)  # live models share adjacency rows


def test_the_traversal_map_is_walked_breadth_first():
    tm = TraversalMap(3)
    order = []
    while len(order) < 6:
        v, x = tm.frontier()
        order.append((v, x))
        tm.add(v, x, 2)
    assert order == [(0, 0), (0, 1), (0, 2), (1, 1), (2, 1), (3, 1)]
    assert tm.path(4, 5) == [(4, 0), (1, 0), (0, 1), (2, 1)] and tm.explored_depth() == 1


def test_registration_and_cli():
    spec = algorithm_spec("model-tree")
    assert (spec.thesis, spec.deterministic, spec.family, spec.uses_lighthouse) == (
        "§5.2.2, Algorithm 5.1", False, "robot", False)
    assert spec.checks == ("models", "marker-budget", "isomorphism") and spec.marker_bound_fn(9, 9) == 0
    run = subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", "explore", "cycle:n=5", "--algorithm",
                          "model-tree", "--cue-n", "5", "--json"], capture_output=True, text=True, timeout=120)
    data = json.loads(run.stdout)
    assert run.returncode == 0 and (data["outcome"], data["verified"]) == ("correct", True)


def test_the_cli_fields_and_the_completed_models_as_world_files(tmp_path):
    """What ``--json`` and ``--models DIR`` report (the CLI wires these two helpers)."""
    world = generators.cycle(5)
    out = _run(world, **{"max-steps": 6})
    assert summary(out.explorer, world) == {"completed_models": 4, "peak_models": 5, "true_world_completed": True}
    paths = write_models(out.explorer, tmp_path / "models")
    assert [world_from_json(json.loads(p.read_text())).n for p in paths] == [3, 4, 5, 6]
    assert not summary(out.explorer, generators.cycle(7))["true_world_completed"]


def test_the_entry_edge_check_rejects_more_loop_closings():
    """§5.2.2: at vertices whose neighbour degrees have no proper rotation onto themselves the robot also checks
    its entry edge (by visiting the neighbours), so fewer wrong loop closings are accepted."""
    world = generators.random_graph(7, 0.7, 0)
    runs = {ec: _run(world, **{"cue-n": 7, "entry-check": ec}) for ec in ("yes", "no")}

    def accepted(out):
        return sum(h.outcome == "case 3" for it in out.explorer.iterations for h in it.hypotheses)
    assert runs["yes"].outcome == runs["no"].outcome == "correct"
    assert accepted(runs["yes"]) < accepted(runs["no"]) and runs["yes"].explorer.peak_models < \
        runs["no"].explorer.peak_models
    assert runs["yes"].by_purpose.get("probe", 0) > 0 and "probe" not in runs["no"].by_purpose
