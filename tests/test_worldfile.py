"""Tests of topomark.spec.worldfile: the topomark/world@1 JSON format, its schema and strict loading."""

from __future__ import annotations

import json

import jsonschema
import pytest
from hypothesis import given, settings

from topomark.reference.worlds import generators as g
from topomark.reference.worlds.strategies import worlds
from topomark.spec.errors import InvalidWorld
from topomark.spec.marker import EdgeMarker, VertexMarker
from topomark.spec.world import Start, World
from topomark.spec.worldfile import (
    FORMAT, dumps_world, load_world, loads_world, save_world, schema, world_from_json, world_to_json,
)

FAST = settings(max_examples=80, deadline=None)


def validator():
    s = schema()
    cls = jsonschema.validators.validator_for(s)
    cls.check_schema(s)
    return cls(s)


VALIDATOR = validator()


# -- round trip and schema -------------------------------------------------------------
@FAST
@given(worlds(max_vertices=8, markers="any", with_start=True))
def test_json_round_trip_is_the_identity(w):
    text = dumps_world(w)
    back = loads_world(text)
    assert back == w
    assert list(back.rotation.items()) == list(w.rotation.items())  # vertex order and clockwise orders kept
    assert back.markers == w.markers
    assert back.start == w.start
    assert dumps_world(back) == text
    assert world_from_json(world_to_json(w)) == w


@FAST
@given(worlds(max_vertices=8, markers="any", with_start=True))
def test_every_written_file_validates_against_the_schema(w):
    obj = json.loads(dumps_world(w))
    VALIDATOR.validate(obj)
    assert obj["format"] == FORMAT


@pytest.mark.parametrize("w", [g.lattice(3, 4), g.wheel_a(), g.wheel_pair_directional()[1], g.DEFAULT_WORLD()])
def test_generated_worlds_round_trip_through_files(w, tmp_path):
    path = tmp_path / "w.json"
    save_world(w, path)
    VALIDATOR.validate(json.loads(path.read_text()))
    assert load_world(path) == w
    assert load_world(str(path)) == w


def test_written_shape():
    w = World({"a": ["b"], "b": ["a"]}, [VertexMarker("a", points_to="b"), EdgeMarker(("a", "b"), 2, head="a")],
              Start("b", "a"))
    assert json.loads(dumps_world(w)) == {
        "format": "topomark/world@1",
        "rotation": {"a": ["b"], "b": ["a"]},
        "markers": [{"kind": "vertex", "at": "a", "count": 1, "points_to": "b"},
                    {"kind": "edge", "between": ["a", "b"], "count": 2, "head": "a"}],
        "start": {"at": "b", "facing": "a"},
    }
    plain = json.loads(dumps_world(World({"a": ["b"], "b": ["a"]})))
    assert set(plain) == {"format", "rotation"}


def test_defaults_on_reading():
    w = loads_world('{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": ["a"]},'
                    ' "markers": [{"kind": "vertex", "at": "a"}, {"kind": "edge", "between": ["b", "a"]}]}')
    assert VertexMarker("a", 1, None) in w.markers and EdgeMarker(("b", "a"), 1, None) in w.markers
    assert w.start is None


# -- bad input ------------------------------------------------------------------------
def doc(rotation=None, **extra) -> str:
    obj = {"format": FORMAT, "rotation": {"a": ["b"], "b": ["a", "c"], "c": ["b"]} if rotation is None else rotation}
    obj.update(extra)
    return json.dumps(obj)


BAD = [
    ("malformed JSON", '{"format": "topomark/world@1",\n  "rotation": {"a": ["b"],}\n}',
     ["malformed JSON", "line 2", "column"]),
    ("truncated JSON", '{"format": "topomark/world@1", "rotation": {', ["malformed JSON", "line 1", "column"]),
    ("not an object", "[1, 2]", ["JSON object"]),
    ("unknown format", doc().replace("world@1", "world@2"), ["unknown format", "topomark/world@2"]),
    ("missing format", '{"rotation": {"a": ["b"], "b": ["a"]}}', ["missing key 'format'"]),
    ("missing rotation", '{"format": "topomark/world@1"}', ["missing key 'rotation'"]),
    ("unknown top-level key", doc(colour="red"), ["unknown key 'colour'"]),
    ("duplicate key", '{"format": "topomark/world@1", "rotation": {"a": ["b"], "b": ["a"], "a": ["b"]}}',
     ["duplicate key 'a'"]),
    ("duplicate top-level key", '{"format": "topomark/world@1", "format": "topomark/world@1", "rotation": {}}',
     ["duplicate key 'format'"]),
    ("empty world", doc({}), ["no vertices"]),
    ("rotation not an object", doc(["a", "b"]), ["rotation must be an object"]),
    ("neighbours not a list", doc({"a": "b", "b": ["a"]}), ["'a'", "must be a list"]),
    ("self-loop", doc({"a": ["a", "b"], "b": ["a"]}), ["self-loop", "'a'"]),
    ("multi-edge", doc({"a": ["b", "b"], "b": ["a"]}), ["multi-edge", "'a'", "'b'"]),
    ("asymmetric", doc({"a": ["b", "c"], "b": ["a", "c"], "c": ["a"]}), ["asymmetric", "'b' lists 'c'"]),
    ("disconnected", doc({"a": ["b"], "b": ["a"], "c": ["d"], "d": ["c"]}), ["disconnected", "'c'"]),
    ("degree 0", doc({"a": ["b"], "b": ["a"], "c": []}), ["'c'", "degree 0"]),
    ("unknown neighbour", doc({"a": ["b", "q"], "b": ["a"]}), ["'q'", "not a vertex"]),
    ("marker at non-vertex", doc(markers=[{"kind": "vertex", "at": "z"}]), ["'z'", "not a vertex"]),
    ("marker on non-edge", doc(markers=[{"kind": "edge", "between": ["a", "c"]}]), ["('a', 'c')", "not an edge"]),
    ("marker on missing vertex's edge", doc(markers=[{"kind": "edge", "between": ["a", "z"]}]), ["not an edge"]),
    ("points_to not a neighbour", doc(markers=[{"kind": "vertex", "at": "a", "points_to": "c"}]),
     ["'c'", "not a neighbour of 'a'"]),
    ("edge head not an end", doc(markers=[{"kind": "edge", "between": ["a", "b"], "head": "c"}]),
     ["head 'c'", "not an end"]),
    ("duplicate marker entries", doc(markers=[{"kind": "vertex", "at": "a"}, {"kind": "vertex", "at": "a"}]),
     ["two marker entries", "'a'"]),
    ("bad marker kind", doc(markers=[{"kind": "face", "at": "a"}]), ["markers[0]", "kind", '"face"']),
    ("missing marker kind", doc(markers=[{"at": "a"}]), ["markers[0]", "kind", "null"]),
    ("marker not an object", doc(markers=["a"]), ["markers[0]", "must be an object"]),
    ("markers not a list", doc(markers={"kind": "vertex", "at": "a"}), ["markers must be a list"]),
    ("count 0", doc(markers=[{"kind": "vertex", "at": "a", "count": 0}]), ["markers[0]", "count", "got 0"]),
    ("count negative", doc(markers=[{"kind": "edge", "between": ["a", "b"], "count": -2}]), ["count", "got -2"]),
    ("count non-integer", doc(markers=[{"kind": "vertex", "at": "a", "count": 1.5}]), ["count", "got 1.5"]),
    ("count string", doc(markers=[{"kind": "vertex", "at": "a", "count": "2"}]), ["count", 'got "2"']),
    ("count boolean", doc(markers=[{"kind": "vertex", "at": "a", "count": True}]), ["count", "got true"]),
    ("unknown marker key", doc(markers=[{"kind": "vertex", "at": "a", "head": "b"}]),
     ["markers[0]", "unknown key 'head'"]),
    ("marker missing at", doc(markers=[{"kind": "vertex"}]), ["markers[0]", "missing key 'at'"]),
    ("between of three", doc(markers=[{"kind": "edge", "between": ["a", "b", "c"]}]), ["two vertex names"]),
    ("facing not a neighbour", doc(start={"at": "a", "facing": "c"}), ["'c'", "not a neighbour of 'a'"]),
    ("start at non-vertex", doc(start={"at": "z", "facing": "a"}), ["'z'", "not a vertex"]),
    ("start missing facing", doc(start={"at": "a"}), ["start", "missing key 'facing'"]),
    ("start unknown key", doc(start={"at": "a", "facing": "b", "heading": 0}), ["start", "unknown key 'heading'"]),
    ("start not an object", doc(start="a"), ["start must be an object"]),
    ("non-string neighbour", doc({"a": ["b", 3], "b": ["a"]}), ["neighbour of vertex 'a'", "string", "3"]),
    ("non-string marker vertex", doc(markers=[{"kind": "vertex", "at": 1}]), ["markers[0].at", "string"]),
    ("non-string points_to", doc(markers=[{"kind": "vertex", "at": "a", "points_to": 0}]),
     ["markers[0].points_to", "string"]),
    ("non-string between", doc(markers=[{"kind": "edge", "between": ["a", 2]}]), ["markers[0].between[1]", "string"]),
    ("non-string head", doc(markers=[{"kind": "edge", "between": ["a", "b"], "head": ["a"]}]),
     ["markers[0].head", "string"]),
    ("non-string start", doc(start={"at": 0, "facing": "b"}), ["start.at", "string"]),
    ("null start", doc(start=None), ["start must be an object"]),
    ("null points_to", doc(markers=[{"kind": "vertex", "at": "a", "points_to": None}]),
     ["markers[0].points_to", "string", "null"]),
    ("null head", doc(markers=[{"kind": "edge", "between": ["a", "b"], "head": None}]),
     ["markers[0].head", "string", "null"]),
]


SHAPE_ERRORS = {
    "not an object", "unknown format", "missing format", "missing rotation", "unknown top-level key", "empty world",
    "rotation not an object", "neighbours not a list", "multi-edge", "bad marker kind", "missing marker kind",
    "marker not an object", "markers not a list", "count 0", "count negative", "count non-integer", "count string",
    "count boolean", "unknown marker key", "marker missing at", "between of three", "start missing facing",
    "start unknown key", "start not an object", "non-string neighbour", "non-string marker vertex",
    "non-string points_to", "non-string between", "non-string head", "non-string start", "null start",
    "null points_to", "null head", "degree 0",
}
"""The BAD cases the JSON Schema (which checks shape only) must reject too."""


@pytest.mark.parametrize("text, words", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_gives_one_message_naming_the_problem(text, words):
    with pytest.raises(InvalidWorld) as info:
        loads_world(text, "bad.json")
    message = str(info.value)
    assert message.startswith("bad.json: ")
    assert message.count("bad.json") == 1
    assert "\n" not in message
    for word in words:
        assert word in message, (word, message)
    assert info.value.__cause__ is None


@pytest.mark.parametrize("text", [b[1] for b in BAD if b[0] in SHAPE_ERRORS],
                         ids=[b[0] for b in BAD if b[0] in SHAPE_ERRORS])
def test_schema_rejects_what_is_wrong_in_shape(text):
    with pytest.raises(jsonschema.ValidationError):
        VALIDATOR.validate(json.loads(text))


def test_missing_file(tmp_path):
    path = tmp_path / "nowhere" / "world.json"
    with pytest.raises(InvalidWorld) as info:
        load_world(path)
    message = str(info.value)
    assert str(path) in message and "cannot read" in message and "\n" not in message


def test_directory_and_binary_files(tmp_path):
    with pytest.raises(InvalidWorld, match="not a regular file"):
        load_world(tmp_path)
    binary = tmp_path / "w.json"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    with pytest.raises(InvalidWorld, match="w.json"):
        load_world(binary)


def test_file_errors_carry_the_file_name(tmp_path):
    path = tmp_path / "loop.json"
    path.write_text(doc({"a": ["a", "b"], "b": ["a"]}))
    with pytest.raises(InvalidWorld) as info:
        load_world(path)
    assert str(info.value) == f"{path}: self-loop at vertex 'a'"


PARSEABLE = [b for b in BAD if not b[0].endswith("JSON") and "duplicate" not in b[0]]


@pytest.mark.parametrize("text", [b[1] for b in PARSEABLE], ids=[b[0] for b in PARSEABLE])
def test_loader_is_at_least_as_strict_as_the_schema(text):
    """Whatever the schema rejects the loader rejects; whatever the loader accepts the schema accepts."""
    obj = json.loads(text)
    with pytest.raises(InvalidWorld):
        world_from_json(obj)
    schema_ok = VALIDATOR.is_valid(obj)
    # the schema checks shape only: graph conditions pass it, shape errors do not
    assert schema_ok == (not any(text == b[1] for b in BAD if b[0] in SHAPE_ERRORS))
    assert SHAPE_ERRORS <= {b[0] for b in BAD}

