"""The explorer contract for algorithms beyond Algorithm 3.1 (issue 10 item 6, issue 11 item 5).

A *kit algorithm* (``AlgorithmSpec(uses_lighthouse=False)``) is given a kit
computed from the world, options checked against its parameters, and the
checks its entry names; it may stop with ``AlgorithmFailed`` / ``LimitReached``.
The toy explorers here are deliberately tiny: each exercises one clause of
the contract, on the smallest world that shows it.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from topomark.reference.worlds import generators
from topomark.reference.algorithms.algorithm_spec import AlgorithmSpec, Parameter
from topomark.reference.run.explore import explore
from topomark.reference.algorithms.registry import algorithm_spec
from topomark.spec.errors import InvalidInput, LimitReached, TopomarkFault
from topomark.spec.kit import Kit, MarkerOp
from topomark.spec.mapstate import PartialMap
from topomark.spec.marker import VertexMarker
from topomark.spec.world import World


class _Toy:
    """Drops ``drops`` undirected vertex markers, one per vertex along exit 1, then stops as ``stop`` says."""

    def __init__(self, robot, policies, observer, options):
        self.robot, self.observer, self.options = robot, observer, options
        self.left = options.get("drops", 1)
        self.S = PartialMap()
        self.position = None
        self.iterations = []

    def start(self):
        self.S.add_vertex(self.robot.sense().degree)
        self.position = (0, 0)

    def done(self):
        return self.left == 0

    def step(self):
        self.robot.operate(MarkerOp("vertex"))
        self.robot.move(1, "new")
        self.left -= 1
        if self.options.get("stop") == "limit":
            raise LimitReached("the toy's cap of one step")
        self.observer(self, _Step(len(self.iterations) + 1))

    def models(self):
        truth = (self.S, (0, 0)) if self.left == self.options.get("drops", 1) else None
        wrong = PartialMap()
        wrong.add_vertex(99)
        return [m for m in (truth, (wrong, (0, 0))) if m is not None] if self.options.get("keep_truth") else \
            [(wrong, (0, 0))]


class _Step:
    kind, hypotheses = "step", []

    def __init__(self, number):
        self.number = number

    def to_json(self):
        return {"number": self.number, "kind": self.kind}


def _spec(checks=(), vertex=3, own=True, **kw) -> AlgorithmSpec:
    return AlgorithmSpec(name="toy", thesis="none", kit=Kit(vertex=vertex), bound=None, markers="k", deterministic=True,
                         options=(), checks=(*checks, "isomorphism"), explorer=_Toy, uses_lighthouse=False, own=own,
                         parameters=(Parameter("drops", "how many to drop", 1, minimum=1),), **kw)


def _toy(spec, **options):
    stop = options.pop("stop", None)
    keep = options.pop("keep_truth", None)

    class Toy(_Toy):
        def __init__(self, robot, policies, observer, opts):
            super().__init__(robot, policies, observer, {**opts, "stop": stop, "keep_truth": keep})
    from dataclasses import replace
    return explore(generators.cycle(5), replace(spec, explorer=Toy), options=options)


def test_a_kit_algorithm_runs_with_its_kit_and_reports_its_marker_operations():
    out = _toy(_spec(), drops=2)
    assert (out.outcome, out.claimed, out.cost, out.marker_operations) == ("wrong-map", "correct", 2, {"drop": 2})
    assert out.violation.check == "extended isomorphism"  # the toy's one-vertex map is judged, and is wrong
    assert out.lighthouse is None and out.kit == "3 undirected vertex markers"


def test_running_out_of_markers_is_the_failed_outcome_naming_the_kit():
    out = _toy(_spec(vertex=1), drops=2)
    assert (out.outcome, out.claimed, out.verified) == ("failed", "failed", False)
    assert "out of markers" in out.reason and "1 undirected vertex marker" in out.reason


def test_a_cap_reached_is_the_limit_outcome():
    out = _toy(_spec(), stop="limit")
    assert (out.outcome, out.reason) == ("limit", "the toy's cap of one step")
    assert out.summary()["outcome"] == "limit"


def test_the_marker_budget_is_checked_after_every_step():
    out = _toy(_spec(("marker-budget",), marker_bound_fn=lambda n, m: 1), drops=2)
    assert out.violation.check == "marker budget" and out.violation.found == "2"
    assert out.outcome == "wrong-map"


class _Models(_Toy):
    """Goes out along exit 1 and back once; holds the true one-vertex model (pose: entered by exit 1) unless
    told not to, and a model with a vertex of the wrong degree."""

    def step(self):
        self.robot.move(1, "new")
        self.robot.move(0, "new")
        self.left, self.position = 0, (0, 1)
        self.observer(self, _Step(1))

    def models(self):
        wrong = PartialMap()
        wrong.add_vertex(99)
        return ([(self.S, self.position)] if self.options.get("keep_truth") else []) + [(wrong, (0, 0))]


def test_the_true_world_must_survive_among_the_models():
    from dataclasses import replace
    spec = replace(_spec(("models",)), explorer=_Models)
    keep = type("Keep", (_Models,), {"__init__": lambda self, r, p, o, opts: _Models.__init__(
        self, r, p, o, {"keep_truth": True})})
    out = explore(generators.cycle(5), replace(spec, explorer=keep))
    assert out.violation is not None and out.violation.check != "models"  # survived; the one-vertex map is wrong
    with pytest.raises(TopomarkFault, match="voided the true world"):  # topomark's own explorer: exit 3
        explore(generators.cycle(5), spec)
    out = explore(generators.cycle(5), replace(spec, own=False))  # an explorer under test: a negative verdict
    assert out.violation.check == "models" and out.outcome == "wrong-map"


def test_options_lighthouses_and_worlds_are_checked_against_the_algorithm():
    spec = _spec()
    with pytest.raises(InvalidInput, match="takes no option --thread-length"):
        explore(generators.cycle(4), spec, options={"thread-length": 3})
    with pytest.raises(InvalidInput, match=r"--drops must be an integer >= 1, got '0'"):
        explore(generators.cycle(4), spec, options={"drops": "0"})
    with pytest.raises(InvalidInput, match="takes no lighthouse"):
        explore(generators.cycle(4), spec, lighthouse="directional-edge")
    plain = generators.cycle(4)
    marked = World(plain.rotation, (VertexMarker("0"),), plain.start)
    with pytest.raises(InvalidInput, match="drops its own markers: the world file must carry none"):
        explore(marked, spec)
    with pytest.raises(InvalidInput, match="takes no option --drops"):
        explore(generators.cycle(4), "basic", options={"drops": 1})


def test_algorithm_3_1_reports_the_correct_outcome():
    out = explore(generators.cycle(4), "basic")
    assert (out.outcome, out.claimed, out.reason) == ("correct", "correct", None)
    assert algorithm_spec("basic").to_json()["family"] == "algorithm-3.1"


def test_the_cli_prints_both_outcomes_and_refuses_a_lighthouse_for_no_algorithm():
    run = subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", "explore", "cycle:n=4", "--json"],
                         capture_output=True, text=True, timeout=120)
    data = json.loads(run.stdout)
    assert run.returncode == 0 and (data["outcome"], data["claimed"]) == ("correct", "correct")


def test_a_searched_lighthouse_reports_its_walk_and_where_v0_is_in_the_world():
    out = explore(generators.lattice_hole(4, 4, 0.1, "vertices", 2), "basic", lighthouse="undirected-vertex")
    data = out.summary()
    assert data["outcome"] == "correct" and isinstance(data["walk_steps"], int)
    assert data["lighthouse_at"] in generators.lattice_hole(4, 4, 0.1, "vertices", 2).vertices
    stuck = explore(generators.cycle(4), "basic", lighthouse="undirected-vertex").summary()
    assert (stuck["outcome"], stuck["lighthouse_at"]) == ("failed", None) and "walk" in stuck["reason"]


def test_a_thread_in_the_world_file_must_be_the_lighthouses_own():
    from topomark.spec.thread import Thread, ThreadedWorld
    base = generators.lattice(3, 3)
    v0, facing = base.start_state()
    own = ThreadedWorld(base.rotation, (), base.start, Thread((v0,), base.neighbour(v0, facing), True, ()))
    assert explore(own, "basic", lighthouse="thread").verified  # the thread the robot ties there: accepted
    other = ThreadedWorld(base.rotation, (), base.start,
                          Thread((v0,), base.neighbour(v0, (facing + 1) % base.degree(v0)), True, ()))
    with pytest.raises(InvalidInput, match="cannot use the thread in the world file"):
        explore(other, "basic", lighthouse="thread")
    with pytest.raises(InvalidInput, match="directional-vertex lighthouse cannot use the thread"):
        explore(own, "basic")
    with pytest.raises(InvalidInput, match="must carry none \\(it carries a thread\\)"):
        explore(own, "dudek")


@pytest.mark.parametrize("mode", ["incremental", "full"])
def test_i2_is_checked_only_where_the_algorithm_names_it(mode):
    """An explorer whose U is not the unexplored edges (here: always empty) is judged on I-1 and its pose alone
    when its entry leaves I-2 out — and caught by I-2 when it names it."""
    class NoU(_Models):
        def step(self):
            super().step()
    from dataclasses import replace
    spec = replace(_spec(("pose", "I-1")), explorer=NoU)
    out = explore(generators.cycle(5), spec, check_mode=mode)
    assert out.violation is not None and out.violation.check != "I-2"  # the one-vertex map fails at the end only
    assert out.violation.check == "extended isomorphism"
    named = explore(generators.cycle(5), replace(spec, checks=("pose", "I-1", "I-2", "isomorphism")), check_mode=mode)
    assert named.violation.check == "I-2"


def test_a_stopped_runs_trace_replays_up_to_where_it_stopped(tmp_path):
    from topomark.reference.replay.replay import replay
    from topomark.reference.trace.reader import parse_trace
    from topomark.reference.trace.records import dump_trace
    world = generators.lattice(3, 3)
    out = explore(world, "case-3b", options={"markers": 2})
    assert out.outcome == "failed" and out.trace[-1]["outcome"] == "failed" and out.trace[-1]["reason"] == out.reason
    text = dump_trace(out.trace)
    result = replay(world, parse_trace(text))
    assert result.ok and "stopped before it had a map: failed (out of markers" in result.message
    bad = text.replace('"outcome":"failed",', "")  # a reason with no outcome: the end contradicts itself
    with pytest.raises(InvalidInput, match="end.outcome and end.reason come together"):
        replay(world, parse_trace(bad))
