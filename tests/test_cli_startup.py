"""``--help`` starts fast: no command's help, nor ``topomark`` alone, imports a heavy library or a command's
implementation (its ``cmd_*`` module); the names and limits the help lists come from a table generated from
the registry, the generators and the other modules that define them, and the table is checked against them.

Not a timing test: a fresh interpreter per command line (``python -m topomark ... --help``), and what it
imported, read from ``sys.modules``."""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from topomark.reference.cli.options.port import action_modules

from topomark.reference.cli import facts
from topomark.reference.cli.facts_table import TABLE
from topomark.reference.cli.main import COMMANDS, build_parser, main

ROOT = Path(__file__).resolve().parents[1]

HEAVY = ("networkx", "numpy", "scipy", "z3", "jsonschema", "hypothesis", "deap", "matplotlib", "dask",
         "distributed", "shtab")
"""Libraries a command may need when it runs, never to print its help."""

PROBE = """
import json, runpy, sys
sys.argv = ["topomark", *sys.argv[1:]]
try:
    runpy.run_module("topomark", run_name="__main__", alter_sys=True)
except SystemExit as exc:
    code = exc.code
print(json.dumps({"exit": code, "modules": sorted(sys.modules)}), file=sys.stderr)
"""
"""``python -m topomark ARGS``, then the exit code and every module imported, as the last line of stderr."""


def probe(*argv: str) -> tuple[int, str, set[str]]:
    """Run ``python -m topomark ARGV`` in a fresh interpreter of this checkout: exit code, stdout, modules."""
    env = {**os.environ, "COLUMNS": "100"}
    done = subprocess.run([sys.executable, "-c", PROBE, *argv], capture_output=True, text=True, timeout=120,
                          cwd=ROOT, env=env)
    report = json.loads(done.stderr.strip().splitlines()[-1])
    return report["exit"], done.stdout, set(report["modules"])


def command_lines() -> list[list[str]]:
    """Every command and sub-command (``conformance run``...), as the parser has them."""
    lines: list[list[str]] = []

    def walk(parser: argparse.ArgumentParser, prefix: list[str]) -> None:
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    lines.append([*prefix, name])
                    walk(sub, [*prefix, name])

    walk(build_parser(), [])
    return lines


def heavy(modules: set[str]) -> set[str]:
    return {m for m in modules if m.partition(".")[0] in HEAVY}


def implementations(modules: set[str]) -> set[str]:
    return {m for m in modules if m.startswith("topomark.reference.cli.cmd_")}


def test_every_command_is_probed():
    lines = command_lines()
    assert [line[0] for line in lines if len(line) == 1] == list(COMMANDS)
    port_actions = len(action_modules())  # each port action registers from its own options/port_*.py
    assert ["conformance", "run"] in lines and len(lines) == len(COMMANDS) + 3 + port_actions


@pytest.mark.parametrize("line", command_lines(), ids=" ".join)
def test_a_commands_help_imports_no_heavy_library_and_not_the_command(line):
    code, out, modules = probe(*line, "--help")
    assert code == 0 and out.startswith(f"usage: topomark {' '.join(line)}"), out
    assert heavy(modules) == set() and implementations(modules) == set()


@pytest.mark.parametrize("line", command_lines(), ids=" ".join)
def test_a_commands_help_from_the_table_is_the_help_from_the_modules(line, monkeypatch, capsys):
    """In this process the registry and the rest are imported: the help is read from them, not the table."""
    _, fast, _ = probe(*line, "--help")
    monkeypatch.setenv("COLUMNS", "100")
    with pytest.raises(SystemExit):
        main([*line, "--help"])
    assert fast == capsys.readouterr().out


def test_topomark_alone_prints_the_commands_and_exits_0():
    code, out, modules = probe()
    lines = out.splitlines()
    assert code == 0 and lines[0].startswith("usage: topomark")
    for name, (_, summary) in COMMANDS.items():
        assert any(line.split() and line.split()[0] == name and summary in line for line in lines), name
    assert "topomark COMMAND --help" in out
    assert heavy(modules) == set() and implementations(modules) == set()


def test_topomark_help_imports_no_heavy_library():
    code, out, modules = probe("--help")
    assert code == 0 and out.startswith("usage: topomark") and heavy(modules) == set()


# the table -------------------------------------------------------------------------------------------------
def test_the_table_is_what_the_modules_hold():
    assert TABLE == facts.table(), ("reference/cli/facts_table.py is out of date: "
                                    "python -m topomark.reference.cli.facts > reference/cli/facts_table.py")


def test_the_table_file_is_what_the_generator_writes():
    assert (ROOT / "reference/cli/facts_table.py").read_text() == facts.source()


def test_help_reads_the_table_and_a_command_that_runs_reads_the_module(monkeypatch):
    """A module not yet imported: ``--help`` reads the table; a command that runs imports the module."""
    monkeypatch.delitem(sys.modules, "colorsys", raising=False)
    monkeypatch.setitem(facts.SOURCES, "probe", ("colorsys", lambda module: module.ONE_THIRD))
    monkeypatch.setitem(TABLE, "probe", "from the table")
    with facts.for_help(True):
        assert facts.fact("probe") == "from the table" and "colorsys" not in sys.modules
    with facts.for_help(False):
        assert facts.fact("probe") == 1.0 / 3.0 and "colorsys" in sys.modules
    with facts.for_help(True):  # imported now: read from the module, as an algorithm registered in-process is
        assert facts.fact("probe") == 1.0 / 3.0


def test_an_algorithm_registered_in_this_process_is_in_explores_help(capsys):
    from topomark.reference.algorithms.registry import register, unregister, variant
    from topomark.reference.explorers.algorithm31 import LighthouseExplorer

    register(variant("help-probe", LighthouseExplorer))
    try:
        with pytest.raises(SystemExit):
            main(["explore", "--help"])
    finally:
        unregister("help-probe")
    assert "help-probe" in capsys.readouterr().out


@pytest.mark.parametrize("argv, asks", [(["explore", "--help"], True), (["explore", "-h"], True),
                                        (["explore", "--hel"], True), (["explore", "w.json"], False),
                                        (["run-external", "w.json", "--", "prog", "--help"], False),
                                        (["bench", "--h"], True), ([], False)])
def test_which_command_lines_ask_for_help(argv, asks):
    from topomark.reference.cli.main import asks_for_help

    assert asks_for_help(argv) is asks
