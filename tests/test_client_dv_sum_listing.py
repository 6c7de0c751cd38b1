"""An independent client written from Algorithm 6.2 as listed with §6.2.2's directional V-markers
(``reference/oracle/examples/client_dv_sum_listing.py``; ``--undirected`` is Case 3a's listing itself) against the
conformance oracle (§6.2.1 Case 3a, §6.2.2, Table 6.2).

* the client is standalone: the standard library only, nothing of topomark;
* it passes ``case-dv-sum-listing``'s suite with the listing's own reference costs, case for case (the kit that
  runs out included: it gives up at the same traversal), and ``case-3a``'s with ``--undirected``: a second
  implementation of each, cross-checking topomark's explorers; on random worlds too, with the assured kit and
  with fewer markers;
* it passes ``case-dv-sum``'s suite with no FAIL; on ``wheel-hub-last``, where the blank is the hub found last,
  it costs what the listing costs (its probes, lines 19–35), more than topomark's variant;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map); a copy that reads no
  direction from the markers (line 18 followed by lines 19–35's probes, as for undirected markers) and a copy
  that takes the blank's edges first (not line 6 as listed) cost other than the listing; the latter costs what
  topomark's variant ``case-dv-sum`` costs, which changes the listing just there.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.kit import Kit
from topomark.spec.worldfile import load_world
from topomark.reference.explorers.counted_markers import sum_to
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.run_external import run_external
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate
from topomark.reference.worstcase.moves import random_world

CLIENT = EXAMPLES / "client_dv_sum_listing.py"
PAIR = ["case-dv-sum", "case-dv-sum-listing"]
FLAGS = {"case-dv-sum-listing": [], "case-3a": ["--undirected"]}


def test_the_client_is_standalone():
    assert imported_modules(CLIENT) == {"json", "re", "sys", "collections"}  # the standard library only: nothing of topomark


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("dv-sum-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms(PAIR + ["case-3a"]))
    return root


def _client(tmp_path: Path, old: str = "", new: str = "") -> list[str]:
    return patched(CLIENT, tmp_path, old, new)


def _kit(listing: str, n: int, markers: int | None = None) -> Kit:
    return Kit(vertex=sum_to(n - 1) if markers is None else markers, directional=listing != "case-3a")


def test_the_client_passes_the_listing_s_suite_with_its_costs_and_the_variant_s_without_a_fail(suite, tmp_path):
    rows = run_algorithms(suite, _client(tmp_path), PAIR)
    rows += run_algorithms(suite, _client(tmp_path) + ["--undirected"], ["case-3a"])
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert {r.algorithm for r in rows} == set(PAIR + ["case-3a"])
    assert {r.case["expected"] for r in rows} == {"correct", "failed"}  # a kit that runs out is played too
    for row in rows:
        j = row.to_json()
        if row.algorithm != "case-dv-sum":  # a listing's own reference: the same costs, failures included
            assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
            assert j["reference"]["variant"]["follows"] == "the thesis's listing"
        elif j["cost"] != j["reference"]["cost"]:
            assert row.reason == "difference" and "case-dv-sum (topomark's variant)" in j["message"]


def test_where_the_blank_is_probed_the_client_costs_the_listing_s_cost_above_the_variant_s(tmp_path):
    world = generate("wheel-hub-last", n=7)
    result = run_external(world, _client(tmp_path), version=2, kit=_kit("case-dv-sum-listing", world.n))
    assert result.verdict == "pass", result.message
    listing, variant = (explore(world, name, check=False).cost for name in PAIR[::-1])
    assert result.cost == listing > variant  # 25 > 16: the hub's back-links probed (lines 19-35)


@pytest.mark.parametrize("listing", ["case-dv-sum-listing", "case-3a"])
def test_the_client_ends_as_topomark_s_listing_ends_on_random_worlds(tmp_path, listing):
    """With the assured kit both map the world at one cost; with fewer markers (every other world) the client gives
    up at the traversal where topomark's checked run ends failed, or FAILs where that run ends with a wrong map
    (the second unmarked place taken for the blank, §6.2.1 Case 3a: the robot cannot tell)."""
    rng = random.Random(62)
    command = _client(tmp_path) + FLAGS[listing]
    for k in range(8):
        world = random_world(rng.randint(4, 8), rng.choice([3, 4, 5]), rng)
        markers = None if k % 2 else rng.randint(1, sum_to(world.n - 1) - 1)
        result = run_external(world, command, version=2, kit=_kit(listing, world.n, markers))
        reference = explore(world, listing, options={"markers": markers})
        assert reference.outcome in (("correct",) if markers is None else ("failed", "wrong-map"))
        if reference.outcome == "wrong-map":
            assert result.verdict == "fail" and not result.gave_up
        else:
            assert result.passed != result.gave_up and result.cost == reference.cost, result.message


def test_seeded_fault_a_wrong_join_fails(suite, tmp_path):
    wrong = _client(tmp_path, "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)",
                    "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = "
                    "[far[0], (far[1] + 1) % len(self.exits[far[0]])], list(e)")
    rows = run_algorithms(suite, wrong, ["case-dv-sum-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)
    rows = run_algorithms(suite, wrong + ["--undirected"], ["case-3a"], select="complete-4")
    assert rows and not any(r.passed for r in rows)


NO_DIRECTION = ("if head is not None:  # a directional lighthouse", "if False:  # no direction read")
BLANK_FIRST = ("key=lambda k: dist[self.U[k][0]]))  # line 6",
               "key=lambda k: (self.U[k][0] != self.blank, dist[self.U[k][0]])))  # the blank's edges first")


@pytest.mark.parametrize("fault", [NO_DIRECTION, BLANK_FIRST], ids=["no-direction", "blank-first"])
def test_seeded_faults_not_the_listing_cost_other_than_the_listing(tmp_path, fault):
    world = generate("wheel-hub-last", n=7)
    result = run_external(world, _client(tmp_path, *fault), version=2, kit=_kit("case-dv-sum-listing", world.n))
    assert result.verdict == "pass", result.message  # still a correct map: no FAIL
    assert result.cost != explore(world, "case-dv-sum-listing", check=False).cost
    if fault is BLANK_FIRST:  # topomark's variant instead of line 6 as listed: its cost exactly
        assert result.cost == explore(world, "case-dv-sum", check=False).cost
