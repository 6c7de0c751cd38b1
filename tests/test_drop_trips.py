"""Drop trips: the traversals made only to carry markers to where they are dropped, and back — part of the cost,
counted apart (the accounting rule of ``reference/run/simulator.py``; §3.1.2, §6.2.1 Case 3b, Algorithm 6.6 line 10)."""

from __future__ import annotations

import csv
import json
import math

import pytest

from conftest import bare, make_world
from topomark.reference.bench import experiments as bench
from topomark.reference.bench.reports.stats import drop_trips, net_cost
from topomark.reference.bench.run_store import CSV_FIELDS, read_runs
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore

CHAIN = "chain:n=3"  # the smallest world with a non-loop edge to mark: v0 – v1 – v2


def test_case_3b_walks_back_over_e_to_drop_and_the_trip_is_in_the_cost_and_counted_apart():
    """Case 3b on a chain of 3: each of the 2 non-loop edges is marked by going back over it and back (§6.2.1 Case 3b):
    2 new edges + 4 drop-trip traversals = 6, every one of them a traversal the simulator counted."""
    out = explore(bare(make_world(CHAIN)), "case-3b")
    assert out.outcome == "correct"
    assert (out.cost, out.drop_trips, out.by_purpose) == (6, 4, {"drop": 4, "new": 2})
    moves = [r for r in out.trace if "purpose" in r]
    assert out.cost == len(moves) == sum(out.by_purpose.values())  # cost = every traversal, the trips included
    assert [r["purpose"] for r in moves] == ["new", "drop", "drop", "new", "drop", "drop"]
    assert out.cost - out.drop_trips == out.m  # without the trips: each edge once, as dropping at v_u would cost


@pytest.mark.parametrize("name", ["case-1a", "case-2", "case-3a", "case-dv-sum", "extension-1"])
def test_an_algorithm_that_drops_where_it_stands_makes_no_drop_trip(name):
    """In transit on e (§6.2.1 Case 1a, Algorithm 6.3 line 6) or at v_u (Algorithm 6.1 line 7, Algorithm 6.2 line 12,
    §6.2.2): markers dropped, no traversal made for them."""
    out = explore(bare(make_world(CHAIN)), name)
    assert out.outcome == "correct" and out.marker_operations["drop"] >= 1
    assert out.drop_trips == 0 and "drop" not in out.by_purpose and out.cost == out.m


def test_extension_2_drops_by_a_trip_only_where_v_k_has_no_marked_edge():
    """Algorithm 6.6 line 10: "goes back on e, drops i markers on e and back" — once on the chain (v1 then has
    a marked edge, so e = (v1, v2) stays blank)."""
    out = explore(bare(make_world(CHAIN)), "extension-2")
    assert (out.drop_trips, out.marker_operations["drop"], out.cost) == (2, 1, out.m + 2)


def test_explore_shows_the_drop_trips_in_text_and_json(capsys):
    assert main(["explore", CHAIN, "--algorithm", "case-3b"]) == 0
    text = capsys.readouterr().out
    assert "drop trips (in the cost)" in text and "4 (cost without them: 2, 1.00 m)" in text
    assert main(["explore", CHAIN, "--algorithm", "case-3b", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["cost"], data["drop_trips"], data["by_purpose"]["drop"]) == (6, 4, 4)
    assert main(["explore", CHAIN, "--algorithm", "case-2", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["drop_trips"] == 0


def test_a_runs_csv_without_the_drop_trips_column_loads_and_reports_them_as_not_measured(tmp_path):
    row = bench.run_one(bench.Run("lattice-hole", 72, 0, "case-3b"))
    assert row["drop_trips"] == 2 * (row["n"] - 1) and row["drop_trips"] < row["cost"]
    old = [f for f in CSV_FIELDS if f != "drop_trips"]
    with (tmp_path / "runs.csv").open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=old, extrasaction="ignore")
        writer.writeheader()
        writer.writerow(row)
    read = read_runs(tmp_path / "runs.csv", note=None)
    assert read.needs_rewrite and len(read.rows) == 1 and "drop_trips" not in read.rows[0]
    assert math.isnan(drop_trips(read.rows[0])) and math.isnan(net_cost(read.rows[0]))  # never read as 0
    assert main(["bench", "table-6.1", "--graphs", "1", "--sizes", "72", "--out", str(tmp_path), "--quiet",
                 "--no-plots", "--report-only"]) == 0
    report = (tmp_path / "table-6.1.md").read_text()
    assert "| drop trips mean |" in report and "not measured" in report


def test_the_section_62_reports_show_the_drop_trips_and_compare_costs_without_them(tmp_path):
    code = main(["bench", "table-6.2", "--graphs", "1", "--sizes", "72", "--out", str(tmp_path), "--jobs", "1",
                 "--quiet", "--no-plots"])
    assert code == 0
    rows = {r["algorithm"]: r for r in read_runs(tmp_path / "runs.csv", note=None).rows}
    b3, e1 = rows["case-3b"], rows["extension-1"]
    assert int(b3["drop_trips"]) == 2 * (int(b3["n"]) - 1) and e1["drop_trips"] == "0"
    report = (tmp_path / "table-6.2.md").read_text()
    assert "| cost/m | drop trips mean | cost/m without drop trips |" in report
    assert "| 72 | `case-3b` | 1 | 1 |" in report and f"| {int(b3['drop_trips']):,.1f} |" in report
    assert "Costs below are compared without drop trips" in report and "ratio without drop trips" in report
    net = (int(b3["cost"]) - int(b3["drop_trips"])) / int(b3["m"])
    assert f"| lattice-hole | `case-3b` | 72 | 1 | {int(b3['cost']) / int(b3['m']):.3f} |" in report
    assert f"| {net:.2f} |" in report
