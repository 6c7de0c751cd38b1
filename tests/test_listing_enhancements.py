"""Algorithms 4.3, 4.4 and 4.5 (d = 2) as listed, registered beside the compositions that change them (§4.1–4.2).

* ``enh3-listing``, ``enh4-listing`` and ``enh5-d2-listing`` make exactly the moves of ``enh3``, ``enh4`` and
  ``enh5-d2`` with their change undone (the monkeypatches of ``tests/test_listing_audit.py``), and so cost the
  listing's figure on the audit's smallest world, where the variant's differs; both maps are correct;
* each is held to its bound (``docs/bounds.md``): Algorithm 3.1's (3.1)+(3.2) for Algorithm 4.3, which adds no
  motion; topomark's bounds of Algorithms 4.4 and 4.5 as listed, checked on every small world and reached;
* replay accepts a trace of either explorer under either name and says whose moves it made; a trace that
  follows neither is still judged by its claims; a trace with one motion changed is refused;
* a program following the listing (topomark's literal explorer as a protocol client) passes the listing's
  conformance suite with its costs, and the variant's suite with differences, never a failure.
"""

from __future__ import annotations

import copy
import sys
from pathlib import Path

import pytest

from test_listing_audit import CHAIN4, FIVE_B, K4, _explore_every_place, _no_records_beyond_e
from topomark.proofs.enumerate import embedded_worlds
from topomark.spec.world import Start, World
from topomark.reference.algorithms.bounds import upper_bound
from topomark.reference.algorithms.registrations.algorithm31 import enh4_listing_bound, enh5_d2_listing_bound
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec
from topomark.reference.explorers.edge_choices import EDGE_CHOICES
from topomark.reference.explorers.policies import Policies
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.replay.replay import replay
from topomark.reference.run.explore import explore

PAIRS = {  # variant: (listing entry, the audit's world, start, facing, the change undone, variant's cost, listing's)
    "enh3": ("enh3-listing", FIVE_B, "v3", "v0", _no_records_beyond_e, 19, 23),
    "enh4": ("enh4-listing", K4, "v0", "v1", _explore_every_place, 22, 24),
    "enh5-d2": ("enh5-d2-listing", CHAIN4, "v2", "v1", _explore_every_place, 7, 9),
}
BOUNDS = {"enh3-listing": upper_bound, "enh4-listing": enh4_listing_bound, "enh5-d2-listing": enh5_d2_listing_bound}


def _world(ours: str) -> World:
    _, rotation, at, facing, *_ = PAIRS[ours]
    return World(rotation).with_start(Start(at, facing))


def _starts(world):
    for v in world.vertices:
        for facing in dict.fromkeys(world.rotation[v]):
            yield world.with_start(Start(v, facing))


@pytest.mark.parametrize("ours", sorted(PAIRS))
def test_the_literal_entry_costs_the_listing_s_figure_where_the_variant_s_differs(ours):
    literal_name, *_, variant_cost, listing_cost = PAIRS[ours]
    world = _world(ours)
    mine, literal = explore(world, ours), explore(world, literal_name)
    assert (mine.outcome, literal.outcome) == ("correct", "correct") and mine.verified and literal.verified
    assert (mine.cost, literal.cost) == (variant_cost, listing_cost)


@pytest.mark.parametrize("ours", sorted(PAIRS))
@pytest.mark.parametrize("text", ["complete:n=5", "lattice:rows=2,cols=3", "wheel-a"])
def test_the_literal_entry_is_the_variant_with_its_change_undone_move_for_move(monkeypatch, ours, text):
    """Not a monkeypatch: the literal explorer makes the very trace the audit's undone variant makes."""
    from conftest import bare, make_world

    literal_name, undo = PAIRS[ours][0], PAIRS[ours][4]
    for world in (_world(ours), bare(make_world(text))):
        literal = explore(world, literal_name).trace
        with monkeypatch.context() as m:
            undo(m)
            undone = explore(world, ours, check=False).trace
        assert [_comparable(r) for r in literal] == [_comparable(r) for r in undone]


def _comparable(record: dict) -> dict:
    """A trace record without what names the explorer or judges the run, and without ``known`` (the undone
    Enhancement-5 still counts the records it grafts, though they change no move)."""
    out = {k: v for k, v in record.items() if k not in ("algorithm", "verified", "violation")}
    if "enhancement" in out:
        out["enhancement"] = {k: v for k, v in out["enhancement"].items() if k != "known"}
    return out


def _every_small_run(literal_name: str, ours: str, edges: tuple[str, ...]) -> tuple[int, int, int]:
    """The listing on every embedded world of up to four vertices, from every start, under ``edges``: correct and
    within its bound (checked runs: ``cost-bound``); how many runs, how many at the bound, how many where the
    variant costs more than the listing."""
    literal, improved, bound_fn = algorithm_spec(literal_name), algorithm_spec(ours), BOUNDS[literal_name]
    runs = reached = above = 0
    for world in embedded_worlds(4, 3):
        bound = bound_fn(world.n, world.m)
        for started in _starts(world):
            for edge in edges:
                policies = Policies(edge=edge)
                as_listed = explore(started, literal, policies, check_mode="incremental", record=False)
                mine = explore(started, improved, policies, check=False, record=False)
                assert as_listed.outcome == "correct" and as_listed.cost <= bound, (started, edge, bound)
                runs += 1
                reached += as_listed.cost == bound
                above += mine.cost > as_listed.cost
    return runs, reached, above


@pytest.mark.parametrize("ours", sorted(PAIRS))
def test_the_listing_s_bound_holds_on_every_small_world_and_is_reached(ours):
    runs, reached, above = _every_small_run(PAIRS[ours][0], ours, ("nearest",))
    assert runs == 96 and reached == 2 and above == 0  # every start of the 12 worlds; at the bound: the one edge


@pytest.mark.slow
@pytest.mark.parametrize("ours", sorted(PAIRS))
def test_the_listing_s_bound_holds_under_every_edge_policy(ours):
    runs, reached, above = _every_small_run(PAIRS[ours][0], ours, tuple(EDGE_CHOICES))
    assert runs == 3 * 96 and reached == 3 * 2 and above == 0


def test_enh3_s_change_can_cost_more_than_its_listing():
    """Rejecting hypotheses from T before any motion changes which one stage 2 walks next (Algorithm 4.3 lines
    27–31): on this world of 5 places and 9 edges (the smallest the enumeration of worlds of up to five places
    and degree four finds) it walks more, so Algorithm 3.1's bound, not the listing's cost, holds enh3."""
    world = World({"v0": ["v1", "v3", "v4"], "v1": ["v0", "v2", "v3", "v4"], "v2": ["v1", "v4", "v3"],
                   "v3": ["v0", "v2", "v1", "v4"], "v4": ["v0", "v1", "v2", "v3"]}).with_start(Start("v1", "v4"))
    mine, literal = explore(world, "enh3"), explore(world, "enh3-listing")
    assert (mine.outcome, literal.outcome) == ("correct", "correct")
    assert (literal.cost, mine.cost) == (22, 24) and mine.cost <= upper_bound(world.n, world.m)


def test_the_registry_names_the_listing_and_whose_each_bound_is():
    for ours, (literal_name, *_) in PAIRS.items():
        improved, literal = algorithm_spec(ours), algorithm_spec(literal_name)
        assert improved.listing_entry == literal.name and improved.changes and not improved.follows_listing
        assert literal.follows_listing and literal.listing_entry is None and literal.kit == improved.kit
        assert literal.options == improved.options and literal.family == improved.family == "algorithm-3.1"
    assert algorithm_spec("enh3-listing").bound_source == algorithm_spec("enh3").bound_source == "thesis"
    assert algorithm_spec("enh3-listing").bound_fn is algorithm_spec("enh3").bound_fn is upper_bound
    for name in ("enh4-listing", "enh5-d2-listing"):
        spec = algorithm_spec(name)
        assert spec.bound_source == "listing" and spec.bound_binds and spec.bound_fn is BOUNDS[name]
    assert algorithm_spec("enh4").bound_fn is None and algorithm_spec("enh5-d2").bound_fn is None  # O(m²n) only
    assert algorithm_spec("enh3+4").listing_entry is None and algorithm_spec("enh3+5").listing_entry is None
    assert all(s.listing_entry in REGISTRY for s in REGISTRY.values() if s.listing_entry is not None)


def test_the_listing_bounds_by_hand():
    assert (enh4_listing_bound(2, 1), enh4_listing_bound(3, 3)) == (1, 22 + 2 * 3)  # one edge: no expansion beyond
    assert enh5_d2_listing_bound(3, 3) == 22 + 2 * 3 * 2  # per pass ≤ 2·min((n−1)(n−2), 2m−2) = 4
    assert enh5_d2_listing_bound(1, 0) == enh4_listing_bound(1, 0) == 0


def _trace(world: World, made: str, named: str, lighthouse: str | None = None) -> list[dict]:
    trace = copy.deepcopy(explore(world, made, lighthouse=lighthouse).trace)
    trace[0]["algorithm"] = named
    return trace


@pytest.mark.parametrize("ours", sorted(PAIRS))
@pytest.mark.parametrize("made_literal", [False, True])
@pytest.mark.parametrize("named_literal", [False, True])
def test_replay_accepts_either_explorer_under_either_name_and_says_which(ours, made_literal, named_literal):
    literal = PAIRS[ours][0]
    made, named = (literal if made_literal else ours), (literal if named_literal else ours)
    world = _world(ours)
    result = replay(world, _trace(world, made, named))
    assert result.ok and result.rerun is not None and result.rerun["algorithm"] == made, result.message
    assert result.to_json()["rerun"]["follows"] == ("the thesis's listing" if made_literal else "topomark's variant")
    assert f"its moves are {made}'s" in result.message


def test_replay_says_whose_moves_with_another_lighthouse_too():
    world = _world("enh3")
    result = replay(world, _trace(world, "enh3-listing", "enh3", lighthouse="thread"))
    assert result.ok and result.rerun is not None and result.rerun["algorithm"] == "enh3-listing"


def test_a_trace_following_neither_is_judged_by_its_claims_and_says_so():
    """Which e the edge policy picks is not in the claims (§3.3 line 4: "remove an unexplored edge"): a run
    taking the newest edge first, its header saying ``nearest``, makes neither re-run's moves."""
    world = _world("enh4")
    trace = copy.deepcopy(explore(world, "enh4-listing", Policies(edge="lifo")).trace)
    assert trace[0]["policies"]["edge"] == "lifo"
    trace[0]["policies"]["edge"] = "nearest"
    result = replay(world, trace)
    assert result.ok and result.rerun is None
    assert "its moves are neither enh4-listing's nor enh4's" in result.message


def test_a_trace_named_for_the_listing_with_one_motion_changed_is_refused():
    world = _world("enh3")
    trace = _trace(world, "enh3", "enh3-listing")
    k = next(i for i, r in enumerate(trace) if r["event"] == "move" and r["purpose"] == "validation")
    degree = int(trace[k - 1]["perception"].strip("[").split(",")[0])
    trace[k]["motion"] = (trace[k]["motion"] + 1) % degree
    result = replay(world, trace)
    assert not result.ok and result.rerun is None and result.line is not None and result.line >= k + 1


CLIENT = [sys.executable, str(Path(__file__).resolve().parent / "clients" / "topomark_client.py")]
DIFFERS = {"enh3": "worst-enh3-n6-d4", "enh4": "complete-4", "enh5-d2": "paw-4"}  # a suite case where they part


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("listing-enhancements") / "suite"
    export(root, cases=[], algorithms=suite_algorithms([n for ours in PAIRS for n in (ours, PAIRS[ours][0])]))
    return root


def _a_program_following_the_listing(suite: Path, ours: str, select: str | None) -> dict:
    literal = PAIRS[ours][0]
    rows = run_algorithms(suite, [*CLIENT, literal], [ours, literal], select=select)
    return {(r.algorithm, r.to_json()["case"]): r.to_json() for r in rows}


def _judged_fairly(rows: dict, ours: str) -> None:
    literal = PAIRS[ours][0]
    assert rows and all(j["verdict"] == "pass" for j in rows.values()), rows
    for (algorithm, case), j in rows.items():
        if algorithm == literal:  # its own suite: the listing's costs exactly
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
        elif j["cost"] != j["reference"]["cost"]:  # the variant's suite: a difference, never a failure
            assert j["reason"] == "difference" and j["cost"] > j["reference"]["cost"]
    assert rows[(ours, DIFFERS[ours])]["reason"] == "difference"


@pytest.mark.slow
@pytest.mark.parametrize("ours", sorted(PAIRS))
def test_a_program_following_its_listing_passes_every_case_of_both_suites(suite, ours):
    _judged_fairly(_a_program_following_the_listing(suite, ours, None), ours)
