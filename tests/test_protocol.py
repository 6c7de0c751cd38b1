"""``topomark/protocol@1`` and ``run-external`` (spec/protocol.md): the example client passes, wrong ones fail."""

from __future__ import annotations

import ast
import json
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.spec.kit import MarkerOp
from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.oracle.run_external import REASONS, Limits, run_external
from topomark.reference.oracle.protocol import ProtocolError, decode
from topomark.reference.oracle.snapshot_wire import map_to_snapshot, snapshot_to_map
from topomark.spec.errors import CheckFailure, InvalidInput
from topomark.spec.invariants import check_invariants, lighthouse_anchor
from topomark.spec.marker import VertexMarker
from topomark.spec.world import Start, World
from topomark.spec.worldfile import dumps_world

ROOT = Path(__file__).resolve().parents[1]
CLIENT = str(ROOT / "reference" / "oracle" / "examples" / "client.py")
WRONG = str(Path(__file__).resolve().parent / "clients" / "wrong_client.py")
TRIANGLE = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, (), Start("a", "b"))


def client(*extra: str) -> list[str]:
    return [sys.executable, CLIENT, *extra]


def wrong(fault: str) -> list[str]:
    return [sys.executable, WRONG, fault]


# -- messages --------------------------------------------------------------------
def test_decode_accepts_every_documented_message():
    assert decode('{"type": "move", "motion": 2}') == {"type": "move", "motion": 2}
    assert decode('{"type": "drop", "direction": null}')["direction"] is None
    assert decode('{"type": "bye", "verdict": "pass", "cost": 3}')["cost"] == 3
    assert decode('{"type": "snapshot", "S": {}, "U": [], "iteration": 1}')["iteration"] == 1


@pytest.mark.parametrize("line, words", [
    ("hello", "not a JSON object"),
    ("[1, 2]", "not a message"),
    ('{"motion": 1}', "not a message"),
    ('{"type": "jump", "motion": 1}', "unknown message type 'jump'"),
    ('{"type": "move"}', "missing field 'motion'"),
    ('{"type": "move", "motion": 1, "speed": 2}', "unknown field 'speed'"),
    ('{"type": "move", "motion": true}', "move.motion must be integer"),
    ('{"type": "move", "motion": "1"}', "move.motion must be integer"),
])
def test_decode_rejects_garbage_with_a_precise_message(line, words):
    with pytest.raises(ProtocolError) as exc:
        decode(line)
    assert exc.value.kind == "garbage" and words in str(exc.value)


def test_decode_rejects_a_valid_message_at_the_wrong_time():
    with pytest.raises(ProtocolError) as exc:
        decode('{"type": "map", "world": {}}', expect=("signature",))
    assert exc.value.kind == "protocol"


def test_snapshot_round_trip_preserves_S_U_and_the_invariants():
    world = g.lattice_hole(4, 4, 0.1, seed=1).with_start(None)
    S = explore(world).explorer.S
    msg = json.loads(json.dumps(map_to_snapshot(S)))
    back = snapshot_to_map(msg["S"], msg["U"])
    assert back.to_world() == S.to_world() and back.unexplored == S.unexplored
    v0 = world.vertices[0]
    truth = World(world.rotation, [VertexMarker(v0, 1, world.rotation[v0][0])])
    assert check_invariants(back, truth, lighthouse_anchor(back, truth)) is None


def test_snapshot_with_a_one_way_edge_is_rejected():
    with pytest.raises(CheckFailure, match="does not lead back"):
        snapshot_to_map({"exits": [[[1, 0]], [None]], "marks": []}, [])
    with pytest.raises(CheckFailure, match="non-empty list"):
        snapshot_to_map({"exits": [[]], "marks": []}, [])


darts = st.one_of(st.none(), st.lists(st.integers(-1, 4), min_size=2, max_size=2), st.integers(), st.text(max_size=2))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.lists(darts, max_size=4), max_size=5),
       st.lists(st.fixed_dictionaries({"vertex": st.integers(-1, 5), "head": st.one_of(st.none(), st.integers(-1, 4))}),
                max_size=2),
       st.lists(darts, max_size=5))
def test_any_snapshot_is_judged_never_crashes(exits, marks, U):
    """Whatever a program sends as a snapshot, the world side gives a verdict (or accepts it) - no exception."""
    from topomark.reference.oracle.run_external import _Fail, _Session

    class Quiet:
        def send(self, msg, timeout=None):
            pass

    session = _Session(TRIANGLE, Quiet(), Limits(), True)
    session.sim.operate(MarkerOp("vertex", direction=0))
    try:
        session.snapshot({"type": "snapshot", "S": {"exits": exits, "marks": marks}, "U": U})
    except _Fail as exc:
        assert exc.reason in ("snapshot", "invariant")


# -- the example client ------------------------------------------------------------
def test_example_client_is_standalone():
    tree = ast.parse(Path(CLIENT).read_text())
    mods = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    mods |= {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert mods <= {"json", "re", "sys", "collections"}, mods


@pytest.mark.parametrize("world", [
    TRIANGLE, g.wheel_pair_directional()[0], g.wheel_pair_directional()[1], g.chain(2).with_start(None),
    g.lattice_hole(5, 5, 0.1, seed=1), g.complete(5), g.random_graph(9, 0.5, seed=3),
], ids=["triangle", "wheel-a", "wheel-b", "chain-2", "lattice-hole", "K5", "random"])
def test_example_client_passes_with_every_snapshot_checked(world):
    result = run_external(world, client())
    assert result.passed, result.message
    assert result.reason == "ok" and result.snapshots == world.m and result.cost >= world.m
    assert result.rule == "markers"


def test_example_client_on_the_triangle_costs_three():
    result = run_external(TRIANGLE, client())
    assert (result.verdict, result.cost, result.snapshots) == ("pass", 3, 3)


# -- deliberately wrong clients -------------------------------------------------------
@pytest.mark.parametrize("fault, reason, words", [
    ("trust-first", "invariant", "I-1 violated"),
    ("keep-e-prime", "invariant", "I-2 violated"),
    ("mirror-map", "not-isomorphic", "not isomorphic"),
    ("garbage", "garbage", "Hello, topomark"),
    ("crash", "crash", "segmentation fault (simulated)"),
    ("bad-exit", "bad-exit", "motion 99 does not exist"),
    ("greedy", "limit", "exceeds the limit of 300"),
    ("no-map", "crash", "closed its output (exit status 0)"),
    ("bad-map", "map-invalid", "degree 0"),
    ("undirected-drop", "marker", "undirected marker"),
    ("two-drops", "marker", "none left"),
])
def test_wrong_clients_get_a_clear_verdict(fault, reason, words):
    world = g.lattice_hole(5, 5, 0.1, seed=1)
    result = run_external(world, wrong(fault), Limits(max_traversals=300 if fault == "greedy" else None, message=5))
    assert (result.verdict, result.reason) == ("fail", reason), result.message
    assert words in result.message + " ".join(result.stderr)
    assert reason in REASONS


def test_a_hanging_client_times_out_per_message_and_by_wall_time():
    slow = run_external(TRIANGLE, wrong("hang"), Limits(message=0.5, wall=30))
    assert slow.reason == "timeout" and "no message within 0.5 s" in slow.message and slow.wall < 5
    wall = run_external(TRIANGLE, wrong("hang"), Limits(message=30, wall=0.7))
    assert wall.reason == "timeout" and "wall-time limit of 0.7 s" in wall.message and wall.wall < 5


def test_a_client_that_stops_reading_cannot_block_topomark():
    result = run_external(g.cycle(5), wrong("flood"), Limits(max_traversals=10 ** 7, message=0.5, wall=30))
    assert result.reason == "timeout" and "stopped reading its input" in result.message and result.wall < 10


def test_invariant_violation_names_the_snapshot_and_the_iteration_state():
    result = run_external(g.lattice_hole(5, 5, 0.1, seed=1), wrong("keep-e-prime"))
    assert result.message.startswith("snapshot ") and result.violation.check == "I-2"


# -- CLI -------------------------------------------------------------------------
def test_cli_run_external_json(tmp_path, capsys):
    world = tmp_path / "tri.json"
    world.write_text(dumps_world(TRIANGLE))
    out = tmp_path / "map.json"
    code = main(["run-external", str(world), "--json", "--map", str(out), "--", *client()])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["verdict"] == "pass" and data["cost"] == 3
    assert main(["check-map", str(world), str(out)]) == 0


def test_cli_run_external_failure_exits_1(capsys):
    assert main(["run-external", "cycle:n=5", "--", *wrong("bad-exit")]) == 1
    assert "FAIL [bad-exit]" in capsys.readouterr().out


@pytest.mark.parametrize("args, words", [
    (["run-external", "cycle:n=5"], "give the program to run after --"),
    (["run-external", "cycle:n=5", "--"], "give the program to run after --"),
    (["run-external", "cycle:n=5", "--", "/nonexistent/explorer"], "cannot start"),
    (["run-external", "wheel-a:marker=undirected", "--", "true"], "or the one Algorithm 3.1's robot drops"),
    (["run-external", "cycle:n=5", "--timeout", "0", "--", "true"], "--timeout must be positive"),
    (["run-external", "nosuch.json", "--", "true"], "cannot read the file"),
])
def test_cli_run_external_bad_input_exits_2(args, words, capsys):
    assert main(args) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err


def test_cli_run_external_rejects_bad_world_files(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "topomark/world@2", "rotation": {}}')
    assert main(["run-external", str(bad), "--", "true"]) == 2
    assert "unknown format 'topomark/world@2'" in capsys.readouterr().err
    bad.write_text('{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": []}')
    assert main(["run-external", str(bad), "--", "true"]) == 2
    assert "malformed JSON" in capsys.readouterr().err


# -- check-map ---------------------------------------------------------------------
def _map_of(world: World) -> World:
    return explore(world).explorer.S.to_world()


def test_check_map_rules(tmp_path, capsys):
    world = g.lattice_hole(4, 4, 0.1, seed=2).with_start(Start("0,0", "0,1"))
    map_ = _map_of(world)
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "m.json").write_text(dumps_world(map_))
    assert main(["check-map", str(tmp_path / "w.json"), str(tmp_path / "m.json"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["rule"] == "lighthouse"
    # the same map checked against a world whose start faces elsewhere: the lighthouse is misplaced
    (tmp_path / "w2.json").write_text(dumps_world(world.with_start(Start("0,0", "1,0"))))
    assert main(["check-map", str(tmp_path / "w2.json"), str(tmp_path / "m.json"), "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["rule"] == "lighthouse" and not data["isomorphic"] and data["mismatch"]["where"]
    # no start: markers ignored
    (tmp_path / "w3.json").write_text(dumps_world(world.with_start(None)))
    assert main(["check-map", str(tmp_path / "w3.json"), str(tmp_path / "m.json"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["rule"] == "graph"


def test_check_map_reports_the_first_mismatch_in_words(tmp_path, capsys):
    world = g.lattice(3, 3)
    other = g.lattice_hole(3, 3, 0.2, "edges", seed=1)
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "m.json").write_text(dumps_world(other))
    assert main(["check-map", str(tmp_path / "w.json"), str(tmp_path / "m.json")]) == 1
    out = capsys.readouterr().out
    assert "not isomorphic" in out and "expected" in out and "found" in out


def test_check_map_world_markers_must_appear_in_the_map(tmp_path, capsys):
    wa = g.wheel_pair_directional()[0]
    plain = World(wa.rotation)
    (tmp_path / "w.json").write_text(dumps_world(wa))
    (tmp_path / "m.json").write_text(dumps_world(plain))
    assert main(["check-map", str(tmp_path / "w.json"), str(tmp_path / "m.json"), "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["rule"] == "markers"


def test_check_map_bad_input(tmp_path, capsys):
    (tmp_path / "w.json").write_text(dumps_world(TRIANGLE))
    (tmp_path / "m.json").write_text("{}")
    assert main(["check-map", str(tmp_path / "w.json"), str(tmp_path / "m.json")]) == 2
    assert "missing key 'format'" in capsys.readouterr().err


def test_peer_refuses_an_empty_command():
    with pytest.raises(InvalidInput):
        run_external(TRIANGLE, [])


def test_the_example_session_in_spec_protocol_md_is_what_really_happens(tmp_path):
    """The documented triangle session, message by message (the hello's limits elided in the doc)."""
    text = (ROOT / "spec" / "protocol.md").read_text()
    block = text.split("## Example session")[1].split("```")[1]
    documented = [(line[0], json.loads(line[2:].replace('"limits":{...},', "")))
                  for line in block.strip().splitlines()]
    log = tmp_path / "session.txt"
    tee = [sys.executable, str(Path(__file__).resolve().parent / "clients" / "tee_client.py"), str(log)]
    assert run_external(TRIANGLE, tee).passed
    actual = [(line[0], json.loads(line[2:])) for line in log.read_text().splitlines()]
    actual[0][1].pop("limits")
    assert actual == documented
