"""No credit for a guess: a right map the program's observations do not determine fails, with a witness world.

The rule (:mod:`topomark.reference.oracle.determination`): the program's actions are replayed on worlds that are not
isomorphic to its map — an untraversed edge subdivided, a two-fold cover — and one that gives every signature the
robot sensed is the witness.  The witness is replayed here again, independently, to show it is one.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from topomark.reference.cli.main import main
from topomark.reference.oracle import determination as d
from topomark.reference.oracle import walk_folding as wf
from topomark.reference.oracle.run_external import Limits, run_external
from topomark.reference.run.simulator import Simulator
from topomark.reference.worlds.deterministic import chain, cycle
from topomark.spec.isomorphism import find_isomorphism
from topomark.spec.kit import MarkerOp
from topomark.spec.worldfile import save_world, world_from_json

GUESS = [sys.executable, str(Path(__file__).resolve().parent / "clients" / "guess_client.py")]


def _signatures(world, kit, actions):
    sim = Simulator(world, world.start_state(), kit)
    seen = [str(sim.robot().sense())]
    for action in actions:
        seen.append(str(d._act(sim, action)))
    return seen


def test_a_map_sent_before_moving_is_a_guess_with_a_three_vertex_witness():
    result = run_external(chain(2), GUESS + ["blind"], Limits(message=5))
    assert (result.verdict, result.reason) == ("fail", "guess")
    assert "never crossed the edge" in result.message and "3 vertices, not 2" in result.message
    witness = world_from_json(result.to_json()["determination"]["witness"])
    assert witness.n == 3 and _signatures(witness, d.LIGHTHOUSE, []) == _signatures(chain(2), d.LIGHTHOUSE, [])


def test_once_round_a_triangle_without_a_marker_is_a_guess_a_hexagon_witnesses():
    result = run_external(cycle(3), GUESS + ["round", "3"], Limits(message=5))
    assert (result.verdict, result.reason) == ("fail", "guess")
    assert "two-fold cover" in result.message
    witness = result.determination.witness
    assert witness.n == 6 and find_isomorphism(witness, cycle(6), markers=False).isomorphic
    assert _signatures(witness, d.LIGHTHOUSE, [1, 1, 1]) == _signatures(cycle(3), d.LIGHTHOUSE, [1, 1, 1])


def test_the_same_walk_that_sees_its_marker_again_knows_its_map():
    result = run_external(cycle(3), GUESS + ["marked", "3"], Limits(message=5))
    assert (result.verdict, result.reason) == ("pass", "ok"), result.message
    assert "determined by what the program sensed" in result.message
    info = result.to_json()["determination"]
    assert info["witness"] is None and info["complete"] and info["candidates"] == 3


def test_a_guess_is_exit_1_and_its_own_reason_on_the_command_line(tmp_path, capsys):
    world = tmp_path / "chain.json"
    save_world(chain(2), str(world))
    assert main(["run-external", str(world), "--json", "--", *GUESS, "blind"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["reason"] == "guess" and out["determination"]["how"] == "subdivided"


def test_a_cover_that_shows_a_difference_is_no_witness():
    """The marker seen again tells the copies of a cover apart: no witness, whatever edge is crossed."""
    three = cycle(3)
    actions = [MarkerOp("vertex", direction=0), 1, 1, 1]
    start = three.start_state()
    for u, i, _w, _j in d._edges(three):
        cover = d.two_fold_cover(three, start, u, i)
        assert cover is not None and d.agrees(cover, cover.start_state(), three, start, d.LIGHTHOUSE, actions)[0] \
            is False
    found = d.determination(three, start, d.LIGHTHOUSE, actions, three)
    assert found.witness is None and found.complete


def test_a_bridge_has_no_connected_cover_and_the_replay_bound_is_reported():
    two = chain(2)
    assert d.two_fold_cover(two, two.start_state(), "0", 0) is None
    three = cycle(3)
    found = d.determination(three, three.start_state(), d.LIGHTHOUSE, [1, 1, 1], three, max_steps=2)
    assert found.witness is None and not found.complete


@pytest.mark.parametrize("n", [3, 4, 5])
def test_a_subdivided_edge_is_never_walked_so_it_always_agrees(n):
    world = cycle(n)
    start = world.start_state()
    walk = [1] * (n - 1)  # every edge but the last
    found = d.determination(world, start, d.LIGHTHOUSE, walk, world)
    assert found.how == "subdivided" and found.witness.n == n + 1


def test_the_protocol_specification_states_the_rule_and_its_bound():
    text = (Path(__file__).resolve().parents[1] / "spec" / "protocol.md").read_text(encoding="utf-8")
    assert "### No credit for a guess" in text and "| `guess` |" in text
    assert f"{d.MAX_REPLAY_STEPS:,} actions in all per run" in text
    assert f"{wf.MAX_BRANCHES:,} branches" in text
