"""One rule for output paths that are already there, in every command that writes (reference/files/overwrite.py).

An existing output file or non-empty output directory is refused (exit 2, a message naming the path and
``--force``) before any work, and nothing is written; ``--force`` writes over it; an empty path is exit 2.
Directories that are inputs as well as outputs (``bench -o``, ``--shards``) are reused without ``--force``.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pytest

from topomark.reference.cli.main import build_parser, main
from topomark.reference.files.overwrite import RULE
from topomark.reference.worlds import generators as g
from topomark.spec.world import Start
from topomark.spec.worldfile import dumps_world

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "reference" / "oracle" / "examples"
SMALL = "lattice:rows=3,cols=3"
SENTINEL = "written before\n"


def _world(tmp: Path) -> str:
    path = tmp / "in" / "w.json"
    if not path.exists():
        path.write_text(dumps_world(g.lattice(3, 3).with_start(Start("1,1", "0,1"))))
    return str(path)


def _summarised_run(tmp: Path) -> str:
    run = tmp / "in" / "run"
    if not run.exists():
        assert main(["worst-case", "--max-vertices", "3", "--max-degree", "2", "--quiet", "-o", str(run)]) == 0
    return str(run)


PORT_MAPS = ROOT / "tests" / "data" / "icfpc2025"
PROBATIO, ALEPH = str(PORT_MAPS / "probatio" / "000.json"), str(PORT_MAPS / "aleph" / "000.json")


def _exchange(tmp: Path) -> str:
    """An /explore exchange on the 3-room shared map whose records pin the map down (``port solve`` exit 0)."""
    import json
    import random

    from topomark.reference.port.files import load_port_file
    from topomark.spec.port_plan import parse_plan, run_plan
    world = load_port_file(PROBATIO)[1]
    rng = random.Random(5)
    plans = ["".join(rng.choice("012345") for _ in range(18)) for _ in range(8)]
    path = tmp / "in" / "exchange.json"
    path.parent.mkdir(exist_ok=True)
    path.write_text(json.dumps({"plans": plans, "results": [list(run_plan(world, parse_plan(q))) for q in plans]}))
    return str(path)


def _trace(tmp: Path) -> str:
    """A trace of Algorithm 3.1 on :func:`_world`'s world."""
    path = tmp / "in" / "t.jsonl"
    if not path.exists():
        assert main(["explore", _world(tmp), "--quiet", "--trace", str(path)]) == 0
    return str(path)


def _suite(tmp: Path, extra: list[str]) -> str:
    """A conformance suite, exported only for a run that gets past the output check (``--force``): the others
    are refused, or told the path is empty, before the suite is read."""
    suite = tmp / "in" / "suite"
    if "--force" in extra and not suite.exists():
        assert main(["conformance", "export", str(suite), "--algorithm", "basic"]) == 0
    return str(suite)


def _client() -> list[str]:
    return ["--", sys.executable, str(EXAMPLES / "client.py")]


def _provider(tmp: Path) -> list[str]:
    return ["--", sys.executable, str(EXAMPLES / "provider.py"), _world(tmp)]


# (command, option): (kind, the file the command writes in the directory, argv(tmp, path, extra options))
# ``extra`` is [] or ["--force"]; a second output in ``out/`` shows that a refused run starts nothing.
CASES = {
    ("explore", "--trace"): ("file", None, lambda t, p, x: ["explore", SMALL, "--quiet", "--trace", p, *x]),
    ("explore", "--map"): ("file", None, lambda t, p, x: ["explore", SMALL, "--quiet", "--trace",
                                                           str(t / "out" / "t.jsonl"), "--map", p, *x]),
    ("explore", "--models"): ("dir", "model-0001.json", lambda t, p, x: [
        "explore", "cycle:n=5", "--algorithm", "model-tree", "--cue-n", "5", "--quiet", "--models", p, *x]),
    ("world", "-o"): ("file", None, lambda t, p, x: ["world", SMALL, "-o", p, *x]),
    ("world --draw", "-o"): ("file", None, lambda t, p, x: ["world", "--draw", SMALL, "-o", p + ".svg", *x]),
    ("run-external", "--map"): ("file", None, lambda t, p, x: ["run-external", _world(t), "--map", p, *x,
                                                                *_client()]),
    ("drive", "--trace"): ("file", None, lambda t, p, x: ["drive", "--check", _world(t), "--trace", p, *x,
                                                          *_provider(t)]),
    ("drive", "--map"): ("file", None, lambda t, p, x: ["drive", "--check", _world(t), "--trace",
                                                        str(t / "out" / "t.jsonl"), "--map", p, *x, *_provider(t)]),
    ("conformance export", "DIR"): ("dir", "manifest.json", lambda t, p, x: [
        "conformance", "export", p, "--algorithm", "basic", *x]),
    ("explore", "--view"): ("file", None, lambda t, p, x: ["explore", SMALL, "--quiet", "--view", p, *x]),
    ("view", "-o"): ("file", None, lambda t, p, x: ["view", _trace(t), "--world", _world(t), "-o", p, *x]),
    ("replay", "--view"): ("file", None, lambda t, p, x: ["replay", _world(t), _trace(t), "--view", p, *x]),
    ("conformance run", "--view-failures"): ("dir", "cycle-4.html", lambda t, p, x: [
        "conformance", "run", _suite(t, x), "-k", "cycle-4", "--view-failures", p, *x, "--", sys.executable,
        str(ROOT / "tests" / "clients" / "wrong_client.py"), "bad-map"]),
    ("search", "-o"): ("dir", "a.json", lambda t, p, x: [
        "search", "--marker", "none", "--max-vertices", "4", "--max-degree", "2", "-o", p, *x]),
    ("worst-case", "-o"): ("dir", "worst-case.json", lambda t, p, x: [
        "worst-case", "--max-vertices", "3", "--max-degree", "2", "--quiet", "-o", p, *x]),
    ("worst-case --search", "-o"): ("dir", "worst-case-search.json", lambda t, p, x: [
        "worst-case", "--search", "--vertices", "5", "--evaluations", "3", "--max-degree", "3", "--quiet",
        "-o", p, *x]),
    ("worst-case --summarise", "-o"): ("dir", "worst-case.md", lambda t, p, x: [
        "worst-case", "--summarise", _summarised_run(t), "-o", p, *x]),
    ("port import", "-o"): ("file", None, lambda t, p, x: ["port", "import", "icfpc2025", PROBATIO, "-o", p, *x]),
    ("port export", "-o"): ("file", None, lambda t, p, x: ["port", "export", "icfpc2025", PROBATIO, "-o", p, *x]),
    ("port minimise", "-o"): ("file", None, lambda t, p, x: ["port", "minimise", ALEPH, "-o", p, *x]),
    ("port solve", "-o"): ("file", None, lambda t, p, x: ["port", "solve", _exchange(t), "--rooms", "3", "-o", p,
                                                          *x]),
}


def _target(tmp: Path, case) -> Path:
    """The output path of ``case`` under ``tmp/out``, already there: a file, or a directory holding the file the
    command writes, each with :data:`SENTINEL` in it."""
    kind, own, _ = CASES[case]
    (tmp / "in").mkdir(exist_ok=True)
    (tmp / "out").mkdir(exist_ok=True)
    path = tmp / "out" / "target"
    if kind == "file":
        written = Path(str(path) + ".svg") if case == ("world --draw", "-o") else path
    else:
        path.mkdir()
        written = path / own
    written.write_text(SENTINEL)
    return written


def _argv(tmp: Path, case, extra: list[str]) -> list[str]:
    return CASES[case][2](tmp, str(tmp / "out" / "target"), extra)


def _snapshot(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.mark.parametrize("case", sorted(CASES), ids=" ".join)
def test_an_existing_output_is_refused_before_any_work(tmp_path, capsys, case):
    written = _target(tmp_path, case)
    argv = _argv(tmp_path, case, [])
    before = _snapshot(tmp_path / "out")
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert str(tmp_path / "out" / "target") in err and "--force" in err, err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert _snapshot(tmp_path / "out") == before, "a refused command wrote something"
    assert written.read_text() == SENTINEL


FAILING = ("conformance run", "--view-failures")
"""Writes only for a failing case (exit 1), and exports a suite first: slow."""


@pytest.mark.parametrize("case", [pytest.param(c, marks=pytest.mark.slow) if c == FAILING else c
                                  for c in sorted(CASES)], ids=" ".join)
def test_force_writes_over_an_existing_output(tmp_path, capsys, case):
    written = _target(tmp_path, case)
    assert main(_argv(tmp_path, case, ["--force"])) == (1 if case == FAILING else 0), capsys.readouterr().err
    assert written.read_text(errors="replace") != SENTINEL and written.stat().st_size > 0


@pytest.mark.parametrize("case", sorted(CASES), ids=" ".join)
def test_an_empty_output_path_is_bad_input(tmp_path, capsys, monkeypatch, case):
    (tmp_path / "in").mkdir()
    (tmp_path / "out").mkdir()
    monkeypatch.chdir(tmp_path / "out")  # an empty path must not become the current directory
    argv = CASES[case][2](tmp_path, "", [])
    if case == ("world --draw", "-o"):
        argv[argv.index(".svg")] = ""
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "empty" in err and "Traceback" not in err, err
    assert _snapshot(tmp_path / "out") == {}


def test_conformance_export_force_replaces_an_earlier_suite_only(tmp_path, capsys):
    """The suite must hold only its own files: --force removes the earlier suite, and refuses anything else."""
    suite = tmp_path / "suite"
    (suite / "algorithms" / "gone").mkdir(parents=True)
    (suite / "algorithms" / "gone" / "x.trace.jsonl").write_text(SENTINEL)
    assert main(["conformance", "export", str(suite), "--algorithm", "basic", "--force"]) == 0
    assert not (suite / "algorithms" / "gone").exists()
    assert main(["conformance", "lint", str(suite)]) == 0
    (suite / "notes.txt").write_text(SENTINEL)
    manifest = (suite / "manifest.json").read_bytes()
    capsys.readouterr()
    assert main(["conformance", "export", str(suite), "--algorithm", "basic", "--force"]) == 2
    err = capsys.readouterr().err
    assert "notes.txt" in err and (suite / "manifest.json").read_bytes() == manifest


def test_models_force_removes_the_earlier_models(tmp_path):
    models = tmp_path / "models"
    models.mkdir()
    (models / "model-9999.json").write_text(SENTINEL)
    (models / "notes.txt").write_text(SENTINEL)
    assert main(["explore", "cycle:n=5", "--algorithm", "model-tree", "--cue-n", "5", "--quiet", "--models",
                 str(models), "--force"]) == 0
    assert not (models / "model-9999.json").exists() and (models / "notes.txt").read_text() == SENTINEL
    assert (models / "model-0001.json").exists()


def test_a_device_is_written_as_always(capsys):
    assert main(["world", SMALL, "-o", "/dev/null"]) == 0


def test_resumable_directories_are_reused_without_force(tmp_path, capsys):
    """bench -o and --shards are inputs as well as outputs: a second run there resumes, it is not refused."""
    bench = ["bench", "figure-3.11", "--graphs", "1", "--sizes", "20", "--jobs", "1", "--no-plots", "--quiet",
             "-o", str(tmp_path / "bench")]
    assert main(bench) == 0 and main(bench) == 0
    assert "0 runs done, 2 already in" in capsys.readouterr().out  # the second sweep resumed: nothing to run
    census = ["census", "--marker", "none", "--max-vertices", "3", "--max-degree", "2", "--quiet",
              "--shards", str(tmp_path / "shards")]
    assert main(census) == 0 and main(census) == 0


def _writing_options() -> set[tuple[str, str]]:
    """(command, option) of every option of the CLI that names an output, read from the parsers."""
    found: set[tuple[str, str]] = set()

    def walk(parser: argparse.ArgumentParser, name: str) -> None:
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for sub, subparser in action.choices.items():
                    walk(subparser, f"{name} {sub}".strip())
            elif (action.dest in ("out", "output", "trace", "map", "models", "view", "view_failures")
                  and action.option_strings
                  and action.help != argparse.SUPPRESS):
                found.add((name, action.option_strings[0]))
            elif name == "conformance export" and action.dest == "dir":
                found.add((name, "DIR"))
    walk(build_parser(), "")
    return found


def test_every_writing_option_follows_the_rule():
    """A new output option must be claimed (and be in this table) or be a resumable directory the rule names."""
    resumable = {("bench", "-o")}
    options = _writing_options()
    assert resumable <= options
    tabled = {(command.split()[0] if command.startswith("worst-case") else command, option)
              for command, option in CASES if command != "world --draw"}
    assert options - resumable == tabled
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for command, _ in options - resumable:
        p = sub.choices[command.split()[0]]
        if " " in command:
            p = next(a for a in p._actions if isinstance(a, argparse._SubParsersAction)).choices[command.split()[1]]
        assert "--force" in p._option_string_actions, command
    for command, option in resumable:
        assert "--force" not in sub.choices[command]._option_string_actions
        assert f"`{command} {option} DIR`" in RULE
