"""Every way a registered algorithm's runs can go (its registration's ``ways``: phases, outcomes) is reached by
some case of its conformance suite; the suite records the ways each reference run went; a must-fail case is
passed by giving up or by a correct map, and failed by a wrong one."""

from __future__ import annotations

import json
import shutil
import sys
from dataclasses import replace
from pathlib import Path

import pytest

from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec
from topomark.reference.algorithms.ways import OUTCOME, WAYS, check_ways, ways_of
from topomark.reference.cli.main import main
from topomark.reference.oracle.conformance.cases import algorithm_cases, suite_algorithms
from topomark.reference.oracle.conformance.coverage import reference_runs, uncovered

TOPOMARK = [sys.executable, str(Path(__file__).resolve().parent / "clients" / "topomark_client.py")]


def went(spec: AlgorithmSpec, cases=None) -> list[list[str]]:
    return [ways for _, _, ways in reference_runs(spec, cases)]


@pytest.mark.parametrize("name", [s.name for s in suite_algorithms()])
def test_every_declared_way_is_reached_by_a_case_of_the_algorithm_s_suite(name):
    spec = algorithm_spec(name)
    assert uncovered(spec, went(spec)) == []


def test_every_registered_algorithm_declares_known_ways_with_an_outcome_and_a_thesis_section():
    for spec in REGISTRY.values():
        assert set(spec.ways) <= set(WAYS) and any(WAYS[w].kind == OUTCOME for w in spec.ways), spec.name
    assert all(way.thesis.startswith("§") for way in WAYS.values())
    with pytest.raises(ValueError, match="unknown ways"):
        replace(algorithm_spec("case-3a"), ways=("correct", "out-of-cheese"))
    with pytest.raises(ValueError, match="name no outcome"):
        check_ways("x", ("phase-ii",))


def test_a_declared_way_no_case_reaches_is_found():
    spec = replace(algorithm_spec("case-3a"), ways=(*algorithm_spec("case-3a").ways, "failed-out-of-thread"))
    assert uncovered(spec, went(spec)) == ["failed-out-of-thread"]


@pytest.mark.parametrize("name, dropped, way", [
    ("case-3a", "lattice-2x3-markers-2", "failed-out-of-markers"),
    ("case-5-v1", "lattice-2x3-markers-4", "phase-ii"),
    ("case-5-v2", "lattice-2x3-markers-4", "phase-ii"),
    ("thread-circumference", "lattice-2x3-thread-1", "failed-out-of-thread"),
])
def test_dropping_the_case_that_reaches_a_way_leaves_it_uncovered(name, dropped, way):
    spec = algorithm_spec(name)
    kept = [case for case in algorithm_cases(spec) if case[0] != dropped]
    assert len(kept) == len(algorithm_cases(spec)) - 1
    assert way in uncovered(spec, went(spec, kept))


def test_case_5_goes_into_phase_ii_only_with_a_small_kit_and_says_so():
    spec = algorithm_spec("case-5-v1")
    runs = {case[0]: ways for case, _, ways in reference_runs(spec)}
    assert runs["lattice-2x3"] == ["correct", "phase-i"]
    assert runs["lattice-2x3-markers-4"] == ["correct", "phase-i", "phase-ii"]
    assert ways_of(reference_runs(spec)[0][1]) == ["correct", "phase-i"]  # of every way: the same, undeclared none


def test_a_small_kit_case_that_goes_no_new_way_is_left_out_and_a_world_is_added_where_the_small_ones_reach_none():
    names = [case[0] for case, _, _ in reference_runs(algorithm_spec("thread-explore"))]
    assert "lattice-2x3-thread-1" in [c[0] for c in algorithm_cases(algorithm_spec("thread-explore"))]
    assert "lattice-2x3-thread-1" not in names  # Algorithm 6.8 maps with any length: nothing new to hold a client to
    names = [case[0] for case, _, _ in reference_runs(algorithm_spec("enh5-d1"))]
    assert names[-1] == "lattice-3x3"  # its sensing rejects no hypothesis on the small worlds


@pytest.fixture(scope="module")
def suite(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("coverage") / "suite"
    argv = ["conformance", "export", str(root), "--algorithm", "case-5-v1", "--algorithm", "thread-circumference"]
    assert main(argv) == 0
    return root


def _suites(root: Path) -> dict:
    return {s["algorithm"]: s for s in json.loads((root / "manifest.json").read_text())["suites"]}


def test_the_export_records_the_declared_ways_and_the_ways_each_case_went(suite):
    manifest = json.loads((suite / "manifest.json").read_text())
    assert manifest["version"] == "2.2.0"
    for name, data in _suites(suite).items():
        spec = algorithm_spec(name)
        assert set(data["ways"]) == set(spec.ways) and data["ways"]["correct"]["thesis"] == "§3.1.3"
        reached = {w for case in data["cases"] for w in case["ways"]}
        assert reached == {w for w in spec.ways if WAYS[w].in_suite}
    cases = {c["name"]: c for c in _suites(suite)["thread-circumference"]["cases"]}
    assert cases["lattice-2x3-thread-1"]["expected"] == "failed"
    assert cases["lattice-2x3-thread-1"]["ways"] == ["failed-out-of-thread", "thread-laid"]
    assert cases["lattice-2x3-thread-1"]["kit"] == {"thread": 1}


def _edited(suite: Path, tmp_path: Path, change) -> Path:
    copy = tmp_path / "suite"
    shutil.copytree(suite, copy)
    manifest = json.loads((copy / "manifest.json").read_text())
    change(manifest)
    (copy / "manifest.json").write_text(json.dumps(manifest))
    return copy


def _older(manifest: dict) -> None:
    manifest["version"] = "2.1.0"
    for s in manifest["suites"]:
        del s["ways"]
        for case in s["cases"]:
            del case["ways"]


def test_a_2_1_suite_without_ways_still_lints(suite, tmp_path, capsys):
    assert main(["conformance", "lint", str(_edited(suite, tmp_path, _older))]) == 0


@pytest.mark.parametrize("change, words", [
    (lambda m: m["suites"][0]["cases"][0].update(ways=["out-of-cheese"]), "a list of the ways the suite declares"),
    (lambda m: m["suites"][0]["ways"]["correct"].update(kind="mood"), "way ↦ {kind: phase|outcome"),
    (lambda m: m["suites"][0].pop("ways"), "absent (the suite declares no ways)"),
])
def test_lint_refuses_damaged_ways(suite, tmp_path, capsys, change, words):
    assert main(["conformance", "lint", str(_edited(suite, tmp_path, change))]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err


@pytest.mark.parametrize("client, code, reason", [
    ("thread-circumference", 0, "failed"),  # gives up, as the reference does
    ("thread-explore", 0, "mapped"),  # maps the world with one edge of thread: better than the reference
    ("thread-circumference map-anyway", 1, "not-isomorphic"),  # sends its partial map: wrong
])
def test_a_must_fail_case_passes_a_program_that_gives_up_or_maps_and_fails_one_that_sends_a_wrong_map(
        suite, capsys, client, code, reason):
    got = main(["conformance", "run", str(suite), "--algorithm", "thread-circumference", "-k", "thread-1", "--json",
                "--", *TOPOMARK, *client.split()])
    [row] = json.loads(capsys.readouterr().out)["cases"]
    assert (got, row["reason"], row["expected"]) == (code, reason, "failed"), row
    assert (row["verdict"] == "pass") == (code == 0)
