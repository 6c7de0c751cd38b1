"""``spec/protocol.schema.json``: every message topomark sends and the example programs send validates against its
definition; topomark reads by that schema, and a line that breaks it is named by its field; the rules of
``spec/protocol.md`` an implementer asked about (head may be omitted, a map may carry start, snapshots before the
first move) hold as written; every JSON example of "The map" is a valid world."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from jsonschema import Draft202012Validator
from referencing import Registry, Resource

from topomark.reference.oracle.drive import drive
from topomark.reference.oracle.protocol import SCHEMA, Expect, ProtocolError, decode
from topomark.reference.oracle.run_external import run_external
from topomark.reference.oracle.snapshot_wire import snapshot_to_map
from topomark.reference.worlds import generators as g
from topomark.spec.kit import Kit
from topomark.spec.world import Start, World
from topomark.spec.worldfile import dumps_world, loads_world, schema as world_schema

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "reference" / "oracle" / "examples"
TEE = str(Path(__file__).resolve().parent / "clients" / "tee_client.py")
TRIANGLE = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, (), Start("a", "b"))
REGISTRY = Registry().with_resources([(s["$id"], Resource.from_contents(s)) for s in (SCHEMA, world_schema())])


def message_validator(version: int) -> Draft202012Validator:
    return Draft202012Validator({"$ref": f"{SCHEMA['$id']}#/$defs/message@{version}"}, registry=REGISTRY)


def session(tmp_path: Path, play, *program: str) -> list[tuple[str, dict]]:
    log = tmp_path / "session.txt"
    result = play([sys.executable, TEE, str(log), sys.executable, *program])
    assert result.passed, result.message
    return [(line[0], json.loads(line[2:])) for line in log.read_text().splitlines()]


def assert_valid(lines: list[tuple[str, dict]], version: int) -> set[str]:
    validator = message_validator(version)
    for side, msg in lines:
        errors = [e.message for e in validator.iter_errors(msg)]
        assert not errors, (side, msg, errors[:3])
    return {msg["type"] for _, msg in lines}


def test_the_schema_is_a_valid_draft_2020_12_schema_with_one_definition_per_message():
    Draft202012Validator.check_schema(SCHEMA)
    assert {"hello@1", "hello@2", "move", "drop@1", "drop@2", "pick_up", "thread", "signature", "snapshot@1",
            "snapshot@2", "map", "bye", "error"} <= set(SCHEMA["$defs"])


def test_the_schema_ships_in_the_package():
    """Read as package data of ``topomark.spec``; the wheel holds every file of the package (tests/test_install.py)."""
    import importlib.resources
    shipped = importlib.resources.files("topomark.spec") / "protocol.schema.json"
    assert json.loads(shipped.read_text(encoding="utf-8")) == SCHEMA


def test_every_message_of_an_at_1_session_validates(tmp_path):
    world = g.lattice_hole(4, 4, 0.1, seed=2).with_start(Start("0,0", "0,1"))
    lines = session(tmp_path, lambda cmd: run_external(world, cmd), str(EXAMPLES / "client.py"))
    assert assert_valid(lines, 1) == {"hello", "drop", "signature", "move", "snapshot", "map", "bye"}


def test_every_message_of_an_at_2_session_validates(tmp_path):
    world = g.complete(5).with_start(Start("3", "1"))
    kit = Kit(edge=1, directional=True)
    lines = session(tmp_path, lambda cmd: run_external(world, cmd, version=2, kit=kit), str(EXAMPLES / "client2.py"))
    assert assert_valid(lines, 2) == {"hello", "drop", "signature", "move", "snapshot", "map", "bye"}
    assert any(m["type"] == "snapshot" and any("exit" in k for k in m["S"]["marks"]) for _, m in lines)


@pytest.mark.parametrize("version", [1, 2])
def test_every_message_topomark_sends_as_the_explorer_validates(tmp_path, version):
    path = tmp_path / "w.json"
    path.write_text(dumps_world(g.cycle(5).with_start(Start("0", "1"))))
    extra = ("--protocol", "2") if version == 2 else ()
    lines = session(tmp_path, lambda cmd: drive(cmd), str(EXAMPLES / "provider.py"), str(path), *extra)
    assert assert_valid(lines, version) == {"hello", "drop", "signature", "move", "map", "bye"}


@pytest.mark.parametrize("line, version, words", [
    ('{"type":"hello","protocol":"topomark/protocol@2","role":"world","kit":{"purple-vertex":1},"signature":"[1,A,A]"}',
     2, "hello.kit: unknown field 'purple-vertex'"),
    ('{"type":"hello","protocol":"topomark/protocol@2","role":"world","kit":{"movable":1},"signature":"[1,A,A]"}',
     2, "hello.kit.movable must be boolean, got 1"),
    ('{"type":"hello","protocol":"topomark/protocol@1","role":"world","markers":{},"signature":"[1,A,A]",'
     '"limits":{"max_traversals":"9"}}', 1, "hello.limits.max_traversals must be integer"),
    ('{"type":"bye","verdict":"maybe"}', 1, 'bye.verdict must be one of pass, fail, got "maybe"'),
    ('{"type":"bye","cost":-1}', 1, "bye.cost must be at least 0"),
    ('{"type":"drop","direction":"0"}', 1, "drop.direction must be integer or null"),
    ('{"type":"thread","op":"knot","count":0}', 2, "thread.count must be an integer 1..1000000, got 0"),
    ('{"type":"drop","kind":"vertex","count":1.5}', 2, "drop.count must be integer"),
    ('{"type":"move","motion":1.0}', 1, "move.motion must be integer, got 1.0"),
    ('{"type":"snapshot","S":[],"U":[]}', 1, "snapshot.S must be object"),
    ('{"type":"map"}', 1, "map message: missing field 'world'"),
])
def test_a_line_that_breaks_its_schema_is_garbage_naming_the_field(line, version, words):
    with pytest.raises(ProtocolError) as exc:
        decode(line, Expect(("hello", "bye", "move", "drop", "thread", "snapshot", "map"), version))
    assert exc.value.kind == "garbage" and words in str(exc.value), str(exc.value)




def test_a_malformed_snapshot_is_a_snapshot_failure_naming_the_field(scripted):
    bad = {"type": "snapshot", "S": {"exits": [[None, None]], "marks": [{"vertex": 0, "head": "x"}]}, "U": []}
    result = run_external(TRIANGLE, scripted({"type": "drop", "direction": 0}, bad))
    assert result.reason == "snapshot" and "snapshot 1 is malformed: snapshot.S.marks[0].head must be integer or null" \
        in result.message, result.message


def test_a_vertex_mark_may_omit_head_meaning_undirected():
    for version in (1, 2):
        S = snapshot_to_map({"exits": [[None]], "marks": [{"vertex": 0}]}, [[0, 0]], version)
        mark = S.vertex_mark(0)
        assert mark.head is None and mark.count == 1
    assert not list(message_validator(1).iter_errors(
        {"type": "snapshot", "S": {"exits": [[None]], "marks": [{"vertex": 0}]}, "U": [[0, 0]]}))


@pytest.mark.slow
def test_an_undirected_snapshot_mark_without_head_passes_a_run(scripted):
    chain = World({"a": ["b"], "b": ["a"]}, (), Start("a", "b"))
    snap = {"type": "snapshot", "S": {"exits": [[None]], "marks": [{"vertex": 0}]}, "U": [[0, 0]]}
    final = {"type": "map", "world": {"format": "topomark/world@1", "rotation": {"x": ["y"], "y": ["x"]},
                                      "markers": [{"kind": "vertex", "at": "x"}]}}
    there_and_back = ({"type": "move", "motion": 0}, {"type": "move", "motion": 0})  # crossed: the map is known
    result = run_external(chain, scripted({"type": "drop", "kind": "vertex"}, snap, *there_and_back, final),
                          version=2, kit=Kit(vertex=1))
    assert result.passed and result.snapshots == 1, result.message


def test_a_snapshot_may_come_after_the_drop_before_the_first_move_but_not_before_the_drop_in_at_1(scripted):
    snap = {"type": "snapshot", "iteration": 7, "S": {"exits": [[None, None]], "marks": [{"vertex": 0, "head": 0}]},
            "U": [[0, 0], [0, 1]]}
    drop = {"type": "drop", "direction": 0}
    after = run_external(TRIANGLE, scripted(drop, snap, {**snap, "iteration": 3}, {"type": "error", "message": "x"}))
    assert after.reason == "crash" and after.snapshots == 2, after.message  # both held; iteration is only a label
    before = run_external(TRIANGLE, scripted({**snap, "S": {**snap["S"], "marks": []}}))
    assert before.reason == "invariant" and "one directional marker" in before.message, before.message


@pytest.mark.slow
def test_a_map_may_carry_a_start_which_is_not_judged(scripted):
    drop = {"type": "drop", "direction": 0}
    world = {"format": "topomark/world@1", "rotation": {"p": ["q", "r"], "q": ["r", "p"], "r": ["p", "q"]},
             "markers": [{"kind": "vertex", "at": "p", "points_to": "q"}], "start": {"at": "r", "facing": "q"}}
    round_to_the_marker = [{"type": "move", "motion": 1}] * 3  # every edge crossed, the marker seen again
    assert run_external(TRIANGLE, scripted(drop, *round_to_the_marker, {"type": "map", "world": world})).passed
    wrong = run_external(TRIANGLE, scripted(drop, {"type": "map", "world": {**world, "start": {"at": "z",
                                                                                             "facing": "q"}}}))
    assert wrong.reason == "map-invalid", wrong.message


def test_every_json_example_of_the_map_section_is_a_valid_world():
    text = (ROOT / "spec" / "protocol.md").read_text().split("## The map", 1)[1].split("\n## ", 1)[0]
    block = json.loads(text.split("```json\n", 1)[1].split("```", 1)[0])
    rows = [line.split("|")[2].strip().strip("`") for line in text.splitlines() if line.startswith("| ") and "{" in line]
    assert len(rows) == 7
    rotation = {"s0": ["s1", "s2", "s3"], "s1": ["s0", "s2"], "s2": ["s1", "s0"], "s3": ["s0"]}
    loads_world(json.dumps(block))
    for row in rows:
        world = loads_world(json.dumps({"format": "topomark/world@1", "rotation": rotation,
                                        "markers": [json.loads(row)]}))
        assert len(world.markers) == 1, row
    thread = {"walk": ["s0", "s1", "s2"], "points_to": "s1", "end": "held", "knots": [[1, 2]]}
    assert json.dumps(thread) in text.replace("\n  ", " ")
    loads_world(json.dumps({"format": "topomark/world@1", "rotation": rotation, "thread": thread}))
