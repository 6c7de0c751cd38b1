"""``topomark/protocol@2`` (spec/protocol.md): the kit in ``hello``, drops and pick-ups of vertex and edge markers,
the version choice, the start anchor of snapshots, refusals and malformed operations, and ``drive`` with an @2
provider.  ``@1`` keeps working unchanged (``tests/test_protocol.py`` holds its own tests)."""

from __future__ import annotations

import ast
import json
import sys
from pathlib import Path

import pytest

from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.oracle.drive import drive
from topomark.reference.run.explore import explore
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.oracle.run_external import START_ANCHOR, run_external
from topomark.reference.oracle.protocol import Expect, ProtocolError, decode
from topomark.reference.oracle.snapshot_wire import map_to_snapshot, snapshot_to_map
from topomark.reference.oracle.marker_messages import op_from_message, op_to_message
from topomark.spec.errors import CheckFailure
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.mapstate import PartialMap
from topomark.spec.world import DartMark, Start, World
from topomark.spec.worldfile import dumps_world

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "reference" / "oracle" / "examples"
CLIENT, CLIENT2, PROVIDER = (str(EXAMPLES / name) for name in ("client.py", "client2.py", "provider.py"))
EDGE_KIT = Kit(edge=1, directional=True)
TRIANGLE = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, (), Start("a", "b"))
CHAIN = World({"a": ["b"], "b": ["a"]}, (), Start("a", "b"))





def play(command, world=TRIANGLE, kit=EDGE_KIT, version=2):
    return run_external(world, command, version=version, kit=kit)


# -- messages ---------------------------------------------------------------------
def test_decode_at_2_takes_the_markerop_fields_and_refuses_the_at_1_forms():
    two = Expect(("drop", "pick_up", "thread", "hello"), 2)
    assert decode('{"type": "drop", "kind": "edge", "exit": 1, "direction": "H", "count": 2}', two)["count"] == 2
    assert decode('{"type": "pick_up", "kind": "vertex"}', two) == {"type": "pick_up", "kind": "vertex"}
    assert decode('{"type": "hello", "protocol": "x", "role": "world", "kit": {}, "signature": "[1,A,A]"}', two)
    for line, words in [('{"type": "drop", "direction": 0}', "missing field 'kind'"),
                        ('{"type": "pick_up", "kind": "vertex", "direction": 0}', "unknown field 'direction'"),
                        ('{"type": "thread", "kind": "lay"}', "missing field 'op'")]:
        with pytest.raises(ProtocolError) as exc:
            decode(line, two)
        assert exc.value.kind == "garbage" and words in str(exc.value)
    with pytest.raises(ProtocolError) as exc:  # @1 has no pick_up: garbage as before
        decode('{"type": "pick_up", "kind": "vertex"}', ("drop",))
    assert exc.value.kind == "garbage" and "topomark/protocol@1" in str(exc.value)


def test_a_hello_of_any_version_is_validated_against_the_version_it_names():
    anyv = Expect(("hello",), None)
    assert "kit" in decode('{"type":"hello","protocol":"topomark/protocol@2","role":"world","kit":{},'
                           '"signature":"[1,A,A]"}', anyv)
    with pytest.raises(ProtocolError) as exc:
        decode('{"type":"hello","protocol":"topomark/protocol@2","role":"world","markers":{},'
               '"signature":"[1,A,A]"}', anyv)
    assert "missing field 'kit'" in str(exc.value)
    with pytest.raises(ProtocolError) as exc:
        decode('{"type":"hello","protocol":"topomark/protocol@7","role":"world"}', anyv)
    assert exc.value.kind == "protocol" and "topomark/protocol@7" in str(exc.value)


def test_ops_on_the_wire_are_markerop_to_json_minus_op():
    op = MarkerOp("edge", exit=2, direction="T", count=3)
    msg = op_to_message(op)
    assert msg == {"type": "drop", "kind": "edge", "exit": 2, "direction": "T", "count": 3}
    assert op_from_message(msg, 4) == op
    pick = MarkerOp("vertex", count=2, pick_up=True)
    assert op_from_message(op_to_message(pick), 1) == pick


def test_snapshot_edge_marks_round_trip_and_hold_at_both_ends_of_an_explored_edge():
    S = PartialMap()
    for d in (2, 1, 1):
        S.add_vertex(d)
    S.add_edge((0, 0), (1, 0))
    S.mark_dart(0, DartMark(0, 1, "H"))
    S.mark_dart(1, DartMark(0, 1, "T"))
    S.mark_dart(0, DartMark(1, 2, None))  # an unexplored edge: marked at this end only
    S.mark_vertex(2, 3, None)
    S.unexplored = [(0, 1), (2, 0)]
    msg = json.loads(json.dumps(map_to_snapshot(S, 2)))
    back = snapshot_to_map(msg["S"], msg["U"], 2)
    assert [back.dart_marks(v) for v in back.vertices] == [S.dart_marks(v) for v in S.vertices]
    assert back.vertex_mark(2) == S.vertex_mark(2)
    once = snapshot_to_map({"exits": [[[1, 0]], [[0, 0]]], "marks": [{"vertex": 0, "exit": 0, "end": "H"}]}, [], 2)
    assert once.dart_marks(1) == (DartMark(0, 1, "T"),)  # the far end, listed implicitly
    with pytest.raises(CheckFailure, match="marked twice, differently"):
        snapshot_to_map({"exits": [[[1, 0]], [[0, 0]]], "marks": [{"vertex": 0, "exit": 0, "end": "H"},
                                                                  {"vertex": 1, "exit": 0, "end": "H"}]}, [], 2)
    with pytest.raises(CheckFailure, match="must be"):  # @1 knows no edge marks
        snapshot_to_map({"exits": [[None]], "marks": [{"vertex": 0, "exit": 0, "end": "H"}]}, [[0, 0]], 1)


# -- the example clients --------------------------------------------------------------
def test_client2_is_standalone():
    tree = ast.parse(Path(CLIENT2).read_text())
    imported = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                for alias in node.names}
    imported |= {node.module.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
    assert imported <= {"json", "re", "sys", "collections"}


@pytest.mark.parametrize("world", [
    TRIANGLE, CHAIN, g.lattice_hole(5, 5, 0.1, seed=1).with_start(Start("0,0", "0,1")), g.wheel_pair_directional()[1],
    g.complete(5).with_start(Start("3", "1")), g.random_graph(9, 0.5, seed=5),
], ids=["triangle", "chain-2", "lattice-hole", "wheel-b", "K5", "random-9"])
def test_client2_passes_under_protocol_2_with_every_snapshot_checked(world):
    if world.start is None:
        world = world.with_start(Start(world.vertices[0], world.rotation[world.vertices[0]][0]))
    result = play([sys.executable, CLIENT2], world)
    assert result.passed, result.message
    assert result.snapshots == world.m and result.rule == "markers"


def test_the_algorithm_3_1_client_passes_at_1_and_at_2_with_its_kit_and_refuses_another_kit():
    assert run_external(TRIANGLE, [sys.executable, CLIENT]).passed
    assert run_external(TRIANGLE, [sys.executable, CLIENT], version=2).passed  # @2 with one directional vertex marker
    result = run_external(TRIANGLE, [sys.executable, CLIENT], version=2, kit=EDGE_KIT)
    assert not result.passed and result.reason == "crash" and "one directional vertex marker" in result.message


@pytest.mark.slow
def test_cli_client2_and_the_conformance_suite_at_2(tmp_path, capsys, default_suite):
    path = tmp_path / "w.json"
    path.write_text(dumps_world(g.lattice_hole(4, 4, 0.1, seed=2)))
    kit = '{"directional-edge": 1}'
    assert main(["run-external", str(path), "--protocol", "2", "--kit", kit, "--", sys.executable, CLIENT2]) == 0
    assert "PASS [ok]" in capsys.readouterr().out
    suite = default_suite
    assert main(["conformance", "run", str(suite), "-k", "lattice", "--kit", kit, "--json", "--",
                 sys.executable, CLIENT2]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["passed"] == report["total"] >= 3
    assert main(["conformance", "run", str(suite), "-k", "triangle", "--protocol", "2", "--",
                 sys.executable, CLIENT]) == 0  # @2 with Algorithm 3.1's kit: client.py speaks it
    assert main(["conformance", "run", str(suite), "-k", "triangle", "--kit", kit, "--",
                 sys.executable, CLIENT]) == 1  # any other kit: client.py refuses the hello


@pytest.mark.parametrize("args, words", [
    (["--protocol", "1", "--kit", '{"directional-edge": 1}'], "--kit needs topomark/protocol@2"),
    (["--kit", '{"directional-edge": 1, "thread": -3}'], "thread length must be a non-negative integer"),
    (["--kit", '{"sideways-edge": 1}'], "unknown key"),
    (["--kit", "{"], "--kit"),
    (["--kit", "{}"], "give 1..1,000,000"),
    (["--kit", '{"undirected-edge": 10000001}'], "edge markers: at most 1,000,000"),
    (["--protocol", "3"], "invalid choice"),
])
def test_cli_protocol_and_kit_bad_input_exits_2(args, words, capsys):
    for command in (["run-external", "cycle:n=4"], ["conformance", "run", "nosuchdir"]):
        assert main(command + args + ["--", sys.executable, CLIENT2]) == 2
        err = capsys.readouterr().err
        assert words in err and "Traceback" not in err


# -- judging at @2 -------------------------------------------------------------------
@pytest.mark.slow
@pytest.mark.parametrize("markers, verdict", [
    ([{"kind": "edge", "between": ["s0", "s1"], "count": 1, "head": "s0"}], "pass"),
    ([{"kind": "edge", "between": ["s0", "s1"], "count": 1, "head": "s1"}], "pass"),  # an isomorphism: s0 -> b
    ([{"kind": "edge", "between": ["s0", "s1"], "count": 2, "head": "s0"}], "fail"),
    ([{"kind": "edge", "between": ["s0", "s1"], "count": 1}], "fail"),
    ([], "fail"),  # the map must show the marker the program dropped
    ([{"kind": "vertex", "at": "s0", "points_to": "s1"}], "fail"),  # ... and no other
])
def test_the_map_must_show_the_markers_the_program_left(scripted, markers, verdict):
    the_map = {"format": "topomark/world@1", "rotation": {"s0": ["s1"], "s1": ["s0"]}, "markers": markers}
    result = play(scripted({"type": "drop", "kind": "edge", "exit": 0, "direction": "H"}, {"type": "move", "motion": 0},
                           {"type": "map", "world": the_map}), CHAIN)
    assert result.verdict == verdict, result.message
    assert result.reason == ("ok" if verdict == "pass" else "not-isomorphic")


@pytest.mark.slow
def test_a_picked_up_marker_is_gone_from_the_world_the_map_is_judged_against(scripted):
    the_map = {"format": "topomark/world@1", "rotation": {"s0": ["s1"], "s1": ["s0"]}}
    result = play(scripted({"type": "drop", "kind": "vertex"}, {"type": "pick_up", "kind": "vertex"},
                           {"type": "move", "motion": 0}, {"type": "map", "world": the_map}), CHAIN,
                  Kit(vertex=1, movable=True))  # the edge crossed: the map is known, not guessed
    assert result.passed, result.message


def test_snapshots_at_2_anchor_at_the_start_and_say_so_when_wrong(scripted):
    drop = {"type": "drop", "kind": "edge", "exit": 0, "direction": "H"}
    good = {"type": "snapshot", "S": {"exits": [[None, None]], "marks": [{"vertex": 0, "exit": 0, "end": "H"}]},
            "U": [[0, 0], [0, 1]]}
    shifted = {"type": "snapshot", "S": {"exits": [[None, None]], "marks": [{"vertex": 0, "exit": 1, "end": "H"}]},
               "U": [[0, 0], [0, 1]]}
    result = play(scripted(drop, good, shifted))
    assert result.reason == "invariant" and "snapshot 2" in result.message and START_ANCHOR in result.message
    result = play(scripted(drop, {"type": "snapshot", "S": {"exits": [[None]], "marks": []}, "U": [[0, 0]]}))
    assert result.reason == "invariant" and "map vertex 0 (the start)" in result.message


# -- refusals and malformed operations ---------------------------------------------------
@pytest.mark.parametrize("kit, ops, words", [
    (EDGE_KIT, [{"type": "drop", "kind": "vertex", "direction": 0}], "has no vertex marker"),
    (EDGE_KIT, [{"type": "drop", "kind": "edge", "exit": 0}], "holds directional markers only"),
    (EDGE_KIT, [{"type": "drop", "kind": "edge", "exit": 0, "direction": "H", "count": 2}], "1 left, 2 asked for"),
    (Kit(vertex=2, directional=True), [{"type": "drop", "kind": "vertex", "direction": 0},
                                       {"type": "drop", "kind": "vertex", "direction": 1}], "cannot join"),
    (Kit(edge=2, directional=True), [{"type": "drop", "kind": "edge", "exit": 0, "direction": "H"},
                                     {"type": "drop", "kind": "edge", "exit": 0, "direction": "T"}], "cannot join"),
    (Kit(vertex=1, movable=True), [{"type": "pick_up", "kind": "vertex"}], "no vertex marker here to pick up"),
    (Kit(edge=1, movable=True), [{"type": "pick_up", "kind": "edge", "exit": 1}],
     "no edge marker on the edge at exit 1 to pick up"),
    (Kit(vertex=1), [{"type": "drop", "kind": "vertex"}, {"type": "pick_up", "kind": "vertex"}], "immovable"),
])
def test_an_operation_the_kit_or_the_markers_refuse_is_a_marker_failure(scripted, kit, ops, words):
    result = play(scripted(*ops), TRIANGLE, kit)
    assert result.reason == "marker", result.message
    assert words in result.message and "refused" in result.message and "violated" not in result.message


@pytest.mark.parametrize("op, words", [
    ({"type": "drop", "kind": "thread"}, "kind must be"),
    ({"type": "drop", "kind": "vertex", "exit": 0}, "takes no exit"),
    ({"type": "drop", "kind": "vertex", "direction": 2}, "an exit 0..1"),
    ({"type": "drop", "kind": "vertex", "direction": "H"}, "an exit 0..1"),
    ({"type": "drop", "kind": "vertex", "direction": True}, "must be integer, string or null"),
    ({"type": "drop", "kind": "edge", "direction": "H"}, "needs an exit"),
    ({"type": "drop", "kind": "edge", "exit": 2, "direction": "H"}, "needs an exit 0..1"),
    ({"type": "drop", "kind": "edge", "exit": -1, "direction": "H"}, "needs an exit 0..1"),
    ({"type": "drop", "kind": "edge", "exit": 0, "direction": 0}, "\"H\", \"T\" or null"),
    ({"type": "drop", "kind": "edge", "exit": 0, "direction": "X" * 5000}, "\"H\", \"T\" or null"),
    ({"type": "drop", "kind": "edge", "exit": 0, "direction": "H", "count": 0}, "count must be an integer 1..1000000"),
    ({"type": "drop", "kind": "edge", "exit": 0, "direction": "H", "count": 10 ** 6 + 1}, "count must be"),
    ({"type": "pick_up", "kind": "edge", "exit": 0, "count": "1"}, "must be integer"),
    ({"type": "thread", "op": "lay"}, "op must be one of tie, untie"),
    ({"type": "thread", "op": "leave", "direction": 0}, "on a tie only"),
    ({"type": "thread", "op": "tie", "count": 2}, "1 but for a knot"),
])
def test_a_malformed_operation_is_garbage_with_a_bounded_message(scripted, op, words):
    result = play(scripted(op))
    assert result.reason == "garbage", result.message
    assert words in result.message and len(result.message) < 400


# -- drive with an @2 provider ---------------------------------------------------------------
def provider(path: Path, *extra: str) -> list[str]:
    return [sys.executable, PROVIDER, str(path), *extra]


def test_drive_with_an_at_2_provider_is_the_same_run_as_at_1(tmp_path):
    world = g.lattice_hole(5, 5, 0.1, seed=1).with_start(Start("0,0", "0,1"))
    path = tmp_path / "w.json"
    path.write_text(dumps_world(world))
    result = drive(provider(path, "--protocol", "2"), world=world, record=True)
    assert result.passed and result.check.isomorphic, result.message
    assert result.cost == explore(world).cost and result.trace


@pytest.mark.parametrize("name, kit", [("directional-edge", '{"directional-edge": 1}'),
                                       ("three-undirected-edge", '{"undirected-edge": 3}')])
def test_drive_another_lighthouse_needs_an_at_2_provider_with_its_kit(tmp_path, name, kit):
    world = g.complete(5).with_start(Start("3", "1"))
    path = tmp_path / "w.json"
    path.write_text(dumps_world(world))
    result = drive(provider(path, "--protocol", "2", "--kit", kit), world=world, light=LIGHTHOUSES[name], record=True)
    assert result.passed and result.check.isomorphic, result.message
    assert result.trace[0]["format"] == "topomark/trace@2"  # trace@1 cannot record these drops
    assert [r["kind"] for r in result.trace if r["event"] == "op"] == [op.kind for op in LIGHTHOUSES[name].ops]
    at1 = drive(provider(path), light=LIGHTHOUSES[name])
    assert at1.reason == "protocol" and "needs a provider speaking topomark/protocol@2" in at1.message
    short = drive(provider(path, "--protocol", "2"), light=LIGHTHOUSES[name])
    assert short.reason == "protocol" and "cannot be dropped with the provider's kit" in short.message


def test_cli_drive_lighthouse(tmp_path, capsys):
    path = tmp_path / "w.json"
    path.write_text(dumps_world(TRIANGLE))
    cmd = ["--", sys.executable, PROVIDER, str(path), "--protocol", "2", "--kit", '{"directional-edge": 1}']
    assert main(["drive", "--lighthouse", "directional-edge", "--check", str(path)] + cmd) == 0
    assert "PASS" in capsys.readouterr().out
    assert main(["drive", "--lighthouse", "directional-edge", "--trace", str(tmp_path / "t.jsonl")] + cmd) == 0
    capsys.readouterr()
    assert '"format":"topomark/trace@2"' in (tmp_path / "t.jsonl").read_text().splitlines()[0]
    assert main(["drive", "--lighthouse", "lamp"] + cmd) == 2
    assert "unknown lighthouse 'lamp'" in capsys.readouterr().err
