"""The engine's lighthouses and Chapter 4 compositions agree with the reference; seeded faults are caught."""

from __future__ import annotations

import numpy as np
import pytest

from topomark.proofs.census_map import plan
from topomark.proofs.world_arrays import to_arrays
from topomark.reference import engine
from topomark.reference.engine import compare, enhanced, runs, signature
from topomark.reference.engine.compare import Case, _unit_cases, compare_case, reference_run
from topomark.reference.engine.equality import main as equality_main
from topomark.reference.engine.lighthouses import script
from topomark.reference.worlds.generators import lattice

COMBOS = (("nearest", "fifo", "shortest"), ("fifo", "lifo", "dfs"), ("lifo", "shortest", "shortest"))
"""Three policy combinations naming every built-in policy once at least: the fast slices' (the command runs all
18)."""
VARIANTS = [("basic", "directional-edge"), ("basic", "vertex-and-edge"), ("basic", "three-undirected-edge"),
            ("basic", "thread"), ("enh1", None), ("enh2", None), ("enh3", None), ("enh1", "vertex-and-edge"),
            ("enh2", "three-undirected-edge"), ("enh3", "directional-edge"), ("enh3", "thread"), ("enh3+4", "thread"),
            ("enh5-d2", "three-undirected-edge")]


def _slice(n: int, degree: int, algorithm: str, lighthouse: str | None) -> tuple[int, list]:
    count, bad = 0, []
    for task in plan(n, degree, 2):
        for unit, _ in task:
            for case in _unit_cases([unit], degree):
                k, found = compare_case(case, COMBOS, lighthouse, algorithm)
                count, bad = count + k, bad + found
    return count, bad


@pytest.mark.parametrize("algorithm, lighthouse", VARIANTS)
def test_the_fixed_slice_agrees(algorithm, lighthouse):
    """Every census world with n <= 4, degree <= 3 from every start orbit (36 of them; 31 of degree >= 2 for the
    lighthouse that needs a second exit), three policy combinations: claim, cost by purpose, marker operations,
    counts and trace digest."""
    count, bad = _slice(4, 3, algorithm, lighthouse)
    assert not bad, [str(d) for d in bad[:2]]
    assert count == 3 * (31 if lighthouse == "three-undirected-edge" else 36)


def test_a_lattice_run_by_each_composition_agrees_field_by_field_and_saves_what_the_thesis_says():
    """On a 3x3 lattice the compositions save validation moves over Algorithm 3.1 (§4.1), identically in both."""
    world, costs = lattice(3, 3), {}
    for algorithm in ("basic", "enh1", "enh2", "enh3"):
        want, codes = reference_run(world, ("0,0", 0), ("nearest", "fifo", "shortest"), None, algorithm)
        run = runs.run_logged(to_arrays(world), (0, 0), ("nearest", "fifo", "shortest"), None, algorithm)
        assert run.actions.tolist() == codes and run.digest() == want["digest"]
        assert (run.claimed, run.cost, run.by_purpose) == (want["claimed"], want["cost"], want["by_purpose"])
        assert run.counts == {k: want[k] for k in run.counts}
        costs[algorithm] = run.cost
    assert costs == {"basic": 44, "enh1": 38, "enh2": 38, "enh3": 36}


def test_each_lighthouse_logs_its_own_operations_and_counts_them():
    world = lattice(2, 3)
    for name, ops in (("directional-edge", {"drop": 1}), ("vertex-and-edge", {"drop": 2}),
                      ("three-undirected-edge", {"drop": 2}), ("thread", {"leave": 1, "tie": 1})):
        run = runs.run_logged(to_arrays(world), (0, 0), ("nearest", "fifo", "shortest"), name)
        want, codes = reference_run(world, ("0,0", 0), ("nearest", "fifo", "shortest"), name)
        assert run.marker_operations == want["marker_operations"] == ops
        assert run.actions.tolist()[:len(ops)] == codes[:len(ops)] and codes[0] < 0


def test_signature_codes_are_equal_exactly_when_the_signatures_are():
    """Two edge items in either order, every rotation: a code is the signature read from one entry."""
    d, marks = 4, []
    for a, b in ((0, 1), (1, 0)):
        code = signature.add_edge_mark(signature.add_edge_mark(0, a, signature.edge_mark(1, 0)), b,
                                       signature.edge_mark(2, 0))
        marks.append(code)
    assert marks[0] != marks[1]  # E-0,E2-1 and E2-0,E-1 differ
    rotations = [signature.rotate(marks[0], d, e) for e in range(d)]
    assert len(set(rotations)) == d and signature.rotate(rotations[1], d, 3) == marks[0]
    assert signature.decode_edges(signature.rotate(marks[0], d, 1)) == (0, 8, 3, 4)  # E2-0,E-3


def test_supports_the_variants_and_refuses_the_rest():
    policies = ("nearest", "fifo", "shortest")
    for algorithm, lighthouse in VARIANTS:
        assert engine.supports(algorithm, lighthouse, policies)
    assert not engine.supports("enh4-listing", None, policies) and not engine.supports(
        "basic", "three-undirected-vertex", policies)
    with pytest.raises(ValueError, match="does not run the undirected-vertex lighthouse"):
        script("undirected-vertex")


def _three_edge_markers_on_one_exit(name):
    """Seeded fault: the second edge drop of three-undirected-edge puts one marker down, not two."""
    rows = script(name)
    if name == "three-undirected-edge":
        rows[1, 2] = 1
    return rows


@pytest.mark.parametrize("algorithm, lighthouse, patch, n", [
    ("basic", "three-undirected-edge", "script", 3),
    ("enh1", "directional-vertex", "stage1", 4),
    ("enh3", "directional-vertex", "records", 4),
])
def test_seeded_fault_a_wrong_kernel_step_is_exit_3_naming_world_start_and_first_differing_action(
        algorithm, lighthouse, patch, n, monkeypatch, capsys):
    """One seeded fault per new kernel family: the lighthouse's script (one marker where it drops two, so v0's
    signatures no longer give the back-link), Enhancement-1 without its stage 1, Enhancement-3 without T."""
    if patch == "script":
        monkeypatch.setattr(runs, "script", _three_edge_markers_on_one_exit)
    elif patch == "stage1":
        monkeypatch.setitem(enhanced.TECHNIQUES, "enh1", enhanced.STAGE2)
    else:
        monkeypatch.setitem(enhanced.TECHNIQUES, "enh3", enhanced.STAGE2 | enhanced.TRACE_S)
    assert equality_main(["--algorithm", algorithm, "--lighthouse", lighthouse, "--max-vertices", str(n),
                          "--max-degree", str(n - 1), "--quiet"]) == 3
    err = capsys.readouterr().err
    assert "disagree" in err and "first differing action #" in err and "world census n=" in err
    assert "start " in err and "facing exit" in err


def test_the_equality_command_names_the_variant_and_refuses_what_the_engine_does_not_run(capsys):
    assert equality_main(["--algorithm", "enh2", "--lighthouse", "thread", "--max-vertices", "3",
                          "--max-degree", "2"]) == 0
    assert capsys.readouterr().out.startswith("enh2 with thread: ")
    with pytest.raises(SystemExit) as exit_:
        equality_main(["--algorithm", "enh4-listing"])
    assert exit_.value.code == 2


@pytest.mark.slow
def test_the_exhaustive_search_runs_a_lighthouse_and_a_composition_compiled_as_the_reference_does():
    from topomark.reference.worstcase.exhaustive import Setup, run_task
    units = [u for task in plan(5, 4, 4, task_worlds=20) for u, _ in task if u[0] == 5][8:12]
    got = {}
    for algorithm, lighthouse in (("basic", "thread"), ("enh3", "thread")):
        ref = run_task(Setup(algorithm, lighthouse=lighthouse, sample=0.05, engine="reference"), 4, units)
        fast = run_task(Setup(algorithm, lighthouse=lighthouse, sample=0.05, engine="compiled"), 4, units)
        assert ref == fast and ref["checked"] > 0 and ref["problem_count"] == 0
        got[algorithm] = fast["tallies"]
    assert got["basic"] != got["enh3"]  # the composition ran, not Algorithm 3.1


def test_a_case_from_a_world_the_census_does_not_enumerate_agrees():
    world = lattice(3, 4)
    case = Case("lattice 3x4", "random", world, [("0,0", 0), ("1,1", 2)])
    count, bad = compare_case(case, COMBOS[:1], "vertex-and-edge", "enh3")
    assert count == 2 and not bad, [str(d) for d in bad]
    assert np.array_equal(script(None), script("directional-vertex"))


KEPT_TRACE_WORLDS = [("small-world:n=16,k=4,p=0.1,seed=529202", "8", 3, ("nearest", "shortest", "shortest")),
                     ("small-world:n=11,k=4,p=0.1,seed=883383", "1", 0, ("lifo", "shortest", "shortest")),
                     ("small-world:n=18,k=4,p=0.1,seed=547136", "6", 2, ("lifo", "fifo", "shortest"))]
"""Runs where Enhancement-3's traces start from states kept at an earlier check while records of T are reached
further on: a trace cache kept past the path it followed made each of them disagree."""


def test_traces_resumed_from_kept_states_agree_with_the_reference():
    from topomark.reference.worlds.argument import resolve_world
    for text, vertex, exit_, policies in KEPT_TRACE_WORLDS:
        world = resolve_world(text)
        start = next((v, exit_) for v in world.vertices if str(v) == vertex)
        count, bad = compare_case(Case(text, "random", world, [start]), (policies,), None, "enh3")
        assert count == 1 and not bad, [str(d) for d in bad]
