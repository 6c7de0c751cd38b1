"""Algorithm 3.1's line 5 as a hook (reference/explorers/edge_choices.py): an edge choice registered by name is
an edge policy like nearest, fifo and lifo; a registration makes one its default (``edge_policy``); and a run's
report names the policies its algorithm consults, and only those."""

from __future__ import annotations

import json

import pytest

from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec
from topomark.reference.algorithms.registrations.algorithm31 import lighthouse_algorithm
from topomark.reference.algorithms.registry import REGISTRY, register, unregister
from topomark.reference.cli.main import main
from topomark.reference.explorers.algorithm31 import LighthouseExplorer
from topomark.reference.explorers.edge_choices import (BUILT_IN, EDGE_CHOICES, register_edge_choice,
                                                       unregister_edge_choice)
from topomark.reference.explorers.policies import Policies
from topomark.reference.run.explore import explore
from topomark.reference.trace.header import header_policies
from topomark.reference.worlds.argument import resolve_world
from topomark.spec.errors import ExplorerFault, InvalidInput

LATTICE = "lattice:rows=3,cols=4"


def farthest(S, dist):
    """The entry of U whose known end is farthest from the robot, the first listed among equals."""
    ds = [dist[v] for v, _ in S.unexplored]
    return ds.index(max(ds))


@pytest.fixture
def choice():
    """``farthest`` registered as an edge choice for the test, and taken out again; the calls it answers."""
    calls: list[int] = []

    def counted(S, dist):
        calls.append(len(S.unexplored))
        return farthest(S, dist)
    register_edge_choice("far-end", counted)
    try:
        yield calls
    finally:
        unregister_edge_choice("far-end")
        for name in [n for n, s in REGISTRY.items() if s.edge_policy == "far-end"]:
            unregister(name)


def edges(outcome) -> list:
    return [it.edge for it in outcome.explorer.iterations]


def test_a_registered_edge_choice_is_an_edge_policy_line_5_asks(choice):
    world = resolve_world(LATTICE)
    far = explore(world, "basic", Policies(edge="far-end"))
    near = explore(world, "basic", Policies(edge="nearest"))
    assert far.verified and near.verified and far.cost <= REGISTRY["basic"].bound_for(world.n, world.m)
    assert len(choice) == far.iterations == world.m  # asked once per iteration, at line 5
    assert edges(far) != edges(near)  # and its answer is the edge taken
    assert far.trace[0]["policies"]["edge"] == "far-end"
    assert header_policies(far.trace[0]["policies"], "t").edge == "far-end"  # a trace naming it is readable


def test_the_command_line_takes_a_registered_edge_choice(choice, capsys):
    assert main(["explore", LATTICE, "--algorithm", "enh3", "--policy", "edge=far-end", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["policies"]["edge"] == "far-end"
    assert main(["explore", LATTICE, "--algorithm", "dudek", "--policy", "far-end", "--quiet"]) == 0
    assert "policies edge=far-end" in capsys.readouterr().out


def test_an_unknown_edge_choice_is_bad_input_and_a_name_is_taken_once(choice, capsys):
    with pytest.raises(InvalidInput, match="unknown edge policy 'nearst'"):
        Policies(edge="nearst")
    with pytest.raises(ValueError, match="registered twice"):
        register_edge_choice("far-end", farthest)
    with pytest.raises(ValueError, match="registered twice"):
        register_edge_choice("nearest", farthest)
    with pytest.raises(ValueError, match="lower-case"):
        register_edge_choice("Far Away", farthest)
    with pytest.raises(ValueError, match="cannot be unregistered"):
        unregister_edge_choice("fifo")
    assert set(BUILT_IN) == {"nearest", "fifo", "lifo"} <= set(EDGE_CHOICES)


def test_a_choice_that_names_no_edge_of_U_is_a_fault_of_the_choice():
    register_edge_choice("past-the-end", lambda S, dist: len(S.unexplored))
    try:
        with pytest.raises(ExplorerFault, match="'past-the-end' returned"):
            explore(resolve_world("cycle:n=4"), "basic", Policies(edge="past-the-end"))
    finally:
        unregister_edge_choice("past-the-end")


def test_a_registration_sets_its_edge_choice_and_runs_take_it_unless_one_is_chosen(choice, capsys):
    spec = register(lighthouse_algorithm("basic-far-end", "§3.3, Algorithm 3.1, the farthest edge of U first",
                                         LighthouseExplorer, edge_policy="far-end"))
    world = resolve_world(LATTICE)
    out = explore(world, "basic-far-end")
    assert out.verified and out.trace[0]["policies"]["edge"] == "far-end"
    assert edges(out) == edges(explore(world, "basic", Policies(edge="far-end")))
    assert explore(world, "basic-far-end", Policies(edge="nearest")).trace[0]["policies"]["edge"] == "nearest"
    assert spec.policies({"hypothesis": "lifo"}).to_json() == {"edge": "far-end", "hypothesis": "lifo",
                                                               "path": "shortest"}
    assert main(["explore", LATTICE, "--algorithm", "basic-far-end", "--quiet"]) == 0
    assert "policies edge=far-end, hypothesis=fifo, path=shortest" in capsys.readouterr().out
    assert main(["explore", LATTICE, "--algorithm", "basic-far-end", "--policy", "hypothesis=lifo", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["policies"] == {"edge": "far-end", "hypothesis": "lifo",
                                                               "path": "shortest"}
    assert main(["algorithms", "--json"]) == 0
    [entry] = [e for e in json.loads(capsys.readouterr().out) if e["name"] == "basic-far-end"]
    assert entry["policies"]["edge"] == "far-end" and entry["options"][0].startswith("policy edge=far-end|")


def test_an_edge_policy_must_be_registered_and_declared():
    basic = REGISTRY["basic"]
    fields = dict(name="x", thesis="§3.3", kit=basic.kit, bound=None, markers="1", deterministic=True,
                  checks=("isomorphism",), explorer=LighthouseExplorer)
    with pytest.raises(ValueError, match="edge_policy 'no-such-choice' is a registered edge choice"):
        AlgorithmSpec(**fields, options=basic.options, edge_policy="no-such-choice")
    with pytest.raises(ValueError, match="declares 'policy edge'"):
        AlgorithmSpec(**fields, options=(), edge_policy="fifo")
    assert AlgorithmSpec(**fields, options=basic.options, edge_policy="fifo").policies().edge == "fifo"


@pytest.mark.parametrize("algorithm, world, shown", [
    ("basic", "cycle:n=5", "policies edge=nearest, hypothesis=fifo, path=shortest)"),
    ("dudek", "cycle:n=5", "policies edge=nearest)"),
    ("case-4", "cycle:n=5", "no policies)"),
    ("labelled-dfs", "chain:n=4", "no policies)"),
])
def test_the_report_names_only_the_policies_the_algorithm_consults(capsys, algorithm, world, shown):
    assert main(["explore", world, "--algorithm", algorithm, "--quiet"]) == 0
    head = capsys.readouterr().out.splitlines()[0]
    assert head.startswith(f"explored {world} with ") and head.endswith(shown), head
    assert main(["explore", world, "--algorithm", algorithm, "--json"]) == 0
    declared = REGISTRY[algorithm].policy_kinds
    assert sorted(json.loads(capsys.readouterr().out)["policies"]) == sorted(declared)
