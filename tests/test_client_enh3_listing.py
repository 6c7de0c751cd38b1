"""An independent client written from Algorithm 4.3's listing (``reference/oracle/examples/client_enh3_listing.py``)
against the conformance oracle (§4.1, Enhancement-3).

* the client is standalone: the standard library only, nothing of topomark;
* it passes ``enh3-listing``'s suite with the listing's own reference costs, case for case: a second
  implementation of the listing, cross-checking topomark's ``enh3-listing`` explorer;
* it passes ``enh3``'s suite too: where topomark's variant costs less, the row is a difference, never a FAIL, and
  the client's cost there is what topomark's ``enh3-listing`` costs on the same world — the oracle does not fail
  a faithful listing for costing what the listing costs;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map), and a copy that never
  rejects a hypothesis without motion (lines 16–24 left out) makes other costs than the listing's.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.worldfile import load_world
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.run.explore import explore

CLIENT = EXAMPLES / "client_enh3_listing.py"
PAIR = ["enh3", "enh3-listing"]


def test_the_client_is_standalone():
    assert imported_modules(CLIENT) == {"json", "re", "sys", "collections"}  # the standard library only: nothing of topomark


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("enh3-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(PAIR))
    return root


def _client(tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new)


@pytest.mark.slow
def test_the_client_passes_the_listing_s_suite_with_its_costs_and_the_variant_s_with_differences(suite, tmp_path):
    rows = run_algorithms(suite, _client(tmp_path), PAIR)
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == set(PAIR)
    differences = []
    for row in rows:
        j = row.to_json()
        assert j["bound_binds"] and j["bound_source"]["source"] == "thesis" and j["cost"] <= j["bound"]
        if row.algorithm == "enh3-listing":  # the listing's own reference: the same costs
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and "enh3 (topomark's variant)" in j["message"]
            differences.append(row)
    assert differences  # the worst cases of enh3, where its grafted records save moves
    for row in differences:  # each costs what topomark's run of the listing costs on that world
        world = load_world(suite / row.case["world"])
        assert row.to_json()["cost"] == explore(world, "enh3-listing", check=False).cost


@pytest.mark.slow
def test_seeded_faults_a_wrong_join_fails_and_no_rejection_without_motion_is_not_the_listing(suite, tmp_path):
    wrong = _client(tmp_path, "self.exits[vk][i], self.exits[far[0]][far[1]] = list(far), [vk, i]",
                    "self.exits[vk][i], self.exits[far[0]][far[1]] = [far[0], (far[1] + 1) % len(self.exits[far[0]])],"
                    " [vk, i]")
    rows = run_algorithms(suite, wrong, ["enh3-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)
    blind = _client(tmp_path, "H = [g for g in H if not self.contradicts(g, e)]  # lines 16-24",
                    "H = list(H)  # lines 16-24 left out")
    rows = run_algorithms(suite, blind, ["enh3"], select="worst-enh3-n20-d4-search")
    assert rows and all(r.passed for r in rows)  # a correct map within the bound: no FAIL
    assert rows[0].to_json()["cost"] != explore(load_world(suite / rows[0].case["world"]), "enh3-listing",
                                                check=False).cost
