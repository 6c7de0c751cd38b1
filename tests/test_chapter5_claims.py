"""What Chapter 5 states about the Figure 3.4 worlds, reproduced and compared (issue 11 item 6).

The two wheels of Figure 3.4 (:func:`~topomark.reference.worlds.generators.wheel_pair`,
derived there from §3.2.2) carry an undirected marker at the centre;
every run here strips it (the robot brings its own kit, or none).  Each test quotes the
thesis passage it reproduces; where our number differs, the docstring says why
(and ``topomark bench chapter-5`` prints the same comparison with times).

* §5.1: "the robot always selects one of the four corner vertices as
  the lighthouse, because … D = (4, 3, 3) … lacks rotational equivalent".
* §5.2.1: "this approach may generate a wrong world model on the two
  graphs shown in Figure 3.4".
* §5.2.2: "using only local signatures … more than 50 models become
  completed … using global signatures … only six … which include the correct
  model. (One of the incorrect models is the correct representation of the
  graph in Figure 3.4(b).) Similar results are observed when exploring the
  graph in Figure 3.4(b)."; Figure 5.3: "(f) is the correct world model".
"""

from __future__ import annotations

import time

import pytest

from topomark.reference.run.explore import explore
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.world import Start, World

from conftest import FIGURE_3_4, bare, make_world

A, B = (bare(make_world(text)) for text in FIGURE_3_4)
WORLDS = {"3.4a": (A, B), "3.4b": (B, A)}  # each world with the other one


def _from(world: World, v: str, facing: int = 0) -> World:
    return world.with_start(Start(v, world.rotation[v][facing]))


def _degrees_around(world: World, v: str) -> list[int]:
    return sorted(world.degree(w) for w in world.rotation[v])


@pytest.mark.parametrize("name", WORLDS)
def test_section_5_1_picks_a_corner_and_maps_from_every_start_facing_and_seed(name):
    """§5.1 held: every start vertex, every facing, walk seeds 0-2: the marker lies at a corner whose neighbour
    degrees are {4, 3, 3} (the centre's (3, 3, 3, 3) is periodic), the run is checked correct, and the corner is
    found at once from a corner (0 walk steps) or after one step from the centre."""
    world, _ = WORLDS[name]
    for v in world.vertices:
        for facing in range(world.degree(v)):
            for seed in range(3):
                light = LIGHTHOUSES["undirected-vertex"].with_options(seed=seed)
                out = explore(_from(world, v, facing), "basic", lighthouse=light, record=False)
                assert (out.outcome, out.verified) == ("correct", True), (v, facing, seed)
                assert _degrees_around(world, out.lighthouse_at) == [3, 3, 4] and world.degree(out.lighthouse_at) == 3
                assert out.walk_steps == (1 if v == "0" else 0)


@pytest.mark.parametrize("name", WORLDS)
def test_section_5_2_1_detects_its_wrong_loop_closings_on_figure_3_4(name):
    """§5.2.1: "this approach may generate a wrong world model on the two graphs shown in Figure 3.4" — it may; ours
    never does, because it detects each wrong loop closing first, as §5.2.1 allows ("detects some signature
    inconsistencies (due to wrong loop closing) and thus cannot proceed reporting failure").  From every start,
    facing and walk seeds 0-2 both schemes report ``failed``.  Scheme B from the centre picks a corner (aperiodic
    D, but four places share it) and at its first step takes a neighbouring corner for the lighthouse: the join
    would be a self-loop, which no world has (§3.1.1).  Scheme A's corner is entered again by an explored entry."""
    world, _ = WORLDS[name]
    for v in world.vertices:
        for facing in range(world.degree(v)):
            for seed in range(3):
                for scheme in ("local-pair", "local-degree-list"):
                    light = LIGHTHOUSES[scheme].with_options(seed=seed)
                    out = explore(_from(world, v, facing), "basic", lighthouse=light, record=False)
                    assert (out.outcome, out.claimed) == ("failed", "failed") and "§5.2.1" in out.reason, (v, seed)
    out = explore(_from(world, "0"), "basic", lighthouse="local-degree-list", record=False)
    assert "self-loop" in out.reason and world.degree(out.lighthouse_at) == 3  # a corner, one of four alike


def _completed(world: World, **options) -> tuple:
    started = time.perf_counter()
    out = explore(world, "model-tree", options=options, record=False)
    seconds = time.perf_counter() - started
    return out, [S.to_world() for S in out.explorer.completed_models], seconds


def _positions(models: list[World], target: World) -> list[int]:
    """1-based completion order of the models isomorphic (unmarked) to ``target``."""
    return [k for k, S in enumerate(models, 1) if find_isomorphism(S, target, markers=False).isomorphic]


@pytest.mark.parametrize("name", WORLDS)
def test_algorithm_5_1_six_completed_models_with_global_signatures_the_correct_one_last(name):
    """§5.2.2 and Figure 5.3 held on both worlds with the n cue (``--cue-n 5``), from the centre facing corner 1:
    exactly six completed models with global signatures, the correct one completed sixth (Figure 5.3 (f)), and
    one incorrect model is the other Figure 3.4 world (for (a) the third; for (b) (a) is the sixth and (b) itself
    the third).  With no marker the two wheels cannot be told apart, so the run ends ``failed`` naming the six
    models it cannot separate — the thesis says nothing of how its run ended.  The time is printed (about 0.1 s
    here; the issue's target is 10 s), not asserted."""
    world, other = WORLDS[name]
    out, models, seconds = _completed(world, **{"cue-n": 5})
    print(f"Figure {name}, global signatures, cue n=5: {len(models)} completed models, {seconds:.2f} s")
    assert len(models) == 6 and out.outcome == "failed" and "no walk can tell them apart" in out.reason
    assert out.extra["true_world_completed"] is True
    mine, others = _positions(models, world), _positions(models, other)
    assert len(mine) == len(others) == 1 and {mine[0], others[0]} == {3, 6}
    assert mine == [6] if name == "3.4a" else others == [6]


@pytest.mark.parametrize("name", WORLDS)
def test_algorithm_5_1_local_signatures_complete_many_more_models(name):
    """§5.2.2, "more than 50" (local) against six (global): with the n cue, local signatures (every degree-matching
    loop closing accepted, §5.2.2) complete 48 models to global's 6 — we measure 48, not "more than 50", because the
    n cue rejects every model over five vertices (§5.3 lists the cues; the thesis ran none); without a cue
    the count is cap-bound (at the same cap of 300 live models, local completes more than twice as many as global,
    which stays at six; at the default 10000, 346 against 6 — ``topomark bench chapter-5``).  Both the correct model and
    the other wheel are among local's completed models too."""
    world, other = WORLDS[name]
    _, glob, _ = _completed(world, **{"cue-n": 5})
    _, loc, seconds = _completed(world, **{"cue-n": 5, "signatures": "local"})
    print(f"Figure {name}, local signatures, cue n=5: {len(loc)} completed models, {seconds:.2f} s")
    assert len(glob) == 6 and len(loc) > 40 and len(loc) > 7 * len(glob)
    assert len(_positions(loc, world)) == len(_positions(loc, other)) == 1
    capped_global = _completed(world, **{"max-models": 300})
    capped_local = _completed(world, **{"max-models": 300, "signatures": "local"})
    assert capped_global[0].outcome == capped_local[0].outcome == "limit"
    assert len(capped_global[1]) == 6 and len(capped_local[1]) > 2 * len(capped_global[1])
