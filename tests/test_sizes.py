"""Every module short enough to read, every function short enough to check by eye.

No module of ``spec/``, ``reference/`` or ``proofs/`` is over 400 lines and no
function or method over 60; a module that grows past that is split by concept,
a function by step.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MAX_MODULE_LINES = 400
MAX_FUNCTION_LINES = 60
SOURCES = sorted(p for top in ("spec", "reference", "proofs") for p in (ROOT / top).rglob("*.py"))


def too_long(source: str) -> list[str]:
    """The functions of ``source`` longer than :data:`MAX_FUNCTION_LINES`, as ``name (lines)``."""
    return [f"{node.name} ({node.end_lineno - node.lineno + 1})" for node in ast.walk(ast.parse(source))
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            and node.end_lineno - node.lineno + 1 > MAX_FUNCTION_LINES]


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: str(p.relative_to(ROOT)))
def test_module_and_function_sizes(path):
    source = path.read_text()
    assert source.count("\n") <= MAX_MODULE_LINES, f"{path.name}: {source.count(chr(10))} lines"
    assert not too_long(source)


def test_a_long_function_is_found():
    body = "\n".join(f"    x{i} = {i}" for i in range(MAX_FUNCTION_LINES))
    assert too_long(f"def f():\n{body}\n") == [f"f ({MAX_FUNCTION_LINES + 1})"]
    assert too_long("def g():\n    return 1\n") == []
