"""Hostile peers that never end: ``drive``'s provider and ``run-external``'s program cost time, never memory.

``drive`` streams its trace (to the ``--trace`` file, or nowhere) and keeps only counters; the simulator keeps
the latest marker operations only, and ``run-external`` caps them (``--max-operations``).
"""

from __future__ import annotations

import json
import sys
import tracemalloc
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.oracle.drive import drive
from topomark.reference.oracle.run_external import Limits, run_external
from topomark.reference.run.simulator import EVENTS_KEPT, Simulator
from topomark.reference.worlds import generators as g
from topomark.spec.kit import Kit, MarkerOp

PRELUDE = "import json, sys\ndef send(m):\n    sys.stdout.write(json.dumps(m) + '\\n'); sys.stdout.flush()\n"

HOMOGENEOUS = PRELUDE + """
send({'type': 'hello', 'protocol': 'topomark/protocol@1', 'role': 'world',
      'markers': {'directional-vertex': 1}, 'signature': '[3,A,A]'})
for line in sys.stdin:  # every vertex looks alike and the marker is never seen again: exploring never ends
    msg = json.loads(line)
    if msg['type'] not in ('drop', 'move'):
        break
    send({'type': 'signature', 'value': '[3,V-0,A]' if msg['type'] == 'drop' else '[3,A,A]'})
"""

FIDGET = PRELUDE + """
hello = json.loads(sys.stdin.readline())
for i in range(10 ** 9):  # drop and pick up the movable marker forever, never moving
    send({'type': 'pick_up' if i % 2 else 'drop', 'kind': 'vertex', 'count': 1})
    if json.loads(sys.stdin.readline())['type'] != 'signature':
        break
"""


def script(tmp_path: Path, name: str, body: str) -> list[str]:
    path = tmp_path / name
    path.write_text(body)
    return [sys.executable, str(path)]


def _peak(command: list[str], moves: int, record: bool) -> int:
    tracemalloc.start()
    try:
        result = drive(command, max_traversals=moves, record=record)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
        assert result.reason == "limit" and result.cost == moves


@pytest.mark.slow
def test_drive_without_a_trace_holds_no_growing_record_list(tmp_path):
    """3,000 more moves of a provider that never ends: without a trace the peak grows by far less than the
    records would take (about 350 bytes each, as the recording run shows)."""
    command = script(tmp_path, "homogeneous.py", HOMOGENEOUS)
    extra, bound = 3000, 3000 * 50
    growth = _peak(command, 1000 + extra, False) - _peak(command, 1000, False)
    assert growth < bound, growth
    kept = _peak(command, 1000 + extra, True) - _peak(command, 1000, True)
    assert kept > 4 * bound  # the bound would catch a driver that kept its records


def test_drive_streams_its_trace_to_the_file(tmp_path, capsys):
    command = script(tmp_path, "homogeneous.py", HOMOGENEOUS)
    trace = tmp_path / "t.jsonl"
    code = main(["drive", "--max-traversals", "500", "--trace", str(trace), "--json", "--", *command])
    assert code == 1 and json.loads(capsys.readouterr().out)["reason"] == "limit"
    lines = [json.loads(x) for x in trace.read_text().splitlines()]
    assert lines[0]["event"] == "header" and lines[-1] == {"event": "end", "cost": 500, "verified": False,
                                                           "violation": None}
    assert [r["step"] for r in lines if r["event"] == "move"] == list(range(1, 501))


def test_an_unwritable_drive_trace_is_refused_before_the_provider_starts(tmp_path, capsys):
    marker = tmp_path / "started"
    command = script(tmp_path, "p.py", f"open({str(marker)!r}, 'w').close()\n")
    assert main(["drive", "--trace", str(tmp_path / "no" / "t.jsonl"), "--", *command]) == 2
    assert "does not exist" in capsys.readouterr().err and not marker.exists()


# -- the simulator and run-external: marker operations are counted and capped ------------------------------------
def test_the_simulator_keeps_the_latest_operations_and_counts_them_all():
    world = g.cycle(3)
    sim = Simulator(world, world.start_state(), Kit(vertex=1, movable=True))
    for _ in range(EVENTS_KEPT):
        sim.operate(MarkerOp("vertex"))
        sim.operate(MarkerOp("vertex", pick_up=True))
    assert len(sim.events) == EVENTS_KEPT and sim.operations == {"drop": EVENTS_KEPT, "pick_up": EVENTS_KEPT}
    assert sim.events[-1]["op"] == "pick_up" and sim.cost == 0


@pytest.mark.parametrize("cap", [None, 300])
def test_a_program_that_only_drops_and_picks_up_ends_at_the_operation_cap(tmp_path, cap):
    world = g.cycle(4)
    limits = Limits(max_traversals=200, wall=60, max_operations=cap)
    result = run_external(world, script(tmp_path, "fidget.py", FIDGET), limits, version=2,
                          kit=Kit(vertex=1, movable=True))
    expected = cap or 1000  # the default: 2 x the traversal limit, at least 1000
    assert result.reason == "limit" and result.cost == 0 and result.operations == expected
    assert f"exceeds the limit of {expected} operations (--max-operations)" in result.message


def test_run_external_max_operations_on_the_command_line(tmp_path, capsys):
    code = main(["run-external", "cycle:n=4", "--kit", '{"undirected-vertex": 1, "movable": true}',
                 "--max-operations", "50", "--json", "--", *script(tmp_path, "fidget.py", FIDGET)])
    out = json.loads(capsys.readouterr().out)
    assert code == 1 and out["reason"] == "limit" and out["operations"] == 50 and out["cost"] == 0
    assert main(["run-external", "cycle:n=4", "--max-operations", "-1", "--", "true"]) == 2
    assert "--max-operations must be >= 0" in capsys.readouterr().err
