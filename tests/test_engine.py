"""The compiled engine agrees with the reference run for run (thesis §3.3), and falls back without numba."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from topomark.proofs.census_map import plan
from topomark.proofs.world_arrays import to_arrays
from topomark.reference import engine
from topomark.reference.cli.main import main
from topomark.reference.engine import choose, compare, digest as digests, runs
from topomark.reference.engine.digest import digest, event_code, move_code, op_code
from topomark.reference.engine.compare import reference_run
from topomark.reference.engine.equality import main as equality_main
from topomark.reference.worlds.generators import cycle, lattice
from topomark.reference.worstcase import exhaustive
from topomark.reference.worstcase.exhaustive import Setup, run_task
from topomark.spec.errors import InvalidInput, TopomarkFault

ROOT = Path(__file__).resolve().parents[1]
NOTICE = "topomark: numba is not installed; the engine runs through the reference (slower)"


def test_the_digest_is_fnv_over_the_codes_and_reads_the_trace_records():
    assert digest([]) == 0xCBF29CE484222325
    assert digest([5]) == ((0xCBF29CE484222325 ^ 5) * 0x100000001B3) % 2 ** 64
    assert digest([-1]) != digest([1]) and digest([1, 2]) != digest([2, 1])
    assert event_code({"event": "move", "motion": 2, "purpose": "retrace"}) == move_code(2, 3)
    assert event_code({"event": "drop", "direction": 0}) == op_code("drop", "vertex", 1, None, 0)
    assert event_code({"event": "op", "op": "drop", "kind": "edge", "count": 2, "exit": 1}) < 0
    assert event_code({"event": "end"}) is None
    codes = {op_code(op, kind, c, x, d) for op in ("drop", "pick_up") for kind in ("vertex", "edge") for c in (1, 2)
             for x in (None, 0, 1) for d in (None, "H", "T", 0, 1)}
    assert len(codes) == 2 * 2 * 2 * 3 * 5  # every operation its own code
    assert digests.describe(move_code(1, 2)) == "move 1 (validation)"


def test_one_run_agrees_with_the_reference_field_by_field():
    world = lattice(3, 3)
    want, codes = reference_run(world, ("0,0", 0), ("nearest", "shortest", "dfs"))
    run = runs.run_logged(to_arrays(world), (0, 0), ("nearest", "shortest", "dfs"))
    assert run.actions.tolist() == codes and run.digest() == want["digest"]
    assert (run.claimed, run.cost, run.by_purpose, run.marker_operations) == (
        want["claimed"], want["cost"], want["by_purpose"], want["marker_operations"])
    assert run.counts == {k: want[k] for k in run.counts} and want["by_purpose"]["retrace"] == 12
    assert (want["hypotheses"], want["hypotheses_rejected"], want["hypotheses_confirmed"]) == (12, 7, 3)


def test_every_start_and_policy_agrees_on_the_small_census_and_a_random_world():
    """The fixed fast slice: n <= 4, degree <= 3, all 18 policy combinations; one random world of n <= 30."""
    count = 0
    for task in plan(4, 3, 2):
        for unit, _ in task:
            result = compare.run_cases(("census", [unit], 3))
            assert result["disagreement_count"] == 0, result["disagreement_text"]
            count += sum(result["counts"].values())
    assert count == 18 * (1 + 3 + 32)
    text, starts = compare.random_cases(1, 30, seed=5, starts=1)[0]
    result = compare.run_cases(("random", text, starts))
    assert result["disagreement_count"] == 0 and result["counts"] == {"random": 18}


@pytest.mark.slow
def test_the_bigger_slice_agrees():
    """Every census world with n <= 5, degree <= 3 and eight seeded random worlds up to 60 vertices (degree 4 among
    them); the command runs n <= 6, degree <= 4."""
    assert equality_main(["--max-vertices", "5", "--max-degree", "3", "--random", "8", "--random-max-vertices", "60",
                          "--quiet"]) == 0


def test_seeded_fault_a_swapped_tie_break_is_caught_with_the_first_differing_action(monkeypatch, capsys):
    """Seeded fault: the engine orders hypotheses lifo when asked fifo (and fifo when asked lifo)."""
    real = runs.policy_codes

    def swapped(policies):
        edge, hypothesis, path = real(policies)
        return edge, {0: 1, 1: 0}.get(hypothesis, hypothesis), path

    monkeypatch.setattr(runs, "policy_codes", swapped)
    assert equality_main(["--max-vertices", "4", "--max-degree", "3", "--quiet"]) == 3
    err = capsys.readouterr().err
    assert "disagree" in err and "first differing action #" in err and "world census n=4" in err


def test_the_wall_the_explorer_kernel_takes_no_world():
    """The compiled explorer sees only its robot: it never indexes it, takes no world arrays, imports no world."""
    import ast
    for name in ("algorithm31.py", "mapstate.py", "signature.py", "lighthouses.py", "trie.py", "records.py",
                 "expansion.py", "enhanced.py"):
        tree = ast.parse((ROOT / "reference" / "engine" / name).read_text())
        assert not _world_reads(tree), f"{name}: {_world_reads(tree)}"
    sneaky = ast.parse("def f(robot, offsets):\n    return robot[1][offsets[0]]\n")
    assert _world_reads(sneaky) == ["argument offsets", "robot[...]"]


def _world_reads(tree) -> list[str]:
    import ast
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.arg) and node.arg in {"offsets", "nbr", "back", "arrays", "world"}:
            found.append(f"argument {node.arg}")
        elif isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name) and node.value.id == "robot":
            found.append("robot[...]")
        elif isinstance(node, ast.ImportFrom) and node.module and (
                "world" in node.module or node.module.endswith("engine.robot") and {a.name for a in node.names}
                - {"move", "sense", "drop_vertex", "operate", "fault", "PURPOSE_NEW", "PURPOSE_RETRACE",
                   "PURPOSE_TRAVEL", "PURPOSE_VALIDATION", "OP_MOVE", "OP_VERTEX", "OP_EDGE", "OP_TIE", "OP_LEAVE"}):
            found.append(f"import from {node.module}")
    return found


def test_the_exhaustive_search_gives_the_same_record_with_either_engine():
    units = [u for task in plan(5, 3, 4, task_worlds=20) for u, _ in task][:6]
    ref = run_task(Setup("basic", sample=0.05, engine="reference"), 3, units)
    fast = run_task(Setup("basic", sample=0.05, engine="compiled"), 3, units)
    assert ref == fast and ref["checked"] > 0
    assert Setup("basic", engine="compiled").to_json() == Setup("basic").to_json()  # the manifest: engine-free


def test_seeded_fault_an_engine_fault_code_is_exit_3_when_the_reference_runs_clean(monkeypatch):
    real = exhaustive.run_starts

    def failing(arrays, starts, policies, lighthouse=None, algorithm="basic"):
        out = real(arrays, starts, policies, lighthouse, algorithm)
        out[0].code = 1
        return out

    monkeypatch.setattr(exhaustive, "run_starts", failing)
    with pytest.raises(TopomarkFault, match="the engine and its reference disagree"):
        run_task(Setup("basic", engine="compiled"), 2, [(3, 0, 0, 1)])


def test_choose_the_engine():
    basic = ("basic", None, ("nearest", "fifo", "shortest"))
    assert choose("reference", *basic) == ("reference", None)
    assert choose("auto", "enh4-listing", None, basic[2]) == ("reference", None)
    assert choose("auto", "basic", "undirected-vertex", basic[2]) == ("reference", None)
    with pytest.raises(InvalidInput, match=r"--engine compiled runs basic, enh1, enh2, enh3, enh4, enh5-d1, enh5-d2, "
                                           r"enh3\+4, enh3\+5 with the"):
        choose("compiled", "enh4-listing", None, basic[2])
    assert choose("auto", *basic) == (("compiled", None) if engine.available() else ("reference", NOTICE))


def test_without_numba_auto_falls_back_to_the_reference_with_a_notice(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "numba", None)  # import numba now raises ImportError
    assert not engine.available()
    assert choose("auto", "basic", None, ("nearest", "fifo", "shortest")) == ("reference", NOTICE)
    assert choose("compiled", "basic", None, ("nearest", "fifo", "shortest")) == ("reference", NOTICE)
    assert main(["worst-case", "--max-vertices", "3", "--max-degree", "2", "--quiet", "--json"]) == 0
    captured = capsys.readouterr()
    assert captured.err.strip().splitlines() == [NOTICE]
    monkeypatch.undo()
    assert main(["worst-case", "--max-vertices", "3", "--max-degree", "2", "--quiet", "--json", "--engine",
                 "reference"]) == 0
    assert capsys.readouterr().out == captured.out


@pytest.mark.parametrize("argv, message", [
    (["--engine", "fast"], "invalid choice"),
    (["--engine", "compiled", "--algorithm", "enh4-listing"], "--engine compiled runs basic, enh1, enh2, enh3, enh4,"),
    (["--engine", "compiled", "--search", "--algorithm", "enh5-d2-listing", "--evaluations", "1"],
     "--engine compiled runs basic, enh1, enh2, enh3, enh4,"),  # the search takes --engine too, and refuses it alike
])
def test_bad_engine_options_are_exit_2(argv, message, capsys):
    size = [] if "--search" in argv else ["--max-vertices", "3", "--max-degree", "2"]
    assert main(["worst-case", *size, "--quiet", *argv]) == 2
    assert message in capsys.readouterr().err


@pytest.mark.slow
def test_the_package_imports_and_its_kernels_run_uncompiled_without_numba():
    """Without numba the kernels are plain Python: the engine module imports, and the uncompiled run is the run."""
    code = ("import sys; sys.modules['numba'] = None\n"
            "from topomark.reference.engine.runs import run_logged\n"
            "from topomark.proofs.world_arrays import to_arrays\n"
            "from topomark.reference.worlds.generators import lattice\n"
            "r = run_logged(to_arrays(lattice(2, 3)), (0, 1), ('nearest', 'shortest', 'dfs'))\n"
            "print(r.cost, r.digest())\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True).stdout
    run = runs.run_logged(to_arrays(lattice(2, 3)), (0, 1), ("nearest", "shortest", "dfs"))
    assert out.split() == [str(run.cost), str(run.digest())]


def test_equality_command_reports_counts_as_json(capsys):
    assert equality_main(["--max-vertices", "3", "--max-degree", "2", "--json", "--algorithm", "basic"]) == 0
    captured = capsys.readouterr()
    report = json.loads(captured.out)
    assert report["compared"] == 18 * 4 and report["by_group"] == {"2": 18, "3": 54}
    assert "run pairs compared, 0 disagreeing" in captured.err  # progress on stderr beside the JSON
    assert equality_main(["--max-vertices", "3", "--max-degree", "2", "--json", "--quiet"]) == 0
    assert capsys.readouterr().err == ""
    assert equality_main(["--max-vertices", "9"]) == 2


def test_a_cycle_costs_m():
    run = runs.run_starts(to_arrays(cycle(5)), [(0, 0), (2, 1)], ("lifo", "fifo", "shortest"))
    assert [(r.claimed, r.cost) for r in run] == [("correct", 5), ("correct", 5)]


def test_a_changed_kernel_source_drops_the_kept_machine_code(tmp_path):
    """numba checks a cached kernel against its own file only; the engine's digest of all its sources does more."""
    from topomark.reference.engine.compiled import KERNEL_SOURCES, fresh_cache
    for name in KERNEL_SOURCES:
        (tmp_path / name).write_text(f"# {name}\n")
    assert fresh_cache(tmp_path)
    kept = tmp_path / "__pycache__" / "runs._run_all-1.py311.nbi"
    kept.write_text("old machine code")
    assert not fresh_cache(tmp_path) and kept.exists()  # nothing changed: the cache stays
    (tmp_path / "algorithm31.py").write_text("# the loop, edited\n")
    assert fresh_cache(tmp_path) and not kept.exists()
