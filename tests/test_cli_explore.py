"""``topomark explore`` and the quick-start default: exit codes, JSON, trace, map (issue 3)."""

from __future__ import annotations

import json
import subprocess
import sys
from dataclasses import replace

import pytest

from faults_min import KeepsLoopDartInU
from topomark.reference.algorithms.registry import REGISTRY
from topomark.reference.cli.main import main
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.worldfile import load_world, save_world
from topomark.reference.worlds import generators as g
from topomark.spec.marker import VertexMarker
from topomark.spec.world import Start, World


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_explore_without_a_world_explores_the_default_world(capsys):
    code, out, err = run(capsys, "explore")  # the README's first command (topomark alone prints the commands)
    assert code == 0
    assert "built-in default world" in out and "verified" in out and "n " in out


def test_json_has_the_documented_keys(capsys):
    code, out, _ = run(capsys, "explore", "lattice:rows=3,cols=3", "--json")
    data = json.loads(out)
    assert code == 0
    for key in ("n", "m", "cost", "verified", "iterations", "hypotheses", "checks"):
        assert key in data
    assert (data["n"], data["m"], data["verified"]) == (9, 12, True)
    assert data["iterations"] == 12 and data["checks"] > 0


def test_trace_is_reproducible_and_map_is_the_world(capsys, tmp_path):
    for name in ("t1.jsonl", "t2.jsonl"):  # the second run writes over the first's map: --force
        code, _, _ = run(capsys, "explore", "lattice-hole:rows=5,cols=6", "--seed", "4",
                         "--trace", str(tmp_path / name), "--map", str(tmp_path / "map.json"), "--force")
        assert code == 0
    assert (tmp_path / "t1.jsonl").read_bytes() == (tmp_path / "t2.jsonl").read_bytes()
    world = g.lattice_hole(5, 6, seed=4)
    mapped = load_world(tmp_path / "map.json")
    assert find_isomorphism(mapped, world, markers=False).isomorphic
    assert len(mapped.markers) == 1 and mapped.markers[0].directional


def test_map_round_trips_through_iso(capsys, tmp_path):
    world = World(g.cycle(6).rotation, [VertexMarker("0", 1, "1")], Start("0", "1"))
    save_world(world, tmp_path / "w.json")
    assert run(capsys, "explore", str(tmp_path / "w.json"), "--map", str(tmp_path / "m.json"))[0] == 0
    assert run(capsys, "iso", str(tmp_path / "w.json"), str(tmp_path / "m.json"))[0] == 0


@pytest.mark.parametrize("argv, words", [
    (["explore", "nosuch"], "neither a world file nor a generator"),
    (["explore", "cycle:n=2"], "n"),
    (["explore", "cycle:n=5", "--seed", "3"], "--seed has no effect"),
    (["explore", "--policy", "edge=middle"], "unknown edge policy"),
    (["explore", "--policy", "colour=red"], "kind must be edge, hypothesis or path"),
    (["explore", "--algorithm", "enh99"], "unknown algorithm"),
    (["explore", "--seed", "1"], "--seed needs a generator"),
    (["explore", "lattice:rows=3,cols"], "is not NAME=VALUE"),
])
def test_bad_input_exits_2_with_one_message(capsys, argv, words):
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert words in err and err.count("\n") == 1 and "Traceback" not in err


def test_wrong_marker_in_world_file_exits_2(capsys, tmp_path):
    world = World(g.cycle(5).rotation, [VertexMarker("2")], Start("0", "1"))
    save_world(world, tmp_path / "w.json")
    code, _, err = run(capsys, "explore", str(tmp_path / "w.json"))
    assert code == 2 and "cannot use the marker" in err


def test_violation_exits_1_with_diagnostic_and_trace(capsys, monkeypatch):
    monkeypatch.setitem(REGISTRY, "basic", replace(REGISTRY["basic"], explorer=KeepsLoopDartInU))
    code, out, _ = run(capsys, "explore", "cycle:n=5")
    assert code == 1
    assert "VIOLATION: I-2 violated" in out and "iteration" in out and '"event": "move"' in out
    code, out, _ = run(capsys, "explore", "cycle:n=5", "--json")
    data = json.loads(out)
    assert code == 1 and data["verified"] is False and data["violation"]["check"] == "I-2"
    assert data["trace_tail"]


def test_console_script_runs_in_a_subprocess():
    proc = subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", "explore", "complete:n=5", "--json"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["verified"] is True


def test_undirected_marker_world_is_refused_in_a_subprocess():
    """Figure 3.4's wheel with its undirected centre marker (asked for): not the basic algorithm's marker class."""
    proc = subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", "explore", "wheel-b:marker=undirected"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert '{"kind": "vertex", "at": "0", "count": 1}' in proc.stderr
