"""The command line behaves like the tools people know: --version, "did you mean", one error prefix, JSON errors
under --json, help for everything, one spelling per option, a fast --help, shell completion, a quiet second
Ctrl-C, and a working --help on every ``python -m`` entry point."""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import time
from importlib.metadata import version
from pathlib import Path

import pytest

from topomark.reference.cli import cmd_world
from topomark.reference.cli.main import COMMANDS, build_parser, main
from topomark.spec.errors import CheckFailure, TopomarkFault


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def run_process(*argv, **kw):
    return subprocess.run([sys.executable, "-m", "topomark.reference.cli.main", *argv], capture_output=True,
                          text=True, timeout=120, **kw)


# 1 --version -----------------------------------------------------------------------------------------------
def test_version_prints_the_installed_version():
    done = run_process("--version")
    assert (done.returncode, done.stdout, done.stderr) == (0, f"topomark {version('topomark')}\n", "")


# 2 did you mean ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("argv, suggestion", [
    (["explor"], "'explore'"),                                                 # command
    (["explore", "--algoritm", "basic"], "'--algorithm'"),                     # option
    (["iso", "--method", "anchord", "a", "b"], "'anchored'"),                  # fixed choice
    (["world", "latice"], "'lattice'"),                                        # generator
    (["world", "lattice:row=3"], "'rows'"),                                    # generator parameter
    (["explore", "--algorithm", "basc"], "'basic'"),                           # algorithm
    (["explore", "--lighthouse", "directional-vertx"], "'directional-vertex'"),  # lighthouse
    (["explore", "--policy", "edge=neares"], "'nearest'"),                     # policy
    (["bench", "figure-3.1"], "'figure-3.10'"),                                # experiment
    (["census", "--marker", "directional-vertx", "--max-vertices", "3", "--max-degree", "2"],
     "'directional-vertex'"),                                                  # marker class
    (["conformance", "export", "never-written", "--family", "thread"], "'threads'"),  # family
    (["completion", "bsh"], "'bash'"),
])
def test_a_misspelled_name_gets_the_closest_one(capsys, argv, suggestion):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert f"(did you mean {suggestion}" in err, err


def test_a_name_close_to_nothing_gets_no_suggestion(capsys):
    code, _, err = run(capsys, "explore", "--algorithm", "zzzzzz")
    assert code == 2 and "did you mean" not in err and "choose from basic" in err


# 3 one prefix ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("argv", [
    ["explore", "--nope"], ["--nope"], ["nope"], ["census", "--marker", "directional-vertex"],
    ["explore", "--check-mode", "half"], ["world", "latice"], ["conformance", "run", "d", "--timeout", "x"],
])
def test_every_error_says_topomark_error_once(capsys, argv):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.startswith("topomark: error: ") and err.count("topomark") == 1 and err.count("\n") == 1, err


# 4 --json: one object, errors too ----------------------------------------------------------------------------
def _only_json(out: str) -> dict:
    data = json.loads(out)  # the whole of stdout: one object, nothing besides
    assert isinstance(data, dict)
    return data


@pytest.mark.parametrize("argv", [
    ["explore", "--json", "--nope"], ["--json", "explore"], ["world", "latice", "--json"],
    ["census", "--json", "--max-vertices", "3"], ["explor", "--json"],
])
def test_under_json_bad_input_is_one_json_object(capsys, argv):
    code, out, err = run(capsys, *argv)
    assert code == 2 and _only_json(out)["exit"] == 2 and _only_json(out)["error"] in err


@pytest.mark.parametrize("raised, code", [(RuntimeError("boom"), 3), (TopomarkFault("two answers"), 3),
                                          (CheckFailure("I-1 broken"), 1), (KeyboardInterrupt(), 130)])
def test_under_json_every_other_outcome_is_one_json_object(capsys, monkeypatch, raised, code):
    def handler(args):
        raise raised

    monkeypatch.setattr(cmd_world, "world_command", handler)
    previous = signal.getsignal(signal.SIGINT)
    try:
        got, out, _ = run(capsys, "world", "cycle", "--json")
    finally:
        signal.signal(signal.SIGINT, previous)
    assert got == code and _only_json(out)["exit"] == code


def test_json_after_the_program_separator_is_the_programs(capsys):
    code, out, err = run(capsys, "run-external", "latice", "--", "prog", "--json")
    assert code == 2 and out == "" and "did you mean 'lattice'" in err


# 5 help for everything ---------------------------------------------------------------------------------------
def _parsers(parser, path=()):
    yield path, parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for choice in action._choices_actions:
                assert choice.help, f"{' '.join(path)} {choice.dest}: no summary"
            for name, sub in action.choices.items():
                yield from _parsers(sub, (*path, name))


def test_every_flag_and_positional_of_every_command_has_help():
    missing, seen = [], 0
    for path, parser in _parsers(build_parser()):
        visible = {a.dest for a in parser._actions if a.help and a.help != argparse.SUPPRESS}
        for action in parser._actions:
            seen += 1
            if isinstance(action, argparse._SubParsersAction):
                continue
            hidden_alias = action.help == argparse.SUPPRESS and action.dest in visible
            if not (hidden_alias or (action.help and action.help != argparse.SUPPRESS and action.help.strip())):
                missing.append(f"{' '.join(path)} {'/'.join(action.option_strings) or action.dest}")
    assert seen > 100 and missing == []


# 6 one spelling per concept ----------------------------------------------------------------------------------
JUSTIFIED = {"-o/--out": "a FILE for world, a DIR for bench and search",
             "--world": "a world FILE elsewhere; contest serve's serves one as a problem: NAME=FILE, repeatable"}


def test_an_option_has_one_type_and_metavar_wherever_it_appears():
    spellings: dict[str, set] = {}
    for path, parser in _parsers(build_parser()):
        for a in parser._actions:
            if a.option_strings and a.help != argparse.SUPPRESS:
                spellings.setdefault("/".join(a.option_strings), set()).add((a.type, a.metavar, a.nargs))
    differ = {k for k, v in spellings.items() if len(v) > 1}
    assert differ == set(JUSTIFIED), differ
    assert "--output" not in spellings and "-o/--output" not in spellings
    assert {"-o/--out", "--jobs", "--quiet", "--json", "--seed", "--timeout"} <= set(spellings)


def test_the_former_output_spelling_is_still_accepted(tmp_path, capsys):
    assert run(capsys, "world", "cycle:n=4", "--output", str(tmp_path / "a.json"))[0] == 0
    assert run(capsys, "world", "cycle:n=4", "-o", str(tmp_path / "b.json"))[0] == 0
    assert (tmp_path / "a.json").read_text() == (tmp_path / "b.json").read_text()


@pytest.mark.parametrize("jobs, refused", [("0", True), ("257", True), ("1", False), ("256", False)])
def test_jobs_has_one_range_in_bench_and_census(tmp_path, capsys, monkeypatch, jobs, refused):
    from topomark.reference.cli import cmd_bench

    monkeypatch.setattr(cmd_bench, "plan", lambda *a: [])  # past --jobs, bench stops at "no runs planned"
    bench = run(capsys, "bench", "lattice", "--sizes", "3", "--out", str(tmp_path / "b"), "--jobs", jobs)
    assert bench[0] == 2 and ("--jobs must be at least 1 and at most 256" in bench[2]) == refused, bench
    if refused:  # (a census that is not refused runs, which takes a while: a tiny one, once)
        census = run(capsys, "census", "--marker", "directional-vertex", "--max-vertices", "2", "--max-degree",
                     "1", "--quiet", "--jobs", jobs)
        assert census[0] == 2 and "--jobs must be at least 1 and at most 256" in census[2]
    elif jobs == "1":
        census = run(capsys, "census", "--marker", "directional-vertex", "--max-vertices", "2", "--max-degree",
                     "1", "--quiet", "--jobs", jobs)
        assert census[0] == 0 and census[2] == ""


# 7 a fast --help ---------------------------------------------------------------------------------------------
def test_help_imports_no_command_module_and_no_heavy_library():
    script = ("import sys\nfrom topomark.reference.cli.main import main\ntry:\n    main(['--help'])\n"
              "except SystemExit:\n    pass\nprint(' '.join(sorted(sys.modules)))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    loaded = set(done.stdout.split("\n")[-2].split())
    heavy = {"z3", "numpy", "networkx", "matplotlib", "dask", "distributed", "shtab"} & loaded
    commands = {m for m in loaded if m.startswith("topomark.reference.cli.cmd_")}
    assert "usage: topomark" in done.stdout and heavy == set() and commands == set()


def test_the_parser_of_one_command_has_the_others_by_name_only():
    parser = build_parser(only="claims")
    names = parser._subparsers._group_actions[0].choices
    assert list(names) == list(COMMANDS) and names["claims"]._actions[-1].option_strings  # claims: full
    assert [a.dest for a in names["explore"]._actions] == []  # explore: its summary only


# 8 completion ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("shell", ["bash", "zsh", "tcsh"])
def test_completion_scripts_complete_commands_and_options(capsys, shell):
    code, out, err = run(capsys, "completion", shell)
    assert code == 0 and err == ""
    assert "census-count" in out and "(bash zsh tcsh)" in out  # the commands, and a command's choices
    if shell != "tcsh":  # shtab's tcsh script completes commands and choices, not option names
        assert "--max-vertices" in out and "--algorithm" in out


# 9 a second Ctrl-C -------------------------------------------------------------------------------------------
def _children(pid: int) -> list[int]:
    found = []
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            stat = Path(f"/proc/{entry}/stat").read_text()
        except OSError:
            continue
        if int(stat[stat.rindex(")") + 2:].split()[1]) == pid:
            found.append(int(entry))
    return found


@pytest.mark.slow
@pytest.mark.parametrize("gap", [0.0, 0.05, 0.3])
def test_ctrl_c_twice_exits_130_quietly(tmp_path, gap):
    """Ctrl-C reaches the whole process group (leader and workers), twice, ``gap`` seconds apart."""
    proc = subprocess.Popen([sys.executable, "-m", "topomark.reference.cli.main", "bench", "lattice", "--jobs", "2",
                             "--no-plots", "--quiet", "--out", str(tmp_path / "b")], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 30
        while len(_children(proc.pid)) < 2 and time.monotonic() < deadline and proc.poll() is None:
            time.sleep(0.05)
        time.sleep(0.3)  # the workers are running their first explorations
        os.killpg(proc.pid, signal.SIGINT)
        time.sleep(gap)
        os.killpg(proc.pid, signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    assert err in ("", "topomark: interrupted\n"), err


# 10 python -m entry points -----------------------------------------------------------------------------------
@pytest.mark.parametrize("module", ["topomark.proofs.bench_z3", "topomark.proofs.bench_census",
                                    "topomark.reference.bench.measure.checked_cost",
                                    "topomark.reference.bench.measure.movable",
                                    "topomark.reference.bench.measure.markers_62",
                                    "topomark.reference.bench.measure.thread_length"])
def test_every_python_m_entry_point_has_help(module):
    done = subprocess.run([sys.executable, "-m", module, "--help"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout.startswith(f"usage: python -m {module}"), done.stderr
    assert "Traceback" not in done.stderr
