"""The conformance suite ``topomark/conformance@2``, Algorithm 3.1's cases: export, self-lint, and runs of good and bad
implementations (tests/test_conformance_algorithms.py: the algorithm suites and @1 suites)."""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

import jsonschema
import pytest

from topomark.reference.oracle import conformance
from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.oracle.run_external import Limits
from topomark.spec.errors import InvalidInput
from topomark.spec.world import Start

ROOT = Path(__file__).resolve().parents[1]
CLIENT = [sys.executable, str(ROOT / "reference" / "oracle" / "examples" / "client.py")]
WRONG = str(Path(__file__).resolve().parent / "clients" / "wrong_client.py")


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("suite") / "suite"
    assert main(["conformance", "export", str(root), "--algorithm", "basic"]) == 0
    return root


@pytest.fixture(scope="module")
def small(tmp_path_factory) -> Path:
    """The first four cases only (the two Figure 3.6 wheels, the triangle, C4): cheap to lint repeatedly."""
    root = tmp_path_factory.mktemp("small") / "suite"
    conformance.export(root, conformance.default_cases()[:4], algorithms=())
    return root


@pytest.fixture
def copy(small, tmp_path) -> Path:
    dest = tmp_path / "suite"
    shutil.copytree(small, dest)
    return dest


def manifest(root: Path) -> dict:
    return json.loads((root / "manifest.json").read_text())


@pytest.mark.slow
def test_manifest_describes_version_layout_and_cases(suite):
    m = manifest(suite)
    assert m["format"] == "topomark/conformance@2" and m["version"] == conformance.SUITE_VERSION
    assert m["protocol"] == "topomark/protocol@1" and m["trace_format"] == "topomark/trace@1"
    assert set(m["policies"]) == set(conformance.POLICIES) and "layout" in m
    names = [c["name"] for c in m["cases"]]
    assert len(names) == len(set(names)) >= 15
    assert {"figure-3.6-wheel-a", "figure-3.6-wheel-b", "triangle", "cycle-4", "chain-2"} <= set(names)
    for case in m["cases"]:
        assert set(case["reference"]) == set(conformance.POLICIES)
        assert all(ref["cost"] >= case["m"] for ref in case["reference"].values())


def test_every_world_and_map_is_valid_against_the_published_schema(suite):
    published = json.loads((suite / "schema" / "world.schema.json").read_text())
    validator = jsonschema.Draft202012Validator(published)
    files = list((suite / "worlds").glob("*.json")) + list((suite / "reference").rglob("*.map.json"))  # the
    # algorithm suites use Algorithm 3.1's worlds of the same name, and add the chiral world and the paw
    assert len(files) == len(manifest(suite)["cases"]) * (1 + len(conformance.POLICIES)) + 2
    for path in files:
        assert not list(validator.iter_errors(json.loads(path.read_text()))), path


def test_lint_passes_on_a_fresh_export(suite, capsys):
    assert main(["conformance", "lint", str(suite), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["ok"] is True


@pytest.mark.parametrize("damage, words", [
    (lambda r: _edit_manifest(r, lambda m: m["cases"].append(dict(m["cases"][0]))), "duplicate case name"),
    (lambda r: _edit_manifest(r, lambda m: m.update(version="3.0.0")), "not compatible"),
    (lambda r: _edit_manifest(r, lambda m: m.update(format="other/suite@1")), "is not topomark/conformance@2"),
    (lambda r: _edit_manifest(r, lambda m: m["cases"][2]["reference"]["default"].update(cost=1)),
     "manifest cost 1"),
    (lambda r: _edit_manifest(r, lambda m: m["cases"][0].update(name="Bad Name")), "no valid name"),
    (lambda r: (r / "worlds" / "extra.json").write_text("{}"), "not listed in the manifest"),
    (lambda r: _edit_json(r / "worlds" / "triangle.json", lambda w: w.update(colour="red")),
     "not valid against schema/world.schema.json"),
    (lambda r: (r / "worlds" / "cycle-4.json").unlink(), "is missing"),
    (lambda r: (r / "manifest.json").write_text("{"), "malformed JSON"),
    (lambda r: _edit_lines(r / "reference" / "triangle" / "default.trace.jsonl",
                           lambda ls: [ls[0]] + ls[2:]), "does not replay"),
])
def test_lint_catches_a_damaged_suite(copy, capsys, damage, words):
    damage(copy)
    assert main(["conformance", "lint", str(copy)]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err


def _edit_json(path: Path, change) -> None:
    obj = json.loads(path.read_text())
    change(obj)
    path.write_text(json.dumps(obj))


def _edit_manifest(root: Path, change) -> None:
    _edit_json(root / "manifest.json", change)


def _edit_lines(path: Path, change) -> None:
    path.write_text("\n".join(change(path.read_text().splitlines())) + "\n")


def test_export_refuses_a_non_empty_directory(suite, capsys):
    assert main(["conformance", "export", str(suite)]) == 2
    err = capsys.readouterr().err
    assert str(suite) in err and "not empty" in err and "--force" in err


@pytest.mark.slow
def test_the_example_client_passes_the_whole_suite(suite, capsys):
    code = main(["conformance", "run", str(suite), "--json", "--", *CLIENT])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["passed"] == data["total"] == len(manifest(suite)["cases"])
    for row in data["cases"]:
        assert row["verdict"] == "pass" and row["ratio"] == round(row["cost"] / row["reference_cost"], 3)
        assert row["ratio_best"] >= row["ratio"] - 1e-9 or row["best_reference_cost"] <= row["reference_cost"]
    assert data["wall_seconds"] < 30


def test_the_text_table(suite, capsys):
    assert main(["conformance", "run", str(suite), "-k", "triangle", "--", *CLIENT]) == 0
    out = capsys.readouterr().out
    assert "triangle" in out and "PASS" in out and "1/1 passed" in out


@pytest.mark.parametrize("fault, reason", [("crash", "crash"), ("hang", "timeout"), ("garbage", "garbage"),
                                           ("trust-first", None)])
def test_crashes_hangs_and_wrong_maps_count_as_failures(suite, fault, reason):
    rows = conformance.run(suite, [sys.executable, WRONG, fault], Limits(message=0.5), select="lattice-3x3")
    assert [r.result.verdict for r in rows] == ["fail"]
    if reason:
        assert rows[0].result.reason == reason
    assert rows[0].to_json()["ratio"] is None


def test_run_exits_1_when_anything_fails(suite, capsys):
    assert main(["conformance", "run", str(suite), "-k", "cycle", "--", sys.executable, WRONG, "bad-exit"]) == 1
    assert "FAIL" in capsys.readouterr().out


def test_run_bad_input(suite, tmp_path, capsys):
    assert main(["conformance", "run", str(suite), "-k", "no-such-case", "--", *CLIENT]) == 2
    assert "no case" in capsys.readouterr().err
    assert main(["conformance", "run", str(tmp_path), "--", *CLIENT]) == 2
    assert "no readable manifest.json" in capsys.readouterr().err
    assert main(["conformance"]) == 2
    assert "needs an action" in capsys.readouterr().err


def test_export_of_custom_cases(tmp_path):
    cases = [("c5", "a cycle", g.cycle(5).with_start(Start("0", "1")))]
    m = conformance.export(tmp_path / "s", cases, algorithms=())
    assert [c["name"] for c in m["cases"]] == ["c5"] and m["cases"][0]["reference"]["default"]["cost"] == 5
    with pytest.raises(InvalidInput, match="duplicate case name"):
        conformance.export(tmp_path / "t", cases + cases, algorithms=())
