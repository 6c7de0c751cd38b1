"""Where a registered explorer changes its listing, the smallest world found where the listing's moves differ.

Every entry that sets ``changes`` (``docs/bounds.md``, "Which entries improve on the thesis's listing") is run
here beside the same explorer with the change undone — the listing's step put back in its place — on the smallest
world an enumeration of embedded worlds (every start) found for it: the listing's robot makes more moves there, so
the change is real, and the explorer's own run is correct.  An entry that follows its listing sets no ``changes``.
"""

from __future__ import annotations

import pytest

from topomark.spec.world import Start, World
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec
from topomark.reference.explorers import case5_v1, edge_footprints, enhanced, expansion, saving_markers
from topomark.reference.explorers.counted_markers import DirectionalVertexCounts
from topomark.reference.explorers.policies import parents_toward
from topomark.reference.run.explore import explore

FIVE = {"v0": ["v2", "v3", "v4"], "v1": ["v2", "v3", "v4"], "v2": ["v0", "v1", "v4"], "v3": ["v0", "v1"],
        "v4": ["v0", "v1", "v2"]}  # 5 places, 7 edges: the smallest world for the searches' changes
FIVE_B = {**FIVE, "v1": ["v2", "v4", "v3"]}  # the same graph, v1's exits in the other order: enh3's
K4 = {"v0": ["v1", "v2", "v3"], "v1": ["v0", "v2", "v3"], "v2": ["v0", "v1", "v3"], "v3": ["v0", "v1", "v2"]}
CHAIN4 = {"v0": ["v1", "v3"], "v1": ["v0", "v2"], "v2": ["v1"], "v3": ["v0"]}
TRIANGLE = {"v0": ["v1", "v2"], "v1": ["v0", "v2"], "v2": ["v0", "v1"]}
KITE = {"v0": ["v1", "v2", "v3"], "v1": ["v0", "v2"], "v2": ["v0", "v1", "v3"], "v3": ["v0", "v2"]}
FIVE_9 = {"v0": ["v1", "v3", "v4"], "v1": ["v0", "v2", "v3", "v4"], "v2": ["v1", "v3", "v4"],
          "v3": ["v0", "v1", "v2", "v4"], "v4": ["v0", "v1", "v2", "v3"]}  # 5 places, 9 edges: case-5-v2's
SIX = {"v0": ["v1", "v4"], "v1": ["v0", "v2", "v5"], "v2": ["v1", "v3"], "v3": ["v2", "v4", "v5"],
       "v4": ["v0", "v3", "v5"], "v5": ["v1", "v3", "v4"]}


def _world(rotation: dict, at: str, facing: str) -> World:
    return World(rotation).with_start(Start(at, facing))


# -- the change undone: the listing's step ------------------------------------------------------------------
def _no_records_beyond_e(monkeypatch):
    """Algorithm 4.3: T is looked up only while tracing executed motions, never grafted at v_u before them."""
    monkeypatch.setattr(enhanced, "graft", lambda *args, **kwargs: 0)


def _explore_every_place(monkeypatch):
    """Algorithms 4.4 line 22, 4.5 line 7: every place within d is walked to, known or not."""
    def walk_all(trie, it, d):
        for m in range(1, trie.at.sig.degree):
            trie.forward(m, "expansion")
            it.expansion += 1
            if d > 1:
                walk_all(trie, it, d - 1)
            trie.back("expansion")
            it.expansion += 1
    monkeypatch.setattr(expansion, "expand", walk_all)


def _neighbours_of_vk_too(monkeypatch):
    """Algorithm 6.1 line 11, 6.3 line 18: v_k's known neighbours are candidates too."""
    monkeypatch.setattr(edge_footprints, "open_ends_beyond",
                        lambda S, vk: {v for v in S.unexplored.ends() if v != vk})


def _check_at_the_candidate_only(monkeypatch):
    """Algorithm 6.1 lines 13–14: the robot goes to the candidate and checks it there, not on the way."""
    def walk(self, target, looked):
        darts = list(self.path_to(target, parents_toward(self.M, self.position[0], target)))
        for dart in darts:
            sig = self.leave(dart, "validation")
        v, entry = self.position
        extra = set(sig.edges) - set(self.map_signature(v, entry).edges)
        if not extra:
            return None
        (p, _, _), = extra
        return v, (entry + p) % self.M.degree(v), entry
    monkeypatch.setattr(edge_footprints.FootprintSearch, "walk_looking", walk)


def _always_come_back(monkeypatch):
    """Algorithm 6.6 lines 19–20: after a loop edge from an unmarked v_k, back to v_k, unexplored edges or not."""
    def arrive(self, it, sig):
        if not sig.edges:
            return original(self, it, sig)
        vk = it.edge[0]
        self.loop(it, self.identify(it, sig, sig.edges))
        if not self.marked(vk):
            self.leave(self.position, "travel")
    original = saving_markers.SavingEdgeCounts.arrive
    monkeypatch.setattr(saving_markers.SavingEdgeCounts, "arrive", arrive)


def _plain_edge_policy(monkeypatch):
    """Algorithm 6.2 line 6 by the edge policy alone, the blank place's edges not put first."""
    monkeypatch.setattr(DirectionalVertexCounts, "edge_policy", property(lambda self: self.policies))


CASES = [  # entry, world, start, facing, the change undone, our cost, the listing's cost
    ("enh3", FIVE_B, "v3", "v0", _no_records_beyond_e, 19, 23),
    ("enh3+4", FIVE_B, "v3", "v0", _no_records_beyond_e, 31, 35),
    ("enh4", K4, "v0", "v1", _explore_every_place, 22, 24),
    ("enh3+4", K4, "v0", "v1", _explore_every_place, 22, 24),
    ("enh5-d2", CHAIN4, "v2", "v1", _explore_every_place, 7, 9),
    ("enh3+5", CHAIN4, "v2", "v1", _explore_every_place, 7, 9),
    ("case-1a", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 21),
    ("case-1b", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-2", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-4", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 21),
    ("case-4-mn", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-1a-edgeinfo", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 21),
    ("case-1b-edgeinfo", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-2-edgeinfo", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-4-edgeinfo", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-4-mn-edgeinfo", FIVE, "v2", "v0", _neighbours_of_vk_too, 19, 20),
    ("case-5-v2", FIVE_9, "v1", "v4", _neighbours_of_vk_too, 20, 21),
    ("case-1a", SIX, "v0", "v1", _check_at_the_candidate_only, 23, 25),
    ("footprints", FIVE, "v0", "v3", _check_at_the_candidate_only, 22, 24),
    ("extension-2", TRIANGLE, "v0", "v1", _always_come_back, 5, 6),
    ("case-dv-sum", KITE, "v1", "v2", _plain_edge_policy, 6, 7),
]


@pytest.mark.parametrize("name, rotation, at, facing, undo, ours, listing", CASES,
                         ids=[f"{c[0]}-{c[4].__name__.strip('_')}" for c in CASES])
def test_the_listing_s_robot_moves_more_on_the_smallest_world_found(monkeypatch, name, rotation, at, facing, undo,
                                                                     ours, listing):
    world, spec = _world(rotation, at, facing), algorithm_spec(name)
    assert spec.changes is not None and not spec.follows_listing
    ran = explore(world, spec)
    assert ran.outcome == "correct" and ran.cost == ours
    undo(monkeypatch)
    literal = explore(world, spec, check=False)
    assert literal.cost == listing > ours


@pytest.mark.parametrize("name", ["case-5-v1", "case-5-directional"])
def test_algorithm_6_4_s_literal_counter_fails_on_the_triangle_where_the_unique_counts_map_it(monkeypatch, name):
    world, spec = _world(TRIANGLE, "v0", "v1"), algorithm_spec(name)
    assert explore(world, spec).outcome == "correct"
    monkeypatch.setattr(case5_v1.VertexCountsThenLighthouse, "next_count", lambda self: len(self.count_of))
    assert explore(world, spec).outcome == "failed"  # v0 and the first new place both show one marker


def test_entries_changing_their_listing_are_those_the_audit_found():
    changed = {name for name, spec in REGISTRY.items() if spec.changes}
    audited = {"enh3", "enh4", "enh5-d2", "enh3+4", "enh3+5", "footprints", "model-tree", "case-1a", "case-1b", "case-2",
               "case-4", "case-4-mn", "case-5-v1", "case-5-v2", "case-dv-sum", "extension-2", "case-1b-edgeinfo",
               "case-2-edgeinfo", "case-1a-edgeinfo", "case-4-edgeinfo", "case-4-mn-edgeinfo", "case-5-directional"}
    follows = {"basic", "enh1", "enh2", "enh5-d1", "labelled-dfs", "single-leaf", "case-3a", "case-3b",
               "case-3b-saving", "case-0", "case-5-edge", "extension-1", "extension-naive"}
    assert audited <= changed and not follows & changed


PAW = {"v0": ["v3"], "v1": ["v2", "v3"], "v2": ["v1", "v3"], "v3": ["v0", "v1", "v2"]}  # a triangle, a pendant


def _model_tree_with(switch: str):
    """model-tree with one of Algorithm 5.1's listed ways switched on (:class:`ModelTreeExplorer`'s switches:
    the listing's step put back in its place by a subclass, as ``model-tree-listing`` puts back all three)."""
    from dataclasses import replace

    from topomark.reference.explorers.model_tree import ModelTreeExplorer

    return replace(algorithm_spec("model-tree"), explorer=type(f"With_{switch}", (ModelTreeExplorer,), {switch: True}))


MODEL_TREE = [  # the listing's way, world, start, facing, options, our (outcome, cost, hypotheses), the listing's
    ("listing_hypotheses", TRIANGLE, "v0", "v1", {"cue-n": 3}, ("correct", 10, 1), ("correct", 10, 2)),
    ("listing_hypotheses", PAW, "v3", "v1", {"cue-n": 4}, ("correct", 30, 1), ("correct", 32, 2)),
    ("listing_paths", PAW, "v0", "v3", {"cue-n": 4}, ("correct", 29, 1), ("correct", 37, 1)),
    ("listing_stops", K4, "v0", "v1", {"cue-n": 4, "max-steps": 20}, ("failed", 136, 20), ("limit", 181, 20)),
]


@pytest.mark.parametrize("switch, rotation, at, facing, options, ours, listing", MODEL_TREE,
                         ids=[f"{c[0]}-{len(c[1])}-places-{c[6][1] - c[5][1]}-moves" for c in MODEL_TREE])
def test_each_way_model_tree_changes_its_listing_shows_on_the_smallest_world_found(switch, rotation, at, facing,
                                                                                    options, ours, listing):
    """An enumeration of every embedded world of up to five vertices (max degree 4) from every start, told n
    (``--cue-n``: with no cue no run on a world with a cycle ends but at a cap, §5.2.2), found these, the
    smallest first, for each of the three changes (``model-tree``'s ``changes``):

    * line 17's multi-edge hypotheses: the triangle is the smallest world where one more hypothesis is formed
      (validated at no cost), the paw from its hub the smallest where it costs validation walks (30 against 32);
    * lines 18–23's paths one by one, out and back, instead of one breadth-first tree: the paw from its pendant
      (29 against 37);
    * the stopping rules: K4 is the smallest, where every live model is completed and no walk tells them apart
      — model-tree fails at once, the listing's window never closes and the run ends at ``--max-steps``.  Without
      a cue no world with a cycle shows this change: the model whose every edge is new (the traversal map)
      is never voided nor completed, so model-tree's extra rules never fire there either.

    model-tree is not deterministic in the thesis's sense (it may fail, §5.2.2), but its runs draw nothing at
    random: the same world and options make the same run, so no seed is needed."""
    world, spec = _world(rotation, at, facing), algorithm_spec("model-tree")
    assert spec.changes is not None and not spec.follows_listing and not spec.deterministic
    runs = [explore(world, spec, options=options) for _ in range(2)]
    assert [(r.outcome, r.cost, r.hypotheses) for r in runs] == [ours] * 2 and runs[0].violation is None
    literal = explore(world, _model_tree_with(switch), options=options)
    assert (literal.outcome, literal.cost, literal.hypotheses) == listing and literal.violation is None
    assert listing != ours
