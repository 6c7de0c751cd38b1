"""Tests of ``topomark port import|export|run|show``: exit codes 0/2, text and --json output, nothing written on
bad input."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.worlds.argument import resolve_world
from topomark.reference.port.files import load_port_document_file, load_port_file
from topomark.spec.port_icfpc import submission_from_json
from topomark.spec.port_plan import parse_plan, run_plan

DATA = Path(__file__).parent / "data" / "icfpc2025"
PROBATIO = DATA / "probatio" / "000.json"


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def clean_error(err: str, *words: str) -> None:
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("topomark: error: "), err
    for w in words:
        assert w in lines[0], (w, lines[0])


def test_import_a_directory_mirrors_it_and_keeps_door_numbers(capsys, tmp_path):
    code, out, _ = run(capsys, "port", "import", "icfpc2025", DATA, "-o", tmp_path / "out")
    assert code == 0 and out.strip() == f"imported 6 maps into {tmp_path / 'out'} (3 to 90 rooms)"
    for src in DATA.rglob("*/*.json"):
        dst = tmp_path / "out" / src.relative_to(DATA)
        assert json.loads(dst.read_text())["format"] == "topomark/port-world@1"
        assert load_port_file(dst) == submission_from_json(json.loads(src.read_text()))
    code, _, err = run(capsys, "port", "import", "icfpc2025", DATA, "-o", tmp_path / "out")
    assert code == 2
    clean_error(err, "the directory is not empty", "--force")
    assert run(capsys, "port", "import", "icfpc2025", DATA, "-o", tmp_path / "out", "--force")[0] == 0


def test_import_stops_at_a_bad_file_and_writes_nothing(capsys, tmp_path):
    src = tmp_path / "in"
    shutil.copytree(DATA, src)
    bad = json.loads(PROBATIO.read_text())
    bad["id"] = "SECRET-ID"
    (src / "probatio" / "001.json").write_text(json.dumps(bad))
    code, out, err = run(capsys, "port", "import", "icfpc2025", src, "-o", tmp_path / "out")
    assert code == 2
    clean_error(err, "probatio/001.json", "unknown key 'id'")
    assert "SECRET" not in err + out and not (tmp_path / "out").exists()


@pytest.mark.parametrize("edit, words", [
    (lambda m: m["map"]["connections"].pop(), "is in no passage"),
    (lambda m: m["map"]["rooms"].__setitem__(0, 4), "room 0's colour 4 is outside the alphabet 0..3"),
    (lambda m: m["map"].__setitem__("startingRoom", 3), "the start room 3 is not a room"),
    (lambda m: m["map"]["connections"][0]["to"].__setitem__("door", 9), "which is not a door-end"),
])
def test_import_names_the_fault_of_a_bad_file(capsys, tmp_path, edit, words):
    obj = json.loads(PROBATIO.read_text())
    edit(obj)
    (tmp_path / "bad.json").write_text(json.dumps(obj))
    code, _, err = run(capsys, "port", "import", "icfpc2025", tmp_path / "bad.json", "-o", tmp_path / "w.json")
    assert code == 2 and not (tmp_path / "w.json").exists()
    clean_error(err, "bad.json", words)


def test_import_a_bare_map_is_refused(capsys, tmp_path):
    (tmp_path / "bare.json").write_text(json.dumps(json.loads(PROBATIO.read_text())["map"]))
    code, _, err = run(capsys, "port", "import", "icfpc2025", tmp_path / "bare.json", "-o", tmp_path / "w.json")
    assert code == 2
    clean_error(err, "unknown key 'rooms'")


def test_export_round_trips_a_contest_map(capsys, tmp_path):
    src = DATA / "iod" / "001.json"
    assert run(capsys, "port", "import", "icfpc2025", src, "-o", tmp_path / "w.json")[0] == 0
    code, out, _ = run(capsys, "port", "export", "icfpc2025", tmp_path / "w.json", "-o", tmp_path / "m.json", "--json")
    assert code == 0 and json.loads(out) == {"output": str(tmp_path / "m.json"), "problem": "iod", "rooms": 90}
    assert submission_from_json(json.loads((tmp_path / "m.json").read_text())) == submission_from_json(
        json.loads(src.read_text()))


def test_export_needs_a_problem_name_and_contest_sized_rooms(capsys, tmp_path):
    assert run(capsys, "port", "import", "thesis", "lattice-hole:rows=3,cols=3", "-o", tmp_path / "t.json")[0] == 0
    code, _, err = run(capsys, "port", "export", "icfpc2025", tmp_path / "t.json", "-o", tmp_path / "m.json")
    assert code == 2
    clean_error(err, "names no problem", "--problem")
    code, _, err = run(capsys, "port", "export", "icfpc2025", tmp_path / "t.json", "--problem", "x", "-o",
                       tmp_path / "m.json")
    assert code == 2 and not (tmp_path / "m.json").exists()
    clean_error(err, "6 doors a room")


def test_import_thesis_keeps_names_and_degrees(capsys, tmp_path):
    code, out, _ = run(capsys, "port", "import", "thesis", "lattice-hole:rows=3,cols=3", "-o", tmp_path / "t.json",
                       "--json")
    assert code == 0 and json.loads(out)["rooms"] == 8
    doc = load_port_document_file(tmp_path / "t.json")
    assert doc.names is not None and len(doc.names) == 8
    thesis = resolve_world("lattice-hole:rows=3,cols=3")
    assert [len(thesis.rotation[v]) for v in doc.names] == list(doc.world.colours)
    for room, v in enumerate(doc.names):  # port i = exit i
        for i, u in enumerate(thesis.rotation[v]):
            assert doc.names[doc.world.target(room, i)] == u
    code, _, _ = run(capsys, "port", "import", "thesis", "lattice-hole:rows=3,cols=3", "-o", tmp_path / "n.json",
                     "--colour", "none")
    assert code == 0 and set(load_port_file(tmp_path / "n.json")[1].colours) == {0}
    code, _, err = run(capsys, "port", "import", "icfpc2025", PROBATIO, "-o", tmp_path / "x.json", "--colour", "none")
    assert code == 2
    clean_error(err, "--colour has no effect")


def test_run_prints_records_in_the_explore_answers_shape(capsys):
    code, out, _ = run(capsys, "port", "run", PROBATIO, "012", "0[1]0", "", "--json")
    world = load_port_file(PROBATIO)[1]
    expected = [list(run_plan(world, parse_plan(p))) for p in ("012", "0[1]0", "")]
    assert code == 0 and json.loads(out) == {"results": expected, "queryCount": 4}
    code, out, _ = run(capsys, "port", "run", PROBATIO, "0[1]0", "--no-echo", "--json")
    assert json.loads(out)["results"] == [list(run_plan(world, parse_plan("0[1]0"), echo_marks=False))]
    code, out, _ = run(capsys, "port", "run", PROBATIO, "012")
    assert out.splitlines() == ["012: " + "".join(map(str, expected[0])), "queryCount: 2"]


def test_run_reads_a_plans_file(capsys, tmp_path):
    (tmp_path / "plans.txt").write_text("01\n\n[2]3\n")
    code, out, _ = run(capsys, "port", "run", PROBATIO, "5", "--plans", tmp_path / "plans.txt", "--json")
    assert code == 0 and len(json.loads(out)["results"]) == 3 and json.loads(out)["queryCount"] == 4


@pytest.mark.parametrize("plans, extra, words", [
    (["01", "0x1"], [], "plan 2: plan character 2 ('x')"),
    (["6"], [], "plan 1: plan character 1 ('6') is not a door (doors 0..5)"),
    (["[4]"], [], "plan 1: plan character 1 starts a mark"),
    (["0" * 19], [], "plan 1: the plan has 19 doors, over the full round's limit of 18"),
    (["0" * 55], ["--round", "lightning"], "over the lightning round's limit of 54"),
    ([], [], "no plan given"),
])
def test_run_names_the_bad_plan(capsys, plans, extra, words):
    code, _, err = run(capsys, "port", "run", PROBATIO, *plans, *extra)
    assert code == 2
    clean_error(err, words)


def test_run_allows_the_lightning_rounds_longer_plans(capsys):
    assert run(capsys, "port", "run", PROBATIO, "0" * 54, "--round", "lightning")[0] == 0


def test_show_counts_passages_by_kind(capsys):
    code, out, _ = run(capsys, "port", "show", PROBATIO, "--json")
    data = json.loads(out)
    world = load_port_file(PROBATIO)[1]
    assert code == 0 and data["rooms"] == 3 and data["problem"] == "probatio"
    assert data["passages"] == (3 * 6 + data["self_joined_doors"]) // 2 == len(list(world.passages()))
    assert sum(data["colour_counts"]) == 3
    code, out, _ = run(capsys, "port", "show", PROBATIO)
    assert code == 0 and out.splitlines()[1] == "rooms 3, doors 6 a room, start room 0"


def test_import_thesis_takes_a_start_vertex(capsys, tmp_path):
    code, _, _ = run(capsys, "port", "import", "thesis", "cycle:n=5", "-o", tmp_path / "c.json", "--start", "3")
    doc = load_port_document_file(tmp_path / "c.json")
    assert code == 0 and doc.names is not None and doc.names[doc.world.start] == "3"
    code, _, err = run(capsys, "port", "import", "thesis", "cycle:n=5", "-o", tmp_path / "d.json", "--start", "9")
    assert code == 2 and not (tmp_path / "d.json").exists()
    clean_error(err, "--start '9' is not a vertex")
