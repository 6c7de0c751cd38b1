"""``topomark bench chapter-5`` (issue 11 item 7): its plan, a tiny sweep through the run store, and the report.

The sweep runs a handful of the experiment's runs (one small world each) plus
a model-tree run with a tiny cap, writes ``runs.csv`` and ``chapter-5.md``,
and the report's rows are read back: the thesis's statement beside ours and
whether it held.
"""

from __future__ import annotations

import csv

import pytest

from topomark.reference.bench import experiments as bench
from topomark.reference.bench.reports.chapter5 import figure_3_4, write_report
from topomark.reference.bench.plan import (CHAPTER_5_FAMILIES, EXPERIMENTS, FAMILIES, SEARCHED,
                                           UNCUED_MODEL_TREE_GRAPHS, Run, plan, resolve_options, world_for)
from topomark.spec.errors import InvalidInput

MT = ("model-tree", "nearest", "none")


def test_the_plan_covers_the_chapter_3_families_the_small_worlds_and_figure_3_4():
    runs = plan("chapter-5", graphs=2)
    assert "chapter-5" in EXPERIMENTS and "chapter-5" not in [p.family for p in EXPERIMENTS["all"].parts]
    for fam in CHAPTER_5_FAMILIES:  # every Chapter 3 size, every lighthouse, two worlds each
        got = {(r.size, r.lighthouse, r.seed) for r in runs if r.family == fam and r.options == ""}
        assert got == {(s, lh, k) for s in FAMILIES[fam].sizes for lh in SEARCHED for k in (0, 1)}
        walks = {(r.lighthouse, r.options) for r in runs if r.family == fam and r.options}
        assert walks == {(lh, f"seed={k}") for lh in ("local-pair", "local-degree-list") for k in (1, 2)}
    model = {(r.family, r.size) for r in runs if r.algorithm == "model-tree"}
    assert {s for f, s in model if f == "small-random-40"} == {6, 8, 10, 12}
    assert max(world_for("small-lattice-hole", s, 0).n for f, s in model if f == "small-lattice-hole") <= 25
    assert world_for("figure-3.4a", 5, 3).markers == ()  # the wheel's marker is stripped


def test_uncued_model_tree_runs_take_at_most_their_part_s_worlds_per_size():
    """Uncued Algorithm 5.1 always ends at a cap (~200 CPU-s on a 6-cycle): Part.graphs caps its worlds a size,
    while the cued runs and every other part get the --graphs asked for."""
    runs = plan("chapter-5", graphs=7)
    for fam in ("small-lattice-hole", "small-random-40"):
        for size in FAMILIES[fam].sizes:
            seeds = {o: {r.seed for r in runs if r.family == fam and r.size == size and r.options == o}
                     for o in ("cue=n", "max-models=1000")}
            assert seeds == {"cue=n": set(range(7)), "max-models=1000": set(range(UNCUED_MODEL_TREE_GRAPHS))}
    assert UNCUED_MODEL_TREE_GRAPHS < 7 and len({r.seed for r in runs if r.family == "lattice-hole"}) == 7
    assert {r.seed for r in plan("chapter-5", graphs=2) if r.options == "max-models=1000"} == {0, 1}


def test_the_cue_option_gives_the_true_count_and_only_to_the_model_tree():
    world = world_for("small-random-40", 8, 0)
    assert resolve_options("cue=n", world, "model-tree") == {"cue-n": world.n}
    assert resolve_options("cue=m,window=5", world, "model-tree") == {"cue-m": world.m, "window": "5"}
    with pytest.raises(InvalidInput, match="model-tree only"):
        resolve_options("cue=n", world, "basic")


def test_a_tiny_sweep_records_the_walk_and_the_models_and_the_report_compares(tmp_path):
    runs = [Run("lattice-hole", 72, 0, "basic", lighthouse=lh) for lh in SEARCHED]
    runs += [Run("random-20", 15, 0, "basic", lighthouse="local-degree-list", options=o) for o in ("", "seed=1")]
    runs += [Run("small-random-40", 6, 0, *MT, "cue=n"), Run("small-random-40", 6, 0, *MT, "max-models=20"),
             Run("figure-3.4a", 5, 0, *MT, "cue=n")]
    result = bench.run_sweep(runs, tmp_path, jobs=1, progress=False)
    assert result["ran"] == len(runs)
    with open(tmp_path / "runs.csv", newline="") as fh:
        rows = {(r["experiment"], r["lighthouse"], r["options"]): r for r in csv.DictReader(fh)}
    walk = rows[("lattice-hole", "undirected-vertex", "")]
    assert walk["outcome"] == "correct" and walk["walk_steps"].isdigit() and walk["lighthouse_at"]
    assert rows[("lattice-hole", "directional-vertex", "")]["walk_steps"] == "0"
    seeded = rows[("random-20", "local-degree-list", "seed=1")]
    assert seeded["walk_steps"] == "200" and seeded["outcome"] in ("correct", "wrong-map", "failed")
    cue = rows[("small-random-40", "none", "cue=n")]
    assert (cue["outcome"], cue["true_world_completed"]) == ("correct", "True") and int(cue["peak_models"]) >= 1
    capped = rows[("small-random-40", "none", "max-models=20")]
    assert capped["outcome"] == "limit" and "--max-models 20 exceeded" in capped["error"]
    assert rows[("figure-3.4a", "none", "cue=n")]["completed_models"] == "6"

    text = bench.write_report("chapter-5", tmp_path, plots=False).read_text()
    assert "usually less than 50 steps" in text and "(§5.1" in text  # the thesis beside ours
    assert "| lattice-hole | all | 1 | 1 | 0 | 0 |" in text  # §5.1's headline row: 1 world, correct
    assert "| random-20 | local-degree-list | 1 | 1 |" in text  # §5.2.1 per family and walk seed
    assert "| small-random-40 | 6 | `cue=n` | 1 | 6.0 | 1 | 0 | 0 | 0 |" in text
    assert "| small-random-40 | 6 | `max-models=20` | 1 | 6.0 | 0 | 0 | 0 | 1 |" in text
    assert "### Peak models and time against n" in text and "| small-random-40 | 6.0 |" in text
    assert "| 3.4(a) | global | 6 | 6 | 3 |" in text and "Figure 3.4(a) took" in text
    assert text.count("Held?") == 5 and "**not held** (a wrong map)" not in text
    assert "Plots: not requested." in text
    assert write_report(tmp_path, plots=False).read_text().split("| 3.4(a) | global")[0] == text.split(
        "| 3.4(a) | global")[0]  # the tables come from the CSV alone


def test_figure_3_4_from_the_centre_six_global_models_against_many_more_local():
    got = {(r["figure"], r["signatures"]): r for r in figure_3_4()}
    assert got[("3.4(a)", "global")]["completed"] == 6 and got[("3.4(a)", "global")]["itself"] == [6]
    assert got[("3.4(b)", "global")]["other"] == [6]
    assert all(got[(f, "local")]["completed"] > 7 * got[(f, "global")]["completed"] for f in ("3.4(a)", "3.4(b)"))
    assert all(r["seconds"] >= 0 and r["outcome"] == "failed" for r in got.values())


def test_the_wheels_section_reads_the_same_whatever_the_runs_took(monkeypatch):
    """The published page is regenerated and compared byte for byte: a time measured as the report is written
    must not change its text (the wheel runs take hundredths of a second)."""
    from topomark.reference.bench.reports import chapter5

    runs = figure_3_4()
    texts = []
    for seconds in (0.01, 0.06):
        monkeypatch.setattr(chapter5, "figure_3_4", lambda: [{**r, "seconds": seconds} for r in runs])
        texts.append("\n".join(chapter5._figure_section({})))
    assert texts[0] == texts[1] and "took under 1 s here" in texts[0]
