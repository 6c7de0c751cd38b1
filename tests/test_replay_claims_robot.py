"""Replay judges the run, not only the robot: a robot-family trace's kit, records and end claim (``spec/trace.md``).

Traces of a §6.2 algorithm (``case-3a``), of Dudek et al.'s movable marker
(``dudek``) and of a thread algorithm (``thread-explore``) are recorded by
``topomark explore --trace`` and tampered with: an end saying ``failed`` for
a run that mapped, the last marker operation left out, a header declaring a
smaller kit than the run used.  Each is refuted (exit 1) naming what is wrong.
"""

from __future__ import annotations

import json

import pytest

from topomark.reference.cli.main import main

ALGORITHMS = ("case-3a", "dudek", "thread-explore")


def record(tmp_path, algorithm: str) -> tuple[str, list[dict]]:
    world = tmp_path / "w.json"
    assert main(["world", "cycle:n=4", "-o", str(world)]) == 0
    trace = tmp_path / f"{algorithm}.jsonl"
    assert main(["explore", str(world), "--algorithm", algorithm, "--trace", str(trace), "--quiet"]) == 0
    return str(world), [json.loads(line) for line in trace.read_text().splitlines()]


def replay(tmp_path, capsys, world: str, records: list[dict]) -> tuple[int, dict]:
    path = tmp_path / "tampered.jsonl"
    path.write_text("".join(json.dumps(r, sort_keys=True, separators=(",", ":")) + "\n" for r in records))
    capsys.readouterr()
    code = main(["replay", world, str(path), "--json"])
    return code, json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_an_untampered_trace_verifies_with_its_re_run(tmp_path, capsys, algorithm):
    world, records = record(tmp_path, algorithm)
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 0 and data["layers"] == ["robot", "re-run"], data


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_a_failed_end_for_a_run_that_mapped_is_refuted(tmp_path, capsys, algorithm):
    world, records = record(tmp_path, algorithm)
    records[-1].update(verified=False, outcome="failed", reason="out of markers")
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 1 and data["divergence"]["check"] == "trace claim"
    assert "found a stopped run: failed" in data["message"] and "expected a verified run" in data["message"]


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_the_last_marker_operation_left_out_is_refuted(tmp_path, capsys, algorithm):
    world, records = record(tmp_path, algorithm)
    last = max(k for k, r in enumerate(records) if r["event"] == "op")
    missing = records.pop(last)
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 1 and data["line"] == last + 1 and data["divergence"]["check"] == "algorithm"
    assert json.dumps(missing, sort_keys=True, separators=(",", ":")) in data["divergence"]["expected"]


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_a_header_declaring_a_smaller_kit_is_refuted(tmp_path, capsys, algorithm):
    world, records = record(tmp_path, algorithm)
    kit = records[0]["kit"]
    if algorithm == "dudek":
        del kit["movable"]  # the one marker, no longer movable: the run's pick-ups are beyond the kit
    else:
        key = "thread" if "thread" in kit else next(iter(kit))
        kit[key] -= 1
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 1 and data["divergence"]["check"] == "marker kit", data
    assert data["line"] == 1 and "the kit" in data["message"]


def test_a_larger_kit_than_the_algorithms_is_refuted_too(tmp_path, capsys):
    world, records = record(tmp_path, "case-3a")
    records[0]["kit"]["undirected-vertex"] += 1  # the robot layer alone accepts it: every drop is within the kit
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 1 and data["line"] == 1 and "the kit case-3a carries on this world" in data["message"]


def test_an_option_given_is_in_the_header_and_re_run(tmp_path, capsys):
    world, _ = record(tmp_path, "case-3a")
    trace = tmp_path / "more.jsonl"
    assert main(["explore", world, "--algorithm", "case-3a", "--markers", "10", "--trace", str(trace), "--quiet"]) == 0
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    assert records[0]["options"] == {"markers": 10}
    assert replay(tmp_path, capsys, world, records)[0] == 0
    del records[0]["options"]  # the kit of 10 markers is then not case-3a's default
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 1 and data["divergence"]["check"] == "marker kit"


def test_a_robot_layer_only_trace_that_claims_a_verified_run_is_refused(tmp_path, capsys):
    world, records = record(tmp_path, "dudek")
    records[0]["algorithm"] = "dudek-elsewhere"  # a name topomark does not run: no algorithm layer
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 1 and data["layers"] == ["robot"] and data["divergence"]["check"] == "trace claim"
    assert "cannot be checked, so it is refused" in data["message"]
    records[-1]["verified"] = False  # an unjudged end claims nothing: the robot layer's verdict stands
    code, data = replay(tmp_path, capsys, world, records)
    assert code == 0 and "robot layer only" in data["message"]


@pytest.mark.parametrize("lighthouse", ["undirected-vertex", "local-degree-list"])  # trace@2: its end may say how it stopped
def test_an_algorithm_3_1_trace_that_claims_failure_after_mapping_is_refuted(tmp_path, capsys, lighthouse):
    """Algorithm 3.1's layer rebuilds S from the iterations: an end saying ``failed`` (or ``limit``) after all m
    iterations, with U empty, claims a stop that did not happen."""
    world = tmp_path / "w.json"
    assert main(["world", "lattice-hole:rows=4,cols=4,seed=0", "-o", str(world)]) == 0
    trace = tmp_path / "t.jsonl"
    assert main(["explore", str(world), "--lighthouse", lighthouse, "--trace", str(trace), "--quiet"]) == 0
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    assert replay(tmp_path, capsys, str(world), records)[0] == 0
    for outcome in ("failed", "limit"):
        records[-1].update(outcome=outcome, reason="tampered", verified=False)
        code, data = replay(tmp_path, capsys, str(world), records)
        assert code == 1 and "trace claim" in json.dumps(data) and "had finished" in json.dumps(data), data
