"""``topomark drive`` (spec/protocol.md, roles reversed): the reference explorer drives an external world."""

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
from topomark.reference.trace.records import dump_trace
from topomark.reference.explorers.policies import Policies
from topomark.reference.replay.replay import parse_trace, replay
from topomark.spec.world import Start
from topomark.spec.worldfile import dumps_world

ROOT = Path(__file__).resolve().parents[1]
PROVIDER = str(ROOT / "reference" / "oracle" / "examples" / "provider.py")


def provider(path: Path) -> list[str]:
    return [sys.executable, PROVIDER, str(path)]


def script(tmp_path: Path, body: str) -> list[str]:
    """A throwaway provider: ``body`` runs after ``import json, sys, time``."""
    path = tmp_path / "p.py"
    path.write_text("import json, sys, time\n"
                    "def send(m):\n    sys.stdout.write(json.dumps(m) + '\\n'); sys.stdout.flush()\n" + body)
    return [sys.executable, str(path)]


HELLO = ("send({'type': 'hello', 'protocol': 'topomark/protocol@1', 'role': 'world', "
         "'markers': {'directional-vertex': 1}, 'signature': '[2,A,A]'})\n")


@pytest.mark.parametrize("world", [
    g.lattice_hole(5, 5, 0.1, seed=1).with_start(Start("0,0", "0,1")), g.wheel_pair_directional()[1],
    g.complete(5).with_start(Start("3", "1")), g.chain(2).with_start(Start("1", "0")),
], ids=["lattice-hole", "wheel-b", "K5", "chain-2"])
def test_drive_maps_the_providers_world_exactly_like_explore(tmp_path, world):
    path = tmp_path / "w.json"
    path.write_text(dumps_world(world))
    result = drive(provider(path), Policies(), world, record=True)
    assert result.passed and result.check.isomorphic, result.message
    reference = explore(world)
    assert result.cost == reference.cost
    assert dump_trace(result.trace) == dump_trace(reference.trace)  # byte-for-byte the same trace
    assert replay(world, parse_trace(dump_trace(result.trace))).ok


def test_drive_without_a_world_cannot_judge_but_maps(tmp_path):
    world = g.random_graph(8, 0.5, seed=2).with_start(Start("0", g.random_graph(8, 0.5, seed=2).rotation["0"][0]))
    path = tmp_path / "w.json"
    path.write_text(dumps_world(world))
    result = drive(provider(path))
    assert result.passed and result.check is None and (result.map.n, result.map.m) == (world.n, world.m)


def test_drive_against_the_wrong_world_fails(tmp_path):
    path = tmp_path / "w.json"
    path.write_text(dumps_world(g.cycle(5)))
    result = drive(provider(path), world=g.cycle(6))
    assert not result.passed and result.reason == "not-isomorphic"


@pytest.mark.parametrize("body, reason, words", [
    ("print('I am a robot')\n", "garbage", "not a JSON object"),
    ("send({'type': 'hello', 'protocol': 'topomark/protocol@9', 'role': 'world', 'markers': {}, "
     "'signature': '[2,A,A]'})\ntime.sleep(5)\n", "protocol", "topomark/protocol@9"),
    ("send({'type': 'hello', 'protocol': 'topomark/protocol@1', 'role': 'world', "
     "'markers': {'undirected-vertex': 1}, 'signature': '[2,A,A]'})\ntime.sleep(5)\n", "protocol",
     "one directional vertex marker"),
    ("send({'type': 'hello', 'protocol': 'topomark/protocol@1', 'role': 'world', "
     "'markers': {'directional-vertex': '1'}, 'signature': '[2,A,A]'})\ntime.sleep(5)\n", "protocol",
     "one directional vertex marker"),
    ("time.sleep(30)\n", "timeout", "no message within 0.5 s"),
    ("sys.exit(3)\n", "crash", "exit status 3"),
    (HELLO + "for line in sys.stdin:\n    send({'type': 'signature', 'value': '[2,V-7,A]'})\n", "garbage",
     "bad signature"),
    (HELLO + "for line in sys.stdin:\n    send({'type': 'error', 'message': 'wheel slipped'})\n", "crash",
     "wheel slipped"),
    # the dropped marker is not there when the robot senses v0 again: no lighthouse (§3.2.2)
    (HELLO + "for line in sys.stdin:\n    send({'type': 'signature', 'value': '[2,A,A]'})\n", "inconsistent",
     "no explicit back-link"),
    # an inconsistent world: the marker is seen at the drop, then every vertex looks new and unmarked, forever
    (HELLO + "first = True\nfor line in sys.stdin:\n"
     "    send({'type': 'signature', 'value': '[2,V-0,A]' if first else '[2,A,A]'}); first = False\n", "limit",
     "more than 200 traversals"),
])
def test_misbehaving_providers_get_a_clear_verdict(tmp_path, body, reason, words):
    result = drive(script(tmp_path, body), max_traversals=200, message=0.5, wall=20)
    assert (result.verdict, result.reason) == ("fail", reason), result.message
    assert words in result.message


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_provider_answering_at_random_is_found_inconsistent(tmp_path, seed):
    body = (f"import random\nrng = random.Random({seed})\n" + HELLO.replace("[2,A,A]", "[3,A,A]") +
            "for line in sys.stdin:\n"
            "    d = rng.randint(1, 4)\n"
            "    v = 'V-%d' % rng.randrange(d) if rng.random() < 0.3 else 'A'\n"
            "    send({'type': 'signature', 'value': '[%d,%s,A]' % (d, v)})\n")
    result = drive(script(tmp_path, body), max_traversals=2000, message=2)
    assert result.verdict == "fail" and result.reason in ("inconsistent", "limit"), result.message


def test_cli_drive_writes_trace_and_map(tmp_path, capsys):
    world = g.lattice(3, 3).with_start(Start("1,1", "0,1"))
    (tmp_path / "w.json").write_text(dumps_world(world))
    code = main(["drive", "--check", str(tmp_path / "w.json"), "--trace", str(tmp_path / "t.jsonl"),
                 "--map", str(tmp_path / "m.json"), "--json", "--", *provider(tmp_path / "w.json")])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["verdict"] == "pass" and data["check"]["isomorphic"]
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")]) == 0
    assert main(["check-map", str(tmp_path / "w.json"), str(tmp_path / "m.json")]) == 0


def test_cli_drive_bad_input(capsys):
    assert main(["drive"]) == 2
    assert "give the program to run after --" in capsys.readouterr().err
    assert main(["drive", "--policy", "edge=sideways", "--", "true"]) == 2
    assert "unknown edge policy" in capsys.readouterr().err


def test_provider_is_standalone():
    tree = ast.parse(Path(PROVIDER).read_text())
    mods = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    mods |= {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert mods <= {"json", "sys"}, mods


@pytest.mark.parametrize("name", ["directional-edge", "vertex-and-edge", "thread"])
def test_a_drive_trace_of_any_lighthouse_replays(tmp_path, name, capsys):
    """drive records trace@2 for a lighthouse other than Algorithm 3.1's, and replay verifies it."""
    from topomark.reference.explorers.lighthouses import LIGHTHOUSES
    world = g.lattice_hole(4, 4, 0.1, seed=2)
    (tmp_path / "w.json").write_text(dumps_world(world))
    kit = json.dumps(LIGHTHOUSES[name].kit.to_json())
    provider = [sys.executable, PROVIDER, str(tmp_path / "w.json"), "--protocol", "2", "--kit", kit]
    assert main(["drive", "--check", str(tmp_path / "w.json"), "--lighthouse", name, "--trace",
                 str(tmp_path / "t.jsonl"), "--", *provider]) == 0
    assert '"format":"topomark/trace@2"' in (tmp_path / "t.jsonl").read_text().splitlines()[0]
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")]) == 0
    assert "VERIFIED" in capsys.readouterr().out


@pytest.mark.parametrize("kit, words", [
    ("{'thread': 1000001}", "a thread is at most 1,000,000 edges long"),
    ("{'directional-vertex': 1, 'directional-edge': 1000001}", "edge markers: at most 1,000,000"),
])
def test_a_providers_kit_past_the_caps_is_refused_as_a_kit_given_on_the_command_line_is(tmp_path, kit, words):
    body = ("send({'type': 'hello', 'protocol': 'topomark/protocol@2', 'role': 'world', "
            f"'kit': {kit}, 'signature': '[2,A,A]'}})\ntime.sleep(5)\n")
    result = drive(script(tmp_path, body), message=2, wall=20)
    assert (result.verdict, result.reason) == ("fail", "garbage") and words in result.message, result.message
