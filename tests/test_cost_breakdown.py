"""The cost breakdown (§3.5.2): every run's cost split by iteration and kind of walk adds up to the cost, the
validation motions split by hypothesis outcome, and ``explore --breakdown`` / ``--breakdown-plot`` show it."""

from __future__ import annotations

import json
import sys

import pytest

from topomark.spec.errors import TopomarkFault
from topomark.reference.cli.main import main
from topomark.reference.explorers import algorithm31
from topomark.reference.run import breakdown as bd
from topomark.reference.run.explore import explore
from topomark.reference.worlds.generators import generate

WORLDS = [("lattice", {"rows": 3, "cols": 4}), ("random", {"n": 9, "seed": 3}), ("strip", {"n": 9}),
          ("k5e-chain", {"gadgets": 2})]
ALGORITHMS = ["basic", "enh1", "enh3", "enh4", "enh5-d1", "dudek", "single-leaf", "case-1a", "thread-explore"]


def _run(world, algorithm):
    return explore(world, algorithm, record=False, keep_hypotheses=False)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("name,params", WORLDS)
def test_the_kinds_and_the_rows_add_up_to_the_cost(name, params, algorithm):
    world = generate(name, **params)
    if algorithm == "single-leaf":
        world = generate("random", n=9, seed=3)  # the one world here with a single leaf (§5.3)
    o = _run(world, algorithm)
    b = o.breakdown
    assert sum(b.by_kind().values()) == o.cost == b.cost
    rows = b.rows()
    assert sum(sum(r[3:]) for r in rows) == o.cost
    assert [r[0] for r in rows[:o.iterations + 1]] == list(range(o.iterations + 1))  # row 0: the start
    by_kind = b.by_kind()
    validation = sum(v for k, v in by_kind.items() if k.startswith("validation"))
    assert validation == o.by_purpose.get("validation", 0)
    for purpose in ("travel", "new", "retrace", "expansion", "establish", "probe", "drop"):
        assert by_kind[purpose] == o.by_purpose.get(purpose, 0)


def test_basic_accounts_for_every_validation_motion_by_outcome_and_retraces_the_rejected_ones():
    o = explore(generate("lattice", rows=4, cols=4), "basic", record=False)
    k = o.breakdown.by_kind()
    assert k["validation other"] == 0 and k["validation case 1"] and k["validation case 2"] and k["validation case 3"]
    assert k["retrace"] == k["validation case 1"] + k["validation case 2"]  # line 17 retraces what was walked
    assert k["new"] == o.m  # every edge is taken once as e (line 7)
    for it, row in zip(o.explorer.iterations, o.breakdown.rows()[1:]):
        walked = {c: sum(h.walked for h in it.hypotheses if h.outcome == c) for c in bd.CASES}
        assert row[5:8] == [walked["case 1"], walked["case 2"], walked["case 3"]]
        assert row[2] == len(it.hypotheses)


def test_enhancements_rejecting_without_motion_attribute_only_the_motions_made():
    o = explore(generate("complete", n=6), "enh3", record=False)
    k = o.breakdown.by_kind()
    assert k["validation other"] == 0
    assert sum(k[f"validation {c}"] for c in bd.CASES) == o.by_purpose["validation"]


def test_seeded_fault_hypotheses_claiming_more_motions_than_made_is_a_fault(monkeypatch):
    real = algorithm31.walk_hypothesis

    def inflated(robot, h, degree, heading):
        done = real(robot, h, degree, heading)
        h.walked += 1  # the split now claims a motion the robot never made
        return done
    monkeypatch.setattr(algorithm31, "walk_hypothesis", inflated)
    with pytest.raises(TopomarkFault, match="account for"):
        _run(generate("lattice", rows=3, cols=3), "basic")


def test_seeded_fault_rows_that_do_not_sum_to_the_cost_are_a_fault(monkeypatch):
    real = bd.CostBreakdown._row

    def lossy(self, number, augmentation, hypotheses, delta):
        return real(self, number, augmentation, hypotheses, {k: v for k, v in delta.items() if k != "travel"})
    monkeypatch.setattr(bd.CostBreakdown, "_row", lossy)  # the walks to v_k fall out of the split
    with pytest.raises(TopomarkFault, match="add up to"):
        _run(generate("lattice", rows=3, cols=3), "basic")


def test_explore_json_carries_the_totals_and_with_breakdown_the_rows(capsys):
    assert main(["explore", "strip:n=8", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    split = data["cost_breakdown"]
    assert set(split) == {"cost", "by_kind"} and sum(split["by_kind"].values()) == data["cost"] == split["cost"]
    assert main(["explore", "strip:n=8", "--json", "--breakdown"]) == 0
    split = json.loads(capsys.readouterr().out)["cost_breakdown"]
    assert split["columns"][:3] == ["iteration", "augmentation", "hypotheses"]
    assert sum(sum(r[3:]) for r in split["rows"]) == split["cost"]
    assert main(["explore", "strip:n=8", "--breakdown", "--quiet"]) == 0
    out = capsys.readouterr().out
    assert "cost by kind of walk" in out and "costliest iterations" in out


@pytest.mark.slow  # matplotlib's import and a rendering: several seconds
def test_breakdown_plot_is_drawn(tmp_path):
    import matplotlib  # noqa: F401  (a test dependency: the plot is drawn, never skipped)
    png = tmp_path / "b.png"
    assert main(["explore", "strip:n=8", "--quiet", "--breakdown-plot", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_breakdown_plot_is_refused_for_a_bad_name_or_without_matplotlib(tmp_path, capsys, monkeypatch):
    assert main(["explore", "strip:n=8", "--quiet", "--breakdown-plot", str(tmp_path / "b.gif")]) == 2
    assert ".png or .svg" in capsys.readouterr().err
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # matplotlib not installed
    assert main(["explore", "strip:n=8", "--quiet", "--breakdown-plot", str(tmp_path / "c.png")]) == 2
    err = capsys.readouterr().err
    assert "pip install '.[plot]'" in err and err.count("\n") == 1 and not (tmp_path / "c.png").exists()
