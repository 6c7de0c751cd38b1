"""An independent client written from Algorithm 6.4 as listed (``reference/oracle/examples/client_case5_listing.py``;
``--directional`` is Table 6.2's "unknown k > 3" row, Version-1 with §6.2.2's directional V-markers) against the
conformance oracle (§6.2.1 Case 5, §6.2.2).

The listing fails by design: its counter (Algorithm 6.4 lines 1, 3, 13, 15) gives v0 and the first new place one
marker each, so a count that must name v_u names two places (``case-5-v1-listing`` and
``case-5-directional-listing`` are registered "implemented, expected to fail").  The oracle judges the client, which
follows the listing to the letter and gives up there, exactly as it judges topomark's literal entries:

* the client is standalone: the standard library only, nothing of topomark;
* it passes each listing's suite with the listing's own reference rows, case for case: the same outcome (failed
  where topomark's literal run fails, correct elsewhere) at the same cost — a second implementation of the
  listing, cross-checking topomark's literal explorers;
* against the variants' suites (``case-5-v1``, ``case-5-directional``, which count as Algorithm 6.2 does: v0 1,
  the j-th new place j + 1) a row is a pass, or a FAIL explained by the listing's own failure and nothing else:
  the client gave up because one marker marks two places, on a world where topomark's literal run ends failed
  too, after the traversals that run makes.  That nothing else explains them is shown by a copy of the client
  with line 3 made i ← 2 (the variants' one change): it passes the variants' suites with their costs, case for
  case;
* phase II (lines 16–35), which the suites' worlds never reach before the shared count ends the run, is
  cross-checked on worlds where the listing maps (a path from v0 into a cyclic part, so the count 1 is never
  sensed again) with K = 4 and 5 markers: the client's cost is the literal entry's;
* the seeded faults: a copy that joins e to the wrong exit of v_k' fails (a wrong map), and a copy that leaves out
  line 22 (no marked neighbour v_n after the lighthouse v_l) costs other than the listing.

``client_case5_v2_listing.py``, built on it, is Algorithm 6.5 as listed (``case-5-v2-listing``), whose line 23 as printed confirms no
hypothesis: it plays that listing's suite with its rows case for case; against ``case-5-v2``'s suite its one FAIL
is the wrong map of ``lattice-2x3-markers-4`` (K = 4, phase II must close a loop), where topomark's literal run
ends ``wrong-map`` too, and a copy with line 23 read "match throughout" (the variant's reading) passes that suite
with its costs.  The paw entered from its pendant with K = 4 is mapped wrongly, as the registration says.  Seeded
faults: a wrong join fails; a search that leaves out line 12's marks condition costs other than the listing
(complete:n=5, 27 against 22).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from listing_clients import EXAMPLES, imported_modules, patched

from topomark.spec.kit import Kit
from topomark.spec.worldfile import load_world, world_from_json
from topomark.reference.oracle.conformance import export, run_algorithms, suite_algorithms
from topomark.reference.oracle.run_external import run_external
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate

CLIENT = EXAMPLES / "client_case5_listing.py"
V2 = EXAMPLES / "client_case5_v2_listing.py"  # Algorithm 6.5, built on Algorithm 6.4's client beside it
FLAGS = {"case-5-v1-listing": [], "case-5-v2-listing": [],
         "case-5-directional-listing": ["--directional"]}
VARIANT = {"case-5-v1-listing": "case-5-v1", "case-5-v2-listing": "case-5-v2",
           "case-5-directional-listing": "case-5-directional"}
SHARED = "1 marker(s) mark 2 places of S"  # the client's message where Algorithm 6.4's counter fails
COUNTER = ("self.i = 1  # line 3", "self.i = 2  # line 3")  # the variants' counter: v0 1, the j-th new place j + 1
LINE_23 = ("LINE_23_AS_PRINTED = True", "LINE_23_AS_PRINTED = False")  # case-5-v2's reading: "match throughout"
FIX = {"case-5-v1-listing": COUNTER, "case-5-v2-listing": LINE_23, "case-5-directional-listing": COUNTER}
WAY = {"case-5-v1-listing": "failed", "case-5-v2-listing": "wrong-map", "case-5-directional-listing": "failed"}
PAW = {"0": ["1", "2", "3"], "1": ["0", "2"], "2": ["1", "0"], "3": ["0"]}  # entered from the pendant's free end
LOLLIPOPS = {  # v0 at the end of a path into a cyclic part: the count 1 (v0, the first new place) is never sensed again
    "lollipop-chord": {"0": ["1"], "1": ["0", "2"], "2": ["1", "3", "6"], "3": ["2", "4", "6"], "4": ["3", "5"],
                       "5": ["4", "6"], "6": ["5", "2", "3"]},
    "lollipop-k4": {"0": ["1"], "1": ["0", "2"], "2": ["1", "3", "4", "5"], "3": ["2", "4", "5"],
                    "4": ["3", "2", "5"], "5": ["4", "2", "3"]},
}


def test_the_clients_are_standalone():
    assert imported_modules(CLIENT) == {"json", "re", "sys", "collections"}  # the standard library only: nothing of topomark
    assert imported_modules(V2) == {"re", "sys", "client_case5_listing"}  # and Algorithm 6.4's client beside it


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("case5-client") / "suite"
    export(root, cases=[], algorithms=suite_algorithms([*VARIANT, *VARIANT.values()]))
    return root


def _client(tmp_path: Path, old: str = "", new: str = "", listing: str = "case-5-v1-listing") -> list[str]:
    if listing == "case-5-v2-listing":
        patched(CLIENT, tmp_path)  # the client Version-2 builds on, beside the copy
        return patched(V2, tmp_path, old, new)
    return patched(CLIENT, tmp_path, old, new)


def _lollipop(name: str):
    return world_from_json({"format": "topomark/world@1", "rotation": LOLLIPOPS[name],
                            "start": {"at": "0", "facing": "1"}})


def _paw():
    return world_from_json({"format": "topomark/world@1", "rotation": PAW, "start": {"at": "3", "facing": "0"}})


@pytest.mark.parametrize("listing", list(FLAGS))
def test_the_client_s_rows_are_the_listing_s_reference_rows(suite, tmp_path, listing):
    rows = run_algorithms(suite, _client(tmp_path, listing=listing) + FLAGS[listing], [listing])
    assert rows and all(r.passed for r in rows), [r.to_json() for r in rows if not r.passed]
    assert "correct" in {r.case["expected"] for r in rows}
    for row in rows:
        j = row.to_json()
        assert j["cost"] == j["reference"]["cost"] and j["difference"] is None
        assert j["reference"]["variant"]["follows"] == "the thesis's listing"
        assert (SHARED in j["message"]) == (row.case["expected"] == "failed")  # gave up where the listing fails
    if WAY[listing] == "failed":  # Algorithm 6.4's counter fails on most of the suite (the triangle first)
        assert "failed" in {r.case["expected"] for r in rows}


@pytest.mark.parametrize("listing", list(FLAGS))
def test_against_the_variant_every_fail_is_the_listing_s_own_failure(suite, tmp_path, listing):
    variant = VARIANT[listing]
    rows = run_algorithms(suite, _client(tmp_path, listing=listing) + FLAGS[listing], [variant])
    failed = [r for r in rows if not r.passed]
    assert failed and len(failed) < len(rows)  # the triangle fails (the listing's smallest failure), chain-6 maps
    for row in rows:
        j = row.to_json()
        reference = explore(load_world(suite / row.case["world"]), listing, options=row.case["options"])  # checked:
        # unchecked, Algorithm 6.5's line 23 would add known places again and again, never ending
        if row.passed:
            assert j["cost"] == j["reference"]["cost"] or row.reason == "difference"
        elif WAY[listing] == "failed":  # Algorithm 6.4's shared count, where topomark's literal run fails too
            assert SHARED in j["message"] and reference.outcome == "failed" and j["cost"] == reference.cost
        else:  # Algorithm 6.5 line 23: a wrong map, where topomark's literal run maps wrongly too
            assert not row.result.gave_up and "snapshot" in j["message"] and reference.outcome == "wrong-map"
    assert ("triangle" if WAY[listing] == "failed" else "lattice-2x3-markers-4") in {r.case["name"] for r in failed}
    copy = run_algorithms(suite, _client(tmp_path, *FIX[listing], listing=listing) + FLAGS[listing], [variant])
    assert copy and all(r.passed and r.to_json()["cost"] == r.to_json()["reference"]["cost"] for r in copy)


@pytest.mark.parametrize("listing", ["case-5-v1-listing", "case-5-directional-listing"])
@pytest.mark.parametrize("world_name", list(LOLLIPOPS))
def test_phase_two_costs_what_the_literal_entry_costs(tmp_path, listing, world_name):
    world = _lollipop(world_name)
    for markers in (4, 5):
        reference = explore(world, listing, options={"markers": markers})
        assert reference.outcome == "correct" and reference.explorer.phase_two_moves > 0  # hypotheses walked
        result = run_external(world, _client(tmp_path, listing=listing) + FLAGS[listing], version=2,
                              kit=Kit(vertex=markers, directional=listing != "case-5-v1-listing"))
        assert result.verdict == "pass" and result.cost == reference.cost, result.message


def test_seeded_fault_a_wrong_join_fails(tmp_path):
    wrong = _client(tmp_path, "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = list(far), list(e)",
                    "self.exits[e[0]][e[1]], self.exits[far[0]][far[1]] = "
                    "[far[0], (far[1] + 1) % len(self.exits[far[0]])], list(e)")
    result = run_external(_lollipop("lollipop-k4"), wrong, version=2, kit=Kit(vertex=4))
    assert result.verdict == "fail" and not result.gave_up


def test_seeded_fault_without_line_22_the_cost_is_not_the_listing_s(tmp_path):
    blind = _client(tmp_path, "if not DIRECTIONAL:  # line 22", "if False:  # line 22 left out")
    world = _lollipop("lollipop-k4")
    result = run_external(world, blind, version=2, kit=Kit(vertex=4))
    assert result.passed and result.cost < explore(world, "case-5-v1-listing", options={"markers": 4}).cost  # 19 < 22


def test_version_2_maps_the_paw_wrongly_with_four_markers_as_the_listing_does(tmp_path):
    """Algorithm 6.5 line 23 as printed confirms no hypothesis: with K = 4 phase II adds the triangle's first place
    again (topomark's ``wrong-map``); the client's map fails the same way, and read as "match throughout" it maps."""
    world, kit = _paw(), Kit(either=4)
    assert explore(world, "case-5-v2-listing", options={"markers": 4}).outcome == "wrong-map"
    result = run_external(world, _client(tmp_path, listing="case-5-v2-listing"), version=2, kit=kit)
    assert result.verdict == "fail" and not result.gave_up and "snapshot" in result.message
    fixed = run_external(world, _client(tmp_path, *LINE_23, listing="case-5-v2-listing"), version=2, kit=kit)
    assert fixed.passed and fixed.cost == explore(world, "case-5-v2", options={"markers": 4}).cost


def test_seeded_faults_in_version_2(suite, tmp_path):
    """A wrong join fails; a search that leaves out line 12's "has c + 1 marked edges" (every vertex of v_u's degree
    with an unexplored edge a candidate) maps the world at another cost than the listing's."""
    name = "case-5-v2-listing"
    wrong = _client(tmp_path, "                self.join(e, found)",
                    "                self.join(e, (found[0], (found[1] + 1) % self.degree(found[0])))", name)
    rows = run_algorithms(suite, wrong, ["case-5-v2-listing"], select="complete-4")
    assert rows and not any(r.passed for r in rows)
    world, kit = generate("complete", n=5), Kit(either=40)
    listing = explore(world, "case-5-v2-listing", options={"markers": 40}).cost
    assert run_external(world, _client(tmp_path, listing=name), version=2, kit=kit).cost == listing  # 22
    blind = _client(tmp_path, "self.degree(v) == degree and self.shown(v) == key}", "self.degree(v) == degree}",
                    name)
    result = run_external(world, blind, version=2, kit=kit)
    assert result.passed and result.cost != listing  # 27: candidates visited that cannot be v_u
