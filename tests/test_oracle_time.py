"""``run-external``'s time is the program's time, and every failure of the program is a verdict that says what
happened (``reference/oracle/run_external.py``, ``peer.py``, ``snapshot_wire.py``, ``marker_messages.py``)."""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.oracle import peer as peer_module
from topomark.reference.oracle import run_external as run_external_module
from topomark.reference.oracle.run_external import Limits, run_external
from topomark.spec.kit import Kit
from topomark.spec.world import Start, World

ROOT = Path(__file__).resolve().parents[1]
CLIENT = str(ROOT / "reference" / "oracle" / "examples" / "client.py")
TRIANGLE = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, (), Start("a", "b"))

LIGHTHOUSE_SNAPSHOT = {"type": "snapshot", "S": {"exits": [[None, None]], "marks": [{"vertex": 0, "head": 0}]},
                       "U": [[0, 0], [0, 1]]}




@pytest.fixture
def scripted(scripted):
    """The shared scripted client, lingering 30 s: long enough for every time limit these tests set."""
    return lambda *messages, pause=0.0: scripted(*messages, pause=pause, linger=30.0)


def _slow(seconds: float, calls: list):
    real = run_external_module.check_invariants

    def slow(*args):
        calls.append(time.monotonic())
        time.sleep(seconds)
        return real(*args)
    return slow


# -- time -------------------------------------------------------------------------
def test_topomark_checking_slowly_does_not_make_a_fast_program_time_out(monkeypatch):
    calls: list = []
    monkeypatch.setattr(run_external_module, "check_invariants", _slow(0.5, calls))
    result = run_external(TRIANGLE, [sys.executable, CLIENT], Limits(wall=1.2, message=0.4))
    assert result.passed, result.message
    assert len(calls) == 3 and result.snapshots == 3
    assert result.topomark_seconds >= 1.5 > result.wall - 1.5 >= result.program_seconds
    assert result.to_json()["program_seconds"] == round(result.program_seconds, 3)


def test_a_slow_program_still_times_out_and_the_verdict_says_whose_time(scripted):
    moves = [{"type": "move", "motion": 1}] * 20
    result = run_external(TRIANGLE, scripted({"type": "drop", "direction": 0}, *moves, pause=0.3),
                          Limits(wall=1.0, message=5))
    assert result.reason == "timeout" and "wall-time limit of 1 s exceeded: topomark waited" in result.message
    assert result.program_seconds >= 1.0 and result.cost < 5


def test_a_program_that_never_makes_topomark_wait_meets_the_ceiling(monkeypatch, scripted):
    monkeypatch.setattr(run_external_module, "check_invariants", _slow(0.2, []))
    monkeypatch.setattr(peer_module, "CEILING", 2)
    result = run_external(TRIANGLE, scripted({"type": "drop", "direction": 0}, *[LIGHTHOUSE_SNAPSHOT] * 40),
                          Limits(wall=0.6, message=5))
    assert result.reason == "limit" and "the ceiling of 2 x the time limit" in result.message
    assert result.program_seconds < 0.6 and 1.2 <= result.wall < 5


def test_the_cli_reports_both_times(capsys):
    assert main(["run-external", "cycle:n=4", "--", sys.executable, CLIENT]) == 0
    assert "s: the program " in capsys.readouterr().out
    assert main(["run-external", "cycle:n=4", "--json", "--", sys.executable, CLIENT]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["program_seconds"] + data["topomark_seconds"] == pytest.approx(data["wall_seconds"], abs=0.002)


# -- @2 verdicts never escape ------------------------------------------------------
def test_a_move_the_thread_does_not_allow_is_a_marker_verdict_with_json(scripted, capsys):
    cmd = scripted({"type": "thread", "op": "tie"}, {"type": "move", "motion": 0}, {"type": "move", "motion": 1})
    assert main(["run-external", "cycle:n=5", "--kit", '{"thread": 1}', "--json", "--", *cmd]) == 1
    out, err = capsys.readouterr()
    data = json.loads(out)
    assert data["reason"] == "marker" and "the thread would run out" in data["message"] and err == ""
    assert data["message"].startswith('move {"motion": 1} after 1 traversals refused')


@pytest.mark.parametrize("version, kit", [(1, None), (2, Kit(vertex=2, directional=True))])
def test_a_vertex_marked_twice_in_a_snapshot_is_an_i1_verdict(scripted, version, kit):
    snapshot = {**LIGHTHOUSE_SNAPSHOT, "S": {"exits": [[None, None]],
                                             "marks": [{"vertex": 0, "head": 0}, {"vertex": 0, "head": 0}]}}
    drop = {"type": "drop", "direction": 0} if version == 1 else {"type": "drop", "kind": "vertex", "direction": 0}
    result = run_external(TRIANGLE, scripted(drop, snapshot), Limits(wall=20, message=5), version=version, kit=kit)
    assert result.reason == "invariant" and result.violation.check == "I-1"
    assert "S.marks[0] and S.marks[1]" in result.message


# -- messages that say what happened -------------------------------------------------
def test_a_malformed_snapshot_names_the_field_and_is_the_programs_fault(scripted, capsys):
    snapshot = {**LIGHTHOUSE_SNAPSHOT, "S": {"exits": [[None, None]], "marks": [{"vertex": 0, "head": "x"}]}}
    assert main(["run-external", "cycle:n=3", "--", *scripted({"type": "drop", "direction": 0}, snapshot)]) == 1
    out = capsys.readouterr().out
    assert out.startswith('FAIL [snapshot] snapshot 1 is malformed: snapshot.S.marks[0].head must be integer or null')
    assert 'got "x"' in out and "internal check" not in out


@pytest.mark.parametrize("kit, op, words", [
    (Kit(vertex=1, directional=True, movable=True), {"kind": "vertex"}, "there is no vertex marker here to pick up"),
    (Kit(edge=1, movable=True), {"kind": "edge", "exit": 1},
     "there is no edge marker on the edge at exit 1 to pick up"),
    (Kit(vertex=1, movable=True), {"kind": "vertex", "count": 2}, "only 1 vertex marker lie here, not the 2"),
])
def test_a_pick_up_where_too_few_markers_lie_says_so(scripted, kit, op, words):
    drop = [{"type": "drop", "kind": "vertex"}] if "count" in op else []
    result = run_external(TRIANGLE, scripted(*drop, {"type": "pick_up", **op}), Limits(wall=20, message=5),
                          version=2, kit=kit)
    assert result.reason == "marker" and words in result.message and "marker kit violated" not in result.message


def test_a_passing_map_says_the_programs_markers_were_compared(capsys):
    assert main(["run-external", "cycle:n=4", "--", sys.executable, CLIENT]) == 0
    out = capsys.readouterr().out
    assert "the markers the program left in the world are compared" in out and "world file" not in out


def test_a_world_files_marker_the_program_cannot_meet_names_what_run_external_judges(capsys):
    argv = ["run-external", "wheel-a:marker=undirected", "--kit", '{"undirected-vertex": 1}', "--", "true"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "run-external plays the world without markers and the program drops its own" in err
    assert "1 undirected vertex marker" in err and "basic algorithm" not in err and "--lighthouse" not in err
    assert err.count("\n") == 1
