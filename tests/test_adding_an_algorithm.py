"""``docs/adding-an-algorithm.md`` is true: its example code, taken from the page itself, runs as written.

The page's Python blocks are run in order: a block whose first line names a file (``# reference/...py``)
becomes that module — put in ``sys.modules`` for the test only, nothing is written into the package — and
the others run as one script, which registers the toy algorithm with ``registry.register`` and runs it and a
broken variant under the checker.  The tests then check what the page promises of them.
"""

from __future__ import annotations

import ast
import re
import sys
import types
from pathlib import Path

import pytest

from topomark.reference.algorithms.algorithm_spec import CHECKS
from topomark.reference.algorithms.registry import REGISTRY, algorithm_spec, unregister
from topomark.reference.cli.main import main
from topomark.reference.run.explore import explore
from topomark.reference.worlds import generators
from topomark.spec.errors import InvalidInput

DOC = Path(__file__).resolve().parents[1] / "docs" / "adding-an-algorithm.md"
TEXT = DOC.read_text()
BLOCKS = re.findall(r"^```python\n(.*?)^```$", TEXT, re.M | re.S)
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
        if "tree-walk" in REGISTRY:
            unregister("tree-walk")


def test_the_page_has_the_two_files_and_the_scripts():
    assert [_module_name(b) for b in BLOCKS] == ["topomark.reference.explorers.tree_walk",
                                                 "topomark.reference.algorithms.registrations.tree_walk", None, None]


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
    allowed = {"topomark.reference.explorers.tree_walk": ("topomark.spec", "topomark.reference.explorers"),
               "topomark.reference.algorithms.registrations.tree_walk": (
                   "topomark.spec", "topomark.reference.explorers", "topomark.reference.worlds",
                   "topomark.reference.algorithms")}
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
