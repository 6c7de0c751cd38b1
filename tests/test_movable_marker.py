"""Dudek et al.'s single movable marker algorithm and its directional variant (§2.3.1).

Every run here is checked (pose, I-1, I-2, bound function, marker budget, iteration counts, final extended
isomorphism); each test adds what it proves.  The decisions of
:mod:`topomark.reference.explorers.movable_marker` are each shown on the smallest world that shows them.
"""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings

from families import family_worlds
from topomark.reference.worlds import generators
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers.movable_marker import MovableMarkerExplorer
from topomark.reference.algorithms.registry import algorithm_spec, variant

from conftest import FIGURE_3_4, SMALL_WORLDS, bare, make_world

ALGORITHMS = ("dudek", "dudek-directional")
NEEDS_BACK_LINK = ("complete-hole:n=6,fraction=0.2,seed=1", "random:n=7,fraction=0.5,seed=3", *FIGURE_3_4,
                   "small-world:n=12,k=4,p=0.2,seed=1")


def _ops(outcome) -> list[str]:
    return [rec["op"] for rec in outcome.trace if rec.get("event") == "op"]


def _assert_one_marker(outcome) -> None:
    """The robot drops, then picks up, then drops ...: never two markers, none left in the world at the end."""
    ops = _ops(outcome)
    assert ops == ["drop", "pick_up"] * (len(ops) // 2)
    assert outcome.marker_operations.get("drop", 0) == outcome.marker_operations.get("pick_up", 0)


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("text", SMALL_WORLDS)
def test_both_algorithms_map_the_thesis_families_within_our_bound(name, text):
    w = bare(make_world(text))  # Figure 3.4's wheels: the robot brings its own marker
    out = explore(w, name)
    assert (out.outcome, out.verified, out.violation) == ("correct", True, None)
    assert (out.nonloop_iterations, out.loop_iterations) == (w.n - 1, w.m - w.n + 1)
    assert out.m <= out.cost <= algorithm_spec(name).bound_for(w.n, w.m)
    _assert_one_marker(out)
    probes = sum(it.probes for it in out.explorer.iterations)  # edges tried: each out and back, the last out only
    assert sum(2 * it.probes - 1 for it in out.explorer.iterations if it.probes) == out.by_purpose.get("probe", 0)
    if name == "dudek-directional":  # the marker's direction names e': no back-link search (§2.3.1)
        assert probes == 0
    elif text in NEEDS_BACK_LINK:  # symmetric neighbourhoods: some v_k' has two or more unexplored edges
        assert probes > 0


@settings(max_examples=25, deadline=None)
@given(family_worlds(small=True))
def test_every_family_world_is_mapped_holding_at_most_one_marker(world):
    for name in ALGORITHMS:
        out = explore(world, name)
        assert out.outcome == "correct", (name, out.violation)
        _assert_one_marker(out)


def test_a_triangle_needs_one_drop_and_no_back_link_search():
    """Cycle v0 v1 v2.  Steps 1–2: S holds no other vertex of degree 2 with an unexplored edge that is not v_k
    or its neighbour, so v_u is new with no drop (1 move each).  Step 3 reaches v0 from v2: drop, come back
    over e (§2.3.1), walk v2 → v1 → v0 seeing the marker; v0 has one unexplored edge, so it is e' with no
    move, and the marker is picked up there.  1 + 1 + (1 + 1 + 2) = 6."""
    for name in ALGORITHMS:
        out = explore(generators.cycle(3), name)
        assert (out.cost, out.by_purpose, out.marker_operations) == (
            6, {"new": 3, "retrace": 1, "validation": 2}, {"drop": 1, "pick_up": 1})
        assert [it.kind for it in out.explorer.iterations] == ["non-loop", "non-loop", "loop"]


def test_a_new_place_is_found_by_searching_s_then_the_marker_is_fetched_from_it():
    """Cycle of 4.  Step 3 reaches v3 from v2: v0 is a candidate, so drop at v3, back to v2, walk to v0 (2),
    no marker: v3 is new; walk back to v2 (2) and over e (1) to pick the marker up — 7 moves, 3 of them
    fetching ('other').  Step 4 reaches v0 from v3, walks v3 v2 v1 v0 (3) and finds it: 5 moves."""
    out = explore(generators.cycle(4), "dudek")
    assert out.cost == 1 + 1 + 7 + 5
    assert out.by_purpose == {"new": 4, "retrace": 2, "validation": 5, "other": 3}
    its = out.explorer.iterations
    assert (its[2].kind, its[2].candidates, its[2].found) == ("non-loop", [0], None)
    assert (its[3].kind, its[3].found, its[3].probes) == ("loop", 0, 0)


def test_the_back_link_search_on_the_smallest_complete_graph():
    """K4: in step 4 the marker is found at v0, which still has two unexplored edges; the undirected marker is
    carried to v_k and v0's edges are traversed until one leads to it (§2.3.1); the directional marker names e'
    where it lies, so the same step costs no probe and one drop fewer."""
    k4 = generators.complete(4)
    plain, pointed = explore(k4, "dudek"), explore(k4, "dudek-directional")
    step = plain.explorer.iterations[3]
    assert (step.kind, step.found, step.probes) == ("loop", 0, 2)
    assert pointed.explorer.iterations[3].probes == 0 and "probe" not in pointed.by_purpose
    assert pointed.marker_operations["drop"] < plain.marker_operations["drop"]
    assert pointed.cost < plain.cost


def test_a_robot_that_keeps_dropping_runs_out_of_its_one_marker():
    class NeverPicksUp(MovableMarkerExplorer):
        def __init__(self, *args):
            super().__init__(*args)
            operate = self.robot.operate
            self.robot = type("R", (), {"move": self.robot.move, "sense": self.robot.sense,
                                        "operate": staticmethod(lambda op: None if op.pick_up else operate(op))})()
    hoarder = variant("hoarder", NeverPicksUp, like="dudek")
    out = explore(generators.cycle(5), hoarder, check=False)
    assert out.outcome == "failed" and "out of markers" in out.reason and "1 undirected movable" in out.reason
    checked = explore(generators.cycle(5), hoarder)  # the checker sees first the marker left lying, not in S
    assert checked.outcome == "wrong-map" and "markers are not preserved" in str(checked.violation)


def test_the_cli_explores_with_dudek_and_lists_both(capsys):
    assert main(["explore", "lattice-hole:rows=4,cols=4,seed=2", "--algorithm", "dudek", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["outcome"], data["verified"], data["lighthouse"]) == ("correct", True, None)
    assert data["marker_operations"]["drop"] == data["marker_operations"]["pick_up"] > 0
    assert main(["algorithms", "--json"]) == 0
    listed = {a["name"]: a for a in json.loads(capsys.readouterr().out)}
    assert listed["dudek"]["kit"] == {"undirected-vertex": 1, "movable": True}
    assert listed["dudek-directional"]["kit"] == {"directional-vertex": 1, "movable": True}
    assert listed["dudek"]["thesis"].startswith("§2.3.1, Dudek et al. [24, 26]")


def test_a_lighthouse_is_bad_input_for_a_movable_marker(capsys):
    assert main(["explore", "cycle:n=4", "--algorithm", "dudek", "--lighthouse", "directional-vertex"]) == 2
    assert "takes no lighthouse" in capsys.readouterr().err
