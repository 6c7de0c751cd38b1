"""``topomark bench comparison-markers``: the thesis's marker algorithms beside Table 2.3's classic baselines (the
footprints model, the labelled graph) on lattice-hole and complete-hole worlds, checked, and the report's table of
cost, cost/m and markers per vertex rendered from a tiny sweep."""

from __future__ import annotations

import csv

from topomark.reference.bench.plan_marker_classes import BASELINES, COMPARED, NAME
from topomark.reference.cli.main import main


def test_a_tiny_sweep_runs_every_algorithm_on_the_same_worlds_and_reports_each(tmp_path):
    code = main(["bench", NAME, "--graphs", "1", "--sizes", "90", "24", "--out", str(tmp_path), "--jobs", "1",
                 "--quiet", "--no-plots"])
    assert code == 0
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    assert {(r["experiment"], r["algorithm"]) for r in rows} == {(f, a) for f in ("lattice-hole", "complete-hole")
                                                                  for a in COMPARED}
    assert all(r["checked"] == "True" and r["verified"] == "True" and r["outcome"] == "correct" for r in rows)
    for family in ("lattice-hole", "complete-hole"):
        assert len({(r["n"], r["m"]) for r in rows if r["experiment"] == family}) == 1  # one world for all
    report = (tmp_path / f"{NAME}.md").read_text()
    for r in rows:
        n, m, cost = int(r["n"]), int(r["m"]), int(r["cost"])
        assert f"| {r['size']} | {n} | {m}.0 | {r['algorithm']} | 1/1 | {cost:,} ± 0 | {cost / m:.2f} |" in report
    for r in rows:  # the baselines drop their whole kit: m + n footprints, n(n + 1)/2 label markers
        n, m = int(r["n"]), int(r["m"])
        if r["algorithm"] == "footprints":
            assert int(r["markers_used"]) == n + m
        if r["algorithm"] == "labelled-dfs":
            assert int(r["markers_used"]) == n * (n + 1) // 2 and int(r["cost"]) <= 2 * m
            cost = int(r["cost"])
            assert f"| labelled-dfs | 1/1 | {cost:,} ± 0 | {cost / m:.2f} | {(n + 1) / 2:.2f} | {(n + 1) / 2:.2f} |" \
                in report
    for a in BASELINES:
        assert f"| {a} (baseline) |" in report
