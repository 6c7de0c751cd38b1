"""Tests of ``topomark world`` and ``topomark iso``: exit codes 0/1/2, text and --json output."""

from __future__ import annotations

import json
import random
import subprocess
import sys

import pytest

from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.worlds.strategies import relabelled, rotated
from topomark.spec.marker import VertexMarker
from topomark.spec.world import World
from topomark.spec.worldfile import load_world, save_world


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def run_process(*argv, cwd):
    return subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", *argv], cwd=cwd,
                          capture_output=True, text=True, timeout=120)


def assert_clean_error(err: str, *words: str):
    """One line on stderr, no traceback, naming the problem."""
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("topomark: error: ")
    for w in words:
        assert w in lines[0], (w, lines[0])


@pytest.fixture
def here(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


# -- topomark world ------------------------------------------------------------------
def test_world_generate_show_and_json(capsys, here):
    code, out, err = run(capsys, "world", "lattice:rows=3,cols=4", "-o", "f.json")
    assert code == 0 and err == ""
    assert "f.json" in out and "n=12" in out and "m=17" in out and "genus=0" in out
    assert load_world(here / "f.json") == g.lattice(3, 4)

    code, out, err = run(capsys, "world", "--show", "f.json")
    assert code == 0 and err == ""
    assert "n=12 m=17 genus=0" in out and "faces=7" in out
    assert "2:4, 3:6, 4:2" in out

    code, out, err = run(capsys, "world", "--show", "f.json", "--json")
    assert code == 0
    info = json.loads(out)
    assert (info["n"], info["m"], info["genus"], info["faces"]) == (12, 17, 0, 7)
    assert info["degree_histogram"] == {"2": 4, "3": 6, "4": 2}
    assert info["markers"] == [] and info["start"] is None


def test_world_to_stdout_is_a_world_file(capsys, here):
    code, out, err = run(capsys, "world", "wheel-b:marker=undirected")
    assert code == 0 and err == ""
    (here / "b.json").write_text(out)
    assert load_world(here / "b.json") == g.wheel_b()
    code, out, _ = run(capsys, "world", "--show", "b.json", "--json")
    info = json.loads(out)
    assert info["genus"] == 1 and info["markers"] == [{"kind": "vertex", "at": "0", "count": 1}]
    assert info["start"] == {"at": "0", "facing": "1"}


def test_world_write_json_summary(capsys, here):
    code, out, _ = run(capsys, "world", "cycle:n=6", "-o", "c.json", "--json")
    assert code == 0
    info = json.loads(out)
    assert info["file"] == "c.json" and info["n"] == 6 and info["m"] == 6 and info["genus"] == 0


def test_random_generator_is_deterministic(capsys, here):
    assert run(capsys, "world", "lattice-hole", "--seed", "3", "-o", "a.json")[0] == 0
    assert run(capsys, "world", "lattice-hole", "--seed", "3", "-o", "b.json")[0] == 0
    assert run(capsys, "world", "lattice-hole:seed=3", "-o", "c.json")[0] == 0
    assert run(capsys, "world", "lattice-hole", "--seed", "4", "-o", "d.json")[0] == 0
    a = (here / "a.json").read_bytes()
    assert a == (here / "b.json").read_bytes() == (here / "c.json").read_bytes()
    assert a != (here / "d.json").read_bytes()
    assert load_world(here / "a.json") == g.lattice_hole(10, 10, seed=3)


@pytest.mark.parametrize("argv, words", [
    (["world", "nosuch"], ["unknown generator 'nosuch'"]),
    (["world", "lattice:rows=x"], ["rows", "'x'"]),
    (["world", "lattice:foo=3"], ["no parameter 'foo'"]),
    (["world", "lattice:rows"], ["'rows'", "NAME=VALUE"]),
    (["world", "lattice:rows=1,cols=1"], ["single vertex"]),
    (["world", "cycle:n=2"], ["n must be >= 3"]),
    (["world", "lattice", "--seed", "3"], ["--seed has no effect", "'lattice'"]),
    (["world", "lattice-hole:seed=1", "--seed", "3"], ["seed given twice"]),
    (["world"], ["GENERATOR"]),
    (["world", "--show", "missing.json"], ["missing.json", "cannot read"]),
    (["world", "--show", "missing.json", "--seed", "1"], ["takes no generator"]),
    (["world", "lattice", "--bogus"], ["--bogus"]),
    (["world", "lattice-hole", "--seed", "x"], ["--seed"]),
])
def test_world_bad_input_exits_2(capsys, here, argv, words):
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert out == ""
    assert_clean_error(err, *words)


# -- topomark iso ------------------------------------------------------------------
@pytest.fixture
def files(here):
    base = g.lattice_hole(5, 6, fraction=0.2, seed=7)
    hub = max(base.vertices, key=base.degree)
    a = base.with_markers([VertexMarker(hub, points_to=base.rotation[hub][0])])
    b = rotated(relabelled(a, random.Random(1)), random.Random(2))
    save_world(a, here / "a.json")
    save_world(b, here / "b.json")
    save_world(g.wheel_a(), here / "wa.json")
    save_world(g.wheel_b(), here / "wb.json")
    (here / "broken.json").write_text('{"format": "topomark/world@1",\n "rotation": {"a": ["b"]\n')
    (here / "loop.json").write_text('{"format": "topomark/world@1", "rotation": {"a": ["a", "b"], "b": ["a"]}}')
    return a, b


def check_witness_json(a: World, b: World, wit: dict):
    """The witness printed by --json satisfies the definition (checked dart by dart here)."""
    f, r = wit["vertex_map"], wit["offsets"]
    assert sorted(f) == sorted(a.vertices) and sorted(f.values()) == sorted(b.vertices)
    for v, ns in a.rotation.items():
        for i, w in enumerate(ns):
            x = b.rotation[f[v]][(i + r[v]) % len(ns)]
            assert x == f[w]
            j = a.rotation[w].index(v)
            assert b.rotation[x].index(f[v]) == (j + r[w]) % len(a.rotation[w])


@pytest.mark.parametrize("method", ["anchored", "networkx", "both"])
def test_iso_isomorphic_copy(capsys, files, method):
    a, b = files
    code, out, err = run(capsys, "iso", "a.json", "b.json", "--method", method)
    assert code == 0 and err == ""
    assert out.startswith("isomorphic: a.json") and "witness verified" in out
    code, out, err = run(capsys, "iso", "a.json", "b.json", "--method", method, "--json")
    assert code == 0
    data = json.loads(out)
    assert data["isomorphic"] is True and "mismatch" not in data
    assert data["methods"] == (["anchored", "networkx"] if method == "both" else [method])
    check_witness_json(a, b, data["witness"])


@pytest.mark.parametrize("method", ["anchored", "networkx", "both"])
def test_iso_not_isomorphic(capsys, files, method):
    code, out, err = run(capsys, "iso", "wa.json", "wb.json", "--method", method)
    assert code == 1 and err == ""
    assert out.startswith("not isomorphic: ")
    if method != "networkx":
        assert "vertex '" in out and "expected" in out and "found" in out
    code, out, _ = run(capsys, "iso", "wa.json", "wb.json", "--method", method, "--json")
    assert code == 1
    data = json.loads(out)
    assert data["isomorphic"] is False and "witness" not in data
    assert set(data["mismatch"]) >= {"check", "where", "expected", "found"}
    assert all(data["mismatch"][k] for k in ("check", "where", "expected", "found"))


def test_iso_markers_matter(capsys, files, here):
    a, _ = files
    (hub_marker,) = a.markers
    hub = hub_marker.at
    save_world(a.with_markers([VertexMarker(hub, points_to=a.rotation[hub][1])]), here / "other.json")
    code, out, _ = run(capsys, "iso", "a.json", "other.json", "--method", "both", "--json")
    assert code == 1 and json.loads(out)["isomorphic"] is False
    # the same embedded graph: with markers ignored it is isomorphic
    code, out, _ = run(capsys, "iso", "a.json", "other.json", "--method", "both", "--ignore-markers")
    assert code == 0 and "markers ignored" in out
    save_world(g.wheel_a().with_markers([]), here / "plain.json")
    assert run(capsys, "iso", "wa.json", "plain.json", "--method", "both")[0] == 1
    assert run(capsys, "iso", "wa.json", "plain.json", "--method", "both", "--ignore-markers")[0] == 0
    assert run(capsys, "iso", "wa.json", "wb.json", "--method", "both", "--ignore-markers")[0] == 1


@pytest.mark.parametrize("argv, words", [
    (["iso", "a.json", "broken.json"], ["broken.json", "malformed JSON", "line"]),
    (["iso", "loop.json", "a.json"], ["loop.json", "self-loop"]),
    (["iso", "a.json", "nope.json"], ["nope.json", "cannot read"]),
    (["iso", "a.json"], ["B"]),
    (["iso", "a.json", "b.json", "--method", "magic"], ["magic"]),
])
def test_iso_bad_input_exits_2(capsys, files, argv, words):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert_clean_error(err, *words)


# -- the real process: exit codes and stderr -------------------------------------------
def test_process_exit_codes(files, here):
    p = run_process("world", "lattice:rows=3,cols=4", "-o", "f.json", cwd=here)
    assert p.returncode == 0 and p.stderr == ""
    p = run_process("world", "--show", "f.json", cwd=here)
    assert p.returncode == 0 and "n=12 m=17 genus=0" in p.stdout
    p = run_process("iso", "a.json", "b.json", "--method", "both", "--json", cwd=here)
    assert p.returncode == 0 and json.loads(p.stdout)["isomorphic"] is True and p.stderr == ""
    p = run_process("iso", "wa.json", "wb.json", cwd=here)
    assert p.returncode == 1 and p.stdout.startswith("not isomorphic") and p.stderr == ""


@pytest.mark.parametrize("argv, words", [
    (["iso", "a.json", "broken.json"], ["malformed JSON"]),
    (["iso", "loop.json", "a.json"], ["self-loop"]),
    (["iso", "missing.json", "a.json"], ["missing.json"]),
    (["world", "nosuch:n=3"], ["unknown generator"]),
    (["world", "lattice", "--seed", "1"], ["--seed has no effect"]),
])
def test_process_bad_input_exit_2_without_traceback(files, here, argv, words):
    p = run_process(*argv, cwd=here)
    assert p.returncode == 2
    assert p.stdout == ""
    assert_clean_error(p.stderr, *words)
