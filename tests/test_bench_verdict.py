"""``topomark bench`` judges every run against its algorithm's expected outcome: Case 0's failures and
§5.2.1's failures and wrong maps are as expected; a run an entry expects to be correct that is not exits 1."""

from __future__ import annotations

import dataclasses
import json

import pytest

from topomark.reference.algorithms import registry
from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec
from topomark.reference.bench.verdict import Tally, row_as_expected
from topomark.reference.cli.main import main


def _row(algorithm: str, outcome: str, family: str = "complete-hole", lighthouse: str = "none") -> dict:
    return {"algorithm": algorithm, "experiment": family, "lighthouse": lighthouse, "outcome": outcome,
            "checked": "True", "size": "24", "seed": "0"}


def _expect_correct(monkeypatch, name: str) -> None:
    """A deliberately broken registry expectation: the entry ``name`` says every run ends correct."""
    spec = registry.REGISTRY[name]
    monkeypatch.setitem(registry.REGISTRY, name, dataclasses.replace(spec, expected="correct", expected_reason=None,
                                                                     status="implemented", status_reason=None))


def test_recorded_rows_are_judged_by_their_entry_family_and_lighthouse():
    assert row_as_expected(_row("case-0", "failed")) and row_as_expected(_row("case-0", "correct"))
    assert not row_as_expected(_row("case-0", "limit")) and not row_as_expected(_row("case-3a", "failed"))
    assert not row_as_expected(_row("case-3a", "error"))
    assert row_as_expected(_row("basic", "wrong-map", "lattice-hole", "local-pair"))  # §5.2.1
    assert not row_as_expected(_row("basic", "wrong-map", "lattice-hole", "directional-vertex"))
    assert row_as_expected(_row("basic", "failed", "small-world-k2-p10", "undirected-vertex"))  # the walk, §5.1
    assert row_as_expected({**_row("case-3a", "unchecked"), "checked": "False"})
    assert row_as_expected(_row("model-tree", "limit", "small-random-40"))
    tally = Tally()
    for row in (_row("case-0", "failed"), _row("case-3a", "correct"), _row("case-3a", "wrong-map")):
        tally.add(row)
    assert tally.failures == 1 and tally.to_json() == {"as_expected": {"correct": 1, "failed": 1},
                                                       "not_as_expected": {"wrong-map": 1}}


def test_a_family_override_and_a_bad_expectation_in_an_entry():
    spec = registry.REGISTRY["case-3a"]
    odd = dataclasses.replace(spec, expected_by_family=(("complete-hole", "may-fail", "L1"),))
    assert odd.expectation("complete-hole") == ("may-fail", "L1") and odd.expectation("lattice-hole")[0] == "correct"
    assert odd.to_json()["expected_by_family"] == {"complete-hole": {"expected": "may-fail", "reason": "L1"}}
    with pytest.raises(ValueError, match="thesis reference"):
        dataclasses.replace(spec, expected="may-fail")
    with pytest.raises(ValueError, match="expected outcome 'maybe'"):
        dataclasses.replace(spec, expected="maybe", expected_reason="L1")
    assert isinstance(odd, AlgorithmSpec)


def test_algorithms_json_shows_the_expectations(capsys):
    assert main(["algorithms", "--json"]) == 0
    text = capsys.readouterr().out
    listed = json.loads(text)
    entries = {a["name"]: a for a in (listed if isinstance(listed, list) else listed["algorithms"])}
    assert entries["case-0"]["expected"] == "fails-by-design" and "§6.2.1 Case 0" in entries["case-0"]["expected_reason"]
    assert entries["case-3a"]["expected"] == "correct" and entries["model-tree"]["expected"] == "may-fail"
    lights = entries["basic"]["expected_by_lighthouse"]
    assert lights["local-pair"]["expected"] == "may-fail" and "§5.2.1" in lights["local-pair"]["reason"]
    assert "directional-vertex" not in lights


def _bench(tmp_path, experiment: str, size: str, capsys) -> tuple[int, dict]:
    code = main(["bench", experiment, "--graphs", "1", "--sizes", size, "--out", str(tmp_path), "--jobs", "1",
                 "--quiet", "--no-plots", "--json"])
    return code, json.loads(capsys.readouterr().out)


@pytest.mark.slow
def test_section_62_exits_0_when_case_0_fails_as_the_thesis_says_and_1_when_its_entry_expects_correct(
        tmp_path, capsys, monkeypatch):
    code, out = _bench(tmp_path, "section-6.2", "24", capsys)
    assert code == 0 and out["failures"] == 0 and out["outcomes"]["as_expected"].get("failed", 0) >= 1
    assert out["outcomes"]["not_as_expected"] == {}
    report = (tmp_path / "section-6.2.md").read_text()
    assert "Runs against their algorithm's expected outcome" in report and "not as expected: 0" in report
    _expect_correct(monkeypatch, "case-0")
    code, out = _bench(tmp_path, "section-6.2", "24", capsys)  # nothing reruns: the same rows judged again
    assert code == 1 and out["ran"] == 0 and out["outcomes"]["not_as_expected"] == {"failed": 1}
    report = (tmp_path / "section-6.2.md").read_text()
    assert "- not as expected: case-0 on complete-hole size 24 seed 0 (none): failed, expected correct" in report


def test_chapter_5_exits_0_on_its_caps_and_failed_walks_and_1_when_the_model_tree_must_be_correct(
        tmp_path, capsys, monkeypatch):
    code, out = _bench(tmp_path, "chapter-5", "5", capsys)
    assert code == 0 and out["outcomes"]["as_expected"].get("limit", 0) >= 1
    _expect_correct(monkeypatch, "model-tree")
    code, out = _bench(tmp_path, "chapter-5", "5", capsys)
    assert code == 1 and out["outcomes"]["not_as_expected"].get("limit", 0) >= 1
