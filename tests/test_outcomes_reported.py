"""A run's outcome decides its exit code, whatever is asked of the output: a failed search for a
lighthouse (§5.1) exits 1 with outcome ``failed`` under ``explore`` and ``drive``, writes no map and
says so; an explorer never raises the checker's own exception."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest

from topomark.reference.cli.main import main

FAILS = ("explore", "cycle:n=6", "--lighthouse", "undirected-vertex", "--seed", "2", "--quiet")
"""The smallest regular world where §5.1's search finds nothing: every vertex of a 6-cycle looks the same."""


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("no_check", [False, True])
@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("with_map", [False, True])
def test_failed_search_exits_1_with_or_without_map(capsys, tmp_path, no_check, as_json, with_map):
    path = tmp_path / "m.json"
    argv = [*FAILS, *(["--no-check"] if no_check else []), *(["--json"] if as_json else []),
            *(["--map", str(path)] if with_map else [])]
    code, out, err = run(capsys, *argv)
    assert code == 1, (out, err)
    assert "no vertices" not in out + err and "error" not in err
    assert not path.exists()
    if as_json:
        data = json.loads(out)
        assert data["outcome"] == "failed" and data["claimed"] == "failed"
        if with_map:
            assert data["map_written"] is False and "stopped without a map" in data["map_not_written"]
        else:
            assert "map_written" not in data
    else:
        assert "outcome: failed" in out
        assert ("no map written to" in out) == with_map


def test_a_correct_run_still_writes_its_map(capsys, tmp_path):
    path = tmp_path / "m.json"
    code, out, _ = run(capsys, "explore", "cycle:n=6", "--quiet", "--json", "--map", str(path))
    assert code == 0 and path.exists() and json.loads(out)["map_written"] is True


ROOT = Path(__file__).resolve().parent.parent
PROVIDER = str(ROOT / "reference" / "oracle" / "examples" / "provider.py")


@pytest.mark.parametrize("name", ["undirected-vertex", "undirected-edge", "local-pair", "local-degree-list"])
def test_drive_reports_a_failed_search_as_failed(tmp_path, capsys, name):
    """A 6-cycle gives §5.1's, §5.2.1's and §6.1's searches nothing to find: FAIL [failed], exit 1, no map."""
    import sys
    from topomark.reference.explorers.lighthouses import LIGHTHOUSES
    from topomark.reference.worlds import generators as g
    from topomark.spec.worldfile import dumps_world
    (tmp_path / "w.json").write_text(dumps_world(g.cycle(6)))
    kit = json.dumps(LIGHTHOUSES[name].kit.to_json())
    provider = [sys.executable, PROVIDER, str(tmp_path / "w.json"), "--protocol", "2", "--kit", kit]
    base = ["drive", "--check", str(tmp_path / "w.json"), "--lighthouse", name, "--map", str(tmp_path / "m.json")]
    assert main([*base, "--", *provider]) == 1
    out, err = capsys.readouterr()
    assert out.startswith("FAIL [failed] the algorithm stopped:") and "internal fault" not in err
    assert main([*base, "--json", "--", *provider]) == 1
    data = json.loads(capsys.readouterr().out)
    assert (data["verdict"], data["reason"], data["n"]) == ("fail", "failed", None)
    assert not (tmp_path / "m.json").exists()


EXPLORERS = ROOT / "reference" / "explorers"


def _names(tree: ast.AST) -> set[str]:
    """Every name a module imports, raises or mentions."""
    found = {a.asname or a.name for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) for a in n.names}
    return found | {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)} | {
        n.attr for n in ast.walk(tree) if isinstance(n, ast.Attribute)}


@pytest.mark.parametrize("path", sorted(EXPLORERS.glob("*.py")), ids=lambda p: p.name)
def test_no_explorer_raises_the_checkers_exception(path):
    """An explorer reports its own inconsistency as a failure the thesis predicts (AlgorithmFailed) or a bug
    (ExplorerFault); the checker's CheckFailure, and require, which raises it, are the checker's alone."""
    names = _names(ast.parse(path.read_text(encoding="utf-8")))
    assert not names & {"CheckFailure", "Violation", "require"}, path.name


def test_an_inconsistency_is_a_failure_or_a_fault_by_the_lighthouse():
    """§5.2.1 predicts an inconsistency with a lighthouse that is not explicit; Lemma 1 rules it out otherwise."""
    from topomark.reference.explorers.inconsistency import inconsistent
    from topomark.reference.explorers.lighthouses import LIGHTHOUSES
    from topomark.spec.errors import AlgorithmFailed, ExplorerFault
    assert isinstance(inconsistent(LIGHTHOUSES["local-pair"], "x", "Lemma 1"), AlgorithmFailed)
    assert isinstance(inconsistent(LIGHTHOUSES["directional-vertex"], "x", "Lemma 1"), ExplorerFault)
    assert isinstance(inconsistent(None, "x", "Lemma 1"), ExplorerFault)


@pytest.mark.parametrize("light, code, words", [
    ("directional-vertex", 3, "Lemma 1"),  # explicit place and back-link: e' outside U is a bug
    ("local-pair", 1, "§5.2.1"),  # not explicit: the thesis predicts a wrong loop closing, the failed outcome
])
def test_e_prime_outside_u_is_a_bug_or_a_failure_by_the_lighthouse(capsys, monkeypatch, light, code, words):
    from types import SimpleNamespace
    from topomark.reference.explorers.algorithm31 import LighthouseExplorer

    def broken(self):
        raise self.not_in_u(SimpleNamespace(number=1), (0, 9))

    monkeypatch.setattr(LighthouseExplorer, "step", broken)
    got, out, err = run(capsys, "explore", "lattice-hole:rows=4,cols=5,seed=3", "--lighthouse", light, "--quiet")
    assert got == code and words in out + err, (out, err)
    assert ("internal fault" in err) == (code == 3) and "check failed" not in out + err


OUTGROWN = {"0": ("2", "5", "4", "3"), "1": ("2", "3"), "2": ("0", "1", "3"), "3": ("1", "0", "4", "2"),
            "4": ("3", "0", "5"), "5": ("4", "0")}
"""The first world of networkx's atlas (6 vertices, 9 edges, planar) where §5.2.1's scheme A, from vertex 0 with
walk seed 1, takes every new place for a new one: its map outgrows the world."""


@pytest.mark.parametrize("no_check", [False, True])
def test_a_map_that_outgrows_the_world_ends_at_the_limit_checked_or_not(capsys, tmp_path, no_check):
    """§5.2.1 "never terminates (when every newly visited place is always validated as a new place)": once the
    believed map has more places than the world it can never become the world; the run ends ``limit``, exit 1,
    the same checked or not, the first wrong join named when checked."""
    from topomark.spec.world import Start, World
    from topomark.spec.worldfile import dumps_world
    (tmp_path / "w.json").write_text(dumps_world(World(OUTGROWN, (), Start("0", "2"))))
    argv = ["explore", str(tmp_path / "w.json"), "--lighthouse", "local-pair", "--seed", "1", "--walk-limit", "50",
            "--json", *(["--no-check"] if no_check else [])]
    assert main(argv) == 1
    data = json.loads(capsys.readouterr().out)
    assert (data["outcome"], data["claimed"]) == ("limit", "limit") and "outgrown the world" in data["reason"]
    assert ("the map had gone wrong before it: I-1 violated" in data["reason"]) != no_check


def _stop_at_second_iteration(monkeypatch):
    from topomark.reference.run.checker import Checker
    from topomark.spec.errors import CheckFailure, Violation
    real = Checker.after_iteration

    def after_iteration(self, explorer, it):
        if it.number == 2:
            raise CheckFailure(Violation("I-1", "seeded", "a", "b", "iteration 2"))
        real(self, explorer, it)
    monkeypatch.setattr(Checker, "after_iteration", after_iteration)


def test_the_checker_stops_a_run_under_an_explicit_lighthouse_and_says_it_claimed_nothing(capsys, tmp_path,
                                                                                         monkeypatch):
    """Lemma 1 rules a wrong join out under an explicit lighthouse: the first violation stops the run,
    ``wrong-map``, exit 1; the algorithm had not finished, so it claimed nothing (``unfinished``), and ``--map``
    writes nothing, saying why."""
    _stop_at_second_iteration(monkeypatch)
    path = tmp_path / "m.json"
    code, out, _ = run(capsys, "explore", "cycle:n=6", "--json", "--map", str(path))
    data = json.loads(out)
    assert code == 1 and (data["outcome"], data["claimed"]) == ("wrong-map", "unfinished")
    assert data["map_written"] is False and "first violation" in data["map_not_written"] and not path.exists()


def test_the_checker_lets_a_marker_less_run_finish_and_names_its_first_violation(capsys, tmp_path, monkeypatch):
    """Under §5.2.1's lighthouses the thesis predicts wrong joins: the first violation is kept, the run
    goes on to the algorithm's own end, and the outcome names that violation; the claimed map is written."""
    _stop_at_second_iteration(monkeypatch)
    path = tmp_path / "m.json"
    code, out, _ = run(capsys, "explore", "lattice-hole:rows=4,cols=4,seed=0", "--lighthouse", "local-degree-list",
                       "--json", "--map", str(path))
    data = json.loads(out)
    assert code == 1 and (data["outcome"], data["claimed"]) == ("wrong-map", "correct")
    assert data["violation"]["where"] == "seeded" and data["map_written"] is True and path.exists()


def test_a_degenerate_join_is_a_bug_under_an_explicit_lighthouse(capsys, monkeypatch):
    """A join that would make a self-loop (no world has one, §3.1.1) under the directional lighthouse: Lemma 1
    rules it out, so it is topomark's fault, exit 3 — never the checker's verdict."""
    from types import SimpleNamespace
    from topomark.reference.explorers.algorithm31 import LighthouseExplorer

    def broken(self):
        raise self.degenerate(SimpleNamespace(number=1, edge=(0, 1)), (0, 2))

    monkeypatch.setattr(LighthouseExplorer, "step", broken)
    code, out, err = run(capsys, "explore", "cycle:n=6", "--quiet")
    assert code == 3 and "self-loop" in err and "Lemma 1" in err and "check failed" not in out + err
