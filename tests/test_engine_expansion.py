"""The engine's Enhancements 4 and 5 and their combinations with Enhancement-3 agree with the reference (§4.2–4.3);
seeded faults (no prune, the wrong distance, no D) are caught."""

from __future__ import annotations

import pytest

from topomark.proofs.census_map import plan
from topomark.proofs.world_arrays import to_arrays
from topomark.reference import engine
from topomark.reference.engine import compare, enhanced, expansion, runs
from topomark.reference.engine.compare import Case, _unit_cases, compare_case
from topomark.reference.engine.equality import main as equality_main
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import explore
from topomark.reference.worlds.argument import resolve_world
from topomark.spec.world import Start

NEW = ("enh4", "enh5-d1", "enh5-d2", "enh3+4", "enh3+5")
"""The Chapter 4 algorithms of §4.2–4.3 the engine runs."""
COMBOS = (("nearest", "fifo", "shortest"), ("fifo", "lifo", "dfs"), ("lifo", "shortest", "shortest"))
"""Three policy combinations naming every built-in policy once at least (the command runs all 18)."""
POLICIES = ("nearest", "fifo", "shortest")


def _census(n: int, degree: int) -> list[Case]:
    return [case for task in plan(n, degree, 2) for unit, _ in task for case in _unit_cases([unit], degree)]


@pytest.mark.parametrize("algorithm", NEW)
def test_the_fixed_slice_and_a_seeded_random_world_agree(algorithm):
    """Every census world with n <= 4, degree <= 3 from every start orbit (36), three policy combinations, and a
    seeded random world of n <= 30: claim, cost by purpose, marker operations, counts and trace digest."""
    count, bad = 0, []
    for case in _census(4, 3):
        k, found = compare_case(case, COMBOS, None, algorithm)
        count, bad = count + k, bad + found
    text, starts = compare.random_cases(1, 30, seed=5, starts=1)[0]
    k, found = compare_case(Case(text, "random", resolve_world(text), starts), COMBOS, None, algorithm)
    assert not bad + found, [str(d) for d in (bad + found)[:2]]
    assert (count, k) == (3 * 36, 3)


def _graph5() -> Case:
    """The census world n = 4, degree <= 3, graph 5 rank 0: its v0 facing exit 0 prunes and skips."""
    return next(c for c in _census(4, 3) if c.name == "census n=4 D=3 graph 5 rank 0")


@pytest.mark.parametrize("algorithm", NEW)
def test_a_run_that_prunes_h_and_skips_a_sensed_neighbour_agrees(algorithm):
    """The reference prunes hypotheses (Algorithm 4.4 line 7, 4.5 line 8) and, with Enhancement-4, does not visit
    again a neighbour of the new vertex that validation sensed (iteration 3 expands fewer than its exits); the
    engine does the very same actions."""
    case = _graph5()
    start = ("v0", 0)
    world = case.world
    out = explore(world.with_start(Start("v0", world.neighbour("v0", 0))), algorithm, Policies(*POLICIES),
                  check=False, record=False)
    short = [it.number for it in out.explorer.iterations if algorithm.endswith("4") and it.kind == "non-loop"
             and it.expansion < 2 * (it.signature.degree - 1)]
    assert out.explorer.stats["pruned"] > 0 and short == ([3] if algorithm.endswith("4") else [])
    count, bad = compare_case(Case(case.name, "4", world, [start]), (POLICIES,), None, algorithm)
    assert count == 1 and not bad, [str(d) for d in bad]
    arrays = to_arrays(world)
    run = runs.run_logged(arrays, (arrays.names.index("v0"), 0), POLICIES, None, algorithm)
    assert run.cost == out.cost and run.by_purpose["expansion"] == out.by_purpose["expansion"] > 0


@pytest.mark.parametrize("algorithm, techniques", [
    ("enh4", expansion.EXPAND_NEW),  # H not pruned
    ("enh3+5", enhanced.TECHNIQUES["enh3"] | expansion.EXPAND_PLACE | expansion.DEPTH2),  # H not pruned
    ("enh5-d2", expansion.PRUNE | expansion.EXPAND_PLACE),  # d = 1, not 2
    ("enh5-d1", expansion.PRUNE),  # no expansion, so no D either
])
def test_seeded_fault_a_missing_technique_is_exit_3(algorithm, techniques, monkeypatch, capsys):
    """The engine without the prune of H, with the wrong distance, or without its expansion disagrees with the
    reference on the small census, and the equality command names where."""
    monkeypatch.setitem(enhanced.TECHNIQUES, algorithm, techniques)
    assert equality_main(["--algorithm", algorithm, "--max-vertices", "4", "--max-degree", "3", "--quiet"]) == 3
    err = capsys.readouterr().err
    assert "disagree" in err and "first differing action #" in err and f"({algorithm})" in err


def test_supports_and_chooses_the_compiled_engine_for_them():
    for algorithm in NEW:
        for lighthouse in (None, *engine.ENGINE_LIGHTHOUSES):
            assert engine.supports(algorithm, lighthouse, POLICIES)
    assert not engine.supports("enh4-listing", None, POLICIES) and not engine.supports("enh5-d2-listing", None,
                                                                                          POLICIES)
    if engine.available():
        assert engine.choose("compiled", "enh3+5", "thread", POLICIES) == ("compiled", None)
