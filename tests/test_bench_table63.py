"""``topomark bench table-6.3`` / ``figure-6.24`` / ``comparison`` (issue 13): the thread classes, explore-explore
against l and every marker on the same worlds, checked, and the reports with the thesis's statements and whether each
held."""

from __future__ import annotations

import csv

from topomark.reference.bench import plan as bench_plan

from topomark.reference.bench.reports import section63 as b63
from topomark.reference.bench.plan import NO_LIGHTHOUSE, Experiment, Part
from topomark.reference.cli.main import main
from topomark.reference.bench.run_store import CSV_FIELDS


def _sweep(tmp_path, experiment: str, *sizes: str) -> tuple[int, list[dict], str]:
    code = main(["bench", experiment, "--graphs", "1", "--sizes", *sizes, "--out", str(tmp_path), "--jobs", "1",
                 "--quiet", "--no-plots"])
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    return code, rows, (tmp_path / f"{experiment}.md").read_text()


def test_table_63_tiny_sweep_runs_every_thread_class_checked_and_reports_table_63_beside_ours(tmp_path):
    code, rows, report = _sweep(tmp_path, "table-6.3", "90")
    assert code == 0
    got = {(r["experiment"], r["algorithm"], r["lighthouse"], r["options"]) for r in rows}
    want = {(f, c.algorithm, c.lighthouse, c.options) for f in ("lattice", b63.EDGE_HOLE) for c in b63.CLASSES}
    assert got == want  # the fixed ε thread is Algorithm 3.1 with the thread lighthouse; l = 8 for explore-explore
    assert all(r["checked"] == "True" and r["verified"] == "True" and r["outcome"] == "correct" for r in rows)
    edge_hole = [r for r in rows if r["experiment"] == b63.EDGE_HOLE]
    assert {int(r["n"]) for r in edge_hole} == {100} and all(int(r["m"]) < 180 for r in edge_hole)  # 10% edges gone
    assert b63.TABLE_63 in report and "| a very long thread l ≫ m | no | O(m) |" in report
    for c in b63.CLASSES:
        assert f"| 90 | 100 | 180.0 | {c.name} | O({c.bound}) | 1/1 |" in report  # the homogeneous 10x10 lattice
    knots = [r for r in rows if r["algorithm"] == "thread-knots"]
    assert "## l ≫ m with knots under 3m" in report and f"{len(knots)} worlds mapped by thread-knots" in report
    assert all(int(r["cost"]) < 3 * int(r["m"]) for r in knots) and "worlds at or above 3m: 0 — held." in report
    assert "| \"a very long thread (with knots) … provides the lowest cost over all the thread classes considered\" |" \
           " yes |" in report


def test_comparison_tiny_sweep_puts_movable_and_immovable_markers_and_threads_on_the_same_worlds(tmp_path):
    code, rows, report = _sweep(tmp_path, "comparison", "90")
    assert code == 0 and {r["algorithm"] for r in rows} == set(b63.COMPARED)
    assert len({(r["n"], r["m"]) for r in rows}) == 1  # one world for all
    assert all(r["verified"] == "True" for r in rows)
    by = {r["algorithm"]: int(r["cost"]) for r in rows}
    for a in b63.COMPARED:
        assert f"| {a} | 1/1 | {by[a]:,} ± 0 |" in report
    for mv in b63.MOVABLE:
        for im in b63.IMMOVABLE:
            wins = int(by[mv] < by[im])
            assert f"| 90 | {mv} | {im} | {by[mv] / by[im]:.2f} | {wins}/1 |" in report


def test_figure_624_tiny_sweep_reports_cost_against_l_and_the_l_at_least_n_case(tmp_path, monkeypatch):
    lengths = (1, 4, 128)  # 128 >= n = 100: explore-explore acts as Algorithm 6.7
    monkeypatch.setattr(b63, "FIGURE_624_SIZE", 90)
    monkeypatch.setattr(b63, "LENGTHS", lengths)
    monkeypatch.setitem(bench_plan.EXPERIMENTS, "figure-6.24", Experiment("figure-6.24", (
        Part(b63.EDGE_HOLE, ("thread-explore",), (90,), options=tuple(f"thread-length={n}" for n in lengths)),
        Part(b63.EDGE_HOLE, ("thread-circumference", "thread-knots"), (90,))), "Figure 6.24 (tiny)"))
    code, rows, report = _sweep(tmp_path, "figure-6.24", "90")
    assert code == 0 and len(rows) == 5 and all(r["verified"] == "True" for r in rows)
    cost = {(r["algorithm"], r["options"]): int(r["cost"]) for r in rows}
    for n in lengths:
        assert f"| {n} | 1/1 | {cost[('thread-explore', f'thread-length={n}')]:,} ± 0 |" in report
    same = cost[("thread-explore", "thread-length=128")] == cost[("thread-circumference", "")]
    assert ("equals Algorithm 6.7's on 1 of 1 worlds — held." in report) == same
    assert "\"cost reduction as l increases\"" in report


def _row(**kw) -> dict:
    base = {"experiment": b63.EDGE_HOLE, "size": "360", "seed": "0", "policy": "nearest", "lighthouse": NO_LIGHTHOUSE,
            "options": "", "n": "400", "m": "684", "checked": "True", "verified": "True", "outcome": "correct"}
    return {**base, **kw}


def test_the_reports_say_not_held_when_the_numbers_contradict_the_thesis(tmp_path):
    """Synthetic runs: a knots run above 3m is listed, a cost rising with l and a fixed ε thread cheaper than the
    carried one are reported as not held."""
    rows = [_row(algorithm="thread-knots", cost="2500", new="684", retrace="700", validation="0", other="1116")]
    rows += [_row(algorithm="thread-explore", options=f"thread-length={n}", cost=str(1000 + n)) for n in b63.LENGTHS]
    rows += [_row(algorithm="basic", lighthouse="thread", cost="100"), _row(algorithm="thread-carried", cost="200")]
    with (tmp_path / "runs.csv").open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_FIELDS, restval="")
        w.writeheader()
        w.writerows(rows)
    fig = b63.write_report("figure-6.24", tmp_path, plots=False).read_text()
    assert "— **not held**." in fig and f"rises from one l to the next {len(b63.LENGTHS) - 1} time(s)" in fig
    table = b63.write_report("table-6.3", tmp_path, plots=False).read_text()
    assert "worlds at or above 3m: 1." in table and f"* {b63.EDGE_HOLE} size 360 seed 0: cost 2500, m 684 (3.65m)" in table
    lattice, edge_hole = [line for line in table.splitlines() if line.startswith("| \"carrying the short")]
    assert lattice.endswith("| — | — | — |") and edge_hole.endswith("| — | — | **no** |")  # runs at 360 only
