"""``topomark bench lighthouses`` (issue 10): every lighthouse side by side, checked, in the CSV and the report."""

from __future__ import annotations

import csv

from topomark.reference.bench import experiments as bench, plan as bench_plan
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.bench.reports.lighthouses import SHORT
from topomark.reference.bench.plan import CERTAIN_LIGHTHOUSES as LIGHTHOUSES
from topomark.reference.explorers.lighthouses import LIGHTHOUSES as ALL
from topomark.reference.bench.run_store import CSV_FIELDS, read_runs

OLD_FIELDS = [f for f in CSV_FIELDS if f != "lighthouse"]  # runs.csv as written before the column existed


def _unverified(rows: list[dict]) -> list[dict]:
    """The runs whose map was not verified: none (the marker-less lighthouses of §5.2.1 are not compared)."""
    wrong = [r for r in rows if r["verified"] != "True"]
    assert not wrong, wrong
    return wrong


def test_the_comparison_leaves_out_only_the_marker_less_lighthouses():
    assert set(ALL) - set(LIGHTHOUSES) == {"local-pair", "local-degree-list"}


def test_a_tiny_sweep_runs_every_lighthouse_checked_and_reports_them_side_by_side(tmp_path):
    code = main(["bench", "lighthouses", "--graphs", "1", "--sizes", "72", "--out", str(tmp_path), "--jobs", "1",
                 "--quiet", "--no-plots"])
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    wrong = _unverified(rows)  # §5.2.1's marker-less lighthouses may map wrong; no other may
    assert code == (1 if wrong else 0)
    assert {(r["lighthouse"], r["algorithm"]) for r in rows} == {(lh, a) for lh in LIGHTHOUSES for a in
                                                                 ("basic", "enh3")}
    assert len(rows) == 2 * len(LIGHTHOUSES) and all(r["checked"] == "True" and r["size"] == "72" for r in rows)
    assert len({(r["n"], r["m"]) for r in rows}) == 1  # one world, explored with every lighthouse
    cost = {(r["lighthouse"], r["algorithm"]): int(r["cost"]) for r in rows}
    report = (tmp_path / "lighthouses.md").read_text()
    assert f"Checked runs whose map was **not** verified: {len(wrong)}." in report
    assert "| size | algorithm | worlds | verified | dir. vertex | dir. edge | vertex + edge | 3 undirected edge |" \
           in report and all(SHORT[lh] in report for lh in LIGHTHOUSES)
    basic = [cost[(lh, "basic")] for lh in LIGHTHOUSES]
    ratios = " | ".join(f"{c / basic[0]:.4f}" for c in basic[1:])
    k = len(LIGHTHOUSES)
    ok = k - sum(r["algorithm"] == "basic" for r in wrong)
    assert f"| 72 | basic | 1 | {ok}/{k} | {basic[0]:,} ± 0 | {basic[1]:,} ± 0 |" in report and ratios in report
    assert "§6.1" in report and "§6.2" in report and "never compares their costs" in report
    trips = {r["lighthouse"]: int(r["drop_trips"]) for r in rows if r["algorithm"] == "basic"}
    assert trips["three-undirected-vertex"] == 2 and trips["directional-vertex"] == 0  # Figure 3.21(b)'s walk
    assert "Mean drop trips per run (" in report and f"{SHORT['three-undirected-vertex']} 2.0" in report
    # The directional-vertex rows are the lattice-hole experiment's runs: that report shows them, only them.
    assert main(["bench", "lattice-hole", "--graphs", "1", "--sizes", "72", "--out", str(tmp_path), "--quiet",
                 "--no-plots", "--report-only"]) == 0
    assert f"| 72 | 72 | {rows[0]['m']}.0 | 1 | 1/1 | {cost[('directional-vertex', 'basic')]:,} ± 0 |" in (
        tmp_path / "lattice-hole.md").read_text()


def test_an_old_runs_csv_without_the_lighthouse_column_still_reads_and_resumes(tmp_path):
    run = bench.Run("lattice-hole", 72, 0, "basic")
    row = bench.run_one(run)
    with (tmp_path / "runs.csv").open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=OLD_FIELDS, extrasaction="ignore")
        writer.writeheader()
        writer.writerow(row)
    read = read_runs(tmp_path / "runs.csv", note=None)
    assert read.rows[0]["lighthouse"] == "directional-vertex" and read.needs_rewrite
    assert "| 72 | 72 |" in bench.write_report("lattice-hole", tmp_path, plots=False).read_text()
    # A sweep over the old file: the old row is that run (skipped), the file gets the new column, rows align.
    done = bench.run_sweep(bench.plan("lighthouses", graphs=1, sizes=[72]), tmp_path, jobs=1, progress=False)
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    assert done["skipped"] == 1 and done["ran"] == 2 * len(LIGHTHOUSES) - 1
    assert done["failures"] == len(_unverified(rows))
    assert list(rows[0]) == list(CSV_FIELDS) and len(rows) == 2 * len(LIGHTHOUSES)
    assert [r["cost"] for r in rows if r["lighthouse"] == "directional-vertex" and r["algorithm"] == "basic"] == [
        str(row["cost"])]


def test_a_start_of_degree_one_is_skipped_for_three_undirected_edge_and_the_report_counts_it(tmp_path, monkeypatch):
    # random-20 worlds at n = 15 have degree-1 vertices; seeds 2, 4 and 6 of the first 8 draw one as the start.
    exp = bench_plan.Experiment("lighthouses", (bench_plan.Part("random-20", ("basic",), (15,),
                                                                lighthouses=tuple(LIGHTHOUSES)),), "test")
    monkeypatch.setitem(bench_plan.EXPERIMENTS, "lighthouses", exp)
    runs = bench.plan("lighthouses", graphs=8)
    low = {s for s in range(8) if (lambda w: w.degree(w.start_state()[0]))(bench.world_for("random-20", 15, s)) < 2}
    assert low == {2, 4, 6}
    three = {r.seed for r in runs if r.lighthouse == "three-undirected-edge"}
    fitting = {lh: 8 if ALL[lh].min_degree <= 1 else 5 for lh in LIGHTHOUSES}
    assert three == set(range(8)) - low and len(runs) == sum(fitting.values())
    failures = bench.run_sweep(runs, tmp_path, jobs=1, progress=False)["failures"]
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    assert failures == len(_unverified(rows))
    report = bench.write_report("lighthouses", tmp_path, plots=False).read_text()
    assert "worlds skipped because the start drawn from their seed has a smaller degree: 3 (" in report
    k = len(LIGHTHOUSES)
    ok = 5 * k - sum(int(r["seed"]) not in low for r in _unverified(rows))
    assert f"| 15 | basic | 5 | {ok}/{5 * k} |" in report  # the means are over the 5 worlds every lighthouse ran


def _w0_hypotheses(world, lighthouse):
    """Hypotheses in loop closures at the vertices across v0's marked exits, and hypotheses naming them elsewhere."""
    out = explore(world, "basic", record=True, lighthouse=lighthouse)
    its = [t for t in out.trace if t["event"] == "iteration"]
    across = {it["edge"][1]: it["joined"][1][0] for it in its if it["augmentation"] == "non-loop" and it["edge"][0] == 0}
    marked = {across[0], across[1]} if lighthouse == "three-undirected-edge" else {across[0]}
    closures = [it for it in its if it["augmentation"] != "non-loop" and it["joined"][1][0] in marked]
    elsewhere = sum(h["dart"][0] in marked for it in its if it not in closures for h in it["hypotheses"])
    return out, len(closures), sum(len(it["hypotheses"]) for it in closures), elsewhere


def test_an_edge_marker_lighthouse_saves_exactly_the_hypotheses_about_the_marked_neighbour():
    for family, size in (("lattice-hole", 72), ("complete-hole", 24)):
        world = bench.world_for(family, size, 0)
        base, closures, at, elsewhere = _w0_hypotheses(world, "directional-vertex")
        edge, e_closures, e_at, e_elsewhere = _w0_hypotheses(world, "directional-edge")
        assert closures == e_closures >= 1 and at > closures and elsewhere > 0
        assert e_at == e_closures and e_elsewhere == 0  # w0 recognised by its marker alone, never hypothesised
        assert base.hypotheses - edge.hypotheses == (at - closures) + elsewhere
        assert base.cost > edge.cost and base.by_purpose["validation"] > edge.by_purpose["validation"]
        for purpose in ("travel", "new"):
            assert base.by_purpose[purpose] == edge.by_purpose[purpose]
        same = explore(world, "basic", record=False, lighthouse="vertex-and-edge")
        assert (same.cost, same.hypotheses) == (edge.cost, edge.hypotheses)
