"""``docs/adding-an-algorithm.md`` is true: its example code, taken from the page itself, runs as written, and
its steps, followed in a copy of the checkout, give what it promises.

The page's Python blocks are run in order: a block whose first line names a file (``# reference/...py``)
becomes that module — put in ``sys.modules`` for the test only, nothing is written into the package — and
the others run as one script, which registers the two examples with ``registry.register`` and runs them and a
broken variant under the checker.  The tests then check what the page promises of them.

Then the page is followed as a newcomer would: the checkout (``topomark/`` with its links, ``spec/``,
``reference/``, ``proofs/``, ``pyproject.toml``, ``docs/``) is copied, the files the page names are written
into the copy, and the commands of its "Running it" section are run there in a subprocess, as written, with
the copy first on the path.
"""

from __future__ import annotations

import ast
import json
import os
import re
import shutil
import subprocess
import sys
import types
from pathlib import Path

import pytest

from topomark.reference.algorithms.algorithm_spec import CHECKS
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec, unregister
from topomark.reference.cli.main import main
from topomark.reference.explorers.contract import Explorer, IterationRecord, conforms
from topomark.reference.explorers.edge_choices import EDGE_CHOICES, unregister_edge_choice
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators
from topomark.spec.errors import InvalidInput

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "adding-an-algorithm.md"
TEXT = DOC.read_text()
BLOCKS = re.findall(r"^```python\n(.*?)^```$", TEXT, re.M | re.S)
COMMANDS = [line for block in re.findall(r"^```sh\n(.*?)^```$", TEXT.split("## Running it")[1].split("\n## ")[0],
                                         re.M | re.S) for line in block.splitlines() if line.strip()]
TOYS = ("tree-walk", "basic-farthest")
FILE = re.compile(r"# (reference/[\w/]+)\.py")


def _module_name(block: str) -> str | None:
    """``topomark.reference.explorers.tree_walk`` for a block opening ``# reference/explorers/tree_walk.py``."""
    found = FILE.fullmatch(block.splitlines()[0])
    return "topomark." + found.group(1).replace("/", ".") if found else None


@pytest.fixture
def doc(monkeypatch):
    """Run every block of the page; yield the script's names.  The modules and the registration are undone."""
    script: dict = {"__name__": "adding_an_algorithm"}
    try:
        for block in BLOCKS:
            name = _module_name(block)
            if name is None:
                exec(compile(block, str(DOC), "exec"), script)
                continue
            module = types.ModuleType(name)
            module.__file__ = str(DOC)
            monkeypatch.setitem(sys.modules, name, module)
            exec(compile(block, str(DOC), "exec"), module.__dict__)
        yield script
    finally:
        for name in TOYS:
            if name in REGISTRY:
                unregister(name)
        if "farthest" in EDGE_CHOICES:
            unregister_edge_choice("farthest")


def test_the_page_has_the_three_files_and_the_scripts():
    assert [_module_name(b) for b in BLOCKS] == ["topomark.reference.explorers.tree_walk",
                                                 "topomark.reference.algorithms.registrations.tree_walk",
                                                 "topomark.reference.algorithms.registrations.basic_farthest",
                                                 None, None, None]


def test_the_example_explorer_keeps_the_whole_contract(doc):
    """What tests/test_explorer_protocol.py asks of every registered explorer: the methods, models() and a
    record with to_json()."""
    spec = algorithm_spec("tree-walk")
    assert conforms(spec.factory)
    out = explore(generators.chain(4), spec)
    assert isinstance(out.explorer, Explorer) and out.explorer.models() == [(out.explorer.S, out.explorer.position)]
    assert all(isinstance(it, IterationRecord) and it.to_json()["iteration"] == it.number
               for it in out.explorer.iterations)


def test_the_variant_takes_its_edge_choice_and_keeps_algorithm_3_1s_checks(doc):
    spec = algorithm_spec("basic-farthest")
    assert spec.edge_policy == "farthest" and spec.checks == algorithm_spec("basic").checks
    assert spec.family == "algorithm-3.1" and list(REGISTRY).index("basic-farthest") == 1  # right after basic
    assert doc["far"].verified and doc["near"].verified


def test_the_toy_is_registered_and_verified_correct(doc):
    spec = algorithm_spec("tree-walk")
    assert spec is doc["SPECS"][0] and spec.factory is sys.modules["topomark.reference.explorers.tree_walk"].TreeWalk
    out = doc["outcome"]
    assert (out.verified, out.outcome, out.violation) == (True, "correct", None)
    assert out.checks > 0 and out.iterations == doc["TREE"].n - 1 and out.marker_operations == {}
    for mode in ("incremental", "full", "both"):  # by name, through the registry, like the CLI
        chain = explore(generators.chain(6), "tree-walk", check_mode=mode)
        assert chain.verified and chain.cost <= 2 * chain.m


def test_a_broken_variant_is_caught_by_a_named_check(doc):
    broken = doc["broken"]
    assert not broken.verified and broken.violation.check == "I-2" and broken.violation.check in CHECKS
    assert "iteration 1" in broken.violation.detail


def test_the_toy_runs_from_the_command_line_and_refuses_a_world_that_is_not_a_tree(doc, capsys):
    assert main(["explore", "chain:n=5", "--algorithm", "tree-walk", "--quiet"]) == 0
    capsys.readouterr()
    with pytest.raises(InvalidInput, match="tree-walk maps trees only"):
        explore(generators.cycle(5), "tree-walk")
    assert main(["explore", "cycle:n=5", "--algorithm", "tree-walk"]) == 2
    assert "tree-walk maps trees only" in capsys.readouterr().err


def test_the_example_keeps_the_wall_and_the_layers():
    """The explorer imports only spec/ and explorers/; the registration nothing above algorithms/."""
    registration = ("topomark.spec", "topomark.reference.explorers", "topomark.reference.worlds",
                    "topomark.reference.algorithms")
    allowed = {"topomark.reference.explorers.tree_walk": ("topomark.spec", "topomark.reference.explorers"),
               "topomark.reference.algorithms.registrations.tree_walk": registration,
               "topomark.reference.algorithms.registrations.basic_farthest": registration}
    for block in BLOCKS:
        name = _module_name(block)
        if name is None:
            continue
        imported = {node.module for node in ast.walk(ast.parse(block)) if isinstance(node, ast.ImportFrom)}
        assert all(m == "__future__" or m.startswith(allowed[name]) or "." not in m for m in imported), name
        assert "__all__" in block and re.search(r"§\d", block.split('"""')[1]), name


def test_the_page_explains_every_check():
    table = TEXT.split("## Which checks to name")[1].split("##")[0]
    assert all(f"| `{name}` |" in table for name in CHECKS)


# -- the page followed in a copy of the checkout -------------------------------------------------------------------
@pytest.fixture(scope="module")
def checkout(tmp_path_factory):
    """A copy of the checkout with the page's files written in; the page's commands run there, as written:
    yields the copy and, per command, (command, exit code, stdout, stderr).  Before and after: whether
    docs/cli.md is what the parsers give."""
    copy = tmp_path_factory.mktemp("checkout")
    ignore = shutil.ignore_patterns("__pycache__")
    for folder in ("topomark", "spec", "reference", "proofs", "docs"):
        shutil.copytree(ROOT / folder, copy / folder, symlinks=True, ignore=ignore)
    shutil.copy(ROOT / "pyproject.toml", copy)
    for block in BLOCKS:
        found = FILE.fullmatch(block.splitlines()[0])
        if found:
            (copy / f"{found.group(1)}.py").write_text(block)
    env = {**os.environ, "PYTHONPATH": str(copy), "PYTHONDONTWRITEBYTECODE": "1"}

    def sh(command: str) -> tuple[str, int, str, str]:
        line = re.sub(r"^topomark ", f"{sys.executable} -m topomark ", command)
        line = re.sub(r"^python ", f"{sys.executable} ", line)
        done = subprocess.run(line, shell=True, cwd=copy, env=env, capture_output=True, text=True, timeout=600)
        return command, done.returncode, done.stdout, done.stderr
    up_to_date = (f"{sys.executable} -c \"import sys; from topomark.reference.cli.docgen import markdown; "
                  "sys.exit(open('docs/cli.md', encoding='utf-8').read() != markdown())\"")
    before = sh(up_to_date)[1] == 0
    runs = [sh(command) for command in COMMANDS]
    after = sh(up_to_date)[1] == 0
    yield copy, runs, (before, after)


def _ran(checkout, words: str) -> tuple[str, int, str, str]:
    """The run of the page's command that is ``words`` (its comment left out), else the first that contains it."""
    runs = checkout[1]
    return next((run for run in runs if run[0].split(" #")[0].strip() == words), None) or \
        next(run for run in runs if words in run[0])


@pytest.mark.slow
def test_the_copy_imports_the_copy(checkout):
    copy, _, _ = checkout
    where = subprocess.run([sys.executable, "-c", "import topomark; print(topomark.__file__)"], cwd=copy,
                           env={**os.environ, "PYTHONPATH": str(copy)}, capture_output=True, text=True)
    assert Path(where.stdout.strip()).resolve() == (copy / "topomark" / "__init__.py").resolve()


@pytest.mark.slow
def test_every_command_of_the_page_succeeds(checkout):
    assert len(checkout[1]) >= 8
    for command, code, _, err in checkout[1]:
        assert code == 0, (command, err[-2000:])


@pytest.mark.slow
def test_docs_cli_md_must_be_regenerated_and_the_page_says_how(checkout):
    copy, _, (before, after) = checkout
    assert (before, after) == (False, True)  # stale once the algorithms exist, current after the page's command
    cli = (copy / "docs" / "cli.md").read_text(encoding="utf-8")
    assert all(name in cli for name in TOYS)


@pytest.mark.slow
def test_both_algorithms_are_listed_with_their_policies(checkout):
    listed = {a["name"]: a for a in json.loads(_ran(checkout, "algorithms --json")[2])}
    assert TOYS[0] in listed and TOYS[1] in listed
    assert listed["tree-walk"]["policies"] == {} and listed["tree-walk"]["family"] == "robot"
    assert listed["basic-farthest"]["policies"] == {"edge": "farthest", "hypothesis": "fifo", "path": "shortest"}
    text = _ran(checkout, "topomark algorithms")[2]
    assert "tree-walk" in text and "basic-farthest" in text


@pytest.mark.slow
def test_the_runs_are_checked_and_name_the_policies_they_use(checkout):
    tree = _ran(checkout, "explore chain:n=8 --algorithm tree-walk")[2]
    assert "(tree-walk; kit: no marker; no policies)" in tree and "verified:" in tree
    far = _ran(checkout, "--algorithm basic-farthest")[2]
    assert "policies edge=farthest, hypothesis=fifo, path=shortest)" in far and "verified:" in far
    assert "cost-bound held at the end" in far
    assert "policies edge=farthest," in _ran(checkout, "--policy edge=farthest")[2]
    assert _ran(checkout, "replay tree.json walk.jsonl")[2].startswith("VERIFIED")
    copy = checkout[0]
    assert (copy / "walk.json").exists() and (copy / "walk.jsonl").exists()


@pytest.mark.slow
def test_the_conformance_suites_hold_what_the_page_says(checkout):
    suites = {s["algorithm"]: s for s in json.loads((checkout[0] / "suite" / "manifest.json").read_text())["suites"]}
    assert set(suites) == set(TOYS)
    assert suites["tree-walk"]["family"] == "marker-less"
    assert [c["name"] for c in suites["tree-walk"]["cases"]] == ["chain-6"]  # the only tree of the shared worlds
    assert suites["basic-farthest"]["family"] == "algorithm-3.1" and len(suites["basic-farthest"]["cases"]) >= 6
    assert all(c["expected"] == "correct" for s in suites.values() for c in s["cases"])


@pytest.mark.slow
def test_help_lists_the_new_algorithms_after_the_pages_facts_command(checkout):
    """``explore --help`` reads its names from the table the page regenerates, not from the registry."""
    copy = checkout[0]
    assert _ran(checkout, "python -m topomark.reference.cli.facts > reference/cli/facts_table.py")[1] == 0
    shown = subprocess.run([sys.executable, "-m", "topomark", "explore", "--help"], cwd=copy, capture_output=True,
                           text=True, env={**os.environ, "PYTHONPATH": str(copy), "COLUMNS": "200"})
    assert shown.returncode == 0 and all(name in shown.stdout for name in TOYS), shown.stdout[-1500:]
