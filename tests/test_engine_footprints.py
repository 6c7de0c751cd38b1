"""The compiled footprint searches of §6.2.1 agree with the reference run for run (Cases 1a, 1b, 2 and 4)."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest

from topomark.proofs.census_map import plan
from topomark.proofs.world_arrays import to_arrays
from topomark.reference import engine
from topomark.reference.cli.main import main
from topomark.reference.engine import FOOTPRINT_CASES, choose, compare, footprint_runs, runs
from topomark.reference.engine.compare import reference_run
from topomark.reference.engine.equality import main as equality_main
from topomark.reference.worlds.generators import lattice
from topomark.reference.worstcase.exhaustive import Setup, run_task

ROOT = Path(__file__).resolve().parents[1]
STARTS_N4_D3 = 1 + 3 + 32
"""Start orbits of every world with n ≤ 4 and degrees ≤ 3 (``tests/test_engine.py`` counts them too)."""


@pytest.mark.parametrize("algorithm", FOOTPRINT_CASES)
def test_every_start_agrees_on_the_small_census(algorithm):
    """The fixed fast slice per case: n <= 4, degree <= 3, every edge policy the case takes."""
    count = 0
    for task in plan(4, 3, 2):
        for unit, _ in task:
            result = compare.run_cases(("census", [unit], 3, algorithm, None))
            assert result["disagreement_count"] == 0, result["disagreement_text"]
            count += sum(result["counts"].values())
    assert count == len(compare.combos_for(algorithm)) * STARTS_N4_D3
    assert len(compare.combos_for(algorithm)) == (1 if algorithm.startswith("case-4") else 3)


def test_one_run_agrees_field_by_field_with_its_searches_and_markers():
    world = lattice(3, 3)
    want, codes = reference_run(world, ("0,0", 0), ("lifo", "fifo", "shortest"), algorithm="case-2")
    run = runs.run_logged(to_arrays(world), (0, 0), ("lifo", "fifo", "shortest"), algorithm="case-2")
    assert run.actions.tolist() == codes and run.digest() == want["digest"]
    assert (run.claimed, run.cost, run.by_purpose, run.marker_operations) == (
        want["claimed"], want["cost"], want["by_purpose"], want["marker_operations"])
    assert run.counts == {k: want[k] for k in run.counts}
    assert want["by_purpose"]["validation"] > 0 and want["loop_iterations"] == 4  # m - n + 1 searches


def test_the_kit_is_the_registrations():
    arrays = to_arrays(lattice(2, 3))  # n = 6, m = 7
    assert [footprint_runs.kit_of(a, arrays) for a in FOOTPRINT_CASES] == [
        (0, 7, 0), (0, 0, 8), (0, 13, 0), (0, 7 - 2, 0), (0, 2 + 6, 0)]


def test_seeded_fault_case_2_dropping_one_marker_is_caught_at_the_first_drop(monkeypatch, capsys):
    """Seeded fault: the engine runs Case 2 with Case 1a's one marker on a non-loop edge."""
    monkeypatch.setitem(footprint_runs.CASES, "case-2", footprint_runs.CASES["case-1a"])
    assert equality_main(["--algorithm", "case-2", "--max-vertices", "3", "--max-degree", "2", "--quiet"]) == 3
    err = capsys.readouterr().err
    assert "disagree" in err and "world census n=2" in err and "(case-2), start v0 facing exit 0" in err
    assert ("first differing action #1: engine drop 1 edge marker(s) on relative exit 0, reference drop 2 edge "
            "marker(s) on relative exit 0") in err


def test_the_equality_command_takes_algorithms(capsys):
    assert equality_main(["--max-vertices", "3", "--max-degree", "2", "--algorithm", "case-1b", "--algorithm",
                          "case-4-mn", "--algorithm", "case-1b", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["by_algorithm"] == {"case-1b": 3 * 4, "case-4-mn": 4} and report["worlds"] == 3
    with pytest.raises(SystemExit) as exit_:
        equality_main(["--algorithm", "case-3a"])
    assert exit_.value.code == 2 and "invalid choice: 'case-3a'" in capsys.readouterr().err


def test_the_exhaustive_search_gives_the_same_record_with_either_engine():
    units = [u for task in plan(4, 3, 4, task_worlds=20) for u, _ in task][:5]
    for algorithm in ("case-1b", "case-4"):
        ref = run_task(Setup(algorithm, sample=0.2, engine="reference"), 3, units)
        fast = run_task(Setup(algorithm, sample=0.2, engine="compiled"), 3, units)
        assert ref == fast and ref["checked"] > 0


def test_worst_case_runs_them_compiled(capsys):
    assert all(engine.supports(a, None, ("lifo", "fifo", "shortest")) for a in FOOTPRINT_CASES)
    assert not engine.supports("case-1a", "directional-vertex", ("nearest", "fifo", "shortest"))
    if engine.available():
        assert choose("auto", "case-4", None, ("nearest", "fifo", "shortest")) == ("compiled", None)
    argv = ["worst-case", "--algorithm", "case-1a", "--policy", "edge=fifo", "--max-vertices", "4", "--max-degree",
            "3", "--quiet", "--json"]
    assert main([*argv, "--engine", "compiled"]) == 0
    fast = capsys.readouterr().out
    assert main([*argv, "--engine", "reference"]) == 0
    assert capsys.readouterr().out == fast


def test_the_wall_the_footprint_kernel_takes_no_world_and_reads_no_marks():
    """The compiled search sees only its robot and the robot's marks through their functions."""
    tree = ast.parse((ROOT / "reference" / "engine" / "footprints.py").read_text())
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.arg) and node.arg in {"offsets", "nbr", "back", "arrays", "world"}:
            found.append(f"argument {node.arg}")
        elif isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name) and node.value.id in {"robot",
                                                                                                          "marks"}:
            found.append(f"{node.value.id}[...]")
        elif isinstance(node, ast.ImportFrom) and node.module and "world" in node.module:
            found.append(f"import from {node.module}")
    assert found == []


def test_the_bench_times_a_footprint_search_and_checks_its_costs():
    from topomark.reference.engine.bench import bench
    report = bench(4, 3, every=2, algorithm="case-2")
    assert report["algorithm"] == "case-2" and report["costs_agree"]
    assert (report["starts"], report["reference_runs"]) == (32, 16)


@pytest.mark.parametrize("algorithm, kit", [("case-1a", (0, 9, 0)), ("case-1b", (0, 0, 10)), ("case-2", (0, 12, 0)),
                                            ("case-4", (0, 5, 0))])
def test_a_short_kit_fails_where_the_references_runs_out(monkeypatch, algorithm, kit):
    """With fewer markers than assured (the 3x3 lattice: m = 12), both stop at the same refused drop."""
    from topomark.reference.engine.compare import _Actions
    from topomark.reference.explorers.policies import Policies
    from topomark.reference.run.explore import explore
    world = lattice(3, 3)
    monkeypatch.setattr(footprint_runs, "kit_of", lambda name, arrays: kit)
    run = runs.run_logged(to_arrays(world), (0, 0), ("nearest", "fifo", "shortest"), algorithm=algorithm)
    sink = _Actions()
    out = explore(world, algorithm, Policies(), check=False, record=False, sink=sink, options={"markers": sum(kit)})
    assert (run.claimed, run.cost, run.by_purpose, run.marker_operations, run.counts["iterations"]) == (
        out.claimed, out.cost, out.by_purpose, out.marker_operations, out.iterations)
    assert run.actions.tolist() == sink.codes and run.claimed == "failed" and out.iterations < 12


def test_case_1b_with_m_markers_runs_the_extension_as_its_reference(monkeypatch):
    """§6.2.1 Case 1b: m markers suffice, the last iteration's refused drop taken as its reference takes it — a new
    leaf left unmarked, or the one edge left in U joined with no search — on every start of n <= 4, D <= 3."""
    from topomark.proofs.census_map import unit_worlds
    from topomark.reference.engine.compare import _Actions
    from topomark.reference.explorers.policies import Policies
    from topomark.reference.run.explore import explore
    from topomark.spec.world import Start
    monkeypatch.setattr(footprint_runs, "kit_of", lambda name, arrays: (0, 0, arrays.m))
    seen = set()
    worlds = [w for task in plan(4, 3, 2) for unit, _ in task for _, w, _autos in unit_worlds(unit, 3)]
    for world in [*worlds, lattice(3, 3)]:
        arrays = to_arrays(world)
        number = {v: k for k, v in enumerate(arrays.names)}
        for v, i in [(v, i) for v in world.vertices for i in range(world.degree(v))]:
            run = runs.run_logged(arrays, (number[v], i), ("nearest", "fifo", "shortest"), algorithm="case-1b")
            sink = _Actions()
            out = explore(world.with_start(Start(v, world.neighbour(v, i))), "case-1b", Policies(), check=False,
                          record=False, sink=sink, options={"markers": world.m})
            assert (run.claimed, run.cost, run.marker_operations, run.counts["loop_iterations"]) == (
                out.claimed, out.cost, out.marker_operations, out.loop_iterations) and run.actions.tolist() == sink.codes
            seen.add((out.claimed, out.loop_iterations > 0))
    assert seen == {("correct", False), ("correct", True)}  # trees end on a leaf, the others on a loop edge
