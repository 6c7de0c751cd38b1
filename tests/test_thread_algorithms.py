"""The thread algorithms of §6.3 (reference/explorers/threads_*.py, reference/algorithms/registrations/threads.py):
carried l = ε (§6.3.1), Algorithm 6.7 (l = c(G)), the knot thread (l ≫ m, Figure 6.20) and Algorithm 6.8
(explore-explore, --thread-length)."""

from __future__ import annotations


import pytest
from hypothesis import given, settings

from topomark.reference.bench.measure import thread_length as bench_threads

from topomark.reference.worlds import generators
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.explorers import threads_carried, threads_knots
from topomark.reference.explorers.policies import Policies
from topomark.reference.algorithms.registry import algorithm_spec, variant
from topomark.reference.run.simulator import Simulator
from topomark.spec.signature import Signature
from topomark.spec.world import Start, World

from conftest import SMALL_WORLDS, bare, make_world
from families import family_worlds

THREADS = ["thread-carried", "thread-circumference", "thread-knots", "thread-explore"]
PAW = World({"a": ["b", "c", "d"], "b": ["c", "a"], "c": ["a", "b"], "d": ["a"]}, (), Start("d", "a"))
"""A triangle with a pendant start: c(G) = 3, but Algorithm 6.7 lays d-a-b-c and then the loop edge c-a."""


@pytest.mark.parametrize("text", SMALL_WORLDS)
@pytest.mark.parametrize("name,opts", [(n, {}) for n in THREADS] + [("thread-explore", {"thread-length": 1}),
                                                                     ("thread-explore", {"thread-length": 3})])
def test_each_algorithm_maps_the_thesis_families_within_our_bound(name, opts, text):
    w = bare(make_world(text))
    out = explore(w, name, options=opts)
    assert out.outcome == "correct" and out.verified, out.violation
    assert out.cost <= algorithm_spec(name).bound_for(w.n, w.m)
    assert all(out.explorer.S.thread_mark(v) is None for v in out.explorer.S.vertices)  # S shows no thread...
    assert out.marker_operations["untie"] == out.marker_operations["tie"]  # ...and none is left in the world


def drive(world: World, name: str, opts: dict) -> tuple[Simulator, int]:
    """Run ``name`` on ``world`` unchecked, watching the true thread after every move: (simulator, most laid)."""
    spec = algorithm_spec(name)
    opts = spec.parse_options(opts)
    kit = spec.kit_for(world.n, world.m, opts)
    most = [0]
    sim = Simulator(World(world.rotation), world.start_state(), kit,
                    listener=lambda *_: most.__setitem__(0, max(most[0], len(sim.layer.thread.laid))))
    explorer = spec.factory(sim.robot(), Policies(), None, opts)
    explorer.start()
    while not explorer.done():
        explorer.step()
    return sim, most[0]


@settings(max_examples=15, deadline=None)
@given(family_worlds(small=True))
def test_the_laid_thread_never_exceeds_its_length_and_is_untied_at_the_end(world):
    for name, opts in [(n, {}) for n in THREADS] + [("thread-explore", {"thread-length": 1})]:
        sim, most = drive(world, name, opts)
        assert most <= sim.kit.thread and sim.layer.thread.tied is None, name
        if name == "thread-knots":
            assert most <= world.m + 1
        out = explore(world, name, options=opts, record=False)
        assert out.outcome == "correct" and out.cost == sim.cost, name


def test_c_of_g_runs_out_on_a_triangle_with_a_pendant_start():
    """§6.3.2 asks for a thread that never runs out on a simple path, footnote 18 (§6.3.2) makes it the longest
    simple cycle; decided: l = c(G) = 3 runs out on the smallest world with a path from v0 longer than
    its longest cycle; n edges (the registered default) and c(G) + 1 here do not."""
    assert bench_threads.circumference(PAW) == 3 and bench_threads.longest_path_from(PAW, "d") == 3
    out = explore(PAW, "thread-circumference", options={"thread-length": 3})
    assert out.outcome == "failed" and out.reason.startswith("out of thread") and not out.verified
    assert out.cost == 3  # d-a-b-c laid; the loop edge c-a would be the fourth
    for opts in ({"thread-length": 4}, {}):
        assert explore(PAW, "thread-circumference", options=opts).outcome == "correct"
    assert explore(PAW, "thread-explore", options={"thread-length": 3}).outcome == "correct"  # 6.8 copes


def test_the_circumference_search_finds_worlds_that_run_out():
    found = bench_threads.search_circumference(40, seed=1)
    assert found["ran_out"] > 0 and found["never_longer_than_path_bound"]
    assert found["smallest"]["c"] < found["smallest"]["n"]


class Unshown(threads_knots.KnotThreadExplorer):
    """Lays the thread but never shows it in S."""

    def show_thread(self) -> None:
        pass


def test_s_shows_the_thread_between_steps_and_a_map_that_does_not_is_caught():
    out = explore(generators.cycle(4), "thread-knots")
    assert out.outcome == "correct" and out.explorer.S.thread_marks == {}  # all rewound and untied at the end
    hidden = explore(generators.cycle(4), variant("unshown", Unshown, like="thread-knots"))
    assert hidden.outcome == "wrong-map" and hidden.violation.check == "I-1" and hidden.violation.where.startswith(
        "map vertex 0")


def test_the_carried_thread_is_the_directional_movable_marker():
    """§6.3.1: tied toward the entry edge, the thread reads as V-p; an untied or passing thread as unmarked."""
    assert str(threads_carried.ThreadAsMarker.as_marker(Signature.parse("[3,A,A,T-2,F]"))) == "[3,V-2,A]"
    assert str(threads_carried.ThreadAsMarker.as_marker(Signature.parse("[3,A,A,S-0,F]"))) == "[3,A,A]"
    k4 = generators.complete(4)
    carried, directional = explore(k4, "thread-carried"), explore(k4, "dudek-directional")
    assert carried.outcome == "correct" and carried.cost == directional.cost  # same moves, thread for marker
    assert carried.marker_operations["tie"] == carried.marker_operations["leave"] == directional.marker_operations["drop"]


def test_algorithm_6_7_searches_back_along_the_thread_when_the_sensed_thread_is_ambiguous():
    out = explore(generators.lattice(3, 3), "thread-circumference")
    how = [it.how for it in out.explorer.iterations]
    assert out.outcome == "correct" and "thread search" in how and "sensed" in how
    assert out.marker_operations["leave"] == out.marker_operations["take"] == how.count("thread search")
    assert out.marker_operations["tie"] == 1  # Algorithm 6.7 never reties


def test_algorithm_6_8_reties_and_searches_off_the_thread_for_the_free_end():
    """l = 1 on a 4-cycle: each v_s explores one edge at a time; the far vertex is found off the thread."""
    out = explore(generators.cycle(4), "thread-explore", options={"thread-length": 1})
    assert out.outcome == "correct"
    assert out.marker_operations["tie"] == 3 and [it.how for it in out.explorer.iterations].count("off-thread search")
    assert max(it.laid for it in out.explorer.iterations) <= 1


def test_the_knot_thread_costs_two_per_edge_plus_two_per_probe_under_3m_on_lattice_holes():
    for seed in range(3):
        w = generators.lattice_hole(5, 5, 0.1, "edges", seed)
        out = explore(w, "thread-knots", record=False)
        probes = sum(it.how == "probe" for it in out.explorer.iterations)
        assert out.outcome == "correct" and out.cost == 2 * w.m + 2 * probes < 3 * w.m
        assert out.by_purpose.get("probe", 0) == 2 * probes


@pytest.mark.parametrize("args,message", [
    (["--algorithm", "thread-explore", "--thread-length", "0"], "--thread-length must be an integer >= 1"),
    (["--algorithm", "thread-explore", "--thread-length", "-2"], "--thread-length must be an integer >= 1"),
    (["--algorithm", "thread-explore", "--thread-length", "two"], "--thread-length must be an integer >= 1"),
    (["--algorithm", "thread-explore", "--thread-length", "2.5"], "--thread-length must be an integer >= 1"),
    (["--algorithm", "thread-circumference", "--thread-length", "0"], "--thread-length must be an integer >= 1"),
    (["--algorithm", "thread-knots", "--thread-length", "3"], "takes no option --thread-length"),
    (["--algorithm", "thread-carried", "--thread-length", "3"], "takes no option --thread-length"),
    (["--algorithm", "dudek", "--thread-length", "3"], "takes no option --thread-length"),
    (["--algorithm", "basic", "--thread-length", "3"], "takes no option --thread-length"),
])
def test_bad_thread_length_is_bad_input(args, message, capsys):
    assert main(["explore", "cycle:n=5", *args]) == 2
    assert message in capsys.readouterr().err


def test_the_cli_runs_a_thread_algorithm_with_a_length(capsys):
    assert main(["explore", "lattice-hole:rows=4,cols=4,seed=1", "--algorithm", "thread-explore",
                 "--thread-length", "3"]) == 0
    assert main(["explore", "chain:n=5", "--algorithm", "thread-circumference", "--thread-length", "3"]) == 1
    assert "out of thread" in capsys.readouterr().out
