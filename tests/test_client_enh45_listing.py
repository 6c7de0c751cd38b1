"""An independent client written from Algorithms 4.4 and 4.5 (d = 2) as listed
(``reference/oracle/examples/client_enh45_listing.py``; ``--enh5`` picks Algorithm 4.5) against the conformance
oracle (§4.2, Enhancements 4 and 5).

* the client is standalone: the standard library only, nothing of topomark;
* it passes ``enh4-listing``'s and ``enh5-d2-listing``'s suites with the listings' own reference costs, case for
  case, within topomark's bounds for the listings: a second implementation of each listing, cross-checking
  topomark's literal explorers; on random worlds too, against topomark's runs of the listings;
* it passes ``enh4``'s and ``enh5-d2``'s suites too: where topomark's variant costs less, the row is a difference,
  never a FAIL, and the client's cost there is what topomark's run of the listing costs on the same world;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map); a copy that leaves out
  the listings' pruning of H (Algorithm 4.4 line 7, 4.5 line 8), or their expansion (4.4 line 22, 4.5 line 7),
  makes other costs than the listings'.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.worldfile import load_world
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.run_external import run_external
from topomark.reference.run.explore import explore
from topomark.reference.worstcase.moves import random_world

CLIENT = EXAMPLES / "client_enh45_listing.py"
PAIRS = {"enh4": ["enh4", "enh4-listing"], "enh5-d2": ["enh5-d2", "enh5-d2-listing"]}
FLAGS = {"enh4": [], "enh5-d2": ["--enh5"]}


def test_the_client_is_standalone():
    assert imported_modules(CLIENT) == {"json", "re", "sys", "collections"}  # the standard library only: nothing of topomark


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("enh45-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(PAIRS["enh4"] + PAIRS["enh5-d2"]))
    return root


def _client(tmp_path: Path, variant: str, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new) + FLAGS[variant]


def _listing_cost(suite: Path, row, listing: str) -> int:
    return explore(load_world(suite / row.case["world"]), listing, check=False).cost


@pytest.mark.parametrize("variant", ["enh4", "enh5-d2"])
def test_the_client_passes_the_listing_s_suite_with_its_costs_and_the_variant_s_with_differences(
        suite, tmp_path, variant):
    pair = PAIRS[variant]
    listing = pair[1]
    rows = run_algorithms(suite, _client(tmp_path, variant), pair)
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == set(pair)
    differences = []
    for row in rows:
        j = row.to_json()
        if row.algorithm == listing:  # the listing's own reference: the same costs, within its bound
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
            assert j["bound_binds"] and j["bound_source"]["source"] == "listing" and j["cost"] <= j["bound"]
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and f"{variant} (topomark's variant)" in j["message"]
            differences.append(row)
    assert differences  # where the variant leaves out walks to places already sensed
    for row in differences:  # each costs what topomark's run of the listing costs on that world
        assert row.to_json()["cost"] == _listing_cost(suite, row, listing)


@pytest.mark.parametrize("variant", ["enh4", "enh5-d2"])
def test_the_client_costs_what_topomark_s_listing_costs_on_random_worlds(tmp_path, variant):
    rng = random.Random(45)
    command = _client(tmp_path, variant)
    for _ in range(8):
        world = random_world(rng.randint(4, 8), rng.choice([3, 4, 5]), rng)
        result = run_external(world, command, version=2)
        assert result.verdict == "pass", result.message
        assert result.cost == explore(world, PAIRS[variant][1], check=False).cost


def test_seeded_fault_a_wrong_join_fails(suite, tmp_path):
    wrong = _client(tmp_path, "enh4", "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)",
                    "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = "
                    "[far[0], (far[1] + 1) % len(self.exits[far[0]])], list(e)")
    rows = run_algorithms(suite, wrong, ["enh4-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)
    rows = run_algorithms(suite, wrong + ["--enh5"], ["enh5-d2-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)


@pytest.mark.parametrize("variant, old, new", [
    ("enh4", "if not self.contradicts(h, e)]  # line 7 [8]", "]  # line 7 [8] left out"),
    ("enh5-d2", "if not self.contradicts(h, e)]  # line 7 [8]", "]  # line 7 [8] left out"),
    ("enh4", "self.around(1)  # Algorithm 4.4 line 22", "pass  # line 22 left out"),
    ("enh5-d2", "self.around(2)  # Algorithm 4.5 line 7", "pass  # line 7 left out"),
])
def test_seeded_faults_leaving_out_a_line_of_the_listing_changes_its_costs(suite, tmp_path, variant, old, new):
    listing = PAIRS[variant][1]
    rows = run_algorithms(suite, _client(tmp_path, variant, old, new), [listing], select="complete-4")
    assert rows and all(r.passed for r in rows)  # still a correct map within the bound: no FAIL
    assert rows[0].to_json()["cost"] != _listing_cost(suite, rows[0], listing)
