"""``topomark bench table-6.1`` / ``table-6.2`` / ``figure-6.13`` (issue 12): kit algorithms in the bench, checked,
their markers counted, and the reports with the thesis's rows and whether each claim held."""

from __future__ import annotations

import csv

import pytest

from topomark.reference.bench import experiments as bench, plan as bench_plan
from topomark.reference.bench.reports.section62_figures import marked_places
from topomark.reference.bench.reports.section62 import CLAIMS
from topomark.reference.bench.reports.stats import slope
from topomark.reference.cli.main import main
from topomark.reference.explorers.counted_markers import sum_to
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.bench.run_store import read_runs
from topomark.spec.errors import InvalidInput

# runs.csv's columns before the kit algorithms' columns existed (and before the lighthouse column)
OLD_FIELDS = ("experiment", "size", "seed", "algorithm", "policy", "n", "m", "cost", "cost_per_m", "verified", "checked",
              "travel", "new", "validation", "retrace", "expansion", "hypotheses", "pruned", "rejected_without_motion",
              "overlap_saved", "recorded", "upper_bound", "expression_3_3", "seconds", "cpu_seconds", "error")


def _sweep(tmp_path, experiment: str, *sizes: str) -> tuple[int, list[dict], str]:
    code = main(["bench", experiment, "--graphs", "1", "--sizes", *sizes, "--out", str(tmp_path), "--jobs", "1",
                 "--quiet", "--no-plots"])
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    return code, rows, (tmp_path / f"{experiment}.md").read_text()


def _check_rows(rows: list[dict], algorithms: tuple[str, ...], families: set[str]) -> None:
    """Every algorithm ran once per family, checked; a deterministic one mapped its world within its marker bound."""
    assert {(r["experiment"], r["algorithm"]) for r in rows} == {(f, a) for f in families for a in algorithms}
    for r in rows:
        assert r["checked"] == "True" and r["lighthouse"] == bench_plan.NO_LIGHTHOUSE and r["options"] == ""
        assert int(r["markers_used"]) >= 1 and int(r["marker_bound"]) >= 1 and int(r["d_max"]) >= 2
        if algorithm_spec(r["algorithm"]).deterministic:
            assert (r["outcome"], r["verified"]) == ("correct", "True"), r
            assert int(r["markers_used"]) <= int(r["marker_bound"]), r
            assert int(r["new"]) == int(r["m"])  # every edge is new exactly once


def _check_phase_two(rows: list[dict], algorithms: tuple[str, ...], families: set[str], report: str) -> None:
    """Case 5 with K = 4, 6, 10: every world mapped correctly, checked, with phase II's traversals > 0, reported."""
    few = [r for r in rows if r["options"] in bench_plan.CASE_5_K]
    assert {(r["experiment"], r["algorithm"], r["options"]) for r in few} == \
        {(f, a, k) for f in families for a in algorithms for k in bench_plan.CASE_5_K}
    for r in few:
        assert (r["checked"], r["outcome"], r["verified"]) == ("True", "correct", "True"), r
        assert 0 < int(r["phase_two"]) < int(r["cost"]) and int(r["markers_used"]) <= int(r["options"][8:])
    assert "## Case 5 with few markers: phase II's share of the cost" in report
    assert "Every world mapped correctly: **yes**; phase II tested hypotheses on every world larger than K: **yes**" \
        in report
    for r in few:
        assert f"| {r['experiment']} | `{r['algorithm']}` | {r['options'][8:]} | {r['size']} | 1 | 1/1 |" in report


def test_table_61_tiny_sweep_runs_every_undirected_algorithm_checked_and_reports_each_claim(tmp_path):
    code, every, report = _sweep(tmp_path, "table-6.1", "72", "24")
    rows = [r for r in every if r["options"] == ""]
    _check_rows(rows, bench_plan.TABLE_61_ALGS, {"lattice-hole", "complete-hole"})
    _check_phase_two(every, ("case-5-v1", "case-5-v2", "case-5-edge"), {"lattice-hole", "complete-hole"}, report)
    wrong = [r for r in rows if r["verified"] != "True"]
    assert all(r["algorithm"] == "case-0" for r in wrong) and code == 0  # Case 0 fails as §6.2.1 expects
    assert "| ≤ thesis count? |" in report and "| cost held? |" in report
    for a in bench_plan.TABLE_61_ALGS:
        assert f"| `{a}` {CLAIMS[a].row}" in report or a == "case-0"
        for fam in ("lattice-hole", "complete-hole"):
            assert f"| {fam} | `{a}` |" in report
    by = {(r["experiment"], r["algorithm"]): r for r in rows}
    r = by[("lattice-hole", "case-3b")]
    assert int(r["markers_used"]) == sum_to(int(r["n"]) - 1)  # Case 3b marks every new place with k markers
    assert f"| lattice-hole | `case-3b` | 72 | 1 | {int(r['cost']) / int(r['m']):.3f} |" in report  # the O(m) breakdown
    assert "## Figure 6.11 (lattice-hole)" in report and "### Figure 6.12 (lattice-hole)" in report
    assert "\"more than 50% reductions on marker usage" in report and "**held**" in report


def test_table_62_tiny_sweep_runs_the_directional_algorithms_and_the_extensions_marker_savings(tmp_path):
    code, every, report = _sweep(tmp_path, "table-6.2", "72")
    rows = [r for r in every if r["options"] == ""]
    _check_rows(rows, bench_plan.TABLE_62_ALGS, {"lattice-hole"})
    _check_phase_two(every, ("case-5-directional",), {"lattice-hole"}, report)
    assert code == 0
    by = {r["algorithm"]: r for r in rows}
    assert int(by["extension-2"]["markers_used"]) < int(by["extension-1"]["markers_used"]) \
        < int(by["case-3b"]["markers_used"])  # Figure 6.18's ordering, on this world
    for a in ("case-dv-sum", "extension-1", "extension-2"):
        assert f"| `{a}` {CLAIMS[a].row}" in report and f"| lattice-hole | `{a}` | O(m) | 1 | 1/1 |" in report
    assert "### Figure 6.18 (lattice-hole)" in report and "edgeINFO" in report
    assert "Lattice-hole worlds above 3m (the target: none at the Chapter 4 sizes): **" in report


def test_figure_613_gives_version_1_the_markers_that_mark_each_fraction_of_places(tmp_path):
    code, rows, report = _sweep(tmp_path, "figure-6.13", "72")
    assert code == 0 and all(r["verified"] == "True" for r in rows)
    v1 = {r["options"]: r for r in rows if r["algorithm"] == "case-5-v1"}
    assert set(v1) == {f"marked-fraction={f}" for f in bench_plan.FRACTIONS}
    n = int(rows[0]["n"])
    for f in bench_plan.FRACTIONS:
        places = max(2, int(float(f) * n))  # K = max(4, Σ^{⌊f·n⌋}): the least kit marks 2 places
        assert marked_places(int(v1[f"marked-fraction={f}"]["markers_used"])) == places
    v2 = {r["options"]: r for r in rows if r["algorithm"] == "case-5-v2"}
    assert set(v2) == set(v1)
    for f in bench_plan.FRACTIONS:  # K = max(4, ⌊f·n⌋ + 3), 100%: m + 4; never more used than K
        k = int(rows[0]["m"]) + 4 if f == "1" else max(4, int(float(f) * n) + 3)
        assert int(v2[f"marked-fraction={f}"]["markers_used"]) <= k
    assert int(v2["marked-fraction=0"]["cost"]) > int(v2["marked-fraction=1"]["cost"])
    assert {r["algorithm"] for r in rows} == {"case-5-v1", "case-5-v2", "basic", "case-3a", "case-1b"}
    assert "## Figure 6.13 (lattice-hole)" in report and "| 72 |" in report
    assert "## Figure 6.13 for Version-2 (lattice-hole)" in report
    assert report.count("* Thesis:") == 3


def test_option_sets_resolve_against_the_world_and_bad_ones_are_bad_input():
    world = bench_plan.world_for("lattice-hole", 72, 0)
    assert bench_plan.resolve_options("marked-fraction=0.5", world, "case-5-v1") == {"markers": sum_to(36)}
    assert bench_plan.resolve_options("markers=7", world, "case-3b") == {"markers": "7"}
    assert bench_plan.resolve_options("", world, "case-3b") == {}
    assert bench_plan.resolve_options("marked-fraction=0.5", world, "case-5-v2") == {"markers": world.n // 2 + 3}
    assert bench_plan.resolve_options("marked-fraction=1", world, "case-5-v2") == {"markers": world.m + 4}
    with pytest.raises(InvalidInput):
        bench_plan.resolve_options("marked-fraction=0.5", world, "case-3a")
    with pytest.raises(InvalidInput):
        bench_plan.option_set("markers")
    assert bench_plan.Run("lattice-hole", 72, 0, "case-5-v1", options="marked-fraction=1").key[-1] == \
        "marked-fraction=1"
    assert slope([(1, 2), (2, 4)]) == 1.0 and slope([(1, 2)]) is None


def test_an_old_runs_csv_still_reads_resumes_and_reports(tmp_path):
    row = bench.run_one(bench.Run("lattice-hole", 72, 0, "basic"))
    with (tmp_path / "runs.csv").open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=OLD_FIELDS, extrasaction="ignore")
        writer.writeheader()
        writer.writerow(row)
    read = read_runs(tmp_path / "runs.csv", note=None)
    assert read.needs_rewrite and read.rows[0]["options"] == "" and read.rows[0]["lighthouse"] == "directional-vertex"
    assert main(["bench", "lattice-hole", "--graphs", "1", "--sizes", "72", "--out", str(tmp_path), "--quiet",
                 "--no-plots"]) == 0
    rows = read_runs(tmp_path / "runs.csv", note=None).rows
    assert len(rows) == 1 and rows[0]["cost"] == str(row["cost"])  # the old run was not done again
    assert main(["bench", "table-6.1", "--graphs", "1", "--sizes", "72", "--out", str(tmp_path), "--quiet",
                 "--no-plots", "--report-only"]) == 0
    assert "Runs in this experiment: 0" in (tmp_path / "table-6.1.md").read_text()
