"""``topomark bench`` (issue 6): fixed-seed worlds, checked runs, resumable CSV, generated report."""

from __future__ import annotations

import builtins
import csv

import pytest

from topomark.reference.bench import experiments as bench, thesis_figures as tf
from topomark.reference.cli.main import main


def test_lattice_hole_sizes_are_the_thesis_sizes():
    for size in (72, 90, 108, 152):
        for seed in range(3):
            w = bench.world_for("lattice-hole", size, seed)
            assert w.n == size and w.start is not None
    w = bench.world_for("complete-hole", 24, 0)
    assert w.n == 24 and w.m == 276 - round(0.1 * 276)


def test_worlds_are_fixed_by_seed_and_shared_by_every_algorithm_of_a_row():
    a = bench.world_for("small-world-k4-p20", 40, 3)
    assert a == bench.world_for("small-world-k4-p20", 40, 3) and a.start == bench.world_for(
        "small-world-k4-p20", 40, 3).start
    assert a != bench.world_for("small-world-k4-p20", 40, 4)
    runs = bench.plan("table-4.1", graphs=4, sizes=[90])
    by_alg: dict[str, set] = {}
    for r in runs:
        by_alg.setdefault(r.algorithm, set()).add((r.family, r.size, r.seed))
    assert set(by_alg) == {"basic", "enh1", "enh2", "enh3"}
    assert len({frozenset(v) for v in by_alg.values()}) == 1 and len(by_alg["basic"]) == 4


@pytest.mark.slow
def test_a_kept_world_is_unchanged_by_every_algorithm_run_on_it():
    """world_for keeps its last worlds for the next runs of a sweep: no run may change one (rotation, markers,
    start), whatever it drops, lays or places as a lighthouse."""
    import copy
    import json
    from topomark.reference.algorithms.registry import algorithm_spec
    from topomark.reference.run.explore import check_run, explore
    from topomark.spec.errors import InvalidInput
    names = [a["name"] for a in json.loads(_algorithms_json()) if a["status"] != "not implementable from the thesis"]
    w = bench.world_for("complete-hole", 24, 1)
    before = (copy.deepcopy(w.rotation), w.markers, w.start, w.n, w.m)
    for name in names:
        options = {"cue-n": w.n} if name in ("model-tree", "model-tree-listing") else None
        try:
            check_run(w, algorithm_spec(name), options=options)
        except InvalidInput:  # an algorithm for a class of worlds (docs/adding-an-algorithm.md) refuses the rest
            continue
        explore(w, name, options=options, record=False)
        assert (w.rotation, w.markers, w.start, w.n, w.m) == before, name
    assert bench.world_for("complete-hole", 24, 1) is w and len(names) > 30


def _algorithms_json() -> str:
    import contextlib
    import io
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["algorithms", "--json"]) == 0
    return out.getvalue()


def test_plan_covers_every_table_and_caps_the_quartic_row():
    runs = bench.plan("tables", graphs=30, heavy_graphs=2, heavy_max_size=40)
    keys = {(r.family, r.algorithm) for r in runs}
    for fam, algs in tf.TABLE_SOURCES.values():
        assert {(fam, a) for a in algs} <= keys
    d2 = [r for r in runs if r.family == "complete-hole" and r.algorithm == "enh5-d2"]
    assert {r.seed for r in d2} == {0, 1} and {r.size for r in d2} == {24, 28, 32, 36, 40}
    assert len([r for r in runs if r.family == "lattice-hole" and r.algorithm == "enh5-d2"]) == 30 * 9
    # By default the heavy row still has a figure beside every column of Table 4.6.
    d2 = [r for r in bench.plan("table-4.6") if r.algorithm == "enh5-d2"]
    assert {r.size for r in d2} == set(tf.COMPLETE_HOLE_SIZES) and len({r.seed for r in d2}) > 1
    with pytest.raises(Exception):
        bench.plan("table-9.9")


def test_sweep_is_checked_resumable_and_reported(tmp_path):
    runs = bench.plan("table-4.3", graphs=2, sizes=[72])
    first = bench.run_sweep(runs, tmp_path, jobs=1, progress=False)
    assert first == {**first, "planned": 4, "ran": 4, "skipped": 0, "failures": 0}
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    assert len(rows) == 4 and all(r["verified"] == "True" and r["checked"] == "True" for r in rows)
    assert {r["algorithm"] for r in rows} == {"basic", "enh4"}
    enh4 = [r for r in rows if r["algorithm"] == "enh4"]
    assert all(int(r["expansion"]) > 0 for r in enh4)
    # A killed sweep restarted: finished keys are skipped, the missing one is redone.
    lines = (tmp_path / "runs.csv").read_text().splitlines(keepends=True)
    (tmp_path / "runs.csv").write_text("".join(lines[:-1]))
    (tmp_path / "runs.csv").write_text("".join(lines[:-1]) + lines[-1][:17])  # killed mid-line
    again = bench.run_sweep(runs, tmp_path, jobs=1, progress=False)
    assert again["ran"] == 1 and again["skipped"] == 3
    assert len(list(csv.DictReader((tmp_path / "runs.csv").open()))) == 4
    report = bench.write_report("table-4.3", tmp_path, plots=False).read_text()
    assert "| 72 | 72 |" in report and "36.5%" in report  # the thesis's Table 4.3 figure beside ours
    assert "## Table 4.3" in report and "not** verified: 0" in report
    assert "Runs in this experiment: 4;" in report
    assert report.count("bound (3.3) at every size: yes; at most") == 2  # basic and enh4, each size-72 row
    # Another experiment's runs in the same CSV (other policies) are not counted as this one's.
    bench.run_sweep(bench.plan("policies", graphs=1, sizes=[90]), tmp_path, jobs=1, progress=False)
    report = bench.write_report("table-4.3", tmp_path, plots=False).read_text()
    assert "Runs in this experiment: 5;" in report  # + the policies' nearest basic run on seed 0, a shared world
    policies = bench.write_report("policies", tmp_path, plots=False).read_text()
    assert "Runs in this experiment: 6;" in policies and "| 90 | basic | 1 |" in policies


def test_plots_are_skipped_without_matplotlib_but_csv_and_markdown_are_written(tmp_path, monkeypatch, capsys):
    real = builtins.__import__

    def no_matplotlib(name, *a, **k):
        if name.startswith("matplotlib"):
            raise ImportError("no matplotlib here")
        return real(name, *a, **k)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    code = main(["bench", "lattice-hole", "--graphs", "2", "--sizes", "72", "--out", str(tmp_path), "--jobs", "2",
                 "--quiet"])
    assert code == 0
    assert "plots skipped" in capsys.readouterr().out
    assert (tmp_path / "runs.csv").exists()
    assert "Plots: skipped" in (tmp_path / "lattice-hole.md").read_text()


def test_plots_are_drawn_when_matplotlib_is_there(tmp_path):
    rows = [{"experiment": "lattice-hole", "size": s, "seed": k, "algorithm": a, "policy": "nearest", "n": s,
             "m": 2 * s, "cost": c * (k + 1), "travel": 10, "new": 2 * s, "verified": True, "checked": True, "expansion": 0, "expression_3_3": 10 ** 6,
             "seconds": 0.1} for s in (72, 90) for k in range(2) for a, c in (("basic", 1000), ("enh1", 400))]
    with (tmp_path / "runs.csv").open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=bench.CSV_FIELDS)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in bench.CSV_FIELDS})
    text = bench.write_report("table-4.1", tmp_path).read_text()
    assert "| 90 | 90 | 180.0 | 2 | 2/2 | 1,500 ± 707 |" in text
    assert "60.0% / 67.5%" in text  # ours / Table 4.1's enh1 at size 72
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        assert "Plots: skipped" in text
    else:
        assert (tmp_path / "table-4.1-lattice-hole.png").stat().st_size > 0


def test_thesis_figures_are_transcribed_with_their_sources():
    assert tf.thesis_cost("lattice-hole", "basic", 260) == (152_000, "§4.1 Enhancement-1 text (Figure 4.2(a))")
    assert tf.thesis_reduction("lattice-hole", "enh3", 260)[0] == 90.4
    assert tf.thesis_reduction("complete-hole", "enh5-d2", 24) is None  # Table 4.6 starts at 28
    assert tf.thesis_reduction("complete-hole", "enh5-d2", 55) == (-2372, "Table 4.6")
    assert tf.thesis_reduction("complete-hole", "enh3+4", 55) == (92.8, "Table 4.8")


def test_bad_input_exits_2():
    assert main(["bench", "no-such-experiment"]) == 2
    assert main(["bench", "tables", "--graphs", "0"]) == 2


def test_a_sink_that_wants_only_op_records_gets_them_all_and_nothing_else():
    """A sink's ``events`` (tracesink): explore skips the move and iteration records it does not want, and the
    op records it gets are those of the whole trace; the bench's DropCount then counts the markers lying."""
    from topomark.reference.worlds import generators
    from topomark.reference.bench.runs import DropCount
    from topomark.reference.run.explore import explore
    from topomark.reference.trace.sink import ListSink

    class Ops(ListSink):
        events = frozenset({"op"})

    world = generators.complete_hole(7, 0.2, 1)
    full, some, count = ListSink(), Ops(), DropCount()
    for sink in (full, some, count):
        out = explore(world, "case-1a", sink=sink)
        assert out.outcome == "correct"
    kinds = {r["event"] for r in full.records}
    assert {"move", "op", "header", "end"} <= kinds
    assert some.records == [r for r in full.records if r["event"] in ("header", "op", "end")]
    assert count.markers == sum(r["count"] for r in full.records if r["event"] == "op") > 0


def test_the_report_kit_s_docstring_examples():
    """The shared statistics and formatting of every bench report, and the §6.2 reports' examples."""
    import doctest

    from topomark.reference.bench.reports import section62, section62_figures, stats, text
    for module in (stats, text, section62, section62_figures):
        assert doctest.testmod(module).failed == 0, module.__name__
