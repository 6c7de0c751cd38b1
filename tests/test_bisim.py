"""Tests of topomark.proofs.bisim (indistinguishability, §3.2) and ``topomark distinguish``.

Second opinions: AALpy's Moore-machine bisimilarity check (an independent
implementation; test dependency ``aalpy``) and a brute force over every
motion sequence up to a bounded length.
"""

from __future__ import annotations

import itertools
import json
import random

import pytest
from aalpy.automata import MooreMachine, MooreState
from aalpy.utils import bisimilar
from hypothesis import given, settings
from hypothesis import strategies as st

from topomark.proofs.bisim import (Distinction, bisimulation, check_relation, distinguishing_sequence,
                                   indistinguishable, is_counterexample)
from topomark.proofs.figures import cycle_world, figure_3_3, figure_3_4, figure_3_6, figure_6_1a, figure_6_1b
from topomark.reference.cli.main import main
from topomark.reference.worlds.strategies import relabelled, rotated, worlds
from topomark.spec.errors import InvalidInput
from topomark.spec.robot import perceive, sense, step
from topomark.spec.world import Start, World
from topomark.spec.worldfile import save_world

FAST = settings(max_examples=60, deadline=None)


# -- second opinions -------------------------------------------------------------------
def aalpy_machine(world: World) -> MooreMachine:
    """The robot as an AALpy Moore machine: output = signature text, inputs = motions."""
    states = {s: MooreState(s, output=str(sense(world, s))) for s in world.darts()}
    for s, state in states.items():
        for motion in range(world.degree(s[0])):
            state.transitions[motion] = states[step(world, s, motion)]
    return MooreMachine(states[world.start_state()], list(states.values()))


def all_sequences(world: World, length: int):
    """Every valid motion sequence of exactly ``length`` motions from the start of ``world``."""
    def extend(state, prefix):
        if len(prefix) == length:
            yield tuple(prefix)
            return
        for motion in range(world.degree(state[0])):
            yield from extend(step(world, state, motion), prefix + [motion])
    yield from extend(world.start_state(), [])


def same_perceptions_up_to(a: World, b: World, length: int) -> bool:
    """Brute force: equal start signatures and equal P for every motion sequence of ≤ ``length`` motions."""
    if sense(a, a.start_state()) != sense(b, b.start_state()):
        return False
    for motions in all_sequences(a, length):
        try:
            if perceive(a, a.start_state(), motions) != perceive(b, b.start_state(), motions):
                return False
        except InvalidInput:  # a motion invalid in b: the degrees differed earlier
            return False
    return True


def small_pair():
    return st.tuples(worlds(2, 5, max_degree=3, markers="undirected-vertex", with_start=True),
                     worlds(2, 5, max_degree=3, markers="undirected-vertex", with_start=True))


def cycles_pair():
    return st.tuples(worlds(3, 7, max_degree=2, with_start=True), worlds(3, 7, max_degree=2, with_start=True))


# -- basic verdicts ------------------------------------------------------------------
def test_cycles_of_different_length_are_indistinguishable_and_not_isomorphic():
    a, b = figure_3_3()
    assert distinguishing_sequence(a, b) is None
    assert indistinguishable(a, b) and is_counterexample(a, b)
    assert check_relation(a, b, bisimulation(a, b)) is None


def test_wheel_pair_is_a_counterexample_and_its_directional_version_is_not():
    a, b = figure_3_4()
    assert is_counterexample(a, b)
    da, db = figure_3_6()
    d = distinguishing_sequence(da, db)
    assert d is not None and not is_counterexample(da, db)
    assert d.motions == (0, 1, 1)  # the §3.3 text's example, and the shortest
    assert [str(s) for s in d.perceptions_a] == ["[3,A,A]", "[3,A,A]", "[4,V-1,A]"]
    assert [str(s) for s in d.perceptions_b] == ["[3,A,A]", "[3,A,A]", "[4,V-3,A]"]


def test_a_world_is_not_a_counterexample_with_itself():
    a, _ = figure_3_4()
    assert indistinguishable(a, a) and not is_counterexample(a, a)


def test_different_start_signatures_give_the_empty_motion_sequence():
    a = cycle_world(3)
    b = World({"x": ["y"], "y": ["x"]}, start=Start("x", "y"))
    d = distinguishing_sequence(a, b)
    assert d == Distinction((), (sense(a, a.start_state()),), (sense(b, b.start_state()),))
    assert bisimulation(a, b) is None


def test_edge_marker_pair_and_its_directional_version():
    a, b = figure_6_1a()
    assert is_counterexample(a, b)
    da, db = figure_6_1b()
    d = distinguishing_sequence(da, db)
    assert d is not None and d.perceptions_a[-1] != d.perceptions_b[-1]


def test_shortest_sequence_on_a_path():
    """From the middle of P3 facing one end vs. facing a degree-2 vertex of P4."""
    p3 = World({"a": ["b"], "b": ["a", "c"], "c": ["b"]}, start=Start("b", "a"))
    p4 = World({"a": ["b"], "b": ["a", "c"], "c": ["b", "d"], "d": ["c"]}, start=Start("b", "c"))
    d = distinguishing_sequence(p3, p4)
    assert d.motions == (0,)
    assert [str(s) for s in d.perceptions_a] == ["[1,A,A]"] and [str(s) for s in d.perceptions_b] == ["[2,A,A]"]


# -- properties ----------------------------------------------------------------------
@FAST
@given(worlds(2, 7, max_degree=4, markers="any", with_start=True), st.randoms(use_true_random=False))
def test_isomorphic_copy_is_indistinguishable_with_a_functional_certificate(world, rng):
    copy = rotated(relabelled(world, rng), rng)
    relation = bisimulation(world, copy)
    assert relation is not None and check_relation(world, copy, relation) is None
    image = dict(relation)
    assert len(image) == len(relation)  # the isomorphism relates each state to exactly one state
    assert not is_counterexample(world, copy)


@FAST
@given(small_pair())
def test_distinction_really_distinguishes_and_is_shortest(pair):
    a, b = pair
    d = distinguishing_sequence(a, b)
    if d is None:
        assert same_perceptions_up_to(a, b, 5)
        return
    if not d.motions:
        assert sense(a, a.start_state()) != sense(b, b.start_state())
        return
    pa = perceive(a, a.start_state(), d.motions)
    pb = perceive(b, b.start_state(), d.motions)
    assert tuple(pa) == d.perceptions_a and tuple(pb) == d.perceptions_b
    assert pa[:-1] == pb[:-1] and pa[-1] != pb[-1]
    assert same_perceptions_up_to(a, b, len(d.motions) - 1)


@FAST
@given(st.one_of(small_pair(), cycles_pair()))
def test_agrees_with_aalpy(pair):
    a, b = pair
    cex = bisimilar(aalpy_machine(a), aalpy_machine(b), return_cex=True)
    d = distinguishing_sequence(a, b)
    assert (cex is None) == (d is None)
    if d is not None:
        assert len(cex) == len(d.motions)


@FAST
@given(cycles_pair())
def test_cycles_without_markers_are_always_indistinguishable(pair):
    a, b = pair
    if all(a.degree(v) == 2 for v in a.vertices) and all(b.degree(v) == 2 for v in b.vertices):
        assert indistinguishable(a, b)
        assert is_counterexample(a, b) == (a.n != b.n)


@FAST
@given(small_pair(), st.randoms(use_true_random=False))
def test_check_relation_rejects_tampered_certificates(pair, rng):
    a, _ = pair
    b = rotated(relabelled(a, rng), rng)
    relation = set(bisimulation(a, b))
    start = (a.start_state(), b.start_state())
    assert check_relation(a, b, relation - {start}) is not None
    if len(relation) > 1:
        dropped = rng.choice(sorted(relation - {start}))
        assert check_relation(a, b, relation - {dropped}) is not None  # no longer closed
    bad = next(((sa, sb) for sa in a.darts() for sb in b.darts() if sense(a, sa) != sense(b, sb)), None)
    if bad is not None:
        assert check_relation(a, b, relation | {bad}) is not None


def test_bisimulation_output_is_accepted_on_the_figures():
    for a, b in (figure_3_3(), figure_3_4(), figure_6_1a()):
        assert check_relation(a, b, bisimulation(a, b)) is None


# -- CLI -----------------------------------------------------------------------------
def write_pair(tmp_path, pair):
    pa, pb = tmp_path / "a.json", tmp_path / "b.json"
    save_world(pair[0], pa)
    save_world(pair[1], pb)
    return str(pa), str(pb)


def test_cli_distinguish_distinguishable(tmp_path, capsys):
    a, b = write_pair(tmp_path, figure_3_6())
    assert main(["distinguish", a, b]) == 0
    out = capsys.readouterr().out
    assert "M = (0,1,1)" in out and "P_A = ([3,A,A], [3,A,A], [4,V-1,A])" in out
    assert main(["distinguish", a, b, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data == {"distinguishable": True, "motions": [0, 1, 1],
                    "perceptions_a": ["[3,A,A]", "[3,A,A]", "[4,V-1,A]"],
                    "perceptions_b": ["[3,A,A]", "[3,A,A]", "[4,V-3,A]"]}


def test_cli_distinguish_indistinguishable(tmp_path, capsys):
    pair = figure_3_4()
    a, b = write_pair(tmp_path, pair)
    assert main(["distinguish", a, b, "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data == {"distinguishable": False, "relation_size": len(bisimulation(*pair))}
    assert main(["distinguish", a, b]) == 1
    assert "indistinguishable" in capsys.readouterr().out


def test_cli_distinguish_needs_starts_and_valid_files(tmp_path, capsys):
    a, b = write_pair(tmp_path, (cycle_world(3, start=False), cycle_world(4)))
    assert main(["distinguish", a, b]) == 2
    assert "no start" in capsys.readouterr().err
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    assert main(["distinguish", str(bad), b]) == 2
    assert main(["distinguish", str(tmp_path / "missing.json"), b]) == 2
