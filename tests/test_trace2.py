"""``topomark/trace@2`` (spec/trace.md): a robot layer for every algorithm, an algorithm layer per family.

Every lighthouse × every algorithm is explored and replayed through the real
CLI; tampering with the robot layer (an op's exit, direction, count, step or
signature, an op removed or duplicated, a perception) is a divergence (exit
1, the line named); a header whose family, lighthouse or kit is wrong, or a
record its format or family does not have, is bad input (exit 2).
"""

from __future__ import annotations

import copy
import json

import pytest

from topomark.reference.worlds import generators as g
from topomark.reference.algorithms.registry import in_family
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.explorers.lighthouses import LIGHTHOUSES
from topomark.reference.replay.replay import parse_trace, replay
from topomark.reference.replay.robot_layer import marker_op
from topomark.reference.run.simulator import Simulator
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.world import Start, World
from topomark.spec.worldfile import dumps_world

from conftest import bare, make_world

WORLDS = ("cycle:n=5", "lattice-hole:rows=3,cols=4,seed=2", "wheel-a")  # wheel-a without its figure's marker

ALGORITHMS = {name: spec.factory for name, spec in in_family("algorithm-3.1").items()}
"""Algorithm 3.1's family, as registered: ``basic`` and the Chapter 4 enhancements, name ↦ explorer class."""

LATTICE = g.lattice(3, 4)  # every iteration kind, hypotheses of every outcome


def files(tmp_path, world, trace: list[dict] | str):
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "t.jsonl").write_text(trace if isinstance(trace, str) else dump_trace(trace))
    return str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")


def run_replay(tmp_path, capsys, world, trace, *extra: str) -> tuple[int, str, str]:
    code = main(["replay", *files(tmp_path, world, trace), *extra])
    out, err = capsys.readouterr()
    return code, out, err


def index(trace: list[dict], pred) -> int:
    return next(k for k, rec in enumerate(trace) if pred(rec))


# -- every lighthouse x every algorithm: explore writes it, replay verifies it -------------------
@pytest.mark.slow
@pytest.mark.parametrize("text", WORLDS)
@pytest.mark.parametrize("light", [n for n, h in LIGHTHOUSES.items() if h.search is None])  # searched ones fail on
@pytest.mark.parametrize("algorithm", ALGORITHMS)  # the cycle: tests/test_lighthouse_search.py replays them
def test_explore_then_replay_verifies_every_lighthouse_and_algorithm(tmp_path, capsys, text, light, algorithm):
    w, t = files(tmp_path, bare(make_world(text)), "")
    argv = ["explore", w, "--lighthouse", light, "--algorithm", algorithm, "--trace", t]
    assert main([*argv, "--force"]) == 0  # files() made t: written over
    capsys.readouterr()
    records = parse_trace(open(t).read())
    header = records[0]
    if light == "directional-vertex":  # Algorithm 3.1's own lighthouse keeps trace@1, byte for byte
        assert header["format"] == "topomark/trace@1" and "family" not in header and records[1]["event"] == "drop"
    else:
        assert header["format"] == "topomark/trace@2" and header["family"] == "algorithm-3.1"
        assert (header["lighthouse"], header["kit"]) == (light, LIGHTHOUSES[light].kit.to_json())
        ops = [r for r in records if r["event"] == "op"]
        assert [marker_op(r) for r in ops] == \
            list(LIGHTHOUSES[light].ops)
        script = LIGHTHOUSES[light].script or LIGHTHOUSES[light].ops  # ops at v0, or between establish moves
        steps = [sum(isinstance(x, int) for x in script[:k]) for k, x in enumerate(script) if not isinstance(x, int)]
        assert [r["step"] for r in ops] == steps and not any(r["event"] == "drop" for r in records)
    assert main(["replay", w, t, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["verified"] is True and data["layers"] == ["robot", "algorithm-3.1"]


@pytest.mark.parametrize("light", [name for name in LIGHTHOUSES if name != "directional-vertex"
                                   and LIGHTHOUSES[name].certain])  # §5.2.1's: tests/test_local_lighthouses.py
def test_hypotheses_are_rechecked_for_every_lighthouse(light):
    """The expected perceptions P^E read S, which carries the lighthouse's marks: tampering one is caught."""
    trace = explore(LATTICE, lighthouse=light).trace
    assert replay(LATTICE, iter(copy.deepcopy(trace))).ok
    k = index(trace, lambda r: r["event"] == "iteration" and any(h["outcome"] == "case 3" for h in r["hypotheses"]))
    h = next(h for h in trace[k]["hypotheses"] if h["outcome"] == "case 3")
    assert any("E" in s or "V" in s or ",T" in s for s in h["expected"])  # the lighthouse's marks are in P^E
    h["expected"][-1] = h["perceived"][-1] = "[2,A,A]" if h["expected"][-1] != "[2,A,A]" else "[3,A,A]"
    result = replay(LATTICE, iter(trace))
    assert not result.ok and result.line == k + 1 and result.divergence.check == "hypothesis"


def test_the_default_lighthouse_still_writes_trace_1():
    trace = explore(g.cycle(3)).trace
    assert [r["event"] for r in trace[:2]] == ["header", "drop"] and trace[0]["format"] == "topomark/trace@1"
    assert set(trace[0]) == {"event", "format", "algorithm", "policies", "n", "m"}


# -- the robot layer: tampering is a divergence at its line (exit 1) ------------------------------
THREE = explore(LATTICE, lighthouse="three-undirected-edge").trace
EDGE = explore(LATTICE, lighthouse="directional-edge").trace


def _first_op(t):
    return index(t, lambda r: r["event"] == "op")


def _wrong_exit(t):
    k = _first_op(t)
    t[k]["exit"] = 2
    return k


def _wrong_count(t):
    k = _first_op(t) + 1
    t[k]["count"] = 3  # 1 + 3 > the kit's 3 edge markers: the simulator refuses
    return k


def _wrong_step(t):
    k = _first_op(t)
    t[k]["step"] = 1
    return k


def _wrong_signature(t):
    k = _first_op(t)
    t[k]["signature"] = "[4,A,A]"
    return k


def _removed(t):
    k = _first_op(t)
    del t[k]
    return k  # the next op now senses a different signature


def _duplicated(t):
    k = _first_op(t) + 1
    t.insert(k, copy.deepcopy(t[k]))
    return k + 1  # 1 + 2 + 2 > 3 markers: the kit refuses the copy


def _perception_after_op(t):
    k = index(t, lambda r: r["event"] == "move")
    t[k]["perception"] = "[5,A,A]"
    return k


def _op_mid_run(t):
    k = index(t, lambda r: r["event"] == "move")
    t.insert(k + 1, {"event": "op", "step": 1, "op": "pick_up", "kind": "edge", "exit": 0, "count": 1,
                     "signature": t[k]["perception"]})
    return k + 1  # the kit's markers are immovable


def _directional_op_in_an_undirected_kit(t):
    k = _first_op(t)
    t[k]["direction"] = "H"
    return k


@pytest.mark.parametrize("tamper", [_wrong_exit, _wrong_count, _wrong_step, _wrong_signature, _removed, _duplicated,
                                    _perception_after_op, _op_mid_run, _directional_op_in_an_undirected_kit],
                         ids=lambda f: f.__name__[1:])
def test_a_tampered_robot_layer_diverges_at_its_line(tmp_path, capsys, tamper):
    trace = copy.deepcopy(THREE)
    k = tamper(trace)
    code, out, err = run_replay(tmp_path, capsys, LATTICE, trace)
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:"), (out, err)


def test_a_wrong_direction_diverges(tmp_path, capsys):
    trace = copy.deepcopy(EDGE)
    k = _first_op(trace)
    assert trace[k]["direction"] == "H"
    trace[k]["direction"] = "T"
    code, out, _ = run_replay(tmp_path, capsys, LATTICE, trace)
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:") and "signature" in out


def test_a_legal_op_that_is_not_the_lighthouses_diverges(tmp_path, capsys):
    """The world allows it, the algorithm layer does not: Algorithm 3.1 drops exactly its lighthouse's markers."""
    trace = copy.deepcopy(THREE)
    k = _first_op(trace)
    sim = Simulator(LATTICE, LATTICE.start_state(), Kit(edge=3))
    sim.operate(MarkerOp("edge", exit=1))
    trace[k].update(exit=1, signature=sim.events[-1]["signature"])
    code, out, _ = run_replay(tmp_path, capsys, LATTICE, trace)
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:") and "lighthouse's operation 1 of 2" in out


def test_a_false_by_marker_claim_diverges(tmp_path, capsys):
    trace = copy.deepcopy(EDGE)
    k = index(trace, lambda r: r["event"] == "iteration" and r["by_marker"])
    trace[k]["by_marker"] = False
    code, out, _ = run_replay(tmp_path, capsys, LATTICE, trace)
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:") and "directional-edge lighthouse" in out


# -- bad input: exit 2, one message naming the line ----------------------------------------------
@pytest.mark.parametrize("edit, words", [
    (lambda t: t[0].update(kit={"undirected-edge": 2}), "line 1: header.kit"),
    (lambda t: t[0].update(kit={"purple-edge": 3}), "line 1: header.kit: kit: unknown key"),
    (lambda t: t[0].update(lighthouse="lantern"), "line 1: header.lighthouse: unknown lighthouse 'lantern'"),
    (lambda t: t[0].update(lighthouse="directional-edge"), "is not the directional-edge lighthouse's kit"),
    (lambda t: t[0].update(lighthouse=None), "the algorithm-3.1 family needs a lighthouse"),
    (lambda t: t[0].update(family="chapter-9"), "line 1: header.family: unknown family 'chapter-9'"),
    (lambda t: t[0].pop("kit"), "line 1: a header event without field 'kit'"),
    (lambda t: t[0].update(algorithm="nope"), "unknown algorithm 'nope'"),
    (lambda t: t.insert(1, {"event": "drop", "direction": 0, "signature": "[2,V-0,A]"}),
     "line 2: expected a trace event (header, op, move, iteration, end), found \"drop\""),
    (lambda t: t[1].update(exit=-1), "line 2: op.exit must be an integer >= 0"),
    (lambda t: t[1].update(count=0), "line 2: op.count must be an integer >= 1"),
    (lambda t: t[1].update(kind="vertex"), "line 2: op.exit: a vertex marker takes no exit"),
    (lambda t: t[1].pop("exit"), "line 2: an edge marker op without field 'exit'"),
    (lambda t: t[1].update(direction=1), "line 2: op.direction: a edge marker's direction is \"H\" or \"T\""),
    (lambda t: t[1].update(op="move"), "line 2: op.op must be one of"),
    (lambda t: t[1].update(thread=1), "line 2: unknown field 'thread' in a op event"),
])
def test_a_malformed_trace_2_is_bad_input(tmp_path, capsys, edit, words):
    trace = copy.deepcopy(THREE)
    edit(trace)
    code, _, err = run_replay(tmp_path, capsys, LATTICE, trace)
    assert code == 2 and words in err and err.count("\n") == 1 and "Traceback" not in err, err


def test_an_op_in_a_trace_1_is_bad_input(tmp_path, capsys):
    trace = explore(LATTICE).trace
    trace.insert(2, {"event": "op", "step": 0, "op": "drop", "kind": "vertex", "count": 1, "signature": "[2,A,A]"})
    code, _, err = run_replay(tmp_path, capsys, LATTICE, trace)
    assert code == 2 and "line 3: expected a trace event (header, drop, move, iteration, end)" in err


# -- a family without an algorithm layer: the robot layer and the end ------------------------------
def robot_trace(world, kit: Kit, script: list) -> list[dict]:
    """A recorder of the ``robot`` family: ``script`` is motions (int) and marker ops, done in order."""
    records: list[dict] = [{"event": "header", "format": "topomark/trace@2", "family": "robot",
                            "algorithm": "chapter-6-sketch", "policies": {}, "lighthouse": None,
                            "kit": kit.to_json(), "n": world.n, "m": world.m}]

    def on_move(motion, purpose, sig, state):
        records.append({"event": "move", "step": sim.cost, "motion": motion, "perception": str(sig),
                        "purpose": purpose})

    sim = Simulator(world, world.start_state(), kit, listener=on_move,
                    op_listener=lambda event: records.append({"event": "op", **event}))
    robot = sim.robot()
    for item in script:
        robot.operate(item) if isinstance(item, MarkerOp) else robot.move(item, "other")
    records.append({"event": "end", "cost": sim.cost, "verified": False, "violation": None})
    return records


MOVABLE = Kit(vertex=1, movable=True)
SCRIPT = [0, 1, MarkerOp("vertex"), 1, 1, 1, 1, MarkerOp("vertex", pick_up=True), 0, MarkerOp("vertex")]


def test_ops_stream_between_moves_from_the_simulator():
    trace = robot_trace(g.cycle(4), MOVABLE, SCRIPT)
    assert [r["event"][0] for r in trace] == list("hmmommmmomoe")
    assert [r["step"] for r in trace if r["event"] == "op"] == [2, 6, 7]
    assert (trace[3]["signature"], trace[7]["perception"], trace[8]["signature"]) == ("[2,V,A]", "[2,V,A]", "[2,A,A]")


def test_a_robot_family_trace_verifies_its_robot_layer(tmp_path, capsys):
    world = g.cycle(4)
    code, out, _ = run_replay(tmp_path, capsys, world, robot_trace(world, MOVABLE, SCRIPT), "--json")
    data = json.loads(out)
    assert code == 0 and data["layers"] == ["robot"] and "robot layer only" in data["message"]
    assert data["cost"] == 7 and data["iterations"] == 0


def test_a_robot_family_trace_is_checked_against_the_world(tmp_path, capsys):
    world = g.cycle(4)
    trace = robot_trace(world, MOVABLE, SCRIPT)
    k = index(trace, lambda r: r["event"] == "op" and r["op"] == "pick_up")
    trace[k]["step"] = 5
    code, out, _ = run_replay(tmp_path, capsys, world, trace)
    assert code == 1 and out.startswith(f"DIVERGED line {k + 1}:")
    twice = robot_trace(world, MOVABLE, SCRIPT)
    twice.insert(k + 1, copy.deepcopy(twice[k]))  # nothing left to pick up
    code, out, _ = run_replay(tmp_path, capsys, world, twice)
    assert code == 1 and out.startswith(f"DIVERGED line {k + 2}:") and "marker kit" in out


def test_a_robot_family_has_no_algorithm_layer(tmp_path, capsys):
    world = g.cycle(4)
    trace = robot_trace(world, MOVABLE, SCRIPT)
    trace.insert(3, explore(world).trace[3])
    code, _, err = run_replay(tmp_path, capsys, world, trace)
    assert code == 2 and "line 4: expected a trace event (header, op, move, end), found \"iteration\"" in err


def test_the_spec_example_is_what_explore_writes():
    from pathlib import Path

    text = (Path(__file__).parent.parent / "spec" / "trace.md").read_text()
    part = text[text.index("# Trace format `topomark/trace@2`"):]
    example = part.split("~~~\n")[1]
    world = World({"a": ["b", "c"], "b": ["c", "a"], "c": ["a", "b"]}, (), Start("a", "b"))
    assert dump_trace(explore(world, lighthouse="directional-edge").trace) == example
