"""The algorithm suites of ``topomark/conformance@2``: export, lint, runs of topomark's own algorithms as clients
(``tests/clients/topomark_client.py``) and of seeded wrong clients, labelled columns, and ``@1`` suites still read."""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

import pytest

from topomark.reference.algorithms.registry import algorithm_spec
from topomark.reference.cli.main import main
from topomark.reference.oracle import conformance

ROOT = Path(__file__).resolve().parents[1]
TOPOMARK = [sys.executable, str(Path(__file__).resolve().parent / "clients" / "topomark_client.py")]
CLIENT = [sys.executable, str(ROOT / "reference" / "oracle" / "examples" / "client.py")]
CHOSEN = ["case-3a", "case-1b", "case-2", "extension-1"]  # Σ k vertex markers, a pool, edge counts, directional edges


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("algorithms") / "suite"
    argv = ["conformance", "export", str(root), "--family", "movable-markers", "--family", "threads"]
    assert main([*argv, *(x for name in CHOSEN for x in ("--algorithm", name))]) == 0
    return root


def manifest(root: Path) -> dict:
    return json.loads((root / "manifest.json").read_text())


def suites(root: Path) -> dict:
    return {s["algorithm"]: s for s in manifest(root)["suites"]}


def cases(root: Path, algorithm: str) -> dict:
    return {c["name"]: c for c in suites(root)[algorithm]["cases"]}


@pytest.mark.slow
def test_each_case_carries_the_registry_kit_bound_and_reference_run(suite):
    got = suites(suite)
    assert set(got) == set(CHOSEN) | {"dudek", "dudek-listing", "dudek-directional", "dudek-directional-listing",
                                      "thread-carried", "thread-circumference",
                                      "thread-circumference-listing",
                                      "thread-knots", "thread-explore", "thread-fallback",
                                      "thread-explore-listing", "thread-fallback-listing"}
    assert manifest(suite)["format"] == "topomark/conformance@2" and manifest(suite)["suites_protocol"].endswith("@2")
    for name, entry in got.items():
        spec = algorithm_spec(name)
        assert entry["family"] == conformance.family_of(spec) and entry["thesis"] == spec.thesis
        for case in entry["cases"]:
            kit = spec.kit_for(case["n"], case["m"], spec.parse_options(case["options"]))
            assert case["kit"] == kit.to_json() and case["bound"] == spec.bound_for(case["n"], case["m"])
            assert (case["reference"]["map"] is None) == (case["expected"] == "failed")
    assert cases(suite, "case-3a")["triangle"]["kit"] == {"undirected-vertex": 3}  # Σ_{k=1}^{2} k (§6.2.1 Case 3a)
    assert cases(suite, "case-1b")["triangle"]["kit"] == {"undirected-either": 4}  # m + 1 V-E-markers (§6.2.1 Case 1b)
    assert set(cases(suite, "extension-1")["cycle-4"]["kit"]) == {"directional-edge"}
    assert cases(suite, "dudek")["cycle-4"]["reference"]["marker_operations"] == {"drop": 2, "pick_up": 2}
    assert cases(suite, "dudek-listing")["cycle-4"]["reference"]["marker_operations"] == {"drop": 5, "pick_up": 5}
    assert "thread" in cases(suite, "thread-explore")["lattice-2x3"]["kit"]
    budget = cases(suite, "case-3a")["lattice-2x3-markers-2"]
    assert budget["expected"] == "failed" and "out of markers" in budget["reason"]
    assert budget["kit"] == {"undirected-vertex": 2} and budget["options"] == {"markers": 2}


@pytest.mark.slow
def test_lint_passes_and_says_what_it_holds(suite, capsys):
    assert main(["conformance", "lint", str(suite), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] and "case-3a" in out["algorithms"] and out["algorithm_cases"] >= 4 * len(out["algorithms"])


def _edit(root: Path, change) -> None:
    m = manifest(root)
    change(m)
    (root / "manifest.json").write_text(json.dumps(m))


def _case(m: dict, algorithm: str, name: str) -> dict:
    return next(c for s in m["suites"] if s["algorithm"] == algorithm for c in s["cases"] if c["name"] == name)


@pytest.mark.slow
@pytest.mark.parametrize("change, words", [
    (lambda m: _case(m, "case-3a", "triangle").update(kit={"undirected-vertex": 2}), "is given"),
    (lambda m: _case(m, "case-3a", "triangle")["reference"].update(cost=99), "manifest cost 99"),
    (lambda m: _case(m, "case-3a", "triangle").update(expected="failed", reason="x"), "a run that fails has no map"),
    (lambda m: _case(m, "case-3a", "lattice-2x3-markers-2").update(expected="correct", reason=None),
     "reference.map must be a relative path"),
    (lambda m: _case(m, "dudek", "triangle")["reference"]["marker_operations"].update(drop=0), "a positive integer"),
    (lambda m: m["suites"].append(dict(m["suites"][0])), "a second suite"),
    (lambda m: m["suites"][0].update(algorithm="no-such"), "unknown algorithm"),
])
def test_lint_catches_a_damaged_algorithm_suite(suite, tmp_path, capsys, change, words):
    copy = tmp_path / "suite"
    shutil.copytree(suite, copy)
    _edit(copy, change)
    assert main(["conformance", "lint", str(copy)]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err


def test_topomark_as_client_passes_its_own_suite_with_ratio_one(suite, capsys):
    code = main(["conformance", "run", str(suite), "--algorithm", "case-3a", "--json", "--", *TOPOMARK, "case-3a"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["protocol"] == 2 and data["passed"] == data["total"] == len(cases(suite, "case-3a"))
    for row in data["cases"]:
        assert row["verdict"] == "pass" and row["reference"]["algorithm"] == "case-3a"
        assert row["marker_operations"] == row["reference"]["marker_operations"]
        assert row["cost"] == row["reference"]["cost"]
    budget = next(r for r in data["cases"] if r["expected"] == "failed")
    assert budget["reason"] == "failed" and "out of markers" in budget["message"] and budget["ratio"] == 1.0


@pytest.mark.slow
def test_a_family_pick_ups_pools_edge_counts_and_threads(suite, capsys):
    for argv, client in ((["--family", "movable-markers"], "dudek,dudek-directional"),
                         (["--family", "threads", "-k", "lattice"], "thread-carried,thread-circumference"),
                         (["--algorithm", "case-1b", "--algorithm", "case-2", "-k", "cycle"], "case-1b,case-2")):
        code = main(["conformance", "run", str(suite), *argv, "--", *TOPOMARK, client])
        out = capsys.readouterr().out
        assert "ref cost (its algorithm)" in out and "ref ops (its algorithm)" in out
        if "threads" not in argv:  # a client of two thread algorithms cannot tell their kits apart: both {thread: 0}
            assert code == 0, out


def test_a_seeded_wrong_client_fails_the_budget_case(suite, capsys):
    code = main(["conformance", "run", str(suite), "--algorithm", "case-3a", "-k", "markers", "--json", "--",
                 *TOPOMARK, "case-3a", "overdraw"])
    [row] = json.loads(capsys.readouterr().out)["cases"]
    assert code == 1 and row["verdict"] == "fail" and row["reason"] == "marker"
    code = main(["conformance", "run", str(suite), "--algorithm", "case-1b", "-k", "markers", "--", *TOPOMARK,
                 "case-1b", "map-anyway"])
    out = capsys.readouterr().out
    assert code == 1 and "FAIL" in out and "not-isomorphic" in out and "ref cost (case-1b)" in out


def test_the_algorithm_3_1_table_says_what_it_compares(suite, capsys):
    assert main(["conformance", "run", str(suite), "-k", "triangle", "--", *CLIENT]) == 0
    out = capsys.readouterr().out
    assert "ref cost (basic)" in out and "best cost (basic)" in out


def test_bad_choices_are_bad_input(suite, capsys):
    for argv, words in ((["--algorithm", "model-tree"], "randomised"), (["--family", "nope"], "unknown family"),
                        (["--algorithm", "case-3a", "--kit", '{"undirected-vertex": 1}'], "own kit"),
                        (["--algorithm", "case-4"], "no suite of case-4")):
        assert main(["conformance", "run", str(suite), *argv, "--", *CLIENT]) == 2
        assert words in capsys.readouterr().err


@pytest.fixture(scope="module")
def suite_at_1(tmp_path_factory) -> Path:
    """A ``topomark/conformance@1`` suite as the previous topomark wrote it: the same files, the @1 manifest."""
    root = tmp_path_factory.mktemp("at1") / "suite"
    conformance.export(root, conformance.default_cases()[2:4], algorithms=())
    _edit(root, lambda m: [m.pop("suites"), m.pop("suites_protocol"),
                           m.update(format="topomark/conformance@1", version="1.0.0")])
    return root


def test_an_at_1_suite_stays_readable(suite_at_1, capsys):
    assert main(["conformance", "lint", str(suite_at_1), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["format"] == "topomark/conformance@1"
    assert main(["conformance", "run", str(suite_at_1), "-k", "triangle", "--", *CLIENT]) == 0
    assert "1/1 passed" in capsys.readouterr().out
    assert main(["conformance", "run", str(suite_at_1), "--algorithm", "case-3a", "--", *CLIENT]) == 2
    assert "only topomark/conformance@2 holds algorithm suites" in capsys.readouterr().err


def test_an_at_1_suite_with_suites_is_refused(suite_at_1, tmp_path, capsys):
    copy = tmp_path / "suite"
    shutil.copytree(suite_at_1, copy)
    _edit(copy, lambda m: m.update(suites=[]))
    assert main(["conformance", "lint", str(copy)]) == 2
    assert "new in topomark/conformance@2" in capsys.readouterr().err


def test_help_names_both_protocols(capsys):
    with pytest.raises(SystemExit):
        main(["conformance", "--help"])
    out = capsys.readouterr().out
    assert "topomark/conformance@2" in out and "topomark/protocol@1" in out and "topomark/protocol@2" in out
