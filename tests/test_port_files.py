"""Tests of the port world file format topomark/port-world@1 (spec/port_worldfile.py, its JSON Schema), of
reference/port/files.py's one reader, and of the contest maps copied into tests/data/icfpc2025/."""

from __future__ import annotations

import csv
import hashlib
import json
from pathlib import Path

import jsonschema
import pytest
from hypothesis import given, settings, strategies as st

from topomark.reference.port.files import load_port_document_file, load_port_file
from topomark.reference.port.generate import random_port_world
from topomark.spec.errors import InvalidInput, InvalidWorld
from topomark.spec.port_icfpc import map_to_json, submission_to_json
from topomark.spec.port_world import from_joins
from topomark.spec.port_worldfile import (FORMAT, dumps_port_world, load_port_world, loads_port_document,
                                          loads_port_world, port_world_to_json, save_port_world, schema)

DATA = Path(__file__).parent / "data" / "icfpc2025"
worlds = st.builds(random_port_world, st.integers(0, 2**32), st.integers(1, 8))

GOOD = {"format": FORMAT, "doors": 2, "alphabet": 2, "colours": [0, 1], "start": 0,
        "passages": [[[0, 0], [1, 0]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]]}


def validator():
    s = schema()
    cls = jsonschema.validators.validator_for(s)
    cls.check_schema(s)
    return cls(s)


def edited(**change) -> dict:
    obj = json.loads(json.dumps(GOOD))
    for key, value in change.items():
        if value is KeyError:
            del obj[key]
        else:
            obj[key] = value
    return obj


# Faults in shape: the schema and the loader both refuse them.
SHAPE_FAULTS = [
    (edited(format="topomark/port-world@2"), "unknown format 'topomark/port-world@2'"),
    (edited(format=KeyError), "missing key 'format'"),
    (edited(passages=KeyError), "missing key 'passages'"),
    (edited(id="SECRET"), "unknown key 'id'"),
    (edited(doors=0), "doors must be in 1..64"),
    (edited(doors=65), "doors must be in 1..64"),
    (edited(doors="2"), "doors must be an integer"),
    (edited(alphabet=0), "alphabet must be in 1.."),
    (edited(colours=[]), "colours must be a list of 1 to"),
    (edited(colours=[0, 1.5]), "colours[1] must be an integer"),
    (edited(colours=[0, -1]), "room 1's colour -1 is outside the alphabet"),
    (edited(start=-1), "the start room -1 is not a room"),
    (edited(start=True), "start must be an integer"),
    (edited(passages=[[[0, 0], [1, 0]], [[0, 1]], [[1, 1], [1, 1]]]), "passages[1] must be a pair of door-ends"),
    (edited(passages=[[[0, 0], [1, 0, 0]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]]), "passages[0][1] must be a door-end"),
    (edited(passages=[[[0, 0], [1, "0"]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]]), "passages[0][1][1] must be an integer"),
    (edited(passages=[[[0, 0], [1, -1]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]]), "(1, -1), which is not a door-end"),
    (edited(names=["a", "a"]), "names[1] repeats the name of room 0"),
    (edited(names=["a", ""]), "names[1] must be a string of 1 to 200"),
    (edited(problem=""), "problem must be a printable string"),
]

# Faults in meaning: the schema (shape only, as it says) accepts them; the loader names each.
MEANING_FAULTS = [
    (edited(passages=GOOD["passages"] + [[[1, 1], [0, 1]]]), "door-end (1, 1) is used twice"),
    (edited(passages=GOOD["passages"][:2]), "door-end (1, 1) is in no passage"),
    (edited(passages=[[[0, 0], [1, 2]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]]), "(1, 2), which is not a door-end"),
    (edited(passages=[[[0, 0], [2, 0]], [[0, 1], [0, 1]], [[1, 1], [1, 1]]]), "(2, 0), which is not a door-end"),
    (edited(colours=[0, 2]), "room 1's colour 2 is outside the alphabet 0..1"),
    (edited(start=2), "the start room 2 is not a room"),
    (edited(passages=[[[0, 0], [0, 0]], [[0, 1], [0, 1]], [[1, 0], [1, 1]]]), "room 1 cannot be reached"),
    (edited(names=["a"]), "names must be a list of 2 room names"),
]


def test_the_good_file_loads_and_validates():
    validator().validate(GOOD)
    w = loads_port_world(json.dumps(GOOD))
    assert w == from_joins([0, 1], [((0, 0), (1, 0)), ((0, 1), (0, 1)), ((1, 1), (1, 1))], 0, doors=2, alphabet=2)
    doc = loads_port_document(json.dumps(edited(names=["hall", "attic"], problem="probatio")))
    assert doc.names == ("hall", "attic") and doc.problem == "probatio" and doc.world == w


@pytest.mark.parametrize("obj, words", SHAPE_FAULTS)
def test_schema_and_loader_both_refuse_faults_of_shape(obj, words):
    with pytest.raises(jsonschema.ValidationError):
        validator().validate(obj)
    with pytest.raises(InvalidWorld) as e:
        loads_port_world(json.dumps(obj), "f.json")
    assert str(e.value).startswith("f.json: ") and words in str(e.value), str(e.value)
    assert "SECRET" not in str(e.value)


@pytest.mark.parametrize("obj, words", MEANING_FAULTS)
def test_the_loader_names_each_fault_the_schema_cannot_see(obj, words):
    validator().validate(obj)
    with pytest.raises(InvalidWorld) as e:
        loads_port_world(json.dumps(obj))
    assert words in str(e.value), str(e.value)


@pytest.mark.parametrize("text, words", [
    ('{"format": "topomark/port-world@1", "format": "topomark/port-world@1"}', "duplicate key 'format'"),
    ("[" * 100 + "]" * 100, "nested deeper"),
    ('{"doors": 1' + "0" * 30 + "}", "out of range"),
    ("{", "malformed JSON"),
    ("[]", "must hold a JSON object"),
])
def test_the_loader_refuses_hostile_text(text, words):
    with pytest.raises(InvalidWorld, match=None) as e:
        loads_port_world(text)
    assert words in str(e.value)


@settings(max_examples=40, deadline=None)
@given(worlds)
def test_round_trip_and_every_written_file_validates(w):
    text = dumps_port_world(w)
    validator().validate(json.loads(text))
    assert loads_port_world(text) == w
    assert json.loads(text) == port_world_to_json(w)


def test_save_and_load_refuse_to_overwrite(tmp_path):
    w = loads_port_world(json.dumps(GOOD))
    path = tmp_path / "w.json"
    save_port_world(w, path, names=["a", "b"], problem="x")
    with pytest.raises(InvalidInput, match="give force=True"):
        save_port_world(w, path)
    save_port_world(w, path, force=True)
    assert load_port_world(path).world == w and load_port_world(path).names is None
    with pytest.raises(InvalidWorld, match="names must be a list of 2"):
        dumps_port_world(w, names=["a"])


# -- one reader for every form -------------------------------------------------------------------------------

def test_load_port_file_reads_each_form_alike(tmp_path):
    w = random_port_world(7, 5)
    forms = {"world.json": dumps_port_world(w, problem="p"), "map.json": json.dumps(map_to_json(w)),
             "file.json": json.dumps(submission_to_json("p", w))}
    for name, text in forms.items():
        (tmp_path / name).write_text(text)
    assert load_port_file(tmp_path / "world.json") == ("p", w)
    assert load_port_file(tmp_path / "map.json") == (None, w)
    assert load_port_file(tmp_path / "file.json") == ("p", w)


@pytest.mark.parametrize("obj, words", [
    ({**GOOD, "colours": [0, 3]}, "room 1's colour 3 is outside"),
    ({"format": "x"}, "unknown format 'x'"),
    ({"problemName": "p", "id": "SECRET", "map": {}}, "unknown key 'id'"),
])
def test_load_port_file_names_the_file_and_the_fault(tmp_path, obj, words):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(obj))
    with pytest.raises(InvalidWorld) as e:
        load_port_file(path)
    assert str(e.value).startswith(f"{path}: ") and words in str(e.value) and "SECRET" not in str(e.value)


# -- the copied contest maps -----------------------------------------------------------------------------------

def manifest() -> list[dict[str, str]]:
    with open(DATA / "MANIFEST.tsv", newline="") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def test_the_copies_carry_their_licence_and_provenance():
    assert "MIT" in (DATA / "LICENSE-source.txt").read_text()
    readme = (DATA / "README.md").read_text()
    assert "icfpc-unagi/icfpc2025" in readme and "LICENSE-source.txt" in readme
    assert {row["file"] for row in manifest()} == {str(p.relative_to(DATA)) for p in DATA.rglob("*/*.json")}


@pytest.mark.parametrize("row", manifest(), ids=lambda r: r["file"])
def test_each_copied_map_matches_its_manifest_and_imports(row):
    path = DATA / row["file"]
    assert hashlib.sha256(path.read_bytes()).hexdigest() == row["sha256"]
    doc = load_port_document_file(path)
    assert doc.world.rooms == int(row["rooms"]) and doc.world.doors == 6
    assert doc.problem is not None
    raw = json.loads(path.read_text())["map"]
    for c in raw["connections"]:  # door numbers kept exactly
        a, b = c["from"], c["to"]
        assert doc.world.joins[a["room"]][a["door"]] == (b["room"], b["door"])
    assert loads_port_world(dumps_port_world(doc.world, problem=doc.problem)) == doc.world


def test_the_mislabelled_copy_keeps_its_own_problem_name():
    rows = [r for r in manifest() if r["problem"] != load_port_file(DATA / r["file"])[0]]
    assert [(r["file"], r["problem"]) for r in rows] == [("hhet/002.json", "hhet")]
    assert load_port_file(DATA / "hhet/002.json")[0] == "he"
