"""An independent client written from Algorithm 6.6's listing (``reference/oracle/examples/client_ext_listing.py``)
against the conformance oracle (§6.2.2, extension-2 of Case 3b, Figure 6.16).

* the client is standalone: the standard library only, nothing of topomark;
* it passes ``extension-2-listing``'s suite with the listing's own reference costs, case for case: a second
  implementation of the listing, cross-checking topomark's ``extension-2-listing`` explorer;
* it passes ``extension-2``'s suite too: where topomark's variant costs less (it skips lines 19–20's come-back
  when v_k has no unexplored edge left), the row is a difference, never a FAIL;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map), and a copy without
  lines 19–20 (the come-back) costs other than the listing.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.worldfile import load_world
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.run.explore import explore

CLIENT = EXAMPLES / "client_ext_listing.py"
PAIR = ["extension-2", "extension-2-listing"]


def test_the_client_is_standalone():
    assert imported_modules(CLIENT) == {"json", "re", "sys", "collections"}  # the standard library only: nothing of topomark


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("ext-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(PAIR))
    return root


def _client(tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new)


def test_the_client_passes_the_listing_s_suite_with_its_costs_and_the_variant_s_with_differences(suite, tmp_path):
    rows = run_algorithms(suite, _client(tmp_path), PAIR)
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == set(PAIR)
    differences = []
    for row in rows:
        j = row.to_json()
        if row.algorithm == "extension-2-listing":  # the listing's own reference: the same costs
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and "extension-2 (topomark's variant)" in j["message"]
            differences.append(row)
    assert differences  # the triangle: the last loop edge leaves v_k with nothing unexplored
    for row in differences:  # each costs what topomark's run of the listing costs on that world
        world = load_world(suite / row.case["world"])
        assert row.to_json()["cost"] == explore(world, "extension-2-listing", check=False).cost


def test_seeded_faults_a_wrong_join_fails_and_no_come_back_is_not_the_listing(suite, tmp_path):
    wrong = _client(tmp_path, "self.exits[vk][i], self.exits[x][j] = [x, j], [vk, i]  # line 17",
                    "self.exits[vk][i], self.exits[x][j] = [x, (j + 1) % len(self.exits[x])], [vk, i]  # line 17")
    rows = run_algorithms(suite, wrong, ["extension-2-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)
    lazy = _client(tmp_path, "if not was_marked:  # lines 19-20: back to v_k", "if False:  # lines 19-20 left out")
    rows = run_algorithms(suite, lazy, ["extension-2-listing"])
    assert rows and any(r.to_json()["cost"] != r.to_json()["reference"]["cost"] for r in rows if r.passed)
