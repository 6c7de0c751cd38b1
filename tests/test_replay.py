"""``topomark replay`` (spec/trace.md): honest traces verify, doctored ones diverge at the right place."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from faults import FAULTS
from topomark.reference.algorithms.registry import algorithm_spec, in_family
from topomark.reference.worlds import generators as g
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.trace.records import dump_trace
from topomark.reference.explorers.policies import Policies
from topomark.reference.replay.replay import parse_trace, replay
from topomark.spec.errors import ExplorerFault, InvalidInput
from topomark.spec.world import Start, World
from topomark.spec.worldfile import dumps_world

from conftest import make_world

LATTICE = make_world("lattice-hole:rows=5,cols=5,seed=1")
WORLDS = [LATTICE, g.wheel_pair_directional()[1], make_world("complete:n=5"),
          make_world("random:n=9,fraction=0.5,seed=3"), make_world("cycle:n=6").with_start(Start("2", "3"))]


def trace_of(world: World, policies: Policies | None = None) -> list[dict]:
    return explore(world, policies=policies).trace


def records(trace: list[dict]) -> list[dict]:
    return parse_trace(dump_trace(trace))


@pytest.mark.parametrize("world", WORLDS, ids=lambda w: f"n{w.n}m{w.m}")
@pytest.mark.parametrize("policy", [Policies(), Policies("lifo", "shortest", "dfs")], ids=["default", "other"])
def test_reference_traces_verify(world, policy):
    result = replay(world, records(trace_of(world, policy)))
    assert result.ok, result.message
    assert result.iterations == world.m and result.cost == explore(world, policies=policy).cost


@pytest.mark.parametrize("algorithm", list(in_family("algorithm-3.1")))
def test_traces_of_every_registered_explorer_verify(algorithm):
    world = g.random_graph(9, 0.5, seed=3)
    out = explore(world, algorithm)
    assert out.verified and replay(world, records(out.trace)).ok


def _first(trace: list[dict], pred) -> int:
    return next(k for k, rec in enumerate(trace) if pred(rec))


def test_a_wrong_perception_is_explained_by_step():
    trace = trace_of(LATTICE)
    k = _first(trace, lambda r: r["event"] == "move" and r["step"] == 40)
    true = trace[k]["perception"]
    trace[k]["perception"] = "[7,A,A]"
    result = replay(LATTICE, records(trace))
    assert not result.ok and result.divergence.where == "step 40"
    assert true in result.divergence.expected and "[7,A,A]" in result.divergence.found
    assert result.line == k + 1


def test_a_wrong_motion_diverges_where_the_perception_stops_matching():
    trace = trace_of(g.complete(5))
    k = _first(trace, lambda r: r["event"] == "move" and r["step"] == 3)
    trace[k]["motion"] = (trace[k]["motion"] + 1) % 4
    result = replay(g.complete(5), records(trace))
    assert not result.ok and result.divergence.where.startswith("step")


def test_the_claimed_cost_must_equal_the_traversals():
    trace = trace_of(LATTICE)
    trace[-1]["cost"] += 1
    result = replay(LATTICE, records(trace))
    assert not result.ok and result.divergence.where == "end" and "cost" in result.divergence.found


def test_step_numbers_must_run_without_gaps():
    trace = trace_of(LATTICE)
    k = _first(trace, lambda r: r["event"] == "move" and r["step"] == 5)
    del trace[k]
    result = replay(LATTICE, records(trace))
    assert not result.ok and result.divergence.where == "step 5" and "step number 5" in result.divergence.expected


def test_a_misjoined_loop_edge_violates_I1():
    """The checker stops the faulty run at the misjoin (I-1); its trace, replayed, diverges there too.  Unchecked,
    the same explorer runs on until its own consistency check finds e' missing from U: a bug in the explorer,
    exit 3, never a checker's verdict."""
    world = g.complete(5)
    fault = replace(algorithm_spec("basic"), explorer=FAULTS["MisindexedLoopEdge"])
    out = explore(world, fault)
    assert out.violation.check == "I-1"
    result = replay(world, records(out.trace))
    assert not result.ok and result.divergence.check == "I-1" and "iteration" in result.divergence.detail
    with pytest.raises(ExplorerFault, match="not in U"):
        explore(world, fault, check=False)


def test_an_edge_not_in_U_is_a_divergence():
    trace = trace_of(g.cycle(5))
    its = [r for r in trace if r["event"] == "iteration"]
    its[1]["edge"] = its[0]["edge"]
    its[1]["joined"][0] = its[0]["edge"]
    result = replay(g.cycle(5), records(trace))
    assert not result.ok and "iteration 2" in result.divergence.where and "not in U" in result.divergence.found


def test_a_loop_join_to_a_dart_not_in_U_is_a_divergence():
    world = g.complete(4)
    trace = trace_of(world)
    loop = next(r for r in trace if r["event"] == "iteration" and r["augmentation"] == "loop")
    loop["joined"][1] = [0, 0]  # v0's exit 0 was explored first
    result = replay(world, records(trace))
    assert not result.ok and "e' = [0, 0] in U" in result.divergence.expected


def test_explicit_unexplored_field_is_checked_by_I2():
    world = g.complete(4)
    trace = trace_of(world)
    loop = next(r for r in trace if r["event"] == "iteration" and r["augmentation"] == "loop")
    # the explorer's claimed U still holds e' (it forgot to remove it)
    its = [r for r in trace if r["event"] == "iteration"]
    before = replay_state_U(world, trace, its.index(loop))
    loop["unexplored"] = before
    result = replay(world, records(trace))
    assert not result.ok and result.divergence.check == "I-2"


def replay_state_U(world, trace, index):
    """U after iteration ``index`` if e' had not been removed: rebuilt by hand from the joins."""
    its = [r for r in trace if r["event"] == "iteration"]
    deg0 = int(next(r for r in trace if r["event"] == "drop")["signature"][1:].split(",")[0])
    U = [[0, i] for i in range(deg0)]
    n = 1
    for k, it in enumerate(its[:index + 1]):
        U.remove(it["edge"])
        a, b = it["joined"]
        if it["augmentation"] == "non-loop":
            d = int(it["signature"][1:].split(",")[0])
            U += [[n, j] for j in range(d) if j != b[1]]
            n += 1
        elif k < index:
            U.remove(b)
    return U


def test_a_correct_unexplored_field_is_accepted():
    world = g.complete(4)
    out = explore(world)
    trace = out.trace
    its = [r for r in trace if r["event"] == "iteration"]
    for k, it in enumerate(its):
        U = replay_state_U(world, trace, k)
        if it["augmentation"] == "loop":
            U.remove(it["joined"][1])
        it["unexplored"] = U
    assert replay(world, records(trace)).ok


def test_the_iteration_signature_must_be_the_new_edges_perception():
    trace = trace_of(LATTICE)
    it = next(r for r in trace if r["event"] == "iteration" and r["augmentation"] == "non-loop")
    it["signature"] = "[4,A,A]" if it["signature"] != "[4,A,A]" else "[3,A,A]"
    result = replay(LATTICE, records(trace))
    assert not result.ok and "v_u's signature" in result.divergence.expected


def test_a_truncated_run_is_incomplete():
    world = g.cycle(5)
    trace = trace_of(world)
    k = max(i for i, r in enumerate(trace) if r["event"] == "iteration")
    cut = trace[:k] + [dict(trace[-1], cost=sum(r["event"] == "move" for r in trace[:k]))]
    result = replay(world, records(cut))
    assert not result.ok and result.divergence.where == "end" and "iterations" in result.divergence.expected


# -- bad input: exit 2 -------------------------------------------------------------
@pytest.mark.parametrize("edit, words", [
    (lambda lines: ["{not json"] + lines[1:], "line 1: malformed JSON"),
    (lambda lines: [lines[0].replace("trace@1", "trace@3")] + lines[1:], "unknown trace format 'topomark/trace@3'"),
    (lambda lines: lines[:1] + ['{"event":"teleport"}'] + lines[1:], "line 2: expected a trace event"),
    (lambda lines: lines[:1] + ['{"event":"move","motion":0,"perception":"[2,A,A]","purpose":"new"}'] + lines[1:],
     "move event without field 'step'"),
    (lambda lines: lines[:1] + ['{"event":"move","motion":0,"perception":"[2,A,A]","purpose":"new","step":1,'
                                '"speed":3}'] + lines[1:], "unknown field 'speed'"),
    (lambda lines: lines[:1] + ['{"event":"move","motion":"0","perception":"[2,A,A]","purpose":"new","step":1}']
     + lines[1:], "move.motion must be integer"),
    (lambda lines: lines[:-1], "exactly one end event"),
    (lambda lines: lines[1:], "first line must be the header"),
    (lambda lines: lines + [lines[0]], "exactly one end event"),
    (lambda lines: lines[:3] + [""] + lines[3:], "line 4: empty line"),
])
def test_malformed_traces_exit_2_with_one_precise_message(tmp_path, capsys, edit, words):
    world = g.cycle(4).with_start(Start("0", "1"))
    lines = dump_trace(trace_of(world)).splitlines()
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "t.jsonl").write_text("\n".join(edit(lines)) + "\n")
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err and err.count("\n") == 1


def test_a_trace_from_another_world_is_bad_input(tmp_path, capsys):
    (tmp_path / "w.json").write_text(dumps_world(g.cycle(5)))
    (tmp_path / "t.jsonl").write_text(dump_trace(trace_of(g.lattice(2, 3))))
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")]) == 2
    assert "recorded on a world with n=6, m=7" in capsys.readouterr().err


def test_a_bad_signature_in_an_iteration_is_bad_input():
    trace = trace_of(g.cycle(4))
    it = next(r for r in trace if r["event"] == "iteration")
    it["signature"] = "[two,A,A]"
    with pytest.raises(InvalidInput, match="not of the form"):
        replay(g.cycle(4), records(trace))


def test_cli_replay_verdicts(tmp_path, capsys):
    world = LATTICE.with_start(Start("0,1", "0,2"))
    (tmp_path / "w.json").write_text(dumps_world(world))
    (tmp_path / "t.jsonl").write_text(dump_trace(trace_of(world)))
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["verified"] is True
    bad = trace_of(world)
    bad[-1]["cost"] = 1
    (tmp_path / "t.jsonl").write_text(dump_trace(bad))
    assert main(["replay", str(tmp_path / "w.json"), str(tmp_path / "t.jsonl")]) == 1
    assert "DIVERGED" in capsys.readouterr().out
