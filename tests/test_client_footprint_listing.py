"""An independent client written from §6.2.1's footprint searches as listed
(``reference/oracle/examples/client_footprint_listing.py``: ``--case 2`` Algorithm 6.1, ``--case 4`` Algorithm 6.3,
``--case 4-mn`` Case 4's extension of Case 2, ``--case 1a`` and ``--case 1b`` the text of Cases 1a and 1b) against
the conformance oracle.

* the client is standalone: the standard library only, nothing of topomark;
* it passes each ``case-*-listing`` suite with the listing's own reference costs, case for case (the must-fail
  cases by giving up where topomark's run does), within topomark's bound for the search as listed: a second
  implementation of each listing, cross-checking topomark's literal explorers; on random worlds too;
* it passes each variant's suite (``case-2``, ``case-4``, ...) with passes and differences only, never a FAIL;
  each difference costs what topomark's run of the listing costs on that world;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map); copies that leave out
  a line of the listing — the candidates' marks (Algorithm 6.1 lines 11–12, Algorithm 6.3 line 18), their
  degree, the search's "exit for loop" (Algorithm 6.1 line 19, Algorithm 6.3 line 24) — map correctly at
  other costs than the listing's;
* Case 1b's extension to m markers maps where topomark's listing entry does, at its cost, and gives up with one
  marker fewer where that entry does; the thesis's "without further motion" for the last edge would be a guess.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.worldfile import load_world
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.conformance.cases import started
from topomark.reference.oracle.run_external import run_external
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators as g
from topomark.reference.worstcase.moves import random_world

CLIENT = EXAMPLES / "client_footprint_listing.py"
CASES = ["2", "4", "1a", "4-mn", "1b"]
DIFFERING = {"4", "1a"}  # whose variant's suite has a world (its worst case) where the listing costs more


def _pair(case: str) -> list[str]:
    return [f"case-{case}", f"case-{case}-listing"]


def test_the_client_is_standalone():
    assert imported_modules(CLIENT) == {"argparse", "json", "re", "sys", "collections"}  # nothing of topomark


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("footprint-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms([name for case in CASES for name in _pair(case)]))
    return root


def _client(tmp_path: Path, case: str, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new) + ["--case", case]


def _run(world, command: list[str], case: str):
    """The client on ``world`` with the kit the listing's entry is given there; the listing's own cost."""
    spec = algorithm_spec(f"case-{case}-listing")
    result = run_external(world, command, version=2, kit=spec.kit_for(world.n, world.m, {"markers": None}))
    return result, explore(world, spec.name, check=False).cost


@pytest.mark.parametrize("case", CASES)
def test_the_client_passes_the_listing_s_suite_with_its_costs_and_the_variant_s_with_differences(
        suite, tmp_path, case):
    variant, listing = _pair(case)
    rows = run_algorithms(suite, _client(tmp_path, case), [variant, listing])
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == {variant, listing}
    assert {r.case["expected"] for r in rows} == {"correct", "failed"}  # the tight kit: the client gives up too
    differences = []
    for row in rows:
        j = row.to_json()
        if row.algorithm == listing:  # the listing's own reference: the same costs, within its bound
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
            assert j["bound_binds"] and j["bound_source"]["source"] == "listing" and j["cost"] <= j["bound"]
            assert j["reason"] == ("failed" if row.case["expected"] == "failed" else "ok")
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and f"{variant} (topomark's variant)" in j["message"]
            differences.append(row)
    assert bool(differences) == (case in DIFFERING)
    for row in differences:  # each costs what topomark's run of the listing costs on that world
        assert row.to_json()["cost"] == explore(load_world(suite / row.case["world"]), listing, check=False).cost


def test_the_client_costs_what_topomark_s_listings_cost_on_random_worlds(tmp_path):
    rng = random.Random(621)
    commands = {case: _client(tmp_path, case) for case in CASES}
    for _ in range(5):
        world = random_world(rng.randint(5, 9), rng.choice([3, 4]), rng)
        for case in CASES:
            result, listed = _run(world, commands[case], case)
            assert result.verdict == "pass", (case, result.message)
            assert result.cost == listed, (case, world)


def test_seeded_fault_a_wrong_join_fails(suite, tmp_path):
    old = "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)"
    new = "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = [far[0], (far[1] + 1) % len(self.exits[far[0]])], list(e)"
    for case in ("2", "4"):
        rows = run_algorithms(suite, _client(tmp_path, case, old, new), [f"case-{case}-listing"], select="complete-4")
        assert rows and not any(r.passed for r in rows)


MARKS = ("and self.shown(v) == key}", "}")  # Algorithm 6.1 lines 11-12 (3, 4), Algorithm 6.3 line 18 (3)
DEGREE = ("if v != vk and len(self.exits[v]) == degree and", "if v != vk and")  # line 11 (2), line 18 (2)
EXIT = ("break  # line 19 [24]: exit for loop", "pass  # line 19 [24] left out")


@pytest.mark.parametrize("case, fault, seed", [
    ("2", MARKS, 124906), ("4-mn", MARKS, 124906), ("4", EXIT, 124906), ("1b", EXIT, 124906), ("1a", DEGREE, 526925),
])
def test_seeded_faults_leaving_out_a_line_of_the_listing_changes_its_costs(tmp_path, case, fault, seed):
    world = random_world(7, 4, random.Random(seed))
    result, listed = _run(world, _client(tmp_path, case), case)
    assert result.verdict == "pass" and result.cost == listed  # the client as written: the listing's cost
    result, listed = _run(world, _client(tmp_path, case, *fault), case)
    assert result.verdict == "pass" and result.cost != listed  # still a correct map: no FAIL, another cost


@pytest.mark.parametrize("world", [g.chain(5), g.complete(4)], ids=["chain-5", "complete-4"])
def test_case_1b_maps_with_m_markers_and_gives_up_with_fewer_where_the_listing_entry_does(tmp_path, world):
    """Case 1b's extension (§6.2.1): with m markers the last vertex, a leaf, stays blank (the chain), or the last
    loop edge is joined to the one entry left in U without a search (K4); one marker fewer, the run gives up."""
    world, spec, command = started(world), algorithm_spec("case-1b-listing"), _client(tmp_path, "1b")
    for markers, outcome in ((world.m, "pass"), (world.m - 1, "fail")):
        kit = spec.kit_for(world.n, world.m, {"markers": markers})
        result = run_external(world, command, version=2, kit=kit)
        listed = explore(world, spec.name, check=False, options={"markers": markers})
        assert result.verdict == outcome and result.gave_up == (outcome == "fail"), result.message
        assert result.cost == listed.cost and (listed.outcome == "failed") == (outcome == "fail")


NO_MOTION = """        if self.case == "1b" and not self.kit.get("undirected-either", 0):  # the last edge, with no motion
            vk, i = self.U.pop()
            self.exits.append([[vk, i]])
            self.exits[vk][i] = [len(self.exits) - 1, 0]
            return
"""


def test_case_1b_s_last_edge_without_further_motion_is_judged_a_guess(tmp_path):
    """The client's decision: out of markers it still follows e.  Adding the chain's last leaf "without further
    motion" (§6.2.1 Case 1b) leaves an edge never crossed, so the right map is a guess to the oracle."""
    world, spec = started(g.chain(5)), algorithm_spec("case-1b-listing")
    command = _client(tmp_path, "1b", "    def iterate(self):\n", "    def iterate(self):\n" + NO_MOTION)
    result = run_external(world, command, version=2, kit=spec.kit_for(world.n, world.m, {"markers": world.m}))
    assert result.verdict == "fail" and result.reason == "guess", result.message
