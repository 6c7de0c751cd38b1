"""The exhaustive worst case: start orbits, tallies, the brute-force second opinion, resuming, and the verdicts."""

from __future__ import annotations

import json
import random

import pytest

from topomark.proofs.census_map import plan, unit_worlds, world_at
from topomark.proofs.start_orbits import dart_image
from topomark.reference.cli.main import main
from topomark.reference.worstcase import exhaustive, resumable
from topomark.reference.worstcase.brute import brute_force, compare
from topomark.reference.worstcase.exhaustive import Setup, run_start, run_task, start_darts
from topomark.reference.worstcase.resumable import task_path, worst_case
from topomark.reference.worstcase.tally import SizeTally, merge_tallies
from topomark.spec.errors import TopomarkFault
from topomark.spec.worldfile import world_from_json


def _worlds(n_max: int, degree: int):
    for task in plan(n_max, degree, 2, task_worlds=50):
        for unit, _ in task:
            yield from unit_worlds(unit, degree)


def _orbit(world, autos, dart):
    return {dart_image(world, sigma, *dart) for sigma in autos}


def test_start_darts_are_one_per_orbit_and_cover_every_dart():
    for _, world, autos in _worlds(5, 4):  # the enumeration alone: no run
        darts = start_darts(world, autos)
        orbits = [_orbit(world, autos, d) for d in darts]
        every = {(int(v[1:]), i) for v in world.vertices for i in range(world.degree(v))}
        assert set().union(*orbits) == every
        assert sum(len(o) for o in orbits) == len(every)  # disjoint: no orbit run twice


def test_starts_in_one_orbit_cost_the_same():
    """What lets one start stand for its orbit: an automorphism renames the run, it does not change its cost."""
    rng = random.Random(3)
    worlds = [w for w in _worlds(5, 4) if len(w[2]) > 1]
    for _, world, autos in rng.sample(worlds, 12):
        for v, i in start_darts(world, autos):
            costs = {run_start(Setup("basic"), world, (f"v{u}", j)).cost for u, j in _orbit(world, autos, (v, i))}
            assert len(costs) == 1


def test_the_cycle_of_four_has_one_start():
    c4 = next(w for _, w, a in _worlds(4, 2) if w.n == 4 and w.m == 4)
    autos = next(a for _, w, a in _worlds(4, 2) if w == c4)
    assert len(autos) == 8 and start_darts(c4, autos) == [("v0", 0)]


def test_tallies_merge_in_any_order():
    setup = Setup("basic", sample=0)
    units = [u for task in plan(5, 3, 2, task_worlds=10) for u, _ in task]
    parts = [{t["n"]: SizeTally.from_json(t) for t in run_task(setup, 3, [u])["tallies"]} for u in units]
    one, two = merge_tallies(parts), merge_tallies(parts[::-1])
    assert {n: t.to_json() for n, t in one.items()} == {n: t.to_json() for n, t in two.items()}


def test_quantiles_are_read_from_the_exact_pairs():
    t = SizeTally(4)
    for k, cost in enumerate((4, 8, 12, 16)):
        t.add_run((0, k, "v0", 0), m=4, cost=cost, counted=cost, bound=None, claimed="correct")
    assert t.quantiles((0.0, 0.25, 0.5, 0.75, 1.0)) == [1.0, 1.0, 2.0, 3.0, 4.0]


@pytest.mark.parametrize("algorithm", ["basic", "enh3"])
def test_the_brute_force_agrees_with_the_exhaustive_search(algorithm, tmp_path):
    setup = Setup(algorithm, sample=0)
    found = worst_case(setup, 4, 3, tmp_path)
    compare(found["tallies"], brute_force(setup, 4, 3))


def test_the_cross_check_catches_a_skipped_orbit(tmp_path, monkeypatch):
    """Seeded fault: the exhaustive search runs only the first start of each world; the brute force sees more."""
    setup = Setup("basic", sample=0)
    monkeypatch.setattr(exhaustive, "start_darts", lambda world, autos: [("v0", 0)])
    found = worst_case(setup, 4, 3, tmp_path)
    with pytest.raises(TopomarkFault, match="disagree"):
        compare(found["tallies"], brute_force(setup, 4, 3))


def test_the_argmax_world_file_reproduces_the_maximum(tmp_path, capsys):
    assert main(["worst-case", "--max-vertices", "4", "--max-degree", "3", "--json", "--out", str(tmp_path)]) == 0
    data = json.loads(capsys.readouterr().out)
    last = data["per_n"][-1]
    assert {"n", "worlds", "runs", "max_cost", "max_cost_per_m", "max_ratio_to_bound", "argmax"} <= set(last)
    world = world_from_json(json.loads((tmp_path / "argmax-cost-n4.json").read_text()))
    assert world == world_from_json(last["argmax"])
    run = run_start(Setup("basic"), world.with_start(None), world.start_state(), check=True)
    assert run.verified and run.cost == last["max_cost"]
    assert last["max_ratio_to_bound"] <= 1 and (tmp_path / "worst-case.md").exists()


def test_a_killed_search_resumes_and_a_damaged_task_runs_again(tmp_path):
    setup = Setup("basic", sample=0)
    first = worst_case(setup, 4, 3, tmp_path, task_worlds=3)
    tasks = sorted(tmp_path.glob("task-*.json"))
    assert len(tasks) > 2
    task_path(tmp_path, 1).unlink()  # killed before it finished
    task_path(tmp_path, 2).write_text(task_path(tmp_path, 2).read_text().replace('"runs": ', '"runs": 1'))
    notes: list[str] = []
    again = worst_case(setup, 4, 3, tmp_path, progress=notes.append, task_worlds=3)
    assert any("task-2.json" in n and "checksum" in n for n in notes)
    assert {n: t.to_json() for n, t in first["tallies"].items()} == {n: t.to_json() for n, t in again["tallies"].items()}


def test_another_search_in_the_same_directory_is_refused(tmp_path, capsys):
    assert main(["worst-case", "--max-vertices", "3", "--max-degree", "2", "--shards", str(tmp_path), "--quiet"]) == 0
    assert main(["worst-case", "--max-vertices", "4", "--max-degree", "2", "--shards", str(tmp_path)]) == 2
    assert "another worst-case search" in capsys.readouterr().err


def test_a_checked_rerun_that_disagrees_is_topomarks_fault(monkeypatch, capsys):
    """Seeded fault: the checked re-run of an argmax costs one more than its unchecked run."""
    real = resumable.run_start

    def skewed(setup, world, dart, check=False):
        out = real(setup, world, dart, check)
        if check:
            out.cost += 1
        return out

    monkeypatch.setattr(resumable, "run_start", skewed)
    assert main(["worst-case", "--max-vertices", "3", "--max-degree", "2", "--quiet"]) == 3
    assert "disagree" in capsys.readouterr().err


def test_a_sampled_run_whose_map_is_wrong_is_a_negative_verdict(monkeypatch, capsys):
    """Seeded fault: the sampled checked re-run reports a wrong map; the search says so and exits 1."""
    real = exhaustive.run_start

    def wrong(setup, world, dart, check=False):
        out = real(setup, world, dart, check)
        if check:
            out.verified, out.outcome = False, "wrong-map"
        return out

    monkeypatch.setattr(exhaustive, "run_start", wrong)
    assert main(["worst-case", "--max-vertices", "3", "--max-degree", "2", "--sample", "1", "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["problem_count"] >= 1 and data["problems"][0]["kind"] == "violation"


def test_an_algorithm_that_fails_by_design_exits_1(capsys):
    assert main(["worst-case", "--algorithm", "case-0", "--max-vertices", "4", "--max-degree", "3", "--quiet"]) == 1
    assert "did not map their world: 16 (failed)" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["--max-vertices", "9"], "--max-vertices must be between 2 and 8"),
    (["--max-vertices", "6", "--cross-check"], "n <= 5"),
    (["--max-vertices", "4", "--algorithm", "nope"], "nope"),
    (["--max-vertices", "4", "--sample", "2"], "--sample"),
    ([], "--max-vertices is required"),
])
def test_bad_input_is_one_message(argv, message, capsys):
    assert main(["worst-case", *argv]) == 2
    assert message in capsys.readouterr().err


def test_a_lighthouse_start_it_cannot_use_is_refused_not_run(capsys):
    assert main(["worst-case", "--lighthouse", "three-undirected-edge", "--max-vertices", "3", "--max-degree", "2",
                 "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["refused_starts"] == 2 and data["per_n"][0]["runs"] == 0  # n = 2: both ends have degree 1


def test_argmax_witness_names_a_census_world():
    assert world_at(4, 3, 5, 0).m == 6  # K4, the argmax family of small worlds


def test_every_kept_worst_world_costs_what_its_index_says():
    from topomark.reference.worlds.worst_cases import WORST_CASES, worst_case_world
    from topomark.reference.run.explore import explore
    assert WORST_CASES
    for name, entry in WORST_CASES.items():
        if not entry.get("stress", True):
            continue  # too large to run checked in the fast suite: the slow test below runs it
        world = worst_case_world(name)
        assert (world.n, world.m) == (entry["n"], entry["m"])
        assert max(world.degree(v) for v in world.vertices) <= entry["max_degree"]
        run = explore(world, entry["algorithm"])
        assert run.verified and run.cost == entry["cost"], name


@pytest.mark.slow
def test_every_large_kept_worst_world_costs_what_its_index_says_and_is_no_stress_case():
    from topomark.reference.worlds.worst_cases import WORST_CASES, worst_case_world, worst_case_worlds
    from topomark.reference.run.explore import explore
    from topomark.reference.engine import available
    from topomark.reference.algorithms.registry import algorithm_spec
    from topomark.reference.worstcase.search import unchecked_run
    stress = {name for name, _, _ in worst_case_worlds()}
    large = [name for name, entry in WORST_CASES.items() if not entry.get("stress", True)]
    assert large and not stress & {f"worst-{name}" for name in large}
    assert all(not e.get("stress", True) for e in WORST_CASES.values() if e["n"] >= 30)  # too large for a suite
    for name in large:
        world, entry = worst_case_world(name), WORST_CASES[name]
        assert (world.n, world.m) == (entry["n"], entry["m"])
        if entry["n"] <= 50 or not available():  # the reference, checked; past n = 50 it takes minutes
            run = explore(world, entry["algorithm"])
            assert run.verified and run.cost == entry["cost"], name
        else:  # the compiled engine, which agrees with the reference exactly (tests/test_engine.py)
            claimed, cost, _ = unchecked_run(world, algorithm_spec(entry["algorithm"]), True)
            assert claimed == "correct" and cost == entry["cost"], name


def test_worst_worlds_are_stress_cases_of_the_conformance_suites():
    from topomark.reference.oracle.conformance.cases import algorithm_cases, default_cases
    from topomark.reference.algorithms.registry import algorithm_spec
    names = {name for name, _, _ in default_cases()}
    assert "worst-basic-n5-d4" in names
    assert any(c[0].startswith("worst-") for c in algorithm_cases(algorithm_spec("basic")))


def test_worst_worlds_are_a_generator():
    from topomark.reference.worlds.generators import generate
    assert generate("worst-case", case="basic-n5-d4").start is not None
    with pytest.raises(Exception, match="unknown worst-case world"):
        generate("worst-case", case="nope")


def test_the_summary_says_what_is_proved_and_describes_the_worst_worlds(tmp_path, capsys):
    out = tmp_path / "basic"
    assert main(["worst-case", "--max-vertices", "4", "--max-degree", "3", "--quiet", "--out", str(out)]) == 0
    capsys.readouterr()
    assert main(["worst-case", "--summarise", str(out)]) == 0
    text = capsys.readouterr().out
    assert "§7.2" in text and "## Proved" in text
    row = next(line for line in text.splitlines() if line.startswith("| basic | 3 | 4 |"))
    assert "hypotheses rejected" in row and "diam" in row
    assert "the largest cost / exact bound" in text and "the bound holds with room to spare" in text
    # K4 costs the most (17) at a ratio of its own; the largest ratio is another world's (m = 3), in its own column
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert cells[5:7] == ["17", "0.1197"] and cells[7].startswith("m=6, diam 1") and cells[8] == "0.2273 (m=3)"
    # diameter-1 worlds are left out of the eccentricity count: K4 is the only max-cost world here
    assert "1 distinct worlds with their start" in text and "Of the 0 of diameter ≥ 2" in text
    assert main(["worst-case", "--summarise", str(tmp_path / "missing")]) == 2


def test_the_search_reports_the_best_world_beside_random_and_repeats_with_its_seed(tmp_path, capsys):
    argv = ["worst-case", "--search", "--vertices", "8", "9", "10", "--evaluations", "40", "--max-degree", "3",
            "--json"]
    assert main([*argv, "-o", str(tmp_path)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [r["n"] for r in data["per_n"]] == [8, 9, 10] and data["fit"]["rows"] == 3
    best = data["per_n"][0]["search"]["best"]
    world = world_from_json(json.loads((tmp_path / "search-best-n8.json").read_text()))
    assert world.n == 8 and max(world.degree(v) for v in world.vertices) <= 3
    from topomark.reference.run.explore import explore
    assert explore(world, "basic").cost == best["cost"]
    assert data["per_n"][0]["random"]["best"]["cost"] > 0
    assert main(argv) == 0
    assert json.loads(capsys.readouterr().out)["per_n"] == data["per_n"]


@pytest.mark.parametrize("argv, message", [
    (["--evaluations", "0"], "--evaluations"),
    (["--algorithm", "enh4", "--objective", "ratio"], "ratio"),
    (["--vertices", "2"], "n"),
])
def test_bad_search_input_is_one_message(argv, message, capsys):
    assert main(["worst-case", "--search", "--quiet", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err
