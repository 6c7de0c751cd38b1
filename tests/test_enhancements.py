"""The Chapter 4 enhancements (issue 6): each a policy of the same checked explorer."""

from __future__ import annotations

import statistics

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from families import family_worlds
from topomark.reference.worlds import generators as g
from topomark.reference.algorithms.registry import in_family
from topomark.reference.cli.main import main
from topomark.reference.explorers.compositions import ENHANCEMENTS
from topomark.reference.algorithms.registry import variant
from topomark.reference.explorers.enhanced import Enhancement, EnhancedExplorer
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.explorers.policies import EDGE_POLICIES, HYPOTHESIS_POLICIES, PATH_POLICIES, Policies
from topomark.spec.world import Start, World

ALGORITHMS = {name: spec.factory for name, spec in in_family("algorithm-3.1").items()}
"""Algorithm 3.1's family, as registered: ``basic`` and the Chapter 4 enhancements, name ↦ explorer class."""

NAMES = ["enh1", "enh2", "enh3", "enh4", "enh5-d1", "enh5-d2", "enh3+4", "enh3+5"]


def test_every_enhancement_is_registered_by_its_name_in_algorithm_3_1s_family():
    """Chapter 4's enhancements are all there, after ``basic``; the family may hold more members (an algorithm
    added by a registration module, docs/adding-an-algorithm.md), so membership is checked, not an exact list."""
    assert set(ENHANCEMENTS) == set(NAMES)
    assert list(ALGORITHMS)[0] == "basic" and set(NAMES) <= set(ALGORITHMS)
    assert [name for name in ALGORITHMS if name in NAMES] == NAMES  # in Chapter 4's order


@settings(max_examples=100, deadline=None)
@given(family_worlds(), st.sampled_from(NAMES), st.builds(Policies, st.sampled_from(EDGE_POLICIES),
                                                          st.sampled_from(HYPOTHESIS_POLICIES),
                                                          st.sampled_from(PATH_POLICIES)))
def test_every_enhancement_maps_every_family_with_every_check_passing(world, name, pol):
    out = explore(world, name, pol, record=False)
    assert out.violation is None, out.violation
    assert out.verified and out.checks > 0
    assert out.nonloop_iterations == world.n - 1 and out.loop_iterations == world.m - world.n + 1
    assert sum(out.by_purpose.values()) == out.cost >= world.m
    assert out.explorer.T == {}  # every record of T was absorbed into the final map without contradiction


@settings(max_examples=30, deadline=None)
@given(family_worlds(small=True), st.sampled_from(NAMES))
def test_full_and_incremental_checks_agree_on_enhancements(world, name):
    out = explore(world, name, check_mode="both", record=False)
    assert out.verified, out.violation


class _AllOff(EnhancedExplorer):
    enhancement = Enhancement("basic")


@settings(max_examples=30, deadline=None)
@given(family_worlds(small=True))
def test_the_trie_explorer_with_every_technique_off_is_the_basic_algorithm(world):
    """Same motions, same perceptions, same cost: the robot's trie bookkeeping is exact."""
    a = explore(world, "basic")
    b = explore(world, variant("_all_off", _AllOff))
    moves = lambda out: [r for r in out.trace if r["event"] == "move"]  # noqa: E731
    assert moves(a) == moves(b) and a.cost == b.cost and b.verified


def _worlds(maker, seeds=range(6)):
    out = []
    for s in seeds:
        w = maker(s)
        v = sorted(w.vertices)[s % w.n]
        out.append(World(w.rotation, (), Start(v, w.rotation[v][0])))
    return out


LATTICE_HOLES = _worlds(lambda s: g.lattice_hole(6, 7, 0.1, "vertices", s))
COMPLETE_HOLES = _worlds(lambda s: g.complete_hole(9, 0.1, s))


@settings(max_examples=15, deadline=None)
@given(family_worlds(small=True))
def test_section_4_1_enhancements_change_only_validation_motions(world):
    """Same hypotheses confirmed, same S, same travel and new edges: the ceiling the bench report states."""
    basic = explore(world, "basic", record=False)
    for name in ("enh1", "enh2", "enh3"):
        out = explore(world, name, record=False)
        assert out.explorer.S.journal == basic.explorer.S.journal
        for p in ("travel", "new"):
            assert out.by_purpose.get(p, 0) == basic.by_purpose.get(p, 0)


def _mean_cost(name, worlds):
    outs = [explore(w, name, record=False) for w in worlds]
    assert all(o.verified for o in outs)
    return statistics.fmean(o.cost for o in outs), outs


@pytest.mark.parametrize("worlds", [LATTICE_HOLES, COMPLETE_HOLES], ids=["lattice-hole", "complete-hole"])
def test_traversal_exploiting_enhancements_never_cost_more_on_average_and_improve_in_order(worlds):
    basic, _ = _mean_cost("basic", worlds)
    e1, outs1 = _mean_cost("enh1", worlds)
    e2, _ = _mean_cost("enh2", worlds)
    e3, outs3 = _mean_cost("enh3", worlds)
    assert e3 <= e2 <= e1 < basic
    assert sum(o.explorer.stats["rejected_without_motion"] for o in outs1) > 0
    assert sum(o.explorer.stats["recorded"] for o in outs3) > 0
    assert all(o.by_purpose.get("expansion", 0) == 0 for o in outs1 + outs3)  # §4.1: no extra motion


def test_expansion_is_an_investment_counted_as_such():
    for name in ("enh4", "enh5-d1", "enh5-d2", "enh3+4", "enh3+5"):
        for w in LATTICE_HOLES[:3]:
            out = explore(w, name, record=False)
            spent = sum(it.expansion for it in out.explorer.iterations)
            assert out.by_purpose["expansion"] == spent > 0
            assert sum(it.pruned for it in out.explorer.iterations) == out.explorer.stats["pruned"]


def test_enhancement_4_pays_off_on_dense_heterogeneous_worlds_and_d2_does_not():
    """Tables 4.4/4.6: expanded signatures prune hypotheses on complete-hole worlds; d = 2 costs far more."""
    basic, _ = _mean_cost("basic", COMPLETE_HOLES)
    e4, outs = _mean_cost("enh4", COMPLETE_HOLES)
    d2, _ = _mean_cost("enh5-d2", COMPLETE_HOLES)
    assert e4 < basic < d2
    assert sum(o.explorer.stats["pruned"] for o in outs) > 0


def test_enhancement_4_costs_more_on_a_homogeneous_world():
    """§4.2: where expanded signatures carry no information, the investment is pure extra cost."""
    w = g.cycle(9)
    w = World(w.rotation, (), Start("0", w.rotation["0"][0]))
    basic = explore(w, "basic", record=False)
    e4 = explore(w, "enh4", record=False)
    assert basic.cost == w.m  # §3.5.1: cycles cost exactly m
    assert e4.explorer.stats["pruned"] == 0 and e4.by_purpose["expansion"] == 2 * (w.n - 1)
    assert e4.cost == basic.cost + e4.by_purpose["expansion"]


def test_motion_free_rejections_are_in_the_trace():
    w = LATTICE_HOLES[0]
    out = explore(w, "enh2")
    hyps = [h for r in out.trace if r["event"] == "iteration" for h in r["hypotheses"]]
    by = {h.get("rejected_by") for h in hyps}
    assert {"map", "motion"} <= by
    free = [h for h in hyps if h.get("rejected_by") == "map"]
    assert all(h["outcome"] in ("case 1", "case 2") for h in free)
    assert all("enhancement" in r for r in out.trace if r["event"] == "iteration")


@pytest.mark.parametrize("name", NAMES)
def test_runs_are_deterministic(name):
    w = COMPLETE_HOLES[1]
    assert dump_trace(explore(w, name).trace) == dump_trace(explore(w, name).trace)


def test_cli_selects_each_algorithm_by_name(capsys):
    for name in ["basic"] + NAMES:
        assert main(["explore", "lattice-hole:rows=4,cols=4", "--algorithm", name, "--quiet", "--json"]) == 0
        assert f'"algorithm": "{name}"' in capsys.readouterr().out
    assert main(["explore", "--algorithm", "enh6"]) == 2
