"""The independent client of §6.2.1's footprint searches with ``--edgeinfo``: §6.2.2's directional markers
(edgeINFO, Figure 6.14) on the five O(mn) searches as listed, against the conformance oracle.

* it passes each ``case-*-edgeinfo-listing`` suite with the listing's own reference costs, case for case, within
  the bound; on random worlds too: a second implementation cross-checking topomark's literal edgeINFO explorers;
* it passes each ``case-*-edgeinfo`` suite (topomark's improved search) with passes and differences only;
* the seeded faults: a copy whose map puts an E-marker's head at the wrong end fails (a wrong map); a copy that
  leaves out the edgeINFO filter (§6.2.2's "potentially confusing" test) maps correctly at the undirected
  listing's cost, not the edgeINFO listing's.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from listing_clients import EXAMPLES, patched

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.run_external import run_external
from topomark.reference.run.explore import explore
from topomark.reference.worstcase.moves import random_world

CLIENT = EXAMPLES / "client_footprint_listing.py"
CASES = ["1b", "2", "1a", "4", "4-mn"]


def _pair(case: str) -> list[str]:
    return [f"case-{case}-edgeinfo", f"case-{case}-edgeinfo-listing"]


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("edgeinfo-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms([name for case in CASES for name in _pair(case)]))
    return root


def _client(tmp_path: Path, case: str, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new) + ["--case", case, "--edgeinfo"]


def _run(world, command: list[str], case: str):
    """The client on ``world`` with the edgeINFO listing's kit there; that listing's own cost."""
    spec = algorithm_spec(f"case-{case}-edgeinfo-listing")
    result = run_external(world, command, version=2, kit=spec.kit_for(world.n, world.m, {"markers": None}))
    return result, explore(world, spec.name, check=False).cost


@pytest.mark.parametrize("case", CASES)
def test_the_client_passes_the_edgeinfo_listing_s_suite_with_its_costs_and_the_variant_s_with_differences(
        suite, tmp_path, case):
    variant, listing = _pair(case)
    rows = run_algorithms(suite, _client(tmp_path, case), [variant, listing])
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == {variant, listing}
    for row in rows:
        j = row.to_json()
        if row.algorithm == listing:  # the listing's own reference: the same costs, within its bound
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
            assert j["bound_binds"] and j["cost"] <= j["bound"]
            assert j["reason"] == ("failed" if row.case["expected"] == "failed" else "ok")
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and f"{variant} (topomark's variant)" in j["message"]


def test_the_client_costs_what_topomark_s_edgeinfo_listings_cost_on_random_worlds(tmp_path):
    rng = random.Random(622)
    commands = {case: _client(tmp_path, case) for case in CASES}
    for _ in range(4):
        world = random_world(rng.randint(5, 9), rng.choice([3, 4]), rng)
        for case in CASES:
            result, listed = _run(world, commands[case], case)
            assert result.verdict == "pass", (case, result.message)
            assert result.cost == listed, (case, world)


def test_seeded_fault_a_head_at_the_wrong_end_fails(suite, tmp_path):
    old = 'marker["head"] = names[v] if self.ends[(v, i)] == "H" else names[w]'
    new = 'marker["head"] = names[w] if self.ends[(v, i)] == "H" else names[v]'
    rows = run_algorithms(suite, _client(tmp_path, "2", old, new), ["case-2-edgeinfo-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)


FILTER = ("chosen = {v for v, j in self.U if v in chosen and self.predicted(v, j)[3] == sig[3]}", "pass")


@pytest.mark.parametrize("case, seed", [("1b", 1), ("4", 32), ("4-mn", 32)])
def test_seeded_fault_leaving_out_the_edgeinfo_filter_costs_the_undirected_listing_s(tmp_path, case, seed):
    world = random_world(7, 4, random.Random(seed))
    result, listed = _run(world, _client(tmp_path, case), case)
    assert result.verdict == "pass" and result.cost == listed  # the client as written: the listing's cost
    result, listed = _run(world, _client(tmp_path, case, *FILTER), case)
    undirected = explore(world, f"case-{case}-listing", check=False).cost
    assert result.verdict == "pass" and result.cost != listed and result.cost == undirected
