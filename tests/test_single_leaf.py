"""§5.3's single-leaf world, mapped with the leaf as Algorithm 3.1's directional lighthouse (``single-leaf``:
reference/explorers/single_leaf.py, leaf_search.py, registrations/single_leaf.py)."""

from __future__ import annotations

import pytest

from topomark.proofs.enumerate import embedded_worlds
from topomark.reference.algorithms.registry import algorithm_spec, variant
from topomark.reference.cli.main import main
from topomark.reference.explorers.leaf_search import search_bound
from topomark.reference.explorers.single_leaf import SingleLeafExplorer
from topomark.reference.run.explore import explore
from topomark.spec.errors import ExplorerFault
from topomark.spec.world import Start, World

# a triangle a-b-c with a pendant d at c, and a path to it from far away: the leaf e
LOLLIPOP = World({"a": ("b", "c"), "b": ("c", "a"), "c": ("a", "b", "d"), "d": ("c", "e"), "e": ("d",)}, (),
                 Start("a", "b"))


def leaf_of(world: World) -> str:
    (leaf,) = [v for v in world.vertices if len(world.rotation[v]) == 1]
    return leaf


def single_leaf_worlds(max_vertices: int, max_degree: int) -> list[World]:
    return [w for w in embedded_worlds(max_vertices, max_degree, min_vertices=3)
            if sum(len(w.rotation[v]) == 1 for v in w.vertices) == 1]


def nonbacktracking_walks(world: World, start: str, length: int) -> list[int]:
    """W(1..length): the non-backtracking walks of each length from ``start`` (computed on the world itself)."""
    counts, layer = [], [(start, None)]
    for _ in range(length):
        layer = [(w, v) for v, came in layer for w in world.rotation[v] if w != came]
        counts.append(len(layer))
    return counts


def distance(world: World, a: str, b: str) -> int:
    dist, queue = {a: 0}, [a]
    for v in queue:
        for w in world.rotation[v]:
            if w not in dist:
                dist[w] = dist[v] + 1
                queue.append(w)
    return dist[b]


def test_every_single_leaf_world_up_to_five_vertices_is_mapped_from_every_start():
    """The sweep behind the §5.3 claim: every single-leaf world of at most 5 vertices (every degree, up to
    extended isomorphism), from every start (place and faced exit), is mapped correctly under every check;
    after the search the run is Algorithm 3.1 from the leaf — the same cost as ``basic`` started there with its
    marker — and the search reaches the leaf within its bound by the leaf's distance."""
    worlds = single_leaf_worlds(5, 4)
    assert len(worlds) == 21  # 1 world of 4 vertices (a triangle with a pendant) and 20 of 5
    runs = 0
    for w in worlds:
        leaf = leaf_of(w)
        base = explore(w.with_start(Start(leaf, w.rotation[leaf][0])), "basic")
        assert base.verified
        for v in w.vertices:
            for x in w.rotation[v]:
                out = explore(w.with_start(Start(v, x)), "single-leaf")
                assert out.verified and out.outcome == "correct", (w.rotation, v, x, out.violation)
                search = out.by_purpose.get("establish", 0)
                assert out.extra["walk_steps"] == search and out.cost - search == base.cost
                k = distance(w, v, leaf)
                assert out.extra["leaf_distance"] == k and out.extra["lighthouse_at"] == leaf
                assert search <= search_bound(nonbacktracking_walks(w, v, k))
                runs += 1
    assert runs == 260


@pytest.mark.slow
def test_every_single_leaf_world_of_six_vertices_and_degree_three_is_mapped_from_every_start():
    for w in single_leaf_worlds(6, 3):
        for v in w.vertices:
            for x in w.rotation[v]:
                out = explore(w.with_start(Start(v, x)), "single-leaf")
                assert out.verified and out.outcome == "correct", (w.rotation, v, x, out.violation)


def test_the_search_walks_to_a_far_leaf_and_is_reported_in_the_cost():
    out = explore(LOLLIPOP, "single-leaf")
    assert out.verified and out.extra["leaf_distance"] == 3 and out.extra["lighthouse_at"] == "e"
    assert out.by_purpose["establish"] == out.extra["walk_steps"] > 0
    assert out.cost == sum(out.by_purpose.values())  # the search is in the reported cost
    at_leaf = explore(LOLLIPOP.with_start(Start("e", "d")), "single-leaf")
    assert at_leaf.extra["walk_steps"] == 0 and at_leaf.extra["leaf_distance"] == 0
    assert at_leaf.cost == out.cost - out.extra["walk_steps"]


def test_a_world_without_exactly_one_leaf_is_refused(capsys):
    for world, leaves in (("wheel-a", 0), ("chain:n=5", 2)):
        assert main(["explore", world, "--algorithm", "single-leaf", "--quiet"]) == 2
        err = capsys.readouterr().err
        assert f"exactly one vertex of degree 1 (§5.3); this world has {leaves}" in err and "Traceback" not in err


def test_the_search_limit_ends_the_run_with_the_limit_outcome(capsys):
    out = explore(LOLLIPOP, "single-leaf", options={"search-limit": 3})
    assert out.outcome == "limit" and "3 search traversals" in out.reason
    assert main(["explore", "random:n=6,fraction=0.4,seed=3", "--algorithm", "single-leaf", "--search-limit",
                 "0"]) == 2
    assert "--search-limit must be an integer >= 1" in capsys.readouterr().err


def test_the_cli_maps_the_claims_world_and_reports_the_search(capsys):
    assert main(["explore", "random:n=6,fraction=0.4,seed=3", "--algorithm", "single-leaf", "--json"]) == 0
    out = __import__("json").loads(capsys.readouterr().out)
    assert out["outcome"] == "correct" and out["by_purpose"]["establish"] == out["walk_steps"] > 0
    assert out["lighthouse"] == "leaf"


class TakesTheLeafForAnyPlace(SingleLeafExplorer):
    """A broken recognition: arriving at a place of degree 2 is taken for arriving at the leaf."""

    def lighthouse_entry(self, sig):
        return 0 if sig.degree in (1, 2) and len(self.iterations) > 0 else super().lighthouse_entry(sig)


class NeverClosesALoop(SingleLeafExplorer):
    """A broken validation: no hypothesis is ever made, so every loop edge is taken for a new place."""

    def hypotheses(self, it, sig):
        return []


def test_a_broken_explorer_is_caught():
    """The leaf is a certain lighthouse (the prior): a loop closed at it wrongly is a bug (exit 3), not a failure
    of the algorithm; a loop never closed is a wrong map the checker names."""
    with pytest.raises(ExplorerFault, match="Lemma 1"):
        explore(LOLLIPOP, variant("single-leaf-broken", TakesTheLeafForAnyPlace, like="single-leaf"))
    broken = explore(LOLLIPOP, variant("single-leaf-no-loops", NeverClosesALoop, like="single-leaf"))
    assert broken.outcome == "wrong-map" and broken.violation.check == "I-1"


def test_the_model_tree_prior_stays_and_points_here(capsys):
    assert main(["explore", "random:n=6,fraction=0.4,seed=3", "--algorithm", "model-tree", "--prior", "single-leaf",
                 "--quiet"]) == 0
    prior = next(p for p in algorithm_spec("model-tree").parameters if p.name == "prior")
    assert "single-leaf" in prior.help and "--algorithm single-leaf" in prior.help
    assert algorithm_spec("single-leaf").deterministic and not algorithm_spec("model-tree").deterministic

